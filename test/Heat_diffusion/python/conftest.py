# Fixtures of the Python tests: the module, the tool and the meshes, all named by
# environment variables that the CTest case test_python sets (test/Heat_diffusion/CMakeLists.txt).
# A variable that is missing fails the tests that need it: nothing is skipped silently.
import json
import os
import struct
import subprocess

import meshio
import numpy as np
import pytest


def _environment(name):
    value = os.environ.get(name)
    if not value:
        pytest.fail(f"{name} is not set: run the tests through CTest (ctest -R test_python)")
    return value


@pytest.fixture(scope="session")
def tool():
    path = _environment("HEAT_DIFFUSION_TOOL")
    assert os.access(path, os.X_OK), f"{path} is not an executable"
    return path


@pytest.fixture(scope="session")
def data_dir():
    return _environment("HEAT_DIFFUSION_DATA_DIR")


@pytest.fixture(scope="session")
def point_data_dir():
    """CGAL's point sets (data/points_3)."""
    return _environment("HEAT_DIFFUSION_POINT_DATA_DIR")


@pytest.fixture(scope="session")
def hostile_dir():
    return _environment("HEAT_DIFFUSION_HOSTILE_DATA_DIR")


def read_mesh(path):
    """V (n x 3 float64) and F (m x 3 int64) of a triangle mesh file, read with meshio."""
    mesh = meshio.read(path)
    V = np.ascontiguousarray(mesh.points, dtype=np.float64)
    F = np.ascontiguousarray(np.concatenate([c.data for c in mesh.cells if c.type == "triangle"]), dtype=np.int64)
    return V, F


_mesh_cache = {}


@pytest.fixture(scope="session")
def mesh(data_dir):
    """mesh(name) -> (V, F, path) of one of CGAL's meshes (read once per session)."""
    def load(name):
        if name not in _mesh_cache:
            path = os.path.join(data_dir, name)
            V, F = read_mesh(path)
            V.setflags(write=False)
            F.setflags(write=False)
            _mesh_cache[name] = (V, F, path)
        return _mesh_cache[name]
    return load


_PLY_TYPES = {"char": "b", "uchar": "B", "short": "h", "ushort": "H", "int": "i", "uint": "I",
              "float": "f", "double": "d", "int8": "b", "uint8": "B", "int16": "h", "uint16": "H",
              "int32": "i", "uint32": "I", "float32": "f", "float64": "d"}


def read_ply_vertices(path):
    """The vertex properties of a binary little-endian PLY (as the tool writes them): {name: array}."""
    with open(path, "rb") as f:
        header = []
        while True:
            line = f.readline().decode("ascii").strip()
            header.append(line)
            if line == "end_header":
                break
        assert "format binary_little_endian 1.0" in header, header
        count, properties, in_vertex = 0, [], False
        for line in header:
            words = line.split()
            if words[0] == "element":
                in_vertex = words[1] == "vertex"
                if in_vertex:
                    count = int(words[2])
            elif words[0] == "property" and in_vertex:
                assert words[1] != "list", "list property on vertices"
                properties.append((words[2], _PLY_TYPES[words[1]]))
        dtype = np.dtype([(name, "<" + code) for name, code in properties])
        records = np.frombuffer(f.read(count * dtype.itemsize), dtype=dtype, count=count)
    return {name: np.array(records[name]) for name, _ in properties}


def read_points(point_data_dir, name):
    """P, N (None without normals) and the path of one of CGAL's XYZ or PWN point files."""
    path = os.path.join(point_data_dir, name)
    values = np.loadtxt(path, ndmin=2)
    return values[:, :3], (values[:, 3:6] if values.shape[1] >= 6 else None), path


def run_tool(tool, *arguments, cwd):
    """Runs the tool (which must succeed) and returns its JSON summary when --json is given."""
    result = subprocess.run([tool, *arguments], cwd=cwd, capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, f"{arguments}: exit {result.returncode}: {result.stderr}"
    return json.loads(result.stdout) if "--json" in arguments else None


def write_off(path, V, F):
    """An OFF file with coordinates written exactly (17 significant digits)."""
    with open(path, "w") as f:
        f.write(f"OFF\n{len(V)} {len(F)} 0\n")
        np.savetxt(f, V, fmt="%.17g")
        np.savetxt(f, np.hstack([np.full((len(F), 1), 3), F]), fmt="%d")


def write_ply(path, V, F):
    """A binary PLY with double coordinates: exact, and fast to write and to read."""
    header = (f"ply\nformat binary_little_endian 1.0\nelement vertex {len(V)}\n"
              "property double x\nproperty double y\nproperty double z\n"
              f"element face {len(F)}\nproperty list uchar int vertex_indices\nend_header\n")
    faces = np.zeros(len(F), dtype=[("count", "u1"), ("indices", "<i4", (3,))])
    faces["count"] = 3
    faces["indices"] = F
    with open(path, "wb") as f:
        f.write(header.encode("ascii"))
        f.write(np.ascontiguousarray(V, dtype="<f8").tobytes())
        f.write(faces.tobytes())
