/* pass_area.c - the "area" pass of shlrender: polygon, triangle, disc and sphere area lights
 * without tables ([AREA]), Lambert diffuse plus a glossy lobe, unshadowed.
 *
 * Per pixel and light (unit radiance, then times the light's RGB radiance):
 *   diffuse   kd / pi * E, E = M^1(light, n) the horizon-clipped cosine moment (the irradiance),
 *             computed as D = shl_*_phong(..., view = n, exponent 1) = (1+1)/(2 pi) M^1 = E / pi,
 *             so the diffuse radiance is kd * D;
 *   Phong     RD_BRDF_PHONG: ks * (e+1)/(2 pi) * the integral of max(0, u.r)^e over the light
 *             clipped to the horizon, r the mirror direction of the view: shl_polygon_phong
 *             (polygons, triangles), shl_ellipse_phong (discs), shl_sphere_phong (spheres);
 *   GGX       RD_BRDF_GGX: ks * shl_polygon_ggx(light polygon, n, v, alpha), the integral of
 *             D G2 / (4 (n.l)(n.v)) (n.l) over the light clipped to the horizon (GGX D,
 *             height-correlated Smith G2, Fresnel 1: ks is the specular albedo). Polygons and
 *             triangles directly; discs and spheres as the mean over the two octagons that
 *             shl_ellipse_phong / shl_sphere_phong build (the sphere: the disc of its cone of
 *             directions), so their GGX value carries that model's error (glossy, 128x128,
 *             --gt 2, each light alone on the GGX floor: polygon 2.5e-6, disc 1.7e-4, sphere
 *             1.8e-4 relative RMSE). It does not depend on the edge method. (Before
 *             shl_polygon_ggx the pass used README's "NDF road", shl_polygon_ggx_ndf over the
 *             half-vector image with masking and Jacobian held at the light centre: 1.5e-2 on
 *             the glossy floor, now 1.7e-4.)
 * Methods (each on "cpu" and "gl"): "exact" (SHLIGHT_EDGE_EXACT: the O(e) recurrence;
 * non-integer exponents fall back to the quadrature inside the kernel), "quadrature"
 * (SHLIGHT_EDGE_QUADRATURE, the Stokes form, constant cost), "lorentz_pearson" (the paper's fit,
 * exponent rounded).
 * Ground truth ("gt"): adaptive Gauss-Kronrod (7, 15) cubature in solid angle over each light
 * with the same BRDFs (GGX: ks D G2 / (4 (n.l)(n.v)), height-correlated Smith G2): planar lights
 * in polar coordinates about the foot of the shading point on the light's plane (split at the
 * vertex directions and at the horizon), spheres over their cap (split where the horizon cuts
 * it). Tolerance 1e-5 (gt 1) or 1e-7 (gt 2) per light of the unit-radiance integrals; the same
 * at a 10x looser tolerance is emitted as method "gt_coarse" (path cpu): its error against "gt"
 * bounds the reference's own. It calls no shlight kernel (the BRDFs are evaluated point by point
 * in double). The diffuse part of polygons and spheres has closed forms
 * (Lambert's polygon formula after the horizon clip; Snyder's clipped cap), used instead. */
#include "../shlight.h"
#include "rd.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define AR_PI 3.14159265358979323846
#define AR_LF 48 /* floats per light in the light buffer */

enum { AR_POLY = 0, AR_DISC = 1, AR_SPHERE = 2 };
static const char *const ar_names[3] = {"exact", "quadrature", "lorentz_pearson"};
static const int ar_methods[3] = {SHLIGHT_EDGE_EXACT, SHLIGHT_EDGE_QUADRATURE,
                                  SHLIGHT_EDGE_LORENTZ_PEARSON};
/* gl-vs-cpu tolerance per method: about 3x the largest max |gl - cpu| / peak(cpu) measured on
   llvmpipe (cornell, glossy, manylights, spheres at 64x48, 256x192, 256x256): exact 2.9e-6,
   quadrature 3.0e-5 (the Stokes nodes in float), Lorentz-Pearson 1.0e-4 (the fit's branches:
   float and double switch at different pixels, see the report) */
static const double ar_tol[3] = {1e-5, 1e-4, 3e-4};
/* the same on the pixels of GGX materials (shl_polygon_ggx, the same for every method), checked
   apart (rd_emit_sel) so the methods keep theirs on the rest: about 3x the largest measured on
   glossy (64x48 7.4e-7, 160x120 and 256x192 <= 1.5e-6, 256x256 1.0e-6, 512x384 2.0e-6). Before
   the Newton-step guard in shli_mf_taylor (README "GGX polygon lights") the float edge rule
   lost the arc on some octagon edges far from the lobe: 7.7e-5 at 64x48, 6.4e-4 at 512x384. */
#define AR_TOL_GGX 6e-6

/* Light buffer: [0] type, [1] nv, [2] r, [4..6] radiance, [8..10] centre, [12..14] a1,
   [16..18] a2 (disc semi-axes), [20..22] and [23] the bounding sphere of the kernel's polygons
   (spheres: per pixel), [24 + 3k ..] vertex k (polygons and triangles). */
static int ar_collect(const rd_scene *s, float **out) {
  int i, k, j, n = 0, i2;
  float *b;
  *out = NULL;
  for (i = 0; i < s->nlights; i++) {
    int t = s->lights[i].type;
    if (t == RD_LIGHT_POLYGON || t == RD_LIGHT_TRIANGLE || t == RD_LIGHT_DISC ||
        t == RD_LIGHT_SPHERE)
      n++;
  }
  if (!n) return 0;
  b = (float *)calloc((size_t)n * AR_LF, sizeof(float));
  if (!b) return -1;
  for (i = 0, j = 0; i < s->nlights; i++) {
    const rd_light *l = &s->lights[i];
    float *o = b + (size_t)j * AR_LF;
    if (l->type == RD_LIGHT_POLYGON || l->type == RD_LIGHT_TRIANGLE) {
      int nv = l->type == RD_LIGHT_TRIANGLE ? 3 : l->nv;
      if (nv < 3 || nv > RD_MAX_POLY) continue;
      o[0] = (float)AR_POLY;
      o[1] = (float)nv;
      for (k = 0; k < nv; k++) {
        o[24 + 3 * k] = l->v[k][0];
        o[24 + 3 * k + 1] = l->v[k][1];
        o[24 + 3 * k + 2] = l->v[k][2];
      }
    } else if (l->type == RD_LIGHT_DISC) {
      /* orthonormal frame about the disc normal (Duff et al. 2017), semi-axes of length r */
      float nn[3], len, sg, a, bb;
      len = sqrtf(rd_dot(l->n, l->n));
      if (!(len > 0.0f)) continue;
      for (k = 0; k < 3; k++)
        nn[k] = l->n[k] / len;
      sg = nn[2] >= 0.0f ? 1.0f : -1.0f;
      a = -1.0f / (sg + nn[2]);
      bb = nn[0] * nn[1] * a;
      o[0] = (float)AR_DISC;
      o[2] = l->r;
      o[12] = l->r * (1.0f + sg * nn[0] * nn[0] * a);
      o[13] = l->r * (sg * bb);
      o[14] = l->r * (-sg * nn[0]);
      o[16] = l->r * bb;
      o[17] = l->r * (sg + nn[1] * nn[1] * a);
      o[18] = l->r * (-nn[1]);
    } else if (l->type == RD_LIGHT_SPHERE) {
      o[0] = (float)AR_SPHERE;
      o[2] = l->r;
    } else {
      continue;
    }
    for (k = 0; k < 3; k++) {
      o[4 + k] = l->radiance[k];
      o[8 + k] = l->c[k];
      o[20 + k] = l->c[k];
    }
    /* bounding sphere of the kernel's polygons (with a margin for the rounding of the
       relative vertices), for the exact below-the-plane early-out */
    if (o[0] == (float)AR_POLY) {
      int nv = (int)o[1];
      double cen[3] = {0.0, 0.0, 0.0}, rad = 0.0;
      for (k = 0; k < nv; k++)
        for (i2 = 0; i2 < 3; i2++)
          cen[i2] += (double)o[24 + 3 * k + i2] / (double)nv;
      for (k = 0; k < nv; k++) {
        double dd = 0.0;
        for (i2 = 0; i2 < 3; i2++)
          dd += ((double)o[24 + 3 * k + i2] - cen[i2]) * ((double)o[24 + 3 * k + i2] - cen[i2]);
        rad = fmax(rad, sqrt(dd));
      }
      for (k = 0; k < 3; k++)
        o[20 + k] = (float)cen[k];
      o[23] = (float)(1.001 * rad + 1e-5);
    } else if (o[0] == (float)AR_DISC) {
      o[23] = 1.0550226f * l->r + 1e-5f; /* octagon vertices at 1.0539686 r */
    }
    j++;
  }
  *out = b;
  return j;
}

/* ---- shading (C twin of the GLSL below) ------------------------------------------------- */
/* octagon h of shl_ellipse_phong's construction (shlight.h shli_ellipse_phong_r, in float as
   the GLSL twin): GGX discs and spheres go through shl_polygon_ggx on these polygons */
static void ar_octagon(const float c[3], const float ua[3], const float va[3], int h,
                       float (*v)[3]) {
  int j, k;
  for (j = 0; j < 8; j++) {
    float cs = 1.0539686339182901f * cosf(0.39269908169872415f * (float)(2 * j + h));
    float sn = 1.0539686339182901f * sinf(0.39269908169872415f * (float)(2 * j + h));
    for (k = 0; k < 3; k++)
      v[j][k] = c[k] + cs * ua[k] + sn * va[k];
  }
}

/* shl_sphere_phong's disc for the direction vw: its centre io_c and axes ua, va (shlight.h's
   expressions in float); returns 0 where the kernel returns 0 */
static int ar_sphere_disc(float *io_c, float r, const float n[3], const float vw[3], float ua[3],
                          float va[3]) {
  float dv = n[0] * vw[0] + n[1] * vw[1] + n[2] * vw[2];
  float rx = 2.0f * dv * n[0] - vw[0], ry = 2.0f * dv * n[1] - vw[1], rz = 2.0f * dv * n[2] - vw[2];
  float l = sqrtf(rx * rx + ry * ry + rz * rz);
  float d = sqrtf(io_c[0] * io_c[0] + io_c[1] * io_c[1] + io_c[2] * io_c[2]), rho, ux, uy, uz, sg,
        a, b;
  if (!(dv > 0.0f) || !(l > 0.0f) || !(r > 0.0f)) return 0;
  if (!(d > r)) {
    io_c[0] = rx / l;
    io_c[1] = ry / l;
    io_c[2] = rz / l;
    d = 1.0f;
    rho = 1.0e4f;
  } else {
    rho = r * d / sqrtf((d - r) * (d + r));
  }
  ux = io_c[0] / d;
  uy = io_c[1] / d;
  uz = io_c[2] / d;
  sg = uz < 0.0f ? -1.0f : 1.0f;
  a = -1.0f / (sg + uz);
  b = ux * uy * a;
  ua[0] = rho * (1.0f + sg * ux * ux * a);
  ua[1] = rho * sg * b;
  ua[2] = -rho * sg * ux;
  va[0] = rho * b;
  va[1] = rho * (sg + uy * uy * a);
  va[2] = -rho * uy;
  return 1;
}

/* the light's bounding sphere (centre b relative to x, radius br) lies below the plane through
   x with unit normal a: the kernels' clip leaves nothing (they return exactly 0) */
static int ar_below(const float b[3], float br, const float a[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] < -br;
}

/* Radiance at one pixel; mat: the 12 floats of rd_mats. The CPU twin of the GLSL body below:
   the same steps, but it calls shl_ellipse_phong / shl_sphere_phong themselves (the GLSL body
   draws their octagons through shl_polygon_phong, see there) and runs one method per call. */
static void ar_shade(const float *lb, int nl, const float x[3], const float nrm[3],
                     const float eye[3], const float *mat, int method, float out[3]) {
  float d[3], view[3], len, val[2], v[RD_MAX_POLY][3], c[3], a1[3], a2[3], bc[3], br, rv[3], dvv;
  int brdf = (int)mat[6], npass, j, k, ps, h, below;
  d[0] = eye[0] - x[0];
  d[1] = eye[1] - x[1];
  d[2] = eye[2] - x[2];
  len = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  view[0] = d[0] / len;
  view[1] = d[1] / len;
  view[2] = d[2] / len;
  npass = brdf == RD_BRDF_PHONG ? 2 : 1;
  dvv = nrm[0] * view[0] + nrm[1] * view[1] + nrm[2] * view[2];
  rv[0] = 2.0f * dvv * nrm[0] - view[0];
  rv[1] = 2.0f * dvv * nrm[1] - view[1];
  rv[2] = 2.0f * dvv * nrm[2] - view[2];
  out[0] = out[1] = out[2] = 0.0f;
  for (j = 0; j < nl; j++) {
    const float *l = lb + (size_t)j * AR_LF;
    int type = (int)l[0], nv = (int)l[1];
    for (k = 0; k < 3; k++) {
      c[k] = l[8 + k] - x[k];
      a1[k] = l[12 + k];
      a2[k] = l[16 + k];
    }
    for (k = 0; k < RD_MAX_POLY; k++) {
      v[k][0] = l[24 + 3 * k] - x[0];
      v[k][1] = l[24 + 3 * k + 1] - x[1];
      v[k][2] = l[24 + 3 * k + 2] - x[2];
    }
    /* the exact early-out of the GLSL body (the kernel would return exactly 0) */
    for (k = 0; k < 3; k++)
      bc[k] = l[20 + k] - x[k];
    br = l[23];
    if (type == AR_SPHERE) {
      float dd = sqrtf(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
      br =
          dd > l[2] ? 1.0550226f * (l[2] * dd / sqrtf((dd - l[2]) * (dd + l[2]))) + 1.0e-5f : -1.0f;
    }
    below = br >= 0.0f && ar_below(bc, br, nrm);
    val[0] = val[1] = 0.0f;
    for (ps = 0; ps < npass; ps++) {
      const float *vw = ps == 0 ? nrm : view;
      float e = ps == 0 ? 1.0f : mat[7];
      if (below || (ps == 1 && br >= 0.0f && ar_below(bc, br, rv))) continue;
      if (type == AR_POLY)
        val[ps] = shl_polygon_phong((const float(*)[3])v, nv, nrm, vw, e, method);
      else if (type == AR_DISC)
        val[ps] = shl_ellipse_phong(c, a1, a2, nrm, vw, e, method);
      else
        val[ps] = shl_sphere_phong(c, l[2], nrm, vw, e, method);
    }
    if (brdf == RD_BRDF_GGX && !below) { /* method independent */
      float t = 0.0f, cc[3];
      int np = type == AR_POLY ? 1 : 2;
      cc[0] = c[0];
      cc[1] = c[1];
      cc[2] = c[2];
      if (type == AR_SPHERE && !ar_sphere_disc(cc, l[2], nrm, view, a1, a2)) np = 0;
      for (h = 0; h < np; h++) {
        if (type != AR_POLY) ar_octagon(cc, a1, a2, h, v);
        t = t + shl_polygon_ggx((const float(*)[3])v, type == AR_POLY ? nv : 8, nrm, view, mat[8]);
      }
      val[1] = type == AR_POLY ? t : 0.5f * t;
    }
    for (k = 0; k < 3; k++)
      out[k] = out[k] + l[4 + k] * (mat[k] * val[0] + mat[3 + k] * val[1]);
  }
}

/* The GLSL pass (C twin: ar_shade). All lights go through ONE call site of shl_polygon_phong
   (and one of shl_polygon_ggx): llvmpipe spends ~2-4 s of LLVM time per inlined copy of the
   edge kernels (shl_polygon_phong, shl_ellipse_phong and shl_sphere_phong each inline the clip
   and moment code once or twice: ~20 s per shader when all three are called; shl_polygon_ggx
   ~4.5 s), so discs and spheres are drawn here as the two octagons that shl_ellipse_phong /
   shl_sphere_phong build (the same float expressions as shl_edge.glsl: the same values as
   calling them), the loops have run-time bounds (no unrolled copies), and the methods
   RD_METHODS[0 .. RD_NM-1] run in one shader, one output each (Lorentz-Pearson's diffuse value
   at exponent 1 is the exact method's: the kernel takes the exact path for orders <= 2, so it
   is copied, not recomputed). Lights whose bounding sphere lies below the horizon (or, for
   Phong, below the mirror direction's plane) are skipped: the kernels return exactly 0 for
   them. RD_GGX compiles the GGX block only for scenes with GGX materials. */
static const char *const ar_glsl[3] = {
    "void rd_octagon(vec3 c, vec3 ua, vec3 va, int h, inout vec3 v[SHLIGHT_POLYGON_MAX]) {\n"
    "  for (int j = 0; j < 8; ++j) {\n"
    "    float cs = 1.0539686339182901 * cos(0.39269908169872415 * float(2 * j + h));\n"
    "    float sn = 1.0539686339182901 * sin(0.39269908169872415 * float(2 * j + h));\n"
    "    v[j] = vec3(c.x + cs * ua.x + sn * va.x, c.y + cs * ua.y + sn * va.y,\n"
    "                c.z + cs * ua.z + sn * va.z);\n"
    "  }\n"
    "}\n"
    "/* light j's polygon h (vertices relative to x): its own vertices, or octagon h of the disc "
    "*/\n"
    "void rd_polygon(int o, vec3 x, int type, vec3 cc, vec3 ua, vec3 va, int h,\n"
    "                inout vec3 v[SHLIGHT_POLYGON_MAX]) {\n"
    "  if (type == 0) {\n"
    "    for (int k = 0; k < SHLIGHT_POLYGON_MAX; ++k) {\n"
    "      int b = o + 24 + 3 * k;\n"
    "      v[k] = vec3(rd_buf1[b] - x.x, rd_buf1[b + 1] - x.y, rd_buf1[b + 2] - x.z);\n"
    "    }\n"
    "  } else {\n"
    "    rd_octagon(cc, ua, va, h, v);\n"
    "  }\n"
    "}\n"
    "/* shl_sphere_phong's disc for the direction vw (its expressions): centre cc, axes ua, va */\n"
    "bool rd_sphere_disc(vec3 c, float rr, vec3 nrm, vec3 vw, inout vec3 cc, inout vec3 ua,\n"
    "                    inout vec3 va) {\n"
    "  float dv = nrm.x * vw.x + nrm.y * vw.y + nrm.z * vw.z;\n"
    "  float rx = 2.0 * dv * nrm.x - vw.x;\n"
    "  float ry = 2.0 * dv * nrm.y - vw.y;\n"
    "  float rz = 2.0 * dv * nrm.z - vw.z;\n"
    "  float l = sqrt(rx * rx + ry * ry + rz * rz);\n"
    "  float dd = sqrt(c.x * c.x + c.y * c.y + c.z * c.z);\n"
    "  float rho;\n"
    "  if (!(dv > 0.0) || !(l > 0.0) || !(rr > 0.0)) return false;\n"
    "  cc = c;\n"
    "  if (!(dd > rr)) {\n"
    "    cc = vec3(rx / l, ry / l, rz / l);\n"
    "    dd = 1.0;\n"
    "    rho = 1.0e4;\n"
    "  } else {\n"
    "    rho = rr * dd / sqrt((dd - rr) * (dd + rr));\n"
    "  }\n"
    "  float ux = cc.x / dd;\n"
    "  float uy = cc.y / dd;\n"
    "  float uz = cc.z / dd;\n"
    "  float sg = uz < 0.0 ? -1.0 : 1.0;\n"
    "  float a = -1.0 / (sg + uz);\n"
    "  float b = ux * uy * a;\n"
    "  ua = vec3(rho * (1.0 + sg * ux * ux * a), rho * sg * b, -rho * sg * ux);\n"
    "  va = vec3(rho * b, rho * (sg + uy * uy * a), -rho * uy);\n"
    "  return true;\n"
    "}\n"
    "/* an exact early-out: the light's bounding sphere (centre b relative to x, radius br) is\n"
    "   below the plane through x with unit normal a, so the clip leaves nothing (the kernel's 0) "
    "*/\n"
    "bool rd_below(vec3 b, float br, vec3 a) {\n"
    "  return a.x * b.x + a.y * b.y + a.z * b.z < -br;\n"
    "}\n"
    "void main() {\n"
    "  ivec2 q = rd_pixel();\n"
    "  vec4 pw = texelFetch(rd_pos, q, 0);\n"
    "  vec4 nw = texelFetch(rd_nrm, q, 0);\n"
    "  int mat = int(nw.w);\n"
    "  vec3 acc0 = vec3(0.0);\n"
    "  vec3 acc1 = vec3(0.0);\n"
    "  vec3 acc2 = vec3(0.0);\n"
    "  if (pw.w >= 0.0 && mat >= 0) {\n"
    "    vec3 x = pw.xyz;\n"
    "    vec3 nrm = nw.xyz;\n"
    "    vec3 d = rd_eye - x;\n"
    "    float len = sqrt(d.x * d.x + d.y * d.y + d.z * d.z);\n"
    "    vec3 view = vec3(d.x / len, d.y / len, d.z / len);\n"
    "    int mo = 12 * mat;\n"
    "    int brdf = int(rd_mats[mo + 6]);\n"
    "    float al = rd_mats[mo + 8];\n",
    "    int npass = brdf == 1 ? 2 : 1;\n"
    "    float dvv = nrm.x * view.x + nrm.y * view.y + nrm.z * view.z;\n"
    "    vec3 rv = vec3(2.0 * dvv * nrm.x - view.x, 2.0 * dvv * nrm.y - view.y, 2.0 * dvv * nrm.z "
    "- view.z);\n"
    "    int nm = RD_NM + min(rd_size.x, 0); /* run-time bounds: one copy of the kernels */\n"
    "    vec3 v[SHLIGHT_POLYGON_MAX];\n"
    "    int nl = int(rd_buf1[0]) + min(rd_size.x, 0); /* this draw's lights: 1 .. nl */\n"
    "    for (int j = 1; j <= nl; ++j) {\n"
    "      int o = RD_LF * j;\n"
    "      int type = int(rd_buf1[o]);\n"
    "      int nv = type == 0 ? int(rd_buf1[o + 1]) : 8;\n"
    "      float rr = rd_buf1[o + 2];\n"
    "      vec3 c = vec3(rd_buf1[o + 8] - x.x, rd_buf1[o + 9] - x.y, rd_buf1[o + 10] - x.z);\n"
    "      vec3 a1 = vec3(rd_buf1[o + 12], rd_buf1[o + 13], rd_buf1[o + 14]);\n"
    "      vec3 a2 = vec3(rd_buf1[o + 16], rd_buf1[o + 17], rd_buf1[o + 18]);\n"
    "      vec3 bc = vec3(rd_buf1[o + 20] - x.x, rd_buf1[o + 21] - x.y, rd_buf1[o + 22] - x.z);\n"
    "      float br = rd_buf1[o + 23];\n"
    "      if (type == 2) { /* the octagons of shl_sphere_phong's disc lie within k rho of c */\n"
    "        float dd = sqrt(c.x * c.x + c.y * c.y + c.z * c.z);\n"
    "        br = dd > rr ? 1.0550226 * (rr * dd / sqrt((dd - rr) * (dd + rr))) + 1.0e-5 : -1.0;\n"
    "      }\n"
    "      bool below = br >= 0.0 && rd_below(bc, br, nrm);\n"
    "      float sggx = 0.0;\n"
    "#if RD_GGX /* only for scenes with GGX materials (~4.5 s of llvmpipe compile time) */\n"
    "      if (brdf == 2 && !below) { /* GGX: shl_polygon_ggx (method independent) */\n"
    "        vec3 cc = c;\n"
    "        vec3 ua = a1;\n"
    "        vec3 va = a2;\n"
    "        int npoly = type == 0 ? 1 : 2;\n"
    "        if (type == 2 && !rd_sphere_disc(c, rr, nrm, view, cc, ua, va)) npoly = 0;\n"
    "        float t = 0.0;\n"
    "        for (int h = 0; h < npoly; ++h) { /* the one call site */\n"
    "          rd_polygon(o, x, type, cc, ua, va, h, v);\n"
    "          t = t + shl_polygon_ggx(v, nv, nrm, view, al);\n"
    "        }\n"
    "        sggx = type == 0 ? t : 0.5 * t;\n"
    "      }\n"
    "#endif\n"
    "      float dex = 0.0; /* the diffuse value of the exact method */\n"
    "      for (int mi = 0; mi < nm; ++mi) {\n"
    "        float vd = 0.0;\n"
    "        float vs = sggx;\n"
    "        int meth = RD_METHODS[mi];\n"
    "        for (int ps = 0; ps < npass; ++ps) {\n"
    "          vec3 vw = ps == 0 ? nrm : view;\n"
    "          float e = ps == 0 ? 1.0 : rd_mats[mo + 7];\n"
    "          vec3 cc = c;\n"
    "          vec3 ua = a1;\n"
    "          vec3 va = a2;\n"
    "          int npoly = type == 0 ? 1 : 2;\n"
    "          if (below || (ps == 1 && br >= 0.0 && rd_below(bc, br, rv))) npoly = 0;\n"
    "          if (type == 2 && !rd_sphere_disc(c, rr, nrm, vw, cc, ua, va)) npoly = 0;\n"
    "          /* Lorentz-Pearson at exponent 1 is the exact recurrence (orders <= 2 take the "
    "exact\n"
    "             path in the kernel): the same bits, not computed twice */\n"
    "          if (ps == 0 && meth == SHLIGHT_EDGE_LORENTZ_PEARSON && RD_METHODS[0] == 0 && mi > "
    "0)\n"
    "            npoly = -1;\n"
    "          float t = 0.0;\n"
    "          for (int h = 0; h < npoly; ++h) {\n"
    "            rd_polygon(o, x, type, cc, ua, va, h, v);\n"
    "            t = t + shl_polygon_phong(v, nv, nrm, vw, e, meth);\n"
    "          }\n"
    "          t = type == 0 ? t : 0.5 * t;\n"
    "          if (npoly < 0) t = dex;\n"
    "          if (ps == 0 && meth == SHLIGHT_EDGE_EXACT) dex = t;\n",
    "          if (ps == 0) vd = t;\n"
    "          else vs = t;\n"
    "        }\n"
    "        vec3 ac = mi == 0 ? acc0 : mi == 1 ? acc1 : acc2;\n"
    "        for (int k = 0; k < 3; ++k)\n"
    "          ac[k] = ac[k] + rd_buf1[o + 4 + k] * (rd_mats[mo + k] * vd + rd_mats[mo + 3 + k] * "
    "vs);\n"
    "        if (mi == 0) acc0 = ac;\n"
    "        else if (mi == 1) acc1 = ac;\n"
    "        else acc2 = ac;\n"
    "      }\n"
    "    }\n"
    "  }\n"
    "  /* llvmpipe ends every loop of an invocation once all its loops together have run 65535\n"
    "     iterations (one shared loop limiter, no error): a loop of 2 iterations that runs 1 says\n"
    "     that happened (w = 0: the host draws fewer lights at a time) */\n"
    "  int left = 0;\n"
    "  for (int i = 0; i < 2 + min(rd_size.x, 0); ++i)\n"
    "    left = left + 1;\n"
    "  float w = left == 2 ? 1.0 : 0.0;\n"
    "  rd_out0 = vec4(acc0, w);\n"
    "#if RD_NM > 1\n"
    "  rd_out1 = vec4(acc1, w);\n"
    "#endif\n"
    "#if RD_NM > 2\n"
    "  rd_out2 = vec4(acc2, w);\n"
    "#endif\n"
    "}\n"};

static const char *const ar_includes[] = {"shl_prelude.glsl", "shl_basis.glsl", "shl_gradient.glsl",
                                          "shl_zonal.glsl",   "shl_light.glsl", "shl_edge.glsl"};

/* ---- ground truth (double) --------------------------------------------------------------- */
typedef struct {
  double x[3], n[3], v[3], r[3], e, a2, nv;
  int brdf;
} ar_pt;

static double ar_dot(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Smith Lambda of GGX for a direction with cosine c to the normal */
static double ar_lambda(double c, double a2) {
  double t2 = (1.0 - c * c) / (c * c);
  return 0.5 * (sqrt(1.0 + a2 * t2) - 1.0);
}

/* the BRDF times the cosine for the unit direction u (towards the light), split into the
   diffuse part (n.u / pi, times kd later) and the specular part (times ks later) */
static void ar_f(const ar_pt *p, const double u[3], double o[2]) {
  double nu = ar_dot(p->n, u);
  o[0] = o[1] = 0.0;
  if (!(nu > 0.0)) return;
  o[0] = nu / AR_PI;
  if (!(p->nv > 0.0)) return;
  if (p->brdf == RD_BRDF_PHONG) {
    double ru = ar_dot(p->r, u);
    if (ru > 0.0) o[1] = (p->e + 1.0) / (2.0 * AR_PI) * pow(ru, p->e);
  } else if (p->brdf == RD_BRDF_GGX) {
    double h[3], hl, nh, den;
    h[0] = u[0] + p->v[0];
    h[1] = u[1] + p->v[1];
    h[2] = u[2] + p->v[2];
    hl = sqrt(ar_dot(h, h));
    if (hl > 0.0) {
      nh = ar_dot(p->n, h) / hl;
      den = nh * nh * (p->a2 - 1.0) + 1.0;
      o[1] = p->a2 / (AR_PI * den * den) / (1.0 + ar_lambda(nu, p->a2) + ar_lambda(p->nv, p->a2)) /
             (4.0 * p->nv);
    }
  }
}

/* adaptive Gauss-Kronrod (7, 15) for a pair of integrands */
typedef void (*ar_fn)(void *ctx, double x, double o[2]);
static const double ar_xk[8] = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.0};
static const double ar_wk[8] = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
static const double ar_wg[4] = {
    0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
    0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

static void ar_adapt(ar_fn f, void *c, double a, double b, double tol, int depth, double o[2]) {
  double m = 0.5 * (a + b), h = 0.5 * (b - a), fc[2], f1[2], f2[2], k[2], g[2], err;
  int j, q;
  f(c, m, fc);
  for (q = 0; q < 2; q++) {
    k[q] = ar_wk[7] * fc[q];
    g[q] = ar_wg[3] * fc[q];
  }
  for (j = 0; j < 7; j++) {
    f(c, m - h * ar_xk[j], f1);
    f(c, m + h * ar_xk[j], f2);
    for (q = 0; q < 2; q++) {
      k[q] += ar_wk[j] * (f1[q] + f2[q]);
      if (j & 1) g[q] += ar_wg[j / 2] * (f1[q] + f2[q]);
    }
  }
  err = fabs(h) * (fabs(k[0] - g[0]) + fabs(k[1] - g[1]));
  if (err <= tol || depth >= 24 || fabs(b - a) < 1e-10) {
    o[0] += h * k[0];
    o[1] += h * k[1];
    return;
  }
  ar_adapt(f, c, a, m, 0.5 * tol, depth + 1, o);
  ar_adapt(f, c, m, b, 0.5 * tol, depth + 1, o);
}

static void ar_frame(const double m[3], double e1[3], double e2[3]) {
  double sg = m[2] >= 0.0 ? 1.0 : -1.0, a = -1.0 / (sg + m[2]), b = m[0] * m[1] * a;
  e1[0] = 1.0 + sg * m[0] * m[0] * a;
  e1[1] = sg * b;
  e1[2] = -sg * m[0];
  e2[0] = b;
  e2[1] = sg + m[1] * m[1] * a;
  e2[2] = -m[1];
}

/* Integration context. Planar lights: polar coordinates about the foot F = x - h m of the
   shading point on the light's plane (m the unit normal towards the point), the direction
   u = sin t (cos phi e1 + sin phi e2) - cos t m, d omega = sin t dt dphi, t = atan(rho / h); the
   region in 2D about F is a triangle q[3] (counter-clockwise) or a disc (qc, R). Spheres: the
   cap about w, u = mu w + sqrt(1 - mu^2) (cos phi e1 + sin phi e2), d omega = dmu dphi. */
typedef struct {
  const ar_pt *p;
  double m[3], e1[3], e2[3], h;
  int disc;
  double q[3][2], qc[2], R;
  double dir[3]; /* planar inner: cos phi e1 + sin phi e2 */
  double mu, st; /* sphere inner */
  double tol_in;
} ar_ctx;

/* [rho0, rho1] of the ray from F in direction (cos phi, sin phi); returns 0 if empty */
static int ar_interval(const ar_ctx *g, double ph, double *r0, double *r1) {
  double dx = cos(ph), dy = sin(ph);
  if (g->disc) {
    double b = dx * g->qc[0] + dy * g->qc[1],
           c = g->qc[0] * g->qc[0] + g->qc[1] * g->qc[1] - g->R * g->R, disc = b * b - c, sq;
    if (disc <= 0.0) return 0;
    sq = sqrt(disc);
    *r0 = fmax(0.0, b - sq);
    *r1 = b + sq;
    return *r1 > *r0;
  } else {
    double lo = 0.0, hi = 1e300;
    int i;
    for (i = 0; i < 3; i++) {
      const double *a = g->q[i], *b = g->q[(i + 1) % 3];
      double ex = b[0] - a[0], ey = b[1] - a[1];
      double A = ex * dy - ey * dx, B = ex * a[1] - ey * a[0];
      /* inside: cross(E, rho d - a) = rho A - B >= 0 */
      if (A > 0.0)
        lo = fmax(lo, B / A);
      else if (A < 0.0)
        hi = fmin(hi, B / A);
      else if (B > 0.0)
        return 0;
    }
    *r0 = lo;
    *r1 = hi;
    return hi > lo && hi < 1e299;
  }
}

static void ar_plane_inner(void *cv, double t, double o[2]) {
  const ar_ctx *g = (const ar_ctx *)cv;
  double u[3], st = sin(t), ct = cos(t);
  int c;
  for (c = 0; c < 3; c++)
    u[c] = st * g->dir[c] - ct * g->m[c];
  ar_f(g->p, u, o);
  o[0] *= st;
  o[1] *= st;
}

static void ar_plane_outer(void *cv, double ph, double o[2]) {
  ar_ctx *g = (ar_ctx *)cv;
  double r0, r1, t0, t1, th, cp = cos(ph), sp = sin(ph);
  int c;
  o[0] = o[1] = 0.0;
  if (!ar_interval(g, ph, &r0, &r1)) return;
  for (c = 0; c < 3; c++)
    g->dir[c] = cp * g->e1[c] + sp * g->e2[c];
  t0 = atan2(r0, g->h);
  t1 = atan2(r1, g->h);
  /* the horizon n.u = 0 crosses at tan t = (n.m) / (n.dir): split there */
  th = atan2(ar_dot(g->p->n, g->m), ar_dot(g->p->n, g->dir));
  if (th < 0.0) th += AR_PI;
  if (th > t0 && th < t1) {
    ar_adapt(ar_plane_inner, g, t0, th, 0.5 * g->tol_in, 0, o);
    ar_adapt(ar_plane_inner, g, th, t1, 0.5 * g->tol_in, 0, o);
  } else {
    ar_adapt(ar_plane_inner, g, t0, t1, g->tol_in, 0, o);
  }
}

/* plane setup from a point on it and its normal; returns 0 when x is (nearly) in the plane */
static int ar_plane(ar_ctx *g, const double o[3], const double m[3]) {
  const ar_pt *p = g->p;
  double h = (p->x[0] - o[0]) * m[0] + (p->x[1] - o[1]) * m[1] + (p->x[2] - o[2]) * m[2];
  int c;
  for (c = 0; c < 3; c++)
    g->m[c] = h < 0.0 ? -m[c] : m[c];
  g->h = fabs(h);
  if (!(g->h > 1e-9)) return 0;
  ar_frame(g->m, g->e1, g->e2);
  return 1;
}

/* 2D coordinates about the foot F = x - h m */
static void ar_2d(const ar_ctx *g, const double w[3], double q[2]) {
  double d[3];
  int c;
  for (c = 0; c < 3; c++)
    d[c] = w[c] - (g->p->x[c] - g->h * g->m[c]);
  q[0] = ar_dot(d, g->e1);
  q[1] = ar_dot(d, g->e2);
}

static double ar_wrap(double a) {
  while (a > AR_PI)
    a -= 2.0 * AR_PI;
  while (a <= -AR_PI)
    a += 2.0 * AR_PI;
  return a;
}

static void ar_sort3(double *a) {
  int i, j;
  for (i = 0; i < 3; i++)
    for (j = i + 1; j < 3; j++)
      if (a[j] < a[i]) {
        double t = a[i];
        a[i] = a[j];
        a[j] = t;
      }
}

/* azimuth pieces [ph[k], ph[k+1]] of a planar region, integrated to acc */
static void ar_plane_pieces(ar_ctx *g, const double *ph, int np, double tol, double acc[2]) {
  int k;
  double span = ph[np] - ph[0];
  g->tol_in = 0.1 * tol / (span > 0.0 ? span : 1.0);
  for (k = 0; k < np; k++)
    ar_adapt(ar_plane_outer, g, ph[k], ph[k + 1], tol * (ph[k + 1] - ph[k]) / span, 0, acc);
}

static void ar_gt_tri(const ar_pt *p, const double a[3], const double b[3], const double c[3],
                      double tol, double acc[2]) {
  double e1[3], e2[3], m[3], ml, ang[4], cr, tmp;
  ar_ctx g;
  int i, inside = 1;
  for (i = 0; i < 3; i++) {
    e1[i] = b[i] - a[i];
    e2[i] = c[i] - a[i];
  }
  m[0] = e1[1] * e2[2] - e1[2] * e2[1];
  m[1] = e1[2] * e2[0] - e1[0] * e2[2];
  m[2] = e1[0] * e2[1] - e1[1] * e2[0];
  ml = sqrt(ar_dot(m, m));
  if (!(ml > 0.0)) return;
  for (i = 0; i < 3; i++)
    m[i] /= ml;
  memset(&g, 0, sizeof g);
  g.p = p;
  if (!ar_plane(&g, a, m)) return;
  ar_2d(&g, a, g.q[0]);
  ar_2d(&g, b, g.q[1]);
  ar_2d(&g, c, g.q[2]);
  cr = (g.q[1][0] - g.q[0][0]) * (g.q[2][1] - g.q[0][1]) -
       (g.q[1][1] - g.q[0][1]) * (g.q[2][0] - g.q[0][0]);
  if (cr < 0.0)
    for (i = 0; i < 2; i++) {
      tmp = g.q[1][i];
      g.q[1][i] = g.q[2][i];
      g.q[2][i] = tmp;
    }
  for (i = 0; i < 3; i++) {
    const double *qa = g.q[i], *qb = g.q[(i + 1) % 3];
    /* F (the origin) inside: cross(qb - qa, -qa) >= 0 for every edge */
    if ((qb[0] - qa[0]) * (-qa[1]) - (qb[1] - qa[1]) * (-qa[0]) < 0.0) inside = 0;
    ang[i] = atan2(qa[1], qa[0]);
  }
  if (inside) { /* pieces between the vertex directions around the full circle */
    ar_sort3(ang);
    ang[3] = ang[0] + 2.0 * AR_PI;
    ar_plane_pieces(&g, ang, 3, tol, acc);
  } else { /* the vertex directions relative to the centroid's span less than pi */
    double ref = atan2(g.q[0][1] + g.q[1][1] + g.q[2][1], g.q[0][0] + g.q[1][0] + g.q[2][0]);
    for (i = 0; i < 3; i++)
      ang[i] = ar_wrap(ang[i] - ref);
    ar_sort3(ang);
    for (i = 0; i < 3; i++)
      ang[i] += ref;
    ar_plane_pieces(&g, ang, 2, tol, acc);
  }
}

static void ar_gt_disc(const ar_pt *p, const double c[3], const double m[3], double R, double tol,
                       double acc[2]) {
  ar_ctx g;
  double dq, ph[3];
  memset(&g, 0, sizeof g);
  g.p = p;
  if (!ar_plane(&g, c, m)) return;
  g.disc = 1;
  g.R = R;
  ar_2d(&g, c, g.qc);
  dq = sqrt(g.qc[0] * g.qc[0] + g.qc[1] * g.qc[1]);
  ph[1] = atan2(g.qc[1], g.qc[0]); /* towards the centre (split there: the ray's end points */
  if (dq < R) {                    /* are extreme in that direction and the opposite one) */
    ph[0] = ph[1] - AR_PI;
    ph[2] = ph[1] + AR_PI;
  } else {
    double amp = asin(fmin(1.0, R / dq));
    ph[0] = ph[1] - amp;
    ph[2] = ph[1] + amp;
  }
  ar_plane_pieces(&g, ph, 2, tol, acc);
}

static void ar_sphere_inner(void *cv, double ph, double o[2]) {
  const ar_ctx *g = (const ar_ctx *)cv;
  double u[3], cp = cos(ph), sp = sin(ph);
  int c;
  for (c = 0; c < 3; c++)
    u[c] = g->mu * g->m[c] + g->st * (cp * g->e1[c] + sp * g->e2[c]);
  ar_f(g->p, u, o);
}

static void ar_sphere_outer(void *cv, double mu, double o[2]) {
  ar_ctx *g = (ar_ctx *)cv;
  double A = ar_dot(g->p->n, g->e1), B = ar_dot(g->p->n, g->e2), C = ar_dot(g->p->n, g->m);
  double R = sqrt(A * A + B * B), st = sqrt(fmax(0.0, 1.0 - mu * mu)), q;
  o[0] = o[1] = 0.0;
  g->mu = mu;
  g->st = st;
  /* the horizon crosses the circle mu where R cos(phi - phi0) = -mu C / st: split there */
  q = st * R > 0.0 ? -mu * C / (st * R) : 2.0;
  if (fabs(q) < 1.0) {
    double p0 = atan2(B, A), da = acos(q);
    ar_adapt(ar_sphere_inner, g, p0 - da, p0 + da, 0.5 * g->tol_in, 0, o);
    ar_adapt(ar_sphere_inner, g, p0 + da, p0 - da + 2.0 * AR_PI, 0.5 * g->tol_in, 0, o);
  } else {
    ar_adapt(ar_sphere_inner, g, 0.0, 2.0 * AR_PI, g->tol_in, 0, o);
  }
}

static void ar_gt_sphere(const ar_pt *p, const double c[3], double R, double tol, double acc[2]) {
  ar_ctx g;
  double d, m0, ms;
  int j;
  memset(&g, 0, sizeof g);
  g.p = p;
  for (j = 0; j < 3; j++)
    g.m[j] = c[j] - p->x[j];
  d = sqrt(ar_dot(g.m, g.m));
  if (!(d > 0.0)) return;
  for (j = 0; j < 3; j++)
    g.m[j] /= d;
  m0 = d > R ? sqrt((d - R) * (d + R)) / d : -1.0;
  ar_frame(g.m, g.e1, g.e2);
  g.tol_in = 0.1 * tol / (1.0 - m0);
  /* the horizon starts to cut the circles at mu = |n - (n.w) w| */
  ms = sqrt(fmax(0.0, 1.0 - ar_dot(p->n, g.m) * ar_dot(p->n, g.m)));
  if (ms > m0 && ms < 1.0) {
    ar_adapt(ar_sphere_outer, &g, m0, ms, tol * (ms - m0) / (1.0 - m0), 0, acc);
    ar_adapt(ar_sphere_outer, &g, ms, 1.0, tol * (1.0 - ms) / (1.0 - m0), 0, acc);
  } else {
    ar_adapt(ar_sphere_outer, &g, m0, 1.0, tol, 0, acc);
  }
}

/* Closed forms of the diffuse part (irradiance of a unit-radiance light at the unit normal n,
   clipped to the horizon), in double. Polygon (vertices relative to the shading point, convex,
   two-sided): Lambert's formula after the horizon clip. Sphere (centre w relative to the
   shading point): the horizon-clipped cap of Snyder (1996), in the form of Lagarde and de
   Rousiers (2014, listing 7); inside the sphere: pi. Both are checked against quadrature in
   pass_grid.c's ground truth. */
static double ar_poly_irr(double (*v)[3], int nv, const double n[3]) {
  double p[RD_MAX_POLY + 2][3], sum = 0.0;
  int i, k, m = 0;
  for (i = 0; i < nv; i++) {
    const double *a = v[i], *b = v[(i + 1) % nv];
    double da = ar_dot(n, a), db = ar_dot(n, b);
    if (da >= 0.0 && m < RD_MAX_POLY + 2) {
      for (k = 0; k < 3; k++)
        p[m][k] = a[k];
      m++;
    }
    if ((da >= 0.0) != (db >= 0.0) && m < RD_MAX_POLY + 2) {
      double t = da / (da - db);
      for (k = 0; k < 3; k++)
        p[m][k] = a[k] + t * (b[k] - a[k]);
      m++;
    }
  }
  for (i = 0; i < m; i++) {
    const double *a = p[i], *b = p[(i + 1) % m];
    double c[3], cl;
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
    cl = sqrt(ar_dot(c, c));
    if (cl > 0.0) sum += atan2(cl, ar_dot(a, b)) * ar_dot(n, c) / cl;
  }
  return m < 3 ? 0.0 : 0.5 * fabs(sum);
}

static double ar_sphere_irr(const double w[3], double r, const double n[3]) {
  double d = sqrt(ar_dot(w, w)), s2, ct, st, x, y, sy, e;
  if (!(d > r)) return AR_PI;
  s2 = (r / d) * (r / d);
  ct = fmin(1.0, fmax(-1.0, ar_dot(n, w) / d));
  if (ct * ct > s2) return ct > 0.0 ? AR_PI * s2 * ct : 0.0;
  st = sqrt(1.0 - ct * ct);
  x = sqrt(1.0 / s2 - 1.0);
  y = fmin(1.0, fmax(-1.0, -x * ct / st));
  sy = st * sqrt(1.0 - y * y);
  e = (ct * acos(y) - x * sy) * s2 + atan(sy / x);
  return e > 0.0 ? e : 0.0;
}

/* reference radiance at pixel i: tol is the absolute tolerance per light of the unit-radiance
   integrals (diffuse and specular parts, before kd, ks and the radiance) */
static void ar_shade_gt(const rd_scene *s, const rd_gbuf *gb, size_t i, double tol, float out[3]) {
  const rd_material *mt = &s->mats[gb->mat[i]];
  ar_pt p;
  double d[3], l, nl, tot[3] = {0.0, 0.0, 0.0};
  int j, k, c;
  memset(&p, 0, sizeof p);
  for (k = 0; k < 3; k++) {
    p.x[k] = (double)gb->pos[3 * i + (size_t)k];
    p.n[k] = (double)gb->nrm[3 * i + (size_t)k];
    d[k] = (double)gb->eye[k] - p.x[k];
  }
  nl = sqrt(ar_dot(p.n, p.n));
  l = sqrt(ar_dot(d, d));
  for (k = 0; k < 3; k++) {
    p.n[k] /= nl;
    p.v[k] = d[k] / l;
  }
  p.nv = ar_dot(p.n, p.v);
  for (k = 0; k < 3; k++)
    p.r[k] = 2.0 * p.nv * p.n[k] - p.v[k];
  p.brdf = mt->brdf;
  p.e = (double)mt->exponent;
  p.a2 = (double)mt->roughness * (double)mt->roughness;
  for (j = 0; j < s->nlights; j++) {
    const rd_light *lt = &s->lights[j];
    double v[RD_MAX_POLY][3], cc[3], m[3], acc[2] = {0.0, 0.0};
    int glossy = p.brdf == RD_BRDF_PHONG || p.brdf == RD_BRDF_GGX;
    if (lt->type == RD_LIGHT_POLYGON || lt->type == RD_LIGHT_TRIANGLE) {
      int nv = lt->type == RD_LIGHT_TRIANGLE ? 3 : lt->nv;
      if (nv < 3 || nv > RD_MAX_POLY) continue;
      for (k = 0; k < nv; k++)
        for (c = 0; c < 3; c++)
          v[k][c] = (double)lt->v[k][c];
      if (glossy)
        for (k = 1; k + 1 < nv; k++) /* fan (planar convex polygons) */
          ar_gt_tri(&p, v[0], v[k], v[k + 1], tol / (double)(nv - 2), acc);
      for (k = 0; k < nv; k++)
        for (c = 0; c < 3; c++)
          v[k][c] -= p.x[c];
      acc[0] = ar_poly_irr(v, nv, p.n) / AR_PI; /* the diffuse part in closed form */
    } else if (lt->type == RD_LIGHT_DISC) {
      double ml = sqrt((double)rd_dot(lt->n, lt->n));
      for (c = 0; c < 3; c++) {
        cc[c] = (double)lt->c[c];
        m[c] = (double)lt->n[c] / ml;
      }
      ar_gt_disc(&p, cc, m, (double)lt->r, tol, acc);
    } else if (lt->type == RD_LIGHT_SPHERE) {
      for (c = 0; c < 3; c++)
        cc[c] = (double)lt->c[c];
      if (glossy) ar_gt_sphere(&p, cc, (double)lt->r, tol, acc);
      for (c = 0; c < 3; c++)
        cc[c] -= p.x[c];
      acc[0] = ar_sphere_irr(cc, (double)lt->r, p.n) / AR_PI; /* closed form */
    } else {
      continue;
    }
    for (c = 0; c < 3; c++)
      tot[c] += (double)lt->radiance[c] * ((double)mt->kd[c] * acc[0] + (double)mt->ks[c] * acc[1]);
  }
  for (c = 0; c < 3; c++)
    out[c] = (float)tot[c];
}

/* ---- driver ------------------------------------------------------------------------------ */
typedef struct {
  char method[40], path[8];
  rd_image img;
  double ms, tol;
  size_t mem;
} ar_out;

static int ar_cmp(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return x < y ? -1 : x > y;
}

typedef struct {
  const rd_run *run;
  const float *lb, *mats;
  int nl, m;
  double tol;
  rd_image *img;
} ar_job;

static void ar_cpu_rows(void *ctx, long lo, long hi) {
  const ar_job *jb = (const ar_job *)ctx;
  const rd_gbuf *gb = jb->run->gb;
  size_t i;
  for (i = (size_t)lo; i < (size_t)hi; i++) {
    float *o = jb->img->rgb + 3 * i;
    if (gb->mat[i] < 0 || gb->depth[i] < 0.0f) {
      o[0] = o[1] = o[2] = 0.0f;
      continue;
    }
    ar_shade(jb->lb, jb->nl, gb->pos + 3 * i, gb->nrm + 3 * i, gb->eye, jb->mats + 12 * gb->mat[i],
             ar_methods[jb->m], o);
  }
}

/* CPU image of method m (index into ar_methods), reps times, on rd_threads() threads; median
   CPU ms (all threads together) */
static double ar_cpu_image(const rd_run *run, const float *lb, int nl, const float *mats, int m,
                           rd_image *img) {
  const rd_gbuf *gb = run->gb;
  int reps = run->reps > 0 ? run->reps : 1, r;
  double ts[64];
  ar_job jb;
  jb.run = run;
  jb.lb = lb;
  jb.mats = mats;
  jb.nl = nl;
  jb.m = m;
  jb.tol = 0.0;
  jb.img = img;
  if (reps > 64) reps = 64;
  for (r = 0; r < reps; r++)
    ts[r] = rd_parallel((long)gb->w * gb->h, gb->w, ar_cpu_rows, &jb, NULL);
  qsort(ts, (size_t)reps, sizeof(double), ar_cmp);
  return ts[reps / 2];
}

static void ar_gt_rows(void *ctx, long lo, long hi) {
  const ar_job *jb = (const ar_job *)ctx;
  const rd_gbuf *gb = jb->run->gb;
  size_t i;
  for (i = (size_t)lo; i < (size_t)hi; i++) {
    float *o = jb->img->rgb + 3 * i;
    if (gb->mat[i] < 0 || gb->depth[i] < 0.0f) {
      o[0] = o[1] = o[2] = 0.0f;
      continue;
    }
    ar_shade_gt(jb->run->scene, gb, i, jb->tol, o);
  }
}

/* the gt image on rd_threads() threads; returns their CPU ms together */
static double ar_gt_image(const rd_run *run, double tol, const char *label, rd_image *img) {
  ar_job jb;
  memset(&jb, 0, sizeof jb);
  jb.run = run;
  jb.tol = tol;
  jb.img = img;
  return rd_parallel((long)run->gb->w * run->gb->h, run->gb->w, ar_gt_rows, &jb, label);
}

/* GL images of methods m0 .. m0 + nm - 1 in one shader (one draw computes all of them). The
   lights go to the GPU in draws of at most *io_chunk lights (0: all), summed here: the buffer
   is a header of AR_LF floats ([0] the draw's light count) and the draw's lights, so the shader
   source is the same for every draw (compiled once where Mesa's shader cache is on). llvmpipe
   ends every loop of an invocation once its loops together have run 65535 iterations, without
   an error; the shader's sentinel reports it (w != 1) and the lights are then drawn again in
   draws of half as many (manylights: 120 lights at 64x48 in 2 draws of 60). *ms is the sum of
   the draws' times. */
static int ar_gl_images(const rd_run *run, const float *lb, int nl, int m0, int nm, rd_image *img,
                        double *ms, int *io_chunk) {
  const rd_scene *s = run->scene;
  int ggx = 0, chunk = *io_chunk > 0 && *io_chunk < nl ? *io_chunk : nl, over = 1, j0, c;
  char defs[512];
  rd_gl_pass p;
  const float *bufs[1];
  size_t bf[1], np = (size_t)run->gb->w * (size_t)run->gb->h, i;
  float *out, *outp[3], *cb;
  char *body;
  int rc = 0, k;
  double tot = 0.0, dms = 0.0;
  memset(&p, 0, sizeof p);
  for (k = 0; k < s->nmats; k++)
    ggx = ggx || s->mats[k].brdf == RD_BRDF_GGX;
  snprintf(defs, sizeof defs,
           "#define SHLIGHT_MAX_BANDS 1\n#define RD_LF %d\n#define RD_NM %d\n"
           "#define RD_GGX %d\nconst int RD_METHODS[3] = int[3](%d, %d, %d);\n",
           AR_LF, nm, ggx, ar_methods[m0], ar_methods[(m0 + 1) % 3], ar_methods[(m0 + 2) % 3]);
  p.defines = defs;
  p.includes = ar_includes;
  p.ninclude = (int)(sizeof ar_includes / sizeof ar_includes[0]);
  {
    size_t nb = 1;
    for (k = 0; k < (int)(sizeof ar_glsl / sizeof ar_glsl[0]); k++)
      nb += strlen(ar_glsl[k]);
    body = (char *)malloc(nb);
    if (!body) return -1;
    body[0] = 0;
    for (k = 0; k < (int)(sizeof ar_glsl / sizeof ar_glsl[0]); k++)
      strcat(body, ar_glsl[k]);
  }
  out = (float *)malloc(sizeof(float) * 4u * np * (size_t)nm);
  cb = (float *)malloc(sizeof(float) * AR_LF * ((size_t)nl + 1u));
  if (!out || !cb) {
    free(out);
    free(cb);
    free(body);
    return -1;
  }
  bufs[0] = cb;
  p.body = body;
  p.bufs = bufs;
  p.buf_floats = bf;
  p.nbuf = 1;
  p.nout = nm;
  for (k = 0; k < nm; k++)
    outp[k] = out + 4u * np * (size_t)k;
  while (over && rc == 0) {
    over = 0;
    tot = 0.0;
    for (k = 0; k < nm; k++)
      memset(img[k].rgb, 0, sizeof(float) * 3u * np);
    for (j0 = 0; j0 < nl && rc == 0; j0 += chunk) {
      c = nl - j0 < chunk ? nl - j0 : chunk;
      memset(cb, 0, sizeof(float) * AR_LF);
      cb[0] = (float)c;
      memcpy(cb + AR_LF, lb + (size_t)j0 * AR_LF, sizeof(float) * AR_LF * (size_t)c);
      bf[0] = (size_t)(c + 1) * AR_LF;
      rc = rd_gl_run(run->scene, run->gb, &p, outp, run->reps > 0 ? run->reps : 1, &dms);
      tot += dms;
      if (rc == 0)
        for (k = 0; k < nm; k++)
          for (i = 0; i < np; i++) {
            over = over || outp[k][4 * i + 3] != 1.0f;
            img[k].rgb[3 * i] += outp[k][4 * i];
            img[k].rgb[3 * i + 1] += outp[k][4 * i + 1];
            img[k].rgb[3 * i + 2] += outp[k][4 * i + 2];
          }
    }
    if (over && chunk == 1) {
      fprintf(stderr, "area: one light alone exceeds llvmpipe's loop limit; GL image wrong\n");
      over = 0;
    }
    if (over) chunk = (chunk + 1) / 2;
  }
  *ms = tot;
  *io_chunk = chunk;
  free(out);
  free(cb);
  free(body);
  return rc;
}

static void ar_add(ar_out *o, const char *method, const char *path, rd_image img, double ms,
                   size_t mem, double tol) {
  snprintf(o->method, sizeof o->method, "%s", method);
  snprintf(o->path, sizeof o->path, "%s", path);
  o->img = img;
  o->ms = ms;
  o->mem = mem;
  o->tol = tol;
}

int rd_pass_area(rd_run *run) {
  const rd_scene *s = run->scene;
  const rd_gbuf *gb = run->gb;
  float *lb = NULL, *mats = NULL;
  int nl, k, m, rc = 0, nout = 0, ggx = 0, *sel = NULL;
  size_t mem;
  ar_out outs[2 * 3 + 2], gouts[3];
  int ngout = 0;
  nl = ar_collect(s, &lb);
  if (nl <= 0) {
    free(lb);
    return nl < 0 ? -1 : 0;
  }
  mem = (size_t)nl * AR_LF * sizeof(float);
  /* the materials as the GL pass sees them (12 floats each, rd_gl_pass layout) */
  mats = (float *)calloc((size_t)(s->nmats > 0 ? s->nmats : 1) * 12, sizeof(float));
  if (!mats) {
    free(lb);
    return -1;
  }
  for (k = 0; k < s->nmats; k++) {
    float *q = mats + 12 * k;
    memcpy(q, s->mats[k].kd, 3 * sizeof(float));
    memcpy(q + 3, s->mats[k].ks, 3 * sizeof(float));
    q[6] = (float)s->mats[k].brdf;
    q[7] = s->mats[k].exponent;
    q[8] = s->mats[k].roughness;
  }
  /* GL first: llvmpipe's JIT of this pass's shader (single-threaded) is the longest piece of
     the run that cannot be split; the CPU paths' rows fill the CPUs around it. The results keep
     their order (CPU, GL, gt) */
  if (run->use_gl) {
    /* CI (gt <= 1): the three methods in one shader and one draw (llvmpipe compile time), the
       draw's time reported for each; gt 2: one shader per method, per-method timings */
    int per = run->gt >= 2, g, chunk = 0;
    for (g = 0; g < (per ? 3 : 1); g++) {
      rd_image im[3];
      int nm = per ? 1 : 3, ok = 1;
      double ms = 0.0;
      for (k = 0; k < nm; k++) {
        im[k] = rd_image_new(gb->w, gb->h);
        ok = ok && im[k].rgb;
      }
      if (ok && ar_gl_images(run, lb, nl, g, nm, im, &ms, &chunk) == 0) {
        for (k = 0; k < nm; k++)
          ar_add(&gouts[ngout++], ar_names[g + k], "gl", im[k], ms, mem, ar_tol[g + k]);
      } else {
        fprintf(stderr, "area: GL pass failed; gl path skipped\n");
        for (k = 0; k < nm; k++)
          rd_image_free(&im[k]);
        rc = -1;
        break;
      }
    }
    if (!per && rc == 0)
      printf("area gl: the three methods run in one shader and one draw per group of lights "
             "(llvmpipe compile time; --gt 2 times them apart): gl ms is that of the draws\n");
    if (rc == 0 && chunk < nl)
      printf("area gl: %d lights in draws of at most %d (llvmpipe's limit of 65535 loop "
             "iterations per invocation); gl ms is the draws' sum\n",
             nl, chunk);
  }
  if (run->use_cpu)
    for (m = 0; m < 3; m++) {
      rd_image im = rd_image_new(gb->w, gb->h);
      if (!im.rgb) {
        rc = -1;
        goto done;
      }
      ar_add(&outs[nout++], ar_names[m], "cpu", im, ar_cpu_image(run, lb, nl, mats, m, &im), mem,
             0.0);
    }
  for (k = 0; k < ngout; k++)
    outs[nout++] = gouts[k];
  ngout = 0;
  if (run->gt) {
    /* absolute tolerance of the unit-radiance integrals per light; gt_coarse: 10x looser */
    double tol = run->gt >= 2 ? 1e-7 : 1e-5, tms[2];
    int gi, i0 = nout;
    rd_tm tm = rd_tm_now();
    for (gi = 0; gi < 2; gi++) {
      rd_image im = rd_image_new(gb->w, gb->h);
      if (!im.rgb) {
        rc = -1;
        goto done;
      }
      tms[gi] = ar_gt_image(run, gi ? 10.0 * tol : tol, gi ? "area gt coarse" : "area gt", &im);
      ar_add(&outs[nout++], gi ? "gt_coarse" : "gt", gi ? "cpu" : "gt", im, tms[gi], 0, 0.0);
    }
    rd_tm_add(RD_TM_GT, tm);
    printf("area gt: diffuse part of polygons and spheres in closed form, the rest by adaptive "
           "Gauss-Kronrod cubature, tolerance %.0e per light (%.0f ms); gt_coarse at %.0e (%.0f "
           "ms) vs gt: RMSE/RMS %.2e, max|diff|/peak %.2e\n",
           tol, tms[0], 10.0 * tol, tms[1], rd_relrmse(gb, &outs[i0 + 1].img, &outs[i0].img, -1),
           rd_compare(&outs[i0 + 1].img, &outs[i0].img, gb->mat).maxrel);
    printf("area vs gt, RMSE/RMS by material (");
    for (k = 0; k < s->nmats && k < 6; k++)
      printf("%s%s%s", k ? ", " : "", s->mats[k].name,
             s->mats[k].brdf == RD_BRDF_PHONG ? " [phong]"
             : s->mats[k].brdf == RD_BRDF_GGX ? " [ggx]"
                                              : "");
    printf("):\n");
    for (m = 0; m < nout; m++) {
      if (m == i0 || (!strcmp(outs[m].path, "gl") && run->use_cpu)) continue;
      printf("  %-16s %-3s all %.2e:", outs[m].method, outs[m].path,
             rd_relrmse(gb, &outs[m].img, &outs[i0].img, -1));
      for (k = 0; k < s->nmats && k < 6; k++)
        printf(" %.2e", rd_relrmse(gb, &outs[m].img, &outs[i0].img, k));
      printf("\n");
    }
  }
  for (k = 0; k < s->nmats; k++)
    ggx = ggx || s->mats[k].brdf == RD_BRDF_GGX;
  if (ggx) {
    sel = (int *)calloc((size_t)s->nmats, sizeof(int));
    if (!sel) {
      rc = -1;
      goto done;
    }
    for (k = 0; k < s->nmats; k++)
      sel[k] = s->mats[k].brdf == RD_BRDF_GGX;
  }
  for (k = 0; k < nout; k++) {
    if (sel && !strcmp(outs[k].path, "gl"))
      rd_emit_sel(run, "area", outs[k].method, outs[k].path, outs[k].img, outs[k].ms, outs[k].mem,
                  outs[k].tol, sel, s->nmats, AR_TOL_GGX, "ggx");
    else
      rd_emit(run, "area", outs[k].method, outs[k].path, outs[k].img, outs[k].ms, outs[k].mem,
              outs[k].tol);
    outs[k].img.rgb = NULL;
  }
  nout = 0;
done:
  for (k = 0; k < nout; k++)
    rd_image_free(&outs[k].img);
  for (k = 0; k < ngout; k++)
    rd_image_free(&gouts[k].img);
  free(lb);
  free(mats);
  free(sel);
  return rc;
}
