/* bench_light.c - sphere and triangle lights: ns per light with and without the gradient, and
 * the cap ZH error of the stable and the printed forms against binary128 (tests/ref/lightref.h).
 * Writes bench/out/light.md. Build and run: make bench-light (gcc -O3 -march=native).
 * Method as bench_basis.c: per-thread CPU time, median of 15 samples of >= 2 ms, 256 random
 * configurations cycled, non-inlined wrappers with a literal band count, a memory barrier. */
#define _POSIX_C_SOURCE 200809L
#define SHLIGHT_IMPLEMENTATION
#include "../shlight.h"
#include "../tests/ref/lightref.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#define NOINL __attribute__((noinline))
#define NCFG 256
static float X[NCFG][3], C[NCFG][3], R[NCFG], P1[NCFG][3], P2[NCFG][3];
static float sh[256], gr[256][3];
static volatile float sink;

static uint64_t rs = 0x1234567u;
static double rnd(void) {
  uint64_t z = (rs += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return (double)((z ^ (z >> 31)) >> 11) * (1.0 / 9007199254740992.0);
}
static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}
typedef void (*wfn)(int i);
static double time_ns(wfn f) {
  double s[15], t0, t;
  int k, j, it;
  for (k = 0; k < 15; ++k) {
    it = 0;
    t0 = now();
    do {
      for (j = 0; j < NCFG; ++j) {
        f(j);
        __asm__ volatile("" ::"r"(sh), "r"(gr) : "memory");
      }
      it += NCFG;
    } while ((t = now()) - t0 < 2e-3);
    s[k] = (t - t0) / it * 1e9;
  }
  for (k = 0; k < 15; ++k)
    for (j = k + 1; j < 15; ++j)
      if (s[j] < s[k]) t = s[k], s[k] = s[j], s[j] = t;
  return s[7];
}

#define NL(X) X(2) X(3) X(4) X(6) X(8) X(10) X(16)
#define W(N)                                                                                       \
  NOINL void sph_##N(int i) {                                                                      \
    shl_sphere_light(N, X[i], C[i], R[i], sh);                                                     \
  }                                                                                                \
  NOINL void sphg_##N(int i) {                                                                     \
    shl_sphere_light_grad(N, X[i], C[i], R[i], sh, gr);                                            \
  }                                                                                                \
  NOINL void tri_##N(int i) {                                                                      \
    shl_triangle_light(N, X[i], C[i], P1[i], P2[i], sh);                                           \
  }                                                                                                \
  NOINL void trig_##N(int i) {                                                                     \
    shl_triangle_light_grad(N, X[i], C[i], P1[i], P2[i], sh, gr);                                  \
  }                                                                                                \
  NOINL void eval_##N(int i) {                                                                     \
    shl_sh_eval(N, X[i], sh);                                                                      \
  }
NL(W)
NOINL void solid(int i) {
  sink = shl_triangle_solid_angle(X[i], C[i], P1[i], P2[i]);
}

int main(void) {
  FILE *md;
  int i, k;
  static const double caps[] = {1e-8, 1e-6, 1e-4, 1e-3, 1e-2, 1e-1, 0.5, 0.9, 0.99};
  for (i = 0; i < NCFG; ++i) {
    double r = 0.05 + 0.5 * rnd(), d = r * (1.1 + 30.0 * rnd());
    double th = acos(2.0 * rnd() - 1.0), ph = 6.283185307179586 * rnd(), n2 = 0;
    for (k = 0; k < 3; ++k)
      X[i][k] = (float)(2.0 * rnd() - 1.0);
    C[i][0] = X[i][0] + (float)(d * sin(th) * cos(ph));
    C[i][1] = X[i][1] + (float)(d * sin(th) * sin(ph));
    C[i][2] = X[i][2] + (float)(d * cos(th));
    R[i] = (float)r;
    for (k = 0; k < 3; ++k) {
      P1[i][k] = C[i][k] + (float)(r * (2.0 * rnd() - 1.0));
      P2[i][k] = C[i][k] + (float)(r * (2.0 * rnd() - 1.0));
    }
    (void)n2;
  }
  md = fopen("bench/out/light.md", "w");
  if (!md) md = stdout;
  fprintf(md, "## shlight light benchmark (bench/bench_light.c)\n\nns per light, median, "
              "gcc -O3 -march=native; shl_sh_eval of the same n for scale.\n\n");
  fprintf(md,
          "| n | sh_eval | sphere | sphere+grad | ratio | triangle | triangle+grad | ratio |\n");
  fprintf(md, "|---|---|---|---|---|---|---|---|\n");
#define ROW(N)                                                                                     \
  {                                                                                                \
    double e = time_ns(eval_##N), a = time_ns(sph_##N), b = time_ns(sphg_##N);                     \
    double c = time_ns(tri_##N), d = time_ns(trig_##N);                                            \
    fprintf(md, "| %d | %.1f | %.1f | %.1f | %.2f | %.1f | %.1f | %.2f |\n", N, e, a, b, b / a, c, \
            d, d / c);                                                                             \
  }
  NL(ROW)
  fprintf(md, "\nshl_triangle_solid_angle: %.1f ns\n", time_ns(solid));
  /* cap ZH error: stable vs printed, float, against binary128 quadrature; n = 16 */
  fprintf(md, "\n### cap ZH, n = 16: max |L_l - ref| / max |ref|\n\n| s = r/d | stable "
              "(shl_zh_cap) | printed (shl_zh_cap_printed) |\n|---|---|---|\n");
  for (k = 0; k < (int)(sizeof caps / sizeof caps[0]); ++k) {
    float zs[16], zp[16], rr = (float)caps[k], dd = 1.0f;
    lref_q ref[SHREF_MAX_BANDS], a = asinq((lref_q)rr);
    double es = 0, ep = 0, mx = 0;
    shl_zh_cap(16, rr, dd, zs);
    shl_zh_cap_printed(16, rr, dd, zp);
    lref_cap_zh_q(16, a, ref);
    for (i = 0; i < 16; ++i)
      mx = fmax(mx, fabs((double)ref[i]));
    for (i = 0; i < 16; ++i) {
      es = fmax(es, fabs((double)zs[i] - (double)ref[i]) / mx);
      ep = fmax(ep, fabs((double)zp[i] - (double)ref[i]) / mx);
    }
    fprintf(md, "| %.0e | %.1e | %.1e |\n", caps[k], es, ep);
  }
  if (md != stdout) {
    fclose(md);
    md = fopen("bench/out/light.md", "r");
    while (md && (k = fgetc(md)) != EOF)
      putchar(k);
    if (md) fclose(md);
  }
  return 0;
}
