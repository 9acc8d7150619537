/* test_brdf.c - shlight's >>brdf and >>hvl sections against independent references.
 *
 * Build: make build/tests/test_brdf (gcc -std=c99 -O2 ... -lquadmath -lm); run it, it ends with
 * "N passed, N failed" (a few seconds).
 *
 * References (none shares code with the header):
 *  - Lambda_l(e) = (e+1) int_0^1 x^e P_l(x) dx: composite Gauss-Legendre quadrature in theta,
 *    in binary128 (nodes refined by Newton in binary128), so the cosine-power kernels can be held
 *    to one float rounding (the kernels run the recurrence in double).
 *  - Lambert: Ramamoorthi-Hanrahan's factorial form (docs/derivations.md sec. 5) in long double.
 *  - GGX / Beckmann: D(h)(n.h) integrated in theta (long double), panels graded geometrically
 *    around the lobe width alpha and around the grazing end 1/alpha.
 *  - Convolutions and irradiance: product quadrature on the sphere (Gauss-Legendre in z or theta,
 *    uniform in phi) with an own long double real SH (associated Legendre recurrence).
 *  - Horizon fraction H: a ring-by-ring quadrature over the cap (the exact fraction of each
 *    ring above the horizon, acos(-cot(beta) cot(psi)) / pi), panels graded toward the kink.
 * Error model: float outputs carry 0.5 ulp; inputs are floats converted exactly. */
/* n out of range: counted instead of aborting (the release behaviour is what is tested) */
#define SHLIGHT_IMPLEMENTATION
#include "../shlight.h"
#include "ref/published.h" /* the published forms, for comparison */
#include "tl.h"
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

__extension__ typedef __float128 tq;
extern tq expq(tq);
extern tq logq(tq);
extern tq cosq(tq);
extern tq sinq(tq);
extern tq fabsq(tq);

typedef long double ld;
#define PI_L 3.141592653589793238462643383279502884L
#define NGL 20

static ld gl_x[NGL], gl_w[NGL];   /* Gauss-Legendre on [-1, 1], long double */
static tq glq_x[NGL], glq_w[NGL]; /* the same refined in binary128 */

static void gl_init(void) {
  int i, k, it;
  for (i = 0; i < NGL; ++i) {
    tq x = (tq)cosl(PI_L * ((ld)i + 0.75L) / ((ld)NGL + 0.5L)), p0, p1, dp;
    for (it = 0; it < 12; ++it) {
      p0 = 1;
      p1 = x;
      for (k = 1; k < NGL; ++k) {
        tq p2 = ((2 * k + 1) * x * p1 - k * p0) / (k + 1);
        p0 = p1;
        p1 = p2;
      }
      dp = NGL * (x * p1 - p0) / (x * x - 1);
      x -= p1 / dp;
    }
    p0 = 1;
    p1 = x;
    for (k = 1; k < NGL; ++k) {
      tq p2 = ((2 * k + 1) * x * p1 - k * p0) / (k + 1);
      p0 = p1;
      p1 = p2;
    }
    dp = NGL * (x * p1 - p0) / (x * x - 1);
    glq_x[i] = x;
    glq_w[i] = 2 / ((1 - x * x) * dp * dp);
    gl_x[i] = (ld)glq_x[i];
    gl_w[i] = (ld)glq_w[i];
  }
}

static ld kl(int l) {
  return sqrtl((2.0L * l + 1.0L) / (4.0L * PI_L));
}

/* P_l(x) for l < n into p (long double) */
static void leg(int n, ld x, ld *p) {
  int l;
  p[0] = 1.0L;
  if (n > 1) p[1] = x;
  for (l = 1; l + 1 < n; ++l)
    p[l + 1] = ((2.0L * l + 1.0L) * x * p[l] - l * p[l - 1]) / (l + 1.0L);
}

/* own real SH in long double (CS phase), index l(l+1)+m */
static void ysh_ld(int n, ld x, ld y, ld z, ld *out) {
  ld pmm = 1.0L, phi = atan2l(y, x), st = sqrtl(fmaxl(0.0L, 1.0L - z * z));
  int l, m;
  for (m = 0; m < n; ++m) {
    ld pl1 = pmm, pl2 = 0.0L, nrm;
    if (m > 0) pmm = pmm * (-(2.0L * m - 1.0L)) * st, pl1 = pmm;
    for (l = m; l < n; ++l) {
      ld f = 1.0L;
      int k;
      if (l > m) {
        ld pn = ((2.0L * l - 1.0L) * z * pl1 - (l + m - 1.0L) * pl2) / (ld)(l - m);
        pl2 = pl1;
        pl1 = pn;
      }
      for (k = l - m + 1; k <= l + m; ++k)
        f /= (ld)k;
      nrm = sqrtl((2.0L * l + 1.0L) / (4.0L * PI_L) * f);
      if (m == 0) {
        out[l * (l + 1)] = nrm * pl1;
      } else {
        out[l * (l + 1) + m] = sqrtl(2.0L) * nrm * pl1 * cosl(m * phi);
        out[l * (l + 1) - m] = sqrtl(2.0L) * nrm * pl1 * sinl(m * phi);
      }
    }
  }
}

static unsigned long long rng = 88172645463325252ULL;
static double urand(void) {
  rng ^= rng << 13;
  rng ^= rng >> 7;
  rng ^= rng << 17;
  return (double)(rng >> 11) * (1.0 / 9007199254740992.0);
}
static void rand_dir(float *d) {
  double z = 2 * urand() - 1, p = 2 * M_PI * urand(), s = sqrt(1 - z * z);
  d[0] = (float)(s * cos(p));
  d[1] = (float)(s * sin(p));
  d[2] = (float)z;
}

static double ulp_of(double v) {
  int e;
  if (v == 0.0) return ldexp(1.0, -149);
  frexp(v, &e);
  return ldexp(1.0, e - 24 > -149 ? e - 24 : -149);
}

/* ---- cosine powers ------------------------------------------------------------------------- */

/* Lambda_l(e), l < n, by quadrature in theta (binary128); panels of width <= min(0.02, 1/sqrt(e))
 * near 0, where the lobe and P_l's oscillation live */
static void lambda_ref(int n, double e, tq *out) {
  int l, i, p, ne = 0;
  tq acc[64], ed[400];
  tq top = (tq)(PI_L / 2), wd;
  for (l = 0; l < n; ++l)
    acc[l] = 0;
  if (e > 400) top = (tq)(12.0 / sqrt(e)); /* cos^e < e^-72 beyond 12 / sqrt(e) */
  wd = top / 160;
  for (p = 0; p <= 160; ++p)
    ed[ne++] = wd * p;
  if (e <= 400) /* x^e with non-integer e is singular at x = 0 (theta = pi/2): grade toward it */
    for (p = 1; p <= 60; ++p)
      ed[ne++] = top - wd * expq(-(tq)p * (tq)0.7);
  for (p = 0; p < ne; ++p) /* sort (insertion) */
    for (i = p; i > 0 && ed[i] < ed[i - 1]; --i) {
      tq tmp = ed[i];
      ed[i] = ed[i - 1];
      ed[i - 1] = tmp;
    }
  for (p = 0; p + 1 < ne; ++p) {
    tq a = ed[p], b = ed[p + 1];
    if (!(b > a)) continue;
    for (i = 0; i < NGL; ++i) {
      tq t = (a + b) / 2 + (b - a) / 2 * glq_x[i], x = cosq(t), pl0 = 1, pl1 = x, f;
      if (!(x > 0)) continue; /* beyond pi/2 by the rounding of pi */
      f = glq_w[i] * (b - a) / 2 * sinq(t) * (e == 0 ? (tq)1 : expq((tq)e * logq(x)));
      acc[0] += f;
      for (l = 1; l < n; ++l) {
        tq p2;
        acc[l] += f * pl1;
        p2 = ((2 * l + 1) * x * pl1 - l * pl0) / (l + 1);
        pl0 = pl1;
        pl1 = p2;
      }
    }
  }
  for (l = 0; l < n; ++l)
    out[l] = acc[l] * ((tq)e + 1);
}

static void test_cosine_power_exact(void) {
  static const double es[] = {0, 0.5, 1, 2, 2.5, 3, 7.25, 10, 32.5, 100, 1000, 1e4};
  int k, l, n = 64;
  double worst = 0, worst_c = 0;
  for (k = 0; k < (int)(sizeof es / sizeof es[0]); ++k) {
    tq ref[64];
    float ph[64], cp[64];
    lambda_ref(n, es[k], ref);
    shl_zh_phong(n, (float)es[k], ph);
    shl_zh_cosine_power(n, (float)es[k], cp);
    for (l = 0; l < n; ++l) {
      double r = (double)(ref[l] * (tq)kl(l));
      double rc = (double)(ref[l] * (tq)kl(l) * 2 * (tq)PI_L / ((tq)es[k] + 1));
      double tol = 0.5 * ulp_of(r) + 1e-13 * fabs(r) + 1e-18; /* quadrature noise on exact zeros */
      double tolc = 0.5 * ulp_of(rc) + 1e-13 * fabs(rc) + 1e-18;
      double err = fabs((double)ph[l] - r), errc = fabs((double)cp[l] - rc);
      if (fabs(r) > 1e-15 && err / ulp_of(r) > worst) worst = err / ulp_of(r);
      if (fabs(rc) > 1e-15 && errc / ulp_of(rc) > worst_c) worst_c = errc / ulp_of(rc);
      TL_CHECK(err <= tol, "phong e=%g l=%d: %.9g vs %.9g (err %.3g ulp)", es[k], l, (double)ph[l],
               r, err / ulp_of(r));
      TL_CHECK(errc <= tolc, "cospow e=%g l=%d: %.9g vs %.9g", es[k], l, (double)cp[l], rc);
    }
  }
  printf("  cosine powers, e in [0, 1e4], n = 64: max error %.3f ulp (phong), %.3f ulp (cos^e) "
         "(exact zeros: 0)\n",
         worst, worst_c);
}

static void test_lambert_closed_form(void) {
  float z[64];
  int l, k;
  shl_zh_lambert(64, z);
  for (l = 0; l < 64; ++l) {
    ld a;
    if (l == 0)
      a = PI_L;
    else if (l == 1)
      a = 2 * PI_L / 3;
    else if (l % 2)
      a = 0;
    else {
      /* 2 pi (-1)^(l/2-1) l! / ((l+2)(l-1) 2^l ((l/2)!)^2), as a product to stay in range */
      ld r = 1.0L;
      for (k = 1; k <= l / 2; ++k)
        r *= (ld)(l / 2 + k) / (4.0L * k); /* l!/(2^l ((l/2)!)^2) */
      a = 2 * PI_L * ((l / 2 - 1) % 2 ? -1 : 1) * r / ((l + 2.0L) * (l - 1.0L));
    }
    {
      double ref = (double)(kl(l) * a / PI_L);
      TL_CHECK(fabs((double)z[l] - ref) <= 0.5 * ulp_of(ref) + 1e-13 * fabs(ref) + 1e-30,
               "lambert l=%d: %.9g vs RH %.9g", l, (double)z[l], ref);
    }
  }
  TL_CHECK(fabs((double)z[2] - 0.1576958) < 1e-7 && fabs((double)z[4] + 0.0352618) < 1e-7,
           "docs/derivations.md table values");
}

static void test_cosine_power_hard(void) {
  float a[64], b[64];
  int l, ok = 1;
  /* 1e30 and +inf: the Dirac limit K_l (phong), 2 pi K_l / (e+1) (cos^e) */
  shl_zh_phong(64, 1e30f, a);
  for (l = 0; l < 64; ++l)
    ok &= a[l] == (float)kl(l);
  TL_CHECK(ok, "phong 1e30 = K_l");
  shl_zh_phong(64, INFINITY, b);
  TL_CHECK(memcmp(a, b, sizeof a) == 0, "phong inf = phong 1e30");
  shl_zh_cosine_power(8, 1e30f, a);
  TL_CHECK(fabs((double)a[3] - 2 * M_PI * (double)kl(3) * 1e-30) < 1e-36, "cos^1e30: %g",
           (double)a[3]);
  /* NaN and negative: exponent 0 */
  shl_zh_phong(16, 0.0f, a);
  shl_zh_phong(16, NAN, b);
  TL_CHECK(memcmp(a, b, 16 * sizeof(float)) == 0, "phong NaN = phong 0");
  shl_zh_phong(16, -3.0f, b);
  TL_CHECK(memcmp(a, b, 16 * sizeof(float)) == 0, "phong -3 = phong 0");
  shl_zh_blinn_phong(16, NAN, b);
  shl_zh_phong(16, 1.0f, a);
  TL_CHECK(memcmp(a, b, 16 * sizeof(float)) == 0, "blinn NaN = blinn 0 = phong 1");
  shl_zh_blinn_phong(16, 20.0f, b);
  shl_zh_phong(16, 21.0f, a);
  TL_CHECK(memcmp(a, b, 16 * sizeof(float)) == 0, "blinn e = phong e+1");
  /* e = 0: hemisphere; cos^0 ZH_0 = sqrt(pi) (2 pi Y_0) */
  shl_zh_cosine_power(4, 0.0f, a);
  TL_CHECK(fabs((double)a[0] - sqrt(M_PI)) < 1e-7 && a[2] == 0.0f, "cos^0: %g %g", (double)a[0],
           (double)a[2]);
  /* n = 1; n = 0 writes nothing */
  a[0] = a[1] = -7.0f;
  shl_zh_phong(1, 5.0f, a);
  TL_CHECK(a[0] == (float)kl(0) && a[1] == -7.0f, "n = 1");
  a[0] = -7.0f;
  shl_zh_phong(0, 5.0f, a);
  shl_zh_ggx(0, 0.5f, a);
  shl_zh_cosine_power(-2, 5.0f, a);
  TL_CHECK(a[0] == -7.0f, "n <= 0 writes nothing");
}

/* ---- microfacet lobes ------------------------------------------------------------------------ */

static ld ndf_cos(int kind, ld al, ld t) {
  ld c = cosl(t), c2 = c * c, s = sinl(t), tn2 = (s * s) / c2;
  if (kind == 0) {
    ld q = c2 * (al * al - 1.0L) + 1.0L;
    return al * al / (PI_L * q * q) * c;
  }
  if (c2 <= 0.0L) return 0.0L;
  return expl(-tn2 / (al * al)) / (PI_L * al * al * c2 * c2) * c;
}

static int cmp_ld(const void *a, const void *b) {
  ld x = *(const ld *)a, y = *(const ld *)b;
  return x < y ? -1 : x > y;
}

/* ZH_l of D(h)(n.h), l < n, by quadrature in theta (long double) */
static void ndf_ref(int kind, double al, int n, ld *out) {
  static ld e[1024];
  ld p[64];
  int ne = 0, i, j, l;
  double s;
  e[ne++] = 0.0L;
  e[ne++] = PI_L / 2;
  for (s = al * 1e-4; s < 1.5707; s *= 1.25)
    e[ne++] = (ld)s;
  for (s = 1e-4 / al; s < 1.5707; s *= 1.25)
    e[ne++] = PI_L / 2 - (ld)s;
  for (s = 0.01; s < 1.5707; s += 0.01)
    e[ne++] = (ld)s; /* P_l's oscillation, l < 64 */
  qsort(e, (size_t)ne, sizeof e[0], cmp_ld);
  for (l = 0; l < n; ++l)
    out[l] = 0.0L;
  for (j = 0; j + 1 < ne; ++j) {
    ld a = e[j], b = e[j + 1];
    if (!(b > a)) continue;
    for (i = 0; i < NGL; ++i) {
      ld t = (a + b) / 2 + (b - a) / 2 * gl_x[i];
      ld f = gl_w[i] * (b - a) / 2 * 2 * PI_L * ndf_cos(kind, al, t) * sinl(t);
      leg(n, cosl(t), p);
      for (l = 0; l < n; ++l)
        out[l] += f * p[l];
    }
  }
  for (l = 0; l < n; ++l)
    out[l] *= kl(l);
}

static void test_microfacet(void) {
  static const double als[] = {1e-4, 1e-3, 0.01, 0.05, 0.1, 0.3, 0.6, 1.0, 2.0, 10.0, 100.0};
  static const int ns[] = {1, 4, 8, 16, 32, 64};
  int kind, a, k, l;
  for (kind = 0; kind < 2; ++kind) {
    printf("  %s: max |error| / K_l by n (rows: alpha)\n", kind ? "Beckmann" : "GGX");
    for (a = 0; a < (int)(sizeof als / sizeof als[0]); ++a) {
      ld ref[64];
      ndf_ref(kind, als[a], 64, ref);
      printf("    alpha %-6g", als[a]);
      for (k = 0; k < 6; ++k) {
        float z[64];
        double worst = 0;
        int n = ns[k];
        if (kind)
          shl_zh_beckmann(n, (float)als[a], z);
        else
          shl_zh_ggx(n, (float)als[a], z);
        for (l = 0; l < n; ++l) {
          double err = fabs((double)z[l] - (double)ref[l]) / (double)kl(l);
          if (err > worst) worst = err;
          /* float rounding of a value <= K_l: 6e-8 K_l; the rule: ~1e-9 */
          TL_CHECK(err <= 1.5e-7, "%s alpha=%g n=%d l=%d: %.9g vs %.9g", kind ? "beckmann" : "ggx",
                   als[a], n, l, (double)z[l], (double)ref[l]);
        }
        printf(" n=%d %.1e", n, worst);
      }
      printf("\n");
    }
  }
  {
    float z[16], d[16];
    int ok = 1;
    shl_zh_ggx(16, 0.0f, z);
    shli_zh_delta(16, d);
    ok &= memcmp(z, d, sizeof z) == 0;
    shl_zh_ggx(16, NAN, z);
    ok &= memcmp(z, d, sizeof z) == 0;
    shl_zh_beckmann(16, -1.0f, z);
    ok &= memcmp(z, d, sizeof z) == 0;
    TL_CHECK(ok, "alpha 0 / NaN / negative: the Dirac lobe K_l");
    shl_zh_ggx(16, 1e-7f, z);
    for (l = 0; l < 16; ++l)
      ok &= fabsf(z[l] - d[l]) <= 1e-7f * d[l];
    shl_zh_ggx(16, INFINITY, z);
    for (l = 0; l < 16; ++l)
      ok &= isfinite(z[l]);
    TL_CHECK(ok, "alpha 1e-7 near Dirac; alpha inf finite");
  }
}

/* ---- convolution ----------------------------------------------------------------------------- */

#define QN 40 /* sphere quadrature: GL in z x 2 QN in phi, exact for degree < 2 QN - 1 */
static ld qz[QN], qwz[QN];
static void sphere_init(void) {
  int i, k, it;
  for (i = 0; i < QN; ++i) {
    ld x = cosl(PI_L * (i + 0.75L) / (QN + 0.5L)), p0, p1, dp = 1;
    for (it = 0; it < 10; ++it) {
      p0 = 1;
      p1 = x;
      for (k = 1; k < QN; ++k) {
        ld p2 = ((2 * k + 1) * x * p1 - k * p0) / (k + 1);
        p0 = p1;
        p1 = p2;
      }
      dp = QN * (x * p1 - p0) / (x * x - 1);
      x -= p1 / dp;
    }
    qz[i] = x;
    qwz[i] = 2 / ((1 - x * x) * dp * dp);
  }
}
/* integral over the sphere of f(w), f given by a callback with context */
typedef ld (*sph_fn)(const ld w[3], const void *ctx);
static ld sphere_int(sph_fn f, const void *ctx) {
  ld s = 0;
  int i, j;
  for (i = 0; i < QN; ++i)
    for (j = 0; j < 2 * QN; ++j) {
      ld ph = PI_L * j / QN, st = sqrtl(1 - qz[i] * qz[i]);
      ld w[3];
      w[0] = st * cosl(ph);
      w[1] = st * sinl(ph);
      w[2] = qz[i];
      s += qwz[i] * (PI_L / QN) * f(w, ctx);
    }
  return s;
}
typedef struct {
  int n;
  const float *a, *b, *za, *zb;
  ld u[3], v[3];
} conv_ctx;
static ld sh_at(int n, const float *c, const ld w[3]) {
  ld y[64 * 64], s = 0;
  int i;
  ysh_ld(n, w[0], w[1], w[2], y);
  for (i = 0; i < n * n; ++i)
    s += (ld)c[i] * y[i];
  return s;
}
static ld zh_at(int n, const float *z, const ld ax[3], const ld w[3]) {
  ld p[64], s = 0, c = ax[0] * w[0] + ax[1] * w[1] + ax[2] * w[2];
  int l;
  leg(n, c, p);
  for (l = 0; l < n; ++l)
    s += (ld)z[l] * kl(l) * p[l];
  return s;
}
static ld f_shsh(const ld w[3], const void *c) {
  const conv_ctx *x = (const conv_ctx *)c;
  return sh_at(x->n, x->a, w) * sh_at(x->n, x->b, w);
}
static ld f_shzh(const ld w[3], const void *c) {
  const conv_ctx *x = (const conv_ctx *)c;
  return sh_at(x->n, x->a, w) * zh_at(x->n, x->zb, x->v, w);
}
static ld f_zhzh(const ld w[3], const void *c) {
  const conv_ctx *x = (const conv_ctx *)c;
  return zh_at(x->n, x->za, x->u, w) * zh_at(x->n, x->zb, x->v, w);
}

static void test_convolution(void) {
  static const int ns[] = {1, 2, 3, 5, 8, 12, 15};
  int k, i;
  for (k = 0; k < (int)(sizeof ns / sizeof ns[0]); ++k) {
    int n = ns[k], rep;
    for (rep = 0; rep < 2; ++rep) {
      float a[256], b[256], za[16], zb[16], u[3], v[3], rb[256];
      conv_ctx c;
      ld ref, na = 0, nb = 0, nza = 0, nzb = 0;
      double got;
      for (i = 0; i < n * n; ++i)
        a[i] = (float)(2 * urand() - 1), b[i] = (float)(2 * urand() - 1);
      for (i = 0; i < n; ++i)
        za[i] = (float)(2 * urand() - 1), zb[i] = (float)(2 * urand() - 1);
      for (i = 0; i < n * n; ++i)
        na += (ld)a[i] * a[i], nb += (ld)b[i] * b[i];
      for (i = 0; i < n; ++i)
        nza += (ld)za[i] * za[i], nzb += (ld)zb[i] * zb[i];
      rand_dir(u);
      rand_dir(v);
      if (rep == 1) v[0] = u[0], v[1] = u[1], v[2] = u[2]; /* same axis */
      c.n = n;
      c.a = a;
      c.b = b;
      c.za = za;
      c.zb = zb;
      for (i = 0; i < 3; ++i)
        c.u[i] = u[i], c.v[i] = v[i];
      {
        ld nu = sqrtl(c.u[0] * c.u[0] + c.u[1] * c.u[1] + c.u[2] * c.u[2]);
        ld nv = sqrtl(c.v[0] * c.v[0] + c.v[1] * c.v[1] + c.v[2] * c.v[2]);
        for (i = 0; i < 3; ++i)
          c.u[i] /= nu, c.v[i] /= nv;
      }
      ref = sphere_int(f_shsh, &c);
      got = (double)shl_sh_dot(n, a, b);
      TL_CHECK(fabs(got - (double)ref) <= 2e-7 * (double)sqrtl(na * nb),
               "sh_dot n=%d: %.9g vs %.9g", n, got, (double)ref);
      ref = sphere_int(f_shzh, &c);
      got = (double)shl_sh_conv_zh(n, a, zb, v);
      /* Y(v) in float: a few ulp per band times the norms */
      TL_CHECK(fabs(got - (double)ref) <= 2e-6 * (double)sqrtl(na * nzb),
               "sh_conv_zh n=%d: %.9g vs %.9g", n, got, (double)ref);
      ref = sphere_int(f_zhzh, &c);
      got = (double)shl_zh_dot_zh(n, za, u, zb, v);
      TL_CHECK(fabs(got - (double)ref) <= 4e-7 * (double)sqrtl(nza * nzb),
               "zh_dot_zh n=%d: %.9g vs %.9g", n, got, (double)ref);
      TL_CHECK(shl_zh_dot_zh(n, za, u, zb, v) == shl_zh_dot_zh(n, zb, v, za, u) ||
                   fabs((double)shl_zh_dot_zh(n, zb, v, za, u) - got) <=
                       1e-7 * (double)sqrtl(nza * nzb),
               "reciprocity");
      /* ZH.ZH = SH.SH of the rotated lobes = SH.ZH of one rotated lobe */
      shl_zh_rotate(n, zb, v, rb);
      TL_CHECK(fabs((double)shl_sh_conv_zh(n, rb, za, u) - got) <= 2e-6 * (double)sqrtl(nza * nzb),
               "zh_dot_zh = sh_conv_zh(rotated) n=%d", n);
    }
  }
  {
    float a[4] = {1, 2, 3, 4}, z[2] = {1, 1}, w0[3] = {0, 0, 0}, wz[3] = {0, 0, 1},
          wn[3] = {NAN, 0, 0};
    TL_CHECK(shl_sh_dot(0, a, a) == 0.0f && shl_sh_conv_zh(0, a, z, wz) == 0.0f &&
                 shl_zh_dot_zh(0, z, wz, z, wz) == 0.0f,
             "n = 0: 0");
    TL_CHECK(shl_sh_conv_zh(2, a, z, w0) == shl_sh_conv_zh(2, a, z, wz) &&
                 shl_sh_conv_zh(2, a, z, wn) == shl_sh_conv_zh(2, a, z, wz) &&
                 shl_zh_dot_zh(2, z, wn, z, w0) == shl_zh_dot_zh(2, z, wz, z, wz),
             "zero / NaN axis: +z");
  }
}

/* irradiance of a ZH radiance about w at normal nrm, quadrature over the hemisphere of nrm */
static ld irr_ref(int n, const float *zh, ld z) {
  ld wax[3], s = 0, st = sqrtl(1 - z * z);
  int i, j, p, np = 12;
  wax[0] = st;
  wax[1] = 0;
  wax[2] = z; /* normal +z, radiance axis at angle acos(z) */
  for (p = 0; p < np; ++p)
    for (i = 0; i < NGL; ++i) {
      ld a = PI_L / 2 * p / np, b = PI_L / 2 * (p + 1) / np;
      ld t = (a + b) / 2 + (b - a) / 2 * gl_x[i], ct = cosl(t), sn = sinl(t);
      for (j = 0; j < 2 * QN; ++j) {
        ld ph = PI_L * j / QN, w[3];
        w[0] = sn * cosl(ph);
        w[1] = sn * sinl(ph);
        w[2] = ct;
        s += gl_w[i] * (b - a) / 2 * (PI_L / QN) * sn * ct * zh_at(n, zh, wax, w);
      }
    }
  return s;
}

static void test_irradiance(void) {
  static const float zs[] = {-1.0f, -0.7f, -0.2f, 0.0f, 0.3f, 0.8f, 1.0f};
  int k, n, i;
  for (n = 1; n <= 12; n += (n < 4 ? 1 : 4)) {
    float zh[16];
    ld nz = 0;
    for (i = 0; i < n; ++i)
      zh[i] = (float)(2 * urand() - 1), nz += (ld)zh[i] * zh[i];
    for (k = 0; k < 7; ++k) {
      ld ref = irr_ref(n, zh, zs[k]);
      double got = (double)shl_zh_irradiance(n, zh, zs[k]);
      TL_CHECK(fabs(got - (double)ref) <= 3e-7 * (double)sqrtl(nz),
               "irradiance n=%d z=%g: %.9g vs %.9g", n, (double)zs[k], got, (double)ref);
      if (n == 3) {
        got = (double)shl_zh_irradiance_quadratic(zh, zs[k]);
        TL_CHECK(fabs(got - (double)ref) <= 3e-7 * (double)sqrtl(nz),
                 "irradiance3 z=%g: %.9g vs %.9g", (double)zs[k], got, (double)ref);
      }
    }
  }
  {
    /* uniform unit radiance: E = pi; Lambert lobe convolution gives E / pi */
    float zh[8] = {0}, lam[8], up[3] = {0, 0, 1};
    zh[0] = (float)sqrt(4 * M_PI);
    TL_CHECK(fabs((double)shl_zh_irradiance(8, zh, 0.3f) - M_PI) < 3e-7 &&
                 fabs((double)shl_zh_irradiance_quadratic(zh, -0.9f) - M_PI) < 3e-7,
             "uniform radiance: E = pi");
    shl_zh_lambert(8, lam);
    TL_CHECK(fabs((double)shl_zh_dot_zh(8, zh, up, lam, up) - 1.0) < 2e-7, "Lambert energy 1");
    TL_CHECK(shl_zh_irradiance(3, zh, NAN) == shl_zh_irradiance(3, zh, 0.0f) &&
                 shl_zh_irradiance(3, zh, 7.0f) == shl_zh_irradiance(3, zh, 1.0f) &&
                 shl_zh_irradiance_quadratic(zh, -7.0f) == shl_zh_irradiance_quadratic(zh, -1.0f),
             "z clamped, NaN -> 0");
  }
}

/* 3-band SH radiance at w in long double (Condon-Shortley signs, as the header's basis) */
static ld sh9_at(const float *sh, const ld *w) {
  ld x = w[0], y = w[1], z = w[2], k0 = 0.5L / sqrtl(PI_L), k1 = sqrtl(3 / (4 * PI_L));
  ld k2 = 0.5L * sqrtl(15 / PI_L), k20 = 0.25L * sqrtl(5 / PI_L), k22 = 0.25L * sqrtl(15 / PI_L);
  ld y9[9] = {k0,
              -k1 * y,
              k1 * z,
              -k1 * x,
              k2 * x * y,
              -k2 * y * z,
              k20 * (3 * z * z - 1),
              -k2 * x * z,
              k22 * (x * x - y * y)};
  ld f = 0;
  int i;
  for (i = 0; i < 9; ++i)
    f += (ld)sh[i] * y9[i];
  return f;
}
/* E(nrm) = int L(w) max(0, nrm . w) dw by Gauss-Legendre in theta about nrm (4 pieces) and
   2 QN points in phi: exact to rounding for the degree-2 radiance */
static ld sh9_irr_ref(const float *sh, const float *nrm) {
  ld n[3] = {nrm[0], nrm[1], nrm[2]}, t1[3], t2[3], r, s = 0;
  int p, i, j, k;
  r = sqrtl(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (k = 0; k < 3; ++k)
    n[k] /= r;
  if (fabsl(n[2]) < 0.9L)
    t1[0] = -n[1], t1[1] = n[0], t1[2] = 0;
  else
    t1[0] = 0, t1[1] = -n[2], t1[2] = n[1];
  r = sqrtl(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]);
  for (k = 0; k < 3; ++k)
    t1[k] /= r;
  t2[0] = n[1] * t1[2] - n[2] * t1[1];
  t2[1] = n[2] * t1[0] - n[0] * t1[2];
  t2[2] = n[0] * t1[1] - n[1] * t1[0];
  for (p = 0; p < 4; ++p)
    for (i = 0; i < NGL; ++i) {
      ld a = PI_L / 2 * p / 4, b = PI_L / 2 * (p + 1) / 4;
      ld t = (a + b) / 2 + (b - a) / 2 * gl_x[i], ct = cosl(t), sn = sinl(t);
      for (j = 0; j < 16; ++j) {
        ld ph = PI_L * j / 8, w[3];
        for (k = 0; k < 3; ++k)
          w[k] = sn * cosl(ph) * t1[k] + sn * sinl(ph) * t2[k] + ct * n[k];
        s += gl_w[i] * (b - a) / 2 * (PI_L / 8) * sn * ct * sh9_at(sh, w);
      }
    }
  return s;
}
static double quad_form(const float *m, const float *nrm) {
  double v[4] = {nrm[0], nrm[1], nrm[2], 1.0}, e = 0.0;
  int i, j;
  for (i = 0; i < 4; ++i)
    for (j = 0; j < 4; ++j)
      e += v[i] * (double)m[4 * i + j] * v[j];
  return e;
}

/* shl_sh_irradiance_matrix: v^T M v against cubature of the 3-band radiance (random SH and
   normals, the axes), against shl_sh_conv_zh with the clamped cosine, symmetry, uniform
   radiance (pi), a point light's ringing (closed form), NaN propagation; measured 2.0e-8 and
   4.5e-8 of sum |sh| */
static void test_irradiance_matrix(void) {
  float sh[9], m[16], nrm[3], cosine[3];
  double err = 0.0, errc = 0.0;
  int t, k, sym = 1;
  shl_zh_cosine_power(3, 1.0f, cosine);
  for (t = 0; t < 400; ++t) {
    double sc = 0.0, e, ref;
    for (k = 0; k < 9; ++k)
      sh[k] = (float)(2 * urand() - 1), sc += fabs((double)sh[k]);
    if (t < 6) {
      nrm[0] = nrm[1] = nrm[2] = 0.0f, nrm[t % 3] = t < 3 ? 1.0f : -1.0f;
    } else {
      rand_dir(nrm);
    }
    shl_sh_irradiance_matrix(sh, m);
    for (k = 0; k < 16; ++k)
      sym &= m[k] == m[4 * (k % 4) + k / 4];
    e = quad_form(m, nrm);
    ref = (double)sh9_irr_ref(sh, nrm);
    err = fmax(err, fabs(e - ref) / sc);
    errc = fmax(errc, fabs(e - (double)shl_sh_conv_zh(3, sh, cosine, nrm)) / sc);
  }
  printf("  irradiance matrix: |v^T M v - cubature| <= %.2e, |.. - shl_sh_conv_zh| <= %.2e of "
         "sum |sh|\n",
         err, errc);
  TL_CHECK(sym, "M symmetric");
  TL_CHECK(err <= 6e-8, "against cubature: %.3e of sum |sh|", err);
  TL_CHECK(errc <= 1.5e-7, "against shl_sh_conv_zh: %.3e of sum |sh|", errc);
  for (k = 0; k < 9; ++k)
    sh[k] = 0.0f;
  sh[0] = (float)sqrt(4 * M_PI); /* uniform unit radiance: E = pi everywhere */
  shl_sh_irradiance_matrix(sh, m);
  rand_dir(nrm);
  TL_CHECK(fabs(quad_form(m, nrm) - M_PI) < 4e-7, "uniform radiance: %.9g", quad_form(m, nrm));
  {
    /* a point light on +z, L_i = Y_i(+z): E(theta) = (1 + 2c + 5/8 (3c^2 - 1)) / 4, c = cos
       theta; its minimum at c = -8/15 is -19/480, its maximum 17/16: -3.73 % */
    float up[3] = {0.0f, 0.0f, 1.0f}, d[3];
    double lo = 1e9, hi = -1e9, c;
    shl_sh_eval(3, up, sh);
    shl_sh_irradiance_matrix(sh, m);
    for (k = 0; k <= 3000; ++k) {
      c = -1.0 + 2.0 * k / 3000.0;
      d[0] = (float)sqrt(1.0 - c * c), d[1] = 0.0f, d[2] = (float)c;
      lo = fmin(lo, quad_form(m, d));
      hi = fmax(hi, quad_form(m, d));
    }
    printf("  point light: E from %.6f to %.6f (%.2f %% of the peak)\n", lo, hi, 100.0 * lo / hi);
    TL_CHECK(fabs(lo + 19.0 / 480.0) < 1e-6 && fabs(hi - 17.0 / 16.0) < 1e-6,
             "point light ringing: %.8f, %.8f", lo, hi);
  }
  sh[4] = NAN;
  shl_sh_irradiance_matrix(sh, m);
  TL_CHECK(isnan(m[1]) && isnan(m[4]) && !isnan(m[0]) && !isnan(m[15]), "NaN propagates to xy");
}

/* ---- windows and band selection ---------------------------------------------------------------
 */

static void cap_ringing(int n, const float *zh, double *ovs, double *neg) {
  int i, l;
  ld p[64];
  *ovs = -1e9;
  *neg = 1e9;
  for (i = 0; i <= 4000; ++i) {
    ld t = PI_L * i / 4000, f = 0;
    leg(n, cosl(t), p);
    for (l = 0; l < n; ++l)
      f += (ld)zh[l] * kl(l) * p[l];
    if ((double)f - 1.0 > *ovs) *ovs = (double)f - 1.0;
    if ((double)f < *neg) *neg = (double)f;
  }
}

static void test_window(void) {
  float zh[64], w[64];
  int n, l, kind;
  for (kind = 1; kind <= 2; ++kind)
    for (n = 1; n <= 64; n += 9) {
      int ok = 1;
      for (l = 0; l < n; ++l)
        w[l] = 1.0f;
      shl_zh_window(n, kind, 0.0f, w);
      for (l = 0; l < n; ++l) {
        ld t = (ld)l / n,
           ref = kind == 1 ? (1 + cosl(PI_L * t)) / 2 : (l ? sinl(PI_L * t) / (PI_L * t) : 1);
        ok &= fabsl((ld)w[l] - ref) <= 1e-7L;
      }
      TL_CHECK(ok, "window kind %d n=%d vs libm", kind, n);
    }
  for (l = 0; l < 8; ++l)
    w[l] = 1.0f;
  shl_zh_window(8, 2, 4.0f, w);
  TL_CHECK(w[3] > 0.0f && w[4] == 0.0f && w[7] == 0.0f, "width 4: zero from band 4");
  for (l = 0; l < 8; ++l)
    w[l] = 2.0f;
  shl_zh_window(8, 0, 4.0f, w);
  shl_zh_window(8, 7, 4.0f, w);
  TL_CHECK(w[7] == 2.0f, "kind none / unknown: unchanged");
  {
    /* ringing of a cap (half-angle 30 deg), n = 8 */
    double o0, n0, o1, n1, o2, n2;
    shl_zh_cap(8, 0.5f, 1.0f, zh);
    cap_ringing(8, zh, &o0, &n0);
    for (l = 0; l < 8; ++l)
      w[l] = zh[l];
    shl_zh_window(8, SHLIGHT_WINDOW_HANNING, 0.0f, w);
    cap_ringing(8, w, &o1, &n1);
    for (l = 0; l < 8; ++l)
      w[l] = zh[l];
    shl_zh_window(8, SHLIGHT_WINDOW_LANCZOS, 0.0f, w);
    cap_ringing(8, w, &o2, &n2);
    printf("  cap 30 deg, n = 8: overshoot / most negative: none %.4f / %.4f, Hanning %.4f / %.4f, "
           "Lanczos %.4f / %.4f\n",
           o0, n0, o1, n1, o2, n2);
    TL_CHECK(n1 > n0 && n2 > n0 && -n1 < 0.5 * -n0, "windows reduce the negative lobe");
  }
}

static void test_bands_for(void) {
  static const float targets[] = {1e-1f, 1e-2f, 1e-4f, 1e-6f, 0.0f};
  float zh[64];
  int lobe, k;
  for (lobe = 0; lobe < 4; ++lobe) {
    if (lobe == 0) shl_zh_phong(64, 10.0f, zh);
    if (lobe == 1) shl_zh_phong(64, 200.0f, zh);
    if (lobe == 2) shl_zh_ggx(64, 0.2f, zh);
    if (lobe == 3) shl_zh_lambert(64, zh);
    for (k = 0; k < 5; ++k) {
      int got = shl_zh_bands_for(64, zh, targets[k]), m, want = 64, l;
      ld tot = 0;
      for (l = 0; l < 64; ++l)
        tot += (ld)zh[l] * zh[l];
      for (m = 64; m >= 1; --m) {
        ld tail = 0;
        for (l = m; l < 64; ++l)
          tail += (ld)zh[l] * zh[l];
        if (tail <= (ld)targets[k] * tot) want = m;
      }
      TL_CHECK(got == want, "bands_for lobe %d target %g: %d vs brute force %d", lobe,
               (double)targets[k], got, want);
    }
  }
  {
    float z0[4] = {0, 0, 0, 0};
    shl_zh_phong(16, 10.0f, zh);
    TL_CHECK(shl_zh_bands_for(16, zh, NAN) == 16 && shl_zh_bands_for(16, zh, -1.0f) == 16 &&
                 shl_zh_bands_for(4, z0, 0.1f) == 1 && shl_zh_bands_for(16, zh, 1.0f) == 1 &&
                 shl_zh_bands_for(0, zh, 0.1f) == 1,
             "bands_for degenerate inputs");
  }
}

/* ---- HVL ------------------------------------------------------------------------------------- */

/* fraction of the cap (half-angle a, sin a = s) at angle beta from the normal that is above the
 * horizon: ring quadrature, graded toward the kink psi* = |pi/2 - beta| and toward a */
static ld h_ref(ld s, ld beta) {
  ld a = asinl(s), al = sqrtl((1 - s) * (1 + s)), acc = 0, k = fabsl(PI_L / 2 - beta);
  ld e[200];
  int ne = 0, j, i;
  e[ne++] = 0;
  e[ne++] = a;
  if (k > 0 && k < a) {
    ld d;
    e[ne++] = k;
    for (d = (a - k) / 2; d > 1e-14L * a; d /= 3)
      e[ne++] = k + d;
    for (d = k / 2; d > 1e-14L * a; d /= 3)
      e[ne++] = k - d;
  }
  qsort(e, (size_t)ne, sizeof e[0], cmp_ld);
  for (j = 0; j + 1 < ne; ++j)
    for (i = 0; i < NGL; ++i) {
      ld lo = e[j], hi = e[j + 1], psi = (lo + hi) / 2 + (hi - lo) / 2 * gl_x[i];
      ld q = -cosl(beta) * cosl(psi) / (sinl(beta) * sinl(psi)), fr;
      if (q >= 1)
        fr = 0;
      else if (q <= -1)
        fr = 1;
      else
        fr = acosl(q) / PI_L;
      acc += gl_w[i] * (hi - lo) / 2 * sinl(psi) * fr;
    }
  return acc / (s * s / (1 + al));
}

static void test_horizon(void) {
  static const double ss[] = {1e-6, 1e-3, 0.05, 0.3, 0.5, 0.8, 0.99, 1.0};
  static const double ts[] = {-1.2, -0.999, -0.9, -0.5, -0.1, 0.0, 0.2, 0.6, 0.95, 0.9999, 1.5};
  int i, j;
  double worst = 0;
  float nrm[3] = {0, 0, 1};
  for (i = 0; i < 8; ++i)
    for (j = 0; j < 11; ++j) {
      float d = 1.0f, r = (float)ss[i], w[3];
      double s = (double)r, c = fmax(-1.0, fmin(1.0, ts[j] * s)), h, ref;
      /* the float axis at angle beta: exact cosine recomputed from the float vector */
      w[0] = (float)sqrt((1 - c) * (1 + c));
      w[1] = 0;
      w[2] = (float)c;
      c = (double)w[2] / sqrt((double)w[0] * w[0] + (double)w[2] * w[2]);
      h = (double)shl_hvl_horizon(nrm, w, r, d);
      ref = c >= s ? 1.0 : c <= -s ? 0.0 : (double)h_ref((ld)s, acosl((ld)c));
      if (fabs(h - ref) > worst) worst = fabs(h - ref);
      TL_CHECK(fabs(h - ref) <= 1.2e-7, "H s=%g t=%g: %.9g vs %.9g", s, ts[j], h, ref);
    }
  printf("  exact H: max |error| %.2e (float output) over s in [1e-6, 1]\n", worst);
  {
    /* smoothstep variant: its max error against the exact H (docs/derivations.md table) */
    static const double as[] = {0.01, 0.1, 0.3, 0.5, 0.8, 1.2, 1.5};
    static const double tab[] = {0.039, 0.040, 0.041, 0.044, 0.051, 0.068, 0.089};
    int k;
    printf("  smoothstep H: max |error| vs exact:");
    for (k = 0; k < 7; ++k) {
      double m = 0;
      for (j = 0; j <= 400; ++j) {
        double be = M_PI / 2 - as[k] + 2 * as[k] * j / 400.0;
        float w[3] = {(float)sin(be), 0.0f, (float)cos(be)};
        float r = (float)sin(as[k]);
        double e = fabs((double)shl_hvl_horizon_smoothstep(nrm, w, r, 1.0f) -
                        (double)shl_hvl_horizon(nrm, w, r, 1.0f));
        if (e > m) m = e;
      }
      printf(" a=%g %.3f", as[k], m);
      TL_CHECK(fabs(m - tab[k]) <= 0.0015, "smoothstep a=%g: %.4f vs docs/derivations.md %.3f",
               as[k], m, tab[k]);
    }
    printf("\n");
  }
  {
    float up[3] = {0, 0, 1}, side[3] = {1, 0, 0}, dn[3] = {0, 0, -1}, z0[3] = {0, 0, 0};
    float nan3[3] = {NAN, 0, 0};
    TL_CHECK(shl_hvl_horizon(up, up, 0.0f, 1.0f) == 1.0f &&
                 shl_hvl_horizon(up, dn, 0.0f, 1.0f) == 0.0f &&
                 shl_hvl_horizon(up, side, 0.0f, 1.0f) == 0.5f &&
                 shl_hvl_horizon(up, side, 1.0f, NAN) == 0.5f &&
                 shl_hvl_horizon(up, up, NAN, 1.0f) == 1.0f,
             "point limit for r <= 0, NaN");
    TL_CHECK(fabs((double)shl_hvl_horizon(up, side, 2.0f, 1.0f) - 0.5) < 1e-7 &&
                 shl_hvl_horizon(up, up, 2.0f, 1.0f) == 1.0f,
             "inside (d <= r): hemisphere cap");
    TL_CHECK(shl_hvl_horizon(z0, up, 0.5f, 1.0f) == 1.0f &&
                 shl_hvl_horizon(nan3, up, 0.5f, 1.0f) == 1.0f,
             "zero / NaN normal: +z");
    TL_CHECK(shl_hvl_horizon_smoothstep(up, side, 0.0f, 1.0f) == 0.5f &&
                 shl_hvl_horizon_smoothstep(up, up, 0.5f, 1.0f) == 1.0f,
             "smoothstep degenerate");
  }
}

static void test_hvl(void) {
  float x[3] = {0, 0, 0}, nx[3] = {0, 0, 1}, y[3] = {0.3f, 0.2f, 2.0f}, ny[3] = {0, 0, -1};
  int n, i;
  /* eq. 21 point-light consistency: (cap solid angle) / (pi r^2) -> 1 / d^2 */
  {
    float zh[1];
    double d = 10.0;
    shl_zh_cap(1, 1.0f, (float)d, zh);
    TL_CHECK(fabs((double)zh[0] / 0.28209479177387814 / M_PI * d * d - 1.0025) < 2e-4,
             "Omega / (pi r^2) d^2 = 1.0025 at d/r = 10 (docs/derivations.md)");
  }
  /* G against its definition with an independent H */
  {
    double dx = 0.3, dy = 0.2, dz = 2.0, d = sqrt(dx * dx + dy * dy + dz * dz), r = 0.5;
    double cj = dz / d, hr = (double)h_ref((ld)(r / d), acosl((ld)(dz / d)));
    double g = (double)shl_hvl_geometric(x, nx, y, ny, (float)r, 1);
    TL_CHECK(fabs(g - cj * hr / (M_PI * r * r)) <= 3e-7 * g, "G: %.9g vs %.9g", g,
             cj * hr / (M_PI * r * r));
    TL_CHECK(shl_hvl_geometric(x, nx, y, ny, 0.0f, 1) == 0.0f &&
                 shl_hvl_geometric(x, nx, y, ny, NAN, 0) == 0.0f &&
                 shl_hvl_geometric(x, nx, y, nx, 0.5f, 1) == 0.0f,
             "G: r <= 0, NaN, HVL facing away: 0");
    TL_CHECK(isfinite(shl_hvl_geometric(x, nx, x, ny, 0.5f, 1)) &&
                 isfinite(shl_hvl_geometric(x, nx, x, ny, 0.5f, 0)),
             "G: x == y finite");
  }
  /* contribution: SH path against quadrature over the cap, ZH path against the SH path */
  for (n = 1; n <= 8; n += 7) {
    float fsh[64], fzh[8], ax[3] = {0.2f, -0.1f, 1.0f};
    double c_sh, c_zh, c_rot;
    ld ref = 0, d, s, al, wv[3];
    for (i = 0; i < n * n; ++i)
      fsh[i] = (float)(2 * urand() - 1);
    /* cap about w = y/|y| in long double by ring quadrature (psi, phi) */
    d = sqrtl((ld)y[0] * y[0] + (ld)y[1] * y[1] + (ld)y[2] * y[2]);
    for (i = 0; i < 3; ++i)
      wv[i] = (ld)y[i] / d;
    s = 0.5L / d;
    al = sqrtl(1 - s * s);
    {
      ld e1[3], e2[3], nrm;
      int j, p, q;
      e1[0] = wv[2];
      e1[1] = 0;
      e1[2] = -wv[0];
      nrm = sqrtl(e1[0] * e1[0] + e1[2] * e1[2]);
      for (j = 0; j < 3; ++j)
        e1[j] /= nrm;
      e2[0] = wv[1] * e1[2] - wv[2] * e1[1];
      e2[1] = wv[2] * e1[0] - wv[0] * e1[2];
      e2[2] = wv[0] * e1[1] - wv[1] * e1[0];
      for (p = 0; p < NGL; ++p)
        for (q = 0; q < 2 * QN; ++q) {
          ld ct = al + (1 - al) * (gl_x[p] + 1) / 2, st = sqrtl(1 - ct * ct), ph = PI_L * q / QN,
             w[3];
          for (j = 0; j < 3; ++j)
            w[j] = ct * wv[j] + st * (cosl(ph) * e1[j] + sinl(ph) * e2[j]);
          ref += gl_w[p] * (1 - al) / 2 * (PI_L / QN) * sh_at(n, fsh, w);
        }
    }
    c_sh = (double)shl_hvl_contribution(n, 2.0f, fsh, x, y, 0.5f);
    {
      /* error scale: lj |L| |F| (Y in float: a few ulp of each band's norm) */
      ld nl = 0, nf = 0;
      int l;
      for (l = 0; l < n; ++l) {
        ld q = 2 * PI_L * s * s / (1 + al) * kl(l); /* |cap ZH_l| <= Omega K_l */
        nl += q * q;
      }
      for (i = 0; i < n * n; ++i)
        nf += (ld)fsh[i] * fsh[i];
      TL_CHECK(fabs(c_sh - 2.0 * (double)ref) <= 2e-6 * 2.0 * (double)sqrtl(nl * nf),
               "contribution n=%d: %.9g vs %.9g", n, c_sh, 2.0 * (double)ref);
    }
    shl_zh_phong(n, 30.0f, fzh);
    shl_zh_rotate(n, fzh, ax, fsh);
    c_zh = (double)shl_hvl_contribution_zh(n, 2.0f, fzh, ax, x, y, 0.5f);
    c_rot = (double)shl_hvl_contribution(n, 2.0f, fsh, x, y, 0.5f);
    TL_CHECK(fabs(c_zh - c_rot) <= 1e-6 * fabs(c_rot) + 1e-9, "contribution_zh n=%d: %.9g vs %.9g",
             n, c_zh, c_rot);
  }
  {
    float f[4] = {1, 0, 0, 0}, zf[2] = {1, 0};
    double e = (double)shl_hvl_radiance(2, f, 3.0f, x, nx, y, ny, 0.5f, 1);
    double want = 3.0 * 0.28209479177387814 * (double)shl_hvl_geometric(x, nx, y, ny, 0.5f, 1);
    TL_CHECK(fabs(e - want) <= 1e-6 * want, "radiance = power F.Y G");
    TL_CHECK(shl_hvl_emission(1, f, ny) == shl_hvl_emission(2, f, ny), "isotropic n = 1");
    TL_CHECK(shl_hvl_contribution(2, 1.0f, f, x, y, 0.0f) == 0.0f &&
                 shl_hvl_contribution_zh(2, 1.0f, zf, nx, x, y, NAN) == 0.0f,
             "contribution r <= 0 / NaN: 0");
    TL_CHECK(isfinite(shl_hvl_contribution(2, 1.0f, f, x, x, 0.5f)) &&
                 fabs((double)shl_hvl_contribution(2, 1.0f, f, x, x, 0.5f) -
                      2 * M_PI * 0.28209479177387814) < 1e-6,
             "x inside: hemisphere cap");
  }
  /* radius heuristics */
  {
    float p[3] = {0, 0, 0}, pn[8][3], dn[8];
    double sw = 0, sd = 0;
    for (i = 0; i < 8; ++i) {
      pn[i][0] = (float)(urand() - 0.5);
      pn[i][1] = (float)(urand() - 0.5);
      pn[i][2] = (float)(urand() - 0.5);
      dn[i] = (float)(2 + urand());
    }
    for (i = 0; i < 8; ++i) {
      double w = 1.0 / (fabs(2.5 - (double)dn[i]) + 1e-3);
      sw += w;
      sd += w * sqrt((double)pn[i][0] * pn[i][0] + (double)pn[i][1] * pn[i][1] +
                     (double)pn[i][2] * pn[i][2]);
    }
    TL_CHECK(fabs((double)shl_hvl_radius_neighbours(8, p, 2.5f, (const float(*)[3])pn, dn, 1e-3f) -
                  sd / sw) < 1e-6 * sd / sw,
             "r1 eq. 23");
    TL_CHECK(shl_hvl_radius_neighbours(0, p, 2.5f, (const float(*)[3])pn, dn, 1e-3f) == 0.0f,
             "r1: no neighbours: 0");
    dn[3] = NAN;
    pn[5][1] = INFINITY;
    TL_CHECK(isfinite(shl_hvl_radius_neighbours(8, p, 2.5f, (const float(*)[3])pn, dn, 0.0f)) &&
                 isfinite(shl_hvl_radius_neighbours(12, p, dn[0], (const float(*)[3])pn, dn, NAN)),
             "r1: NaN / inf neighbours skipped, eps 0 / NaN, count > 8");
    {
      /* E9: |tan g - (g + g^3/3)| = 0.01 at g = 0.5786, i.e. fov / sqrt(m) = 0.41 */
      double g = 0.5786, fov = g / sqrt(2.0) * 4.0;
      double r2 = (double)shl_hvl_radius_fov(1.0f, (float)fov, 16);
      double rt = (double)shl_hvl_radius_fov_tan(1.0f, (float)fov, 16);
      TL_CHECK(fabs(r2 - (g + g * g * g / 3)) < 1e-6 && fabs(rt - tan(g)) < 1e-6 * tan(g),
               "r2 Taylor and tan: %.7g %.7g", r2, rt);
      TL_CHECK(fabs((rt - r2) - 0.0100) < 2e-4, "E9: tan - Taylor = %.5f at g = 0.5786", rt - r2);
      TL_CHECK(shl_hvl_radius_fov(NAN, 1.0f, 4) == 0.0f &&
                   shl_hvl_radius_fov_tan(1.0f, -1.0f, 4) == 0.0f &&
                   shl_hvl_radius_fov(1.0f, 0.5f, 0) == shl_hvl_radius_fov(1.0f, 0.5f, 1) &&
                   isfinite(shl_hvl_radius_fov_tan(1.0f, 100.0f, 1)),
               "r2 degenerate");
    }
  }
}

int main(void) {
  gl_init();
  sphere_init();
  TL_RUN(test_cosine_power_exact);
  TL_RUN(test_lambert_closed_form);
  TL_RUN(test_cosine_power_hard);
  TL_RUN(test_microfacet);
  TL_RUN(test_convolution);
  TL_RUN(test_irradiance);
  TL_RUN(test_irradiance_matrix);
  TL_RUN(test_window);
  TL_RUN(test_bands_for);
  TL_RUN(test_horizon);
  TL_RUN(test_hvl);
  return tl_summary();
}
