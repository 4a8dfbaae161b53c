#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz, clang, ASan + UBSan) in build-fuzz and runs each for
# FUZZ_SECONDS (default 30) on a scratch copy of its seed corpus. A crash, sanitizer report,
# leak, hang (> 10 s for one input) or > 2 GB of memory fails the run; the input that did it is
# kept in build-fuzz/artifacts/ (add it to tests/fuzz/regressions/<target>/ once fixed).
# FUZZ_SEED fixes the random choices of every target (CI sets it, so that a red run can be
# reproduced); unset, the clock picks them, to explore.
# Usage: tools/fuzz.sh [TARGET...]   (targets: ply centerline_csv ... see tests/fuzz; with no
# target also the CAD/mesh readers through the release build, tools/fuzz_cad.py)
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${FUZZ_BUILD_DIR:-build-fuzz}
SECONDS_PER_TARGET=${FUZZ_SECONDS:-30}
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  targets=(ply centerline_csv force_curve_csv case_json truth_json json_util harness_config
           section_json kbl)
fi
mkdir -p "$BUILD_DIR"
CC=clang CXX=clang++ cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCABLEFIT_SANITIZE=ON -DCABLEFIT_FUZZ=ON -DCABLEFIT_FREECAD=OFF > "$BUILD_DIR/configure.log" \
  || { cat "$BUILD_DIR/configure.log"; exit 1; }
cmake --build "$BUILD_DIR" -j "$(nproc)" --target "${targets[@]/#/fuzz_}"
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
artifacts="$PWD/$BUILD_DIR/artifacts"
mkdir -p "$artifacts"
failed=0
printf '%-18s %10s %10s %8s %s\n' target runs exec/s corpus result
for t in "${targets[@]}"; do
  work="$PWD/$BUILD_DIR/corpus-run/$t"
  rm -rf "$work" && mkdir -p "$work"
  log="$PWD/$BUILD_DIR/fuzz-$t.log"
  case "$t" in
    ply) dict=tests/fuzz/ply.dict ;;
    kbl) dict=tests/fuzz/kbl.dict ;;
    *_csv) dict=tests/fuzz/csv.dict ;;
    *) dict=tests/fuzz/json.dict ;;
  esac
  regressions=()
  [ -d "tests/fuzz/regressions/$t" ] && regressions=("tests/fuzz/regressions/$t")
  set +e
  "$BUILD_DIR/tests/fuzz/fuzz_$t" "$work" "tests/fuzz/corpus/$t" "${regressions[@]}" \
    -max_total_time="$SECONDS_PER_TARGET" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
    -dict="$dict" -print_final_stats=1 -artifact_prefix="$artifacts/$t-" \
    ${FUZZ_SEED:+-seed="$FUZZ_SEED"} > "$log" 2>&1
  rc=$?
  set -e
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  speed=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  size=$(ls "$work" | wc -l)
  if [ $rc -eq 0 ]; then result=ok; else result="FAILED (exit $rc, see $log)"; failed=1; fi
  printf '%-18s %10s %10s %8s %s\n' "$t" "${runs:-?}" "${speed:-?}" "$size" "$result"
  [ $rc -eq 0 ] || grep -E "ERROR|SUMMARY|threw|==[0-9]+==" "$log" | head -20 || true
done
# The CAD and mesh readers run behind the crash probe (a helper process): they are fuzzed through
# the release build's command line, by mutating the sample and third-party files (tools/fuzz_cad.py).
cablefit_bin=${RELEASE_BUILD_DIR:-build}/addin/cablefit
if [ $# -eq 0 ] && [ -x "$cablefit_bin" ]; then
  if python3 tools/fuzz_cad.py "$cablefit_bin" "$SECONDS_PER_TARGET" "$artifacts" \
      ${FUZZ_SEED:+"$FUZZ_SEED"} > "$BUILD_DIR/fuzz-cad.log" 2>&1; then
    printf '%-18s %s\n' cad "$(tail -1 "$BUILD_DIR/fuzz-cad.log")"
  else
    printf '%-18s FAILED (see %s)\n' cad "$BUILD_DIR/fuzz-cad.log"
    grep -A1 FINDING "$BUILD_DIR/fuzz-cad.log" | head -20 || true
    failed=1
  fi
fi
exit $failed
