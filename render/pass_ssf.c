/* pass_ssf.c - instant global illumination with interleaved virtual point lights (VPLs) and the
 * screen-space SH filter of [SSF] (Segovia & Wald), against the same light filtered as
 * irradiance (classical IGI), through shlight's >>ssf kernels (C) and shl_ssf.glsl (GL).
 *
 * What is rendered. One-bounce indirect light only, unshadowed between the bounce and the
 * receiver (the seed's setting without the shadow rays): at a camera pixel x with geometric
 * normal n_g, shading normal n_s (the normal map's) and albedo kd(x),
 *   L(x) = kd(x) / pi * E(x),   E(x) = sum_j Phi_j max(0, n_j . -w) max(0, n_s . w) /
 *                                       (pi max(d^2, dmin^2))   over VPLs j with n_g . w >= 0
 * (w = (y_j - x) / d, d = |y_j - x|; the per-VPL term is shl_ssf_vpl_irradiance, its SH
 * shl_ssf_vpl_sh). Non-Lambert materials count with their diffuse part kd only. dmin, the VPL
 * clamp distance, is 0.05 of the scene's bounding-box diagonal (SHLIGHT_SSF_CLAMP=f sets the
 * fraction); the ground truth uses the same clamp.
 *
 * VPLs (spot_vpls). From the scene's first spot light (no spot: the pass emits nothing): its
 * reflective shadow map, rd_gbuffer_view from the light (eye c, axis n, fov_y = 2 angle, the
 * half-angle clamped to 85 degrees), N x N texels (16 x 16 = 256 VPLs; SHLIGHT_SSF_RSM=N). Texel
 * (i, j) is the square of pitch p = 2 tan(angle) / N about (sx, sy) on the image plane at unit
 * distance (rd_gbuffer_view's ray); its solid angle is exact for a plane rectangle,
 * F(x1, y1) - F(x0, y1) - F(x1, y0) + F(x0, y0), F(x, y) = atan(x y / sqrt(1 + x^2 + y^2)), and
 * only the part inside the cone (sx^2 + sy^2 <= tan^2 angle) is lit: texels on the cone's edge
 * are split into 8 x 8 sub-rectangles counted by their centres (so the lit flux is right at
 * every N, up to that sub-sampling). Flux: the spot's intensity I (rd_light.radiance) through the
 * texel's solid angle dw lands at distance d on the surface at y, footprint dA = d^2 dw / cos
 * theta_g (n_g, the geometric normal), irradiance E = I cos theta_s / d^2 (n_s: the normal map's),
 * reflected flux Phi = kd(y) E dA = kd(y) I dw cos theta_s / cos theta_g     (= kd(y) I dw without
 * a bump; cos theta_g is bounded below by 0.05, the grazing limit of the ratio). The VPL emits as a
 * cosine emitter about its geometric normal (a bumped floor does not light itself). Background
 * texels and texels outside the cone are VPLs of zero flux (kept, so that the interleaved sets
 * stay regular sub-lattices).
 * Interleaving: n_int x m_int = 4 x 4 sets; the VPL of texel (i, j) is stored at index
 * ((j / 4) (N / 4) + i / 4) 16 + (j mod 4) 4 + i mod 4 (the ordering of >>ssf), so set s of
 * shl_ssf_interleave is the 4 x 4 sub-lattice of the map at offset s (16 VPLs of the 256);
 * a pixel's set is weighted by 16 (the kernels' flux argument).
 *
 * Methods (each on "cpu", the C kernels, and "gl", shl_ssf.glsl in fragment passes with the
 * VPLs in an SSBO):
 *   all         every pixel sums every VPL (shl_ssf_vpl_irradiance at n_s): the per-method
 *               reference at the VPL level, what filtering tries to reach at 1/16 the cost;
 *   unfiltered  each pixel its interleaved set only: the structured noise of the pattern;
 *   irr_filter  classical IGI: the interleaved irradiance (at n_s) box-filtered over the 4 x 4
 *               window around the pixel (offsets -2..1) with the discontinuity weight
 *               shl_ssf_weight (geometric normals, cos >= 0.9; plane distance <= 0.02 times the
 *               eye distance): across a normal map it averages irradiances that belong to
 *               different normals;
 *   sh_filter   [SSF]: the interleaved SH of the incoming radiance (run->bands bands, RGB),
 *               the same filter on the SH, then E at n_s from the filtered SH (the clamped
 *               cosine rotated once, shl_zh_cosine_power + shl_zh_rotate, shl_sh_dot per
 *               channel; shl_ssf_irradiance is the one-channel form). Negative E (SH ringing)
 *               is clamped to 0 (every method clamps; only this one can ring).
 * GL stages: stage 1 computes, per pixel, the interleaved irradiance (rd_out0) and the 3 n^2 SH
 * floats (rd_out1..7, then 8 vec4 per further draw: n = 3 fits one draw, n = 5 takes three,
 * each recomputing the pixel's 16 VPLs and writing its slice); the SH go to stage 2 as one SSBO
 * (the runner's 4 input textures would hold 16 floats), the irradiance as rd_in0. Stage 2 runs
 * both filters and the unfiltered shading in one draw. "all" is its own draw. Reported GL ms:
 * all: its draw; unfiltered: stage 1; irr_filter and sh_filter: stage 1 + stage 2 (shared
 * draws: each figure includes the other methods' work, an upper bound; the CPU figures are
 * per method).
 *
 * Ground truth ("gt"): the same sum over an N_gt x N_gt RSM with the same flux and clamp
 * (N_gt = 128 at --gt 1, 512 at --gt 2; SHLIGHT_SSF_GT=N), in double, written independently of
 * the kernels (no normalisation: Phi cos_y cos_s / (pi d^2 max(d^2, dmin^2)) from dot products
 * with d = y - x). It is also computed at N_gt / 2 and the RMSE between the two printed (the
 * discretisation error of the N_gt / 2 image; the N_gt image is closer).
 *
 * Printed per method (stdout): RMSE, PSNR and SSIM over the pixels whose material has a normal
 * map (bump_freq > 0) and over the others, against gt and against "all" (the same 256 VPLs
 * without interleaving: the error of the filter alone; against gt the VPL discretisation of
 * "all" itself, RMSE ~0.009 on cornell's floor, dominates). [SSF]'s claim is that sh_filter
 * keeps the normal-map detail that irr_filter blurs.
 * Measured (cornell, 5 bands, llvmpipe; "vs all" on the normal-mapped floor):
 *   64x48 --gt 1 (gt 128^2; 64^2 differs by RMSE 8.8e-4): RMSE / PSNR / SSIM vs gt: all 0.0060 /
 *     29.8 / 0.940, unfiltered 0.033 / 15.0 / 0.567, irr_filter 0.0107 / 24.9 / 0.814,
 *     sh_filter 0.0100 / 25.4 / 0.855; floor vs all: irr_filter RMSE 0.0134 SSIM 0.60,
 *     sh_filter RMSE 0.0090 SSIM 0.84. The pass takes ~1.2 s wall (5 shader builds).
 *   256x256 --gt 2 (gt 512^2, 40 s; 256^2 differs by RMSE 1.9e-4): all 0.0063 / 29.6 / 0.955,
 *     unfiltered 0.036 / 14.4 / 0.244, irr_filter 0.0069 / 28.7 / 0.927, sh_filter 0.0067 /
 *     28.9 / 0.935; floor vs all: irr_filter RMSE 0.0046 SSIM 0.905, sh_filter RMSE 0.0036
 *     SSIM 0.956; elsewhere the two filters agree (RMSE 0.0029 / 0.0030 vs all).
 *   max |gl - cpu| / peak: 3.1e-7 (tolerance GL_TOL = 1e-6). */
#include "rd.h"
#include "../shlight.h"

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#define SSF_LANES_NAME "SSE2"
#else
#define SSF_LANES_NAME "scalar"
#endif
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define SSF_AVX 1 /* the AVX lanes, chosen at run time by __builtin_cpu_supports */
#else
#define SSF_AVX 0
#endif

#define SSF_PI 3.14159265358979323846
#define SSF_STRIDE 9 /* floats per VPL: y, n_g, Phi rgb */
#define SSF_NI 4     /* interleaving pattern n_int x m_int */
#define SSF_MI 4
#define SSF_PLANE 0.02f  /* filter: plane distance <= SSF_PLANE * eye distance */
#define SSF_MINCOS 0.90f /* filter: cosine between geometric normals >= this */

enum { M_ALL = 0, M_UNF = 1, M_IRR = 2, M_SH = 3, M_COUNT = 4 };
static const char *const method_name[M_COUNT] = {"all", "unfiltered", "irr_filter", "sh_filter"};

static int env_int(const char *name, int def, int lo, int hi) {
  const char *v = getenv(name);
  int x;
  if (!v || sscanf(v, "%d", &x) != 1 || x < lo || x > hi) return def;
  return x;
}

/* ---- VPLs from the spot's RSM ------------------------------------------------------------- */
static double rect_f(double x, double y) {
  return atan(x * y / sqrt(1.0 + x * x + y * y));
}
static double rect_omega(double x0, double x1, double y0, double y1) {
  return rect_f(x1, y1) - rect_f(x0, y1) - rect_f(x1, y0) + rect_f(x0, y0);
}
/* the lit solid angle of the texel at (sx, sy), pitch p, cone radius tc on the image plane */
static double texel_omega(double sx, double sy, double p, double tc) {
  double x0 = sx - 0.5 * p, x1 = sx + 0.5 * p, y0 = sy - 0.5 * p, y1 = sy + 0.5 * p;
  double fx = fmax(fabs(x0), fabs(x1)), fy = fmax(fabs(y0), fabs(y1));
  double nx = x0 > 0 ? x0 : (x1 < 0 ? -x1 : 0), ny = y0 > 0 ? y0 : (y1 < 0 ? -y1 : 0);
  double om = 0.0, q = p / 8.0;
  int a, b;
  if (fx * fx + fy * fy <= tc * tc) return rect_omega(x0, x1, y0, y1);
  if (nx * nx + ny * ny >= tc * tc) return 0.0;
  for (b = 0; b < 8; b++)
    for (a = 0; a < 8; a++) {
      double cx = x0 + ((double)a + 0.5) * q, cy = y0 + ((double)b + 0.5) * q;
      if (cx * cx + cy * cy <= tc * tc)
        om += rect_omega(cx - 0.5 * q, cx + 0.5 * q, cy - 0.5 * q, cy + 0.5 * q);
    }
  return om;
}

/* N x N VPLs of spot l into out (N * N * SSF_STRIDE floats, zero flux where no light goes);
   interleave != 0 stores them in the sub-lattice order of the header (N a multiple of 4). */
static int spot_vpls(const rd_scene *s, const rd_light *l, int N, int interleave, float *out) {
  float eye[3], dir[3], up[3] = {0.0f, 0.0f, 0.0f}, fov;
  double ang = (double)l->angle, th, tc, p, len;
  rd_gbuf g;
  int i, j, k;
  for (k = 0; k < 3; k++) {
    eye[k] = l->c[k];
    dir[k] = l->n[k];
  }
  len = sqrt((double)rd_dot(dir, dir));
  if (!(len > 0)) return -1;
  for (k = 0; k < 3; k++)
    dir[k] = (float)((double)dir[k] / len);
  /* up: the world axis least aligned with the axis (as pass_hvl) */
  if (fabsf(dir[0]) <= fabsf(dir[1]) && fabsf(dir[0]) <= fabsf(dir[2]))
    up[0] = 1.0f;
  else if (fabsf(dir[1]) <= fabsf(dir[2]))
    up[1] = 1.0f;
  else
    up[2] = 1.0f;
  if (!(ang > 0.0)) ang = 1e-3;
  if (ang > 85.0 * SSF_PI / 180.0) ang = 85.0 * SSF_PI / 180.0;
  fov = (float)(2.0 * ang);
  tc = tan(ang);
  if (rd_gbuffer_view(s, eye, dir, up, fov, N, N, &g)) return -1;
  th = (double)tanf(0.5f * fov); /* rd_gbuffer_view's image-plane half-size */
  p = 2.0 * th / (double)N;
  memset(out, 0, (size_t)N * (size_t)N * SSF_STRIDE * sizeof(float));
  for (j = 0; j < N; j++)
    for (i = 0; i < N; i++) {
      size_t t = (size_t)j * (size_t)N + (size_t)i, o = t;
      double sx = (2.0 * ((double)i + 0.5) / (double)N - 1.0) * th;
      double sy = (1.0 - 2.0 * ((double)j + 0.5) / (double)N) * th, lv[3], d = 0, cs = 0, cg = 0,
             om;
      const float *y = g.pos + 3 * t, *ns = g.nrm + 3 * t, *ng = g.gnrm + 3 * t;
      int m = g.mat[t], c;
      float *q;
      if (interleave)
        o = (size_t)((((j / SSF_MI) * (N / SSF_NI) + i / SSF_NI) * SSF_NI * SSF_MI) +
                     (j % SSF_MI) * SSF_NI + i % SSF_NI);
      q = out + o * SSF_STRIDE;
      for (c = 0; c < 3; c++) {
        q[c] = y[c];
        q[3 + c] = ng[c];
      }
      if (m < 0 || m >= s->nmats) continue;
      om = texel_omega(sx, sy, p, tc);
      for (c = 0; c < 3; c++) {
        lv[c] = (double)eye[c] - (double)y[c];
        d += lv[c] * lv[c];
      }
      d = sqrt(d);
      if (!(om > 0) || !(d > 0)) continue;
      for (c = 0; c < 3; c++) {
        cs += (double)ns[c] * lv[c] / d;
        cg += (double)ng[c] * lv[c] / d;
      }
      if (!(cs > 0) || !(cg > 0)) continue;
      for (c = 0; c < 3; c++)
        q[6 + c] =
            (float)((double)s->mats[m].kd[c] * (double)l->radiance[c] * om * cs / fmax(cg, 0.05));
    }
  rd_gbuf_free(&g);
  return 0;
}

/* ---- CPU paths ---------------------------------------------------------------------------- */
/* "all": every VPL per pixel; E (rgb, 3 floats per pixel) */
static void cpu_all(const rd_gbuf *gb, const float *v, int nv, float dmin, float *E) {
  int npx = gb->w * gb->h, px, j;
  for (px = 0; px < npx; px++) {
    const float *x = gb->pos + 3 * px, *ns = gb->nrm + 3 * px, *ng = gb->gnrm + 3 * px;
    float acc[3] = {0.0f, 0.0f, 0.0f}, e;
    if (gb->mat[px] >= 0)
      for (j = 0; j < nv; j++) {
        const float *q = v + j * SSF_STRIDE;
        if (q[6] == 0.0f && q[7] == 0.0f && q[8] == 0.0f) continue;
        e = shl_ssf_vpl_irradiance(x, ng, ns, q, q + 3, 1.0f, dmin);
        acc[0] += q[6] * e;
        acc[1] += q[7] * e;
        acc[2] += q[8] * e;
      }
    memcpy(E + 3 * px, acc, sizeof acc);
  }
}

/* stage 1: the pixel's interleaved set, scaled by n_int m_int: irradiance E (3 per pixel) and,
   when sh != NULL, the SH (3 n^2 per pixel: r, g, b) */
static void cpu_stage1(const rd_gbuf *gb, const float *v, int nv, float dmin, int n, float *E,
                       float *sh) {
  int w = gb->w, npx = gb->w * gb->h, nn = n * n, px, k, i, r[2], cnt;
  const float scale = (float)(SSF_NI * SSF_MI);
  float t[SHLIGHT_MAX_COEFFS];
  for (px = 0; px < npx; px++) {
    const float *x = gb->pos + 3 * px, *ns = gb->nrm + 3 * px, *ng = gb->gnrm + 3 * px;
    float acc[3] = {0.0f, 0.0f, 0.0f}, e, *o = sh ? sh + (size_t)px * 3 * (size_t)nn : NULL;
    if (o) memset(o, 0, 3 * (size_t)nn * sizeof(float));
    if (gb->mat[px] >= 0) {
      cnt = shl_ssf_interleave(px % w, px / w, SSF_NI, SSF_MI, nv, r);
      for (k = 0; k < cnt; k++) {
        const float *q = v + (r[0] + k * r[1]) * SSF_STRIDE;
        if (q[6] == 0.0f && q[7] == 0.0f && q[8] == 0.0f) continue;
        e = shl_ssf_vpl_irradiance(x, ng, ns, q, q + 3, scale, dmin);
        acc[0] += q[6] * e;
        acc[1] += q[7] * e;
        acc[2] += q[8] * e;
        if (!o) continue;
        for (i = 0; i < nn; i++)
          t[i] = 0.0f;
        shl_ssf_vpl_sh(n, x, ng, q, q + 3, scale, dmin, t);
        for (i = 0; i < nn; i++) {
          o[i] += q[6] * t[i];
          o[nn + i] += q[7] * t[i];
          o[2 * nn + i] += q[8] * t[i];
        }
      }
    }
    memcpy(E + 3 * px, acc, sizeof acc);
  }
}

/* the filter window of pixel (x, y): offsets -n/2 .. n - 1 - n/2 */
static int win_lo(int n) {
  return -(n / 2);
}

/* stage 2 on the CPU: irr_filter (when E_in) or sh_filter (when sh_in) radiance into rgb */
static void cpu_filter(const rd_scene *s, const rd_gbuf *gb, int n, const float *E_in,
                       const float *sh_in, float *rgb) {
  int w = gb->w, h = gb->h, nn = n * n, x, y, dx, dy, i, c;
  float zh[SHLIGHT_MAX_BANDS], tr[SHLIGHT_MAX_COEFFS], acc[3 * SHLIGHT_MAX_COEFFS];
  shl_zh_cosine_power(n, 1.0f, zh);
  for (y = 0; y < h; y++)
    for (x = 0; x < w; x++) {
      int px = y * w + x, m = gb->mat[px], cnt = sh_in ? 3 * nn : 3;
      const float *p = gb->pos + 3 * px, *np = gb->gnrm + 3 * px;
      float ws = 0.0f, md = SSF_PLANE * gb->depth[px], E[3];
      if (m < 0 || m >= s->nmats) {
        rgb[3 * px] = rgb[3 * px + 1] = rgb[3 * px + 2] = 0.0f;
        continue;
      }
      for (i = 0; i < cnt; i++)
        acc[i] = 0.0f;
      for (dy = win_lo(SSF_MI); dy < win_lo(SSF_MI) + SSF_MI; dy++)
        for (dx = win_lo(SSF_NI); dx < win_lo(SSF_NI) + SSF_NI; dx++) {
          int qx = x + dx, qy = y + dy, qp;
          float wt;
          const float *src;
          if (qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
          qp = qy * w + qx;
          if (gb->mat[qp] < 0) continue;
          wt = shl_ssf_weight(p, np, gb->pos + 3 * qp, gb->gnrm + 3 * qp, md, SSF_MINCOS);
          if (!(wt > 0.0f)) continue;
          ws += wt;
          src = sh_in ? sh_in + (size_t)qp * 3 * (size_t)nn : E_in + 3 * qp;
          for (i = 0; i < cnt; i++)
            acc[i] += wt * src[i];
        }
      if (sh_in) {
        shl_zh_rotate(n, zh, gb->nrm + 3 * px, tr);
        for (c = 0; c < 3; c++)
          E[c] = shl_sh_dot(n, acc + c * nn, tr) / ws;
      } else {
        for (c = 0; c < 3; c++)
          E[c] = acc[c] / ws;
      }
      for (c = 0; c < 3; c++)
        rgb[3 * px + c] = s->mats[m].kd[c] * 0.318309886f * (E[c] > 0.0f ? E[c] : 0.0f);
    }
}

/* kd / pi E, clamped at 0, background 0 */
static void shade(const rd_scene *s, const rd_gbuf *gb, const float *E, int stride, float *rgb) {
  int npx = gb->w * gb->h, px, c;
  for (px = 0; px < npx; px++) {
    int m = gb->mat[px];
    for (c = 0; c < 3; c++) {
      float e = E[(size_t)px * (size_t)stride + (size_t)c];
      rgb[3 * px + c] =
          (m < 0 || m >= s->nmats) ? 0.0f : s->mats[m].kd[c] * 0.318309886f * (e > 0.0f ? e : 0.0f);
    }
  }
}

/* ---- ground truth --------------------------------------------------------------------------- */
typedef struct {
  double y[3], n[3], phi[3];
} gt_vpl;

typedef struct {
  const rd_run *run;
  const gt_vpl *v;
  int nv;
  double dm2;
  float *rgb;
  int avx;     /* the AVX lanes (gt_four_avx) */
  long *check; /* SHLIGHT_RENDER_GT_CHECK: sums compared with gt_one's, sums that differ */
} gt_job;

/* pixel px's position, unit shading normal and geometric normal in double; 0 without a
   material (the pixel stays 0) */
static int gt_pixel(const gt_job *jb, int px, double x[3], double ns[3], double ng[3]) {
  const rd_gbuf *gb = jb->run->gb;
  const rd_scene *s = jb->run->scene;
  const float *xf = gb->pos + 3 * px, *nsf = gb->nrm + 3 * px, *ngf = gb->gnrm + 3 * px;
  double ln = 0;
  int m = gb->mat[px], c;
  if (m < 0 || m >= s->nmats) return 0;
  for (c = 0; c < 3; c++) {
    x[c] = (double)xf[c];
    ns[c] = (double)nsf[c];
    ng[c] = (double)ngf[c];
    ln += ns[c] * ns[c];
  }
  for (c = 0; c < 3; c++)
    ns[c] /= sqrt(ln);
  return 1;
}

static void gt_store(const gt_job *jb, int px, const double acc[3]) {
  const rd_scene *s = jb->run->scene;
  int m = jb->run->gb->mat[px], c;
  for (c = 0; c < 3; c++)
    jb->rgb[3 * px + c] = (float)((double)s->mats[m].kd[c] / SSF_PI * acc[c]);
}

/* one pixel: the sum over the VPLs in their order */
static void gt_one(const gt_job *jb, const double x[3], const double ns[3], const double ng[3],
                   double acc[3]) {
  const gt_vpl *v = jb->v;
  const double dm2 = jb->dm2;
  int j;
  acc[0] = acc[1] = acc[2] = 0.0;
  for (j = 0; j < jb->nv; j++) {
    const gt_vpl *q = &v[j];
    double d0 = q->y[0] - x[0], d1 = q->y[1] - x[1], d2 = q->y[2] - x[2];
    double dd = d0 * d0 + d1 * d1 + d2 * d2, cy, cs, f;
    if (!(dd > 0) || ng[0] * d0 + ng[1] * d1 + ng[2] * d2 < 0) continue;
    cy = -(q->n[0] * d0 + q->n[1] * d1 + q->n[2] * d2);
    cs = ns[0] * d0 + ns[1] * d1 + ns[2] * d2;
    if (!(cy > 0) || !(cs > 0)) continue;
    f = cy * cs / (dd * (dd > dm2 ? dd : dm2));
    acc[0] += q->phi[0] * f;
    acc[1] += q->phi[1] * f;
    acc[2] += q->phi[2] * f;
  }
}

#if defined(__SSE2__)
/* four pixels at once, two per SSE2 vector: per lane the operations of gt_one in the same order
   (no contraction: -ffp-contract=off), and a skipped VPL adds phi * 0 = +0 to a sum that is +0
   or positive, so each sum is bit for bit gt_one's; the VPLs stream through the cache once per
   four pixels instead of once per pixel. x, ns, ng: [component][pixel] */
static void gt_four(const gt_job *jb, double x[3][4], double ns[3][4], double ng[3][4],
                    double acc[3][4]) {
  const gt_vpl *v = jb->v;
  const __m128d zero = _mm_setzero_pd(), dm2 = _mm_set1_pd(jb->dm2);
  const __m128d sgn = _mm_set1_pd(-0.0);
  __m128d X[2][3], S[2][3], G[2][3], E[2][3];
  int j, h, c;
  for (h = 0; h < 2; h++)
    for (c = 0; c < 3; c++) {
      X[h][c] = _mm_loadu_pd(&x[c][2 * h]);
      S[h][c] = _mm_loadu_pd(&ns[c][2 * h]);
      G[h][c] = _mm_loadu_pd(&ng[c][2 * h]);
      E[h][c] = zero;
    }
  for (j = 0; j < jb->nv; j++) {
    const gt_vpl *q = &v[j];
    const __m128d y0 = _mm_set1_pd(q->y[0]), y1 = _mm_set1_pd(q->y[1]), y2 = _mm_set1_pd(q->y[2]);
    const __m128d n0 = _mm_set1_pd(q->n[0]), n1 = _mm_set1_pd(q->n[1]), n2 = _mm_set1_pd(q->n[2]);
    for (h = 0; h < 2; h++) {
      __m128d d0 = _mm_sub_pd(y0, X[h][0]), d1 = _mm_sub_pd(y1, X[h][1]);
      __m128d d2 = _mm_sub_pd(y2, X[h][2]);
      __m128d dd =
          _mm_add_pd(_mm_add_pd(_mm_mul_pd(d0, d0), _mm_mul_pd(d1, d1)), _mm_mul_pd(d2, d2));
      __m128d gd = _mm_add_pd(_mm_add_pd(_mm_mul_pd(G[h][0], d0), _mm_mul_pd(G[h][1], d1)),
                              _mm_mul_pd(G[h][2], d2));
      __m128d cy = _mm_xor_pd(
          _mm_add_pd(_mm_add_pd(_mm_mul_pd(n0, d0), _mm_mul_pd(n1, d1)), _mm_mul_pd(n2, d2)), sgn);
      __m128d cs = _mm_add_pd(_mm_add_pd(_mm_mul_pd(S[h][0], d0), _mm_mul_pd(S[h][1], d1)),
                              _mm_mul_pd(S[h][2], d2));
      __m128d ok = _mm_and_pd(_mm_and_pd(_mm_cmpgt_pd(dd, zero), _mm_cmpnlt_pd(gd, zero)),
                              _mm_and_pd(_mm_cmpgt_pd(cy, zero), _mm_cmpgt_pd(cs, zero)));
      __m128d f;
      if (_mm_movemask_pd(ok) == 0) continue;
      f = _mm_and_pd(ok, _mm_div_pd(_mm_mul_pd(cy, cs), _mm_mul_pd(dd, _mm_max_pd(dd, dm2))));
      E[h][0] = _mm_add_pd(E[h][0], _mm_mul_pd(_mm_set1_pd(q->phi[0]), f));
      E[h][1] = _mm_add_pd(E[h][1], _mm_mul_pd(_mm_set1_pd(q->phi[1]), f));
      E[h][2] = _mm_add_pd(E[h][2], _mm_mul_pd(_mm_set1_pd(q->phi[2]), f));
    }
  }
  for (h = 0; h < 2; h++)
    for (c = 0; c < 3; c++)
      _mm_storeu_pd(&acc[c][2 * h], E[h][c]);
}

#if SSF_AVX
/* gt_four with the four pixels in one AVX vector: the same per-lane operations in the same
   order (AVX has no fused multiply-add, so no contraction either), so each sum is bit for bit
   gt_one's; chosen at run time where the CPU has AVX */
__attribute__((target("avx"))) static void
gt_four_avx(const gt_job *jb, double x[3][4], double ns[3][4], double ng[3][4], double acc[3][4]) {
  const gt_vpl *v = jb->v;
  const __m256d zero = _mm256_setzero_pd(), dm2 = _mm256_set1_pd(jb->dm2);
  const __m256d sgn = _mm256_set1_pd(-0.0);
  __m256d X[3], S[3], G[3], E[3];
  int j, c;
  for (c = 0; c < 3; c++) {
    X[c] = _mm256_loadu_pd(x[c]);
    S[c] = _mm256_loadu_pd(ns[c]);
    G[c] = _mm256_loadu_pd(ng[c]);
    E[c] = zero;
  }
  for (j = 0; j < jb->nv; j++) {
    const gt_vpl *q = &v[j];
    __m256d d0 = _mm256_sub_pd(_mm256_set1_pd(q->y[0]), X[0]);
    __m256d d1 = _mm256_sub_pd(_mm256_set1_pd(q->y[1]), X[1]);
    __m256d d2 = _mm256_sub_pd(_mm256_set1_pd(q->y[2]), X[2]);
    __m256d dd = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(d0, d0), _mm256_mul_pd(d1, d1)),
                               _mm256_mul_pd(d2, d2));
    __m256d gd = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(G[0], d0), _mm256_mul_pd(G[1], d1)),
                               _mm256_mul_pd(G[2], d2));
    __m256d cy =
        _mm256_xor_pd(_mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(_mm256_set1_pd(q->n[0]), d0),
                                                  _mm256_mul_pd(_mm256_set1_pd(q->n[1]), d1)),
                                    _mm256_mul_pd(_mm256_set1_pd(q->n[2]), d2)),
                      sgn);
    __m256d cs = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(S[0], d0), _mm256_mul_pd(S[1], d1)),
                               _mm256_mul_pd(S[2], d2));
    __m256d ok = _mm256_and_pd(
        _mm256_and_pd(_mm256_cmp_pd(dd, zero, _CMP_GT_OQ), _mm256_cmp_pd(gd, zero, _CMP_NLT_UQ)),
        _mm256_and_pd(_mm256_cmp_pd(cy, zero, _CMP_GT_OQ), _mm256_cmp_pd(cs, zero, _CMP_GT_OQ)));
    __m256d f;
    if (_mm256_movemask_pd(ok) == 0) continue;
    f = _mm256_and_pd(
        ok, _mm256_div_pd(_mm256_mul_pd(cy, cs), _mm256_mul_pd(dd, _mm256_max_pd(dd, dm2))));
    E[0] = _mm256_add_pd(E[0], _mm256_mul_pd(_mm256_set1_pd(q->phi[0]), f));
    E[1] = _mm256_add_pd(E[1], _mm256_mul_pd(_mm256_set1_pd(q->phi[1]), f));
    E[2] = _mm256_add_pd(E[2], _mm256_mul_pd(_mm256_set1_pd(q->phi[2]), f));
  }
  for (c = 0; c < 3; c++)
    _mm256_storeu_pd(acc[c], E[c]);
}
#endif
#define GT_LANES 4
#else
#define GT_LANES 1
#endif

static void gt_rows(void *ctx, long lo, long hi) {
  const gt_job *jb = (const gt_job *)ctx;
  double x[3][4], ns[3][4], ng[3][4], acc[3][4], a[3], b[3], c3[3], one[3];
  int px, k = 0, t, c, pp[4];
  long nsum = 0, nbad = 0;
  for (px = (int)lo; px < (int)hi; px++) {
    if (!gt_pixel(jb, px, a, b, c3)) continue;
    for (c = 0; c < 3; c++) {
      x[c][k] = a[c];
      ns[c][k] = b[c];
      ng[c][k] = c3[c];
    }
    pp[k++] = px;
    if (k < GT_LANES) continue;
#if SSF_AVX
    if (jb->avx)
      gt_four_avx(jb, x, ns, ng, acc);
    else
#endif
#if defined(__SSE2__)
      gt_four(jb, x, ns, ng, acc);
#else
    gt_one(jb, a, b, c3, one);
    for (c = 0; c < 3; c++)
      acc[c][0] = one[c];
#endif
    for (t = 0; t < k; t++) {
      for (c = 0; c < 3; c++)
        one[c] = acc[c][t];
      gt_store(jb, pp[t], one);
    }
    if (jb->check) /* the lanes against gt_one, bit for bit */
      for (t = 0; t < k; t++) {
        for (c = 0; c < 3; c++) {
          a[c] = x[c][t];
          b[c] = ns[c][t];
          c3[c] = ng[c][t];
        }
        gt_one(jb, a, b, c3, one);
        for (c = 0; c < 3; c++) {
          nsum++;
          nbad += memcmp(&one[c], &acc[c][t], sizeof(double)) != 0;
        }
      }
    k = 0;
  }
  for (t = 0; t < k; t++) { /* the row's last pixels, one at a time */
    for (c = 0; c < 3; c++) {
      a[c] = x[c][t];
      b[c] = ns[c][t];
      c3[c] = ng[c][t];
    }
    gt_one(jb, a, b, c3, one);
    gt_store(jb, pp[t], one);
  }
  if (jb->check) {
    __atomic_add_fetch(&jb->check[0], nsum, __ATOMIC_RELAXED);
    __atomic_add_fetch(&jb->check[1], nbad, __ATOMIC_RELAXED);
  }
}

/* the gt image on rd_threads() threads; *ms: the CPU ms of all of them */
static int gt_render(const rd_run *run, const rd_light *l, int N, double dmin, const char *label,
                     rd_image *out, double *ms, int bg) {
  const rd_gbuf *gb = run->gb;
  const rd_scene *s = run->scene;
  int j, nv = 0, c;
  double t0 = rd_cpu_ms();
  gt_job jb;
  float *raw = (float *)malloc((size_t)N * (size_t)N * SSF_STRIDE * sizeof(float));
  gt_vpl *v = (gt_vpl *)malloc((size_t)N * (size_t)N * sizeof(gt_vpl));
  double dm2 = dmin * dmin;
  long check[2] = {0, 0};
  *out = rd_image_new(gb->w, gb->h);
  if (!raw || !v || !out->rgb || spot_vpls(s, l, N, 0, raw)) {
    free(raw);
    free(v);
    rd_image_free(out);
    return -1;
  }
  for (j = 0; j < N * N; j++) {
    const float *q = raw + (size_t)j * SSF_STRIDE;
    double ln = 0;
    if (q[6] == 0.0f && q[7] == 0.0f && q[8] == 0.0f) continue;
    for (c = 0; c < 3; c++) {
      v[nv].y[c] = (double)q[c];
      ln += (double)q[3 + c] * (double)q[3 + c];
      v[nv].phi[c] = (double)q[6 + c] / SSF_PI;
    }
    for (c = 0; c < 3; c++)
      v[nv].n[c] = (double)q[3 + c] / sqrt(ln);
    nv++;
  }
  free(raw);
  jb.run = run;
  jb.v = v;
  jb.nv = nv;
  jb.dm2 = dm2;
  jb.avx = rd_use_avx(SSF_AVX);
  jb.check = getenv("SHLIGHT_RENDER_GT_CHECK") ? check : NULL;
  jb.rgb = out->rgb;
  t0 = rd_cpu_ms() - t0; /* the VPLs, on this thread */
  t0 += (bg ? rd_parallel_bg : rd_parallel)((long)gb->w * gb->h, gb->w, gt_rows, &jb, label);
  if (jb.check)
    fprintf(stderr, "%s: %s lanes vs the scalar loop: %ld of %ld sums differ\n", label,
            jb.avx ? "AVX" : SSF_LANES_NAME, check[1], check[0]);
  if (ms) *ms = t0;
  free(v);
  return 0;
}

/* ---- GL paths ----------------------------------------------------------------------------- */
static const char *const gl_includes[7] = {
    "shl_prelude.glsl", "shl_basis.glsl", "shl_gradient.glsl", "shl_zonal.glsl",
    "shl_light.glsl",   "shl_brdf.glsl",  "shl_ssf.glsl"};

/* shared declarations of the bodies: the G-buffer at a pixel and VPL j of rd_buf1 */
static const char *const gl_common =
    "vec3 vpl_v(int j, int o) {\n"
    "  int b = j * 9 + o;\n"
    "  return vec3(rd_buf1[b], rd_buf1[b + 1], rd_buf1[b + 2]);\n"
    "}\n"
    "vec3 shade(vec4 nrm, vec3 e) {\n"
    "  int m = int(nrm.w) * 12;\n"
    "  vec3 kd = vec3(rd_mats[m], rd_mats[m + 1], rd_mats[m + 2]);\n"
    "  return kd * 0.318309886 * max(e, vec3(0.0));\n"
    "}\n";

static const char *const gl_all_body =
    "void main() {\n"
    "  ivec2 px = rd_pixel();\n"
    "  vec4 p = texelFetch(rd_pos, px, 0), ns = texelFetch(rd_nrm, px, 0);\n"
    "  vec3 ng = texelFetch(rd_gnrm, px, 0).xyz, acc = vec3(0.0);\n"
    "  int j;\n"
    "  if (ns.w < 0.0) { rd_out0 = vec4(0.0); return; }\n"
    "  for (j = 0; j < SSF_NVPL; ++j) {\n"
    "    vec3 phi = vpl_v(j, 6);\n"
    "    if (phi == vec3(0.0)) continue;\n"
    "    acc += phi * shl_ssf_vpl_irradiance(p.xyz, ng, ns.xyz, vpl_v(j, 0), vpl_v(j, 3), 1.0,\n"
    "                                        SSF_DMIN);\n"
    "  }\n"
    "  rd_out0 = vec4(shade(ns, acc), 1.0);\n"
    "}\n";

/* stage 1: SSF_FIRST = the first SH float this draw writes (0: rd_out0 is E and rd_out1.. the
   SH; else rd_out0.. the SH), SSF_NOUT outputs */
static const char *const gl_stage1_body =
    "float shr[SHLIGHT_MAX_COEFFS];\n"
    "float shg[SHLIGHT_MAX_COEFFS];\n"
    "float shb[SHLIGHT_MAX_COEFFS];\n"
    "float pick(int q) {\n"
    "  const int nn = SSF_BANDS * SSF_BANDS;\n"
    "  if (q < nn) return shr[q];\n"
    "  if (q < 2 * nn) return shg[q - nn];\n"
    "  if (q < 3 * nn) return shb[q - 2 * nn];\n"
    "  return 0.0;\n"
    "}\n"
    "vec4 pick4(int q) { return vec4(pick(q), pick(q + 1), pick(q + 2), pick(q + 3)); }\n"
    "void main() {\n"
    "  const int nn = SSF_BANDS * SSF_BANDS;\n"
    "  ivec2 px = rd_pixel();\n"
    "  vec4 p = texelFetch(rd_pos, px, 0), ns = texelFetch(rd_nrm, px, 0);\n"
    "  vec3 ng = texelFetch(rd_gnrm, px, 0).xyz, acc = vec3(0.0);\n"
    "  float t[SHLIGHT_MAX_COEFFS];\n"
    "  int r[2];\n"
    "  int i, k, cnt = 0;\n"
    "  for (i = 0; i < nn; ++i) { shr[i] = 0.0; shg[i] = 0.0; shb[i] = 0.0; }\n"
    "  if (ns.w >= 0.0) cnt = shl_ssf_interleave(px.x, px.y, SSF_NI, SSF_MI, SSF_NVPL, r);\n"
    "  for (k = 0; k < cnt; ++k) {\n"
    "    int j = r[0] + k * r[1];\n"
    "    vec3 phi = vpl_v(j, 6), y = vpl_v(j, 0), ny = vpl_v(j, 3);\n"
    "    if (phi == vec3(0.0)) continue;\n"
    "    acc += phi * shl_ssf_vpl_irradiance(p.xyz, ng, ns.xyz, y, ny, SSF_SCALE, SSF_DMIN);\n"
    "    for (i = 0; i < nn; ++i) t[i] = 0.0;\n"
    "    shl_ssf_vpl_sh(SSF_BANDS, p.xyz, ng, y, ny, SSF_SCALE, SSF_DMIN, t);\n"
    "    for (i = 0; i < nn; ++i) {\n"
    "      shr[i] += phi.x * t[i];\n"
    "      shg[i] += phi.y * t[i];\n"
    "      shb[i] += phi.z * t[i];\n"
    "    }\n"
    "  }\n"
    "  SSF_WRITE\n"
    "}\n";

/* stage 2: rd_in0 = stage 1's E (xyz), rd_buf2 = the SH (3 n^2 per pixel); rd_out0 sh_filter,
   rd_out1 irr_filter, rd_out2 unfiltered */
static const char *const gl_stage2_body =
    "void main() {\n"
    "  const int nn = SSF_BANDS * SSF_BANDS;\n"
    "  ivec2 px = rd_pixel();\n"
    "  vec4 p = texelFetch(rd_pos, px, 0), ns = texelFetch(rd_nrm, px, 0);\n"
    "  vec3 ng = texelFetch(rd_gnrm, px, 0).xyz, ei = vec3(0.0), e;\n"
    "  float shr[SHLIGHT_MAX_COEFFS], shg[SHLIGHT_MAX_COEFFS], shb[SHLIGHT_MAX_COEFFS];\n"
    "  float zh[SHLIGHT_MAX_BANDS], tr[SHLIGHT_MAX_COEFFS];\n"
    "  float ws = 0.0, md = SSF_PLANE * p.w, wt;\n"
    "  int i, dx, dy;\n"
    "  if (ns.w < 0.0) { rd_out0 = vec4(0.0); rd_out1 = vec4(0.0); rd_out2 = vec4(0.0); return; }\n"
    "  for (i = 0; i < nn; ++i) { shr[i] = 0.0; shg[i] = 0.0; shb[i] = 0.0; }\n"
    "  for (dy = -(SSF_MI / 2); dy < -(SSF_MI / 2) + SSF_MI; ++dy)\n"
    "    for (dx = -(SSF_NI / 2); dx < -(SSF_NI / 2) + SSF_NI; ++dx) {\n"
    "      ivec2 q = px + ivec2(dx, dy);\n"
    "      vec4 qp;\n"
    "      int b;\n"
    "      if (q.x < 0 || q.y < 0 || q.x >= rd_size.x || q.y >= rd_size.y) continue;\n"
    "      qp = texelFetch(rd_pos, q, 0);\n"
    "      if (texelFetch(rd_nrm, q, 0).w < 0.0) continue;\n"
    "      wt = shl_ssf_weight(p.xyz, ng, qp.xyz, texelFetch(rd_gnrm, q, 0).xyz, md, SSF_MINCOS);\n"
    "      if (!(wt > 0.0)) continue;\n"
    "      ws += wt;\n"
    "      b = (q.y * rd_size.x + q.x) * 3 * nn;\n"
    "      for (i = 0; i < nn; ++i) {\n"
    "        shr[i] += wt * rd_buf2[b + i];\n"
    "        shg[i] += wt * rd_buf2[b + nn + i];\n"
    "        shb[i] += wt * rd_buf2[b + 2 * nn + i];\n"
    "      }\n"
    "      ei += wt * texelFetch(rd_in0, q, 0).xyz;\n"
    "    }\n"
    "  shl_zh_cosine_power(SSF_BANDS, 1.0, zh);\n"
    "  shl_zh_rotate(SSF_BANDS, zh, ns.xyz, tr);\n"
    "  e = vec3(shl_sh_dot(SSF_BANDS, shr, tr), shl_sh_dot(SSF_BANDS, shg, tr),\n"
    "           shl_sh_dot(SSF_BANDS, shb, tr)) / ws;\n"
    "  rd_out0 = vec4(shade(ns, e), 1.0);\n"
    "  rd_out1 = vec4(shade(ns, ei / ws), 1.0);\n"
    "  rd_out2 = vec4(shade(ns, texelFetch(rd_in0, px, 0).xyz), 1.0);\n"
    "}\n";

typedef struct {
  char defines[512];
  char *body; /* gl_common + the body (+ the stage-1 writes) */
} gl_src;

static int gl_build(gl_src *g, int n, int nvpl, float dmin, const char *body, int first, int nout) {
  char writes[1024] = "", *at;
  size_t len;
  int o, q = first;
  snprintf(g->defines, sizeof g->defines,
           "#define SHLIGHT_MAX_BANDS %d\n#define SSF_BANDS %d\n#define SSF_NVPL %d\n"
           "#define SSF_NI %d\n#define SSF_MI %d\n#define SSF_SCALE %.1f\n#define SSF_DMIN %.9g\n"
           "#define SSF_PLANE %.9g\n#define SSF_MINCOS %.9g\n",
           n, n, nvpl, SSF_NI, SSF_MI, (double)(SSF_NI * SSF_MI), (double)dmin, (double)SSF_PLANE,
           (double)SSF_MINCOS);
  for (o = 0; o < nout; o++) {
    len = strlen(writes);
    if (o == 0 && first == 0)
      snprintf(writes + len, sizeof writes - len, "  rd_out0 = vec4(acc, 0.0);\n");
    else {
      snprintf(writes + len, sizeof writes - len, "  rd_out%d = pick4(%d);\n", o, q);
      q += 4;
    }
  }
  len = strlen(gl_common) + strlen(body) + strlen(writes) + 1;
  g->body = (char *)malloc(len);
  if (!g->body) return -1;
  strcpy(g->body, gl_common);
  strcat(g->body, body);
  at = strstr(g->body, "SSF_WRITE");
  if (at) { /* splice the writes in place of the marker */
    char *rest = at + strlen("SSF_WRITE");
    size_t nrest = strlen(rest) + 1;
    char *tmp = (char *)malloc(nrest);
    if (!tmp) {
      free(g->body);
      g->body = NULL;
      return -1;
    }
    memcpy(tmp, rest, nrest);
    *at = 0;
    strcat(g->body, writes);
    strcat(g->body, tmp);
    free(tmp);
  }
  return 0;
}

static int gl_run1(const rd_run *run, gl_src *g, const float *const *bufs, const size_t *nb,
                   int nbuf, const float *const *in, int nin, float *const *out, int nout,
                   double *ms) {
  rd_gl_pass p;
  int rc;
  memset(&p, 0, sizeof p);
  p.defines = g->defines;
  p.includes = gl_includes;
  p.ninclude = 7;
  p.body = g->body;
  p.bufs = bufs;
  p.buf_floats = nb;
  p.nbuf = nbuf;
  p.inputs = in;
  p.ninputs = nin;
  p.nout = nout;
  rc = rd_gl_run(run->scene, run->gb, &p, out, run->reps, ms);
  free(g->body);
  g->body = NULL;
  return rc;
}

static rd_image image_from_rgba(const rd_gbuf *gb, const float *o) {
  rd_image im = rd_image_new(gb->w, gb->h);
  size_t i, n = (size_t)gb->w * (size_t)gb->h;
  if (im.rgb)
    for (i = 0; i < n; i++) {
      im.rgb[3 * i] = o[4 * i];
      im.rgb[3 * i + 1] = o[4 * i + 1];
      im.rgb[3 * i + 2] = o[4 * i + 2];
    }
  return im;
}

/* ---- metrics over the normal-mapped pixels ----------------------------------------------- */
static rd_image image_copy(const rd_image *im) {
  rd_image c = rd_image_new(im->w, im->h);
  if (c.rgb && im->rgb) memcpy(c.rgb, im->rgb, (size_t)im->w * (size_t)im->h * 3 * sizeof(float));
  return c;
}

/* one line per method: the error against gt and against "all" (the same VPLs unfiltered and
   not interleaved: what the filter alone costs) over the normal-mapped pixels and the others */
static void print_regions(const rd_image *img, const rd_image *gt, const rd_image *all,
                          const char *method, const char *path, const int *bump, const int *plain) {
  rd_metrics a, b, c, d;
  size_t i, nb = 0, n = (size_t)img->w * (size_t)img->h;
  for (i = 0; i < n; i++)
    nb += bump[i] >= 0;
  if (!nb) {
    printf("ssf %-10s (%s): no normal-mapped pixels in view (no material with bump_freq > 0)\n",
           method, path);
    return;
  }
  memset(&a, 0, sizeof a);
  a.rmse = a.psnr = a.ssim = NAN;
  b = c = d = a;
  if (gt->rgb) {
    a = rd_compare(img, gt, bump);
    b = rd_compare(img, gt, plain);
  }
  if (all->rgb) {
    c = rd_compare(img, all, bump);
    d = rd_compare(img, all, plain);
  }
  if (gt->rgb)
    printf("ssf %-10s (%s): normal-mapped pixels vs gt RMSE %.4g PSNR %.2f SSIM %.4f, vs all "
           "RMSE %.4g PSNR %.2f SSIM %.4f | other pixels vs gt RMSE %.4g PSNR %.2f SSIM %.4f, vs "
           "all RMSE %.4g PSNR %.2f SSIM %.4f\n",
           method, path, a.rmse, a.psnr, a.ssim, c.rmse, c.psnr, c.ssim, b.rmse, b.psnr, b.ssim,
           d.rmse, d.psnr, d.ssim);
  else
    printf("ssf %-10s (%s): normal-mapped pixels vs all RMSE %.4g PSNR %.2f SSIM %.4f | other "
           "pixels vs all RMSE %.4g PSNR %.2f SSIM %.4f\n",
           method, path, c.rmse, c.psnr, c.ssim, d.rmse, d.psnr, d.ssim);
}

/* the ground truth and its N / 2 twin, on a thread of its own beside the CPU and GL paths
   (rd_bg_ok) or inline; what the pass prints of it is printed once it is joined */
typedef struct {
  const rd_run *run;
  const rd_light *spot;
  int N, bg, rc;
  double dmin, ms, wall, cpu; /* ms: the gt's own (printed); wall, cpu: both images (--timings) */
  rd_image gt, half;
} gt_task;

static void *gt_task_run(void *a) {
  gt_task *t = (gt_task *)a;
  char label[32];
  rd_tm t0 = rd_tm_now();
  double c0, ms2 = 0.0;
  if (t->bg) rd_thread_nice();
  c0 = rd_cpu_ms();
  snprintf(label, sizeof label, "ssf gt %d^2", t->N);
  t->rc = gt_render(t->run, t->spot, t->N, t->dmin, label, &t->gt, &t->ms, t->bg);
  snprintf(label, sizeof label, "ssf gt %d^2", t->N / 2);
  if (!t->rc) t->rc = gt_render(t->run, t->spot, t->N / 2, t->dmin, label, &t->half, &ms2, t->bg);
  /* this thread's own CPU time (the VPLs) is background work too; the rows count theirs */
  if (t->bg) rd_bg_add_cpu(rd_cpu_ms() - c0);
  t->wall = rd_tm_now().wall - t0.wall;
  t->cpu = t->ms + ms2; /* gt_render's: the VPLs and the rows */
  return NULL;
}

/* waits for the ground truth (a thread of its own: *started), prints its convergence, counts
   its time, hands the image to *gt; 0 or -1 */
static int gt_join(gt_task *t, pthread_t *th, int *started, const rd_gbuf *gb, rd_image *gt) {
  if (*started) pthread_join(*th, NULL);
  *started = 0;
  if (t->rc) {
    rd_image_free(&t->gt);
    rd_image_free(&t->half);
    return -1;
  }
  {
    rd_metrics d = rd_compare(&t->half, &t->gt, gb->mat);
    printf("ssf gt: %d x %d RSM, %.0f ms; the %d x %d RSM differs by RMSE %.3g (PSNR %.1f dB): "
           "the gt's discretisation error is below that\n",
           t->N, t->N, t->ms, t->N / 2, t->N / 2, d.rmse, d.psnr);
  }
  rd_image_free(&t->half);
  rd_tm_add_ms(RD_TM_GT, t->wall, t->cpu);
  *gt = t->gt;
  t->gt.rgb = NULL;
  return 0;
}

/* ---- the pass ------------------------------------------------------------------------------ */
/* max |gl - cpu| / peak accepted: 3.3 x the worst measured on llvmpipe (3.1e-7: cornell and
   spheres, 64x48 and 256x256, 3 and 5 bands; GLSL runs the kernels' double parts in float) */
#define GL_TOL 1e-6

int rd_pass_ssf(rd_run *run) {
  const rd_scene *s = run->scene;
  const rd_gbuf *gb = run->gb;
  const rd_light *spot = NULL;
  int N = env_int("SHLIGHT_SSF_RSM", 16, 4, 256), n = run->bands, i, nv, rc = -1, npx, m;
  int Ngt = env_int("SHLIGHT_SSF_GT", run->gt >= 2 ? 512 : 128, 8, 4096);
  double frac = 0.05, diag = 0, ms_cpu[M_COUNT], ms_gl[M_COUNT];
  float dmin, *vpl = NULL, *E1 = NULL, *SH = NULL, *Eall = NULL;
  int *bump = NULL, *plain = NULL;
  size_t nn, mem_v, mem[M_COUNT];
  rd_image gt = {0, 0, NULL}, cpu_img[M_COUNT], keep[M_COUNT];
  const char *fe = getenv("SHLIGHT_SSF_CLAMP");
  gt_task gtt;
  pthread_t gth;
  int gt_started = 0;
  for (i = 0; i < s->nlights; i++)
    if (s->lights[i].type == RD_LIGHT_SPOT) {
      spot = &s->lights[i];
      break;
    }
  if (!spot) return 0;
  if (n < 1) n = 1;
  if (n > 16) n = 16;
  nn = (size_t)n * (size_t)n;
  npx = gb->w * gb->h;
  if (fe && sscanf(fe, "%lf", &frac) != 1) frac = 0.05;
  for (i = 0; i < 3; i++)
    diag += ((double)s->bmax[i] - (double)s->bmin[i]) * ((double)s->bmax[i] - (double)s->bmin[i]);
  dmin = (float)(frac * sqrt(diag));
  if (N % SSF_NI || N % SSF_MI) N = (N / 4 + 1) * 4;
  nv = N * N;
  memset(cpu_img, 0, sizeof cpu_img);
  memset(keep, 0, sizeof keep);
  memset(&gtt, 0, sizeof gtt);
  vpl = (float *)malloc((size_t)nv * SSF_STRIDE * sizeof(float));
  bump = (int *)malloc((size_t)npx * sizeof(int));
  plain = (int *)malloc((size_t)npx * sizeof(int));
  if (!vpl || !bump || !plain || spot_vpls(s, spot, N, 1, vpl)) goto done;
  for (i = 0; i < npx; i++) {
    m = gb->mat[i];
    bump[i] = (m >= 0 && m < s->nmats && s->mats[m].bump_freq > 0) ? m : -1;
    plain[i] = (m >= 0 && bump[i] < 0) ? m : -1;
  }
  mem_v = (size_t)nv * SSF_STRIDE * sizeof(float);
  mem[M_ALL] = mem_v;
  mem[M_UNF] = mem_v + (size_t)npx * 3 * sizeof(float);
  mem[M_IRR] = mem[M_UNF];
  mem[M_SH] = mem_v + (size_t)npx * 3 * nn * sizeof(float);
  printf("ssf: %d x %d RSM = %d VPLs, %d x %d interleaved (%d per pixel), %d bands (%d SH floats "
         "per pixel), clamp %.4g\n",
         N, N, nv, SSF_NI, SSF_MI, nv / (SSF_NI * SSF_MI), n, (int)(3 * nn), (double)dmin);
  /* ground truth: on a thread of its own while the CPU and GL paths run (the pass processes
     run at the same time), else here; joined below */
  if (run->gt) {
    gtt.run = run;
    gtt.spot = spot;
    gtt.N = Ngt;
    gtt.dmin = (double)dmin;
    gt_started = rd_bg_start(&gth, gt_task_run, &gtt, &gtt.bg);
  }
  /* CPU */
  if (run->use_cpu) {
    double t0;
    E1 = (float *)malloc((size_t)npx * 3 * sizeof(float));
    Eall = (float *)malloc((size_t)npx * 3 * sizeof(float));
    SH = (float *)malloc((size_t)npx * 3 * nn * sizeof(float));
    for (i = 0; i < M_COUNT; i++) {
      cpu_img[i] = rd_image_new(gb->w, gb->h);
      if (!cpu_img[i].rgb) goto done;
    }
    if (!E1 || !Eall || !SH) goto done;
    t0 = rd_cpu_ms();
    cpu_all(gb, vpl, nv, dmin, Eall);
    shade(s, gb, Eall, 3, cpu_img[M_ALL].rgb);
    ms_cpu[M_ALL] = rd_cpu_ms() - t0;
    t0 = rd_cpu_ms();
    cpu_stage1(gb, vpl, nv, dmin, n, E1, NULL);
    shade(s, gb, E1, 3, cpu_img[M_UNF].rgb);
    ms_cpu[M_UNF] = rd_cpu_ms() - t0;
    t0 = rd_cpu_ms();
    cpu_stage1(gb, vpl, nv, dmin, n, E1, NULL);
    cpu_filter(s, gb, n, E1, NULL, cpu_img[M_IRR].rgb);
    ms_cpu[M_IRR] = rd_cpu_ms() - t0;
    t0 = rd_cpu_ms();
    cpu_stage1(gb, vpl, nv, dmin, n, E1, SH);
    cpu_filter(s, gb, n, NULL, SH, cpu_img[M_SH].rgb);
    ms_cpu[M_SH] = rd_cpu_ms() - t0;
  }
  /* GL */
  if (run->use_gl) {
    float *o[8] = {NULL}, *shb = NULL, *e1 = NULL;
    const float *bufs[2];
    size_t nb[2];
    int nsh = (int)(3 * nn), draws, d, ok = 0;
    double ms;
    gl_src g;
    memset(ms_gl, 0, sizeof ms_gl);
    for (i = 0; i < 8; i++)
      if (!(o[i] = (float *)malloc((size_t)npx * 4 * sizeof(float)))) goto gl_done;
    shb = (float *)malloc((size_t)npx * (size_t)nsh * sizeof(float));
    e1 = (float *)malloc((size_t)npx * 4 * sizeof(float));
    if (!shb || !e1) goto gl_done;
    bufs[0] = vpl;
    nb[0] = (size_t)nv * SSF_STRIDE;
    /* all */
    if (gl_build(&g, n, nv, dmin, gl_all_body, 0, 1) ||
        gl_run1(run, &g, bufs, nb, 1, NULL, 0, o, 1, &ms))
      goto gl_done;
    ms_gl[M_ALL] = ms;
    {
      rd_image im = image_from_rgba(gb, o[0]);
      if (!run->use_cpu) keep[M_ALL] = image_copy(&im);
      rd_emit(run, "ssf", method_name[M_ALL], "gl", im, ms, mem[M_ALL], GL_TOL);
    }
    /* stage 1: draw 0 writes E and SH floats 0..27, draw d > 0 SH floats 28 + 32 (d - 1).. */
    draws = nsh <= 28 ? 1 : 1 + (nsh - 28 + 31) / 32;
    for (d = 0; d < draws; d++) {
      int first = d == 0 ? 0 : 28 + 32 * (d - 1), nout, k, j;
      int left = nsh - first;
      nout = d == 0 ? 1 + (nsh < 28 ? (nsh + 3) / 4 : 7) : (left < 32 ? (left + 3) / 4 : 8);
      if (gl_build(&g, n, nv, dmin, gl_stage1_body, first, nout) ||
          gl_run1(run, &g, bufs, nb, 1, NULL, 0, o, nout, &ms))
        goto gl_done;
      ms_gl[M_UNF] += ms;
      if (d == 0) memcpy(e1, o[0], (size_t)npx * 4 * sizeof(float));
      for (k = d == 0 ? 1 : 0; k < nout; k++) {
        int base = first + 4 * (k - (d == 0 ? 1 : 0));
        for (i = 0; i < npx; i++)
          for (j = 0; j < 4 && base + j < nsh; j++)
            shb[(size_t)i * (size_t)nsh + (size_t)(base + j)] = o[k][4 * i + j];
      }
    }
    /* stage 2 */
    bufs[1] = shb;
    nb[1] = (size_t)npx * (size_t)nsh;
    {
      const float *in[1];
      in[0] = e1;
      if (gl_build(&g, n, nv, dmin, gl_stage2_body, 0, 3) ||
          gl_run1(run, &g, bufs, nb, 2, in, 1, o, 3, &ms))
        goto gl_done;
    }
    ms_gl[M_IRR] = ms_gl[M_UNF] + ms;
    ms_gl[M_SH] = ms_gl[M_UNF] + ms;
    {
      static const int slot[M_COUNT] = {-1, 2, 1, 0};
      for (i = 1; i < M_COUNT; i++) {
        rd_image im = image_from_rgba(gb, o[slot[i]]);
        if (!run->use_cpu) keep[i] = image_copy(&im);
        rd_emit(run, "ssf", method_name[i], "gl", im, ms_gl[i], mem[i], GL_TOL);
      }
    }
    ok = 1;
  gl_done:
    for (i = 0; i < 8; i++)
      free(o[i]);
    free(shb);
    free(e1);
    if (!ok) goto done;
  }
  if (run->gt && gt_join(&gtt, &gth, &gt_started, gb, &gt)) goto done;
  /* hand the CPU images and the gt over; the region metrics first */
  for (i = 0; i < M_COUNT; i++) {
    if (!run->use_cpu) break;
    keep[i] = image_copy(&cpu_img[i]);
    rd_emit(run, "ssf", method_name[i], "cpu", cpu_img[i], ms_cpu[i], mem[i], 0);
    cpu_img[i].rgb = NULL;
  }
  for (i = 0; i < M_COUNT; i++)
    if (keep[i].rgb)
      print_regions(&keep[i], &gt, &keep[M_ALL], method_name[i], run->use_cpu ? "cpu" : "gl", bump,
                    plain);
  if (gt.rgb) {
    rd_emit(run, "ssf", "gt", "gt", gt, 0, 0, 0);
    gt.rgb = NULL;
  }
  rc = 0;
done:
  if (gt_started) pthread_join(gth, NULL);
  rd_image_free(&gtt.gt);
  rd_image_free(&gtt.half);
  for (i = 0; i < M_COUNT; i++) {
    rd_image_free(&cpu_img[i]);
    rd_image_free(&keep[i]);
  }
  rd_image_free(&gt);
  free(vpl);
  free(bump);
  free(plain);
  free(E1);
  free(Eall);
  free(SH);
  if (rc) fprintf(stderr, "ssf: pass failed\n");
  return rc;
}
