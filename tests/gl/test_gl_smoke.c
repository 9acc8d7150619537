/* test_gl_smoke.c - self-test of the headless GLSL harness (glctx + glrun): runs toy.glsl on
 * both paths and compares it with its C twin below. Run from the repository root;
 * SHLIGHT_GL_BACKEND=osmesa|egl picks the backend. Build with -ffp-contract=off. */
#include "../tl.h"
#include "glrun.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* C twin of toy_poly() in toy.glsl, built with the same TOY_SCALE as DEFINES below */
#define TOY_SCALE 2.0f
static void toy_poly(const float d[3], float out_y[4]) {
  float x = d[0];
  float y = d[1];
  float z = d[2];
  out_y[0] = TOY_SCALE * 0.5f;
  out_y[1] = TOY_SCALE * (x * y - z);
  out_y[2] = TOY_SCALE * (3.0f * z * z - 1.0f);
  out_y[3] = TOY_SCALE * x * (x * x - 3.0f * y * y);
}

static const char *const FILES[] = {"tests/gl/toy.glsl"};
static const char DEFINES[] = "#define TOY_SCALE 2.0\n";
/* one main for both paths: item i reads vec4 0 (direction), writes vec4 0 (4 values) */
static const char MAIN_TOY[] = "void glrun_main(int item) {\n"
                               "  float y[4];\n"
                               "  toy_poly(in_vec4(0).xyz, y);\n"
                               "  out_vec4(0, vec4(y[0], y[1], y[2], y[3]));\n"
                               "}\n";

#define N 10000 /* not a multiple of 64 (compute groups) or 256 (fragment rows) */
static float dirs[4 * N], got[4 * N];

static void make_dirs(void) { /* unit vectors rounded to float on the C side, plus a few odd ones */
  unsigned s = 12345u;
  int i, k;
  for (i = 0; i < N; i++) {
    double v[3], r = 0.0;
    for (k = 0; k < 3; k++) {
      s = s * 1664525u + 1013904223u;
      v[k] = (double)(s >> 8) / 8388608.0 - 1.0;
      r += v[k] * v[k];
    }
    r = sqrt(r);
    for (k = 0; k < 3; k++)
      dirs[4 * i + k] = (float)(v[k] / r);
    dirs[4 * i + 3] = 0.0f;
  }
  memset(dirs, 0, 4 * sizeof(float)); /* zero vector */
  dirs[4] = 1e3f, dirs[5] = -7.5f, dirs[6] = 0.125f;
  dirs[10] = 1.0f, dirs[8] = dirs[9] = 0.0f; /* pole */
}

/* max |GLSL - C| over all values; *inexact = number of values that are not bit-identical */
static double compare_toy(const float *out, int *inexact) {
  double worst = 0.0;
  int i, k;
  *inexact = 0;
  for (i = 0; i < N; i++) {
    float ref[4];
    toy_poly(dirs + 4 * i, ref);
    for (k = 0; k < 4; k++) {
      double e = fabs((double)out[4 * i + k] - (double)ref[k]);
      if (!(e <= worst)) worst = e; /* NaN sticks */
      *inexact += memcmp(&out[4 * i + k], &ref[k], sizeof(float)) != 0;
    }
  }
  return worst;
}

static void check_toy(const char *path, int rc) {
  int inexact = 0;
  double worst;
  TL_CHECK(rc == 0, "%s run failed", path);
  if (rc) return;
  worst = compare_toy(got, &inexact);
  printf("  %s: max |GLSL - C| = %.3g, %d of %d values not bit-identical\n", path, worst, inexact,
         4 * N);
  /* the largest value is ~4e9 (x = 1e3): allow a few float ulps relative */
  TL_CHECK(worst <= 1e-6 * 4e9, "%s: max abs diff %g", path, worst);
}

static void test_info(void) {
  const char *b = glrun_backend(), *r = glrun_renderer();
  printf("  backend %s, renderer %s\n", b, r);
  TL_CHECK(!strcmp(b, "osmesa") || !strcmp(b, "egl"), "backend '%s'", b);
  TL_CHECK(r && *r && strcmp(r, "(no context)"), "no renderer");
}

static void test_toy_compute(void) {
  check_toy("compute", glrun_compute(DEFINES, FILES, 1, MAIN_TOY, dirs, 4 * N, got, 4 * N, N));
}

static void test_toy_fragment(void) {
  check_toy("fragment", glrun_fragment(DEFINES, FILES, 1, MAIN_TOY, dirs, 1, got, 1, N));
}

static void test_toy_es(void) { /* the same through GLSL ES 3.10 compute / 3.00 fragment */
  glrun_set_versions("#version 310 es", "#version 300 es");
  check_toy("compute 310 es",
            glrun_compute(DEFINES, FILES, 1, MAIN_TOY, dirs, 4 * N, got, 4 * N, N));
  check_toy("fragment 300 es", glrun_fragment(DEFINES, FILES, 1, MAIN_TOY, dirs, 1, got, 1, N));
  glrun_set_versions("#version 450", "#version 330");
}

/* Layout: 3 vec4 in and 5 vec4 out per item; out float j = in float j + item (exact),
 * floats 12..15 = (item, GLRUN_COUNT, GLRUN_IN_STRIDE, GLRUN_OUT_STRIDE), 16 = -1,
 * 17..19 never written (NaN). */
static const char MAIN_LAYOUT[] =
    "void glrun_main(int item) {\n"
    "  for (int j = 0; j < 12; j++) out_float(j, in_float(j) + float(item));\n"
    "  out_vec4(3, vec4(float(item), float(GLRUN_COUNT), float(GLRUN_IN_STRIDE),\n"
    "                   float(GLRUN_OUT_STRIDE)));\n"
    "  out_float(16, -1.0);\n"
    "}\n";

static void check_layout(const char *path, int count) {
  static float in[12 * 1000], out[20 * 1000];
  int i, j, bad = 0, rc;
  for (i = 0; i < 12 * count; i++)
    in[i] = 0.25f * (float)(i / 12) - (float)(i % 12);
  for (i = 0; i < 20 * count; i++)
    out[i] = 7.0f;
  if (!strcmp(path, "compute"))
    rc = glrun_compute(NULL, NULL, 0, MAIN_LAYOUT, in, (size_t)(12 * count), out,
                       (size_t)(20 * count), count);
  else
    rc = glrun_fragment(NULL, NULL, 0, MAIN_LAYOUT, in, 3, out, 5, count);
  TL_CHECK(rc == 0, "%s layout run failed (count %d)", path, count);
  for (i = 0; i < count && !rc; i++) {
    const float *o = out + 20 * i;
    for (j = 0; j < 12; j++)
      bad += o[j] != in[12 * i + j] + (float)i;
    bad += o[12] != (float)i || o[13] != (float)count || o[14] != 12.0f || o[15] != 20.0f;
    bad += o[16] != -1.0f || !isnan(o[17]) || !isnan(o[18]) || !isnan(o[19]);
  }
  TL_CHECK(bad == 0, "%s layout (count %d): %d wrong values", path, count, bad);
}

static void test_layout(void) {
  static const int counts[] = {1, 63, 257, 1000};
  int i;
  for (i = 0; i < 4; i++)
    check_layout("compute", counts[i]), check_layout("fragment", counts[i]);
}

static void test_errors(void) {
  static const char *const missing[] = {"tests/gl/no_such_file.glsl"};
  float out[4];
  int rc;
  printf("  (compiler errors below are expected)\n");
  fflush(stdout);
  /* an error inside a file is reported with the file's name and line */
  rc = glrun_compute("#define TOY_SCALE no_such_name\n", FILES, 1, MAIN_TOY, dirs, 4, out, 4, 1);
  TL_CHECK(rc != 0, "bad define accepted");
  TL_CHECK(strstr(glrun_last_log(), "\"toy.glsl\":") != NULL, "log: %s", glrun_last_log());
  /* an error in main_src names main_src */
  rc = glrun_fragment(NULL, NULL, 0, "void glrun_main(int item) {\n  no_such_fn(item);\n}\n", NULL,
                      0, out, 1, 1);
  TL_CHECK(rc != 0, "bad main accepted");
  TL_CHECK(strstr(glrun_last_log(), "\"main_src\":2") != NULL, "log: %s", glrun_last_log());
  TL_CHECK(glrun_compute(NULL, missing, 1, MAIN_TOY, dirs, 4, out, 4, 1) != 0, "missing file");
  TL_CHECK(glrun_fragment(NULL, NULL, 0, MAIN_TOY, dirs, 1, out, 9, 1) != 0, "9 outputs");
  /* the context survives failed runs */
  TL_CHECK(glrun_compute(DEFINES, FILES, 1, MAIN_TOY, dirs, 4, out, 4, 1) == 0, "run after errors");
  TL_CHECK(!strcmp(glrun_last_log(), ""), "log not cleared");
}

int main(void) {
  make_dirs();
  TL_CHECK(glrun_open(NULL) == 0, "no GL context (see the message above)");
  if (tl_failed) return tl_summary();
  TL_RUN(test_info);
  TL_RUN(test_toy_compute);
  TL_RUN(test_toy_fragment);
  TL_RUN(test_toy_es);
  TL_RUN(test_layout);
  TL_RUN(test_errors);
  glrun_close();
  return tl_summary();
}
