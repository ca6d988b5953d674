#!/usr/bin/env bash
# Installs the Debian packages dynslam needs (only those missing; as root or through sudo),
# then configures and builds into build/. Safe to run again: a second run installs nothing and
# rebuilds only what changed.
#
#   bash scripts/setup.sh [--sanitize LIST] [TARGET...]
#     TARGET     build only these CMake targets (e.g. dynslam dynslam-eval) and what they
#                need; none given: everything, the tests included
#     --sanitize LIST  build with -fsanitize=LIST (address,undefined or thread), RelWithDebInfo
#     -h, --help this text
#   Environment: BUILD_DIR (default build/).
#   Exit codes: 0 built, 1 a package could not be installed (no root, no sudo) or the build
#   failed, 2 usage. Outputs: the programs in $BUILD_DIR/bin, the test binaries in
#   $BUILD_DIR/tests.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$ROOT/build}"
TARGETS=()
CMAKE_ARGS=(-DCMAKE_BUILD_TYPE=Release -DDYNSLAM_SANITIZE=)
while (($#)); do
  case "$1" in
    -h|--help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"; exit 0 ;;
    --sanitize)
      [ -n "${2:-}" ] || { echo "setup: --sanitize needs a list (see --help)" >&2; exit 2; }
      CMAKE_ARGS=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DDYNSLAM_SANITIZE=$2"); shift ;;
    -*) echo "setup: unknown argument '$1' (see --help)" >&2; exit 2 ;;
    *) TARGETS+=(--target "$1") ;;
  esac
  shift
done

# What each package is for is in README.md ("Dependencies").
PACKAGES=(build-essential cmake ccache zlib1g-dev
          libmrpt-dev mrpt-apps libopencv-dev libceres-dev libeigen3-dev
          libgtest-dev libgmock-dev opencv-doc xvfb
          librosbag-storage-dev libsensor-msgs-dev libcv-bridge-dev libmrpt-ros1bridge-dev)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "setup: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
    SUDO="sudo"
  fi
  echo "setup: installing ${missing[*]}"
  { $SUDO apt-get update -qq &&
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
  } || { echo "setup: apt-get could not install ${missing[*]}" >&2; exit 1; }
else
  echo "setup: all Debian packages present"
fi

JOBS="$(nproc 2>/dev/null || echo 2)"
{ cmake -S "$ROOT" -B "$BUILD_DIR" "${CMAKE_ARGS[@]}" >/dev/null &&
  cmake --build "$BUILD_DIR" -j"$JOBS" "${TARGETS[@]}"
} || { echo "setup: the build failed" >&2; exit 1; }
echo "setup: programs in $BUILD_DIR/bin"
