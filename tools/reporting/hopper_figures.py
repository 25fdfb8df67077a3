"""Mass flow or funnel flow: the velocity sections of the frictional hopper silos (the
velocity_field probe's time-mean downward speed on rings about the axis), one panel per hopper
half-angle, with the mass flow index and Jenike's predicted pattern from the verdicts."""
import math
import os
import re

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import LogNorm  # noqa: E402

from .files import Skip, need_dir, read_csv, read_json  # noqa: E402


def flow_pattern(res, out):
    root = need_dir(os.path.join(res.verify, "hopper_flow_pattern"), "hopper flow pattern")
    variants = sorted(v for v in os.listdir(root) if os.path.isdir(os.path.join(root, v)) and "mu=0.5" in v)
    if not variants:
        raise Skip("no mu = 0.5 run of hopper_flow_pattern")
    rows = [r for r in res.verdicts("verify") if r["case"] == "hopper_flow_pattern"]
    fig, axes = plt.subplots(1, len(variants), figsize=(5.5 * len(variants) + 1, 6), squeeze=False,
                             constrained_layout=True)
    for ax, variant in zip(axes[0], variants):
        run = os.path.join(root, variant)
        label = ",".join(re.split(r"_(?=[A-Za-z0-9.]+=)", variant))
        field = read_csv(os.path.join(run, "probes", "flow.csv"), need=("r_centre", "z_centre", "mean_vz", "solid_fraction"))
        nr = 1 + int(max(c["radial_bin"] for c in field))
        nz = 1 + int(max(c["height_bin"] for c in field))
        grid = [[math.nan] * nr for _ in range(nz)]
        for c in field:
            if c["solid_fraction"] >= 0.2:
                grid[int(c["height_bin"])][int(c["radial_bin"])] = max(0.5, -1000 * c["mean_vz"])
        geo = read_json(os.path.join(run, "summary.json"))["probes"]["flow"]
        z0, z1, R = geo["z"][0], geo["z"][1], geo["radius"]
        mirrored = [row[::-1] + row for row in grid]  # the section through the axis, both sides
        # Log scale: a funnel flow's resting zone (a few mm/s) apart from the plug above (tens).
        im = ax.imshow(mirrored, origin="lower", aspect="equal", cmap="viridis", norm=LogNorm(vmin=0.5, vmax=1000),
                       extent=[-R * 1000, R * 1000, z0 * 1000, z1 * 1000])
        fig.colorbar(im, ax=ax, label="mean downward speed [mm/s] (0.5: at rest or rising)", shrink=0.8)
        pick = {r["quantity"]: r for r in rows if r["variant"] == label}
        mfi = pick.get("mass_flow_index", {}).get("measured", math.nan)
        pattern = pick.get("flow_pattern_is_mass_flow", {})
        predicted = {1.0: "mass flow", 0.0: "funnel flow"}.get(pattern.get("expected"), "?")
        ax.set(xlabel="r [mm]", ylabel="z above the transition [mm]",
               title="%s\nMFI = %.2f (mass flow if >= 0.3)\nJenike predicts %s: %s"
               % (label, mfi, predicted, pattern.get("verdict", "not judged")))
        ax.title.set_fontsize(9)
        ax.axhline(0.0, color="grey", lw=0.5)
    fig.suptitle("Velocity section during discharge, time mean over the steady flow (silodem)")
    fig.savefig(os.path.join(out, "figures", "flow_pattern.png"), dpi=100)
    plt.close(fig)
    return [("flow_pattern.png", "Hopper flow pattern: velocity sections against Jenike's boundary",
             "cases/hopper_flow_pattern.json (verify, with the material tests)")]
