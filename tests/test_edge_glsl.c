/* test_edge_glsl.c - the GLSL twin shlight_glsl/shl_edge.glsl against the C kernels on
   llvmpipe (compute path). Polygon moments by the exact, Lorentzian-Pearson and quadrature
   methods, single-axis Phong and the edge integral, on random polygons (triangles, quads,
   non-convex 8-gons, lights straddling the axis hemisphere). GLSL runs shli_real as float,
   C as double: the tolerance below is in units of the normalised lobe, (e+1)/(2 pi) |diff|.
   Run from the repository root (tests/run.sh runs it). */
#include "../shlight.h"
#include "gl/glrun.h"
#include "tl.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define NI 192
#define IN 32 /* 24 vertex floats, nv, axis (3), exponent, view (3) */
#define OUTS 11

static unsigned int st = 777u;
static float rndf(void) {
  st = st * 1664525u + 1013904223u;
  return (float)(st >> 8) * (1.0f / 16777216.0f);
}

static void test_glsl_edge(void) {
  static float in[NI * IN], out[NI * OUTS], ref[NI * OUTS];
  static const float es[6] = {1.0f, 4.0f, 13.0f, 60.0f, 250.0f, 1500.0f};
  const char *files[6] = {"shlight_glsl/shl_prelude.glsl",  "shlight_glsl/shl_basis.glsl",
                          "shlight_glsl/shl_gradient.glsl", "shlight_glsl/shl_zonal.glsl",
                          "shlight_glsl/shl_light.glsl",    "shlight_glsl/shl_edge.glsl"};
  /* SHLIGHT_GLSL_SUBSET (tests/run.sh sets it for the second backend, the same llvmpipe
     compiler): without the FAST path (SHLIGHT_EDGE_FAST_ON), which llvmpipe takes ~14 s to
     compile */
  int fast = getenv("SHLIGHT_GLSL_SUBSET") == NULL;
  const char *defines = fast ? "#define SHLIGHT_MAX_BANDS 3\n#define SHLIGHT_EDGE_FAST_ON 1\n"
                             : "#define SHLIGHT_MAX_BANDS 3\n#define SKIP_FAST 1\n";
  const char *main_src =
      "void glrun_main(int item) {\n"
      "  vec3 v[SHLIGHT_POLYGON_MAX];\n"
      "  int k;\n"
      "  for (k = 0; k < SHLIGHT_POLYGON_MAX; ++k)\n"
      "    v[k] = vec3(in_float(3 * k), in_float(3 * k + 1), in_float(3 * k + 2));\n"
      "  int nv = int(in_float(24));\n"
      "  vec3 ax = vec3(in_float(25), in_float(26), in_float(27));\n"
      "  float e = in_float(28);\n"
      "  vec3 vw = vec3(in_float(29), in_float(30), in_float(31));\n"
      "  for (k = 0; k < 5; ++k) {\n"
      "    int m = k == 0 ? SHLIGHT_EDGE_EXACT : k == 1 ? SHLIGHT_EDGE_LORENTZ_PEARSON\n"
      "          : k == 2 ? SHLIGHT_EDGE_QUADRATURE : SHLIGHT_EDGE_AUTO;\n"
      "    float ek = k == 3 ? e + 0.5 : e;\n"
      "    int nk = k == 4 ? SHLIGHT_POLYGON_MAX + 1 : nv; /* above the GLSL maximum: -1 */\n"
      "    out_float(k == 4 ? 9 : k,\n"
      "              (k == 0 && e > 60.0) ? 0.0 : shl_polygon_moment(v, nk, ax, ek, m));\n"
      "  }\n"
      "  out_float(4, shl_polygon_phong(v, nv, ax, vw, e, SHLIGHT_EDGE_AUTO));\n"
      "  out_float(6, shl_sphere_phong(v[0], 0.3 * length(v[0]), ax, vw, e, SHLIGHT_EDGE_AUTO));\n"
      "  out_float(7, shl_polygon_phong_double_axis(v, nv, ax, vw, e, SHLIGHT_EDGE_AUTO));\n"
      "  out_float(8, shl_polygon_ggx_ndf(v, nv, ax, 0.02 + 0.001 * e));\n"
      "#ifndef SKIP_FAST\n"
      "  out_float(10, shl_polygon_phong(v, nv, ax, vw, e, SHLIGHT_EDGE_FAST));\n"
      "#else\n"
      "  out_float(10, 0.0);\n"
      "#endif\n"
      "  out_float(5, shl_edge_integral(in_float(0) + 1.5, in_float(1) * 0.5 + 0.5, in_float(2),\n"
      "                                 e, SHLIGHT_EDGE_LORENTZ_PEARSON));\n"
      "}\n";
  int i, k, bad = 0;
  double worst[OUTS] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  for (i = 0; i < NI; ++i) {
    float *p = in + i * IN, cx = 2 * rndf() - 1, cy = 2 * rndf() - 1, cz = 2 * rndf() - 0.5f;
    float rad = 0.1f + 1.2f * rndf(), e = es[i % 6], l, dv;
    int nv = 3 + (i % 3 == 2 ? 5 : i % 2);
    memset(p, 0, sizeof(float) * IN);
    for (k = 0; k < nv; ++k) {
      float a = 6.2831853f * ((float)k + 0.3f * rndf()) / (float)nv;
      float rr = (nv == 8 && (k & 1)) ? 0.4f * rad : rad;
      p[3 * k] = cx + rr * cosf(a);
      p[3 * k + 1] = cy + rr * sinf(a) * 0.8f;
      p[3 * k + 2] = cz + 0.3f * rr * cosf(a) + 0.2f * rr * sinf(a);
    }
    p[24] = (float)nv;
    p[25] = 0.3f * (2 * rndf() - 1);
    p[26] = 0.3f * (2 * rndf() - 1);
    p[27] = 1.0f;
    l = sqrtf(p[25] * p[25] + p[26] * p[26] + p[27] * p[27]);
    for (k = 25; k < 28; ++k)
      p[k] /= l;
    p[28] = e;
    p[29] = 2 * rndf() - 1;
    p[30] = 2 * rndf() - 1;
    p[31] = 1.0f;
    l = sqrtf(p[29] * p[29] + p[30] * p[30] + p[31] * p[31]);
    for (k = 29; k < 32; ++k)
      p[k] /= l;
    dv = p[29] * p[25] + p[30] * p[26] + p[31] * p[27];
    (void)dv;
    {
      const float(*v)[3] = (const float(*)[3])p;
      float *r = ref + i * OUTS;
      r[0] = e <= 60.0f ? shl_polygon_moment(v, nv, p + 25, e, SHLIGHT_EDGE_EXACT) : 0.0f;
      r[1] = shl_polygon_moment(v, nv, p + 25, e, SHLIGHT_EDGE_LORENTZ_PEARSON);
      r[2] = shl_polygon_moment(v, nv, p + 25, e, SHLIGHT_EDGE_QUADRATURE);
      r[3] = shl_polygon_moment(v, nv, p + 25, e + 0.5f, SHLIGHT_EDGE_AUTO);
      r[4] = shl_polygon_phong(v, nv, p + 25, p + 29, e, SHLIGHT_EDGE_AUTO);
      r[5] =
          shl_edge_integral(p[0] + 1.5f, p[1] * 0.5f + 0.5f, p[2], e, SHLIGHT_EDGE_LORENTZ_PEARSON);
      r[6] = shl_sphere_phong(p, 0.3f * sqrtf(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), p + 25,
                              p + 29, e, SHLIGHT_EDGE_AUTO);
      r[7] = shl_polygon_phong_double_axis(v, nv, p + 25, p + 29, e, SHLIGHT_EDGE_AUTO);
      r[8] = shl_polygon_ggx_ndf(v, nv, p + 25, 0.02f + 0.001f * e);
      r[9] = -1.0f; /* nv = SHLIGHT_POLYGON_MAX + 1 in GLSL: the documented -1 */
      r[10] = fast ? shl_polygon_phong(v, nv, p + 25, p + 29, e, SHLIGHT_EDGE_FAST) : 0.0f;
    }
  }
  TL_CHECK(glrun_compute(defines, files, 6, main_src, in, (size_t)NI * IN, out, (size_t)NI * OUTS,
                         NI) == 0,
           "glrun: %s", glrun_last_log());
  for (i = 0; i < NI; ++i) {
    double e = in[i * IN + 28], nrm = (e + 1) / 6.283185307179586;
    for (k = 0; k < OUTS; ++k) {
      double d = fabs((double)out[i * OUTS + k] - (double)ref[i * OUTS + k]);
      /* moments: normalised-lobe units; Phong is normalised already; F: relative to 1 + |F| */
      double s = (k < 4 || k == 9) ? d * ((k == 3 || k == 9) ? (e + 1.5) / 6.283185307179586 : nrm)
                                   : (k == 5 ? d / (1.0 + fabs((double)ref[i * OUTS + k])) : d);
      if (s > worst[k]) worst[k] = s;
      /* FAST: C's polynomial atan2 / sin / log1p / exp against GLSL's built-ins, 1.4e-6 */
      if (!(s <= 2e-5)) {
        bad++;
        if (bad < 6)
          printf("  item %d output %d: GLSL %.7g C %.7g (nv %g, e %g)\n", i, k, out[i * OUTS + k],
                 ref[i * OUTS + k], in[i * IN + 24], e);
      }
    }
  }
  printf("  %s: max |GLSL - C| (normalised): exact %.2e, Lorentzian-Pearson %.2e, quadrature %.2e,"
         " auto (e + 0.5) %.2e, Phong %.2e, F %.2e, sphere Phong %.2e, double-axis Phong %.2e,"
         " GGX NDF %.2e, nv > max (-1) %.1g, fast Phong %.2e\n",
         glrun_renderer(), worst[0], worst[1], worst[2], worst[3], worst[4], worst[5], worst[6],
         worst[7], worst[8], worst[9], worst[10]);
  TL_CHECK(bad == 0, "%d outputs differ beyond 2e-5 of the normalised lobe", bad);
}

int main(void) {
  TL_RUN(test_glsl_edge);
  glrun_close();
  return tl_summary();
}
