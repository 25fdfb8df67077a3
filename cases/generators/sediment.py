"""Shared by the case generators: a loose fill for sedimentation (Landry et al. 2003) — balls of
random radii (1) on square lattice layers inside a cylinder, alternate layers shifted by half a
cell, with a small random jitter; under gravity the lattice collapses into a random packing."""
import math
import random


def lattice_fill(seed, reach, radii, cell, layer_dz, z_start, z_stop, jitter):
    """Balls with centres within `reach` of the axis (a number, or a function of the layer's z for
    a hopper), layers from z_start below z_stop."""
    rng = random.Random(seed)
    balls = []
    z, layer = z_start, 0
    while z < z_stop:
        layer_reach = reach(z) if callable(reach) else reach
        n = int(layer_reach // cell) + 1
        shift = 0.5 * cell * (layer % 2)
        for i in range(-n, n + 1):
            for j in range(-n, n + 1):
                x = i * cell + shift + rng.uniform(-jitter, jitter)
                y = j * cell + shift + rng.uniform(-jitter, jitter)
                if math.hypot(x, y) <= layer_reach - 2e-4:
                    balls.append({"id": "g%d" % len(balls), "material": "grain",
                                  "radius": round(rng.uniform(*radii), 7), "position": [x, y, z]})
        z += layer_dz
        layer += 1
    return balls
