/* test_ggx_glsl.c - the GLSL twin of shl_polygon_ggx (shlight_glsl/shl_edge.glsl) against the C
   kernel on llvmpipe (compute path): quads of the research sampler (tests/ref/ggxcases.h) at
   random roughness 0.03..1 (a quarter of them at grazing views, 80-88 deg), wide lights at views
   85-89.5 deg, plus the same lights moved just below the horizon (both sides must give exactly 0).
   GLSL runs shli_real as float, C as double: the tolerance is on |GLSL - C| in absolute terms (the
   values are in [0, 1], the directional albedo of these roughness values is 0.33..1, so this is
   close to error / albedo). Run from the repository root (tests/run.sh runs it). */
#include "../shlight.h"
#include "gl/glrun.h"
#include "ref/ggxcases.h"
#include "tl.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NI 256
#define IN 16 /* 12 vertex floats, view (3), alpha */
#define OUTS 2

typedef float (*ggx_fn)(const float (*v)[3], int nv, const float nrm[3], const float view[3],
                        float alpha);

/* the GLSL function `name` against its C kernel f on NI quads (seed: the sampler's), both
   passes (the quad, then moved below the horizon); |GLSL - C| asserted below tol. graze: n
   wide lights (a 2e4 x 2e4 quad at height 1, a wall straddling the horizon) at views 85-89.5
   deg, alpha >= 0.01 instead (GLSL's split budget past 88.85 deg is a quarter of C's) */
static void glsl_vs_c(const char *name, ggx_fn f, unsigned seed, double tol, int graze, int n) {
  static const float wide[2][4][3] = {
      {{-1e4f, -1e4f, 1}, {1e4f, -1e4f, 1}, {1e4f, 1e4f, 1}, {-1e4f, 1e4f, 1}},
      {{-2, -3, -1}, {-2, 3, -1}, {-2, 3, 2}, {-2, -3, 2}}};
  static float in[NI * IN], out[NI * OUTS], ref[NI * OUTS];
  static char main_src[1024];
  const char *files[6] = {"shlight_glsl/shl_prelude.glsl",  "shlight_glsl/shl_basis.glsl",
                          "shlight_glsl/shl_gradient.glsl", "shlight_glsl/shl_zonal.glsl",
                          "shlight_glsl/shl_light.glsl",    "shlight_glsl/shl_edge.glsl"};
  const float nrm[3] = {0, 0, 1};
  ggxc_rng r;
  int i, k, bad = 0, nz = 0;
  double worst = 0, worst_rel = 0;
  snprintf(main_src, sizeof main_src,
           "void glrun_main(int item) {\n"
           "  vec3 v[SHLIGHT_POLYGON_MAX];\n"
           "  int k;\n"
           "  for (k = 0; k < SHLIGHT_POLYGON_MAX; ++k) v[k] = vec3(0.0);\n"
           "  for (k = 0; k < 4; ++k)\n"
           "    v[k] = vec3(in_float(3 * k), in_float(3 * k + 1), in_float(3 * k + 2));\n"
           "  vec3 vw = vec3(in_float(12), in_float(13), in_float(14));\n"
           "  float a = in_float(15);\n"
           "  float top = max(max(v[0].z, v[1].z), max(v[2].z, v[3].z)) + 0.01;\n"
           "  int pass;\n"
           "  for (pass = 0; pass < 2; ++pass) { /* one call site: llvmpipe inlines each */\n"
           "    out_float(pass, %s(v, 4, vec3(0.0, 0.0, 1.0), vw, a));\n"
           "    for (k = 0; k < 4; ++k) v[k].z = v[k].z - top; /* all below the horizon */\n"
           "  }\n"
           "}\n",
           name);
  r.s = seed;
  for (i = 0; i < n; ++i) {
    ggxc_case cs;
    float *p = in + i * IN, below[4][3], top;
    double rough = 0.03 + 0.97 * ggxc_rnd(&r), t;
    ggxc_make(&r, &cs, i % 4 == 3 ? 80 + 8 * ggxc_rnd(&r) : -1);
    for (k = 0; k < 12; ++k)
      p[k] = graze ? wide[i % 2][k / 3][k % 3] : (float)cs.q[k / 3][k % 3];
    for (k = 0; k < 3; ++k)
      p[12 + k] = (float)cs.view[k];
    if (graze) {
      t = (85 + 4.5 * ggxc_rnd(&r)) / 57.29577951308232;
      p[12] = (float)sin(t), p[13] = 0.0f, p[14] = (float)cos(t);
    }
    p[15] = (float)(graze ? fmax(rough * rough, 0.01) : rough * rough);
    ref[i * OUTS] = f((const float(*)[3])p, 4, nrm, p + 12, p[15]);
    top = fmaxf(fmaxf(p[2], p[5]), fmaxf(p[8], p[11])) + 0.01f;
    for (k = 0; k < 12; ++k)
      below[k / 3][k % 3] = p[k] - (k % 3 == 2 ? top : 0.0f);
    ref[i * OUTS + 1] = f((const float(*)[3])below, 4, nrm, p + 12, p[15]);
  }
  TL_CHECK(glrun_compute("#define SHLIGHT_MAX_BANDS 3\n", files, 6, main_src, in, (size_t)n * IN,
                         out, (size_t)n * OUTS, n) == 0,
           "glrun: %s", glrun_last_log());
  for (i = 0; i < n; ++i) {
    double c = ref[i * OUTS], g = out[i * OUTS], d = fabs(g - c);
    if (d > worst) worst = d;
    if (c >= 0.01 && d / c > worst_rel) worst_rel = d / c;
    if (!(d <= tol)) {
      bad++;
      if (bad < 6)
        printf("  item %d: GLSL %.7g C %.7g (alpha %g, view z %g)\n", i, g, c, in[i * IN + 15],
               in[i * IN + 14]);
    }
    if (out[i * OUTS + 1] != 0.0f || ref[i * OUTS + 1] != 0.0f) nz++;
  }
  printf("  %s%s, %s: max |GLSL - C| %.2e, max relative (C >= 0.01) %.2e; below the horizon: %d "
         "non-zero\n",
         name, graze ? " (wide lights, 85-89.5 deg)" : "", glrun_renderer(), worst, worst_rel, nz);
  TL_CHECK(bad == 0, "%s: %d outputs differ beyond %g", name, bad, tol);
  TL_CHECK(nz == 0, "%s: %d lights below the horizon gave light", name, nz);
}

/* measured 2.5e-5 (llvmpipe, float inside vs C's double) */
static void test_glsl_ggx(void) {
  glsl_vs_c("shl_polygon_ggx", shl_polygon_ggx, 31337u, 7.5e-5, 0, NI);
}

/* wide lights at views 85-89.5 deg (the graded remainder, g = 0 past 88.85 deg): measured
   2.7e-4 (1.3e-3 to 2.3e-3 with three other seeds; float inside) */
static void test_glsl_ggx_graze(void) {
  glsl_vs_c("shl_polygon_ggx", shl_polygon_ggx, 4711u, 7e-3, 1, 48);
}

/* the table-free LTC: measured 8.6e-7 */
static void test_glsl_ggx_fast(void) {
  glsl_vs_c("shl_polygon_ggx_fast", shl_polygon_ggx_fast, 31338u, 5e-6, 0, NI);
}

int main(void) {
  TL_RUN(test_glsl_ggx);
  TL_RUN(test_glsl_ggx_graze);
  TL_RUN(test_glsl_ggx_fast);
  glrun_close();
  return tl_summary();
}
