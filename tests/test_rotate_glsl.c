/* test_rotate_glsl.c - the GLSL twin of shl_sh_rotate (shlight_glsl/shl_zonal.glsl) against the
   C kernel on llvmpipe (compute path, SHLIGHT_MAX_BANDS 16): random rotations, the hard ones
   (identity, pi about x, 1e-6 and pi - 1e-6 about skew axes, pure z) at n = 1, 2, 4, 9, 16.
   Run from the repository root (tests/run.sh runs it).
   Tolerance, per band, |GLSL - C| / |band of the input| <= 1e-6 + 1.5e-7 l: C runs in double
   (its own error 4e-8, tests/test_rotate); GLSL runs the same recurrence in float, whose
   start values carry ~2 ulp and each step of the three-term recurrence in l adds a few ulp
   relative to the band (the recurrence is the forward Jacobi one, stable: growth linear in l).
   The bound is that model with 1.2e-7 = 1 ulp and room for the 2l + 1 terms summed per row. */
#include "../shlight.h"
#include "gl/glrun.h"
#include "tl.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define NI 256
#define NB 16
#define NN (NB * NB)
#define IN (9 + 1 + NN)

static unsigned long long st = 0x2545F4914F6CDD1DULL;
static double rnd(void) {
  st ^= st << 13;
  st ^= st >> 7;
  st ^= st << 17;
  return (double)(st >> 11) * (1.0 / 9007199254740992.0);
}

static void quat_R(double w, double x, double y, double z, float R[9]) {
  double s = 1.0 / sqrt(w * w + x * x + y * y + z * z);
  w *= s, x *= s, y *= s, z *= s;
  R[0] = (float)(1 - 2 * (y * y + z * z));
  R[1] = (float)(2 * (x * y - z * w));
  R[2] = (float)(2 * (x * z + y * w));
  R[3] = (float)(2 * (x * y + z * w));
  R[4] = (float)(1 - 2 * (x * x + z * z));
  R[5] = (float)(2 * (y * z - x * w));
  R[6] = (float)(2 * (x * z - y * w));
  R[7] = (float)(2 * (y * z + x * w));
  R[8] = (float)(1 - 2 * (x * x + y * y));
}

static void axis_angle(double ax, double ay, double az, double ang, float R[9]) {
  double s = sin(0.5 * ang);
  quat_R(cos(0.5 * ang), ax * s, ay * s, az * s, R);
}

static void test_glsl_rotate(void) {
  static float in[NI * IN], out[NI * NN], ref[NI * NN];
  static const int ns[5] = {1, 2, 4, 9, 16};
  const char *files[4] = {"shlight_glsl/shl_prelude.glsl", "shlight_glsl/shl_basis.glsl",
                          "shlight_glsl/shl_gradient.glsl", "shlight_glsl/shl_zonal.glsl"};
  const char *defines = "#define SHLIGHT_MAX_BANDS 16\n";
  const char *main_src = "void glrun_main(int item) {\n"
                         "  float R[9];\n"
                         "  float sh[SHLIGHT_MAX_COEFFS];\n"
                         "  float o[SHLIGHT_MAX_COEFFS];\n"
                         "  int k;\n"
                         "  for (k = 0; k < 9; ++k) R[k] = in_float(k);\n"
                         "  int n = int(in_float(9));\n"
                         "  for (k = 0; k < 256; ++k) {\n"
                         "    sh[k] = in_float(10 + k);\n"
                         "    o[k] = 0.0;\n"
                         "  }\n"
                         "  shl_sh_rotate(n, R, sh, o);\n"
                         "  for (k = 0; k < 256; ++k) out_float(k, o[k]);\n"
                         "}\n";
  int i, k, l, m, bad = 0;
  double worst = 0.0, worst16 = 0.0;
  for (i = 0; i < NI; ++i) {
    float *p = in + i * IN, *r = ref + i * NN;
    int n = ns[i % 5];
    switch (i / 5) {
    case 0:
      axis_angle(0, 0, 1, 0, p);
      break;
    case 1:
      axis_angle(1, 0, 0, 3.141592653589793, p);
      break;
    case 2:
      axis_angle(0.48, 0.6, 0.64, 1e-6, p);
      break;
    case 3:
      axis_angle(0.6, -0.64, 0.48, 3.141592653589793 - 1e-6, p);
      break;
    case 4:
      axis_angle(0, 0, 1, 2.0, p);
      break;
    default:
      quat_R(2 * rnd() - 1, 2 * rnd() - 1, 2 * rnd() - 1, 2 * rnd() - 1, p);
    }
    p[9] = (float)n;
    for (k = 0; k < NN; ++k) {
      p[10 + k] = (float)(2 * rnd() - 1);
      r[k] = 0.0f;
    }
    shl_sh_rotate(n, p, p + 10, r);
  }
  TL_CHECK(glrun_compute(defines, files, 4, main_src, in, (size_t)NI * IN, out, (size_t)NI * NN,
                         NI) == 0,
           "glrun: %s", glrun_last_log());
  for (i = 0; i < NI; ++i) {
    int n = ns[i % 5];
    for (l = 0; l < n; ++l) {
      double e = 0.0, b = 0.0, rel;
      for (m = -l; m <= l; ++m) {
        int j = l * (l + 1) + m;
        double d = (double)out[i * NN + j] - (double)ref[i * NN + j];
        e += d * d;
        b += (double)in[i * IN + 10 + j] * (double)in[i * IN + 10 + j];
      }
      rel = sqrt(e / b);
      if (!(rel <= worst)) worst = rel;
      if (n == 16 && !(rel <= worst16)) worst16 = rel;
      if (!(rel <= 1e-6 + 1.5e-7 * l)) bad++;
    }
  }
  printf("  %s: max per-band |GLSL - C| / |band| = %.3g (n = 16: %.3g) over %d rotations\n",
         glrun_renderer(), worst, worst16, NI);
  TL_CHECK(bad == 0, "%d bands differ beyond 1e-6 + 1.5e-7 l (worst %g)", bad, worst);
}

int main(void) {
  TL_RUN(test_glsl_rotate);
  glrun_close();
  return tl_summary();
}
