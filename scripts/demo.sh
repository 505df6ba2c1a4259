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
echo
echo "Results in out/:"
echo "  out/fandisk_ns.ply   fandisk coloured by its Normal Signature (red convex, blue concave);"
echo "                       open it in MeshLab or ParaView (per-vertex colour, scalar 'ns')"
echo "  out/fandisk_ns.json  the run's summary (vertex count, NS range, timings)"
