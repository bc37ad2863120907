#!/usr/bin/env python3
"""Converts a Radiance .hdr (RGBE, flat or new-style RLE) to the EXR that `--env` reads.

    scripts/hdr_to_exr.py IN.hdr OUT.exr [--roll FRACTION]

Writes float32 RGB, uncompressed, one scanline per chunk. --roll turns the map about +Y by
FRACTION of a turn (its columns rolled by FRACTION x width): 0.5 puts the sun of the glTF
Render Fidelity project's chinese_garden_1k.hdr where that project's goldens have it (see
docs/gltf.md, "Khronos' sample models"). Needs numpy only.
"""
import argparse
import struct

import numpy as np


def read_hdr(path):
    data = open(path, "rb").read()
    pos = 0
    while True:
        end = data.index(b"\n", pos)
        line = data[pos:end]
        pos = end + 1
        if line.startswith((b"-Y", b"+Y")):
            parts = line.split()
            h, w, flip = int(parts[1]), int(parts[3]), parts[0] == b"+Y"
            break
    img = np.zeros((h, w, 4), np.uint8)
    for y in range(h):
        if data[pos] == 2 and data[pos + 1] == 2 and (data[pos + 2] << 8 | data[pos + 3]) == w:
            pos += 4
            for c in range(4):
                x = 0
                while x < w:
                    n = data[pos]
                    pos += 1
                    if n > 128:
                        n -= 128
                        img[y, x:x + n, c] = data[pos]
                        pos += 1
                    else:
                        img[y, x:x + n, c] = np.frombuffer(data[pos:pos + n], np.uint8)
                        pos += n
                    x += n
        else:
            img[y] = np.frombuffer(data[pos:pos + 4 * w], np.uint8).reshape(w, 4)
            pos += 4 * w
    e = img[..., 3].astype(np.int32)
    scale = np.where(e > 0, np.ldexp(1.0, e - 136), 0.0)
    rgb = img[..., :3].astype(np.float64) * scale[..., None]
    return (rgb[::-1] if flip else rgb).astype(np.float32)


def write_exr(path, rgb):
    h, w, _ = rgb.shape

    def attr(name, typ, val):
        return name + b"\0" + typ + b"\0" + struct.pack("<i", len(val)) + val

    chans = b"".join(c + b"\0" + struct.pack("<iB3xii", 2, 0, 1, 1) for c in (b"B", b"G", b"R")) + b"\0"
    box = struct.pack("<iiii", 0, 0, w - 1, h - 1)
    head = b"\x76\x2f\x31\x01" + struct.pack("<i", 2)
    head += attr(b"channels", b"chlist", chans) + attr(b"compression", b"compression", b"\0")
    head += attr(b"dataWindow", b"box2i", box) + attr(b"displayWindow", b"box2i", box)
    head += attr(b"lineOrder", b"lineOrder", b"\0") + attr(b"pixelAspectRatio", b"float", struct.pack("<f", 1))
    head += attr(b"screenWindowCenter", b"v2f", struct.pack("<ff", 0, 0))
    head += attr(b"screenWindowWidth", b"float", struct.pack("<f", 1)) + b"\0"
    line = 8 + 12 * w
    start = len(head) + 8 * h
    out = [head, b"".join(struct.pack("<Q", start + y * line) for y in range(h))]
    for y in range(h):
        out.append(struct.pack("<ii", y, 12 * w))
        for c in (2, 1, 0):
            out.append(rgb[y, :, c].astype("<f4").tobytes())
    open(path, "wb").write(b"".join(out))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("input")
    ap.add_argument("output")
    ap.add_argument("--roll", type=float, default=0.0)
    a = ap.parse_args()
    rgb = read_hdr(a.input)
    if a.roll:
        rgb = np.roll(rgb, int(round(a.roll * rgb.shape[1])), axis=1)
    write_exr(a.output, rgb)


if __name__ == "__main__":
    main()
