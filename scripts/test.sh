#!/usr/bin/env bash
# Installs and builds everything (scripts/setup.sh), then runs the full CTest suite.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cd build
ctest --output-on-failure -j "$(nproc)"
bash ../scripts/sanitize_and_fuzz.sh  # ASan + UBSan suite in build/sanitize/, then 60 s of fuzzing
