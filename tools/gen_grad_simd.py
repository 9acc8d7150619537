#!/usr/bin/env python3
"""Tables of shli_sh_grad_avx512 in shlight.h (the AVX-512 gradient pass); imported by
tools/gen_basis.py, which writes them into the @generated gradv region.

Band l (1..15) writes its 2l+1 gradients, 3(2l+1) floats at out_grad + l*l, in chunks of 16
floats; local float f = 16 c + j is coefficient k = f // 3 (band order: k < l sine m = l - k,
k >= l cosine m = k - l) and component f % 3.  Each lane is
    out = c1 * P[i1] + c2 * P[i2] + Y[k] * w[f % 3]
where P is band l-1 of Y times the band's weight a_l (the kernel's), Y band l, both band order
and zero beyond their 2l-1 and 2l+1 lanes, w a per-band 3-vector; the c are the Cartesian
derivatives of the solid harmonic H_l^m in terms of band l-1 (gen_basis.grad_abc).  P and Y
are 32 lanes (two zmm) for l >= 8.  In band order YC_{l-1}[m] sits at
l-1+m and YS_{l-1}[m] at l-1-m, so with k the output position:
  cosine m = k-l: gx = Ap P[k-2] + Bp P[k]; gy = -A[m>=2] P[2l-k] + Bp P[2l-k-2]; gz = C P[k-1]
  sine   m = l-k: gx = A[m>=2] P[k] + B P[k-2]; gy = Ap P[2l-k-2] - B P[2l-k]; gz = C P[k-1]
The taps are put in one order for every band, so their lane indices do not depend on the
band except through 2l:
  tap 1: x k-2, y 2l-k-2, z k-1;  tap 2: x k, y 2l-k, z k-1 (coefficient 0)
i.e. SHLI_GRADV_TAP (per chunk c = 0..5, constant) plus 2l on the y lanes.  A tap outside band
l-1 (index < 0 or > 2l-2) has coefficient 0; the permute then reads some finite lane of P
(P is zero beyond its 2l-1 lanes, and the index is taken mod 16 or mod 32), so the product is 0.
"""
import math
import struct
import sys

NB = 16  # bands
S2 = math.sqrt(2.0)


from gen_basis import grad_abc  # the one definition of the coefficients


def lane_terms(l, k, comp):
    """[(tap, coef), (tap, coef)] for output position k (band order) and component comp, in
    the uniform tap order (module doc); taps outside band l-1 carry coefficient 0"""
    if k >= l:
        m = k - l
        a, b, c = grad_abc(l, m)
        ap = a * S2 if m == 1 else a
        bp = b * S2 if m == 0 else b
        cf = [(ap, bp), (bp, -a if m >= 2 else 0.0), (c, 0.0)][comp]
    else:
        m = l - k
        a, b, c = grad_abc(l, m)
        ap = a * S2 if m == 1 else a
        cf = [(b, a if m >= 2 else 0.0), (ap, -b), (c, 0.0)][comp]
    taps = tap_base(k, comp)
    if comp == 1:
        taps = (taps[0] + 2 * l, taps[1] + 2 * l)
    out = []
    for tap, v in zip(taps, cf):
        if v != 0.0:
            assert 0 <= tap <= 2 * l - 2, (l, k, comp, tap)
        out.append((tap, v))
    return out


def tap_base(k, comp):
    """the two P taps of position k, component comp, without the 2l of the y lanes"""
    return [(k - 2, k), (-k - 2, -k), (k - 1, k - 1)][comp]


def lit(v):
    if v == 0.0:
        return '0.0f'
    s = '%.9g' % v
    f = struct.unpack('f', struct.pack('f', v))[0]
    if struct.unpack('f', struct.pack('f', float(s)))[0] != f:
        s = '%.9g' % f  # 9 digits of v round to another float: the float nearest v
    if '.' not in s and 'e' not in s:
        s += '.0'
    return s + 'f'


def lit_short(v):
    """the shortest literal for the float that lit(v) gives (the same value, bit for bit)"""
    import struct
    f = struct.unpack('f', struct.pack('f', float(lit(v)[:-1])))[0]
    if f == 0.0:
        return '-0.0f' if math.copysign(1.0, f) < 0 else '0'
    for p in range(1, 10):
        s = '%.*g' % (p, f)
        if struct.unpack('f', struct.pack('f', float(s)))[0] == f:
            break
    if 'e' not in s and abs(f) < 1e6 and float(s) == int(float(s)):
        return '%d' % int(float(s))
    if 'e' not in s and '.' not in s:
        s += '.0'
    return s + 'f'


def fmt_rows(vals, per=8, ind='    '):
    rows = []
    for i in range(0, len(vals), per):
        rows.append(ind + ', '.join(vals[i:i + per]) + ',')
    return rows


def main():
    nchunk = [0] * (NB + 1)
    ch0 = [0] * (NB + 1)
    coef = []
    tot = 0
    for l in range(1, NB):
        ch0[l] = tot
        nf = 3 * (2 * l + 1)
        nc = (nf + 15) // 16
        for c in range(nc):
            c1 = []
            c2 = []
            for j in range(16):
                f = 16 * c + j
                if f >= nf:
                    (t1, a1), (t2, a2) = (0, 0.0), (0, 0.0)
                else:
                    (t1, a1), (t2, a2) = lane_terms(l, f // 3, f % 3)
                c1.append(a1)
                c2.append(a2)
            coef.append((l, c, c1, c2))
        tot += nc
    ch0[NB] = tot
    L = []
    w = L.append
    w('#define SHLI_GRADV_CHUNKS %d' % tot)
    w('/* first chunk of band l (l = 1..15; [16] = total) */')
    w('static const short SHLI_GRADV_CH0[17] = {%s};' % ', '.join(str(v) for v in ch0))
    w('/* l as a float */')
    w('static const float SHLI_GRADV_LF[16] = {%s};' % ', '.join('%d.0f' % l for l in range(NB)))
    w('/* mask of the last chunk of band l */')
    lm = []
    ym = []
    for l in range(NB):
        nf = 3 * (2 * l + 1)
        rem = nf - 16 * ((nf + 15) // 16 - 1)
        lm.append('0x%04X' % ((1 << rem) - 1))
        mk = (1 << (2 * l + 1)) - 1
        ym.append('0x%04X, 0x%04X' % (mk & 0xFFFF, mk >> 16))
    w('static const unsigned short SHLI_GRADV_LASTM[16] = {%s};' % ', '.join(lm))
    w('/* load masks of band l (2l+1 lanes), low and high zmm */')
    w('static const unsigned short SHLI_GRADV_YM[16 * 2] = {')
    L += fmt_rows(ym, 4)
    w('};')
    w('/* Q tap (coefficient k = f / 3 of the band) of chunk c = 0..5 */')
    w('SHLI_GRADV_ALIGN static const int SHLI_GRADV_IY[6 * 16] = {')
    iy = []
    for c in range(6):
        iy += [str(min((16 * c + j) // 3, 31)) for j in range(16)]
    L += fmt_rows(iy, 16)
    w('};')
    w('/* P taps of chunk c = 0..5 (tap 1, tap 2; 16 lanes each), plus 2l on the y lanes')
    w('   (lane j of chunk c is component (16 c + j) % 3) */')
    w('SHLI_GRADV_ALIGN static const int SHLI_GRADV_TAP[6 * 32] = {')
    for c in range(6):
        t1 = [tap_base((16 * c + j) // 3, (16 * c + j) % 3)[0] for j in range(16)]
        t2 = [tap_base((16 * c + j) // 3, (16 * c + j) % 3)[1] for j in range(16)]
        L += fmt_rows([str(v) for v in t1], 16)
        L += fmt_rows([str(v) for v in t2], 16)
    w('};')
    w('/* per chunk (band l = 1..15, its chunks in turn): coefficients of the two terms, 2 x 16 */')
    w('/* clang-format off */')
    w('SHLI_GRADV_ALIGN static const float SHLI_GRADV_COEF[SHLI_GRADV_CHUNKS * 32] = {')
    vals = [lit_short(v) for l, c, c1, c2 in coef for v in list(c1) + list(c2)]
    row = ''
    for i, v in enumerate(vals):
        item = v + (',' if i + 1 < len(vals) else '')
        if row and len(row) + 1 + len(item) > 98:
            L.append(row)
            row = ''
        row = (row + ' ' + item) if row else '    ' + item
    L.append(row)
    w('};')
    w('/* clang-format on */')
    return L


if __name__ == '__main__':
    sys.stdout.write('\n'.join(main()) + '\n')
