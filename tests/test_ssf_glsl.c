/* test_ssf_glsl.c - the GLSL twin shlight_glsl/shl_ssf.glsl against the C kernels of >>ssf on
   llvmpipe (compute path, SHLIGHT_MAX_BANDS 8, n = 1..8 by item, 256 random items). GLSL runs
   the VPL weight, the normalisations and the lobe in float where C uses double, so real-valued
   outputs differ by float rounding: the tolerance is 2e-6 of each output's scale (the bound
   e_max = flux / (pi max(d^2, dmin^2)) of the VPL's weight times (|Y|max + 1) plus the prefill
   for its SH, e_max for its irradiance, sum |sh| for the SH irradiance); measured worst on
   llvmpipe 2.3e-7 (printed); the integer outputs (interleaving) and the 0/1 filter weight must be
   equal (the weight's inputs stay clear of its thresholds), and so must the VPL outputs of the
   degenerate items (x == y, flux 0: nothing added). Run from the repository root
   (tests/run.sh runs it). */
#include "../shlight.h"
#include "gl/glrun.h"
#include "tl.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define NI 256
#define NB 8
#define NN (NB * NB)
/* inputs: x, nx, ns, y, ny (15), flux, dmin, n (3), px, py, n_int, m_int, nvpl (5),
   p, np, q, nq (12), max_dist, min_cos (2), sh prefill (64) */
#define I_X 0
#define I_NX 3
#define I_NS 6
#define I_Y 9
#define I_NY 12
#define I_FLUX 15
#define I_DMIN 16
#define I_N 17
#define I_PX 18
#define I_P 23
#define I_MD 35
#define I_SH 37
#define IN (I_SH + NN)
/* outputs: vpl_sh (64), vpl_irradiance, irradiance of the prefill, count, first, stride,
   weight */
#define O_S NN
#define NS 6
#define OUTS (O_S + NS)

static unsigned int st = 4004u;
static float rndf(void) {
  st = st * 1664525u + 1013904223u;
  return (float)(st >> 8) * (1.0f / 16777216.0f);
}
static float rnds(void) {
  return 2.0f * rndf() - 1.0f;
}

static void c_item(const float *p, float *o) {
  int k, r[2], n = (int)p[I_N];
  float sh[NN];
  for (k = 0; k < NN; ++k)
    sh[k] = p[I_SH + k];
  shl_ssf_vpl_sh(n, p + I_X, p + I_NX, p + I_Y, p + I_NY, p[I_FLUX], p[I_DMIN], sh);
  for (k = 0; k < NN; ++k)
    o[k] = k < n * n ? sh[k] : 0.0f;
  o[O_S + 0] =
      shl_ssf_vpl_irradiance(p + I_X, p + I_NX, p + I_NS, p + I_Y, p + I_NY, p[I_FLUX], p[I_DMIN]);
  o[O_S + 1] = shl_ssf_irradiance(n, p + I_SH, p + I_NS);
  o[O_S + 2] = (float)shl_ssf_interleave((int)p[I_PX], (int)p[I_PX + 1], (int)p[I_PX + 2],
                                         (int)p[I_PX + 3], (int)p[I_PX + 4], r);
  o[O_S + 3] = (float)r[0];
  o[O_S + 4] = (float)r[1];
  o[O_S + 5] = shl_ssf_weight(p + I_P, p + I_P + 3, p + I_P + 6, p + I_P + 9, p[I_MD], p[I_MD + 1]);
}

/* 0/1 weight inputs clear of the thresholds: plane distances and cosine at least 1 % away */
static int weight_clear(const float *p) {
  double a[3], b[3], d[3], la = 0, lb = 0, c = 0, da = 0, db = 0, md = p[I_MD], mc = p[I_MD + 1];
  int k;
  for (k = 0; k < 3; ++k) {
    a[k] = p[I_P + 3 + k];
    b[k] = p[I_P + 9 + k];
    d[k] = (double)p[I_P + 6 + k] - (double)p[I_P + k];
    la += a[k] * a[k];
    lb += b[k] * b[k];
  }
  for (k = 0; k < 3; ++k) {
    c += a[k] * b[k] / sqrt(la * lb);
    da += a[k] * d[k] / sqrt(la);
    db += b[k] * d[k] / sqrt(lb);
  }
  return fabs(c - mc) > 0.01 && fabs(fabs(da) - md) > 0.01 * md && fabs(fabs(db) - md) > 0.01 * md;
}

static void test_glsl_ssf(void) {
  static float in[NI * IN], out[NI * OUTS], ref[NI * OUTS];
  const char *files[7] = {"shlight_glsl/shl_prelude.glsl",  "shlight_glsl/shl_basis.glsl",
                          "shlight_glsl/shl_gradient.glsl", "shlight_glsl/shl_zonal.glsl",
                          "shlight_glsl/shl_light.glsl",    "shlight_glsl/shl_brdf.glsl",
                          "shlight_glsl/shl_ssf.glsl"};
  const char *defines = "#define SHLIGHT_MAX_BANDS 8\n";
  const char *main_src =
      "vec3 v3(int j) { return vec3(in_float(j), in_float(j + 1), in_float(j + 2)); }\n"
      "void glrun_main(int item) {\n"
      "  float sh[SHLIGHT_MAX_COEFFS];\n"
      "  float pre[SHLIGHT_MAX_COEFFS];\n"
      "  int r[2];\n"
      "  int k;\n"
      "  int n = int(in_float(17));\n"
      "  for (k = 0; k < 64; ++k) { sh[k] = in_float(37 + k); pre[k] = sh[k]; }\n"
      "  shl_ssf_vpl_sh(n, v3(0), v3(3), v3(9), v3(12), in_float(15), in_float(16), sh);\n"
      "  for (k = 0; k < 64; ++k) out_float(k, k < n * n ? sh[k] : 0.0);\n"
      "  out_float(64, shl_ssf_vpl_irradiance(v3(0), v3(3), v3(6), v3(9), v3(12), in_float(15), "
      "in_float(16)));\n"
      "  out_float(65, shl_ssf_irradiance(n, pre, v3(6)));\n"
      "  out_float(66, float(shl_ssf_interleave(int(in_float(18)), int(in_float(19)), "
      "int(in_float(20)), int(in_float(21)), int(in_float(22)), r)));\n"
      "  out_float(67, float(r[0]));\n"
      "  out_float(68, float(r[1]));\n"
      "  out_float(69, shl_ssf_weight(v3(23), v3(26), v3(29), v3(32), in_float(35), "
      "in_float(36)));\n"
      "}\n";
  static const char *snames[NS] = {"vpl_irradiance", "irradiance", "count",
                                   "first",          "stride",     "weight"};
  double worst[1 + NS];
  int i, k, bad = 0, ones = 0;
  memset(worst, 0, sizeof worst);
  for (i = 0; i < NI; ++i) {
    float *p = in + i * IN;
    memset(p, 0, sizeof(float) * IN);
    for (k = 0; k < 15; ++k)
      p[k] = 2.0f * rnds();
    for (k = 0; k < 3; ++k) { /* mostly facing each other; ns near nx */
      p[I_NY + k] += 0.8f * (p[I_X + k] - p[I_Y + k]);
      p[I_NX + k] += 0.8f * (p[I_Y + k] - p[I_X + k]);
      p[I_NS + k] = p[I_NX + k] + 0.6f * rnds();
    }
    if (i % 16 == 5) p[I_NX] = p[I_NX + 1] = p[I_NX + 2] = 0.0f;  /* horizon test off */
    if (i % 16 == 7) memcpy(p + I_Y, p + I_X, 3 * sizeof(float)); /* x == y: nothing */
    if (i % 16 == 9) p[I_NY] = p[I_NY + 1] = p[I_NY + 2] = 0.0f;  /* ny = 0: +z */
    p[I_FLUX] = (i % 16 == 11) ? 0.0f : 0.1f + 5.0f * rndf();     /* flux 0: nothing */
    p[I_DMIN] = (i % 3 == 0) ? 0.0f : 0.6f * rndf();
    p[I_N] = (float)(1 + i % NB);
    p[I_PX] = (float)((int)(200.0f * rnds()));
    p[I_PX + 1] = (float)((int)(200.0f * rnds()));
    p[I_PX + 2] = (float)(1 + i % 5);
    p[I_PX + 3] = (float)(1 + (i / 5) % 4);
    p[I_PX + 4] = (float)((int)(40.0f * rndf()));
    do {
      for (k = 0; k < 6; ++k)
        p[I_P + k] = rnds();
      for (k = 0; k < 3; ++k) {
        p[I_P + 6 + k] = p[I_P + k] + 0.3f * rnds();
        p[I_P + 9 + k] = p[I_P + 3 + k] + 0.5f * rnds();
      }
      p[I_MD] = 0.02f + 0.2f * rndf();
      p[I_MD + 1] = 0.5f + 0.45f * rndf();
    } while (!weight_clear(p));
    for (k = 0; k < NN; ++k)
      p[I_SH + k] = rnds();
    c_item(p, ref + i * OUTS);
  }
  TL_CHECK(glrun_compute(defines, files, 7, main_src, in, (size_t)NI * IN, out, (size_t)NI * OUTS,
                         NI) == 0,
           "glrun: %s", glrun_last_log());
  for (i = 0; i < NI; ++i) {
    const float *p = in + i * IN;
    double w[3], e, scale_sh, sumsh = 0;
    int n = (int)p[I_N], degenerate;
    /* e_max >= e (cos <= 1); |Y_i| <= sqrt((2l+1)/4pi) <= 1.1 for l < 8 */
    for (k = 0; k < 3; ++k)
      w[k] = (double)p[I_Y + k] - (double)p[I_X + k];
    e = (double)p[I_FLUX] / (3.141592653589793 * fmax(w[0] * w[0] + w[1] * w[1] + w[2] * w[2],
                                                      (double)p[I_DMIN] * (double)p[I_DMIN]));
    scale_sh = e * 2.1 + 1.0; /* plus the prefill, |pre| < 1 */
    degenerate = i % 16 == 7 || i % 16 == 11;
    for (k = 0; k < n * n; ++k)
      sumsh += fabs((double)p[I_SH + k]);
    for (k = 0; k < OUTS; ++k) {
      double r = (double)ref[i * OUTS + k], g = (double)out[i * OUTS + k], scale = 1.0, err;
      int grp = k < O_S ? 0 : 1 + (k - O_S);
      if (k < O_S)
        scale = scale_sh;
      else if (k == O_S)
        scale = e;
      else if (k == O_S + 1)
        scale = sumsh;
      err = fabs(g - r) / scale;
      if (!(err <= worst[grp])) worst[grp] = err;
      /* integers, and the VPL outputs of the degenerate items (nothing added: exact) */
      if ((k >= O_S + 2 || (k <= O_S && degenerate)) ? g != r : !(err <= 2e-6)) {
        if (bad < 10) printf("  item %d output %d: GLSL %.9g C %.9g\n", i, k, g, r);
        bad++;
      }
    }
    ones += ref[i * OUTS + O_S + 5] == 1.0f;
  }
  printf("  %s: max |GLSL - C| / scale: vpl_sh %.2g", glrun_renderer(), worst[0]);
  for (k = 0; k < NS; ++k)
    printf(", %s %.2g", snames[k], worst[1 + k]);
  printf(" (%d of %d weights 1)\n", ones, NI);
  TL_CHECK(bad == 0, "%d outputs differ beyond 2e-6 of their scale (integers: at all)", bad);
  TL_CHECK(ones > NI / 8 && ones < NI - NI / 8, "weights too one-sided (%d of %d are 1)", ones, NI);
}

int main(void) {
  TL_RUN(test_glsl_ssf);
  glrun_close();
  return tl_summary();
}
