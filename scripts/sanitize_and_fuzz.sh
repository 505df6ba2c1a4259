#!/usr/bin/env bash
# The robustness stage of scripts/test.sh (run it after scripts/setup.sh):
#  1. the test suite built with AddressSanitizer + UndefinedBehaviorSanitizer (clang,
#     -O1) in build/sanitize/: tests, tool and fuzz target only, no examples or
#     benchmarks; CTest runs the suites there (all but the doc and install checks
#     and the three slowest suites, see below), including fuzz_regressions, which
#     replays the seed corpus and every input in test/Heat_diffusion/fuzz/regressions/;
#  2. libFuzzer on fuzz_mesh_pipeline for HEAT_DIFFUSION_FUZZ_SECONDS (default 60) from
#     the seed corpus test/Heat_diffusion/fuzz/corpus/. A crashing, hanging or
#     leaking input fails the run and is kept in test/Heat_diffusion/fuzz/regressions/,
#     where CTest replays it from then on: commit it with the fix.
set -euo pipefail
cd "$(dirname "$0")/.."
build=build/sanitize
seconds=${HEAT_DIFFUSION_FUZZ_SECONDS:-60}
fuzz_dir=test/Heat_diffusion/fuzz
stage_start=$SECONDS
stage_done() { echo "== $1: $((SECONDS - stage_start)) s"; stage_start=$SECONDS; }

echo "== building the sanitizer configuration in $build/"
# Ninja builds the selected targets in parallel (CMake's Makefiles build them one by one).
if [ -f "$build/CMakeCache.txt" ] && ! grep -q '^CMAKE_GENERATOR:INTERNAL=Ninja$' "$build/CMakeCache.txt"; then
  rm -rf "$build"
fi
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE=TRUE \
      -DCMAKE_CXX_COMPILER=clang++ \
      -DCGAL_HEAT_DIFFUSION_SANITIZE=ON -DCGAL_HEAT_DIFFUSION_BUILD_FUZZERS=ON \
      -DCGAL_HEAT_DIFFUSION_BUILD_EXAMPLES=OFF -DCGAL_HEAT_DIFFUSION_BUILD_BENCHMARKS=OFF \
      -DCGAL_HEAT_DIFFUSION_BUILD_PYTHON=OFF \
      -DCGAL_HEAT_DIFFUSION_DATA_DIR="$PWD/build/data/meshes" \
      -DCGAL_HEAT_DIFFUSION_POINT_DATA_DIR="$PWD/build/data/points_3" >/dev/null
# Not under the sanitizers, by CTest label: the doc, install, add_subdirectory
# (doc, install) and compile-failure (compile) checks, where no package code runs, and
# the three slowest suites (not_sanitized, test/Heat_diffusion/CMakeLists.txt), 10 to
# 12 times slower under ASan at -O1 than at -O2: test_coarse_level (simplifies
# armadillo, 3.5 min at -O2), test_local_heat_kernel (2 min at -O2) and
# test_applications (1 min at -O2, 12 min under ASan on a loaded machine). Their code
# still runs under the sanitizers: the features, decomposition, enhancement and
# denoising through test_cli (every subcommand, both kernels) and the fuzz target, the
# kernel and diffusion through test_heat_kernel_and_diffusion. Every other suite runs;
# built with CGAL_HEAT_DIFFUSION_TEST_UNDER_SANITIZERS, they leave out the checks that
# a smaller mesh runs through the same code (armadillo) and the comparisons with
# test-only baselines (test_support::under_sanitizers).
excluded_labels='^(doc|install|compile|not_sanitized)$'
# `all` of this configuration is what those tests run: the tool (test_cli,
# test_hostile_cli), the fuzz target (fuzz_regressions) and the test programs not
# marked NOT_SANITIZED. A suite whose program is not built is reported by CTest as
# "Not Run", a failure.
cmake --build "$build" -j "$(nproc)"
stage_done "sanitizer build"

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1:suppressions=$PWD/test/Heat_diffusion/ubsan.supp}
echo "== test suite under ASan + UBSan (all but the labels ${excluded_labels})"
(cd "$build" && ctest --output-on-failure -j "$(nproc)" -LE "$excluded_labels")
stage_done "sanitized test suite"

echo "== fuzzing fuzz_mesh_pipeline for $seconds s"
work_corpus="$build/fuzz_corpus"  # new inputs land here; the seeds stay as they are
mkdir -p "$work_corpus" "$fuzz_dir/regressions"
log="$build/fuzz.log"
status=0
"$build/bin/fuzz_mesh_pipeline" -max_total_time="$seconds" -max_len=2048 -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$fuzz_dir/regressions/" \
    "$work_corpus" "$fuzz_dir/corpus" >"$log" 2>&1 || status=$?
grep -aE '^#[0-9]+[[:space:]]+(INITED|DONE)|^Done|stat::number_of_executed_units|stat::peak_rss' "$log" || true
if [ "$status" -ne 0 ]; then
  tail -n 60 "$log"
  echo "fuzz_mesh_pipeline failed (exit $status); the input is kept in $fuzz_dir/regressions/:"
  grep -aE 'Test unit written to' "$log" || true
  exit 1
fi
stage_done "fuzzing"
