#!/usr/bin/env bash
# The silo of Dosta et al. (2024) at the paper's size, 100,000 grains (docs/dosta-benchmark.md).
# Not in CI: hours per code. Every step continues where it stopped when the script is rerun.
#   1. fill: writes results/dosta/<orifice>_<material>/fill.json and runs it (the lattice settles
#      behind the gate for 0.35 s, checkpointed every 10 min of wall clock);
#   2. discharge.json from the settled state (the outlet open at t = 0, as the benchmark starts);
#   3. speed: speed.json, the discharge's first moments, and `silodem compare` of every code on it
#      (each code continues silodem's state at a third of --speed-piece s for the piece)
#      -> speed/verdicts.json, speed.md: the run times (delete speed.md to measure again);
#   4. flow: flow.json, and `silodem compare` of every code on a piece of the steady flow (each
#      code continues silodem's discharge at --flow-start s for --flow-piece s, LAMMPS and LIGGGHTS
#      on --threads ranks) -> flow/verdicts.json, flow.md: the mass flows judged between codes
#      (delete flow.md to run it again, keeping the runs that finished; --skip-flow leaves it out);
#   5. the discharge in silodem for --duration s (the benchmark's 5 s by default; fixed when
#      discharge.json is first written), checkpointed;
#      stop it any time (SIGTERM, Ctrl-C) and rerun the script to continue.
#   tools/dosta_full.sh [--orifice small|large] [--material M1|M2] [--threads N]
#                       [--speed-piece S] [--duration S] [--skip-speed] [--codes a,b]
#                       [--flow-start S] [--flow-piece S] [--skip-flow]
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
orifice=small material=M1 threads=$(nproc) piece=0.01 duration=5 speed=1 flow=1 flow_start=0.099 flow_piece=0.114 codes=silodem,lammps,liggghts,yade
while [ $# -gt 0 ]; do
  case "$1" in
    --orifice) orifice=$2; shift 2 ;;
    --material) material=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --speed-piece) piece=$2; shift 2 ;;
    --duration) duration=$2; shift 2 ;;
    --skip-speed) speed=0; shift ;;
    --flow-start) flow_start=$2; shift 2 ;;
    --flow-piece) flow_piece=$2; shift 2 ;;
    --skip-flow) flow=0; shift ;;
    --codes) codes=$2; shift 2 ;;
    *) echo "dosta_full: unknown option $1 (see the header of $0)" >&2; exit 2 ;;
  esac
done
silodem="$top/build/silodem"
[ -x "$silodem" ] || { echo "dosta_full: $silodem is not built (tools/build.sh)" >&2; exit 2; }
dir="$top/results/dosta/${orifice}_${material}"
mkdir -p "$dir"
gen=("/usr/bin/python3" "$top/cases/generators/dosta_silo.py" --size full --orifice "$orifice" --material "$material")

# Runs a case into DIR, continuing from its checkpoints if an earlier run was stopped.
run_resumable() {  # case out
  if [ -f "$2/summary.json" ]; then echo "dosta_full: $2 is complete"; return 0; fi
  local restart=()
  [ -d "$2.checkpoint" ] && restart=(--restart)
  "$silodem" run "$1" --out "$2" --threads "$threads" --progress-every 60 "${restart[@]}"
}

cd "$top"
[ -f "$dir/fill.json" ] || "${gen[@]}" --stage fill --out "$dir/fill.json"
run_resumable "$dir/fill.json" "$dir/fill"
[ -f "$dir/discharge.json" ] || "${gen[@]}" --stage discharge --state "$dir/fill/state.json" \
  --duration "$duration" --out "$dir/discharge.json"
if [ "$speed" = 1 ] && [ ! -f "$dir/speed.md" ]; then
  "${gen[@]}" --stage speed --state "$dir/fill/state.json" --speed-piece "$piece" --out "$dir/speed.json"
  # A failing verdict here is a finding, not a reason to stop the long run.
  # One thread: the reference codes run one rank each, so the run times compare per core.
  "$silodem" compare "$dir/speed.json" --codes "$codes" --threads 1 --out "$dir/speed" \
    --report "$dir/speed.md" ||
    echo "dosta_full: the speed comparison exits non-zero: its rows are reports, so \"nothing was judged\" is" \
         "expected; any failed run is named in $dir/speed.md" >&2
fi
if [ "$flow" = 1 ] && [ ! -f "$dir/flow.md" ]; then
  "${gen[@]}" --stage flow --state "$dir/fill/state.json" --flow-start "$flow_start" --flow-piece "$flow_piece" \
    --out "$dir/flow.json"
  # --resume: a stopped flow step keeps the runs that finished (each about an hour at this size).
  "$silodem" compare "$dir/flow.json" --codes "$codes" --threads "$threads" --ranks "$threads" --out "$dir/flow" \
    --resume --report "$dir/flow.md" ||
    echo "dosta_full: the flow comparison exits non-zero: a failed row or run is named in $dir/flow.md" >&2
fi
run_resumable "$dir/discharge.json" "$dir/discharge"
echo "dosta_full: done: $dir/discharge (probes/outflow.csv: the discharged mass against time)"
