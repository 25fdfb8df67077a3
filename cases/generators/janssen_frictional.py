#!/usr/bin/env python3
"""Writes cases/janssen_frictional.json: the Janssen column predicted, not fitted (docs/theory.md
section 4.3). Frictional grains of the frictional silo (frictional_silo.py: r = 4-5 mm, mu = 0.3 or
0.5, with or without EPSD rolling resistance) sediment from a loose lattice into a cylinder of the
silo's wall balls (friction 0.3 against the grains) of D = 0.18 m = 20 mean grain diameters, and
settle under gravity to a column of about 0.72 m = 4 D. Settled, the column's wall friction is
mobilised only where the settling slid the grains along the wall (measured: the deeper half then
carries 20-30 % more pressure than Janssen and the floor 1.8 x p_h/K); as in the experiments of
Vanel & Clement (1999) and Ovarlez et al. (2003), the friction is then mobilised by a slip: the
mantle rises by 2 mm (0.2 d) at 1 cm/s, stops, and the column comes to rest again. The check
janssen_prediction compares that state's horizontal wall pressure profile with Janssen's law
evaluated with the K and mu_w that the virtual material tests of the same grains and wall measured
(cases/lateral_pressure_ratio.json, cases/wall_friction.json: verify runs them first), its
tolerance their seed scatter, and with EN 1991-4's own K = 1.1 (1 - sin phi_i), phi_i the peak
angle of the virtual shear test (cases/direct_shear.json), and the floor's vertical stress with p_h/K at the base; the settled
state before the slip is reported the same way. The janssen check fits K and mu_w to the final
profile and reports them beside it.
Run from the repository root: python3 cases/generators/janssen_frictional.py
"""
from common import between_from_scatter, write_case

from frictional_silo import VARIANTS, WALL_FRICTION, column_case

D, H = 0.18, 1.15          # inner diameter (20 d), top of the wall
BELOW = 0.02               # the mantle reaches under the floor (it rises by 2 mm)
LATTICE_TOP = 1.07         # the loose lattice (49 % solid) settles to about 0.72 m (59.5 %)
T_SLIDE, V_SLIDE, SLIDE = 1.0, 0.01, 0.2   # at rest by about 0.9 s; then 2 mm of wall slip
T_END = 1.6
# The sample standard deviation of the profile ratio (janssen_predicted_profile) over three packings
# of the mu = 0.5 column (seeds 2002-2004, the run of this file with "seed" set).
COLUMN_SCATTER = 0.0164
COLUMN_SCATTER_MEASURED = ("silodem run of this case at mu = 0.5 with seed 2002, 2003, 2004 (2026-12-04, before its "
                           "commit): profile ratios 1.058, 1.049, 1.026 with K = 1.1 x 0.511, mu_w = 0.270; "
                           "reports/frictional_silo.md")

# The silo's K from the test's K_o, as EN 1991-4 converts a lateral pressure ratio measured with a
# frictionless wall; the column's own scatter between packings of the profile ratio (measured below).
PREDICTION = {
    "K_factor": 1.1,
    "K_factor_source": {"type": "published", "citation":
                        "EN 1991-4:2006, Annex C: K_m = 1.1 K_o, the 1.1 for the difference between K_o measured with "
                        "nearly zero wall friction and K in the silo (clause as recalled: docs/theory.md section 4.3)"},
    "column_scatter": COLUMN_SCATTER,
    "column_scatter_source": {"type": "seed_scatter", "realisations": 3, "scatter": COLUMN_SCATTER,
                              "measured": COLUMN_SCATTER_MEASURED},
}

# Between codes: the final profile band by band, the load balance and the fitted K and mu_w, each
# judged against twice sqrt(2) x silodem's scatter over three packings (common.between_from_scatter);
# the ledger's state functions are reported: at rest the kinetic energy is 1e-4 of the scale, a
# residual ringing, and the gravitational change is the scale itself.
COMPARE_MEASURED = ("silodem compare cases/janssen_frictional.json (2026-12-04, the case of commit 6f239bb), rows "
                    "'silodem seeds', seeds 2002-2004 (the wall load recounted with one value per packing)")
# The profile, K and mu_w come from the wall pressure probe, which until commit 9417e8b re-binned
# the mantle's balls after its slip (reports/frictional_silo.md): their scatter measured again with
# the fixed probe. The wall load sums every wall ball's force, which the binning never touched.
PROBE_MEASURED = ("silodem compare cases/janssen_frictional.json (the full tier of 2026-12-07/08, the wall pressure probe "
                  "of commit 9417e8b), rows 'silodem seeds', seeds 2002-2004")
AT_REST = "the column is at rest: its kinetic energy is a residual ringing of 1e-4 of the scale, not a state to compare"
COLUMN_BETWEEN = [
    between_from_scatter("band_pressure", 0.1737, 3, PROBE_MEASURED, relative_to="largest"),
    between_from_scatter("wall_load/weight", 0.000337, 3, COMPARE_MEASURED),
    between_from_scatter("effective_wall_friction_mu_w", 0.0193, 3, PROBE_MEASURED, relative_to="absolute"),
    between_from_scatter("lateral_pressure_ratio_K", 0.0342, 3, PROBE_MEASURED),
    {"quantity": "energy_kinetic", "relative_to": "absolute", "report": AT_REST},
    {"quantity": "energy_gravitational_change", "relative_to": "absolute",
     "report": "the energy scale is this change itself (1 in every code)"},
]

case = column_case("janssen_frictional",
                   "The Janssen column predicted: frictional grains (mu 0.3 or 0.5) settled in a cylinder of D = 0.18 m = 20 d "
                   "of the silo's wall balls (friction 0.3) to about 4 D, the wall friction mobilised by a 2 mm slip of the "
                   "mantle; the wall pressure profile against Janssen with the K and mu_w of the virtual material tests",
                   D, H, LATTICE_TOP, WALL_FRICTION, below=BELOW)
case.update({
    "time": {"dt_per_contact_time": 0.04, "duration": T_END},
    "stages": {"events": [
        {"time": T_SLIDE, "type": "move_wall", "wall": "mantle", "velocity": [0.0, 0.0, V_SLIDE]},
        {"time": T_SLIDE + SLIDE, "type": "move_wall", "wall": "mantle", "velocity": [0.0, 0.0, 0.0]}]},
    # At rest again after the slip: the stop tests end the run (the wall load is then the weight
    # within p_ft, the bound of the global test).
    "equilibrium": {"check_interval_steps": 200, "p_ft": 0.01, "min_time": T_SLIDE + SLIDE + 0.1},
    "output": {"series_interval": 0.01, "probes": [
        {"type": "wall_pressure", "name": "mantle_settled", "wall": "mantle", "angle_bins": 8, "height_bins": 47,
         "from_time": T_SLIDE - 0.05, "to_time": T_SLIDE},
        {"type": "wall_pressure", "name": "mantle", "wall": "mantle", "angle_bins": 8, "height_bins": 47},
        {"type": "wall_pressure", "name": "floor", "wall": "bottom", "angle_bins": 8, "height_bins": 4}]},
    "verify": {
        # Rolling resistance is in the material tests; the column runs without (its time: 8 min a run).
        # (the axis rolling = none names the material tests' group this column takes).
        "variants": {"mu": VARIANTS["mu"], "rolling": {"none": {}}},
        "checks": [
            {"type": "janssen_prediction", "wall_probe": "mantle", "floor_probe": "floor",
             "lateral_pressure_ratio_from": "lateral_pressure_ratio", "wall_friction_from": "wall_friction",
             "internal_friction_from": "direct_shear",
             "coverage": 2.0, "exclude_bottom_diameters": 0.5, **PREDICTION},
            {"type": "janssen_prediction", "wall_probe": "mantle_settled", "value": "mean",
             "lateral_pressure_ratio_from": "lateral_pressure_ratio", "wall_friction_from": "wall_friction",
             "coverage": 2.0, "exclude_bottom_diameters": 0.5, **PREDICTION,
             "report": "the settled column before the slip: its wall friction is not mobilised everywhere, which "
                       "Janssen's law assumes; reported to show by how much"},
            {"type": "janssen", "wall_probe": "mantle", "ball_diameter": 0.009, "exclude_bottom_diameters": 0.5,
             "weight_tolerance": "stop_test"},
            {"type": "pressure_profile", "wall_probe": "mantle", "value": "final"},
        ],
    },
})
# Every code from one shared state (approach b): silodem's column settled at 0.95 s, before the
# slip, at mu = 0.5. The state carries positions, velocities and spins but no contact history, so
# each code first re-settles on springs that start at zero (silodem too), then slips the mantle by
# the same 2 mm and comes to rest; the profile compared is the one Janssen's law assumes (wall
# friction mobilised). A fixed duration instead of the stop tests: every code runs as long.
case["compare"] = {
    "base": {"integrator": {"scheme": "velocity_verlet", "dashpot_velocity": "half_step"},
             "contact": {"clamp_tensile_force": True}, "equilibrium": None,
             "time": {"duration": T_SLIDE + SLIDE + 0.2},
             "output": {"dump_interval_steps": 2000, "probes": [
                 {"type": "wall_pressure", "name": "mantle", "wall": "mantle", "angle_bins": 8, "height_bins": 47},
                 {"type": "wall_pressure", "name": "floor", "wall": "bottom", "angle_bins": 8, "height_bins": 4}]}},
    "from_state_at": T_SLIDE - 0.05,
    "checks": [
        {"type": "janssen", "wall_probe": "mantle", "ball_diameter": 0.009, "exclude_bottom_diameters": 0.5},
        {"type": "pressure_profile", "wall_probe": "mantle", "value": "final"},
        {"type": "static_balance", "tolerance": 0.01},
        {"type": "energy_terms"}],
    "seeds": [2003, 2004],
    "between_codes": COLUMN_BETWEEN,
    # YADE's run: about 55 min alone on the machines of early December, 100 min on those of
    # 2026-12-07 (1.8x slower); the limit only catches a hung run.
    "time_limit_s": 10800,
}
write_case(case, "cases/janssen_frictional.json")
