"""A small glTF 2.0 loader and an unlit OpenGL renderer (moderngl on Mesa's llvmpipe).

It reads what the Khronos sample models under fixtures/gltf use, and nothing more: GLB and .gltf
with external or data: URIs, buffers/bufferViews/accessors (strides, normalized integers, sparse),
the node hierarchy (matrix or TRS), every primitive mode, TEXCOORD_0/1, COLOR_0,
baseColorFactor, baseColorTexture with its sampler and KHR_texture_transform, alphaMode and
doubleSided. Section numbers below are the glTF 2.0 specification's.

It draws glTF's unlit model (KHR_materials_unlit: base colour factor x texture x vertex colour)
into a linear RGBA32F target cleared to the background, then encodes sRGB on the CPU, with the
view and projection matrices it is given (barytex's, from --print-camera).
"""

import base64
import ctypes
import ctypes.util
import json
import math
import struct
import urllib.parse
from io import BytesIO
from pathlib import Path

import moderngl
import numpy as np
from PIL import Image

# §3.6.2.2 component types → numpy dtypes; §3.11 normalized integers → [0, 1] or [-1, 1].
DTYPES = {5120: np.int8, 5121: np.uint8, 5122: np.int16, 5123: np.uint16, 5125: np.uint32, 5126: np.float32}
NCOMP = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT2": 4, "MAT3": 9, "MAT4": 16}

GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T = 0x0DE1, 0x2802, 0x2803
GL_SRGB8_ALPHA8 = 0x8C43
LINEAR, LINEAR_MIPMAP_LINEAR = 9729, 9987
MIPMAP_FILTERS = {9984, 9985, 9986, 9987}


class Gltf:
    """The JSON document and its buffers, with accessor and image reads."""

    def __init__(self, path):
        self.path = Path(path)
        data = self.path.read_bytes()
        glb_bin = None
        if data[:4] == b"glTF":  # §4.4 GLB: header, JSON chunk, optional BIN chunk
            offset, chunks = 12, []
            while offset + 8 <= len(data):
                length, kind = struct.unpack_from("<II", data, offset)
                chunks.append((kind, data[offset + 8 : offset + 8 + length]))
                offset += 8 + length
            self.json = json.loads(chunks[0][1])
            glb_bin = next((c for k, c in chunks[1:] if k == 0x004E4942), None)
        else:
            self.json = json.loads(data)
        self.buffers = []
        for i, b in enumerate(self.json.get("buffers", [])):
            uri = b.get("uri")
            self.buffers.append(glb_bin if uri is None and i == 0 else self.read_uri(uri))

    def read_uri(self, uri):
        if uri.startswith("data:"):
            return base64.b64decode(uri.split(",", 1)[1])
        return (self.path.parent / urllib.parse.unquote(uri)).read_bytes()

    def view_bytes(self, index):
        v = self.json["bufferViews"][index]
        start = v.get("byteOffset", 0)
        return self.buffers[v["buffer"]][start : start + v["byteLength"]], v.get("byteStride")

    def _read(self, view, offset, count, ncomp, dtype):
        """`count` elements of `ncomp` components from a bufferView, honouring its stride."""
        raw, stride = self.view_bytes(view)
        item = np.dtype(dtype).itemsize
        stride = stride or ncomp * item
        return np.ndarray((count, ncomp), dtype, raw, offset, (stride, item)).copy()

    def accessor(self, index):
        """Accessor `index` as a (count, components) float array (normalized applied), or as
        uint32 for unnormalized integer scalars (indices)."""
        a = self.json["accessors"][index]
        dtype, ncomp, count = DTYPES[a["componentType"]], NCOMP[a["type"]], a["count"]
        if "bufferView" in a:
            values = self._read(a["bufferView"], a.get("byteOffset", 0), count, ncomp, dtype)
        else:
            values = np.zeros((count, ncomp), dtype)  # §3.6.2.3: no bufferView → zeros
        sparse = a.get("sparse")
        if sparse:  # §3.6.2.3 sparse accessors: indices and substitute values
            idx, val = sparse["indices"], sparse["values"]
            where = self._read(idx["bufferView"], idx.get("byteOffset", 0), sparse["count"], 1,
                               DTYPES[idx["componentType"]])[:, 0]
            values = values.copy()
            values[where] = self._read(val["bufferView"], val.get("byteOffset", 0), sparse["count"], ncomp, dtype)
        if dtype is np.float32:
            return values.astype(np.float32)
        if a.get("normalized"):
            info = np.iinfo(dtype)
            return np.maximum(values.astype(np.float32) / info.max, -1.0)
        return values.astype(np.uint32) if ncomp == 1 else values.astype(np.float32)

    def image_rgba(self, index):
        img = self.json["images"][index]
        raw = self.read_uri(img["uri"]) if "uri" in img else self.view_bytes(img["bufferView"])[0]
        # §3.8.4: colour-space information in the PNG (gAMA, iCCP, sRGB) is ignored.
        return np.asarray(Image.open(BytesIO(raw)).convert("RGBA"))


def local_matrix(node):
    """§3.5.3: `matrix` (column-major) or T·R·S."""
    if "matrix" in node:
        return np.array(node["matrix"], np.float64).reshape(4, 4).T
    q = np.array(node.get("rotation", [0, 0, 0, 1]), np.float64)
    x, y, z, w = q / np.linalg.norm(q)  # a unit quaternion, within the writer's rounding
    r = np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                  [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                  [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])
    m = np.eye(4)
    m[:3, :3] = r * np.array(node.get("scale", [1, 1, 1]))
    m[:3, 3] = node.get("translation", [0, 0, 0])
    return m


def instances(doc):
    """(world matrix, mesh index) for every mesh node of the default scene (§3.5.1)."""
    g = doc.json
    scenes = g.get("scenes", [])
    if not scenes:
        return []
    out = []

    def visit(i, parent):
        node = g["nodes"][i]
        world = parent @ local_matrix(node)
        if "mesh" in node:
            out.append((world, node["mesh"]))
        for c in node.get("children", []):
            visit(c, world)

    for root in scenes[g.get("scene", 0)].get("nodes", []):
        visit(root, np.eye(4))
    return out


def texture_transform(info):
    """(uv set, 3×3 matrix) of a textureInfo with KHR_texture_transform: T·R·S."""
    t = info.get("extensions", {}).get("KHR_texture_transform", {})
    (ox, oy), r, (sx, sy) = t.get("offset", [0, 0]), t.get("rotation", 0.0), t.get("scale", [1, 1])
    c, s = math.cos(r), math.sin(r)
    m = np.array([[1, 0, ox], [0, 1, oy], [0, 0, 1]]) @ np.array([[c, s, 0], [-s, c, 0], [0, 0, 1]]) \
        @ np.diag([sx, sy, 1.0])
    return t.get("texCoord", info.get("texCoord", 0)), m


VERTEX = """
#version 330
uniform mat4 vp;
in vec3 pos; in vec2 uv0; in vec2 uv1; in vec4 col;
out vec2 v_uv0; out vec2 v_uv1; out vec4 v_col;
void main() { gl_Position = vp * vec4(pos, 1.0); v_uv0 = uv0; v_uv1 = uv1; v_col = col; }
"""
FRAGMENT = """
#version 330
uniform vec4 base; uniform bool textured; uniform sampler2D tex; uniform int set; uniform mat3 xf;
uniform int mode; uniform float cutoff; uniform bool premultiplied;
in vec2 v_uv0; in vec2 v_uv1; in vec4 v_col;
out vec4 colour;
void main() {
    vec4 c = base * v_col;
    if (textured) {
        vec4 t = texture(tex, (xf * vec3(set == 1 ? v_uv1 : v_uv0, 1.0)).xy);
        if (premultiplied && t.a > 0.0) t.rgb /= t.a;
        c *= t;
    }
    if (mode == 1 && c.a < cutoff) discard;   // MASK
    colour = vec4(c.rgb, mode == 2 ? c.a : 1.0);
}
"""
GL_MODES = [moderngl.POINTS, moderngl.LINES, moderngl.LINE_LOOP, moderngl.LINE_STRIP,
            moderngl.TRIANGLES, moderngl.TRIANGLE_STRIP, moderngl.TRIANGLE_FAN]


class Renderer:
    def __init__(self, size=(256, 256)):
        #: Filter textures as linear-light premultiplied RGBA32F (barytex's convention) instead
        #: of OpenGL's sRGB8_ALPHA8 with straight alpha.
        self.premultiplied = False
        self.ctx = moderngl.create_standalone_context(backend="egl")
        self.renderer_name = self.ctx.info["GL_RENDERER"]
        self.size = size
        self.prog = self.ctx.program(vertex_shader=VERTEX, fragment_shader=FRAGMENT)
        self.colour = self.ctx.texture(size, 4, dtype="f4")
        self.depth = self.ctx.depth_texture(size)
        self.fbo = self.ctx.framebuffer([self.colour], self.depth)
        gl = ctypes.CDLL(ctypes.util.find_library("OpenGL") or "libOpenGL.so.0")
        self.bind_texture, self.tex_parameteri = gl.glBindTexture, gl.glTexParameteri

    def texture(self, doc, tex_index, cache):
        """The GL texture for glTF texture `tex_index`: sRGB-decoded (base colour, §3.9.2), with
        the sampler's filters and wraps (§3.8.4; undefined filters: linear, trilinear)."""
        if tex_index in cache:
            return cache[tex_index]
        t = doc.json["textures"][tex_index]
        sampler = doc.json.get("samplers", [])[t["sampler"]] if "sampler" in t else {}
        rgba = doc.image_rgba(t["source"])
        size = (rgba.shape[1], rgba.shape[0])
        if self.premultiplied:
            linear = srgb_decode(rgba)
            linear[..., :3] *= linear[..., 3:]
            tex = self.ctx.texture(size, 4, linear.astype(np.float32).tobytes(), dtype="f4")
        else:
            tex = self.ctx.texture(size, 4, np.ascontiguousarray(rgba).tobytes(), internal_format=GL_SRGB8_ALPHA8)
        # Rows go up as stored: the image's first row is t = 0, glTF's v = 0 (§3.7.2.1).
        minf, magf = sampler.get("minFilter", LINEAR_MIPMAP_LINEAR), sampler.get("magFilter", LINEAR)
        if minf in MIPMAP_FILTERS:
            tex.build_mipmaps()  # glGenerateMipmap
        tex.filter = (minf, magf)
        self.bind_texture(GL_TEXTURE_2D, tex.glo)
        self.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, sampler.get("wrapS", 10497))
        self.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, sampler.get("wrapT", 10497))
        cache[tex_index] = tex
        return tex

    def render(self, path, view, projection_gl, background):
        """The linear RGB image (height, width, 3), top row first."""
        doc = Gltf(path)
        g = doc.json
        vp = (np.asarray(projection_gl) @ np.asarray(view)).astype(np.float32)
        self.fbo.use()
        self.fbo.clear(*background, depth=1.0)
        self.ctx.enable(moderngl.DEPTH_TEST)
        self.ctx.depth_func = "<"
        self.prog["vp"].write(vp.T.tobytes())
        textures, draws = {}, []
        for world, mesh in instances(doc):
            for prim in g["meshes"][mesh]["primitives"]:
                draws.append(self.prepare(doc, world, view, prim, textures))
        # Opaque and masked in scene order, then blended back to front by the view depth of
        # each primitive's vertex centroid (as barytex orders them; glTF leaves it open, §3.9.4).
        order = [d for d in draws if not d["blend"]] + sorted((d for d in draws if d["blend"]), key=lambda d: d["depth"])
        for d in order:
            self.draw(d)
        out = np.frombuffer(self.colour.read(), np.float32).reshape(self.size[1], self.size[0], 4)
        for d in draws:
            d["vao"].release()
            for b in d["buffers"]:
                b.release()
        for t in textures.values():
            t.release()
        return out[::-1, :, :3].copy()

    def prepare(self, doc, world, view, prim, textures):
        g, attrs = doc.json, prim["attributes"]
        pos = doc.accessor(attrs["POSITION"]).astype(np.float64)
        n = len(pos)
        world_pos = (pos @ world[:3, :3].T + world[:3, 3]).astype(np.float32)

        def attr(name, width, default):
            if name not in attrs:
                return np.tile(np.array(default, np.float32), (n, 1))
            a = doc.accessor(attrs[name]).astype(np.float32)
            return np.hstack([a, np.ones((n, width - a.shape[1]), np.float32)]) if a.shape[1] < width else a

        material = g["materials"][prim["material"]] if "material" in prim else {}
        pbr = material.get("pbrMetallicRoughness", {})
        mode = {"OPAQUE": 0, "MASK": 1, "BLEND": 2}[material.get("alphaMode", "OPAQUE")]
        vertices = np.hstack([world_pos, attr("TEXCOORD_0", 2, [0, 0]), attr("TEXCOORD_1", 2, [0, 0]),
                              attr("COLOR_0", 4, [1, 1, 1, 1])]).astype(np.float32)
        vbo = self.ctx.buffer(vertices.tobytes())
        buffers = [vbo]
        ibo = None
        if "indices" in prim:
            ibo = self.ctx.buffer(doc.accessor(prim["indices"])[:, 0].astype(np.uint32).tobytes())
            buffers.append(ibo)
        vao = self.ctx.vertex_array(self.prog, [(vbo, "3f 2f 2f 4f", "pos", "uv0", "uv1", "col")],
                                    index_buffer=ibo, index_element_size=4)
        info = pbr.get("baseColorTexture")
        tex, uv_set, xf = None, 0, np.eye(3)
        if info is not None:
            tex = self.texture(doc, info["index"], textures)
            uv_set, xf = texture_transform(info)
        centre = world_pos.astype(np.float64).mean(axis=0)
        return {
            "vao": vao, "buffers": buffers, "mode": GL_MODES[prim.get("mode", 4)],
            "base": pbr.get("baseColorFactor", [1, 1, 1, 1]), "tex": tex, "set": uv_set, "xf": xf,
            "alpha": mode, "cutoff": material.get("alphaCutoff", 0.5), "blend": mode == 2,
            "double_sided": material.get("doubleSided", False),
            "flips": np.linalg.det(world[:3, :3]) < 0,  # §3.7.4: negative determinant reverses winding
            "depth": (np.asarray(view) @ np.append(centre, 1.0))[2],
        }

    def draw(self, d):
        ctx, prog = self.ctx, self.prog
        prog["base"].value = tuple(d["base"])
        prog["textured"].value = d["tex"] is not None
        prog["set"].value = d["set"]
        prog["xf"].write(d["xf"].T.astype(np.float32).tobytes())
        prog["mode"].value = d["alpha"]
        prog["cutoff"].value = d["cutoff"]
        prog["premultiplied"].value = self.premultiplied
        if d["tex"] is not None:
            d["tex"].use(0)
            prog["tex"].value = 0
        if d["double_sided"]:
            ctx.disable(moderngl.CULL_FACE)
        else:
            ctx.enable(moderngl.CULL_FACE)
            ctx.cull_face = "back"
        ctx.front_face = "cw" if d["flips"] else "ccw"
        if d["blend"]:
            ctx.enable(moderngl.BLEND)
            ctx.blend_func = moderngl.SRC_ALPHA, moderngl.ONE_MINUS_SRC_ALPHA
        else:
            ctx.disable(moderngl.BLEND)
        self.fbo.depth_mask = not d["blend"]
        d["vao"].render(d["mode"])


def srgb_decode(rgba8):
    """8-bit sRGB RGBA → linear float RGBA (alpha is linear already)."""
    c = rgba8.astype(np.float64) / 255.0
    c[..., :3] = np.where(c[..., :3] <= 0.04045, c[..., :3] / 12.92, ((c[..., :3] + 0.055) / 1.055) ** 2.4)
    return c


def srgb_encode(linear):
    """Linear [0, 1] → 8-bit sRGB (IEC 61966-2-1), rounded to nearest."""
    c = np.clip(linear.astype(np.float64), 0.0, 1.0)
    s = np.where(c <= 0.0031308, 12.92 * c, 1.055 * np.power(c, 1 / 2.4) - 0.055)
    return np.round(s * 255.0).astype(np.uint8)
