#!/usr/bin/env python3
"""Writes cases/janssen_frictional.json: the Janssen column predicted, not fitted (docs/theory.md
section 4.3). Frictional grains of the frictional silo (frictional_silo.py: r = 4-5 mm, mu = 0.3 or
0.5, with or without EPSD rolling resistance) sediment from a loose lattice into a cylinder of the
silo's wall balls (friction 0.3 against the grains) of D = 0.18 m = 20 mean grain diameters, and
settle under gravity to a column of about 0.72 m = 4 D. The check janssen_prediction compares the
horizontal wall pressure profile with Janssen's law evaluated with the K and mu_w that the virtual
material tests of the same grains and wall measured (cases/lateral_pressure_ratio.json,
cases/wall_friction.json: verify runs them first), its tolerance their seed scatter; the floor's
vertical stress against p_h/K at the base. The janssen check fits K and mu_w to the same profile and
reports them beside it.
Run from the repository root: python3 cases/generators/janssen_frictional.py
"""
from common import write_case

from frictional_silo import EPSD, VARIANTS, WALL_FRICTION, column_fill, column_walls, materials

D, H = 0.18, 0.95          # inner diameter (20 d), wall height
LATTICE_TOP = 0.88         # the loose lattice (49 % solid) settles to about 0.72 m (60 %)

case = {
    "format": "silodem-case/1",
    "name": "janssen_frictional",
    "description": "The Janssen column predicted: frictional grains (mu 0.3/0.5, with and without rolling resistance) "
                   "settled in a cylinder of D = 0.18 m = 20 d of the silo's wall balls (friction 0.3) to about 4 D; "
                   "the wall pressure profile against Janssen with the K and mu_w of the virtual material tests",
    "seed": 2002,
    "gravity": [0.0, 0.0, -9.81],
    "contact": {"tangential": "linear_history"},
    "materials": materials(0.5),
    "material_pairs": [{"materials": ["grain", "wall"], "friction": WALL_FRICTION}],
    "walls": column_walls(D, H),
    "balls": column_fill(D, LATTICE_TOP),
    "integrator": {"scheme": "velocity_verlet"},
    "time": {"dt_per_contact_time": 0.04, "duration": 2.0},
    "output": {"series_interval": 0.01, "probes": [
        {"type": "wall_pressure", "name": "mantle", "wall": "mantle", "angle_bins": 8, "height_bins": 38},
        {"type": "wall_pressure", "name": "floor", "wall": "bottom", "angle_bins": 8, "height_bins": 4}]},
    "verify": {
        "variants": {k: VARIANTS[k] for k in ("mu", "rolling")},
        "checks": [
            {"type": "janssen_prediction", "wall_probe": "mantle", "floor_probe": "floor",
             "lateral_pressure_ratio_from": "lateral_pressure_ratio", "wall_friction_from": "wall_friction",
             "coverage": 2.0, "exclude_bottom_diameters": 0.5},
            {"type": "janssen", "wall_probe": "mantle", "ball_diameter": 0.009, "exclude_bottom_diameters": 0.5,
             "weight_tolerance": "stop_test"},
            {"type": "pressure_profile", "wall_probe": "mantle", "value": "final"},
        ],
    },
}
write_case(case, "cases/janssen_frictional.json")
