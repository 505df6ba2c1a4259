# Real files through the front ends' repair (CGAL's repair functions): CGAL's whole data
# set, STL exports, polygon soups with inconsistent orientation, meshes with
# non-manifold vertices. The tool repairs by default and reports it; --no-repair keeps
# the strict reading; the module's repair() returns the repaired mesh and, for each of
# its vertices, the input vertex it comes from.
import json
import os
import subprocess

import numpy as np
import pytest
from scipy.spatial import cKDTree

import cgal_heat_diffusion as hd
from conftest import read_ply_vertices, write_off

# The files of CGAL's data set that are no mesh the package processes, and the repair each needs.
NEEDS_REPAIR = {
    "blobby-shuffled.off": "faces_reoriented", "cube-shuffled.off": "faces_reoriented",
    "cube4-shuffled.off": "faces_reoriented", "oblong-shuffled.off": "faces_reoriented",
    "tet-shuffled.off": "faces_reoriented", "pig.stl": "vertices_split", "polygon_mesh.off": "vertices_split",
    "cube-ouvert.off": "isolated_vertices_removed", "prim.off": "isolated_vertices_removed",
    "degtri_sliding.off": "degenerate_faces_removed",
}
# The files no repair makes a mesh of, and why (the message of denoise, the last run: b9.ply
# is a point set, on which ncc, diffuse and denoise take the point-set path and refuse it:
# mst_orient_normals() cannot orient its estimated normals).
NOT_MESHES = {"b9.ply": "could not orient"}


def tool_run(tool, cwd, *arguments):
    result = subprocess.run([tool, *arguments], cwd=cwd, capture_output=True, text=True, timeout=600)
    return result.returncode, result.stdout, result.stderr


def test_every_cgal_mesh_goes_through_or_is_refused_with_a_reason(tool, data_dir, tmp_path, capsys):
    names = sorted(os.listdir(data_dir))
    assert len(names) == 143
    through, repaired, refused = 0, set(), {}
    for name in names:
        path = os.path.join(data_dir, name)
        for command, output in (("ncc", "n.ply"), ("diffuse", "d"), ("denoise", "x.ply")):
            status, out, err = tool_run(tool, tmp_path, command, path, "-o", output, "--json", "--quiet")
            if status == 0:
                through += 1
                summary = json.loads(out)
                if "repair" in summary:
                    repaired.add(name)
                    assert summary["repair"][NEEDS_REPAIR[name]] > 0, (name, summary["repair"])
                assert (name in NEEDS_REPAIR) == ("repair" in summary), name
            else:
                assert status == 1, f"{command} {name}: exit {status}: {err}"
                # one line, that names the file and says why
                assert err.count("\n") == 1 and err.startswith(f"heat_diffusion: {path}: "), err
                refused[name] = err.strip()
    with capsys.disabled():
        print(f"\nCGAL's {len(names)} meshes through ncc, diffuse and denoise: {through} runs went through, "
              f"{len(repaired)} files of them repaired ({', '.join(sorted(repaired))}), "
              f"{len(refused)} refused ({'; '.join(refused.values())})")
    assert repaired == set(NEEDS_REPAIR)
    assert set(refused) == set(NOT_MESHES)
    for name, why in NOT_MESHES.items():
        assert why in refused[name]
    assert through == 3 * (len(names) - len(NOT_MESHES))


def test_no_repair_keeps_the_strict_reading(tool, data_dir, tmp_path):
    for name, message in (("pig.stl", "vertex 90 is non-manifold"), ("cube-shuffled.off", "cannot read a polygon mesh"),
                          ("cube-ouvert.off", "vertex 8 is isolated"), ("degtri_sliding.off", "has zero area")):
        status, _, err = tool_run(tool, tmp_path, "ncc", os.path.join(data_dir, name), "-o", "n.ply", "--no-repair")
        assert status == 1 and message in err and err.count("\n") == 1, err
        assert not os.path.exists(tmp_path / "n.ply")


def coordinates(ply):
    return np.column_stack([ply["x"], ply["y"], ply["z"]])


def matched(a, b, tolerance=0.0):
    """For each point of a, the index of the point of b at the same position, to `tolerance`
    times the bounding-box diagonal (all must have one)."""
    distance, index = cKDTree(b).query(a)
    diagonal = np.linalg.norm(b.max(axis=0) - b.min(axis=0))
    assert np.all(distance <= tolerance * diagonal), f"{np.sum(distance > tolerance * diagonal)} points without a match"
    return index


def off_vertices(path):
    """The vertices of an OFF file, as written (meshio does not read the comments of CGAL's soups)."""
    words = [w for line in open(path) for w in line.split("#")[0].split()]
    assert words[0] == "OFF"
    n = int(words[1])
    return np.array(words[4:4 + 3 * n], dtype=np.float64).reshape(n, 3)


def close(a, b, tolerance=1e-12):
    scale = max(1.0, float(np.max(np.abs(b))))
    assert float(np.max(np.abs(np.asarray(a) - np.asarray(b)))) <= tolerance * scale


def test_stl_export_equals_the_mesh(tool, mesh, tmp_path):
    """An STL export of fandisk (float coordinates, no shared vertices) gives the NS and the
    features of the OFF of the same coordinates, vertex for vertex."""
    V, F, _ = mesh("fandisk.off")
    V32 = V.astype(np.float32).astype(np.float64)
    write_off(tmp_path / "fandisk32.off", V32, F)
    # binary STL, as CAD programs export it: float32 coordinates, three points per facet
    facets = np.zeros(len(F), dtype=[("normal", "<f4", 3), ("points", "<f4", (3, 3)), ("attribute", "<u2")])
    facets["points"] = V32[F]
    facets["normal"] = np.cross(V32[F[:, 1]] - V32[F[:, 0]], V32[F[:, 2]] - V32[F[:, 0]])
    with open(tmp_path / "fandisk.stl", "wb") as stl:
        stl.write(b"binary STL of fandisk".ljust(80, b" "))
        stl.write(np.uint32(len(F)).tobytes())
        stl.write(facets.tobytes())
    for name in ("fandisk32.off", "fandisk.stl"):
        subprocess.run([tool, "features", name, "-o", name, "-k", "0,10", "--quiet"], cwd=tmp_path, check=True)
    for k in (0, 10):
        off = read_ply_vertices(tmp_path / f"fandisk32.off_k{k}.ply")
        stl = read_ply_vertices(tmp_path / f"fandisk.stl_k{k}.ply")
        index = matched(coordinates(stl), coordinates(off))
        assert len(set(index)) == len(index) == len(V)
        close(stl["field"], off["field"][index])
        assert np.array_equal(stl["feature"], off["feature"][index])


# (oblong-shuffled.off has its coordinates rounded: up to 1e-6 of the diagonal off oblong.off's)
@pytest.mark.parametrize("shuffled, original, tolerance", [("cube-shuffled.off", "cube.off", 0),
                                                           ("blobby-shuffled.off", "blobby.off", 0),
                                                           ("oblong-shuffled.off", "oblong.off", 1e-6)])
def test_shuffled_soup_equals_its_original(shuffled, original, tolerance, tool, data_dir, tmp_path):
    """A soup with inconsistent orientation, repaired, gives the NS of the consistently
    oriented original (outward: the repair turns closed components outward)."""
    for name in (shuffled, original):
        subprocess.run([tool, "diffuse", os.path.join(data_dir, name), "-o", name, "-k", "0,10", "--quiet"],
                       cwd=tmp_path, check=True)
    for k in (0, 10):
        repaired = read_ply_vertices(tmp_path / f"{shuffled}_k{k}.ply")
        reference = read_ply_vertices(tmp_path / f"{original}_k{k}.ply")
        index = matched(coordinates(repaired), coordinates(reference), tolerance)
        close(repaired["field"], reference["field"][index], 1e-9 if tolerance == 0 else 1e-3)
        if "origin" in repaired:  # merged duplicate points renumber the vertices
            V = off_vertices(os.path.join(data_dir, shuffled))
            assert np.array_equal(V[repaired["origin"].astype(np.int64)], coordinates(repaired))


def touching_copies(V, F):
    """Two copies of a mesh that touch at one vertex: a non-manifold vertex."""
    top = int(np.argmax(V[:, 2]))
    W = V - V[top]
    W[:, 2] *= -1  # the second copy mirrored below the first, its top at the same point
    copy_F = F[:, ::-1] + len(V)  # mirrored, so reversed to keep its outward orientation
    V2 = np.vstack([V - V[top], W])
    V2 = np.delete(V2, len(V) + top, axis=0)
    F2 = copy_F.copy()
    F2[F2 == len(V) + top] = top
    F2[F2 > len(V) + top] -= 1
    return V2, np.vstack([F, F2])


def rolled_sheet(n=12):
    """A square sheet rolled up until two of its corners meet, and only they: at that vertex
    the sheet's two ends are two fans (a scan's two sheets that touch)."""
    x, y = np.meshgrid(np.linspace(0, 1, n), np.linspace(0, 1, n))
    angle = 2 * np.pi * x * (1 - 0.5 * y)  # a full turn along the edge y = 0 only
    V = np.column_stack([np.cos(angle).ravel(), np.sin(angle).ravel(), y.ravel()])
    index = np.arange(n * n).reshape(n, n)
    quads = np.stack([index[:-1, :-1], index[:-1, 1:], index[1:, 1:], index[1:, :-1]], axis=-1).reshape(-1, 4)
    F = np.vstack([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])
    corner, other = index[0, 0], index[0, -1]  # the same point
    F[F == other] = corner
    F[F > other] -= 1
    return np.delete(V, other, axis=0), F


def test_non_manifold_meshes_are_repaired_and_map_back(tool, mesh, tmp_path):
    V, F, _ = mesh("elephant.off")
    cases = {"two copies touching at a vertex": touching_copies(V, F), "a rolled sheet": rolled_sheet()}
    for what, (V2, F2) in cases.items():
        with pytest.raises(ValueError, match=r"non-manifold.*cgal_heat_diffusion.repair\(V, F\) repairs"):
            hd.normal_signature(V2, F2)
        V3, F3, origin = hd.repair(V2, F2)
        assert len(V3) == len(V2) + 1 and np.array_equal(V3, V2[origin]), what
        assert set(origin) == set(range(len(V2))), what  # every input vertex has a vertex of the result
        ns = hd.normal_signature(V3, F3)
        copies = np.flatnonzero(np.bincount(origin) > 1)
        assert len(copies) == 1
        rows = np.flatnonzero(origin == copies[0])
        if what.startswith("two copies"):  # the copies of the split vertex have the same NS by symmetry
            close(ns[rows[0]], ns[rows[1]], 1e-9)
        assert np.all(np.isfinite(ns)) and np.all(np.isfinite(hd.denoise(V3, F3)))
        # the tool on the same file: the same mesh and NS, with origin in its output
        write_off(tmp_path / "non_manifold.off", V2, F2)
        status, out, err = tool_run(tool, tmp_path, "ncc", "non_manifold.off", "-o", "t.ply", "--json")
        assert status == 0 and "1 vertex split (non-manifold)" in err, err
        summary = json.loads(out)
        assert summary["repair"]["vertices_split"] == 1
        assert summary["repair"]["copies"] == {str(copies[0]): [int(r) for r in rows]}
        ply = read_ply_vertices(tmp_path / "t.ply")
        assert np.array_equal(ply["origin"], origin) and np.array_equal(coordinates(ply), V3)
        close(ply["ns"], ns)


def test_repair_of_a_mesh_that_needs_none_is_the_identity(mesh):
    for name in ("fandisk.off", "mech-holes-shark.off"):
        V, F, _ = mesh(name)
        V2, F2, origin = hd.repair(V, F)
        assert np.array_equal(V2, V) and np.array_equal(F2, F) and np.array_equal(origin, np.arange(len(V)))


def test_repair_of_soups(mesh):
    """Duplicate points, duplicate and degenerate faces, an isolated vertex, a reversed face."""
    V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [1, 0, 0], [5, 5, 5]], dtype=np.float64)
    F = np.array([[0, 1, 2], [0, 3, 2], [0, 2, 2], [0, 1, 2], [4, 2, 1]])
    V2, F2, origin = hd.repair(V, F)
    assert np.array_equal(V2, V[origin]) and 5 not in origin and 4 not in origin
    ns = hd.normal_signature(V2, F2)
    assert np.all(np.isfinite(ns))
    with pytest.raises(ValueError, match="repair: cannot be repaired into a mesh: no face is left"):
        hd.repair(V, np.array([[0, 1, 1], [2, 2, 2]]))
    with pytest.raises(ValueError, match=r"F\[0\] refers to vertex 9"):
        hd.repair(V, np.array([[0, 1, 9]]))
