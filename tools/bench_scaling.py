#!/usr/bin/python3
"""Cost per step against N, silodem alone (issue 5 §1: linear in N from 5,000 to 1,000,000 within 20 %).

The anchor scene of tools/bench_dense.py at each N (wider boxes, the same 32-odd layers, so every
size has the same depth profile), settled as bench_dense settles it (SETTLE steps on 2 threads, not
timed), then STEPS timed steps on 1 thread from that state. The timed runs go in ROUNDS rounds
over every bed in turn (beds under 100,000 balls several times a round, up to 10: 400 steps of
5,000 balls last 0.11 s, and single runs that short scatter); the figure is the median of all of
a bed's runs. Interleaving matters here: the host's speed changed by up to 2x within minutes, and
when each size ran its repeats back to back (up to 2026-12-01) one slow spell could land on one
size only (a tiled 20,000-ball bed: 57.1 ns per ball-step in one run, 79.9 in the next).

After the settling every size has come to the same packing: about 3 contacts and 4.5 list pairs per ball (bench_dense's 5,000 to 100,000 beds: 2.95-2.97 contacts). A
shorter settling (4,000 steps, used up to 2026-12-01) caught the beds still falling, and the wider
ones further along (1.32 contacts per ball at 5,000, 1.60 at 10^6), so their cost grew with the
work asked, not only with N. Figure: loop seconds per mobile ball-step (summary.json
run.loop_seconds / N / steps), with the contacts per ball and list pairs per ball at the end of
the timed run so that a change in cost can be told from a change in the packing; peak RSS and the
solver's own bytes per mobile ball. The timed runs are pinned to CPU 0 (taskset, where present):
unpinned, the same one-thread run on this 2-vCPU VM took 1.35 s or 1.95 s depending on the core it
landed on (reports/perf_experiments.md).

A control series holds the work per ball fixed: the smallest bed tiled into N / N_0 independent
boxes (same contacts and list pairs per ball, same sweep front; the rebuilds can come a little
sooner, as the two largest displacements then belong to two copies' fastest balls), so that the
part of the growth due to the data leaving the caches is told from the part due to the wider scene.
Each row also gives the solver's own split of the run's time (run.loop_breakdown_seconds:
neighbour check and builds, force loop, the rest).

LAMMPS runs the same beds in the same rounds (1 rank, pinned to CPU 0 as well, the same STEPS
steps): its input is the harness adapter's own translation (`silodem compare` of a 2-step copy of
the bed writes it), with the dumps taken out and thermo output every 100 steps. Its `Loop time` per
mobile ball-step shows how the reference code's cost grows on the same beds and machine. Without
`lmp` on the PATH that series is left out and the report says so.

Usage (after tools/build.sh): tools/bench_scaling.py [N ...]   (default 5000 20000 100000 1000000)
Writes reports/bench_scaling.json and reports/bench_scaling.md; `tools/bench_scaling.py --render`
rewrites the Markdown from the JSON. Run on a quiet machine; the whole run takes about 45
minutes (25 without LAMMPS) and 3 GB of memory, 1.5 GB of disk under /tmp.
"""
import json
import os
import re
import shutil
import statistics
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_dense import DT, SETTLE, SILODEM, TOP, lammps_timing_input, lammps_translation, loop_time, run, settled_case  # noqa: E402

WORK = "/tmp/silodem_bench_scaling"
PIN = ["taskset", "-c", "0"] if shutil.which("taskset") else []
STEPS, ROUNDS = 400, 3


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


def prepare(n, case, kind):
    """Writes `case` (n mobile balls; kind "dense": the wide bed, "tiled": the smallest bed tiled) as
    a timed run of STEPS steps; returns its path."""
    case["time"] = {"dt": DT, "duration": DT * STEPS}
    case["output"] = {"series_interval": DT * STEPS * 0.999}
    path = os.path.join(WORK, "%s_%d.json" % (kind, n))
    json.dump(case, open(path, "w"))
    return path


def time_once(n, path, kind):
    """One timed run on CPU 0: (seconds per step and its parts, peak RSS, summary, contacts per ball at
    the end). The parts are the solver's loop breakdown: list check and builds, force loop, the rest."""
    out = os.path.join(WORK, "timed_%s_%d" % (kind, n))
    _, rss = run(PIN + [SILODEM, "run", path, "--out", out, "--threads", "1", "--quiet"])
    s = json.load(open(os.path.join(out, "summary.json")))
    series = open(os.path.join(out, "series.csv")).read().splitlines()
    contacts = float(series[-1].split(",")[series[0].split(",").index("contacts")]) / n
    seconds = dict(s["run"]["loop_breakdown_seconds"], total=s["run"]["loop_seconds"])
    return {k: v / s["run"]["steps"] for k, v in seconds.items()}, rss, s, contacts


def lammps_prepare(n, case, kind):
    """The adapter's LAMMPS translation of `case` (written by `silodem compare` on a 2-step copy, so
    that its per-step dumps stay small), as a timed input of STEPS steps without dumps and with
    thermo output every 100 steps, in its own directory; returns that directory, or None without lmp."""
    if not shutil.which("lmp"):
        return None
    short = dict(case, time={"dt": DT, "duration": 2 * DT}, output={"series_interval": 1.0},
                 compare={"codes": ["silodem", "lammps"], "checks": [{"type": "energy_balance", "tolerance": 1.0}],
                          "time_limit_s": 7200})
    short_path = os.path.join(WORK, "lammps_source_%s_%d.json" % (kind, n))
    json.dump(short, open(short_path, "w"))
    prep = os.path.join(WORK, "lammps_prepare_%s_%d" % (kind, n))
    src = lammps_translation(short_path, short["name"], prep)
    if not src:
        raise RuntimeError("bench_scaling: the adapter wrote no LAMMPS input for %s (see %s)" % (short_path, prep))
    d = os.path.join(WORK, "lammps_%s_%d" % (kind, n))
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    shutil.move(os.path.join(src, "data.lmp"), d)
    text = lammps_timing_input(open(os.path.join(src, "in.lammps")).read(), 1)
    text, runs = re.subn(r"^run \d+", "run %d" % STEPS, text, flags=re.M)
    text = re.sub(r"^thermo \d+", "thermo 100", text, flags=re.M)
    if runs != 1:
        raise RuntimeError("bench_scaling: expected one run command in the adapter's LAMMPS input")
    open(os.path.join(d, "in.lammps"), "w").write(text)
    shutil.rmtree(prep, ignore_errors=True)
    return d


def lammps_once(d):
    """One timed LAMMPS run on CPU 0: (loop seconds per step, neighbour-list builds)."""
    run(PIN + ["lmp", "-in", "in.lammps", "-log", "log.txt", "-echo", "none", "-screen", "none"], cwd=d)
    log = os.path.join(d, "log.txt")
    builds = re.findall(r"Neighbor list builds = (\d+)", open(log).read())
    return loop_time(log) / STEPS, int(builds[-1]) if builds else None


def row(n, kind, timings, rss, s, contacts, lammps=None):
    mem = s["memory"]
    samples = [t["total"] for t in timings]
    # The parts of the run whose total is the (lower) median, so that they add up to it.
    mid = sorted(timings, key=lambda t: t["total"])[(len(timings) - 1) // 2]
    return {"mobile": n, "scene": kind, "steps": STEPS, "repeats": len(samples),
            "seconds_per_step": statistics.median(samples), "all": samples,
            "ns_per_ball_step": statistics.median(samples) / n * 1e9,
            "median_run_ns_per_ball_step": {k: v / n * 1e9 for k, v in mid.items()},
            "neighbour_builds": s["run"]["neighbour_builds"],
            "contacts_per_ball": contacts, "pairs_per_ball": mem["list_pairs"] / n, "rss_bytes": rss,
            "solver_bytes_per_mobile": mem["total_bytes"] / n,
            "particles_and_integrator_bytes_per_mobile": (mem["particles_bytes"] + mem["integrator_bytes"]) / n,
            "lammps": None if not lammps else {
                "repeats": len(lammps), "ns_per_ball_step": statistics.median(t for t, _ in lammps) / n * 1e9,
                "all": [t for t, _ in lammps], "neighbour_builds": lammps[-1][1]}}


def table(f, rows, ref):
    f.write("| mobile | repeats | ns per ball-step | relative to N = %d | of the median run: neighbour / force / other "
            "| builds | contacts/ball | list pairs/ball | solver bytes/mobile ball | of which balls + integrator "
            "| peak RSS/mobile ball |\n"
            "|---|---|---|---|---|---|---|---|---|---|---|\n" % ref["mobile"])
    for r in rows:
        parts = r["median_run_ns_per_ball_step"]
        f.write("| %d | %d | %.1f | %.3f | %.1f / %.1f / %.1f | %d | %.2f | %.2f | %.0f | %.0f | %.0f |\n" % (
            r["mobile"], r["repeats"], r["ns_per_ball_step"], r["ns_per_ball_step"] / ref["ns_per_ball_step"],
            parts["neighbour"], parts["force"], parts["other"], r["neighbour_builds"], r["contacts_per_ball"], r["pairs_per_ball"], r["solver_bytes_per_mobile"],
            r["particles_and_integrator_bytes_per_mobile"], r["rss_bytes"] / r["mobile"]))


def lammps_table(f, rows, data):
    """The reference code on the same beds: its cost per ball-step, its growth, and silodem's speed over it."""
    if not all(r.get("lammps") for r in rows):
        f.write("\nLAMMPS on the same beds: %s.\n" % data.get("lammps", "not run"))
        return
    ref = rows[0]["lammps"]["ns_per_ball_step"]
    f.write("\nLAMMPS on the same beds, in the same rounds (1 rank on CPU 0, `Loop time` per mobile ball-step; "
            "the adapter's input without dumps, thermo every 100 steps):\n\n"
            "| mobile | LAMMPS repeats | LAMMPS ns per ball-step | LAMMPS relative to N = %d | LAMMPS builds "
            "| silodem ns per ball-step | silodem speed / LAMMPS |\n|---|---|---|---|---|---|---|\n" % rows[0]["mobile"])
    for r in rows:
        q = r["lammps"]
        f.write("| %d | %d | %.1f | %.3f | %s | %.1f | %.2f |\n" % (
            r["mobile"], q["repeats"], q["ns_per_ball_step"], q["ns_per_ball_step"] / ref,
            q["neighbour_builds"] if q["neighbour_builds"] is not None else "—", r["ns_per_ball_step"],
            q["ns_per_ball_step"] / r["ns_per_ball_step"]))
    f.write("\nLargest over smallest cost per ball-step − 1, LAMMPS: %.3f (silodem: %.3f).\n" % (
        lammps_spread(rows), spread(rows)))


def spread(rows, cost=lambda r: r["ns_per_ball_step"]):
    """Largest over smallest cost per ball-step − 1 (the target's measure); None if a row has no cost."""
    v = [cost(r) for r in rows]
    return max(v) / min(v) - 1.0 if all(v) else None


def lammps_spread(rows):
    return spread(rows, lambda r: (r.get("lammps") or {}).get("ns_per_ball_step"))


def main():
    if sys.argv[1:] == ["--render"]:
        write_markdown(json.load(open(os.path.join(TOP, "reports", "bench_scaling.json"))))
        return
    sizes = [int(a) for a in sys.argv[1:]] or [5000, 20000, 100000, 1000000]
    base = settled_case(sizes[0], WORK, SETTLE, "scaling_%d" % sizes[0])
    runs = [("dense", n, prepare(n, dict(base) if n == sizes[0] else settled_case(n, WORK, SETTLE, "scaling_%d" % n),
                                 "dense")) for n in sizes]
    runs += [("tiled", n, prepare(n, tiled(base, n // sizes[0]), "tiled")) for n in sizes[1:] if n % sizes[0] == 0]
    lammps_dirs = {(kind, n): lammps_prepare(n, json.load(open(path)), kind) for kind, n, path in runs}
    # Rounds over every bed in turn, so that a change of the host's speed (up to 2x within minutes
    # here) falls on all sizes alike; small beds run several times a round (short runs scatter).
    samples, last, lammps = {}, {}, {}
    for k in range(ROUNDS):
        for kind, n, path in runs:
            for _ in range(max(1, min(10, 100000 // n))):
                t, rss, s, contacts = time_once(n, path, kind)
                samples.setdefault((kind, n), []).append(t)
                last[(kind, n)] = (rss, s, contacts)
                if lammps_dirs[(kind, n)]:
                    lammps.setdefault((kind, n), []).append(lammps_once(lammps_dirs[(kind, n)]))
            print("round %d, %s N = %d: %.1f ns per ball-step%s" % (
                k + 1, kind, n, t["total"] / n * 1e9,
                ", LAMMPS %.1f" % (lammps[(kind, n)][-1][0] / n * 1e9) if (kind, n) in lammps else ""), flush=True)
    def rows_of(scene):
        return [row(n, kind, samples[(kind, n)], *last[(kind, n)], lammps.get((kind, n)))
                for kind, n, _ in runs if kind == scene]
    rows = rows_of("dense")
    tiled_rows = [rows[0]] + rows_of("tiled")
    stamp = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
    data = {"date": stamp, "sizes": sizes, "settle_steps": SETTLE, "rounds": ROUNDS, "rows": rows, "spread": spread(rows),
            "tiled_rows": tiled_rows[1:], "tiled_spread": spread(tiled_rows),
            "lammps": "lmp %s" % shutil.which("lmp") if lammps else "not run: lmp is not on the PATH",
            "lammps_spread": lammps_spread(rows), "lammps_tiled_spread": lammps_spread(tiled_rows)}
    json.dump(data, open(os.path.join(TOP, "reports", "bench_scaling.json"), "w"), indent=1)
    write_markdown(data)


def write_markdown(data):
    """reports/bench_scaling.md from the figures of one run (`--render` rewrites it from the JSON)."""
    rows, sizes = data["rows"], data["sizes"]
    tiled_rows = [rows[0]] + data["tiled_rows"]
    contacts = [r["contacts_per_ball"] for r in rows]
    with open(os.path.join(TOP, "reports", "bench_scaling.md"), "w") as f:
        f.write("# Cost per step against N (silodem, 1 thread)\n\nMeasured %s by `tools/bench_scaling.py %s`: the anchor "
                "scene at each N, settled %d steps on 2 threads (as tools/bench_dense.py settles it), then %d timed steps "
                "on 1 thread pinned to CPU 0, in %d rounds over all beds (column `repeats`: runs per bed, the figure is "
                "their median). Linear cost means a constant time per ball-step; target: within 20 %% from 5,000 to "
                "1,000,000. The parts are the solver's own loop breakdown (`run.loop_breakdown_seconds`) of the run "
                "whose total is the median: the list's displacement check and builds, the force loop, and the rest "
                "(integration, energy ledger, guards). Column `builds`: neighbour-list builds in one timed run.\n\n" %
                (data["date"], " ".join(map(str, sizes)), data["settle_steps"], STEPS, data["rounds"]))
        table(f, rows, rows[0])
        f.write("\nLargest over smallest cost per ball-step − 1: %.3f (%s the 20 %% target), with %.2f to %.2f contacts "
                "per ball at the end of the timed runs. Peak RSS includes the parsed case file (every ball as JSON).\n" %
                (data["spread"], "within" if data["spread"] <= 0.2 else "outside", min(contacts), max(contacts)))
        lammps_table(f, rows, data)
        f.write("\n## The same work per ball at every N\n\nA wider bed has a longer sweep front and may settle to a "
                "slightly different packing. Here the %d-ball bed, settled as above, is copied into N / %d boxes stacked "
                "along z (5 cm apart, no contact between copies): every ball has the same partners, so what changes "
                "with N is how far the data is from the core (caches against memory), and the list's rebuilds: the two "
                "largest displacements that trigger one now come from two copies' fastest balls, which can come "
                "sooner than one bed's two largest (column `builds`). Timed as above; the first row is the %d-ball bed of the table above.\n\n" %
                (sizes[0], sizes[0], sizes[0]))
        table(f, tiled_rows, rows[0])
        f.write("\nLargest over smallest cost per ball-step − 1, tiled: %.3f.\n" % data["tiled_spread"])
        lammps_table(f, tiled_rows, data)


if __name__ == "__main__":
    main()
