/* fuzz_families.c - libFuzzer target for shlight's public function families other than the
 * basis (tests/fuzz_basis.c) and the BRDF table loaders (tests/fuzz_brdftab.c):
 *   family 0 light:  zh_cap(_da, _printed), zh_rotate, sphere_light(_grad), triangle_light(_grad),
 *                    triangle_solid_angle
 *   family 1 grid:   grid_build, grid_sample, grid_trilinear / _taylor / _hermite
 *   family 2 edge:   edge_integral, polygon_moment / _phong / _phong2, ellipse_phong, sphere_phong,
 *                    polygon_ggx(_ndf), polygon_beckmann(_taylor, _ndf), polygon_blinn_phong,
 *                    lobe_to_sg, sg_to_lobe, lobe_product
 *   family 3 brdf:   zh_phong / cosine_power / lambert / blinn_phong / ggx / beckmann, sh_dot,
 *                    sh_conv_zh, zh_dot_zh, zh_irradiance(3), zh_window, zh_bands_for,
 *                    sh_rotate_z, brdf_eval
 *   family 4 hvl:    hvl_horizon(_smoothstep), hvl_geometric, hvl_emission, hvl_radiance,
 *                    hvl_contribution(_zh), hvl_radius_neighbours, hvl_radius_fov(_tan)
 *   family 5 ssf:    ssf_vpl_sh, ssf_vpl_irradiance, ssf_interleave, ssf_weight, ssf_irradiance
 * Input: byte 0 picks the family (mod 6; -DFUZZ_ONLY=k pins it), the rest is read as a stream:
 * each float is one selector byte (a quarter of the values come from a table of hard values:
 * 0, -0, denormals, 1e-20, 1e15, 1e21, 3e9, 1e38, FLT_MAX, inf, NaN, ...) and, for the rest,
 * four raw bytes; missing bytes read as zero.
 * Checked: every output array is malloc'ed with its documented size plus 4 canary floats that
 * must be unchanged (ASan sees the writes past those too), no UB (UBSan with float-cast-overflow
 * in the replay build), and finiteness where the function's contract promises it for finite
 * input (comments at each check). The edge family keeps exponent <= 1e9, method ids valid
 * and subedges in [0, 64]: the float-to-int and INT_MIN cases outside those are the area
 * helpers' (docs/contracts.md) and would stop the sanitizer replay; its values are checked for
 * finiteness only where the documented current behaviour promises it.
 * Replay without libFuzzer: tests/fuzz_replay.c (links against the two globals below);
 * seeded random driver: tests/fuzz_random.c. */
#define SHLIGHT_ASSERT(x) ((void)0)
#define SHLIGHT_IMPLEMENTATION
#include "../shlight.h"
#include "ref/published.h" /* the published forms, for comparison */

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* the names tests/fuzz_replay.c links against */
int fuzz_basis_soft_fail;
long fuzz_basis_failures;

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* clang-format off */
#define FF_LIST(X)                                                                                \
  X(zh_cap) X(zh_cap_da) X(zh_cap_printed) X(zh_rotate) X(sphere_light) X(sphere_light_grad)      \
  X(triangle_light) X(triangle_light_grad) X(triangle_solid_angle) X(grid_build)                  \
  X(grid_sample) X(grid_trilinear) X(grid_taylor) X(grid_hermite) X(edge_integral)                \
  X(polygon_moment) X(polygon_phong) X(polygon_phong2) X(ellipse_phong) X(sphere_phong)           \
  X(polygon_ggx_ndf) X(polygon_ggx) X(polygon_beckmann_taylor) X(polygon_beckmann_ndf)            \
  X(polygon_blinn_phong) X(polygon_beckmann) X(lobe_to_sg) X(sg_to_lobe) X(lobe_product)          \
  X(zh_phong) X(zh_cosine_power) X(zh_lambert) X(zh_blinn_phong) X(zh_ggx) X(zh_beckmann)         \
  X(sh_dot) X(sh_conv_zh) X(zh_dot_zh) X(zh_irradiance3) X(zh_irradiance) X(zh_window)            \
  X(zh_bands_for) X(sh_rotate_z) X(brdf_eval) X(hvl_horizon) X(hvl_horizon_smoothstep)            \
  X(hvl_geometric) X(hvl_emission) X(hvl_radiance) X(hvl_contribution) X(hvl_contribution_zh)     \
  X(hvl_radius_neighbours) X(hvl_radius_fov) X(hvl_radius_fov_tan) X(ssf_vpl_sh)                  \
  X(ssf_vpl_irradiance) X(ssf_interleave) X(ssf_weight) X(ssf_irradiance) X(sh_irradiance_matrix)
/* clang-format on */
#define FF_ENUM(name) FF_##name,
enum { FF_LIST(FF_ENUM) FF_COUNT };
#define FF_NAME(name) "shl_" #name,
const char *const fuzz_fam_names[FF_COUNT] = {FF_LIST(FF_NAME)};
long fuzz_fam_calls[FF_COUNT];
long fuzz_fam_fails[FF_COUNT];
#define CALL(id) (fuzz_fam_calls[FF_##id]++)

typedef struct {
  const uint8_t *p;
  size_t n, i;
} rd_t;
static unsigned rd_u8(rd_t *r) {
  return r->i < r->n ? r->p[r->i++] : 0u;
}
static const float HARD[32] = {
    0.0f,      -0.0f, 1.0f,    -1.0f,  0.5f,  1e-45f,  1e-40f,   1.17549435e-38f,
    1e-20f,    1e-8f, 1e-3f,   2.0f,   10.0f, 1e4f,    3e9f,     1e12f,
    1e15f,     1e18f, 1e21f,   1e30f,  1e38f, FLT_MAX, -FLT_MAX, INFINITY,
    -INFINITY, NAN,   0.7071f, -1e15f, 64.0f, 1e8f,    -1e-20f,  0.999999f};
static float rd_f(rd_t *r) {
  unsigned s = rd_u8(r);
  uint32_t b;
  float f;
  if ((s & 3u) == 0) return HARD[(s >> 2) & 31u];
  if ((s & 3u) == 1) return (float)((int)(s >> 2) - 32) / 8.0f; /* small exact values */
  b = rd_u8(r) | (rd_u8(r) << 8) | (rd_u8(r) << 16) | ((uint32_t)rd_u8(r) << 24);
  memcpy(&f, &b, 4);
  return f;
}
static void rd_v3(rd_t *r, float v[3]) {
  v[0] = rd_f(r);
  v[1] = rd_f(r);
  v[2] = rd_f(r);
}
static int rd_n(rd_t *r) { /* band count: mostly 1..16, sometimes 0, negative, 17..70 */
  unsigned s = rd_u8(r);
  if (s < 200) return (int)(s % 16u) + 1;
  if (s < 215) return (int)(s % 70u);
  return -(int)(s % 4u);
}
static int finite3(const float v[3]) {
  return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]);
}
static int moderate(float v) {
  return isfinite(v) && fabsf(v) <= 1e15f;
}
static int moderate3(const float v[3]) {
  return moderate(v[0]) && moderate(v[1]) && moderate(v[2]);
}
static int nonzero3(const float v[3]) {
  return v[0] != 0.0f || v[1] != 0.0f || v[2] != 0.0f;
}

static void ff_fail(int id, const char *what) {
  printf("FAIL fuzz_families: %s: %s\n", fuzz_fam_names[id], what);
  fflush(stdout);
  fuzz_fam_fails[id]++;
  fuzz_basis_failures++;
  if (!fuzz_basis_soft_fail) abort();
}
#define FF_CHECK(id, cond, what) \
  do { \
    if (!(cond)) ff_fail(FF_##id, what); \
  } while (0)

/* output buffers: count floats + 4 canaries */
#define CANARY 0x7fc0deadu
static float *obuf(size_t count) {
  float *p = (float *)malloc((count + 4) * sizeof(float));
  size_t i;
  uint32_t c = CANARY;
  if (!p) abort();
  for (i = 0; i < count; ++i)
    p[i] = 0.0f;
  for (i = 0; i < 4; ++i)
    memcpy(p + count + i, &c, 4);
  return p;
}
static int canary_ok(const float *p, size_t count) {
  size_t i;
  for (i = 0; i < 4; ++i) {
    uint32_t c;
    memcpy(&c, p + count + i, 4);
    if (c != CANARY) return 0;
  }
  return 1;
}
static int all_finite(const float *p, size_t count) {
  size_t i;
  for (i = 0; i < count; ++i)
    if (!isfinite(p[i])) return 0;
  return 1;
}
static size_t nn_of(int n) {
  int c = n < 1 ? 0 : (n > SHLIGHT_MAX_BANDS ? SHLIGHT_MAX_BANDS : n);
  return (size_t)(c * c);
}
static size_t nb_of(int n) {
  return n < 1 ? 0 : (size_t)(n > SHLIGHT_MAX_BANDS ? SHLIGHT_MAX_BANDS : n);
}
/* an input array of count floats from the stream (values moderate when tame != 0) */
static float *ibuf(rd_t *r, size_t count, int tame) {
  float *p = obuf(count);
  size_t i;
  for (i = 0; i < count; ++i) {
    p[i] = rd_f(r);
    if (tame && !moderate(p[i])) p[i] = 0.25f;
  }
  return p;
}

static void fam_light(rd_t *r) {
  int n = rd_n(r);
  size_t nb = nb_of(n), nn = nn_of(n);
  float x[3], c[3], p1[3], p2[3], rad = rd_f(r), d = rd_f(r);
  float *o = obuf(nn), *oz = obuf(nb), *g = obuf(3 * nn), *zh;
  int fin;
  rd_v3(r, x);
  rd_v3(r, c);
  rd_v3(r, p1);
  rd_v3(r, p2);
  fin = finite3(x) && finite3(c) && isfinite(rad) && isfinite(d);
  CALL(zh_cap);
  shl_zh_cap(n, rad, d, oz);
  FF_CHECK(zh_cap, canary_ok(oz, nb), "canary");
  FF_CHECK(zh_cap, !fin || all_finite(oz, nb), "non-finite for finite r, d"); /* contract: finite */
  CALL(zh_cap_da);
  shl_zh_cap_derivative(n, rad, d, oz);
  FF_CHECK(zh_cap_da, canary_ok(oz, nb), "canary");
  CALL(zh_cap_printed);
  shl_zh_cap_printed(n, rad, d, oz);
  FF_CHECK(zh_cap_printed, canary_ok(oz, nb), "canary");
  zh = ibuf(r, nb, 0);
  CALL(zh_rotate);
  shl_zh_rotate(n, zh, c, o);
  FF_CHECK(zh_rotate, canary_ok(o, nn), "canary");
  FF_CHECK(zh_rotate, !all_finite(zh, nb) || all_finite(o, nn), "non-finite for finite zh");
  CALL(sphere_light);
  shl_sphere_light(n, x, c, rad, o);
  FF_CHECK(sphere_light, canary_ok(o, nn), "canary");
  FF_CHECK(sphere_light, all_finite(o, nn), "non-finite"); /* any input: zeros or finite */
  CALL(sphere_light_grad);
  shl_sphere_light_grad(n, x, c, rad, o, (float(*)[3])g);
  FF_CHECK(sphere_light_grad, canary_ok(o, nn) && canary_ok(g, 3 * nn), "canary");
  FF_CHECK(sphere_light_grad, all_finite(o, nn) && all_finite(g, 3 * nn), "non-finite");
  CALL(triangle_light);
  shl_triangle_light(n, x, c, p1, p2, o);
  FF_CHECK(triangle_light, canary_ok(o, nn), "canary");
  FF_CHECK(triangle_light, all_finite(o, nn), "non-finite");
  CALL(triangle_light_grad);
  shl_triangle_light_grad(n, x, c, p1, p2, o, (float(*)[3])g);
  FF_CHECK(triangle_light_grad, canary_ok(o, nn) && canary_ok(g, 3 * nn), "canary");
  FF_CHECK(triangle_light_grad, all_finite(o, nn) && all_finite(g, 3 * nn), "non-finite");
  {
    float om;
    CALL(triangle_solid_angle);
    om = shl_triangle_solid_angle(x, c, p1, p2);
    FF_CHECK(triangle_solid_angle, isfinite(om) && fabsf(om) <= 6.2832f, "outside [-2pi, 2pi]");
  }
  free(o);
  free(oz);
  free(g);
  free(zh);
}

static void fam_grid(rd_t *r) {
  shl_grid g;
  int n = (int)(rd_u8(r) % 6u) - 1, nl = (int)(rd_u8(r) % 5u), i, method = (int)(rd_u8(r) % 5u) - 1;
  int order = (int)(rd_u8(r) % 3u), threads = (int)(rd_u8(r) % 3u);
  size_t nv, nn;
  float *sh, *gr, *cen, *rad, *inten, p[3], f[3], cell[3], *c8, *g8, *o;
  shl_result rc;
  memset(&g, 0, sizeof g);
  g.n = n;
  g.dims[0] = (int)(rd_u8(r) % 4u);
  g.dims[1] = (int)(rd_u8(r) % 4u);
  g.dims[2] = (int)(rd_u8(r) % 3u);
  rd_v3(r, g.origin);
  rd_v3(r, g.spacing);
  for (i = 0; i < 3; ++i)
    if (rd_u8(r) & 1u) g.spacing[i] = 0.5f; /* mostly valid grids */
  if (rd_u8(r) & 1u) g.origin[0] = g.origin[1] = g.origin[2] = 0.0f;
  g.cull = (rd_u8(r) & 1u) ? 0.0f : rd_f(r);
  nv = (size_t)(g.dims[0] > 0 ? g.dims[0] : 0) * (size_t)(g.dims[1] > 0 ? g.dims[1] : 0) *
       (size_t)(g.dims[2] > 0 ? g.dims[2] : 0);
  nn = nn_of(n);
  sh = obuf(nv * nn);
  gr = obuf(3 * nv * nn);
  cen = ibuf(r, 3 * (size_t)nl, 0);
  rad = ibuf(r, (size_t)nl, 0);
  inten = ibuf(r, (size_t)nl, 1); /* moderate: a sum of 1e38-intensity lights overflows */
  CALL(grid_build);
  rc = shl_grid_build(&g, (const float(*)[3])cen, rad, inten, nl, order, threads, sh,
                      (float(*)[3])gr);
  FF_CHECK(grid_build, canary_ok(sh, nv * nn) && canary_ok(gr, 3 * nv * nn), "canary");
  /* contract: lights with non-finite data add nothing, so a built grid is finite */
  FF_CHECK(grid_build, rc != SHLIGHT_OK || (all_finite(sh, nv * nn) && all_finite(gr, 3 * nv * nn)),
           "non-finite grid");
  rd_v3(r, p);
  o = obuf(nn);
  CALL(grid_sample);
  {
    shl_result rs = shl_grid_sample(&g, sh, (const float(*)[3])gr, p, method, o);
    FF_CHECK(grid_sample, canary_ok(o, nn), "canary");
    /* finite from a finite grid: trilinear always (a convex combination); Taylor / Hermite
       add spacing x gradient terms, finite while those fit (spacing <= 1e3, |grad| <= 1e30) */
    int tame = method == SHLIGHT_GRID_TRILINEAR;
    if (!tame) {
      size_t q;
      tame =
          fabsf(g.spacing[0]) <= 1e3f && fabsf(g.spacing[1]) <= 1e3f && fabsf(g.spacing[2]) <= 1e3f;
      for (q = 0; tame && q < 3 * nv * nn; ++q)
        tame = fabsf(gr[q]) <= 1e30f;
    }
    FF_CHECK(grid_sample, rc != SHLIGHT_OK || rs != SHLIGHT_OK || !tame || all_finite(o, nn),
             "non-finite from a finite grid");
  }
  free(o);
  /* the kernels on gathered corners: f in [0, 1] and a finite cell give finite output */
  {
    int kn = rd_n(r);
    size_t knn = nn_of(kn);
    c8 = ibuf(r, 8 * knn, 1);
    g8 = ibuf(r, 24 * knn, 1);
    rd_v3(r, f);
    rd_v3(r, cell);
    for (i = 0; i < 3; ++i) {
      if (!(f[i] >= 0.0f && f[i] <= 1.0f)) f[i] = 0.5f;
      if (!moderate(cell[i])) cell[i] = 1.0f;
    }
    o = obuf(knn);
    CALL(grid_trilinear);
    shl_grid_trilinear(kn, c8, f, o);
    FF_CHECK(grid_trilinear, canary_ok(o, knn) && all_finite(o, knn), "canary / non-finite");
    CALL(grid_taylor);
    shl_grid_taylor(kn, c8, (const float(*)[3])g8, f, cell, o);
    FF_CHECK(grid_taylor, canary_ok(o, knn) && all_finite(o, knn), "canary / non-finite");
    CALL(grid_hermite);
    shl_grid_hermite(kn, c8, (const float(*)[3])g8, f, cell, o);
    FF_CHECK(grid_hermite, canary_ok(o, knn) && all_finite(o, knn), "canary / non-finite");
    free(o);
    free(c8);
    free(g8);
  }
  free(sh);
  free(gr);
  free(cen);
  free(rad);
  free(inten);
}

static float tame_exp(float e) {
  return (isfinite(e) && fabsf(e) <= 1e9f) ? e : 10.0f;
}

static void fam_edge(rd_t *r) {
  float v[8][3], nrm[3], view[3], a1[3], a2[3], e = tame_exp(rd_f(r)), al = rd_f(r), res;
  int nv = (int)(rd_u8(r) % 9u), i, method = (int)(rd_u8(r) % 7u), sub = (int)(rd_u8(r) % 65u);
  for (i = 0; i < 8; ++i)
    rd_v3(r, v[i]);
  rd_v3(r, nrm);
  rd_v3(r, view);
  rd_v3(r, a1);
  rd_v3(r, a2);
  /* the area functions: run (ASan / UBSan), values recorded only (other helpers' contracts) */
  CALL(edge_integral);
  res = shl_edge_integral(rd_f(r), rd_f(r), rd_f(r), e, method);
  CALL(polygon_moment);
  res = shl_polygon_moment((const float(*)[3])v, nv, nrm, e, method);
  CALL(polygon_phong);
  res = shl_polygon_phong((const float(*)[3])v, nv, nrm, view, e, method);
  CALL(polygon_phong2);
  /* phong2 with a fit method (1..3) or FAST (6) is not fuzzed: a product lobe whose SG
     sharpness is just above ln 2 gets np ~ 1e16 and those methods' float-to-int rounding of
     the exponent overflows (UB, an open finding of the area functions, docs/contracts.md) */
  res = shl_polygon_phong_double_axis(
      (const float(*)[3])v, nv, nrm, view, e,
      (method >= 1 && method <= 3) || method == 6 ? SHLIGHT_EDGE_AUTO : method);
  CALL(ellipse_phong);
  res = shl_ellipse_phong(v[0], a1, a2, nrm, view, e, method);
  CALL(sphere_phong);
  res = shl_sphere_phong(v[0], al, nrm, view, e, method);
  CALL(polygon_ggx_ndf);
  res = shl_polygon_ggx_ndf((const float(*)[3])v, nv, nrm, al);
  CALL(polygon_ggx);
  res = shl_polygon_ggx((const float(*)[3])v, nv, nrm, view, al);
  CALL(polygon_beckmann_taylor);
  res = shl_polygon_beckmann((const float(*)[3])v, nv, nrm, view, al);
  CALL(polygon_beckmann_ndf);
  res = shl_polygon_beckmann_ndf((const float(*)[3])v, nv, nrm, al);
  CALL(polygon_blinn_phong);
  res = shl_polygon_blinn_phong((const float(*)[3])v, nv, nrm, view, e, sub);
  CALL(polygon_beckmann);
  res = shl_polygon_beckmann_subedges((const float(*)[3])v, nv, nrm, view, al, sub);
  (void)res;
  /* lobe / SG helpers (this round's contracts): finite for finite input, mu in [0, 1] */
  {
    float n1 = rd_f(r), n2 = rd_f(r), rp[3] = {0, 0, 0}, np = 0.0f, mu, l;
    CALL(lobe_to_sg);
    l = shl_lobe_to_sg(n1);
    FF_CHECK(lobe_to_sg, !isfinite(n1) || (isfinite(l) && l >= 0.0f), "non-finite / negative");
    CALL(sg_to_lobe);
    l = shl_sg_to_lobe(n1);
    FF_CHECK(sg_to_lobe, !isfinite(n1) || (isfinite(l) && l >= 0.0f), "non-finite / negative");
    CALL(lobe_product);
    mu = shl_lobe_product(a1, n1, a2, n2, rp, &np);
    FF_CHECK(lobe_product, mu >= 0.0f && mu <= 1.0f, "mu outside [0, 1]");
    FF_CHECK(lobe_product,
             !(isfinite(n1) && isfinite(n2)) || (isfinite(np) && finite3(rp)) || !finite3(a1),
             "non-finite np / rp for finite input");
  }
}

static void fam_brdf(rd_t *r) {
  int n = rd_n(r), kind = (int)(rd_u8(r) % 4u);
  size_t nb = nb_of(n), nn = nn_of(n);
  float e = rd_f(r), w[3], u[3], z = rd_f(r), res;
  float *o = obuf(nb), *sh = ibuf(r, nn, 1), *zh = ibuf(r, nb, 1), *zh2 = ibuf(r, nb, 1),
        *io = ibuf(r, nn, 1), zh3[3];
  rd_v3(r, w);
  rd_v3(r, u);
  /* ZH of the lobes: finite for any exponent / alpha (documented clamps) */
  CALL(zh_phong);
  shl_zh_phong(n, e, o);
  FF_CHECK(zh_phong, canary_ok(o, nb) && all_finite(o, nb), "canary / non-finite");
  CALL(zh_cosine_power);
  shl_zh_cosine_power(n, e, o);
  FF_CHECK(zh_cosine_power, canary_ok(o, nb) && all_finite(o, nb), "canary / non-finite");
  CALL(zh_lambert);
  shl_zh_lambert(n, o);
  FF_CHECK(zh_lambert, canary_ok(o, nb) && all_finite(o, nb), "canary / non-finite");
  CALL(zh_blinn_phong);
  shl_zh_blinn_phong(n, e, o);
  FF_CHECK(zh_blinn_phong, canary_ok(o, nb) && all_finite(o, nb), "canary / non-finite");
  CALL(zh_ggx);
  shl_zh_ggx(n, e, o);
  FF_CHECK(zh_ggx, canary_ok(o, nb) && all_finite(o, nb), "canary / non-finite");
  CALL(zh_beckmann);
  shl_zh_beckmann(n, e, o);
  FF_CHECK(zh_beckmann, canary_ok(o, nb) && all_finite(o, nb), "canary / non-finite");
  /* contractions of moderate (|v| <= 1e15) data: finite */
  CALL(sh_dot);
  res = shl_sh_dot(n, sh, io);
  FF_CHECK(sh_dot, isfinite(res), "non-finite");
  CALL(sh_conv_zh);
  res = shl_sh_conv_zh(n, sh, zh, w);
  FF_CHECK(sh_conv_zh, isfinite(res), "non-finite");
  CALL(zh_dot_zh);
  res = shl_zh_dot_zh(n, zh, u, zh2, w);
  FF_CHECK(zh_dot_zh, isfinite(res), "non-finite");
  zh3[0] = zh[0 % (nb ? nb : 1)];
  zh3[1] = 1.0f;
  zh3[2] = -0.5f;
  CALL(zh_irradiance3);
  res = shl_zh_irradiance_quadratic(zh3, isfinite(z) ? z : 0.5f);
  FF_CHECK(zh_irradiance3, isfinite(res) || !isfinite(zh3[0]), "non-finite");
  CALL(zh_irradiance);
  res = shl_zh_irradiance(n, zh, isfinite(z) ? z : 0.5f);
  FF_CHECK(zh_irradiance, isfinite(res), "non-finite");
  if (nn >= 9) { /* it reads bands 0..2 */
    float *mm = obuf(16);
    CALL(sh_irradiance_matrix);
    shl_sh_irradiance_matrix(sh, mm);
    FF_CHECK(sh_irradiance_matrix, canary_ok(mm, 16) && all_finite(mm, 16), "canary / non-finite");
    free(mm);
  }
  CALL(zh_window);
  shl_zh_window(n, kind, e, zh2);
  FF_CHECK(zh_window, canary_ok(zh2, nb) && all_finite(zh2, nb), "canary / non-finite");
  CALL(zh_bands_for);
  {
    int m = shl_zh_bands_for(n, zh, z);
    FF_CHECK(zh_bands_for, n < 1 || (m >= 1 && m <= (int)nb), "outside [1, n]");
  }
  CALL(sh_rotate_z);
  shl_sh_rotate_z(n, w[0], w[1], io);
  FF_CHECK(sh_rotate_z, canary_ok(io, nn), "canary");
  {
    shl_brdf_params b;
    b.model = (int)(rd_u8(r) % 6u);
    b.kd = rd_f(r);
    b.ks = rd_f(r);
    b.exponent = rd_f(r);
    b.alpha_x = rd_f(r);
    b.alpha_y = rd_f(r);
    b.f0 = rd_f(r);
    CALL(brdf_eval);
    res = shl_brdf_eval(&b, w, u);
    (void)res; /* brdftab helper's contract: run only */
  }
  free(o);
  free(sh);
  free(zh);
  free(zh2);
  free(io);
}

static void fam_hvl(rd_t *r) {
  int n = rd_n(r), ex = (int)(rd_u8(r) & 1u), cnt = (int)(rd_u8(r) % 12u) - 2;
  size_t nb = nb_of(n), nn = nn_of(n);
  float x[3], nx[3], y[3], ny[3], rad = rd_f(r), d = rd_f(r), pw = rd_f(r), res, pn[8][3], dn[8];
  float *fe = ibuf(r, nn, 1), *fz = ibuf(r, nb, 1);
  int i, fin;
  rd_v3(r, x);
  rd_v3(r, nx);
  rd_v3(r, y);
  rd_v3(r, ny);
  for (i = 0; i < 8; ++i) {
    rd_v3(r, pn[i]);
    dn[i] = rd_f(r);
  }
  fin = finite3(x) && finite3(y) && finite3(nx) && finite3(ny) && isfinite(rad) && isfinite(d);
  CALL(hvl_horizon);
  res = shl_hvl_horizon(nx, y, rad, d);
  FF_CHECK(hvl_horizon, !fin || (res >= 0.0f && res <= 1.0f), "H outside [0, 1]");
  CALL(hvl_horizon_smoothstep);
  res = shl_hvl_horizon_smoothstep(nx, y, rad, d);
  FF_CHECK(hvl_horizon_smoothstep, !fin || (res >= 0.0f && res <= 1.0f), "H outside [0, 1]");
  CALL(hvl_geometric);
  res = shl_hvl_geometric(x, nx, y, ny, rad, ex);
  FF_CHECK(hvl_geometric, isfinite(res) && res >= 0.0f, "non-finite or negative");
  CALL(hvl_emission);
  res = shl_hvl_emission(n, fe, nx);
  FF_CHECK(hvl_emission, isfinite(res), "non-finite");
  CALL(hvl_radiance);
  res = shl_hvl_radiance(n, fe, moderate(pw) ? pw : 1.0f, x, nx, y, ny, moderate(rad) ? rad : 1.0f,
                         ex);
  /* finite where the exact value fits: G <= 1 / (pi r^2) with r >= 1e-6 here */
  FF_CHECK(hvl_radiance, !moderate3(x) || !moderate3(y) || !(rad >= 1e-6f) || isfinite(res),
           "non-finite");
  CALL(hvl_contribution);
  res = shl_hvl_contribution(n, moderate(pw) ? pw : 1.0f, fe, x, y, moderate(rad) ? rad : 1.0f);
  FF_CHECK(hvl_contribution, !moderate3(x) || !moderate3(y) || isfinite(res), "non-finite");
  CALL(hvl_contribution_zh);
  res = shl_hvl_contribution_zh(n, moderate(pw) ? pw : 1.0f, fz, ny, x, y,
                                moderate(rad) ? rad : 1.0f);
  FF_CHECK(hvl_contribution_zh, !moderate3(x) || !moderate3(y) || isfinite(res), "non-finite");
  CALL(hvl_radius_neighbours);
  res = shl_hvl_radius_neighbours(cnt, x, d, (const float(*)[3])pn, dn, pw);
  FF_CHECK(hvl_radius_neighbours, isfinite(res) && res >= 0.0f, "non-finite or negative");
  CALL(hvl_radius_fov);
  res = shl_hvl_radius_fov(d, pw, cnt);
  FF_CHECK(hvl_radius_fov, !isfinite(d) || !isfinite(pw) || (isfinite(res) && res >= 0.0f),
           "non-finite for finite input");
  CALL(hvl_radius_fov_tan);
  res = shl_hvl_radius_fov_tan(d, pw, cnt);
  FF_CHECK(hvl_radius_fov_tan, !isfinite(d) || !isfinite(pw) || (isfinite(res) && res >= 0.0f),
           "non-finite for finite input");
  free(fe);
  free(fz);
}

static void fam_ssf(rd_t *r) {
  int n = rd_n(r), range[2] = {-7, -7}, k, fin;
  size_t nn = nn_of(n);
  float x[3], nx[3], y[3], ny[3], ns[3], flux = rd_f(r), dmin = rd_f(r), res;
  float *io = ibuf(r, nn, 1);
  rd_v3(r, x);
  rd_v3(r, nx);
  rd_v3(r, y);
  rd_v3(r, ny);
  rd_v3(r, ns);
  /* finite where e = flux cos / (pi max(d^2, dmin^2)) fits: |flux| <= 1e6 and max(d, dmin)
     >= 1e-6 (else e exceeds FLT_MAX and the sum overflows, IEEE inf: docs/contracts.md) */
  {
    double dx = (double)y[0] - x[0], dy = (double)y[1] - x[1], dz = (double)y[2] - x[2];
    double dd = sqrt(dx * dx + dy * dy + dz * dz);
    fin = fabsf(flux) <= 1e6f && (dd >= 1e-6 || dmin >= 1e-6f);
  }
  CALL(ssf_vpl_sh);
  shl_ssf_vpl_sh(n, x, nx, y, ny, flux, dmin, io);
  FF_CHECK(ssf_vpl_sh, canary_ok(io, nn), "canary");
  FF_CHECK(ssf_vpl_sh, !fin || all_finite(io, nn), "non-finite");
  CALL(ssf_vpl_irradiance);
  res = shl_ssf_vpl_irradiance(x, nx, ns, y, ny, flux, dmin);
  FF_CHECK(ssf_vpl_irradiance, res >= 0.0f && (!fin || isfinite(res)),
           "NaN, negative, or non-finite where e fits a float");
  CALL(ssf_interleave);
  k = shl_ssf_interleave((int)(rd_u8(r) | (rd_u8(r) << 8)) - 1000, (int)rd_u8(r) - 10,
                         (int)(rd_u8(r) % 20u) - 2, (int)(rd_u8(r) % 20u) - 2,
                         (int)(rd_u8(r) | (rd_u8(r) << 8)) - 100, range);
  FF_CHECK(ssf_interleave, k >= 0, "negative count");
  CALL(ssf_weight);
  res = shl_ssf_weight(x, nx, y, ny, rd_f(r), rd_f(r));
  FF_CHECK(ssf_weight, isfinite(res) && res >= 0.0f && res <= 1.0f, "weight outside [0, 1]");
  CALL(ssf_irradiance);
  res = shl_ssf_irradiance(n, io, ns);
  FF_CHECK(ssf_irradiance, !fin || isfinite(res), "non-finite");
  (void)nonzero3;
  free(io);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  rd_t r;
  int fam;
  r.p = data;
  r.n = size;
  r.i = 0;
#ifdef FUZZ_ONLY
  fam = FUZZ_ONLY;
#else
  fam = (int)(rd_u8(&r) % 6u);
#endif
  switch (fam) {
  case 0:
    fam_light(&r);
    break;
  case 1:
    fam_grid(&r);
    break;
  case 2:
    fam_edge(&r);
    break;
  case 3:
    fam_brdf(&r);
    break;
  case 4:
    fam_hvl(&r);
    break;
  default:
    fam_ssf(&r);
    break;
  }
  return 0;
}
