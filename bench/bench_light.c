/* bench_light.c - sphere and triangle lights: ns per light with and without the gradient, and
 * the cap ZH error of the stable and the printed forms against binary128 (tests/ref/lightref.h).
 * Writes bench/out/light.md. Build and run: make bench-light (gcc -O3 -march=native).
 * Method as bench_basis.c: per-thread CPU time, median of 31 samples of >= 1 ms, interleaved
 * across all variants and n, 256 random configurations cycled, non-inlined wrappers (bw_*) with
 * a literal band count, a memory barrier. --count-only VARIANT N K runs K calls only
 * (bench/callgrind_light.sh counts instructions with it). */
#define _POSIX_C_SOURCE 200809L
#define SHLIGHT_IMPLEMENTATION
#include "../shlight.h"
#include "../tests/ref/published.h" /* the published forms, for comparison */
#include "../tests/ref/lightref.h"
#define BENCH_SEED 0x1234567u
#include "bench_util.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifndef BENCH_FLAGS
#define BENCH_FLAGS "?"
#endif
#ifndef BENCH_REV
#define BENCH_REV "?"
#endif

#define NOINL __attribute__((noinline))
#define NCFG 256
#define NSAMP 31
static float X[NCFG][3], C[NCFG][3], R[NCFG], P1[NCFG][3], P2[NCFG][3], U[NCFG][3];
static float sh[SHLIGHT_MAX_COEFFS], gr[SHLIGHT_MAX_COEFFS][3];
static volatile float sink;

typedef void (*wfn)(int i);
/* one sample: reps passes over the NCFG configurations, ns per call */
static double sample_ns(wfn f, int reps) {
  double t0 = now();
  int j, k;
  for (k = 0; k < reps; ++k)
    for (j = 0; j < NCFG; ++j) {
      f(j);
      __asm__ volatile("" ::"r"(sh), "r"(gr) : "memory");
    }
  return (now() - t0) / ((double)reps * NCFG) * 1e9;
}
static int calibrate(wfn f) { /* passes per sample so one sample takes >= 1 ms */
  int reps = 1;
  sample_ns(f, 1);
  while (sample_ns(f, reps) * reps * NCFG < 1e6)
    reps *= 2;
  return reps;
}
static void sort(double *v, int m) {
  int a, b;
  double t;
  for (a = 0; a < m; ++a)
    for (b = a + 1; b < m; ++b)
      if (v[b] < v[a]) t = v[a], v[a] = v[b], v[b] = t;
}
/* quartiles of m sorted values: q[0] lower, q[1] median, q[2] upper */
static void quart(const double *v, int m, double *q) {
  q[0] = v[m / 4];
  q[1] = v[m / 2];
  q[2] = v[(3 * m) / 4];
}

#define NL(X) \
  X(2) X(3) X(4) X(5) X(6) X(7) X(8) X(9) X(10) X(11) X(12) X(13) X(14) X(15) X(16) X(32) X(64)
#define W(N) \
  NOINL void bw_eval_##N(int i) { \
    shl_sh_eval(N, U[i], sh); \
  } \
  NOINL void bw_evgrad_##N(int i) { \
    shl_sh_eval_grad(N, U[i], sh, gr); \
  } \
  NOINL void bw_sph_##N(int i) { \
    shl_sphere_light(N, X[i], C[i], R[i], sh); \
  } \
  NOINL void bw_sphg_##N(int i) { \
    shl_sphere_light_grad(N, X[i], C[i], R[i], sh, gr); \
  } \
  NOINL void bw_tri_##N(int i) { \
    shl_triangle_light(N, X[i], C[i], P1[i], P2[i], sh); \
  } \
  NOINL void bw_trig_##N(int i) { \
    shl_triangle_light_grad(N, X[i], C[i], P1[i], P2[i], sh, gr); \
  }
NL(W)
NOINL void bw_solid(int i) {
  sink = shl_triangle_solid_angle(X[i], C[i], P1[i], P2[i]);
}
#define NV 6 /* variants per n: eval, sphere, sphere+grad, triangle, triangle+grad, eval+grad */
static const char *const vnames[NV] = {"eval", "sph", "sphg", "tri", "trig", "evgrad"};
#define FN(N) {bw_eval_##N, bw_sph_##N, bw_sphg_##N, bw_tri_##N, bw_trig_##N, bw_evgrad_##N},
#define NN(N) N,
static const wfn fns[][NV] = {NL(FN)};
static const int ns[] = {NL(NN)};
#define NNS ((int)(sizeof ns / sizeof ns[0]))

int main(int argc, char **argv) {
  FILE *md;
  int i, k, v, j;
  static const double caps[] = {1e-8, 1e-6, 1e-4, 1e-3, 1e-2, 1e-1, 0.5, 0.9, 0.99};
  static int reps[32][NV];
  static double smp[32][NV][NSAMP];
  for (i = 0; i < NCFG; ++i) {
    double r = 0.05 + 0.5 * rnd(), d = r * (1.1 + 30.0 * rnd());
    double th = acos(2.0 * rnd() - 1.0), ph = 6.283185307179586 * rnd();
    for (k = 0; k < 3; ++k)
      X[i][k] = (float)(2.0 * rnd() - 1.0);
    C[i][0] = X[i][0] + (float)(d * sin(th) * cos(ph));
    C[i][1] = X[i][1] + (float)(d * sin(th) * sin(ph));
    C[i][2] = X[i][2] + (float)(d * cos(th));
    R[i] = (float)r;
    U[i][0] = (float)(sin(th) * cos(ph)); /* the unit direction to the light, for shl_sh_eval */
    U[i][1] = (float)(sin(th) * sin(ph));
    U[i][2] = (float)cos(th);
    for (k = 0; k < 3; ++k) {
      P1[i][k] = C[i][k] + (float)(r * (2.0 * rnd() - 1.0));
      P2[i][k] = C[i][k] + (float)(r * (2.0 * rnd() - 1.0));
    }
  }
  /* --count-only VARIANT N K: K calls (configurations cycled), for callgrind_light.sh */
  if (argc == 5 && !strcmp(argv[1], "--count-only")) {
    int n = atoi(argv[3]), kk = atoi(argv[4]);
    wfn f = 0;
    if (!strcmp(argv[2], "solid")) f = bw_solid;
    for (i = 0; i < NNS; ++i)
      for (v = 0; v < NV; ++v)
        if (ns[i] == n && !strcmp(argv[2], vnames[v])) f = fns[i][v];
    if (!f) return 2;
    for (k = 0; k < kk; ++k) {
      f(k % NCFG);
      __asm__ volatile("" ::"r"(sh), "r"(gr) : "memory");
    }
    return 0;
  }
  for (i = 0; i < NNS; ++i)
    for (v = 0; v < NV; ++v)
      reps[i][v] = calibrate(fns[i][v]);
  /* interleaved: sample s of every variant and n before sample s + 1, so a burst of load from
     other processes hits all of them; ratios are taken per sample (same moment), then median */
  for (j = 0; j < NSAMP; ++j)
    for (i = 0; i < NNS; ++i)
      for (v = 0; v < NV; ++v)
        smp[i][v][j] = sample_ns(fns[i][v], reps[i][v]);
  md = fopen("bench/out/light.md", "w");
  if (!md) md = stdout;
  fprintf(
      md,
      "## shlight light benchmark (bench/bench_light.c)\n\nns per light, median of %d "
      "interleaved samples of >= 1 ms, " BENCH_FLAGS " (shlight.h at " BENCH_REV
      "); shl_sh_eval and shl_sh_eval_grad (the basis values and gradient the lights use) at the "
      "unit direction to the light, for scale. ratio: with gradient / without, the "
      "median of the per-sample ratios, [lower - upper quartile].\n\n",
      NSAMP);
  fprintf(md, "| n | sh_eval | sh_eval_grad | sphere | sphere+grad | ratio | triangle | "
              "triangle+grad | ratio |\n");
  fprintf(md, "|---|---|---|---|---|---|---|---|---|\n");
  for (i = 0; i < NNS; ++i) {
    double med[NV], q[3], rq[2][3], rt[NSAMP], tmp[NSAMP];
    for (v = 0; v < NV; ++v) {
      memcpy(tmp, smp[i][v], sizeof tmp);
      sort(tmp, NSAMP);
      quart(tmp, NSAMP, q);
      med[v] = q[1];
    }
    for (k = 0; k < 2; ++k) {
      for (j = 0; j < NSAMP; ++j)
        rt[j] = smp[i][2 + 2 * k][j] / smp[i][1 + 2 * k][j];
      sort(rt, NSAMP);
      quart(rt, NSAMP, rq[k]);
    }
    fprintf(
        md,
        "| %d | %.1f | %.1f | %.1f | %.1f | %.2f [%.2f-%.2f] | %.1f | %.1f | %.2f [%.2f-%.2f] |\n",
        ns[i], med[0], med[5], med[1], med[2], rq[0][1], rq[0][0], rq[0][2], med[3], med[4],
        rq[1][1], rq[1][0], rq[1][2]);
  }
  {
    double t[NSAMP];
    int rr = calibrate(bw_solid);
    for (j = 0; j < NSAMP; ++j)
      t[j] = sample_ns(bw_solid, rr);
    sort(t, NSAMP);
    fprintf(md, "\nshl_triangle_solid_angle: %.1f ns\n", t[NSAMP / 2]);
  }
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
