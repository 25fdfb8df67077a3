#!/usr/bin/env bash
# The benchmark command (issue 5): every benchmark program and script, each writing JSON and
# Markdown under reports/, then the report with their figures. Not part of CI (about 90 minutes);
# run it on a quiet machine — every figure is a median or a ratio measured side by side, but a
# second job on these 2 cores still moves them.
#   tools/bench.sh [STAGE...]   stages: stability dense_stability stress feature_cost dense cores scaling work_precision
#                               (default: all, in that order)
#   stability        build/bench/bench_stability       one-contact stability limits  -> stability.{md,json}
#   dense_stability  build/bench/bench_dense_stability dense-packing limits, guards  -> dense_stability.{md,json}
#   stress           build/bench/bench_stress_runs     10^7-step drift, impacts, stiffness ratios -> stress_runs.{md,json}
#   feature_cost     build/bench/bench_feature_cost    time per step of each feature -> feature_cost.{md,json}
#   dense            tools/bench_dense.py              throughput against LAMMPS, LIGGGHTS, YADE -> bench_dense.{md,json}
#   cores            tools/bench_cores.py              each CPU alone and together, silodem and LAMMPS -> bench_cores.{md,json}
#   scaling          tools/bench_scaling.py            cost per step from 5,000 to 1,000,000 balls, LAMMPS on the same beds -> bench_scaling.{md,json}
#   work_precision   tools/work_precision.py           error against run time per integrator -> work_precision.{md,json}
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
"$top/tools/setup.sh"
"$top/tools/build.sh"
all_stages=(stability dense_stability stress feature_cost dense cores scaling work_precision)
stages=("$@")
[ ${#stages[@]} -eq 0 ] && stages=("${all_stages[@]}")
cd "$top"
for s in "${stages[@]}"; do
  echo "[bench] $s ($(date -u +%H:%M:%S))"
  case "$s" in
    stability) build/bench/bench_stability reports ;;
    dense_stability) build/bench/bench_dense_stability reports ;;
    stress) build/bench/bench_stress_runs reports ;;
    feature_cost) build/bench/bench_feature_cost reports ;;
    dense) /usr/bin/python3 tools/bench_dense.py 5000 20000 100000 ;;
    cores) /usr/bin/python3 tools/bench_cores.py 5000 ;;
    scaling) /usr/bin/python3 tools/bench_scaling.py ;;
    work_precision) /usr/bin/python3 tools/work_precision.py ;;
    *) echo "bench: unknown stage $s (${all_stages[*]})" >&2; exit 2 ;;
  esac
done
# The report draws the suite's results and these figures together; without the suite's results
# it is left as it is rather than redrawn with every code figure missing.
if [ ! -d "$top/results" ]; then
  echo "[bench] no results/: reports/report.md not redrawn (run tools/suite.sh, which draws it with these figures)"
  exit 0
fi
[ -d "$top/results/compare" ] || echo "[bench] no results/compare: the report's code figures will say skipped (run tools/suite.sh)"
/usr/bin/python3 tools/report.py --results results --out reports --bench reports/benchmarks.json
