#!/usr/bin/env bash
# The command-line tool as a user meets it: outputs, exit codes, messages.
# Usage: test_cli.sh HEAT_DIFFUSION_BINARY DATA_DIR WORK_DIR [POINT_DATA_DIR]
# (POINT_DATA_DIR: CGAL's data/points_3, by default next to DATA_DIR)
set -u
tool=$1 data=$2 work=$3 points=${4:-$2/../points_3}
source "$(dirname "$0")/command_line_checks.sh"
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1

# success, JSON summary, PLY with the NS property and colours
expect 0 '"vertices": 6475' -- "$tool" ncc "$data/fandisk.off" -o fandisk_ns.ply --json --quiet
"$tool" ncc "$data/fandisk.off" -o fandisk_ns.ply --json --quiet > summary.json
if python3 -c 'import json,sys; d=json.load(open("summary.json")); assert d["ns"]["min"] < 0 < d["ns"]["max"]; assert all(v >= 0 for v in d["timings_ms"].values())'; then pass; else fail "JSON summary"; fi
if head -c 600 fandisk_ns.ply | grep -aq "property double ns" && head -c 600 fandisk_ns.ply | grep -aq "property uchar red"; then pass; else fail "PLY header lacks ns or colours"; fi
[ ! -e fandisk_ns.ply.partial ] && pass || fail "temporary file left behind"
# default output name, other normals, other formats, polygon faces
expect 0 'written to elephant_ns.ply' -- "$tool" ncc "$data/elephant.off"
[ -s elephant_ns.ply ] && pass || fail "default output missing"
expect 0 '"normals": "pmp"' -- "$tool" ncc "$data/elephant.off" --normals pmp --json -o e.ply
expect 0 '"triangulated_faces": 6' -- "$tool" ncc "$data/cube_quad.off" --json -o cube.ply
expect 0 '"vertices": ' -- "$tool" ncc fandisk_ns.ply --json -o reread.ply
# help
expect 0 'Usage: heat_diffusion COMMAND' -- "$tool" --help
expect 0 'Normal-Controlled Coordinates' -- "$tool" ncc --help
# bad usage: exit 2
expect 2 'missing COMMAND' -- "$tool"
expect 2 "unknown command 'frobnicate'" -- "$tool" frobnicate
expect 2 'unknown option --bogus' -- "$tool" ncc "$data/fandisk.off" --bogus
expect 2 'option -o needs a value' -- "$tool" ncc "$data/fandisk.off" -o
expect 2 'exactly one MESH' -- "$tool" ncc
expect 2 "--normals must be" -- "$tool" ncc "$data/fandisk.off" --normals magic
# bad input: exit 1, the message names the file (CGAL's OFF reader rejects 'nan' itself;
# non-finite coordinates that reach the API are rejected there, see the C++ tests)
expect 1 'missing.off: no such file' -- "$tool" ncc missing.off
printf 'OFF\n3 1 0\n0 0 0\n1 0\n' > truncated.off
expect 1 'truncated.off: cannot read' -- "$tool" ncc truncated.off
head -c 300 /dev/urandom > garbage.off 2>/dev/null || printf 'garbage' > garbage.off
expect 1 'garbage.off' -- "$tool" ncc garbage.off
printf 'OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 nan\n3 0 1 2\n3 0 2 3\n' > nan.off
expect 1 'nan.off: cannot read' -- "$tool" ncc nan.off
printf 'OFF\n0 0 0\n' > empty.off
expect 1 'empty.off: ' -- "$tool" ncc empty.off
# never overwrite the input; a failed run leaves no output
cp "$data/elephant.off" mine.off
expect 1 'refusing to overwrite the input' -- "$tool" ncc mine.off -o mine.off
expect 1 'refusing to overwrite the input' -- "$tool" ncc mine.off -o ./sub/../mine.off
cmp -s mine.off "$data/elephant.off" && pass || fail "input was modified"
expect 1 '' -- "$tool" ncc nan.off -o should_not_exist.ply
[ ! -e should_not_exist.ply ] && [ ! -e should_not_exist.ply.partial ] && pass || fail "failed run left an output"

# diffuse: outputs per k, conserved total heat, field files, bad parameters
expect 0 '"collapsed": 0' -- "$tool" diffuse "$data/fandisk.off" --sigma 1 -m 60 -k 0,5,20 -o fd --json --quiet
"$tool" diffuse "$data/fandisk.off" --sigma 1 -m 60 -k 0,5,20 -o fd --json --quiet > diffuse.json
if python3 -c '
import json; d = json.load(open("diffuse.json")); h = d["total_heat"]
assert set(h) == {"0", "5", "20"}, h
assert all(abs(h[k] - h["0"]) <= 1e-12 * max(1.0, abs(h["0"])) * 100 for k in h), h'; then pass; else fail "diffuse JSON / heat conservation"; fi
for k in 0 5 20; do [ -s fd_k$k.ply ] && pass || fail "fd_k$k.ply missing"; done
awk 'BEGIN { srand(1); for(i = 0; i < 2775; ++i) print rand() }' > field.txt
expect 0 '"field": "field.txt"' -- "$tool" diffuse "$data/elephant.off" --field field.txt -m 40 -k 3 -o ef --json --quiet
printf '1\n2\n' > short.txt
expect 1 'short.txt: has 2 values, the mesh has 2775 vertices' -- "$tool" diffuse "$data/elephant.off" --field short.txt
expect 2 '--sigma must be a number > 0' -- "$tool" diffuse "$data/elephant.off" --sigma 0
expect 2 '--time must be a number > 0' -- "$tool" diffuse "$data/elephant.off" --time -1
expect 2 '-k takes a comma-separated list' -- "$tool" diffuse "$data/elephant.off" -k 1,-2
expect 2 '-m must be a whole number from 1 to 1000000' -- "$tool" diffuse "$data/elephant.off" -m 0
expect 0 'Usage: heat_diffusion diffuse' -- "$tool" diffuse --help
# the default operator keeps a constant field (and every field within its range); the
# paper's column normalisation does not
awk 'BEGIN { for(i = 0; i < 6475; ++i) print 1 }' > ones.txt
"$tool" diffuse "$data/fandisk.off" --field ones.txt -k 0,1,100 -o ones --json --quiet --no-baseline > ones.json
"$tool" diffuse "$data/fandisk.off" --field ones.txt -k 0,1,100 -o ones_columns --normalization columns --json --quiet \
  --no-baseline > ones_columns.json
if python3 -c '
import json; d = json.load(open("ones.json")); c = json.load(open("ones_columns.json"))
assert d["normalization"] == "balanced" and c["normalization"] == "columns", (d["normalization"], c["normalization"])
assert all(abs(d[m][k] - 1) <= 1e-13 for m in ("minimum", "maximum") for k in d[m]), (d["minimum"], d["maximum"])
assert c["maximum"]["100"] > 1.1 and c["minimum"]["100"] < 0.9, (c["minimum"], c["maximum"])
assert all(abs(x["total_heat"][k] - 6475) <= 1e-9 for x in (d, c) for k in x["total_heat"])'; then pass; else fail "constant field, balanced and columns"; fi
expect 2 "--normalization must be 'balanced' or 'columns'" -- "$tool" diffuse "$data/fandisk.off" --normalization rows
expect 2 'unknown option --normalization' -- "$tool" hks "$data/fandisk.off" --normalization columns
# the local kernel's accuracy: in (0, 1), and refused where no local kernel runs
expect 2 "--kernel-tolerance must be a number > 0, not '0'" -- "$tool" diffuse "$data/fandisk.off" --kernel-tolerance 0
expect 2 "--kernel-tolerance must be below 1, not '1'" -- "$tool" diffuse "$data/fandisk.off" --kernel-tolerance 1
expect 2 "--kernel-tolerance must be a number > 0, not 'nan'" -- "$tool" features "$data/fandisk.off" --kernel-tolerance nan
expect 2 '--kernel-tolerance is the accuracy of the local kernel' -- \
  "$tool" diffuse "$data/fandisk.off" --kernel spectral --kernel-tolerance 1e-3
expect 2 'unknown option --kernel-tolerance' -- "$tool" hks "$data/fandisk.off" --kernel-tolerance 1e-3
expect 2 '--kernel-tolerance applies to --method signature_diffusion only' -- \
  "$tool" denoise "$data/fandisk.off" -o denoised.off --kernel-tolerance 1e-3
cp field.txt ef_k0.ply
expect 1 'refusing to overwrite the input' -- "$tool" diffuse "$data/elephant.off" --field ef_k0.ply -o ef -k 0

# features: one PLY per k with the labels and colours, JSON vertex lists that match the labels
expect 0 '"collapsed": 0' -- "$tool" features "$data/fandisk.off" --sigma 1 -k 0,10 -o feat --json --quiet
"$tool" features "$data/fandisk.off" --sigma 1 -k 0,10 -o feat --json --quiet > features.json
if python3 -c '
import json; d = json.load(open("features.json")); f = d["features"]
assert set(f) == {"0", "10"}, f
assert all(len(f[k]["convex"]) > 0 for k in f), f
assert all(not set(f[k]["convex"]) & set(f[k]["concave"]) for k in f), f
assert all(0 <= i < 6475 for k in f for s in ("convex", "concave") for i in f[k][s])'; then pass; else fail "features JSON"; fi
for k in 0 10; do head -c 600 feat_k$k.ply | grep -aq "property double feature" && pass || fail "feat_k$k.ply lacks the feature property"; done
expect 0 'heat regions collapsed' -- "$tool" features "$data/fandisk.off" -k 10 -o feat01
expect 2 '--c must be in \[0, 1\]' -- "$tool" features "$data/elephant.off" --c 1.5
expect 2 '--c must be a number >= 0' -- "$tool" features "$data/elephant.off" --c -1
expect 1 'short.txt: has 2 values' -- "$tool" features "$data/elephant.off" --field short.txt
expect 0 'Usage: heat_diffusion features' -- "$tool" features --help
cp "$data/elephant.off" feat_k0.ply
expect 1 'refusing to overwrite the input' -- "$tool" features feat_k0.ply -o feat -k 0
# hks: maxima only (the HKS is positive), the accuracy bound, the warning below it
expect 0 '"maxima": \[[0-9]' -- "$tool" hks "$data/fandisk.off" -t 20 -o hks.ply --json --quiet
expect 0 'below 4 ln 10 / lambda_m' -- "$tool" hks "$data/fandisk.off" -t 5 -o hks5.ply
head -c 600 hks.ply | grep -aq "property double hks" && pass || fail "hks.ply lacks the hks property"
expect 2 'give the time once' -- "$tool" hks "$data/elephant.off" -t 1 --time 2
expect 2 '-t must be a number > 0' -- "$tool" hks "$data/elephant.off" -t 0
expect 0 'Usage: heat_diffusion hks' -- "$tool" hks --help
# decompose: L bands + residual, every band of sum 0
expect 0 '"steps_per_level": 2' -- "$tool" decompose "$data/elephant.off" --levels 4 --steps-per-level 2 -o dec --json --quiet
"$tool" decompose "$data/elephant.off" --levels 4 --steps-per-level 2 -o dec --json --quiet > decompose.json
if python3 -c '
import json; d = json.load(open("decompose.json")); b = d["bands"]
assert set(b) == {"1", "2", "3", "4"}, b
assert all(b[j]["relative_sum"] <= 1e-12 for j in b), b
assert abs(d["residual_heat"] - d["total_heat"]) <= 1e-12 * abs(d["total_heat"]) * 100, d'; then pass; else fail "decompose JSON"; fi
for f in dec_band1 dec_band2 dec_band3 dec_band4 dec_residual; do [ -s $f.ply ] && pass || fail "$f.ply missing"; done
expect 2 '--levels must be a whole number' -- "$tool" decompose "$data/elephant.off" --levels 2.5
expect 2 '--steps-per-level must be a whole number' -- "$tool" decompose "$data/elephant.off" --steps-per-level 0
expect 0 'Usage: heat_diffusion decompose' -- "$tool" decompose --help
# enhance: the enhancement raises the NS variance, the smoothing lowers it, weights 1 keep the mesh
"$tool" enhance "$data/elephant.off" --weights 1,3,3 -o enhanced.off --json --quiet > enhance.json &&
  python3 -c 'import json; d = json.load(open("enhance.json")); assert d["ns_variance_after"] > d["ns_variance_before"], d' &&
  pass || fail "enhance 1,3,3 does not raise the NS variance"
"$tool" enhance "$data/elephant.off" --weights 0,0,1 -o smoothed.ply --json --quiet > smooth.json &&
  python3 -c 'import json; d = json.load(open("smooth.json")); assert d["ns_variance_after"] < d["ns_variance_before"], d' &&
  pass || fail "enhance 0,0,1 does not lower the NS variance"
expect 0 '"max_displacement_relative": [0-9.]*e-1[0-9]' -- "$tool" enhance "$data/elephant.off" --weights 1,1 -o same.obj --json --quiet
[ -s enhanced.off ] && [ -s smoothed.ply ] && [ -s same.obj ] && pass || fail "enhance outputs missing"
expect 2 '--weights takes a comma-separated list' -- "$tool" enhance "$data/elephant.off" --weights 1,x
expect 2 'must end in .off, .obj, .ply or .stl' -- "$tool" enhance "$data/elephant.off" -o out.vtp
expect 2 '--anchor-weight must be a number > 0' -- "$tool" enhance "$data/elephant.off" --anchor-weight 0
cp "$data/elephant.off" mine2.off
expect 1 'refusing to overwrite the input' -- "$tool" enhance mine2.off -o mine2.off
cmp -s mine2.off "$data/elephant.off" && pass || fail "enhance modified its input"
expect 0 'Usage: heat_diffusion enhance' -- "$tool" enhance --help
# denoise: OFF and PLY outputs with the input's vertex count, JSON with timings, errors;
# a noisy elephant (Gaussian noise of 0.1 mean edge length on each coordinate) is
# denoised, the clean one is left as it is
python3 - "$data/elephant.off" noisy_elephant.off <<'PYTHON'
import math, random, sys
tokens = open(sys.argv[1]).read().split()
nv, nf = int(tokens[1]), int(tokens[2])
points = [[float(x) for x in tokens[4 + 3 * i:7 + 3 * i]] for i in range(nv)]
faces = [[int(x) for x in tokens[4 + 3 * nv + 4 * f + 1:4 + 3 * nv + 4 * f + 4]] for f in range(nf)]
edges = [math.dist(points[f[k]], points[f[(k + 1) % 3]]) for f in faces for k in range(3)]
sigma = 0.1 * sum(edges) / len(edges)
random.seed(5)
with open(sys.argv[2], "w") as out:
    out.write("OFF\n%d %d 0\n" % (nv, nf))
    for p in points:
        out.write("%r %r %r\n" % tuple(x + random.gauss(0, sigma) for x in p))
    for f in faces:
        out.write("3 %d %d %d\n" % tuple(f))
PYTHON
"$tool" denoise noisy_elephant.off -o denoised.off --json --quiet > denoise.json &&
  "$tool" denoise "$data/elephant.off" -o clean_denoised.off --json --quiet > clean_denoise.json &&
  python3 -c '
import json; d = json.load(open("denoise.json")); c = json.load(open("clean_denoise.json"))
assert d["vertices"] == 2775 and d["method"] == "normal_filtering" and d["max_iterations"] == 40, d
assert d["given"] == [] and d["denoiser"]["stage"] == "curved" and d["denoiser"]["noise_level_in_mean_edge_lengths"] > 0, d
assert c["denoiser"]["stage"] == "unchanged", c
assert 0 < d["displacement_in_mean_edge_lengths"]["mean"] < 1, d
assert c["displacement_in_mean_edge_lengths"]["max"] < 1e-9, c
assert all(v >= 0 for v in d["timings_ms"].values()) and "denoise" in d["timings_ms"], d' &&
  [ "$(sed -n 2p denoised.off | cut -d" " -f1)" = 2775 ] && pass || fail "denoise OFF output or JSON"
expect 0 'written to denoised.ply' -- "$tool" denoise "$data/elephant.off" -o denoised.ply --method signature_diffusion --iterations 1 -m 60
head -c 300 denoised.ply | grep -aq "element vertex 2775" && pass || fail "denoise PLY output"
expect 0 'written to elephant_denoised.off' -- "$tool" denoise "$data/elephant.off" --iterations 0
python3 -c '
import sys
def vertices(path):
    tokens = [t for line in open(path) for t in line.split("#")[0].split()]
    n = int(tokens[1])
    return [float(x) for x in tokens[4:4 + 3 * n]]
a, b = vertices("elephant_denoised.off"), vertices(sys.argv[1])
assert len(a) == len(b) == 3 * 2775 and max(abs(x - y) for x, y in zip(a, b)) < 1e-12' "$data/elephant.off" &&
  pass || fail "denoise with 0 iterations changed the vertices"
expect 2 '--sigma must be a number > 0' -- "$tool" denoise "$data/elephant.off" --method signature_diffusion --sigma 0
expect 2 '--anchor-weight must be a number > 0' -- "$tool" denoise "$data/elephant.off" --method signature_diffusion --anchor-weight -1
# the two methods, and the options of one refused with the other
expect 2 '--method must be normal_filtering or signature_diffusion' -- "$tool" denoise "$data/elephant.off" --method bilateral
expect 2 '--sigma applies to --method signature_diffusion only' -- "$tool" denoise "$data/elephant.off" --sigma 1
expect 2 '--kernel applies to --method signature_diffusion only' -- "$tool" denoise "$data/elephant.off" --kernel local
expect 2 '--normal-sigma applies to --method normal_filtering only' -- "$tool" denoise "$data/elephant.off" --method signature_diffusion --normal-sigma 0.5
expect 2 '--normalization applies to --method signature_diffusion only' -- "$tool" denoise "$data/elephant.off" --normalization columns
expect 2 '--normal-sigma must be a number > 0' -- "$tool" denoise "$data/elephant.off" --normal-sigma 0
expect 2 '--displacement-limit must be a number > 0' -- "$tool" denoise "$data/elephant.off" --displacement-limit nan
expect 0 'normal_filtering, vertices moved' -- "$tool" denoise "$data/elephant.off" -o nf.off --normal-sigma 0.5 --displacement-limit 0.8
expect 0 'signature_diffusion, vertices moved' -- "$tool" denoise "$data/elephant.off" -o sd_local.off --method signature_diffusion --kernel local --iterations 1
expect 2 '--iterations must be a whole number' -- "$tool" denoise "$data/elephant.off" --iterations 1.5
expect 2 'must end in .off, .obj, .ply or .stl' -- "$tool" denoise "$data/elephant.off" -o out.vtp
expect 2 'exactly one NOISY' -- "$tool" denoise
expect 1 'no such file' -- "$tool" denoise missing.off -o out.off
cp "$data/elephant.off" mine3.off
expect 1 'refusing to overwrite the input' -- "$tool" denoise mine3.off -o mine3.off
cmp -s mine3.off "$data/elephant.off" && pass || fail "denoise modified its input"
expect 0 'Usage: heat_diffusion denoise' -- "$tool" denoise --help


# The options every subcommand that diffuses shares (tools/Heat_diffusion/diffusion_options.h):
# the same names in --help, the same checks and messages.
for c in diffuse features hks decompose enhance denoise; do
  help=$("$tool" "$c" --help)
  for opt in '--sigma S' '--time T' '--kernel K' '-m M' '--coarse N' '-o ' '--json' '--quiet' 'A progress bar'; do
    grep -qF -- "$opt" <<<"$help" && pass || fail "$c --help lacks '$opt'"
  done
  # denoise takes them with its signature_diffusion method
  method=(); [ "$c" = denoise ] && method=(--method signature_diffusion)
  expect 2 "--kernel must be 'automatic', 'spectral' or 'local', not 'magic'" -- "$tool" "$c" "$data/elephant.off" "${method[@]}" --kernel magic
  expect 2 "-m must be a whole number from 1 to 1000000, not '1e30'" -- "$tool" "$c" "$data/elephant.off" "${method[@]}" -m 1e30
  expect 2 "--sigma must be a number > 0 or 'inf'" -- "$tool" "$c" "$data/elephant.off" "${method[@]}" --sigma -inf
  expect 2 '--coarse' -- "$tool" "$c" "$data/elephant.off" "${method[@]}" --coarse 1e30
done
# --coarse N: the size used and whether it was automatic, in --json; heat still conserved
"$tool" diffuse "$data/fandisk.off" -m 40 --coarse 2000 -k 0,10 -o coarse --json --quiet > coarse.json &&
  python3 -c '
import json; d = json.load(open("coarse.json")); c = d["coarse"]; h = d["total_heat"]
assert c["automatic"] is False and 1500 <= c["vertex_count"] <= 2500, c
assert abs(h["10"] - h["0"]) <= 1e-10 * abs(h["0"]), h' && pass || fail "diffuse --coarse 2000 JSON"
expect 0 '"coarse": \{"vertex_count": 0, "automatic": false\}' -- "$tool" diffuse "$data/elephant.off" -m 20 --coarse 0 -k 1 -o c0 --json --quiet --no-baseline
expect 0 '"coarse": \{"vertex_count": 0, "automatic": true\}' -- "$tool" diffuse "$data/elephant.off" -m 20 -k 1 -o c1 --json --quiet --no-baseline
expect 0 '"coarse": \{"vertex_count": (49[0-9]|50[0-9]), "automatic": false\}' -- "$tool" hks "$data/elephant.off" -m 20 --coarse 500 -o c.ply --json --quiet
expect 2 "--coarse must be 0 \(no coarse level\) or at least 4, not '2'" -- "$tool" diffuse "$data/elephant.off" --coarse 2
expect 2 "--coarse must be a whole number from 0 to 1000000000, not '-1'" -- "$tool" features "$data/elephant.off" --coarse -1
# the global isotropic baseline of the paper's Fig. 5 next to the total heat, for the same k
if python3 -c '
import json, math; d = json.load(open("diffuse.json")); h, g = d["total_heat"], d["global_total_heat"]
assert set(g) == set(h), (g, h)
assert all(math.isfinite(v) and abs(v / g["0"] - 1) < 0.2 for v in g.values()), g
assert d["global_baseline"]["sigma"] is None and d["global_baseline"]["eigenpairs"] == 60, d'; then pass; else fail "diffuse global_total_heat"; fi
expect 0 '' -- "$tool" diffuse "$data/elephant.off" -m 20 -k 1 -o nb --json --quiet --no-baseline
"$tool" diffuse "$data/elephant.off" -m 20 -k 1 -o nb --json --quiet --no-baseline | grep -q global_total_heat &&
  fail "--no-baseline still reports global_total_heat" || pass
# --kernel local: no eigenpairs; the options of the eigenpairs are refused, not ignored
"$tool" diffuse "$data/elephant.off" --kernel local -k 0,3 -o loc --json --quiet --no-baseline > local.json &&
  python3 -c '
import json; d = json.load(open("local.json")); h = d["total_heat"]
assert d["kernel"] == "local" and "eigenpairs" not in d and "coarse" not in d, d
assert abs(h["3"] - h["0"]) <= 1e-12 * abs(h["0"]) * 100, h' && pass || fail "diffuse --kernel local"
for c in features decompose enhance; do
  out_name=loc_$c; [ "$c" = enhance ] && out_name=loc_enhanced.off
  expect 0 '"kernel": "local"' -- "$tool" "$c" "$data/elephant.off" --kernel local -o "$out_name" --json --quiet
done
expect 2 '-m is the number of eigenpairs of the spectral kernel: --kernel local computes none' -- "$tool" diffuse "$data/elephant.off" --kernel local -m 10
expect 2 '--coarse is the coarse level of the eigen solve: --kernel local computes none' -- "$tool" features "$data/elephant.off" --kernel local --coarse 100
expect 2 '--scale-invariant needs the eigenvalues' -- "$tool" decompose "$data/elephant.off" --kernel local --scale-invariant
expect 2 '--kernel local: the heat kernel signature is a sum over the eigenpairs' -- "$tool" hks "$data/elephant.off" --kernel local
# --kernel automatic (the default): local unless the eigenpairs are asked for
for c in diffuse features decompose enhance; do
  out_name=auto_$c; [ "$c" = enhance ] && out_name=auto_enhanced.off
  expect 0 '"kernel": "local", "kernel_automatic": true' -- "$tool" "$c" "$data/elephant.off" -o "$out_name" --json --quiet
  expect 0 '"kernel": "spectral", "kernel_automatic": true' -- "$tool" "$c" "$data/elephant.off" -m 20 -o "$out_name" --json --quiet
  expect 0 '"kernel": "spectral", "kernel_automatic": false' -- "$tool" "$c" "$data/elephant.off" --kernel spectral -o "$out_name" --json --quiet
done
expect 0 '"kernel": "spectral", "kernel_automatic": true' -- "$tool" features "$data/elephant.off" --coarse 0 -o auto_c0 --json --quiet
expect 0 '"kernel": "spectral", "kernel_automatic": true' -- "$tool" decompose "$data/elephant.off" --scale-invariant -o auto_si --json --quiet
expect 0 '"kernel": "local", "kernel_automatic": false' -- "$tool" features "$data/elephant.off" --kernel local -o auto_l --json --quiet
expect 0 '"kernel": "spectral", "kernel_automatic": true' -- "$tool" hks "$data/elephant.off" -o auto_hks.ply --json --quiet
# -k is the number of diffusion steps everywhere: the scales (diffuse, features), the steps
# of one level (decompose, enhance; also --steps-per-level), the steps per iteration (denoise)
expect 0 '"steps_per_level": 2' -- "$tool" decompose "$data/elephant.off" -m 20 -k 2 --levels 2 -o deck --json --quiet
expect 2 'give the steps per level once' -- "$tool" decompose "$data/elephant.off" -k 2 --steps-per-level 2
expect 2 "-k must be a whole number from 1 to 1000000 here" -- "$tool" enhance "$data/elephant.off" -k 0
expect 2 "-k must be a whole number from 0 to 1000000, not '1,2'" -- "$tool" denoise "$data/elephant.off" -k 1,2
# the progress bar: on stderr, for the eigen solve and the diffusion steps; never with
# --quiet, and not when stderr is not a terminal
out=$(HEAT_DIFFUSION_PROGRESS=always "$tool" diffuse "$data/elephant.off" -m 20 -k 0,20 -o prog 2>&1 >/dev/null)
grep -q 'eigen solve \[' <<<"$out" && grep -q 'diffusion \[#' <<<"$out" && pass || fail "no progress bar: $out"
out=$(HEAT_DIFFUSION_PROGRESS=always "$tool" enhance "$data/elephant.off" -m 20 -o prog_e.off 2>&1 >/dev/null)
grep -q 'eigen solve \[' <<<"$out" && pass || fail "no enhance progress bar: $out"
# and for the heat regions of the spectral kernel, and the local kernel's columns
out=$(HEAT_DIFFUSION_PROGRESS=always "$tool" features "$data/elephant.off" -m 20 -o prog 2>&1 >/dev/null)
grep -q 'heat regions \[#' <<<"$out" && pass || fail "no heat regions progress bar: $out"
out=$(HEAT_DIFFUSION_PROGRESS=always "$tool" diffuse "$data/elephant.off" -k 0,20 -o prog --no-baseline 2>&1 >/dev/null)
grep -q 'local kernel \[#' <<<"$out" && pass || fail "no local kernel progress bar: $out"
out=$(HEAT_DIFFUSION_PROGRESS=always "$tool" features "$data/elephant.off" -m 20 -o prog --quiet 2>&1 >/dev/null)
[ -z "$out" ] && pass || fail "--quiet still shows a progress bar: $out"
out=$("$tool" diffuse "$data/elephant.off" -m 20 -k 0,20 -o prog 2>&1 >/dev/null)
grep -q '\[#' <<<"$out" && fail "progress bar without a terminal: $out" || pass

# Point sets (files without faces): every subcommand but hks runs on them and writes PLY
# points with the fields and the normals; the JSON says so and gives k; hks
# refuses them; options of meshes only are usage errors there.
expect 0 '"input_kind": "points".*"neighbors": 8, "normals": "file"' -- \
  "$tool" ncc "$points/kitten.xyz" -o kitten_ns.ply --json --quiet
if python3 -c '
import sys; header = open("kitten_ns.ply", "rb").read(600).split(b"end_header")[0].decode()
for line in ("element vertex 5210", "property double ns", "property double nx", "property double nz", "element face 0"):
    assert line in header, (line, header)'; then pass; else fail "point-set PLY header"; fi
expect 0 '"points": 5210, "neighbors": 8' -- "$tool" ncc kitten_ns.ply -o kitten_again.ply --json --quiet
expect 0 '"points": 5210' -- "$tool" ncc "$points/kitten.off" -o kitten_off.ply --json --quiet
expect 0 '"given": \["k"\].*"neighbors": 12' -- "$tool" ncc "$points/kitten.xyz" --neighbors 12 -o k12.ply --json --quiet
expect 0 '"neighbors": 0, "neighbor_radius": 0.0(3|29999)' -- \
  "$tool" ncc "$points/kitten.xyz" --neighbors 0 --neighbor-radius 0.03 -o kr.ply --json --quiet
expect 0 '"normals": "estimated"' -- "$tool" ncc "$points/half.xyz" -o half_ns.ply --json --quiet
"$tool" diffuse "$points/oni.pwn" -k 0,10,40 -o oni --json --quiet > oni.json
if python3 -c '
import json; d = json.load(open("oni.json")); h = d["total_heat"]
assert d["input_kind"] == "points" and d["points"] == 1435 and d["kernel"] == "local", d
assert d["point_set"]["neighbors"] == 8 and d["point_set"]["normals"] == "file", d["point_set"]
assert all(abs(h[k] - h["0"]) <= 1e-10 * max(1.0, abs(h["0"])) for k in h), h'; then pass; else fail "diffuse on points: JSON / heat"; fi
for k in 0 10 40; do [ -s oni_k$k.ply ] && pass || fail "oni_k$k.ply missing"; done
awk 'BEGIN { srand(2); for(i = 0; i < 1435; ++i) print rand() }' > oni_field.txt
expect 0 '"field": "oni_field.txt"' -- "$tool" diffuse "$points/oni.pwn" --field oni_field.txt -k 3 -o onif --json --quiet
expect 1 'short.txt: has 2 values, the point set has 1435 points' -- "$tool" diffuse "$points/oni.pwn" --field short.txt
"$tool" features "$points/hippo1.ply" -k 0,10 -o hippo --json --quiet > hippo.json
if python3 -c '
import json; d = json.load(open("hippo.json")); f = d["features"]
assert d["input_kind"] == "points" and d["points"] == 6104 and set(f) == {"0", "10"}, d
assert all(len(f[k]["convex"]) > 0 and len(f[k]["concave"]) > 0 for k in f), f'; then pass; else fail "features on points: JSON"; fi
# the PLY points: the labels are the JSON's, the positions the file's, the normals unit
if python3 -c '
import json, math, struct
f = json.load(open("hippo.json"))["features"]["0"]
data = open("hippo_k0.ply", "rb").read()
end = data.index(b"end_header\n") + len(b"end_header\n")
header = data[:end].decode().split("\n")
names = [l.split()[2] for l in header if l.startswith("property double")]
assert names == ["x", "y", "z", "feature", "field", "nx", "ny", "nz"], names
assert "element vertex 6104" in header and "element face 0" in header, header
size = 8 * len(names) + 4
rows = [struct.unpack_from("<%dd" % len(names), data, end + i * size) for i in range(6104)]
assert [i for i, r in enumerate(rows) if r[3] == 1] == f["convex"] and [i for i, r in enumerate(rows) if r[3] == -1] == f["concave"]
assert all(abs(math.hypot(r[5], r[6], r[7]) - 1) < 1e-12 for r in rows)
first = open("'"$points"'/hippo1.ply", "rb").read()
start = first.index(b"end_header\n") + len(b"end_header\n")
assert struct.unpack_from("<3d", first, start) == rows[0][:3]'; then pass; else fail "features on points: PLY output"; fi
expect 1 "kitten.xyz: this file holds points and no faces: 'hks' needs a triangle mesh \(ncc, diffuse, features, decompose, enhance and denoise" -- \
  "$tool" hks "$points/kitten.xyz" -o refused.off
# decompose, enhance and denoise on points: PLY points, the JSON of the library's choices
"$tool" decompose "$points/oni.pwn" --levels 2 -o oni_bands --json --quiet > oni_bands.json
if python3 -c '
import json; d = json.load(open("oni_bands.json"))
assert d["input_kind"] == "points" and d["levels"] == 2 and d["steps_per_level"] == 5, d
assert set(d["outputs"]) == {"1", "2", "residual"} and all(abs(b["relative_sum"]) < 1e-12 for b in d["bands"].values()), d
assert abs(d["residual_heat"] - d["total_heat"]) <= 1e-10 * max(1.0, abs(d["total_heat"])), d'; then pass; else fail "decompose on points: JSON"; fi
for f in oni_bands_band1.ply oni_bands_band2.ply oni_bands_residual.ply; do [ -s $f ] && pass || fail "$f missing"; done
expect 0 '"input_kind": "points".*"weights": \[0, 0, 1\]' -- \
  "$tool" enhance "$points/oni.pwn" --weights 0,0,1 -o oni_smooth.ply --json --quiet
"$tool" denoise "$points/kitten.xyz" -o kitten_denoised.ply --json --quiet > kitten_denoised.json
if python3 -c '
import json; d = json.load(open("kitten_denoised.json"))
assert d["input_kind"] == "points" and d["neighbors"] == 24 and d["normals"] == "file" and d["given"] == [], d
assert d["denoiser"]["iterations"] >= 1 and d["denoiser"]["noise_level"] > 0, d
header = open("kitten_denoised.ply", "rb").read(600).split(b"end_header")[0].decode()
assert "element vertex 5210" in header and "property double nx" in header and "element face" not in header, header'
then pass; else fail "denoise on points: JSON / PLY"; fi
expect 0 '"neighbors": 12' -- "$tool" denoise "$points/kitten.xyz" --neighbors 12 -o k12d.ply --json --quiet
expect 2 'the output kitten_d.off of a point set must end in .ply' -- "$tool" denoise "$points/kitten.xyz" -o kitten_d.off
expect 2 'the output kitten_e.stl of a point set must end in .ply' -- "$tool" enhance "$points/kitten.xyz" -o kitten_e.stl
expect 2 'on a point set the denoiser is normal filtering' -- \
  "$tool" denoise "$points/kitten.xyz" --method signature_diffusion
expect 2 '--sigma applies to --method signature_diffusion only' -- "$tool" denoise "$points/kitten.xyz" --sigma 1
expect 1 'b9.ply: .*could not orient' -- "$tool" ncc "$data/b9.ply" -o b9_ns.ply
expect 1 'cube.xyz: CGAL::Heat_diffusion: the point set has 8 points, fewer than k \+ 1 = 9' -- "$tool" ncc "$points/cube.xyz" -o c.ply
expect 2 "--neighbors must be at least 2" -- "$tool" ncc "$points/kitten.xyz" --neighbors 1
expect 2 "--neighbors must be a whole number from 0 to 1000" -- "$tool" features "$points/kitten.xyz" --neighbors 2.5
expect 2 "--neighbor-radius must be a number > 0" -- "$tool" diffuse "$points/kitten.xyz" --neighbor-radius 0
expect 1 'kitten.xyz: CGAL::Heat_diffusion: point 14 has 1 neighbour\(s\) within --neighbor-radius; a fan needs 2' -- \
  "$tool" ncc "$points/kitten.xyz" --neighbor-radius 0.02 -o kr2.ply
expect 2 '--neighbors concerns point sets: .*fandisk.off is read as a mesh' -- "$tool" ncc "$data/fandisk.off" --neighbors 8
# the spectral kernel on points: the points' own eigenpairs, no coarse level
expect 0 '"kernel": "spectral".*"eigenpairs": 20' -- "$tool" diffuse "$points/oni.pwn" -m 20 -k 5 -o oni_m20 --json --quiet
expect 2 '--coarse simplifies a mesh: on a point set' -- "$tool" features "$points/kitten.xyz" --kernel spectral --coarse 500
expect 2 '--normals is the vertex normal rule of a mesh' -- "$tool" ncc "$points/kitten.xyz" --normals pmp
cp "$points/kitten.xyz" mine.xyz
expect 1 'refusing to overwrite the input' -- "$tool" ncc mine.xyz -o ./mine.xyz
cmp -s mine.xyz "$points/kitten.xyz" && pass || fail "the point file was modified"
# a mesh with faces keeps the mesh path
expect 0 '"faces": 12946' -- "$tool" ncc "$data/fandisk.off" -o fandisk_again.ply --json --quiet

echo "test_cli: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
