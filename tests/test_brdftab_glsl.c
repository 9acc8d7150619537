/* test_brdftab_glsl.c - the GLSL twin shlight_glsl/shl_brdftab.glsl against the C kernels on
   llvmpipe (compute path, n = 3): shl_brdf_table_lookup on an isotropic (8 theta_o samples) and
   an anisotropic (4 x 4) table passed as arrays, and the SSBO route of the GPU layout contract:
   shl_brdf_table_cell, the 4 weighted samples gathered straight from the storage buffer at
   (2 s + which) n^2 + i, then shl_sh_rotate_z for the isotropic table. Run from the repository
   root (tests/run.sh runs it).
   Tolerance 1e-5 absolute (table values in [-1, 1]): theta_o and phi_o come from the own atan2
   in float in GLSL (double in C), a few ulp of 1.6 rad = 5e-7 rad, times n_theta 2 / pi moves
   the weights by < 3e-6 and the result by < 6e-6; the z-rotation's angle recurrence adds ~1e-6. */
#include "../shlight.h"
#include "gl/glrun.h"
#include "tl.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define NI 512
#define NB 3
#define NN (NB * NB)
#define ISO (8 * 2 * NN)
#define ANI (4 * 4 * 2 * NN)
#define IN (ISO + ANI + 4)
#define OUTS (4 * NN + 1)

static unsigned int st = 777u;
static float rndf(void) {
  st = st * 1664525u + 1013904223u;
  return (float)(st >> 8) * (1.0f / 16777216.0f);
}

static void test_glsl_brdftab(void) {
  static float in[NI * IN], out[NI * OUTS], ref[NI * OUTS], iso[ISO], ani[ANI];
  const char *files[6] = {"shlight_glsl/shl_prelude.glsl",  "shlight_glsl/shl_basis.glsl",
                          "shlight_glsl/shl_gradient.glsl", "shlight_glsl/shl_zonal.glsl",
                          "shlight_glsl/shl_light.glsl",    "shlight_glsl/shl_brdftab.glsl"};
  const char *defines = "#define SHLIGHT_MAX_BANDS 3\n#define SHLIGHT_BRDF_TABLE_FLOATS 288\n";
  const char *main_src =
      "void glrun_main(int item) {\n"
      "  float ti[SHLIGHT_BRDF_TABLE_FLOATS];\n"
      "  float ta[SHLIGHT_BRDF_TABLE_FLOATS];\n"
      "  float o[SHLIGHT_MAX_COEFFS];\n"
      "  int idx[4];\n"
      "  float w[4];\n"
      "  int k;\n"
      "  int j;\n"
      "  int base = item * GLRUN_IN_STRIDE;\n"
      "  for (k = 0; k < 288; ++k) {\n"
      "    ti[k] = k < 144 ? in_float(k) : 0.0;\n"
      "    ta[k] = in_float(144 + k);\n"
      "  }\n"
      "  vec3 wo = vec3(in_float(432), in_float(433), in_float(434));\n"
      "  int which = int(in_float(435));\n"
      "  shl_brdf_table_lookup(3, 8, 1, which, ti, wo, o);\n"
      "  for (k = 0; k < 9; ++k) out_float(k, o[k]);\n"
      "  shl_brdf_table_lookup(3, 4, 4, which, ta, wo, o);\n"
      "  for (k = 0; k < 9; ++k) out_float(9 + k, o[k]);\n"
      "  shl_brdf_table_cell(4, 4, wo, idx, w);\n"
      "  out_float(36, w[0] + w[1] + w[2] + w[3]);\n"
      "  for (k = 0; k < 9; ++k) {\n"
      "    float s = 0.0;\n"
      "    for (j = 0; j < 4; ++j) s += w[j] * glrun_in[base + 144 + (2 * idx[j] + which) * 9 + "
      "k];\n"
      "    out_float(18 + k, s);\n"
      "  }\n"
      "  shl_brdf_table_cell(8, 1, wo, idx, w);\n"
      "  for (k = 0; k < 9; ++k) {\n"
      "    float s = 0.0;\n"
      "    for (j = 0; j < 4; ++j) s += w[j] * glrun_in[base + (2 * idx[j] + which) * 9 + k];\n"
      "    o[k] = s;\n"
      "  }\n"
      "  float rho = length(wo.xy);\n"
      "  if (rho > 0.0) shl_sh_rotate_z(3, wo.x / rho, wo.y / rho, o);\n"
      "  for (k = 0; k < 9; ++k) out_float(27 + k, o[k]);\n"
      "}\n";
  int i, k, bad = 0;
  double worst = 0.0;
  for (k = 0; k < ISO; ++k)
    iso[k] = 2.0f * rndf() - 1.0f;
  for (k = 0; k < ANI; ++k)
    ani[k] = 2.0f * rndf() - 1.0f;
  for (i = 0; i < NI; ++i) {
    float *p = in + i * IN, *r = ref + i * OUTS, wo[3];
    memcpy(p, iso, sizeof iso);
    memcpy(p + ISO, ani, sizeof ani);
    if (i == 0) { /* pole, zero vector, below the horizon, grazing */
      wo[0] = 0.0f;
      wo[1] = 0.0f;
      wo[2] = 1.0f;
    } else if (i == 1) {
      wo[0] = wo[1] = wo[2] = 0.0f;
    } else if (i == 2) {
      wo[0] = 0.3f;
      wo[1] = -0.2f;
      wo[2] = -0.9f;
    } else if (i == 3) {
      wo[0] = -1.0f;
      wo[1] = 0.0f;
      wo[2] = 0.0f;
    } else {
      float z = rndf(), ph = 6.2831853f * rndf(), s = sqrtf(1.0f - z * z);
      wo[0] = s * cosf(ph);
      wo[1] = s * sinf(ph);
      wo[2] = z;
    }
    p[ISO + ANI] = wo[0];
    p[ISO + ANI + 1] = wo[1];
    p[ISO + ANI + 2] = wo[2];
    p[ISO + ANI + 3] = (float)(i & 1);
    shl_brdf_table_lookup(NB, 8, 1, i & 1, iso, wo, r);
    shl_brdf_table_lookup(NB, 4, 4, i & 1, ani, wo, r + NN);
    shl_brdf_table_lookup(NB, 4, 4, i & 1, ani, wo, r + 2 * NN); /* the SSBO route: same values */
    shl_brdf_table_lookup(NB, 8, 1, i & 1, iso, wo, r + 3 * NN);
    r[4 * NN] = 1.0f;
  }
  TL_CHECK(glrun_compute(defines, files, 6, main_src, in, (size_t)NI * IN, out, (size_t)NI * OUTS,
                         NI) == 0,
           "glrun: %s", glrun_last_log());
  for (i = 0; i < NI * OUTS; ++i) {
    double e = fabs((double)out[i] - (double)ref[i]);
    if (!(e <= worst)) worst = e;
    if (!(e <= 1e-5)) bad++;
  }
  printf("  %s: max |GLSL - C| = %.3g over %d outputs\n", glrun_renderer(), worst, NI * OUTS);
  TL_CHECK(bad == 0, "%d outputs differ beyond 1e-5 (worst %g)", bad, worst);
}

int main(void) {
  TL_RUN(test_glsl_brdftab);
  glrun_close();
  return tl_summary();
}
