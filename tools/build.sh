#!/usr/bin/env bash
# Configures and builds silodem (Release, -O3) in ./build. Pass -DSILODEM_NATIVE=ON for -march=native.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cmake -S "$top" -B "$top/build" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$top/build" -j "$(nproc)"
