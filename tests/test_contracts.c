/* test_contracts.c - regression tests for the out-of-domain contracts of the zonal, light,
 * grid, lobe/SG, ZH convolution, HVL and SSF functions (docs/contracts.md), and for the
 * restructurings that keep every public function under 16 KB of stack.
 *
 * Build: make build/tests/test_contracts; ends with "N passed, N failed" (about a second).
 *
 * References (none shares code with the kernel under test):
 *  - closed forms in long double (1 / (pi r^2), d g (1 + g^2/3), the lobe product's mu at its
 *    own axis);
 *  - scale invariance: a triangle's solid angle and SH at 1e15 / 1e21 against the same
 *    triangle at scale 1 (the exact results are equal);
 *  - shl_sh_eval_accurate (renormalised in double) and shl_zh_rotate + shl_sh_dot for the
 *    streamed (n > 45) contractions;
 *  - per-coefficient kernels (shl_grid_trilinear / _taylor / _hermite on the full gathered
 *    corners) for the chunked shl_grid_sample: the same bits.
 * Each test is named after the finding it guards. */
#define SHLIGHT_IMPLEMENTATION
#include "../shlight.h"
#include "tl.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int finite_f(float v) {
  return isfinite(v) != 0;
}

/* ---- shl_lobe_product: float-normalised axes, huge exponents -------------------------- */
static void test_lobe_product_float_axes_mu_le_1(void) {
  /* axes normalised in float: |r|^2 - 1 ~ 5e-8, the finding's case (mu 3.56 at n2 = 1e8,
     +inf for 1e10..1e30) */
  float r1[3] = {0.36f, 0.48f, 0.8f}, r2[3], rp[3], np;
  double worst = 0.0;
  int i, j, bad = 0;
  float ns[] = {1.0f,  50.0f, 1e4f,  1e6f,  1e8f,  1e10f,   1e15f,
                1e20f, 1e25f, 1e29f, 1e30f, 3e38f, INFINITY};
  for (i = 0; i < 16; ++i) {
    /* r2: r1 turned by a tiny angle, normalised in float (a renderer's typical axis) */
    double a = 1e-4 * i, x = 0.36 + a, y = 0.48 - 0.5 * a, z = 0.8, l = sqrt(x * x + y * y + z * z);
    r2[0] = (float)(x / l);
    r2[1] = (float)(y / l);
    r2[2] = (float)(z / l);
    for (j = 0; j < (int)(sizeof ns / sizeof ns[0]); ++j) {
      float mu = shl_lobe_product(r1, ns[j], r2, ns[j], rp, &np);
      float mu2 = shl_lobe_product(r1, 1.0f, r2, ns[j], rp, &np);
      if (!(mu >= 0.0f && mu <= 1.0f) || !(mu2 >= 0.0f && mu2 <= 1.0f) || !finite_f(np)) bad++;
      if (!finite_f(rp[0]) || !finite_f(rp[1]) || !finite_f(rp[2])) bad++;
      if (mu > worst) worst = mu;
    }
  }
  /* identical axes: the product of two lobes at their common axis is exactly 1 */
  for (j = 0; j < 5; ++j) { /* n <= 1e8 (the finding's n): beyond 1e9 the lobe is narrower
                               than the double rounding of the axis */
    float mu = shl_lobe_product(r1, ns[j], r1, ns[j], rp, &np);
    TL_CHECK(fabsf(mu - 1.0f) <= 1e-6f, "identical float axes, n = %g: mu = %.9g (exact 1)",
             (double)ns[j], (double)mu);
  }
  printf("  lobe_product float axes: max mu %.9g over n up to inf\n", worst);
  TL_CHECK(bad == 0, "%d cases with mu outside [0, 1] or non-finite np / rp", bad);
}

static void test_lobe_product_mu_closed_form(void) {
  /* mu = (rp.r1)^n1 (rp.r2)^n2 at the returned axis, in long double from the unit axes */
  float r1[3] = {0.0f, 0.0f, 1.0f}, r2[3] = {0.6f, 0.0f, 0.8f}, rp[3], np;
  float n1 = 30.0f, n2 = 1e6f;
  float mu = shl_lobe_product(r1, n1, r2, n2, rp, &np);
  long double l =
      sqrtl((long double)rp[0] * rp[0] + (long double)rp[1] * rp[1] + (long double)rp[2] * rp[2]);
  long double c1 = rp[2] / l, c2 = (0.6L * rp[0] + 0.8L * rp[2]) / l;
  long double want = powl(c1, n1) * powl(c2, n2);
  /* rp is rounded to float (0.5 ulp ~ 6e-8 of angle), n2 = 1e6 turns that into ~6e-2 of mu
     relative at most; the kernel's mu is for the shli_real axis */
  TL_CHECK(fabsl(mu - want) <= 0.1L * want + 1e-30L, "mu %.9g vs %.9Lg", (double)mu, want);
}

static void test_lobe_product_degenerate_axes(void) {
  float z[3] = {0, 0, 0}, r[3] = {0, 0, 1}, nan3[3] = {NAN, 0, 0}, rp[3], np;
  float mu = shl_lobe_product(z, 10.0f, r, 10.0f, rp, &np); /* zero axis: +z */
  TL_CHECK(fabsf(mu - 1.0f) <= 1e-6f && rp[2] == 1.0f, "zero r1 as +z: mu %g rp.z %g", (double)mu,
           (double)rp[2]);
  mu = shl_lobe_product(nan3, 10.0f, r, 10.0f, rp, &np);
  TL_CHECK(finite_f(mu) && mu >= 0.0f && mu <= 1.0f, "NaN r1: mu %g", (double)mu);
  mu = shl_lobe_product(r, NAN, r, 10.0f, rp, &np);
  TL_CHECK(mu == 0.0f && np == 0.0f, "NaN n1: mu %g np %g", (double)mu, (double)np);
  mu = shl_lobe_product(r, -3.0f, r, 10.0f, rp, &np);
  TL_CHECK(mu == 0.0f && np == 0.0f, "negative n1: mu %g np %g", (double)mu, (double)np);
}

/* ---- shl_lobe_to_sg / shl_sg_to_lobe: the argument inf --------------------------------- */
static void test_sg_lobe_inf_argument(void) {
  float v[] = {1e-30f, 1.0f, 1e7f, 1e29f, 1e30f, FLT_MAX};
  int i;
  for (i = 0; i < 6; ++i) {
    float l = shl_lobe_to_sg(v[i]), n = shl_sg_to_lobe(v[i] + 1.0f);
    TL_CHECK(finite_f(l) && l > 0.0f, "lobe_to_sg(%g) = %g", (double)v[i], (double)l);
    TL_CHECK(finite_f(n), "sg_to_lobe(%g) = %g", (double)v[i] + 1.0, (double)n);
  }
  /* documented: +inf -> +inf (the delta-lobe limit), NaN -> 0, -inf -> 0 */
  TL_CHECK(shl_lobe_to_sg(INFINITY) == INFINITY, "lobe_to_sg(inf)");
  TL_CHECK(shl_sg_to_lobe(INFINITY) == INFINITY, "sg_to_lobe(inf)");
  TL_CHECK(shl_lobe_to_sg(NAN) == 0.0f && shl_sg_to_lobe(NAN) == 0.0f, "NaN -> 0");
  TL_CHECK(shl_lobe_to_sg(-INFINITY) == 0.0f && shl_sg_to_lobe(-INFINITY) == 0.0f, "-inf -> 0");
  /* large finite: lambda ~ n + ln2/2 (relative 1e-7 at 1e7) */
  TL_CHECK(fabs((double)shl_lobe_to_sg(1e7f) - (1e7 + 0.34657359)) <= 2.0, "lambda(1e7)");
}

/* ---- shl_zh_window: Lanczos width inf --------------------------------------------------- */
static void test_zh_window_lanczos_width_inf(void) {
  float zh[16];
  int i, bad = 0;
  for (i = 0; i < 16; ++i)
    zh[i] = 1.0f;
  shl_zh_window(16, SHLIGHT_WINDOW_LANCZOS, INFINITY, zh);
  for (i = 0; i < 16; ++i)
    if (zh[i] != 1.0f) bad++;
  TL_CHECK(bad == 0, "Lanczos width inf: %d bands not 1 (zh[1] = %g)", bad, (double)zh[1]);
  for (i = 0; i < 16; ++i)
    zh[i] = 1.0f;
  shl_zh_window(16, SHLIGHT_WINDOW_HANNING, INFINITY, zh);
  for (i = 0; i < 16; ++i)
    if (zh[i] != 1.0f) bad++;
  TL_CHECK(bad == 0, "Hanning width inf: %d bands not 1", bad);
  /* huge finite widths: sinc(l / w) = 1 - (pi l / w)^2 / 6: 1 in float */
  for (i = 0; i < 16; ++i)
    zh[i] = 1.0f;
  shl_zh_window(16, SHLIGHT_WINDOW_LANCZOS, FLT_MAX, zh);
  for (i = 0; i < 16; ++i)
    if (zh[i] != 1.0f) bad++;
  TL_CHECK(bad == 0, "Lanczos width FLT_MAX: %d bands not 1", bad);
  /* the ordinary case against sin(pi t) / (pi t) in long double */
  for (i = 0; i < 16; ++i)
    zh[i] = 1.0f;
  shl_zh_window(16, SHLIGHT_WINDOW_LANCZOS, 17.0f, zh);
  for (i = 1; i < 16; ++i) {
    long double t = i / 17.0L,
                want = sinl(3.14159265358979323846L * t) / (3.14159265358979323846L * t);
    TL_CHECK(fabsl(zh[i] - want) <= 1e-7L, "Lanczos l=%d: %g vs %Lg", i, (double)zh[i], want);
  }
}

/* ---- triangle solid angle / light at 1e15 / 1e21 ---------------------------------------- */
static void scaled_tri(double s, float x[3], float p0[3], float p1[3], float p2[3]) {
  /* a triangle at distance ~3 of x = the origin, all scaled by s (exact in float: powers of 10
     are not, so the reference is the scaled float triangle seen at scale 1 in long double) */
  const double b[4][3] = {{0.0, 0.0, 0.0}, {1.0, 0.25, 3.0}, {-0.5, 1.0, 3.0}, {-0.25, -0.75, 3.5}};
  int k;
  for (k = 0; k < 3; ++k) {
    x[k] = (float)(s * b[0][k]);
    p0[k] = (float)(s * b[1][k]);
    p1[k] = (float)(s * b[2][k]);
    p2[k] = (float)(s * b[3][k]);
  }
}

static long double solid_angle_ld(const float x[3], const float p0[3], const float p1[3],
                                  const float p2[3]) {
  long double r[3][3], l[3], nm, dn;
  const float *p[3];
  int i, k;
  long double m = 0.0L;
  p[0] = p0;
  p[1] = p1;
  p[2] = p2;
  for (i = 0; i < 3; ++i)
    for (k = 0; k < 3; ++k) {
      r[i][k] = (long double)p[i][k] - x[k];
      if (fabsl(r[i][k]) > m) m = fabsl(r[i][k]);
    }
  for (i = 0; i < 3; ++i)
    for (k = 0; k < 3; ++k)
      r[i][k] /= m;
  for (i = 0; i < 3; ++i)
    l[i] = sqrtl(r[i][0] * r[i][0] + r[i][1] * r[i][1] + r[i][2] * r[i][2]);
  nm = r[0][0] * (r[1][1] * r[2][2] - r[1][2] * r[2][1]) -
       r[0][1] * (r[1][0] * r[2][2] - r[1][2] * r[2][0]) +
       r[0][2] * (r[1][0] * r[2][1] - r[1][1] * r[2][0]);
  dn = l[0] * l[1] * l[2] + (r[0][0] * r[1][0] + r[0][1] * r[1][1] + r[0][2] * r[1][2]) * l[2] +
       (r[0][0] * r[2][0] + r[0][1] * r[2][1] + r[0][2] * r[2][2]) * l[1] +
       (r[1][0] * r[2][0] + r[1][1] * r[2][1] + r[1][2] * r[2][2]) * l[0];
  return 2.0L * atan2l(nm, dn);
}

static void test_triangle_solid_angle_1e15_1e21(void) {
  double sc[] = {1e-30, 1e-12, 1e-6, 1.0, 1e6, 1e12, 1e15, 1e18, 1e21, 1e30, 1e36};
  int i;
  for (i = 0; i < (int)(sizeof sc / sizeof sc[0]); ++i) {
    float x[3], p0[3], p1[3], p2[3];
    float om;
    long double want;
    scaled_tri(sc[i], x, p0, p1, p2);
    om = shl_triangle_solid_angle(x, p0, p1, p2);
    want = solid_angle_ld(x, p0, p1, p2);
    TL_CHECK(fabsl(om - want) <= 1e-6L * fabsl(want) + 1e-12L, "scale %g: Omega %.9g vs %.9Lg",
             sc[i], (double)om, want);
  }
}

static void test_triangle_light_1e15_1e21(void) {
  /* the sphere model depends only on ratios: the SH at scale s equals the SH at scale 1 */
  double sc[] = {1e-15, 1e12, 1e15, 1e18, 1e21, 1e30};
  float x[3], p0[3], p1[3], p2[3], ref[16], sh[16], g[16][3], refg[16][3];
  int i, k;
  scaled_tri(1.0, x, p0, p1, p2);
  shl_triangle_light(4, x, p0, p1, p2, ref);
  shl_triangle_light_grad(4, x, p0, p1, p2, sh, refg);
  for (i = 0; i < (int)(sizeof sc / sizeof sc[0]); ++i) {
    double worst = 0.0, gw = 0.0;
    scaled_tri(sc[i], x, p0, p1, p2);
    shl_triangle_light(4, x, p0, p1, p2, sh);
    for (k = 0; k < 16; ++k)
      worst = fmax(worst, fabs((double)sh[k] - ref[k]));
    TL_CHECK(worst <= 2e-6 && fabs((double)ref[0]) > 1e-3, "scale %g: max |SH - SH(1)| %.3g", sc[i],
             worst);
    shl_triangle_light_grad(4, x, p0, p1, p2, sh, g);
    for (k = 0; k < 16; ++k) {
      int a;
      worst = fmax(worst, fabs((double)sh[k] - ref[k]));
      /* the gradient scales as 1 / s */
      for (a = 0; a < 3; ++a)
        gw = fmax(gw, fabs((double)g[k][a] * sc[i] - refg[k][a]));
    }
    TL_CHECK(worst <= 2e-6 && gw <= 1e-5, "grad scale %g: SH %.3g, s grad %.3g", sc[i], worst, gw);
  }
}

/* ---- shl_zh_rotate: zh = 1e38 ------------------------------------------------------------ */
static void test_zh_rotate_zh_1e38(void) {
  float zh[8], big[64], ref[64], d[3] = {0.3f, -0.5f, 0.8f};
  int i, bad = 0;
  for (i = 0; i < 8; ++i)
    zh[i] = 1.0f;
  shl_zh_rotate(8, zh, d, ref);
  for (i = 0; i < 8; ++i)
    zh[i] = 1e38f;
  shl_zh_rotate(8, zh, d, big);
  for (i = 0; i < 64; ++i) {
    double want = (double)ref[i] * 1e38;
    if (!finite_f(big[i]) || fabs((double)big[i] - want) > 1e-6 * 1e38) bad++;
  }
  TL_CHECK(bad == 0, "zh = 1e38: %d of 64 values non-finite or off (out[0] = %g)", bad,
           (double)big[0]);
  for (i = 0; i < 8; ++i)
    zh[i] = FLT_MAX;
  shl_zh_rotate(8, zh, d, big);
  for (i = 0; i < 64; ++i)
    if (!finite_f(big[i])) bad++;
  TL_CHECK(bad == 0, "zh = FLT_MAX: %d non-finite", bad);
}

/* ---- shl_hvl_geometric: r <= 1e-20 ---------------------------------------------------------- */
static void test_hvl_geometric_r_1e20(void) {
  float x[3] = {0, 0, 0}, nx[3] = {0, 0, 1}, y[3] = {0.0f, 0.0f, 2.0f}, ny[3] = {0, 0, -1};
  float rs[] = {1e-10f, 1e-19f, 3e-20f, 1e-20f, 1e-30f, 1e-38f, 1e-45f};
  int i;
  for (i = 0; i < 7; ++i) {
    float gv = shl_hvl_geometric(x, nx, y, ny, rs[i], 1);
    long double want = 1.0L / (3.14159265358979323846L * (long double)rs[i] * rs[i]);
    if (want > FLT_MAX) {
      TL_CHECK(gv == FLT_MAX, "r = %g: %g (saturates at FLT_MAX)", (double)rs[i], (double)gv);
    } else {
      TL_CHECK(fabsl(gv - want) <= 1e-6L * want, "r = %g: %g vs %Lg", (double)rs[i], (double)gv,
               want);
    }
    gv = shl_hvl_geometric(x, nx, y, ny, rs[i], 0);
    TL_CHECK(finite_f(gv), "smoothstep, r = %g: %g", (double)rs[i], (double)gv);
  }
  /* oblique: cj H / (pi r^2) with cj ~ 1e-3 fits in float at r = 1e-20 */
  {
    float y2[3] = {1.0f, 0.0f, 1e-3f}, ny2[3] = {0, 0, -1};
    float gv = shl_hvl_geometric(x, nx, y2, ny2, 1e-20f, 1);
    TL_CHECK(finite_f(gv) && gv > 1e36f && gv < FLT_MAX, "oblique r = 1e-20: %g", (double)gv);
  }
}

/* ---- shl_hvl_radius_fov: d ~ 3e38 ------------------------------------------------------------ */
static void test_hvl_radius_fov_d_3e38(void) {
  float ds[] = {1.0f, 1e30f, 1e38f, 3e38f, FLT_MAX};
  float fovs[] = {0.0f, 1e-3f, 0.2f, 0.5f, 1.0f, 1e10f, 1e30f};
  int i, j, bad = 0;
  for (i = 0; i < 5; ++i)
    for (j = 0; j < 7; ++j) {
      long double g = 1.41421356237309504880L * fovs[j] / 2.0L;
      long double want = (long double)ds[i] * (g + g * g * g / 3.0L);
      float r = shl_hvl_radius_fov(ds[i], fovs[j], 4);
      float rt = shl_hvl_radius_fov_tan(ds[i], fovs[j], 4);
      if (want > FLT_MAX) {
        if (r != FLT_MAX) bad++;
      } else if (!(fabsl(r - want) <= 1e-6L * want)) {
        bad++;
      }
      if (!finite_f(rt)) bad++;
    }
  TL_CHECK(bad == 0, "%d cases off (exact fits: the value; above FLT_MAX: FLT_MAX)", bad);
  TL_CHECK(shl_hvl_radius_fov(INFINITY, 0.5f, 1) == FLT_MAX, "d = inf: FLT_MAX");
  TL_CHECK(shl_hvl_radius_fov_tan(INFINITY, 0.5f, 1) == FLT_MAX, "tan, d = inf: FLT_MAX");
  TL_CHECK(shl_hvl_radius_fov(3e38f, 0.0f, 1) == 0.0f, "fov = 0: 0");
}

/* ---- 16 KB stack: the streamed contractions for n > 45 against the buffered definition ------ */
static void test_stack_streamed_conv_zh_n46_64(void) {
  static float sh[4096], zh[64], rot[4096];
  float w[3] = {0.2f, -0.7f, 0.4f};
  int n, i;
  for (i = 0; i < 4096; ++i)
    sh[i] = (float)sin(0.37 * i + 0.1);
  for (i = 0; i < 64; ++i)
    zh[i] = (float)(1.0 / (1.0 + 0.1 * i));
  for (n = 44; n <= 64; n += 4) {
    float c = shl_sh_conv_zh(n, sh, zh, w);
    double want, scale = 0.0;
    shl_zh_rotate(n, zh, w, rot);
    want = (double)shl_sh_dot(n, sh, rot);
    for (i = 0; i < n * n; ++i)
      scale += fabs((double)sh[i] * rot[i]);
    TL_CHECK(fabs(c - want) <= 4e-7 * scale, "n=%d: conv_zh %.9g vs dot(rotate) %.9g (scale %g)", n,
             (double)c, want, scale);
  }
}

static void test_stack_streamed_hvl_ssf_batch_n64(void) {
  static float f[4096], y[4096], io[4096], io0[4096], bt[3 * 4096];
  float dir[3] = {-0.3f, 0.5f, 0.81f}, u[3];
  double l = sqrt(0.09 + 0.25 + 0.81 * 0.81), maxd = 0.0, s = 0.0, scale = 0.0;
  int i, n;
  u[0] = (float)(-0.3 / l);
  u[1] = (float)(0.5 / l);
  u[2] = (float)(0.81 / l);
  for (i = 0; i < 4096; ++i)
    f[i] = (float)cos(0.11 * i);
  for (n = 46; n <= 64; n += 18) {
    float e;
    double yref;
    shl_sh_eval_accurate(n, u, y);
    s = 0.0;
    scale = 0.0;
    for (i = 0; i < n * n; ++i) {
      s += (double)f[i] * y[i];
      scale += fabs((double)f[i] * y[i]);
    }
    e = shl_hvl_emission(n, f, dir);
    TL_CHECK(fabs(e - s) <= 4e-7 * scale, "hvl_emission n=%d: %.9g vs %.9g", n, (double)e, s);
    /* ssf: io += e Y(w) with w from x to y */
    {
      float x[3] = {0, 0, 0}, nx[3] = {0, 0, 0}, py[3], ny[3];
      for (i = 0; i < 3; ++i) {
        py[i] = 2.0f * u[i];
        ny[i] = -u[i];
      }
      for (i = 0; i < n * n; ++i)
        io[i] = io0[i] = (float)(0.01 * i);
      shl_ssf_vpl_sh(n, x, nx, py, ny, 4.0f * 3.14159265f, 0.0f, io);
      /* e = flux cos / (pi d^2) = 4 pi / (4 pi) = 1 */
      maxd = 0.0;
      for (i = 0; i < n * n; ++i)
        maxd = fmax(maxd, fabs((double)io[i] - ((double)io0[i] + y[i])));
      TL_CHECK(maxd <= 2e-5 * (1.0 + 0.01 * n * n), "ssf_vpl_sh n=%d: max diff %.3g", n, maxd);
    }
    /* batch with count 3 (< any SIMD width): strided, every value against the accurate one */
    {
      float xs[3], ys[3], zs[3];
      for (i = 0; i < 3; ++i) {
        xs[i] = u[0];
        ys[i] = u[1];
        zs[i] = u[2];
      }
      shl_sh_eval_batch(n, 3, xs, ys, zs, bt);
      maxd = 0.0;
      for (i = 0; i < n * n; ++i) {
        int j;
        for (j = 0; j < 3; ++j)
          maxd = fmax(maxd, fabs((double)bt[i * 3 + j] - y[i]));
      }
      TL_CHECK(maxd <= 2e-5, "batch n=%d count 3: max diff %.3g", n, maxd);
    }
    yref = 0.0;
    (void)yref;
  }
}

/* ---- 16 KB stack: shl_grid_sample in chunks, the same bits as one call ----------------------- */
static void test_stack_grid_sample_chunked_same_bits(void) {
  int n, method, bad = 0;
  for (n = 1; n <= 20; n += (n < 9 ? 1 : 11)) {
    shl_grid g;
    int nn = n * n, nv = 2 * 3 * 2, v, i, c;
    float *sh = (float *)malloc(sizeof(float) * (size_t)(nv * nn));
    float(*gr)[3] = (float(*)[3])malloc(sizeof(float[3]) * (size_t)(nv * nn));
    float *c8 = (float *)malloc(sizeof(float) * (size_t)(8 * nn));
    float(*g8)[3] = (float(*)[3])malloc(sizeof(float[3]) * (size_t)(8 * nn));
    float *out = (float *)malloc(sizeof(float) * (size_t)nn);
    float *ref = (float *)malloc(sizeof(float) * (size_t)nn);
    float p[3] = {0.7f, 1.3f, 0.25f}, f[3];
    if (!sh || !gr || !c8 || !g8 || !out || !ref) abort();
    memset(&g, 0, sizeof g);
    g.n = n;
    g.dims[0] = 2;
    g.dims[1] = 3;
    g.dims[2] = 2;
    g.spacing[0] = g.spacing[1] = g.spacing[2] = 1.0f;
    for (v = 0; v < nv * nn; ++v) {
      sh[v] = (float)sin(0.3 * v);
      gr[v][0] = (float)cos(0.2 * v);
      gr[v][1] = (float)sin(0.7 * v);
      gr[v][2] = (float)cos(0.9 * v);
    }
    /* the cell of p: (0..1, 1..2, 0..1), f = (0.7, 0.3, 0.25) */
    f[0] = 0.7f;
    f[1] = (float)((double)1.3f - 1.0);
    f[2] = 0.25f;
    for (c = 0; c < 8; ++c) {
      int ix = c & 1, iy = 1 + ((c >> 1) & 1), iz = (c >> 2) & 1;
      size_t vv = (size_t)ix + 2u * ((size_t)iy + 3u * (size_t)iz);
      for (i = 0; i < nn; ++i) {
        c8[c * nn + i] = sh[vv * (size_t)nn + (size_t)i];
        g8[c * nn + i][0] = gr[vv * (size_t)nn + (size_t)i][0];
        g8[c * nn + i][1] = gr[vv * (size_t)nn + (size_t)i][1];
        g8[c * nn + i][2] = gr[vv * (size_t)nn + (size_t)i][2];
      }
    }
    for (method = SHLIGHT_GRID_TRILINEAR; method <= SHLIGHT_GRID_HERMITE; ++method) {
      shl_result rc = shl_grid_sample(&g, sh, (const float(*)[3])gr, p, method, out);
      if (method == SHLIGHT_GRID_TRILINEAR) shl_grid_trilinear(n, c8, f, ref);
      if (method == SHLIGHT_GRID_TAYLOR)
        shl_grid_taylor(n, c8, (const float(*)[3])g8, f, g.spacing, ref);
      if (method == SHLIGHT_GRID_HERMITE)
        shl_grid_hermite(n, c8, (const float(*)[3])g8, f, g.spacing, ref);
      if (rc != SHLIGHT_OK || memcmp(out, ref, sizeof(float) * (size_t)nn) != 0) {
        bad++;
        printf("  n=%d method %d: rc %d, chunked != one call\n", n, method, (int)rc);
      }
    }
    free(sh);
    free(gr);
    free(c8);
    free(g8);
    free(out);
    free(ref);
  }
  TL_CHECK(bad == 0, "%d (n, method) pairs differ from the one-call kernel", bad);
}

/* shl_result_string: every shl_result has its own string, starting with its enumerator's name;
 * anything else is "unknown shl_result"; never NULL. */
static void test_result_string(void) {
  static const shl_result codes[] = {
      SHLIGHT_OK,       SHLIGHT_EINVAL, SHLIGHT_ENOMEM,     SHLIGHT_ELENGTH,   SHLIGHT_EMAGIC,
      SHLIGHT_EVERSION, SHLIGHT_EDIMS,  SHLIGHT_ENONFINITE, SHLIGHT_ECHECKSUM, SHLIGHT_ESTORAGE};
  static const char *names[] = {
      "SHLIGHT_OK:",        "SHLIGHT_EINVAL:",   "SHLIGHT_ENOMEM:", "SHLIGHT_ELENGTH:",
      "SHLIGHT_EMAGIC:",    "SHLIGHT_EVERSION:", "SHLIGHT_EDIMS:",  "SHLIGHT_ENONFINITE:",
      "SHLIGHT_ECHECKSUM:", "SHLIGHT_ESTORAGE:"};
  int i, j, nc = (int)(sizeof codes / sizeof codes[0]);
  for (i = 0; i < nc; ++i) {
    const char *t = shl_result_string(codes[i]);
    TL_CHECK(t != NULL && strncmp(t, names[i], strlen(names[i])) == 0, "code %d: %s", (int)codes[i],
             t ? t : "(null)");
    for (j = 0; j < i; ++j)
      TL_CHECK(strcmp(t, shl_result_string(codes[j])) != 0, "codes %d and %d share a string", i, j);
  }
  TL_CHECK(strcmp(shl_result_string((shl_result)42), "unknown shl_result") == 0, "unknown code");
  TL_CHECK(strcmp(shl_result_string((shl_result)-100), "unknown shl_result") == 0, "unknown code");
}

int main(void) {
  TL_RUN(test_result_string);
  TL_RUN(test_lobe_product_float_axes_mu_le_1);
  TL_RUN(test_lobe_product_mu_closed_form);
  TL_RUN(test_lobe_product_degenerate_axes);
  TL_RUN(test_sg_lobe_inf_argument);
  TL_RUN(test_zh_window_lanczos_width_inf);
  TL_RUN(test_triangle_solid_angle_1e15_1e21);
  TL_RUN(test_triangle_light_1e15_1e21);
  TL_RUN(test_zh_rotate_zh_1e38);
  TL_RUN(test_hvl_geometric_r_1e20);
  TL_RUN(test_hvl_radius_fov_d_3e38);
  TL_RUN(test_stack_streamed_conv_zh_n46_64);
  TL_RUN(test_stack_streamed_hvl_ssf_batch_n64);
  TL_RUN(test_stack_grid_sample_chunked_same_bits);
  return tl_summary();
}
