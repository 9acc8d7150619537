/* arearef.h - long double ground truth for area-light integrals (polygon, sphere, ellipse lights).
 * Header-only, C99 and C++ clean, depends on libm only.  Test code: static scratch (GGX albedo
 * cache), not thread-safe.
 *
 * What it computes: int_{L clipped} f(u) d omega for a light L seen from the origin, f any
 * integrand of the unit direction u, clipped to half-spaces u.m >= 0 (planes through the shading
 * point).
 *
 * Method (validated against Arvo's closed form for Lambert polygons):
 *   - polygon: Sutherland-Hodgman clipping of the 3D polygon (clipping commutes with the radial
 *     projection), signed fan from vertex 0 (exact for non-convex simple polygons: the sign rides
 *     on the triangle determinant), then per spherical triangle an adaptive rule: the Duffy
 *     (collapsed square) map of the flat triangle through the three unit vertices,
 *     p(s,t) = a + s(b-a) + st(c-b), u = p/|p|, d omega = s det(a,b,c)/|p|^3 ds dt, with a tensor
 *     Gauss-Legendre rule (16x16 for moments, 12x12 for GGX), split 1 -> 4 at the great-circle edge
 *     midpoints (the children tile the spherical triangle exactly).  A triangle is accepted when
 *     |Q - sum Q_children| <= abs_tol * Omega_T / Omega_total + eps_loc * sum |Q_children|.  Splits
 * are forced while a triangle's bounding cap is larger than 0.6 rad (large triangles are poorly
 *     resolved by one flat-triangle rule) or lies within 6 sigma of the hint axis with radius > 1.5
 *     sigma (a narrow peak between the nodes would be missed otherwise).
 *   - sphere and ellipse: polar coordinates in which every clip boundary is a coordinate line:
 *       sphere:  u = cos(t) w + sin(t) (cos(phi) t1 + sin(phi) t2), d omega = sin t dt dphi,
 *                t in [0, asin(r/|c|)]; a plane m cuts t to one interval per phi:
 *                m.w cos t + B(phi) sin t >= 0  <=>  |t - atan2(B, m.w)| <= pi/2;
 *       ellipse: p = c + rho (cos(phi) a1 + sin(phi) a2), rho in [0,1],
 *                d omega = |(a1 x a2).c| rho / |p|^3 drho dphi; a plane cuts rho linearly
 *                (m.c + rho B(phi) >= 0, a chord of the ellipse).
 *     The outer phi integral is split at every phi where a bound is not smooth (a clip circle/chord
 *     meets the rim, passes the centre, or two clip boundaries cross), then both the outer (phi)
 * and the inner (t or rho) integrals are adaptive Gauss-Legendre (halving), with the same forced
 *     splits near the hint axis.
 *   - arref_polygon_moment_arvo: Arvo's edge recurrence in long double (research note 3.1), an
 *     independent formulation used as a fast exact oracle for integer exponents.
 *
 * err_est is the sum of |Q - sum Q_children| over the accepted pieces: a pessimistic bound (the
 * returned value is the refined sum, typically orders of magnitude more accurate).  A global
 * evaluation budget (arref_max_evals) stops runaway cases; they return converged = 0. */
#ifndef ARREARREF_H
#define ARREARREF_H

#include <float.h>
#include <math.h>
#include <stdlib.h>

#if defined(__GNUC__) || defined(__clang__)
#define ARREF_FN static __attribute__((unused))
#else
#define ARREF_FN static
#endif

typedef long double (*arref_fn)(const long double u[3], void *ctx); /* integrand at unit u */
typedef struct {
  long double axis[3];
  long double sigma;
} arref_hint; /* narrow peak near +axis, angular width sigma (sigma >= 1: none) */
typedef struct {
  long double value, err_est;
  long evals;
  int converged;
} arref_result;

/* Tunables (globals so that a test can trade accuracy for speed). */
static long arref_max_evals = 60000000L;      /* per call; beyond it: converged = 0 */
static long double arref_ggx_rel_tol = 1e-8L; /* GGX: abs tol = this * directional albedo */
static long double arref_moment_tol = 1e-14L; /* moments: abs tol = this * 2 pi / (e + 1) */
/* peak hints: a region (bounding-cap radius rho) is split while rho > size * sigma and its
   distance to the hint axis is < reach * sigma */
static long double arref_hint_size = 3.0L, arref_hint_reach = 3.0L;

#define ARREF_PI 3.141592653589793238462643383279502884L
#define ARREF_MAXDEPTH 40

/* ---------------------------------------------------------------- small vector helpers */
ARREF_FN long double arref__dot(const long double a[3], const long double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
ARREF_FN void arref__cross(const long double a[3], const long double b[3], long double o[3]) {
  long double x = a[1] * b[2] - a[2] * b[1], y = a[2] * b[0] - a[0] * b[2],
              z = a[0] * b[1] - a[1] * b[0];
  o[0] = x;
  o[1] = y;
  o[2] = z;
}
ARREF_FN long double arref__normalize(long double a[3]) {
  long double l = sqrtl(arref__dot(a, a));
  if (l > 0) {
    a[0] /= l;
    a[1] /= l;
    a[2] /= l;
  }
  return l;
}
ARREF_FN void arref__ld3(const double *d, long double o[3]) {
  o[0] = (long double)d[0];
  o[1] = (long double)d[1];
  o[2] = (long double)d[2];
}
/* an orthonormal pair (t1, t2) with t1 x t2 = w (w unit) */
ARREF_FN void arref__frame(const long double w[3], long double t1[3], long double t2[3]) {
  long double h[3] = {0, 0, 0};
  int k = 0;
  if (fabsl(w[1]) < fabsl(w[k])) k = 1;
  if (fabsl(w[2]) < fabsl(w[k])) k = 2;
  h[k] = 1;
  arref__cross(h, w, t1);
  arref__normalize(t1);
  arref__cross(w, t1, t2);
}
/* the hemisphere about the unit n as four spherical triangles (two horizon points, the pole) */
ARREF_FN void arref__hemi_tris(const long double n[3], long double tri[4][3][3]) {
  long double t1[3], t2[3];
  int q, k;
  arref__frame(n, t1, t2);
  for (q = 0; q < 4; q++)
    for (k = 0; k < 3; k++) {
      long double x = q == 0   ? t1[k]
                      : q == 1 ? t2[k]
                      : q == 2 ? -t1[k]
                               : -t2[k],
                  y = q == 0   ? t2[k]
                      : q == 1 ? -t1[k]
                      : q == 2 ? -t2[k]
                               : t1[k];
      tri[q][0][k] = x;
      tri[q][1][k] = y;
      tri[q][2][k] = n[k];
    }
}
/* angle between unit vectors, accurate at all angles */
ARREF_FN long double arref__angle(const long double a[3], const long double b[3]) {
  long double c[3];
  arref__cross(a, b, c);
  return atan2l(sqrtl(arref__dot(c, c)), arref__dot(a, b));
}

/* ---------------------------------------------------------------- Gauss-Legendre on [0,1] */
static long double arref__gx[2][16], arref__gw[2][16];
static int arref__gready;
ARREF_FN void arref__gl_build(int n, long double *x, long double *w) {
  int i, k, it;
  for (i = 0; i < n; i++) {
    long double z = cosl(ARREF_PI * ((long double)i + 0.75L) / ((long double)n + 0.5L)), p0, p1,
                p2 = 0, dp = 1;
    for (it = 0; it < 100; it++) {
      long double dz;
      p0 = 1;
      p1 = z;
      for (k = 2; k <= n; k++) {
        p2 = ((2 * (long double)k - 1) * z * p1 - ((long double)k - 1) * p0) / (long double)k;
        p0 = p1;
        p1 = p2;
      }
      dp = (long double)n * (z * p1 - p0) / (z * z - 1);
      dz = p1 / dp;
      z -= dz;
      if (fabsl(dz) < 1e-20L) break;
    }
    p0 = 1;
    p1 = z;
    for (k = 2; k <= n; k++) {
      p2 = ((2 * (long double)k - 1) * z * p1 - ((long double)k - 1) * p0) / (long double)k;
      p0 = p1;
      p1 = p2;
    }
    dp = (long double)n * (z * p1 - p0) / (z * z - 1);
    x[i] = (1 - z) / 2;
    w[i] = 1 / ((1 - z * z) * dp * dp);
  }
}
ARREF_FN void arref__gl_init(void) {
  if (arref__gready) return;
  arref__gl_build(16, arref__gx[0], arref__gw[0]);
  arref__gl_build(12, arref__gx[1], arref__gw[1]);
  arref__gready = 1;
}

/* ---------------------------------------------------------------- integration state */
typedef struct {
  arref_fn f;
  void *ctx;
  int has_hint;
  long double hax[3], hsig;
  int n;
  const long double *gx, *gw;
  long double abs_tol, tol_dens, eps_loc;
  long evals, budget;
  long double err;
  int ok;
} arref__st;

ARREF_FN void arref__st_init(arref__st *s, arref_fn f, void *ctx, const arref_hint *hint,
                             long double abs_tol, int order) {
  arref__gl_init();
  s->f = f;
  s->ctx = ctx;
  s->has_hint = hint != NULL && hint->sigma > 0 && hint->sigma < 1;
  s->hsig = s->has_hint ? hint->sigma : 1;
  s->hax[0] = s->hax[1] = s->hax[2] = 0;
  if (s->has_hint) {
    s->hax[0] = hint->axis[0];
    s->hax[1] = hint->axis[1];
    s->hax[2] = hint->axis[2];
    if (arref__normalize(s->hax) == 0) s->has_hint = 0;
  }
  s->n = order == 12 ? 12 : 16;
  s->gx = arref__gx[order == 12 ? 1 : 0];
  s->gw = arref__gw[order == 12 ? 1 : 0];
  s->abs_tol = abs_tol > 0 ? abs_tol : 1e-18L;
  s->tol_dens = 0;
  /* local relative floor: rounding of one rule evaluation scales with the peak's conditioning */
  s->eps_loc = 8 * LDBL_EPSILON * (s->has_hint ? 1 / (s->hsig * s->hsig) : 1);
  if (s->eps_loc < 16 * LDBL_EPSILON) s->eps_loc = 16 * LDBL_EPSILON;
  s->evals = 0;
  s->budget = arref_max_evals;
  s->err = 0;
  s->ok = 1;
}

/* does a region with bounding cap (centre m unit, radius rho) need a forced split? */
ARREF_FN int arref__force(const arref__st *s, const long double m[3], long double rho) {
  if (rho > 0.6L) return 1;
  if (s->has_hint && rho > arref_hint_size * s->hsig &&
      arref__angle(m, s->hax) - rho < arref_hint_reach * s->hsig)
    return 1;
  return 0;
}

/* ---------------------------------------------------------------- spherical triangles */
/* Duffy-Gauss rule on the flat triangle (a,b,c) (any lengths), signed by det(a,b,c) */
ARREF_FN long double arref__trule(arref__st *s, const long double a[3], const long double b[3],
                                  const long double c[3]) {
  long double ba[3], cb[3], ca[3], x[3], det, sum = 0;
  int i, j, k, n = s->n;
  for (k = 0; k < 3; k++) {
    ba[k] = b[k] - a[k];
    cb[k] = c[k] - b[k];
    ca[k] = c[k] - a[k];
  }
  arref__cross(ba, ca, x);
  det = arref__dot(a, x);
  if (det == 0) return 0;
  for (i = 0; i < n; i++) {
    long double si = s->gx[i], inner = 0;
    for (j = 0; j < n; j++) {
      long double st = si * s->gx[j], p[3], r2, r, u[3];
      for (k = 0; k < 3; k++)
        p[k] = a[k] + si * ba[k] + st * cb[k];
      r2 = arref__dot(p, p);
      r = sqrtl(r2);
      u[0] = p[0] / r;
      u[1] = p[1] / r;
      u[2] = p[2] / r;
      inner += s->gw[j] * s->f(u, s->ctx) / (r2 * r);
    }
    sum += s->gw[i] * si * inner;
  }
  s->evals += n * n;
  return det * sum;
}

ARREF_FN long double arref__tri_omega(const long double a[3], const long double b[3],
                                      const long double c[3]) {
  long double x[3];
  arref__cross(b, c, x);
  return fabsl(
      2 * atan2l(arref__dot(a, x), 1 + arref__dot(a, b) + arref__dot(b, c) + arref__dot(c, a)));
}

ARREF_FN void arref__mid(const long double a[3], const long double b[3], long double m[3]) {
  m[0] = a[0] + b[0];
  m[1] = a[1] + b[1];
  m[2] = a[2] + b[2];
  arref__normalize(m);
}

/* adaptive refinement of the spherical triangle with unit vertices a, b, c; q = its rule value */
ARREF_FN long double arref__trec(arref__st *s, const long double a[3], const long double b[3],
                                 const long double c[3], long double q, int depth) {
  long double mab[3], mbc[3], mca[3], q1, q2, q3, q4, sum, diff, tol, m[3], rho, t, om, asum;
  int force;
  arref__mid(a, b, mab);
  arref__mid(b, c, mbc);
  arref__mid(c, a, mca);
  q1 = arref__trule(s, a, mab, mca);
  q2 = arref__trule(s, mab, b, mbc);
  q3 = arref__trule(s, mca, mbc, c);
  q4 = arref__trule(s, mab, mbc, mca);
  sum = q1 + q2 + q3 + q4;
  diff = fabsl(q - sum);
  m[0] = a[0] + b[0] + c[0];
  m[1] = a[1] + b[1] + c[1];
  m[2] = a[2] + b[2] + c[2];
  arref__normalize(m);
  rho = arref__angle(m, a);
  t = arref__angle(m, b);
  if (t > rho) rho = t;
  t = arref__angle(m, c);
  if (t > rho) rho = t;
  om = arref__tri_omega(a, b, c);
  /* rounding floors: the rule itself (eps_loc), and the child tiling (the normalised midpoints
     move the child edges by ~eps, relative area error ~eps / width, width ~ omega / rho) */
  asum = fabsl(q1) + fabsl(q2) + fabsl(q3) + fabsl(q4);
  tol = s->tol_dens * om + s->eps_loc * asum + 1e-6L * s->abs_tol * ldexpl(1, -2 * depth);
  if (om > 0)
    tol += 8 * LDBL_EPSILON * asum * (rho / om < 1e30L ? rho / om : 1e30L);
  else
    tol += asum;
  force = arref__force(s, m, rho);
  if (depth >= ARREF_MAXDEPTH || s->evals > s->budget || (!force && diff <= tol)) {
    if (diff > tol) s->ok = 0;
    s->err += diff;
    return sum;
  }
  return arref__trec(s, a, mab, mca, q1, depth + 1) + arref__trec(s, mab, b, mbc, q2, depth + 1) +
         arref__trec(s, mca, mbc, c, q3, depth + 1) + arref__trec(s, mab, mbc, mca, q4, depth + 1);
}

/* integrate over a list of triangles (vertices any length, radially projected), each weighted
   by the sign of its determinant; returns the signed sum.  tri[k][0..2][3] */
ARREF_FN long double arref__tris(arref__st *s, long double (*tri)[3][3], int ntri) {
  long double otot = 0, val = 0;
  int k, i;
  for (k = 0; k < ntri; k++) {
    for (i = 0; i < 3; i++)
      arref__normalize(tri[k][i]);
    otot += arref__tri_omega(tri[k][0], tri[k][1], tri[k][2]);
  }
  if (!(otot > 0)) return 0;
  s->tol_dens = s->abs_tol / otot;
  for (k = 0; k < ntri; k++) {
    long double q = arref__trule(s, tri[k][0], tri[k][1], tri[k][2]);
    if (arref__tri_omega(tri[k][0], tri[k][1], tri[k][2]) == 0) continue;
    val += arref__trec(s, tri[k][0], tri[k][1], tri[k][2], q, 0);
  }
  return val;
}

/* Sutherland-Hodgman against u.m >= 0 (m through the origin). out needs room for 2n vertices. */
ARREF_FN int arref__clip(long double (*in)[3], int n, const long double m[3],
                         long double (*out)[3]) {
  int i, k = 0, j;
  for (i = 0; i < n; i++) {
    const long double *P = in[i], *Q = in[(i + 1) % n];
    long double dp = arref__dot(P, m), dq = arref__dot(Q, m);
    if (dp >= 0) {
      for (j = 0; j < 3; j++)
        out[k][j] = P[j];
      k++;
    }
    if ((dp > 0 && dq < 0) || (dp < 0 && dq > 0)) {
      long double t = dp / (dp - dq);
      for (j = 0; j < 3; j++)
        out[k][j] = P[j] + t * (Q[j] - P[j]);
      k++;
    }
  }
  return k;
}

/* copy + clip a double polygon into a malloc'ed long double polygon; returns vertex count */
ARREF_FN int arref__clip_poly(const double (*v)[3], int nv, const long double (*m)[3], int nm,
                              long double (**out)[3]) {
  int cap = (nv + 2) << (nm > 0 ? nm : 0), n = nv, i, k;
  long double(*a)[3] = (long double(*)[3])malloc(sizeof(long double[3]) * (size_t)cap);
  long double(*b)[3] = (long double(*)[3])malloc(sizeof(long double[3]) * (size_t)cap);
  for (i = 0; i < nv; i++)
    arref__ld3(v[i], a[i]);
  for (k = 0; k < nm && n >= 3; k++) {
    long double(*t)[3];
    n = arref__clip(a, n, m[k], b);
    t = a;
    a = b;
    b = t;
  }
  free(b);
  *out = a;
  return n;
}

ARREF_FN arref_result arref__poly_ld(long double (*p)[3], int np, arref_fn f, void *ctx,
                                     const arref_hint *hint, long double abs_tol, int order) {
  arref_result res = {0, 0, 0, 1};
  arref__st s;
  long double orient = 0, x[3], (*tri)[3][3];
  int i, k;
  if (np < 3) return res;
  for (i = 1; i + 1 < np; i++) {
    long double d1[3], d2[3];
    for (k = 0; k < 3; k++) {
      d1[k] = p[i][k] - p[0][k];
      d2[k] = p[i + 1][k] - p[0][k];
    }
    arref__cross(d1, d2, x);
    orient += arref__dot(p[0], x);
  }
  if (orient == 0) return res;
  tri = (long double(*)[3][3])malloc(sizeof(long double[3][3]) * (size_t)(np - 2));
  for (i = 1; i + 1 < np; i++)
    for (k = 0; k < 3; k++) {
      tri[i - 1][0][k] = p[0][k];
      tri[i - 1][1][k] = p[i][k];
      tri[i - 1][2][k] = p[i + 1][k];
    }
  arref__st_init(&s, f, ctx, hint, abs_tol, order);
  res.value = arref__tris(&s, tri, np - 2);
  if (orient < 0) res.value = -res.value;
  free(tri);
  res.err_est = s.err;
  res.evals = s.evals;
  res.converged = s.ok;
  return res;
}

ARREF_FN void arref__planes(const double (*clip)[3], int nclip, long double m[3][3]) {
  int k;
  for (k = 0; k < nclip && k < 3; k++) {
    arref__ld3(clip[k], m[k]);
    arref__normalize(m[k]);
  }
}

ARREF_FN arref_result arref__polygon_o(const double (*v)[3], int nv, const double (*clip)[3],
                                       int nclip, arref_fn f, void *ctx, const arref_hint *hint,
                                       long double abs_tol, int order) {
  long double m[3][3], (*p)[3];
  arref_result res;
  int np;
  if (nclip > 3) nclip = 3;
  if (nclip < 0) nclip = 0;
  arref__planes(clip, nclip, m);
  np = arref__clip_poly(v, nv, (const long double(*)[3])m, nclip, &p);
  res = arref__poly_ld(p, np, f, ctx, hint, abs_tol, order);
  free(p);
  return res;
}

ARREF_FN arref_result arref_polygon(const double (*v)[3], int nv, const double (*clip)[3],
                                    int nclip, arref_fn f, void *ctx, const arref_hint *hint,
                                    long double abs_tol) {
  return arref__polygon_o(v, nv, clip, nclip, f, ctx, hint, abs_tol, 16);
}

/* ---------------------------------------------------------------- polar regions (sphere, ellipse)
 */
typedef struct {
  int kind;                                 /* 0 sphere cap, 1 ellipse */
  long double w[3], t1[3], t2[3], beta;     /* sphere */
  long double c[3], a1[3], a2[3], nc, amax; /* ellipse */
  int nclip;
  long double A[3], Bc[3], Bs[3];
  int hint_on;                 /* hint peak located in (r, phi) */
  long double hR, hphi, hsigp; /* its radius-like scale, azimuth and width in parameter units */
  long double tin;             /* inner tolerance per unit of phi */
} arref__pol;

ARREF_FN void arref__pmap(const arref__pol *P, long double r, long double cp, long double sp,
                          long double u[3], long double *jac) {
  int k;
  if (P->kind == 0) {
    long double cr = cosl(r), sr = sinl(r);
    for (k = 0; k < 3; k++)
      u[k] = cr * P->w[k] + sr * (cp * P->t1[k] + sp * P->t2[k]);
    *jac = sr;
  } else {
    long double p[3], r2, l;
    for (k = 0; k < 3; k++)
      p[k] = P->c[k] + r * (cp * P->a1[k] + sp * P->a2[k]);
    r2 = arref__dot(p, p);
    l = sqrtl(r2);
    for (k = 0; k < 3; k++)
      u[k] = p[k] / l;
    *jac = P->nc * r / (r2 * l);
  }
}

/* the r-interval at azimuth (cp, sp); returns 0 when empty */
ARREF_FN int arref__pbounds(const arref__pol *P, long double cp, long double sp, long double *lo,
                            long double *hi) {
  int k;
  long double l = 0, h = P->kind == 0 ? P->beta : 1;
  for (k = 0; k < P->nclip; k++) {
    long double A = P->A[k], B = P->Bc[k] * cp + P->Bs[k] * sp;
    if (P->kind == 0) {
      long double tc = atan2l(B, A);
      if (tc < -ARREF_PI / 2) return 0;
      if (tc - ARREF_PI / 2 > l) l = tc - ARREF_PI / 2;
      if (tc + ARREF_PI / 2 < h) h = tc + ARREF_PI / 2;
    } else {
      if (B > 0) {
        if (-A / B > l) l = -A / B;
      } else if (B < 0) {
        if (-A / B < h) h = -A / B;
      } else if (A < 0)
        return 0;
    }
  }
  *lo = l;
  *hi = h;
  return h > l;
}

ARREF_FN long double arref__rrule(arref__st *s, const arref__pol *P, long double cp, long double sp,
                                  long double r0, long double r1) {
  long double sum = 0, u[3], jac, d = r1 - r0;
  int i;
  for (i = 0; i < s->n; i++) {
    arref__pmap(P, r0 + d * s->gx[i], cp, sp, u, &jac);
    sum += s->gw[i] * jac * s->f(u, s->ctx);
  }
  s->evals += s->n;
  return sum * d;
}

ARREF_FN long double arref__rrec(arref__st *s, const arref__pol *P, long double cp, long double sp,
                                 long double r0, long double r1, long double q, long double tdens,
                                 int depth) {
  long double rm = (r0 + r1) / 2, ql = arref__rrule(s, P, cp, sp, r0, rm),
              qr = arref__rrule(s, P, cp, sp, rm, r1), sum = ql + qr, diff = fabsl(q - sum),
              tol = tdens * (r1 - r0) + s->eps_loc * (fabsl(ql) + fabsl(qr)) +
                    1e-7L * s->abs_tol * ldexpl(1, -depth);
  int force = 0;
  if (s->has_hint) {
    long double u0[3], u1[3], m[3], jac;
    int k;
    arref__pmap(P, r0, cp, sp, u0, &jac);
    arref__pmap(P, r1, cp, sp, u1, &jac);
    for (k = 0; k < 3; k++)
      m[k] = u0[k] + u1[k];
    arref__normalize(m);
    force = arref__force(s, m, arref__angle(u0, u1) / 2);
  }
  if (depth >= 2 * ARREF_MAXDEPTH || s->evals > s->budget || (!force && diff <= tol)) {
    if (diff > tol) s->ok = 0;
    return sum;
  }
  return arref__rrec(s, P, cp, sp, r0, rm, ql, tdens, depth + 1) +
         arref__rrec(s, P, cp, sp, rm, r1, qr, tdens, depth + 1);
}

/* inner integral F(phi) */
ARREF_FN long double arref__inner(arref__st *s, const arref__pol *P, long double phi) {
  long double cp = cosl(phi), sp = sinl(phi), lo, hi, q;
  if (!arref__pbounds(P, cp, sp, &lo, &hi)) return 0;
  q = arref__rrule(s, P, cp, sp, lo, hi);
  return arref__rrec(s, P, cp, sp, lo, hi, q, P->tin / (hi - lo), 0);
}

ARREF_FN long double arref__phrule(arref__st *s, const arref__pol *P, long double p0,
                                   long double p1) {
  long double sum = 0, d = p1 - p0;
  int i;
  for (i = 0; i < s->n; i++)
    sum += s->gw[i] * arref__inner(s, P, p0 + d * s->gx[i]);
  return sum * d;
}

ARREF_FN int arref__phforce(const arref__pol *P, long double p0, long double p1) {
  long double dphi, dist;
  if (!P->hint_on) return 0;
  if ((p1 - p0) * P->hR <= arref_hint_size * P->hsigp) return 0;
  if (P->hphi >= p0 && P->hphi <= p1)
    dphi = 0;
  else {
    long double d0 = fabsl(remainderl(P->hphi - p0, 2 * ARREF_PI)),
                d1 = fabsl(remainderl(P->hphi - p1, 2 * ARREF_PI));
    dphi = d0 < d1 ? d0 : d1;
  }
  if (dphi > ARREF_PI / 2) dphi = ARREF_PI / 2;
  dist = P->hR * dphi * 2 / ARREF_PI;
  return dist < arref_hint_reach * P->hsigp;
}

ARREF_FN long double arref__phrec(arref__st *s, const arref__pol *P, long double p0, long double p1,
                                  long double q, long double tdens, int depth) {
  long double pm = (p0 + p1) / 2, ql = arref__phrule(s, P, p0, pm),
              qr = arref__phrule(s, P, pm, p1), sum = ql + qr, diff = fabsl(q - sum),
              tol = tdens * (p1 - p0) + s->eps_loc * (fabsl(ql) + fabsl(qr)) +
                    1e-7L * s->abs_tol * ldexpl(1, -depth);
  int force = arref__phforce(P, p0, p1) || (p1 - p0) > 0.8L;
  if (depth >= 2 * ARREF_MAXDEPTH || s->evals > s->budget || (!force && diff <= tol)) {
    if (diff > tol) s->ok = 0;
    s->err += diff;
    return sum;
  }
  return arref__phrec(s, P, p0, pm, ql, tdens, depth + 1) +
         arref__phrec(s, P, pm, p1, qr, tdens, depth + 1);
}

ARREF_FN int arref__cmpld(const void *a, const void *b) {
  long double x = *(const long double *)a, y = *(const long double *)b;
  return x < y ? -1 : x > y ? 1 : 0;
}

ARREF_FN void arref__addbp(long double *bp, int *nbp, long double phi) {
  phi = fmodl(phi, 2 * ARREF_PI);
  if (phi < 0) phi += 2 * ARREF_PI;
  if (phi >= 2 * ARREF_PI) phi = 0;
  bp[(*nbp)++] = phi;
}

/* P: geometry filled in (kind, frame, clip coefficients); does breakpoints + outer integral */
ARREF_FN arref_result arref__polar(arref__pol *P, const long double (*m)[3], arref_fn f, void *ctx,
                                   const arref_hint *hint, long double abs_tol) {
  arref_result res = {0, 0, 0, 1};
  arref__st s;
  long double bp[64];
  int nbp = 0, k, j, i;
  arref__st_init(&s, f, ctx, hint, abs_tol, 16);
  /* breakpoints */
  for (k = 0; k < P->nclip; k++) {
    long double R = hypotl(P->Bc[k], P->Bs[k]), ph0, val;
    if (R == 0) continue;
    ph0 = atan2l(P->Bs[k], P->Bc[k]);
    arref__addbp(bp, &nbp, ph0 + ARREF_PI / 2);
    arref__addbp(bp, &nbp, ph0 - ARREF_PI / 2);
    /* rim crossing: sphere A cos(beta) + B sin(beta) = 0; ellipse A + B = 0 */
    val = P->kind == 0 ? -P->A[k] * cosl(P->beta) / (R * sinl(P->beta)) : -P->A[k] / R;
    if (fabsl(val) <= 1) {
      arref__addbp(bp, &nbp, ph0 + acosl(val));
      arref__addbp(bp, &nbp, ph0 - acosl(val));
    }
  }
  for (k = 0; k < P->nclip; k++)
    for (j = k + 1; j < P->nclip; j++) {
      if (P->kind == 0) {
        long double d[3];
        arref__cross(m[k], m[j], d);
        if (arref__normalize(d) == 0) continue;
        for (i = 0; i < 2; i++) {
          long double sg = i ? -1.0L : 1.0L;
          if (sg * arref__dot(d, P->w) > cosl(P->beta) - 1e-12L)
            arref__addbp(bp, &nbp, atan2l(sg * arref__dot(d, P->t2), sg * arref__dot(d, P->t1)));
        }
      } else {
        long double det = P->Bc[k] * P->Bs[j] - P->Bs[k] * P->Bc[j], x, y;
        if (det == 0) continue;
        x = (-P->A[k] * P->Bs[j] + P->A[j] * P->Bs[k]) / det;
        y = (-P->Bc[k] * P->A[j] + P->Bc[j] * P->A[k]) / det;
        if (x * x + y * y < 1 + 1e-12L) arref__addbp(bp, &nbp, atan2l(y, x));
      }
    }
  bp[nbp++] = 0;
  qsort(bp, (size_t)nbp, sizeof bp[0], arref__cmpld);
  bp[nbp++] = 2 * ARREF_PI;
  /* hint location in parameter space */
  P->hint_on = 0;
  if (s.has_hint) {
    if (P->kind == 0) {
      long double th = arref__angle(P->w, s.hax);
      if (th <= P->beta + arref_hint_reach * s.hsig) {
        P->hint_on = 1;
        P->hR = sinl(th);
        P->hphi = atan2l(arref__dot(s.hax, P->t2), arref__dot(s.hax, P->t1));
        P->hsigp = s.hsig;
      }
    } else {
      long double n[3], t, q[3], x, y, d[3];
      arref__cross(P->a1, P->a2, n);
      t = arref__dot(n, P->c) / arref__dot(n, s.hax);
      if (t > 0 && isfinite(t)) {
        for (k = 0; k < 3; k++) {
          q[k] = t * s.hax[k];
          d[k] = q[k] - P->c[k];
        }
        x = arref__dot(d, P->a1) / arref__dot(P->a1, P->a1);
        y = arref__dot(d, P->a2) / arref__dot(P->a2, P->a2);
        P->hsigp = s.hsig * sqrtl(arref__dot(q, q)) / P->amax;
        P->hR = hypotl(x, y);
        P->hphi = atan2l(y, x);
        P->hint_on = P->hR <= 1 + arref_hint_reach * P->hsigp;
      }
    }
    if (P->hint_on) {
      if (P->hphi < 0) P->hphi += 2 * ARREF_PI;
    }
  }
  P->tin = 0.05L * s.abs_tol / (2 * ARREF_PI);
  for (i = 0; i + 1 < nbp; i++) {
    long double q;
    if (bp[i + 1] - bp[i] < 1e-15L) continue;
    q = arref__phrule(&s, P, bp[i], bp[i + 1]);
    res.value += arref__phrec(&s, P, bp[i], bp[i + 1], q, 0.5L * s.abs_tol / (2 * ARREF_PI), 0);
  }
  res.err_est = s.err;
  res.evals = s.evals;
  res.converged = s.ok;
  return res;
}

ARREF_FN arref_result arref_sphere(const double c[3], double r, const double (*clip)[3], int nclip,
                                   arref_fn f, void *ctx, const arref_hint *hint,
                                   long double abs_tol) {
  arref__pol P;
  long double m[3][3], d;
  int k;
  arref_result res = {0, 0, 0, 1};
  if (nclip > 3) nclip = 3;
  if (nclip < 0) nclip = 0;
  arref__ld3(c, P.w);
  d = arref__normalize(P.w);
  if (!(d > (long double)r) || !(r > 0)) return res;
  P.kind = 0;
  P.beta = asinl((long double)r / d);
  arref__frame(P.w, P.t1, P.t2);
  arref__planes(clip, nclip, m);
  P.nclip = nclip;
  for (k = 0; k < nclip; k++) {
    P.A[k] = arref__dot(m[k], P.w);
    P.Bc[k] = arref__dot(m[k], P.t1);
    P.Bs[k] = arref__dot(m[k], P.t2);
  }
  return arref__polar(&P, (const long double(*)[3])m, f, ctx, hint, abs_tol);
}

ARREF_FN arref_result arref_ellipse(const double c[3], const double a1[3], const double a2[3],
                                    const double (*clip)[3], int nclip, arref_fn f, void *ctx,
                                    const arref_hint *hint, long double abs_tol) {
  arref__pol P;
  long double m[3][3], n[3], l1, l2;
  int k;
  arref_result res = {0, 0, 0, 1};
  if (nclip > 3) nclip = 3;
  if (nclip < 0) nclip = 0;
  P.kind = 1;
  arref__ld3(c, P.c);
  arref__ld3(a1, P.a1);
  arref__ld3(a2, P.a2);
  arref__cross(P.a1, P.a2, n);
  P.nc = fabsl(arref__dot(n, P.c));
  if (!(P.nc > 0)) return res;
  l1 = sqrtl(arref__dot(P.a1, P.a1));
  l2 = sqrtl(arref__dot(P.a2, P.a2));
  P.amax = l1 > l2 ? l1 : l2;
  P.beta = 0;
  arref__planes(clip, nclip, m);
  P.nclip = nclip;
  for (k = 0; k < nclip; k++) {
    P.A[k] = arref__dot(m[k], P.c);
    P.Bc[k] = arref__dot(m[k], P.a1);
    P.Bs[k] = arref__dot(m[k], P.a2);
  }
  return arref__polar(&P, (const long double(*)[3])m, f, ctx, hint, abs_tol);
}

/* ---------------------------------------------------------------- axial moments */
typedef struct {
  long double ax[3], e;
  long ie; /* e as an integer when it is one (power by squaring), else -1 */
} arref__mom;
ARREF_FN long double arref__mom_f(const long double u[3], void *ctx) {
  const arref__mom *M = (const arref__mom *)ctx;
  long double x = arref__dot(u, M->ax);
  if (M->e == 0) return 1;
  if (x <= 0) return 0;
  if (x >= 1) return 1;
  if (M->ie >= 0) {
    long n = M->ie;
    long double r = 1;
    while (n) {
      if (n & 1) r *= x;
      n >>= 1;
      if (n) x *= x;
      if (x < 1e-4000L) return 0; /* keeps clear of (slow) subnormals */
    }
    return r;
  }
  return powl(x, M->e);
}
ARREF_FN void arref__mom_setup(arref__mom *M, arref_hint *h, const double axis[3], double e,
                               const double *nrm, double (*clip)[3]) {
  int k;
  arref__ld3(axis, M->ax);
  arref__normalize(M->ax);
  M->e = (long double)e;
  M->ie = (e == floor(e) && e >= 0 && e < 1e9) ? (long)e : -1;
  for (k = 0; k < 3; k++) {
    h->axis[k] = M->ax[k];
    clip[0][k] = axis[k];
    if (nrm) clip[1][k] = nrm[k];
  }
  h->sigma = e > 1 ? 1 / sqrtl((long double)e) : 1;
}
ARREF_FN long double arref__mom_tol(double e) {
  return arref_moment_tol * 2 * ARREF_PI / ((long double)e + 1);
}

ARREF_FN long double arref_polygon_moment(const double (*v)[3], int nv, const double axis[3],
                                          double e) {
  arref__mom M;
  arref_hint h;
  double clip[2][3];
  arref__mom_setup(&M, &h, axis, e, NULL, clip);
  return arref_polygon(v, nv, (const double(*)[3])clip, 1, arref__mom_f, &M, &h, arref__mom_tol(e))
      .value;
}
ARREF_FN long double arref_polygon_moment2(const double (*v)[3], int nv, const double axis[3],
                                           double e, const double nrm[3]) {
  arref__mom M;
  arref_hint h;
  double clip[2][3];
  arref__mom_setup(&M, &h, axis, e, nrm, clip);
  return arref_polygon(v, nv, (const double(*)[3])clip, 2, arref__mom_f, &M, &h, arref__mom_tol(e))
      .value;
}
ARREF_FN long double arref_sphere_moment2(const double c[3], double r, const double axis[3],
                                          double e, const double nrm[3]) {
  arref__mom M;
  arref_hint h;
  double clip[2][3];
  arref__mom_setup(&M, &h, axis, e, nrm, clip);
  return arref_sphere(c, r, (const double(*)[3])clip, 2, arref__mom_f, &M, &h, arref__mom_tol(e))
      .value;
}
ARREF_FN long double arref_ellipse_moment2(const double c[3], const double a1[3],
                                           const double a2[3], const double axis[3], double e,
                                           const double nrm[3]) {
  arref__mom M;
  arref_hint h;
  double clip[2][3];
  arref__mom_setup(&M, &h, axis, e, nrm, clip);
  return arref_ellipse(c, a1, a2, (const double(*)[3])clip, 2, arref__mom_f, &M, &h,
                       arref__mom_tol(e))
      .value;
}

/* ---------------------------------------------------------------- GGX */
typedef struct {
  long double n[3], v[3], a2, nv, lv;
} arref__ggx;
ARREF_FN long double arref__ggx_lambda(long double c, long double a2) {
  long double c2 = c * c, t2 = (1 - c2) / c2;
  return (sqrtl(1 + a2 * t2) - 1) / 2;
}
ARREF_FN long double arref__ggx_f(const long double u[3], void *ctx) {
  const arref__ggx *G = (const arref__ggx *)ctx;
  long double nl = arref__dot(G->n, u), h[3], hl, nh, d, D, G2;
  if (nl <= 0) return 0;
  h[0] = G->v[0] + u[0];
  h[1] = G->v[1] + u[1];
  h[2] = G->v[2] + u[2];
  hl = sqrtl(arref__dot(h, h));
  if (!(hl > 0)) return 0;
  nh = arref__dot(G->n, h) / hl;
  d = nh * nh * (G->a2 - 1) + 1;
  D = G->a2 / (ARREF_PI * d * d);
  G2 = 1 / (1 + G->lv + arref__ggx_lambda(nl, G->a2));
  return D * G2 / (4 * G->nv);
}
ARREF_FN void arref__ggx_setup(arref__ggx *G, arref_hint *h, const double nrm[3],
                               const double view[3], double alpha) {
  long double s;
  int k;
  arref__ld3(nrm, G->n);
  arref__normalize(G->n);
  arref__ld3(view, G->v);
  arref__normalize(G->v);
  G->a2 = (long double)alpha * (long double)alpha;
  G->nv = arref__dot(G->n, G->v);
  G->lv = arref__ggx_lambda(G->nv, G->a2);
  for (k = 0; k < 3; k++)
    h->axis[k] = 2 * G->nv * G->n[k] - G->v[k];
  s = (long double)alpha * (G->nv > 0.05L ? G->nv : 0.05L);
  h->sigma = s < 1 ? s : 1;
}
/* albedo over the 4 octant triangles of the upper hemisphere */
ARREF_FN arref_result arref__ggx_albedo_r(const double nrm[3], const double view[3], double alpha,
                                          long double abs_tol) {
  arref__ggx G;
  arref_hint h;
  arref__st s;
  long double tri[4][3][3];
  arref_result res;
  arref__ggx_setup(&G, &h, nrm, view, alpha);
  arref__hemi_tris(G.n, tri);
  arref__st_init(&s, arref__ggx_f, &G, &h, abs_tol, 12);
  res.value = arref__tris(&s, tri, 4);
  res.err_est = s.err;
  res.evals = s.evals;
  res.converged = s.ok;
  return res;
}
/* cached coarse albedo (sets the absolute tolerance of the GGX light integrals) */
static double arref__alb_key[7];
static long double arref__alb_val = -1;
ARREF_FN long double arref__ggx_scale(const double nrm[3], const double view[3], double alpha) {
  int k, same = arref__alb_val > 0;
  for (k = 0; k < 3 && same; k++)
    same = arref__alb_key[k] == nrm[k] && arref__alb_key[3 + k] == view[k];
  if (same && arref__alb_key[6] == alpha) return arref__alb_val;
  arref__alb_val = arref__ggx_albedo_r(nrm, view, alpha, 1e-5L).value;
  for (k = 0; k < 3; k++) {
    arref__alb_key[k] = nrm[k];
    arref__alb_key[3 + k] = view[k];
  }
  arref__alb_key[6] = alpha;
  if (!(arref__alb_val > 1e-6L)) arref__alb_val = 1e-6L;
  return arref__alb_val;
}
ARREF_FN long double arref_ggx_albedo(const double nrm[3], const double view[3], double alpha) {
  return arref__ggx_albedo_r(nrm, view, alpha,
                             arref_ggx_rel_tol * arref__ggx_scale(nrm, view, alpha))
      .value;
}
ARREF_FN long double arref_polygon_ggx(const double (*v)[3], int nv, const double nrm[3],
                                       const double view[3], double alpha) {
  arref__ggx G;
  arref_hint h;
  long double tol = arref_ggx_rel_tol * arref__ggx_scale(nrm, view, alpha);
  arref__ggx_setup(&G, &h, nrm, view, alpha);
  return arref__polygon_o(v, nv, (const double(*)[3])nrm, 1, arref__ggx_f, &G, &h, tol, 12).value;
}
ARREF_FN long double arref_sphere_ggx(const double c[3], double r, const double nrm[3],
                                      const double view[3], double alpha) {
  arref__ggx G;
  arref_hint h;
  long double tol = arref_ggx_rel_tol * arref__ggx_scale(nrm, view, alpha);
  arref__ggx_setup(&G, &h, nrm, view, alpha);
  return arref_sphere(c, r, (const double(*)[3])nrm, 1, arref__ggx_f, &G, &h, tol).value;
}
ARREF_FN long double arref_ellipse_ggx(const double c[3], const double a1[3], const double a2[3],
                                       const double nrm[3], const double view[3], double alpha) {
  arref__ggx G;
  arref_hint h;
  long double tol = arref_ggx_rel_tol * arref__ggx_scale(nrm, view, alpha);
  arref__ggx_setup(&G, &h, nrm, view, alpha);
  return arref_ellipse(c, a1, a2, (const double(*)[3])nrm, 1, arref__ggx_f, &G, &h, tol).value;
}

/* ---------------------------------------------------------------- Blinn-Phong and Beckmann
   kind 0: Blinn-Phong microfacet with the implicit G = (n.l)(n.v) (f = D_Blinn / 4), integrand
           f (n.l) = (e+2)/(8 pi) (n.h)^e (n.l);
   kind 1: Beckmann with the height-correlated Smith G2 = 1 / (1 + Lambda(v) + Lambda(l)),
           Lambda(c) = (erf(a) - 1)/2 + exp(-a^2)/(2 a sqrt(pi)), a = c / (alpha sqrt(1 - c^2)),
           integrand D_B G2 / (4 (n.v)), D_B = exp(-tan^2 t / alpha^2) / (pi alpha^2 cos^4 t);
   kind 2: the half-vector measure of [AREA] eq. 23-24, D_Blinn(h) / (4 (h.l)): its integral
           over the light is int over H(light) of D_Blinn(h) dh;
   kind 3: D_B(h) (h.n) / (4 (h.l)): int over H(light) of D_B(h) (h.n) dh;
   kind 4: D_B / (4 (n.v)), kind 1 without G2.
   par: the exponent e (kinds 0, 2) or alpha (kinds 1, 3). */
typedef struct {
  long double n[3], v[3], par, nv, lv;
  int kind;
} arref__mf;
ARREF_FN long double arref__beck_lambda(long double c, long double al) {
  long double a;
  if (c >= 1) return 0;
  a = c / (al * sqrtl(1 - c * c));
  return (erfl(a) - 1) / 2 + expl(-a * a) / (2 * a * sqrtl(ARREF_PI));
}
ARREF_FN long double arref__beck_d(long double nh, long double al) {
  long double c2 = nh * nh, t2 = (1 - c2) / c2;
  if (nh <= 0) return 0;
  return expl(-t2 / (al * al)) / (ARREF_PI * al * al * c2 * c2);
}
ARREF_FN long double arref__mf_f(const long double u[3], void *ctx) {
  const arref__mf *M = (const arref__mf *)ctx;
  long double nl = arref__dot(M->n, u), h[3], hl, nh, hu;
  if (nl <= 0) return 0;
  h[0] = M->v[0] + u[0];
  h[1] = M->v[1] + u[1];
  h[2] = M->v[2] + u[2];
  hl = sqrtl(arref__dot(h, h));
  if (!(hl > 0)) return 0;
  nh = arref__dot(M->n, h) / hl;
  hu = arref__dot(u, h) / hl;
  if (nh <= 0) return 0;
  switch (M->kind) {
  case 0:
    return (M->par + 2) / (8 * ARREF_PI) * powl(nh, M->par) * nl;
  case 1:
    return arref__beck_d(nh, M->par) / (1 + M->lv + arref__beck_lambda(nl, M->par)) / (4 * M->nv);
  case 4:
    return arref__beck_d(nh, M->par) / (4 * M->nv);
  case 2:
    return (M->par + 2) / (2 * ARREF_PI) * powl(nh, M->par) / (4 * hu);
  default:
    return arref__beck_d(nh, M->par) * nh / (4 * hu);
  }
}
ARREF_FN void arref__mf_setup(arref__mf *M, arref_hint *h, const double nrm[3],
                              const double view[3], double par, int kind) {
  long double s, al;
  int k;
  arref__ld3(nrm, M->n);
  arref__normalize(M->n);
  arref__ld3(view, M->v);
  arref__normalize(M->v);
  M->kind = kind;
  M->par = (long double)par;
  M->nv = arref__dot(M->n, M->v);
  M->lv = (kind == 1) ? arref__beck_lambda(M->nv, M->par) : 0;
  for (k = 0; k < 3; k++)
    h->axis[k] = 2 * M->nv * M->n[k] - M->v[k];
  al = (kind == 1 || kind == 3 || kind == 4) ? M->par : sqrtl(2 / (M->par + 2));
  s = al * (M->nv > 0.05L ? M->nv : 0.05L);
  h->sigma = s < 1 ? s : 1;
}
/* directional albedo of kinds 0 and 1 (the hemisphere as 4 octant triangles), abs tol tol */
ARREF_FN long double arref_mf_albedo(const double nrm[3], const double view[3], double par,
                                     int kind, long double tol) {
  arref__mf M;
  arref_hint h;
  arref__st s;
  long double tri[4][3][3];
  arref__mf_setup(&M, &h, nrm, view, par, kind);
  arref__hemi_tris(M.n, tri);
  arref__st_init(&s, arref__mf_f, &M, &h, tol, 12);
  return arref__tris(&s, tri, 4);
}
/* the integral over the polygon (clipped to n.l >= 0) of integrand `kind`, absolute tolerance
   tol */
ARREF_FN long double arref_polygon_mf(const double (*v)[3], int nv, const double nrm[3],
                                      const double view[3], double par, int kind, long double tol) {
  arref__mf M;
  arref_hint h;
  arref__mf_setup(&M, &h, nrm, view, par, kind);
  return arref__polygon_o(v, nv, (const double(*)[3])nrm, 1, arref__mf_f, &M, &h, tol, 12).value;
}

/* ---------------------------------------------------------------- Arvo exact moment */
ARREF_FN long double arref_polygon_moment_arvo(const double (*v)[3], int nv, const double axis[3],
                                               int e, const double *nrm) {
  long double m[2][3], (*p)[3], r[3], omega = 0, sum = 0;
  int np, i, k;
  if (e < 0) return 0;
  arref__ld3(axis, r);
  arref__normalize(r);
  m[0][0] = r[0];
  m[0][1] = r[1];
  m[0][2] = r[2];
  if (nrm) {
    arref__ld3(nrm, m[1]);
    arref__normalize(m[1]);
  }
  np = arref__clip_poly(v, nv, (const long double(*)[3])m, nrm ? 2 : 1, &p);
  if (np < 3) {
    free(p);
    return 0;
  }
  for (i = 0; i < np; i++)
    arref__normalize(p[i]);
  for (i = 1; i + 1 < np; i++) {
    long double x[3];
    arref__cross(p[i], p[i + 1], x);
    omega +=
        2 * atan2l(arref__dot(p[0], x), 1 + arref__dot(p[0], p[i]) + arref__dot(p[0], p[i + 1]) +
                                            arref__dot(p[i], p[i + 1]));
  }
  if (omega < 0) { /* reverse the winding */
    for (i = 0; i < np / 2; i++)
      for (k = 0; k < 3; k++) {
        long double t = p[i][k];
        p[i][k] = p[np - 1 - i][k];
        p[np - 1 - i][k] = t;
      }
    omega = -omega;
  }
  for (i = 0; i < np; i++) {
    const long double *a = p[i], *b = p[(i + 1) % np];
    long double ev[3], len, ta[3], tb[3], A, B, sA, sB, c2, T, S, pa, pb, a2, b2;
    arref__cross(a, b, ev);
    len = arref__normalize(ev);
    if (!(len > 0)) continue;
    A = arref__dot(a, r);
    B = arref__dot(b, r);
    arref__cross(ev, a, ta);
    arref__cross(ev, b, tb);
    sA = -arref__dot(ta, r);
    sB = -arref__dot(tb, r);
    c2 = A * A + sA * sA;
    a2 = A * A;
    b2 = B * B;
    if (e % 2 == 1) { /* even k: T_0, T_2, ..., T_{e-1} */
      T = atan2l(len, arref__dot(a, b));
      S = T;
      pa = A;
      pb = B;
      for (k = 2; k <= e - 1; k += 2) {
        T = (pb * sB - pa * sA) / (long double)k + c2 * (long double)(k - 1) / (long double)k * T;
        S += T;
        pa *= a2;
        pb *= b2;
        if (fabsl(pa) < 1e-4000L) pa = 0;
        if (fabsl(pb) < 1e-4000L) pb = 0;
        if (fabsl(T) < 1e-4000L) T = 0;
      }
    } else if (e >= 2) { /* odd k: T_1, T_3, ..., T_{e-1} */
      T = sB - sA;
      S = T;
      pa = a2;
      pb = b2;
      for (k = 3; k <= e - 1; k += 2) {
        T = (pb * sB - pa * sA) / (long double)k + c2 * (long double)(k - 1) / (long double)k * T;
        S += T;
        pa *= a2;
        pb *= b2;
        if (fabsl(pa) < 1e-4000L) pa = 0;
        if (fabsl(pb) < 1e-4000L) pb = 0;
        if (fabsl(T) < 1e-4000L) T = 0;
      }
    } else
      S = 0;
    sum += arref__dot(ev, r) * S;
  }
  free(p);
  return ((e % 2 == 0 ? omega : 0) + sum) / (long double)(e + 1);
}

#endif /* ARREARREF_H */
