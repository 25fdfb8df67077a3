#!/usr/bin/env python3
"""Silo cases (docs/model.md sections 3, 4, 7; the paper's Algorithm 5): a cylinder on a conical hopper,
the outlet closed by a gate of wall balls.
  cases/silo_discharge.json  sedimented fill, the gate is taken away at t_open (release "remove":
                             the paper's gate balls "become mobile", but wall balls overlap by design
                             and would fly apart), leavers are recycled as analytic drops at the top; the
                             steady mass flow is held against Beverloo (docs/theory.md section 6).
  cases/silo_fill.json       the fill by analytic free-fall drops (Algorithm 5) with the free-fall
                             velocity at their first contact (16), one every FILL_INTERVAL steps, until
                             full (drops.full_level), then settled by the stop tests; wall pressure map
                             of the filled silo (Fig. 7). Measured at CI size: every 120 steps 97.9 %
                             of the attempts are placed, every 60 steps 93.4 % (the rest land where a
                             ball still falls). Drops started at rest (the paper's option) stand on
                             drops started at rest in towers far above the bed: the fill then needs
                             twice the time, and 5 % of the attempts fail.
Run from the repository root: python3 cases/generators/silo.py [scale [fill_interval_steps]]
(scale 1 = CI size; scale multiplies the fill's drop count), or
python3 cases/generators/silo.py paper OUTDIR  (the paper's size, about 22,000 balls; tools/paper_size.sh)
"""
import copy
import math
import random
import sys

from common import energy_between, with_scatter, without_scatter_sources, write_case

# The energy a discharge dissipates is summed over millions of collisions in a chaotic flow: between
# codes it is compared relative to itself (5 %), not to the state scale |dE_grav| as the state
# functions are. Measured: the seed scatter at CI size is 2.3 % of it (0.020 of 0.888); at paper size
# (closure, every code removing leavers every 200 steps) LAMMPS and LIGGGHTS differ by 2.0 % of it
# among themselves, while the lost energy is 2.8 x the state scale, so 0.05 of the scale would ask
# 1.8 % of it: tighter than the codes agree with each other.
# Each case's measured seed scatter of the terms (common.py with_scatter); the closure has no seeds.
DISCHARGE_ENERGY_BETWEEN = energy_between({"energy_kinetic": 0.0217, "energy_elastic": 1.05e-4, "energy_lost": 0.0250},
                                          relative_lost=True)
FILL_ENERGY_BETWEEN = energy_between({"energy_kinetic": 3.92e-4, "energy_elastic": 1.91e-5, "energy_lost": 0.00435},
                                     relative_lost=True)
CLOSURE_ENERGY_BETWEEN = energy_between({}, relative_lost=True)
from sediment import lattice_fill

# "paper OUTDIR": the paper's size (about 22,000 mobile balls, docs/model.md section 8) — the silo scaled
# 2.2x in diameter and 2.8x in height, the same grains — written to OUTDIR (not part of the suite).
PAPER = len(sys.argv) > 2 and sys.argv[1] == "paper"
# YADE runs about 7x the CI-size time per step at the paper size: a paper compare takes up to an hour.
PAPER_TIME_LIMIT_S = 7200
OUT = sys.argv[2] if PAPER else "cases"
SCALE = 1.0 if PAPER else float(sys.argv[1]) if len(sys.argv) > 1 else 1.0  # scales the fill's drop count

R_BALL = (0.0025, 0.003)       # grains, d about 5.5 mm
R_WALL = (0.0025, 0.003)
SPACING = 0.0035               # wall-ball spacing: overlapping (< 2 r_min), tight for 2.5 mm grains
D = 0.154 if PAPER else 0.07   # cylinder inner diameter
H = 0.34 if PAPER else 0.12    # cylinder height
D0 = 0.036                     # outlet diameter (6.5 d)
BETA = math.radians(30)        # hopper half-angle from vertical
H_HOPPER = (D - D0) / 2 / math.tan(BETA)
Z_GATE = -H_HOPPER - 0.002     # gate surface just below the outlet rim

inner = D / 2 - R_BALL[1] - R_WALL[1]
half = inner / math.sqrt(2) - 0.001


def base(name, description, duration, fill_count):
    return {
        "format": "silodem-case/1",
        "name": name,
        "description": description,
        "seed": 2002,
        "gravity": [0.0, 0.0, -9.81],
        "materials": {
            "grain": {"density": 2500.0, "stiffness": 4.0e5, "restitution": 0.3, "reference_radius": 0.00275},
            "wall": {"density": 7800.0, "stiffness": 4.0e5, "damping": 4.0},
        },
        "walls": [
            {"name": "mantle", "type": "cylinder", "material": "wall", "radius": list(R_WALL), "spacing": SPACING,
             "centre": [0.0, 0.0, 0.0], "diameter": D, "height": H},
            {"name": "hopper", "type": "cone", "material": "wall", "radius": list(R_WALL), "spacing": SPACING,
             "centre": [0.0, 0.0, 0.0], "diameter": D, "height": H_HOPPER, "hole_diameter": D0},
            {"name": "gate", "type": "disk", "material": "wall", "radius": list(R_WALL), "spacing": SPACING,
             "centre": [0.0, 0.0, Z_GATE], "diameter": D0 + 2 * SPACING},
        ],
        "drops": {"material": "grain", "radius": list(R_BALL), "z0": H - 0.01, "count": fill_count,
                  "inlet": {"x": [-half, half], "y": [-half, half]}, "initial_velocity": "free_fall",
                  "interval_steps": 40},
        "integrator": {"scheme": "velocity_verlet"},
        "time": {"dt_per_contact_time": 0.04, "duration": duration},
        "output": {"series_interval": 0.005, "probes": [
            {"type": "wall_pressure", "name": "mantle", "wall": "mantle", "angle_bins": 12, "height_bins": 12},
            {"type": "wall_pressure", "name": "hopper", "wall": "hopper", "angle_bins": 12, "height_bins": 4},
            {"type": "drops", "name": "drops"},
        ]},
    }


# The fill (Algorithm 5): analytic drops at random points of the inlet square, each placed at its
# first contact (Algorithm 2) with the free-fall velocity (16), one every FILL_INTERVAL steps, until
# the fill height reaches drops.full_level; then settled by the stop tests (27)-(29).
# The cross-section is 4.8x larger at paper size: drops may come 4.8x as often for the same rise rate.
# At paper size the fill ends at 0.13 m in the cylinder: about 22,000 balls, the paper's count.
FILL_INTERVAL = 25 if PAPER else int(sys.argv[2]) if len(sys.argv) > 2 else 120
fill = base("silo_fill", "Silo fill (Algorithm 5): cylinder on a hopper, outlet closed by the gate, analytic "
            "free-fall drops until the silo is full (the fill height, the median column top, at drops.full_level, one ball below "
            "the mantle's top), then settled to rest by the stop tests (27)-(29).",
            12.0 if PAPER else 6.0, 40000 if PAPER else int(6000 * SCALE))
fill["materials"]["grain"]["stiffness"] = 1.0e5
fill["materials"]["wall"]["stiffness"] = 1.0e5
fill["drops"].update({"initial_velocity": "free_fall", "interval_steps": FILL_INTERVAL, "z0": H,
                      "full_level": 0.13 if PAPER else H - 0.006})
fill["equilibrium"] = {"check_interval_steps": 200, "p_f": 0.1, "p_ft": 0.01}
fill["output"]["probes"] = [
    {"type": "wall_pressure", "name": "mantle", "wall": "mantle", "angle_bins": 16, "height_bins": 12},
    {"type": "wall_pressure", "name": "hopper", "wall": "hopper", "angle_bins": 16, "height_bins": 4},
    {"type": "drops", "name": "drops"},
]
fill["verify"] = {"checks": [
    # At rest by the stop tests: the wall load is the weight within p_ft (silo_checks.cpp).
    {"type": "static_balance", "tolerance": "stop_test", "min_placed_fraction": 0.95},
    {"type": "pressure_profile", "wall_probe": "mantle", "value": "final"},
    {"type": "pressure_profile", "wall_probe": "hopper", "value": "final"},
    {"type": "energy_balance", "tolerance": 0.05},
]}
# Comparison (a) of the fill: every code replays one drop sequence. Analytic first contact depends
# on the packing each code has made so far, so here the drops are released at rest at their points
# (drops.placement "release": attempt k at step k x interval, at the explicit points below, radius
# from the seed) and every code's integrator lets them fall; a smaller fill (the hopper and about
# 2 cm of the cylinder) keeps YADE within minutes. The seed scatter of silodem's own fills (other
# wall roughness and radii) is the yardstick for the differences between codes.
XDUMP = 250  # steps between frames (about 1 ms): the reference codes' probes see frames only


def cross_code_probes(from_time, history, outflow=True):
    extra = {"history_interval": 0.001} if history else {}
    return [dict({"type": "wall_pressure", "name": "mantle", "wall": "mantle", "angle_bins": 12, "height_bins": 12,
                  "from_time": from_time}, **extra),
            dict({"type": "wall_pressure", "name": "hopper", "wall": "hopper", "angle_bins": 12, "height_bins": 4,
                  "from_time": from_time}, **extra),
            {"type": "outflow", "name": "outflow"}][:3 if outflow else 2]


# Release points: a grid of 7 x 7 points 6.3 mm apart (wider than the largest grain) over the inlet,
# in one shuffled order repeated, so a point is used again only after the 48 others, 1,960 steps
# (7.4 ms at the compared step of 3.8 us) later; released at 1 m/s, its last ball has fallen 7.7 mm
# by then (every 30 steps it would be 5.7 mm, less than the largest grain: silodem refused 91 of the
# 800 drops and LAMMPS, which creates a ball wherever it is told, blew up). Random points would put a new
# ball on one still near the release height (its start overlaps: the drop is refused).
RELEASE_SPEED = 1.0
_grid = [[round(-0.0189 + 0.0063 * i, 6), round(-0.0189 + 0.0063 * j, 6)] for i in range(7) for j in range(7)]
random.Random(2002).shuffle(_grid)
RELEASE_POINTS = [_grid[k % len(_grid)] for k in range(800)]
fill["compare"] = {
    "base": {"drops": {"placement": "release", "release_speed": RELEASE_SPEED, "count": len(RELEASE_POINTS),
                       "positions": RELEASE_POINTS, "inlet": None, "interval_steps": 40, "z0": 0.06,
                       "full_level": None, "initial_velocity": None},
             "equilibrium": None,
             "integrator": {"scheme": "velocity_verlet", "dashpot_velocity": "half_step"},
             "contact": {"clamp_tensile_force": True},
             "time": {"duration": 0.5},
             "output": {"dump_interval_steps": XDUMP, "probes": cross_code_probes(0.3, False, outflow=False)}},
    # Every drop has landed by 0.2 s. The frictionless bed then rings on its walls: the total wall
    # load swings +-5 % about the weight to the end (measured in every code), so the wall load is
    # checked at the last frame with 10 %, and the pressures are compared as means over 0.3-0.5 s.
    "checks": [
        {"type": "static_balance", "tolerance": 0.1},
        {"type": "pressure_profile", "wall_probe": "mantle"},
        {"type": "pressure_profile", "wall_probe": "hopper"},
        {"type": "energy_terms"},
    ],
    "seeds": [2003, 2004],
    "between_codes": [
        with_scatter({"quantity": "wall_load/weight", "tolerance": 0.1}, 0.0201),
        with_scatter({"quantity": "band_pressure", "tolerance": 0.3, "relative_to": "largest"}, 0.0644),
    ] + FILL_ENERGY_BETWEEN,
    "time_limit_s": 900,
}
if PAPER:  # hours per code at 22,000 balls; the paper-size fill is silodem's (verify)
    del fill["compare"]
write_case(fill, OUT + "/silo_fill.json")

# Discharge: a sedimented fill (loose lattice in the cylinder that collapses into the hopper),
# the outlet opened at T_OPEN, leavers recycled at the top.
T_OPEN, T_END = (0.5, 1.0) if PAPER else (0.35, 0.85)  # the paper-size sediment is taller: settles later
reach = D / 2 - R_BALL[1] - R_WALL[1] + 0.0005
balls = lattice_fill(2002, reach, R_BALL, 0.0065, 0.0042, 0.004, 0.25 if PAPER else H - 0.012, 1e-4)
discharge = base("silo_discharge", "Discharge (docs/model.md section 7): sedimented fill, the gate taken away at "
                 "t = %.2f s, leavers recycled as analytic drops at the top; steady mass flow against "
                 "Beverloo across three outlets." % T_OPEN, T_END, 0)
discharge["materials"]["grain"]["stiffness"] = 1.0e5
discharge["materials"]["wall"]["stiffness"] = 1.0e5
discharge["balls"] = balls
discharge["drops"]["z0"] = H
discharge["drops"]["interval_steps"] = 1
discharge["stages"] = {"outflow": {"below_z": Z_GATE - 0.03, "mode": "recycle"},
                       "events": [{"time": T_OPEN, "type": "open_outlet", "wall": "gate"}]}
discharge["output"]["probes"] = [
    # The filled state just before the gate opens (the sediment is at rest by then), for the discharge factor.
    {"type": "wall_pressure", "name": "mantle_filled", "wall": "mantle", "angle_bins": 12, "height_bins": 12,
     "from_time": T_OPEN - 0.05, "to_time": T_OPEN},
    {"type": "wall_pressure", "name": "mantle", "wall": "mantle", "angle_bins": 12, "height_bins": 12,
     "from_time": T_OPEN + 0.15},
    {"type": "wall_pressure", "name": "hopper", "wall": "hopper", "angle_bins": 12, "height_bins": 4,
     "from_time": T_OPEN + 0.15},
    {"type": "outflow", "name": "outflow"},
]
mean_d = R_BALL[0] + R_BALL[1]


def outlet_patch(d0):
    """Walls and outflow height for outlet diameter d0 at the same hopper half-angle."""
    h_h = (D - d0) / 2 / math.tan(BETA)
    z_gate = -h_h - 0.002
    walls = [dict(w) for w in discharge["walls"]]
    walls[1].update({"height": h_h, "hole_diameter": d0})
    walls[2].update({"centre": [0.0, 0.0, z_gate], "diameter": d0 + 2 * SPACING})
    return {"walls": walls, "stages": {"outflow": {"below_z": z_gate - 0.03, "mode": "recycle"},
                                       "events": [{"time": T_OPEN, "type": "open_outlet", "wall": "gate"}]}}


discharge["verify"] = {
    # Three outlets, 5.5 to 7.6 grain diameters (docs/theory.md section 6: Beverloo fails below ~5-6 d).
    "variants": {"outlet": {"D0_%d_mm" % round(d0 * 1000): outlet_patch(d0) for d0 in (0.030, 0.036, 0.042)}},
    "checks": [
        # Per outlet: steady flow, and its ratio to Beverloo with the frictional constants
        # C = 0.58, k = 1.5 (loose: frictionless grains are expected to flow faster); bulk density
        # from a packing fraction of 0.6.
        {"type": "beverloo", "outflow_probe": "outflow", "from_time": T_OPEN + 0.15, "bulk_density": 0.6 * 2500.0,
         "outlet_wall": "hopper", "grain_diameter": mean_d, "tolerance": 1.5, "max_scatter": 0.2},
        # Across outlets: the 5/2 law and the fitted C and k.
        {"type": "beverloo_fit", "axis": "outlet", "outlet_wall": "hopper", "bulk_density": 0.6 * 2500.0,
         # k: docs/theory.md gives 1.3-2.9 for frictional spheres and only infers 1-1.5 for frictionless
         # ones ("calibrate"); these frictionless grains measured k = 0.78, so the range is wide.
         "grain_diameter": mean_d, "k_min": -0.5, "k_max": 3.0, "min_r2": 0.95},
        # Wall pressure in discharge against after filling: EN 1991-4 C_h = 1.15 (docs/theory.md, EN section 5.2.2).
        # Recycling keeps the fill height, so the factor is the flow's own; judged within 50 %.
        {"type": "discharge_factor", "filled_probe": "mantle_filled", "discharge_probe": "mantle", "C_h": 1.15,
         "tolerance": 0.5},
        {"type": "energy_balance", "tolerance": 0.05},
    ]}
# Across codes (silo issue, approach (b)): every code starts from the state silodem reaches at T_OPEN
# (the sedimented fill, gate still closed), then the gate is taken away and leavers are removed
# (recycling as analytic drops has no equivalent in the reference codes). 36 mm outlet only.
X_END, X_FROM = T_OPEN + 0.17, T_OPEN + 0.07
LEAVER_EVERY = 200
discharge["compare"] = {
    # YADE's law clamps the tensile force always: every code clamps here (LAMMPS limit_damping).
    "base": {"integrator": {"scheme": "velocity_verlet", "dashpot_velocity": "half_step"},
             "contact": {"clamp_tensile_force": True},
             # Leavers are deleted every LEAVER_EVERY steps in every code alike (what the reference
             # codes can do cheaply); deleting them at once in silodem alone lost 2-5 % less energy
             # at paper size, where the dense stream below the outlet keeps colliding.
             "stages": {"outflow": {"mode": "remove", "every_steps": LEAVER_EVERY}},
             "time": {"duration": X_END},
             "output": {"dump_interval_steps": XDUMP, "probes": cross_code_probes(X_FROM, False)}},
    "from_state_at": T_OPEN,
    "checks": [
        {"type": "beverloo", "outflow_probe": "outflow", "from_time": X_FROM, "bulk_density": 0.6 * 2500.0,
         "outlet_wall": "hopper", "grain_diameter": mean_d, "tolerance": 1.5, "max_scatter": 0.25},
        {"type": "pressure_profile", "wall_probe": "mantle"},
        {"type": "pressure_profile", "wall_probe": "hopper"},
        {"type": "energy_terms"},
    ],
    "seeds": [2003, 2004],
    "between_codes": [
        with_scatter({"quantity": "mass_flow_rate", "tolerance": 0.15}, 0.0210),
        with_scatter({"quantity": "band_pressure", "tolerance": 0.3, "relative_to": "largest"}, 0.0777),
    ] + DISCHARGE_ENERGY_BETWEEN,
    "time_limit_s": 900,
}
if PAPER:  # one outlet (the base case's); compare without the seed scatter (hours per realisation)
    del discharge["verify"]["variants"]
    del discharge["compare"]["seeds"]
    discharge["compare"]["between_codes"] = without_scatter_sources(discharge["compare"]["between_codes"])
    discharge["verify"]["checks"] = [c for c in discharge["verify"]["checks"] if c["type"] != "beverloo_fit"]
    discharge["compare"]["time_limit_s"] = PAPER_TIME_LIMIT_S
write_case(discharge, OUT + "/silo_discharge.json")
if PAPER:
    # The ranks piece (tools/paper_size.sh ranks): the discharge compare cut to 0.05 s after the
    # shared state, enough steps (about 13,000) to time LAMMPS on 1 and 2 ranks on the same scene.
    piece = copy.deepcopy(discharge)
    piece["name"] = "silo_discharge_ranks"
    piece["compare"]["base"]["time"]["duration"] = T_OPEN + 0.05
    for entry in piece["compare"]["base"]["output"]["probes"] + piece["compare"]["checks"]:
        if "from_time" in entry:
            entry["from_time"] = T_OPEN + 0.02
    write_case(piece, OUT + "/silo_discharge_ranks.json")

# Sudden closure during steady discharge (outlet 36 mm): the balls in the outlet plane are stopped
# and fixed; the pressure history of the hopper and the mantle around the closing instant.
T_CLOSE, T_STOP = (0.8, 0.9) if PAPER else (0.65, 0.75)
closure = copy.deepcopy(discharge)
closure["name"] = "silo_closure"
closure["description"] = ("Sudden gate closure (docs/model.md section 7): steady discharge through 36 mm, at t = %.2f s "
                          "the balls in the outlet plane are stopped and become wall balls." % T_CLOSE)
closure["time"]["duration"] = T_STOP
closure["stages"]["events"].append({"time": T_CLOSE, "type": "close_outlet", "centre": [0.0, 0.0, -H_HOPPER],
                                    "diameter": D0, "thickness": 2 * R_BALL[1]})
closure["output"]["probes"] = [
    {"type": "wall_pressure", "name": "mantle", "wall": "mantle", "angle_bins": 12, "height_bins": 12,
     "from_time": T_CLOSE, "history_interval": 0.001},
    {"type": "wall_pressure", "name": "hopper", "wall": "hopper", "angle_bins": 12, "height_bins": 4,
     "from_time": T_CLOSE, "history_interval": 0.001},
    {"type": "outflow", "name": "outflow"},
]
closure["verify"] = {"checks": [
    {"type": "closure_overpressure", "wall_probe": "hopper", "close_time": T_CLOSE, "window": 0.05},
    {"type": "closure_overpressure", "wall_probe": "mantle", "close_time": T_CLOSE, "window": 0.05},
    {"type": "energy_balance", "tolerance": 0.05},
]}
# Across codes: the gate is taken away at T_OPEN, leavers are removed (not recycled), and the outlet
# closes at XT_CLOSE — earlier than in the verify run, so the silo is still mostly full without
# recycling. Every code starts from silodem's state 60 ms before the closure.
XT_CLOSE = T_OPEN + 0.15
closure["compare"] = {
    "base": {"integrator": {"scheme": "velocity_verlet", "dashpot_velocity": "half_step"},
             "contact": {"clamp_tensile_force": True},
             "stages": {"outflow": {"mode": "remove", "every_steps": LEAVER_EVERY},
                        "events": [{"time": T_OPEN, "type": "open_outlet", "wall": "gate"},
                                   dict(closure["stages"]["events"][1], time=XT_CLOSE)]},
             "time": {"duration": XT_CLOSE + 0.04},
             "output": {"dump_interval_steps": XDUMP, "probes": cross_code_probes(XT_CLOSE, True)}},
    # The shared state is taken during steady discharge, 60 ms before the closure.
    "from_state_at": XT_CLOSE - 0.06,
    "checks": [
        {"type": "closure_overpressure", "wall_probe": "hopper", "close_time": XT_CLOSE, "window": 0.035},
        {"type": "closure_overpressure", "wall_probe": "mantle", "close_time": XT_CLOSE, "window": 0.035},
        {"type": "energy_terms"},
    ],
    # No seed scatter here (CI time): the yardstick is the spread of the reference codes.
    # Tolerance from the spread of the three reference codes among themselves (mean ratio 1.50-1.77
    # in the hopper after 60 ms of chaotic divergence from the shared state). The peak is one sample
    # of a spike (4.4-5.6 in the hopper, 2.5-4.3 on the mantle): reported per code, not compared.
    # Without seeds there is no measured scatter: these rows are reported.
    "between_codes": [{"quantity": "closure_mean_post/pre_pressure", "tolerance": 0.5}] + CLOSURE_ENERGY_BETWEEN,
    "time_limit_s": 900,
}
if PAPER:
    closure["compare"]["time_limit_s"] = PAPER_TIME_LIMIT_S
write_case(closure, OUT + "/silo_closure.json")
