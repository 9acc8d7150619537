/* test_simd_novl.c - the AVX-512F kernels that run where AVX-512VL is missing.
 *
 * Built with -march=native -mno-avx512vl (tests/tests.mk): on an AVX-512 machine shl_sh_eval
 * then takes the 512-bit across-m core (shli_sh_eval_avx512_16, n = 7..16) and the scalar
 * Horner forms for n <= 6 instead of the 256-bit kernels a -march=native build selects, and
 * shl_sh_eval_grad those values (from its rsqrt14 prologue) before the 512-bit gradient pass;
 * CI's machine has VL, so without this build those paths
 * would compile but never run. Without AVX-512 the build selects the portable paths and the
 * test checks those. Reference: binary128 (tests/ref/shref.h, theta/phi formulation, shares
 * nothing with the kernels). Bounds: the float targets (n <= 4: 3e-7, n = 16: 2e-6)
 * interpolated linearly in n between, and 1e-5 of max|grad| for the gradient; measured in a
 * comment. ~2.5 s. */
#define SHLIGHT_IMPLEMENTATION
#include "../shlight.h"
#include "ref/shref.h"
#include "tl.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>

static uint64_t st = 0x4e6f564cu;
static double u01(void) {
  uint64_t z = (st += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return (double)((z ^ (z >> 31)) >> 11) * (1.0 / 9007199254740992.0);
}

/* direction k of the sample: random unit, near-pole (theta 1e-7..1e-2, both poles), exact
   poles, then the same scaled by a factor in [0.1, 10] for the gradient */
#define NDIR 400
static void direction(int k, float d[3]) {
  double x, y, z, r;
  if (k < 300) {
    z = 2.0 * u01() - 1.0;
    r = 6.283185307179586 * u01();
    x = sqrt(1.0 - z * z) * cos(r);
    y = sqrt(1.0 - z * z) * sin(r);
  } else if (k < 398) {
    double th = pow(10.0, -7.0 + 5.0 * u01()), ph = 6.283185307179586 * u01();
    x = sin(th) * cos(ph);
    y = sin(th) * sin(ph);
    z = (k & 1 ? -1.0 : 1.0) * cos(th);
  } else {
    x = 0.0;
    y = 0.0;
    z = k == 398 ? 1.0 : -1.0;
  }
  r = sqrt(x * x + y * y + z * z);
  d[0] = (float)(x / r);
  d[1] = (float)(y / r);
  d[2] = (float)(z / r);
}

static void test_novl_paths(void) {
  static float yv[256], yg[256], g[256][3];
  static double ry[256], rg[256][3];
  int n, k, i, c;
  for (n = 1; n <= 16; ++n) {
    double ev = 0.0, eg = 0.0, gmax = 0.0, ey = 0.0;
    double tol = n <= 4 ? 3e-7 : 3e-7 + (2e-6 - 3e-7) * (n - 4) / 12.0;
    for (k = 0; k < NDIR; ++k) {
      float d[3], ds[3];
      double s = pow(10.0, -1.0 + 2.0 * u01());
      direction(k, d);
      shl_sh_eval(n, d, yv);
      shref_eval_d(n, d, ry);
      for (i = 0; i < n * n; ++i) {
        ev = fmax(ev, fabs((double)yv[i] - ry[i]));
      }
      for (c = 0; c < 3; ++c) {
        ds[c] = (float)((double)d[c] * s);
      }
      shl_sh_eval_grad(n, ds, yg, g);
      shref_grad_d(n, ds, ry, rg);
      for (i = 0; i < n * n; ++i) {
        ey = fmax(ey, fabs((double)yg[i] - ry[i]));
        for (c = 0; c < 3; ++c) {
          eg = fmax(eg, fabs((double)g[i][c] - rg[i][c]) * s);
          gmax = fmax(gmax, fabs(rg[i][c]) * s);
        }
      }
    }
    /* measured (Zen 4, -march=native -mno-avx512vl): shl_sh_eval n = 4 1.9e-7, 10 5.8e-7,
       16 1.3e-6; gradient / max|grad| 3.3e-7, 4.9e-7, 8.4e-7 */
    TL_CHECK(ev <= tol, "shl_sh_eval vs binary128, n = %d: %.3g > %.3g", n, ev, tol);
    TL_CHECK(ey <= tol, "shl_sh_eval_grad values vs binary128, n = %d: %.3g > %.3g", n, ey, tol);
    /* n = 1: the gradient is 0 (the reference's finite differences give ~1e-26) */
    TL_CHECK(eg <= 1e-5 * gmax || eg <= 1e-20, "shl_sh_eval_grad gradient, n = %d: %.3g of max", n,
             gmax > 0.0 ? eg / gmax : eg);
    if (n == 4 || n == 10 || n == 16) {
      printf("n = %2d: values %.2e, grad values %.2e, gradient %.2e of max|grad|\n", n, ev, ey,
             gmax > 0.0 ? eg / gmax : eg);
    }
  }
#if defined(__AVX512F__) && !defined(__AVX512VL__)
  printf("AVX-512F without VL: the 512-bit across-m core and the gradient pass ran\n");
#else
  printf("no AVX-512F-only build here: the portable or 256-bit paths ran\n");
#endif
}

int main(void) {
  TL_RUN(test_novl_paths);
  return tl_summary();
}
