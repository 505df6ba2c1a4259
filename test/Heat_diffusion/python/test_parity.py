# The front ends run what the library measures: every subcommand of the tool and every
# function of the module, with their defaults and with one non-default value of each
# option, give to the bit what the library gives when called with no named parameter
# or with just that one (the program parity_reference, built from
# test/Heat_diffusion/parity_reference.cpp, is the library so called). The module also
# takes what numpy users pass (float32, any integer type, Fortran order, views, lists)
# and gives the same results (its refusals of what is wrong: test_hostile_input.py).
import json
import os
import subprocess

import numpy as np
import pytest

import cgal_heat_diffusion as hd
from conftest import read_ply_vertices, read_points, run_tool, write_ply

# CAD with creases, an organic mesh, an open mesh with holes.
MESHES = ["fandisk.off", "elephant.off", "mech-holes-shark.off"]
SCALES = [0, 10, 40]  # the front ends' default steps (the library's defaults::feature_scales)
WEIGHTS = [1.0, 3.0, 3.0]  # defaults::enhancement_weights


def noisy(V, F, seed=5, level=0.3):
    """V moved along the area-weighted vertex normals by Gaussian noise of `level` mean edge
    lengths (as benchmark_denoising makes its inputs): the denoiser leaves a clean mesh as it is."""
    corners = V[F]
    face_normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    normals = np.zeros_like(V)
    for c in range(3):
        np.add.at(normals, F[:, c], face_normals)
    normals /= np.linalg.norm(normals, axis=1)[:, None]
    edges = np.concatenate([corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 1], corners[:, 0] - corners[:, 2]])
    mean_edge = np.mean(np.linalg.norm(edges, axis=1))
    return V + np.random.default_rng(seed).normal(0, level * mean_edge, len(V))[:, None] * normals


@pytest.fixture(scope="session")
def noisy_mesh(mesh, tmp_path_factory):
    """noisy_mesh(name) -> (V, F, path) of a noisy copy of one of CGAL's meshes, written exactly."""
    cache = {}
    def load(name):
        if name not in cache:
            V, F, _ = mesh(name)
            V2 = noisy(V, F)
            path = tmp_path_factory.mktemp("noisy") / (os.path.splitext(name)[0] + "_noisy.ply")
            write_ply(path, V2, F)
            cache[name] = (V2, F, str(path))
        return cache[name]
    return load


def input_of(command, name, mesh, noisy_mesh):
    """The mesh a command runs on: denoise on a noisy copy, the others on the mesh itself."""
    return noisy_mesh(name) if command == "denoise" else mesh(name)


@pytest.fixture(scope="session")
def reference_program():
    path = os.environ.get("HEAT_DIFFUSION_PARITY_REFERENCE")
    if not path:
        pytest.fail("HEAT_DIFFUSION_PARITY_REFERENCE is not set: run the tests through CTest (ctest -R test_python)")
    assert os.access(path, os.X_OK), f"{path} is not an executable"
    return path


def reference(program, command, path, tmp_path, parameter=None, value=None):
    """The library's result (parity_reference), as a flat array of doubles."""
    output = tmp_path / f"reference_{command}.bin"
    arguments = [program, command, path, str(output)] + ([parameter, value] if parameter else [])
    result = subprocess.run(arguments, capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, f"{arguments}: {result.stderr}"
    return np.fromfile(output, dtype="<f8")


def features_layout(scales):
    """[{'steps', 'convex', 'concave'}, ...] in the reference's layout."""
    out = []
    for scale in scales:
        out += [scale["steps"], len(scale["convex"]), *sorted(scale["convex"]),
                len(scale["concave"]), *sorted(scale["concave"])]
    return np.array(out, dtype=np.float64)


def points_of(ply):
    return np.column_stack([ply["x"], ply["y"], ply["z"]]).ravel()


def option_value(options, name, default):
    return options[options.index(name) + 1] if name in options else default


def tool_result(tool, command, path, tmp_path, options):
    """The tool's result for `command` with `options`, in the reference's layout."""
    run = lambda *a: run_tool(tool, command, path, *a, *options, "--quiet", cwd=tmp_path)
    if command == "ncc":
        run("-o", "ns.ply")
        return read_ply_vertices(tmp_path / "ns.ply")["ns"]
    if command == "diffuse":
        run("-o", "d")
        steps = option_value(options, "-k", ",".join(map(str, SCALES))).split(",")
        return np.concatenate([read_ply_vertices(tmp_path / f"d_k{k}.ply")["field"] for k in steps])
    if command == "features":
        summary = run("-o", "f", "--json")
        steps = option_value(options, "-k", ",".join(map(str, SCALES))).split(",")
        return features_layout([{"steps": int(k), **summary["features"][k]} for k in steps])
    if command == "hks":
        run("-o", "h.ply")
        ply = read_ply_vertices(tmp_path / "h.ply")
        return np.concatenate([ply["hks"], ply["maximum"]])
    if command == "decompose":
        run("-o", "p")
        levels = int(option_value(options, "--levels", "3"))
        files = [f"p_band{j}.ply" for j in range(1, levels + 1)] + ["p_residual.ply"]
        return np.concatenate([read_ply_vertices(tmp_path / f)["field"] for f in files])
    if command in ("enhance", "denoise"):
        run("-o", "out.ply")
        ply = read_ply_vertices(tmp_path / "out.ply")
        if command == "denoise" and "nx" in ply:  # a point set's, with its filtered normals
            return np.concatenate([points_of(ply), np.column_stack([ply["nx"], ply["ny"], ply["nz"]]).ravel()])
        return points_of(ply)
    raise AssertionError(command)


def same(front_end, library, what):
    front_end, library = np.asarray(front_end, dtype=np.float64).ravel(), np.asarray(library).ravel()
    assert front_end.shape == library.shape, f"{what}: shape {front_end.shape} against {library.shape}"
    different = np.flatnonzero(front_end != library)
    assert different.size == 0, \
        f"{what}: {different.size} values differ, first at {different[0]}: " \
        f"{front_end[different[0]]!r} against the library's {library[different[0]]!r}, " \
        f"largest difference {np.max(np.abs(front_end - library)):.3g}"


COMMANDS = ["ncc", "diffuse", "features", "hks", "decompose", "enhance", "denoise"]


@pytest.mark.parametrize("name", MESHES)
@pytest.mark.parametrize("command", COMMANDS)
def test_tool_defaults_are_the_library_defaults(name, command, mesh, noisy_mesh, tool, reference_program, tmp_path):
    _, _, path = input_of(command, name, mesh, noisy_mesh)
    same(tool_result(tool, command, path, tmp_path, []), reference(reference_program, command, path, tmp_path),
         f"heat_diffusion {command} {name}")


# One non-default value of each option: (command, tool options, library parameter, value).
TOOL_OPTIONS = [
    ("ncc", ["--normals", "pmp"], "vertex_normal_rule", "pmp"),
    ("diffuse", ["--sigma", "0.5"], "sigma", "0.5"),
    ("diffuse", ["--time", "2"], "time", "2"),
    ("diffuse", ["--kernel", "spectral"], "kernel_method", "spectral"),
    ("diffuse", ["--normalization", "columns"], "operator_normalization", "columns"),
    ("diffuse", ["--kernel-tolerance", "1e-4"], "local_kernel_tolerance", "1e-4"),
    ("features", ["--kernel-tolerance", "1e-4"], "local_kernel_tolerance", "1e-4"),
    ("diffuse", ["-m", "60"], "number_of_eigenpairs", "60"),
    ("diffuse", ["--coarse", "3000"], "coarse_vertex_count", "3000"),
    ("diffuse", ["--scale-invariant"], "scale_invariant_kernel", "true"),
    ("diffuse", ["-k", "3,7"], "steps", "3,7"),
    ("features", ["--c", "0.5"], "feature_threshold", "0.5"),
    ("features", ["--sigma", "1"], "sigma", "1"),
    ("hks", ["-t", "50"], "time", "50"),
    ("hks", ["--sigma", "1"], "sigma", "1"),
    ("hks", ["-m", "60"], "number_of_eigenpairs", "60"),
    ("hks", ["--coarse", "3000"], "coarse_vertex_count", "3000"),
    ("hks", ["--scale-invariant"], "scale_invariant_kernel", "true"),
    ("hks", ["--c", "0.5"], "feature_threshold", "0.5"),
    ("decompose", ["--levels", "2"], "levels", "2"),
    ("decompose", ["-k", "3"], "steps_per_level", "3"),
    ("decompose", ["--sigma", "0.5"], "sigma", "0.5"),
    ("enhance", ["--weights", "0,0,1"], "weights", "0,0,1"),
    ("enhance", ["-k", "3"], "steps_per_level", "3"),
    ("enhance", ["--anchor-weight", "0.1"], "anchor_weight", "0.1"),
    ("enhance", ["--sigma", "0.5"], "sigma", "0.5"),
    ("denoise", ["--method", "signature_diffusion"], "denoising_method", "signature_diffusion"),
    ("denoise", ["--iterations", "3"], "number_of_iterations", "3"),
    ("denoise", ["-k", "2"], "number_of_steps", "2"),
    ("denoise", ["--normal-sigma", "0.3"], "normal_sigma", "0.3"),
    ("denoise", ["--displacement-limit", "2"], "displacement_limit", "2"),
    ("denoise", ["--method", "signature_diffusion", "--sigma", "0.5"], "signature:sigma", "0.5"),
    ("denoise", ["--method", "signature_diffusion", "--time", "2"], "signature:time", "2"),
    ("denoise", ["--method", "signature_diffusion", "--anchor-weight", "1"], "signature:anchor_weight", "1"),
    ("denoise", ["--method", "signature_diffusion", "--kernel", "spectral"], "signature:kernel_method", "spectral"),
    ("denoise", ["--method", "signature_diffusion", "--normalization", "columns"],
     "signature:operator_normalization", "columns"),
    ("denoise", ["--method", "signature_diffusion", "--kernel-tolerance", "1e-4"],
     "signature:local_kernel_tolerance", "1e-4"),
    ("denoise", ["--method", "signature_diffusion", "-m", "60"], "signature:number_of_eigenpairs", "60"),
]


@pytest.mark.parametrize("command, options, parameter, value", TOOL_OPTIONS,
                         ids=[f"{c} {' '.join(o)}" for c, o, _, _ in TOOL_OPTIONS])
def test_tool_option_is_the_library_parameter(command, options, parameter, value, mesh, noisy_mesh, tool,
                                              reference_program, tmp_path):
    _, _, path = input_of(command, "fandisk.off", mesh, noisy_mesh)
    same(tool_result(tool, command, path, tmp_path, options),
         reference(reference_program, command, path, tmp_path, parameter, value),
         f"heat_diffusion {command} {' '.join(options)}")


def test_tool_json_reports_what_the_library_chose(mesh, noisy_mesh, tool, tmp_path):
    """The summary names the parameters given and reports the denoiser's own choices."""
    _, _, path = noisy_mesh("fandisk.off")
    summary = run_tool(tool, "denoise", path, "-o", "n.off", "--json", "--quiet", cwd=tmp_path)
    assert summary["given"] == []
    assert summary["method"] == "normal_filtering"
    chosen = summary["denoiser"]
    # fandisk is piecewise flat; the estimate reads the noise of 0.3 mean edge length
    assert chosen["stage"] == "piecewise_flat"
    assert 0.2 < chosen["noise_level_in_mean_edge_lengths"] < 0.4 and chosen["iterations"] >= 1
    summary = run_tool(tool, "denoise", path, "-o", "n.off", "--json", "--quiet", "--displacement-limit", "2",
                       cwd=tmp_path)
    assert summary["given"] == ["displacement_limit"] and summary["displacement_limit"] == 2
    summary = run_tool(tool, "diffuse", mesh("fandisk.off")[2], "-o", "d", "--json", "--quiet", "--no-baseline",
                       "-m", "60", cwd=tmp_path)
    assert summary["given"] == ["number_of_eigenpairs"]
    assert summary["kernel"] == "spectral" and summary["kernel_automatic"] and summary["eigenpairs"] == 60


# The module: each function with its defaults, on the three meshes.
def module_result(command, V, F, **keywords):
    if command == "ncc":
        return hd.normal_signature(V, F)
    if command == "coordinates":
        return hd.normal_controlled_coordinates(V, F)
    if command == "diffuse":
        diffusion = hd.HeatDiffusion(V, F, **keywords)
        return diffusion.diffuse(diffusion.normal_signature(), SCALES)
    if command == "features":
        return features_layout(hd.multiscale_features(V, F, **keywords))
    if command == "hks":
        return hd.heat_kernel_signature(V, F, **keywords)
    if command == "decompose":
        bands, residual = hd.decompose(V, F, **keywords)
        return np.concatenate([bands.ravel(), residual])
    if command == "enhance":
        return hd.filter_shape(V, F, keywords.pop("weights", WEIGHTS), **keywords)
    if command == "denoise":
        return hd.denoise(V, F, **keywords)
    if command == "reconstruct":
        return hd.reconstruct(V, F, hd.normal_signature(V, F), **keywords)
    raise AssertionError(command)


def library_result(program, command, path, tmp_path, parameter=None, value=None):
    values = reference(program, command, path, tmp_path, parameter, value)
    if command == "hks":  # the module returns the signature, not its maxima
        values = values[:len(values) // 2]
    return values


MODULE_COMMANDS = ["ncc", "coordinates", "diffuse", "features", "hks", "decompose", "enhance", "denoise",
                   "reconstruct"]


@pytest.mark.parametrize("name", MESHES)
@pytest.mark.parametrize("command", MODULE_COMMANDS)
def test_module_defaults_are_the_library_defaults(name, command, mesh, noisy_mesh, reference_program, tmp_path):
    V, F, path = input_of(command, name, mesh, noisy_mesh)
    same(module_result(command, V, F), library_result(reference_program, command, path, tmp_path),
         f"cgal_heat_diffusion {command} {name}")


def test_module_methods_are_the_library_defaults(mesh, reference_program, tmp_path):
    """HeatDiffusion's methods with their defaults: features(), decompose(), normal_signature()."""
    V, F, path = mesh("fandisk.off")
    diffusion = hd.HeatDiffusion(V, F)
    same(diffusion.normal_signature(), library_result(reference_program, "ncc", path, tmp_path), "normal_signature")
    same(features_layout(diffusion.features()), library_result(reference_program, "features", path, tmp_path),
         "HeatDiffusion.features")
    bands, residual = diffusion.decompose()
    same(np.concatenate([bands.ravel(), residual]), library_result(reference_program, "decompose", path, tmp_path),
         "HeatDiffusion.decompose")
    # diffuse() with no steps: one step (anisotropic_heat_diffusion()'s number_of_steps)
    same(diffusion.diffuse(diffusion.normal_signature()),
         library_result(reference_program, "diffuse", path, tmp_path, "steps", "1"), "HeatDiffusion.diffuse")


# One non-default value of each keyword: (function, keywords, library parameter, value).
MODULE_KEYWORDS = [
    ("diffuse", {"sigma": 0.5}, "sigma", "0.5"),
    ("diffuse", {"time": 2}, "time", "2"),
    ("diffuse", {"kernel": "spectral"}, "kernel_method", "spectral"),
    ("diffuse", {"normalization": "columns"}, "operator_normalization", "columns"),
    ("diffuse", {"m": 60}, "number_of_eigenpairs", "60"),
    ("diffuse", {"coarse": 3000}, "coarse_vertex_count", "3000"),
    ("diffuse", {"scale_invariant": True}, "scale_invariant_kernel", "true"),
    ("diffuse", {"kernel_tolerance": 1e-4}, "local_kernel_tolerance", "1e-4"),
    ("features", {"kernel_tolerance": 1e-4}, "local_kernel_tolerance", "1e-4"),
    ("decompose", {"kernel_tolerance": 1e-4}, "local_kernel_tolerance", "1e-4"),
    ("enhance", {"kernel_tolerance": 1e-4}, "local_kernel_tolerance", "1e-4"),
    ("features", {"feature_threshold": 0.5}, "feature_threshold", "0.5"),
    ("features", {"sigma": 1.0}, "sigma", "1"),
    ("hks", {"time": 50.0}, "time", "50"),
    ("hks", {"sigma": 1.0}, "sigma", "1"),
    ("hks", {"m": 60}, "number_of_eigenpairs", "60"),
    ("hks", {"coarse": 3000}, "coarse_vertex_count", "3000"),
    ("hks", {"scale_invariant": True}, "scale_invariant_kernel", "true"),
    ("decompose", {"levels": 2}, "levels", "2"),
    ("decompose", {"steps_per_level": 3}, "steps_per_level", "3"),
    ("decompose", {"sigma": 0.5}, "sigma", "0.5"),
    ("enhance", {"weights": [0, 0, 1]}, "weights", "0,0,1"),
    ("enhance", {"steps_per_level": 3}, "steps_per_level", "3"),
    ("enhance", {"anchor_weight": 0.1}, "anchor_weight", "0.1"),
    ("enhance", {"sigma": 0.5}, "sigma", "0.5"),
    ("denoise", {"method": "signature_diffusion"}, "denoising_method", "signature_diffusion"),
    ("denoise", {"number_of_iterations": 3}, "number_of_iterations", "3"),
    ("denoise", {"number_of_steps": 2}, "number_of_steps", "2"),
    ("denoise", {"normal_sigma": 0.3}, "normal_sigma", "0.3"),
    ("denoise", {"displacement_limit": 2}, "displacement_limit", "2"),
    ("denoise", {"method": "signature_diffusion", "sigma": 0.5}, "signature:sigma", "0.5"),
    ("denoise", {"method": "signature_diffusion", "time": 2}, "signature:time", "2"),
    ("denoise", {"method": "signature_diffusion", "anchor_weight": 1}, "signature:anchor_weight", "1"),
    ("denoise", {"method": "signature_diffusion", "kernel": "spectral"}, "signature:kernel_method", "spectral"),
    ("denoise", {"method": "signature_diffusion", "m": 60}, "signature:number_of_eigenpairs", "60"),
    ("reconstruct", {"anchor_weight": 0.5}, "anchor_weight", "0.5"),
]


@pytest.mark.parametrize("command, keywords, parameter, value", MODULE_KEYWORDS,
                         ids=[f"{c} {k}" for c, k, _, _ in MODULE_KEYWORDS])
def test_module_keyword_is_the_library_parameter(command, keywords, parameter, value, mesh, noisy_mesh,
                                                 reference_program, tmp_path):
    V, F, path = input_of(command, "fandisk.off", mesh, noisy_mesh)
    same(module_result(command, V, F, **dict(keywords)),
         library_result(reference_program, command, path, tmp_path, parameter, value),
         f"cgal_heat_diffusion {command} {keywords}")


# What numpy users pass: the same mesh in other types and layouts.
def variants(V, F):
    yield "float64 C, int64", V, F
    yield "Fortran order", np.asfortranarray(V), np.asfortranarray(F)
    yield "int32 faces", V, F.astype(np.int32)
    yield "uint32 faces", V, F.astype(np.uint32)
    yield "uint16 faces", V, F.astype(np.uint16)
    yield "big-endian", V.astype(">f8"), F.astype(">i8")
    wide = np.zeros((len(V), 4))
    wide[:, 1:] = V
    faces = np.zeros((len(F), 4), dtype=np.int64)
    faces[:, 1:] = F
    yield "slices", wide[:, 1:], faces[:, 1:]
    yield "every other row of a view", np.repeat(V, 2, axis=0)[::2], F[::1]
    yield "transposed", V.T.copy().T, F.T.copy().T
    yield "lists", V.tolist(), F.tolist()
    yield "tuples", tuple(map(tuple, V)), tuple(map(tuple, F))


def test_module_takes_what_numpy_users_pass(noisy_mesh):
    V, F, _ = noisy_mesh("fandisk.off")
    assert len(V) < 65536
    ns = hd.normal_signature(V, F)
    denoised = hd.denoise(V, F)
    for what, V2, F2 in variants(V, F):
        same(hd.normal_signature(V2, F2), ns, what)
        same(hd.HeatDiffusion(V2, F2).normal_signature(), ns, what)
    for what, V2, F2 in list(variants(V, F))[1:3] + list(variants(V, F))[6:7]:
        same(hd.denoise(V2, F2), denoised, what)
    # float32 coordinates (what many PLY readers give): the mesh of those coordinates
    V32 = V.astype(np.float32)
    same(hd.normal_signature(V32, F), hd.normal_signature(V32.astype(np.float64), F), "float32")
    same(hd.denoise(V32, F), hd.denoise(V32.astype(np.float64), F), "float32")
    # integer coordinates are numbers too
    tetrahedron_V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]])
    tetrahedron_F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    same(hd.normal_signature(tetrahedron_V, tetrahedron_F),
         hd.normal_signature(tetrahedron_V.astype(np.float64), tetrahedron_F), "int64 coordinates")
    # fields and normals as float32 and lists
    diffusion = hd.HeatDiffusion(V, F)
    same(diffusion.diffuse(ns.astype(np.float32), 10), diffusion.diffuse(ns.astype(np.float32).astype(np.float64), 10),
         "float32 field")
    same(diffusion.diffuse(ns.tolist(), 10), diffusion.diffuse(ns, 10), "field as a list")
    corners = V[F]
    face_normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    normals = np.zeros_like(V)
    for c in range(3):
        np.add.at(normals, F[:, c], face_normals)
    same(hd.reconstruct(V, F, ns, normals=np.asfortranarray(normals)), hd.reconstruct(V, F, ns, normals=normals),
         "Fortran-order normals")
    # scalars of numpy types
    same(hd.HeatDiffusion(V, F, sigma=np.float32(0.5)).diffuse(ns, 10),
         hd.HeatDiffusion(V, F, sigma=float(np.float32(0.5))).diffuse(ns, 10), "numpy float32 sigma")
    # the caller's arrays are not modified
    V_copy, F_copy = np.array(V), np.array(F)
    hd.denoise(V, F)
    assert np.array_equal(V, V_copy) and np.array_equal(F, F_copy)


# Point sets: the tool on point files and the module on P (and N) give what the library's
# point-set classes give on the file read with CGAL::IO::read_point_set().
POINT_FILES = ["kitten.xyz", "oni.pwn", "half.xyz"]  # normals given (kitten, oni) and estimated (half)
POINT_COMMANDS = ["points_ncc", "points_diffuse", "points_features", "points_decompose", "points_enhance",
                  "points_denoise"]


@pytest.mark.parametrize("name", POINT_FILES)
@pytest.mark.parametrize("command", POINT_COMMANDS)
def test_tool_on_points_is_the_library(name, command, point_data_dir, tool, reference_program, tmp_path):
    _, _, path = read_points(point_data_dir, name)
    same(tool_result(tool, command[len("points_"):], path, tmp_path, []),
         reference(reference_program, command, path, tmp_path), f"heat_diffusion {command} {name}")


POINT_TOOL_OPTIONS = [
    ("points_ncc", ["--neighbors", "12"], "k", "12"),
    ("points_ncc", ["--neighbor-radius", "0.03"], "neighbor_radius", "0.03"),
    ("points_diffuse", ["--sigma", "0.5"], "sigma", "0.5"),
    ("points_diffuse", ["--time", "2"], "time", "2"),
    ("points_diffuse", ["--normalization", "columns"], "operator_normalization", "columns"),
    ("points_diffuse", ["--kernel-tolerance", "1e-4"], "local_kernel_tolerance", "1e-4"),
    ("points_diffuse", ["-k", "3,7"], "steps", "3,7"),
    ("points_features", ["--c", "0.5"], "feature_threshold", "0.5"),
    ("points_features", ["--neighbors", "12"], "k", "12"),
    ("points_diffuse", ["--kernel", "spectral"], "kernel_method", "spectral"),
    ("points_diffuse", ["-m", "40"], "number_of_eigenpairs", "40"),
    ("points_features", ["--scale-invariant"], "scale_invariant_kernel", "true"),
    ("points_decompose", ["--levels", "2"], "levels", "2"),
    ("points_decompose", ["-k", "3"], "steps_per_level", "3"),
    ("points_decompose", ["--sigma", "0.5"], "sigma", "0.5"),
    ("points_enhance", ["--weights", "0,0,1"], "weights", "0,0,1"),
    ("points_enhance", ["--anchor-weight", "0.1"], "anchor_weight", "0.1"),
    ("points_enhance", ["-k", "3"], "steps_per_level", "3"),
    ("points_enhance", ["--normalization", "columns"], "operator_normalization", "columns"),
    ("points_denoise", ["--neighbors", "12"], "k", "12"),
    ("points_denoise", ["--neighbor-radius", "0.03"], "neighbor_radius", "0.03"),
    ("points_denoise", ["--iterations", "3"], "number_of_iterations", "3"),
    ("points_denoise", ["-k", "2"], "number_of_steps", "2"),
    ("points_denoise", ["--normal-sigma", "0.3"], "normal_sigma", "0.3"),
    ("points_denoise", ["--displacement-limit", "0.5"], "displacement_limit", "0.5"),
]


@pytest.mark.parametrize("command, options, parameter, value", POINT_TOOL_OPTIONS,
                         ids=[f"{c} {' '.join(o)}" for c, o, _, _ in POINT_TOOL_OPTIONS])
def test_tool_option_on_points_is_the_library_parameter(command, options, parameter, value, point_data_dir, tool,
                                                        reference_program, tmp_path):
    _, _, path = read_points(point_data_dir, "kitten.xyz")
    same(tool_result(tool, command[len("points_"):], path, tmp_path, options),
         reference(reference_program, command, path, tmp_path, parameter, value),
         f"heat_diffusion {command} {' '.join(options)}")


def point_module_result(command, P, N, **keywords):
    if command == "points_ncc":
        return hd.point_set_normal_signature(P, N, **keywords)
    if command == "points_coordinates":
        return np.concatenate([a.ravel() for a in hd.point_set_normal_controlled_coordinates(P, N, **keywords)])
    if command == "points_diffuse":
        diffusion = hd.PointSetHeatDiffusion(P, N, **keywords)
        return diffusion.diffuse(diffusion.normal_signature(), SCALES)
    if command == "points_features":
        return features_layout(hd.point_set_multiscale_features(P, N, **keywords))
    if command == "points_decompose":
        bands, residual = hd.point_set_decompose(P, N, **keywords)
        return np.concatenate([bands.ravel(), residual])
    if command == "points_enhance":
        return hd.point_set_filter_shape(P, N, **{"weights": [1, 3, 3], **keywords})
    if command == "points_denoise":
        X, M = hd.point_set_denoise(P, N, **keywords)
        return np.concatenate([X.ravel()] + ([M.ravel()] if M is not None else []))
    raise AssertionError(command)


@pytest.mark.parametrize("name", POINT_FILES)
@pytest.mark.parametrize("command", POINT_COMMANDS + ["points_coordinates"])
def test_module_on_points_is_the_library(name, command, point_data_dir, reference_program, tmp_path):
    P, N, path = read_points(point_data_dir, name)
    same(point_module_result(command, P, N), reference(reference_program, command, path, tmp_path),
         f"cgal_heat_diffusion {command} {name}")


POINT_MODULE_KEYWORDS = [
    ("points_ncc", {"neighbors": 12}, "k", "12"),
    ("points_ncc", {"neighbor_radius": 0.03}, "neighbor_radius", "0.03"),
    ("points_diffuse", {"sigma": 0.5}, "sigma", "0.5"),
    ("points_diffuse", {"time": 2}, "time", "2"),
    ("points_diffuse", {"normalization": "columns"}, "operator_normalization", "columns"),
    ("points_features", {"feature_threshold": 0.5}, "feature_threshold", "0.5"),
    ("points_features", {"neighbors": 12}, "k", "12"),
    ("points_diffuse", {"kernel": "spectral"}, "kernel_method", "spectral"),
    ("points_diffuse", {"m": 40}, "number_of_eigenpairs", "40"),
    ("points_diffuse", {"kernel_tolerance": 1e-4}, "local_kernel_tolerance", "1e-4"),
    ("points_features", {"scale_invariant": True}, "scale_invariant_kernel", "true"),
    ("points_decompose", {"levels": 2}, "levels", "2"),
    ("points_decompose", {"steps_per_level": 3}, "steps_per_level", "3"),
    ("points_decompose", {"time": 2}, "time", "2"),
    ("points_enhance", {"weights": [0, 0, 1]}, "weights", "0,0,1"),
    ("points_enhance", {"anchor_weight": 0.1}, "anchor_weight", "0.1"),
    ("points_enhance", {"sigma": 0.5}, "sigma", "0.5"),
    ("points_denoise", {"neighbors": 12}, "k", "12"),
    ("points_denoise", {"neighbor_radius": 0.03}, "neighbor_radius", "0.03"),
    ("points_denoise", {"number_of_iterations": 3}, "number_of_iterations", "3"),
    ("points_denoise", {"number_of_steps": 2}, "number_of_steps", "2"),
    ("points_denoise", {"normal_sigma": 0.3}, "normal_sigma", "0.3"),
    ("points_denoise", {"displacement_limit": 0.5}, "displacement_limit", "0.5"),
]


@pytest.mark.parametrize("command, keywords, parameter, value", POINT_MODULE_KEYWORDS,
                         ids=[f"{c} {k}" for c, k, _, _ in POINT_MODULE_KEYWORDS])
def test_module_keyword_on_points_is_the_library_parameter(command, keywords, parameter, value, point_data_dir,
                                                           reference_program, tmp_path):
    P, N, path = read_points(point_data_dir, "kitten.xyz")
    same(point_module_result(command, P, N, **keywords),
         reference(reference_program, command, path, tmp_path, parameter, value),
         f"cgal_heat_diffusion {command} {keywords}")


def test_module_takes_points_as_numpy_users_pass(point_data_dir):
    P, N, _ = read_points(point_data_dir, "oni.pwn")
    ns = hd.point_set_normal_signature(P, N)
    wide = np.zeros((len(P), 7))
    wide[:, 1:4], wide[:, 4:] = P, N
    for what, P2, N2 in [("Fortran order", np.asfortranarray(P), np.asfortranarray(N)),
                         ("big-endian", P.astype(">f8"), N.astype(">f8")),
                         ("slices", wide[:, 1:4], wide[:, 4:]),
                         ("lists", P.tolist(), N.tolist())]:
        same(hd.point_set_normal_signature(P2, N2), ns, what)
    P32, N32 = P.astype(np.float32), N.astype(np.float32)
    same(hd.point_set_normal_signature(P32, N32),
         hd.point_set_normal_signature(P32.astype(np.float64), N32.astype(np.float64)), "float32")
    diffusion = hd.PointSetHeatDiffusion(P, N)
    same(diffusion.normal_signature(), ns, "PointSetHeatDiffusion.normal_signature")
    same(diffusion.diffuse(ns.tolist(), 10), diffusion.diffuse(ns, 10), "field as a list")
