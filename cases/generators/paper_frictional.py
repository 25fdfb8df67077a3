#!/usr/bin/env python3
"""The paper-size silo cases (silo.py paper OUTDIR, about 22,000 balls) with frictional grains
(silo_friction.py: mu 0.5, wall 0.3, a history spring): OUTDIR/silo_{fill,discharge,closure}.json
are read and OUTDIR/silo_{fill,discharge,closure}_frictional.json written, everything else the same,
so that each stands beside its frictionless run in reports/paper_size.md. Their comparisons across
codes keep the paper cases' tolerances without a seed-scatter source (none was measured at this
size): reported rows.
Run from the repository root: python3 cases/generators/paper_frictional.py OUTDIR (tools/paper_size.sh)"""
import json
import sys

from common import write_case
from silo_friction import with_friction

out = sys.argv[1]
for stage in ("fill", "discharge", "closure"):
    with open("%s/silo_%s.json" % (out, stage)) as f:
        case = json.load(f)
    case["name"] += "_frictional"
    case["description"] = ("With frictional grains (mu 0.5, wall 0.3, history spring), otherwise the paper-size case: "
                           + case["description"])
    write_case(with_friction(case), "%s/silo_%s_frictional.json" % (out, stage))
