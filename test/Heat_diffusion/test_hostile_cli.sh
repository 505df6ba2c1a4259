#!/usr/bin/env bash
# Hostile input through the command-line tool: every subcommand, on every mesh of the
# corpus test/Heat_diffusion/data/, exits 0 with finite outputs or exits 1 with a
# message that names the file and the problem, and leaves no output behind.
# Usage: test_hostile_cli.sh HEAT_DIFFUSION_BINARY CORPUS_DIR WORK_DIR
#
# To add a mesh: put it into CORPUS_DIR and a line into `accepted` or `rejected`.
# To add a subcommand: a line into `commands` (it is run only if `--help` lists it).
set -u
shopt -s nullglob
tool=$(cd "$(dirname "$1")" && pwd)/$(basename "$1") corpus=$(cd "$2" && pwd)
# a folder of this run's own: two CTest runs in one build tree must not collide
mkdir -p "$3" && work=$(mktemp -d "$3/run.XXXXXX") && cd "$work" || exit 1
passed=0 failed=0
pass() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAILED: $*"; }

# Subcommands and the options that keep them fast on tiny meshes.
declare -A commands=(
  [ncc]=""
  [diffuse]="-m 10 -k 0,3"
  [features]="-m 10 -k 0,3"
  [hks]="-m 10"
  [decompose]="-m 10 --levels 2 --steps-per-level 2"
  [enhance]="-m 10 --steps-per-level 2"
  [denoise]="--iterations 3"
)
available=()
for c in ncc diffuse features hks decompose enhance denoise; do
  "$tool" --help | grep -qE "^  $c " && available+=("$c")
done
echo "subcommands under test: ${available[*]}"

# Meshes every subcommand accepts.
accepted=(
  quad_faces.off          # triangulated by the tool
  needle.off
  duplicated_vertex.off
  two_neighbours.off
  two_components.off
  three_components.off
  single_triangle.off
  open_strip.off
  hole.off
  octahedron.off
  huge_coordinates.off
  tiny_coordinates.off
)
# Files that are no mesh the package processes, which the tool repairs by default
# (CGAL's repair functions): every subcommand accepts them and says what it repaired.
# With --no-repair they are rejected as listed below.
repaired=(
  zero_area.off isolated_vertex.off nonmanifold_edge.off nonmanifold_vertex.off
  polygon_with_repeated_point.off broken_by_triangulation.off
)
# Files every subcommand rejects with --no-repair (exit 1), and what the message says
# after the file name; all but the `repaired` ones are rejected without it too.
declare -A rejected=(
  [zero_area.off]='face 0 \(vertices 0, 1, 2\) has zero area'
  [isolated_vertex.off]='vertex 4 is isolated'
  [pillow.off]='vertex 0 has no usable normal'
  [nonmanifold_edge.off]='cannot read a polygon mesh'
  [nonmanifold_vertex.off]='cannot read a polygon mesh'
  [nan_coordinate.off]='vertex 3 has 2 numbers, expected 3'
  [inf_coordinate.off]='vertex 3 has 2 numbers, expected 3'
  [overflow_coordinate.off]='vertex 3 has 2 numbers, expected 3'
  [truncated.off]='vertex 1 has 2 numbers, expected 3'
  [header_only.off]='no vertex and face counts'
  [empty.off]='the mesh has no faces'
  [garbage.off]='cannot read'
  [huge_face_size.off]='face 0 declares 2000000000 vertices, but its line has 3 indices'
  [huge_counts.off]='the vertex count 2000000000 is out of range'
  [negative_index.off]='face 0 has the vertex index -1, not one of 0..2'
  [index_out_of_range.off]='face 0 has the vertex index 7, not one of 0..2'
  # CGAL's PLY and OBJ readers leave indices unchecked: its builder read out of bounds
  [index_out_of_range.ply]='face 3 has the vertex index 4, not one of 0..3'
  [negative_index.ply]='face 2 has the vertex index -1, not one of 0..3'
  # CGAL's PLY reader read on from a failed stream: a list length from uninitialised memory
  [header_without_end.ply]='cannot read the PLY file: the header has no end_header line'
  [truncated_before_list_length.ply]='cannot read the PLY file: the file ends in the face element 3 \(the header declares 4\)'
  # coordinates of type int: CGAL's reader dereferenced a null pointer (a crash)
  [integer_coordinates.ply]="cannot read the PLY file: the vertex property 'x' is of type int; the reader takes coordinates of type float or double"
  [no_coordinates.ply]="cannot read the PLY file: the vertex element has no property 'x'"
  # a list length that does not fit its type: CGAL's reader wrapped char 200 to 2^64 - 56
  [list_length_beyond_its_type.ply]='the face element 2 has a list .vertex_indices. of length 200, more than its type char holds'
  [truncated_binary.ply]='cannot read the PLY file: the file ends in the face element 3 \(the header declares 4\)'
  # a NaN that the readers pass on, in a mesh that needs a repair (an isolated vertex):
  # no repair applies, the package refuses it
  [nan_coordinate_isolated.ply]='vertex 2 has a non-finite coordinate'
  [index_out_of_range.obj]='face 4 refers to a vertex the file does not have \(it has 4 vertices'
  [relative_index_out_of_range.obj]='face 2 refers to a vertex the file does not have'
  [fractional_index.off]='face 0 has the vertex index 1.5'
  [bad_color.off]='vertex 0 has an invalid colour'
  [missing_normal.off]='vertex 1 has 3 numbers, expected 6'
  # a coordinate of 2e103 in a polygon face: CGAL's triangulation overflowed (SIGFPE)
  [huge_coordinate_polygons.off]='cannot triangulate its polygon faces'
  [broken_by_triangulation.off]='cannot read a polygon mesh'
  # a pentagon with two corners at one point: CGAL's triangulation broke the halfedge structure (a crash)
  [polygon_with_repeated_point.off]='cannot triangulate its polygon faces'
)

# Every value of a JSON summary is finite (the tool writes null for NaN and infinity),
# and every double property of every PLY output is finite, with valid face indices.
check_outputs() {
  python3 - "$@" <<'EOF'
import json, math, struct, sys
summary, plys = sys.argv[1], sys.argv[2:]
def walk(x, path):
    if x is None and not path.endswith(".sigma"):  # sigma may be infinite
        raise SystemExit("null (NaN or infinity) at " + path)
    if isinstance(x, dict):
        for k, v in x.items(): walk(v, path + "." + k)
    if isinstance(x, list):
        for i, v in enumerate(x): walk(v, path + "[%d]" % i)
walk(json.load(open(summary)), "summary")
sizes = {"char": "b", "uchar": "B", "short": "h", "ushort": "H", "int": "i", "uint": "I",
         "float": "f", "double": "d", "int8": "b", "uint8": "B", "int16": "h", "uint16": "H",
         "int32": "i", "uint32": "I", "float32": "f", "float64": "d"}
for name in plys:
    data = open(name, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().split("\n")
    if "format binary_little_endian 1.0" not in header: raise SystemExit(name + ": not a binary PLY")
    elements, offset = [], end
    for line in header:
        w = line.split()
        if w[:1] == ["element"]: elements.append((w[1], int(w[2]), []))
        elif w[:1] == ["property"]: elements[-1][2].append(w[1:])
    nv = 0
    for element, count, props in elements:
        if element == "vertex": nv = count
        for _ in range(count):
            for p in props:
                if p[0] == "list":
                    n, = struct.unpack_from("<" + sizes[p[1]], data, offset); offset += struct.calcsize(sizes[p[1]])
                    values = struct.unpack_from("<%d%s" % (n, sizes[p[2]]), data, offset); offset += n * struct.calcsize(sizes[p[2]])
                    if element == "face" and not all(0 <= i < nv for i in values): raise SystemExit(name + ": bad face index")
                else:
                    v, = struct.unpack_from("<" + sizes[p[0]], data, offset); offset += struct.calcsize(sizes[p[0]])
                    if not math.isfinite(v): raise SystemExit("%s: %s %s = %r" % (name, element, p[1], v))
    if offset != len(data): raise SystemExit(name + ": %d bytes after the data" % (len(data) - offset))
EOF
}

# Known defects of subcommands (reported, to be fixed in their command_*.h): checked,
# but reported as KNOWN instead of failing. Remove a line once it is fixed.
declare -A known=(
)
check_failed() {  # check_failed "COMMAND MESH" MESSAGE
  if [ -n "${known[$1]:-}" ]; then echo "KNOWN: $1: ${known[$1]}"; pass; else fail "$1: $2"; fi
}

# run DIR COMMAND...: runs in a new empty folder DIR; sets $status and $out.
run() {
  local dir=$1; shift
  rm -rf "$dir" && mkdir -p "$dir"
  out=$(cd "$dir" && timeout 120 "$@" 2>&1); status=$?
}

# Accepted meshes: exit 0, a finite JSON summary, finite PLY outputs; the repaired ones
# with the repair in the summary.
for mesh in "${accepted[@]}" "${repaired[@]}"; do
  for c in "${available[@]}"; do
    dir="$work/ok_${c}_${mesh%.off}"
    # shellcheck disable=SC2086
    run "$dir" "$tool" "$c" "$corpus/$mesh" ${commands[$c]} --json --quiet
    if [ "$status" -ne 0 ]; then fail "$c $mesh -> exit $status: $out"; continue; fi
    printf '%s\n' "$out" > "$dir.json"
    if [[ " ${repaired[*]} " == *" $mesh "* ]] && ! grep -q '"repair": {' "$dir.json"; then
      fail "$c $mesh: no repair in the summary"
    fi
    if why=$(check_outputs "$dir.json" "$dir"/*.ply 2>&1); then pass; else check_failed "$c $mesh" "$why"; fi
    if ls "$dir" | grep -q partial; then fail "$c $mesh left a temporary file"; else pass; fi
    if ls "$dir"/*.off >/dev/null 2>&1 && grep -qiE 'nan|inf' "$dir"/*.off; then fail "$c $mesh wrote a non-finite OFF"; else pass; fi
  done
done

# Rejected files: exit 1, the message names the file and the problem, nothing written.
printf '' > "$work/zero_bytes.off"
rejected[zero_bytes.off]='no OFF header'
mkdir -p "$work/a_directory.off"
rejected[a_directory.off]='no such file'
rejected[missing.off]='no such file'
for mode in --no-repair repair; do
  for mesh in "${!rejected[@]}"; do
    [ "$mode" = repair ] && [[ " ${repaired[*]} " == *" $mesh "* ]] && continue
    path="$corpus/$mesh"
    [ -e "$path" ] || path="$work/$mesh"
    for c in "${available[@]}"; do
      dir="$work/bad_${c}_${mesh%.off}"
      # shellcheck disable=SC2086
      run "$dir" "$tool" "$c" "$path" ${commands[$c]} --quiet $([ "$mode" = repair ] || echo --no-repair)
      if [ "$status" -ne 1 ]; then fail "$c $mesh ($mode) -> exit $status, expected 1: $out"; continue; fi
      if grep -qE -- "$mesh: .*(${rejected[$mesh]})" <<<"$out"; then pass; else check_failed "$c $mesh" "($mode) message lacks '${rejected[$mesh]}': $out"; fi
      # one message per failure: nothing from CGAL's readers before the tool's
      if [ "$(wc -l <<<"$out")" -eq 1 ]; then pass; else fail "$c $mesh ($mode): more than one line: $out"; fi
      if [ -z "$(ls -A "$dir")" ]; then pass; else fail "$c $mesh left $(ls "$dir")"; fi
    done
  done
done

# Point files (no faces): every subcommand but hks runs on them (exit 0, finite outputs)
# or rejects them (exit 1, one line naming the file and the point); hks refuses every
# point file, saying that it needs a mesh.
declare -A point_commands=([ncc]="" [diffuse]="-k 0,3" [features]="-k 0,3" [decompose]="--levels 2" [enhance]=""
                           [denoise]="")
# (points_extreme_normals.pwn: normals of length 1e308 and 1e-200, whose squares over- and underflow)
accepted_points=(points_bump.xyz points_bump.pwn points_bump.ply points_bump.off points_extreme_normals.pwn)
declare -A rejected_points=(
  # (k + 1 = 25 for denoise, whose neighbour count is 24)
  [points_too_few.xyz]='the point set has 5 points, fewer than k \+ 1 = (9|25)'
  [points_duplicate.xyz]='point 3 coincides with point 10'
  # one point at 1e300 among points near 1: the others' neighbourhoods are lost to rounding, which is said
  [points_huge_coordinate.xyz]='point 1 has its [0-9]+ neighbours within .* in a bounding box whose largest side is 1e\+300 .*point 0, at 1e\+300 from its nearest neighbour, is the farthest from the others'
  # (20 points: too few for denoise's 24 neighbours)
  [points_collinear.xyz]='point 0 has a degenerate neighbourhood|fewer than k \+ 1 = 25'
  [points_tangent_normals.pwn]='point 0 has a degenerate neighbourhood|the normals are not those of the points. surface'
  [points_nan_coordinate.ply]='point 2 has a non-finite coordinate'
  [points_inf_coordinate.ply]='point 2 has a non-finite coordinate'
  [points_nan_normal.ply]='point 4 has a null or non-finite normal'
  [points_zero_normal.pwn]='point 4 has a null or non-finite normal'
  [points_two_clusters.xyz]='point 49 has a normal that CGAL::mst_orient_normals\(\) could not orient'
  # CGAL's XYZ reader rejects the line itself
  [points_nan_coordinate.xyz]='cannot read the points .*Error line 7'
  [points_incomplete_normal.xyz]='cannot read the points .*Error line 4 of file \(incomplete normal coordinates\)'
  [points_empty.xyz]='the file holds no points'
)
for file in "${accepted_points[@]}" "${!rejected_points[@]}"; do
  for c in "${available[@]}"; do
    dir="$work/points_${c}_${file//./_}"
    if [ -n "${point_commands[$c]+set}" ]; then
      # shellcheck disable=SC2086
      run "$dir" "$tool" "$c" "$corpus/$file" ${point_commands[$c]} --json --quiet
    else
      run "$dir" "$tool" "$c" "$corpus/$file" --quiet
    fi
    if [ -n "${point_commands[$c]+set}" ] && [[ " ${accepted_points[*]} " == *" $file "* ]]; then
      if [ "$status" -ne 0 ]; then fail "$c $file -> exit $status: $out"; continue; fi
      printf '%s\n' "$out" > "$dir.json"
      grep -q '"input_kind": "points"' "$dir.json" && pass || fail "$c $file: the summary does not say points"
      if why=$(check_outputs "$dir.json" "$dir"/*.ply 2>&1); then pass; else fail "$c $file: $why"; fi
      continue
    fi
    expected=${rejected_points[$file]:-}
    [ -n "${point_commands[$c]+set}" ] || expected="this file holds points and no faces: '$c' needs a triangle mesh"
    if [ "$status" -ne 1 ]; then fail "$c $file -> exit $status, expected 1: $out"; continue; fi
    if grep -qE -- "$file: .*($expected)" <<<"$out"; then pass; else fail "$c $file: message lacks '$expected': $out"; fi
    if [ "$(wc -l <<<"$out")" -eq 1 ]; then pass; else fail "$c $file: more than one line: $out"; fi
    if [ -z "$(ls -A "$dir")" ]; then pass; else fail "$c $file left $(ls "$dir")"; fi
  done
done
# One point far from all the others (a corrupt line, a scanner's stray return), at 1e40
# to 1e300 and at 5.6e78 (a file that once crashed CGAL's jet fitting), in grids of 10 to
# 100 points on a bumpy height field, with and without normals, along +x, -x and z:
# every subcommand refuses the file naming the far point (exit 1, never a signal); and
# meshes with one far vertex, in a face or isolated, strict and repaired: exit 0 with
# finite outputs or exit 1 naming the far vertex.
far_points() {  # far_points N FAR AXIS NORMALS: the grid's last point moved to FAR along AXIS
  awk -v n="$1" -v far="$2" -v axis="$3" -v normals="$4" 'BEGIN {
    w = (n >= 50 ? 10 : 5)
    for(i = 0; i < n; ++i) {
      x = i % w + 0.02 * sin(7 * i); y = int(i / w) + 0.03 * cos(5 * i); z = 0.3 * sin(x) * cos(y) + 0.05 * sin(13 * i)
      if(i == n - 1) { if(axis == "x") x = far; else if(axis == "z") z = far; else x = -far }
      if(normals) printf "%.17g %.17g %.17g %.6f %.6f 1\n", x, y, z, -0.1 * cos(x) * cos(y), 0.1 * sin(x) * sin(y)
      else printf "%.17g %.17g %.17g\n", x, y, z
    } }'
}
far_mesh() {  # far_mesh W FAR face|isolated: a W x W grid mesh, its last vertex moved to FAR, or one more at FAR
  awk -v w="$1" -v far="$2" -v mode="$3" 'BEGIN {
    n = w * w; extra = (mode == "isolated"); print "OFF"; print n + extra, 2 * (w - 1) * (w - 1), 0
    for(i = 0; i < n; ++i) { x = i % w; y = int(i / w); if(mode == "face" && i == n - 1) x = far
      printf "%.17g %.17g %.17g\n", x, y, 0.3 * sin(x) * cos(y) }
    if(extra) printf "%.17g 0 0\n", far
    for(r = 0; r + 1 < w; ++r) for(c = 0; c + 1 < w; ++c) {
      a = r * w + c; print 3, a, a + 1, a + w + 1; print 3, a, a + w + 1, a + w } }'
}
sizes=(10 22 35 100) axes=(x -x z) case_number=0
far_files=()
for far in 1e40 5.5555555555555555e78 1e150 1e200 1e300; do
  for normals in 0 1; do
    n=${sizes[$((case_number % 4))]} axis=${axes[$((case_number % 3))]}
    case_number=$((case_number + 1))
    file="far_${far}_${n}_${axis}_${normals}.$([ "$normals" = 1 ] && echo pwn || echo xyz)"
    far_points "$n" "$far" "$axis" "$normals" > "$work/$file"
    far_files+=("$file")
  done
done
for file in "${far_files[@]}"; do
  n=$(wc -l < "$work/$file")
  for c in "${available[@]}"; do
    dir="$work/far_${c}_${file//./_}"
    # shellcheck disable=SC2086
    run "$dir" "$tool" "$c" "$work/$file" ${point_commands[$c]:-} --quiet
    [ "$status" -eq 1 ] || { fail "$c $file -> exit $status, expected 1: $out"; continue; }
    if [ -n "${point_commands[$c]+set}" ]; then
      # (denoise's 24 neighbours: the smaller grids are too few)
      grep -qE "point [0-9]+ has its [0-9]+ neighbours within .*point $((n - 1)), at [^ ]+ from its nearest neighbour, is the farthest|fewer than k \+ 1 = 25" <<<"$out" &&
        pass || fail "$c $file: the message does not name the far point $((n - 1)): $out"
    else
      grep -q "needs a triangle mesh" <<<"$out" && pass || fail "$c $file: $out"
    fi
  done
done
for far in 1e40 5.5555555555555555e78 1e150 1e300; do
  for mode in face isolated; do
    file="far_mesh_${far}_$mode.off"
    far_mesh 5 "$far" "$mode" > "$work/$file"
    for repair in --no-repair ""; do
      for c in "${available[@]}"; do
        dir="$work/far_${c}_${file//./_}$repair"
        # shellcheck disable=SC2086
        run "$dir" "$tool" "$c" "$work/$file" ${commands[$c]} $repair --json --quiet
        if [ "$status" -eq 0 ] && [ "$mode$repair" = isolated ]; then  # repaired: the far vertex removed
          printf '%s\n' "$out" > "$dir.json"
          if why=$(check_outputs "$dir.json" "$dir"/*.ply 2>&1); then pass; else fail "$c $file: $why"; fi
        elif [ "$status" -eq 1 ]; then
          grep -qE "vertex (24|25), at [^ ]+ from the median of the vertices, is the farthest|vertex 25 is isolated" <<<"$out" &&
            pass || fail "$c $file $repair: the message does not name the far vertex: $out"
        else
          fail "$c $file $repair -> exit $status: $out"
        fi
      done
    done
  done
done

# The tool reads its own point output: the points, with the normals it wrote.
"$tool" ncc "$corpus/points_bump.xyz" -o own_points.ply --quiet &&
  "$tool" ncc own_points.ply -o own_points_again.ply --json --quiet | grep -q '"normals": "file"' &&
  pass || fail "the tool cannot read its own point output"

# A 40-byte file declaring a face of 2e9 vertices is rejected at once (CGAL's reader
# alone allocates 16 GB for it), within a small address space and 10 s of CPU time (a
# limit of the process, not of the wall clock, so a loaded machine cannot fail it: a
# run over the limit is killed and does not exit with 1).
out=$( (ulimit -t 10 -v 4000000; "$tool" ncc "$corpus/huge_face_size.off" -o x.ply) 2>&1); status=$?
if grep -q ReserveShadowMemoryRange <<<"$out"; then  # AddressSanitizer needs the address space: limit it its way
  out=$( (ulimit -t 10; ASAN_OPTIONS="${ASAN_OPTIONS:-}:max_allocation_size_mb=4000:allocator_may_return_null=1" \
        "$tool" ncc "$corpus/huge_face_size.off" -o x.ply) 2>&1); status=$?
fi
[ "$status" -eq 1 ] && pass || fail "huge_face_size.off: exit $status: $out"

# The same for PLY: a face list of 4e9 vertices (ASCII and binary) and 4e9 vertices
# in a 150-byte file; CGAL's reader alone grew to 15 GB on the binary one and was killed.
# 1e11 vertices without properties: the check itself looped over them; and again
# after "formal ascii 1.0", which CGAL's reader takes for the format line.
for ply in huge_face_size_ascii.ply huge_face_size_binary.ply huge_counts.ply vertices_without_properties.ply \
           misspelt_format_keyword.ply; do
  out=$( (ulimit -t 10; "$tool" ncc "$corpus/$ply" -o x.ply) 2>&1); status=$?
  [ "$status" -eq 1 ] && grep -q "$ply: cannot read the PLY file: " <<<"$out" &&
    pass || fail "$ply: exit $status: $out"
done
# The check walks valid PLYs without complaint: the tool reads its own binary output.
"$tool" ncc "$corpus/octahedron.off" -o own.ply --quiet && "$tool" ncc own.ply -o own_again.ply --quiet &&
  pass || fail "the tool cannot read its own PLY output"

# expect CODE PATTERN -- COMMAND...: exit status CODE and output matching PATTERN
expect() {
  local code=$1 pattern=$2; shift 3
  local out status
  out=$("$@" 2>&1); status=$?
  if [ "$status" -ne "$code" ]; then fail "$* -> exit $status, expected $code: $out"; return; fi
  if [ -n "$pattern" ] && ! grep -qE -- "$pattern" <<<"$out"; then fail "$* -> output lacks '$pattern': $out"; return; fi
  pass
}

# Parameters: m larger than the vertex count is clamped; sigma <= 0, t <= 0, k < 0,
# non-numbers, and numbers out of the range of the option (-m 1e30 converted to
# std::size_t was undefined behaviour) are usage errors (exit 2) naming the option,
# for every subcommand that takes them.
octahedron="$corpus/octahedron.off"
mkdir -p params && cd params || exit 1
for c in "${available[@]}"; do
  [ "$c" = ncc ] && continue
  help=$("$tool" "$c" --help)
  # denoise takes the diffusion options with its signature_diffusion method only
  extra=()
  [ "$c" = denoise ] && extra=(--method signature_diffusion)
  # shellcheck disable=SC2086
  expect 0 '' -- "$tool" "$c" "$octahedron" ${commands[$c]} "${extra[@]}" -m 1000 --quiet
  for bad in 0 -1 nan inf -inf abc '' 1e30 -1e30 2.5 1000001 18446744073709551616; do
    grep -q -- '-m M' <<<"$help" && expect 2 '-m must be a whole number from 1 to 1000000' -- "$tool" "$c" "$octahedron" "${extra[@]}" -m "$bad"
  done
  for bad in 0 -1 nan inf -inf abc ''; do
    grep -q -- '--sigma S' <<<"$help" && [ "$bad" != inf ] &&
      expect 2 '--sigma must be a number > 0' -- "$tool" "$c" "$octahedron" "${extra[@]}" --sigma "$bad"
    grep -q -- '--time T' <<<"$help" && expect 2 '--time must be a number > 0' -- "$tool" "$c" "$octahedron" "${extra[@]}" --time "$bad"
  done
  if grep -q -- '--coarse N  *compute' <<<"$help"; then
    for bad in -1 1 3 1.5 nan abc '' 1e30 1000000001; do
      expect 2 '--coarse must be' -- "$tool" "$c" "$octahedron" "${extra[@]}" --coarse "$bad"
    done
  fi
  if grep -q -- '-k K1' <<<"$help"; then
    for bad in -1 1,-1 1.5 abc '' , 1000001 99999999999999999999 1e30; do
      expect 2 '-k takes a comma-separated list|-k needs at least one step' -- "$tool" "$c" "$octahedron" -k "$bad"
    done
  elif grep -q -- '-k K ' <<<"$help"; then
    for bad in -1 1.5 abc '' 1000001 1e30 1,2; do
      expect 2 '-k must be a whole number' -- "$tool" "$c" "$octahedron" -k "$bad"
    done
  fi
done
# the counts of the subcommands' own options, also converted to std::size_t
for bad in -1 1.5 nan 1e30 10001; do
  grep -qw denoise <<<"${available[*]}" && expect 2 '--iterations must be a whole number from 0 to 10000' -- "$tool" denoise "$octahedron" --iterations "$bad"
done
for bad in 0 1.5 1e30 1001; do
  grep -qw decompose <<<"${available[*]}" && expect 2 '--levels must be a whole number from 1 to 1000' -- "$tool" decompose "$octahedron" --levels "$bad"
done
for c in decompose enhance; do
  for bad in 0 1.5 1e30 1000001; do
    grep -qw $c <<<"${available[*]}" && expect 2 '--steps-per-level must be a whole number from 1 to 1000000' -- "$tool" "$c" "$octahedron" --steps-per-level "$bad"
  done
done
cd "$work" || exit 1

# A run with several outputs writes all of them or none: a failure at a later output
# (here a temporary file name too long for the file system: the name of the first
# output fits, that of the last does not) leaves no output and no temporary file.
mkdir -p all_or_none && cd all_or_none || exit 1
long=$(printf 'p%.0s' $(seq 237))  # 237 + "_k0.ply.partial" fits in 255 bytes, + "_k99999.ply.partial" does not
for c in diffuse features; do
  grep -qw $c <<<"${available[*]}" || continue
  rm -f ./*
  expect 1 "${long}_k99999.ply: cannot write the output file" -- "$tool" "$c" "$octahedron" -m 4 -k 0,99999 -o "$long" --quiet
  [ -z "$(ls -A)" ] && pass || fail "$c left $(ls -A | cut -c1-40) after a failed later output"
done
if grep -qw decompose <<<"${available[*]}"; then
  rm -f ./*
  long=$(printf 'p%.0s' $(seq 235))  # + "_band1.ply.partial" fits, + "_residual.ply.partial" does not
  expect 1 "${long}_residual.ply: cannot write the output file" -- "$tool" decompose "$octahedron" -m 4 --levels 2 -k 1 -o "$long" --quiet
  [ -z "$(ls -A)" ] && pass || fail "decompose left $(ls -A | cut -c1-40) after a failed later output"
fi
# an output that is a folder is found before any work: nothing written either
mkdir -p out_k5.ply out_residual.ply
for c in diffuse features decompose; do
  grep -qw $c <<<"${available[*]}" || continue
  case $c in decompose) k=(--levels 2 -k 1) ;; *) k=(-k 0,5) ;; esac
  expect 1 'cannot write the output file \(it exists and is not a regular file\)' -- "$tool" "$c" "$octahedron" -m 4 "${k[@]}" -o out --quiet
  [ "$(ls -A | tr '\n' ' ')" = "out_k5.ply out_residual.ply " ] && pass || fail "$c left $(ls -A) next to a folder output"
done
cd "$work" || exit 1

# The tool never overwrites its input (same path, another spelling, a symbolic or
# a hard link), and never writes over something that is not a regular file.
mkdir -p overwrite && cd overwrite || exit 1
cp "$corpus/octahedron.off" mine.off
ln -sf mine.off link.ply
ln -f mine.off hard.ply
for c in "${available[@]}"; do
  case $c in ncc) extra=() ;; denoise) extra=(--iterations 1) ;; *) extra=(-m 4) ;; esac
  case $c in
    ncc|hks|enhance|denoise)  # -o names the output file
      for target in mine.off ./mine.off "$(pwd)/mine.off" ../overwrite/mine.off link.ply hard.ply; do
        expect 1 'refusing to overwrite the input' -- "$tool" "$c" mine.off "${extra[@]}" -o "$target"
      done ;;
    diffuse|features)  # -o names a prefix: PREFIX_k<K>.ply
      cp mine.off in_k0.ply
      expect 1 'refusing to overwrite the input' -- "$tool" "$c" in_k0.ply "${extra[@]}" -k 0 -o in ;;
    decompose)  # PREFIX_band<j>.ply, PREFIX_residual.ply
      cp mine.off in_residual.ply
      expect 1 'refusing to overwrite the input' -- "$tool" "$c" in_residual.ply "${extra[@]}" -o in ;;
  esac
  cmp -s mine.off "$corpus/octahedron.off" && pass || fail "$c modified its input"
done
# a directory or a device as output: exit 1, nothing left behind, the device intact
mkdir -p out_dir.ply
expect 1 'cannot write|not a regular file' -- "$tool" ncc mine.off -o out_dir.ply
[ -d out_dir.ply ] && [ -z "$(ls -A out_dir.ply)" ] && pass || fail "the output folder was changed"
# (a FIFO of our own: never try this on /dev/null, which a tool running as root and
# renaming its temporary file over the target would replace)
mkfifo a_fifo.ply
expect 1 'not a regular file' -- "$tool" ncc mine.off -o a_fifo.ply
[ -p a_fifo.ply ] && pass || fail "the FIFO output was replaced by a file"
partials=(./*.partial*)
[ ${#partials[@]} -eq 0 ] && pass || fail "temporary files left: ${partials[*]}"
# a temporary name that is taken by another file: that file is kept
cp mine.off out.ply.partial
expect 0 '' -- "$tool" ncc mine.off -o out.ply --quiet
cmp -s out.ply.partial mine.off && pass || fail "out.ply.partial was overwritten"
cd "$work" || exit 1

echo "test_hostile_cli: $passed passed, $failed failed"
[ "$failed" -eq 0 ] || { echo "outputs kept in $work"; exit 1; }
cd / && rm -rf "$work"
