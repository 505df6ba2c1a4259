#!/usr/bin/env bash
# Installs what the package needs from Debian 12's packages (only what is missing),
# then configures and builds everything in build/ (incrementally).
# Used by scripts/demo.sh and scripts/test.sh; run it as root or with sudo.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(g++ cmake make python3 libcgal-dev libcgal-demo libeigen3-dev libboost-dev libspectra-dev
          libsuitesparse-dev libtbb-dev clang libclang-rt-14-dev ninja-build
          doxygen python3-matplotlib python3-numpy  # the reference manual; scripts/render.py
          pybind11-dev python3-pybind11 python3-dev python3-scipy python3-meshio python3-pytest  # the Python module
          libjs-mathjax chromium  # the manual's formulas offline; checked in a browser
          time)  # /usr/bin/time -v: benchmark/Heat_diffusion/compile_cost.sh
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "== installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

echo "== building in build/"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$(nproc)" "$@"
