#!/usr/bin/env bash
# Camera-IMU calibration errors on the simulator ([Calibration] in params/sim/*.ini) and what the
# estimator makes of them: a time offset ignored, configured (known) and estimated online; a
# believed extrinsic rotation 2 degrees off, as configured and estimated online; and exact
# calibration with both estimates on (no regression). The ground-truth detector, params/sim_vio.ini,
# full dynamic handling, repeatable solves (max_solver_time = 100).
#
#   bash bench/calibration.sh [--seeds "1 2"] [--scenarios "a b"] [--duration S] [--out DIR]
#                             [--build DIR] [--jobs N] [--keep-renders] [--report-only]
#     --seeds "A B"       Scenario.seed values (default "1")
#     --scenarios "a b"   scenarios of params/sim/ (default indoor_people_high outdoor_street_high)
#     --duration S        seconds rendered (default 20)
#     --out DIR           work folder (default /tmp/dynslam-calibration): renders, runs, rows.tsv
#     --build DIR         the build folder whose bin/ holds the programs (default build/)
#     --jobs N            renders and runs side by side (default 2)
#     --keep-renders      keep each render's rawlog and images after the runs (about 0.6 GB a
#                         render, 16 a seed; by default only the ground truth and the runs stay)
#     --report-only       print the table from the runs already in the work folder
#     -h, --help          this text
# Prints one row per scenario and seed and writes OUT/rows.tsv. Columns: ape_exact (m, SE(3);
# aligned on the first pose on the straight street), ape_exact_est (both estimates on) and their
# ratio, the window solve median of each (ms); for a 20 ms offset: ape_td20 ignored, ape_td20_known
# (configured), ape_td20_est (estimated) and the estimate at 10 s and at the end (ms); for true
# offsets -30 -10 +10 +30 ms the estimate's error at 10 s and at the end (ms); for a 2 degree
# rotation error: ape_rot2 as believed, ape_rot2_est (estimated, rotation only) and the rotation
# error left at the end (deg); ape_jit2: the camera's stamps jittered by 2 ms (sigma) against the
# IMU.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=bench/lib.sh
source "$ROOT/bench/lib.sh"
SEEDS="1"; SCENARIOS="indoor_people_high outdoor_street_high"; DURATION=20
OUT=/tmp/dynslam-calibration; BUILD="$ROOT/build"; JOBS=2; REPORT_ONLY=0; KEEP_RENDERS=0
while [ $# -gt 0 ]; do
  case "$1" in
    --seeds) SEEDS="$2"; shift 2 ;;
    --scenarios) SCENARIOS="$2"; shift 2 ;;
    --duration) DURATION="$2"; shift 2 ;;
    --out) OUT="$2"; shift 2 ;;
    --build) BUILD="$(realpath -m "$2")"; shift 2 ;;
    --jobs) JOBS="$2"; shift 2 ;;
    --keep-renders) KEEP_RENDERS=1; shift ;;
    --report-only) REPORT_ONLY=1; shift ;;
    -h | --help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"; exit 0 ;;
    *) echo "calibration.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
B="$BUILD/bin"
mkdir -p "$OUT"
[ "$REPORT_ONLY" = 1 ] || cmake --build "$BUILD" -j2 --target dynslam dynslam-sim dynslam-eval > "$OUT/build.log" 2>&1 ||
  { echo "calibration.sh: the build failed, see $OUT/build.log" >&2; exit 1; }

# The renders: name and [Calibration] settings.
RENDERS="exact:
td20:--set Calibration.time_offset_s=0.02
tdm30:--set Calibration.time_offset_s=-0.03
tdm10:--set Calibration.time_offset_s=-0.01
tdp10:--set Calibration.time_offset_s=0.01
tdp30:--set Calibration.time_offset_s=0.03
rot2:--set Calibration.cam_yaw_error_deg=2
jit2:--set Calibration.time_jitter_s=0.002"
EST_TD="--set Estimator.estimate_time_offset=true"
EST_ROT="--set Estimator.estimate_extrinsic=rotation"
# The runs: render, name, settings.
RUNS="exact:off:
exact:est:$EST_TD $EST_ROT
td20:off:
td20:known:--set Estimator.time_offset=0.02
td20:est:$EST_TD
tdm30:est:$EST_TD
tdm10:est:$EST_TD
tdp10:est:$EST_TD
tdp30:est:$EST_TD
rot2:off:
rot2:est:$EST_ROT
jit2:off:"

render() {  # seed scenario name settings...
  local seed="$1" sc="$2" name="$3"; shift 3
  simRender "$OUT/seed$seed/$sc/$name" "$sc" "$seed" "$@"
}

run() {  # seed scenario render name settings...
  local seed="$1" sc="$2" r="$3" name="$4"; shift 4
  simVioRun "$OUT/seed$seed/$sc/$r" "$OUT/seed$seed/$sc/$r/run_$name" "$seed" "$@"
}
export -f render run simRender simVioRun variantSettings
export B OUT ROOT DURATION

[ "$REPORT_ONLY" = 1 ] || {
for seed in $SEEDS; do for sc in $SCENARIOS; do
  while IFS=: read -r name settings; do echo "render $seed $sc $name $settings"; done <<< "$RENDERS"
done; done | sed 's/ *$//' > "$OUT/render.jobs"  # xargs -L joins a line ending in a blank
xargs -P "$JOBS" -L 1 bash -c '"$@"' _ < "$OUT/render.jobs"
for seed in $SEEDS; do for sc in $SCENARIOS; do
  while IFS=: read -r r name settings; do echo "run $seed $sc $r $name $settings"; done <<< "$RUNS"
done; done | sed 's/ *$//' > "$OUT/run.jobs"
xargs -P "$JOBS" -L 1 bash -c '"$@"' _ < "$OUT/run.jobs"
# The renders' rawlogs and images (six seeds fill 55 GB); the next run renders them again.
[ "$KEEP_RENDERS" = 1 ] || for seed in $SEEDS; do for sc in $SCENARIOS; do
  while IFS=: read -r name settings; do
    S="$OUT/seed$seed/$sc/$name"
    rm -rf "$S/sim.rawlog" "$S/sim_Images" "$S/labels" "$S/.rendered"
  done <<< "$RENDERS"
done; done
}

ape() { jsonField "$1/ape.json" rmse 2>/dev/null || echo -; }
solveMs() { jsonField "$1/summary.json" solve_ms_median; }
# tdAt KEYFRAMES_CSV SECONDS: the time offset (ms) of the last keyframe at or before SECONDS of
# stream; "end" for the last keyframe.
tdAt() {
  awk -F, -v s="$2" 'NR == 2 { t0 = $2 } NR > 1 && (s == "end" || $2 - t0 <= s + 1e-6) { v = $21 }
    END { printf "%.2f", v }' "$1"
}
# rotationLeft CALIBRATION_TXT KEYFRAMES_CSV: degrees between the estimated and the true camera
# rotation at the end, from the believed one and the estimate's change (small angles).
rotationLeft() {
  awk -F'[ ,]' 'FNR == NR && $1 == "camera_in_imu_true" { for (i = 0; i < 9; i++) R[i] = $(2 + int(i / 3) * 4 + i % 3) }
    FNR == NR && $1 == "camera_in_imu_believed" { for (i = 0; i < 9; i++) Q[i] = $(2 + int(i / 3) * 4 + i % 3) }
    FNR != NR && FNR > 1 { c[0] = $22; c[1] = $23; c[2] = $24 }
    END {
      # The believed rotation times Exp(change) against the true one: E = R^T Q Exp(c), small
      # angles: vec(R^T Q) + c, with vec the rotation vector of R^T Q from its skew part.
      for (i = 0; i < 3; i++) for (j = 0; j < 3; j++) { m[i, j] = 0; for (k = 0; k < 3; k++) m[i, j] += R[k * 3 + i] * Q[k * 3 + j] }
      d = 57.29577951308232
      x = (m[2, 1] - m[1, 2]) / 2 * d + c[0]; y = (m[0, 2] - m[2, 0]) / 2 * d + c[1]; z = (m[1, 0] - m[0, 1]) / 2 * d + c[2]
      printf "%.3f", sqrt(x * x + y * y + z * z) }' "$1" "$2"
}

{
  printf 'seed\tscenario\tape_exact\tape_exact_est\tratio\tsolve_ms\tsolve_ms_est\tape_td20\tape_td20_known\tape_td20_est\ttd20_at10\ttd20_end\terr_m30\terr_m10\terr_p10\terr_p30\terr_m30_end\terr_m10_end\terr_p10_end\terr_p30_end\tape_rot2\tape_rot2_est\trot2_left_deg\tape_jit2\n'
  for seed in $SEEDS; do for sc in $SCENARIOS; do
    D="$OUT/seed$seed/$sc"
    e=$(ape "$D/exact/run_off"); ee=$(ape "$D/exact/run_est")
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s' "$seed" "$sc" "$e" "$ee" \
      "$(awk -v a="$ee" -v b="$e" 'BEGIN { printf "%.3f", a / b }')" \
      "$(solveMs "$D/exact/run_off")" "$(solveMs "$D/exact/run_est")"
    printf '\t%s\t%s\t%s\t%s\t%s' "$(ape "$D/td20/run_off")" "$(ape "$D/td20/run_known")" \
      "$(ape "$D/td20/run_est")" "$(tdAt "$D/td20/run_est/keyframes.csv" 10)" \
      "$(tdAt "$D/td20/run_est/keyframes.csv" end)"
    for at in 10 end; do for r in tdm30:-30 tdm10:-10 tdp10:10 tdp30:30; do
      printf '\t%s' "$(awk -v a="$(tdAt "$D/${r%%:*}/run_est/keyframes.csv" "$at")" -v b="${r##*:}" \
        'BEGIN { printf "%.2f", a - b }')"
    done; done
    printf '\t%s\t%s\t%s\t%s\n' "$(ape "$D/rot2/run_off")" "$(ape "$D/rot2/run_est")" \
      "$(rotationLeft "$D/rot2/calibration.txt" "$D/rot2/run_est/keyframes.csv")" \
      "$(ape "$D/jit2/run_off")"
  done; done
} | tee "$OUT/rows.tsv" | column -t
