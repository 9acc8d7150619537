/* bench_edge.c - polygon (quad) lights, single-axis Phong: ns and error per method.
 * For each method of shl_polygon_phong (exact, the paper's three O(1) fits with the
 * docs/derivations.md errata fixed, shlight's Stokes-form quadrature, auto) and exponents 1..1e4:
 * ns per quad light (per-thread CPU time, median of 15 samples of >= 2 ms over 256 configurations)
 * and the error in units of the normalised lobe against long double cubature of the doubly clipped
 * moment (tests/ref/arearef.h): median, p95, max; then the error by configuration (lights
 * straddling the horizon, grazing views, large lights, slivers). Writes bench/out/edge.md.
 * `--count-only METHOD EXPONENT K` runs K calls of the wrapper bw_phong for callgrind
 * (bench/callgrind_edge.sh). Build and run: make bench-edge. */
#define _POSIX_C_SOURCE 200809L
#define SHLIGHT_IMPLEMENTATION
#include "../shlight.h"
#include "../tests/ref/arearef.h"
#define BENCH_QUADS
#include "bench_util.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define NCFG 256
static cfg C[NCFG];
static volatile float sink;
static int g_method;
static float g_e;

__attribute__((noinline)) void bw_phong(int i) {
  sink = shl_polygon_phong((const float(*)[3])C[i].v, 4, C[i].n, C[i].view, g_e, g_method);
}
BENCH_DEFINE_TIME_NS(bw_phong)
static long double ref_of(const cfg *c, double e) {
  double v[4][3], n[3], vw[3], r[3], dv;
  int i, k;
  for (i = 0; i < 4; ++i)
    for (k = 0; k < 3; ++k)
      v[i][k] = c->v[i][k];
  for (k = 0; k < 3; ++k)
    n[k] = c->n[k], vw[k] = c->view[k];
  dv = n[0] * vw[0] + n[1] * vw[1] + n[2] * vw[2];
  for (k = 0; k < 3; ++k)
    r[k] = 2 * dv * n[k] - vw[k];
  unit(r);
  return arref_polygon_moment2((const double(*)[3])v, 4, r, e, n) * (e + 1) /
         (2 * 3.141592653589793238L);
}

#define NM 7
static const int MS[NM] = {
    SHLIGHT_EDGE_EXACT,     SHLIGHT_EDGE_LORENTZ,    SHLIGHT_EDGE_LORENTZ_PEARSON,
    SHLIGHT_EDGE_ELLIPSOID, SHLIGHT_EDGE_QUADRATURE, SHLIGHT_EDGE_FAST,
    SHLIGHT_EDGE_AUTO};
static const char *MN[NM] = {"exact",     "Lorentzian",          "Lorentzian-Pearson",
                             "ellipsoid", "quadrature (Stokes)", "fast (Stokes, float SIMD)",
                             "auto"};
#define NE 6
static const double ES[NE] = {1, 10, 100, 1000, 10000, 57.5};

int main(int argc, char **argv) {
  static double err[NM][NE][NCFG], errc[NM][4][NE * NCFG];
  static long double ref[NE][NCFG];
  int i, m, ie, k, ncls[4] = {0, 0, 0, 0};
  FILE *out;
  for (i = 0; i < NCFG; ++i)
    make(&C[i]);
  if (argc == 5 && !strcmp(argv[1], "--count-only")) {
    int kk, K = atoi(argv[4]);
    g_method = atoi(argv[2]);
    g_e = (float)atof(argv[3]);
    for (kk = 0; kk < K; ++kk)
      bw_phong(kk % NCFG);
    return 0;
  }
  out = fopen("bench/out/edge.md", "w");
  if (!out) out = stdout;
  fprintf(
      out,
      "### Polygon (quad) lights, single-axis Phong: ns per light and error (normalised lobe)\n\n");
  fprintf(out,
          "`gcc -O3 -march=native`, per-thread CPU time, median of 15; error against long double "
          "cubature of the doubly clipped moment (tests/ref/arearef.h), %d random quads per "
          "exponent.\n\n",
          NCFG);
  fprintf(out,
          "| method | exponent | ns / quad | median | p95 | max |\n|---|---|---|---|---|---|\n");
  for (ie = 0; ie < NE; ++ie)
    for (i = 0; i < NCFG; ++i)
      ref[ie][i] = ref_of(&C[i], ES[ie]);
  for (m = 0; m < NM; ++m)
    for (ie = 0; ie < NE; ++ie) {
      double med, p95, mx, ns, tmp[NCFG];
      g_method = MS[m];
      g_e = (float)ES[ie];
      ns = time_ns();
      for (i = 0; i < NCFG; ++i) {
        float got =
            shl_polygon_phong((const float(*)[3])C[i].v, 4, C[i].n, C[i].view, g_e, g_method);
        err[m][ie][i] = tmp[i] = (double)fabsl(got - ref[ie][i]);
      }
      stats(tmp, NCFG, &med, &p95, &mx);
      fprintf(out, "| %s | %g | %.0f | %.1e | %.1e | %.1e |\n", MN[m], ES[ie], ns, med, p95, mx);
      fflush(out);
    }
  fprintf(out, "\n### Error by configuration (all exponents pooled): median / p95 / max\n\n");
  fprintf(out, "| method | straddles the horizon | grazing view (> 70 deg) | large (half-extent > "
               "0.4 d) | sliver |\n|---|---|---|---|---|\n");
  for (m = 0; m < NM; ++m) {
    for (k = 0; k < 4; ++k)
      ncls[k] = 0;
    for (ie = 0; ie < NE; ++ie)
      for (i = 0; i < NCFG; ++i)
        for (k = 0; k < 4; ++k)
          if (C[i].cls & (1 << k)) errc[m][k][ncls[k]++] = err[m][ie][i];
    fprintf(out, "| %s |", MN[m]);
    for (k = 0; k < 4; ++k) {
      double med, p95, mx;
      stats(errc[m][k], ncls[k], &med, &p95, &mx);
      fprintf(out, " %.1e / %.1e / %.1e |", med, p95, mx);
    }
    fprintf(out, "\n");
  }
  fprintf(
      out,
      "\nConfigurations: straddling %d, grazing %d, large %d, sliver %d (of %d, x %d exponents).\n",
      ncls[0] / NE, ncls[1] / NE, ncls[2] / NE, ncls[3] / NE, NCFG, NE);
  if (out != stdout) fclose(out);
  return 0;
}
