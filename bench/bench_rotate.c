/* bench_rotate.c - shl_sh_rotate: ns per rotation at n = 2..16, 32, 64 (its C-only path for
 * n <= 8, the portable kernel above), next to
 *   - the portable kernel alone at every n (tests/test_rotate_portable.c: SHLIGHT_ROTATE_FAST 0,
 *     the body the GLSL twin shares), the reference of the error columns;
 *   - re-projection: the rotated function sampled at the 2 n^2 points of a Gauss-Legendre (n) x
 *     uniform-phi (2 n) rule, exact for the product of two n-band functions, and projected back
 *     (two shl_sh_eval and 2 n^2 flops per point: O(n^4));
 *   - the yardstick: applying stored band matrices (sum (2l + 1)^2 multiply-adds, the floor of
 *     any method that rebuilds nothing), measured in the same run (DESIGN.md section 6);
 *   - with -DBENCH_DXM (a C++ build against DirectXMath's SHMath, see docs/rotation.md):
 *     DirectXMath's XMSHRotate, n = 2..6.
 * Error: the worst per-band |out - ref| / |band| over the configurations, ref = the portable
 * kernel (its own error against a long-double reference is 4e-8, tests/test_rotate). Timings:
 * per-thread CPU time, median of 15 samples of >= 2 ms, the clock read after every
 * 16 * reps rotations (reps = 8192 / n^2 + 1: a read costs about 1 us here); noisy on a shared
 * machine: read the ratios. Output: a markdown table on stdout and in bench/out/rotate.md.
 * Instruction counts (load-robust): `bench_rotate --count VARIANT N K` runs K rotations of one
 * variant (shl, portable, dxm) and nothing else timed; under
 *   valgrind --tool=callgrind --toggle-collect='rw_*' build/bench/bench_rotate --count shl 4 1000
 * the total / K is the count per rotation (docs/rotation.md). */
#ifndef __cplusplus
#define _POSIX_C_SOURCE 200809L
#endif
#define SHLIGHT_IMPLEMENTATION
#include "../shlight.h"
#include "bench_util.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#ifdef BENCH_DXM
#include "DirectXSH.h"
#endif

#define NCFG 16
#define NMAX 64
#define NC (NMAX * NMAX)

static float g_R[NCFG][9];
static float g_in[NCFG][NC];
static float g_out[NCFG][NC];
static float g_ref[NCFG][NC];
static float g_mat[NCFG][NC * 2]; /* stored band matrices for the yardstick (n <= 16 only) */
static int g_n;
static volatile float g_sink;

/* re-projection workspace */
static float g_qx[2 * NC], g_qy[2 * NC], g_qz[2 * NC], g_qw[2 * NC];
static int g_nq;

static void quat_R(double w, double x, double y, double z, float R[9]) {
  double s = 1.0 / sqrt(w * w + x * x + y * y + z * z);
  w *= s, x *= s, y *= s, z *= s;
  R[0] = (float)(1 - 2 * (y * y + z * z));
  R[1] = (float)(2 * (x * y - z * w));
  R[2] = (float)(2 * (x * z + y * w));
  R[3] = (float)(2 * (x * y + z * w));
  R[4] = (float)(1 - 2 * (x * x + z * z));
  R[5] = (float)(2 * (y * z - x * w));
  R[6] = (float)(2 * (x * z - y * w));
  R[7] = (float)(2 * (y * z + x * w));
  R[8] = (float)(1 - 2 * (x * x + y * y));
}

/* Gauss-Legendre on [-1, 1] by Newton, double */
static void gauss(int k, double *xs, double *ws) {
  int i, j, it;
  for (i = 0; i < k; ++i) {
    double x = cos(3.141592653589793 * (i + 0.75) / (k + 0.5)), p0 = 1, p1 = 0, p2, dp = 1;
    for (it = 0; it < 100; ++it) {
      p1 = 1.0, p0 = x;
      for (j = 2; j <= k; ++j)
        p2 = p1, p1 = p0, p0 = ((2.0 * j - 1.0) * x * p1 - (j - 1.0) * p2) / j;
      if (k == 1) p1 = 1.0;
      dp = k * (x * p0 - p1) / (x * x - 1.0);
      x -= p0 / dp;
      if (fabs(p0 / dp) < 1e-16) break;
    }
    xs[i] = x;
    ws[i] = 2.0 / ((1.0 - x * x) * dp * dp);
  }
}

static void setup_quad(int n) {
  double xs[NMAX], ws[NMAX];
  int it, ip, np = 2 * n;
  gauss(n, xs, ws);
  g_nq = 0;
  for (it = 0; it < n; ++it)
    for (ip = 0; ip < np; ++ip) {
      double r = sqrt(1.0 - xs[it] * xs[it]), ph = 6.283185307179586 * ip / np;
      g_qx[g_nq] = (float)(r * cos(ph));
      g_qy[g_nq] = (float)(r * sin(ph));
      g_qz[g_nq] = (float)xs[it];
      g_qw[g_nq] = (float)(ws[it] * 6.283185307179586 / np);
      g_nq++;
    }
}

static void reproject(int n, const float R[9], const float *in, float *out) {
  static float y[NC], yr[NC];
  int k, i, nc = n * n;
  for (i = 0; i < nc; ++i)
    out[i] = 0.0f;
  for (k = 0; k < g_nq; ++k) {
    float d[3] = {g_qx[k], g_qy[k], g_qz[k]}, e[3], f = 0.0f;
    /* R^T d */
    e[0] = R[0] * d[0] + R[3] * d[1] + R[6] * d[2];
    e[1] = R[1] * d[0] + R[4] * d[1] + R[7] * d[2];
    e[2] = R[2] * d[0] + R[5] * d[1] + R[8] * d[2];
    shl_sh_eval(n, e, yr);
    shl_sh_eval(n, d, y);
    for (i = 0; i < nc; ++i)
      f += in[i] * yr[i];
    f *= g_qw[k];
    for (i = 0; i < nc; ++i)
      out[i] += f * y[i];
  }
}

/* stored band matrices: column j of band l = the rotation of the unit vector e_j */
static void build_mats(int n, int c) {
  static float e[NC], o[NC];
  int l, i, j, p = 0;
  for (l = 0; l < n; ++l)
    for (j = 0; j < 2 * l + 1; ++j) {
      memset(e, 0, sizeof(float) * (size_t)(n * n));
      e[l * l + j] = 1.0f;
      shl_sh_rotate(n, g_R[c], e, o);
      for (i = 0; i < 2 * l + 1; ++i)
        g_mat[c][p++] = o[l * l + i];
    }
}
static void apply_mats(int n, const float *mat, const float *in, float *out) {
  int l, i, j, p = 0;
  for (l = 0; l < n; ++l) {
    int b = l * l, w = 2 * l + 1;
    for (i = 0; i < w; ++i)
      out[b + i] = 0.0f;
    for (j = 0; j < w; ++j) {
      float a = in[b + j];
      for (i = 0; i < w; ++i)
        out[b + i] += mat[p++] * a;
    }
  }
}

void rotate_portable(int n, const float R[9], const float *sh, float *out_sh);

static __attribute__((noinline)) void run_shl(int j) {
  shl_sh_rotate(g_n, g_R[j], g_in[j], g_out[j]);
}
static __attribute__((noinline)) void run_portable(int j) {
  rotate_portable(g_n, g_R[j], g_in[j], g_out[j]);
}
static __attribute__((noinline)) void run_reproj(int j) {
  reproject(g_n, g_R[j], g_in[j], g_out[j]);
}
static __attribute__((noinline)) void run_mats(int j) {
  apply_mats(g_n, g_mat[j], g_in[j], g_out[j]);
}
#ifdef BENCH_DXM
static DirectX::XMMATRIX g_M[NCFG];
static __attribute__((noinline)) void run_dxm(int j) {
  DirectX::XMSHRotate(g_out[j], (size_t)g_n, g_M[j], g_in[j]);
}
#endif

/* reps: rotations between two clock reads (a CPU-time read costs about 1 us here, which at
 * 16 rotations per read was most of a small-n rotation's time) */
static double time_fn(void (*fn)(int), int reps) {
  double s[15], t0, t;
  int k, j, r, it;
  for (k = 0; k < 15; ++k) {
    it = 0;
    t0 = now();
    do {
      for (r = 0; r < reps; ++r)
        for (j = 0; j < NCFG; ++j)
          fn(j);
      it += NCFG * reps;
    } while ((t = now()) - t0 < 2e-3);
    s[k] = (t - t0) / it * 1e9;
  }
  g_sink = g_out[0][0];
  return pct(s, 15, 0.5);
}

static double err_vs_ref(int n) {
  double worst = 0.0;
  int c, l, m;
  for (c = 0; c < NCFG; ++c)
    for (l = 0; l < n; ++l) {
      double e = 0.0, b = 0.0;
      for (m = -l; m <= l; ++m) {
        int i = l * (l + 1) + m;
        double d = (double)g_out[c][i] - (double)g_ref[c][i];
        e += d * d;
        b += (double)g_in[c][i] * (double)g_in[c][i];
      }
      if (b > 0 && sqrt(e / b) > worst) worst = sqrt(e / b);
    }
  return worst;
}

/* --count: K rotations of one variant inside rw_* (callgrind's --toggle-collect) */
static __attribute__((noinline)) void rw_shl(int n, int k) {
  int j;
  for (j = 0; j < k; ++j)
    shl_sh_rotate(n, g_R[j % NCFG], g_in[j % NCFG], g_out[j % NCFG]);
}
static __attribute__((noinline)) void rw_portable(int n, int k) {
  int j;
  for (j = 0; j < k; ++j)
    rotate_portable(n, g_R[j % NCFG], g_in[j % NCFG], g_out[j % NCFG]);
}
#ifdef BENCH_DXM
static __attribute__((noinline)) void rw_dxm(int n, int k) {
  int j;
  for (j = 0; j < k; ++j)
    DirectX::XMSHRotate(g_out[j % NCFG], (size_t)n, g_M[j % NCFG], g_in[j % NCFG]);
}
#endif

static const char *fmtd(char *buf, double v, const char *f) {
  snprintf(buf, 32, f, v);
  return buf;
}

int main(int argc, char **argv) {
  static const int ns[] = {2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 32, 64};
  FILE *md;
  char row[640], f1[32], f2[32], f3[32], f4[32], f5[32];
  unsigned k;
  int c, i;
  for (c = 0; c < NCFG; ++c) {
    quat_R(2 * rnd() - 1, 2 * rnd() - 1, 2 * rnd() - 1, 2 * rnd() - 1, g_R[c]);
    for (i = 0; i < NC; ++i)
      g_in[c][i] = (float)(2 * rnd() - 1);
#ifdef BENCH_DXM
    /* DirectXMath multiplies row vectors (v M): its matrix is our R transposed */
    g_M[c] = DirectX::XMMatrixSet(g_R[c][0], g_R[c][3], g_R[c][6], 0, g_R[c][1], g_R[c][4],
                                  g_R[c][7], 0, g_R[c][2], g_R[c][5], g_R[c][8], 0, 0, 0, 0, 1);
#endif
  }
  if (argc == 5 && strcmp(argv[1], "--count") == 0) {
    int n = atoi(argv[3]), kk = atoi(argv[4]);
    if (strcmp(argv[2], "shl") == 0) rw_shl(n, kk);
    if (strcmp(argv[2], "portable") == 0) rw_portable(n, kk);
#ifdef BENCH_DXM
    if (strcmp(argv[2], "dxm") == 0) rw_dxm(n, kk);
#endif
    g_sink = g_out[0][0];
    return 0;
  }
  md = fopen("bench/out/rotate.md", "w");
  snprintf(row, sizeof row,
           "| n | shl_sh_rotate ns | portable kernel ns | re-projection ns | stored matrices ns "
           "(yardstick) | rotate / yardstick | shl_sh_rotate error | re-projection error | "
           "XMSHRotate ns | XMSHRotate error | XMSHRotate / rotate |\n"
           "|---|---|---|---|---|---|---|---|---|---|---|\n");
  fputs(row, stdout);
  if (md) fputs(row, md);
  for (k = 0; k < sizeof ns / sizeof ns[0]; ++k) {
    int n = ns[k];
    double t_shl, t_po, t_rp, t_m = 0.0, e_sh, e_rp, t_dx = -1.0, e_dx = -1.0;
    int reps = 8192 / (n * n) + 1;
    g_n = n;
    setup_quad(n);
    for (c = 0; c < NCFG; ++c)
      rotate_portable(n, g_R[c], g_in[c], g_ref[c]);
    t_po = time_fn(run_portable, reps);
    t_shl = time_fn(run_shl, reps);
    e_sh = err_vs_ref(n);
    t_rp = time_fn(run_reproj, 1);
    e_rp = err_vs_ref(n);
    if (n <= 16) {
      for (c = 0; c < NCFG; ++c)
        build_mats(n, c);
      t_m = time_fn(run_mats, reps);
    }
#ifdef BENCH_DXM
    if (n <= 6) {
      t_dx = time_fn(run_dxm, reps);
      e_dx = err_vs_ref(n);
    }
#endif
    snprintf(row, sizeof row,
             "| %d | %.1f | %.1f | %.1f | %s | %s | %.2g | %.2g | %s | %s | %s |\n", n, t_shl, t_po,
             t_rp, t_m > 0 ? fmtd(f1, t_m, "%.1f") : "-",
             t_m > 0 ? fmtd(f2, t_shl / t_m, "%.2f") : "-", e_sh, e_rp,
             t_dx > 0 ? fmtd(f3, t_dx, "%.1f") : "-", t_dx > 0 ? fmtd(f4, e_dx, "%.2g") : "-",
             t_dx > 0 ? fmtd(f5, t_dx / t_shl, "%.2f") : "-");
    fputs(row, stdout);
    if (md) fputs(row, md);
    fflush(stdout);
  }
  if (md) fclose(md);
  return 0;
}
