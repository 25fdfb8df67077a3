#!/usr/bin/python3
"""What each core of this machine gives silodem and LAMMPS on the anchor bed (issue 5 §1, context
for the 2-thread against 2-rank ratio).

The 2-thread and 2-rank figures of tools/bench_dense.py depend on both cores. On this VM they do
not run alike, and not alike for every code, so the ratio silodem/LAMMPS at 2 threads/ranks is not
the 1-thread ratio times the codes' own parallel efficiency alone. This benchmark measures it
directly, on the settled 5,000-ball bed of bench_dense.py (N as argument), STEPS steps:

  - silodem 1 thread and LAMMPS 1 rank, each pinned (taskset) to CPU 0, then to CPU 1, alone;
  - the same two runs of one code at once, one on each CPU (is a core slower only when the other
    is busy, as with shared hyperthreads, or always?);
  - silodem 2 threads and LAMMPS 2 MPI ranks (unpinned), as in bench_dense.py;
  - ROUNDS rounds, each code's runs interleaved, medians reported.

From the pinned one-thread times it states the ideal 2-thread time of a perfectly balanced code,
1 / (1/t0 + 1/t1), and of an evenly split one, max(t0, t1) / 2, for each code, against the measured
2-thread/2-rank time.

Usage (after tools/build.sh): tools/bench_cores.py [N]   (default 5000)
Writes reports/bench_cores.json and reports/bench_cores.md.
"""
import json
import os
import shutil
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_dense import DT, SILODEM, STEPS, TOP, lammps_timing_input, lammps_translation, loop_time, settled_case  # noqa: E402

WORK = "/tmp/silodem_bench_cores"
SETTLE, ROUNDS = 10000, 3


def silodem(case, threads, cpu=None, tag=""):
    out = os.path.join(WORK, "silodem_%s" % tag)
    pin = ["taskset", "-c", str(cpu)] if cpu is not None else []
    return pin + [SILODEM, "run", case, "--out", out, "--threads", str(threads), "--quiet"], \
        lambda: json.load(open(os.path.join(out, "summary.json")))["run"]["loop_seconds"]


def lammps(src, ranks, cpu=None, tag=""):
    d = os.path.join(WORK, "lammps_%s" % tag)
    os.makedirs(d, exist_ok=True)
    for f in ("data.lmp", "in.lammps"):
        shutil.copy(os.path.join(src, f), d)
    text = lammps_timing_input(open(os.path.join(d, "in.lammps")).read(), ranks)
    open(os.path.join(d, "in.lammps"), "w").write(text)
    pin = ["taskset", "-c", str(cpu)] if cpu is not None else []
    mpi = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", "2"] if ranks == 2 else []
    cmd = pin + mpi + ["lmp", "-in", "in.lammps", "-log", "log.txt", "-echo", "none", "-screen", "none"]
    return (cmd, d), lambda: loop_time(os.path.join(d, "log.txt"))


def together(*jobs):
    """Runs the prepared jobs (each: command or (command, cwd), and how to read its loop seconds)
    at once; returns their loop seconds."""
    procs = []
    for cmd, _ in jobs:
        cmd, cwd = cmd if isinstance(cmd, tuple) else (cmd, None)
        procs.append((cmd, subprocess.Popen(cmd, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)))
    for cmd, p in procs:
        if p.wait() != 0:
            raise RuntimeError("%s failed: %s" % (cmd, p.stderr.read().decode()[-2000:]))
    return tuple(result() for _, result in jobs)


def timed(job):
    """One prepared job alone; returns its loop seconds."""
    return together(job)[0]


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 5000
    if not shutil.which("taskset") or os.cpu_count() < 2:
        sys.exit("bench_cores: needs taskset and 2 CPUs")
    dense = settled_case(n, WORK, SETTLE, "cores_bed_%d" % n)
    dense["time"] = {"dt": DT, "duration": DT * STEPS}
    dense["output"] = {"series_interval": 1.0}
    dense["compare"] = {"codes": ["silodem", "lammps"], "checks": [{"type": "energy_balance", "tolerance": 1.0}],
                        "time_limit_s": 7200}
    case = os.path.join(WORK, "bed_%d.json" % n)
    json.dump(dense, open(case, "w"))
    # The LAMMPS input is the harness adapter's own translation of the same case.
    src = lammps_translation(case, dense["name"], os.path.join(WORK, "compare"))
    if not src:
        sys.exit("bench_cores: the LAMMPS translation was not written (is lmp installed?)")
    keys = ["alone_cpu0", "alone_cpu1", "together_cpu0", "together_cpu1", "two"]
    t = {code: {k: [] for k in keys} for code in ("silodem", "lammps")}
    for _ in range(ROUNDS):
        for code, make in (("silodem", lambda w, c, tag: silodem(case, w, c, tag)),
                           ("lammps", lambda w, c, tag: lammps(src, w, c, tag))):
            t[code]["alone_cpu0"].append(timed(make(1, 0, "a0")))
            t[code]["alone_cpu1"].append(timed(make(1, 1, "a1")))
            a, b = together(make(1, 0, "t0"), make(1, 1, "t1"))
            t[code]["together_cpu0"].append(a)
            t[code]["together_cpu1"].append(b)
            t[code]["two"].append(timed(make(2, None, "two")))
    med = {code: {k: statistics.median(v) for k, v in t[code].items()} for code in t}
    for code, m in med.items():
        m["ideal_balanced_two"] = 1.0 / (1.0 / m["alone_cpu0"] + 1.0 / m["alone_cpu1"])
        m["ideal_even_two"] = max(m["alone_cpu0"], m["alone_cpu1"]) / 2.0
        m["cpu1_over_cpu0"] = m["alone_cpu1"] / m["alone_cpu0"]
    result = {"measured": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), "mobile": n, "steps": STEPS,
              "rounds": ROUNDS, "seconds": t, "median": med,
              "commands": "tools/bench_cores.py %d" % n}
    rep = os.path.join(TOP, "reports")
    json.dump(result, open(os.path.join(rep, "bench_cores.json"), "w"), indent=1)
    row = lambda label, key, fmt="%.2f": "| %s | %s | %s |" % (label, fmt % med["silodem"][key], fmt % med["lammps"][key])
    md = ["# What each core gives silodem and LAMMPS", "",
          "Measured %s by `%s`: the settled %d-ball anchor bed of tools/bench_dense.py, %d steps, loop seconds "
          "(silodem summary.json `run.loop_seconds`, LAMMPS `Loop time`), median of %d interleaved rounds." %
          (result["measured"], result["commands"], n, STEPS, ROUNDS), "",
          "| loop seconds | silodem | LAMMPS |", "|---|---|---|",
          row("1 thread/rank alone on CPU 0", "alone_cpu0"), row("1 thread/rank alone on CPU 1", "alone_cpu1"),
          row("CPU 1 over CPU 0", "cpu1_over_cpu0"),
          row("1 thread/rank on CPU 0, the same run on CPU 1 at once", "together_cpu0"),
          row("1 thread/rank on CPU 1, the same run on CPU 0 at once", "together_cpu1"),
          row("2 threads / 2 MPI ranks (measured)", "two"),
          row("ideal 2: perfectly balanced, 1/(1/t0 + 1/t1)", "ideal_balanced_two"),
          row("ideal 2: split evenly, max(t0, t1)/2", "ideal_even_two"), "",
          "silodem/LAMMPS speed ratio, 1 thread on CPU 0: %.2f; on CPU 1: %.2f; 2 threads against 2 ranks: %.2f." % (
              med["lammps"]["alone_cpu0"] / med["silodem"]["alone_cpu0"],
              med["lammps"]["alone_cpu1"] / med["silodem"]["alone_cpu1"],
              med["lammps"]["two"] / med["silodem"]["two"]), ""]
    open(os.path.join(rep, "bench_cores.md"), "w").write("\n".join(md))
    print("\n".join(md))


if __name__ == "__main__":
    main()
