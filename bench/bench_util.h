/* bench_util.h - harness pieces shared by the bench/ programs. Include after
 * `#define _POSIX_C_SOURCE 200809L` (clock_gettime). Every function is static and marked unused,
 * so a program takes only what it calls:
 *   rnd()    splitmix64, a uniform double in [0, 1); state rs, seeded with BENCH_SEED (define it
 *            before the include to keep a program's own sequence; default 0x2545F4914F6CDD1D)
 *   now()    per-thread CPU time in seconds (CLOCK_THREAD_CPUTIME_ID)
 *   cmpd     qsort comparator of doubles; pct(a, n, p) the p-quantile, nearest rank (sorts a);
 *            stats(x, n, &med, &p95, &max) (sorts x)
 *   unit, cross  of double 3-vectors
 *   BENCH_DEFINE_TIME_NS(fn) defines time_ns(): ns per call of fn(j), j over 0..NCFG-1, median
 *            of 15 samples of >= 2 ms (a direct call: fn is the program's noinline wrapper)
 *   with BENCH_QUADS defined: the quad-light configuration cfg and its sampler make() of
 *            bench_edge.c and bench_microfacet.c
 *   with BENCH_GGXCASES defined: NR, NPER, NCFG, ROUGH and ggx_case() of bench_ggx.c and
 *            bench_beckmann.c */
#ifndef BENCH_UTIL_H
#define BENCH_UTIL_H

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <time.h>

#define BENCH_FN static __attribute__((unused))

#ifndef BENCH_SEED
#define BENCH_SEED 0x2545F4914F6CDD1Dull
#endif
static uint64_t rs = BENCH_SEED;
BENCH_FN double rnd(void) {
  uint64_t z = (rs += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return (double)((z ^ (z >> 31)) >> 11) * (1.0 / 9007199254740992.0);
}
BENCH_FN double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}
BENCH_FN int cmpd(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return x < y ? -1 : x > y;
}
BENCH_FN double pct(double *a, int n, double p) {
  if (n == 0) return 0;
  qsort(a, (size_t)n, sizeof *a, cmpd);
  return a[(int)floor(p * (n - 1) + 0.5)];
}
BENCH_FN void stats(double *x, int n, double *med, double *p95, double *mx) {
  qsort(x, (size_t)n, sizeof *x, cmpd);
  *med = n ? x[n / 2] : 0, *p95 = n ? x[n * 95 / 100] : 0, *mx = n ? x[n - 1] : 0;
}
BENCH_FN void unit(double a[3]) {
  double l = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  a[0] /= l, a[1] /= l, a[2] /= l;
}
BENCH_FN void cross(const double a[3], const double b[3], double o[3]) {
  o[0] = a[1] * b[2] - a[2] * b[1], o[1] = a[2] * b[0] - a[0] * b[2],
  o[2] = a[0] * b[1] - a[1] * b[0];
}

#define BENCH_DEFINE_TIME_NS(fn) \
  static double time_ns(void) { \
    double s[15], t0, t; \
    int k, j, it; \
    for (k = 0; k < 15; ++k) { \
      it = 0; \
      t0 = now(); \
      do { \
        for (j = 0; j < NCFG; ++j) \
          fn(j); \
        it += NCFG; \
      } while ((t = now()) - t0 < 2e-3); \
      s[k] = (t - t0) / it * 1e9; \
    } \
    for (k = 0; k < 15; ++k) \
      for (j = k + 1; j < 15; ++j) \
        if (s[j] < s[k]) t = s[k], s[k] = s[j], s[j] = t; \
    return s[7]; \
  }

#ifdef BENCH_QUADS
typedef struct {
  float v[4][3], n[3], view[3];
  int cls; /* bit 0 straddles the horizon, 1 grazing view (> 70 deg), 2 large, 3 sliver */
} cfg;
/* surface normal +z; view at angle tv; the quad centred near the mirror direction (60 %) or
   anywhere above z > -0.25 (40 %), distance 1..10, half-extent / distance 0.02..1.2, tilted;
   15 % slivers */
static void make(cfg *c) {
  double tv = acos(1 - rnd() * 0.97), pv = 6.2831853 * rnd(), r[3], d[3], t1[3], t2[3], nl[3];
  double dist = 1 + 9 * rnd(), ext, sx, sy, mn = 1e9, mx = -1e9;
  int i, k, sliver = rnd() < 0.15;
  c->view[0] = (float)(sin(tv) * cos(pv)), c->view[1] = (float)(sin(tv) * sin(pv));
  c->view[2] = (float)cos(tv);
  c->n[0] = 0, c->n[1] = 0, c->n[2] = 1;
  r[0] = -c->view[0], r[1] = -c->view[1], r[2] = c->view[2];
  if (rnd() < 0.6) {
    for (k = 0; k < 3; ++k)
      d[k] = r[k] + 0.4 * (rnd() - 0.5);
  } else {
    double z = -0.25 + 1.25 * rnd(), p = 6.2831853 * rnd();
    d[0] = sqrt(1 - z * z) * cos(p), d[1] = sqrt(1 - z * z) * sin(p), d[2] = z;
  }
  unit(d);
  for (k = 0; k < 3; ++k)
    nl[k] = -d[k] + 0.8 * (rnd() - 0.5);
  unit(nl);
  t1[0] = 0.3, t1[1] = -0.7, t1[2] = 0.5;
  cross(nl, t1, t2);
  unit(t2);
  cross(t2, nl, t1);
  ext = dist * (rnd() < 1.0 / 3 ? 0.02 + 0.08 * rnd()
                : rnd() < 0.5   ? 0.1 + 0.3 * rnd()
                                : 0.4 + 0.8 * rnd());
  for (i = 0; i < 4; ++i) {
    sx = (i == 0 || i == 3) ? -ext : ext;
    sy = (i < 2) ? -ext : ext;
    if (sliver) sy *= 0.02;
    for (k = 0; k < 3; ++k)
      c->v[i][k] = (float)(dist * d[k] + sx * t1[k] + sy * t2[k]);
    mn = fmin(mn, c->v[i][2]), mx = fmax(mx, c->v[i][2]);
  }
  c->cls =
      (mn < 0 && mx > 0) | (tv > 1.2217 ? 2 : 0) | (ext / dist > 0.4 ? 4 : 0) | (sliver ? 8 : 0);
}
#endif

#ifdef BENCH_GGXCASES
/* bench_ggx.c's sampler, the LTC comparison's (tests/ref/ggxcases.h, included before this
   header): NR roughness values x NPER quads, alpha = r^2 */
#define NR 7
#define NPER 250
#define NCFG (NR * NPER)
static const double ROUGH[NR] = {0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1.0};
/* the next case of rg, float-rounded: quad q, view; alpha of case number i */
static void ggx_case(ggxc_rng *rg, int i, float q[4][3], float view[3], float *alpha) {
  ggxc_case cs;
  int j;
  ggxc_make(rg, &cs, -1);
  for (j = 0; j < 12; ++j)
    q[j / 3][j % 3] = (float)cs.q[j / 3][j % 3];
  for (j = 0; j < 3; ++j)
    view[j] = (float)cs.view[j];
  *alpha = (float)(ROUGH[i / NPER] * ROUGH[i / NPER]);
}
#endif

#endif
