#!/usr/bin/env python3
"""POV-Ray's render of lancer's own sample grid, for comparing pictures rather than sampling.

POV-Ray's anti-aliasing (+A0.0 +AM1 +R3) averages a pixel's centre with a 3 x 3 grid, counting the
centre twice; lancer averages exactly the 3 x 3 grid. Where a picture has many edges that alone
costs a few dB. So for the picture comparison POV-Ray renders the scene K times larger without
anti-aliasing, in linear light (+FN16 File_Gamma=1.0): its pixel centres are then lancer's K x K
sample positions. This script averages each K x K block in linear light, as lancer does, and
writes the sRGB-encoded 8-bit PNG that lancer would have written.

    bench/pov_supersample.py K IN.png OUT.png    (IN: 16-bit linear RGB PNG, K times OUT's size)
"""
import struct
import sys
import zlib


def read_png16(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit(f"{path}: not a PNG")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
    width, height, depth, colour, _, _, interlace = header
    if depth != 16 or colour != 2 or interlace:
        sys.exit(f"{path}: expected a 16-bit RGB PNG without interlacing")
    bpp, stride = 6, width * 6
    raw, rows, prev, p = zlib.decompress(idat), [], bytearray(stride), 0
    for _ in range(height):
        kind, line = raw[p], bytearray(raw[p + 1:p + 1 + stride])
        p += 1 + stride
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(struct.unpack(f">{width * 3}H", bytes(line)))
        prev = line
    return width, height, rows


def srgb8(linear):
    c = min(max(linear, 0.0), 1.0)
    c = c * 12.92 if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055
    return int(c * 255 + 0.5)


def write_png8(path, width, height, pixels):
    raw = b"".join(b"\x00" + bytes(pixels[y * width * 3:(y + 1) * width * 3]) for y in range(height))
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b"")
    open(path, "wb").write(png)


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    k = int(sys.argv[1])
    width, height, rows = read_png16(sys.argv[2])
    if width % k or height % k:
        sys.exit(f"{sys.argv[2]}: {width}x{height} is not a multiple of {k}")
    out_w, out_h, scale = width // k, height // k, 1.0 / (65535.0 * k * k)
    pixels = bytearray(out_w * out_h * 3)
    for y in range(out_h):
        block = rows[y * k:(y + 1) * k]
        for x in range(out_w):
            for c in range(3):
                total = sum(row[(x * k + i) * 3 + c] for row in block for i in range(k))
                pixels[(y * out_w + x) * 3 + c] = srgb8(total * scale)
    write_png8(sys.argv[3], out_w, out_h, pixels)


if __name__ == "__main__":
    main()
