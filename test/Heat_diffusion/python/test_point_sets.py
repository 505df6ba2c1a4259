# The module on point sets: P (n x 3) and optional normals N, the results per row of P,
# the guarantees of the point-set diffusion as numpy sees them, and bad input raising
# ValueError that names the point (parity with the library: test_parity.py).
import os
import warnings

import numpy as np
import pytest

import cgal_heat_diffusion as hd
from conftest import read_ply_vertices, read_points


def bump(n=7):
    """A paraboloid patch of n x n points off a lattice (no four of them cocircular), and its normals."""
    x, y = np.meshgrid(np.arange(n, dtype=float), np.arange(n, dtype=float))
    x, y = x.ravel(), y.ravel()
    x, y = x + 0.05 * np.sin(3 * y), y + 0.05 * np.cos(2 * x)
    c = (n - 1) / 2
    P = np.column_stack([x, y, 0.08 * ((x - c) ** 2 + (y - c) ** 2)])
    N = np.column_stack([-0.16 * (x - c), -0.16 * (y - c), np.ones_like(x)])
    return P, N / np.linalg.norm(N, axis=1)[:, None]


def test_diffusion_on_points_conserves_heat_and_is_its_matrix(point_data_dir):
    P, N, _ = read_points(point_data_dir, "kitten.xyz")
    diffusion = hd.PointSetHeatDiffusion(P, N)
    assert diffusion.number_of_points == len(P) and diffusion.normalization == "balanced"
    ns = diffusion.normal_signature()
    assert np.array_equal(ns, hd.point_set_normal_signature(P, N))
    assert np.all(np.isfinite(ns)) and ns.min() < 0 < ns.max()
    fields = diffusion.diffuse(ns, [0, 1, 10])
    assert fields.shape == (3, len(P)) and np.array_equal(fields[0], ns)
    assert np.all(np.abs(fields.sum(axis=1) - ns.sum()) <= 1e-11 * np.abs(ns).sum())
    A = diffusion.operator_matrix()
    assert A.shape == (len(P), len(P)) and A.has_sorted_indices
    assert np.allclose(A @ ns, fields[1], rtol=0, atol=1e-13 * np.abs(ns).max())
    assert np.abs(np.asarray(A.sum(axis=0)).ravel() - 1).max() < 1e-12  # columns: heat is conserved
    normals = diffusion.normals()
    assert np.allclose(np.linalg.norm(normals, axis=1), 1) and np.all(np.sum(normals * N, axis=1) > 0.99)
    coordinates, normals_of_ncc = hd.point_set_normal_controlled_coordinates(P, N)
    assert np.array_equal(normals_of_ncc, normals)
    assert np.allclose(coordinates, ns[:, None] * normals, rtol=0, atol=1e-15)
    stats = diffusion.region_statistics()
    assert 1 <= stats["min_size"] <= stats["mean_size"] <= stats["max_size"]
    for scale in diffusion.features(steps=[0, 10]):
        assert len(scale["convex"]) > 0 and np.all(np.diff(scale["convex"]) > 0)
        assert np.all((0 <= scale["concave"]) & (scale["concave"] < len(P)))


def test_estimated_normals_are_oriented_outward_on_a_bump():
    P, N = bump()
    estimated = hd.PointSetHeatDiffusion(P).normals()
    # mst_orient_normals() gives one orientation of the patch: the same as N, or the opposite for all
    agreement = np.sum(estimated * N, axis=1)
    assert np.all(agreement > 0.9) or np.all(agreement < -0.9), agreement


def test_field_per_point_and_steps():
    P, N = bump()
    diffusion = hd.PointSetHeatDiffusion(P, N, sigma=1.0)
    f = np.arange(len(P), dtype=float)
    one = diffusion.diffuse(f)  # one step by default, an (n,) array
    assert one.shape == (len(P),) and np.array_equal(one, diffusion.diffuse(f, [1])[0])
    assert abs(one.sum() - f.sum()) <= 1e-12 * f.sum()


P_BUMP, N_BUMP = bump()

BAD_POINT_SETS = {
    "P of shape (n, 2)": (P_BUMP[:, :2], None, {}, r"P must have shape \(n, 3\)"),
    "P of text": ([["0", "0", "0"]] * 10, None, {}, "P must be an array of numbers"),
    "NaN point": (np.vstack([P_BUMP[:5], [[1, np.nan, 2]], P_BUMP[5:]]), None, {},
                  r"P\[5\] is \(1, nan, 2\), not a finite point"),
    "N of another shape": (P_BUMP, N_BUMP[:10], {}, r"N must have shape \(49, 3\) \(one normal per row of P\)"),
    "NaN normal": (P_BUMP, np.where(np.arange(49)[:, None] == 4, np.nan, N_BUMP), {},
                   r"N\[4\] is \(nan, nan, nan\), not a finite normal"),
    "null normal": (P_BUMP, np.where(np.arange(49)[:, None] == 4, 0.0, N_BUMP), {},
                    "point 4 has a null or non-finite normal"),
    "duplicate points": (np.vstack([P_BUMP, P_BUMP[3:4]]), None, {}, "point 3 coincides with point 49"),
    # (k + 1 = 25 for point_set_denoise, whose neighbour count is 24)
    "fewer points than k + 1": (P_BUMP[:5], None, {}, r"the point set has 5 points, fewer than k \+ 1 = (9|25)"),
    "collinear points": (np.column_stack([np.arange(40.0), 2 * np.arange(40.0), np.zeros(40)]), None, {},
                         "point 0 .*(degenerate neighbourhood|no usable estimated normal)"),
    "two clusters, no normals": (np.vstack([P_BUMP, P_BUMP + [1000, 0, 0]]), None, {},
                                 r"could not orient .* give oriented normals as N \(n x 3\), or more neighbours "
                                 r"\(neighbors=\)"),
    "neighbors 1": (P_BUMP, N_BUMP, {"neighbors": 1}, "the neighbour count k must be at least 2"),
    "neighbors -1": (P_BUMP, N_BUMP, {"neighbors": -1}, "neighbors must be from 0 to"),
    "neighbors 2.5": (P_BUMP, N_BUMP, {"neighbors": 2.5}, "neighbors must be a whole number"),
    "negative radius": (P_BUMP, N_BUMP, {"neighbor_radius": -1.0}, "neighbor_radius must be positive"),
    "NaN radius": (P_BUMP, N_BUMP, {"neighbor_radius": float("nan")}, "neighbor_radius must be positive"),
}


# Every function on point sets, called on P and N with the keywords it needs besides.
POINT_SET_FUNCTIONS = {
    "point_set_normal_signature": lambda P, N, **kw: hd.point_set_normal_signature(P, N, **kw),
    "PointSetHeatDiffusion": lambda P, N, **kw: hd.PointSetHeatDiffusion(P, N, **kw),
    "point_set_multiscale_features": lambda P, N, **kw: hd.point_set_multiscale_features(P, N, **kw),
    "point_set_decompose": lambda P, N, **kw: hd.point_set_decompose(P, N, **kw),
    "point_set_filter_shape": lambda P, N, **kw: hd.point_set_filter_shape(P, N, weights=[0, 0, 1], **kw),
    "point_set_denoise": lambda P, N, **kw: hd.point_set_denoise(P, N, **kw),
}


@pytest.mark.parametrize("case", list(BAD_POINT_SETS))
@pytest.mark.parametrize("function", list(POINT_SET_FUNCTIONS))
def test_bad_point_sets_raise_value_error(case, function):
    P, N, keywords, message = BAD_POINT_SETS[case]
    with pytest.raises(ValueError, match=message):
        POINT_SET_FUNCTIONS[function](P, N, **keywords)


def far_point_grid(n, far, axis, normals):
    """A grid of n points on a bumpy height field (rows of 5, or of 10 from 50 points), its
    last point moved to `far` along `axis` (0: x, 2: z, -1: -x), with normals or None."""
    i = np.arange(n)
    width = 10 if n >= 50 else 5
    x = i % width + 0.02 * np.sin(7 * i)
    y = i // width + 0.03 * np.cos(5 * i)
    P = np.column_stack([x, y, 0.3 * np.sin(x) * np.cos(y) + 0.05 * np.sin(13 * i)])
    P[-1, abs(axis) if axis >= 0 else 0] = far if axis >= 0 else -far
    N = np.column_stack([-0.1 * np.cos(x) * np.cos(y), 0.1 * np.sin(x) * np.sin(y), np.ones(n)]) if normals else None
    return P, N


FAR_POINT_CASES = [(far, [10, 22, 35, 100][k % 4], [0, -1, 2][k % 3], normals)
                   for k, (far, normals) in enumerate((far, normals) for far in [1e40, 5.5555555555555555e78, 1e150,
                                                                                  1e200, 1e300]
                                                      for normals in (False, True))]


@pytest.mark.parametrize("far, n, axis, normals", FAR_POINT_CASES)
@pytest.mark.parametrize("function", list(POINT_SET_FUNCTIONS))
def test_a_far_point_is_named(function, far, n, axis, normals):
    # One point far from all the others (once a crash of the interpreter, in CGAL's jet
    # fitting): refused with a message that names it.
    P, N = far_point_grid(n, far, axis, normals)
    message = (rf"point \d+ has its \d+ neighbours within .*point {n - 1}, at \S+ from its nearest neighbour, is the "
               rf"farthest from the others|fewer than k \+ 1 = 25")
    with pytest.raises(ValueError, match=message):
        POINT_SET_FUNCTIONS[function](P, N)


def test_point_sets_take_both_kernels():
    spectral = hd.PointSetHeatDiffusion(P_BUMP, N_BUMP, kernel="spectral", m=20)
    assert spectral.kernel == "spectral" and hd.PointSetHeatDiffusion(P_BUMP, N_BUMP).kernel == "local"
    assert hd.PointSetHeatDiffusion(P_BUMP, N_BUMP, scale_invariant=True).kernel == "spectral"  # the package's rule
    ns = spectral.normal_signature()
    f = spectral.diffuse(ns, 10)
    assert abs(f.sum() - ns.sum()) <= 1e-12 * np.abs(ns).sum()
    with pytest.raises(ValueError, match="m, coarse and scale_invariant concern the eigenpairs of the spectral kernel"):
        hd.PointSetHeatDiffusion(P_BUMP, N_BUMP, kernel="local", m=20)
    with pytest.raises(ValueError, match="kernel_tolerance concerns the local kernel"):
        hd.PointSetHeatDiffusion(P_BUMP, N_BUMP, kernel="spectral", kernel_tolerance=1e-3)
    with pytest.raises(TypeError):  # no coarse level on points: the spectral kernel has the points' own eigenpairs
        hd.PointSetHeatDiffusion(P_BUMP, N_BUMP, coarse=20)
    with pytest.raises(ValueError, match="normalization must be 'balanced', 'columns' or None"):
        hd.PointSetHeatDiffusion(P_BUMP, N_BUMP, normalization="rows")
    diffusion = hd.PointSetHeatDiffusion(P_BUMP, N_BUMP)
    with pytest.raises(ValueError, match=r"field must have shape \(49,\)"):
        diffusion.diffuse(np.zeros(3), 1)
    with pytest.raises(ValueError, match="field value at point 2 is nan"):
        diffusion.diffuse(np.where(np.arange(49) == 2, np.nan, 0.0), 1)


HOSTILE_DIR = os.environ.get("HEAT_DIFFUSION_HOSTILE_DATA_DIR", "")
POINT_FILES = sorted(f for f in os.listdir(HOSTILE_DIR) if f.startswith("points_")) if os.path.isdir(HOSTILE_DIR) else []


def test_hostile_point_files_are_there():
    assert len(POINT_FILES) >= 15, POINT_FILES


def arrays_of_point_file(path):
    """P and N (None without normals) of a point file, as numpy reads it."""
    if path.endswith(".ply"):
        ply = read_ply_vertices(path)
        P = np.column_stack([ply["x"], ply["y"], ply["z"]])
        return P, (np.column_stack([ply["nx"], ply["ny"], ply["nz"]]) if "nx" in ply else None)
    skip = 2 if path.endswith(".off") else 0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # (an empty file)
        values = np.loadtxt(path, ndmin=2, skiprows=skip, comments="#")
    return values[:, :3], (values[:, 3:6] if values.shape[1] >= 6 else None)


@pytest.mark.parametrize("name", POINT_FILES)
def test_hostile_point_file(name):
    try:
        P, N = arrays_of_point_file(os.path.join(HOSTILE_DIR, name))
    except ValueError as e:  # numpy cannot read it (an incomplete line): no arrays to give
        pytest.skip(f"{name} cannot be read into arrays: {e}")
    for function_name, function in POINT_SET_FUNCTIONS.items():
        try:
            result = function(P, N)
        except ValueError as e:
            assert str(e), f"{name}: {function_name}: ValueError without a message"
            continue
        for array in result if isinstance(result, tuple) else [result]:
            if isinstance(array, np.ndarray):
                assert np.all(np.isfinite(array)), f"{name}: {function_name}: non-finite values"
        if isinstance(result, hd.PointSetHeatDiffusion):
            f = result.diffuse(result.normal_signature(), [0, 5])
            assert np.all(np.isfinite(f)) and abs(f[1].sum() - f[0].sum()) <= 1e-12 * max(1.0, np.abs(f[0]).sum())


def noisy_bump(seed=1, n=15, noise=0.02):
    """bump() with n x n points moved along their normals by Gaussian noise."""
    P, N = bump(n)
    return P + np.random.default_rng(seed).normal(0, noise, len(P))[:, None] * N, N


def test_point_set_denoise_moves_points_along_their_normals_only():
    P, N = noisy_bump()
    P_copy, N_copy = P.copy(), N.copy()
    X, M = hd.point_set_denoise(P, N)
    assert np.array_equal(P, P_copy) and np.array_equal(N, N_copy)  # the caller's arrays are kept
    assert X.shape == P.shape and M.shape == N.shape and np.all(np.isfinite(X))
    assert np.allclose(np.linalg.norm(M, axis=1), 1) and np.all(np.sum(M * N, axis=1) > 0.9)
    moved = X - P
    assert np.abs(moved).max() > 0  # the noise is there to remove
    # each displacement is along the point's output normal: its part across it is rounding
    across = moved - np.sum(moved * M, axis=1)[:, None] * M
    assert np.linalg.norm(across, axis=1).max() <= 1e-9 * np.linalg.norm(moved, axis=1).max()
    X_estimated, M_estimated = hd.point_set_denoise(P)  # normals estimated: not returned
    assert M_estimated is None and X_estimated.shape == P.shape and np.all(np.isfinite(X_estimated))
    assert np.array_equal(hd.point_set_denoise(P, N, number_of_iterations=0)[0], P)


def test_point_set_decompose_and_filter_shape():
    P, N = noisy_bump(noise=0.005)
    ns = hd.point_set_normal_signature(P, N)
    bands, residual = hd.point_set_decompose(P, N, levels=3)
    assert bands.shape == (3, len(P)) and residual.shape == (len(P),)
    assert np.allclose(bands.sum(axis=0) + residual, ns, rtol=0, atol=1e-12 * np.abs(ns).max())
    assert np.all(np.abs(bands.sum(axis=1)) <= 1e-12 * np.abs(ns).sum())  # every band sums to 0 (eq. 25)
    diffusion = hd.PointSetHeatDiffusion(P, N)
    same_bands, same_residual = diffusion.decompose(levels=3)
    assert np.array_equal(same_bands, bands) and np.array_equal(same_residual, residual)
    assert np.allclose(hd.synthesize(bands, residual, [1, 1, 1]), ns, rtol=0, atol=1e-12 * np.abs(ns).max())
    diagonal = np.linalg.norm(P.max(axis=0) - P.min(axis=0))
    # unit weights keep the points; the smoothing filter moves them, along their normals
    assert np.abs(hd.point_set_filter_shape(P, N, weights=[1, 1, 1]) - P).max() <= 1e-9 * diagonal
    smoothed = hd.point_set_filter_shape(P, N, weights=[0, 0, 1])
    assert np.abs(smoothed - P).max() > 1e-4 * diagonal
    assert np.var(hd.point_set_normal_signature(smoothed, N)) < np.var(ns)
    with pytest.raises(ValueError, match="weights must have 1 to 1000 values"):
        hd.point_set_filter_shape(P, N, weights=[])
    with pytest.raises(ValueError, match="levels must be from 1 to 1000"):
        hd.point_set_decompose(P, N, levels=0)
