/* hello_sh.c - project a small environment onto 3 bands of SH and shade a normal with it.
   Build and run: make example */
#define SHLIGHT_IMPLEMENTATION
#include "../shlight.h"

#include <stdio.h>

int main(void) {
  /* a "sky": a bright key light from above-right plus a dim uniform fill */
  const float key[3] = {0.48f, 0.0f, 0.8771545f}; /* unit direction of the key light */
  float sky[9], y[9], grad[9][3];
  float n_up[3] = {0.0f, 0.0f, 1.0f};
  int i;
  shl_sh_eval(3, key, sky); /* SH of a delta light = Y(direction) */
  for (i = 0; i < 9; ++i)
    sky[i] *= 2.0f;
  sky[0] += 0.5f * 3.5449077f; /* uniform radiance 0.5: coefficient 0.5 * sqrt(4 pi) */

  /* radiance reconstructed toward +z, and how fast it changes when the direction tilts */
  shl_sh_eval_grad(3, n_up, y, grad);
  {
    float L = 0.0f, gx = 0.0f, gy = 0.0f;
    for (i = 0; i < 9; ++i) {
      L += sky[i] * y[i];
      gx += sky[i] * grad[i][0];
      gy += sky[i] * grad[i][1];
    }
    printf("band-limited radiance toward +z: %.4f\n", (double)L);
    printf("its gradient along x, y:         %.4f %.4f\n", (double)gx, (double)gy);
  }
  printf("Y_1^1 at +x (Condon-Shortley: negative): %.6f\n",
         (double)(shl_sh_eval(2, (const float[3]){1.0f, 0.0f, 0.0f}, y), y[3]));
  return 0;
}
