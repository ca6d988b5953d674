#!/usr/bin/env bash
# Soak run: a long simulator sequence through the whole system (params/sim_vio.ini), sampling
# the process's resident memory every few seconds. Prints the resident set after the first
# 1,000 frames and at the end, the growth between them (target < 5 %), the run's status and APE.
#
#   bash bench/estimator_soak.sh [--build DIR] [--out DIR] [--frames N] [--scenario NAME]
#                                [--dynslam-args "ARGS"]
#     --build DIR           the build folder whose bin/ holds the programs (default build/)
#     --out DIR             work folder (default /tmp/dynslam-soak): NAME/ (the rendering, kept
#                           for the next run), NAME/soak/ (dynslam's outputs), NAME/soak.log,
#                           NAME/soak.rss (seconds and resident kB per sample)
#     --frames N            frames rendered and run (default 10000, at 30 Hz)
#     --scenario NAME       a scenario of params/sim/ (default indoor_people_low)
#     --dynslam-args "ARGS" extra arguments for the dynslam run, e.g. "--no-map"
#     -h, --help            this text
#   Exit codes: 0 done (whatever the run's status, which it prints), 1 a program failed,
#   2 usage.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
. "$ROOT/bench/lib.sh"
BUILD="$ROOT/build"; OUT="/tmp/dynslam-soak"; FRAMES=10000; SCENARIO=indoor_people_low; EXTRA=""

while [ $# -gt 0 ]; do
  case "$1" in
    --build) BUILD="$2"; shift 2 ;;
    --out) OUT="$2"; shift 2 ;;
    --dynslam-args) EXTRA="$2"; shift 2 ;;
    --frames) FRAMES="$2"; shift 2 ;;
    --scenario) SCENARIO="$2"; shift 2 ;;
    -h|--help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"; exit 0 ;;
    *) echo "estimator_soak.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
BIN="$BUILD/bin"
mkdir -p "$OUT"
S="$OUT/$SCENARIO"
duration=$(awk -v f="$FRAMES" 'BEGIN { printf "%.3f", f / 30.0 }')
if [ ! -f "$S/sim.rawlog" ]; then
  echo "rendering $FRAMES frames of $SCENARIO ..." >&2
  "$BIN/dynslam-sim" --config "$ROOT/params/sim/$SCENARIO.ini" --out "$S" \
    --set Scenario.duration="$duration" --quiet > /dev/null 2>&1
fi

R="$S/soak"
# shellcheck disable=SC2086
"$BIN/dynslam" --config "$ROOT/params/sim_vio.ini" --rawlog "$S/sim.rawlog" --out "$R" \
  --set Detection.objects="$S/objects.txt" $EXTRA > "$R.log" 2>&1 &
pid=$!
: > "$R.rss"
start=$(date +%s)
while kill -0 "$pid" 2> /dev/null; do
  rss=$(awk '/^VmRSS/ { print $2 }' "/proc/$pid/status" 2> /dev/null || true)
  [ -n "$rss" ] && echo "$(( $(date +%s) - start )) $rss" >> "$R.rss"
  sleep 5
done
wait "$pid" || true
elapsed=$(( $(date +%s) - start ))

fps=$(jsonField "$R/summary.json" fps)
status=$(jsonField "$R/summary.json" status)
# The sample taken when about 1,000 frames had been processed (frames = seconds x fps).
awk -v fps="$fps" -v total="$elapsed" '
  { t[NR] = $1; m[NR] = $2 }
  END {
    if (NR < 2) { print "too few memory samples"; exit }
    k = 1; while (k < NR && t[k] * fps < 1000) k++
    growth = 100 * (m[NR] - m[k]) / m[k]
    printf "resident memory: %.1f MB after ~1000 frames (t = %d s), %.1f MB at the end (t = %d s): growth %.2f %% (target < 5 %%)\n", m[k] / 1024, t[k], m[NR] / 1024, t[NR], growth
  }' "$R.rss"
"$BIN/dynslam-eval" ape "$S/groundtruth.tum" "$R/trajectory.tum" --align se3 --json "$R/ape.json" > /dev/null 2>&1 || true
echo "status $status, $FRAMES frames in ${elapsed} s ($fps FPS), APE RMSE $(jsonField "$R/ape.json" rmse) m, restarts $(jsonField "$R/summary.json" resets)"
# The static map (map.3Dscene) keeps one point per occupied voxel and grows with what the camera
# has seen (and, as the trajectory drifts, with walls seen again a little elsewhere), up to
# MapSceneOptions::max_points (1,000,000): say so, since it is in the growth above.
mapPoints=$(jsonField "$R/summary.json" map_points)
if [ -n "$mapPoints" ] && [ "$mapPoints" -gt 0 ]; then
  echo "the static map holds $mapPoints points (about 64 bytes each, $(( mapPoints * 64 / 1048576 )) MB) and grows with the space seen; --dynslam-args \"--no-map\" measures the rest"
fi
