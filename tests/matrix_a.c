/* matrix_a.c - compile-matrix TU: the implementation, plus the kernels, used from C and C++. */
#define SHLIGHT_IMPLEMENTATION
#include "../shlight.h"
#include "../shlight.h" /* included twice: the guards hold */

#include <math.h>
#include <stdio.h>

int matrix_b(void);

int main(void) {
  float d[3] = {0.0f, 0.6f, 0.8f}, y[64], g[64][3], xs[3] = {0.0f, 0.0f, 1.0f};
  float ys[3] = {0.6f, 0.0f, 0.0f}, zs[3] = {0.8f, 1.0f, 0.0f}, yb[3 * 64];
  shl_sh_eval(8, d, y);
  shl_sh_eval_grad(8, d, y, g);
  if (!(fabs((double)shl_sh_eval_dot_grad(8, y, d, g[0])) < 1e30)) return 1;
  shl_sh_eval_accurate(8, d, y);
  shl_sh_eval_batch(8, 3, xs, ys, zs, yb);
#ifndef MATRIX_ALONE
  if (matrix_b() != 0) return 1;
#endif
  /* Y_1^-1 = -sqrt(3/4pi) y */
  if (fabs((double)y[1] + 0.48860251 * 0.6) > 1e-6 || fabs((double)yb[3] - (double)y[1]) > 1e-6) {
    printf("matrix: wrong value\n");
    return 1;
  }
  return 0;
}
