/* bench_batch.c - shl_sh_eval_batch at any count: ns per direction for count = 16 .. 65536 at
 * n = 3, 6, 10, 16 (and the spread across counts), each against a plain-loop yardstick of the
 * same run.
 *
 * Build:  make build/bench/bench_batch            (against ./shlight.h)
 *         sh bench/baseline.sh                    (the same bench against a baseline header too,
 *                                                  run interleaved: see there)
 * Run:    build/bench/bench_batch [--quick]
 *
 * Time = per-thread CPU time, median of S samples of >= 2 ms each; the counts of one n are
 * timed interleaved (sample k of every count before sample k + 1 of any), so that they share the
 * machine's noise. Each sample evaluates about 64 Ki directions (count 65536: one call) in two
 * ways: `reuse`, into one output of n^2 * count floats rewritten call after call (small counts
 * then stay in L1: the kernel's compute speed), and `fresh`, each call writing the next
 * n^2 * count floats of a 64 MiB arena, as a caller that keeps its results does (every count
 * then writes n^2 x 256 KiB in all; the lines are flushed from the caches before each sample,
 * so these are memory-cold writes). count = 65536 writes n^2 x 256 KiB either
 * way (beyond the L2 for n >= 3).
 * The yardstick `loop` is the plain float loop of Sloan's recurrence (bench_basis.c's base_f),
 * one direction a call, n a run-time argument: ratio = batch ns / loop ns. */
#define _POSIX_C_SOURCE 200809L
#define SHLIGHT_IMPLEMENTATION
#ifdef BENCH_HEADER
#include BENCH_HEADER /* bench/baseline.sh: the same bench against another header */
#else
#include "../shlight.h"
#endif
#include "bench_util.h"

#include <stdio.h>
#include <string.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#if defined(__clang__)
#define NOINL __attribute__((noinline, used))
#else
#define NOINL __attribute__((noinline, noclone, used))
#endif

#define MAXN 16
#define MAXCNT 65536
#define NCNT 7
#define NBN 4
static const int COUNTS[NCNT] = {16, 32, 100, 1000, 1024, 4096, 65536};
static const int BANDS[NBN] = {3, 6, 10, 16};

static float *gx, *gy, *gz, *gout;

/* the yardstick: bench_basis.c's base_f (Sloan's recurrence as a plain float loop) */
static float LA[MAXN][MAXN], LB[MAXN][MAXN], LPMM[MAXN], LP1[MAXN];
static void loop_init(void) {
  double p = 0.28209479177387814;
  int l, m;
  for (m = 0; m < MAXN; m++) {
    if (m > 0) p *= -sqrt((2.0 * m + 1.0) / (2.0 * m));
    LPMM[m] = (float)(m > 0 ? p * 1.4142135623730951 : p);
    LP1[m] = (float)sqrt(2.0 * m + 3.0);
    for (l = m + 2; l < MAXN; l++) {
      LA[m][l] = (float)sqrt((4.0 * l * l - 1.0) / ((double)l * l - (double)m * m));
      LB[m][l] = (float)sqrt(((l - 1.0) * (l - 1.0) - (double)m * m) /
                             (4.0 * (l - 1.0) * (l - 1.0) - 1.0));
    }
  }
}
NOINL void bw_loop(int n, float x, float y, float z, float *out) {
  float c = 1.0f, s = 0.0f, p0, p1, p2, t;
  int l, m, i;
  for (m = 0; m < n; m++) {
    p0 = LPMM[m];
    i = m * m + 2 * m;
    out[i] = p0 * c;
    if (m > 0) out[m * m] = p0 * s;
    if (m + 1 < n) {
      p1 = LP1[m] * z * p0;
      i = (m + 1) * (m + 2);
      out[i + m] = p1 * c;
      if (m > 0) out[i - m] = p1 * s;
      for (l = m + 2; l < n; l++) {
        p2 = LA[m][l] * (z * p1 - LB[m][l] * p0);
        i = l * (l + 1);
        out[i + m] = p2 * c;
        if (m > 0) out[i - m] = p2 * s;
        p0 = p1;
        p1 = p2;
      }
    }
    t = x * c - y * s;
    s = x * s + y * c;
    c = t;
  }
}

/* fresh: the arena's lines written by the sample are first flushed from the caches, as memory
   a caller allocated for its results and has not touched lately */
static void flush(const float *p, size_t bytes) {
#if defined(__SSE2__)
  size_t k;
  for (k = 0; k < bytes; k += 64)
    _mm_clflush((const char *)p + k);
  _mm_mfence();
#else
  (void)p;
  (void)bytes;
#endif
}

/* one sample: ~64 Ki directions in calls of `count` (count < 0: the yardstick loop); fresh: each
   call writes the next n^2 x count floats of the 64 MiB output arena (a caller that keeps its
   results), else every call rewrites the start of it */
/* 64-byte aligned: at 3 bands a call of 32 directions takes about 30 cycles, and where this
   loop fell relative to 32-byte boundaries moved it by up to 10 % between builds whose
   library code at 3 bands was identical */
#if defined(__GNUC__)
__attribute__((aligned(64)))
#endif
static double
sample(int n, int count, int fresh) {
  size_t per = (size_t)n * (size_t)n * (size_t)(count > 0 ? count : 1), o = 0;
  double t0, t1;
  int j, reps, r, total = 0;
  if (count < 0) {
    t0 = now();
    for (r = 0; r < 8; ++r)
      for (j = 0; j < 2048; ++j) {
        bw_loop(n, gx[j], gy[j], gz[j], gout);
        __asm__ volatile("" ::: "memory");
      }
    t1 = now();
    return (t1 - t0) * 1e9 / (8 * 2048);
  }
  reps = MAXCNT / count;
  if (reps < 1) reps = 1;
  if (fresh) flush(gout, per * (size_t)reps * sizeof(float));
  t0 = now();
  for (r = 0; r < reps; ++r) {
    /* consecutive calls walk the inputs (as a user batching a stream does) */
    int off = (r * count) % (MAXCNT - count + 1);
    if (o + per > (size_t)MAXN * MAXN * MAXCNT) o = 0;
    shl_sh_eval_batch(n, count, gx + off, gy + off, gz + off, gout + o);
    __asm__ volatile("" ::: "memory");
    if (fresh) o += per;
    total += count;
  }
  t1 = now();
  return (t1 - t0) * 1e9 / total;
}

int main(int argc, char **argv) {
  int quick = argc > 1 && strcmp(argv[1], "--quick") == 0;
  int S = quick ? 5 : 15, s, a, c, j, f;
  static double tm[2][NBN][NCNT + 1][64];
  void *mem;
  gx = (float *)malloc(sizeof(float) * MAXCNT);
  gy = (float *)malloc(sizeof(float) * MAXCNT);
  gz = (float *)malloc(sizeof(float) * MAXCNT);
  /* 64-byte aligned output (posix_memalign): a row of a count that is a multiple of 16 then
     starts on a cache line, as a user who allocates for SIMD has it */
  if (posix_memalign(&mem, 64, sizeof(float) * (size_t)MAXN * MAXN * MAXCNT)) return 1;
  gout = (float *)mem;
  if (!gx || !gy || !gz) return 1;
  memset(gout, 0, sizeof(float) * (size_t)MAXN * MAXN * MAXCNT);
  for (j = 0; j < MAXCNT; ++j) {
    double z = 2.0 * rnd() - 1.0, ph = 6.283185307179586 * rnd(), r = sqrt(1.0 - z * z);
    gx[j] = (float)(r * cos(ph));
    gy[j] = (float)(r * sin(ph));
    gz[j] = (float)z;
  }
  loop_init();
  for (f = 0; f < 2; ++f)
    for (a = 0; a < NBN; ++a) /* warm-up */
      for (c = 0; c <= NCNT; ++c)
        (void)sample(BANDS[a], c < NCNT ? COUNTS[c] : -1, f);
  for (s = 0; s < S; ++s)
    for (f = 0; f < 2; ++f)
      for (a = 0; a < NBN; ++a)
        for (c = 0; c <= NCNT; ++c)
          tm[f][a][c][s] = sample(BANDS[a], c < NCNT ? COUNTS[c] : -1, f);
  printf("shl_sh_eval_batch, ns per direction (median of %d samples of ~64 Ki directions; "
         "ratio to the plain loop in parentheses)\n",
         S);
  for (f = 0; f < 2; ++f) {
    printf("\n### %s\n\n| n | loop ns |",
           f ? "fresh: each call writes a new region of a 64 MiB arena"
             : "reuse: every call rewrites one output buffer");
    for (c = 0; c < NCNT; ++c)
      printf(" count %d |", COUNTS[c]);
    printf(" max/min |\n|---|---|");
    for (c = 0; c < NCNT; ++c)
      printf("---|");
    printf("---|\n");
    for (a = 0; a < NBN; ++a) {
      double lo = 1e30, hi = 0, lp = pct(tm[f][a][NCNT], S, 0.5);
      printf("| %d | %.2f |", BANDS[a], lp);
      for (c = 0; c < NCNT; ++c) {
        double v = pct(tm[f][a][c], S, 0.5);
        lo = v < lo ? v : lo;
        hi = v > hi ? v : hi;
        printf(" %.2f (%.3f) |", v, v / lp);
      }
      printf(" %.2f |\n", hi / lo);
    }
  }
  free(gx);
  free(gy);
  free(gz);
  free(gout);
  return 0;
}
