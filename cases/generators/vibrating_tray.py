#!/usr/bin/env python3
"""Writes cases/vibrating_tray.json: seed 001's tray (Bogulsky & Bogulskaya 2011; the notes' I.2),
reduced: a planar tray 50 cm long with three slots of 3 d = 2.4 cm (at the middle and 12.5 cm
either side: the text gives no positions), vibrating horizontally with A = 1 cm; 600 frictional
discs (d = 0.8 cm, disc inertia) of a shell ten times stiffer than the seed's (k = m g / eps per
disc, eps = 0.001 r; the seed's 0.01 r lets the settling pile pass through itself, overlaps > 0.9 r) on a loose lattice, 15 layers, that settle onto the floor as the run starts. The
frequency axis: still, 5 Hz (Gamma = 1.0) and the paper's 9 Hz (Gamma = 3.26). Velocity Verlet at
dt = t_c/50 (the seed's midpoint scheme at 2 ms needs its viscosity window: equilibrium_column).
Checks: the grain count (judged exactly), the discharge through each slot and Gamma (reported);
an area-fraction map of the bed from 1 s (probes/density_map.csv).
Run from the repository root: python3 cases/generators/vibrating_tray.py
  --packing S --out F: another realisation, each lattice grain moved along x by a uniform draw in
  [-1, 1] mm (seeded by S), for the seed scatter of the slot rate (reports/vibrating_tray.md).
  --scale N --out F: N trays side by side as one, N times as long with N times the grains and the
  slots (the speed runs' larger size, reports/vibrating_tray.md); its between-codes rows are
  reports (the seed scatter was measured at scale 1).
"""
import argparse
import math
import random

from common import as_speed_run, write_case

G, R, RHO = 9.81, 0.004, 2500.0
MASS = RHO * 4.0 / 3.0 * math.pi * R ** 3
EPS = 0.001 * R  # ten times the seed's shell stiffness: its 0.01 r lets a falling pile pass through itself
K_SHELL = MASS * G / EPS
LENGTH, HEIGHT, SLOT = 0.5, 0.2, 0.024
SLOTS = [-0.125, 0.0, 0.125]
COLUMNS, LAYERS = 40, 15


def tray(frequency):
    t = {"name": "tray", "type": "tray", "material": "steel", "radius": [R, R], "spacing": 0.002, "centre": [0, 0, 0],
         "length": LENGTH, "height": HEIGHT, "slots": [{"x": x, "width": SLOT} for x in SLOTS]}
    if frequency > 0.0:
        t["motion"] = {"oscillation": {"direction": [1, 0, 0], "amplitude": 0.01, "frequency": frequency}}
    return t


parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
parser.add_argument("--packing", type=int, help="seed of a jittered lattice (default: none, the regular one)")
parser.add_argument("--scale", type=int, default=1, help="N trays' length and grains in one (default 1)")
parser.add_argument("--out", default="cases/vibrating_tray.json")
args = parser.parse_args()
if args.scale < 1:
    parser.error("--scale must be at least 1")
LENGTH, COLUMNS = LENGTH * args.scale, COLUMNS * args.scale
SLOTS = [0.5 * (2 * k + 1 - args.scale) * 0.5 + x for k in range(args.scale) for x in SLOTS]
jitter = random.Random(args.packing) if args.packing is not None else None

balls = []
pitch = (LENGTH - 4 * R) / COLUMNS
for layer in range(LAYERS):
    for col in range(COLUMNS):
        x = -0.5 * LENGTH + 2 * R + pitch * (col + 0.5 + 0.25 * (layer % 2))
        if x > 0.5 * LENGTH - 2 * R:
            continue
        if jitter:
            x += jitter.uniform(-0.001, 0.001)  # the lattice's gap is 4 mm: no overlap
        balls.append({"id": "g%d_%d" % (layer, col), "material": "grain", "radius": R,
                      "position": [round(x, 6), 0.0, round(0.0085 + 0.0085 * layer, 6)]})

grain = {"density": RHO, "stiffness": K_SHELL, "restitution": 0.3, "reference_radius": R, "friction": 0.5,
         "tangential_damping_ratio": 0.5}
case = {
    "format": "silodem-case/1",
    "name": "vibrating_tray",
    "description": "Seed 001's vibrating tray, reduced: 600 discs in a planar 50 cm tray with three slots of 3 d, "
                   "still, at 5 Hz and at the paper's 9 Hz (A = 1 cm): discharge per slot against Gamma.",
    "dimension": 2,
    "grain_inertia": "disc",
    "gravity": [0, 0, -G],
    "contact": {"tangential": "linear_history"},
    "materials": {"grain": grain, "steel": dict(grain, stiffness=1e3 * K_SHELL)},
    "balls": balls,
    "walls": [tray(9.0)],
    "stages": {"outflow": {"below_z": -0.05, "mode": "remove"}},
    "integrator": {"scheme": "velocity_verlet"},
    "time": {"dt_per_contact_time": 0.02, "duration": 3.0},
    "output": {"series_interval": 0.01, "probes": [{"type": "outflow", "name": "out"},
                                                   {"type": "wall_load", "name": "tray_load", "wall": "tray", "interval": 0.01},
                                                   # Where the bed compacts: 2 cm cells (2.5 d: centre counting) over the tray, from 1 s.
                                                   {"type": "area_fraction", "name": "density_map", "x": [-0.5 * LENGTH, 0.5 * LENGTH],
                                                    "z": [0.0, 0.16], "x_bins": 25 * args.scale, "z_bins": 8, "interval": 0.01,
                                                    "from_time": 1.0}]},
    "verify": {
        "variants": {"frequency": {"still": {"walls": [tray(0.0)]}, "f5": {"walls": [tray(5.0)]}, "f9": {}}},
        "checks": [
            {"type": "slot_discharge", "outflow_probe": "out", "tray": "tray", "from_time": 1.0},
            {"type": "energy_balance", "tolerance": 0.05},
        ]},
    # The paper's 9 Hz in every code (the planar mode: LAMMPS and LIGGGHTS in their turned x-y plane,
    # YADE with blocked degrees of freedom), with its run time. Leavers are removed every 20 steps and
    # the dump is read every 233 steps (0.01 s); the clamp is YADE's (its linear law clamps), the
    # dashpot at the half-step velocity every code's velocity Verlet.
    "compare": {
        "base": {"contact": {"clamp_tensile_force": True},
                 "integrator": {"scheme": "velocity_verlet", "dashpot_velocity": "half_step"},
                 "stages": {"outflow": {"below_z": -0.05, "mode": "remove", "every_steps": 20}},
                 "output": {"dump_interval_steps": 233}},
        "checks": [{"type": "slot_discharge", "outflow_probe": "out", "tray": "tray", "from_time": 1.0}],
        # The vibrated bed is chaotic: the codes part after the first collisions, so their per-slot
        # rates differ as two packings of one code do. The yardstick: silodem's rate over six
        # packings (the lattice and --packing 1..5), pooled relative scatter 0.038; two
        # realisations differ by sqrt(2) of it, so 3 sqrt(2) x 0.038 = 0.16.
        "between_codes": [{"quantity": "slot_mass_rate", "tolerance": 0.16,
                           "tolerance_source": {"type": "seed_scatter", "realisations": 6, "scatter": 0.038,
                                                "measured": "silodem's slot rates over the lattice and --packing 1..5 "
                                                            "(reports/vibrating_tray.md)"}}],
        "time_limit_s": 1800,
    },
}
if args.scale > 1:
    as_speed_run(case, args.scale, "Seed 001's vibrating tray at %d times the reduced case's length and grains (%d discs, "
                 "%d slots), for the speed runs." % (args.scale, len(balls), len(SLOTS)), "slot_mass_rate")
write_case(case, args.out)
