# Shared by the bench scripts (sourced, not run).

# jsonField FILE KEY: the value of the first `"KEY": value` line of FILE (dynslam's summary.json,
# dynslam-eval's --json), a number or a string without its quotes; empty when absent.
jsonField() { sed -n "s/^ *\"$2\": *\"\{0,1\}\([^\",]*\).*/\1/p" "$1" | head -1; }

# variantSettings NAME: dynslam's --set options for an estimator variant (params/sim_vio.ini);
# the variants are described in bench/estimator_ablation.sh. full-no-both: the paper's Table 9
# "without rigid & non-rigid" (the full estimator with both kinds of dynamic feature dropped).
variantSettings() {
  case "$1" in
    none) echo "--set Estimator.dynamic_handling=none" ;;
    remove) echo "--set Estimator.dynamic_handling=remove" ;;
    full) echo "--set Estimator.dynamic_handling=full --set Estimator.rigid_factors=true --set Estimator.nonrigid_factors=true" ;;
    full-no-rigid) echo "--set Estimator.dynamic_handling=full --set Estimator.rigid_factors=false --set Estimator.nonrigid_factors=true" ;;
    full-no-nonrigid) echo "--set Estimator.dynamic_handling=full --set Estimator.rigid_factors=true --set Estimator.nonrigid_factors=false" ;;
    full-no-both) echo "--set Estimator.dynamic_handling=full --set Estimator.rigid_factors=false --set Estimator.nonrigid_factors=false" ;;
    # The simulator's receiver: RTK-like, 2 cm at HDOP 0.8, antenna 0.5 m above the body origin.
    full-gnss) echo "--set Estimator.dynamic_handling=full --set Estimator.use_gnss=true --set Estimator.gnss_uere_horizontal=0.025 --set Estimator.gnss_lever_arm_z=0.5" ;;
    *) echo "variantSettings: unknown variant '$1'" >&2; return 1 ;;
  esac
}

# simRender RENDER SCENARIO SEED [SETTINGS...]: dynslam-sim renders params/sim/SCENARIO.ini for
# DURATION s into RENDER (its log RENDER.log), unless RENDER/.rendered says an earlier call did.
# Needs B (the programs' folder), ROOT and DURATION.
simRender() {
  local S="$1" sc="$2" seed="$3"; shift 3
  [ -f "$S/.rendered" ] && return 0
  mkdir -p "$S"
  # shellcheck disable=SC2068
  "$B/dynslam-sim" --config "$ROOT/params/sim/$sc.ini" --out "$S" --quiet \
    --set Scenario.seed="$seed" --set Scenario.duration="$DURATION" $@ > "$S.log" 2>&1 &&
    touch "$S/.rendered"
}

# simVioRun RENDER RUN SEED [SETTINGS...]: dynslam on a simulator render (params/sim_vio.ini, the
# ground-truth detector, full dynamic handling, repeatable solves: max_solver_time = 100) into
# the fresh folder RUN (its log RUN.log), then its APE into RUN/ape.json: SE(3)-aligned, or on the
# first pose where the path is too straight for Umeyama (the street). Needs B (the programs'
# folder) and ROOT. Never fails: a failed run leaves no ape.json.
simVioRun() {
  local S="$1" R="$2" seed="$3"; shift 3
  rm -rf "$R"; mkdir -p "$R"
  # shellcheck disable=SC2046,SC2068
  "$B/dynslam" --config "$ROOT/params/sim_vio.ini" --rawlog "$S/sim.rawlog" --out "$R" --quiet \
    --no-map --set Detection.objects="$S/objects.txt" --set Detection.seed="$seed" \
    --set Estimator.max_solver_time=100 $(variantSettings full) $@ > "$R.log" 2>&1 || true
  "$B/dynslam-eval" ape "$S/groundtruth.tum" "$R/trajectory.tum" --align se3 --json "$R/ape.json" \
    >> "$R.log" 2>&1 ||
    "$B/dynslam-eval" ape "$S/groundtruth.tum" "$R/trajectory.tum" --align-origin \
      --json "$R/ape.json" >> "$R.log" 2>&1 || true
}
