#!/usr/bin/env bash
# The README's test command: installs what is missing, builds everything and runs all tests.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh --with-browser --with-freecad
BUILD_DIR=${BUILD_DIR:-build}
extra=()
[ "${CI:-}" = "true" ] && extra+=(-DCABLEFIT_WERROR=ON)
cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release "${extra[@]}"
cmake --build "$BUILD_DIR" -j "$(nproc)"
tools/install-freecad-workbench.sh "$BUILD_DIR"
ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$(nproc)"
