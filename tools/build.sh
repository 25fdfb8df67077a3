#!/usr/bin/env bash
# Configures and builds silodem (Release, -O3, warnings are errors) in ./build. Pass
# -DSILODEM_NATIVE=ON for -march=native, -DSILODEM_WERROR=OFF to keep going past a warning.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cmake -S "$top" -B "$top/build" -DCMAKE_BUILD_TYPE=Release -DSILODEM_WERROR=ON "$@" >/dev/null
cmake --build "$top/build" -j "$(nproc)"
