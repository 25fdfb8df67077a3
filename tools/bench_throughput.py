#!/usr/bin/python3
"""Throughput of silodem and LAMMPS on the same scene, measured in the same run (issue 5, first
figures): polydisperse frictionless Kelvin-Voigt balls collapsing from a loose lattice into a box
of fixed wall balls, velocity Verlet with the half-step dashpot in both codes (the scheme LAMMPS
uses), identical k, c, dt, skin and step count. Writes reports/benchmarks.md and .json.
Usage (after tools/build.sh): tools/bench_throughput.py [N ...]   (default 5000 20000)
"""
import json
import math
import os
import random
import subprocess
import sys
import time

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SILODEM = os.path.join(TOP, "build", "silodem")
STEPS = 20000


def scene(n_mobile, seed=1):
    rng = random.Random(seed)
    side = 0.0105 * math.ceil(math.sqrt(n_mobile / 40.0)) + 0.02   # ~40 layers of balls
    balls, ws, k = [], 0.008, 0
    m = int(side / ws) + 1
    def wall(x, y, z):
        nonlocal k
        balls.append({"id": "w%d" % k, "material": "wall", "radius": 0.005, "position": [x, y, z], "fixed": True})
        k += 1
    height = 0.0105 * (n_mobile / (int((side - 0.02) / 0.0105) ** 2) + 2)
    for i in range(m):
        for j in range(m):
            wall(-side / 2 + i * ws, -side / 2 + j * ws, 0.0)
    for h in range(1, int(height / ws) + 2):
        for i in range(m):
            wall(-side / 2 + i * ws, -side / 2, h * ws)
            wall(-side / 2 + i * ws, side / 2, h * ws)
            if 0 < i < m - 1:
                wall(-side / 2, -side / 2 + i * ws, h * ws)
                wall(side / 2, -side / 2 + i * ws, h * ws)
    nx = int((side - 0.02) / 0.0105)
    z, count = 0.012, 0
    while count < n_mobile:
        for i in range(nx):
            for j in range(nx):
                if count < n_mobile:
                    balls.append({"id": "b%d" % count, "material": "grain", "radius": rng.uniform(0.004, 0.005),
                                  "position": [-side / 2 + 0.01 + i * 0.0105, -side / 2 + 0.01 + j * 0.0105, z]})
                    count += 1
        z += 0.0105
    return {"name": "bench_%d" % n_mobile, "seed": seed,
            "materials": {"grain": {"density": 2500, "stiffness": 2e5, "damping": 1.0},
                          "wall": {"density": 2500, "stiffness": 2e5, "damping": 1.0}},
            "balls": balls, "integrator": {"scheme": "velocity_verlet", "dashpot_velocity": "half_step"},
            "time": {"dt": 2e-5, "duration": 2e-5 * STEPS}, "neighbour": {"skin": 0.001},
            "output": {"series_interval": 0.01, "dump_interval_steps": STEPS},
            "compare": {"codes": ["silodem", "lammps"], "checks": [{"type": "energy_balance", "tolerance": 1.0}],
                        "time_limit_s": 1800}}


def main():
    sizes = [int(a) for a in sys.argv[1:]] or [5000, 20000]
    rows = []
    for n in sizes:
        case = scene(n)
        path = "/tmp/silodem_bench_%d.json" % n
        with open(path, "w") as f:
            json.dump(case, f)
        out = "/tmp/silodem_bench_out"
        subprocess.run([SILODEM, "compare", path, "--out", out, "--quiet"], check=False, stdout=subprocess.DEVNULL)
        row = {"mobile": n, "wall": sum(1 for b in case["balls"] if b.get("fixed")), "steps": STEPS}
        for code in ("silodem", "lammps"):
            with open(os.path.join(out, case["name"], "base", code, "summary.json")) as f:
                s = json.load(f)
            secs = s["run"]["wall_seconds"]
            row[code + "_seconds"] = secs
            row[code + "_mps"] = n * STEPS / secs / 1e6
        row["ratio"] = row["silodem_mps"] / row["lammps_mps"]
        rows.append(row)
        print("N = %d: silodem %.2f M mobile particle-steps/s, LAMMPS %.2f, ratio %.2f"
              % (n, row["silodem_mps"], row["lammps_mps"], row["ratio"]))
    stamp = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
    with open(os.path.join(TOP, "reports", "benchmarks.json"), "w") as f:
        json.dump({"date": stamp, "rows": rows}, f, indent=1)
    with open(os.path.join(TOP, "reports", "benchmarks.md"), "w") as f:
        f.write("# Throughput: silodem against LAMMPS, same scene, same run\n\n"
                "Measured %s by `tools/bench_throughput.py` on this 2-core machine (1 thread / 1 MPI rank). "
                "Scene: frictionless Kelvin-Voigt balls (r 4-5 mm) collapsing from a loose lattice into a box of "
                "fixed wall balls over %d steps (dt = 2e-5 s: free fall, impact, then the dense bed; skin 1 mm), "
                "velocity Verlet with the half-step dashpot in both codes. Rates over the whole run (LAMMPS: "
                "process start to end, including reading its data file; silodem: in process); the dense-bed "
                "segment alone is measured by tools/bench_dense.py (reports/bench_dense.md). Single runs: expect "
                "about 10 %% scatter (run-to-run spread measured on this shared machine in the anchor runs of "
                "2026-11-21).\n\n"
                "| mobile balls | wall balls | silodem s | LAMMPS s | silodem Mps/s | LAMMPS Mps/s | ratio |\n"
                "|---|---|---|---|---|---|---|\n" % (stamp, STEPS))
        for r in rows:
            f.write("| %d | %d | %.2f | %.2f | %.2f | %.2f | %.2f |\n" % (r["mobile"], r["wall"], r["silodem_seconds"],
                    r["lammps_seconds"], r["silodem_mps"], r["lammps_mps"], r["ratio"]))


if __name__ == "__main__":
    main()
