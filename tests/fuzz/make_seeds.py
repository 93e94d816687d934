#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Writes the small hand-made seed inputs of tests/fuzz/seeds/: tiny PNG, OpenEXR,
# STL and OFF files. Run from anywhere; the output is committed, this script says how it was made.
import os
import struct
import zlib

here = os.path.join(os.path.dirname(os.path.abspath(__file__)), "seeds")


def put(target, name, data):
    os.makedirs(os.path.join(here, target), exist_ok=True)
    mode = "wb" if isinstance(data, bytes) else "w"
    with open(os.path.join(here, target, name), mode) as f:
        f.write(data)


def png(w, h, depth, gamma=None):
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    raw = b""
    for y in range(h):
        raw += b"\0"
        for x in range(w):
            for c in (x * 60, y * 60, 128):
                raw += struct.pack(">H", c * 257) if depth == 16 else bytes([c])
    out = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, depth, 2, 0, 0, 0))
    if gamma is not None:
        out += chunk(b"gAMA", struct.pack(">I", gamma))
    return out + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b"")


def exr(w, h, channels, batches=None):
    """Uncompressed scanline OpenEXR with float channels (sorted, as the format requires)."""
    channels = sorted(channels)
    def attr(name, kind, value):
        return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(value)) + value
    chlist = b"".join(c.encode() + b"\0" + struct.pack("<iB3xii", 2, 0, 1, 1) for c in channels) + b"\0"
    box = struct.pack("<iiii", 0, 0, w - 1, h - 1)
    header = (attr("channels", "chlist", chlist) + attr("compression", "compression", b"\0") +
              attr("dataWindow", "box2i", box) + attr("displayWindow", "box2i", box) +
              attr("lineOrder", "lineOrder", b"\0") + attr("pixelAspectRatio", "float", struct.pack("<f", 1)) +
              attr("screenWindowCenter", "v2f", struct.pack("<ff", 0, 0)) +
              attr("screenWindowWidth", "float", struct.pack("<f", 1)))
    if batches is not None:
        header += attr("scadray:batches", "int", struct.pack("<i", batches))
    head = b"\x76\x2f\x31\x01" + struct.pack("<i", 2) + header + b"\0"
    line_bytes = 8 + 4 * w * len(channels)
    table = b"".join(struct.pack("<Q", len(head) + 8 * h + y * line_bytes) for y in range(h))
    lines = b""
    for y in range(h):
        data = b"".join(struct.pack("<f", (x + y + i) / 10.0) for i in range(len(channels)) for x in range(w))
        lines += struct.pack("<ii", y, len(data)) + data
    return head + table + lines


put("image", "rgb8.png", png(4, 3, 8))
put("image", "rgb16_linear.png", png(3, 2, 16, gamma=100000))
put("image", "mean.exr", exr(4, 3, ["R", "G", "B"]))
put("image", "estimate.exr", exr(2, 2, ["R", "G", "B", "var.R", "var.G", "var.B"], batches=4))

tetra = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
faces = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
ascii_stl = "solid tetra\n"
for f in faces:
    ascii_stl += "  facet normal 0 0 0\n    outer loop\n"
    for i in f:
        ascii_stl += "      vertex %g %g %g\n" % tetra[i]
    ascii_stl += "    endloop\n  endfacet\n"
put("stl", "tetra_ascii.stl", ascii_stl + "endsolid tetra\n")
binary = b"binary tetra".ljust(80, b" ") + struct.pack("<I", len(faces))
for f in faces:
    binary += struct.pack("<3f", 0, 0, 0) + b"".join(struct.pack("<3f", *tetra[i]) for i in f) + b"\0\0"
put("stl", "tetra_binary.stl", binary)
put("off", "cube.off", "OFF\n# a cube\n8 6 0\n" +
    "".join("%d %d %d\n" % (x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)) +
    "4 0 2 3 1\n4 4 5 7 6\n4 0 1 5 4\n4 2 6 7 3\n4 0 4 6 2\n4 1 3 7 5\n")
put("off", "colored.off", "COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n3 0 1 2 200 200 200\n")
put("pov", "names", b"mesh\xff\0name*/x\n/*\0\"q\\\"\r\n#declare\0out;put.png")
