#!/usr/bin/env python3
"""png_sheet.py OUT.png IN1.png [IN2.png ...] - put shlrender's PNGs (8-bit RGB, same height)
side by side, 2-pixel white gaps, and write OUT.png compressed with zlib level 9 (shlrender
writes stored deflate blocks: no dependency there, small files here for docs/)."""
import struct, sys, zlib

def read(path):
    b = open(path, 'rb').read()
    i, idat = 8, b''
    while i + 12 <= len(b):
        n = struct.unpack('>I', b[i:i+4])[0]; t = b[i+4:i+8]; d = b[i+8:i+8+n]
        if t == b'IHDR':
            w, h, depth, ctype = struct.unpack('>IIBB', d[:10])
            assert depth == 8 and ctype == 2, path + ': not 8-bit RGB'
        if t == b'IDAT': idat += d
        i += 12 + n
    raw = zlib.decompress(idat)
    rows = []
    for y in range(h):
        r = raw[y * (3 * w + 1):(y + 1) * (3 * w + 1)]
        assert r[0] == 0, path + ': filtered rows are not supported'
        rows.append(r[1:])
    return w, h, rows

def main():
    out, ins = sys.argv[1], [read(p) for p in sys.argv[2:]]
    h = ins[0][1]
    assert all(i[1] == h for i in ins), 'images differ in height'
    gap = b'\xff' * 6
    raw = b''.join(b'\x00' + gap.join(i[2][y] for i in ins) for y in range(h))
    w = sum(i[0] for i in ins) + 2 * (len(ins) - 1)
    def chunk(t, d):
        return struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
    open(out, 'wb').write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 2, 0, 0, 0))
                          + chunk(b'IDAT', zlib.compress(raw, 9)) + chunk(b'IEND', b''))

main()
