#!/usr/bin/env python3
"""Writes cases/direct_shear.json: the virtual direct shear test of EN 1991-4 Annex C (C.9, the
angle of internal friction phi_i) on the silo's own grains (frictional_silo.py). Frictional grains
sediment from a loose lattice into a shear box of two rings of frictionless wall balls (D = 0.18 m =
20 d, the K test's cell): a lower ring on a floor, with a flange over the ring's edge that keeps the
sheared-out grains in, and an upper ring a few millimetres above it. Settled, the upper ring moves
sideways at 2 cm/s for 2 cm (2 d; inertial number about 0.005, quasi-static); the section_force probe
gives the force across the plane between the rings — the traction the material carries, whatever
the rings do — and the check direct_shear the peak and critical-state friction angles tau/sigma
along the shear, under the weight above the plane (sigma about 1.4 kPa, the silo's stress levels).
Variants: mu = 0.3, 0.5; rolling resistance none or EPSD; seeds 2002-2004 (docs/theory.md 4.4).
Run from the repository root: python3 cases/generators/direct_shear.py
"""
from common import write_case

from frictional_silo import R_WALL, SPACING, VARIANTS, column_fill, materials

D = 0.18                    # inner diameter of both rings (the K test's cell, 20 d)
LOWER = 0.06                # lower ring height; its top row sits at or below z = LOWER
GAP = 0.012                 # upper ring's base above LOWER: 2-4 mm between the rows, under the smallest grain
UPPER_TOP = 0.27
LATTICE_TOP = 0.24          # settles to about 0.16 m
SHEAR_START, SPEED, TRAVEL = 0.6, 0.02, 0.02
PLANE = LOWER + GAP / 2     # between the rings


def ring(name, z_base, height):
    return {"name": name, "type": "cylinder", "material": "wall", "radius": list(R_WALL), "spacing": SPACING,
            "centre": [0.0, 0.0, z_base], "diameter": D, "height": height}


case = {
    "format": "silodem-case/1",
    "name": "direct_shear",
    "description": "Virtual direct shear test (EN 1991-4 Annex C): frictional grains settled in a shear box of two "
                   "frictionless rings (D = 0.18 m = 20 d); the upper ring moves 2 cm sideways at 2 cm/s; peak and "
                   "critical-state angles of internal friction from the force across the plane between the rings, over "
                   "three packings, mu = 0.3 and 0.5, with and without rolling resistance",
    "seed": 2002,
    "gravity": [0.0, 0.0, -9.81],
    "contact": {"tangential": "linear_history"},
    "materials": materials(0.5),
    "material_pairs": [{"materials": ["grain", "wall"], "friction": 0.0}],
    "walls": [
        ring("lower", 0.0, LOWER),
        {"name": "floor", "type": "disk", "material": "wall", "radius": list(R_WALL), "spacing": SPACING,
         "centre": [0.0, 0.0, 0.0], "diameter": D + 2 * SPACING},
        # Beyond the lower ring, under the upper ring's outward travel (and a margin).
        {"name": "flange", "type": "disk", "material": "wall", "radius": list(R_WALL), "spacing": SPACING,
         "centre": [0.0, 0.0, LOWER], "diameter": D + 2 * (TRAVEL + 0.02), "hole_diameter": D + 2 * SPACING},
        ring("upper", LOWER + GAP, UPPER_TOP - LOWER - GAP),
    ],
    "balls": column_fill(D, LATTICE_TOP),
    "integrator": {"scheme": "velocity_verlet"},
    "time": {"dt_per_contact_time": 0.04, "duration": SHEAR_START + TRAVEL / SPEED},
    "stages": {"events": [{"time": SHEAR_START, "type": "move_wall", "wall": "upper", "velocity": [SPEED, 0.0, 0.0]}]},
    "output": {"series_interval": 0.01, "probes": [
        {"type": "section_force", "name": "shear_plane", "z": PLANE, "interval": 0.002}]},
    "verify": {
        "variants": VARIANTS,
        "checks": [
            # Peak: the largest running mean over 2 mm of travel; critical state: the mean over the last half.
            {"type": "direct_shear", "section_probe": "shear_plane", "moving_wall": "upper", "smoothing": 0.002,
             "critical_from": 0.5},
            {"type": "spread", "axis": "seed", "quantities": ["internal_friction_peak_deg",
                                                                "internal_friction_critical_deg"]},
        ],
    },
}
write_case(case, "cases/direct_shear.json")
