#!/usr/bin/env bash
# Builds the programs the main job runs (scripts/setup.sh with their targets only), then runs
# it; it needs no download.
#
# Default (--input sim): renders 20 s of the simulator's indoor_people_high scenario (three people
# walking across a room in front of a handheld RGB-D + IMU camera; cached in build/demo/sim and
# rendered again only when the command changes), runs the full system on it
# (params/sim_vio.ini: the ground-truth detector reading the simulator's objects.txt, so no
# network weights; depth segmentation, tracking, features, the sliding-window estimator with the
# paper's dynamic factors, dynamic_handling = full), and prints APE and FPS.
# --input 7scenes: the 600 real RGB-D frames of ../shared/data/7scenes, converted to a rawlog, run
# through params/7scenes_rgbd_odometry.ini (the dense RGB-D odometry baseline).
# --input realpeople: real people's pixels (cut from Debian opencv-doc's vtest.avi by
# dynslam-sprites) walking through those 600 real frames (params/sim/realpeople_7scenes.ini),
# run through params/realpeople_vio.ini: the whole system with the real detector, YOLOX-nano
# (../shared/models/yolox_nano.onnx), and no ground truth but for the score.
#
#   bash scripts/demo.sh [--input sim|7scenes|realpeople] [--config params/FILE.ini] [--no-build]
#                        [--set Section.key=value]...
#     --input sim|7scenes|realpeople
#                          the simulated scenario (default), the real 7-Scenes frames, or
#                          those frames with real-appearance people and the real detector
#     --config FILE.ini    the dynslam configuration (default params/sim_vio.ini,
#                          params/7scenes_rgbd_odometry.ini with --input 7scenes,
#                          params/realpeople_vio.ini with --input realpeople)
#     --no-build           use the programs already in $BUILD_DIR/bin (no package check, no
#                          build)
#     --set Section.key=value
#                          handed to dynslam (repeatable), e.g. --set
#                          Estimator.max_solver_time=100: the estimator's solves then stop on
#                          their iteration count, not the clock, and the trajectory is the same
#                          to the byte from run to run, whatever else the machine is doing
#     -h, --help           this text
# Without --no-build it builds dynslam, dynslam-eval and dynslam-sim (--input sim),
# sevenscenes2rawlog (--input 7scenes) or all of those and dynslam-sprites (--input realpeople),
# installing missing Debian packages first.
# Environment: BUILD_DIR (default build/), DYNSLAM_SHARED_DIR (default ../shared).
# Outputs in build/demo/<input>_run: trajectory.tum, objects/ID.tum, map.3Dscene (open it with
# SceneViewer3D), timing.csv, keyframes.csv, summary.json (with the APE), frames/ (annotated
# PNGs and annotated.avi), ape.json and ape.png (dynslam-eval's plot); formats in
# docs/programs.md.
# Exit codes: 0 done, 1 a build, a program or the data failed (7-Scenes, vtest.avi or the
# YOLOX-nano model absent), 2 usage,
# 130 interrupted (Ctrl-C).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$ROOT/build}"
INPUT=sim
CONFIG=""
BUILD=1
SETS=()
while [ $# -gt 0 ]; do
  case "$1" in
    --input) INPUT="$2"; shift 2 ;;
    --config) CONFIG="$2"; shift 2 ;;
    --no-build) BUILD=0; shift ;;
    --set) SETS+=(--set "$2"); shift 2 ;;
    -h|--help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"; exit 0 ;;
    *) echo "demo: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
case "$INPUT" in
  sim|7scenes|realpeople) ;;
  *) echo "demo: --input must be sim, 7scenes or realpeople, not '$INPUT'" >&2; exit 2 ;;
esac

# Only the programs this input runs: a first demo does not wait for the tests to build.
if [ "$BUILD" = 1 ]; then
  case "$INPUT" in
    sim) bash "$ROOT/scripts/setup.sh" dynslam dynslam-eval dynslam-sim ;;
    7scenes) bash "$ROOT/scripts/setup.sh" dynslam dynslam-eval sevenscenes2rawlog ;;
    realpeople) bash "$ROOT/scripts/setup.sh" dynslam dynslam-eval dynslam-sim dynslam-sprites \
                  sevenscenes2rawlog ;;
  esac
fi
BIN="$BUILD_DIR/bin"
DEMO="$BUILD_DIR/demo"
RUN="$DEMO/${INPUT}_run"
mkdir -p "$DEMO"
rm -rf "$RUN"

# --input realpeople: the sprite bank from vtest.avi, the 7-Scenes frames with its people
# rendered in (both cached like the simulated scenario), and the real detector's model.
realPeople() {
  local vtest=/usr/share/doc/opencv-doc/examples/data/vtest.avi model="$SHARED/models/yolox_nano.onnx"
  for f in "$vtest" "$model"; do
    [ -f "$f" ] || { echo "demo: $f is absent (opencv-doc package; ../shared/models)" >&2; exit 1; }
  done
  [ "$DEMO/sprites_vtest/bank.txt" -nt "$BIN/dynslam-sprites" ] ||
    "$BIN/dynslam-sprites" --video "$vtest" --out "$DEMO/sprites_vtest"
  local sim="$DEMO/realpeople"
  local render=("$BIN/dynslam-sim" --config "$ROOT/params/sim/realpeople_7scenes.ini" --out "$sim"
                --set "Augment.rawlog=$DEMO/7scenes.rawlog" --set "People.sprites=$DEMO/sprites_vtest")
  local stamp
  stamp="${render[*]} $(stat -c %Y "$BIN/dynslam-sim") $(stat -c %Y "$DEMO/sprites_vtest/bank.txt")"
  if [ ! -f "$sim/sim.rawlog" ] || [ "$(cat "$sim/demo_command.txt" 2>/dev/null)" != "$stamp" ]; then
    rm -rf "$sim"
    echo "demo: rendering real people into the 600 7-Scenes frames ($sim)"
    "${render[@]}" --quiet
    echo "$stamp" > "$sim/demo_command.txt"
  fi
  CONFIG="${CONFIG:-$ROOT/params/realpeople_vio.ini}"
  RAWLOG="$sim/sim.rawlog"
  GT="$sim/groundtruth.tum"
  EXTRA=(--set "Detection.model=$model")
}

if [ "$INPUT" = sim ]; then
  CONFIG="${CONFIG:-$ROOT/params/sim_vio.ini}"
  SIM="$DEMO/sim"
  render=("$BIN/dynslam-sim" --config "$ROOT/params/sim/indoor_people_high.ini" --out "$SIM"
          --set Scenario.duration=20)
  # Rendered once; again only when the command (or the program) changed since.
  stamp="${render[*]} $(stat -c %Y "$BIN/dynslam-sim")"
  if [ ! -f "$SIM/sim.rawlog" ] || [ "$(cat "$SIM/demo_command.txt" 2>/dev/null)" != "$stamp" ]; then
    rm -rf "$SIM"
    echo "demo: rendering 20 s of params/sim/indoor_people_high.ini into $SIM"
    "${render[@]}"
    echo "$stamp" > "$SIM/demo_command.txt"
  fi
  RAWLOG="$SIM/sim.rawlog"
  GT="$SIM/groundtruth.tum"
  EXTRA=(--set "Detection.objects=$SIM/objects.txt" --set Estimator.dynamic_handling=full)
else
  SHARED="${DYNSLAM_SHARED_DIR:-$ROOT/../shared}"
  SCENES="$SHARED/data/7scenes"
  if [ ! -d "$SCENES" ]; then
    echo "demo: $SCENES is absent (it ships beside the repository as ../shared)" >&2
    exit 1
  fi
  if [ ! "$DEMO/7scenes.rawlog" -nt "$BIN/sevenscenes2rawlog" ]; then
    "$BIN/sevenscenes2rawlog" --in "$SCENES" --out "$DEMO/7scenes.rawlog"
  fi
  if [ "$INPUT" = 7scenes ]; then
    CONFIG="${CONFIG:-$ROOT/params/7scenes_rgbd_odometry.ini}"
    RAWLOG="$DEMO/7scenes.rawlog"
    GT="$DEMO/7scenes.gt.tum"
    EXTRA=()
  else
    realPeople
  fi
fi
"$BIN/dynslam" --config "$CONFIG" --rawlog "$RAWLOG" --out "$RUN" --gt "$GT" \
  --frames "$RUN/frames" "${EXTRA[@]}" "${SETS[@]}"
"$BIN/dynslam-eval" ape "$GT" "$RUN/trajectory.tum" --align se3 \
  --json "$RUN/ape.json" --plot "$RUN/ape.png" >/dev/null

fps=$(sed -n 's/^ *"fps": *\([0-9.]*\).*/\1/p' "$RUN/summary.json")
rmse=$(sed -n 's/^ *"rmse": *\([0-9.e+-]*\).*/\1/p' "$RUN/ape.json")
# The stages alone (timing.csv's pipeline_ms), without reading the rawlog and writing the outputs.
stages_fps=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "pipeline_ms") c = i; next }
                      { ms += $c; n++ } END { if (ms > 0) printf "%.1f", 1000 * n / ms; else print 0 }' \
             "$RUN/timing.csv")
objects=""
if [ -d "$RUN/objects" ]; then
  objects=", $(find "$RUN/objects" -name '*.tum' | wc -l) objects followed"
fi
printf '\ndemo: APE RMSE %.4f m (SE(3)-aligned), %.1f FPS (stages alone %s FPS)%s -- outputs in %s\n' \
  "$rmse" "$fps" "$stages_fps" "$objects" "${RUN#"$ROOT"/}"
