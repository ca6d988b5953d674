#!/usr/bin/env bash
# Injected sensor faults: renders a scenario with a 1 s IMU gap, 20 black frames and 10 frames
# without depth (dynslam-sim --imu-gap/--black-frames/--no-depth), runs the whole system
# (params/sim_vio.ini) and prints its status, APE, restarts and the worst jump of the
# trajectory: the largest difference, over consecutive frames, between the estimated and the
# true distance moved (a continuous trajectory keeps it at centimetres).
#
#   bash bench/estimator_faults.sh [--build DIR] [--out DIR] [--scenario NAME] [--duration S]
#     --build DIR       the build folder whose bin/ holds the programs (default build/)
#     --out DIR         work folder (default /tmp/dynslam-faults): NAME/ (the rendering),
#                       NAME/run/ (dynslam's outputs, ape.json), NAME/run.log
#     --scenario NAME   a scenario of params/sim/ (default indoor_people_low)
#     --duration S      seconds rendered (default 20)
#     -h, --help        this text
#   Exit codes: 0 done (whatever the run's status, which it prints), 1 a program is missing,
#   2 usage.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
. "$ROOT/bench/lib.sh"
BUILD="$ROOT/build"; OUT="/tmp/dynslam-faults"; SCENARIO=indoor_people_low; DURATION=20
while [ $# -gt 0 ]; do
  case "$1" in
    --build) BUILD="$2"; shift 2 ;;
    --out) OUT="$2"; shift 2 ;;
    --scenario) SCENARIO="$2"; shift 2 ;;
    --duration) DURATION="$2"; shift 2 ;;
    -h|--help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"; exit 0 ;;
    *) echo "estimator_faults.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
BIN="$BUILD/bin"
S="$OUT/$SCENARIO"
"$BIN/dynslam-sim" --config "$ROOT/params/sim/$SCENARIO.ini" --out "$S" --quiet \
  --set Scenario.duration="$DURATION" --imu-gap 8:1 --black-frames 300:20 --no-depth 450:10 \
  > /dev/null 2>&1
"$BIN/dynslam" --config "$ROOT/params/sim_vio.ini" --rawlog "$S/sim.rawlog" --out "$S/run" --quiet \
  --set Detection.objects="$S/objects.txt" > "$S/run.log" 2>&1 || true
"$BIN/dynslam-eval" ape "$S/groundtruth.tum" "$S/run/trajectory.tum" --align se3 \
  --json "$S/run/ape.json" > /dev/null 2>&1 || true
jump=$(awk 'FNR == 1 { f++ } /^#/ { next }
  f == 1 { gt[sprintf("%.3f", $1)] = $2 " " $3 " " $4; next }
  { key = sprintf("%.3f", $1); split(gt[key], g, " ")
    if (n++) {
      de = sqrt(($2-px)^2 + ($3-py)^2 + ($4-pz)^2); dg = sqrt((g[1]-gx)^2 + (g[2]-gy)^2 + (g[3]-gz)^2)
      d = de > dg ? de - dg : dg - de; if (d > worst) { worst = d; at = $1 }
    }
    px = $2; py = $3; pz = $4; gx = g[1]; gy = g[2]; gz = g[3] }
  END { printf "%.3f m at t = %.2f s", worst, at - 1700000000 }' "$S/groundtruth.tum" "$S/run/trajectory.tum")
echo "faults: IMU gap 8-9 s, black frames 300-319, no depth 450-459 ($SCENARIO, $DURATION s)"
echo "status $(jsonField "$S/run/summary.json" status), frames $(jsonField "$S/run/summary.json" frames), APE RMSE $(jsonField "$S/run/ape.json" rmse) m"
echo "restarts $(jsonField "$S/run/summary.json" resets), IMU gaps seen $(jsonField "$S/run/summary.json" imu_gaps), frames without a keyframe-worthy view $(jsonField "$S/run/summary.json" blind_frames)"
echo "worst trajectory jump (|estimated - true| distance between consecutive frames): $jump"
