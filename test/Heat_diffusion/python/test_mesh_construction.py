# The Surface_mesh the binding builds from V and F in one pass (surface_mesh_from_triangles.h)
# must be the very mesh that add_face() builds face by face: same edge, halfedge and face
# numbers, same links, same vertex halfedges (the package then computes the same bits).
# Input that is not an oriented manifold must be declined, so that add_face() decides as
# before (same meshes, same errors). hd._compare_mesh_constructions(V, F) builds both and
# returns (one-pass construction applied, first difference or None).
import numpy as np
import pytest

import cgal_heat_diffusion as hd

from test_hostile_input import BAD_MESHES

MESHES = ["fandisk.off", "armadillo.off", "elephant.off", "mech-holes-shark.off", "blobby_3cc.off"]


def variants(V, F, seed):
    """V and F, then the same surface with its faces shuffled, each face's corners
    rotated, and its vertices renumbered: other orders in which add_face() meets them."""
    rng = np.random.default_rng(seed)
    yield "as read", V, F
    shuffled = F[rng.permutation(len(F))]
    yield "faces shuffled", V, np.ascontiguousarray(shuffled)
    shift = rng.integers(0, 3, len(F))
    rotated = np.take_along_axis(shuffled, (np.arange(3)[None, :] + shift[:, None]) % 3, axis=1)
    yield "corners rotated", V, np.ascontiguousarray(rotated)
    order = rng.permutation(len(V))  # new vertex i is old vertex order[i]
    new_index = np.empty_like(order)
    new_index[order] = np.arange(len(V))
    yield "vertices renumbered", np.ascontiguousarray(V[order]), np.ascontiguousarray(new_index[F])


@pytest.mark.parametrize("name", MESHES)
def test_one_pass_mesh_is_the_add_face_mesh(mesh, name):
    V, F, _ = mesh(name)
    for label, V1, F1 in variants(V, F, seed=len(name)):
        applied, difference = hd._compare_mesh_constructions(V1, F1)
        assert applied, f"{name}, {label}: the one-pass construction declined a manifold mesh"
        assert difference is None, f"{name}, {label}: {difference}"


def test_one_pass_mesh_of_a_large_mesh():
    # 104k vertices, faces in subdivision order.
    V, F = hd.loop_subdivision(*[np.ascontiguousarray(a) for a in small_closed_mesh()], 6)
    applied, difference = hd._compare_mesh_constructions(V, F)
    assert applied and difference is None, difference


def small_closed_mesh():
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=np.float64)
    F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]], dtype=np.int64)
    return V, F


def test_small_manifolds_the_package_may_reject():
    # Built in one pass as add_face() builds them; the package rejects some of them
    # (isolated vertices: test_hostile_input).
    V, F = small_closed_mesh()
    assert hd._compare_mesh_constructions(np.vstack([V, [[5.0, 5, 5]]]), F) == (True, None)
    assert hd._compare_mesh_constructions(V, np.zeros((0, 3), dtype=np.int64)) == (True, None)
    assert hd._compare_mesh_constructions(V[:3], np.array([[0, 1, 2]])) == (True, None)
    # A triangle and its reverse: a closed surface of two faces.
    assert hd._compare_mesh_constructions(V[:3], np.array([[0, 1, 2], [0, 2, 1]])) == (True, None)


TWO_TETRAHEDRA_V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [-1, 0, 0], [0, -1, 0], [0, 0, -1]],
                            dtype=np.float64)
NOT_MANIFOLD = {
    "non-manifold edge": BAD_MESHES["non-manifold edge"][:2],
    "inconsistent orientation": BAD_MESHES["inconsistent orientation"][:2],
    "duplicated face": BAD_MESHES["duplicated face"][:2],
    "two open fans at a vertex": BAD_MESHES["non-manifold vertex"][:2],
    # Two closed fans at vertex 0 (no border halfedge to give it away).
    "two tetrahedra sharing a vertex": (TWO_TETRAHEDRA_V, np.array(
        [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3], [0, 4, 5], [0, 6, 4], [0, 5, 6], [4, 6, 5]])),
    # An open fan and a closed one at vertex 0.
    "open and closed fans at a vertex": (TWO_TETRAHEDRA_V, np.array(
        [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3], [0, 4, 5]])),
}


@pytest.mark.parametrize("case", sorted(NOT_MANIFOLD))
def test_not_manifold_is_declined(case):
    V, F = NOT_MANIFOLD[case]
    applied, difference = hd._compare_mesh_constructions(np.ascontiguousarray(V), np.ascontiguousarray(F))
    assert not applied, f"{case}: built in one pass"
    assert difference is None, difference
