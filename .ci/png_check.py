#!/usr/bin/env python3
"""Tell a rendered frame from a blank one: read a PNG (stdlib only) and fail when nearly all
pixels share one colour or the picture has hardly any colours.

usage: png_check.py FILE [MAX_SHARE_PERCENT] [MIN_COLOURS]
"""
import collections
import struct
import sys
import zlib


def read_png(path):
    with open(path, 'rb') as f:
        data = f.read()
    if data[:8] != b'\x89PNG\r\n\x1a\n':
        raise ValueError('not a PNG file')
    pos, idat = 8, b''
    width = height = depth = colour = None
    while pos < len(data):
        length, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b'IHDR':
            width, height, depth, colour, _, _, interlace = struct.unpack('>IIBBBBB', body)
            if depth != 8 or colour not in (2, 6) or interlace != 0:
                raise ValueError('only 8-bit RGB/RGBA, non-interlaced PNGs are read')
        elif kind == b'IDAT':
            idat += body
        elif kind == b'IEND':
            break
    channels = 3 if colour == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * channels
    previous = bytearray(stride)
    pixels = collections.Counter()
    for row in range(height):
        start = row * (stride + 1)
        kind = raw[start]
        line = bytearray(raw[start + 1:start + 1 + stride])
        for i in range(stride):
            left = line[i - channels] if i >= channels else 0
            up = previous[i]
            upper_left = previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + left) & 0xff
            elif kind == 2:
                line[i] = (line[i] + up) & 0xff
            elif kind == 3:
                line[i] = (line[i] + (left + up) // 2) & 0xff
            elif kind == 4:
                p = left + up - upper_left
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - upper_left)
                pred = left if pa <= pb and pa <= pc else (up if pb <= pc else upper_left)
                line[i] = (line[i] + pred) & 0xff
        for i in range(0, stride, channels):
            pixels[bytes(line[i:i + 3])] += 1
        previous = line
    return width, height, pixels


def main():
    path = sys.argv[1]
    max_share = float(sys.argv[2]) if len(sys.argv) > 2 else 92.0
    min_colours = int(sys.argv[3]) if len(sys.argv) > 3 else 64
    width, height, pixels = read_png(path)
    share = 100.0 * pixels.most_common(1)[0][1] / (width * height)
    print('%s: %dx%d, %d colours, the most common covers %.1f%%'
          % (path, width, height, len(pixels), share))
    if share > max_share or len(pixels) < min_colours:
        print('%s looks blank (limits: at most %.1f%% one colour, at least %d colours)'
              % (path, max_share, min_colours), file=sys.stderr)
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main())
