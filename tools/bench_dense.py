#!/usr/bin/python3
"""Dense-bed throughput against the reference codes, measured side by side in one run (issue 5 §1).

The scene is the project's settling anchor, on which LAMMPS, LIGGGHTS and YADE were first timed
on this machine (2026-11-21: 20,000 mobile balls on a loose 25 x 25 x 32 lattice in a closed box
0.32 x 0.32 x 0.41 m of 7,298 fixed wall balls, 20,000 steps; the bed settles by step 7,500 with
about 6 contacts per ball), here scaled to N mobile balls: radii uniform in [4.5, 5.5] mm, density 2500, a loose 12 mm lattice in a closed box of fixed
wall balls (r 5 mm on a 10 mm grid), pair k = 1e4 N/m and c = 1.1024 N s/m (per ball 2e4 and
2.2048, in series (11)), clamped (YADE's law; LAMMPS limit_damping), dt = 4e-5 s, skin 1 mm,
velocity Verlet with the half-step dashpot (the scheme of the reference codes).

1. silodem settles the lattice for SETTLE steps (2 threads; not timed) -> a dense bed.
2. From that state every code runs STEPS more steps, REPEATS times; the median is reported:
   silodem 1 and 2 threads (`run --threads`, summary.json `run.loop_seconds`: the step loop alone,
   as the reference codes' `Loop time`), LAMMPS 1 and 2 MPI
   ranks (`Loop time` of its log; 2 ranks split along x with `processors * 1 1`), LIGGGHTS 1 rank
   (`Loop time`), YADE 1 thread (wall time of its run; only for N <= YADE_MAX_N: 0.3 Mps/s).
   The LAMMPS, LIGGGHTS and YADE inputs are the harness adapters' own translations
   (`silodem compare`), so every code integrates the same physics from the same state.
3. Peak RSS of each silodem run (/usr/bin/time), and the solver's own count of the bytes it
   holds per mobile ball and per neighbour-list pair (summary.json "memory").

4. The same bed and protocol frictional: Coulomb friction mu = 0.5 with a linear history spring
   k_t = 2/7 k_n (no tangential dashpot), grains rotating (`contact.tangential: "linear_history"`),
   every code from the harness adapters' own translation (LAMMPS `pair granular ... tangential
   linear_history`, LIGGGHTS `tangential history`, YADE ViscElMat with ks): the frictionless and
   frictional rows side by side in one report.

Usage (after tools/build.sh): tools/bench_dense.py [N ...]   (default 5000 20000)
Writes reports/bench_dense.json and reports/bench_dense.md. Run on a quiet machine.
"""
import json
import math
import os
import random
import re
import shutil
import statistics
import subprocess
import sys
import time

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SILODEM = os.path.join(TOP, "build", "silodem")
WORK = "/tmp/silodem_bench_dense"
DT, SETTLE, STEPS, REPEATS, YADE_MAX_N = 4e-5, 10000, 5000, 3, 5000


def scene(n, seed=1):
    """The anchor scene with about 25 x 25 balls per layer at N = 20,000, scaled in x and y."""
    rng = random.Random(seed)
    per_side = max(4, round(25 * math.sqrt(n / 20000.0)))
    layers = math.ceil(n / per_side ** 2)
    inner = per_side * 0.012 + 0.02
    height = layers * 0.012 + 0.05
    balls = []

    def wall(x, y, z):
        balls.append({"id": "w%d" % len(balls), "material": "wall", "radius": 0.005, "position": [x, y, z],
                      "fixed": True})
    m, h = int(round(inner / 0.01)) + 1, int(round(height / 0.01)) + 1
    for i in range(m):
        for j in range(m):
            wall(-inner / 2 + i * 0.01, -inner / 2 + j * 0.01, 0.0)
            wall(-inner / 2 + i * 0.01, -inner / 2 + j * 0.01, (h - 1) * 0.01)
    for k in range(1, h - 1):
        for i in range(m):
            wall(-inner / 2 + i * 0.01, -inner / 2, k * 0.01)
            wall(-inner / 2 + i * 0.01, inner / 2, k * 0.01)
            if 0 < i < m - 1:
                wall(-inner / 2, -inner / 2 + i * 0.01, k * 0.01)
                wall(inner / 2, -inner / 2 + i * 0.01, k * 0.01)
    count = 0
    for k in range(layers):
        for i in range(per_side):
            for j in range(per_side):
                if count < n:
                    balls.append({"id": "b%d" % count, "material": "grain", "radius": rng.uniform(0.0045, 0.0055),
                                  "position": [-inner / 2 + 0.016 + i * 0.012, -inner / 2 + 0.016 + j * 0.012,
                                               0.016 + k * 0.012]})
                    count += 1
    return {"format": "silodem-case/1", "name": "dense_%d" % n, "seed": seed, "gravity": [0, 0, -9.81],
            "materials": {"grain": {"density": 2500, "stiffness": 2e4, "damping": 2.2048},
                          "wall": {"density": 2500, "stiffness": 2e4, "damping": 2.2048}},
            "contact": {"clamp_tensile_force": True},
            "balls": balls, "integrator": {"scheme": "velocity_verlet", "dashpot_velocity": "half_step"},
            "time": {"dt": DT, "duration": DT * SETTLE}, "neighbour": {"skin": 0.001},
            "output": {"series_interval": 1.0}}


def run(cmd, cwd=None):
    """Runs cmd under /usr/bin/time; returns (stdout+stderr text, peak RSS in bytes)."""
    p = subprocess.run(["/usr/bin/time", "-f", "RSS_KB=%M"] + cmd, cwd=cwd, capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError("%s failed (%d): %s" % (" ".join(cmd), p.returncode, (p.stdout + p.stderr)[-2000:]))
    rss = re.findall(r"RSS_KB=(\d+)", p.stderr)
    return p.stdout + p.stderr, int(rss[-1]) * 1024 if rss else 0


def lammps_timing_input(text, ranks):
    """The adapter's LAMMPS input for a timed run: no dumps, and with 2 ranks split along x
    (`processors * 1 1`: the default split, along z, would put the settled bed in one rank)."""
    text = re.sub(r"^dump .*$|^dump_modify .*$", "", text, flags=re.M)
    if ranks == 2:
        text = re.sub(r"^(units .*)$", r"\1\nprocessors * 1 1", text, count=1, flags=re.M)
    return text


def lammps_translation(case_path, name, out, code="lammps"):
    """The harness adapter's translation of the case file for `code` (lammps or liggghts:
    `silodem compare --codes CODE` into `out`): the directory holding its input (in.lammps or
    in.liggghts) and data.lmp, or None if none was written (the code missing, or the run failed;
    `out` keeps the log)."""
    shutil.rmtree(out, ignore_errors=True)
    subprocess.run([SILODEM, "compare", case_path, "--codes", code, "--out", out, "--quiet"],
                   stdout=subprocess.DEVNULL, check=False)
    src = os.path.join(out, name, "base", code)
    return src if os.path.exists(os.path.join(src, "in." + code)) else None


def loop_time(log):
    m = re.findall(r"Loop time of ([0-9.eE+-]+) on (\d+) procs", open(log).read())
    if not m:
        raise RuntimeError("no 'Loop time' in " + log)
    return float(m[-1][0])


def settled_case(n, work, settle_steps, name):
    """The anchor scene at n balls, settled by silodem for settle_steps on 2 threads (not timed):
    the case with its balls replaced by the settled state."""
    os.makedirs(work, exist_ok=True)
    case = scene(n)
    case["time"] = {"dt": DT, "duration": DT * settle_steps}
    settle_path = os.path.join(work, "settle_%d.json" % n)
    settled = os.path.join(work, "settled_%d" % n)
    text = json.dumps(case)
    # The same settling case already run (the frictional rows start from the frictionless bed's state).
    if not (os.path.exists(settle_path) and open(settle_path).read() == text
            and os.path.exists(os.path.join(settled, "state.json"))):
        open(settle_path, "w").write(text)
        shutil.rmtree(settled, ignore_errors=True)
        run([SILODEM, "run", settle_path, "--out", settled, "--threads", "2", "--quiet"])
    state = json.load(open(os.path.join(settled, "state.json")))
    case["name"] = name
    case["balls"] = [{k: b[k] for k in ("id", "material", "radius", "position", "velocity", "fixed") if k in b}
                     for b in state["balls"]]
    return case


FRICTION = {"friction": 0.5, "shear_stiffness_ratio": 2.0 / 7.0}


def measure(n, frictional):
    case = scene(n)
    dense = settled_case(n, WORK, SETTLE, ("friction_bed_%d" if frictional else "dense_bed_%d") % n)
    if frictional:
        dense["contact"]["tangential"] = "linear_history"
        for m in dense["materials"].values():
            m.update(FRICTION)
    dense["time"] = {"dt": DT, "duration": DT * STEPS}
    dense["output"] = {"series_interval": 1.0, "dump_interval_steps": STEPS}
    codes = ["silodem", "lammps", "liggghts"] + (["yade"] if n <= YADE_MAX_N else [])
    # energy_terms, not energy_balance: a ledger rebuilt from one frame per run is refused (docs/case-format.md).
    dense["compare"] = {"codes": codes, "checks": [{"type": "energy_terms"}], "time_limit_s": 7200}
    dense_path = os.path.join(WORK, "%s.json" % dense["name"])
    json.dump(dense, open(dense_path, "w"))
    contacts = None
    times = {k: [] for k in ("silodem_1", "silodem_2", "lammps_1", "lammps_2", "liggghts_1", "yade_1")}
    rss, memory = {}, {}
    for rep in range(REPEATS if n < 100000 else 2):
        for t in (1, 2):
            out = os.path.join(WORK, "silodem_%d_%d" % (n, t))
            _, rss["silodem_%d" % t] = run([SILODEM, "run", dense_path, "--out", out, "--threads", str(t), "--quiet"])
            s = json.load(open(os.path.join(out, "summary.json")))
            times["silodem_%d" % t].append(s["run"]["loop_seconds"])
            memory = s.get("memory", {})
        cmp_out = os.path.join(WORK, "compare_%d" % n)
        shutil.rmtree(cmp_out, ignore_errors=True)
        subprocess.run([SILODEM, "compare", dense_path, "--codes", ",".join(c for c in codes if c != "silodem"),
                        "--out", cmp_out, "--quiet"], stdout=subprocess.DEVNULL)
        base = os.path.join(cmp_out, dense["name"], "base")
        times["lammps_1"].append(loop_time(os.path.join(base, "lammps", "log.txt")))
        times["liggghts_1"].append(loop_time(os.path.join(base, "liggghts", "log.txt")))
        if "yade" in codes:
            times["yade_1"].append(json.load(open(os.path.join(base, "yade", "summary.json")))["run"]["wall_seconds"])
        # 2 MPI ranks: the adapter's own input, split along x (see lammps_timing_input).
        lmp_dir = os.path.join(base, "lammps")
        text = lammps_timing_input(open(os.path.join(lmp_dir, "in.lammps")).read(), 2)
        open(os.path.join(lmp_dir, "in2.lammps"), "w").write(text)
        run(["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", "2", "lmp", "-in", "in2.lammps", "-log",
             "log2.txt", "-echo", "none", "-screen", "none"], cwd=lmp_dir)
        times["lammps_2"].append(loop_time(os.path.join(lmp_dir, "log2.txt")))
        if contacts is None:
            series = open(os.path.join(WORK, "silodem_%d_1" % n, "series.csv")).read().splitlines()
            head = series[0].split(",")
            contacts = float(series[-1].split(",")[head.index("contacts")]) / n
    row = {"contact": "linear_history mu 0.5" if frictional else "frictionless", "mobile": n, "wall": sum(1 for b in case["balls"] if b.get("fixed")), "steps": STEPS,
           "contacts_per_ball": contacts, "repeats": REPEATS if n < 100000 else 2, "rss_bytes": rss, "memory": memory, "seconds": {}, "mps": {}}
    for k, v in times.items():
        if v:
            row["seconds"][k] = {"median": statistics.median(v), "all": v}
            row["mps"][k] = n * STEPS / statistics.median(v) / 1e6
    row["ratio_1"] = row["mps"]["silodem_1"] / row["mps"]["lammps_1"]
    row["ratio_2"] = row["mps"]["silodem_2"] / row["mps"]["lammps_2"]
    return row


def main():
    sizes = [int(a) for a in sys.argv[1:]] or [5000, 20000]
    cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "?")
    rows = []
    for n in sizes:
        for frictional in (False, True):
            r = measure(n, frictional)
            rows.append(r)
            print("N = %d %s: %s; silodem/LAMMPS 1 thread/rank %.2f, 2 threads/ranks %.2f"
                  % (n, r["contact"], ", ".join("%s %.2f Mps/s" % kv for kv in r["mps"].items()), r["ratio_1"],
                     r["ratio_2"]), flush=True)
    stamp = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
    json.dump({"date": stamp, "cpu": cpu, "cores": os.cpu_count(), "rows": rows},
              open(os.path.join(TOP, "reports", "bench_dense.json"), "w"), indent=1)
    with open(os.path.join(TOP, "reports", "bench_dense.md"), "w") as f:
        f.write("# Dense-bed throughput: silodem against LAMMPS, LIGGGHTS and YADE, same state, same run\n\n"
                "Measured %s by `tools/bench_dense.py %s` on %d cores (%s). Scene and protocol: the script's "
                "docstring (the settling anchor scene, settled by silodem, then %d steps from that state "
                "in every code). Median of %d repeats (2 at N ≥ 100,000); Mps/s = mobile balls x steps / loop seconds.\n\n"
                "| contact law | mobile | wall | contact pairs/ball | silodem 1 thr | silodem 2 thr | LAMMPS 1 rank | LAMMPS 2 ranks "
                "| LIGGGHTS 1 rank | YADE 1 thr | silodem/LAMMPS 1 | silodem/LAMMPS 2 | silodem peak RSS / ball |\n"
                "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n"
                % (stamp, " ".join(map(str, sizes)), os.cpu_count(), cpu, STEPS, REPEATS))
        for r in rows:
            g = lambda k: "%.2f" % r["mps"][k] if k in r["mps"] else "—"
            f.write("| %s | %d | %d | %.2f | %s | %s | %s | %s | %s | %s | %.2f | %.2f | %.0f B |\n" % (
                r["contact"], r["mobile"], r["wall"], r["contacts_per_ball"], g("silodem_1"), g("silodem_2"), g("lammps_1"),
                g("lammps_2"), g("liggghts_1"), g("yade_1"), r["ratio_1"], r["ratio_2"],
                r["rss_bytes"].get("silodem_1", 0) / r["mobile"]))
        f.write("\nPeak RSS includes the parsed case file (every ball as JSON). The solver's own arrays: "
                + "; ".join("N = %d %s: %s" % (r["mobile"], r["contact"], json.dumps(r["memory"])) for r in rows) + "\n")


if __name__ == "__main__":
    main()
