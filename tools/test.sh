#!/usr/bin/env bash
# The test job: set up, build, run every test registered with CTest.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
"$top/tools/setup.sh"
"$top/tools/build.sh"
cd "$top/build" && ctest --output-on-failure -j "$(nproc)"
