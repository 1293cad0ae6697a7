#!/usr/bin/env python3
"""Mean colour (0..1) of a rectangle of an X window dump (xwd -id WID, ZPixmap at 24 or 32 bits).

usage: window_mean.py FILE.xwd X Y W H  -> prints "mean min_channel_mean" (the rectangle's mean over
R, G and B, and its darkest channel's mean). Standard library only, so the UI tests need no ImageMagick.
"""
import struct
import sys


def read_xwd(path):
    data = open(path, "rb").read()
    fields = struct.unpack(">25I", data[:100])
    header_size, _, fmt, depth, width, height = fields[0:6]
    byte_order, bits_per_pixel, bytes_per_line = fields[7], fields[11], fields[12]
    red_mask, green_mask, blue_mask = fields[15:18]
    ncolors = fields[19]
    if fmt != 2 or bits_per_pixel not in (24, 32):
        raise SystemExit(f"{path}: not a 24/32-bit ZPixmap dump (format {fmt}, {bits_per_pixel} bits)")
    offset = header_size + 12 * ncolors
    return data[offset:], width, height, bytes_per_line, bits_per_pixel // 8, byte_order, (red_mask, green_mask, blue_mask)


def channel(pixel, mask):
    shift = (mask & -mask).bit_length() - 1
    return ((pixel & mask) >> shift) / float(mask >> shift)


def main():
    path, x, y, w, h = sys.argv[1], *map(int, map(float, sys.argv[2:6]))
    pixels, width, height, stride, size, order, masks = read_xwd(path)
    x0, y0 = max(x, 0), max(y, 0)
    x1, y1 = min(x + w, width), min(y + h, height)
    if x1 <= x0 or y1 <= y0:
        raise SystemExit(f"{path}: the rectangle {x},{y} {w}x{h} lies outside the {width}x{height} dump")
    sums = [0.0, 0.0, 0.0]
    count = 0
    endian = "little" if order == 0 else "big"
    for row in range(y0, y1, 2):  # every other row and column: plenty for a mean
        base = row * stride
        for col in range(x0, x1, 2):
            p = int.from_bytes(pixels[base + col * size: base + col * size + size], endian)
            for i, m in enumerate(masks):
                sums[i] += channel(p, m)
            count += 1
    means = [s / count for s in sums]
    print(f"{sum(means) / 3:.4f} {min(means):.4f}")


main()
