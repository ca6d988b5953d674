# shellcheck shell=bash
# Tables 1, 2 and 8 of REPORT.md (sourced by report.sh): perception quality and the timings,
# from $OUT/perception (bench-segmentation, bench-detection) and $OUT/timing (dynslam runs).

# segStats SC: over the seeds' bench-segmentation outputs, "KEY VALUE" lines: means of the
# quality figures, the median of the per-seed time medians.
segStats() {
  awk '
    /mask IoU, people >= 50 % visible/ {
      match($0, /mean [0-9.]+/); iou += substr($0, RSTART + 5, RLENGTH - 5)
      match($0, /median [0-9.]+/); iouMed += substr($0, RSTART + 7, RLENGTH - 7); k++
      match($0, /visible \([0-9]+\)/); scored += substr($0, RSTART + 9, RLENGTH - 10) }
    /precision [0-9.]+, recall [0-9.]+ \(means\)/ {  # the people line, not the cars one
      match($0, /precision [0-9.]+/); prec += substr($0, RSTART + 10, RLENGTH - 10)
      match($0, /recall [0-9.]+/); rec += substr($0, RSTART + 7, RLENGTH - 7) }
    /time per frame: median/ {
      match($0, /median [0-9.]+ ms/); t[++nt] = substr($0, RSTART + 7, RLENGTH - 10) + 0
      match($0, /\([0-9.]+ objects/); obj += substr($0, RSTART + 1, RLENGTH - 9) }
    /^ *(none \(visible|mild \(|severe \()/ {
      cls = $1; match($0, /\( *[0-9]+\)/); n[cls] += substr($0, RSTART + 1, RLENGTH - 2)
      split(substr($0, RSTART + RLENGTH), f, " "); mean[cls] += f[1]; med[cls] += f[2]
      sub(/%/, "", f[3]); w5[cls] += f[3]; c[cls]++ }
    END {
      if (!k) { print "missing 1"; exit }
      for (i = 1; i <= nt; ++i) for (j = i + 1; j <= nt; ++j) if (t[j] < t[i]) { x = t[i]; t[i] = t[j]; t[j] = x }
      printf "iou %.3f\niou_median %.3f\nprecision %.3f\nrecall %.3f\n", iou / k, iouMed / k, prec / k, rec / k
      printf "time_ms %.3f\nobjects %.1f\nseeds %d\nscored %d\n", t[int(nt / 2) + 1], obj / nt, k, scored
      # A class no person fell into (n = 0) prints zeros: leave it out.
      for (cls in c) if (n[cls]) printf "%s_n %d\n%s_mean %.2f\n%s_median %.2f\n%s_within5 %.0f\n", cls, n[cls], cls, mean[cls] / c[cls], cls, med[cls] / c[cls], cls, w5[cls] / c[cls]
    }' "$OUT"/perception/seg_"$1"_seed*.txt 2>/dev/null
}
stat() { awk -v k="$2" '$1 == k { print $2 }' <<< "$1"; }

# detLine FILE NAME-REGEX: "median_ms people_per_frame" of that bench-detection row.
detLine() { awk -v re="$2" '$0 ~ re { printf "%s %s", $(NF - 4), $(NF - 1); exit }' "$1"; }

table1() {
  local sc s d y3 y2 hog truth
  echo "## Table 1 analogue: detector and segmentation time per frame, mask quality"
  echo
  echo "Detector: \`bench-detection\` on 30 colour frames spread over the scenario (seed $FIRST_SEED), median"
  echo "latency and people found per frame, against the true people per frame (all that project / at"
  echo "least half visible). YOLOX runs on a 416 x 320 input (\`trim_padding\`, the default), the 4:3"
  echo "frame without the square letterbox's grey rows. Segmentation: \`bench-segmentation --every 3\`"
  echo "with the ground-truth boxes of the people at least 20 % visible (those the system's ground-truth"
  echo "detector reports; \`--min-visible\`), \`object_cluster = occluder_aware\`, \`overlap_rule = connected\`, every seed: median time per frame (median over the"
  echo "seeds), mask IoU against the simulator's instance labels for people >= 50 % visible, precision"
  echo "and recall (means over the seeds); on augmented_7scenes the inserted people's boxes and labels"
  echo "where they are composited into the real Kinect depth (real pixels are background). Paper"
  echo "(R7-5800H + RTX 3060): YOLO 18-20 ms, segmentation 0.7-1.6 ms, against Mask R-CNN 86-95 ms."
  echo
  echo "| scenario | YOLOX-nano 416: ms / people per frame | YOLOX-nano 320 | HOG | true people per frame (all / >= 50 % visible) | segmentation ms (objects per frame) | mask IoU mean / median (people scored) | precision / recall |"
  echo "|---|---|---|---|---|---|---|---|"
  for sc in $SCENARIOS; do
    d="$OUT/perception/det_$sc.txt"
    if [ ! -f "$d" ]; then y3="not run"; y2="-"; hog="-"; truth="-"
    elif grep -q ABSENT "$d"; then y3="skipped: ../shared/models/yolox_nano.onnx absent"; y2="-"; hog="-"; truth="-"
    elif grep -q FAILED "$d"; then y3="failed (see $d)"; y2="-"; hog="-"; truth="-"
    else
      y3=$(detLine "$d" '^yolox_nano input 416 +[0-9]' | awk '{ printf "%.1f / %.2f", $1, $2 }')
      y2=$(detLine "$d" '^yolox_nano input 320 +[0-9]' | awk '{ printf "%.1f / %.2f", $1, $2 }')
      hog=$(detLine "$d" '^hog people' | awk '{ printf "%.1f / %.2f", $1, $2 }')
      truth=$(awk '/^TRUTH/ { printf "%s / %s", $3, $5 }' "$d")
    fi
    s=$(segStats "$sc")
    if [ -z "$s" ] || [ -n "$(stat "$s" missing)" ]; then
      echo "| $sc | $y3 | $y2 | $hog | $truth | failed (see $OUT/perception/seg_${sc}_seed*.txt) | - | - |"
    elif [ "$(stat "$s" scored)" = 0 ]; then
      echo "| $sc | $y3 | $y2 | $hog | $truth | $(stat "$s" time_ms) ($(stat "$s" objects)) | no person >= 50 % visible | - |"
    else
      echo "| $sc | $y3 | $y2 | $hog | $truth | $(stat "$s" time_ms) ($(stat "$s" objects)) | $(stat "$s" iou) / $(stat "$s" iou_median) ($(stat "$s" scored)) | $(stat "$s" precision) / $(stat "$s" recall) |"
    fi
  done
  echo
}

table2() {
  local sc s cls
  echo "## Table 2 analogue: object depth d_t under no, mild and severe occlusion"
  echo
  echo "|d_t − true depth| / true depth, % (true depth: median depth of the person's visible pixels),"
  echo "people at least 20 % visible with ground-truth boxes, same runs as Table 1: mean and median of the error (means over"
  echo "the seeds), the share within 5 %, and how many person-frames were scored (all seeds). Paper"
  echo "(two staged scenes): 0.2-3.5 % error with and without occlusion."
  echo
  echo "| scenario | none (visible >= 0.9): mean / median / <= 5 % (n) | mild (0.5-0.9) | severe (0.2-0.5) |"
  echo "|---|---|---|---|"
  for sc in $SCENARIOS; do
    s=$(segStats "$sc")
    if [ -z "$s" ] || [ -n "$(stat "$s" missing)" ]; then echo "| $sc | failed (see $OUT/perception) | - | - |"; continue; fi
    printf '| %s' "$sc"
    for cls in none mild severe; do
      if [ -z "$(stat "$s" "${cls}_n")" ]; then printf ' | -'; continue; fi
      printf ' | %s %% / %s %% / %s %% (%s)' "$(stat "$s" "${cls}_mean")" "$(stat "$s" "${cls}_median")" \
        "$(stat "$s" "${cls}_within5")" "$(stat "$s" "${cls}_n")"
    done
    echo " |"
  done
  echo
}

# csvMedian FILE EXPR: upper median over the frames of timing.csv; EXPR is a column name or
# "thread" (pipeline_ms minus Detection_ms and Estimator_ms: the stages of the paper's tracking thread).
csvMedian() {
  awk -F, -v e="$2" 'NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
    { if (e == "thread") print $col["pipeline_ms"] - $col["Detection_ms"] - $col["Estimator_ms"]; else if (e in col) print $col[e] }' \
    "$1" | sort -g | awk '{ v[NR] = $1 } END { if (NR) printf "%.3f", v[int(NR / 2) + 1]; else printf "-" }'
}
num() { local x; x=$(jsonField "$1" "$2" 2>/dev/null); awk -v x="$x" -v f="$3" 'BEGIN { if (x == "") printf "-"; else printf f, x }'; }

table8() {
  local sc T D R
  echo "One deterministic run per scenario (seed $FIRST_SEED, ours, ground-truth detector, as fast as"
  echo "it goes) for the stages, and one \`--realtime\` run (frames handed over at the camera's 30 Hz)"
  echo "with YOLOX-nano in its own detection thread (\`Detection.mode = realtime\`, the tracker's"
  echo "predicted boxes segmented on frames without a fresh detection) for the detection thread and"
  echo "the end-to-end rate. Nothing else of this command ran meanwhile. Mapping to the paper's"
  echo "columns: feature tracking = grey image, pyramid, KLT both ways and the fundamental RANSAC;"
  echo "feature extraction = spacing and new Shi-Tomasi corners (both from \`FeatureTracking\`);"
  echo "tracking thread = every stage but detection and the estimator, per frame (Segmentation,"
  echo "Tracking, FeatureTracking, DynamicClassification; here they run in the pipeline's one thread,"
  echo "as does the estimator); dynamic feature recognition = \`DynamicClassification\` (scene flow,"
  echo "rigid sets); target state estimation = \`Tracking\` (the Kalman box filters);"
  echo "state-estimation thread = \`Estimator\` per frame, and its window solve per keyframe."
  echo "Paper (R7-5800H + RTX 3060): 1.536, 1.178, 5.644, 0.625, 0.112, 32.801, 19.680 ms; 30 FPS."
  echo
  echo "| scenario | feature tracking | feature extraction | tracking thread | dynamic feature recognition | target state estimation | state estimation: per frame / solve per keyframe | detection thread (YOLOX-nano 416): ms per run / Hz | FPS as fast as possible | real time: FPS / lag median ms / frames late |"
  echo "|---|---|---|---|---|---|---|---|---|---|"
  for sc in indoor_people_high market_crowd_high outdoor_street_high; do
    T="$OUT/timing/$sc"; D="$T/det"; R="$T/rt"
    if [ ! -f "$D/timing.csv" ] || [ "$(jsonField "$D/summary.json" status)" != ok ]; then
      echo "| $sc | failed (see $T/det.log) | | | | | | | | |"; continue
    fi
    local det rt
    if [ -f "$T/rt.absent" ]; then det="skipped: ../shared/models absent"; rt="-"
    elif [ "$(jsonField "$R/summary.json" status 2>/dev/null)" != ok ]; then det="failed (see $T/rt.log)"; rt="-"
    else
      det="$(num "$R/summary.json" detector_ms %.1f) / $(num "$R/summary.json" detector_hz %.1f)"
      rt="$(num "$R/summary.json" fps %.1f) / $(num "$R/summary.json" lag_median_ms %.0f) / $(num "$R/summary.json" frames_late %d) of $(num "$R/summary.json" frames %d)"
    fi
    echo "| $sc | $(num "$D/summary.json" tracking_ms_median %.3f) | $(num "$D/summary.json" extraction_ms_median %.3f) | $(csvMedian "$D/timing.csv" thread) | $(csvMedian "$D/timing.csv" DynamicClassification_ms) | $(csvMedian "$D/timing.csv" Tracking_ms) | $(csvMedian "$D/timing.csv" Estimator_ms) / $(num "$D/summary.json" solve_ms_median %.1f) | $det | $(num "$D/summary.json" fps %.1f) | $rt |"
  done
  echo
}
