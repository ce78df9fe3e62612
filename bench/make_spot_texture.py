#!/usr/bin/env python3
"""Draws a stand-in texture for Spot the cow (../shared/models/spot.obj has texture coordinates
but no image beside it): a 512x512 PNG of cream and brown patches on a grid of 16x16 cells, red
lines every 4 cells, so that the picture shows where the model's (u, v) put each part of the
image, its seams included. Written to bench/out/spot_texture.png, which bench/spot.toml uses.

    python3 bench/make_spot_texture.py
"""
import os
import struct
import zlib

SIZE, CELLS = 512, 16
CREAM, BROWN, RED = (236, 226, 204), (92, 58, 38), (200, 40, 40)


def texel(x, y):
    cell = SIZE // CELLS
    if x % (4 * cell) < 3 or y % (4 * cell) < 3:
        return RED
    return BROWN if (x // cell + y // cell) % 2 else CREAM


def png(width, height, pixel):
    rows = b"".join(b"\x00" + bytes(c for x in range(width) for c in pixel(x, y)) for y in range(height))
    chunk = lambda kind, data: struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))


out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "out", "spot_texture.png")
os.makedirs(os.path.dirname(out), exist_ok=True)
with open(out, "wb") as f:
    f.write(png(SIZE, SIZE, texel))
print(out)
