#!/usr/bin/env bash
# The main job: set up, build, then
#   1. verify: every case in cases/ in silodem alone, every integrator and time step of its
#      "verify" section, against theory          -> reports/verification.md, results/verify/,
#   2. compare: every case's "compare" section in silodem, LAMMPS, LIGGGHTS and YADE, each against
#      theory and each reference code against silodem -> reports/comparison.md, results/compare/
#   3. the report from both: figures, tables, pages -> reports/index.html, reports/report.md,
#      reports/figures/*.png, reports/tables/*.csv (tools/report.py)
#   4. (full tier) the fast tests under ASan and UBSan (tools/sanitize.sh --fast), then 60 s of
#      libFuzzer on the case loader and the checkpoint reader (tools/fuzz.sh): CI leaves both out
#      (reports/ci_budget.md)
# They write to separate folders, so on a machine with two cores or more they run side by side
# (their progress lines interleave; each report is written whole at its end); each runs its jobs
# one thread (or rank) each, as many at a time as there are cores (silodem's results are bitwise
# the same for any thread count), so no core waits once the other is done.
# Exit status is non-zero if any check of either fails (both always run).
#
#   tools/suite.sh        the full tier (the README's main command), as above.
#   tools/suite.sh --ci   the CI tier: verify without the frictional silo cases (the material tests,
#                         the predicted column and the frictional discharge: about 80 min on one
#                         core, reports/frictional_silo.md); compare without YADE and without the
#                         seven silo-scale cases, frictionless and frictional (their shared states and seed realisations, and
#                         YADE's runs, are most of the full tier's time: reports/ci_budget.md). The
#                         tests cover what it leaves out at small size (SiloCases.*, SeedScatter.*,
#                         Compare.* through YADE, the material checks on columns of known K and
#                         mu_w); every left-out code is a skip row saying so, every left-out case
#                         is named on stdout.
#                         No sanitizer pass, no fuzzing.
#                         Writes results/ci/{verify,compare} and its reports to results/ci/reports,
#                         never over the full tier's reports/.
#   tools/suite.sh --resume  either tier, keeping the runs of an earlier, stopped or failed, run of
#                         it that finished from the same inputs (verify and compare --resume): the
#                         full tier takes hours, so a stop costs only the runs under way. After a
#                         change of the solver or of a reference code, run without it.
set -uo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
results="$top/results" reports="$top/reports" codes=()
compared=("$top"/cases/*.json)
silo_scale="janssen_column silo_fill silo_discharge silo_closure janssen_frictional silo_discharge_frictional silo_closure_frictional"
frictional_silo="lateral_pressure_ratio wall_friction direct_shear angle_of_repose janssen_frictional silo_discharge_frictional hopper_flow_pattern"
verified=("$top"/cases/*.json)
tier=full resume=()
for arg in "$@"; do
  case "$arg" in
    --ci) tier=ci ;;
    --resume) resume=(--resume) ;;
    *) echo "usage: tools/suite.sh [--ci] [--resume]" >&2; exit 2 ;;
  esac
done
case "$tier" in
  full) ;;
  ci)
    results="$top/results/ci" reports="$top/results/ci/reports" codes=(--codes silodem,lammps,liggghts)
    compared=() verified=()
    for f in "$top"/cases/*.json; do
      case " $silo_scale " in *" $(basename "$f" .json) "*) ;; *) compared+=("$f") ;; esac
      case " $frictional_silo " in *" $(basename "$f" .json) "*) ;; *) verified+=("$f") ;; esac
    done
    echo "suite --ci: verify leaves out $frictional_silo; compare leaves out $silo_scale and YADE" \
         "(tools/suite.sh without --ci runs them)" ;;
esac
"$top/tools/setup.sh" || exit 1
"$top/tools/build.sh" || exit 1
mkdir -p "$reports" || exit 1
# verify's runs are independent jobs: one thread each, as many at a time as there are cores. Two
# threads on a small case beside compare's runs spin at every step's barrier (the mill's 3 s took
# 45 s so in CI, against 4 s on one thread).
verify() {
  "$top/build/silodem" verify "${verified[@]}" --out "$results/verify" --threads 1 --jobs "$(nproc)" \
    "${resume[@]}" --report "$reports/verification.md"
}
# compare runs as many jobs at a time as there are cores (one thread or rank each): its run times
# share the cores with verify's and are not speed figures (those are the benchmarks', measured
# alone: reports/benchmarks.md); one at a time left a core idle for hours once verify was done.
compare() {
  "$top/build/silodem" compare "${compared[@]}" "${codes[@]}" --jobs "$(nproc)" --out "$results/compare" \
    "${resume[@]}" --report "$reports/comparison.md"
}
status=0
if [ "$(nproc)" -ge 2 ]; then
  verify & v=$!
  compare & c=$!
  wait $v || status=1
  wait $c || status=1
else
  verify || status=1
  compare || status=1
fi
/usr/bin/python3 "$top/tools/report.py" --results "$results" --out "$reports" || status=1
# The full tier also runs the fast tests under the sanitizers (tests/README.md) and fuzzes the case
# loader and the checkpoint reader, 60 s each (fuzz/README.md).
if [ "$tier" = full ]; then
  "$top/tools/sanitize.sh" --fast || status=1
  "$top/tools/fuzz.sh" 60 || status=1
fi
exit $status
