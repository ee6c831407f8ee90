#!/usr/bin/env python3
"""Checks that a `prism merge` of sample-range parts equals one render of their union.

Usage: compare-merge.py [--bitwise] SINGLE.exr MERGED.exr PART.exr...

Reads the EXRs with its own reader (Python's zlib only, not OpenEXR, so it is an oracle
independent of the library Prism writes them with) and checks that MERGED and SINGLE have
the same size, channels, fingerprint and sample range, and pixels equal within the float
rounding of the merge (below). Prints how many channel values are bitwise equal and the
largest difference; exits 1 when they are not equal, 2 on unreadable input. With --bitwise
every value must be bitwise equal (e.g. a part resumed from a checkpoint against the same
range rendered without interruption: prism's --resume is bitwise exact).

Tolerance. The film accumulates in double; each part's mean is converted from XYZ to RGB and
rounded to float when the part is written, and merge averages those floats weighted by their
sample counts. The 3x3 conversion has entries up to ~3.3 and cancels, so a part's rounding
error scales with that pixel's largest channel in the part, not with the channel itself
(tests/apps/resume_cli_test.cpp, CliRender.SampleRangesMergeToTheWholeRender, allows 16 float
ulps, 2e-6, of it for two parts). The merged error is the count-weighted mean of the parts'
errors, so each channel may differ by 2e-6 x sum_i (n_i / N) * max_c |part_i(pixel, c)|.

File format: OpenEXR single-part scanline files (openexr.com, "OpenEXR File Layout"):
magic, version, header attributes, the line offset table, then chunks of (y, size, data);
NO_COMPRESSION, ZIPS (1 line a chunk) or ZIP (16 lines): zlib, then the byte predictor,
then the two interleaved halves.
"""
import struct
import sys
import zlib

MAGIC = 20000630
LINES_PER_CHUNK = {0: 1, 2: 1, 3: 16}  # NO_COMPRESSION, ZIPS, ZIP
PIXEL_BYTES = {1: 2, 2: 4}  # HALF, FLOAT
TOLERANCE_PER_PART_SCALE = 2e-6  # 16 float ulps of the pixel's largest channel (see above)


class ExrError(Exception):
    pass


def _cstring(data, pos):
    end = data.index(b"\0", pos)
    return data[pos:end].decode("utf-8", "replace"), end + 1


def _parse_channels(value):
    channels, pos = [], 0
    while value[pos] != 0:
        name, pos = _cstring(value, pos)
        pixel_type, _p_linear, x_sampling, y_sampling = struct.unpack_from("<iB3xii", value, pos)
        pos += 16
        if pixel_type not in PIXEL_BYTES or (x_sampling, y_sampling) != (1, 1):
            raise ExrError(f"channel {name}: only unsubsampled half/float channels are read")
        channels.append((name, pixel_type))
    return channels


def _read_header(data):
    magic, version = struct.unpack_from("<ii", data, 0)
    if magic != MAGIC:
        raise ExrError("not an OpenEXR file")
    if version & 0x1A00:  # tiled (bit 9), deep (bit 11), multipart (bit 12)
        raise ExrError(f"only single-part scanline files are read (version field {version:#x})")
    pos, attributes = 8, {}
    while data[pos] != 0:
        name, pos = _cstring(data, pos)
        kind, pos = _cstring(data, pos)
        (size,) = struct.unpack_from("<i", data, pos)
        value = data[pos + 4 : pos + 4 + size]
        pos += 4 + size
        if kind == "int":
            attributes[name] = struct.unpack("<i", value)[0]
        elif kind == "string":
            attributes[name] = value.decode("utf-8", "replace")
        elif kind == "chlist":
            attributes[name] = _parse_channels(value)
        elif kind == "compression":
            attributes[name] = value[0]
        elif kind == "box2i":
            attributes[name] = struct.unpack("<4i", value)
    return attributes, pos + 1


def _unzip(block, size):
    raw = bytearray(zlib.decompress(block))
    if len(raw) != size:
        raise ExrError("a ZIP chunk inflates to the wrong size")
    for i in range(1, len(raw)):  # undo the predictor: each byte was stored as a difference
        raw[i] = (raw[i - 1] + raw[i] - 128) & 0xFF
    half = (len(raw) + 1) // 2  # even bytes first, then odd bytes
    out = bytearray(len(raw))
    out[0::2] = raw[:half]
    out[1::2] = raw[half:]
    return bytes(out)


def read_exr(path):
    """Returns (attributes, width, height, {channel: [values, row-major]})."""
    with open(path, "rb") as f:
        data = f.read()
    attributes, pos = _read_header(data)
    compression = attributes.get("compression")
    if compression not in LINES_PER_CHUNK:
        raise ExrError(f"compression {compression} is not read (NONE, ZIPS and ZIP are)")
    x0, y0, x1, y1 = attributes["dataWindow"]
    width, height = x1 - x0 + 1, y1 - y0 + 1
    channels = attributes["channels"]
    lines = LINES_PER_CHUNK[compression]
    chunks = (height + lines - 1) // lines
    offsets = struct.unpack_from(f"<{chunks}Q", data, pos)
    values = {name: [] for name, _ in channels}
    for offset in offsets:
        y, size = struct.unpack_from("<ii", data, offset)
        rows = min(lines, y1 - y + 1)
        expected = rows * width * sum(PIXEL_BYTES[t] for _, t in channels)
        block = data[offset + 8 : offset + 8 + size]
        raw = block if size == expected else _unzip(block, expected)
        at = 0
        for _row in range(rows):
            for name, pixel_type in channels:  # channels are stored in the chlist's order
                code = "e" if pixel_type == 1 else "f"
                values[name].extend(struct.unpack_from(f"<{width}{code}", raw, at))
                at += width * PIXEL_BYTES[pixel_type]
    return attributes, width, height, values


def main(argv):
    bitwise_only = len(argv) > 1 and argv[1] == "--bitwise"
    if bitwise_only:
        argv = argv[:1] + argv[2:]
    if len(argv) < 4:
        print(__doc__.splitlines()[2], file=sys.stderr)
        return 2
    try:
        single, merged, parts = read_exr(argv[1]), read_exr(argv[2]), [read_exr(p) for p in argv[3:]]
    except (OSError, ExrError, KeyError, struct.error, zlib.error) as e:
        print(f"compare-merge: cannot read input: {e}", file=sys.stderr)
        return 2
    (sa, w, h, sv), (ma, mw, mh, mv) = single, merged
    problems = []
    for key in ("prism:fingerprint", "prism:sampleBegin", "prism:sampleEnd", "prism:spp"):
        if sa.get(key) != ma.get(key):
            problems.append(f"{key}: single {sa.get(key)!r}, merged {ma.get(key)!r}")
    if (w, h) != (mw, mh) or sorted(sv) != sorted(mv):
        problems.append(f"layout: single {w}x{h} {sorted(sv)}, merged {mw}x{mh} {sorted(mv)}")
    if any((pw, ph) != (w, h) for _, pw, ph, _ in parts):
        problems.append("a part's size differs from the single render's")
    if problems:
        print("compare-merge: NOT EQUAL: " + "; ".join(problems))
        return 1

    total = sum(pa["prism:sampleEnd"] - pa["prism:sampleBegin"] for pa, _, _, _ in parts)
    rgb = [c for c in ("R", "G", "B") if c in sv]
    scale = [0.0] * (w * h)  # sum_i (n_i / N) * max_c |part_i(pixel, c)|
    for pa, _, _, pv in parts:
        weight = (pa["prism:sampleEnd"] - pa["prism:sampleBegin"]) / total
        for px in range(w * h):
            scale[px] += weight * max(abs(pv[c][px]) for c in rgb)
    bitwise = compared = failed = 0
    worst = (0.0, None)
    for channel in sorted(sv):
        for px, (a, b) in enumerate(zip(sv[channel], mv[channel])):
            compared += 1
            if struct.pack("<f", a) == struct.pack("<f", b):
                bitwise += 1
                continue
            diff = abs(a - b)
            if diff > worst[0]:
                worst = (diff, f"{channel} at ({px % w}, {px // w}): single {a!r}, merged {b!r}")
            if not bitwise_only and channel in rgb and diff <= TOLERANCE_PER_PART_SCALE * scale[px]:
                continue
            failed += 1
    summary = (f"{bitwise} of {compared} channel values bitwise equal; "
               f"largest difference {worst[0]:.3g}{' (' + worst[1] + ')' if worst[1] else ''}")
    allowed = "bitwise" if bitwise_only else "within the merge's float rounding"
    if failed:
        print(f"compare-merge: NOT EQUAL: {failed} values not equal {allowed}; {summary}")
        return 1
    print(f"compare-merge: equal {allowed}: {summary}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
