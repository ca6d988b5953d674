#!/usr/bin/env bash
# The jobs of bench/paper_tables, one per call so a queue (xargs -P) can run them side by side:
#   bash jobs.sh render SEED SCENARIO      dynslam-sim into $OUT/seedSEED/SCENARIO
#   bash jobs.sh run SEED SCENARIO VARIANT the whole system (params/sim_vio.ini) + APE / RPE
#   bash jobs.sh rgbd7                     RGB-D only on the real 7-Scenes (params/7scenes_vo.ini)
#   bash jobs.sh segmentation SEED SCENARIO   bench-segmentation (Tables 1-2)
#   bash jobs.sh detector SCENARIO         bench-detection on the scenario's colour frames
#   bash jobs.sh timing SCENARIO           Table 8: a deterministic run and a --realtime run
# Environment (exported by bench/paper_tables): ROOT BIN OUT DURATION SHARED FIRST_SEED.
# Every run job writes RUN/row.tsv (see rowHeader), "failed" with its log when something broke:
# the report then prints "failed (see LOG)" rather than leaving a hole.
set -uo pipefail
. "$ROOT/bench/lib.sh"

scenarioDir() { echo "$OUT/seed$1/$2"; }

# The accuracy runs lift the estimator's wall-time limit per solve (0.05 s by default): with it a
# solve stops wherever the CPU it got left it, and the same run gave 0.080 / 0.085 / 0.098 m APE
# on one machine; without it the solve stops at its iteration limit and a re-run gives the same
# trajectory byte for byte. The timing runs (Table 8) keep the limit, as the system runs.
DETERMINISTIC_SOLVES="--set Estimator.max_solver_time=100"

# Settings every render of SCENARIO takes: the seed, the duration (not for the augmented
# 7-Scenes scene, whose length is the real sequence's) and where the converted 7-Scenes is.
simSettings() {
  local seed="$1" sc="$2"
  echo "--set Scenario.seed=$seed"
  if [ "$sc" = augmented_7scenes ]; then
    echo "--set Augment.rawlog=$OUT/7scenes.rawlog"
  else
    echo "--set Scenario.duration=$DURATION"
  fi
}

render() {
  local seed="$1" sc="$2" S
  S=$(scenarioDir "$seed" "$sc")
  # A render is kept unless the 7-Scenes rawlog it augments was converted again since.
  if [ -f "$S/.rendered" ] && { [ "$sc" != augmented_7scenes ] || [ "$S/.rendered" -nt "$OUT/7scenes.rawlog" ]; }; then
    return 0
  fi
  mkdir -p "$(dirname "$S")"
  # shellcheck disable=SC2046
  if "$BIN/dynslam-sim" --config "$ROOT/params/sim/$sc.ini" --out "$S" --quiet \
    $(simSettings "$seed" "$sc") > "$S.render.log" 2>&1; then
    touch "$S/.rendered"
  else
    echo "render $sc seed $seed failed: see $S.render.log" >&2
  fi
}

rowHeader() {
  printf 'seed\tscenario\tvariant\tstatus\talign\tape_rmse\tape_mean\tape_median\tape_std\trpe_rmse\trpe_mean\trpe_median\trpe_std\tresets\tfps\tlog\n'
}

# evaluate GT RUN_DIR LOG SEED SCENARIO VARIANT: APE (SE(3)-aligned; on the first pose when the
# path is too straight for Umeyama, as bench/estimator_ablation.sh) and RPE (1 frame, the
# paper's m/frame), then RUN_DIR/row.tsv.
evaluate() {
  local gt="$1" R="$2" log="$3" seed="$4" sc="$5" v="$6" align=se3 plot=() k a p
  if [ "$seed" = "$FIRST_SEED" ] && [ "$v" = full ]; then plot=(--plot "$R/ape.png"); fi
  if [ -f "$R/trajectory.tum" ]; then
    "$BIN/dynslam-eval" ape "$gt" "$R/trajectory.tum" --align se3 --json "$R/ape.json" "${plot[@]}" \
      >> "$log" 2>&1 || true
    if [ ! -f "$R/ape.json" ]; then
      align=origin
      "$BIN/dynslam-eval" ape "$gt" "$R/trajectory.tum" --align-origin --json "$R/ape.json" \
        "${plot[@]}" >> "$log" 2>&1 || true
    fi
    "$BIN/dynslam-eval" rpe "$gt" "$R/trajectory.tum" --delta 1 --delta-unit f --json "$R/rpe.json" \
      >> "$log" 2>&1 || true
  fi
  local status=ok
  [ "$(jsonField "$R/summary.json" status 2>/dev/null)" = ok ] || status=failed
  [ -f "$R/ape.json" ] && [ -f "$R/rpe.json" ] || status=failed
  {
    printf '%s\t%s\t%s\t%s\t%s' "$seed" "$sc" "$v" "$status" "$align"
    for k in rmse mean median std; do
      a=$(jsonField "$R/ape.json" "$k" 2>/dev/null); printf '\t%s' "${a:--}"
    done
    for k in rmse mean median std; do
      p=$(jsonField "$R/rpe.json" "$k" 2>/dev/null); printf '\t%s' "${p:--}"
    done
    a=$(jsonField "$R/summary.json" resets 2>/dev/null); printf '\t%s' "${a:--}"
    a=$(jsonField "$R/summary.json" fps 2>/dev/null); printf '\t%s' "${a:--}"
    printf '\t%s\n' "$log"
  } > "$R/row.tsv"
}

run() {
  local seed="$1" sc="$2" v="$3" S R log
  S=$(scenarioDir "$seed" "$sc"); R="$S/run_$v"; log="$S/run_$v.log"
  rm -rf "$R"; mkdir -p "$R"
  if [ ! -f "$S/.rendered" ]; then
    echo "not rendered: see $S.render.log" > "$log"
  else
    # The ground-truth detector's misses and jitter follow the seed too.
    # shellcheck disable=SC2046,SC2086
    "$BIN/dynslam" --config "$ROOT/params/sim_vio.ini" --rawlog "$S/sim.rawlog" --out "$R" --quiet \
      --no-map --set Detection.objects="$S/objects.txt" --set Detection.seed="$seed" \
      $DETERMINISTIC_SOLVES $(variantSettings "$v") > "$log" 2>&1 || true
  fi
  evaluate "$S/groundtruth.tum" "$R" "$log" "$seed" "$sc" "$v"
}

rgbd7() {
  local R="$OUT/7scenes_rgbd/run" log="$OUT/7scenes_rgbd/run.log"
  rm -rf "$R"; mkdir -p "$R"
  # shellcheck disable=SC2086
  "$BIN/dynslam" --config "$ROOT/params/7scenes_vo.ini" --rawlog "$OUT/7scenes.rawlog" --out "$R" \
    --quiet --no-map $DETERMINISTIC_SOLVES > "$log" 2>&1 || true
  FIRST_SEED=- evaluate "$OUT/7scenes.gt.tum" "$R" "$log" - 7scenes_rgbd rgbd
  # Its plot: this run is the only one of its table.
  "$BIN/dynslam-eval" ape "$OUT/7scenes.gt.tum" "$R/trajectory.tum" --align se3 --plot "$R/ape.png" \
    >> "$log" 2>&1 || true
}

segmentation() {
  local seed="$1" sc="$2" f="$OUT/perception/seg_${2}_seed$1.txt"
  mkdir -p "$OUT/perception"
  # The [Segmentation] of params/sim_vio.ini (what the SLAM tables run), each frame alone.
  # shellcheck disable=SC2046
  "$BIN/bench-segmentation" --config "$ROOT/params/sim/$sc.ini" --every 3 $(simSettings "$seed" "$sc") \
    --seg-config "$ROOT/params/sim_vio.ini" > "$f" 2>&1 || echo "FAILED" >> "$f"
}

detector() {
  local sc="$1" S f="$OUT/perception/det_$1.txt" n
  S=$(scenarioDir "$FIRST_SEED" "$sc")
  mkdir -p "$OUT/perception"
  if [ ! -f "$SHARED/models/yolox_nano.onnx" ]; then echo "ABSENT" > "$f"; return 0; fi
  n=$(find "$S/sim_Images" -name 'colour_*.png' | wc -l)
  "$BIN/bench-detection" --video "$S/sim_Images/colour_%06d.png" --frames 30 --realtime-seconds 0 \
    --model "$SHARED/models/yolox_nano.onnx" > "$f" 2>&1 || echo "FAILED" >> "$f"
  # The true people on the 30 frames bench-detection samples (frame i * n / 30), for its
  # "people / frame": all that project into the image, and those at least half visible.
  awk -v n="$n" 'BEGIN { for (i = 0; i < 30; ++i) want[int(i * n / 30)] = 1 }
    !/^#/ && ($1 in want) && $4 == "person" { all++; if ($18 >= 0.5) half++ }
    END { printf "TRUTH people/frame %.2f half-visible %.2f\n", all / 30, half / 30 }' \
    "$S/objects.txt" >> "$f"
}

# A copy of params/sim_vio.ini with YOLOX-nano in its own thread instead of the ground-truth
# detector (whose keys are unknown to onnx_yolo), and the predicted-box segmentation.
# params/sim_vio.ini with its [Detection] section replaced by YOLOX-nano in the detection thread
# (its [PredictedBoxes] stage, which fills the frames between detections, is kept as it is).
yoloxIni() {
  awk '/^\[/ { skip = ($0 == "[Detection]") } !skip' "$ROOT/params/sim_vio.ini"
  printf '\n[Detection]\ndetector = onnx_yolo\nmode = realtime\nmodel = %s\nlayout = yolox\ninput_size = 416\n' \
    "$SHARED/models/yolox_nano.onnx"
}

timing() {
  local sc="$1" S T
  S=$(scenarioDir "$FIRST_SEED" "$sc"); T="$OUT/timing/$sc"
  rm -rf "$T"; mkdir -p "$T"
  [ -f "$S/.rendered" ] || { echo "not rendered" > "$T/failed"; return 0; }
  # 1. As fast as it goes, ground-truth detector (as the accuracy tables): per-stage medians.
  # shellcheck disable=SC2046
  "$BIN/dynslam" --config "$ROOT/params/sim_vio.ini" --rawlog "$S/sim.rawlog" --out "$T/det" --quiet \
    --no-map --set Detection.objects="$S/objects.txt" --set Detection.seed="$FIRST_SEED" \
    $(variantSettings full) > "$T/det.log" 2>&1 || true
  # 2. --realtime (camera rate), YOLOX-nano in the detection thread: the detector thread's
  # time and rate and the end-to-end rate as a live camera would see it.
  [ -f "$SHARED/models/yolox_nano.onnx" ] || { echo "ABSENT" > "$T/rt.absent"; return 0; }
  yoloxIni > "$T/sim_vio_yolox_realtime.ini"
  # shellcheck disable=SC2046
  "$BIN/dynslam" --config "$T/sim_vio_yolox_realtime.ini" --rawlog "$S/sim.rawlog" --out "$T/rt" \
    --quiet --no-map --realtime $(variantSettings full) > "$T/rt.log" 2>&1 || true
}

"$@"
