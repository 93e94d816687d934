#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Writes textured_camera.glb: a binary glTF with what the tests once read from Khronos' Duck.glb
# (SCEA-licensed, so never in this repository): a matrix node hierarchy, a perspective camera
# on a child node, and one base-colour texture stored as a PNG inside the GLB's binary chunk,
# sampled with REPEAT. The mesh is a UV sphere with normals and texture coordinates.
# Run from this folder: python3 make_textured_camera.py
import json, math, struct, zlib

def png(width, height, pixels):
    """8-bit RGB PNG; pixels[y][x] = (r, g, b), row 0 at the top."""
    raw = b"".join(b"\0" + bytes(c for p in row for c in p) for row in pixels)
    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))

# 128 x 128 texels: yellow with orange bands along v, a white patch at the top-left corner (so
# orientation shows) and a little deterministic noise (so the PNG is not trivially small)
N = 128
seed = 12345
def noise():
    global seed
    seed = (seed * 1103515245 + 12345) & 0x7fffffff
    return (seed >> 16) % 21 - 10
pixels = []
for y in range(N):
    row = []
    for x in range(N):
        r, g, b = (250, 205, 40) if (y // 16) % 2 == 0 else (240, 140, 30)
        if x < 16 and y < 16:
            r, g, b = 255, 255, 255
        row.append(tuple(max(0, min(255, c + noise())) for c in (r, g, b)))
    pixels.append(row)
image = png(N, N, pixels)

# UV sphere of radius 0.5: SEG segments around y, RING rings from pole to pole; the seam and the
# poles have their own vertices so u and v are continuous on every triangle
SEG, RING = 32, 16
pos, nrm, uv, idx = [], [], [], []
for j in range(RING + 1):
    theta = math.pi * j / RING
    for i in range(SEG + 1):
        phi = 2 * math.pi * i / SEG
        n = (math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi))
        nrm.append(n)
        pos.append(tuple(0.5 * c for c in n))
        uv.append((i / SEG, j / RING))
for j in range(RING):
    for i in range(SEG):
        a, b = j * (SEG + 1) + i, (j + 1) * (SEG + 1) + i
        if j > 0: idx += [a, b, a + 1]             # counter-clockwise seen from outside
        if j < RING - 1: idx += [a + 1, b, b + 1]

buf = bytearray()
views, accessors = [], []
def add(data, target=None):
    while len(buf) % 4: buf.append(0)
    off = len(buf)
    buf.extend(data)
    view = {"buffer": 0, "byteOffset": off, "byteLength": len(data)}
    if target: view["target"] = target
    views.append(view)
    return len(views) - 1
def accessor(view, ctype, count, kind, **extra):
    accessors.append(dict({"bufferView": view, "componentType": ctype, "count": count, "type": kind}, **extra))
    return len(accessors) - 1
p = accessor(add(b"".join(struct.pack("<3f", *v) for v in pos), 34962), 5126, len(pos), "VEC3",
             min=[min(v[k] for v in pos) for k in range(3)], max=[max(v[k] for v in pos) for k in range(3)])
n = accessor(add(b"".join(struct.pack("<3f", *v) for v in nrm), 34962), 5126, len(nrm), "VEC3")
t = accessor(add(b"".join(struct.pack("<2f", *v) for v in uv), 34962), 5126, len(uv), "VEC2")
i = accessor(add(struct.pack("<%dH" % len(idx), *idx), 34963), 5123, len(idx), "SCALAR")
img_view = add(image)

def matrix(rot_y_deg, translation):
    """Column-major 4x4: a rotation about y, then a translation."""
    c, s = math.cos(math.radians(rot_y_deg)), math.sin(math.radians(rot_y_deg))
    tx, ty, tz = translation
    return [c, 0, -s, 0, 0, 1, 0, 0, s, 0, c, 0, tx, ty, tz, 1]

# The root turns everything 20 degrees about y; the sphere sits on y = 0 and the camera, 30
# degrees round from +z, looks at its centre (a glTF camera looks down its local -z)
d, a = 2.4, 30
gltf = {
    "asset": {"version": "2.0", "generator": "scadray make_textured_camera.py (MIT)"},
    "scene": 0,
    "scenes": [{"nodes": [0]}],
    "nodes": [
        {"name": "root", "matrix": matrix(20, (0, 0, 0)), "children": [1, 2]},
        {"name": "ball", "matrix": matrix(0, (0, 0.5, 0)), "mesh": 0},
        {"name": "camera", "camera": 0,
         "matrix": matrix(a, (d * math.sin(math.radians(a)), 0.5, d * math.cos(math.radians(a))))},
    ],
    "cameras": [{"type": "perspective",
                 "perspective": {"yfov": 0.6, "aspectRatio": 1.5, "znear": 0.1, "zfar": 100}}],
    "meshes": [{"name": "ball", "primitives": [
        {"attributes": {"POSITION": p, "NORMAL": n, "TEXCOORD_0": t}, "indices": i, "material": 0}]}],
    "materials": [{"name": "yellow", "pbrMetallicRoughness": {
        "baseColorTexture": {"index": 0}, "metallicFactor": 0.0, "roughnessFactor": 0.8}}],
    "textures": [{"source": 0, "sampler": 0}],
    "samplers": [{"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 10497}],
    "images": [{"bufferView": img_view, "mimeType": "image/png"}],
    "accessors": accessors,
    "bufferViews": views,
    "buffers": [{"byteLength": len(buf)}],
}
while len(buf) % 4: buf.append(0)
gltf["buffers"][0]["byteLength"] = len(buf)
text = json.dumps(gltf, separators=(",", ":")).encode()
text += b" " * (-len(text) % 4)
glb = (struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(text) + 8 + len(buf)) +
       struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(buf), b"BIN\0") + bytes(buf))
with open("textured_camera.glb", "wb") as f:
    f.write(glb)
print("textured_camera.glb: %d bytes, %d triangles, %d-byte PNG" % (len(glb), len(idx) // 3, len(image)))
