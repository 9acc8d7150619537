/* bench_microfacet.c - Blinn-Phong and Beckmann polygon (quad) lights in half-vector space
 * (shl_polygon_blinn_phong, shl_polygon_beckmann_subedges): ns per light and error by sub-edge
 * count k and by the balancing heuristic (k = 2 with it, -2 without: the paper's single split), for
 * Blinn-Phong exponents 1..1e4 and Beckmann alpha 1..0.02. Error in units of the directional
 * albedo (the whole hemisphere as the light) against long double cubature of the light-space
 * integrand (tests/ref/arearef.h): median, p95, max; then by configuration (straddling the
 * horizon, grazing view, large, sliver). Baseline in the same run: shl_polygon_phong with the
 * QUADRATURE method (one Stokes-form moment). ns: per-thread CPU time, median of 15 samples of
 * >= 2 ms over the configurations. Writes bench/out/microfacet.md.
 * `--count-only KIND K PARAM N` runs N calls of the wrapper bw_mf for callgrind
 * (bench/callgrind_microfacet.sh; KIND 0 Blinn-Phong, 1 Beckmann, 2 Phong baseline).
 * Build and run: make bench-microfacet. */
#define _POSIX_C_SOURCE 200809L
#define SHLIGHT_IMPLEMENTATION
#include "../shlight.h"
#include "../tests/ref/arearef.h"
#define BENCH_QUADS /* bench_edge.c's quad sampler */
#include "bench_util.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define NCFG 96
static cfg C[NCFG];
static volatile float sink;
static int g_kind, g_k;
static float g_par;

static float eval(int i) {
  const float(*v)[3] = (const float(*)[3])C[i].v;
  if (g_kind == 0) return shl_polygon_blinn_phong(v, 4, C[i].n, C[i].view, g_par, g_k);
  if (g_kind == 1) return shl_polygon_beckmann_subedges(v, 4, C[i].n, C[i].view, g_par, g_k);
  return shl_polygon_phong(v, 4, C[i].n, C[i].view, g_par, SHLIGHT_EDGE_QUADRATURE);
}
__attribute__((noinline)) void bw_mf(int i) {
  sink = eval(i);
}
BENCH_DEFINE_TIME_NS(bw_mf)

#define NK 5
static const int KS[NK] = {1, -2, 2, 4, 8};
#define NP 4
static const double PS[2][NP] = {{1, 30, 1000, 10000}, {1.0, 0.4, 0.1, 0.02}};

int main(int argc, char **argv) {
  static double err[2][NK][NP][NCFG], errc[NK][4][NP * NCFG];
  static long double ref[NCFG], alb[NCFG];
  int i, kind, q, ip, k, ncls[4];
  FILE *out;
  for (i = 0; i < NCFG; ++i)
    make(&C[i]);
  if (argc == 6 && !strcmp(argv[1], "--count-only")) {
    int kk, N = atoi(argv[5]);
    g_kind = atoi(argv[2]);
    g_k = atoi(argv[3]);
    g_par = (float)atof(argv[4]);
    for (kk = 0; kk < N; ++kk)
      bw_mf(kk % NCFG);
    return 0;
  }
  out = fopen("bench/out/microfacet.md", "w");
  if (!out) out = stdout;
  for (kind = 0; kind < 2; ++kind) {
    fprintf(out,
            "### %s polygon (quad) lights in half-vector space: ns per light and error (of the "
            "albedo) by sub-edges k\n\n",
            kind ? "Beckmann" : "Blinn-Phong");
    fprintf(out,
            "`gcc -O3 -march=native`, per-thread CPU time, median of 15; error against long "
            "double cubature (tests/ref/arearef.h), %d random quads per %s; k = -2: the paper's "
            "single split without its balancing heuristic. Baseline: shl_polygon_phong "
            "(QUADRATURE) in the same run.\n\n",
            NCFG, kind ? "alpha" : "exponent");
    fprintf(out,
            "| %s | k | ns / quad | x Phong | median | p95 | max |\n"
            "|---|---|---|---|---|---|---|\n",
            kind ? "alpha" : "exponent");
    for (ip = 0; ip < NP; ++ip) {
      double base;
      g_kind = 2;
      g_par = kind ? (float)(2 / (PS[1][ip] * PS[1][ip]) - 2) : (float)PS[0][ip];
      base = time_ns();
      for (i = 0; i < NCFG; ++i) {
        double n[3], vw[3], v[4][3];
        int a, b;
        for (a = 0; a < 4; ++a)
          for (b = 0; b < 3; ++b)
            v[a][b] = C[i].v[a][b];
        for (b = 0; b < 3; ++b)
          n[b] = C[i].n[b], vw[b] = C[i].view[b];
        unit(vw);
        alb[i] = arref_mf_albedo(n, vw, PS[kind][ip], kind, 1e-6L);
        ref[i] =
            arref_polygon_mf((const double(*)[3])v, 4, n, vw, PS[kind][ip], kind, 1e-6L * alb[i]);
      }
      for (q = 0; q < NK; ++q) {
        double med, p95, mx, ns, tmp[NCFG];
        g_kind = kind;
        g_k = KS[q];
        g_par = (float)PS[kind][ip];
        ns = time_ns();
        for (i = 0; i < NCFG; ++i)
          err[kind][q][ip][i] = tmp[i] = (double)(fabsl(eval(i) - ref[i]) / alb[i]);
        stats(tmp, NCFG, &med, &p95, &mx);
        fprintf(out, "| %g | %d | %.0f | %.1f | %.1e | %.1e | %.1e |\n", PS[kind][ip], KS[q], ns,
                ns / base, med, p95, mx);
        fflush(out);
      }
    }
    fprintf(out, "\n#### %s: error by configuration (all %s pooled): median / p95 / max\n\n",
            kind ? "Beckmann" : "Blinn-Phong", kind ? "alphas" : "exponents");
    fprintf(out, "| k | straddles the horizon | grazing view (> 70 deg) | large (half-extent > "
                 "0.4 d) | sliver |\n|---|---|---|---|---|\n");
    for (q = 0; q < NK; ++q) {
      for (k = 0; k < 4; ++k)
        ncls[k] = 0;
      for (ip = 0; ip < NP; ++ip)
        for (i = 0; i < NCFG; ++i)
          for (k = 0; k < 4; ++k)
            if (C[i].cls & (1 << k)) errc[q][k][ncls[k]++] = err[kind][q][ip][i];
      fprintf(out, "| %d |", KS[q]);
      for (k = 0; k < 4; ++k) {
        double med, p95, mx;
        stats(errc[q][k], ncls[k], &med, &p95, &mx);
        fprintf(out, " %.1e / %.1e / %.1e |", med, p95, mx);
      }
      fprintf(out, "\n");
    }
    fprintf(out, "\nConfigurations: straddling %d, grazing %d, large %d, sliver %d (of %d).\n\n",
            ncls[0] / NP, ncls[1] / NP, ncls[2] / NP, ncls[3] / NP, NCFG);
  }
  if (out != stdout) fclose(out);
  return 0;
}
