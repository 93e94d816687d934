#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Writes geom_skin_morph_colors.gltf: a skinned bar posed by its second joint (COLOR_0 float
# RGB), a cube whose morph target (weight 0.5) lifts its top (COLOR_0 normalized unsigned byte
# RGBA), and a quad with COLOR_0 normalized unsigned short RGBA, placed twice by
# EXT_mesh_gpu_instancing. Test data for scadray; run it to regenerate the file.
import base64, json, math, struct

data = bytearray()
views, accessors = [], []

def add(fmt, values, comp, typ, count, normalized=False, minmax=None):
    while len(data) % 4:
        data.append(0)
    off = len(data)
    data.extend(struct.pack('<%d%s' % (len(values), fmt), *values))
    views.append({"buffer": 0, "byteOffset": off, "byteLength": len(data) - off})
    acc = {"bufferView": len(views) - 1, "componentType": comp, "count": count, "type": typ}
    if normalized:
        acc["normalized"] = True
    if minmax:
        acc["min"], acc["max"] = minmax
    accessors.append(acc)
    return len(accessors) - 1

def positions(pts):
    flat = [c for p in pts for c in p]
    mn = [min(p[i] for p in pts) for i in range(3)]
    mx = [max(p[i] for p in pts) for i in range(3)]
    return add('f', flat, 5126, "VEC3", len(pts), minmax=(mn, mx))

# Skinned bar: 2 x 9 vertices along +Y, from y = 0 to 2; joint 1 at y = 1 bends the top 60 deg
rows = 9
bar, joints, weights, colors = [], [], [], []
for r in range(rows):
    y = 2.0 * r / (rows - 1)
    w1 = min(max((y - 0.75) / 0.5, 0.0), 1.0)  # blend over 0.75 .. 1.25
    for x in (-0.2, 0.2):
        bar.append((x, y, 0.0))
        joints += [0, 1, 0, 0]
        weights += [1 - w1, w1, 0, 0]
        colors += [1 - y / 2, 0.3, y / 2]
bar_idx = []
for r in range(rows - 1):
    a = 2 * r
    bar_idx += [a, a + 1, a + 3, a, a + 3, a + 2]
bar_pos = positions(bar)
bar_ind = add('H', bar_idx, 5123, "SCALAR", len(bar_idx))
bar_j = add('B', joints, 5121, "VEC4", len(bar))
bar_w = add('f', weights, 5126, "VEC4", len(bar))
bar_c = add('f', colors, 5126, "VEC3", len(bar))
ibm = add('f', [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1,
                1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1], 5126, "MAT4", 2)

# Cube with flat normals; the morph target lifts the top face by 1 (weight 0.5: by 0.5)
faces = [((0, 0, 1), [(-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)]),
         ((0, 0, -1), [(-1, 1, -1), (1, 1, -1), (1, -1, -1), (-1, -1, -1)]),
         ((1, 0, 0), [(1, -1, 1), (1, -1, -1), (1, 1, -1), (1, 1, 1)]),
         ((-1, 0, 0), [(-1, -1, -1), (-1, -1, 1), (-1, 1, 1), (-1, 1, -1)]),
         ((0, 1, 0), [(-1, 1, 1), (1, 1, 1), (1, 1, -1), (-1, 1, -1)]),
         ((0, -1, 0), [(-1, -1, -1), (1, -1, -1), (1, -1, 1), (-1, -1, 1)])]
cube, normals, cidx, ccol, delta = [], [], [], [], []
for n, quad in faces:
    base = len(cube)
    for p in quad:
        cube.append(tuple(0.5 * c for c in p))
        normals.append(n)
        ccol += [int(255 * (p[0] + 1) / 2), int(255 * (p[1] + 1) / 2), int(255 * (p[2] + 1) / 2), 255]
        delta += [0, 1.0 if p[1] > 0 else 0.0, 0]
    cidx += [base, base + 1, base + 2, base, base + 2, base + 3]
cube_pos = positions(cube)
cube_n = add('f', [c for n in normals for c in n], 5126, "VEC3", len(cube))
cube_ind = add('H', cidx, 5123, "SCALAR", len(cidx))
cube_c = add('B', ccol, 5121, "VEC4", len(cube), normalized=True)
cube_d = add('f', delta, 5126, "VEC3", len(cube),
             minmax=([0, 0, 0], [0, 1, 0]))

# Quad with unsigned short colours, instanced twice
quad = [(-0.4, -0.4, 0), (0.4, -0.4, 0), (0.4, 0.4, 0), (-0.4, 0.4, 0)]
quad_pos = positions(quad)
quad_n = add('f', [0, 0, 1] * 4, 5126, "VEC3", 4)
quad_c = add('H', [65535, 65535, 0, 65535, 0, 65535, 65535, 65535,
                   65535, 0, 65535, 65535, 13107, 13107, 13107, 65535], 5123, "VEC4", 4,
             normalized=True)
quad_ind = add('H', [0, 1, 2, 0, 2, 3], 5123, "SCALAR", 6)
inst_t = add('f', [0, 0, 0, 1.0, 0, 0], 5126, "VEC3", 2)

s = math.sin(math.radians(30)); c = math.cos(math.radians(30))
material = {"pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1], "metallicFactor": 0,
                                     "roughnessFactor": 0.6}, "doubleSided": True}
gltf = {
    "asset": {"version": "2.0", "generator": "scadray tests/data/gltf/geom_make_models.py",
              "copyright": "scadray authors, MIT"},
    "extensionsUsed": ["EXT_mesh_gpu_instancing"],
    "scene": 0,
    "scenes": [{"nodes": [0, 1, 3, 4, 5]}],
    "nodes": [
        {"name": "bar", "mesh": 0, "skin": 0, "translation": [7, 7, 7]},  # ignored: skinned
        {"name": "root joint", "translation": [-1.5, -1, 0], "children": [2]},
        {"name": "bend joint", "translation": [0, 1, 0], "rotation": [0, 0, s, c]},
        {"name": "cube", "mesh": 1, "translation": [0.5, -0.5, 0],
         "rotation": [0.2126, 0.2126, 0, 0.9537]},
        {"name": "quads", "mesh": 2, "translation": [1.6, -0.3, 0.6],
         "extensions": {"EXT_mesh_gpu_instancing": {"attributes": {"TRANSLATION": inst_t}}}},
        {"name": "camera", "camera": 0, "translation": [0, 0.2, 5.5]},
    ],
    "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}],
    "skins": [{"joints": [1, 2], "inverseBindMatrices": ibm}],
    "materials": [material],
    "meshes": [
        {"name": "bar", "primitives": [{"attributes": {"POSITION": bar_pos, "JOINTS_0": bar_j,
                                                       "WEIGHTS_0": bar_w, "COLOR_0": bar_c},
                                        "indices": bar_ind, "material": 0}]},
        {"name": "cube", "weights": [0.5],
         "primitives": [{"attributes": {"POSITION": cube_pos, "NORMAL": cube_n, "COLOR_0": cube_c},
                         "indices": cube_ind, "material": 0,
                         "targets": [{"POSITION": cube_d}]}]},
        {"name": "quad", "primitives": [{"attributes": {"POSITION": quad_pos, "NORMAL": quad_n,
                                                        "COLOR_0": quad_c},
                                         "indices": quad_ind, "material": 0}]},
    ],
    "buffers": [{"byteLength": len(data),
                 "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(data)).decode()}],
    "bufferViews": views,
    "accessors": accessors,
}
with open("geom_skin_morph_colors.gltf", "w") as f:
    json.dump(gltf, f, indent=1)
    f.write("\n")
