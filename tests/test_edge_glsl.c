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

/* llvmpipe's loop limit: Mesa's gallivm ends every loop of a shader invocation (a vector of 8
   lanes) once all its loops together have run 65535 iterations, with no error. A shader that
   calls the edge kernels for many lights in a loop (shlrender's area pass: 120 lights of
   manylights, two octagons per sphere light, two methods each) runs out and returns partial
   sums; that was the manylights GL area regression (0.24 of the peak), the kernels themselves
   agree with C. The inputs are that scene's: a floor point under a sphere light of radius 0.05
   drawn as the octagon of shl_sphere_phong (1.0539686 rho about the centre), one of its
   triangle lights, exponents 1 and 60. Groups of 8 items (one vector) share a case:
     mode 0: one call, then a counting loop: 65535 - its count = the loop iterations used;
     mode 1: K calls summed in a loop (K within the budget), then a sentinel loop of 2;
     mode 2: K calls past the budget: the sentinel runs once (llvmpipe only).
   Checked: the single value and the in-budget sum against C, the iterations per call against
   a bound (about 1.25x the measured: the renderer draws fewer lights at a time when they
   grow), the sentinel in both directions. */
#define LB_CASES 7
#define LB_IN 32 /* 24 vertex floats, nv, method, exponent, mode, calls, loop count */
static void test_glsl_loop_budget(void) {
  static float in[8 * LB_CASES * LB_IN], out[8 * LB_CASES * 4];
  /* octagon exact e = 1, octagon quadrature e = 1, triangle exact e = 1, octagon exact e = 60,
     then the octagon exact e = 1 summed 64 times (within) and 1200 times (past the budget), and
     no call (the harness's own iterations, subtracted from the others) */
  static const int nvs[LB_CASES] = {8, 8, 3, 8, 8, 8, 8};
  static const int meths[LB_CASES] = {
      SHLIGHT_EDGE_EXACT, SHLIGHT_EDGE_QUADRATURE, SHLIGHT_EDGE_EXACT, SHLIGHT_EDGE_EXACT,
      SHLIGHT_EDGE_EXACT, SHLIGHT_EDGE_EXACT,      SHLIGHT_EDGE_EXACT};
  static const float exps[LB_CASES] = {1.0f, 1.0f, 1.0f, 60.0f, 1.0f, 1.0f, 1.0f};
  static const int modes[LB_CASES] = {0, 0, 0, 0, 1, 2, 0};
  static const int calls[LB_CASES] = {1, 1, 1, 1, 64, 1200, 0};
  /* iterations per call, about 1.25x the measured on llvmpipe 15: 80, 96, 40, 312 (with four
     inlined copies of the 5-node rule per half-arc, three half-arcs per edge and two clip call
     sites: 164, 164, 74, 396; every loop in the inlined code costs at least one iteration,
     taken or not, as llvmpipe runs both sides of a branch under a mask) */
  static const double bound[4] = {100.0, 120.0, 50.0, 390.0};
  const char *files[6] = {"shlight_glsl/shl_prelude.glsl",  "shlight_glsl/shl_basis.glsl",
                          "shlight_glsl/shl_gradient.glsl", "shlight_glsl/shl_zonal.glsl",
                          "shlight_glsl/shl_light.glsl",    "shlight_glsl/shl_edge.glsl"};
  const char *main_src =
      "void glrun_main(int item) {\n"
      "  vec3 v[SHLIGHT_POLYGON_MAX];\n"
      "  for (int k = 0; k < SHLIGHT_POLYGON_MAX; ++k)\n"
      "    v[k] = vec3(in_float(3 * k), in_float(3 * k + 1), in_float(3 * k + 2));\n"
      "  int nv = int(in_float(24));\n"
      "  int m = int(in_float(25));\n"
      "  float e = in_float(26);\n"
      "  int calls = int(in_float(28));\n"
      "  int count = int(in_float(29));\n"
      "  vec3 nrm = vec3(0.0, 1.0, 0.0);\n"
      "  vec3 vw = vec3(0.0, 0.8, 0.6);\n"
      "  float t = 0.0;\n"
      "  for (int r = 0; r < calls; ++r)\n"
      "    t = t + shl_polygon_phong(v, nv, nrm, vw, e, m);\n"
      "  int c = 0;\n"
      "  for (int i = 0; i < count; ++i)\n"
      "    c = c + 1;\n"
      "  out_float(0, t);\n"
      "  out_float(1, float(c));\n"
      "}\n";
  const float nrm[3] = {0.0f, 1.0f, 0.0f}, vw[3] = {0.0f, 0.8f, 0.6f};
  float oct[8][3], tri[3][3], ref[LB_CASES];
  double base;
  int i, k, q, llvmpipe = strstr(glrun_renderer(), "llvmpipe") != NULL;
  { /* the sphere light (-0.25, 1.45, 0.25), r = 0.05, seen from the origin */
    const double c[3] = {-0.25, 1.45, 0.25}, r = 0.05;
    double d = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]), rho = r * d / sqrt(d * d - r * r);
    double u[3] = {c[0] / d, c[1] / d, c[2] / d}, a[3], b[3], l;
    a[0] = u[1]; /* a = normalise(u x z), b = u x a */
    a[1] = -u[0];
    a[2] = 0.0;
    l = sqrt(a[0] * a[0] + a[1] * a[1]);
    a[0] /= l;
    a[1] /= l;
    b[0] = u[1] * a[2] - u[2] * a[1];
    b[1] = u[2] * a[0] - u[0] * a[2];
    b[2] = u[0] * a[1] - u[1] * a[0];
    for (k = 0; k < 8; ++k) {
      double cs = 1.0539686339182901 * rho * cos(0.39269908169872415 * (2 * k)),
             sn = 1.0539686339182901 * rho * sin(0.39269908169872415 * (2 * k));
      for (q = 0; q < 3; ++q)
        oct[k][q] = (float)(c[q] + cs * a[q] + sn * b[q]);
    }
  }
  { /* triangle light 3 of manylights from the floor point (0.1, 0, 0.2) */
    const float x = -2.0f + 0.21f * 3.0f, z = 1.8f * cosf(2.1f), y = 1.0f;
    const float t9[9] = {x, y, z, x + 0.12f, y + 0.02f, z, x + 0.05f, y - 0.01f, z + 0.1f};
    for (k = 0; k < 3; ++k) {
      tri[k][0] = t9[3 * k] - 0.1f;
      tri[k][1] = t9[3 * k + 1];
      tri[k][2] = t9[3 * k + 2] - 0.2f;
    }
  }
  memset(in, 0, sizeof in);
  for (q = 0; q < LB_CASES; ++q) {
    const float(*v)[3] = nvs[q] == 8 ? (const float(*)[3])oct : (const float(*)[3])tri;
    ref[q] = shl_polygon_phong(v, nvs[q], nrm, vw, exps[q], (shl_edge_method)meths[q]);
    for (i = 0; i < 8; ++i) {
      float *p = in + (8 * q + i) * LB_IN;
      for (k = 0; k < nvs[q]; ++k)
        memcpy(p + 3 * k, v[k], sizeof(float) * 3);
      p[24] = (float)nvs[q];
      p[25] = (float)meths[q];
      p[26] = exps[q];
      p[27] = (float)modes[q];
      p[28] = (float)calls[q];
      p[29] = modes[q] == 0 ? 70000.0f : 2.0f;
    }
  }
  TL_CHECK(glrun_compute("#define SHLIGHT_MAX_BANDS 1\n", files, 6, main_src, in,
                         sizeof in / sizeof in[0], out, sizeof out / sizeof out[0],
                         8 * LB_CASES) == 0,
           "glrun: %s", glrun_last_log());
  base = 65535.0 - (double)out[8 * (LB_CASES - 1) * 4 + 1];
  for (q = 0; q < LB_CASES - 1; ++q) {
    const float *o = out + 8 * q * 4;
    double d = fabs((double)o[0] - (double)calls[q] * (double)ref[q]) / (double)calls[q];
    if (modes[q] == 0) {
      double used = 65535.0 - (double)o[1] - base;
      printf("  %s, %s, exponent %g: GLSL %.7g C %.7g, %g loop iterations per call\n",
             nvs[q] == 8 ? "octagon" : "triangle",
             meths[q] == SHLIGHT_EDGE_EXACT ? "exact" : "quadrature", exps[q], o[0], ref[q], used);
      TL_CHECK(d <= 2e-5 * (1.0 + fabs((double)ref[q])), "case %d: GLSL %.7g C %.7g", q, o[0],
               ref[q]);
      if (llvmpipe)
        TL_CHECK(used > 0.0 && used <= bound[q], "case %d: %g loop iterations (bound %g)", q, used,
                 bound[q]);
    } else if (modes[q] == 1) {
      printf("  %d calls summed: GLSL %.7g, %d x C %.7g, sentinel %g (2: within the budget)\n",
             calls[q], o[0], calls[q], (double)calls[q] * ref[q], o[1]);
      TL_CHECK(d <= 2e-5 * (1.0 + fabs((double)ref[q])) && o[1] == 2.0f,
               "%d calls: GLSL %.7g, C %.7g, sentinel %g", calls[q], o[0],
               (double)calls[q] * ref[q], o[1]);
    } else {
      printf("  %d calls summed: GLSL %.7g, %d x C %.7g, sentinel %g (%s)\n", calls[q], o[0],
             calls[q], (double)calls[q] * ref[q], o[1],
             llvmpipe ? "1: llvmpipe's limit reached" : "no limit expected");
      if (llvmpipe)
        TL_CHECK(o[1] == 1.0f && (double)o[0] < 0.9 * (double)calls[q] * (double)ref[q],
                 "past the budget: GLSL %.7g, sentinel %g (want 1)", o[0], o[1]);
      else
        TL_CHECK(o[1] == 2.0f, "sentinel %g without a loop limit", o[1]);
    }
  }
}

int main(void) {
  TL_RUN(test_glsl_edge);
  TL_RUN(test_glsl_loop_budget);
  glrun_close();
  return tl_summary();
}
