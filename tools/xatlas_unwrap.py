"""xatlas beside `barytex unwrap`, on the same meshes, atlas size and padding, in one run.

For each mesh (the glTF fixtures Suzanne and Avocado, and the built-in torus and sphere of
`barytex unwrap --mesh`), `barytex unwrap --dump-mesh` writes the welded mesh that barytex
unwraps; xatlas (its Python bindings, https://pypi.org/project/xatlas/, version 0.0.11) unwraps
that same mesh with the same resolution and padding; then `barytex unwrap --compare-uvs`
measures xatlas's uvs with the very code that measures ours (charts as connected pieces, flips
per chart against its majority orientation, exact overlap tests, uv area over the unit square,
barytex-uv's angle and area distortion). Times: median of --runs runs; ours is weld + charts +
pack (the stages of `--stats`, the exact checks apart), xatlas's is add_mesh + generate.

Run from the repository root (creates target/xatlas-venv with xatlas, trimesh and numpy from
PyPI on first use, builds `barytex` in release mode):

    BARYTEX_FIXTURES=/path/to/fixtures python3 tools/xatlas_unwrap.py [--size 1024] [--padding 4]
        [--runs 3] [--report docs/report]

With --report DIR it writes DIR/unwrap.md (the table) and DIR/unwrap-pareto.svg (distortion vs
time per method and mesh, xatlas beside ours).
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

from pinned_venv import ensure_venv

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
VENV = os.path.join(ROOT, "target", "xatlas-venv")
METHODS = ["lscm-arap", "lscm", "mean-value", "pairs", "per-triangle"]


def meshes():
    fixtures = os.environ.get("BARYTEX_FIXTURES")
    found = []
    if fixtures:
        for name in ["Suzanne", "Avocado"]:
            path = os.path.join(fixtures, "gltf", name, "glTF", name + ".gltf")
            if os.path.exists(path):
                found.append((name, [path]))
    else:
        print("BARYTEX_FIXTURES is not set: only the built-in meshes", file=sys.stderr)
    found += [
        ("torus 32×16", ["--mesh", "torus"]),
        ("sphere 32×16", ["--mesh", "sphere"]),
        ("torus 256×128", ["--mesh", "dense-torus"]),
    ]
    return found


class DoesNotFit(Exception):
    """barytex refused a layout whose charts do not fit the atlas (too many for the padding)."""


def barytex(binary, source, out_dir, extra):
    args = [binary, "unwrap", *source, "--layout", os.path.join(out_dir, "layout.png"), *extra]
    if source[0] != "--mesh":
        args += ["-o", os.path.join(out_dir, "out.gltf")]
    done = subprocess.run(args, capture_output=True, text=True)
    if done.returncode != 0:
        if "do not fit" in done.stderr:
            raise DoesNotFit(done.stderr.strip().removeprefix("barytex: "))
        raise SystemExit(f"{' '.join(args)}:\n{done.stdout}{done.stderr}")


def run_xatlas(mesh_json, size, padding, runs):
    import numpy as np
    import xatlas

    with open(mesh_json) as f:
        mesh = json.load(f)
    positions = np.asarray(mesh["positions"], dtype=np.float32)
    faces = np.asarray(mesh["triangles"], dtype=np.uint32)
    seconds = []
    atlas = None
    for _ in range(runs):
        pack = xatlas.PackOptions()
        pack.resolution = size
        pack.padding = padding
        started = time.perf_counter()
        atlas = xatlas.Atlas()
        atlas.add_mesh(positions, faces)
        atlas.generate(chart_options=xatlas.ChartOptions(), pack_options=pack)
        seconds.append(time.perf_counter() - started)
    vmapping, indices, uvs = atlas[0]
    # The binding divides texel coordinates by the atlas's width and height, and xatlas's atlas is
    # only near the requested resolution and not square (e.g. 1239 × 935 for the sphere). Scaling
    # both axes by one factor puts the layout in a square of side max(width, height) as it is,
    # without stretching it: what a square texture holding xatlas's atlas would show.
    side = max(atlas.width, atlas.height)
    uvs = uvs * np.array([atlas.width / side, atlas.height / side])
    info = {
        "atlas_count": int(atlas.atlas_count),
        "chart_count": int(atlas.chart_count),
        "width": int(atlas.width),
        "height": int(atlas.height),
        "seconds": statistics.median(seconds),
    }
    return info, {
        "vertex_of": vmapping.tolist(),
        "uvs": uvs.astype(float).tolist(),
        "indices": indices.tolist(),
    }


def fmt(x, digits=4):
    if x is None:
        return "–"
    if isinstance(x, str):
        return "∞"
    return f"{x:.{digits}f}"


def pareto_svg(rows, path):
    """Angle distortion (mean) against time, log time axis; one mark per mesh and method."""
    import math

    w, h, m = 640, 400, 60
    rows = [r for r in rows if "refused" not in r]
    times = [r["ms"] for r in rows if r["ms"] > 0]
    finite = [r for r in rows if isinstance(r["angle_mean"], float)]
    dist = [r["angle_mean"] for r in finite]
    t0, t1 = math.log10(min(times)) - 0.2, math.log10(max(times)) + 0.2
    d0, d1 = 1.0, max(dist) * 1.05 + 0.01
    colours = {"xatlas": "#d62728", "lscm-arap": "#9467bd", "lscm": "#8c564b", "mean-value": "#ff7f0e", "pairs": "#1f77b4", "per-triangle": "#2ca02c"}
    shapes = {}
    out = [
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" font-family="sans-serif" font-size="11">',
        f'<rect width="{w}" height="{h}" fill="white"/>',
        f'<line x1="{m}" y1="{h - m}" x2="{w - 20}" y2="{h - m}" stroke="black"/>',
        f'<line x1="{m}" y1="20" x2="{m}" y2="{h - m}" stroke="black"/>',
        f'<text x="{w / 2}" y="{h - 20}" text-anchor="middle">time per mesh, ms (log scale; ours: weld + charts + pack; xatlas: add_mesh + generate)</text>',
        f'<text x="15" y="{h / 2}" transform="rotate(-90 15 {h / 2})" text-anchor="middle">angle distortion, area-weighted mean σ1/σ2</text>',
    ]
    for k in range(int(math.floor(t0)), int(math.ceil(t1)) + 1):
        if t0 <= k <= t1:
            x = m + (k - t0) / (t1 - t0) * (w - m - 20)
            out.append(f'<line x1="{x}" y1="{h - m}" x2="{x}" y2="{h - m + 5}" stroke="black"/>')
            out.append(f'<text x="{x}" y="{h - m + 18}" text-anchor="middle">{10 ** k:g}</text>')
    for j in range(5):
        d = d0 + (d1 - d0) * j / 4
        y = h - m - (d - d0) / (d1 - d0) * (h - m - 20)
        out.append(f'<text x="{m - 5}" y="{y + 4}" text-anchor="end">{d:.2f}</text>')
    marks = ["circle", "square", "diamond", "triangle"]
    for r in rows:
        if not isinstance(r["angle_mean"], float) or r["ms"] <= 0:
            continue
        shape = shapes.setdefault(r["mesh"], marks[len(shapes) % len(marks)])
        x = m + (math.log10(r["ms"]) - t0) / (t1 - t0) * (w - m - 20)
        y = h - m - (r["angle_mean"] - d0) / (d1 - d0) * (h - m - 20)
        c = colours.get(r["method"], "black")
        if shape == "circle":
            out.append(f'<circle cx="{x:.1f}" cy="{y:.1f}" r="5" fill="{c}"/>')
        elif shape == "square":
            out.append(f'<rect x="{x - 5:.1f}" y="{y - 5:.1f}" width="10" height="10" fill="{c}"/>')
        elif shape == "diamond":
            out.append(f'<polygon points="{x:.1f},{y - 6:.1f} {x + 6:.1f},{y:.1f} {x:.1f},{y + 6:.1f} {x - 6:.1f},{y:.1f}" fill="{c}"/>')
        else:
            out.append(f'<polygon points="{x:.1f},{y - 6:.1f} {x + 6:.1f},{y + 5:.1f} {x - 6:.1f},{y + 5:.1f}" fill="{c}"/>')
    ly = 30
    for name, c in colours.items():
        out.append(f'<rect x="{w - 170}" y="{ly - 9}" width="10" height="10" fill="{c}"/><text x="{w - 155}" y="{ly}">{name}</text>')
        ly += 15
    for name, shape in shapes.items():
        out.append(f'<text x="{w - 170}" y="{ly}">{shape}: {name}</text>')
        ly += 15
    out.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def main():
    ensure_venv(VENV, __file__, ["xatlas==0.0.11", "trimesh", "numpy"], "xatlas, trimesh, numpy")
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, default=1024)
    parser.add_argument("--padding", type=int, default=4)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--report", help="folder for unwrap.md and unwrap-pareto.svg")
    parser.add_argument("--only", action="append", help="only the meshes whose name contains this (repeatable)")
    parser.add_argument("--methods", help="comma-separated barytex methods (default: all)")
    args = parser.parse_args()
    methods = args.methods.split(",") if args.methods else METHODS
    subprocess.check_call(["cargo", "build", "--release", "-q", "-p", "barytex"], cwd=ROOT)
    binary = os.path.join(os.environ.get("CARGO_TARGET_DIR", os.path.join(ROOT, "target")), "release", "barytex")
    common = ["--size", str(args.size), "--padding", str(args.padding)]
    rows = []
    for name, source in meshes():
        if args.only and not any(o in name for o in args.only):
            continue
        with tempfile.TemporaryDirectory() as tmp:
            mesh_json = os.path.join(tmp, "mesh.json")
            barytex(binary, source, tmp, common + ["--dump-mesh", mesh_json])
            info, uvs = run_xatlas(mesh_json, args.size, args.padding, args.runs)
            peer = os.path.join(tmp, "xatlas.json")
            with open(peer, "w") as f:
                json.dump(uvs, f)
            xatlas_row = None
            for method in methods:
                stats, seconds, checks = [], [], []
                try:
                    for _ in range(args.runs):
                        out = os.path.join(tmp, "stats.json")
                        barytex(binary, source, tmp, common + ["--method", method, "--compare-uvs", peer, "--stats-json", out])
                        with open(out) as f:
                            stats = json.load(f)
                        s = stats["seconds"]
                        seconds.append(s["weld"] + s["charts"] + s["pack"])
                        checks.append(s["check"])
                except DoesNotFit as refused:
                    rows.append({"mesh": name, "method": method, "refused": str(refused)})
                    continue
                ours = stats["meshes"][0]
                rows.append({"mesh": name, "method": method, "ms": 1e3 * statistics.median(seconds),
                             "check_ms": 1e3 * statistics.median(checks), **ours})
                if xatlas_row is None:
                    xatlas_row = {"mesh": name, "method": "xatlas", "ms": 1e3 * info["seconds"],
                                  "check_ms": None, **stats["compare"], "atlases": info["atlas_count"],
                                  "size": (info["width"], info["height"])}
            rows.append(xatlas_row)
    header = ("| mesh | method | time ms | exact checks ms | charts | flips | overlaps (between / within) "
              "| efficiency | angle mean / max | area mean / max |")
    lines = [header, "|" + "---|" * 10]
    for r in rows:
        if "refused" in r:
            lines.append(f"| {r['mesh']} | {r['method']} | {r['refused']} |" + " |" * 7)
            continue
        atl = f" ({r['atlases']} atlases)" if r.get("atlases", 1) != 1 else ""
        if "size" in r:
            w, h = r["size"]
            # Its efficiency in its own w × h rectangle, beside the square's.
            own = r["efficiency"] * max(w, h) ** 2 / (w * h)
            atl += f", {w}×{h} atlas, {100 * own:.1f}% of it"
        lines.append(
            f"| {r['mesh']} | {r['method']}{atl} | {r['ms']:.1f} | {fmt(r['check_ms'], 1)} | {r['charts']} | {r['flips']} "
            f"| {r['overlaps_between_charts']} / {r['overlaps_within_charts']} | {100 * r['efficiency']:.1f}% "
            f"| {fmt(r['angle_mean'])} / {fmt(r['angle_max'], 2)} | {fmt(r['area_mean'])} / {fmt(r['area_max'], 2)} |"
        )
    table = "\n".join(lines)
    print(table)
    if args.report:
        os.makedirs(args.report, exist_ok=True)
        pareto_svg(rows, os.path.join(args.report, "unwrap-pareto.svg"))
        command = "python3 tools/xatlas_unwrap.py " + " ".join(sys.argv[1:])
        with open(os.path.join(args.report, "unwrap.md"), "w") as f:
            f.write(
                "# UV unwrapping: barytex beside xatlas\n\n"
                f"Generated by `{command}` (xatlas 0.0.11 from PyPI, default chart options; "
                f"atlas {args.size}×{args.size} texels, padding {args.padding}; median of {args.runs} runs). "
                "Every figure of both tools is measured by the same code (`barytex unwrap --compare-uvs`): "
                "charts are connected pieces of the uv mesh; a flip is a triangle against its chart's majority "
                "orientation or of zero uv area (exact `orient2d`); overlaps are pairs of triangles whose uv "
                "interiors intersect (exact); efficiency is the triangles' uv area over the unit square; distortion "
                "is barytex-uv's (σ1/σ2 for angle, max(ρ, 1/ρ) of the area ratio against the mesh's mean for area; "
                "area-weighted means, 1 is none). Times are ours (weld + charts + pack, the exact checks apart) "
                "against xatlas's add_mesh + generate; only ratios within one run mean anything.\n\n"
                + table
                + "\n\n![angle distortion against time](unwrap-pareto.svg)\n"
            )
        print(f"wrote {args.report}/unwrap.md and unwrap-pareto.svg")


if __name__ == "__main__":
    main()
