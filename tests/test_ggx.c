/* test_ggx.c - shl_polygon_ggx (GGX polygon lights, >>edge) against tests/ref/arearef.h: long
 * double adaptive cubature of D G2 / (4 n.v) over the horizon-clipped polygon, which shares no
 * formula with the kernel (no half vectors, no Stokes form, no Taylor model).
 *  - the research sampler (tests/ref/ggxcases.h) at the 7 roughness
 *    values of the LTC comparison, 24 quads each: median relative error where the light gives
 *    >= 5 % of the directional albedo (asserted below LTC's published median and at ~3x the
 *    value measured here), max error / albedo;
 *  - named hard cases: horizon-straddling lights, grazing views (85-88 deg), large lights,
 *    slivers, a light filling the hemisphere, a rotated frame, triangles, non-convex 8-gons;
 *  - lights entirely below the horizon give exactly 0; winding and vertex-order invariance;
 *    degenerate inputs.
 * Errors are measured in the kernel's float output against the long double reference.
 * Build: make build/tests/test_ggx. Run: build/tests/test_ggx (ends "N passed, N failed"). */
#define SHLIGHT_IMPLEMENTATION
#include "../shlight.h"

#include "tl.h"
#include "ref/arearef.h"
#define GGXC_HARD_CASES
#include "ref/ggxcases.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const double ZN[3] = {0, 0, 1};

static int cmpd(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return x < y ? -1 : x > y;
}

/* kernel on double input (rounded to float, like a caller would), nrm and view as given */
static double kern(const double (*q)[3], int nv, const double nrm[3], const double view[3],
                   double alpha) {
  float fv[64][3], fn[3], fw[3];
  int i, k;
  for (i = 0; i < nv; ++i)
    for (k = 0; k < 3; ++k)
      fv[i][k] = (float)q[i][k];
  for (k = 0; k < 3; ++k)
    fn[k] = (float)nrm[k], fw[k] = (float)view[k];
  return shl_polygon_ggx((const float(*)[3])fv, nv, fn, fw, (float)alpha);
}
/* the reference evaluated on the float-rounded input the kernel saw */
static double ref(const double (*q)[3], int nv, const double nrm[3], const double view[3],
                  double alpha, double *alb) {
  double rq[64][3], rn[3], rv[3];
  int i, k;
  for (i = 0; i < nv; ++i)
    for (k = 0; k < 3; ++k)
      rq[i][k] = (double)(float)q[i][k];
  for (k = 0; k < 3; ++k)
    rn[k] = (double)(float)nrm[k], rv[k] = (double)(float)view[k];
  if (alb) *alb = (double)arref_ggx_albedo(rn, rv, alpha);
  return (double)arref_polygon_ggx((const double(*)[3])rq, nv, rn, rv, alpha);
}

/* The research sampler, 24 quads per roughness. Measured here (gcc -O2, x86-64), median rel.
   error on visible configurations / max error over albedo:
     roughness 0.05: 1.7e-7 / 9.8e-4   0.1: 5.1e-6 / 7.8e-3   0.2: 4.3e-5 / 1.2e-3
     roughness 0.3:  1.5e-5 / 1.5e-4   0.5: 1.2e-5 / 1.9e-4   0.7: 6.4e-5 / 1.2e-4
     roughness 1.0:  1.0e-4 / 3.9e-4
   asserted at ~3x (the max at 0.1 at the requirement, 1e-2); the medians also against LTC's
   published ones (7e-5, 1e-3, 4e-3, 1.6e-2, 0.11, 6.8e-2, 1.1e-2). The full 1,750-quad
   comparison: bench/bench_ggx.c. */
typedef double (*ggx_kern)(const double (*q)[3], int nv, const double nrm[3], const double view[3],
                           double alpha);

/* k on the research sampler's 24 quads at one roughness: the median relative error over the
   visible ones (light >= 5 % of the albedo) and the max error / albedo; returns the number
   of visible quads */
static int sampler_errors(ggx_kern k, double roughness, unsigned seed, double *out_med,
                          double *out_emax) {
  ggxc_rng r;
  double rel[64], emax = 0;
  int nvis = 0, c;
  r.s = seed;
  for (c = 0; c < 24; ++c) {
    ggxc_case cs;
    double alb, gt, got, a = roughness * roughness;
    ggxc_make(&r, &cs, -1);
    got = k((const double(*)[3])cs.q, 4, ZN, cs.view, a);
    gt = ref((const double(*)[3])cs.q, 4, ZN, cs.view, a, &alb);
    if (fabs(got - gt) / alb > emax) emax = fabs(got - gt) / alb;
    if (gt >= 0.05 * alb) rel[nvis++] = fabs(got - gt) / gt;
  }
  qsort(rel, (size_t)nvis, sizeof rel[0], cmpd);
  *out_med = nvis ? rel[nvis / 2] : 0;
  *out_emax = emax;
  return nvis;
}

static const double sampler_rough[7] = {0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1.0};
static const double sampler_ltc[7] = {7.3e-5, 1.0e-3, 3.8e-3, 1.6e-2, 0.11, 6.8e-2, 1.1e-2};

static void test_research_sampler(void) {
  static const double tol_med[7] = {5.1e-7, 1.5e-5, 1.3e-4, 4.5e-5, 3.6e-5, 1.9e-4, 3.0e-4};
  static const double tol_max[7] = {3e-3, 1e-2, 3.7e-3, 4.4e-4, 5.8e-4, 3.7e-4, 1.2e-3};
  int ir;
  for (ir = 0; ir < 7; ++ir) {
    double med, emax, rgh = sampler_rough[ir];
    int nvis = sampler_errors(kern, rgh, 1000u + (unsigned)ir, &med, &emax);
    printf("  roughness %.2f: %2d visible, median rel. error %.2e (LTC %.1e), max err/albedo "
           "%.2e\n",
           rgh, nvis, med, sampler_ltc[ir], emax);
    TL_CHECK(nvis >= 5, "roughness %g: only %d visible", rgh, nvis);
    TL_CHECK(med <= tol_med[ir] && med <= sampler_ltc[ir], "roughness %g: median %g", rgh, med);
    TL_CHECK(emax <= tol_max[ir], "roughness %g: max err/albedo %g", rgh, emax);
  }
}

/* Hard cases, 6 each at alpha 0.01, 0.09, 0.49: max error / albedo. Measured: straddling
   6.9e-5, grazing 5.6e-3, large 8.0e-3, sliver 9.5e-7 (asserted at ~3x; with a fixed 7- or
   28-node cubature per fan triangle: 5.2e-5, 9.2e-3, 1.7e-2). Grazing views and very large
   lights are the weak spot: the BRDF apart from D (masking, Jacobian) varies inside the lobe
   faster than the first-order model, and the remainder's adaptive pieces follow it. */
static void test_hard_cases(void) {
  static const char *names[4] = {"straddling", "grazing view", "large", "sliver"};
  static const double alphas[3] = {0.01, 0.09, 0.49};
  static const double tol[4] = {1.6e-4, 1.3e-2, 2.5e-2, 1.9e-6};
  int kind, ia, c;
  for (kind = 0; kind < 4; ++kind) {
    ggxc_rng r;
    double worst = 0;
    r.s = 77u + (unsigned)kind;
    for (ia = 0; ia < 3; ++ia)
      for (c = 0; c < 6; ++c) {
        double q[4][3], view[3], alb, gt, got;
        ggxc_hard(&r, kind, q, view);
        got = kern((const double(*)[3])q, 4, ZN, view, alphas[ia]);
        gt = ref((const double(*)[3])q, 4, ZN, view, alphas[ia], &alb);
        if (fabs(got - gt) / alb > worst) worst = fabs(got - gt) / alb;
      }
    printf("  %-12s max err/albedo %.2e\n", names[kind], worst);
    TL_CHECK(worst <= tol[kind], "%s: %g", names[kind], worst);
  }
}

/* Grazing views with lights straddling the horizon, the lobe cut by it (the remainder's worst
   case before its adaptive pieces): the four worst quads of bench_ggx's sampler (cases 674,
   764, 964, 643 of bench/bench_ggx.c; measured error / albedo 2.6e-2, 3.1e-2, 1.8e-2, 1.5e-2
   with a fixed 7- or 28-node cubature, now 2.3e-3, 1.2e-3, 4.0e-3, 3.4e-3), and 18 drawn ones
   (view 80-88 deg, light centred on the horizon, alpha 0.01, 0.04, 0.09; measured 5.0e-2 before,
   now 4.0e-3). Asserted at 5e-3 (the bench quads) and 8e-3 (the drawn ones). */
static void test_grazing_straddling(void) {
  static const struct {
    float alpha, view[3], q[4][3];
  } qs[4] = {{0.0399999991f,
              {0.995235145f, 0.0f, 0.0975040048f},
              {{-6.71101475f, -0.326214731f, 8.51835537f},
               {-8.88011265f, -2.58299232f, -5.83675861f},
               {-5.03840208f, 5.16409349f, -7.63517666f},
               {-2.86930418f, 7.42087078f, 6.7199378f}}},
             {0.0900000036f,
              {0.961713791f, 0.0f, 0.274055719f},
              {{-1.7517947f, 5.09022522f, 0.557582557f},
               {-2.60228014f, 3.07070446f, 4.3102808f},
               {-4.68837547f, -2.65135717f, 0.758165538f},
               {-3.83788991f, -0.631836593f, -2.99453259f}}},
             {0.0900000036f,
              {0.999143243f, 0.0f, 0.0413854308f},
              {{-4.69676113f, 1.76398396f, 0.889303982f},
               {-3.25368094f, -1.23319256f, 1.91875839f},
               {-0.908757925f, -1.34041011f, -1.6804893f},
               {-2.35183811f, 1.65676641f, -2.70994377f}}},
             {0.0399999991f,
              {0.995550454f, 0.0f, 0.0942302048f},
              {{-9.21273136f, -0.370904475f, -0.953336477f},
               {-4.41421318f, 2.54180956f, 0.146758303f},
               {-5.14097166f, 2.96221352f, 2.20371461f},
               {-9.93949032f, 0.0494995192f, 1.10361981f}}}};
  static const double alphas[3] = {0.01, 0.04, 0.09};
  double worst = 0, worst_b = 0;
  ggxc_rng r;
  int c, i, k, ia;
  for (c = 0; c < 4; ++c) {
    double q[4][3], view[3], alb, gt, got;
    for (i = 0; i < 4; ++i)
      for (k = 0; k < 3; ++k)
        q[i][k] = qs[c].q[i][k];
    for (k = 0; k < 3; ++k)
      view[k] = qs[c].view[k];
    got = kern((const double(*)[3])q, 4, ZN, view, qs[c].alpha);
    gt = ref((const double(*)[3])q, 4, ZN, view, qs[c].alpha, &alb);
    printf("  bench quad %d: err/albedo %.2e\n", c, fabs(got - gt) / alb);
    if (fabs(got - gt) / alb > worst_b) worst_b = fabs(got - gt) / alb;
  }
  r.s = 8080u;
  for (ia = 0; ia < 3; ++ia)
    for (c = 0; c < 6; ++c) {
      ggxc_case cs;
      double cz, alb, gt, got;
      ggxc_make(&r, &cs, 80 + 8 * ggxc_rnd(&r));
      cz = (cs.q[0][2] + cs.q[1][2] + cs.q[2][2] + cs.q[3][2]) / 4;
      for (i = 0; i < 4; ++i)
        cs.q[i][2] -= cz;
      got = kern((const double(*)[3])cs.q, 4, ZN, cs.view, alphas[ia]);
      gt = ref((const double(*)[3])cs.q, 4, ZN, cs.view, alphas[ia], &alb);
      if (fabs(got - gt) / alb > worst) worst = fabs(got - gt) / alb;
    }
  printf("  grazing straddling: bench quads max err/albedo %.2e, drawn %.2e\n", worst_b, worst);
  TL_CHECK(worst_b <= 5e-3, "bench quads: %g", worst_b);
  TL_CHECK(worst <= 8e-3, "drawn: %g", worst);
}

/* a light filling the upper hemisphere (a 2e4 x 2e4 quad at height 1) gives the directional
   albedo; measured error / albedo: alpha 0.04: 3.8e-5 (view 30 deg), 9.0e-4 (75 deg; 3.7e-3
   with a fixed cubature); alpha 1: 1.7e-4, 1.1e-3 (asserted at ~3x, the 75-deg ones at the
   fixed cubature's ~3x) */
static void test_hemisphere(void) {
  static const double alphas[2] = {0.04, 1.0}, tvs[2] = {30, 75};
  double q[4][3] = {{-1e4, -1e4, 1}, {1e4, -1e4, 1}, {1e4, 1e4, 1}, {-1e4, 1e4, 1}};
  static const double tol[2][2] = {{1.2e-4, 1.1e-2}, {5.1e-4, 2.2e-3}};
  int ia, iv;
  for (ia = 0; ia < 2; ++ia)
    for (iv = 0; iv < 2; ++iv) {
      double t = tvs[iv] * 3.14159265358979323846 / 180, view[3] = {sin(t), 0, cos(t)};
      double alb = (double)arref_ggx_albedo(ZN, view, alphas[ia]);
      double gt = ref((const double(*)[3])q, 4, ZN, view, alphas[ia], NULL);
      double got = kern((const double(*)[3])q, 4, ZN, view, alphas[ia]);
      printf("  hemisphere alpha %.2f view %2.0f: albedo %.6f, light %.6f, kernel %.6f\n",
             alphas[ia], tvs[iv], alb, gt, got);
      TL_CHECK(fabs(got - gt) <= tol[ia][iv] * alb, "hemisphere %g %g: %g vs %g", alphas[ia],
               tvs[iv], got, gt);
    }
}

/* rotating the whole scene (normal, view, light) changes nothing beyond float rounding */
static void test_rotation(void) {
  ggxc_rng r;
  double worst = 0;
  int c;
  r.s = 4242u;
  for (c = 0; c < 40; ++c) {
    ggxc_case cs;
    double ax[3], t1[3], t2[3], q[4][3], n[3], v[3], a = 0.002 + 0.5 * ggxc_rnd(&r), base, rot;
    int i, k;
    ggxc_make(&r, &cs, -1);
    ax[0] = ggxc_rnd(&r) - 0.5, ax[1] = ggxc_rnd(&r) - 0.5, ax[2] = ggxc_rnd(&r) - 0.5;
    ggxc_unit(ax);
    ggxc_perp(ax, t1, t2); /* frame (t1, t2, ax): old x, y, z */
    for (i = 0; i < 4; ++i)
      for (k = 0; k < 3; ++k)
        q[i][k] = cs.q[i][0] * t1[k] + cs.q[i][1] * t2[k] + cs.q[i][2] * ax[k];
    for (k = 0; k < 3; ++k) {
      n[k] = ax[k];
      v[k] = cs.view[0] * t1[k] + cs.view[1] * t2[k] + cs.view[2] * ax[k];
    }
    base = kern((const double(*)[3])cs.q, 4, ZN, cs.view, a);
    rot = kern((const double(*)[3])q, 4, n, v, a);
    if (fabs(rot - base) > worst * (base > 1e-3 ? base : 1e-3))
      worst = fabs(rot - base) / (base > 1e-3 ? base : 1e-3);
  }
  printf("  rotated frames: max difference %.2e (relative, floor 1e-3)\n", worst);
  TL_CHECK(worst < 3e-6, "rotation: %g", worst); /* float input rounding; measured 9.3e-7 */
}

/* a light entirely below the horizon gives exactly 0; one straddling it matches the clipped
   reference (test_hard_cases); winding and the starting vertex do not matter */
static void test_horizon_winding(void) {
  ggxc_rng r;
  int c, bad = 0;
  double worst = 0;
  r.s = 99u;
  for (c = 0; c < 200; ++c) {
    ggxc_case cs;
    float fv[4][3], rv[4][3], sv[4][3], fn[3] = {0, 0, 1}, fw[3], a = (float)(0.01 + ggxc_rnd(&r));
    float g0, g1, g2;
    double top = -1e30;
    int i, k;
    ggxc_make(&r, &cs, -1);
    for (i = 0; i < 4; ++i)
      if (cs.q[i][2] > top) top = cs.q[i][2];
    for (i = 0; i < 4; ++i)
      for (k = 0; k < 3; ++k) {
        fv[i][k] = (float)(cs.q[i][k] - (k == 2 ? top + 1e-3 : 0)); /* all below */
        rv[3 - i][k] = (float)cs.q[i][k];
        sv[(i + 1) % 4][k] = (float)cs.q[i][k];
      }
    for (k = 0; k < 3; ++k)
      fw[k] = (float)cs.view[k];
    if (shl_polygon_ggx((const float(*)[3])fv, 4, fn, fw, a) != 0.0f) bad++;
    for (i = 0; i < 4; ++i)
      for (k = 0; k < 3; ++k)
        fv[i][k] = (float)cs.q[i][k];
    g0 = shl_polygon_ggx((const float(*)[3])fv, 4, fn, fw, a);
    g1 = shl_polygon_ggx((const float(*)[3])rv, 4, fn, fw, a);
    g2 = shl_polygon_ggx((const float(*)[3])sv, 4, fn, fw, a);
    if (fabsf(g1 - g0) > worst * (g0 + 1e-6f)) worst = fabsf(g1 - g0) / (g0 + 1e-6f);
    if (fabsf(g2 - g0) > worst * (g0 + 1e-6f)) worst = fabsf(g2 - g0) / (g0 + 1e-6f);
  }
  printf("  below the horizon: %d of 200 non-zero; winding / start vertex: max rel. change "
         "%.2e\n",
         bad, worst);
  TL_CHECK(bad == 0, "%d lights below the horizon gave light", bad);
  /* the fan is from the vertex centroid, so only the summation order changes; measured 0 */
  TL_CHECK(worst < 1e-6, "winding: %g", worst);
}

static void test_degenerate(void) {
  float q[9][3] = {{-1, -1, 2}, {1, -1, 2}, {1, 1, 2}, {-1, 1, 2}, {0, 0, 2},
                   {0, 0, 2},   {0, 0, 2},  {0, 0, 2}, {0, 0, 2}};
  float n[3] = {0, 0, 1}, v[3] = {0.3f, 0, 1}, z[3] = {0, 0, 0}, below[3] = {0.3f, 0, -1};
  float good = shl_polygon_ggx((const float(*)[3])q, 4, n, v, 0.2f), t;
  float nan = (float)NAN, inf = (float)INFINITY;
  TL_CHECK(good > 0.0f && good < 1.0f, "reference value %g", good);
  TL_CHECK(shl_polygon_ggx((const float(*)[3])q, 2, n, v, 0.2f) == 0.0f, "nv = 2");
  /* nv = 9 (above SHLIGHT_POLYGON_MAX, fan pieces): the quad, then its centre five times:
     the pentagon q0 q1 q2 q3 c (repeated vertices are zero-length edges) */
  t = shl_polygon_ggx((const float(*)[3])q, 5, n, v, 0.2f);
  TL_CHECK(t > 0.0f && fabsf(shl_polygon_ggx((const float(*)[3])q, 9, n, v, 0.2f) - t) <= 1e-4f * t,
           "nv = 9: %g, the pentagon %g", shl_polygon_ggx((const float(*)[3])q, 9, n, v, 0.2f), t);
  TL_CHECK(shl_polygon_ggx((const float(*)[3])q, 4, z, v, 0.2f) == 0.0f, "zero normal");
  TL_CHECK(shl_polygon_ggx((const float(*)[3])q, 4, n, z, 0.2f) == 0.0f, "zero view");
  TL_CHECK(shl_polygon_ggx((const float(*)[3])q, 4, n, below, 0.2f) == 0.0f, "view below");
  TL_CHECK(shl_polygon_ggx((const float(*)[3])q, 4, n, v, nan) == 0.0f, "NaN alpha");
  t = q[1][0];
  q[1][0] = nan;
  TL_CHECK(shl_polygon_ggx((const float(*)[3])q, 4, n, v, 0.2f) == 0.0f, "NaN vertex");
  q[1][0] = inf;
  TL_CHECK(shl_polygon_ggx((const float(*)[3])q, 4, n, v, 0.2f) == 0.0f, "Inf vertex");
  q[1][0] = t;
  n[1] = nan;
  TL_CHECK(shl_polygon_ggx((const float(*)[3])q, 4, n, v, 0.2f) == 0.0f, "NaN normal");
  n[1] = 0;
  v[1] = inf;
  TL_CHECK(shl_polygon_ggx((const float(*)[3])q, 4, n, v, 0.2f) == 0.0f, "Inf view");
  v[1] = 0;
  t = q[2][2];
  q[2][0] = q[2][1] = q[2][2] = 0; /* a vertex at the shading point */
  TL_CHECK(shl_polygon_ggx((const float(*)[3])q, 4, n, v, 0.2f) == 0.0f, "vertex at the point");
  q[2][0] = q[2][1] = 1;
  q[2][2] = t;
  /* alpha clamped to [1e-4, 1]; non-unit normal and view are normalised */
  TL_CHECK(shl_polygon_ggx((const float(*)[3])q, 4, n, v, 0.0f) ==
               shl_polygon_ggx((const float(*)[3])q, 4, n, v, 1e-4f),
           "alpha 0");
  TL_CHECK(shl_polygon_ggx((const float(*)[3])q, 4, n, v, 7.0f) ==
               shl_polygon_ggx((const float(*)[3])q, 4, n, v, 1.0f),
           "alpha 7");
  TL_CHECK(shl_polygon_ggx((const float(*)[3])q, 4, n, v, -1.0f) ==
               shl_polygon_ggx((const float(*)[3])q, 4, n, v, 1e-4f),
           "alpha < 0");
  {
    float n5[3] = {0, 0, 5}, v5[3] = {3, 0, 10};
    float a = shl_polygon_ggx((const float(*)[3])q, 4, n5, v5, 0.2f);
    TL_CHECK(fabsf(a - good) <= 1e-6f * good, "scaled vectors %g vs %g", a, good);
  }
  /* tiny alpha stays finite: a light on the mirror direction keeps ~all the albedo */
  {
    float m[4][3] = {{-0.4f, -0.1f, 1}, {-0.2f, -0.1f, 1}, {-0.2f, 0.1f, 1}, {-0.4f, 0.1f, 1}};
    float a = shl_polygon_ggx((const float(*)[3])m, 4, n, v, 1e-4f);
    TL_CHECK(a > 0.99f && a < 1.001f, "alpha 1e-4 on the mirror direction: %g", a);
  }
}

/* triangles and non-convex 8-gons (stars), some straddling the horizon, alpha 0.01 / 0.09 /
   0.49, 6 each: max error / albedo. Measured: triangles 3.4e-4, stars 2.9e-4 (asserted at ~3x). */
static void test_polygons(void) {
  static const double alphas[3] = {0.01, 0.09, 0.49};
  ggxc_rng r;
  double worst[2] = {0, 0};
  int kind, ia, c, i, k;
  r.s = 5150u;
  for (kind = 0; kind < 2; ++kind)
    for (ia = 0; ia < 3; ++ia)
      for (c = 0; c < 6; ++c) {
        double q[8][3], view[3], t = ggxc_rnd(&r) * 1.4, d[3], t1[3], t2[3], alb, gt, got;
        double rad = 0.2 + 0.8 * ggxc_rnd(&r);
        int nv = kind == 0 ? 3 : 8;
        view[0] = sin(t), view[1] = 0, view[2] = cos(t);
        d[0] = -view[0] + 0.4 * (ggxc_rnd(&r) - 0.5), d[1] = 0.4 * (ggxc_rnd(&r) - 0.5);
        d[2] = view[2] - 0.1 + 0.4 * (ggxc_rnd(&r) - 0.5);
        ggxc_unit(d);
        ggxc_perp(d, t1, t2);
        for (i = 0; i < nv; ++i) {
          double a = 6.283185307179586 * (i + 0.3 * ggxc_rnd(&r)) / nv;
          double rr = (nv == 8 && (i & 1)) ? 0.4 * rad : rad;
          for (k = 0; k < 3; ++k)
            q[i][k] = d[k] + rr * (cos(a) * t1[k] + sin(a) * t2[k]);
        }
        got = kern((const double(*)[3])q, nv, ZN, view, alphas[ia]);
        gt = ref((const double(*)[3])q, nv, ZN, view, alphas[ia], &alb);
        if (fabs(got - gt) / alb > worst[kind]) worst[kind] = fabs(got - gt) / alb;
      }
  printf("  triangles max err/albedo %.2e, non-convex 8-gons %.2e\n", worst[0], worst[1]);
  TL_CHECK(worst[0] <= 1e-3, "triangles: %g", worst[0]);
  TL_CHECK(worst[1] <= 9e-4, "8-gons: %g", worst[1]);
}

/* more vertices than SHLIGHT_POLYGON_MAX (fan pieces): quads of the research sampler with each
   edge split into k collinear points (nv = 8..64, the same region), at alpha 1e-4, 1 and
   0.02..0.52, against the reference on the subdivided polygon (the region's value) and the
   4-gon's result; regular 9..64-gons (discs); every vertex scaled by 1e6 and 1e-6 (the same
   solid angle). Measured: subdivided max err/albedo 4.7e-3 (a 28-gon at alpha 0.029; its 4-gon
   5.3e-3), discs 2.1e-3 (a 48-gon), scale 8.9e-7 (relative, floor 1e-3); asserted at the
   contract's 1e-2 (polygons) and 1e-6 (scale). */
static void test_many_vertices(void) {
  static double sq[64][3];
  ggxc_rng r;
  double wsub = 0, wdisc = 0, wscale = 0, alb, gt;
  int c, i, j, k, nv;
  r.s = 777u;
  for (c = 0; c < 60; ++c) {
    ggxc_case cs;
    double a = c % 3 == 0 ? 1e-4 : (c % 3 == 1 ? 1.0 : 0.02 + 0.5 * ggxc_rnd(&r)), g4, gs;
    int kk = 2 + c % 15;
    float fv[4][3], fw[3], fn[3] = {0, 0, 1}, g6, gm;
    ggxc_make(&r, &cs, -1);
    for (nv = 0, i = 0; i < 4; ++i)
      for (j = 0; j < kk; ++j, ++nv)
        for (k = 0; k < 3; ++k)
          sq[nv][k] = cs.q[i][k] + (double)j / kk * (cs.q[(i + 1) % 4][k] - cs.q[i][k]);
    g4 = kern((const double(*)[3])cs.q, 4, ZN, cs.view, a);
    gs = kern((const double(*)[3])sq, nv, ZN, cs.view, a);
    if (fabs(gs - g4) > 1e-4 * (g4 > 1e-3 ? g4 : 1e-3)) { /* the reference where they differ */
      gt = ref((const double(*)[3])sq, nv, ZN, cs.view, a, &alb);
      if (fabs(gs - gt) / alb > wsub) wsub = fabs(gs - gt) / alb;
    }
    for (i = 0; i < 4; ++i)
      for (k = 0; k < 3; ++k)
        fv[i][k] = (float)(cs.q[i][k] * 1e6);
    for (k = 0; k < 3; ++k)
      fw[k] = (float)cs.view[k];
    g6 = shl_polygon_ggx((const float(*)[3])fv, 4, fn, fw, (float)a);
    for (i = 0; i < 4; ++i)
      for (k = 0; k < 3; ++k)
        fv[i][k] = (float)(cs.q[i][k] * 1e-6);
    gm = shl_polygon_ggx((const float(*)[3])fv, 4, fn, fw, (float)a);
    g4 = fmax(fabs(g6 - g4), fabs(gm - g4)) / (g4 > 1e-3 ? g4 : 1e-3);
    if (g4 > wscale) wscale = g4;
  }
  for (c = 0; c < 8; ++c) {
    double ctr[3], rad = 0.1 + 0.8 * ggxc_rnd(&r), ax[3], t1[3], t2[3], th, ph, v[3];
    double a = c % 4 == 0 ? 1e-4 : (c % 4 == 1 ? 1 : 0.05 + 0.4 * ggxc_rnd(&r));
    nv = c < 4 ? 9 + 2 * c : 16 * (c - 3);
    ctr[0] = ggxc_rnd(&r) - 0.5, ctr[1] = ggxc_rnd(&r) - 0.5, ctr[2] = 0.3 + ggxc_rnd(&r);
    ax[0] = ggxc_rnd(&r) - 0.5, ax[1] = ggxc_rnd(&r) - 0.5, ax[2] = ggxc_rnd(&r) - 0.5;
    ggxc_unit(ax);
    ggxc_perp(ax, t1, t2);
    for (i = 0; i < nv; ++i)
      for (k = 0; k < 3; ++k)
        sq[i][k] = ctr[k] + rad * (cos(6.283185307179586 * i / nv) * t1[k] +
                                   sin(6.283185307179586 * i / nv) * t2[k]);
    th = acos(ggxc_rnd(&r)) * 0.9, ph = 6.283185307179586 * ggxc_rnd(&r);
    v[0] = sin(th) * cos(ph), v[1] = sin(th) * sin(ph), v[2] = cos(th);
    gt = ref((const double(*)[3])sq, nv, ZN, v, a, &alb);
    gt = fabs(kern((const double(*)[3])sq, nv, ZN, v, a) - gt) / alb;
    if (gt > wdisc) wdisc = gt;
  }
  printf("  nv 8..64: subdivided quads max err/albedo %.2e, discs %.2e; vertices x 1e6, 1e-6: "
         "max rel. change %.2e\n",
         wsub, wdisc, wscale);
  TL_CHECK(wsub <= 1e-2, "subdivided quads: %g", wsub);
  TL_CHECK(wdisc <= 1e-2, "discs: %g", wdisc);
  TL_CHECK(wscale <= 1e-6, "scale: %g", wscale);
}

/* the research sampler's worst quads between the bench's roughness values (2,800 draws at
   roughness uniform in [0.05, 1]: 4 above 4.0e-3 of the albedo, all at views 80-87 deg):
   max error / albedo within the contract's 1e-2. Measured 5.6e-3, 4.9e-3, 4.4e-3, 8.8e-3. */
static void test_sampler_between_roughness(void) {
  static const struct {
    double rough, view[3], q[4][3];
  } cs[4] = {{0.267292929,
              {0.985223874, 0, 0.171271475},
              {{-7.80555615, -1.84352521, 1.98264013},
               {-4.83121108, 3.02528187, -3.8510213},
               {2.29002699, 6.98556562, 3.08508175},
               {-0.684318084, 2.11675855, 8.91874319}}},
             {0.278800924,
              {0.999007519, 0, 0.0445418547},
              {{0.186190736, -8.03606968, 2.65109495},
               {-13.0587791, 4.20339641, -4.59788287},
               {-14.0375619, 10.2373329, 7.37844147},
               {-0.792592036, -2.00213318, 14.6274193}}},
             {0.290433897,
              {0.997974739, 0, 0.0636114793},
              {{-0.859168193, -0.586384364, 2.08848908},
               {-3.76784418, -1.70699497, -3.00304782},
               {-4.04760973, 2.94625922, -3.86737205},
               {-1.13893374, 4.06686983, 1.22416485}}},
             {0.968405524,
              {0.998186276, 0, 0.0602009901},
              {{-0.199872038, 7.76856725, -8.90811877},
               {5.98524413, 1.936731, -8.45414888},
               {8.59162593, 6.09550911, 9.4601203},
               {2.40650976, 11.9273454, 9.00615041}}}};
  double worst = 0, alb, gt, a;
  int c;
  for (c = 0; c < 4; ++c) {
    a = cs[c].rough * cs[c].rough;
    gt = ref(cs[c].q, 4, ZN, cs[c].view, a, &alb);
    gt = fabs(kern(cs[c].q, 4, ZN, cs[c].view, a) - gt) / alb;
    printf("  roughness %.3f view %.1f deg: err/albedo %.2e\n", cs[c].rough,
           acos(cs[c].view[2]) * 57.29577951308232, gt);
    if (gt > worst) worst = gt;
  }
  TL_CHECK(worst <= 1e-2, "max err/albedo %g", worst);
}

/* the last tenth of a degree before grazing: view 89.9 deg, alpha 0.04 and 1, a 1 x 1 light
   overhead (height 1) and one ahead of the view, 0.05..1.5 above the horizon: max error / albedo.
   Measured: alpha 0.04 1.3e-3 overhead, 2.8e-4 ahead; alpha 1 6.3e-5, 2.7e-5 (asserted at
   ~3x). */
static void test_grazing_last_degree(void) {
  static const double q0[4][3] = {{-0.5, -0.5, 1}, {0.5, -0.5, 1}, {0.5, 0.5, 1}, {-0.5, 0.5, 1}};
  static const double q1[4][3] = {{2, -1, 0.05}, {4, -1, 0.05}, {4, 1, 1.5}, {2, 1, 1.5}};
  double v[3] = {sin(89.9 / 57.29577951308232), 0, cos(89.9 / 57.29577951308232)}, worst = 0, alb,
         gt;
  int c;
  for (c = 0; c < 4; ++c) {
    const double(*q)[3] = c & 1 ? q1 : q0;
    double a = c < 2 ? 0.04 : 1.0;
    gt = ref(q, 4, ZN, v, a, &alb);
    gt = fabs(kern(q, 4, ZN, v, a) - gt) / alb;
    printf("  view 89.9 deg, alpha %.2f, light %s: err/albedo %.2e\n", a,
           c & 1 ? "ahead" : "overhead", gt);
    if (gt > worst) worst = gt;
  }
  TL_CHECK(worst <= 4e-3, "view 89.9 deg: %g", worst);
}

/* the last degrees before grazing with wide lights (the lobe in light space a sliver 2 alpha (h.v)
   wide, on the horizon): a light filling the hemisphere (a 2e4 x 2e4 quad at height 1), a wall
   straddling the horizon ahead of the mirror direction and a tilted plane through the horizon
   5 cm above the shading point. Measured error / albedo (before the remainder's pieces were
   graded in half-vector space and split at unit midpoints: 7.4e-2, 0.82, 0.13, 9.8e-2, 0.15,
   5.6e-2, 0.99, 0.30, 0.87, 0.27, 9.8e-2, 2.3e-2, 3.2, 6.7e-2), asserted at ~3x, within 1e-2. */
static void test_grazing_wide(void) {
  static const double hemi[4][3] = {{-1e4, -1e4, 1}, {1e4, -1e4, 1}, {1e4, 1e4, 1}, {-1e4, 1e4, 1}};
  static const double wall[4][3] = {{-2, -3, -1}, {-2, 3, -1}, {-2, 3, 2}, {-2, -3, 2}};
  static const double tilt[4][3] = {{-6, -6, -0.3}, {-6, 6, -0.3}, {6, 6, 0.4}, {6, -6, 0.4}};
  static const struct {
    int light;
    double alpha, view, bound;
  } cs[14] = {{0, 0.01, 88, 5e-3},   {0, 0.01, 89.5, 2.5e-3}, {0, 0.04, 88, 1e-2},
              {1, 0.04, 85, 5e-3},   {1, 0.04, 88, 1e-2},     {1, 0.1, 88, 1e-2},
              {1, 0.01, 89, 5e-3},   {2, 0.1, 85, 7e-3},      {2, 0.04, 87, 1e-2},
              {0, 0.04, 89.5, 1e-2}, {1, 0.1, 89.9, 1.5e-3},  {0, 1.0, 89.9, 1.7e-3},
              {2, 0.04, 89.9, 1e-2}, {1, 0.01, 87, 3.5e-3}};
  int c;
  for (c = 0; c < 14; ++c) {
    const double(*q)[3] = cs[c].light == 0 ? hemi : (cs[c].light == 1 ? wall : tilt);
    double t = cs[c].view / 57.29577951308232, v[3] = {sin(t), 0, cos(t)}, alb, gt;
    gt = ref(q, 4, ZN, v, cs[c].alpha, &alb);
    gt = fabs(kern(q, 4, ZN, v, cs[c].alpha) - gt) / alb;
    printf("  %s, alpha %.2f, view %.1f deg: err/albedo %.2e\n",
           cs[c].light == 0 ? "hemisphere" : (cs[c].light == 1 ? "wall" : "tilted plane"),
           cs[c].alpha, cs[c].view, gt);
    TL_CHECK(gt <= cs[c].bound, "case %d: %g", c, gt);
  }
}

/* the C kernels' own exp, log, sin, cos (shli_mexp, shli_mlog, shli_msincos; GLSL uses the
   built-ins) against libm on the ranges the GGX and Beckmann bodies use and beyond: measured
   relative error 3.3e-16 (exp, [-40, 40]), 1.1e-15 (log, [1e-13, 1e17]), absolute 2.2e-16
   (sin, cos, [-7, 7]) and relative 2.2e-16 for sin near 0 and pi; the clamps of exp */
static void test_transcendentals(void) {
  double me = 0, ml = 0, ms = 0, mr = 0, x, e;
  int i;
  for (i = 0; i <= 200000; ++i) {
    x = -40.0 + 80.0 * i / 200000;
    e = fabs(shli_mexp(x) / exp(x) - 1.0);
    me = e > me ? e : me;
    x = exp(-30.0 + 70.0 * i / 200000);
    e = fabs(shli_mlog(x) - log(x)) / (fabs(log(x)) > 1e-300 ? fabs(log(x)) : 1.0);
    ml = e > ml ? e : ml;
    x = -7.0 + 14.0 * i / 200000;
    e = fabs(shli_msincos(x, 0) - sin(x)) + fabs(shli_msincos(x, 1) - cos(x));
    ms = e > ms ? e : ms;
    x = 1e-9 * (i + 1);
    e = fabs(shli_msincos(x, 0) / sin(x) - 1.0) +
        fabs(shli_msincos(3.141592653589793 - x, 0) / sin(3.141592653589793 - x) - 1.0);
    mr = e > mr ? e : mr;
  }
  printf("  exp %.2e, log %.2e, sin + cos %.2e (abs), sin near 0 and pi %.2e\n", me, ml, ms, mr);
  TL_CHECK(me < 1e-15 && ml < 3e-15 && ms < 1e-15 && mr < 1e-15, "transcendentals");
  TL_CHECK(shli_mexp(-1e300) >= 0.0 && shli_mexp(-1e300) < 1e-300 && shli_mexp(1e300) > 1e307 &&
               shli_mexp(1e300) < 1.7e308,
           "exp clamps: %g %g", shli_mexp(-1e300), shli_mexp(1e300));
}

/* shl_polygon_ggx_fast, measured on this fit (gcc -O2, x86-64), asserted at ~1.5x. Sampler,
   median rel. error / max err/albedo: roughness 0.05: 3.7e-5 / 5.8e-4, 0.1: 1.1e-3 / 3.2e-2,
   0.2: 2.1e-3 / 8.5e-3, 0.3: 5.1e-3 / 9.8e-3, 0.5: 1.9e-2 / 4.0e-2, 0.7: 2.4e-2 / 2.6e-2,
   1.0: 2.2e-2 / 9.9e-3 (24 quads each; the bench's 250 give the figures of the docs; roughness
   <= 0.25 has its own coefficient set); hard cases (max err/albedo): straddling 9.3e-3, grazing
   4.0e-2, large 6.7e-2, sliver 7.0e-4; 9..64 vertices 9.6e-4 */
#define FAST_MED \
  { 6e-5, 1.5e-3, 3.1e-3, 7.7e-3, 2.9e-2, 3.6e-2, 3.3e-2 }
#define FAST_MAX \
  { 9e-4, 4.8e-2, 1.3e-2, 1.5e-2, 6e-2, 3.9e-2, 1.5e-2 }
#define FAST_HARD \
  { 1.4e-2, 6e-2, 1e-1, 1.05e-3 }
#define FAST_MANY 1.4e-3
/* ---- shl_polygon_ggx_fast (the table-free linearly transformed cosine) against the same long
   double cubature. The fit (tools/fit_ggx_fast.c) never saw these quads (its training quads come
   from the sampler with other seeds and fixed view angles). */
static double kern_fast(const double (*q)[3], int nv, const double nrm[3], const double view[3],
                        double alpha) {
  float fv[64][3], fn[3], fw[3];
  int i, k;
  for (i = 0; i < nv; ++i)
    for (k = 0; k < 3; ++k)
      fv[i][k] = (float)q[i][k];
  for (k = 0; k < 3; ++k)
    fn[k] = (float)nrm[k], fw[k] = (float)view[k];
  return shl_polygon_ggx_fast((const float(*)[3])fv, nv, fn, fw, (float)alpha);
}
static double ref_n(const double (*q)[3], int nv, const double nrm[3], const double view[3],
                    double alpha, double *alb) {
  double rq[64][3], rn[3], rv[3];
  int i, k;
  for (i = 0; i < nv; ++i)
    for (k = 0; k < 3; ++k)
      rq[i][k] = (double)(float)q[i][k];
  for (k = 0; k < 3; ++k)
    rn[k] = (double)(float)nrm[k], rv[k] = (double)(float)view[k];
  if (alb) *alb = (double)arref_ggx_albedo(rn, rv, alpha);
  return (double)arref_polygon_ggx((const double(*)[3])rq, nv, rn, rv, alpha);
}

/* The research sampler (the quads of test_research_sampler), 24 per roughness: median
   relative error (visible: >= 5 % of the albedo) and max error / albedo, asserted at the
   measured values x ~1.5 (FAST_MED, FAST_MAX below); LTC's published medians printed beside. */
static void test_fast_sampler(void) {
  static const double tol_med[7] = FAST_MED;
  static const double tol_max[7] = FAST_MAX;
  int ir;
  for (ir = 0; ir < 7; ++ir) {
    double med, emax, rgh = sampler_rough[ir];
    int nvis = sampler_errors(kern_fast, rgh, 1000u + (unsigned)ir, &med, &emax);
    printf("  fast, roughness %.2f: %2d visible, median rel. error %.2e (LTC %.1e), max "
           "err/albedo %.2e\n",
           rgh, nvis, med, sampler_ltc[ir], emax);
    TL_CHECK(med <= tol_med[ir], "fast, roughness %g: median %g", rgh, med);
    TL_CHECK(emax <= tol_max[ir], "fast, roughness %g: max err/albedo %g", rgh, emax);
  }
}

/* The hard cases of test_hard_cases (straddling, grazing view 85-88 deg, large, sliver) */
static void test_fast_hard(void) {
  static const char *names[4] = {"straddling", "grazing view", "large", "sliver"};
  static const double alphas[3] = {0.01, 0.09, 0.49};
  static const double tol[4] = FAST_HARD;
  int kind, ia, c;
  for (kind = 0; kind < 4; ++kind) {
    ggxc_rng r;
    double worst = 0;
    r.s = 77u + (unsigned)kind;
    for (ia = 0; ia < 3; ++ia)
      for (c = 0; c < 6; ++c) {
        double q[4][3], view[3], alb, gt, got;
        ggxc_hard(&r, kind, q, view);
        got = kern_fast((const double(*)[3])q, 4, ZN, view, alphas[ia]);
        gt = ref((const double(*)[3])q, 4, ZN, view, alphas[ia], &alb);
        if (fabs(got - gt) / alb > worst) worst = fabs(got - gt) / alb;
      }
    printf("  fast, %-12s max err/albedo %.2e\n", names[kind], worst);
    TL_CHECK(worst <= tol[kind], "fast, %s: %g", names[kind], worst);
  }
}

/* Lights wholly below the horizon give exactly 0, also under a grazing view where a lobe
   transformed before clipping would reach below the horizon (a light 1e-3 below it, spanning
   the mirror direction's azimuth); winding and start vertex change nothing but rounding. */
static void test_fast_horizon(void) {
  ggxc_rng r;
  int c, bad = 0, i, k;
  double worst = 0;
  float g[4][3] = {{-3, -2, -1e-3f}, {-0.2f, -2, -1e-3f}, {-0.2f, 2, -1e-3f}, {-3, 2, -1e-3f}};
  float fn[3] = {0, 0, 1}, fw[3] = {0.999f, 0, 0.045f};
  for (k = 0; k < 5; ++k)
    if (shl_polygon_ggx_fast((const float(*)[3])g, 4, fn, fw, (float)(0.05 + 0.2 * k)) != 0.0f)
      bad++;
  r.s = 99u;
  for (c = 0; c < 200; ++c) {
    ggxc_case cs;
    float fv[4][3], rv[4][3], sv[4][3], a = (float)(0.01 + ggxc_rnd(&r)), g0, g1, g2;
    double top = -1e30;
    ggxc_make(&r, &cs, -1);
    for (i = 0; i < 4; ++i)
      if (cs.q[i][2] > top) top = cs.q[i][2];
    for (i = 0; i < 4; ++i)
      for (k = 0; k < 3; ++k) {
        fv[i][k] = (float)(cs.q[i][k] - (k == 2 ? top + 1e-3 : 0));
        rv[3 - i][k] = (float)cs.q[i][k];
        sv[(i + 1) % 4][k] = (float)cs.q[i][k];
      }
    for (k = 0; k < 3; ++k)
      fw[k] = (float)cs.view[k];
    if (shl_polygon_ggx_fast((const float(*)[3])fv, 4, fn, fw, a) != 0.0f) bad++;
    for (i = 0; i < 4; ++i)
      for (k = 0; k < 3; ++k)
        fv[i][k] = (float)cs.q[i][k];
    g0 = shl_polygon_ggx_fast((const float(*)[3])fv, 4, fn, fw, a);
    g1 = shl_polygon_ggx_fast((const float(*)[3])rv, 4, fn, fw, a);
    g2 = shl_polygon_ggx_fast((const float(*)[3])sv, 4, fn, fw, a);
    if (fabsf(g1 - g0) > worst * (g0 + 1e-6f)) worst = fabsf(g1 - g0) / (g0 + 1e-6f);
    if (fabsf(g2 - g0) > worst * (g0 + 1e-6f)) worst = fabsf(g2 - g0) / (g0 + 1e-6f);
  }
  printf("  fast, below the horizon: %d of 205 non-zero; winding / start vertex: max rel. change "
         "%.2e\n",
         bad, worst);
  TL_CHECK(bad == 0, "fast: %d lights below the horizon gave light", bad);
  TL_CHECK(worst < 1e-5, "fast, winding: %g", worst);
}

/* 9 to 64 vertices: regular polygons (discs of half-angle 20 deg about the mirror direction and
   a tilted one straddling the horizon), against the cubature; above SHLIGHT_POLYGON_MAX the C
   kernel sums fan pieces, which must agree with the 8-vertex pieces' sum to rounding. */
static void test_fast_many(void) {
  static const int ns[4] = {9, 16, 33, 64};
  double worst = 0;
  int in, ic;
  for (in = 0; in < 4; ++in)
    for (ic = 0; ic < 2; ++ic) {
      double q[64][3], view[3] = {sin(0.6), 0, cos(0.6)}, c[3], t1[3] = {0, 1, 0}, t2[3], alb, gt,
                       got;
      int i, k;
      c[0] = -view[0], c[1] = 0, c[2] = ic == 0 ? view[2] : 0.05;
      ggxc_unit(c);
      ggxc_cross(c, t1, t2);
      for (i = 0; i < ns[in]; ++i) {
        double t = 2 * 3.14159265358979323846 * i / ns[in];
        for (k = 0; k < 3; ++k)
          q[i][k] = 2 * (c[k] + 0.364 * (cos(t) * t1[k] + sin(t) * t2[k]));
      }
      got = kern_fast((const double(*)[3])q, ns[in], ZN, view, 0.09);
      gt = ref_n((const double(*)[3])q, ns[in], ZN, view, 0.09, &alb);
      if (fabs(got - gt) / alb > worst) worst = fabs(got - gt) / alb;
    }
  printf("  fast, 9..64 vertices: max err/albedo %.2e\n", worst);
  TL_CHECK(worst <= FAST_MANY, "fast, 9..64 vertices: %g", worst);
}

/* The fit has two coefficient sets (roughness <= 0.25 and >= 0.3, interpolated between): the
   result is continuous in alpha. At alpha 0.0625 and 0.09 (the ends of the interpolation) and
   the next float up, on 200 quads of the sampler: max change 4e-7 relative, 9e-8 absolute
   (float rounding; the sets alone differed by up to 0.12 absolute at 0.0625). */
static void test_fast_continuous(void) {
  static const float ends[2] = {0.0625f, 0.09f};
  ggxc_rng r;
  double worst = 0;
  int c, e, k;
  r.s = 4242u;
  for (c = 0; c < 200; ++c) {
    ggxc_case cs;
    float q[4][3], fv[3], fn[3] = {0.0f, 0.0f, 1.0f};
    ggxc_make(&r, &cs, -1);
    for (k = 0; k < 12; ++k)
      q[k / 3][k % 3] = (float)cs.q[k / 3][k % 3];
    for (k = 0; k < 3; ++k)
      fv[k] = (float)cs.view[k];
    for (e = 0; e < 2; ++e) {
      double f0 = shl_polygon_ggx_fast((const float(*)[3])q, 4, fn, fv, ends[e]);
      double f1 = shl_polygon_ggx_fast((const float(*)[3])q, 4, fn, fv, nextafterf(ends[e], 1.0f));
      double d = fabs(f1 - f0) / (f0 + 1e-3);
      if (d > worst) worst = d;
    }
  }
  printf("  fast, across the coefficient sets: max change %.2e\n", worst);
  TL_CHECK(worst < 2e-6, "fast, jump between the coefficient sets: %g", worst);
}

static void test_fast_degenerate(void) {
  float q[9][3] = {{-1, -1, 2}, {1, -1, 2}, {1, 1, 2}, {-1, 1, 2}, {0, 0, 2},
                   {0, 0, 2},   {0, 0, 2},  {0, 0, 2}, {0, 0, 2}};
  float n[3] = {0, 0, 1}, v[3] = {0.3f, 0, 1}, z[3] = {0, 0, 0}, below[3] = {0.3f, 0, -1};
  float good = shl_polygon_ggx_fast((const float(*)[3])q, 4, n, v, 0.2f), nan = (float)NAN;
  float n2[3] = {0, 0, 7}, v2[3] = {0.6f, 0, 2};
  TL_CHECK(good > 0.0f && good < 1.0f, "fast reference value %g", good);
  TL_CHECK(shl_polygon_ggx_fast((const float(*)[3])q, 2, n, v, 0.2f) == 0.0f, "fast nv = 2");
  TL_CHECK(shl_polygon_ggx_fast((const float(*)[3])q, 4, z, v, 0.2f) == 0.0f, "fast zero normal");
  TL_CHECK(shl_polygon_ggx_fast((const float(*)[3])q, 4, n, z, 0.2f) == 0.0f, "fast zero view");
  TL_CHECK(shl_polygon_ggx_fast((const float(*)[3])q, 4, n, below, 0.2f) == 0.0f,
           "fast view below");
  TL_CHECK(shl_polygon_ggx_fast((const float(*)[3])q, 4, n, v, nan) == 0.0f, "fast NaN alpha");
  TL_CHECK(shl_polygon_ggx_fast((const float(*)[3])q, 4, n2, v2, 0.2f) == good ||
               fabsf(shl_polygon_ggx_fast((const float(*)[3])q, 4, n2, v2, 0.2f) - good) <=
                   1e-6f * good,
           "fast scaled vectors");
  TL_CHECK(shl_polygon_ggx_fast((const float(*)[3])q, 4, n, v, 0.0f) ==
               shl_polygon_ggx_fast((const float(*)[3])q, 4, n, v, 1e-4f),
           "fast alpha 0 clamps to 1e-4");
  TL_CHECK(shl_polygon_ggx_fast((const float(*)[3])q, 4, n, v, 7.0f) ==
               shl_polygon_ggx_fast((const float(*)[3])q, 4, n, v, 1.0f),
           "fast alpha 7 clamps to 1");
  q[2][1] = nan;
  TL_CHECK(shl_polygon_ggx_fast((const float(*)[3])q, 4, n, v, 0.2f) == 0.0f, "fast NaN vertex");
  q[2][1] = (float)INFINITY;
  TL_CHECK(shl_polygon_ggx_fast((const float(*)[3])q, 4, n, v, 0.2f) == 0.0f, "fast Inf vertex");
  q[2][1] = 1;
  n2[0] = nan;
  TL_CHECK(shl_polygon_ggx_fast((const float(*)[3])q, 4, n2, v, 0.2f) == 0.0f, "fast NaN normal");
  q[1][0] = 0, q[1][1] = 0, q[1][2] = 0;
  TL_CHECK(shl_polygon_ggx_fast((const float(*)[3])q, 4, n, v, 0.2f) == 0.0f,
           "fast vertex at the point");
}

int main(void) {
  TL_RUN(test_transcendentals);
  TL_RUN(test_degenerate);
  TL_RUN(test_horizon_winding);
  TL_RUN(test_rotation);
  TL_RUN(test_hemisphere);
  TL_RUN(test_grazing_wide);
  TL_RUN(test_hard_cases);
  TL_RUN(test_grazing_straddling);
  TL_RUN(test_polygons);
  TL_RUN(test_many_vertices);
  TL_RUN(test_sampler_between_roughness);
  TL_RUN(test_grazing_last_degree);
  TL_RUN(test_research_sampler);
  TL_RUN(test_fast_degenerate);
  TL_RUN(test_fast_horizon);
  TL_RUN(test_fast_many);
  TL_RUN(test_fast_hard);
  TL_RUN(test_fast_sampler);
  TL_RUN(test_fast_continuous);
  return tl_summary();
}
