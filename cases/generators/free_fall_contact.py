#!/usr/bin/env python3
"""Writes cases/free_fall_contact.json: (1) an analytic drop (Algorithm 2) above two fixed balls
at different heights, offset horizontally, which must pick the higher one and touch it at the
height sqrt(R^2 - b^2) above its centre; (2) the same obstacles 0.1 m away with a ball released at
rest and integrated, whose first contact must be the same; (3) a damped head-on drop onto a fixed
ball whose rebound apex follows from the gravity-corrected restitution (docs/theory.md sections 1c, 3).
Run from the repository root: python3 cases/generators/free_fall_contact.py
"""
from common import CONTACT_END, REFERENCE_SCHEME, SAME_SCHEME, integrators, write_case

R = 0.005
case = {
    "format": "silodem-case/1",
    "name": "free_fall_contact",
    "description": "Analytic first contact against integrated free fall, obstacle choice, and the damped "
                   "rebound height.",
    "seed": 1,
    "gravity": [0.0, 0.0, -9.81],
    "materials": {"grain": {"density": 2500.0, "stiffness": 2.0e5, "damping_ratio": 0.1, "reference_radius": R}},
    "balls": [
        {"id": "high", "material": "grain", "radius": R, "position": [0.0, 0.0, 0.02], "fixed": True},
        {"id": "low", "material": "grain", "radius": R, "position": [0.004, 0.0, 0.0], "fixed": True},
        {"id": "twin_high", "material": "grain", "radius": R, "position": [0.1, 0.0, 0.02], "fixed": True},
        {"id": "twin_low", "material": "grain", "radius": R, "position": [0.104, 0.0, 0.0], "fixed": True},
        {"id": "twin", "material": "grain", "radius": R, "position": [0.102, 0.0, 0.0999]},
        {"id": "anvil", "material": "grain", "radius": R, "position": [0.2, 0.0, 0.0], "fixed": True},
        {"id": "bouncer", "material": "grain", "radius": R, "position": [0.2, 0.0, 0.05]},
    ],
    "drops": {"material": "grain", "radius": [R, R], "z0": 0.1, "count": 1, "positions": [[0.002, 0.0]],
              "initial_velocity": "free_fall"},
    "integrator": {"scheme": "predictor_corrector", "max_corrector_passes": 1},
    "time": {"dt_per_contact_time": 0.02, "duration": 0.2},
    "output": {"series_interval": 1.0e-3, "probes": [
        {"type": "drops", "name": "drops"},
        {"type": "pair", "name": "twin_high", "balls": ["twin", "twin_high"]},
        {"type": "pair", "name": "twin_low", "balls": ["twin", "twin_low"]},
        {"type": "ball", "name": "bouncer", "balls": ["bouncer"]},
    ]},
    "verify": {
        "variants": {
            "integrator": integrators(),
            "contact_end": CONTACT_END,
        },
        "checks": [
            {"type": "first_contact", "drops_probe": "drops", "drop": 0, "obstacle": "high",
             "twin": {"pair_probe": "twin_high", "other_pair_probes": ["twin_low"]}},
            {"type": "rebound_height", "ball_probe": "bouncer", "obstacle": "anvil", "tolerance": "scheme_bound"},
            {"type": "energy_balance", "tolerance": 0.01},
        ],
    },
    # All codes with velocity Verlet and the half-step dashpot velocity; the single drop is placed by
    # Algorithm 2 before the first step and handed to the reference codes as a ball at that state.
    "compare": {
        "base": dict(REFERENCE_SCHEME, output={"dump_interval_steps": 1}),
        "variants": {"contact_end": CONTACT_END},
        "checks": [
            {"type": "first_contact", "drops_probe": "drops", "drop": 0, "obstacle": "high",
             "twin": {"pair_probe": "twin_high", "other_pair_probes": ["twin_low"]}},
            {"type": "rebound_height", "ball_probe": "bouncer", "obstacle": "anvil", "tolerance": "scheme_bound"},
            {"type": "energy_balance", "tolerance": 0.01},
        ],
        "between_codes": [
            {"quantity": "integrated_contact_height", "tolerance": 1e-5, "tolerance_source": SAME_SCHEME},
            {"quantity": "rebound_height", "tolerance": 1e-5, "tolerance_source": SAME_SCHEME},
        ],
        "ledger_reconstruction_tolerance": 0.01,
        "time_limit_s": 300,
    },
}
write_case(case, "cases/free_fall_contact.json")
