#!/usr/bin/env bash
# The README's test command: installs what is missing, builds everything and runs all tests.
# With CI=true (what .ci/run sets) or --hardening it then runs the hardening stages:
#   2. tools/fuzz.sh      every libFuzzer target for FUZZ_SECONDS (default 30) on its seed corpus
#   3. tools/sanitize.sh  the whole suite again built with ASan + UBSan + LSan (build-asan),
#                         within what is left of a HARDENING_BUDGET (default 85 min, CI's limit
#                         is 90) counted from the start of this script.
# A sanitizer report or failed test in stage 3 fails the run. Running out of the budget does not
# (the machine's speed is not a defect) unless HARDENING_STRICT=1; it is printed either way. The
# long corpus tests run a subset of their cases in the sanitizer build (tests/support
# SanitizerBuild()).
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
$hardening || exit 0

stage_start=$SECONDS
# CI fuzzes with fixed seeds: the same commit gives the same mutations (exploring with new seeds
# is `tools/fuzz.sh` by hand).
[ "${CI:-}" = "true" ] && export FUZZ_SEED=${FUZZ_SEED:-20261203}
tools/fuzz.sh
echo "test.sh: fuzzing took $((SECONDS - stage_start)) s"

budget=$(( ${HARDENING_BUDGET:-5100} - SECONDS ))
if [ "$budget" -lt 600 ]; then
  echo "test.sh: SANITIZER STAGE NOT RUN: only ${budget} s of the hardening budget left"
  exit 0
fi
stage_start=$SECONDS
set +e
mkdir -p build-asan
timeout --signal=INT --kill-after=30 "$budget" tools/sanitize.sh > build-asan/sanitize.log 2>&1
rc=$?
set -e
# ctest's summary and the names of failed tests, so the CI log shows the verdict.
grep -E "tests passed|tests failed|\*\*\*Failed|Exception|Timeout|Not Run" build-asan/sanitize.log | tail -40 || true
echo "test.sh: sanitizer build and tests took $((SECONDS - stage_start)) s (full log: build-asan/sanitize.log)"
if [ $rc -eq 124 ] || [ $rc -eq 130 ]; then
  echo "test.sh: SANITIZER STAGE INCOMPLETE: stopped at the time budget (${budget} s)"
  [ "${HARDENING_STRICT:-0}" = "1" ] && exit $rc
elif [ $rc -ne 0 ]; then
  echo "test.sh: SANITIZER STAGE FAILED (exit $rc, full log above in build-asan/sanitize.log)"
  tail -200 build-asan/sanitize.log
  exit $rc
fi
exit 0
