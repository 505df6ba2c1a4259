#!/usr/bin/python3
"""Pictures of the CGAL Heat_diffusion package, headless (matplotlib, Agg backend).

  render.py mesh IN.ply [IN2.ply ...] -o OUT.png [--titles T1,T2,...] [--view ELEV,AZIM]
            [--points-property feature | --points-color R,G,B | --points-json F.json --points-key a.b.c]
      renders coloured meshes (the tool's PLYs: per-vertex red/green/blue; OFF meshes
      are grey) side by side, face colours averaged from the vertex colours, shaded,
      with optional feature points as dots (only those facing the viewer).
  render.py heat DIFFUSE.json [DIFFUSE2.json ...] -o OUT.png [--labels L1,L2,...]
      plots the total heat against k (the paper's Fig. 5) from `heat_diffusion diffuse
      --json` outputs ("total_heat"), with the global isotropic baseline the JSON
      has ("global_total_heat", drawn once if several files have the same one).
  render.py noise IN.off -o OUT.off [--amplitude 0.2] [--seed 1]
      a noisy copy: Gaussian noise along the vertex normals, of standard deviation
      amplitude * mean edge length.
  render.py composite IMAGE[@I/N] [...] -o OUT.png [--titles T1|T2|...] [--columns C]
            [--height PX]
      composes pictures already rendered (the PNGs of `mesh`) into one figure, C per
      row: IMAGE@I/N is the I-th of N equal side-by-side pictures of IMAGE (1-based);
      each picture loses its own title band and white margins, is drawn PX pixels
      high and gets the title given here (the README's overview figure).
  render.py error REFERENCE MESH [--json]
      the vertex distance between two meshes with the same vertices (RMS and maximum,
      relative to the bounding-box diagonal of REFERENCE).

Reads PLY (ascii, binary little or big endian; any scalar properties; faces as lists)
and OFF. Uses Debian's python3-matplotlib and python3-numpy.
"""
import argparse
import json
import math
import os
import sys

import numpy as np

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

# --------------------------------------------------------------------------- reading

PLY_TYPES = {
    "char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1",
    "short": "i2", "int16": "i2", "ushort": "u2", "uint16": "u2",
    "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4",
    "float": "f4", "float32": "f4", "double": "f8", "float64": "f8",
}


class Mesh:
    """Vertices (n x 3), triangles (f x 3), per-vertex properties (name -> array)."""

    def __init__(self, points, triangles, properties=None):
        self.points = np.asarray(points, dtype=float)
        self.triangles = np.asarray(triangles, dtype=np.int64).reshape(-1, 3)
        self.properties = properties or {}

    def colors(self):
        """Per-vertex RGB in [0, 1], or None."""
        p = self.properties
        if all(c in p for c in ("red", "green", "blue")):
            rgb = np.stack([p["red"], p["green"], p["blue"]], axis=1).astype(float)
            return rgb / (255.0 if rgb.max() > 1.0 else 1.0)
        return None


def _triangulate(faces):
    tris = []
    for f in faces:
        for i in range(1, len(f) - 1):
            tris.append((f[0], f[i], f[i + 1]))
    return tris


def read_ply(path):
    with open(path, "rb") as fh:
        if fh.readline().strip() != b"ply":
            raise ValueError(f"{path}: not a PLY file")
        fmt = None
        elements = []  # [name, count, [(prop name, type) | (prop name, ('list', count type, item type))]]
        while True:
            line = fh.readline()
            if not line:
                raise ValueError(f"{path}: no end_header")
            words = line.decode("ascii", "replace").split()
            if not words or words[0] in ("comment", "obj_info"):
                continue
            if words[0] == "format":
                fmt = words[1]
            elif words[0] == "element":
                elements.append([words[1], int(words[2]), []])
            elif words[0] == "property":
                if words[1] == "list":
                    elements[-1][2].append((words[4], ("list", PLY_TYPES[words[2]], PLY_TYPES[words[3]])))
                else:
                    elements[-1][2].append((words[2], PLY_TYPES[words[1]]))
            elif words[0] == "end_header":
                break
        if fmt not in ("ascii", "binary_little_endian", "binary_big_endian"):
            raise ValueError(f"{path}: unknown PLY format {fmt}")
        data = {}
        if fmt == "ascii":
            tokens = fh.read().split()
            pos = 0
            for name, count, props in elements:
                columns = {p: [] for p, _ in props}
                for _ in range(count):
                    for p, t in props:
                        if isinstance(t, tuple):
                            n = int(tokens[pos]); pos += 1
                            columns[p].append([int(x) for x in tokens[pos:pos + n]]); pos += n
                        else:
                            columns[p].append(float(tokens[pos])); pos += 1
                data[name] = {p: (v if isinstance(dict(props)[p], tuple) else np.array(v))
                              for p, v in columns.items()}
        else:
            order = "<" if fmt == "binary_little_endian" else ">"
            raw = fh.read()
            pos = 0
            for name, count, props in elements:
                if all(not isinstance(t, tuple) for _, t in props):
                    dtype = np.dtype([(p, order + t) for p, t in props])
                    arr = np.frombuffer(raw, dtype=dtype, count=count, offset=pos)
                    pos += dtype.itemsize * count
                    data[name] = {p: arr[p] for p, _ in props}
                    continue
                # Lists: fast path for one list of triangles, generic loop otherwise.
                if len(props) == 1:
                    p, (_, ct, it) = props[0]
                    dtype = np.dtype([("n", order + ct), ("i", order + it, (3,))])
                    if count and pos + dtype.itemsize * count <= len(raw):
                        arr = np.frombuffer(raw, dtype=dtype, count=count, offset=pos)
                        if np.all(arr["n"] == 3):
                            pos += dtype.itemsize * count
                            data[name] = {p: arr["i"].astype(np.int64)}
                            continue
                columns = {p: [] for p, _ in props}
                for _ in range(count):
                    for p, t in props:
                        if isinstance(t, tuple):
                            ct, it = np.dtype(order + t[1]), np.dtype(order + t[2])
                            n = int(np.frombuffer(raw, ct, 1, pos)[0]); pos += ct.itemsize
                            columns[p].append(np.frombuffer(raw, it, n, pos).tolist()); pos += it.itemsize * n
                        else:
                            dt = np.dtype(order + t)
                            columns[p].append(np.frombuffer(raw, dt, 1, pos)[0]); pos += dt.itemsize
                data[name] = {p: (v if isinstance(dict(props)[p], tuple) else np.array(v))
                              for p, v in columns.items()}
    vertex = data.get("vertex")
    if vertex is None:
        raise ValueError(f"{path}: no vertex element")
    points = np.stack([vertex["x"], vertex["y"], vertex["z"]], axis=1).astype(float)
    faces = data.get("face", {})
    flist = faces.get("vertex_indices", faces.get("vertex_index", []))
    if isinstance(flist, np.ndarray):
        triangles = flist
    else:
        triangles = _triangulate(flist)
    props = {p: np.asarray(v, dtype=float) for p, v in vertex.items() if p not in ("x", "y", "z")}
    return Mesh(points, triangles, props)


def read_off(path):
    with open(path) as fh:
        tokens = [t for line in fh for t in line.split("#", 1)[0].split()]
    head = tokens[0]
    if not head.endswith("OFF"):
        raise ValueError(f"{path}: not an OFF file")
    pos = 1
    nv, nf = int(tokens[pos]), int(tokens[pos + 1]); pos += 3
    points = np.array(tokens[pos:pos + 3 * nv], dtype=float).reshape(nv, 3); pos += 3 * nv
    faces = []
    for _ in range(nf):
        n = int(tokens[pos]); faces.append([int(x) for x in tokens[pos + 1:pos + 1 + n]]); pos += 1 + n
        # optional face colours are skipped: they start a line we do not track, so
        # only meshes without face colours are read exactly (the tool writes none)
    return Mesh(points, _triangulate(faces))


def read_mesh(path):
    ext = os.path.splitext(path)[1].lower()
    if ext == ".ply":
        return read_ply(path)
    if ext == ".off":
        return read_off(path)
    raise ValueError(f"{path}: only PLY and OFF are read")


def write_off(path, mesh):
    tmp = path + ".tmp"
    with open(tmp, "w") as fh:
        fh.write(f"OFF\n{len(mesh.points)} {len(mesh.triangles)} 0\n")
        np.savetxt(fh, mesh.points, fmt="%.17g")
        np.savetxt(fh, np.hstack([np.full((len(mesh.triangles), 1), 3), mesh.triangles]), fmt="%d")
    os.replace(tmp, path)


# --------------------------------------------------------------------------- geometry

def face_normals(mesh):
    p = mesh.points[mesh.triangles]
    return np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])  # length = 2 area


def vertex_normals(mesh):
    fn = face_normals(mesh)
    vn = np.zeros_like(mesh.points)
    for c in range(3):
        np.add.at(vn, mesh.triangles[:, c], fn)
    # Outward for a closed, consistently oriented mesh (signed volume > 0).
    p = mesh.points[mesh.triangles]
    volume = np.einsum("ij,ij->i", p[:, 0], np.cross(p[:, 1], p[:, 2])).sum()
    if volume < 0:
        vn = -vn
    norms = np.linalg.norm(vn, axis=1, keepdims=True)
    return vn / np.where(norms > 0, norms, 1.0)


def view_direction(elev, azim):
    """Unit vector from the scene towards the camera of mplot3d's view_init(elev, azim)."""
    e, a = math.radians(elev), math.radians(azim)
    return np.array([math.cos(e) * math.cos(a), math.cos(e) * math.sin(a), math.sin(e)])


# --------------------------------------------------------------------------- mesh pictures

def draw_mesh(ax, mesh, elev, azim, points=None, title=None, zoom=1.2):
    tri = mesh.triangles
    colors = mesh.colors()
    if colors is None:
        face_rgb = np.full((len(tri), 3), 0.78)
    else:
        face_rgb = colors[tri].mean(axis=1)
    fn = face_normals(mesh)
    fn = fn / np.maximum(np.linalg.norm(fn, axis=1, keepdims=True), 1e-300)
    eye = view_direction(elev, azim)
    light = eye + np.array([0.3, 0.3, 0.6])
    light /= np.linalg.norm(light)
    shade = 0.45 + 0.55 * np.abs(fn @ light)
    face_rgb = np.clip(face_rgb * shade[:, None], 0.0, 1.0)
    # Edges in the face colour close the antialiasing seams between the triangles.
    coll = Poly3DCollection(mesh.points[tri], facecolors=face_rgb, edgecolors=face_rgb, linewidths=0.3)
    ax.add_collection3d(coll)

    lo, hi = mesh.points.min(axis=0), mesh.points.max(axis=0)
    half = (hi - lo).max() / 2
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_zlim(lo[2], hi[2])
    # Equal aspect: the box has the proportions of the bounding box.
    extent = np.maximum(hi - lo, 1e-9 * (hi - lo).max())
    try:
        ax.set_box_aspect(tuple(extent), zoom=zoom)
    except TypeError:  # matplotlib < 3.6
        ax.set_box_aspect(tuple(extent))
    ax.view_init(elev=elev, azim=azim)
    ax.set_axis_off()
    if points:
        # Dots over the surface: draw in zorder, not by mplot3d's depth of each collection.
        ax.computed_zorder = False
        coll.set_zorder(1)
        vn = vertex_normals(mesh)
        for indices, color in points:
            idx = np.asarray(sorted(set(int(i) for i in indices)), dtype=np.int64)
            if len(idx) == 0:
                continue
            idx = idx[vn[idx] @ eye > 0.0]  # those facing the viewer
            q = mesh.points[idx] + 0.004 * 2 * half * vn[idx]
            ax.scatter(q[:, 0], q[:, 1], q[:, 2], s=22, c=[color], edgecolors="black",
                       linewidths=0.5, depthshade=False, zorder=10)
    if title:
        ax.set_title(title, fontsize=11, pad=0)


def feature_points(mesh, args, path):
    """[(vertex indices, colour)] of the dots asked for on the command line."""
    if args.points_property:
        p = mesh.properties.get(args.points_property)
        if p is None:
            raise ValueError(f"{path}: no vertex property '{args.points_property}'")
        return [(np.nonzero(p > 0)[0], (0.85, 0.1, 0.1)), (np.nonzero(p < 0)[0], (0.1, 0.25, 0.9))]
    if args.points_color:
        rgb = np.array([float(x) for x in args.points_color.split(",")])
        c = mesh.colors()
        if c is None:
            return []
        hit = np.nonzero(np.all(np.abs(c * 255 - rgb) < 0.5, axis=1))[0]
        return [(hit, tuple(rgb / 255))]
    if args.points_json:
        with open(args.points_json) as fh:
            node = json.load(fh)
        for key in args.points_key.split("."):
            node = node[key] if isinstance(node, dict) else node[int(key)]
        if isinstance(node, dict):  # {"convex": [...], "concave": [...]}
            out = []
            for key, color in (("convex", (0.85, 0.1, 0.1)), ("concave", (0.1, 0.25, 0.9))):
                out.append((node.get(key, []), color))
            return out
        return [(node, (0.85, 0.1, 0.1))]
    return []


def cmd_mesh(args):
    titles = args.titles.split("|") if args.titles else [None] * len(args.inputs)
    if len(titles) != len(args.inputs):
        raise ValueError("--titles: one title per input, separated by '|'")
    elev, azim = (float(x) for x in args.view.split(","))
    n = len(args.inputs)
    fig = plt.figure(figsize=(args.size * n, args.size), dpi=args.dpi)
    for i, (path, title) in enumerate(zip(args.inputs, titles)):
        mesh = read_mesh(path)
        ax = fig.add_subplot(1, n, i + 1, projection="3d")
        draw_mesh(ax, mesh, elev, azim, feature_points(mesh, args, path), title, args.zoom)
    fig.subplots_adjust(left=0, right=1, bottom=0, top=0.93 if any(titles) else 1, wspace=0)
    if args.caption:
        fig.text(0.5, 0.01, args.caption, ha="center", fontsize=9)
    save(fig, args.output)


# --------------------------------------------------------------------------- heat plot

def _sigma_name(summary):
    sigma = summary.get("sigma")
    return "sigma = inf (isotropic)" if sigma is None or sigma == float("inf") else f"sigma = {sigma:g}"


def _drift(series, h0=None):
    """k values and |H_k / H_0 - 1|, floored at 1e-17 for the log scale; H_0 is the
    first value of the series unless given."""
    ks = sorted(int(k) for k in series)
    h0 = series[str(ks[0])] if h0 is None else h0
    return ks, [max(abs(series[str(k)] / h0 - 1.0), 1e-17) for k in ks]


def _baseline_name(summary):
    """The global baseline of a `diffuse --json` output, by its parameters (the same
    baseline in several files is drawn once)."""
    b = summary.get("global_baseline") or {}
    sigma = b.get("sigma")
    iso = sigma is None or sigma == float("inf")
    m = b.get("eigenpairs")
    return ("global isotropic smoothing" if iso else f"global smoothing, sigma = {sigma:g}") + \
        (f", m = {m}" if m else "")


def cmd_heat(args):
    labels = args.labels.split("|") if args.labels else None
    fig, ax = plt.subplots(figsize=(6.4, 4.0), dpi=args.dpi)
    markers = "osD^v"
    baselines = {}  # name -> (ks, drift)
    for i, path in enumerate(args.inputs):
        with open(path) as fh:
            summary = json.load(fh)
        name = labels[i] if labels else _sigma_name(summary)
        heat = summary.get("total_heat", {})
        if not heat:
            raise ValueError(f"{path}: no 'total_heat'")
        ks, drift = _drift(heat)
        h0 = heat[str(ks[0])]  # the heat of F^0 (conserved: that of F^k for the first k)
        ax.plot(ks, drift, "-" + markers[i % len(markers)], ms=4, color=f"C{i}",
                label=f"local diffusion (this package), {name}")
        baseline = summary.get("global_total_heat") or summary.get("baseline_total_heat")
        if baseline:
            # against the heat of F^0 itself: the truncated projection at k = 0 already differs
            baselines.setdefault(_baseline_name(summary), _drift(baseline, h0))
    for j, (name, (kb, db)) in enumerate(baselines.items()):
        ax.plot(kb, db, "--" + markers[(len(args.inputs) + j) % len(markers)], ms=4, color="black", mfc="white",
                label=f"{name} (baseline)")
    ax.set_yscale("log")
    ax.set_xscale("symlog", linthresh=1)
    ax.set_xlim(left=0)
    ax.set_ylim(bottom=5e-18)
    ax.axhline(np.finfo(float).eps, color="grey", lw=0.8, ls=":")
    ax.text(ax.get_xlim()[1], np.finfo(float).eps * 1.3, "machine epsilon ", ha="right", va="bottom",
            fontsize=7, color="grey")
    ax.set_xlabel("diffusion steps k (time k t)")
    ax.set_ylabel("relative drift of the total heat  |H(k)/H(F^0) - 1|")
    ax.set_title("Heat conservation (paper, Fig. 5)" + ("" if baselines else
                 "\n(the global baseline is not in the JSON)"), fontsize=10)
    ax.grid(True, alpha=0.3, which="both")
    ax.legend(fontsize=8, loc="best")
    fig.tight_layout()
    save(fig, args.output)


# --------------------------------------------------------------------------- noise and error

def cmd_noise(args):
    mesh = read_mesh(args.input)
    tri = mesh.triangles
    edges = np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]])
    mean_edge = np.linalg.norm(mesh.points[edges[:, 0]] - mesh.points[edges[:, 1]], axis=1).mean()
    rng = np.random.default_rng(args.seed)
    offsets = rng.normal(0.0, args.amplitude * mean_edge, len(mesh.points))
    noisy = Mesh(mesh.points + offsets[:, None] * vertex_normals(mesh), tri)
    write_off(args.output, noisy)
    print(json.dumps({"input": args.input, "output": args.output, "vertices": len(mesh.points),
                      "amplitude_in_mean_edge_lengths": args.amplitude, "mean_edge_length": mean_edge,
                      "seed": args.seed}))


def cmd_error(args):
    ref, other = read_mesh(args.reference), read_mesh(args.mesh)
    if ref.points.shape != other.points.shape:
        raise ValueError(f"{args.mesh}: {len(other.points)} vertices, {args.reference} has {len(ref.points)}")
    diagonal = np.linalg.norm(ref.points.max(axis=0) - ref.points.min(axis=0))
    d = np.linalg.norm(ref.points - other.points, axis=1)
    result = {"reference": args.reference, "mesh": args.mesh, "diagonal": diagonal,
              "rms_relative": math.sqrt((d ** 2).mean()) / diagonal, "max_relative": d.max() / diagonal}
    print(json.dumps(result))


# --------------------------------------------------------------------------- composite

def _ink(image):
    """Rows x columns mask of the pixels that are not (nearly) white or transparent."""
    rgb = image[..., :3].astype(float)
    if rgb.max() > 1.0:
        rgb = rgb / 255.0
    alpha = image[..., 3] if image.shape[-1] == 4 else np.ones(image.shape[:2])
    return (alpha > 0.1) & (rgb.min(axis=-1) < 0.94)


def _panel(spec):
    """The picture named by IMAGE or IMAGE@I/N, without its title band and margins."""
    path, _, part = spec.partition("@")
    image = plt.imread(path)
    if image.ndim == 2:
        image = np.stack([image] * 3, axis=-1)
    if part:
        try:
            i, n = (int(x) for x in part.split("/"))
        except ValueError:
            raise ValueError(f"{spec}: the part of a strip is I/N, e.g. {path}@2/3")
        if not 1 <= i <= n:
            raise ValueError(f"{spec}: I must be in 1..N")
        w = image.shape[1]
        image = image[:, round((i - 1) * w / n):round(i * w / n)]
    ink = _ink(image)
    rows = np.nonzero(ink.any(axis=1))[0]
    if len(rows) == 0:
        raise ValueError(f"{spec}: the picture is blank")
    # A title of `render.py mesh` is ink in the top 7 % (its axes start at 93 % of the
    # height): drop it, up to the first white row below it, or the whole 7 % where the
    # mesh reaches into the band.
    h = image.shape[0]
    band = int(math.ceil(0.07 * h))
    if rows[0] < band:
        # (from half the band on: the white rows inside a line of text, above the
        # letters' bodies, are not its end)
        gaps = np.nonzero(~ink[band // 2:2 * band].any(axis=1))[0]
        top = band // 2 + gaps[0] if len(gaps) else band
        if ink[top:].any():
            image, ink = image[top:], ink[top:]
    rows = np.nonzero(ink.any(axis=1))[0]
    cols = np.nonzero(ink.any(axis=0))[0]
    margin = 2
    r0, r1 = max(rows[0] - margin, 0), min(rows[-1] + margin + 1, image.shape[0])
    c0, c1 = max(cols[0] - margin, 0), min(cols[-1] + margin + 1, image.shape[1])
    return image[r0:r1, c0:c1]


def cmd_composite(args):
    titles = args.titles.split("|") if args.titles else [None] * len(args.inputs)
    if len(titles) != len(args.inputs):
        raise ValueError("--titles: one title per picture, separated by '|'")
    if args.columns < 1:
        raise ValueError("--columns: at least 1")
    panels = [_panel(spec) for spec in args.inputs]
    # Layout in pixels: every picture args.height high, a title band above each row.
    height, gap, band = args.height, 8, (22 if any(titles) else 0)
    rows = [list(range(i, min(i + args.columns, len(panels)))) for i in range(0, len(panels), args.columns)]
    widths = [height * p.shape[1] / p.shape[0] for p in panels]
    row_widths = [sum(widths[i] for i in row) + gap * (len(row) - 1) for row in rows]
    total_w = max(row_widths) + 2 * gap
    total_h = len(rows) * (height + band) + (len(rows) + 1) * gap
    dpi = 100
    fig = plt.figure(figsize=(total_w / dpi, total_h / dpi), dpi=dpi)
    fig.patch.set_facecolor("white")
    for r, row in enumerate(rows):
        x = (total_w - row_widths[r]) / 2
        y = total_h - (r + 1) * (height + band + gap)  # bottom of the pictures, from below
        for i in row:
            ax = fig.add_axes([x / total_w, y / total_h, widths[i] / total_w, height / total_h])
            ax.imshow(panels[i], interpolation="antialiased")
            ax.set_axis_off()
            if titles[i]:
                ax.set_title(titles[i], fontsize=10, pad=3)
            x += widths[i] + gap
    # RGB, a palette of 256 colours: the shaded meshes need no more, and the file stays small.
    fig.canvas.draw()
    rgb = np.asarray(fig.canvas.buffer_rgba())[..., :3]
    plt.close(fig)
    from PIL import Image
    out = Image.fromarray(rgb).quantize(colors=256, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE)
    os.makedirs(os.path.dirname(os.path.abspath(args.output)), exist_ok=True)
    tmp = args.output + ".tmp.png"
    out.save(tmp, optimize=True)
    os.replace(tmp, args.output)


def save(fig, path):
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    tmp = path + ".tmp.png"
    fig.savefig(tmp)
    plt.close(fig)
    os.replace(tmp, path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    sub = parser.add_subparsers(dest="command", required=True)
    m = sub.add_parser("mesh", help="render coloured meshes to PNG")
    m.add_argument("inputs", nargs="+")
    m.add_argument("-o", "--output", required=True)
    m.add_argument("--titles", help="one title per input, separated by '|'")
    m.add_argument("--caption")
    m.add_argument("--view", default="25,-60", help="ELEV,AZIM in degrees (default 25,-60)")
    m.add_argument("--zoom", type=float, default=1.2, help="zoom of the 3D box (default 1.2)")
    m.add_argument("--size", type=float, default=4.0, help="inches per picture (default 4)")
    m.add_argument("--dpi", type=int, default=100)
    m.add_argument("--points-property", help="dots at the vertices where this property is > 0 (red) or < 0 (blue)")
    m.add_argument("--points-color", help="dots at the vertices of this colour, R,G,B in 0..255")
    m.add_argument("--points-json", help="dots at the vertex indices of this JSON file ...")
    m.add_argument("--points-key", default="", help="... under this dotted key (e.g. features.10)")
    m.set_defaults(func=cmd_mesh)
    h = sub.add_parser("heat", help="plot the total heat against k")
    h.add_argument("inputs", nargs="+")
    h.add_argument("-o", "--output", required=True)
    h.add_argument("--labels", help="one label per input, separated by '|'")
    h.add_argument("--dpi", type=int, default=100)
    h.set_defaults(func=cmd_heat)
    n = sub.add_parser("noise", help="a copy with Gaussian noise along the normals")
    n.add_argument("input")
    n.add_argument("-o", "--output", required=True)
    n.add_argument("--amplitude", type=float, default=0.2, help="in mean edge lengths (default 0.2)")
    n.add_argument("--seed", type=int, default=1)
    n.set_defaults(func=cmd_noise)
    c = sub.add_parser("composite", help="compose rendered pictures into one figure")
    c.add_argument("inputs", nargs="+", metavar="IMAGE[@I/N]")
    c.add_argument("-o", "--output", required=True)
    c.add_argument("--titles", help="one title per picture, separated by '|'")
    c.add_argument("--columns", type=int, default=4, help="pictures per row (default 4)")
    c.add_argument("--height", type=int, default=170, help="height of each picture in pixels (default 170)")
    c.set_defaults(func=cmd_composite)
    e = sub.add_parser("error", help="vertex distance between two meshes")
    e.add_argument("reference")
    e.add_argument("mesh")
    e.set_defaults(func=cmd_error)
    args = parser.parse_args()
    try:
        args.func(args)
    except (OSError, ValueError, KeyError, IndexError) as err:
        print(f"render.py: {err}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
