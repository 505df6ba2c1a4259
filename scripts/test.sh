#!/usr/bin/env bash
# Installs and builds everything (scripts/setup.sh), then runs the full CTest suite.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cd build
ctest --output-on-failure -j "$(nproc)"
# The ASan + UBSan suite and 60 s of fuzzing (scripts/sanitize_and_fuzz.sh) are not
# part of this command yet: their CI cost has not been measured on a quiet machine.
