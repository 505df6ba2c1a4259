#!/usr/bin/env bash
# The main job: installs and builds (scripts/setup.sh), then runs the heat_diffusion
# tool on CGAL's fandisk end to end and writes into out/: the Normal Signature, the
# diffused fields, the features at several scales, a noisy copy and its denoised
# result, the decomposition bands, an enhanced shape (PLY with colours and the
# --json summaries), PNG pictures of each (scripts/render.py) and out/summary.md.
# A subcommand the tool does not have yet is skipped with a note, never a failure.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --target heat_diffusion

mesh=build/data/meshes/fandisk.off
tool=build/bin/heat_diffusion
out=out
mkdir -p "$out"
rm -f "$out"/*.png "$out"/summary.md "$out"/notes.txt
start=$SECONDS

# Debian's python3 has matplotlib and numpy (scripts/setup.sh installs them); a
# python3 earlier on the PATH (pyenv, venv) may not.
py=python3
if /usr/bin/python3 -c 'import matplotlib, numpy' 2>/dev/null; then py=/usr/bin/python3; fi
render() { "$py" scripts/render.py "$@"; }

note() { echo "note: $*" | tee -a "$out/notes.txt" >&2; }
# Runs the tool with --json, keeps the summary in out/NAME.json; a failure is a note.
run() {
  local name=$1; shift
  echo "== heat_diffusion $*"
  local rc=0
  "$tool" "$@" --json > "$out/$name.json.tmp" || rc=$?
  if [ $rc -eq 0 ]; then
    mv "$out/$name.json.tmp" "$out/$name.json"
  else
    rm -f "$out/$name.json.tmp"
    note "heat_diffusion $1 failed (exit $rc): $name skipped"
    return 1
  fi
}
picture() {  # picture OUT.png INPUTS... [render options]: a failure is a note
  local png=$1; shift
  render mesh "$@" -o "$out/$png" || note "picture $png failed"
}

# 1. The Normal Signature.
run fandisk_ns ncc "$mesh" -o "$out/fandisk_ns.ply" && picture fandisk_ns.png "$out/fandisk_ns.ply" \
  --titles "Normal Signature (red convex, blue concave)"

# 2. The NS diffused by k = 0, 10, 40 steps, feature-preserving and smooth.
for sigma in 0.1 1; do
  if run "fandisk_diffuse_sigma$sigma" diffuse "$mesh" --sigma "$sigma" -k 0,10,40 -o "$out/fandisk_sigma$sigma" --quiet; then
    picture "fandisk_diffuse_sigma$sigma.png" "$out/fandisk_sigma${sigma}_k"{0,10,40}.ply \
      --titles "sigma $sigma, k = 0|k = 10|k = 40"
  fi
done

# 3. Heat conservation (the paper's Fig. 5): total heat for k up to 1000, anisotropic
#    (sigma 0.1) and isotropic (sigma inf), against the global isotropic smoothing
#    baseline that `diffuse --json` reports as "global_total_heat"; the PLYs of these
#    runs are not kept. The plot is out/fandisk_heat.png.
curve_dir=$(mktemp -d)
trap 'rm -rf "$curve_dir"' EXIT
curve_k=0,1,2,5,10,20,50,100,200,500,1000
run fandisk_heat_sigma0.1 diffuse "$mesh" --sigma 0.1 -k "$curve_k" -o "$curve_dir/a" --quiet || true
run fandisk_heat_sigmainf diffuse "$mesh" --sigma inf -k "$curve_k" -o "$curve_dir/b" --quiet || true
heat_inputs=()
for f in "$out"/fandisk_heat_sigma0.1.json "$out"/fandisk_heat_sigmainf.json; do [ -f "$f" ] && heat_inputs+=("$f"); done
if [ ${#heat_inputs[@]} -gt 0 ]; then
  render heat "${heat_inputs[@]}" -o "$out/fandisk_heat.png" || note "picture fandisk_heat.png failed"
fi

# 4. Features at the scales k = 0, 10, 40.
# A constant field stays constant (the default, balanced operator), and does not with
# the paper's column normalisation.
awk 'BEGIN { for(i = 0; i < 6475; ++i) print 1 }' > "$curve_dir/ones.txt"
for normalization in balanced columns; do
  run "fandisk_ones_$normalization" diffuse "$mesh" --field "$curve_dir/ones.txt" --normalization "$normalization" \
    -k 0,1,10,100,1000 -o "$curve_dir/ones_$normalization" --no-baseline --quiet || true
done

run fandisk_features features "$mesh" --sigma 0.1 -k 0,10,40 -o "$out/fandisk_features" --quiet &&
  picture fandisk_features.png "$out/fandisk_features_k"{0,10,40}.ply --points-property feature \
    --titles "features, k = 0|k = 10|k = 40"

# 5. A noisy copy (Gaussian noise along the normals, 0.2 mean edge length) and its
#    denoised result; the error is measured against the original fandisk.
render noise "$mesh" -o "$out/fandisk_noisy.off" --amplitude 0.2 --seed 1 > "$out/fandisk_noisy.json" &&
  render error "$mesh" "$out/fandisk_noisy.off" > "$out/fandisk_noisy_error.json" || note "noisy copy failed"
if [ -f "$out/fandisk_noisy.off" ]; then
  run fandisk_noisy_ns ncc "$out/fandisk_noisy.off" -o "$out/fandisk_noisy_ns.ply" --quiet &&
    picture fandisk_noisy.png "$out/fandisk_noisy_ns.ply" --titles "noisy copy, coloured by its NS"
  if run fandisk_denoise denoise "$out/fandisk_noisy.off" -o "$out/fandisk_denoised.off" --quiet; then
    render error "$mesh" "$out/fandisk_denoised.off" > "$out/fandisk_denoised_error.json" ||
      note "denoising error not measured"
    run fandisk_denoised_ns ncc "$out/fandisk_denoised.off" -o "$out/fandisk_denoised_ns.ply" --quiet &&
      picture fandisk_denoised.png "$out/fandisk_noisy_ns.ply" "$out/fandisk_denoised_ns.ply" \
        --titles "noisy|denoised (coloured by the NS)"
  fi
fi

# 6. The decomposition of the NS into detail bands and a residual.
run fandisk_decompose decompose "$mesh" --levels 3 --steps-per-level 5 -o "$out/fandisk_decomposed" --quiet &&
  picture fandisk_decompose.png "$out/fandisk_decomposed_band"{1,2,3}.ply "$out/fandisk_decomposed_residual.ply" \
    --titles "band 1 (finest)|band 2|band 3|residual"

# 7. An enhanced shape (band weights 1, 3, 3), shown with its NS.
run fandisk_enhance enhance "$mesh" --weights 1,3,3 -o "$out/fandisk_enhanced.off" --quiet &&
  run fandisk_enhanced_ns ncc "$out/fandisk_enhanced.off" -o "$out/fandisk_enhanced_ns.ply" --quiet &&
  picture fandisk_enhanced.png "$out/fandisk_ns.ply" "$out/fandisk_enhanced_ns.ply" \
    --titles "input|enhanced, weights 1, 3, 3 (coloured by the NS)"

# The same filters on a mesh with detail: armadillo.
armadillo=build/data/meshes/armadillo.off
run armadillo_enhance enhance "$armadillo" --weights 1,3,3 -o "$out/armadillo_enhanced.off" --quiet &&
  run armadillo_smooth enhance "$armadillo" --weights 0,0,1 -o "$out/armadillo_smoothed.off" --quiet &&
  render mesh "$out/armadillo_smoothed.off" "$armadillo" "$out/armadillo_enhanced.off" \
    --titles "smoothing, weights 0, 0, 1|input|enhancement, weights 1, 3, 3" --size 3.2 --zoom 2.2 --view 10,90 \
    -o "$out/armadillo_filters.png" || note "armadillo's shape filters skipped"

# 8. The one-page summary.
"$py" scripts/summary.py "$out" > "$out/summary.md.tmp" && mv "$out/summary.md.tmp" "$out/summary.md" ||
  note "summary failed"

echo
echo "Done in $((SECONDS - start)) s. Results in $out/:"
echo "  $out/summary.md      one page: the pictures with timings, heat conservation, denoising error"
echo "  $out/fandisk_heat.png the total heat against k, this package vs the global baseline (Fig. 5)"
echo "  $out/*.png           the pictures (fandisk_ns, fandisk_diffuse_sigma*, fandisk_heat, fandisk_features,"
echo "                       fandisk_noisy, fandisk_denoised, fandisk_decompose, fandisk_enhanced,"
echo "                       armadillo_filters)"
echo "  $out/*.ply           the coloured meshes (per-vertex colour and scalar properties): open them in"
echo "                       MeshLab or ParaView"
echo "  $out/*.json          the tool's --json summaries (timings in ms, total heat, features, bands)"
[ -f "$out/notes.txt" ] && echo "  $out/notes.txt       what was skipped"
exit 0
