#!/usr/bin/env bash
# Installs the Debian packages dynslam needs (only those missing; as root or through sudo),
# then configures and builds into build/. Safe to run again: a second run installs nothing and
# rebuilds only what changed.
#
#   bash scripts/setup.sh            # install + build
#   BUILD_DIR=out bash scripts/setup.sh
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$ROOT/build}"

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
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
else
  echo "setup: all Debian packages present"
fi

JOBS="$(nproc 2>/dev/null || echo 2)"
cmake -S "$ROOT" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$BUILD_DIR" -j"$JOBS"
echo "setup: programs in $BUILD_DIR/bin"
