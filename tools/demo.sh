#!/usr/bin/env bash
# The README's demo command: installs what is missing, builds, and runs cablefit on samples/.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh
BUILD_DIR=${BUILD_DIR:-build}
cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build "$BUILD_DIR" -j "$(nproc)" --target cablefit
CABLEFIT="$BUILD_DIR/addin/cablefit"
OUT=${OUT:-demo-out}
mkdir -p "$OUT"
for c in samples/cases/*/; do
  "$CABLEFIT" simulate "$c/case.json" --out "$OUT/simulate/$(basename "$c")"
done
echo "demo: results in $OUT/"
