#!/usr/bin/python3
"""Figures a silo engineer looks at, drawn from the result files of `silodem verify` (matplotlib,
Debian's python3-matplotlib under /usr/bin/python3):
  janssen_pressure_map.png   horizontal pressure on the unrolled mantle (the paper's Fig. 7)
  janssen_profile.png        angle-averaged pressure against depth, with the fitted Janssen curve
  silo_fill.png              the silo filled by analytic drops: mantle map, pressure against height, fill history
  discharge_factor.png       mantle pressure in discharge over pressure after filling, per outlet (EN C_h)
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


def save(fig, out, name):
    fig.tight_layout()
    fig.savefig(os.path.join(out, name), dpi=120)
    plt.close(fig)


def final_map(run, probe):
    """(summary, nominal geometry, final pressure grid [height bin][angle bin]) of a wall probe."""
    summary = json.load(open(os.path.join(run, "summary.json")))
    rows = table(os.path.join(run, "probes", probe + ".csv"))
    na = 1 + max(int(r["angle_bin"]) for r in rows)
    nh = 1 + max(int(r["height_bin"]) for r in rows)
    grid = [[0.0] * na for _ in range(nh)]
    for r in rows:
        grid[int(r["height_bin"])][int(r["angle_bin"])] = float(r["pressure_final"])
    return summary, summary["probes"][probe]["geometry"], grid


def janssen(results, out, verdicts):
    run = os.path.join(results, "janssen_column", "base")
    if not os.path.exists(run):
        return
    summary, geo, grid = final_map(run, "mantle")
    nh, na = len(grid), len(grid[0])
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


def band_profile(run, probe, column):
    """(height of band centre, angle-averaged pressure) of a wall probe, bottom band first."""
    rows = table(os.path.join(run, "probes", probe + ".csv"))
    geo = json.load(open(os.path.join(run, "summary.json")))["probes"][probe]["geometry"]
    nh = 1 + max(int(r["height_bin"]) for r in rows)
    force, area = [0.0] * nh, [0.0] * nh
    for r in rows:
        h = int(r["height_bin"])
        force[h] += float(r[column]) * float(r["area"])
        area[h] += float(r["area"])
    z = [geo["centre"][2] + geo["height"] * (h + 0.5) / nh for h in range(nh)]
    return z, [f / a for f, a in zip(force, area)]


def silo_fill(results, out):
    """The filled silo: the unrolled mantle map (Fig. 7), the angle-averaged profile and the fill history."""
    run = os.path.join(results, "silo_fill", "base")
    if not os.path.exists(run):
        return
    summary, geo, grid = final_map(run, "mantle")
    nh, na = len(grid), len(grid[0])
    fig, axes = plt.subplots(1, 3, figsize=(14, 4.5))
    im = axes[0].imshow(grid, origin="lower", aspect="auto", cmap="viridis",
                        extent=[0, 360, geo["centre"][2], geo["centre"][2] + geo["height"]])
    axes[0].axhline(summary["fill"]["z_top"], color="w", ls="--", lw=0.8)
    axes[0].set_xlabel("angle around the mantle [deg]")
    axes[0].set_ylabel("height above the transition [m]")
    axes[0].set_title("horizontal pressure, unrolled mantle (Fig. 7)")
    fig.colorbar(im, ax=axes[0], label="pressure [Pa]")
    for probe, style in (("mantle", "o-"), ("hopper", "s-")):
        z, p = band_profile(run, probe, "pressure_final")
        if probe == "hopper":  # cone bands are counted from the outlet up to the transition
            z = [-geo_h for geo_h in reversed([summary["probes"]["hopper"]["geometry"]["height"] * (h + 0.5) / len(z)
                                                for h in range(len(z))])]
        axes[1].plot(p, z, style, label=probe)
    axes[1].axhline(summary["fill"]["z_top"], color="k", ls="--", lw=0.8, label="fill top")
    axes[1].set_xlabel("angle-averaged wall pressure [Pa]")
    axes[1].set_ylabel("height [m]")
    axes[1].legend(fontsize=8)
    axes[1].set_title("pressure against height, at rest")
    drops = table(os.path.join(run, "probes", "drops.csv"))
    t = [float(d["t"]) for d in drops]
    placed, n = [], 0
    for d in drops:
        n += d["outcome"] == "placed"
        placed.append(n)
    axes[2].plot(t, placed, label="placed")
    axes[2].plot(t, [i + 1 - k for i, k in enumerate(placed)], label="rejected")
    axes[2].set(xlabel="time [s]", ylabel="drops", title="fill history (stop tests at t = %.2f s)" % summary["run"]["time"])
    axes[2].legend(fontsize=8)
    fig.suptitle("Silo fill by analytic drops (Algorithm 5): %d balls" % summary["balls"]["mobile"])
    save(fig, out, "silo_fill.png")


def discharge_factor(results, out):
    """Mantle pressure during discharge against after filling (EN 1991-4 C_h), one line per outlet."""
    root = os.path.join(results, "silo_discharge")
    if not os.path.exists(root):
        return
    fig, ax = plt.subplots(figsize=(5.5, 5))
    for variant in sorted(os.listdir(root)):
        run = os.path.join(root, variant)
        if not os.path.exists(os.path.join(run, "probes", "mantle_filled.csv")):
            continue
        z, pf = band_profile(run, "mantle_filled", "pressure_mean")
        _, pe = band_profile(run, "mantle", "pressure_mean")
        keep = [i for i, p in enumerate(pf) if p > 0.05 * max(pf)]
        ax.plot([pe[i] / pf[i] for i in keep], [z[i] for i in keep], "o-", label=variant.replace("outlet=", ""))
    ax.axvline(1.15, color="k", ls="--", lw=0.8, label="EN 1991-4 C_h = 1.15")
    ax.axvline(1.0, color="grey", lw=0.5)
    ax.set(xlabel="p_h in discharge / p_h after filling", ylabel="height above the transition [m]",
           title="Discharge factor on the mantle")
    ax.legend(fontsize=8)
    save(fig, out, "discharge_factor.png")


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
    silo_fill(results, out)
    discharge_factor(results, out)


if __name__ == "__main__":
    main()
