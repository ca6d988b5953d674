#!/usr/bin/env bash
# One estimator setting against the defaults, seed by seed: renders simulator scenarios (kept
# for the next comparison), runs the whole system (params/sim_vio.ini, the ground-truth
# detector, full dynamic handling, repeatable solves: max_solver_time = 100) once as configured
# and once with the given --set options, and prints APE RMSE of each (SE(3)-aligned; on the
# first pose where the path is too straight for Umeyama, the street), their ratio and the
# window solve median. The last line: the geometric mean of the ratios and how many improved.
#
#   bash bench/compare_settings.sh --set Section.key=value [--set ...] [--seeds "1 2"]
#                                  [--scenarios "a b"] [--duration S] [--out DIR]
#                                  [--build DIR] [--jobs N]
#     --set S.k=v         a setting of the compared variant (repeatable; at least one)
#     --seeds "A B"       Scenario.seed values (default "1 2 3 4")
#     --scenarios "a b"   scenarios of params/sim/ (default indoor_people_high
#                         outdoor_street_high market_crowd_high)
#     --duration S        seconds rendered (default 20)
#     --out DIR           work folder (default /tmp/dynslam-compare): seedN/SCENARIO/ the
#                         renders (about 0.6 GB each), run_base/ and run_variant/ the runs
#     --build DIR         the build folder whose bin/ holds the programs (default build/)
#     --jobs N            renders and runs side by side (default 2)
#     -h, --help          this text
# Writes OUT/rows.tsv: seed, scenario, ape_base, ape_variant, ratio, solve_ms_base,
# solve_ms_variant.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=bench/lib.sh
source "$ROOT/bench/lib.sh"
SEEDS="1 2 3 4"; SCENARIOS="indoor_people_high outdoor_street_high market_crowd_high"
DURATION=20; OUT=/tmp/dynslam-compare; BUILD="$ROOT/build"; JOBS=2; VARIANT=""
while [ $# -gt 0 ]; do
  case "$1" in
    --set) VARIANT="$VARIANT --set $2"; shift 2 ;;
    --seeds) SEEDS="$2"; shift 2 ;;
    --scenarios) SCENARIOS="$2"; shift 2 ;;
    --duration) DURATION="$2"; shift 2 ;;
    --out) OUT="$2"; shift 2 ;;
    --build) BUILD="$(realpath -m "$2")"; shift 2 ;;
    --jobs) JOBS="$2"; shift 2 ;;
    -h | --help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"; exit 0 ;;
    *) echo "compare_settings.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
[ -n "$VARIANT" ] || { echo "compare_settings.sh: give the compared setting with --set" >&2; exit 2; }
B="$BUILD/bin"
mkdir -p "$OUT"
cmake --build "$BUILD" -j2 --target dynslam dynslam-sim dynslam-eval > "$OUT/build.log" 2>&1 ||
  { echo "compare_settings.sh: the build failed, see $OUT/build.log" >&2; exit 1; }

render() {  # seed scenario
  simRender "$OUT/seed$1/$2" "$2" "$1"
}

run() {  # seed scenario name settings...
  local seed="$1" sc="$2" name="$3"; shift 3
  simVioRun "$OUT/seed$seed/$sc" "$OUT/seed$seed/$sc/run_$name" "$seed" "$@"
}
export -f render run simRender simVioRun variantSettings
export B OUT ROOT DURATION

for seed in $SEEDS; do for sc in $SCENARIOS; do echo "render $seed $sc"; done; done |
  xargs -P "$JOBS" -L 1 bash -c '"$@"' _
for seed in $SEEDS; do for sc in $SCENARIOS; do
  echo "run $seed $sc base"; echo "run $seed $sc variant $VARIANT"
done; done | sed 's/ *$//' | xargs -P "$JOBS" -L 1 bash -c '"$@"' _

ape() { jsonField "$1/ape.json" rmse 2>/dev/null || true; }
{
  printf 'seed\tscenario\tape_base\tape_variant\tratio\tsolve_ms_base\tsolve_ms_variant\n'
  for seed in $SEEDS; do for sc in $SCENARIOS; do
    D="$OUT/seed$seed/$sc"
    a=$(ape "$D/run_base"); b=$(ape "$D/run_variant")
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$seed" "$sc" "${a:--}" "${b:--}" \
      "$(awk -v a="$a" -v b="$b" 'BEGIN { if (a > 0 && b > 0) printf "%.3f", b / a; else printf "-" }')" \
      "$(jsonField "$D/run_base/summary.json" solve_ms_median)" \
      "$(jsonField "$D/run_variant/summary.json" solve_ms_median)"
  done; done
} > "$OUT/rows.tsv"
column -t "$OUT/rows.tsv"
awk -F'\t' -v v="$VARIANT" 'NR > 1 && $5 != "-" { s += log($5); n++; if ($5 < 1) better++ }
  END { if (n) printf "%s: geometric mean ratio %.3f over %d runs, %d better\n", v, exp(s / n), n, better }' \
  "$OUT/rows.tsv"
