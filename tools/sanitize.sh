#!/usr/bin/env bash
# Builds everything with AddressSanitizer + UndefinedBehaviorSanitizer + LeakSanitizer
# (-DCABLEFIT_SANITIZE=ON: every report is fatal) in build-asan and runs the whole CTest suite.
# -O1 as the sanitizers recommend (and it compiles much faster than -O3 on 2 cores). The FreeCAD
# module is left out: it is loaded into FreeCAD's uninstrumented Python, where ASan cannot run.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${ASAN_BUILD_DIR:-build-asan}
cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG" -DCABLEFIT_SANITIZE=ON -DCABLEFIT_FREECAD=OFF
cmake --build "$BUILD_DIR" -j "$(nproc)"
# Leaks in uninstrumented system libraries (fontconfig, Mesa) are not ours: tools/lsan.supp.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_odr_violation=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/tools/lsan.supp:print_suppressions=0}
# Everything runs 2-10x slower under ASan: a larger per-test limit instead of skipping tests.
ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$(nproc)" --timeout 3000
