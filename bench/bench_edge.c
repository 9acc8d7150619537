/* bench_edge.c - polygon (quad) lights, single-axis Phong: ns and error per method.
 * For each method of shl_polygon_phong (exact, the paper's three O(1) fits with the MATH.md
 * errata fixed, shlight's Stokes-form quadrature, auto) and exponents 1..1e4: ns per quad light
 * (per-thread CPU time, median of 15 samples of >= 2 ms over 256 configurations) and the error
 * in units of the normalised lobe against long double cubature of the doubly clipped moment
 * (tests/ref/arearef.h): median, p95, max; then the error by configuration (lights straddling
 * the horizon, grazing views, large lights, slivers). Writes bench/out/edge.md.
 * `--count-only METHOD EXPONENT K` runs K calls of the wrapper bw_phong for callgrind
 * (bench/callgrind_edge.sh). Build and run: make bench-edge. */
#define _POSIX_C_SOURCE 200809L
#define SHLIGHT_IMPLEMENTATION
#include "../shlight.h"
#include "../tests/ref/arearef.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define NCFG 256
typedef struct {
  float v[4][3], n[3], view[3];
  int cls; /* bit 0 straddles the horizon, 1 grazing view (> 70 deg), 2 large, 3 sliver */
} cfg;
static cfg C[NCFG];
static volatile float sink;
static int g_method;
static float g_e;

static uint64_t rs = 0x2545F4914F6CDD1Dull;
static double rnd(void) {
  uint64_t z = (rs += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return (double)((z ^ (z >> 31)) >> 11) * (1.0 / 9007199254740992.0);
}
static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}
static void unit(double a[3]) {
  double l = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  a[0] /= l, a[1] /= l, a[2] /= l;
}
static void cross(const double a[3], const double b[3], double o[3]) {
  o[0] = a[1] * b[2] - a[2] * b[1], o[1] = a[2] * b[0] - a[0] * b[2],
  o[2] = a[0] * b[1] - a[1] * b[0];
}
/* surface normal +z; view at angle tv; the quad centred near the mirror direction (60 %) or
   anywhere above z > -0.25 (40 %), distance 1..10, half-extent/distance 0.02..1.2, tilted */
static void make(cfg *c) {
  double tv = acos(1 - rnd() * 0.97), pv = 6.2831853 * rnd(), r[3], d[3], t1[3], t2[3], nl[3];
  double dist = 1 + 9 * rnd(), ext, sx, sy, mn = 1e9, mx = -1e9;
  int i, k, sliver = rnd() < 0.15;
  c->view[0] = (float)(sin(tv) * cos(pv)), c->view[1] = (float)(sin(tv) * sin(pv));
  c->view[2] = (float)cos(tv);
  c->n[0] = 0, c->n[1] = 0, c->n[2] = 1;
  r[0] = -c->view[0], r[1] = -c->view[1], r[2] = c->view[2];
  if (rnd() < 0.6) {
    for (k = 0; k < 3; ++k)
      d[k] = r[k] + 0.4 * (rnd() - 0.5);
  } else {
    double z = -0.25 + 1.25 * rnd(), p = 6.2831853 * rnd();
    d[0] = sqrt(1 - z * z) * cos(p), d[1] = sqrt(1 - z * z) * sin(p), d[2] = z;
  }
  unit(d);
  for (k = 0; k < 3; ++k)
    nl[k] = -d[k] + 0.8 * (rnd() - 0.5);
  unit(nl);
  t1[0] = 0.3, t1[1] = -0.7, t1[2] = 0.5;
  cross(nl, t1, t2);
  unit(t2);
  cross(t2, nl, t1);
  ext = dist * (rnd() < 1.0 / 3 ? 0.02 + 0.08 * rnd()
                : rnd() < 0.5   ? 0.1 + 0.3 * rnd()
                                : 0.4 + 0.8 * rnd());
  for (i = 0; i < 4; ++i) {
    sx = (i == 0 || i == 3) ? -ext : ext;
    sy = (i < 2) ? -ext : ext;
    if (sliver) sy *= 0.02;
    for (k = 0; k < 3; ++k)
      c->v[i][k] = (float)(dist * d[k] + sx * t1[k] + sy * t2[k]);
    mn = fmin(mn, c->v[i][2]), mx = fmax(mx, c->v[i][2]);
  }
  c->cls =
      (mn < 0 && mx > 0) | (tv > 1.2217 ? 2 : 0) | (ext / dist > 0.4 ? 4 : 0) | (sliver ? 8 : 0);
}

__attribute__((noinline)) void bw_phong(int i) {
  sink = shl_polygon_phong((const float(*)[3])C[i].v, 4, C[i].n, C[i].view, g_e, g_method);
}
static double time_ns(void) {
  double s[15], t0, t;
  int k, j, it;
  for (k = 0; k < 15; ++k) {
    it = 0;
    t0 = now();
    do {
      for (j = 0; j < NCFG; ++j)
        bw_phong(j);
      it += NCFG;
    } while ((t = now()) - t0 < 2e-3);
    s[k] = (t - t0) / it * 1e9;
  }
  for (k = 0; k < 15; ++k)
    for (j = k + 1; j < 15; ++j)
      if (s[j] < s[k]) t = s[k], s[k] = s[j], s[j] = t;
  return s[7];
}
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
static int cmpd(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return x < y ? -1 : x > y;
}
static void stats(double *x, int n, double *med, double *p95, double *mx) {
  qsort(x, (size_t)n, sizeof *x, cmpd);
  *med = n ? x[n / 2] : 0, *p95 = n ? x[n * 95 / 100] : 0, *mx = n ? x[n - 1] : 0;
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
