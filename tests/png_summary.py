#!/usr/bin/env python3
"""png_summary.py FILE - one JSON line on an 8-bit RGB(A) PNG, for tests that judge an image
without an imaging library: its size, its distinct colours, and how many distinct saturated
hues (twelve 30-degree sectors) cover at least 0.5% of it, which tells part colours from a
grey or single-colour image."""
import colorsys
import json
import struct
import sys
import zlib


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    return a if pa <= pb and pa <= pc else (b if pb <= pc else c)


def read_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(f"{path}: not a PNG")
    chunks, at = {}, 8
    while at < len(data):
        size, name = struct.unpack(">I4s", data[at:at + 8])
        chunks.setdefault(name, []).append(data[at + 8:at + 8 + size])
        at += 12 + size
    width, height, depth, kind = struct.unpack(">IIBB", chunks[b"IHDR"][0][:10])
    channels = {2: 3, 6: 4}.get(kind)
    if depth != 8 or channels is None:
        raise ValueError(f"{path}: expected 8-bit RGB or RGBA, got depth {depth} type {kind}")
    raw = zlib.decompress(b"".join(chunks[b"IDAT"]))
    stride, above, pixels = width * channels, bytearray(width * channels), []
    for y in range(height):
        start = y * (stride + 1)
        method, row = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        for i in range(stride):
            left = row[i - channels] if i >= channels else 0
            corner = above[i - channels] if i >= channels else 0
            guess = (0, left, above[i], (left + above[i]) // 2, paeth(left, above[i], corner))
            row[i] = (row[i] + guess[method]) & 255
        pixels += [tuple(row[i:i + 3]) for i in range(0, stride, channels)]
        above = row
    return width, height, pixels


def main():
    width, height, pixels = read_png(sys.argv[1])
    sectors = {}
    for r, g, b in pixels:
        h, s, v = colorsys.rgb_to_hsv(r / 255, g / 255, b / 255)
        if s > 0.12 and v > 0.15:
            sectors[int(h * 12) % 12] = sectors.get(int(h * 12) % 12, 0) + 1
    hues = sum(1 for n in sectors.values() if n >= 0.005 * len(pixels))
    print(json.dumps({"width": width, "height": height, "colours": len(set(pixels)),
                      "hues": hues}))


if __name__ == "__main__":
    main()
