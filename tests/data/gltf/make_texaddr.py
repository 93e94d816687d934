#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Writes the texaddr*.gltf test models (texture addressing: KHR_texture_transform, sampler
# wrap modes, NEAREST, a second texture coordinate set) and their texture, texaddr.png.
# Run from this folder: python3 make_texaddr.py
import base64, json, struct, zlib

def png(width, height, pixels):
    """8-bit RGB or RGBA PNG; pixels[y][x] = (r, g, b[, a]), row 0 at the top."""
    raw = b"".join(b"\0" + bytes(c for p in row for c in p) for row in pixels)
    colour_type = 6 if len(pixels[0][0]) == 4 else 2
    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, colour_type, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))

# 8 x 8 texels, each its own colour: red rises to the right, green downwards, blue in a
# checker, and a white marker at the top-left texel so orientation shows
N = 8
pixels = [[(36 * x, 36 * y, 200 if (x + y) % 2 else 40) for x in range(N)] for y in range(N)]
pixels[0][0] = (255, 255, 255)
with open("texaddr.png", "wb") as f:
    f.write(png(N, N, pixels))

def quad_model(quads, name, camera_distance=3.2):
    """quads: list of dicts with centre (x, y), uv0 ((u0, v0), (u1, v1)), optional uv1,
    sampler (dict), textureInfo (dict), image (default texaddr.png), z (default 0), size
    (default 1) and material (extra material properties). Each quad is size x size in glTF's xy
    plane facing +z."""
    images = []
    buf = bytearray()
    views, accessors, meshes, nodes, materials, samplers, textures = [], [], [], [], [], [], []
    def add(data, count, kind, target=34962):
        off = len(buf)
        buf.extend(data)
        while len(buf) % 4: buf.append(0)
        views.append({"buffer": 0, "byteOffset": off, "byteLength": len(data), "target": target})
        acc = {"bufferView": len(views) - 1, "componentType": 5126 if kind != "SCALAR" else 5123,
               "count": count, "type": kind}
        accessors.append(acc)
        return len(accessors) - 1, acc
    for i, q in enumerate(quads):
        cx, cy = q["centre"]
        z, h = q.get("z", 0), q.get("size", 1) / 2
        pos = [(cx - h, cy - h, z), (cx + h, cy - h, z), (cx + h, cy + h, z), (cx - h, cy + h, z)]
        pi, pacc = add(b"".join(struct.pack("<3f", *p) for p in pos), 4, "VEC3")
        pacc["min"] = [cx - h, cy - h, z]
        pacc["max"] = [cx + h, cy + h, z]
        ni, _ = add(struct.pack("<3f", 0, 0, 1) * 4, 4, "VEC3")
        def uvs(r):
            (u0, v0), (u1, v1) = r
            # glTF v grows downwards: the quad's top edge (y + .5) has v0
            return b"".join(struct.pack("<2f", *t) for t in [(u0, v1), (u1, v1), (u1, v0), (u0, v0)])
        attrs = {"POSITION": pi, "NORMAL": ni}
        attrs["TEXCOORD_0"], _ = add(uvs(q["uv0"]), 4, "VEC2")
        if "uv1" in q:
            attrs["TEXCOORD_1"], _ = add(uvs(q["uv1"]), 4, "VEC2")
        ii, _ = add(struct.pack("<6H", 0, 1, 2, 0, 2, 3), 6, "SCALAR", 34963)
        samplers.append(q["sampler"])
        image = q.get("image", "texaddr.png")
        if image not in images: images.append(image)
        textures.append({"source": images.index(image), "sampler": i})
        info = dict({"index": i}, **q.get("textureInfo", {}))
        materials.append(dict({"name": q["name"], "pbrMetallicRoughness": {
            "baseColorTexture": info, "metallicFactor": 0.0, "roughnessFactor": 1.0}},
            **q.get("material", {})))
        meshes.append({"name": q["name"], "primitives": [{"attributes": attrs, "indices": ii, "material": i}]})
        nodes.append({"mesh": i, "name": q["name"]})
    nodes.append({"camera": 0, "translation": [0, 0, camera_distance], "name": "camera"})
    gltf = {
        "asset": {"version": "2.0", "generator": "scadray make_texaddr.py (MIT)"},
        "extensionsUsed": ["KHR_texture_transform"],
        "scene": 0, "scenes": [{"nodes": list(range(len(nodes)))}],
        "nodes": nodes, "meshes": meshes, "materials": materials,
        "textures": textures, "samplers": samplers, "images": [{"uri": i} for i in images],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.75, "aspectRatio": 4 / 3, "znear": 0.1}}],
        "accessors": accessors, "bufferViews": views,
        "buffers": [{"byteLength": len(buf),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(buf)).decode()}],
    }
    with open(name, "w") as f:
        json.dump(gltf, f, indent=1)
        f.write("\n")

REPEAT, CLAMP, MIRROR, NEAREST, LINEAR = 10497, 33071, 33648, 9728, 9729
quad_model([
    {"name": "transform", "centre": (-.6, .6), "uv0": ((0, 0), (1, 1)), "sampler": {},
     "textureInfo": {"extensions": {"KHR_texture_transform": {
         "offset": [0.1, 0.2], "rotation": 0.4, "scale": [1.5, 1.2]}}}},
    {"name": "clamp", "centre": (.6, .6), "uv0": ((-.5, -.5), (1.5, 1.5)),
     "sampler": {"wrapS": CLAMP, "wrapT": CLAMP, "magFilter": LINEAR}},
    {"name": "mirror", "centre": (-.6, -.6), "uv0": ((-1, -1), (2, 2)),
     "sampler": {"wrapS": MIRROR, "wrapT": MIRROR}},
    {"name": "nearest", "centre": (.6, -.6), "uv0": ((0, 0), (2, 2)),
     "sampler": {"magFilter": NEAREST, "minFilter": NEAREST, "wrapT": MIRROR},
     "textureInfo": {"extensions": {"KHR_texture_transform": {"rotation": -0.3}}}},
], "texaddr_wrap.gltf")

# TEXCOORD_1: the texture reads the second set (0..1 over the quad); TEXCOORD_0 is a
# single point, so a renderer reading the wrong set shows one flat colour
quad_model([
    {"name": "texcoord1", "centre": (0, 0), "uv0": ((0.01, 0.01), (0.01, 0.01)),
     "uv1": ((0, 0), (1, 1)), "sampler": {"magFilter": NEAREST}, "textureInfo": {"texCoord": 1}},
], "texaddr_uv1.gltf", camera_distance=1.8)

# Alpha per texel: a checkerboard of opaque and clear texels (alpha 255 / 0, a soft 96 on the
# diagonal squares of the second half) over a white floor lit by the automatic lights. MASK
# cuts the clear texels out (the floor and the shadow show the checkerboard), BLEND lets
# light through by 1 - alpha
A = 8
rgba = [[(220, 60 + 20 * x, 40, 255 if (x + y) % 2 == 0 else (0 if x < A // 2 else 96))
         for x in range(A)] for y in range(A)]
with open("texaddr_alpha.png", "wb") as f:
    f.write(png(A, A, rgba))
quad_model([
    {"name": "floor", "centre": (0, 0), "z": -0.6, "size": 3.2, "uv0": ((0, 0), (0.001, 0.001)),
     "sampler": {}, "image": "texaddr.png", "textureInfo": {},
     "material": {"pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1], "metallicFactor": 0.0,
                                           "roughnessFactor": 1.0}}},
    {"name": "mask", "centre": (-.6, 0), "uv0": ((0, 0), (1, 1)), "image": "texaddr_alpha.png",
     "sampler": {"magFilter": NEAREST}, "material": {"alphaMode": "MASK", "alphaCutoff": 0.5}},
    {"name": "blend", "centre": (.6, 0), "uv0": ((0, 0), (1, 1)), "image": "texaddr_alpha.png",
     "sampler": {"magFilter": NEAREST}, "material": {"alphaMode": "BLEND"}},
], "texaddr_alpha.gltf", camera_distance=3.0)
