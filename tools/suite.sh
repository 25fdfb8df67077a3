#!/usr/bin/env bash
# The main job: set up, build, then
#   1. verify: every case in cases/ in silodem alone, every integrator and time step of its
#      "verify" section, against theory          -> reports/verification.md, results/verify/,
#      and figures                                -> reports/figures/*.png
#   2. compare: every case's "compare" section in silodem, LAMMPS, LIGGGHTS and YADE, each against
#      theory and each reference code against silodem -> reports/comparison.md, results/compare/
# Exit status is non-zero if any check of either fails (both always run).
set -uo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
"$top/tools/setup.sh" || exit 1
"$top/tools/build.sh" || exit 1
status=0
"$top/build/silodem" verify "$top"/cases/*.json --out "$top/results/verify" \
  --report "$top/reports/verification.md" || status=1
# Figures (pressure map, Janssen profile, discharge, closure) from the verify results.
/usr/bin/python3 "$top/tools/plot_reports.py" "$top/results/verify" "$top/reports/figures" || status=1
"$top/build/silodem" compare "$top"/cases/*.json --out "$top/results/compare" \
  --report "$top/reports/comparison.md" || status=1
exit $status
