/* solid_angle_float.c - why the GLSL shl_triangle_solid_angle differs from C .
 * A float twin of the C kernel (the same formula, shli_real = float, no contraction, the own
 * atan2 in float), i.e. what llvmpipe runs, against binary128 at the same float inputs, on the
 * configurations of tests/test_glsl.c (make_lights). Prints, over N configurations:
 *  - max |Omega_float - Omega| / (A / d^2), the test's face-on scale, and the same with only
 *    N, only D or only the atan2 in float (the rest in binary128): which part loses;
 *  - the floor of any float evaluation that forms R_i = p_i - x in float: Omega in binary128
 *    at the float-rounded R_i (and e_i = p_i - p0 for N, as the kernel does);
 *  - max |Omega_float - Omega| / (u (|Omega| + 2 (|D| EN + |N| ED) / (N^2 + D^2))): the error
 *    against the a-priori float condition of 2 atan2(N, D) (EN = |R0||e1||e2|, ED = the sum
 *    of the magnitudes of D's four terms), the bound tests/test_glsl.c asserts.
 * Build and run: make bench-solid-float [SOLID_N=2000000]   (gcc, -ffp-contract=off) */
#include <math.h>
#include <quadmath.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

typedef __float128 Q;
static uint64_t rs = 0x5eed1234u;
static double rnd(void) {
  uint64_t z = (rs += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return (double)((z ^ (z >> 31)) >> 11) * (1.0 / 9007199254740992.0);
}
/* shli_atan2r of shlight.h with shli_real = float */
static float atan2_f(float y, float x) {
  float ay = fabsf(y), ax = fabsf(x), t, t2, a;
  if (!(ax > 0.0f || ay > 0.0f)) return 0.0f;
  t = ay > ax ? ax / ay : ay / ax;
  t = t / (1.0f + sqrtf(1.0f + t * t));
  t = t / (1.0f + sqrtf(1.0f + t * t));
  t2 = t * t;
  a = -0.066666666666666667f;
  a = 0.076923076923076923f + t2 * a;
  a = -0.090909090909090909f + t2 * a;
  a = 0.11111111111111111f + t2 * a;
  a = -0.14285714285714286f + t2 * a;
  a = 0.2f + t2 * a;
  a = -0.33333333333333333f + t2 * a;
  a = 4.0f * (t + t * (t2 * a));
  if (ay > ax) a = 1.5707963267948966f - a;
  if (x < 0.0f) a = 3.1415926535897932f - a;
  if (y < 0.0f) a = -a;
  return a;
}
static float dotf(const float *a, const float *b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
static Q dotq(const Q *a, const Q *b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
/* N and D of shl_triangle_solid_angle; float twin (kind 0) or binary128 at the exact
   differences (kind 1) or at the float-rounded differences (kind 2) */
static void nd_f(const float *x, const float *p0, const float *p1, const float *p2, float *n,
                 float *d) {
  float a[3], b[3], c[3], u[3], v[3], la, lb, lc;
  int k;
  for (k = 0; k < 3; ++k) {
    a[k] = p0[k] - x[k], b[k] = p1[k] - x[k], c[k] = p2[k] - x[k];
    u[k] = p1[k] - p0[k], v[k] = p2[k] - p0[k];
  }
  la = sqrtf(dotf(a, a)), lb = sqrtf(dotf(b, b)), lc = sqrtf(dotf(c, c));
  *n = a[0] * (u[1] * v[2] - u[2] * v[1]) + a[1] * (u[2] * v[0] - u[0] * v[2]) +
       a[2] * (u[0] * v[1] - u[1] * v[0]);
  *d = la * lb * lc + dotf(a, b) * lc + dotf(a, c) * lb + dotf(b, c) * la;
}
static void nd_q(const float *x, const float *p0, const float *p1, const float *p2, int rnd32, Q *n,
                 Q *d) {
  Q a[3], b[3], c[3], u[3], v[3], la, lb, lc;
  int k;
  for (k = 0; k < 3; ++k) {
    a[k] = (Q)p0[k] - x[k], b[k] = (Q)p1[k] - x[k], c[k] = (Q)p2[k] - x[k];
    u[k] = (Q)p1[k] - p0[k], v[k] = (Q)p2[k] - p0[k];
    if (rnd32) {
      a[k] = (float)a[k], b[k] = (float)b[k], c[k] = (float)c[k];
      u[k] = (float)u[k], v[k] = (float)v[k];
    }
  }
  la = sqrtq(dotq(a, a)), lb = sqrtq(dotq(b, b)), lc = sqrtq(dotq(c, c));
  *n = a[0] * (u[1] * v[2] - u[2] * v[1]) + a[1] * (u[2] * v[0] - u[0] * v[2]) +
       a[2] * (u[0] * v[1] - u[1] * v[0]);
  *d = la * lb * lc + dotq(a, b) * lc + dotq(a, c) * lb + dotq(b, c) * la;
}
int main(int argc, char **argv) {
  long i, nc = argc > 1 ? atol(argv[1]) : 200000;
  int k;
  double ef = 0, en = 0, ed = 0, ea = 0, er = 0, ec = 0;
  for (i = 0; i < nc; ++i) {
    float q[16], nf, df;
    double r = 0.01 + 0.5 * rnd(), dist = r * (1.05 + 20.0 * rnd() * rnd());
    double th = acos(2.0 * rnd() - 1.0), ph = 6.283185307179586 * rnd();
    double e1[3], e2[3], cr[3], cen[3], d2 = 0, sc, om, mn, md, cnd, l0, l1, l2, dab, dac, dbc;
    Q nq, dq, nr, dr;
    const float *x = q, *p0 = q + 3, *p1 = q + 8, *p2 = q + 11;
    for (k = 0; k < 3; ++k)
      q[k] = (float)(2.0 * rnd() - 1.0);
    q[3] = q[0] + (float)(dist * sin(th) * cos(ph));
    q[4] = q[1] + (float)(dist * sin(th) * sin(ph));
    q[5] = q[2] + (float)(dist * cos(th));
    for (k = 8; k < 16; ++k)
      q[k] = q[3 + (k % 3)] + (float)(0.3 * (2.0 * rnd() - 1.0));
    for (k = 0; k < 3; ++k) {
      e1[k] = (double)p1[k] - p0[k], e2[k] = (double)p2[k] - p0[k];
      cen[k] = ((double)p0[k] + p1[k] + p2[k]) / 3.0 - x[k];
      d2 += cen[k] * cen[k];
    }
    cr[0] = e1[1] * e2[2] - e1[2] * e2[1];
    cr[1] = e1[2] * e2[0] - e1[0] * e2[2];
    cr[2] = e1[0] * e2[1] - e1[1] * e2[0];
    sc = 0.5 * sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]) / d2; /* face-on A / d^2 */
    nd_q(x, p0, p1, p2, 0, &nq, &dq);
    nd_q(x, p0, p1, p2, 1, &nr, &dr);
    nd_f(x, p0, p1, p2, &nf, &df);
    om = (double)(2 * atan2q(nq, dq));
    ef = fmax(ef, fabs(2.0 * (double)atan2_f(nf, df) - om) / sc);
    en = fmax(en, fabs((double)(2 * atan2q((Q)nf, dq)) - om) / sc);
    ed = fmax(ed, fabs((double)(2 * atan2q(nq, (Q)df)) - om) / sc);
    ea = fmax(ea, fabs(2.0 * (double)atan2_f((float)nq, (float)dq) - om) / sc);
    er = fmax(er, fabs((double)(2 * atan2q(nr, dr)) - om) / sc);
    /* the a-priori condition, in double */
    {
      double a[3], b[3], c[3];
      for (k = 0; k < 3; ++k)
        a[k] = (double)p0[k] - x[k], b[k] = (double)p1[k] - x[k], c[k] = (double)p2[k] - x[k];
      l0 = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
      l1 = sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
      l2 = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
      dab = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
      dac = a[0] * c[0] + a[1] * c[1] + a[2] * c[2];
      dbc = b[0] * c[0] + b[1] * c[1] + b[2] * c[2];
    }
    mn = l0 * sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]) *
         sqrt(e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2]);
    md = l0 * l1 * l2 + fabs(dab) * l2 + fabs(dac) * l1 + fabs(dbc) * l0;
    cnd = 5.9604644775390625e-8 *
          (fabs(om) + 2.0 * (fabs((double)dq) * mn + fabs((double)nq) * md) /
                          ((double)nq * (double)nq + (double)dq * (double)dq));
    ec = fmax(ec, fabs(2.0 * (double)atan2_f(nf, df) - om) / cnd);
  }
  printf("%ld configurations (tests/test_glsl.c make_lights), max |Omega - ref| / (A/d^2):\n"
         "  float twin %.3e; only N in float %.3e, only D %.3e, only the atan2 %.3e\n"
         "  floor: R_i, e_i rounded to float, the rest exact: %.3e\n"
         "  float twin / (u * float condition of 2 atan2(N, D)): %.3f\n",
         nc, ef, en, ed, ea, er, ec);
  return 0;
}
