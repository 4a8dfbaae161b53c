#!/usr/bin/env bash
# The README's demo command: installs what is missing, builds, and runs cablefit's main jobs on
# samples/: diagnose the sample recordings, relax the sample harness CAD, compute a cross-section,
# and print the performance figures. Results (JSON, CSV, STEP, PNG, report.html) go to demo-out/.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh --with-freecad
BUILD_DIR=${BUILD_DIR:-build}
cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build "$BUILD_DIR" -j "$(nproc)" --target cablefit
tools/install-freecad-workbench.sh "$BUILD_DIR"  # FreeCAD: Cablefit workbench on next start
CABLEFIT="$BUILD_DIR/addin/cablefit"
OUT=${OUT:-demo-out}
mkdir -p "$OUT"
status=0
"$CABLEFIT" diagnose samples/cases --out "$OUT/diagnose" || status=$?
"$CABLEFIT" relax samples/harness --config samples/harness/harness.json --out "$OUT/relax" || status=$?
"$CABLEFIT" section samples/materials/examples/mixed-filled.json --out "$OUT/section.json" || status=$?
"$CABLEFIT" simulate samples/cases/sample-none --out "$OUT/simulate" || status=$?
"$CABLEFIT" bench --repeat 5
echo
echo "demo: diagnosis report $OUT/diagnose/report.html, harness report $OUT/relax/report.html"
exit $status
