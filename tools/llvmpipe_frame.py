#!/usr/bin/env python3
"""Frame time of barytex's unlit renderer beside Mesa's llvmpipe (OpenGL 4.5 on the CPU), on the
same glTF scenes with the same camera, 1 and 2 threads on each side, and the ratio.

    python3 tools/llvmpipe_frame.py [--fixtures DIR] [--barytex BIN] [--frames N] [--rounds R]
                                    [--scenes Avocado Suzanne ...] [--markdown FILE] [--json FILE]

e.g. `python3 tools/llvmpipe_frame.py --frames 5 --rounds 3 --markdown /tmp/peers-llvmpipe.md`
(about a minute on 2 shared cores); `--help` lists every option.

The script makes its own virtual environment (moderngl, numpy, Pillow at the versions of
tools/conformance/requirements.txt) under ~/.cache/barytex/llvmpipe-venv on first use and re-runs
itself there. It needs a release build of barytex (`cargo build --release -p barytex`; default
target/release/barytex) and Mesa's EGL/llvmpipe (Debian: libegl1 libegl-mesa0 libopengl0
libgl1-mesa-dri).

Both sides draw glTF's unlit model (base colour factor × base colour texture × COLOR_0) at
1024×1024 by default, no anti-aliasing, depth test, the same background, textures filtered
trilinearly (barytex `--filter trilinear`; OpenGL LINEAR_MIPMAP_LINEAR after glGenerateMipmap),
with the view and projection barytex prints (`--print-camera`, automatic camera).

- barytex: `barytex render FILE --shading unlit --filter trilinear --aa none --threads T --stats
  --frames 1+N`, one process drawing the prepared scene 1 + N times; the frame is the draw
  (rasterization and shading into barytex's float target, cleared), median of the N warm frames
  after the first, as llvmpipe's are timed after warm-up frames. With `--cold`, one process per
  frame instead (N of them after a warm-up process): the first draw of a process, which touches
  fresh memory (its `raster` + `shade` of the `stages:` line). Load, PNG decode, mips, the
  target's creation (`target`: allocation and the first clear, which touches fresh pages; llvmpipe
  creates its framebuffer with the context, outside its frames) and encode + write are reported
  apart.
- llvmpipe: one subprocess per thread count and round, LP_NUM_THREADS=T set before the context exists;
  scene upload and mip generation are timed apart (each followed by glFinish); the frame is
  clear + draws + glFinish + glReadPixels into memory, median of N frames after warm-up frames.
- Each round measures both sides back to back for each thread count; the ratio is the median of
  the rounds' ratios, with their range, so load that comes and goes shows as a spread.

The glTF reader is tools/conformance/gl_render.py's (the conformance run's), bounded here before
use: files and buffers up to --max-mib, images up to 8192², URIs only under the model's folder,
required extensions only KHR_texture_transform and KHR_materials_unlit; anything else is skipped
with a message. Ratios are barytex ÷ llvmpipe (above 1: barytex is slower); on a machine shared
with other work they are indicative, not exact.
"""

import argparse
import json
import os
import re
import shlex
import statistics
import struct
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from pinned_venv import ensure_venv

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
CONFORMANCE = HERE / "conformance"
VENV = Path.home() / ".cache" / "barytex" / "llvmpipe-venv"
DEFAULT_SCENES = ["Avocado", "Suzanne"]
BACKGROUND_SRGB8 = (118, 118, 124)  # barytex's default background, #76767c, given explicitly
SUPPORTED_REQUIRED = {"KHR_texture_transform", "KHR_materials_unlit"}
MAX_IMAGE_SIDE = 8192


# ---------------------------------------------------------------------------------------------
# Scenes: finding them and bounding them before gl_render reads them


def find_scene(name, fixtures):
    """A path as given, else the fixture folder NAME's glTF/ (or glTF-Binary/) file."""
    p = Path(name)
    if p.suffix in (".gltf", ".glb") and p.is_file():
        return p
    for variant in ("glTF", "glTF-Binary", "glTF-Embedded"):
        found = sorted((fixtures / "gltf" / name / variant).glob("*.gl[tb]*"))
        found = [f for f in found if f.suffix in (".gltf", ".glb")]
        if found:
            return found[0]
    return None


def check_scene(path, max_bytes):
    """None when the file is within bounds and uses only what the GL side draws, else why not."""
    if path.stat().st_size > max_bytes:
        return f"file larger than {max_bytes >> 20} MiB"
    data = path.read_bytes()
    if data[:4] == b"glTF":
        if len(data) < 20:
            return "truncated GLB"
        length, kind = struct.unpack_from("<II", data, 12)
        if kind != 0x4E4F534A or 20 + length > len(data):
            return "GLB without a whole JSON chunk"
        doc = json.loads(data[20 : 20 + length])
    else:
        doc = json.loads(data)
    unsupported = set(doc.get("extensionsRequired", [])) - SUPPORTED_REQUIRED
    if unsupported:
        return f"requires {', '.join(sorted(unsupported))}"
    folder = path.parent.resolve()
    total = 0
    for b in doc.get("buffers", []):
        total += int(b.get("byteLength", 0))
    if total > max_bytes:
        return f"buffers larger than {max_bytes >> 20} MiB"
    for item in doc.get("buffers", []) + doc.get("images", []):
        uri = item.get("uri")
        if uri is None or uri.startswith("data:"):
            continue
        from urllib.parse import unquote

        target = (folder / unquote(uri)).resolve()
        if folder not in target.parents:
            return "a URI outside the model's folder"
        if not target.is_file():
            return "a missing external file"
        if target.stat().st_size > max_bytes:
            return f"an external file larger than {max_bytes >> 20} MiB"
    if not doc.get("meshes"):
        return "no meshes"
    return None


# ---------------------------------------------------------------------------------------------
# barytex side


def barytex_command(binary, scene, size, threads, out, frames=1):
    return [str(binary), "render", str(scene), "--camera", "auto", "--shading", "unlit",
            "--filter", "trilinear", "--aa", "none", "--size", f"{size[0]}x{size[1]}",
            "--threads", str(threads), "--background", ",".join(map(str, BACKGROUND_SRGB8)),
            "--stats", "--print-camera", "--frames", str(frames), "-o", str(out)]


def parse_frames(text):
    """`frames: N, draw … of the first A ms; of the M after it median B ms, min C ms, max D ms`
    → (B, C, D) in ms."""
    m = re.search(r"^frames: .* median ([0-9.]+) ms, min ([0-9.]+) ms, max ([0-9.]+) ms$", text, re.M)
    if m is None:
        raise ValueError("no `frames:` line in barytex's output (is --frames supported?)")
    return tuple(float(v) for v in m.groups())


def parse_stages(text):
    """`stages: load 1.0 ms, decode 2.0 ms, …` → {"load": 1.0, "decode": 2.0, …} in ms."""
    line = next((l for l in text.splitlines() if l.startswith("stages:")), None)
    if line is None:
        raise ValueError("no `stages:` line in barytex's output (is --stats supported?)")
    return {k.strip(): float(v) for k, v in re.findall(r"([a-z][a-z +]*?) ([0-9.]+) ms", line[7:])}


def parse_matrices(text):
    """The view and the OpenGL projection (z in [−w, w]) that `--print-camera` prints, rows as
    printed."""
    import numpy as np

    out = {}
    for title, key in (("view (world", "view"), ("projection (glTF/OpenGL", "projection")):
        if title not in text:
            raise ValueError(f"no `{title}…` block in barytex's --print-camera output")
        lines = text.split(title, 1)[1].splitlines()[1:5]
        out[key] = np.array([[float(v) for v in re.findall(r"-?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?", l)] for l in lines])
        if out[key].shape != (4, 4):
            raise ValueError(f"could not read the {key} matrix")
    return out["view"], out["projection"]


def run_checked(cmd):
    """The command's standard output; its last line of error output as a RuntimeError if it fails."""
    run = subprocess.run(cmd, capture_output=True, text=True)
    if run.returncode != 0:
        raise RuntimeError((run.stderr.strip() or run.stdout.strip() or "failed").splitlines()[-1])
    return run.stdout


def run_barytex(binary, scene, size, threads, runs, out_png, cold=False):
    """Median frame (ms) of `runs` warm frames drawn by one process after its first (`--frames`),
    or with `cold`, of `runs` processes after one warm-up, each drawing one frame (the first frame
    of a process); the stage times, the matrices, the image. `runs` 0: one process, for the
    camera."""
    if runs == 0 or not cold:
        cmd = barytex_command(binary, scene, size, threads, out_png, frames=runs + 1)
        text = run_checked(cmd)
        view, projection = parse_matrices(text)
        if runs == 0:
            return {"view": view.tolist(), "projection": projection.tolist()}
        stages = parse_stages(text)
        median, low, high = parse_frames(text)
        return {"stages": stages, "stage_samples": [stages], "frame_ms": median, "frames_ms": [low, median, high],
                "view": view.tolist(), "projection": projection.tolist(), "stats": text}
    samples = []
    text = ""
    for i in range(runs + 1):
        cmd = barytex_command(binary, scene, size, threads, out_png)
        text = run_checked(cmd)
        stages = parse_stages(text)
        if i > 0:  # the first run warms the file cache and the binary
            samples.append(stages)
    view, projection = parse_matrices(text)
    stages = {k: statistics.median(s[k] for s in samples) for k in samples[0]}
    frames = [s["raster"] + s["shade"] for s in samples]
    return {"stages": stages, "stage_samples": samples, "frame_ms": statistics.median(frames), "frames_ms": frames,
            "view": view.tolist(), "projection": projection.tolist(), "stats": text}


# ---------------------------------------------------------------------------------------------
# llvmpipe side (runs in a subprocess with LP_NUM_THREADS set)


def worker(job_path):
    """Renders every scene of the job with llvmpipe and prints the timings as JSON."""
    import moderngl
    import numpy as np
    from PIL import Image

    sys.path.insert(0, str(CONFORMANCE))
    sys.dont_write_bytecode = True  # no __pycache__ left in the source tree
    import gl_render
    from gl_render import GL_SRGB8_ALPHA8, GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T
    from gl_render import LINEAR, LINEAR_MIPMAP_LINEAR, Gltf, Renderer, instances

    Image.MAX_IMAGE_PIXELS = MAX_IMAGE_SIDE * MAX_IMAGE_SIDE
    GL_FRAMEBUFFER_SRGB = 0x8DB9
    job = json.loads(Path(job_path).read_text())
    size = tuple(job["size"])

    class FrameRenderer(Renderer):
        """gl_render's renderer with a chosen target, forced trilinear filtering and timings."""

        def __init__(self, target):
            self.premultiplied = False
            self.ctx = moderngl.create_standalone_context(backend="egl")
            self.renderer_name = self.ctx.info["GL_RENDERER"]
            self.size = size
            self.prog = self.ctx.program(vertex_shader=gl_render.VERTEX, fragment_shader=gl_render.FRAGMENT)
            import ctypes
            import ctypes.util

            gl = ctypes.CDLL(ctypes.util.find_library("OpenGL") or "libOpenGL.so.0")
            self.bind_texture, self.tex_parameteri = gl.glBindTexture, gl.glTexParameteri
            self.target = target
            if target == "srgb8":
                # An 8-bit sRGB target: blending and writes in linear light, encoded by GL.
                self.colour = self.ctx.texture(size, 4, internal_format=GL_SRGB8_ALPHA8)
                gl.glEnable(GL_FRAMEBUFFER_SRGB)
            else:
                self.colour = self.ctx.texture(size, 4, dtype="f4")
            self.depth = self.ctx.depth_texture(size)
            self.fbo = self.ctx.framebuffer([self.colour], self.depth)
            self.decode_s = self.mips_s = 0.0

        def texture(self, doc, tex_index, cache):
            if tex_index in cache:
                return cache[tex_index]
            t = doc.json["textures"][tex_index]
            sampler = doc.json.get("samplers", [])[t["sampler"]] if "sampler" in t else {}
            started = time.perf_counter()
            rgba = doc.image_rgba(t["source"])
            self.decode_s += time.perf_counter() - started
            if max(rgba.shape[:2]) > MAX_IMAGE_SIDE:
                raise ValueError(f"an image larger than {MAX_IMAGE_SIDE}²")
            tex = self.ctx.texture((rgba.shape[1], rgba.shape[0]), 4, np.ascontiguousarray(rgba).tobytes(),
                                   internal_format=GL_SRGB8_ALPHA8)
            self.ctx.finish()
            started = time.perf_counter()
            tex.build_mipmaps()  # glGenerateMipmap
            self.ctx.finish()
            self.mips_s += time.perf_counter() - started
            tex.filter = (LINEAR_MIPMAP_LINEAR, LINEAR)  # barytex --filter trilinear
            self.bind_texture(GL_TEXTURE_2D, tex.glo)
            self.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, sampler.get("wrapS", 10497))
            self.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, sampler.get("wrapT", 10497))
            cache[tex_index] = tex
            return tex

        def frame(self, order, background):
            """clear + draws + glFinish + readback: the timed frame."""
            self.fbo.use()
            self.fbo.depth_mask = True
            self.fbo.clear(*background, depth=1.0)
            for d in order:
                self.draw(d)
            self.ctx.finish()
            dtype = "f1" if self.target == "srgb8" else "f4"
            return self.fbo.read(components=4, dtype=dtype)

    renderer = FrameRenderer(job["target"])
    bg = gl_render.srgb_decode(np.array([[list(BACKGROUND_SRGB8) + [255]]], np.uint8))[0, 0]
    # Probed first, so that the scenes' glGenerateMipmap times do not include compiling the
    # driver's mip-generation code.
    results = {"renderer": renderer.renderer_name, "scenes": {}, "srgb_mips": probe_srgb_mips(renderer.ctx)}
    for scene in job["scenes"]:
        doc = Gltf(scene["path"])
        view = np.array(scene["view"])
        vp = (np.array(scene["projection"]) @ view).astype(np.float32)
        ctx = renderer.ctx
        ctx.enable(moderngl.DEPTH_TEST)
        ctx.depth_func = "<"
        renderer.prog["vp"].write(vp.T.tobytes())
        renderer.decode_s = renderer.mips_s = 0.0
        textures, draws = {}, []
        started = time.perf_counter()
        for world, mesh in instances(doc):
            for prim in doc.json["meshes"][mesh]["primitives"]:
                draws.append(renderer.prepare(doc, world, view, prim, textures))
        ctx.finish()
        upload_s = time.perf_counter() - started - renderer.decode_s - renderer.mips_s
        # Opaque and masked in scene order, blended back to front (as gl_render and barytex do).
        order = [d for d in draws if not d["blend"]] + sorted((d for d in draws if d["blend"]),
                                                               key=lambda d: d["depth"])
        for _ in range(job["warmup"]):
            renderer.frame(order, bg)
        times = []
        for _ in range(job["frames"]):
            started = time.perf_counter()
            pixels = renderer.frame(order, bg)
            times.append(time.perf_counter() - started)
        if job["target"] == "srgb8":
            img = np.frombuffer(pixels, np.uint8).reshape(size[1], size[0], 4)[::-1, :, :3]
        else:
            linear = np.frombuffer(pixels, np.float32).reshape(size[1], size[0], 4)[::-1, :, :3]
            img = gl_render.srgb_encode(linear)
        Image.fromarray(np.ascontiguousarray(img)).save(scene["png"])
        for d in draws:
            d["vao"].release()
            for b in d["buffers"]:
                b.release()
        for t in textures.values():
            t.release()
        results["scenes"][scene["name"]] = {
            "frame_ms": statistics.median(times) * 1e3, "frames_ms": [t * 1e3 for t in times],
            "upload_ms": upload_s * 1e3, "mips_ms": renderer.mips_s * 1e3, "decode_ms": renderer.decode_s * 1e3,
        }
    print(json.dumps(results))


def probe_srgb_mips(ctx):
    """What glGenerateMipmap does to an sRGB texture on this driver: level 1 of black|white."""
    import numpy as np

    data = np.array([[[0, 0, 0, 255], [255, 255, 255, 255]]] * 2, np.uint8)
    tex = ctx.texture((2, 2), 4, data.tobytes(), internal_format=0x8C43)
    tex.build_mipmaps()
    value = int(np.frombuffer(tex.read(level=1), np.uint8)[0])
    tex.release()
    # sRGB(0.5) = 187.5 (linear light); (0 + 255) / 2 = 127.5 (averaging the stored bytes).
    return {"level1": value, "linear_light": abs(value - 187.5) < abs(value - 127.5)}


def run_llvmpipe(threads, job, tmp):
    job_path = Path(tmp) / f"job-{threads}.json"
    job_path.write_text(json.dumps(job))
    env = dict(os.environ, LP_NUM_THREADS=str(threads))
    run = subprocess.run([sys.executable, str(Path(__file__).resolve()), "--worker", str(job_path)],
                         capture_output=True, text=True, env=env)
    if run.returncode != 0:
        raise RuntimeError(f"llvmpipe worker (LP_NUM_THREADS={threads}) failed:\n{run.stderr.strip()}")
    return json.loads(run.stdout.strip().splitlines()[-1])


# ---------------------------------------------------------------------------------------------
# Comparison and reports


def compare(a_png, b_png, diff_png):
    """Mean absolute difference of the RGB channels (8-bit sRGB), the share of pixels with a
    channel more than 8 apart; writes |a − b| × 4."""
    import numpy as np
    from PIL import Image

    a = np.asarray(Image.open(a_png).convert("RGB")).astype(np.int16)
    b = np.asarray(Image.open(b_png).convert("RGB")).astype(np.int16)
    d = np.abs(a - b)
    Image.fromarray(np.clip(d * 4, 0, 255).astype(np.uint8)).save(diff_png)
    return float(d.mean()), float((d.max(axis=2) > 8).mean())


def same_image(a_png, b_png):
    import numpy as np
    from PIL import Image

    return bool(np.array_equal(np.asarray(Image.open(a_png)), np.asarray(Image.open(b_png))))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--worker", help=argparse.SUPPRESS)
    default_fixtures = os.environ.get("BARYTEX_FIXTURES") or str(ROOT / ".." / "shared" / "fixtures")
    ap.add_argument("--fixtures", default=default_fixtures, help="folder holding gltf/ (default "
                    "$BARYTEX_FIXTURES, else ../shared/fixtures)")
    ap.add_argument("--barytex", default=str(ROOT / "target" / "release" / "barytex"),
                    help="the barytex binary (default target/release/barytex)")
    ap.add_argument("--scenes", nargs="+", default=DEFAULT_SCENES,
                    help="fixture names (gltf/NAME/glTF*/) or .gltf/.glb paths (default: %(default)s)")
    ap.add_argument("--size", default="1024x1024", help="WIDTHxHEIGHT (default %(default)s)")
    ap.add_argument("--threads", default="1,2", help="thread counts on each side (default %(default)s)")
    ap.add_argument("--frames", type=int, default=11, help="timed frames / barytex runs (default %(default)s)")
    ap.add_argument("--rounds", type=int, default=1,
                    help="repeat both sides this many times; the ratio is the median of the rounds' "
                         "ratios, with their range (default %(default)s)")
    ap.add_argument("--cold", action="store_true",
                    help="time barytex's first frame in a process, one process per frame (before 2026-12-04 "
                         "the only way), instead of warm frames drawn by one process with --frames")
    ap.add_argument("--warmup", type=int, default=3, help="llvmpipe frames before timing (default %(default)s)")
    ap.add_argument("--gl-target", choices=["srgb8", "rgba32f"], default="srgb8",
                    help="llvmpipe's colour target: GL_SRGB8_ALPHA8 with GL_FRAMEBUFFER_SRGB, or "
                         "linear RGBA32F read back as floats and encoded afterwards (default %(default)s)")
    ap.add_argument("--out", default="/tmp/llvmpipe-frame", help="folder for the images (default %(default)s)")
    ap.add_argument("--markdown", help="also write the results as a markdown section to this file")
    ap.add_argument("--json", help="also write the rows (scene, threads, frame medians, ratio and its "
                    "range) as JSON to this file (tools/speed_bars.py reads it)")
    ap.add_argument("--max-mib", type=int, default=256, help="largest model file or buffer (default %(default)s)")
    ap.add_argument("--venv", default=str(VENV), help="the virtual environment (default %(default)s)")
    args = ap.parse_args()
    ensure_venv(args.venv, __file__, ["-r", str(CONFORMANCE / "requirements.txt")],
                "moderngl, numpy, Pillow")
    if args.worker:
        return worker(args.worker)

    try:
        size = tuple(int(v) for v in args.size.lower().split("x"))
        threads = [int(t) for t in args.threads.split(",")]
        assert len(size) == 2 and min(size) > 0 and min(threads) > 0 and args.frames > 0 and args.rounds > 0
    except (ValueError, AssertionError):
        sys.exit("--size is WIDTHxHEIGHT, --threads a comma-separated list of counts ≥ 1, --frames and --rounds ≥ 1")
    binary = Path(args.barytex)
    if not binary.is_file():
        sys.exit(f"no barytex binary at {binary} (cargo build --release -p barytex, or --barytex)")
    fixtures, out = Path(args.fixtures), Path(args.out)
    if not (fixtures / "gltf").is_dir() and not all(Path(n).is_file() for n in args.scenes):
        sys.exit(f"no gltf/ folder under {fixtures} (--fixtures DIR or BARYTEX_FIXTURES)")
    out.mkdir(parents=True, exist_ok=True)
    command = "python3 tools/llvmpipe_frame.py " + " ".join(shlex.quote(a) for a in sys.argv[1:])
    version = subprocess.run([str(binary), "--version"], capture_output=True, text=True).stdout.strip()

    # Scenes: bounded, and drawn by barytex once (its camera, and a warm file cache).
    scenes, skipped = [], []
    for name in args.scenes:
        path = find_scene(name, fixtures)
        why = "not found" if path is None else check_scene(path, args.max_mib << 20)
        if why is None:
            try:
                first = run_barytex(binary, path, size, threads[0], 0, out / f"{safe(name)}-barytex-t{threads[0]}.png")
            except (RuntimeError, ValueError) as e:
                why = f"barytex: {e}"
        if why is not None:
            print(f"skipping {name}: {why}", file=sys.stderr)
            skipped.append((name, why))
            continue
        scenes.append({"name": name, "path": str(path), "view": first["view"], "projection": first["projection"]})
    if not scenes:
        sys.exit("no scene to measure")

    # Rounds: both sides back to back for each thread count, so that each round's ratio is
    # measured under about the same load.
    bx = {(s["name"], t): [] for s in scenes for t in threads}  # per round: run_barytex's result
    gl = {t: [] for t in threads}  # per round: the worker's result
    jobs = tempfile.TemporaryDirectory()
    for r in range(args.rounds):
        for t in threads:
            for s in scenes:
                what = f"{args.frames} runs" if args.cold else f"1 + {args.frames} frames"
                print(f"round {r + 1}/{args.rounds}: barytex {s['name']}, --threads {t}, {what} …",
                      file=sys.stderr)
                png = out / f"{safe(s['name'])}-barytex-t{t}.png"
                bx[s["name"], t].append(run_barytex(binary, s["path"], size, t, args.frames, png, args.cold))
            print(f"round {r + 1}/{args.rounds}: llvmpipe, LP_NUM_THREADS={t}, {args.frames} frames …",
                  file=sys.stderr)
            job = {"size": size, "frames": args.frames, "warmup": args.warmup, "target": args.gl_target,
                   "scenes": [{"name": s["name"], "path": s["path"], "view": s["view"],
                               "projection": s["projection"],
                               "png": str(out / f"{safe(s['name'])}-llvmpipe-t{t}.png")} for s in scenes]}
            gl[t].append(run_llvmpipe(t, job, jobs.name))
    jobs.cleanup()

    rows = []
    for s in scenes:
        name = s["name"]
        bx_png = lambda t: out / f"{safe(name)}-barytex-t{t}.png"
        gl_png = lambda t: out / f"{safe(name)}-llvmpipe-t{t}.png"
        mad, over8 = compare(bx_png(threads[0]), gl_png(threads[0]), out / f"{safe(name)}-diff.png")
        stable = all(same_image(bx_png(threads[0]), bx_png(t)) and same_image(gl_png(threads[0]), gl_png(t))
                     for t in threads)
        for t in threads:
            b, g = bx[name, t], [round_[ "scenes"][name] for round_ in gl[t]]
            b_frames = [f for one in b for f in one["frames_ms"]]
            g_frames = [f for one in g for f in one["frames_ms"]]
            ratios = [one_b["frame_ms"] / one_g["frame_ms"] for one_b, one_g in zip(b, g)]
            stage_samples = [st for one in b for st in one["stage_samples"]]
            rows.append({
                "scene": name, "threads": t,
                "bx": statistics.median(b_frames), "bx_range": (min(b_frames), max(b_frames)),
                "gl": statistics.median(g_frames), "gl_range": (min(g_frames), max(g_frames)),
                "ratio": statistics.median(ratios), "ratio_range": (min(ratios), max(ratios)),
                "mad": mad, "over8": over8, "stable": stable,
                "bx_stages": {k: statistics.median(st[k] for st in stage_samples) for k in stage_samples[0]},
                "gl_upload": statistics.median(one["upload_ms"] for one in g),
                "gl_mips": statistics.median(one["mips_ms"] for one in g),
                "gl_decode": statistics.median(one["decode_ms"] for one in g),
            })

    renderer = gl[threads[0]][0]["renderer"]
    mips = gl[threads[0]][0]["srgb_mips"]
    table = render_table(rows)
    print()
    print(f"barytex: {version}; OpenGL: {renderer}; {size[0]}×{size[1]}, {args.frames} frames × "
          f"{args.rounds} round(s); "
          f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} CPUs")
    print("\n".join(table))
    print()
    if len(threads) > 1:
        print("scaling (frame at 1 thread ÷ frame at N):")
        for line in scaling(rows, threads):
            print("  " + line)
    print("\nnot in the frames (ms, medians): ")
    for r in rows:
        st = r["bx_stages"]
        print(f"  {r['scene']}, {r['threads']} thr: barytex load {st.get('load', 0):.1f}, decode "
              f"{st.get('decode', 0):.1f}, mips {st.get('mips', 0):.1f}, target {st.get('target', 0):.1f}, "
              "encode + write "
              f"{st.get('encode + write', 0):.1f}; llvmpipe upload {r['gl_upload']:.1f}, glGenerateMipmap "
              f"{r['gl_mips']:.1f}, PNG decode (Pillow) {r['gl_decode']:.1f}")
    print(f"\nglGenerateMipmap on sRGB: level 1 of black|white = {mips['level1']} "
          f"({'linear-light average' if mips['linear_light'] else 'average of the stored sRGB bytes'})")
    for name, why in skipped:
        print(f"skipped {name}: {why}")
    print(f"images: {out}/<scene>-barytex-t*.png, -llvmpipe-t*.png, -diff.png (|difference| × 4)")
    if args.json:
        keep = ("scene", "threads", "bx", "bx_range", "gl", "gl_range", "ratio", "ratio_range", "mad")
        Path(args.json).write_text(json.dumps({
            "barytex": version, "renderer": renderer, "size": list(size), "frames": args.frames,
            "rounds": args.rounds, "rows": [{k: r[k] for k in keep} for r in rows],
        }, indent=1))
        print(f"wrote {args.json}")
    if args.markdown:
        write_markdown(Path(args.markdown), rows, threads, table, command, version, renderer, size, args, mips,
                       skipped)
        print(f"wrote {args.markdown}")


def safe(name):
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", Path(name).stem if name.endswith((".gltf", ".glb")) else name)


def render_table(rows):
    lines = ["| scene | threads | barytex frame ms | llvmpipe frame ms | ratio | mean abs. diff (sRGB8) "
             "| px > 8 apart |",
             "|---|---:|---:|---:|---:|---:|---:|"]
    span = lambda lo_hi: f"({lo_hi[0]:.0f}–{lo_hi[1]:.0f})"
    for r in rows:
        lo, hi = r["ratio_range"]
        ratio = f"{r['ratio']:.2f}×" + (f" ({lo:.2f}–{hi:.2f})" if hi > lo else "")
        lines.append(f"| {r['scene']} | {r['threads']} | {r['bx']:.1f} {span(r['bx_range'])} | {r['gl']:.1f} "
                     f"{span(r['gl_range'])} | {ratio} | {r['mad']:.3f} | {100 * r['over8']:.2f} % |")
    return lines


def scaling(rows, threads):
    out = []
    for name in dict.fromkeys(r["scene"] for r in rows):
        by = {r["threads"]: r for r in rows if r["scene"] == name}
        for t in threads[1:]:
            out.append(f"{name}, {t} threads: barytex {by[threads[0]]['bx'] / by[t]['bx']:.2f}×, "
                       f"llvmpipe {by[threads[0]]['gl'] / by[t]['gl']:.2f}×")
    return out


def write_markdown(path, rows, threads, table, command, version, renderer, size, args, mips, skipped):
    stable = all(r["stable"] for r in rows)
    lines = [
        f"## Unlit trilinear frame, {size[0]}×{size[1]}, vs Mesa llvmpipe (`tools/llvmpipe_frame.py`)",
        "",
        f"`{command}` — {time.strftime('%Y-%m-%d', time.gmtime())}, barytex {version.split()[-1]}, "
        f"OpenGL {renderer}, {os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.1f} at the end.",
        "",
        "Same scene, automatic camera (barytex's printed view and projection on both sides), unlit, "
        "trilinear, no anti-aliasing, depth test, background #76767c. barytex frame: "
        + (f"`raster` + `shade` of `--stats` ({args.frames} processes per round, `--threads N`, `--cold`)"
           if args.cold else
           f"the draw (raster + shade) of `--frames {args.frames + 1}`, median of the {args.frames} warm frames "
           "after the first (one process per round, `--threads N`)")
        + "; llvmpipe frame: clear + "
        f"draws + glFinish + glReadPixels into a {'GL_SRGB8_ALPHA8' if args.gl_target == 'srgb8' else 'RGBA32F'} "
        f"target ({args.frames} frames per round after {args.warmup} warm-up, `LP_NUM_THREADS=N`); "
        f"{args.rounds} round(s), each measuring both sides back to back. Frame times are medians over "
        "all rounds (min–max in brackets); ratio: barytex ÷ llvmpipe, the median of the rounds' "
        "ratios of medians (their range in brackets; above 1: barytex slower). Mean absolute difference over every "
        "pixel's RGB, 8-bit sRGB, as a check that both draw the same picture.",
        "",
    ] + table + [
        "",
    ] + ([
        "Scaling, frame at 1 thread ÷ frame at N: " + "; ".join(scaling(rows, threads)) + ".",
        "",
    ] if len(threads) > 1 else []) + [
        "Outside the frames (medians, ms): " + "; ".join(
            f"{r['scene']} ({r['threads']} thr) barytex load {r['bx_stages'].get('load', 0):.1f}, decode "
            f"{r['bx_stages'].get('decode', 0):.1f}, mips {r['bx_stages'].get('mips', 0):.1f}, target "
            f"{r['bx_stages'].get('target', 0):.1f}, encode + write "
            f"{r['bx_stages'].get('encode + write', 0):.1f}, llvmpipe upload {r['gl_upload']:.1f}, "
            f"glGenerateMipmap {r['gl_mips']:.1f}" for r in rows) + ".",
        "",
        "Notes: the machine is shared with other work, so absolute times move between runs and the "
        "ratios are indicative, not exact. llvmpipe's LP_NUM_THREADS counts rasterizer threads; "
        "vertex processing and setup run on the calling thread besides them. The barytex frame "
        "excludes the encode to 8 bits (reported apart); the llvmpipe frame includes the write "
        "to its target and the readback. "
        + ("Each barytex frame is the only one of its process: the " if args.cold else
           "Each barytex frame draws into a new target: the ")
        + "target's creation (allocation, and the clear that first touches its pages) is reported "
        "apart as `target`, as llvmpipe creates its framebuffer with the context; llvmpipe's frames "
        "are warm frames reusing its framebuffer and compiled shaders and include a clear. Mips differ: barytex filters premultiplied alpha in linear "
        "light, correctly rounded; glGenerateMipmap on this driver averages "
        + ("in linear light" if mips["linear_light"] else "the stored sRGB bytes (not linear light)")
        + f" (level 1 of black|white: {mips['level1']}) with straight alpha (the scenes here are opaque). "
        "llvmpipe's level of detail comes from finite differences over 2×2 quads, barytex's from exact "
        "per-pixel derivatives. `--stats` makes barytex draw once more with a constant shader to time "
        "rasterization; that pass is outside its frame. "
        + ("Each side drew identical images at every thread count." if stable else
           "**Some images differ between thread counts on one side.**"),
    ]
    if skipped:
        lines += ["", "Skipped: " + "; ".join(f"{n} ({w})" for n, w in skipped) + "."]
    path.write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
