#!/usr/bin/env bash
# Object states for planners (issue 54 item 0): each scenario and seed rendered by dynslam-sim,
# run by dynslam with params/sim_vio.ini (the ground-truth detector with its 10 % misses and 3 px
# jitter, full dynamic handling, the ObjectStates stage, repeatable solves), then scored by
# bench-objects against objects.txt: per run and pooled per scenario.
#
#   bash bench/objects.sh [--seeds "1 2"] [--scenarios "a b"] [--duration S] [--out DIR]
#                         [--build DIR] [--jobs N] [--set S.k=v]... [--report-only]
#     --seeds "A B"       Scenario.seed values (default "1 2 3 4 5 6")
#     --scenarios "a b"   scenarios of params/sim/ (default indoor_people_high market_crowd_high)
#     --duration S        seconds rendered (default 20)
#     --out DIR           work folder (default /tmp/dynslam-objects): renders, runs, scores
#     --build DIR         the build folder whose bin/ holds the programs (default build/)
#     --jobs N            renders and runs side by side (default 2)
#     --set S.k=v         a dynslam override for every run (repeatable), e.g.
#                         --set ObjectStates.thickness_fraction=0.6
#     --report-only       score the runs already in the work folder
#     -h, --help          this text
# Prints bench-objects' line per run and the pooled line per scenario (OUT/SCENARIO.json); each
# run's top view in OUT/SCENARIO/seedN/run/objects_top.png.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=bench/lib.sh
source "$ROOT/bench/lib.sh"
SEEDS="1 2 3 4 5 6"; SCENARIOS="indoor_people_high market_crowd_high"; DURATION=20
OUT=/tmp/dynslam-objects; BUILD="$ROOT/build"; JOBS=2; REPORT_ONLY=0; SETS=""
while [ $# -gt 0 ]; do
  case "$1" in
    --seeds) SEEDS="$2"; shift 2 ;;
    --scenarios) SCENARIOS="$2"; shift 2 ;;
    --duration) DURATION="$2"; shift 2 ;;
    --out) OUT="$2"; shift 2 ;;
    --build) BUILD="$(realpath -m "$2")"; shift 2 ;;
    --jobs) JOBS="$2"; shift 2 ;;
    --set) SETS="$SETS --set $2"; shift 2 ;;
    --report-only) REPORT_ONLY=1; shift ;;
    -h | --help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"; exit 0 ;;
    *) echo "objects.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
B="$BUILD/bin"
mkdir -p "$OUT"
[ "$REPORT_ONLY" = 1 ] ||
  cmake --build "$BUILD" -j2 --target dynslam dynslam-sim dynslam-eval bench-objects > "$OUT/build.log" 2>&1 ||
  { echo "objects.sh: the build failed, see $OUT/build.log" >&2; exit 1; }

job() {  # seed scenario: render (kept) and run
  simRender "$OUT/$2/seed$1" "$2" "$1" &&
    simVioRun "$OUT/$2/seed$1" "$OUT/$2/seed$1/run" "$1" $SETS
}
export -f job simRender simVioRun variantSettings
export B OUT ROOT DURATION SETS

[ "$REPORT_ONLY" = 1 ] || {
  for sc in $SCENARIOS; do for seed in $SEEDS; do echo "job $seed $sc"; done; done |
    xargs -P "$JOBS" -L 1 bash -c '"$@"' _
}
echo "data: simulator ($DURATION s renders), detector: ground truth (10 % misses, 3 px jitter), params/sim_vio.ini$SETS"
for sc in $SCENARIOS; do
  pairs=()
  for seed in $SEEDS; do pairs+=(--sim "$OUT/$sc/seed$seed" --run "$OUT/$sc/seed$seed/run"); done
  echo "== $sc"
  "$B/bench-objects" "${pairs[@]}" --json "$OUT/$sc.json" --plot
done
