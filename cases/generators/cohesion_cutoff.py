#!/usr/bin/env python3
"""Writes cases/cohesion_cutoff.json: pairs that start touching and separate at 0.95 and 1.05
times the escape speed v* = N_max/sqrt(k m_eff), N_max = p_N g min(m_i, m_j) (docs/model.md (10),
docs/theory.md section 2a), for equal and unequal masses. Both balls of a pair are free and fall
together, so gravity does not change their relative motion.
Run from the repository root: python3 cases/generators/cohesion_cutoff.py
"""
import math

from common import integrators, write_case

RHO, K_BALL, P_N, G = 2500.0, 2.0e5, 0.1, 9.81
K = K_BALL / 2  # series pair stiffness (11)


def mass(r):
    return RHO * 4.0 / 3.0 * math.pi * r**3


balls, probes = [], []
row = 0
for label, ra, rb in (("equal", 0.005, 0.005), ("unequal", 0.005, 0.003)):
    ma, mb = mass(ra), mass(rb)
    m_eff = ma * mb / (ma + mb)
    v_star = P_N * G * min(ma, mb) / math.sqrt(K * m_eff)
    for factor in (0.95, 1.05):
        y = 0.05 * row
        row += 1
        u0 = factor * v_star
        name = f"{label}_{int(round(factor * 100))}"
        # Touching to within 1e-15 m (|delta_c| ~ 1e-9 m), never overlapping.
        a = {"id": name + "_a", "material": "grain", "radius": ra, "position": [-ra - 5e-16, y, 0.0],
             "velocity": [-u0 * mb / (ma + mb), 0.0, 0.0]}
        b = {"id": name + "_b", "material": "grain", "radius": rb, "position": [rb + 5e-16, y, 0.0],
             "velocity": [u0 * ma / (ma + mb), 0.0, 0.0]}
        balls += [a, b]
        probes.append({"type": "pair", "name": name, "balls": [a["id"], b["id"]]})

case = {
    "format": "silodem-case/1",
    "name": "cohesion_cutoff",
    "description": "Touching pairs separating at 0.95 and 1.05 v* (equal and unequal masses): the slow "
                   "pair is captured (turns at the gap u0/omega_c < |delta_c|), the fast one escapes at "
                   "sqrt(u0^2 - v*^2) (docs/theory.md section 2a), within the scheme's bound (references/cohesion.hpp).",
    "seed": 1,
    "gravity": [0.0, 0.0, -G],
    "materials": {"grain": {"density": RHO, "stiffness": K_BALL, "damping": 0.0}},
    "contact": {"cohesion": {"enabled": True, "p_N": P_N}},
    "balls": balls,
    "integrator": {"scheme": "predictor_corrector", "max_corrector_passes": 1},
    "time": {"dt": 1.0e-8, "duration": 2.0e-4},
    "output": {"series_interval": 1.0e-6, "probes": probes},
    "verify": {
        "variants": {
            "integrator": integrators("pc_explicit", "pc_multi_fixed_point", "velocity_verlet"),
        },
        "checks": [
            {"type": "cohesion_separation", "tolerance": "scheme_bound"},
            {"type": "cohesion_energy", "tolerance": "scheme_bound"},
            {"type": "energy_balance", "tolerance": 1e-6},
        ],
    },
    # No reference code has the paper's cohesion (a linear tensile spring acting only on separation,
    # cut off at delta_c): they report "not representable", silodem runs alone (docs/reference-codes.md).
    "compare": {
        "base": {"output": {"dump_interval_steps": 100}},
        "checks": [
            {"type": "cohesion_separation", "tolerance": "scheme_bound"},
            {"type": "cohesion_energy", "tolerance": "scheme_bound"},
        ],
        "time_limit_s": 300,
    },
}
write_case(case, "cases/cohesion_cutoff.json")
