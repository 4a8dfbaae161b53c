#!/usr/bin/env bash
# The README's test command: installs what is missing, builds everything and runs all tests.
# With CI=true (what .ci/run sets) or --hardening it then runs the hardening stages:
#   2. tools/sanitize.sh  the whole suite again built with ASan + UBSan + LSan (build-asan)
#   3. tools/fuzz.sh      every libFuzzer target for FUZZ_SECONDS (default 30) on its seed corpus
set -euo pipefail
cd "$(dirname "$0")/.."
hardening=false
[ "${CI:-}" = "true" ] && hardening=true
[ "${1:-}" = "--hardening" ] && hardening=true
deps=(--with-browser --with-freecad)
$hardening && deps+=(--with-fuzz)
tools/install-deps.sh "${deps[@]}"

BUILD_DIR=${BUILD_DIR:-build}
extra=()
[ "${CI:-}" = "true" ] && extra+=(-DCABLEFIT_WERROR=ON)
stage_start=$SECONDS
cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release "${extra[@]}"
cmake --build "$BUILD_DIR" -j "$(nproc)"
tools/install-freecad-workbench.sh "$BUILD_DIR"
ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$(nproc)"
echo "test.sh: release build and tests took $((SECONDS - stage_start)) s"

if $hardening; then
  stage_start=$SECONDS
  tools/sanitize.sh
  echo "test.sh: sanitizer build and tests took $((SECONDS - stage_start)) s"
  stage_start=$SECONDS
  tools/fuzz.sh
  echo "test.sh: fuzzing took $((SECONDS - stage_start)) s"
fi
