#!/usr/bin/env bash
# The silo cases at the paper's size (about 22,000 mobile balls; docs/model.md §8: the paper's
# run took 405 days on a 300 MHz Pentium III). Not part of CI: hours of CPU in all.
#   tools/paper_size.sh [--threads N] [STAGE...]
#     stages: discharge closure fill compare janssen, and with frictional grains (mu 0.5, wall 0.3,
#     history spring: cases/generators/paper_frictional.py) discharge_frictional closure_frictional
#     fill_frictional compare_frictional, and ranks (LAMMPS on 1 and 2 MPI ranks on the discharge,
#     0.05 s from the shared state: its speed-up) (default: discharge closure)
#   (janssen: the Janssen column at 22,119 balls, settled by silodem to 3.5 s, then 0.1 s in every code)
# Cases are generated into results/paper/cases; results and the wall times into results/paper/;
# a summary table is appended to reports/paper_size.md.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
"$top/tools/setup.sh"
"$top/tools/build.sh"
out="$top/results/paper"
mkdir -p "$out/cases"
python3 "$top/cases/generators/silo.py" paper "$out/cases"
python3 "$top/cases/generators/janssen_column.py" paper "$out/cases"
python3 "$top/cases/generators/paper_frictional.py" "$out/cases"
threads=1
if [ "${1:-}" = "--threads" ]; then threads=$2; shift 2; fi
stages=("$@")
[ ${#stages[@]} -eq 0 ] && stages=(discharge closure)
report="$top/reports/paper_size.md"
[ -f "$report" ] || printf '# Paper-size silo runs\n\nWritten by `tools/paper_size.sh` (machine: see reports/benchmarks.md).\n\n| date | stage | code | mobile balls | wall balls | steps | wall time (s) | result |\n|---|---|---|---|---|---|---|---|\n' > "$report"
for stage in "${stages[@]}"; do
  case "$stage" in
    discharge|closure|fill|discharge_frictional|closure_frictional|fill_frictional)
      "$top/build/silodem" verify "$out/cases/silo_$stage.json" --threads "$threads" --out "$out/verify" \
        --report "$out/verify_$stage.md" || true
      ;;
    compare|compare_frictional)
      suffix=${stage#compare}
      "$top/build/silodem" compare "$out/cases/silo_discharge$suffix.json" "$out/cases/silo_closure$suffix.json" \
        --threads "$threads" --out "$out/compare" --report "$out/compare$suffix.md" || true
      ;;
    ranks)
      # LAMMPS on 1 and then 2 MPI ranks on the paper-size discharge, 0.05 s from the shared state
      # (silodem on --threads; the runs one at a time): the loop times give the speed-up.
      for ranks in 1 2; do
        "$top/build/silodem" compare "$out/cases/silo_discharge_ranks.json" --codes silodem,lammps --ranks "$ranks" \
          --threads "$threads" --out "$out/ranks$ranks" --report "$out/ranks$ranks.md" || true
      done
      ;;
    janssen)
      "$top/build/silodem" compare "$out/cases/janssen_column.json" --out "$out/compare" --report "$out/compare_janssen.md" || true
      ;;
    *) echo "paper_size: unknown stage $stage (discharge closure fill compare janssen ranks, *_frictional)" >&2; exit 2 ;;
  esac
done
# One row per run found: code, balls, steps, wall seconds, from each summary.json.
/usr/bin/python3 - "$out" "$report" <<'PY'
import glob, json, os, sys, time
out, report = sys.argv[1], sys.argv[2]
rows = []
for f in sorted(glob.glob(os.path.join(out, "*", "*", "*", "summary.json")) + glob.glob(os.path.join(out, "*", "*", "*", "*", "summary.json"))):
    s = json.load(open(f))
    if "run" not in s or "reconstructed" in f:
        continue
    rel = os.path.relpath(os.path.dirname(f), out)
    rows.append("| %s | %s | %s | %s | %s | %s | %.0f | %s |" % (time.strftime("%Y-%m-%d"), rel, s.get("code", "silodem"),
                s.get("balls", {}).get("mobile", "?"), s.get("balls", {}).get("fixed", "?"), s["run"].get("steps", "?"),
                s["run"].get("wall_seconds", 0.0), s.get("status", "?")))
open(report, "a").write("\n".join(rows) + "\n")
print("\n".join(rows))
PY
