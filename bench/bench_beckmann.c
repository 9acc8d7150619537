/* bench_beckmann.c - Beckmann polygon (quad) lights on bench_ggx's sampler (tests/ref/ggxcases.h:
 * 7 roughness values x 250 quads, alpha = r^2): shl_polygon_beckmann (shl_polygon_ggx's
 * method with the Beckmann NDF) next to shl_polygon_beckmann_subedges at k = 8 (G2 held at one
 * direction), both against long double cubature of the same integrand (tests/ref/arearef.h,
 * arref_polygon_mf kind 1, abs. tolerance 1e-9 x the albedo arref_mf_albedo). Per roughness:
 * median / p95 / max relative error where the light gives >= 5 % of the albedo ("visible"),
 * error / albedo over all quads. Writes bench/out/beckmann.md. `--count-only K` runs K passes of
 * the 1,750 calls of the wrapper bw_beck for callgrind (bench/callgrind_beckmann.sh). Build and
 * run: make bench-beckmann. */
#define _POSIX_C_SOURCE 200809L
#define SHLIGHT_IMPLEMENTATION
#include "../shlight.h"
#include "../tests/ref/arearef.h"
#include "../tests/ref/ggxcases.h"
#define BENCH_GGXCASES
#include "bench_util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
  float q[4][3], view[3], alpha;
  double gt, alb;
} cfg;
static cfg C[NCFG];
static volatile float sink;
static const float NZ[3] = {0, 0, 1};

/* the wrapper callgrind counts */
__attribute__((noinline)) float bw_beck(const cfg *c) {
  return shl_polygon_beckmann((const float(*)[3])c->q, 4, NZ, c->view, c->alpha);
}

int main(int argc, char **argv) {
  ggxc_rng rg;
  int i, ir, k, m, K = 0;
  FILE *o;
  if (argc == 3 && strcmp(argv[1], "--count-only") == 0) K = atoi(argv[2]);
  rg.s = 2017u;
  for (i = 0; i < NCFG; ++i)
    ggx_case(&rg, i, C[i].q, C[i].view, &C[i].alpha);
  if (K > 0) {
    float s = 0;
    for (k = 0; k < K; ++k)
      for (i = 0; i < NCFG; ++i)
        s += bw_beck(&C[i]);
    sink = s;
    return 0;
  }
  for (i = 0; i < NCFG; ++i) { /* ground truth on the float-rounded input */
    double q[4][3], v[3], n[3] = {0, 0, 1};
    for (k = 0; k < 12; ++k)
      q[k / 3][k % 3] = C[i].q[k / 3][k % 3];
    for (k = 0; k < 3; ++k)
      v[k] = C[i].view[k];
    C[i].alb = (double)arref_mf_albedo(n, v, (double)C[i].alpha, 1, 1e-10L);
    C[i].gt = (double)arref_polygon_mf((const double(*)[3])q, 4, n, v, (double)C[i].alpha, 1,
                                       1e-9L * (long double)C[i].alb);
  }
  o = fopen("bench/out/beckmann.md", "w");
  if (!o) o = stdout;
  fprintf(o,
          "### Beckmann quad lights (bench_ggx's sampler, %d quads per roughness, F = 1, "
          "height-correlated G2)\n\n",
          NPER);
  fprintf(
      o,
      "| roughness (alpha = r^2) | vis. | shl_polygon_beckmann rel. err vis. median "
      "/ p95 / max | err/albedo median / p95 / max | shl_polygon_beckmann_subedges k = 8 rel. err "
      "vis. median / p95 / max | err/albedo median / p95 / max |\n"
      "|---|---|---|---|---|---|\n");
  for (ir = 0; ir < NR; ++ir) {
    static double rel[2][NPER], ea[2][NPER];
    int nv = 0;
    for (i = ir * NPER; i < (ir + 1) * NPER; ++i) {
      double got[2], d[2];
      got[0] = shl_polygon_beckmann((const float(*)[3])C[i].q, 4, NZ, C[i].view, C[i].alpha);
      got[1] =
          shl_polygon_beckmann_subedges((const float(*)[3])C[i].q, 4, NZ, C[i].view, C[i].alpha, 8);
      for (m = 0; m < 2; ++m) {
        d[m] = fabs(got[m] - C[i].gt);
        ea[m][i - ir * NPER] = d[m] / C[i].alb;
      }
      if (C[i].gt >= 0.05 * C[i].alb) {
        rel[0][nv] = d[0] / C[i].gt;
        rel[1][nv] = d[1] / C[i].gt;
        nv++;
      }
    }
    fprintf(o, "| %.2f | %d", ROUGH[ir], nv);
    for (m = 0; m < 2; ++m)
      fprintf(o, " | %.1e / %.1e / %.1e | %.1e / %.1e / %.1e", pct(rel[m], nv, 0.5),
              pct(rel[m], nv, 0.95), pct(rel[m], nv, 1), pct(ea[m], NPER, 0.5),
              pct(ea[m], NPER, 0.95), pct(ea[m], NPER, 1));
    fprintf(o, " |\n");
  }
  if (o != stdout) fclose(o);
  return 0;
}
