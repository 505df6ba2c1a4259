#!/usr/bin/env bash
# Makes the user manual's figures (doc/Heat_diffusion/fig/*.png) with the command-line
# tool and scripts/render.py, on CGAL's fandisk: what sigma, t, m and k do, the heat
# conservation plot, and one figure per application (shape filtering on armadillo too). Run it after scripts/setup.sh;
# the figures are committed, so only a change of the maths needs a new run. Its last
# step composes the README's overview figure, hd_overview.png, from the pictures made
# before it; --overview-only runs that step alone, from the pictures in OUTPUT_DIR (no
# tool, no build needed).
#   bash scripts/manual_figures.sh [--overview-only] [OUTPUT_DIR]   (default doc/Heat_diffusion/fig)
# HEAT_DIFFUSION_BUILD_DIR names another build folder (default build).
set -euo pipefail
cd "$(dirname "$0")/.."
overview_only=0
if [ "${1:-}" = --overview-only ]; then overview_only=1; shift; fi
build=${HEAT_DIFFUSION_BUILD_DIR:-build}
tool=$build/bin/heat_diffusion
mesh=$build/data/meshes/fandisk.off
fig=${1:-doc/Heat_diffusion/fig}

py=python3
if /usr/bin/python3 -c 'import matplotlib, numpy' 2>/dev/null; then py=/usr/bin/python3; fi

# The README's figure: one picture of each capability, cut from the figures below (the
# NS and its diffusion, the isotropic baseline, features, denoising, enhancement).
overview() {
  echo "== overview (the README's figure)"
  "$py" scripts/render.py composite \
    "$fig/hd_scales.png@1/3" "$fig/hd_scales.png@3/3" "$fig/hd_sigma.png@3/3" "$fig/hd_features.png@2/3" \
    "$fig/hd_denoising.png@1/3" "$fig/hd_denoising.png@2/3" \
    "$fig/hd_enhancement_armadillo.png@2/3" "$fig/hd_enhancement_armadillo.png@3/3" \
    --titles "Normal Signature|diffused, σ = 0.1, k = 40|isotropic, k = 10|features, k = 10|noisy|denoised|armadillo|enhanced (1, 3, 3)" \
    --columns 4 --height 170 -o "$fig/hd_overview.png"
}
if [ "$overview_only" = 1 ]; then overview; ls -l "$fig/hd_overview.png"; exit 0; fi

[ -x "$tool" ] || { echo "$tool is missing: run scripts/setup.sh first" >&2; exit 1; }
mkdir -p "$fig"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Three small pictures per figure: 2.6 inches at 80 dpi keep each PNG near 100 KB.
picture() { local png=$1; shift; "$py" scripts/render.py mesh "$@" --size 2.6 --dpi 80 -o "$fig/$png"; }
diffuse() { "$tool" diffuse "$mesh" --quiet "$@"; }

# The tool's default kernel is the local one (no eigenpairs asked for); it is named
# where the point is the effect of sigma: at t = 1 the truncated spectral kernel
# collapses thousands of heat regions for sigma = 0.1 (see the manual).
echo "== sigma: the edge weights (k = 10, t = 1, local kernel)"
for sigma in 0.1 1 inf; do diffuse --kernel local --sigma "$sigma" -k 10 -o "$work/sigma$sigma"; done
picture hd_sigma.png "$work"/sigma{0.1,1,inf}_k10.ply --titles "sigma 0.1|sigma 1|sigma inf (isotropic)"

echo "== k: the scales (sigma = 0.1, local kernel)"
diffuse --sigma 0.1 -k 0,10,40 -o "$work/scales"
picture hd_scales.png "$work"/scales_k{0,10,40}.ply --titles "k = 0 (the NS)|k = 10|k = 40"

echo "== t and the kernel: one step of t = 4, and the truncated vs the local kernel at t = 1"
diffuse --sigma 1 --time 4 -m 150 -k 1 -o "$work/t4"
diffuse --sigma 1 --time 1 -m 150 -k 10 -o "$work/spectral"
diffuse --sigma 1 --time 1 --kernel local -k 10 -o "$work/local"
picture hd_kernels.png "$work/t4_k1.ply" "$work/spectral_k10.ply" "$work/local_k10.ply" \
  --titles "t = 4, k = 1|spectral m = 150, t = 1, k = 10|local, t = 1, k = 10"

echo "== m: the number of eigenpairs (sigma = 1, t = 1, k = 10)"
for m in 30 300; do diffuse --sigma 1 -m "$m" -k 10 -o "$work/m$m"; done
picture hd_eigenpairs.png "$work/m30_k10.ply" "$work/spectral_k10.ply" "$work/m300_k10.ply" \
  --titles "m = 30|m = 150|m = 300"

echo "== heat conservation (the paper's Fig. 5)"
diffuse --sigma 0.1 -k 0,1,2,5,10,20,50,100,200,500,1000 -o "$work/heat" --json > "$work/heat.json"
"$py" scripts/render.py heat "$work/heat.json" --dpi 80 -o "$fig/hd_heat.png"

echo "== features (sigma = 0.1, k = 0, 10, 40)"
"$tool" features "$mesh" --sigma 0.1 -k 0,10,40 -o "$work/features" --quiet
picture hd_features.png "$work"/features_k{0,10,40}.ply --points-property feature \
  --titles "features, k = 0|k = 10|k = 40"

echo "== scalar field smoothing: a noisy height field in [-1, 1], sigma 1 and 0.1 (k = 10, local kernel)"
"$py" - "$mesh" "$work/field.txt" <<'EOF'
import sys
import numpy as np
sys.path.insert(0, "scripts")
import render
mesh = render.read_mesh(sys.argv[1])
z = mesh.points[:, 2]
z = 2 * (z - z.min()) / (z.max() - z.min()) - 1
noisy = z + np.random.default_rng(7).normal(0.0, 0.15, len(z))
np.savetxt(sys.argv[2], noisy)
EOF
diffuse --kernel local --field "$work/field.txt" --sigma 1 -k 0,10 -o "$work/field_sigma1"
diffuse --kernel local --field "$work/field.txt" --sigma 0.1 -k 10 -o "$work/field_sigma0.1"
picture hd_field_smoothing.png "$work/field_sigma1_k0.ply" "$work/field_sigma1_k10.ply" \
  "$work/field_sigma0.1_k10.ply" --titles "noisy height field|sigma 1, k = 10|sigma 0.1, k = 10"

echo "== denoising (0.2 mean edge length of noise along the normals)"
"$py" scripts/render.py noise "$mesh" -o "$work/noisy.off" --amplitude 0.2 --seed 1 > /dev/null
"$tool" denoise "$work/noisy.off" -o "$work/denoised.off" --quiet
"$tool" ncc "$work/noisy.off" -o "$work/noisy_ns.ply" --quiet
"$tool" ncc "$work/denoised.off" -o "$work/denoised_ns.ply" --quiet
"$tool" ncc "$mesh" -o "$work/clean_ns.ply" --quiet
picture hd_denoising.png "$work/noisy_ns.ply" "$work/denoised_ns.ply" "$work/clean_ns.ply" \
  --titles "noisy|denoised|clean (coloured by the NS)"

echo "== decomposition and enhancement"
"$tool" decompose "$mesh" --levels 3 --steps-per-level 5 -o "$work/bands" --quiet
picture hd_decomposition.png "$work"/bands_band{1,2,3}.ply "$work/bands_residual.ply" \
  --titles "band 1 (finest)|band 2|band 3|residual"
"$tool" enhance "$mesh" --weights 0,0,1 -o "$work/smoothed.off" --quiet
"$tool" enhance "$mesh" --weights 1,3,3 -o "$work/enhanced.off" --quiet
"$tool" ncc "$work/smoothed.off" -o "$work/smoothed_ns.ply" --quiet
"$tool" ncc "$work/enhanced.off" -o "$work/enhanced_ns.ply" --quiet
picture hd_enhancement.png "$work/smoothed_ns.ply" "$work/clean_ns.ply" "$work/enhanced_ns.ply" \
  --titles "weights 0, 0, 1|input|weights 1, 3, 3"
# an organic mesh with detail: armadillo's back, shaded (the filters' defaults)
armadillo=$build/data/meshes/armadillo.off
"$tool" enhance "$armadillo" --weights 0,0,1 -o "$work/armadillo_smoothed.off" --quiet
"$tool" enhance "$armadillo" --weights 1,3,3 -o "$work/armadillo_enhanced.off" --quiet
"$py" scripts/render.py mesh "$work/armadillo_smoothed.off" "$armadillo" "$work/armadillo_enhanced.off" \
  --titles "smoothing, weights 0, 0, 1|input (armadillo)|enhancement, weights 1, 3, 3" \
  --size 3.2 --dpi 90 --zoom 2.2 --view 10,90 -o "$fig/hd_enhancement_armadillo.png"

overview
ls -l "$fig"
