#!/usr/bin/env python3
"""The frictional discharge with the tangential dashpot off in every code. LIGGGHTS caps the
tangential spring alone and adds its dashpot on top while a contact sticks, where silodem and LAMMPS
cap the sum (docs/reference-codes.md); with rho_gamma = 0 the three laws are the same. Written when
LIGGGHTS's rate seemed 4.4 % low; that gap lies within silodem's six realisations and is withdrawn
(reports/frictional_silo.md), so this isolates the law's difference, should a discharge show one.

Writes OUT/silo_discharge_frictional.json: the case with tangential_damping_ratio 0 for grain and
wall in the compared runs (compare.base; the shared fill is the case's own) and without seeds.
    /usr/bin/python3 reports/experiments/discharge_without_tangential_damping.py /tmp/exp
    build/silodem compare /tmp/exp/silo_discharge_frictional.json --codes silodem,lammps,liggghts \
        --jobs 2 --out /tmp/exp/cmp          # about 1.5 h on 2 cores
"""
import json
import pathlib
import sys

from new_case_file import write_new

out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "/tmp/exp")
case = json.loads(pathlib.Path("cases/silo_discharge_frictional.json").read_text())
case["compare"].pop("seeds", None)
case["compare"]["base"]["materials"] = {
    name: dict(case["materials"][name], tangential_damping_ratio=0.0) for name in ("grain", "wall")}
write_new(out, "silo_discharge_frictional.json", case)
