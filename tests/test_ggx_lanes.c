/* test_ggx_lanes.c - the GGX / Beckmann polygon lights' edges and remainder in AVX2 double lanes
 * (the C-only paths of shli_mf_taylor, shli_ggx_edges4 and shli_ggx_tri4) against the portable
 * kernel (tests/test_ggx_portable.c, SHLIGHT_NO_SIMD), call for call: the bench's sampler (7
 * roughness values x 250 quads of bench/bench_ggx.c), the named hard cases of tests/test_ggx.c
 * (straddling, grazing 85-88 deg, 113-deg-wide, slivers; grazing 80-88 deg straddling), a light
 * filling the hemisphere, pentagons, views past 88.85 deg, and alpha at the 0.02 node-count switch
 * and the 1e-4 clamp. Built with -march=x86-64-v3 (tests/tests.mk); on a CPU without AVX2 it says
 * so and checks nothing. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "tl.h"
#define GGXC_HARD_CASES
#include "ref/ggxcases.h"
#define SHLIGHT_IMPLEMENTATION
#include "../shlight.h"
#if !SHLIGHT_GGX_LANES
#error "test_ggx_lanes.c needs the edge lanes: build with -mavx2 -mfma (-march=x86-64-v3)"
#endif

float ggx_portable(const float (*v)[3], int nv, const float nrm[3], const float view[3],
                   float alpha, int ndf);

static const float ZN[3] = {0.0f, 0.0f, 1.0f};
static double worst[2];     /* max |lanes - portable| / max(|portable|, 1e-3 albedo-ish) */
static double worst_abs[2]; /* max |lanes - portable| */
static int ncalls;

static void cmp(const float (*q)[3], int nv, const float view[3], float alpha) {
  int ndf;
  for (ndf = 0; ndf < 2; ++ndf) {
    float a = ndf == 0 ? shl_polygon_ggx(q, nv, ZN, view, alpha)
                       : shl_polygon_beckmann(q, nv, ZN, view, alpha);
    float b = ggx_portable(q, nv, ZN, view, alpha, ndf);
    double d = fabs((double)a - (double)b);
    double rel = d / fmax(fabs((double)b), 1e-6);
    if (rel > worst[ndf]) worst[ndf] = rel;
    if (d > worst_abs[ndf]) worst_abs[ndf] = d;
    ncalls++;
  }
}
static void cmp_d(double (*q)[3], int nv, const double view[3], double alpha) {
  float qf[5][3], vf[3];
  int i, k;
  for (i = 0; i < nv; ++i)
    for (k = 0; k < 3; ++k)
      qf[i][k] = (float)q[i][k];
  for (k = 0; k < 3; ++k)
    vf[k] = (float)view[k];
  cmp((const float(*)[3])qf, nv, vf, (float)alpha);
}
static void report(const char *what, double tol) {
  printf("  %-28s max |lanes - portable| / |portable|: GGX %.2e, Beckmann %.2e (abs. %.1e, "
         "%.1e)\n",
         what, worst[0], worst[1], worst_abs[0], worst_abs[1]);
  TL_CHECK(worst[0] <= tol, "%s: GGX %g", what, worst[0]);
  TL_CHECK(worst[1] <= tol, "%s: Beckmann %g", what, worst[1]);
  worst[0] = worst[1] = worst_abs[0] = worst_abs[1] = 0;
}

static void test_lanes_sampler(void) { /* bench_ggx's quads (bench/bench_util.h's ggx_case) */
  static const double rough[7] = {0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1.0};
  ggxc_rng rg;
  int i;
  rg.s = 2017u;
  for (i = 0; i < 1750; ++i) {
    ggxc_case cs;
    ggxc_make(&rg, &cs, -1);
    cmp_d(cs.q, 4, cs.view, (double)(float)(rough[i / 250] * rough[i / 250]));
  }
  report("sampler (1,750 quads)", 1e-6);
}

static void test_lanes_hard(void) {
  static const char *names[4] = {"straddling", "grazing view 85-88", "large (113 deg)", "sliver"};
  static const double alphas[5] = {1e-4, 0.01, 0.0199, 0.09, 0.49};
  int kind, ia, c, i;
  for (kind = 0; kind < 4; ++kind) {
    ggxc_rng r;
    r.s = 77u + (unsigned)kind;
    for (ia = 0; ia < 5; ++ia)
      for (c = 0; c < 12; ++c) {
        double q[4][3], view[3];
        ggxc_hard(&r, kind, q, view);
        cmp_d(q, 4, view, alphas[ia]);
      }
    report(names[kind], 1e-6);
  }
  { /* grazing 80-88 deg, the light centred on the horizon */
    ggxc_rng r;
    r.s = 8080u;
    for (ia = 0; ia < 5; ++ia)
      for (c = 0; c < 12; ++c) {
        ggxc_case cs;
        double cz;
        ggxc_make(&r, &cs, 80 + 8 * ggxc_rnd(&r));
        cz = (cs.q[0][2] + cs.q[1][2] + cs.q[2][2] + cs.q[3][2]) / 4;
        for (i = 0; i < 4; ++i)
          cs.q[i][2] -= cz;
        cmp_d(cs.q, 4, cs.view, alphas[ia]);
      }
    report("grazing straddling 80-88", 1e-6);
  }
}

static void test_lanes_hemisphere_pentagon(void) {
  static const double views[3] = {30, 75, 88};
  static const double alphas[4] = {1e-4, 0.04, 0.3, 1.0};
  int iv, ia, c, i, k;
  for (iv = 0; iv < 3; ++iv)
    for (ia = 0; ia < 4; ++ia) {
      double t = views[iv] * 3.14159265358979323846 / 180;
      double q[4][3] = {{-1e4, -1e4, 1}, {1e4, -1e4, 1}, {1e4, 1e4, 1}, {-1e4, 1e4, 1}};
      double v[3];
      v[0] = sin(t), v[1] = 0, v[2] = cos(t);
      cmp_d(q, 4, v, alphas[ia]);
    }
  report("hemisphere-filling", 1e-6);
  for (c = 0; c < 200; ++c) { /* pentagons: a sampler quad with one side's midpoint pushed out */
    ggxc_rng r;
    ggxc_case cs;
    double p[5][3];
    r.s = 500u + (unsigned)c;
    ggxc_make(&r, &cs, -1);
    for (i = 0; i < 4; ++i)
      for (k = 0; k < 3; ++k)
        p[i < 2 ? i : i + 1][k] = cs.q[i][k];
    for (k = 0; k < 3; ++k)
      p[2][k] = 0.5 * (cs.q[1][k] + cs.q[2][k]) + 0.2 * (cs.q[1][k] - cs.q[0][k]);
    cmp_d(p, 5, cs.view, 0.0025 + 0.99 * ggxc_rnd(&r));
  }
  report("pentagons", 1e-6);
}

/* views past 88.85 deg (n.v < 0.02): the graded remainder at every alpha with its larger split
   budget, every piece's estimate from the remainder lanes (shli_ggx_tri4) */
static void test_lanes_past_8885(void) {
  static const double alphas[4] = {1e-4, 0.04, 0.2, 0.6};
  int ia, c, i;
  ggxc_rng r;
  r.s = 8885u;
  for (ia = 0; ia < 4; ++ia) {
    for (c = 0; c < 8;
         ++c) { /* sampler quads at 89-89.9 deg, half of them centred on the horizon */
      ggxc_case cs;
      double cz;
      ggxc_make(&r, &cs, 89 + 0.9 * ggxc_rnd(&r));
      cz = (cs.q[0][2] + cs.q[1][2] + cs.q[2][2] + cs.q[3][2]) / 4;
      for (i = 0; i < 4 && (c & 1) != 0; ++i)
        cs.q[i][2] -= cz;
      cmp_d(cs.q, 4, cs.view, alphas[ia]);
    }
    for (c = 0; c < 2; ++c) { /* a light filling the hemisphere at 89.5 and 89.9 deg */
      double t = (89.5 + 0.4 * c) * 3.14159265358979323846 / 180;
      double q[4][3] = {{-1e4, -1e4, 1}, {1e4, -1e4, 1}, {1e4, 1e4, 1}, {-1e4, 1e4, 1}};
      double v[3];
      v[0] = sin(t), v[1] = 0, v[2] = cos(t);
      cmp_d(q, 4, v, alphas[ia]);
    }
  }
  report("past 88.85 deg", 1e-6);
}

int main(void) {
  __builtin_cpu_init();
  if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma")) {
    printf("no AVX2 / FMA on this CPU: the edge lanes are not run\n");
    return tl_summary();
  }
  TL_RUN(test_lanes_sampler);
  TL_RUN(test_lanes_hard);
  TL_RUN(test_lanes_hemisphere_pentagon);
  TL_RUN(test_lanes_past_8885);
  printf("  %d calls compared\n", ncalls);
  return tl_summary();
}
