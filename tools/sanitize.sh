#!/usr/bin/env bash
# Builds the tree with AddressSanitizer and UndefinedBehaviorSanitizer on an optimised build
# (CMake preset asan-ubsan: -O2 -g, build-asan/) and runs the GoogleTest suite under them. Any
# sanitizer report aborts its test, so a clean exit means no finding.
#   tools/sanitize.sh          every test (the whole-case runs and the cross-code compare too)
#   tools/sanitize.sh --fast   the fast tests only, as CI runs them: no whole-case or silo runs,
#                              no cross-code compare, no kill-and-restart runs (the release tests
#                              run those; they exercise the same code on larger scenes)
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
filter=()
if [ "${1:-}" = "--fast" ]; then
  filter=(-E '^(Cases|Compare|SiloCases|SeedScatter|ReferenceRun|Restart|Signals|Report)\.')
fi
cmake --preset asan-ubsan >/dev/null
cmake --build --preset asan-ubsan
ctest --preset asan-ubsan "${filter[@]}"
