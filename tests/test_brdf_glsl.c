/* test_brdf_glsl.c - the GLSL twins shlight_glsl/shl_brdf.glsl and shl_hvl.glsl against the C
   kernels on llvmpipe (compute path, n = 8 bands, 64 random items). GLSL runs the recurrences,
   the trapezoidal rule and the own atan2 in float where C uses double, so the outputs differ by
   float rounding: the tolerances below are 2e-5 of each output's scale (1 for the lobes'
   K_l-normalised values and H, the product of the norms for the convolutions), measured
   worst cases printed. Run from the repository root (tests/run.sh runs it). */
#include "../shlight.h"
#include "gl/glrun.h"
#include "tl.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define NI 64
#define NB 8
#define NN (NB * NB)
/* inputs: e, alpha, z, r, d, fov, then u, v, nx, w (4 vec3 = 12), x, y, ny (9), p (3), dist,
   eps, pn (24), dn (8), zh (8), sh (64), sh2 (64) */
#define I_E 0
#define I_VEC 6
#define I_HV 18
#define I_P 27
#define I_PN 32
#define I_DN 56
#define I_ZH 64
#define I_SH 72
#define I_SH2 (72 + NN)
#define IN (72 + 2 * NN)
/* outputs: phong, cospow, lambert, blinn, ggx, beckmann, windowed zh (7 x 8), then scalars */
#define O_S 56
#define NS 16
#define O_M (O_S + NS) /* shl_sh_irradiance_matrix: 16 floats */
#define OUTS (O_M + 16)

static unsigned int st = 424242u;
static float rndf(void) {
  st = st * 1664525u + 1013904223u;
  return (float)(st >> 8) * (1.0f / 16777216.0f);
}

static void c_item(const float *p, float *o) {
  int k;
  float tmp[NB];
  shl_zh_phong(NB, p[0], o);
  shl_zh_cosine_power(NB, p[0], o + 8);
  shl_zh_lambert(NB, o + 16);
  shl_zh_blinn_phong(NB, p[0], o + 24);
  shl_zh_ggx(NB, p[1], o + 32);
  shl_zh_beckmann(NB, p[1], o + 40);
  for (k = 0; k < NB; ++k)
    tmp[k] = p[I_ZH + k];
  shl_zh_window(NB, 1 + (int)(p[5] > 0.5f), 0.0f, tmp);
  for (k = 0; k < NB; ++k)
    o[48 + k] = tmp[k];
  o[O_S + 0] = shl_sh_dot(NB, p + I_SH, p + I_SH2);
  o[O_S + 1] = shl_sh_conv_zh(NB, p + I_SH, p + I_ZH, p + I_VEC);
  o[O_S + 2] = shl_zh_dot_zh(NB, p + I_ZH, p + I_VEC, o + 32, p + I_VEC + 3);
  o[O_S + 3] = shl_zh_irradiance_quadratic(p + I_ZH, p[2]);
  o[O_S + 4] = shl_zh_irradiance(NB, p + I_ZH, p[2]);
  o[O_S + 5] = (float)shl_zh_bands_for(NB, o + 32, 1e-3f);
  o[O_S + 6] = shl_hvl_horizon(p + I_VEC + 6, p + I_VEC + 9, p[3], p[4]);
  o[O_S + 7] = shl_hvl_geometric(p + I_HV, p + I_VEC + 6, p + I_HV + 3, p + I_HV + 6, p[3], 1);
  o[O_S + 8] = shl_hvl_geometric(p + I_HV, p + I_VEC + 6, p + I_HV + 3, p + I_HV + 6, p[3], 0);
  o[O_S + 9] = shl_hvl_emission(NB, p + I_SH, p + I_VEC);
  o[O_S + 10] = shl_hvl_radiance(NB, p + I_SH, 2.0f, p + I_HV, p + I_VEC + 6, p + I_HV + 3,
                                 p + I_HV + 6, p[3], 1);
  o[O_S + 11] = shl_hvl_contribution(NB, 1.5f, p + I_SH2, p + I_HV, p + I_HV + 3, p[3]);
  o[O_S + 12] =
      shl_hvl_contribution_zh(NB, 1.5f, o + 32, p + I_VEC + 3, p + I_HV, p + I_HV + 3, p[3]);
  o[O_S + 13] = shl_hvl_radius_neighbours(8, p + I_P, p[I_P + 3], (const float(*)[3])(p + I_PN),
                                          p + I_DN, p[I_P + 4]);
  o[O_S + 14] = shl_hvl_radius_fov(p[4], p[5], 64);
  o[O_S + 15] = shl_hvl_radius_fov_tan(p[4], p[5], 64);
  shl_sh_irradiance_matrix(p + I_SH, o + O_M);
}

static void test_glsl_brdf(void) {
  static float in[NI * IN], out[NI * OUTS], ref[NI * OUTS];
  const char *files[7] = {"shlight_glsl/shl_prelude.glsl",  "shlight_glsl/shl_basis.glsl",
                          "shlight_glsl/shl_gradient.glsl", "shlight_glsl/shl_zonal.glsl",
                          "shlight_glsl/shl_light.glsl",    "shlight_glsl/shl_brdf.glsl",
                          "shlight_glsl/shl_hvl.glsl"};
  const char *defines = "#define SHLIGHT_MAX_BANDS 8\n";
  const char *main_src =
      "vec3 v3(int j) { return vec3(in_float(j), in_float(j + 1), in_float(j + 2)); }\n"
      "void glrun_main(int item) {\n"
      "  float z[SHLIGHT_MAX_BANDS];\n"
      "  float zh[SHLIGHT_MAX_BANDS];\n"
      "  float g[SHLIGHT_MAX_BANDS];\n"
      "  float sh[SHLIGHT_MAX_COEFFS];\n"
      "  float sh2[SHLIGHT_MAX_COEFFS];\n"
      "  float z3[3];\n"
      "  vec3 pn[8];\n"
      "  float dn[8];\n"
      "  int k;\n"
      "  float e = in_float(0);\n"
      "  float al = in_float(1);\n"
      "  for (k = 0; k < 8; ++k) { zh[k] = in_float(64 + k); pn[k] = v3(32 + 3 * k); dn[k] = "
      "in_float(56 + k); }\n"
      "  for (k = 0; k < 64; ++k) { sh[k] = in_float(72 + k); sh2[k] = in_float(136 + k); }\n"
      "  for (k = 0; k < 3; ++k) z3[k] = zh[k];\n"
      "  shl_zh_phong(8, e, z); for (k = 0; k < 8; ++k) out_float(k, z[k]);\n"
      "  shl_zh_cosine_power(8, e, z); for (k = 0; k < 8; ++k) out_float(8 + k, z[k]);\n"
      "  shl_zh_lambert(8, z); for (k = 0; k < 8; ++k) out_float(16 + k, z[k]);\n"
      "  shl_zh_blinn_phong(8, e, z); for (k = 0; k < 8; ++k) out_float(24 + k, z[k]);\n"
      "  shl_zh_ggx(8, al, g); for (k = 0; k < 8; ++k) out_float(32 + k, g[k]);\n"
      "  shl_zh_beckmann(8, al, z); for (k = 0; k < 8; ++k) out_float(40 + k, z[k]);\n"
      "  for (k = 0; k < 8; ++k) z[k] = zh[k];\n"
      "  shl_zh_window(8, in_float(5) > 0.5 ? 2 : 1, 0.0, z);\n"
      "  for (k = 0; k < 8; ++k) out_float(48 + k, z[k]);\n"
      "  out_float(56, shl_sh_dot(8, sh, sh2));\n"
      "  out_float(57, shl_sh_conv_zh(8, sh, zh, v3(6)));\n"
      "  out_float(58, shl_zh_dot_zh(8, zh, v3(6), g, v3(9)));\n"
      "  out_float(59, shl_zh_irradiance_quadratic(z3, in_float(2)));\n"
      "  out_float(60, shl_zh_irradiance(8, zh, in_float(2)));\n"
      "  out_float(61, float(shl_zh_bands_for(8, g, 1e-3)));\n"
      "  out_float(62, shl_hvl_horizon(v3(12), v3(15), in_float(3), in_float(4)));\n"
      "  out_float(63, shl_hvl_geometric(v3(18), v3(12), v3(21), v3(24), in_float(3), 1));\n"
      "  out_float(64, shl_hvl_geometric(v3(18), v3(12), v3(21), v3(24), in_float(3), 0));\n"
      "  out_float(65, shl_hvl_emission(8, sh, v3(6)));\n"
      "  out_float(66, shl_hvl_radiance(8, sh, 2.0, v3(18), v3(12), v3(21), v3(24), in_float(3), "
      "1));\n"
      "  out_float(67, shl_hvl_contribution(8, 1.5, sh2, v3(18), v3(21), in_float(3)));\n"
      "  out_float(68, shl_hvl_contribution_zh(8, 1.5, g, v3(9), v3(18), v3(21), in_float(3)));\n"
      "  out_float(69, shl_hvl_radius_neighbours(8, v3(27), in_float(30), pn, dn, "
      "in_float(31)));\n"
      "  out_float(70, shl_hvl_radius_fov(in_float(4), in_float(5), 64));\n"
      "  out_float(71, shl_hvl_radius_fov_tan(in_float(4), in_float(5), 64));\n"
      "  float m[16];\n"
      "  shl_sh_irradiance_matrix(sh, m);\n"
      "  for (k = 0; k < 16; ++k) out_float(72 + k, m[k]);\n"
      "}\n";
  static const char *names[] = {"phong", "cos^e", "lambert", "blinn", "ggx", "beckmann", "window"};
  static const char *snames[NS] = {"sh_dot",       "sh_conv_zh", "zh_dot_zh", "irradiance3",
                                   "irradiance",   "bands_for",  "horizon",   "G exact",
                                   "G smoothstep", "emission",   "radiance",  "contrib",
                                   "contrib_zh",   "r1",         "r2",        "r2 tan"};
  double worst[7 + NS + 1];
  int i, k, bad = 0;
  memset(worst, 0, sizeof worst);
  for (i = 0; i < NI; ++i) {
    float *p = in + i * IN;
    memset(p, 0, sizeof(float) * IN);
    p[0] = (i % 4 == 0) ? (float)(i / 4) : 1000.0f * rndf() * rndf(); /* exponent */
    p[1] = 0.02f + 1.5f * rndf() * rndf();                            /* roughness */
    p[2] = 2.0f * rndf() - 1.0f;                                      /* z */
    p[3] = 0.05f + 0.5f * rndf();                                     /* r */
    p[4] = 0.3f + 2.0f * rndf();                                      /* d (some inside) */
    p[5] = 0.2f + rndf();                                             /* fov */
    for (k = 0; k < 12; ++k)
      p[I_VEC + k] = 2.0f * rndf() - 1.0f;
    for (k = 0; k < 9; ++k)
      p[I_HV + k] = 2.0f * rndf() - 1.0f;
    p[I_HV + 5] += 2.0f; /* HVL above x */
    for (k = 0; k < 3; ++k)
      p[I_P + k] = rndf();
    p[I_P + 3] = 2.0f + rndf();
    p[I_P + 4] = 1e-3f;
    for (k = 0; k < 24; ++k)
      p[I_PN + k] = rndf();
    for (k = 0; k < 8; ++k)
      p[I_DN + k] = 2.0f + rndf();
    for (k = 0; k < NB; ++k)
      p[I_ZH + k] = 2.0f * rndf() - 1.0f;
    for (k = 0; k < 2 * NN; ++k)
      p[I_SH + k] = 2.0f * rndf() - 1.0f;
    c_item(p, ref + i * OUTS);
  }
  TL_CHECK(glrun_compute(defines, files, 7, main_src, in, (size_t)NI * IN, out, (size_t)NI * OUTS,
                         NI) == 0,
           "glrun: %s", glrun_last_log());
  for (i = 0; i < NI; ++i) {
    for (k = 0; k < OUTS; ++k) {
      double r = (double)ref[i * OUTS + k], g = (double)out[i * OUTS + k], scale = 1.0, e;
      int grp = k < O_S ? k / 8 : k < O_M ? 7 + (k - O_S) : 7 + NS;
      if (k < O_S)
        scale = 1.0; /* K_l-scale lobes, window of |zh| <= 1 */
      else if (k - O_S <= 4 || (k - O_S >= 9 && k - O_S <= 12))
        scale = 64.0; /* sums of 64 */
      else
        scale = fmax(1.0, fabs(r));
      e = fabs(g - r) / scale;
      if (!(e <= worst[grp])) worst[grp] = e;
      if (!(e <= 2e-5)) {
        if (bad < 10) printf("  item %d output %d: GLSL %.9g C %.9g\n", i, k, g, r);
        bad++;
      }
    }
  }
  printf("  %s: max |GLSL - C| / scale:", glrun_renderer());
  for (k = 0; k < 7; ++k)
    printf(" %s %.2g", names[k], worst[k]);
  for (k = 0; k < NS; ++k)
    printf(", %s %.2g", snames[k], worst[7 + k]);
  printf(", irradiance matrix %.2g\n", worst[7 + NS]);
  TL_CHECK(bad == 0, "%d outputs differ beyond 2e-5 of their scale", bad);
}

int main(void) {
  TL_RUN(test_glsl_brdf);
  glrun_close();
  return tl_summary();
}
