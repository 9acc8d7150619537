/* bench_store.c - the store floors of shl_sh_eval_batch's output layout on this machine: how
 * fast one core can write n^2 floats per direction, with no arithmetic at all.
 *
 * Build:  make build/bench/bench_store
 * Run:    build/bench/bench_store [--quick]
 *
 * Part 1, bandwidth of plain sequential writes (one 64-byte vector per line, SIMD width of the
 * build) into a buffer of a given size, written over and over (the buffer stays in L1, L2 or
 * memory), with and without software prefetch for writing (`__builtin_prefetch(p, 1, 3)`,
 * PREFETCHW) DIST bytes ahead, and streaming (non-temporal) stores.
 *
 * Part 2, the batch's own pattern with no arithmetic: rows of `count` floats (n^2 rows), two
 * vectors of directions at a time, each writing its 2 x SHLI_W floats to every row (the store
 * order of the batch kernels), the output reused from call to call as bench_batch.c does
 * (`reuse`) or each call writing the next region of a 64 MiB arena (`fresh`, a caller that keeps
 * its results); plain stores, plain + prefetchw of the next pair's lines, streaming stores.
 * ns per direction, median of S samples of ~64 Ki directions (per-thread CPU time).
 * These times are lower bounds for the batch at that count: it does the same stores plus the
 * arithmetic (bench_batch.c's L1-resident counts 16, 32). */
#define _POSIX_C_SOURCE 200809L
#include "bench_util.h"

#include <stdio.h>
#include <string.h>
#include <immintrin.h>

#if defined(__AVX512F__)
#define VW 16
typedef __m512 vf;
#define VSTORE(p, v) _mm512_storeu_ps((p), (v))
#define VSTREAM(p, v) _mm512_stream_ps((p), (v))
#define VSET(c) _mm512_set1_ps(c)
#define VADD(a, b) _mm512_add_ps((a), (b))
#elif defined(__AVX__)
#define VW 8
typedef __m256 vf;
#define VSTORE(p, v) _mm256_storeu_ps((p), (v))
#define VSTREAM(p, v) _mm256_stream_ps((p), (v))
#define VSET(c) _mm256_set1_ps(c)
#define VADD(a, b) _mm256_add_ps((a), (b))
#else
#define VW 4
typedef __m128 vf;
#define VSTORE(p, v) _mm_storeu_ps((p), (v))
#define VSTREAM(p, v) _mm_stream_ps((p), (v))
#define VSET(c) _mm_set1_ps(c)
#define VADD(a, b) _mm_add_ps((a), (b))
#endif
#define LINEF 16 /* floats per 64-byte line */

#define NOINL __attribute__((noinline))
#define ARENA ((size_t)64 << 20) /* bytes */
static float *arena;

/* part 1: write `bytes` sequentially; mode 0 plain, 1 plain + prefetchw `dist` bytes ahead,
   2 streaming */
NOINL static void seq(float *p, size_t bytes, int mode, size_t dist) {
  size_t nf = bytes / sizeof(float), i, k;
  vf v = VSET(1.0f);
  for (i = 0; i < nf; i += LINEF) {
    if (mode == 1) __builtin_prefetch(p + i + dist / sizeof(float), 1, 3);
    for (k = 0; k < LINEF; k += VW) {
      if (mode == 2)
        VSTREAM(p + i + k, v);
      else
        VSTORE(p + i + k, v);
    }
  }
  if (mode == 2) _mm_sfence();
  __asm__ volatile("" ::: "memory");
}

/* part 2: one call of the batch's store pattern: count directions, n2 rows of count floats;
   mode 0 plain, 1 plain + prefetchw of the next pair's lines, 2 streaming */
NOINL static void rows(float *out, int n2, int count, int mode) {
  int j, i, v;
  vf a = VSET(1.0f);
  for (j = 0; j + 2 * VW <= count; j += 2 * VW) {
    for (i = 0; i < n2; ++i) {
      float *p = out + (ptrdiff_t)i * count + j;
      if (mode == 1 && j + 4 * VW <= count) {
        __builtin_prefetch(p + 2 * VW, 1, 3);
        if (2 * VW > LINEF) __builtin_prefetch(p + 2 * VW + LINEF, 1, 3);
      }
      for (v = 0; v < 2; ++v) {
        if (mode == 2 && count % VW == 0) /* as the batch: streams only aligned rows */
          VSTREAM(p + v * VW, a);
        else
          VSTORE(p + v * VW, a);
      }
    }
    a = VADD(a, a);
  }
  if (mode == 2) _mm_sfence();
  __asm__ volatile("" ::: "memory");
}

/* ns per direction of ~64 Ki directions in calls of count; fresh: each call writes the next
   region of the arena */
static double rows_sample(int n, int count, int mode, int fresh) {
  int n2 = n * n, r, reps = 65536 / count, total = 0;
  size_t per = (size_t)n2 * (size_t)count, off = 0;
  double t0, t1;
  if (reps < 1) reps = 1;
  t0 = now();
  for (r = 0; r < reps; ++r) {
    if (fresh) {
      if ((off + per) * sizeof(float) > ARENA) off = 0;
    }
    rows(arena + off, n2, count, mode);
    if (fresh) off += per;
    total += count;
  }
  t1 = now();
  return (t1 - t0) * 1e9 / total;
}

static double seq_sample(size_t bytes, int mode, size_t dist) {
  size_t done = 0;
  double t0 = now(), t1;
  while (done < ((size_t)64 << 20)) { /* >= 64 MiB a sample */
    seq(arena, bytes, mode, dist);
    done += bytes;
  }
  t1 = now();
  return (double)done / ((t1 - t0) * 1e9); /* GB/s */
}

#define S_MAX 31
static double med(double *a, int n) {
  return pct(a, n, 0.5);
}

int main(int argc, char **argv) {
  int quick = argc > 1 && strcmp(argv[1], "--quick") == 0;
  int S = quick ? 5 : 11, s, a, c, md, f;
  static const size_t SIZES[3] = {16 << 10, 1 << 20, (size_t)64 << 20};
  static const char *SNAME[3] = {"16 KiB (L1)", "1 MiB (L2)", "64 MiB (memory)"};
  static const int BANDS[4] = {3, 6, 10, 16};
  static const int COUNTS[6] = {32, 100, 1000, 1024, 4096, 65536};
  static const char *MNAME[3] = {"plain", "plain+prefetchw", "streaming"};
  static double tm[S_MAX];
  void *mem;
  if (posix_memalign(&mem, 64, ARENA)) return 1;
  arena = (float *)mem;
  memset(arena, 0, ARENA);
  printf("## Sequential write bandwidth, one core (GB/s, median of %d samples of 64 MiB; "
         "%d-float vectors)\n\n",
         S, VW);
  printf("| buffer | plain | plain + prefetchw 256 B ahead | plain + prefetchw 1 KiB ahead | "
         "streaming |\n|---|---|---|---|---|\n");
  for (a = 0; a < 3; ++a) {
    size_t bytes = SIZES[a];
    printf("| %s |", SNAME[a]);
    for (md = 0; md < 4; ++md) {
      int mode = md == 0 ? 0 : md == 3 ? 2 : 1;
      size_t dist = md == 1 ? 256 : 1024;
      for (s = 0; s < S; ++s)
        tm[s] = seq_sample(bytes, mode, dist);
      printf(" %.1f |", med(tm, S));
    }
    printf("\n");
  }
  printf("\n## The batch's store pattern alone (ns per direction, n^2 rows of count floats, "
         "two vectors of directions a step; median of %d samples of ~64 Ki directions)\n\n",
         S);
  for (f = 0; f < 2; ++f) {
    printf("### %s\n\n| n | stores |", f ? "fresh (each call a new region of a 64 MiB arena)"
                                         : "reuse (one output buffer, as bench_batch.c)");
    for (c = 0; c < 6; ++c)
      printf(" count %d |", COUNTS[c]);
    printf("\n|---|---|");
    for (c = 0; c < 6; ++c)
      printf("---|");
    printf("\n");
    for (a = 0; a < 4; ++a)
      for (md = 0; md < 3; ++md) {
        printf("| %d | %s |", BANDS[a], MNAME[md]);
        for (c = 0; c < 6; ++c) {
          (void)rows_sample(BANDS[a], COUNTS[c], md, f);
          for (s = 0; s < S; ++s)
            tm[s] = rows_sample(BANDS[a], COUNTS[c], md, f);
          printf(" %.2f |", med(tm, S));
        }
        printf("\n");
      }
    printf("\n");
  }
  free(mem);
  return 0;
}
