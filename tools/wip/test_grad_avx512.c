/* test + bench of tools/wip/grad_avx512.h.
   gcc -std=c99 -O3 -march=native -I/work/main tools/wip/test_grad_avx512.c -o /tmp/tg -lm
   (add -fsanitize=address,undefined for the sanitizer run; ./tg [bench]) */
#define _POSIX_C_SOURCE 200809L
#define _DEFAULT_SOURCE
#define SHLIGHT_IMPLEMENTATION
#include "shlight.h"
#include "tools/wip/grad_avx512.h"
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <time.h>
#include <unistd.h>

static uint64_t rng = 0x9E3779B97F4A7C15ull;
static double urand(void) {
  rng ^= rng << 13;
  rng ^= rng >> 7;
  rng ^= rng << 17;
  return (double)(rng >> 11) * (1.0 / 9007199254740992.0);
}

/* random direction d (|d| in [0.1, 10]) -> unit u (float), ir */
static void make_dir(int kind, int i, float u[3], float *ir) {
  double x, y, z, r, s;
  if (kind == 1) { /* exact poles */
    x = 0.0;
    y = 0.0;
    z = (i & 1) ? -1.0 : 1.0;
  } else if (kind == 2) { /* near poles */
    double e = pow(10.0, -1.0 - 7.0 * urand());
    double ph = 2.0 * M_PI * urand();
    x = e * cos(ph);
    y = e * sin(ph);
    z = (i & 1) ? -1.0 : 1.0;
  } else {
    do {
      x = 2.0 * urand() - 1.0;
      y = 2.0 * urand() - 1.0;
      z = 2.0 * urand() - 1.0;
      r = x * x + y * y + z * z;
    } while (r > 1.0 || r < 1e-4);
  }
  r = sqrt(x * x + y * y + z * z);
  s = 0.1 * pow(100.0, urand()); /* |d| */
  u[0] = (float)(x / r);
  u[1] = (float)(y / r);
  u[2] = (float)(z / r);
  *ir = (float)(1.0 / s);
}

/* buffer of `bytes` ending exactly at a PROT_NONE page */
static void *guarded(size_t bytes) {
  long pg = sysconf(_SC_PAGESIZE);
  size_t np = (bytes + (size_t)pg - 1) / (size_t)pg + 1;
  char *p = (char *)mmap(NULL, np * (size_t)pg, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == (char *)MAP_FAILED) {
    perror("mmap");
    exit(1);
  }
  mprotect(p + (np - 1) * (size_t)pg, (size_t)pg, PROT_NONE);
  return p + (np - 1) * (size_t)pg - bytes;
}

static int test(void) {
  int n, t, i, k, fails = 0;
  double worst = 0.0;
  float(*gs)[3] = (float(*)[3])malloc(sizeof(float[3]) * 256);
  float(*gcan)[3] = (float(*)[3])malloc(sizeof(float[3]) * (256 + 16));
  for (n = 1; n <= 16; ++n) {
    float *y = (float *)guarded(sizeof(float) * (size_t)(n * n));
    float(*gv)[3] = (float(*)[3])guarded(sizeof(float[3]) * (size_t)(n * n));
    double nworst = 0.0;
    for (t = 0; t < 2000 + 2 + 200; ++t) {
      float u[3], ir;
      double mx = 0.0, md = 0.0;
      make_dir(t < 2000 ? 0 : (t < 2002 ? 1 : 2), t, u, &ir);
      shl_sh_eval(n, u, y);
      shli_sh_grad(n, y, u[0], u[1], u[2], ir, gs);
      for (i = 0; i < n * n; ++i) {
        for (k = 0; k < 3; ++k) {
          gv[i][k] = -12345.0f;
        }
      }
      shli_sh_grad_avx512(n, y, u[0], u[1], u[2], ir, gv);
      /* canary: a normal buffer with entries past n*n */
      memset(gcan, 0x7f, sizeof(float[3]) * (256 + 16));
      shli_sh_grad_avx512(n, y, u[0], u[1], u[2], ir, gcan);
      for (i = n * n; i < 256 + 16; ++i) {
        for (k = 0; k < 3; ++k) {
          uint32_t b;
          memcpy(&b, &gcan[i][k], 4);
          if (b != 0x7f7f7f7fu) {
            if (fails++ < 10) {
              printf("n=%d: canary [%d][%d] overwritten\n", n, i, k);
            }
          }
        }
      }
      for (i = 0; i < n * n; ++i) {
        for (k = 0; k < 3; ++k) {
          if (fabs(gs[i][k]) > mx) {
            mx = fabs(gs[i][k]);
          }
          if (!(fabs((double)gv[i][k] - gs[i][k]) <= md)) {
            md = fabs((double)gv[i][k] - gs[i][k]);
          }
          if (memcmp(&gv[i][k], &gcan[i][k], 4) != 0 && fails++ < 10) {
            printf("n=%d: two runs differ at [%d][%d]\n", n, i, k);
          }
        }
      }
      if (n == 1) {
        mx = 1.0;
      }
      if (!(md / mx <= nworst)) {
        nworst = md / mx;
      }
      if (!(md / mx <= 1e-6)) {
        if (fails++ < 10) {
          printf("n=%d t=%d: rel err %.3g (u = %.9g %.9g %.9g, ir %.9g)\n", n, t, md / mx, u[0], u[1], u[2], ir);
        }
      }
    }
    printf("n=%2d  max |simd - scalar| / max|grad| = %.3g\n", n, nworst);
    if (nworst > worst) {
      worst = nworst;
    }
  }
  printf("overall worst %.3g, failures %d\n", worst, fails);
  free(gs);
  free(gcan);
  return fails != 0;
}

/* ------------------------------------------------------------------------------- bench */
#define ND 1024
static float dirs[ND][3], irs[ND];

__attribute__((noinline)) static void w_val(int n, const float *d, float ir, float *y, float (*g)[3]) {
  (void)ir;
  (void)g;
  shl_sh_eval(n, d, y);
}
__attribute__((noinline)) static void w_scal(int n, const float *d, float ir, float *y, float (*g)[3]) {
  shl_sh_eval(n, d, y);
  shli_sh_grad(n, y, d[0], d[1], d[2], ir, g);
}
__attribute__((noinline)) static void w_simd(int n, const float *d, float ir, float *y, float (*g)[3]) {
  shl_sh_eval(n, d, y);
  shli_sh_grad_avx512(n, y, d[0], d[1], d[2], ir, g);
}
__attribute__((noinline)) static void w_pscal(int n, const float *d, float ir, float *y, float (*g)[3]) {
  shli_sh_grad(n, y, d[0], d[1], d[2], ir, g);
}
__attribute__((noinline)) static void w_psimd(int n, const float *d, float ir, float *y, float (*g)[3]) {
  shli_sh_grad_avx512(n, y, d[0], d[1], d[2], ir, g);
}
__attribute__((noinline)) static void w_full(int n, const float *d, float ir, float *y, float (*g)[3]) {
  (void)ir;
  shl_sh_eval_grad(n, d, y, g);
}

typedef void (*wfn)(int, const float *, float, float *, float (*)[3]);

static double now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e9 + ts.tv_nsec;
}

static double run1(wfn f, int n, float *y, float (*g)[3]) {
  int i;
  double t0 = now();
  for (i = 0; i < ND; ++i) {
    f(n, dirs[i], irs[i], y, g);
    __asm__ volatile("" ::"r"(g), "r"(y) : "memory");
  }
  return (now() - t0) / ND;
}

static int cmpd(const void *a, const void *b) {
  double x = *(const double *)a, z = *(const double *)b;
  return x < z ? -1 : x > z;
}

static void bench(int reps) {
  static float y[256];
  static float g[256][3];
  wfn fs[6] = {w_val, w_scal, w_simd, w_pscal, w_psimd, w_full};
  double *s[6];
  double med[6];
  int n, i, r, v;
  for (i = 0; i < ND; ++i) {
    make_dir(0, i, dirs[i], &irs[i]);
  }
  for (v = 0; v < 6; ++v) {
    s[v] = (double *)malloc(sizeof(double) * (size_t)reps);
  }
  printf("  n | value ns | val+scalar ns | val+simd ns | scal/val simd/val | scalar pass | simd pass | eval_grad\n");
  for (n = 3; n <= 16; ++n) {
    shl_sh_eval(n, dirs[0], y);
    for (r = 0; r < 20; ++r) { /* warm */
      for (v = 0; v < 6; ++v) {
        run1(fs[v], n, y, g);
      }
    }
    for (r = 0; r < reps; ++r) {
      for (v = 0; v < 6; ++v) {
        s[v][r] = run1(fs[v], n, y, g);
      }
    }
    for (v = 0; v < 6; ++v) {
      qsort(s[v], (size_t)reps, sizeof(double), cmpd);
      med[v] = s[v][reps / 2];
    }
    printf(" %2d | %8.1f | %13.1f | %11.1f | %8.2f %8.2f | %11.1f | %9.1f | %9.1f\n", n, med[0], med[1], med[2],
           med[1] / med[0], med[2] / med[0], med[3], med[4], med[5]);
  }
  for (v = 0; v < 6; ++v) {
    free(s[v]);
  }
}

int main(int argc, char **argv) {
  int rc = 0;
  if (argc < 2 || strcmp(argv[1], "bench") != 0) {
    rc = test();
  }
  if (argc >= 2 && (strcmp(argv[1], "bench") == 0 || strcmp(argv[1], "all") == 0)) {
    bench(argc >= 3 ? atoi(argv[2]) : 101);
  }
  return rc;
}
