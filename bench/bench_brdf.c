/* bench_brdf.c - per-shading-point convolution cost of a sphere light (a ZH cap about w) with a
 * circularly symmetric lobe (normalised Phong, exponent 20, about r), n = 3..15 bands:
 *   sh_sh      shl_sh_dot of the two SH vectors (both given: the table / accumulated case)
 *   sh_sh_rot  the same with both SH made per point (two shl_zh_rotate, then shl_sh_dot)
 *   sh_sh_1rot the light's SH made per point (one shl_zh_rotate of the cap), the lobe's SH given
 *              (from a table): [HVL]'s SH path
 *   sh_zh      shl_sh_conv_zh: SH radiance (given) against the ZH lobe turned to r
 *   zh_zh      shl_zh_dot_zh: ZH cap about w against the ZH lobe about r, O(n)
 * each next to its error against the integral of the true (untruncated) lobe over the cap,
 * computed by long double quadrature: max over 256 configurations of |value - ref|, relative to
 * the largest ref. The four compute the same band-limited sum, so their errors agree to float
 * rounding; the ratio sh_sh / zh_zh is then a ratio at equal error. Also the ringing of a cap
 * (half-angle 30 deg) before and after the windows. Writes bench/out/brdf.md and brdf.csv.
 * Build and run: make bench-brdf (gcc -O3 -march=native). Timing method as bench_light.c:
 * per-thread CPU time, median of 15 samples of >= 2 ms, 256 configurations cycled, non-inlined
 * wrappers with a literal band count, a memory barrier. */
#define _POSIX_C_SOURCE 200809L
#define SHLIGHT_IMPLEMENTATION
#include "../shlight.h"
#define BENCH_SEED 0x5eed5u
#include "bench_util.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#define NOINL __attribute__((noinline))
#define NCFG 256
#define EXPO 20.0f
static float W[NCFG][3], RD[NCFG][3], CAPZH[NCFG][16], LOBE[16], LSH[NCFG][256], FSH[NCFG][256];
static float ta[256], tb[256];
static volatile float sink;

typedef void (*wfn)(int i);
static double time_ns(wfn f) {
  double s[15], t0, t;
  int k, j, it;
  for (k = 0; k < 15; ++k) {
    it = 0;
    t0 = now();
    do {
      for (j = 0; j < NCFG; ++j) {
        f(j);
        __asm__ volatile("" ::"r"(ta), "r"(tb) : "memory");
      }
      it += NCFG;
    } while ((t = now()) - t0 < 2e-3);
    s[k] = (t - t0) / it * 1e9;
  }
  for (k = 0; k < 15; ++k)
    for (j = k + 1; j < 15; ++j)
      if (s[j] < s[k]) t = s[k], s[k] = s[j], s[j] = t;
  return s[7];
}

#define NL(X) X(3) X(4) X(5) X(6) X(7) X(8) X(9) X(10) X(11) X(12) X(13) X(14) X(15)
#define WR(N) \
  NOINL void shsh_##N(int i) { \
    sink = shl_sh_dot(N, LSH[i], FSH[i]); \
  } \
  NOINL void shshrot_##N(int i) { \
    shl_zh_rotate(N, CAPZH[i], W[i], ta); \
    shl_zh_rotate(N, LOBE, RD[i], tb); \
    sink = shl_sh_dot(N, ta, tb); \
  } \
  NOINL void shsh1_##N(int i) { \
    shl_zh_rotate(N, CAPZH[i], W[i], ta); \
    sink = shl_sh_dot(N, ta, FSH[i]); \
  } \
  NOINL void shzh_##N(int i) { \
    sink = shl_sh_conv_zh(N, LSH[i], LOBE, RD[i]); \
  } \
  NOINL void zhzh_##N(int i) { \
    sink = shl_zh_dot_zh(N, CAPZH[i], W[i], LOBE, RD[i]); \
  }
NL(WR)
/* 3-band irradiance at a normal: the basis road against the matrix road (M given per SH) */
static float COS3[3], IRM[NCFG][16];
NOINL static void irr_conv(int i) {
  sink = shl_sh_conv_zh(3, LSH[i], COS3, RD[i]);
}
NOINL static void irr_matrix(int i) {
  const float *m = IRM[i], *d = RD[i];
  float e = m[15] + 2.0f * (m[3] * d[0] + m[7] * d[1] + m[11] * d[2]);
  e += d[0] * (m[0] * d[0] + 2.0f * (m[1] * d[1] + m[2] * d[2]));
  e += d[1] * (m[5] * d[1] + 2.0f * m[6] * d[2]) + m[10] * d[2] * d[2];
  sink = e;
}
NOINL static void irr_build(int i) {
  shl_sh_irradiance_matrix(LSH[i], IRM[i]);
}
typedef struct {
  int n;
  wfn f[5];
} row;
#define ROW(N) {N, {shsh_##N, shshrot_##N, shzh_##N, zhzh_##N, shsh1_##N}},
static const row rows[] = {NL(ROW)};

/* integral over the cap (axis w, sin a = s) of (e+1)/(2pi) max(0, r.w)^e, long double */
static long double cap_ref(const float *w, const float *r, double s) {
  long double wv[3], rv[3], e1[3], e2[3], nn, acc = 0, al = sqrtl(1.0L - (long double)s * s);
  int i, j, k;
  for (k = 0; k < 3; ++k)
    wv[k] = w[k], rv[k] = r[k];
  nn = sqrtl(wv[0] * wv[0] + wv[1] * wv[1] + wv[2] * wv[2]);
  for (k = 0; k < 3; ++k)
    wv[k] /= nn;
  nn = sqrtl(rv[0] * rv[0] + rv[1] * rv[1] + rv[2] * rv[2]);
  for (k = 0; k < 3; ++k)
    rv[k] /= nn;
  e1[0] = fabsl(wv[0]) < 0.9L ? 1 : 0;
  e1[1] = 1 - e1[0];
  e1[2] = 0;
  nn = e1[0] * wv[0] + e1[1] * wv[1];
  for (k = 0; k < 3; ++k)
    e1[k] -= nn * wv[k];
  nn = sqrtl(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
  for (k = 0; k < 3; ++k)
    e1[k] /= nn;
  e2[0] = wv[1] * e1[2] - wv[2] * e1[1];
  e2[1] = wv[2] * e1[0] - wv[0] * e1[2];
  e2[2] = wv[0] * e1[1] - wv[1] * e1[0];
  /* midpoint in cos(psi) (256) x phi (512): the lobe is smooth at this scale except at the
     horizon of r, which a cap of s = 0.3 reaches only for configurations near grazing */
  for (i = 0; i < 256; ++i) {
    long double ct = al + (1 - al) * (i + 0.5L) / 256, st = sqrtl(1 - ct * ct);
    for (j = 0; j < 512; ++j) {
      long double ph = 2 * 3.14159265358979323846L * (j + 0.5L) / 512, c = 0, om[3];
      for (k = 0; k < 3; ++k)
        om[k] = ct * wv[k] + st * (cosl(ph) * e1[k] + sinl(ph) * e2[k]);
      for (k = 0; k < 3; ++k)
        c += om[k] * rv[k];
      if (c > 0)
        acc += (1 - al) / 256 * (2 * 3.14159265358979323846L / 512) * (EXPO + 1) /
               (2 * 3.14159265358979323846L) * powl(c, EXPO);
    }
  }
  return acc;
}

static void ringing(int n, const float *zh, double *ovs, double *neg) {
  int i, l;
  *ovs = -1e9;
  *neg = 1e9;
  for (i = 0; i <= 2000; ++i) {
    double t = 3.141592653589793 * i / 2000, c = cos(t), p0 = 1, p1 = c,
           f = zh[0] * 0.28209479177387814;
    for (l = 1; l < n; ++l) {
      double p2;
      f += zh[l] * sqrt((2 * l + 1) / (4 * 3.141592653589793)) * p1;
      p2 = ((2 * l + 1) * c * p1 - l * p0) / (l + 1);
      p0 = p1;
      p1 = p2;
    }
    if (f - 1 > *ovs) *ovs = f - 1;
    if (f < *neg) *neg = f;
  }
}

int main(void) {
  static long double ref[NCFG];
  const double s = 0.3; /* cap: sin a = 0.3, a = 17.5 deg */
  FILE *md, *csv;
  int i, k, r;
  const int nrows = (int)(sizeof rows / sizeof rows[0]);
  long double rmax = 0;
  shl_zh_phong(16, EXPO, LOBE);
  for (i = 0; i < NCFG; ++i) {
    /* light direction in the upper hemisphere, lobe axis anywhere within 60 deg of it */
    double z = 0.2 + 0.8 * rnd(), p = 6.283185307179586 * rnd(), sz = sqrt(1 - z * z);
    double dz = cos(1.0472 * rnd()), dp = 6.283185307179586 * rnd(), sd = sqrt(1 - dz * dz);
    double e1[3], e2[3], nn;
    W[i][0] = (float)(sz * cos(p));
    W[i][1] = (float)(sz * sin(p));
    W[i][2] = (float)z;
    e1[0] = -sin(p);
    e1[1] = cos(p);
    e1[2] = 0;
    e2[0] = W[i][1] * e1[2] - W[i][2] * e1[1];
    e2[1] = W[i][2] * e1[0] - W[i][0] * e1[2];
    e2[2] = W[i][0] * e1[1] - W[i][1] * e1[0];
    nn = sqrt(e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2]);
    for (k = 0; k < 3; ++k)
      RD[i][k] = (float)(dz * W[i][k] + sd * (cos(dp) * e1[k] + sin(dp) * e2[k] / nn));
    shl_zh_cap(16, (float)s, 1.0f, CAPZH[i]);
    ref[i] = cap_ref(W[i], RD[i], s);
    if (ref[i] > rmax) rmax = ref[i];
  }
  md = fopen("bench/out/brdf.md", "w");
  csv = fopen("bench/out/brdf.csv", "w");
  if (!md || !csv) {
    fprintf(stderr,
            "bench_brdf: cannot write bench/out/brdf.md / .csv (run from the repository root)\n");
    return 1;
  }
  fprintf(md,
          "Sphere light (sin a = %.1f) x normalised Phong lobe (e = %g), per shading point; ns "
          "per call (median), error = max |value - quadrature of the true lobe| / max ref over "
          "%d configurations\n\n",
          s, (double)EXPO, NCFG);
  fprintf(md, "| n | SH.SH dot | SH.SH + light rotation | SH.SH + 2 rotations | SH.ZH (conv_zh) | "
              "ZH.ZH | ratios to ZH.ZH (dot / +1 rot / +2 rot) | error |\n"
              "|---|---|---|---|---|---|---|---|\n");
  fprintf(
      csv,
      "n,sh_sh_ns,sh_sh_1rot_ns,sh_sh_rot_ns,sh_zh_ns,zh_zh_ns,err_sh_sh,err_sh_zh,err_zh_zh\n");
  printf("n   sh_sh  +1rot  +2rot  sh_zh  zh_zh  ratios(dot/+1/+2)  err\n");
  for (r = 0; r < nrows; ++r) {
    int n = rows[r].n;
    double t[5], e[3] = {0, 0, 0};
    for (i = 0; i < NCFG; ++i) {
      float v[3];
      shl_zh_rotate(n, CAPZH[i], W[i], LSH[i]);
      shl_zh_rotate(n, LOBE, RD[i], FSH[i]);
      v[0] = shl_sh_dot(n, LSH[i], FSH[i]);
      v[1] = shl_sh_conv_zh(n, LSH[i], LOBE, RD[i]);
      v[2] = shl_zh_dot_zh(n, CAPZH[i], W[i], LOBE, RD[i]);
      for (k = 0; k < 3; ++k) {
        double d = (double)(fabsl((long double)v[k] - ref[i]) / rmax);
        if (d > e[k]) e[k] = d;
      }
    }
    for (k = 0; k < 5; ++k)
      t[k] = time_ns(rows[r].f[k]);
    fprintf(md, "| %d | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f / %.1f / %.1f | %.2e |\n", n, t[0],
            t[4], t[1], t[2], t[3], t[0] / t[3], t[4] / t[3], t[1] / t[3], e[2]);
    fprintf(csv, "%d,%.3f,%.3f,%.3f,%.3f,%.3f,%.3e,%.3e,%.3e\n", n, t[0], t[4], t[1], t[2], t[3],
            e[0], e[1], e[2]);
    printf("%-3d %6.1f %6.1f %6.1f %6.1f %6.1f  %4.1f/%4.1f/%4.1f  %.2e (sh.sh %.2e, sh.zh %.2e)\n",
           n, t[0], t[4], t[1], t[2], t[3], t[0] / t[3], t[4] / t[3], t[1] / t[3], e[2], e[0],
           e[1]);
  }
  {
    /* unit normals: RD is normalised at set-up */
    double dmax = 0.0, t[3];
    shl_zh_cosine_power(3, 1.0f, COS3);
    for (i = 0; i < NCFG; ++i) {
      shl_zh_rotate(3, CAPZH[i], W[i], LSH[i]);
      shl_sh_irradiance_matrix(LSH[i], IRM[i]);
      irr_matrix(i);
      {
        double a = (double)sink;
        irr_conv(i);
        if (fabs(a - (double)sink) > dmax) dmax = fabs(a - (double)sink);
      }
    }
    t[0] = time_ns(irr_conv);
    t[1] = time_ns(irr_matrix);
    t[2] = time_ns(irr_build);
    fprintf(md,
            "\n3-band irradiance of the cap at a normal: shl_sh_conv_zh %.1f ns, (n, 1)^T M (n, 1) "
            "%.1f ns (%.1fx), shl_sh_irradiance_matrix (once per SH) %.1f ns; max |difference| "
            "%.1e\n",
            t[0], t[1], t[0] / t[1], t[2], dmax);
    printf("irradiance n=3: conv_zh %.1f ns, matrix %.1f ns per normal, build %.1f ns, max diff "
           "%.1e\n",
           t[0], t[1], t[2], dmax);
  }
  fprintf(md, "\nRinging of a cap of half-angle 30 deg: overshoot above 1 / most negative value\n\n"
              "| n | none | Hanning | Lanczos |\n|---|---|---|---|\n");
  for (k = 4; k <= 16; k *= 2) {
    float z0[16], z1[16], z2[16];
    double o[3], g[3];
    shl_zh_cap(k, 0.5f, 1.0f, z0);
    for (i = 0; i < k; ++i)
      z1[i] = z2[i] = z0[i];
    shl_zh_window(k, SHLIGHT_WINDOW_HANNING, 0.0f, z1);
    shl_zh_window(k, SHLIGHT_WINDOW_LANCZOS, 0.0f, z2);
    ringing(k, z0, &o[0], &g[0]);
    ringing(k, z1, &o[1], &g[1]);
    ringing(k, z2, &o[2], &g[2]);
    fprintf(md, "| %d | %+.3f / %+.3f | %+.3f / %+.3f | %+.3f / %+.3f |\n", k, o[0], g[0], o[1],
            g[1], o[2], g[2]);
    printf("ringing n=%d: none %+.3f/%+.3f hanning %+.3f/%+.3f lanczos %+.3f/%+.3f\n", k, o[0],
           g[0], o[1], g[1], o[2], g[2]);
  }
  fclose(md);
  fclose(csv);
  return 0;
}
