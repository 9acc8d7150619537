/* matrix_b.c - a second TU using the kernels without the implementation (linked with matrix_a). */
#include "../shlight.h"

#include <math.h>

int matrix_b(void);

int matrix_b(void) {
  float d[3] = {0.0f, 0.0f, 1.0f}, y[16];
  shl_sh_eval(4, d, y);
  return fabs((double)y[2] - 0.48860251) < 1e-6 ? 0 : 1;
}
