/* fuzz_basis.c - libFuzzer target for shlight's SH basis and gradient functions.
 *
 * Input bytes: [0] n as a signed byte (-128..127: covers n < 1, 1..64 and n > 64, clamped);
 * [1..12] three little-endian floats d (any bit pattern: NaN, Inf, denormals, zero, huge);
 * [13] optional batch count (byte % 20, 0..19: below, at and above the SIMD widths);
 * missing bytes read as zero.  Every output buffer is malloc'ed with exactly the size the
 * documented n (clamped) implies, so ASan flags any write (or read) beyond it.
 *
 * Checked (failures print the input and abort(), or count in replay mode):
 *  - no out-of-bounds access (ASan), no UB (UBSan);
 *  - for finite non-zero d with |d| in [1e-20, 1e20]: every output of shl_sh_eval_grad,
 *    shl_sh_eval_accurate, shl_sh_eval_grad_spherical finite, and the values bounded by
 *    Unsold's |Y_lm| <= sqrt((2l+1)/4pi); shl_sh_grad_from_spherical finite where
 *    sin(theta) >= 1e-6 (it divides by sin(theta)) and exactly 0 at an exact pole;
 *    shl_sh_eval and shl_sh_eval_batch finite on the direction normalised (in double);
 *  - zero / NaN / Inf d (documented): shl_sh_eval_grad and shl_sh_eval_accurate give finite
 *    values and an all-zero gradient;
 *  - shl_sh_eval and the batch on the raw d only run (unit d is their documented domain).
 *
 * Build and run with libFuzzer (clang 14):
 *   clang -std=c99 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
 *     -o build/tests/fuzz_basis tests/fuzz_basis.c -lm
 *   build/tests/fuzz_basis -max_len=16 -max_total_time=60 corpus_work/ tests/corpus/basis/
 * (copy new interesting inputs into tests/corpus/basis/ to keep them).  Without libFuzzer,
 * replay the corpus with tests/fuzz_replay.c (see tests/tests.mk):
 *   clang -std=c99 -g -O1 -fsanitize=address,undefined -o build/tests/fuzz_replay_asan \
 *     tests/fuzz_replay.c tests/fuzz_basis.c -lm && build/tests/fuzz_replay_asan tests/corpus/basis
 */
/* Release-mode contract (n out of range is clamped, not asserted): */
#define SHLIGHT_IMPLEMENTATION
#include "../shlight.h"
#include "ref/published.h" /* the published forms, for comparison */

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef SHLIGHT_MAX_BANDS
#define SHLIGHT_MAX_BANDS 64
#endif

/* Replay mode (fuzz_replay.c sets it): count failures instead of aborting. */
int fuzz_basis_soft_fail;
long fuzz_basis_failures;

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void fuzz_fail(const char *what, int n, const float d[3]) {
  uint32_t b[3];
  memcpy(b, d, sizeof b);
  printf("FAIL fuzz_basis: %s (n=%d, d = %a %a %a = 0x%08x 0x%08x 0x%08x)\n", what, n, (double)d[0],
         (double)d[1], (double)d[2], (unsigned)b[0], (unsigned)b[1], (unsigned)b[2]);
  fflush(stdout);
  if (!fuzz_basis_soft_fail) abort();
  fuzz_basis_failures++;
}
#define FUZZ_CHECK(cond, what) \
  do { \
    if (!(cond)) fuzz_fail(what, n, d); \
  } while (0)

static float *alloc_f(size_t count) {
  /* exactly count floats; at least one byte so that a zero-size buffer still traps writes */
  size_t bytes = count ? count * sizeof(float) : 1;
  float *p = (float *)malloc(bytes);
  if (!p) abort();
  memset(p, 0, bytes);
  return p;
}

static int finite_all(const float *v, size_t count) {
  size_t i;
  for (i = 0; i < count; i++)
    if (!isfinite(v[i])) return 0;
  return 1;
}
/* Unsold: sum_m Y_lm^2 = (2l+1)/4pi, so |Y_lm| <= sqrt((2l+1)/4pi) (+ float slack). */
static int bounded(const float *y, int nb) {
  int l, m;
  for (l = 0; l < nb; l++) {
    double lim = sqrt((2.0 * l + 1.0) / (4.0 * 3.14159265358979323846)) * (1.0 + 1e-5) + 1e-6;
    for (m = -l; m <= l; m++)
      if (!(fabs((double)y[l * (l + 1) + m]) <= lim)) return 0;
  }
  return 1;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  uint8_t buf[30];
  int n, nb, count, j, degenerate, in_range;
  float d[3];
  size_t nn;
  double ad[3], r;
  memset(buf, 0, sizeof buf);
  memcpy(buf, data, size < sizeof buf ? size : sizeof buf);
  n = (int)(int8_t)buf[0];
  memcpy(d, buf + 1, sizeof d);
  count = (int)(buf[13] % 20);
  nb = n < 1 ? 0 : (n > SHLIGHT_MAX_BANDS ? SHLIGHT_MAX_BANDS : n);
  nn = (size_t)nb * (size_t)nb;

  ad[0] = (double)d[0];
  ad[1] = (double)d[1];
  ad[2] = (double)d[2];
  degenerate = !(isfinite(d[0]) && isfinite(d[1]) && isfinite(d[2])) ||
               (d[0] == 0.0f && d[1] == 0.0f && d[2] == 0.0f);
  r = degenerate ? 0.0 : sqrt(ad[0] * ad[0] + ad[1] * ad[1] + ad[2] * ad[2]);
  in_range = !degenerate && r >= 1e-20 && r <= 1e20;

  {
    float *y = alloc_f(nn), *g = alloc_f(3 * nn), *dt = alloc_f(nn), *dp = alloc_f(nn);
    float *g2 = alloc_f(3 * nn);
    float dn[3] = {0.0f, 0.0f, 1.0f};

    shl_sh_eval(n, d, y); /* raw input: only memory safety */

    if (!degenerate) { /* the unit direction, normalised in double then rounded */
      dn[0] = (float)(ad[0] / r);
      dn[1] = (float)(ad[1] / r);
      dn[2] = (float)(ad[2] / r);
      shl_sh_eval(n, dn, y);
      FUZZ_CHECK(finite_all(y, nn), "shl_sh_eval(unit d) non-finite");
    }

    shl_sh_eval_grad(n, d, y, (float(*)[3])g);
    if (in_range || degenerate) {
      FUZZ_CHECK(finite_all(y, nn) && bounded(y, nb), "shl_sh_eval_grad values");
      FUZZ_CHECK(finite_all(g, 3 * nn), "shl_sh_eval_grad gradient non-finite");
    }
    if (degenerate) {
      size_t i;
      int nz = 0;
      for (i = 0; i < 3 * nn; i++)
        nz += g[i] != 0.0f;
      FUZZ_CHECK(nz == 0, "shl_sh_eval_grad(degenerate d): gradient not zero");
    }

    shl_sh_eval_accurate(n, d, y);
    if (in_range || degenerate)
      FUZZ_CHECK(finite_all(y, nn) && bounded(y, nb), "shl_sh_eval_accurate values");

    shl_sh_eval_grad_spherical(n, d, y, dt, dp);
    if (in_range) {
      FUZZ_CHECK(finite_all(y, nn) && bounded(y, nb), "shl_sh_eval_grad_spherical values");
      FUZZ_CHECK(finite_all(dt, nn) && finite_all(dp, nn),
                 "shl_sh_eval_grad_spherical partials non-finite");
    }

    shl_sh_grad_from_spherical(n, d, dt, dp, (float(*)[3])g2);
    if (in_range) {
      double st = sqrt(ad[0] * ad[0] + ad[1] * ad[1]) / r;
      if (st >= 1e-6) FUZZ_CHECK(finite_all(g2, 3 * nn), "shl_sh_grad_from_spherical non-finite");
      if (d[0] == 0.0f && d[1] == 0.0f) {
        size_t i;
        int nz = 0;
        for (i = 0; i < 3 * nn; i++)
          nz += g2[i] != 0.0f;
        FUZZ_CHECK(nz == 0, "shl_sh_grad_from_spherical at the pole not 0");
      }
    }

    { /* batch: count lanes, raw (permuted / sign-flipped d) and unit */
      float *xs = alloc_f((size_t)count), *ys = alloc_f((size_t)count),
            *zs = alloc_f((size_t)count);
      float *out = alloc_f(nn * (size_t)count);
      for (j = 0; j < count; j++) {
        xs[j] = (j & 1) ? -d[j % 3] : d[j % 3];
        ys[j] = d[(j + 1) % 3];
        zs[j] = (j & 2) ? -d[(j + 2) % 3] : d[(j + 2) % 3];
      }
      shl_sh_eval_batch(n, count, xs, ys, zs, out);
      if (!degenerate) {
        for (j = 0; j < count; j++) {
          xs[j] = (j & 1) ? -dn[j % 3] : dn[j % 3];
          ys[j] = dn[(j + 1) % 3];
          zs[j] = (j & 2) ? -dn[(j + 2) % 3] : dn[(j + 2) % 3];
        }
        shl_sh_eval_batch(n, count, xs, ys, zs, out);
        FUZZ_CHECK(finite_all(out, nn * (size_t)count), "shl_sh_eval_batch(unit) non-finite");
      }
      free(xs);
      free(ys);
      free(zs);
      free(out);
    }
    /* >>zonal / >>light: bytes 14..29 are a light centre c and radius r (shading point x = d);
     * every output must be finite for every input, NaN and infinity included (documented:
     * zeros for r <= 0, NaN or non-finite positions; the surface limit inside the light) */
    {
      float c[3], rr, p2[3], om;
      memcpy(c, buf + 14, sizeof c);
      memcpy(&rr, buf + 26, sizeof rr);
      p2[0] = c[1];
      p2[1] = c[2];
      p2[2] = d[0];
      if (nb >= 1) {
        shl_sphere_light(n, d, c, rr, y);
        FUZZ_CHECK(finite_all(y, nn), "shl_sphere_light non-finite");
        shl_sphere_light_grad(n, d, c, rr, y, (float(*)[3])g);
        FUZZ_CHECK(finite_all(y, nn) && finite_all(g, 3 * nn), "shl_sphere_light_grad non-finite");
        shl_triangle_light(n, d, c, p2, dn, y);
        FUZZ_CHECK(finite_all(y, nn), "shl_triangle_light non-finite");
        shl_triangle_light_grad(n, d, c, p2, dn, y, (float(*)[3])g);
        FUZZ_CHECK(finite_all(y, nn) && finite_all(g, 3 * nn),
                   "shl_triangle_light_grad non-finite");
        shl_zh_cap(n, rr, c[0], y);
        FUZZ_CHECK(finite_all(y, (size_t)nb), "shl_zh_cap non-finite");
      }
      om = shl_triangle_solid_angle(d, c, p2, dn);
      FUZZ_CHECK(isfinite(om), "shl_triangle_solid_angle non-finite");
    }
    free(y);
    free(g);
    free(dt);
    free(dp);
    free(g2);
  }
  return 0;
}
