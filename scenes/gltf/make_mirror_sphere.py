#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Writes mirror_sphere.gltf: a polished metal sphere (metallic 1, roughness 0) and a red cube
# beside it, no camera and no lights, so scadray frames it as a glTF viewer would and the
# sphere reflects the studio environment. Hand-made for scadray's tests (MIT).
import base64, json, math, struct, sys

def sphere(n_seg=48, n_ring=24, r=1.0):
    pos, nrm, idx = [], [], []
    for i in range(n_ring + 1):
        th = math.pi * i / n_ring
        for j in range(n_seg + 1):
            ph = 2 * math.pi * j / n_seg
            n = (math.sin(th) * math.cos(ph), math.cos(th), math.sin(th) * math.sin(ph))
            nrm.append(n)
            pos.append(tuple(r * c for c in n))
    for i in range(n_ring):
        for j in range(n_seg):
            a = i * (n_seg + 1) + j
            b = a + n_seg + 1
            if i != 0:
                idx += [a, a + 1, b]
            if i != n_ring - 1:
                idx += [a + 1, b + 1, b]
    return pos, nrm, idx

def cube(h=0.4):
    pos, nrm, idx = [], [], []
    for axis in range(3):
        for s in (-1, 1):
            n = [0, 0, 0]; n[axis] = s
            u = [0, 0, 0]; u[(axis + 1) % 3] = 1
            v = [0, 0, 0]; v[(axis + 2) % 3] = 1
            base = len(pos)
            for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                pos.append(tuple(h * (n[k] + a * u[k] + b * v[k]) for k in range(3)))
                nrm.append(tuple(n))
            quad = [0, 1, 2, 0, 2, 3] if s > 0 else [0, 2, 1, 0, 3, 2]
            idx += [base + q for q in quad]
    return pos, nrm, idx

buf = bytearray()
views, accessors = [], []

def add(data, fmt, count, comp, typ, target, minmax=None):
    while len(buf) % 4: buf.append(0)
    off = len(buf)
    buf.extend(struct.pack("<" + fmt * count, *data))
    views.append({"buffer": 0, "byteOffset": off, "byteLength": len(buf) - off, "target": target})
    acc = {"bufferView": len(views) - 1, "componentType": comp, "count": count, "type": typ}
    if minmax: acc["min"], acc["max"] = minmax
    accessors.append(acc)
    return len(accessors) - 1

meshes = []
for name, (pos, nrm, idx), mat in (("sphere", sphere(), 0), ("cube", cube(), 1)):
    flat = [c for p in pos for c in p]
    mn = [min(p[k] for p in pos) for k in range(3)]
    mx = [max(p[k] for p in pos) for k in range(3)]
    a_pos = add(flat, "f", len(flat), 5126, "VEC3", 34962, (mn, mx))
    accessors[a_pos]["count"] = len(pos)
    a_nrm = add([c for n in nrm for c in n], "f", 3 * len(nrm), 5126, "VEC3", 34962)
    accessors[a_nrm]["count"] = len(nrm)
    a_idx = add(idx, "H", len(idx), 5123, "SCALAR", 34963)
    meshes.append({"name": name, "primitives": [{"attributes": {"POSITION": a_pos, "NORMAL": a_nrm},
                                                 "indices": a_idx, "material": mat}]})

doc = {
    "asset": {"version": "2.0", "generator": "scadray scenes/gltf/make_mirror_sphere.py (MIT)"},
    "scene": 0,
    "scenes": [{"nodes": [0, 1]}],
    "nodes": [{"name": "mirror sphere", "mesh": 0},
              {"name": "red cube", "mesh": 1, "translation": [1.6, -0.6, 0.4]}],
    "meshes": meshes,
    "materials": [
        {"name": "polished metal", "pbrMetallicRoughness": {
            "baseColorFactor": [0.95, 0.95, 0.95, 1], "metallicFactor": 1.0, "roughnessFactor": 0.0}},
        {"name": "red", "pbrMetallicRoughness": {
            "baseColorFactor": [0.8, 0.1, 0.05, 1], "metallicFactor": 0.0, "roughnessFactor": 0.6}}],
    "buffers": [{"byteLength": len(buf),
                 "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(buf)).decode()}],
    "bufferViews": views,
    "accessors": accessors,
}
out = sys.argv[1] if len(sys.argv) > 1 else "mirror_sphere.gltf"
with open(out, "w") as f:
    json.dump(doc, f, indent=1)
    f.write("\n")
