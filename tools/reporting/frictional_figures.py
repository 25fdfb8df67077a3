"""The frictional silo page: the virtual material tests (K, mu_w, phi_i with their scatter over
packings), the Janssen column against Janssen evaluated with them (and with EN 1991-4's K from phi_i) (and EN 1991-4's filling pressure, the same
law for a slender silo with the measured K and mu_w), and the discharge against Beverloo."""
import math
import os
import re

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from .files import Skip, field, need_dir, read_csv, read_json, wall_bands, wall_grid  # noqa: E402
from .silo_figures import outlet_flows  # noqa: E402


def save(fig, out, name):
    fig.tight_layout()
    fig.savefig(os.path.join(out, "figures", name), dpi=100)
    plt.close(fig)
    return name


def spread(rows, case, quantity):
    """{group label: (mean, scatter)} of a material test's spread rows."""
    return {r["variant"]: (r["expected"], r["measured"]) for r in rows
            if r["case"] == case and r["quantity"] == quantity + "_spread"}


def material_tests(res, out):
    rows = res.verdicts("verify")
    K = spread(rows, "lateral_pressure_ratio", "lateral_pressure_ratio_K")
    mu = spread(rows, "wall_friction", "wall_friction_mu_w")
    phi = spread(rows, "direct_shear", "internal_friction_peak_deg")
    phi_cs = spread(rows, "direct_shear", "internal_friction_critical_deg")
    if not K and not mu and not phi:
        raise Skip("no virtual material test (lateral_pressure_ratio, wall_friction, direct_shear) in these results")
    groups = sorted(set(K) | set(mu) | set(phi))
    fig, axes = plt.subplots(1, 3, figsize=(14, 4))
    for ax, data, name in ((axes[0], K, "lateral pressure ratio K_o"), (axes[1], mu, "wall friction mu_w"),
                           (axes[2], phi, "angle of internal friction phi_i, peak [deg]")):
        xs = range(len(groups))
        ax.errorbar(list(xs), [data.get(g, (math.nan, 0))[0] for g in groups],
                    yerr=[data.get(g, (0, 0))[1] for g in groups], fmt="o", capsize=4)
        ax.set_xticks(list(xs))
        ax.set_xticklabels([g.replace(",", "\n") for g in groups], fontsize=8)
        ax.set_title("%s\nmean and scatter over 3 packings" % name, fontsize=9)
    if phi_cs:
        xs = range(len(groups))
        axes[2].errorbar([x + 0.15 for x in xs], [phi_cs.get(g, (math.nan, 0))[0] for g in groups],
                         yerr=[phi_cs.get(g, (0, 0))[1] for g in groups], fmt="s", capsize=4, label="critical state")
        axes[2].legend(fontsize=8)
    fig.suptitle("Virtual material tests (EN 1991-4 Annex C), silodem")
    with open(os.path.join(out, "tables", "material_tests.csv"), "w") as f:
        f.write("group,K,K_scatter,mu_w,mu_w_scatter,phi_i_peak_deg,phi_i_peak_scatter,phi_i_critical_deg,"
                "phi_i_critical_scatter,K_EN=1.1(1-sin phi_i)\n")
        for g in groups:
            k, m = K.get(g, (math.nan, math.nan)), mu.get(g, (math.nan, math.nan))
            p, c = phi.get(g, (math.nan, math.nan)), phi_cs.get(g, (math.nan, math.nan))
            f.write('"%s",%.4f,%.4f,%.4f,%.4f,%.2f,%.2f,%.2f,%.2f,%.4f\n'
                    % (g, k[0], k[1], m[0], m[1], p[0], p[1], c[0], c[1], en_K(p[0])))
    return [(save(fig, out, "material_tests.png"), "Material tests: K_o (frictionless wall), mu_w (the silo's wall) and "
             "phi_i (direct shear), table in tables/material_tests.csv",
             "cases/lateral_pressure_ratio.json, cases/wall_friction.json, cases/direct_shear.json (verify)")]


def en_K(phi_deg):
    """EN 1991-4's K_m = 1.1 (1 - sin phi_i)."""
    return 1.1 * (1.0 - math.sin(math.radians(phi_deg)))


def janssen_column(res, out):
    root = need_dir(os.path.join(res.verify, "janssen_frictional"), "frictional Janssen column")
    rows = res.verdicts("verify")
    K = spread(rows, "lateral_pressure_ratio", "lateral_pressure_ratio_K")
    mu = spread(rows, "wall_friction", "wall_friction_mu_w")
    phi = spread(rows, "direct_shear", "internal_friction_peak_deg")
    variants = sorted(v for v in os.listdir(root) if os.path.isdir(os.path.join(root, v)))
    if not variants:
        raise Skip("no finished run of janssen_frictional")
    fig, axes = plt.subplots(1, len(variants), figsize=(max(8.0, 5.5 * len(variants)), 5.5), squeeze=False)
    for ax, variant in zip(axes[0], variants):
        run = os.path.join(root, variant)
        s = read_json(os.path.join(run, "summary.json"))
        z_top = field(s, run, ["fill", "z_top"])
        mass = field(s, run, ["fill", "mobile_mass"])
        label = ",".join(re.split(r"_(?=[A-Za-z0-9.]+=)", variant))  # the directory name of a variant label
        group = next((g for g in K if all(t in label.split(",") for t in g.split(","))), None)
        # The column stands on the lowest disk inside the mantle (harness column_floor); the mantle reaches below it.
        geo0 = field(s, run, ["probes", "mantle", "geometry"])
        disks = [w["centre"][2] for w in s["input"]["walls"]
                 if w["type"] == "disk" and geo0["centre"][2] <= w["centre"][2] < geo0["centre"][2] + geo0["height"]]
        z_floor = min(disks) if disks else geo0["centre"][2]
        for probe, column, style, what in (("mantle", "pressure_final", "o", "at rest after the 2 mm slip"),
                                           ("mantle_settled", "pressure_mean", "x", "settled, before the slip")):
            z, p, geo = wall_bands(run, probe, column)
            keep = [i for i, zi in enumerate(z) if z_floor < zi < z_top]
            ax.plot([p[i] / 1000 for i in keep], [z_top - z[i] for i in keep], style, ms=4, label="DEM, " + what)
        D = geo["diameter"]
        gamma = mass * 9.81 / (math.pi * D * D / 4 * (z_top - z_floor))
        pred = next((ch for ch in field(s, run, ["input", "verify", "checks"]) if ch["type"] == "janssen_prediction"), {})
        factor = pred.get("K_factor", 1.0)  # the silo's K from the test's K_o (EN 1991-4 C: 1.1)
        if group and group in mu:
            (k, sk), (m, sm) = (factor * K[group][0], factor * K[group][1]), mu[group]
            depth = [(z_top - z_floor) * i / 100 for i in range(101)]
            law = lambda kk, mm: [gamma * D / (4 * mm) * (1 - math.exp(-4 * mm * kk * x / D)) / 1000 for x in depth]
            ax.plot(law(k, m), depth, "k-", label="Janssen, K = %.2f K_o = %.3f, mu_w = %.3f (material tests)" % (factor, k, m))
            lo, hi = law(k - 2 * sk, m + 2 * sm), law(k + 2 * sk, m - 2 * sm)
            ax.fill_betweenx(depth, lo, hi, color="grey", alpha=0.3, label="+/- 2 scatters of K and mu_w")
            if group in phi:
                k_en = en_K(phi[group][0])
                ax.plot(law(k_en, m), depth, "b--", label="EN 1991-4 p_hf, K = 1.1(1 - sin %.1f deg) = %.3f, mu_w = %.3f"
                        % (phi[group][0], k_en, m))
            ax.plot([gamma * x * k / 1000 for x in depth[:40]], depth[:40], ":", color="grey", label="hydrostatic K gamma z")
        ax.invert_yaxis()
        ax.set(xlabel="horizontal wall pressure [kPa]", ylabel="depth below the surface [m]", title=label)
        ax.legend(fontsize=7)
    fig.suptitle("Frictional Janssen column (D = 0.18 m = 20 d) against Janssen from the material tests\n"
                 "(EN 1991-4's p_hf of a slender silo is the same curve)", fontsize=10)
    return [(save(fig, out, "janssen_frictional.png"), "Frictional Janssen column against Janssen from the material tests",
             "cases/janssen_frictional.json (verify, with the material tests)")]


def discharge(res, out):
    root = need_dir(os.path.join(res.verify, "silo_discharge_frictional"), "frictional discharge")
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.3))
    pts, consts, _ = outlet_flows(root, a)
    a.set(xlabel="time [s]", ylabel="discharged mass [kg]", title="discharged mass (leavers recycled)")
    a.legend(fontsize=8)
    fit = {r["quantity"]: r["measured"] for r in res.verdicts("verify") if r["case"] == "silo_discharge_frictional"
           and r["quantity"] in ("beverloo_C", "beverloo_k")}
    if pts:
        b.plot([d * 1000 for d, _ in pts], [w for _, w in pts], "o", label="silodem, steady flow")
    if pts and consts:
        rho, d = consts
        xs = [min(p[0] for p in pts) * (0.8 + 1.2 * i / 60) for i in range(61)]
        if len(fit) == 2:
            w = [fit["beverloo_C"] * rho * math.sqrt(9.81) * max(0.0, x - fit["beverloo_k"] * d) ** 2.5 for x in xs]
            b.plot([x * 1000 for x in xs], w, "-", label="Beverloo fitted: C = %.3f, k = %.2f" % (fit["beverloo_C"], fit["beverloo_k"]))
        for C, k, style in ((0.55, 2.9, ":"), (0.65, 1.3, ":")):
            b.plot([x * 1000 for x in xs], [C * rho * math.sqrt(9.81) * max(0.0, x - k * d) ** 2.5 for x in xs], style,
                   color="grey")
        b.plot([], [], ":", color="grey", label="published range (C 0.55-0.65, k 1.3-2.9)")
    b.set(xlabel="outlet diameter D0 [mm]", ylabel="mass flow rate [kg/s]", title="flow rate against outlet diameter")
    b.legend(fontsize=8)
    fig.suptitle("Discharge of frictional grains through a flat bottom (mu = 0.5), silodem")
    return [(save(fig, out, "discharge_frictional.png"), "Frictional discharge: mass against time and Beverloo",
             "cases/silo_discharge_frictional.json (verify, four outlets)")]


def shear_and_heap(res, out):
    """The direct shear test's stress ratio along the travel and the angle-of-repose heaps' surface
    profiles (one packing per material group), with the angles the checks measured."""
    rows = res.verdicts("verify")
    shear_root = os.path.join(res.verify, "direct_shear")
    heap_root = os.path.join(res.verify, "angle_of_repose")
    if not os.path.isdir(shear_root) and not os.path.isdir(heap_root):
        raise Skip("no direct_shear or angle_of_repose results")
    fig, (a, b) = plt.subplots(1, 2, figsize=(12, 4.5))
    for root, ax in ((shear_root, a), (heap_root, b)):
        if not os.path.isdir(root):
            ax.set_title("not run")
            continue
        for variant in sorted(v for v in os.listdir(root) if v.endswith("seed=2002")):
            label = ",".join(re.split(r"_(?=[A-Za-z0-9.]+=)", variant))
            run = os.path.join(root, variant)
            if root == shear_root:
                probe = read_json(os.path.join(run, "summary.json"))["input"]
                ev = next(e for e in probe["stages"]["events"] if e["type"] == "move_wall")
                v = math.hypot(*ev["velocity"])
                data = [r for r in read_csv(os.path.join(run, "probes", "shear_plane.csv"), need=("t", "fx", "fz"))
                        if r["t"] > ev["time"] and r["fz"] > 0]
                ax.plot([1000 * v * (r["t"] - ev["time"]) for r in data], [-r["fx"] / r["fz"] for r in data], lw=0.8,
                        label=label.replace(",seed=2002", ""))
            else:
                state = read_json(os.path.join(run, "state.json"))["balls"]
                grains = [s for s in state if not s.get("fixed")]
                foot = min(s["position"][2] - s["radius"] for s in grains)
                top = {}
                for s in grains:
                    k = int(math.hypot(s["position"][0], s["position"][1]) / 0.01)
                    top[k] = max(top.get(k, 0.0), s["position"][2] + s["radius"] - foot)
                angle = next((r["measured"] for r in rows if r["case"] == "angle_of_repose"
                              and r["quantity"] == "angle_of_repose_deg" and r["variant"] == label), math.nan)
                ks = sorted(top)
                ax.plot([(k + 0.5) * 10 for k in ks], [1000 * top[k] for k in ks], "-o", ms=2,
                        label="%s: %.1f deg" % (label.replace(",seed=2002", ""), angle))
    a.set(xlabel="travel of the upper ring [mm]", ylabel="tau / sigma across the shear plane",
          title="Direct shear (cases/direct_shear.json), seed 2002")
    b.set(xlabel="distance from the tube's axis [mm]", ylabel="heap surface above its foot [mm]",
          title="Angle of repose heaps (cases/angle_of_repose.json), seed 2002")
    for ax in (a, b):
        ax.legend(fontsize=7)
    return [(save(fig, out, "shear_and_heap.png"), "Direct shear stress ratio along the travel; heap surface profiles "
             "with the fitted angle of repose", "cases/direct_shear.json, cases/angle_of_repose.json (verify)")]


def wall_maps(res, out):
    """The paper's Fig. 7 for the frictional silos: the column at rest after its wall slip, the
    discharge silo filled behind its gate and during the steady flow (silodem, mu 0.5)."""
    panels = []
    col = os.path.join(res.verify, "janssen_frictional")
    if os.path.isdir(col):
        runs = sorted(v for v in os.listdir(col) if "mu=0.5" in v)
        if runs:
            grid, geo = wall_grid(os.path.join(col, runs[0]), "mantle", "pressure_final")
            panels.append(("Janssen column (D 0.18 m),\nat rest after the slip", grid, geo))
    dis = os.path.join(res.verify, "silo_discharge_frictional")
    if os.path.isdir(dis):
        runs = sorted(v for v in os.listdir(dis) if "D0_7.0_d" in v)
        if runs:
            run = os.path.join(dis, runs[0])
            for probe, title in (("mantle_filled", "discharge silo (D 0.14 m),\nfilled, gate closed"),
                                 ("mantle", "the same during discharge\n(time mean, 7 d outlet)")):
                grid, geo = wall_grid(run, probe, "pressure_mean")
                panels.append((title, grid, geo))
    if not panels:
        raise Skip("no frictional column or discharge results")
    fig, axes = plt.subplots(1, len(panels), figsize=(4.6 * len(panels) + 1, 5), squeeze=False, constrained_layout=True)
    for ax, (title, grid, geo) in zip(axes[0], panels):
        im = ax.imshow([[v / 1000 for v in row] for row in grid], origin="lower", aspect="auto", cmap="viridis", vmin=0,
                       extent=[0, 360, geo["centre"][2], geo["centre"][2] + geo["height"]])
        fig.colorbar(im, ax=ax, label="horizontal wall pressure [kPa]", shrink=0.9)
        ax.set(xlabel="angle around the mantle [deg]", ylabel="height [m]", title=title)
    fig.suptitle("Unrolled mantle (the paper's Fig. 7), frictional grains (mu 0.5), silodem; each its own colour scale")
    fig.savefig(os.path.join(out, "figures", "wall_maps_frictional.png"), dpi=100)
    plt.close(fig)
    return [("wall_maps_frictional.png", "Unrolled mantle pressure of the frictional silos",
             "cases/janssen_frictional.json, cases/silo_discharge_frictional.json (verify)")]
