#!/usr/bin/env python3
"""Generates shlight's straight-line SH code: the basis (Reinsch-form recurrence), its
gradient (solid-harmonic identities) and the SIMD batch kernels, for n = 1..UNROLLED bands,
plus the constant tables of the run-time loops. Writes the regions between
'@generated begin NAME' and '@generated end NAME' markers in shlight.h and shlight_glsl/.

  python3 tools/gen_basis.py          rewrite the regions
  python3 tools/gen_basis.py --check  exit 1 if a region is stale (CI)

Math (docs/derivations.md sections 1 and 3, errata applied):
  X_l^m(z): normalised associated Legendre / sin^m, Condon-Shortley phase;
  Y_l^m = X_l^m U_m, Y_l^-m = X_l^m V_m, U_m + i V_m = (x + i y)^m.
  Reinsch form with t = 1 - |z|, g_l = X_l(1)/X_{l-1}(1), c_l = beta_l / g_{l-1}:
    D_{m+1} = -alpha t X_m,  D_l = c_l D_{l-1} - alpha_l t X_{l-1},  X_l = g_l X_{l-1} + D_l,
  evaluated at |z|, with the sign (-1)^(l-m) restored through U, V (parity).
  Gradient of Y(d/|d|): (grad H_l(n) - l Y_l(n) n) / |d|, H_l the solid harmonic, whose
  Cartesian derivatives are <= 2 terms of band l-1 (coefficients A, B, C below).
"""
import math
import re
import os
import sys

UNROLLED = 16      # straight-line code for n <= UNROLLED
MAX_BANDS = 64     # tables for the run-time loops
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))


def lit_d(v):
    """double literal in C, float literal in GLSL (no suffix), always with a dot"""
    s = repr(float(v))
    if 'e' in s or 'E' in s:
        mant, ex = s.lower().split('e')
        if '.' not in mant:
            mant += '.0'
        s = mant + 'e' + ex
    elif '.' not in s:
        s += '.0'
    return s


def f32(v):
    """v rounded to float"""
    import struct
    return struct.unpack('f', struct.pack('f', v))[0]


def lit_fr(v):
    """lit_f(v), or lit_f of the float nearest v where 9 digits of v round to another float"""
    return lit_f(v) if f32(float(lit_f(v)[:-1])) == f32(v) else lit_f(f32(v))


def lit_frs(v):
    """the shortest float literal of the float that lit_fr(v) gives (C-only code)"""
    f = f32(float(lit_fr(v)[:-1]))
    for p in range(1, 10):
        s = '%.*g' % (p, f)
        if f32(float(s)) == f:
            break
    if 'e' not in s and '.' not in s:
        s += '.0'
    return s + 'f'


def lit_f(v):
    s = '%.9g' % float(v)
    if 'e' in s:
        mant, ex = s.split('e')
        if '.' not in mant:
            mant += '.0'
        s = mant + 'e' + ex
    elif '.' not in s:
        s += '.0'
    return s + 'f'


def alpha(l, m):
    return math.sqrt((2 * l + 1) * (2 * l - 1) / ((l - m) * (l + m)))


def beta(l, m):
    if l == m + 1:
        return 0.0
    return math.sqrt((2 * l + 1) * (l + m - 1) * (l - m - 1) / ((2 * l - 3) * (l - m) * (l + m)))


def diag(m):
    """X_m^m (a constant; sin^m and the azimuth live in U_m, V_m)"""
    v = 0.5 / math.sqrt(math.pi)
    for k in range(1, m + 1):
        v *= -math.sqrt((2 * k + 1) / (2 * k)) * (math.sqrt(2.0) if k == 1 else 1.0)
    return v


def reinsch(l, m):
    """(alpha, g, c) of step l in column m; X(1) values carried in double"""
    x2, x1 = 0.0, diag(m)
    gprev = 0.0
    for k in range(m + 1, l + 1):
        a, b = alpha(k, m), beta(k, m)
        x = a * x1 - b * x2
        g = x / x1
        c = 0.0 if k == m + 1 else b / gprev
        if k == l:
            return a, g, c
        gprev, x2, x1 = g, x1, x


def grad_abc(l, m):
    """coefficients of grad H_l^{+-m} in band l-1 (m >= 0)"""
    f = (2 * l + 1) / (2 * l - 1)
    a = -0.5 * math.sqrt(f * (l + m) * (l + m - 1)) if m >= 1 else 0.0
    b = 0.5 * math.sqrt(f * max(0, (l - m) * (l - m - 1)))
    c = math.sqrt(f * (l - m) * (l + m))
    return a, b, c


def idx(l, m):
    return l * (l + 1) + m


# ---------------------------------------------------------------- scalar basis (mirrored)
def gen_core(n):
    """shli_sh_core_<n>(x, y, z, t, sg, out_y): x, y, z unit; t = 1 - |z|; sg = sign(z)"""
    L = []
    w = L.append
    w('SHLIGHT_INLINE void shli_sh_core_%d(shli_real x, shli_real y, shli_real z, shli_real t,' % n)
    w('                                   float sg, float *out_y) {')
    if n == 1:
        w('  SHLIGHT_UNUSED(x);')
        w('  SHLIGHT_UNUSED(y);')
        w('  SHLIGHT_UNUSED(z);')
        w('  SHLIGHT_UNUSED(t);')
        w('  SHLIGHT_UNUSED(sg);')
        w('  out_y[0] = %s;' % lit_f(diag(0)))
        w('}')
        return L
    w('  SHLIGHT_UNUSED(z);')
    w('@DECLS@')
    for m in range(n):
        if m == 1:
            pass
        elif m >= 2:
            w('  qc = x * pc - y * ps;')
            w('  ps = x * ps + y * pc;')
            w('  pc = qc;')
        k = diag(m)
        if m == 0:
            w('  out_y[0] = %s;' % lit_f(k))
        else:
            w('  fc = SHLIGHT_FLOAT(pc);')
            w('  fs = SHLIGHT_FLOAT(ps);')
            w('  out_y[%d] = %s * fc;' % (idx(m, m), lit_f(k)))
            w('  out_y[%d] = %s * fs;' % (idx(m, -m), lit_f(k)))
            if m + 1 < n:
                w('  gc = sg * fc;')
                w('  gs = sg * fs;')
        if m + 1 >= n:
            continue
        # l = m + 1
        a, g, c = reinsch(m + 1, m)
        w('  dd = %s * t;' % lit_d(-a * k))
        w('  xa = %s + dd;' % lit_d(g * k))
        prev = 'xa'
        cur = 'xb'
        for l in range(m + 1, n):
            if l > m + 1:
                a, g, c = reinsch(l, m)
                w('  dd = %s * dd - %s * (t * %s);' % (lit_d(c), lit_d(a), prev))
                w('  %s = %s * %s + dd;' % (cur, lit_d(g), prev))
                prev, cur = cur, prev
            odd = (l - m) % 2 == 1
            if m == 0:
                if odd:
                    w('  out_y[%d] = sg * SHLIGHT_FLOAT(%s);' % (idx(l, 0), prev))
                else:
                    w('  out_y[%d] = SHLIGHT_FLOAT(%s);' % (idx(l, 0), prev))
            else:
                w('  xf = SHLIGHT_FLOAT(%s);' % prev)
                w('  out_y[%d] = xf * %s;' % (idx(l, m), 'gc' if odd else 'fc'))
                w('  out_y[%d] = xf * %s;' % (idx(l, -m), 'gs' if odd else 'fs'))
    w('}')
    return declare(L, [('shli_real', 'pc', 'x'), ('shli_real', 'ps', 'y'), ('shli_real', 'qc', None),
                       ('float', 'fc', None), ('float', 'fs', None), ('float', 'gc', None),
                       ('float', 'gs', None), ('shli_real', 'xa', None), ('shli_real', 'xb', None),
                       ('shli_real', 'dd', None), ('float', 'xf', None)])


def gen_core_any(nmax):
    """shli_sh_core(n, x, y, z, t, sg, out_y): any 1 <= n <= nmax in one body, the column-m
    recurrence of gen_core with each band's step under `if (n > l)` and, for GLSL (and C
    builds with a smaller SHLIGHT_MAX_BANDS), under `#if SHLIGHT_MAX_BANDS > l`: a shader
    compiles only the bands it can use, and a constant n folds every test away."""
    L = []
    w = L.append
    w('SHLIGHT_INLINE void shli_sh_core(int n, shli_real x, shli_real y, shli_real z, shli_real t,')
    w('                                 float sg, float *out_y) {')
    w('@DECLS@')
    w('  SHLIGHT_UNUSED(z);')
    w('#if SHLIGHT_MAX_BANDS > SHLIGHT_UNROLLED_BANDS')
    w('  if (n > SHLIGHT_UNROLLED_BANDS) {')
    w('    shli_sh_core_loop(n, x, y, z, t, sg, out_y);')
    w('    return;')
    w('  }')
    w('#endif')
    for m in range(nmax):
        k = diag(m)
        if m == 0:
            w('  out_y[0] = %s;' % lit_f(k))
        else:
            w('#if SHLIGHT_MAX_BANDS > %d' % m)
            w('  if (n > %d) {' % m)
            if m >= 2:
                w('    qc = x * pc - y * ps;')
                w('    ps = x * ps + y * pc;')
                w('    pc = qc;')
            w('    fc = SHLIGHT_FLOAT(pc);')
            w('    fs = SHLIGHT_FLOAT(ps);')
            w('    out_y[%d] = %s * fc;' % (idx(m, m), lit_f(k)))
            w('    out_y[%d] = %s * fs;' % (idx(m, -m), lit_f(k)))
            if m + 1 < nmax:
                w('    gc = sg * fc;')
                w('    gs = sg * fs;')
            w('  }')
            w('#endif')
        prev, cur = 'xa', 'xb'
        if m < CORE_LOOP_COLS and m + 1 < nmax:
            L.extend(core_col_call(m))
        for l in range(m + 1, nmax):
            w('#if SHLIGHT_MAX_BANDS > %d' % l)
            w('  if (n > %d) {' % l)
            a, g, c = reinsch(l, m)
            if l == m + 1:
                w('    dd = %s * t;' % lit_d(-a * k))
                w('    xa = %s + dd;' % lit_d(g * k))
            else:
                w('    dd = %s * dd - %s * (t * %s);' % (lit_d(c), lit_d(a), prev))
                w('    %s = %s * %s + dd;' % (cur, lit_d(g), prev))
                prev, cur = cur, prev
            odd = (l - m) % 2 == 1
            if m == 0:
                if odd:
                    w('    out_y[%d] = sg * SHLIGHT_FLOAT(%s);' % (idx(l, 0), prev))
                else:
                    w('    out_y[%d] = SHLIGHT_FLOAT(%s);' % (idx(l, 0), prev))
            else:
                w('    xf = SHLIGHT_FLOAT(%s);' % prev)
                w('    out_y[%d] = xf * %s;' % (idx(l, m), 'gc' if odd else 'fc'))
                w('    out_y[%d] = xf * %s;' % (idx(l, -m), 'gs' if odd else 'fs'))
            w('  }')
            w('#endif')
        if m < CORE_LOOP_COLS and m + 1 < nmax:
            w('#endif')
    w('}')
    return declare(L, [('shli_real', 'pc', 'x'), ('shli_real', 'ps', 'y'), ('shli_real', 'qc', None),
                       ('float', 'fc', '0.0f'), ('float', 'fs', '0.0f'), ('float', 'gc', '0.0f'),
                       ('float', 'gs', '0.0f'), ('shli_real', 'xa', '0.0'), ('shli_real', 'xb', '0.0'),
                       ('shli_real', 'dd', '0.0'), ('float', 'xf', None)])


def core_col_call(m):
    """GLSL (SHLIGHT_BY_BANDS 1): column m < CORE_LOOP_COLS through shli_sh_core_col and a
    copy loop; C: the straight-line steps that follow, up to the matching #endif"""
    k = diag(m)
    L = ['#if SHLIGHT_BY_BANDS',
         '#if SHLIGHT_MAX_BANDS > %d' % (m + 1),
         '  if (n > %d) {' % (m + 1),
         '    float xs[16];',
         '    int l;',
         '    shli_sh_core_col(%d, t, %s, xs);' % (m, lit_d(k)),
         '    for (l = %d; l < SHLIGHT_MAX_BANDS; ++l) {' % (m + 1),
         '      if (n > l) {']
    if m == 0:
        L.append('        out_y[l * l + l] = l % 2 == 1 ? sg * xs[l] : xs[l];')
    else:
        L.append('        out_y[l * l + l + %d] = xs[l] * ((l - %d) %% 2 == 1 ? gc : fc);' % (m, m))
        L.append('        out_y[l * l + l - %d] = xs[l] * ((l - %d) %% 2 == 1 ? gs : fs);' % (m, m))
    L += ['      }', '    }', '  }', '#endif', '#else']
    return L


CORE_LOOP_COLS = 6  # columns m < 6 (75 of the 120 steps at 16 bands) run shli_sh_core_col


# column m of the basis (1 <= l < 16 in order, l <= m zero): the recurrence of shli_sh_core's
# straight-line steps with the coefficients computed on the way; xs[l], 16 entries, indexed by
# the counter of a 16-trip loop makes shader compilers unroll it whatever the body costs.
CORE_COL = '''SHLIGHT_INLINE void shli_sh_core_col(int m, shli_real t, shli_real k, float *out_xs) {
  shli_real dd = 0.0;
  shli_real xa = 0.0;
  shli_real gp = 1.0;
  shli_real al;
  shli_real g;
  int l;
  for (l = 0; l < 16; ++l) {
    out_xs[l] = 0.0f;
    if (l > m) {
      al = SHLIGHT_SQRTR(SHLIGHT_ITOR((2 * l + 1) * (2 * l - 1)) / SHLIGHT_ITOR((l - m) * (l + m)));
      g = SHLIGHT_SQRTR(SHLIGHT_ITOR((2 * l + 1) * (l + m)) / SHLIGHT_ITOR((2 * l - 1) * (l - m)));
      if (l == m + 1) {
        dd = -al * k * t;
        xa = g * k + dd;
      } else {
        dd = SHLIGHT_SQRTR(SHLIGHT_ITOR((2 * l + 1) * (l + m - 1) * (l - m - 1)) /
                           SHLIGHT_ITOR((2 * l - 3) * (l - m) * (l + m))) /
                 gp * dd -
             al * (t * xa);
        xa = g * xa + dd;
      }
      gp = g;
      out_xs[l] = SHLIGHT_FLOAT(xa);
    }
  }
}'''




def fmt_table_packed(ctype, name, size, vals, lit, per_row):
    """a C table several numbers per line, kept so by clang-format off/on"""
    out = ['/* clang-format off */', 'static const %s %s[%s] = {' % (ctype, name, size)]
    for i in range(0, len(vals), per_row):
        row = [lit(v) for v in vals[i:i + per_row]]
        out.append('  ' + ', '.join(row) + (',' if i + per_row < len(vals) else ''))
    out += ['};', '/* clang-format on */']
    return out


def declare(L, candidates):
    body = '\n'.join(L)
    decl = []
    for ty, v, init in candidates:
        if re.search(r'\b%s\b' % v, body.replace('@DECLS@', '')):
            decl.append('  %s %s%s;' % (ty, v, (' = ' + init) if init else ''))
    k = L.index('@DECLS@')
    return L[:k] + decl + L[k + 1:]


def gen_tables():
    """The run-time loops' Reinsch constants from closed forms (per band l, column m < l):
    alpha = s1_l q, g = s2_l (l + m) q, c = s2_l (l - m - 1) q with q = 1 / sqrt((l - m)(l + m)),
    s1_l = sqrt((2l + 1)(2l - 1)), s2_l = sqrt((2l + 1) / (2l - 1)). Tables (double in C):
    SHLI_SH_RSQ[k] = 1 / sqrt(k) (k = 1..2 MAX_BANDS - 1, [0] = 0), SHLI_SH_S12[2 l + {0, 1}] =
    s1_l, s2_l. The products are within 5 ulp (double) of the exact constants."""
    rsq = [0.0] + [1.0 / math.sqrt(k) for k in range(1, 2 * MAX_BANDS)]
    s12 = [0.0, 0.0]
    for l in range(1, MAX_BANDS):
        s12 += [math.sqrt((2 * l + 1) * (2 * l - 1)), math.sqrt((2 * l + 1) / (2 * l - 1))]
    diagv = [diag(m) for m in range(MAX_BANDS)]
    return rsq, s12, diagv


def fmt_table(ctype, name, size, vals, lit, glsl):
    out = []
    if glsl:
        out.append('const %s %s[%s] = %s[%s](' % (ctype, name, size, ctype, size))
    else:
        out.append('static const %s %s[%s] = {' % (ctype, name, size))
    row = []
    for i, v in enumerate(vals):
        row.append(lit(v))
        if len(row) == 4 or i == len(vals) - 1:
            out.append('    ' + ', '.join(row) + (',' if i != len(vals) - 1 else ''))
            row = []
    out.append(');' if glsl else '};')
    return out


# ---------------------------------------------------------------- gradient (mirrored)
def grad_terms(l, m):
    """[(coef, index in band l-1)] for d/dx, d/dy, d/dz of the solid harmonic H_l^m"""
    sq2 = math.sqrt(2.0)
    am = abs(m)
    A, B, C = grad_abc(l, am)

    def pr(mm):
        return idx(l - 1, mm) if abs(mm) <= l - 1 else None

    if m >= 0:  # cos type
        Ap = A * (sq2 if am == 1 else 1.0)
        Bp = B * (sq2 if am == 0 else 1.0)
        gx = [(Ap, pr(am - 1) if am >= 1 else None), (Bp, pr(am + 1))]
        gy = [(-A, pr(-(am - 1)) if am >= 2 else None), (Bp, pr(-(am + 1)))]
        gz = [(C, pr(am))]
    else:       # sin type
        Ap = A * (sq2 if am == 1 else 1.0)
        gx = [(A, pr(-(am - 1)) if am >= 2 else None), (B, pr(-(am + 1)))]
        gy = [(Ap, pr(am - 1)), (-B, pr(am + 1))]
        gz = [(C, pr(-am))]
    return [[(c, j) for c, j in g if c != 0.0 and j is not None] for g in (gx, gy, gz)]


def gen_grad(n):
    """shli_sh_grad_<n>(y, nx, ny, nz, ir, out_grad): gradient from the values y of the unit
    direction (nx, ny, nz) = d / |d|, ir = 1 / |d|"""
    L = []
    w = L.append
    w('SHLIGHT_INLINE void shli_sh_grad_%d(const float *y, float nx, float ny, float nz, float ir,' % n)
    w('                                   float (*out_grad)[3]) {')
    if n == 1:
        for v in ('y', 'nx', 'ny', 'nz', 'ir'):
            w('  SHLIGHT_UNUSED(%s);' % v)
    else:
        w('  float r[%d];' % ((n - 1) * (n - 1)))
        w('  float lr;')
        w('  float q;')
        w('  int i;')
        w('  for (i = 0; i < %d; ++i) {' % ((n - 1) * (n - 1)))
        w('    r[i] = y[i] * ir;')
        w('  }')
    w('  out_grad[0][0] = 0.0f;')
    w('  out_grad[0][1] = 0.0f;')
    w('  out_grad[0][2] = 0.0f;')
    for l in range(1, n):
        w('  lr = %s * ir;' % lit_f(float(l)))
        for m in range(-l, l + 1):
            i = idx(l, m)
            w('  q = lr * y[%d];' % i)
            for k, (g, nk) in enumerate(zip(grad_terms(l, m), ('nx', 'ny', 'nz'))):
                expr = ' + '.join('%s * r[%d]' % (lit_f(cf), j) for cf, j in g)
                if expr:
                    w('  out_grad[%d][%d] = %s - q * %s;' % (i, k, expr, nk))
                else:
                    w('  out_grad[%d][%d] = -q * %s;' % (i, k, nk))
    w('}')
    return L


def gen_grad_any(nmax):
    """shli_sh_grad_lines(n, y, nx, ny, nz, ir, ib, out_grad) (C only): any 1 <= n <= nmax in
    one straight-line body, band l under `if (n > l)` and `#if SHLIGHT_MAX_BANDS > l`; band l-1
    times ir in r (a local: no reloads, y may alias out_grad), so c (y_j ir) rounds as the
    table's coefficients do, each output times ib (1: exact; shl_sh_eval_grad's second factor
    of 1 / |d| for tiny |d|). The mirrored kernel (GLSL) is shli_sh_grad_bands: one loop body per
    band, computing the same coefficients, which shader compilers unroll and fold."""
    L = []
    w = L.append
    w('/* output i of shli_sh_grad_lines from its terms in band l-1 (a: x, b: y, c: z) */')
    w('#define SHLI_G3(i, a, b, c)                                                                      \\')
    w('  q = lr * y[i];                                                                             \\')
    w('  SHLIGHT_SET3(out_grad[i], (a - q * nx) * ib, (b - q * ny) * ib, (c - q * nz) * ib)')
    w('#define SHLI_G2(i, a, b)                                                                         \\')
    w('  q = lr * y[i];                                                                             \\')
    w('  SHLIGHT_SET3(out_grad[i], (a - q * nx) * ib, (b - q * ny) * ib, -q * nz * ib)')
    w('SHLIGHT_CPU_INLINE void shli_sh_grad_lines(int n, const float *y, float nx, float ny, float nz,')
    w('                                           float ir, float ib, float (*out_grad)[3]) {')
    w('  float r[%d];' % (2 * nmax - 3))
    w('  float lr;')
    w('  float q;')
    w('#if SHLIGHT_MAX_BANDS > SHLIGHT_UNROLLED_BANDS')
    w('  if (n > SHLIGHT_UNROLLED_BANDS) {')
    w('    shli_sh_grad_loop(n, y, nx, ny, nz, ir, ib, out_grad);')
    w('    return;')
    w('  }')
    w('#endif')
    w('  lr = 0.0f;')
    w('  q = 0.0f;')
    w('  SHLIGHT_SET3(out_grad[0], 0.0f, 0.0f, 0.0f);')
    for l in range(1, nmax):
        w('#if SHLIGHT_MAX_BANDS > %d' % l)
        w('  if (n > %d) {' % l)
        w('    lr = %s * ir;' % lit_f(float(l)))
        p0 = (l - 1) * (l - 1)
        for k in range(2 * l - 1):
            w('    r[%d] = y[%d] * ir;' % (k, p0 + k))
        for m in range(-l, l + 1):
            i = idx(l, m)
            terms = [' + '.join('%s * r[%d]' % (lit_frs(cf), j - p0) for cf, j in g)
                     for g in grad_terms(l, m)]
            if all(terms):
                w('    SHLI_G3(%d, %s, %s, %s);' % (i, terms[0], terms[1], terms[2]))
            elif terms[0] and terms[1]:
                w('    SHLI_G2(%d, %s, %s);' % (i, terms[0], terms[1]))
            else:
                ex = [('(%s - q * %s) * ib' % (e, nk)) if e else ('-q * %s * ib' % nk)
                      for e, nk in zip(terms, ('nx', 'ny', 'nz'))]
                w('    q = lr * y[%d];' % i)
                w('    SHLIGHT_SET3(out_grad[%d], %s, %s, %s);' % (i, ex[0], ex[1], ex[2]))
        w('  }')
        w('#endif')
    w('}')
    w('#undef SHLI_G3')
    w('#undef SHLI_G2')
    w('')
    w(GRAD_BAND)
    w('')
    w('SHLIGHT_INLINE void shli_sh_grad_bands(int n, const float *y, float nx, float ny, float nz,')
    w('                                       float ir, float ib, float (*out_grad)[3]) {')
    w('  float gb[%d];' % (3 * (2 * nmax - 1)))
    w('  int k;')
    w('  SHLIGHT_SET3(out_grad[0], 0.0f, 0.0f, 0.0f);')
    h = nmax - 1
    for l in range(1, nmax):
        w('#if SHLIGHT_MAX_BANDS > %d' % l)
        w('  if (n > %d) {' % l)
        w('    shli_sh_grad_band(%d, y, nx, ny, nz, ir, ib, gb);' % l)
        w('    for (k = %d; k <= %d; ++k) {' % (h - l, h + l))
        off = l * l + l - h
        w('      SHLIGHT_SET3(out_grad[k %s %d], gb[3 * k], gb[3 * k + 1], gb[3 * k + 2]);'
          % ('+' if off >= 0 else '-', abs(off)))
        w('    }')
        w('  }')
        w('#endif')
    w('}')
    w('')
    w('SHLIGHT_INLINE void shli_sh_grad(int n, const float *y, float nx, float ny, float nz, float ir,')
    w('                                 float ib, float (*out_grad)[3]) {')
    w('#if SHLIGHT_BY_BANDS')
    w('#if SHLIGHT_MAX_BANDS > SHLIGHT_UNROLLED_BANDS')
    w('  if (n > SHLIGHT_UNROLLED_BANDS) {')
    w('    shli_sh_grad_loop(n, y, nx, ny, nz, ir, ib, out_grad);')
    w('    return;')
    w('  }')
    w('#endif')
    w('  shli_sh_grad_bands(n, y, nx, ny, nz, ir, ib, out_grad);')
    w('#else')
    w('  shli_sh_grad_lines(n, y, nx, ny, nz, ir, ib, out_grad);')
    w('#endif')
    w('}')
    return L


# band l (1..15) of the gradient as one loop over the orders m = k - 15, k < 31: band l-1
# times ir in rb (zero outside it), the coefficients of grad_abc and grad_terms computed in
# shli_real in the order grad_abc uses (so in C they round to the constants of
# shli_sh_grad_lines), outputs at out_gb[3 k ..]. rb[k], 31 entries, indexed by the counter of
# a 31-trip loop makes shader compilers unroll both loops whatever the body costs.
GRAD_BAND = '''SHLIGHT_INLINE void shli_sh_grad_band(int l, const float *y, float nx, float ny, float nz,
                                      float ir, float ib, float *out_gb) {
  float rb[31];
  shli_real f = SHLIGHT_ITOR(2 * l + 1) / SHLIGHT_ITOR(2 * l - 1);
  shli_real a;
  float lr = SHLIGHT_ITOF(l) * ir;
  float ca;
  float cb;
  float cc;
  float ap;
  float bp;
  float q;
  float gx;
  float gy;
  int k;
  int m;
  int am;
  for (k = 0; k < 31; ++k) {
    rb[k] = 0.0f;
    if (k >= 16 - l && k <= 14 + l) {
      rb[k] = y[l * l - l + k - 15] * ir;
    }
  }
  for (k = 0; k < 31; ++k) {
    m = k - 15;
    am = m < 0 ? -m : m;
    if (am <= l) {
      a = -0.5 * SHLIGHT_SQRTR(f * SHLIGHT_ITOR(l + am) * SHLIGHT_ITOR(l + am - 1));
      ca = SHLIGHT_FLOAT(a);
      ap = am == 1 ? SHLIGHT_FLOAT(a * 1.4142135623730951) : ca;
      a = 0.5 * SHLIGHT_SQRTR(f * SHLIGHT_ITOR((l - am) * (l - am - 1)));
      cb = SHLIGHT_FLOAT(a);
      bp = am == 0 ? SHLIGHT_FLOAT(a * 1.4142135623730951) : cb;
      cc = SHLIGHT_FLOAT(SHLIGHT_SQRTR(f * SHLIGHT_ITOR(l - am) * SHLIGHT_ITOR(l + am)));
      if (m >= 0) {
        gx = (am >= 1 ? ap * rb[k - 1] : 0.0f) + (am + 1 < l ? bp * rb[k + 1] : 0.0f);
        gy = (am >= 2 ? -ca * rb[31 - k] : 0.0f) + (am + 1 < l ? bp * rb[29 - k] : 0.0f);
      } else {
        gx = (am >= 2 ? ca * rb[k + 1] : 0.0f) + (am + 1 < l ? cb * rb[k - 1] : 0.0f);
        gy = ap * rb[29 - k] + (am + 1 < l ? -cb * rb[31 - k] : 0.0f);
      }
      q = lr * y[l * l + l + m];
      out_gb[3 * k] = (gx - q * nx) * ib;
      out_gb[3 * k + 1] = (gy - q * ny) * ib;
      out_gb[3 * k + 2] = (cc * rb[k] - q * nz) * ib;
    }
  }
}'''


def gen_grad_tables():
    """A, B, C of grad_abc per (l, m), 1 <= l < MAX_BANDS, 0 <= m <= l, at
    SHLI_SH_GTAB[3 * (l * (l + 1) / 2 - 1 + m)] (float)"""
    vals = []
    for l in range(1, MAX_BANDS):
        for m in range(0, l + 1):
            vals += list(grad_abc(l, m))
    return vals


# ---------------------------------------------------------------- SIMD batch (C only)
def lit_fs(v):
    """the shortest float literal for the float that lit_f(v) gives (packed C-only tables; the
    same value as lit_f, which rounds v to 9 digits first, bit for bit)"""
    import struct
    f = struct.unpack('f', struct.pack('f', float(lit_f(v)[:-1])))[0]
    if f == 0.0:
        return '-0.0f' if math.copysign(1.0, f) < 0 else '0'
    for p in range(1, 10):
        s = '%.*g' % (p, f)
        if struct.unpack('f', struct.pack('f', float(s)))[0] == f:
            break
    if s == '%d' % int(float(s)) and abs(f) < 1e6 and 'e' not in s:
        return s
    if 'e' not in s and '.' not in s:
        s += '.0'
    return s + 'f'


def packed_table(ctype, name, vals, lit, width=98):
    """a C-only constant table with as many numbers per line as fit (clang-format off)"""
    out = ['/* clang-format off */', 'static const %s %s[%d] = {' % (ctype, name, len(vals))]
    row = ''
    for i, v in enumerate(vals):
        item = lit(v) + (',' if i + 1 < len(vals) else '')
        if row and len(row) + 1 + len(item) > width:
            out.append(row)
            row = ''
        row = (row + ' ' + item) if row else '    ' + item
    out += [row, '};', '/* clang-format on */']
    return out


def gen_batch_tables():
    """>>basis batch (C only), read by the one batch body of shlight.h with literal n (the loops
    unroll and these loads fold to constants):
    SHLI_SH_BRS[m] (m < 16): X_m^m; SHLI_SH_BRS[16 + 3 (l (l-1)/2 + m) + {0, 1, 2}] for
    0 <= m < l < 16: the float Reinsch step of band l in column m (alpha, g, c; the first step
    of a column, l = m + 1, as -alpha X_m^m, g X_m^m);
    SHLI_SH_BPOLY[3 (l (l+1)/2 + m) + k], 0 <= m <= l < POLY_BANDS: coefficient k of X_l^m in z^2
    (its even part, or its odd part divided by z), the Horner forms of n <= POLY_BANDS."""
    rs = [diag(m) for m in range(UNROLLED)]
    for l in range(1, UNROLLED):
        for m in range(l):
            a, g, c = reinsch(l, m)
            if l == m + 1:
                k = diag(m)
                rs += [-a * k, g * k, 0.0]
            else:
                rs += [a, g, c]
    po = []
    for l in range(POLY_BANDS):
        for m in range(l + 1):
            c = xpoly(l, m)
            odd = (l - m) % 2 == 1
            ev = [c[i] for i in range(1 if odd else 0, len(c), 2)]
            po += ev + [0.0] * (3 - len(ev))
    return (packed_table('float', 'SHLI_SH_BRS', rs, lit_fs) +
            packed_table('float', 'SHLI_SH_BPOLY', po, lit_fs))


# ---------------------------------------------------------------- small n: float polynomials
POLY_BANDS = 6     # n <= POLY_BANDS: Horner forms in float straight from d (Sloan-style)


def xpoly(l, m):
    """X_l^m(z) as polynomial coefficients [c0, c1, ...] in z (plain recurrence, double)"""
    p2, p1 = [0.0], [diag(m)]
    if l == m:
        return p1
    for k in range(m + 1, l + 1):
        a, b = alpha(k, m), beta(k, m)
        p = [0.0] + [a * c for c in p1]
        for i, c in enumerate(p2):
            p[i] -= b * c
        p2, p1 = p1, p
    return p1


def horner(coefs, var):
    """expression for sum coefs[i] var^i (float literals)"""
    e = lit_f(coefs[-1])
    for c in reversed(coefs[:-1]):
        if ' ' in e:
            e = '(%s)' % e
        e = '%s * %s + %s' % (e, var, lit_f(c)) if c != 0.0 else '%s * %s' % (e, var)
    return e


def gen_poly(n):
    """shli_sh_poly_<n>(d, out_y): float Horner forms in z^2 times (x + iy)^m, d unit"""
    L = []
    w = L.append
    w('SHLIGHT_INLINE void shli_sh_poly_%d(float x, float y, float z, float *out_y) {' % n)
    if n == 1:
        w('  SHLIGHT_UNUSED(x);')
        w('  SHLIGHT_UNUSED(y);')
        w('  SHLIGHT_UNUSED(z);')
        w('  out_y[0] = %s;' % lit_f(diag(0)))
        w('}')
        return L
    w('@DECLS@')
    if n >= 3:
        w('  z2 = z * z;')
    for m in range(n):
        if m == 2:
            w('  pc = x * x - y * y;')
            w('  ps = 2.0f * x * y;')
        elif m >= 3:
            w('  qc = x * pc - y * ps;')
            w('  ps = x * ps + y * pc;')
            w('  pc = qc;')
        cu = 'x' if m == 1 else 'pc'
        su = 'y' if m == 1 else 'ps'
        for l in range(m, n):
            c = xpoly(l, m)
            odd = (l - m) % 2 == 1
            ev = [c[i] for i in range(1 if odd else 0, len(c), 2)]
            e = horner(ev, 'z2') if len(ev) > 1 else lit_f(ev[0])
            if odd:
                e = '(%s) * z' % e if len(ev) > 1 else '%s * z' % e
            if m == 0:
                w('  out_y[%d] = %s;' % (idx(l, 0), e))
            elif len(ev) == 1 and not odd:
                w('  out_y[%d] = %s * %s;' % (idx(l, m), e, cu))
                w('  out_y[%d] = %s * %s;' % (idx(l, -m), e, su))
            else:
                w('  xf = %s;' % e)
                w('  out_y[%d] = xf * %s;' % (idx(l, m), cu))
                w('  out_y[%d] = xf * %s;' % (idx(l, -m), su))
    w('}')
    return declare(L, [('float', 'z2', None), ('float', 'pc', None), ('float', 'ps', None),
                       ('float', 'qc', None), ('float', 'xf', None)])


# ---------------------------------------------------------------- regions
def zh_table(nb):
    """>>zonal: per band l, (2l+1)/(l+1), l/(l+1), 1/(l(l+1)) (0 for l = 0), sqrt(4 pi/(2l+1)),
    sqrt(pi (2l+1))"""
    vals = []
    for l in range(nb):
        vals += [(2 * l + 1) / (l + 1), l / (l + 1), 1.0 / (l * (l + 1)) if l else 0.0,
                 math.sqrt(4 * math.pi / (2 * l + 1)), math.sqrt(math.pi * (2 * l + 1))]
    return vals


# tables the kernels read: mirrored into GLSL as the prefix for UNROLLED bands
MIRRORED_TABLES = {'SHLI_ZH_TAB': lambda: zh_table(UNROLLED)}
# tables the kernels read whose GLSL twin takes the C values as written (fitted coefficients)
VERBATIM_TABLES = ('SHLI_GGX_FAST_FIT',)


def gen_lane_table():
    """The AVX-512 run-time core of n > 16 bands: SHLI_SH_RSQF[k] = 1 / sqrt(k) as floats
    (k = 1 .. 2 MAX_BANDS - 1, [0] = 0) and SHLI_SH_RSQR[63 - k] = 1 / sqrt(k) (k = 63 .. 1,
    16 zeros after: the masked lanes of a chunk), so that a chunk's s2_l q = s2_l / sqrt((l - m)
    (l + m)) is s2_l times two contiguous loads (l + m ascending, l - m descending); alpha = (2l - 1) s2_l q, g = (l + m) s2_l q, c = (l - m - 1) s2_l q
    (gen_tables). SHLI_SH_LANEK[63 + k] = k (k = -63 .. 2 MAX_BANDS - 2, as floats): l + m and
    m - l + 1 of a chunk's orders from one contiguous load each. SHLI_SH_LANER[15 - k + j] = k - j
    (j = 0..15): the lane reversal of a chunk's sines, a load instead of two vector operations."""
    rsqf = [0.0] + [1.0 / math.sqrt(k) for k in range(1, 2 * MAX_BANDS)]
    rsqr = [1.0 / math.sqrt(MAX_BANDS - 1 - i) for i in range(MAX_BANDS - 1)] + [0.0] * 16
    return rsqf, [float(k) for k in range(-63, 2 * MAX_BANDS - 1)], rsqr


def gen_lane_table_scaled():
    """SHLI_SH_LANES_S[(l - 1) * 48 + {0, 16, 32} + m], l = 1..15, m = 0..15: alpha', beta', pi
    of band l for the scaled Reinsch step of the n <= 16 cores. With D_l = pi_l D~_l and
    X_l = pi_l X~_l, pi_l = prod_{k <= l} c'_k (c' = c, or 1 where c = 0: the first step of a
    column, where D_{l-1} = 0), the step is X~_l = (alpha' - beta' t) X~_{l-1} + D~_{l-1},
    D~_l = D~_{l-1} - beta' t X~_{l-1} (alpha' = g / c', beta' = a / c'): two FMAs that both
    depend only on the previous band, so the band chain is one FMA latency long."""
    vals = []
    pi = [1.0] * 16
    for l in range(1, 16):
        a_s, b_s, p_s = [], [], []
        for m in range(16):
            if m < l:
                a, g, c = reinsch(l, m)
            else:
                a, g, c = 0.0, 1.0, 0.0
            cp = c if c != 0.0 else 1.0
            pi[m] *= cp
            a_s.append(g / cp)
            b_s.append(a / cp)
            p_s.append(pi[m])
        vals += a_s + b_s + p_s
    return vals


def gen_poly_lanes():
    """SHLI_SH_PLANES: the n <= POLY_BANDS Horner forms across the outputs, lane i = output
    i = l (l + 1) + m (40 lanes, five 256-bit vectors): [k * 40 + i] for k = 0, 1, 2 the
    coefficients of X_l^|m| in z^2 (even part, or odd part divided by z). SHLI_SH_PTAP[i]: the
    trigonometric tap, 0 for m = 0 (lane 0 of the powers is 1), m for cos(m phi) lanes,
    8 + |m| for sin(|m| phi) lanes (the second source of a two-source permute). SHLI_SH_PODD[v]:
    lanes of vector v whose l - |m| is odd (times z)."""
    nl = 40
    co = [[0.0] * nl for _ in range(3)]
    tap = [0] * nl
    odd = [0] * (nl // 8)
    for l in range(POLY_BANDS):
        for m in range(-l, l + 1):
            i = idx(l, m)
            am = abs(m)
            c = xpoly(l, am)
            o = (l - am) % 2 == 1
            ev = [c[k] for k in range(1 if o else 0, len(c), 2)]
            for k, v in enumerate(ev):
                co[k][i] = v
            tap[i] = am if m >= 0 else 8 + am
            if o:
                odd[i // 8] |= 1 << (i % 8)
    return co[0] + co[1] + co[2], tap, odd


def gen_light_idx():
    """>>light, C only (AVX-512): SHLI_LIGHT_BAND[i] = l for coefficient i = l (l+1) + m < 256
    (the band of each lane when per-band light weights scale 16 coefficients at a time)"""
    band = [int(math.isqrt(i)) for i in range(UNROLLED * UNROLLED)]
    lit = lambda v: '%d' % v
    return (['#if SHLIGHT_SIMD_EVAL'] +
            fmt_table_packed('int', 'SHLI_LIGHT_BAND', '%d' % len(band), band, lit, 32) +
            ['#endif'])


def gen_band_weights(nmax):
    """>>light, mirrored: the per-band weights of a cap light applied to Y and its gradient,
    io_sh[i] = kv_l y, io_grad[i] = kg_l io_grad[i] + (ka_l wg[0..2] + kb_l wg[3..5]) y (y the
    old io_sh[i]), as one constant-trip loop per band (unrolled by shader compilers into
    constant indices: a run-time loop over n * n outputs would send the arrays to memory)."""
    L = []
    w = L.append
    w('SHLIGHT_INLINE void shli_sh_band_weights(int n, const float *kv, const float *kg, const float *ka,')
    w('                                         const float *kb, const float *wg, float *io_sh,')
    w('                                         float (*io_grad)[3]) {')
    w('  float y;')
    w('  int i;')
    w('  int l;')
    w('  l = 0;')
    w('#if SHLIGHT_MAX_BANDS > SHLIGHT_UNROLLED_BANDS')
    w('  for (l = SHLIGHT_UNROLLED_BANDS; l < n; ++l) {')
    w('    for (i = l * l; i < (l + 1) * (l + 1); ++i) {')
    body = ['y = io_sh[i];', 'io_sh[i] = kv[l] * y;',
            'io_grad[i][0] = kg[l] * io_grad[i][0] + (ka[l] * wg[0] + kb[l] * wg[3]) * y;',
            'io_grad[i][1] = kg[l] * io_grad[i][1] + (ka[l] * wg[1] + kb[l] * wg[4]) * y;',
            'io_grad[i][2] = kg[l] * io_grad[i][2] + (ka[l] * wg[2] + kb[l] * wg[5]) * y;']
    for b in body:
        w('      ' + b)
    w('    }')
    w('  }')
    w('#endif')
    for l in range(nmax):
        ind = '  '
        if l > 0:
            w('#if SHLIGHT_MAX_BANDS > %d' % l)
            w('  if (n > %d) {' % l)
            ind = '    '
        w(ind + 'l = %d;' % l)
        w(ind + 'for (i = %d; i < %d; ++i) {' % (l * l, (l + 1) * (l + 1)))
        for b in body:
            w(ind + '  ' + b)
        w(ind + '}')
        if l > 0:
            w('  }')
            w('#endif')
    w('}')
    w('')
    # one constant-trip loop per band, as above (shader compilers unroll it; constant indices)
    w('SHLIGHT_INLINE void shli_sh_zero_grad(int n, float *out_sh, float (*out_grad)[3]) {')
    w('  int i;')
    w('#if SHLIGHT_MAX_BANDS > SHLIGHT_UNROLLED_BANDS')
    w('  for (i = SHLIGHT_UNROLLED_BANDS * SHLIGHT_UNROLLED_BANDS; i < n * n; ++i) {')
    w('    out_sh[i] = 0.0f;')
    w('    SHLIGHT_SET3(out_grad[i], 0.0f, 0.0f, 0.0f);')
    w('  }')
    w('#endif')
    w('  out_sh[0] = 0.0f;')
    w('  SHLIGHT_SET3(out_grad[0], 0.0f, 0.0f, 0.0f);')
    for l in range(1, nmax):
        w('#if SHLIGHT_MAX_BANDS > %d' % l)
        w('  if (n > %d) {' % l)
        w('    for (i = %d; i < %d; ++i) {' % (l * l, (l + 1) * (l + 1)))
        w('      out_sh[i] = 0.0f;')
        w('      SHLIGHT_SET3(out_grad[i], 0.0f, 0.0f, 0.0f);')
        w('    }')
        w('  }')
        w('#endif')
    w('}')
    return L


def c_regions():
    rsq, s12, diagv = gen_tables()
    R = {}
    lt = gen_lane_table()
    R['sh_tab'] = (fmt_table_packed('shli_real', 'SHLI_SH_RSQ', '%d' % len(rsq), rsq, lit_d, 4) +
                   fmt_table_packed('shli_real', 'SHLI_SH_S12', '%d' % len(s12), s12, lit_d, 4) +
                   fmt_table_packed('float', 'SHLI_SH_DIAG', '%d' % len(diagv), diagv, lit_f, 6))
    body = []
    for n in range(1, POLY_BANDS + 1):
        body += [''] + gen_poly(n)
    body += ['', CORE_COL, ''] + gen_core_any(UNROLLED)
    R['basis'] = body
    R['gradient'] = gen_grad_any(UNROLLED)
    R['batch'] = gen_batch_tables()
    R['zh_tab'] = fmt_table_packed('shli_real', 'SHLI_ZH_TAB', '%d' % (5 * MAX_BANDS),
                                   zh_table(MAX_BANDS), lit_d, 5)
    import gen_grad_simd
    R['gradv'] = gen_grad_simd.main()
    R['light_idx'] = gen_light_idx() + [''] + gen_band_weights(UNROLLED)
    ls = gen_lane_table_scaled()
    pco, ptap, podd = gen_poly_lanes()
    R['plane'] = (['#if SHLIGHT_SIMD_EVAL'] +
                  packed_table('float', 'SHLI_SH_PLANES', pco, lit_fs) +
                  packed_table('int', 'SHLI_SH_PTAP', ptap, str) +
                  packed_table('int', 'SHLI_SH_PODD', podd, lambda v: '0x%02X' % v) +
                  ['#endif'])
    R['lanes'] = (['#if SHLIGHT_SIMD_EVAL'] + packed_table('float', 'SHLI_SH_LANEK', lt[1], lit_fs) +
                  packed_table('float', 'SHLI_SH_RSQF', lt[0], lit_fs) +
                  packed_table('float', 'SHLI_SH_RSQR', lt[2], lit_fs) +
                  packed_table('int', 'SHLI_SH_LANER', list(range(15, -16, -1)), str) +
                  packed_table('float', 'SHLI_SH_LANES_S', ls, lit_fs) + ['#endif'])
    return R


import re

# GLSL array length of a pointer parameter, by name (default: n * n coefficients)
ARRAY_SIZES = {'zh': 'SHLIGHT_MAX_BANDS', 'out_zh': 'SHLIGHT_MAX_BANDS',
               'out_dzh': 'SHLIGHT_MAX_BANDS', 'g': '8', 'out_g': '8', 'out_nt': '3',
               'c8': '8 * SHLIGHT_MAX_COEFFS', 'g8': '8 * SHLIGHT_MAX_COEFFS',
               'io_zh': 'SHLIGHT_MAX_BANDS', 'zh_a': 'SHLIGHT_MAX_BANDS', 'zh_b': 'SHLIGHT_MAX_BANDS',
               'zh3': '3', 'fzh': 'SHLIGHT_MAX_BANDS', 'pn': '8', 'dn': '8',
               'v': 'SHLIGHT_POLYGON_MAX', 'io_px': 'SHLIGHT_CLIP_MAX', 'io_py': 'SHLIGHT_CLIP_MAX',
               'io_pz': 'SHLIGHT_CLIP_MAX', 'out_axis': '3', 'out_exponent': '1',
               'out_idx': '4', 'out_w': '4', 'tab': 'SHLIGHT_BRDF_TABLE_FLOATS',
               'out_range': '2', 'io_split': 'SHLIGHT_HALF_K', 'io_am': '2', 'out_par': '5', 'out_fit': '6',
               'kv': 'SHLIGHT_MAX_BANDS', 'kg': 'SHLIGHT_MAX_BANDS', 'ka': 'SHLIGHT_MAX_BANDS',
               'kb': 'SHLIGHT_MAX_BANDS', 'wg': '6', 'out_gb': '93',
               'out_xs': '16', 'out_q': '2'}


def glsl_param(prm, fname):
    """DESIGN.md section 4's fixed mapping of a C parameter to GLSL"""
    prm = ' '.join(prm.split())
    m = re.match(r'^const float (\w+)\[3\]$', prm)
    if m:
        return 'vec3 ' + m.group(1)
    m = re.match(r'^float ((out|io)_\w+)\[3\]$', prm)
    if m:
        return '%s vec3 %s' % ('out' if m.group(2) == 'out' else 'inout', m.group(1))
    m = re.match(r'^(const )?float \(\*(\w+)\)\[3\]$', prm)
    if m:
        qual = '' if m.group(1) else ('inout ' if m.group(2).startswith('io_') else 'out ')
        return '%svec3 %s[%s]' % (qual, m.group(2), ARRAY_SIZES.get(m.group(2), 'SHLIGHT_MAX_COEFFS'))
    m = re.match(r'^const (float|shli_real|int) (\w+)\[(\d+)\]$', prm)
    if m:
        return '%s %s[%s]' % m.groups()
    m = re.match(r'^float ((out|io)_\w+)\[(\d+)\]$', prm)
    if m:
        return '%s float %s[%s]' % ('out' if m.group(2) == 'out' else 'inout', m.group(1), m.group(3))
    m = re.match(r'^(const )?(float|shli_real|int) \*(\w+)$', prm)
    if m:
        const, typ, name = m.groups()
        qual = '' if const else ('inout ' if name.startswith('io_') else 'out ')
        return '%s%s %s[%s]' % (qual, typ, name, ARRAY_SIZES.get(name, 'SHLIGHT_MAX_COEFFS'))
    if re.match(r'^(int|float|shli_real|shl_[a-z_]+) (\w+)$', prm):
        return prm  # shl_* enum types: #defined as int in shl_prelude.glsl
    raise SystemExit('gen_basis: no GLSL mapping for parameter "%s" of %s' % (prm, fname))


def glsl_signature(sig):
    """'SHLIGHT_INLINE void name(params) {' (may span lines) -> GLSL signature"""
    sig = ' '.join(sig.split())
    m = re.match(r'SHLIGHT_INLINE (\w+) (\w+)\((.*)\) \{$', sig)
    ret, name, params = m.groups()
    return name, '%s %s(%s) {' % (ret, name, ', '.join(glsl_param(p, name)
                                                      for p in params.split(',')))


def split_items(lines):
    """kernels (SHLIGHT_INLINE functions) and constant tables of a C section, in order"""
    items = []
    i = 0
    while i < len(lines):
        ln = lines[i]
        if ln.startswith('SHLIGHT_INLINE ') or ln.startswith('SHLIGHT_CPU_INLINE '):
            j = i
            while not lines[j].rstrip().endswith(('{', ';')):
                j += 1
            if lines[j].rstrip().endswith(';') or ln.startswith('SHLIGHT_CPU_INLINE '):
                # a prototype, or a C-only function (the run-time loops): no GLSL twin
                if lines[j].rstrip().endswith('{'):
                    while lines[j] != '}':
                        j += 1
                i = j + 1
                continue
            name, sig = glsl_signature(' '.join(lines[i:j + 1]))
            k = j + 1
            while lines[k] != '}':
                k += 1
            items.append(('fn', name, [sig] + lines[j + 1:k + 1]))
            i = k + 1
        elif ln.startswith('static const ') and re.match(r'static const \w+ (\w+)\[', ln).group(1) \
                in MIRRORED_TABLES:
            name = re.match(r'static const \w+ (\w+)\[', ln).group(1)
            vals = MIRRORED_TABLES[name]()
            k = i
            while lines[k] != '};':
                k += 1
            items.append(('mtab', name, fmt_table('float', name, '%d' % len(vals), vals, lit_d, True)))
            i = k + 1
        elif ln.startswith('static const ') and re.match(r'static const \w+ (\w+)\[', ln).group(1) \
                in VERBATIM_TABLES:
            m = re.match(r'static const \w+ (\w+)\[(\d+)\] = \{$', ln)
            k = i + 1
            while lines[k] != '};':
                k += 1
            body = ['const float %s[%s] = float[%s](' % (m.group(1), m.group(2), m.group(2))]
            items.append(('mtab', m.group(1), body + lines[i + 1:k] + [');']))
            i = k + 1
        elif ln.startswith('SHLIGHT_CPU_INLINE ') or ln.startswith('static const '):
            # C-only: the run-time loops and their tables (GLSL stops at UNROLLED bands)
            k = i
            while lines[k] not in ('}', '};'):
                k += 1
            i = k + 1
        elif False:
            m = re.match(r'static const (\w+) (\w+)\[(\d+)\] = \{$', ln)
            k = i + 1
            while lines[k] != '};':
                k += 1
            size = m.group(3)
            body = ['const float %s[%s] = float[%s](' % (m.group(2), size, size)] + lines[i + 1:k] + [');']
            items.append(('tab', m.group(2), body))
            i = k + 1
        else:
            i += 1
    return items


def guard(kind, name):
    if kind == 'tab' or name.endswith('_loop'):
        return '#if SHLIGHT_MAX_BANDS > SHLIGHT_UNROLLED_BANDS'
    if name.startswith('shli_fast_'):
        return '#if SHLIGHT_EDGE_FAST_ON'
    if name == 'shl_sh_irradiance_matrix':  # reads bands 0..2 of sh
        return '#if SHLIGHT_MAX_BANDS >= 3'
    m = re.match(r'shli_sh_(?:core|grad|poly)_(\d+)$', name)
    if m:
        return '#if SHLIGHT_MAX_BANDS >= %s' % m.group(1)
    return None


def glsl_module(header_text, section, deps):
    lines = header_text.split('\n')
    a = next(i for i, l in enumerate(lines) if l.startswith('/* >>%s ' % section))
    b = next(i for i in range(a + 1, len(lines)) if lines[i].startswith('/* >>') or
             lines[i].startswith('#ifdef __cplusplus'))
    out = ['// shl_%s.glsl - GLSL twin of the >>%s section of shlight.h.' % (section, section),
           '// GENERATED by tools/gen_basis.py from shlight.h: do not edit; edit shlight.h and',
           '// rerun. Needs: %s. The host defines SHLIGHT_MAX_BANDS.' % ', '.join(deps),
           '#ifndef SHL_%s_GLSL' % section.upper(),
           '#define SHL_%s_GLSL' % section.upper()]
    sec = []
    for ln in lines[a:b]:
        m = re.match(r'/\* @generated (\w+): defined in >>generated', ln)
        if m:
            # a region written under >>generated at the end of the header: GLSL needs its
            # definitions before their use, so the module takes them at the section's marker
            i = lines.index('/* @generated begin %s */' % m.group(1))
            sec += lines[i + 1:lines.index('/* @generated end %s */' % m.group(1))]
        else:
            sec.append(ln)
    for kind, name, body in split_items(sec):
        g = guard(kind, name)
        out.append('')
        if g:
            out.append(g)
        out += body
        if g:
            out.append('#endif')
    out += ['', '#endif', '']
    return '\n'.join(out)


def replace_region(text, name, lines, path):
    b = '@generated begin %s' % name
    e = '@generated end %s' % name
    i = text.index(b)
    i = text.index('\n', i) + 1
    j = text.index(e)
    j = text.rindex('\n', 0, j) + 1
    return text[:i] + '\n'.join(lines) + '\n' + text[j:]


def table_typedefs(text):
    """the sections reach a table of >>generated through `SHLI_TAB_DECL(T, name, N);` (the
    accessor returns a pointer to the whole array): keep N equal to the table's length"""
    defs = dict(re.findall(r'#define (SHLI_\w+) (\d+)\n', text))
    for ty, name, size in re.findall(r'static const ([\w ]+?) (SHLI_\w+)\[([^\]]+)\] = \{', text):
        expr = re.sub(r'SHLI_\w+', lambda m: defs.get(m.group(0), m.group(0)), size)
        if not re.match(r'^[\d *+]+$', expr):
            continue
        n = eval(expr)
        text = re.sub(r'SHLI_TAB_DECL\(%s, %s, \d+\);' % (re.escape(ty), name[5:].lower()),
                      'SHLI_TAB_DECL(%s, %s, %d);' % (ty, name[5:].lower(), n), text)
    return text


def clang_format(text, path):
    """the project's one style (.clang-format) for the header and the GLSL twins alike"""
    import subprocess
    name = 'shlight.h' if path.endswith('.h') else 'glsl.c'
    try:
        r = subprocess.run(['clang-format', '--style=file', '--assume-filename=' +
                            os.path.join(ROOT, name)], input=text, capture_output=True,
                           text=True, check=True)
    except (OSError, subprocess.CalledProcessError) as e:
        raise SystemExit('gen_basis: clang-format failed (%s); install clang-format' % e)
    return r.stdout


def main():
    unknown = [a for a in sys.argv[1:] if a != '--check']
    if unknown:
        print(__doc__.split('Math (')[0].rstrip())
        sys.exit(0 if unknown[0] in ('-h', '--help') else 2)
    check = '--check' in sys.argv
    stale = []
    hpath = os.path.join(ROOT, 'shlight.h')
    text = open(hpath).read()
    new = text
    for name, lines in c_regions().items():
        new = replace_region(new, name, lines, hpath)
    new = table_typedefs(new)
    outputs = [(hpath, text, new)]
    for sec, deps in (('basis', ['shl_prelude.glsl']),
                      ('gradient', ['shl_prelude.glsl', 'shl_basis.glsl']),
                      ('zonal', ['shl_prelude.glsl', 'shl_basis.glsl', 'shl_gradient.glsl']),
                      ('light', ['shl_prelude.glsl', 'shl_basis.glsl', 'shl_gradient.glsl',
                                 'shl_zonal.glsl']),
                      ('grid', ['shl_prelude.glsl', 'shl_basis.glsl']),
                      ('edge', ['shl_prelude.glsl', 'shl_basis.glsl', 'shl_gradient.glsl', 'shl_zonal.glsl',
                                'shl_light.glsl']),
                      ('brdf', ['shl_prelude.glsl', 'shl_basis.glsl', 'shl_gradient.glsl',
                                'shl_zonal.glsl', 'shl_light.glsl']),
                      ('hvl', ['shl_prelude.glsl', 'shl_basis.glsl', 'shl_gradient.glsl',
                               'shl_zonal.glsl', 'shl_light.glsl', 'shl_brdf.glsl']),
                      ('brdftab', ['shl_prelude.glsl', 'shl_basis.glsl', 'shl_gradient.glsl',
                                   'shl_zonal.glsl', 'shl_light.glsl']),
                      ('ssf', ['shl_prelude.glsl', 'shl_basis.glsl', 'shl_gradient.glsl',
                               'shl_zonal.glsl', 'shl_light.glsl', 'shl_brdf.glsl'])):
        gp = os.path.join(ROOT, 'shlight_glsl', 'shl_%s.glsl' % sec)
        old = open(gp).read() if os.path.exists(gp) else ''
        outputs.append((gp, old, glsl_module(new, sec, deps)))
    outputs = [(path, old, clang_format(fresh, path)) for path, old, fresh in outputs]
    for path, old, fresh in outputs:
        if old != fresh:
            stale.append(os.path.relpath(path, ROOT))
            if not check:
                open(path, 'w').write(fresh)
    if check:
        if stale:
            print('stale generated code (run python3 tools/gen_basis.py):', ', '.join(stale))
            sys.exit(1)
        print('generated code is fresh')
    else:
        print('rewrote:', ', '.join(stale) if stale else 'nothing (fresh)')


if __name__ == '__main__':
    main()
