"""The frictional silo in every code (`silodem compare`, each code from silodem's shared state,
history springs restarting at zero in all): the Janssen column's final profile, the discharge's
mass against time and its wall pressure, with the envelope of silodem's own packings (the seed
scatter that judges the differences)."""
import math
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from .files import CODE_STYLE, Skip, field, read_csv, read_json, wall_bands  # noqa: E402
from .frictional_figures import save, spread  # noqa: E402


def seed_runs(res, case):
    """silodem's runs from the other packings (compare "seeds")."""
    base = os.path.join(res.compare, case, "base")
    return [os.path.join(base, d) for d in sorted(os.listdir(base))
            if d.startswith("silodem_seed") and os.path.exists(os.path.join(base, d, "summary.json"))]


def envelope(ax, profiles, label, colour="C0"):
    """Min-max band of (xs, ys) profiles sharing their ys, drawn horizontally."""
    n = min(len(p[1]) for p in profiles)
    ys = profiles[0][1][:n]
    ax.fill_betweenx(ys, [min(p[0][i] for p in profiles) for i in range(n)],
                     [max(p[0][i] for p in profiles) for i in range(n)], color=colour, alpha=0.15, label=label)


def column_profile(run, z_floor_of):
    """(p_h [kPa], depth [m]) of the final mantle profile between the floor and the fill top."""
    s = read_json(os.path.join(run, "summary.json"))
    z_top = field(s, run, ["fill", "z_top"])
    z, p, geo = wall_bands(run, "mantle", "pressure_final")
    keep = [i for i, zi in enumerate(z) if z_floor_of < zi < z_top]
    return [p[i] / 1000 for i in keep], [z_top - z[i] for i in keep], geo, s


def column(res, out):
    runs = res.run_dirs("compare", "janssen_frictional", "base")
    if "silodem" not in runs:
        raise Skip("frictional Janssen column compare not in these results")
    s0 = read_json(os.path.join(runs["silodem"], "summary.json"))
    z_floor = next(w["centre"][2] for w in s0["input"]["walls"] if w["type"] == "disk")
    rows = [r for r in res.verdicts("compare") if r["case"] == "janssen_frictional"]
    fig, ax = plt.subplots(figsize=(7.5, 6))
    seeds = [column_profile(r, z_floor) for r in [runs["silodem"]] + seed_runs(res, "janssen_frictional")]
    if len(seeds) > 1:
        envelope(ax, seeds, "silodem, %d packings (seed scatter)" % len(seeds))
    depth = 0.0
    for code, run in runs.items():
        p, d, geo, s = column_profile(run, z_floor)
        K = next((r["measured"] for r in rows if r["code"] == code and r["quantity"] == "lateral_pressure_ratio_K"), math.nan)
        mu = next((r["measured"] for r in rows if r["code"] == code and r["quantity"] == "effective_wall_friction_mu_w"),
                  math.nan)
        colour, marker = CODE_STYLE[code]
        ax.plot(p, d, marker=marker, color=colour, ls="-" if code == "silodem" else "none", ms=5, mfc="none",
                label="%s (fit: K = %.3f, mu_w = %.3f)" % (code, K, mu))
        depth = max(depth, max(d))
    # Janssen with the material tests' K and mu_w, where verify ran them in the same results.
    K = spread(res.verdicts("verify"), "lateral_pressure_ratio", "lateral_pressure_ratio_K")
    mu = spread(res.verdicts("verify"), "wall_friction", "wall_friction_mu_w")
    group = next((g for g in K if "mu=0.5" in g and "rolling=none" in g and g in mu), None)
    if group:
        D, mass = geo["diameter"], s0["fill"]["mobile_mass"]
        gamma = mass * 9.81 / (math.pi * D * D / 4 * (s0["fill"]["z_top"] - z_floor))
        # The silo's K from the test's K_o by the factor the case's prediction states (EN 1991-4 C: 1.1).
        pred = next((c for c in s0["input"].get("verify", {}).get("checks", []) if c["type"] == "janssen_prediction"), {})
        factor = pred.get("K_factor", 1.0)
        k, m = factor * K[group][0], mu[group][0]
        zs = [depth * i / 100 for i in range(101)]
        ax.plot([gamma * D / (4 * m) * (1 - math.exp(-4 * m * k * z / D)) / 1000 for z in zs], zs, "k-",
                label="Janssen, K = %.2f K_o = %.3f, mu_w = %.3f (material tests)" % (factor, k, m))
    ax.invert_yaxis()
    ax.set(xlabel="horizontal wall pressure p_h [kPa]", ylabel="depth below the fill top [m]",
           title="Frictional Janssen column (mu 0.5), every code from one settled state,\n"
                 "at rest after the same 2 mm wall slip")
    ax.legend(fontsize=7)
    return [(save(fig, out, "janssen_frictional_codes.png"), "Frictional Janssen column in every code",
             "cases/janssen_frictional.json (compare, seeds 2002-2004)")]


def discharge(res, out):
    runs = res.run_dirs("compare", "silo_discharge_frictional", "base")
    if "silodem" not in runs:
        raise Skip("frictional discharge compare not in these results")
    rows = [r for r in res.verdicts("compare") if r["case"] == "silo_discharge_frictional"
            and r["quantity"] == "mass_flow_rate" and r["code"] in CODE_STYLE]
    fig, (a, b) = plt.subplots(1, 2, figsize=(12, 4.8))
    for run in seed_runs(res, "silo_discharge_frictional"):
        flow = read_csv(os.path.join(run, "probes", "outflow.csv"), need=("t", "cumulative_mass"))
        a.plot([r["t"] for r in flow], [r["cumulative_mass"] for r in flow], color="C0", lw=0.6, alpha=0.4)
    a.plot([], [], color="C0", lw=0.6, alpha=0.4, label="silodem, the other packings")
    seeds = []
    for run in [runs["silodem"]] + seed_runs(res, "silo_discharge_frictional"):
        z, p, _ = wall_bands(run, "mantle", "pressure_mean")
        seeds.append(([x / 1000 for x in p], z))
    envelope(b, seeds, "silodem, %d packings" % len(seeds))
    for code, run in runs.items():
        colour, marker = CODE_STYLE[code]
        flow = read_csv(os.path.join(run, "probes", "outflow.csv"), need=("t", "cumulative_mass"))
        w = next((r["measured"] for r in rows if r["code"] == code), math.nan)
        a.plot([r["t"] for r in flow], [r["cumulative_mass"] for r in flow], color=colour, lw=1.2,
               label="%s: %.3f kg/s" % (code, w))
        z, p, _ = wall_bands(run, "mantle", "pressure_mean")
        b.plot([x / 1000 for x in p], z, marker=marker, color=colour, ls="-" if code == "silodem" else "none",
               mfc="none", label=code)
    a.set(xlabel="time [s]", ylabel="discharged mass [kg]", title="discharged mass (7 d outlet; steady rate from 0.5 s)")
    b.set(xlabel="horizontal wall pressure during discharge [kPa]", ylabel="height [m]",
          title="mantle pressure, mean over the steady flow")
    for ax in (a, b):
        ax.legend(fontsize=7)
    fig.suptitle("Frictional discharge (mu 0.5) in every code from one filled state")
    return [(save(fig, out, "discharge_frictional_codes.png"), "Frictional discharge in every code",
             "cases/silo_discharge_frictional.json (compare, seeds 2002-2005)")]
