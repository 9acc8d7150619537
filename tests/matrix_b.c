/* matrix_b.c - a second TU using the kernels without the implementation (linked with matrix_a). */
#include "../shlight.h"

#include <math.h>

int matrix_b(void);

int matrix_b(void) {
  float d[3] = {0.0f, 0.0f, 1.0f}, y[16], tab[2 * 4 * 4], f[4];
  shl_brdf_table t = {2, 4, 1, 0, tab}; /* >>brdftab: CPU part from the other TU, kernel here */
  shl_brdf_params b = {SHLIGHT_BRDF_LAMBERT, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f};
  shl_sh_eval(4, d, y);
  if (shl_brdf_table_build(&t, &b, 4, NULL) != SHLIGHT_OK) return 1;
  shl_brdf_table_lookup(2, 4, 1, 0, tab, d, f);
  if (fabs((double)f[0] - 0.28209479) > 1e-6) return 1; /* Lambert: sqrt(pi)/2 / pi */
  return fabs((double)y[2] - 0.48860251) < 1e-6 ? 0 : 1;
}
