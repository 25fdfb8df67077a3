#!/usr/bin/env python3
"""Writes cases/silo_closure_frictional.json: the sudden gate closure of cases/silo_closure.json
(written by silo.py; run it first) with frictional grains — Coulomb friction mu = 0.5 between
grains, 0.3 against the wall balls, a history spring (the frictional silo's material,
silo_frictional.py) — and everything else the same: the same grains, hopper, outlet, stages and
probes, so that its peak overpressure, where and when, stands beside the frictionless result.
Its comparison across codes is the frictionless case's, with the history spring in every code and
two more packings (seeds) whose scatter is the yardstick of the differences between codes.
Run from the repository root: python3 cases/generators/silo_closure_frictional.py
"""
import json

from common import between_from_scatter, write_case
from silo_friction import with_friction

with open("cases/silo_closure.json") as f:
    case = json.load(f)
case["name"] = "silo_closure_frictional"
case["description"] = ("Sudden gate closure with frictional grains (mu 0.5, wall 0.3, history spring): the silo_closure "
                       "case otherwise unchanged; the peak overpressure on hopper and mantle, where and when, beside the "
                       "frictionless case's")
with_friction(case)
compare = case["compare"]
compare["seeds"] = [2003, 2004, 2005, 2006]
# The scatter of silodem's five packings (compare's rows "silodem seeds"); the hopper's and the
# mantle's largest mean ratio scatter alike (0.142, 0.151 of the mean), the larger is taken.
MEASURED = ("silodem compare cases/silo_closure_frictional.json (2026-12-04, the commit after f386ab3), rows "
            "'silodem seeds', seeds 2002-2006")
compare["between_codes"] = [
    between_from_scatter("closure_mean_post/pre_pressure", 0.151, 5, MEASURED),
    between_from_scatter("energy_kinetic", 0.0207, 5, MEASURED, relative_to="absolute"),
    between_from_scatter("energy_gravitational_change", 0.110, 5, MEASURED, relative_to="absolute"),
]
write_case(case, "cases/silo_closure_frictional.json")
