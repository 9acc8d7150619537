/* ref_brdftab.c - measures BRDF SH tables against tests/ref/brdfref.h (long double, nested
 * adaptive Gauss-Legendre, independent of shlight's quadrature and BRDF code):
 *  1. lookup error against theta_o (0.05 .. 89.99 deg), GGX alpha 0.05 / 0.3 / 1, Phong 1000,
 *     n = 9, tables of 90 and 128 samples at quad_order 64: max |lookup - ref| / |ref|_2;
 *  2. quadrature error at single outgoing directions against quad_order (float floor?), down to
 *     alpha = SHLIGHT_BRDF_MIN_ALPHA and up to exponent SHLIGHT_BRDF_MAX_EXPONENT, and the
 *     error estimate beside the true error.
 * Opt-in (minutes): make brdftab-ref. Ends with "N passed, N failed" (checks: the lookup
 * within 1e-3 of the norm at theta_o <= 89.9 deg for GGX alpha >= 0.05 and Phong e <= 1000,
 * 90 and 128 samples). `l M` runs the lookup rows of model M (0 .. 3) only, `a` the
 * anisotropic GGX rows (stretched half-vector rule) only. */
#define SHLIGHT_IMPLEMENTATION
#include "../shlight.h"
#include "ref/brdfref.h"
#include <stdio.h>
#include <stdlib.h>

#define N 9
#define NN 81

static int npass, nfail;

static void ref_at(int model, double par, double theta_deg, long double tol, long double *out) {
  brdfref r;
  r.model = model == SHLIGHT_BRDF_PHONG ? 1 : 0;
  r.alpha = (long double)(float)par;
  r.exponent = (long double)(float)par;
  r.alpha_y = 0.0L;
  r.f0 = 1.0L;
  r.n = N;
  r.tol = tol;
  brdfref_project(&r, (long double)theta_deg * BRDFREF_PI / 180.0L, out);
}

static double relerr(const float *got, const long double *ref) {
  long double nrm = 0.0L, e = 0.0L;
  int i;
  for (i = 0; i < NN; ++i)
    nrm += ref[i] * ref[i];
  nrm = sqrtl(nrm);
  for (i = 0; i < NN; ++i)
    e = fmaxl(e, fabsl((long double)got[i] - ref[i]));
  return (double)(e / nrm);
}

static shl_brdf_params mkp(int model, double par) {
  shl_brdf_params b;
  b.model = model;
  b.kd = 0.0f;
  b.ks = 1.0f;
  b.exponent = (float)par;
  b.alpha_x = b.alpha_y = (float)par;
  b.f0 = 1.0f;
  return b;
}

static void lookup_table(int only_m) {
  static const double degs[] = {0.05, 0.3,  1.0,  3.7,  20.0, 45.0, 70.0, 80.0,
                                85.0, 87.9, 88.5, 89.0, 89.5, 89.7, 89.9, 89.99};
  static const int models[4] = {SHLIGHT_BRDF_GGX, SHLIGHT_BRDF_GGX, SHLIGHT_BRDF_GGX,
                                SHLIGHT_BRDF_PHONG};
  static const double pars[4] = {0.05, 0.3, 1.0, 1000.0};
  static const int nts[2] = {90, 128};
  const int nd = (int)(sizeof degs / sizeof degs[0]);
  static long double ref[16][2 * NN];
  float *tab = (float *)malloc(sizeof(float) * 2 * 128 * NN);
  int m, k, j, w;
  printf("## lookup error / |ref|_2 (F, F'), n = 9, quad_order 64\n\n| model | samples |");
  for (k = 0; k < nd; ++k)
    printf(" %g |", degs[k]);
  printf("\n|---|---|");
  for (k = 0; k < nd; ++k)
    printf("---|");
  printf("\n");
  for (m = 0; m < 4; ++m) {
    shl_brdf_params b = mkp(models[m], pars[m]);
    if (only_m >= 0 && m != only_m) continue;
    for (k = 0; k < nd; ++k)
      ref_at(models[m], pars[m], degs[k], 1e-11L, ref[k]);
    for (j = 0; j < 2; ++j) {
      shl_brdf_table t;
      t.n = N;
      t.n_theta = nts[j];
      t.n_phi = 1;
      t.flags = 0;
      t.data = tab;
      if (shl_brdf_table_build(&t, &b, 64, NULL) != SHLIGHT_OK) abort();
      printf("| %s %g | %d |", models[m] == SHLIGHT_BRDF_GGX ? "GGX" : "Phong", pars[m], nts[j]);
      for (k = 0; k < nd; ++k) {
        double th = degs[k] * 3.14159265358979323846 / 180.0, e[2];
        float wo[3], o[NN];
        wo[0] = (float)sin(th);
        wo[1] = 0.0f;
        wo[2] = (float)cos(th);
        for (w = 0; w < 2; ++w) {
          shl_brdf_table_lookup(N, nts[j], 1, w, tab, wo, o);
          e[w] = relerr(o, ref[k] + w * NN);
        }
        printf(" %.1e %.1e |", e[0], e[1]);
        if (degs[k] <= 89.9) { /* both 90 (the default) and 128 samples */
          if (e[0] <= 1e-3 && e[1] <= 1e-3)
            ++npass;
          else {
            ++nfail;
            fprintf(stderr, "FAIL %g deg %s %g: %g %g\n", degs[k],
                    models[m] == SHLIGHT_BRDF_GGX ? "GGX" : "Phong", pars[m], e[0], e[1]);
          }
        }
      }
      printf("\n");
      fflush(stdout);
    }
  }
  free(tab);
}

/* quadrature error at one w_o: the library's per-direction projection (the source set up as
   shl_brdf_table_build does) against the reference; the estimate is the build's (e1, e2 from
   the projections at q / 4, q / 2, q), here in units of |ref|_2 like the error */
static void quad_table(int only_m, int only_k) {
  static const int models[7] = {SHLIGHT_BRDF_GGX,  SHLIGHT_BRDF_GGX, SHLIGHT_BRDF_GGX,
                                SHLIGHT_BRDF_GGX,  SHLIGHT_BRDF_GGX, SHLIGHT_BRDF_PHONG,
                                SHLIGHT_BRDF_PHONG};
  static const double pars[7] = {1e-3, 0.01, 0.05, 0.3, 1.0, 1000.0, 1e6};
  static const double degs[5] = {30.0, 85.5, 89.5, 89.9, 90.0};
  static const int qs[3] = {32, 64, 128};
  int m, k, j, w, i;
  printf("\n## quadrature error / |ref|_2 at single w_o (max of F, F'), n = 9, and the build's "
         "error estimate / |ref|_2 (90 deg: cos theta_o = 1e-6)\n\n| model | theta_o |");
  for (j = 0; j < 3; ++j)
    printf(" q = %d: error (estimate) |", qs[j]);
  printf("\n|---|---|---|---|---|\n");
  for (m = 0; m < 7; ++m)
    for (k = 0; k < 5; ++k) {
      shl_brdf_params b = mkp(models[m], pars[m]);
      if ((only_m >= 0 && m != only_m) || (only_k >= 0 && k != only_k)) continue;
      shli_tabsrc src;
      long double ref[2 * NN], nrm = 0.0L;
      double xg[256], wg[256], acc[3][2 * NN];
      double th = degs[k] * 3.14159265358979323846 / 180.0, wo[3];
      double dg = degs[k];
      float y[NN];
      if (degs[k] >= 90.0) {
        th = acos(SHLIGHT_BRDF_TABLE_GRAZING);
        dg = th * 180.0 / 3.14159265358979323846;
      }
      ref_at(models[m], pars[m], dg, 1e-12L, ref);
      src.brdf = &b;
      src.merl = NULL;
      src.channel = 0;
      src.gmax = 3.14159265358979323846;
      src.half = 0;
      if (models[m] == SHLIGHT_BRDF_PHONG) {
        src.width = 1.0 / sqrt(pars[m] + 1.0);
        src.gmax = 0.5 * 3.14159265358979323846;
      } else {
        src.width = (double)(float)pars[m];
        src.half = 1;
      }
      wo[0] = sin(th);
      wo[1] = 0.0;
      wo[2] = cos(th);
      for (w = 0; w < 2; ++w) {
        long double nw = 0.0L;
        for (i = 0; i < NN; ++i)
          nw += ref[w * NN + i] * ref[w * NN + i];
        nrm = fmaxl(nrm, sqrtl(nw));
      }
      printf("| %s %g | %g |", models[m] == SHLIGHT_BRDF_GGX ? "GGX" : "Phong", pars[m], degs[k]);
      for (j = 0; j < 3; ++j) {
        long double e = 0.0L;
        double e1 = 0.0, e2 = 0.0, mx = 0.0, es;
        int r;
        for (r = 0; r < 3; ++r) {
          int q = qs[j] >> (2 - r);
          shli_gauss_legendre(q, xg, wg);
          shli_tab_project(N, &src, 0.0, 1, wo, q, xg, wg, acc[r], y);
        }
        for (i = 0; i < 2 * NN; ++i) {
          double d1 = fabs(acc[1][i] - (double)(float)acc[0][i]);
          double d2 = fabs(acc[2][i] - (double)(float)acc[1][i]);
          long double got = (long double)(float)acc[2][i];
          e1 = d1 > e1 ? d1 : e1;
          e2 = d2 > e2 ? d2 : e2;
          mx = fabs(acc[2][i]) > mx ? fabs(acc[2][i]) : mx;
          e = fmaxl(e, fabsl(got - ref[i]) / nrm);
        }
        es = e2 < e1 ? pow(e2, 2.5) / pow(e1, 1.5) : e2;
        if (es < mx * 5.9604644775390625e-8) es = mx * 5.9604644775390625e-8;
        printf(" %.1e (%.1e) |", (double)e, es / (double)nrm);
        if (qs[j] == 128) {
          /* the float floor: a few 2^-24 of the largest coefficient; the estimate within 10x */
          double fl = 8.0 * 5.9604644775390625e-8 * mx / (double)nrm;
          if (e <= fl && es / (double)nrm <= 10.0 * ((double)e > fl / 8.0 ? (double)e : fl / 8.0) &&
              es / (double)nrm >= 0.1 * (double)e)
            ++npass;
          else {
            ++nfail;
            fprintf(stderr, "FAIL quad %s %g at %g deg: %g (estimate %g)\n",
                    models[m] == SHLIGHT_BRDF_GGX ? "GGX" : "Phong", pars[m], degs[k], (double)e,
                    es / (double)nrm);
          }
        }
        fflush(stdout);
      }
      printf("\n");
    }
}

/* anisotropic GGX (the stretched half-vector rule) against the reference, w_o in the xz plane:
   (ax, ay) and (ay, ax) are phi_o = 0 and 90 deg of one BRDF */
static void aniso_table(void) {
  static const float al[3][2] = {{0.05f, 0.2f}, {0.2f, 0.05f}, {0.3f, 1.0f}};
  static const double degs[2] = {30.0, 89.5};
  static const int qs[3] = {16, 32, 64};
  int m, k, j, i, r, w;
  printf("\n## anisotropic GGX: quadrature error / |ref|_2 (max of F, F'), n = 9, and the build's "
         "estimate / |ref|_2\n\n| (alpha_x, alpha_y) | theta_o |");
  for (j = 0; j < 3; ++j)
    printf(" q = %d: error (estimate) |", qs[j]);
  printf("\n|---|---|---|---|---|\n");
  for (m = 0; m < 3; ++m)
    for (k = 0; k < 2; ++k) {
      shl_brdf_params b = mkp(SHLIGHT_BRDF_GGX, 0.0);
      shli_tabsrc src;
      brdfref rf;
      long double ref[2 * NN], nrm = 0.0L;
      double xg[256], wg[256], acc[3][2 * NN], th = degs[k] * 3.14159265358979323846 / 180.0, wo[3];
      float y[NN];
      b.alpha_x = al[m][0];
      b.alpha_y = al[m][1];
      rf.model = 0;
      rf.alpha = (long double)al[m][0];
      rf.alpha_y = (long double)al[m][1];
      rf.exponent = 0.0L;
      rf.f0 = 1.0L;
      rf.n = N;
      rf.tol = 1e-12L;
      brdfref_project(&rf, (long double)degs[k] * BRDFREF_PI / 180.0L, ref);
      src.brdf = &b;
      src.merl = NULL;
      src.channel = 0;
      src.gmax = 3.14159265358979323846;
      src.half = 2;
      src.width = 0.0;
      wo[0] = sin(th);
      wo[1] = 0.0;
      wo[2] = cos(th);
      for (w = 0; w < 2; ++w) {
        long double nw = 0.0L;
        for (i = 0; i < NN; ++i)
          nw += ref[w * NN + i] * ref[w * NN + i];
        nrm = fmaxl(nrm, sqrtl(nw));
      }
      printf("| (%g, %g) | %g |", (double)al[m][0], (double)al[m][1], degs[k]);
      for (j = 0; j < 3; ++j) {
        long double e = 0.0L;
        double e1 = 0.0, e2 = 0.0, mx = 0.0, es;
        for (r = 0; r < 3; ++r) {
          int q = qs[j] >> (2 - r);
          shli_gauss_legendre(q, xg, wg);
          shli_tab_project(N, &src, 0.0, 1, wo, q, xg, wg, acc[r], y);
        }
        for (i = 0; i < 2 * NN; ++i) {
          double d1 = fabs(acc[1][i] - (double)(float)acc[0][i]);
          double d2 = fabs(acc[2][i] - (double)(float)acc[1][i]);
          e1 = d1 > e1 ? d1 : e1;
          e2 = d2 > e2 ? d2 : e2;
          mx = fabs(acc[2][i]) > mx ? fabs(acc[2][i]) : mx;
          e = fmaxl(e, fabsl((long double)(float)acc[2][i] - ref[i]) / nrm);
        }
        es = e2 < e1 ? pow(e2, 2.5) / pow(e1, 1.5) : e2;
        if (es < mx * 5.9604644775390625e-8) es = mx * 5.9604644775390625e-8;
        printf(" %.1e (%.1e) |", (double)e, es / (double)nrm);
        if (qs[j] >= 32) { /* the float floor (8 ulps of the largest coefficient) */
          if (e <= 8.0 * 5.9604644775390625e-8 * mx / (double)nrm)
            ++npass;
          else {
            ++nfail;
            fprintf(stderr, "FAIL aniso (%g, %g) at %g deg, q = %d: %g\n", (double)al[m][0],
                    (double)al[m][1], degs[k], qs[j], (double)e);
          }
        }
        fflush(stdout);
      }
      printf("\n");
    }
}

int main(int argc, char **argv) {
  brdfref_init();
  if (argc < 2 || argv[1][0] == 'l')
    lookup_table(argc > 2 && argv[1][0] == 'l' ? atoi(argv[2]) : -1);
  /* "q M K": only model M, angle K of the quadrature table (-1: all), to run cases in parallel */
  if (argc < 2 || argv[1][0] == 'q')
    quad_table(argc > 2 ? atoi(argv[2]) : -1, argc > 3 ? atoi(argv[3]) : -1);
  if (argc < 2 || argv[1][0] == 'a') /* "a": the anisotropic rows only */
    aniso_table();
  printf("%d passed, %d failed\n", npass, nfail);
  return nfail != 0;
}
