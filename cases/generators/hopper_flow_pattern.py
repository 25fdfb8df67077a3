#!/usr/bin/env python3
"""Writes cases/hopper_flow_pattern.json: mass flow or funnel flow (docs/theory.md section 6.1).
The frictional silo's grains (frictional_silo.py: r = 4-5 mm, mu = 0.3 or 0.5) sediment from a loose
lattice into a cylinder of the silo's wall balls (D = 0.18 m = 20 d, wall friction 0.3) on a conical
hopper of half-angle 35 or 65 deg with an outlet of 7 d closed by a gate; the gate is taken away at
T_OPEN and the leavers are dropped again at the top. A velocity_field probe averages the grains'
velocity on rings of one grain diameter during the steady flow; the check flow_pattern compares the
observed pattern (the mass flow index just above the transition) with Jenike's boundary evaluated
with the critical-state angle of internal friction and the wall friction that the virtual material
tests of the same grains and wall measured (about 54-56 deg: 35 deg is mass flow, 65 deg funnel flow).
Run from the repository root: python3 cases/generators/hopper_flow_pattern.py
"""
import math

from common import write_case

from frictional_silo import R_BALL, R_WALL, SPACING, VARIANTS, WALL_FRICTION, column_fill, materials

D, H = 0.18, 0.40            # cylinder (20 d) and its height above the transition
D_GRAIN = R_BALL[0] + R_BALL[1]
D0 = 7 * D_GRAIN             # outlet
LATTICE_TOP = 0.33           # settles to about 0.16 m above the transition
T_OPEN, T_FIELD, T_END = 0.5, 0.65, 1.0
BETAS = (35, 65)
# The velocity section: rings of one grain diameter, bands of 8 mm with one edge at the transition.
FIELD = {"type": "velocity_field", "name": "flow", "centre": [0.0, 0.0, 0.0], "radius": D / 2, "z": [-0.088, 0.2],
         "radial_bins": 10, "height_bins": 36, "interval": 0.002, "from_time": T_FIELD}
# The index is taken one grain diameter above the transition (the band 8-16 mm), in the cylinder,
# where the wall layer and the axis cross the same section. The band at the transition itself holds
# the corner where the mantle's lowest ring meets the cone's top ring; inside the hopper the axis
# speeds up into the converging flow, and the ratio falls to 0.22-0.27 along a mass-flow hopper's
# wall (reports/frictional_silo.md, the measured sections).
LEVEL = 0.012
PUBLISHED_MFI = {"type": "published", "citation":
                 "Johanson (1964), J. Appl. Mech. 31, 499, as DEM hopper studies apply it (Ketterhagen, Curtis, "
                 "Wassgren & Hancock 2009, Powder Technol. 195, 1): mass flow when v_wall / v_axis >= 0.3 "
                 "(as recalled: docs/theory.md section 6.1)"}
PUBLISHED_BOUNDARY = {"type": "published", "citation":
                      "Jenike (1964), Bulletin 123, Utah Eng. Exp. Station: the mass-flow boundary of conical hoppers, "
                      "in the fit of Arnold & McLean (1976), Powder Technol. 13, 255 (as recalled: docs/theory.md "
                      "section 6.1)"}


def walls(beta_deg):
    h = (D - D0) / 2 / math.tan(math.radians(beta_deg))
    z_gate = -h - R_WALL[1]
    return [
        {"name": "mantle", "type": "cylinder", "material": "wall", "radius": list(R_WALL), "spacing": SPACING,
         "centre": [0.0, 0.0, 0.0], "diameter": D, "height": H},
        {"name": "hopper", "type": "cone", "material": "wall", "radius": list(R_WALL), "spacing": SPACING,
         "centre": [0.0, 0.0, 0.0], "diameter": D, "height": h, "hole_diameter": D0},
        {"name": "gate", "type": "disk", "material": "wall", "radius": list(R_WALL), "spacing": SPACING,
         "centre": [0.0, 0.0, z_gate], "diameter": D0 + 2 * SPACING},
    ], z_gate


def beta_patch(beta_deg):
    w, z_gate = walls(beta_deg)
    return {"walls": w, "stages": {"outflow": {"below_z": z_gate - 0.03, "mode": "recycle"},
                                   "events": [{"time": T_OPEN, "type": "open_outlet", "wall": "gate"}]}}


inlet = D / 2 / math.sqrt(2) - 0.01
case = {
    "format": "silodem-case/1",
    "name": "hopper_flow_pattern",
    "description": "Mass flow or funnel flow: frictional grains (mu 0.3 or 0.5) discharging from a cylinder of D = 0.18 m "
                   "= 20 d on a conical hopper of half-angle 35 or 65 deg (outlet 7 d, leavers recycled); the velocity "
                   "section's mass flow index against Jenike's boundary from the virtual material tests",
    "seed": 2002,
    "gravity": [0.0, 0.0, -9.81],
    "contact": {"tangential": "linear_history"},
    "materials": materials(0.5),
    "material_pairs": [{"materials": ["grain", "wall"], "friction": WALL_FRICTION}],
    "walls": walls(BETAS[0])[0],
    "balls": column_fill(D, LATTICE_TOP),
    "drops": {"material": "grain", "radius": list(R_BALL), "z0": H, "count": 0,
              "inlet": {"x": [-inlet, inlet], "y": [-inlet, inlet]}, "initial_velocity": "free_fall", "interval_steps": 1},
    "stages": beta_patch(BETAS[0])["stages"],
    "integrator": {"scheme": "velocity_verlet"},
    "time": {"dt_per_contact_time": 0.04, "duration": T_END},
    "output": {"series_interval": 0.005, "probes": [
        FIELD,
        # Filled (the last 50 ms behind the gate) and discharging: the switch at the transition.
        {"type": "wall_pressure", "name": "mantle_filled", "wall": "mantle", "angle_bins": 8, "height_bins": 20,
         "from_time": T_OPEN - 0.05, "to_time": T_OPEN},
        {"type": "wall_pressure", "name": "mantle", "wall": "mantle", "angle_bins": 8, "height_bins": 20,
         "from_time": T_FIELD},
        {"type": "wall_pressure", "name": "hopper_filled", "wall": "hopper", "angle_bins": 8, "height_bins": 4,
         "from_time": T_OPEN - 0.05, "to_time": T_OPEN},
        {"type": "wall_pressure", "name": "hopper", "wall": "hopper", "angle_bins": 8, "height_bins": 4,
         "from_time": T_FIELD},
        {"type": "outflow", "name": "outflow"}]},
    "verify": {
        "variants": {"mu": VARIANTS["mu"], "rolling": {"none": {}},
                     "beta": {str(b): beta_patch(b) for b in BETAS}},
        "checks": [
            {"type": "flow_pattern", "velocity_probe": "flow", "hopper_wall": "hopper", "z": LEVEL,
             "wall_friction_from": "wall_friction", "internal_friction_from": "direct_shear",
             "mass_flow_index": 0.3, "mass_flow_index_source": PUBLISHED_MFI, "boundary_source": PUBLISHED_BOUNDARY,
             "margin_deg": 5.0},
            # Discharge against filling pressures, band by band (EN 1991-4's C_h on the mantle; on the
            # hopper the largest ratio is the switch at the transition): reported.
            {"type": "discharge_factor", "filled_probe": "mantle_filled", "discharge_probe": "mantle", "C_h": 1.15,
             "tolerance": 0.5},
            {"type": "discharge_factor", "filled_probe": "hopper_filled", "discharge_probe": "hopper", "C_h": 1.15,
             "tolerance": 0.5},
            {"type": "energy_balance", "tolerance": 0.05},
        ]},
}
write_case(case, "cases/hopper_flow_pattern.json")
