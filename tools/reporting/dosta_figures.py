"""The silo of Dosta et al. (2024), docs/dosta-benchmark.md: the reduced case in every code from one
settled fill (discharged mass against time, the steady rates against Beverloo's), and, when
tools/dosta_full.sh has run, the paper's size in silodem with each code's speed on it."""
import math
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from .files import CODE_STYLE, Skip, complete_runs, read_csv, read_json  # noqa: E402
from .frictional_codes import seed_runs  # noqa: E402
from .frictional_figures import save  # noqa: E402


def outflow(run):
    flow = read_csv(os.path.join(run, "probes", "outflow.csv"), need=("t", "cumulative_mass"))
    return [r["t"] for r in flow], [r["cumulative_mass"] for r in flow]


def reduced(res, out):
    runs = res.run_dirs("compare", "dosta_silo", "base")
    if "silodem" not in runs:
        raise Skip("the dosta_silo compare is not in these results")
    rows = [r for r in res.verdicts("compare") if r["case"] == "dosta_silo" and r["quantity"] == "mass_flow_rate"]
    beverloo = next((r["expected"] for r in rows if r["code"] == "silodem"), math.nan)
    fig, ax = plt.subplots(figsize=(8, 4.8))
    for run in seed_runs(res, "dosta_silo"):
        ax.plot(*outflow(run), color="C0", lw=0.6, alpha=0.4)
    ax.plot([], [], color="C0", lw=0.6, alpha=0.4, label="silodem, the other packings")
    for code, run in runs.items():
        colour, _ = CODE_STYLE[code]
        w = next((r["measured"] for r in rows if r["code"] == code), math.nan)
        ax.plot(*outflow(run), color=colour, lw=1.2, label="%s: %.3f kg/s" % (code, w))
    t, m = outflow(runs["silodem"])
    if t and math.isfinite(beverloo):
        t0 = 0.19
        m0 = next((mm for tt, mm in zip(t, m) if tt >= t0), 0.0)
        ax.plot([t0, t[-1]], [m0, m0 + beverloo * (t[-1] - t0)], "k--", lw=0.8,
                label="Beverloo C 0.58, k 1.5: %.3f kg/s" % beverloo)
    ax.set(xlabel="time [s]", ylabel="discharged mass [kg]",
           title="Dosta et al. silo, reduced: 1,600 grains, orifice r 22 mm, gate away at 0.12 s")
    ax.legend(fontsize=7)
    return [(save(fig, out, "dosta_reduced.png"), "The Dosta et al. silo (reduced) in every code",
             "cases/dosta_silo.json (compare, seeds 2003, 2004)")]


def flow_runs(flow_dir):
    """{code: run} of the flow piece's compare (tools/dosta_full.sh step 4) and its mass-flow rows."""
    runs = complete_runs(os.path.join(flow_dir, "dosta_flow", "base"))
    path = os.path.join(flow_dir, "verdicts.json")
    rows = [r for r in read_json(path).get("rows", []) if r.get("quantity") == "mass_flow_rate"] \
        if os.path.exists(path) else []
    return runs, rows


def full(res, out):
    root = os.path.join(os.path.dirname(res.verify), "dosta")
    runs = sorted(d for d in os.listdir(root)) if os.path.isdir(root) else []
    done = [d for d in runs if os.path.exists(os.path.join(root, d, "discharge", "summary.json"))]
    flows = {d: flow_runs(os.path.join(root, d, "flow")) for d in runs}
    flows = {d: f for d, f in flows.items() if f[0]}
    if not done and not flows:
        raise Skip("no finished tools/dosta_full.sh discharge or flow piece in results/dosta")
    made = []
    if done:
        fig, ax = plt.subplots(figsize=(7, 4.8))
        for d in done:
            t, m = outflow(os.path.join(root, d, "discharge"))
            ax.plot(t, m, lw=1.2, label="silodem, %s (100,000 grains)" % d.replace("_", " orifice, "))
        ax.set(xlabel="time [s] (outlet open from 0)", ylabel="discharged mass [kg]",
               title="Dosta et al. silo at the paper's size")
        ax.legend(fontsize=7)
        made.append((save(fig, out, "dosta_full.png"), "The Dosta et al. silo at the paper's size",
                     "tools/dosta_full.sh (results/dosta/<orifice>_<material>/discharge)"))
    for d, (codes, rows) in flows.items():
        fig, ax = plt.subplots(figsize=(7, 4.8))
        for code, run in codes.items():
            t, m = outflow(run)
            w = next((r["measured"] for r in rows if r["code"] == code), math.nan)
            ax.plot(t, [mm - m[0] for mm in m], color=CODE_STYLE[code][0], lw=1.2,
                    label="%s: %.3f kg/s" % (code, w))
        ax.set(xlabel="time [s] (outlet open from 0; every code from silodem's state at the piece's start)",
               ylabel="mass discharged in the piece [kg]",
               title="Dosta et al. silo, paper's size (%s): the steady flow in every code" % d)
        ax.legend(fontsize=7)
        made.append((save(fig, out, "dosta_flow_%s.png" % d), "The steady flow at the paper's size in every code",
                     "tools/dosta_full.sh (results/dosta/%s/flow, the compare of flow.json)" % d))
    speeds = []
    for d in runs:
        path = os.path.join(root, d, "speed", "verdicts.json")
        if os.path.exists(path):
            speeds += [(d, r["run"].split()[-1], r["wall_seconds"]) for r in read_json(path).get("runs", [])]
    if speeds:
        fig, ax = plt.subplots(figsize=(7, 3.6))
        labels = ["%s %s" % s[:2] for s in speeds]
        ax.barh(labels, [s[2] / 60 for s in speeds], color=[CODE_STYLE.get(s[1], ("grey", ""))[0] for s in speeds])
        ax.set(xlabel="wall minutes for the speed piece (one core each)", title="Each code on the paper's size")
        made.append((save(fig, out, "dosta_speed.png"), "Speed of each code at the paper's size",
                     "tools/dosta_full.sh (results/dosta/<run>/speed/verdicts.json)"))
    return made
