#!/usr/bin/env bash
# Real people with the real detector, per seed: real people's pixels (the sprite bank cut from
# Debian opencv-doc's vtest.avi by dynslam-sprites) walking through the 600 real 7-Scenes frames
# (params/sim/realpeople_7scenes.ini, Scenario.seed = each seed: a different choreography), the
# same frames with no people inserted, and per seed:
#   - YOLOX-nano (input 416) and HOG on 100 frames against the ground truth: recall of the people
#     at least half visible and precision, box IoU >= 0.5 (bench-detection --truth);
#   - the depth-threshold masks from YOLOX-nano's boxes against the sprite labels, every 6th frame
#     (bench-segmentation on YOLOX-nano's boxes, the system's [Segmentation]): mean mask IoU of the people
#     at least half visible it boxed, and the mean error of their object depth d_t;
#   - the tracker on YOLOX-nano's boxes, every frame (bench-tracking with the system's [Tracking]
#     and [Segmentation]): MOTA and IDF1;
#   - APE RMSE (SE(3)) of the whole system with YOLOX-nano (params/realpeople_vio.ini) as full,
#     remove and none, of the same ini on the frames without people, and of the dense RGB-D
#     odometry (params/7scenes_rgbd_odometry.ini) with and without the people;
#   - the ratios the issue asks for: full / no people <= 1.15, full / remove <= 0.85,
#     full / none <= 0.30; then the means over the seeds.
# Accuracy runs set Estimator.max_solver_time=100 (solves end on their iteration count, so a
# re-run gives the same trajectory).
#   bash bench/realpeople.sh [--build DIR] [--out DIR] [--seeds "1 2 3 4 5 6"]
#     --build DIR     the build folder whose bin/ holds the programs (default build/)
#     --out DIR       work folder (default /tmp/dynslam-realpeople): the 7-Scenes rawlog, the
#                     sprite bank, seed_N/ (renders and runs, kept for the next run)
#     --seeds "A B"   Scenario.seed values (default "1 2 3 4 5 6")
#     -h, --help      this text
#   Environment: DYNSLAM_SHARED_DIR (default ../shared: data/7scenes, models/yolox_nano.onnx).
#   Exit codes: 0 done, 1 a program, the data, vtest.avi or the model is missing, 2 usage.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
. "$ROOT/bench/lib.sh"
BUILD="$ROOT/build"; OUT="/tmp/dynslam-realpeople"; SEEDS="1 2 3 4 5 6"
while [ $# -gt 0 ]; do
  case "$1" in
    --build) BUILD="$2"; shift 2 ;;
    --out) OUT="$2"; shift 2 ;;
    --seeds) SEEDS="$2"; shift 2 ;;
    -h|--help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"; exit 0 ;;
    *) echo "realpeople: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
B="$BUILD/bin"
SHARED="${DYNSLAM_SHARED_DIR:-$ROOT/../shared}"
VTEST=/usr/share/doc/opencv-doc/examples/data/vtest.avi
MODEL="$SHARED/models/yolox_nano.onnx"
for f in "$VTEST" "$MODEL" "$SHARED/data/7scenes" "$B/dynslam" "$B/dynslam-sim" "$B/dynslam-sprites" \
         "$B/dynslam-eval" "$B/bench-detection" "$B/sevenscenes2rawlog"; do
  [ -e "$f" ] || { echo "realpeople: $f is missing" >&2; exit 1; }
done
mkdir -p "$OUT"
[ "$OUT/7scenes.rawlog" -nt "$B/sevenscenes2rawlog" ] ||
  "$B/sevenscenes2rawlog" --in "$SHARED/data/7scenes" --out "$OUT/7scenes.rawlog" >/dev/null
[ "$OUT/sprites/bank.txt" -nt "$B/dynslam-sprites" ] ||
  "$B/dynslam-sprites" --video "$VTEST" --out "$OUT/sprites" >/dev/null

# render SEED NAME [--set ...]: the scenario into seed_SEED/NAME (once per program build).
render() {
  local seed="$1" name="$2"; shift 2
  local dir="$OUT/seed_$seed/$name"
  [ "$dir/sim.rawlog" -nt "$B/dynslam-sim" ] && return 0
  "$B/dynslam-sim" --config "$ROOT/params/sim/realpeople_7scenes.ini" --out "$dir" --quiet \
    --set "Augment.rawlog=$OUT/7scenes.rawlog" --set "People.sprites=$OUT/sprites" \
    --set "Scenario.seed=$seed" "$@" 2>&1 | grep -v ' frames, ' >&2 || true
}

# ape SEQUENCE RUN INI [--set ...]: dynslam on a sequence, then its APE RMSE (m) on stdout.
ape() {
  local seq="$1" run="$2" ini="$3"; shift 3
  "$B/dynslam" --config "$ROOT/params/$ini" --rawlog "$seq/sim.rawlog" --out "$seq/$run" --quiet \
    --no-map "$@" > "$seq/$run.log" 2>&1
  "$B/dynslam-eval" ape "$seq/groundtruth.tum" "$seq/$run/trajectory.tum" --align se3 \
    --json "$seq/$run/ape.json" > /dev/null
  jsonField "$seq/$run/ape.json" rmse
}

# recallPrecision FILE ROW: a detector's recall and precision from bench-detection's accuracy table.
recallPrecision() {
  sed -n '/^accuracy/,$p' "$1" | awk -v row="$2" 'index($0, row) == 1 { print $(NF - 4), $(NF - 3) }'
}

ROWS="$OUT/rows.txt"
: > "$ROWS"
# maskScores FILE: bench-segmentation's mean mask IoU and mean d_t error (%) of the people at least
# half visible.
maskScores() {
  awk '/summary, people >= 50 % visible/ { gsub(/[(),%]/, " "); print $9, $14 }' "$1"
}

# motScores FILE: bench-tracking's MOTA and IDF1.
motScores() {
  awk '$1 == "MOTA" { mota = $2 } $1 == "IDF1" { idf1 = $2 } END { print mota, idf1 }' "$1"
}

COLUMNS="seed yolo_rec yolo_pre hog_rec hog_pre mask_iou dt_err mota idf1 full remove none no_people odom odom_none f/nopeople f/remove f/none"
printf '%-5s %9s %9s %9s %9s %9s %9s %9s %9s %9s %9s %9s %9s %9s %9s %10s %9s %9s\n' $COLUMNS
for seed in $SEEDS; do
  render "$seed" people
  render "$seed" nopeople --set People.walkers=0 --set People.standing=0
  S="$OUT/seed_$seed/people"; N="$OUT/seed_$seed/nopeople"
  "$B/bench-detection" --video "$S/sim_Images/colour_%06d.png" --frames 100 --realtime-seconds 0 \
    --model "$MODEL" --truth "$S/objects.txt" > "$S/detection.txt" 2>&1
  read -r yr yp < <(recallPrecision "$S/detection.txt" "yolox_nano input 416")
  read -r hr hp < <(recallPrecision "$S/detection.txt" "hog people")
  scene=(--config "$ROOT/params/sim/realpeople_7scenes.ini" --set "Augment.rawlog=$OUT/7scenes.rawlog"
         --set "People.sprites=$OUT/sprites" --set "Scenario.seed=$seed")
  "$B/bench-segmentation" "${scene[@]}" --every 6 --boxes yolox --model "$MODEL" \
    --seg-config "$ROOT/params/realpeople_vio.ini" > "$S/segmentation.txt" 2>&1
  read -r miou dterr < <(maskScores "$S/segmentation.txt")
  "$B/bench-tracking" "${scene[@]}" --detector yolox --model "$MODEL" \
    --system "$ROOT/params/realpeople_vio.ini" --sweep '' > "$S/tracking.txt" 2>&1
  read -r mota idf1 < <(motScores "$S/tracking.txt")
  yolo=(--set "Detection.model=$MODEL" --set Estimator.max_solver_time=100)
  full=$(ape "$S" full realpeople_vio.ini "${yolo[@]}")
  remove=$(ape "$S" remove realpeople_vio.ini "${yolo[@]}" --set Estimator.dynamic_handling=remove)
  none=$(ape "$S" none realpeople_vio.ini "${yolo[@]}" --set Estimator.dynamic_handling=none)
  nopeople=$(ape "$N" full realpeople_vio.ini "${yolo[@]}")
  odom=$(ape "$S" odometry 7scenes_rgbd_odometry.ini)
  odomN=$(ape "$N" odometry 7scenes_rgbd_odometry.ini)
  echo "$seed $yr $yp $hr $hp $miou $dterr $mota $idf1 $full $remove $none $nopeople $odom $odomN" |
    awk '{ printf "%s", $0; printf " %.3f %.3f %.3f\n", $10 / $13, $10 / $11, $10 / $12 }' >> "$ROWS"
  tail -n 1 "$ROWS" | awk '{ printf "%-5s", $1; for (i = 2; i <= NF; ++i) printf " %9.4f", $i;
                             printf "\n" }'
done
awk '{ for (i = 2; i <= NF; ++i) s[i] += $i; n++ }
     END { printf "%-5s", "mean"; for (i = 2; i <= 18; ++i) printf " %9.4f", s[i] / n; printf "\n" }' \
  "$ROWS"
