#!/usr/bin/env python3
"""Experiment (not part of the suite): does the frictional discharge silo's wall lower the flow of
its largest outlet? cases/silo_discharge_frictional.json (D = 0.14 m = 25 d) rebuilt with a wider
cylinder (D given, default 0.24 m: L = D - D_0 > 30 d at D_0 = 10 d, Mankoc et al. 2007's stricter
condition) and the same fill height, one outlet, run by `silodem verify` into OUT. Compare its
mass_flow_rate row with the narrow silo's (reports/frictional_silo.md).
Usage, from the repository root:
  /usr/bin/python3 reports/experiments/beverloo_wall_effect.py OUT [D] [OUTLET_LABEL]
"""
import json
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "cases", "generators"))
from sediment import lattice_fill  # noqa: E402

out = sys.argv[1]
D = float(sys.argv[2]) if len(sys.argv) > 2 else 0.24
label = sys.argv[3] if len(sys.argv) > 3 else "D0_10.0_d"
case = json.load(open("cases/silo_discharge_frictional.json"))
R_BALL, R_WALL, SPACING = (0.0025, 0.003), 0.003, 0.0035
inner = D / 2 - R_BALL[1] - R_WALL
patch = case["verify"]["variants"]["outlet"][label]
walls = patch["walls"]
for w in walls:
    if w["name"] == "mantle":
        w["diameter"] = D
    if w["name"] == "floor":
        w["diameter"] = D + 2 * SPACING
case["walls"] = walls
case["name"] = "silo_discharge_frictional_wide"
case["balls"] = lattice_fill(2002, inner + 0.0005, R_BALL, 0.0065, 0.0042, 0.006, 0.21, 1e-4)
half = inner / math.sqrt(2) - 0.001
case["drops"]["inlet"] = {"x": [-half, half], "y": [-half, half]}
case["verify"] = {"variants": {"outlet": {label: {}}},
                  "checks": [c for c in case["verify"]["checks"] if c["type"] == "beverloo"]}
case.pop("compare", None)
# A folder of its own: nothing this script did not make is overwritten.
path = os.path.join(tempfile.mkdtemp(prefix="beverloo_wall_effect_"), "silo_discharge_frictional_wide.json")
with open(path, "w") as f:
    json.dump(case, f)
print("%d grains in D = %.3f m, outlet %s -> %s" % (len(case["balls"]), D, label, out), flush=True)
sys.exit(subprocess.call(["build/silodem", "verify", path, "--out", out, "--threads", "1", "--quiet"]))
