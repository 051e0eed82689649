#!/usr/bin/env python3
"""Writes the hand-made seed inputs of the fuzz targets into fuzz/regressions/<target>/.

Run from the repository root: `python3 tools/gen_fuzz_seeds.py` (needs Pillow for the PNG and
JPEG seeds). The output is deterministic; the byte layouts are documented in
tests/src/fuzz_inputs/<target>.rs. Existing seeds of the same name are overwritten, other files
are left alone.
"""

import base64
import io
import json
import math
import os
import struct

from PIL import Image

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
REG = os.path.join(ROOT, "fuzz", "regressions")


def write(target, name, data):
    os.makedirs(os.path.join(REG, target), exist_ok=True)
    if isinstance(data, str):
        data = data.encode()
    with open(os.path.join(REG, target, name), "wb") as f:
        f.write(data)


def f32(*xs):
    return b"".join(struct.pack("<f", x) for x in xs)


def u32(*xs):
    return b"".join(struct.pack("<I", x) for x in xs)


# ---------------------------------------------------------------------------------------------
# Images (png_jpeg_loader, and embedded in the glTF seeds)


def checker(w, h, mode):
    img = Image.new("RGBA", (w, h))
    for y in range(h):
        for x in range(w):
            on = (x + y) % 2 == 0
            img.putpixel((x, y), (230, 40, 40, 255) if on else (30, 30, 200, 128))
    return img.convert(mode)


def encode(img, fmt, **kw):
    out = io.BytesIO()
    img.save(out, fmt, **kw)
    return out.getvalue()


def image_seeds():
    t = "png_jpeg_loader"
    write(t, "seed-rgba8.png", encode(checker(4, 4, "RGBA"), "PNG"))
    write(t, "seed-rgb8.png", encode(checker(5, 3, "RGB"), "PNG"))
    write(t, "seed-gray8.png", encode(checker(3, 5, "L"), "PNG"))
    write(t, "seed-gray-alpha.png", encode(checker(2, 2, "LA"), "PNG"))
    write(t, "seed-palette.png", encode(checker(4, 4, "RGB").convert("P"), "PNG"))
    write(t, "seed-1bit.png", encode(checker(8, 2, "1"), "PNG"))
    write(t, "seed-gray16.png", encode(checker(3, 3, "L").convert("I;16"), "PNG"))
    write(t, "seed-64x64.png", encode(checker(64, 64, "RGB"), "PNG", optimize=True))
    write(t, "seed-65x1-over-limit.png", encode(checker(65, 1, "RGB"), "PNG"))
    write(t, "seed-baseline.jpg", encode(checker(8, 8, "RGB"), "JPEG", quality=80))
    write(t, "seed-gray.jpg", encode(checker(8, 8, "L"), "JPEG", quality=80))
    write(t, "seed-progressive.jpg",
          encode(checker(16, 8, "RGB"), "JPEG", quality=70, progressive=True))
    write(t, "seed-420.jpg", encode(checker(16, 16, "RGB"), "JPEG", quality=60, subsampling=2))
    write(t, "seed-truncated.png", encode(checker(4, 4, "RGBA"), "PNG")[:40])


# ---------------------------------------------------------------------------------------------
# glTF (gltf_loader)


class Bin:
    """A glTF binary buffer with its buffer views and accessors."""

    def __init__(self):
        self.data = bytearray()
        self.views = []
        self.accessors = []

    def view(self, payload, target=None):
        while len(self.data) % 4:
            self.data.append(0)
        v = {"buffer": 0, "byteOffset": len(self.data), "byteLength": len(payload)}
        if target:
            v["target"] = target
        self.data += payload
        self.views.append(v)
        return len(self.views) - 1

    def accessor(self, payload, ctype, count, typ, minmax=None, target=None):
        a = {"bufferView": self.view(payload, target), "componentType": ctype,
             "count": count, "type": typ}
        if minmax:
            a["min"], a["max"] = minmax
        self.accessors.append(a)
        return len(self.accessors) - 1


def scene_document(b, png, uri_images):
    quad_pos = [-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0]
    pos = b.accessor(f32(*quad_pos), 5126, 4, "VEC3", ([-1, -1, 0], [1, 1, 0]), 34962)
    nrm = b.accessor(f32(*[0, 0, 1] * 4), 5126, 4, "VEC3", None, 34962)
    uv = b.accessor(f32(0, 1, 1, 1, 1, 0, 0, 0), 5126, 4, "VEC2", None, 34962)
    idx = b.accessor(struct.pack("<6H", 0, 1, 2, 0, 2, 3), 5123, 6, "SCALAR", None, 34963)
    tri = b.accessor(f32(0, 0, 0.5, 1.5, 0, -0.5, 0, 1.5, 0.2), 5126, 3, "VEC3",
                     ([0, 0, -0.5], [1.5, 1.5, 0.5]))
    # A sparse accessor: base positions of the triangle, vertex 1 moved.
    sp_idx = b.view(struct.pack("<H", 1) + b"\0\0")
    sp_val = b.view(f32(2, 0, 0))
    b.accessors.append({"bufferView": b.accessors[tri]["bufferView"], "componentType": 5126,
                        "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [2, 1.5, 0.5],
                        "sparse": {"count": 1,
                                   "indices": {"bufferView": sp_idx, "componentType": 5123},
                                   "values": {"bufferView": sp_val}}})
    sparse = len(b.accessors) - 1
    if uri_images:
        image = {"uri": "data:image/png;base64," + base64.b64encode(png).decode()}
    else:
        image = {"bufferView": b.view(png), "mimeType": "image/png"}
    lights = [
        {"type": "point", "color": [1, 0.9, 0.8], "intensity": 20, "range": 10},
        {"type": "spot", "intensity": 40,
         "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.6}},
        {"type": "directional", "color": [0.3, 0.3, 0.5], "intensity": 1.5},
    ]
    doc = {
        "asset": {"version": "2.0"},
        "extensionsUsed": ["KHR_lights_punctual", "KHR_texture_transform"],
        "extensions": {"KHR_lights_punctual": {"lights": lights}},
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 2, 3, 4, 5, 6]}],
        "nodes": [
            {"mesh": 0, "rotation": [0.1, 0.2, 0, math.sqrt(1 - 0.05)]},
            {"mesh": 1, "translation": [0, 0, -1], "scale": [1, 1, -1]},
            {"camera": 0, "translation": [0.3, 0.2, 3.5]},
            {"camera": 1, "translation": [0, 0, 5]},
            {"extensions": {"KHR_lights_punctual": {"light": 0}}, "translation": [1, 1, 2]},
            {"extensions": {"KHR_lights_punctual": {"light": 1}}, "translation": [0, 0, 3]},
            {"extensions": {"KHR_lights_punctual": {"light": 2}},
             "rotation": [-0.38268343, 0, 0, 0.9238795]},
        ],
        "cameras": [
            {"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1, "zfar": 50}},
            {"type": "orthographic",
             "orthographic": {"xmag": 2, "ymag": 1.5, "znear": 0.1, "zfar": 20}},
        ],
        "meshes": [
            {"primitives": [{"attributes": {"POSITION": pos, "NORMAL": nrm, "TEXCOORD_0": uv},
                             "indices": idx, "material": 0}]},
            {"primitives": [{"attributes": {"POSITION": sparse}, "material": 1},
                            {"attributes": {"POSITION": tri}, "mode": 4}]},
        ],
        "materials": [
            {"pbrMetallicRoughness": {
                "baseColorTexture": {"index": 0, "extensions": {"KHR_texture_transform": {
                    "offset": [0.25, 0], "rotation": 0.3, "scale": [3, 2]}}},
                "roughnessFactor": 0.3}},
            {"pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.8, 0.3, 0.7]},
             "emissiveFactor": [0.1, 0, 0.2], "alphaMode": "BLEND", "doubleSided": True},
        ],
        "textures": [{"source": 0, "sampler": 0}],
        "samplers": [{"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 33648}],
        "images": [image],
        "bufferViews": b.views,
        "accessors": b.accessors,
    }
    return doc


def gltf_seeds():
    png = encode(checker(4, 4, "RGBA"), "PNG")
    # GLB: the image in a buffer view of the binary chunk.
    b = Bin()
    doc = scene_document(b, png, uri_images=False)
    while len(b.data) % 4:
        b.data.append(0)
    doc["buffers"] = [{"byteLength": len(b.data)}]
    js = json.dumps(doc, separators=(",", ":")).encode()
    while len(js) % 4:
        js += b" "
    body = struct.pack("<I4s", len(js), b"JSON") + js
    body += struct.pack("<I4s", len(b.data), b"BIN\0") + bytes(b.data)
    write("gltf_loader", "seed-textured-lights.glb",
          struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body)
    # glTF: everything in data URIs.
    b = Bin()
    doc = scene_document(b, png, uri_images=True)
    doc["buffers"] = [{"byteLength": len(b.data), "uri":
                       "data:application/octet-stream;base64,"
                       + base64.b64encode(bytes(b.data)).decode()}]
    write("gltf_loader", "seed-textured-lights.gltf", json.dumps(doc, separators=(",", ":")))


# ---------------------------------------------------------------------------------------------
# Byte layouts of the other new targets


def render_options_seeds():
    t = "render_options"
    fog = lambda d: f32(d)

    def opts(w, h, cam, shading, filt, probes, aa, n, flags, bg=(46, 46, 51, 255),
             fogc=(46, 46, 51), density=0.1):
        return bytes([w, h, cam, shading, filt, probes, aa, n, flags, *bg, *fogc]) + fog(density)

    write(t, "seed-default", opts(16, 12, 0, 3, 0, 0, 0, 0, 0))
    write(t, "seed-msaa4-aniso8-fog", opts(24, 16, 0, 3, 4, 8, 3, 4, 1))
    write(t, "seed-supersample6-trilinear", opts(8, 8, 1, 2, 3, 0, 1, 6, 0))
    write(t, "seed-jitter3-ewa-hybrid", opts(20, 10, 2, 4, 5, 0, 2, 3, 5))
    write(t, "seed-adaptive-flat-viewdepth-fog", opts(12, 12, 0, 1, 1, 0, 4, 8, 3))
    write(t, "seed-unlit-bilinear-1x64", opts(1, 64, 0, 0, 2, 0, 0, 0, 0))
    write(t, "seed-zero-width", opts(0, 5, 0, 3, 0, 0, 0, 0, 0))
    write(t, "seed-no-such-camera", opts(4, 4, 3, 3, 0, 0, 0, 0, 0))
    write(t, "seed-msaa3-invalid", opts(4, 4, 0, 3, 0, 0, 3, 3, 0))
    write(t, "seed-supersample17-invalid", opts(4, 4, 0, 3, 0, 0, 1, 17, 0))
    write(t, "seed-fog-nan-density", opts(6, 6, 0, 3, 0, 0, 0, 0, 1) [:-4] + u32(0x7fc00001))
    write(t, "seed-fog-inf-density", opts(6, 6, 0, 0, 0, 0, 0, 0, 1, density=math.inf))


def textures_3d_seeds():
    t = "textures_3d"

    def inp(filters, modes, kind, sizes, dir, ddx, ddy, lod, layer, ref, bias=0.0, lmin=0.0,
            texels=b""):
        return bytes([filters, modes, kind, sizes]) + f32(*dir, *ddx, *ddy, lod, layer, ref,
                                                          bias, lmin) + texels

    z3 = (0, 0, 0)
    write(t, "seed-cube-edge-linear", inp(0x05, 0, 0x38, 0x04, (1, 0, 1), z3, z3, 0, 0, 0.5))
    write(t, "seed-cube-corner-cubic", inp(0x1a, 0, 0x33, 0x07, (1, 1, 1), (0.1, 0, 0),
                                           (0, 0.1, 0), 1.5, 1.4, 0.25))
    write(t, "seed-zero-direction", inp(0x05, 0, 0x08, 0, z3, z3, z3, 0, 0, 0))
    write(t, "seed-ewa-anisotropic", inp(0x75, 0x3f, 0x75, 0x06, (0.3, 0.9, -0.2),
                                         (2, 0, 0), (0, 0.01, 0), 0, 2.5, 0.5))
    write(t, "seed-border-mirror-volume", inp(0x01, 0xbb, 0x72, 0x03, (1.2, -0.3, 0.5), z3, z3,
                                              0, -1, 1.0, texels=bytes(range(0, 256, 3))))
    write(t, "seed-nan-inf", inp(0x15, 0x15, 0x74, 0x05, (math.nan, 1, 0), (math.inf, 0, 0),
                                 z3, math.nan, math.inf, math.nan, math.inf, math.nan))
    write(t, "seed-huge-coordinates", inp(0x15, 0x15, 0x66, 0x07, (3e38, -3e38, 1e30),
                                          (1e30, 0, 0), (0, 1e-30, 0), 1e30, -1e30, 1e38))


def interp_3d_seeds():
    t = "interp_3d"

    def raw(p, a, b, c, d, mode=0):
        return f32(*p, *a, *b, *c, *d) + bytes([mode])

    z = (0, 0, 0)
    write(t, "seed-unit-triangle", raw((0.25, 0.25, 1), (0, 0, 0), (1, 0, 0), (1, 1, 0),
                                       (0, 1, 0)))
    write(t, "seed-saddle", raw((0.5, 0.5, 0.25), (0, 0, 0), (1, 0, 0), (1, 1, 1), (0, 1, 0)))
    write(t, "seed-collinear", raw((1, 1, 1), (0, 0, 0), (1, 1, 1), (2, 2, 2), (3, 0, 0)))
    write(t, "seed-sliver", raw((0.5, 1e-7, 0), (0, 0, 0), (1, 0, 0), (0.5, 1e-7, 0),
                                (0, 1, 0)))
    write(t, "seed-nan", raw((math.nan, 0, 0), z, (1, 0, 0), (0, 1, 0), (1, 1, 0)))
    write(t, "seed-inf-corner", raw(z, (math.inf, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0)))
    write(t, "seed-huge", raw((1e38, 1e38, 0), (-3e38, -3e38, 0), (3e38, -3e38, 0),
                              (3e38, 3e38, 1e38), (-3e38, 3e38, 0)))
    write(t, "seed-tiny", raw((1e-45, 1e-45, 0), z, (1e-40, 0, 0), (1e-40, 1e-40, 1e-42),
                              (0, 1e-40, 0)))
    write(t, "seed-parallel-diagonals", raw((0.5, 0, 0), z, (1, 0, 0), (2, 0, 0), (3, 0, 1e-30)))

    def grid(p_bytes, corners, k=16):
        # Kind 1: corners from the low byte of words 3..14; alpha, beta from bytes 0 and 4.
        words = [0] * 15
        words[0], words[1] = p_bytes
        for i, v in enumerate(corners):
            words[3 + i] = v & 0xff
        return u32(*words) + bytes([(k << 3) | 1])

    write(t, "seed-grid-saddle", grid((3, 11), [0, 0, 0, 4, 0, 0, 4, 4, 4, 0, 4, 0]))
    write(t, "seed-grid-twisted", grid((7, 2), [0, 0, 0, 100, 0, 0, 0xf0, 80, 60, 3, 0x90, 0x85],
                                       k=12))
    write(t, "seed-grid-planar-folded", grid((5, 9), [0, 0, 0, 4, 0, 0, 0, 4, 0, 4, 4, 0]))


def shade_seeds():
    t = "shade"

    def light(pos, dir, col, att=(1, 0, 0), spot=(0, 0)):
        return f32(*pos, *dir, *col, *att, *spot)

    mat = f32(0, 0, 0, 0, 0, 1, 0, 0, 1, 0.1, 0.1, 0.1, 0, 0, 0, 0.7, 0.7, 0.7, 0.7, 0.7, 0.7,
              0.3, 0.3, 0.3, 32)
    lights = (light((0, 0, 2), (0, 0, -1), (1, 1, 1)) +
              light((1, 1, 2), (-1, -1, -2), (20, 20, 20), (10, 0, 0), (0.2, 0.6)) +
              light((0, 3, 0), (0, -1, 0), (5, 5, 5), (0, 0, 1), (8, 0)))
    # Byte 0: lobe, count 3, normalize; lights: point, spot punctual cone, spot Warn.
    write(t, "seed-three-lights", bytes([0x1c, 1, 0x16, 2]) + mat + lights)
    write(t, "seed-blinn-directional", bytes([0x15, 0, 0, 0]) + mat + lights)
    write(t, "seed-normalized-punctual-no-range", bytes([0x1e, 0x0d, 0x1e, 0x06]) + mat + lights)
    write(t, "seed-point-at-light", bytes([0x14, 1, 0, 0]) +
          f32(0, 0, 2) + mat[12:] + lights)
    bad = f32(math.nan, math.inf, 0, 0, 0, 0, -0.0, 1e-45, 3e38) + mat[36:]
    write(t, "seed-non-finite", bytes([0x0c, 0x16, 0x1f, 0x05]) + bad + lights)
    write(t, "seed-huge-shininess", bytes([0x16, 0x12, 0, 0]) + mat[:96] + f32(3e38) + lights)


def load_path_seeds():
    t = "load_path"
    write(t, "seed-inside", "inside.bin")
    write(t, "seed-inside-both", b"inside.bin\0inside.png")
    write(t, "seed-dotdot", "../decoy.bin")
    write(t, "seed-dotdot-image", b"inside.bin\0../decoy.png")
    write(t, "seed-percent-dotdot", "%2e%2e/decoy.bin")
    write(t, "seed-percent-slash", "..%2fdecoy.bin")
    write(t, "seed-backslash", "..\\decoy.bin")
    write(t, "seed-absolute", b"\x01/decoy.bin")
    write(t, "seed-absolute-image", b"inside.bin\0\x01/decoy.png")
    write(t, "seed-file-uri", b"file://\x01/decoy.bin")
    write(t, "seed-symlink", "link.bin")
    write(t, "seed-inside-then-out", "./sub/../../decoy.bin")
    write(t, "seed-folder", ".")
    write(t, "seed-data-uri", "data:application/octet-stream;base64," +
          base64.b64encode(f32(0, 0, 0, 1, 0, 0, 0, 1, 0)).decode())


if __name__ == "__main__":
    image_seeds()
    gltf_seeds()
    render_options_seeds()
    textures_3d_seeds()
    interp_3d_seeds()
    shade_seeds()
    load_path_seeds()
