/* bands_impl.c - shlight built with SHLIGHT_BY_BANDS 1, the kernel shapes of the GLSL twins
 * (the values' first columns and the gradient as loop bodies that shader compilers unroll),
 * linked into test_basis, which holds them to the C build's straight-line kernels. */
#define SHLIGHT_BY_BANDS 1
#define SHLIGHT_NO_SIMD
#define SHLIGHT_STATIC
#define SHLIGHT_IMPLEMENTATION
/* the light kernels' loop counters serve the C shape only */
#pragma GCC diagnostic ignored "-Wunused-variable"
#include "../shlight.h"

void bands_sh_core(int n, double x, double y, double z, double t, float sg, float *out_y);
void bands_sh_grad(int n, const float *y, float nx, float ny, float nz, float ir, float ib,
                   float (*out_grad)[3]);
float bands_sh_eval_dot_grad(int n, const float *sh, const float d[3], float out_grad[3]);

/* shli_sh_core of the GLSL shape */
void bands_sh_core(int n, double x, double y, double z, double t, float sg, float *out_y) {
  shli_sh_core(n, x, y, z, t, sg, out_y);
}

/* shli_sh_grad of the GLSL shape */
void bands_sh_grad(int n, const float *y, float nx, float ny, float nz, float ir, float ib,
                   float (*out_grad)[3]) {
  shli_sh_grad(n, y, nx, ny, nz, ir, ib, out_grad);
}

/* shl_sh_eval_dot_grad of the GLSL shape (the portable kernel, n <= 16) */
float bands_sh_eval_dot_grad(int n, const float *sh, const float d[3], float out_grad[3]) {
  return shl_sh_eval_dot_grad(n, sh, d, out_grad);
}
