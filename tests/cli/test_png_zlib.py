"""The tool's PNG writer checked by a decoder it shares no code with: Python's zlib inflates the
image data and this script undoes the row filters. Pictures of several kinds (noise, a flat colour,
black rows between noise, gradients, a smooth shaded ball) and sizes are written by png_from_raw and
must come back exactly; every chunk's CRC and the zlib stream's end are checked, and the pictures
in docs/images must decode too.

usage: test_png_zlib.py PNG_FROM_RAW WORKDIR IMAGES_DIR
"""
import math
import os
import random
import struct
import subprocess
import sys
import zlib

failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL:", what)


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    return a if pa <= pb and pa <= pc else b if pb <= pc else c


def decode(path):
    """(width, height, RGB bytes, set of filter types) of an 8-bit RGB PNG."""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "signature"
    pos, idat, w, h = 8, b"", 0, 0
    while True:
        (n,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + n]
        (crc,) = struct.unpack(">I", data[pos + 8 + n:pos + 12 + n])
        assert zlib.crc32(kind + body) == crc, "CRC of " + kind.decode()
        pos += 12 + n
        if kind == b"IHDR":
            w, h, depth, colour, comp, filt, interlace = struct.unpack(">IIBBBBB", body)
            assert (depth, colour, comp, filt, interlace) == (8, 2, 0, 0, 0), "IHDR"
        elif kind == b"IDAT":
            idat += body
        elif kind == b"IEND":
            break
    assert pos == len(data), "bytes after IEND"
    z = zlib.decompressobj()
    raw = z.decompress(idat)
    assert z.eof and not z.unused_data, "zlib stream end"
    stride = 3 * w
    assert len(raw) == h * (stride + 1), "image data length"
    out, seen, prev = bytearray(), set(), bytes(stride)
    for y in range(h):
        t, f = raw[y * (stride + 1)], raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)]
        seen.add(t)
        row = bytearray(stride)
        for i in range(stride):
            a = row[i - 3] if i >= 3 else 0
            b = prev[i]
            c = prev[i - 3] if i >= 3 else 0
            pred = [0, a, b, (a + b) >> 1, paeth(a, b, c)][t]
            row[i] = (f[i] + pred) & 255
        out += row
        prev = row
    return w, h, bytes(out), seen


def picture(kind, w, h, rnd):
    px = bytearray(3 * w * h)
    for y in range(h):
        for x in range(w):
            for k in range(3):
                i = 3 * (y * w + x) + k
                if kind == "noise":
                    px[i] = rnd.randrange(256)
                elif kind == "flat":
                    px[i] = (40, 120, 200)[k]
                elif kind == "black rows":
                    px[i] = 0 if y % 4 else rnd.randrange(256)
                elif kind == "gradient":
                    px[i] = (x * 255 // max(w - 1, 1) + 40 * k + y) & 255
                else:  # a shaded ball on a gradient, like a render
                    dx, dy = (2 * x + 1) / w - 1, (2 * y + 1) / h - 1
                    r2 = dx * dx + dy * dy
                    shade = math.sqrt(1 - r2) if r2 < 1 else 0.3 + 0.5 * y / h
                    px[i] = int(255 * shade * (0.6, 0.8, 1.0)[k])
    return bytes(px)


def main():
    helper, work, images = sys.argv[1], sys.argv[2], sys.argv[3]
    os.makedirs(work, exist_ok=True)
    rnd = random.Random(5)
    seen_all = set()
    for w, h in [(1, 1), (2, 3), (31, 7), (200, 120), (90, 260)]:
        for kind in ["noise", "flat", "black rows", "gradient", "ball"]:
            px = picture(kind, w, h, rnd)
            raw, png = os.path.join(work, "in.rgb"), os.path.join(work, "out.png")
            open(raw, "wb").write(px)
            rc = subprocess.call([helper, str(w), str(h), raw, png])
            check(rc == 0, "%s %dx%d: png_from_raw exit %d" % (kind, w, h, rc))
            if rc != 0:
                continue
            try:
                gw, gh, back, seen = decode(png)
            except AssertionError as e:
                check(False, "%s %dx%d: %s" % (kind, w, h, e))
                continue
            seen_all |= seen
            check((gw, gh) == (w, h) and back == px, "%s %dx%d: pixels differ" % (kind, w, h))
            size, limit = os.path.getsize(png), {"flat": len(px) / 50, "ball": len(px) / 4}.get(kind)
            if limit and w >= 90:  # smooth pictures shrink a lot
                check(size < limit, "%s %dx%d: %d bytes for %d" % (kind, w, h, size, len(px)))
    check(len(seen_all) >= 3, "filters used: %s" % sorted(seen_all))
    names = sorted(f for f in os.listdir(images) if f.endswith(".png"))
    check(names, "no pictures in " + images)
    for name in names:
        try:
            decode(os.path.join(images, name))
        except AssertionError as e:
            check(False, "%s: %s" % (name, e))
    print("test_png_zlib: %d failures" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
