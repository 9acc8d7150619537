#!/usr/bin/env python3
"""Writes the seed corpus of tests/fuzz_brdftab.c into tests/corpus/brdftab/ (stdlib only).
Each file: one selector byte (bit 0: 0 SHLT, 1 MERL; bits 1-2: storage mode), then the file.
Valid SHLT / MERL files and one of each broken kind the loaders must reject."""
import os
import struct
import zlib

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'corpus', 'brdftab')


def shlt(n, nt, nphi, flags=None, version=2, magic=b'SHLT', count=None, vals=None, crc=None,
         grid=1, reserved=0):
    if flags is None:
        flags = 1 if nphi > 1 else 0
    c = nphi * nt * 2 * n * n
    if count is None:
        count = c
    if vals is None:
        vals = [0.01 * ((i * 37) % 101 - 50) for i in range(c)]
    head = magic + struct.pack('<IiiiII', version, n, nt, nphi, flags, count)
    if version != 1:  # version 2: grid id and a reserved word before the CRC
        head += struct.pack('<II', grid, reserved)
    pay = struct.pack('<%df' % len(vals), *vals)
    if crc is None:
        crc = zlib.crc32(pay, zlib.crc32(head)) & 0xffffffff
    return head + struct.pack('<I', crc) + pay


def merl(dims, vals=None):
    c = 3 * dims[0] * dims[1] * dims[2]
    if vals is None:
        vals = [float((i * 13) % 17) for i in range(c)]
    return struct.pack('<3i', *dims) + struct.pack('<%dd' % len(vals), *vals)


def main():
    os.makedirs(OUT, exist_ok=True)
    files = {}
    good = shlt(2, 3, 1)
    files['shlt_valid_iso'] = b'\x00' + good
    files['shlt_valid_aniso'] = b'\x00' + shlt(1, 2, 3)
    files['shlt_short_storage'] = b'\x02' + good
    files['shlt_no_storage'] = b'\x04' + good
    files['shlt_big_storage'] = b'\x06' + good
    files['shlt_truncated_header'] = b'\x00' + good[:36]
    files['shlt_truncated_payload'] = b'\x00' + good[:-3]
    files['shlt_trailing_byte'] = b'\x00' + good + b'\x00'
    files['shlt_bad_magic'] = b'\x00' + shlt(2, 3, 1, magic=b'SHLX')
    files['shlt_bad_version'] = b'\x00' + shlt(2, 3, 1, version=3)
    files['shlt_version1'] = b'\x00' + shlt(2, 3, 1, version=1)
    files['shlt_unknown_grid'] = b'\x00' + shlt(2, 3, 1, grid=2)
    files['shlt_reserved_set'] = b'\x00' + shlt(2, 3, 1, reserved=1)
    files['shlt_zero_bands'] = b'\x00' + shlt(0, 3, 1, count=0, vals=[])
    files['shlt_huge_dims'] = b'\x00' + shlt(64, 4096, 4096, count=0, vals=[])
    files['shlt_negative_theta'] = b'\x00' + shlt(2, -3, 1, count=24, vals=[0.0] * 24)
    files['shlt_bad_flags'] = b'\x00' + shlt(2, 3, 1, flags=1)
    files['shlt_unknown_flag'] = b'\x00' + shlt(2, 3, 1, flags=4)
    files['shlt_count_mismatch'] = b'\x00' + shlt(2, 3, 1, count=23, vals=[0.0] * 23)
    files['shlt_bad_crc'] = b'\x00' + shlt(2, 3, 1, crc=12345)
    files['shlt_nan'] = b'\x00' + shlt(1, 2, 1, vals=[0.0, float('nan'), 0.0, 0.0])
    files['shlt_inf'] = b'\x00' + shlt(1, 2, 1, vals=[0.0, 0.0, float('inf'), 0.0])
    mgood = merl((2, 3, 4))
    files['merl_valid'] = b'\x01' + mgood
    files['merl_valid_1x1x1'] = b'\x01' + merl((1, 1, 1), [1.0, -1.0, 2.0])
    files['merl_short_storage'] = b'\x03' + mgood
    files['merl_truncated_header'] = b'\x01' + mgood[:7]
    files['merl_truncated_payload'] = b'\x01' + mgood[:-1]
    files['merl_trailing'] = b'\x01' + mgood + b'\x00' * 8
    files['merl_zero_dim'] = b'\x01' + struct.pack('<3i', 90, 0, 180)
    files['merl_huge_dim'] = b'\x01' + struct.pack('<3i', 90, 90, 100000)
    files['merl_negative_dim'] = b'\x01' + struct.pack('<3i', -90, 90, 180)
    files['merl_nan'] = b'\x01' + merl((1, 1, 2), [0.0, float('nan'), 0.0, 0.0, 0.0, 0.0])
    files['merl_inf'] = b'\x01' + merl((1, 1, 1), [0.0, float('-inf'), 0.0])
    files['merl_overflow_float'] = b'\x01' + merl((1, 1, 1), [0.0, 1e300, 0.0])
    files['empty'] = b''
    for name, data in sorted(files.items()):
        with open(os.path.join(OUT, name), 'wb') as f:
            f.write(data)
    print('wrote %d files to %s' % (len(files), os.path.relpath(OUT)))


if __name__ == '__main__':
    main()
