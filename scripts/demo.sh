#!/usr/bin/env bash
# The main job: installs and builds (scripts/setup.sh), then runs the heat_diffusion
# tool on CGAL's fandisk and writes what it produces to out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --target heat_diffusion

mesh=build/data/meshes/fandisk.off
mkdir -p out
echo "== heat_diffusion ncc $mesh"
build/bin/heat_diffusion ncc "$mesh" -o out/fandisk_ns.ply --json | tee out/fandisk_ns.json
echo "== heat_diffusion diffuse $mesh (sigma 0.1 and 1, k = 0, 10, 40)"
build/bin/heat_diffusion diffuse "$mesh" --sigma 0.1 -k 0,10,40 -o out/fandisk_sigma0.1 --json | tee out/fandisk_diffuse_sigma0.1.json
build/bin/heat_diffusion diffuse "$mesh" --sigma 1 -k 0,10,40 -o out/fandisk_sigma1 --json | tee out/fandisk_diffuse_sigma1.json
echo
echo "Results in out/:"
echo "  out/fandisk_ns.ply   fandisk coloured by its Normal Signature (red convex, blue concave);"
echo "                       open it in MeshLab or ParaView (per-vertex colour, scalar 'ns')"
echo "  out/fandisk_ns.json  the run's summary (vertex count, NS range, timings)"
echo "  out/fandisk_sigma{0.1,1}_k{0,10,40}.ply  the NS diffused by k steps, feature-preserving"
echo "                       (sigma 0.1) and smooth (sigma 1), on one colour scale per sigma"
echo "  out/fandisk_diffuse_sigma*.json  total heat at each k (conserved), heat regions, timings"
