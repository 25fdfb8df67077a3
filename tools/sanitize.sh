#!/usr/bin/env bash
# Builds the tree with AddressSanitizer and UndefinedBehaviorSanitizer (CMake preset asan-ubsan:
# Debug, build-asan/) and runs the GoogleTest suite under them. The preset's test filter skips the
# Janssen column run and the cross-code compare (see CMakePresets.json). Any sanitizer report
# aborts its test, so a clean exit means no finding.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
cmake --preset asan-ubsan >/dev/null
cmake --build --preset asan-ubsan
ctest --preset asan-ubsan
