/* bench_grid.c - [GRAD] Table 2 workload: SH + gradients of 648 sphere lights on an 8^3 grid,
   n = 5..9, forward / reversed, 1 / 2 threads, median of 5; plus this CPU's measured float
   FMA peak (AVX-512, 1 and 2 threads). Build and run: make bench-grid. */
#define _POSIX_C_SOURCE 199309L
#define SHLIGHT_IMPLEMENTATION
#include "../shlight.h"
#include <immintrin.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}
static int cmpd(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return x < y ? -1 : x > y;
}
static unsigned long long st = 88172645463325252ull;
static double rnd(void) {
  st ^= st << 13;
  st ^= st >> 7;
  st ^= st << 17;
  return (double)(st >> 11) * (1.0 / 9007199254740992.0);
}

/* FMA peak: 16 independent zmm accumulators (> latency 4 x 2 ports) */
#define FMA_ITERS 50000000L
static void *fma_loop(void *arg) {
  __m512 a[16], m = _mm512_set1_ps(0.999999f), c = _mm512_set1_ps(1e-7f);
  long i;
  int k;
  for (k = 0; k < 16; ++k)
    a[k] = _mm512_set1_ps((float)k);
  for (i = 0; i < FMA_ITERS; ++i) {
    for (k = 0; k < 16; ++k)
      a[k] = _mm512_fmadd_ps(a[k], m, c);
  }
  for (k = 1; k < 16; ++k)
    a[0] = _mm512_add_ps(a[0], a[k]);
  *(float *)arg = _mm512_reduce_add_ps(a[0]);
  return NULL;
}
static double fma_peak(int threads) {
  pthread_t th;
  float sink[2];
  double t0 = now(), t;
  if (threads == 2) pthread_create(&th, NULL, fma_loop, &sink[1]);
  fma_loop(&sink[0]);
  if (threads == 2) pthread_join(th, NULL);
  t = now() - t0;
  if (sink[0] == 12345.0f) printf("!");
  return (double)threads * (double)FMA_ITERS * 16.0 * 16.0 * 2.0 / t; /* flop/s */
}

int main(int argc, char **argv) {
  enum { NL = 648 };
  static float c[NL][3], r[NL], in[NL];
  shl_grid g;
  int j, k, n, o, t, rep;
  double pk1, pk2;
  (void)argc;
  (void)argv;
  for (j = 0; j < NL; ++j) {
    for (k = 0; k < 3; ++k)
      c[j][k] = (float)rnd();
    r[j] = (float)(0.005 + 0.02 * rnd());
    in[j] = (float)(0.5 + rnd());
  }
  for (k = 0; k < 3; ++k) {
    g.origin[k] = 0.0f;
    g.spacing[k] = 1.0f / 7.0f;
  }
  g.dims[0] = g.dims[1] = g.dims[2] = 8;
  g.cull = 0.0f;
  pk1 = fma_peak(1);
  pk2 = fma_peak(2);
  printf("FMA peak (AVX-512 float): 1 thread %.1f GFLOP/s, 2 threads %.1f GFLOP/s\n", pk1 * 1e-9,
         pk2 * 1e-9);
  printf("8^3 grid, %d lights, SH + gradients, cull 0: median of 5, ms\n", NL);
  printf(" n   fwd/1   rev/1   fwd/2   rev/2   ns/light-vertex (rev/1)\n");
  for (n = 5; n <= 9; ++n) {
    float *sh = (float *)malloc(sizeof(float) * 512u * (size_t)(n * n));
    float(*gr)[3] = (float(*)[3])malloc(sizeof(float[3]) * 512u * (size_t)(n * n));
    double med[4];
    g.n = n;
    for (o = 0; o < 2; ++o)
      for (t = 1; t <= 2; ++t) {
        double ts[5];
        for (rep = 0; rep < 5; ++rep) {
          double t0 = now();
          shl_grid_build(&g, (const float(*)[3])c, r, in, NL, o, t, sh, gr);
          ts[rep] = now() - t0;
        }
        qsort(ts, 5, sizeof(double), cmpd);
        med[(t - 1) * 2 + o] = ts[2];
      }
    printf("%2d %7.2f %7.2f %7.2f %7.2f   %.1f\n", n, med[0] * 1e3, med[1] * 1e3, med[2] * 1e3,
           med[3] * 1e3, med[1] * 1e9 / (512.0 * NL));
    free(sh);
    free(gr);
  }
  return 0;
}
