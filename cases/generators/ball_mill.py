#!/usr/bin/env python3
"""Writes cases/ball_mill.json: seed 003's mill (Katnov 2021; the notes' II.2 and B12), the set-up
of the thesis's code at the thesis date, in the planar mode: a 24-gon drum of circumradius 1 m
about a horizontal axis (y), 72 steel shot of r = 0.05 m and 25 ore balls of r = 0.1 m (about 43 %
of the section), Hertz contacts with the corrected damping (zeta 0.1 -> e = 0.707, notes B1),
sliding friction 0.1 without a spring (the thesis's) and a constant rolling couple 0.05 (CDT),
dt = 1e-5 s (the thesis's). The drum turns at four fractions of the critical speed sqrt(g/R) about
the thesis's 2.25 rad/s; the charge settles for 1.5 s and is averaged over the next 1.5 s.
Checks: the torque identity (judged), the drum's power (judged, exact), the Froude number, the
dynamic angle and Mellmann's regime (reported).
Run from the repository root: python3 cases/generators/ball_mill.py
  --packing S --out F: another realisation of the mill, each lattice ball moved along x by a uniform
  draw in [-2, 2] mm (seeded by S), for the seed scatter of the compared torque (reports/ball_mill.md).
  --scale N --out F: the mill with N times the charge in a drum sqrt(N) times as wide, at the same
  fractions of its critical speed (the speed runs' larger size, reports/ball_mill.md); its
  between-codes rows are reports (the seed scatter was measured at scale 1); no grinding case.
"""
import argparse
import math
import random

from common import as_speed_run, write_case

parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
parser.add_argument("--packing", type=int, help="seed of a jittered lattice (default: none, the regular one)")
parser.add_argument("--scale", type=int, default=1, help="N times the charge (default 1)")
parser.add_argument("--out", default="cases/ball_mill.json")
args = parser.parse_args()
if args.scale < 1:
    parser.error("--scale must be at least 1")

G, R_DRUM = 9.81, math.sqrt(args.scale)
R_SHOT, R_ORE = 0.05, 0.1
N_SHOT, N_ORE = 72 * args.scale, 25 * args.scale
OMEGA_C = math.sqrt(G / R_DRUM)
WALL_R, WALL_SPACING = 0.02, 0.03
SETTLE, END = 1.5, 3.0


def restitution_of_zeta(zeta):
    """Hertz damping ratio -> restitution: zeta = sqrt(5/6) |beta|, beta = ln e / sqrt(ln^2 e + pi^2) (notes B1)."""
    beta = zeta / math.sqrt(5.0 / 6.0)
    return math.exp(-math.pi * beta / math.sqrt(1.0 - beta * beta))


E_REST = restitution_of_zeta(0.1)


def material(density, e_modulus, poisson):
    return {"density": density, "youngs_modulus": e_modulus, "poisson_ratio": poisson, "restitution": E_REST,
            "friction": 0.1, "rolling_friction": 0.05}


def charge(jitter):
    """Ore on a square lattice of 0.21 m cells from the bottom up, then the shot four to a cell; each
    ball moved along x by a uniform draw in [-2, 2] mm with `jitter` (the gaps are 5 mm or more)."""
    def shift():
        return jitter.uniform(-0.002, 0.002) if jitter else 0.0

    cells = []
    cells_across = int(R_DRUM / 0.21) + 1
    for i in range(-cells_across, cells_across + 1):
        for j in range(-cells_across, cells_across + 1):
            x, z = 0.21 * i, 0.21 * j
            if math.hypot(x, z) + 0.105 * math.sqrt(2) < 0.93 * R_DRUM:
                cells.append((z, x))
    cells.sort()
    balls = []
    for k, (z, x) in enumerate(cells[:N_ORE]):
        balls.append({"id": "ore%d" % k, "material": "ore", "radius": R_ORE, "position": [round(x + shift(), 6), 0.0, round(z, 6)]})
    shot = 0
    for z, x in cells[N_ORE:]:
        for dx, dz in ((-0.0525, -0.0525), (0.0525, -0.0525), (-0.0525, 0.0525), (0.0525, 0.0525)):
            if shot < N_SHOT:
                jx = shift()
                balls.append({"id": "shot%d" % shot, "material": "shot", "radius": R_SHOT,
                              "position": [round(x + dx + jx, 6), 0.0, round(z + dz, 6)]})
                shot += 1
    assert shot == N_SHOT, "the lattice has no room for the shot"
    return balls


def drum(omega):
    return {"name": "drum", "type": "drum", "material": "wall", "radius": [WALL_R, WALL_R], "spacing": WALL_SPACING,
            "centre": [0, 0, 0], "diameter": 2 * R_DRUM, "sides": 24,
            "motion": {"rotation": {"centre": [0, 0, 0], "axis": [0, 1, 0], "angular_speed": omega}}}


SPEEDS = {"w0_30": 0.3, "w0_50": 0.5, "w0_72": 0.72, "w1_50": 1.5}  # fractions of sqrt(g/R); 0.72: the thesis's 2.25 rad/s

case = {
    "format": "silodem-case/1",
    "name": "ball_mill",
    "description": "Seed 003's ball mill (the thesis code's set-up, planar): 72 shot and 25 ore balls in a 24-gon "
                   "drum of R = 1 m turning at 0.3-1.5 of the critical speed; torque identity, power, regime.",
    "dimension": 2,
    "grain_inertia": "sphere",
    "gravity": [0, 0, -G],
    "contact": {"normal": "hertz", "tangential": "coulomb_sliding", "rolling": "constant_torque"},
    "materials": {"shot": material(7800.0, 2e11, 0.25), "ore": material(4800.0, 6e10, 0.25),
                  "wall": material(7800.0, 2e11, 0.3)},
    "balls": charge(random.Random(args.packing) if args.packing is not None else None),
    "walls": [drum(0.72 * OMEGA_C)],
    "time": {"dt": 1e-5, "duration": END},
    "output": {"series_interval": 0.01, "probes": [
        {"type": "wall_load", "name": "drum_load", "wall": "drum", "from_time": SETTLE, "interval": 0.01},
        {"type": "charge", "name": "charge", "wall": "drum", "from_time": SETTLE, "interval": 0.01}]},
    "verify": {
        "variants": {"speed": {label: {"walls": [drum(f * OMEGA_C)]} for label, f in SPEEDS.items()}},
        "checks": [
            {"type": "torque_identity", "wall_probe": "drum_load", "charge_probe": "charge"},
            {"type": "mill_regime", "charge_probe": "charge", "wall": "drum"},
            {"type": "energy_balance", "tolerance": 0.05},
        ]},
}

# The drum in every code, with the contact model they share (none has the thesis's sliding-only
# friction or its constant rolling couple, and LIGGGHTS's 2-D integrator takes discs only): Hertz
# with the Mindlin spring, no rolling law, disc inertia, every code's velocity Verlet with the
# half-step dashpot, clamped (YADE's Hertz law clamps); dumps every 0.01 s, the probes' interval.
COMPARE_MATERIALS = {name: {"rolling_friction": None} for name in case["materials"]}  # a merge patch: null removes
case["compare"] = {
    "base": {"contact": {"normal": "hertz", "tangential": "mindlin", "rolling": "none", "clamp_tensile_force": True},
             "materials": COMPARE_MATERIALS, "grain_inertia": "disc",
             "integrator": {"scheme": "velocity_verlet", "dashpot_velocity": "half_step"},
             "output": {"dump_interval_steps": 1000}},
    "checks": [{"type": "torque_identity", "wall_probe": "drum_load", "charge_probe": "charge"},
               {"type": "mill_regime", "charge_probe": "charge", "wall": "drum"}],
    # The charge is chaotic: the codes part within the first second, so their mean torques differ
    # as two packings of one code do. The yardstick: silodem's torque over ten packings (the lattice
    # and --packing 1..9), relative scatter 0.028; two realisations differ by sqrt(2) of it, so
    # 3 sqrt(2) x 0.028 = 0.12.
    "between_codes": [{"quantity": "drum_torque", "tolerance": 0.12,
                       "tolerance_source": {"type": "seed_scatter", "realisations": 10, "scatter": 0.028,
                                            "measured": "silodem's mean drum torque over the lattice and --packing 1..9 "
                                                        "(reports/ball_mill.md)"}}],
    "time_limit_s": 1800,
}
if args.scale > 1:
    as_speed_run(case, args.scale, "Seed 003's ball mill at %d times the charge (%d shot, %d ore) in a drum of R = %.3g m, "
                 "for the speed runs." % (args.scale, N_SHOT, N_ORE, R_DRUM), "drum_torque")
write_case(case, args.out)
if args.packing is not None or args.scale > 1:
    raise SystemExit(0)  # a realisation of the mill alone

# The grinding run: the same mill at the thesis's 2.25 rad/s with its breakage model (notes B7-B12:
# E_min = 25 J at the ore's size, scaled with r as the code does; S = 0.01 1/J, the final code's),
# counted once the charge has settled (the lattice's fall would break grains no mill does), then
# 15 s, the thesis's run per regime. Checks: the charge's volume is kept through every break (judged);
# the ore's size distribution every 2.5 s (reported; the grain count it gives at the end judged
# against the charge's); breaks reported.
grinding = {k: v for k, v in case.items() if k != "compare"}
grinding.update({
    "name": "ball_mill_grinding",
    "description": "Seed 003's mill grinding: the ball_mill set-up at the thesis's 2.25 rad/s with its breakage "
                   "model (E_min 25 J scaled with size, S = 0.01 1/J, 2-6 fragments; and E_min 1 J) for the thesis's 15 s "
                   "after the charge settles; volume kept, the ore's size distribution against time reported.",
    "breakage": {"materials": ["ore"], "minimum_energy": 25.0, "size_exponent": 1.0, "strength": 0.01,
                 "from_time": SETTLE},
    "time": {"dt": 1e-5, "duration": SETTLE + 15.0},
    "output": {"series_interval": 0.01, "probes": [
        {"type": "charge", "name": "charge", "wall": "drum", "from_time": SETTLE, "interval": 0.01}]},
    # The thesis's E_min breaks nothing once the charge turns (reports/ball_mill.md); 1 J grinds.
    "verify": {"variants": {"minimum_energy": {"thesis_25J": {}, "low_1J": {"breakage": {"minimum_energy": 1.0}}}},
               "checks": [
        {"type": "charge_volume", "charge_probe": "charge"},
        # Sieves between the fragment sizes: 0.09 m passes every broken ore grain (2 fragments: 0.079 m),
        # 0.065 m those of 4 or more (0.063 m), 0.05 m only a second generation.
        {"type": "size_distribution", "material": "ore", "every": 2.5, "sieves": [0.09, 0.065, 0.05],
         "charge_probe": "charge"},
        {"type": "mill_regime", "charge_probe": "charge", "wall": "drum"},
        {"type": "energy_balance", "tolerance": 0.05},
    ]},
})
# No reference code breaks grains: compare runs silodem alone (with the drum's common model, so
# that breakage is what each code is refused for) and names the reason for each code.
grinding["compare"] = {"base": case["compare"]["base"], "checks": [{"type": "charge_volume", "charge_probe": "charge"}],
                       "time_limit_s": 600}
write_case(grinding, "cases/ball_mill_grinding.json")
