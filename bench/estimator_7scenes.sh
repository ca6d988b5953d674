#!/usr/bin/env bash
# The estimator on real RGB-D data: the 600 Kinect frames of ../shared/data/7scenes, RGB-D only
# (params/7scenes_vo.ini). Prints APE RMSE (SE(3)-aligned, target 0.05 m, aim 0.03), the
# window's median solve time per keyframe (target 30 ms) and the whole pipeline's FPS.
#
#   bash bench/estimator_7scenes.sh [--build DIR] [--out DIR]
#     --build DIR   the build folder whose bin/ holds the programs (default build/)
#     --out DIR     work folder (default /tmp/dynslam-7scenes): 7scenes.rawlog (converted again
#                   when sevenscenes2rawlog is newer), run/ (dynslam's outputs, ape.json),
#                   run.log
#     -h, --help    this text
#   Environment: DYNSLAM_SHARED_DIR (default ../shared).
#   Exit codes: 0 done, 1 7-Scenes absent or a program failed, 2 usage.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
. "$ROOT/bench/lib.sh"
BUILD="$ROOT/build"; OUT="/tmp/dynslam-7scenes"
while [ $# -gt 0 ]; do
  case "$1" in
    --build) BUILD="$2"; shift 2 ;;
    --out) OUT="$2"; shift 2 ;;
    -h|--help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"; exit 0 ;;
    *) echo "estimator_7scenes.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
BIN="$BUILD/bin"
SCENES="${DYNSLAM_SHARED_DIR:-$ROOT/../shared}/data/7scenes"
[ -d "$SCENES" ] || { echo "estimator_7scenes.sh: $SCENES is absent" >&2; exit 1; }
mkdir -p "$OUT"
# Converted again when the converter is newer than the cached rawlog (its conversion changed).
[ "$OUT/7scenes.rawlog" -nt "$BIN/sevenscenes2rawlog" ] || "$BIN/sevenscenes2rawlog" --in "$SCENES" --out "$OUT/7scenes.rawlog" > /dev/null
"$BIN/dynslam" --config "$ROOT/params/7scenes_vo.ini" --rawlog "$OUT/7scenes.rawlog" --out "$OUT/run" \
  --quiet > "$OUT/run.log" 2>&1
"$BIN/dynslam-eval" ape "$OUT/7scenes.gt.tum" "$OUT/run/trajectory.tum" --align se3 \
  --json "$OUT/run/ape.json" > /dev/null
awk -v ape="$(jsonField "$OUT/run/ape.json" rmse)" -v solve="$(jsonField "$OUT/run/summary.json" solve_ms_median)" \
    -v fps="$(jsonField "$OUT/run/summary.json" fps)" -v kf="$(jsonField "$OUT/run/summary.json" keyframes)" \
  'BEGIN {
     printf "7-Scenes, RGB-D only: APE RMSE %.4f m (target 0.05: ratio %.2f; aim 0.03: ratio %.2f)\n", ape, ape / 0.05, ape / 0.03
     printf "window solve median %.1f ms per keyframe over %d keyframes (target 30 ms: ratio %.2f); %.1f FPS\n", solve, kf, solve / 30, fps
   }'
