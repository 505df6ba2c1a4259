# What the paper proves and the package guarantees, checked through the binding on
# CGAL's real meshes: heat conservation, the doubly stochastic A_t (and the paper's
# column-stochastic one), the detail bands,
# invariance of the Normal Signature, the input's vertex order; and the binding's own
# behaviour: the progress callback, cancellation, the GIL released during the work.
import signal
import threading
import time

import numpy as np
import pytest
import scipy.sparse

import cgal_heat_diffusion as hd

MESHES = ["fandisk.off", "armadillo.off"]


@pytest.fixture(scope="module")
def diffusions(mesh):
    cache = {}

    def get(name):
        if name not in cache:
            V, F, _ = mesh(name)
            cache[name] = hd.HeatDiffusion(V, F)
        return cache[name]
    return get


@pytest.mark.parametrize("name", MESHES)
def test_heat_is_conserved(name, diffusions):
    d = diffusions(name)
    ns = d.normal_signature()
    positive = np.abs(ns) + 1.0
    for field in (ns, positive):
        fields = d.diffuse(field, [1, 10, 100])
        for f in fields:
            assert abs(f.sum() - field.sum()) <= 1e-12 * np.abs(field).sum()
    # heat is moved, never created: a positive field stays positive
    assert d.diffuse(positive, 100).min() > 0


@pytest.mark.parametrize("name", MESHES)
def test_operator_matrix_is_doubly_stochastic(name, diffusions):
    d = diffusions(name)
    assert d.normalization == "balanced"
    A = d.operator_matrix()
    n = d.number_of_vertices
    assert isinstance(A, scipy.sparse.csc_matrix) and A.shape == (n, n)
    assert A.has_sorted_indices and A.nnz > n
    assert A.data.min() > 0
    assert np.max(np.abs(np.asarray(A.sum(axis=0)).ravel() - 1.0)) <= 1e-13
    assert np.max(np.abs(np.asarray(A.sum(axis=1)).ravel() - 1.0)) <= 1e-13
    assert abs(A - A.T).max() <= 1e-15
    # the diagonal is there (each vertex keeps part of its heat)
    assert np.all(A.diagonal() > 0)
    ns = d.normal_signature()
    assert np.max(np.abs(A @ ns - d.diffuse(ns, 1))) <= 1e-13 * np.max(np.abs(ns))
    assert np.max(np.abs(A @ (A @ ns) - d.diffuse(ns, 2))) <= 1e-13 * np.max(np.abs(ns))
    # a constant stays constant, and every diffused value lies within the input's range
    assert np.max(np.abs(d.diffuse(np.full(n, 3.0), 100) - 3.0)) <= 1e-12 * 3.0
    f = d.diffuse(ns, 100)
    assert ns.min() - 1e-13 <= f.min() and f.max() <= ns.max() + 1e-13
    stats = d.region_statistics()
    assert stats["min_size"] <= stats["mean_size"] <= stats["max_size"]
    # A_t lives on the regions made symmetric: at least their entries
    assert A.nnz >= round(stats["mean_size"] * n)


def test_paper_normalization(mesh):
    V, F, _ = mesh("fandisk.off")
    d = hd.HeatDiffusion(V, F, normalization="columns")
    assert d.normalization == "columns"
    A = d.operator_matrix()
    n = d.number_of_vertices
    assert np.max(np.abs(np.asarray(A.sum(axis=0)).ravel() - 1.0)) <= 1e-13
    rows = np.asarray(A.sum(axis=1)).ravel()
    assert rows.min() < 0.9 and rows.max() > 1.1  # what the balancing is for
    assert A.nnz == round(d.region_statistics()["mean_size"] * n)
    ones = d.diffuse(np.ones(n), 100)
    assert abs(ones.sum() - n) <= 1e-9 and ones.max() > 1.1
    with pytest.raises(ValueError, match="normalization must be 'balanced', 'columns' or None"):
        hd.HeatDiffusion(V, F, normalization="rows")


def test_diffuse_steps(diffusions):
    d = diffusions("fandisk.off")
    ns = d.normal_signature()
    together = d.diffuse(ns, [40, 0, 10, 10])
    assert together.shape == (4, len(ns))
    for row, k in enumerate([40, 0, 10, 10]):
        assert np.array_equal(together[row], d.diffuse(ns, k))
    assert np.array_equal(d.diffuse(ns, 0), ns)
    assert np.array_equal(d.diffuse(ns, np.int64(3)), d.diffuse(ns, 3))
    assert d.diffuse(ns, []).shape == (0, len(ns))


def test_decomposition(diffusions, mesh):
    d = diffusions("fandisk.off")
    ns = d.normal_signature()
    bands, residual = d.decompose(ns, 3, steps_per_level=5)
    assert bands.shape == (3, len(ns)) and residual.shape == (len(ns),)
    scale = np.abs(ns).sum()
    for band in bands:  # eq. 25: every band sums to zero
        assert abs(band.sum()) <= 1e-12 * scale
    assert np.max(np.abs(bands.sum(axis=0) + residual - ns)) <= 1e-12 * np.max(np.abs(ns))
    assert np.array_equal(residual, d.diffuse(ns, 15))
    assert np.max(np.abs(hd.synthesize(bands, residual, [1, 1, 1]) - ns)) <= 1e-12 * np.max(np.abs(ns))
    assert np.array_equal(hd.synthesize(bands, residual, [0, 0, 0]), residual)
    V, F, _ = mesh("fandisk.off")
    bands2, residual2 = hd.decompose(V, F, levels=3, steps_per_level=5)
    assert np.array_equal(bands2, bands) and np.array_equal(residual2, residual)
    # decompose_field()'s own steps per level
    bands3, residual3 = d.decompose(ns, 2)
    assert bands3.shape == (2, len(ns))
    assert np.max(np.abs(bands3.sum(axis=0) + residual3 - ns)) <= 1e-12 * np.max(np.abs(ns))
    assert all(abs(band.sum()) <= 1e-12 * scale for band in bands3)


def rotation(seed):
    q, r = np.linalg.qr(np.random.default_rng(seed).normal(size=(3, 3)))
    q = q * np.sign(np.diag(r))
    return q if np.linalg.det(q) > 0 else -q


@pytest.mark.parametrize("name", MESHES)
def test_normal_signature_invariance(name, mesh):
    V, F, _ = mesh(name)
    ns = hd.normal_signature(V, F)
    moved = np.ascontiguousarray((2.75 * V) @ rotation(1).T + np.array([3.0, -1.0, 7.0]))
    assert np.max(np.abs(hd.normal_signature(moved, F) - ns)) <= 1e-9 * np.max(np.abs(ns))


def test_results_follow_the_input_order(mesh):
    """The same mesh with its vertices shuffled gives the same results, shuffled."""
    V, F, _ = mesh("fandisk.off")
    order = np.random.default_rng(7).permutation(len(V))  # new vertex i is old vertex order[i]
    new_index = np.empty_like(order)
    new_index[order] = np.arange(len(V))
    V2, F2 = np.ascontiguousarray(V[order]), np.ascontiguousarray(new_index[F])
    ns, ns2 = hd.normal_signature(V, F), hd.normal_signature(V2, F2)
    assert np.max(np.abs(ns2 - ns[order])) <= 1e-12 * np.max(np.abs(ns))
    d, d2 = hd.HeatDiffusion(V, F), hd.HeatDiffusion(V2, F2)
    f, f2 = d.diffuse(ns, 10), d2.diffuse(ns2, 10)
    # to the local kernel's accuracy: its patches follow clusters of the spatial order,
    # whose ties the input order breaks (2.3e-5 of the largest value at the default
    # tolerance, 1e-2)
    assert np.max(np.abs(f2 - f[order])) <= 1e-4 * np.max(np.abs(f))
    features = d.features(steps=[10])[0]
    features2 = d2.features(steps=[10])[0]
    assert sorted(order[features2["convex"]]) == features["convex"].tolist()
    assert sorted(order[features2["concave"]]) == features["concave"].tolist()


def test_reconstruction_and_filtering(mesh):
    V, F, _ = mesh("fandisk.off")
    diagonal = np.linalg.norm(V.max(axis=0) - V.min(axis=0))
    ns = hd.normal_signature(V, F)
    # with its own NS the mesh is reproduced (up to rounding)
    assert np.max(np.abs(hd.reconstruct(V, F, ns) - V)) <= 1e-8 * diagonal
    # weights 1 give back the NS: the shape is reproduced
    same = hd.filter_shape(V, F, [1.0, 1.0, 1.0], steps_per_level=5, anchor_weight=1.0)
    assert np.max(np.abs(same - V)) <= 1e-8 * diagonal
    # enhanced details (filter_shape()'s own steps per level and anchor weight) move the
    # vertices, and the NS follows the weights
    W = hd.filter_shape(V, F, [1.0, 3.0, 3.0])
    assert W.shape == V.shape and np.all(np.isfinite(W))
    assert np.max(np.abs(W - V)) > 1e-4 * diagonal
    assert np.var(hd.normal_signature(W, F)) > np.var(ns)


def noisy_fandisk(mesh):
    V, F, _ = mesh("fandisk.off")
    edges = np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])
    mean_edge = np.linalg.norm(V[edges[:, 0]] - V[edges[:, 1]], axis=1).mean()
    noise = np.random.default_rng(3).normal(scale=0.2 * mean_edge, size=V.shape)
    return V, F, np.ascontiguousarray(V + noise)


def face_normals(V, F):
    n = np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]])
    return n / np.linalg.norm(n, axis=1)[:, None]


def test_denoising(mesh):
    V, F, noisy = noisy_fandisk(mesh)
    denoised = hd.denoise(noisy, F)
    assert denoised.shape == V.shape and np.all(np.isfinite(denoised))
    # the mean angle between the face normals and those of the clean mesh (degrees)
    error = lambda X: np.degrees(np.arccos(np.clip((face_normals(X, F) * face_normals(V, F)).sum(axis=1), -1, 1))).mean()
    assert error(denoised) < 0.5 * error(noisy), (error(denoised), error(noisy))


def test_heat_kernel_signature(mesh):
    V, F, _ = mesh("fandisk.off")
    early = hd.heat_kernel_signature(V, F, time=5.0, m=40)
    late = hd.heat_kernel_signature(V, F, time=50.0, m=40)
    assert early.shape == (len(V),) and np.all(early > 0) and np.all(late > 0)
    assert np.all(late <= early * (1 + 1e-12))  # h_t(i, i) decreases with t


def test_progress_reports_and_cancels(mesh):
    V, F, _ = mesh("fandisk.off")
    fractions = []
    hd.HeatDiffusion(V, F, progress=fractions.append)  # None: continue
    assert fractions and fractions == sorted(fractions) and 0 <= fractions[0] and fractions[-1] == 1.0
    calls = []

    def cancel(fraction):
        calls.append(fraction)
        return False
    with pytest.raises(RuntimeError, match="cancelled"):
        hd.HeatDiffusion(V, F, progress=cancel)
    assert len(calls) == 1
    with pytest.raises(RuntimeError, match="cancelled"):
        hd.HeatDiffusion(V, F, kernel="spectral", m=20, progress=lambda f: f < 0.3)
    with pytest.raises(RuntimeError, match="cancelled"):
        hd.denoise(noisy_fandisk(mesh)[2], F, progress=lambda f: False)

    def fail(fraction):
        raise ZeroDivisionError("from the callback")
    with pytest.raises(ZeroDivisionError, match="from the callback"):
        hd.HeatDiffusion(V, F, progress=fail)
    with pytest.raises(ValueError, match="progress must be callable"):
        hd.HeatDiffusion(V, F, progress=3)
    # the object still works after a cancelled construction of another
    assert hd.HeatDiffusion(V, F).diffuse(hd.normal_signature(V, F), 1).shape == (len(V),)


def test_keyboard_interrupt_cancels(mesh):
    """Ctrl-C during a long construction (the eigen solve, GIL released) cancels it:
    the construction stops before its end (the progress never reaches 1), rather than
    running to completion and leaving the interrupt to the next Python bytecode."""
    V, F, _ = mesh("armadillo.off")
    main = threading.get_ident()
    fractions = []
    timer = threading.Timer(0.2, lambda: signal.pthread_kill(main, signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            hd.HeatDiffusion(V, F, kernel="spectral", m=150, progress=fractions.append)
    finally:
        timer.cancel()
    assert fractions and max(fractions) < 1.0, fractions[-5:]


def test_gil_is_released(mesh):
    """Another Python thread runs while the C++ work runs."""
    V, F, _ = mesh("armadillo.off")
    done = threading.Event()
    ticks = 0

    def work():
        hd.HeatDiffusion(V, F)
        done.set()
    worker = threading.Thread(target=work)
    worker.start()
    while not done.is_set():
        ticks += 1
        time.sleep(0.001)
    worker.join()
    # with the GIL held for the whole construction, this thread would run only at the
    # few progress calls
    assert ticks > 20


@pytest.mark.parametrize("work", ["diffuse", "features", "decompose"])
def test_keyboard_interrupt_stops_a_long_diffusion(diffusions, work):
    """A diffusion of many steps stops soon after Ctrl-C, not at its end, also inside
    features() and decompose()."""
    d = diffusions("armadillo.off")
    ns = d.normal_signature()
    start = time.perf_counter()
    d.diffuse(ns, 200)
    per_200 = time.perf_counter() - start
    long_runs = {  # each 200000 steps, 1000 times the steps timed above
        "diffuse": lambda: d.diffuse(ns, 200000),
        "features": lambda: d.features(ns, [0, 200000]),
        "decompose": lambda: d.decompose(ns, levels=10, steps_per_level=20000),
    }
    main = threading.get_ident()
    timer = threading.Timer(0.2, lambda: signal.pthread_kill(main, signal.SIGINT))
    start = time.perf_counter()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            long_runs[work]()
    finally:
        timer.cancel()
    elapsed = time.perf_counter() - start
    assert elapsed < 100 * per_200 + 1.0, f"{elapsed:.1f} s, {per_200:.3f} s per 200 steps"
    # the object is intact
    assert np.array_equal(d.diffuse(ns, 3), d.diffuse(ns, [3])[0])
