/* bench_basis.c - shlight SH basis / gradient: speed against error (DESIGN.md section 6).
 *
 * Build:  make -f bench/bench.mk          (build/bench/bench_basis; flags in bench/bench.mk)
 * Run:    build/bench/bench_basis [--quick] [--n 1,3,16] [--callgrind bench/out/instr.csv]
 *         build/bench/bench_basis --count-only VARIANT N K    (used by bench/callgrind.sh)
 * Method, columns and variants: bench/README.md.
 *
 * Every variant is called through a function pointer to a non-inlined wrapper (bw_*), one
 * wrapper per variant (and per n for the static-inline kernels, whose n is a literal as in
 * user code), with an asm barrier after each call.  Time = per-thread CPU time, median of S
 * samples of >= T ms, the variants' samples interleaved so that they share the machine's noise;
 * every ratio is taken against the plain-loop yardstick (`loop`, research base_f) of the same
 * run.  Errors: max abs error against the binary128 reference tests/ref/shref.h at the very
 * float input the variant saw. */
#define _POSIX_C_SOURCE 200112L
#define SHLIGHT_IMPLEMENTATION
#include "../shlight.h"
#include "../tests/ref/published.h" /* the published forms, for comparison */
#include "../tests/ref/shref.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#ifndef BENCH_REV
#define BENCH_REV "?"
#endif
#ifndef BENCH_FLAGS
#define BENCH_FLAGS "(flags not recorded: build with bench/bench.mk)"
#endif
#if defined(__clang__)
#define NOINL __attribute__((noinline, used))
#else
#define NOINL __attribute__((noinline, noclone, used))
#endif

#define NDIR 1024 /* random unit directions, cycled by the timing loop */
#define NPOLE 258 /* 256 near-pole (theta log-uniform in [1e-7, 1e-2], both poles) + 2 exact */
#define MAXN 64
#define MAXC (MAXN * MAXN)

/* ------------------------------------------------------------------ directions */
static uint64_t sm_state;
static uint64_t sm_next(void) {
  uint64_t z = (sm_state += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}
static double sm_u01(void) {
  return (double)(sm_next() >> 11) * (1.0 / 9007199254740992.0);
}

static const double PI_D = 3.14159265358979323846;
static double rnd_d[NDIR][3], pole_d[NPOLE][3]; /* unit, double */
static float rnd_f[NDIR][3], pole_f[NPOLE][3];  /* the same rounded to float */
static float rnd_g[NDIR][3], pole_g[NPOLE][3];  /* times a factor in [0.1, 10] (gradient) */
static float soa_rnd[3][NDIR], soa_pole[3][NPOLE];

static void make_dirs(void) {
  int j, i, k = (NPOLE - 2) / 2;
  sm_state = 0x5348u; /* fixed seed: every run sees the same directions */
  for (j = 0; j < NDIR; j++) {
    double z = 2.0 * sm_u01() - 1.0, ph = 2.0 * PI_D * sm_u01(), r = sqrt(fmax(0.0, 1.0 - z * z));
    double len;
    rnd_d[j][0] = r * cos(ph);
    rnd_d[j][1] = r * sin(ph);
    rnd_d[j][2] = z;
    len = sqrt(rnd_d[j][0] * rnd_d[j][0] + rnd_d[j][1] * rnd_d[j][1] + z * z); /* renormalise */
    for (i = 0; i < 3; i++)
      rnd_d[j][i] /= len;
  }
  for (j = 0; j < 2 * k; j++) {
    double th = pow(10.0, -7.0 + 5.0 * sm_u01()), ph = 2.0 * PI_D * sm_u01();
    pole_d[j][0] = sin(th) * cos(ph);
    pole_d[j][1] = sin(th) * sin(ph);
    pole_d[j][2] = (j < k ? 1.0 : -1.0) * cos(th);
  }
  pole_d[2 * k][0] = pole_d[2 * k][1] = pole_d[2 * k + 1][0] = pole_d[2 * k + 1][1] = 0.0;
  pole_d[2 * k][2] = 1.0;
  pole_d[2 * k + 1][2] = -1.0;
  for (j = 0; j < NDIR + NPOLE; j++) {
    const double *v = j < NDIR ? rnd_d[j] : pole_d[j - NDIR];
    float *f = j < NDIR ? rnd_f[j] : pole_f[j - NDIR];
    float *g = j < NDIR ? rnd_g[j] : pole_g[j - NDIR];
    double s = pow(10.0, -1.0 + 2.0 * sm_u01()); /* log-uniform in [0.1, 10] */
    for (k = 0; k < 3; k++) {
      f[k] = (float)v[k];
      g[k] = (float)(v[k] * s);
      if (j < NDIR)
        soa_rnd[k][j] = f[k];
      else
        soa_pole[k][j - NDIR] = f[k];
    }
  }
}

/* ------------------------------------------------------------------ the yardstick base_f */
/* peers-sh.md section 6: float, run-time n, tables built once: a_lm = sqrt((4l^2-1)/(l^2-m^2)),
   b_lm = sqrt(((l-1)^2-m^2)/(4(l-1)^2-1)), P_mm/sin^m with sqrt(2) folded in; (x+iy)^m by
   complex multiply.  Sloan's recurrence as a plain loop. */
static float LA[MAXN][MAXN], LB[MAXN][MAXN], LPMM[MAXN], LP1[MAXN];
static void loop_init(void) {
  double p = 0.28209479177387814; /* 1 / (2 sqrt(pi)) */
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

/* ------------------------------------------------------------------ wrappers */
typedef struct {
  float *y, *dth, *dph, (*g)[3]; /* n*n each (g: n*n float[3]) */
  float *sh;                     /* n*n coefficients of shl_sh_eval_dot_grad */
  float *bout;                   /* batch output, n*n*NDIR */
} bufs;
typedef void (*wfn)(int n, const float *d, bufs *b);
/* after each library call in a wrapper: no tail call, so callgrind's --toggle-collect on the
 * wrapper sees the callee's instructions too */
#define NOTAIL() __asm__ volatile("" ::: "memory")

NOINL void bw_loop(int n, const float *d, bufs *b) {
  float x = d[0], y = d[1], z = d[2], c = 1.0f, s = 0.0f, p0, p1, p2, t;
  float *out = b->y;
  int l, m, i;
  for (m = 0; m < n; m++) {
    p0 = LPMM[m];
    i = m * m + 2 * m; /* l = m */
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
NOINL void bw_empty(int n, const float *d, bufs *b) {
  (void)n;
  (void)d;
  (void)b;
}
NOINL void bw_eval_rt(int n, const float *d, bufs *b) {
  shl_sh_eval(n, d, b->y);
  NOTAIL();
}
NOINL void bw_accurate(int n, const float *d, bufs *b) {
  shl_sh_eval_accurate(n, d, b->y);
  NOTAIL();
}
NOINL void bw_batch(int n, const float *d, bufs *b) {
  (void)d;
  shl_sh_eval_batch(n, NDIR, soa_rnd[0], soa_rnd[1], soa_rnd[2], b->bout);
  NOTAIL();
}
NOINL void bw_batch32(int n, const float *d, bufs *b) { /* 32 directions: two vectors a call */
  int j = (int)((d - rnd_f[0]) / 3) & (NDIR - 32);
  shl_sh_eval_batch(n, 32, soa_rnd[0] + j, soa_rnd[1] + j, soa_rnd[2] + j, b->bout);
  NOTAIL();
}
NOINL void bw_batch16(int n, const float *d, bufs *b) { /* the 16 directions from d's block */
  int j = (int)((d - rnd_f[0]) / 3) & (NDIR - 16);
  shl_sh_eval_batch(n, 16, soa_rnd[0] + j, soa_rnd[1] + j, soa_rnd[2] + j, b->bout);
  NOTAIL();
}

/* one wrapper per n for the static-inline kernels (n a literal, as in user code) */
#define NLIST16(X) \
  X(1) X(2) X(3) X(4) X(5) X(6) X(7) X(8) X(9) X(10) X(11) X(12) X(13) X(14) X(15) X(16)
#define NLIST(X) NLIST16(X) X(17) X(20) X(24) X(32) X(48) X(64)
#define W_EVAL(N) \
  NOINL void bw_eval_##N(int n, const float *d, bufs *b) { \
    (void)n; \
    shl_sh_eval(N, d, b->y); \
    NOTAIL(); \
  }
#define W_GRAD(N) \
  NOINL void bw_grad_##N(int n, const float *d, bufs *b) { \
    (void)n; \
    shl_sh_eval_grad(N, d, b->y, b->g); \
    NOTAIL(); \
  }
#define W_DOTGRAD(N) \
  NOINL void bw_dotgrad_##N(int n, const float *d, bufs *b) { \
    (void)n; \
    b->y[0] = shl_sh_eval_dot_grad(N, b->sh, d, b->g[0]); \
    NOTAIL(); \
  }
#define W_GSPH(N) \
  NOINL void bw_grad_sph_##N(int n, const float *d, bufs *b) { \
    (void)n; \
    shl_sh_eval_grad_spherical(N, d, b->y, b->dth, b->dph); \
    NOTAIL(); \
    shl_sh_grad_from_spherical(N, d, b->dth, b->dph, b->g); \
    NOTAIL(); \
  }
NLIST(W_EVAL)
NLIST(W_GRAD)
NLIST(W_GSPH)
NLIST(W_DOTGRAD)
#define NUM(N) N,
#define FEVAL(N) bw_eval_##N,
#define FGRAD(N) bw_grad_##N,
#define FGSPH(N) bw_grad_sph_##N,
#define FDOTGRAD(N) bw_dotgrad_##N,
static const int NSET[] = {NLIST(NUM)};
#define NNS ((int)(sizeof(NSET) / sizeof(NSET[0])))
static const wfn F_EVAL[NNS] = {NLIST(FEVAL)};
static const wfn F_GRAD[NNS] = {NLIST(FGRAD)};
static const wfn F_GSPH[NNS] = {NLIST(FGSPH)};
static const wfn F_DOTGRAD[NNS] = {NLIST(FDOTGRAD)};

/* ------------------------------------------------------------------ variants */
enum {
  V_EVAL,
  V_EVAL_RT,
  V_ACC,
  V_BATCH,
  V_BATCH16,
  V_BATCH32,
  V_GRAD,
  V_GSPH,
  V_DOTGRAD,
  V_LOOP,
  V_EMPTY,
  NV
};
typedef struct {
  const char *name, *label;
  const wfn *per_n; /* wrapper per n, or NULL: rt */
  wfn rt;
  int is_grad;
  int dirs; /* directions per call (time is reported per direction) */
} variant;
static const variant VAR[NV] = {
    {"eval", "shl_sh_eval (fast path), n a literal in the wrapper", F_EVAL, 0, 0, 1},
    {"eval_rt", "shl_sh_eval, n a run-time argument", 0, bw_eval_rt, 0, 1},
    {"accurate", "shl_sh_eval_accurate", 0, bw_accurate, 0, 1},
    {"batch", "shl_sh_eval_batch, count 1024, time per direction", 0, bw_batch, 0, NDIR},
    {"batch16", "shl_sh_eval_batch, count 16 (output in L1), per direction", 0, bw_batch16, 0, 16},
    {"batch32", "shl_sh_eval_batch, count 32 (output in L1), per direction", 0, bw_batch32, 0, 32},
    {"grad", "shl_sh_eval_grad: values + Cartesian gradient", F_GRAD, 0, 1, 1},
    {"grad_sph", "shl_sh_eval_grad_spherical + shl_sh_grad_from_spherical", F_GSPH, 0, 1, 1},
    {"dotgrad", "shl_sh_eval_dot_grad: f = sh . Y and its gradient (errors: tests/test_basis)",
     F_DOTGRAD, 0, 0, 1},
    {"loop", "plain-loop yardstick (research base_f), run-time n", 0, bw_loop, 0, 1},
    {"empty", "empty function: harness overhead", 0, bw_empty, 0, 1},
};
static wfn var_fn(int v, int ni) {
  return VAR[v].per_n ? VAR[v].per_n[ni] : VAR[v].rt;
}
static int var_find(const char *s) {
  int v;
  for (v = 0; v < NV; v++)
    if (!strcmp(s, VAR[v].name)) return v;
  return -1;
}
static int n_index(int n) {
  int i;
  for (i = 0; i < NNS; i++)
    if (NSET[i] == n) return i;
  return -1;
}

/* ------------------------------------------------------------------ timing */
static double cpu_ns(void) {
  struct timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e9 * (double)t.tv_sec + (double)t.tv_nsec;
}
static double run_calls(wfn f, int n, long reps, bufs *b) {
  double t0 = cpu_ns();
  long r;
  for (r = 0; r < reps; r++) {
    f(n, rnd_f[r & (NDIR - 1)], b);
    __asm__ volatile("" ::"r"(b->y), "r"(b->bout) : "memory");
  }
  return cpu_ns() - t0;
}
static int cmp_d(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return x < y ? -1 : x > y;
}
static double quantile(double *v, int k, double q) {
  qsort(v, (size_t)k, sizeof(double), cmp_d);
  return v[(int)floor(q * (k - 1) + 0.5)];
}

/* ------------------------------------------------------------------ results */
static int g_nlist[NNS], g_nn;    /* selected n (indices into NSET) */
static int g_var[NV];             /* selected variants */
static double R_ns[NV][NNS];      /* median ns per call (batch: per direction) */
static double R_spread[NV][NNS];  /* (p75 - p25) / median */
static double R_err[NV][NNS][2];  /* value error: [0] random, [1] near-pole */
static double R_gerr[NV][NNS][2]; /* gradient error / max |grad| */
static double R_gerr_np[NV][NNS]; /* gradient, near-pole set without the two exact poles */
static double R_floor[NNS][2];    /* float rounding floor of the reference */
static double R_instr[NV][NNS];   /* callgrind instructions per call, < 0: none */
static double R_floor_g[NNS][2];

static void time_n(int ni, int samples, double sample_ms, bufs *b) {
  int n = NSET[ni], v, s;
  long reps[NV];
  static double t[NV][256];
  for (v = 0; v < NV; v++) {
    double el;
    if (!g_var[v]) continue;
    reps[v] = 1;
    for (;;) { /* calibrate (also warms up) */
      el = run_calls(var_fn(v, ni), n, reps[v], b);
      if (el >= 0.25e6 * sample_ms) break;
      reps[v] *= 4;
    }
    reps[v] = (long)ceil((double)reps[v] * 1.15e6 * sample_ms / el);
    if (reps[v] < 1) reps[v] = 1;
  }
  for (s = 0; s < samples; s++) /* interleaved: every variant sees the same noise */
    for (v = 0; v < NV; v++)
      if (g_var[v]) t[v][s] = run_calls(var_fn(v, ni), n, reps[v], b) / (double)reps[v];
  for (v = 0; v < NV; v++) {
    double med, q1, q3;
    if (!g_var[v]) continue;
    med = quantile(t[v], samples, 0.5);
    q1 = quantile(t[v], samples, 0.25);
    q3 = quantile(t[v], samples, 0.75);
    R_ns[v][ni] = med / VAR[v].dirs;
    R_spread[v][ni] = (q3 - q1) / med;
  }
}

/* ------------------------------------------------------------------ errors */
static void upd(double *e, double v) {
  if (v > *e || v != v) *e = v;
}
/* value variants on the unit sets (random: set 0, near-pole: set 1) */
/* batch over a whole set (SoA out[i * cnt + j]) in calls of w directions (w = cnt: one call) */
static float *batch_set(int n, int cnt, const float *x, const float *y, const float *z, int w) {
  float *o = (float *)malloc(sizeof(float) * (size_t)n * n * cnt), *t;
  int j = 0, i, k;
  if (!o || !(t = (float *)malloc(sizeof(float) * (size_t)n * n * w))) exit(2);
  for (;; j += w) {
    if (j > cnt - w) j = cnt - w;
    shl_sh_eval_batch(n, w, x + j, y + j, z + j, t);
    for (i = 0; i < n * n; i++)
      for (k = 0; k < w; k++)
        o[(size_t)i * cnt + j + k] = t[(size_t)i * w + k];
    if (j + w >= cnt) break;
  }
  free(t);
  return o;
}
static void errors_values(int nmax, bufs *b) {
  static double ref[MAXC];
  float *bat[2][NNS][2];
  int set, j, ii, v, i, q;
  for (ii = 0; ii < g_nn; ii++) /* batch outputs per n over each whole set */
    for (q = 0; q < 2; q++) {
      int ni = g_nlist[ii], n = NSET[ni];
      bat[q][ni][0] = bat[q][ni][1] = 0;
      if (!g_var[q ? V_BATCH16 : V_BATCH]) continue;
      bat[q][ni][0] = batch_set(n, NDIR, soa_rnd[0], soa_rnd[1], soa_rnd[2], q ? 16 : NDIR);
      bat[q][ni][1] = batch_set(n, NPOLE, soa_pole[0], soa_pole[1], soa_pole[2], q ? 16 : NPOLE);
    }
  for (set = 0; set < 2; set++) {
    int cnt = set ? NPOLE : NDIR;
    for (j = 0; j < cnt; j++) {
      const float *d = set ? pole_f[j] : rnd_f[j];
      shref_eval_d(nmax, d, ref);
      for (ii = 0; ii < g_nn; ii++) {
        int ni = g_nlist[ii], n = NSET[ni], nc = n * n;
        for (i = 0; i < nc; i++)
          upd(&R_floor[ni][set], fabs((double)(float)ref[i] - ref[i]));
        for (v = 0; v < NV; v++) {
          if (!g_var[v] || VAR[v].is_grad || v == V_EMPTY || v == V_BATCH32 || v == V_DOTGRAD)
            continue;
          if (v == V_BATCH || v == V_BATCH16) {
            const float *o = bat[v == V_BATCH16][ni][set];
            for (i = 0; i < nc; i++)
              upd(&R_err[v][ni][set], fabs((double)o[(size_t)i * cnt + j] - ref[i]));
            continue;
          }
          var_fn(v, ni)(n, d, b);
          for (i = 0; i < nc; i++)
            upd(&R_err[v][ni][set], fabs((double)b->y[i] - ref[i]));
        }
      }
    }
  }
  for (ii = 0; ii < g_nn; ii++)
    for (q = 0; q < 4; q++)
      free(bat[q >> 1][g_nlist[ii]][q & 1]);
}
/* gradient variants on the scaled sets (|d| in [0.1, 10]) */
static void errors_grad(int nmax, int nrand, bufs *b) {
  static double ry[MAXC], rg[MAXC][3];
  int set, j, ii, v, i, k;
  for (set = 0; set < 2; set++) {
    int cnt = set ? NPOLE : nrand;
    for (j = 0; j < cnt; j++) {
      const float *d = set ? pole_g[j] : rnd_g[j];
      int exact = set && d[0] == 0.0f && d[1] == 0.0f;
      shref_grad_d(nmax, d, ry, rg);
      for (ii = 0; ii < g_nn; ii++) {
        int ni = g_nlist[ii], n = NSET[ni], nc = n * n;
        double gmax = 0.0;
        for (i = 0; i < nc; i++)
          for (k = 0; k < 3; k++)
            gmax = fmax(gmax, fabs(rg[i][k]));
        if (!(gmax > 1e-12)) gmax = 1.0; /* n = 1: the gradient is 0 (reference: ~1e-27) */
        for (i = 0; i < nc; i++)
          for (k = 0; k < 3; k++)
            upd(&R_floor_g[ni][set], fabs((double)(float)rg[i][k] - rg[i][k]) / gmax);
        for (v = 0; v < NV; v++) {
          double e = 0.0;
          if (!g_var[v] || !VAR[v].is_grad) continue;
          var_fn(v, ni)(n, d, b);
          for (i = 0; i < nc; i++) {
            upd(&R_err[v][ni][set], fabs((double)b->y[i] - ry[i]));
            for (k = 0; k < 3; k++)
              upd(&e, fabs((double)b->g[i][k] - rg[i][k]) / gmax);
          }
          upd(&R_gerr[v][ni][set], e);
          if (set && !exact) upd(&R_gerr_np[v][ni], e);
        }
      }
    }
  }
}

/* ------------------------------------------------------------------ output */
static void fmt_ns(char *s, double v) {
  if (v < 0)
    strcpy(s, "");
  else if (v < 10)
    sprintf(s, "%.2f", v);
  else if (v < 100)
    sprintf(s, "%.1f", v);
  else
    sprintf(s, "%.0f", v);
}
static void fmt_e(char *s, double v) {
  if (v < 0)
    strcpy(s, "");
  else
    sprintf(s, "%.1e", v);
}
static void pr(FILE **fo, const char *f, const char *s) {
  fprintf(fo[0], f, s);
  if (fo[1]) fprintf(fo[1], f, s);
}
static void table_head(FILE **fo, const char *title, const char *first) {
  int ii;
  char s[32];
  pr(fo, "\n%s\n\n", title);
  pr(fo, "| %s |", first);
  for (ii = 0; ii < g_nn; ii++) {
    sprintf(s, "n=%d", NSET[g_nlist[ii]]);
    pr(fo, " %s |", s);
  }
  pr(fo, "%s\n|---|", "");
  for (ii = 0; ii < g_nn; ii++)
    pr(fo, "%s---|", "");
  pr(fo, "%s\n", "");
}
/* what: 0 ns, 1 ratio to loop, 2 ratio to eval, 3 err random, 4 err pole, 5 grad random,
   6 grad pole, 7 instr, 8 grad pole without exact poles */
static double cell(int what, int v, int ni) {
  switch (what) {
  case 0:
    return R_ns[v][ni];
  case 1:
    return g_var[V_LOOP] ? R_ns[v][ni] / R_ns[V_LOOP][ni] : -1;
  case 2:
    return g_var[V_EVAL] ? R_ns[v][ni] / R_ns[V_EVAL][ni] : -1;
  case 3:
    return R_err[v][ni][0];
  case 4:
    return R_err[v][ni][1];
  case 5:
    return R_gerr[v][ni][0];
  case 6:
    return R_gerr[v][ni][1];
  case 7:
    return R_instr[v][ni];
  default:
    return R_gerr_np[v][ni];
  }
}
static void table(FILE **fo, const char *title, int what, int grad_only, int errs) {
  int v, ii;
  char s[32];
  table_head(fo, title, "variant");
  for (v = 0; v < NV; v++) {
    if (!g_var[v] || (grad_only && !VAR[v].is_grad) || (errs && (v == V_EMPTY || v == V_DOTGRAD)))
      continue;
    pr(fo, "| %s |", VAR[v].name);
    for (ii = 0; ii < g_nn; ii++) {
      double c = cell(what, v, g_nlist[ii]);
      if (what == 0)
        fmt_ns(s, c);
      else if (what <= 2)
        sprintf(s, "%.2f", c);
      else if (what == 7 && c < 0)
        s[0] = 0;
      else if (what == 7)
        sprintf(s, "%.0f", c);
      else
        fmt_e(s, c);
      pr(fo, " %s |", s);
    }
    pr(fo, "%s\n", "");
  }
  if (errs) {
    pr(fo, "| %s |", "float rounding floor");
    for (ii = 0; ii < g_nn; ii++) {
      int ni = g_nlist[ii];
      fmt_e(s, what == 3   ? R_floor[ni][0]
               : what == 4 ? R_floor[ni][1]
               : what == 5 ? R_floor_g[ni][0]
                           : R_floor_g[ni][1]);
      pr(fo, " %s |", s);
    }
    pr(fo, "%s\n", "");
  }
}

/* Log-log SVG: x = ns per call, y = max error (worst of the two sets; for the gradient variants
   the gradient error / max|grad| without the two exact poles, where grad_sph returns 0 by
   contract; n = 1 has an exactly zero gradient and is left out), one polyline per variant. */
static int svg_pt(int v, int ni, double *lx, double *ly) {
  double e = VAR[v].is_grad ? fmax(R_gerr[v][ni][0], R_gerr_np[v][ni])
                            : fmax(R_err[v][ni][0], R_err[v][ni][1]);
  if (!(e > 1e-12) || !(R_ns[v][ni] > 0) || v == V_EMPTY || v == V_BATCH32 || v == V_DOTGRAD ||
      !g_var[v])
    return 0;
  *lx = log10(R_ns[v][ni]);
  *ly = log10(e);
  return 1;
}
static void write_svg(const char *path) {
  static const char *col[NV] = {"#1f77b4", "#17becf", "#2ca02c", "#9467bd", "#e377c2",
                                "#d62728", "#ff7f0e", "#000000", "#bcbd22", "#7f7f7f"};
  const double W = 860, H = 560, L = 70, R = 170, T = 40, B = 50;
  double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9, lx, ly, e;
  int v, ii, row = 0;
  FILE *f = fopen(path, "w");
  if (!f) return;
  for (v = 0; v < NV; v++)
    for (ii = 0; ii < g_nn; ii++)
      if (svg_pt(v, g_nlist[ii], &lx, &ly))
        x0 = fmin(x0, lx), x1 = fmax(x1, lx), y0 = fmin(y0, ly), y1 = fmax(y1, ly);
  x0 = floor(x0), x1 = fmax(ceil(x1), x0 + 1), y0 = floor(y0), y1 = fmax(ceil(y1), y0 + 1);
#define SX(u) (L + ((u)-x0) / (x1 - x0) * (W - L - R))
#define SY(u) (H - B - ((u)-y0) / (y1 - y0) * (H - T - B))
  fprintf(f,
          "<svg xmlns='http://www.w3.org/2000/svg' width='%.0f' height='%.0f' "
          "font-family='sans-serif' font-size='11'>\n<rect width='100%%' height='100%%' "
          "fill='white'/>\n<text x='%.0f' y='24' font-size='14'>shlight basis: time vs max "
          "error (log-log; point labels = n)</text>\n",
          W, H, L);
  for (e = x0; e <= x1 + 1e-9; e++)
    fprintf(f,
            "<line x1='%.1f' y1='%.0f' x2='%.1f' y2='%.0f' stroke='#ddd'/><text x='%.1f' "
            "y='%.0f' text-anchor='middle'>1e%g</text>\n",
            SX(e), T, SX(e), H - B, SX(e), H - B + 15, e);
  for (e = y0; e <= y1 + 1e-9; e++)
    fprintf(f,
            "<line x1='%.0f' y1='%.1f' x2='%.0f' y2='%.1f' stroke='#ddd'/><text x='%.0f' "
            "y='%.1f' text-anchor='end'>1e%g</text>\n",
            L, SY(e), W - R, SY(e), L - 4, SY(e) + 4, e);
  fprintf(f,
          "<text x='%.0f' y='%.0f' text-anchor='middle'>ns per call (batch: per "
          "direction)</text>\n<text x='14' y='%.0f' transform='rotate(-90 14 %.0f)' "
          "text-anchor='middle'>max abs error (gradient variants: gradient error / "
          "max|grad|, exact poles excluded)</text>\n",
          (L + W - R) / 2, H - 12, (T + H - B) / 2, (T + H - B) / 2);
  for (v = 0; v < NV; v++) {
    int any = 0;
    for (ii = 0; ii < g_nn; ii++)
      if (svg_pt(v, g_nlist[ii], &lx, &ly))
        fprintf(f, "%s%.1f,%.1f",
                any++ ? " "
                      : "<polyline fill='none' stroke-width='1.5' "
                        "points='",
                SX(lx), SY(ly));
    if (!any) continue;
    fprintf(f, "' stroke='%s'/>\n", col[v]);
    for (ii = 0; ii < g_nn; ii++) {
      int n = NSET[g_nlist[ii]];
      if (!svg_pt(v, g_nlist[ii], &lx, &ly)) continue;
      fprintf(f, "<circle cx='%.1f' cy='%.1f' r='2' fill='%s'/>", SX(lx), SY(ly), col[v]);
      if (n == 1 || n == 4 || n == 10 || n == 16 || n >= 32)
        fprintf(f, "<text x='%.1f' y='%.1f' font-size='9' fill='%s'>%d</text>", SX(lx) + 3,
                SY(ly) - 3, col[v], n);
      fprintf(f, "\n");
    }
    fprintf(f,
            "<line x1='%.0f' y1='%d' x2='%.0f' y2='%d' stroke='%s' stroke-width='2'/><text "
            "x='%.0f' y='%d'>%s</text>\n",
            W - R + 12, 50 + 16 * row, W - R + 32, 50 + 16 * row, col[v], W - R + 37, 54 + 16 * row,
            VAR[v].name);
    row++;
  }
#undef SX
#undef SY
  fprintf(f, "</svg>\n");
  fclose(f);
}

static void load_callgrind(const char *path) {
  char line[256], name[64];
  int n, v, ni;
  double ins;
  FILE *f = fopen(path, "r");
  if (!f) {
    fprintf(stderr, "bench_basis: cannot read %s (%s); instr column left blank\n", path,
            strerror(errno));
    return;
  }
  while (fgets(line, sizeof line, f))
    if (sscanf(line, "%63[^,],%d,%lf", name, &n, &ins) == 3 && (v = var_find(name)) >= 0 &&
        (ni = n_index(n)) >= 0)
      R_instr[v][ni] = ins;
  fclose(f);
}

static void cpu_model(char *s, size_t cap) {
  char line[256];
  FILE *f = fopen("/proc/cpuinfo", "r");
  strcpy(s, "unknown CPU");
  if (!f) return;
  while (fgets(line, sizeof line, f))
    if (!strncmp(line, "model name", 10) && strchr(line, ':')) {
      strncpy(s, strchr(line, ':') + 2, cap - 1);
      s[cap - 1] = 0;
      s[strcspn(s, "\n")] = 0;
      break;
    }
  fclose(f);
}

static void usage(void) {
  fprintf(
      stderr,
      "usage: bench_basis [--quick] [--n LIST] [--variants LIST] [--samples S] [--sample-ms T]\n"
      "                   [--no-error] [--callgrind FILE] [--out DIR]\n"
      "       bench_basis --count-only VARIANT N K\n"
      "  LIST: comma separated; n from 1..17,20,24,32,48,64; variants: "
      "eval,eval_rt,accurate,batch,\n"
      "  batch16,batch32,grad,grad_sph,loop,empty (loop and eval are always timed: they are the "
      "ratios' "
      "bases)\n");
  exit(2);
}

int main(int argc, char **argv) {
  int samples = 15, quick = 0, noerr = 0, a, v, ii, nmax = 1, nrand_g = NDIR;
  double sample_ms = 4.0;
  const char *outdir = "bench/out", *cgfile = 0, *nl = 0, *vl = 0;
  static bufs b;
  FILE *fo[2];
  char path[512], s[128];

  for (a = 0; a < NV; a++)
    for (ii = 0; ii < NNS; ii++)
      R_instr[a][ii] = -1;
  b.y = (float *)malloc(sizeof(float) * MAXC);
  b.dth = (float *)malloc(sizeof(float) * MAXC);
  b.dph = (float *)malloc(sizeof(float) * MAXC);
  b.g = (float(*)[3])malloc(sizeof(float) * 3 * MAXC);
  b.sh = (float *)malloc(sizeof(float) * MAXC);
  if (!b.y || !b.dth || !b.dph || !b.g || !b.sh) return 2;
  for (a = 0; a < MAXC; a++)
    b.sh[a] = (float)(0.8 * cos(0.7 * a) / (1.0 + 0.1 * a));
  make_dirs();
  loop_init();

  if (argc == 5 && !strcmp(argv[1], "--count-only")) { /* run by callgrind.sh */
    long k, K = atol(argv[4]);
    int n = atoi(argv[3]), ni = n_index(n);
    v = var_find(argv[2]);
    if (v < 0 || ni < 0 || K < 1) usage();
    if ((v == V_BATCH || v == V_BATCH16 || v == V_BATCH32) &&
        !(b.bout = (float *)malloc(sizeof(float) * (size_t)n * n * NDIR)))
      return 2;
    for (k = 0; k < K; k++) {
      var_fn(v, ni)(n, rnd_f[k & (NDIR - 1)], &b);
      __asm__ volatile("" ::"r"(b.y), "r"(b.bout) : "memory");
    }
    return 0;
  }
  for (a = 1; a < argc; a++) {
    if (!strcmp(argv[a], "--quick"))
      quick = 1;
    else if (!strcmp(argv[a], "--no-error"))
      noerr = 1;
    else if (!strcmp(argv[a], "--n") && a + 1 < argc)
      nl = argv[++a];
    else if (!strcmp(argv[a], "--variants") && a + 1 < argc)
      vl = argv[++a];
    else if (!strcmp(argv[a], "--samples") && a + 1 < argc)
      samples = atoi(argv[++a]);
    else if (!strcmp(argv[a], "--sample-ms") && a + 1 < argc)
      sample_ms = atof(argv[++a]);
    else if (!strcmp(argv[a], "--callgrind") && a + 1 < argc)
      cgfile = argv[++a];
    else if (!strcmp(argv[a], "--out") && a + 1 < argc)
      outdir = argv[++a];
    else
      usage();
  }
  if (quick) { /* still >= 11 samples of >= 2 ms; gradient error on 256 random directions */
    samples = samples < 11 ? samples : 11;
    sample_ms = sample_ms < 2.0 ? sample_ms : 2.0;
    nrand_g = 256;
  }
  if (samples < 1 || samples > 256 || !(sample_ms > 0)) usage();
  if (nl) {
    char buf[256], *t;
    strncpy(buf, nl, sizeof buf - 1);
    buf[sizeof buf - 1] = 0;
    for (t = strtok(buf, ","); t; t = strtok(0, ",")) {
      int ni = n_index(atoi(t));
      if (ni < 0) usage();
      for (ii = 0; ii < g_nn && g_nlist[ii] != ni; ii++)
        continue;
      if (ii == g_nn) g_nlist[g_nn++] = ni;
    }
    for (a = 0; a < g_nn; a++) /* ascending */
      for (ii = a + 1; ii < g_nn; ii++)
        if (g_nlist[ii] < g_nlist[a]) v = g_nlist[a], g_nlist[a] = g_nlist[ii], g_nlist[ii] = v;
  } else /* the default set: 1..16, 32, 64 (17, 20, 24, 48 on request) */
    for (g_nn = 0, ii = 0; ii < NNS; ii++)
      if (NSET[ii] <= 16 || NSET[ii] == 32 || NSET[ii] == 64) g_nlist[g_nn++] = ii;
  if (vl) {
    char buf[256], *t;
    strncpy(buf, vl, sizeof buf - 1);
    buf[sizeof buf - 1] = 0;
    for (t = strtok(buf, ","); t; t = strtok(0, ","))
      if ((v = var_find(t)) < 0)
        usage();
      else
        g_var[v] = 1;
    g_var[V_LOOP] = g_var[V_EVAL] = 1;
  } else
    for (v = 0; v < NV; v++)
      g_var[v] = 1;
  for (ii = 0; ii < g_nn; ii++)
    nmax = NSET[g_nlist[ii]] > nmax ? NSET[g_nlist[ii]] : nmax;
  if ((g_var[V_BATCH] || g_var[V_BATCH16] || g_var[V_BATCH32]) &&
      !(b.bout = (float *)malloc(sizeof(float) * (size_t)nmax * nmax * NDIR)))
    return 2;
  if (cgfile) load_callgrind(cgfile);

  for (ii = 0; ii < g_nn; ii++) {
    fprintf(stderr, "\rtiming n = %d   ", NSET[g_nlist[ii]]);
    time_n(g_nlist[ii], samples, sample_ms, &b);
  }
  if (!noerr) {
    fprintf(stderr, "\rerrors: values (binary128 reference, %d directions)...", NDIR + NPOLE);
    errors_values(nmax, &b);
    if (g_var[V_GRAD] || g_var[V_GSPH]) {
      fprintf(stderr, "\rerrors: gradients (binary128 reference, %d directions)...",
              nrand_g + NPOLE);
      errors_grad(nmax, nrand_g, &b);
    }
  }
  fprintf(stderr, "\r%60s\r", "");

  mkdir(outdir, 0777);
  sprintf(path, "%s/basis.md", outdir);
  fo[0] = stdout;
  fo[1] = fopen(path, "w");
  cpu_model(s, sizeof s);
  pr(fo, "## shlight basis benchmark (bench/bench_basis.c)\n\n%s", "");
  pr(fo, "Build: `%s`", BENCH_FLAGS);
  pr(fo, " (compiler %s)", __VERSION__);
  pr(fo, "; shlight.h at %s.  \n", BENCH_REV);
  pr(fo, "CPU: %s.  \n", s);
  sprintf(s, "%d samples of >= %.1f ms each, median, variants interleaved", samples, sample_ms);
  pr(fo, "Time: per-thread CPU time, %s; ns per call include the harness (row `empty`).  \n", s);
  sprintf(s, "%d random + %d near-pole", NDIR, NPOLE);
  pr(fo, "Error: max abs error vs binary128 (tests/ref/shref.h) over %s directions", s);
  sprintf(s, "%d random + %d near-pole", nrand_g, NPOLE);
  pr(fo, "; gradients over %s directions scaled by factors in [0.1, 10], error / max|grad|.  \n",
     s);
  {
    double worst = -1, sum = 0;
    int wv = 0, wn = 0, cnt = 0;
    for (v = 0; v < NV; v++)
      for (ii = 0; ii < g_nn; ii++)
        if (g_var[v]) {
          double q = R_spread[v][g_nlist[ii]];
          sum += q, cnt++;
          if (q > worst) worst = q, wv = v, wn = NSET[g_nlist[ii]];
        }
    sprintf(s, "%.0f %% on average, at most %.0f %% (%s, n = %d)", 100 * sum / cnt, 100 * worst,
            VAR[wv].name, wn);
    pr(fo, "Noise: interquartile spread of the samples / median: %s.\n", s);
  }
  table(fo, "### ns per call (batch: per direction)", 0, 0, 0);
  table(fo, "### ratio to the plain loop `loop` (same run)", 1, 0, 0);
  table(fo, "### value + gradient: ratio to `eval` (value alone, same run)", 2, 1, 0);
  if (cgfile)
    table(fo,
          "### instructions per call (callgrind, -O3 -march=x86-64-v3; "
          "batch: per direction, AVX2 path)",
          7, 0, 0);
  if (!noerr) {
    table(fo,
          "### max abs error, 1024 random unit directions (grad variants: values at the "
          "scaled inputs)",
          3, 0, 1);
    table(fo, "### max abs error, 258 near-pole directions (theta in [1e-7, 1e-2] + exact poles)",
          4, 0, 1);
    table(fo, "### gradient: max abs error / max|grad|, random directions, |d| in [0.1, 10]", 5, 1,
          1);
    table(fo, "### gradient: max abs error / max|grad|, near-pole directions incl. exact poles", 6,
          1, 1);
    table(fo, "### gradient: near-pole directions without the two exact poles", 8, 1, 0);
  }
  if (fo[1]) fclose(fo[1]);

  sprintf(path, "%s/basis.csv", outdir);
  if ((fo[1] = fopen(path, "w")) != 0) {
    fprintf(fo[1], "variant,n,ns,ratio_to_loop,instr,max_err_random,max_err_pole,"
                   "grad_err_random,grad_err_pole\n");
    for (v = 0; v < NV; v++)
      for (ii = 0; ii < g_nn && g_var[v]; ii++) {
        int ni = g_nlist[ii];
        fprintf(fo[1], "%s,%d,%.4g,%.4g,", VAR[v].name, NSET[ni], R_ns[v][ni],
                R_ns[v][ni] / R_ns[V_LOOP][ni]);
        if (R_instr[v][ni] >= 0) fprintf(fo[1], "%.0f", R_instr[v][ni]);
        if (noerr || v == V_EMPTY || v == V_DOTGRAD)
          fprintf(fo[1], ",,");
        else
          fprintf(fo[1], ",%.3e,%.3e", R_err[v][ni][0], R_err[v][ni][1]);
        if (noerr || !VAR[v].is_grad)
          fprintf(fo[1], ",,\n");
        else
          fprintf(fo[1], ",%.3e,%.3e\n", R_gerr[v][ni][0], R_gerr[v][ni][1]);
      }
    fclose(fo[1]);
  }
  if (!noerr) {
    sprintf(path, "%s/basis_time_vs_error.svg", outdir);
    write_svg(path);
  }
  return 0;
}
