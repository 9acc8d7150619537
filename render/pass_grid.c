/* pass_grid.c - the "grid" pass of shlrender: sphere and triangle lights through SH ([GRAD]).
 *
 * Every RD_LIGHT_SPHERE and RD_LIGHT_TRIANGLE of the scene (a triangle as the paper's sphere,
 * shl_triangle_light) is projected to SH (run->bands bands, RGB), convolved with the Lambert
 * lobe at the shading normal (unshadowed, like the seed) and shaded diffuse:
 *   L_o = kd / pi * E(n),  E(n) = pi * shl_sh_conv_zh(L_sh, shl_zh_lambert, n);
 * Phong and GGX materials add ks * S, S = sum_i (R L_sh)_i F_i: the light SH rotated into the
 * pixel's local frame (shl_sh_rotate) dotted with the BRDF SH table's coefficients at w_o
 * (run->brdf_bands bands, default 9; the product uses min(bands, brdf_bands); see gd_brdf).
 * Methods, each on "cpu" (C kernels) and "gl" (the GLSL twins in a full-screen pass):
 *   perpixel         the SH of every light at every pixel;
 *   trilinear        SH on a 3D grid (shl_grid_build, 2 threads), trilinear reconstruction;
 *   taylor, hermite  the same grid with gradients, first-order Taylor / tricubic Hermite;
 *   trilinear_eqmem  trilinear on a finer grid with about the float count of the grid with
 *                    gradients (4x the vertices: the seed's Figure 7 comparison).
 * The grid spans the bounds of the receivers (triangles and spheres of the scene, lights
 * excluded: only surfaces are shaded), cell size h on every axis, SHLIGHT_GRID_RES vertices
 * along the longest axis (default 24; SHLIGHT_GRID_CULL sets shl_grid.cull, default 0: no
 * culling, so the grids differ from per-pixel SH by the interpolation alone). The cell lookup is
 * done in float the same way on both paths (shl_grid_sample does it in double: Taylor's corner
 * choice would then differ at cell mid-planes). shl_grid_build takes sphere lights with one scalar
 * intensity each: the RGB grid is built per distinct light colour (<= 3 colours) or per
 * channel; triangle lights are added by a local 2-thread loop over shl_triangle_light(_grad)
 * (the library's build has no triangle lights).
 * Ground truth ("gt"): the exact unshadowed irradiance of the real lights, in double (and for
 * glossy materials the same BRDF integrated over each light, gd_spec_gt): a sphere
 * by the closed form of the horizon-clipped cap (Snyder 1996), checked against a
 * semi-analytic quadrature; a triangle by Lambert's polygon formula after clipping it to the
 * horizon. Not SH-truncated: the table shows each method's total error. */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#endif
#include "../shlight.h"
#include "rd.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#if !defined(SHLIGHT_NO_THREADS) && (defined(__unix__) || defined(__APPLE__))
#include <pthread.h>
#define GD_THREADS 1
#else
#define GD_THREADS 0
#endif

#define GD_PI 3.14159265358979323846
#define GD_LF 16 /* floats per light in the GL light buffer */

enum { GD_TRILINEAR = 0, GD_TAYLOR = 1, GD_HERMITE = 2, GD_EQMEM = 3, GD_NGRID = 4 };
static const char *const gd_names[GD_NGRID] = {"trilinear", "taylor", "hermite", "trilinear_eqmem"};
/* gl-vs-cpu tolerances: about 3x the largest max |gl - cpu| / peak(cpu) measured on llvmpipe
   (scenes cornell, glossy, manylights, spheres at 64x48 and 256x192): perpixel 4.7e-7, the grid
   methods 2.3e-7 */
static const double gd_tol_perpixel = 2e-6;
static const double gd_tol_grid[GD_NGRID] = {1e-6, 1e-6, 1e-6, 1e-6};
/* the pixels of glossy materials (BRDF table: the lookup's angles and shl_sh_rotate in float in
   GLSL, double inside in C): about 3x the largest max |gl - cpu| / peak(cpu) measured on
   llvmpipe (glossy, 64x48 and 256x192, every method): 6.0e-7 */
static const double gd_tol_spec = 2e-6;

/* ---- lights ---------------------------------------------------------------------------- */
typedef struct {
  int n;      /* all lights used */
  int nsph;   /* spheres first, then triangles */
  float *buf; /* GD_LF floats per light: p0 xyz, r (sphere; 0 triangle), p1, 0, p2, 0, rgb, 0 */
  float bmin[3], bmax[3]; /* receiver bounds */
} gd_lights;

static int gd_collect(const rd_scene *s, gd_lights *L) {
  int i, k, j = 0, pass;
  memset(L, 0, sizeof *L);
  for (i = 0; i < s->nlights; i++)
    if (s->lights[i].type == RD_LIGHT_SPHERE || s->lights[i].type == RD_LIGHT_TRIANGLE) L->n++;
  if (!L->n) return 0;
  L->buf = (float *)calloc((size_t)L->n * GD_LF, sizeof(float));
  if (!L->buf) return -1;
  for (pass = 0; pass < 2; pass++)
    for (i = 0; i < s->nlights; i++) {
      const rd_light *l = &s->lights[i];
      float *o = L->buf + (size_t)j * GD_LF;
      if (l->type != (pass ? RD_LIGHT_TRIANGLE : RD_LIGHT_SPHERE)) continue;
      if (!pass && !(l->r > 0.0f)) continue; /* no light (and r = 0 would read as a triangle) */
      for (k = 0; k < 3; k++) {
        if (pass) {
          o[k] = l->v[0][k];
          o[4 + k] = l->v[1][k];
          o[8 + k] = l->v[2][k];
        } else {
          o[k] = l->c[k];
        }
        o[12 + k] = l->radiance[k];
      }
      o[3] = pass ? 0.0f : l->r;
      if (!pass) L->nsph++;
      j++;
    }
  L->n = j;
  /* receiver bounds: triangles and spheres (the lights are not shaded) */
  for (k = 0; k < 3; k++) {
    L->bmin[k] = s->bmin[k];
    L->bmax[k] = s->bmax[k];
  }
  if (s->ntris + s->nspheres > 0) {
    for (k = 0; k < 3; k++) {
      L->bmin[k] = 3e38f;
      L->bmax[k] = -3e38f;
    }
    for (i = 0; i < s->ntris; i++)
      for (j = 0; j < 3; j++)
        for (k = 0; k < 3; k++) {
          L->bmin[k] = fminf(L->bmin[k], s->tris[i].p[j][k]);
          L->bmax[k] = fmaxf(L->bmax[k], s->tris[i].p[j][k]);
        }
    for (i = 0; i < s->nspheres; i++)
      for (k = 0; k < 3; k++) {
        L->bmin[k] = fminf(L->bmin[k], s->spheres[i].c[k] - s->spheres[i].r);
        L->bmax[k] = fmaxf(L->bmax[k], s->spheres[i].c[k] + s->spheres[i].r);
      }
  }
  return 0;
}

/* SH of light j seen from x (unit radiance) */
static void gd_light_sh(int n, const float *l, const float x[3], float *sh) {
  if (l[3] > 0.0f)
    shl_sphere_light(n, x, l, l[3], sh);
  else
    shl_triangle_light(n, x, l, l + 4, l + 8, sh);
}

/* ---- glossy materials: BRDF SH tables ---------------------------------------------------- */
/* Phong and GGX materials (ks > 0) add ks * S to the diffuse term, S = the integral of the
   light times the specular lobe f times cos(theta_i): S = sum_i Lloc_i F_i, Lloc = the pixel's
   light SH rotated into the local frame (t, b, nrm) by shl_sh_rotate, F = the table's SH of
   f cos at w_o (shl_brdf_table_lookup; built once per material by shl_brdf_table_build with
   kd = 0, ks = 1, f0 = 1: Phong (e + 1) / (2 pi) cos^e of the mirror angle, GGX
   D G2 / (4 cos_i cos_o) with height-correlated Smith G2, no Fresnel, as the area pass).
   Tables: nb = run->brdf_bands bands, GD_NT theta_o samples, isotropic. The product runs over
   min(n, nb) bands (the SH of the lighting has n). */
#define GD_NT 90
typedef struct {
  int nb, nmats, any;
  int *off;             /* per material: float offset of its table in gpu, or -1 (no table) */
  float *gpu;           /* nmats offsets (as floats), then the tables */
  size_t floats;        /* of gpu */
  shl_brdf_params *par; /* per material (kd = 0, ks = 1) */
} gd_brdf;

static int gd_brdf_build(const rd_scene *s, int nb, gd_brdf *B) {
  size_t one = shl_brdf_table_size(nb, GD_NT, 1), at;
  int m, k = 0;
  memset(B, 0, sizeof *B);
  B->nb = nb;
  B->nmats = s->nmats;
  B->off = (int *)malloc(sizeof(int) * (size_t)(s->nmats > 0 ? s->nmats : 1));
  B->par = (shl_brdf_params *)calloc((size_t)(s->nmats > 0 ? s->nmats : 1), sizeof *B->par);
  if (!B->off || !B->par || !one) return -1;
  for (m = 0; m < s->nmats; m++) {
    const rd_material *mt = &s->mats[m];
    int glossy = (mt->brdf == RD_BRDF_PHONG || mt->brdf == RD_BRDF_GGX) &&
                 (mt->ks[0] > 0.0f || mt->ks[1] > 0.0f || mt->ks[2] > 0.0f);
    B->off[m] = -1;
    if (mt->brdf == RD_BRDF_GGX && !(mt->roughness > 0.0f && mt->roughness <= 4.0f)) glossy = 0;
    if (glossy) B->off[m] = k++;
  }
  B->any = k > 0;
  B->floats = (size_t)s->nmats + (size_t)k * one;
  B->gpu = (float *)calloc(B->floats ? B->floats : 1, sizeof(float));
  if (!B->gpu) return -1;
  at = (size_t)s->nmats;
  for (m = 0; m < s->nmats; m++) {
    const rd_material *mt = &s->mats[m];
    shl_brdf_table t;
    shl_result r;
    float est = 0.0f;
    if (B->off[m] < 0) {
      B->gpu[m] = -1.0f;
      continue;
    }
    B->par[m].model = mt->brdf == RD_BRDF_PHONG ? SHLIGHT_BRDF_PHONG : SHLIGHT_BRDF_GGX;
    B->par[m].kd = 0.0f;
    B->par[m].ks = 1.0f;
    B->par[m].exponent = mt->exponent;
    B->par[m].alpha_x = B->par[m].alpha_y = mt->roughness;
    B->par[m].f0 = 1.0f;
    t.n = nb;
    t.n_theta = GD_NT;
    t.n_phi = 1;
    t.flags = 0;
    t.data = B->gpu + at;
    r = shl_brdf_table_build(&t, &B->par[m], 32, &est);
    if (r != SHLIGHT_OK) {
      fprintf(stderr, "grid: shl_brdf_table_build failed for material %s (%d)\n", mt->name, (int)r);
      return -1;
    }
    printf("grid: BRDF table %s (%s), %d bands, %d theta_o samples; quadrature error estimate "
           "%.2e\n",
           mt->name, mt->brdf == RD_BRDF_PHONG ? "Phong" : "GGX", nb, GD_NT, (double)est);
    B->off[m] = (int)at;
    B->gpu[m] = (float)at;
    at += one;
  }
  return 0;
}

static void gd_brdf_free(gd_brdf *B) {
  free(B->off);
  free(B->gpu);
  free(B->par);
  memset(B, 0, sizeof *B);
}

/* per pixel: R (world -> local, rows t, b, nrm) and F (nb bands); 0 when mat has no table */
typedef struct {
  int has, nd; /* nd: coefficients of the product, min(n, nb)^2 */
  float R[9];
  float F[SHLIGHT_MAX_COEFFS];
  float loc[SHLIGHT_MAX_COEFFS];
} gd_spec;

static void gd_spec_setup(const gd_brdf *B, int n, int mat, const float x[3], const float nz[3],
                          const float eye[3], gd_spec *S) {
  float t[3], b[3], v[3], vl, wo[3];
  int k, m = n < B->nb ? n : B->nb;
  S->has = B->any && mat >= 0 && mat < B->nmats && B->off[mat] >= 0;
  if (!S->has) return;
  S->nd = m * m;
  rd_frame(nz, t, b);
  for (k = 0; k < 3; k++)
    v[k] = eye[k] - x[k];
  vl = 1.0f / sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (k = 0; k < 3; k++)
    v[k] = v[k] * vl;
  wo[0] = t[0] * v[0] + t[1] * v[1] + t[2] * v[2];
  wo[1] = b[0] * v[0] + b[1] * v[1] + b[2] * v[2];
  wo[2] = nz[0] * v[0] + nz[1] * v[1] + nz[2] * v[2];
  for (k = 0; k < 3; k++) {
    S->R[k] = t[k];
    S->R[3 + k] = b[k];
    S->R[6 + k] = nz[k];
  }
  shl_brdf_table_lookup(B->nb, GD_NT, 1, 0, B->gpu + B->off[mat], wo, S->F);
}

/* sum_i (R sh)_i F_i over min(n, nb) bands */
static float gd_spec_dot(int n, gd_spec *S, const float *sh) {
  float a = 0.0f;
  int i;
  shl_sh_rotate(n, S->R, sh, S->loc);
  for (i = 0; i < S->nd; i++)
    a = a + S->loc[i] * S->F[i];
  return a;
}

/* ---- per-pixel SH (C twin of the GLSL body below) -------------------------------------- */
static void gd_shade_perpixel(int n, const gd_lights *L, const float x[3], const float nrm[3],
                              const float kd[3], const float ks[3], gd_spec *S, const float *zl,
                              float *acc, float *sh, float out[3]) {
  int nn = n * n, i, j, c;
  for (i = 0; i < 3 * nn; i++)
    acc[i] = 0.0f;
  for (j = 0; j < L->n; j++) {
    const float *l = L->buf + (size_t)j * GD_LF;
    gd_light_sh(n, l, x, sh);
    for (c = 0; c < 3; c++)
      for (i = 0; i < nn; i++)
        acc[c * nn + i] = acc[c * nn + i] + l[12 + c] * sh[i];
  }
  for (c = 0; c < 3; c++) {
    out[c] = kd[c] * shl_sh_conv_zh(n, acc + c * nn, zl, nrm);
    if (S->has) out[c] = out[c] + ks[c] * gd_spec_dot(n, S, acc + c * nn);
  }
}

static const char *const gd_perpixel_glsl =
    "void main() {\n"
    "  ivec2 q = rd_pixel();\n"
    "  vec4 pw = texelFetch(rd_pos, q, 0);\n"
    "  vec4 nw = texelFetch(rd_nrm, q, 0);\n"
    "  int mat = int(nw.w);\n"
    "  if (pw.w < 0.0 || mat < 0) {\n"
    "    rd_out0 = vec4(0.0);\n"
    "    return;\n"
    "  }\n"
    "  float zl[SHLIGHT_MAX_BANDS];\n"
    "  float sh[SHLIGHT_MAX_COEFFS];\n"
    "  float ar[SHLIGHT_MAX_COEFFS];\n"
    "  float ag[SHLIGHT_MAX_COEFFS];\n"
    "  float ab[SHLIGHT_MAX_COEFFS];\n"
    "  int i;\n"
    "  shl_zh_lambert(RD_NB, zl);\n"
    "  for (i = 0; i < RD_NN; ++i) {\n"
    "    ar[i] = 0.0;\n"
    "    ag[i] = 0.0;\n"
    "    ab[i] = 0.0;\n"
    "  }\n"
    "  for (int j = 0; j < RD_NL; ++j) {\n"
    "    int o = 16 * j;\n"
    "    vec3 p0 = vec3(rd_buf1[o], rd_buf1[o + 1], rd_buf1[o + 2]);\n"
    "    float r = rd_buf1[o + 3];\n"
    "#if RD_NTRI > 0 /* compiled only for scenes with triangle lights (llvmpipe JIT time) */\n"
    "    if (r > 0.0) {\n"
    "      shl_sphere_light(RD_NB, pw.xyz, p0, r, sh);\n"
    "    } else {\n"
    "      vec3 p1 = vec3(rd_buf1[o + 4], rd_buf1[o + 5], rd_buf1[o + 6]);\n"
    "      vec3 p2 = vec3(rd_buf1[o + 8], rd_buf1[o + 9], rd_buf1[o + 10]);\n"
    "      shl_triangle_light(RD_NB, pw.xyz, p0, p1, p2, sh);\n"
    "    }\n"
    "#else\n"
    "    shl_sphere_light(RD_NB, pw.xyz, p0, r, sh);\n"
    "#endif\n"
    "    vec3 c = vec3(rd_buf1[o + 12], rd_buf1[o + 13], rd_buf1[o + 14]);\n"
    "    for (i = 0; i < RD_NN; ++i) {\n"
    "      ar[i] = ar[i] + c.x * sh[i];\n"
    "      ag[i] = ag[i] + c.y * sh[i];\n"
    "      ab[i] = ab[i] + c.z * sh[i];\n"
    "    }\n"
    "  }\n"
    "  vec3 kd = vec3(rd_mats[12 * mat], rd_mats[12 * mat + 1], rd_mats[12 * mat + 2]);\n"
    "  vec3 rgb;\n"
    "  for (int ch = 0; ch < 3 + min(rd_size.x, 0); ++ch) { /* one inlined copy of the kernel */\n"
    "    for (i = 0; i < RD_NN; ++i) sh[i] = ch == 0 ? ar[i] : (ch == 1 ? ag[i] : ab[i]);\n"
    "    rgb[ch] = kd[ch] * shl_sh_conv_zh(RD_NB, sh, zl, nw.xyz);\n"
    "  }\n"
    "#if RD_SPEC\n"
    "  if (gd_spec_setup(mat, pw.xyz, nw.xyz)) {\n"
    "    vec3 ks = vec3(rd_mats[12 * mat + 3], rd_mats[12 * mat + 4], rd_mats[12 * mat + 5]);\n"
    "    for (int ch = 0; ch < 3; ++ch) {\n"
    "      for (i = 0; i < RD_NN; ++i) sh[i] = ch == 0 ? ar[i] : (ch == 1 ? ag[i] : ab[i]);\n"
    "      rgb[ch] = rgb[ch] + ks[ch] * gd_spec_dot(sh);\n"
    "    }\n"
    "  }\n"
    "#endif\n"
    "  rd_out0 = vec4(rgb, 1.0);\n"
    "}\n";

/* GLSL twin of rd_frame (gd_frame) / gd_spec_setup / gd_spec_dot (the table in rd_buf3: material
   offsets, then the tables; the lookup as shl_brdf_table_lookup does it, on min(n, nb) bands) */
static const char *const gd_spec_glsl =
    "#if RD_SPEC\n"
    "float gd_R[9];\n"
    "float gd_F[SHLIGHT_MAX_COEFFS];\n"
    "void gd_frame(vec3 z, out vec3 t, out vec3 b) {\n"
    "  float sg = z.z >= 0.0 ? 1.0 : -1.0;\n"
    "  float a = -1.0 / (sg + z.z);\n"
    "  float c = z.x * z.y * a;\n"
    "  t = vec3(1.0 + sg * z.x * z.x * a, sg * c, -sg * z.x);\n"
    "  b = vec3(c, sg + z.y * z.y * a, -z.y);\n"
    "}\n"
    "bool gd_spec_setup(int mat, vec3 x, vec3 nz) {\n"
    "  int off = int(rd_buf3[mat]);\n"
    "  if (off < 0) return false;\n"
    "  vec3 t;\n"
    "  vec3 b;\n"
    "  gd_frame(nz, t, b);\n"
    "  vec3 v = rd_eye - x;\n"
    "  v = v * (1.0 / sqrt(v.x * v.x + v.y * v.y + v.z * v.z));\n"
    "  vec3 wo = vec3(t.x * v.x + t.y * v.y + t.z * v.z, b.x * v.x + b.y * v.y + b.z * v.z,\n"
    "                 nz.x * v.x + nz.y * v.y + nz.z * v.z);\n"
    "  for (int k = 0; k < 3; ++k) {\n"
    "    gd_R[k] = t[k];\n"
    "    gd_R[3 + k] = b[k];\n"
    "    gd_R[6 + k] = nz[k];\n"
    "  }\n"
    "  int idx[4];\n"
    "  float w[4];\n"
    "  shl_brdf_table_cell(RD_NT, 1, wo, idx, w);\n"
    "  for (int i = 0; i < RD_NF; ++i) {\n"
    "    gd_F[i] = (w[0] * rd_buf3[off + 2 * idx[0] * RD_NBB + i] +\n"
    "               w[1] * rd_buf3[off + 2 * idx[1] * RD_NBB + i]) +\n"
    "              (w[2] * rd_buf3[off + 2 * idx[2] * RD_NBB + i] +\n"
    "               w[3] * rd_buf3[off + 2 * idx[3] * RD_NBB + i]);\n"
    "  }\n"
    "  float rho = sqrt(wo.x * wo.x + wo.y * wo.y);\n"
    "  if (rho > 0.0) shl_sh_rotate_z(RD_NM, wo.x / rho, wo.y / rho, gd_F);\n"
    "  return true;\n"
    "}\n"
    "float gd_spec_dot(float sh[SHLIGHT_MAX_COEFFS]) {\n"
    "  float o[SHLIGHT_MAX_COEFFS];\n"
    "  shl_sh_rotate(RD_NB, gd_R, sh, o);\n"
    "  float a = 0.0;\n"
    "  for (int i = 0; i < RD_NF; ++i) a = a + o[i] * gd_F[i];\n"
    "  return a;\n"
    "}\n"
    "#endif\n";

/* ---- the grid --------------------------------------------------------------------------- */
typedef struct {
  shl_grid g;
  int grad;       /* gradients stored */
  size_t nv, nn;  /* vertices, coefficients per vertex */
  float *sh;      /* 3 * nv * nn: channel c at sh[(c nv + v) nn + i] */
  float *gr;      /* 3 * nv * nn * 3, or NULL */
  float isp[3];   /* 1 / spacing (the cell lookup of both paths) */
  double wall_ms; /* build, wall clock (2 threads) */
  int builds;     /* shl_grid_build calls */
} gd_grid;

static double gd_wall_ms(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

static size_t gd_floats(const gd_grid *G) {
  return 3u * G->nv * G->nn * (G->grad ? 4u : 1u);
}

/* grid of cell size h over the receiver box, centred, >= 2 vertices per axis */
static void gd_layout(const gd_lights *L, int n, double h, float cull, int grad, gd_grid *G) {
  int dims[3], k;
  memset(G, 0, sizeof *G);
  for (k = 0; k < 3; k++) {
    double ext = (double)L->bmax[k] - (double)L->bmin[k];
    int d = (int)ceil(ext / h - 1e-9) + 1;
    dims[k] = d < 2 ? 2 : d;
    G->g.origin[k] = (float)((double)L->bmin[k] - 0.5 * ((double)(dims[k] - 1) * h - ext));
    G->g.spacing[k] = (float)h;
    G->isp[k] = 1.0f / G->g.spacing[k];
  }
  G->g.dims[0] = dims[0];
  G->g.dims[1] = dims[1];
  G->g.dims[2] = dims[2];
  G->g.n = n;
  G->g.cull = cull;
  G->grad = grad;
  G->nn = (size_t)n * (size_t)n;
  G->nv = (size_t)dims[0] * (size_t)dims[1] * (size_t)dims[2];
}

typedef struct {
  const gd_grid *G;
  const gd_lights *L;
  const double *cut2; /* per triangle light: squared culling radius about the centroid */
  int z0, z1, fail;
} gd_trijob;

static void *gd_tri_run(void *arg) {
  gd_trijob *jb = (gd_trijob *)arg;
  const gd_grid *G = jb->G;
  const gd_lights *L = jb->L;
  int n = G->g.n, nn = n * n, ix, iy, iz, j, i, c;
  float *tsh = (float *)malloc(sizeof(float) * (size_t)nn * 4u);
  float(*tg)[3];
  if (!tsh) {
    jb->fail = 1;
    return NULL;
  }
  tg = (float(*)[3])(void *)(tsh + nn);
  for (iz = jb->z0; iz < jb->z1; iz++)
    for (iy = 0; iy < G->g.dims[1]; iy++)
      for (ix = 0; ix < G->g.dims[0]; ix++) {
        size_t v =
            (size_t)ix + (size_t)G->g.dims[0] * ((size_t)iy + (size_t)G->g.dims[1] * (size_t)iz);
        float p[3];
        p[0] = (float)((double)G->g.origin[0] + (double)ix * (double)G->g.spacing[0]);
        p[1] = (float)((double)G->g.origin[1] + (double)iy * (double)G->g.spacing[1]);
        p[2] = (float)((double)G->g.origin[2] + (double)iz * (double)G->g.spacing[2]);
        for (j = L->nsph; j < L->n; j++) {
          const float *l = L->buf + (size_t)j * GD_LF;
          double d2 = 0.0;
          for (c = 0; c < 3; c++) {
            double dc = ((double)l[c] + (double)l[4 + c] + (double)l[8 + c]) / 3.0 - (double)p[c];
            d2 += dc * dc;
          }
          if (d2 > jb->cut2[j - L->nsph]) continue;
          if (G->grad)
            shl_triangle_light_grad(n, p, l, l + 4, l + 8, tsh, tg);
          else
            shl_triangle_light(n, p, l, l + 4, l + 8, tsh);
          for (c = 0; c < 3; c++) {
            float w = l[12 + c], *o = G->sh + ((size_t)c * G->nv + v) * (size_t)nn;
            if (w == 0.0f) continue;
            for (i = 0; i < nn; i++)
              o[i] += w * tsh[i];
            if (G->grad) {
              float *og = G->gr + 3u * ((size_t)c * G->nv + v) * (size_t)nn;
              for (i = 0; i < nn; i++) {
                og[3 * i] += w * tg[i][0];
                og[3 * i + 1] += w * tg[i][1];
                og[3 * i + 2] += w * tg[i][2];
              }
            }
          }
        }
      }
  free(tsh);
  return NULL;
}

/* Builds the RGB grid: spheres by shl_grid_build (per colour group or per channel, both
   cores), triangles by gd_tri_run on two z slabs. Returns 0 or -1. */
static int gd_build(const gd_lights *L, gd_grid *G) {
  size_t nvn = G->nv * G->nn, k;
  int ns = L->nsph, nt = L->n - L->nsph, j, c, ng = 0, rc = 0;
  float chroma[3][3];
  float(*cen)[3] = NULL, *rad = NULL, *inten = NULL, *tsh = NULL, *tgr = NULL;
  int *gid = NULL;
  double t0 = gd_wall_ms(), *cut2 = NULL;
  G->sh = (float *)calloc(3u * nvn, sizeof(float));
  G->gr = G->grad ? (float *)calloc(9u * nvn, sizeof(float)) : NULL;
  if (!G->sh || (G->grad && !G->gr)) return -1;
  if (ns > 0) {
    cen = (float(*)[3])malloc(sizeof(float) * 3u * (size_t)ns);
    rad = (float *)malloc(sizeof(float) * (size_t)ns);
    inten = (float *)malloc(sizeof(float) * (size_t)ns);
    gid = (int *)malloc(sizeof(int) * (size_t)ns);
    tsh = (float *)malloc(sizeof(float) * nvn);
    tgr = G->grad ? (float *)malloc(sizeof(float) * 3u * nvn) : NULL;
    if (!cen || !rad || !inten || !gid || !tsh || (G->grad && !tgr)) {
      rc = -1;
      goto done;
    }
    /* colour groups: radiance = m * chroma, chroma = radiance / max component */
    for (j = 0; j < ns; j++) {
      const float *l = L->buf + (size_t)j * GD_LF;
      float m = fmaxf(l[12], fmaxf(l[13], l[14]));
      int g;
      for (c = 0; c < 3; c++)
        cen[j][c] = l[c];
      rad[j] = l[3];
      gid[j] = -1;
      if (!(m > 0.0f)) continue;
      for (g = 0; g < ng && g < 3; g++)
        if (fabsf(chroma[g][0] - l[12] / m) < 1e-6f && fabsf(chroma[g][1] - l[13] / m) < 1e-6f &&
            fabsf(chroma[g][2] - l[14] / m) < 1e-6f)
          break;
      if (g == ng) {
        if (ng < 3)
          for (c = 0; c < 3; c++)
            chroma[ng][c] = l[12 + c] / m;
        ng++;
      }
      gid[j] = g < 3 ? g : -1;
    }
    for (int b = 0; b < (ng <= 3 ? ng : 3); b++) {
      /* build b: colour group b (ng <= 3), else channel b */
      shl_result r;
      for (j = 0; j < ns; j++) {
        const float *l = L->buf + (size_t)j * GD_LF;
        if (ng <= 3)
          inten[j] = gid[j] == b ? fmaxf(l[12], fmaxf(l[13], l[14])) : 0.0f;
        else
          inten[j] = l[12 + b];
      }
      r = shl_grid_build(&G->g, (const float(*)[3])cen, rad, inten, ns, SHLIGHT_GRID_REVERSED, 2,
                         tsh, G->grad ? (float(*)[3])(void *)tgr : NULL);
      G->builds++;
      if (r != SHLIGHT_OK) {
        fprintf(stderr, "grid: shl_grid_build failed (%d)\n", (int)r);
        rc = -1;
        goto done;
      }
      for (c = 0; c < 3; c++) {
        float w = ng <= 3 ? chroma[b][c] : (c == b ? 1.0f : 0.0f);
        float *o = G->sh + (size_t)c * nvn, *og = G->grad ? G->gr + 3u * (size_t)c * nvn : NULL;
        if (w == 0.0f) continue;
        for (k = 0; k < nvn; k++)
          o[k] += w * tsh[k];
        if (og)
          for (k = 0; k < 3u * nvn; k++)
            og[k] += w * tgr[k];
      }
    }
  }
  if (nt > 0) {
    gd_trijob jb[2];
    cut2 = (double *)malloc(sizeof(double) * (size_t)nt);
    if (!cut2) {
      rc = -1;
      goto done;
    }
    for (j = 0; j < nt; j++) {
      /* the culling radius of shl_grid_build for the equivalent sphere (|cos gamma| <= 1) */
      const float *l = L->buf + (size_t)(ns + j) * GD_LF;
      double e1[3], e2[3], cr[3], area, rs, w, rcut = 1e150;
      for (c = 0; c < 3; c++) {
        e1[c] = (double)l[4 + c] - (double)l[c];
        e2[c] = (double)l[8 + c] - (double)l[c];
      }
      cr[0] = e1[1] * e2[2] - e1[2] * e2[1];
      cr[1] = e1[2] * e2[0] - e1[0] * e2[2];
      cr[2] = e1[0] * e2[1] - e1[1] * e2[0];
      area = 0.5 * sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]);
      rs = sqrt(area / GD_PI);
      w = fmax((double)l[12], fmax((double)l[13], (double)l[14]));
      if (G->g.cull > 0.0f) {
        rcut = rs * sqrt(2.0 * GD_PI * w / (double)G->g.cull);
        if (rcut < 2.0 * rs) rcut = 2.0 * rs;
      }
      cut2[j] = rcut * rcut;
    }
    for (j = 0; j < 2; j++) {
      jb[j].G = G;
      jb[j].L = L;
      jb[j].cut2 = cut2;
      jb[j].fail = 0;
    }
    jb[0].z0 = 0;
    jb[0].z1 = G->g.dims[2] / 2;
    jb[1].z0 = G->g.dims[2] / 2;
    jb[1].z1 = G->g.dims[2];
#if GD_THREADS
    {
      pthread_t th;
      if (pthread_create(&th, NULL, gd_tri_run, &jb[1]) == 0) {
        gd_tri_run(&jb[0]);
        pthread_join(th, NULL);
      } else {
        gd_tri_run(&jb[0]);
        gd_tri_run(&jb[1]);
      }
    }
#else
    gd_tri_run(&jb[0]);
    gd_tri_run(&jb[1]);
#endif
    if (jb[0].fail || jb[1].fail) rc = -1;
  }
done:
  G->wall_ms = gd_wall_ms() - t0;
  free(cen);
  free(rad);
  free(inten);
  free(gid);
  free(tsh);
  free(tgr);
  free(cut2);
  return rc;
}

static void gd_grid_free(gd_grid *G) {
  free(G->sh);
  free(G->gr);
  G->sh = G->gr = NULL;
}

/* The cell of x and the fraction in it, in float exactly as the GLSL body computes them (with
   the reciprocal cell size: llvmpipe may turn a division into a reciprocal), so that both paths
   pick the same cell and, for Taylor, the same corner. shl_grid_sample does this in double. */
static void gd_cell(const gd_grid *G, const float x[3], int lo[3], float f[3]) {
  int dims[3], k;
  dims[0] = G->g.dims[0];
  dims[1] = G->g.dims[1];
  dims[2] = G->g.dims[2];
  for (k = 0; k < 3; k++) {
    float u = (x[k] - G->g.origin[k]) * G->isp[k], fl;
    if (!(u >= 0.0f)) u = 0.0f;
    u = fminf(u, (float)(dims[k] - 1));
    fl = fminf(floorf(u), (float)(dims[k] - 2));
    lo[k] = (int)fl;
    f[k] = u - fl;
  }
}

/* C twin of the GLSL body: gather the 8 corners per channel, the library's reconstruction
   kernel, the Lambert convolution. c8: 8 n^2 floats, g8: 8 n^2 float[3]. */
static void gd_shade_grid(const gd_grid *G, int method, const float x[3], const float nrm[3],
                          const float kd[3], const float ks[3], gd_spec *S, const float *zl,
                          float *c8, float (*g8)[3], float *sh, float out[3]) {
  int c, ch, i, k, n = G->g.n, nn = n * n, lo[3];
  float f[3];
  gd_cell(G, x, lo, f);
  for (ch = 0; ch < 3; ch++) {
    for (c = 0; c < 8; c++) {
      size_t v = (size_t)(lo[0] + (c & 1)) +
                 (size_t)G->g.dims[0] * ((size_t)(lo[1] + ((c >> 1) & 1)) +
                                         (size_t)G->g.dims[1] * (size_t)(lo[2] + (c >> 2)));
      size_t base = ((size_t)ch * G->nv + v) * (size_t)nn;
      for (i = 0; i < nn; i++) {
        c8[c * nn + i] = G->sh[base + (size_t)i];
        if (G->grad)
          for (k = 0; k < 3; k++)
            g8[c * nn + i][k] = G->gr[3u * (base + (size_t)i) + (size_t)k];
      }
    }
    if (method == GD_TAYLOR)
      shl_grid_taylor(n, c8, (const float(*)[3])g8, f, G->g.spacing, sh);
    else if (method == GD_HERMITE)
      shl_grid_hermite(n, c8, (const float(*)[3])g8, f, G->g.spacing, sh);
    else
      shl_grid_trilinear(n, c8, f, sh);
    out[ch] = kd[ch] * shl_sh_conv_zh(n, sh, zl, nrm);
    if (S->has) out[ch] = out[ch] + ks[ch] * gd_spec_dot(n, S, sh);
  }
}

static const char *const gd_grid_glsl =
    "void main() {\n"
    "  ivec2 q = rd_pixel();\n"
    "  vec4 pw = texelFetch(rd_pos, q, 0);\n"
    "  vec4 nw = texelFetch(rd_nrm, q, 0);\n"
    "  int mat = int(nw.w);\n"
    "  if (pw.w < 0.0 || mat < 0) {\n"
    "    rd_out0 = vec4(0.0);\n"
    "    return;\n"
    "  }\n"
    "  ivec3 dims = ivec3(RD_NX, RD_NY, RD_NZ);\n"
    "  vec3 u = (pw.xyz - RD_ORG) * RD_ISP;\n"
    "  ivec3 lo;\n"
    "  vec3 f;\n"
    "  for (int k = 0; k < 3; ++k) {\n"
    "    float uk = u[k];\n"
    "    if (!(uk >= 0.0)) uk = 0.0;\n"
    "    uk = min(uk, float(dims[k] - 1));\n"
    "    float fl = min(floor(uk), float(dims[k] - 2));\n"
    "    lo[k] = int(fl);\n"
    "    f[k] = uk - fl;\n"
    "  }\n"
    "  int vb[8];\n"
    "  for (int c = 0; c < 8; ++c) {\n"
    "    ivec3 iv = lo + ivec3(c & 1, (c >> 1) & 1, c >> 2);\n"
    "    vb[c] = (iv.x + RD_NX * (iv.y + RD_NY * iv.z)) * RD_NN;\n"
    "  }\n"
    "  float zl[SHLIGHT_MAX_BANDS];\n"
    "  float c8[8 * SHLIGHT_MAX_COEFFS];\n"
    "#if RD_GRAD\n"
    "  vec3 g8[8 * SHLIGHT_MAX_COEFFS];\n"
    "#endif\n"
    "  float s1[SHLIGHT_MAX_COEFFS];\n"
    "  float sh[SHLIGHT_MAX_COEFFS];\n"
    "  vec3 kd = vec3(rd_mats[12 * mat], rd_mats[12 * mat + 1], rd_mats[12 * mat + 2]);\n"
    "  vec3 rgb;\n"
    "  int nn = RD_NN + min(rd_size.x, 0); /* a run-time bound: one copy of the kernel, not 25 */\n"
    "  shl_zh_lambert(RD_NB, zl);\n"
    "#if RD_SPEC\n"
    "  bool hs = gd_spec_setup(mat, pw.xyz, nw.xyz);\n"
    "  vec3 ks = vec3(rd_mats[12 * mat + 3], rd_mats[12 * mat + 4], rd_mats[12 * mat + 5]);\n"
    "#endif\n"
    "  for (int ch = 0; ch < 3; ++ch) {\n"
    "    for (int i = 0; i < nn; ++i) {\n"
    "      for (int c = 0; c < 8; ++c) {\n"
    "        int o = ch * RD_NV * RD_NN + vb[c] + i;\n"
    "        c8[c] = rd_buf1[o];\n"
    "#if RD_GRAD\n"
    "        g8[c] = vec3(rd_buf2[3 * o], rd_buf2[3 * o + 1], rd_buf2[3 * o + 2]);\n"
    "#endif\n"
    "      }\n"
    "#if RD_METHOD == 1\n"
    "      shl_grid_taylor(1, c8, g8, f, RD_SP, s1);\n"
    "#elif RD_METHOD == 2\n"
    "      shl_grid_hermite(1, c8, g8, f, RD_SP, s1);\n"
    "#else\n"
    "      shl_grid_trilinear(1, c8, f, s1);\n"
    "#endif\n"
    "      sh[i] = s1[0];\n"
    "    }\n"
    "    rgb[ch] = kd[ch] * shl_sh_conv_zh(RD_NB, sh, zl, nw.xyz);\n"
    "#if RD_SPEC\n"
    "    if (hs) rgb[ch] = rgb[ch] + ks[ch] * gd_spec_dot(sh);\n"
    "#endif\n"
    "  }\n"
    "  rd_out0 = vec4(rgb, 1.0);\n"
    "}\n";

static const char *const gd_includes[] = {
    "shl_prelude.glsl", "shl_basis.glsl", "shl_gradient.glsl", "shl_zonal.glsl",
    "shl_light.glsl",   "shl_grid.glsl",  "shl_brdf.glsl",     "shl_brdftab.glsl"};

/* ---- ground truth (double) --------------------------------------------------------------- */
/* Irradiance at normal n (unit) of a unit-radiance sphere, w = c - x: the horizon-clipped cap
   in closed form (Snyder 1996; the form of Lagarde & de Rousiers 2014, listing 7). Inside the
   sphere: pi. */
static double gd_sphere_irr(const double w[3], double r, const double n[3]) {
  double d = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]), s2, ct, st, x, y, sy, e;
  if (!(d > r)) return GD_PI;
  s2 = (r / d) * (r / d);
  ct = (n[0] * w[0] + n[1] * w[1] + n[2] * w[2]) / d;
  if (ct > 1.0) ct = 1.0;
  if (ct < -1.0) ct = -1.0;
  if (ct * ct > s2) return ct > 0.0 ? GD_PI * s2 * ct : 0.0;
  st = sqrt(1.0 - ct * ct);
  x = sqrt(1.0 / s2 - 1.0);
  y = -x * ct / st;
  if (y > 1.0) y = 1.0;
  if (y < -1.0) y = -1.0;
  sy = st * sqrt(1.0 - y * y);
  e = (ct * acos(y) - x * sy) * s2 + atan(sy / x);
  return e > 0.0 ? e : 0.0;
}

/* Independent check of gd_sphere_irr: the cap in its own frame, mu = cos(theta) by Gauss-
   Legendre (q nodes per piece, split where the horizon starts to cut the circles), the
   azimuth of max(0, a + b cos phi) in closed form. */
static double gd_sphere_irr_quad(const double w[3], double r, const double n[3], int q) {
  static const double x8[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290,
                               -0.1834346424956498, 0.1834346424956498,  0.5255324099163290,
                               0.7966664774136267,  0.9602898564975363};
  static const double w8[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066115205762,
                               0.3626837833783620, 0.3626837833783620, 0.3137066115205762,
                               0.2223810344533745, 0.1012285362903763};
  double d = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]), nw, np, m0, br[3], sum = 0.0;
  int p, k, s, nb = 0;
  if (!(d > r)) return GD_PI;
  nw = (n[0] * w[0] + n[1] * w[1] + n[2] * w[2]) / d;
  np = sqrt(fmax(0.0, 1.0 - nw * nw));
  m0 = sqrt((d - r) * (d + r)) / d;
  br[nb++] = m0;
  if (np > m0 && np < 1.0) br[nb++] = np;
  br[nb++] = 1.0;
  for (p = 0; p + 1 < nb; p++)
    for (s = 0; s < q; s++) { /* q sub-panels of 8 nodes */
      double a0 = br[p] + (br[p + 1] - br[p]) * (double)s / (double)q;
      double a1 = br[p] + (br[p + 1] - br[p]) * (double)(s + 1) / (double)q;
      for (k = 0; k < 8; k++) {
        double mu = 0.5 * (a0 + a1) + 0.5 * (a1 - a0) * x8[k], a = mu * nw,
               b = sqrt(fmax(0.0, 1.0 - mu * mu)) * np, f;
        if (a >= b)
          f = 2.0 * GD_PI * a;
        else if (a <= -b)
          f = 0.0;
        else {
          double ph = acos(-a / b);
          f = 2.0 * (a * ph + sqrt(b * b - a * a));
        }
        sum += 0.5 * (a1 - a0) * w8[k] * f;
      }
    }
  return sum;
}

/* Irradiance at normal n of a unit-radiance two-sided triangle (vertices relative to the
   shading point): Lambert's polygon formula after clipping to the horizon n.u >= 0. */
static double gd_tri_irr(double v[3][3], const double n[3]) {
  double p[5][3], sum = 0.0;
  int i, j, k, m = 0;
  for (i = 0; i < 3; i++) {
    const double *a = v[i], *b = v[(i + 1) % 3];
    double da = n[0] * a[0] + n[1] * a[1] + n[2] * a[2];
    double db = n[0] * b[0] + n[1] * b[1] + n[2] * b[2];
    if (da >= 0.0) {
      for (k = 0; k < 3; k++)
        p[m][k] = a[k];
      m++;
    }
    if ((da >= 0.0) != (db >= 0.0)) {
      double t = da / (da - db);
      for (k = 0; k < 3; k++)
        p[m][k] = a[k] + t * (b[k] - a[k]);
      m++;
    }
  }
  if (m < 3) return 0.0;
  for (i = 0; i < m; i++) {
    const double *a = p[i], *b = p[(i + 1) % m];
    double c[3], cl, dt;
    j = 0;
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
    cl = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    dt = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    if (cl > 0.0) sum += atan2(cl, dt) * (n[0] * c[0] + n[1] * c[1] + n[2] * c[2]) / cl;
    (void)j;
  }
  return 0.5 * fabs(sum);
}

/* exact unshadowed L_o = kd / pi * sum_j radiance_j E_j at pixel (x, n) */
static void gd_shade_gt(const gd_lights *L, const float xf[3], const float nf[3], const float kd[3],
                        float out[3]) {
  double x[3], n[3], acc[3] = {0.0, 0.0, 0.0}, nl;
  int j, k, c;
  for (k = 0; k < 3; k++) {
    x[k] = (double)xf[k];
    n[k] = (double)nf[k];
  }
  nl = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (k = 0; k < 3; k++)
    n[k] /= nl;
  for (j = 0; j < L->n; j++) {
    const float *l = L->buf + (size_t)j * GD_LF;
    double e;
    if (l[3] > 0.0f) {
      double w[3];
      for (k = 0; k < 3; k++)
        w[k] = (double)l[k] - x[k];
      e = gd_sphere_irr(w, (double)l[3], n);
    } else {
      double v[3][3];
      for (c = 0; c < 3; c++)
        for (k = 0; k < 3; k++)
          v[c][k] = (double)l[4 * c + k] - x[k];
      e = gd_tri_irr(v, n);
    }
    for (c = 0; c < 3; c++)
      acc[c] += (double)l[12 + c] * e;
  }
  for (c = 0; c < 3; c++)
    out[c] = (float)((double)kd[c] / GD_PI * acc[c]);
}

/* Gauss-Legendre nodes / weights on [0, 1] (Newton, double), k <= 128 */
static void gd_gauss01(int k, double *xs, double *ws) {
  int i, j, it;
  for (i = 0; i < k; i++) {
    double x = cos(GD_PI * (i + 0.75) / (k + 0.5)), p0 = 1.0, p1 = 0.0, p2, dp = 1.0;
    for (it = 0; it < 100; it++) {
      p1 = 1.0;
      p0 = x;
      for (j = 2; j <= k; j++) {
        p2 = p1;
        p1 = p0;
        p0 = ((2.0 * j - 1.0) * x * p1 - (j - 1.0) * p2) / j;
      }
      if (k == 1) p1 = 1.0;
      dp = k * (x * p0 - p1) / (x * x - 1.0);
      x -= p0 / dp;
      if (fabs(p0 / dp) < 1e-15) break;
    }
    xs[i] = 0.5 * (x + 1.0);
    ws[i] = 1.0 / ((1.0 - x * x) * dp * dp);
  }
}

/* f_spec(wo, wi) cos(theta_i) of material parameters P, world directions, frame (t, b, z) */
static double gd_fcos(const shl_brdf_params *P, const double t[3], const double b[3],
                      const double z[3], const float wo[3], const double wi[3]) {
  float li[3];
  li[0] = (float)(t[0] * wi[0] + t[1] * wi[1] + t[2] * wi[2]);
  li[1] = (float)(b[0] * wi[0] + b[1] * wi[1] + b[2] * wi[2]);
  li[2] = (float)(z[0] * wi[0] + z[1] * wi[1] + z[2] * wi[2]);
  if (!(li[2] > 0.0f)) return 0.0;
  return (double)shl_brdf_eval(P, wo, li) * (double)li[2];
}

/* The specular part of the ground truth: S_j = the integral over light j's solid angle of
   f_spec cos(theta_i) (unshadowed, the real light, no SH), by product Gauss rules: a sphere over
   its cap (q Gauss nodes in cos of the angle from the cap axis, 2q + 4 uniform in azimuth), a
   triangle by q x q Gauss nodes on the square mapped to it (Duffy), dw = cos_l dA / r^2.
   q = 12 (gt 1) or 40 (gt 2); the run prints the difference of the two on a pixel subset. */
static void gd_spec_gt(const gd_lights *L, const shl_brdf_params *P, const float xf[3],
                       const float nf[3], const float eye[3], int q, float ks_out[3]) {
  double x[3], z[3], t[3], b[3], xs[128], ws[128], acc[3] = {0.0, 0.0, 0.0}, v[3], vl;
  float tf[3], bf[3], nz[3], wo[3];
  int j, k, c, a, e, np = 2 * q + 4;
  for (k = 0; k < 3; k++)
    nz[k] = nf[k];
  rd_frame(nz, tf, bf);
  for (k = 0; k < 3; k++) {
    x[k] = (double)xf[k];
    z[k] = (double)nf[k];
    t[k] = (double)tf[k];
    b[k] = (double)bf[k];
    v[k] = (double)eye[k] - x[k];
  }
  vl = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (q > 128) q = 128;
  wo[0] = (float)((t[0] * v[0] + t[1] * v[1] + t[2] * v[2]) / vl);
  wo[1] = (float)((b[0] * v[0] + b[1] * v[1] + b[2] * v[2]) / vl);
  wo[2] = (float)((z[0] * v[0] + z[1] * v[1] + z[2] * v[2]) / vl);
  gd_gauss01(q, xs, ws);
  for (j = 0; j < L->n; j++) {
    const float *l = L->buf + (size_t)j * GD_LF;
    double sum = 0.0;
    if (l[3] > 0.0f) {
      double w[3], d, s2, cm, e1[3], e2[3], h;
      for (k = 0; k < 3; k++)
        w[k] = (double)l[k] - x[k];
      d = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
      s2 = (double)l[3] * (double)l[3] / (d * d);
      if (!(s2 < 1.0)) continue;
      cm = sqrt(1.0 - s2);
      for (k = 0; k < 3; k++)
        w[k] /= d;
      /* e1, e2 perpendicular to w */
      if (fabs(w[0]) < 0.9) {
        e1[0] = 0.0, e1[1] = -w[2], e1[2] = w[1];
      } else {
        e1[0] = w[2], e1[1] = 0.0, e1[2] = -w[0];
      }
      h = sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
      for (k = 0; k < 3; k++)
        e1[k] /= h;
      e2[0] = w[1] * e1[2] - w[2] * e1[1];
      e2[1] = w[2] * e1[0] - w[0] * e1[2];
      e2[2] = w[0] * e1[1] - w[1] * e1[0];
      for (a = 0; a < q; a++) {
        double u = cm + (1.0 - cm) * xs[a], su = sqrt(fmax(0.0, 1.0 - u * u));
        for (e = 0; e < np; e++) {
          double ph = 2.0 * GD_PI * (e + 0.5) / np, wi[3];
          for (k = 0; k < 3; k++)
            wi[k] = u * w[k] + su * (cos(ph) * e1[k] + sin(ph) * e2[k]);
          sum += ws[a] * (1.0 - cm) * (2.0 * GD_PI / np) * gd_fcos(P, t, b, z, wo, wi);
        }
      }
    } else {
      double p0[3], e1[3], e2[3], cr[3], ar2;
      for (k = 0; k < 3; k++) {
        p0[k] = (double)l[k];
        e1[k] = (double)l[4 + k] - p0[k];
        e2[k] = (double)l[8 + k] - p0[k];
      }
      cr[0] = e1[1] * e2[2] - e1[2] * e2[1];
      cr[1] = e1[2] * e2[0] - e1[0] * e2[2];
      cr[2] = e1[0] * e2[1] - e1[1] * e2[0];
      ar2 = sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]);
      if (!(ar2 > 0.0)) continue;
      for (a = 0; a < q; a++)
        for (e = 0; e < q; e++) {
          /* Duffy: (s, tt) in the square -> barycentrics (s (1 - tt), s tt), Jacobian s */
          double sa = xs[a], tb = xs[e], pt[3], r2, r, cl, wi[3];
          for (k = 0; k < 3; k++)
            pt[k] = p0[k] + sa * (1.0 - tb) * e1[k] + sa * tb * e2[k] - x[k];
          r2 = pt[0] * pt[0] + pt[1] * pt[1] + pt[2] * pt[2];
          r = sqrt(r2);
          for (k = 0; k < 3; k++)
            wi[k] = pt[k] / r;
          cl = fabs(cr[0] * wi[0] + cr[1] * wi[1] + cr[2] * wi[2]) / ar2;
          sum += ws[a] * ws[e] * sa * ar2 * cl / r2 * gd_fcos(P, t, b, z, wo, wi);
        }
    }
    for (c = 0; c < 3; c++)
      acc[c] += (double)l[12 + c] * sum;
  }
  for (c = 0; c < 3; c++)
    ks_out[c] = (float)acc[c];
}

/* ---- driver ------------------------------------------------------------------------------ */
typedef struct {
  char method[40], path[8];
  rd_image img;
  double ms, tol;
  size_t mem;
} gd_out;

static int cmp_double(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return x < y ? -1 : x > y;
}

/* One CPU method over the G-buffer, reps times; returns the median per-thread CPU ms. kind:
   -1 perpixel, -2 gt, else GD_*. */
static double gd_cpu_image(const rd_run *run, const gd_lights *L, const gd_grid *G,
                           const gd_brdf *B, int kind, rd_image *img) {
  const rd_gbuf *gb = run->gb;
  const rd_scene *s = run->scene;
  int n = run->bands, reps = kind == -2 ? 1 : (run->reps > 0 ? run->reps : 1), r;
  size_t np = (size_t)gb->w * (size_t)gb->h, i;
  float zl[SHLIGHT_MAX_BANDS], *acc = NULL, *sh = NULL, *c8, (*g8)[3];
  double ts[64];
  gd_spec S;
  if (reps > 64) reps = 64;
  acc = (float *)malloc(sizeof(float) * 36u * (size_t)n * (size_t)n);
  if (!acc) return -1.0;
  sh = acc + 3 * n * n;
  c8 = sh + n * n;
  g8 = (float(*)[3])(void *)(c8 + 8 * n * n);
  shl_zh_lambert(n, zl);
  for (r = 0; r < reps; r++) {
    double t0 = rd_cpu_ms();
    for (i = 0; i < np; i++) {
      int m = gb->mat[i];
      float *o = img->rgb + 3 * i;
      const float *x = gb->pos + 3 * i, *nr = gb->nrm + 3 * i, *kd;
      if (m < 0 || gb->depth[i] < 0.0f) {
        o[0] = o[1] = o[2] = 0.0f;
        continue;
      }
      kd = s->mats[m].kd;
      if (kind == -2) {
        gd_shade_gt(L, x, nr, kd, o);
        if (B->any && B->off[m] >= 0) {
          float sp[3];
          int c;
          gd_spec_gt(L, &B->par[m], x, nr, gb->eye, run->gt >= 2 ? 40 : 12, sp);
          for (c = 0; c < 3; c++)
            o[c] = o[c] + s->mats[m].ks[c] * sp[c];
        }
        if ((i & 1023) == 0) rd_progress("grid gt", (long)i, (long)np);
        continue;
      }
      gd_spec_setup(B, n, m, x, nr, gb->eye, &S);
      if (kind == -1)
        gd_shade_perpixel(n, L, x, nr, kd, s->mats[m].ks, &S, zl, acc, sh, o);
      else
        gd_shade_grid(G, kind, x, nr, kd, s->mats[m].ks, &S, zl, c8, g8, sh, o);
    }
    if (kind == -2) rd_progress("grid gt", (long)np, (long)np);
    ts[r] = rd_cpu_ms() - t0;
  }
  free(acc);
  qsort(ts, (size_t)reps, sizeof(double), cmp_double);
  return ts[reps / 2];
}

static int gd_gl_image(const rd_run *run, const gd_lights *L, const gd_grid *G, const gd_brdf *B,
                       int kind, rd_image *img, double *ms) {
  char defs[1536], *body;
  rd_gl_pass p;
  const float *bufs[3];
  size_t bf[3], dl;
  float *out;
  int n = run->bands, rc, nm = n < B->nb ? n : B->nb;
  size_t np = (size_t)run->gb->w * (size_t)run->gb->h, i;
  const char *main_body;
  memset(&p, 0, sizeof p);
  if (kind == -1) {
    snprintf(defs, sizeof defs,
             "#define SHLIGHT_MAX_BANDS %d\n#define RD_NB %d\n#define RD_NN %d\n#define RD_NL %d\n"
             "#define RD_NTRI %d\n",
             n, n, n * n, L->n, L->n - L->nsph);
    bufs[0] = L->buf;
    bf[0] = (size_t)L->n * GD_LF;
    bufs[1] = NULL;
    bf[1] = 0;
    main_body = gd_perpixel_glsl;
  } else {
    snprintf(defs, sizeof defs,
             "#define SHLIGHT_MAX_BANDS %d\n#define RD_NB %d\n#define RD_NN %d\n"
             "#define RD_NX %d\n#define RD_NY %d\n#define RD_NZ %d\n#define RD_NV %d\n"
             "#define RD_ORG vec3(%.9e, %.9e, %.9e)\n#define RD_SP vec3(%.9e, %.9e, %.9e)\n"
             "#define RD_ISP vec3(%.9e, %.9e, %.9e)\n"
             "#define RD_METHOD %d\n#define RD_GRAD %d\n",
             n, n, n * n, G->g.dims[0], G->g.dims[1], G->g.dims[2], (int)G->nv,
             (double)G->g.origin[0], (double)G->g.origin[1], (double)G->g.origin[2],
             (double)G->g.spacing[0], (double)G->g.spacing[1], (double)G->g.spacing[2],
             (double)G->isp[0], (double)G->isp[1], (double)G->isp[2], kind == GD_EQMEM ? 0 : kind,
             G->grad);
    bufs[0] = G->sh;
    bf[0] = 3u * G->nv * G->nn;
    bufs[1] = G->gr;
    bf[1] = G->grad ? 9u * G->nv * G->nn : 0;
    main_body = gd_grid_glsl;
  }
  /* glossy materials: the tables in rd_buf3 */
  dl = strlen(defs);
  snprintf(defs + dl, sizeof defs - dl,
           "#define RD_SPEC %d\n#define RD_NT %d\n#define RD_NBB %d\n#define RD_NF %d\n"
           "#define RD_NM %d\n",
           B->any, GD_NT, B->nb * B->nb, nm * nm, nm);
  bufs[2] = B->gpu;
  bf[2] = B->floats;
  p.nbuf = 3;
  body = (char *)malloc(strlen(gd_spec_glsl) + strlen(main_body) + 1);
  if (!body) return -1;
  strcpy(body, gd_spec_glsl);
  strcat(body, main_body);
  p.body = body;
  p.defines = defs;
  p.includes = gd_includes;
  p.ninclude = (int)(sizeof gd_includes / sizeof gd_includes[0]);
  p.bufs = bufs;
  p.buf_floats = bf;
  p.nout = 1;
  out = (float *)malloc(sizeof(float) * 4u * np);
  if (!out) {
    free(body);
    return -1;
  }
  rc = rd_gl_run(run->scene, run->gb, &p, &out, run->reps > 0 ? run->reps : 1, ms);
  free(body);
  if (rc == 0)
    for (i = 0; i < np; i++) {
      img->rgb[3 * i] = out[4 * i];
      img->rgb[3 * i + 1] = out[4 * i + 1];
      img->rgb[3 * i + 2] = out[4 * i + 2];
    }
  free(out);
  return rc;
}

static int gd_grid_res(void) {
  const char *e = getenv("SHLIGHT_GRID_RES");
  int r = e ? atoi(e) : 24;
  return r < 2 ? 2 : r > 256 ? 256 : r;
}

static float gd_grid_cull(void) {
  const char *e = getenv("SHLIGHT_GRID_CULL");
  double c = e ? atof(e) : 0.0;
  return c > 0.0 ? (float)c : 0.0f;
}

int rd_pass_grid(rd_run *run) {
  const rd_scene *s = run->scene;
  const rd_gbuf *gb = run->gb;
  gd_lights L;
  gd_brdf B;
  int *sel = NULL;
  gd_grid G[2]; /* 0: coarse grid with gradients, 1: the equal-memory trilinear grid */
  gd_out outs[2 * (GD_NGRID + 1) + 1];
  int nout = 0, n = run->bands, k, rc = 0, res = gd_grid_res(), pp_cpu = -1, pp_gl = -1;
  int use_gl = run->use_gl, gl_ok = 1;
  float cull = gd_grid_cull();
  double h, ext = 0.0;
  memset(G, 0, sizeof G);
  memset(&B, 0, sizeof B);
  if (gd_collect(s, &L)) return -1;
  if (!L.n) {
    free(L.buf);
    return 0;
  }
  if (n < 1 || n > SHLIGHT_MAX_BANDS) {
    fprintf(stderr, "grid: bands %d out of range\n", n);
    free(L.buf);
    return -1;
  }
  if (use_gl && n > 16) {
    fprintf(stderr, "grid: GLSL kernels take at most 16 bands (asked %d): gl path skipped\n", n);
    use_gl = 0;
  }
  /* the grids: cell h from the longest receiver axis; the equal-memory grid's cell shrinks by
     4^(1/3), then adjusted to the float count closest to the gradient grid's */
  for (k = 0; k < 3; k++)
    ext = fmax(ext, (double)L.bmax[k] - (double)L.bmin[k]);
  h = ext > 0.0 ? ext / (double)(res - 1) : 1.0;
  gd_layout(&L, n, h, cull, 1, &G[0]);
  {
    double best = 1e300, hb = h / cbrt(4.0), f;
    for (f = 0.85; f <= 1.15; f += 0.005) {
      gd_grid t;
      double rel;
      gd_layout(&L, n, h / cbrt(4.0) * f, cull, 0, &t);
      rel = fabs((double)gd_floats(&t) / (double)gd_floats(&G[0]) - 1.0);
      if (rel < best - 1e-12) {
        best = rel;
        hb = h / cbrt(4.0) * f;
      }
    }
    gd_layout(&L, n, hb, cull, 0, &G[1]);
  }
  if (gd_brdf_build(s, run->brdf_bands > 0 ? run->brdf_bands : 9, &B)) {
    fprintf(stderr, "grid: BRDF tables failed\n");
    rc = -1;
    goto done;
  }
  if (B.any) {
    sel = (int *)calloc((size_t)(s->nmats > 0 ? s->nmats : 1), sizeof(int));
    if (!sel) {
      rc = -1;
      goto done;
    }
    for (k = 0; k < s->nmats; k++)
      sel[k] = B.off[k] >= 0;
  }
  rd_gate_enter(1); /* the builds' wall time is reported: alone */
  k = gd_build(&L, &G[0]) || gd_build(&L, &G[1]);
  rd_gate_leave(1);
  if (k) {
    fprintf(stderr, "grid: out of memory building the grid\n");
    rc = -1;
    goto done;
  }
  printf("grid: %d bands, %d sphere + %d triangle lights; receiver box [%.3g %.3g %.3g]-[%.3g "
         "%.3g %.3g], cull %g\n",
         n, L.nsph, L.n - L.nsph, (double)L.bmin[0], (double)L.bmin[1], (double)L.bmin[2],
         (double)L.bmax[0], (double)L.bmax[1], (double)L.bmax[2], (double)cull);
  for (k = 0; k < 2; k++)
    printf("grid: %s grid %dx%dx%d (%zu vertices, cell %.4g), %s, %.1f KiB; build %.1f ms wall "
           "(%d shl_grid_build calls + triangle loop, 2 threads)\n",
           k ? "equal-memory" : "coarse", G[k].g.dims[0], G[k].g.dims[1], G[k].g.dims[2], G[k].nv,
           (double)G[k].g.spacing[0], k ? "values" : "values + gradients",
           (double)gd_floats(&G[k]) * 4.0 / 1024.0, G[k].wall_ms, G[k].builds);
  /* methods: -1 perpixel, then the grid methods */
  for (k = -1; k < GD_NGRID; k++) {
    const char *name = k < 0 ? "perpixel" : gd_names[k];
    const gd_grid *g = k == GD_EQMEM ? &G[1] : &G[0];
    size_t mem = k < 0 ? (size_t)L.n * GD_LF * sizeof(float)
                       : gd_floats(g) / (k == GD_TRILINEAR ? 4u : 1u) * sizeof(float);
    /* trilinear on the coarse grid reads only its values */
    if (run->use_cpu) {
      rd_image im = rd_image_new(gb->w, gb->h);
      double ms;
      if (!im.rgb) {
        rc = -1;
        goto done;
      }
      ms = gd_cpu_image(run, &L, g, &B, k, &im);
      if (k < 0) pp_cpu = nout;
      snprintf(outs[nout].method, sizeof outs[nout].method, "%s", name);
      snprintf(outs[nout].path, sizeof outs[nout].path, "cpu");
      outs[nout].img = im;
      outs[nout].ms = ms;
      outs[nout].mem = mem;
      outs[nout].tol = 0.0;
      nout++;
    }
    if (use_gl && gl_ok) {
      rd_image im = rd_image_new(gb->w, gb->h);
      double ms = 0.0;
      if (!im.rgb) {
        rc = -1;
        goto done;
      }
      if (gd_gl_image(run, &L, g, &B, k, &im, &ms)) {
        fprintf(stderr, "grid: GL %s failed; gl path skipped\n", name);
        rd_image_free(&im);
        gl_ok = 0;
        rc = -1;
      } else {
        if (k < 0) pp_gl = nout;
        snprintf(outs[nout].method, sizeof outs[nout].method, "%s", name);
        snprintf(outs[nout].path, sizeof outs[nout].path, "gl");
        outs[nout].img = im;
        outs[nout].ms = ms;
        outs[nout].mem = mem;
        outs[nout].tol = k < 0 ? gd_tol_perpixel : gd_tol_grid[k];
        nout++;
      }
    }
  }
  if (run->gt) {
    rd_image im = rd_image_new(gb->w, gb->h);
    double ms;
    rd_tm tm = rd_tm_now();
    if (!im.rgb) {
      rc = -1;
      goto done;
    }
    ms = gd_cpu_image(run, &L, NULL, &B, -2, &im);
    snprintf(outs[nout].method, sizeof outs[nout].method, "gt");
    snprintf(outs[nout].path, sizeof outs[nout].path, "gt");
    outs[nout].img = im;
    outs[nout].ms = ms;
    outs[nout].mem = 0;
    outs[nout].tol = 0.0;
    nout++;
    /* check of the sphere closed form against the semi-analytic quadrature (1 and 4 panels
       of 8 nodes per piece), every light, every pixel (gt 2) or every 7th (gt 1) */
    {
      double e1 = 0.0, e4 = 0.0, emax = 0.0;
      size_t np = (size_t)gb->w * (size_t)gb->h, i, step = run->gt >= 2 ? 1 : 7;
      int j, c;
      for (i = 0; i < np; i += step) {
        double x[3], nn[3], nl;
        if (gb->mat[i] < 0) continue;
        for (c = 0; c < 3; c++) {
          x[c] = (double)gb->pos[3 * i + (size_t)c];
          nn[c] = (double)gb->nrm[3 * i + (size_t)c];
        }
        nl = sqrt(nn[0] * nn[0] + nn[1] * nn[1] + nn[2] * nn[2]);
        for (c = 0; c < 3; c++)
          nn[c] /= nl;
        for (j = 0; j < L.nsph; j++) {
          const float *l = L.buf + (size_t)j * GD_LF;
          double w[3], a, q1, q4;
          for (c = 0; c < 3; c++)
            w[c] = (double)l[c] - x[c];
          a = gd_sphere_irr(w, (double)l[3], nn);
          q1 = gd_sphere_irr_quad(w, (double)l[3], nn, 1);
          q4 = gd_sphere_irr_quad(w, (double)l[3], nn, 4);
          /* relative to the light's face-on irradiance pi s^2 */
          {
            double d2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2],
                   ref = GD_PI * (double)l[3] * (double)l[3] / d2;
            e1 = fmax(e1, fabs(q1 - a) / ref);
            e4 = fmax(e4, fabs(q4 - a) / ref);
            emax = fmax(emax, a / ref);
          }
        }
      }
      printf("grid gt check: sphere closed form vs quadrature (8 / 32 nodes per piece): max "
             "|diff| / (pi s^2) = %.2e / %.2e\n",
             e1, e4);
      /* the specular quadrature: q against 2q nodes per dimension on the glossy pixels */
      if (B.any) {
        int q = run->gt >= 2 ? 40 : 12;
        double dmax = 0.0, pk = 0.0;
        for (i = 0; i < np; i += step) {
          float a[3], b2[3];
          int m = gb->mat[i];
          if (m < 0 || B.off[m] < 0) continue;
          gd_spec_gt(&L, &B.par[m], gb->pos + 3 * i, gb->nrm + 3 * i, gb->eye, q, a);
          gd_spec_gt(&L, &B.par[m], gb->pos + 3 * i, gb->nrm + 3 * i, gb->eye, 2 * q, b2);
          for (c = 0; c < 3; c++) {
            dmax = fmax(dmax, fabs((double)a[c] - (double)b2[c]));
            pk = fmax(pk, fabs((double)b2[c]));
          }
        }
        printf("grid gt check: specular quadrature, %d vs %d nodes per dimension: max |diff| / "
               "peak = %.2e (peak %.3g)\n",
               q, 2 * q, pk > 0.0 ? dmax / pk : 0.0, pk);
      }
      (void)emax;
    }
    rd_tm_add(RD_TM_GT, tm);
  }
  /* the seed-003 claim: each grid scheme against per-pixel SH (same path) */
  {
    int ref = pp_cpu >= 0 ? pp_cpu : pp_gl, i;
    if (ref >= 0) {
      printf("grid vs perpixel (%s path; perpixel %.2f ms, light buffer %.1f KiB): method: "
             "max|diff|/peak, RMSE/RMS (all; per material), shading time ratio (with the "
             "build), memory KiB\n",
             outs[ref].path, outs[ref].ms, (double)outs[ref].mem / 1024.0);
      for (i = 0; i < nout; i++) {
        const gd_grid *g = !strcmp(outs[i].method, "trilinear_eqmem") ? &G[1] : &G[0];
        int m;
        if (i == ref || strcmp(outs[i].path, outs[ref].path) != 0) continue;
        printf("  %-16s %.2e  %.2e (", outs[i].method,
               rd_compare(&outs[i].img, &outs[ref].img, gb->mat).maxrel,
               rd_relrmse(gb, &outs[i].img, &outs[ref].img, -1));
        for (m = 0; m < s->nmats && m < 6; m++)
          printf("%s%s %.2e", m ? ", " : "", s->mats[m].name,
                 rd_relrmse(gb, &outs[i].img, &outs[ref].img, m));
        printf(")  %.3f (%.3f)  %.1f\n", outs[ref].ms > 0.0 ? outs[i].ms / outs[ref].ms : 0.0,
               outs[ref].ms > 0.0 ? (outs[i].ms + g->wall_ms) / outs[ref].ms : 0.0,
               (double)outs[i].mem / 1024.0);
      }
    }
  }
  for (k = 0; k < nout; k++) {
    if (sel && !strcmp(outs[k].path, "gl"))
      rd_emit_sel(run, "grid", outs[k].method, outs[k].path, outs[k].img, outs[k].ms, outs[k].mem,
                  outs[k].tol, sel, s->nmats, gd_tol_spec, "glossy");
    else
      rd_emit(run, "grid", outs[k].method, outs[k].path, outs[k].img, outs[k].ms, outs[k].mem,
              outs[k].tol);
    outs[k].img.rgb = NULL;
  }
  nout = 0;
done:
  for (k = 0; k < nout; k++)
    rd_image_free(&outs[k].img);
  gd_grid_free(&G[0]);
  gd_grid_free(&G[1]);
  gd_brdf_free(&B);
  free(sel);
  free(L.buf);
  return rc;
}
