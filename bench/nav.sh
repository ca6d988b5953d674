#!/usr/bin/env bash
# Closed-loop navigation among walking people (issue 54 item 4): dynslam-nav-demo on each
# navigation scenario and seed in three variants, the simulator's obstacles (the reference), the
# SLAM system's without prediction (obstacle_horizon_s = 0) and with it (the scenario's horizon);
# then one row per scenario and variant over the seeds.
#
#   bash bench/nav.sh [--seeds "1 2"] [--scenarios "a b"] [--out DIR] [--build DIR] [--jobs N]
#                     [--set S.k=v]... [--report-only]
#     --seeds "A B"       Scenario.seed values (default "1 2 3 4 5 6")
#     --scenarios "a b"   navigation scenarios of params/nav/ (default room_people)
#     --out DIR           work folder (default /tmp/dynslam-nav): one run folder per scenario,
#                         variant and seed (nav.json, top.png, top.avi, ...)
#     --build DIR         the build folder whose bin/ holds the programs (default build/; a
#                         folder without CMakeCache.txt is not built, only its bin/ used)
#     --jobs N            runs side by side (default 2)
#     --set S.k=v         a dynslam-nav-demo override for every run (repeatable)
#     --report-only       tabulate the runs already in the work folder
#     -h, --help          this text
# Prints per scenario and variant: goals reached of given, mean time to a goal reached (s),
# collisions with people while the robot moved, contacts while it stood, the least distance to a
# person (the least over the seeds and the mean of each run's), emergency stops, the robot's
# position error (RMSE, m); and the ratio of the mean time to goal to the reference's.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
SEEDS="1 2 3 4 5 6"; SCENARIOS="room_people"; OUT=/tmp/dynslam-nav; BUILD="$ROOT/build"
JOBS=2; REPORT_ONLY=0; SETS=""
while [ $# -gt 0 ]; do
  case "$1" in
    --seeds) SEEDS="$2"; shift 2 ;;
    --scenarios) SCENARIOS="$2"; shift 2 ;;
    --out) OUT="$2"; shift 2 ;;
    --build) BUILD="$(realpath -m "$2")"; shift 2 ;;
    --jobs) JOBS="$2"; shift 2 ;;
    --set) SETS="$SETS --set $2"; shift 2 ;;
    --report-only) REPORT_ONLY=1; shift ;;
    -h | --help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"; exit 0 ;;
    *) echo "nav.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
B="$BUILD/bin"
mkdir -p "$OUT"
# A folder with bin/ only (a copy of the programs, to keep running while the tree is rebuilt) is
# used as it is.
[ "$REPORT_ONLY" = 1 ] || [ ! -f "$BUILD/CMakeCache.txt" ] ||
  cmake --build "$BUILD" -j2 --target dynslam-nav-demo > "$OUT/build.log" 2>&1 ||
  { echo "nav.sh: the build failed, see $OUT/build.log" >&2; exit 1; }
VARIANTS="ground_truth horizon0 predicted"

job() {  # scenario variant seed
  local dir="$OUT/$1/$2/seed$3" extra=""
  case "$2" in
    ground_truth) extra="--obstacles ground_truth" ;;
    horizon0) extra="--obstacles estimated --set Navigation.obstacle_horizon_s=0" ;;
    predicted) extra="--obstacles estimated" ;;
  esac
  # shellcheck disable=SC2086
  # Solves end on their iteration count (not the wall clock): runs side by side repeat exactly.
  "$B/dynslam-nav-demo" --config "$ROOT/params/nav/$1.ini" --out "$dir" --set "Scenario.seed=$3" \
    --set Estimator.max_solver_time=100 $extra $SETS --quiet > "$dir.log" 2>&1 || echo "nav.sh: $1 $2 seed $3 failed, see $dir.log" >&2
}
export -f job
export B OUT ROOT SETS

[ "$REPORT_ONLY" = 1 ] || {
  for sc in $SCENARIOS; do for v in $VARIANTS; do mkdir -p "$OUT/$sc/$v"; for seed in $SEEDS; do
    echo "job $sc $v $seed"; done; done; done | xargs -P "$JOBS" -L 1 bash -c '"$@"' _
}

field() { sed -n "s/^  \"$2\": \([^,]*\),\{0,1\}$/\1/p" "$1"; }  # a top-level number of nav.json
echo "data: simulator, closed loop; detector: ground truth (params/sim_vio.ini's: 10 % misses, 3 px jitter); seeds $SEEDS$SETS"
for sc in $SCENARIOS; do
  echo "== $sc"
  printf '%-13s %-8s %-10s %-10s %-8s %-17s %-6s %-8s %s\n' variant goals "time (s)" collisions \
    "still" "min dist (m)" "stops" "error" "time / reference"
  reference=""
  for v in $VARIANTS; do
    reached=0 total=0 timeSum=0 coll=0 still=0 minAll=1e9 minSum=0 stops=0 errSum=0 runs=0
    for seed in $SEEDS; do
      j="$OUT/$sc/$v/seed$seed/nav.json"
      [ -f "$j" ] || { echo "nav.sh: $j missing" >&2; continue; }
      r=$(field "$j" goals_reached); t=$(field "$j" mean_time_to_goal_s)
      reached=$((reached + r)); total=$((total + $(field "$j" goals_total)))
      timeSum=$(awk -v a="$timeSum" -v b="$t" -v n="$r" 'BEGIN { print a + b * n }')
      coll=$((coll + $(field "$j" collisions_people)))
      still=$((still + $(field "$j" contacts_people_robot_still)))
      d=$(field "$j" min_distance_people_m)
      minAll=$(awk -v a="$minAll" -v b="$d" 'BEGIN { print ((b < a) ? b : a) }')
      minSum=$(awk -v a="$minSum" -v b="$d" 'BEGIN { print a + b }')
      stops=$((stops + $(field "$j" emergency_stops)))
      errSum=$(awk -v a="$errSum" -v b="$(field "$j" position_error_rmse_m)" 'BEGIN { print a + b }')
      runs=$((runs + 1))
    done
    [ "$runs" -gt 0 ] || continue
    meanTime=$(awk -v s="$timeSum" -v n="$reached" 'BEGIN { printf "%.1f", n ? s / n : 0 }')
    [ "$v" = ground_truth ] && reference="$meanTime"
    ratio=$(awk -v a="$meanTime" -v r="$reference" 'BEGIN { printf "%.2f", (r > 0) ? a / r : 0 }')
    printf '%-13s %-8s %-10s %-10s %-8s %-17s %-6s %-8s %s\n' "$v" "$reached/$total" "$meanTime" \
      "$coll" "$still" "$(awk -v a="$minAll" -v s="$minSum" -v n="$runs" 'BEGIN { printf "%.2f / %.2f", a, s / n }')" \
      "$stops" "$(awk -v s="$errSum" -v n="$runs" 'BEGIN { printf "%.3f", s / n }')" "$ratio"
  done
done
