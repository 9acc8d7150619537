/* lightref.h - binary128 (__float128) references for shlight's light section (sphere / cap /
 * triangle lights).  Header-only, C99 + GNU __float128; link with -lquadmath -lm.  Test code
 * only: static scratch, not thread-safe, slow (software quad).
 *
 * Independence from the kernels under test.  The kernels evaluate the cap zonal harmonics with
 * L_l = sqrt(pi(2l+1))/(l(l+1)) s^2 P'_l(alpha) (P'_l by P'_{l+1} = P'_{l-1} + (2l+1) P_l),
 * gradients analytically (docs/derivations.md sec. 3) and the triangle solid angle by van
 * Oosterom's edge formula.  This file uses none of that:
 *
 *   - cap ZH (lref_cap_zh_q): the defining integral L_l = 2 pi K_l int_0^a P_l(cos t) sin t dt,
 *     by composite Gauss-Legendre in the angle t on [0, a] (P_l(cos t) by Bonnet's three-term
 *     recurrence at each node).  In the variable t the integrand is a trigonometric polynomial
 *     of degree l+1, evaluated to full relative precision even for a = 1e-8 (no 1 - cos a
 *     anywhere), so the quadrature is as well conditioned as the integral itself.
 *     Panels: M = ceil((n+1) a / 2), 32 nodes each.  On one panel of width h = a/M the
 *     integrand's highest frequency k = l+1 <= n+1 gives k h / 2 <= 1; the 32-point rule's error
 *     for e^{ikt} is about (kh/2)^64 (32!)^4 / ((64!)^2 65) ~ 3e-37 relative: below quad
 *     rounding (1e-34).
 *     dL_l/da = 2 pi K_l P_l(cos a) sin a (fundamental theorem of calculus, no recurrence in P').
 *   - sphere light (lref_sphere_q): L_l^m = sqrt(4pi/(2l+1)) Y_l^m(w) L_l with Y from shref_eval_q
 *     (angle-based theta recurrence), a = asin(r/|c-x|) in quad (asinq).
 *   - second check (lref_sphere_quad2d_q, small n): int over the cap of Y directly, 2-D
 *     quadrature in a frame tilted to the cap axis: theta by the same composite GL (degree <= l+1
 *     trig polynomial), phi by the trapezoid rule with 2n+2 points (exact for trig polynomials
 *     of degree < 2n+2; Y restricted to a circle has degree <= n-1 in phi).
 *   - gradient wrt the shading point (lref_sphere_grad_q): 5-point central differences of
 *     lref_sphere_q in quad; step discussed at the function.
 *   - triangle solid angle (lref_tri_solid_angle_q): Omega = int_T |R.n| / |R|^3 dA, R = p - x,
 *     by tensor Gauss-Legendre on the collapsed square of each sub-triangle, with adaptive 4-way
 *     subdivision near the shading point; and (lref_tri_solid_angle_unit_q) by the unit-vector
 *     form Omega = 2 atan2(|u1.(u2 x u3)|, 1 + u1.u2 + u2.u3 + u3.u1) in quad.
 *   - exact triangle SH projection (lref_tri_sh_q): int_T Y(R/|R|) |R.n| / |R|^3 dA with the same
 *     quadrature.  Its difference to the sphere approximation ([GRAD] eq. 26) is a modelling
 *     error, measured, not a bug.
 *   - the sphere approximation itself in quad (lref_tri_as_sphere_q, eq. 24-26) and its gradient
 *     by the same FD stencil (lref_tri_as_sphere_grad_q).
 *
 * Conventions: those of shlight (real SH, CS phase, i = l(l+1)+m, n bands l = 0..n-1), unit
 * radiance (the SH projection of the indicator of the light's solid angle). */
#ifndef LIGHTREF_H
#define LIGHTREF_H

#include "shref.h"
#include <quadmath.h>

typedef shref_q lref_q;
#define LREF_FN SHREF_FN

/* 32-point Gauss-Legendre rule on [-1,1], built once. */
#define LREF_GL_N 32
static lref_q lref_glx[LREF_GL_N], lref_glw[LREF_GL_N];
static int lref_gl_ready;
LREF_FN void lref_gl_init(void) {
  if (lref_gl_ready) return;
  shref_gauss_legendre(LREF_GL_N, lref_glx, lref_glw);
  lref_gl_ready = 1;
}

/* 20-point rule for the triangle quadrature (per dimension of the collapsed square). */
#define LREF_TGL_N 20
static lref_q lref_tglx[LREF_TGL_N], lref_tglw[LREF_TGL_N];
static int lref_tgl_ready;
LREF_FN void lref_tgl_init(void) {
  if (lref_tgl_ready) return;
  shref_gauss_legendre(LREF_TGL_N, lref_tglx, lref_tglw);
  lref_tgl_ready = 1;
}

/* Legendre P_0..P_{n-1}(z) by Bonnet: (k+1) P_{k+1} = (2k+1) z P_k - k P_{k-1}. */
LREF_FN void lref_legendre_q(int n, lref_q z, lref_q *P) {
  int k;
  if (n < 1) return;
  P[0] = 1;
  if (n > 1) P[1] = z;
  for (k = 1; k + 1 < n; k++)
    P[k + 1] = ((lref_q)(2 * k + 1) * z * P[k] - (lref_q)k * P[k - 1]) / (lref_q)(k + 1);
}

/* 2 pi K_l = sqrt(pi (2l+1)). */
LREF_FN lref_q lref_2pik(int l) {
  return sqrtq(shref_pi() * (lref_q)(2 * l + 1));
}

/* Cap ZH: L[l] = 2 pi K_l int_0^a P_l(cos t) sin t dt, l = 0..n-1 (n <= SHREF_MAX_BANDS),
 * a in [0, pi].  Composite 32-point GL in t (see the header for the error bound). */
LREF_FN void lref_cap_zh_q(int n, lref_q a, lref_q *L) {
  lref_q P[SHREF_MAX_BANDS + 1], h;
  int l, M, p, i;
  if (n < 1) return;
  if (n > SHREF_MAX_BANDS) n = SHREF_MAX_BANDS;
  lref_gl_init();
  for (l = 0; l < n; l++)
    L[l] = 0;
  if (!(a > 0)) return;
  M = (int)ceilq((lref_q)(n + 1) * a / 2);
  if (M < 1) M = 1;
  h = a / (lref_q)M;
  for (p = 0; p < M; p++) {
    lref_q t0 = h * (lref_q)p;
    for (i = 0; i < LREF_GL_N; i++) {
      lref_q t = t0 + h * (lref_glx[i] + 1) / 2, wt = h / 2 * lref_glw[i] * sinq(t);
      lref_legendre_q(n, cosq(t), P);
      for (l = 0; l < n; l++)
        L[l] += wt * P[l];
    }
  }
  for (l = 0; l < n; l++)
    L[l] *= lref_2pik(l);
}

/* dL_l/da = 2 pi K_l P_l(cos a) sin a. */
LREF_FN void lref_cap_dzh_q(int n, lref_q a, lref_q *dL) {
  lref_q P[SHREF_MAX_BANDS + 1], s = sinq(a);
  int l;
  if (n < 1) return;
  if (n > SHREF_MAX_BANDS) n = SHREF_MAX_BANDS;
  lref_legendre_q(n, cosq(a), P);
  for (l = 0; l < n; l++)
    dL[l] = lref_2pik(l) * P[l] * s;
}

/* Closed forms for l <= 2 (self-check of the quadrature):
 * L_0 = 2pi K_0 (1 - cos a), L_1 = 2pi K_1 sin^2(a)/2, L_2 = 2pi K_2 cos(a) sin^2(a)/2. */
LREF_FN void lref_cap_zh_closed3_q(lref_q a, lref_q *L) {
  lref_q s = sinq(a), c = cosq(a);
  lref_q h = sinq(a / 2);
  L[0] = lref_2pik(0) * 2 * h * h; /* 1 - cos a = 2 sin^2(a/2), no cancellation */
  L[1] = lref_2pik(1) * s * s / 2;
  L[2] = lref_2pik(2) * c * s * s / 2;
}

/* Half-angle of a sphere of radius r seen from distance dist; s = r/dist clamped to 1
 * (inside or on the sphere: hemisphere, a = pi/2). */
LREF_FN lref_q lref_half_angle_q(lref_q r, lref_q dist) {
  lref_q s = r / dist;
  if (s >= 1) return shref_pi() / 2;
  return asinq(s);
}

LREF_FN lref_q lref_norm3(const lref_q v[3]) {
  return sqrtq(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

/* Sphere light (centre c, radius r > 0, unit radiance) at shading point x, x != c:
 * out[l(l+1)+m] = sqrt(4pi/(2l+1)) Y_l^m(w) L_l(a), w = (c-x)/|c-x|, a = asin(min(1, r/|c-x|)). */
LREF_FN void lref_sphere_q(int n, const lref_q c[3], lref_q r, const lref_q x[3], lref_q *out) {
  lref_q d[3], dist, L[SHREF_MAX_BANDS], *Y;
  int l, m, k;
  if (n < 1) return;
  if (n > SHREF_MAX_BANDS) n = SHREF_MAX_BANDS;
  for (k = 0; k < 3; k++)
    d[k] = c[k] - x[k];
  dist = lref_norm3(d);
  lref_cap_zh_q(n, lref_half_angle_q(r, dist), L);
  Y = (lref_q *)malloc(sizeof(lref_q) * (size_t)(n * n));
  if (!Y) abort();
  shref_eval_q(n, d[0], d[1], d[2], Y);
  for (l = 0; l < n; l++) {
    lref_q f = sqrtq(4 * shref_pi() / (lref_q)(2 * l + 1)) * L[l];
    for (m = -l; m <= l; m++)
      out[l * (l + 1) + m] = f * Y[l * (l + 1) + m];
  }
  free(Y);
}

/* Orthonormal frame (e1, e2, w) around unit w. */
LREF_FN void lref_frame(const lref_q w[3], lref_q e1[3], lref_q e2[3]) {
  lref_q t[3] = {0, 0, 0}, nn;
  int k, i = 0;
  for (k = 1; k < 3; k++)
    if (fabsq(w[k]) < fabsq(w[i])) i = k;
  t[i] = 1; /* the axis least aligned with w */
  e1[0] = t[1] * w[2] - t[2] * w[1];
  e1[1] = t[2] * w[0] - t[0] * w[2];
  e1[2] = t[0] * w[1] - t[1] * w[0];
  nn = lref_norm3(e1);
  for (k = 0; k < 3; k++)
    e1[k] /= nn;
  e2[0] = w[1] * e1[2] - w[2] * e1[1];
  e2[1] = w[2] * e1[0] - w[0] * e1[2];
  e2[2] = w[0] * e1[1] - w[1] * e1[0];
}

/* Second, independent check: out_i = int over the cap {angle(u, w) <= a} of Y_i(u) du by 2-D
 * quadrature in the tilted frame (theta composite GL as lref_cap_zh_q, phi trapezoid with 2n+2
 * points, exact).  Cost ~ (n+1) a/2 * 32 * (2n+2) shref evaluations: meant for n <= ~16. */
LREF_FN void lref_sphere_quad2d_q(int n, const lref_q c[3], lref_q r, const lref_q x[3],
                                  lref_q *out) {
  lref_q d[3], w[3], e1[3], e2[3], dist, a, h, *Y;
  int nn, M, p, i, j, k, np;
  if (n < 1) return;
  if (n > SHREF_MAX_BANDS) n = SHREF_MAX_BANDS;
  nn = n * n;
  lref_gl_init();
  for (k = 0; k < 3; k++)
    d[k] = c[k] - x[k];
  dist = lref_norm3(d);
  for (k = 0; k < 3; k++)
    w[k] = d[k] / dist;
  lref_frame(w, e1, e2);
  a = lref_half_angle_q(r, dist);
  for (i = 0; i < nn; i++)
    out[i] = 0;
  M = (int)ceilq((lref_q)(n + 1) * a / 2);
  if (M < 1) M = 1;
  h = a / (lref_q)M;
  np = 2 * n + 2;
  Y = (lref_q *)malloc(sizeof(lref_q) * (size_t)nn);
  if (!Y) abort();
  for (p = 0; p < M; p++) {
    for (i = 0; i < LREF_GL_N; i++) {
      lref_q t = h * (lref_q)p + h * (lref_glx[i] + 1) / 2;
      lref_q st = sinq(t), ct = cosq(t);
      lref_q wt = h / 2 * lref_glw[i] * st * 2 * shref_pi() / (lref_q)np;
      for (j = 0; j < np; j++) {
        lref_q ph = 2 * shref_pi() * ((lref_q)j + (lref_q)0.25) / (lref_q)np, u[3];
        lref_q cp = cosq(ph), sp = sinq(ph);
        for (k = 0; k < 3; k++)
          u[k] = ct * w[k] + st * (cp * e1[k] + sp * e2[k]);
        shref_eval_q(n, u[0], u[1], u[2], Y);
        for (k = 0; k < nn; k++)
          out[k] += wt * Y[k];
      }
    }
  }
  free(Y);
}

/* Generic 5-point central-difference gradient wrt x of a function F(x) -> R^nn:
 * g[i][k] = [F(x-2h e_k) - 8F(x-h e_k) + 8F(x+h e_k) - F(x+2h e_k)] / (12 h). */
typedef void (*lref_field_fn)(int n, const lref_q x[3], const void *ctx, lref_q *out);
LREF_FN void lref_fd_grad_q(int n, lref_field_fn f, const void *ctx, const lref_q x[3], lref_q h,
                            lref_q (*g)[3]) {
  static const int step[4] = {-2, -1, 1, 2};
  static const int wt[4] = {1, -8, 8, -1};
  int nn = n * n, i, k, s;
  lref_q *t = (lref_q *)malloc(sizeof(lref_q) * (size_t)nn);
  if (!t) abort();
  for (i = 0; i < nn; i++)
    g[i][0] = g[i][1] = g[i][2] = 0;
  for (k = 0; k < 3; k++) {
    for (s = 0; s < 4; s++) {
      lref_q p[3];
      p[0] = x[0];
      p[1] = x[1];
      p[2] = x[2];
      p[k] += (lref_q)step[s] * h;
      f(n, p, ctx, t);
      for (i = 0; i < nn; i++)
        g[i][k] += (lref_q)wt[s] * t[i];
    }
    for (i = 0; i < nn; i++)
      g[i][k] /= 12 * h;
  }
  free(t);
}

typedef struct {
  lref_q c[3], r;
} lref_sphere_ctx;
LREF_FN void lref_sphere_field(int n, const lref_q x[3], const void *ctx, lref_q *out) {
  const lref_sphere_ctx *s = (const lref_sphere_ctx *)ctx;
  lref_sphere_q(n, s->c, s->r, x, out);
}

/* FD step for the sphere light at distance dist, radius r, n bands.  F(x) varies on three
 * length scales: the direction (Y_l of degree l: dist/(l+1)), the cap size through
 * L_l(a(dist)) (L_l oscillates in a on the scale 1/(l+1), da/ddist = -tan(a)/dist, so the scale
 * in dist is dist*alpha/((l+1) s) >= dist*alpha/(n+1), alpha = cos a), and the square-root
 * singularity of alpha at the light surface (alpha ~ sqrt(2(dist-r)/r), scale dist-r).  With
 * S = min(dist/(n+1), dist*alpha/(n+1), (dist-r)/2) (inside: min(dist/(n+1), (r-dist)/2)) and
 * h = 2^-20 S:
 *   truncation h^4/30 |F^(5)| ~ 2^-80/30 * 5! |F|/S ... relative to the gradient scale |F|/S:
 *   <~ 4 * 2^-80 ~ 3e-24 (the constant 5!/30 of a function analytic in a disc of radius S);
 *   rounding (18/12) u_F / h, u_F ~ 1e-33 |F| (quadrature + shref): ~ 1.5e-33 * 2^20 ~ 2e-27
 *   relative to |F|/S.
 * So the FD gradient is good to ~1e-23 of its own scale, 1e16 below float resolution. */
LREF_FN lref_q lref_sphere_fd_step(int n, lref_q r, lref_q dist) {
  lref_q s = r / dist, alpha = s < 1 ? sqrtq((1 - s) * (1 + s)) : 0, S;
  S = dist / (lref_q)(n + 1);
  if (s < 1) {
    if (dist * alpha / (lref_q)(n + 1) < S) S = dist * alpha / (lref_q)(n + 1);
    if ((dist - r) / 2 < S) S = (dist - r) / 2;
  } else if (dist < r && (r - dist) / 2 < S) {
    /* inside: the clamped (hemisphere) extension depends on the direction only; smooth up
     * to the surface, where the clamp switches: stay (r - dist)/2 away from it */
    S = (r - dist) / 2;
  }
  return ldexpq(S, -20);
}

/* out_g[i][k] = d out_i / d x_k of lref_sphere_q (outside the light, dist > r). */
LREF_FN void lref_sphere_grad_q(int n, const lref_q c[3], lref_q r, const lref_q x[3],
                                lref_q (*out_g)[3]) {
  lref_sphere_ctx ctx;
  lref_q d[3];
  int k;
  if (n > SHREF_MAX_BANDS) n = SHREF_MAX_BANDS;
  for (k = 0; k < 3; k++) {
    ctx.c[k] = c[k];
    d[k] = c[k] - x[k];
  }
  ctx.r = r;
  lref_fd_grad_q(n, lref_sphere_field, &ctx, x, lref_sphere_fd_step(n, r, lref_norm3(d)), out_g);
}

/* ------------------------------------------------------------------------- triangles */

LREF_FN void lref_cross(const lref_q a[3], const lref_q b[3], lref_q o[3]) {
  o[0] = a[1] * b[2] - a[2] * b[1];
  o[1] = a[2] * b[0] - a[0] * b[2];
  o[2] = a[0] * b[1] - a[1] * b[0];
}
LREF_FN lref_q lref_dot(const lref_q a[3], const lref_q b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Quadrature state: integrand |h| / |R|^3 * (1, or Y(R/|R|)) over the triangle. */
typedef struct {
  lref_q x[3], nrm[3], absh; /* shading point, unit normal, |distance to the plane| */
  int n;                     /* 0: solid angle only; else SH bands */
  lref_q *acc, *Y;
  long ntri; /* sub-triangles integrated (diagnostic) */
} lref_tri_state;

LREF_FN void lref_tri_leaf(lref_tri_state *st, const lref_q a[3], const lref_q b[3],
                           const lref_q c[3]) {
  /* collapsed square: p(u,v) = a + u (b - a) + u v (c - b), dA = u |(b-a) x (c-b)| du dv */
  lref_q ba[3], cb[3], cr[3], A2;
  int i, j, k, nn = st->n * st->n;
  for (k = 0; k < 3; k++) {
    ba[k] = b[k] - a[k];
    cb[k] = c[k] - b[k];
  }
  lref_cross(ba, cb, cr);
  A2 = lref_norm3(cr);
  st->ntri++;
  for (i = 0; i < LREF_TGL_N; i++) {
    lref_q u = (lref_tglx[i] + 1) / 2, wu = lref_tglw[i] / 2;
    for (j = 0; j < LREF_TGL_N; j++) {
      lref_q v = (lref_tglx[j] + 1) / 2, wv = lref_tglw[j] / 2, R[3], rr, f;
      for (k = 0; k < 3; k++)
        R[k] = a[k] + u * ba[k] + u * v * cb[k] - st->x[k];
      rr = lref_norm3(R);
      f = wu * wv * u * A2 * st->absh / (rr * rr * rr);
      if (st->n == 0) {
        st->acc[0] += f;
      } else {
        shref_eval_q(st->n, R[0], R[1], R[2], st->Y);
        for (k = 0; k < nn; k++)
          st->acc[k] += f * st->Y[k];
      }
    }
  }
}

/* Subdivide while the shading point is closer than 2 diameters to the sub-triangle (lower
 * bound: |x - centroid| - max |vertex - centroid|).  On an accepted sub-triangle of diameter D
 * the nearest singularity of the integrand is >= 2D away, i.e. >= 4 half-widths of the panel
 * in the collapsed square: Bernstein ellipse parameter rho >= 4 + sqrt(17) ~ 8.1, and the
 * 20-point rule's error ~ rho^-40 ~ 4e-37 (relative to the sub-triangle's contribution). */
LREF_FN void lref_tri_rec(lref_tri_state *st, const lref_q a[3], const lref_q b[3],
                          const lref_q c[3], int depth) {
  lref_q g[3], e[3], D = 0, rmax = 0, dc;
  int k;
  for (k = 0; k < 3; k++)
    g[k] = (a[k] + b[k] + c[k]) / 3;
  {
    const lref_q *v[3];
    int i;
    v[0] = a;
    v[1] = b;
    v[2] = c;
    for (i = 0; i < 3; i++) {
      lref_q t;
      for (k = 0; k < 3; k++)
        e[k] = v[(i + 1) % 3][k] - v[i][k];
      t = lref_norm3(e);
      if (t > D) D = t;
      for (k = 0; k < 3; k++)
        e[k] = v[i][k] - g[k];
      t = lref_norm3(e);
      if (t > rmax) rmax = t;
    }
  }
  for (k = 0; k < 3; k++)
    e[k] = st->x[k] - g[k];
  dc = lref_norm3(e) - rmax;
  if (dc >= 2 * D || depth >= 60) {
    lref_tri_leaf(st, a, b, c);
    return;
  }
  {
    lref_q ab[3], bc[3], ca[3];
    for (k = 0; k < 3; k++) {
      ab[k] = (a[k] + b[k]) / 2;
      bc[k] = (b[k] + c[k]) / 2;
      ca[k] = (c[k] + a[k]) / 2;
    }
    lref_tri_rec(st, a, ab, ca, depth + 1);
    lref_tri_rec(st, ab, b, bc, depth + 1);
    lref_tri_rec(st, ca, bc, c, depth + 1);
    lref_tri_rec(st, ab, bc, ca, depth + 1);
  }
}

/* Common driver: returns 0 for a degenerate (zero-area) triangle or x in its plane (the
 * integrand |R.n| is then identically 0: solid angle 0, projection 0), else integrates. */
LREF_FN long lref_tri_integrate_q(lref_q p[3][3], const lref_q x[3], int n, lref_q *out) {
  lref_tri_state st;
  lref_q e1[3], e2[3], cr[3], A2, R[3];
  int k, nn = n > 0 ? n * n : 1;
  if (n > SHREF_MAX_BANDS) n = SHREF_MAX_BANDS;
  lref_tgl_init();
  for (k = 0; k < nn; k++)
    out[k] = 0;
  for (k = 0; k < 3; k++) {
    e1[k] = p[1][k] - p[0][k];
    e2[k] = p[2][k] - p[0][k];
    R[k] = p[0][k] - x[k];
    st.x[k] = x[k];
  }
  lref_cross(e1, e2, cr);
  A2 = lref_norm3(cr);
  if (A2 == 0) return 0;
  for (k = 0; k < 3; k++)
    st.nrm[k] = cr[k] / A2;
  st.absh = fabsq(lref_dot(R, st.nrm));
  if (st.absh == 0) return 0;
  st.n = n;
  st.acc = out;
  st.Y = n > 0 ? (lref_q *)malloc(sizeof(lref_q) * (size_t)nn) : NULL;
  st.ntri = 0;
  lref_tri_rec(&st, p[0], p[1], p[2], 0);
  free(st.Y);
  return st.ntri;
}

/* Unsigned solid angle of triangle p seen from x, by quadrature. */
LREF_FN lref_q lref_tri_solid_angle_q(lref_q p[3][3], const lref_q x[3]) {
  lref_q o;
  lref_tri_integrate_q(p, x, 0, &o);
  return o;
}

/* Unsigned solid angle by the unit-vector form of van Oosterom-Strackee, in quad:
 * Omega = 2 atan2(|u1.(u2 x u3)|, 1 + u1.u2 + u2.u3 + u3.u1), u_i = (p_i - x)/|p_i - x|.
 * Cancellation for a distant triangle: N ~ Omega, relative loss ~ 1/Omega (1e8 at distance 1e4
 * for a unit triangle), i.e. ~1e-26 relative in quad: fine as a reference. */
LREF_FN lref_q lref_tri_solid_angle_unit_q(lref_q p[3][3], const lref_q x[3]) {
  lref_q u[3][3], cr[3], N, D;
  int i, k;
  for (i = 0; i < 3; i++) {
    lref_q nn;
    for (k = 0; k < 3; k++)
      u[i][k] = p[i][k] - x[k];
    nn = lref_norm3(u[i]);
    if (nn == 0) return 0;
    for (k = 0; k < 3; k++)
      u[i][k] /= nn;
  }
  lref_cross(u[1], u[2], cr);
  N = fabsq(lref_dot(u[0], cr));
  D = 1 + lref_dot(u[0], u[1]) + lref_dot(u[1], u[2]) + lref_dot(u[2], u[0]);
  return 2 * atan2q(N, D);
}

/* Exact SH projection of a uniform (unit radiance, two-sided) triangle light: out_i = int over
 * the triangle's solid angle of Y_i. Returns the number of leaf sub-triangles. */
LREF_FN long lref_tri_sh_q(int n, lref_q p[3][3], const lref_q x[3], lref_q *out) {
  if (n < 1) return 0;
  return lref_tri_integrate_q(p, x, n, out);
}

/* The triangle-as-sphere approximation ([GRAD] eq. 24-26) in quad: centroid c, radius
 * r_s = sqrt(|e1 x e2| / (2 pi)), out = sphere(c, r_s, x) * |cos gamma|, cos gamma = n_t.(-w). */
LREF_FN void lref_tri_as_sphere_q(int n, lref_q p[3][3], const lref_q x[3], lref_q *out) {
  lref_q c[3], e1[3], e2[3], cr[3], A2, rs, d[3], dist, cg;
  int k, i;
  if (n < 1) return;
  if (n > SHREF_MAX_BANDS) n = SHREF_MAX_BANDS;
  for (k = 0; k < 3; k++) {
    c[k] = (p[0][k] + p[1][k] + p[2][k]) / 3;
    e1[k] = p[1][k] - p[0][k];
    e2[k] = p[2][k] - p[0][k];
  }
  lref_cross(e1, e2, cr);
  A2 = lref_norm3(cr);
  rs = sqrtq(A2 / (2 * shref_pi()));
  for (k = 0; k < 3; k++)
    d[k] = c[k] - x[k];
  dist = lref_norm3(d);
  cg = A2 > 0 ? fabsq(lref_dot(cr, d)) / (A2 * dist) : 0;
  lref_sphere_q(n, c, rs, x, out);
  for (i = 0; i < n * n; i++)
    out[i] *= cg;
}

typedef struct {
  lref_q p[3][3];
} lref_tri_ctx;
LREF_FN void lref_tri_field(int n, const lref_q x[3], const void *ctx, lref_q *out) {
  lref_tri_as_sphere_q(n, ((lref_tri_ctx *)(size_t)ctx)->p, x, out);
}

/* Gradient wrt x of lref_tri_as_sphere_q by the 5-point stencil.  Step: as for the sphere
 * (lref_sphere_fd_step) with the additional scale of |cos gamma| = |n.d|/|d|, which varies on
 * the scale dist and has a kink at cos gamma = 0 (edge-on; do not test there): the step is also
 * capped at 2^-20 * |n.d| so that the stencil never crosses the kink. */
LREF_FN void lref_tri_as_sphere_grad_q(int n, lref_q p[3][3], const lref_q x[3],
                                       lref_q (*out_g)[3]) {
  lref_tri_ctx ctx;
  lref_q c[3], e1[3], e2[3], cr[3], d[3], A2, rs, dist, h, hn;
  int k, i;
  if (n > SHREF_MAX_BANDS) n = SHREF_MAX_BANDS;
  for (i = 0; i < 3; i++)
    for (k = 0; k < 3; k++)
      ctx.p[i][k] = p[i][k];
  for (k = 0; k < 3; k++) {
    c[k] = (p[0][k] + p[1][k] + p[2][k]) / 3;
    e1[k] = p[1][k] - p[0][k];
    e2[k] = p[2][k] - p[0][k];
    d[k] = c[k] - x[k];
  }
  lref_cross(e1, e2, cr);
  A2 = lref_norm3(cr);
  rs = sqrtq(A2 / (2 * shref_pi()));
  dist = lref_norm3(d);
  h = lref_sphere_fd_step(n, rs, dist);
  hn = A2 > 0 ? ldexpq(fabsq(lref_dot(cr, d)) / A2, -20) : h;
  if (hn < h) h = hn;
  lref_fd_grad_q(n, lref_tri_field, &ctx, x, h, out_g);
}

#endif /* LIGHTREF_H */
