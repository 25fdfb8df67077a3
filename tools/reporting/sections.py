"""Vertical sections through the silo (the paper's Figs. 4-6): balls in a slab around the plane
y = 0 coloured by speed, their velocity vectors, and the contact force network (line width in
proportion to the normal force k δ + c δ̇ of each touching pair, docs/model.md §2, (3)-(5), series k and c)."""
import math
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import LineCollection, PatchCollection  # noqa: E402
from matplotlib.patches import Circle  # noqa: E402

from .files import Skip, field, read_json  # noqa: E402
from .silo_figures import save  # noqa: E402


def section(res, out):
    run = os.path.join(res.compare, "silo_discharge", "base", "silodem")
    if not os.path.exists(os.path.join(run, "state.json")):
        raise Skip("silo discharge compare (silodem) not in these results")
    state = read_json(os.path.join(run, "state.json"))
    s = read_json(os.path.join(run, "summary.json"))
    mats = field(s, run + "/summary.json", ["derived", "materials"])
    balls = field(state, run + "/state.json", ["balls"])
    fixed = [b.get("fixed", False) for b in balls]
    slab = 0.5 * max(b["radius"] for b in balls)  # half-thickness of the slab of centres shown
    near = [i for i, b in enumerate(balls) if abs(b["position"][1]) < b["radius"]]
    fig, axes = plt.subplots(1, 3, figsize=(15, 6.2), sharey=True)
    speed = {i: math.sqrt(sum(v * v for v in balls[i].get("velocity", [0, 0, 0]))) for i in near}
    vmax = max([speed[i] for i in near if not fixed[i]] + [1e-9])
    for ax in axes:
        walls = [Circle((balls[i]["position"][0], balls[i]["position"][2]),
                        math.sqrt(max(balls[i]["radius"] ** 2 - balls[i]["position"][1] ** 2, 0))) for i in near if fixed[i]]
        ax.add_collection(PatchCollection(walls, facecolor="0.75", edgecolor="none"))
        ax.set_aspect("equal")
        ax.set_xlabel("x [m]")
    mob = [i for i in near if not fixed[i]]
    grains = PatchCollection([Circle((balls[i]["position"][0], balls[i]["position"][2]),
                                     math.sqrt(max(balls[i]["radius"] ** 2 - balls[i]["position"][1] ** 2, 0))) for i in mob],
                             cmap="plasma", edgecolor="none")
    grains.set_array([speed[i] for i in mob])
    grains.set_clim(0, vmax)
    axes[0].add_collection(grains)
    fig.colorbar(grains, ax=axes[0], label="speed [m/s]", shrink=0.7)
    axes[0].set_title("balls cut by y = 0, coloured by speed")
    axes[0].set_ylabel("z [m]")
    in_slab = [i for i in mob if abs(balls[i]["position"][1]) < slab]
    axes[1].quiver([balls[i]["position"][0] for i in in_slab], [balls[i]["position"][2] for i in in_slab],
                   [balls[i]["velocity"][0] for i in in_slab], [balls[i]["velocity"][2] for i in in_slab],
                   [speed[i] for i in in_slab], cmap="plasma", angles="xy", scale_units="xy",
                   scale=vmax / (10 * slab) if vmax > 0 else 1, width=0.004)
    axes[1].set_title("velocities of the centres within ±%.1f mm" % (1000 * slab))
    # Contact force network: every touching pair of balls both cut by the plane.
    pick = near
    cell = 2.2 * max(b["radius"] for b in balls)
    grid = {}
    for i in pick:
        x, _, z = balls[i]["position"]
        grid.setdefault((int(math.floor(x / cell)), int(math.floor(z / cell))), []).append(i)
    segs, forces = [], []
    for (gx, gz), members in grid.items():
        for i in members:
            for dx in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    for j in grid.get((gx + dx, gz + dz), []):
                        if j <= i or (fixed[i] and fixed[j]):
                            continue
                        bi, bj = balls[i], balls[j]
                        d = [a - b for a, b in zip(bi["position"], bj["position"])]
                        dist = math.sqrt(sum(v * v for v in d))
                        delta = bi["radius"] + bj["radius"] - dist
                        if delta <= 0 or dist == 0:
                            continue
                        ki, kj = mats[bi["material"]]["k"], mats[bj["material"]]["k"]
                        ci, cj = mats[bi["material"]]["c"], mats[bj["material"]]["c"]
                        vi, vj = bi.get("velocity", [0, 0, 0]), bj.get("velocity", [0, 0, 0])
                        rate = -sum((a - b) * n / dist for a, b, n in zip(vi, vj, d))  # dδ/dt
                        f = ki * kj / (ki + kj) * delta + (ci * cj / (ci + cj) if ci + cj > 0 else 0.0) * rate
                        if f > 0:
                            segs.append([(bi["position"][0], bi["position"][2]), (bj["position"][0], bj["position"][2])])
                            forces.append(f)
    if forces:
        fmax = max(forces)
        axes[2].add_collection(LineCollection(segs, linewidths=[0.2 + 3.5 * f / fmax for f in forces], colors="k"))
    axes[2].set_title("contact forces (line width ∝ normal force, largest %.3g N)" % (max(forces) if forces else 0))
    xs = [balls[i]["position"][0] for i in near]
    zs = [balls[i]["position"][2] for i in near]
    for ax in axes:
        ax.set_xlim(min(xs) - cell, max(xs) + cell)
        ax.set_ylim(min(zs) - cell, max(zs) + cell)
    fig.suptitle("Vertical section y = 0 during discharge (the paper's Figs. 4-6), silodem at t = %.3f s, %d balls cut"
                 % (state["time"], len(mob)))
    return [(save(fig, out, "section.png"), "Vertical section during discharge: speed, velocities, force network",
             "cases/silo_discharge.json (compare, silodem's final state)")]
