#!/usr/bin/env python3
"""Writes cases/equilibrium_column.json: seed 001's own test (Bogulsky & Bogulskaya 2011; the notes'
case V1, docs/theory.md section 7.8). A column of 40 discs (planar mode, disc inertia) stands on a
rigid floor at its exact static overlaps, reading A of the seed's law: each disc a shell of stiffness
m g / eps, so a disc pair has m g / (2 eps) and a disc on the rigid floor m g / eps, both of frequency
omega0 = sqrt(g / eps) = 495 rad/s. At the seed's dt = 2 ms its explicit midpoint scheme keeps the
column at rest only with an artificial viscosity inside [283, 1000] 1/s (the column's top mode is
700 rad/s); velocity Verlet needs none (omega_max dt = 1.4 < 2). At rest to round-off, the floor
carries the weight exactly; any growth of the round-off would show in its load.
Run from the repository root: python3 cases/generators/equilibrium_column.py
"""
import math

from common import write_case

N, R, G = 40, 0.004, 9.81
OMEGA0 = 495.2                    # sqrt(g / eps): the seed's contact frequency
EPS = G / OMEGA0 ** 2             # shell compression under one weight, m (0.01 r)
DENSITY = 2500.0
MASS = DENSITY * 4.0 / 3.0 * math.pi * R ** 3
K_SHELL = MASS * G / EPS          # per disc; a pair in series: m g / (2 eps)
K_FLOOR = 1e6 * K_SHELL           # rigid: the disc–floor pair is m g / eps to 1e-6

# Disc i (from the bottom) carries the N - i discs above it and itself on its lower contact.
z = R - N * MASS * G / (K_SHELL * K_FLOOR / (K_SHELL + K_FLOOR))
balls = [{"id": "floor", "material": "floor", "radius": R, "position": [0.0, 0.0, -R], "fixed": True}]
for i in range(N):
    if i > 0:
        z += 2.0 * R - (N - i) * MASS * G / (0.5 * K_SHELL)
    balls.append({"id": "d%d" % i, "material": "disc", "radius": R, "position": [0.0, 0.0, z]})

VISCOSITY_INSIDE = 300.0
case = {
    "format": "silodem-case/1",
    "name": "equilibrium_column",
    "description": "Seed 001's equilibrium column: 40 discs on a rigid floor at their static overlaps, the seed's "
                   "midpoint scheme at dt = 2 ms with a viscosity inside its stability window, and velocity Verlet.",
    "dimension": 2,
    "grain_inertia": "disc",
    "materials": {"disc": {"density": DENSITY, "stiffness": K_SHELL, "damping": 0.0},
                  "floor": {"density": DENSITY, "stiffness": K_FLOOR, "damping": 0.0}},
    "balls": balls,
    "integrator": {"scheme": "runge_kutta_midpoint", "viscosity": VISCOSITY_INSIDE},
    "time": {"dt": 0.002, "duration": 10.0},
    # The seed's law compresses the bottom pair by 78 eps = 0.78 r (the notes' A13): above the default guard.
    "guards": {"max_overlap_ratio": 0.9},
    "output": {"series_interval": 0.1, "probes": [{"type": "ball", "name": "top", "balls": ["d%d" % (N - 1)]}]},
    "verify": {
        "variants": {"integrator": {
            "midpoint_viscosity_300": {},
            "velocity_verlet": {"integrator": {"scheme": "velocity_verlet", "viscosity": None}},
        }},
        "checks": [
            {"type": "static_balance", "tolerance": 1e-9, "tolerance_source": {
                "type": "scheme_bound",
                "derivation": "the column starts at its exact static state, a fixed point of both schemes to "
                              "round-off (1e-16 of the forces); inside the midpoint scheme's viscosity window (283 to "
                              "1000 1/s at dt = 2 ms, docs/theory.md 7.8) and below velocity Verlet's limit (omega_max "
                              "dt = 1.4 < 2) round-off decays, so the floor's load stays the weight to about 1e-13; "
                              "below the window it grows by up to 1.40 per step and passes 1e-9 within 100 steps"}},
        ],
    },
}

if __name__ == "__main__":
    write_case(case, "cases/equilibrium_column.json")
