#!/usr/bin/env python3
"""png_err.py OUT.png TEST.png REF.png [GAIN] - the error image |TEST - REF| x GAIN (default 10)
of two shlrender PNGs of the same pass (same exposure), taken in linear light (sRGB decoded,
the difference scaled, sRGB encoded), written with zlib level 9. The 8-bit inputs limit it to
about 0.4 % of the exposure's white per step before the gain."""
import struct, sys, zlib


def read(path):
    """(w, h, rows) of an 8-bit RGB PNG with unfiltered rows (shlrender's), as png_sheet.py"""
    b = open(path, 'rb').read()
    i, idat, w, h = 8, b'', 0, 0
    while i + 12 <= len(b):
        n = struct.unpack('>I', b[i:i + 4])[0]
        t, d = b[i + 4:i + 8], b[i + 8:i + 8 + n]
        if t == b'IHDR':
            w, h, depth, ctype = struct.unpack('>IIBB', d[:10])
            assert depth == 8 and ctype == 2, path + ': not 8-bit RGB'
        if t == b'IDAT':
            idat += d
        i += 12 + n
    raw = zlib.decompress(idat)
    rows = []
    for y in range(h):
        r = raw[y * (3 * w + 1):(y + 1) * (3 * w + 1)]
        assert r[0] == 0, path + ': filtered rows are not supported'
        rows.append(r[1:])
    return w, h, rows


def lin(v):
    c = v / 255.0
    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4


def enc(c):
    c = min(max(c, 0.0), 1.0)
    s = 12.92 * c if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055
    return int(round(255.0 * s))


def main():
    out, a, b = sys.argv[1], read(sys.argv[2]), read(sys.argv[3])
    gain = float(sys.argv[4]) if len(sys.argv) > 4 else 10.0
    w, h = a[0], a[1]
    assert (w, h) == (b[0], b[1]), 'sizes differ'
    L = [lin(i) for i in range(256)]
    rows = []
    for y in range(h):
        ra, rb = a[2][y], b[2][y]
        rows.append(b'\x00' + bytes(enc(gain * abs(L[ra[i]] - L[rb[i]])) for i in range(3 * w)))
    def chunk(t, d):
        return struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
    png = (b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 2, 0, 0, 0)) +
           chunk(b'IDAT', zlib.compress(b''.join(rows), 9)) + chunk(b'IEND', b''))
    open(out, 'wb').write(png)


if __name__ == '__main__':
    main()
