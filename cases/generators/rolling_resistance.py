#!/usr/bin/env python3
"""Writes cases/rolling_resistance.json: a ball (r = 5 mm) rolling on a floor against a rolling
couple mu_r R* F_n (mu_r = 0.05), for the constant torque and the elastic-plastic spring (EPSD):
  *_decay    thrown rolling at 0.1 m/s, it slows at a = (5/7) mu_r g R*/r until it stops;
  *_incline  gravity tilted by arctan 0.1 (> mu_r), from rest it rolls down at (5/7)(g_t - mu_r g_n R*/r)
             (the EPSD spring after its damped elastic start, references::spring_rolling);
  epsd_held  tilted by arctan 0.025 (< mu_r), the spring holds it to its elastic deflection;
  *_sds      the same with the limit on spring and dashpot together (contact.rolling_limit, LAMMPS's form).
(docs/theory.md section 10.5). The ball starts 1e-9 m above the floor so that every code makes first
contact inside its run (a contact present at a run's start gets no spring increment in LAMMPS's and
LIGGGHTS's first force evaluation). Run from the repository root:
python3 cases/generators/rolling_resistance.py
"""
import math

from common import REFERENCE_SCHEME, write_case

PLANE_R, R, V0, MU_R = 1000.0, 0.005, 0.1, 0.05
G = 9.81


def grain():
    return {"density": 2500.0, "stiffness": 2.0e5, "restitution": 0.5, "reference_radius": R, "friction": 0.5,
            "tangential_damping_ratio": 0.5, "rolling_friction": MU_R, "rolling_damping_ratio": 0.3}


K_N = 0.5 * 2.0e5  # the pair's k_n, the series of the two materials' stiffness
MASS = 2500.0 * 4.0 / 3.0 * math.pi * R ** 3


def ball(v0, resting_on=None):
    """1e-9 m above the floor, or (undamped runs) resting on it under the normal gravity `resting_on`: an
    undamped normal spring started off the floor would bounce for ever, leaving the floor and losing the
    springs at each bounce."""
    z = PLANE_R + R + 1e-9 if resting_on is None else PLANE_R + R - MASS * resting_on / K_N
    b = {"id": "ball", "material": "grain", "radius": R, "position": [0, 0, z]}
    if v0:
        b["velocity"] = [v0, 0, 0]
        b["angular_velocity"] = [0, v0 / R, 0]  # rolling: the contact point at rest
    return b


def run(model, v0, tan_theta, duration, eta_r=0.3, limit=None, undamped=False):
    th = math.atan(tan_theta)
    out = {"contact": {"rolling": model, "rolling_limit": limit},
           "balls": [ball(v0, G * math.cos(th) if undamped else None), FLOOR],
           "gravity": [G * math.sin(th), 0, -G * math.cos(th)], "time": {"duration": duration}}
    # The dashpot ratio belongs to the spring only.
    out["materials"] = {m: {"rolling_damping_ratio": eta_r if model == "epsd" else None} for m in ("grain", "floor")}
    if undamped:  # no dashpot anywhere: YADE's moment law (CohFrictMat) has none
        for m in out["materials"].values():
            m.update(restitution=1.0, tangential_damping_ratio=0.0, rolling_damping_ratio=0.0)
    return out


def scheme(derivation):
    return {"type": "scheme_bound", "derivation": derivation}


FLOOR = {"id": "floor", "material": "floor", "radius": PLANE_R, "position": [0, 0, 0], "fixed": True}
# Thrown at 20 rad/s, the EPSD dashpot (eta_r = 0.3) would give C_r w = 95 times the limit couple
# until the spring reaches the limit: how long that lasts hangs on how the normal force comes in at
# first contact, so the thrown ball's spring is undamped; the slopes start from rest and keep it.
RUNS = {"cdt_decay": run("constant_torque", V0, 0.0, 0.1), "cdt_incline": run("constant_torque", 0.0, 0.1, 0.2),
        "epsd_decay": run("epsd", V0, 0.0, 0.1, eta_r=0.0), "epsd_incline": run("epsd", 0.0, 0.1, 0.2),
        "epsd_held": run("epsd", 0.0, 0.025, 0.1),
        # LAMMPS's rolling sds: the limit holds spring and dashpot together.
        "epsd_incline_sds": run("epsd", 0.0, 0.1, 0.2, limit="spring_and_dashpot"),
        "epsd_held_sds": run("epsd", 0.0, 0.025, 0.1, limit="spring_and_dashpot"),
        # Undamped (restitution 1, no tangential or rolling dashpot), resting on the floor from the start:
        # what YADE's CohFrictMat moment law can carry.
        "epsd_decay_undamped": run("epsd", V0, 0.0, 0.1, undamped=True),
        "epsd_incline_undamped": run("epsd", 0.0, 0.1, 0.2, undamped=True),
        "epsd_held_undamped": run("epsd", 0.0, 0.025, 0.1, undamped=True)}

CHECK = {"type": "rolling_resistance", "ball_probe": "ball", "floor": "floor", "tolerance": 1e-3,
         "tolerance_source": scheme(
             "the couple and the weight are constant, which the scheme integrates exactly; left are the floor's "
             "curvature (a ball of radius 1000 m tilts by x/1000 over the x <= 7 mm a run travels: at most "
             "(5/7) g x t/2000 = 5e-6 m/s, 1e-4 of the final speed), the lever arm r - delta/2 (delta/(2r) = 1.3e-5), "
             "and the start 1e-9 m above the floor: first contact after 1.4e-5 s and the small bounces after it keep "
             "the ball off the floor for about 3e-5 s, 1.5e-4 to 3e-4 of a run; the EPSD's damped elastic start is in "
             "the closed form")}

SAME_LIGGGHTS = (
    "LIGGGHTS 3.8 rolling_friction epsd runs silodem's EPSD: k_r = 2.25 k_n mu_r^2 R*^2 grown by omega_r dt, the "
    "limit mu_r R* |F_n| on the spring alone, the dashpot eta_r 2 sqrt(I_r k_r) with I_r the series of 1.4 m r^2 "
    "(the floor's mass scaled up) and off at the limit; its spring is not turned with the contact, which on a floor of "
    "radius 1000 m turns by under 1e-5 rad; same scheme (velocity Verlet, half-step velocity) and the same start, "
    "so rounding is left: measured 1e-15; 1e-5 is far above it")
SAME_LAMMPS = (
    "LAMMPS 29Sep2021 rolling sds is silodem's EPSD with k_roll = k_r/R*^2, gamma_roll = C_r/R*^2 and the limit on "
    "spring and dashpot together (contact.rolling_limit \"spring_and_dashpot\"; the same as silodem's default "
    "without a dashpot, eta_r = 0 in *_decay), the same spring rotation and reset and the same scheme; it takes the "
    "contact-point velocity with the radius as lever arm where silodem takes r - delta/2, so omega/v differs by "
    "delta/(2r) = 1.28e-5 (as in slip_to_roll): measured 3.7e-6 in speed, 9.1e-6 in spin")
CDT_LIGGGHTS = (
    "LIGGGHTS 3.8 rolling_friction cdt takes mu_r R* times the elastic normal force k_n delta where silodem takes the "
    "whole normal force (spring and dashpot), and has no one-step limit: over the landing the dashpot's impulse "
    "c_ij delta_static = 4.5e-7 N s is 3.5e-4 of the weight's m g t, so the couple's impulse and the final speeds "
    "differ by that order: measured 1.9e-4 (thrown), 4.2e-5 (from rest)")
HELD_LAMMPS = (
    "held, the ball's centre moves with the springs' deflection at the contact point, which LAMMPS's slip velocity "
    "takes with the radius as lever arm and silodem with r - delta/2: the displacement differs by up to "
    "2 delta/(2r) = 2.6e-5 of itself (measured 1.26e-5); otherwise the same algorithm (see rolling_speed)")
SAME_YADE = (
    "YADE 2023.02a CohFrictMat's moment law (Law2_ScGeom6D_CohFrictPhys_CohesionMoment, incremental form) on the "
    "undamped runs: normal k_n delta, the tangential force grown by k_t v_t dt at the contact point and capped at "
    "mu F_n, the bending moment grown by k_r w_r dt and capped at mu_r R* F_n (the backend sets CohFrictMat's "
    "young, poisson, alphaKr and etaRoll so that k_n, k_t, k_r and the limit are silodem's), velocity and spin by "
    "leapfrog, which is velocity Verlet's trajectory; the driver starts it at silodem's step 0 (the springs grown "
    "for the first force only); YADE turns both springs with the contact to first order, and the contact normal "
    "turns by under 1e-5 rad on the floor of radius 1000 m: measured 1.6e-11 to 1.6e-10; 1e-5 is far above it")
UNDAMPED_LAMMPS = (
    "undamped, the tangential and rolling springs swing for the whole run (period 0.7 ms), and the final value "
    "samples that swing: LAMMPS's slip lever arm (the radius, silodem r - delta/2) shifts its frequency by about "
    "delta/(2r) = 1.3e-5, a phase shift of w_t t delta/(2r) ~ 1e-2 rad by the end, and its first force evaluation "
    "grows no spring: no bound tighter than the swing itself; each code's own theory row judges it")
UNDAMPED = ["run=epsd_decay_undamped", "run=epsd_incline_undamped"]
BETWEEN = (
    [{"quantity": q, "codes": ["liggghts"], "variants": ["run=epsd_decay", "run=epsd_incline"] + UNDAMPED,
      "tolerance": 1e-5, "tolerance_source": scheme(SAME_LIGGGHTS)} for q in ("rolling_speed", "rolling_spin")] +
    [{"quantity": "held_displacement", "codes": ["liggghts"], "tolerance": 1e-5, "tolerance_source": scheme(SAME_LIGGGHTS)}] +
    [{"quantity": q, "codes": ["lammps"], "variants": ["run=epsd_decay", "run=epsd_incline_sds"], "tolerance": 1e-5,
      "tolerance_source": scheme(SAME_LAMMPS)} for q in ("rolling_speed", "rolling_spin")] +
    [{"quantity": "held_displacement", "codes": ["lammps"], "variants": ["run=epsd_held_sds"], "tolerance": 3e-5,
      "tolerance_source": scheme(HELD_LAMMPS)}] +
    [{"quantity": q, "codes": ["lammps"], "variants": UNDAMPED + (["run=epsd_held_undamped"] if q == "held_displacement" else []),
      "report": UNDAMPED_LAMMPS} for q in ("rolling_speed", "rolling_spin", "held_displacement")] +
    [{"quantity": q, "codes": ["yade"], "variants": UNDAMPED, "tolerance": 1e-5, "tolerance_source": scheme(SAME_YADE)}
     for q in ("rolling_speed", "rolling_spin")] +
    [{"quantity": "held_displacement", "codes": ["yade"], "variants": ["run=epsd_held_undamped"], "tolerance": 1e-5,
      "tolerance_source": scheme(SAME_YADE)}] +
    [{"quantity": q, "codes": ["liggghts"], "variants": ["run=cdt_decay", "run=cdt_incline"], "report": CDT_LIGGGHTS}
     for q in ("rolling_speed", "rolling_spin")])

case = {
    "name": "rolling_resistance",
    "description": "A ball (r = 5 mm) on a floor against a rolling couple mu_r R* F_n (mu_r = 0.05), constant torque "
                   "and elastic-plastic spring (eta_r = 0.3 from rest, 0 thrown): thrown rolling at 0.1 m/s it slows at (5/7) mu_r g R*/r; on a "
                   "slope of tan 0.1 it rolls down at (5/7)(g_t - mu_r g_n R*/r); on a slope of tan 0.025 the spring "
                   "holds it (Ai et al. 2011; docs/theory.md 10.5)",
    **run("epsd", 0.0, 0.1, 0.2),
    "contact": {"tangential": "linear_history", "rolling": "epsd"},
    "materials": {"grain": grain(), "floor": grain()},
    "time": {"dt": 1e-5, "duration": 0.1},
    "output": {"probes": [{"type": "ball", "name": "ball", "balls": ["ball"]}]},
    "verify": {"variants": {"run": RUNS},
               "checks": [CHECK, {"type": "energy_balance", "tolerance": 1e-3}]},
    "compare": {
        "codes": ["silodem", "lammps", "liggghts", "yade"],
        "base": dict(REFERENCE_SCHEME, output={"dump_interval_steps": 10}),
        "variants": {"run": RUNS},
        "checks": [CHECK, {"type": "energy_balance", "tolerance": 1e-3}],
        "between_codes": BETWEEN,
    },
}
write_case(case, "cases/rolling_resistance.json")
