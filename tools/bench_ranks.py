#!/usr/bin/python3
"""silodem over MPI processes against its threads and against LAMMPS's ranks (issue 31 §3).

On the settled anchor bed of tools/bench_dense.py with friction (N grains, default 5,000; its
tangential springs make the contact history move between processes), STEPS steps, loop seconds of:

  - silodem 1 thread and 2 threads (`silodem run --threads`);
  - silodem-mpi on 1 and 2 processes (`mpirun -np N silodem-mpi run`);
  - LAMMPS on 1 and 2 ranks (`processors * 1 1`), the reference code in the same run.

ROUNDS rounds, the runs interleaved, medians reported. It also checks that the 2-process state is
the 1-thread state byte for byte (the test asks that on a small bed; this is the benchmark's size).
Run it on a quiet machine: two processes share two cores.

Usage (after tools/build.sh): tools/bench_ranks.py [N]
Writes reports/bench_ranks.json and reports/bench_ranks.md.
"""
import filecmp
import json
import os
import shutil
import statistics
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_cores import lammps, timed  # noqa: E402
from bench_dense import DT, FRICTION, SETTLE, STEPS, TOP, lammps_translation, settled_case  # noqa: E402

WORK = "/tmp/silodem_bench_ranks"
ROUNDS = 3
SILODEM = os.path.join(TOP, "build", "silodem")
SILODEM_MPI = os.path.join(TOP, "build", "silodem-mpi")
MPIRUN = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np"]


def silodem_job(case, tag, threads=None, ranks=None):
    out = os.path.join(WORK, "silodem_%s" % tag)
    if ranks:
        cmd = MPIRUN + [str(ranks), SILODEM_MPI, "run", case, "--out", out, "--quiet"]
    else:
        cmd = [SILODEM, "run", case, "--out", out, "--threads", str(threads), "--quiet"]
    return cmd, lambda: json.load(open(os.path.join(out, "summary.json")))["run"]["loop_seconds"]


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 5000
    if not os.path.exists(SILODEM_MPI):
        sys.exit("bench_ranks: %s is not built (libopenmpi-dev missing? tools/setup.sh installs it)" % SILODEM_MPI)
    os.makedirs(WORK, exist_ok=True)
    bed = settled_case(n, WORK, SETTLE, "ranks_bed_%d" % n)
    bed["contact"]["tangential"] = "linear_history"
    for m in bed["materials"].values():
        m.update(FRICTION)
    bed["time"] = {"dt": DT, "duration": DT * STEPS}
    bed["output"] = {"series_interval": 1.0}
    bed["compare"] = {"codes": ["silodem", "lammps"], "checks": [{"type": "energy_terms"}], "time_limit_s": 7200}
    case = os.path.join(WORK, "bed_%d.json" % n)
    json.dump(bed, open(case, "w"))
    src = lammps_translation(case, bed["name"], os.path.join(WORK, "compare"))
    jobs = {
        "silodem_1_thread": lambda: silodem_job(case, "t1", threads=1),
        "silodem_2_threads": lambda: silodem_job(case, "t2", threads=2),
        "silodem_mpi_1_process": lambda: silodem_job(case, "p1", ranks=1),
        "silodem_mpi_2_processes": lambda: silodem_job(case, "p2", ranks=2),
    }
    if src:
        jobs["lammps_1_rank"] = lambda: lammps(src, 1, None, "r1")
        jobs["lammps_2_ranks"] = lambda: lammps(src, 2, None, "r2")
    seconds = {k: [] for k in jobs}
    for _ in range(ROUNDS):
        for k, make in jobs.items():
            seconds[k].append(timed(make()))
    med = {k: statistics.median(v) for k, v in seconds.items()}
    same = filecmp.cmp(os.path.join(WORK, "silodem_t1", "state.sds"), os.path.join(WORK, "silodem_p2", "state.sds"),
                       shallow=False)
    p2 = json.load(open(os.path.join(WORK, "silodem_p2", "summary.json")))["run"]
    result = {"measured": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), "mobile": n, "steps": STEPS,
              "rounds": ROUNDS, "seconds": seconds, "median": med, "two_process_state_equals_one_thread": same,
              "redistributions_on_2_processes": p2["redistributions"], "commands": "tools/bench_ranks.py %d" % n}
    rep = os.path.join(TOP, "reports")
    json.dump(result, open(os.path.join(rep, "bench_ranks.json"), "w"), indent=1)
    base = med["silodem_1_thread"]
    md = ["# silodem over MPI processes", "",
          "Measured %s by `%s`: the settled %d-ball anchor bed of tools/bench_dense.py with friction (linear "
          "tangential springs), %d steps, loop seconds (silodem `run.loop_seconds`, LAMMPS `Loop time`), median of "
          "%d interleaved rounds, on this machine's 2 cores." % (result["measured"], result["commands"], n, STEPS, ROUNDS),
          "", "| run | loop seconds | speed-up over 1 thread/rank |", "|---|---|---|"]
    for k, v in med.items():
        ref = med["lammps_1_rank"] if k.startswith("lammps") else base
        md.append("| %s | %.2f | %.2f |" % (k.replace("_", " "), v, ref / v))
    md += ["", "The 2-process state.sds equals the 1-thread one byte for byte: %s. Redistributions on 2 processes: %d "
           "in %d steps." % ("yes" if same else "NO", p2["redistributions"], STEPS)]
    if src:
        md.append("silodem-mpi on 2 processes against LAMMPS on 2 ranks: %.2f × as fast." %
                  (med["lammps_2_ranks"] / med["silodem_mpi_2_processes"]))
    md.append("")
    open(os.path.join(rep, "bench_ranks.md"), "w").write("\n".join(md))
    print("\n".join(md))
    shutil.rmtree(os.path.join(WORK, "compare"), ignore_errors=True)


if __name__ == "__main__":
    main()
