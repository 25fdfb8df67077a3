#!/usr/bin/env bash
# Builds the tree with AddressSanitizer and UndefinedBehaviorSanitizer on an optimised build
# (CMake preset asan-ubsan: -O1 -g1, build-asan/) and runs the GoogleTest suite under them. Any
# sanitizer report aborts its test, so a clean exit means no finding.
#   tools/sanitize.sh          every target, every test (the whole-case runs and the cross-code
#                              compare too)
#   tools/sanitize.sh --fast   as CI runs it: the solver's and the references' test executables
#                              and silodem only, and their fast tests: no whole-case or silo runs,
#                              no kill-and-restart runs, no rotating-drum or hopper thread runs; not
#                              the harness, backend, compare and command-line tests, which run
#                              whole cases through the same solver code and reference codes (the
#                              release tests run all of these; the frictional two-thread test stays)
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
targets=() filter=()
if [ "${1:-}" = "--fast" ]; then
  mapfile -t tests < <(sed -n 's/^silodem_test(\(test_[a-z_]*\) .*/\1/p' tests/CMakeLists.txt | grep -v -E '^(test_silo_cases|test_compare|test_harness|test_backends|test_cli)$')
  targets=(--target silodem "${tests[@]}")
  filter=(-E '^(Cases|Compare|SiloCases|SeedScatter|ReferenceRun|Restart|Signals|Report|RotatingDrum)\.|_NOT_BUILT|^SurfaceContacts\.ThreadsChange|^Threads\.OneAndTwoThreadsGiveBitwiseTheSameState$')
fi
cmake --preset asan-ubsan >/dev/null
cmake --build --preset asan-ubsan "${targets[@]}"
ctest --preset asan-ubsan "${filter[@]}"
