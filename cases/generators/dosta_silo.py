#!/usr/bin/env python3
"""Writes the silo discharge of the multi-code benchmark of Dosta et al. (2024), docs/dosta-benchmark.md.

Spheres of d = 4 mm (material M1 or M2, Hertz with Mindlin friction) fill a cylinder on a 45 degree
conical hopper with smooth steel walls; at T_OPEN the gate under the orifice is taken away and a
grain 2 cm below the orifice is removed. The benchmark's own walls (the triangulated files of the
MercuryDPM driver) are a cylinder of radius 0.102 m and orifices of radius 22 or 32 mm; its text and
MercuryDPM's smooth-wall variant say 0.1 m and 20 or 30 mm, one grain radius less
(docs/dosta-benchmark.md, "Where the sources disagree"). `--walls` chooses; the default is the
triangulated walls' size, which the codes read.

The benchmark starts from a supplied packing of 100,000 grains; those files are not public here,
so the grains sediment from a loose lattice behind the closed gate and settle until T_OPEN.

  /usr/bin/python3 cases/generators/dosta_silo.py                       # cases/dosta_silo.json (reduced, CI)
  /usr/bin/python3 cases/generators/dosta_silo.py --size full --out F   # the paper's size (not committed)
Run from the repository root.
"""
import argparse
import math

from common import between_from_scatter, write_case

from sediment import lattice_fill

R = 0.002                                  # grain radius (d = 4 mm, monodisperse)
# (orifice radius, orifice height) of the triangulated walls; the nominal sizes are 2 mm less.
ORIFICE = {"small": (0.022, -0.0593008), "large": (0.032, -0.0554222)}
CYLINDER = {"stl": 0.102, "nominal": 0.1}
SILO_HEIGHT = 0.3                          # the cylinder's height above the transition (the benchmark's)
DELETE_BELOW = 0.02                        # grains 2 cm below the orifice are removed
MATERIALS = {  # Dosta et al. (2024), table of the silo case (MercuryDPM driver MercuryOS.h)
    "M1": {"density": 2500.0, "youngs_modulus": 1.0e9, "restitution": 0.5, "friction": 0.3, "dt": 1.5e-6},
    "M2": {"density": 2000.0, "youngs_modulus": 0.5e9, "restitution": 0.4, "friction": 0.4, "dt": 2.0e-6},
}
NU = 0.2                                   # Poisson's ratio of M1, M2 and steel
# Tangential dashpot of the usual Hertz-Mindlin law (EDEM, LIGGGHTS): gamma_t/gamma_n = sqrt(S_t/S_n)
# = sqrt(4 G*/E*) = sqrt(2 (1 - nu)/(2 - nu)) when every material has the same nu.
RHO_GAMMA = math.sqrt(2 * (1 - NU) / (2 - NU))
SIZES = {
    # grains, cylinder radius (None: the benchmark's), lattice cell and layer spacing, time to open, steady window
    "reduced": {"grains": 1600, "cylinder": 0.04, "height": 0.08, "cell": 0.0046, "dz": 0.0044, "t_open": 0.12, "run": 0.13,
                "steady_after": 0.07},
    "full": {"grains": 100000, "cylinder": None, "height": SILO_HEIGHT, "cell": 0.0044, "dz": 0.0042, "t_open": 0.35, "run": 5.0,
             "steady_after": 0.1},
}
DISCHARGE_MEASURED = ("silodem compare of cases/dosta_silo.json with compare.seeds 2003-2007, 2026-12-05: rows 'silodem "
                      "seeds' (mass flow 0.7347 kg/s +/- 1.58 %; the cylinder was then 0.3 m high, the fill 3 cm above "
                      "the transition: the height does not enter); reports/dosta_benchmark.md")
# The scatter of the steady rate at the paper's size: the standard deviation of the twelve 0.1 s
# windows of one discharge over 0.1-1.3 s (0.891 kg/s, sd 0.0094). The flow piece's window (0.104 s
# at the defaults) is no shorter than 0.1 s, so this bounds its scatter from above.
FULL_WINDOW_SCATTER = 0.0106
FULL_MEASURED = ("tools/dosta_full.sh --duration 1.5, silodem's discharge of 100,000 grains of M1 to 1.33 s, 2026-12-05 to 07: "
                 "twelve 0.1 s windows over 0.1-1.3 s, 0.891 kg/s +/- 1.06 % (sd); reports/dosta_benchmark.md")

parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
parser.add_argument("--size", choices=SIZES, default="reduced")
parser.add_argument("--orifice", choices=ORIFICE, default="small")
parser.add_argument("--material", choices=MATERIALS, default="M1")
parser.add_argument("--walls", choices=CYLINDER, default="stl")
parser.add_argument("--stage", choices=("fill", "discharge", "speed", "flow"), help="the paper's size in two cases: the fill "
                    "settled behind the gate, then the discharge from its state.json (--state); and the speed "
                    "piece of the discharge in every code and the flow piece, a steady flow in every code (each its own "
                    "case: the discharge's checkpoints stay valid)")
parser.add_argument("--state", help="the settled fill's state.json (--stage discharge, speed, flow)")
parser.add_argument("--speed-piece", type=float, default=0.01,
                    help="simulated seconds each code runs in the discharge's compare section (its speed)")
parser.add_argument("--flow-start", type=float, default=0.099,
                    help="--stage flow: every code continues silodem's discharge from this time (s, steady flow)")
parser.add_argument("--flow-piece", type=float, default=0.114,
                    help="--stage flow: the simulated seconds every code runs from --flow-start")
parser.add_argument("--duration", type=float, help="the discharge's simulated time (default the benchmark's 5 s)")
parser.add_argument("--grains", type=int, help="--size reduced: this many grains instead of 1,600 (a deeper fill)")
parser.add_argument("--cylinder", type=float, help="--size reduced: this cylinder radius (m) instead of 0.04")
parser.add_argument("--run", type=float, help="--size reduced: the simulated seconds after the gate opens instead of 0.13")
parser.add_argument("--out", default="cases/dosta_silo.json")
args = parser.parse_args()
if (args.size == "full") != (args.stage is not None) or (args.stage in ("discharge", "speed", "flow")) != (args.state is not None):
    parser.error("--size full needs --stage; --stage discharge, speed and flow need --state (and only they)")

size = dict(SIZES[args.size])
if (args.grains or args.cylinder or args.run) and args.size != "reduced":
    parser.error("--grains, --cylinder and --run change the reduced size only")
# The reduced silo's rate against the paper's size (reports/dosta_benchmark.md): its fill height
# and its width, varied one at a time.
size["grains"] = args.grains or size["grains"]
size["cylinder"] = args.cylinder or size["cylinder"]
size["run"] = args.run or size["run"]
if args.grains:
    size["height"] = SILO_HEIGHT
mat = MATERIALS[args.material]
shrink = CYLINDER["stl"] - CYLINDER[args.walls]           # 0 or one grain radius
r_o, z_o = ORIFICE[args.orifice][0] - shrink, ORIFICE[args.orifice][1]
R_cyl = (size["cylinder"] or CYLINDER["stl"]) - shrink
z_t = z_o + (R_cyl - r_o)                                  # 45 degrees: the transition
z_top = z_t + size["height"]
T_OPEN, T_END = size["t_open"], size["t_open"] + size["run"]
T_STEADY = T_OPEN + size["steady_after"]
# The gate's balls (gaps of about 2 mm hold 4 mm grains) draw their radii from the seed, so each
# seed of compare.seeds settles another packing.
GATE_R, GATE_SPACING = (0.0019, 0.0021), 0.003


def reach(z):
    """How far from the axis a lattice centre may lie at height z: inside the cone and the cylinder."""
    wall = min(R_cyl, r_o + (z - z_o))
    return wall - R * math.sqrt(2) - 0.0005                # the cone's normal gap is r sqrt(2) horizontally


balls = []
z_stop = z_o + 2 * R
while len(balls) < size["grains"]:                         # the lowest layers up to the wanted count
    z_stop += size["dz"]
    balls = lattice_fill(2002, reach, (R, R), size["cell"], size["dz"], z_o + R + 0.001, z_stop, 1e-4)
balls = balls[:size["grains"]]
if balls[-1]["position"][2] + R > z_top:
    raise SystemExit("the lattice does not fit below the silo's top")

base = "reduced" if args.size == "reduced" else "the paper's size"
case = {
    "format": "silodem-case/1",
    "name": "dosta_silo" if args.size == "reduced" else "dosta_silo_full",
    "description": "Dosta et al. (2024) silo discharge, %s: %d grains of %s (d 4 mm, Hertz-Mindlin) in a cylinder of "
                   "R = %.3f m on a 45 degree hopper, orifice radius %.3f m, smooth steel walls; gate taken away at "
                   "%.2f s, grains removed 2 cm below the orifice" % (base, len(balls), args.material, R_cyl, r_o, T_OPEN),
    "seed": 2002,
    "gravity": [0.0, 0.0, -9.8],
    "contact": {"normal": "hertz", "tangential": "mindlin"},
    "materials": {
        "grain": {"density": mat["density"], "youngs_modulus": mat["youngs_modulus"], "poisson_ratio": NU,
                  "restitution": mat["restitution"], "friction": mat["friction"],
                  "tangential_damping_ratio": RHO_GAMMA},
        "steel": {"density": 7200.0, "youngs_modulus": 210.0e9, "poisson_ratio": NU, "restitution": 0.6,
                  "friction": 0.5, "tangential_damping_ratio": RHO_GAMMA},
    },
    "material_pairs": [{"materials": ["grain", "steel"], "restitution": 0.4, "friction": 0.2}],
    "surfaces": [{"name": "silo", "material": "steel", "axis": [0.0, 0.0],
                  "profile": [[R_cyl, z_top], [R_cyl, z_t], [r_o, z_o]]}],
    "walls": [{"name": "gate", "type": "disk", "material": "steel", "radius": list(GATE_R),
               "spacing": GATE_SPACING, "centre": [0.0, 0.0, z_o - GATE_R[1]], "diameter": 2 * r_o + 2 * GATE_SPACING}],
    "balls": balls,
    "stages": {"outflow": {"below_z": z_o - DELETE_BELOW, "mode": "remove", "every_steps": 200},
               "events": [{"time": T_OPEN, "type": "open_outlet", "wall": "gate"}]},
    "integrator": {"scheme": "velocity_verlet", "dashpot_velocity": "half_step"},
    "time": {"dt": mat["dt"], "duration": T_END},
    "output": {"series_interval": 0.01, "probes": [{"type": "outflow", "name": "outflow"}]},
}
BULK_DENSITY = 0.6 * mat["density"]


def beverloo(from_time):
    return {"type": "beverloo", "outflow_probe": "outflow", "from_time": from_time, "bulk_density": BULK_DENSITY,
            "outlet_wall": "silo_1", "grain_diameter": 2 * R, "tolerance": 0.2, "max_scatter": 0.2}


if args.size == "reduced":
    case["verify"] = {"checks": [beverloo(T_STEADY), {"type": "energy_balance", "tolerance": 0.05}]}
    # Every code from silodem's settled fill just before the gate opens (approach b).
    case["compare"] = {
        "base": {"contact": {"clamp_tensile_force": True}, "output": {"dump_interval_steps": 2000}},
        "from_state_at": T_OPEN - 0.01,
        "checks": [beverloo(T_STEADY)],
        "seeds": [2003, 2004],
        "between_codes": [between_from_scatter("mass_flow_rate", 0.0158, 6, DISCHARGE_MEASURED)],
        "time_limit_s": 1800,
    }
elif args.stage == "fill":
    # The fill alone: settled behind the gate; a run of hours, checkpointed every 10 min.
    case["name"] = "dosta_fill"
    case["stages"] = {"outflow": {"below_z": z_o - DELETE_BELOW, "mode": "remove", "every_steps": 200}}
    case["time"] = {"dt": 2 * mat["dt"], "duration": T_OPEN}   # preparation only: twice the benchmark's step
    case["checkpoint"] = {"interval_seconds": 600}
    case["output"]["probes"] = []
else:
    # The discharge from the settled fill, as the benchmark starts: the outlet open at t = 0.
    import json
    with open(args.state) as f:
        settled = json.load(f)["balls"]
    case["name"] = "dosta_discharge"
    case["balls"] = [b for b in settled if b["material"] == "grain"]
    del case["walls"]
    case["stages"] = {"outflow": {"below_z": z_o - DELETE_BELOW, "mode": "remove", "every_steps": 200}}
    case["time"]["duration"] = args.duration or size["run"]
    case["checkpoint"] = {"interval_seconds": 600}
    steady = size["steady_after"]
    case["verify"] = {"checks": [beverloo(steady), {"type": "energy_balance", "tolerance": 0.05}]}
    if args.stage == "speed":
        # Each code's speed on this scene, in one run: every code continues silodem's state at a
        # third of the piece for the piece (the flow's start, not its steady part: reported only).
        # Dumps every third of the piece: the codes write a frame only on multiples of the
        # interval, so the piece starts and ends on one (a start at 1 ms = 666.7 steps gave none).
        third = max(1, round(args.speed_piece / 3 / mat["dt"]))
        case["name"] = "dosta_speed"
        del case["checkpoint"]
        case["time"]["duration"] = 4 * third * mat["dt"]
        case["compare"] = {
            "base": {"contact": {"clamp_tensile_force": True}, "output": {"dump_interval_steps": third}},
            "from_state_at": third * mat["dt"],
            "checks": [{"type": "energy_terms"}],
            "between_codes": [{"quantity": "energy_kinetic", "relative_to": "absolute",
                               "report": "the speed piece is the flow's start, not a steady flow"}],
            "time_limit_s": 36000,
        }
    elif args.stage == "flow":
        # The steady flow in every code: each continues silodem's discharge at --flow-start for
        # --flow-piece s, and the mass flows after a 10 ms settling of the new contacts (the shared
        # state carries no tangential history) are judged against each other.
        every = 2000                                       # dump steps (3 ms for M1): LAMMPS's outflow is read from them
        start = max(1, round(args.flow_start / mat["dt"] / every)) * every
        piece = max(1, round(args.flow_piece / mat["dt"] / every)) * every
        case["name"] = "dosta_flow"
        del case["checkpoint"]
        case["time"]["duration"] = (start + piece) * mat["dt"]
        case["verify"] = {"checks": [beverloo(start * mat["dt"] + 0.01)]}
        case["compare"] = {
            "base": {"contact": {"clamp_tensile_force": True}, "output": {"dump_interval_steps": every}},
            "from_state_at": start * mat["dt"],
            "checks": [beverloo(start * mat["dt"] + 0.01)],
            "between_codes": [between_from_scatter("mass_flow_rate", FULL_WINDOW_SCATTER, 12, FULL_MEASURED)],
            "time_limit_s": 36000,
        }
write_case(case, args.out)
print("%s: %d grains, cylinder R %.3f m, orifice r %.3f m at z %.4f, transition z %.4f, top grain %.3f m"
      % (args.out, len(case["balls"]), R_cyl, r_o, z_o, z_t, max(b["position"][2] for b in case["balls"])))
