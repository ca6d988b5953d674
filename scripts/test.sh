#!/usr/bin/env bash
# Set-up (scripts/setup.sh: every target, the tests included) followed by the whole test suite.
# Tests that need ../shared/data or ../shared/models skip, saying why, when that folder is absent.
#
#   bash scripts/test.sh
#     -h, --help   this text
#   Environment: BUILD_DIR (default build/), DYNSLAM_SHARED_DIR (default ../shared).
#   Exit codes: 0 every test passed, 1 the set-up failed, 8 some test failed (ctest's code),
#   2 usage. Outputs: the build in $BUILD_DIR; ctest's log in $BUILD_DIR/Testing/Temporary.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$ROOT/build}"
case "${1:-}" in
  "") ;;
  -h|--help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"; exit 0 ;;
  *) echo "test: unknown argument '$1' (see --help)" >&2; exit 2 ;;
esac
bash "$ROOT/scripts/setup.sh"
cd "$BUILD_DIR"
ctest --output-on-failure -j"$(nproc 2>/dev/null || echo 2)"
