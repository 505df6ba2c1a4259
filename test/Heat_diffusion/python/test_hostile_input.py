# Bad input through the binding: every case raises ValueError with a message (the
# package's own, or the binding's for what never reaches the package), never a crash.
# The hostile corpus of test/Heat_diffusion/data goes through it too.
import os
import subprocess
import sys
import tempfile

import numpy as np
import pytest

import cgal_heat_diffusion as hd

# A square of two triangles and a tetrahedron: small valid meshes to break.
SQUARE_V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=np.float64)
SQUARE_F = np.array([[0, 1, 2], [0, 2, 3]], dtype=np.int64)
TETRA_V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=np.float64)
TETRA_F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]], dtype=np.int32)

ALL_FUNCTIONS = {
    "normal_signature": lambda V, F: hd.normal_signature(V, F),
    "normal_controlled_coordinates": lambda V, F: hd.normal_controlled_coordinates(V, F),
    "HeatDiffusion": lambda V, F: hd.HeatDiffusion(V, F),
    "HeatDiffusion spectral": lambda V, F: hd.HeatDiffusion(V, F, kernel="spectral", m=3),
    "multiscale_features": lambda V, F: hd.multiscale_features(V, F),
    "decompose": lambda V, F: hd.decompose(V, F),
    "filter_shape": lambda V, F: hd.filter_shape(V, F, [1.0, 2.0]),
    "heat_kernel_signature": lambda V, F: hd.heat_kernel_signature(V, F, m=3),
    "denoise": lambda V, F: hd.denoise(V, F),
    "reconstruct": lambda V, F: hd.reconstruct(V, F, np.zeros(len(V))),
}

BAD_MESHES = {
    # (float32, integer coordinates, Fortran order, views and lists are accepted: test_parity.py)
    "V of bool": (SQUARE_V.astype(bool), SQUARE_F, "V must be an array of numbers, not of bool"),
    "V of complex": (SQUARE_V.astype(complex), SQUARE_F, "V must be an array of numbers, not of complex128"),
    "V of text": ([["0", "0", "0"]] * 4, SQUARE_F, r"V must be an array of numbers, not of <U1 \(list\)"),
    "V ragged": ([[0.0, 0, 0], [1.0, 0]], SQUARE_F, "V must be an array of numbers"),
    "V of objects": (SQUARE_V.astype(object), SQUARE_F, "V must be an array of numbers, not of object"),
    "V of shape (n, 2)": (np.ascontiguousarray(SQUARE_V[:, :2]), SQUARE_F, r"V must have shape \(n, 3\)"),
    "V flat": (SQUARE_V.ravel(), SQUARE_F, r"V must have shape \(n, 3\)"),
    "F of float": (SQUARE_V, SQUARE_F.astype(np.float64), "F must be an array of integers, not of float64"),
    "F of bool": (SQUARE_V, SQUARE_F.astype(bool), "F must be an array of integers, not of bool"),
    "F of float lists": (SQUARE_V, [[0, 1, 2.5]], r"F must be an array of integers, not of float64 \(list\)"),
    "F of quads": (SQUARE_V, np.array([[0, 1, 2, 3]]), r"F must have shape \(m, 3\)"),
    "F out of range": (SQUARE_V, np.array([[0, 1, 2], [0, 2, 4]]), r"F\[1\] refers to vertex 4, out of range"),
    "F negative": (SQUARE_V, np.array([[0, 1, 2], [0, -1, 3]]), "refers to vertex -1, out of range"),
    "F huge": (SQUARE_V, np.array([[0, 1, 2], [0, 2, 2**62]], dtype=np.int64), "out of range"),
    "F huge unsigned": (SQUARE_V, np.array([[0, 1, 2], [0, 2, 2**64 - 1]], dtype=np.uint64), "out of range"),
    "F repeated vertex": (SQUARE_V, np.array([[0, 1, 1], [0, 2, 3]]), "face 0 .* repeats a vertex"),
    "NaN coordinate": (np.array([[0, 0, 0], [1, 0, 0], [1, 1, np.nan], [0, 1, 0]]), SQUARE_F,
                       r"V\[2\] is \(1, 1, nan\), not a finite point"),
    "inf coordinate": (np.array([[0, 0, 0], [1, 0, np.inf], [1, 1, 0], [0, 1, 0]]), SQUARE_F,
                       r"V\[1\] is \(1, 0, inf\), not a finite point"),
    "isolated vertex": (np.vstack([SQUARE_V, [[5.0, 5, 5]]]), SQUARE_F, "vertex 4 is isolated"),
    "zero-area face": (np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0]], dtype=np.float64),
                       np.array([[0, 1, 2], [0, 2, 3]]), "face 0 .* has zero area"),
    "non-manifold edge": (np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1]], dtype=np.float64),
                          np.array([[0, 1, 2], [1, 0, 3], [0, 1, 4]]), "face 2 .* non-manifold"),
    "inconsistent orientation": (SQUARE_V, np.array([[0, 1, 2], [0, 3, 2]]), "face 1 .* non-manifold"),
    "duplicated face": (SQUARE_V, np.array([[0, 1, 2], [0, 2, 3], [0, 1, 2]]), "face 2 .* non-manifold"),
    "non-manifold vertex": (np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0]], dtype=np.float64),
                            np.array([[0, 1, 2], [0, 3, 4]]), "(vertex 0 is non-manifold|face 1 .* non-manifold)"),
    "no faces": (SQUARE_V, np.zeros((0, 3), dtype=np.int64), "vertex 0 is isolated"),
}


@pytest.mark.parametrize("function", sorted(ALL_FUNCTIONS))
@pytest.mark.parametrize("case", sorted(BAD_MESHES))
def test_bad_mesh_raises_value_error(case, function):
    V, F, message = BAD_MESHES[case]
    with pytest.raises(ValueError, match=message):
        ALL_FUNCTIONS[function](V, F)


def test_valid_small_meshes_work():
    for V, F in ((SQUARE_V, SQUARE_F), (TETRA_V, TETRA_F), (SQUARE_V, SQUARE_F.astype(np.uint32))):
        for name, function in ALL_FUNCTIONS.items():
            if name in ("HeatDiffusion spectral", "heat_kernel_signature") and len(V) <= 3:
                continue
            result = function(V, F)
            assert result is not None, name


def test_empty_mesh():
    V, F = np.zeros((0, 3)), np.zeros((0, 3), dtype=np.int64)
    assert hd.normal_signature(V, F).shape == (0,)
    with pytest.raises(ValueError, match="the mesh is empty"):
        hd.HeatDiffusion(V, F)


BAD_PARAMETERS = {
    "sigma 0": (lambda V, F: hd.HeatDiffusion(V, F, sigma=0.0), "sigma must be positive"),
    "sigma NaN": (lambda V, F: hd.HeatDiffusion(V, F, sigma=float("nan")), "sigma must be positive"),
    "time 0": (lambda V, F: hd.HeatDiffusion(V, F, time=0.0), "time must be positive and finite"),
    "time inf": (lambda V, F: hd.HeatDiffusion(V, F, time=float("inf")), "time must be positive and finite"),
    "kernel": (lambda V, F: hd.HeatDiffusion(V, F, kernel="magic"), "kernel must be 'local', 'spectral' or None"),
    # The package's own checks and messages.
    "m 0": (lambda V, F: hd.HeatDiffusion(V, F, m=0), "Edge_weighted_heat_kernel: number_of_eigenpairs must be positive"),
    "m negative": (lambda V, F: hd.HeatDiffusion(V, F, m=-3), "number_of_eigenpairs must be positive"),
    "hks m 0": (lambda V, F: hd.heat_kernel_signature(V, F, m=0), "number_of_eigenpairs must be positive"),
    "denoise m 0": (lambda V, F: hd.denoise(V, F, kernel="spectral", m=0), "denoise_mesh: number_of_eigenpairs must be positive"),
    "coarse 2": (lambda V, F: hd.HeatDiffusion(V, F, coarse=2),
                 r"Edge_weighted_heat_kernel: coarse_vertex_count must be at least 4 \(or 0 for none\)"),
    "coarse negative": (lambda V, F: hd.HeatDiffusion(V, F, coarse=-1), "coarse .* must not be negative"),
    "local with m": (lambda V, F: hd.HeatDiffusion(V, F, kernel="local", m=10), "kernel='local' computes none"),
    "spectral with kernel_tolerance": (lambda V, F: hd.HeatDiffusion(V, F, kernel="spectral", kernel_tolerance=1e-4),
                                       "kernel_tolerance concerns the local kernel"),
    "m with kernel_tolerance": (lambda V, F: hd.multiscale_features(V, F, m=10, kernel_tolerance=1e-4),
                                "kernel_tolerance concerns the local kernel"),
    "kernel_tolerance 0": (lambda V, F: hd.HeatDiffusion(V, F, kernel_tolerance=0.0),
                           "local_kernel_tolerance must be in"),
    "kernel_tolerance text": (lambda V, F: hd.decompose(V, F, kernel_tolerance="small"), "kernel_tolerance"),
    "feature threshold": (lambda V, F: hd.multiscale_features(V, F, feature_threshold=2.0), "threshold"),
    "steps per level": (lambda V, F: hd.decompose(V, F, steps_per_level=0), "steps_per_level"),
    "steps per level 2.5": (lambda V, F: hd.filter_shape(V, F, [1.0], steps_per_level=2.5), "steps_per_level"),
    "weights NaN": (lambda V, F: hd.filter_shape(V, F, [1.0, float("nan")]), "weight 1 is nan"),
    "anchor weight": (lambda V, F: hd.reconstruct(V, F, np.zeros(len(V)), anchor_weight=-1.0), "anchor_weight"),
    "ns length": (lambda V, F: hd.reconstruct(V, F, np.zeros(3)), r"ns must have shape \(4,\)"),
    "ns NaN": (lambda V, F: hd.reconstruct(V, F, np.full(len(V), np.nan)), "not"),
    "denoise method": (lambda V, F: hd.denoise(V, F, method="magic"), "method must be"),
    "denoise iterations": (lambda V, F: hd.denoise(V, F, number_of_iterations=-1), "number_of_iterations"),
    "hks time": (lambda V, F: hd.heat_kernel_signature(V, F, time=-1.0, m=3), "time must be positive"),
    "subdivision": (lambda V, F: hd.loop_subdivision(V, F, -1), "iterations must not be negative"),
}


@pytest.mark.parametrize("case", sorted(BAD_PARAMETERS))
def test_bad_parameters_raise_value_error(case):
    function, message = BAD_PARAMETERS[case]
    with pytest.raises(ValueError, match=message):
        function(TETRA_V, TETRA_F.astype(np.int64))


def test_bad_fields_and_steps():
    d = hd.HeatDiffusion(TETRA_V, TETRA_F)
    good = np.arange(4, dtype=np.float64)
    cases = [
        (lambda: d.diffuse(np.zeros(5)), r"field must have shape \(4,\)"),
        (lambda: d.diffuse(np.zeros((4, 1))), r"field must have shape \(4,\)"),
        (lambda: d.diffuse(np.zeros(4, dtype=bool)), "field must be an array of numbers, not of bool"),
        (lambda: d.diffuse(["0", "1", "2", "3"]), r"field must be an array of numbers, not of <U1 \(list\)"),
        (lambda: d.diffuse(np.array([0, np.nan, 0, 0])), "field value at vertex 1 is nan, not a finite number"),
        (lambda: d.diffuse(good, -1), "steps must not be negative"),
        (lambda: d.diffuse(good, [1, -2]), "steps must not be negative"),
        (lambda: d.diffuse(good, 1.5), "steps must be a whole number"),
        (lambda: d.diffuse(good, True), "steps must be a whole number"),
        (lambda: d.diffuse(good, "3"), "steps must be a whole number"),
        (lambda: d.features(np.array([0, np.inf, 0, 0])), "field value at vertex 1 is inf, not a finite number"),
        (lambda: d.decompose(np.array([0, np.inf, 0, 0]), 2), "not a finite number"),
        (lambda: hd.synthesize(np.zeros((2, 4)), np.zeros(4), [1.0]), "1 weights for 2 detail bands"),
        (lambda: hd.synthesize(np.zeros((2, 3)), np.zeros(4), [1.0, 1.0]), r"bands must have shape \(L, 4\)"),
        (lambda: hd.synthesize(np.full((2, 4), np.nan), np.zeros(4), [1.0, 1.0]), "must be finite"),
    ]
    for function, message in cases:
        with pytest.raises(ValueError, match=message):
            function()


def test_field_errors_name_the_row_on_large_meshes(mesh):
    # Meshes of 100000 vertices or more are renumbered inside the package (along a
    # Hilbert curve); a message about a field value names the Python function and the
    # caller's row all the same, not the package's C++ function or its own index.
    V, F, _ = mesh("fandisk.off")
    V, F = hd.loop_subdivision(V, F, 2)
    assert len(V) >= 100000
    d = hd.HeatDiffusion(V, F)
    bad = d.normal_signature()
    bad[12345] = np.nan
    # (the free functions name themselves, not the method they call)
    for name, function in (("HeatDiffusion.diffuse", lambda: d.diffuse(bad, 1)),
                           ("HeatDiffusion.features", lambda: d.features(bad, [0])),
                           ("HeatDiffusion.decompose", lambda: d.decompose(bad, 1)),
                           ("decompose", lambda: hd.decompose(V, F, bad, levels=1)),
                           ("multiscale_features", lambda: hd.multiscale_features(V, F, bad, steps=[0]))):
        with pytest.raises(ValueError) as error:
            function()
        message = str(error.value)
        assert message.startswith("cgal_heat_diffusion." + name + ": field value at vertex 12345 is nan, not a finite"
                                  " number"), message
        assert "vertex_index" not in message and "CGAL::" not in message, message


HOSTILE_DIR = os.environ.get("HEAT_DIFFUSION_HOSTILE_DATA_DIR", "")
# (the point files, points_*, go through the point-set functions: test_point_sets.py)
HOSTILE_FILES = sorted(f for f in os.listdir(HOSTILE_DIR) if not f.startswith("points_")) \
    if os.path.isdir(HOSTILE_DIR) else []


def test_hostile_corpus_is_there():
    assert HOSTILE_DIR, "HEAT_DIFFUSION_HOSTILE_DATA_DIR is not set: run the tests through CTest"
    assert len(HOSTILE_FILES) >= 30, HOSTILE_FILES


class Unreadable(Exception):
    pass


def read_off(path):
    """V and F of an OFF file, as arrays, for what the arrays can hold. meshio is not
    used for OFF: on hostile OFF files it loops forever (a header alone) or calls
    sys.exit(). Integer-valued indices give an int64 F, others a float64 F (which the
    binding must reject), faces all of one size k an (m, k) F."""
    with open(path, "rb") as f:
        data = f.read()
    lines = []
    for raw in data.decode("ascii", errors="strict").splitlines():
        line = raw.split("#", 1)[0].split()
        if line:
            lines.append(line)
    if not lines or not lines[0][0].endswith("OFF"):
        raise Unreadable("no OFF header")
    header = lines[0][1:] if len(lines[0]) > 1 else (lines[1] if len(lines) > 1 else [])
    body = lines[1:] if len(lines[0]) > 1 else lines[2:]
    if len(header) < 2:
        raise Unreadable("no vertex and face counts")
    try:
        n, m = int(header[0]), int(header[1])
    except ValueError:
        raise Unreadable(f"counts {header[:2]} are not integers")
    if n < 0 or m < 0 or n + m > len(body):
        raise Unreadable(f"counts {n}, {m} for {len(body)} lines")
    try:
        V = np.array([[float(x) for x in line[:3]] for line in body[:n]], dtype=np.float64).reshape(n, 3)
        faces = [[float(x) for x in line] for line in body[n:n + m]]
    except ValueError as e:
        raise Unreadable(str(e))
    polygons = []
    for face in faces:
        k = face[0]
        if k != int(k) or k < 0 or len(face) < 1 + int(k):
            raise Unreadable(f"face {face}: bad vertex count")
        polygons.append(face[1:1 + int(k)])
    if len({len(p) for p in polygons}) > 1:
        raise Unreadable("faces of different sizes")
    F = np.array(polygons, dtype=np.float64).reshape(m, len(polygons[0]) if polygons else 3)
    if np.all(np.isfinite(F)) and np.all(F == np.round(F)) and np.all(np.abs(F) < 2**62):
        F = F.astype(np.int64)
    return np.ascontiguousarray(V), np.ascontiguousarray(F)


def read_with_meshio(path):
    """V and F as meshio reads them, in a child process: meshio may loop or exit on
    hostile files."""
    script = (
        "import sys, meshio, numpy as np\n"
        "m = meshio.read(sys.argv[1])\n"
        "tri = [c.data for c in m.cells if c.type == 'triangle']\n"
        "F = np.concatenate(tri) if tri else (m.cells[0].data if m.cells else np.zeros((0, 3), np.int64))\n"
        "np.savez(sys.argv[2], V=np.asarray(m.points, dtype=np.float64), F=F)\n")
    with tempfile.TemporaryDirectory() as work:
        out = os.path.join(work, "mesh.npz")
        try:
            result = subprocess.run([sys.executable, "-c", script, path, out], capture_output=True, text=True,
                                    timeout=30)
        except subprocess.TimeoutExpired:
            raise Unreadable("meshio did not finish in 30 s")
        if result.returncode != 0:
            raise Unreadable("meshio: " + (result.stderr.strip().splitlines() or ["failed"])[-1])
        arrays = np.load(out)
        return np.ascontiguousarray(arrays["V"]), np.ascontiguousarray(arrays["F"])


@pytest.mark.parametrize("name", HOSTILE_FILES)
def test_hostile_file(name):
    path = os.path.join(HOSTILE_DIR, name)
    try:
        V, F = read_off(path) if name.endswith(".off") else read_with_meshio(path)
    except (Unreadable, UnicodeDecodeError) as e:  # no arrays to give the binding
        pytest.skip(f"{name} cannot be read into arrays: {e}")
    # The one-pass Surface_mesh is add_face()'s, or the file is left to add_face() (test_mesh_construction).
    try:
        applied, difference = hd._compare_mesh_constructions(V, F)
        assert difference is None, f"{name}: the one-pass mesh differs: {difference}"
    except ValueError:
        pass  # V or F that the binding refuses before building a mesh
    for function in ("normal_signature", "HeatDiffusion", "multiscale_features", "denoise"):
        try:
            result = ALL_FUNCTIONS[function](V, F)
        except ValueError as e:
            assert str(e), f"{name}: {function}: ValueError without a message"
            continue
        if isinstance(result, np.ndarray):
            assert np.all(np.isfinite(result)), f"{name}: {function}: non-finite result"
        if isinstance(result, hd.HeatDiffusion):
            f = result.diffuse(result.normal_signature(), [0, 5])
            assert np.all(np.isfinite(f))
            assert abs(f[1].sum() - f[0].sum()) <= 1e-12 * max(1.0, np.abs(f[0]).sum())


def test_free_functions_name_themselves_in_errors():
    # multiscale_features() and decompose() build a HeatDiffusion and call its method: the
    # binding's own errors carry the free function's name, not the class's or the
    # method's. (The package's errors carry "CGAL::Heat_diffusion:" wherever they come from.)
    V, F = TETRA_V, TETRA_F
    cases = [
        (lambda: hd.decompose(V, F, kernel=1), "decompose", "kernel"),
        (lambda: hd.decompose(V, F, m="many"), "decompose", "m must"),
        (lambda: hd.decompose(V[:, :2], F), "decompose", "V"),
        (lambda: hd.decompose(V, F, steps_per_level="5"), "decompose", "steps_per_level"),
        (lambda: hd.multiscale_features(V, F, kernel="fast"), "multiscale_features", "kernel"),
        (lambda: hd.multiscale_features(V, F, coarse=[4]), "multiscale_features", "coarse"),
        (lambda: hd.multiscale_features(V, F.astype(np.float64)), "multiscale_features", "F"),
        # the steps are checked before the diffusion is built (which would refuse sigma first)
        (lambda: hd.multiscale_features(V, F, steps=-1, sigma=-1.0), "multiscale_features", "steps"),
    ]
    for function, name, argument in cases:
        with pytest.raises(ValueError) as error:
            function()
        message = str(error.value)
        assert message.startswith("cgal_heat_diffusion." + name + ": ") and argument in message, message


def test_arguments_of_the_wrong_type():
    V, F = TETRA_V, TETRA_F
    cases = [
        (lambda: hd.HeatDiffusion(V, F, m="many"), "m must be a whole number or None"),
        (lambda: hd.HeatDiffusion(V, F, m=2.5), "m must be a whole number or None"),
        (lambda: hd.HeatDiffusion(V, F, coarse=[4]), "coarse must be a whole number or None"),
        (lambda: hd.HeatDiffusion(V, F, kernel=1), "kernel must be 'local', 'spectral' or None"),
        (lambda: hd.filter_shape(V, F, "13"), "weights must be a sequence of numbers"),
        (lambda: hd.filter_shape(V, F, []), r"weights must have 1 to 1000 values \(one per detail band\), not 0"),
        (lambda: hd.decompose(V, F, levels=0), "levels must be from 1 to 1000, not 0"),
        (lambda: hd.decompose(V, F, levels=-1), "levels must be from 1 to 1000, not -1"),
        # refused before the bands (levels x n doubles) are allocated
        (lambda: hd.decompose(V, F, levels=10**6), "levels must be from 1 to 1000, not 1000000"),
        (lambda: hd.decompose(V, F, levels=2.0), "levels must be a whole number, not float"),
        # checked before the diffusion is built (which would refuse sigma first)
        (lambda: hd.decompose(V, F, levels=0, sigma=-1.0), "levels must be from 1 to 1000, not 0"),
        (lambda: hd.synthesize(np.zeros((1, 4)), np.zeros(4), None), "weights must be a sequence of numbers"),
        (lambda: hd.denoise(V, F, number_of_iterations=1.5), "number_of_iterations must be a whole number"),
        (lambda: hd.denoise(V, F, normal_sigma="wide"), "normal_sigma must be a number or None"),
        (lambda: hd.filter_shape(V, F, [1.0], steps_per_level="5"), "steps_per_level must be a whole number or None"),
        (lambda: hd.filter_shape(V, F, [1.0], anchor_weight=[1.0]), "anchor_weight must be a number or None"),
        (lambda: hd.decompose(V, F, steps_per_level=True), "steps_per_level must be a whole number or None"),
        # numpy arrays of one or more dimensions have __index__ too: not a number
        (lambda: hd.HeatDiffusion(V, F, m=np.array([20])), "m must be a whole number or None"),
        (lambda: hd.HeatDiffusion(V, F, coarse=np.array([100])), "coarse must be a whole number or None"),
        (lambda: hd.decompose(V, F, steps_per_level=np.array([2])), "steps_per_level must be a whole number or None"),
        (lambda: hd.denoise(V, F, number_of_iterations=np.array([3])), "number_of_iterations must be a whole number"),
        (lambda: hd.denoise(V, F, normal_sigma=np.array([0.3])), "normal_sigma must be a number or None"),
        (lambda: hd.denoise(V, F, normal_sigma=True), "normal_sigma must be a number or None"),
        (lambda: hd.filter_shape(V, F, [1.0], anchor_weight=np.array([1.0])), "anchor_weight must be a number or None"),
        (lambda: hd.HeatDiffusion(V, F, m=10**30), "m is out of range"),
        (lambda: hd.denoise(V, F, number_of_iterations=2**32), "number_of_iterations must be from 0 to 4294967295, not 4294967296"),
        (lambda: hd.HeatDiffusion(V, F).diffuse(np.zeros(4), np.array([[1, 2]])), "steps must be a whole number"),
        (lambda: hd.HeatDiffusion(V, F).diffuse(np.zeros(4), 2**64), "steps is out of range"),
    ]
    for function, message in cases:
        with pytest.raises(ValueError, match=message):
            function()


def test_numbers_as_numpy_scalars():
    # numpy's float64 and integers are numbers, as Python's are.
    V, F = TETRA_V, TETRA_F
    np.testing.assert_array_equal(hd.denoise(V, F, normal_sigma=np.float64(0.3)), hd.denoise(V, F, normal_sigma=0.3))
    np.testing.assert_array_equal(hd.denoise(V, F, normal_sigma=np.int64(1)), hd.denoise(V, F, normal_sigma=1.0))
    np.testing.assert_array_equal(hd.filter_shape(V, F, [1.0], anchor_weight=np.int32(2)),
                                  hd.filter_shape(V, F, [1.0], anchor_weight=2.0))


def test_steps_as_numpy_arrays():
    # A 1-D array of steps is a list of steps; a 0-d array or a numpy integer, one step.
    d = hd.HeatDiffusion(TETRA_V, TETRA_F)
    field = np.arange(4, dtype=np.float64)
    as_list = d.diffuse(field, [0, 3])
    np.testing.assert_array_equal(d.diffuse(field, np.array([0, 3])), as_list)
    np.testing.assert_array_equal(d.diffuse(field, np.arange(0, 6, 3)), as_list)
    np.testing.assert_array_equal(d.diffuse(field, np.int64(3)), d.diffuse(field, 3))
    np.testing.assert_array_equal(d.diffuse(field, np.array(3)), d.diffuse(field, 3))
