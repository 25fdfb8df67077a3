#!/usr/bin/python3
"""Velocity Verlet on one head-on clamped Kelvin–Voigt collision, in the pair's own coordinate,
with each choice of the velocity the dashpot sees — a model for trying a scheme before it goes
into the solver (reports/perf_experiments.md, eighth session).

Units: m_eff = k = 1 (ω = 1), c = 2ζ, Δt = π/divisor (t_c/divisor of the undamped pair, as in
cases/collision_restitution.json). The touch falls at (p + 1/2)/phases of a step, p = 0..phases-1.
The onset correction is the solver's (forces/force_field.cpp onset_scale, clamped law): the
dashpot is scaled by 1/2 + δ/(δ̇ Δt) in the step that first sees the touch.

Dashpot velocities:
  predicted    v½ + ½Δt a_n (the solver's default)
  half_step    v½ (LAMMPS, LIGGGHTS, YADE)
  extrapolated v½ + ½Δt a_n + ½Δt (a_n − a_{n−1}) (second-order in the velocity; tried here only)

Prints, per damping ratio and step, the range of e/e_exact − 1 over the phases (e_exact:
Schwager & Pöschel's closed form, docs/theory.md §1b), and the largest stable Ω = ωΔt of the undamped-
spring-plus-dashpot step (spectral radius of the 4×4 step matrix ≤ 1; found by bisection).
Reproduces the solver's figures in reports/work_precision.md: predicted, onset-corrected, t_c/50,
ζ = 0.9: worst 4.50e-3; plain 5.38e-2.

Usage: tools/dashpot_velocity_model.py   (needs numpy for the stability column)
"""
import math

ZETAS = (0.1, 0.3, 0.5, 0.7, 0.9)


def exact_clamped_e(zeta):
    w = math.sqrt(1.0 - zeta * zeta)
    wt = math.atan(-2.0 * zeta * w / (w * w - zeta * zeta))
    if w * w - zeta * zeta > 0.0:
        wt += math.pi
    return math.exp(-zeta * wt / w)


def dashpot_velocity(mode, v_half, a, a_prev, dt):
    if mode == "half_step":
        return v_half
    if mode == "predicted":
        return v_half + 0.5 * dt * a
    return v_half + 0.5 * dt * a + 0.5 * dt * (a - a_prev)


def collide(zeta, dt, phase, mode, onset=True):
    """Restitution of one collision; the approach speed is 1."""
    c, d, u, a, a_prev, touched = 2.0 * zeta, -dt * (3.0 + phase), 1.0, 0.0, 0.0, False
    for _ in range(1000000):
        v_half = u + 0.5 * dt * a
        d += dt * v_half
        ud = dashpot_velocity(mode, v_half, a, a_prev, dt)
        f = 0.0
        if d > 0.0:
            scale = 0.5 + d / (ud * dt) if onset and ud > 0.0 and d < ud * dt * (1.0 + 1e-9) else 1.0
            f = max(0.0, d + scale * c * ud)
            touched = True
        a_prev, a = a, -f
        u = v_half + 0.5 * dt * a
        if touched and f == 0.0 and d < 0.0:
            return -u
    raise RuntimeError("no separation")


def stable_limit(zeta, mode):
    import numpy as np

    def radius(dt):
        def step(s):
            x, v, a, a_prev = s
            v_half = v + 0.5 * dt * a
            x2 = x + dt * v_half
            a2 = -(x2 + 2.0 * zeta * dashpot_velocity(mode, v_half, a, a_prev, dt))
            return np.array([x2, v_half + 0.5 * dt * a2, a2, a])
        return max(abs(np.linalg.eigvals(np.column_stack([step(e) for e in np.eye(4)]))))
    lo, hi = 1e-3, 4.0
    for _ in range(50):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if radius(mid) <= 1.0 + 1e-12 else (lo, mid)
    return lo


def main(phases=8):
    for mode in ("predicted", "half_step", "extrapolated"):
        for zeta in ZETAS:
            e0 = exact_clamped_e(zeta)
            cells = []
            for divisor in (25, 50, 100):
                rel = [collide(zeta, math.pi / divisor, (p + 0.5) / phases, mode) / e0 - 1.0 for p in range(phases)]
                cells.append("t_c/%d %+.2e..%+.2e" % (divisor, min(rel), max(rel)))
            try:
                limit = "%.3f" % stable_limit(zeta, mode)
            except ImportError:
                limit = "n/a"
            print("%-12s zeta %.1f  %s  stable Omega < %s" % (mode, zeta, "  ".join(cells), limit))


if __name__ == "__main__":
    main()
