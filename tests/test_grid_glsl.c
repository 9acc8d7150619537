/* test_grid_glsl.c - the GLSL twin shlight_glsl/shl_grid.glsl against the C kernels on
   llvmpipe (compute path, n = 3). Run from the repository root (tests/run.sh runs it). */
#include "../shlight.h"
#include "gl/glrun.h"
#include "tl.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define NI 256
#define NB 3
#define NN (NB * NB)
#define IN (8 * NN + 24 * NN + 6)
#define OUTS (3 * NN)

static unsigned int st = 12345u;
static float rndf(void) {
  st = st * 1664525u + 1013904223u;
  return (float)(st >> 8) * (1.0f / 16777216.0f);
}

static void test_glsl_grid(void) {
  static float in[NI * IN], out[NI * OUTS], ref[NI * OUTS];
  const char *files[3] = {"shlight_glsl/shl_prelude.glsl", "shlight_glsl/shl_basis.glsl",
                          "shlight_glsl/shl_grid.glsl"};
  const char *defines = "#define SHLIGHT_MAX_BANDS 3\n";
  const char *main_src =
      "void glrun_main(int item) {\n"
      "  float c8[8 * SHLIGHT_MAX_COEFFS];\n"
      "  vec3 g8[8 * SHLIGHT_MAX_COEFFS];\n"
      "  float o[SHLIGHT_MAX_COEFFS];\n"
      "  int k;\n"
      "  int b = 8 * SHLIGHT_MAX_COEFFS;\n"
      "  for (k = 0; k < b; ++k) {\n"
      "    c8[k] = in_float(k);\n"
      "    g8[k] = vec3(in_float(b + 3 * k), in_float(b + 3 * k + 1), in_float(b + 3 * k + 2));\n"
      "  }\n"
      "  vec3 f = vec3(in_float(4 * b), in_float(4 * b + 1), in_float(4 * b + 2));\n"
      "  vec3 cell = vec3(in_float(4 * b + 3), in_float(4 * b + 4), in_float(4 * b + 5));\n"
      "  shl_grid_trilinear(3, c8, f, o);\n"
      "  for (k = 0; k < 9; ++k) out_float(k, o[k]);\n"
      "  shl_grid_taylor(3, c8, g8, f, cell, o);\n"
      "  for (k = 0; k < 9; ++k) out_float(9 + k, o[k]);\n"
      "  shl_grid_hermite(3, c8, g8, f, cell, o);\n"
      "  for (k = 0; k < 9; ++k) out_float(18 + k, o[k]);\n"
      "}\n";
  int i, k, bad = 0, nbit = 0;
  double worst = 0.0;
  for (i = 0; i < NI; ++i) {
    float *p = in + i * IN;
    for (k = 0; k < 8 * NN; ++k)
      p[k] = 2.0f * rndf() - 1.0f;
    for (k = 0; k < 24 * NN; ++k)
      p[8 * NN + k] = 4.0f * rndf() - 2.0f;
    for (k = 0; k < 3; ++k)
      p[32 * NN + k] = rndf();
    for (k = 0; k < 3; ++k)
      p[32 * NN + 3 + k] = 0.1f + rndf();
    shl_grid_trilinear(NB, p, p + 32 * NN, ref + i * OUTS);
    shl_grid_taylor(NB, p, (const float(*)[3])(p + 8 * NN), p + 32 * NN, p + 32 * NN + 3,
                    ref + i * OUTS + NN);
    shl_grid_hermite(NB, p, (const float(*)[3])(p + 8 * NN), p + 32 * NN, p + 32 * NN + 3,
                     ref + i * OUTS + 2 * NN);
  }
  TL_CHECK(glrun_compute(defines, files, 3, main_src, in, (size_t)NI * IN, out, (size_t)NI * OUTS,
                         NI) == 0,
           "glrun: %s", glrun_last_log());
  for (i = 0; i < NI * OUTS; ++i) {
    double e = fabs((double)out[i] - (double)ref[i]);
    if (e > worst) worst = e;
    nbit += out[i] != ref[i];
    if (!(e <= 1e-6 * (1.0 + fabs((double)ref[i])))) bad++;
  }
  printf("  %s: max |GLSL - C| = %.3g, %d bitwise-different of %d\n", glrun_renderer(), worst, nbit,
         NI * OUTS);
  TL_CHECK(bad == 0, "%d outputs differ beyond 1e-6 (worst %g)", bad, worst);
}

int main(void) {
  TL_RUN(test_glsl_grid);
  glrun_close();
  return tl_summary();
}
