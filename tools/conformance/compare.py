"""Renders every fixture with barytex and with llvmpipe (gl_render.py), compares the two images
and writes docs/CONFORMANCE.md with side-by-side pictures of the fixtures below the bar.

Run it through run.sh, which makes the virtual environment.
"""

import argparse
import math
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
from PIL import Image

from gl_render import Gltf, Renderer, instances, srgb_encode

SIZE = 256
BACKGROUND = (0.18, 0.18, 0.2, 1.0)  # RenderOptions::default (crates/barytex-render/src/options.rs)
BAR_DB = 40.0
COMMAND = ["render", None, "--camera", "auto", "--shading", "unlit", "--aa", "none", "--filter", "file",
           "--size", f"{SIZE}x{SIZE}", "--print-camera", "-o", None]

# Differences that are conventions of barytex's, not defects: fixture → why (shown in the doc).
CONVENTIONS = {
}


PREMULTIPLIED = (
    "barytex filters textures on premultiplied alpha in linear light (its texture crate's "
    "convention, docs/CONVENTIONS.md's texture row, which keeps the colour of transparent texels out "
    "of the filter); OpenGL filters the "
    "stored straight-alpha texels (OpenGL 4.6 §8.14, §8.15: the filter weights the texel values as "
    "stored, after sRGB decoding, §8.24), so the colour of transparent texels bleeds into edges. With "
    "the reference's textures uploaded premultiplied in linear light (RGBA32F, divided by alpha after "
    "sampling), PSNR∪ rises to {premul} dB and the file passes the bar.")
VACUOUS = ("Nothing is covered in either image: the automatic camera looks from +Z along a plane "
           "that lies in y = 0 through the eye, so every triangle is edge-on (zero area) in both. The "
           "fixture tests nothing under this camera.")


def matrices(text):
    """The view and OpenGL projection matrices from `--print-camera` (rows as printed)."""
    blocks = {}
    for title, key in (("view (world", "view"), ("projection (glTF/OpenGL", "projection_gl")):
        lines = text.split(title, 1)[1].splitlines()[1:5]
        blocks[key] = np.array([[float(v) for v in re.findall(r"-?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?", line)] for line in lines])
    return blocks["view"], blocks["projection_gl"]


def auto_camera(path):
    """README's automatic camera, recomputed independently for an aspect of 1: bounds of the
    world-space vertices of every primitive, r = half the diagonal, d = r / sin(22.5°)."""
    doc = Gltf(path)
    pts = []
    for world, mesh in instances(doc):
        for prim in doc.json["meshes"][mesh]["primitives"]:
            p = doc.accessor(prim["attributes"]["POSITION"]).astype(np.float64)
            pts.append(p @ world[:3, :3].T + world[:3, 3])
    pts = np.vstack(pts)
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    r = np.linalg.norm(hi - lo) / 2 or 1.0
    d = r / math.sin(math.radians(22.5))
    view = np.eye(4)
    view[:3, 3] = -((lo + hi) / 2 + [0, 0, d])
    n, f, t = d / 100, d * 100, 1 / math.tan(math.radians(22.5))
    proj = np.array([[t, 0, 0, 0], [0, t, 0, 0], [0, 0, (f + n) / (n - f), 2 * f * n / (n - f)], [0, 0, -1, 0]])
    return view, proj


def coverage(img, bg):
    return np.any(img != bg, axis=2)


def neighbourhood_any(mask):
    """Whether each pixel's 3×3 neighbourhood (itself included) holds a True."""
    p = np.pad(mask, 1)
    h, w = mask.shape
    return np.any([p[dy : dy + h, dx : dx + w] for dy in range(3) for dx in range(3)], axis=0)


def compare(bx, gl, bg):
    """Coverage mismatch, whether it lies only along silhouettes, and PSNR over the union of
    covered pixels and over the pixels both cover."""
    cb, cg = coverage(bx, bg), coverage(gl, bg)
    mismatch = cb ^ cg
    # A mismatched pixel is on a silhouette when, within 1 px, the renderer that covers it also
    # leaves a pixel uncovered and the one that does not cover it covers a pixel: both images
    # have a coverage boundary there.
    edge = np.where(cb, neighbourhood_any(~cb) & neighbourhood_any(cg), neighbourhood_any(~cg) & neighbourhood_any(cb))
    off_edge = int((mismatch & ~edge).sum())

    def psnr(mask):
        if not mask.any():
            return None
        err = (bx[mask].astype(np.float64) - gl[mask]) ** 2
        mse = err.mean()
        return math.inf if mse == 0 else 10 * math.log10(255**2 / mse)

    return {
        "covered": int((cb | cg).sum()), "mismatch": int(mismatch.sum()), "off_edge": off_edge,
        "psnr": psnr(cb | cg), "psnr_both": psnr(cb & cg),
        "max_diff": int(np.abs(bx.astype(int) - gl).max()),
        "over_8": int((np.abs(bx.astype(int) - gl).max(axis=2)[cb & cg] > 8).sum()),
    }


def side_by_side(bx, gl, bg, path):
    """barytex | llvmpipe | |difference| × 4, coverage mismatch in magenta."""
    diff = np.clip(np.abs(bx.astype(int) - gl) * 4, 0, 255).astype(np.uint8)
    diff[coverage(bx, bg) ^ coverage(gl, bg)] = (255, 0, 255)
    gap = np.full((SIZE, 4, 3), 255, np.uint8)
    Image.fromarray(np.hstack([bx, gap, gl, gap, diff])).save(path, optimize=True)


def fmt_db(v):
    return "—" if v is None else ("∞" if v == math.inf else f"{v:.1f}")


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--fixtures", required=True, help="folder holding gltf/")
    ap.add_argument("--barytex", required=True)
    ap.add_argument("--doc", required=True)
    ap.add_argument("--images", required=True)
    args = ap.parse_args()
    root = Path(args.fixtures) / "gltf"
    files = sorted(p for p in root.glob("*/glTF*/*") if p.suffix in (".gltf", ".glb"))
    if not files:
        sys.exit(f"no glTF files under {root}/*/glTF*/")
    renderer = Renderer((SIZE, SIZE))
    if "llvmpipe" not in renderer.renderer_name:
        sys.exit(f"expected Mesa llvmpipe, got {renderer.renderer_name}")
    bg = srgb_encode(np.array(BACKGROUND[:3]))
    images = Path(args.images)
    images.mkdir(parents=True, exist_ok=True)
    for old in images.glob("*.png"):
        old.unlink()
    version = subprocess.run([args.barytex, "--version"], capture_output=True, text=True).stdout.strip()
    rows, started = [], time.time()
    with tempfile.TemporaryDirectory() as tmp:
        for i, f in enumerate(files):
            name = f"{f.parent.parent.name}/{f.parent.name}"
            out = Path(tmp) / f"{i}.png"
            cmd = [args.barytex] + [str(f) if c is None and k == 1 else str(out) if c is None else c
                                    for k, c in enumerate(COMMAND)]
            run = subprocess.run(cmd, capture_output=True, text=True)
            row = {"name": name, "model": f.parent.parent.name}
            if run.returncode != 0:
                row["error"] = (run.stderr.strip() or run.stdout.strip()).splitlines()[-1]
                rows.append(row)
                print(f"{name}: barytex failed: {row['error']}")
                continue
            view, proj = matrices(run.stdout)
            spec_view, spec_proj = auto_camera(f)
            row["camera_err"] = max(np.abs(view - spec_view).max() / max(1, np.abs(spec_view).max()),
                                    np.abs(proj - spec_proj).max() / max(1, np.abs(spec_proj).max()))
            bx = np.asarray(Image.open(out).convert("RGB"))
            gl = srgb_encode(renderer.render(f, view, proj, BACKGROUND))
            row.update(compare(bx, gl, bg))
            # The same with textures filtered as barytex filters them: premultiplied, linear light.
            renderer.premultiplied = True
            premul = compare(bx, srgb_encode(renderer.render(f, view, proj, BACKGROUND)), bg)
            renderer.premultiplied = False
            row["psnr_premul"] = premul["psnr"]
            passes = lambda c: c["psnr"] is not None and c["psnr"] >= BAR_DB and c["off_edge"] == 0
            if row["psnr"] is None:
                row["verdict"] = "vacuous"
            elif passes(row):
                row["verdict"] = "pass"
            elif row["model"] in CONVENTIONS:
                row["verdict"] = "convention"
            elif passes(premul):
                row["verdict"] = "convention"
                row["why"] = PREMULTIPLIED
            else:
                row["verdict"] = "**below**"
            if row["verdict"] not in ("pass", "vacuous"):
                # One picture per model (its variants hold the same scene).
                row["picture"] = f"{row['model']}.png".replace(" ", "_")
                if not (images / row["picture"]).exists():
                    side_by_side(bx, gl, bg, images / row["picture"])
            rows.append(row)
            print(f"{name}: PSNR {fmt_db(row['psnr'])} dB (both covered {fmt_db(row['psnr_both'])}), "
                  f"coverage mismatch {row['mismatch']} px ({row['off_edge']} off silhouettes), {row['verdict']}")
    write_doc(Path(args.doc), rows, renderer.renderer_name, version, time.time() - started)


def write_doc(path, rows, gl_name, version, seconds):
    passed = sum(r.get("verdict") == "pass" for r in rows)
    conv = sum(r.get("verdict") == "convention" for r in rows)
    vacuous = sum(r.get("verdict") == "vacuous" for r in rows)
    lines = [
        "# Conformance against OpenGL (Mesa llvmpipe)",
        "",
        "<!-- Generated by tools/conformance/run.sh; do not edit by hand. -->",
        "",
        "Regenerate with `tools/conformance/run.sh [FIXTURES]` after `cargo build --release -p barytex`",
        "(FIXTURES holds the Khronos glTF sample models' `gltf/` folder; default `$BARYTEX_FIXTURES`,",
        "else `../shared/fixtures`). It renders every `gltf/*/glTF*/*.gltf|glb` twice at "
        f"{SIZE}×{SIZE}:",
        "",
        f"- **barytex** ({version}): `barytex render FILE --camera auto --shading unlit --aa none "
        f"--filter file --size {SIZE}x{SIZE} --print-camera`;",
        f"- **OpenGL** ({gl_name}, through moderngl): `tools/conformance/gl_render.py`, a small glTF",
        "  loader drawing glTF's unlit model (base colour factor × base colour texture × COLOR_0; glTF 2.0",
        "  §3.9.2 and KHR_materials_unlit) with the matrices barytex printed, sRGB textures decoded by",
        "  the texture unit (`GL_SRGB8_ALPHA8`, OpenGL 4.6 §8.24), the file's sampler (mipmaps by",
        "  `glGenerateMipmap` when the min filter uses them; undefined filters: linear / linear-mipmap-linear),",
        "  KHR_texture_transform, alpha modes (MASK discards below the cutoff, BLEND is",
        "  `GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA` after the opaque draws, back to front), back-face",
        "  culling unless doubleSided (winding reversed under a negative determinant, §3.7.4), into a",
        "  linear RGBA32F target cleared to barytex's background (0.18, 0.18, 0.2), sRGB-encoded on the CPU.",
        "",
        "Coverage: a pixel is covered when it differs from the background. A coverage mismatch is a pixel",
        "covered in one image only; it lies *along a silhouette* when, within 1 px (its 3×3 neighbourhood),",
        "both images have a coverage boundary. PSNR (8-bit sRGB, RGB) is over the union of covered pixels",
        "(∪) and, to separate shading from coverage, over the pixels both cover (∩). *PSNR∪ premul.*: the",
        "same, with the reference filtering textures as barytex does (premultiplied alpha, linear light).",
        "*>8*: pixels both cover whose channels differ by more than 8/255. *camera*: the largest",
        "difference between the matrices barytex printed and README's automatic camera recomputed here,",
        "relative to the largest",
        "entry (the printout has 6 decimals).",
        "",
        f"**The bar:** PSNR∪ ≥ {BAR_DB:.0f} dB and coverage differing only along silhouettes, or a",
        "documented, justified convention difference.",
        "",
        f"**Result:** {passed} of {len(rows)} files pass, {conv} differ by a documented convention, "
        f"{vacuous} cover nothing in either image, {len(rows) - passed - conv - vacuous} are below the bar "
        f"(run took {seconds:.0f} s).",
        "",
        "| fixture | PSNR∪ dB | PSNR∩ dB | PSNR∪ premul. dB | >8 px | coverage mismatch px | off silhouettes px "
        "| edge-only | camera | verdict |",
        "|---|---:|---:|---:|---:|---:|---:|:---:|---:|---|",
    ]
    for r in rows:
        if "error" in r:
            lines.append(f"| {r['name']} | — | — | — | — | — | — | — | — | barytex failed: {r['error']} |")
            continue
        verdict = r["verdict"] + (f" ([diff](conformance/{r['picture']}))" if "picture" in r else "")
        lines.append(
            f"| {r['name']} | {fmt_db(r['psnr'])} | {fmt_db(r['psnr_both'])} | {fmt_db(r['psnr_premul'])} | "
            f"{r['over_8']} | {r['mismatch']} | "
            f"{r['off_edge']} | {'yes' if r['off_edge'] == 0 else 'no'} | {r['camera_err']:.1e} | {verdict} |")
    failing = [r for r in rows if r.get("verdict") not in ("pass", None)]
    lines += ["", "## Below the bar, and conventions", "",
              "Pictures: barytex | llvmpipe | absolute difference × 4 with coverage mismatches in magenta.", ""]
    notes = Path(__file__).with_name("notes.md")
    explained = parse_notes(notes.read_text()) if notes.exists() else {}
    for model in dict.fromkeys(r["model"] for r in failing):
        group = [r for r in failing if r["model"] == model]
        r = group[0]
        why = CONVENTIONS.get(model) or r.get("why", "").format(premul=fmt_db(r["psnr_premul"]))
        if r["verdict"] == "vacuous":
            why = VACUOUS
        variants = ", ".join(g["name"].split("/", 1)[1] for g in group)
        lines += [f"### {model} ({variants}) — {r['verdict']}", ""]
        for text in [t for t in (why, explained.get(model)) if t] or ["*Not yet explained.*"]:
            lines += [text, ""]
        if "picture" in r:
            lines += [f"![{model}](conformance/{r['picture']})", ""]
    for title in ("Findings", "Not covered"):
        if title in explained:
            lines += [f"## {title}", "", explained[title], ""]
    path.write_text("\n".join(lines) + "\n")


def parse_notes(text):
    """`## Model` sections of notes.md → their text (the hand-written explanations)."""
    out = {}
    for block in text.split("\n## ")[1:]:
        title, _, body = block.partition("\n")
        out[title.strip()] = body.strip()
    return out


if __name__ == "__main__":
    main()
