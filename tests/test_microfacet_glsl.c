/* test_microfacet_glsl.c - the GLSL twins of shl_polygon_blinn_phong,
   shl_polygon_beckmann_subedges, shl_polygon_beckmann and shl_polygon_beckmann_ndf
   (shlight_glsl/shl_edge.glsl) against the C kernels on llvmpipe (compute path), on random quads
   around the mirror direction: front, grazing and horizon-straddling views, Blinn-Phong
   exponents 1..3000, Beckmann alpha 0.03..1, k = 2 and 8 sub-edges. GLSL runs shli_real as float, C
   as double: differences are in units of the albedo-scale result (Blinn-Phong and Beckmann give at
   most ~1 for a hemisphere light) and of the normalised lobe (NDF). One call site per kernel:
   llvmpipe compiles each inlined copy of the half-vector sums in seconds. Run from the repository
   root (tests/run.sh runs it). */
#include "../shlight.h"
#include "gl/glrun.h"
#include "tl.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define NI 96
#define IN 20 /* 12 vertex floats, normal (3), view (3), exponent, alpha */
#define OUTS 6
#define TOL 7.5e-5 /* 3x the measured 2.4e-5 (Beckmann in float: exp, the A&S Lambda) */

static unsigned int st = 4242u;
static float rndf(void) {
  st = st * 1664525u + 1013904223u;
  return (float)(st >> 8) * (1.0f / 16777216.0f);
}

static void test_glsl_microfacet(void) {
  static float in[NI * IN], out[NI * OUTS], ref[NI * OUTS];
  static const float es[6] = {1.0f, 5.0f, 30.0f, 120.0f, 700.0f, 3000.0f};
  static const float als[6] = {1.0f, 0.6f, 0.3f, 0.15f, 0.07f, 0.03f};
  const char *files[6] = {"shlight_glsl/shl_prelude.glsl",  "shlight_glsl/shl_basis.glsl",
                          "shlight_glsl/shl_gradient.glsl", "shlight_glsl/shl_zonal.glsl",
                          "shlight_glsl/shl_light.glsl",    "shlight_glsl/shl_edge.glsl"};
  const char *defines = "#define SHLIGHT_MAX_BANDS 3\n";
  const char *main_src =
      "void glrun_main(int item) {\n"
      "  vec3 v[SHLIGHT_POLYGON_MAX];\n"
      "  int k;\n"
      "  for (k = 0; k < SHLIGHT_POLYGON_MAX; ++k)\n"
      "    v[k] = vec3(0.0);\n"
      "  for (k = 0; k < 4; ++k)\n"
      "    v[k] = vec3(in_float(3 * k), in_float(3 * k + 1), in_float(3 * k + 2));\n"
      "  vec3 n = vec3(in_float(12), in_float(13), in_float(14));\n"
      "  vec3 vw = vec3(in_float(15), in_float(16), in_float(17));\n"
      "  for (k = 0; k < 2; ++k)\n"
      "    out_float(k, shl_polygon_blinn_phong(v, 4, n, vw, in_float(18), k == 0 ? 2 : 8));\n"
      "  for (k = 0; k < 2; ++k)\n"
      "    out_float(2 + k, shl_polygon_beckmann_subedges(v, 4, n, vw, in_float(19), k == 0 ? -2 : "
      "8));\n"
      "  out_float(4, shl_polygon_beckmann_ndf(v, 4, n, in_float(19)));\n"
      "  out_float(5, shl_polygon_beckmann(v, 4, n, vw, in_float(19)));\n"
      "}\n";
  int i, k, bad = 0;
  double worst[OUTS] = {0, 0, 0, 0, 0, 0};
  for (i = 0; i < NI; ++i) {
    float *p = in + i * IN, th, ph = 6.2831853f * rndf(), r[3], c[3], t1[3], t2[3], d, s, l;
    int cfg = i % 3;
    memset(p, 0, sizeof(float) * IN);
    th = cfg == 1 ? acosf(0.03f + 0.2f * rndf()) : acosf(0.3f + 0.7f * rndf());
    p[12] = 0, p[13] = 0, p[14] = 1;
    p[15] = sinf(th) * cosf(ph), p[16] = sinf(th) * sinf(ph), p[17] = cosf(th);
    r[0] = -p[15], r[1] = -p[16], r[2] = p[17];
    for (k = 0; k < 3; ++k)
      c[k] = r[k] + 0.4f * (rndf() - 0.5f);
    if (cfg == 2) c[2] = 0.05f * (rndf() - 0.5f);
    l = sqrtf(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    d = 1.0f + 2.0f * rndf();
    for (k = 0; k < 3; ++k)
      c[k] = c[k] / l * d;
    t1[0] = c[1], t1[1] = -c[0], t1[2] = 0;
    l = sqrtf(t1[0] * t1[0] + t1[1] * t1[1]);
    t1[0] /= l, t1[1] /= l;
    t2[0] = c[1] * t1[2] - c[2] * t1[1], t2[1] = c[2] * t1[0] - c[0] * t1[2],
    t2[2] = c[0] * t1[1] - c[1] * t1[0];
    l = sqrtf(t2[0] * t2[0] + t2[1] * t2[1] + t2[2] * t2[2]);
    s = d * (0.1f + 0.6f * rndf());
    for (k = 0; k < 4; ++k) {
      float a = (k == 0 || k == 3) ? -1.0f : 1.0f, b = k < 2 ? -1.0f : 1.0f;
      int j;
      for (j = 0; j < 3; ++j)
        p[3 * k + j] = c[j] + s * (a * t1[j] + b * 0.7f * t2[j] / l);
    }
    p[18] = es[i % 6];
    p[19] = als[(i / 2) % 6];
    {
      const float(*v)[3] = (const float(*)[3])p;
      float *o = ref + i * OUTS;
      o[0] = shl_polygon_blinn_phong(v, 4, p + 12, p + 15, p[18], 2);
      o[1] = shl_polygon_blinn_phong(v, 4, p + 12, p + 15, p[18], 8);
      o[2] = shl_polygon_beckmann_subedges(v, 4, p + 12, p + 15, p[19], -2);
      o[3] = shl_polygon_beckmann_subedges(v, 4, p + 12, p + 15, p[19], 8);
      o[4] = shl_polygon_beckmann_ndf(v, 4, p + 12, p[19]);
      o[5] = shl_polygon_beckmann(v, 4, p + 12, p + 15, p[19]);
    }
  }
  TL_CHECK(glrun_compute(defines, files, 6, main_src, in, (size_t)NI * IN, out, (size_t)NI * OUTS,
                         NI) == 0,
           "glrun: %s", glrun_last_log());
  for (i = 0; i < NI; ++i)
    for (k = 0; k < OUTS; ++k) {
      double dd = fabs((double)out[i * OUTS + k] - (double)ref[i * OUTS + k]);
      if (dd > worst[k]) worst[k] = dd;
      if (!(dd <= TOL)) {
        bad++;
        if (bad < 6)
          printf("  item %d output %d: GLSL %.7g C %.7g (e %g, alpha %g)\n", i, k,
                 out[i * OUTS + k], ref[i * OUTS + k], in[i * IN + 18], in[i * IN + 19]);
      }
    }
  printf("  %s: max |GLSL - C|: Blinn-Phong k=2 %.2e, k=8 %.2e; Beckmann k=-2 %.2e, k=8 %.2e;"
         " Beckmann NDF %.2e; Beckmann Taylor %.2e\n",
         glrun_renderer(), worst[0], worst[1], worst[2], worst[3], worst[4], worst[5]);
  TL_CHECK(bad == 0, "%d outputs differ beyond %.1e", bad, TOL);
}

int main(void) {
  TL_RUN(test_glsl_microfacet);
  glrun_close();
  return tl_summary();
}
