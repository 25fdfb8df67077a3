#!/usr/bin/env python3
"""Writes cases/silo_closure_frictional.json: the sudden gate closure of cases/silo_closure.json
(written by silo.py; run it first) with frictional grains — Coulomb friction mu = 0.5 between
grains, 0.3 against the wall balls, a history spring (the frictional silo's material,
silo_frictional.py) — and everything else the same: the same grains, hopper, outlet, stages and
probes, so that its peak overpressure, where and when, stands beside the frictionless result
(verify only; the frictionless case keeps the comparison across codes).
Run from the repository root: python3 cases/generators/silo_closure_frictional.py
"""
import json

from common import write_case

with open("cases/silo_closure.json") as f:
    case = json.load(f)
case["name"] = "silo_closure_frictional"
case["description"] = ("Sudden gate closure with frictional grains (mu 0.5, wall 0.3, history spring): the silo_closure "
                       "case otherwise unchanged; the peak overpressure on hopper and mantle, where and when, beside the "
                       "frictionless case's")
case["contact"] = {"tangential": "linear_history"}
case["materials"]["grain"].update({"friction": 0.5, "tangential_damping_ratio": 0.5})
case["materials"]["wall"].update({"friction": 0.0, "tangential_damping_ratio": 0.5})
case["material_pairs"] = [{"materials": ["grain", "wall"], "friction": 0.3}]
case.pop("compare", None)
write_case(case, "cases/silo_closure_frictional.json")
