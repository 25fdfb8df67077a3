#!/usr/bin/python3
"""The frictionless speed before and after a change, measured in one interleaved run (issue 27 §4:
a frictionless scene must stay within noise, <= 2 %, of its former speed).

The anchor dense bed of tools/bench_dense.py at N balls is settled once by the NEW binary; from
that state each binary runs STEPS steps on 1 thread, alternately, REPEATS times; the figure is the
median of summary.json run.loop_seconds (the step loop alone). The noise figure is each binary's
own spread (max - min)/median.

With --friction the same bed runs with Coulomb friction mu = 0.5 and a linear history spring
k_t = 2/7 k_n (the scene of tools/bench_friction.py), to measure a change to the frictional loop.

Usage: tools/bench_before_after.py [--friction] OLD_SILODEM NEW_SILODEM [N] [STEPS] [REPEATS]
       (defaults 20000 2000 5). Prints a Markdown table; record it in reports/.
"""
import json
import os
import statistics
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bench_dense  # noqa: E402  (the anchor scene and its settling)

WORK = "/tmp/silodem_bench_before_after"


def loop_seconds(binary, case_path, out):
    subprocess.run([binary, "run", case_path, "--out", out, "--quiet"], check=True, capture_output=True)
    s = json.load(open(os.path.join(out, "summary.json")))
    return s["run"]["loop_seconds"], s["run"]["steps"]


def main():
    args = sys.argv[1:]
    friction = "--friction" in args
    args = [a for a in args if a != "--friction"]
    old, new = args[0], args[1]
    n = int(args[2]) if len(args) > 2 else 20000
    steps = int(args[3]) if len(args) > 3 else 2000
    repeats = int(args[4]) if len(args) > 4 else 5
    os.makedirs(WORK, exist_ok=True)
    bench_dense.SILODEM = new
    dense = bench_dense.settled_case(n, WORK, bench_dense.SETTLE, "before_after_%d" % n)
    dense["time"]["duration"] = bench_dense.DT * steps * (1 + 1e-9)
    if friction:
        dense["contact"]["tangential"] = "linear_history"
        for m in dense["materials"].values():
            m["friction"], m["shear_stiffness_ratio"] = 0.5, 2.0 / 7.0
    path = os.path.join(WORK, "dense.json")
    json.dump(dense, open(path, "w"))
    times = {"before": [], "after": []}
    for k in range(repeats):
        for label, binary in (("before", old), ("after", new)) if k % 2 == 0 else (("after", new), ("before", old)):
            t, done = loop_seconds(binary, path, os.path.join(WORK, "out_" + label))
            times[label].append(t / done)
    med = {k: statistics.median(v) for k, v in times.items()}
    print("| binary | ms per step (median of %d) | spread | / before - 1 |" % repeats)
    print("|---|---|---|---|")
    for label in ("before", "after"):
        v = times[label]
        print("| %s | %.4f | %.1f %% | %+.1f %% |" % (label, 1e3 * med[label], 100 * (max(v) - min(v)) / med[label],
                                                     100 * (med[label] / med["before"] - 1)))
    print("\n%d mobile balls, %s, %d steps per run, 1 thread; per-run ms/step: %s" %
          (n, "mu = 0.5, linear history" if friction else "frictionless", steps, {k: [round(1e3 * x, 4) for x in v] for k, v in times.items()}))


if __name__ == "__main__":
    main()
