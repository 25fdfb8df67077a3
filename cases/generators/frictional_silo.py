"""The frictional silo's grains and wall, shared by its virtual material tests (lateral_pressure_ratio,
wall_friction) and the column they predict (janssen_frictional): the paper's silo grains (r = 4-5 mm,
k = 1e5 N/m, e = 0.3) with Coulomb friction and a history spring, the Janssen column's wall balls
(r = 4-5 mm, 6 mm apart) of a wall material with friction 0.3 against the grains, and the axes every
material test sweeps (EN 1991-4 Annex C: mu = 0.3 and 0.5, with and without rolling resistance, three
packings)."""
from sediment import lattice_fill

R_BALL = (0.004, 0.005)     # mobile radii (1), the Janssen column's
R_WALL = (0.004, 0.005)     # wall-ball radii
SPACING = 0.006             # wall-ball centre spacing
LATTICE, LAYER = 0.0105, 0.007
WALL_FRICTION = 0.3         # grain-wall contact friction of the wall material

GRAIN = {"density": 2500.0, "stiffness": 1.0e5, "restitution": 0.3, "reference_radius": 0.0045,
         "tangential_damping_ratio": 0.5}
WALL = {"density": 7800.0, "stiffness": 1.0e5, "damping": 2.0, "friction": 0.0, "tangential_damping_ratio": 0.5}
EPSD = {"rolling_friction": 0.05, "rolling_damping_ratio": 0.3}

VARIANTS = {
    "mu": {m: {"materials": {"grain": {"friction": float(m)}}} for m in ("0.3", "0.5")},
    "rolling": {"none": {}, "epsd": {"contact": {"rolling": "epsd"}, "materials": {"grain": EPSD, "wall": EPSD}}},
    "seed": {str(s): {"seed": s} for s in (2002, 2003, 2004)},
}


def materials(grain_friction=0.5):
    return {"grain": dict(GRAIN, friction=grain_friction), "wall": WALL}


def column_walls(diameter, height, z_base=0.0):
    """A cylinder of wall balls from z_base on a disk at z = 0 that reaches under it."""
    return [
        {"name": "mantle", "type": "cylinder", "material": "wall", "radius": list(R_WALL), "spacing": SPACING,
         "centre": [0.0, 0.0, z_base], "diameter": diameter, "height": height},
        {"name": "bottom", "type": "disk", "material": "wall", "radius": list(R_WALL), "spacing": SPACING,
         "centre": [0.0, 0.0, 0.0], "diameter": diameter + 2 * SPACING},
    ]


def column_fill(diameter, z_top, seed=2002):
    """The loose lattice that sediments into the column (centres within the wall's reach)."""
    reach = diameter / 2 - R_BALL[1] - R_WALL[1] + 0.0005
    return lattice_fill(seed, reach, R_BALL, LATTICE, LAYER, 0.01, z_top, 2e-4)


def column_case(name, description, diameter, wall_top, lattice_top, grain_wall_friction, below=0.0):
    """The scene every frictional-silo column shares: the grains (mu 0.5, varied by the axes) sedimenting
    from a loose lattice into a cylinder on a floor, the grain-wall friction given, velocity Verlet at
    0.04 t_c. The mantle reaches `below` under the floor when it is to slide up past the column."""
    return {
        "format": "silodem-case/1",
        "name": name,
        "description": description,
        "seed": 2002,
        "gravity": [0.0, 0.0, -9.81],
        "contact": {"tangential": "linear_history"},
        "materials": materials(0.5),
        "material_pairs": [{"materials": ["grain", "wall"], "friction": grain_wall_friction}],
        "walls": column_walls(diameter, wall_top + below, z_base=-below),
        "balls": column_fill(diameter, lattice_top),
        "integrator": {"scheme": "velocity_verlet"},
    }
