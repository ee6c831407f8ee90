#!/usr/bin/env python3
"""Writes a textured test scene for load-time benchmarks (docs/performance-design.md "Textured scene loads"):
N quads, each with its own SIZE x SIZE RGB PNG (a sinusoid plus noise, so that the images
compress like photographs rather than flat colours), as an OBJ/MTL scene and as a pbrt-v4
scene over the same images, and a SIZE x SIZE/2 run-length-encoded Radiance .hdr sky
(a gradient and a small sun) for environment-light runs.

  scripts/bench/textured_scene.py OUT_DIR [N=24] [SIZE=1024] [SKY_WIDTH=4096]

Only the Python standard library (zlib for PNG); deterministic (fixed seed)."""
import math
import os
import random
import struct
import sys
import zlib


def write_png(path, width, height, rows):
    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)
    raw = b"".join(b"\x00" + bytes(r) for r in rows)  # filter type 0 per row
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(raw, 6)))
        f.write(chunk(b"IEND", b""))


def texture_rows(size, index, rng):
    for y in range(size):
        row = bytearray(3 * size)
        for x in range(size):
            for c in range(3):
                v = 127 + 90 * math.sin(0.01 * (x + 3 * c) + 0.013 * y * (index + 1)) + rng.randint(-20, 19)
                row[3 * x + c] = max(0, min(255, int(v)))
        yield row


def rgbe(r, g, b):
    m = max(r, g, b)
    if m < 1e-32:
        return bytes((0, 0, 0, 0))
    f, e = math.frexp(m)
    s = f * 256.0 / m
    return bytes((int(r * s), int(g * s), int(b * s), e + 128))


def write_hdr(path, width, height):
    with open(path, "wb") as f:
        f.write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n")
        f.write(b"-Y %d +X %d\n" % (height, width))
        for y in range(height):
            theta = math.pi * (y + 0.5) / height
            texels = []
            for x in range(width):
                phi = 2 * math.pi * (x + 0.5) / width
                sky = 0.5 + 0.5 * math.cos(theta) if theta < math.pi / 2 else 0.1
                sun = 5e4 * math.exp(-((phi - 1.0) ** 2 + (theta - 0.6) ** 2) / 0.0004)
                texels.append(rgbe(0.6 * sky + sun, 0.8 * sky + sun, sky + 0.9 * sun))
            # New run-length scanline: the marker, then each component as dumps of <= 128 bytes.
            line = bytearray((2, 2, width >> 8, width & 0xFF))
            for k in range(4):
                component = bytes(t[k] for t in texels)
                for start in range(0, width, 128):
                    part = component[start:start + 128]
                    line.append(len(part))
                    line += part
            f.write(line)


def main():
    out = sys.argv[1]
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 24
    size = int(sys.argv[3]) if len(sys.argv) > 3 else 1024
    sky_width = int(sys.argv[4]) if len(sys.argv) > 4 else 4096
    os.makedirs(out, exist_ok=True)
    rng = random.Random(1)
    obj, mtl = ["mtllib scene.mtl"], []
    pbrt = ['Scale -1 1 1', 'LookAt 3 2 -8  3 2 0  0 1 0', 'Camera "perspective" "float fov" 50',
            'Film "rgb" "integer xresolution" 256 "integer yresolution" 256', 'WorldBegin',
            'AttributeBegin', 'AreaLightSource "diffuse" "rgb L" [10 10 10]',
            'Shape "trianglemesh" "point3 P" [0 0 -5 6 0 -5 6 4 -5] "integer indices" [0 1 2]', 'AttributeEnd']
    for i in range(n):
        name = "t%d.png" % i
        write_png(os.path.join(out, name), size, size, texture_rows(size, i, rng))
        x, y = i % 6, i // 6
        mtl += ["newmtl m%d" % i, "Kd 0.8 0.8 0.8", "map_Kd " + name]
        v = 4 * i + 1
        obj += ["v %d %d 0" % (x, y), "v %g %d 0" % (x + 0.9, y), "v %g %g 0" % (x + 0.9, y + 0.9),
                "v %d %g 0" % (x, y + 0.9), "vt 0 0", "vt 1 0", "vt 1 1", "vt 0 1", "usemtl m%d" % i,
                "f %d/%d %d/%d %d/%d" % (v, v, v + 1, v + 1, v + 2, v + 2),
                "f %d/%d %d/%d %d/%d" % (v, v, v + 2, v + 2, v + 3, v + 3)]
        pbrt += ['Texture "t%d" "spectrum" "imagemap" "string filename" "%s"' % (i, name),
                 'AttributeBegin', 'Material "diffuse" "texture reflectance" "t%d"' % i,
                 'Shape "trianglemesh" "point3 P" [%d %d 0 %g %d 0 %g %g 0 %d %g 0] "point2 uv" [0 0 1 0 1 1 0 1] '
                 '"integer indices" [0 1 2 0 2 3]' % (x, y, x + 0.9, y, x + 0.9, y + 0.9, x, y + 0.9),
                 'AttributeEnd']
    mtl += ["newmtl light", "Ke 10 10 10"]
    v = 4 * n + 1
    obj += ["v 0 0 5", "v 6 0 5", "v 6 4 5", "usemtl light", "f %d %d %d" % (v, v + 1, v + 2)]
    for name, lines in (("scene.obj", obj), ("scene.mtl", mtl), ("scene.pbrt", pbrt)):
        with open(os.path.join(out, name), "w") as f:
            f.write("\n".join(lines) + "\n")
    write_hdr(os.path.join(out, "sky.hdr"), sky_width, sky_width // 2)


if __name__ == "__main__":
    main()
