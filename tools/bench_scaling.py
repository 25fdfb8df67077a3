#!/usr/bin/python3
"""Cost per step against N, silodem alone (issue 5 §1: linear in N from 5,000 to 1,000,000 within 20 %).

The anchor scene of tools/bench_dense.py at each N (wider boxes, the same 32-odd layers, so every
size has the same depth profile), settled as bench_dense settles it (SETTLE steps on 2 threads, not
timed), then STEPS timed steps on 1 thread from that state, REPEATS times at N >= 100,000 and more
often below (up to 30 times: 400 steps of 5,000 balls last 0.15 s, and single runs that short
scatter), once at N >= 1,000,000. By then every size has come to the same packing: about 3
contacts and 4.5 list pairs per ball (bench_dense's 5,000 to 100,000 beds: 2.95-2.97 contacts). A
shorter settling (4,000 steps, used up to 2026-12-01) caught the beds still falling, and the wider
ones further along (1.32 contacts per ball at 5,000, 1.60 at 10^6), so their cost grew with the
work asked, not only with N. Figure: loop seconds per mobile ball-step (summary.json
run.loop_seconds / N / steps), with the contacts per ball and list pairs per ball at the end of
the timed run so that a change in cost can be told from a change in the packing; peak RSS and the
solver's own bytes per mobile ball. The timed runs are pinned to CPU 0 (taskset, where present):
unpinned, the same one-thread run on this 2-vCPU VM took 1.35 s or 1.95 s depending on the core it
landed on (reports/perf_experiments.md).

A control series holds the work per ball fixed: the smallest bed tiled into N / N_0 independent
boxes (same contacts, list pairs and rebuilds per ball, same sweep front), so that the part of the
growth due to the data leaving the caches is told from the part due to the wider scene.

Usage (after tools/build.sh): tools/bench_scaling.py [N ...]   (default 5000 20000 100000 1000000)
Writes reports/bench_scaling.json and reports/bench_scaling.md. Run on a quiet machine; the
1,000,000 size needs about 15 minutes and 3 GB.
"""
import json
import os
import shutil
import statistics
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_dense import DT, SETTLE, SILODEM, TOP, run, settled_case  # noqa: E402

WORK = "/tmp/silodem_bench_scaling"
PIN = ["taskset", "-c", "0"] if shutil.which("taskset") else []
STEPS, REPEATS = 400, 3


def tiled(base, copies):
    """`copies` copies of the settled bed `base`, each in its own box, stacked along z with 5 cm
    between the boxes: N = copies x base's balls, with the same work per ball (contacts, list
    pairs, rebuilds) and the same sweep front at every N, so only the data's size grows."""
    z = [b["position"][2] for b in base["balls"]]
    pitch = max(z) - min(z) + 0.05
    case = dict(base, name="tiled_%d" % copies, balls=[])
    for q in range(copies):
        for b in base["balls"]:
            case["balls"].append(dict(b, id="%s_%d" % (b["id"], q),
                                      position=[b["position"][0], b["position"][1], b["position"][2] + q * pitch]))
    return case


def measure(n, dense, kind):
    """Times `dense` (n mobile balls; kind "dense": the wide bed, "tiled": the smallest bed tiled)."""
    steps = STEPS
    repeats = 1 if n >= 1000000 else min(30, max(REPEATS, REPEATS * 100000 // n))
    dense["time"] = {"dt": DT, "duration": DT * steps}
    dense["output"] = {"series_interval": DT * steps * 0.999}
    path = os.path.join(WORK, "%s_%d.json" % (kind, n))
    json.dump(dense, open(path, "w"))
    del dense
    out = os.path.join(WORK, "timed_%s_%d" % (kind, n))
    per_step, rss = [], 0
    for _ in range(repeats):
        _, rss = run(PIN + [SILODEM, "run", path, "--out", out, "--threads", "1", "--quiet"])
        s = json.load(open(os.path.join(out, "summary.json")))
        per_step.append(s["run"]["loop_seconds"] / s["run"]["steps"])
    series = open(os.path.join(out, "series.csv")).read().splitlines()
    head = series[0].split(",")
    contacts = float(series[-1].split(",")[head.index("contacts")]) / n
    mem = s["memory"]
    return {"mobile": n, "scene": kind, "steps": steps, "repeats": len(per_step), "seconds_per_step": statistics.median(per_step),
            "all": per_step, "ns_per_ball_step": statistics.median(per_step) / n * 1e9,
            "contacts_per_ball": contacts, "pairs_per_ball": mem["list_pairs"] / n, "rss_bytes": rss,
            "solver_bytes_per_mobile": mem["total_bytes"] / n,
            "particles_and_integrator_bytes_per_mobile": (mem["particles_bytes"] + mem["integrator_bytes"]) / n}


def table(f, rows, ref):
    f.write("| mobile | repeats | ns per ball-step | relative to N = %d | contacts/ball | list pairs/ball "
            "| solver bytes/mobile ball | of which balls + integrator | peak RSS/mobile ball |\n"
            "|---|---|---|---|---|---|---|---|---|\n" % ref["mobile"])
    for r in rows:
        f.write("| %d | %d | %.1f | %.3f | %.2f | %.2f | %.0f | %.0f | %.0f |\n" % (
            r["mobile"], r["repeats"], r["ns_per_ball_step"], r["ns_per_ball_step"] / ref["ns_per_ball_step"],
            r["contacts_per_ball"], r["pairs_per_ball"], r["solver_bytes_per_mobile"],
            r["particles_and_integrator_bytes_per_mobile"], r["rss_bytes"] / r["mobile"]))


def spread(rows):
    return max(r["ns_per_ball_step"] for r in rows) / min(r["ns_per_ball_step"] for r in rows) - 1.0


def main():
    sizes = [int(a) for a in sys.argv[1:]] or [5000, 20000, 100000, 1000000]
    rows = []
    base = settled_case(sizes[0], WORK, SETTLE, "scaling_%d" % sizes[0])
    for n in sizes:
        r = measure(n, dict(base) if n == sizes[0] else settled_case(n, WORK, SETTLE, "scaling_%d" % n), "dense")
        rows.append(r)
        print("N = %d: %.1f ns per ball-step, %.2f contacts/ball, %.0f B/ball in the solver" %
              (n, r["ns_per_ball_step"], r["contacts_per_ball"], r["solver_bytes_per_mobile"]), flush=True)
    tiled_rows = [rows[0]]
    for n in sizes[1:]:
        if n % sizes[0] == 0:
            r = measure(n, tiled(base, n // sizes[0]), "tiled")
            tiled_rows.append(r)
            print("N = %d tiled: %.1f ns per ball-step, %.2f contacts/ball" % (n, r["ns_per_ball_step"],
                                                                              r["contacts_per_ball"]), flush=True)
    stamp = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
    json.dump({"date": stamp, "rows": rows, "spread": spread(rows), "tiled_rows": tiled_rows[1:],
               "tiled_spread": spread(tiled_rows)},
              open(os.path.join(TOP, "reports", "bench_scaling.json"), "w"), indent=1)
    with open(os.path.join(TOP, "reports", "bench_scaling.md"), "w") as f:
        f.write("# Cost per step against N (silodem, 1 thread)\n\nMeasured %s by `tools/bench_scaling.py %s`: the anchor "
                "scene at each N, settled %d steps on 2 threads, then %d timed steps on 1 thread pinned to CPU 0 (median of %d repeats "
                "at N ≥ 100,000, up to 30 below (column `repeats`), "
                "1 at N ≥ 10^6). Linear cost means a constant time per ball-step; target: within 20 %% from 5,000 to "
                "1,000,000.\n\n" % (stamp, " ".join(map(str, sizes)), SETTLE, STEPS, REPEATS))
        table(f, rows, rows[0])
        f.write("\nLargest over smallest cost per ball-step − 1: %.3f (%s the 20 %% target). Peak RSS includes the "
                "parsed case file (every ball as JSON).\n" % (spread(rows), "within" if spread(rows) <= 0.2 else "outside"))
        f.write("\n## The same work per ball at every N\n\nThe wider beds above end the timed run with more contacts "
                "per ball than the smallest (column contacts/ball) and have a longer sweep front. Here the %d-ball bed, settled as above, is copied into N / %d boxes stacked along z "
                "(5 cm apart, no contact between copies): every ball has the same partners and the list is rebuilt at "
                "the same steps, so what changes with N is only how far the data is from the core (caches against "
                "memory). Timed as above; the first row is the %d-ball bed of the table above.\n\n" %
                (sizes[0], sizes[0], sizes[0]))
        table(f, tiled_rows, rows[0])
        f.write("\nLargest over smallest cost per ball-step − 1, tiled: %.3f.\n" % spread(tiled_rows))


if __name__ == "__main__":
    main()
