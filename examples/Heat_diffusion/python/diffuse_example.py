#!/usr/bin/env python3
"""Anisotropic heat diffusion of the Normal Signature from Python.

Reads a triangle mesh with meshio, diffuses its Normal Signature at the scales
k = 0, 10, 40 and saves a picture of the three fields (matplotlib, no display).

    PYTHONPATH=build/python python3 examples/Heat_diffusion/python/diffuse_example.py \
        build/data/meshes/fandisk.off fandisk_diffused.png
"""
import sys

import matplotlib
matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt
import meshio
import numpy as np
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

import cgal_heat_diffusion as hd

path = sys.argv[1] if len(sys.argv) > 1 else "build/data/meshes/fandisk.off"
output = sys.argv[2] if len(sys.argv) > 2 else "fandisk_diffused.png"

mesh = meshio.read(path)
V = mesh.points  # n x 3 numbers (float32 or float64, any layout)
F = mesh.cells_dict["triangle"]  # m x 3 integers

# A_t is built once (local kernel, sigma = 0.1, t = 1), then applied k times.
diffusion = hd.HeatDiffusion(V, F, sigma=0.1, time=1.0)
ns = hd.normal_signature(V, F)  # > 0 convex, < 0 concave
steps = [0, 10, 40]
fields = diffusion.diffuse(ns, steps)  # one row per k, in the order of V
for k, field in zip(steps, fields):
    print(f"k = {k:2d}: total heat {field.sum():.12g}")  # conserved
A = diffusion.operator_matrix()  # scipy.sparse.csc_matrix, columns sum to 1
print(f"A_t: {A.shape[0]} x {A.shape[1]}, {A.nnz} entries, "
      f"heat regions of {diffusion.region_statistics()['mean_size']:.1f} vertices on average")

# Red convex, blue concave; one colour scale for the three pictures.
limit = np.percentile(np.abs(ns), 98)
figure = plt.figure(figsize=(12, 4.4))
for column, (k, field) in enumerate(zip(steps, fields)):
    axes = figure.add_subplot(1, 3, column + 1, projection="3d")
    faces = Poly3DCollection(V[F], facecolors=plt.cm.coolwarm(0.5 + 0.5 * np.clip(field[F].mean(axis=1) / limit, -1, 1)),
                             linewidths=0)
    axes.add_collection3d(faces)
    low, high = V.min(axis=0), V.max(axis=0)
    axes.set_xlim(low[0], high[0])
    axes.set_ylim(low[1], high[1])
    axes.set_zlim(low[2], high[2])
    axes.set_box_aspect(high - low)
    axes.set_axis_off()
    axes.set_title(f"$F^{{{k}}}$")
figure.tight_layout()
figure.savefig(output, dpi=100)
print(f"written to {output}")
