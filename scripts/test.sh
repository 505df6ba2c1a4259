#!/usr/bin/env bash
# The full test suite:
#  1. installs and builds everything (scripts/setup.sh) and runs the CTest suite in build/
#     (tests, examples, the Python module's pytest suite, the Doxygen warnings-as-errors
#     build, the install check);
#  2. the robustness stage (scripts/sanitize_and_fuzz.sh): the suite again under
#     AddressSanitizer + UndefinedBehaviorSanitizer in build/sanitize/, then 60 s of
#     libFuzzer on hostile OFF input (HEAT_DIFFUSION_FUZZ_SECONDS to change it).
# HEAT_DIFFUSION_SKIP_SANITIZERS=1 skips stage 2 (for a quick run while editing; the
# CI never sets it).
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
bash scripts/setup.sh
(cd build && ctest --output-on-failure -j "$(nproc)")
echo "== build and CTest suite: $((SECONDS - start)) s"
if [ "${HEAT_DIFFUSION_SKIP_SANITIZERS:-0}" = 1 ]; then
  echo "== HEAT_DIFFUSION_SKIP_SANITIZERS=1: the sanitizer and fuzzing stage is skipped"
  exit 0
fi
bash scripts/sanitize_and_fuzz.sh
echo "== all stages: $((SECONDS - start)) s"
