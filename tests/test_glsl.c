/* test_glsl.c - runs the GLSL twins of shlight's kernels headless (llvmpipe through OSMesa or
 * EGL, tests/gl/) on the C tests' kinds of input and compares them with the C kernels.
 *
 * Tolerance, and why: the GLSL bodies are the C bodies token for token, but shli_real is float
 * in GLSL and double in C, so the GLSL result carries the float rounding of the Reinsch-form
 * recurrence (error growth about linear in l, see README "Accuracy") while C is at the float
 * rounding floor. The bound used is TOL_Y(n) = 2.5e-7 + 1.2e-7 * n for values (|Y| <= 2.6 for
 * n <= 20) and the same times (1 + n) relative to max|grad| for gradients (gradient terms are
 * l times larger). Both were set from the float recurrence's error measured against a
 * binary128 reference (tests/test_basis prints it), not from this test's own outcome.
 * GLSL supports 1..16 bands (the straight-line kernels; the table-driven loops above 16 bands
 * are C only). The compute path (GLSL 4.50) checks every kernel; the fragment path (GLSL 3.30,
 * which flushes denormals) and the GLSL ES 3.00 fragment path check the kernels whose outputs fit
 * in 8 vec4 per pixel. */
#include "../shlight.h"
#include "gl/glrun.h"
#include "tl.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NDIR 1200
static float dirs[NDIR][3];
static const char *const files_basis[] = {"shlight_glsl/shl_prelude.glsl",
                                          "shlight_glsl/shl_basis.glsl"};
static const char *const files_grad[] = {"shlight_glsl/shl_prelude.glsl",
                                         "shlight_glsl/shl_basis.glsl",
                                         "shlight_glsl/shl_gradient.glsl"};

static uint64_t rng_state = 0x5eed1234u;
static double rnd(void) {
  uint64_t z = (rng_state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return (double)(z >> 11) * (1.0 / 9007199254740992.0);
}

/* random unit directions, near-pole directions (theta log-uniform in [1e-7, 1e-2], both
 * poles), the exact poles, and for the gradient kernels non-unit lengths and the zero vector */
static void make_dirs(int nonunit) {
  int i;
  for (i = 0; i < NDIR; ++i) {
    double th, ph = 6.283185307179586 * rnd(), s = 1.0;
    if (i % 3 == 1) {
      th = pow(10.0, -7.0 + 5.0 * rnd());
      if (i % 2) th = 3.141592653589793 - th;
    } else {
      th = acos(2.0 * rnd() - 1.0);
    }
    if (nonunit) s = pow(10.0, -2.0 + 4.0 * rnd());
    dirs[i][0] = (float)(s * sin(th) * cos(ph));
    dirs[i][1] = (float)(s * sin(th) * sin(ph));
    dirs[i][2] = (float)(s * cos(th));
  }
  dirs[0][0] = 0.0f, dirs[0][1] = 0.0f, dirs[0][2] = 1.0f;
  dirs[1][0] = 0.0f, dirs[1][1] = 0.0f, dirs[1][2] = -1.0f;
  if (nonunit) {
    dirs[2][0] = 0.0f, dirs[2][1] = 0.0f, dirs[2][2] = 0.0f;
    dirs[3][0] = 0.0f, dirs[3][1] = 0.0f, dirs[3][2] = 7.5f;
  }
}

static double tol_y(int n) {
  return 2.5e-7 + 1.2e-7 * n;
}

static char defines[128];
static void set_bands(int maxb) {
  snprintf(defines, sizeof defines, "#define SHLIGHT_MAX_BANDS %d\n", maxb);
}

/* shl_sh_eval on the compute path: n bands in a shader built for maxb bands */
static void check_eval_compute(int n, int maxb) {
  static float in[NDIR * 3], out[NDIR * 400], y[400];
  static char main_src[512];
  double err = 0.0;
  int i, k, ok;
  make_dirs(0);
  memcpy(in, dirs, sizeof in);
  set_bands(maxb);
  snprintf(main_src, sizeof main_src,
           "void glrun_main(int item) {\n"
           "  float y[SHLIGHT_MAX_COEFFS];\n"
           "  shl_sh_eval(%d, vec3(in_float(0), in_float(1), in_float(2)), y);\n"
           "  for (int i = 0; i < %d; ++i) out_float(i, y[i]);\n"
           "}\n",
           n, n * n);
  ok = glrun_compute(defines, files_basis, 2, main_src, in, (size_t)NDIR * 3, out,
                     (size_t)NDIR * (size_t)(n * n), NDIR) == 0;
  TL_CHECK(ok, "compute build/run failed for n=%d: %s", n, glrun_last_log());
  if (!ok) return;
  for (i = 0; i < NDIR; ++i) {
    shl_sh_eval(n, dirs[i], y);
    for (k = 0; k < n * n; ++k) {
      double e = fabs((double)out[i * n * n + k] - (double)y[k]);
      if (!(e <= err)) err = e; /* NaN counts as failure */
    }
  }
  printf("     shl_sh_eval compute   n=%2d (built for %2d): max |GLSL - C| = %.2e (tol %.2e)\n", n,
         maxb, err, tol_y(n));
  TL_CHECK(err <= tol_y(n), "shl_sh_eval n=%d: %.3e > %.3e", n, err, tol_y(n));
}

/* shl_sh_eval_grad on the compute path, non-unit inputs, zero vector included */
static void check_grad_compute(int n) {
  static float in[NDIR * 3], out[NDIR * 4 * 256], y[256], g[256][3];
  static char main_src[640];
  double err_y = 0.0, err_g = 0.0;
  int i, k, c, ok;
  make_dirs(1);
  memcpy(in, dirs, sizeof in);
  set_bands(n);
  snprintf(main_src, sizeof main_src,
           "void glrun_main(int item) {\n"
           "  float y[SHLIGHT_MAX_COEFFS];\n"
           "  vec3 g[SHLIGHT_MAX_COEFFS];\n"
           "  shl_sh_eval_grad(%d, vec3(in_float(0), in_float(1), in_float(2)), y, g);\n"
           "  for (int i = 0; i < %d; ++i) {\n"
           "    out_float(4 * i, y[i]);\n"
           "    out_float(4 * i + 1, g[i].x);\n"
           "    out_float(4 * i + 2, g[i].y);\n"
           "    out_float(4 * i + 3, g[i].z);\n"
           "  }\n"
           "}\n",
           n, n * n);
  ok = glrun_compute(defines, files_grad, 3, main_src, in, (size_t)NDIR * 3, out,
                     (size_t)NDIR * 4 * (size_t)(n * n), NDIR) == 0;
  TL_CHECK(ok, "compute build/run failed for grad n=%d: %s", n, glrun_last_log());
  if (!ok) return;
  for (i = 0; i < NDIR; ++i) {
    double gmax = 0.0;
    shl_sh_eval_grad(n, dirs[i], y, g);
    for (k = 0; k < n * n; ++k)
      for (c = 0; c < 3; ++c)
        if (fabs((double)g[k][c]) > gmax) gmax = fabs((double)g[k][c]);
    for (k = 0; k < n * n; ++k) {
      const float *o = out + (size_t)(i * n * n + k) * 4;
      double e = fabs((double)o[0] - (double)y[k]);
      if (!(e <= err_y)) err_y = e;
      for (c = 0; c < 3; ++c) {
        e = fabs((double)o[1 + c] - (double)g[k][c]) / (gmax > 0.0 ? gmax : 1.0);
        if (!(e <= err_g)) err_g = e;
      }
    }
  }
  printf("     shl_sh_eval_grad compute n=%2d: max |dY| = %.2e, max |dgrad|/max|grad| = %.2e\n", n,
         err_y, err_g);
  TL_CHECK(err_y <= tol_y(n), "grad values n=%d: %.3e", n, err_y);
  TL_CHECK(err_g <= tol_y(n) * (1 + n), "grad n=%d: %.3e > %.3e", n, err_g, tol_y(n) * (1 + n));
}

/* the paper's spherical partials and Jacobian, away from the poles (singular there) */
static void check_spherical_compute(int n) {
  static float in[NDIR * 3], out[NDIR * 6 * 100], y[100], dt[100], dp[100], g[100][3];
  static char main_src[900];
  double err = 0.0, gmax = 0.0;
  int i, k, c, ok;
  make_dirs(0);
  for (i = 0; i < NDIR; ++i) /* keep away from the poles: theta in [0.05, pi - 0.05] */
    if (fabs((double)dirs[i][2]) > 0.998) dirs[i][0] = 0.1f, dirs[i][1] = 0.05f;
  memcpy(in, dirs, sizeof in);
  set_bands(n);
  snprintf(main_src, sizeof main_src,
           "void glrun_main(int item) {\n"
           "  float y[SHLIGHT_MAX_COEFFS];\n"
           "  float t[SHLIGHT_MAX_COEFFS];\n"
           "  float p[SHLIGHT_MAX_COEFFS];\n"
           "  vec3 g[SHLIGHT_MAX_COEFFS];\n"
           "  vec3 d = vec3(in_float(0), in_float(1), in_float(2));\n"
           "  shl_sh_eval_grad_spherical(%d, d, y, t, p);\n"
           "  shl_sh_grad_from_spherical(%d, d, t, p, g);\n"
           "  for (int i = 0; i < %d; ++i) {\n"
           "    out_float(6 * i, y[i]);\n"
           "    out_float(6 * i + 1, t[i]);\n"
           "    out_float(6 * i + 2, p[i]);\n"
           "    out_float(6 * i + 3, g[i].x);\n"
           "    out_float(6 * i + 4, g[i].y);\n"
           "    out_float(6 * i + 5, g[i].z);\n"
           "  }\n"
           "}\n",
           n, n, n * n);
  ok = glrun_compute(defines, files_grad, 3, main_src, in, (size_t)NDIR * 3, out,
                     (size_t)NDIR * 6 * (size_t)(n * n), NDIR) == 0;
  TL_CHECK(ok, "compute build/run failed for spherical n=%d: %s", n, glrun_last_log());
  if (!ok) return;
  for (i = 0; i < NDIR; ++i) {
    float ref[6];
    shl_sh_eval_grad_spherical(n, dirs[i], y, dt, dp);
    shl_sh_grad_from_spherical(n, dirs[i], dt, dp, g);
    for (k = 0; k < n * n; ++k) {
      ref[0] = y[k], ref[1] = dt[k], ref[2] = dp[k];
      ref[3] = g[k][0], ref[4] = g[k][1], ref[5] = g[k][2];
      for (c = 0; c < 6; ++c) {
        double e = fabs((double)out[(size_t)(i * n * n + k) * 6 + (size_t)c] - (double)ref[c]);
        if (fabs((double)ref[c]) > gmax) gmax = fabs((double)ref[c]);
        if (!(e <= err)) err = e;
      }
    }
  }
  printf("     spherical partials + Jacobian compute n=%2d: max |GLSL - C| = %.2e (max %.2e)\n", n,
         err, gmax);
  TL_CHECK(err <= tol_y(n) * (1 + n) * (gmax > 1.0 ? gmax : 1.0), "spherical n=%d: %.3e", n, err);
}

/* shl_sh_eval on the fragment path (GLSL 3.30 or ES 3.00), n <= 5 (25 floats per pixel) */
static void check_eval_fragment(int n, const char *version) {
  static float in[NDIR * 4], out[NDIR * 32], y[32];
  static char main_src[600];
  double err = 0.0;
  int i, k, ok, nv = (n * n + 3) / 4;
  make_dirs(0);
  for (i = 0; i < NDIR; ++i) {
    in[4 * i] = dirs[i][0], in[4 * i + 1] = dirs[i][1], in[4 * i + 2] = dirs[i][2];
    in[4 * i + 3] = 0.0f;
  }
  set_bands(n);
  glrun_set_versions(NULL, version);
  snprintf(main_src, sizeof main_src,
           "void glrun_main(int item) {\n"
           "  float y[SHLIGHT_MAX_COEFFS];\n"
           "  shl_sh_eval(%d, in_vec4(0).xyz, y);\n"
           "  for (int i = 0; i < %d; ++i) out_float(i, y[i]);\n"
           "}\n",
           n, n * n);
  ok = glrun_fragment(defines, files_basis, 2, main_src, in, 1, out, nv, NDIR) == 0;
  glrun_set_versions(NULL, "#version 330");
  TL_CHECK(ok, "fragment (%s) build/run failed for n=%d: %s", version, n, glrun_last_log());
  if (!ok) return;
  for (i = 0; i < NDIR; ++i) {
    shl_sh_eval(n, dirs[i], y);
    for (k = 0; k < n * n; ++k) {
      double e = fabs((double)out[i * nv * 4 + k] - (double)y[k]);
      if (!(e <= err)) err = e;
    }
  }
  printf("     shl_sh_eval fragment (%s) n=%d: max |GLSL - C| = %.2e\n", version, n, err);
  TL_CHECK(err <= tol_y(n), "fragment n=%d: %.3e", n, err);
}

static void test_context(void) {
  TL_CHECK(glrun_open(NULL) == 0, "no headless GL context");
  printf("     backend %s, renderer %s\n", glrun_backend(), glrun_renderer());
}

static void test_eval_compute(void) {
  static const int ns[] = {1, 2, 3, 4, 5, 8, 10, 16};
  size_t i;
  for (i = 0; i < sizeof ns / sizeof ns[0]; ++i)
    check_eval_compute(ns[i], ns[i]);
  check_eval_compute(3, 6); /* run-time n below the shader's band count: the switch */
}

static void test_grad_compute(void) {
  static const int ns[] = {1, 2, 3, 4, 6, 10, 16};
  size_t i;
  for (i = 0; i < sizeof ns / sizeof ns[0]; ++i)
    check_grad_compute(ns[i]);
}

static void test_spherical_compute(void) {
  check_spherical_compute(3);
  check_spherical_compute(10);
}

static void test_eval_fragment(void) {
  int n;
  for (n = 1; n <= 5; ++n)
    check_eval_fragment(n, "#version 330");
  check_eval_fragment(4, "#version 300 es");
}

int main(void) {
  TL_RUN(test_context);
  if (tl_failed) return tl_summary();
  TL_RUN(test_eval_compute);
  TL_RUN(test_grad_compute);
  TL_RUN(test_spherical_compute);
  TL_RUN(test_eval_fragment);
  glrun_close();
  return tl_summary();
}
