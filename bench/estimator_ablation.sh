#!/usr/bin/env bash
# The estimator's ablation table (issue 6): renders simulator scenarios, runs the whole system
# (params/sim_vio.ini) with each dynamic_handling variant built so far, and prints APE RMSE
# (SE(3)-aligned), the ratios the issue asks for, the static scenario's error as a fraction of
# its path length, and the estimator's median solve time per keyframe.
#   bash bench/estimator_ablation.sh [--build DIR] [--out DIR] [--duration S] [--scenarios "a b"]
# Variants: none (every feature static, VINS-Mono-like), remove (dynamic features dropped,
# Dynamic-VINS-like), full (the paper; so far with its non-rigid factors r_D only: the rigid
# object factors are not in the window yet).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="$ROOT/build"; OUT="/tmp/dynslam-ablation"; DURATION=20
SCENARIOS="static indoor_people_high"
while [ $# -gt 0 ]; do
  case "$1" in
    --build) BUILD="$2"; shift 2 ;;
    --out) OUT="$2"; shift 2 ;;
    --duration) DURATION="$2"; shift 2 ;;
    --scenarios) SCENARIOS="$2"; shift 2 ;;
    *) echo "estimator_ablation.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
BIN="$BUILD/bin"
for p in dynslam dynslam-sim dynslam-eval; do
  [ -x "$BIN/$p" ] || { echo "estimator_ablation.sh: $BIN/$p is missing (build first)" >&2; exit 1; }
done
mkdir -p "$OUT"

json() { sed -n "s/^ *\"$2\": *\([0-9.eE+-]*\).*/\1/p" "$1" | head -1; }
pathLength() {
  awk '!/^#/ { if (n++) d += sqrt(($2-x)^2 + ($3-y)^2 + ($4-z)^2); x=$2; y=$3; z=$4 } END { printf "%.2f", d }' "$1"
}

printf '%-22s %-8s %10s %10s %9s %9s\n' scenario variant "APE [m]" "% path" "solve ms" restarts
for sc in $SCENARIOS; do
  S="$OUT/$sc"
  if [ ! -f "$S/sim.rawlog" ]; then
    "$BIN/dynslam-sim" --config "$ROOT/params/sim/$sc.ini" --out "$S" \
      --set Scenario.duration="$DURATION" --quiet > /dev/null 2>&1
  fi
  length=$(pathLength "$S/groundtruth.tum")
  declare -A ape=()
  for v in none remove full; do
    R="$S/run_$v"
    "$BIN/dynslam" --config "$ROOT/params/sim_vio.ini" --rawlog "$S/sim.rawlog" --out "$R" --quiet \
      --set Detection.objects="$S/objects.txt" --set Estimator.dynamic_handling=$v > "$R.log" 2>&1 || true
    "$BIN/dynslam-eval" ape "$S/groundtruth.tum" "$R/trajectory.tum" --align se3 --json "$R/ape.json" \
      > /dev/null 2>&1 || true
    ape[$v]=$(json "$R/ape.json" rmse)
    solve=$(json "$R/summary.json" solve_ms_median)
    restarts=$(json "$R/summary.json" resets)
    pct=$(awk -v a="${ape[$v]:-nan}" -v l="$length" 'BEGIN { printf "%.3f", 100 * a / l }')
    shown=$(awk -v a="${ape[$v]:-}" 'BEGIN { if (a == "") print "failed"; else printf "%.4f", a }')
    printf '%-22s %-8s %10s %10s %9.1f %9s\n' "$sc" "$v" "$shown" "$pct" "${solve:-0}" "${restarts:-?}"
  done
  awk -v r="${ape[remove]:-nan}" -v n="${ape[none]:-nan}" -v sc="$sc" -v l="$length" \
    -v f="${ape[full]:-nan}" \
    'BEGIN { printf "%-22s path %.2f m; full / none = %.3f (target <= 0.5), full / remove = %.3f (target <= 0.85), remove / none = %.3f\n", sc, l, f / n, f / r, r / n }'
  unset ape
done
