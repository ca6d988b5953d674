#!/usr/bin/env bash
# Set-up (scripts/setup.sh) followed by the main job on the default input, which needs no
# download: the 600 real RGB-D frames of ../shared/data/7scenes, converted to a rawlog, run
# through the configured pipeline, and scored against the ground truth (APE, FPS, a plot).
#
#   bash scripts/demo.sh [--config params/FILE.ini]
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$ROOT/build}"
CONFIG="$ROOT/params/7scenes_rgbd_odometry.ini"
if [ "${1:-}" = "--config" ]; then CONFIG="$2"; fi
SCENES="${DYNSLAM_SHARED_DIR:-$ROOT/../shared}/data/7scenes"

bash "$ROOT/scripts/setup.sh"
BIN="$BUILD_DIR/bin"
DEMO="$BUILD_DIR/demo"
mkdir -p "$DEMO"

if [ ! -d "$SCENES" ]; then
  echo "demo: the default input $SCENES is absent (it ships beside the repository as ../shared)" >&2
  exit 1
fi
if [ ! -f "$DEMO/7scenes.rawlog" ]; then
  "$BIN/sevenscenes2rawlog" --in "$SCENES" --out "$DEMO/7scenes.rawlog"
fi

"$BIN/dynslam" --config "$CONFIG" --rawlog "$DEMO/7scenes.rawlog" --out "$DEMO/run"
"$BIN/dynslam-eval" ape "$DEMO/7scenes.gt.tum" "$DEMO/run/trajectory.tum" --align se3 \
  --json "$DEMO/run/ape.json" --plot "$DEMO/run/ape.png"
fps=$(sed -n 's/^ *"fps": *\([0-9.]*\).*/\1/p' "$DEMO/run/summary.json")
rmse=$(sed -n 's/^ *"rmse": *\([0-9.e+-]*\).*/\1/p' "$DEMO/run/ape.json")
printf '\ndemo: APE RMSE %.4f m (SE(3)-aligned), %.1f FPS -- outputs in %s\n' "$rmse" "$fps" "$DEMO/run"
