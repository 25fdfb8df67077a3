#!/usr/bin/python3
"""Figures a silo engineer looks at, drawn from the result files of `silodem verify` (matplotlib,
Debian's python3-matplotlib under /usr/bin/python3):
  janssen_pressure_map.png   horizontal pressure on the unrolled mantle (the paper's Fig. 7)
  janssen_profile.png        angle-averaged pressure against depth, with the fitted Janssen curve
  discharge_flow.png         cumulative discharged mass per outlet, and the 5/2 law across outlets
  closure_history.png        band pressures of hopper and mantle around the sudden closure
Usage: tools/plot_reports.py RESULTS_DIR OUT_DIR   (e.g. results/verify reports/figures)
"""
import csv
import json
import math
import os
import re
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def table(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def janssen(results, out, verdicts):
    run = os.path.join(results, "janssen_column", "base")
    if not os.path.exists(run):
        return
    summary = json.load(open(os.path.join(run, "summary.json")))
    geo = summary["probes"]["mantle"]["geometry"]
    rows = table(os.path.join(run, "probes", "mantle.csv"))
    na = 1 + max(int(r["angle_bin"]) for r in rows)
    nh = 1 + max(int(r["height_bin"]) for r in rows)
    grid = [[0.0] * na for _ in range(nh)]
    for r in rows:
        grid[int(r["height_bin"])][int(r["angle_bin"])] = float(r["pressure_final"])
    fig, ax = plt.subplots(figsize=(6, 5))
    im = ax.imshow(grid, origin="lower", aspect="auto", cmap="viridis",
                   extent=[0, 360, geo["centre"][2], geo["centre"][2] + geo["height"]])
    ax.set_xlabel("angle around the mantle [deg]")
    ax.set_ylabel("height [m]")
    ax.set_title("Janssen column: horizontal wall pressure, unrolled mantle")
    fig.colorbar(im, ax=ax, label="pressure [Pa]")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "janssen_pressure_map.png"), dpi=120)
    plt.close(fig)
    # Angle-averaged profile against depth below the fill top, with the fitted curve.
    z_top = summary["fill"]["z_top"]
    depth, p = [], []
    for h in range(nh):
        z = geo["centre"][2] + geo["height"] * (h + 0.5) / nh
        if z < z_top:
            depth.append(z_top - z)
            p.append(sum(grid[h]) / na)
    fig, ax = plt.subplots(figsize=(5, 5))
    ax.plot(p, depth, "o", label="silodem, angle average")
    note = next((r["note"] for r in verdicts if r["case"] == "janssen_column" and r["quantity"] == "janssen_fit_r2"), "")
    m = re.search(r"p_ho=([0-9.eE+-]+) Pa, z_o=([0-9.eE+-]+) m", note)
    if m:
        p_ho, z_o = float(m.group(1)), float(m.group(2))
        zs = [max(depth) * i / 100 for i in range(101)]
        ax.plot([p_ho * (1 - math.exp(-z / z_o)) for z in zs], zs, "-", label="Janssen fit")
    ax.invert_yaxis()
    ax.set_xlabel("horizontal wall pressure [Pa]")
    ax.set_ylabel("depth below the fill top [m]")
    ax.legend()
    ax.set_title("Janssen column: pressure against depth")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "janssen_profile.png"), dpi=120)
    plt.close(fig)


def discharge(results, out):
    base = os.path.join(results, "silo_discharge")
    if not os.path.exists(base):
        return
    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4))
    pts = []
    for variant in sorted(os.listdir(base)):
        rows = table(os.path.join(base, variant, "probes", "outflow.csv"))
        t = [float(r["t"]) for r in rows]
        m = [float(r["cumulative_mass"]) for r in rows]
        a.plot(t, m, label=variant)
        d0 = json.load(open(os.path.join(base, variant, "summary.json")))["input"]["walls"][1]["hole_diameter"]
        late = [(ti, mi) for ti, mi in zip(t, m) if ti >= 0.5]
        if len(late) > 2:
            pts.append((d0, (late[-1][1] - late[0][1]) / (late[-1][0] - late[0][0])))
    a.set_xlabel("time [s]")
    a.set_ylabel("discharged mass [kg]")
    a.legend()
    a.set_title("Discharge (outlet opened at 0.35 s)")
    if pts:
        b.plot([d for d, _ in pts], [w ** 0.4 for _, w in pts], "o-")
    b.set_xlabel("outlet diameter D0 [m]")
    b.set_ylabel("W^(2/5) [(kg/s)^0.4]")
    b.set_title("Beverloo: W^(2/5) linear in D0")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "discharge_flow.png"), dpi=120)
    plt.close(fig)


def closure(results, out):
    run = os.path.join(results, "silo_closure", "base")
    if not os.path.exists(run):
        return
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, probe in zip(axes, ("hopper", "mantle")):
        rows = table(os.path.join(run, "probes", probe + "_history.csv"))
        rows = [r for r in rows if 0.55 <= float(r["t"]) <= 0.75]
        t = [float(r["t"]) for r in rows]
        for band in [k for k in rows[0] if k.startswith("band")][:6]:
            ax.plot(t, [float(r[band]) for r in rows], label=band)
        ax.axvline(0.65, color="k", ls="--", lw=1)
        ax.set_xlim(0.55, 0.75)
        ax.set_xlabel("time [s] (closure at 0.65 s)")
        ax.set_ylabel("band pressure [Pa]")
        ax.set_title(probe + (" (band 0 at the outlet end)" if probe == "hopper" else " (band 0 at the bottom)"))
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "closure_history.png"), dpi=120)
    plt.close(fig)


def main():
    results, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    verdicts = json.load(open(os.path.join(results, "verdicts.json")))["rows"]
    janssen(results, out, verdicts)
    discharge(results, out)
    closure(results, out)


if __name__ == "__main__":
    main()
