/* bench_ggx.c - GGX polygon (quad) lights: shl_polygon_ggx against long double cubature
 * (tests/ref/arearef.h) on the LTC comparison's sampler (tests/ref/ggxcases.h: 7 roughness values
 * x 250 quads), next to LTC's numbers measured externally on that sampler. Per roughness: median /
 * p95 / max relative error where the light gives >= 5 % of the directional albedo ("visible"),
 * error / albedo over all quads; then pooled by configuration (straddling the horizon, grazing view
 * >= 60 deg); ns per light (per-thread CPU time, median of 15 samples over the 1,750 quads). Writes
 * bench/out/ggx.md.
 * `--count-only K [R]` runs K passes of the 1,750 calls of the wrapper bw_ggx for callgrind
 * (bench/callgrind_ggx.sh), or of the 250 of roughness index R only. Also writes
 * bench/out/ggx_speed.md: the speed-against-error table per roughness (every GGX road: the
 * instructions per quad of each roughness from bench/out/ggx_instr_rough.txt, written by
 * callgrind_ggx.sh; ns per quad of each roughness timed here; LTC's row measured externally),
 * which bench/readme_tables.py copies into docs/area-lights.md and bench/plot_ggx.py plots.
 * The same tables carry shl_polygon_ggx_fast (the table-free LTC; `--count-only K R fast` counts
 * its wrapper bw_ggx_fast). Build and run: make bench-ggx. */
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
#include <time.h>

/* the LTC comparison, LTC reference (clipped quad, 64x64 tables): rel. error on visible
   configurations median / p95 / max, err / albedo median / p95 / max */
/* LTC measured externally (an independent run of the reference clipped-quad shader and 64x64
   tables on a 1,400-quad harness of the same sampler): x86 instructions and ns per quad, median
   relative error (visible) and max error / albedo per roughness */
static const double LTC_X_INSTR = 463, LTC_X_NS = 58;
static const double LTC_X[NR][2] = {{8.3e-5, 8.9e-2}, {1.1e-3, 9.7e-3}, {1.4e-2, 4.3e-2},
                                    {5.0e-2, 0.14},   {0.14, 0.20},     {0.12, 0.10},
                                    {3.1e-2, 7.1e-3}};
static const double LTC[NR][6] = {
    {7.3e-5, 0.019, 0.24, 1.0e-5, 1.9e-3, 0.11}, {1.0e-3, 0.020, 0.20, 8.0e-5, 2.7e-3, 0.028},
    {3.8e-3, 0.19, 1.3, 3.8e-4, 0.021, 0.18},    {0.016, 0.45, 0.68, 9.7e-4, 0.030, 0.20},
    {0.11, 0.74, 0.97, 2.1e-3, 0.070, 0.20},     {0.068, 0.50, 0.64, 1.8e-3, 0.037, 0.071},
    {0.011, 0.048, 0.13, 6.0e-4, 4.8e-3, 0.013}};
typedef struct {
  float q[4][3], view[3], alpha;
  double gt, alb;
  int straddle, grazing;
} cfg;
static cfg C[NCFG];
static volatile float sink;
static const float NZ[3] = {0, 0, 1};

/* the yardstick timed in the same run: FAST Phong of the same quad (1.3k instructions, README) */
__attribute__((noinline)) float yard_phong(const cfg *c) {
  return shl_polygon_phong((const float(*)[3])c->q, 4, NZ, c->view, 2.0f / (c->alpha * c->alpha),
                           SHLIGHT_EDGE_FAST);
}
/* the wrappers callgrind counts */
__attribute__((noinline)) float bw_ggx(const cfg *c) {
  return shl_polygon_ggx((const float(*)[3])c->q, 4, NZ, c->view, c->alpha);
}
/* the portable edge kernel (tests/test_ggx_portable.c, SHLIGHT_NO_SIMD), timed next to bw_ggx:
   what the build runs without the edges' AVX2 lanes */
float ggx_portable(const float (*v)[3], int nv, const float nrm[3], const float view[3],
                   float alpha, int ndf);
__attribute__((noinline)) float pw_ggx(const cfg *c) {
  return ggx_portable((const float(*)[3])c->q, 4, NZ, c->view, c->alpha, 0);
}
__attribute__((noinline)) float bw_ggx_fast(const cfg *c) {
  return shl_polygon_ggx_fast((const float(*)[3])c->q, 4, NZ, c->view, c->alpha);
}
static int FAST; /* 1: the timing loops run shl_polygon_ggx_fast */
static float call(const cfg *c) {
  return FAST ? bw_ggx_fast(c) : bw_ggx(c);
}

/* ns per quad of roughness index ir: median of 15 samples of >= 2 ms over its NPER quads */
static double ns_rough(int ir) {
  double ns[15];
  int s, i, k, reps = 1;
  for (;;) {
    double t0 = now();
    float acc = 0;
    for (k = 0; k < reps; ++k)
      for (i = ir * NPER; i < (ir + 1) * NPER; ++i)
        acc += call(&C[i]);
    sink = acc;
    if (now() - t0 > 2e-3) break;
    reps *= 2;
  }
  for (s = 0; s < 15; ++s) {
    double t0 = now();
    float acc = 0;
    for (k = 0; k < reps; ++k)
      for (i = ir * NPER; i < (ir + 1) * NPER; ++i)
        acc += call(&C[i]);
    sink = acc;
    ns[s] = (now() - t0) * 1e9 / ((double)reps * NPER);
  }
  return pct(ns, 15, 0.5);
}

/* bench/out/ggx_speed.md: per roughness, every GGX road's cost and error side by side */
static void speed_table(void) {
  double instr[NR], finstr[NR];
  int ir, i, have = 1, fhave = 1;
  FILE *f = fopen("bench/out/ggx_instr_rough.txt", "r"), *o;
  for (ir = 0; ir < NR; ++ir)
    if (!f || fscanf(f, "%lf", &instr[ir]) != 1) have = 0;
  if (f) fclose(f);
  f = fopen("bench/out/ggx_fast_instr_rough.txt", "r");
  for (ir = 0; ir < NR; ++ir)
    if (!f || fscanf(f, "%lf", &finstr[ir]) != 1) fhave = 0;
  if (f) fclose(f);
  o = fopen("bench/out/ggx_speed.md", "w");
  if (!o) return;
  fprintf(o, "| roughness | road | x86 instructions per quad | ns per quad | rel. err vis. median "
             "/ p95 / max | max err / albedo |\n|---|---|---|---|---|---|\n");
  for (ir = 0; ir < NR; ++ir) {
    static double rel[NPER];
    double emax = 0, ns = ns_rough(ir);
    int nv = 0;
    char ins[32];
    for (i = ir * NPER; i < (ir + 1) * NPER; ++i) {
      double got = shl_polygon_ggx((const float(*)[3])C[i].q, 4, NZ, C[i].view, C[i].alpha);
      double d = fabs(got - C[i].gt);
      if (d / C[i].alb > emax) emax = d / C[i].alb;
      if (C[i].gt >= 0.05 * C[i].alb) rel[nv++] = d / C[i].gt;
    }
    if (have)
      snprintf(ins, sizeof ins, "%.0f", instr[ir]);
    else
      snprintf(ins, sizeof ins, "-");
    fprintf(o, "| %.2f | shl_polygon_ggx | %s | %.0f | %.1e / %.1e / %.1e | %.1e |\n", ROUGH[ir],
            ins, ns, pct(rel, nv, 0.5), pct(rel, nv, 0.95), pct(rel, nv, 1), emax);
    {
      double fmax = 0, fns;
      int fv = 0;
      FAST = 1;
      fns = ns_rough(ir);
      FAST = 0;
      for (i = ir * NPER; i < (ir + 1) * NPER; ++i) {
        double got = shl_polygon_ggx_fast((const float(*)[3])C[i].q, 4, NZ, C[i].view, C[i].alpha);
        double d = fabs(got - C[i].gt);
        if (d / C[i].alb > fmax) fmax = d / C[i].alb;
        if (C[i].gt >= 0.05 * C[i].alb) rel[fv++] = d / C[i].gt;
      }
      if (fhave)
        snprintf(ins, sizeof ins, "%.0f", finstr[ir]);
      else
        snprintf(ins, sizeof ins, "-");
      fprintf(o, "| %.2f | shl_polygon_ggx_fast | %s | %.0f | %.1e / %.1e / %.1e | %.1e |\n",
              ROUGH[ir], ins, fns, pct(rel, fv, 0.5), pct(rel, fv, 0.95), pct(rel, fv, 1), fmax);
    }
    fprintf(o, "| %.2f | LTC (measured externally) | %.0f | %.0f | %.1e / - / - | %.1e |\n",
            ROUGH[ir], LTC_X_INSTR, LTC_X_NS, LTC_X[ir][0], LTC_X[ir][1]);
  }
  fclose(o);
}

int main(int argc, char **argv) {
  ggxc_rng rg;
  int i, ir, k, K = 0, R = -1;
  FILE *o;
  if (argc >= 3 && strcmp(argv[1], "--count-only") == 0) K = atoi(argv[2]);
  if (argc >= 4 && K > 0) R = atoi(argv[3]);
  if (argc == 5 && strcmp(argv[4], "fast") == 0) FAST = 1;
  rg.s = 2017u;
  for (i = 0; i < NCFG; ++i) {
    cfg *c = &C[i];
    int j, below = 0, above = 0;
    ggx_case(&rg, i, c->q, c->view, &c->alpha);
    for (j = 0; j < 4; ++j)
      below += c->q[j][2]<0, above += c->q[j][2]> 0;
    c->straddle = below > 0 && above > 0;
    c->grazing = c->view[2] < 0.5f;
  }
  if (K > 0) {
    float s = 0;
    for (k = 0; k < K; ++k)
      for (i = R < 0 ? 0 : R * NPER; i < (R < 0 ? NCFG : (R + 1) * NPER); ++i)
        s += call(&C[i]);
    sink = s;
    return 0;
  }
  for (i = 0; i < NCFG; ++i) { /* ground truth on the float-rounded input */
    double q[4][3], v[3], n[3] = {0, 0, 1};
    for (k = 0; k < 12; ++k)
      q[k / 3][k % 3] = C[i].q[k / 3][k % 3];
    for (k = 0; k < 3; ++k)
      v[k] = C[i].view[k];
    C[i].alb = (double)arref_ggx_albedo(n, v, (double)C[i].alpha);
    C[i].gt = (double)arref_polygon_ggx((const double(*)[3])q, 4, n, v, (double)C[i].alpha);
  }
  o = fopen("bench/out/ggx.md", "w");
  if (!o) o = stdout;
  fprintf(o,
          "### GGX quad lights: shl_polygon_ggx vs LTC (research sampler, %d quads per "
          "roughness, F = 1, height-correlated G2)\n\n",
          NPER);
  fprintf(o, "| roughness (alpha = r^2) | vis. | shl_polygon_ggx rel. err vis. median / p95 / "
             "max | err/albedo median / p95 / max | LTC rel. err vis. median / p95 / max "
             "(published) | LTC err/albedo median / p95 / max |\n|---|---|---|---|---|---|\n");
  for (ir = 0; ir < NR; ++ir) {
    static double rel[NPER], ea[NPER];
    int nv = 0;
    for (i = ir * NPER; i < (ir + 1) * NPER; ++i) {
      double got = shl_polygon_ggx((const float(*)[3])C[i].q, 4, NZ, C[i].view, C[i].alpha);
      double d = fabs(got - C[i].gt);
      ea[i - ir * NPER] = d / C[i].alb;
      if (C[i].gt >= 0.05 * C[i].alb) {
        rel[nv++] = d / C[i].gt;
      }
    }
    fprintf(o,
            "| %.2f | %d | %.1e / %.1e / %.1e | %.1e / %.1e / %.1e | %.1e / %.2g / %.2g | "
            "%.1e / %.1e / %.2g |\n",
            ROUGH[ir], nv, pct(rel, nv, 0.5), pct(rel, nv, 0.95), pct(rel, nv, 1),
            pct(ea, NPER, 0.5), pct(ea, NPER, 0.95), pct(ea, NPER, 1), LTC[ir][0], LTC[ir][1],
            LTC[ir][2], LTC[ir][3], LTC[ir][4], LTC[ir][5]);
  }
  fprintf(o,
          "\n| roughness (alpha = r^2) | vis. | shl_polygon_ggx_fast rel. err vis. median / p95 / "
          "max | err/albedo median / p95 / max |\n|---|---|---|---|\n");
  for (ir = 0; ir < NR; ++ir) {
    static double rel[NPER], ea[NPER];
    int nv = 0;
    for (i = ir * NPER; i < (ir + 1) * NPER; ++i) {
      double got = shl_polygon_ggx_fast((const float(*)[3])C[i].q, 4, NZ, C[i].view, C[i].alpha);
      double d = fabs(got - C[i].gt);
      ea[i - ir * NPER] = d / C[i].alb;
      if (C[i].gt >= 0.05 * C[i].alb) rel[nv++] = d / C[i].gt;
    }
    fprintf(o, "| %.2f | %d | %.1e / %.1e / %.1e | %.1e / %.1e / %.1e |\n", ROUGH[ir], nv,
            pct(rel, nv, 0.5), pct(rel, nv, 0.95), pct(rel, nv, 1), pct(ea, NPER, 0.5),
            pct(ea, NPER, 0.95), pct(ea, NPER, 1));
  }
  fprintf(o, "\nBy configuration, all roughness values pooled: err/albedo median / p95 / max "
             "(rel. err vis. median)\n\n| configuration | quads | shl_polygon_ggx | LTC "
             "(published) |\n|---|---|---|---|\n");
  {
    static const char *nm[4] = {"light above the horizon, view < 60 deg",
                                "light above the horizon, view >= 60 deg",
                                "light straddles the horizon, view < 60 deg",
                                "light straddles the horizon, view >= 60 deg"};
    static const char *ltc[4] = {"1.5e-4 / 5.3e-3 / 0.033 (0.4 %)", "8.1e-4 / 0.031 / 0.12 (5 %)",
                                 "7.5e-4 / 0.018 / 0.076 (1.1 %)", "1.7e-3 / 0.082 / 0.20 (6 %)"};
    int g;
    for (g = 0; g < 4; ++g) {
      static double ea[NCFG], rel[NCFG];
      int ne = 0, nv = 0;
      for (i = 0; i < NCFG; ++i)
        if (C[i].straddle == (g >= 2) && C[i].grazing == (g & 1)) {
          double d = fabs(shl_polygon_ggx((const float(*)[3])C[i].q, 4, NZ, C[i].view, C[i].alpha) -
                          C[i].gt);
          ea[ne++] = d / C[i].alb;
          if (C[i].gt >= 0.05 * C[i].alb) rel[nv++] = d / C[i].gt;
        }
      fprintf(o, "| %s | %d | %.1e / %.1e / %.1e (%.1e) | %s |\n", nm[g], ne, pct(ea, ne, 0.5),
              pct(ea, ne, 0.95), pct(ea, ne, 1), pct(rel, nv, 0.5), ltc[g]);
    }
  }
  { /* ns per light: median of 15 samples, each >= 2 ms over all quads; the yardstick alternates */
    double ns[15], ny[15], np[15];
    int s, reps = 1, w;
    for (;;) {
      double t0 = now(), t;
      float acc = 0;
      for (k = 0; k < reps; ++k)
        for (i = 0; i < NCFG; ++i)
          acc += bw_ggx(&C[i]);
      sink = acc;
      t = now() - t0;
      if (t > 2e-3) break;
      reps *= 2;
    }
    for (s = 0; s < 15; ++s)
      for (w = 0; w < 3; ++w) {
        double t0 = now();
        float acc = 0;
        for (k = 0; k < (w == 1 ? 4 * reps : reps); ++k)
          for (i = 0; i < NCFG; ++i)
            acc += w == 1 ? yard_phong(&C[i]) : w == 2 ? pw_ggx(&C[i]) : bw_ggx(&C[i]);
        sink = acc;
        (w == 1   ? ny
         : w == 2 ? np
                  : ns)[s] = (now() - t0) * 1e9 / ((double)(w == 1 ? 4 * reps : reps) * NCFG);
      }
    fprintf(o,
            "\nns per quad light (median of 15, this build): shl_polygon_ggx %.0f; in the same "
            "run shl_polygon_phong FAST (the yardstick) %.0f: ratio %.1f; the portable edge "
            "kernel (SHLIGHT_NO_SIMD) %.0f: %.2fx shl_polygon_ggx's time. LTC's reference "
            "shader on the CPU: 68 ns, 709 instructions, in the research note's run (not this "
            "one)\n",
            pct(ns, 15, 0.5), pct(ny, 15, 0.5), pct(ns, 15, 0.5) / pct(ny, 15, 0.5),
            pct(np, 15, 0.5), pct(np, 15, 0.5) / pct(ns, 15, 0.5));
  }
  if (o != stdout) fclose(o);
  speed_table();
  return 0;
}
