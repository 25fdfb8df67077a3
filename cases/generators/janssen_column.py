#!/usr/bin/env python3
"""Writes cases/janssen_column.json: a tall cylinder of fixed wall balls on a flat bottom, filled
by sedimentation — balls of random radii (1) on a loose lattice that collapses under gravity (the
preparation of Landry et al. 2003) — and settled to rest by the stop tests (27)-(29). (Analytic
drops, Algorithm 2, stack into towers unless each drop waits about sqrt(2d/g) = 45 ms for the last
one to move away, which is too slow for CI; the silo-fill case uses them.) The wall-pressure probe gives the
horizontal pressure against depth; the check fits Janssen, reports K and the wall-roughness
friction mu_w, compares with EN 1991-4 and balances the wall load against the weight (docs/model.md
section 3, docs/theory.md sections 4-5). CI size: 2,891 balls.
Run from the repository root: python3 cases/generators/janssen_column.py
        python3 cases/generators/janssen_column.py paper OUTDIR   (the paper's size: about 22,000
        balls in the paper's 154 mm diameter, 1.22 m wall; tools/paper_size.sh janssen)
"""
import sys

from common import energy_between, with_scatter, without_scatter_sources, write_case

from sediment import lattice_fill

PAPER = len(sys.argv) > 2 and sys.argv[1] == "paper"
# Inner diameter, wall height (the settled fill is about 4.5 D); at paper size the paper silo's
# diameter and a wall tall enough for about 22,000 balls.
D, H = (0.154, 1.22) if PAPER else (0.08, 0.85)
R_BALL = (0.004, 0.005)     # mobile radii (1)
R_WALL = (0.004, 0.005)     # wall-ball radii (1)
SPACING = 0.006             # wall-ball centre spacing: overlapping, no hole a 4 mm ball fits through
LATTICE = 0.0105            # initial square-lattice spacing in a layer
LAYER = 0.007               # layer spacing; alternate layers shifted by half a cell keep 10.1 mm clearance

reach = D / 2 - R_BALL[1] - R_WALL[1] + 0.0005   # centres inside the wall's inner surface
balls = lattice_fill(2002, reach, R_BALL, LATTICE, LAYER, 0.01, H - 0.02, 2e-4)

case = {
    "format": "silodem-case/1",
    "name": "janssen_column",
    "description": "Column settling against Janssen: cylinder D = 8 cm, wall 10.6 D, flat bottom, filled by "
                   "sedimentation from a loose lattice and settled by the stop tests (27)-(29).",
    "seed": 2002,
    "gravity": [0.0, 0.0, -9.81],
    "materials": {
        "grain": {"density": 2500.0, "stiffness": 1.0e5, "restitution": 0.3, "reference_radius": 0.0045},
        "wall": {"density": 7800.0, "stiffness": 1.0e5, "damping": 2.0},
    },
    "walls": [
        {"name": "mantle", "type": "cylinder", "material": "wall", "radius": list(R_WALL), "spacing": SPACING,
         "centre": [0.0, 0.0, 0.0], "diameter": D, "height": H},
        {"name": "bottom", "type": "disk", "material": "wall", "radius": list(R_WALL), "spacing": SPACING,
         "centre": [0.0, 0.0, 0.0], "diameter": D + 2 * SPACING},
    ],
    "balls": balls,
    "integrator": {"scheme": "velocity_verlet"},
    "time": {"dt_per_contact_time": 0.04, "duration": 4.0},
    "equilibrium": {"check_interval_steps": 200, "p_f": 0.1, "p_ft": 0.01},
    "output": {"series_interval": 0.01, "probes": [
        {"type": "wall_pressure", "name": "mantle", "wall": "mantle", "angle_bins": 8, "height_bins": 20},
        {"type": "wall_pressure", "name": "bottom", "wall": "bottom", "angle_bins": 1, "height_bins": 4},
    ]},
    "verify": {
        "checks": [
            {"type": "janssen", "wall_probe": "mantle", "ball_diameter": 2 * R_BALL[1],
             "exclude_bottom_diameters": 0.5},
            {"type": "energy_balance", "tolerance": 0.05},
        ],
    },
    # Across codes (approach (b) of the silo issue): every code starts from the column silodem has
    # settled by the verify protocol at the compared (clamped) time step — its stop tests hold from
    # t = 1.69 s there — taken at t = 2.0 s, and carries on for 0.1 s at rest; the wall pressure
    # profile, the Janssen fit and the weight balance are compared.
    # Each code filling from the lattice itself (approach (a)) takes 2.6 s of simulated time, about
    # 25 min in YADE: not in CI.
    "compare": {
        "base": {"integrator": {"scheme": "velocity_verlet", "dashpot_velocity": "half_step"},
                 "contact": {"clamp_tensile_force": True},
                 "equilibrium": None,
                 "time": {"duration": 2.1},
                 "output": {"dump_interval_steps": 500}},
        "from_state_at": 2.0,
        "checks": [
            {"type": "janssen", "wall_probe": "mantle", "ball_diameter": 2 * R_BALL[1],
             "exclude_bottom_diameters": 0.5},
            {"type": "pressure_profile", "wall_probe": "mantle", "value": "final"},
            {"type": "static_balance", "tolerance": 0.02},
            {"type": "energy_terms"},
        ],
        # Two more realisations of the settled column (other wall roughness) in silodem: the seed
        # scatter, the yardstick for the differences between codes.
        "seeds": [2003, 2004],
        # Judged against the measured seed scatter where it supports the tolerance (common.py
        # with_scatter); the wall load (0.01, about 100 scatters) is reported. mu_w and K of the
        # frictionless column are reported in every code, and so is their comparison.
        "between_codes": [
            with_scatter({"quantity": "band_pressure", "tolerance": 0.05, "relative_to": "largest"}, 0.0674),
            with_scatter({"quantity": "wall_load/weight", "tolerance": 0.01}, 9.9e-5),
            # Absolute: mu_w from wall roughness alone ranges from 0.00007 to 0.046 between
            # realisations; near 0 the fitted Janssen curve is almost straight and a relative
            # difference is ill-conditioned (0.0036 against 0.0042 is 16 %). A difference of 0.002
            # moves the deepest band's Janssen pressure by about 2 K dmu H/D = 1.7 %, within the
            # 5 % the band pressures are compared to.
            {"quantity": "effective_wall_friction_mu_w", "tolerance": 0.002, "relative_to": "absolute"},
            {"quantity": "lateral_pressure_ratio_K", "tolerance": 0.1},
        ] + energy_between({"energy_kinetic": 0.00263, "energy_elastic": 0.0170, "energy_gravitational_change": 0.00402,
                            "energy_lost": 0.0134}),
        "time_limit_s": 900,
    },
}
if PAPER:
    # The taller column falls and settles later; one realisation only (the lead run alone is
    # about 25 min), and YADE needs up to an hour for its 0.1 s.
    case["time"]["duration"] = 4.0
    case["compare"]["from_state_at"] = 3.5
    case["compare"]["base"]["time"]["duration"] = 3.6
    del case["compare"]["seeds"]
    case["compare"]["between_codes"] = without_scatter_sources(case["compare"]["between_codes"])
    case["compare"]["time_limit_s"] = 7200
    write_case(case, sys.argv[2] + "/janssen_column.json")
else:
    write_case(case, "cases/janssen_column.json")
