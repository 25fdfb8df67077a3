#!/usr/bin/env bash
# The test job: set up, build, run every test registered with CTest.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
"$top/tools/setup.sh"
"$top/tools/build.sh"
# A one-node Slurm for the sweep's Slurm test (tests/harness/sweep_test.cpp); if it cannot start,
# the test is skipped and says why.
if "$top/tools/slurm_local.sh" start; then
  eval "$("$top/tools/slurm_local.sh" env)"
else
  echo "test: no local Slurm (above); the Slurm sweep test is skipped" >&2
fi
cd "$top/build" && ctest --output-on-failure -j "$(nproc)"
