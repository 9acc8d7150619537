/* pass_hvl.c - one-bounce indirect light from a spot light's reflective shadow map (RSM):
 * virtual point lights (VPL) against Harmonics Virtual Lights (HVL, [HVL] sec. 3 and 5).
 *
 * What is rendered. The pass outputs the one-bounce indirect radiance only (no direct light,
 * like [HVL]'s GI figures): at a camera pixel x with shading normal n_x and albedo kd(x),
 *   L(x) = kd(x) / pi * E_ind(x),
 * E_ind the irradiance from the surfaces that the scene's first spot light lights directly.
 * Visibility: the light's visibility is the RSM's (the first hit from the light); there is no
 * receiver-side visibility (neither between the virtual lights and x nor in the ground truth).
 * One geometric gate, in every method and the ground truth alike: light passes from y to x
 * only when each point lies strictly in front of the other's geometric plane (n_g(y) . (x - y)
 * > eps and n_g(x) . (y - x) > eps, eps = 1e-5 scene diagonal). Without normal maps it changes
 * nothing (the shading cosines are then 0 there too); with one (cornell's floor) it stops the
 * tilted shading normals from sending light between points of the same plane, an unphysical
 * transfer whose integral diverges (log) at the receiver and kept the ground truth from
 * converging (max error 0.125 of peak between N = 256 and 512 without it, 0.005 with it).
 * Bounce surfaces reflect their diffuse part kd only (the RSM's flux). Receivers: Lambert ones
 * kd / pi; Phong and GGX ones (ks > 0) kd / pi + ks f_s, and a measured BRDF (--brdf FILE,
 * shl_merl_read) replaces a material's BRDF altogether: the BRDF part is shaded through BRDF SH
 * tables on every path (see "receiver BRDFs" below), the ground truth uses the real BRDF.
 *
 * The light set (rsm_lights). The RSM is rd_gbuffer_view from the spot (eye c, axis n, fov_y =
 * 2 * angle) of m = w x h texels (16 x 16 = 256 by default; SHLIGHT_HVL_RSM=N for N x N); the
 * same set serves every method. Texel (i, j) covers the square [sx -+ p/2] x [sy -+ p/2] of
 * the image plane at unit distance (sx, sy as rd_gbuffer_view, p = 2 tan(fov_y / 2) / h), of
 * solid angle Omega = F(x1, y1) - F(x0, y1) - F(x1, y0) + F(x0, y0), F(x, y) = atan(x y /
 * sqrt(1 + x^2 + y^2)) (exact for a plane rectangle); only the part inside the cone
 * (sx^2 + sy^2 <= tan^2 angle) is lit: texels that the cone's edge cuts are split into 16 x 16
 * sub-rectangles, each counted when its centre is inside.
 * Flux of a texel. The spot sends the flux I Omega into the texel's solid angle. It lands at
 * distance d on the surface at y, whose geometric normal n_g makes the angle theta_g with the
 * direction to the light -l: the texel's footprint is dA = d^2 Omega / cos theta_g and the
 * irradiance there is E = I cos theta_s / d^2 (theta_s: the angle to the shading normal n_s,
 * the normal map's; = theta_g without one). The diffusely reflected flux is
 *   Phi = kd(y) E dA = kd(y) I Omega max(0, n_s . -l) / (n_g . -l)   (n_g . -l floored at 0.05)
 * i.e. kd(y) I Omega on a plain surface: the cosine cancels against the footprint, and the
 * brief's "kd I dOmega max(0, n . -l)" would count it twice. The reflected radiance is
 * Lambertian, kd E / pi, so the intensity that the patch sends towards x is
 * Phi / pi max(0, n_s . w_yx) (n_s: the VPL's normal).
 *
 * Methods (each on "cpu", C kernels, and "gl", the GLSL twins in a fragment shader with the
 * light set in an SSBO):
 *   vpl             E = sum Phi max(0, n_y . -w) max(0, n_x . w) / (pi d^2), w = (y - x)/d:
 *                   the 1/d^2 spike is kept (what [HVL] removes);
 *   vpl_clamp       the same with d^2 clamped below by r_fov^2 (the texel spacing of the
 *                   fov heuristic at that VPL: the usual distance clamp, made scale-free);
 *   hvl_neighbours  HVLs with radius r1 (eq. 23, shl_hvl_radius_neighbours over the 8-connected
 *                   RSM neighbours, eps = r_fov / 4; no neighbour: r_fov);
 *   hvl_fov         HVLs with radius r2 (eq. 24-26, shl_hvl_radius_fov with lambda = the full
 *                   field of view 2 angle (erratum E9) and M = w h, the texel spacing).
 * HVL j: L_j = Phi_j (F' . Y(-w_j)) G_j (eq. 20-21, shl_hvl_radiance with the exact H) with F'
 * = 1/pi, the Lambert BRDF of unit albedo (kd(y) is in Phi): it is constant, so the emission
 * needs band 0 only (n = 1, [HVL]: "isotropic HVL reconstruction only use band 0"), exact at
 * any band count. The receiver's lobe is Lambert's ZH (shl_zh_lambert, max(0, cos)/pi) about
 * n_x with run->bands bands, and the contribution lj (cap . lobe) is shl_hvl_contribution_zh;
 * L = kd(x) sum_j Phi_j (...) (in the point limit this is the VPL sum: G_j pi r^2 / d^2 -> 1).
 *
 * Ground truth (path "gt"): the same bounce integrated over the lit surfaces with an N x N RSM
 * (N = 128 at --gt 1, 512 at --gt 2; SHLIGHT_HVL_GT=N), same texel flux, traced with rd_trace
 * along rd_gbuffer_view's rays. Each texel is a Lambertian patch: the quad cut from the plane
 * through its centre y, normal n_s, by its four corner rays (a flat wall: the quads tile it),
 * radiance Phi / (pi A). A texel whose corner rays hit off the plane of its centre (an edge, a
 * silhouette, the scene's boundary) is split 2 x 2, up to 3 times (gt_cell), so that the quads
 * follow the surfaces up to their edges. Near a receiver (d < 6 patch radii) the patch's
 * irradiance is the exact projected solid angle of the quad clipped to x's horizon (Lambert's
 * polygon formula in double: bounded as x approaches the patch); farther away the point formula
 * (the VPL term, relative error O((size / d)^2)). The GT is also computed at N / 2 and the
 * difference is printed, an estimate of the error of the N / 2 image (the N image is closer).
 * Measured on cornell at 64x48 against N = 512: N = 128 is within p99 0.0025, max 0.021 of the
 * peak (N = 64: p99 0.0062, max 0.027).
 *
 * Printed per method and path: the 99th percentile and the max over the pixels of
 * max_rgb |method - gt| / peak(gt) (the spikes show in the max). */
#include "rd.h"
#include "../shlight.h"

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#define HVL_LANES_NAME "SSE2"
#else
#define HVL_LANES_NAME "scalar"
#endif
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define HVL_AVX 1 /* the AVX lanes, chosen at run time by __builtin_cpu_supports */
#else
#define HVL_AVX 0
#endif

#define HVL_PI 3.14159265358979323846
#define HVL_STRIDE 15   /* floats per light in the set: y, n_s, Phi, n_g, r_nb, r_fov, dist */
#define HVL_GT_NEAR 6.0 /* polygon form factor within this many patch radii */

enum { M_VPL = 0, M_VPL_CLAMP = 1, M_HVL_NB = 2, M_HVL_FOV = 3, M_COUNT = 4 };
static const char *const method_name[M_COUNT] = {"vpl", "vpl_clamp", "hvl_neighbours", "hvl_fov"};
/* floats per light that each method reads (its buffer: mem) */
static const int method_stride[M_COUNT] = {12, 13, 13, 13};
/* rd_emit's gl tolerance, max |gl - cpu| / peak(cpu), ~3x the worst measured on llvmpipe
   (Mesa 22.3.6; cornell and spheres, 64x48 and 256x256, bands 1, 3, 5, 9, 16): VPL 1.5e-7
   (plain float arithmetic on both sides); HVL 8.8e-6 (cornell, 256x256, 1 band, one pixel;
   typically 2e-7..3e-6: the kernels' shli_real is double in C and float in GLSL, and the exact
   H has slope 1/s in the cosine for a cap of sine s) */
static const double method_tol[M_COUNT] = {5e-7, 5e-7, 3e-5, 3e-5};
/* the same on the pixels of BRDF-table materials (Phong, GGX, --brdf), VPL: the table lookup,
   its rotation about z and the SH evaluation at w_i, float on both sides; worst measured on
   llvmpipe 4.0e-7 (hvl_glossy with a measured back wall and room, 64x48); HVL: its Lambert
   part's tolerance (the table term measured at 3.0e-7, same runs) */
static const double method_tol_brdf[M_COUNT] = {2e-6, 2e-6, 3e-5, 3e-5};

/* ---- the spot and its RSM frame ----------------------------------------------------------- */
typedef struct {
  const rd_light *l;
  float eye[3], dir[3], up[3];
  float fov;              /* RSM fov_y = 2 angle (clamped to 2 * 85 degrees) */
  double tcone;           /* tan(angle): the cone's radius on the image plane */
  float f[3], r[3], u[3]; /* the frame of rd_gbuffer_view: forward, right, up */
} spot_view;

static void normf3(float v[3]) {
  double a = (double)v[0], b = (double)v[1], c = (double)v[2], l = sqrt(a * a + b * b + c * c);
  if (l > 0) {
    v[0] = (float)(a / l);
    v[1] = (float)(b / l);
    v[2] = (float)(c / l);
  } else {
    v[0] = v[1] = 0.0f;
    v[2] = 1.0f;
  }
}

static void spot_setup(const rd_light *l, spot_view *sv) {
  float ax = fabsf(l->n[0]), ay = fabsf(l->n[1]), az = fabsf(l->n[2]);
  double ang = (double)l->angle;
  int k;
  memset(sv, 0, sizeof *sv);
  sv->l = l;
  for (k = 0; k < 3; k++) {
    sv->eye[k] = l->c[k];
    sv->dir[k] = l->n[k];
  }
  normf3(sv->dir);
  /* up: the world axis least aligned with the axis */
  if (ax <= ay && ax <= az)
    sv->up[0] = 1.0f;
  else if (ay <= az)
    sv->up[1] = 1.0f;
  else
    sv->up[2] = 1.0f;
  if (!(ang > 0.0)) ang = 1e-3;
  if (ang > 85.0 * HVL_PI / 180.0) {
    fprintf(stderr, "hvl: spot half-angle %.1f deg clamped to 85 deg for the RSM\n",
            ang * 180.0 / HVL_PI);
    ang = 85.0 * HVL_PI / 180.0;
  }
  sv->fov = (float)(2.0 * ang);
  sv->tcone = tan(ang);
  /* the frame exactly as rd_gbuffer_view builds it */
  memcpy(sv->f, sv->dir, sizeof sv->f);
  sv->r[0] = sv->f[1] * sv->up[2] - sv->f[2] * sv->up[1];
  sv->r[1] = sv->f[2] * sv->up[0] - sv->f[0] * sv->up[2];
  sv->r[2] = sv->f[0] * sv->up[1] - sv->f[1] * sv->up[0];
  normf3(sv->r);
  sv->u[0] = sv->r[1] * sv->f[2] - sv->r[2] * sv->f[1];
  sv->u[1] = sv->r[2] * sv->f[0] - sv->r[0] * sv->f[2];
  sv->u[2] = sv->r[0] * sv->f[1] - sv->r[1] * sv->f[0];
}

/* image-plane centre (sx, sy) and pitch p of texel (i, j) of a w x h view (rd_gbuffer_view) */
static void texel_plane(const spot_view *sv, int w, int h, int i, int j, double *sx, double *sy,
                        double *p) {
  double th = (double)tanf(0.5f * sv->fov);
  *sx = (2.0 * ((double)i + 0.5) / (double)w - 1.0) * th * (double)w / (double)h;
  *sy = (1.0 - 2.0 * ((double)j + 0.5) / (double)h) * th;
  *p = 2.0 * th / (double)h;
}

static double rect_f(double x, double y) {
  return atan(x * y / sqrt(1.0 + x * x + y * y));
}
/* solid angle of the image-plane rectangle [x0, x1] x [y0, y1] (unit distance) */
static double rect_omega(double x0, double x1, double y0, double y1) {
  return rect_f(x1, y1) - rect_f(x0, y1) - rect_f(x1, y0) + rect_f(x0, y0);
}
/* lit solid angle of the texel centred at (sx, sy), pitch p, inside the cone of radius tc */
static double texel_omega(double sx, double sy, double p, double tc) {
  double x0 = sx - 0.5 * p, x1 = sx + 0.5 * p, y0 = sy - 0.5 * p, y1 = sy + 0.5 * p;
  double fx = fmax(fabs(x0), fabs(x1)), fy = fmax(fabs(y0), fabs(y1));
  double nx = (x0 > 0 ? x0 : x1 < 0 ? -x1 : 0), ny = (y0 > 0 ? y0 : y1 < 0 ? -y1 : 0);
  double om = 0.0, q = p / 16.0;
  int a, b;
  if (fx * fx + fy * fy <= tc * tc) return rect_omega(x0, x1, y0, y1);
  if (nx * nx + ny * ny >= tc * tc) return 0.0;
  for (b = 0; b < 16; b++)
    for (a = 0; a < 16; a++) {
      double cx = x0 + ((double)a + 0.5) * q, cy = y0 + ((double)b + 0.5) * q;
      if (cx * cx + cy * cy <= tc * tc)
        om += rect_omega(cx - 0.5 * q, cx + 0.5 * q, cy - 0.5 * q, cy + 0.5 * q);
    }
  return om;
}

/* Reflected flux (rgb) of RSM texel k: see the header. Returns 0 when the texel sends none. */
static int texel_flux(const rd_scene *s, const spot_view *sv, const float y[3], const float ns[3],
                      const float ng[3], int m, double omega, double phi[3]) {
  double l[3], d = 0, cs = 0, cg = 0, ratio;
  int c;
  if (m < 0 || m >= s->nmats || !(omega > 0)) return 0;
  for (c = 0; c < 3; c++) {
    l[c] = (double)sv->eye[c] - (double)y[c]; /* towards the light */
    d += l[c] * l[c];
  }
  d = sqrt(d);
  if (!(d > 0)) return 0;
  for (c = 0; c < 3; c++) {
    cs += (double)ns[c] * l[c] / d;
    cg += (double)ng[c] * l[c] / d;
  }
  if (!(cs > 0) || !(cg > 0)) return 0;
  ratio = cs / fmax(cg, 0.05); /* the normal map's irradiance over the footprint's cosine */
  for (c = 0; c < 3; c++)
    phi[c] = (double)s->mats[m].kd[c] * (double)sv->l->radiance[c] * omega * ratio;
  return phi[0] > 0 || phi[1] > 0 || phi[2] > 0;
}

/* ---- the light set -------------------------------------------------------------------------- */
typedef struct {
  int w, h, count;
  float *buf; /* count * HVL_STRIDE */
} light_set;

static int rsm_lights(const rd_run *run, const spot_view *sv, int w, int h, light_set *ls) {
  const rd_scene *s = run->scene;
  rd_gbuf g;
  int i, j, m = w * h;
  int *idx;
  memset(ls, 0, sizeof *ls);
  ls->w = w;
  ls->h = h;
  if (rd_gbuffer_view(s, sv->eye, sv->dir, sv->up, sv->fov, w, h, &g)) return -1;
  ls->buf = (float *)calloc((size_t)m * HVL_STRIDE, sizeof(float));
  idx = (int *)malloc((size_t)m * sizeof(int));
  if (!ls->buf || !idx) {
    free(idx);
    free(ls->buf);
    rd_gbuf_free(&g);
    return -1;
  }
  for (j = 0; j < h; j++)
    for (i = 0; i < w; i++) {
      size_t k = (size_t)j * (size_t)w + (size_t)i;
      double sx, sy, p, phi[3];
      float *q = ls->buf + (size_t)ls->count * HVL_STRIDE;
      int c;
      idx[k] = -1;
      texel_plane(sv, w, h, i, j, &sx, &sy, &p);
      if (!texel_flux(s, sv, g.pos + 3 * k, g.nrm + 3 * k, g.gnrm + 3 * k, g.mat[k],
                      texel_omega(sx, sy, p, sv->tcone), phi))
        continue;
      for (c = 0; c < 3; c++) {
        q[c] = g.pos[3 * k + (size_t)c];
        q[3 + c] = g.nrm[3 * k + (size_t)c];
        q[6 + c] = (float)phi[c];
        q[9 + c] = g.gnrm[3 * k + (size_t)c];
      }
      q[14] = g.depth[k];
      q[13] = shl_hvl_radius_fov(q[14], sv->fov, m);
      idx[k] = ls->count++;
    }
  /* eq. 23 over the 8-connected RSM neighbours that hit a surface (lit or not: they sample the
     density of the RSM's positions) */
  for (j = 0; j < h; j++)
    for (i = 0; i < w; i++) {
      size_t k = (size_t)j * (size_t)w + (size_t)i;
      float pn[8][3], dn[8];
      int cnt = 0, di, dj;
      float *q;
      if (idx[k] < 0) continue;
      q = ls->buf + (size_t)idx[k] * HVL_STRIDE;
      for (dj = -1; dj <= 1; dj++)
        for (di = -1; di <= 1; di++) {
          int a = i + di, b = j + dj;
          size_t kk;
          if ((di == 0 && dj == 0) || a < 0 || b < 0 || a >= w || b >= h) continue;
          kk = (size_t)b * (size_t)w + (size_t)a;
          if (g.mat[kk] < 0) continue;
          memcpy(pn[cnt], g.pos + 3 * kk, sizeof pn[cnt]);
          dn[cnt] = g.depth[kk];
          cnt++;
        }
      q[12] = shl_hvl_radius_neighbours(cnt, q, q[14], (const float(*)[3])pn, dn, 0.25f * q[13]);
      if (!(q[12] > 0.0f)) q[12] = q[13];
    }
  free(idx);
  rd_gbuf_free(&g);
  return 0;
}

/* the buffer a method reads: y, n_s, Phi, n_g (+ r) */
static float *method_buffer(const light_set *ls, int method) {
  int st = method_stride[method], j, c;
  float *b = (float *)malloc((size_t)(ls->count > 0 ? ls->count : 1) * (size_t)st * sizeof(float));
  if (!b) return NULL;
  for (j = 0; j < ls->count; j++) {
    const float *q = ls->buf + (size_t)j * HVL_STRIDE;
    for (c = 0; c < 12; c++)
      b[j * st + c] = q[c];
    if (st > 12) b[j * st + 12] = method == M_HVL_NB ? q[12] : q[13];
  }
  return b;
}

/* ---- receiver BRDFs: SH tables (glossy and measured materials) --------------------------- */
/* A receiver of kind HV_ANALYTIC (Phong / GGX, ks > 0) reflects kd / pi (the Lambert term
   above) plus ks f_s; one of kind HV_MEASURED (--brdf FILE) reflects the measured f (three
   channels) and has no Lambert term. f_s (kd = 0, ks = 1, f0 = 1: Phong (e + 1) / (2 pi) cos^e
   of the mirror angle, GGX D G2 / (4 cos_i cos_o), as the grid and area passes) and the
   measured f are tabulated once per material and channel by shl_brdf_table_build(_merl):
   HV_NT theta_o samples, isotropic, nb = run->brdf_bands bands, in the local frame (t, b, nrm)
   of rd_frame. Per pixel the table is looked up at w_o (the eye direction in that frame):
     HVL:  F  = SH of f cos(theta_i); light j adds Phi_j shl_hvl_contribution(nb, lj, F, 0,
           R (y_j - x), r_j): the cap is taken in the local frame (R: rows t, b, nrm), so no
           SH rotation is needed; the cap's SH is exact at any band count, so the product has
           nb bands (not run->bands);
     VPL:  F' = SH of f (without the cosine); light j adds Phi_j (F' . Y(w_i)) cos_y cos_x /
           (pi d^2), w_i = R (y_j - x) / d: the same table, so every method shares the BRDF's
           SH truncation, and the ground truth uses the real BRDF (shl_brdf_eval /
           shl_merl_eval) with none. */
#define HV_NT 90
#define HV_QUAD 32 /* shl_brdf_table_build quad_order (analytic) */
#define HV_QUAD_MERL 16
#define HV_HDR 4 /* floats per material in the buffer: kind, offsets of the r, g, b tables */
enum { HV_LAMBERT = 0, HV_ANALYTIC = 1, HV_MEASURED = 2 };
typedef struct {
  int nb, nmats, any;
  float *gpu;           /* HV_HDR per material (kind, 3 table offsets), then the tables */
  size_t floats;        /* of gpu */
  shl_brdf_params *par; /* per material (kd = 0, ks = 1, f0 = 1), analytic kinds */
  const shl_merl *merl;
} hv_brdf;

static int hv_kind(const hv_brdf *B, int m) {
  return B->any && m >= 0 && m < B->nmats ? (int)B->gpu[HV_HDR * m] : HV_LAMBERT;
}

static void hv_brdf_free(hv_brdf *B) {
  free(B->gpu);
  free(B->par);
  memset(B, 0, sizeof *B);
}

static int hv_brdf_build(const rd_run *run, hv_brdf *B) {
  const rd_scene *s = run->scene;
  int nb = run->brdf_bands > 0 ? run->brdf_bands : 9, m, c, tables = 0, named = -1;
  size_t one = shl_brdf_table_size(nb, HV_NT, 1), at;
  int *kind = (int *)calloc((size_t)(s->nmats > 0 ? s->nmats : 1), sizeof(int));
  memset(B, 0, sizeof *B);
  B->nb = nb;
  B->nmats = s->nmats;
  B->merl = run->merl;
  B->par = (shl_brdf_params *)calloc((size_t)(s->nmats > 0 ? s->nmats : 1), sizeof *B->par);
  if (!kind || !B->par || !one) {
    free(kind);
    return -1;
  }
  if (run->merl && run->merl_mat) {
    for (m = 0; m < s->nmats; m++)
      if (!strcmp(s->mats[m].name, run->merl_mat)) named = m;
    if (named < 0) {
      fprintf(stderr, "hvl: --brdf: no material '%s' in the scene\n", run->merl_mat);
      free(kind);
      return -1;
    }
  }
  for (m = 0; m < s->nmats; m++) {
    const rd_material *mt = &s->mats[m];
    int glossy = (mt->brdf == RD_BRDF_PHONG || mt->brdf == RD_BRDF_GGX) &&
                 (mt->ks[0] > 0.0f || mt->ks[1] > 0.0f || mt->ks[2] > 0.0f);
    if (mt->brdf == RD_BRDF_GGX &&
        !(mt->roughness >= SHLIGHT_BRDF_MIN_ALPHA && mt->roughness <= 4.0f))
      glossy = 0;
    if (run->merl && (named >= 0 ? m == named : mt->brdf != RD_BRDF_LAMBERT))
      kind[m] = HV_MEASURED;
    else if (glossy)
      kind[m] = HV_ANALYTIC;
    tables += kind[m] == HV_MEASURED ? 3 : kind[m] == HV_ANALYTIC ? 1 : 0;
  }
  if (run->merl && named < 0) {
    int k = 0;
    for (m = 0; m < s->nmats; m++)
      k += kind[m] == HV_MEASURED;
    if (!k) {
      fprintf(stderr, "hvl: --brdf: the scene has no Phong / GGX material to replace; name one "
                      "as --brdf FILE:MATERIAL\n");
      free(kind);
      return -1;
    }
  }
  B->any = tables > 0;
  B->floats = (size_t)HV_HDR * (size_t)s->nmats + (size_t)tables * one;
  B->gpu = (float *)calloc(B->floats ? B->floats : 1, sizeof(float));
  if (!B->gpu) {
    free(kind);
    return -1;
  }
  at = (size_t)HV_HDR * (size_t)s->nmats;
  for (m = 0; m < s->nmats; m++) {
    const rd_material *mt = &s->mats[m];
    float *h = B->gpu + HV_HDR * m;
    h[0] = (float)kind[m];
    for (c = 0; c < 3; c++)
      h[1 + c] = -1.0f;
    if (kind[m] == HV_LAMBERT) continue;
    B->par[m].model = mt->brdf == RD_BRDF_PHONG ? SHLIGHT_BRDF_PHONG : SHLIGHT_BRDF_GGX;
    B->par[m].kd = 0.0f;
    B->par[m].ks = 1.0f;
    B->par[m].exponent = mt->exponent;
    B->par[m].alpha_x = B->par[m].alpha_y = mt->roughness;
    B->par[m].f0 = 1.0f;
    for (c = 0; c < (kind[m] == HV_MEASURED ? 3 : 1); c++) {
      shl_brdf_table t;
      shl_result r;
      float est = 0.0f;
      double t0 = rd_cpu_ms();
      t.n = nb;
      t.n_theta = HV_NT;
      t.n_phi = 1;
      t.flags = 0;
      t.data = B->gpu + at;
      r = kind[m] == HV_MEASURED ? shl_brdf_table_build_merl(&t, run->merl, c, HV_QUAD_MERL, &est)
                                 : shl_brdf_table_build(&t, &B->par[m], HV_QUAD, &est);
      if (r != SHLIGHT_OK) {
        fprintf(stderr, "hvl: BRDF table of material %s failed (%d)\n", mt->name, (int)r);
        free(kind);
        return -1;
      }
      printf("hvl: BRDF table %s (%s%s), %d bands, %d theta_o samples, %.0f ms; quadrature "
             "error estimate %.2e\n",
             mt->name,
             kind[m] == HV_MEASURED      ? "measured, channel "
             : mt->brdf == RD_BRDF_PHONG ? "Phong"
                                         : "GGX",
             kind[m] == HV_MEASURED ? (c == 0   ? "r"
                                       : c == 1 ? "g"
                                                : "b")
                                    : "",
             nb, HV_NT, rd_cpu_ms() - t0, (double)est);
      h[1 + c] = (float)at;
      at += one;
    }
    if (kind[m] == HV_ANALYTIC) h[2] = h[3] = h[1];
  }
  free(kind);
  return 0;
}

/* the pixel's local frame R (rows t, b, nrm) and w_o (the eye direction in it) */
static void hv_local(const float x[3], const float nz[3], const float eye[3], float R[9],
                     float wo[3]) {
  float t[3], b[3], v[3], vl;
  int k;
  rd_frame(nz, t, b);
  for (k = 0; k < 3; k++)
    v[k] = eye[k] - x[k];
  vl = 1.0f / sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (k = 0; k < 3; k++)
    v[k] = v[k] * vl;
  for (k = 0; k < 3; k++) {
    R[k] = t[k];
    R[3 + k] = b[k];
    R[6 + k] = nz[k];
  }
  wo[0] = t[0] * v[0] + t[1] * v[1] + t[2] * v[2];
  wo[1] = b[0] * v[0] + b[1] * v[1] + b[2] * v[2];
  wo[2] = nz[0] * v[0] + nz[1] * v[1] + nz[2] * v[2];
}

/* ---- CPU shading ---------------------------------------------------------------------------- */
typedef struct {
  const rd_run *run;
  const hv_brdf *B;
  int method, nl;
  const float *b;
  float eps, *rgb;
  float fzh[SHLIGHT_MAX_BANDS];
} cpu_job;

static void shade_rows(void *ctx, long lo, long hi) {
  const cpu_job *jb = (const cpu_job *)ctx;
  const rd_run *run = jb->run;
  const hv_brdf *B = jb->B;
  const int method = jb->method, nl = jb->nl;
  const float *b = jb->b, eps = jb->eps, *fzh = jb->fzh;
  float *rgb = jb->rgb;
  const rd_gbuf *gb = run->gb;
  const rd_scene *s = run->scene;
  int st = method_stride[method], bands = run->bands, px, j, c, nb = B->nb;
  float femit[1];
  femit[0] = 1.1283791670955126f; /* 2 / sqrt(pi): F' . Y = femit[0] Y_0^0 = 1 / pi */
  for (px = (int)lo; px < (int)hi; px++) {
    const float *x = gb->pos + 3 * px, *nx = gb->nrm + 3 * px, *gx = gb->gnrm + 3 * px;
    int m = gb->mat[px], kind = hv_kind(B, m), nch = kind == HV_MEASURED ? 3 : 1;
    float acc[3] = {0.0f, 0.0f, 0.0f}, spec[3] = {0.0f, 0.0f, 0.0f};
    float R[9], wo[3], F[3][SHLIGHT_MAX_COEFFS], ysh[SHLIGHT_MAX_COEFFS];
    const float zero[3] = {0.0f, 0.0f, 0.0f};
    if (m < 0 || m >= s->nmats) {
      rgb[3 * px] = rgb[3 * px + 1] = rgb[3 * px + 2] = 0.0f;
      continue;
    }
    if (kind != HV_LAMBERT) {
      hv_local(x, nx, gb->eye, R, wo);
      for (c = 0; c < nch; c++)
        shl_brdf_table_lookup(nb, HV_NT, 1, method <= M_VPL_CLAMP ? 1 : 0,
                              B->gpu + (int)B->gpu[HV_HDR * m + 1 + c], wo, F[c]);
    }
    for (j = 0; j < nl; j++) {
      const float *y = b + j * st, *ny = y + 3, *phi = y + 6, *gy = y + 9;
      float dv[3] = {y[0] - x[0], y[1] - x[1], y[2] - x[2]}, yl[3];
      /* each point strictly in front of the other's geometric plane (see the header) */
      if (!(-(gy[0] * dv[0] + gy[1] * dv[1] + gy[2] * dv[2]) > eps) ||
          !(gx[0] * dv[0] + gx[1] * dv[1] + gx[2] * dv[2] > eps))
        continue;
      if (kind != HV_LAMBERT)
        for (c = 0; c < 3; c++)
          yl[c] = R[3 * c] * dv[0] + R[3 * c + 1] * dv[1] + R[3 * c + 2] * dv[2];
      if (method <= M_VPL_CLAMP) {
        float d2 = dv[0] * dv[0] + dv[1] * dv[1] + dv[2] * dv[2], d, cy, cx, gf;
        if (!(d2 > 0.0f)) continue;
        d = sqrtf(d2);
        cy = -(ny[0] * dv[0] + ny[1] * dv[1] + ny[2] * dv[2]) / d;
        cx = (nx[0] * dv[0] + nx[1] * dv[1] + nx[2] * dv[2]) / d;
        if (!(cy > 0.0f) || !(cx > 0.0f)) continue;
        if (method == M_VPL_CLAMP && d2 < y[12] * y[12]) d2 = y[12] * y[12];
        gf = cy * cx / (3.14159265f * d2);
        acc[0] += phi[0] * gf;
        acc[1] += phi[1] * gf;
        acc[2] += phi[2] * gf;
        if (kind != HV_LAMBERT) {
          float wi[3] = {yl[0] / d, yl[1] / d, yl[2] / d};
          shl_sh_eval(nb, wi, ysh);
          for (c = 0; c < 3; c++)
            spec[c] += phi[c] * gf * shl_sh_dot(nb, F[nch == 3 ? c : 0], ysh);
        }
      } else {
        float r = y[12], lj, cc;
        lj = shl_hvl_radiance(1, femit, 1.0f, x, nx, y, ny, r, 1);
        if (!(lj > 0.0f)) continue;
        cc = shl_hvl_contribution_zh(bands, lj, fzh, nx, x, y, r);
        acc[0] += phi[0] * cc;
        acc[1] += phi[1] * cc;
        acc[2] += phi[2] * cc;
        for (c = 0; c < nch && kind != HV_LAMBERT; c++) {
          float cs = shl_hvl_contribution(nb, lj, F[c], zero, yl, r);
          if (nch == 3)
            spec[c] += phi[c] * cs;
          else {
            spec[0] += phi[0] * cs;
            spec[1] += phi[1] * cs;
            spec[2] += phi[2] * cs;
          }
        }
      }
    }
    for (j = 0; j < 3; j++) {
      float kd = s->mats[m].kd[j];
      float dif = method <= M_VPL_CLAMP ? kd * acc[j] * 0.318309886f : kd * acc[j];
      rgb[3 * px + j] = kind == HV_MEASURED   ? spec[j]
                        : kind == HV_ANALYTIC ? dif + s->mats[m].ks[j] * spec[j]
                                              : dif;
    }
  }
}

/* the CPU image of a method, on rd_threads() threads; returns their CPU ms together */
static double shade_cpu(const rd_run *run, const hv_brdf *B, int method, const float *b, int nl,
                        float eps, float *rgb) {
  cpu_job jb;
  jb.run = run;
  jb.B = B;
  jb.method = method;
  jb.nl = nl;
  jb.b = b;
  jb.eps = eps;
  jb.rgb = rgb;
  shl_zh_lambert(run->bands, jb.fzh);
  return rd_parallel((long)run->gb->w * run->gb->h, run->gb->w, shade_rows, &jb,
                     method_name[method]);
}

/* ---- GL shading ----------------------------------------------------------------------------- */
/* GLSL twin of rd_frame (hv_frame), hv_local and the table lookup (shl_brdf_table_lookup's sums,
   done on the table in rd_buf2: HV_HDR floats per material, then the tables) */
static const char *const gl_spec =
    "#if HVL_SPEC\n"
    "float hv_F[3][SHLIGHT_MAX_COEFFS];\n"
    "float hv_R[9];\n"
    "void hv_frame(vec3 z, out vec3 t, out vec3 b) {\n"
    "  float sg = z.z >= 0.0 ? 1.0 : -1.0;\n"
    "  float a = -1.0 / (sg + z.z);\n"
    "  float c = z.x * z.y * a;\n"
    "  t = vec3(1.0 + sg * z.x * z.x * a, sg * c, -sg * z.x);\n"
    "  b = vec3(c, sg + z.y * z.y * a, -z.y);\n"
    "}\n"
    "void hv_setup(int mi, int nch, vec3 x, vec3 nz) {\n"
    "  vec3 t;\n"
    "  vec3 b;\n"
    "  hv_frame(nz, t, b);\n"
    "  vec3 v = rd_eye - x;\n"
    "  float vl = 1.0 / sqrt(v.x * v.x + v.y * v.y + v.z * v.z);\n"
    "  v = v * vl;\n"
    "  for (int k = 0; k < 3; ++k) {\n"
    "    hv_R[k] = t[k];\n"
    "    hv_R[3 + k] = b[k];\n"
    "    hv_R[6 + k] = nz[k];\n"
    "  }\n"
    "  vec3 wo = vec3(t.x * v.x + t.y * v.y + t.z * v.z, b.x * v.x + b.y * v.y + b.z * v.z,\n"
    "                 nz.x * v.x + nz.y * v.y + nz.z * v.z);\n"
    "  int idx[4];\n"
    "  float w[4];\n"
    "  shl_brdf_table_cell(HVL_NT, 1, wo, idx, w);\n"
    "  float rho = sqrt(wo.x * wo.x + wo.y * wo.y);\n"
    "  for (int c = 0; c < nch; ++c) {\n"
    "    int off = int(rd_buf2[4 * mi + 1 + c] + 0.5);\n"
    "    float F[SHLIGHT_MAX_COEFFS];\n"
    "    for (int i = 0; i < SHLIGHT_MAX_COEFFS; ++i) F[i] = 0.0;\n"
    "    for (int i = 0; i < HVL_NBB; ++i) {\n"
    "      F[i] = (w[0] * rd_buf2[off + (2 * idx[0] + HVL_WHICH) * HVL_NBB + i] +\n"
    "              w[1] * rd_buf2[off + (2 * idx[1] + HVL_WHICH) * HVL_NBB + i]) +\n"
    "             (w[2] * rd_buf2[off + (2 * idx[2] + HVL_WHICH) * HVL_NBB + i] +\n"
    "              w[3] * rd_buf2[off + (2 * idx[3] + HVL_WHICH) * HVL_NBB + i]);\n"
    "    }\n"
    "    if (rho > 0.0) shl_sh_rotate_z(HVL_NB, wo.x / rho, wo.y / rho, F);\n"
    "    hv_F[c] = F;\n"
    "  }\n"
    "}\n"
    "#endif\n";

static const char *const gl_body =
    "void main() {\n"
    "  ivec2 px = rd_pixel();\n"
    "  vec4 P = texelFetch(rd_pos, px, 0);\n"
    "  vec4 N = texelFetch(rd_nrm, px, 0);\n"
    "  vec3 acc = vec3(0.0);\n"
    "  if (N.w >= 0.0) {\n"
    "    int mi = int(N.w + 0.5);\n"
    "    vec3 kd = vec3(rd_mats[12 * mi], rd_mats[12 * mi + 1], rd_mats[12 * mi + 2]);\n"
    "    vec3 x = P.xyz;\n"
    "    vec3 nx = N.xyz;\n"
    "    vec3 gx = texelFetch(rd_gnrm, px, 0).xyz;\n"
    "    vec3 spec = vec3(0.0);\n"
    "#if HVL_SPEC\n"
    "    int kind = int(rd_buf2[4 * mi] + 0.5);\n"
    "    int nch = kind == 2 ? 3 : 1;\n"
    "    float ysh[SHLIGHT_MAX_COEFFS];\n"
    "    if (kind != 0) hv_setup(mi, nch, x, nx);\n"
    "#endif\n"
    "#if HVL_METHOD >= 2\n"
    "    float fzh[SHLIGHT_MAX_BANDS];\n"
    "    float femit[SHLIGHT_MAX_COEFFS];\n"
    "    for (int k = 0; k < SHLIGHT_MAX_COEFFS; ++k) femit[k] = 0.0;\n"
    "    femit[0] = 1.1283791670955126;\n"
    "    shl_zh_lambert(HVL_BANDS, fzh);\n"
    "#endif\n"
    "    for (int j = 0; j < HVL_NL; ++j) {\n"
    "      int b = HVL_ST * j;\n"
    "      vec3 y = vec3(rd_buf1[b], rd_buf1[b + 1], rd_buf1[b + 2]);\n"
    "      vec3 ny = vec3(rd_buf1[b + 3], rd_buf1[b + 4], rd_buf1[b + 5]);\n"
    "      vec3 phi = vec3(rd_buf1[b + 6], rd_buf1[b + 7], rd_buf1[b + 8]);\n"
    "      vec3 gy = vec3(rd_buf1[b + 9], rd_buf1[b + 10], rd_buf1[b + 11]);\n"
    "      vec3 dv = y - x;\n"
    "      if (!(-(gy.x * dv.x + gy.y * dv.y + gy.z * dv.z) > HVL_EPS) ||\n"
    "          !(gx.x * dv.x + gx.y * dv.y + gx.z * dv.z > HVL_EPS)) continue;\n"
    "#if HVL_SPEC\n"
    "      vec3 yl = vec3(0.0);\n"
    "      if (kind != 0) {\n"
    "        yl = vec3(hv_R[0] * dv.x + hv_R[1] * dv.y + hv_R[2] * dv.z,\n"
    "                  hv_R[3] * dv.x + hv_R[4] * dv.y + hv_R[5] * dv.z,\n"
    "                  hv_R[6] * dv.x + hv_R[7] * dv.y + hv_R[8] * dv.z);\n"
    "      }\n"
    "#endif\n"
    "#if HVL_METHOD < 2\n"
    "      float d2 = dv.x * dv.x + dv.y * dv.y + dv.z * dv.z;\n"
    "      if (!(d2 > 0.0)) continue;\n"
    "      float d = sqrt(d2);\n"
    "      float cy = -(ny.x * dv.x + ny.y * dv.y + ny.z * dv.z) / d;\n"
    "      float cx = (nx.x * dv.x + nx.y * dv.y + nx.z * dv.z) / d;\n"
    "      if (!(cy > 0.0) || !(cx > 0.0)) continue;\n"
    "#if HVL_METHOD == 1\n"
    "      float rc = rd_buf1[b + 12];\n"
    "      if (d2 < rc * rc) d2 = rc * rc;\n"
    "#endif\n"
    "      float gf = cy * cx / (3.14159265 * d2);\n"
    "      acc += phi * gf;\n"
    "#if HVL_SPEC\n"
    "      if (kind != 0) {\n"
    "        shl_sh_eval(HVL_NB, vec3(yl.x / d, yl.y / d, yl.z / d), ysh);\n"
    "        for (int c = 0; c < 3; ++c)\n"
    "          spec[c] += phi[c] * gf * shl_sh_dot(HVL_NB, hv_F[nch == 3 ? c : 0], ysh);\n"
    "      }\n"
    "#endif\n"
    "#else\n"
    "      float r = rd_buf1[b + 12];\n"
    "      float lj = shl_hvl_radiance(1, femit, 1.0, x, nx, y, ny, r, 1);\n"
    "      if (!(lj > 0.0)) continue;\n"
    "      acc += phi * shl_hvl_contribution_zh(HVL_BANDS, lj, fzh, nx, x, y, r);\n"
    "#if HVL_SPEC\n"
    "      for (int c = 0; c < nch && kind != 0; ++c) {\n"
    "        float cs = shl_hvl_contribution(HVL_NB, lj, hv_F[c], vec3(0.0), yl, r);\n"
    "        if (nch == 3)\n"
    "          spec[c] += phi[c] * cs;\n"
    "        else\n"
    "          spec += phi * cs;\n"
    "      }\n"
    "#endif\n"
    "#endif\n"
    "    }\n"
    "#if HVL_METHOD < 2\n"
    "    acc = kd * acc * 0.318309886;\n"
    "#else\n"
    "    acc = kd * acc;\n"
    "#endif\n"
    "#if HVL_SPEC\n"
    "    vec3 ks = vec3(rd_mats[12 * mi + 3], rd_mats[12 * mi + 4], rd_mats[12 * mi + 5]);\n"
    "    if (kind == 2) acc = spec;\n"
    "    if (kind == 1) acc = acc + ks * spec;\n"
    "#endif\n"
    "  }\n"
    "  rd_out0 = vec4(acc, 1.0);\n"
    "}\n";

static int shade_gl(const rd_run *run, const hv_brdf *B, int method, const float *b, int nl,
                    float eps, float *rgb, double *ms) {
  static const char *const inc_hvl[8] = {"shl_prelude.glsl", "shl_basis.glsl", "shl_gradient.glsl",
                                         "shl_zonal.glsl",   "shl_light.glsl", "shl_brdf.glsl",
                                         "shl_brdftab.glsl", "shl_hvl.glsl"};
  static const char *const inc_vpl[1] = {"shl_prelude.glsl"};
  const rd_gbuf *gb = run->gb;
  char defs[512], *body;
  size_t npx = (size_t)gb->w * (size_t)gb->h, k, nf[2];
  float *out4 = (float *)malloc(npx * 4 * sizeof(float));
  float *outs[1];
  const float *bufs[2];
  rd_gl_pass p;
  int rc, spec = B->any, mb = run->bands > B->nb || !spec ? run->bands : B->nb;
  size_t lb = strlen(gl_spec) + strlen(gl_body) + 1;
  body = (char *)malloc(lb);
  if (!out4 || !body) {
    free(out4);
    free(body);
    return -1;
  }
  snprintf(body, lb, "%s%s", gl_spec, gl_body);
  /* HVL_METHOD: both HVL radii (2, 3) give the same shader (the radius is in the light set), so
     the second draws with the first's program (rd_gl_run reuses a program of the same source) */
  snprintf(defs, sizeof defs,
           "#define SHLIGHT_MAX_BANDS %d\n#define HVL_BANDS %d\n#define HVL_NL %d\n"
           "#define HVL_ST %d\n#define HVL_METHOD %d\n#define HVL_EPS %.9e\n"
           "#define HVL_SPEC %d\n#define HVL_NB %d\n#define HVL_NBB %d\n#define HVL_NT %d\n"
           "#define HVL_WHICH %d\n",
           mb, run->bands, nl, method_stride[method], method == M_HVL_FOV ? M_HVL_NB : method,
           (double)eps, spec, B->nb, B->nb * B->nb, HV_NT, method <= M_VPL_CLAMP ? 1 : 0);
  memset(&p, 0, sizeof p);
  p.defines = defs;
  p.includes = method <= M_VPL_CLAMP && !spec ? inc_vpl : inc_hvl;
  p.ninclude = method <= M_VPL_CLAMP && !spec ? 1 : 8;
  p.body = body;
  bufs[0] = b;
  bufs[1] = B->gpu;
  nf[0] = (size_t)nl * (size_t)method_stride[method];
  nf[1] = B->floats;
  p.bufs = bufs;
  p.buf_floats = nf;
  p.nbuf = spec ? 2 : 1;
  p.nout = 1;
  outs[0] = out4;
  rc = rd_gl_run(run->scene, gb, &p, outs, run->reps, ms);
  if (rc == 0)
    for (k = 0; k < npx; k++) {
      rgb[3 * k] = out4[4 * k];
      rgb[3 * k + 1] = out4[4 * k + 1];
      rgb[3 * k + 2] = out4[4 * k + 2];
    }
  free(out4);
  free(body);
  return rc;
}

/* ---- ground truth --------------------------------------------------------------------------- */
typedef struct {
  double q[4][3]; /* quad corners (world) */
  double ns[3];   /* quad normal (the shading normal of the centre) */
  double a;       /* quad area */
  int ok;         /* the quad is usable */
} gt_quad;

/* projected solid angle seen from x (normal nx) of the polygon v (relative to x), clipped to
   nx . v >= 0: Lambert's formula 1/2 sum_i angle(v_i, v_i+1) nx . unit(v_i x v_i+1) */
static double poly_projected(const double (*v)[3], int n, const double nx[3]) {
  double c[12][3], sum = 0;
  int i, k, nc = 0;
  for (i = 0; i < n; i++) {
    const double *a = v[i], *b = v[(i + 1) % n];
    double da = nx[0] * a[0] + nx[1] * a[1] + nx[2] * a[2];
    double db = nx[0] * b[0] + nx[1] * b[1] + nx[2] * b[2];
    if (da >= 0 && nc < 12) {
      memcpy(c[nc], a, sizeof c[nc]);
      nc++;
    }
    if ((da >= 0) != (db >= 0) && nc < 12) {
      double t = da / (da - db);
      for (k = 0; k < 3; k++)
        c[nc][k] = a[k] + t * (b[k] - a[k]);
      nc++;
    }
  }
  if (nc < 3) return 0;
  for (i = 0; i < nc; i++) {
    const double *a = c[i], *b = c[(i + 1) % nc];
    double la = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    double lb = sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
    double cr[3], s, dt;
    if (!(la > 0) || !(lb > 0)) continue;
    cr[0] = a[1] * b[2] - a[2] * b[1];
    cr[1] = a[2] * b[0] - a[0] * b[2];
    cr[2] = a[0] * b[1] - a[1] * b[0];
    s = sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]);
    if (!(s > 0)) continue;
    dt = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    sum += atan2(s, dt) * (cr[0] * nx[0] + cr[1] * nx[1] + cr[2] * nx[2]) / s;
  }
  return fabs(0.5 * sum);
}

typedef struct {
  int n;         /* patches */
  double *p;     /* 3n centres */
  double *ns;    /* 3n normals (shading) */
  double *ng;    /* 3n geometric normals */
  double *phi;   /* 3n flux / pi */
  double *near2; /* n: squared distance below which the quad is integrated exactly */
  gt_quad *quad; /* n */
} gt_patches;

static void gt_free(gt_patches *gp) {
  free(gp->p);
  free(gp->ns);
  free(gp->ng);
  free(gp->phi);
  free(gp->near2);
  free(gp->quad);
  memset(gp, 0, sizeof *gp);
}

/* the ray of rd_gbuffer_view through the image-plane point (sx, sy); returns 1 on a hit */
static int view_ray(const rd_scene *s, const spot_view *sv, double sx, double sy, float d[3],
                    rd_hit *h) {
  int c;
  for (c = 0; c < 3; c++)
    d[c] = sv->f[c] + (float)sx * sv->r[c] + (float)sy * sv->u[c];
  normf3(d);
  return rd_trace(s, sv->eye, d, 1e-6f, INFINITY, h);
}

/* distance along the ray c + t dir (dir need not be unit) to the plane through y with normal
   n; -1 when the ray does not cross it in front of the light */
static double plane_t(const spot_view *sv, const double dir[3], const double y[3],
                      const double n[3]) {
  double dc = 0, den = 0;
  int c;
  for (c = 0; c < 3; c++) {
    dc += (y[c] - (double)sv->eye[c]) * n[c];
    den += dir[c] * n[c];
  }
  return den != 0 && dc / den > 0 ? dc / den : -1.0;
}

static int gt_push(gt_patches *gp, int *cap) {
  if (gp->n == *cap) {
    int nc = *cap ? 2 * *cap : 4096;
    double *p = (double *)realloc(gp->p, (size_t)nc * 3 * sizeof(double));
    double *ns = p ? (double *)realloc(gp->ns, (size_t)nc * 3 * sizeof(double)) : NULL;
    double *ng = ns ? (double *)realloc(gp->ng, (size_t)nc * 3 * sizeof(double)) : NULL;
    double *phi = ng ? (double *)realloc(gp->phi, (size_t)nc * 3 * sizeof(double)) : NULL;
    double *n2 = phi ? (double *)realloc(gp->near2, (size_t)nc * sizeof(double)) : NULL;
    gt_quad *q = n2 ? (gt_quad *)realloc(gp->quad, (size_t)nc * sizeof(gt_quad)) : NULL;
    if (p) gp->p = p;
    if (ns) gp->ns = ns;
    if (ng) gp->ng = ng;
    if (phi) gp->phi = phi;
    if (n2) gp->near2 = n2;
    if (!q) return -1;
    gp->quad = q;
    *cap = nc;
  }
  return gp->n++;
}

/* One GT cell: the image-plane square centred at (sx, sy) of side p. Its centre ray gives the
   patch; the four corner rays (ct: their hit distances, -1 for a miss; NULL: trace them) cut
   the plane of the patch. A corner whose real hit is off that plane (an edge, a silhouette,
   a miss) marks a cell that straddles two surfaces: it is split 2 x 2, up to `depth` times, so
   that the quads tile the surfaces up to the edges. */
static int gt_cell(const rd_scene *s, const spot_view *sv, double sx, double sy, double p,
                   const double *ct, int depth, gt_patches *gp, int *cap) {
  rd_hit h;
  float dc[3];
  double phi[3], y[3], ns[3], ng[3], cd[4][3], tq[4], r2 = 0, t0;
  double om = texel_omega(sx, sy, p, sv->tcone);
  int c, k, split = 0, o, hit;
  gt_quad *q;
  if (!(om > 0)) return 0;
  hit = view_ray(s, sv, sx, sy, dc, &h);
  if (!hit) {
    split = 1; /* the centre misses: a corner may hit */
  } else {
    for (c = 0; c < 3; c++) {
      y[c] = (double)h.p[c];
      ns[c] = (double)h.n[c];
      ng[c] = (double)h.ng[c];
    }
    t0 = (double)h.t;
    for (k = 0; k < 4 && !split; k++) {
      double cx = sx + (k == 1 || k == 2 ? 0.5 : -0.5) * p, cy = sy + (k >= 2 ? 0.5 : -0.5) * p;
      double tc, tp, dl;
      float d1[3];
      rd_hit hc;
      for (c = 0; c < 3; c++)
        cd[k][c] = (double)sv->f[c] + cx * (double)sv->r[c] + cy * (double)sv->u[c];
      dl = sqrt(cd[k][0] * cd[k][0] + cd[k][1] * cd[k][1] + cd[k][2] * cd[k][2]);
      if (ct)
        tc = ct[k];
      else
        tc = view_ray(s, sv, cx, cy, d1, &hc) ? (double)hc.t : -1.0;
      tp = plane_t(sv, cd[k], y, ng) * dl;
      if (!(tc > 0) || !(tp > 0) || fabs(tc - tp) > 0.25 * t0 * p * dl) split = 1;
    }
  }
  if (split && depth > 0) {
    double cc[9], sub[4];
    int a, b, rc = 0;
    /* corner distances of the 3 x 3 sub-grid */
    for (b = 0; b < 3; b++)
      for (a = 0; a < 3; a++) {
        float d1[3];
        rd_hit hc;
        double cx = sx + 0.5 * p * (double)(a - 1), cy = sy + 0.5 * p * (double)(b - 1);
        cc[3 * b + a] = view_ray(s, sv, cx, cy, d1, &hc) ? (double)hc.t : -1.0;
      }
    for (b = 0; b < 2 && !rc; b++)
      for (a = 0; a < 2 && !rc; a++) {
        sub[0] = cc[3 * b + a];
        sub[1] = cc[3 * b + a + 1];
        sub[2] = cc[3 * (b + 1) + a + 1];
        sub[3] = cc[3 * (b + 1) + a];
        rc = gt_cell(s, sv, sx + 0.25 * p * (double)(2 * a - 1),
                     sy + 0.25 * p * (double)(2 * b - 1), 0.5 * p, sub, depth - 1, gp, cap);
      }
    return rc;
  }
  if (!hit || !texel_flux(s, sv, h.p, h.n, h.ng, h.mat, om, phi)) return 0;
  if ((o = gt_push(gp, cap)) < 0) return -1;
  q = &gp->quad[o];
  for (c = 0; c < 3; c++) {
    gp->p[3 * o + c] = y[c];
    gp->ns[3 * o + c] = ns[c];
    gp->ng[3 * o + c] = ng[c];
    gp->phi[3 * o + c] = phi[c] / HVL_PI;
    q->ns[c] = ns[c];
  }
  /* the emitting quad: the corner rays cut the plane through y with normal n_s */
  q->ok = 1;
  for (k = 0; k < 4; k++) {
    double cx = sx + (k == 1 || k == 2 ? 0.5 : -0.5) * p, cy = sy + (k >= 2 ? 0.5 : -0.5) * p;
    double dir[3];
    for (c = 0; c < 3; c++)
      dir[c] = (double)sv->f[c] + cx * (double)sv->r[c] + cy * (double)sv->u[c];
    tq[k] = plane_t(sv, dir, y, ns);
    /* a corner ray nearly parallel to the plane: no usable quad (point formula only) */
    if (!(tq[k] > 0) || tq[k] > 8.0 * (double)h.t) {
      q->ok = 0;
      break;
    }
    for (c = 0; c < 3; c++)
      q->q[k][c] = (double)sv->eye[c] + tq[k] * dir[c];
    r2 = fmax(r2, (q->q[k][0] - y[0]) * (q->q[k][0] - y[0]) +
                      (q->q[k][1] - y[1]) * (q->q[k][1] - y[1]) +
                      (q->q[k][2] - y[2]) * (q->q[k][2] - y[2]));
  }
  if (q->ok) {
    double e1[3], e2[3], cr[3];
    for (c = 0; c < 3; c++) {
      e1[c] = q->q[2][c] - q->q[0][c];
      e2[c] = q->q[3][c] - q->q[1][c];
    }
    cr[0] = e1[1] * e2[2] - e1[2] * e2[1];
    cr[1] = e1[2] * e2[0] - e1[0] * e2[2];
    cr[2] = e1[0] * e2[1] - e1[1] * e2[0];
    q->a = 0.5 * sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]);
    q->ok = q->a > 0;
  }
  gp->near2[o] = q->ok ? HVL_GT_NEAR * HVL_GT_NEAR * r2 : 0.0;
  return 0;
}

static int gt_build(const rd_run *run, const spot_view *sv, int N, gt_patches *gp) {
  const rd_scene *s = run->scene;
  double *ct, sx, sy, p, c4[4];
  int i, j, cap = 0, rc = 0;
  memset(gp, 0, sizeof *gp);
  /* hit distances of the (N + 1)^2 texel corners */
  ct = (double *)malloc((size_t)(N + 1) * (size_t)(N + 1) * sizeof(double));
  if (!ct) return -1;
  for (j = 0; j <= N; j++) {
    for (i = 0; i <= N; i++) {
      float d[3];
      rd_hit h;
      texel_plane(sv, N, N, i, j, &sx, &sy, &p);
      ct[(size_t)j * (size_t)(N + 1) + (size_t)i] =
          view_ray(s, sv, sx - 0.5 * p, sy + 0.5 * p, d, &h) ? (double)h.t : -1.0;
    }
    rd_progress("hvl gt rays", j + 1, N + 1);
  }
  for (j = 0; j < N && !rc; j++)
    for (i = 0; i < N && !rc; i++) {
      size_t k = (size_t)j * (size_t)(N + 1) + (size_t)i;
      texel_plane(sv, N, N, i, j, &sx, &sy, &p);
      /* corners in the order (-,-), (+,-), (+,+), (-,+) of (sx, sy); row j is at +sy */
      c4[0] = ct[k + (size_t)(N + 1)];
      c4[1] = ct[k + (size_t)(N + 1) + 1];
      c4[2] = ct[k + 1];
      c4[3] = ct[k];
      rc = gt_cell(s, sv, sx, sy, p, c4, 3, gp, &cap);
    }
  free(ct);
  if (rc) gt_free(gp);
  return rc;
}

/* the real BRDF of a table material (no SH): channel c of f_s (analytic, kd = 0, ks = 1) or
   of the measured f, at the local directions wo, wi */
static double gt_brdf(const hv_brdf *B, int m, int kind, int c, const float wo[3],
                      const float wi[3]) {
  return kind == HV_MEASURED ? (double)shl_merl_eval(B->merl, c, wo, wi)
                             : (double)shl_brdf_eval(&B->par[m], wo, wi);
}

/* the BRDF term of one emitting point p (world, normal ns, flux / pi phi[3] times weight wt)
   at x (normal nx, frame R, w_o wo): sum_c phi_c wt cos_y cos_x / d^2 f_c(wo, wi) into e */
static void gt_spec_point(const hv_brdf *B, int m, int kind, const double x[3], const double nx[3],
                          const float R[9], const float wo[3], const double p[3],
                          const double ns[3], const double *phi, double wt, double e[3]) {
  double dv[3] = {p[0] - x[0], p[1] - x[1], p[2] - x[2]}, d2, d, cy, cx, g;
  float wi[3];
  int c;
  d2 = dv[0] * dv[0] + dv[1] * dv[1] + dv[2] * dv[2];
  if (!(d2 > 0)) return;
  d = sqrt(d2);
  cy = -(ns[0] * dv[0] + ns[1] * dv[1] + ns[2] * dv[2]) / d;
  cx = (nx[0] * dv[0] + nx[1] * dv[1] + nx[2] * dv[2]) / d;
  if (!(cy > 0) || !(cx > 0)) return;
  g = wt * cy * cx / d2;
  for (c = 0; c < 3; c++)
    wi[c] = (float)(((double)R[3 * c] * dv[0] + (double)R[3 * c + 1] * dv[1] +
                     (double)R[3 * c + 2] * dv[2]) /
                    d);
  if (kind == HV_MEASURED)
    for (c = 0; c < 3; c++)
      e[c] += phi[c] * g * gt_brdf(B, m, kind, c, wo, wi);
  else {
    double f = gt_brdf(B, m, kind, 0, wo, wi);
    for (c = 0; c < 3; c++)
      e[c] += phi[c] * g * f;
  }
}

/* indirect radiance at every camera pixel: kd(x)/pi E(x) (Lambert), plus the table materials'
   f_s (analytic: ks f_s; measured: f, no Lambert term) with the real BRDF. Near a patch
   (d^2 < near2) the Lambert part is the exact polygon form factor and the BRDF part the
   point formula at the centres of 4 x 4 bilinear sub-quads (equal weights) */
typedef struct {
  const rd_run *run;
  const hv_brdf *B;
  const gt_patches *gp;
  double eps;
  float *rgb;
  int avx;     /* the AVX lanes (gt_lambert_pk_avx) */
  long *check; /* SHLIGHT_RENDER_GT_CHECK: sums compared with the scalar loop's, sums that differ */
} gt_job;

/* patch j's Lambert term at x into e: the loop body of gt_shade for a Lambert pixel (the same
   operations in the same order) */
static inline void gt_lambert(const gt_patches *gp, int j, double eps, const double x[3],
                              const double nx[3], const double gx[3], double e[3]) {
  const double *p = gp->p + 3 * j, *ns = gp->ns + 3 * j, *phi = gp->phi + 3 * j;
  const double *ng = gp->ng + 3 * j;
  double dx = p[0] - x[0], dy = p[1] - x[1], dz = p[2] - x[2];
  double d2 = dx * dx + dy * dy + dz * dz, cy, cx, gf;
  int c;
  if (!(-(ng[0] * dx + ng[1] * dy + ng[2] * dz) > eps) ||
      !(gx[0] * dx + gx[1] * dy + gx[2] * dz > eps))
    return;
  if (d2 < gp->near2[j]) {
    const gt_quad *q = &gp->quad[j];
    double v[4][3], side, ps;
    int k, kk;
    for (kk = 0; kk < 4; kk++)
      for (k = 0; k < 3; k++)
        v[kk][k] = q->q[kk][k] - x[k];
    side = -(dx * q->ns[0] + dy * q->ns[1] + dz * q->ns[2]);
    if (!(side > 1e-9 * sqrt(d2 + q->a))) return;
    ps = poly_projected((const double(*)[3])v, 4, nx) / q->a;
    for (c = 0; c < 3; c++)
      e[c] += phi[c] * ps;
    return;
  }
  cy = -(ns[0] * dx + ns[1] * dy + ns[2] * dz);
  cx = nx[0] * dx + nx[1] * dy + nx[2] * dz;
  if (!(cy > 0) || !(cx > 0) || !(d2 > 0)) return;
  gf = cy * cx / (d2 * d2);
  e[0] += phi[0] * gf;
  e[1] += phi[1] * gf;
  e[2] += phi[2] * gf;
}

#define GT_PK 16 /* Lambert pixels that share one pass over the patches */

#if defined(__SSE2__)
/* gt_lambert for patch j at GT_PK pixels (nq of them used; the others copy pixel 0 and are
   dropped), two per SSE2 vector: per lane the far-field operations of gt_lambert in the same
   order (no contraction: -ffp-contract=off), a lane that skips the patch adds phi * 0 = +0 to a
   sum that is +0 or positive, and a lane near the patch takes gt_lambert itself, so every sum
   is bit for bit the scalar loop's. E: the sums, [pair][channel] */
static void gt_lambert_pk(const gt_patches *gp, int nq, double eps, double (*qx)[3],
                          double (*qn)[3], double (*qg)[3], double (*qe)[3]) {
  const __m128d zero = _mm_setzero_pd(), ve = _mm_set1_pd(eps), sgn = _mm_set1_pd(-0.0);
  __m128d X[GT_PK / 2][3], N[GT_PK / 2][3], G[GT_PK / 2][3], E[GT_PK / 2][3];
  double tmp[6];
  int j, h, c, t;
  for (h = 0; h < GT_PK / 2; h++)
    for (c = 0; c < 3; c++) {
      int a = 2 * h < nq ? 2 * h : 0, b = 2 * h + 1 < nq ? 2 * h + 1 : 0;
      X[h][c] = _mm_set_pd(qx[b][c], qx[a][c]);
      N[h][c] = _mm_set_pd(qn[b][c], qn[a][c]);
      G[h][c] = _mm_set_pd(qg[b][c], qg[a][c]);
      E[h][c] = zero;
    }
  for (j = 0; j < gp->n; j++) {
    const double *p = gp->p + 3 * j, *ns = gp->ns + 3 * j, *phi = gp->phi + 3 * j;
    const double *ng = gp->ng + 3 * j;
    const __m128d p0 = _mm_set1_pd(p[0]), p1 = _mm_set1_pd(p[1]), p2 = _mm_set1_pd(p[2]);
    const __m128d ng0 = _mm_set1_pd(ng[0]), ng1 = _mm_set1_pd(ng[1]), ng2 = _mm_set1_pd(ng[2]);
    const __m128d near2 = _mm_set1_pd(gp->near2[j]);
    for (h = 0; h < (nq + 1) / 2; h++) {
      __m128d dx = _mm_sub_pd(p0, X[h][0]), dy = _mm_sub_pd(p1, X[h][1]);
      __m128d dz = _mm_sub_pd(p2, X[h][2]);
      __m128d d2 =
          _mm_add_pd(_mm_add_pd(_mm_mul_pd(dx, dx), _mm_mul_pd(dy, dy)), _mm_mul_pd(dz, dz));
      __m128d a = _mm_xor_pd(
          _mm_add_pd(_mm_add_pd(_mm_mul_pd(ng0, dx), _mm_mul_pd(ng1, dy)), _mm_mul_pd(ng2, dz)),
          sgn);
      __m128d b = _mm_add_pd(_mm_add_pd(_mm_mul_pd(G[h][0], dx), _mm_mul_pd(G[h][1], dy)),
                             _mm_mul_pd(G[h][2], dz));
      __m128d gate = _mm_and_pd(_mm_cmpgt_pd(a, ve), _mm_cmpgt_pd(b, ve));
      __m128d nr = _mm_and_pd(gate, _mm_cmplt_pd(d2, near2));
      __m128d cy, cx, ok, gf;
      int mg = _mm_movemask_pd(gate), mn;
      if (mg == 0) continue;
      mn = _mm_movemask_pd(nr);
      if (mn) { /* near the patch: the exact quad, gt_lambert itself, for those lanes */
        for (c = 0; c < 3; c++)
          _mm_storeu_pd(tmp + 2 * c, E[h][c]);
        for (t = 0; t < 2; t++)
          if ((mn >> t & 1) && 2 * h + t < nq) {
            double e[3];
            for (c = 0; c < 3; c++)
              e[c] = tmp[2 * c + t];
            gt_lambert(gp, j, eps, qx[2 * h + t], qn[2 * h + t], qg[2 * h + t], e);
            for (c = 0; c < 3; c++)
              tmp[2 * c + t] = e[c];
          }
        for (c = 0; c < 3; c++)
          E[h][c] = _mm_loadu_pd(tmp + 2 * c);
        if (mn == mg) continue;
      }
      cy = _mm_xor_pd(_mm_add_pd(_mm_add_pd(_mm_mul_pd(_mm_set1_pd(ns[0]), dx),
                                            _mm_mul_pd(_mm_set1_pd(ns[1]), dy)),
                                 _mm_mul_pd(_mm_set1_pd(ns[2]), dz)),
                      sgn);
      cx = _mm_add_pd(_mm_add_pd(_mm_mul_pd(N[h][0], dx), _mm_mul_pd(N[h][1], dy)),
                      _mm_mul_pd(N[h][2], dz));
      ok = _mm_andnot_pd(nr, gate);
      ok = _mm_and_pd(ok, _mm_and_pd(_mm_cmpgt_pd(cy, zero), _mm_cmpgt_pd(cx, zero)));
      ok = _mm_and_pd(ok, _mm_cmpgt_pd(d2, zero));
      if (_mm_movemask_pd(ok) == 0) continue;
      gf = _mm_and_pd(ok, _mm_div_pd(_mm_mul_pd(cy, cx), _mm_mul_pd(d2, d2)));
      E[h][0] = _mm_add_pd(E[h][0], _mm_mul_pd(_mm_set1_pd(phi[0]), gf));
      E[h][1] = _mm_add_pd(E[h][1], _mm_mul_pd(_mm_set1_pd(phi[1]), gf));
      E[h][2] = _mm_add_pd(E[h][2], _mm_mul_pd(_mm_set1_pd(phi[2]), gf));
    }
  }
  for (h = 0; h < (nq + 1) / 2; h++)
    for (c = 0; c < 3; c++) {
      _mm_storeu_pd(tmp + 2 * c, E[h][c]);
      for (t = 0; t < 2; t++)
        if (2 * h + t < nq) qe[2 * h + t][c] = tmp[2 * c + t];
    }
}
#endif

#if HVL_AVX
/* gt_lambert_pk four pixels per AVX vector: the same per-lane operations in the same order
   (AVX has no fused multiply-add, so no contraction either), so every sum is bit for bit the
   scalar loop's; chosen at run time where the CPU has AVX */
__attribute__((target("avx"))) static void gt_lambert_pk_avx(const gt_patches *gp, int nq,
                                                             double eps, double (*qx)[3],
                                                             double (*qn)[3], double (*qg)[3],
                                                             double (*qe)[3]) {
  const __m256d zero = _mm256_setzero_pd(), ve = _mm256_set1_pd(eps);
  const __m256d sgn = _mm256_set1_pd(-0.0);
  __m256d X[GT_PK / 4][3], N[GT_PK / 4][3], G[GT_PK / 4][3], E[GT_PK / 4][3];
  double tmp[12];
  int j, h, c, t;
  for (h = 0; h < GT_PK / 4; h++)
    for (c = 0; c < 3; c++) {
      int i0 = 4 * h < nq ? 4 * h : 0, i1 = 4 * h + 1 < nq ? 4 * h + 1 : 0;
      int i2 = 4 * h + 2 < nq ? 4 * h + 2 : 0, i3 = 4 * h + 3 < nq ? 4 * h + 3 : 0;
      X[h][c] = _mm256_set_pd(qx[i3][c], qx[i2][c], qx[i1][c], qx[i0][c]);
      N[h][c] = _mm256_set_pd(qn[i3][c], qn[i2][c], qn[i1][c], qn[i0][c]);
      G[h][c] = _mm256_set_pd(qg[i3][c], qg[i2][c], qg[i1][c], qg[i0][c]);
      E[h][c] = zero;
    }
  for (j = 0; j < gp->n; j++) {
    const double *p = gp->p + 3 * j, *ns = gp->ns + 3 * j, *phi = gp->phi + 3 * j;
    const double *ng = gp->ng + 3 * j;
    const __m256d p0 = _mm256_set1_pd(p[0]), p1 = _mm256_set1_pd(p[1]);
    const __m256d p2 = _mm256_set1_pd(p[2]);
    const __m256d ng0 = _mm256_set1_pd(ng[0]), ng1 = _mm256_set1_pd(ng[1]);
    const __m256d ng2 = _mm256_set1_pd(ng[2]);
    const __m256d near2 = _mm256_set1_pd(gp->near2[j]);
    for (h = 0; h < (nq + 3) / 4; h++) {
      __m256d dx = _mm256_sub_pd(p0, X[h][0]), dy = _mm256_sub_pd(p1, X[h][1]);
      __m256d dz = _mm256_sub_pd(p2, X[h][2]);
      __m256d d2 = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)),
                                 _mm256_mul_pd(dz, dz));
      __m256d a =
          _mm256_xor_pd(_mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(ng0, dx), _mm256_mul_pd(ng1, dy)),
                                      _mm256_mul_pd(ng2, dz)),
                        sgn);
      __m256d b =
          _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(G[h][0], dx), _mm256_mul_pd(G[h][1], dy)),
                        _mm256_mul_pd(G[h][2], dz));
      __m256d gate =
          _mm256_and_pd(_mm256_cmp_pd(a, ve, _CMP_GT_OQ), _mm256_cmp_pd(b, ve, _CMP_GT_OQ));
      __m256d nr = _mm256_and_pd(gate, _mm256_cmp_pd(d2, near2, _CMP_LT_OQ));
      __m256d cy, cx, ok, gf;
      int mg = _mm256_movemask_pd(gate), mn;
      if (mg == 0) continue;
      mn = _mm256_movemask_pd(nr);
      if (mn) { /* near the patch: the exact quad, gt_lambert itself, for those lanes */
        for (c = 0; c < 3; c++)
          _mm256_storeu_pd(tmp + 4 * c, E[h][c]);
        for (t = 0; t < 4; t++)
          if ((mn >> t & 1) && 4 * h + t < nq) {
            double e[3];
            for (c = 0; c < 3; c++)
              e[c] = tmp[4 * c + t];
            gt_lambert(gp, j, eps, qx[4 * h + t], qn[4 * h + t], qg[4 * h + t], e);
            for (c = 0; c < 3; c++)
              tmp[4 * c + t] = e[c];
          }
        for (c = 0; c < 3; c++)
          E[h][c] = _mm256_loadu_pd(tmp + 4 * c);
        if (mn == mg) continue;
      }
      cy = _mm256_xor_pd(_mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(_mm256_set1_pd(ns[0]), dx),
                                                     _mm256_mul_pd(_mm256_set1_pd(ns[1]), dy)),
                                       _mm256_mul_pd(_mm256_set1_pd(ns[2]), dz)),
                         sgn);
      cx = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(N[h][0], dx), _mm256_mul_pd(N[h][1], dy)),
                         _mm256_mul_pd(N[h][2], dz));
      ok = _mm256_andnot_pd(nr, gate);
      ok = _mm256_and_pd(ok, _mm256_and_pd(_mm256_cmp_pd(cy, zero, _CMP_GT_OQ),
                                           _mm256_cmp_pd(cx, zero, _CMP_GT_OQ)));
      ok = _mm256_and_pd(ok, _mm256_cmp_pd(d2, zero, _CMP_GT_OQ));
      if (_mm256_movemask_pd(ok) == 0) continue;
      gf = _mm256_and_pd(ok, _mm256_div_pd(_mm256_mul_pd(cy, cx), _mm256_mul_pd(d2, d2)));
      E[h][0] = _mm256_add_pd(E[h][0], _mm256_mul_pd(_mm256_set1_pd(phi[0]), gf));
      E[h][1] = _mm256_add_pd(E[h][1], _mm256_mul_pd(_mm256_set1_pd(phi[1]), gf));
      E[h][2] = _mm256_add_pd(E[h][2], _mm256_mul_pd(_mm256_set1_pd(phi[2]), gf));
    }
  }
  for (h = 0; h < (nq + 3) / 4; h++)
    for (c = 0; c < 3; c++) {
      _mm256_storeu_pd(tmp + 4 * c, E[h][c]);
      for (t = 0; t < 4; t++)
        if (4 * h + t < nq) qe[4 * h + t][c] = tmp[4 * c + t];
    }
}
#endif

static void gt_shade(void *ctx, long lo, long hi) {
  const gt_job *jb = (const gt_job *)ctx;
  const rd_run *run = jb->run;
  const hv_brdf *B = jb->B;
  const gt_patches *gp = jb->gp;
  const double eps = jb->eps;
  float *rgb = jb->rgb;
  const rd_gbuf *gb = run->gb;
  const rd_scene *s = run->scene;
  int px, j, c, t, nq = 0, qp[GT_PK];
  long nsum = 0, nbad = 0;
  double qx[GT_PK][3], qn[GT_PK][3], qg[GT_PK][3], qe[GT_PK][3];
  for (px = (int)lo; px <= (int)hi; px++) {
    double x[3], nx[3], gx[3], e[3] = {0, 0, 0}, es[3] = {0, 0, 0};
    float R[9], wo[3];
    int m = px < (int)hi ? gb->mat[px] : -1, kind = hv_kind(B, m);
    /* Lambert pixels: GT_PK at a time, each summing the patches in the order of the loop
       below (the same sums); the pending ones when the row ends or a glossy pixel comes */
    if (px < (int)hi && m >= 0 && m < s->nmats && kind == HV_LAMBERT) {
      for (c = 0; c < 3; c++) {
        qx[nq][c] = (double)gb->pos[3 * px + c];
        qn[nq][c] = (double)gb->nrm[3 * px + c];
        qg[nq][c] = (double)gb->gnrm[3 * px + c];
        qe[nq][c] = 0.0;
      }
      qp[nq++] = px;
      if (nq < GT_PK && px + 1 < (int)hi) continue;
    }
    if (nq > 0) {
#if HVL_AVX
      if (jb->avx)
        gt_lambert_pk_avx(gp, nq, eps, qx, qn, qg, qe);
      else
#endif
#if defined(__SSE2__)
        gt_lambert_pk(gp, nq, eps, qx, qn, qg, qe);
#else
      for (j = 0; j < gp->n; j++)
        for (t = 0; t < nq; t++)
          gt_lambert(gp, j, eps, qx[t], qn[t], qg[t], qe[t]);
#endif
      for (t = 0; t < nq; t++) {
        int mt = gb->mat[qp[t]];
        for (c = 0; c < 3; c++)
          rgb[3 * qp[t] + c] = (float)((double)s->mats[mt].kd[c] / HVL_PI * qe[t][c]);
      }
      if (jb->check) /* the lanes against the scalar loop, bit for bit */
        for (t = 0; t < nq; t++) {
          double e1[3] = {0, 0, 0};
          for (j = 0; j < gp->n; j++)
            gt_lambert(gp, j, eps, qx[t], qn[t], qg[t], e1);
          for (c = 0; c < 3; c++) {
            nsum++;
            nbad += memcmp(&e1[c], &qe[t][c], sizeof(double)) != 0;
          }
        }
      nq = 0;
    }
    if (px >= (int)hi || (m >= 0 && m < s->nmats && kind == HV_LAMBERT)) continue;
    if (m < 0 || m >= s->nmats) {
      rgb[3 * px] = rgb[3 * px + 1] = rgb[3 * px + 2] = 0.0f;
      continue;
    }
    for (c = 0; c < 3; c++) {
      x[c] = (double)gb->pos[3 * px + c];
      nx[c] = (double)gb->nrm[3 * px + c];
      gx[c] = (double)gb->gnrm[3 * px + c];
    }
    if (kind != HV_LAMBERT) hv_local(gb->pos + 3 * px, gb->nrm + 3 * px, gb->eye, R, wo);
    for (j = 0; j < gp->n; j++) {
      const double *p = gp->p + 3 * j, *ns = gp->ns + 3 * j, *phi = gp->phi + 3 * j;
      const double *ng = gp->ng + 3 * j;
      double dx = p[0] - x[0], dy = p[1] - x[1], dz = p[2] - x[2];
      double d2 = dx * dx + dy * dy + dz * dz, cy, cx, gf;
      /* the methods' geometric gate */
      if (!(-(ng[0] * dx + ng[1] * dy + ng[2] * dz) > eps) ||
          !(gx[0] * dx + gx[1] * dy + gx[2] * dz > eps))
        continue;
      if (d2 < gp->near2[j]) {
        const gt_quad *q = &gp->quad[j];
        double v[4][3], side = 0, ps;
        int k, kk;
        for (kk = 0; kk < 4; kk++)
          for (k = 0; k < 3; k++)
            v[kk][k] = q->q[kk][k] - x[k];
        /* x must be in front of the patch (it emits on its normal's side only) */
        side = -(dx * q->ns[0] + dy * q->ns[1] + dz * q->ns[2]);
        if (!(side > 1e-9 * sqrt(d2 + q->a))) continue;
        ps = poly_projected((const double(*)[3])v, 4, nx) / q->a; /* pi * radiance / flux */
        for (c = 0; c < 3; c++)
          e[c] += phi[c] * ps;
        if (kind != HV_LAMBERT) {
          int a, bb;
          for (bb = 0; bb < 4; bb++)
            for (a = 0; a < 4; a++) {
              double u = ((double)a + 0.5) / 4.0, w = ((double)bb + 0.5) / 4.0, pt[3];
              for (k = 0; k < 3; k++)
                pt[k] = (1 - u) * (1 - w) * q->q[0][k] + u * (1 - w) * q->q[1][k] +
                        u * w * q->q[2][k] + (1 - u) * w * q->q[3][k];
              gt_spec_point(B, m, kind, x, nx, R, wo, pt, ns, phi, 1.0 / 16.0, es);
            }
        }
        continue;
      }
      if (kind != HV_LAMBERT) gt_spec_point(B, m, kind, x, nx, R, wo, p, ns, phi, 1.0, es);
      cy = -(ns[0] * dx + ns[1] * dy + ns[2] * dz);
      cx = nx[0] * dx + nx[1] * dy + nx[2] * dz;
      if (!(cy > 0) || !(cx > 0) || !(d2 > 0)) continue;
      gf = cy * cx / (d2 * d2);
      e[0] += phi[0] * gf;
      e[1] += phi[1] * gf;
      e[2] += phi[2] * gf;
    }
    for (c = 0; c < 3; c++) {
      double dif = (double)s->mats[m].kd[c] / HVL_PI * e[c];
      rgb[3 * px + c] = (float)(kind == HV_MEASURED   ? es[c]
                                : kind == HV_ANALYTIC ? dif + (double)s->mats[m].ks[c] * es[c]
                                                      : dif);
    }
  }
  if (jb->check) {
    __atomic_add_fetch(&jb->check[0], nsum, __ATOMIC_RELAXED);
    __atomic_add_fetch(&jb->check[1], nbad, __ATOMIC_RELAXED);
  }
}

/* the gt image on rd_threads() threads; *ms: the CPU ms of all of them */
static int gt_image(const rd_run *run, const hv_brdf *B, const spot_view *sv, int N, double eps,
                    float *rgb, int *npatch, double *ms, int bg) {
  double t0 = rd_cpu_ms();
  gt_patches gp;
  gt_job jb;
  char label[32];
  long check[2] = {0, 0};
  if (gt_build(run, sv, N, &gp)) return -1;
  snprintf(label, sizeof label, "hvl gt %d", N);
  jb.run = run;
  jb.B = B;
  jb.gp = &gp;
  jb.eps = eps;
  jb.rgb = rgb;
  jb.avx = rd_use_avx(HVL_AVX);
  jb.check = getenv("SHLIGHT_RENDER_GT_CHECK") ? check : NULL;
  t0 = rd_cpu_ms() - t0; /* the patches, on this thread */
  t0 += (bg ? rd_parallel_bg : rd_parallel)((long)run->gb->w * run->gb->h, run->gb->w, gt_shade,
                                            &jb, label);
  if (jb.check)
    fprintf(stderr, "%s: %s lanes vs the scalar loop: %ld of %ld sums differ\n", label,
            jb.avx ? "AVX" : HVL_LANES_NAME, check[1], check[0]);
  if (ms) *ms = t0;
  if (npatch) *npatch = gp.n;
  gt_free(&gp);
  return 0;
}

/* the ground truth and its N / 2 twin, on a thread of its own beside the methods (rd_bg_ok) or
   inline; what the pass prints of it is printed once it is joined */
typedef struct {
  const rd_run *run;
  const hv_brdf *B;
  const spot_view *sv;
  int n1, bg, rc, half_ok, np1, np2;
  double eps, ms, ms2, wall; /* ms: the N image's CPU ms (its table entry), ms2 the N / 2 one's */
  float *gt, *half;
} gt_task;

static void *gt_task_run(void *a) {
  gt_task *t = (gt_task *)a;
  rd_tm t0 = rd_tm_now();
  double c0;
  if (t->bg) rd_thread_nice();
  c0 = rd_cpu_ms();
  t->rc = gt_image(t->run, t->B, t->sv, t->n1, t->eps, t->gt, &t->np1, &t->ms, t->bg);
  if (!t->rc)
    t->half_ok =
        gt_image(t->run, t->B, t->sv, t->n1 / 2, t->eps, t->half, &t->np2, &t->ms2, t->bg) == 0;
  /* this thread's own CPU time (the patches) is background work too; the rows count theirs */
  if (t->bg) rd_bg_add_cpu(rd_cpu_ms() - c0);
  t->wall = rd_tm_now().wall - t0.wall;
  return NULL;
}

/* ---- error statistics ----------------------------------------------------------------------- */
static int cmp_float(const void *a, const void *b) {
  float x = *(const float *)a, y = *(const float *)b;
  return x < y ? -1 : x > y;
}

static int cmp_d(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return x < y ? -1 : x > y;
}

static double image_peak(const rd_gbuf *gb, const float *ref) {
  size_t i, n = (size_t)gb->w * (size_t)gb->h;
  double peak = 0;
  for (i = 0; i < n * 3; i++)
    if (gb->mat[i / 3] >= 0 && (double)ref[i] > peak) peak = (double)ref[i];
  return peak;
}

/* p99 and max over the foreground pixels of max_rgb |a - ref| / peak(ref); rmse / peak */
static void err_stats(const rd_gbuf *gb, const float *a, const float *ref, double *p99, double *mx,
                      double *rmse) {
  size_t i, n = (size_t)gb->w * (size_t)gb->h, cnt = 0;
  double peak = image_peak(gb, ref), se = 0;
  float *e = (float *)malloc((n ? n : 1) * sizeof(float));
  *p99 = *mx = *rmse = (double)NAN;
  if (!e || !(peak > 0)) {
    free(e);
    return;
  }
  for (i = 0; i < n; i++) {
    double m = 0;
    int c;
    if (gb->mat[i] < 0) continue;
    for (c = 0; c < 3; c++) {
      double d = fabs((double)a[3 * i + (size_t)c] - (double)ref[3 * i + (size_t)c]);
      se += d * d;
      if (!(d <= m)) m = d;
    }
    e[cnt++] = (float)(m / peak);
  }
  if (cnt) {
    qsort(e, cnt, sizeof(float), cmp_float);
    *p99 = (double)e[(size_t)(0.99 * (double)(cnt - 1) + 0.5)];
    *mx = (double)e[cnt - 1];
    *rmse = sqrt(se / (3.0 * (double)cnt)) / peak;
  }
  free(e);
}

static int env_int(const char *name, int def, int lo, int hi) {
  const char *v = getenv(name);
  int x;
  if (!v || !*v || sscanf(v, "%d", &x) != 1 || x < lo || x > hi) return def;
  return x;
}

/* ---- the pass ------------------------------------------------------------------------------- */
int rd_pass_hvl(rd_run *run) {
  const rd_scene *s = run->scene;
  const rd_gbuf *gb = run->gb;
  const rd_light *l = NULL;
  spot_view sv;
  light_set ls;
  hv_brdf B;
  int *sel = NULL;
  size_t npx, nb;
  float eps;
  float *gt = NULL, *cpu = NULL;
  int i, method, rc = 0, rsm = env_int("SHLIGHT_HVL_RSM", 16, 2, 1024), gt_started = 0;
  gt_task gtt;
  pthread_t gth;
  rd_image cimg[M_COUNT], gimg[M_COUNT];
  double cms[M_COUNT], gms[M_COUNT];
  size_t mem[M_COUNT];
  for (i = 0; i < s->nlights; i++)
    if (s->lights[i].type == RD_LIGHT_SPOT) {
      l = &s->lights[i];
      break;
    }
  if (!l || !gb) return 0;
  if (run->bands < 1 || run->bands > SHLIGHT_MAX_BANDS) {
    fprintf(stderr, "hvl: bands %d out of [1, %d]\n", run->bands, SHLIGHT_MAX_BANDS);
    return -1;
  }
  npx = (size_t)gb->w * (size_t)gb->h;
  {
    double dg = 0;
    for (i = 0; i < 3; i++)
      dg += ((double)s->bmax[i] - (double)s->bmin[i]) * ((double)s->bmax[i] - (double)s->bmin[i]);
    eps = (float)(1e-5 * sqrt(dg));
  }
  nb = npx * 3 * sizeof(float);
  spot_setup(l, &sv);
  if (rsm_lights(run, &sv, rsm, rsm, &ls)) {
    fprintf(stderr, "hvl: cannot build the RSM\n");
    return -1;
  }
  if (hv_brdf_build(run, &B)) {
    fprintf(stderr, "hvl: cannot build the BRDF tables\n");
    hv_brdf_free(&B);
    free(ls.buf);
    return -1;
  }
  if (B.any) {
    sel = (int *)calloc((size_t)(s->nmats > 0 ? s->nmats : 1), sizeof(int));
    if (!sel) {
      hv_brdf_free(&B);
      free(ls.buf);
      return -1;
    }
    for (i = 0; i < s->nmats; i++)
      sel[i] = hv_kind(&B, i) != HV_LAMBERT;
  }
  {
    double r1 = 0, r2 = 0;
    for (i = 0; i < ls.count; i++) {
      r1 += (double)ls.buf[(size_t)i * HVL_STRIDE + 12];
      r2 += (double)ls.buf[(size_t)i * HVL_STRIDE + 13];
    }
    printf("hvl: spot at (%.3g, %.3g, %.3g), half-angle %.1f deg; RSM %dx%d, %d lights, "
           "%d bands; mean radius r1 (neighbours) %.3g, r2 (fov) %.3g\n",
           (double)l->c[0], (double)l->c[1], (double)l->c[2], (double)sv.fov * 90.0 / HVL_PI, rsm,
           rsm, ls.count, run->bands, ls.count ? r1 / ls.count : 0.0,
           ls.count ? r2 / ls.count : 0.0);
  }
  /* the ground truth: on a thread of its own while the methods run (the pass processes run at
     the same time: their GL work goes first), else here; the statistics, which need it, are
     printed once it is joined, in the order of before */
  memset(&gtt, 0, sizeof gtt);
  memset(cimg, 0, sizeof cimg);
  memset(gimg, 0, sizeof gimg);
  if (run->gt) {
    gtt.run = run;
    gtt.B = &B;
    gtt.sv = &sv;
    gtt.n1 = env_int("SHLIGHT_HVL_GT", run->gt >= 2 ? 512 : 128, 4, 4096);
    gtt.eps = (double)eps;
    gtt.gt = (float *)malloc(nb);
    gtt.half = (float *)malloc(nb);
    gtt.rc = -1;
    if (gtt.gt && gtt.half) {
      gt_started = rd_bg_start(&gth, gt_task_run, &gtt, &gtt.bg);
    }
  }
  for (method = 0; method < M_COUNT && rc == 0; method++) {
    float *b = method_buffer(&ls, method);
    if (!b) {
      rc = -1;
      break;
    }
    mem[method] = (size_t)ls.count * (size_t)method_stride[method] * sizeof(float);
    if (run->use_cpu) {
      double t[64];
      int r, reps = run->reps < 1 ? 1 : run->reps > 64 ? 64 : run->reps;
      cimg[method] = rd_image_new(gb->w, gb->h);
      if (!cimg[method].rgb) {
        free(b);
        rc = -1;
        break;
      }
      for (r = 0; r < reps; r++) {
        t[r] = shade_cpu(run, &B, method, b, ls.count, eps, cimg[method].rgb);
        if (t[r] > 2000.0) { /* slow: one timing is enough */
          reps = r + 1;
          break;
        }
      }
      qsort(t, (size_t)reps, sizeof(double), cmp_d);
      cms[method] = t[reps / 2];
    }
    if (run->use_gl) {
      rd_image im = rd_image_new(gb->w, gb->h);
      double ms = 0;
      if (!im.rgb || run->bands > 16) {
        if (run->bands > 16)
          fprintf(stderr, "hvl: GLSL kernels take at most 16 bands; no gl path\n");
        rd_image_free(&im);
      } else if (shade_gl(run, &B, method, b, ls.count, eps, im.rgb, &ms)) {
        fprintf(stderr, "hvl: %s: GL pass failed\n", method_name[method]);
        rd_image_free(&im);
        rc = -1;
      } else {
        gimg[method] = im;
        gms[method] = ms;
      }
    }
    free(b);
  }
  if (gt_started) pthread_join(gth, NULL);
  if (run->gt) {
    if (gtt.rc) {
      fprintf(stderr, "hvl: ground truth failed\n");
      rc = -1;
    } else {
      double p99, mx, rmse;
      if (gtt.half_ok) {
        err_stats(gb, gtt.half, gtt.gt, &p99, &mx, &rmse);
        printf("hvl gt convergence: RSM %dx%d (%d patches) vs %dx%d (%d patches): "
               "rmse/peak %.3g, p99 %.3g, max %.3g (the error of the coarse one; second order)\n",
               gtt.n1 / 2, gtt.n1 / 2, gtt.np2, gtt.n1, gtt.n1, gtt.np1, rmse, p99, mx);
      }
      rd_tm_add_ms(RD_TM_GT, gtt.wall, gtt.ms + gtt.ms2);
      gt = gtt.gt;
      gtt.gt = NULL;
      {
        rd_image im = rd_image_new(gb->w, gb->h);
        if (im.rgb) {
          memcpy(im.rgb, gt, nb);
          rd_emit(run, "hvl", "gt", "gt", im, gtt.ms, 0, 0);
        }
      }
    }
  }
  for (method = 0; method < M_COUNT && rc == 0; method++) {
    if (cimg[method].rgb) {
      if (gt) {
        double p99, mx, rmse;
        err_stats(gb, cimg[method].rgb, gt, &p99, &mx, &rmse);
        printf("hvl %-15s cpu: |m - gt|/peak p99 %.4f max %.4f (rmse/peak %.4f)\n",
               method_name[method], p99, mx, rmse);
      }
      cpu = (float *)malloc(nb);
      if (cpu) memcpy(cpu, cimg[method].rgb, nb);
      rd_emit(run, "hvl", method_name[method], "cpu", cimg[method], cms[method], mem[method], 0);
      cimg[method].rgb = NULL;
    }
    if (gimg[method].rgb) {
      rd_image im = gimg[method];
      gimg[method].rgb = NULL;
      if (gt) {
        double p99, mx, rmse;
        err_stats(gb, im.rgb, gt, &p99, &mx, &rmse);
        printf("hvl %-15s gl:  |m - gt|/peak p99 %.4f max %.4f (rmse/peak %.4f)\n",
               method_name[method], p99, mx, rmse);
      }
      if (cpu) {
        double p99, mx, rmse;
        err_stats(gb, im.rgb, cpu, &p99, &mx, &rmse);
        printf("hvl %-15s gl vs cpu: max/peak %.3g\n", method_name[method], mx);
      }
      if (sel)
        rd_emit_sel(run, "hvl", method_name[method], "gl", im, gms[method], mem[method],
                    method_tol[method], sel, s->nmats, method_tol_brdf[method], "brdf-table");
      else
        rd_emit(run, "hvl", method_name[method], "gl", im, gms[method], mem[method],
                method_tol[method]);
    }
    free(cpu);
    cpu = NULL;
  }
  for (method = 0; method < M_COUNT; method++) {
    rd_image_free(&cimg[method]);
    rd_image_free(&gimg[method]);
  }
  free(gtt.gt);
  free(gtt.half);
  free(gt);
  free(ls.buf);
  free(sel);
  hv_brdf_free(&B);
  return rc;
}
