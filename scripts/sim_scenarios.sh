#!/usr/bin/env bash
# Renders every scenario of params/sim/ in full, writes a contact sheet of each (colour | depth |
# instance labels at evenly spread times) to docs/images/sim_<name>.png, and prints what
# `rawlog-edit --info` counts in each rawlog. The augmented 7-Scenes scenario first converts
# ../shared/data/7scenes with sevenscenes2rawlog (skipped, saying so, when it is absent); the
# real-appearance ones (appearance = video) first cut the sprite bank from Debian opencv-doc's
# vtest.avi with dynslam-sprites into DIR/sprites_vtest (skipped when opencv-doc is absent).
#
#   bash scripts/sim_scenarios.sh [--out DIR] [--only NAME] [--duration S]
#     --out DIR       where the sequences go, one folder per scenario (default build/sim; the
#                     street ones are ~1 GB each)
#     --only NAME     one scenario, e.g. --only market_crowd_high
#     --duration S    override every scenario's duration (s), for a quick look
#     -h, --help      this text
#   Environment: BUILD_DIR (default build/), DYNSLAM_SHARED_DIR (default ../shared).
#   Prints per scenario its render time and the rawlog's observations per sensor label.
#   Exit codes: 0 done, 1 a program failed, 2 usage. Needs a build (bash scripts/setup.sh).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BIN="${BUILD_DIR:-$ROOT/build}/bin"
OUT="${BUILD_DIR:-$ROOT/build}/sim"
ONLY=""
EXTRA=()
while (($#)); do
  case "$1" in
    --out) OUT="$2"; shift 2 ;;
    --only) ONLY="$2"; shift 2 ;;
    --duration) EXTRA+=(--set "Scenario.duration=$2"); shift 2 ;;
    -h|--help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"; exit 0 ;;
    *) echo "sim_scenarios: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
SHARED="${DYNSLAM_SHARED_DIR:-$ROOT/../shared}"
VTEST=/usr/share/doc/opencv-doc/examples/data/vtest.avi  # real people for appearance = video
mkdir -p "$OUT" "$ROOT/docs/images"

counts() {  # "RGBD 901, IMU 6001, GPS 1501" from rawlog-edit's table (run from the folder)
  (cd "$(dirname "$1")" && rawlog-edit --info -i "$(basename "$1")" 2>&1) |
    sed -n 's/^Sensor (Label.*: *\([A-Za-z0-9_]*\) *\/ *\([0-9]*\) *\/.*/\1 \2/p' |
    paste -sd, | sed 's/,/, /g'
}

for ini in "$ROOT"/params/sim/*.ini; do
  name="$(basename "$ini" .ini)"
  [ -z "$ONLY" ] || [ "$ONLY" = "$name" ] || continue
  args=()
  if grep -q '^scene *= *augment' "$ini"; then
    if [ ! -d "$SHARED/data/7scenes" ]; then
      echo "$name: skipped, $SHARED/data/7scenes is absent"
      continue
    fi
    [ "$OUT/7scenes.rawlog" -nt "$BIN/sevenscenes2rawlog" ] ||
      "$BIN/sevenscenes2rawlog" --in "$SHARED/data/7scenes" --out "$OUT/7scenes.rawlog" >/dev/null
    args+=(--set "Augment.rawlog=$OUT/7scenes.rawlog")
  fi
  if grep -q '^appearance *= *video' "$ini"; then
    if [ ! -f "$VTEST" ]; then
      echo "$name: skipped, $VTEST is absent (Debian package opencv-doc)"
      continue
    fi
    [ "$OUT/sprites_vtest/bank.txt" -nt "$BIN/dynslam-sprites" ] ||
      "$BIN/dynslam-sprites" --video "$VTEST" --out "$OUT/sprites_vtest" >/dev/null
    args+=(--set "People.sprites=$OUT/sprites_vtest")
  fi
  start=$SECONDS
  "$BIN/dynslam-sim" --config "$ini" --out "$OUT/$name" --quiet "${args[@]}" "${EXTRA[@]}" \
    --contact-sheet "$ROOT/docs/images/sim_$name.png" --sheet-frames 4
  printf '%-22s %5d s   rawlog-edit: %s\n' "$name" $((SECONDS - start)) \
    "$(counts "$OUT/$name/sim.rawlog")"
done
