#!/usr/bin/env python3
"""Writes the particle-scale friction and Hertz cases (docs/theory.md section 10):
  cases/chung_ooi_normal_impact.json   Chung & Ooi (2011) tests 1 and 2, elastic Hertz impacts
  cases/chung_ooi_oblique_impact.json  test 4, oblique impact of alumina on a plane, 40-85 deg judged
                                       against gross sliding, 10-30 deg reported
  cases/slip_to_roll.json              a ball thrown along a floor, mu = 0.2, 0.5, 1 (MFiX DEM-04 type),
                                       and a ball at rest on a floor set moving (move_wall)
A "plane" or "floor" is one fixed ball of radius 1000 m. Run from the repository root:
python3 cases/generators/friction_particle.py
"""
import math

from common import write_case

PLANE_R = 1000.0
# The scheme of LAMMPS's and LIGGGHTS's fix nve/sphere and YADE's leapfrog.
HALF_STEP_VERLET = {"integrator": {"scheme": "velocity_verlet", "dashpot_velocity": "half_step"}}


def sphere_mass(rho, r):
    return rho * 4.0 / 3.0 * math.pi * r**3


def hertz_duration(m, r, e_star, v):
    """Johnson (1985): t_c = 2.9432 delta_max / v (docs/theory.md 10.1)."""
    k = 4.0 / 3.0 * e_star * math.sqrt(r)
    d = (5.0 * m * v * v / (4.0 * k)) ** 0.4
    return 2.9432 * d / v, d


def scheme(derivation):
    return {"type": "scheme_bound", "derivation": derivation}


def compare(case, base, between, time_limit_s):
    """The case in every code: its own variants and checks, the reference scheme, and the quantities
    compared between codes, each with its tolerance and source (or `report` with a reason)."""
    return {"codes": ["silodem", "lammps", "liggghts", "yade"], "base": dict(HALF_STEP_VERLET, **base),
            "variants": case["verify"]["variants"], "checks": case["verify"]["checks"],
            "between_codes": between, "time_limit_s": time_limit_s}


def between(quantities, derivation, codes=None):
    rows = []
    for q in quantities:
        row = {"quantity": q}
        if codes:
            row["codes"] = codes
        rows.append(dict(row, tolerance=1e-5, tolerance_source=scheme(derivation)))
    return rows


def reported(quantities, reason, codes):
    return [{"quantity": q, "codes": codes, "report": reason} for q in quantities]


# ---- Tests 1 and 2: elastic normal impacts ---------------------------------------------------
MATERIALS = {  # E (Pa), nu, rho (Chung & Ooi 2011, table of tests 1-2)
    "glass": (48e9, 0.20, 2800.0), "limestone": (20e9, 0.25, 2500.0),
    "aluminium": (70e9, 0.30, 2699.0), "magnesium": (40e9, 0.35, 1800.0)}
RIGID = {"density": 7800.0, "youngs_modulus": 1e13, "poisson_ratio": 0.3, "restitution": 1.0}


def normal_variant(test, name):
    e, nu, rho = MATERIALS[name]
    mat = {"density": rho, "youngs_modulus": e, "poisson_ratio": nu, "restitution": 1.0}
    if test == 1:  # two spheres R = 10 mm at +-10 m/s
        r, v = 0.01, 10.0
        m_eff, r_eff, e_star, v_rel = sphere_mass(rho, r) / 2, r / 2, e / (2 * (1 - nu * nu)), 2 * v
        balls = [{"id": "a", "material": "grain", "radius": r, "position": [-r - 1e-9, 0, 0], "velocity": [v, 0, 0]},
                 {"id": "b", "material": "grain", "radius": r, "position": [r + 1e-9, 0, 0], "velocity": [-v, 0, 0]}]
    else:  # a sphere R = 0.1 m at 0.2 m/s on a rigid plane
        r, v = 0.1, 0.2
        e_w = RIGID["youngs_modulus"]
        e_star = 1 / ((1 - nu * nu) / e + (1 - 0.09) / e_w)
        m_eff, r_eff, v_rel = sphere_mass(rho, r), r * PLANE_R / (r + PLANE_R), v
        balls = [{"id": "a", "material": "grain", "radius": r, "position": [0, 0, PLANE_R + r + 1e-9], "velocity": [0, 0, -v]},
                 {"id": "b", "material": "plane", "radius": PLANE_R, "position": [0, 0, 0], "fixed": True}]
    tc, _ = hertz_duration(m_eff, r_eff, e_star, v_rel)
    dt = tc / 1000
    return {"materials": {"grain": mat, "plane": RIGID}, "balls": balls,
            "time": {"dt": dt, "duration": 1.5 * tc}}


base1 = normal_variant(1, "glass")
normal = {
    "name": "chung_ooi_normal_impact",
    "description": "Chung & Ooi (2011) tests 1 and 2: elastic Hertz impacts of two spheres (glass, limestone) and of "
                   "a sphere on a rigid plane (aluminium, magnesium alloys), against Hertz's solution",
    "gravity": [0, 0, 0],
    "contact": {"normal": "hertz"},
    **base1,
    "output": {"probes": [{"type": "pair", "name": "impact", "balls": ["a", "b"]}]},
    "verify": {
        "variants": {"test": {f"t{t}_{n}": normal_variant(t, n) for t, n in
                              ((1, "glass"), (1, "limestone"), (2, "aluminium"), (2, "magnesium"))}},
        "checks": [{"type": "hertz_impact", "pair_probe": "impact", "tolerance": 2e-3, "tolerance_source": scheme(
            "the pair probe samples the contact's end at the steps: within one step, dt = t_c/1000, of the true "
            "end; the scheme's error on the largest overlap and on an elastic restitution is O((omega dt)^2) ~ 1e-5 "
            "(docs/theory.md 8.3); 2e-3 covers both, and a plane of radius 1000 m and E = 1e13 Pa moves E* and R* by "
            "under 1e-4 in the impact's closed form (its own E*, R* are used)")},
                   {"type": "energy_balance", "tolerance": 1e-3}]},
}
normal["compare"] = compare(normal, {"output": {"dump_interval_steps": 1}}, between(
    ("hertz_max_overlap", "hertz_duration", "normal_restitution"),
    "silodem and LAMMPS run the same normal law here (Hertz, the Tsuji-form dashpot c = 2 zeta sqrt(2 m* E* a) given "
    "to LAMMPS as damping tsuji with the restitution whose polynomial gives alpha = 2 zeta sqrt(3/2)), the same scheme "
    "(velocity Verlet, dashpot at the half-step velocity) and the same state, so they differ by floating-point "
    "rounding (measured below 1e-9); 1e-5 is far above that"), 600)
write_case(normal, "cases/chung_ooi_normal_impact.json")

# ---- Test 4: oblique impact on a plane ---------------------------------------------------------
R4, V4, MU4, E4 = 2.5e-3, 3.9, 0.092, 0.98
alumina = {"density": 4000.0, "youngs_modulus": 380e9, "poisson_ratio": 0.23, "restitution": E4, "friction": MU4}
plane4 = dict(alumina, youngs_modulus=1e13)
m4 = sphere_mass(4000.0, R4)
tc4, _ = hertz_duration(m4, R4, 380e9 / (1 - 0.23**2), V4 * math.cos(math.radians(85)))


def oblique_variant(deg):
    th = math.radians(deg)
    return {"balls": [{"id": "ball", "material": "alumina", "radius": R4, "position": [0, 0, PLANE_R + R4 + 1e-9],
                       "velocity": [V4 * math.sin(th), 0, -V4 * math.cos(th)]},
                      {"id": "plane", "material": "plane", "radius": PLANE_R, "position": [0, 0, 0], "fixed": True}]}


oblique = {
    "name": "chung_ooi_oblique_impact",
    "description": "Chung & Ooi (2011) test 4: alumina sphere (R = 2.5 mm, 3.9 m/s, mu = 0.092, e = 0.98) on a plane "
                   "at incidence 10-85 deg; Hertz-Mindlin with history; rigid-body gross sliding above 32.5 deg",
    "gravity": [0, 0, 0],
    "contact": {"normal": "hertz", "tangential": "mindlin"},
    "materials": {"alumina": alumina, "plane": plane4},
    **oblique_variant(45),
    "time": {"dt": 2e-8, "duration": 2.2 * tc4},
    "output": {"probes": [{"type": "ball", "name": "ball", "balls": ["ball"]}]},
    "verify": {
        "variants": {"incidence": {f"deg_{d}": oblique_variant(d) for d in (10, 20, 30, 40, 50, 60, 70, 80, 85)}},
        "checks": [{"type": "oblique_impact", "ball_probe": "ball", "plane": "plane", "tolerance": 2e-3,
                    "tolerance_source": scheme(
                        "the DEM's friction acts at the lever arm r - delta/2, the rigid body's at r: spin and rebound "
                        "angle may differ by up to delta_max/(2r) = 1.9e-3 at 40 deg (Hertz delta_max at V cos theta, "
                        "docs/theory.md 10.3); e_n and e_t carry the Hertz restitution mapping (1e-8) and the scheme's "
                        "O((omega dt)^2) at dt = t_c/350 (1e-5)")},
                   {"type": "energy_balance", "tolerance": 1e-3}]},
}
YADE_MINDLIN = ("YADE 2023.02a's Mindlin spring is incremental (F_t += k_t(delta) du, rotated to first order, never "
                "rescaled, the cap on the elastic part alone), silodem's is the total displacement times k_t(delta) (as "
                "LAMMPS's mindlin); in gross sliding (30-85 deg) both give mu F_n and agree to 1e-11, in partial stick "
                "(10-20 deg) they differ by 2-5 % in e_t and spin (docs/reference-codes.md, friction in the codes)")
oblique["compare"] = compare(
    oblique, {"output": {"dump_interval_steps": 1}, "contact": {"slip_lever_arm": "radius", "clamp_tensile_force": True}},
    between(("normal_restitution",),
            "YADE's Law2_ScGeom_MindlinPhys_Mindlin has the same normal law as silodem's (Hertz k_n = 4/3 E* sqrt(R*), "
            "dashpot 2 beta_n sqrt(m* 1.5 k_n sqrt(delta)) with beta_n = zeta, total clamped at zero) and its leapfrog is "
            "velocity Verlet with the half-step velocity, so the normal rebound is the same algorithm; measured, 1e-11 "
            "at every angle; 1e-5 is far above rounding", ["yade"]) +
    between(("normal_restitution", "tangential_restitution", "rebound_spin", "rebound_angle"),
            "the compared runs take the radius as the slip velocity's lever arm (contact.slip_lever_arm \"radius\", as "
            "LAMMPS 29Sep2021 pair granular does) and clamp the normal force at zero (LAMMPS limit_damping; unclamped, "
            "LAMMPS caps friction at mu |F_n| where silodem caps at mu max(F_n, 0), which differs while the damped "
            "contact ends in tension), so silodem and LAMMPS run the same algorithm (Hertz with the Tsuji-form dashpot, "
            "Mindlin spring with history rotated into the tangent plane and reset at the cap, velocity Verlet with the "
            "half-step velocity) from the same state; measured, they agree to 8e-12; 1e-5 is far above rounding and far "
            "below either difference (lever arm up to 3.1e-3 in partial stick, the tensile cap 4e-5; "
            "docs/reference-codes.md)", ["lammps", "liggghts"]) +
    reported(("tangential_restitution", "rebound_spin", "rebound_angle"), YADE_MINDLIN, ["yade"]), 600)
write_case(oblique, "cases/chung_ooi_oblique_impact.json")

# ---- Slip to roll ---------------------------------------------------------------------------
R5, U0, K5 = 0.005, 1.0, 2.0e5
m5 = sphere_mass(2500.0, R5)
static = m5 * 9.81 / (K5 / 2)


def grain(mu):
    return {"density": 2500.0, "stiffness": K5, "restitution": 0.5, "reference_radius": R5, "friction": mu,
            "tangential_damping_ratio": 0.5}


def slip_variant(mu, phase):
    ts = 2 * U0 / (7 * mu * 9.81)
    t = round((0.5 if phase == "sliding" else 1.5) * ts / 1e-5) * 1e-5
    return {"materials": {"grain": grain(mu), "floor": grain(mu)}, "time": {"duration": t}}


def moving_floor(phase):
    """The ball at rest and the floor set moving at -u0 at t = 0 (a move_wall event): in the floor's
    frame the same slide and roll (Galilean invariance; the check subtracts the floor's velocity). The
    ball starts 1e-9 m above the floor, as the compared runs do: first contact after 1.4e-5 s, which
    shifts the slide by mu g 1.4e-5 s = 7e-5 m/s, inside the check's 1e-3."""
    v = slip_variant(0.5, phase)
    v["balls"] = [{"id": "ball", "material": "grain", "radius": R5, "position": [0, 0, PLANE_R + R5 + 1e-9]},
                  {"id": "floor", "material": "floor", "radius": PLANE_R, "position": [0, 0, 0], "fixed": True}]
    v["stages"] = {"events": [{"time": 0, "type": "move_wall", "ball": "floor", "velocity": [-U0, 0, 0]}]}
    return v


slip = {
    "name": "slip_to_roll",
    "description": "A ball (r = 5 mm) thrown at 1 m/s without spin along a floor: it slides, v = u0 - mu g t, spins "
                   "up at 5 mu g/(2r), and from t_s = 2 u0/(7 mu g) rolls at 5 u0/7 (MFiX DEM-04 type); linear law "
                   "with a history spring, mu = 0.2, 0.5, 1; each mu stopped while sliding (t_s/2) and rolling (1.5 t_s); "
                   "compared between codes from the ball 1e-9 m above the floor (first contact within 1.4e-5 s: at most "
                   "1.6e-4 of the sliding speed at mu = 1, inside the check's 1e-3), so that every code makes first "
                   "contact inside its run",
    "contact": {"tangential": "linear_history"},
    "materials": {"grain": grain(0.5), "floor": grain(0.5)},
    "balls": [{"id": "ball", "material": "grain", "radius": R5, "position": [0, 0, PLANE_R + R5 - static],
               "velocity": [U0, 0, 0]},
              {"id": "floor", "material": "floor", "radius": PLANE_R, "position": [0, 0, 0], "fixed": True}],
    "time": {"dt": 1e-5, "duration": 0.05},
    "output": {"probes": [{"type": "ball", "name": "ball", "balls": ["ball"]}]},
    "verify": {
        "variants": {"run": dict({f"mu_{mu}_{phase}": slip_variant(mu, phase) for mu in (0.2, 0.5, 1.0)
                                  for phase in ("sliding", "rolling")},
                                 **{f"moving_floor_mu_0.5_{phase}": moving_floor(phase) for phase in ("sliding", "rolling")})},
        "checks": [{"type": "slip_to_roll", "ball_probe": "ball", "floor": "floor", "tolerance": 1e-3,
                    "tolerance_source": scheme(
                        "a constant friction force is integrated exactly by the scheme; the floor is a ball of radius "
                        "1000 m, which tilts by x/1000 over the distance x <= 0.2 m a run travels and changes the "
                        "speed by at most g x t/1000 m = 4e-4 m/s (6e-4 of the rolling speed); the normal force "
                        "starts at m g to 1e-6 (docs/theory.md 10.4)")},
                   {"type": "energy_balance", "tolerance": 1e-3}]},
}
slip["compare"] = compare(
    slip, {"contact": {"clamp_tensile_force": True}, "output": {"dump_interval_steps": 1},
           "balls": [dict(slip["balls"][0], position=[0, 0, PLANE_R + R5 + 1e-9]), slip["balls"][1]]},
    between(("sliding_speed", "sliding_spin", "rolling_speed", "rolling_spin"),
            "silodem, LAMMPS and LIGGGHTS run the same scheme here (velocity Verlet, dashpot and spring increment at the "
            "half-step velocity, the spring rotated into the tangent plane and reset at the Coulomb cap) from the same "
            "state, and the ball starts 1e-9 m above the floor so that every code makes first contact inside the run (a "
            "contact present at a run's start gets no spring increment in LAMMPS's and LIGGGHTS's first force "
            "evaluation: docs/reference-codes.md); measured, sliding agrees to 1e-16 and rolling with LIGGGHTS to 1e-11. "
            "LAMMPS 29Sep2021 takes the contact-point velocity with the radius as lever arm where silodem and LIGGGHTS "
            "take r - delta/2, so a rolling ball's omega/v differs by delta/(2r) = 1.28e-5 (delta = m g / k_ij = 1.28e-7 "
            "m): measured 3.7e-6 in speed and 9.2e-6 in spin, inside 1e-5, which is far below any other difference of "
            "algorithm (the setup increment alone gives 1.1e-5 to 3.4e-4). The moving_floor variants set the floor moving "
            "(move_wall: LAMMPS's and LIGGGHTS's fix move linear, YADE's velocity of a fixed body), the same motion in the "
            "floor's frame: measured the same agreement (LIGGGHTS 2e-11, YADE 2e-11, LAMMPS 3.7e-6 and 9.2e-6 rolling)"), 300)
write_case(slip, "cases/slip_to_roll.json")
