#!/usr/bin/env python3
"""Writes assets/environments/studio.hdr: a procedural photo-studio panorama
(Radiance RGBE, equirectangular, 512x256) for the example scene
assets/scenes/studio.json. Standard library only, deterministic.

Layout, in shadelab's panorama convention (centre column looks along -z,
u = 0.75 along +x, top row straight up): a chequered floor at y = -1 fading
into the distance, dark walls brightening toward the horizon, a large cool
softbox up and to the left of -z, a warm one to the right, a blue strip light
behind (+z)."""
import math
import pathlib
import struct

WIDTH, HEIGHT = 512, 256
SUPERSAMPLE = 3

# (centre azimuth from -z toward +x in degrees, elevation in degrees,
#  half width, half height in degrees, radiance)
SOFTBOXES = [
    (-35.0, 32.0, 16.0, 11.0, (7.0, 7.2, 7.6)),
    (70.0, 18.0, 9.0, 14.0, (4.0, 2.6, 1.4)),
    (180.0, 8.0, 30.0, 2.5, (0.6, 1.2, 3.0)),
]


def direction(u, v):
    longitude = (u - 0.5) * 2.0 * math.pi
    polar = v * math.pi
    ring = math.sin(polar)
    return (ring * math.sin(longitude), math.cos(polar), -ring * math.cos(longitude))


def radiance(d):
    x, y, z = d
    azimuth = math.degrees(math.atan2(x, -z))
    elevation = math.degrees(math.asin(max(-1.0, min(1.0, y))))
    for centre, height, half_w, half_h, light in SOFTBOXES:
        da = (azimuth - centre + 180.0) % 360.0 - 180.0
        if abs(da) < half_w and abs(elevation - height) < half_h:
            return light
    if y >= 0.0:
        t = math.sqrt(y)
        return tuple(h + (top - h) * t for h, top in zip((0.32, 0.31, 0.3), (0.04, 0.045, 0.06)))
    # Floor plane y = -1: 1 m checker squares fading to grey with distance.
    s = -1.0 / y
    px, pz = x * s, z * s
    checker = 0.16 if (math.floor(px) + math.floor(pz)) % 2 == 0 else 0.07
    fade = math.exp(-math.hypot(px, pz) / 12.0)
    value = 0.12 + (checker - 0.12) * fade
    return (value, value, value * 0.95)


def rgbe(color):
    brightest = max(color)
    if brightest < 1e-32:
        return bytes(4)
    mantissa, exponent = math.frexp(brightest)
    scale = mantissa * 256.0 / brightest
    return bytes([int(c * scale) for c in color] + [exponent + 128])


def rle_channel(values):
    """Radiance's run-length code for one channel of one scanline."""
    out = bytearray()
    i = 0
    while i < len(values):
        run = 1
        while i + run < len(values) and run < 127 and values[i + run] == values[i]:
            run += 1
        if run >= 4:
            out += bytes([128 + run, values[i]])
            i += run
            continue
        start = i
        while i < len(values) and i - start < 128:
            if i + 3 < len(values) and values[i] == values[i + 1] == values[i + 2] == values[i + 3]:
                break
            i += 1
        out += bytes([i - start]) + bytes(values[start:i])
    return out


def rle_scanline(row):
    encoded = bytearray([2, 2, WIDTH >> 8, WIDTH & 255])
    for channel in range(4):
        encoded += rle_channel(row[channel::4])
    return bytes(encoded)


def main():
    rows = []
    for j in range(HEIGHT):
        row = bytearray()
        for i in range(WIDTH):
            total = [0.0, 0.0, 0.0]
            for sj in range(SUPERSAMPLE):
                for si in range(SUPERSAMPLE):
                    u = (i + (si + 0.5) / SUPERSAMPLE) / WIDTH
                    v = (j + (sj + 0.5) / SUPERSAMPLE) / HEIGHT
                    for c, value in enumerate(radiance(direction(u, v))):
                        total[c] += value
            row += rgbe([t / SUPERSAMPLE**2 for t in total])
        rows.append(rle_scanline(bytes(row)))
    header = f"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y {HEIGHT} +X {WIDTH}\n".encode()
    out = pathlib.Path(__file__).resolve().parent.parent / "assets" / "environments" / "studio.hdr"
    out.write_bytes(header + b"".join(rows))
    print(f"wrote {out} ({WIDTH}x{HEIGHT})")


if __name__ == "__main__":
    main()
