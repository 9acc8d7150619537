/* glsl_budget.c - compile and run budgets of shlight's GLSL on the headless context of
 * tests/gl (llvmpipe here). For each shader: process CPU and wall seconds from
 * glShaderSource to the first frame read back (compile + link + first draw; run with
 * MESA_SHADER_CACHE_DISABLE=true, bench/glsl_budget.sh does), and for the kernels in the run
 * table the time per 512 x 512 frame with a per-pixel direction, from two runs of the same
 * shader (2 and 2 + REPS evaluations per pixel, the repeat count a run-time input; REPS = 8, or
 * --reps N), in process CPU ms (llvmpipe's threads included) and wall ms.
 *
 *   glsl_budget [--check FACTOR] [--no-run] [--one-include] [--match STR] [--reps N] [GLSL_DIR]
 *
 * --check F: exit 1 when a compile time exceeds F x its budget (CI: F = 2, CPU seconds, which
 * load on a shared machine moves less than wall time); the rows over budget today (checked = 0)
 * are skipped then. --one-include: shlight_glsl/shlight.glsl instead of the module files.
 * --match STR: only the rows whose name contains STR. Ends with "N passed, N failed". */
#include "../tests/gl/glrun.h"

#include <stdio.h>
#include <stdlib.h>
#include <math.h>
#include <string.h>
#include <time.h>

static double now(clockid_t c) {
  struct timespec t;
  clock_gettime(c, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static char g_files[4][512];

/* the shader's repeat count: a.w in the timed runs (GLSL_BUDGET_REPS), 1 in the compile table */
#define REPS_DECL \
  "#ifdef GLSL_BUDGET_REPS\n" \
  "  int reps = int(a.w);\n" \
  "#else\n" \
  "  const int reps = 1;\n" \
  "#endif\n"

static const char *MAIN_VALUES =
    "void glrun_main(int item) {\n"
    "  vec4 a = in_vec4(0);\n"
    "  float y[SHLIGHT_MAX_COEFFS];\n"
    "  float acc = 0.0;\n" REPS_DECL "  for (int r = 0; r < reps; ++r) {\n"
    "    vec3 d = normalize(a.xyz + vec3(0.0, 0.0, 0.01 * float(r)));\n"
    "    shl_sh_eval(SHLIGHT_MAX_BANDS, d, y);\n"
    "    acc += GLSL_BUDGET_SUM_Y;\n"
    "  }\n"
    "  out_float(0, acc);\n"
    "}\n";

static const char *MAIN_GRAD =
    "void glrun_main(int item) {\n"
    "  vec4 a = in_vec4(0);\n"
    "  float y[SHLIGHT_MAX_COEFFS];\n"
    "  vec3 g[SHLIGHT_MAX_COEFFS];\n"
    "  float acc = 0.0;\n" REPS_DECL "  for (int r = 0; r < reps; ++r) {\n"
    "    vec3 d = normalize(a.xyz + vec3(0.0, 0.0, 0.01 * float(r)));\n"
    "    shl_sh_eval_grad(SHLIGHT_MAX_BANDS, d, y, g);\n"
    "    acc += GLSL_BUDGET_SUM_Y + GLSL_BUDGET_SUM_G;\n"
    "  }\n"
    "  out_float(0, acc);\n"
    "}\n";

/* f(d) = sum_i sh[i] Y_i(d) and its gradient; sh: constants (as from a uniform block), set
   before the timed repeats; the consumer reads the returned value and gradient only */
static const char *MAIN_DOT_GRAD =
    "void glrun_main(int item) {\n"
    "  vec4 a = in_vec4(0);\n"
    "  float sh[SHLIGHT_MAX_COEFFS];\n"
    "  vec3 g;\n"
    "  float acc = 0.0;\n" REPS_DECL "  GLSL_BUDGET_SET_SH\n"
    "  for (int r = 0; r < reps; ++r) {\n"
    "    vec3 d = normalize(a.xyz + vec3(0.0, 0.0, 0.01 * float(r)));\n"
    "    acc += shl_sh_eval_dot_grad(SHLIGHT_MAX_BANDS, sh, d, g) + dot(g, vec3(1.0));\n"
    "  }\n"
    "  out_float(0, acc);\n"
    "}\n";

static const char *MAIN_SPHERE =
    "void glrun_main(int item) {\n"
    "  vec4 a = in_vec4(0);\n"
    "  float y[SHLIGHT_MAX_COEFFS];\n"
    "  vec3 g[SHLIGHT_MAX_COEFFS];\n"
    "  float acc = 0.0;\n"
    "  shl_sphere_light_grad(SHLIGHT_MAX_BANDS, a.xyz, vec3(0.0, 0.0, 3.0), 0.5, y, g);\n"
    "  acc += GLSL_BUDGET_SUM_Y + GLSL_BUDGET_SUM_G;\n"
    "  out_float(0, acc);\n"
    "}\n";

static const char *MAIN_HERMITE =
    "void glrun_main(int item) {\n"
    "  vec4 a = in_vec4(0);\n"
    "  float c8[8 * SHLIGHT_MAX_COEFFS];\n"
    "  vec3 g8[8 * SHLIGHT_MAX_COEFFS];\n"
    "  float y[SHLIGHT_MAX_COEFFS];\n"
    "  float acc = 0.0;\n"
    "  for (int i = 0; i < 8 * SHLIGHT_MAX_COEFFS; ++i) {\n"
    "    c8[i] = sin(float(i) + a.x);\n"
    "    g8[i] = vec3(cos(float(i) + a.y), a.z, 0.5);\n"
    "  }\n"
    "  shl_grid_hermite(SHLIGHT_MAX_BANDS, c8, g8, fract(a.xyz), vec3(1.0), y);\n"
    "  acc += GLSL_BUDGET_SUM_Y;\n"
    "  out_float(0, acc);\n"
    "}\n";

#define POLY_MAIN(call) \
  "void glrun_main(int item) {\n" \
  "  vec4 a = in_vec4(0);\n" \
  "  vec3 v[SHLIGHT_POLYGON_MAX];\n" \
  "  for (int i = 0; i < SHLIGHT_POLYGON_MAX; ++i) v[i] = vec3(0.0);\n" \
  "  v[0] = vec3(-0.5, -0.5, 1.0) + 0.1 * a.xyz;\n" \
  "  v[1] = vec3(0.5, -0.5, 1.0);\n" \
  "  v[2] = vec3(0.5, 0.5, 1.0);\n" \
  "  v[3] = vec3(-0.5, 0.5, 1.0);\n" \
  "  vec3 nrm = vec3(0.0, 0.0, 1.0);\n" \
  "  vec3 view = normalize(vec3(0.3, 0.0, 1.0));\n" \
  "  out_float(0, " call ");\n" \
  "}\n"

/* POLY_MAIN with the repeat count of the run table (its first vertex moved per repeat) */
#define POLY_RUN_MAIN(call) \
  "void glrun_main(int item) {\n" \
  "  vec4 a = in_vec4(0);\n" \
  "  vec3 v[SHLIGHT_POLYGON_MAX];\n" \
  "  for (int i = 0; i < SHLIGHT_POLYGON_MAX; ++i) v[i] = vec3(0.0);\n" \
  "  v[1] = vec3(0.5, -0.5, 1.0);\n" \
  "  v[2] = vec3(0.5, 0.5, 1.0);\n" \
  "  v[3] = vec3(-0.5, 0.5, 1.0);\n" \
  "  vec3 nrm = vec3(0.0, 0.0, 1.0);\n" \
  "  vec3 view = normalize(vec3(0.3, 0.0, 1.0));\n" \
  "  float acc = 0.0;\n" REPS_DECL "  for (int r = 0; r < reps; ++r) {\n" \
  "    v[0] = vec3(-0.5, -0.5, 1.0) + 0.1 * a.xyz + vec3(0.0, 0.0, 0.01 * float(r));\n" \
  "    acc += " call ";\n" \
  "  }\n" \
  "  out_float(0, acc);\n" \
  "}\n"

struct kcase {
  const char *name;
  int bands;
  const char *modules; /* space-separated, after shl_prelude.glsl */
  const char *main_src;
  double budget; /* seconds, compile + link + first draw */
  int runtime;   /* also timed per frame */
  int checked;   /* held to --check (0: over its budget today, printed only) */
};

static const struct kcase CASES[] = {
    {"values, n = 4", 4, "basis", NULL, 0.0, 1, 1},
    {"values, n = 9", 9, "basis", NULL, 0.0, 1, 1},
    {"values, n = 16", 16, "basis", NULL, 0.5, 1, 1},
    {"values + gradient, n = 4", 4, "basis gradient", NULL, 0.0, 1, 1},
    {"values + gradient, n = 9", 9, "basis gradient", NULL, 0.0, 1, 1},
    {"values + gradient, n = 16", 16, "basis gradient", NULL, 5.0, 1, 1},
    {"SH function value + gradient, n = 4", 4, "basis gradient", NULL, 0.0, 1, 1},
    {"SH function value + gradient, n = 9", 9, "basis gradient", NULL, 0.0, 1, 1},
    {"SH function value + gradient, n = 16", 16, "basis gradient", NULL, 1.0, 1, 1},
    {"sphere light + gradient, n = 9", 9, "basis gradient zonal light", NULL, 1.5, 0, 1},
    {"shl_grid_hermite, n = 5", 5, "basis grid", NULL, 1.0, 0, 1},
    {"shl_polygon_moment (one call site)", 4, "basis gradient zonal light edge",
     POLY_MAIN("shl_polygon_moment(v, 4, nrm, 3.5, SHLIGHT_EDGE_AUTO)"), 2.0, 0, 1},
    {"shl_polygon_phong (one call site)", 4, "basis gradient zonal light edge",
     POLY_MAIN("shl_polygon_phong(v, 4, nrm, view, 20.0, SHLIGHT_EDGE_AUTO)"), 2.0, 0, 1},
    {"shl_polygon_ggx (one call site)", 4, "basis gradient zonal light edge",
     POLY_RUN_MAIN("shl_polygon_ggx(v, 4, nrm, view, 0.3)"), 2.0, 1, 1},
    {"shl_polygon_ggx_fast (one call site)", 4, "basis gradient zonal light edge",
     POLY_RUN_MAIN("shl_polygon_ggx_fast(v, 4, nrm, view, 0.3)"), 2.0, 1, 1},
    {"shl_polygon_beckmann (one call site)", 4, "basis gradient zonal light edge",
     POLY_RUN_MAIN("shl_polygon_beckmann(v, 4, nrm, view, 0.3)"), 2.0, 1, 1},
    {"shl_polygon_beckmann_subedges (one call site)", 4, "basis gradient zonal light edge",
     POLY_MAIN("shl_polygon_beckmann_subedges(v, 4, nrm, view, 0.3, 4)"), 2.0, 0, 1},
};

static const char *main_of(const struct kcase *k) {
  if (k->main_src) return k->main_src;
  if (strstr(k->name, "sphere")) return MAIN_SPHERE;
  if (strstr(k->name, "hermite")) return MAIN_HERMITE;
  if (strstr(k->name, "SH function")) return MAIN_DOT_GRAD;
  if (strstr(k->name, "gradient")) return MAIN_GRAD;
  return MAIN_VALUES;
}

/* one build + draw of count pixels, reps evaluations each; returns CPU seconds (wall in *wall) */
static int run(const struct kcase *k, const char *dir, int one_include, int count, int reps,
               double *cpu, double *wall) {
  static float in[4 * 512 * 512], out[4 * 512 * 512];
  const char *files[8];
  static char defines[65536];
  char mods[128], *tok;
  size_t at;
  int nf = 0, i;
  double c0, w0;
  if (one_include) {
    snprintf(g_files[0], sizeof g_files[0], "%s/shlight.glsl", dir);
    files[nf++] = g_files[0];
  } else {
    static char paths[8][512];
    snprintf(paths[nf], sizeof paths[nf], "%s/shl_prelude.glsl", dir);
    files[nf] = paths[nf];
    nf++;
    snprintf(mods, sizeof mods, "%s", k->modules);
    for (tok = strtok(mods, " "); tok; tok = strtok(NULL, " ")) {
      snprintf(paths[nf], sizeof paths[nf], "%s/shl_%s.glsl", dir, tok);
      files[nf] = paths[nf];
      nf++;
    }
  }
  /* every coefficient consumed with a constant index (a loop over 256 of them is not
     unrolled by Mesa, and its dynamic indexing would dominate the time) */
  at = (size_t)snprintf(defines, sizeof defines, "#define SHLIGHT_MAX_BANDS %d\n%s", k->bands,
                        reps > 1 ? "#define GLSL_BUDGET_REPS 1\n" : "");
  at += (size_t)snprintf(defines + at, sizeof defines - at, "#define GLSL_BUDGET_SUM_Y (y[0]");
  for (i = 1; i < k->bands * k->bands; ++i)
    at += (size_t)snprintf(defines + at, sizeof defines - at, " + y[%d]", i);
  at +=
      (size_t)snprintf(defines + at, sizeof defines - at, ")\n#define GLSL_BUDGET_SUM_G dot(g[0]");
  for (i = 1; i < k->bands * k->bands; ++i)
    at += (size_t)snprintf(defines + at, sizeof defines - at, " + g[%d]", i);
  at += (size_t)snprintf(defines + at, sizeof defines - at,
                         ", vec3(1.0))\n#define GLSL_BUDGET_SET_SH");
  for (i = 0; i < k->bands * k->bands; ++i)
    at += (size_t)snprintf(defines + at, sizeof defines - at, " sh[%d] = %.6f;", i,
                           0.8 * cos(0.7 * i) / (1.0 + 0.1 * i));
  snprintf(defines + at, sizeof defines - at, "\n");
  for (i = 0; i < count; ++i) {
    float u = (float)(i % 512) / 512.0f, v = (float)(i / 512) / 512.0f;
    in[4 * i] = 2.0f * u - 1.0f + 1e-3f;
    in[4 * i + 1] = 2.0f * v - 1.0f;
    in[4 * i + 2] = 0.3f + u * v;
    in[4 * i + 3] = (float)reps;
  }
  c0 = now(CLOCK_PROCESS_CPUTIME_ID);
  w0 = now(CLOCK_MONOTONIC);
  if (glrun_fragment(defines, files, nf, main_of(k), in, 1, out, 1, count) != 0) return -1;
  *cpu = now(CLOCK_PROCESS_CPUTIME_ID) - c0;
  *wall = now(CLOCK_MONOTONIC) - w0;
  return 0;
}

int main(int argc, char **argv) {
  double factor = 0.0, cpu, wall, c1, w1, c2, w2;
  const char *dir = "shlight_glsl";
  int i, a, passed = 0, failed = 0, do_run = 1, one = 0, reps = 8;
  const char *match = "";
  for (a = 1; a < argc; ++a) {
    if (!strcmp(argv[a], "--check") && a + 1 < argc)
      factor = atof(argv[++a]);
    else if (!strcmp(argv[a], "--no-run"))
      do_run = 0;
    else if (!strcmp(argv[a], "--one-include"))
      one = 1;
    else if (!strcmp(argv[a], "--match") && a + 1 < argc)
      match = argv[++a];
    else if (!strcmp(argv[a], "--reps") && a + 1 < argc)
      reps = atoi(argv[++a]);
    else
      dir = argv[a];
  }
  if (glrun_open(NULL) != 0) {
    printf("no GL context\n0 passed, 1 failed\n");
    return 1;
  }
  printf("renderer: %s (%s); GLSL from %s%s\n", glrun_renderer(), glrun_backend(), dir,
         one ? "/shlight.glsl" : " (per-module files)");
  printf("%-40s %9s %9s %8s\n", "shader (compile + link + first draw)", "CPU s", "wall s",
         "budget");
  for (i = 0; i < (int)(sizeof CASES / sizeof CASES[0]); ++i) {
    const struct kcase *k = &CASES[i];
    if (!strstr(k->name, match)) continue;
    if (factor > 0.0 && !k->checked) {
      printf("%-40s skipped: over budget today, not checked (known gap)\n", k->name);
      continue;
    }
    if (run(k, dir, one, 64, 1, &cpu, &wall) != 0) {
      printf("%-40s FAILED to build: %s\n", k->name, glrun_last_log());
      failed++;
      continue;
    }
    printf("%-40s %9.3f %9.3f", k->name, cpu, wall);
    if (k->budget > 0.0) {
      printf(" %8.1f", k->budget);
      if (factor > 0.0) {
        int ok = cpu <= factor * k->budget;
        printf("  %s (%.0fx)", ok ? "ok" : "OVER", factor);
        if (ok)
          passed++;
        else
          failed++;
      }
    }
    printf("\n");
    fflush(stdout);
  }
  if (do_run) {
    printf("\nrun time, 512 x 512 pass, per-pixel direction (ms per frame, from %d extra "
           "evaluations per pixel)\n",
           reps);
    for (i = 0; i < (int)(sizeof CASES / sizeof CASES[0]); ++i) {
      const struct kcase *k = &CASES[i];
      if (!k->runtime || !strstr(k->name, match)) continue;
      if (run(k, dir, one, 512 * 512, 2, &c1, &w1) != 0 ||
          run(k, dir, one, 512 * 512, 2 + reps, &c2, &w2) != 0) {
        printf("%-40s FAILED\n", k->name);
        failed++;
        continue;
      }
      printf("%-40s %9.2f ms CPU (wall %.2f ms)\n", k->name, 1e3 * (c2 - c1) / reps,
             1e3 * (w2 - w1) / reps);
      fflush(stdout);
    }
  }
  glrun_close();
  printf("%d passed, %d failed\n", passed, failed);
  return failed ? 1 : 0;
}
