"""Silo figures from silodem's verification runs (and the closure peak from its compare run):
the unrolled wall maps (the paper's Fig. 7), the fill, discharge and gate closure."""
import math
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from .files import (CODE_STYLE, ResultFileError, Skip, field, need_dir, read_csv, read_json,  # noqa: E402
                    wall_bands, wall_grid)


def save(fig, out, name):
    fig.tight_layout()
    fig.savefig(os.path.join(out, "figures", name), dpi=100)
    plt.close(fig)
    return name


def dump_frame(path, step):
    """Rows (dicts of floats) of frame `step` of a silodem/LAMMPS-style text dump."""
    try:
        f = open(path)
    except FileNotFoundError:
        raise ResultFileError("%s: missing" % path)
    with f:
        for line in f:
            if line.startswith("ITEM: TIMESTEP") and int(next(f)) == step:
                next(f)
                n = int(next(f))
                for _ in range(4):
                    next(f)
                cols = next(f).split()[2:]
                return [dict(zip(cols, map(float, next(f).split()))) for _ in range(n)]
    raise ResultFileError("%s: no frame at step %d" % (path, step))


def mantle_map_from_frame(rows, geo, na, nh):
    """Horizontal pressure [Pa] on (height, angle) cells of the mantle from the wall balls' loads."""
    r_wall, z0, h = geo["diameter"] / 2, geo["centre"][2], geo["height"]
    force = [[0.0] * na for _ in range(nh)]
    for b in rows:
        rho = math.hypot(b["x"], b["y"])
        if b["fixed"] != 1 or not (z0 <= b["z"] <= z0 + h) or rho < r_wall - 1e-9:
            continue
        a = min(na - 1, int((math.atan2(b["y"], b["x"]) % (2 * math.pi)) / (2 * math.pi) * na))
        k = min(nh - 1, int((b["z"] - z0) / h * nh))
        force[k][a] += (b["fx"] * b["x"] + b["fy"] * b["y"]) / rho
    area = math.pi * geo["diameter"] / na * h / nh
    return [[f / area for f in row] for row in force]


def wall_maps(res, out):
    """Fig. 7 three times: after filling, during discharge, at the peak after the gate closure."""
    panels = []
    fill = os.path.join(res.verify, "silo_fill", "base")
    if os.path.isdir(fill):
        grid, geo = wall_grid(fill, "mantle", "pressure_final")
        panels.append(("after filling,\nat rest", grid, geo))
    dis = os.path.join(res.verify, "silo_discharge", "outlet=D0_36_mm")
    if os.path.isdir(dis):
        grid, geo = wall_grid(dis, "mantle", "pressure_mean")
        panels.append(("during discharge\n(time mean, 36 mm outlet)", grid, geo))
    clo = os.path.join(res.compare, "silo_closure", "base", "silodem")
    if os.path.isdir(clo):
        hist = read_csv(os.path.join(clo, "probes", "hopper_history.csv"), need=("t",))
        s = read_json(os.path.join(clo, "summary.json"))
        close_t = next(e["time"] for e in field(s, clo + "/summary.json", ["input", "stages", "events"])
                       if e["type"] == "close_outlet")
        after = [r for r in hist if r["t"] >= close_t]
        if after:
            peak = max(after, key=lambda r: sum(v for k, v in r.items() if k.startswith("band")))
            dt, every = s["derived"]["dt"], s["input"]["output"]["dump_interval_steps"]
            step = int(round(peak["t"] / dt / every)) * every
            bins, geo = wall_grid(clo, "mantle", "pressure_final")  # for the bin counts and the geometry
            grid = mantle_map_from_frame(dump_frame(os.path.join(clo, "dump.txt"), step), geo, len(bins[0]), len(bins))
            panels.append(("%.0f ms after the gate closure\n(hopper pressure peak)" % (1000 * (step * dt - close_t)), grid, geo))
    if not panels:
        raise Skip("no silo fill, discharge or closure results")
    vmax = max(max(max(r) for r in g) for _, g, _ in panels) / 1000
    fig, axes = plt.subplots(1, len(panels), figsize=(4.8 * len(panels) + 1, 4.8), squeeze=False, constrained_layout=True)
    for ax, (title, grid, geo) in zip(axes[0], panels):
        im = ax.imshow([[v / 1000 for v in row] for row in grid], origin="lower", aspect="auto", cmap="viridis",
                       vmin=0, vmax=vmax, extent=[0, 360, geo["centre"][2], geo["centre"][2] + geo["height"]])
        ax.set(xlabel="angle around the mantle [deg]", ylabel="height above the transition [m]", title=title)
    fig.colorbar(im, ax=list(axes[0]), label="horizontal wall pressure [kPa]", shrink=0.9)
    fig.suptitle("Unrolled mantle (the paper's Fig. 7), silodem, one colour scale")
    fig.savefig(os.path.join(out, "figures", "wall_maps.png"), dpi=100)
    plt.close(fig)
    return [("wall_maps.png", "Unrolled mantle pressure after filling, during discharge and after the gate closure",
             "cases/silo_fill.json, cases/silo_discharge.json (verify), cases/silo_closure.json (compare, silodem dump)")]


def silo_fill(res, out):
    run = need_dir(os.path.join(res.verify, "silo_fill", "base"), "silo fill")
    s = read_json(os.path.join(run, "summary.json"))
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.5))
    for probe, style in (("mantle", "o-"), ("hopper", "s-")):
        z, p, geo = wall_bands(run, probe, "pressure_final")
        if probe == "hopper":  # cone bands run from the outlet up to the transition at z = 0
            z = [-geo["height"] * (1 - (h + 0.5) / len(z)) for h in range(len(z))]
        axes[0].plot([v / 1000 for v in p], z, style, label=probe)
    axes[0].axhline(field(s, run, ["fill", "z_top"]), color="k", ls="--", lw=0.8, label="fill top")
    axes[0].set(xlabel="angle-averaged wall pressure [kPa]", ylabel="height [m]", title="pressure against height, at rest")
    axes[0].legend(fontsize=8)
    drops = read_csv(os.path.join(run, "probes", "drops.csv"), need=("t",), text=("outcome",))
    placed, n = [], 0
    for d in drops:
        n += d["outcome"] == "placed"
        placed.append(n)
    t = [d["t"] for d in drops]
    axes[1].plot(t, placed, label="placed")
    axes[1].plot(t, [i + 1 - k for i, k in enumerate(placed)], label="rejected")
    axes[1].set(xlabel="time [s]", ylabel="drops", title="fill history (at rest at t = %.2f s)" % s["run"]["time"])
    axes[1].legend(fontsize=8)
    fig.suptitle("Silo fill by analytic drops (Algorithm 5): %d balls, silodem" % s["balls"]["mobile"])
    return [(save(fig, out, "silo_fill.png"), "Silo fill: wall pressure at rest and fill history", "cases/silo_fill.json (verify)")]


def outlet_flows(root, a):
    """Per outlet variant of a discharge case: its discharged mass against time drawn on axes `a`,
    the steady rate as its beverloo check takes it; returns ([(D0, W)], (rho_b, d), {variant: run})."""
    pts, consts, runs = [], None, {}
    for variant in sorted(os.listdir(root)):
        run = os.path.join(root, variant)
        if not os.path.isdir(run):
            continue
        runs[variant] = run
        rows = read_csv(os.path.join(run, "probes", "outflow.csv"), need=("t", "cumulative_mass"))
        s = read_json(os.path.join(run, "summary.json"))
        a.plot([r["t"] for r in rows], [r["cumulative_mass"] for r in rows], label=variant.replace("outlet=", ""))
        checks = field(s, run, ["input", "verify", "checks"])
        bev = next(ch for ch in checks if ch["type"] == "beverloo")
        consts = (bev["bulk_density"], bev["grain_diameter"])
        late = [r for r in rows if r["t"] >= bev["from_time"]]
        d0 = next(w["hole_diameter"] for w in s["input"]["walls"] if w["name"] == bev["outlet_wall"])
        if len(late) > 2:
            pts.append((d0, (late[-1]["cumulative_mass"] - late[0]["cumulative_mass"]) / (late[-1]["t"] - late[0]["t"])))
    return pts, consts, runs


def discharge(res, out):
    root = need_dir(os.path.join(res.verify, "silo_discharge"), "silo discharge")
    fig, (a, b, c) = plt.subplots(1, 3, figsize=(15, 4.3))
    pts, consts, runs = outlet_flows(root, a)
    for variant, run in runs.items():
        if variant == "outlet=D0_36_mm":
            zf, pf, _ = wall_bands(run, "mantle_filled", "pressure_mean")
            _, pe, _ = wall_bands(run, "mantle", "pressure_mean")
            keep = [i for i, p in enumerate(pf) if p > 0.05 * max(pf)]
            c.plot([pe[i] / pf[i] for i in keep], [zf[i] for i in keep], "o-", label="silodem, 36 mm outlet")
    a.set(xlabel="time [s]", ylabel="discharged mass [kg]", title="discharged mass (leavers recycled)")
    a.legend(fontsize=8)
    fit = {r["quantity"]: r["measured"] for r in res.verdicts("verify") if r["case"] == "silo_discharge"
           and r["quantity"] in ("beverloo_C", "beverloo_k")}
    if pts:
        b.plot([d * 1000 for d, _ in pts], [w for _, w in pts], "o", label="silodem, steady flow")
    if pts and len(fit) == 2 and consts:
        rho, d = consts
        xs = [min(p[0] for p in pts) * (0.8 + 0.5 * i / 50) for i in range(51)]
        w = [fit["beverloo_C"] * rho * math.sqrt(9.81) * max(0.0, x - fit["beverloo_k"] * d) ** 2.5 for x in xs]
        b.plot([x * 1000 for x in xs], w, "-", label="Beverloo, fitted C = %.2f, k = %.2f" % (fit["beverloo_C"], fit["beverloo_k"]))
        w0 = [0.58 * rho * math.sqrt(9.81) * max(0.0, x - 1.5 * d) ** 2.5 for x in xs]
        b.plot([x * 1000 for x in xs], w0, "--", label="Beverloo, C = 0.58, k = 1.5 (frictional)")
    b.set(xlabel="outlet diameter D0 [mm]", ylabel="mass flow rate [kg/s]", title="flow rate against outlet diameter")
    b.legend(fontsize=8)
    c.axvline(1.15, color="k", ls="--", lw=0.8, label="EN 1991-4 C_h = 1.15")
    c.axvline(1.0, color="grey", lw=0.5)
    c.set(xlabel="p_h in discharge / p_h after filling", ylabel="height above the transition [m]", title="discharge factor")
    c.legend(fontsize=8)
    fig.suptitle("Discharge through the hopper outlet, silodem")
    return [(save(fig, out, "discharge.png"), "Discharge: mass against time, Beverloo, discharge factor",
             "cases/silo_discharge.json (verify, three outlets)")]


def closure(res, out):
    """Band pressure histories through the sudden closure, every code from the same state."""
    return closure_of(res, out, "silo_closure", "closure_history.png", "")


def closure_frictional(res, out):
    """The same with frictional grains (mu 0.5, wall 0.3, history springs)."""
    return closure_of(res, out, "silo_closure_frictional", "closure_history_frictional.png", " with friction")


def closure_of(res, out, case, name, what):
    runs = res.run_dirs("compare", case, "base")
    if not runs:
        raise Skip("%s compare not in these results" % case)
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.3))
    if "silodem" not in runs:
        raise Skip("silodem's closure run is not in these results")
    s = read_json(os.path.join(runs["silodem"], "summary.json"))
    start = s["run"]["start_step"] * s["derived"]["dt"]
    close_t = next(e["time"] for e in field(s, runs["silodem"], ["input", "stages", "events"]) if e["type"] == "close_outlet")
    for code, run in runs.items():
        for ax, probe in zip(axes, ("hopper", "mantle")):
            rows = read_csv(os.path.join(run, "probes", probe + "_history.csv"), need=("t",))
            bands = [k for k in rows[0] if k.startswith("band")]
            mean = [sum(r[k] for k in bands) / len(bands) / 1000 for r in rows]
            colour, _ = CODE_STYLE[code]
            ax.plot([r["t"] for r in rows], mean, color=colour, lw=1, label=code)
    for ax, probe in zip(axes, ("hopper", "mantle")):
        ax.axvline(close_t, color="k", ls="--", lw=0.8)
        ax.set(xlabel="time [s] (gate closed at %.3g s)" % close_t, ylabel="mean band pressure [kPa]",
               title=probe + ": pressure through the closure")
        ax.legend(fontsize=8)
    fig.suptitle("Sudden gate closure%s: every code from one state, silodem's at t = %.3g s" % (what, start))
    return [(save(fig, out, name), "Gate closure%s: wall pressure history in every code" % what,
             "cases/%s.json (compare)" % case)]
