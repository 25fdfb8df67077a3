#!/usr/bin/env bash
# The main job: set up, build, run every verification case in cases/ and write the comparison
# report (results/ and reports/verification.md). Exit status is non-zero if any check fails.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
"$top/tools/setup.sh"
"$top/tools/build.sh"
exec "$top/build/silodem" verify "$top"/cases/*.json --out "$top/results" --report "$top/reports/verification.md"
