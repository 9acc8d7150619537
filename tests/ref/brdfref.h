/* brdfref.h - an independent reference for BRDF SH tables, in long double: its own GGX
 * (isotropic or anisotropic, height-correlated Smith, Schlick) and Phong lobe, its own real SH
 * (associated Legendre recurrence, Condon-Shortley phase, the >>basis convention), and the
 * projection of F = cos_i f and F' = f by nested adaptive Gauss-Legendre quadrature over the
 * hemisphere (outer theta_i, inner phi_i; each panel compares the 12- and 24-point rules and
 * bisects until they agree to tol), written without any of shlight's quadrature or BRDF code. */
#ifndef BRDFREF_H
#define BRDFREF_H
#include <math.h>
#include <string.h>

#define BRDFREF_MAXN 10 /* bands */
#define BRDFREF_PI 3.141592653589793238462643383279502884L

typedef struct brdfref {
  int model; /* 0: GGX, 1: Phong */
  long double alpha, f0, exponent;
  long double alpha_y; /* > 0: anisotropic GGX, alpha along x, alpha_y along y; else isotropic */
  int n;
  long double wo[3];
  long double tol;
} brdfref;

static long double brdfref_x12[12], brdfref_w12[12], brdfref_x24[24], brdfref_w24[24];

static void brdfref_gl(int q, long double *x, long double *w) {
  int i, k, it;
  for (i = 0; i < q; ++i) {
    long double z = cosl(BRDFREF_PI * ((long double)i + 0.75L) / ((long double)q + 0.5L)), p0, p1,
                dp = 1.0L;
    for (it = 0; it < 100; ++it) {
      long double dz;
      p0 = 1.0L;
      p1 = 0.0L;
      for (k = 1; k <= q; ++k) {
        long double p2 = p1;
        p1 = p0;
        p0 = ((2.0L * k - 1.0L) * z * p1 - (k - 1.0L) * p2) / k;
      }
      dp = q * (z * p0 - p1) / (z * z - 1.0L);
      dz = p0 / dp;
      z -= dz;
      if (fabsl(dz) < 1e-19L) break;
    }
    x[i] = z;
    w[i] = 2.0L / ((1.0L - z * z) * dp * dp);
  }
}

static long double brdfref_k[BRDFREF_MAXN][BRDFREF_MAXN];

static void brdfref_init(void) {
  int l, m, j;
  brdfref_gl(12, brdfref_x12, brdfref_w12);
  brdfref_gl(24, brdfref_x24, brdfref_w24);
  for (l = 0; l < BRDFREF_MAXN; ++l)
    for (m = 0; m <= l; ++m) {
      long double f = 1.0L;
      for (j = l - m + 1; j <= l + m; ++j)
        f *= (long double)j; /* (l + m)! / (l - m)! */
      brdfref_k[l][m] =
          sqrtl((2.0L * l + 1.0L) / (4.0L * BRDFREF_PI) / f) * (m ? sqrtl(2.0L) : 1.0L);
    }
}

/* real SH, n bands, at (theta, phi) */
static void brdfref_sh(int n, long double ct, long double phi, long double *y) {
  long double st = sqrtl(fmaxl(0.0L, 1.0L - ct * ct)), p[BRDFREF_MAXN][BRDFREF_MAXN],
              cm[BRDFREF_MAXN], sm[BRDFREF_MAXN];
  int l, m;
  p[0][0] = 1.0L;
  for (m = 1; m < n; ++m)
    p[m][m] = -(2.0L * m - 1.0L) * st * p[m - 1][m - 1]; /* Condon-Shortley phase */
  for (m = 0; m + 1 < n; ++m)
    p[m + 1][m] = (2.0L * m + 1.0L) * ct * p[m][m];
  for (m = 0; m < n; ++m)
    for (l = m + 2; l < n; ++l)
      p[l][m] = ((2.0L * l - 1.0L) * ct * p[l - 1][m] - (l + m - 1.0L) * p[l - 2][m]) / (l - m);
  for (m = 0; m < n; ++m) {
    cm[m] = cosl(m * phi);
    sm[m] = sinl(m * phi);
  }
  for (l = 0; l < n; ++l)
    for (m = 0; m <= l; ++m) {
      if (m == 0) {
        y[l * (l + 1)] = brdfref_k[l][0] * p[l][0];
      } else {
        y[l * (l + 1) + m] = brdfref_k[l][m] * cm[m] * p[l][m];
        y[l * (l + 1) - m] = brdfref_k[l][m] * sm[m] * p[l][m];
      }
    }
}

static long double brdfref_f(const brdfref *r, const long double wi[3]) {
  const long double *wo = r->wo;
  if (!(wi[2] > 0.0L) || !(wo[2] > 0.0L)) return 0.0L;
  if (r->model == 1) {
    long double c = 2.0L * wo[2] * wi[2] - (wo[0] * wi[0] + wo[1] * wi[1] + wo[2] * wi[2]);
    return c > 0.0L ? (r->exponent + 1.0L) / (2.0L * BRDFREF_PI) * powl(c, r->exponent) : 0.0L;
  } else {
    long double h[3] = {wi[0] + wo[0], wi[1] + wo[1], wi[2] + wo[2]}, hl, a2 = r->alpha * r->alpha,
                d, lo, li, t, c, fr;
    hl = sqrtl(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
    h[0] /= hl;
    h[1] /= hl;
    h[2] /= hl;
    if (r->alpha_y > 0.0L) { /* D = 1 / (pi ax ay (hx^2 / ax^2 + hy^2 / ay^2 + hz^2)^2) */
      long double ax = r->alpha, ay = r->alpha_y, sx = h[0] / ax, sy = h[1] / ay;
      t = sx * sx + sy * sy + h[2] * h[2];
      d = 1.0L / (BRDFREF_PI * ax * ay * t * t);
      lo = 0.5L *
           (sqrtl(1.0L + (ax * ax * wo[0] * wo[0] + ay * ay * wo[1] * wo[1]) / (wo[2] * wo[2])) -
            1.0L);
      li = 0.5L *
           (sqrtl(1.0L + (ax * ax * wi[0] * wi[0] + ay * ay * wi[1] * wi[1]) / (wi[2] * wi[2])) -
            1.0L);
    } else {
      t = h[2] * h[2] * (a2 - 1.0L) + 1.0L;
      d = a2 / (BRDFREF_PI * t * t);
      lo = 0.5L * (sqrtl(1.0L + a2 * (1.0L - wo[2] * wo[2]) / (wo[2] * wo[2])) - 1.0L);
      li = 0.5L * (sqrtl(1.0L + a2 * (1.0L - wi[2] * wi[2]) / (wi[2] * wi[2])) - 1.0L);
    }
    c = 1.0L - (wi[0] * h[0] + wi[1] * h[1] + wi[2] * h[2]);
    if (c < 0.0L) c = 0.0L;
    fr = r->f0 + (1.0L - r->f0) * c * c * c * c * c;
    return d * fr / (1.0L + lo + li) / (4.0L * wi[2] * wo[2]);
  }
}

/* inner: integral over phi in [a, b] at cos theta_i = ct (sin st) of f [ct Y, Y] */
static void brdfref_phi_rule(const brdfref *r, long double ct, long double st, long double a,
                             long double b, int q, long double *out) {
  const long double *x = q == 12 ? brdfref_x12 : brdfref_x24,
                    *w = q == 12 ? brdfref_w12 : brdfref_w24;
  int nn = r->n * r->n, i, k;
  long double y[BRDFREF_MAXN * BRDFREF_MAXN];
  memset(out, 0, sizeof(long double) * 2 * nn);
  for (i = 0; i < q; ++i) {
    long double ph = 0.5L * (a + b) + 0.5L * (b - a) * x[i], wi[3], f;
    wi[0] = st * cosl(ph);
    wi[1] = st * sinl(ph);
    wi[2] = ct;
    f = brdfref_f(r, wi);
    if (f == 0.0L) continue;
    f *= 0.5L * (b - a) * w[i];
    brdfref_sh(r->n, ct, ph, y);
    for (k = 0; k < nn; ++k) {
      out[k] += f * ct * y[k];
      out[nn + k] += f * y[k];
    }
  }
}

static void brdfref_phi(const brdfref *r, long double ct, long double st, long double a,
                        long double b, int depth, long double *out) {
  long double g1[2 * BRDFREF_MAXN * BRDFREF_MAXN], g2[2 * BRDFREF_MAXN * BRDFREF_MAXN], e = 0.0L;
  int nn2 = 2 * r->n * r->n, k;
  brdfref_phi_rule(r, ct, st, a, b, 12, g1);
  brdfref_phi_rule(r, ct, st, a, b, 24, g2);
  for (k = 0; k < nn2; ++k)
    e = fmaxl(e, fabsl(g1[k] - g2[k]));
  if (e <= r->tol * (b - a) || depth >= 30) {
    for (k = 0; k < nn2; ++k)
      out[k] += g2[k];
    return;
  }
  brdfref_phi(r, ct, st, a, 0.5L * (a + b), depth + 1, out);
  brdfref_phi(r, ct, st, 0.5L * (a + b), b, depth + 1, out);
}

/* outer: integral over theta in [a, b] of sin(theta) (inner integral) */
static void brdfref_theta_rule(const brdfref *r, long double a, long double b, int q,
                               long double *out) {
  const long double *x = q == 12 ? brdfref_x12 : brdfref_x24,
                    *w = q == 12 ? brdfref_w12 : brdfref_w24;
  int nn2 = 2 * r->n * r->n, i, k;
  long double in[2 * BRDFREF_MAXN * BRDFREF_MAXN];
  memset(out, 0, sizeof(long double) * nn2);
  for (i = 0; i < q; ++i) {
    long double th = 0.5L * (a + b) + 0.5L * (b - a) * x[i], wt = 0.5L * (b - a) * w[i];
    memset(in, 0, sizeof in);
    /* phi panels split at the lobe's azimuth (phi = pi for a mirror lobe of w_o at phi = 0) */
    brdfref_phi(r, cosl(th), sinl(th), -BRDFREF_PI, 0.0L, 0, in);
    brdfref_phi(r, cosl(th), sinl(th), 0.0L, BRDFREF_PI, 0, in);
    for (k = 0; k < nn2; ++k)
      out[k] += wt * sinl(th) * in[k];
  }
}

static void brdfref_theta(const brdfref *r, long double a, long double b, int depth,
                          long double *out) {
  long double g1[2 * BRDFREF_MAXN * BRDFREF_MAXN], g2[2 * BRDFREF_MAXN * BRDFREF_MAXN], e = 0.0L;
  int nn2 = 2 * r->n * r->n, k;
  brdfref_theta_rule(r, a, b, 12, g1);
  brdfref_theta_rule(r, a, b, 24, g2);
  for (k = 0; k < nn2; ++k)
    e = fmaxl(e, fabsl(g1[k] - g2[k]));
  if (e <= r->tol * (b - a) || depth >= 40) {
    for (k = 0; k < nn2; ++k)
      out[k] += g2[k];
    return;
  }
  brdfref_theta(r, a, 0.5L * (a + b), depth + 1, out);
  brdfref_theta(r, 0.5L * (a + b), b, depth + 1, out);
}

/* the SH of F (out[0 .. n^2)) and F' (out[n^2 .. 2 n^2)) at w_o = (sin t, 0, cos t), t = theta_o,
   to an absolute tolerance of about tol (per unit of integration range) */
static void brdfref_project(brdfref *r, long double theta_o, long double *out) {
  long double th_r = theta_o; /* the lobe's polar angle: theta panels split there */
  r->wo[0] = sinl(theta_o);
  r->wo[1] = 0.0L;
  r->wo[2] = cosl(theta_o);
  memset(out, 0, sizeof(long double) * 2 * r->n * r->n);
  brdfref_theta(r, 0.0L, th_r, 0, out);
  brdfref_theta(r, th_r, 0.5L * BRDFREF_PI, 0, out);
}
#endif
