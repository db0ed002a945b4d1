#!/usr/bin/env python3
"""Writes tests/data/bad/huge_16384.png: a legal 16384x16384 PNG (1-bit grey,
all black, 33 KB on disk) that decodes to 268 M texels. The loaders must
refuse it from its header, before allocating. Run from anywhere; the output
is committed."""
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))

SIDE = 16384


def chunk(kind, data):
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)


def main():
    row = b"\x00" + b"\x00" * (SIDE // 8)  # filter byte "none", then 1 bit per texel
    header = struct.pack(">IIBBBBB", SIDE, SIDE, 1, 0, 0, 0, 0)  # 1-bit greyscale
    data = zlib.compress(row * SIDE, 9)
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", data) + chunk(b"IEND", b"")
    with open(os.path.join(HERE, "bad", "huge_16384.png"), "wb") as out:
        out.write(png)


if __name__ == "__main__":
    main()
