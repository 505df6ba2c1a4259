#!/usr/bin/env bash
# Compile cost of the package: for each example and for a baseline translation unit
# (read a mesh, PMP vertex normals: what any CGAL program pays), the wall-clock time,
# the CPU time (and its ratio to the baseline's) and the peak memory (maximum resident
# set size) of the compiler, with the flags the project's build uses (its
# compile_commands.json); each example twice: header-only (CGAL::Heat_diffusion) and as
# a program linked with CGAL::Heat_diffusion_compiled compiles it.
#
# Usage: benchmark/Heat_diffusion/compile_cost.sh [BUILD_DIR]   (default: build)
# BUILD_DIR is configured with CMAKE_EXPORT_COMPILE_COMMANDS=ON if it has no
# compile_commands.json. Needs GNU time (/usr/bin/time, Debian package `time`).
# Run it with nothing else compiling: the times are those of one compiler process.
set -euo pipefail
usage="usage: compile_cost.sh [BUILD_DIR]   (default: build)"
case "${1:-}" in
  -h|--help) echo "$usage"; exit 0 ;;
  -*) echo "compile_cost.sh: unknown option $1" >&2; echo "$usage" >&2; exit 2 ;;
esac
if [ $# -gt 1 ]; then
  echo "compile_cost.sh: one BUILD_DIR at most" >&2; echo "$usage" >&2; exit 2
fi
cd "$(dirname "$0")/../.."
source_dir=$(pwd)
build_dir=${1:-build}
if [ ! -x /usr/bin/time ]; then
  echo "compile_cost.sh: GNU time (/usr/bin/time) is missing (Debian: apt-get install time)" >&2
  exit 2
fi
if [ ! -f "$build_dir/compile_commands.json" ]; then
  cmake -S . -B "$build_dir" -DCMAKE_EXPORT_COMPILE_COMMANDS=ON >/dev/null
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The baseline: CGAL, Surface_mesh, its I/O and PMP normals, no package header.
cat > "$work/baseline.cpp" <<'CPP'
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <iostream>
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
int main(int argc, char** argv)
{
  Mesh mesh;
  if(argc < 2 || !CGAL::IO::read_polygon_mesh(argv[1], mesh))
    return 1;
  auto normals = mesh.add_property_map<Mesh::Vertex_index, K::Vector_3>("v:n").first;
  CGAL::Polygon_mesh_processing::compute_vertex_normals(mesh, normals);
  std::cout << normals[*vertices(mesh).begin()] << std::endl;
  return 0;
}
CPP

# A program with a single anisotropic_heat_diffusion() call (the local kernel, the
# default): what a program that only smooths a field pays.
cat > "$work/single_call.cpp" <<'CPP'
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Heat_diffusion/Anisotropic_heat_diffusion.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <iostream>
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
int main(int argc, char** argv)
{
  Mesh mesh;
  if(argc < 2 || !CGAL::IO::read_polygon_mesh(argv[1], mesh))
    return 1;
  auto height = mesh.add_property_map<Mesh::Vertex_index, double>("v:h").first;
  auto smoothed = mesh.add_property_map<Mesh::Vertex_index, double>("v:s").first;
  for(Mesh::Vertex_index v : vertices(mesh))
    height[v] = mesh.point(v).z();
  CGAL::Heat_diffusion::anisotropic_heat_diffusion(mesh, height, smoothed);
  std::cout << smoothed[*vertices(mesh).begin()] << std::endl;
  return 0;
}
CPP

# "name<TAB>directory<TAB>command" of each example, the command compiling to $work/out.o.
python3 - "$build_dir/compile_commands.json" "$source_dir/examples/Heat_diffusion" "$work" > "$work/commands" <<'PY'
import json, os, shlex, sys
entries, examples, work = json.load(open(sys.argv[1])), os.path.realpath(sys.argv[2]), sys.argv[3]
rows = []
for e in entries:
    source = os.path.realpath(os.path.join(e["directory"], e["file"]))
    if os.path.dirname(source) != examples:
        continue
    args = e["arguments"] if "arguments" in e else shlex.split(e["command"])
    out = args.index("-o")
    args[out + 1] = os.path.join(work, "out.o")
    rows.append((os.path.basename(source)[:-4], e["directory"], args, source))
if not rows:
    sys.exit("compile_cost.sh: no example in compile_commands.json (CGAL_HEAT_DIFFUSION_BUILD_EXAMPLES=OFF?)")
rows.sort()
# The baseline with the flags of the first example.
name, directory, args, source = rows[0]
base = [os.path.join(work, "baseline.cpp") if a == source or a == os.path.relpath(source, directory) else a
        for a in args]
print("baseline (mesh I/O + PMP normals)\t%s\t%s" % (directory, shlex.join(base)))
single = [os.path.join(work, "single_call.cpp") if a == source or a == os.path.relpath(source, directory) else a
          for a in args]
print("one anisotropic_heat_diffusion() call\t%s\t%s" % (directory, shlex.join(single)))
for name, directory, args, source in rows:
    print("%s\t%s\t%s" % (name, directory, shlex.join(args)))
# The same, as a program linked with CGAL::Heat_diffusion_compiled compiles it: the
# spectral path's instantiations are the library's (extern templates).
for name, directory, args, source in rows:
    extern = args[:1] + ["-DCGAL_HEAT_DIFFUSION_EXTERN_TEMPLATES"] + args[1:]
    print("%s (compiled library)\t%s\t%s" % (name, directory, shlex.join(extern)))
PY

printf '%-50s %10s %10s %12s %14s\n' "translation unit" "wall (s)" "CPU (s)" "CPU/baseline" "peak RSS (MiB)"
baseline_cpu=
while IFS=$'\t' read -r name directory command; do
  if ! (cd "$directory" && eval /usr/bin/time -v -o "$work/time" "$command") 2> "$work/errors"; then
    echo "compile_cost.sh: $name does not compile:" >&2
    cat "$work/errors" >&2
    exit 1
  fi
  wall=$(sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$work/time" |
         awk -F: '{ s = 0; for(i = 1; i <= NF; ++i) s = s * 60 + $i; printf "%.1f", s }')
  cpu=$(awk -F': ' '/User time|System time/ { s += $2 } END { printf "%.1f", s }' "$work/time")
  rss=$(awk -F': ' '/Maximum resident set size/ { printf "%.0f", $2 / 1024 }' "$work/time")
  baseline_cpu=${baseline_cpu:-$cpu}
  ratio=$(awk -v a="$cpu" -v b="$baseline_cpu" 'BEGIN { printf "%.2f", a / b }')
  printf '%-50s %10s %10s %12s %14s\n' "$name" "$wall" "$cpu" "$ratio" "$rss"
done < "$work/commands"
