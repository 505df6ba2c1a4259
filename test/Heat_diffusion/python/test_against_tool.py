# The Python module against the command-line tool on CGAL's real meshes: the same
# Normal Signature, the same diffused fields (both to 1e-12) and the same features,
# vertex for vertex in the order of the mesh file.
import os

import numpy as np
import pytest

import cgal_heat_diffusion as hd
from conftest import read_ply_vertices, run_tool, write_ply

MESHES = ["fandisk.off", "armadillo.off"]


def close(a, b, tolerance=1e-12):
    """Equal up to `tolerance` relative to the field's largest magnitude."""
    a, b = np.asarray(a), np.asarray(b)
    assert a.shape == b.shape
    scale = max(1.0, float(np.max(np.abs(b))))
    difference = float(np.max(np.abs(a - b))) if a.size else 0.0
    assert difference <= tolerance * scale, f"max difference {difference:.3g} (scale {scale:.3g})"


@pytest.mark.parametrize("name", MESHES)
def test_normal_signature_equals_tool(name, mesh, tool, tmp_path):
    V, F, path = mesh(name)
    run_tool(tool, "ncc", path, "-o", "ns.ply", "--quiet", cwd=tmp_path)
    ply = read_ply_vertices(tmp_path / "ns.ply")
    # the same vertices in the same order: the tool's mesh is the file's
    assert np.array_equal(np.column_stack([ply["x"], ply["y"], ply["z"]]), V)
    ns = hd.normal_signature(V, F)
    assert ns.shape == (len(V),) and ns.dtype == np.float64
    close(ns, ply["ns"])
    assert ns.min() < 0 < ns.max()
    # the NCC are the NS along the unit normals
    ncc = hd.normal_controlled_coordinates(V, F)
    assert ncc.shape == (len(V), 3)
    close(np.linalg.norm(ncc, axis=1), np.abs(ns))


@pytest.mark.parametrize("name", MESHES)
def test_diffusion_equals_tool(name, mesh, tool, tmp_path):
    V, F, path = mesh(name)
    summary = run_tool(tool, "diffuse", path, "-k", "0,10,40", "-o", "d", "--json", "--no-baseline", "--quiet",
                       cwd=tmp_path)
    diffusion = hd.HeatDiffusion(V, F)  # the tool's defaults: sigma 0.1, time 1, local kernel
    assert diffusion.kernel == summary["kernel"] == "local"
    ns = hd.normal_signature(V, F)
    close(diffusion.normal_signature(), ns, 0)
    fields = diffusion.diffuse(ns, [0, 10, 40])
    assert fields.shape == (3, len(V))
    for row, k in enumerate([0, 10, 40]):
        close(fields[row], read_ply_vertices(tmp_path / f"d_k{k}.ply")["field"])
        close(fields[row].sum(), summary["total_heat"][str(k)])
    regions = diffusion.region_statistics()
    expected = summary["heat_regions"]
    assert (regions["min_size"], regions["max_size"], regions["collapsed_regions"], regions["capped_regions"]) == \
        (expected["min"], expected["max"], expected["collapsed"], expected["capped"])
    assert regions["mean_size"] == pytest.approx(expected["mean"], rel=1e-12)


@pytest.mark.parametrize("name", MESHES)
def test_features_equal_tool(name, mesh, tool, tmp_path):
    V, F, path = mesh(name)
    summary = run_tool(tool, "features", path, "-k", "0,10,40", "-o", "f", "--json", "--quiet", cwd=tmp_path)
    features = hd.multiscale_features(V, F, steps=[0, 10, 40])
    assert [f["steps"] for f in features] == [0, 10, 40]
    for f in features:
        expected = summary["features"][str(f["steps"])]
        assert f["convex"].tolist() == expected["convex"]
        assert f["concave"].tolist() == expected["concave"]
    assert any(len(f["convex"]) > 0 for f in features) and any(len(f["concave"]) > 0 for f in features)


def test_spectral_diffusion_equals_tool(mesh, tool, tmp_path):
    V, F, path = mesh("fandisk.off")
    run_tool(tool, "diffuse", path, "--kernel", "spectral", "-m", "60", "--time", "20", "-k", "5", "-o", "s",
             "--quiet", cwd=tmp_path)
    diffusion = hd.HeatDiffusion(V, F, kernel="spectral", m=60, time=20.0)
    assert diffusion.kernel == "spectral"
    close(diffusion.diffuse(diffusion.normal_signature(), 5), read_ply_vertices(tmp_path / "s_k5.ply")["field"])


def test_large_mesh_in_input_order(mesh, tool, tmp_path):
    """From 100000 vertices on, the package numbers the vertices along a Hilbert curve:
    results must still come back in the order of V, as the tool writes them."""
    V0, F0, _ = mesh("armadillo.off")
    V, F = hd.loop_subdivision(V0, F0, 1)
    assert len(V) >= 100000
    write_ply(tmp_path / "large.ply", V, F)
    run_tool(tool, "diffuse", "large.ply", "-k", "10", "-o", "l", "--quiet", cwd=tmp_path)
    ply = read_ply_vertices(tmp_path / "l_k10.ply")
    assert np.array_equal(np.column_stack([ply["x"], ply["y"], ply["z"]]), V)
    diffusion = hd.HeatDiffusion(V, F)
    ns = diffusion.normal_signature()
    close(ns, hd.normal_signature(V, F))
    close(diffusion.diffuse(ns, 10), ply["field"])
    A = diffusion.operator_matrix()
    close(A @ ns, diffusion.diffuse(ns, 1))
    assert np.max(np.abs(np.asarray(A.sum(axis=0)).ravel() - 1.0)) <= 1e-12
    # column j is the diffusion of the heat of vertex j (of V), row i the heat vertex i receives
    for j in (0, len(V) // 2, len(V) - 1):
        unit = np.zeros(len(V))
        unit[j] = 1.0
        close(A[:, [j]].toarray().ravel(), diffusion.diffuse(unit, 1))
