/* Self-checks of lightref.h (the references themselves, no shlight).
 * gcc -std=c99 -O2 -o /tmp/selftest_lightref wip3/ref/selftest_lightref.c -lquadmath -lm */
#include "lightref.h"
#include <stdio.h>

typedef lref_q Q;
static int nfail;
static void report(const char *what, double err, double tol) {
  printf("%-64s %10.3e  (tol %.0e) %s\n", what, err, tol, err <= tol ? "ok" : "FAIL");
  if (!(err <= tol)) nfail++;
}

static Q mx(Q a, Q b) {
  return a > b ? a : b;
}

int main(void) {
  char buf[256];
  Q pi = shref_pi();
  int i, k, l;
  /* 1. zonal quadrature vs closed forms l <= 2 and the cap area */
  {
    static const double as[] = {1e-8, 1e-6, 1e-4, 1e-2, 0.3, 1.0, 1.5707963267948966, 2.5, 3.14};
    Q worst = 0, worsta = 0;
    for (i = 0; i < 9; i++) {
      Q a = as[i], L[64], C[3], area;
      lref_cap_zh_q(64, a, L);
      lref_cap_zh_closed3_q(a, C);
      for (l = 0; l < 3; l++) /* relative to max_l |L_l| (L_2 ~ cos a vanishes at pi/2) */
        worst = mx(worst, fabsq(L[l] - C[l]) / mx(fabsq(C[0]), mx(fabsq(C[1]), fabsq(C[2]))));
      area = L[0] / sqrtq(1 / (4 * pi)); /* L_0 = K_0 * area */
      worsta = mx(worsta, fabsq(area - 4 * pi * sinq(a / 2) * sinq(a / 2)) / area);
    }
    report("zonal quad (n=64) vs closed form l<=2, 9 caps 1e-8..3.14, err/max|L|", (double)worst,
           1e-30);
    report("zonal quad L_0/K_0 vs cap area 4pi sin^2(a/2), max rel", (double)worsta, 1e-30);
  }
  /* 2. zonal quad vs the Legendre-difference form (eq. 9) evaluated in quad at moderate caps,
   *    where its cancellation (~1/a^2) costs at most 1e4 * 1e-34 */
  {
    static const double as[] = {0.01, 0.2, 0.7, 1.2, 1.5707963267948966, 2.0, 3.0};
    Q worst = 0;
    for (i = 0; i < 7; i++) {
      Q a = as[i], L[64], P[66], al = cosq(a), scale = 0;
      lref_cap_zh_q(64, a, L);
      lref_legendre_q(66, al, P);
      for (l = 0; l < 64; l++)
        scale = mx(scale, fabsq(L[l]));
      for (l = 0; l < 64; l++) {
        Q e = sqrtq(pi / (Q)(2 * l + 1)) * ((l ? P[l - 1] : 1) - P[l + 1]);
        worst = mx(worst, fabsq(L[l] - e) / scale);
      }
    }
    report("zonal quad vs eq.9 (quad), l<64, a in [0.01,3], max err / max|L|", (double)worst,
           1e-28);
  }
  /* 3. tiny cap limit: L_l -> pi s^2 K_l (point light) */
  {
    Q s = (Q)1e-8, L[64], worst = 0;
    lref_cap_zh_q(64, asinq(s), L);
    for (l = 0; l < 64; l++) {
      Q pt = pi * s * s * sqrtq((Q)(2 * l + 1) / (4 * pi));
      /* next term: relative -s^2 (l(l+1)/4 ... ) ~ 64*65/8*1e-16 ~ 5e-14 */
      worst = mx(worst, fabsq(L[l] - pt) / pt);
    }
    report("zonal quad s=1e-8 vs point-light limit pi s^2 K_l (expect ~5e-14)", (double)worst,
           1e-12);
  }
  /* 4. dL/da vs 5-point FD of the quadrature */
  {
    static const double as[] = {1e-6, 1e-3, 0.1, 0.8, 1.5};
    Q worst = 0;
    for (i = 0; i < 5; i++) {
      Q a = as[i], h = ldexpq(a, -22) / 64, dL[64], Lm2[64], Lm1[64], Lp1[64], Lp2[64], scale = 0;
      lref_cap_dzh_q(64, a, dL);
      lref_cap_zh_q(64, a - 2 * h, Lm2);
      lref_cap_zh_q(64, a - h, Lm1);
      lref_cap_zh_q(64, a + h, Lp1);
      lref_cap_zh_q(64, a + 2 * h, Lp2);
      for (l = 0; l < 64; l++)
        scale = mx(scale, fabsq(dL[l]));
      for (l = 0; l < 64; l++) {
        Q fd = (Lm2[l] - 8 * Lm1[l] + 8 * Lp1[l] - Lp2[l]) / (12 * h);
        worst = mx(worst, fabsq(fd - dL[l]) / scale);
      }
    }
    report("dL/da = 2piK_l P_l(cos a) sin a vs FD of quadrature, l<64, max/scale", (double)worst,
           1e-20);
  }
  /* 5. sphere light (rotated ZH) vs 2-D quadrature in the tilted frame, n = 8 */
  {
    static const double cfg[][7] = {{0.3, -0.2, 0.5, 0.4, 1.1, 2.0, -0.7},
                                    {0, 0, 0, 0.01, 0, 0, -3.0},
                                    {1, 2, 3, 0.9, 1.2, 2.1, 3.3},
                                    {0, 0, 0, 1.0, 0.3, -0.4, 1.00001}};
    Q worst = 0;
    for (i = 0; i < 4; i++) {
      Q c[3] = {cfg[i][0], cfg[i][1], cfg[i][2]}, r = cfg[i][3];
      Q x[3] = {cfg[i][4], cfg[i][5], cfg[i][6]}, A[64], B[64], scale = 0;
      lref_sphere_q(8, c, r, x, A);
      lref_sphere_quad2d_q(8, c, r, x, B);
      for (k = 0; k < 64; k++)
        scale = mx(scale, fabsq(A[k]));
      for (k = 0; k < 64; k++)
        worst = mx(worst, fabsq(A[k] - B[k]) / scale);
    }
    report("sphere light (rotated ZH) vs 2-D tilted-frame quadrature, n=8", (double)worst, 1e-30);
  }
  /* 6. FD gradient of the sphere light vs the analytic chain rule evaluated in quad
   *    (grad_x L_l^m = -sqrt(4pi/(2l+1)) L_l grad_d Y + 2pi Y P_l(alpha) s^2/(rho alpha) n,
   *    grad_d Y from shref's own FD at h = 2^-30 |d|): checks the FD step choice */
  {
    static const double cfg[][7] = {{0.3, -0.2, 0.5, 0.4, 1.1, 2.0, -0.7},
                                    {0, 0, 5, 0.5, 0, 0, 0},
                                    {0, 0, 0, 1.0, 0.3, -0.4, 1.00001},
                                    {0, 0, 0, 1e-4, 3, 4, 0}};
    int n = 16;
    Q worst = 0;
    for (i = 0; i < 4; i++) {
      Q c[3] = {cfg[i][0], cfg[i][1], cfg[i][2]}, r = cfg[i][3];
      Q x[3] = {cfg[i][4], cfg[i][5], cfg[i][6]}, d[3], rho, s, al, a, L[16], P[16];
      Q(*g)[3] = malloc(sizeof(Q) * 3 * 256), (*gy)[3] = malloc(sizeof(Q) * 3 * 256), Y[256];
      Q scale = 0;
      for (k = 0; k < 3; k++)
        d[k] = c[k] - x[k];
      rho = lref_norm3(d);
      s = r / rho;
      al = sqrtq((1 - s) * (1 + s));
      a = asinq(s);
      lref_cap_zh_q(n, a, L);
      lref_legendre_q(n, al, P);
      shref_grad_q(n, d, Y, gy);
      lref_sphere_grad_q(n, c, r, x, g);
      for (k = 0; k < 256; k++)
        scale = mx(scale, mx(fabsq(g[k][0]), mx(fabsq(g[k][1]), fabsq(g[k][2]))));
      for (l = 0; l < n; l++) {
        int m;
        for (m = -l; m <= l; m++) {
          int id = l * (l + 1) + m, j;
          for (j = 0; j < 3; j++) {
            Q an = -sqrtq(4 * pi / (Q)(2 * l + 1)) * L[l] * gy[id][j] +
                   2 * pi * Y[id] * P[l] * s * s / (rho * al) * (d[j] / rho);
            worst = mx(worst, fabsq(an - g[id][j]) / scale);
          }
        }
      }
      free(g);
      free(gy);
    }
    report("sphere-light FD gradient vs analytic chain rule in quad, n=16, 4 cfgs", (double)worst,
           1e-18);
  }
  /* 7. solid angle: octant, docs/derivations.md's close point, hemisphere limit, far triangle */
  {
    Q p[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, x[3] = {0, 0, 0};
    Q o1 = lref_tri_solid_angle_q(p, x), o2 = lref_tri_solid_angle_unit_q(p, x);
    report("octant: quadrature vs pi/2, rel", (double)(fabsq(o1 - pi / 2) / (pi / 2)), 1e-30);
    report("octant: unit-vector form vs pi/2, rel", (double)(fabsq(o2 - pi / 2) / (pi / 2)), 1e-32);
  }
  {
    Q p[3][3] = {{0.1, 0.0, 0.0}, {1.3, 0.2, 0.0}, {0.4, 1.1, 0.0}}, x[3] = {0.55, 0.45, 0.05};
    Q o1 = lref_tri_solid_angle_q(p, x), o2 = lref_tri_solid_angle_unit_q(p, x);
    printf("  h=0.05 point: quadrature %.12f  unit-vector %.12f (docs/derivations.md 5.536260)\n",
           (double)o1, (double)o2);
    report("h=0.05 above triangle: quadrature vs unit-vector form, rel",
           (double)(fabsq(o1 - o2) / o2), 1e-30);
    report("h=0.05: vs docs/derivations.md 5.536260 (6 decimals)", fabs((double)o1 - 5.536260),
           5e-7);
  }
  {
    /* equilateral triangle of inradius 1 centred at 0, x at height h: Omega -> 2pi - O(h) */
    Q s3 = sqrtq((Q)3), p[3][3] = {{2, 0, 0}, {-1, s3, 0}, {-1, -s3, 0}};
    static const double hs[] = {1e-1, 1e-3, 1e-6, 1e-9};
    for (i = 0; i < 4; i++) {
      Q x[3] = {0, 0, hs[i]}, o1 = lref_tri_solid_angle_q(p, x),
        o2 = lref_tri_solid_angle_unit_q(p, x);
      snprintf(buf, sizeof buf, "hemisphere limit h=%.0e: quad vs unit rel (2pi-Omega = %.3e)",
               hs[i], (double)(2 * pi - o1));
      report(buf, (double)(fabsq(o1 - o2) / o2), 1e-28);
    }
  }
  {
    Q p[3][3] = {{1000.1, -500.0, 20.0}, {1001.3, -499.8, 20.0}, {1000.4, -498.9, 20.0}}, x[3];
    Q dir[3] = {0.2, 0.3, 1.0}, nd = lref_norm3(dir), o1, o2;
    for (k = 0; k < 3; k++)
      x[k] = (Q)(float)((k == 0 ? 1000.3 : k == 1 ? -500.2 : 20.0) + (double)(dir[k] / nd) * 1e4);
    o1 = lref_tri_solid_angle_q(p, x);
    o2 = lref_tri_solid_angle_unit_q(p, x);
    printf("  distance 1e4: Omega = %.6e\n", (double)o1);
    report("distance 1e4, offset 1e3: quadrature vs unit-vector form, rel",
           (double)(fabsq(o1 - o2) / o2), 1e-24);
  }
  /* 8. triangle SH projection: closed surfaces around x integrate Y to sqrt(4pi) delta_{i0} */
  {
    Q v[4][3] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    static const double xs[][3] = {{0.1, -0.2, 0.05}, {0.0, 0.0, 0.0}, {0.3, 0.3, 0.3 - 1e-3}};
    int f, n = 8, j;
    for (j = 0; j < 3; j++) {
      Q acc[64], o[64], worst = 0, x[3] = {xs[j][0], xs[j][1], xs[j][2]};
      long nt = 0;
      for (k = 0; k < 64; k++)
        acc[k] = 0;
      for (f = 0; f < 4; f++) {
        Q p[3][3];
        int q = 0, t;
        for (t = 0; t < 4; t++)
          if (t != f) {
            for (k = 0; k < 3; k++)
              p[q][k] = v[t][k];
            q++;
          }
        nt += lref_tri_sh_q(n, p, x, o);
        for (k = 0; k < 64; k++)
          acc[k] += o[k];
      }
      for (k = 0; k < 64; k++)
        worst = mx(worst, fabsq(acc[k] - (k == 0 ? sqrtq(4 * pi) : 0)));
      snprintf(buf, sizeof buf,
               "tetrahedron around x #%d: sum of 4 face projections - sqrt(4pi)d_i0 (%ld leaves)",
               j, nt);
      report(buf, (double)worst, 1e-28);
    }
  }
  /* 9. triangle-as-sphere in quad at a far distance approaches the exact projection */
  {
    Q p[3][3] = {{0, 0, 0}, {1, 0, 0}, {0.5, 0.8660254037844386, 0}}, x[3] = {30, 40, 500};
    Q A[25], B[25], num = 0, den = 0;
    lref_tri_sh_q(5, p, x, A);
    lref_tri_as_sphere_q(5, p, x, B);
    for (k = 0; k < 25; k++) {
      num += (A[k] - B[k]) * (A[k] - B[k]);
      den += A[k] * A[k];
    }
    printf("  triangle-as-sphere rel L2 at d/sqrt(A) ~ 770: %.3e (modelling error, O((A/d^2)))\n",
           (double)sqrtq(num / den));
  }
  printf("%s (%d failures)\n", nfail ? "SELFTEST FAILED" : "selftest ok", nfail);
  printf("%d passed, %d failed\n", nfail ? 0 : 1, nfail ? 1 : 0);
  return nfail != 0;
}
