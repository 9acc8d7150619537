/* bench_brdftab.c - >>brdftab: table build time per material and band count (n = 3..10,
   90 theta_o samples, quad_order 32, CPU time of this thread, best of 2) with the build's error
   estimate; anisotropic GGX builds (90 x 4 samples, n = 9, q = 16 and 24); the lookup kernel's
   time; and the shading error of sum_i L_i T_i against direct
   quadrature of L f cos over a cap light (GGX, kd 0.2 + ks 0.8, f0 0.04) as a function of n and
   roughness. Writes bench/out/brdftab.md and bench/out/brdftab.csv. Build and run:
   make bench-brdftab. */
#define _POSIX_C_SOURCE 199309L
#define SHLIGHT_IMPLEMENTATION
#include "../shlight.h"
#include "../tests/ref/shref.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define PI 3.14159265358979323846

static double cpu_now(void) {
  struct timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static shl_brdf_params mk(int model, float kd, float ks, float e, float ax, float ay, float f0) {
  shl_brdf_params b;
  b.model = model;
  b.kd = kd;
  b.ks = ks;
  b.exponent = e;
  b.alpha_x = ax;
  b.alpha_y = ay;
  b.f0 = f0;
  return b;
}

static void cap_sh(int nb, double a, const double c[3], double *out) {
  double ca = cos(a), p[42];
  shref_q y[1600];
  int l, m;
  p[0] = 1.0;
  p[1] = ca;
  for (l = 1; l <= nb; ++l)
    p[l + 1] = ((2.0 * l + 1.0) * ca * p[l] - l * p[l - 1]) / (l + 1.0);
  shref_eval_q(nb, (shref_q)c[0], (shref_q)c[1], (shref_q)c[2], y);
  for (l = 0; l < nb; ++l) {
    double zl = l == 0 ? sqrt(PI) * (1.0 - ca) : sqrt(PI / (2.0 * l + 1.0)) * (p[l - 1] - p[l + 1]);
    for (m = -l; m <= l; ++m)
      out[l * (l + 1) + m] = sqrt(4.0 * PI / (2.0 * l + 1.0)) * zl * (double)y[l * (l + 1) + m];
  }
}
static double cap_direct(const shl_brdf_params *b, const double wo[3], double a,
                         const double c[3]) {
  double e1[3], e2[3], s = 0.0, x[64], w[64], l = sqrt(c[0] * c[0] + c[1] * c[1]);
  float fo[3];
  int i, j, k, p;
  e1[0] = c[1] / l;
  e1[1] = -c[0] / l;
  e1[2] = 0.0;
  e2[0] = c[1] * e1[2] - c[2] * e1[1];
  e2[1] = c[2] * e1[0] - c[0] * e1[2];
  e2[2] = c[0] * e1[1] - c[1] * e1[0];
  shli_gauss_legendre(64, x, w);
  for (k = 0; k < 3; ++k)
    fo[k] = (float)wo[k];
  for (p = 0; p < 8; ++p)
    for (i = 0; i < 64; ++i) {
      double g0 = a * p / 8.0, g1 = a * (p + 1) / 8.0;
      double g = 0.5 * (g0 + g1) + 0.5 * (g1 - g0) * x[i], wg = 0.5 * (g1 - g0) * w[i] * sin(g);
      for (j = 0; j < 512; ++j) {
        double ps = 2.0 * PI * (j + 0.5) / 512.0, wi[3];
        float fi[3];
        for (k = 0; k < 3; ++k) {
          wi[k] = cos(g) * c[k] + sin(g) * (cos(ps) * e1[k] + sin(ps) * e2[k]);
          fi[k] = (float)wi[k];
        }
        if (wi[2] <= 0.0) continue;
        s += wg * (2.0 * PI / 512.0) * (double)shl_brdf_eval(b, fo, fi) * wi[2];
      }
    }
  return s;
}

int main(void) {
  const char *names[7] = {"Lambert",   "Phong e=50", "Blinn-Phong e=100", "Beckmann a=0.2",
                          "GGX a=0.1", "GGX a=0.3",  "GGX a=0.6"};
  shl_brdf_params ms[7];
  const int nt = 90, q = 32;
  float *d = (float *)malloc(shl_brdf_table_size(10, nt, 1) * sizeof(float));
  FILE *md, *csv;
  int k, n, r;
  ms[0] = mk(SHLIGHT_BRDF_LAMBERT, 0.8f, 0, 0, 0, 0, 1);
  ms[1] = mk(SHLIGHT_BRDF_PHONG, 0.2f, 0.8f, 50, 0, 0, 1);
  ms[2] = mk(SHLIGHT_BRDF_BLINN_PHONG, 0.2f, 0.8f, 100, 0, 0, 0.04f);
  ms[3] = mk(SHLIGHT_BRDF_BECKMANN, 0.2f, 0.8f, 0, 0.2f, 0.2f, 0.04f);
  ms[4] = mk(SHLIGHT_BRDF_GGX, 0.2f, 0.8f, 0, 0.1f, 0.1f, 0.04f);
  ms[5] = mk(SHLIGHT_BRDF_GGX, 0.2f, 0.8f, 0, 0.3f, 0.3f, 0.04f);
  ms[6] = mk(SHLIGHT_BRDF_GGX, 0.2f, 0.8f, 0, 0.6f, 0.6f, 0.04f);
  if (!d) return 1;
  md = fopen("bench/out/brdftab.md", "w");
  csv = fopen("bench/out/brdftab.csv", "w");
  if (!md || !csv) {
    fprintf(stderr, "bench_brdftab: cannot write bench/out/ (run from the repository root)\n");
    return 1;
  }
  fprintf(csv, "kind,material,n,value,estimate\n");
  fprintf(md,
          "Table build, isotropic, 90 theta_o samples, quad_order %d: ms per table (CPU time, best "
          "of 2) "
          "and the build's error estimate |T(32) - T(16)| (max over the table)\n\n",
          q);
  fprintf(md, "| material | n=3 | n=4 | n=5 | n=6 | n=7 | n=8 | n=9 | n=10 | estimate (n=10) |\n");
  fprintf(md, "|---|---|---|---|---|---|---|---|---|---|\n");
  for (k = 0; k < 7; ++k) {
    float est = 0.0f;
    fprintf(md, "| %s |", names[k]);
    for (n = 3; n <= 10; ++n) {
      shl_brdf_table t;
      double best = 1e30;
      t.n = n;
      t.n_theta = nt;
      t.n_phi = 1;
      t.flags = 0;
      t.data = d;
      for (r = 0; r < 2; ++r) {
        double t0 = cpu_now(), dt;
        if (shl_brdf_table_build(&t, &ms[k], q, &est) != SHLIGHT_OK) return 1;
        dt = cpu_now() - t0;
        if (dt < best) best = dt;
      }
      fprintf(md, " %.1f |", 1e3 * best);
      fprintf(csv, "build_ms,%s,%d,%.3f,%.3g\n", names[k], n, 1e3 * best, (double)est);
      fflush(csv);
    }
    fprintf(md, " %.1e |\n", (double)est);
    fflush(md);
  }
  { /* anisotropic GGX (the stretched half-vector rule): 90 x 4 samples, n = 9, one run */
    const float al[2][2] = {{0.05f, 0.2f}, {1e-3f, 0.01f}};
    const int qa[2] = {16, 24};
    float *da = (float *)malloc(shl_brdf_table_size(9, nt, 4) * sizeof(float));
    int a, j;
    if (!da) return 1;
    fprintf(md,
            "\nTable build, anisotropic GGX (kd 0.2, ks 0.8, f0 0.04), 90 x 4 samples, n = 9: "
            "ms per table (CPU time, one run) and the estimate\n\n"
            "| (alpha_x, alpha_y) | q = 16 | q = 24 | estimate (q = 24) |\n|---|---|---|---|\n");
    for (a = 0; a < 2; ++a) {
      shl_brdf_params g = mk(SHLIGHT_BRDF_GGX, 0.2f, 0.8f, 0, al[a][0], al[a][1], 0.04f);
      shl_brdf_table t;
      float est = 0.0f;
      t.n = 9;
      t.n_theta = nt;
      t.n_phi = 4;
      t.flags = SHLIGHT_BRDF_TABLE_ANISO;
      t.data = da;
      fprintf(md, "| (%g, %g) |", (double)al[a][0], (double)al[a][1]);
      for (j = 0; j < 2; ++j) {
        double t0 = cpu_now(), dt;
        if (shl_brdf_table_build(&t, &g, qa[j], j ? &est : NULL) != SHLIGHT_OK) return 1;
        dt = cpu_now() - t0;
        fprintf(md, " %.0f |", 1e3 * dt);
        fprintf(csv, "build_ms,GGX aniso %g %g q%d,9,%.3f,%.3g\n", (double)al[a][0],
                (double)al[a][1], qa[j], 1e3 * dt, (double)est);
      }
      fprintf(md, " %.1e |\n", (double)est);
      fflush(md);
    }
    free(da);
  }
  { /* lookup kernel: ns per call */
    float o[100], wo[3];
    fprintf(md, "\nshl_brdf_table_lookup (isotropic, rotation included): ns per call, n = 3..10:");
    for (n = 3; n <= 10; ++n) {
      double t0, dt, acc = 0.0;
      int i, reps = 200000;
      t0 = cpu_now();
      for (i = 0; i < reps; ++i) {
        double th = 1.5 * (i % 1000) / 1000.0;
        wo[0] = (float)sin(th) * 0.6f;
        wo[1] = (float)sin(th) * 0.8f;
        wo[2] = (float)cos(th);
        shl_brdf_table_lookup(n, nt, 1, 0, d, wo, o);
        acc += (double)o[i % (n * n)];
      }
      dt = cpu_now() - t0;
      fprintf(md, " %.0f", 1e9 * dt / reps);
      fprintf(csv, "lookup_ns,iso,%d,%.1f,%g\n", n, 1e9 * dt / reps, acc * 0.0);
    }
    fprintf(md, "\n");
  }
  { /* shading error against direct quadrature */
    const float rough[5] = {0.1f, 0.2f, 0.3f, 0.5f, 1.0f};
    fprintf(md,
            "\nShading error: max over 6 views of |sum_i L_i T_i - integral L f cos| / integral, "
            "cap light "
            "of half-angle 0.4 rad at 40 deg, GGX (kd 0.2, ks 0.8, f0 0.04), 90 theta_o samples, "
            "quad_order 48, lookup between samples\n\n");
    fprintf(md, "| alpha | n=3 | n=4 | n=5 | n=6 | n=7 | n=8 | n=9 | n=10 "
                "|\n|---|---|---|---|---|---|---|---|---|\n");
    for (r = 0; r < 5; ++r) {
      shl_brdf_params b = mk(SHLIGHT_BRDF_GGX, 0.2f, 0.8f, 0, rough[r], rough[r], 0.04f);
      shl_brdf_table t;
      double c[3], lsh[100], refs[6], worst[11];
      float obuf[6][100];
      int v, i, nn;
      t.n = 10;
      t.n_theta = nt;
      t.n_phi = 1;
      t.flags = 0;
      t.data = d;
      if (shl_brdf_table_build(&t, &b, 48, NULL) != SHLIGHT_OK) return 1;
      c[0] = -sin(0.7);
      c[1] = 0.2;
      c[2] = cos(0.7);
      {
        double cl = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
        for (i = 0; i < 3; ++i)
          c[i] /= cl;
      }
      cap_sh(10, 0.4, c, lsh);
      for (v = 0; v < 6; ++v) {
        double th = 0.13 + 0.23 * v, ph = 0.4 * v - 0.3, wo[3];
        float fo[3];
        wo[0] = sin(th) * cos(ph);
        wo[1] = sin(th) * sin(ph);
        wo[2] = cos(th);
        for (i = 0; i < 3; ++i)
          fo[i] = (float)wo[i];
        shl_brdf_table_lookup(10, nt, 1, 0, d, fo, obuf[v]);
        refs[v] = cap_direct(&b, wo, 0.4, c);
      }
      fprintf(md, "| %.1f |", (double)rough[r]);
      for (n = 3; n <= 10; ++n) {
        worst[n] = 0.0;
        nn = n * n;
        for (v = 0; v < 6; ++v) {
          double lo = 0.0, e;
          for (i = 0; i < nn; ++i)
            lo += lsh[i] * (double)obuf[v][i];
          e = fabs(lo - refs[v]) / refs[v];
          if (e > worst[n]) worst[n] = e;
        }
        fprintf(md, " %.1e |", worst[n]);
        fprintf(csv, "shading_rel_err,GGX a=%.1f,%d,%.3g,\n", (double)rough[r], n, worst[n]);
      }
      fprintf(md, "\n");
      fflush(md);
    }
  }
  fclose(md);
  fclose(csv);
  free(d);
  printf("wrote bench/out/brdftab.md and bench/out/brdftab.csv\n");
  return 0;
}
