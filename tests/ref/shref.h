/* shref.h - binary128 (__float128, libquadmath) reference for shlight's SH basis tests.
 *
 * Header-only, C99 + GNU __float128; link with -lquadmath -lm.  Test code only: not thread-safe
 * (lazily built coefficient tables in static storage), not fast (software quad arithmetic).
 *
 * Independence from the code under test.  shlight evaluates Y with Sloan-style normalised
 * recurrences in z = cos(theta) multiplied by (x+iy)^m, and its gradient from solid harmonics
 * (Cartesian polynomial gradient projected on the tangent plane).  This reference uses none of
 * that:
 *   - values (shref_eval_q): angles theta = atan2(rho_xy, z), phi = atan2(y, x) of the input,
 *     the fully normalised associated Legendre recurrence in theta (sin(theta), cos(theta) from
 *     sinq/cosq), N_mm = -sqrt((2m+1)/(2m)) sin(theta) N_{m-1,m-1}  (Condon-Shortley phase),
 *     N_{m+1,m} = sqrt(2m+3) cos(theta) N_mm, N_lm = a_lm (cos(theta) N_{l-1,m} - b_lm N_{l-2,m}),
 *     and cos(m phi), sin(m phi) from cosq/sinq (no complex power), times sqrt(2) for m != 0;
 *   - values, second formulation (shref_eval_explicit_q, l < 20): the explicit finite sum for
 *     d^m/dz^m of the Legendre polynomial (Rodrigues, expanded with binomials), factorial
 *     normalisation, and the binomial expansion of Re/Im (x+iy)^m.  Used only to cross-check
 *     shref_eval_q (they share nothing but the input);
 *   - gradients (shref_grad_*): central finite differences of shref_eval_q itself, in quad;
 *   - spherical partials (shref_dtheta_dphi_*): central finite differences in theta and phi.
 *
 * Conventions (those of shlight, DESIGN.md sec. 2): real SH, CS phase, Y_1^-1 = -K y,
 * Y_1^0 = K z, Y_1^1 = -K x, K = sqrt(3/4pi); index i = l*(l+1)+m; n bands = l = 0..n-1.
 * Zero or non-finite input evaluates at (0,0,1) (shlight's documented degenerate result).
 *
 * Finite-difference step (gradients).  We use the 4th-order 5-point central stencil
 *   f'(t) ~ [f(t-2h) - 8 f(t-h) + 8 f(t+h) - f(t+2h)] / (12 h),
 * truncation error h^4/30 |f^(5)|.  Along a Cartesian axis at radius r = |d|, the k-th
 * derivative of Y_l(d/|d|) is bounded by about (l+k)^k |Y|max / r^k, |Y|max <= sqrt((2l+1)/4pi)
 * (3.2 at l = 63, 4.5 at l = 127).  With h = 2^-30 r (~9.3e-10 r, a power of two times r):
 *   truncation * r <= (9.3e-10)^4/30 * 68^5 * 3.2 ~ 1.7e-28 (l <= 63); ~ 8e-27 (l <= 127);
 *   rounding   * r <= (18/12) * u_eval / 9.3e-10 ~ 3e-23, with u_eval ~ 2e-32 the absolute
 *                     rounding error of one shref_eval_q value (l * 1e-34 * |Y|, l <= 127).
 * So |error| * |d| <~ 1e-22, i.e. ~1e-22 / |d| absolute, 1e15 times below float resolution of
 * gradients that are O(l)/|d|.  (A 2nd-order stencil with h = 1e-12 r would give ~1e-19.)
 * The spherical partials use the same stencil with h = 2^-30 rad: same bounds.
 * The test file checks this claim: tangency (grad . d = 0), Unsold's identity
 * sum_m |grad Y_lm|^2 |d|^2 = l(l+1)(2l+1)/4pi, d_phi Y_lm = -m Y_l,-m, and the chain rule
 * between the Cartesian and spherical references. */
#ifndef SHREF_H
#define SHREF_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define SHREF_MAX_BANDS 128
#define SHREF_EXPLICIT_MAX_BANDS 20

__extension__ typedef __float128 shref_q;

/* quadmath.h lives in gcc's private include directory, which clang does not search: declare
 * the few libquadmath functions used here ourselves when it is not found. */
#if defined(__has_include)
#if __has_include(<quadmath.h>)
#define SHREF_HAVE_QUADMATH_H 1
#endif
#elif defined(__GNUC__) && !defined(__clang__)
#define SHREF_HAVE_QUADMATH_H 1
#endif
#ifdef SHREF_HAVE_QUADMATH_H
#include <quadmath.h>
#else
extern shref_q acosq(shref_q);
extern shref_q atan2q(shref_q, shref_q);
extern shref_q cosq(shref_q);
extern shref_q fabsq(shref_q);
extern int finiteq(shref_q);
extern shref_q hypotq(shref_q, shref_q);
extern shref_q ldexpq(shref_q, int);
extern shref_q sinq(shref_q);
extern shref_q sqrtq(shref_q);
#endif

#if defined(__GNUC__)
#define SHREF_FN static inline __attribute__((unused))
#else
#define SHREF_FN static inline
#endif

SHREF_FN shref_q shref_pi(void) {
  return acosq((shref_q)-1);
}

/* Coefficients of the theta recurrence, built once (quad, exact up to final rounding):
 * A[l][m] = sqrt((4l^2-1)/(l^2-m^2)), B[l][m] = sqrt(((l-1)^2-m^2)/(4(l-1)^2-1)) for l >= m+2;
 * D[m] = -sqrt((2m+1)/(2m)) for m >= 1, E[m] = sqrt(2m+3). */
static shref_q shref_tab_a[SHREF_MAX_BANDS][SHREF_MAX_BANDS];
static shref_q shref_tab_b[SHREF_MAX_BANDS][SHREF_MAX_BANDS];
static shref_q shref_tab_d[SHREF_MAX_BANDS];
static shref_q shref_tab_e[SHREF_MAX_BANDS];
static int shref_tab_ready;

SHREF_FN void shref_init_tables(void) {
  int l, m;
  if (shref_tab_ready) return;
  for (m = 0; m < SHREF_MAX_BANDS; m++) {
    shref_tab_d[m] = m ? -sqrtq((shref_q)(2 * m + 1) / (shref_q)(2 * m)) : (shref_q)1;
    shref_tab_e[m] = sqrtq((shref_q)(2 * m + 3));
    for (l = m + 2; l < SHREF_MAX_BANDS; l++) {
      shref_q ll = (shref_q)l, mm = (shref_q)m, l1 = (shref_q)(l - 1);
      shref_tab_a[l][m] = sqrtq((4 * ll * ll - 1) / (ll * ll - mm * mm));
      shref_tab_b[l][m] = sqrtq((l1 * l1 - mm * mm) / (4 * l1 * l1 - 1));
    }
  }
  shref_tab_ready = 1;
}

/* Is (x,y,z) degenerate (zero or non-finite)? Then shlight evaluates at (0,0,1). */
SHREF_FN int shref_degenerate(shref_q x, shref_q y, shref_q z) {
  if (!finiteq(x) || !finiteq(y) || !finiteq(z)) return 1;
  return x == 0 && y == 0 && z == 0;
}

/* Real SH (CS phase) at direction (x,y,z)/|(x,y,z)|, n <= 128 bands, out[l*(l+1)+m].
 * Scale-invariant: only the angles are used.  n < 1 writes nothing, n > 128 is clamped. */
SHREF_FN void shref_eval_q(int n, shref_q x, shref_q y, shref_q z, shref_q *out) {
  shref_q theta, phi, ct, st, sqrt2, pmm;
  int l, m;
  if (n < 1) return;
  if (n > SHREF_MAX_BANDS) n = SHREF_MAX_BANDS;
  shref_init_tables();
  if (shref_degenerate(x, y, z)) {
    x = 0;
    y = 0;
    z = 1;
  }
  theta = atan2q(hypotq(x, y), z); /* in [0, pi] */
  phi = atan2q(y, x);
  ct = cosq(theta);
  st = sinq(theta);
  sqrt2 = sqrtq((shref_q)2);
  pmm = 1 / sqrtq(4 * shref_pi()); /* N_00 */
  for (m = 0; m < n; m++) {
    shref_q cm, sm, p0, p1;
    if (m > 0) pmm *= shref_tab_d[m] * st; /* N_mm = -sqrt((2m+1)/2m) sin(theta) N_{m-1,m-1} */
    if (m == 0) {
      cm = 1;
      sm = 0;
    } else {
      cm = sqrt2 * cosq((shref_q)m * phi);
      sm = sqrt2 * sinq((shref_q)m * phi);
    }
#define SHREF_PUT(L, P)                                                                            \
  do {                                                                                             \
    if (m == 0) {                                                                                  \
      out[(L) * ((L) + 1)] = (P);                                                                  \
    } else {                                                                                       \
      out[(L) * ((L) + 1) + m] = (P)*cm;                                                           \
      out[(L) * ((L) + 1) - m] = (P)*sm;                                                           \
    }                                                                                              \
  } while (0)
    SHREF_PUT(m, pmm);
    if (m + 1 >= n) continue;
    p0 = pmm;
    p1 = shref_tab_e[m] * ct * pmm; /* N_{m+1,m} = sqrt(2m+3) cos(theta) N_mm */
    SHREF_PUT(m + 1, p1);
    for (l = m + 2; l < n; l++) {
      shref_q p2 = shref_tab_a[l][m] * (ct * p1 - shref_tab_b[l][m] * p0);
      SHREF_PUT(l, p2);
      p0 = p1;
      p1 = p2;
    }
#undef SHREF_PUT
  }
}

/* Binomial coefficient and factorial in quad (exact while they fit in 113 bits). */
SHREF_FN shref_q shref_binom(int a, int b) {
  shref_q r = 1;
  int i;
  if (b < 0 || b > a) return 0;
  if (b > a - b) b = a - b;
  for (i = 1; i <= b; i++)
    r = r * (shref_q)(a - b + i) / (shref_q)i;
  return r;
}
SHREF_FN shref_q shref_fact(int a) {
  shref_q r = 1;
  int i;
  for (i = 2; i <= a; i++)
    r *= (shref_q)i;
  return r;
}
SHREF_FN shref_q shref_powi(shref_q v, int e) {
  shref_q r = 1;
  while (e-- > 0)
    r *= v;
  return r;
}

/* Explicit finite sums (independent second formulation), n <= 20:
 *   P_l^m(z) = (-1)^m (1-z^2)^(m/2) d^m/dz^m P_l(z),
 *   P_l(z)   = 2^-l sum_k (-1)^k C(l,k) C(2l-2k,l) z^(l-2k)                  (Rodrigues)
 *   => P_l^m(z)/sin^m = (-1)^m 2^-l sum_{k <= (l-m)/2} (-1)^k C(l,k) C(2l-2k,l)
 *                                         (l-2k)!/(l-2k-m)! z^(l-2k-m)
 *   sin^m(theta) cos(m phi) = Re (x+iy)^m = sum_{j even} (-1)^(j/2) C(m,j) x^(m-j) y^j,
 *   sin^m(theta) sin(m phi) = Im (x+iy)^m = sum_{j odd} (-1)^((j-1)/2) C(m,j) x^(m-j) y^j,
 *   Y_l^{+-m} = sqrt(2) K_l^m (P_l^m/sin^m) Re/Im(x+iy)^m, K_l^m = sqrt((2l+1)/4pi (l-m)!/(l+m)!).
 * Cancellation in the alternating sums is < 2^(2l) ~ 1e11 for l < 20: ~1e-23 relative. */
SHREF_FN void shref_eval_explicit_q(int n, shref_q x, shref_q y, shref_q z, shref_q *out) {
  shref_q r, pi4;
  int l, m, k, j;
  if (n < 1) return;
  if (n > SHREF_EXPLICIT_MAX_BANDS) n = SHREF_EXPLICIT_MAX_BANDS;
  if (shref_degenerate(x, y, z)) {
    x = 0;
    y = 0;
    z = 1;
  }
  r = sqrtq(x * x + y * y + z * z);
  x /= r;
  y /= r;
  z /= r;
  pi4 = 4 * shref_pi();
  for (l = 0; l < n; l++) {
    for (m = 0; m <= l; m++) {
      shref_q s = 0, re = 0, im = 0, K, q;
      for (k = 0; 2 * k <= l - m; k++) {
        shref_q t = shref_binom(l, k) * shref_binom(2 * l - 2 * k, l) * shref_fact(l - 2 * k) /
                    shref_fact(l - 2 * k - m) * shref_powi(z, l - 2 * k - m);
        s += (k & 1) ? -t : t;
      }
      q = s / shref_powi((shref_q)2, l);
      if (m & 1) q = -q;
      for (j = 0; j <= m; j++) {
        shref_q t = shref_binom(m, j) * shref_powi(x, m - j) * shref_powi(y, j);
        if ((j & 1) == 0)
          re += ((j / 2) & 1) ? -t : t;
        else
          im += (((j - 1) / 2) & 1) ? -t : t;
      }
      K = sqrtq((shref_q)(2 * l + 1) / pi4 * shref_fact(l - m) / shref_fact(l + m));
      if (m == 0) {
        out[l * (l + 1)] = K * q;
      } else {
        out[l * (l + 1) + m] = sqrtq((shref_q)2) * K * q * re;
        out[l * (l + 1) - m] = sqrtq((shref_q)2) * K * q * im;
      }
    }
  }
}

/* Quad scratch buffer (grows, never freed: test code). */
SHREF_FN shref_q *shref_scratch(int which, int count) {
  static shref_q *buf[4];
  static int cap[4];
  if (count > cap[which]) {
    free(buf[which]);
    buf[which] = (shref_q *)malloc(sizeof(shref_q) * (size_t)count);
    if (!buf[which]) abort();
    cap[which] = count;
  }
  return buf[which];
}

SHREF_FN int shref_clamp_n(int n) {
  return n > SHREF_MAX_BANDS ? SHREF_MAX_BANDS : n;
}

/* The quad reference at the float input (normalised in quad), rounded to double. */
SHREF_FN void shref_eval_d(int n, const float d[3], double *out) {
  shref_q *t;
  int i;
  if (n < 1) return;
  n = shref_clamp_n(n);
  t = shref_scratch(0, n * n);
  shref_eval_q(n, (shref_q)d[0], (shref_q)d[1], (shref_q)d[2], t);
  for (i = 0; i < n * n; i++)
    out[i] = (double)t[i];
}

/* Gradient of Y_i(d/|d|) with respect to d (Cartesian), quad, by the 5-point central stencil
 * with h = 2^-30 |d| (see the header comment for the error bound, ~1e-22/|d|).
 * out_y may be NULL.  Degenerate d: Y(0,0,1) and zero gradient (shlight's convention). */
SHREF_FN void shref_grad_q(int n, const shref_q d[3], shref_q *out_y, shref_q (*out_grad)[3]) {
  static const int step[4] = {-2, -1, 1, 2};
  static const int wt[4] = {1, -8, 8, -1};
  shref_q *t, r, h;
  int nn, i, k, s;
  if (n < 1) return;
  n = shref_clamp_n(n);
  nn = n * n;
  if (out_y) shref_eval_q(n, d[0], d[1], d[2], out_y);
  for (i = 0; i < nn; i++)
    out_grad[i][0] = out_grad[i][1] = out_grad[i][2] = 0;
  if (shref_degenerate(d[0], d[1], d[2])) return;
  t = shref_scratch(1, nn);
  r = sqrtq(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  h = ldexpq(r, -30);
  for (k = 0; k < 3; k++) {
    for (s = 0; s < 4; s++) {
      shref_q p[3];
      p[0] = d[0];
      p[1] = d[1];
      p[2] = d[2];
      p[k] += (shref_q)step[s] * h;
      shref_eval_q(n, p[0], p[1], p[2], t);
      for (i = 0; i < nn; i++)
        out_grad[i][k] += (shref_q)wt[s] * t[i];
    }
    for (i = 0; i < nn; i++)
      out_grad[i][k] /= 12 * h;
  }
}

/* Double-rounded wrapper: out_y (may be NULL) and out_grad at the float input. */
SHREF_FN void shref_grad_d(int n, const float d[3], double *out_y, double (*out_grad)[3]) {
  shref_q dq[3], *y;
  shref_q(*g)[3];
  int i, k;
  if (n < 1) return;
  n = shref_clamp_n(n);
  dq[0] = (shref_q)d[0];
  dq[1] = (shref_q)d[1];
  dq[2] = (shref_q)d[2];
  y = shref_scratch(2, n * n);
  g = (shref_q(*)[3])shref_scratch(3, 3 * n * n);
  shref_grad_q(n, dq, y, g);
  for (i = 0; i < n * n; i++) {
    if (out_y) out_y[i] = (double)y[i];
    for (k = 0; k < 3; k++)
      out_grad[i][k] = (double)g[i][k];
  }
}

/* dY/dtheta and dY/dphi at d/|d| by the 5-point stencil in theta and phi with h = 2^-30 rad
 * (the point moves on the unit sphere; crossing theta = 0 is harmless because
 * Y(sin t cos p, sin t sin p, cos t) is smooth in t).  phi = atan2(y, x) (0 at the poles).
 * Degenerate d: evaluated at (0,0,1). */
SHREF_FN void shref_dtheta_dphi_q(int n, const shref_q d[3], shref_q *dtheta, shref_q *dphi) {
  static const int step[4] = {-2, -1, 1, 2};
  static const int wt[4] = {1, -8, 8, -1};
  shref_q *t, th, ph, h;
  int nn, i, s;
  if (n < 1) return;
  n = shref_clamp_n(n);
  nn = n * n;
  if (shref_degenerate(d[0], d[1], d[2])) {
    th = 0;
    ph = 0;
  } else {
    th = atan2q(hypotq(d[0], d[1]), d[2]);
    ph = atan2q(d[1], d[0]);
  }
  h = ldexpq((shref_q)1, -30);
  t = shref_scratch(1, nn);
  for (i = 0; i < nn; i++)
    dtheta[i] = dphi[i] = 0;
  for (s = 0; s < 4; s++) {
    shref_q a = th + (shref_q)step[s] * h;
    shref_eval_q(n, sinq(a) * cosq(ph), sinq(a) * sinq(ph), cosq(a), t);
    for (i = 0; i < nn; i++)
      dtheta[i] += (shref_q)wt[s] * t[i];
    a = ph + (shref_q)step[s] * h;
    shref_eval_q(n, sinq(th) * cosq(a), sinq(th) * sinq(a), cosq(th), t);
    for (i = 0; i < nn; i++)
      dphi[i] += (shref_q)wt[s] * t[i];
  }
  for (i = 0; i < nn; i++) {
    dtheta[i] /= 12 * h;
    dphi[i] /= 12 * h;
  }
}

SHREF_FN void shref_dtheta_dphi_d(int n, const float d[3], double *dtheta, double *dphi) {
  shref_q dq[3], *a, *b;
  int i;
  if (n < 1) return;
  n = shref_clamp_n(n);
  dq[0] = (shref_q)d[0];
  dq[1] = (shref_q)d[1];
  dq[2] = (shref_q)d[2];
  a = shref_scratch(2, n * n);
  b = (shref_q *)shref_scratch(3, 3 * n * n);
  shref_dtheta_dphi_q(n, dq, a, b);
  for (i = 0; i < n * n; i++) {
    dtheta[i] = (double)a[i];
    dphi[i] = (double)b[i];
  }
}

/* Gauss-Legendre nodes/weights on [-1,1] in quad (Newton on P_N), N <= 256. */
SHREF_FN void shref_gauss_legendre(int N, shref_q *x, shref_q *w) {
  int i, it, j;
  for (i = 0; i < N; i++) {
    shref_q z = cosq(shref_pi() * ((shref_q)i + (shref_q)0.75) / ((shref_q)N + (shref_q)0.5));
    shref_q dp = 1;
    for (it = 0; it < 100; it++) {
      shref_q p0 = 1, p1 = z, dz;
      for (j = 2; j <= N; j++) {
        shref_q p2 = ((shref_q)(2 * j - 1) * z * p1 - (shref_q)(j - 1) * p0) / (shref_q)j;
        p0 = p1;
        p1 = p2;
      }
      if (N == 1) {
        p1 = z;
        p0 = 1;
      }
      dp = (shref_q)N * (z * p1 - p0) / (z * z - 1);
      dz = p1 / dp;
      z -= dz;
      if (fabsq(dz) < ldexpq((shref_q)1, -118)) break;
    }
    {
      shref_q p0 = 1, p1 = z;
      for (j = 2; j <= N; j++) {
        shref_q p2 = ((shref_q)(2 * j - 1) * z * p1 - (shref_q)(j - 1) * p0) / (shref_q)j;
        p0 = p1;
        p1 = p2;
      }
      if (N == 1) p0 = 1;
      dp = (shref_q)N * (z * p1 - p0) / (z * z - 1);
    }
    x[i] = z;
    w[i] = 2 / ((1 - z * z) * dp * dp);
  }
}

#endif /* SHREF_H */
