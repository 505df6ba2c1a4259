#!/usr/bin/env python3
"""The overhead of the Python binding: HeatDiffusion construction + NS + diffusion by
k steps from Python, against the same work timed inside the C++ tool (its --json
timings 'ncc_and_local_operator' + 'diffusion': the NCC, A_t, the NS and F^k).

Both run in fresh processes. The Python figure counts everything a Python user pays: the
checks of V and F, the Surface_mesh built from them, the field copies and the reordering
to the input's vertex order. The tool's figure excludes its file reading (where it builds
its Surface_mesh). Runs come in pairs, one of each, back to back, the first of the pair
alternating (Python first, then C++ first), so that both see the same load on a shared
machine. The overhead is given for the fastest run of each (the least disturbed), for the
medians, and as the median of the pairs' ratios (each pair's two runs close in time); the
results are checked equal (1e-12) on the way.

    PYTHONPATH=build/python /usr/bin/python3 benchmark/Heat_diffusion/benchmark_python.py \
        --tool build/bin/heat_diffusion --data build/data/meshes [--repeat 5] [--levels 0,2] [--verbose]

Meshes: fandisk, and armadillo Loop-subdivided twice (416,002 vertices), as the C++
benchmarks make it (CGAL::Subdivision_method_3, here through the binding).
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

import meshio
import numpy as np

import cgal_heat_diffusion as hd


def read_mesh(path):
    mesh = meshio.read(path)
    return (np.ascontiguousarray(mesh.points, dtype=np.float64),
            np.ascontiguousarray(mesh.cells_dict["triangle"], dtype=np.int64))


def write_off(path, V, F):
    with open(path, "w") as f:
        f.write(f"OFF\n{len(V)} {len(F)} 0\n")
        np.savetxt(f, V, fmt="%.17g")
        np.savetxt(f, np.hstack([np.full((len(F), 1), 3), F]), fmt="%d")


# Each Python run is a fresh process, as each run of the tool is: a process that has
# already built and freed an operator reuses the memory its allocator keeps, and runs
# faster for it (fewer page faults).
PYTHON_RUN = """
import sys, time
import numpy as np
import cgal_heat_diffusion as hd
V, F = np.load(sys.argv[1]), np.load(sys.argv[2])
start = time.perf_counter()
diffusion = hd.HeatDiffusion(V, F)
field = diffusion.diffuse(diffusion.normal_signature(), int(sys.argv[3]))
seconds = time.perf_counter() - start
np.save(sys.argv[4], field)
print(seconds)
"""


def python_run(V_path, F_path, k, work):
    out = os.path.join(work, "field.npy")
    result = subprocess.run([sys.executable, "-c", PYTHON_RUN, V_path, F_path, str(k), out], capture_output=True,
                            text=True, check=True)
    return float(result.stdout), np.load(out)


def tool_run(tool, path, k, work):
    prefix = os.path.join(work, "out")
    result = subprocess.run([tool, "diffuse", path, "-k", str(k), "-o", prefix, "--json", "--quiet",
                             "--no-baseline"], capture_output=True, text=True, check=True)
    timings = json.loads(result.stdout)["timings_ms"]
    return (timings["ncc_and_local_operator"] + timings["diffusion"]) / 1000.0, prefix + f"_k{k}.ply"


def ply_field(path):
    with open(path, "rb") as f:
        header = []
        while not header or header[-1] != "end_header":
            header.append(f.readline().decode("ascii").strip())
        count = int(next(line.split()[2] for line in header if line.startswith("element vertex")))
        names = [line.split() for line in header if line.startswith("property") and "list" not in line]
        codes = {"double": "<f8", "float": "<f4", "uchar": "u1", "int": "<i4"}
        dtype = np.dtype([(w[2], codes[w[1]]) for w in names])
        return np.frombuffer(f.read(count * dtype.itemsize), dtype=dtype, count=count)["field"]


def whole_number(lowest, highest):
    """An argparse type: a whole number in [lowest, highest] (a usage error otherwise)."""
    def parse(text):
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"not a whole number: '{text}'")
        if not lowest <= value <= highest:
            raise argparse.ArgumentTypeError(f"{value} is not in [{lowest}, {highest}]")
        return value
    return parse


def levels_list(text):
    """An argparse type: a comma-separated list of subdivision levels from 0 to 3."""
    return [whole_number(0, 3)(item) for item in text.split(",")]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--tool", required=True)
    parser.add_argument("--data", required=True)
    parser.add_argument("--repeat", type=whole_number(1, 100), default=5)
    parser.add_argument("--levels", type=levels_list, default=[0, 2],
                        help="Loop subdivision levels of armadillo (0 = fandisk)")
    parser.add_argument("-k", type=whole_number(0, 100000), default=10)
    parser.add_argument("--verbose", action="store_true", help="print the times of every pair")
    args = parser.parse_args()
    # checked now: the runs take minutes before the tool is first called
    if not (os.path.isfile(args.tool) and os.access(args.tool, os.X_OK)):
        parser.error(f"--tool '{args.tool}' is not an executable file")
    if not os.path.isdir(args.data):
        parser.error(f"--data '{args.data}' is not a directory")

    print(f"Python binding overhead: HeatDiffusion + NS + {args.k} steps, local kernel, sigma 0.1, t 1; "
          f"{args.repeat} alternating runs of each")
    print(f"{'mesh':>22} {'vertices':>9} {'Python s':>9} {'C++ s':>9} {'overhead':>9}   "
          f"{'medians: Python, C++, overhead':>32}   {'pairs':>8}")
    with tempfile.TemporaryDirectory() as work:
        for level in args.levels:
            if level == 0:
                name, path = "fandisk", os.path.join(args.data, "fandisk.off")
                V, F = read_mesh(path)
            else:
                name = f"armadillo, Loop x{level}"
                V, F = hd.loop_subdivision(*read_mesh(os.path.join(args.data, "armadillo.off")), level)
                path = os.path.join(work, f"armadillo_{level}.off")
                write_off(path, V, F)
            V_path, F_path = os.path.join(work, "V.npy"), os.path.join(work, "F.npy")
            np.save(V_path, V)
            np.save(F_path, F)
            python_times, tool_times = [], []
            for r in range(args.repeat):
                for which in ((0, 1) if r % 2 == 0 else (1, 0)):
                    if which == 0:
                        seconds, field = python_run(V_path, F_path, args.k, work)
                        python_times.append(seconds)
                    else:
                        seconds, ply = tool_run(args.tool, path, args.k, work)
                        tool_times.append(seconds)
                if args.verbose:
                    print(f"  pair {r}: Python {python_times[-1]:.3f} s, C++ {tool_times[-1]:.3f} s")
            expected = ply_field(ply)
            difference = np.max(np.abs(field - expected)) / max(1.0, np.max(np.abs(expected)))
            if not difference <= 1e-12:
                sys.exit(f"{name}: the Python result differs from the tool's by {difference:.3g}")
            p, c = min(python_times), min(tool_times)
            pm, cm = statistics.median(python_times), statistics.median(tool_times)
            paired = statistics.median(x / y for x, y in zip(python_times, tool_times))
            print(f"{name:>22} {len(V):>9} {p:>9.3f} {c:>9.3f} {100 * (p / c - 1):>8.1f}%"
                  f"   {pm:>10.3f} {cm:>10.3f} {100 * (pm / cm - 1):>8.1f}%   {100 * (paired - 1):>8.1f}%")
            sys.stdout.flush()


if __name__ == "__main__":
    main()
