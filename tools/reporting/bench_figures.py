"""Benchmark figures: error against run time (work-precision) per integrator from the restitution
verification runs, and from the benchmark JSON: throughput against ball count per code, cost per
ball-step against N (silodem and LAMMPS on the same beds), stability limits, feature cost."""
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from .files import Skip, read_json  # noqa: E402
from .silo_figures import save  # noqa: E402


def bench_json(res, name, what, command):
    """The benchmark JSON `name` beside res.bench and its rows; Skip, naming the command that
    writes it, when it is missing or has no rows."""
    path = os.path.join(os.path.dirname(res.bench or ""), name)
    if not os.path.exists(path):
        raise Skip("no %s (%s; run %s)" % (what, path, command))
    b = read_json(path)
    if not b.get("rows"):
        raise Skip("%s has no rows" % what)
    return b, b["rows"]


def work_precision(res, out):
    """Worst restitution error of each (integrator, Δt) variant against its solver wall time."""
    rows = [r for r in res.verdicts("verify") if r["case"] == "collision_restitution" and r["quantity"] == "restitution"]
    if not rows:
        raise Skip("collision restitution verification not in these results")
    err, secs = {}, {}
    for r in rows:
        err[r["variant"]] = max(err.get(r["variant"], 0.0), abs(r["measured"] / r["expected"] - 1) if r["expected"] else 0.0)
    base = os.path.join(res.verify, "collision_restitution")
    for v in err:
        path = os.path.join(base, v.replace(",", "_"), "summary.json")
        if os.path.exists(path):
            secs[v] = read_json(path)["run"]["wall_seconds"]
    fig, ax = plt.subplots(figsize=(7, 5))
    schemes = sorted({v.split("integrator=")[-1] for v in err})
    for k, scheme in enumerate(schemes):
        for end, style in (("contact_end=clamped", "o-"), ("contact_end=unclamped", "s--")):
            pts = sorted((secs[v], err[v]) for v in err if v.endswith("integrator=" + scheme) and v.startswith(end) and v in secs)
            if pts:
                ax.loglog([p[0] for p in pts], [max(p[1], 1e-12) for p in pts], style, color="C%d" % k,
                          label="%s, %s" % (scheme, end.split("=")[1]))
    ax.set(xlabel="solver wall time for the case (all pairs) [s]", ylabel="worst |e / e_theory − 1|",
           title="Work-precision, collision_restitution, silodem: restitution error against run time\n(Δt = t_c/50 and t_c/100 per line; lower left is better)")
    ax.legend(fontsize=7)
    return [(save(fig, out, "work_precision.png"), "Work-precision of the integrators (restitution error against run time)",
             "cases/collision_restitution.json (verify)")]


def throughput(res, out):
    """Particle-steps per second against N for every code and thread/rank count in the dense
    anchor benchmark (bench_dense.json, tools/bench_dense.py); else the older whole-run benchmark
    (benchmarks.json: silodem and LAMMPS, 1 thread/rank)."""
    dense = os.path.join(os.path.dirname(res.bench or ""), "bench_dense.json")
    series, title, source = {}, "", ""
    if os.path.exists(dense):
        b = read_json(dense)
        for r in b.get("rows", []):
            for key, mps in r.get("mps", {}).items():
                code, _, n = key.rpartition("_")
                law = r.get("contact", "frictionless")  # frictionless and frictional rows: separate curves
                series.setdefault("%s, %s %s, %s" % (code, n, "rank(s)" if code in ("lammps", "liggghts") else "thread(s)",
                                                     law), []).append((r["mobile"], mps))
        title, source = "dense anchor scene, %s" % b.get("date", "?"), "tools/bench_dense.py"
    elif res.bench and os.path.exists(res.bench):
        b = read_json(res.bench)
        for r in b.get("rows", []):
            for key, label in (("silodem_mps", "silodem, 1 thread"), ("lammps_mps", "lammps, 1 rank(s)")):
                if key in r:
                    series.setdefault(label, []).append((r["mobile"], r[key]))
        title, source = "settling scene, whole run, %s" % b.get("date", "?"), "tools/bench_throughput.py"
    if not series:
        raise Skip("no benchmark JSON with rows (%s, %s)" % (dense, res.bench))
    fig, ax = plt.subplots(figsize=(7, 5))
    for k, (label, pts) in enumerate(sorted(series.items())):
        pts.sort()
        ax.semilogx([n for n, _ in pts], [m for _, m in pts], "o-", color="C%d" % k, label=label)
    ax.set(xlabel="mobile balls", ylabel="million particle-steps per second",
           title="Throughput per code, same scene and step count (%s)" % title)
    ax.set_ylim(bottom=0)
    ax.legend(fontsize=8)
    return [(save(fig, out, "throughput.png"), "Throughput against ball count, every code measured in the same run",
             source)]


def stability(res, out):
    """Largest stable ωΔt per scheme against ζ (bench/stability_limits.cpp), with docs/theory.md §7
    and the limit the case loader enforces."""
    _, rows = bench_json(res, "stability.json", "stability benchmark", "build/bench/bench_stability reports")
    fig, ax = plt.subplots(figsize=(8, 5.5))
    schemes = []
    for r in rows:
        if r["scheme"] not in schemes:
            schemes.append(r["scheme"])
    for k, s in enumerate(schemes):
        mine = [r for r in rows if r["scheme"] == s]
        z = [r["zeta"] for r in mine]
        ax.plot(z, [r["measured_omega_dt"] for r in mine], "o-", color="C%d" % k, ms=4, label=s + " (measured)")
        th = [(r["zeta"], r["theory_omega_dt"]) for r in mine if r["theory_omega_dt"] is not None]
        if len(th) > 1:
            ax.plot([a for a, _ in th], [b for _, b in th], "x", color="k", ms=8)
        elif th:
            ax.plot([th[0][0]], [th[0][1]], "x", color="k", ms=8)
    ax.plot([], [], "x", color="k", label="docs/theory.md §7 (closed forms)")
    ax.set(xlabel="damping ratio ζ", ylabel="largest stable ω Δt",
           title="Stability limits on one linear contact, silodem's integrators\n(%d steps per trial; bisection to 1e-4)"
                 % rows[0]["steps"])
    ax.legend(fontsize=7)
    return [(save(fig, out, "stability.png"), "Stability limits of the integrators against theory",
             "bench/stability_limits.cpp (build/bench/bench_stability reports)")]


def dense_stability(res, out):
    """Largest stable step in a caged FCC block against the top eigenvalue of its contact network
    (bench/dense_stability.cpp), beside the one-contact limit the loader enforces."""
    b, rows = bench_json(res, "dense_stability.json", "dense-packing stability benchmark",
                         "build/bench/bench_dense_stability reports")
    fig, ax = plt.subplots(figsize=(9, 5))
    labels = ["%s\nζ=%.1f" % (r["scheme"].replace("predictor_corrector", "PC").replace("velocity_verlet", "Verlet"), r["zeta_pair"])
              for r in rows]
    xs = range(len(rows))
    ax.bar([x - 0.2 for x in xs], [r["measured_omega_dt"] for r in rows], 0.4, label="measured (FCC block)")
    ax.bar([x + 0.2 for x in xs], [r["loader_omega_dt"] for r in rows], 0.4, color="0.75",
           label="one-contact limit (the loader's)")
    th = [(x, r["theory_omega_dt"]) for x, r in zip(xs, rows) if r["theory_omega_dt"] is not None]
    ax.plot([x - 0.2 for x, _ in th], [t for _, t in th], "kx", ms=9, label="eigenvalue oracle")
    ax.set_xticks(list(xs))
    ax.set_xticklabels(labels, fontsize=7)
    ax.set(ylabel="largest stable ω_pair Δt",
           title="Stability in a dense packing: %d balls, 12 contacts each (ω_max/ω_pair = %.3f)"
                 % (b["mobile"], b["omega_max_over_omega_pair"]))
    ax.legend(fontsize=8)
    return [(save(fig, out, "dense_stability.png"), "Stable time step in a dense packing against its highest natural frequency",
             "bench/dense_stability.cpp (build/bench/bench_dense_stability reports)")]


def feature_cost(res, out):
    """Time per step of each feature against the base scene (bench/feature_cost.cpp)."""
    b, rows = bench_json(res, "feature_cost.json", "feature-cost benchmark", "build/bench/bench_feature_cost reports")
    fig, ax = plt.subplots(figsize=(9, 5))
    vals = [100.0 * (r["ratio_to_base"] - 1.0) for r in rows]
    ax.barh(range(len(rows)), vals, color=["C2" if abs(v) <= 100 * b["base_spread"] else "C0" for v in vals])
    ax.axvspan(-100 * b["base_spread"], 100 * b["base_spread"], color="0.85", label="base's own spread (noise)")
    ax.set_yticks(range(len(rows)))
    ax.set_yticklabels([r["variant"] for r in rows], fontsize=8)
    ax.set(xlabel="time per step against the base scene (%)",
           title="What each feature costs: %d mobile + %d wall balls, %d steps, median of %d"
                 % (b["mobile"], b["wall"], b["steps"], b["repeats"]))
    ax.legend(fontsize=8)
    return [(save(fig, out, "feature_cost.png"), "Time per step with each feature on, against the base scene",
             "bench/feature_cost.cpp (build/bench/bench_feature_cost reports)")]


def scaling(res, out):
    """Cost per ball-step against N for silodem and LAMMPS on the same beds (bench_scaling.json,
    tools/bench_scaling.py): absolute, and relative to each series' cheapest bed with the 20 % target."""
    b, rows = bench_json(res, "bench_scaling.json", "scaling benchmark", "/usr/bin/python3 tools/bench_scaling.py")
    beds = (("wide bed", rows), ("tiled control", rows[:1] + b.get("tiled_rows", [])))
    fig, (ax, rel) = plt.subplots(1, 2, figsize=(11, 4.5))
    for k, (code, get) in enumerate((("silodem", lambda r: r["ns_per_ball_step"]),
                                     ("LAMMPS", lambda r: (r.get("lammps") or {}).get("ns_per_ball_step")))):
        for bed, style in zip(beds, ("o-", "s--")):
            pts = [(r["mobile"], get(r)) for r in bed[1] if get(r)]
            if len(pts) < 2:
                continue
            label = "%s, %s" % (code, bed[0])
            ax.semilogx([n for n, _ in pts], [t for _, t in pts], style, color="C%d" % k, label=label)
            # Relative to the series' cheapest bed: the target bounds largest over smallest.
            cheapest = min(t for _, t in pts)
            rel.semilogx([n for n, _ in pts], [t / cheapest for _, t in pts], style, color="C%d" % k, label=label)
    rel.axhspan(1.0, 1.2, color="0.88", label="largest/smallest ≤ 1.2 (the target)")
    ax.set(xlabel="mobile balls", ylabel="ns per mobile ball-step (1 thread / 1 rank, CPU 0)", title="Cost per ball-step")
    ax.set_ylim(bottom=0)
    rel.set(xlabel="mobile balls", ylabel="relative to the cheapest bed",
            title="Growth with N (%s)" % b.get("date", "?"))
    ax.legend(fontsize=8)
    rel.legend(fontsize=8)
    return [(save(fig, out, "scaling.png"), "Cost per ball-step from 5,000 to 10^6 balls, silodem and LAMMPS on the same beds",
             "tools/bench_scaling.py")]
