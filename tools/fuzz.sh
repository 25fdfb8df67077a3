#!/usr/bin/env bash
# Fuzzes the case-file loader and the checkpoint reader with libFuzzer, SECONDS each (default 60):
# configures a separate clang build in ./build-fuzz (SILODEM_FUZZ=ON: ASan + UBSan + coverage),
# builds the targets, runs each on its seed corpus fuzz/corpus/<name> (read-only; new inputs go to
# build-fuzz/corpus/<name>) and prints the executions and crashes. A crash input is kept in
# build-fuzz/artifacts/; exit status 1 then.
#   tools/fuzz.sh [SECONDS] [case|checkpoint ...]
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(case checkpoint)
build="$top/build-fuzz"
CXX=${CXX_FUZZ:-clang++} cmake -S "$top" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DSILODEM_FUZZ=ON -DSILODEM_TESTS=OFF >/dev/null
mkdir -p "$build/artifacts"
rm -f "$build"/artifacts/crash-* "$build"/artifacts/leak-* "$build"/artifacts/timeout-* "$build"/artifacts/oom-*
failed=0
for t in "${targets[@]}"; do
  case "$t" in
    # max_len: a little above the largest seed (case files ~5 KB, checkpoints ~27 KB).
    case) exe=fuzz_case_loader; extra=(-dict="$top/fuzz/case.dict" -max_len=8192) ;;
    checkpoint) exe=fuzz_checkpoint_reader; extra=(-max_len=32768) ;;
    *) echo "fuzz: unknown target $t (case, checkpoint)" >&2; exit 2 ;;
  esac
  cmake --build "$build" --target "$exe" -j 2 >/dev/null
  mkdir -p "$build/corpus/$t"
  log="$build/fuzz_$t.log"
  set +e
  "$build/fuzz/$exe" "$build/corpus/$t" "$top/fuzz/corpus/$t" "${extra[@]}" -max_total_time="$seconds" \
    -timeout=10 -rss_limit_mb=2048 -artifact_prefix="$build/artifacts/$t-" -print_final_stats=1 >"$log" 2>&1
  status=$?
  set -e
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  crashes=$(find "$build/artifacts" -type f -name "$t-*" | wc -l)
  echo "$exe: ${seconds} s, executions: ${runs:-unknown}, crashes: ${crashes} (exit ${status}; log ${log})"
  if [ "$crashes" -gt 0 ] || [ "$status" -ne 0 ]; then
    grep -m1 -A20 -E "ERROR: (AddressSanitizer|libFuzzer)|runtime error|terminate called|uncaught" "$log" || tail -30 "$log"
    find "$build/artifacts" -type f -name "$t-*"
    failed=1
  fi
done
exit $failed
