/* tests/ref/published.h - the published forms of four shlight kernels, kept as comparison
   points for the tests and benchmarks; not part of the library (use the functions their
   comments name). Include after shlight.h; C only, no GLSL twins.
   [GRAD] Mezieres, Mellado, Barthe, Paulin 2022, "Recursive analytic spherical harmonics
   gradient for spherical lights"; [HVL] Mezieres, Desrichard, Vanderhaeghe, Paulin 2022,
   "Harmonics Virtual Lights"; corrections E1-E8: docs/derivations.md section 12. */
#ifndef SHLIGHT_TESTS_PUBLISHED_H
#define SHLIGHT_TESTS_PUBLISHED_H

/* shl_sh_grad_from_spherical: Cartesian gradient from the spherical partials ([GRAD]
   eq. 23): grad Y = dY/dtheta grad(theta) + dY/dphi grad(phi). Singular at the poles; at an
   exact pole (x = y = 0) or for d = 0 every entry is 0. Comparison point only: use
   shl_sh_eval_grad. */
SHLIGHT_INLINE void shl_sh_grad_from_spherical(int n, const float d[3], const float *dtheta,
                                               const float *dphi, float (*out_grad)[3]);

/* shl_hvl_horizon_smoothstep: [HVL] eq. 22 with correction E8 (docs/derivations.md section 12)
   fixed: H =
   S((a + pi/2 - clamp(beta, pi/2 - a, pi/2 + a)) / (2a)), S(x) = 3x^2 - 2x^3 on x clamped to [0,
   1]. Same arguments and degenerate results as shl_hvl_horizon (a = 0: the point limit). Max abs
   error against the exact H: 0.039 (a = 0.01) to 0.089 (a = 1.5) (docs/derivations.md section 6;
   remeasured in tests/test_brdf). Cost: 2 normalisations, 2 own atan2. */
SHLIGHT_INLINE float shl_hvl_horizon_smoothstep(const float nrm[3], const float w[3], float r,
                                                float d);

/* shl_sh_eval_grad_spherical: the paper's form ([GRAD] sections 3-4, corrections E1-E3 of
   docs/derivations.md fixed): Y_i(d / |d|), dY_i / dtheta and dY_i / dphi, by Sloan's recurrence
   for X and the normalised T recurrence Z_l = alpha (cos Z_{l-1} - sin X_{l-1}) - beta Z_{l-2}.
   Any finite d != 0; zero / NaN / Inf d: as (0,0,1). At an exact pole phi is taken as 0.
   Kept as the comparison point of shl_sh_eval_grad in tests and bench. */
SHLIGHT_INLINE void shl_sh_eval_grad_spherical(int n, const float d[3], float *out_y,
                                               float *out_dtheta, float *out_dphi);

/* shl_zh_cap_printed: the printed form of [GRAD] eq. 9 / [HVL] eq. 14, as a shader would
   write it, all in float: alpha = sqrt(1 - s^2) (= cos(asin(s))), L_0 = sqrt(pi)(1 - alpha),
   L_l = sqrt(pi / (2l+1)) (P_{l-1}(alpha) - P_{l+1}(alpha)). Comparison point for tests and
   bench only (correction E4 (docs/derivations.md section 12)): relative error 1.4e-4 at s = 1e-2,
   4.6e-2 at s = 1e-3, and every L_l is 0 for s < 2.4e-4. Use shl_zh_cap. Same domain and degenerate
   results as shl_zh_cap. out_zh: n floats. Cost: O(n). */
SHLIGHT_INLINE void shl_zh_cap_printed(int n, float r, float d, float *out_zh);

SHLIGHT_INLINE void shl_sh_eval_grad_spherical(int n, const float d[3], float *out_y,
                                               float *out_dtheta, float *out_dphi) {
  shli_real x = SHLIGHT_REAL(d[0]);
  shli_real y = SHLIGHT_REAL(d[1]);
  shli_real z = SHLIGHT_REAL(d[2]);
  shli_real mx = SHLIGHT_ABSR(x);
  shli_real r;
  shli_real st;
  shli_real cp;
  shli_real sp;
  shli_real pc = 1.0;
  shli_real ps = 0.0;
  shli_real wc = 0.0;
  shli_real ws = 0.0;
  shli_real qc;
  shli_real xm = 0.28209479177387814;
  shli_real x1;
  shli_real x2;
  shli_real xl;
  shli_real z1;
  shli_real z2;
  shli_real zl;
  shli_real al;
  shli_real be;
  shli_real fm;
  int m;
  int l;
  int b;
  n = shli_bands(n);
  if (n < 1) {
    return;
  }
  if (SHLIGHT_ABSR(y) > mx) {
    mx = SHLIGHT_ABSR(y);
  }
  if (SHLIGHT_ABSR(z) > mx) {
    mx = SHLIGHT_ABSR(z);
  }
  if (!(SHLIGHT_ABSR(x) + SHLIGHT_ABSR(y) + SHLIGHT_ABSR(z) > 0.0 && mx <= SHLIGHT_REAL_MAX)) {
    x = 0.0;
    y = 0.0;
    z = 1.0;
    mx = 1.0;
  }
  x = x / mx;
  y = y / mx;
  z = z / mx;
  r = SHLIGHT_SQRTR(x * x + y * y + z * z);
  x = x / r;
  y = y / r;
  z = z / r;
  st = SHLIGHT_SQRTR(x * x + y * y);
  cp = 1.0;
  sp = 0.0;
  if (st > 0.0) {
    cp = x / st;
    sp = y / st;
  }
  for (m = 0; m < n; ++m) {
    fm = SHLIGHT_REAL(SHLIGHT_ITOF(m));
    if (m > 0) {
      /* w = (x + iy)^(m-1) e^(i phi) = sin^(m-1) e^(i m phi); p = (x + iy)^m */
      wc = pc * cp - ps * sp;
      ws = pc * sp + ps * cp;
      qc = x * pc - y * ps;
      ps = x * ps + y * pc;
      pc = qc;
      xm = xm * -SHLIGHT_SQRTR((2.0 * fm + 1.0) / (2.0 * fm));
      if (m == 1) {
        xm = xm * 1.4142135623730951;
      }
    }
    x2 = 0.0;
    x1 = 0.0;
    z2 = 0.0;
    z1 = 0.0;
    for (l = m; l < n; ++l) {
      if (l == m) {
        xl = xm;
        zl = 0.0;
      } else {
        al = SHLIGHT_SQRTR(SHLIGHT_REAL(SHLIGHT_ITOF((2 * l + 1) * (2 * l - 1))) /
                           SHLIGHT_REAL(SHLIGHT_ITOF((l - m) * (l + m))));
        be = 0.0;
        if (l > m + 1) {
          be = SHLIGHT_SQRTR(SHLIGHT_REAL(SHLIGHT_ITOF((2 * l + 1) * (l + m - 1) * (l - m - 1))) /
                             SHLIGHT_REAL(SHLIGHT_ITOF((2 * l - 3) * (l - m) * (l + m))));
        }
        xl = al * z * x1 - be * x2;
        zl = al * (z * z1 - st * x1) - be * z2;
      }
      b = l * (l + 1);
      out_y[b + m] = SHLIGHT_FLOAT(xl * pc);
      out_dtheta[b + m] = SHLIGHT_FLOAT(fm * z * xl * wc + zl * pc);
      out_dphi[b + m] = SHLIGHT_FLOAT(-fm * xl * ps);
      if (m > 0) {
        out_y[b - m] = SHLIGHT_FLOAT(xl * ps);
        out_dtheta[b - m] = SHLIGHT_FLOAT(fm * z * xl * ws + zl * ps);
        out_dphi[b - m] = SHLIGHT_FLOAT(fm * xl * pc);
      }
      x2 = x1;
      x1 = xl;
      z2 = z1;
      z1 = zl;
    }
  }
}

SHLIGHT_INLINE void shl_sh_grad_from_spherical(int n, const float d[3], const float *dtheta,
                                               const float *dphi, float (*out_grad)[3]) {
  shli_real x = SHLIGHT_REAL(d[0]);
  shli_real y = SHLIGHT_REAL(d[1]);
  shli_real z = SHLIGHT_REAL(d[2]);
  shli_real rxy2 = x * x + y * y;
  shli_real r2 = rxy2 + z * z;
  shli_real rxy = SHLIGHT_SQRTR(rxy2);
  float tx = 0.0f;
  float ty = 0.0f;
  float tz = 0.0f;
  float px = 0.0f;
  float py = 0.0f;
  int i;
  n = shli_bands(n);
  if (n < 1) {
    return;
  }
  if (rxy > 0.0 && r2 <= SHLIGHT_REAL_MAX) {
    tx = SHLIGHT_FLOAT(z * x / (r2 * rxy));
    ty = SHLIGHT_FLOAT(z * y / (r2 * rxy));
    tz = SHLIGHT_FLOAT(-rxy / r2);
    px = SHLIGHT_FLOAT(-y / rxy2);
    py = SHLIGHT_FLOAT(x / rxy2);
  }
  for (i = 0; i < n * n; ++i) {
    out_grad[i][0] = dtheta[i] * tx + dphi[i] * px;
    out_grad[i][1] = dtheta[i] * ty + dphi[i] * py;
    out_grad[i][2] = dtheta[i] * tz;
  }
}

SHLIGHT_INLINE void shl_zh_cap_printed(int n, float r, float d, float *out_zh) {
  float s = 0.0f;
  float al;
  float fl;
  float pm = 1.0f;
  float pl;
  float pn;
  int l;
  n = shli_bands(n);
  if (n < 1) {
    return;
  }
  if (r > 0.0f && d >= 0.0f && d <= 3.4028234e38f) {
    s = 1.0f;
    if (d > r) {
      s = r / d;
    }
  }
  al = SHLIGHT_FLOAT(SHLIGHT_SQRTR(SHLIGHT_REAL(1.0f - s * s)));
  out_zh[0] = 1.77245385f * (1.0f - al);
  /* walk P_{l-1}, P_l, P_{l+1} */
  pl = al;
  fl = 1.0f;
  for (l = 1; l < n; ++l) {
    pn = ((2.0f * fl + 1.0f) * al * pl - fl * pm) / (fl + 1.0f);
    out_zh[l] =
        SHLIGHT_FLOAT(SHLIGHT_SQRTR(SHLIGHT_REAL(3.14159265f / (2.0f * fl + 1.0f)))) * (pm - pn);
    pm = pl;
    pl = pn;
    fl = fl + 1.0f;
  }
}

SHLIGHT_INLINE float shl_hvl_horizon_smoothstep(const float nrm[3], const float w[3], float r,
                                                float d) {
  return shli_hvl_hs(shli_cos_between(nrm, w), r, d);
}

#endif
