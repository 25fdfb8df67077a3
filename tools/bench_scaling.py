#!/usr/bin/python3
"""Cost per step against N, silodem alone (issue 5 §1: linear in N from 5,000 to 1,000,000 within 20 %).

The anchor scene of tools/bench_dense.py at each N (wider boxes, the same 32-odd layers, so every
size has the same depth profile), settled for SETTLE steps on 2 threads (not timed), then STEPS
timed steps on 1 thread from that state, REPEATS times at N >= 100,000 and more often below (up to
30 times: 400 steps of 5,000 balls last 0.15 s, and single runs that short scatter), once at
N >= 1,000,000. The same STEPS at every N: the bed is still settling, so a longer run would end
denser (at 8,000 steps the 5,000-ball bed had 2.8 contacts per ball instead of 1.3). Figure: loop
seconds per mobile ball-step (summary.json run.loop_seconds / N / steps), with the contacts per
ball and list pairs per ball at the end of the timed run so that a change in cost can be told
from a change in the packing; peak RSS and the solver's own bytes per mobile ball. The timed runs
are pinned to CPU 0 (taskset, where present): unpinned, the same one-thread run on this 2-vCPU VM
took 1.35 s or 1.95 s depending on the core it landed on (reports/perf_experiments.md).

Usage (after tools/build.sh): tools/bench_scaling.py [N ...]   (default 5000 20000 100000 1000000)
Writes reports/bench_scaling.json and reports/bench_scaling.md. Run on a quiet machine; the
1,000,000 size needs about 10 minutes and 3 GB.
"""
import json
import os
import shutil
import statistics
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_dense import DT, SILODEM, TOP, run, settled_case  # noqa: E402

WORK = "/tmp/silodem_bench_scaling"
PIN = ["taskset", "-c", "0"] if shutil.which("taskset") else []
SETTLE, STEPS, REPEATS = 4000, 400, 3


def measure(n):
    steps = STEPS
    repeats = 1 if n >= 1000000 else min(30, max(REPEATS, REPEATS * 100000 // n))
    dense = settled_case(n, WORK, SETTLE, "scaling_%d" % n)
    dense["time"] = {"dt": DT, "duration": DT * steps}
    dense["output"] = {"series_interval": DT * steps * 0.999}
    path = os.path.join(WORK, "dense_%d.json" % n)
    json.dump(dense, open(path, "w"))
    del dense
    out = os.path.join(WORK, "timed_%d" % n)
    per_step, rss = [], 0
    for _ in range(repeats):
        _, rss = run(PIN + [SILODEM, "run", path, "--out", out, "--threads", "1", "--quiet"])
        s = json.load(open(os.path.join(out, "summary.json")))
        per_step.append(s["run"]["loop_seconds"] / s["run"]["steps"])
    series = open(os.path.join(out, "series.csv")).read().splitlines()
    head = series[0].split(",")
    contacts = float(series[-1].split(",")[head.index("contacts")]) / n
    mem = s["memory"]
    return {"mobile": n, "steps": steps, "repeats": len(per_step), "seconds_per_step": statistics.median(per_step),
            "all": per_step, "ns_per_ball_step": statistics.median(per_step) / n * 1e9,
            "contacts_per_ball": contacts, "pairs_per_ball": mem["list_pairs"] / n, "rss_bytes": rss,
            "solver_bytes_per_mobile": mem["total_bytes"] / n,
            "particles_and_integrator_bytes_per_mobile": (mem["particles_bytes"] + mem["integrator_bytes"]) / n}


def main():
    sizes = [int(a) for a in sys.argv[1:]] or [5000, 20000, 100000, 1000000]
    rows = []
    for n in sizes:
        r = measure(n)
        rows.append(r)
        print("N = %d: %.1f ns per ball-step, %.2f contacts/ball, %.0f B/ball in the solver" %
              (n, r["ns_per_ball_step"], r["contacts_per_ball"], r["solver_bytes_per_mobile"]), flush=True)
    ref = rows[0]["ns_per_ball_step"]
    spread = max(r["ns_per_ball_step"] for r in rows) / min(r["ns_per_ball_step"] for r in rows) - 1.0
    stamp = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
    json.dump({"date": stamp, "rows": rows, "spread": spread}, open(os.path.join(TOP, "reports", "bench_scaling.json"), "w"),
              indent=1)
    with open(os.path.join(TOP, "reports", "bench_scaling.md"), "w") as f:
        f.write("# Cost per step against N (silodem, 1 thread)\n\nMeasured %s by `tools/bench_scaling.py %s`: the anchor "
                "scene at each N, settled %d steps on 2 threads, then %d timed steps on 1 thread pinned to CPU 0 (median of %d repeats "
                "at N ≥ 100,000, up to 30 below (column `repeats`), "
                "1 at N ≥ 10^6). Linear cost means a constant time per ball-step; target: within 20 %% from 5,000 to "
                "1,000,000.\n\n| mobile | repeats | ns per ball-step | relative to N = %d | contacts/ball | list pairs/ball "
                "| solver bytes/mobile ball | of which balls + integrator | peak RSS/mobile ball |\n"
                "|---|---|---|---|---|---|---|---|---|\n" % (stamp, " ".join(map(str, sizes)), SETTLE, STEPS, REPEATS,
                                                         rows[0]["mobile"]))
        for r in rows:
            f.write("| %d | %d | %.1f | %.3f | %.2f | %.2f | %.0f | %.0f | %.0f |\n" % (
                r["mobile"], r["repeats"], r["ns_per_ball_step"], r["ns_per_ball_step"] / ref, r["contacts_per_ball"],
                r["pairs_per_ball"], r["solver_bytes_per_mobile"], r["particles_and_integrator_bytes_per_mobile"],
                r["rss_bytes"] / r["mobile"]))
        f.write("\nLargest over smallest cost per ball-step − 1: %.3f (%s the 20 %% target). Peak RSS includes the "
                "parsed case file (every ball as JSON).\n" % (spread, "within" if spread <= 0.2 else "outside"))


if __name__ == "__main__":
    main()
