#!/usr/bin/env python3
"""Writes cases/wall_friction.json: the virtual wall friction test of EN 1991-4 Annex C on the silo's
own grains and wall balls (frictional_silo.py). The grains sediment into the cylinder of the K test
(D = 8 cm) whose wall material has friction 0.3 against them, and settle under their own weight for
1 s; then the mantle slides up past the column at 1 cm/s for 1 s (a move_wall event), while the
bottom disk stays: the grains, held by their weight and the bottom, are confined and sheared across
the wall balls under the lateral pressure of the column (0.3-1 kPa), the wall friction fully
mobilised upwards on the grains, as in a filled silo. The check wall_friction gives the steady
mu_w = sum tau / sum p over the column's bands (time means over the last 0.7 s, after 3 mm of slip),
and the spread check its scatter over three packings. Slow enough to be quasi-static: the shear rate of
a wall layer of 5 d, 0.01/0.045 = 0.2 /s, gives an inertial number I = gamma' d / sqrt(p / rho) of
0.002-0.005 (docs/theory.md section 4.2).
Run from the repository root: python3 cases/generators/wall_friction.py
"""
from common import write_case

from frictional_silo import VARIANTS, WALL_FRICTION, column_case

D, H = 0.08, 0.45            # inner diameter, top of the wall
BELOW = 0.02                 # the mantle reaches this far under the bottom (it rises by 0.01 m)
V_WALL, T_START, T_END = 0.01, 1.0, 2.0

case = column_case("wall_friction",
                   "Virtual wall friction test (EN 1991-4 Annex C): frictional grains settled in a cylinder (D = 8 cm) of "
                   "the silo's wall balls (friction 0.3), then the mantle slides up past them at 1 cm/s; mu_w = "
                   "tau/sigma of the steady sliding over the column's bands, over three packings, mu = 0.3 and 0.5, "
                   "with and without rolling resistance",
                   D, H, H - 0.02, WALL_FRICTION, below=BELOW)
case.update({
    "time": {"dt_per_contact_time": 0.04, "duration": T_END},
    "stages": {"events": [{"time": T_START, "type": "move_wall", "wall": "mantle", "velocity": [0.0, 0.0, V_WALL]}]},
    "output": {"series_interval": 0.01, "probes": [
        {"type": "wall_pressure", "name": "mantle", "wall": "mantle", "angle_bins": 8, "height_bins": 19,
         "from_time": T_START + 0.3, "history_interval": 0.01}]},
    "verify": {
        "variants": VARIANTS,
        "checks": [
            {"type": "wall_friction", "wall_probe": "mantle", "exclude_bottom_diameters": 0.5,
             "exclude_top_diameters": 0.5},
            {"type": "spread", "axis": "seed", "quantities": ["wall_friction_mu_w"]},
        ],
    },
})
write_case(case, "cases/wall_friction.json")
