/* test_ssf.c - shlight's >>ssf section (screen-space SH filter for VPLs, [SSF]) against
 * independent references.
 *
 * Build: make build/tests/test_ssf (gcc -std=c99 -O2 ... -lquadmath -lm); run it, it ends with
 * "N passed, N failed" (about a second).
 *
 * References (none shares code with the header):
 *  - the VPL's weight e = flux max(0, n_y . -w) / (pi max(d^2, dmin^2)) and direction w in long
 *    double straight from the definition (>>ssf), and Y_i(w) from tests/ref/shref.h (binary128,
 *    angle-based associated Legendre recurrence);
 *  - the n-band irradiance of a delta: e sum_{l<n} (2l+1)/(4 pi) A_l P_l(z) with
 *    Ramamoorthi-Hanrahan's factorial A_l (docs/derivations.md sec. 5) and the three-term Legendre
 *    recurrence in long double, and its limit e max(0, z);
 *  - the irradiance of a band-limited SH radiance: product quadrature over the hemisphere of the
 *    normal (Gauss-Legendre in cos theta, uniform in phi, exact for these polynomials) with the
 *    binary128 Y;
 *  - the 1/pi of the VPL's weight: its irradiance integrated over a sphere of receivers equals
 *    its flux (Gauss-Legendre, exact for the cosine);
 *  - the spot-light texel solid angle of >>ssf's documentation: summed over the cone it tends to
 *    2 pi (1 - cos a);
 *  - interleaving: a brute-force count of how often each VPL is used over a pixel tile;
 *  - filter weight: limits and symmetry stated in the kernel's documentation.
 * Error model: the kernels round e and Y to float (0.5 ulp each) and the SH sums accumulate in
 * float; tolerances are stated next to each check with the measured worst case printed. */
/* n out of range: counted instead of aborting (the release behaviour is what is tested) */
#define SHLIGHT_IMPLEMENTATION
#include "../shlight.h"
#include "ref/shref.h"
#include "tl.h"
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

typedef long double ld;
#define PI_L 3.141592653589793238462643383279502884L

static unsigned int g_seed = 20040u;
static float rndf(void) { /* [0, 1) */
  g_seed = g_seed * 1664525u + 1013904223u;
  return (float)(g_seed >> 8) * (1.0f / 16777216.0f);
}
static float rnds(void) { /* [-1, 1) */
  return 2.0f * rndf() - 1.0f;
}
static void rnd_vec(float *v, float scale) {
  v[0] = scale * rnds();
  v[1] = scale * rnds();
  v[2] = scale * rnds();
}

/* ---- references ------------------------------------------------------------------------- */

/* e and the unit w in long double; returns 0 where the kernel must add nothing */
static ld ref_vpl(const float *x, const float *nx, const float *y, const float *ny, float flux,
                  float dmin, ld *w) {
  ld d[3], d2 = 0, nn = 0, cy = 0, side = 0, dd, den;
  int k;
  for (k = 0; k < 3; ++k) {
    d[k] = (ld)y[k] - (ld)x[k];
    d2 += d[k] * d[k];
    nn += (ld)ny[k] * (ld)ny[k];
  }
  if (!(d2 > 0) || !((ld)flux > 0) || !isfinite(flux)) return 0;
  dd = sqrtl(d2);
  for (k = 0; k < 3; ++k) {
    w[k] = d[k] / dd;
    side += (ld)nx[k] * w[k];
    cy -= (ld)ny[k] * w[k];
  }
  if (side < 0) return 0;
  cy /= sqrtl(nn);
  if (!(cy > 0)) return 0;
  den = d2;
  if ((ld)dmin > 0 && (ld)dmin * (ld)dmin > den) den = (ld)dmin * (ld)dmin;
  return (ld)flux * cy / (PI_L * den);
}

static ld ref_A(int l) { /* Ramamoorthi-Hanrahan, docs/derivations.md sec. 5 */
  ld f = 1, h = 1;
  int k;
  if (l == 0) return PI_L;
  if (l == 1) return 2 * PI_L / 3;
  if (l % 2) return 0;
  for (k = 2; k <= l; ++k)
    f *= (ld)k;
  for (k = 2; k <= l / 2; ++k)
    h *= (ld)k;
  return 2 * PI_L * ((l / 2 - 1) % 2 ? -1 : 1) * f /
         ((ld)(l + 2) * (ld)(l - 1) * powl(2.0L, (ld)l) * h * h);
}

/* n-band clamped cosine at z: sum_{l<n} (2l+1)/(4 pi) A_l P_l(z) */
static ld ref_cos_n(int n, ld z) {
  ld p0 = 1, p1 = z, s = ref_A(0) / (4 * PI_L), p2;
  int l;
  for (l = 1; l < n; ++l) {
    s += (2.0L * l + 1) / (4 * PI_L) * ref_A(l) * p1;
    p2 = ((2.0L * l + 1) * z * p1 - (ld)l * p0) / (ld)(l + 1);
    p0 = p1;
    p1 = p2;
  }
  return s;
}

#define NGL 24
static ld gl_x[NGL], gl_w[NGL];
static void gl_init(void) {
  int i, k, it;
  for (i = 0; i < NGL; ++i) {
    ld x = cosl(PI_L * ((ld)i + 0.75L) / ((ld)NGL + 0.5L)), p0 = 1, p1 = x, dp = 1;
    for (it = 0; it < 20; ++it) {
      p0 = 1;
      p1 = x;
      for (k = 1; k < NGL; ++k) {
        ld p2 = ((2.0L * k + 1) * x * p1 - (ld)k * p0) / (ld)(k + 1);
        p0 = p1;
        p1 = p2;
      }
      dp = (ld)NGL * (x * p1 - p0) / (x * x - 1);
      x -= p1 / dp;
    }
    gl_x[i] = x;
    gl_w[i] = 2 / ((1 - x * x) * dp * dp);
  }
}

/* int over the hemisphere of nrm (unit) of L(w) (nrm . w), L = sum sh_i Y_i: Gauss-Legendre in
   t = nrm . w on [0, 1], 2n + 2 uniform nodes in phi (exact for degree < 2n + 2 in phi) */
static ld ref_irradiance_quad(int n, const float *sh, const ld *nrm) {
  ld t1[3], t2[3], s = 0;
  int i, j, k, np = 2 * n + 2;
  shref_q yq[64 * 64];
  /* a frame around nrm */
  if (fabsl(nrm[2]) < 0.9L) {
    t1[0] = -nrm[1];
    t1[1] = nrm[0];
    t1[2] = 0;
  } else {
    t1[0] = 0;
    t1[1] = -nrm[2];
    t1[2] = nrm[1];
  }
  {
    ld l = sqrtl(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]);
    for (k = 0; k < 3; ++k)
      t1[k] /= l;
  }
  t2[0] = nrm[1] * t1[2] - nrm[2] * t1[1];
  t2[1] = nrm[2] * t1[0] - nrm[0] * t1[2];
  t2[2] = nrm[0] * t1[1] - nrm[1] * t1[0];
  for (i = 0; i < NGL; ++i) {
    ld t = 0.5L * (gl_x[i] + 1), st = sqrtl(1 - t * t), wt = 0.5L * gl_w[i];
    for (j = 0; j < np; ++j) {
      ld ph = 2 * PI_L * ((ld)j + 0.5L) / (ld)np, d[3], L = 0;
      for (k = 0; k < 3; ++k)
        d[k] = t * nrm[k] + st * (cosl(ph) * t1[k] + sinl(ph) * t2[k]);
      shref_eval_q(n, (shref_q)d[0], (shref_q)d[1], (shref_q)d[2], yq);
      for (k = 0; k < n * n; ++k)
        L += (ld)sh[k] * (ld)yq[k];
      s += wt * (2 * PI_L / (ld)np) * L * t;
    }
  }
  return s;
}

/* ---- tests ------------------------------------------------------------------------------ */

/* io_sh += e Y(w) for random geometry, n from 1 to SHLIGHT_MAX_BANDS, against long double e and
   binary128 Y. Tolerance per coefficient: 4e-7 |e| (max(|Y_i|, K_l) + 1) + 1 ulp of the prefill:
   the float roundings of e and Y_i and of the sum with the prefill (the kernel computes e in
   double and Y at the float rounding floor; measured worst printed). */
static void test_vpl_sh_projection(void) {
  static const int ns[] = {1, 2, 3, 4, 5, 8, 9, 16, 17, 32, 64};
  static float sh[64 * 64], pre[64 * 64];
  static shref_q yq[64 * 64];
  double worst = 0;
  int t, k, bad = 0, nonzero = 0;
  for (t = 0; t < 400; ++t) {
    int n = ns[t % 11];
    float x[3], nx[3], y[3], ny[3], flux = 0.1f + 10.0f * rndf(), dmin = 0.0f;
    ld w[3], e;
    rnd_vec(x, 2.0f);
    rnd_vec(y, 2.0f);
    rnd_vec(nx, 1.0f);
    rnd_vec(ny, 1.0f);
    for (k = 0; k < 3; ++k) { /* mostly facing each other, so that most VPLs count */
      ny[k] += 0.8f * (x[k] - y[k]);
      nx[k] += 0.8f * (y[k] - x[k]);
    }
    if (t % 3 == 0) dmin = 0.5f * rndf();
    if (t % 7 == 0) nx[0] = nx[1] = nx[2] = 0.0f; /* horizon test off */
    for (k = 0; k < n * n; ++k)
      sh[k] = pre[k] = rnds();
    shl_ssf_vpl_sh(n, x, nx, y, ny, flux, dmin, sh);
    e = ref_vpl(x, nx, y, ny, flux, dmin, w);
    if (e > 0) nonzero++;
    shref_eval_q(n, (shref_q)w[0], (shref_q)w[1], (shref_q)w[2], yq);
    for (k = 0; k < n * n; ++k) {
      int l = (int)sqrt((double)k);
      ld yk = (ld)yq[k], kl = sqrtl((2.0L * l + 1) / (4 * PI_L));
      ld ref = (ld)pre[k] + e * yk;
      ld tol = 4e-7L * e * (fmaxl(fabsl(yk), kl) + 1) + 1.2e-7L * fabsl((ld)pre[k]);
      ld err = fabsl((ld)sh[k] - ref);
      if (e > 0 && (double)(err / tol) > worst) worst = (double)(err / tol);
      if (!(err <= tol)) {
        if (bad < 5) printf("  n %d i %d: %.9g vs %.12Lg (e %.6Lg)\n", n, k, (double)sh[k], ref, e);
        bad++;
      }
    }
  }
  printf("  max |sh - (pre + e Y)| / tolerance = %.3g over %d non-zero VPLs\n", worst, nonzero);
  TL_CHECK(bad == 0, "%d coefficients off", bad);
  TL_CHECK(nonzero > 200, "only %d of 400 random VPLs reach x: the test is too weak", nonzero);
}

/* shl_ssf_vpl_irradiance against e max(0, ns . w) in long double: relative 1e-6 (a handful of
   float roundings of the inputs' normalisation and of the output). */
static void test_vpl_irradiance_exact(void) {
  double worst = 0;
  int t, k, bad = 0, zero_ok = 0;
  for (t = 0; t < 2000; ++t) {
    float x[3], nx[3], ns[3], y[3], ny[3], flux = 0.01f + 100.0f * rndf();
    float dmin = (t % 2) ? 0.3f * rndf() : 0.0f, got;
    ld w[3], e, c = 0, nn = 0, ref;
    rnd_vec(x, 3.0f);
    rnd_vec(y, 3.0f);
    rnd_vec(nx, 1.0f);
    rnd_vec(ny, 1.0f);
    for (k = 0; k < 3; ++k)
      ns[k] = nx[k] + 0.7f * rnds(); /* a normal-mapped normal near nx */
    e = ref_vpl(x, nx, y, ny, flux, dmin, w);
    for (k = 0; k < 3; ++k) {
      c += (ld)ns[k] * w[k];
      nn += (ld)ns[k] * (ld)ns[k];
    }
    c /= sqrtl(nn);
    ref = e * (c > 0 ? c : 0);
    got = shl_ssf_vpl_irradiance(x, nx, ns, y, ny, flux, dmin);
    if (ref == 0) {
      zero_ok += got == 0.0f;
      if (got != 0.0f) bad++;
      continue;
    }
    if ((double)(fabsl((ld)got - ref) / ref) > worst) worst = (double)(fabsl((ld)got - ref) / ref);
    if (!(fabsl((ld)got - ref) <= 1e-6L * ref)) {
      if (bad < 5) printf("  t %d: %.9g vs %.12Lg\n", t, (double)got, ref);
      bad++;
    }
  }
  printf("  max relative error %.3g; %d exact zeros (below a plane / facing away)\n", worst,
         zero_ok);
  TL_CHECK(bad == 0, "%d irradiances off", bad);
}

/* The constant of e (the 1/pi of a cosine emitter): the flux that a VPL's irradiance delivers
   to a sphere of receivers around it (radius 3, facing it, beyond the clamp) integrates to the
   VPL's flux. Gauss-Legendre in cos(theta) over the VPL's hemisphere, uniform in phi; the
   integrand is cos(theta) / pi, so the rule is exact and the tolerance is float rounding,
   1e-6 relative. A receiver behind the VPL gets nothing. */
static void test_vpl_flux_conservation(void) {
  const float y[3] = {0.5f, -0.25f, 1.0f}, ny[3] = {0.0f, 0.0f, 2.0f}, flux = 3.0f, R = 3.0f;
  ld total = 0;
  int i, j, np = 16;
  gl_init();
  for (i = 0; i < NGL; ++i) {
    ld ct = 0.5L * (gl_x[i] + 1), st = sqrtl(1 - ct * ct), wt = 0.5L * gl_w[i];
    for (j = 0; j < np; ++j) {
      ld ph = 2 * PI_L * ((ld)j + 0.5L) / (ld)np;
      float x[3], nx[3];
      x[0] = y[0] + (float)(R * st * cosl(ph));
      x[1] = y[1] + (float)(R * st * sinl(ph));
      x[2] = y[2] + (float)(R * ct);
      nx[0] = y[0] - x[0];
      nx[1] = y[1] - x[1];
      nx[2] = y[2] - x[2];
      total += wt * (2 * PI_L / (ld)np) * (ld)R * (ld)R *
               (ld)shl_ssf_vpl_irradiance(x, nx, nx, y, ny, flux, 0.5f);
    }
  }
  printf("  flux through a sphere of receivers: %.9Lg of %.9g\n", total, (double)flux);
  TL_CHECK(fabsl(total - (ld)flux) <= 1e-6L * (ld)flux, "%.9Lg vs %.9g", total, (double)flux);
  {
    const float xb[3] = {0.5f, -0.25f, -2.0f}, nb[3] = {0.0f, 0.0f, 1.0f};
    TL_CHECK(shl_ssf_vpl_irradiance(xb, nb, nb, y, ny, flux, 0.5f) == 0.0f,
             "a receiver behind the VPL is lit");
  }
}

/* The irradiance from the accumulated SH of one VPL: shl_ssf_irradiance(n, vpl SH, ns) against
   e times the long double n-band clamped cosine (tolerance 2e-6 e: float Y, float lobe and the
   float dot), and the truncation error of that series against e max(0, z), the numbers that the
   kernel's documentation states (0.094 at n = 3, 0.059 at 5, 0.021 at 16, 0.0050 at 64). */
static void test_sh_irradiance_convergence(void) {
  static const int ns[] = {1, 2, 3, 5, 8, 16, 32, 64};
  static float sh[64 * 64];
  static const double doc[] = {0.75, 0.25, 0.094, 0.059, 0.043, 0.021, 0.011, 0.0050};
  double prev = 1e30;
  int a, t, k;
  for (a = 0; a < 8; ++a) {
    int n = ns[a], bad = 0;
    double worst = 0, trunc = 0;
    /* sweep z = ns . w from -1 to 1 with random frames */
    for (t = 0; t <= 400; ++t) {
      float x[3] = {0.1f, -0.2f, 0.3f}, nx[3] = {0.0f, 0.0f, 0.0f}, y[3], ny[3], ns3[3];
      ld z = -1 + (ld)t / 200, w[3], e, ref, got, ex;
      float axis[3], u[3], v[3], ln;
      rnd_vec(axis, 1.0f);
      ln = sqrtf(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
      for (k = 0; k < 3; ++k)
        axis[k] /= ln;
      /* VPL at x + 1.5 axis facing x; ns at angle acos(z) from axis */
      for (k = 0; k < 3; ++k) {
        y[k] = x[k] + 1.5f * axis[k];
        ny[k] = -axis[k];
      }
      u[0] = -axis[1];
      u[1] = axis[0];
      u[2] = 0.0f;
      ln = sqrtf(u[0] * u[0] + u[1] * u[1]);
      if (ln < 1e-3f) {
        u[0] = 1.0f;
        u[1] = 0.0f;
        ln = 1.0f;
      }
      u[0] /= ln;
      u[1] /= ln;
      v[0] = axis[1] * u[2] - axis[2] * u[1];
      v[1] = axis[2] * u[0] - axis[0] * u[2];
      v[2] = axis[0] * u[1] - axis[1] * u[0];
      for (k = 0; k < 3; ++k)
        ns3[k] = (float)(z * axis[k] +
                         sqrtl(1 - z * z) * (cosl(0.3L * t) * u[k] + sinl(0.3L * t) * v[k]));
      memset(sh, 0, sizeof(float) * (size_t)(n * n));
      shl_ssf_vpl_sh(n, x, nx, y, ny, 2.0f, 0.0f, sh);
      got = (ld)shl_ssf_irradiance(n, sh, ns3);
      e = ref_vpl(x, nx, y, ny, 2.0f, 0.0f, w);
      {
        ld zz = 0, nn = 0;
        for (k = 0; k < 3; ++k) {
          zz += (ld)ns3[k] * w[k];
          nn += (ld)ns3[k] * (ld)ns3[k];
        }
        z = zz / sqrtl(nn);
      }
      ref = e * ref_cos_n(n, z);
      ex = e * (z > 0 ? z : 0);
      if ((double)(fabsl(got - ref) / e) > worst) worst = (double)(fabsl(got - ref) / e);
      if ((double)(fabsl(ref - ex) / e) > trunc) trunc = (double)(fabsl(ref - ex) / e);
      if (!(fabsl(got - ref) <= 2e-6L * e)) bad++;
    }
    printf("  n %2d: |E_n - e cos_n| / e <= %.2g; truncation |e cos_n - e max(0,z)| / e = %.4f\n",
           n, worst, trunc);
    TL_CHECK(bad == 0, "n %d: %d irradiances off the n-band series", n, bad);
    TL_CHECK(trunc <= doc[a] * 1.02 && trunc >= doc[a] * 0.9,
             "n %d: truncation %.4f is not the documented %.4f", n, trunc, doc[a]);
    TL_CHECK(trunc <= prev, "n %d: no convergence (%.4f after %.4f)", n, trunc, prev);
    prev = trunc;
  }
}

/* Many VPLs: the SH sum then one irradiance equals the sum of the exact irradiances up to the
   truncation bound (0.021 e_sum at n = 16; usually far less because the VPLs spread). */
static void test_many_vpls(void) {
  static float sh[16 * 16];
  int t, j, bad = 0;
  double worst = 0;
  for (t = 0; t < 50; ++t) {
    float x[3] = {0, 0, 0}, nx[3] = {0, 0, 1}, ns[3];
    ld exact = 0, esum = 0;
    float got;
    memset(sh, 0, sizeof sh);
    rnd_vec(ns, 0.5f);
    ns[2] = 1.0f;
    for (j = 0; j < 64; ++j) {
      float y[3], ny[3], f = rndf();
      ld w[3], e;
      rnd_vec(y, 2.0f);
      y[2] = 0.2f + 2.0f * rndf();
      rnd_vec(ny, 1.0f);
      ny[2] = -1.0f;
      shl_ssf_vpl_sh(16, x, nx, y, ny, f, 0.1f, sh);
      exact += (ld)shl_ssf_vpl_irradiance(x, nx, ns, y, ny, f, 0.1f);
      e = ref_vpl(x, nx, y, ny, f, 0.1f, w);
      esum += e;
    }
    got = shl_ssf_irradiance(16, sh, ns);
    if ((double)(fabsl((ld)got - exact) / esum) > worst)
      worst = (double)(fabsl((ld)got - exact) / esum);
    if (!(fabsl((ld)got - exact) <= 0.021L * esum)) bad++;
  }
  printf("  64 VPLs, n = 16: max |E_sh - E_exact| / sum e = %.3g (bound 0.021)\n", worst);
  TL_CHECK(bad == 0, "%d sums beyond the truncation bound", bad);
}

/* shl_ssf_irradiance of a band-limited random SH radiance against hemisphere quadrature with
   binary128 Y: relative to sum |sh_i|, 1e-6 (float Y, float lobe, float dot of n^2 terms). */
static void test_irradiance_band_limited(void) {
  static float sh[64 * 64];
  static const int ns[] = {1, 2, 3, 5, 8, 12};
  int a, t, k, bad = 0;
  double worst = 0;
  gl_init();
  for (a = 0; a < 6; ++a) {
    int n = ns[a];
    for (t = 0; t < 6; ++t) {
      float nrm[3];
      ld nl[3], len = 0, ref, scale = 0;
      float got;
      for (k = 0; k < n * n; ++k) {
        sh[k] = rnds();
        scale += fabsl((ld)sh[k]);
      }
      rnd_vec(nrm, 1.0f);
      if (t == 0) nrm[0] = nrm[1] = 0.0f, nrm[2] = (a % 2) ? -1.0f : 1.0f; /* poles */
      for (k = 0; k < 3; ++k)
        len += (ld)nrm[k] * (ld)nrm[k];
      for (k = 0; k < 3; ++k)
        nl[k] = (ld)nrm[k] / sqrtl(len);
      ref = ref_irradiance_quad(n, sh, nl);
      got = shl_ssf_irradiance(n, sh, nrm);
      if ((double)(fabsl((ld)got - ref) / scale) > worst)
        worst = (double)(fabsl((ld)got - ref) / scale);
      if (!(fabsl((ld)got - ref) <= 1e-6L * scale)) {
        if (bad < 5) printf("  n %d: %.9g vs %.12Lg\n", n, (double)got, ref);
        bad++;
      }
    }
  }
  printf("  max |E - quadrature| / sum |sh| = %.3g\n", worst);
  TL_CHECK(bad == 0, "%d irradiances off the quadrature", bad);
}

/* Interleaving: over any n x m tile, every VPL is used exactly once; set sizes add up; the
   return value is the number of indices the (first, stride) loop visits. */
static void test_interleave_partition(void) {
  static int used[5000];
  static const int cfg[][3] = {{4, 4, 256},  {4, 4, 255}, {4, 4, 7}, {3, 5, 100},  {1, 1, 10},
                               {8, 2, 4096}, {2, 8, 0},   {5, 3, 1}, {16, 16, 300}};
  int c, ox, px, py, j, k, bad = 0, sizes = 0;
  for (c = 0; c < 9; ++c) {
    int n = cfg[c][0], m = cfg[c][1], nvpl = cfg[c][2];
    for (ox = -2; ox <= 1; ++ox) { /* tile origins, negative ones included */
      int x0 = ox * 37 - 1, y0 = ox * 53 + 2, total = 0;
      memset(used, 0, sizeof(int) * (size_t)nvpl);
      for (py = y0; py < y0 + m; ++py)
        for (px = x0; px < x0 + n; ++px) {
          int r[2] = {-1, -1}, cnt = shl_ssf_interleave(px, py, n, m, nvpl, r), seen = 0;
          if (r[1] != n * m || r[0] < 0 || r[0] >= n * m) bad++;
          for (j = r[0]; j < nvpl; j += r[1]) {
            used[j]++;
            seen++;
          }
          if (seen != cnt) bad++;
          total += cnt;
        }
      for (j = 0; j < nvpl; ++j)
        if (used[j] != 1) bad++;
      if (total != nvpl) bad++;
      sizes++;
    }
  }
  TL_CHECK(bad == 0, "%d partition violations over %d tiles", bad, sizes);
  { /* the pattern: set of (px, py) is (py mod m) n + (px mod n), periodic into negatives */
    int r[2], r2[2];
    shl_ssf_interleave(5, 6, 4, 4, 256, r);
    TL_CHECK(r[0] == 2 * 4 + 1 && r[1] == 16, "set of (5, 6): %d / %d", r[0], r[1]);
    shl_ssf_interleave(-1, -1, 4, 4, 256, r);
    TL_CHECK(r[0] == 15, "set of (-1, -1): %d", r[0]);
    for (k = -20; k < 20; ++k) {
      shl_ssf_interleave(k, 2 * k, 3, 5, 100, r);
      shl_ssf_interleave(k + 3, 2 * k + 5, 3, 5, 100, r2);
      if (r[0] != r2[0]) bad++;
    }
    TL_CHECK(bad == 0, "pattern not periodic");
  }
  { /* clamps and degenerate counts */
    int r[2];
    TL_CHECK(shl_ssf_interleave(3, 3, 0, -5, 10, r) == 10 && r[0] == 0 && r[1] == 1,
             "n, m < 1 -> 1: %d %d", r[0], r[1]);
    TL_CHECK(shl_ssf_interleave(0, 0, 1000, 1000, 10, r) == 1 && r[1] == 256 * 256,
             "n, m > 256 -> 256: stride %d", r[1]);
    TL_CHECK(shl_ssf_interleave(3, 0, 4, 4, -7, r) == 0, "nvpl < 0 -> 0");
    TL_CHECK(shl_ssf_interleave(3, 0, 4, 4, 3, r) == 0 && r[0] == 3, "s >= nvpl -> 0");
    TL_CHECK(shl_ssf_interleave(-2147483647 - 1, -2147483647 - 1, 4, 4, 16, r) == 1 && r[0] == 0,
             "INT_MIN pixel: set %d", r[0]);
  }
}

/* The discontinuity weight: limits and symmetry of its documentation. */
static void test_weight_limits(void) {
  const float p[3] = {1.0f, 2.0f, 3.0f}, n0[3] = {0.0f, 0.0f, 2.0f}, up[3] = {0.0f, 0.0f, 1.0f};
  const float nan = (float)NAN, inf = (float)INFINITY;
  float q[3], nq[3];
  int t, bad = 0;
  TL_CHECK(shl_ssf_weight(p, n0, p, n0, 0.0f, 1.0f) == 1.0f, "same point, same normal");
  /* in the tangent plane, far away: accepted (a plane distance, not a depth difference) */
  q[0] = 50.0f;
  q[1] = -30.0f;
  q[2] = 3.0f;
  TL_CHECK(shl_ssf_weight(p, up, q, up, 1e-6f, 0.99f) == 1.0f, "tangent plane");
  /* off the plane by 0.99 / 1.01 max_dist */
  q[0] = 1.5f;
  q[1] = 2.0f;
  q[2] = 3.0f + 0.099f;
  TL_CHECK(shl_ssf_weight(p, up, q, up, 0.1f, 0.9f) == 1.0f, "inside the plane tolerance");
  q[2] = 3.0f + 0.101f;
  TL_CHECK(shl_ssf_weight(p, up, q, up, 0.1f, 0.9f) == 0.0f, "outside the plane tolerance");
  TL_CHECK(shl_ssf_weight(p, up, q, up, inf, 0.9f) == 1.0f, "max_dist inf: no plane test");
  /* normal threshold: angle 25 degrees, cos 0.906 */
  nq[0] = sinf(0.4363323f);
  nq[1] = 0.0f;
  nq[2] = cosf(0.4363323f);
  TL_CHECK(shl_ssf_weight(p, up, p, nq, 0.0f, 0.90f) == 1.0f, "cos above the threshold");
  TL_CHECK(shl_ssf_weight(p, up, p, nq, 0.0f, 0.91f) == 0.0f, "cos below the threshold");
  nq[0] = 0.0f;
  nq[2] = -1.0f;
  TL_CHECK(shl_ssf_weight(p, up, p, nq, 1.0f, 0.0f) == 0.0f, "opposite normals");
  TL_CHECK(shl_ssf_weight(p, up, p, nq, 1.0f, -1.0f) == 1.0f, "min_cos -1: no normal test");
  /* symmetry on random pairs */
  for (t = 0; t < 2000; ++t) {
    float a[3], b[3], na[3], nb[3];
    rnd_vec(a, 1.0f);
    rnd_vec(b, 1.0f);
    rnd_vec(na, 1.0f);
    rnd_vec(nb, 1.0f);
    if (shl_ssf_weight(a, na, b, nb, 0.5f, 0.2f) != shl_ssf_weight(b, nb, a, na, 0.5f, 0.2f)) bad++;
  }
  TL_CHECK(bad == 0, "%d asymmetric pairs", bad);
  /* degenerate inputs */
  q[0] = nan;
  TL_CHECK(shl_ssf_weight(p, up, q, up, 1.0f, 0.0f) == 0.0f, "NaN position");
  q[0] = inf;
  TL_CHECK(shl_ssf_weight(p, up, q, up, inf, -1.0f) == 0.0f, "infinite position");
  nq[0] = nan;
  TL_CHECK(shl_ssf_weight(p, up, p, nq, 1.0f, -1.0f) == 0.0f, "NaN normal");
  TL_CHECK(shl_ssf_weight(p, up, p, up, nan, 0.0f) == 0.0f, "NaN max_dist");
  TL_CHECK(shl_ssf_weight(p, up, p, up, -1.0f, 0.0f) == 0.0f, "negative max_dist");
  TL_CHECK(shl_ssf_weight(p, up, p, up, 1.0f, nan) == 0.0f, "NaN min_cos");
  nq[0] = nq[1] = nq[2] = 0.0f;
  TL_CHECK(shl_ssf_weight(p, up, p, nq, 1.0f, 0.99f) == 1.0f, "zero normal is +z");
}

/* Degenerate inputs of the VPL kernels: defined results, io_sh untouched where nothing is added,
   the clamp. */
static void test_bad_input(void) {
  static float sh[65 * 65], pre[65 * 65];
  const float x[3] = {0, 0, 0}, nx[3] = {0, 0, 1}, y[3] = {0, 0, 1}, ny[3] = {0, 0, -1};
  const float nan = (float)NAN, inf = (float)INFINITY, zero[3] = {0, 0, 0};
  float v[3];
  int k, same;
#define UNTOUCHED(call, what) \
  do { \
    for (k = 0; k < 64 * 64; ++k) \
      sh[k] = pre[k] = (float)k; \
    call; \
    same = memcmp(sh, pre, sizeof(float) * 64 * 64) == 0; \
    TL_CHECK(same, "%s changed io_sh", what); \
  } while (0)
  UNTOUCHED(shl_ssf_vpl_sh(5, x, nx, x, ny, 1.0f, 0.0f, sh), "x == y");
  UNTOUCHED(shl_ssf_vpl_sh(5, x, nx, x, ny, 1.0f, 0.5f, sh), "x == y with a clamp");
  UNTOUCHED(shl_ssf_vpl_sh(5, x, nx, y, ny, 0.0f, 0.0f, sh), "flux 0");
  UNTOUCHED(shl_ssf_vpl_sh(5, x, nx, y, ny, -1.0f, 0.0f, sh), "flux < 0");
  UNTOUCHED(shl_ssf_vpl_sh(5, x, nx, y, ny, nan, 0.0f, sh), "flux NaN");
  UNTOUCHED(shl_ssf_vpl_sh(5, x, nx, y, ny, inf, 0.0f, sh), "flux inf");
  UNTOUCHED(shl_ssf_vpl_sh(5, x, nx, y, nx, 1.0f, 0.0f, sh), "VPL facing away");
  UNTOUCHED(shl_ssf_vpl_sh(5, x, ny, y, ny, 1.0f, 0.0f, sh), "VPL below the receiver's plane");
  UNTOUCHED(shl_ssf_vpl_sh(0, x, nx, y, ny, 1.0f, 0.0f, sh), "n = 0");
  UNTOUCHED(shl_ssf_vpl_sh(-3, x, nx, y, ny, 1.0f, 0.0f, sh), "n < 0");
  v[0] = nan;
  v[1] = v[2] = 0.0f;
  UNTOUCHED(shl_ssf_vpl_sh(5, v, nx, y, ny, 1.0f, 0.0f, sh), "x NaN");
  UNTOUCHED(shl_ssf_vpl_sh(5, x, nx, v, ny, 1.0f, 0.0f, sh), "y NaN");
  v[0] = inf;
  UNTOUCHED(shl_ssf_vpl_sh(5, x, nx, v, ny, 1.0f, 0.0f, sh), "y infinite");
  TL_CHECK(shl_ssf_vpl_irradiance(x, nx, nx, x, ny, 1.0f, 0.0f) == 0.0f, "irradiance x == y");
  v[0] = nan;
  TL_CHECK(shl_ssf_vpl_irradiance(v, nx, nx, y, ny, 1.0f, 0.0f) == 0.0f, "irradiance x NaN");
  /* nx = 0: no horizon test; ny = 0: +z (faces away from x below it, towards x above it) */
  {
    const float below[3] = {0, 0, -1};
    float e1 = shl_ssf_vpl_irradiance(x, zero, below, below, nx, 1.0f, 0.0f);
    float e0 = shl_ssf_vpl_irradiance(x, nx, below, below, nx, 1.0f, 0.0f);
    float ez = shl_ssf_vpl_irradiance(x, zero, below, below, zero, 1.0f, 0.0f);
    TL_CHECK(fabsf(e1 - 0.31830988f) < 1e-7f && e0 == 0.0f && fabsf(ez - e1) < 1e-7f,
             "nx = 0 / ny = 0: %.9g %.9g %.9g", (double)e1, (double)e0, (double)ez);
  }
  /* clamp: d = 0.1 < dmin = 0.5 gives flux / (pi dmin^2); dmin NaN / < 0: no clamp */
  {
    const float yc[3] = {0, 0, 0.1f};
    float c = shl_ssf_vpl_irradiance(x, nx, nx, yc, ny, 1.0f, 0.5f);
    float u = shl_ssf_vpl_irradiance(x, nx, nx, yc, ny, 1.0f, nan);
    float un = shl_ssf_vpl_irradiance(x, nx, nx, yc, ny, 1.0f, -2.0f);
    float big = shl_ssf_vpl_irradiance(x, nx, nx, y, ny, 1.0f, 0.5f); /* d = 1 > dmin */
    TL_CHECK(fabsf(c - 1.2732395f) < 2e-7f, "clamped %.9g vs 4/pi", (double)c);
    TL_CHECK(fabsf(u - 31.830988f) < 5e-6f && u == un, "no clamp %.9g %.9g", (double)u, (double)un);
    TL_CHECK(fabsf(big - 0.31830988f) < 1e-7f, "beyond the clamp %.9g", (double)big);
  }
  /* tiny distances without a clamp: finite (|y - x| taken as >= 1e-18) */
  {
    const float yt[3] = {0, 0, 1e-30f};
    float e = shl_ssf_vpl_irradiance(x, nx, nx, yt, ny, 1.0f, 0.0f);
    TL_CHECK(isfinite(e) && fabsf(e / 3.1830988e35f - 1.0f) < 1e-6f, "d = 1e-30: %.9g", (double)e);
  }
  /* n above SHLIGHT_MAX_BANDS: clamped to 64, in debug and release builds alike */
  {
    for (k = 0; k < 65 * 65; ++k)
      sh[k] = pre[k] = 0.0f;
    shl_ssf_vpl_sh(65, x, nx, y, ny, 1.0f, 0.0f, sh);
    shl_ssf_vpl_sh(64, x, nx, y, ny, 1.0f, 0.0f, pre);
    TL_CHECK(memcmp(sh, pre, sizeof(float) * 65 * 65) == 0, "n = 65 is not n = 64");
    TL_CHECK(shl_ssf_irradiance(0, sh, nx) == 0.0f, "irradiance n = 0");
  }
#undef UNTOUCHED
}

/* The spot-light VPL flux Phi = kd I dw (>>ssf): the VPLs of a w x w pinhole map through a cone
   hitting a plane reflect, summed, kd times the cone's flux I 2 pi (1 - cos a) (the texels whose
   centre lies in the cone; the map's edge error shrinks as 1/w). Checks the documented texel
   solid angle dw = (2 tan(a)/w)^2 / (1 + u^2 + v^2)^(3/2). */
static void test_spot_texel_solid_angle(void) {
  const int ws[] = {64, 256, 1024};
  const double a = 0.6, ta = tan(a), exact = 2.0 * M_PI * (1.0 - cos(a));
  double prev = 1e30;
  int k;
  for (k = 0; k < 3; ++k) {
    int w = ws[k], i, j;
    double s = 0, h = 2.0 * ta / w, err;
    for (j = 0; j < w; ++j)
      for (i = 0; i < w; ++i) {
        double u = ((i + 0.5) * h - ta), v = ((j + 0.5) * h - ta), r2 = 1 + u * u + v * v;
        if (1.0 / sqrt(r2) >= cos(a)) s += h * h / (r2 * sqrt(r2));
      }
    err = fabs(s - exact) / exact;
    printf("  w %4d: sum of texel solid angles in the cone %.7f vs 2 pi (1 - cos a) %.7f (rel "
           "%.2g)\n",
           w, s, exact, err);
    TL_CHECK(err < 4.0 / w && err <= prev, "w %d: %.3g", w, err);
    prev = err;
  }
}

int main(void) {
  TL_RUN(test_vpl_sh_projection);
  TL_RUN(test_vpl_irradiance_exact);
  TL_RUN(test_vpl_flux_conservation);
  TL_RUN(test_sh_irradiance_convergence);
  TL_RUN(test_many_vpls);
  TL_RUN(test_irradiance_band_limited);
  TL_RUN(test_interleave_partition);
  TL_RUN(test_weight_limits);
  TL_RUN(test_bad_input);
  TL_RUN(test_spot_texel_solid_angle);
  return tl_summary();
}
