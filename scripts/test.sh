#!/usr/bin/env bash
# Set-up (scripts/setup.sh: every target, the tests included) followed by the whole test suite.
# Tests that need ../shared/data or ../shared/models skip, saying why, when that folder is absent.
#
#   bash scripts/test.sh [--sanitize address,undefined | --sanitize thread]
#     --sanitize LIST  build with those sanitizers into their own folder (default
#                      build-sanitize-address-undefined/, build-sanitize-thread/) and run the
#                      suite there; any finding fails its test. thread: only the tests that
#                      start threads (the rawlog reader, the real-time detector, System's
#                      thread, the live sensors, the renderer's threads)
#     -h, --help   this text
#   Environment: BUILD_DIR (default build/), DYNSLAM_SHARED_DIR (default ../shared).
#   Exit codes: 0 every test passed, 1 the set-up failed, 8 some test failed (ctest's code),
#   2 usage. Outputs: the build in $BUILD_DIR; ctest's log in $BUILD_DIR/Testing/Temporary.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
SANITIZE=""
while (($#)); do
  case "$1" in
    -h|--help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"; exit 0 ;;
    --sanitize)
      case "${2:-}" in
        address,undefined|undefined,address|address|undefined|thread) SANITIZE="$2"; shift ;;
        *) echo "test: --sanitize takes address,undefined or thread (see --help)" >&2; exit 2 ;;
      esac ;;
    *) echo "test: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
  shift
done

CTEST_ARGS=()
if [ -z "$SANITIZE" ]; then
  BUILD_DIR="${BUILD_DIR:-$ROOT/build}"
  BUILD_DIR="$BUILD_DIR" bash "$ROOT/scripts/setup.sh"
else
  BUILD_DIR="${BUILD_DIR:-$ROOT/build-sanitize-${SANITIZE//,/-}}"
  TARGETS=()  # address,undefined: everything; thread: the test programs that start threads
  [ "$SANITIZE" = thread ] && TARGETS=(io_test detection_test system_test sim_render_test
                                       live_sensors_test runner_test)
  SUPP="$ROOT/scripts/sanitizers"
  # MRPT, OpenCV and Ceres are not instrumented: what they do that the sanitizers cannot see
  # is suppressed (scripts/sanitizers/*.supp); a finding in our code stops its test with a
  # report. A finding exits 66: neither a program's own 0 / 1 nor a signal, so no test mistakes it.
  export ASAN_OPTIONS="detect_leaks=1:strict_string_checks=1:exitcode=66"
  export LSAN_OPTIONS="suppressions=$SUPP/lsan.supp:print_suppressions=0:exitcode=66"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:exitcode=66:suppressions=$SUPP/ubsan.supp"
  # OpenCV tries every capture back-end on a file it cannot open, gPhoto2's too, and libgphoto2
  # leaks the USB port list of that probe from a plug-in it unloads (no stack LSan can name).
  export OPENCV_VIDEOIO_PRIORITY_GPHOTO2=0
  export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:exitcode=66:suppressions=$SUPP/tsan.supp"
  # Set before the build: it runs each test program to list its tests.
  BUILD_DIR="$BUILD_DIR" bash "$ROOT/scripts/setup.sh" --sanitize "$SANITIZE" "${TARGETS[@]}"
  if [ "$SANITIZE" = thread ]; then
    CTEST_ARGS=(-R 'FrameReader|Realtime|SystemTest\.Threaded|LiveSensors|RenderSpeed\.ThreadCount')
  fi
  # Instrumented code runs 2-15 x slower: ctest's per-test limit grows with it.
  CTEST_ARGS+=(--timeout 3000)
fi
cd "$BUILD_DIR"
ctest --output-on-failure -j"$(nproc 2>/dev/null || echo 2)" "${CTEST_ARGS[@]}"
