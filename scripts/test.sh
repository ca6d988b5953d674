#!/usr/bin/env bash
# Set-up (scripts/setup.sh) followed by the whole test suite. Tests that need ../shared/data or
# ../shared/models skip, saying why, when that folder is absent.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$ROOT/build}"
bash "$ROOT/scripts/setup.sh"
cd "$BUILD_DIR"
ctest --output-on-failure -j"$(nproc 2>/dev/null || echo 2)"
