#!/usr/bin/python3
"""Writes the one-page summary of scripts/demo.sh (Markdown, on stdout) from the
pictures and the --json outputs in the given folder (default out/). Whatever is
missing is left out."""
import json
import os
import sys

out = sys.argv[1] if len(sys.argv) > 1 else "out"
NAN = float("nan")


def load(name):
    path = os.path.join(out, name + ".json")
    try:
        with open(path) as fh:
            return json.load(fh)
    except (OSError, ValueError):
        return None


def has(png):
    return os.path.exists(os.path.join(out, png))


def ms(summary, *stages):
    t = (summary or {}).get("timings_ms", {})
    if stages:
        return sum(t.get(s, 0.0) for s in stages)
    return sum(t.values())


def fmt_ms(x):
    return f"{x / 1000:.2f} s" if x >= 1000 else f"{x:.0f} ms"


def drift(series, h0=None):
    """(sorted k, H at the first k, largest |H(k) - H0| / |H0|) of a {k: H} map; H0 is
    the value at the first k unless given."""
    ks = sorted(series, key=int)
    if not ks:
        return [], NAN, NAN
    first = series[ks[0]]
    h0 = first if h0 is None else h0
    worst = max(abs(series[k] - h0) for k in ks) / abs(h0) if h0 else NAN
    return ks, first, worst


lines = []
add = lines.append
timings = []  # (what, summary)


def section(title, pictures=(), summary=None, what=None):
    """A section: its title, its pictures (alt text, file) that exist, and the run
    that made it in the timing table."""
    add(f"## {title}")
    add("")
    for alt, png in pictures:
        if has(png):
            add(f"![{alt}]({png})")
            add("")
    if summary and what:
        timings.append((what, summary))


def table(header, rows):
    add("| " + " | ".join(header) + " |")
    add("|" + "---|" * len(header))
    for row in rows:
        add("| " + " | ".join(str(x) for x in row) + " |")
    add("")


ns = load("fandisk_ns")
n = (ns or {}).get("vertices")
add("# CGAL Heat_diffusion on fandisk")
add("")
add(f"`scripts/demo.sh`: CGAL's `fandisk.off`{f' ({n} vertices)' if n else ''}, "
    "edge-weighted heat kernel at t = 1, computed locally without eigenpairs (the tool's default, "
    "`--kernel automatic`) unless said otherwise. "
    "Colours: red positive (convex), blue negative (concave), white zero.")
add("")

if has("fandisk_ns.png"):
    section("Normal Signature", [("Normal Signature", "fandisk_ns.png")], ns, "`ncc`")
    r = (ns or {}).get("ns") or {}
    if "min" in r and "max" in r:
        add(f"NS from {r['min']:.3g} to {r['max']:.3g}.")
        add("")

diff = [(s, load(f"fandisk_diffuse_sigma{s}")) for s in ("0.1", "1")]
if any(d for _, d in diff):
    section("Diffusion of the NS, k = 0, 10, 40", [(f"sigma {s}", f"fandisk_diffuse_sigma{s}.png") for s, _ in diff])
    rows = []
    for s, d in diff:
        if not d:
            continue
        timings.append((f"`diffuse --sigma {s}`", d))
        _, h0, worst = drift(d.get("total_heat", {}))
        r = d.get("heat_regions", {})
        t = d.get("timings_ms", {})
        # the spectral kernel times its eigen solve and A_t apart, the local one together
        rows.append([s, d.get("kernel", "?"),
                     f"{r.get('min')} / {r.get('mean', 0):.0f} / {r.get('max')}, {r.get('collapsed')}",
                     f"{h0:.6g}", f"{worst:.1e}",
                     fmt_ms(ms(d, "ncc_and_eigen_solve", "operator", "ncc_and_local_operator")),
                     fmt_ms(t.get("diffusion", 0))])
    table(["sigma", "kernel", "heat regions (min / mean / max, collapsed)", "total heat k = 0", "largest drift",
           "NCC, kernel and A_t", "diffusion"], rows)

curves = [(s, load(f"fandisk_heat_sigma{s}")) for s in ("0.1", "inf")]
if has("fandisk_heat.png"):
    section("Heat conservation (the paper's Fig. 5)", [("total heat against k", "fandisk_heat.png")])
    rows, baseline = [], None
    for s, c in curves:
        if not c:
            continue
        ks, h0, worst = drift(c["total_heat"])
        rows.append([f"this package, sigma {s}", f"{h0:.6g}", f"{worst:.1e}"])
        if baseline is None and c.get("global_total_heat"):
            baseline = c
    if baseline:
        # against the heat of F^0: the truncated projection at k = 0 already differs from it
        ks, h0, worst = drift(baseline["global_total_heat"], drift(baseline["total_heat"])[1])
        m = baseline.get("global_baseline", {}).get("eigenpairs", "?")
        rows.append([f"global isotropic smoothing (baseline, m = {m})", f"{h0:.6g}", f"{worst:.1e}"])
    if rows:
        add(f"Total heat sum_i F^k(i) for k = 0 .. {ks[-1]} (t = 1): the local diffusion conserves it to "
            "rounding; the global spectral smoothing of Patane and Seo conserves the area-weighted "
            "integral instead, and its vertex sum drifts.")
        add("")
        table(["diffusion", "total heat at k = 0", "largest drift from the heat of F^0"], rows)

ones = [(n, load(f"fandisk_ones_{n}")) for n in ("balanced", "columns")]
if any(o for _, o in ones):
    section("A constant field", [])
    add("A field of ones diffused on fandisk (sigma 0.1, t = 1): the default operator is doubly stochastic "
        "and keeps it; the paper's column normalisation conserves its total but not its values.")
    add("")
    rows = []
    for n, o in ones:
        if not o or "minimum" not in o:
            continue
        for k in sorted(o["minimum"], key=int):
            rows.append([f"`--normalization {n}`", k, f"{o['minimum'][k]:.6g}", f"{o['maximum'][k]:.6g}",
                         f"{o['total_heat'][k]:.6g}"])
    table(["operator", "k", "min F^k", "max F^k", "total heat"], rows)

feat = load("fandisk_features")
if feat and has("fandisk_features.png"):
    section("Features at the scales k = 0, 10, 40", [("features", "fandisk_features.png")], feat, "`features`")
    per = feat.get("features", {})
    table(["k", "convex", "concave"],
          [[k, len(per[k].get("convex", [])), len(per[k].get("concave", []))] for k in sorted(per, key=int)])

noisy_err, den_err, den = load("fandisk_noisy_error"), load("fandisk_denoised_error"), load("fandisk_denoise")
if has("fandisk_noisy.png") or has("fandisk_denoised.png"):
    section("Denoising", [("noisy and denoised", "fandisk_denoised.png")] if has("fandisk_denoised.png")
            else [("noisy copy", "fandisk_noisy.png")], den, "`denoise`")
    if noisy_err:
        add("Noise: Gaussian along the normals, 0.2 mean edge length. Vertex error relative to the "
            "bounding-box diagonal (RMS / max):")
        add("")
        table(["mesh", "RMS", "max"],
              [[name, f"{e['rms_relative']:.2e}", f"{e['max_relative']:.2e}"]
               for name, e in (("noisy", noisy_err), ("denoised", den_err)) if e])

dec = load("fandisk_decompose")
if dec and has("fandisk_decompose.png"):
    section("Decomposition into detail bands (eq. 24)", [("bands", "fandisk_decompose.png")], dec, "`decompose`")
    bands = dec.get("bands", {})
    add(f"{dec.get('levels')} levels of {dec.get('steps_per_level')} steps. Every band sums to zero (eq. 25):")
    add("")
    table(["band", "sum / sum abs S", "L2 norm"],
          [[b, f"{bands[b].get('relative_sum', NAN):.1e}", f"{bands[b].get('l2_norm', NAN):.3g}"]
           for b in sorted(bands, key=int)])

enh = load("fandisk_enhance")
if enh and has("fandisk_enhanced.png"):
    section("Enhancement (band weights 1, 3, 3)", [("enhanced", "fandisk_enhanced.png")], enh, "`enhance`")
    add(f"NS variance {enh.get('ns_variance_before', NAN):.3g} before, "
        f"{enh.get('ns_variance_after', NAN):.3g} after; largest vertex displacement "
        f"{enh.get('max_displacement_relative', NAN):.2%} of the bounding-box diagonal.")
    add("")

arm, arm_smooth = load("armadillo_enhance"), load("armadillo_smooth")
if arm and has("armadillo_filters.png"):
    section("Shape filtering of armadillo (the paper's Fig. 10)", [("smoothed, input, enhanced", "armadillo_filters.png")],
            arm, "`enhance`")
    def ratio(summary):
        return summary.get("ns_variance_after", NAN) / summary.get("ns_variance_before", NAN)
    text = (f"Enhancement (1, 3, 3): NS variance {ratio(arm):.2f} times the input's; largest vertex displacement "
            f"{arm.get('max_displacement_relative', NAN):.2%} of the bounding-box diagonal.")
    if arm_smooth:
        text += f" Smoothing (0, 0, 1): {ratio(arm_smooth):.2f} times."
    add(text)
    add("")

if timings:
    add("## Timings")
    add("")
    rows = []
    for what, s in timings:
        kernel = ms(s, "ncc_and_eigen_solve", "ncc_and_local_operator", "eigen_solve", "kernel")
        rows.append([what, s.get("kernel", "-"), fmt_ms(ms(s)), fmt_ms(kernel) if kernel else "-"])
    table(["run", "kernel", "total", "of which NCC and kernel"], rows)

notes = os.path.join(out, "notes.txt")
if os.path.exists(notes):
    add("## Skipped")
    add("")
    with open(notes) as fh:
        for line in fh:
            add("- " + line.strip().removeprefix("note: "))
    add("")

print("\n".join(lines))
