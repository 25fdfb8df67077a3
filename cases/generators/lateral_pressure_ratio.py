#!/usr/bin/env python3
"""Writes cases/lateral_pressure_ratio.json: the virtual K test of EN 1991-4 Annex C on the silo's
own grains (r = 4-5 mm, k = 1e5 N/m, e = 0.3) and wall balls, the wall made frictionless
(material_pairs: grain-wall mu = 0). Frictional grains sediment from a loose lattice into a cylinder
(D = 8 cm, the Janssen column's) and settle under their own weight, which loads them by confined
uniaxial compression to the silo's stress levels (sigma_v up to about 2.5 kPa at the base, the
Janssen column's range); the check lateral_pressure_ratio gives K = sigma_h/sigma_v per height band
of the mantle from the slice equilibrium (the weight above, less what the wall's roughness carries),
and the spread check its mean and scatter over three packings (seeds: other wall roughness, hence
another packing). Variants: mu = 0.3, 0.5; rolling resistance none or EPSD (mu_r = 0.05, eta_r =
0.3); seed 2002, 2003, 2004 (docs/theory.md section 4.1).
Run from the repository root: python3 cases/generators/lateral_pressure_ratio.py
"""
from common import write_case

from frictional_silo import VARIANTS, column_fill, column_walls, materials

D, H = 0.08, 0.45           # inner diameter, wall height

case = {
    "format": "silodem-case/1",
    "name": "lateral_pressure_ratio",
    "description": "Virtual K test (EN 1991-4 Annex C): frictional grains settled under their own weight in a "
                   "cylinder of frictionless wall balls (D = 8 cm); K = sigma_h/sigma_v per band from the slice "
                   "equilibrium, over three packings, mu = 0.3 and 0.5, with and without rolling resistance",
    "seed": 2002,
    "gravity": [0.0, 0.0, -9.81],
    "contact": {"tangential": "linear_history"},
    "materials": materials(0.5),
    # The wall is frictionless for the grains (its roughness remains: the check takes out what it carries).
    "material_pairs": [{"materials": ["grain", "wall"], "friction": 0.0}],
    "walls": column_walls(D, H),
    "balls": column_fill(D, H - 0.02),
    "integrator": {"scheme": "velocity_verlet"},
    # At rest from about 1 s (potential energy constant to 1e-7, the walls carry the weight to 1e-5;
    # measured). The stop tests do not hold: grains spinning about a contact normal keep ~1e-5 J of
    # kinetic energy (point contacts resist no twist), and the global force test stays at 0.14.
    "time": {"dt_per_contact_time": 0.04, "duration": 1.5},
    "output": {"series_interval": 0.01, "probes": [
        {"type": "wall_pressure", "name": "mantle", "wall": "mantle", "angle_bins": 8, "height_bins": 18}]},
    "verify": {
        "variants": VARIANTS,
        "checks": [
            {"type": "lateral_pressure_ratio", "wall_probe": "mantle", "exclude_bottom_diameters": 0.5,
             "exclude_top_diameters": 0.5},
            {"type": "spread", "axis": "seed", "quantities": ["lateral_pressure_ratio_K", "wall_carried_fraction"]},
        ],
    },
}
write_case(case, "cases/lateral_pressure_ratio.json")
