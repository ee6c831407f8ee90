#!/usr/bin/python3
"""Test images for scene/image_color_tags.h, written by Pillow (Debian 12's python3-pil),
a PNG and JPEG writer independent of Prism's, around the ICC profiles that
scripts/testdata/icc_texture_oracle.c writes with Little CMS 2.

    apt-get install python3-pil liblcms2-dev
    gcc -O1 -o /tmp/icc_oracle scripts/testdata/icc_texture_oracle.c -llcms2 -lm
    /tmp/icc_oracle tests/scene/loaders/data/color_tags
    /usr/bin/python3 scripts/testdata/icc_texture_images.py tests/scene/loaders/data/color_tags

Every RGB image is one row of the eight codes the oracle transforms (ROW below)."""
import os
import struct
import sys
import zlib

from PIL import Image, PngImagePlugin

ROW = [(255, 0, 0), (0, 255, 0), (0, 0, 255), (200, 100, 50), (128, 128, 128), (10, 20, 30), (255, 255, 255), (0, 0, 0)]
GREY = [0, 10, 50, 128, 200, 255]


def row_image():
    image = Image.new("RGB", (len(ROW), 1))
    image.putdata(ROW)
    return image


def png_info(*chunks):
    info = PngImagePlugin.PngInfo()
    for kind, data in chunks:
        info.add(kind, data)
    return info


def with_chunk(path, kind, data):
    """Inserts a chunk after IHDR (Pillow writes neither cICP nor an iCCP it did not make)."""
    png = open(path, "rb").read()
    ihdr_end = 8 + 12 + 13
    chunk = struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    open(path, "wb").write(png[:ihdr_end] + chunk + png[ihdr_end:])


def main(folder):
    profile = lambda name: open(os.path.join(folder, name), "rb").read()
    out = lambda name: os.path.join(folder, name)
    row_image().save(out("display-p3-icc.png"), icc_profile=profile("display-p3-table-v2.icc"))
    row_image().save(out("rec2020-gamma22-icc.png"), icc_profile=profile("rec2020-gamma22-v4.icc"))
    row_image().save(out("srgb-icc.png"), icc_profile=profile("srgb-lcms2.icc"))
    grey = Image.new("L", (len(GREY), 1))
    grey.putdata(GREY)
    grey.save(out("gray-gamma18-icc.png"), icc_profile=profile("gray-gamma18.icc"))
    # cICP (PNG Third Edition §11.3.2.6): Display P3 primaries (12), the sRGB curve (13),
    # RGB (0), full range (1); and PQ (16), which a texture refuses.
    for name, cicp in (("display-p3-cicp.png", [12, 13, 0, 1]), ("pq-cicp.png", [9, 16, 0, 1])):
        row_image().save(out(name))
        with_chunk(out(name), b"cICP", bytes(cicp))
    # cHRM (Rec.2020: white, red, green, blue x, y × 100000) and gAMA 1/1.8.
    chrm = struct.pack(">8I", 31270, 32900, 70800, 29200, 17000, 79700, 13100, 4600)
    row_image().save(out("rec2020-gamma18-chrm.png"),
                     pnginfo=png_info((b"gAMA", struct.pack(">I", 55556)), (b"cHRM", chrm)))
    # What an sRGB encoder writes (§12.2): sRGB, with gAMA 45455 beside it.
    row_image().save(out("srgb-chunk.png"), pnginfo=png_info((b"sRGB", bytes([0])), (b"gAMA", struct.pack(">I", 45455))))
    # An iCCP chunk whose data is not zlib: passed over, the image read as sRGB.
    row_image().save(out("corrupt-iccp.png"))
    with_chunk(out("corrupt-iccp.png"), b"iCCP", b"broken\0\0not zlib data")
    # A flat JPEG (4:4:4, quality 100: every pixel decodes to the code written) with a
    # ~98 kB profile, which Pillow splits over two APP2 segments (ICC.1 Annex B.4).
    Image.new("RGB", (16, 16), (200, 100, 50)).save(out("display-p3-large-icc.jpg"), quality=100, subsampling=0,
                                                    icc_profile=profile("display-p3-large.icc"))


if __name__ == "__main__":
    main(sys.argv[1])
