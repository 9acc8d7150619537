/* test_rotate_portable.c - shl_sh_rotate's portable kernel alone (SHLIGHT_ROTATE_FAST 0: the
 * body the GLSL twin shares, for every n), in a translation unit of its own, so that
 * tests/test_rotate.c and bench/bench_rotate.c can hold the C-only small-n path to it. */
#define SHLIGHT_ROTATE_FAST 0
#include "../shlight.h"

void rotate_portable(int n, const float R[9], const float *sh, float *out_sh);
void rotate_portable(int n, const float R[9], const float *sh, float *out_sh) {
  shl_sh_rotate(n, R, sh, out_sh);
}
