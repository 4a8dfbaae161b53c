#!/usr/bin/env bash
# Installs the Cablefit FreeCAD workbench for the current user: FreeCAD's user Mod folder gets a
# folder Cablefit/ of symbolic links to the workbench sources (addin/freecad/workbench) and to the
# built module cablefit_native (BUILD_DIR/addin/freecad), so a rebuild or a source change needs no
# second install. FreeCAD 0.20 loads user workbenches from $(FreeCAD.getUserAppDataDir())/Mod,
# ~/.local/share/FreeCAD/Mod on Debian 12; FREECAD_MOD_DIR overrides it.
# Usage: tools/install-freecad-workbench.sh [BUILD_DIR]   (default: build)
# Without FreeCAD or without the module's prerequisites it says so and exits 0 (nothing to do).
set -euo pipefail
cd "$(dirname "$0")/.."
SRC=$(pwd)
BUILD_DIR=$(realpath -m "${1:-build}")

if ! command -v freecadcmd >/dev/null; then
  echo "install-freecad-workbench: FreeCAD not installed (tools/install-deps.sh --with-freecad); skipped"
  exit 0
fi
if ! cmake --build "$BUILD_DIR" --target cablefit_native -j "$(nproc)" >/dev/null 2>&1; then
  echo "install-freecad-workbench: cannot build cablefit_native in $BUILD_DIR (needs pybind11-dev" \
       "and python3-dev for /usr/bin/python3, and a configured build); skipped" >&2
  exit 0
fi
module=$(ls "$BUILD_DIR"/addin/freecad/cablefit_native*.so)

if [ -z "${FREECAD_MOD_DIR:-}" ]; then
  # Ask FreeCAD itself (it honours FREECAD_USER_HOME); the Debian 0.20 default is the fallback.
  data=$(freecadcmd -c "import FreeCAD; print('USERDATA=' + FreeCAD.getUserAppDataDir())" 2>/dev/null |
         sed -n 's/^USERDATA=//p' | tail -1)
  FREECAD_MOD_DIR="${data:-$HOME/.local/share/FreeCAD/}Mod"
fi
MOD_DIR=$FREECAD_MOD_DIR
target="$MOD_DIR/Cablefit"
mkdir -p "$target"
for f in Init.py InitGui.py cablefit_workbench Resources; do
  ln -sfn "$SRC/addin/freecad/workbench/$f" "$target/$f"
done
rm -f "$target"/cablefit_native*.so
ln -sfn "$module" "$target/$(basename "$module")"

# FreeCAD puts each Mod folder on sys.path: the module and the workbench must import from there.
check=$(mktemp --suffix=.py)
trap 'rm -f "$check"' EXIT
cat > "$check" <<PY
import os, sys
import cablefit_native, cablefit_workbench
ok = os.path.realpath(os.path.dirname(cablefit_workbench.__file__)).startswith(
    os.path.realpath("$SRC")) and hasattr(cablefit_native, "relax")
print("install-freecad-workbench: " + ("OK" if ok else "FAILED"))
sys.stdout.flush()
os._exit(0 if ok else 1)
PY
if ! HOME="$HOME" freecadcmd "$check" 2>&1 | grep -q "install-freecad-workbench: OK"; then
  echo "install-freecad-workbench: FreeCAD does not load $target (is $MOD_DIR its user Mod folder?)" >&2
  exit 1
fi
echo "install-freecad-workbench: Cablefit workbench in $target (module $module)"
