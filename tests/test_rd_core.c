/* test_rd_core.c - shlrender's metrics and PNG writer against closed forms and an independent
 * decoder: RMSE/PSNR of a constant offset, SSIM of identical / inverted images, the mask, and a
 * PNG written here then decoded by tests/png_check.py (Python's zlib and crc32). */
#include "../render/rd.h"
#include "tl.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv) {
  rd_image a = rd_image_new(40, 24), b = rd_image_new(40, 24);
  int mask[40 * 24], i;
  rd_metrics m;
  for (i = 0; i < 40 * 24 * 3; i++) {
    a.rgb[i] = 0.25f + 0.5f * (float)((i * 37) % 101) / 100.0f; /* peak 0.75 */
    b.rgb[i] = a.rgb[i] + 0.01f;
  }
  for (i = 0; i < 40 * 24; i++)
    mask[i] = (i % 7 == 0) ? -1 : 0;
  m = rd_compare(&b, &a, NULL);
  TL_CHECK(fabs((double)(m.rmse) - (0.01)) <= 1e-7, "rmse of a constant offset: %.9g vs %.9g",
           (double)(m.rmse), (double)(0.01));
  TL_CHECK(fabs((double)(m.psnr) - (20.0 * log10(0.75 / 0.01))) <= 2e-4,
           "psnr of a constant offset: %.9g vs %.9g", (double)(m.psnr),
           (double)(20.0 * log10(0.75 / 0.01)));
  TL_CHECK(fabs((double)(m.maxrel) - (0.01 / 0.75)) <= 1e-6,
           "maxrel of a constant offset: %.9g vs %.9g", (double)(m.maxrel), (double)(0.01 / 0.75));
  m = rd_compare(&a, &a, mask);
  TL_CHECK(m.rmse == 0.0, "identical: rmse 0");
  TL_CHECK(isinf(m.psnr), "identical: psnr infinite");
  TL_CHECK(fabs((double)(m.ssim) - (1.0)) <= 1e-12, "identical: ssim 1: %.9g vs %.9g",
           (double)(m.ssim), (double)(1.0));
  for (i = 0; i < 40 * 24 * 3; i++)
    b.rgb[i] = 1.0f - a.rgb[i];
  m = rd_compare(&b, &a, mask);
  TL_CHECK(m.ssim < 0.5, "inverted: ssim < 0.5");
  b.rgb[5] = NAN;
  m = rd_compare(&b, &a, NULL);
  TL_CHECK(isinf(m.maxrel), "NaN pixel: maxrel infinite (never hidden)");
  if (argc > 1) {
    TL_CHECK(rd_png_write(argv[1], &a, 1.0f) == 0, "png written");
  }
  TL_CHECK(rd_png_write("/nonexistent/x.png", &b, 1.0f) != 0, "png: an unwritable path gives -1");
  rd_image_free(&a);
  rd_image_free(&b);
  return tl_summary();
}
