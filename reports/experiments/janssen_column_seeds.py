#!/usr/bin/env python3
"""The predicted Janssen column's scatter between packings (reports/frictional_silo.md): writes
OUT/janssen_frictional_seeds.json, cases/janssen_frictional.json at mu = 0.5 with seeds 2003 and
2004 as verify variants (another wall roughness each, so another packing), without compare.
--unjudged leaves out the checks that take the material tests (janssen_prediction), so it runs on
its own; a later verify of the full file with --resume keeps those runs and judges them (only the
judging changed).
    /usr/bin/python3 reports/experiments/janssen_column_seeds.py /tmp/jfs --unjudged
    build/silodem verify /tmp/jfs/janssen_frictional_seeds.json --out /tmp/jfs/verify --jobs 1 --threads 1
                                                   # 2 runs, about 30 min each beside two other jobs
"""
import json
import pathlib
import sys

from new_case_file import write_new

args = [a for a in sys.argv[1:] if not a.startswith("--")]
out = pathlib.Path(args[0] if args else "/tmp/jfs")
case = json.loads(pathlib.Path("cases/janssen_frictional.json").read_text())
case["name"] = "janssen_frictional_seeds"
case.pop("compare", None)
case["verify"]["variants"] = {"mu": {"0.5": {"materials": {"grain": {"friction": 0.5}}}},
                              "seed": {"2003": {"seed": 2003}, "2004": {"seed": 2004}}}
if "--unjudged" in sys.argv:
    case["verify"]["checks"] = [c for c in case["verify"]["checks"] if c["type"] != "janssen_prediction"]
write_new(out, "janssen_frictional_seeds.json", case)
