#!/usr/bin/env python3
"""Writes cases/angle_of_repose.json: the angle of repose of the silo's own grains (EN 1991-4
Annex C lists it beside phi_i; the heap a silo's filling leaves on its top) by the lifted-cylinder
test. Frictional grains (frictional_silo.py) sediment from a loose lattice into a tube of D = 0.12 m
(13 d) of wall balls, frictionless against the grains, standing on a wide rough base (wall balls of
the grains' own friction 0.5, their bumps keep the heap's foot from sliding) with a low rim that
stops grains rolling away. Settled, the tube rises
at 0.1 m/s until it clears the column, the grains slump into a heap, and the stop tests end the run
at rest. The check angle_of_repose fits a line to the heap's surface profile (the highest grain top
per radial bin about the tube's axis) between a quarter and three quarters of its height
(docs/theory.md 4.5). Variants: mu = 0.3, 0.5; rolling resistance none or EPSD; seeds 2002-2004.
Run from the repository root: python3 cases/generators/angle_of_repose.py
"""
from common import write_case

import copy

from frictional_silo import EPSD, R_WALL, SPACING, VARIANTS, WALL, column_fill, materials

D = 0.12                     # the tube (13 d)
TUBE_HEIGHT = 0.27
LATTICE_TOP = 0.25           # settles to about 0.2 m
BASE = 0.6                   # base diameter: the heap's foot is about 0.3 m across
BASE_FRICTION = 0.5
T_LIFT, V_LIFT = 0.5, 0.1
T_CLEAR = T_LIFT + 0.24 / V_LIFT  # the tube's lowest row above the settled column's top
T_END = T_CLEAR + 2.0

mats = materials(0.5)
mats["base"] = dict(WALL)
variants = copy.deepcopy(VARIANTS)
variants["rolling"]["epsd"]["materials"]["base"] = EPSD

case = {
    "format": "silodem-case/1",
    "name": "angle_of_repose",
    "description": "Angle of repose by the lifted-cylinder test: frictional grains settled in a frictionless tube "
                   "(D = 0.12 m = 13 d) on a rough base; the tube rises at 0.1 m/s and the grains slump into a heap "
                   "whose surface slope is measured at rest, over three packings, mu = 0.3 and 0.5, with and without "
                   "rolling resistance",
    "seed": 2002,
    "gravity": [0.0, 0.0, -9.81],
    "contact": {"tangential": "linear_history"},
    "materials": mats,
    "material_pairs": [{"materials": ["grain", "wall"], "friction": 0.0},
                       {"materials": ["grain", "base"], "friction": BASE_FRICTION}],
    "walls": [
        {"name": "tube", "type": "cylinder", "material": "wall", "radius": list(R_WALL), "spacing": SPACING,
         "centre": [0.0, 0.0, 0.004], "diameter": D, "height": TUBE_HEIGHT},
        {"name": "base", "type": "disk", "material": "base", "radius": list(R_WALL), "spacing": SPACING,
         "centre": [0.0, 0.0, 0.0], "diameter": BASE},
        # A low rim at the base's edge stops the grains that roll away (spheres without rolling
        # resistance roll far: one left a rimless base of 0.6 m at mu = 0.3); the heap's foot ends
        # about 0.1 m inside it.
        {"name": "rim", "type": "cylinder", "material": "base", "radius": list(R_WALL), "spacing": SPACING,
         "centre": [0.0, 0.0, 0.0], "diameter": BASE, "height": 0.03},
    ],
    "balls": column_fill(D, LATTICE_TOP),
    "integrator": {"scheme": "velocity_verlet"},
    "time": {"dt_per_contact_time": 0.04, "duration": T_END},
    "stages": {"events": [
        {"time": T_LIFT, "type": "move_wall", "wall": "tube", "velocity": [0.0, 0.0, V_LIFT]},
        {"time": T_CLEAR, "type": "move_wall", "wall": "tube", "velocity": [0.0, 0.0, 0.0]}]},
    # At rest after the slump: the stop tests end the run.
    "equilibrium": {"check_interval_steps": 200, "p_ft": 0.01, "min_time": T_CLEAR + 0.3},
    "output": {"series_interval": 0.01},
    "verify": {
        "variants": variants,
        "checks": [
            {"type": "angle_of_repose", "axis_wall": "tube", "fit_from": 0.25, "fit_to": 0.75},
            {"type": "spread", "axis": "seed", "quantities": ["angle_of_repose_deg"]},
        ],
    },
}
write_case(case, "cases/angle_of_repose.json")
