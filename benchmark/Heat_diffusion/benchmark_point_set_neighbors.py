#!/usr/bin/env python3
"""The neighbour count k of the point-set NS: the vertices of CGAL's meshes taken as
points, their NS (point_set_normal_signature) against the mesh's NS (normal_signature),
as Spearman's rho over all vertices, for each k, with the normals estimated (what a file
without normals gets) and with the mesh's area-weighted vertex normals given. A k whose
estimated normals the package refuses (mst_orient_normals() flipped a region) is shown as
refused, with the number of opposite fan triangles. This is the measurement behind
defaults::number_of_neighbors (the user manual, section on the tool and the module on points).

    PYTHONPATH=build/python /usr/bin/python3 benchmark/Heat_diffusion/benchmark_point_set_neighbors.py \\
        --data build/data/meshes [--neighbors 6,8,10,12,16,20] [--meshes fandisk.off,armadillo.off]
"""
import argparse
import os
import re
import sys

import meshio
import numpy as np
from scipy.stats import spearmanr

import cgal_heat_diffusion as hd


def whole_numbers(text):
    values = []
    for item in text.split(","):
        if not item.isdigit() or not 2 <= int(item) <= 1000:
            raise argparse.ArgumentTypeError(f"not a whole number from 2 to 1000: '{item}'")
        values.append(int(item))
    return values


def vertex_normals(V, F):
    """Area-weighted vertex normals (the package's default rule for meshes)."""
    corners = V[F]
    face_normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    normals = np.zeros_like(V)
    for c in range(3):
        np.add.at(normals, F[:, c], face_normals)
    return normals / np.linalg.norm(normals, axis=1)[:, None]


def rho_or_refusal(P, N, k, mesh_ns):
    try:
        return f"{spearmanr(hd.point_set_normal_signature(P, N, neighbors=k), mesh_ns)[0]:.3f}"
    except ValueError as e:
        found = re.search(r"(\d+) triangles shared by two points' fans", str(e))
        return f"refused ({found.group(1)} opposite triangles)" if found else "refused: " + str(e)[:60]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--data", required=True, help="folder of CGAL's meshes (build/data/meshes)")
    parser.add_argument("--neighbors", type=whole_numbers, default=[6, 8, 10, 12, 16, 20],
                        help="the k to measure, comma-separated (default 6,8,10,12,16,20)")
    parser.add_argument("--meshes", default="fandisk.off,armadillo.off,mech-holes-shark.off,elephant.off",
                        help="comma-separated mesh files in DATA (default fandisk, armadillo, mech-holes-shark, "
                             "elephant)")
    args = parser.parse_args()
    if not os.path.isdir(args.data):
        parser.error(f"--data '{args.data}' is not a directory")
    names = args.meshes.split(",")
    for name in names:
        if not os.path.isfile(os.path.join(args.data, name)):
            parser.error(f"--meshes: {os.path.join(args.data, name)} is not a file")
    print("| mesh | points | k | rho, estimated normals | rho, the mesh's normals |")
    print("|---|---|---|---|---|")
    for name in names:
        mesh = meshio.read(os.path.join(args.data, name))
        V = np.ascontiguousarray(mesh.points, dtype=np.float64)
        F = np.ascontiguousarray(mesh.cells_dict["triangle"], dtype=np.int64)
        mesh_ns, N = hd.normal_signature(V, F), vertex_normals(V, F)
        for k in args.neighbors:
            print(f"| {name} | {len(V)} | {k} | {rho_or_refusal(V, None, k, mesh_ns)} | "
                  f"{rho_or_refusal(V, N, k, mesh_ns)} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
