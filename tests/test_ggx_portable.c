/* test_ggx_portable.c - shl_polygon_ggx and shl_polygon_beckmann with the portable edge kernel
 * (SHLIGHT_NO_SIMD: shli_ggx_side, the GLSL twin's body), in a translation unit of its own, so
 * that tests/test_ggx_lanes.c can hold the C-only edge lanes to it. */
#define SHLIGHT_NO_SIMD
#include "../shlight.h"

float ggx_portable(const float (*v)[3], int nv, const float nrm[3], const float view[3],
                   float alpha, int ndf);
float ggx_portable(const float (*v)[3], int nv, const float nrm[3], const float view[3],
                   float alpha, int ndf) {
  return ndf == 0 ? shl_polygon_ggx(v, nv, nrm, view, alpha)
                  : shl_polygon_beckmann(v, nv, nrm, view, alpha);
}
