#!/usr/bin/env python3
"""Writes cases/lateral_pressure_ratio.json: the virtual K test of EN 1991-4 Annex C on the silo's
own grains (r = 4-5 mm, k = 1e5 N/m, e = 0.3) and wall balls, the wall made frictionless
(material_pairs: grain-wall mu = 0). Frictional grains sediment from a loose lattice into a cylinder
(D = 0.18 m = 20 d, the frictional Janssen column's: a cell of 9 d gave K 12 % higher than the column
shows, measured) and settle under their own weight to about 0.29 m, which loads them by confined
uniaxial compression to the silo's stress levels (sigma_v up to about 3.5 kPa in the bands used, the
column's range); the check lateral_pressure_ratio gives K = sigma_h/sigma_v per height band
of the mantle from the slice equilibrium (the weight above, less what the wall's roughness carries),
and the spread check its mean and scatter over three packings (seeds: other wall roughness, hence
another packing). Variants: mu = 0.3, 0.5; rolling resistance none or EPSD (mu_r = 0.05, eta_r =
0.3); seed 2002, 2003, 2004 (docs/theory.md section 4.1).
Run from the repository root: python3 cases/generators/lateral_pressure_ratio.py
"""
from common import write_case

from frictional_silo import VARIANTS, column_case

D, H = 0.18, 0.40           # inner diameter (the Janssen column's, 20 d), wall height
LATTICE_TOP = 0.36          # settles to about 0.29 m

case = column_case("lateral_pressure_ratio",
                   "Virtual K test (EN 1991-4 Annex C): frictional grains settled under their own weight in a "
                   "cylinder of frictionless wall balls (D = 0.18 m = 20 d); K = sigma_h/sigma_v per band from the slice "
                   "equilibrium, over three packings, mu = 0.3 and 0.5, with and without rolling resistance",
                   D, H, LATTICE_TOP, 0.0)
case.update({
    # At rest by the stop tests, or at the latest at 1.5 s.
    "time": {"dt_per_contact_time": 0.04, "duration": 1.5},
    "equilibrium": {"check_interval_steps": 200, "p_ft": 0.01, "min_time": 0.6},
    "output": {"series_interval": 0.01, "probes": [
        {"type": "wall_pressure", "name": "mantle", "wall": "mantle", "angle_bins": 8, "height_bins": 16}]},
    "verify": {
        "variants": VARIANTS,
        "checks": [
            # A quarter diameter (5 d) at each end: the floor's and the surface's layers.
            {"type": "lateral_pressure_ratio", "wall_probe": "mantle", "exclude_bottom_diameters": 0.25,
             "exclude_top_diameters": 0.25},
            {"type": "spread", "axis": "seed", "quantities": ["lateral_pressure_ratio_K", "wall_carried_fraction"]},
        ],
    },
})
write_case(case, "cases/lateral_pressure_ratio.json")
