#!/usr/bin/env bash
# Installs the Debian packages cablefit builds and tests with; the README's two set-up commands run it.
# Idempotent: installs only what is missing, so a second run costs a few seconds.
# Usage: tools/install-deps.sh [--with-browser] [--with-freecad] [--with-fuzz]
set -euo pipefail

pkgs=(build-essential cmake ninja-build pkg-config git python3-dev
      libgtest-dev libgmock-dev libbenchmark-dev
      libeigen3-dev libocct-data-exchange-dev libtbb-dev libfontconfig-dev
      libcgal-dev libassimp-dev libosmesa6-dev nlohmann-json3-dev libcli11-dev
      libpng-dev libstb-dev libfreetype-dev fonts-dejavu-core pybind11-dev python3-numpy
      libxml2-dev)
for arg in "$@"; do
  case "$arg" in
    --with-browser) pkgs+=(chromium chromium-driver) ;;
    --with-freecad) pkgs+=(freecad xvfb xauth) ;;
    --with-fuzz) pkgs+=(clang libclang-rt-14-dev) ;;  # libFuzzer + sanitizer runtimes
    *) echo "install-deps: unknown option $arg" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#pkgs[@]} packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y --no-install-recommends "${missing[@]}"
