"""Cross-code figures from `silodem compare`: the Janssen column in every code with the seed
scatter, the energy ledgers against time, and the collision cases against their closed forms."""
import math
import os
import re

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from .files import CODE_STYLE, Skip, field, read_csv, read_json, wall_bands  # noqa: E402
from .silo_figures import save  # noqa: E402


def janssen(res, out):
    """Horizontal pressure, wall shear and vertical stress against depth, every code, with the
    silodem seed scatter, the Janssen fit, the hydrostatic line and EN 1991-4."""
    base = os.path.join(res.compare, "janssen_column", "base")
    runs = res.run_dirs("compare", "janssen_column", "base")
    if "silodem" not in runs:
        raise Skip("Janssen column compare not in these results")
    rows = [r for r in res.verdicts("compare") if r["case"] == "janssen_column" and r["code"] == "silodem"]
    note = next((r["note"] for r in rows if r["quantity"] == "janssen_fit_r2"), "")
    m = re.search(r"p_ho=([0-9.eE+-]+) Pa, z_o=([0-9.eE+-]+) m", note)
    K = next((r["measured"] for r in rows if r["quantity"] == "lateral_pressure_ratio_K"), None)
    mu = next((r["measured"] for r in rows if r["quantity"] == "effective_wall_friction_mu_w"), None)
    fig, axes = plt.subplots(1, 3, figsize=(15, 5.2), sharey=True)
    depth_max = 0.0

    def profile(run, column):
        z, p, geo = wall_bands(run, "mantle", column)
        z_top = field(read_json(os.path.join(run, "summary.json")), run, ["fill", "z_top"])
        keep = [i for i, zi in enumerate(z) if zi < z_top]
        return [z_top - z[i] for i in keep], [p[i] / 1000 for i in keep], geo, z_top

    # Seed scatter: silodem from the other seeds' packings (compare.seeds), min-max envelope.
    seeds = [os.path.join(base, d) for d in sorted(os.listdir(base)) if d.startswith("silodem_seed")]
    for ax, column in zip(axes[:2], ("pressure_final", "shear_final")):
        prof = [profile(r, column) for r in [runs["silodem"]] + seeds]
        if len(prof) > 1:
            n = min(len(p[0]) for p in prof)
            d = [sum(p[0][i] for p in prof) / len(prof) for i in range(n)]
            lo = [min(p[1][i] for p in prof) for i in range(n)]
            hi = [max(p[1][i] for p in prof) for i in range(n)]
            ax.fill_betweenx(d, lo, hi, color="C0", alpha=0.15, label="silodem, %d packings (seed scatter)" % len(prof))
        for code, run in runs.items():
            d, p, geo, z_top = profile(run, column)
            colour, marker = CODE_STYLE[code]
            ax.plot(p, d, marker=marker, color=colour, ls="-" if code == "silodem" else "none", ms=5, mfc="none", label=code)
            depth_max = max(depth_max, max(d))
    diameter = geo["diameter"]
    zs = [depth_max * i / 100 for i in range(101)]
    if m and K and mu:
        p_ho, z_o = float(m.group(1)), float(m.group(2))
        gamma = 4 * mu * p_ho / diameter  # ρ_b g from the fit: μ_w = γ D / (4 p_ho)
        ph = [p_ho * (1 - math.exp(-z / z_o)) / 1000 for z in zs]
        axes[0].plot(ph, zs, "k-", lw=1.2, label="Janssen fit = EN 1991-4 p_hf (K = %.2f, μ_w = %.3f)" % (K, mu))
        axes[0].plot([1.15 * v for v in ph], zs, "k--", lw=1, label="EN 1991-4 discharge p_he = 1.15 p_hf")
        axes[0].plot([K * gamma * z / 1000 for z in zs], zs, ":", color="grey", label="hydrostatic K γ z")
        axes[1].plot([mu * v for v in ph], zs, "k-", lw=1.2, label="Janssen τ = μ_w p_h")
        axes[2].plot([v / K for v in ph], zs, "k-", lw=1.2, label="Janssen p_v = p_h / K")
        axes[2].plot([gamma * z / 1000 for z in zs], zs, ":", color="grey", label="hydrostatic γ z")
    for code, run in runs.items():
        s = read_json(os.path.join(run, "summary.json"))
        _, pb, _ = wall_bands(run, "bottom", "pressure_final")
        zb = [s["fill"]["z_top"] - s["probes"]["bottom"]["geometry"]["centre"][2]]
        colour, marker = CODE_STYLE[code]
        axes[2].plot([sum(pb) / len(pb) / 1000], zb, marker=marker, color=colour, ls="none", ms=7, mfc="none",
                     label=code + " (floor, mean of its rings)")
    axes[0].set(xlabel="horizontal wall pressure p_h [kPa]", ylabel="depth below the fill top [m]")
    axes[1].set(xlabel="vertical wall shear τ [kPa]")
    axes[2].set(xlabel="vertical stress p_v [kPa]")
    for ax, t in zip(axes, ("horizontal pressure", "wall shear", "vertical stress on the floor")):
        ax.set_title(t)
        ax.legend(fontsize=7)
    axes[0].invert_yaxis()
    fig.suptitle("Janssen column, frictionless grains: %s from one settled state (wall friction only from roughness)"
                 % ", ".join(runs))
    return [(save(fig, out, "janssen_codes.png"), "Janssen column in every code against Janssen and EN 1991-4",
             "cases/janssen_column.json (compare, seeds 2002-2004)")]


def energy(res, out):
    """Energy ledgers against time for every code (each rebuilt from its dump the same way)."""
    made = []
    for case in ("silo_closure", "silo_discharge", "collision_restitution"):
        variant = "base" if case != "collision_restitution" else "contact_end=clamped"
        runs = res.run_dirs("compare", case, variant)
        if not runs:
            continue
        fig, axes = plt.subplots(1, 5, figsize=(19, 3.8))
        terms = (("E_kin", "kinetic"), ("E_grav", "gravitational (datum z = 0)"), ("E_el", "elastic"),
                 ("E_diss", "dissipated (dashpots)"), ("balance", "balance (residual)"))
        for code, run in runs.items():
            rows = read_csv(os.path.join(run, "series.csv"), need=("t",) + tuple(t for t, _ in terms))
            colour, _ = CODE_STYLE[code]
            for ax, (col, _) in zip(axes, terms):
                ax.plot([r["t"] for r in rows], [r[col] for r in rows], color=colour, lw=1, label=code)
        for ax, (_, title) in zip(axes, terms):
            ax.set(xlabel="time [s]", ylabel="energy [J]", title=title)
            ax.legend(fontsize=7)
        fig.suptitle("Energy ledger, %s (%s): %s" % (case, variant, ", ".join(runs)))
        made.append((save(fig, out, "energy_%s.png" % case), "Energy ledger against time, %s, every code" % case,
                     "cases/%s.json (compare)" % case))
    if not made:
        raise Skip("no compare results with energy series")
    return made


def collisions(res, out):
    """Restitution against damping ratio (theory line, each code's points), and the free-fall and
    cohesion quantities against their closed forms."""
    rows = res.verdicts("compare")
    rest = [r for r in rows if r["case"] == "collision_restitution" and r["quantity"] == "restitution"
            and r["code"] in CODE_STYLE and r["verdict"] != "skip"]
    other = [r for r in rows + res.verdicts("verify") if r["case"] in ("free_fall_contact", "cohesion_cutoff")
             and r["code"] in CODE_STYLE and r["quantity"] not in ("run", "energy_drift") and r["verdict"] != "skip"
             and isinstance(r["expected"], float) and r["expected"] != 0.0 and not r["quantity"].startswith("ledger")]
    if not rest and not other:
        raise Skip("no collision, free-fall or cohesion results")
    variants = sorted({r["variant"] for r in rest})
    fig, axes = plt.subplots(1, len(variants) + 1, figsize=(5 * (len(variants) + 1), 4.3), squeeze=False)
    for ax, v in zip(axes[0], variants):
        pts = [r for r in rest if r["variant"] == v]
        zeta = lambda r: float(re.search(r"zeta=([0-9.]+)", r["note"]).group(1))  # noqa: E731
        theory = sorted({(zeta(r), r["expected"]) for r in pts})
        ax.plot([z for z, _ in theory], [e for _, e in theory], "k-", lw=1, label="closed form (docs/theory.md §1)")
        for code in CODE_STYLE:
            mine = [r for r in pts if r["code"] == code]
            if mine:
                colour, marker = CODE_STYLE[code]
                ax.plot([zeta(r) for r in mine], [r["measured"] for r in mine], marker, color=colour, mfc="none", ls="none",
                        label=code)
        ax.set(xlabel="damping ratio ζ", ylabel="coefficient of restitution e", title="restitution, " + v)
        ax.legend(fontsize=7)
    ax = axes[0][-1]
    labels = sorted({(r["case"], r["quantity"]) for r in other})
    for k, (case, q) in enumerate(labels):
        for j, code in enumerate(CODE_STYLE):
            mine = [abs(r["measured"] / r["expected"] - 1) for r in other if (r["case"], r["quantity"], r["code"]) == (case, q, code)]
            if mine:
                colour, marker = CODE_STYLE[code]
                ax.plot([max(max(mine), 1e-16)], [k + 0.15 * (j - 1.5)], marker, color=colour, mfc="none",
                        label=code if k == 0 else None)
    ax.set_yticks(range(len(labels)))
    ax.set_yticklabels(["%s: %s" % (c.split("_")[0], q) for c, q in labels], fontsize=7)
    ax.set_xscale("log")
    ax.set(xlabel="|measured / closed form − 1| (worst row)", title="free fall and cohesion against theory")
    ax.legend(fontsize=7)
    fig.suptitle("Collision cases: silodem, LAMMPS, LIGGGHTS, YADE against the closed forms")
    return [(save(fig, out, "collisions.png"), "Collision cases against their closed forms",
             "cases/collision_restitution.json, cases/free_fall_contact.json, cases/cohesion_cutoff.json")]
