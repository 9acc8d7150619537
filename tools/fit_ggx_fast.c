/* fit_ggx_fast.c - the fit behind shl_polygon_ggx_fast (shlight.h, >>edge "fast GGX polygon
 * lights"): a linearly transformed cosine whose transform and magnitude are closed-form
 * functions of (alpha, n.v), fitted to what a user sees, the polygon integrals of the accurate
 * shl_polygon_ggx, not to the lobe's shape (docs/area-lights.md "Fast GGX polygon lights").
 *
 *   build:  cc -O2 -std=c99 -o build/fit_ggx_fast tools/fit_ggx_fast.c -lm
 *   points: build/fit_ggx_fast points > build/ggx_fast_points.txt
 *           the optimum (Nelder-Mead) of the 5 parameters at each of 17 x 15 grid points
 *           (roughness x view angle), 160 training quads each (~1.5 min)
 *   smooth: build/fit_ggx_fast smooth build/ggx_fast_points.txt tools/ggx_fast_coef.txt
 *           the albedo fit and the weighted least-squares polynomials through the points: the
 *           high set (roughness r >= 0.3; its low set left 0)
 *   points low: build/fit_ggx_fast points low > build/ggx_fast_points_low.txt
 *           the same on the low grid (19 roughness values, 0.01 to 0.4; 21 view angles, 9 of
 *           them 73 to 86 deg) with k held at 1 (~1 min)
 *   smoothlow: build/fit_ggx_fast smoothlow build/ggx_fast_points_low.txt COEF_IN COEF_OUT
 *           the low set (r <= 0.25; x = 2 r / 0.35 - 1, degree 7 in 2 mu - 1, pinned at the
 *           alpha -> 0 limit), the high set kept from COEF_IN; the kernel interpolates the two for
 *           0.25 < r < 0.3 (KEEP_ALB=1: the low albedo of COEF_IN kept, no refit)
 *   check:  build/fit_ggx_fast check tools/ggx_fast_coef.txt
 *           median / p95 / max relative error and max error / albedo on the bench sampler;
 *           CHECK_R="r0,r1,..." checks other roughness values (TRY_RL, TRY_RS: other splits,
 *           for experiments; emit writes them into the kernel; CHECK_TEST=1: tests/test_ggx.c's
 *           24 quads per roughness instead of the bench's 250)
 *   lm:     build/fit_ggx_fast lm COEF_IN COEF_OUT ITERATIONS
 *           Levenberg-Marquardt on all coefficients against every training quad (tried, not
 *           used: it lowered the training cost but raised the median at low roughness)
 *   emit:   build/fit_ggx_fast emit tools/ggx_fast_coef.txt shlight.h
 *           writes the packed table SHLI_GGX_FAST_FIT and its Horner loops (shli_ggx_fast_poly,
 *           shli_ggx_fast_fit) between the @fit ggx_fast markers; then python3
 *           tools/gen_basis.py (the GLSL twin) and python3 tools/gen_glsl_one.py
 *   --check build/fit_ggx_fast --check tools/ggx_fast_coef.txt shlight.h   (tests/run.sh)
 *
 * Training quads: tests/ref/ggxcases.h's sampler at a fixed view angle with its own seeds
 * (never the seed 2017 of the bench sampler nor the seeds of tests/test_ggx.c). */
#define _POSIX_C_SOURCE 200809L
#define SHLIGHT_IMPLEMENTATION
#include "../shlight.h"
#include "../tests/ref/arearef.h"
#include "../tests/ref/ggxcases.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NQ 160
#define NRG 17
#define NTH 15
static const double RG[NRG] = {0.01, 0.025, 0.05, 0.075, 0.1, 0.15, 0.2,  0.25, 0.3,
                               0.4,  0.5,   0.6,  0.7,   0.8, 0.9,  0.95, 1.0};
static const double *RGP = RG; /* the grid `points` runs over (RGL for `points low`) */
static const double TH[NTH] = {0, 10, 20, 30, 40, 50, 60, 65, 70, 75, 80, 83, 86, 88, 89};
/* the view angles of `points low`: denser at grazing (a low-roughness lobe changes fast there) */
#define NTHL 21
static const double THL[NTHL] = {0,  10, 20, 30, 40, 50, 60, 65, 70, 73, 75,
                                 76, 78, 80, 82, 83, 84, 85, 86, 88, 89};

typedef struct {
  double q[NQ][4][3];
  double gt[NQ];
  double alb, mu, s, alpha;
} pt;

static pt P;

static double ltc(const double q[4][3], const double *m, double mu, double s) {
  double px[SHLIGHT_CLIP_MAX], py[SHLIGHT_CLIP_MAX], pz[SHLIGHT_CLIP_MAX];
  double ux = -s * m[3], uz = mu, l = sqrt(ux * ux + uz * uz);
  int i;
  for (i = 0; i < 4; ++i)
    px[i] = q[i][0], py[i] = q[i][1], pz[i] = q[i][2];
  return shli_ltc_ff(px, py, pz, 4, m[0], m[1], m[2], ux / l, uz / l);
}

/* the per-point parameters p: log(a / alpha), g (c = a (mu + (1 - mu) g)), d, P, log k; the
   transform m: a, c, d, P (the axis (-s P, 0, mu) normalised), k */
static double gmu; /* mu of the point p2m is called for */
static void p2m(const double *p, double alpha, double *m) {
  double g = gmu + (1 - gmu) * p[1];
  m[0] = alpha * (p[0] > 0.05 ? p[0] : 0.05), m[1] = m[0] * (g > 1e-3 ? g : 1e-3), m[2] = p[2];
  m[3] = p[3], m[4] = p[4];
}
static double prior[5];
static int fixk; /* k held at 1 (`points low`) */
static double obj(const double *p) {
  double sum = 0, mx = 0, m[5], reg = 0;
  int i;
  if (p[1] < -0.5 || p[1] > 3 || fabs(p[2]) > 3 || p[3] < 0 || p[3] > 3 || fabs(p[4]) > 1)
    return 1e30;
  gmu = P.mu;
  {
    double q[5];
    memcpy(q, p, sizeof q);
    q[0] = exp(p[0]), q[4] = exp(p[4]); /* the optimiser works on the logs */
    if (fixk) q[4] = 1;
    p2m(q, P.alpha, m);
  }
  for (i = 0; i < NQ; ++i) {
    double f = m[4] * P.alb * ltc((const double(*)[3])P.q[i], m, P.mu, P.s);
    double e = (f - P.gt[i]) / (P.gt[i] + 0.02 * P.alb);
    double ea = fabs(f - P.gt[i]) / P.alb;
    sum += e * e;
    if (ea > mx) mx = ea;
  }
  for (i = 0; i < 5; ++i)
    reg += (p[i] - prior[i]) * (p[i] - prior[i]);
  return sum / NQ + mx * mx + 1e-10 * reg;
}

static double nm(double *x, int n, double step, int iters) {
  double s[6][5], f[6], c[5], xr[5], xe[5], fr, fe;
  int i, j, it;
  for (i = 0; i <= n; ++i) {
    for (j = 0; j < n; ++j)
      s[i][j] = x[j] + (i == j + 1 ? step : 0);
    f[i] = obj(s[i]);
  }
  for (it = 0; it < iters; ++it) {
    int hi = 0, lo = 0, sh;
    for (i = 1; i <= n; ++i) {
      if (f[i] > f[hi]) hi = i;
      if (f[i] < f[lo]) lo = i;
    }
    sh = lo;
    for (i = 0; i <= n; ++i)
      if (i != hi && f[i] > f[sh]) sh = i;
    for (j = 0; j < n; ++j) {
      c[j] = 0;
      for (i = 0; i <= n; ++i)
        if (i != hi) c[j] += s[i][j] / n;
    }
    for (j = 0; j < n; ++j)
      xr[j] = c[j] + (c[j] - s[hi][j]);
    fr = obj(xr);
    if (fr < f[lo]) {
      for (j = 0; j < n; ++j)
        xe[j] = c[j] + 2 * (c[j] - s[hi][j]);
      fe = obj(xe);
      if (fe < fr)
        memcpy(s[hi], xe, sizeof xe), f[hi] = fe;
      else
        memcpy(s[hi], xr, sizeof xr), f[hi] = fr;
    } else if (fr < f[sh]) {
      memcpy(s[hi], xr, sizeof xr), f[hi] = fr;
    } else {
      for (j = 0; j < n; ++j)
        xe[j] = c[j] + 0.5 * (s[hi][j] - c[j]);
      fe = obj(xe);
      if (fe < f[hi]) {
        memcpy(s[hi], xe, sizeof xe), f[hi] = fe;
      } else {
        for (i = 0; i <= n; ++i)
          if (i != lo) {
            for (j = 0; j < n; ++j)
              s[i][j] = s[lo][j] + 0.5 * (s[i][j] - s[lo][j]);
            f[i] = obj(s[i]);
          }
      }
    }
  }
  {
    int lo = 0;
    for (i = 1; i <= n; ++i)
      if (f[i] < f[lo]) lo = i;
    memcpy(x, s[lo], sizeof(double) * (size_t)n);
    return f[lo];
  }
}

static void setup(int ir, double th, unsigned long long seed) {
  ggxc_rng rg;
  double n[3] = {0, 0, 1}, v[3];
  int i, k;
  rg.s = seed;
  P.alpha = RGP[ir] * RGP[ir];
  P.mu = cos(th * 3.14159265358979323846 / 180);
  P.s = sin(th * 3.14159265358979323846 / 180);
  v[0] = P.s, v[1] = 0, v[2] = P.mu;
  P.alb = (double)arref_ggx_albedo(n, v, P.alpha);
  for (i = 0; i < NQ; ++i) {
    ggxc_case cs;
    float fq[4][3], fv[3], fn[3] = {0, 0, 1};
    fv[0] = (float)P.s, fv[1] = 0.0f, fv[2] = (float)P.mu;
    ggxc_make(&rg, &cs, th);
    for (k = 0; k < 12; ++k)
      fq[k / 3][k % 3] = (float)cs.q[k / 3][k % 3], P.q[i][k / 3][k % 3] = fq[k / 3][k % 3];
    P.gt[i] = shl_polygon_ggx((const float(*)[3])fq, 4, fn, fv, (float)P.alpha);
  }
}

/* ---- the closed-form model: 5 polynomials in (r, mu) of degree DI in r and DJ in mu, and the
   albedo E0(tau) + sum_{i=1..AI, j=0..AJ} e_ij r^i tau^j, tau = alpha s / (mu + alpha s) */
#define DI 7
#define DJ 5
#define DJL 7 /* the low set's degree in mu (its k is 1: four outputs) */
#define AI 8
#define AJ 6
static double CO[5][DI + 1][DJ + 1], CA[AI + 1][AJ + 1];
/* the low-roughness set (r <= RS, in 2 r / RL - 1; see "the low-roughness set" below) */
static double RL = 0.35, RS = 0.25, RB = 0.3; /* TRY_RL, TRY_RS: other splits (experiments) */
#define NRGL 19
static const double RGL[NRGL] = {0.01,  0.0175, 0.025, 0.0325, 0.04,  0.05, 0.06, 0.075, 0.09, 0.1,
                                 0.125, 0.15,   0.175, 0.2,    0.225, 0.25, 0.3,  0.35,  0.4};
static double CL[5][DI + 1][DJL + 1], CAL[AI + 1][AJ + 1];

static double e0(double tau) {
  return (1 - tau) / sqrt((1 - tau) * (1 - tau) + tau * tau);
}
static double model_alb(double r, double mu) {
  double al = r * r, s = sqrt(1 - mu * mu), tau = al * s / (mu + al * s), e = e0(tau), ri = al;
  int i, j;
  for (i = 0; i <= AI; ++i) {
    double t = 0;
    for (j = AJ; j >= 0; --j)
      t = t * (2 * tau - 1) + CA[i][j];
    e += ri * t;
    ri *= 2 * r - 1;
  }
  return e;
}
static void model_p(double r, double mu, double *p) {
  int k, i, j;
  double x = 2 * r - 1, y = 2 * mu - 1;
  for (k = 0; k < 5; ++k) {
    double t = 0;
    for (i = DI; i >= 0; --i) {
      double u = 0;
      for (j = DJ; j >= 0; --j)
        u = u * y + CO[k][i][j];
      t = t * x + u;
    }
    p[k] = t;
  }
}

/* least squares by modified Gram-Schmidt: A (m x n, row-major, destroyed), b (m) -> x (n) */
static void lsq(double *A, double *b, int m, int n, double *x) {
  double *R = calloc((size_t)(n * n), sizeof *R);
  int i, j, k;
  for (j = 0; j < n; ++j) {
    double nr = 0;
    for (k = 0; k < j; ++k) {
      double d = 0;
      for (i = 0; i < m; ++i)
        d += A[i * n + k] * A[i * n + j];
      R[k * n + j] = d;
      for (i = 0; i < m; ++i)
        A[i * n + j] -= d * A[i * n + k];
    }
    for (i = 0; i < m; ++i)
      nr += A[i * n + j] * A[i * n + j];
    nr = sqrt(nr);
    R[j * n + j] = nr;
    for (i = 0; i < m; ++i)
      A[i * n + j] /= nr;
  }
  for (j = 0; j < n; ++j) {
    double d = 0;
    for (i = 0; i < m; ++i)
      d += A[i * n + j] * b[i];
    x[j] = d;
  }
  for (j = n - 1; j >= 0; --j) {
    for (k = j + 1; k < n; ++k)
      x[j] -= R[j * n + k] * x[k];
    x[j] /= R[j * n + j];
  }
  free(R);
}

static void fit_albedo(void) {
  enum { NR_ = 40, NT_ = 40 };
  int m = NR_ * NT_, n = (AI + 1) * (AJ + 1), ir, it, i, j, row = 0;
  double *A = malloc(sizeof(double) * (size_t)(m * n)), *b = malloc(sizeof(double) * (size_t)m),
         x[(AI + 1) * (AJ + 1)], nrm[3] = {0, 0, 1}, emax = 0, erel = 0;
  double *W = malloc(sizeof(double) * (size_t)m), *R = malloc(sizeof(double) * (size_t)m),
         *M = malloc(sizeof(double) * (size_t)m);
  for (ir = 0; ir < NR_; ++ir)
    for (it = 0; it < NT_; ++it) {
      double r = 0.01 + 0.99 * ir / (NR_ - 1.0), th = 88.5 * pow(it / (NT_ - 1.0), 0.7), v[3];
      double mu = cos(th * 3.14159265358979323846 / 180), s = sqrt(1 - mu * mu), al = r * r;
      double tau = al * s / (mu + al * s), ri = al, e;
      v[0] = s, v[1] = 0, v[2] = mu;
      e = (double)arref_ggx_albedo(nrm, v, al);
      R[row] = r, M[row] = mu, W[row] = 1 / (2e-5 + 3e-3 * al);
      for (i = 0; i <= AI; ++i) {
        for (j = 0; j <= AJ; ++j)
          A[row * n + i * (AJ + 1) + j] = W[row] * ri * pow(2 * tau - 1, j);
        ri *= 2 * r - 1;
      }
      b[row] = W[row] * (e - e0(tau));
      b[row] = b[row];
      M[row] = mu;
      R[row] = r;
      W[row] = e;
      row++;
    }
  lsq(A, b, m, n, x);
  for (i = 0; i <= AI; ++i)
    for (j = 0; j <= AJ; ++j)
      CA[i][j] = x[i * (AJ + 1) + j];
  for (row = 0; row < m; ++row) {
    double d = fabs(model_alb(R[row], M[row]) - W[row]);
    if (d > emax) emax = d;
    if (d / W[row] > erel) erel = d / W[row];
  }
  fprintf(stderr, "albedo fit: max abs err %.2e, max rel err %.2e (%d points)\n", emax, erel, m);
  {
    double rb[4] = {0.0, 0.075, 0.15, 0.35}, mxs[4] = {0, 0, 0, 0};
    int b;
    for (row = 0; row < m; ++row)
      for (b = 3; b >= 0; --b)
        if (R[row] >= rb[b]) {
          double d = fabs(model_alb(R[row], M[row]) - W[row]);
          if (d > mxs[b]) mxs[b] = d;
          break;
        }
    fprintf(stderr, "  max abs err by r from 0, 0.075, 0.15, 0.35: %.2e %.2e %.2e %.2e\n", mxs[0],
            mxs[1], mxs[2], mxs[3]);
    if (getenv("ALBDBG"))
      for (row = 0; row < m; ++row)
        fprintf(stderr, "%g %g %g %g\n", R[row], acos(M[row]) * 57.29577951308232, W[row],
                model_alb(R[row], M[row]) - W[row]);
  }
  free(A), free(b), free(W), free(R), free(M);
}

static void fit_params(const char *fn) {
  FILE *f = fopen(fn, "r");
  static double pr[1000], pm[1000], pv[1000][5], pw[1000];
  int np = 0, n = (DI + 1) * (DJ + 1), k, i, j, row;
  double th, alb, fx;
  while (f && fscanf(f, "%lf %lf %lf %lf %lf %lf %lf %lf %lf %lf", &pr[np], &th, &pm[np], &alb,
                     &pv[np][0], &pv[np][1], &pv[np][2], &pv[np][3], &pv[np][4], &fx) == 10) {
    pw[np] = 1 / (fx + 0.02);
    if (th < 1e-9) pw[np] *= 0.01; /* the axis is free at normal view */
    np++;
  }
  if (f) fclose(f);
  for (k = 0; k < 5; ++k) {
    double *A = malloc(sizeof(double) * (size_t)(np * n)), *b = malloc(sizeof(double) * (size_t)np),
           x[(DI + 1) * (DJ + 1)], emax = 0, p[5];
    for (row = 0; row < np; ++row) {
      for (i = 0; i <= DI; ++i)
        for (j = 0; j <= DJ; ++j)
          A[row * n + i * (DJ + 1) + j] =
              pw[row] * pow(2 * pr[row] - 1, i) * pow(2 * pm[row] - 1, j);
      b[row] = pw[row] * (k == 0 || k == 4 ? exp(pv[row][k]) : pv[row][k]);
    }
    lsq(A, b, np, n, x);
    for (i = 0; i <= DI; ++i)
      for (j = 0; j <= DJ; ++j)
        CO[k][i][j] = (double)(float)x[i * (DJ + 1) + j];
    for (row = 0; row < np; ++row) {
      model_p(pr[row], pm[row], p);
      if (fabs(p[k] - (k == 0 || k == 4 ? exp(pv[row][k]) : pv[row][k])) > emax)
        emax = fabs(p[k] - (k == 0 || k == 4 ? exp(pv[row][k]) : pv[row][k]));
    }
    fprintf(stderr, "param %d: %d points, max abs deviation %.3g\n", k, np, emax);
    free(A), free(b);
  }
}

static void save(const char *fn) {
  FILE *f = fopen(fn, "w");
  int k, i, j;
  for (k = 0; k < 5; ++k)
    for (i = 0; i <= DI; ++i)
      for (j = 0; j <= DJ; ++j)
        fprintf(f, "%.17g\n", CO[k][i][j]);
  for (i = 0; i <= AI; ++i)
    for (j = 0; j <= AJ; ++j)
      fprintf(f, "%.17g\n", CA[i][j]);
  for (k = 0; k < 5; ++k)
    for (i = 0; i <= DI; ++i)
      for (j = 0; j <= DJL; ++j)
        fprintf(f, "%.17g\n", CL[k][i][j]);
  for (i = 0; i <= AI; ++i)
    for (j = 0; j <= AJ; ++j)
      fprintf(f, "%.17g\n", CAL[i][j]);
  fclose(f);
}
static void load(const char *fn) {
  FILE *f = fopen(fn, "r");
  int k, i, j;
  for (k = 0; k < 5; ++k)
    for (i = 0; i <= DI; ++i)
      for (j = 0; j <= DJ; ++j)
        if (fscanf(f, "%lf", &CO[k][i][j]) != 1) exit(3);
  for (i = 0; i <= AI; ++i)
    for (j = 0; j <= AJ; ++j)
      if (fscanf(f, "%lf", &CA[i][j]) != 1) exit(3);
  for (k = 0; k < 5; ++k) /* the low set (absent in a file from `smooth`: left 0) */
    for (i = 0; i <= DI; ++i)
      for (j = 0; j <= DJL; ++j)
        if (fscanf(f, "%lf", &CL[k][i][j]) != 1) CL[k][i][j] = 0;
  for (i = 0; i <= AI; ++i)
    for (j = 0; j <= AJ; ++j)
      if (fscanf(f, "%lf", &CAL[i][j]) != 1) CAL[i][j] = 0;
  fclose(f);
}

static int cmpd(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return x < y ? -1 : x > y;
}
static double pct(double *a, int n, double p) {
  if (n == 0) return 0;
  qsort(a, (size_t)n, sizeof *a, cmpd);
  return a[(int)floor(p * (n - 1) + 0.5)];
}

/* ---- the low-roughness set (r <= RS): the same model shape with its own coefficients, in
   xl = 2 r / RL - 1 instead of 2 r - 1, fitted to the points of `points low` (a finer grid,
   r 0.01 to RL, with k held at 1: the low set's k is 1, so a quad that holds the whole lobe gets
   exactly the albedo fit). As alpha -> 0 the GGX slope distribution has the cosine's gnomonic
   shape (1 + |p|^2)^-2: the lobe tends to the cosine mapped by the reflection's Jacobian at the
   mirror direction times alpha, a = 2 alpha, c = a mu, d = 0, P = 1; the fit is pinned there at
   r = 0. */
static double xlow(double r) {
  return r * (2.0 / RL) - 1;
}
static void model_p_low(double r, double mu, double *p) {
  int k, i, j;
  double x = xlow(r), y = 2 * mu - 1;
  for (k = 0; k < 5; ++k) {
    double t = 0;
    for (i = DI; i >= 0; --i) {
      double u = 0;
      for (j = DJL; j >= 0; --j)
        u = u * y + CL[k][i][j];
      t = t * x + u;
    }
    p[k] = t;
  }
}
static double model_alb_low(double r, double mu) {
  double al = r * r, s = sqrt(1 - mu * mu), tau = al * s / (mu + al * s), x = xlow(r), t = 0;
  int i, j;
  for (i = AI; i >= 0; --i) {
    double u = 0;
    for (j = AJ; j >= 0; --j)
      u = u * (2 * tau - 1) + CAL[i][j];
    t = t * x + u;
  }
  return e0(tau) + al * t;
}
/* the albedo of the low set: relative least squares on a 40 x 40 grid (r 0.005 to RL, view 0 to
   89 deg) against the long double albedo */
static void fit_albedo_low(void) {
  enum { NR_ = 40, NT_ = 40 };
  int m = NR_ * NT_, n = (AI + 1) * (AJ + 1), ir, it, i, j, row = 0;
  double *A = malloc(sizeof(double) * (size_t)(m * n)), *b = malloc(sizeof(double) * (size_t)m),
         x[(AI + 1) * (AJ + 1)], nrm[3] = {0, 0, 1}, emax = 0,
         *E = malloc(sizeof(double) * (size_t)m), *R = malloc(sizeof(double) * (size_t)m),
         *M = malloc(sizeof(double) * (size_t)m);
  for (ir = 0; ir < NR_; ++ir)
    for (it = 0; it < NT_; ++it) {
      double r = 0.005 + (RL - 0.005) * ir / (NR_ - 1.0), th = 89 * pow(it / (NT_ - 1.0), 0.6);
      double mu = cos(th * 3.14159265358979323846 / 180), s = sqrt(1 - mu * mu), al = r * r, v[3];
      double tau = al * s / (mu + al * s), e, xi = 1;
      v[0] = s, v[1] = 0, v[2] = mu;
      e = (double)arref_ggx_albedo(nrm, v, al);
      for (i = 0; i <= AI; ++i) {
        for (j = 0; j <= AJ; ++j)
          A[row * n + i * (AJ + 1) + j] = al * xi * pow(2 * tau - 1, j) / e;
        xi *= xlow(r);
      }
      b[row] = (e - e0(tau)) / e;
      E[row] = e, R[row] = r, M[row] = mu;
      row++;
    }
  lsq(A, b, m, n, x);
  for (i = 0; i <= AI; ++i)
    for (j = 0; j <= AJ; ++j)
      CAL[i][j] = (double)(float)x[i * (AJ + 1) + j];
  {
    double rb[3] = {0.0, 0.075, 0.15}, mxs[3] = {0, 0, 0};
    int bb;
    for (row = 0; row < m; ++row) {
      double d = fabs(model_alb_low(R[row], M[row]) - E[row]) / E[row];
      if (d > emax) emax = d;
      for (bb = 2; bb >= 0; --bb)
        if (R[row] >= rb[bb]) {
          if (d > mxs[bb]) mxs[bb] = d;
          break;
        }
    }
    fprintf(stderr, "low albedo fit: max rel err %.2e; by r from 0, 0.075, 0.15: %.2e %.2e %.2e\n",
            emax, mxs[0], mxs[1], mxs[2]);
  }
  free(A), free(b), free(E), free(R), free(M);
}
/* a / alpha, g, d, P of the low set: weighted least squares (weights 1 / (residual + 0.02)) with
   the alpha -> 0 limit as 21 heavy points at r = 0, reweighted 4 times (points further than 3
   median deviations count less: a stalled optimum does not pull the surface); k = 1 */
static void fit_params_low(const char *fn) {
  static const double LIM[4] = {2, 0, 0, 1};
  FILE *f = fopen(fn, "r");
  static double pr[2000], pm[2000], pv[2000][5], pw[2000], res[2000], tmp[2000];
  int np = 0, n = (DI + 1) * (DJL + 1), k, i, j, row, it;
  double th, alb, fx;
  while (f && np < 1900 &&
         fscanf(f, "%lf %lf %lf %lf %lf %lf %lf %lf %lf %lf", &pr[np], &th, &pm[np], &alb,
                &pv[np][0], &pv[np][1], &pv[np][2], &pv[np][3], &pv[np][4], &fx) == 10) {
    if (pr[np] > RL + 1e-9) continue;
    pw[np] = 1 / (fx + 0.02);
    if (th < 1e-9) pw[np] *= 0.01; /* the axis is free at normal view */
    pv[np][0] = exp(pv[np][0]);
    np++;
  }
  if (f) fclose(f);
  for (i = 0; i < 21; ++i) {
    pr[np] = 0, pm[np] = 0.02 + 0.98 * i / 20.0, pw[np] = 50;
    for (k = 0; k < 4; ++k)
      pv[np][k] = LIM[k];
    np++;
  }
  for (k = 0; k < 4; ++k) {
    double *A = malloc(sizeof(double) * (size_t)(np * n)), *b = malloc(sizeof(double) * (size_t)np),
           x[(DI + 1) * (DJL + 1)], p[5], *rw = malloc(sizeof(double) * (size_t)np), med = 0, sc;
    for (row = 0; row < np; ++row)
      rw[row] = 1;
    for (it = 0; it < 4; ++it) {
      for (row = 0; row < np; ++row) {
        for (i = 0; i <= DI; ++i)
          for (j = 0; j <= DJL; ++j)
            A[row * n + i * (DJL + 1) + j] =
                rw[row] * pw[row] * pow(xlow(pr[row]), i) * pow(2 * pm[row] - 1, j);
        b[row] = rw[row] * pw[row] * pv[row][k];
      }
      lsq(A, b, np, n, x);
      for (i = 0; i <= DI; ++i)
        for (j = 0; j <= DJL; ++j)
          CL[k][i][j] = (double)(float)x[i * (DJL + 1) + j];
      for (row = 0; row < np; ++row) {
        model_p_low(pr[row], pm[row], p);
        res[row] = fabs(p[k] - pv[row][k]);
      }
      memcpy(tmp, res, sizeof(double) * (size_t)np);
      med = pct(tmp, np, 0.5);
      sc = 3 * med + 1e-6;
      for (row = 0; row < np; ++row)
        rw[row] = res[row] < sc ? 1 : sc / res[row];
    }
    fprintf(stderr, "low param %d: %d points, median abs deviation %.3g\n", k, np, med);
    free(A), free(b), free(rw);
  }
  memset(CL[4], 0, sizeof CL[4]);
  CL[4][0][0] = 1;
}
/* the piecewise model: the low set for r <= RS, the high set for r >= RB, between them the
   parameters and the albedo interpolated linearly in r (continuous in roughness) */
static void model_fit(double r, double mu, double *p, double *alb) {
  double q[5], w = (r - RS) / (RB - RS), e = 0;
  int k;
  if (w < 1) model_p_low(r, mu, p), *alb = model_alb_low(r, mu);
  if (w > 0) {
    model_p(r, mu, q), e = model_alb(r, mu);
    if (w >= 1) w = 1, *alb = 0;
    for (k = 0; k < 5; ++k)
      p[k] = w >= 1 ? q[k] : p[k] + w * (q[k] - p[k]);
    *alb = w >= 1 ? e : *alb + w * (e - *alb);
  }
}
/* the model (model_fit) on the bench sampler (seed 2017, 250 quads per roughness
   0.05 ... 1), against shl_polygon_ggx and the long double albedo; CHECK_R="r0,r1,..." checks
   other roughness values, each on the quads of the nearest bench roughness */
static void check(void) {
  static double RO[7] = {0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1.0}, cq[7][250][4][3], cv[7][250][3];
  double rl[32];
  int nrl = 0, ir, i, k, nq = getenv("CHECK_TEST") ? 24 : 250;
  const char *e = getenv("CHECK_R");
  ggxc_rng rg;
  rg.s = 2017u;
  for (ir = 0; ir < 7; ++ir)
    for (i = 0; i < 250; ++i) {
      ggxc_case cs;
      ggxc_make(&rg, &cs, -1);
      for (k = 0; k < 12; ++k)
        cq[ir][i][k / 3][k % 3] = (float)cs.q[k / 3][k % 3];
      for (k = 0; k < 3; ++k)
        cv[ir][i][k] = (float)cs.view[k];
    }
  if (e)
    while (*e && nrl < 32) {
      char *e2;
      rl[nrl++] = strtod(e, &e2);
      e = *e2 == ',' ? e2 + 1 : e2;
    }
  else
    for (nrl = 0; nrl < 7; ++nrl)
      rl[nrl] = RO[nrl];
  for (k = 0; k < nrl; ++k) {
    static double rel[250];
    double emax = 0, al = (double)(float)(rl[k] * rl[k]), r = sqrt(al);
    int nv = 0, b = 0;
    for (ir = 1; ir < 7; ++ir)
      if (fabs(RO[ir] - rl[k]) < fabs(RO[b] - rl[k])) b = ir;
    if (nq == 24) { /* CHECK_TEST: tests/test_ggx.c's 24 quads (seed 1000 + roughness index) */
      rg.s = 1000u + (unsigned)b;
      for (i = 0; i < 24; ++i) {
        ggxc_case cs;
        int c;
        ggxc_make(&rg, &cs, -1);
        for (c = 0; c < 12; ++c)
          cq[b][i][c / 3][c % 3] = (float)cs.q[c / 3][c % 3];
        for (c = 0; c < 3; ++c)
          cv[b][i][c] = (float)cs.view[c];
      }
    }
    for (i = 0; i < nq; ++i) {
      float fq[4][3], fv[3], fn[3] = {0, 0, 1};
      double nrm[3] = {0, 0, 1}, alb, gt, p[5], m[5], mu, s, got, ea = 0;
      int c;
      for (c = 0; c < 12; ++c)
        fq[c / 3][c % 3] = (float)cq[b][i][c / 3][c % 3];
      for (c = 0; c < 3; ++c)
        fv[c] = (float)cv[b][i][c];
      alb = (double)arref_ggx_albedo(nrm, cv[b][i], al);
      gt = shl_polygon_ggx((const float(*)[3])fq, 4, fn, fv, (float)al);
      mu = cv[b][i][2] / sqrt(cv[b][i][0] * cv[b][i][0] + cv[b][i][2] * cv[b][i][2]);
      s = sqrt(1 - mu * mu);
      model_fit(r, mu, p, &ea);
      gmu = mu;
      p2m(p, al, m);
      got = m[4] * ea * ltc((const double(*)[3])cq[b][i], m, mu, s);
      if (fabs(got - gt) / alb > emax) emax = fabs(got - gt) / alb;
      if (gt >= 0.05 * alb) rel[nv++] = fabs(got - gt) / gt;
    }
    printf("r %.3f: vis %d rel median %.2e p95 %.2e max %.2e; max err/albedo %.3g\n", rl[k], nv,
           pct(rel, nv, 0.5), pct(rel, nv, 0.95), pct(rel, nv, 1), emax);
    fflush(stdout);
  }
}

/* ---- Levenberg-Marquardt on the polynomial coefficients against every training quad at once
   (the per-point optima only start it): residual psi((k E F - gt) / (gt + 0.02 E)), psi a soft
   clip at 0.3 (a few quads where the 4-parameter lobe cannot follow must not steer the rest) */
#define NPT (NRG * NTH)
#define NC (5 * (DI + 1) * (DJ + 1))
static double (*TQ)[4][3], *TG, TA[NPT], TM[NPT], TS[NPT], TL[NPT], TE[NPT], TW[NPT];

static void load_train(void) {
  int ir, it, i;
  TQ = malloc(sizeof(*TQ) * (size_t)(NPT * NQ));
  TG = malloc(sizeof(double) * (size_t)(NPT * NQ));
  for (ir = 0; ir < NRG; ++ir)
    for (it = 0; it < NTH; ++it) {
      int pi = ir * NTH + it;
      setup(ir, TH[it], 0x5EEDull * 1000003ull + (unsigned long long)(ir * 97 + it * 7 + 1));
      TA[pi] = P.alpha, TM[pi] = P.mu, TS[pi] = P.s, TL[pi] = P.alb;
      TE[pi] = model_alb(RG[ir], P.mu);
      /* the targets scale with roughness (LTC's median relative error grows from 7e-5 at
         r = 0.05 to 1e-2 and more): weigh each point by the inverse of such a scale */
      TW[pi] = sqrt(0.01 / (1e-4 + 0.03 * P.alpha));
      for (i = 0; i < NQ; ++i) {
        memcpy(TQ[pi * NQ + i], P.q[i], sizeof P.q[i]);
        TG[pi * NQ + i] = P.gt[i];
      }
    }
}
static double psi(double e) {
  return e / sqrt(1 + (e / 0.3) * (e / 0.3));
}
/* residuals of point pi with parameters p into out[NQ] */
static void point_res(int pi, const double *p, double *out) {
  double m[5];
  int i;
  gmu = TM[pi];
  p2m(p, TA[pi], m);
  for (i = 0; i < NQ; ++i) {
    double f = m[4] * TE[pi] * ltc((const double(*)[3])TQ[pi * NQ + i], m, TM[pi], TS[pi]);
    double g = TG[pi * NQ + i];
    out[i] = TW[pi] * psi((f - g) / (g + 0.02 * TL[pi]));
  }
}
static double total(const double *co, double *res) {
  int pi, k, i;
  double sum = 0;
  for (pi = 0; pi < NPT; ++pi) {
    double p[5];
    memcpy(CO, co, sizeof CO);
    model_p(sqrt(TA[pi]), TM[pi], p);
    point_res(pi, p, res + pi * NQ);
    for (i = 0; i < NQ; ++i)
      sum += res[pi * NQ + i] * res[pi * NQ + i];
  }
  (void)k;
  return sum;
}
static void lm(int iters) {
  static double co[NC], trial[NC], JtJ[NC][NC], Jtr[NC], A[NC][NC], dl[NC];
  double *res = malloc(sizeof(double) * NPT * NQ), *r2 = malloc(sizeof(double) * NPT * NQ);
  double lam = 1e-3, cost;
  int itn, pi, k, i, j, q, kk, n1 = (DI + 1) * (DJ + 1);
  memcpy(co, CO, sizeof co);
  cost = total(co, res);
  fprintf(stderr, "lm start cost %.6g\n", cost);
  for (itn = 0; itn < iters; ++itn) {
    memset(JtJ, 0, sizeof JtJ);
    memset(Jtr, 0, sizeof Jtr);
    for (pi = 0; pi < NPT; ++pi) {
      double p[5], dp[5][NQ], basis[(DI + 1) * (DJ + 1)], rr = sqrt(TA[pi]), mu = TM[pi];
      memcpy(CO, co, sizeof CO);
      model_p(rr, mu, p);
      for (k = 0; k < 5; ++k) {
        double pp[5], h = 1e-5;
        memcpy(pp, p, sizeof pp);
        pp[k] += h;
        point_res(pi, pp, dp[k]);
        for (q = 0; q < NQ; ++q)
          dp[k][q] = (dp[k][q] - res[pi * NQ + q]) / h;
      }
      for (i = 0; i <= DI; ++i)
        for (j = 0; j <= DJ; ++j)
          basis[i * (DJ + 1) + j] = pow(2 * rr - 1, i) * pow(2 * mu - 1, j);
      /* J row q: column (k, b) = dp[k][q] basis[b]; JtJ += outer, per point by the 5x5 block */
      {
        double G[5][5], g[5];
        memset(G, 0, sizeof G);
        memset(g, 0, sizeof g);
        for (q = 0; q < NQ; ++q)
          for (k = 0; k < 5; ++k) {
            g[k] += dp[k][q] * res[pi * NQ + q];
            for (kk = 0; kk < 5; ++kk)
              G[k][kk] += dp[k][q] * dp[kk][q];
          }
        for (k = 0; k < 5; ++k)
          for (i = 0; i < n1; ++i) {
            Jtr[k * n1 + i] += g[k] * basis[i];
            for (kk = 0; kk < 5; ++kk)
              for (j = 0; j < n1; ++j)
                JtJ[k * n1 + i][kk * n1 + j] += G[k][kk] * basis[i] * basis[j];
          }
      }
    }
    for (;;) {
      double c2;
      /* solve (JtJ + lam diag) dl = -Jtr by Cholesky */
      for (i = 0; i < NC; ++i) {
        for (j = 0; j < NC; ++j)
          A[i][j] = JtJ[i][j];
        A[i][i] += lam * (JtJ[i][i] + 1e-12);
      }
      for (j = 0; j < NC; ++j) {
        double d = A[j][j];
        for (k = 0; k < j; ++k)
          d -= A[j][k] * A[j][k];
        d = sqrt(d > 1e-300 ? d : 1e-300);
        A[j][j] = d;
        for (i = j + 1; i < NC; ++i) {
          double t = A[i][j];
          for (k = 0; k < j; ++k)
            t -= A[i][k] * A[j][k];
          A[i][j] = t / d;
        }
      }
      for (i = 0; i < NC; ++i) {
        double t = -Jtr[i];
        for (k = 0; k < i; ++k)
          t -= A[i][k] * dl[k];
        dl[i] = t / A[i][i];
      }
      for (i = NC - 1; i >= 0; --i) {
        double t = dl[i];
        for (k = i + 1; k < NC; ++k)
          t -= A[k][i] * dl[k];
        dl[i] = t / A[i][i];
      }
      for (i = 0; i < NC; ++i)
        trial[i] = co[i] + dl[i];
      c2 = total(trial, r2);
      if (c2 < cost) {
        memcpy(co, trial, sizeof co);
        memcpy(res, r2, sizeof(double) * NPT * NQ);
        cost = c2;
        lam = lam / 3 > 1e-9 ? lam / 3 : 1e-9;
        break;
      }
      lam *= 4;
      if (lam > 1e8) break;
    }
    fprintf(stderr, "lm %d cost %.6g lam %.2g\n", itn, cost, lam);
    if (lam > 1e8) break;
  }
  memcpy(CO, co, sizeof CO);
  free(res), free(r2);
}

/* ---- the kernel text: shli_ggx_fast_fit, Horner loops over the packed table SHLI_GGX_FAST_FIT */
/* the shortest decimal that rounds to the same float as c (at most 9 digits), spelt without
   an exponent where that is shorter: the float GLSL reads, and within 3e-8 of it in C */
static void lit(char *o, double c) {
  char e[32], dg[16];
  int ex, nd = 0, k;
  const char *p = e;
  for (k = 0; k < 9; ++k) {
    sprintf(e, "%.*e", k, c);
    if ((float)strtod(e, NULL) == (float)c) break;
  }
  if (*p == '-') *o++ = *p++;
  for (; *p != 'e'; ++p)
    if (*p != '.') dg[nd++] = *p;
  ex = atoi(p + 1);
  while (nd > 1 && dg[nd - 1] == '0')
    --nd;
  if (ex < -4 || ex > nd + 2) { /* keep the exponent: d.ddd e+XX */
    *o++ = dg[0], *o++ = '.';
    if (nd == 1) *o++ = '0';
    for (k = 1; k < nd; ++k)
      *o++ = dg[k];
    sprintf(o, "e%+03d", ex);
    return;
  }
  if (ex < 0) {
    *o++ = '0', *o++ = '.';
    for (k = 0; k < -ex - 1; ++k)
      *o++ = '0';
    for (k = 0; k < nd; ++k)
      *o++ = dg[k];
  } else {
    for (k = 0; k <= ex; ++k)
      *o++ = k < nd ? dg[k] : '0';
    *o++ = '.';
    if (nd <= ex + 1) *o++ = '0';
    for (k = ex + 1; k < nd; ++k)
      *o++ = dg[k];
  }
  *o = 0;
}
/* the coefficients in the order the kernel reads them: per out_fit[k], k < 5, the DI + 1 rows
   of r-power DI down to 0, each DJ + 1 coefficients of mu-power DJ down to 0; then the albedo's
   AI + 1 rows of AJ + 1 */
#define NSET (5 * (DI + 1) * (DJ + 1) + (AI + 1) * (AJ + 1))
#define NTAB (NSET + 4 * (DI + 1) * (DJL + 1) + (AI + 1) * (AJ + 1))
static char *emit_text(void) {
  static char buf[65536];
  double tab[NTAB];
  char l1[64];
  int k, i, j, n = 0, col, set;
  char *o = buf;
  for (set = 0; set < 2; ++set) {
    for (k = 0; k < 5 - set; ++k) /* the low set: no k (it is 1) */
      for (i = DI; i >= 0; --i)
        for (j = set ? DJL : DJ; j >= 0; --j)
          tab[n++] = set ? CL[k][i][j] : CO[k][i][j];
    for (i = AI; i >= 0; --i)
      for (j = AJ; j >= 0; --j)
        tab[n++] = set ? CAL[i][j] : CA[i][j];
  }
  o += sprintf(o, "/* @fit ggx_fast begin: written by tools/fit_ggx_fast.c (emit), checked by its "
                  "--check */\n");
  o += sprintf(o,
               "/* The fit of shl_polygon_ggx_fast (docs/area-lights.md): out_fit[0..4] a / alpha, "
               "g, d, P,\n"
               "   k (low set: 1), degree %d in x and %d (low set: %d) in y = 2 mu - 1; out_fit[5] "
               "the albedo,\n"
               "   degree %d in x and %d in 2 tau - 1. Per set, per output: rows of x-powers down "
               "to 0, each "
               "of\n   y-powers down to 0. */\n",
               DI, DJ, DJL, AI, AJ);
  o += sprintf(o, "/* clang-format off */\nstatic const shli_real SHLI_GGX_FAST_FIT[%d] = {\n",
               NTAB);
  col = 0;
  for (i = 0; i < NTAB; ++i) {
    int w;
    lit(l1, tab[i]);
    w = (int)strlen(l1) + (i + 1 < NTAB ? 1 : 0);
    if (col > 0 && col + w > 100) {
      o += sprintf(o, "\n");
      col = 0;
    }
    o += sprintf(o, "%s%s%s", col == 0 ? "  " : "", l1, i + 1 < NTAB ? "," : "\n");
    col += (col == 0 ? 2 : 0) + w;
  }
  o += sprintf(o, "};\n/* clang-format on */\n");
  o += sprintf(o, "/* sum_ij SHLI_GGX_FAST_FIT[at + cols i + j] x^(rows - 1 - i) y^(cols - 1 - j) "
                  "by Horner */\n");
  o += sprintf(
      o,
      "SHLIGHT_ALWAYS_INLINE\nSHLIGHT_INLINE shli_real shli_ggx_fast_poly(int at, int rows, "
      "int cols, shli_real x, shli_real y) {\n  shli_real u;\n  shli_real t = 0.0;\n"
      "  int i;\n  int a;\n  SHLIGHT_UNROLL(%d)\n  for (i = 0; i < rows; ++i) {\n"
      "    a = at + cols * i;\n    u = SHLI_GGX_FAST_FIT[a];\n",
      (DI > AI ? DI : AI) + 1);
  for (j = 1; j <= (DJL > AJ ? DJL : AJ); ++j) {
    if (j > (DJ < AJ ? DJ : AJ))
      o += sprintf(o, "    if (cols > %d) {\n      u = SHLI_GGX_FAST_FIT[a + %d] + y * u;\n    }\n",
                   j, j);
    else
      o += sprintf(o, "    u = SHLI_GGX_FAST_FIT[a + %d] + y * u;\n", j);
  }
  o += sprintf(o, "    t = u + x * t;\n  }\n  return t;\n}\n");
  o += sprintf(o, "/* one set: the high one (at 0) or the low one (at %d; k = 1) */\n", NSET);
  o += sprintf(o,
               "SHLIGHT_ALWAYS_INLINE\nSHLIGHT_INLINE void shli_ggx_fast_set(int at, int cols, "
               "shli_real x, shli_real r, shli_real mu,\n"
               "                                      shli_real tau, shli_real *out_fit) {\n"
               "  shli_real y = 2.0 * mu - 1.0;\n  shli_real z = 2.0 * tau - 1.0;\n"
               "  shli_real t = 1.0 - tau;\n  int b = at + %d * cols;\n"
               "  out_fit[0] = shli_ggx_fast_poly(at, %d, cols, x, y);\n",
               4 * (DI + 1), DI + 1);
  for (k = 1; k < 4; ++k)
    o += sprintf(o, "  out_fit[%d] = shli_ggx_fast_poly(at + %d * cols, %d, cols, x, y);\n", k,
                 k * (DI + 1), DI + 1);
  o += sprintf(o,
               "  out_fit[4] = 1.0;\n  if (at == 0) {\n"
               "    out_fit[4] = shli_ggx_fast_poly(b, %d, cols, x, y);\n"
               "    b = b + %d * cols;\n  }\n"
               "  out_fit[5] = t / SHLIGHT_SQRTR(t * t + tau * tau) + r * r * "
               "shli_ggx_fast_poly(b, %d, %d, x, z);\n}\n",
               DI + 1, DI + 1, AI + 1, AJ + 1);
  o += sprintf(
      o,
      "/* the low set for r <= %g, the high set for r >= %g, between them their outputs "
      "interpolated\n   linearly in r (continuous in roughness) */\n"
      "SHLIGHT_INLINE void shli_ggx_fast_fit(shli_real r, shli_real mu, shli_real tau,\n"
      "                                      shli_real *out_fit) {\n"
      "  shli_real hi[6];\n  shli_real w = (r - %g) / (%g - %g);\n  int i;\n"
      "  if (w < 1.0) {\n    shli_ggx_fast_set(%d, %d, r * (2.0 / %g) - 1.0, r, mu, tau, "
      "out_fit);\n  }\n  if (w > 0.0) {\n    shli_ggx_fast_set(0, %d, 2.0 * r - 1.0, r, mu, "
      "tau, hi);\n    for (i = 0; i < 6; ++i) {\n      if (w < 1.0) {\n"
      "        hi[i] = out_fit[i] + w * (hi[i] - out_fit[i]);\n      }\n"
      "      out_fit[i] = hi[i];\n    }\n  }\n}\n",
      RS, RB, RS, RB, RS, NSET, DJL + 1, RL, DJ + 1);
  o += sprintf(o, "/* @fit ggx_fast end */\n");
  return buf;
}
static char *slurp(const char *fn, long *n) {
  FILE *f = fopen(fn, "rb");
  char *b;
  if (!f) return NULL;
  fseek(f, 0, SEEK_END);
  *n = ftell(f);
  fseek(f, 0, SEEK_SET);
  b = malloc((size_t)*n + 1);
  if (fread(b, 1, (size_t)*n, f) != (size_t)*n) *n = 0;
  b[*n] = 0;
  fclose(f);
  return b;
}
/* write (w = 1) or compare (w = 0) the region of shlight.h; returns 0 when fresh / written */
static int region(const char *hdr, int w) {
  long n;
  char *h = slurp(hdr, &n), *a, *b, *t = emit_text();
  const char *endm = "/* @fit ggx_fast end */\n";
  if (!h) return 2;
  a = strstr(h, "/* @fit ggx_fast begin");
  b = a ? strstr(a, endm) : NULL;
  if (!a || !b) return 2;
  b += strlen(endm);
  if (!w) return (long)strlen(t) == b - a && memcmp(a, t, strlen(t)) == 0 ? 0 : 1;
  {
    FILE *f = fopen(hdr, "wb");
    fwrite(h, 1, (size_t)(a - h), f);
    fputs(t, f);
    fputs(b, f);
    fclose(f);
  }
  return 0;
}

int main(int argc, char **argv) {
  if (getenv("TRY_RL")) RL = atof(getenv("TRY_RL"));
  if (getenv("TRY_RS")) RS = atof(getenv("TRY_RS"));
  if (argc >= 2 && strcmp(argv[1], "points") == 0) {
    int ir, it, lo = 0, hi = NRG, a = 2, nth = NTH;
    const double *th = TH;
    static double prev[NTHL][5];
    if (argc >= 3 && strcmp(argv[2], "low") == 0)
      RGP = RGL, hi = NRGL, fixk = 1, a = 3, th = THL, nth = NTHL;
    if (argc >= a + 2) lo = atoi(argv[a]), hi = atoi(argv[a + 1]);
    for (ir = lo; ir < hi; ++ir) {
      for (it = 0; it < nth; ++it) {
        double x[5], y[5], fx, fy;
        setup(ir, th[it], 0x5EEDull * 1000003ull + (unsigned long long)(ir * 97 + it * 7 + 1));
        prior[0] = log(2.0), prior[1] = 0, prior[2] = 0, prior[3] = 1, prior[4] = 0;
        if (ir > lo) {
          memcpy(prior, prev[it], sizeof prior);
        }
        memcpy(x, prior, sizeof x);
        fx = nm(x, 5, 0.2, 400);
        fx = nm(x, 5, 0.03, 300);
        y[0] = log(2.0), y[1] = 0, y[2] = 0, y[3] = 1, y[4] = 0;
        fy = nm(y, 5, 0.2, 400);
        fy = nm(y, 5, 0.03, 300);
        if (fy < fx) memcpy(x, y, sizeof x), fx = fy;
        if (it > 0) {
          memcpy(y, prev[it - 1], sizeof y);
          fy = nm(y, 5, 0.2, 400);
          fy = nm(y, 5, 0.03, 300);
          if (fy < fx) memcpy(x, y, sizeof x), fx = fy;
        }
        memcpy(prev[it], x, sizeof x);
        printf("%g %g %.9g %.9g %.9g %.9g %.9g %.9g %.9g %.4g\n", RGP[ir], th[it], P.mu, P.alb,
               x[0], x[1], x[2], x[3], x[4], sqrt(fx));
        fflush(stdout);
      }
    }
    return 0;
  }
  if (argc >= 4 && strcmp(argv[1], "smooth") == 0) {
    fit_albedo();
    fit_params(argv[2]);
    save(argv[3]);
    return 0;
  }
  if (argc >= 5 && strcmp(argv[1], "smoothlow") == 0) {
    load(argv[3]);
    if (!getenv("KEEP_ALB")) fit_albedo_low(); /* KEEP_ALB: the low albedo of COEF_IN kept */
    fit_params_low(argv[2]);
    save(argv[4]);
    return 0;
  }
  if (argc >= 3 && strcmp(argv[1], "check") == 0) {
    load(argv[2]);
    check();
    return 0;
  }
  if (argc >= 5 && strcmp(argv[1], "lm") == 0) {
    load(argv[2]);
    if (argc >= 6) fit_albedo();
    load_train();
    lm(atoi(argv[4]));
    save(argv[3]);
    check();
    return 0;
  }
  if (argc >= 4 && strcmp(argv[1], "emit") == 0) {
    load(argv[2]);
    return region(argv[3], 1);
  }
  if (argc >= 4 && strcmp(argv[1], "--check") == 0) {
    int rc;
    load(argv[2]);
    rc = region(argv[3], 0);
    printf("%s: shli_ggx_fast_fit %s %s\n", rc == 0 ? "ok" : "FAIL",
           rc == 0 ? "matches" : "differs from", argv[2]);
    return rc;
  }
  fprintf(stderr, "usage: fit_ggx_fast points [ir0 ir1] | smooth POINTS COEF | check COEF |\n"
                  "       emit COEF HEADER | --check COEF HEADER\n");
  return 2;
}
