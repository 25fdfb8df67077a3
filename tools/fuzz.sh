#!/usr/bin/env bash
# Fuzzes the case-file loader with libFuzzer for SECONDS (default 60): configures a separate clang
# build in ./build-fuzz (SILODEM_FUZZ=ON: ASan + UBSan + coverage), builds fuzz_case_loader, runs it
# on the seed corpus fuzz/corpus/case (read-only; new inputs go to build-fuzz/corpus) and prints
# the executions and crashes. A crash input is kept in build-fuzz/artifacts/; exit status 1 then.
#   tools/fuzz.sh [SECONDS]
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
build="$top/build-fuzz"
CXX=${CXX_FUZZ:-clang++} cmake -S "$top" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DSILODEM_FUZZ=ON -DSILODEM_TESTS=OFF >/dev/null
cmake --build "$build" --target fuzz_case_loader -j 2
mkdir -p "$build/corpus" "$build/artifacts"
rm -f "$build"/artifacts/crash-* "$build"/artifacts/leak-* "$build"/artifacts/timeout-* "$build"/artifacts/oom-*
log="$build/fuzz.log"
# max_len 8 KiB: the seeds are at most ~5 KB; a longer case file adds no new loader branch.
set +e
"$build/fuzz/fuzz_case_loader" "$build/corpus" "$top/fuzz/corpus/case" \
  -dict="$top/fuzz/case.dict" -max_total_time="$seconds" -max_len=8192 -timeout=10 -rss_limit_mb=2048 \
  -artifact_prefix="$build/artifacts/" -print_final_stats=1 >"$log" 2>&1
status=$?
set -e
runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
crashes=$(find "$build/artifacts" -type f | wc -l)
echo "fuzz_case_loader: ${seconds} s, executions: ${runs:-unknown}, crashes: ${crashes} (exit ${status}; log ${log})"
if [ "$crashes" -gt 0 ] || [ "$status" -ne 0 ]; then
  grep -m1 -A20 -E "ERROR: (AddressSanitizer|libFuzzer)|runtime error|terminate called|uncaught" "$log" || tail -30 "$log"
  find "$build/artifacts" -type f
  exit 1
fi
