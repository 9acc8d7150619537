#!/usr/bin/env python3
"""png_check.py FILE W H - decode an 8-bit RGB PNG with Python's zlib and crc32 (independent of
render/rd_core.c's writer): signature, chunk CRCs, IHDR, the filter bytes, the pixel count.
Prints "N passed, N failed"."""
import struct, sys, zlib
path, w, h = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
ok = fail = 0
def check(c, what):
    global ok, fail
    if c: ok += 1
    else: fail += 1; print("FAIL png_check:", what)
b = open(path, 'rb').read()
check(b[:8] == b'\x89PNG\r\n\x1a\n', 'signature')
i, idat, chunks = 8, b'', []
while i + 12 <= len(b):
    n = struct.unpack('>I', b[i:i+4])[0]; t = b[i+4:i+8]; d = b[i+8:i+8+n]
    crc = struct.unpack('>I', b[i+8+n:i+12+n])[0]
    check(crc == zlib.crc32(t + d) & 0xffffffff, 'crc of ' + t.decode('latin1'))
    chunks.append(t)
    if t == b'IHDR':
        check(struct.unpack('>IIBBBBB', d) == (w, h, 8, 2, 0, 0, 0), 'IHDR')
    if t == b'IDAT': idat += d
    i += 12 + n
check(chunks[0] == b'IHDR' and chunks[-1] == b'IEND', 'chunk order')
raw = zlib.decompress(idat)
check(len(raw) == h * (3 * w + 1), 'decoded size')
check(all(raw[y * (3 * w + 1)] == 0 for y in range(h)), 'filter bytes')
print("%d passed, %d failed" % (ok, fail))
sys.exit(1 if fail else 0)
