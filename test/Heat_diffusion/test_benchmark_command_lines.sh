#!/usr/bin/env bash
# The benchmarks' command lines: a benchmark runs for minutes, so -h and --help print
# its usage, and a typing error (an unknown option, a missing or bad value, a TOOL that
# cannot run) stops it at once with exit 2, before any work, instead of running it with
# other settings. The C++ benchmarks, compile_cost.sh and, given PYTHON (the Python
# module's interpreter, the module on PYTHONPATH), benchmark_python.py. Nothing is
# timed here.
# Usage: test_benchmark_command_lines.sh BENCHMARK_DIR WORK_DIR [PYTHON]
set -u
bin=$1 work=$2 python=${3:-}
source "$(dirname "$0")/command_line_checks.sh"
rm -rf "$work" && mkdir -p "$work" || exit 1

for b in benchmark_heat_diffusion benchmark_denoising benchmark_scale_curve benchmark_local_kernel \
         benchmark_features benchmark_mesh_input benchmark_kernel_accuracy benchmark_point_set_denoising; do
  expect 0 "^usage: $b" -- "$bin/$b" --help
  expect 0 "^usage: $b" -- "$bin/$b" -h
  expect 2 "unknown option --bogus" -- "$bin/$b" --bogus
done

# values: missing, not a number, out of range, inconsistent
expect 2 'option --levels needs a value' -- "$bin/benchmark_local_kernel" --levels
expect 2 "--levels must be a whole number from -1 \(no table 2\) to 4, not 'x'" -- "$bin/benchmark_local_kernel" --levels x
expect 2 "--levels must be a whole number from -1 \(no table 2\) to 4, not '-2'" -- "$bin/benchmark_local_kernel" --levels -2
expect 2 '--first-level 3 is above --levels 2' -- "$bin/benchmark_local_kernel" --levels 2 --first-level 3
expect 2 '--time must be a number > 0' -- "$bin/benchmark_local_kernel" --time 0
expect 2 'one DATA_DIR at most' -- "$bin/benchmark_heat_diffusion" "$work" "$work"
expect 2 '--repeats must be a whole number from 1' -- "$bin/benchmark_heat_diffusion" --repeats 0
expect 2 '--coarse must be 0 \(no coarse level\) or at least 4' -- "$bin/benchmark_scale_curve" --coarse 2
expect 2 '--min-level 3 is above --max-level 1' -- "$bin/benchmark_scale_curve" --min-level 3 --max-level 1
expect 2 '--sigmas and --steps are settings of --shape-filter' -- "$bin/benchmark_features" --sigmas 0.5
expect 2 '--steps must be a whole number' -- "$bin/benchmark_features" --shape-filter --steps 2.5
expect 2 '--meshes needs at least one mesh' -- "$bin/benchmark_features" --meshes ,
expect 2 '--meshes needs at least one mesh' -- "$bin/benchmark_kernel_accuracy" --meshes ,
expect 2 "--times must be a number > 0 and <= 1000, not '0'" -- "$bin/benchmark_kernel_accuracy" --times 1,0
expect 2 "--noise must be a number > 0 and <= 10, not 'abc'" -- "$bin/benchmark_denoising" --noise abc
expect 2 "--noise must be a number > 0" -- "$bin/benchmark_denoising" --noise 0.3 --noise -0.1
expect 2 "--half takes tune or check, not 'both'" -- "$bin/benchmark_denoising" --half both
expect 2 "--baselines: unknown baseline 'NLLR'" -- "$bin/benchmark_denoising" --baselines GNF,NLLR
expect 2 "--points must be a whole number from 100" -- "$bin/benchmark_point_set_denoising" --points 10
expect 2 "--noise must be a number > 0 and <= 10, not '20'" -- "$bin/benchmark_point_set_denoising" --noise 0.5,20
expect 2 '--meshes needs at least one mesh' -- "$bin/benchmark_point_set_denoising" --meshes ,
# the cheapest run that goes through every method and the summary (a few seconds)
expect 0 "^Means over 1 rows" -- "$bin/benchmark_point_set_denoising" --meshes fandisk.off --points 2000 --noise 1
# benchmark_mesh_input checks its TOOL and DIR before it writes and reads its meshes
expect 2 "TOOL '$work/no_such_tool' is not an executable file" -- \
  "$bin/benchmark_mesh_input" "$work/no_such_tool" --dir "$work" --levels 0
expect 2 'one TOOL at most, not 2 arguments' -- "$bin/benchmark_mesh_input" /bin/true /bin/true --dir "$work"
touch "$work/not_executable"
expect 2 "is not an executable file" -- "$bin/benchmark_mesh_input" "$work/not_executable" --dir "$work" --levels 0
expect 2 "--dir '$work/no_such_dir' is not a directory" -- "$bin/benchmark_mesh_input" /bin/true --dir "$work/no_such_dir"
expect 2 "unknown option --repeats" -- "$bin/benchmark_mesh_input" /bin/true --dir "$work" --repeats 5
[ -z "$(ls "$work" | grep armadillo)" ] && pass || fail "benchmark_mesh_input wrote its meshes despite a usage error"

compile_cost=$(dirname "$0")/../../benchmark/Heat_diffusion/compile_cost.sh
expect 0 "^usage: compile_cost.sh" -- bash "$compile_cost" --help
expect 2 "unknown option --bogus" -- bash "$compile_cost" --bogus
expect 2 "one BUILD_DIR at most" -- bash "$compile_cost" "$work" "$work"

if [ -n "$python" ]; then
  script=$(dirname "$0")/../../benchmark/Heat_diffusion/benchmark_python.py
  expect 0 "^usage: benchmark_python.py" -- "$python" "$script" --help
  expect 2 "argument --repeat: 0 is not in \[1, 100\]" -- "$python" "$script" --tool /bin/true --data "$work" --repeat 0
  expect 2 "argument --levels: not a whole number: 'x'" -- "$python" "$script" --tool /bin/true --data "$work" --levels 0,x
  expect 2 "--tool '$work/no_such_tool' is not an executable file" -- \
    "$python" "$script" --tool "$work/no_such_tool" --data "$work"
  expect 2 "--data '$work/no_such_dir' is not a directory" -- "$python" "$script" --tool /bin/true --data "$work/no_such_dir"
  script=$(dirname "$0")/../../benchmark/Heat_diffusion/benchmark_point_set_neighbors.py
  expect 0 "^usage: benchmark_point_set_neighbors.py" -- "$python" "$script" --help
  expect 2 "argument --neighbors: not a whole number from 2 to 1000: '1'" -- "$python" "$script" --data "$work" --neighbors 8,1
  expect 2 "--data '$work/no_such_dir' is not a directory" -- "$python" "$script" --data "$work/no_such_dir"
  expect 2 "--meshes: $work/no_such.off is not a file" -- "$python" "$script" --data "$work" --meshes no_such.off
fi

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
