#!/usr/bin/env bash
# Relax figures of real-shaped KBL harnesses at three sizes (tools/make_vehicle_kbl.py: 183, 500
# and 1000 segments), end to end as `cablefit relax` runs them, pictures and STEP included:
# `cablefit bench --relax` rows (seconds per stage, the network's levels) per size, so the growth
# from 183 to 1000 segments can be read off. Usage: tools/bench_harness.sh [BUILD_DIR] [REPEAT]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
repeat=${2:-3}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
for n in 183 500 1000; do
  python3 tools/make_vehicle_kbl.py "$dir/vehicle_harness_$n.kbl" --segments "$n" >/dev/null
done
"$build/addin/cablefit" bench --repeat "$repeat" --relax "$dir"/vehicle_harness_183.kbl \
  "$dir"/vehicle_harness_500.kbl "$dir"/vehicle_harness_1000.kbl
