/* shlight.h - v0.2.0 - analytic spherical-harmonics lighting - MIT or public domain (see end)

   One C99 header (C++ clean, no dependency but libm) for the math of spherical-harmonics (SH)
   lighting, with GLSL twins in shlight_glsl/ that run the same function bodies. Every function
   documents its domain, what bad input gives, its measured accuracy and its cost; no function
   allocates or keeps state (reentrant, thread safe).

   USAGE
     #define SHLIGHT_IMPLEMENTATION    in exactly ONE C or C++ file, before the #include
     #include "shlight.h"              in every file that calls it (the kernels are inline;
                                       large band counts and the CPU-only functions are
                                       compiled in the implementation file)
     cc -std=c99 ... -lm               (and -pthread for the 2-thread grid build on old glibc)

   THE IMPORTANT PARTS: shading a point x with normal nrm
     float light[16], lobe[4], grad[16][3];
     shl_sphere_light(4, x, centre, radius, light);   1. a light's SH seen from x (or
                                                         shl_sphere_light_grad for the gradient)
     shl_zh_cosine_power(4, 1.0f, lobe);              2. a lobe's ZH (clamped cosine; Phong,
                                                         GGX, Beckmann: shl_zh_phong, _ggx, ...)
     e = shl_sh_conv_zh(4, light, lobe, nrm);         3. convolution: irradiance at nrm
     e = shl_zh_dot_zh(4, cap, axis, lobe, nrm);      3'. the same, O(n), for one cap's ZH
     L = albedo / pi * e;                             4. shade
   Area lights take no SH at all:
     shl_polygon_moment(quad, 4, nrm, 1.0f, SHLIGHT_EDGE_AUTO) / pi   Lambert from a quad
     shl_polygon_ggx(quad, 4, nrm, view, alpha)                      GGX specular, no table
   Other calls most users need: shl_sh_eval (basis), shl_sh_eval_grad (basis + gradient),
   shl_sh_eval_batch (many directions), shl_sh_rotate (rotate SH), shl_grid_build and
   shl_grid_sample (light grids), shl_brdf_table_build / _lookup (any BRDF as SH tables).

   OPTIONS (define before including; each is #ifndef-guarded)
     SHLIGHT_MAX_BANDS       largest band count accepted (default and maximum 64)
     SHLIGHT_NO_SIMD         no SSE2 / AVX2 / AVX-512 intrinsics (the portable kernels only)
     SHLIGHT_NO_THREADS      shl_grid_build runs on the calling thread only (no pthreads)
     SHLIGHT_STATIC          the implementation's functions become static (one file only)
     SHLIGHT_REFERENCE_FORMS the published forms kept for comparison (tests, benchmarks):
                             shl_zh_cap_printed, shl_sh_eval_grad_spherical,
                             shl_sh_grad_from_spherical, shl_hvl_horizon_smoothstep

   CONTENTS (grep for the anchors)
     >>options    the option macros
     >>api        EVERY public type, constant and function with its contract: read this part
     ------------ end of the API; the implementation follows ------------
     >>numerics   domains and degenerate inputs in general
     >>prelude    math shims shared with shlight_glsl/shl_prelude.glsl
     >>basis      SH basis: shl_sh_eval, shl_sh_eval_accurate, shl_sh_eval_batch
     >>gradient   Cartesian gradient: shl_sh_eval_grad
     >>zonal      ZH of a uniform spherical cap, its derivative, ZH -> SH
     >>light      sphere and triangle lights (with gradients), triangle solid angle
     >>grid       light grids: build and sampling (trilinear, Taylor, Hermite)
     >>edge       area lights without tables: edge integrals, polygon moments, Phong, GGX,
                  Beckmann, Blinn-Phong polygon / disc / sphere lights
     >>brdf       ZH of BRDF lobes, convolution, irradiance, windowing, band selection
     >>hvl        Harmonics Virtual Lights
     >>brdftab    BRDF SH tables: lookup; CPU: analytic BRDFs, build, files, MERL loader
     >>ssf        screen-space SH filter for virtual point lights
     >>rotate     SH rotation

   CONVENTIONS
     Real SH with the Condon-Shortley phase (Sloan / D3DX / DirectXMath):
       Y_1^-1 = -K y, Y_1^0 = K z, Y_1^1 = -K x, K = sqrt(3 / 4pi); orthonormal on the sphere.
     Index i = l * (l + 1) + m; m < 0 are the sin(|m| phi) functions.
     n = number of BANDS, always: orders l = 0 .. n-1, n * n coefficients, a ZH has n floats.
     Directions right-handed, theta from +z. Gradients are Cartesian, 3 floats per
     coefficient: out_grad[i][k] = d coef_i / d x_k. nrm: the shading normal; exponent: a
     Phong exponent; alpha: GGX / Beckmann roughness (perceptual roughness squared). Outputs
     come last and are named out_* (io_*: read and written). Kernels never fail: bad input
     gives the documented value. The CPU functions that can fail return shl_result.
     Derivations: docs/math.md; measured accuracy and speed: docs/accuracy.md, docs/speed.md.
*/
#ifndef SHLIGHT_H
#define SHLIGHT_H

/* >>options ---------------------------------------------------------------------------------
   SHLIGHT_MAX_BANDS       largest band count the functions accept (default 64; tables hold 64)
   SHLIGHT_UNROLLED_BANDS  straight-line generated code for n <= this (16); run-time loop above
   SHLIGHT_NO_SIMD         batch evaluation without SSE2 / AVX2 / AVX-512 intrinsics
   SHLIGHT_BATCH_COMPACT   default 1: shl_sh_eval_batch runs 7..16 bands as one loop; 0 unrolls
                           it per band count (the batch at 7..16 bands 10-20 % faster when its
                           output stays in L1, at 3.5x the implementation's compile time, 7.7
                           against 2.2 s, and +200 KB of .text, gcc 12 -O2)
   SHLIGHT_STATIC          the CPU-only functions become static (private to one file)
*/
#ifndef SHLIGHT_MAX_BANDS
#define SHLIGHT_MAX_BANDS 64
#endif
#if SHLIGHT_MAX_BANDS < 1 || SHLIGHT_MAX_BANDS > 64
#error "SHLIGHT_MAX_BANDS must be in [1, 64]"
#endif
#define SHLIGHT_UNROLLED_BANDS 16
#ifndef SHLIGHT_BATCH_COMPACT
#define SHLIGHT_BATCH_COMPACT 1
#endif
#define SHLIGHT_MAX_COEFFS (SHLIGHT_MAX_BANDS * SHLIGHT_MAX_BANDS)
/* Scratch of the kernels that evaluate Y once and contract it (shl_sh_conv_zh, the HVL
   emission, shl_ssf_vpl_sh): n^2 <= SHLI_YBUF_COEFFS in a stack buffer (8 KB at most), more
   bands (n > 45, C only) through shli_sh_ystream without a buffer: every public function stays
   under 16 KB of stack. */
#if SHLIGHT_MAX_COEFFS > 2048
#define SHLI_YBUF_COEFFS 2048
#else
#define SHLI_YBUF_COEFFS SHLIGHT_MAX_COEFFS
#endif

#ifdef SHLIGHT_STATIC
#if defined(__GNUC__) || defined(__clang__)
#define SHLIGHT_API static __attribute__((unused)) /* no warning for the functions not called */
#else
#define SHLIGHT_API static
#endif
#elif defined(__cplusplus)
#define SHLIGHT_API extern "C"
#else
#define SHLIGHT_API extern
#endif

/* SHLIGHT_INLINE marks the kernels that have GLSL twins; SHLIGHT_CPU_INLINE the inline helpers
   that exist in C only (the table-driven loops for more than 16 bands). */
#if defined(__cplusplus) || (defined(__STDC_VERSION__) && __STDC_VERSION__ >= 199901L)
#define SHLIGHT_INLINE static inline
#elif defined(__GNUC__) || defined(_MSC_VER)
#define SHLIGHT_INLINE static __inline
#else
#define SHLIGHT_INLINE static
#endif
#define SHLIGHT_CPU_INLINE SHLIGHT_INLINE

/* >>api -------------------------------------------------------------------------------------
   Every public type, constant and function, grouped by module, each with its contract. */
#include <stddef.h>

/* ---- prelude ------------------------------------------------------------------------------- */
/* edge-integral methods (shl_edge_method, shl_polygon_moment) and polygon limits. GLSL has no
   enums: there the selectors are #defines of the same values and shl_edge_method is int. A
   value outside the enumerators is accepted and documented at each function (AUTO, or EXACT
   for shl_edge_integral). */
typedef enum shl_edge_method {
  SHLIGHT_EDGE_EXACT = 0,
  SHLIGHT_EDGE_LORENTZ = 1,
  SHLIGHT_EDGE_LORENTZ_PEARSON = 2,
  SHLIGHT_EDGE_ELLIPSOID = 3,
  SHLIGHT_EDGE_AUTO = 4,
  SHLIGHT_EDGE_QUADRATURE = 5,
  SHLIGHT_EDGE_FAST = 6,
  SHLIGHT_EDGE_INT_MIN_ = -2147483647 - 1 /* not a method: makes the type a signed int that
                                             holds any int (no sign conversion in C++) */
} shl_edge_method;

#define SHLIGHT_POLYGON_MAX 8 /* vertices of a polygon light in one piece (GLSL: at most) */

/* ---- basis --------------------------------------------------------------------------------- */
/* shl_sh_eval: the real SH basis Y_i(d), i < n * n, of n bands at the direction d.
   d: a unit vector to float precision (| |d|^2 - 1 | <= 1e-6, which every float-normalised
   vector meets) is evaluated as given; any other finite non-zero d is normalised first (in
   double, scaled by its largest component: denormal and huge d work; about 10 ns more); a
   zero, NaN or infinite d gives Y(0, 0, 1). n: bands, 1..SHLIGHT_MAX_BANDS; n > max is taken
   as max, n < 1 writes nothing (debug and release alike). out_y: n * n floats.
   Accuracy: max abs error 3e-7 (n <= 4), 2e-6 (n <= 16), 1e-5 (n <= 32) against binary128.
   Cost: 1 ns (n = 2) to 32 ns (n = 16) on Zen 4, see docs/speed.md; in C, n > 6 runs out of
   line in the implementation (define SHLIGHT_IMPLEMENTATION in one file). */
SHLIGHT_INLINE void shl_sh_eval(int n, const float d[3], float *out_y);

/* ---- gradient ------------------------------------------------------------------------------ */
/* shl_sh_eval_grad: Y_i(d / |d|) and its gradient with respect to d, out_grad[i][k] =
   dY_i / dd_k, for any finite d != 0 (scaled by its largest component first, so denormal and
   huge inputs work). Zero, NaN or infinite d: the values at (0,0,1) and a zero gradient.
   Finite at the poles. The gradient scales like l / |d|: below |d| ~ 1e-38 the entries whose
   exact value exceeds FLT_MAX are +-inf (IEEE overflow, correct sign); every entry that fits in
   a float is within the stated accuracy. n as shl_sh_eval. out_y: n * n floats, out_grad:
   n * n float[3]. Accuracy: values as shl_sh_eval, gradient 1.3e-6 of max |grad| at n = 16.
   Cost: about 4x shl_sh_eval (docs/speed.md). */
SHLIGHT_INLINE void shl_sh_eval_grad(int n, const float d[3], float *out_y, float (*out_grad)[3]);

#ifdef SHLIGHT_REFERENCE_FORMS
/* shl_sh_eval_grad_spherical: the paper's form ([GRAD] sections 3-4, corrections E1-E3 of
   docs/math.md fixed): Y_i(d / |d|), dY_i / dtheta and dY_i / dphi, by Sloan's recurrence for X
   and the normalised T recurrence Z_l = alpha (cos Z_{l-1} - sin X_{l-1}) - beta Z_{l-2}.
   Any finite d != 0; zero / NaN / Inf d: as (0,0,1). At an exact pole phi is taken as 0.
   Kept as the comparison point of shl_sh_eval_grad in tests and bench. */
SHLIGHT_INLINE void shl_sh_eval_grad_spherical(int n, const float d[3], float *out_y,
                                               float *out_dtheta, float *out_dphi);
#endif

#ifdef SHLIGHT_REFERENCE_FORMS
/* shl_sh_grad_from_spherical: Cartesian gradient from the spherical partials ([GRAD]
   eq. 23): grad Y = dY/dtheta grad(theta) + dY/dphi grad(phi). Singular at the poles; at an
   exact pole (x = y = 0) or for d = 0 every entry is 0. Comparison point only: use
   shl_sh_eval_grad. */
SHLIGHT_INLINE void shl_sh_grad_from_spherical(int n, const float d[3], const float *dtheta,
                                               const float *dphi, float (*out_grad)[3]);
#endif

/* ---- zonal --------------------------------------------------------------------------------- */
/* shl_zh_cap: ZH coefficients L_l, l < n, of the unit-radiance cap that a sphere of radius r
   subtends at distance d (its centre on +z): out_zh[l] = int_cap Y_l^0. Stable s^2 P'_l form
   (see >>zonal), any s from 1e-30 to 1: relative error at the float rounding floor in C.
   Small caps: L_l -> pi s^2 K_l (a point light). r <= 0, NaN r or d, infinite d: zeros;
   d <= r: the hemisphere. out_zh: n floats. Cost: O(n), one sqrt and 2 divisions per band. */
SHLIGHT_INLINE void shl_zh_cap(int n, float r, float d, float *out_zh);

/* shl_zh_cap_derivative: derivative of shl_zh_cap with respect to the half-angle a,
   out_dzh[l] = dL_l / da = sqrt(pi (2l+1)) P_l(alpha) s (docs/math.md section 2: the paper's eq. 16
   is O'_l = -(2l+1) P_l, no division by alpha^2 - 1). Chain with da/dd = -s / (d alpha), or use
   shl_sphere_light_grad, which does it for the full SH. Same domain as shl_zh_cap; d <= r: the
   value at a = pi/2 (s = 1, alpha = 0). out_dzh: n floats. Cost: O(n), one sqrt per band. */
SHLIGHT_INLINE void shl_zh_cap_derivative(int n, float r, float d, float *out_dzh);

#ifdef SHLIGHT_REFERENCE_FORMS
/* shl_zh_cap_printed: the printed form of [GRAD] eq. 9 / [HVL] eq. 14, as a shader would
   write it, all in float: alpha = sqrt(1 - s^2) (= cos(asin(s))), L_0 = sqrt(pi)(1 - alpha),
   L_l = sqrt(pi / (2l+1)) (P_{l-1}(alpha) - P_{l+1}(alpha)). Comparison point for tests and
   bench only (correction E4 (docs/math.md section 12)): relative error 1.4e-4 at s = 1e-2, 4.6e-2
   at s = 1e-3, and every L_l is 0 for s < 2.4e-4. Use shl_zh_cap. Same domain and degenerate
   results as shl_zh_cap. out_zh: n floats. Cost: O(n). */
SHLIGHT_INLINE void shl_zh_cap_printed(int n, float r, float d, float *out_zh);
#endif

/* shl_zh_rotate: SH of a circularly symmetric function with ZH coefficients zh about the axis
   dir ([GRAD] eq. 11): out_sh[l (l+1) + m] = sqrt(4 pi / (2l+1)) Y_l^m(dir) zh[l]. dir: any
   finite non-zero vector (normalised in shli_real); zero, NaN or infinite dir: the axis +z.
   zh: n floats, any finite values: |out_sh[l (l+1) + m]| <= |zh[l]| (Unsold's bound), so the
   output is finite for finite zh up to FLT_MAX (no intermediate overflow; a value that float
   rounding carries past FLT_MAX saturates to +-FLT_MAX). Not finite input: a NaN zh[l] gives
   NaN in band l, an infinite one +-FLT_MAX or NaN (where Y = 0) in band l only. out_sh: n * n
   floats. Cost: one shl_sh_eval plus n sqrt and n * n mul (two in a band with |zh| >= 1e30). */
SHLIGHT_INLINE void shl_zh_rotate(int n, const float *zh, const float dir[3], float *out_sh);

/* shl_sh_rotate: out_sh (n * n floats) = the SH of the function sh (n * n floats) rotated by
   the rotation matrix R (row-major, R[3 i + j] = R_ij): g(w) = f(R^T w), so sh = Y(d) gives
   out_sh = Y(R d). n: bands, 1..SHLIGHT_MAX_BANDS (64 in C; GLSL: written for n <= 16, see
   accuracy); n < 1 writes nothing, n > max asserts in debug and is clamped in release.
   Method: R = Rz(alpha) Ry(beta) Rz(gamma) (zyz Euler angles, found without inverse
   trigonometry: beta from R's third column, alpha from its first two entries, gamma from the
   second row of Rz(-alpha) R); the z rotations act on each (m, -m) pair; the y rotation is the
   real-basis form of Wigner's d^l_{m'm}(beta), each entry carried up the bands by the
   three-term recurrence in l of its Jacobi polynomial (start at l = max(|m|, |m'|) from the
   closed form sqrt(C(2q, q+p)) cos(beta/2)^a sin(beta/2)^b), one row m' at a time, so the
   work space is O(n) and no matrix of a band is ever stored.
   R must be a rotation (orthonormal, det +1; float rounding of one is fine: the kernel uses
   the exact rotation with R's third column, R_00, R_01, R_10, R_11 as above, within 1e-7 of a
   float-rounded R); any other finite matrix gives the rotation that decomposition yields (an
   all-zero R: the identity); NaN in R gives NaN out. sh and out_sh must not overlap.
   Accuracy (C, double inside; against a long-double re-projection by Gauss quadrature,
   tests/test_rotate.c): per band, |error| / |input band| <= 4.3e-8 for every n = 1..64 and
   for beta = 0, 1e-6, pi / 2, pi - 1e-6, pi (the float rounding of the output); band energy
   kept to 1e-7. GLSL (float inside): within 1.8e-6 of C per band at n = 16 (llvmpipe).
   Cost: about n^3 / 3 steps of the two recurrences (one sqrt and one division each) and
   n^3 / 3 of the row dot products: 0.6 us at n = 6, 8.7 us at n = 16, 0.47 ms at n = 64 (gcc
   -O3 -march=native; docs/rotation.md has the table; DirectXMath's XMSHRotate, n <= 6, is
   faster at small n). Stack: about 7 KB at SHLIGHT_MAX_BANDS = 64. */
SHLIGHT_INLINE void shl_sh_rotate(int n, const float R[9], const float *sh, float *out_sh);

/* ---- light --------------------------------------------------------------------------------- */
/* shl_sphere_light: SH of the unit-radiance sphere light (centre c, radius r) seen from x:
   out_sh[l (l+1) + m] = 2 pi s^2 q_l Y_l^m(w) (see >>light). Accuracy: the cap factors in
   shli_real by the stable s^2 P'_l form for every s from 1e-30 to 1 (float rounding floor in
   C); Y at the float-rounded axis. Degenerate inputs (see >>light): r <= 0 / NaN, NaN or
   infinite positions: zeros; x on or inside the sphere: the hemisphere about c - x (its
   value at the surface); x == c: the hemisphere about +z. out_sh: n * n floats. Cost: one
   shl_sh_eval, n * n mul (AVX-512, 3 <= n <= 16: one permute and one multiply per 16
   coefficients), the O(n) double recurrence, 2 sqrt and 2 divisions; 11 / 36 / 77 ns at
   n = 2 / 8 / 16 (bench/out/light.md, Zen 4). */
SHLIGHT_INLINE void shl_sphere_light(int n, const float x[3], const float c[3], float r,
                                     float *out_sh);

/* shl_sphere_light_grad: shl_sphere_light and its gradient with respect to the shading point
   x, out_grad[i][k] = d out_sh[i] / d x_k: the rotational term through the pole-free
   Cartesian gradient of Y (finite for a probe exactly below or above the light) plus the
   radial term 2 pi s^2 P_l(alpha) / (d alpha) Y w (docs/math.md section 3). Singular only as
   d -> r+ (1 / alpha: exact, large, finite); on or inside the sphere the radial term is 0
   (the hemisphere extension is constant along rays from c); x == c, r <= 0 / NaN, NaN or
   infinite positions: zero gradient (values as shl_sphere_light). out_sh: n * n floats,
   out_grad: n * n float[3]. Cost: the basis values at the unit axis, the O(n) recurrence with
   4 weights per band, and the basis gradient pass with those weights folded in (AVX-512,
   n <= 16; otherwise the scalar gradient and 7 flops per coefficient): 2.4 / 2.5 / 2.7 times
   shl_sphere_light at n = 2 / 8 / 16 (1.95 at n = 3), 8.3 / 9.9 at n = 32 / 64 (the scalar
   gradient loop; bench/out/light.md, Zen 4). */
SHLIGHT_INLINE void shl_sphere_light_grad(int n, const float x[3], const float c[3], float r,
                                          float *out_sh, float (*out_grad)[3]);

/* shl_triangle_light: SH of the unit-radiance two-sided triangle light (p0, p1, p2) seen
   from x, approximated by the paper's sphere ([GRAD] eq. 24-26): the sphere light at the
   centroid with r_s = sqrt(area / pi), times |cos gamma|, gamma the angle between the
   triangle's normal and the direction from x to the centroid. A model, not the exact
   projection: its error is set by distance / sqrt(area) (docs/math.md section 4: L_0 within 1e-3 at
   20, 3e-5 at 100 for well-shaped triangles; slivers are worse). x closer to the centroid than
   r_s: the hemisphere (as shl_sphere_light) times |cos gamma|; x == centroid: axis +z.
   Zero-area triangle, NaN or infinite input: zeros. out_sh: n * n floats. Cost: one
   shl_sphere_light plus a cross product. */
SHLIGHT_INLINE void shl_triangle_light(int n, const float x[3], const float p0[3],
                                       const float p1[3], const float p2[3], float *out_sh);

/* shl_triangle_light_grad: shl_triangle_light and its gradient with respect to x ([GRAD]
   eq. 27-28): |cos gamma| grad S + S grad |cos gamma|, grad_x |cos gamma| =
   sign(cos gamma) (n_t - (n_t . w) w) / d. Edge-on (cos gamma = 0, the kink of |.|): the
   gradient of |cos gamma| is taken as 0 (the mean of the one-sided limits). Other degenerate
   inputs as shl_triangle_light (zeros) and shl_sphere_light_grad (inside the sphere: radial
   term 0). out_sh: n * n floats, out_grad: n * n float[3]. Cost: one shl_sphere_light_grad
   plus a cross product. */
SHLIGHT_INLINE void shl_triangle_light_grad(int n, const float x[3], const float p0[3],
                                            const float p1[3], const float p2[3], float *out_sh,
                                            float (*out_grad)[3]);

/* shl_triangle_solid_angle: signed solid angle of the triangle (p0, p1, p2) seen from x, by
   van Oosterom-Strackee in the edge form with atan2 (docs/math.md section 4, correction E6
   (docs/math.md section 12)): Omega = 2 atan2(N, D), R_i = p_i - x, N = R_0 . ((p1 - p0) x (p2 -
   p0)), D = |R0||R1||R2| + (R0.R1)|R2| + (R0.R2)|R1| + (R1.R2)|R0|, in shli_real. Positive when x
   is behind the triangle, i.e. on the side opposite to n = (p1 - p0) x (p2 - p0) (p0, p1, p2
   clockwise as seen from x); |Omega| for a two-sided light. Range [-2 pi, 2 pi]; Omega > pi (D < 0)
   for points close to the triangle. Accuracy (float inputs): relative 1e-7 at distance 1e4 (no
   unit-vector cancellation: the printed form loses 6e-2 there). Degenerate: zero-area triangle 0; x
   at a vertex 0; x in the triangle's plane: 0 outside the triangle, 2 pi inside it (both sides'
   limits are +-2 pi), 0 or 2 pi on an edge; NaN or infinite input: 0. Any finite scale, from
   denormals to FLT_MAX: when N and D overflow (|p_i - x| above ~7e12 in C, 1e12 in GLSL) or fall
   below 1e-30 they are recomputed with everything divided by the largest component of the p_i - x
   (Omega is scale-invariant). GLSL: in float the sum D cancels when two pairs of the R_i are nearly
   opposite (x near an edge, or near a vertex with the other two almost behind each other): the GLSL
   result is within 2.5 u (|Omega| + 2 (|D| EN + |N| ED) / (N^2 + D^2)) of the exact one, EN =
   |R0||p1 - p0| |p2 - p0| and ED the sum of the magnitudes of D's terms (up to 1.2e-2 of the
   face-on solid angle area / d^2 there; bench/solid_angle_float.c, tests/test_glsl). Cost: 3 sqrt,
   ~40 flops and the own atan2 (2 sqrt, 8-term polynomial). */
SHLIGHT_INLINE float shl_triangle_solid_angle(const float x[3], const float p0[3],
                                              const float p1[3], const float p2[3]);

/* ---- grid ---------------------------------------------------------------------------------- */
/* the order in which shl_grid_build sums the lights (the same bits either way) */
typedef enum shl_grid_order { SHLIGHT_GRID_FORWARD = 0, SHLIGHT_GRID_REVERSED = 1 } shl_grid_order;

/* reconstruction of shl_grid_sample */
typedef enum shl_grid_method {
  SHLIGHT_GRID_TRILINEAR = 0,
  SHLIGHT_GRID_TAYLOR = 1,
  SHLIGHT_GRID_HERMITE = 2
} shl_grid_method;

#ifndef SHLIGHT_RESULT_DEFINED
#define SHLIGHT_RESULT_DEFINED
/* Status of the CPU functions that can fail. */
typedef enum shl_result {
  SHLIGHT_OK = 0,
  SHLIGHT_EINVAL = -1,     /* an invalid argument */
  SHLIGHT_ENOMEM = -2,     /* an allocation failed */
  SHLIGHT_ELENGTH = -3,    /* loaders: input truncated, or longer than its header says */
  SHLIGHT_EMAGIC = -4,     /* loaders: not the expected file type (magic bytes) */
  SHLIGHT_EVERSION = -5,   /* loaders: unsupported format version */
  SHLIGHT_EDIMS = -6,      /* loaders: zero, negative, oversized or inconsistent dimensions */
  SHLIGHT_ENONFINITE = -7, /* NaN or infinity in the data */
  SHLIGHT_ECHECKSUM = -8,  /* loaders: checksum mismatch */
  SHLIGHT_ESTORAGE = -9    /* the caller's buffer is missing or too small (size reported) */
} shl_result;
#endif

/* shl_grid: plain data (no pointers), the same fields in GLSL. spacing: the cell size per
   axis (> 0 and finite where the dims > 1; ignored where dims = 1). n: bands of the stored
   SH. cull: the culling tolerance eps (>= 0, see >>grid). */
typedef struct shl_grid {
  float origin[3];
  float spacing[3];
  int dims[3]; /* vertices along x, y, z (>= 1 each) */
  int n;
  float cull;
} shl_grid;

#define SHLIGHT_GRID_FORWARD 0

#define SHLIGHT_GRID_TRILINEAR 0

/* shl_result_string: a constant string naming r and what it means ("SHLIGHT_EINVAL: an
   invalid argument"); any value that is not a shl_result gives "unknown shl_result".
   Never NULL. Cost: a switch. */
SHLIGHT_API const char *shl_result_string(shl_result r);

/* shl_grid_trilinear: out_sh[i] = sum_k w_k c8[k n^2 + i], w the trilinear weights of the
   fraction f (in [0, 1]^3; outside: linear extrapolation). out_sh: n * n floats. Cost: 7 FMA
   per coefficient. */
SHLIGHT_INLINE void shl_grid_trilinear(int n, const float *c8, const float f[3], float *out_sh);

/* shl_grid_taylor: first-order Taylor expansion from the nearest corner k (cx = f[0] >= 0.5,
   ...): out_sh[i] = c8[k n^2 + i] + g8[k n^2 + i] . ((f - corner) * cell), cell the cell size
   (shl_grid.spacing). out_sh: n * n floats. Cost: 3 FMA per coefficient. */
SHLIGHT_INLINE void shl_grid_taylor(int n, const float *c8, const float (*g8)[3], const float f[3],
                                    const float cell[3], float *out_sh);

/* shl_grid_hermite: tricubic Hermite from the corner values and gradients, mixed
   derivatives estimated in the cell (see >>grid): out_sh[i] = sum_k (wv_k c8[k n^2 + i] +
   wx_k g8[..][0] + wy_k g8[..][1] + wz_k g8[..][2]). f in [0, 1]^3, cell the cell size.
   out_sh: n * n floats. Cost: ~150 flops for the weights, 32 FMA per coefficient. */
SHLIGHT_INLINE void shl_grid_hermite(int n, const float *c8, const float (*g8)[3], const float f[3],
                                     const float cell[3], float *out_sh);

/* shl_grid_build: out_sh[v n^2 + i] = sum_j I_j shl_sphere_light(n, p_v, c_j, r_j)[i] over
   the lights that reach vertex v (culling, see >>grid), out_grad likewise with
   shl_sphere_light_grad (out_grad NULL: no gradients, values by shl_sphere_light). With
   cull = 0 each vertex holds exactly the per-point sum (same bits as a caller's loop
   out += I * shl_sphere_light(_grad) in light order). intensity NULL: all 1. order
   SHLIGHT_GRID_FORWARD or SHLIGHT_GRID_REVERSED, threads 1 or 2 (more: 2): the same bits.
   Lights with r <= 0 / NaN, non-finite centres or a non-finite intensity add nothing. Returns
   SHLIGHT_EINVAL (and writes nothing) for: g or out_sh NULL, n outside [1, SHLIGHT_MAX_BANDS], a
   dim < 1, a spacing <= 0 or non-finite on an axis with dims > 1, non-finite origin, cull < 0 or
   NaN, nlights < 0, centres or radii NULL with nlights > 0, an unknown order, threads < 1. Cost:
   (vertices) x (lights reaching them) shl_sphere_light_grad calls. */
SHLIGHT_API shl_result shl_grid_build(const shl_grid *g, const float (*centres)[3],
                                      const float *radii, const float *intensity, int nlights,
                                      int sum_order, int threads, float *out_sh,
                                      float (*out_grad)[3]);

/* shl_grid_sample: reconstruction at p from a grid built by shl_grid_build: clamps p to the
   grid's box (NaN components: the origin's), gathers the 8 corners of its cell and calls
   shl_grid_trilinear, shl_grid_taylor or shl_grid_hermite (method SHLIGHT_GRID_TRILINEAR,
   _TAYLOR, _HERMITE). grad may be NULL for trilinear only. out_sh: g->n^2 floats. Returns
   SHLIGHT_EINVAL for NULL g / sh / out_sh, invalid g (as shl_grid_build), an unknown method
   or a NULL grad that the method needs (nothing written then); otherwise SHLIGHT_OK (no
   allocation: the corners are gathered in chunks of at most 64 coefficients, 8 KB of stack).
   The output is finite wherever the grid's corner values (and gradients) are. */
SHLIGHT_API shl_result shl_grid_sample(const shl_grid *g, const float *sh, const float (*grad)[3],
                                       const float p[3], shl_grid_method method, float *out_sh);

/* ---- edge ---------------------------------------------------------------------------------- */
/* shl_edge_integral: the edge integral of [AREA] eq. 3,
   F(Phi, c, delta, e) = sum over k = e, e - 2, ..., >= 0 of c^k integral from -delta to
   Phi - delta of cos^k, for Phi in [0, pi], c in [0, 1], any delta, e = exponent >= 0 (rounded to
   the nearest integer), by `method`: SHLIGHT_EDGE_EXACT (the O(n) recurrence, in shli_real) or one
   of the O(1) fits SHLIGHT_EDGE_LORENTZ / _LORENTZ_PEARSON / _ELLIPSOID (AUTO, QUADRATURE,
   FAST and any unknown method id mean EXACT here). The arc is split at +-pi/2 and reduced with I(p
   + pi) = (-1)^n I(p) (docs/math.md section 7.2); orders n <= 2 and c < 1.0e-3 always take the
   exact path (closed forms; the fits are 0/0 there). Degenerate: c clamped to [0, 1], Phi to [0,
   pi]; NaN input -> 0; n > 1.0e6 clamped. Accuracy: EXACT matches long double quadrature to 1.0e-12
   relative to F(-pi/2, pi/2) in C (double inside); the fits' errors are in docs/area-lights.md. */
SHLIGHT_INLINE float shl_edge_integral(float phi, float c, float delta, float exponent,
                                       shl_edge_method method);

/* shl_polygon_moment: the axial moment of [AREA] eq. 1, integral over the solid angle of the
   polygon v[0..nv-1] (vertices relative to the shading point, any winding, two-sided), clipped
   to the hemisphere u.axis > 0, of (u.axis)^exponent. nv >= 3, any count in C (above
   SHLIGHT_POLYGON_MAX = 8 the polygon is summed in fan pieces of at most 8 vertices, see the
   start of >>edge; GLSL: at most SHLIGHT_POLYGON_MAX, above it -1). A non-convex or
   self-overlapping (planar) polygon is integrated with its winding number relative to its net
   orientation (a region wound twice counts twice). axis any non-zero vector (normalised
   inside); exponent >= 0 real. method:
   - SHLIGHT_EDGE_EXACT: exact at every real exponent. Integer exponents up to 65536: Arvo's
     form with the O(e) recurrence (double inside in C); any other exponent: the Stokes form
     (see >>edge) with an adaptive rule and an error estimate (shli_stokes_half, lev > 0:
     composite 5-node Gauss-Legendre, 2^l panels with the panel at the clip circle cut
     geometrically, until two levels agree to 1e-9), within 1e-5 of the normalised lobe
     (measured: 5.5e-8 against cubature for exponents 0.3..9999.5, the float output's rounding;
     3.2e-10 against its own 14-level refinement; 9e-11 against the recurrence at integer
     exponents). Cost: ~61k x86 instructions per doubly clipped quad at e = 777.7 (callgrind,
     GCC -O3 -march=x86-64-v3; QUADRATURE 10k).
   - SHLIGHT_EDGE_LORENTZ / _LORENTZ_PEARSON / _ELLIPSOID: Arvo's form with the paper's O(1)
     fits of F (errata fixed), exponent rounded to the nearest integer; above 65536 they take
     QUADRATURE (no float-to-int conversion of huge exponents).
   - SHLIGHT_EDGE_QUADRATURE: the Stokes form (see >>edge), O(1), any real exponent.
   - SHLIGHT_EDGE_AUTO: the recurrence for integer exponents <= 16, EXACT's adaptive rule
     above: exact everywhere, so its switch point is continuous (jump < 1e-7 relative at 16
     and the next float, measured). Cost: 2.5k instructions per quad at e = 10, 64k at 100
     (was QUADRATURE's 10k: exactness costs 6x; FAST is the constant-time road).
   - SHLIGHT_EDGE_FAST: the Stokes form in float with a 4-node rational-graded rule per
     half-arc and polynomial transcendentals, SIMD over 8 edges in C: O(1), any real exponent
     (finite to 1e30), ~1.3k x86 instructions per doubly clipped quad (GCC -O3
     -march=x86-64-v3), p95 1e-4 and max 1.5e-3 of the normalised lobe (docs/accuracy.md). GLSL:
   only with SHLIGHT_EDGE_FAST_ON 1 defined by the host, else it means QUADRATURE.
   - any other value (an unknown method id): SHLIGHT_EDGE_AUTO.
   Degenerate: nv < 3, zero axis, NaN anywhere, a polygon through the shading point or reduced
   to < 3 vertices by the clip: 0; NaN exponent or exponent >= 1e30: 0 (the limit of the
   moment); negative exponent: treated as 0. Result >= 0 (GLSL nv > SHLIGHT_POLYGON_MAX: -1).
   Accuracy and cost: docs/area-lights.md (measured against tests/ref/arearef.h). */
SHLIGHT_INLINE float shl_polygon_moment(const float (*v)[3], int nv, const float axis[3],
                                        float exponent, shl_edge_method method);

/* shl_polygon_phong: single-axis Phong shading from a polygon light ([AREA] eq. 10):
   (e+1)/(2 pi) M^e(P, r) with r the mirror direction of `view` about `nrm`, the polygon first
   clipped to the horizon u.nrm >= 0 (then to u.r >= 0 by the moment). Unit-radiance light,
   rho_s = 1: a light covering the whole r-hemisphere above the horizon gives 1 at normal
   incidence. view and nrm: unit, pointing away from the surface. Same methods and degenerate
   results as shl_polygon_moment; view below the horizon (nrm.view <= 0): 0. */
SHLIGHT_INLINE float shl_polygon_phong(const float (*v)[3], int nv, const float nrm[3],
                                       const float view[3], float exponent, shl_edge_method method);

/* shl_lobe_to_sg: the sharpness lambda of the spherical Gaussian exp(lambda (u.r - 1)) with the
   same half-maximum angle as the cosine lobe max(0, u.r)^n ([AREA] eq. 22, correction E16
   (docs/math.md section 12)): lambda = ln 2 / (1 - 2^(-1/n)), in the stable form ln 2 / -expm1(-ln
   2 / n) (float: 3e-8 relative at n = 1e7; the printed form is negative). n <= 0 or NaN: 0; lambda
   ~ n + ln 2 / 2 for large n: n >= 1e30 returns n itself (the relative difference is below float's
   resolution), so n = +inf gives +inf (the delta-lobe limit, documented; finite n gives
   a finite lambda). */
SHLIGHT_INLINE float shl_lobe_to_sg(float exponent);

/* shl_sg_to_lobe: the inverse, n = -ln 2 / log1p(-ln 2 / lambda) (exact round trip); lambda <=
   ln 2 has no cosine-lobe counterpart (the SG never falls to half): 0; NaN: 0. lambda >= 1e30
   returns lambda (as shl_lobe_to_sg), so +inf gives +inf (the limit); finite lambda gives a
   finite n. */
SHLIGHT_INLINE float shl_sg_to_lobe(float lambda);

/* shl_lobe_product: the product of two cosine lobes max(0, u.r1)^exponent1 max(0, u.r2)^exponent2
   approximated by one lobe mu max(0, u.r_p)^e_p ([AREA] sec. 7.1): both mapped to SGs
   (shl_lobe_to_sg), the exact SG product (axis r_p along lambda1 r1 + lambda2 r2, sharpness
   lambda_p = |lambda1 r1 + lambda2 r2|), mapped back (shl_sg_to_lobe), mu the true product at r_p
   (clamped lobes, docs/math.md 7.3). r1, r2: any finite non-zero vectors, normalised here in
   shli_real (so a float-normalised axis is exact enough for any exponent); zero, NaN or infinite:
   +z. Writes r_p (unit) and returns mu in [0, 1] (a product of two cosines <= 1 raised to
   exponent1, exponent2 >= 0), e_p in out_exponent[0]. Accuracy is the paper's: good for aligned
   lobes, poor beyond ~60 degrees (docs/accuracy.md); above n ~ 1e9 a lobe is narrower than the
   double rounding of the axes, and mu (still in [0, 1]) loses accuracy. Opposite lobes with equal
   sharpness (no axis), exponent1 or exponent2 negative or NaN, or |lambda1 r1 + lambda2 r2| >= 1e30
   (exponents ~1e30 and above, +inf): mu = 0, e_p = 0, r_p = r1. */
SHLIGHT_INLINE float shl_lobe_product(const float r1[3], float exponent1, const float r2[3],
                                      float exponent2, float *out_axis, float *out_exponent);

/* shl_polygon_phong_double_axis: double-axis Phong, (e+1)/(2 pi) times the integral over the
   polygon (clipped to the horizon) of max(0, u.r)^e max(0, u.nrm), by the lobe product of
   shl_lobe_product (exponent2 = 1: the cosine) and one moment about its axis ([AREA] sec. 7.1).
   Inputs and degenerate results as shl_polygon_phong. Exponents above 1e6: the product's limit,
   max(0, nrm.r) times the single-axis value (relative error ~ 1 / e; the SG road loses its axis to
   float rounding above ~1e12). Error: docs/area-lights.md (the product approximation dominates). */
SHLIGHT_INLINE float shl_polygon_phong_double_axis(const float (*v)[3], int nv, const float nrm[3],
                                                   const float view[3], float exponent,
                                                   shl_edge_method method);

/* shl_ellipse_phong: single-axis Phong (as shl_polygon_phong) from a planar ellipse light with
   centre c (relative to the shading point) and orthogonal semi-axis vectors a1, a2 (a disc when
   |a1| = |a2|), by the polygon road of [AREA] sec. 9 with two changes. The polygons are fixed
   to the light, never re-oriented per shading point, so the result is continuous in the shading
   point (the paper's arg-max orientation is what makes its Figure 17 jump); and two regular
   octagons rotated by pi/8 are averaged (vertices c + k (a1 cos t + a2 sin t), t = j pi/4 and
   j pi/4 + pi/8, k = sqrt(pi / (2 sqrt 2)): each has the ellipse's area), which cancels the
   octagon's leading rim error: 1.5e-3 instead of 1.4e-2 of the normalised lobe at e = 1000
   (tests/test_edge). Cost: two octagon moments. Non-uniform scale maps the outline exactly.
   Degenerate: as shl_polygon_phong; zero axes: 0. */
SHLIGHT_INLINE float shl_ellipse_phong(const float c[3], const float a1[3], const float a2[3],
                                       const float nrm[3], const float view[3], float exponent,
                                       shl_edge_method method);

/* shl_sphere_phong: single-axis Phong from a uniform sphere light (centre c relative to the
   shading point, radius r): the disc through c facing the point with radius r d / sqrt(d^2 -
   r^2) subtends the sphere's cap exactly; it is drawn as shl_ellipse_phong's octagons in the
   frame of Duff et al. (2017) about c / d (continuous in c except at c / d = -z). Shading point
   inside the sphere (d <= r): the light fills every direction, taken as an octagon of radius
   1e4 at distance 1 across the mirror direction (the r-hemisphere to 1e-4 rad). r <= 0, NaN
   or infinite input: 0. */
SHLIGHT_INLINE float shl_sphere_phong(const float c[3], float r, const float nrm[3],
                                      const float view[3], float exponent, shl_edge_method method);

/* shl_polygon_ggx_ndf: the integral over the polygon v[0..nv-1] (as shl_polygon_moment: any
   winding, two-sided, clipped to u.axis > 0) of D(u) (u.axis), D the isotropic GGX normal
   distribution about `axis` with roughness alpha (D(t) = alpha^2 / (pi (t^2 (alpha^2 - 1) +
   1)^2), normalised: the whole hemisphere gives 1). Closed form, one atan2 per edge, derived
   for shlight by the Stokes form of >>edge: the antiderivative of D(t) t is
   -(1 - t^2) / (2 pi (1 - (1 - alpha^2) t^2)), which along an edge's arc becomes
   w^2 / (2 pi (w^2 + alpha^2 c^2 cos^2 theta)) and integrates to
   (|w| / q) atan2(q sin Phi, cos Phi - (1 - alpha^2) x_A x_B) / (2 pi), q^2 = w^2 + alpha^2 c^2.
   alpha = 1 gives the cosine moment / pi (Lambert). It is the half-vector-space core of a GGX
   polygon light (the map from light to half vectors is not in this function). alpha clamped
   to [1e-4, 1]; degenerate inputs as shl_polygon_moment. */
SHLIGHT_INLINE float shl_polygon_ggx_ndf(const float (*v)[3], int nv, const float axis[3],
                                         float alpha);

/* shl_polygon_ggx: a GGX polygon light, the integral over the polygon v[0..nv-1] (vertices
   relative to the shading point, any winding, two-sided), clipped to the shading hemisphere
   nrm.l > 0, of f(view, l) (nrm.l) dl with f = D G2 / (4 (n.l)(n.v)) the GGX microfacet BRDF
   without Fresnel (F = 1), D the GGX normal distribution of roughness alpha (= perceptual
   roughness squared), G2 the height-correlated Smith masking-shadowing; multiply by the
   light's radiance (and a Fresnel or specular colour) outside. No table. Method: the half-vector
   NDF integral and its first moment by Stokes along the edges' images, a first-order Taylor model
   of the rest of the BRDF and a 7-point cubature of its remainder (derivation above;
   docs/accuracy.md "GGX polygon lights"). nrm and view any non-zero vectors (normalised inside), nv
   >= 3 (C: any count, fan pieces above SHLIGHT_POLYGON_MAX; GLSL: above it -1), alpha clamped to
   [1e-4, 1]. Degenerate inputs give 0: nv < 3, NaN or infinite input, zero normal or view, view at
   or below the horizon (nrm.view <= 0), NaN alpha, a light entirely below the horizon (exactly 0:
   the polygon is clipped first, so no light comes from below), a polygon through the shading point.
   Result >= 0. Accuracy against long double cubature (tests/ref/arearef.h) on the LTC comparison's
   sampler (docs/area-lights.md, bench/bench_ggx.c): median relative error 1e-6 to 5e-5 at
   roughness 0.05 to 1 (LTC: 7e-5 to 0.11), p95 below 0.9 %; weakest at grazing views with very
   large lights (up to 16 % for a light filling the hemisphere at alpha 0.04, view 85 deg).
   Cost: 18k x86 instructions per quad (10 Gauss nodes per edge with exp, sincos, log; 7 or 28
   cubature nodes per fan triangle), about 16x shl_polygon_phong FAST. */
SHLIGHT_INLINE float shl_polygon_ggx(const float (*v)[3], int nv, const float nrm[3],
                                     const float view[3], float alpha);

/* shl_polygon_beckmann: the Beckmann microfacet specular from a unit-radiance polygon
   light, the integral over the polygon (vertices relative to the shading point, any winding,
   two-sided) clipped to nrm.l > 0 of D_B(h) G2(l, v) / (4 (n.v)) dl, the same integrand as
   shl_polygon_beckmann_subedges (D_B(h) = exp(-tan^2 t / alpha^2) / (pi alpha^2 cos^4 t), t the
   angle of h from nrm; G2 the height-correlated Smith 1 / (1 + Lambda(v) + Lambda(l)) with
   Beckmann's Lambda, shli_beckmann_lambda; Fresnel 1), by shl_polygon_ggx's method with the
   Beckmann NDF: A and M1 by Stokes (the cap CDF 1 - exp(-tan^2 / alpha^2); the first moment's
   radial antiderivative by erfc, shli_beck_i), the first-order Taylor model of G2 (h.v) /
   ((n.v)(h.n)) and the 7-point cubature of its remainder (derivation at "GGX polygon lights"). No
   table; the recommended Beckmann light (shl_polygon_beckmann_subedges holds G2 at one direction).
   nrm and view any non-zero vectors, nv >= 3 (C: any count; GLSL: at most SHLIGHT_POLYGON_MAX,
   above it -1), alpha clamped to [1e-4, 1]. Degenerate inputs give 0 as shl_polygon_ggx (nv < 3,
   NaN / Inf input, zero normal or view, view at or below the horizon, NaN alpha, a light wholly
   below the horizon, a polygon through the shading point). Result >= 0. Accuracy against long
   double cubature (tests/ref/arearef.h) on bench_ggx's sampler (bench/bench_beckmann.c,
   docs/area-lights.md): median relative error 3e-6 to 1e-4 at roughness 0.05 to 1, p95 below 0.7 %,
   max error / albedo
   <= 4.9e-2 (grazing views, lights straddling the horizon; up to 6.7e-2 in test_microfacet's
   grazing set). Cost: 33k x86 instructions per quad (shl_polygon_beckmann_subedges k = 8: ~220k).
 */
SHLIGHT_INLINE float shl_polygon_beckmann(const float (*v)[3], int nv, const float nrm[3],
                                          const float view[3], float alpha);

/* shl_polygon_beckmann_ndf: the integral over the polygon v[0..nv-1] (as shl_polygon_moment:
   any winding, two-sided, clipped to u.axis > 0) of D(u) (u.axis), D the isotropic Beckmann
   normal distribution about `axis`, D(t) = exp(-(1 - t^2) / (t^2 alpha^2)) / (pi alpha^2 t^4)
   (normalised: the whole hemisphere gives 1). Stokes form of >>edge with the closed-form
   radial CDF 1 - exp(-tan^2(T) / alpha^2) of a cap of half-angle T: along an edge's arc the
   CDF is 1 - exp(-w^2 / (alpha^2 c^2 cos^2 theta)) (no elementary antiderivative: an Owen's T
   function), integrated with the graded 5+5-node Gauss-Legendre rule of QUADRATURE. Error
   (tests/test_microfacet, against long double cubature): max 1.0e-4 of the normalised lobe
   for alpha in [1e-3, 1] (as QUADRATURE moments). Cost: one QUADRATURE moment (20 exp + 20 sin per
   edge). The half-vector-space core of a Beckmann polygon light (shl_polygon_beckmann_subedges adds
   the map). alpha clamped to [1e-4, 1]; NaN alpha and the degenerate inputs of shl_polygon_moment:
   0.
 */
SHLIGHT_INLINE float shl_polygon_beckmann_ndf(const float (*v)[3], int nv, const float axis[3],
                                              float alpha);

/* shl_polygon_blinn_phong: the normalised Blinn-Phong microfacet specular from a unit-radiance
   polygon light, integral over the polygon v[0..nv-1] (vertices relative to the shading point,
   any winding, two-sided), clipped to the horizon u.nrm > 0, of f (nrm.l) dl with
   f = D(h) / 4, D(h) = (e+2)/(2 pi) (nrm.h)^e, h = normalise(l + view): the microfacet BRDF
   D G / (4 (n.l)(n.v)) with the implicit G = (n.l)(n.v), Fresnel 1. The usual engine form
   (e+8)/(8 pi) (n.h)^e is this times (e+8)/(e+2). Computed in half-vector space ([AREA] sec.
   8) over the light's image H(P), H's curved edges replaced by great arcs between the images
   of k sub-edges per light edge (shli_half_splits); the integrand there, t^e (n.l)(h.v), is
   integrated without a held factor (shli_half_image: two QUADRATURE moments and two line
   integrals per arc). subedges = k in [1, SHLIGHT_HALF_K] (clamped): 1 = the vertices only,
   2 = the paper's single split with its balancing heuristic, >= 3 = split at p plus graded
   splits; -k = the same without the balancing heuristic. Error (of the albedo, docs/accuracy.md
   "Microfacet polygon lights", 96 random quads x e = 1..1e4): worst case k = 2: 0.15, k = 4:
   3.0e-2, k = 8: 8.3e-3. Cost: ~90k / 220k / 420k x86 instructions per quad at k = 2 / 4 / 8
   (Phong QUADRATURE: 9.3k). view, nrm: any length (normalised inside). Degenerate: nv < 3, NaN /
   Inf input, zero nrm or view, view at or below the horizon (nrm.view <= 0), light wholly below the
   horizon, NaN exponent: 0; exponent clamped to [0, 1e6]. */
SHLIGHT_INLINE float shl_polygon_blinn_phong(const float (*v)[3], int nv, const float nrm[3],
                                             const float view[3], float exponent, int subedges);

/* shl_polygon_beckmann_subedges: the Beckmann microfacet specular from a unit-radiance polygon
   light (as shl_polygon_blinn_phong): integral over the polygon clipped to the horizon of D_B(h)
   G2(l, v) / (4 (n.v)) dl, D_B as in shl_polygon_beckmann_ndf about nrm, G2 the height-correlated
   Smith masking-shadowing 1 / (1 + Lambda(v) + Lambda(l)) with Beckmann's Lambda
   (shli_beckmann_lambda), Fresnel 1. In half-vector space: the integral of D_B (h.v) over the
   sub-edge image polygon without approximation beyond the split (shli_half_image), times G2 / (n.v)
   with G2 held at the light point nearest the mirror direction. subedges as shl_polygon_blinn_phong
   (the balancing uses m = alpha). Error (of the albedo, docs/accuracy.md): worst case 0.41 / 0.35 /
   0.36 at k = 2 / 4 / 8 (alpha = 0.4, lights straddling the horizon, grazing views, large lights:
   the held G2; without G2 k = 8 is within 1.1e-2); slivers 1.8e-3 at k = 8. Cost: ~48k / 115k /
   220k instructions per quad at k = 2 / 4 / 8. alpha clamped to [1e-4, 1]; NaN alpha and the
   degenerate inputs of shl_polygon_blinn_phong: 0. shl_polygon_beckmann computes the same integral
   with G2 not held (worst 4.9e-2 of the albedo on bench_ggx's sampler, 33k instructions): prefer
   it. */
SHLIGHT_INLINE float shl_polygon_beckmann_subedges(const float (*v)[3], int nv, const float nrm[3],
                                                   const float view[3], float alpha, int subedges);

/* ---- brdf ---------------------------------------------------------------------------------- */
/* windows of shl_sh_window */
typedef enum shl_window_kind {
  SHLIGHT_WINDOW_NONE = 0,
  SHLIGHT_WINDOW_HANNING = 1,
  SHLIGHT_WINDOW_LANCZOS = 2
} shl_window_kind;

#define SHLIGHT_WINDOW_NONE 0

/* shl_zh_phong: ZH of the normalised Phong lobe (e+1)/(2 pi) max(0, cos t)^e about its axis:
   out_zh[l] = K_l Lambda_l(e) (docs/math.md section 5; the printed products of [SSF] sec. 3.3.2).
   exponent: any real >= 0 (non-integer too); NaN or negative: 0 (the uniform hemisphere
   1/(2 pi)); above 1e30: 1e30, where every Lambda_l rounds to 1 (the Dirac limit, out_zh[l] =
   K_l). out_zh[0] = K_0 = 0.2820948 always (unit integral). Accuracy: within one float rounding
   of the exact value (binary128 quadrature) for e in [0, 1e4], n <= 64. out_zh: n floats.
   Cost: O(n), one division per band. */
SHLIGHT_INLINE void shl_zh_phong(int n, float exponent, float *out_zh);

/* shl_zh_cosine_power: ZH of the unnormalised clamped cosine power max(0, cos t)^e:
   out_zh[l] = 2 pi K_l Lambda_l(e) / (e+1) = sqrt(pi (2l+1)) int_0^1 x^e P_l(x) dx. Same
   exponent domain and accuracy as shl_zh_phong (e = 0: the hemisphere indicator, out_zh[0] =
   sqrt(pi); e = 1: the clamped cosine, out_zh = A_l K_l of docs/math.md section 6; above 1e30:
   1e30, every coefficient about 2 pi K_l 1e-30). out_zh: n floats. Cost: O(n). */
SHLIGHT_INLINE void shl_zh_cosine_power(int n, float exponent, float *out_zh);

/* shl_zh_lambert: ZH of the Lambert lobe max(0, cos t) / pi (k_d = 1; the BRDF times the
   cosine) about the normal: out_zh[l] = K_l Lambda_l(1) = (1/pi) K_l A_l with the
   Ramamoorthi-Hanrahan A_l (correction E7 (docs/math.md section 12): [SSF] even-l formula is off by
   2, 16, 192, ...): 0.2820948, 0.3257350, 0.1576958, 0, -0.0352618, 0, 0.0158923, ... Multiply by
   pi for the clamped cosine (irradiance). Accuracy: one float rounding. out_zh: n floats. Cost:
   O(n). */
SHLIGHT_INLINE void shl_zh_lambert(int n, float *out_zh);

/* shl_zh_blinn_phong: ZH of the normalised Blinn-Phong NDF times the cosine, D(h) (n . h) with
   D = (e+2)/(2 pi) (n . h)^e, about the normal n (unit integral over the hemisphere of h):
   the Phong lobe of exponent e + 1, exactly (a lobe over half vectors h; turning it into a
   lobe over light directions is the BRDF tables' business). exponent: NaN or < 0: 0, then as
   shl_zh_phong. out_zh: n floats. Cost: O(n). */
SHLIGHT_INLINE void shl_zh_blinn_phong(int n, float exponent, float *out_zh);

/* shl_zh_ggx: ZH of the GGX (Trowbridge-Reitz) NDF times the cosine about the normal,
   D(h)(n . h) with D = alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2) (unit integral:
   out_zh[0] = K_0). alpha: the roughness (GGX alpha, not its square root); alpha < 1e-6, 0,
   negative or NaN: the Dirac limit out_zh[l] = K_l (off by < 1e-7 K_l at alpha = 1e-6, l < 64);
   alpha > 1e4: 1e4. Measured max |error| / K_l against a long double quadrature in t: 5.4e-8
   (the float rounding of the output) for alpha in [1e-4, 1e2] and n in {1, 4, 8, 16, 32, 64}
   (tests/test_brdf; the rule itself is good to ~1e-9 K_l). out_zh: n floats. Cost:
   (36 + 2 ln(1/min(alpha, 1))) / h nodes, h = min(0.35, 6 / (n+1)), each one exp, one sqrt
   and n Legendre steps: 116 nodes at n = 4 and 223 at n = 32 for alpha = 0.1. */
SHLIGHT_INLINE void shl_zh_ggx(int n, float alpha, float *out_zh);

/* shl_zh_beckmann: ZH of the Beckmann NDF times the cosine about the normal, D(h)(n . h) with
   D = exp(-tan^2 t / alpha^2) / (pi alpha^2 cos^4 t). alpha: the Beckmann roughness (RMS
   slope); degenerate alpha as shl_zh_ggx. Accuracy as shl_zh_ggx (max 7e-8 K_l). out_zh: n
   floats. Cost: about 22 / h nodes (alpha-independent: 63 at n = 4, 121 at n = 32), each two
   exp, one sqrt and n Legendre steps. */
SHLIGHT_INLINE void shl_zh_beckmann(int n, float alpha, float *out_zh);

/* shl_sh_dot: sum_i a[i] b[i], i < n^2: the integral over the sphere of the product of two
   functions given by their SH ([HVL] eq. 4), accumulated in shli_real in four interleaved
   partial sums (i mod 4: independent add chains, so the loop is not bound by the add
   latency; the result does not depend on the compiler's reassociation). a, b: n^2 floats.
   n < 1: 0. Cost: n^2 FMA. */
SHLIGHT_INLINE float shl_sh_dot(int n, const float *a, const float *b);

/* shl_sh_conv_zh: the integral of the SH function sh (n^2 coefficients) times the lobe with
   ZH coefficients zh (n floats) turned to the axis w: sum_l sqrt(4 pi/(2l+1)) zh[l] sum_m
   sh[l(l+1)+m] Y_lm(w) = shl_sh_dot(sh, shl_zh_rotate(zh, w)) without the rotated copy. w: any
   finite non-zero vector (normalised in shli_real); zero, NaN or infinite: +z. n < 1: 0.
   Cost: one SH evaluation (n^2 values, a float[SHLIGHT_MAX_COEFFS] on the stack) and n^2 FMA. */
SHLIGHT_INLINE float shl_sh_conv_zh(int n, const float *sh, const float *zh, const float w[3]);

/* shl_zh_dot_zh: the integral over the sphere of the product of two circularly symmetric
   functions, ZH zh_a about the axis u and ZH zh_b about the axis v (n floats each):
   sum_l zh_a[l] zh_b[l] P_l(u . v) (see >>brdf; equal to shl_sh_dot of the two rotated SH).
   Use it when the lobe is circularly symmetric about its own axis (Phong about the mirror
   direction, a microfacet lobe about the normal) and the radiance is a ZH (a sphere light's
   cap, an HVL). u, v: any finite non-zero vectors; zero, NaN or infinite: +z. n < 1: 0.
   Cost: O(n): two normalisations, n Legendre steps, 3n flops. */
SHLIGHT_INLINE float shl_zh_dot_zh(int n, const float *zh_a, const float u[3], const float *zh_b,
                                   const float v[3]);

/* shl_zh_irradiance_quadratic: irradiance E = int L(w) max(0, n . w) dw of a 3-band ZH radiance
   zh3 = (L_0, L_1, L_2) about an axis w_l, at a normal with z = w_l . n: [HVL] Appendix B,
   E = sigma^T M sigma, sigma = (z, 1), M = ((c3 L2, c2 L1), (c2 L1, c4 L0 - c5 L2)), i.e.
   c3 L2 z^2 + 2 c2 L1 z + c4 L0 - c5 L2 with the exact constants c2 = sqrt(3 pi)/6,
   c3 = 3 sqrt(5 pi)/16, c4 = sqrt(pi)/2, c5 = sqrt(5 pi)/16 (the printed 6-digit values
   differ by <= 1.1e-6). z outside [-1, 1]: clamped; NaN: 0. Cost: 5 flops. */
SHLIGHT_INLINE float shl_zh_irradiance_quadratic(const float *zh3, float z);

/* shl_zh_irradiance: the same for n bands, E(z) = sum_l A_l K_l L_l P_l(z), A_l = pi
   Lambda_l(1) (docs/math.md section 6): the exact irradiance of the band-limited radiance (its
   bands
   >= n are zero, so the clamped cosine's are not needed). zh: n floats; z as
   shl_zh_irradiance_quadratic. n < 1: 0. Cost: O(n). */
SHLIGHT_INLINE float shl_zh_irradiance(int n, const float *zh, float z);

/* shl_sh_window: multiplies band l of a ZH (io_zh, n floats) by a window sigma_l against
   ringing (Sloan, "Stupid SH tricks"; [HVL] sec. 4.2): kind SHLIGHT_WINDOW_HANNING (1):
   sigma_l = (1 + cos(pi l / width)) / 2; SHLIGHT_WINDOW_LANCZOS (2): sigma_l = sinc(l / width)
   = sin(pi l / width) / (pi l / width); both 0 for l >= width. width: the window's band count,
   > 0 (typically n, or n + 1 to keep the last band); <= 0 or NaN: n; +inf: sigma_l = 1 (the
   limit; every band kept). Another kind
   (SHLIGHT_WINDOW_NONE): unchanged. For an SH vector multiply its band l by the sigma_l that
   this returns for a ZH of ones. Measured on a cap (half-angle 30 deg, n = 8; tests/test_brdf,
   bench/out/brdf.md): see docs/accuracy.md. Cost: O(n). */
SHLIGHT_INLINE void shl_sh_window(int n, shl_window_kind kind, float width, float *io_zh);

/* shl_zh_bands_for: the smallest band count m in [1, n] whose truncation of the lobe zh (n
   floats, n = the largest band count considered) has relative squared L2 error
     sum_{m <= l < n} zh[l]^2 / sum_{l < n} zh[l]^2 <= target,
   i.e. the fraction of the lobe's energy (over the sphere, within the first n bands) that the
   dropped bands carry. (The bands >= n are not seen: pass a large n, e.g. 64, to measure
   against the full lobe.) For an L2 error target eps relative to the lobe's norm, pass eps^2.
   target NaN or < 0: n; a zero lobe: 1. Cost: O(n). */
SHLIGHT_INLINE int shl_zh_bands_for(int n, const float *zh, float target);

/* ---- hvl ----------------------------------------------------------------------------------- */
/* shl_hvl_horizon: exact fraction H in [0, 1] of the cap of a sphere of radius r at distance
   d in the direction w that lies above the plane of the normal nrm (see >>hvl). nrm, w: any
   finite non-zero vectors (normalised in shli_real; zero, NaN or infinite: +z). d <= r (x on
   or inside the sphere): the cap is the hemisphere about w (s = 1). r <= 0 or NaN, d NaN, or
   a cap too small for float (s = 0): the point limit, 1 if nrm . w > 0, 0 if < 0, 1/2 if 0.
   Accuracy: max |error| 3.0e-8 (the float rounding of the output) against a long double
   ring-by-ring quadrature of the cap, s from 1e-6 to 1, all crossing angles (tests/test_brdf).
   Cost: 2 normalisations, ~8 sqrt, 2 own atan2. */
SHLIGHT_INLINE float shl_hvl_horizon(const float nrm[3], const float w[3], float r, float d);

#ifdef SHLIGHT_REFERENCE_FORMS
/* shl_hvl_horizon_smoothstep: [HVL] eq. 22 with correction E8 (docs/math.md section 12) fixed: H =
   S((a + pi/2 - clamp(beta, pi/2 - a, pi/2 + a)) / (2a)), S(x) = 3x^2 - 2x^3 on x clamped to [0,
   1]. Same arguments and degenerate results as shl_hvl_horizon (a = 0: the point limit). Max abs
   error against the exact H: 0.039 (a = 0.01) to 0.089 (a = 1.5) (docs/math.md section 6;
   remeasured in tests/test_brdf). Cost: 2 normalisations, 2 own atan2. */
SHLIGHT_INLINE float shl_hvl_horizon_smoothstep(const float nrm[3], const float w[3], float r,
                                                float d);
#endif

/* shl_hvl_geometric: [HVL] eq. 21, G_j = max(0, n_j . (x - y)/|x - y|) H(n_x, w_j) /
   (pi r^2), with H exact (exact != 0, shl_hvl_horizon) or the smoothstep variant (exact = 0).
   x, nrm: shading point and its normal; y, light_nrm: the HVL's centre and normal (normals: any
   non-zero vectors, normalised here). r <= 0 or NaN: 0 (no HVL). x == y: the direction +z
   (then H is the hemisphere's). NaN or infinite positions: 0. Bounded by 1 / (pi r^2); a
   value above FLT_MAX (possible for r < 3.1e-20 only) saturates to FLT_MAX, never inf. Cost:
   about 3 normalisations and one H. */
SHLIGHT_INLINE float shl_hvl_geometric(const float x[3], const float nrm[3], const float y[3],
                                       const float light_nrm[3], float r, int exact);

/* shl_hvl_emission: the reconstruction F' . Y(dir) of an SH emission function femit (n^2
   floats) in the direction dir ([HVL] eq. 20 with dir = -w_j, from the HVL to x; any
   finite non-zero vector, normalised; zero, NaN or infinite: +z). n = 1 (isotropic HVL):
   femit[0] Y_0^0, no SH evaluation. Not clamped: a band-limited emission can be negative.
   n < 1: 0. Cost: one SH evaluation (a float[SHLIGHT_MAX_COEFFS] on the stack) and n^2 FMA. */
SHLIGHT_INLINE float shl_hvl_emission(int n, const float *femit, const float dir[3]);

/* shl_hvl_radiance: [HVL] eq. 20, L_j = power (F' . Y(-w_j)) G_j(-w_j): the radiance that
   HVL j (centre y, normal light_nrm, radius r, emission femit: n^2 floats of SH in world axes)
   sends to the shading point x with normal nrm; exact selects H as in shl_hvl_geometric. Degenerate
   inputs: those of shl_hvl_geometric give 0. Cost: shl_hvl_emission + shl_hvl_geometric. */
SHLIGHT_INLINE float shl_hvl_radiance(int n, const float *femit, float power, const float x[3],
                                      const float nrm[3], const float y[3],
                                      const float light_nrm[3], float r, int exact);

/* shl_hvl_contribution: [HVL] eq. 19, lj (L . F): the light that HVL j (centre y, radius
   r, radiance lj from shl_hvl_radiance) reflects at x through a lobe F given by its SH fsh
   (n^2 floats, world axes; e.g. the BRDF with the cosine for the outgoing direction),
   L = the SH of the sphere's unit cap at x (shl_zh_cap about w_j). x inside the sphere: the
   hemisphere about w_j; r <= 0, NaN or infinite: 0. Cost: shl_zh_cap + shl_sh_conv_zh. */
SHLIGHT_INLINE float shl_hvl_contribution(int n, float lj, const float *fsh, const float x[3],
                                          const float y[3], float r);

/* shl_hvl_contribution_zh: the same with a circularly symmetric lobe, ZH fzh (n floats) about
   the axis faxis ([HVL] sec. 6.3: Phong about the mirror direction, a microfacet lobe
   about the normal): lj shl_zh_dot_zh(cap about w_j, fzh about faxis). Degenerate inputs as
   shl_hvl_contribution (faxis zero, NaN or infinite: +z). Cost: shl_zh_cap + O(n). */
SHLIGHT_INLINE float shl_hvl_contribution_zh(int n, float lj, const float *fzh,
                                             const float faxis[3], const float x[3],
                                             const float y[3], float r);

/* shl_hvl_radius_neighbours: [HVL] eq. 23, r1 = sum w_i |p - pn_i| / sum w_i with
   w_i = 1 / (|dist - dn_i| + eps): the HVL at p (distance dist to its primary light) and up
   to 8 neighbours pn_i (distances dn_i) from the RSM. count: clamped to [0, 8]. eps: NaN or
   below 1e-20: 1e-20. Neighbours with a non-finite position or distance are skipped; none
   left: 0. Cost: count sqrt and divisions. */
SHLIGHT_INLINE float shl_hvl_radius_neighbours(int count, const float p[3], float dist,
                                               const float (*pn)[3], const float *dn, float eps);

/* shl_hvl_radius_fov: [HVL] eq. 24-26, r2 = d (g + g^3 / 3), g = sqrt(2) fov / sqrt(hvl_count),
   the Taylor form of d tan(g) (fov: the RSM's field of view in radians, hvl_count the number of
   HVLs, d the HVL's distance to the light). Within 1 % absolute of tan for g <= 0.5786, i.e.
   fov / sqrt(hvl_count) <= 0.41 (correction E9 (docs/math.md section 12); the paper's 0.2 is
   wrong). hvl_count < 1: 1. d or fov NaN or < 0: 0. A result above FLT_MAX (d near FLT_MAX, or a
   huge fov) saturates to FLT_MAX, never inf; +inf d or fov: FLT_MAX. Cost: 1 sqrt, 8 flops. */
SHLIGHT_INLINE float shl_hvl_radius_fov(float d, float fov, int hvl_count);

/* shl_hvl_radius_fov_tan: eq. 25 itself, r2 = d tan(g), g as shl_hvl_radius_fov, with the own
   sine (no GLSL tan); g clamped to [0, 1.5707] (tan <= 1.3e4). Same degenerate inputs and
   saturation at FLT_MAX.
   Cost: 1 sqrt, 2 short polynomials. */
SHLIGHT_INLINE float shl_hvl_radius_fov_tan(float d, float fov, int hvl_count);

/* ---- brdftab ------------------------------------------------------------------------------- */
/* shl_sh_rotate_z: io_sh (n bands) becomes the SH of the function rotated by the angle phi
   about +z, given c1 = cos(phi) and s1 = sin(phi) (unit: c1^2 + s1^2 = 1): for m > 0,
   (a, b) = (io_sh[l(l+1)+m], io_sh[l(l+1)-m]) -> (a cos(m phi) - b sin(m phi),
   a sin(m phi) + b cos(m phi)); m = 0 unchanged. cos(m phi), sin(m phi) by the angle-addition
   recurrence in shli_real. Cost: 4 flops per coefficient. */
SHLIGHT_INLINE void shl_sh_rotate_z(int n, float c1, float s1, float *io_sh);

/* shl_brdf_table_cell: the samples and weights of the lookup at the outgoing direction wo
   (local frame, any finite vector; wo_x = wo_y = 0, zero included, is normal incidence,
   theta_o = 0, phi_o = 0; wo_z < 0 counts as the horizon). out_idx[j] is a sample index
   s = p * n_theta + t (the table's F of sample s starts at float 2 s n^2, F' at (2 s + 1) n^2),
   out_w[j] its weight, j < 4: (t0, p0), (t0 + 1, p0), (t0, p1), (t0 + 1, p1) with
   p1 = (p0 + 1) mod n_phi; the weights add up to 1. Isotropic tables (n_phi = 1) have weight 0
   at j = 2, 3 (indices repeat j = 0, 1); n_theta = 1 puts all weight on t = 0. The samples
   cover theta_o in [0, 90] degrees (grid of >>brdftab): no clamping at the ends.
   n_theta or n_phi outside [1, 4096] (SHLIGHT_BRDF_TABLE_MAX_SAMPLES): all indices 0, all
   weights 0 (so n_theta n_phi < 2^24 and no index overflows an int). Cost: one atan2 and one
   log (a second atan2 with n_phi > 1), ~40 flops. */
SHLIGHT_INLINE void shl_brdf_table_cell(int n_theta, int n_phi, const float wo[3], int *out_idx,
                                        float *out_w);

/* shl_brdf_table_lookup: the SH (n bands) of F (which = 0) or F' (which = 1) at the outgoing
   direction wo (local frame, see shl_brdf_table_cell), interpolated from the table tab (layout
   of >>brdftab: n_theta * n_phi * 2 * n^2 floats) and, for an isotropic table (n_phi = 1),
   rotated about z to wo's azimuth (shl_sh_rotate_z with cos, sin of atan2(wo_y, wo_x); no
   rotation when wo_x = wo_y = 0). out_sh: n * n floats. GLSL: tab is
   float[SHLIGHT_BRDF_TABLE_FLOATS] (the host defines it; shl_prelude.glsl defaults it to
   2 * 90 * SHLIGHT_MAX_COEFFS, one isotropic table of 90 samples); a shader that keeps the
   table in an SSBO calls shl_brdf_table_cell, sums the 4 weighted samples itself and then
   shl_sh_rotate_z. which outside {0, 1} is taken as 0; n_theta or n_phi outside [1, 4096],
   or a table of n_theta n_phi 2 n^2 >= 2^31 floats (beyond int indexing), give zeros.
   Cost: the cell, 4 FMA per coefficient, the rotation (4 flops per coefficient). */
SHLIGHT_INLINE void shl_brdf_table_lookup(int n, int n_theta, int n_phi, int which,
                                          const float *tab, const float wo[3], float *out_sh);

/* ---- ssf ----------------------------------------------------------------------------------- */
/* the analytic BRDFs (shl_brdf_params.model) */
typedef enum shl_brdf_model {
  SHLIGHT_BRDF_LAMBERT = 0,
  SHLIGHT_BRDF_PHONG = 1,
  SHLIGHT_BRDF_BLINN_PHONG = 2,
  SHLIGHT_BRDF_BECKMANN = 3,
  SHLIGHT_BRDF_GGX = 4
} shl_brdf_model;

typedef struct shl_brdf_params {
  shl_brdf_model model; /* SHLIGHT_BRDF_* */
  float kd;             /* diffuse albedo, >= 0 */
  float ks;             /* specular scale, >= 0 */
  float exponent;       /* Phong / Blinn-Phong exponent e in [0, SHLIGHT_BRDF_MAX_EXPONENT] */
  float alpha_x;        /* Beckmann / GGX slope roughness along x, [SHLIGHT_BRDF_MIN_ALPHA, 4] */
  float alpha_y;        /* along y (= alpha_x: isotropic) */
  float f0;             /* Schlick reflectance at normal incidence, [0, 1] (1: no Fresnel) */
} shl_brdf_params;

/* shl_brdf_table: n bands, n_theta x n_phi outgoing samples, flags (SHLIGHT_BRDF_TABLE_ANISO
   iff n_phi > 1), data: shl_brdf_table_size(n, n_theta, n_phi) floats owned by the caller, in
   the layout of >>brdftab: data[((p * n_theta + t) * 2 + k) * n^2 + i]. */
typedef struct shl_brdf_table {
  int n;
  int n_theta;
  int n_phi;
  int flags;
  float *data;
} shl_brdf_table;

/* shl_merl: a measured isotropic BRDF in MERL's half-diff parametrisation [MPBM03]: dims
   (n_theta_h, n_theta_d, n_phi_d), 90 x 90 x 180 in the MERL files; data: 3 * the product of
   the dims floats owned by the caller, data[((c * n_theta_h + ih) * n_theta_d + id) * n_phi_d
   + ip], channel c = 0 red, 1 green, 2 blue, the MERL scale factors (1, 1.15, 1.66) / 1500
   applied, negative (invalid) samples kept as stored. */
typedef struct shl_merl {
  int n_theta_h;
  int n_theta_d;
  int n_phi_d;
  float *data;
} shl_merl;

/* shl_brdf_table.flags: bit 0 set for an anisotropic table (n_phi > 1); other bits 0. */
#define SHLIGHT_BRDF_TABLE_ANISO 1

#define SHLIGHT_BRDF_TABLE_VERSION 2
#define SHLIGHT_BRDF_TABLE_HEADER 40
#define SHLIGHT_BRDF_TABLE_GRID 1

#define SHLIGHT_BRDF_TABLE_GRAZING 1e-6

#define SHLIGHT_BRDF_MAX_EXPONENT 1e6f
#define SHLIGHT_BRDF_MIN_ALPHA 1e-3f
/* limits the loaders enforce (SHLIGHT_EDIMS beyond them) */
#define SHLIGHT_BRDF_TABLE_MAX_SAMPLES 4096 /* n_theta, n_phi each */
#define SHLIGHT_MERL_MAX_DIM 1024           /* each of the three MERL dimensions */

/* shl_ssf_vpl_sh: adds to io_sh (n * n floats, n bands) the SH of the incoming radiance at the
   receiver x due to one VPL at y with normal light_nrm and flux `flux`: io_sh[i] += e Y_i(w), with
   w = (y - x) / |y - x| and e = flux max(0, light_nrm . -w) / (pi max(|y - x|^2, dmin^2)) (see
   >>ssf for the constant). nrm: the receiver's geometric normal, any length: a VPL strictly below
   its plane (nrm . w < 0) adds nothing (a normal-mapped shading normal must not see light through
   the surface); nrm = 0 turns the test off. light_nrm: any finite non-zero vector (normalised;
   zero, NaN or infinite: +z, the library's convention). dmin: the clamp distance (<= 0 or NaN: no
   clamp); |y - x| is taken as at least 1e-18. Nothing is added when flux <= 0, NaN or infinite, x
   == y (no direction), x or y NaN or infinite, or the VPL faces away (light_nrm . -w <= 0). n < 1:
   nothing; n > SHLIGHT_MAX_BANDS: see shli_bands. Accuracy: e to a few float roundings, times Y of
   >>basis. Cost: 2 normalisations, one SH evaluation (a float[SHLIGHT_MAX_COEFFS] on the
   stack) and n^2 FMA. */
SHLIGHT_INLINE void shl_ssf_vpl_sh(int n, const float x[3], const float nrm[3], const float y[3],
                                   const float light_nrm[3], float flux, float dmin, float *io_sh);

/* shl_ssf_vpl_irradiance: the irradiance at x with the shading normal shading_nrm due to the
   same VPL, e max(0, shading_nrm . w) with e and w as in shl_ssf_vpl_sh (x, nrm, y, light_nrm:
   the same; the exact value that shl_ssf_irradiance of the accumulated SH approaches as the
   band count grows). shading_nrm: any finite non-zero vector
   (normalised; zero, NaN or infinite: +z). Degenerate inputs as shl_ssf_vpl_sh: 0. Cost: 3
   normalisations, ~30 flops. */
SHLIGHT_INLINE float shl_ssf_vpl_irradiance(const float x[3], const float nrm[3],
                                            const float shading_nrm[3], const float y[3],
                                            const float light_nrm[3], float flux, float dmin);

/* shl_ssf_interleave: the VPL set of pixel (px, py) under tile_x x tile_y interleaved sampling of
   nvpl VPLs (see >>ssf): out_range[0] = the first VPL s = (py mod tile_y) tile_x + (px mod
   tile_x), out_range[1] = the stride tile_x tile_y; the set is s, s + stride, ... below nvpl, and
   the return value is its size, ceil((nvpl - s) / stride) (0 when s >= nvpl). Every
   tile_x x tile_y tile of pixels uses every VPL exactly once. px, py: any int (negative ones
   continue the pattern periodically). tile_x, tile_y: clamped to [1, 256]; nvpl < 0: 0.
   out_range: 2 ints. Cost: a few integer operations. */
SHLIGHT_INLINE int shl_ssf_interleave(int px, int py, int tile_x, int tile_y, int nvpl,
                                      int *out_range);

/* shl_ssf_weight: the discontinuity-aware filter weight ([SSF] sec. 2.3; IGI) between a
   pixel's surface point p with geometric normal p_nrm and a neighbour's q with q_nrm: 1 when both
   lie on one smooth surface, else 0. The test: the normals (normalised) agree, p_nrm . q_nrm >=
   min_cos, and each point lies within max_dist of the other's tangent plane, |p_nrm . (q - p)| <=
   max_dist and |q_nrm . (p - q)| <= max_dist (symmetric in the two pixels; a plane distance, so a
   slanted plane passes at any depth, a depth step or a silhouette does not). Give it the geometric
   (interpolated) normals, not the normal-mapped ones, and a max_dist that scales with the
   pixel's footprint, e.g. 0.02 times the eye distance. max_dist < 0 or NaN: 0 for every pair;
   +infinity: no plane test. min_cos <= -1: no normal test; NaN: 0. p == q and p_nrm == q_nrm: 1 for
   max_dist >= 0 and min_cos <= 1. Normals zero: +z; NaN or infinite: 0; NaN or infinite
   positions: 0. Cost: 2 normalisations, ~20 flops. */
SHLIGHT_INLINE float shl_ssf_weight(const float p[3], const float p_nrm[3], const float q[3],
                                    const float q_nrm[3], float max_dist, float min_cos);

/* shl_ssf_irradiance: the irradiance E = int L(w) max(0, nrm . w) dw of the radiance with SH sh
   (n * n floats, e.g. the filtered sum of shl_ssf_vpl_sh) at the normal nrm: sh convolved with
   the clamped cosine turned to nrm, shl_sh_conv_zh(sh, shl_zh_cosine_power(n, 1)). A
   Lambertian surface of albedo kd reflects kd E / pi. Exact for the band-limited radiance; for
   a VPL's delta (e at w) the n-band clamped cosine gives e times a value that differs from
   max(0, nrm . w) by at most 0.094 (n = 3, 4), 0.059 (n = 5, 6), 0.021 (n = 16), 0.0050
   (n = 64), about 0.32 / n, the worst at the horizon nrm . w = 0, where it also rings below 0
   (tests/test_ssf). nrm: any finite non-zero vector (normalised; zero, NaN or infinite: +z).
   n < 1: 0. Cost: O(n) for the lobe, one SH evaluation and n^2 FMA (for RGB see >>ssf: one
   rotation, three dots). */
SHLIGHT_INLINE float shl_ssf_irradiance(int n, const float *sh, const float nrm[3]);

/* shl_sh_eval_accurate: Y_i(d / |d|) for any d != 0, the input normalised in double: error
   at the float rounding floor for every n. Zero / NaN / Inf d: Y(0,0,1). CPU only. */
SHLIGHT_API void shl_sh_eval_accurate(int n, const float d[3], float *out_y);

/* shl_sh_eval_batch: SoA batch of count unit directions (x[j], y[j], z[j]);
   out_y[i * count + j] = Y_i. SIMD across directions (AVX-512, AVX2+FMA or SSE2 as compiled,
   scalar with SHLIGHT_NO_SIMD). The vector path runs the recurrence in float (Reinsch form,
   input renormalised per lane); accuracy in docs/accuracy.md. count <= 0: nothing written. CPU
   only. Cost (AVX-512, output in L1, count a multiple of 32): per direction ~0.1 of the plain float
   loop for 7..16 bands, 0.05-0.12 for n <= 6. The output is n^2 count floats written once:
   beyond L1 the stores bound it (n = 16: 0.22-0.28 of the loop from count 100 on). When it
   exceeds 256 KiB, count is a multiple of the SIMD width and out_y is float-aligned, the rows
   go out by streaming (non-temporal) stores, so that any count costs about the same per
   direction (n = 10: 0.26-0.30 of the loop at count 1000 .. 65536); the values then sit in
   memory, not in the caches. */
SHLIGHT_API void shl_sh_eval_batch(int n, int count, const float *x, const float *y, const float *z,
                                   float *out_y);

/* shl_brdf_eval: f_s(w_o, w_i) of an analytic BRDF (models above), evaluated in double. wo, wi
   unit, local frame; 0 when either is at or below the surface (z <= 0), for an unknown model,
   and for alpha <= 0 (microfacet models). Reciprocal: f(wo, wi) = f(wi, wo) up to rounding.
   Cost: ~30 flops (Beckmann: two erf). */
SHLIGHT_API float shl_brdf_eval(const shl_brdf_params *brdf, const float wo[3], const float wi[3]);

/* shl_brdf_table_size: floats of a table of n bands and n_theta x n_phi samples:
   n_phi n_theta 2 n^2; 0 for n outside [1, SHLIGHT_MAX_BANDS], n_theta or n_phi outside
   [1, SHLIGHT_BRDF_TABLE_MAX_SAMPLES], or a size whose SHLT file would not fit in size_t.
   The kernels index tables with int: shl_brdf_table_lookup gives zeros for a table of
   n_theta n_phi 2 n^2 >= 2^31 floats. */
SHLIGHT_API size_t shl_brdf_table_size(int n, int n_theta, int n_phi);

/* shl_brdf_table_build: fills t->data (t->n, n_theta, n_phi, flags set by the caller, data
   holding shl_brdf_table_size floats) with the SH of F and F' of the analytic BRDF at each
   outgoing sample (layout and sampling of >>brdftab). Quadrature over w_i, sums in double:
   - the kd / pi term: Gauss-Legendre in cos(theta_i) (n/2 + 2 nodes) x uniform phi_i (n + 2
     nodes), exact for it (its products with Y are polynomials of degree <= n);
   - isotropic microfacet lobes (Blinn-Phong; Beckmann and GGX with alpha_x = alpha_y), over
     the half vector h (w_i its mirror of w_o, d w_i = 4 (w_o . h) d h): D depends only on the
     angle t of h from the normal, with the width alpha (Blinn-Phong sqrt(2 / (e + 2))) at any
     theta_o, so a sharp lobe is not foreshortened at grazing w_o. Panels of t at atan(3^k
     alpha), k < 8, at t1 = (90 deg - theta_o) / 2 (below it every circle of h is whole, above
     it w_i crosses the horizon) and graded (ratio 1/4, down to t1) towards the end tmax = 90
     deg - t1 (w_i = w_o's backscatter on the horizon, where F' of a grazing w_o peaks like
     1 / (cos_i + cos_o)); quad_order Gauss-Legendre nodes per panel after g = g0 + (g1 - g0)
     s^2 (3 - 2 s). Whole circles: 2 quad_order uniform nodes; arcs (closed-form ends): panels
     graded towards the ends (1 - 4^-k, k <= 3), quad_order nodes each;
   - other specular terms (Phong, anisotropic Beckmann / GGX), in the frame whose pole is the
     mirror direction r of w_o: panels of the angle g from r with break points at 2, 6, 18, 54
     lobe widths (width: 1/sqrt(e + 1) Phong, 2 max(alpha) microfacet), where the circle of
     angle g about r first meets the horizon (g = pi/2 - theta_o) and where it leaves it;
     quad_order Gauss-Legendre nodes per panel after the same substitution; on each circle only
     the arc above the horizon (end points in closed form): 2 quad_order uniform nodes round a
     whole circle, else panels at 0, +-w/2, +-3w/2, +-9w/2 and graded towards the arc's ends
     (pm - L/4, /16, /64), quad_order Gauss-Legendre nodes each.
   Every panel's integrand is smooth, so the error falls geometrically with quad_order
   (docs/brdf-tables.md has the error against quad_order).
   Outgoing samples on the grid of >>brdftab (shl_brdf_table_theta), the last one at
   cos theta_o = SHLIGHT_BRDF_TABLE_GRAZING. Y by shl_sh_eval in float at the float-rounded
   node; the table rounds to float. Stack: about 13.5 KB deep (gcc -O2 -fstack-usage: 12.6 KB in
   the build loop; the quadrature nodes are made on the fly, no per-arc scratch arrays).
   out_err_est (may be NULL; NULL also skips the extra passes): an estimate of the returned
   table's largest absolute error (table units) from the tables at quad_order / 4 and / 2: per
   sample, with e1 = max |T(q/2) - T(q/4)| and e2 = max |T(q) - T(q/2)|, e2^2.5 / e1^1.5 while
   e2 < e1 (geometric convergence), else e2; at least 2^-24 max |T| (the float rounding of the
   table); the max over the samples. Measured against an independent long-double projection
   (GGX alpha 0.01 .. 1, Phong 1000, theta_o 30 .. 89.5 deg, q 32 .. 128): 0.65 .. 5.5 times
   the true error (docs/brdf-tables.md; 0.77 .. 1.8 for the half-vector rule, which sits at
   the float floor); not a guaranteed bound. Accuracy (n = 9, against an
   independent long-double projection and q = 256): isotropic GGX reaches the float rounding
   floor at q = 24 for every alpha in [1e-3, 4] and theta_o up to cos theta_o = 1e-6, Beckmann
   at q = 24 for alpha <= 1 and q = 48 up to alpha 4 (q = 32: 8e-8), Blinn-Phong at q = 16 up
   to e = 1e6, Phong at q = 32 up to e = 1e6; anisotropic Beckmann / GGX (the specular-frame rule)
   reach it at q = 128 for max(alpha) >= 0.05 and do not converge near grazing below that
   (docs/brdf-tables.md). quad_order in [2, 256]. Returns SHLIGHT_EINVAL (data untouched) for NULL t
   / data / brdf, n, n_theta, n_phi out of range (see shl_brdf_table_size), flags != (n_phi > 1 ?
   ANISO : 0), an unknown model, negative or non-finite kd / ks, a Phong / Blinn-Phong exponent
   outside [0, SHLIGHT_BRDF_MAX_EXPONENT] (larger ones, up to 1e27, used to give non-finite tables),
   alpha outside [SHLIGHT_BRDF_MIN_ALPHA, 4] for Beckmann / GGX, f0 outside [0, 1] (microfacet
   models), quad_order out of range; SHLIGHT_ENOMEM when n > 16 and the 2 n^2-double accumulator (on
   the stack up to 16 bands) cannot be allocated. Cost: per sample, up to ~20 t panels x q x (2q ..
   8q) nodes (isotropic microfacet) or ~12 panels x q x (2q .. 14q) (specular frame), x 1.31 with
   out_err_est, each node one BRDF evaluation, one shl_sh_eval and 2 n^2 FMA. Measured, 90 samples,
   n = 9, one core of a loaded machine: GGX q = 16 0.18 s (alpha 1) .. 0.27 s (alpha 1e-3), q = 32
   0.75 .. 1.1 s; Phong 1000 q = 32 0.55 s. */
SHLIGHT_API shl_result shl_brdf_table_build(shl_brdf_table *t, const shl_brdf_params *brdf,
                                            int quad_order, float *out_err_est);

/* shl_brdf_table_theta: theta_o (radians) of sample t of an n_theta-sample table (the grid of
   >>brdftab: 0 at t = 0, pi/2 at t = n_theta - 1; n_theta = 1: 0), float-rounded from a double
   bisection of the grid variable. -1 for n_theta outside [1, SHLIGHT_BRDF_TABLE_MAX_SAMPLES] or
   t outside [0, n_theta). Cost: ~60 iterations of one log. */
SHLIGHT_API float shl_brdf_table_theta(int n_theta, int t);

/* shl_brdf_table_write: the SHLT file of t into buf (capacity cap bytes); *out_len (may not be
   NULL) = its length, 40 + 4 x shl_brdf_table_size bytes. Format version 2 (little-endian):
     0  "SHLT"                4  uint32 version (2)       8  int32 bands n
     12 int32 n_theta         16 int32 n_phi              20 uint32 flags
     24 uint32 payload floats (= n_phi n_theta 2 n^2)     28 uint32 grid (1: the outgoing
        grid of >>brdftab)    32 uint32 reserved (0)      36 uint32 CRC-32 (IEEE 802.3,
        reflected, as zlib's crc32) of bytes 0..35 followed by the payload
     40 payload: the table's data, float32 little-endian, in the >>brdftab layout.
   (Version 1, 32-byte header, no grid field, sampled theta_o at cell centres; not written.)
   Returns SHLIGHT_EINVAL for NULL t / t->data / out_len or an invalid table (dims, flags),
   SHLIGHT_ENONFINITE for a NaN / Inf in the data (nothing written), SHLIGHT_ESTORAGE (with
   *out_len set) when buf is NULL or cap too small. Cost: one pass over the data. */
SHLIGHT_API shl_result shl_brdf_table_write(const shl_brdf_table *t, void *buf, size_t cap,
                                            size_t *out_len);

/* shl_brdf_table_read: parses an SHLT file of len bytes at buf into *out, the payload copied to
   storage (storage_floats floats; out->data = storage). Checks, in this order, each with its
   error: len < 8: SHLIGHT_ELENGTH; magic: SHLIGHT_EMAGIC; version other than 2 (version 1
   files hold the cell-centred grid of earlier releases, which the lookup no longer reads:
   rebuild them): SHLIGHT_EVERSION; len < 40: SHLIGHT_ELENGTH; n, n_theta, n_phi out of
   range, flags inconsistent with n_phi or with unknown bits, payload floats != n_phi n_theta
   2 n^2, grid != 1 or reserved != 0: SHLIGHT_EDIMS; len != 40 + 4 x payload floats:
   SHLIGHT_ELENGTH (truncated, or trailing bytes); CRC: SHLIGHT_ECHECKSUM; a NaN / Inf payload
   float: SHLIGHT_ENONFINITE; storage NULL or storage_floats too small: SHLIGHT_ESTORAGE, with
   out->n, n_theta, n_phi, flags set and out->data NULL, so that a caller can call with (NULL, 0) to
   learn the size. NULL out or buf: SHLIGHT_EINVAL. Never reads outside [buf, buf + len) or writes
   outside storage; on any error storage is untouched. Cost: two passes over the payload. */
SHLIGHT_API shl_result shl_brdf_table_read(const void *buf, size_t len, float *storage,
                                           size_t storage_floats, shl_brdf_table *out_table);

/* shl_merl_read: parses a MERL binary BRDF of len bytes at buf (int32 n_theta_h, n_theta_d,
   n_phi_d little-endian, then 3 x their product float64 little-endian: red, green, blue, each
   [theta_h][theta_d][phi_d]) into *out, the samples scaled and stored as floats in storage
   (storage_floats floats). Errors, in this order: len < 12: SHLIGHT_ELENGTH; a dimension < 1
   or > SHLIGHT_MERL_MAX_DIM: SHLIGHT_EDIMS; len != 12 + 24 x product: SHLIGHT_ELENGTH; a NaN /
   Inf sample (or one beyond float range once scaled): SHLIGHT_ENONFINITE; storage NULL / too small:
   SHLIGHT_ESTORAGE (out's dims set, out->data NULL); NULL out / buf: SHLIGHT_EINVAL. Never reads
   outside the buffer; storage untouched on error. Cost: two passes over the samples. */
SHLIGHT_API shl_result shl_merl_read(const void *buf, size_t len, float *storage,
                                     size_t storage_floats, shl_merl *out_merl);

/* shl_merl_eval: channel c (0 red, 1 green, 2 blue) of the measured BRDF at (wo, wi) (unit,
   local frame; 0 when either z <= 0): the half-diff angles of [MPBM03] (theta_h, theta_d,
   phi_d folded to [0, pi) by reciprocity), index coordinates u_h = sqrt(theta_h / (pi/2)) n_theta_h
   (MERL's non-linear theta_h index), u_d = theta_d / (pi/2) n_theta_d, u_p = phi_d / pi n_phi_d,
   sample i at coordinate i (MERL's convention: the index is the floor of the coordinate),
   trilinear between samples (clamped at the ends of theta_h and theta_d, periodic in phi_d).
   Reconstruction (for grazing directions): the trilinear interpolant is of f cos(theta_h)
   cos(theta_d) = f (cos_i + cos_o) / 2, divided by the query's factor (floored at 1e-6), so
   that the 1 / (cos_i + cos_o) growth of f at grazing is carried by the factor; only valid
   samples (> 0; MERL marks invalid ones negative) enter the sum, their weights renormalised
   to 1; beyond the last theta_d sample, linear extrapolation from the last two layers when
   their 8 samples are valid, else the last layer held; a cell without any valid sample takes
   the nearest theta_d layer below that has one (held along theta_d); 0 if none.
   Invalid m or c: 0. Cost: ~100 flops, 2 acos, 2 atan2. */
SHLIGHT_API float shl_merl_eval(const shl_merl *m, int c, const float wo[3], const float wi[3]);

/* shl_brdf_table_build_merl: shl_brdf_table_build for channel c of a measured BRDF (tables
   must be isotropic: n_phi = 1, flags 0): the whole BRDF by the specular-frame quadrature,
   lobe width 0.1 rad. Errors as shl_brdf_table_build (EINVAL also for an invalid m / c). */
SHLIGHT_API shl_result shl_brdf_table_build_merl(shl_brdf_table *t, const shl_merl *m, int c,
                                                 int quad_order, float *out_err_est);

/* ================================================================================================
   END OF THE API: stop here if you only want the API. The implementation follows.
   ================================================================================================
 */

/* >>numerics --------------------------------------------------------------------------------
   Domains and degenerate inputs (each has a named test in tests/):
   - shl_sh_eval: d unit to float precision is evaluated as given (the kernel corrects the
     |d| - 1 ~ 1e-7 of float normalisation to second order); any other finite non-zero d is
     normalised first; zero, NaN or infinite d gives Y(0,0,1).
   - shl_sh_eval_accurate, shl_sh_eval_grad, shl_sh_eval_grad_spherical: any finite d != 0,
     from denormals to FLT_MAX (the input is scaled by its largest component first). Zero,
     NaN or infinite d: the values of d = (0,0,1) and a zero gradient.
   - shl_sh_grad_from_spherical: the Jacobian of the paper ([GRAD] eq. 23) divides by
     sin(theta); at an exact pole (x = y = 0) it returns 0 for every entry.
   - n < 1: nothing is written. n > SHLIGHT_MAX_BANDS: taken as SHLIGHT_MAX_BANDS. Debug and
     release builds behave the same (no assertion).
   Accuracy (float output, max abs error against a binary128 reference, measured by
   tests/test_basis and bench/; docs/accuracy.md has the table): the Legendre part runs in shli_real
   (double in C, float in GLSL) with a Reinsch-type modified recurrence in t = 1 - |z|, which
   keeps the error growth linear in l at the poles instead of quadratic.
*/

/* >>prelude ---------------------------------------------------------------------------------
   The kernels' bodies are shared with GLSL; they do math only through these macros, which
   shlight_glsl/shl_prelude.glsl defines for GLSL. shli_real is the internal precision. */
#include <math.h>
#include <stddef.h>
#include <string.h>
typedef double shli_real;
#define SHLIGHT_FLOAT(x) ((float)(x))
#define SHLIGHT_REAL(x) ((shli_real)(x))
#define SHLIGHT_ITOF(i) ((float)(i))
#define SHLIGHT_SQRTR(x) sqrt(x)
#define SHLIGHT_ABSR(x) fabs(x)
#define SHLIGHT_REAL_MAX 3.4028234663852886e38
#define SHLIGHT_REAL_WIDE 1 /* shli_real holds squares of any float: no input scaling needed */
#define SHLIGHT_UNUSED(x) ((void)(x))
/* 1 (GLSL): zeroing an output array by constant-trip per-band code, which shader compilers keep
   in registers; 0 (C): the plain loop */
#define SHLIGHT_BY_BANDS 0
#define SHLIGHT_SET3(o, a, b, c)                                                                   \
  ((o)[0] = (a), (o)[1] = (b), (o)[2] = (c))         /* GLSL: o = vec3(a, b, c) */
#define SHLIGHT_SIGN1(x) ((float)copysign(1.0, (x))) /* +-1 with the sign bit of x, branch-free */
#define SHLIGHT_FTOI(x) ((int)(x))                   /* truncation toward zero, as GLSL int() */
#define SHLIGHT_ITOR(i) ((shli_real)(i))
#define SHLIGHT_MAXR(a, b) ((a) > (b) ? (a) : (b))
#define SHLIGHT_MINR(a, b) ((a) < (b) ? (a) : (b))
#define SHLIGHT_EXPR(x) exp(x)
#define SHLIGHT_LOGR(x) log(x)
#define SHLIGHT_SINR(x) sin(x)
#define SHLIGHT_COSR(x) cos(x)
#define SHLIGHT_POWR(x, y) pow((x), (y)) /* x >= 0 only (GLSL pow) */
#define SHLIGHT_SQRTF(x) sqrtf(x)
#define SHLIGHT_ABSF(x) fabsf(x)
/* the FAST edge method's transcendentals: shlight's own branch-free polynomials in C (>>edge),
   the built-ins in GLSL */
#define SHLIGHT_FATAN2(y, x) shli_fatan2((y), (x))
#define SHLIGHT_FSIN(x) shli_fsin(x)
#define SHLIGHT_FSQRT(x) shli_fsqrt(x)
#define SHLIGHT_FLOG1P(x) shli_flog1p(x)
#define SHLIGHT_FEXP(x) shli_fexp(x)
#define SHLIGHT_POLYGON_ANY 1 /* C: any nv >= 3 (fan pieces); GLSL 0: above the max gives -1 */
#define SHLIGHT_CLIP_MAX 20   /* after two plane clips of a non-convex 8-gon (<= 2.25 nv) */
#define SHLIGHT_EDGE_STOKES_ADAPT 105 /* internal: EXACT's adaptive Stokes rule */
#define SHLIGHT_ADAPT_LEVELS 7        /* its most halvings (128 panels of 5 nodes per half-arc) */
#define SHLIGHT_ADAPT_TOL 1.0e-9      /* its stop: two successive levels this close (GLSL 2e-6) */
#define SHLIGHT_EDGE_FAST_ON                                                                       \
  1                     /* GLSL: 0 unless the host defines it (compile cost, docs/accuracy.md) */
#define SHLIGHT_LANES 8 /* edges per block of the FAST edge loop (GLSL: 1) */
#define SHLIGHT_FAST_PAD (SHLIGHT_CLIP_MAX + SHLIGHT_LANES)
#define SHLIGHT_HALF_K                                                                             \
  8 /* sub-edges per light edge in half-vector space (shl_polygon_blinn_phong) */

/* >>basis -----------------------------------------------------------------------------------
   Real SH basis of n bands at a unit direction. Straight-line code for n <= 16 (generated by
   tools/gen_basis.py: constants folded, no loops or tables), a table-driven loop above. */

/* The band count the kernels work with: n in [1, SHLIGHT_MAX_BANDS] as given; n > max is
   clamped to max and n < 1 gives 0 (the kernels then write nothing), in debug and release
   builds alike. */
SHLIGHT_INLINE int shli_bands(int n) {
  if (n > SHLIGHT_MAX_BANDS) {
    return SHLIGHT_MAX_BANDS;
  }
  if (n < 1) {
    return 0;
  }
  return n;
}

/* @generated begin sh_tab */
/* clang-format off */
static const shli_real SHLI_SH_TAB[6048] = {
  1.7320508075688772, 1.7320508075688772, 0.0, 1.9364916731037085,
  1.2909944487358056, 0.6454972243679029, 2.23606797749979, 2.23606797749979,
  0.0, 1.9720265943665387, 1.1832159566199232, 0.7888106377466155,
  2.091650066335189, 1.673320053068151, 0.4183300132670377, 2.6457513110645907,
  2.6457513110645907, 0.0, 1.984313483298443, 1.133893419027682,
  0.8504200642707612, 2.04939015319192, 1.4638501094228, 0.5855400437691199,
  2.29128784747792, 1.9639610121239315, 0.32732683535398854, 3.0,
  3.0, 0.0, 1.98997487421324, 1.1055415967851334,
  0.8844332774281064, 2.03100960115899, 1.3540064007726604, 0.6770032003863299,
  2.1712405933672376, 1.6887426837300736, 0.48249790963716394, 2.48746859276655,
  2.2110831935702664, 0.2763853991962833, 3.3166247903554, 3.3166247903554003,
  0.0, 1.9930434571835665, 1.0871146130092184, 0.9059288441743482,
  2.0213149892370277, 1.2862913567871994, 0.7350236324498282, 2.1139418156609704,
  1.5374122295716148, 0.5765295860893556, 2.301368353023109, 1.882937743382544,
  0.4184306096405653, 2.6739483914241875, 2.4308621740219887, 0.24308621740219885,
  3.605551275463989, 3.605551275463989, 0.0, 1.9948914348241344,
  1.0741723110591497, 0.9207191237649848, 2.0155644370746373, 1.2403473458920844,
  0.7752170911825529, 2.0816659994661326, 1.4411533842457838, 0.6405126152203485,
  2.207940216581962, 1.698415551216894, 0.5095246653650679, 2.4308621740219887,
  2.0568833780186058, 0.37397879600338285, 2.850438562747845, 2.6311740579210876,
  0.21926450482675733, 3.872983346207417, 3.8729833462074166, 0.0,
  1.996089927833914, 1.0645812948447546, 0.9315086329891595, 2.011869540407391,
  1.2071217242444345, 0.8047478161629565, 2.0615528128088303, 1.3743685418725533,
  0.687184270936277, 2.15322168769582, 1.5790292376436015, 0.5741924500522186,
  2.3048861143232218, 1.8439088914585773, 0.4609772228646444, 2.557041559783794,
  2.216102685145955, 0.34093887463783923, 3.017804310611087, 2.816617356570348,
  0.20118695404073914, 4.123105625617661, 4.123105625617661, 0.0,
  1.9969111950679366, 1.0571882797418493, 0.9397229153260873, 2.0093531297410117,
  1.1819724292594185, 0.8273807004815933, 2.048122358357819, 1.325255643643295,
  0.7228667147145245, 2.1180441711898057, 1.495090003192804, 0.6229541679970017,
  2.229177150706235, 1.7046648799518267, 0.5245122707544083, 2.401636346922061,
  1.9778181680534621, 0.423818178868599, 2.679137506321349, 2.363944858518838,
  0.31519264780251166, 3.1770662567847086, 2.990180006385608, 0.18688625039910048,
  4.358898943540674, 4.358898943540674, 0.0, 1.997498435543818,
  1.0513149660756942, 0.9461834694681237, 2.0075614636426526, 1.1622724263194302,
  0.8452890373232224, 2.038688303787511, 1.2875926129184283, 0.751095690869083,
  2.0939473213563384, 1.4327007988227578, 0.6612465225335805, 2.179449471770337,
  1.6059101370939326, 0.5735393346764045, 2.3065125189341593, 1.820930936000652,
  0.4855815829335072, 2.496873044429772, 2.102629932151387, 0.39424311227838504,
  2.7970572771691153, 2.50263019536184, 0.29442708180727534, 3.3291640592396967,
  3.1539448982270817, 0.1752191610126156, 4.58257569495584, 4.58257569495584,
  0.0, 1.9979328159850827, 1.0465362369445674, 0.9513965790405152,
  2.006240264773888, 1.1464230084422218, 0.8598172563316665, 2.031798495964875,
  1.2577800213115895, 0.7740184746532857, 2.0766559657295187, 1.3844373104863459,
  0.6922186552431729, 2.1447610589527217, 1.53197218496623, 0.6127888739864918,
  2.2430448056157952, 1.7089865185644153, 0.5340582870513797, 2.3837686425440854,
  1.9297174725356883, 0.45405117000839723, 2.5900450446533423, 2.220038609702865,
  0.37000643495047747, 2.910959328215754, 2.63372510648092, 0.2772342217348337,
  3.4749100707788108, 3.309438162646486, 0.16547190813232432, 4.795831523312719,
  4.795831523312719, 0.0, 1.998263134713633, 1.042572070285374,
  0.9556910644282591, 2.0052378963551982, 1.1333953327225033, 0.8718425636326949,
  2.026608708444444, 1.2335879094879225, 0.7930207989565214, 2.0637972912229676,
  1.3459547551454134, 0.717842536077554, 2.1194781197266463, 1.4744195615489715,
  0.6450585581776749, 2.1981657747106436, 1.624731224786128, 0.5734345499245157,
  2.307395517477243, 1.805787796286538, 0.501607721190705, 2.460209661583209,
  2.032347111742651, 0.4278625498405581, 2.680951323690902, 2.3312620206007844,
  0.34968930309011775, 3.021089890583219, 2.7583864218368523, 0.2627034687463669,
  3.614994027406106, 3.4578203740406233, 0.1571736533654829, 5.0,
  5.0, 0.0, 1.998520162579474, 1.039230484541327,
  0.9592896780381471, 2.004459314343183, 1.1224972160321822, 0.8819620983110006,
  2.0225995873897262, 1.213559752433836, 0.8090398349558905, 2.053959590644373,
  1.3145341380123985, 0.7394254526319745, 2.100420126042015, 1.4282856857085702,
  0.6721344403334446, 2.165063509461097, 1.5588457268119897, 0.606217782649107,
  2.252817784447915, 1.7121415161804154, 0.5406762682674995, 2.3717082451262845,
  1.8973665961010275, 0.47434164902525694, 2.53546276418555, 2.129788721915862,
  0.40567404226968795, 2.7695585470349866, 2.437211521390789, 0.3323470256441984,
  3.1277162108561214, 2.8774989139876315, 0.2502172968684897, 3.75,
  3.6, 0.15, 5.196152422706632, 5.196152422706632,
  0.0, 1.9987240828047461, 1.036375450343202, 0.9623486324615438,
  2.0038424627162224, 1.1132458126201232, 0.890596650096099, 2.019436802675439,
  1.1967032904743342, 0.8227335122011046, 2.0462565272714635, 1.2883837393931434,
  0.7578727878783199, 2.085665361461421, 1.390443574307614, 0.6952217871538069,
  2.1398475105532757, 1.5058186185374902, 0.6340288920157854, 2.212182180562894,
  1.638653467083625, 0.5735287134792688, 2.307927774486216, 1.795054935711501,
  0.5128728387747147, 2.435532422657966, 1.9845078999435284, 0.4510245227144381,
  2.6093477445855915, 2.2227777083506894, 0.3865700362349023, 2.8559149146989657,
  2.5385910352879693, 0.3173238794109962, 3.2310988842807022, 2.9917582261858353,
  0.23934065809486682, 3.880424243261593, 3.7367048268444973, 0.14371941641709604,
  5.385164807134504, 5.385164807134504, 0.0, 1.9988885800753267,
  1.0339078862458588, 0.9649806938294676, 2.003345416333104, 1.105294022804471,
  0.8980513935286331, 2.0168969490698876, 1.1823189011788997, 0.834578047890988,
  2.040107114108727, 1.2662733811709337, 0.773833732937793, 2.0739902137422357,
  1.3588211745207752, 0.7151690392214606, 2.120141504711419, 1.4621665549733924,
  0.6579749497380267, 2.1809662438042814, 1.5793203834444796, 0.6016458603598018,
  2.260078437898682, 1.7145422632334826, 0.5455361746651991, 2.363017336304797,
  1.874117197758977, 0.48890013854582, 2.4986107250941583, 2.067815772491717,
  0.430794952602441, 2.6817904466978773, 2.3118883161188597, 0.3699021305790176,
  2.9401072717216916, 2.635958243612551, 0.3041490281091405, 3.331480966792211,
  3.101723658737576, 0.2297573080546352, 4.006690832666208, 3.868529079815649,
  0.1381617528505589, 5.5677643628300215, 5.5677643628300215, 0.0,
  1.9990231989649345, 1.0317539091431922, 0.9672692898217423, 2.002939017015334,
  1.098385912556796, 0.9045531044585381, 2.014825999813336, 1.16989896763355,
  0.844927032179786, 2.035116803738375, 1.2473296539041652, 0.7877871498342097,
  2.064582282206258, 1.331988569165328, 0.7325937130409301, 2.104417123236605,
  1.4255728899344744, 0.6788442333021306, 2.1563858652847827, 1.5303383560085555,
  0.6260475092762272, 2.2230674720995864, 1.6493726405900155, 0.5736948315095708,
  2.3082731640774234, 1.787050191543812, 0.5212229725336118, 2.4177911997760035,
  1.9498316127225837, 0.46795958705341995, 2.5607991541103545, 2.1477670324796523,
  0.41303212163070235, 2.7527763762750106, 2.39757942449759, 0.3551969517774207,
  3.0222389997200043, 2.7297642578116172, 0.2924747419083875, 3.4290845264669656,
  3.207853266694903, 0.2212312597720623, 4.129164564412516, 3.995965707495983,
  0.13319885691653277, 5.744562646538029, 5.744562646538029, 0.0,
  1.999134760937227, 1.0298573010888745, 0.9692774598483522, 2.002602473449653,
  1.0923286218816286, 0.910273851568024, 2.013114894621608, 1.1590661514488048,
  0.8540487431728034, 2.03100960115899, 1.2309149097933276, 0.8000946913656628,
  2.0568833780186058, 1.3089257860118402, 0.7479575920067656, 2.091650066335189,
  1.3944333775567925, 0.6972166887783963, 2.1366369348357592, 1.4891711970067414,
  0.6474657378290178, 2.1937410968480306, 1.5954480704349314, 0.5982930264130993,
  2.265686062395524, 1.7164288351481245, 0.5492572272473997, 2.356455943866682,
  1.8566016527434466, 0.49985429112323554, 2.4720661623652207, 2.022599587389726,
  0.4494665749754947, 2.622022120425379, 2.2247460415730487, 0.39727607885233013,
  2.822324793743504, 2.4802248187442912, 0.3420999749992125, 3.1024184114977142,
  2.8203803740888307, 0.2820380374088831, 3.5241105031922135, 3.3105280484532913,
  0.21358245473892204, 4.248161366991607, 4.119429204355498, 0.12873216263610932,
  5.916079783099616, 5.916079783099616, 0.0, 1.9992282461607314,
  1.0281745265969477, 0.9710537195637837, 2.0023206350873464, 1.0869740590474166,
  0.9153465760399299, 2.011684617428885, 1.14953406710222, 0.862150550326665,
  2.0275875100994063, 1.216552506059644, 0.8110350040397624, 2.050498830661811,
  1.2888849792731385, 0.7616138513886725, 2.081130384894172, 1.3675999672161698,
  0.713530417678002, 2.120501774999912, 1.4540583599999402, 0.6664434149999723,
  2.170043987823959, 1.5500314198742564, 0.6200125679497024, 2.231763704062155,
  1.6578816087318868, 0.5738820953302683, 2.3085099321848035, 1.7808505191139916,
  0.5276594130708121, 2.404423007708918, 1.9235384061671341, 0.48088460154178375,
  2.5257296658248256, 2.092747437397713, 0.432982228427113, 2.6822461565718467,
  2.29906813420444, 0.38317802236740667, 2.8904737863674566, 2.5601339250683184,
  0.3303398612991379, 3.1807526624998683, 2.90811671999988, 0.27263594249998874,
  3.616739979706598, 3.4100691237233645, 0.20667085598323412, 4.363956650455962,
  4.239272174728649, 0.1246844757273132, 6.082762530298219, 6.082762530298219,
  0.0, 1.9993073592865873, 1.0266713466606803, 0.9726360126259072,
  2.0020822493927, 1.0822066212933512, 0.9198756280993486, 2.0104767610501466,
  1.1410814049203533, 0.8693953561297932, 2.024705365770985, 1.2038788661340993,
  0.8208264996368858, 2.045142707894042, 1.2713049265287286, 0.773837781365313,
  2.0723520109148583, 1.344228331404232, 0.7281236795106262, 2.1071307505705477,
  1.4237369936287485, 0.683393756941799, 2.1505813167606567, 1.5112193036696506,
  0.6393620130910059, 2.2042200113840402, 1.6084848731721375, 0.5957351382119027,
  2.27014788693852, 1.7179497522777991, 0.552198134660721, 2.351326355949745,
  1.8429314681768267, 0.508394887772918, 2.452039967047846, 1.9881405138225778,
  0.46389945322526804, 2.5787147157554005, 2.1605447618491196, 0.41816995390628114,
  2.7414640249326636, 2.3709959134552765, 0.37046811147738695, 2.957271469692045,
  2.637566445941553, 0.31970502375049126, 3.2573446421352252, 2.993235617097234,
  0.26410902503799116, 3.7071359757712075, 3.5067502473511425, 0.20038572842006527,
  4.476792006187765, 4.355797627642149, 0.12099437854561525, 6.244997998398398,
  6.244997998398398, 0.0, 1.9993749023132206, 1.0253204627247288,
  0.9740544395884919, 2.0018788167600157, 1.077934747486162, 0.9239440692738535,
  2.0094473837049796, 1.1335344215771679, 0.8759129621278119, 2.0222546987202583,
  1.1926117453991267, 0.8296429533211316, 2.0406034646643136, 1.2557559782549623,
  0.7848474864093514, 2.064945519862449, 1.3236830255528518, 0.7412624943095973,
  2.0959143930173156, 1.3972762620115438, 0.6986381310057719, 2.1343747458109497,
  1.477644054792196, 0.6567306910187537, 2.181496864867922, 1.5662028773410723,
  0.6152939875268497, 2.2388700687965297, 1.6648008203871627, 0.5740692484093667,
  2.3086792761230392, 1.7759071354792608, 0.5327721406437784, 2.393988887964797,
  1.9029142442797105, 0.49107464368508646, 2.499218627891526, 2.050640925449457,
  0.4485777024420686, 2.630984211674012, 2.22621740987801, 0.4047668017960019,
  2.7996848562146504, 2.440750900289695, 0.3589339559249552, 3.0227707252027662,
  2.712742958515303, 0.31002776668746324, 3.3322915038553673, 3.075961388174185,
  0.25633011568118214, 3.7954453500749294, 3.6008071269941637, 0.19463822308076564,
  4.586880604965702, 4.469268281761454, 0.11761232320424878, 6.4031242374328485,
  6.4031242374328485, 0.0, 1.9994330262111444, 1.024099842693513,
  0.9753331835176311, 2.0017038197041495, 1.0740849764266163, 0.927618843277533,
  2.0085629048630174, 1.1267548002890095, 0.8818081045740077, 2.0201530928418565,
  1.182528639712306, 0.8376244531295504, 2.036721702667708, 1.2419034772364077,
  0.7948182254313005, 2.0586356572329083, 1.3054762704403806, 0.7531593867925276,
  2.0864051427642445, 1.3739741184057221, 0.7124310243585225, 2.12071897704336,
  1.4482958867613192, 0.672423090282041, 2.16249683767267, 1.529570933963596,
  0.6329259037090739, 2.212966837126626, 1.6192440271658237, 0.5937228099608023,
  2.2737827461170492, 1.719201588527525, 0.5545811575895242, 2.3472057856097748,
  1.831965491207629, 0.5152402944021457, 2.4363963011027034, 1.961001900887542,
  0.47539440021516166, 2.545902128334635, 2.1112359113018924, 0.4346662170327426,
  2.6825208978397423, 2.289956864009536, 0.3925640338302062, 2.8569279019669076,
  2.5085220602636262, 0.3484058417032814, 3.0870260332121804, 2.7858527616792843,
  0.3011732715328957, 3.405684103161407, 3.1564877053691087, 0.24919639779229807,
  3.8818006219248393, 3.6924444940260663, 0.18935612789877262, 4.6944115712195496,
  4.579913728019073, 0.11449784320047683, 6.557438524302, 6.557438524302,
  0.0, 1.9994834043566154, 1.0229915092057102, 0.9764918951509052,
  2.0015521927055073, 1.0705976844703875, 0.93095450823512, 2.0077973005261263,
  1.1206310514564422, 0.8871662490696839, 2.0183369913189213, 1.1734517391389077,
  0.8448852521800138, 2.0333753673671238, 1.2294827802684938, 0.8038925870986299,
  2.053213645607735, 1.2892271728234614, 0.7639864727842736, 2.0782676508504454,
  1.3532905633444765, 0.7249770875059691, 2.109093611499728, 1.422411970546328,
  0.6866816409533998, 2.1464256001881026, 1.497506232689374, 0.6489193674987286,
  2.1912299819386596, 1.5797239404674057, 0.6115060414712539, 2.2447856245084963,
  1.6705381391691134, 0.5742474853393827, 2.3088045634909626, 1.771873269655855,
  0.5369312938351075, 2.385618676693372, 1.8863031397110381, 0.4993155369823337,
  2.4784787961282104, 2.0173664619648224, 0.4611123341633879, 2.592055169165965,
  2.170092699766854, 0.42196246939911064, 2.733320777194377, 2.3519271803765567,
  0.38139359681782, 2.9132185131333963, 2.574472174396955, 0.3387463387364415,
  3.1500915737605033, 2.857059799457201, 0.29303177430330263, 3.477606935810889,
  3.234983196103152, 0.24262373970773646, 3.9663216356056115, 3.781841559530932,
  0.1844800760746796, 4.799553550666383, 4.687936026232281, 0.11161752443410194,
  6.708203932499369, 6.708203932499369, 0.0, 1.9995273543594643,
  1.0219806477837263, 0.9775467065757381, 2.0014199504806127, 1.06742397358966,
  0.9339959768909527, 2.007130147392398, 1.1150723041068873, 0.8920578432855105,
  2.0167567261094463, 1.1652372195299023, 0.8515195065795441, 2.0304696544257586,
  1.2182817926554552, 0.8121878617703032, 2.0485186285285693, 1.2746338133066653,
  0.7738848152219039, 2.071246207462304, 1.3348031114757075, 0.7364430959865967,
  2.099106952968333, 1.399404635312222, 0.6997023176561111, 2.13269479691169,
  1.4691897489836088, 0.6635050479280812, 2.1727821204292765, 1.5450895078608187,
  0.6276926125684577, 2.2203760785213684, 1.6282757909156704, 0.5921002876056983,
  2.2768011615887245, 1.7202497665337027, 0.5565513950550215, 2.3438230508096156,
  1.8229734839630343, 0.5208495668465812, 2.4238399287081647, 1.9390719429665317,
  0.48476798574163293, 2.520188753119764, 2.0721551970095837, 0.44803355611018036,
  2.637657453519176, 2.2273551829717486, 0.41030227054742735, 2.7833887165203404,
  2.412270220984295, 0.37111849553604537, 2.968585521759479, 2.6387426860084258,
  0.3298428357510532, 3.212020107460678, 2.926507209019729, 0.28551289844094924,
  3.5481383448627977, 3.311595788538611, 0.2365425563241865, 4.049117044147934,
  3.8691562866302482, 0.17996075751768598, 4.9024576397038775, 4.793514136599347,
  0.10894350310453059, 6.855654600401044, 6.855654600401044, 0.0,
  1.9995659251169713, 1.0210549404852622, 0.978510984631709, 2.001303922772438,
  1.0645233631768287, 0.9367805595956094, 2.006545234033805, 1.1100037464867856,
  0.8965414875470195, 2.0153730163574504, 1.1577674774819393, 0.8576055388755108,
  2.027929979067325, 1.2081284981677678, 0.8198014808995567, 2.0444249365614087,
  1.2614536842612945, 0.7829712523001141, 2.0651428073658282, 1.3181762600207418,
  0.7469665473450866, 2.09045903459792, 1.3788134057986283, 0.711645628799292,
  2.120859937619644, 1.443989744762311, 0.6768701928573331, 2.1569713147200757,
  1.51446922097367, 0.6425020937464057, 2.1995988939162627, 1.5911991998543178,
  0.6083996940619449, 2.2497863146393398, 1.6753727874973807, 0.5744135271419591,
  2.3088998502573728, 1.7685190342396897, 0.540380816017683, 2.3787552750286562,
  1.872637131405538, 0.5061181436231184, 2.461813623284564, 1.9904025039322009,
  0.47141111935236335, 2.561494400004334, 2.125495353195086, 0.4359990468092483,
  2.682699200432281, 2.2831482556870477, 0.3995509447452333, 2.8327354701599723,
  2.4711096654586995, 0.3616258047012731, 3.0230595245361758, 2.7014574474578588,
  0.3216020770783166, 3.272862341586756, 2.994320865707032, 0.27854147587972394,
  3.6173508639233867, 3.3864561279282768, 0.2308947359951098, 4.1302856147316565,
  3.9545287800622244, 0.17575683466943218, 5.003259806931095, 4.896807470613412,
  0.10645233631768287, 7.0, 7.0, 0.0,
  1.999599959991998, 1.0202040612204075, 0.9793958987715905, 2.0012015621390296,
  1.0618620533798933, 0.9393395087591363, 2.0060295584492223, 1.1053632260842654,
  0.9006663323649569, 2.0141544582822295, 1.1509454047327023, 0.8632090535495271,
  2.0256969852033815, 1.1988818892020014, 0.8268150960013803, 2.040833163195855,
  1.2494896917525642, 0.7913434714432909, 2.0598020245415825, 1.3031400563426339,
  0.7566619681989486, 2.0829166249916646, 1.3602720816272096, 0.722644543364455,
  2.1105794120443453, 1.4214106244380287, 0.6891687876063168, 2.143303524935281,
  1.4871902009755011, 0.65611332395978, 2.181742422927143, 1.558387444947959,
  0.6233549779791837, 2.226731535981231, 1.6359660264351903, 0.5907655095460409,
  2.279347756579982, 1.72114014272366, 0.5582076138563221, 2.3409961892097852,
  1.8154664324484047, 0.5255297567613804, 2.413539895086639, 1.9209807328240596,
  0.4925591622625794, 2.4994999499899975, 2.0404081224408146, 0.4590918275491831,
  2.6023754002021375, 2.177497783842605, 0.4248776163595327, 2.7271780286589284,
  2.337581167421938, 0.3895968612369898, 2.881375640452898, 2.5285541334586656,
  0.3528215069942325, 3.076671755470364, 2.7627256579733883, 0.31394609749697594,
  3.3326665999866636, 3.0606121836612217, 0.2720544163254419, 3.685311620355928,
  3.459680296660667, 0.22563132369526093, 4.209917369179489, 4.038084007172163,
  0.17183336200732605, 5.1020829079896375, 4.997958767010257, 0.10412414097938037,
  7.14142842854285, 7.14142842854285, 0.0, 1.9996301433163013,
  1.0194192887494873, 0.980210854566814, 2.0011108026404845, 1.0594116013979036,
  0.9416992012425809, 2.005572593692741, 1.1010986788901327, 0.9044739148026085,
  2.0130756973145445, 1.1446901023945448, 0.8683855949199999, 2.023722941870884,
  1.1904252599240497, 0.8332976819468345, 2.0376637928566366, 1.2385799525207006,
  0.799083840335936, 2.055100362512741, 1.289474737262896, 0.7656256252498448,
  2.0762959289776095, 1.343485601103159, 0.7328103278744504, 2.101586702153082,
  1.4010578014353883, 0.7005289007176939, 2.1313979316066587, 1.462724070710452,
  0.6686738608962066, 2.16626598859266, 1.5291289331242306, 0.6371370554684294,
  2.2068688837967403, 1.6010617392250859, 0.6058071445716542, 2.2540690024196626,
  1.6795023939597482, 0.5745666084599139, 2.3089740030467127, 1.7656860023298389,
  0.5432880007168738, 2.373025495016857, 1.8611964666798877, 0.5118290283369692,
  2.4481315559624925, 1.9681057606757295, 0.4800257952867632, 2.5368709635522038,
  2.0891878523371092, 0.44768311121509474, 2.642819729764217, 2.2282597721541433,
  0.4145599576100733, 2.771096763508498, 2.3907501489092926, 0.38034661459920566,
  2.92932626741242, 2.584699647716841, 0.3446266196955788, 3.129453348568974,
  2.8226441967484868, 0.3068091518204876, 3.391478683343663, 3.1254803552382775,
  0.2659983281053854, 3.7520827549509086, 3.5313720046596786, 0.2207107502912299,
  4.288094577086753, 4.119934005436291, 0.16816057165046092, 5.199038372622383,
  5.097096443747434, 0.10194192887494868, 7.280109889280518, 7.280109889280518,
  0.0, 1.9996570350656429, 1.0186932065428749, 0.9809638285227679,
  2.001029954578611, 1.0571479005320963, 0.9438820540465148, 2.005165742569031,
  1.097166161028338, 0.907999581540693, 2.012116077941606, 1.13893362902355,
  0.8731824489180556, 2.0219691012187377, 1.1826611724109601, 0.8393079288077777,
  2.0348525745124633, 1.2285902336679022, 0.8062623408445609, 2.05093861593886,
  1.276999515584573, 0.773939100354287, 2.0704503630568767, 1.3282134404515813,
  0.7422369226052956, 2.0936710932275253, 1.3826129860936487, 0.7110581071338764,
  2.120956574313453, 1.44064974859027, 0.6803068257231829, 2.152751779136535,
  1.5028644495858832, 0.649887329550652, 2.1896136405167104, 1.5699116667855657,
  0.6197019737311446, 2.2322423665242948, 1.6425934395178772, 0.5896489270064176,
  2.281525179097777, 1.721905795545492, 0.559619383552285, 2.3385985444214192,
  1.8091045343637395, 0.5294940100576799, 2.40493870165752, 1.9058004805587898,
  0.4991382210987306, 2.4824968676061645, 2.014101232208775, 0.46839563539738943,
  2.57390753524675, 2.136828897185981, 0.4370786380607689, 2.6828214372554746,
  2.2778672580471016, 0.4049541792083735, 2.814461876127284, 2.4427404962614165,
  0.3717213798658678, 2.9766058474075248, 2.6396316005312017, 0.33697424687632355,
  3.181434861470179, 2.8812994971805392, 0.3001353642896396, 3.449341847899896,
  3.1890141612659413, 0.26032768663395445, 3.8177218337642147, 3.601624371475675,
  0.2160974622885405, 4.364892619721514, 4.200179690675419, 0.1647129290460949,
  5.2942276258058785, 5.194336538526522, 0.09989108727935621, 7.416198487095663,
  7.416198487095663, 0.0, 1.9996810970242025, 1.0180194675759577,
  0.9816616294482446, 2.000957625144651, 1.0550503841671792, 0.9459072409774715,
  2.0048019276803304, 1.0935283241892713, 0.9112736034910591, 2.011258633374281,
  1.133618502447321, 0.8776401309269594, 2.0204037344055767, 1.1755076272905176,
  0.8448961071150591, 2.032347111742651, 1.2194082670455901, 0.8129388446970606,
  2.047236300622924, 1.2655642585668985, 0.7816720420560256, 2.065261756400137,
  1.3142574813455419, 0.7510042750545954, 2.0866640042581523, 1.3658164391507903,
  0.7208475651073618, 2.1117432276343306, 1.4206272622267315, 0.6911159654075989,
  2.140872096444188, 1.4791479939068937, 0.6617241025372944, 2.1745130000370927,
  1.541927400026302, 0.6325856000107907, 2.2132414012032218, 1.6096301099659795,
  0.6036112912372422, 2.2577778844717558, 1.6830707866062178, 0.5747070978655378,
  2.309032839320659, 1.763261440935776, 0.5457713983848831, 2.3681699644075387,
  1.8514783358095306, 0.5166916285980083, 2.436698586202241, 1.9493588689617924,
  0.48733971724044817, 2.516611478423583, 2.0590457550738406, 0.45756572334974244,
  2.610597133091268, 2.183408511312697, 0.42718862177857103, 2.7223790180154004,
  2.3263966153949784, 0.3959824026204219, 2.857282362665615, 2.4936282437809005,
  0.36365411888471455, 3.0232336480930644, 2.6934263410283665, 0.32980730706469796,
  3.2326459750489227, 2.9387690682262937, 0.29387690682262935, 3.506296856664995,
  3.251293448907541, 0.2550034077574541, 3.882282239175223, 3.6705213897656654,
  0.21176084940955764, 4.440380741791797, 4.278912351181186, 0.16146839061061083,
  5.387743291748205, 5.2897843228073285, 0.09795896894087644, 7.54983443527075,
  7.54983443527075, 0.0, 1.9997027127445488, 1.017392608238455,
  0.982310104506094, 2.000892657933311, 1.053101398912269, 0.9477912590210421,
  2.004475279706239, 1.0901532222963755, 0.9143220574098634, 2.0104893204621375,
  1.128695758855936, 0.8817935616062015, 2.019000652888363, 1.1688951148301052,
  0.850105538058258, 2.0301043149089075, 1.2109394159105762, 0.8191648989983314,
  2.043927530895554, 1.2550432207253401, 0.7888843101702138, 2.0606339124677437,
  1.3014529973480484, 0.7591809151196951, 2.080429121163547, 1.3504539909307232,
  0.7299751302328237, 2.103568396796263, 1.402378931197509, 0.7011894655987543,
  2.1303665267886505, 1.457619202539603, 0.6727473242490476, 2.1612110802356472,
  1.5166393545513313, 0.6445717256843159, 2.1965800991528313, 1.579996211671335,
  0.6165838874814964, 2.237065999409558, 1.648364420617569, 0.588701578791989,
  2.2834083052253473, 1.7225711776261392, 0.5608371275992081, 2.3365392323724383,
  1.8036443197260927, 0.5328949126463456, 2.3976484205817057, 1.8928803320381884,
  0.5047680885435171, 2.4682769910096853, 1.9919428348499215, 0.4763341561597639,
  2.5504579176967366, 2.103009160206081, 0.44744875749065544, 2.646932186513285,
  2.228995525484871, 0.4179366610284134, 2.7614942223615198, 2.3739160858897277,
  0.38757813647179223, 2.8995689334795958, 2.5434815205961367, 0.35608741288345913,
  3.0692292301532142, 2.7461524690844548, 0.3230767610687593, 3.283115312298085,
  2.995122741043867, 0.287992571254218, 3.562382073519887, 3.3123903490623507,
  0.24999172445753592, 3.945813533917238, 3.738139137395278, 0.20767439652195993,
  4.514622706474837, 4.356214892212562, 0.15840781426227496, 5.4796702194827125,
  5.38353565422863, 0.09613456525408268, 7.681145747868608, 7.681145747868608,
  0.0, 1.999722202929419, 1.0168078997946202, 0.9829143031347988,
  2.0008340863641942, 1.051285706394746, 0.949548379969448, 2.0041808978803712,
  1.087013368341896, 0.9171675295384751, 2.009796433957522, 1.1241234291626812,
  0.8856730047948409, 2.01773808219149, 1.1627643185510286, 0.8549737636404617,
  2.0280884736970566, 1.203103331854186, 0.8249851418428706, 2.040957926871414,
  1.2453302604639138, 0.7956276664075003, 2.05648782774514, 1.2896618580774606,
  0.7668259696676796, 2.0748551572206133, 1.336347389396327, 0.7385077678242862,
  2.096278462987061, 1.3856755941778882, 0.710602868809173, 2.1210256952710402,
  1.437983522217654, 0.6830421730533859, 2.1494244983113386, 1.4936678717078795,
  0.6557566266034593, 2.1818758009066443, 1.553199722679306, 0.6286760782273381,
  2.2188719234915513, 1.6171439442396052, 0.6017279792519462, 2.2610209882022123,
  1.6861851437440227, 0.5748358444581896, 2.309080304331543, 1.7611629439816852,
  0.5479173603498577, 2.3640028165740805, 1.8431208400408081, 0.5208819765332722,
  2.427003028192247, 1.933375293644671, 0.4936277345475757, 2.499652753661774,
  2.03361579958924, 0.4660369540725341, 2.584023986516814, 2.1460538193105747,
  0.4379701672062398, 2.682908869119486, 2.2736515839995644, 0.40925728511992154,
  2.800171174350684, 2.420486947320083, 0.3796842270306012, 2.941333423413998,
  2.592361661314032, 0.34897176209996583, 3.114612114748308, 2.7978718996891576,
  0.31674021505915, 3.332870338215699, 3.05042369938386, 0.28244663883183885,
  3.61763358112354, 3.372370287488046, 0.24526329363549426, 4.0083617957607425,
  3.8045467891966367, 0.20381500656410556, 4.587677367223091, 4.43216288019858,
  0.15551448702451157, 5.570086360997064, 5.475678117590335, 0.09440824340672992,
  7.810249675906654, 7.810249675906654, 0.0, 1.9997398373972732,
  1.0162612288412374, 0.9834786085560357, 2.000781097471685, 1.0495900839195722,
  0.9511910135521127, 2.003914664148956, 1.0840849822445167, 0.9198296819044389,
  2.0091701535415942, 1.1198653314821994, 0.8893048220593948, 2.016597794967223,
  1.1570643085877512, 0.8595334863794719, 2.026269782326438, 1.19583134694675,
  0.8304384353796879, 2.038282265682208, 1.2363351447580606, 0.8019471209241472,
  2.0527580932671254, 1.2787673367893566, 0.7739907564777687, 2.0698504623413863,
  1.3233470169067878, 0.7465034454345985, 2.089747701170037, 1.3703263614229755,
  0.7194213397470617, 2.1126794915808556, 1.4199976910625423, 0.6926818005183134,
  2.138924963620744, 1.4727024339683812, 0.6662225296523627, 2.16882326842116,
  1.5288426318378672, 0.6399806365832932, 2.2027874902660782, 1.5888958946181546,
  0.6138915956479234, 2.2413231386314436, 1.6534351022690974, 0.587888036362346,
  2.2850530390571566, 1.7231547507644132, 0.5618982882927436, 2.334751342174844,
  1.7989067718396337, 0.5358445703352102, 2.391390808713624, 1.8817501445615403,
  0.5096406641520839, 2.4562098918795665, 1.9730210606901435, 0.4831888311894229,
  2.530810146968753, 2.074434546695699, 0.45637560027305374, 2.6173015454240547,
  2.1882357183053576, 0.4290658271186975, 2.7185261844213704, 2.3174321572116603,
  0.4010940272097103, 2.8384157154273413, 2.4661644740598208, 0.3722512413675202,
  2.9825883613622137, 2.640324123173107, 0.3422642381891065, 3.1594015543799085,
  2.8486407457523764, 0.31076080862753197, 3.3819373146171707, 3.1047293380092063,
  0.27720797660796476, 3.6720853103265165, 3.4312928309608433, 0.24079247936567325,
  4.069969922789823, 3.869807467570651, 0.2001624552191716, 4.659599168037919,
  4.50682542482356, 0.15277374321435797, 5.659063526768365, 5.566291993542654,
  0.0927715332257109, 7.937253933193772, 7.937253933193772, 0.0,
  1.9997558444720196, 1.0157490003667404, 0.9840068441052793, 2.000733003506377,
  1.0480030018366735, 0.9527300016697035, 2.0036730976765997, 1.0813473860476883,
  0.9223257116289114, 2.0086021902359583, 1.1158901056866426, 0.8927120845493154,
  2.0155644370746373, 1.1517511068997928, 0.8638133301748445, 2.024623199288969,
  1.1890644186300292, 0.8355587806589396, 2.0358626776148885, 1.2279806626883452,
  0.807882014926543, 2.04939015319192, 1.2686700948330931, 0.7807200583588267,
  2.065338955232288, 1.3113263207824053, 0.754012634449883, 2.0838723233492997,
  1.3561708771003382, 0.7277014462489617, 2.105188395801711, 1.4034589305344742,
  0.701729465267237, 2.129526642456072, 1.4534864385017634, 0.6760402039543085,
  2.15717618448496, 1.5065992399577497, 0.65057694452721, 2.1884866196096624,
  1.5632047282926163, 0.6252818913170464, 2.2238822302255676, 1.6237870252440652,
  0.6000952049815025, 2.2638808373138692, 1.688926973869077, 0.5749538634447923,
  2.309119150238896, 1.7593288763724924, 0.5497902738664038, 2.3603873774083293,
  1.8358568490953673, 0.524530528312962, 2.4186773244895647, 1.9195851781663213,
  0.4990921463232436, 2.485250608738542, 2.0118695404073907, 0.47338106833115084,
  2.5617376914898995, 2.1144501580551553, 0.44728753343474426, 2.6502855925592113,
  2.229605339772035, 0.42068025278717636, 2.753785273643051, 2.3603873774083293,
  0.39339789623472166, 2.8762349126466136, 2.5109987332629164, 0.36523617938369696,
  3.023346655611956, 2.6874192494328497, 0.33592740617910627, 3.2036163775859374,
  2.8985100559110863, 0.30510632167485113, 3.430341291957747, 3.158091983072212,
  0.2722493088855355, 3.7257691732316682, 3.48921240032807, 0.23655677290359797,
  4.130677910464576, 3.933978962347215, 0.19669894811736077, 4.730438582238213,
  4.580265928833825, 0.15017265340438768, 5.746668038819286, 5.655451085822155,
  0.09121695299713152, 8.06225774829855, 8.06225774829855, 0.0,
  1.9997704184116871, 1.0152680585782414, 0.9845023598334455, 2.0006892194794212,
  1.0465143609584662, 0.954174858520955, 2.003453239981564, 1.0787825138362261,
  0.9246707261453376, 2.00808550799198, 1.1121704351955577, 0.8959150727964226,
  2.0146249989266223, 1.1467865378505389, 0.8678384610760835, 2.0231275572197505,
  1.182751494990008, 0.8403760622297426, 2.0336672464136805, 1.2202003478482082,
  0.8134668985654724, 2.0463381929681126, 1.259285041826531, 0.7870531511415817,
  2.0612570164355724, 1.3001775026747455, 0.7610795137608267, 2.0785659739196416,
  1.3430733985326917, 0.7354925753869499, 2.0984369935682445, 1.3881967803605313,
  0.7102402132077135, 2.121076835512745, 1.4358058578855508, 0.6852709776271947,
  2.1467337069291124, 1.4862002586432315, 0.6605334482858808, 2.175705782539062,
  1.5397302461045672, 0.6359755364344949, 2.208352261041382, 1.5968085579837685,
  0.6115437030576135, 2.245107850251132, 1.6579257971085284, 0.5871820531426037,
  2.286501965119339, 1.7236707121668864, 0.5628312529524525, 2.3331845190640195,
  1.794757322356938, 0.5384271967070814, 2.385961118190391, 1.8720618004263068,
  0.5138993177640842, 2.445841952609133, 1.9566735620873064, 0.48916839052182676,
  2.5141111186622465, 2.049967527524601, 0.4641435911376455, 2.592427243404466,
  2.153708786828326, 0.43871845657614045, 2.6829735569770374, 2.2702083943651856,
  0.412765162611852, 2.788688888041424, 2.4025627343126112, 0.3861261537288126,
  2.9136366884765588, 2.5550352498948286, 0.3586014385817303, 3.0636213640182377,
  2.7336929094316584, 0.3299284545865794, 3.247274886556724, 2.9475264354899493,
  0.2997484510667745, 3.4781061257848678, 3.2105595007244934, 0.26754662506037447,
  3.7787151949558417, 3.5461788752662518, 0.2325363196895903, 4.190523102306887,
  3.997114343738877, 0.1934087585680102, 4.800242498283606, 4.652542729105649,
  0.1476997691779571, 5.832961297660049, 5.743223431542202, 0.08973786611784691,
  8.18535277187245, 8.18535277187245, 0.0, 1.9997837253305382,
  1.0148156218095272, 0.9849681035210112, 2.0006492452694955, 1.0451152773795869,
  0.9555339678899087, 2.0032525635409364, 1.0763745117533383, 0.9268780517875981,
  2.007614102698299, 1.108682414922941, 0.8989316877753578, 2.01376839728275,
  1.1421372999514101, 0.8716310973313397, 2.021764861822134, 1.1768482031501974,
  0.8449166586719367, 2.0316689128469165, 1.2129366643862185, 0.8187322484606978,
  2.0435634958370184, 1.250538855661459, 0.7930246401755593, 2.0575510889201474,
  1.2898081452932264, 0.7677429436269207, 2.0737562817937576, 1.3309182107034565,
  0.742838071090301, 2.092329063290693, 1.3740668475341868, 0.7182622157565065,
  2.1134489978863145, 1.4194806702221516, 0.6939683276641628, 2.137330535547045,
  1.4674209647039413, 0.6699095708431038, 2.164229788517753, 1.5181910456766325,
  0.6460387428411203, 2.194453234862844, 1.5721456010957688, 0.6223076337670751,
  2.2283689902271124, 1.6297026943452018, 0.5986662958819108, 2.26642155537461,
  1.691359369682545, 0.5750621856920651, 2.3091513442812377, 1.7577122172887032,
  0.5514391269925345, 2.357220902803847, 1.8294848797880603, 0.5277360230157866,
  2.4114506711982813, 1.9075654563210285, 0.5038852148772528, 2.472868650996119,
  1.9930583157282151, 0.4798103352679037, 2.542780813545333, 2.0873573842536315,
  0.4554234292917014, 2.6228732881544783, 2.1922523005470262, 0.4306209876074517,
  2.7153647529617073, 2.3100864316241387, 0.4052783213375683, 2.823240984254163,
  2.4439996580110663, 0.3792413262430965, 2.9506295411768546, 2.5983155661109616,
  0.35231397506589307, 3.1034255267365447, 2.7791870388685473, 0.32423848786799725,
  3.2903947927675277, 2.9957325725196893, 0.29466222024783834, 3.5252545092289025,
  3.2621758145103277, 0.26307869471857476, 3.8309516410665476, 3.602238110256604,
  0.22871353080994317, 4.2495404163273935, 4.059262487238107, 0.1902779290892863,
  4.869054559942033, 4.723709647704958, 0.1453449122370756, 5.918000276506184,
  5.82967191417027, 0.0883283623359132, 8.306623862918075, 8.306623862918075,
  0.0, 1.9997959079539562, 1.0143892286722969, 0.9854066792816591,
  2.0006126512626468, 1.0437979050065977, 0.9568147462560489, 2.003068898536696,
  1.0741094093602568, 0.9289594891764392, 2.007182825438889, 1.105405034299678,
  0.901777791139211, 2.0129851418084135, 1.1377742105873636, 0.8752109312210499,
  2.020519735117675, 1.1713157884740142, 0.8492039466436606, 2.0298446082707464,
  1.2061395498420378, 0.8237050584287089, 2.041033151747078, 1.242368005411265,
  0.7986651463358133, 2.05417580622839, 1.2801385459104457, 0.7740372603179443,
  2.0693821921874793, 1.319606035597813, 0.7497761565896662, 2.086783809278447,
  1.3609459625729003, 0.7258378467055466, 2.1065374432940898, 1.4043582955293932,
  0.7021791477646965, 2.128829465602405, 1.4500722446856962, 0.6787572209167089,
  2.153881274688683, 1.4983521910877793, 0.6555290836009037, 2.1819562196814157,
  1.5495051415128898, 0.6324510781685262, 2.2133684736166277, 1.6038901982729186,
  0.6094782753437089, 2.2484945083721164, 1.6619307235793903, 0.586563784792726,
  2.2877880931096652, 1.7241301571261243, 0.5636579359835409, 2.331800141069391,
  1.7910928619808364, 0.5407072790885545, 2.381205343704925, 1.8635520081168977,
  0.5176533355880272, 2.4368384883249483, 1.9424074906937996, 0.49443099763114895,
  2.4997448849424453, 2.0287784573445933, 0.470966427597852, 2.5712518414944623,
  2.1240776081910773, 0.44717423330338485, 2.653072389409734, 2.2301188200835447,
  0.42295356932618955, 2.7474599559507977, 2.349277353639088, 0.39818260231170977,
  2.8574464124459094, 2.4847360108225294, 0.37271040162337954, 2.9872223331649694,
  2.6408777148270017, 0.3463446183379675, 3.142772045349815, 2.823940098720123,
  0.3188319466296914, 3.3329931799232604, 3.0431676860168904, 0.2898254939063704,
  3.5718080155573873, 3.312981347763374, 0.2588266677940136, 3.882505138933644,
  3.657432377256331, 0.22507276167731272, 4.307762549377366, 4.120468525491393,
  0.18729402388597244, 4.936915467005507, 4.79381646796187, 0.14309899904363793,
  6.00183795378794, 5.914854795037391, 0.08698315875054988, 8.426149773176359,
  8.426149773176359, 0.0, 1.9998070894618132, 1.0139866932482435,
  0.9858203962135696, 2.0005790667495753, 1.042555288306116, 0.9580237784434592,
  2.0029003737382305, 1.0719748479162357, 0.9309255258219948, 2.006787240141572,
  1.1023197516270606, 0.9044674885145114, 2.012267067265178, 1.133671587191649,
  0.878595480073529, 2.0193789699002838, 1.1661202502241073, 0.8532587196761765,
  2.028174564353883, 1.1997652352515926, 0.8284093291022903, 2.038719034276605,
  1.2347171616041412, 0.8040018726724639, 2.051092518508251, 1.2710995889346905,
  0.7799929295735605, 2.0653918808301674, 1.3090511920754584, 0.7563406887547092,
  2.0817329415978842, 1.348728384697221, 0.7330045569006634, 2.100253277532792,
  1.3903085076625523, 0.7099447698702395, 2.1211157310350712, 1.433993733657513,
  0.6871219973775582, 2.1445128179296153, 1.4800158884302979, 0.6644969294993174,
  2.1706722879831912, 1.5286424563261913, 0.642029831657, 2.199864183907207,
  1.5801841321023598, 0.619680051804847, 2.232409874139121, 1.6350044148624547,
  0.5974054592766662, 2.2686937214152283, 1.693531932887424, 0.5751617885278045,
  2.3091783228561997, 1.7562764709047152, 0.5529018519514844, 2.3544246660323176,
  1.8238500934053166, 0.5305745726270011, 2.4051191684167574, 1.8969954004413863,
  0.5081237679753712, 2.4621105385610873, 1.9766239534927041, 0.4854865850683834,
  2.5264609488587735, 2.063869507518435, 0.4625914413403389, 2.599518559377407,
  2.1601633099051694, 0.4393552494722377, 2.6830227563535707, 2.2673431743832992,
  0.41567958197027144, 2.779261071101684, 2.3878158498197566, 0.3914452212819275,
  2.8913106749975586, 2.5248065049274455, 0.3665041700701131, 3.023424130754203,
  2.682756623063588, 0.34066750769061444, 3.181673596552607, 2.8679874673150256,
  0.3136861292375809, 3.3750864864783527, 3.0898679101562383, 0.2852185763221143,
  3.6177871466386518, 3.3630134039176203, 0.2547737427210318, 3.9334007920684586,
  3.711800747444884, 0.22160004462357513, 4.365220161552396, 4.180774239233281,
  0.18444592231911536, 5.003863241835769, 4.86290934769955, 0.14095389413621884,
  6.08452369306165, 5.998826176257964, 0.0856975168036852, 8.54400374531753,
  8.54400374531753, 0.0, 1.9998173766146947, 1.0136060675992289,
  0.9862113090154658, 2.0005481704913133, 1.0413812394338335, 0.9591669310574796,
  2.0027453684852228, 1.0699598543962148, 0.9327855140890082, 2.006423508165125,
  1.0994101414603423, 0.9070133667047825, 2.0116071169352767, 1.1298067369088536,
  0.8818003800264231, 2.018331170617378, 1.1612316324099983, 0.8570995382073797,
  2.0266417589709342, 1.1937752826815091, 0.832866476289425, 2.036596983383623,
  1.2275379077928688, 0.8090590755907541, 2.0482681218167156, 1.2626310339966054,
  0.7856370878201101, 2.0617411082663915, 1.2991793284966302, 0.7625617797697611,
  2.077118389447868, 1.337322798685614, 0.7397955907622542, 2.0945212414223042,
  1.3772194464146659, 0.7173017950076384, 2.114092655278392, 1.4190484946389206,
  0.6950441606394712, 2.1360009363293826, 1.463014339951632, 0.6729865963777507,
  2.160444209320314, 1.5093514339087126, 0.6510927754116014, 2.187656088337278,
  1.5583303642950472, 0.6293257240422307, 2.2179128626497655, 1.6102655030196928,
  0.6076473596300728, 2.251542681017716, 1.6655247229446122, 0.5860179580731042,
  2.288937406256616, 1.7245418814262174, 0.5643955248303986, 2.330568089339511,
  1.7878330548357892, 0.5427350345037217, 2.3770054267421457, 1.8560179359493467,
  0.520987490792799, 2.4289471963710163, 1.9298484573906707, 0.49909873898034574,
  2.4872556519115805, 2.0102477186682637, 0.4770079332433168, 2.553009428665931,
  2.098363913971998, 0.4546455146939328, 2.627577099222425, 2.1956466171584648,
  0.4319304820639603, 2.7127239018635745, 2.3039572865142683, 0.40876661534930575,
  2.810770872987142, 2.4257337670984924, 0.3850371058886496, 2.9248397391993977,
  2.564243059024129, 0.36059668017526825, 3.0592440829352534, 2.7239844574081027,
  0.33525962552715105, 3.2201425716601713, 2.911361777117415, 0.30878079454275614,
  3.4166905021097276, 3.1358666252239966, 0.280823876885731, 3.6632113844356327,
  3.4123064950907267, 0.2509048893449063, 3.9836622870659237, 3.7653794220212156,
  0.21828286504470817, 4.421942042651783, 4.240218397063354, 0.18172364558842943,
  5.069933466241216, 4.931031179494881, 0.1389022867463347, 6.166103577895309,
  6.081636405595373, 0.08446717229993576, 8.660254037844387, 8.660254037844387,
  0.0, 1.9998268623119293, 1.013245610238044, 0.9865812520738851,
  2.0005196830021448, 1.0402702351611144, 0.9602494478410302, 2.002602473449653,
  1.0680546525064814, 0.9345478209431713, 2.006088294144213, 1.0966616007988363,
  0.9094266933453767, 2.010999166349609, 1.1261595331557808, 0.8848396331938284,
  2.0173664619648224, 1.1566234381931648, 0.8607430237716575, 2.025231468252456,
  1.1881357947081075, 0.8370956735443486, 2.034646147672012, 1.2207876886032072,
  0.8138584590688047, 2.0456741208451685, 1.2546801274517037, 0.7909939933934651,
  2.058391910218466, 1.2899255970702388, 0.7684663131482272, 2.072890493972125,
  1.3266499161421605, 0.7462405778299649, 2.089277235093362, 1.3649944602609967,
  0.7242827748323656, 2.1076782705877317, 1.4051188470584879, 0.7025594235292438,
  2.1282414723677108, 1.447204201210043, 0.6810372711576675, 2.151140127038182,
  1.491457154746473, 0.6596829722917091, 2.1765775303657784, 1.5381147881251498,
  0.6384627422406284, 2.204792759220492, 1.5874507866387544, 0.6173419725817377,
  2.23606797749979, 1.639783183499846, 0.5962847939999438, 2.2707377655731187,
  1.6954841982945954, 0.5752535672785235, 2.3092011545768742, 1.7549928774784245,
  0.5542082770984499, 2.3519373281195866, 1.8188315337458136, 0.5331057943737729,
  2.3995263740041235, 1.8876274142165772, 0.5118989597875463, 2.452677108793573,
  1.9621416870348583, 0.4905354217587146, 2.512264995942121, 2.0433088633662586,
  0.4689561325758626, 2.57938477285798, 2.1322914122292635, 0.4470933606287165,
  2.6554250227189717, 2.2305570190839363, 0.4248680036350355, 2.742176371060038,
  2.3399905033045654, 0.40218586775547227, 2.8419928002940256, 2.463060426921489,
  0.3789323733725368, 2.958039891549808, 2.6030751045638314, 0.3549647869859769,
  3.094691329981182, 2.764590921449856, 0.3301004085313261, 3.258191035456548,
  2.9540932054806035, 0.3040978299759445, 3.4578203740406233, 3.1811947441173736,
  0.2766256299232498, 3.7080992435478315, 3.4608926273113094, 0.2472066162365221,
  4.033311993114693, 3.8182020201485756, 0.21510997296611695, 4.477955262542641,
  4.298837052040935, 0.17911821050170565, 5.135159492527825, 4.998221906060417,
  0.1369375864674087, 6.246620708052497, 6.163332431945131, 0.08328827610736661,
  8.774964387392123, 8.774964387392123, 0.0, 1.9998356276964555,
  1.01290375948262, 0.9869318682138354, 2.0004933602015593, 1.039217329974835,
  0.9612760302267243, 2.002470458388139, 1.066250503817061, 0.9362199545710782,
  2.0057786887261884, 1.0940611029415572, 0.9117175857846312, 2.010437878949827,
  1.1227120622706823, 0.8877258166791447, 2.016476250935834, 1.152272143391905,
  0.8642041075439287, 2.023930902055773, 1.1828167609416858, 0.8411141411140878,
  2.032848451332995, 1.2144289449521788, 0.8184195063808162, 2.0432858729372536,
  1.2472004678967652, 0.7960854050404882, 2.0553115470788255, 1.2812331722049821,
  0.7740783748738432, 2.069006567737256, 1.3166405431055268, 0.7523660246317292,
  2.084466358567583, 1.3535495834854436, 0.7309167750821396, 2.101802663710911,
  1.3921030629773563, 0.7096996007335543, 2.1211460004039293, 1.4324622340390172,
  0.6886837663649124, 2.142648687075512, 1.4748101352597678, 0.6678385518157439,
  2.1664885966711602, 1.5193556392239305, 0.6471329574472298, 2.192873834075712,
  1.566338452911223, 0.6265353811644891, 2.222048604328897, 1.6160353486028345,
  0.6060132557260628, 2.2543006332406597, 1.668768001230099, 0.5855326320105609,
  2.289970636764013, 1.7249129471728926, 0.56505768959112, 2.329464529787843,
  1.7849143799673082, 0.5445501498205347, 2.373269349949012, 1.8493007921680613,
  0.5239685577809507, 2.4219742976657535, 1.9187069111378048, 0.5032673865279488,
  2.4762989422953163, 1.9939030444455792, 0.48239589784973697, 2.5371316554402603,
  2.075834990814758, 0.46129666462550184, 2.605582948209479, 2.16567933357671,
  0.43990361463276917, 2.6830610444131415, 2.2649216608682363, 0.41813938354490526,
  2.771381524719315, 2.3754698783308412, 0.39591164638847354, 2.8729307933334525,
  2.4998228980953416, 0.3731078952381107, 2.9909176242909328, 2.641329850023161,
  0.3495877742677713, 3.129774934930183, 2.8046035131192544, 0.32517142181092806,
  3.2958306995353994, 2.996209726850363, 0.2996209726850363, 3.4984906202129955,
  3.2258809614951, 0.2726096587178958, 3.7524683234530465, 3.508801549202849,
  0.24366677425019784, 4.08237105425971, 3.8702998306618026, 0.212071223597907,
  4.533285307111795, 4.356663801639907, 0.17662150547188807, 5.199572632010784,
  5.064518797413102, 0.1350538345976827, 6.326115462280566, 6.243958118614586,
  0.08215734366598137, 8.888194417315589, 8.888194417315589, 0.0,
  1.9998437438960075, 1.012579110833421, 0.9872646330625863, 2.0004689881644953,
  1.0382180824651168, 0.9622509056993784, 2.002348245495923, 1.0645395735547944,
  0.9378086719411287, 2.0054921448185667, 1.0915969902177005, 0.913895154600866,
  2.0099185872250467, 1.119448327062051, 0.8904702601629955, 2.0156530313665453,
  1.1481567900189182, 0.867496241347627, 2.022728905479906, 1.1777915145832363,
  0.8449373908966695, 2.031188159302652, 1.208428398572464, 0.8227597607301882,
  2.0410819741009916, 1.2401510728714886, 0.8009309012295031, 2.052471655021707,
  1.273052039190679, 0.7794196158310279, 2.0654297373670207, 1.3072340109917855,
  0.7581957263752354, 2.080041347693259, 1.3428115029412178, 0.7372298447520412,
  2.0964058725393757, 1.3799127262284498, 0.7164931463109261, 2.1146390030469853,
  1.418681862803674, 0.6959571402433116, 2.134875244058141, 1.4592818123941724,
  0.6755934316639688, 2.1572710033322613, 1.501897533965498, 0.655373469366763,
  2.182008412973175, 1.546740140841744, 0.6352682721314307, 2.2093000848659194,
  1.5940519599665497, 0.6152481248993699, 2.239395070578584, 1.6441128366273148,
  0.5952822339512691, 2.2725863922877876, 1.6972480651263222, 0.5753383271614654,
  2.309220647751098, 1.7538384666464035, 0.5553821811046945, 2.349710389144992,
  1.814333338453728, 0.5353770506912641, 2.394550264191991, 1.879267295948145,
  0.5152829682438462, 2.4443383390943216, 1.9492824729486362, 0.4950558661456855,
  2.4998046798700093, 2.025158221666843, 0.4746464582031664, 2.5618502928697695,
  2.1078515067915826, 0.4539987860781869, 2.6316011619021364, 2.1985528694372283,
  0.43304829246490856, 2.7104848088426365, 2.298765597372869, 0.41171921146976764,
  2.800341365745591, 2.4104204160848126, 0.38992094966077856, 2.903589165072375,
  2.5360462327847326, 0.36754293228764245, 3.023479547049818, 2.6790325100441423,
  0.34444703700567547, 3.1645038326793435, 2.844047748357385, 0.3204560843219588,
  3.3330729064933458, 3.0377373325002646, 0.29533557399308125, 3.538715147107479,
  3.269951971377797, 0.26876317572968195, 3.796335359549017, 3.5560609697041423,
  0.2402743898448745, 4.1308594747340415, 3.9217020329753556, 0.20915744175868564,
  4.587956201323544, 4.413730016463156, 0.1742261848603877, 5.263202323804273,
  5.129956695353531, 0.13324562845074106, 6.4046257321744235, 6.323554520374747,
  0.08107121179967625, 9.0, 9.0, 0.0,
  1.9998512734706997, 1.0122703976826994, 0.9875808757880004, 2.0004463787579296,
  1.0372684926892959, 0.9631778860686337, 2.002234887276781, 1.0629148167024884,
  0.9393200705742926, 2.005226424709705, 1.0892587986077409, 0.9159676261019645,
  2.0094371943003937, 1.116353996833552, 0.8930831974668418, 2.0148902224924443,
  1.1442586448722523, 0.870631577620192, 2.021615713033862, 1.1730362779332282,
  0.8485794351006335, 2.029651520364431, 1.2027564565122553, 0.8268950638521757,
  2.0390437571110946, 1.2334956061536253, 0.8055481509574695, 2.0498475553074673,
  1.265337997103375, 0.7845095582040924, 2.0621280068192998, 1.298376893182522,
  0.7637511136367776, 2.0759613157800856, 1.3327159064267213, 0.7432454093533641,
  2.0914362051303703, 1.368470603356909, 0.7229656017734614, 2.108655631303644,
  1.405770420869096, 0.702885210434548, 2.1277388766652563, 1.4447609656369025,
  0.6829779110283539, 2.148824109820312, 1.4856067919745366, 0.6632173178457754,
  2.1720715312443337, 1.5284947812460123, 0.6435767499983213, 2.197667258551746,
  1.5736382839012502, 0.6240289746504956, 2.2258281560136597, 1.6212822370963693,
  0.6045459189172904, 2.256807882426375, 1.6717095425380555, 0.5850983398883195,
  2.2909045287220002, 1.7252490895313828, 0.5656554391906172, 2.3284703548785814,
  1.782285950647803, 0.5461844042307784, 2.369924334949, 1.8432744827381107,
  0.5266498522108889, 2.415768511260961, 1.9087553669222408, 0.5070131443387202,
  2.4666095953611307, 1.9793780703515245, 0.48723152500960615, 2.5231879186313635,
  2.0559308966625927, 0.46725702196877095, 2.5864168725876286, 2.139381857572483,
  0.44703501501514564, 2.657437636129203, 2.230935299466491, 0.42650233666271165,
  2.7376967103008276, 2.3321120124784827, 0.4055846978223448, 2.8290583996396093,
  2.444865283639168, 0.38419311600044076, 2.933972498555351, 2.5717536715732088,
  0.3622188269821421, 3.0557323181195044, 2.7162065049951147, 0.33952581312438934,
  3.1988867926715954, 2.882947356358351, 0.315939436313244, 3.3699286222291,
  3.0787002227772025, 0.2912283994518975, 3.578507270596818, 3.313432657960017,
  0.2650746126368013, 3.839716272412791, 3.6026967494243474, 0.2370195229884439,
  4.178796197750934, 3.9724358916891602, 0.2063603060617745, 4.641990620744179,
  4.470065042198098, 0.1719255785460807, 5.326076286310114, 5.194568229858012,
  0.1315080564521016, 6.48218713089957, 6.402160129283526, 0.08002700161604408,
  9.1104335791443, 9.1104335791443, 0.0, 1.9998582716222577,
  1.0119764747968047, 0.987881796825453, 2.000425365996799, 1.0363649486489432,
  0.9640604173478557, 2.0021295480744317, 1.0613698809069274, 0.9407596671675043,
  2.0049795559912873, 1.0870371086699748, 0.9179424473213125, 2.008990092044097,
  1.1134161955907043, 0.8955738964533926, 2.0141820348953634, 1.14056091132629,
  0.8736211235690734, 2.020582745058868, 1.1685297802750079, 0.8520529647838602,
  2.028226472538682, 1.1973867127035591, 0.830839759835123, 2.0371548787463363,
  1.2272017341845403, 0.8099531445617962, 2.0474176886798627, 1.2580518328032892,
  0.7893658558765736, 2.0590734940371007, 1.2900219480714363, 0.7690515459656643,
  2.0721907337418237, 1.3232061311845378, 0.7489846025572859, 2.086848885665883,
  1.3577089135657552, 0.7291399721001278, 2.103139912645616, 1.3936469300663719,
  0.7094929825792442, 2.12117001791416, 1.4311508554601562, 0.690019162454004,
  2.141061780766223, 1.4703677289599362, 0.6706940518062867, 2.162956763984135,
  1.5114637627840943, 0.6514930012000408, 2.1870187121873528, 1.5546277592657087,
  0.632390952921644, 2.213437497548904, 1.6000752994329426, 0.6133621981159615,
  2.2424340202102795, 1.648053918467796, 0.5943801017424837, 2.274266341049202,
  1.6988495559644643, 0.5754167850847379, 2.3092374229244204, 1.7527946704125115,
  0.5564427525119086, 2.3477049963741186, 1.8102785514210071, 0.5374264449531115,
  2.390094267447928, 1.8717605708929554, 0.5183336965549724, 2.436914481173311,
  1.9377874187643196, 0.4991270624089916, 2.4887807960417625, 2.00901582331082,
  0.47976497273094215, 2.54644359843292, 2.0862429481137172, 0.4602006503192025,
  2.610828435721686, 2.1704477357204377, 0.4403807000012484, 2.683091424427564,
  2.262848189276258, 0.42024323515130524, 2.7646977464940217, 2.3649824096515126,
  0.39971533684250926, 2.857535521959309, 2.4788259949526537, 0.3787095270066554,
  2.964085565205234, 2.6069668224094222, 0.3571187427958114, 3.087682591165061,
  2.752873635496561, 0.3348089556685006, 3.2329323920941886, 2.92132445068752,
  0.31160794140666875, 3.406408434268068, 3.119120975956303, 0.2872874583117647,
  3.617879738650736, 3.3563462635675503, 0.26153347508318575, 3.8826262149202986,
  3.648733069443172, 0.2338931454771264, 4.226199178182553, 4.022526928631587,
  0.20367224955096638, 4.695409992748237, 4.525696378552517, 0.16971361419571943,
  5.388220653490314, 5.258384011237535, 0.12983664225277863, 6.558833179989168,
  6.479811093483275, 0.0790220865058936, 9.219544457292887, 9.219544457292887,
  0.0, 1.9998647872087154, 1.0116963041173497, 0.9881684830913655,
  2.000405802986828, 1.0355041803696514, 0.9649016226171765, 2.002031488588732,
  1.059899023370505, 0.9421324652182268, 2.0047497946453157, 1.0849234182786414,
  0.9198263763666744, 2.008574092592483, 1.1106233217864319, 0.8979507708060512,
  2.013523358640141, 1.1370484848791382, 0.8764748737610026, 2.0196224382692196,
  1.164252935002256, 0.8553695032669636, 2.0269023985711137, 1.192295528571243,
  0.8346068699998704, 2.0354009783964297, 1.2212405870378582, 0.8141603913585717,
  2.0451631494069873, 1.2511586325783923, 0.7940045168285951, 2.0562418048969415,
  1.282127243053387, 0.7741145618435546, 2.0686985978844015, 1.3142320504206786,
  0.7544665474637231, 2.082604955760821, 1.3475679125511197, 0.7350370432097015,
  2.098043306103502, 1.3822402957858366, 0.7158030103176656, 2.115108557622118,
  1.418366915111303, 0.6967416425108154, 2.1339098923270936, 1.456079691234958,
  0.6778302010921357, 2.15457294084902, 1.4955271001187314, 0.6590458407302885,
  2.177242433764466, 1.5368770120690347, 0.6403654216954311, 2.202085449720072,
  1.5803201462696987, 0.6217653034503734, 2.229295418852362, 1.6260743055158409,
  0.6032211133365214, 2.259097091480811, 1.674389608979895, 0.5847074825009158,
  2.291752753204015, 1.7255550141771407, 0.5661977390268743, 2.3275700671692823,
  1.7799065219529808, 0.5476635452163017, 2.3669120658091054, 1.837837604040011,
  0.5290744617690943, 2.4102100184572057, 1.8998126027839148, 0.5103974156732907,
  2.4579802006254377, 1.9663841605003503, 0.49159604012508756, 2.5108460379097233,
  2.0382161954796576, 0.4726298424300658, 2.569567779107718, 2.1161146416181205,
  0.45345313748959737, 2.635082915551423, 2.2010692588723653, 0.43401365667905795,
  2.708562261386938, 2.294311562586583, 0.41425069880035525, 2.7914893992966676,
  2.3973967782194907, 0.3940926210771766, 2.8857759273205366, 2.512322572020232,
  0.3734533553003048, 2.993933259716449, 2.641705817396867, 0.3522274423195822,
  3.1193369740851558, 2.78905423565261, 0.3302827384325459, 3.266648997213455,
  2.959199679828659, 0.3074493173847958, 3.4425225545320015, 3.159020697099954,
  0.2835018574320472, 3.6568447550295295, 3.3987145370274447, 0.25813021800208447,
  3.9250796170268956, 3.694192580731196, 0.23088703629569973, 4.273085449562092,
  4.071999075465052, 0.2010863740970396, 4.748234588488344, 4.580649838306403,
  0.16758475018194158, 5.449660097723792, 5.321432801306762, 0.1282272964170304,
  6.634595476956914, 6.556541412522127, 0.07805406443478723, 9.327379053088816,
  9.327379053088816, 0.0, 1.9998708635995426, 1.011428942510113,
  0.9884419210894296, 2.000387559348663, 1.034683220352756, 0.9657043389959068,
  2.0019400528375666, 1.0584970394313569, 0.9434430134062097, 2.0045355939935123,
  1.0829100335367252, 0.9216255604567872, 2.0081863708331458, 1.1079648942527704,
  0.9002214765803754, 2.012909669488331, 1.133707744884232, 0.879201924604099,
  2.01872810400379, 1.1601885655194195, 0.8585395384843706, 2.0256699219641874,
  1.1874616783927991, 0.8382082435713881, 2.0337693941836053, 1.2155863045695117,
  0.8181830896140938, 2.0430672992386545, 1.2446272052833183, 0.7984400939553362,
  2.053611516679313, 1.2746554241457804, 0.7789560925335326, 2.0654577464763926,
  1.3057491500712828, 0.75970859640511, 2.0786703768790002, 1.3379947253474027,
  0.7406756515315976, 2.093323528646668, 1.3714878291133343, 0.7218356995333339,
  2.1095023109728985, 1.4063348739819326, 0.7031674369909661, 2.1273043338491933,
  1.4426546631850852, 0.6846496706641081, 2.146841533841884, 1.4805803681668164,
  0.6662611656750674, 2.1682423862514404, 1.5202619030038833, 0.647980483247557,
  2.1916545977709445, 1.5618687938137765, 0.6297858039571681, 2.217248402004267,
  1.6055936704168832, 0.6116547315873839, 2.245220618335757, 1.6516565468217062,
  0.5935640715140509, 2.2757996867138424, 1.700310110763216, 0.5754895759506267,
  2.3092519628873704, 1.7518463166731777, 0.5574056462141928, 2.345889659434789,
  1.8066046802543778, 0.5392849791804113, 2.3860809611036204, 1.8649828201729446,
  0.5210981409306759, 2.4302630494871367, 1.9274500047656602, 0.5028130447214765,
  2.478959074942161, 1.9945647729419684, 0.4843943020001925, 2.532800566080826,
  2.066998163123433, 0.4658024029573934, 2.5925574567724947, 2.14556479181172,
  0.4469926649607749, 2.6591789854600476, 2.2312651257308445, 0.42791385972920304,
  2.7338504392044243, 2.3253440517370967, 0.4085063874673278, 2.818073537283664,
  2.4293737390376418, 0.3886997982460226, 2.9137830356681276, 2.545373686330778,
  0.3684093493373494, 3.023520548187637, 2.675989450694805, 0.34753109749283184,
  3.1507019974797803, 2.8247673080853204, 0.32593468939446, 3.300044751007142,
  2.9965923601099336, 0.3034523908972085, 3.4782808253503625, 3.1984191497474597,
  0.27986167560290276, 3.6954140033404452, 3.440557865179035, 0.25485613816141,
  3.967090228120452, 3.739096536849162, 0.22799369127129032, 4.319471185839906,
  4.120874809479451, 0.1985963763604554, 4.800483606590367, 4.634949689121734,
  0.16553391746863333, 5.510417940805665, 5.3837416663043856, 0.12667627450127966,
  6.709503846072757, 6.632383112209852, 0.07712073386290526, 9.433981132056603,
  9.433981132056603, 0.0, 1.9998765393992466, 1.011173531156922,
  0.9887030082423245, 2.0003705190385945, 1.033899369390734, 0.9664711496478606,
  2.0018546571324873, 1.0571592009576054, 0.9446954561748818, 2.0043355784676153,
  1.0809899749038825, 0.9233456035637329, 2.0078244158833765, 1.1054314199807356,
  0.9023929959026407, 2.0123369499166883, 1.1305263763576898, 0.8818105735589986,
  2.0178938091080516, 1.1563211715113553, 0.8615726375966962, 2.0245207360079855,
  1.1828660480046653, 0.8416546880033201, 2.0322489257159004, 1.2102156523926153,
  0.8220332733232852, 2.041115445871322, 1.238429596371364, 0.802685849499958,
  2.051163749502396, 1.2675731036250761, 0.7835906458773199, 2.0624442951479285,
  1.297717758744764, 0.7647265364031645, 2.075015292373336, 1.3289423782615746,
  0.7460729141117611, 2.088943595415536, 1.361334028473046, 0.72760956694249,
  2.1043057735055917, 1.3949892206385384, 0.7093165528670533, 2.121189393817639,
  1.4300153216748128, 0.6911740721428262, 2.139694562502488, 1.4665322282320425,
  0.6731623342704457, 2.15993578160212, 1.504674364711589, 0.6552614168905309,
  2.1820441958008057, 1.5445930824207952, 0.6374511133800106, 2.206170324340349,
  1.586459559076206, 0.6197107652641429, 2.232487401980132, 1.6304683272888605,
  0.6020190746912717, 2.261195491439219, 1.6768416003931288, 0.5843538910460901,
  2.2925265824159404, 1.7258346182232365, 0.5666919641927044, 2.326750965074676,
  1.7777423103941343, 0.5490086546805415, 2.3641852678409805, 1.8329076795621084,
  0.5312775882788721, 2.405202694161139, 1.8917324560817945, 0.5134702380793442,
  2.450246201756396, 1.9546907901652146, 0.4955554115911813, 2.4998456742490585,
  2.022347062313845, 0.47749861193521337, 2.554640592649938, 2.095379362510623,
  0.4592612301393147, 2.6154104116986345, 2.1746109041089774, 0.4407995075896575,
  2.683115933222251, 2.26105275271538, 0.4220631805068709, 2.7589567059421496,
  2.3559630297932963, 0.40299367614885323, 2.8444523358476395, 2.4609306725872835,
  0.38352166326035586, 2.9415604324537985, 2.5779967834988344, 0.3635636489549639,
  3.052852426856088, 2.709835300243044, 0.34301712661304357, 3.181784090726459,
  2.860030643349626, 0.3217534473768329, 3.333127565665411, 3.033520593470767,
  0.2996069721946437, 3.5136927277959087, 3.237334872800725, 0.27635785499518384,
  3.7335986710069116, 3.481895389815435, 0.2517032811914772, 4.008671156935231,
  3.783464912163588, 0.22520624477164217, 4.365371758308253, 4.169175274788781,
  0.19619648351947208, 4.852175249428115, 4.688618780346269, 0.16355646908184657,
  5.570516254441429, 5.445336113892184, 0.1251801405492456, 6.783586474317657,
  6.707366401572515, 0.07622007274514221, 9.539392014169456, 9.539392014169456,
  0.0, 1.9998818490620738, 1.0109292863390698, 0.9889525627230039,
  2.0003545784976002, 1.0331501669163428, 0.9672044115812575, 2.001774780720167,
  1.0558812030172307, 0.9458935777029363, 2.0041485213628913, 1.07915689611848,
  0.9249916252444115, 2.0074859899884734, 1.1030142802134473, 0.9044717097750261,
  2.011801622321476, 1.1274932169054421, 0.8843084054160336, 2.0171142753944307,
  1.1526367287968173, 0.8644775465976133, 2.023447459817405, 1.1784913776958508,
  0.8449560821215542, 2.030829634865503, 1.2051076954146942, 0.8257219394508087,
  2.039294573798096, 1.2325406764713769, 0.8067538973267193, 2.0488818088573746,
  1.2608503439122305, 0.788031464945144, 2.059637167842408, 1.2901024018353546,
  0.7695347660070535, 2.071613417146505, 1.320368991148322, 0.7512444259981832,
  2.0848710298466884, 1.351729568801699, 0.7331414610449892, 2.0994791020631762,
  1.3842719354262703, 0.7152071666369062, 2.1155164466544747, 1.4180934422628897,
  0.697423004391585, 2.1330729007701543, 1.4533024159093362, 0.6797704848608183,
  2.152250893377902, 1.4900198492616241, 0.6622310441162776, 2.1731673313392137,
  1.5283814198429637, 0.6447859114962501, 2.1959558789334137, 1.5685399135238671,
  0.6274159654095467, 2.220769727328383, 1.6106681538865195, 0.6101015734418636,
  2.2477849793591993, 1.6549625672205093, 0.5928224121386899, 2.2772048139563297,
  1.7016475532860487, 0.575557260670281, 2.3092646478068697, 1.7509808867986156,
  0.5582837610082543, 2.3442385854376138, 1.803260450336626, 0.5409781351009878,
  2.3824475519994492, 1.8588327054061637, 0.5236148465932856, 2.424269649468337,
  1.9181034589200028, 0.5061661905483341, 2.470153488192001, 1.981551699318858,
  0.48860178887314293, 2.5206355554906392, 2.049747594574806, 0.47088796091583374,
  2.5763631457586738, 2.123376219031874, 0.45298692672679974, 2.6381250818277024,
  2.20326929910885, 0.434855782718852, 2.706893556694228, 2.290448394125885,
  0.4164451625683428, 2.7838821814150108, 2.386184726927152, 0.39769745448785865,
  2.8706282115791177, 2.4920838320302234, 0.3785443795488947, 2.9691118200566313,
  2.610208193456379, 0.3589036266002521, 3.08193388934878, 2.7432598355741895,
  0.3386740537745912, 3.212589564092661, 2.8948609258856943, 0.31772863820696645,
  3.365905118846386, 3.070001372134616, 0.29590374671177017, 3.5487673916445974,
  3.275785284595013, 0.2729821070495844, 3.7714094728317034, 3.5227451119856568,
  0.24866436084604643, 4.049834909066995, 3.827316507469907, 0.22251840159708766,
  4.410801788087184, 4.216920390808626, 0.19388139727855752, 4.903326792736094,
  4.741678656711828, 0.16164813602426684, 5.629975951412505, 5.506240216216626,
  0.12373573519587923, 6.8568700342551825, 6.781519814098532, 0.07535022015665037,
  9.643650760992955, 9.643650760992955, 0.0, 1.9998868234161447,
  1.0106954914038575, 0.9891913320122872, 2.0003396450733497, 1.0324333651991482,
  0.9679062798742016, 2.0016999578079715, 1.054659117554737, 0.9470408402532342,
  2.0039733258976007, 1.0774050139234412, 0.9265683119741592, 2.0071690935688102,
  1.1007056319570896, 0.9064634616117203, 2.0113004923008573, 1.1245981247273609,
  0.8867023675734965, 2.016384794429989, 1.1491225172558, 0.8672622771741889,
  2.022443516585266, 1.1743220418882188, 0.8481214746970475, 2.0295026777220864,
  1.2002435190829541, 0.8292591586391321, 2.037593117942273, 1.2269377914491106,
  0.8106553264931624, 2.0467508859627226, 1.2544602204287656, 0.792290665533957,
  2.0570177050964973, 1.2828712569419018, 0.7741464481545955, 2.0684415300404617,
  1.3122370997030885, 0.7562044303373731, 2.0810772097500796, 1.3426304579032773,
  0.7384467518468024, 2.0949872753918224, 1.3741314386978623, 0.7208558366939601,
  2.1102428770167667, 1.4068285846778446, 0.703414292338922, 2.126924898488314,
  1.4408200925243417, 0.686104805963972, 2.145125287716314, 1.4762152517617642,
  0.6689100359545498, 2.1649486489337093, 1.5131361524805496, 0.6518124964531598,
  2.186514156332896, 1.5517197238491518, 0.634794432483744, 2.209957864872265,
  1.592120182219804, 0.6178376826524612, 2.235435515889769, 1.6345119901129492,
  0.6009235257768196, 2.2631259643322514, 1.6790934574077994, 0.584032506924452,
  2.2932353938112353, 1.7260911566321127, 0.5671442371791227, 2.3260025395170056,
  1.7757653796312622, 0.5502371598857433, 2.361705213431921, 1.8284169394311645,
  0.5332882740007564, 2.4006685305027804, 1.8843957282441177, 0.5162728022586625,
  2.4432753824721836, 1.944111594655286, 0.4991637878168977, 2.4899799195977463,
  2.008048322256247, 0.48193159734149926, 2.5413251136628174, 2.076781813315851,
  0.4645433003469667, 2.5979659434920794, 2.151004060740754, 0.44696188275132565,
  2.660700457224925, 2.2315552221886468, 0.42914523503627827, 2.730512076979636,
  2.3194672481870025, 0.41104482879263343, 2.808628287463981, 2.4160243333023494,
  0.39260395416163174, 2.896603768262651, 2.5228484433255347, 0.3737553249371162,
  2.9964409783250137, 2.6420232282005496, 0.3544177501244639, 3.110769900793782,
  2.776278513611655, 0.3344913871821271, 3.2431245956418544, 2.9292738283216746,
  0.31385076732017947, 3.398384852815104, 3.106050671927783, 0.2923341808873208,
  3.583513606426221, 3.313786775835, 0.26972683059122093, 3.808856673932688,
  3.563123985291869, 0.24573268864081857, 4.090593422164386, 3.8706690446286665,
  0.21992437753571972, 4.455775194539068, 4.2641289496126555, 0.19164624492641147,
  4.95395464923395, 4.7941496605489835, 0.15980498868496615, 5.68881686843911,
  5.5664767207307415, 0.12234014770836796, 6.929379795322673, 6.854870335157913,
  0.07450946016475991, 9.746794344808963, 9.746794344808963, 0.0,
  1.9998914901119567, 1.0104714897407774, 0.989420000371179, 2.000325635670118,
  1.0317469068193241, 0.968578728850794, 2.001629770744439, 1.0534893530233884,
  0.9481404177210506, 2.0038090090281333, 1.0757290469519454, 0.928079962076188,
  2.0068719353847584, 1.0984983225263945, 0.908373612858364, 2.010830700310035,
  1.1218318643834932, 0.8889988359265419, 2.01570115502881, 1.145766972332166,
  0.8699341826966444, 2.021503030200214, 1.1703438595895972, 0.8511591706106166,
  2.0282601622361676, 1.1956059903707934, 0.8326541718653743, 2.0360007724210583,
  1.221600463452635, 0.8144003089684233, 2.0447578054035205, 1.2483784496147807,
  0.7963793557887394, 2.054569335276506, 1.275995692434883, 0.778573642841623,
  2.0654790494468114, 1.3045130838611438, 0.7609659655856674, 2.077536822919267,
  1.3339973284007924, 0.7435394945184742, 2.090799398612213, 1.3645217127784972,
  0.7262776858337159, 2.1053311930476477, 1.3961670017052823, 0.7091641913423655,
  2.1212052514431505, 1.429022485182754, 0.6921827662603965, 2.1385043821689567,
  1.463187208852444, 0.6753171733165129, 2.157322508119823, 1.4987714266937717,
  0.6585510814260512, 2.177766282327517, 1.5358983254309855, 0.6418679568965314,
  2.1999570278461684, 1.5747060830898887, 0.6252509447562794, 2.224033078604932,
  1.6153503413025296, 0.6086827373024024, 2.2501526199764346, 1.6580071936668463,
  0.592145426309588, 2.2784971572891304, 1.7028768228160869, 0.5756203344730435,
  2.30927578033236, 1.7501879598308416, 0.5590878205015187, 2.3427304462985696,
  1.8002033955767958, 0.542527050721774, 2.379142578812672, 1.8532268508646075,
  0.5259157279480644, 2.4188413860345723, 1.9096116205536096, 0.5092297654809625,
  2.462214450449026, 1.969771560359221, 0.49244289008980524, 2.509721358776966,
  2.0341952065876456, 0.4755261521893198, 2.5619114569770582, 2.103464143623269,
  0.4584473133537893, 2.619447288133321, 2.178277218552972, 0.44117006958034877,
  2.6831359917082103, 2.2594829403858614, 0.423653051322349, 2.753972065929082,
  2.348123550950059, 0.40584851497902263, 2.8331966900165186, 2.445496090330048,
  0.387700599686471, 2.922381752369147, 2.5532387941751495, 0.36914295819399756,
  3.0235517325432153, 2.6734562687750536, 0.3500954637681618, 3.1393653774707446,
  2.8089058640527718, 0.3304595134179732, 3.2733952219476596, 2.9632840956578814,
  0.3101111262897783, 3.430573975783143, 3.141683535717194, 0.2888904400659489,
  3.6179398331596997, 3.3513547928216165, 0.2665850403380831, 3.845950111902438,
  3.603047999571758, 0.2429021123306803, 4.130958098893623, 3.913539251583432,
  0.21741884731019068, 4.500305239952869, 4.310818703533801, 0.1894865364190682,
  5.004074426861097, 4.846051023907589, 0.15802340295350836, 5.747057841637358,
  5.626067150234466, 0.12099069140289175, 7.001139724845413, 6.927443517215461,
  0.07369620762995173, 9.848857801796104, 9.848857801796104, 0.0,
  1.9998958740074786, 1.0102566786223337, 0.9896391953851448, 2.0003124755897512,
  1.0310889049431706, 0.9692235706465805, 2.001563844167317, 1.05236861909828,
  0.9491952250690373, 2.003654687570543, 1.0741241624089513, 0.9295305251615921,
  2.006592906979296, 1.0963858151536363, 0.9102070918256597, 2.01038968030247,
  1.1191860075910658, 0.8912036727114042, 2.015059581322366, 1.1425595564198985,
  0.8725000249024677, 2.0206207371165195, 1.166543930706444, 0.8540768064100756,
  2.0270950271354393, 1.1911795520280415, 0.8359154751073978, 2.034508328302205,
  1.216510134448741, 0.817998193853464, 2.0428908116485625, 1.2425830710027337,
  0.8003077406458287, 2.0522772973609484, 1.2694498746562572, 0.7828274227046914,
  2.0627076767397248, 1.2971666833105482, 0.7655409934291763, 2.0742274115532053,
  1.3257948403742141, 0.7484325711789914, 2.0868881236943024, 1.3554015648736193,
  0.7314865588206833, 2.10074829105082, 1.3860607281160051, 0.7146875629348151,
  2.115874069249651, 1.4178537577446115, 0.6980203115050396, 2.1323402636539974,
  1.4508706948573589, 0.6814695687966384, 2.1502314819794006, 1.4852114360063904,
  0.6650200459730106, 2.169643505550271, 1.5209871997672002, 0.6486563057830709,
  2.19068492708904, 1.5583222677231312, 0.6323626593659086, 2.2134791157628677,
  1.5973560629216572, 0.6161230528412106, 2.2381665870442937, 1.6382456461870605,
  0.5999209408572335, 2.264907877223198, 1.681168733608972, 0.5837391436142262,
  2.293887052193106, 1.7263273691762548, 0.5675596830168509, 2.3253160203711225,
  1.7739524279119905, 0.551363592459132, 2.359439874575983, 1.8243091813731824,
  0.5351306932028003, 2.396543563683243, 1.8777042354631592, 0.5188393282200836,
  2.4369603013188543, 1.934494259809812, 0.5024660415090422, 2.4810822700525734,
  1.995097083135059, 0.4859851869175144, 2.5293743976401966, 2.0600059527172734,
  0.46936844492292307, 2.582392301723346, 2.129808083895543, 0.4525842178278029,
  2.6408059771877084, 2.205209114971179, 0.43559686221652916, 2.7054315286285773,
  2.287065828325189, 0.4183657003033883, 2.7772743854448723, 2.376430659710561,
  0.40084372573431143, 2.857589250842502, 2.4746133718636094, 0.382975878978892,
  2.947965016338654, 2.5832683132864496, 0.36469670305220464, 3.0504479274591025,
  2.7045208429018843, 0.3459270845572178, 3.1677251709421843, 2.841155565690413,
  0.32656960525177153, 3.303407331831786, 2.996905620630899, 0.3065017112008874,
  3.462479464912943, 3.176914148219092, 0.285565316693851, 3.6520542164650296,
  3.388503912184048, 0.2635503042809815, 3.882699218096911, 3.642532256152772,
  0.24016696194413883, 4.170939837786537, 3.9559429389315603, 0.2149968988549761,
  4.5444045708129694, 4.357006444181506, 0.18739812663146266, 5.053700982153701,
  4.897400951777812, 0.15630003037588766, 5.804716775356509, 5.685031893390395,
  0.11968488196611358, 7.072172579907818, 6.9992635842386655, 0.07290899566915277,
  9.9498743710662, 9.9498743710662, 0.0, 1.999899997499875,
  1.010050503787815, 0.9898494937120602, 2.000300097533387, 1.0304576260020475,
  0.9698424715313393, 2.0015018399653335, 1.0512938957393672, 0.9502079442259664,
  2.003509566260053, 1.0725859294119477, 0.9309236368481051, 2.006330560710418,
  1.0943621240238646, 0.9119684366865535, 2.009975124224178, 1.1166528467912102,
  0.8933222774329679, 2.014456679674625, 1.139490647088677, 0.8749660325859482,
  2.019791910946544, 1.1629104941813435, 0.8568814167652006, 2.0260009385377056,
  1.1869500447998675, 0.8390508937378378, 2.033107535404053, 1.2116499453418088,
  0.8214575900622438, 2.0411393876950195, 1.2370541743606176, 0.8040852133344019,
  2.050128406152894, 1.2632104320740056, 0.7869179740788883, 2.0601110952949977,
  1.2901705849322205, 0.7699405103627771, 2.0711289891204965, 1.3179911748948618,
  0.7531378142256347, 2.0832291640623697, 1.3467340050504206, 0.7364951590119488,
  2.0964648423393215, 1.3764668156773323, 0.7199980266619891, 2.110896101882131,
  1.4072640679214208, 0.7036320339607104, 2.126590712784548, 1.4392078561269162,
  0.6873828566576319, 2.143625124985847, 1.4723889747377539, 0.6712361502480935,
  2.1620856379316593, 1.5069081718917625, 0.6551774660398969, 2.182069790686946,
  1.5428776297786484, 0.6391921609082973, 2.2036880209407337, 1.5804227220888092,
  0.6232652988519247, 2.2270656543019625, 1.619684112219609, 0.6073815420823534,
  2.2523453022861735, 1.6608202734029363, 0.5915250288832373, 2.2796897698997216,
  1.7040105350765598, 0.5756792348231622, 2.3092856038177696, 1.7494587907710377,
  0.559826813046732, 2.3413474528008105, 1.7973980445743594, 0.543949408226451,
  2.376123467524206, 1.8480960302966045, 0.5280274372276014, 2.4139020437712624,
  1.901862216304631, 0.5120398274666315, 2.4550203204780643, 1.9590566193713848,
  0.49596370110667964, 2.4998749968748437, 2.0201010075756307, 0.4797739892992125,
  2.548936253300936, 2.0854932981553116, 0.46344295514562467, 2.6027658834214114,
  2.1558262872783414, 0.44693959614307055, 2.66204122828011, 2.2318123429015064,
  0.43022888537860365, 2.7275872383586823, 2.314316444667973, 0.4132707936907094,
  2.800420136546742, 2.404401127338111, 0.39601900920863026, 2.8818079873141285,
  2.503388756656718, 0.3784192306574108, 2.973356488274833, 2.612949641211216,
  0.3604068470636162, 3.0771334062727926, 2.7352296944647043, 0.34190371180808804,
  3.1958540558147233, 2.8730405148233373, 0.32281354099138615, 3.3331666624997918,
  3.030151511363447, 0.3030151511363447, 3.4941080705655354, 3.211755903247108,
  0.2823521673184271, 3.6858645968194432, 3.4252479081554426, 0.260616688664001,
  3.919113037998304, 3.6815910356953765, 0.23752200230292753, 4.2105490620886155,
  3.997895069053837, 0.21265399303477858, 4.588085255941684, 4.402708073883434,
  0.1853771820582499, 5.102848469237549, 4.948216697442472, 0.15463177179507726,
  5.861810705086615, 5.743390286802037, 0.11842041828457808, 7.142499991070982,
  7.070353526514709, 0.07214646455627255, 10.04987562112089, 10.04987562112089,
  0.0, 1.9999038808121516, 1.0098524546675214, 0.9900514261446303,
  2.0002884407389465, 1.0298514744398535, 0.9704369662990932, 2.0014434529268534,
  1.0502624059913193, 0.9511810469355343, 2.0033729274450507, 1.0711102780399284,
  0.9322626494051223, 2.006083590807607, 1.0924217573704795, 0.9136618334371278,
  2.0095849514311737, 1.1142253196054033, 0.8953596318257704, 2.0138893930227235,
  1.1365514396266856, 0.8773379533960378, 2.019012297710742, 1.1594328046259705,
  0.8595794930847713, 2.0249722013498492, 1.1829045532637732, 0.8420676480860761,
  2.0317909841257302, 1.207004545025186, 0.8247864391005443, 2.039494100390043,
  1.231773664592006, 0.807720435798037, 2.0481108525946854, 1.2572561669393119,
  0.7908546856553735, 2.057674715309792, 1.2835000699457115, 0.7741746453640804,
  2.0682237166479993, 1.3105576026284353, 0.7576661140195639, 2.079800886039749,
  1.3384857187384527, 0.7413151673012969, 2.0924547792884325, 1.3673466874558073,
  0.725108091832625, 2.106240094280516, 1.3972087754138074, 0.7090313188667084,
  2.121218393765348, 1.428147037386571, 0.6930713563787771, 2.137458955423961,
  1.4602442368737951, 0.6772147185501657, 2.1550397742434892, 1.4935919227430123,
  0.6614478515004769, 2.1740487483076762, 1.5282916943549008, 0.6457570539527752,
  2.1945850869136296, 1.5644566956215977, 0.6301283912920322, 2.216760989986629,
  1.602213388802217, 0.6145476011844121, 2.240703660851407, 1.6417036723069716,
  0.5989999885444353, 2.2665577315871053, 1.6830874244458705, 0.583470307141235,
  2.2944882029246356, 1.72654557843834, 0.5679426244862958, 2.3246840310364427,
  1.7722838652456048, 0.5524001657908378, 2.3573625346259575, 1.820537402978462,
  0.5368251316474953, 2.3927748518131526, 1.8715763692399907, 0.5211984825731619,
  2.431212753862865, 1.9257130723666256, 0.5054996814962391, 2.4730172314250742,
  1.9833108489646631, 0.48970638246041087, 2.518589423253983, 2.044795373334917,
  0.47379404991906593, 2.5684046799274403, 2.1106691924156196, 0.45773548751182086,
  2.623030881497777, 2.181530634116963, 0.4415002473808139, 2.683152615576965,
  2.2580987358816045, 0.42505387969536074, 2.7496035655057365, 2.3412466003316172,
  0.40835696517411935, 2.8234106165378328, 2.4320467687009053, 0.39136384783692724,
  2.9058550387955533, 2.5318340932080066, 0.37402094558754656, 2.9985591469319215,
  2.642294693831099, 0.3562644531008224, 3.103611993694993, 2.765594845866825,
  0.3380171478281675, 3.2237567204439284, 2.9045728867366085, 0.3191838337073196,
  3.36267879757377, 3.063034152245414, 0.2996446453283558, 3.5254663214603954,
  3.2462214643150173, 0.27924485714537783, 3.719378522783703, 3.461599813283842,
  0.2577787094998606, 3.9552002506265582, 3.720237859500228, 0.2349623911263302,
  4.249795746725822, 4.039409818670088, 0.2103859280557338, 4.631358821780329,
  4.447938670422691, 0.18342015135763678, 5.151530384858702, 4.998514630852998,
  0.15301575400570402, 5.918355855044205, 5.801160689597785, 0.11719516544641992,
  7.212142538802183, 7.140735186932855, 0.07140735186932855, 10.14889156509222,
  10.14889156509222, 0.0, 1.9999075422415888, 1.0096620601608013,
  0.9902454820807876, 2.0002774502336993, 1.0292689792464664, 0.9710084709872329,
  2.00138840697041, 1.0492715920039046, 0.9521168149665056, 2.0032441221645985,
  1.069693463291776, 0.9335506588728224, 2.0058508169851517, 1.090559667487073,
  0.9152911494980787, 2.009217282263425, 1.1118969426117984, 0.8973203396516268,
  2.013354961475882, 1.1337338618019532, 0.8796210996739291, 2.018278060051096,
  1.1561010246894627, 0.8621770353616335, 2.0240036830724666, 1.1790312716926994,
  0.8449724113797675, 2.0305520040368283, 1.20255992472084, 0.8279920793159884,
  2.037946468004401, 1.2267250584104161, 0.8112214095939847, 2.0462140332620873,
  1.2515678067525389, 0.7946462265095485, 2.0553854565506686, 1.2771327108664348,
  0.7782527456842339, 2.065495628015008, 1.3034681147667526, 0.7620275132482552,
  2.0765839633729715, 1.3306266173069528, 0.7459573460660187, 2.088694862424349,
  1.358665590120693, 0.7300292723036561, 2.101878245013908, 1.38764777340724,
  0.7142304716066679, 2.1161901780239925, 1.417641963918985, 0.6985482141050072,
  2.131693610033774, 1.4487238126443125, 0.6829697973894615, 2.1484592341177464,
  1.4809767536151457, 0.6674824805026007, 2.1665665040950546, 1.514493090241203,
  0.6520734138538515, 2.186104835690469, 1.5493752718971288, 0.6367295637933404,
  2.207175031940517, 1.5857374015883325, 0.6214376303521844, 2.2298909823360082,
  1.623707025972822, 0.6061839563631867, 2.2543816984054104, 1.6634272726098176,
  0.5909544257955929, 2.280793765779844, 1.7050594171363884, 0.5757343486434557,
  2.3092943157350887, 1.7487859866731739, 0.5605083290619146, 2.3400746498965814,
  1.7948145372993194, 0.5452601125972618, 2.3733546932559406, 1.8433822860240316,
  0.5299724072319091, 2.4093885072910144, 1.8947618358307976, 0.5146266714602167,
  2.448471173298657, 1.9492683127232024, 0.4992028605754544, 2.4909474657464044,
  2.007268346183996, 0.4836791195624085, 2.537222891273055, 2.0691914841450156,
  0.4680314071280392, 2.587777893723606, 2.13554486375249, 0.45223302997111564,
  2.643186355240041, 2.2069322966081897, 0.43625405863185135, 2.7041400158187314,
  2.284079430837181, 0.4200605849815506, 2.7714811842308174, 2.3678674195370086,
  0.4036137646938084, 2.8462472829158076, 2.4593787201893873, 0.3868685627264205,
  2.9297326385411577, 2.5599605579485845, 0.3697720805925733, 3.023576001082084,
  2.671314719402618, 0.35226128167946613, 3.12988748235043, 2.795627654138248,
  0.33425982821218186, 3.2514377600273052, 2.9357641910926153, 0.3156735689346898,
  3.391949166620303, 3.095565258857364, 0.29638390776293916, 3.55656053048694,
  3.280322819381158, 0.27623771110578177, 3.7526032630695187, 3.4975719733463477,
  0.2550312897231712, 3.9909691869953585, 3.758485545034463, 0.2324836419608947,
  4.288689443508021, 4.080500635570738, 0.20818880793728262, 4.67423628505073,
  4.492712545825459, 0.18152373922527107, 5.199759609828131, 5.048310300804011,
  0.15144930902412032, 5.974367690972049, 5.858360551341525, 0.11600713963052521,
  7.281119823375588, 7.210429339653495, 0.07069048372209308, 10.246950765959598,
  10.246950765959598, 0.0, 1.9999109983756762, 1.009478884894388,
  0.9904321134812882, 2.000267076184672, 1.0287087820378313, 0.9715582941468408,
  2.001336451869822, 1.0483190938365736, 0.9530173580332483, 2.003122562401013,
  1.0683320332805404, 0.9347905291204726, 2.0056311702248357, 1.0887712066934825,
  0.9168599635313532, 2.0088704151407044, 1.1096617531253412, 0.899208662015363,
  2.012850888208274, 1.1310304990884588, 0.881820389119815, 2.0175857290120396,
  1.1529061308640225, 0.864679598148017, 2.023090748054419, 1.1753193869649488,
  0.8477713610894704, 2.029384576547972, 1.1983032737711834, 0.8310813027767885,
  2.036488846447588, 1.2218933078685528, 0.814595538579035, 2.0444284042245155,
  1.2461277892416092, 0.7983006149829063, 2.0532315626607223, 1.2710481102185422,
  0.7821834524421799, 2.0629303958645377, 1.296699105971995, 0.7662312898925425,
  2.0735610838150595, 1.3231294534819906, 0.7504316303330691, 2.0851643140813305,
  1.350392127214576, 0.7347721868667547, 2.0977857499942565, 1.378544921424797,
  0.7192408285694594, 2.111476576553321, 1.4076510510355476, 0.7038255255177739,
  2.126294137828391, 1.4377798455791977, 0.6885142922491932, 2.1423026827023595,
  1.4690075538530465, 0.6732951288493129, 2.1595742396679976, 1.5014182809120364,
  0.6581559587559612, 2.1781896462739727, 1.5351050840407046, 0.6430845622332682,
  2.198239765020215, 1.5701712607287248, 0.62806850429149, 2.2198269254487766,
  1.6067318698486384, 0.6130950556001382, 2.243066642430056, 1.644915537782041,
  0.5981511046480149, 2.2680896739835417, 1.6848666149592024, 0.5832230590243392,
  2.295044499475125, 1.726747766271761, 0.5682967332033643, 2.324100322209071,
  1.7707431026354827, 0.5533572195735884, 2.355450731420241, 1.8170619928099,
  0.5383887386103408, 2.389318200536428, 1.865943737561782, 0.5233744629746462,
  2.4259596557734726, 1.9176633469447453, 0.5082963088287276, 2.4656734282028214,
  1.9725387425622571, 0.49313468564056423, 2.508808013192485, 2.0309398202034403,
  0.47786819298904476, 2.5557732184577815, 2.0932999694035166, 0.46247324905426535,
  2.6070545088933597, 2.160130878797355, 0.4469236300960045, 2.6632316891894763,
  2.232041796654037, 0.43118989253543905, 2.725003562395726, 2.309764924316377,
  0.41523863807934885, 2.7932209603490614, 2.39418939458491, 0.39903156576415166,
  2.8689317229186946, 2.4864074931962024, 0.3825242297224926, 2.9534430901841535,
  2.587778707589925, 0.3656643825942285, 3.048410072517037, 2.7000203499436615,
  0.34838972257337564, 3.15596362193526, 2.8253388615420425, 0.3306247603932177,
  3.278901671634696, 2.9666253219552012, 0.31227634967949486, 3.420983045851002,
  3.1277559276352016, 0.2932271182158002, 3.58739680096308, 3.3140713304135123,
  0.27332547054956796, 3.7855458183539588, 3.5331760971303616, 0.2523697212235973,
  4.026427847623897, 3.7963462563311032, 0.23008159129279418, 4.327239304683761,
  4.12118029017501, 0.20605901450875053, 4.71672818301789, 4.537043299855305,
  0.1796848831625863, 5.247548447216315, 5.097618491581563, 0.14992995563475184,
  6.029860968626961, 5.915006473986447, 0.11485449464051352, 7.349450528911878,
  7.27945576196986, 0.06999476694201788, 10.344080432788601, 10.344080432788601,
  0.0, 1.9999142642803165, 1.0093025258984765, 0.9906117383818399,
  2.000257273332539, 1.0281696264793425, 0.9720876468531967, 2.001287360401074,
  1.0474027306771978, 0.9538846297238762, 2.003007714333814, 1.0670228010937144,
  0.9359849132400999, 2.0054236804054733, 1.0870520884440884, 0.9183715919613848,
  2.0085428066528825, 1.1075142578740191, 0.9010285487788635, 2.01237490984602,
  1.1284345288856188, 0.8839403809604013, 2.01693216223369, 1.1498398308061224,
  0.8670923314275678, 2.0222292005832188, 1.1717589760388747, 0.850470224544344,
  2.0282832594585125, 1.1942228536998718, 0.8340604057586407, 2.035114331163999,
  1.2172646466775323, 0.8178496844864668, 2.0427453553397386, 1.2409200756736725,
  0.8018252796660659, 2.0512024418451382, 1.2652276744091506, 0.7859747674359876,
  2.060515131339684, 1.2902291009323255, 0.7702860304073587, 2.0707166988892576,
  1.3159694908828927, 0.7547472080063647, 2.0818445070340523, 1.3424978596761648,
  0.7393466473578877, 2.0939404160972237, 1.369867561932763, 0.7240728541644607,
  2.107051261153797, 1.3981368181487814, 0.7089144430050157, 2.1212294070964752,
  1.4273693206630487, 0.6938600864334266, 2.136533395731581, 1.4576349335364989,
  0.6788984621950818, 2.1530287019487093, 1.4890105041514436, 0.6640181977972655,
  2.1707886199082655, 1.5215808083469151, 0.6492078115613505, 2.1898953051158454,
  1.5554396559701331, 0.6344556491457122, 2.210441004513925, 1.5906911901642262,
  0.6197498143496987, 2.23252951474063, 1.6274514219604592, 0.6050780927801709,
  2.2562779190547357, 1.6658500523862068, 0.590427866668529, 2.2818186668908265,
  1.7060326481426742, 0.5757860187481524, 2.309302077676826, 1.7481632550637656,
  0.5611388226130605, 2.338899373941917, 1.7924275576003477, 0.5464718163415694,
  2.3708063800247934, 1.8390367246921293, 0.5317696553326638, 2.4052480649546846,
  1.888232125758818, 0.5170159391958666, 2.442484165814746, 1.9402911597593773,
  0.5021930060553683, 2.4828162077272387, 1.9955345220985286, 0.4872816856287103,
  2.526596348415599, 2.054335348711749, 0.47226099970385016, 2.5742386341313708,
  2.117130839285613, 0.45710779484575753, 2.626233482828139, 2.184437195997237,
  0.4417962868309019, 2.68316654646136, 2.256869057771237, 0.4262974886901227,
  2.745743606178963, 2.335165123012015, 0.4105784831669478, 2.8148239191203728,
  2.4202224351315356, 0.39460148398883726, 2.891465627791987, 2.5131430222864934,
  0.37832260550549357, 2.9769887480605344, 2.6152985263335538, 0.36169022172698073,
  3.073064382071465, 2.728421647633544, 0.34464273443792126, 3.181844110644713,
  2.8547386413260973, 0.32710546931861534, 3.306152850809338, 2.9971666030701476,
  0.30898624773919053, 3.4497855597360347, 3.159616680879733, 0.29016887885630194,
  3.6179810331804427, 3.3474777783632135, 0.27050325481722937, 3.8182129327736556,
  3.568423301657622, 0.24978963111603356, 4.061583919126564, 3.833831549829747,
  0.22775236929681666, 4.365454104956741, 4.161460922482127, 0.20399318247461404,
  4.7588446015548325, 4.580943868786427, 0.17790073276840496, 5.2949086575981354,
  5.1464532746748235, 0.14845538292331223, 6.0848497783755375, 5.971114268499359,
  0.11373550987617825, 7.417152482145437, 7.347833300069311, 0.06931918207612559,
  10.44030650891055, 10.44030650891055, 0.0, 1.9999173536642967,
  1.0091326096471211, 0.9907847440171755, 2.000248000496954, 1.027650348879169,
  0.9725976516177852, 2.0012409258499892, 1.0465204841600861, 0.954720441689903,
  2.0028990924496943, 1.0657628198356173, 0.9371362726140768, 2.00522746550976,
  1.0853983528906044, 0.919829112619156, 2.008233054204616, 1.1054493876355684,
  0.9027836665690477, 2.0119249706822404, 1.125939662491896, 0.8859853081903444,
  2.016314507597559, 1.1468944905600795, 0.8694200170374796, 2.021415235473568,
  1.1683409159159157, 0.8530743195576524, 2.027243121560175, 1.1903078878885431,
  0.836935233671632, 2.0338166722716813, 1.2128264559418283, 0.8209902163298529,
  2.041157101756155, 1.235929988219323, 0.8052271135368322, 2.049288529699769,
  1.2596544173383903, 0.7896341123613789, 2.0582382121161595, 1.284038517650448,
  0.7741996944657116, 2.068036809639357, 1.3091242189460153, 0.7589125906933418,
  2.078718698759269, 1.3349569625059525, 0.7437617362533163, 2.090322332549336,
  1.3615861065229622, 0.728736226026374, 2.1028906587854292, 1.389065389289458,
  0.7138252694959712, 2.1164716050054913, 1.4174534602330355, 0.6990181447724558,
  2.131118642090737, 1.4468144909606837, 0.6843041511300533, 2.146891440465227,
  1.4772188810540552, 0.6696725594111719, 2.1638566361465967, 1.5087440765792783,
  0.6551125595673183, 2.1820887278148593, 1.5414755233187538, 0.6406132044961055,
  2.201671131034508, 1.5755077818412073, 0.6261633491933005, 2.2226974220830753,
  1.610945838023513, 0.6117515840595621, 2.2452728119317706, 1.6479066509590976,
  0.5973661609726728, 2.2695159013685045, 1.686520990925219, 0.5829949104432854,
  2.295560781843053, 1.7269356340470672, 0.5686251477959856, 2.32355956444664,
  1.7693159986153313, 0.5542435658313086, 2.3536854430520586, 1.813849332260302,
  0.5398361107917565, 2.3861364292142917, 1.8607485915891269, 0.525387837625165,
  2.4211399390888504, 1.9102571996480835, 0.5108827394407667, 2.4589584709016927,
  1.9626549263160302, 0.49630354458566256, 2.499896692080371, 2.0182652192942445,
  0.48163147278612645, 2.5443103680164785, 2.0774644289308863, 0.4668459390855924,
  2.5926177247459115, 2.140693534193872, 0.4519241905520396, 2.645314069066717,
  2.208473213624507, 0.4368408554422103, 2.7029908287469, 2.2814234517863747,
  0.42156737696052576, 2.766360682042366, 2.3602893892655046, 0.40607129277686105,
  2.8362912178301483, 2.4459759126241645, 0.3903153052059837, 2.9138507710226813,
  2.539594708689493, 0.37425606233318837, 3.0003720007454313, 2.6425294685464347,
  0.35784253219899637, 3.0975419381638054, 2.756528146806322, 0.3410137913574832,
  3.207532588473958, 2.883836639178421, 0.3236959492955371, 3.3331955894404945,
  3.0273978289413668, 0.30579776049912794, 3.478361683321618, 3.191157507634512,
  0.28720417568710604, 3.648318931110918, 3.380552404056906, 0.2677665270540123,
  3.85061110505241, 3.603324153351797, 0.2472869517006135, 4.096444789910179,
  3.870952416153655, 0.22549237375652356, 4.403342262069016, 4.2013540849098865,
  0.20198817715912917, 4.8005952011926905, 4.624426569956261, 0.17616863123642898,
  5.341851491616981, 5.19482805606789, 0.14702343554909125, 6.139347586270607,
  6.026699006706009, 0.11264857956459831, 7.484242706439235, 7.415579929315939,
  0.06866277712329573, 10.535653752852738, 10.535653752852738, 0.0,
  1.9999202790233863, 1.008968789417203, 0.9909514896061835, 2.0002392201431918,
  1.0271498698032606, 0.9730893503399312, 2.0011969598294543, 1.0456704835144897,
  0.9555264763149647, 2.002796254386498, 1.0645493604396703, 0.9382468939468278,
  2.005041722182436, 1.0838063363148307, 0.9212353858676053, 2.007939880845941,
  1.1034624570414633, 0.9044774238044777, 2.0114992001634167, 1.1235400937849715,
  0.8879591063784451, 2.015730171524109, 1.1440630703244945, 0.8716671011996147,
  2.0206453950409013, 1.1650568043479068, 0.8555885906929941, 2.0262596857853516,
  1.1865484646490796, 0.8397112211362721, 2.032590200926194, 1.2085671464966556,
  0.8240230544295383, 2.039656589961929, 1.231144067814858, 0.808512522147071,
  2.047481170703415, 1.2543127892597494, 0.7931683814436652, 2.0560891342074314,
  1.2781094618046194, 0.777979672402812, 2.0655087825066842, 1.3025731060852963,
  0.7629356764213876, 2.0757718037500075, 1.3277459285247797, 0.7480258752252279,
  2.086913590289098, 1.3536736801875233, 0.7332399101015747, 2.0989736063635362,
  1.3804060654462897, 0.7185675409172466, 2.1119958133929795, 1.407997208928653,
  0.7039986044643265, 2.1260291625469296, 1.4365061909100876, 0.6895229716368422,
  2.141128166308921, 1.4659976634187206, 0.6751305028902005, 2.157353563288025,
  1.4965425619205217, 0.6608110013675034, 2.174773093692713, 1.5282189307029879,
  0.6465541629897255, 2.193462406850109, 1.561112884154582, 0.6323495226955269,
  2.213506127165678, 1.5953197312905785, 0.6181863958750994, 2.234999111292685,
  1.6309452974297969, 0.6040538138628878, 2.2580479374461646, 1.6681074853205902,
  0.5899404521255744, 2.2827726783356126, 1.706938128845548, 0.5758345494900645,
  2.309309022903887, 1.7475852065218607, 0.5617238163820266, 2.3378108300553713,
  1.790215500492852, 0.5475953295625193, 2.3684532213865324, 1.8350178111643405,
  0.5334354102221919, 2.401436351795345, 1.8822068703260815, 0.519229481469264,
  2.436990039894594, 1.9320281397362549, 0.5049619001583392, 2.475379498965439,
  1.9847637424137305, 0.4906157565517086, 2.5169124905026963, 2.0407398571643482,
  0.47617263333834786, 2.561948336298957, 2.100336023452298, 0.4616123128466588,
  2.6109093868012647, 2.1639969692406877, 0.44691241756057687, 2.6642957768269,
  2.232247813017133, 0.4320479638097676, 2.7227046419646563, 2.305713840943042,
  0.41699080102161407, 2.7868554801948844, 2.385146582148775, 0.4017088980461095,
  2.8576241224135828, 2.4714587004658015, 0.3861654219477814, 2.936088989915161,
  2.565771459655591, 0.3703175302595699, 3.0235952572861637, 2.6694804974238204,
  0.35411475986234353, 3.121845727437656, 2.7843488920389907, 0.3374968353986655,
  3.2330326320654423, 2.912642010869768, 0.3203906211956744, 3.360034074663275,
  3.0573283021710878, 0.30270577249218694, 3.5067162450830565, 3.222387900887133,
  0.28432834419592345, 3.6784160091769906, 3.4133049454525226, 0.26511106372446774,
  3.882746599231806, 3.637888705586557, 0.244857893645249, 4.1310175650133685,
  3.9077193182558894, 0.2232982467574794, 4.440911856050236, 4.240870781453379,
  0.2000410745968575, 4.841989241322631, 4.66750314253623, 0.17448609878640112,
  5.38838772010907, 5.242755619565581, 0.14563210054348838, 6.193367271940008,
  6.081775068841989, 0.11159220309801816, 7.550737471508088, 7.48271280960261,
  0.06802466190547829, 10.63014581273465, 10.63014581273465, 0.0,
  1.9999230517668953, 1.0088107429266633, 0.9911123088402322, 2.0002308980015773,
  1.0266671865848804, 0.973563711416697, 2.001155290363024, 1.0448509923134373,
  0.9563042980495868, 2.002698796408437, 1.0633798918982853, 0.9393189045101518,
  2.004865717449585, 1.0822726439329626, 0.9225930735166228, 2.0076621219791386,
  1.10154912887351, 0.9061129931056284, 2.011095893180013, 1.1212304537198305,
  0.8898654394601827, 2.0151767912518244, 1.1413390676116526, 0.8738377236401716,
  2.0199165315300798, 1.1618988898181875, 0.8580176417118925, 2.0253288796408033,
  1.182935451825602, 0.8423934278152014, 2.0314297652334754, 1.2044760554924143,
  0.8269537097410609, 2.038237416177488, 1.2265499495581345, 0.8116874666193536,
  2.045772515502441, 1.249188527165207, 0.7965839883372339, 2.0540583838235573,
  1.2724255475013186, 0.7816328363222387, 2.0631211905361195, 1.2962973852041104,
  0.766823805332009, 2.0729901977067717, 1.3208433118131642, 0.7521468858936072,
  2.083698041359236, 1.346105814329418, 0.737592227029818, 2.095281055778127,
  1.3721309568812514, 0.7231500988968755, 2.107779647575866, 1.3989687926388492,
  0.708810854937017, 2.1212387276334996, 1.4266738345145662, 0.6945648931189335,
  2.135708210699571, 1.4553055949014773, 0.6804026157980934, 2.151243594493428,
  1.484929206818472, 0.6663143876749555, 2.1679066327159013, 1.5156161414562497,
  0.6522904912596516, 2.185766119558944, 1.547445040395713, 0.6383210791632314,
  2.2048988073078637, 1.580502684884398, 0.624396122423466, 2.2253904836855147,
  1.6148851297540903, 0.6105053539314245, 2.247337242018343, 1.6506990361727654,
  0.5966382058455777, 2.270846985542186, 1.6880632458897664, 0.5827837396524194,
  2.2960412177993827, 1.7271106505570575, 0.5689305672423248, 2.3230571849150383,
  1.76799042391764, 0.5550667609973985, 2.35205045369759, 1.8108707032892948,
  0.541179750408295, 2.3831980335534158, 1.8559418314398282, 0.5272562021135876,
  2.416702182355585, 1.9034203029172307, 0.5132818794383542, 2.4527950798433413,
  1.9535536034150507, 0.4992414764282907, 2.4917446114702866, 2.0066261915380186,
  0.4851184199322682, 2.5338615876670425, 2.0629669563306896, 0.470894631336353,
  2.5795088384059155, 2.1229586015199127, 0.45655023688600277, 2.629112786198643,
  2.187049574359933, 0.4420632118387099, 2.6831783361117654, 2.2557693976160857,
  0.4274089384956794, 2.742308266703368, 2.329748615960383, 0.4125596507429845,
  2.8072288215893044, 2.4097450946386063, 0.39748372695069795, 2.8788239875026065,
  2.4966792104004907, 0.3821447771021159, 2.958182169989156, 2.5916817241497916,
  0.36650044583936436, 3.0466609357036853, 2.6961601200917573, 0.35050081561192836,
  3.1459787071585366, 2.81189247277002, 0.3340862343885171, 3.2583477508331544,
  2.9411634565042637, 0.31718429432889117, 3.386672388585604, 3.0869668674718342,
  0.2997055211137703, 3.5348539301776403, 3.253316891490926, 0.2815370386867147,
  3.7082775990104557, 3.4457446716468842, 0.2625329273635721, 3.914625454986746,
  3.672126532996417, 0.24249892199032938, 4.165309080125664, 3.9441422263136823,
  0.22116685381198212, 4.4781706472262774, 4.280021503543699, 0.19814914368257866,
  4.883035602701224, 4.71018478490649, 0.17285081779473363, 5.434527662004391,
  5.2902481665529475, 0.144279495451444, 6.246921163583227, 6.136356187236621,
  0.1105649763466058, 7.616652339259214, 7.5492483362569205, 0.06740400300229392,
  10.723805294763608, 10.723805294763608, 0.0, 1.99992568232909,
  1.0086581702181492, 0.991267512110941, 2.0002230027324766, 1.0262013666192704,
  0.9740216361132059, 2.0011157601983665, 1.0440603966252346, 0.9570553635731319,
  2.0026063494256827, 1.062252063608406, 0.940354285817277, 2.004698781438517,
  1.080794125645114, 0.923904655793403, 2.0073987136808005, 1.0997053822773086,
  0.907693331403492, 2.0107134927681765, 1.1190057698883766, 0.8917077228797999,
  2.014652210534554, 1.1387164668238783, 0.8759357437106758, 2.019225774219596,
  1.1588600095521158, 0.8603657646674802, 2.0244469918735533, 1.1794604213524185,
  0.8449865705211352, 2.030330674313626, 1.2005433552463178, 0.8297873190673082,
  2.036893755258915, 1.222136253155349, 0.814757502103566, 2.0441554316077406,
  1.2442685235873205, 0.7998869080204204, 2.0521373262123084, 1.2669717405310772,
  0.7851655856812312, 2.060863675964301, 1.2902798666906927, 0.7705838092736081,
  2.0703615485468183, 1.3142295047297197, 0.7561320438170988, 2.0806610918529187,
  1.3388601808444869, 0.7418009110084318, 2.091795820843316, 1.36421466576738,
  0.7275811550759359, 2.1038029475464812, 1.3903393392481092, 0.713463608298372,
  2.1167237610324783, 1.4172846052130506, 0.6994391558194276, 2.130604065566976,
  1.4451053662106443, 0.6854986993563315, 2.1454946868376807, 1.473861567479798,
  0.6716331193578827, 2.161452058223823, 1.5036188231122247, 0.6578332351115982,
  2.178538901656738, 1.534449139427789, 0.6440897622289485, 2.1968250208349382,
  1.5664317539866517, 0.6303932668482867, 2.2163882285932353, 1.5996541128107697,
  0.6167341157824655, 2.2373154353248577, 1.6342130136285917, 0.6031024216962658,
  2.2597039318420773, 1.6702159496224052, 0.5894879822196722, 2.28366290837106,
  1.7077826966948795, 0.5758802116761804, 2.309315262103892, 1.7470471982872924,
  0.5622680638165998, 2.3367997596891175, 1.788159816109933, 0.5486399435791841,
  2.3662736393599086, 1.8312900339394078, 0.5349836054205012, 2.3979157616563596,
  1.8766297265136724, 0.5212860351426869, 2.4319304501333328, 1.9243971388011591,
  0.5075333113321738, 2.468552207266437, 1.9748417658131496, 0.4937104414532874,
  2.508051550635505, 2.0282503844269737, 0.47980116620853136, 2.550742297239093,
  2.084954573395432, 0.4657877238436604, 2.596990739732362, 2.1453401763006466,
  0.4516505634317151, 2.6472273230684213, 2.2098593305614647, 0.4373679925069566,
  2.7019616675588005, 2.2790459282887277, 0.4229157392700732, 2.761802132740172,
  2.3535357305090163, 0.4082664022311559, 2.8274816367957394, 2.434092887328506,
  0.3933887494672333, 2.8998922393771807, 2.5216454255453744, 0.3782468138318062,
  2.980132231766215, 2.617333525290328, 0.362798706475887, 3.0695714534056746,
  2.722576419542425, 0.3469950338632501, 3.1699437990791552, 2.8391670548274175,
  0.3307767442517379, 3.2834813841409245, 2.9694092517448363, 0.31407213239608833,
  3.4131145086783494, 3.116321942706319, 0.29679256597203035, 3.562779283988147,
  3.2839530791542924, 0.27882620483385495, 3.7379088561416833, 3.4778804139753055,
  0.260028442166378, 3.9462534975171915, 3.7060467628857103, 0.24020673463148118,
  4.199325914825533, 3.980230649704201, 0.2190952651213321, 4.5151260930746595,
  4.318816262940978, 0.19630983013368086, 4.9237428083972095, 4.752482188974697,
  0.17126061942251164, 5.4802812101987195, 5.337317352541362, 0.14296385765735792,
  6.300021070339818, 6.190455486507821, 0.10956558383199683, 7.682002206113771,
  7.615202186930173, 0.06680001918359801, 10.816653826391969, 10.816653826391969,
  0.0, 1.9999281802675053, 1.0085107917588267, 0.9914173885086786,
  2.00021550563071, 1.0257515413490819, 0.9744639642816282, 2.0010782253195765,
  1.043297194397386, 0.9577810309221904, 2.0025185754847046, 1.0611636895730916,
  0.9413548859116129, 2.0045403009622476, 1.0793678543642875, 0.9251724465979602,
  2.007148682418254, 1.097927484399729, 0.9092211980185247, 2.0103505748904253,
  1.1168614304946807, 0.8934891443957446, 2.0141544582822295, 1.1361896944156167,
  0.8779647638666129, 2.0185705005452848, 1.155933534500291, 0.8626369660449937,
  2.023610634484806, 1.176115582435614, 0.847495052049192, 2.029288649344949,
  1.1967599726906106, 0.8325286766543384, 2.035620298582228, 1.2178924863312472,
  0.8177278122509807, 2.0426234255230833, 1.2395407112148626, 0.8030827143082206,
  2.0503181089348272, 1.2617342208829703, 0.7885838880518569, 2.058726830928174,
  1.2845047748526213, 0.7742220560755525, 2.067874670067229, 1.3078865434613247,
  0.7599881266059045, 2.0777895231051633, 1.3319163609648481, 0.745873162140315,
  2.0885023594104837, 1.3566340112409978, 0.7318683481694858, 2.100047512924653,
  1.3820825512410106, 0.7179649616836421, 2.112463017427761, 1.408308678285174,
  0.704154339142587, 2.1257909920244162, 1.4353631484609306, 0.6904278435634857,
  2.1400780851469685, 1.463301254801346, 0.6767768303456226, 2.155375987071779,
  1.4921833756650777, 0.6631926114067012, 2.171742023039142, 1.5220756058906806,
  0.6496664171484615, 2.1892398416659034, 1.5530504859681196, 0.6361893556977839,
  2.207940216581962, 1.585187847802434, 0.6227523687795277, 2.227921983292136,
  1.6185757998276202, 0.6093461834645157, 2.2492731384077813, 1.653311879513412,
  0.5959612588943694, 2.2720921349348764, 1.6895044080284973, 0.5825877269063786,
  2.296489415687265, 1.7272740904314472, 0.5692153252558179, 2.3225892377139177,
  1.7667559158678519, 0.5558333218460659, 2.3505318547086316, 1.808101426698947,
  0.5424304280096842, 2.3804761428476167, 1.8514814444370353, 0.5289946984105816,
  2.4126027799687715, 1.8970893654455299, 0.5155134145232416, 2.4471181207236796,
  1.9451451728829248, 0.5019729478407549, 2.484258954535837, 1.99590035663563,
  0.48835859790020725, 2.5242983935863643, 2.049643994792347, 0.47465439879401733,
  2.5675532215427483, 2.106710335624819, 0.4608428859179292, 2.614393150693245,
  2.1674883386089294, 0.44690481208431543, 2.6652526012690485, 2.2324338027723654,
  0.43281879849668303, 2.7206458563359703, 2.3020849553612055, 0.41856090097476467,
  2.781186797034676, 2.3770827325082697, 0.4041040645264059, 2.8476149478272355,
  2.458197519064537, 0.3894174287626989, 2.920830361386981, 2.546364930439932,
  0.3744654309470488, 3.001941119581944, 2.6427344898883782, 0.3592066296935658,
  3.092329219213245, 2.748737083745107, 0.3435921354681384, 3.1937438845342623,
  2.8661804091974146, 0.3275634753368474, 3.308436899350074, 2.997387276334255,
  0.31104962301581895, 3.439364308694041, 3.1454015472671997, 0.2939627614268411,
  3.5904967158690826, 3.31430466080223, 0.2761920550668525, 3.7673147665756197,
  3.509720594502073, 0.2575941720735466, 3.977636347014507, 3.7396581040307333,
  0.23797824298377387, 4.233074405077109, 4.015993666355206, 0.21708073872190303,
  4.551785364008281, 4.357264621956645, 0.194520742051636, 4.964119043305287,
  4.794405571739294, 0.1697134715659927, 5.525657855571779, 5.383974320813528,
  0.14168353475825074, 6.352678312265657, 6.2440855206029955, 0.10859279166266081,
  7.746801342133588, 7.680589364850395, 0.06621197728319306, 10.908712114635714,
  10.908712114635714, 0.0, 1.9999305543498809, 1.0083683467310316,
  0.9915622076188494, 2.0002083803641892, 1.0253169008589538, 0.9748914795052354,
  2.001042553631994, 1.042559985925913, 0.958482567706081, 2.0024351646667506,
  1.060112734235339, 0.9423224304314118, 2.004389713853072, 1.0779911066100556,
  0.9263986072430161, 2.0069111359729677, 1.0962119650272515, 0.9106991709457162,
  2.010005835013949, 1.1147931521926104, 0.8952126828213389, 2.0136817297432517,
  1.1337535789310746, 0.8799281508121772, 2.0179483106896927, 1.15311332039411,
  0.8648349902955828, 2.0228167093470253, 1.1728937222264266, 0.8499229871205987,
  2.0282997806044354, 1.1931175180026086, 0.8351822626018266, 2.0344121996262037,
  1.213808959440844, 0.8206032401853597, 2.041170574649462, 1.2349939611324474,
  0.8061766135170143, 2.048593577453658, 1.2567002617993024, 0.7918933156543556,
  2.056702093586388, 1.2789576044150646, 0.7777444891713233, 2.065519394818255,
  1.3017979379106654, 0.7637214569075899, 2.075071336757264, 1.3252556436432947,
  0.7498156931139695, 2.0853865850969515, 1.3493677903568508, 0.7360187947401008,
  2.0964968746218404, 1.3741744220210381, 0.7223224526008023, 2.1084373058737715,
  1.3997188837313272, 0.7087184221424442, 2.121246685324458, 1.4260481918147616,
  0.6951984935096963, 2.1349679160428727, 1.4532134554577538, 0.681754460585119,
  2.1496484472412165, 1.4812703586031915, 0.6683780886380253, 2.1653407927949155,
  1.5102797126216638, 0.6550610801732518, 2.1821031309436485, 1.5403080924308108,
  0.6417950385128378, 2.2, 1.5714285714285716, 0.6285714285714287,
  2.219103108161305, 1.6037215739653128, 0.615381534195992, 2.239492279624577,
  1.63727586829696, 0.6022164113276173, 2.261256564390693, 1.6721897282889155,
  0.5890668361017773, 2.2844955457417626, 1.7085722989161083, 0.5759232468256544,
  2.3093208878289224, 1.746545209282378, 0.5627756785465442, 2.33585817672021,
  1.7862444880801602, 0.5496136886400496, 2.3642491224580118, 1.827822850975942,
  0.5364262714820699, 2.3946542083105715, 1.871452448511623, 0.5232017597989483,
  2.4272558980796988, 1.9173281883990896, 0.509927709680609, 2.4622625453239673,
  1.9656717798804781, 0.4965907654434892, 2.4999131929373513, 2.016736693462065,
  0.48317649947528646, 2.540483512427542, 2.070814291642618, 0.46966922078492374,
  2.5842932164465062, 2.128241472367711, 0.4560517440787953, 2.631715396072669,
  2.1894102874890273, 0.44230510858364186, 2.6831884018831027, 2.254780169649666,
  0.42840823223343666, 2.739231129500274, 2.324893647727123, 0.4143374817731507,
  2.8004629246952355, 2.400396792595916, 0.4000661320993193, 2.8676298524868558,
  2.482066174841564, 0.38556367764529154, 2.941639881478984, 2.570844938435415,
  0.37079494304356936, 3.0236107921196176, 2.6678918753996625, 0.35571891671995504,
  3.114936626751698, 2.774649432232605, 0.34028719451909306, 3.217381800565651,
  2.892939938323737, 0.32444186224191446, 3.333217590583135, 3.0251050401930977,
  0.30811255039003765, 3.465425560003649, 3.1742133280705693, 0.2912122319330797,
  3.6180105030251086, 3.3443794565778315, 0.2736310464472771, 3.7965001532218348,
  3.541273252164905, 0.25522690105693, 4.008779427706144, 3.7729688731351945,
  0.23581055457094968, 4.266560655025175, 4.0514399497297875, 0.21512070529538696,
  4.588155358163374, 4.395375721265753, 0.1927796368976207, 5.004172172341273,
  4.835964704363415, 0.16820746797785793, 5.570666709309299, 5.430229733444358,
  0.14043697586494033, 6.404903748128619, 6.297258306983601, 0.1076454411450188,
  7.811063427242591, 7.745424238778368, 0.06563918846422345, 11.0,
  11.0, 0.0, 1.9999328126312064, 1.0082305914917644,
  0.991702221139442, 2.0002016027423095, 1.0248966890084559, 0.9753049137338538,
  2.001008623797031, 1.0418474652827519, 0.9591611585142793, 2.0023558323410815,
  1.059097299750655, 0.9432585325904266, 2.0042465039468067, 1.0766613450953921,
  0.9275851588514145, 2.0066852554114494, 1.0945555938607907, 0.9121296615506587,
  2.009678076247351, 1.112796951310517, 0.8968811249368344, 2.013232369887639,
  1.1314033153087562, 0.8818290545788829, 2.0173570051679612, 1.1503936641040438,
  0.8669633410639175, 2.0220623787945473, 1.1697881530216392, 0.8522742257729081,
  2.0273604896750053, 1.189608221214259, 0.8377522684607464, 2.0332650261750596,
  1.2098767097901177, 0.8233883163849416, 2.0397914675768525, 1.230617992835622,
  0.8091734747412308, 2.0469572012584396, 1.2518581230836734, 0.7950990781747662,
  2.054781657396831, 1.2736249942542337, 0.7811566631425971, 2.0632864633269623,
  1.2959485224202412, 0.7673379409067211, 2.0724956200769387, 1.31886084913987,
  0.7536347709370687, 2.082435704058702, 1.3423965695585018, 0.7400391345002,
  2.0931360974389888, 1.3665929892370257, 0.7265431082019631, 2.1046292513681086,
  1.3914904141276754, 0.7131388372404335, 2.116950987028628, 1.4171324789199904,
  0.6998185081086373, 2.130140840414079, 1.4435665199500372, 0.6865743204640421,
  2.1442424578992103, 1.470844000046566, 0.6733984578526443, 2.159304051068864,
  1.499020994130451, 0.6602830569384128, 2.1753789209975603, 1.5281587461553108,
  0.6472201748422493, 2.192526064300185, 1.558324310163768, 0.6342017541364171,
  2.210810875914998, 1.5895912909471472, 0.6212195849678505, 2.2303059668759246,
  1.6220407031824908, 0.6082652636934339, 2.251092119469365, 1.6557619721716816,
  0.5953301472976834, 2.2732594074001615, 1.6908541046778058, 0.5824053027223555,
  2.2969085152442688, 1.7274270651837063, 0.5694814500605625, 2.32215229998978,
  1.765603401645122, 0.5565488983446581, 2.3491176484720016, 1.805520176098315,
  0.5435974723736862, 2.3779476988274286, 1.8473312701634572, 0.5306164286639716,
  2.4088045128832167, 1.8912101547430213, 0.5175943581401953, 2.441872311283984,
  1.9373532387046486, 0.5045190725793355, 2.4773614164325855, 1.9859839454046346,
  0.4913774710279508, 2.5155130932771907, 2.037357711910452, 0.47815538136673874,
  2.5566055393935865, 2.0917681685947525, 0.46483737079883386, 2.6009613607279904,
  2.1495548435768517, 0.45140651715113883, 2.6489569883038904, 2.2111128580057264,
  0.4378441302981637, 2.7010346601430566, 2.276905250699105, 0.4241294094439511,
  2.7577178363264525, 2.3474788193522693, 0.410239016974183, 2.819631272493003,
  2.4234847300766305, 0.3961465424163724, 2.887527510873346, 2.50570569125373,
  0.3818218196196159, 2.962322361523962, 2.5950923167069417, 0.36723004481702015,
  3.045143214409083, 2.6928125945600985, 0.3523306198489848, 3.1373960489957224,
  2.800320440425934, 0.3370756085697883, 3.240860336910434, 2.919452700192044,
  0.32140763671839007, 3.357826678076163, 3.052569707341966, 0.30525697073419666,
  3.491301933260598, 3.2027645834043503, 0.2885373498562478, 3.6453247944652145,
  3.374184933719868, 0.27113986074534646, 3.8254696821547998, 3.5725460668057223,
  0.2529236153490777, 4.039687976486355, 3.805987019168962, 0.23370095731739246,
  4.299790548127196, 4.086577793674607, 0.21321275445258822, 4.624242715262162,
  4.433158305540586, 0.19108440972157695, 5.04390975742287, 4.877168938995668,
  0.16674081842720234, 5.615316523671391, 5.476093799944001, 0.13922272372738984,
  6.456707801213565, 6.349985358218299, 0.10672244299526554, 7.874801584801994,
  7.8097205799689196, 0.06508100483307433, 11.090536506409418, 11.090536506409418,
  0.0, 1.999934962522136, 1.0080972981818888, 0.9918376643402472,
  2.000195150510295, 1.024490199041858, 0.9757049514684368, 2.000976324197765,
  1.0411584125907072, 0.9598179116070581, 2.002280316727302, 1.0581156145306883,
  0.9441647021966137, 2.0041101966336043, 1.0753762030716905, 0.9287339935619139,
  2.0064702879675207, 1.0929553601123896, 0.9135149278551313, 2.0093661988319607,
  1.1108691180534418, 0.8984970807785189, 2.0128048587007847, 1.1291344329297088,
  0.8836704257710759, 2.016794565011597, 1.147769264640746, 0.8690253003708511,
  2.0213450396537893, 1.1667926651660088, 0.8545523744877807, 2.0264674961174465,
  1.186224875776066, 0.8402426203413805, 2.032174718230445, 1.2060874343969303,
  0.8260872838335145, 2.0384811515943446, 1.2264032944551342, 0.8120778571392102,
  2.045403009039479, 1.2471969567313892, 0.7982060523080896, 2.052958391661832,
  1.2684946159861723, 0.7844637756756597, 2.061167427285998, 1.2903243243985516,
  0.7708431028874462, 2.070052428528366, 1.3127161741887199, 0.7573362543396464,
  2.0796380730232684, 1.3357025021856765, 0.743935570837592, 2.089951608835173,
  1.3593181195675923, 0.7306334892675808, 2.1010230886282955, 1.383600570560097,
  0.7174225180681982, 2.1128856368212916, 1.4085904245475278, 0.7042952122737639,
  2.125575754744259, 1.4343316068599472, 0.6912441478843119, 2.1391336697698105,
  1.4608717744769437, 0.6782618952928666, 2.1536037355497313, 1.4882627440790828,
  0.6653409914706485, 2.1690348919049462, 1.5165609813319136, 0.6524739105730326,
  2.18548119465488, 1.545828162072964, 0.639653032581916, 2.2030024278174767,
  1.5761318182759183, 0.6268706095415584, 2.221664813273171, 1.6075460844009122,
  0.6141187288722587, 2.241541836308564, 1.640152563152608, 0.6013892731559562,
  2.2627152096276104, 1.6740413339521345, 0.5886738756754759, 2.2852760036904685,
  1.7093121328416512, 0.5759638708488172, 2.309325977947799, 1.7460757394239457,
  0.5632502385238534, 2.3349791561327624, 1.784455615255932, 0.5505235408768302,
  2.3623636998679354, 1.824589849491495, 0.5377738503764404, 2.3916241492819417,
  1.8666334823663937, 0.5249906669155481, 2.4229241182778334, 1.9107612965280474,
  0.5121628217497859, 2.456449557186463, 1.9571711919046615, 0.4992783652818014,
  2.4924127290882647, 2.0060882941442126, 0.48632443494405164, 2.5310570914145734,
  2.057769993019978, 0.47328709839459504, 2.5726633363642675, 2.112512170510496,
  0.4601511658537714, 2.6175569292901475, 2.170656965752805, 0.4468999635373423,
  2.6661176041309327, 2.232602546548667, 0.43351505758226555, 2.718791445307441,
  2.2988155309916576, 0.41997591431578357, 2.776106431189776, 2.3698469534546867,
  0.4062594777350892, 2.838692674564989, 2.4463530366169826, 0.3923396379480066,
  2.9073091337386874, 2.529122579756419, 0.3781865539822683, 2.9828793881825737,
  2.619113609135918, 0.36376577904665525, 3.0665403510749116, 2.717503237944434,
  0.3490371131304777, 3.1597098337926908, 2.8257567619284227, 0.3339530718642681,
  3.2641822337127038, 2.9457254304236593, 0.3184568032890443, 3.3822673080135375,
  3.0797881178659856, 0.30247919014755215, 3.516997000317366, 3.2310622848444095,
  0.28593471547295657, 3.6724436149875954, 3.4037282285250883, 0.268715386462507,
  3.854227868687594, 3.6035463812932793, 0.2506814873943151, 4.0703670511434815,
  3.8387201457938525, 0.2316469053496291, 4.3327697576600785, 4.121415135335196,
  0.2113546223248818, 4.660053829615625, 4.4706207471109245, 0.18943308250470023,
  5.083339073331011, 4.918027233547889, 0.1653118397831223, 5.659615711335886,
  5.521576303742327, 0.13803940759355818, 6.508100483307433, 6.402277711221134,
  0.10582277208629974, 7.938028412771474, 7.8734915964074785, 0.06453681636399572,
  11.180339887498949, 11.180339887498949, 0.0, 1.9999370108498655,
  1.0079682534683314, 0.9919687573815342, 2.000189003166225, 1.0240967696211065,
  0.9760922335451183, 2.000945552018784, 1.0404916870497678, 0.9604538649690164,
  2.002208376727653, 1.0571660229122006, 0.9450423538154522, 2.0039803549032986,
  1.0741334702281684, 0.9298468846751302, 2.0062655407194474, 1.0914084541513798,
  0.9148570865680677, 2.009069190813427, 1.1090061933290118, 0.9000629974844152,
  2.0123977981401153, 1.1269427669584648, 0.8854550311816504, 2.0162591342103853,
  1.1452351882314988, 0.8710239459788867, 2.0206623002588144, 1.1639014849490774,
  0.856760815309737, 2.0256177880110418, 1.1829607881984483, 0.8426569998125936,
  2.031137550861524, 1.202433430110022, 0.8287041207515021, 2.037235086431024,
  1.2223410518586146, 0.8148940345724095, 2.043925531654069, 1.242706723245674,
  0.8012188084083953, 2.051225771754743, 1.2635550754009213, 0.7876706963538216,
  2.0591545647103624, 1.2849124483792662, 0.7742421163310962, 2.0677326830840053,
  1.3068070557090912, 0.760925627374914, 2.076983075437105, 1.329269168279747,
  0.7477139071573576, 2.0869310499230824, 1.3523313203501577, 0.734599729572925,
  2.0976044831253327, 1.3760285409302184, 0.7215759421951143, 2.1090340577540707,
  1.4003986143487033, 0.7086354434053677, 2.1212535334768408, 1.425482374496437,
  0.6957711589804038, 2.134300055952273, 1.4513240380475456, 0.6829760179047275,
  2.1482145100979437, 1.4779715829473856, 0.6702429271505582, 2.163041924791459,
  1.5054771796548556, 0.6575647451366036, 2.178831937630847, 1.5338976840921161,
  0.6449342535387307, 2.195639330132132, 1.5632952030540783, 0.6323441270780542,
  2.213524645904059, 1.5937377450509225, 0.6197869008531368, 2.232554907023082,
  1.6252999723128037, 0.6072549347102781, 2.252804447180858, 1.6580640731251113,
  0.5947403740557464, 2.2743558843821523, 1.6921207779803213, 0.582235106401831,
  2.2973012612860297, 1.7275705484870945, 0.5697307127989354, 2.3217433880453044,
  1.7645249749144312, 0.5572184131308732, 2.3477974311634675, 1.803108427133543,
  0.5446890040299245, 2.375592803073568, 1.8434600151850888, 0.5321327878884792,
  2.405275421698606, 1.8857359306117072, 0.5195394910868989, 2.4370104283545273,
  1.9301122592567856, 0.5068981690977417, 2.4709854776524347, 1.9767883821219474,
  0.4941970955304871, 2.5074147468799985, 2.0259911154790387, 0.48142363140095973,
  2.54654385803878, 2.0779797881596442, 0.4685640698791354, 2.588655968142819,
  2.1330525177496824, 0.45560345039313616, 2.6340793696990463, 2.191554035589607,
  0.44252533410943984, 2.68319706418682, 2.2538855339169293, 0.42931153026989116,
  2.736458943081334, 2.3205171837329717, 0.41594175934836275, 2.794397458650249,
  2.392004224604613, 0.4023932340456358, 2.8576480300020304, 2.4690078979217542,
  0.38864013208027615, 2.9269759724376283, 2.552323047965612, 0.3746529244720164,
  3.0033125650914796, 2.642915057280502, 0.36039750781097757, 3.087804160651147,
  2.7419700946582184, 0.3458340659929285, 3.181880300215261, 2.8509647489928738,
  0.33091555122238714, 3.287350179841097, 2.9717645625763516, 0.3155856172647453,
  3.4065425527567816, 3.1067668081141844, 0.29977574464259676, 3.5425142363333566,
  3.2591130974266886, 0.2834011389066685, 3.6993708691595395, 3.4330161665800527,
  0.26635470257948685, 3.882779083247815, 3.6342812219199545, 0.24849786132786017,
  4.100821538196413, 3.871175532057413, 0.22964600613899913, 4.365503756637908,
  4.1559595763192885, 0.20954418031861963, 4.695594862326935, 4.507771067833858,
  0.1878237944930774, 5.122467122538475, 4.958548174617244, 0.1639189479212312,
  5.703572363433117, 5.566686626710722, 0.1368857367223948, 6.559091417018227,
  6.454145954345935, 0.10494546267229163, 8.0007560126649, 7.936749964563579,
  0.06400604810131919, 11.269427669584644, 11.269427669584644, 0.0
};
/* clang-format on */
/* clang-format off */
static const float SHLI_SH_DIAG[64] = {
  0.282094792f, -0.488602512f, 0.546274215f, -0.59004359f, 0.625835735f, -0.656382057f,
  0.683184105f, -0.707162733f, 0.72892666f, -0.748900952f, 0.767395118f, -0.784642106f,
  0.800821996f, -0.816077119f, 0.830522083f, -0.844250651f, 0.857340589f, -0.869857172f,
  0.881855769f, -0.893383784f, 0.904482145f, -0.915186448f, 0.925527866f, -0.935533864f,
  0.945228774f, -0.954634267f, 0.963769732f, -0.97265259f, 0.981298561f, -0.989721879f,
  0.997935479f, -1.00595115f, 1.01377969f, -1.02143096f, 1.02891407f, -1.0362374f,
  1.04340868f, -1.05043508f, 1.05732325f, -1.06407938f, 1.07070922f, -1.07721815f,
  1.08361119f, -1.08989305f, 1.09606813f, -1.10214057f, 1.10811428f, -1.11399291f,
  1.11977993f, -1.12547859f, 1.13109198f, -1.13662303f, 1.14207449f, -1.14744899f,
  1.15274901f, -1.15797692f, 1.16313498f, -1.16822531f, 1.17324995f, -1.17821086f,
  1.18310989f, -1.18794881f, 1.1927293f, -1.197453f
};
/* clang-format on */
/* @generated end sh_tab */

/* Run-time loop for any n: the same recurrence as the generated code, constants from
   SHLI_SH_TAB. x, y, z: unit direction; t = 1 - |z| computed without cancellation; sg: sign
   of z (the recurrence runs at |z| and the parity (-1)^(l-m) is restored through U, V). */
SHLIGHT_CPU_INLINE void shli_sh_core_loop(int n, shli_real x, shli_real y, shli_real z, shli_real t,
                                          float sg, float *out_y) {
  shli_real pc = 1.0;
  shli_real ps = 0.0;
  shli_real qc;
  shli_real xa;
  shli_real dd;
  float ec;
  float es;
  float oc;
  float os;
  float sw;
  float k;
  float xf;
  int m;
  int l;
  int j;
  int b;
  SHLIGHT_UNUSED(z);
  for (m = 0; m < n; ++m) {
    if (m > 0) {
      qc = x * pc - y * ps;
      ps = x * ps + y * pc;
      pc = qc;
    }
    ec = SHLIGHT_FLOAT(pc);
    es = SHLIGHT_FLOAT(ps);
    oc = sg * ec;
    os = sg * es;
    k = SHLI_SH_DIAG[m];
    out_y[m * m + 2 * m] = k * ec;
    if (m > 0) {
      out_y[m * m] = k * es;
    }
    xa = SHLIGHT_REAL(k);
    dd = 0.0;
    for (l = m + 1; l < n; ++l) {
      j = 3 * ((l * (l - 1)) / 2 + m);
      dd = SHLI_SH_TAB[j + 2] * dd - (SHLI_SH_TAB[j] * t) * xa;
      xa = SHLI_SH_TAB[j + 1] * xa + dd;
      xf = SHLIGHT_FLOAT(xa);
      sw = ec;
      ec = oc;
      oc = sw;
      sw = es;
      es = os;
      os = sw;
      b = l * (l + 1);
      out_y[b + m] = xf * ec;
      if (m > 0) {
        out_y[b - m] = xf * es;
      }
    }
  }
}

/* @generated begin basis */

SHLIGHT_INLINE void shli_sh_poly_1(float x, float y, float z, float *out_y) {
  SHLIGHT_UNUSED(x);
  SHLIGHT_UNUSED(y);
  SHLIGHT_UNUSED(z);
  out_y[0] = 0.282094792f;
}

SHLIGHT_INLINE void shli_sh_poly_2(float x, float y, float z, float *out_y) {
  out_y[0] = 0.282094792f;
  out_y[2] = 0.488602512f * z;
  out_y[3] = -0.488602512f * x;
  out_y[1] = -0.488602512f * y;
}

SHLIGHT_INLINE void shli_sh_poly_3(float x, float y, float z, float *out_y) {
  float z2;
  float pc;
  float ps;
  float xf;
  z2 = z * z;
  out_y[0] = 0.282094792f;
  out_y[2] = 0.488602512f * z;
  out_y[6] = 0.946174696f * z2 + -0.315391565f;
  out_y[3] = -0.488602512f * x;
  out_y[1] = -0.488602512f * y;
  xf = -1.09254843f * z;
  out_y[7] = xf * x;
  out_y[5] = xf * y;
  pc = x * x - y * y;
  ps = 2.0f * x * y;
  out_y[8] = 0.546274215f * pc;
  out_y[4] = 0.546274215f * ps;
}

SHLIGHT_INLINE void shli_sh_poly_4(float x, float y, float z, float *out_y) {
  float z2;
  float pc;
  float ps;
  float qc;
  float xf;
  z2 = z * z;
  out_y[0] = 0.282094792f;
  out_y[2] = 0.488602512f * z;
  out_y[6] = 0.946174696f * z2 + -0.315391565f;
  out_y[12] = (1.86588166f * z2 + -1.119529f) * z;
  out_y[3] = -0.488602512f * x;
  out_y[1] = -0.488602512f * y;
  xf = -1.09254843f * z;
  out_y[7] = xf * x;
  out_y[5] = xf * y;
  xf = -2.285229f * z2 + 0.457045799f;
  out_y[13] = xf * x;
  out_y[11] = xf * y;
  pc = x * x - y * y;
  ps = 2.0f * x * y;
  out_y[8] = 0.546274215f * pc;
  out_y[4] = 0.546274215f * ps;
  xf = 1.44530572f * z;
  out_y[14] = xf * pc;
  out_y[10] = xf * ps;
  qc = x * pc - y * ps;
  ps = x * ps + y * pc;
  pc = qc;
  out_y[15] = -0.59004359f * pc;
  out_y[9] = -0.59004359f * ps;
}

SHLIGHT_INLINE void shli_sh_poly_5(float x, float y, float z, float *out_y) {
  float z2;
  float pc;
  float ps;
  float qc;
  float xf;
  z2 = z * z;
  out_y[0] = 0.282094792f;
  out_y[2] = 0.488602512f * z;
  out_y[6] = 0.946174696f * z2 + -0.315391565f;
  out_y[12] = (1.86588166f * z2 + -1.119529f) * z;
  out_y[20] = (3.70249414f * z2 + -3.17356641f) * z2 + 0.317356641f;
  out_y[3] = -0.488602512f * x;
  out_y[1] = -0.488602512f * y;
  xf = -1.09254843f * z;
  out_y[7] = xf * x;
  out_y[5] = xf * y;
  xf = -2.285229f * z2 + 0.457045799f;
  out_y[13] = xf * x;
  out_y[11] = xf * y;
  xf = (-4.6833258f * z2 + 2.00713963f) * z;
  out_y[21] = xf * x;
  out_y[19] = xf * y;
  pc = x * x - y * y;
  ps = 2.0f * x * y;
  out_y[8] = 0.546274215f * pc;
  out_y[4] = 0.546274215f * ps;
  xf = 1.44530572f * z;
  out_y[14] = xf * pc;
  out_y[10] = xf * ps;
  xf = 3.31161144f * z2 + -0.473087348f;
  out_y[22] = xf * pc;
  out_y[18] = xf * ps;
  qc = x * pc - y * ps;
  ps = x * ps + y * pc;
  pc = qc;
  out_y[15] = -0.59004359f * pc;
  out_y[9] = -0.59004359f * ps;
  xf = -1.77013077f * z;
  out_y[23] = xf * pc;
  out_y[17] = xf * ps;
  qc = x * pc - y * ps;
  ps = x * ps + y * pc;
  pc = qc;
  out_y[24] = 0.625835735f * pc;
  out_y[16] = 0.625835735f * ps;
}

SHLIGHT_INLINE void shli_sh_poly_6(float x, float y, float z, float *out_y) {
  float z2;
  float pc;
  float ps;
  float qc;
  float xf;
  z2 = z * z;
  out_y[0] = 0.282094792f;
  out_y[2] = 0.488602512f * z;
  out_y[6] = 0.946174696f * z2 + -0.315391565f;
  out_y[12] = (1.86588166f * z2 + -1.119529f) * z;
  out_y[20] = (3.70249414f * z2 + -3.17356641f) * z2 + 0.317356641f;
  out_y[30] = ((7.36787031f * z2 + -8.18652257f) * z2 + 1.75425484f) * z;
  out_y[3] = -0.488602512f * x;
  out_y[1] = -0.488602512f * y;
  xf = -1.09254843f * z;
  out_y[7] = xf * x;
  out_y[5] = xf * y;
  xf = -2.285229f * z2 + 0.457045799f;
  out_y[13] = xf * x;
  out_y[11] = xf * y;
  xf = (-4.6833258f * z2 + 2.00713963f) * z;
  out_y[21] = xf * x;
  out_y[19] = xf * y;
  xf = (-9.51187968f * z2 + 6.34125312f) * z2 + -0.452946651f;
  out_y[31] = xf * x;
  out_y[29] = xf * y;
  pc = x * x - y * y;
  ps = 2.0f * x * y;
  out_y[8] = 0.546274215f * pc;
  out_y[4] = 0.546274215f * ps;
  xf = 1.44530572f * z;
  out_y[14] = xf * pc;
  out_y[10] = xf * ps;
  xf = 3.31161144f * z2 + -0.473087348f;
  out_y[22] = xf * pc;
  out_y[18] = xf * ps;
  xf = (7.19030518f * z2 + -2.39676839f) * z;
  out_y[32] = xf * pc;
  out_y[28] = xf * ps;
  qc = x * pc - y * ps;
  ps = x * ps + y * pc;
  pc = qc;
  out_y[15] = -0.59004359f * pc;
  out_y[9] = -0.59004359f * ps;
  xf = -1.77013077f * z;
  out_y[23] = xf * pc;
  out_y[17] = xf * ps;
  xf = -4.40314469f * z2 + 0.489238299f;
  out_y[33] = xf * pc;
  out_y[27] = xf * ps;
  qc = x * pc - y * ps;
  ps = x * ps + y * pc;
  pc = qc;
  out_y[24] = 0.625835735f * pc;
  out_y[16] = 0.625835735f * ps;
  xf = 2.07566231f * z;
  out_y[34] = xf * pc;
  out_y[26] = xf * ps;
  qc = x * pc - y * ps;
  ps = x * ps + y * pc;
  pc = qc;
  out_y[35] = -0.656382057f * pc;
  out_y[25] = -0.656382057f * ps;
}

SHLIGHT_INLINE void shli_sh_core(int n, shli_real x, shli_real y, shli_real z, shli_real t,
                                 float sg, float *out_y) {
  shli_real pc = x;
  shli_real ps = y;
  shli_real qc;
  float fc = 0.0f;
  float fs = 0.0f;
  float gc = 0.0f;
  float gs = 0.0f;
  shli_real xa = 0.0;
  shli_real xb = 0.0;
  shli_real dd = 0.0;
  float xf;
  SHLIGHT_UNUSED(z);
#if SHLIGHT_MAX_BANDS > SHLIGHT_UNROLLED_BANDS
  if (n > SHLIGHT_UNROLLED_BANDS) {
    shli_sh_core_loop(n, x, y, z, t, sg, out_y);
    return;
  }
#endif
  out_y[0] = 0.282094792f;
#if SHLIGHT_MAX_BANDS > 1
  if (n > 1) {
    dd = -0.48860251190291987 * t;
    xa = 0.48860251190291987 + dd;
    out_y[2] = sg * SHLIGHT_FLOAT(xa);
  }
#endif
#if SHLIGHT_MAX_BANDS > 2
  if (n > 2) {
    dd = 0.6454972243679029 * dd - 1.9364916731037085 * (t * xa);
    xb = 1.2909944487358056 * xa + dd;
    out_y[6] = SHLIGHT_FLOAT(xb);
  }
#endif
#if SHLIGHT_MAX_BANDS > 3
  if (n > 3) {
    dd = 0.7888106377466155 * dd - 1.9720265943665387 * (t * xb);
    xa = 1.1832159566199232 * xb + dd;
    out_y[12] = sg * SHLIGHT_FLOAT(xa);
  }
#endif
#if SHLIGHT_MAX_BANDS > 4
  if (n > 4) {
    dd = 0.8504200642707612 * dd - 1.984313483298443 * (t * xa);
    xb = 1.133893419027682 * xa + dd;
    out_y[20] = SHLIGHT_FLOAT(xb);
  }
#endif
#if SHLIGHT_MAX_BANDS > 5
  if (n > 5) {
    dd = 0.8844332774281064 * dd - 1.98997487421324 * (t * xb);
    xa = 1.1055415967851334 * xb + dd;
    out_y[30] = sg * SHLIGHT_FLOAT(xa);
  }
#endif
#if SHLIGHT_MAX_BANDS > 6
  if (n > 6) {
    dd = 0.9059288441743482 * dd - 1.9930434571835665 * (t * xa);
    xb = 1.0871146130092184 * xa + dd;
    out_y[42] = SHLIGHT_FLOAT(xb);
  }
#endif
#if SHLIGHT_MAX_BANDS > 7
  if (n > 7) {
    dd = 0.9207191237649848 * dd - 1.9948914348241344 * (t * xb);
    xa = 1.0741723110591497 * xb + dd;
    out_y[56] = sg * SHLIGHT_FLOAT(xa);
  }
#endif
#if SHLIGHT_MAX_BANDS > 8
  if (n > 8) {
    dd = 0.9315086329891595 * dd - 1.996089927833914 * (t * xa);
    xb = 1.0645812948447546 * xa + dd;
    out_y[72] = SHLIGHT_FLOAT(xb);
  }
#endif
#if SHLIGHT_MAX_BANDS > 9
  if (n > 9) {
    dd = 0.9397229153260873 * dd - 1.9969111950679366 * (t * xb);
    xa = 1.0571882797418493 * xb + dd;
    out_y[90] = sg * SHLIGHT_FLOAT(xa);
  }
#endif
#if SHLIGHT_MAX_BANDS > 10
  if (n > 10) {
    dd = 0.9461834694681237 * dd - 1.997498435543818 * (t * xa);
    xb = 1.0513149660756942 * xa + dd;
    out_y[110] = SHLIGHT_FLOAT(xb);
  }
#endif
#if SHLIGHT_MAX_BANDS > 11
  if (n > 11) {
    dd = 0.9513965790405152 * dd - 1.9979328159850827 * (t * xb);
    xa = 1.0465362369445674 * xb + dd;
    out_y[132] = sg * SHLIGHT_FLOAT(xa);
  }
#endif
#if SHLIGHT_MAX_BANDS > 12
  if (n > 12) {
    dd = 0.9556910644282591 * dd - 1.998263134713633 * (t * xa);
    xb = 1.042572070285374 * xa + dd;
    out_y[156] = SHLIGHT_FLOAT(xb);
  }
#endif
#if SHLIGHT_MAX_BANDS > 13
  if (n > 13) {
    dd = 0.9592896780381471 * dd - 1.998520162579474 * (t * xb);
    xa = 1.039230484541327 * xb + dd;
    out_y[182] = sg * SHLIGHT_FLOAT(xa);
  }
#endif
#if SHLIGHT_MAX_BANDS > 14
  if (n > 14) {
    dd = 0.9623486324615438 * dd - 1.9987240828047461 * (t * xa);
    xb = 1.036375450343202 * xa + dd;
    out_y[210] = SHLIGHT_FLOAT(xb);
  }
#endif
#if SHLIGHT_MAX_BANDS > 15
  if (n > 15) {
    dd = 0.9649806938294676 * dd - 1.9988885800753267 * (t * xb);
    xa = 1.0339078862458588 * xb + dd;
    out_y[240] = sg * SHLIGHT_FLOAT(xa);
  }
#endif
#if SHLIGHT_MAX_BANDS > 1
  if (n > 1) {
    fc = SHLIGHT_FLOAT(pc);
    fs = SHLIGHT_FLOAT(ps);
    out_y[3] = -0.488602512f * fc;
    out_y[1] = -0.488602512f * fs;
    gc = sg * fc;
    gs = sg * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 2
  if (n > 2) {
    dd = 1.092548430592079 * t;
    xa = -1.092548430592079 + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[7] = xf * gc;
    out_y[5] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 3
  if (n > 3) {
    dd = 0.4183300132670377 * dd - 2.091650066335189 * (t * xa);
    xb = 1.673320053068151 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[13] = xf * fc;
    out_y[11] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 4
  if (n > 4) {
    dd = 0.5855400437691199 * dd - 2.04939015319192 * (t * xb);
    xa = 1.4638501094228 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[21] = xf * gc;
    out_y[19] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 5
  if (n > 5) {
    dd = 0.6770032003863299 * dd - 2.03100960115899 * (t * xa);
    xb = 1.3540064007726604 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[31] = xf * fc;
    out_y[29] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 6
  if (n > 6) {
    dd = 0.7350236324498282 * dd - 2.0213149892370277 * (t * xb);
    xa = 1.2862913567871994 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[43] = xf * gc;
    out_y[41] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 7
  if (n > 7) {
    dd = 0.7752170911825529 * dd - 2.0155644370746373 * (t * xa);
    xb = 1.2403473458920844 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[57] = xf * fc;
    out_y[55] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 8
  if (n > 8) {
    dd = 0.8047478161629565 * dd - 2.011869540407391 * (t * xb);
    xa = 1.2071217242444345 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[73] = xf * gc;
    out_y[71] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 9
  if (n > 9) {
    dd = 0.8273807004815933 * dd - 2.0093531297410117 * (t * xa);
    xb = 1.1819724292594185 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[91] = xf * fc;
    out_y[89] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 10
  if (n > 10) {
    dd = 0.8452890373232224 * dd - 2.0075614636426526 * (t * xb);
    xa = 1.1622724263194302 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[111] = xf * gc;
    out_y[109] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 11
  if (n > 11) {
    dd = 0.8598172563316665 * dd - 2.006240264773888 * (t * xa);
    xb = 1.1464230084422218 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[133] = xf * fc;
    out_y[131] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 12
  if (n > 12) {
    dd = 0.8718425636326949 * dd - 2.0052378963551982 * (t * xb);
    xa = 1.1333953327225033 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[157] = xf * gc;
    out_y[155] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 13
  if (n > 13) {
    dd = 0.8819620983110006 * dd - 2.004459314343183 * (t * xa);
    xb = 1.1224972160321822 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[183] = xf * fc;
    out_y[181] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 14
  if (n > 14) {
    dd = 0.890596650096099 * dd - 2.0038424627162224 * (t * xb);
    xa = 1.1132458126201232 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[211] = xf * gc;
    out_y[209] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 15
  if (n > 15) {
    dd = 0.8980513935286331 * dd - 2.003345416333104 * (t * xa);
    xb = 1.105294022804471 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[241] = xf * fc;
    out_y[239] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 2
  if (n > 2) {
    qc = x * pc - y * ps;
    ps = x * ps + y * pc;
    pc = qc;
    fc = SHLIGHT_FLOAT(pc);
    fs = SHLIGHT_FLOAT(ps);
    out_y[8] = 0.546274215f * fc;
    out_y[4] = 0.546274215f * fs;
    gc = sg * fc;
    gs = sg * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 3
  if (n > 3) {
    dd = -1.445305721320277 * t;
    xa = 1.445305721320277 + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[14] = xf * gc;
    out_y[10] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 4
  if (n > 4) {
    dd = 0.32732683535398854 * dd - 2.29128784747792 * (t * xa);
    xb = 1.9639610121239315 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[22] = xf * fc;
    out_y[18] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 5
  if (n > 5) {
    dd = 0.48249790963716394 * dd - 2.1712405933672376 * (t * xb);
    xa = 1.6887426837300736 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[32] = xf * gc;
    out_y[28] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 6
  if (n > 6) {
    dd = 0.5765295860893556 * dd - 2.1139418156609704 * (t * xa);
    xb = 1.5374122295716148 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[44] = xf * fc;
    out_y[40] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 7
  if (n > 7) {
    dd = 0.6405126152203485 * dd - 2.0816659994661326 * (t * xb);
    xa = 1.4411533842457838 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[58] = xf * gc;
    out_y[54] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 8
  if (n > 8) {
    dd = 0.687184270936277 * dd - 2.0615528128088303 * (t * xa);
    xb = 1.3743685418725533 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[74] = xf * fc;
    out_y[70] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 9
  if (n > 9) {
    dd = 0.7228667147145245 * dd - 2.048122358357819 * (t * xb);
    xa = 1.325255643643295 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[92] = xf * gc;
    out_y[88] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 10
  if (n > 10) {
    dd = 0.751095690869083 * dd - 2.038688303787511 * (t * xa);
    xb = 1.2875926129184283 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[112] = xf * fc;
    out_y[108] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 11
  if (n > 11) {
    dd = 0.7740184746532857 * dd - 2.031798495964875 * (t * xb);
    xa = 1.2577800213115895 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[134] = xf * gc;
    out_y[130] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 12
  if (n > 12) {
    dd = 0.7930207989565214 * dd - 2.026608708444444 * (t * xa);
    xb = 1.2335879094879225 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[158] = xf * fc;
    out_y[154] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 13
  if (n > 13) {
    dd = 0.8090398349558905 * dd - 2.0225995873897262 * (t * xb);
    xa = 1.213559752433836 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[184] = xf * gc;
    out_y[180] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 14
  if (n > 14) {
    dd = 0.8227335122011046 * dd - 2.019436802675439 * (t * xa);
    xb = 1.1967032904743342 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[212] = xf * fc;
    out_y[208] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 15
  if (n > 15) {
    dd = 0.834578047890988 * dd - 2.0168969490698876 * (t * xb);
    xa = 1.1823189011788997 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[242] = xf * gc;
    out_y[238] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 3
  if (n > 3) {
    qc = x * pc - y * ps;
    ps = x * ps + y * pc;
    pc = qc;
    fc = SHLIGHT_FLOAT(pc);
    fs = SHLIGHT_FLOAT(ps);
    out_y[15] = -0.59004359f * fc;
    out_y[9] = -0.59004359f * fs;
    gc = sg * fc;
    gs = sg * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 4
  if (n > 4) {
    dd = 1.7701307697799304 * t;
    xa = -1.7701307697799304 + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[23] = xf * gc;
    out_y[17] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 5
  if (n > 5) {
    dd = 0.2763853991962833 * dd - 2.48746859276655 * (t * xa);
    xb = 2.2110831935702664 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[33] = xf * fc;
    out_y[27] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 6
  if (n > 6) {
    dd = 0.4184306096405653 * dd - 2.301368353023109 * (t * xb);
    xa = 1.882937743382544 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[45] = xf * gc;
    out_y[39] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 7
  if (n > 7) {
    dd = 0.5095246653650679 * dd - 2.207940216581962 * (t * xa);
    xb = 1.698415551216894 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[59] = xf * fc;
    out_y[53] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 8
  if (n > 8) {
    dd = 0.5741924500522186 * dd - 2.15322168769582 * (t * xb);
    xa = 1.5790292376436015 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[75] = xf * gc;
    out_y[69] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 9
  if (n > 9) {
    dd = 0.6229541679970017 * dd - 2.1180441711898057 * (t * xa);
    xb = 1.495090003192804 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[93] = xf * fc;
    out_y[87] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 10
  if (n > 10) {
    dd = 0.6612465225335805 * dd - 2.0939473213563384 * (t * xb);
    xa = 1.4327007988227578 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[113] = xf * gc;
    out_y[107] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 11
  if (n > 11) {
    dd = 0.6922186552431729 * dd - 2.0766559657295187 * (t * xa);
    xb = 1.3844373104863459 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[135] = xf * fc;
    out_y[129] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 12
  if (n > 12) {
    dd = 0.717842536077554 * dd - 2.0637972912229676 * (t * xb);
    xa = 1.3459547551454134 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[159] = xf * gc;
    out_y[153] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 13
  if (n > 13) {
    dd = 0.7394254526319745 * dd - 2.053959590644373 * (t * xa);
    xb = 1.3145341380123985 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[185] = xf * fc;
    out_y[179] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 14
  if (n > 14) {
    dd = 0.7578727878783199 * dd - 2.0462565272714635 * (t * xb);
    xa = 1.2883837393931434 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[213] = xf * gc;
    out_y[207] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 15
  if (n > 15) {
    dd = 0.773833732937793 * dd - 2.040107114108727 * (t * xa);
    xb = 1.2662733811709337 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[243] = xf * fc;
    out_y[237] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 4
  if (n > 4) {
    qc = x * pc - y * ps;
    ps = x * ps + y * pc;
    pc = qc;
    fc = SHLIGHT_FLOAT(pc);
    fs = SHLIGHT_FLOAT(ps);
    out_y[24] = 0.625835735f * fc;
    out_y[16] = 0.625835735f * fs;
    gc = sg * fc;
    gs = sg * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 5
  if (n > 5) {
    dd = -2.075662314881041 * t;
    xa = 2.075662314881041 + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[34] = xf * gc;
    out_y[26] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 6
  if (n > 6) {
    dd = 0.24308621740219885 * dd - 2.6739483914241875 * (t * xa);
    xb = 2.4308621740219887 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[46] = xf * fc;
    out_y[38] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 7
  if (n > 7) {
    dd = 0.37397879600338285 * dd - 2.4308621740219887 * (t * xb);
    xa = 2.0568833780186058 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[60] = xf * gc;
    out_y[52] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 8
  if (n > 8) {
    dd = 0.4609772228646444 * dd - 2.3048861143232218 * (t * xa);
    xb = 1.8439088914585773 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[76] = xf * fc;
    out_y[68] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 9
  if (n > 9) {
    dd = 0.5245122707544083 * dd - 2.229177150706235 * (t * xb);
    xa = 1.7046648799518267 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[94] = xf * gc;
    out_y[86] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 10
  if (n > 10) {
    dd = 0.5735393346764045 * dd - 2.179449471770337 * (t * xa);
    xb = 1.6059101370939326 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[114] = xf * fc;
    out_y[106] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 11
  if (n > 11) {
    dd = 0.6127888739864918 * dd - 2.1447610589527217 * (t * xb);
    xa = 1.53197218496623 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[136] = xf * gc;
    out_y[128] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 12
  if (n > 12) {
    dd = 0.6450585581776749 * dd - 2.1194781197266463 * (t * xa);
    xb = 1.4744195615489715 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[160] = xf * fc;
    out_y[152] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 13
  if (n > 13) {
    dd = 0.6721344403334446 * dd - 2.100420126042015 * (t * xb);
    xa = 1.4282856857085702 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[186] = xf * gc;
    out_y[178] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 14
  if (n > 14) {
    dd = 0.6952217871538069 * dd - 2.085665361461421 * (t * xa);
    xb = 1.390443574307614 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[214] = xf * fc;
    out_y[206] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 15
  if (n > 15) {
    dd = 0.7151690392214606 * dd - 2.0739902137422357 * (t * xb);
    xa = 1.3588211745207752 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[244] = xf * gc;
    out_y[236] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 5
  if (n > 5) {
    qc = x * pc - y * ps;
    ps = x * ps + y * pc;
    pc = qc;
    fc = SHLIGHT_FLOAT(pc);
    fs = SHLIGHT_FLOAT(ps);
    out_y[35] = -0.656382057f * fc;
    out_y[25] = -0.656382057f * fs;
    gc = sg * fc;
    gs = sg * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 6
  if (n > 6) {
    dd = 2.3666191622317516 * t;
    xa = -2.3666191622317516 + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[47] = xf * gc;
    out_y[37] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 7
  if (n > 7) {
    dd = 0.21926450482675733 * dd - 2.850438562747845 * (t * xa);
    xb = 2.6311740579210876 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[61] = xf * fc;
    out_y[51] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 8
  if (n > 8) {
    dd = 0.34093887463783923 * dd - 2.557041559783794 * (t * xb);
    xa = 2.216102685145955 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[77] = xf * gc;
    out_y[67] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 9
  if (n > 9) {
    dd = 0.423818178868599 * dd - 2.401636346922061 * (t * xa);
    xb = 1.9778181680534621 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[95] = xf * fc;
    out_y[85] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 10
  if (n > 10) {
    dd = 0.4855815829335072 * dd - 2.3065125189341593 * (t * xb);
    xa = 1.820930936000652 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[115] = xf * gc;
    out_y[105] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 11
  if (n > 11) {
    dd = 0.5340582870513797 * dd - 2.2430448056157952 * (t * xa);
    xb = 1.7089865185644153 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[137] = xf * fc;
    out_y[127] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 12
  if (n > 12) {
    dd = 0.5734345499245157 * dd - 2.1981657747106436 * (t * xb);
    xa = 1.624731224786128 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[161] = xf * gc;
    out_y[151] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 13
  if (n > 13) {
    dd = 0.606217782649107 * dd - 2.165063509461097 * (t * xa);
    xb = 1.5588457268119897 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[187] = xf * fc;
    out_y[177] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 14
  if (n > 14) {
    dd = 0.6340288920157854 * dd - 2.1398475105532757 * (t * xb);
    xa = 1.5058186185374902 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[215] = xf * gc;
    out_y[205] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 15
  if (n > 15) {
    dd = 0.6579749497380267 * dd - 2.120141504711419 * (t * xa);
    xb = 1.4621665549733924 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[245] = xf * fc;
    out_y[235] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 6
  if (n > 6) {
    qc = x * pc - y * ps;
    ps = x * ps + y * pc;
    pc = qc;
    fc = SHLIGHT_FLOAT(pc);
    fs = SHLIGHT_FLOAT(ps);
    out_y[48] = 0.683184105f * fc;
    out_y[36] = 0.683184105f * fs;
    gc = sg * fc;
    gs = sg * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 7
  if (n > 7) {
    dd = -2.6459606618018996 * t;
    xa = 2.6459606618018996 + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[62] = xf * gc;
    out_y[50] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 8
  if (n > 8) {
    dd = 0.20118695404073914 * dd - 3.017804310611087 * (t * xa);
    xb = 2.816617356570348 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[78] = xf * fc;
    out_y[66] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 9
  if (n > 9) {
    dd = 0.31519264780251166 * dd - 2.679137506321349 * (t * xb);
    xa = 2.363944858518838 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[96] = xf * gc;
    out_y[84] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 10
  if (n > 10) {
    dd = 0.39424311227838504 * dd - 2.496873044429772 * (t * xa);
    xb = 2.102629932151387 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[116] = xf * fc;
    out_y[104] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 11
  if (n > 11) {
    dd = 0.45405117000839723 * dd - 2.3837686425440854 * (t * xb);
    xa = 1.9297174725356883 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[138] = xf * gc;
    out_y[126] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 12
  if (n > 12) {
    dd = 0.501607721190705 * dd - 2.307395517477243 * (t * xa);
    xb = 1.805787796286538 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[162] = xf * fc;
    out_y[150] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 13
  if (n > 13) {
    dd = 0.5406762682674995 * dd - 2.252817784447915 * (t * xb);
    xa = 1.7121415161804154 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[188] = xf * gc;
    out_y[176] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 14
  if (n > 14) {
    dd = 0.5735287134792688 * dd - 2.212182180562894 * (t * xa);
    xb = 1.638653467083625 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[216] = xf * fc;
    out_y[204] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 15
  if (n > 15) {
    dd = 0.6016458603598018 * dd - 2.1809662438042814 * (t * xb);
    xa = 1.5793203834444796 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[246] = xf * gc;
    out_y[234] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 7
  if (n > 7) {
    qc = x * pc - y * ps;
    ps = x * ps + y * pc;
    pc = qc;
    fc = SHLIGHT_FLOAT(pc);
    fs = SHLIGHT_FLOAT(ps);
    out_y[63] = -0.707162733f * fc;
    out_y[49] = -0.707162733f * fs;
    gc = sg * fc;
    gs = sg * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 8
  if (n > 8) {
    dd = 2.915706640699319 * t;
    xa = -2.915706640699319 + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[79] = xf * gc;
    out_y[65] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 9
  if (n > 9) {
    dd = 0.18688625039910048 * dd - 3.1770662567847086 * (t * xa);
    xb = 2.990180006385608 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[97] = xf * fc;
    out_y[83] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 10
  if (n > 10) {
    dd = 0.29442708180727534 * dd - 2.7970572771691153 * (t * xb);
    xa = 2.50263019536184 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[117] = xf * gc;
    out_y[103] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 11
  if (n > 11) {
    dd = 0.37000643495047747 * dd - 2.5900450446533423 * (t * xa);
    xb = 2.220038609702865 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[139] = xf * fc;
    out_y[125] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 12
  if (n > 12) {
    dd = 0.4278625498405581 * dd - 2.460209661583209 * (t * xb);
    xa = 2.032347111742651 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[163] = xf * gc;
    out_y[149] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 13
  if (n > 13) {
    dd = 0.47434164902525694 * dd - 2.3717082451262845 * (t * xa);
    xb = 1.8973665961010275 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[189] = xf * fc;
    out_y[175] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 14
  if (n > 14) {
    dd = 0.5128728387747147 * dd - 2.307927774486216 * (t * xb);
    xa = 1.795054935711501 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[217] = xf * gc;
    out_y[203] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 15
  if (n > 15) {
    dd = 0.5455361746651991 * dd - 2.260078437898682 * (t * xa);
    xb = 1.7145422632334826 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[247] = xf * fc;
    out_y[233] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 8
  if (n > 8) {
    qc = x * pc - y * ps;
    ps = x * ps + y * pc;
    pc = qc;
    fc = SHLIGHT_FLOAT(pc);
    fs = SHLIGHT_FLOAT(ps);
    out_y[80] = 0.72892666f * fc;
    out_y[64] = 0.72892666f * fs;
    gc = sg * fc;
    gs = sg * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 9
  if (n > 9) {
    dd = -3.1773176489546975 * t;
    xa = 3.1773176489546975 + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[98] = xf * gc;
    out_y[82] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 10
  if (n > 10) {
    dd = 0.1752191610126156 * dd - 3.3291640592396967 * (t * xa);
    xb = 3.1539448982270817 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[118] = xf * fc;
    out_y[102] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 11
  if (n > 11) {
    dd = 0.2772342217348337 * dd - 2.910959328215754 * (t * xb);
    xa = 2.63372510648092 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[140] = xf * gc;
    out_y[124] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 12
  if (n > 12) {
    dd = 0.34968930309011775 * dd - 2.680951323690902 * (t * xa);
    xb = 2.3312620206007844 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[164] = xf * fc;
    out_y[148] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 13
  if (n > 13) {
    dd = 0.40567404226968795 * dd - 2.53546276418555 * (t * xb);
    xa = 2.129788721915862 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[190] = xf * gc;
    out_y[174] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 14
  if (n > 14) {
    dd = 0.4510245227144381 * dd - 2.435532422657966 * (t * xa);
    xb = 1.9845078999435284 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[218] = xf * fc;
    out_y[202] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 15
  if (n > 15) {
    dd = 0.48890013854582 * dd - 2.363017336304797 * (t * xb);
    xa = 1.874117197758977 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[248] = xf * gc;
    out_y[232] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 9
  if (n > 9) {
    qc = x * pc - y * ps;
    ps = x * ps + y * pc;
    pc = qc;
    fc = SHLIGHT_FLOAT(pc);
    fs = SHLIGHT_FLOAT(ps);
    out_y[99] = -0.748900952f * fc;
    out_y[81] = -0.748900952f * fs;
    gc = sg * fc;
    gs = sg * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 10
  if (n > 10) {
    dd = 3.431895299891714 * t;
    xa = -3.431895299891714 + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[119] = xf * gc;
    out_y[101] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 11
  if (n > 11) {
    dd = 0.16547190813232432 * dd - 3.4749100707788108 * (t * xa);
    xb = 3.309438162646486 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[141] = xf * fc;
    out_y[123] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 12
  if (n > 12) {
    dd = 0.2627034687463669 * dd - 3.021089890583219 * (t * xb);
    xa = 2.7583864218368523 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[165] = xf * gc;
    out_y[147] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 13
  if (n > 13) {
    dd = 0.3323470256441984 * dd - 2.7695585470349866 * (t * xa);
    xb = 2.437211521390789 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[191] = xf * fc;
    out_y[173] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 14
  if (n > 14) {
    dd = 0.3865700362349023 * dd - 2.6093477445855915 * (t * xb);
    xa = 2.2227777083506894 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[219] = xf * gc;
    out_y[201] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 15
  if (n > 15) {
    dd = 0.430794952602441 * dd - 2.4986107250941583 * (t * xa);
    xb = 2.067815772491717 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[249] = xf * fc;
    out_y[231] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 10
  if (n > 10) {
    qc = x * pc - y * ps;
    ps = x * ps + y * pc;
    pc = qc;
    fc = SHLIGHT_FLOAT(pc);
    fs = SHLIGHT_FLOAT(ps);
    out_y[120] = 0.767395118f * fc;
    out_y[100] = 0.767395118f * fs;
    gc = sg * fc;
    gs = sg * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 11
  if (n > 11) {
    dd = -3.6802976988053104 * t;
    xa = 3.6802976988053104 + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[142] = xf * gc;
    out_y[122] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 12
  if (n > 12) {
    dd = 0.1571736533654829 * dd - 3.614994027406106 * (t * xa);
    xb = 3.4578203740406233 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[166] = xf * fc;
    out_y[146] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 13
  if (n > 13) {
    dd = 0.2502172968684897 * dd - 3.1277162108561214 * (t * xb);
    xa = 2.8774989139876315 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[192] = xf * gc;
    out_y[172] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 14
  if (n > 14) {
    dd = 0.3173238794109962 * dd - 2.8559149146989657 * (t * xa);
    xb = 2.5385910352879693 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[220] = xf * fc;
    out_y[200] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 15
  if (n > 15) {
    dd = 0.3699021305790176 * dd - 2.6817904466978773 * (t * xb);
    xa = 2.3118883161188597 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[250] = xf * gc;
    out_y[230] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 11
  if (n > 11) {
    qc = x * pc - y * ps;
    ps = x * ps + y * pc;
    pc = qc;
    fc = SHLIGHT_FLOAT(pc);
    fs = SHLIGHT_FLOAT(ps);
    out_y[143] = -0.784642106f * fc;
    out_y[121] = -0.784642106f * fs;
    gc = sg * fc;
    gs = sg * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 12
  if (n > 12) {
    dd = 3.923210528935984 * t;
    xa = -3.923210528935984 + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[167] = xf * gc;
    out_y[145] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 13
  if (n > 13) {
    dd = 0.15 * dd - 3.75 * (t * xa);
    xb = 3.6 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[193] = xf * fc;
    out_y[171] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 14
  if (n > 14) {
    dd = 0.23934065809486682 * dd - 3.2310988842807022 * (t * xb);
    xa = 2.9917582261858353 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[221] = xf * gc;
    out_y[199] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 15
  if (n > 15) {
    dd = 0.3041490281091405 * dd - 2.9401072717216916 * (t * xa);
    xb = 2.635958243612551 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[251] = xf * fc;
    out_y[229] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 12
  if (n > 12) {
    qc = x * pc - y * ps;
    ps = x * ps + y * pc;
    pc = qc;
    fc = SHLIGHT_FLOAT(pc);
    fs = SHLIGHT_FLOAT(ps);
    out_y[168] = 0.800821996f * fc;
    out_y[144] = 0.800821996f * fs;
    gc = sg * fc;
    gs = sg * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 13
  if (n > 13) {
    dd = -4.161193153549645 * t;
    xa = 4.161193153549645 + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[194] = xf * gc;
    out_y[170] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 14
  if (n > 14) {
    dd = 0.14371941641709604 * dd - 3.880424243261593 * (t * xa);
    xb = 3.7367048268444973 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[222] = xf * fc;
    out_y[198] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 15
  if (n > 15) {
    dd = 0.2297573080546352 * dd - 3.331480966792211 * (t * xb);
    xa = 3.101723658737576 * xb + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[252] = xf * gc;
    out_y[228] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 13
  if (n > 13) {
    qc = x * pc - y * ps;
    ps = x * ps + y * pc;
    pc = qc;
    fc = SHLIGHT_FLOAT(pc);
    fs = SHLIGHT_FLOAT(ps);
    out_y[195] = -0.816077119f * fc;
    out_y[169] = -0.816077119f * fs;
    gc = sg * fc;
    gs = sg * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 14
  if (n > 14) {
    dd = 4.394709780272119 * t;
    xa = -4.394709780272119 + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[223] = xf * gc;
    out_y[197] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 15
  if (n > 15) {
    dd = 0.1381617528505589 * dd - 4.006690832666208 * (t * xa);
    xb = 3.868529079815649 * xa + dd;
    xf = SHLIGHT_FLOAT(xb);
    out_y[253] = xf * fc;
    out_y[227] = xf * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 14
  if (n > 14) {
    qc = x * pc - y * ps;
    ps = x * ps + y * pc;
    pc = qc;
    fc = SHLIGHT_FLOAT(pc);
    fs = SHLIGHT_FLOAT(ps);
    out_y[224] = 0.830522083f * fc;
    out_y[196] = 0.830522083f * fs;
    gc = sg * fc;
    gs = sg * fs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 15
  if (n > 15) {
    dd = -4.624151256630013 * t;
    xa = 4.624151256630013 + dd;
    xf = SHLIGHT_FLOAT(xa);
    out_y[254] = xf * gc;
    out_y[226] = xf * gs;
  }
#endif
#if SHLIGHT_MAX_BANDS > 15
  if (n > 15) {
    qc = x * pc - y * ps;
    ps = x * ps + y * pc;
    pc = qc;
    fc = SHLIGHT_FLOAT(pc);
    fs = SHLIGHT_FLOAT(ps);
    out_y[255] = -0.844250651f * fc;
    out_y[225] = -0.844250651f * fs;
  }
#endif
}
/* @generated end basis */

/* Across-m SIMD core (C only, AVX-512): one 16-lane register holds X_l^m of every order m of
   band l, so a band costs one Reinsch step (4 vector ops) and its outputs two multiplies, one
   lane reversal and two masked stores. Float lanes: the Reinsch form keeps the float error
   within the stated targets (docs/accuracy.md, tests/test_basis); the scalar kernel (double) stays
   the reference and SHLIGHT_NO_SIMD selects it. Used by shl_sh_eval for 7 <= n <= 64 (n <= 16: the
   rescaled step of SHLI_SH_LANES_S, 256-bit lanes with AVX-512VL), and the Horner forms across the
   outputs for n = 4..6 (AVX-512VL). */
#if !defined(SHLIGHT_NO_SIMD) && defined(__AVX512F__)
#define SHLIGHT_SIMD_EVAL 1
#include <immintrin.h>
/* @generated begin lanes */
#if SHLIGHT_SIMD_EVAL
/* clang-format off */
static const float SHLI_SH_LANES[7632] = {
    1.7320508f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1.7320508f, 1, 1, 1, 1, 1, 1, 1, 1,
    1, 1, 1, 1, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1.9364917f, 2.236068f, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1.2909944f, 2.236068f, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1,
    1, 1, 1, 0.6454972f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1.9720266f, 2.09165f,
    2.6457512f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1.183216f, 1.67332f, 2.6457512f, 1, 1, 1,
    1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0.7888106f, 0.41833f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    1.9843135f, 2.04939f, 2.291288f, 3, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1.1338934f,
    1.4638501f, 1.963961f, 3, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0.85042006f, 0.58554006f,
    0.32732683f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1.9899749f, 2.0310097f, 2.1712406f,
    2.4874685f, 3.3166249f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1.1055416f, 1.3540064f, 1.6887426f,
    2.2110832f, 3.3166249f, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0.88443327f, 0.6770032f, 0.4824979f,
    0.2763854f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1.9930434f, 2.021315f, 2.113942f, 2.3013682f,
    2.6739483f, 3.6055512f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1.0871146f, 1.2862914f, 1.5374123f,
    1.8829378f, 2.4308622f, 3.6055512f, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0.90592885f, 0.7350236f,
    0.57652956f, 0.4184306f, 0.24308622f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1.9948914f, 2.0155644f,
    2.081666f, 2.20794f, 2.4308622f, 2.8504386f, 3.8729835f, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    1.0741723f, 1.2403474f, 1.4411534f, 1.6984155f, 2.0568833f, 2.631174f, 3.8729835f, 1, 1, 1, 1,
    1, 1, 1, 1, 1, 0.92071915f, 0.7752171f, 0.6405126f, 0.50952464f, 0.3739788f, 0.2192645f, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 1.9960899f, 2.0118694f, 2.0615528f, 2.1532216f, 2.304886f, 2.5570416f,
    3.0178044f, 4.1231055f, 0, 0, 0, 0, 0, 0, 0, 0, 1.0645813f, 1.2071217f, 1.3743685f,
    1.5790292f, 1.8439089f, 2.2161026f, 2.8166173f, 4.1231055f, 1, 1, 1, 1, 1, 1, 1, 1,
    0.93150866f, 0.8047478f, 0.6871843f, 0.57419246f, 0.46097723f, 0.34093887f, 0.20118695f, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 1.9969112f, 2.0093532f, 2.0481224f, 2.1180441f, 2.2291772f, 2.4016364f,
    2.6791375f, 3.1770663f, 4.358899f, 0, 0, 0, 0, 0, 0, 0, 1.0571883f, 1.1819724f, 1.3252556f,
    1.49509f, 1.7046648f, 1.9778181f, 2.3639448f, 2.99018f, 4.358899f, 1, 1, 1, 1, 1, 1, 1,
    0.9397229f, 0.8273807f, 0.7228667f, 0.6229542f, 0.5245123f, 0.42381817f, 0.31519264f,
    0.18688625f, 0, 0, 0, 0, 0, 0, 0, 0, 1.9974984f, 2.0075614f, 2.0386882f, 2.0939474f,
    2.1794496f, 2.3065126f, 2.4968731f, 2.7970574f, 3.329164f, 4.582576f, 0, 0, 0, 0, 0, 0,
    1.051315f, 1.1622725f, 1.2875926f, 1.4327008f, 1.6059102f, 1.820931f, 2.10263f, 2.5026302f,
    3.153945f, 4.582576f, 1, 1, 1, 1, 1, 1, 0.94618344f, 0.84528905f, 0.7510957f, 0.66124654f,
    0.5735393f, 0.48558158f, 0.39424312f, 0.2944271f, 0.17521916f, 0, 0, 0, 0, 0, 0, 0,
    1.9979328f, 2.0062404f, 2.0317986f, 2.0766559f, 2.144761f, 2.2430449f, 2.3837686f, 2.590045f,
    2.9109592f, 3.47491f, 4.7958317f, 0, 0, 0, 0, 0, 1.0465362f, 1.146423f, 1.2577801f,
    1.3844373f, 1.5319722f, 1.7089865f, 1.9297174f, 2.2200387f, 2.6337252f, 3.3094382f,
    4.7958317f, 1, 1, 1, 1, 1, 0.9513966f, 0.85981727f, 0.77401847f, 0.69221866f, 0.61278886f,
    0.5340583f, 0.45405117f, 0.37000644f, 0.27723423f, 0.16547191f, 0, 0, 0, 0, 0, 0, 1.9982631f,
    2.0052378f, 2.0266087f, 2.0637972f, 2.1194782f, 2.1981657f, 2.3073955f, 2.4602096f,
    2.6809514f, 3.0210898f, 3.614994f, 5, 0, 0, 0, 0, 1.042572f, 1.1333953f, 1.2335879f,
    1.3459548f, 1.4744196f, 1.6247312f, 1.8057878f, 2.0323472f, 2.331262f, 2.7583864f, 3.4578204f,
    5, 1, 1, 1, 1, 0.95569104f, 0.87184256f, 0.7930208f, 0.7178425f, 0.6450586f, 0.57343453f,
    0.5016077f, 0.42786255f, 0.3496893f, 0.26270348f, 0.15717365f, 0, 0, 0, 0, 0, 1.9985201f,
    2.0044594f, 2.0225997f, 2.0539596f, 2.1004202f, 2.1650636f, 2.2528179f, 2.3717082f,
    2.5354629f, 2.7695587f, 3.1277163f, 3.75f, 5.196152f, 0, 0, 0, 1.0392305f, 1.1224972f,
    1.2135597f, 1.3145342f, 1.4282857f, 1.5588458f, 1.7121415f, 1.8973666f, 2.1297886f,
    2.4372115f, 2.8774989f, 3.6f, 5.196152f, 1, 1, 1, 0.95928967f, 0.8819621f, 0.80903983f,
    0.7394255f, 0.67213446f, 0.6062178f, 0.5406763f, 0.47434166f, 0.40567404f, 0.33234704f,
    0.2502173f, 0.15f, 0, 0, 0, 0, 1.9987241f, 2.0038424f, 2.0194368f, 2.0462565f, 2.0856655f,
    2.1398475f, 2.2121823f, 2.3079278f, 2.4355323f, 2.6093478f, 2.8559148f, 3.231099f, 3.8804243f,
    5.3851647f, 0, 0, 1.0363754f, 1.1132458f, 1.1967033f, 1.2883837f, 1.3904436f, 1.5058186f,
    1.6386535f, 1.7950549f, 1.9845079f, 2.2227776f, 2.5385911f, 2.9917583f, 3.7367048f,
    5.3851647f, 1, 1, 0.96234864f, 0.8905966f, 0.8227335f, 0.75787276f, 0.6952218f, 0.6340289f,
    0.5735287f, 0.5128728f, 0.45102453f, 0.38657004f, 0.3173239f, 0.23934066f, 0.14371942f, 0, 0,
    0, 1.9988886f, 2.0033455f, 2.016897f, 2.040107f, 2.07399f, 2.1201415f, 2.1809661f, 2.2600784f,
    2.3630173f, 2.4986107f, 2.6817904f, 2.9401073f, 3.331481f, 4.006691f, 5.5677643f, 0,
    1.0339079f, 1.105294f, 1.1823189f, 1.2662734f, 1.3588212f, 1.4621665f, 1.5793204f, 1.7145423f,
    1.8741173f, 2.0678158f, 2.3118882f, 2.6359582f, 3.1017237f, 3.868529f, 5.5677643f, 1,
    0.9649807f, 0.8980514f, 0.83457804f, 0.77383375f, 0.715169f, 0.65797496f, 0.6016459f,
    0.54553616f, 0.48890013f, 0.43079495f, 0.36990213f, 0.30414903f, 0.22975731f, 0.13816175f, 0,
    0, 1.9990232f, 2.002939f, 2.014826f, 2.035117f, 2.0645823f, 2.104417f, 2.156386f, 2.2230675f,
    2.308273f, 2.4177911f, 2.5607991f, 2.7527764f, 3.022239f, 3.4290845f, 4.1291647f, 5.7445626f,
    1.0317539f, 1.0983859f, 1.169899f, 1.2473296f, 1.3319886f, 1.4255729f, 1.5303384f, 1.6493727f,
    1.7870502f, 1.9498316f, 2.147767f, 2.3975794f, 2.7297642f, 3.2078533f, 3.9959657f, 5.7445626f,
    0.9672693f, 0.9045531f, 0.844927f, 0.78778714f, 0.7325937f, 0.6788442f, 0.6260475f,
    0.5736948f, 0.52122295f, 0.46795958f, 0.4130321f, 0.35519695f, 0.29247475f, 0.22123127f,
    0.13319886f, 0, 1.9991348f, 2.0026026f, 2.013115f, 2.0310097f, 2.0568833f, 2.09165f,
    2.136637f, 2.193741f, 2.265686f, 2.356456f, 2.4720662f, 2.6220222f, 2.8223248f, 3.1024184f,
    3.5241106f, 4.2481613f, 1.0298573f, 1.0923287f, 1.1590662f, 1.230915f, 1.3089257f, 1.3944334f,
    1.4891711f, 1.595448f, 1.7164289f, 1.8566016f, 2.0225997f, 2.224746f, 2.4802248f, 2.8203804f,
    3.310528f, 4.119429f, 0.96927744f, 0.91027385f, 0.8540487f, 0.80009466f, 0.7479576f,
    0.6972167f, 0.64746577f, 0.598293f, 0.5492572f, 0.4998543f, 0.4494666f, 0.39727607f,
    0.34209996f, 0.28203803f, 0.21358246f, 0.12873216f, 1.9992282f, 2.0023205f, 2.0116847f,
    2.0275874f, 2.0504987f, 2.0811303f, 2.1205018f, 2.170044f, 2.2317636f, 2.3085098f, 2.404423f,
    2.5257297f, 2.6822462f, 2.8904738f, 3.1807528f, 3.61674f, 1.0281745f, 1.086974f, 1.1495341f,
    1.2165525f, 1.288885f, 1.3676f, 1.4540584f, 1.5500314f, 1.6578816f, 1.7808505f, 1.9235384f,
    2.0927474f, 2.2990682f, 2.560134f, 2.9081168f, 3.4100692f, 0.9710537f, 0.91534656f,
    0.86215055f, 0.811035f, 0.76161385f, 0.7135304f, 0.6664434f, 0.6200126f, 0.5738821f,
    0.5276594f, 0.4808846f, 0.43298224f, 0.38317803f, 0.33033985f, 0.27263594f, 0.20667085f,
    1.9993074f, 2.0020823f, 2.0104768f, 2.0247054f, 2.0451427f, 2.072352f, 2.1071308f, 2.1505814f,
    2.20422f, 2.2701478f, 2.3513265f, 2.45204f, 2.5787146f, 2.7414641f, 2.9572716f, 3.2573447f,
    1.0266713f, 1.0822066f, 1.1410815f, 1.2038789f, 1.271305f, 1.3442284f, 1.423737f, 1.5112193f,
    1.6084849f, 1.7179497f, 1.8429315f, 1.9881405f, 2.1605449f, 2.370996f, 2.6375666f, 2.9932356f,
    0.972636f, 0.9198756f, 0.8693954f, 0.8208265f, 0.7738378f, 0.72812366f, 0.6833938f,
    0.63936204f, 0.59573513f, 0.5521981f, 0.5083949f, 0.46389946f, 0.41816995f, 0.3704681f,
    0.319705f, 0.26410902f, 1.9993749f, 2.0018787f, 2.0094473f, 2.0222547f, 2.0406034f,
    2.0649455f, 2.0959144f, 2.1343749f, 2.1814969f, 2.2388701f, 2.3086793f, 2.3939888f,
    2.4992187f, 2.6309843f, 2.7996848f, 3.0227706f, 1.0253204f, 1.0779347f, 1.1335344f,
    1.1926117f, 1.255756f, 1.323683f, 1.3972763f, 1.4776441f, 1.5662029f, 1.6648008f, 1.7759072f,
    1.9029143f, 2.0506408f, 2.2262175f, 2.4407508f, 2.712743f, 0.97405446f, 0.92394406f,
    0.87591296f, 0.82964295f, 0.7848475f, 0.7412625f, 0.69863814f, 0.6567307f, 0.615294f,
    0.57406926f, 0.5327721f, 0.49107465f, 0.4485777f, 0.4047668f, 0.35893396f, 0.31002778f,
    1.999433f, 2.0017037f, 2.0085628f, 2.020153f, 2.0367217f, 2.0586357f, 2.086405f, 2.120719f,
    2.1624968f, 2.212967f, 2.2737827f, 2.3472059f, 2.4363964f, 2.545902f, 2.6825209f, 2.8569279f,
    1.0240998f, 1.074085f, 1.1267548f, 1.1825286f, 1.2419034f, 1.3054763f, 1.3739741f, 1.4482958f,
    1.5295709f, 1.619244f, 1.7192016f, 1.8319654f, 1.9610019f, 2.1112359f, 2.2899568f, 2.508522f,
    0.97533315f, 0.92761886f, 0.8818081f, 0.83762443f, 0.7948182f, 0.7531594f, 0.712431f,
    0.67242306f, 0.6329259f, 0.5937228f, 0.55458117f, 0.5152403f, 0.4753944f, 0.43466622f,
    0.39256403f, 0.34840584f, 1.9994833f, 2.001552f, 2.0077972f, 2.018337f, 2.0333753f,
    2.0532136f, 2.0782676f, 2.1090937f, 2.1464255f, 2.19123f, 2.2447855f, 2.3088045f, 2.3856187f,
    2.478479f, 2.592055f, 2.7333207f, 1.0229915f, 1.0705976f, 1.1206311f, 1.1734518f, 1.2294828f,
    1.2892271f, 1.3532906f, 1.4224119f, 1.4975063f, 1.579724f, 1.6705382f, 1.7718732f, 1.8863032f,
    2.0173664f, 2.1700926f, 2.3519273f, 0.97649187f, 0.9309545f, 0.88716626f, 0.84488523f,
    0.8038926f, 0.76398647f, 0.7249771f, 0.6866816f, 0.64891934f, 0.61150604f, 0.5742475f,
    0.5369313f, 0.49931553f, 0.46111232f, 0.42196247f, 0.3813936f, 1.9995273f, 2.00142f,
    2.0071301f, 2.0167568f, 2.0304697f, 2.0485187f, 2.0712461f, 2.099107f, 2.1326947f, 2.1727822f,
    2.220376f, 2.276801f, 2.343823f, 2.42384f, 2.5201888f, 2.6376574f, 1.0219806f, 1.0674239f,
    1.1150723f, 1.1652372f, 1.2182817f, 1.2746338f, 1.3348031f, 1.3994046f, 1.4691898f,
    1.5450895f, 1.6282758f, 1.7202498f, 1.8229735f, 1.9390719f, 2.0721552f, 2.2273552f,
    0.9775467f, 0.93399596f, 0.89205784f, 0.8515195f, 0.81218785f, 0.77388483f, 0.7364431f,
    0.6997023f, 0.6635051f, 0.62769264f, 0.59210026f, 0.5565514f, 0.5208496f, 0.48476797f,
    0.44803354f, 0.41030228f, 1.999566f, 2.001304f, 2.0065453f, 2.015373f, 2.02793f, 2.044425f,
    2.0651429f, 2.090459f, 2.1208599f, 2.1569712f, 2.1995988f, 2.2497864f, 2.3088999f, 2.3787553f,
    2.4618137f, 2.5614944f, 1.021055f, 1.0645233f, 1.1100037f, 1.1577675f, 1.2081285f, 1.2614536f,
    1.3181763f, 1.3788134f, 1.4439898f, 1.5144693f, 1.5911992f, 1.6753728f, 1.768519f, 1.8726372f,
    1.9904025f, 2.1254954f, 0.978511f, 0.9367806f, 0.8965415f, 0.8576055f, 0.8198015f,
    0.78297126f, 0.74696654f, 0.7116456f, 0.67687017f, 0.64250207f, 0.6083997f, 0.57441354f,
    0.54038084f, 0.5061181f, 0.4714111f, 0.43599904f, 1.9995999f, 2.0012016f, 2.0060296f,
    2.0141544f, 2.025697f, 2.0408332f, 2.059802f, 2.0829167f, 2.1105795f, 2.1433036f, 2.1817424f,
    2.2267315f, 2.2793477f, 2.3409963f, 2.41354f, 2.4995f, 1.0202041f, 1.061862f, 1.1053632f,
    1.1509454f, 1.1988819f, 1.2494897f, 1.30314f, 1.360272f, 1.4214106f, 1.4871902f, 1.5583874f,
    1.6359661f, 1.7211401f, 1.8154664f, 1.9209807f, 2.0404081f, 0.9793959f, 0.9393395f,
    0.90066636f, 0.86320907f, 0.82681507f, 0.79134345f, 0.75666195f, 0.72264457f, 0.6891688f,
    0.6561133f, 0.623355f, 0.59076554f, 0.55820763f, 0.52552974f, 0.49255916f, 0.45909184f,
    1.9996301f, 2.0011108f, 2.0055726f, 2.0130756f, 2.023723f, 2.0376637f, 2.0551004f, 2.0762959f,
    2.1015868f, 2.131398f, 2.166266f, 2.206869f, 2.254069f, 2.308974f, 2.3730254f, 2.4481316f,
    1.0194193f, 1.0594116f, 1.1010987f, 1.1446902f, 1.1904253f, 1.23858f, 1.2894747f, 1.3434856f,
    1.4010578f, 1.4627241f, 1.5291289f, 1.6010617f, 1.6795024f, 1.765686f, 1.8611965f, 1.9681058f,
    0.98021084f, 0.9416992f, 0.9044739f, 0.8683856f, 0.83329767f, 0.7990838f, 0.7656256f,
    0.7328103f, 0.7005289f, 0.6686739f, 0.63713706f, 0.6058071f, 0.5745666f, 0.543288f, 0.511829f,
    0.4800258f, 1.999657f, 2.00103f, 2.0051658f, 2.0121162f, 2.021969f, 2.0348525f, 2.0509386f,
    2.0704503f, 2.093671f, 2.1209567f, 2.1527517f, 2.1896136f, 2.2322423f, 2.2815251f, 2.3385985f,
    2.4049387f, 1.0186932f, 1.0571479f, 1.0971662f, 1.1389337f, 1.1826612f, 1.2285903f,
    1.2769995f, 1.3282135f, 1.382613f, 1.4406497f, 1.5028645f, 1.5699117f, 1.6425934f, 1.7219058f,
    1.8091046f, 1.9058005f, 0.9809638f, 0.94388205f, 0.9079996f, 0.8731825f, 0.8393079f,
    0.8062623f, 0.7739391f, 0.7422369f, 0.7110581f, 0.68030685f, 0.6498873f, 0.619702f,
    0.5896489f, 0.55961937f, 0.529494f, 0.4991382f, 1.9996811f, 2.0009577f, 2.004802f, 2.0112586f,
    2.0204036f, 2.0323472f, 2.0472362f, 2.0652618f, 2.086664f, 2.1117432f, 2.140872f, 2.174513f,
    2.2132413f, 2.257778f, 2.309033f, 2.36817f, 1.0180194f, 1.0550504f, 1.0935283f, 1.1336185f,
    1.1755077f, 1.2194083f, 1.2655642f, 1.3142575f, 1.3658165f, 1.4206272f, 1.479148f, 1.5419275f,
    1.6096301f, 1.6830708f, 1.7632614f, 1.8514783f, 0.9816616f, 0.94590724f, 0.9112736f,
    0.8776401f, 0.8448961f, 0.81293887f, 0.78167206f, 0.7510043f, 0.72084755f, 0.691116f,
    0.6617241f, 0.6325856f, 0.6036113f, 0.5747071f, 0.5457714f, 0.5166916f, 1.9997027f,
    2.0008926f, 2.0044754f, 2.0104892f, 2.0190008f, 2.0301044f, 2.0439274f, 2.060634f, 2.080429f,
    2.1035683f, 2.1303666f, 2.161211f, 2.1965802f, 2.237066f, 2.2834084f, 2.3365393f, 1.0173926f,
    1.0531014f, 1.0901532f, 1.1286957f, 1.1688951f, 1.2109394f, 1.2550433f, 1.301453f, 1.350454f,
    1.4023789f, 1.4576192f, 1.5166394f, 1.5799962f, 1.6483644f, 1.7225711f, 1.8036443f,
    0.9823101f, 0.9477913f, 0.9143221f, 0.88179356f, 0.8501055f, 0.8191649f, 0.7888843f,
    0.7591809f, 0.7299751f, 0.70118946f, 0.6727473f, 0.6445717f, 0.6165839f, 0.5887016f,
    0.56083715f, 0.5328949f, 1.9997222f, 2.000834f, 2.004181f, 2.0097964f, 2.017738f, 2.0280886f,
    2.040958f, 2.0564878f, 2.074855f, 2.0962784f, 2.1210258f, 2.1494246f, 2.1818757f, 2.2188718f,
    2.261021f, 2.3090804f, 1.0168079f, 1.0512857f, 1.0870134f, 1.1241235f, 1.1627643f, 1.2031033f,
    1.2453302f, 1.2896619f, 1.3363473f, 1.3856755f, 1.4379835f, 1.4936678f, 1.5531998f, 1.617144f,
    1.6861851f, 1.761163f, 0.9829143f, 0.94954836f, 0.91716754f, 0.885673f, 0.8549738f,
    0.82498515f, 0.79562765f, 0.766826f, 0.73850775f, 0.7106029f, 0.68304217f, 0.65575665f,
    0.62867606f, 0.60172796f, 0.57483584f, 0.54791737f, 1.9997399f, 2.000781f, 2.0039146f,
    2.00917f, 2.0165977f, 2.0262697f, 2.0382822f, 2.052758f, 2.0698504f, 2.0897477f, 2.1126795f,
    2.138925f, 2.1688232f, 2.2027874f, 2.2413232f, 2.285053f, 1.0162612f, 1.0495901f, 1.084085f,
    1.1198653f, 1.1570643f, 1.1958313f, 1.2363352f, 1.2787673f, 1.323347f, 1.3703264f, 1.4199977f,
    1.4727024f, 1.5288427f, 1.5888959f, 1.6534351f, 1.7231548f, 0.9834786f, 0.951191f,
    0.91982967f, 0.8893048f, 0.8595335f, 0.83043844f, 0.8019471f, 0.77399075f, 0.7465035f,
    0.7194213f, 0.6926818f, 0.6662225f, 0.6399806f, 0.6138916f, 0.58788806f, 0.5618983f,
    1.9997559f, 2.000733f, 2.003673f, 2.0086021f, 2.0155644f, 2.0246232f, 2.0358627f, 2.04939f,
    2.0653389f, 2.0838723f, 2.1051884f, 2.1295266f, 2.1571763f, 2.1884866f, 2.2238822f,
    2.2638807f, 1.015749f, 1.048003f, 1.0813473f, 1.1158901f, 1.1517512f, 1.1890644f, 1.2279806f,
    1.2686701f, 1.3113263f, 1.3561709f, 1.403459f, 1.4534864f, 1.5065992f, 1.5632048f, 1.623787f,
    1.6889269f, 0.9840068f, 0.95273f, 0.92232573f, 0.89271206f, 0.86381334f, 0.8355588f,
    0.807882f, 0.78072006f, 0.75401264f, 0.7277014f, 0.7017295f, 0.67604023f, 0.65057695f,
    0.6252819f, 0.6000952f, 0.57495385f, 1.9997704f, 2.0006893f, 2.0034533f, 2.0080855f,
    2.014625f, 2.0231276f, 2.0336673f, 2.046338f, 2.0612571f, 2.078566f, 2.098437f, 2.1210768f,
    2.1467338f, 2.1757057f, 2.2083523f, 2.245108f, 1.0152681f, 1.0465144f, 1.0787826f, 1.1121705f,
    1.1467866f, 1.1827515f, 1.2202003f, 1.2592851f, 1.3001775f, 1.3430734f, 1.3881968f,
    1.4358059f, 1.4862002f, 1.5397302f, 1.5968086f, 1.6579258f, 0.9845024f, 0.9541749f,
    0.9246707f, 0.8959151f, 0.86783844f, 0.8403761f, 0.8134669f, 0.78705317f, 0.7610795f,
    0.7354926f, 0.7102402f, 0.68527097f, 0.6605334f, 0.63597554f, 0.6115437f, 0.58718204f,
    1.9997838f, 2.0006492f, 2.0032525f, 2.0076141f, 2.0137684f, 2.0217648f, 2.031669f, 2.0435636f,
    2.0575511f, 2.0737562f, 2.092329f, 2.113449f, 2.1373305f, 2.1642299f, 2.1944532f, 2.228369f,
    1.0148156f, 1.0451152f, 1.0763745f, 1.1086824f, 1.1421373f, 1.1768482f, 1.2129366f,
    1.2505388f, 1.2898082f, 1.3309182f, 1.3740668f, 1.4194807f, 1.4674209f, 1.5181911f,
    1.5721456f, 1.6297027f, 0.9849681f, 0.955534f, 0.92687804f, 0.8989317f, 0.8716311f,
    0.84491664f, 0.81873226f, 0.79302466f, 0.76774293f, 0.7428381f, 0.7182622f, 0.69396836f,
    0.6699096f, 0.6460388f, 0.62230766f, 0.5986663f, 1.9997959f, 2.0006127f, 2.003069f,
    2.0071828f, 2.0129852f, 2.0205197f, 2.0298445f, 2.0410333f, 2.0541759f, 2.0693822f, 2.086784f,
    2.1065373f, 2.1288295f, 2.1538813f, 2.1819563f, 2.2133684f, 1.0143893f, 1.0437979f,
    1.0741094f, 1.105405f, 1.1377742f, 1.1713158f, 1.2061396f, 1.242368f, 1.2801385f, 1.3196061f,
    1.3609459f, 1.4043583f, 1.4500723f, 1.4983522f, 1.5495051f, 1.6038902f, 0.9854067f,
    0.95681477f, 0.9289595f, 0.9017778f, 0.87521094f, 0.84920394f, 0.8237051f, 0.79866517f,
    0.77403724f, 0.7497762f, 0.7258378f, 0.70217913f, 0.67875725f, 0.6555291f, 0.63245106f,
    0.6094783f, 1.9998071f, 2.000579f, 2.0029004f, 2.0067873f, 2.012267f, 2.019379f, 2.0281746f,
    2.038719f, 2.0510926f, 2.0653918f, 2.081733f, 2.1002533f, 2.1211157f, 2.144513f, 2.1706722f,
    2.1998641f, 1.0139867f, 1.0425553f, 1.0719749f, 1.1023197f, 1.1336716f, 1.1661203f,
    1.1997652f, 1.2347171f, 1.2710996f, 1.3090512f, 1.3487284f, 1.3903085f, 1.4339937f,
    1.4800159f, 1.5286424f, 1.5801841f, 0.9858204f, 0.9580238f, 0.93092555f, 0.90446746f,
    0.8785955f, 0.8532587f, 0.8284093f, 0.80400187f, 0.77999294f, 0.7563407f, 0.73300457f,
    0.7099448f, 0.687122f, 0.66449696f, 0.6420298f, 0.61968005f, 1.9998174f, 2.0005481f,
    2.0027454f, 2.0064235f, 2.0116072f, 2.018331f, 2.0266418f, 2.036597f, 2.048268f, 2.061741f,
    2.0771184f, 2.0945213f, 2.1140926f, 2.1360009f, 2.1604443f, 2.1876562f, 1.0136061f,
    1.0413812f, 1.0699599f, 1.0994102f, 1.1298068f, 1.1612316f, 1.1937753f, 1.2275379f, 1.262631f,
    1.2991793f, 1.3373228f, 1.3772194f, 1.4190485f, 1.4630144f, 1.5093514f, 1.5583304f,
    0.9862113f, 0.95916694f, 0.9327855f, 0.90701336f, 0.88180035f, 0.85709953f, 0.8328665f,
    0.8090591f, 0.7856371f, 0.7625618f, 0.73979557f, 0.7173018f, 0.69504416f, 0.67298657f,
    0.65109277f, 0.62932575f, 1.9998269f, 2.0005198f, 2.0026026f, 2.0060883f, 2.0109992f,
    2.0173664f, 2.0252314f, 2.034646f, 2.045674f, 2.0583918f, 2.0728905f, 2.0892773f, 2.1076782f,
    2.1282415f, 2.1511402f, 2.1765776f, 1.0132456f, 1.0402702f, 1.0680547f, 1.0966616f,
    1.1261595f, 1.1566235f, 1.1881357f, 1.2207876f, 1.2546802f, 1.2899256f, 1.3266499f,
    1.3649944f, 1.4051188f, 1.4472042f, 1.4914571f, 1.5381148f, 0.98658127f, 0.9602494f,
    0.93454784f, 0.9094267f, 0.88483965f, 0.86074305f, 0.8370957f, 0.81385845f, 0.790994f,
    0.7684663f, 0.74624056f, 0.7242828f, 0.7025594f, 0.68103725f, 0.659683f, 0.6384627f,
    1.9998356f, 2.0004933f, 2.0024705f, 2.0057788f, 2.010438f, 2.0164762f, 2.0239308f, 2.0328484f,
    2.0432858f, 2.0553114f, 2.0690067f, 2.0844665f, 2.1018026f, 2.121146f, 2.1426487f, 2.1664886f,
    1.0129038f, 1.0392174f, 1.0662504f, 1.0940611f, 1.122712f, 1.1522721f, 1.1828167f, 1.2144289f,
    1.2472005f, 1.2812332f, 1.3166405f, 1.3535496f, 1.3921031f, 1.4324622f, 1.4748101f,
    1.5193557f, 0.98693186f, 0.96127605f, 0.93621993f, 0.9117176f, 0.88772583f, 0.8642041f,
    0.84111416f, 0.8184195f, 0.7960854f, 0.77407837f, 0.752366f, 0.7309168f, 0.70969963f,
    0.68868375f, 0.6678386f, 0.64713293f, 1.9998437f, 2.000469f, 2.0023482f, 2.0054922f,
    2.0099187f, 2.0156531f, 2.022729f, 2.0311882f, 2.041082f, 2.0524716f, 2.0654297f, 2.0800414f,
    2.096406f, 2.114639f, 2.1348753f, 2.157271f, 1.0125791f, 1.038218f, 1.0645396f, 1.091597f,
    1.1194483f, 1.1481568f, 1.1777915f, 1.2084284f, 1.240151f, 1.2730521f, 1.307234f, 1.3428115f,
    1.3799127f, 1.4186819f, 1.4592818f, 1.5018976f, 0.98726463f, 0.9622509f, 0.9378087f,
    0.91389513f, 0.89047027f, 0.86749625f, 0.8449374f, 0.82275975f, 0.8009309f, 0.7794196f,
    0.7581957f, 0.7372298f, 0.7164931f, 0.6959571f, 0.67559344f, 0.65537345f, 1.9998512f,
    2.0004463f, 2.002235f, 2.0052264f, 2.009437f, 2.0148902f, 2.0216157f, 2.0296514f, 2.0390437f,
    2.0498476f, 2.062128f, 2.0759614f, 2.0914361f, 2.1086557f, 2.127739f, 2.1488242f, 1.0122705f,
    1.0372685f, 1.0629148f, 1.0892588f, 1.116354f, 1.1442586f, 1.1730363f, 1.2027564f, 1.2334956f,
    1.265338f, 1.2983769f, 1.3327159f, 1.3684705f, 1.4057704f, 1.4447609f, 1.4856068f, 0.9875809f,
    0.96317786f, 0.9393201f, 0.91596764f, 0.8930832f, 0.8706316f, 0.8485794f, 0.82689506f,
    0.80554813f, 0.78450954f, 0.7637511f, 0.7432454f, 0.7229656f, 0.7028852f, 0.6829779f,
    0.6632173f, 1.9998583f, 2.0004253f, 2.0021296f, 2.0049796f, 2.00899f, 2.014182f, 2.0205827f,
    2.0282264f, 2.037155f, 2.0474176f, 2.0590734f, 2.0721908f, 2.086849f, 2.1031399f, 2.12117f,
    2.1410618f, 1.0119765f, 1.0363649f, 1.0613699f, 1.0870371f, 1.1134162f, 1.1405609f,
    1.1685297f, 1.1973867f, 1.2272017f, 1.2580519f, 1.2900219f, 1.3232062f, 1.3577089f, 1.393647f,
    1.4311509f, 1.4703678f, 0.9878818f, 0.9640604f, 0.94075966f, 0.91794246f, 0.8955739f,
    0.8736211f, 0.852053f, 0.83083975f, 0.80995315f, 0.7893658f, 0.76905155f, 0.7489846f,
    0.72914f, 0.709493f, 0.6900192f, 0.67069405f, 1.9998648f, 2.0004058f, 2.0020316f, 2.0047498f,
    2.008574f, 2.0135233f, 2.0196223f, 2.0269024f, 2.0354009f, 2.0451632f, 2.0562418f, 2.0686986f,
    2.082605f, 2.0980432f, 2.1151085f, 2.13391f, 1.0116963f, 1.0355042f, 1.059899f, 1.0849234f,
    1.1106234f, 1.1370485f, 1.164253f, 1.1922956f, 1.2212406f, 1.2511586f, 1.2821273f, 1.314232f,
    1.3475679f, 1.3822403f, 1.4183669f, 1.4560797f, 0.9881685f, 0.9649016f, 0.9421325f,
    0.9198264f, 0.89795077f, 0.87647486f, 0.8553695f, 0.8346069f, 0.8141604f, 0.7940045f,
    0.77411455f, 0.75446653f, 0.735037f, 0.715803f, 0.69674164f, 0.6778302f, 1.9998709f,
    2.0003877f, 2.00194f, 2.0045357f, 2.0081863f, 2.0129097f, 2.018728f, 2.0256698f, 2.0337694f,
    2.0430672f, 2.0536115f, 2.0654578f, 2.0786703f, 2.0933235f, 2.1095023f, 2.1273043f, 1.011429f,
    1.0346832f, 1.0584971f, 1.0829101f, 1.1079649f, 1.1337078f, 1.1601886f, 1.1874617f,
    1.2155863f, 1.2446272f, 1.2746555f, 1.3057492f, 1.3379947f, 1.3714879f, 1.4063349f,
    1.4426546f, 0.98844194f, 0.9657043f, 0.943443f, 0.92162555f, 0.90022147f, 0.87920195f,
    0.8585395f, 0.83820826f, 0.81818306f, 0.7984401f, 0.7789561f, 0.7597086f, 0.7406756f,
    0.7218357f, 0.70316744f, 0.68464965f, 1.9998765f, 2.0003705f, 2.0018547f, 2.0043356f,
    2.0078244f, 2.012337f, 2.0178938f, 2.0245206f, 2.032249f, 2.0411155f, 2.0511637f, 2.0624442f,
    2.0750153f, 2.0889435f, 2.1043057f, 2.1211894f, 1.0111735f, 1.0338994f, 1.0571592f, 1.08099f,
    1.1054314f, 1.1305264f, 1.1563212f, 1.1828661f, 1.2102157f, 1.2384295f, 1.2675731f,
    1.2977178f, 1.3289424f, 1.3613341f, 1.3949893f, 1.4300153f, 0.988703f, 0.96647114f,
    0.9446955f, 0.9233456f, 0.902393f, 0.88181055f, 0.8615726f, 0.84165466f, 0.8220333f,
    0.80268586f, 0.7835907f, 0.7647265f, 0.7460729f, 0.7276096f, 0.70931655f, 0.6911741f,
    1.9998819f, 2.0003545f, 2.0017748f, 2.0041485f, 2.007486f, 2.0118017f, 2.0171142f, 2.0234475f,
    2.0308297f, 2.0392945f, 2.0488818f, 2.059637f, 2.0716133f, 2.084871f, 2.0994792f, 2.1155164f,
    1.0109293f, 1.0331502f, 1.0558811f, 1.0791569f, 1.1030142f, 1.1274933f, 1.1526368f,
    1.1784914f, 1.2051077f, 1.2325407f, 1.2608503f, 1.2901024f, 1.320369f, 1.3517295f, 1.384272f,
    1.4180934f, 0.9889526f, 0.9672044f, 0.9458936f, 0.9249916f, 0.9044717f, 0.8843084f,
    0.8644776f, 0.8449561f, 0.8257219f, 0.8067539f, 0.78803146f, 0.76953477f, 0.7512444f,
    0.7331415f, 0.71520716f, 0.697423f, 1.9998869f, 2.0003397f, 2.0017f, 2.0039732f, 2.007169f,
    2.0113006f, 2.0163848f, 2.0224435f, 2.0295026f, 2.0375931f, 2.0467508f, 2.0570178f,
    2.0684416f, 2.081077f, 2.0949874f, 2.1102428f, 1.0106955f, 1.0324334f, 1.0546591f, 1.077405f,
    1.1007056f, 1.1245981f, 1.1491225f, 1.174322f, 1.2002435f, 1.2269378f, 1.2544602f, 1.2828712f,
    1.3122371f, 1.3426305f, 1.3741314f, 1.4068285f, 0.98919135f, 0.9679063f, 0.94704086f,
    0.9265683f, 0.90646344f, 0.88670236f, 0.8672623f, 0.84812146f, 0.82925916f, 0.81065536f,
    0.7922907f, 0.77414644f, 0.7562044f, 0.7384468f, 0.72085583f, 0.7034143f, 1.9998915f,
    2.0003257f, 2.0016298f, 2.003809f, 2.006872f, 2.0108306f, 2.015701f, 2.021503f, 2.0282602f,
    2.0360007f, 2.0447578f, 2.0545692f, 2.065479f, 2.0775368f, 2.0907993f, 2.1053312f, 1.0104715f,
    1.0317469f, 1.0534893f, 1.075729f, 1.0984983f, 1.1218319f, 1.145767f, 1.1703439f, 1.195606f,
    1.2216004f, 1.2483784f, 1.2759957f, 1.3045131f, 1.3339974f, 1.3645217f, 1.396167f, 0.98942f,
    0.96857876f, 0.94814044f, 0.92807996f, 0.9083736f, 0.8889988f, 0.8699342f, 0.85115916f,
    0.8326542f, 0.8144003f, 0.7963793f, 0.77857363f, 0.76096594f, 0.7435395f, 0.7262777f,
    0.7091642f, 1.9998958f, 2.0003126f, 2.0015638f, 2.0036547f, 2.006593f, 2.0103896f, 2.0150595f,
    2.0206208f, 2.027095f, 2.0345082f, 2.0428908f, 2.0522773f, 2.0627077f, 2.0742273f, 2.086888f,
    2.1007483f, 1.0102566f, 1.031089f, 1.0523686f, 1.0741242f, 1.0963858f, 1.119186f, 1.1425595f,
    1.166544f, 1.1911795f, 1.2165102f, 1.242583f, 1.2694498f, 1.2971667f, 1.3257948f, 1.3554015f,
    1.3860607f, 0.9896392f, 0.96922356f, 0.9491952f, 0.9295305f, 0.9102071f, 0.8912037f, 0.8725f,
    0.8540768f, 0.83591545f, 0.8179982f, 0.80030775f, 0.78282744f, 0.765541f, 0.7484326f,
    0.73148656f, 0.7146876f, 1.9999f, 2.0003002f, 2.0015018f, 2.0035095f, 2.0063305f, 2.0099752f,
    2.0144567f, 2.0197918f, 2.026001f, 2.0331075f, 2.0411394f, 2.0501285f, 2.060111f, 2.071129f,
    2.083229f, 2.0964649f, 1.0100505f, 1.0304576f, 1.0512938f, 1.0725859f, 1.0943621f, 1.1166528f,
    1.1394906f, 1.1629105f, 1.1869501f, 1.2116499f, 1.2370542f, 1.2632104f, 1.2901706f,
    1.3179911f, 1.346734f, 1.3764669f, 0.9898495f, 0.9698425f, 0.95020795f, 0.93092364f,
    0.9119684f, 0.8933223f, 0.874966f, 0.85688144f, 0.8390509f, 0.82145756f, 0.8040852f,
    0.786918f, 0.7699405f, 0.7531378f, 0.73649514f, 0.719998f, 1.9999039f, 2.0002885f, 2.0014434f,
    2.003373f, 2.0060835f, 2.009585f, 2.0138893f, 2.0190122f, 2.0249722f, 2.031791f, 2.039494f,
    2.048111f, 2.0576746f, 2.0682237f, 2.0798008f, 2.0924547f, 1.0098524f, 1.0298514f, 1.0502625f,
    1.0711102f, 1.0924218f, 1.1142253f, 1.1365515f, 1.1594328f, 1.1829046f, 1.2070045f,
    1.2317736f, 1.2572562f, 1.2835001f, 1.3105576f, 1.3384857f, 1.3673466f, 0.99005145f,
    0.970437f, 0.95118105f, 0.93226266f, 0.91366184f, 0.89535964f, 0.87733793f, 0.8595795f,
    0.84206766f, 0.8247864f, 0.8077204f, 0.7908547f, 0.77417463f, 0.7576661f, 0.7413152f,
    0.7251081f, 1.9999075f, 2.0002775f, 2.0013883f, 2.0032442f, 2.0058508f, 2.0092173f, 2.013355f,
    2.0182781f, 2.0240037f, 2.030552f, 2.0379465f, 2.046214f, 2.0553854f, 2.0654957f, 2.0765839f,
    2.0886948f, 1.009662f, 1.029269f, 1.0492716f, 1.0696934f, 1.0905597f, 1.111897f, 1.1337339f,
    1.156101f, 1.1790313f, 1.20256f, 1.2267251f, 1.2515678f, 1.2771327f, 1.3034681f, 1.3306266f,
    1.3586656f, 0.99024546f, 0.9710085f, 0.9521168f, 0.93355066f, 0.91529113f, 0.89732033f,
    0.8796211f, 0.862177f, 0.84497243f, 0.8279921f, 0.8112214f, 0.7946462f, 0.7782527f,
    0.7620275f, 0.7459574f, 0.7300293f, 1.999911f, 2.000267f, 2.0013363f, 2.0031226f, 2.0056312f,
    2.0088704f, 2.012851f, 2.0175858f, 2.0230908f, 2.0293846f, 2.0364888f, 2.0444283f, 2.0532315f,
    2.0629303f, 2.0735612f, 2.0851643f, 1.0094789f, 1.0287088f, 1.0483191f, 1.0683321f,
    1.0887712f, 1.1096617f, 1.1310306f, 1.1529062f, 1.1753194f, 1.1983032f, 1.2218933f,
    1.2461278f, 1.2710481f, 1.2966992f, 1.3231294f, 1.3503921f, 0.9904321f, 0.9715583f,
    0.95301735f, 0.93479055f, 0.91686f, 0.89920866f, 0.8818204f, 0.8646796f, 0.84777135f,
    0.83108133f, 0.8145955f, 0.7983006f, 0.78218347f, 0.7662313f, 0.75043166f, 0.7347722f,
    1.9999143f, 2.0002573f, 2.0012875f, 2.0030077f, 2.0054238f, 2.0085428f, 2.0123749f,
    2.0169322f, 2.0222292f, 2.0282834f, 2.0351143f, 2.0427454f, 2.0512025f, 2.0605152f,
    2.0707166f, 2.0818446f, 1.0093025f, 1.0281696f, 1.0474027f, 1.0670228f, 1.0870521f,
    1.1075143f, 1.1284345f, 1.1498399f, 1.171759f, 1.1942228f, 1.2172647f, 1.2409201f, 1.2652277f,
    1.2902291f, 1.3159695f, 1.3424978f, 0.99061173f, 0.9720876f, 0.9538846f, 0.9359849f,
    0.9183716f, 0.9010286f, 0.8839404f, 0.8670923f, 0.85047024f, 0.83406043f, 0.8178497f,
    0.8018253f, 0.78597474f, 0.770286f, 0.7547472f, 0.7393466f, 1.9999174f, 2.000248f, 2.001241f,
    2.0028992f, 2.0052276f, 2.008233f, 2.011925f, 2.0163145f, 2.0214152f, 2.0272431f, 2.0338166f,
    2.041157f, 2.0492885f, 2.0582383f, 2.0680368f, 2.0787187f, 1.0091326f, 1.0276504f, 1.0465205f,
    1.0657629f, 1.0853983f, 1.1054494f, 1.1259396f, 1.1468945f, 1.1683409f, 1.1903079f,
    1.2128265f, 1.23593f, 1.2596544f, 1.2840385f, 1.3091242f, 1.334957f, 0.99078476f, 0.97259766f,
    0.95472044f, 0.9371363f, 0.91982913f, 0.9027837f, 0.8859853f, 0.86942f, 0.8530743f,
    0.8369352f, 0.8209902f, 0.8052271f, 0.7896341f, 0.77419966f, 0.75891256f, 0.7437617f,
    1.9999202f, 2.0002391f, 2.0011969f, 2.0027962f, 2.0050418f, 2.0079398f, 2.0114992f,
    2.0157301f, 2.0206454f, 2.0262597f, 2.0325902f, 2.0396566f, 2.047481f, 2.0560892f, 2.0655088f,
    2.0757718f, 1.0089688f, 1.0271499f, 1.0456705f, 1.0645493f, 1.0838064f, 1.1034625f, 1.12354f,
    1.1440631f, 1.1650568f, 1.1865485f, 1.2085671f, 1.2311441f, 1.2543128f, 1.2781094f,
    1.3025731f, 1.3277459f, 0.9909515f, 0.97308934f, 0.9555265f, 0.9382469f, 0.9212354f,
    0.9044774f, 0.8879591f, 0.8716671f, 0.8555886f, 0.83971125f, 0.82402307f, 0.8085125f,
    0.79316837f, 0.7779797f, 0.7629357f, 0.7480259f, 1.999923f, 2.0002308f, 2.0011554f, 2.002699f,
    2.0048656f, 2.007662f, 2.011096f, 2.0151768f, 2.0199165f, 2.0253289f, 2.0314298f, 2.0382373f,
    2.0457726f, 2.0540583f, 2.063121f, 2.0729902f, 1.0088108f, 1.0266672f, 1.044851f, 1.0633799f,
    1.0822726f, 1.1015491f, 1.1212305f, 1.1413391f, 1.1618989f, 1.1829355f, 1.2044761f, 1.22655f,
    1.2491885f, 1.2724255f, 1.2962974f, 1.3208433f, 0.9911123f, 0.97356373f, 0.9563043f,
    0.9393189f, 0.92259306f, 0.90611297f, 0.88986546f, 0.8738377f, 0.8580176f, 0.8423934f,
    0.8269537f, 0.81168747f, 0.796584f, 0.78163284f, 0.7668238f, 0.7521469f, 1.9999257f,
    2.000223f, 2.0011158f, 2.0026064f, 2.0046988f, 2.0073986f, 2.0107136f, 2.0146523f, 2.0192258f,
    2.024447f, 2.0303307f, 2.0368938f, 2.0441554f, 2.0521374f, 2.0608637f, 2.0703616f, 1.0086582f,
    1.0262014f, 1.0440603f, 1.062252f, 1.0807941f, 1.0997053f, 1.1190058f, 1.1387165f, 1.15886f,
    1.1794604f, 1.2005434f, 1.2221363f, 1.2442685f, 1.2669717f, 1.2902799f, 1.3142295f,
    0.9912675f, 0.9740216f, 0.9570554f, 0.9403543f, 0.92390466f, 0.9076933f, 0.8917077f,
    0.87593573f, 0.86036575f, 0.84498656f, 0.8297873f, 0.8147575f, 0.7998869f, 0.7851656f,
    0.7705838f, 0.75613207f, 1.9999282f, 2.0002155f, 2.0010781f, 2.0025187f, 2.0045402f,
    2.0071487f, 2.0103505f, 2.0141544f, 2.0185704f, 2.0236106f, 2.0292888f, 2.0356202f,
    2.0426235f, 2.050318f, 2.0587268f, 2.0678747f, 1.0085108f, 1.0257516f, 1.0432972f, 1.0611637f,
    1.0793679f, 1.0979275f, 1.1168615f, 1.1361897f, 1.1559335f, 1.1761156f, 1.1967599f,
    1.2178925f, 1.2395407f, 1.2617342f, 1.2845048f, 1.3078865f, 0.9914174f, 0.97446394f,
    0.957781f, 0.9413549f, 0.92517245f, 0.9092212f, 0.8934891f, 0.87796474f, 0.862637f,
    0.8474951f, 0.83252865f, 0.8177278f, 0.8030827f, 0.7885839f, 0.7742221f, 0.7599881f,
    1.9999305f, 2.0002084f, 2.0010426f, 2.0024352f, 2.0043898f, 2.006911f, 2.010006f, 2.0136817f,
    2.0179484f, 2.0228167f, 2.0282998f, 2.0344121f, 2.0411706f, 2.0485935f, 2.0567021f,
    2.0655193f, 1.0083684f, 1.025317f, 1.04256f, 1.0601127f, 1.0779911f, 1.096212f, 1.1147932f,
    1.1337535f, 1.1531134f, 1.1728938f, 1.1931175f, 1.213809f, 1.2349939f, 1.2567003f, 1.2789576f,
    1.301798f, 0.9915622f, 0.9748915f, 0.95848256f, 0.94232243f, 0.92639863f, 0.9106992f,
    0.8952127f, 0.8799282f, 0.86483496f, 0.849923f, 0.83518225f, 0.82060325f, 0.8061766f,
    0.7918933f, 0.7777445f, 0.76372147f, 1.9999328f, 2.0002017f, 2.0010085f, 2.0023558f,
    2.0042465f, 2.0066853f, 2.0096781f, 2.0132325f, 2.017357f, 2.0220623f, 2.0273604f, 2.033265f,
    2.0397916f, 2.0469573f, 2.0547817f, 2.0632865f, 1.0082306f, 1.0248967f, 1.0418475f,
    1.0590973f, 1.0766613f, 1.0945556f, 1.1127969f, 1.1314033f, 1.1503936f, 1.1697881f,
    1.1896082f, 1.2098767f, 1.230618f, 1.2518581f, 1.273625f, 1.2959485f, 0.9917022f, 0.9753049f,
    0.95916116f, 0.9432585f, 0.9275852f, 0.91212964f, 0.8968811f, 0.8818291f, 0.8669633f,
    0.85227424f, 0.8377523f, 0.82338834f, 0.80917346f, 0.7950991f, 0.78115666f, 0.7673379f,
    1.9999349f, 2.0001953f, 2.0009763f, 2.0022802f, 2.00411f, 2.0064702f, 2.0093663f, 2.0128047f,
    2.0167947f, 2.0213451f, 2.0264676f, 2.0321748f, 2.0384812f, 2.045403f, 2.0529585f, 2.0611675f,
    1.0080973f, 1.0244902f, 1.0411584f, 1.0581156f, 1.0753762f, 1.0929554f, 1.1108692f,
    1.1291344f, 1.1477692f, 1.1667926f, 1.1862249f, 1.2060875f, 1.2264032f, 1.2471969f,
    1.2684946f, 1.2903243f, 0.9918377f, 0.97570497f, 0.9598179f, 0.9441647f, 0.928734f,
    0.9135149f, 0.8984971f, 0.88367045f, 0.8690253f, 0.8545524f, 0.8402426f, 0.8260873f,
    0.8120779f, 0.79820603f, 0.78446376f, 0.7708431f, 1.999937f, 2.000189f, 2.0009456f,
    2.0022085f, 2.0039804f, 2.0062656f, 2.0090692f, 2.0123978f, 2.0162592f, 2.0206623f,
    2.0256178f, 2.0311375f, 2.037235f, 2.0439255f, 2.0512257f, 2.0591545f, 1.0079683f, 1.0240967f,
    1.0404917f, 1.057166f, 1.0741335f, 1.0914085f, 1.1090062f, 1.1269428f, 1.1452352f, 1.1639014f,
    1.1829607f, 1.2024335f, 1.2223411f, 1.2427068f, 1.263555f, 1.2849125f, 0.99196875f,
    0.9760922f, 0.96045387f, 0.9450424f, 0.9298469f, 0.9148571f, 0.900063f, 0.885455f,
    0.87102395f, 0.8567608f, 0.842657f, 0.8287041f, 0.814894f, 0.8012188f, 0.7876707f, 0.7742421f,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1,
    1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 5.91608f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 5.91608f, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 4.3639565f, 6.0827627f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    4.239272f, 6.0827627f, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0.124684475f, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 3.707136f, 4.476792f, 6.244998f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 3.5067503f, 4.355798f, 6.244998f, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0.20038573f,
    0.12099438f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 3.3322916f, 3.7954454f, 4.5868807f,
    6.4031243f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 3.0759614f, 3.6008072f, 4.4692683f,
    6.4031243f, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0.2563301f, 0.19463822f, 0.117612325f, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 3.0870261f, 3.405684f, 3.8818007f, 4.6944118f, 6.5574384f, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2.7858527f, 3.1564877f, 3.6924446f, 4.5799136f, 6.5574384f, 1,
    1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0.30117327f, 0.2491964f, 0.18935613f, 0.11449784f, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 2.9132185f, 3.1500916f, 3.477607f, 3.9663217f, 4.7995534f, 6.708204f,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2.5744722f, 2.8570597f, 3.2349832f, 3.7818415f, 4.687936f,
    6.708204f, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0.33874634f, 0.29303178f, 0.24262375f, 0.18448007f,
    0.11161752f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2.7833886f, 2.9685855f, 3.2120202f, 3.5481384f,
    4.049117f, 4.9024577f, 6.8556547f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2.4122703f, 2.6387427f,
    2.9265072f, 3.3115957f, 3.8691564f, 4.7935143f, 6.8556547f, 1, 1, 1, 1, 1, 1, 1, 1, 1,
    0.3711185f, 0.32984284f, 0.2855129f, 0.23654255f, 0.17996076f, 0.1089435f, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 2.6826992f, 2.8327355f, 3.0230596f, 3.2728624f, 3.6173508f, 4.1302857f,
    5.0032597f, 7, 0, 0, 0, 0, 0, 0, 0, 0, 2.2831483f, 2.4711096f, 2.7014575f, 2.9943209f,
    3.386456f, 3.9545288f, 4.8968077f, 7, 1, 1, 1, 1, 1, 1, 1, 1, 0.39955094f, 0.3616258f,
    0.32160208f, 0.27854148f, 0.23089473f, 0.17575684f, 0.10645234f, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    2.6023755f, 2.727178f, 2.8813756f, 3.0766718f, 3.3326666f, 3.6853116f, 4.2099175f, 5.1020827f,
    7.1414285f, 0, 0, 0, 0, 0, 0, 0, 2.1774979f, 2.3375812f, 2.5285542f, 2.7627256f, 3.0606122f,
    3.4596803f, 4.038084f, 4.9979587f, 7.1414285f, 1, 1, 1, 1, 1, 1, 1, 0.4248776f, 0.38959685f,
    0.3528215f, 0.3139461f, 0.2720544f, 0.22563133f, 0.17183337f, 0.10412414f, 0, 0, 0, 0, 0, 0,
    0, 0, 2.536871f, 2.6428196f, 2.7710967f, 2.9293263f, 3.1294534f, 3.3914788f, 3.7520828f,
    4.2880945f, 5.1990385f, 7.28011f, 0, 0, 0, 0, 0, 0, 2.0891879f, 2.2282598f, 2.3907502f,
    2.5846996f, 2.8226442f, 3.1254804f, 3.531372f, 4.119934f, 5.0970964f, 7.28011f, 1, 1, 1, 1, 1,
    1, 0.44768313f, 0.41455996f, 0.38034663f, 0.3446266f, 0.30680916f, 0.26599833f, 0.22071075f,
    0.16816057f, 0.10194193f, 0, 0, 0, 0, 0, 0, 0, 2.482497f, 2.5739076f, 2.6828215f, 2.814462f,
    2.976606f, 3.1814349f, 3.4493418f, 3.8177218f, 4.3648925f, 5.2942276f, 7.4161983f, 0, 0, 0, 0,
    0, 2.0141013f, 2.136829f, 2.2778673f, 2.4427404f, 2.6396315f, 2.8812995f, 3.1890142f,
    3.6016245f, 4.2001796f, 5.1943364f, 7.4161983f, 1, 1, 1, 1, 1, 0.46839562f, 0.43707862f,
    0.40495417f, 0.3717214f, 0.33697423f, 0.30013537f, 0.2603277f, 0.21609746f, 0.16471294f,
    0.09989109f, 0, 0, 0, 0, 0, 0, 2.4366987f, 2.5166116f, 2.6105971f, 2.722379f, 2.8572824f,
    3.0232337f, 3.232646f, 3.5062969f, 3.8822823f, 4.4403806f, 5.3877435f, 7.5498343f, 0, 0, 0, 0,
    1.9493588f, 2.0590458f, 2.1834085f, 2.3263967f, 2.4936283f, 2.6934264f, 2.938769f, 3.2512934f,
    3.6705215f, 4.2789125f, 5.2897844f, 7.5498343f, 1, 1, 1, 1, 0.4873397f, 0.45756572f,
    0.42718863f, 0.3959824f, 0.3636541f, 0.3298073f, 0.29387692f, 0.25500342f, 0.21176085f,
    0.16146839f, 0.09795897f, 0, 0, 0, 0, 0, 2.3976483f, 2.468277f, 2.550458f, 2.6469321f,
    2.7614942f, 2.899569f, 3.0692291f, 3.2831154f, 3.562382f, 3.9458134f, 4.5146227f, 5.47967f,
    7.6811457f, 0, 0, 0, 1.8928803f, 1.9919429f, 2.1030092f, 2.2289956f, 2.3739161f, 2.5434816f,
    2.7461524f, 2.9951227f, 3.3123903f, 3.7381392f, 4.356215f, 5.383536f, 7.6811457f, 1, 1, 1,
    0.5047681f, 0.47633415f, 0.44744876f, 0.41793665f, 0.38757813f, 0.35608742f, 0.32307675f,
    0.28799257f, 0.24999173f, 0.2076744f, 0.1584078f, 0.096134566f, 0, 0, 0, 0, 2.3640027f,
    2.4270031f, 2.4996529f, 2.584024f, 2.6829088f, 2.8001711f, 2.9413335f, 3.114612f, 3.3328702f,
    3.6176336f, 4.008362f, 4.5876775f, 5.5700865f, 7.81025f, 0, 0, 1.8431208f, 1.9333752f,
    2.0336158f, 2.1460538f, 2.2736516f, 2.420487f, 2.5923617f, 2.7978718f, 3.0504236f, 3.3723702f,
    3.8045468f, 4.432163f, 5.475678f, 7.81025f, 1, 1, 0.52088195f, 0.49362773f, 0.46603695f,
    0.43797016f, 0.4092573f, 0.37968424f, 0.34897175f, 0.3167402f, 0.28244665f, 0.2452633f,
    0.20381501f, 0.1555145f, 0.094408244f, 0, 0, 0, 2.3347514f, 2.3913908f, 2.45621f, 2.53081f,
    2.6173015f, 2.7185261f, 2.8384156f, 2.9825883f, 3.1594017f, 3.3819373f, 3.6720853f, 4.06997f,
    4.6595993f, 5.6590633f, 7.937254f, 0, 1.7989068f, 1.8817501f, 1.973021f, 2.0744345f,
    2.1882358f, 2.3174322f, 2.4661646f, 2.640324f, 2.8486407f, 3.1047294f, 3.4312928f, 3.8698075f,
    4.5068254f, 5.566292f, 7.937254f, 1, 0.53584456f, 0.5096407f, 0.48318884f, 0.4563756f,
    0.42906582f, 0.40109402f, 0.37225124f, 0.34226424f, 0.3107608f, 0.27720797f, 0.24079248f,
    0.20016246f, 0.15277374f, 0.09277153f, 0, 0, 2.3091192f, 2.3603873f, 2.4186773f, 2.4852507f,
    2.5617378f, 2.6502855f, 2.7537854f, 2.876235f, 3.0233467f, 3.2036164f, 3.4303412f, 3.7257693f,
    4.1306777f, 4.7304387f, 5.746668f, 8.062258f, 1.7593288f, 1.8358568f, 1.9195852f, 2.0118694f,
    2.1144502f, 2.2296054f, 2.3603873f, 2.5109987f, 2.6874192f, 2.89851f, 3.158092f, 3.4892125f,
    3.933979f, 4.580266f, 5.6554513f, 8.062258f, 0.54979026f, 0.52453053f, 0.49909213f,
    0.47338107f, 0.44728753f, 0.42068025f, 0.3933979f, 0.3652362f, 0.3359274f, 0.3051063f,
    0.2722493f, 0.23655677f, 0.19669895f, 0.15017265f, 0.09121695f, 0, 2.286502f, 2.3331845f,
    2.385961f, 2.445842f, 2.514111f, 2.5924273f, 2.6829736f, 2.788689f, 2.9136367f, 3.0636213f,
    3.2472749f, 3.478106f, 3.7787151f, 4.190523f, 4.8002424f, 5.832961f, 1.7236707f, 1.7947574f,
    1.8720618f, 1.9566735f, 2.0499675f, 2.1537087f, 2.2702084f, 2.4025626f, 2.5550354f, 2.733693f,
    2.9475265f, 3.2105596f, 3.5461788f, 3.9971144f, 4.6525426f, 5.7432237f, 0.5628313f,
    0.5384272f, 0.5138993f, 0.4891684f, 0.4641436f, 0.43871847f, 0.41276518f, 0.38612616f,
    0.35860145f, 0.32992846f, 0.29974845f, 0.26754662f, 0.23253632f, 0.19340876f, 0.14769977f,
    0.08973787f, 2.2664216f, 2.3091514f, 2.357221f, 2.4114506f, 2.4728687f, 2.5427809f,
    2.6228733f, 2.7153647f, 2.823241f, 2.9506295f, 3.1034255f, 3.2903948f, 3.5252545f, 3.8309517f,
    4.2495403f, 4.869055f, 1.6913594f, 1.7577122f, 1.8294849f, 1.9075655f, 1.9930583f, 2.0873573f,
    2.1922524f, 2.3100865f, 2.4439998f, 2.5983155f, 2.779187f, 2.9957325f, 3.2621758f, 3.6022382f,
    4.0592623f, 4.7237096f, 0.5750622f, 0.5514391f, 0.527736f, 0.5038852f, 0.47981033f,
    0.4554234f, 0.430621f, 0.40527833f, 0.37924132f, 0.35231397f, 0.32423848f, 0.2946622f,
    0.2630787f, 0.22871353f, 0.19027793f, 0.14534491f, 2.2484946f, 2.2877882f, 2.3318002f,
    2.3812053f, 2.4368384f, 2.499745f, 2.5712519f, 2.6530724f, 2.74746f, 2.8574464f, 2.9872224f,
    3.142772f, 3.3329933f, 3.571808f, 3.8825052f, 4.3077626f, 1.6619307f, 1.7241302f, 1.7910929f,
    1.863552f, 1.9424075f, 2.0287786f, 2.1240776f, 2.2301188f, 2.3492773f, 2.484736f, 2.6408777f,
    2.82394f, 3.0431676f, 3.3129814f, 3.6574323f, 4.1204686f, 0.58656377f, 0.56365794f,
    0.5407073f, 0.51765335f, 0.494431f, 0.47096643f, 0.44717422f, 0.42295358f, 0.3981826f,
    0.3727104f, 0.34634462f, 0.31883195f, 0.2898255f, 0.25882667f, 0.22507276f, 0.18729402f,
    2.23241f, 2.2686937f, 2.3091784f, 2.3544247f, 2.4051192f, 2.4621105f, 2.526461f, 2.5995185f,
    2.6830227f, 2.779261f, 2.8913107f, 3.0234241f, 3.1816735f, 3.3750865f, 3.6177871f, 3.9334009f,
    1.6350044f, 1.6935319f, 1.7562765f, 1.82385f, 1.8969954f, 1.9766239f, 2.0638695f, 2.1601634f,
    2.2673433f, 2.387816f, 2.5248065f, 2.6827567f, 2.8679874f, 3.0898678f, 3.3630135f, 3.7118008f,
    0.59740543f, 0.5751618f, 0.55290186f, 0.53057456f, 0.50812376f, 0.4854866f, 0.46259144f,
    0.43935525f, 0.41567957f, 0.39144522f, 0.36650416f, 0.34066752f, 0.31368613f, 0.28521857f,
    0.25477374f, 0.22160004f, 2.217913f, 2.2515426f, 2.2889373f, 2.330568f, 2.3770053f,
    2.4289472f, 2.4872556f, 2.5530095f, 2.627577f, 2.712724f, 2.810771f, 2.9248397f, 3.0592442f,
    3.2201426f, 3.4166906f, 3.6632113f, 1.6102655f, 1.6655247f, 1.7245419f, 1.7878331f, 1.856018f,
    1.9298484f, 2.0102477f, 2.0983639f, 2.1956465f, 2.3039572f, 2.4257338f, 2.564243f, 2.7239845f,
    2.9113617f, 3.1358666f, 3.4123065f, 0.60764736f, 0.58601797f, 0.56439555f, 0.54273504f,
    0.5209875f, 0.49909875f, 0.47700793f, 0.4546455f, 0.43193048f, 0.40876663f, 0.3850371f,
    0.3605967f, 0.33525962f, 0.3087808f, 0.2808239f, 0.2509049f, 2.2047927f, 2.236068f, 2.270738f,
    2.3092012f, 2.3519373f, 2.3995264f, 2.452677f, 2.512265f, 2.5793848f, 2.655425f, 2.7421763f,
    2.8419929f, 2.95804f, 3.0946913f, 3.258191f, 3.4578204f, 1.5874507f, 1.6397831f, 1.6954842f,
    1.7549928f, 1.8188316f, 1.8876274f, 1.9621416f, 2.043309f, 2.1322913f, 2.230557f, 2.3399906f,
    2.4630604f, 2.603075f, 2.764591f, 2.9540932f, 3.1811948f, 0.617342f, 0.5962848f, 0.57525355f,
    0.5542083f, 0.5331058f, 0.51189893f, 0.4905354f, 0.46895614f, 0.44709337f, 0.42486802f,
    0.40218586f, 0.3789324f, 0.3549648f, 0.33010042f, 0.30409783f, 0.27662563f, 2.1928737f,
    2.2220485f, 2.2543006f, 2.2899706f, 2.3294644f, 2.3732693f, 2.4219742f, 2.476299f, 2.5371315f,
    2.605583f, 2.6830611f, 2.7713816f, 2.8729308f, 2.9909177f, 3.129775f, 3.2958307f, 1.5663384f,
    1.6160353f, 1.668768f, 1.724913f, 1.7849144f, 1.8493007f, 1.9187069f, 1.993903f, 2.075835f,
    2.1656792f, 2.2649217f, 2.37547f, 2.4998229f, 2.6413298f, 2.8046036f, 2.9962096f, 0.62653536f,
    0.60601324f, 0.5855326f, 0.5650577f, 0.5445501f, 0.5239686f, 0.5032674f, 0.4823959f,
    0.46129668f, 0.43990362f, 0.4181394f, 0.39591163f, 0.37310788f, 0.34958777f, 0.3251714f,
    0.299621f, 2.1820085f, 2.2093f, 2.2393951f, 2.2725863f, 2.3092206f, 2.3497105f, 2.3945503f,
    2.4443383f, 2.4998047f, 2.5618503f, 2.631601f, 2.7104847f, 2.8003414f, 2.9035892f, 3.0234795f,
    3.1645038f, 1.5467402f, 1.594052f, 1.6441128f, 1.6972481f, 1.7538384f, 1.8143333f, 1.8792673f,
    1.9492825f, 2.0251582f, 2.1078515f, 2.1985528f, 2.2987657f, 2.4104204f, 2.5360463f,
    2.6790326f, 2.8440478f, 0.6352683f, 0.61524814f, 0.59528226f, 0.5753383f, 0.5553822f,
    0.535377f, 0.515283f, 0.49505585f, 0.47464645f, 0.45399877f, 0.43304828f, 0.4117192f,
    0.38992095f, 0.36754292f, 0.34444705f, 0.3204561f, 2.1720715f, 2.1976674f, 2.2258282f,
    2.2568078f, 2.2909045f, 2.3284705f, 2.3699243f, 2.4157686f, 2.4666097f, 2.5231879f, 2.586417f,
    2.6574376f, 2.7376966f, 2.8290584f, 2.9339726f, 3.0557323f, 1.5284948f, 1.5736383f,
    1.6212822f, 1.6717095f, 1.725249f, 1.7822859f, 1.8432745f, 1.9087554f, 1.9793781f, 2.0559309f,
    2.139382f, 2.2309353f, 2.332112f, 2.4448652f, 2.5717537f, 2.7162066f, 0.64357674f, 0.624029f,
    0.6045459f, 0.5850983f, 0.5656554f, 0.5461844f, 0.52664983f, 0.50701314f, 0.48723152f,
    0.46725702f, 0.447035f, 0.42650235f, 0.4055847f, 0.38419312f, 0.36221883f, 0.33952582f,
    2.1629567f, 2.1870186f, 2.2134376f, 2.242434f, 2.2742662f, 2.3092375f, 2.347705f, 2.3900943f,
    2.4369144f, 2.4887807f, 2.5464437f, 2.6108284f, 2.6830914f, 2.7646978f, 2.8575356f,
    2.9640856f, 1.5114638f, 1.5546278f, 1.6000752f, 1.6480539f, 1.6988496f, 1.7527946f,
    1.8102785f, 1.8717606f, 1.9377874f, 2.0090158f, 2.086243f, 2.1704478f, 2.2628481f, 2.3649824f,
    2.478826f, 2.6069667f, 0.651493f, 0.632391f, 0.6133622f, 0.5943801f, 0.5754168f, 0.55644274f,
    0.5374265f, 0.5183337f, 0.49912706f, 0.47976497f, 0.46020064f, 0.4403807f, 0.42024323f,
    0.39971533f, 0.37870952f, 0.35711876f, 2.154573f, 2.1772425f, 2.2020855f, 2.2292955f,
    2.259097f, 2.2917528f, 2.32757f, 2.3669121f, 2.4102101f, 2.4579802f, 2.5108461f, 2.5695677f,
    2.635083f, 2.7085624f, 2.7914894f, 2.885776f, 1.4955271f, 1.536877f, 1.5803201f, 1.6260743f,
    1.6743896f, 1.7255551f, 1.7799065f, 1.8378376f, 1.8998126f, 1.9663842f, 2.038216f, 2.1161146f,
    2.2010694f, 2.2943115f, 2.3973968f, 2.5123227f, 0.6590458f, 0.6403654f, 0.6217653f,
    0.6032211f, 0.5847075f, 0.56619775f, 0.54766357f, 0.5290745f, 0.51039743f, 0.49159604f,
    0.47262985f, 0.45345312f, 0.43401366f, 0.4142507f, 0.39409262f, 0.37345335f, 2.1468415f,
    2.1682425f, 2.1916547f, 2.2172484f, 2.2452207f, 2.2757998f, 2.309252f, 2.3458896f, 2.386081f,
    2.430263f, 2.478959f, 2.5328007f, 2.5925574f, 2.659179f, 2.7338505f, 2.8180735f, 1.4805803f,
    1.5202619f, 1.5618688f, 1.6055937f, 1.6516565f, 1.7003101f, 1.7518463f, 1.8066046f,
    1.8649828f, 1.92745f, 1.9945648f, 2.0669982f, 2.1455648f, 2.231265f, 2.325344f, 2.4293737f,
    0.66626114f, 0.6479805f, 0.6297858f, 0.61165476f, 0.5935641f, 0.5754896f, 0.55740565f,
    0.539285f, 0.52109814f, 0.50281304f, 0.4843943f, 0.4658024f, 0.44699267f, 0.42791387f,
    0.4085064f, 0.3886998f, 2.1396945f, 2.1599357f, 2.1820443f, 2.2061703f, 2.2324874f,
    2.2611954f, 2.2925265f, 2.326751f, 2.3641853f, 2.4052026f, 2.450246f, 2.4998457f, 2.5546405f,
    2.6154103f, 2.683116f, 2.7589567f, 1.4665322f, 1.5046743f, 1.5445931f, 1.5864595f, 1.6304684f,
    1.6768416f, 1.7258346f, 1.7777423f, 1.8329077f, 1.8917325f, 1.9546908f, 2.022347f, 2.0953794f,
    2.1746109f, 2.2610528f, 2.355963f, 0.67316234f, 0.6552614f, 0.6374511f, 0.61971074f,
    0.6020191f, 0.58435386f, 0.56669194f, 0.54900867f, 0.5312776f, 0.51347023f, 0.4955554f,
    0.47749862f, 0.45926124f, 0.4407995f, 0.42206317f, 0.40299368f, 2.1330729f, 2.152251f,
    2.1731672f, 2.195956f, 2.2207696f, 2.247785f, 2.2772048f, 2.3092647f, 2.3442385f, 2.3824475f,
    2.4242697f, 2.4701536f, 2.5206356f, 2.576363f, 2.6381252f, 2.7068934f, 1.4533024f, 1.4900198f,
    1.5283815f, 1.5685399f, 1.6106682f, 1.6549625f, 1.7016475f, 1.7509809f, 1.8032604f,
    1.8588327f, 1.9181035f, 1.9815516f, 2.0497477f, 2.1233761f, 2.2032692f, 2.2904484f,
    0.67977047f, 0.662231f, 0.64478594f, 0.62741596f, 0.6101016f, 0.59282243f, 0.57555723f,
    0.55828375f, 0.54097813f, 0.5236148f, 0.5061662f, 0.4886018f, 0.47088796f, 0.45298693f,
    0.4348558f, 0.41644517f, 2.126925f, 2.1451254f, 2.1649487f, 2.1865141f, 2.2099578f,
    2.2354355f, 2.263126f, 2.2932353f, 2.3260026f, 2.3617053f, 2.4006686f, 2.4432755f, 2.48998f,
    2.541325f, 2.597966f, 2.6607006f, 1.4408201f, 1.4762152f, 1.5131361f, 1.5517197f, 1.5921202f,
    1.634512f, 1.6790935f, 1.7260911f, 1.7757654f, 1.828417f, 1.8843957f, 1.9441116f, 2.0080483f,
    2.0767817f, 2.151004f, 2.2315552f, 0.68610483f, 0.66891f, 0.6518125f, 0.6347944f, 0.61783767f,
    0.60092354f, 0.58403254f, 0.5671442f, 0.5502372f, 0.5332883f, 0.5162728f, 0.49916378f,
    0.4819316f, 0.4645433f, 0.44696188f, 0.42914525f, 2.1212053f, 2.1385043f, 2.1573224f,
    2.1777663f, 2.1999571f, 2.224033f, 2.2501526f, 2.2784972f, 2.3092759f, 2.3427305f, 2.3791425f,
    2.4188414f, 2.4622145f, 2.5097213f, 2.5619113f, 2.6194472f, 1.4290224f, 1.4631872f,
    1.4987714f, 1.5358983f, 1.5747061f, 1.6153504f, 1.6580071f, 1.7028768f, 1.750188f, 1.8002034f,
    1.8532269f, 1.9096116f, 1.9697715f, 2.0341952f, 2.1034641f, 2.1782773f, 0.6921828f,
    0.67531717f, 0.6585511f, 0.64186794f, 0.62525094f, 0.60868275f, 0.59214544f, 0.57562035f,
    0.5590878f, 0.5425271f, 0.52591574f, 0.5092298f, 0.49244288f, 0.47552615f, 0.4584473f,
    0.44117007f, 2.115874f, 2.1323402f, 2.1502314f, 2.1696434f, 2.190685f, 2.213479f, 2.2381666f,
    2.2649078f, 2.2938871f, 2.325316f, 2.3594398f, 2.3965435f, 2.4369602f, 2.4810822f, 2.5293744f,
    2.5823922f, 1.4178537f, 1.4508706f, 1.4852115f, 1.5209872f, 1.5583223f, 1.5973561f,
    1.6382457f, 1.6811687f, 1.7263274f, 1.7739525f, 1.8243092f, 1.8777043f, 1.9344943f, 1.995097f,
    2.060006f, 2.1298082f, 0.69802034f, 0.68146956f, 0.66502005f, 0.6486563f, 0.63236266f,
    0.6161231f, 0.5999209f, 0.58373916f, 0.56755966f, 0.5513636f, 0.5351307f, 0.5188393f,
    0.502466f, 0.4859852f, 0.46936846f, 0.4525842f, 2.110896f, 2.1265907f, 2.143625f, 2.1620855f,
    2.1820698f, 2.203688f, 2.2270656f, 2.2523453f, 2.2796898f, 2.3092856f, 2.3413475f, 2.3761234f,
    2.413902f, 2.4550204f, 2.499875f, 2.5489364f, 1.4072641f, 1.4392079f, 1.472389f, 1.5069082f,
    1.5428777f, 1.5804228f, 1.6196841f, 1.6608202f, 1.7040105f, 1.7494588f, 1.7973981f, 1.848096f,
    1.9018623f, 1.9590566f, 2.020101f, 2.0854933f, 0.70363206f, 0.6873829f, 0.67123616f,
    0.6551775f, 0.63919216f, 0.6232653f, 0.6073815f, 0.591525f, 0.57567924f, 0.5598268f,
    0.5439494f, 0.5280274f, 0.51203984f, 0.4959637f, 0.479774f, 0.46344295f, 2.10624f, 2.1212184f,
    2.137459f, 2.1550398f, 2.1740487f, 2.194585f, 2.2167609f, 2.2407036f, 2.2665577f, 2.2944882f,
    2.3246841f, 2.3573625f, 2.3927748f, 2.4312127f, 2.4730172f, 2.5185895f, 1.3972088f,
    1.4281471f, 1.4602443f, 1.4935919f, 1.5282917f, 1.5644567f, 1.6022134f, 1.6417037f,
    1.6830875f, 1.7265456f, 1.7722839f, 1.8205374f, 1.8715764f, 1.9257131f, 1.9833108f,
    2.0447953f, 0.70903134f, 0.69307137f, 0.67721474f, 0.6614478f, 0.6457571f, 0.6301284f,
    0.6145476f, 0.599f, 0.5834703f, 0.5679426f, 0.5524002f, 0.5368251f, 0.5211985f, 0.50549966f,
    0.48970637f, 0.47379404f, 2.1018782f, 2.1161902f, 2.1316936f, 2.1484592f, 2.1665666f,
    2.1861048f, 2.207175f, 2.229891f, 2.2543817f, 2.2807937f, 2.3092942f, 2.3400745f, 2.3733547f,
    2.4093885f, 2.448471f, 2.4909475f, 1.3876477f, 1.417642f, 1.4487238f, 1.4809767f, 1.5144931f,
    1.5493753f, 1.5857373f, 1.623707f, 1.6634272f, 1.7050594f, 1.748786f, 1.7948146f, 1.8433822f,
    1.8947618f, 1.9492683f, 2.0072684f, 0.7142305f, 0.6985482f, 0.6829698f, 0.6674825f,
    0.65207344f, 0.63672954f, 0.6214376f, 0.60618395f, 0.5909544f, 0.5757344f, 0.5605083f,
    0.54526013f, 0.52997243f, 0.5146267f, 0.49920285f, 0.48367912f, 2.0977857f, 2.1114767f,
    2.1262941f, 2.1423028f, 2.1595743f, 2.1781898f, 2.1982398f, 2.219827f, 2.2430665f, 2.2680898f,
    2.2950444f, 2.3241003f, 2.3554506f, 2.3893182f, 2.4259596f, 2.4656734f, 1.3785449f,
    1.4076511f, 1.4377799f, 1.4690075f, 1.5014182f, 1.5351051f, 1.5701712f, 1.6067319f,
    1.6449156f, 1.6848667f, 1.7267478f, 1.7707431f, 1.817062f, 1.8659438f, 1.9176633f, 1.9725387f,
    0.71924084f, 0.70382553f, 0.6885143f, 0.67329514f, 0.658156f, 0.6430846f, 0.6280685f,
    0.61309505f, 0.5981511f, 0.58322304f, 0.56829673f, 0.55335724f, 0.5383887f, 0.52337444f,
    0.5082963f, 0.49313468f, 2.0939405f, 2.1070514f, 2.1212294f, 2.1365335f, 2.1530287f,
    2.1707885f, 2.1898954f, 2.210441f, 2.2325294f, 2.256278f, 2.2818186f, 2.309302f, 2.3388994f,
    2.3708065f, 2.4052482f, 2.4424841f, 1.3698676f, 1.3981369f, 1.4273694f, 1.4576349f,
    1.4890105f, 1.5215808f, 1.5554397f, 1.5906912f, 1.6274514f, 1.66585f, 1.7060326f, 1.7481632f,
    1.7924275f, 1.8390367f, 1.8882321f, 1.9402912f, 0.7240729f, 0.70891446f, 0.6938601f,
    0.67889845f, 0.6640182f, 0.64920783f, 0.6344556f, 0.6197498f, 0.6050781f, 0.5904279f,
    0.575786f, 0.5611388f, 0.54647183f, 0.53176963f, 0.51701593f, 0.50219303f, 2.0903223f,
    2.1028907f, 2.1164715f, 2.1311185f, 2.1468914f, 2.1638567f, 2.1820886f, 2.2016711f,
    2.2226975f, 2.2452729f, 2.269516f, 2.2955608f, 2.3235595f, 2.3536854f, 2.3861365f, 2.42114f,
    1.3615861f, 1.3890654f, 1.4174534f, 1.4468145f, 1.4772189f, 1.5087441f, 1.5414755f,
    1.5755078f, 1.6109458f, 1.6479067f, 1.6865209f, 1.7269356f, 1.769316f, 1.8138493f, 1.8607486f,
    1.9102572f, 0.7287362f, 0.7138253f, 0.6990181f, 0.6843042f, 0.66967255f, 0.65511256f,
    0.6406132f, 0.62616336f, 0.61175156f, 0.59736615f, 0.58299494f, 0.56862515f, 0.55424356f,
    0.5398361f, 0.5253878f, 0.51088274f, 2.0869136f, 2.0989735f, 2.1119957f, 2.1260293f,
    2.141128f, 2.1573536f, 2.174773f, 2.1934624f, 2.2135062f, 2.2349992f, 2.258048f, 2.2827728f,
    2.309309f, 2.3378108f, 2.3684533f, 2.4014363f, 1.3536737f, 1.380406f, 1.4079973f, 1.4365062f,
    1.4659977f, 1.4965426f, 1.528219f, 1.5611129f, 1.5953197f, 1.6309453f, 1.6681075f, 1.7069381f,
    1.7475852f, 1.7902155f, 1.8350178f, 1.8822069f, 0.7332399f, 0.71856755f, 0.7039986f,
    0.689523f, 0.6751305f, 0.660811f, 0.6465542f, 0.63234955f, 0.6181864f, 0.6040538f, 0.5899404f,
    0.5758346f, 0.5617238f, 0.5475953f, 0.5334354f, 0.5192295f, 2.083698f, 2.0952811f, 2.1077797f,
    2.1212387f, 2.135708f, 2.1512437f, 2.1679065f, 2.1857662f, 2.2048988f, 2.2253904f, 2.2473373f,
    2.270847f, 2.2960413f, 2.3230572f, 2.3520505f, 2.383198f, 1.3461058f, 1.372131f, 1.3989688f,
    1.4266739f, 1.4553056f, 1.4849292f, 1.5156162f, 1.547445f, 1.5805026f, 1.6148851f, 1.650699f,
    1.6880633f, 1.7271106f, 1.7679905f, 1.8108706f, 1.8559418f, 0.7375922f, 0.7231501f,
    0.70881087f, 0.6945649f, 0.68040264f, 0.66631436f, 0.65229046f, 0.6383211f, 0.62439615f,
    0.61050534f, 0.5966382f, 0.58278376f, 0.56893057f, 0.55506676f, 0.5411798f, 0.5272562f,
    2.080661f, 2.091796f, 2.103803f, 2.1167238f, 2.130604f, 2.1454947f, 2.161452f, 2.1785388f,
    2.196825f, 2.2163882f, 2.2373154f, 2.2597039f, 2.2836628f, 2.3093152f, 2.3367999f, 2.3662736f,
    1.3388602f, 1.3642147f, 1.3903394f, 1.4172846f, 1.4451053f, 1.4738616f, 1.5036188f,
    1.5344491f, 1.5664318f, 1.5996541f, 1.634213f, 1.670216f, 1.7077827f, 1.7470472f, 1.7881598f,
    1.83129f, 0.7418009f, 0.72758114f, 0.7134636f, 0.69943917f, 0.6854987f, 0.6716331f,
    0.6578332f, 0.64408976f, 0.63039327f, 0.6167341f, 0.60310245f, 0.58948797f, 0.5758802f,
    0.5622681f, 0.54863995f, 0.5349836f, 2.0777895f, 2.0885024f, 2.1000476f, 2.112463f, 2.125791f,
    2.140078f, 2.155376f, 2.171742f, 2.1892397f, 2.20794f, 2.227922f, 2.249273f, 2.272092f,
    2.2964895f, 2.3225892f, 2.3505318f, 1.3319163f, 1.356634f, 1.3820826f, 1.4083086f, 1.4353632f,
    1.4633013f, 1.4921833f, 1.5220757f, 1.5530505f, 1.5851878f, 1.6185758f, 1.6533118f,
    1.6895044f, 1.7272741f, 1.7667559f, 1.8081014f, 0.74587315f, 0.7318683f, 0.71796495f,
    0.7041543f, 0.69042784f, 0.6767768f, 0.66319263f, 0.6496664f, 0.63618934f, 0.62275237f,
    0.6093462f, 0.5959613f, 0.5825877f, 0.5692153f, 0.55583334f, 0.5424304f, 2.0750713f,
    2.0853865f, 2.0964968f, 2.1084373f, 2.1212466f, 2.1349678f, 2.1496484f, 2.165341f, 2.1821032f,
    2.2f, 2.219103f, 2.2394922f, 2.2612565f, 2.2844956f, 2.309321f, 2.335858f, 1.3252556f,
    1.3493677f, 1.3741745f, 1.3997189f, 1.4260482f, 1.4532135f, 1.4812703f, 1.5102797f,
    1.5403081f, 1.5714285f, 1.6037216f, 1.6372758f, 1.6721897f, 1.7085723f, 1.7465452f,
    1.7862445f, 0.7498157f, 0.7360188f, 0.72232246f, 0.7087184f, 0.6951985f, 0.68175447f,
    0.6683781f, 0.65506107f, 0.64179504f, 0.62857145f, 0.61538154f, 0.6022164f, 0.58906686f,
    0.57592326f, 0.5627757f, 0.5496137f, 2.0724957f, 2.0824356f, 2.093136f, 2.1046293f, 2.116951f,
    2.1301408f, 2.1442425f, 2.1593041f, 2.175379f, 2.192526f, 2.210811f, 2.230306f, 2.2510922f,
    2.2732594f, 2.2969086f, 2.3221524f, 1.3188609f, 1.3423966f, 1.366593f, 1.3914905f, 1.4171325f,
    1.4435666f, 1.470844f, 1.4990209f, 1.5281588f, 1.5583243f, 1.5895913f, 1.6220407f, 1.655762f,
    1.6908541f, 1.7274271f, 1.7656034f, 0.75363475f, 0.7400391f, 0.7265431f, 0.7131388f,
    0.6998185f, 0.68657434f, 0.67339844f, 0.660283f, 0.6472202f, 0.63420177f, 0.6212196f,
    0.6082653f, 0.5953301f, 0.5824053f, 0.56948143f, 0.5565489f, 2.0700524f, 2.079638f,
    2.0899515f, 2.1010232f, 2.1128857f, 2.1255758f, 2.1391337f, 2.1536038f, 2.169035f, 2.185481f,
    2.2030025f, 2.221665f, 2.2415419f, 2.262715f, 2.285276f, 2.309326f, 1.3127161f, 1.3357025f,
    1.3593181f, 1.3836006f, 1.4085904f, 1.4343317f, 1.4608718f, 1.4882628f, 1.516561f, 1.5458281f,
    1.5761318f, 1.6075461f, 1.6401526f, 1.6740413f, 1.7093121f, 1.7460757f, 0.75733626f,
    0.7439356f, 0.7306335f, 0.71742254f, 0.7042952f, 0.6912441f, 0.6782619f, 0.665341f,
    0.6524739f, 0.639653f, 0.62687063f, 0.61411875f, 0.6013893f, 0.5886739f, 0.57596385f,
    0.56325024f, 2.0677326f, 2.076983f, 2.086931f, 2.0976045f, 2.109034f, 2.1212535f, 2.1343f,
    2.1482146f, 2.1630418f, 2.178832f, 2.1956394f, 2.2135246f, 2.232555f, 2.2528045f, 2.274356f,
    2.2973013f, 1.306807f, 1.3292692f, 1.3523313f, 1.3760285f, 1.4003986f, 1.4254824f, 1.451324f,
    1.4779716f, 1.5054772f, 1.5338976f, 1.5632952f, 1.5937377f, 1.6252999f, 1.6580641f,
    1.6921208f, 1.7275705f, 0.76092565f, 0.7477139f, 0.7345997f, 0.7215759f, 0.70863545f,
    0.69577116f, 0.682976f, 0.6702429f, 0.65756476f, 0.64493424f, 0.6323441f, 0.6197869f,
    0.6072549f, 0.5947404f, 0.5822351f, 0.5697307f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 8.185352f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 8.185352f, 1, 1, 1, 1, 1, 1, 1,
    1, 1, 1, 1, 1, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 5.918f, 8.306623f, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 5.829672f, 8.306623f, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1,
    1, 1, 1, 0.08832836f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 4.9369154f, 6.0018377f,
    8.426149f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 4.7938166f, 5.914855f, 8.426149f, 1, 1, 1,
    1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0.143099f, 0.08698316f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 4.36522f, 5.0038633f, 6.0845237f, 8.5440035f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    4.180774f, 4.8629093f, 5.998826f, 8.5440035f, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0.18444592f,
    0.1409539f, 0.08569752f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 3.9836624f, 4.421942f,
    5.0699334f, 6.1661034f, 8.6602545f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 3.7653794f, 4.240218f,
    4.931031f, 6.0816364f, 8.6602545f, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0.21828286f, 0.18172364f,
    0.13890229f, 0.08446717f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 3.7080991f, 4.033312f,
    4.4779553f, 5.1351595f, 6.2466207f, 8.774964f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 3.4608927f,
    3.818202f, 4.298837f, 4.998222f, 6.1633325f, 8.774964f, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1,
    0.24720661f, 0.21510997f, 0.17911822f, 0.13693759f, 0.083288275f, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 3.4984906f, 3.7524683f, 4.082371f, 4.533285f, 5.1995726f, 6.3261156f, 8.888194f, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 3.2258809f, 3.5088015f, 3.8702998f, 4.3566637f, 5.064519f, 6.243958f,
    8.888194f, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0.27260965f, 0.24366677f, 0.21207123f, 0.17662151f,
    0.13505383f, 0.08215734f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 3.333073f, 3.5387151f, 3.7963355f,
    4.1308594f, 4.5879564f, 5.263202f, 6.404626f, 9, 0, 0, 0, 0, 0, 0, 0, 0, 3.0377374f,
    3.269952f, 3.556061f, 3.9217021f, 4.41373f, 5.1299567f, 6.3235545f, 9, 1, 1, 1, 1, 1, 1, 1, 1,
    0.29533556f, 0.26876318f, 0.24027438f, 0.20915744f, 0.17422618f, 0.13324563f, 0.08107121f, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 3.1988869f, 3.3699286f, 3.5785072f, 3.8397162f, 4.1787963f,
    4.6419907f, 5.3260765f, 6.4821873f, 9.110434f, 0, 0, 0, 0, 0, 0, 0, 2.8829474f, 3.0787003f,
    3.3134327f, 3.6026967f, 3.972436f, 4.470065f, 5.194568f, 6.40216f, 9.110434f, 1, 1, 1, 1, 1,
    1, 1, 0.31593943f, 0.2912284f, 0.2650746f, 0.23701952f, 0.20636031f, 0.17192557f, 0.13150805f,
    0.080027f, 0, 0, 0, 0, 0, 0, 0, 0, 3.0876825f, 3.2329323f, 3.4064085f, 3.6178796f, 3.8826263f,
    4.226199f, 4.69541f, 5.388221f, 6.558833f, 9.219544f, 0, 0, 0, 0, 0, 0, 2.7528737f,
    2.9213245f, 3.119121f, 3.3563464f, 3.6487331f, 4.0225267f, 4.5256963f, 5.258384f, 6.479811f,
    9.219544f, 1, 1, 1, 1, 1, 1, 0.33480895f, 0.31160793f, 0.28728744f, 0.26153347f, 0.23389314f,
    0.20367225f, 0.16971362f, 0.12983665f, 0.07902209f, 0, 0, 0, 0, 0, 0, 0, 2.9939332f,
    3.119337f, 3.266649f, 3.4425225f, 3.6568449f, 3.9250796f, 4.2730856f, 4.7482347f, 5.4496603f,
    6.6345954f, 9.327379f, 0, 0, 0, 0, 0, 2.6417058f, 2.7890542f, 2.9591997f, 3.1590207f,
    3.3987145f, 3.6941926f, 4.071999f, 4.58065f, 5.3214326f, 6.5565414f, 9.327379f, 1, 1, 1, 1, 1,
    0.35222745f, 0.33028275f, 0.3074493f, 0.28350186f, 0.25813022f, 0.23088704f, 0.20108637f,
    0.16758475f, 0.1282273f, 0.07805406f, 0, 0, 0, 0, 0, 0, 2.913783f, 3.0235205f, 3.150702f,
    3.3000448f, 3.4782808f, 3.695414f, 3.9670901f, 4.3194714f, 4.8004837f, 5.510418f, 6.7095037f,
    9.433981f, 0, 0, 0, 0, 2.5453737f, 2.6759894f, 2.8247674f, 2.9965923f, 3.198419f, 3.440558f,
    3.7390966f, 4.120875f, 4.6349497f, 5.383742f, 6.6323833f, 9.433981f, 1, 1, 1, 1, 0.36840934f,
    0.3475311f, 0.32593468f, 0.3034524f, 0.2798617f, 0.25485614f, 0.2279937f, 0.19859637f,
    0.16553392f, 0.12667628f, 0.077120736f, 0, 0, 0, 0, 0, 2.8444524f, 2.9415605f, 3.0528524f,
    3.1817842f, 3.3331275f, 3.5136926f, 3.7335987f, 4.0086713f, 4.3653717f, 4.852175f, 5.570516f,
    6.7835865f, 9.539392f, 0, 0, 0, 2.4609306f, 2.5779967f, 2.7098353f, 2.8600307f, 3.0335207f,
    3.237335f, 3.4818954f, 3.783465f, 4.169175f, 4.6886187f, 5.4453363f, 6.7073665f, 9.539392f, 1,
    1, 1, 0.38352168f, 0.36356366f, 0.34301713f, 0.32175344f, 0.29960698f, 0.27635786f,
    0.2517033f, 0.22520624f, 0.19619648f, 0.16355647f, 0.12518014f, 0.07622007f, 0, 0, 0, 0,
    2.7838821f, 2.870628f, 2.969112f, 3.081934f, 3.2125895f, 3.365905f, 3.5487673f, 3.7714095f,
    4.0498347f, 4.410802f, 4.903327f, 5.629976f, 6.85687f, 9.643651f, 0, 0, 2.3861847f,
    2.4920838f, 2.6102083f, 2.74326f, 2.894861f, 3.0700014f, 3.2757852f, 3.5227451f, 3.8273165f,
    4.2169204f, 4.7416787f, 5.5062404f, 6.78152f, 9.643651f, 1, 1, 0.39769745f, 0.3785444f,
    0.35890362f, 0.33867407f, 0.31772864f, 0.29590374f, 0.27298212f, 0.24866436f, 0.2225184f,
    0.19388139f, 0.16164814f, 0.12373573f, 0.07535022f, 0, 0, 0, 2.7305121f, 2.8086283f,
    2.8966038f, 2.996441f, 3.11077f, 3.2431245f, 3.3983848f, 3.5835135f, 3.8088567f, 4.0905933f,
    4.4557753f, 4.9539547f, 5.688817f, 6.92938f, 9.746795f, 0, 2.3194673f, 2.4160244f, 2.5228484f,
    2.6420233f, 2.7762785f, 2.9292738f, 3.1060507f, 3.3137867f, 3.563124f, 3.8706691f, 4.264129f,
    4.79415f, 5.566477f, 6.8548703f, 9.746795f, 1, 0.41104484f, 0.39260396f, 0.37375534f,
    0.35441774f, 0.33449137f, 0.31385076f, 0.29233417f, 0.26972684f, 0.2457327f, 0.21992438f,
    0.19164625f, 0.15980498f, 0.12234015f, 0.07450946f, 0, 0, 2.683136f, 2.753972f, 2.8331966f,
    2.9223816f, 3.0235517f, 3.1393654f, 3.2733953f, 3.430574f, 3.61794f, 3.8459501f, 4.130958f,
    4.500305f, 5.0040746f, 5.747058f, 7.0011396f, 9.848858f, 2.2594829f, 2.3481236f, 2.445496f,
    2.5532389f, 2.6734562f, 2.8089058f, 2.963284f, 3.1416836f, 3.3513548f, 3.603048f, 3.9135392f,
    4.3108187f, 4.846051f, 5.626067f, 6.9274435f, 9.848858f, 0.42365304f, 0.4058485f, 0.3877006f,
    0.36914295f, 0.35009545f, 0.3304595f, 0.31011114f, 0.28889045f, 0.26658505f, 0.24290211f,
    0.21741885f, 0.18948653f, 0.1580234f, 0.12099069f, 0.07369621f, 0, 2.640806f, 2.7054315f,
    2.7772744f, 2.8575892f, 2.947965f, 3.050448f, 3.167725f, 3.3034074f, 3.4624794f, 3.6520543f,
    3.8826993f, 4.17094f, 4.5444045f, 5.053701f, 5.8047166f, 7.0721726f, 2.205209f, 2.2870657f,
    2.3764307f, 2.4746134f, 2.5832684f, 2.704521f, 2.8411555f, 2.9969056f, 3.1769142f, 3.388504f,
    3.6425323f, 3.9559429f, 4.3570065f, 4.897401f, 5.685032f, 6.999264f, 0.43559685f, 0.4183657f,
    0.40084374f, 0.38297588f, 0.3646967f, 0.3459271f, 0.32656962f, 0.30650172f, 0.28556532f,
    0.2635503f, 0.24016696f, 0.2149969f, 0.18739812f, 0.15630002f, 0.11968488f, 0.072909f,
    2.6027658f, 2.6620412f, 2.7275872f, 2.80042f, 2.881808f, 2.9733565f, 3.0771334f, 3.195854f,
    3.3331666f, 3.494108f, 3.6858647f, 3.9191132f, 4.210549f, 4.588085f, 5.1028485f, 5.8618107f,
    2.1558263f, 2.2318122f, 2.3143165f, 2.404401f, 2.5033886f, 2.6129496f, 2.7352297f, 2.8730404f,
    3.0301516f, 3.211756f, 3.425248f, 3.681591f, 3.997895f, 4.402708f, 4.948217f, 5.74339f,
    0.4469396f, 0.4302289f, 0.4132708f, 0.396019f, 0.37841922f, 0.36040685f, 0.34190372f,
    0.32281354f, 0.30301514f, 0.28235218f, 0.2606167f, 0.237522f, 0.212654f, 0.18537718f,
    0.15463178f, 0.118420415f, 2.5684047f, 2.623031f, 2.6831527f, 2.7496035f, 2.8234105f,
    2.905855f, 2.9985592f, 3.103612f, 3.2237568f, 3.3626788f, 3.5254662f, 3.7193785f, 3.9552002f,
    4.249796f, 4.6313586f, 5.1515303f, 2.1106691f, 2.1815307f, 2.2580988f, 2.3412466f, 2.4320467f,
    2.5318341f, 2.6422946f, 2.765595f, 2.904573f, 3.063034f, 3.2462215f, 3.4615998f, 3.720238f,
    4.0394096f, 4.4479384f, 4.9985147f, 0.45773548f, 0.44150025f, 0.4250539f, 0.40835696f,
    0.39136386f, 0.37402093f, 0.35626444f, 0.33801714f, 0.31918383f, 0.29964465f, 0.27924487f,
    0.2577787f, 0.23496239f, 0.21038593f, 0.18342015f, 0.15301575f, 2.5372229f, 2.5877779f,
    2.6431863f, 2.70414f, 2.7714813f, 2.8462472f, 2.9297326f, 3.023576f, 3.1298876f, 3.2514377f,
    3.3919492f, 3.5565605f, 3.7526033f, 3.9909692f, 4.2886896f, 4.6742363f, 2.0691915f,
    2.1355448f, 2.2069323f, 2.2840793f, 2.3678675f, 2.4593787f, 2.5599606f, 2.6713147f,
    2.7956276f, 2.935764f, 3.0955653f, 3.2803228f, 3.497572f, 3.7584856f, 4.0805006f, 4.4927125f,
    0.4680314f, 0.45223302f, 0.43625405f, 0.42006058f, 0.40361378f, 0.38686857f, 0.36977208f,
    0.35226128f, 0.33425984f, 0.31567356f, 0.29638392f, 0.2762377f, 0.2550313f, 0.23248364f,
    0.2081888f, 0.18152374f, 2.508808f, 2.5557733f, 2.6070545f, 2.6632316f, 2.7250035f, 2.793221f,
    2.8689318f, 2.953443f, 3.0484102f, 3.1559637f, 3.2789016f, 3.420983f, 3.5873969f, 3.7855458f,
    4.0264277f, 4.3272395f, 2.0309398f, 2.0932999f, 2.160131f, 2.2320418f, 2.3097649f, 2.3941894f,
    2.4864075f, 2.5877788f, 2.7000203f, 2.8253388f, 2.9666252f, 3.1277559f, 3.3140714f,
    3.5331762f, 3.7963462f, 4.12118f, 0.4778682f, 0.46247324f, 0.44692364f, 0.4311899f,
    0.41523865f, 0.39903158f, 0.38252422f, 0.3656644f, 0.34838971f, 0.33062476f, 0.31227636f,
    0.2932271f, 0.27332547f, 0.25236973f, 0.23008159f, 0.20605901f, 2.4828162f, 2.5265963f,
    2.5742385f, 2.6262336f, 2.6831665f, 2.7457435f, 2.8148239f, 2.8914657f, 2.9769888f,
    3.0730643f, 3.181844f, 3.3061528f, 3.4497855f, 3.617981f, 3.818213f, 4.061584f, 1.9955345f,
    2.0543354f, 2.1171308f, 2.1844373f, 2.256869f, 2.335165f, 2.4202225f, 2.513143f, 2.6152985f,
    2.7284217f, 2.8547387f, 2.9971666f, 3.1596167f, 3.3474777f, 3.5684233f, 3.8338315f,
    0.48728168f, 0.472261f, 0.45710778f, 0.44179627f, 0.4262975f, 0.4105785f, 0.3946015f,
    0.3783226f, 0.36169022f, 0.34464273f, 0.32710546f, 0.30898625f, 0.29016888f, 0.27050325f,
    0.24978963f, 0.22775237f, 2.4589584f, 2.4998968f, 2.5443103f, 2.5926178f, 2.645314f,
    2.7029908f, 2.7663608f, 2.8362913f, 2.9138508f, 3.000372f, 3.097542f, 3.2075326f, 3.3331957f,
    3.4783616f, 3.648319f, 3.8506112f, 1.962655f, 2.0182652f, 2.0774643f, 2.1406934f, 2.2084732f,
    2.2814236f, 2.3602893f, 2.445976f, 2.5395947f, 2.6425295f, 2.7565281f, 2.8838367f, 3.0273979f,
    3.1911576f, 3.3805523f, 3.6033242f, 0.49630356f, 0.4816315f, 0.46684593f, 0.4519242f,
    0.43684086f, 0.42156738f, 0.4060713f, 0.3903153f, 0.37425607f, 0.35784253f, 0.3410138f,
    0.32369596f, 0.30579776f, 0.28720418f, 0.26776654f, 0.24728695f, 2.43699f, 2.4753795f,
    2.5169125f, 2.5619483f, 2.6109095f, 2.6642957f, 2.7227046f, 2.7868555f, 2.857624f, 2.936089f,
    3.0235953f, 3.1218457f, 3.2330327f, 3.360034f, 3.5067163f, 3.678416f, 1.9320282f, 1.9847637f,
    2.0407398f, 2.100336f, 2.163997f, 2.2322478f, 2.305714f, 2.3851466f, 2.4714587f, 2.5657713f,
    2.6694806f, 2.784349f, 2.912642f, 3.0573282f, 3.2223878f, 3.413305f, 0.5049619f, 0.49061576f,
    0.47617263f, 0.4616123f, 0.4469124f, 0.43204796f, 0.4169908f, 0.4017089f, 0.3861654f,
    0.37031752f, 0.35411477f, 0.33749685f, 0.3203906f, 0.30270576f, 0.28432834f, 0.26511106f,
    2.4167023f, 2.452795f, 2.4917445f, 2.5338616f, 2.5795088f, 2.6291127f, 2.6831784f, 2.7423084f,
    2.8072288f, 2.878824f, 2.958182f, 3.046661f, 3.1459787f, 3.2583477f, 3.3866725f, 3.534854f,
    1.9034203f, 1.9535536f, 2.0066261f, 2.062967f, 2.1229587f, 2.1870496f, 2.2557695f, 2.3297486f,
    2.409745f, 2.4966793f, 2.5916817f, 2.69616f, 2.8118925f, 2.9411635f, 3.0869668f, 3.2533169f,
    0.5132819f, 0.49924147f, 0.48511842f, 0.47089463f, 0.45655024f, 0.4420632f, 0.42740893f,
    0.41255966f, 0.39748374f, 0.38214478f, 0.36650044f, 0.35050082f, 0.33408624f, 0.3171843f,
    0.29970554f, 0.28153703f, 2.3979158f, 2.4319305f, 2.468552f, 2.5080516f, 2.5507424f,
    2.5969908f, 2.6472273f, 2.7019618f, 2.7618022f, 2.8274817f, 2.8998923f, 2.9801323f,
    3.0695715f, 3.1699438f, 3.2834814f, 3.4131145f, 1.8766297f, 1.9243971f, 1.9748417f,
    2.0282505f, 2.0849545f, 2.1453402f, 2.2098594f, 2.2790458f, 2.3535357f, 2.434093f, 2.5216455f,
    2.6173334f, 2.7225764f, 2.839167f, 2.9694092f, 3.116322f, 0.521286f, 0.5075333f, 0.49371043f,
    0.47980118f, 0.46578774f, 0.45165056f, 0.437368f, 0.42291573f, 0.4082664f, 0.39338875f,
    0.3782468f, 0.36279872f, 0.34699503f, 0.33077675f, 0.31407213f, 0.29679257f, 2.3804762f,
    2.4126027f, 2.447118f, 2.484259f, 2.5242984f, 2.5675533f, 2.6143932f, 2.6652527f, 2.720646f,
    2.7811868f, 2.847615f, 2.9208302f, 3.0019412f, 3.0923293f, 3.193744f, 3.3084369f, 1.8514814f,
    1.8970894f, 1.9451451f, 1.9959004f, 2.049644f, 2.1067104f, 2.1674883f, 2.2324338f, 2.302085f,
    2.3770828f, 2.4581976f, 2.546365f, 2.6427345f, 2.748737f, 2.8661804f, 2.9973872f, 0.5289947f,
    0.5155134f, 0.501973f, 0.4883586f, 0.4746544f, 0.46084288f, 0.4469048f, 0.4328188f,
    0.4185609f, 0.40410405f, 0.38941744f, 0.37446544f, 0.35920662f, 0.34359214f, 0.32756346f,
    0.3110496f, 2.3642492f, 2.3946543f, 2.4272559f, 2.4622626f, 2.4999132f, 2.5404835f,
    2.5842931f, 2.6317153f, 2.6831884f, 2.739231f, 2.800463f, 2.8676298f, 2.94164f, 3.0236108f,
    3.1149366f, 3.2173817f, 1.8278228f, 1.8714525f, 1.9173282f, 1.9656718f, 2.0167367f,
    2.0708144f, 2.1282415f, 2.1894102f, 2.25478f, 2.3248937f, 2.4003968f, 2.4820662f, 2.570845f,
    2.667892f, 2.7746494f, 2.89294f, 0.53642625f, 0.52320176f, 0.5099277f, 0.49659076f,
    0.4831765f, 0.46966922f, 0.45605174f, 0.44230512f, 0.42840824f, 0.4143375f, 0.40006614f,
    0.38556367f, 0.37079495f, 0.3557189f, 0.3402872f, 0.32444185f, 2.3491178f, 2.3779478f,
    2.4088044f, 2.4418724f, 2.4773614f, 2.5155132f, 2.5566056f, 2.6009614f, 2.648957f, 2.7010345f,
    2.7577178f, 2.8196313f, 2.8875275f, 2.9623225f, 3.0451431f, 3.137396f, 1.8055202f, 1.8473313f,
    1.8912102f, 1.9373533f, 1.985984f, 2.0373578f, 2.0917683f, 2.1495547f, 2.211113f, 2.2769053f,
    2.3474789f, 2.4234848f, 2.5057056f, 2.5950923f, 2.6928127f, 2.8003204f, 0.54359746f,
    0.5306164f, 0.51759434f, 0.50451905f, 0.49137747f, 0.47815537f, 0.46483737f, 0.4514065f,
    0.43784413f, 0.4241294f, 0.410239f, 0.39614654f, 0.3818218f, 0.36723006f, 0.35233063f,
    0.33707562f, 2.334979f, 2.3623638f, 2.3916242f, 2.422924f, 2.4564495f, 2.4924128f, 2.5310571f,
    2.5726633f, 2.617557f, 2.6661177f, 2.7187915f, 2.7761064f, 2.8386927f, 2.907309f, 2.9828794f,
    3.0665402f, 1.7844557f, 1.8245898f, 1.8666335f, 1.9107614f, 1.9571712f, 2.0060883f, 2.05777f,
    2.112512f, 2.170657f, 2.2326026f, 2.2988155f, 2.369847f, 2.446353f, 2.5291226f, 2.6191137f,
    2.7175033f, 0.5505235f, 0.53777385f, 0.5249907f, 0.5121628f, 0.49927837f, 0.48632443f,
    0.4732871f, 0.46015117f, 0.44689995f, 0.43351507f, 0.4199759f, 0.40625948f, 0.39233965f,
    0.37818655f, 0.36376578f, 0.3490371f, 2.3217435f, 2.3477974f, 2.3755927f, 2.4052753f,
    2.4370105f, 2.4709854f, 2.5074148f, 2.5465438f, 2.588656f, 2.6340795f, 2.683197f, 2.736459f,
    2.7943974f, 2.8576481f, 2.926976f, 3.0033126f, 1.7645249f, 1.8031085f, 1.84346f, 1.885736f,
    1.9301122f, 1.9767884f, 2.0259912f, 2.0779798f, 2.1330526f, 2.191554f, 2.2538855f, 2.320517f,
    2.3920043f, 2.469008f, 2.552323f, 2.642915f, 0.55721843f, 0.544689f, 0.5321328f, 0.5195395f,
    0.50689816f, 0.4941971f, 0.48142362f, 0.46856406f, 0.45560345f, 0.44252533f, 0.42931154f,
    0.41594175f, 0.40239322f, 0.38864014f, 0.37465292f, 0.36039752f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 9.949874f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 9.949874f, 1, 1,
    1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    7.1425f, 10.049875f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 7.0703535f, 10.049875f, 1, 1,
    1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0.07214647f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    5.918356f, 7.2121425f, 10.148891f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 5.801161f,
    7.140735f, 10.148891f, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0.11719517f, 0.071407355f, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 5.1997595f, 5.9743676f, 7.28112f, 10.246951f, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 5.0483103f, 5.858361f, 7.210429f, 10.246951f, 1, 1, 1, 1, 1, 1, 1, 1,
    1, 1, 1, 1, 0.15144931f, 0.11600714f, 0.07069048f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    4.716728f, 5.2475486f, 6.029861f, 7.3494506f, 10.34408f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    4.537043f, 5.0976186f, 5.9150066f, 7.2794557f, 10.34408f, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1,
    0.17968488f, 0.14992996f, 0.11485449f, 0.06999477f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    4.365454f, 4.7588444f, 5.2949085f, 6.08485f, 7.4171524f, 10.440307f, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 4.161461f, 4.580944f, 5.1464534f, 5.971114f, 7.347833f, 10.440307f, 1, 1, 1, 1, 1, 1, 1,
    1, 1, 1, 0.20399319f, 0.17790073f, 0.14845538f, 0.11373551f, 0.06931918f, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 4.0964446f, 4.4033422f, 4.8005953f, 5.3418517f, 6.1393476f, 7.484243f, 10.535654f,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 3.8709524f, 4.201354f, 4.6244264f, 5.194828f, 6.026699f, 7.41558f,
    10.535654f, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0.22549237f, 0.20198818f, 0.17616864f, 0.14702344f,
    0.11264858f, 0.06866278f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 3.8827467f, 4.1310177f, 4.440912f,
    4.841989f, 5.3883877f, 6.1933675f, 7.5507374f, 10.630146f, 0, 0, 0, 0, 0, 0, 0, 0, 3.6378887f,
    3.9077194f, 4.240871f, 4.6675034f, 5.2427554f, 6.081775f, 7.4827127f, 10.630146f, 1, 1, 1, 1,
    1, 1, 1, 1, 0.24485789f, 0.22329825f, 0.20004107f, 0.1744861f, 0.1456321f, 0.1115922f,
    0.068024665f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 3.7082777f, 3.9146254f, 4.165309f, 4.478171f,
    4.8830357f, 5.434528f, 6.246921f, 7.6166525f, 10.723805f, 0, 0, 0, 0, 0, 0, 0, 3.4457448f,
    3.6721265f, 3.9441423f, 4.2800217f, 4.7101846f, 5.2902484f, 6.1363564f, 7.549248f, 10.723805f,
    1, 1, 1, 1, 1, 1, 1, 0.26253292f, 0.24249892f, 0.22116685f, 0.19814914f, 0.17285082f,
    0.1442795f, 0.11056498f, 0.067404f, 0, 0, 0, 0, 0, 0, 0, 0, 3.5627792f, 3.7379088f,
    3.9462535f, 4.199326f, 4.515126f, 4.923743f, 5.4802814f, 6.300021f, 7.682002f, 10.816654f, 0,
    0, 0, 0, 0, 0, 3.2839532f, 3.4778805f, 3.7060468f, 3.9802306f, 4.318816f, 4.7524824f,
    5.3373175f, 6.1904554f, 7.6152024f, 10.816654f, 1, 1, 1, 1, 1, 1, 0.2788262f, 0.26002845f,
    0.24020673f, 0.21909526f, 0.19630983f, 0.17126063f, 0.14296386f, 0.109565586f, 0.06680002f, 0,
    0, 0, 0, 0, 0, 0, 3.4393642f, 3.5904968f, 3.7673147f, 3.9776363f, 4.233074f, 4.5517855f,
    4.964119f, 5.5256577f, 6.3526783f, 7.7468014f, 10.908712f, 0, 0, 0, 0, 0, 3.1454015f,
    3.3143046f, 3.5097206f, 3.739658f, 4.0159936f, 4.3572645f, 4.7944055f, 5.3839746f, 6.2440853f,
    7.680589f, 10.908712f, 1, 1, 1, 1, 1, 0.29396275f, 0.27619207f, 0.25759417f, 0.23797825f,
    0.21708074f, 0.19452074f, 0.16971347f, 0.14168353f, 0.10859279f, 0.066211976f, 0, 0, 0, 0, 0,
    0, 3.3332176f, 3.4654255f, 3.6180105f, 3.7965002f, 4.0087795f, 4.2665606f, 4.5881553f,
    5.0041723f, 5.570667f, 6.404904f, 7.8110633f, 11, 0, 0, 0, 0, 3.025105f, 3.1742134f,
    3.3443794f, 3.5412734f, 3.7729688f, 4.05144f, 4.3953757f, 4.8359647f, 5.4302297f, 6.2972584f,
    7.7454243f, 11, 1, 1, 1, 1, 0.30811256f, 0.29121223f, 0.27363104f, 0.2552269f, 0.23581055f,
    0.2151207f, 0.19277963f, 0.16820747f, 0.14043698f, 0.107645445f, 0.06563919f, 0, 0, 0, 0, 0,
    3.2408602f, 3.3578267f, 3.491302f, 3.6453247f, 3.8254697f, 4.039688f, 4.2997904f, 4.624243f,
    5.0439095f, 5.6153164f, 6.456708f, 7.8748016f, 11.090536f, 0, 0, 0, 2.9194527f, 3.0525696f,
    3.2027645f, 3.3741848f, 3.572546f, 3.8059871f, 4.086578f, 4.4331584f, 4.877169f, 5.476094f,
    6.349985f, 7.8097205f, 11.090536f, 1, 1, 1, 0.32140765f, 0.30525696f, 0.28853735f,
    0.27113986f, 0.2529236f, 0.23370096f, 0.21321276f, 0.19108441f, 0.16674082f, 0.13922273f,
    0.106722444f, 0.06508101f, 0, 0, 0, 0, 3.15971f, 3.2641823f, 3.3822672f, 3.516997f,
    3.6724436f, 3.8542278f, 4.070367f, 4.33277f, 4.6600537f, 5.083339f, 5.6596155f, 6.5081005f,
    7.9380283f, 11.18034f, 0, 0, 2.8257568f, 2.9457254f, 3.0797882f, 3.2310622f, 3.4037282f,
    3.6035464f, 3.83872f, 4.121415f, 4.4706206f, 4.9180274f, 5.5215764f, 6.402278f, 7.873492f,
    11.18034f, 1, 1, 0.33395308f, 0.3184568f, 0.30247918f, 0.28593472f, 0.26871538f, 0.2506815f,
    0.23164691f, 0.21135463f, 0.18943308f, 0.16531184f, 0.13803941f, 0.10582277f, 0.06453682f, 0,
    0, 0, 3.087804f, 3.1818802f, 3.2873502f, 3.4065425f, 3.5425143f, 3.6993709f, 3.8827791f,
    4.1008215f, 4.365504f, 4.695595f, 5.122467f, 5.7035723f, 6.5590916f, 8.000756f, 11.269427f, 0,
    2.74197f, 2.8509648f, 2.9717646f, 3.1067667f, 3.259113f, 3.433016f, 3.6342812f, 3.8711755f,
    4.1559596f, 4.507771f, 4.958548f, 5.5666866f, 6.454146f, 7.93675f, 11.269427f, 1, 0.34583408f,
    0.33091554f, 0.3155856f, 0.29977575f, 0.28340113f, 0.2663547f, 0.24849786f, 0.22964601f,
    0.20954418f, 0.18782379f, 0.16391894f, 0.13688573f, 0.104945466f, 0.064006045f, 0, 0
};
/* clang-format on */
static const int SHLI_SH_LANES_AT[4] = {-1, 47, 79, 95};
/* clang-format off */
static const float SHLI_SH_LANES_S[720] = {
    1.7320508f, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1.7320508f, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 2, 2.236068f, 1, 1, 1, 1,
    1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 3, 2.236068f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0.6454972f, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1.5f, 4, 2.6457512f, 1, 1, 1, 1, 1,
    1, 1, 1, 1, 1, 1, 1, 1, 2.5f, 5, 2.6457512f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0.50917506f, 0.41833f, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1.3333334f, 2.5f, 6, 3, 1, 1,
    1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 2.3333333f, 3.5f, 7, 3, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0.4330127f, 0.24494897f, 0.32732683f, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1.25f, 2, 3.5f,
    8, 3.3166249f, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 2.25f, 3, 4.5f, 9, 3.3166249f, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0.38297084f, 0.16583124f, 0.15793452f, 0.2763854f, 1, 1, 1, 1, 1, 1, 1, 1,
    1, 1, 1, 1, 1.2f, 1.75f, 2.6666667f, 4.5f, 1e+01f, 3.6055512f, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1,
    2.2f, 2.75f, 3.6666667f, 5.5f, 11, 3.6055512f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0.34694433f,
    0.12188988f, 0.09105392f, 0.11564811f, 0.24308622f, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1,
    1.1666666f, 1.6f, 2.25f, 3.3333333f, 5.5f, 12, 3.8729835f, 1, 1, 1, 1, 1, 1, 1, 1, 1,
    2.1666667f, 2.6f, 3.25f, 4.3333335f, 6.5f, 13, 3.8729835f, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0.31943828f, 0.09449112f, 0.058321185f, 0.058925565f, 0.09090909f, 0.2192645f, 1, 1, 1, 1, 1,
    1, 1, 1, 1, 1, 1.1428572f, 1.5f, 2, 2.75f, 4, 6.5f, 14, 4.1231055f, 1, 1, 1, 1, 1, 1, 1, 1,
    2.142857f, 2.5f, 3, 3.75f, 5, 7.5f, 15, 4.1231055f, 0, 0, 0, 0, 0, 0, 0, 0, 0.29755953f,
    0.07604152f, 0.0400774f, 0.033834614f, 0.04190702f, 0.074755795f, 0.20118695f, 1, 1, 1, 1, 1,
    1, 1, 1, 1, 1.125f, 1.4285715f, 1.8333334f, 2.4f, 3.25f, 4.6666665f, 7.5f, 16, 4.358899f, 1,
    1, 1, 1, 1, 1, 1, 2.125f, 2.4285715f, 2.8333333f, 3.4f, 4.25f, 5.6666665f, 8.5f, 17,
    4.358899f, 0, 0, 0, 0, 0, 0, 0, 0.2796235f, 0.06291529f, 0.02897062f, 0.021077415f,
    0.021980746f, 0.031682864f, 0.06341265f, 0.18688625f, 1, 1, 1, 1, 1, 1, 1, 1, 1.1111112f,
    1.375f, 1.7142857f, 2.1666667f, 2.8f, 3.75f, 5.3333335f, 8.5f, 18, 4.582576f, 1, 1, 1, 1, 1,
    1, 2.1111112f, 2.375f, 2.7142856f, 3.1666667f, 3.8f, 4.75f, 6.3333335f, 9.5f, 19, 4.582576f,
    0, 0, 0, 0, 0, 0, 0.26457512f, 0.053181604f, 0.021759707f, 0.013937367f, 0.012606823f,
    0.015384615f, 0.025f, 0.055024374f, 0.17521916f, 1, 1, 1, 1, 1, 1, 1, 1.1f, 1.3333334f,
    1.625f, 2, 2.5f, 3.2f, 4.25f, 6, 9.5f, 2e+01f, 4.7958317f, 1, 1, 1, 1, 1, 2.1f, 2.3333333f,
    2.625f, 3, 3.5f, 4.2f, 5.25f, 7, 10.5f, 21, 4.7958317f, 0, 0, 0, 0, 0, 0.25171587f,
    0.04572646f, 0.016842416f, 0.009647706f, 0.0077253208f, 0.008216281f, 0.011351279f,
    0.020359373f, 0.048576746f, 0.16547191f, 1, 1, 1, 1, 1, 1, 1.0909091f, 1.3f, 1.5555556f,
    1.875f, 2.2857144f, 2.8333333f, 3.6f, 4.75f, 6.6666665f, 10.5f, 22, 5, 1, 1, 1, 1, 2.090909f,
    2.3f, 2.5555556f, 2.875f, 3.2857144f, 3.8333333f, 4.6f, 5.75f, 7.6666665f, 11.5f, 23, 5, 0, 0,
    0, 0, 0.24056262f, 0.039866272f, 0.013356386f, 0.006925533f, 0.004983284f, 0.0047114994f,
    0.005693889f, 0.008711013f, 0.016986769f, 0.043470044f, 0.15717365f, 1, 1, 1, 1, 1,
    1.0833334f, 1.2727273f, 1.5f, 1.7777778f, 2.125f, 2.5714285f, 3.1666667f, 4, 5.25f,
    7.3333335f, 11.5f, 24, 5.196152f, 1, 1, 1, 2.0833333f, 2.2727273f, 2.5f, 2.7777777f, 3.125f,
    3.5714285f, 4.1666665f, 5, 6.25f, 8.333333f, 12.5f, 25, 5.196152f, 0, 0, 0, 0.23076923f,
    0.03516054f, 0.010805848f, 0.0051209154f, 0.003349437f, 0.0028561947f, 0.0030785508f,
    0.004131996f, 0.0068910914f, 0.01444714f, 0.039327566f, 0.15f, 1, 1, 1, 1, 1.0769231f, 1.25f,
    1.4545455f, 1.7f, 2, 2.375f, 2.857143f, 3.5f, 4.4f, 5.75f, 8, 12.5f, 26, 5.3851647f, 1, 1,
    2.0769231f, 2.25f, 2.4545455f, 2.7f, 3, 3.375f, 3.857143f, 4.5f, 5.4f, 6.75f, 9, 13.5f, 27,
    5.3851647f, 0, 0, 0.22208045f, 0.031313863f, 0.008890334f, 0.0038810025f, 0.0023286014f,
    0.0018109101f, 0.0017656373f, 0.0021191887f, 0.0031080511f, 0.0055848313f, 0.012479576f,
    0.0359011f, 0.14371942f, 1, 1, 1, 1.0714285f, 1.2307693f, 1.4166666f, 1.6363636f, 1.9f,
    2.2222223f, 2.625f, 3.142857f, 3.8333333f, 4.8f, 6.25f, 8.666667f, 13.5f, 28, 5.5677643f, 1,
    2.0714285f, 2.2307692f, 2.4166667f, 2.6363637f, 2.9f, 3.2222223f, 3.625f, 4.142857f,
    4.8333335f, 5.8f, 7.25f, 9.666667f, 14.5f, 29, 5.5677643f, 0, 0.21430334f, 0.028121457f,
    0.007419677f, 0.0030032508f, 0.0016653438f, 0.0011915334f, 0.0010622884f, 0.001156094f,
    0.0015195266f, 0.0024059173f, 0.004616222f, 0.010919284f, 0.033020586f, 0.13816175f, 1, 1
};
/* clang-format on */
#endif
/* @generated end lanes */
/* @generated begin plane */
#if SHLIGHT_SIMD_EVAL
/* clang-format off */
static const float SHLI_SH_PLANES[120] = {
    0.2820948f, -0.48860252f, 0.48860252f, -0.48860252f, 0.54627424f, -1.0925485f, -0.31539157f,
    -1.0925485f, 0.54627424f, -0.5900436f, 1.4453057f, 0.4570458f, -1.119529f, 0.4570458f,
    1.4453057f, -0.5900436f, 0.6258357f, -1.7701308f, -0.47308734f, 2.0071397f, 0.31735665f,
    2.0071397f, -0.47308734f, -1.7701308f, 0.6258357f, -0.6563821f, 2.0756624f, 0.4892383f,
    -2.3967683f, -0.45294666f, 1.7542548f, -0.45294666f, -2.3967683f, 0.4892383f, 2.0756624f,
    -0.6563821f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0.9461747f, 0, 0, 0, 0, -2.285229f, 1.8658817f,
    -2.285229f, 0, 0, 0, 0, 3.3116114f, -4.683326f, -3.1735663f, -4.683326f, 3.3116114f, 0, 0, 0,
    0, -4.403145f, 7.190305f, 6.3412533f, -8.1865225f, 6.3412533f, 7.190305f, -4.403145f, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 3.7024941f, 0, 0, 0, 0,
    0, 0, 0, 0, -9.51188f, 7.3678703f, -9.51188f, 0, 0, 0, 0, 0, 0, 0, 0
};
/* clang-format on */
/* clang-format off */
static const int SHLI_SH_PTAP[40] = {
    0, 9, 0, 1, 10, 9, 0, 1, 2, 11, 10, 9, 0, 1, 2, 3, 12, 11, 10, 9, 0, 1, 2, 3, 4, 13, 12, 11,
    10, 9, 0, 1, 2, 3, 4, 5, 0, 0, 0, 0
};
/* clang-format on */
/* clang-format off */
static const int SHLI_SH_PODD[5] = {
    0xA4, 0x54, 0xAA, 0x54, 0x05
};
/* clang-format on */
#endif
/* @generated end plane */
#ifdef __AVX512VL__
/* n = 4..6 (C only, AVX-512VL): the Horner forms of shli_sh_poly_<n> evaluated across the
   outputs, lane i = output i, so that the n^2 results leave in ceil(n^2 / 8) 256-bit stores (a
   float store per output bounds the scalar form at n^2 cycles on Zen 4): per vector two FMAs in
   z^2, a multiply by z on the odd lanes and one by (x + iy)^|m| (a two-source permute of the
   powers, lane m of c and s). Same coefficients and the same float input as shli_sh_poly_<n>.
   256-bit vectors: on Zen 4 they issue on both FMA pipes and store in one cycle (bench: n = 6 at
   0.37 of the loop, 0.47-0.48 with 512-bit vectors, 0.47-0.55 scalar). */
SHLIGHT_CPU_INLINE void shli_sh_eval_avx512_poly(int n, float x, float y, float z, float *out_y) {
  __m256 vz = _mm256_set1_ps(z), z2 = _mm256_set1_ps(z * z), one = _mm256_set1_ps(1.0f);
  __m256 c = _mm256_mask_blend_ps((__mmask8)0xAA, one, _mm256_set1_ps(x));
  __m256 s = _mm256_maskz_mov_ps((__mmask8)0xAA, _mm256_set1_ps(y));
  int v, nv = (n * n + 7) >> 3;
  if (n > 2) {
    /* lanes 2, 3 (and 6, 7) times (x + iy)^2, lanes 4..7 times (x + iy)^4 */
    float cr = x * x - y * y, ci = 2.0f * x * y;
    __m256 vc = _mm256_set1_ps(cr), vi = _mm256_set1_ps(ci);
    __m256 t0 = _mm256_mul_ps(s, vi), t1 = _mm256_mul_ps(c, vi);
    c = _mm256_mask_fmsub_ps(c, (__mmask8)0xCC, vc, t0);
    s = _mm256_mask_fmadd_ps(s, (__mmask8)0xCC, vc, t1);
    if (n > 4) {
      vc = _mm256_set1_ps(cr * cr - ci * ci);
      vi = _mm256_set1_ps(2.0f * cr * ci);
      t0 = _mm256_mul_ps(s, vi);
      t1 = _mm256_mul_ps(c, vi);
      c = _mm256_mask_fmsub_ps(c, (__mmask8)0xF0, vc, t0);
      s = _mm256_mask_fmadd_ps(s, (__mmask8)0xF0, vc, t1);
    }
  }
  for (v = 0; v < nv; ++v) {
    __m256 h = _mm256_fmadd_ps(_mm256_loadu_ps(SHLI_SH_PLANES + 80 + 8 * v), z2,
                               _mm256_loadu_ps(SHLI_SH_PLANES + 40 + 8 * v));
    __m256 r;
    h = _mm256_fmadd_ps(h, z2, _mm256_loadu_ps(SHLI_SH_PLANES + 8 * v));
    h = _mm256_mask_mul_ps(h, (__mmask8)SHLI_SH_PODD[v], h, vz);
    r = _mm256_mul_ps(
        h, _mm256_permutex2var_ps(
               c, _mm256_loadu_si256((const __m256i *)(const void *)(SHLI_SH_PTAP + 8 * v)), s));
    if (8 * v + 8 <= n * n) {
      _mm256_storeu_ps(out_y + 8 * v, r);
    } else {
      _mm256_mask_storeu_ps(out_y + 8 * v, (__mmask8)((1u << (n * n - 8 * v)) - 1u), r);
    }
  }
}
#endif

/* Full unrolling of the band loops of the across-m cores when n is a compile-time constant
   (inlined with a literal n): the loop then has no branches and every mask is an immediate.
   GCC does not peel a 16-trip loop of this size by itself. */
#if defined(__clang__)
#define SHLI_UNROLL_BANDS _Pragma("unroll")
#elif defined(__GNUC__) && __GNUC__ >= 8
#define SHLI_UNROLL_BANDS _Pragma("GCC unroll 16")
#else
#define SHLI_UNROLL_BANDS
#endif

/* n <= 16 with AVX-512VL: the same in 256-bit registers, orders 0..7 and, from band 8 on,
   8..15: 256-bit operations issue on both FMA pipes of a Zen 4 core and a 256-bit store takes
   one cycle where a 512-bit one takes two */
SHLIGHT_CPU_INLINE void shli_sh_eval_avx512_16y(int n, float x, float y, float z, float *out_y) {
  static const unsigned short bits[3] = {0xAA, 0xCC, 0xF0};
  float s2 = x * x + y * y;
  float e = (z - 1.0f) * (z + 1.0f) + s2;
  /* (x + iy)^m from the raw x, y; the renormalisation |d|^-m = 1 + m dl (to O(e^2)) is one
     lane vector applied after the powers, off their chain */
  float dl = e * (-0.5f + 0.375f * e);
  float cr = x * x - y * y, ci = 2.0f * x * y, q;
  __m256 c, s, c8, s8, co, so, co8, so8, vs, xv, dd, xv8, dd8, vt, pk, vc, vi;
  __m256i iota = _mm256_set_epi32(7, 6, 5, 4, 3, 2, 1, 0);
  int b, l;
  vt = _mm256_set1_ps(s2 / (1.0f + fabsf(z)));
  vs = _mm256_set1_ps(copysignf(1.0f, z));
  /* lane m gets (x + iy)^m as the product of (x + iy)^(2^b) over the set bits b of m; orders
     8..15 are orders 0..7 times (x + iy)^8 */
  c = _mm256_mask_blend_ps((__mmask8)0xAA, _mm256_set1_ps(1.0f), _mm256_set1_ps(x));
  s = _mm256_maskz_mov_ps((__mmask8)0xAA, _mm256_set1_ps(y));
  for (b = 1; b < 3; ++b) {
    __m256 t0, t1;
    vc = _mm256_set1_ps(cr);
    vi = _mm256_set1_ps(ci);
    t0 = _mm256_mul_ps(s, vi);
    t1 = _mm256_mul_ps(c, vi);
    c = _mm256_mask_fmsub_ps(c, (__mmask8)bits[b], vc, t0);
    s = _mm256_mask_fmadd_ps(s, (__mmask8)bits[b], vc, t1);
    q = cr * cr - ci * ci;
    ci = 2.0f * cr * ci;
    cr = q;
  }
  c8 = _mm256_setzero_ps();
  s8 = _mm256_setzero_ps();
  if (n > 8) {
    vc = _mm256_set1_ps(cr);
    vi = _mm256_set1_ps(ci);
    c8 = _mm256_fmsub_ps(c, vc, _mm256_mul_ps(s, vi));
    s8 = _mm256_fmadd_ps(s, vc, _mm256_mul_ps(c, vi));
  }
  /* parity: X_l^m(z) = sg^(l-m) X_l^m(|z|), sg^m into the odd lanes, sg^l per band; with the
     renormalisation 1 + m dl */
  pk = _mm256_fmadd_ps(_mm256_cvtepi32_ps(iota), _mm256_set1_ps(dl), _mm256_set1_ps(1.0f));
  pk = _mm256_mask_mul_ps(pk, (__mmask8)0xAA, pk, vs);
  c = _mm256_mul_ps(c, pk);
  s = _mm256_mul_ps(s, pk);
  co = _mm256_mul_ps(c, vs);
  so = _mm256_mul_ps(s, vs);
  co8 = c8;
  so8 = s8;
  if (n > 8) {
    pk = _mm256_fmadd_ps(_mm256_set1_ps(8.0f * dl), vs, pk); /* lanes 8..15: + 8 dl sg^m */
    pk = _mm256_mask_blend_ps((__mmask8)0x55, pk,
                              _mm256_fmadd_ps(_mm256_cvtepi32_ps(iota), _mm256_set1_ps(dl),
                                              _mm256_set1_ps(1.0f + 8.0f * dl)));
    c8 = _mm256_mul_ps(c8, pk);
    s8 = _mm256_mul_ps(s8, pk);
    co8 = _mm256_mul_ps(c8, vs);
    so8 = _mm256_mul_ps(s8, vs);
  }
  xv = _mm256_loadu_ps(SHLI_SH_DIAG);
  xv8 = _mm256_loadu_ps(SHLI_SH_DIAG + 8);
  dd = _mm256_setzero_ps();
  dd8 = _mm256_setzero_ps();
  out_y[0] = SHLI_SH_DIAG[0];
  SHLI_UNROLL_BANDS
  for (l = 1; l < n; ++l) {
    /* scaled Reinsch step (tools/gen_basis.py, gen_lane_table_scaled): X~ and D~ both from
       the previous band only, one FMA of latency per band */
    const float *tb = SHLI_SH_LANES_S + (l - 1) * 48;
    __m256 bt = _mm256_mul_ps(_mm256_loadu_ps(tb + 16), vt);
    __m256 at = _mm256_sub_ps(_mm256_loadu_ps(tb), bt);
    __m256 yc, ys, xo;
    __m256 xn = _mm256_fmadd_ps(at, xv, dd);
    dd = _mm256_fnmadd_ps(bt, xv, dd);
    xv = xn;
    xo = _mm256_mul_ps(xv, _mm256_loadu_ps(tb + 32));
    yc = _mm256_mul_ps(xo, (l & 1) ? co : c);
    ys = _mm256_mul_ps(xo, (l & 1) ? so : s);
    if (l < 8) {
      ys = _mm256_permutexvar_ps(_mm256_sub_epi32(_mm256_set1_epi32(l), iota), ys);
      _mm256_mask_storeu_ps(out_y + l * l, (__mmask8)((1u << l) - 1u), ys);
      _mm256_mask_storeu_ps(out_y + l * l + l, (__mmask8)((2u << l) - 1u), yc);
    } else {
      __m256 bt8 = _mm256_mul_ps(_mm256_loadu_ps(tb + 24), vt);
      __m256 at8 = _mm256_sub_ps(_mm256_loadu_ps(tb + 8), bt8);
      __m256 yc8, ys8, xo8;
      __m256 xn8 = _mm256_fmadd_ps(at8, xv8, dd8);
      dd8 = _mm256_fnmadd_ps(bt8, xv8, dd8);
      xv8 = xn8;
      xo8 = _mm256_mul_ps(xv8, _mm256_loadu_ps(tb + 40));
      yc8 = _mm256_mul_ps(xo8, (l & 1) ? co8 : c8);
      ys8 = _mm256_mul_ps(xo8, (l & 1) ? so8 : s8);
      /* sines: m = l..8 (lanes l-8..0 of ys8) at l^2 .., then m = 7..1 (lanes 7..1 of ys) */
      ys8 = _mm256_permutexvar_ps(_mm256_sub_epi32(_mm256_set1_epi32(l - 8), iota), ys8);
      ys = _mm256_permutexvar_ps(_mm256_sub_epi32(_mm256_set1_epi32(7), iota), ys);
      _mm256_mask_storeu_ps(out_y + l * l, (__mmask8)((1u << (l - 7)) - 1u), ys8);
      _mm256_mask_storeu_ps(out_y + l * l + l - 7, (__mmask8)0x7F, ys);
      _mm256_storeu_ps(out_y + l * l + l, yc);
      _mm256_mask_storeu_ps(out_y + l * l + l + 8, (__mmask8)((2u << (l - 8)) - 1u), yc8);
    }
  }
}

/* The order lanes of the 512-bit across-m cores for n <= 16 bands at (x, y, z), |d| ~ 1:
   lv[0] + i lv[1] has (x + iy)^m in lane m (from the raw x, y, as the product of
   (x + iy)^(2^b) over the set bits b of m), renormalised by |d|^-m = 1 + m dl (to O(e^2),
   e = |d|^2 - 1 formed without cancellation near the poles; one lane vector off the chain of
   powers) and times sg^m (parity: X_l^m(z) = sg^(l-m) X_l^m(|z|)); lv[2] + i lv[3] the same
   times sg (odd bands); lv[4] = t = s2 / (1 + |z|), which is 1 - |z| / |d| to a relative
   O(|d| - 1): no normalisation, no cancellation at the poles. */
SHLIGHT_CPU_INLINE void shli_sh_lanes512(int n, float x, float y, float z, __m512 *lv) {
  static const unsigned short bits[4] = {0xAAAA, 0xCCCC, 0xF0F0, 0xFF00};
  float s2 = x * x + y * y;
  float e = (z - 1.0f) * (z + 1.0f) + s2;
  float dl = e * (-0.5f + 0.375f * e);
  float cr = x * x - y * y, ci = 2.0f * x * y, q;
  __m512 c, s, vs, pk;
  __m512i iota = _mm512_set_epi32(15, 14, 13, 12, 11, 10, 9, 8, 7, 6, 5, 4, 3, 2, 1, 0);
  int b;
  lv[4] = _mm512_set1_ps(s2 / (1.0f + fabsf(z)));
  vs = _mm512_set1_ps(copysignf(1.0f, z));
  c = _mm512_mask_blend_ps((__mmask16)0xAAAA, _mm512_set1_ps(1.0f), _mm512_set1_ps(x));
  s = _mm512_maskz_mov_ps((__mmask16)0xAAAA, _mm512_set1_ps(y));
  for (b = 1; (1 << b) < n; ++b) {
    __m512 vc = _mm512_set1_ps(cr), vi = _mm512_set1_ps(ci), t0 = _mm512_mul_ps(s, vi);
    __m512 t1 = _mm512_mul_ps(c, vi);
    c = _mm512_mask_fmsub_ps(c, (__mmask16)bits[b], vc, t0);
    s = _mm512_mask_fmadd_ps(s, (__mmask16)bits[b], vc, t1);
    q = cr * cr - ci * ci;
    ci = 2.0f * cr * ci;
    cr = q;
  }
  pk = _mm512_fmadd_ps(_mm512_cvtepi32_ps(iota), _mm512_set1_ps(dl), _mm512_set1_ps(1.0f));
  pk = _mm512_mask_mul_ps(pk, (__mmask16)0xAAAA, pk, vs);
  lv[0] = _mm512_mul_ps(c, pk);
  lv[1] = _mm512_mul_ps(s, pk);
  lv[2] = _mm512_mul_ps(lv[0], vs);
  lv[3] = _mm512_mul_ps(lv[1], vs);
}

/* n <= 16: one register per band (the common case; no chunk bookkeeping) */
SHLIGHT_CPU_INLINE void shli_sh_eval_avx512_16(int n, float x, float y, float z, float *out_y) {
  __m512 lv[5], c, s, co, so, xv, dd, vt;
  __m512i iota = _mm512_set_epi32(15, 14, 13, 12, 11, 10, 9, 8, 7, 6, 5, 4, 3, 2, 1, 0);
  int l;
  shli_sh_lanes512(n, x, y, z, lv);
  c = lv[0];
  s = lv[1];
  co = lv[2];
  so = lv[3];
  vt = lv[4];
  xv = _mm512_loadu_ps(SHLI_SH_DIAG);
  dd = _mm512_setzero_ps();
  out_y[0] = SHLI_SH_DIAG[0];
  for (l = 1; l < n; ++l) {
    /* scaled Reinsch step (tools/gen_basis.py, gen_lane_table_scaled): X~ and D~ both from
       the previous band only, one FMA of latency per band */
    const float *tb = SHLI_SH_LANES_S + (l - 1) * 48;
    __m512 bt = _mm512_mul_ps(_mm512_loadu_ps(tb + 16), vt);
    __m512 at = _mm512_sub_ps(_mm512_loadu_ps(tb), bt);
    __m512 yc, ys, xo;
    __m512 xn = _mm512_fmadd_ps(at, xv, dd);
    dd = _mm512_fnmadd_ps(bt, xv, dd);
    xv = xn;
    xo = _mm512_mul_ps(xv, _mm512_loadu_ps(tb + 32));
    yc = _mm512_mul_ps(xo, (l & 1) ? co : c);
    ys = _mm512_mul_ps(xo, (l & 1) ? so : s);
    ys = _mm512_permutexvar_ps(_mm512_sub_epi32(_mm512_set1_epi32(l), iota), ys);
    _mm512_mask_storeu_ps(out_y + l * l, (__mmask16)((1u << l) - 1u), ys);
    _mm512_mask_storeu_ps(out_y + l * l + l, (__mmask16)((2u << l) - 1u), yc);
  }
}

/* n > 16: up to four registers (chunks of 16 orders) per band */
SHLIGHT_CPU_INLINE void shli_sh_eval_avx512(int n, float x, float y, float z, float *out_y) {
  static const unsigned short bits[4] = {0xAAAA, 0xCCCC, 0xF0F0, 0xFF00};
  /* float prologue, short latency: t = 1 - |z| / |d| = s2 / (|d| (|d| + |z|)) is s2 / (1 + |z|)
     to a relative O(|d| - 1), no normalisation needed; (x + iy) is renormalised to second
     order with e = |d|^2 - 1 formed without cancellation near the poles */
  float s2 = x * x + y * y;
  float e = (z - 1.0f) * (z + 1.0f) + s2;
  float k = 1.0f + e * (-0.5f + 0.375f * e);
  float cr = x * k, ci = y * k, sg, q;
  /* up to 4 chunks of 16 orders: lanes j of chunk h hold m = 16 h + j */
  __m512 c[4], s[4], co[4], so[4], xv[4], dd[4], vs, vt;
  __m512i iota = _mm512_set_epi32(15, 14, 13, 12, 11, 10, 9, 8, 7, 6, 5, 4, 3, 2, 1, 0);
  int b, l, h, nh = (n + 15) >> 4;
  vt = _mm512_set1_ps(s2 / (1.0f + fabsf(z)));
  sg = copysignf(1.0f, z);
  vs = _mm512_set1_ps(sg);
  c[0] = _mm512_set1_ps(1.0f);
  s[0] = _mm512_setzero_ps();
  /* lane j gets (x + iy)^j as the product of (x + iy)^(2^b) over the set bits b of j */
  for (b = 0; b < 4 && (1 << b) < n; ++b) {
    __m512 vc = _mm512_set1_ps(cr), vi = _mm512_set1_ps(ci);
    __m512 nc = _mm512_fmsub_ps(c[0], vc, _mm512_mul_ps(s[0], vi));
    __m512 ns = _mm512_fmadd_ps(s[0], vc, _mm512_mul_ps(c[0], vi));
    c[0] = _mm512_mask_mov_ps(c[0], (__mmask16)bits[b], nc);
    s[0] = _mm512_mask_mov_ps(s[0], (__mmask16)bits[b], ns);
    q = cr * cr - ci * ci;
    ci = 2.0f * cr * ci;
    cr = q;
  }
  /* chunk h = chunk h-1 times (x + iy)^16 (cr, ci hold it after four squarings) */
  for (h = 1; h < nh; ++h) {
    __m512 vc = _mm512_set1_ps(cr), vi = _mm512_set1_ps(ci);
    c[h] = _mm512_fmsub_ps(c[h - 1], vc, _mm512_mul_ps(s[h - 1], vi));
    s[h] = _mm512_fmadd_ps(s[h - 1], vc, _mm512_mul_ps(c[h - 1], vi));
  }
  /* parity: X_l^m(z) = sg^(l-m) X_l^m(|z|); sg^m into the odd lanes (16 h is even), sg^l per
     band through the odd-band copies co, so */
  for (h = 0; h < nh; ++h) {
    c[h] = _mm512_mask_mul_ps(c[h], (__mmask16)0xAAAA, c[h], vs);
    s[h] = _mm512_mask_mul_ps(s[h], (__mmask16)0xAAAA, s[h], vs);
    co[h] = _mm512_mul_ps(c[h], vs);
    so[h] = _mm512_mul_ps(s[h], vs);
    xv[h] = _mm512_loadu_ps(SHLI_SH_DIAG + 16 * h);
    dd[h] = _mm512_setzero_ps();
  }
  out_y[0] = SHLI_SH_DIAG[0];
  for (l = 1; l < n; ++l) {
    for (h = 0; h <= (l >> 4); ++h) { /* chunks whose lowest order m = 16 h has started */
      const float *tb = SHLI_SH_LANES + (SHLI_SH_LANES_AT[h] + l) * 48;
      __m512 at = _mm512_mul_ps(_mm512_loadu_ps(tb), vt), yc, ys;
      int top = l < 16 * h + 15 ? l : 16 * h + 15; /* largest order of the chunk in band l */
      int lo = h > 0 ? 16 * h : 1;                 /* smallest sine order of the chunk */
      dd[h] = _mm512_fnmadd_ps(at, xv[h], _mm512_mul_ps(_mm512_loadu_ps(tb + 32), dd[h]));
      xv[h] = _mm512_fmadd_ps(_mm512_loadu_ps(tb + 16), xv[h], dd[h]);
      yc = _mm512_mul_ps(xv[h], (l & 1) ? co[h] : c[h]);
      ys = _mm512_mul_ps(xv[h], (l & 1) ? so[h] : s[h]);
      /* sines: Y_l^-m at l (l + 1) - m, ascending addresses for descending m */
      ys = _mm512_permutexvar_ps(_mm512_sub_epi32(_mm512_set1_epi32(top - 16 * h), iota), ys);
      _mm512_mask_storeu_ps(out_y + l * l + l - top, (__mmask16)((2u << (top - lo)) - 1u), ys);
      _mm512_mask_storeu_ps(out_y + l * l + l + 16 * h, (__mmask16)((2u << (top - 16 * h)) - 1u),
                            yc);
    }
  }
}
/* AVX-512 gradient pass for 2..16 bands (C only; shl_sh_eval_grad uses it for n >= 5): lanes
   follow the output array (band order), so each 16-float chunk of the AoS gradient is three
   permutes and three multiply-adds from the previous band P (times (l-1)/|d|) and this band Q
   (times l/|d|): out = c1 P[i1] + c2 P[i2] - Q[k] u[f % 3]; tables by tools/gen_grad_simd.py.
   Agrees with the scalar pass to 3.8e-7 of max|grad| (tests/test_basis, native build). */
#if defined(__GNUC__) || defined(__clang__)
#define SHLI_GRADV_ALIGN __attribute__((aligned(64)))
#else
#define SHLI_GRADV_ALIGN
#endif
/* @generated begin gradv */
#define SHLI_GRADV_CHUNKS 55
/* first chunk of band l (l = 1..15; [16] = total) */
static const short SHLI_GRADV_CH0[17] = {0,  0,  1,  2,  4,  6,  9,  12, 15,
                                         19, 23, 27, 32, 37, 43, 49, 55};
/* l as a float */
static const float SHLI_GRADV_LF[16] = {0.0f, 1.0f, 2.0f,  3.0f,  4.0f,  5.0f,  6.0f,  7.0f,
                                        8.0f, 9.0f, 10.0f, 11.0f, 12.0f, 13.0f, 14.0f, 15.0f};
/* mask of the last chunk of band l */
static const unsigned short SHLI_GRADV_LASTM[16] = {0x0007, 0x01FF, 0x7FFF, 0x001F, 0x07FF, 0x0001,
                                                    0x007F, 0x1FFF, 0x0007, 0x01FF, 0x7FFF, 0x001F,
                                                    0x07FF, 0x0001, 0x007F, 0x1FFF};
/* load masks of band l (2l+1 lanes), low and high zmm */
static const unsigned short SHLI_GRADV_YM[16 * 2] = {
    0x0001, 0x0000, 0x0007, 0x0000, 0x001F, 0x0000, 0x007F, 0x0000, 0x01FF, 0x0000, 0x07FF,
    0x0000, 0x1FFF, 0x0000, 0x7FFF, 0x0000, 0xFFFF, 0x0001, 0xFFFF, 0x0007, 0xFFFF, 0x001F,
    0xFFFF, 0x007F, 0xFFFF, 0x01FF, 0xFFFF, 0x07FF, 0xFFFF, 0x1FFF, 0xFFFF, 0x7FFF,
};
/* Q tap (coefficient k = f / 3 of the band) of chunk c = 0..5 */
SHLI_GRADV_ALIGN static const int SHLI_GRADV_IY[6 * 16] = {
    0,  0,  0,  1,  1,  1,  2,  2,  2,  3,  3,  3,  4,  4,  4,  5,  5,  5,  6,  6,  6,  7,  7,  7,
    8,  8,  8,  9,  9,  9,  10, 10, 10, 11, 11, 11, 12, 12, 12, 13, 13, 13, 14, 14, 14, 15, 15, 15,
    16, 16, 16, 17, 17, 17, 18, 18, 18, 19, 19, 19, 20, 20, 20, 21, 21, 21, 22, 22, 22, 23, 23, 23,
    24, 24, 24, 25, 25, 25, 26, 26, 26, 27, 27, 27, 28, 28, 28, 29, 29, 29, 30, 30, 30, 31, 31, 31,
};
/* P taps of chunk c = 0..5 (tap 1, tap 2; 16 lanes each), plus 2l on the y lanes
   (lane j of chunk c is component (16 c + j) % 3) */
SHLI_GRADV_ALIGN static const int SHLI_GRADV_TAP[6 * 32] = {
    -2,  -2,  -1,  -1,  -3,  0,   0,   -4,  1,   1,   -5,  2,   2,   -6,  3,   3,   0,   0,
    -1,  1,   -1,  0,   2,   -2,  1,   3,   -3,  2,   4,   -4,  3,   5,   -7,  4,   4,   -8,
    5,   5,   -9,  6,   6,   -10, 7,   7,   -11, 8,   8,   -12, -5,  4,   6,   -6,  5,   7,
    -7,  6,   8,   -8,  7,   9,   -9,  8,   10,  -10, 9,   9,   -13, 10,  10,  -14, 11,  11,
    -15, 12,  12,  -16, 13,  13,  -17, 14,  9,   11,  -11, 10,  12,  -12, 11,  13,  -13, 12,
    14,  -14, 13,  15,  -15, 14,  14,  -18, 15,  15,  -19, 16,  16,  -20, 17,  17,  -21, 18,
    18,  -22, 19,  19,  16,  -16, 15,  17,  -17, 16,  18,  -18, 17,  19,  -19, 18,  20,  -20,
    19,  21,  -23, 20,  20,  -24, 21,  21,  -25, 22,  22,  -26, 23,  23,  -27, 24,  24,  -28,
    -21, 20,  22,  -22, 21,  23,  -23, 22,  24,  -24, 23,  25,  -25, 24,  26,  -26, 25,  25,
    -29, 26,  26,  -30, 27,  27,  -31, 28,  28,  -32, 29,  29,  -33, 30,  25,  27,  -27, 26,
    28,  -28, 27,  29,  -29, 28,  30,  -30, 29,  31,  -31, 30,
};
/* per chunk (band l = 1..15, its chunks in turn): coefficients of the two terms, 2 x 16 */
/* clang-format off */
SHLI_GRADV_ALIGN static const float SHLI_GRADV_COEF[SHLI_GRADV_CHUNKS * 32] = {
    0, -1.7320508f, 0, 0, 0, 1.7320508f, -1.7320508f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -2.236068f, 0, 0, -2.236068f, 2.236068f, 0, 1.2909944f,
    2.5819888f, -2.236068f, 0, 2.236068f, -2.236068f, 0, 0, 0, -2.236068f, 0, 0, 0, 0, 0,
    1.2909944f, 0, 0, 0, 0, 0, 0, 2.236068f, 0, 0, 0, -3.2403703f, 0, 0, -2.6457512f, 2.6457512f,
    0.83666f, -2.8982754f, 3.34664f, 0, 2.04939f, 3.5496478f, -2.8982754f, 0.83666f, 3.34664f,
    -2.6457512f, -3.2403703f, 0, 0, -2.6457512f, 0, 0, 0, -0.83666f, 0, 2.04939f, 0, 0, 0.83666f,
    0, 0, 0, 0, 2.6457512f, -3.2403703f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2.6457512f, 0, 0,
    3.2403703f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -4.2426405f, 0, 0, -3.6742346f, 3,
    0.80178374f, -3.105295f, 3.927922f, 1.3887302f, -3.5856857f, 4.3915505f, 0, 2.7774603f,
    4.5355735f, -3.5856857f, -4.2426405f, 0, 0, -3.6742346f, 0, 0, -3.105295f, -0.80178374f, 0, 0,
    -1.3887302f, 0, 2.7774603f, 0, 0, 1.3887302f, 1.3887302f, 4.3915505f, -3.105295f, 0.80178374f,
    3.927922f, -3.6742346f, 0, 3, -4.2426405f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0.80178374f, 3.105295f,
    0, 0, 3.6742346f, 0, 0, 4.2426405f, 0, 0, 0, 0, 0, 0, 0, -5.2440443f, 0, 0, -4.690416f,
    3.3166249f, 0.78173596f, -4.136558f, 4.4221663f, 1.3540064f, -3.5823643f, 5.066228f,
    1.9148542f, -4.281744f, 5.4160256f, 0, -5.2440443f, 0, 0, -4.690416f, 0, 0, -4.136558f,
    -0.78173596f, 0, -3.5823643f, -1.3540064f, 0, 0, -1.9148542f, 0, 3.4960294f, 3.4960294f,
    5.527708f, -4.281744f, 1.9148542f, 5.4160256f, -3.5823643f, 1.3540064f, 5.066228f, -4.136558f,
    0.78173596f, 4.4221663f, -4.690416f, 0, 3.3166249f, -5.2440443f, 0, 0, 0, 1.9148542f, 0, 0,
    1.3540064f, 3.5823643f, 0, 0.78173596f, 4.136558f, 0, 0, 4.690416f, 0, 0, 5.2440443f, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    -6.244998f, 0, 0, -5.700877f, 3.6055512f, 0.76870614f, -5.156637f, 4.8617244f, 1.3314381f,
    -4.6122365f, 5.6488132f, 1.8829378f, -4.0676103f, 6.149649f, 2.4308622f, -6.244998f, 0, 0,
    -5.700877f, 0, 0, -5.156637f, -0.76870614f, 0, -4.6122365f, -1.3314381f, 0, -4.0676103f,
    -1.8829378f, 0, 0, -4.981785f, 6.4314566f, 0, 4.2103767f, 6.522688f, -4.981785f, 2.4308622f,
    6.4314566f, -4.0676103f, 1.8829378f, 6.149649f, -4.6122365f, 1.3314381f, 5.6488132f,
    -5.156637f, 0.76870614f, -2.4308622f, 0, 4.2103767f, 0, 0, 2.4308622f, 0, 0, 1.8829378f,
    4.0676103f, 0, 1.3314381f, 4.6122365f, 0, 0.76870614f, 5.156637f, 4.8617244f, -5.700877f, 0,
    3.6055512f, -6.244998f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 5.700877f, 0, 0, 6.244998f, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -7.2456884f, 0, 0, -6.708204f, 3.8729835f, 0.7595545f,
    -6.17065f, 5.262348f, 1.315587f, -5.633007f, 6.17065f, 1.8605211f, -5.095247f, 6.793662f,
    2.4019222f, -7.2456884f, 0, 0, -6.708204f, 0, 0, -6.17065f, -0.7595545f, 0, -5.633007f,
    -1.315587f, 0, -5.095247f, -1.8605211f, 0, -4.5573273f, -4.5573273f, 7.205767f, 2.941742f,
    -5.6839857f, 7.4420843f, 0, 4.922476f, 7.519206f, -5.6839857f, 2.941742f, 7.4420843f,
    -4.5573273f, 2.4019222f, 7.205767f, -5.095247f, 1.8605211f, -2.4019222f, 0, 0, -2.941742f, 0,
    4.922476f, 0, 0, 2.941742f, 0, 0, 2.4019222f, 4.5573273f, 0, 1.8605211f, 5.095247f, 6.793662f,
    -5.633007f, 1.315587f, 6.17065f, -6.17065f, 0.7595545f, 5.262348f, -6.708204f, 0, 3.8729835f,
    -7.2456884f, 0, 0, 0, 0, 0, 0, 1.315587f, 5.633007f, 0, 0.7595545f, 6.17065f, 0, 0, 6.708204f,
    0, 0, 7.2456884f, 0, 0, 0, 0, 0, -8.246211f, 0, 0, -7.7136245f, 4.1231055f, 0.7527726f,
    -7.1809936f, 5.6332345f, 1.3038405f, -6.6483083f, 6.6483083f, 1.8439089f, -6.115554f,
    7.3756356f, 2.3804762f, -8.246211f, 0, 0, -7.7136245f, 0, 0, -7.1809936f, -0.7527726f, 0,
    -6.6483083f, -1.3038405f, 0, -6.115554f, -1.8439089f, 0, -5.582711f, -5.582711f, 7.8951464f,
    2.9154758f, -5.049752f, 8.246211f, 3.4496377f, -6.387488f, 8.449852f, 0, 5.6332345f, 8.51665f,
    -6.387488f, 3.4496377f, 8.449852f, -5.049752f, 2.9154758f, -2.3804762f, 0, -5.049752f,
    -2.9154758f, 0, 0, -3.4496377f, 0, 5.6332345f, 0, 0, 3.4496377f, 0, 0, 2.9154758f, 5.049752f,
    8.246211f, -5.582711f, 2.3804762f, 7.8951464f, -6.115554f, 1.8439089f, 7.3756356f,
    -6.6483083f, 1.3038405f, 6.6483083f, -7.1809936f, 0.7527726f, 5.6332345f, -7.7136245f, 0,
    4.1231055f, 0, 2.3804762f, 5.582711f, 0, 1.8439089f, 6.115554f, 0, 1.3038405f, 6.6483083f, 0,
    0.7527726f, 7.1809936f, 0, 0, 7.7136245f, 0, -8.246211f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 8.246211f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -9.246621f, 0, 0,
    -8.717798f, 4.358899f, 0.747545f, -8.188945f, 5.98036f, 1.294786f, -7.660057f, 7.0918345f,
    1.8311038f, -7.131125f, 7.9112725f, 2.3639448f, -9.246621f, 0, 0, -8.717798f, 0, 0,
    -8.188945f, -0.747545f, 0, -7.660057f, -1.294786f, 0, -7.131125f, -1.8311038f, 0, -6.6021385f,
    -6.6021385f, 8.523324f, 2.8952293f, -6.0730844f, 8.97054f, 3.4256816f, -5.543942f, 9.27679f,
    3.9556363f, -7.0918345f, 9.455779f, 0, 6.3431296f, 9.514694f, -7.0918345f, 3.9556363f,
    -2.3639448f, 0, -6.0730844f, -2.8952293f, 0, -5.543942f, -3.4256816f, 0, 0, -3.9556363f, 0,
    6.3431296f, 0, 0, 3.9556363f, 0, 9.455779f, -5.543942f, 3.4256816f, 9.27679f, -6.0730844f,
    2.8952293f, 8.97054f, -6.6021385f, 2.3639448f, 8.523324f, -7.131125f, 1.8311038f, 7.9112725f,
    -7.660057f, 1.294786f, 7.0918345f, 0, 3.4256816f, 5.543942f, 0, 2.8952293f, 6.0730844f, 0,
    2.3639448f, 6.6021385f, 0, 1.8311038f, 7.131125f, 0, 1.294786f, 7.660057f, 0, -8.188945f,
    0.747545f, 5.98036f, -8.717798f, 0, 4.358899f, -9.246621f, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0.747545f, 8.188945f, 0, 0, 8.717798f, 0, 0, 9.246621f, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    -10.246951f, 0, 0, -9.721111f, 4.582576f, 0.74339193f, -9.1952505f, 6.30789f, 1.2875926f,
    -8.669365f, 7.5078907f, 1.820931f, -8.143451f, 8.41052f, 2.3508117f, -10.246951f, 0, 0,
    -9.721111f, 0, 0, -9.1952505f, -0.74339193f, 0, -8.669365f, -1.2875926f, 0, -8.143451f,
    -1.820931f, 0, -7.617501f, -7.617501f, 9.104654f, 2.8791447f, -7.091507f, 9.635461f,
    3.4066498f, -6.5654597f, 10.028906f, 3.9336605f, -6.039345f, 10.300741f, 4.4603515f,
    -7.7967606f, 10.460452f, 0, 7.0524354f, -2.3508117f, 0, -7.091507f, -2.8791447f, 0,
    -6.5654597f, -3.4066498f, 0, -6.039345f, -3.9336605f, 0, 0, -4.4603515f, 0, 7.0524354f, 0,
    10.513149f, -7.7967606f, 4.4603515f, 10.460452f, -6.039345f, 3.9336605f, 10.300741f,
    -6.5654597f, 3.4066498f, 10.028906f, -7.091507f, 2.8791447f, 9.635461f, -7.617501f,
    2.3508117f, 9.104654f, 0, 4.4603515f, 0, 0, 3.9336605f, 6.039345f, 0, 3.4066498f, 6.5654597f,
    0, 2.8791447f, 7.091507f, 0, 2.3508117f, 7.617501f, 0, -8.143451f, 1.820931f, 8.41052f,
    -8.669365f, 1.2875926f, 7.5078907f, -9.1952505f, 0.74339193f, 6.30789f, -9.721111f, 0,
    4.582576f, -10.246951f, 0, 0, 0, 1.820931f, 8.143451f, 0, 1.2875926f, 8.669365f, 0,
    0.74339193f, 9.1952505f, 0, 0, 9.721111f, 0, 0, 10.246951f, 0, 0, 0, -11.247222f, 0, 0,
    -10.723805f, 4.7958317f, 0.7400129f, -10.200374f, 6.6188765f, 1.2817398f, -9.676924f,
    7.9011755f, 1.8126539f, -9.153454f, 8.880155f, 2.3401263f, -11.247222f, 0, 0, -10.723805f, 0,
    0, -10.200374f, -0.7400129f, 0, -9.676924f, -1.2817398f, 0, -9.153454f, -1.8126539f, 0,
    -8.629959f, -8.629959f, 9.648587f, 2.8660576f, -8.106435f, 10.253919f, 3.391165f, -7.5828753f,
    10.723805f, 3.91578f, -7.059273f, 11.075499f, 4.4400773f, -6.535617f, 11.320021f, 4.964157f,
    -8.502101f, -2.3401263f, 0, -8.106435f, -2.8660576f, 0, -7.5828753f, -3.391165f, 0,
    -7.059273f, -3.91578f, 0, -6.535617f, -4.4400773f, 0, 0, -4.964157f, 11.464231f, 0,
    7.7613206f, 11.511899f, -8.502101f, 4.964157f, 11.464231f, -6.535617f, 4.4400773f, 11.320021f,
    -7.059273f, 3.91578f, 11.075499f, -7.5828753f, 3.391165f, 10.723805f, 0, 7.7613206f, 0, 0,
    4.964157f, 0, 0, 4.4400773f, 6.535617f, 0, 3.91578f, 7.059273f, 0, 3.391165f, 7.5828753f, 0,
    -8.106435f, 2.8660576f, 10.253919f, -8.629959f, 2.3401263f, 9.648587f, -9.153454f, 1.8126539f,
    8.880155f, -9.676924f, 1.2817398f, 7.9011755f, -10.200374f, 0.7400129f, 6.6188765f,
    -10.723805f, 2.8660576f, 8.106435f, 0, 2.3401263f, 8.629959f, 0, 1.8126539f, 9.153454f, 0,
    1.2817398f, 9.676924f, 0, 0.7400129f, 10.200374f, 0, 0, 0, 4.7958317f, -11.247222f, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 10.723805f, 0, 0, 11.247222f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, -12.247449f, 0, 0, -11.726039f, 5, 0.7372098f, -11.204618f, 6.915641f, 1.2768848f,
    -10.683185f, 8.275159f, 1.8057878f, -10.161736f, 9.325048f, 2.331262f, -12.247449f, 0, 0,
    -11.726039f, 0, 0, -11.204618f, -0.7372098f, 0, -10.683185f, -1.2768848f, 0, -10.161736f,
    -1.8057878f, 0, -9.640268f, -9.640268f, 10.161736f, 2.8552012f, -9.118781f, 10.834726f,
    3.3783195f, -8.59727f, 11.373118f, 3.9009476f, -8.075728f, 11.795357f, 4.423259f, -7.5541525f,
    12.113593f, 4.9453535f, -7.032533f, -2.331262f, 0, -9.118781f, -2.8552012f, 0, -8.59727f,
    -3.3783195f, 0, -8.075728f, -3.9009476f, 0, -7.5541525f, -4.423259f, 0, -7.032533f,
    -4.9453535f, 12.335879f, 5.467294f, -9.207747f, 12.467349f, 0, 8.469895f, 12.510865f,
    -9.207747f, 5.467294f, 12.467349f, -7.032533f, 4.9453535f, 12.335879f, -7.5541525f, 4.423259f,
    12.113593f, 0, 0, -5.467294f, 0, 8.469895f, 0, 0, 5.467294f, 0, 0, 4.9453535f, 7.032533f, 0,
    4.423259f, 7.5541525f, 0, -8.075728f, 3.9009476f, 11.795357f, -8.59727f, 3.3783195f,
    11.373118f, -9.118781f, 2.8552012f, 10.834726f, -9.640268f, 2.331262f, 10.161736f,
    -10.161736f, 1.8057878f, 9.325048f, -10.683185f, 3.9009476f, 8.075728f, 0, 3.3783195f,
    8.59727f, 0, 2.8552012f, 9.118781f, 0, 2.331262f, 9.640268f, 0, 1.8057878f, 10.161736f, 0,
    1.2768848f, 1.2768848f, 8.275159f, -11.204618f, 0.7372098f, 6.915641f, -11.726039f, 0, 5,
    -12.247449f, 0, 0, 0, 0, 0, 0, 0, 10.683185f, 0, 0.7372098f, 11.204618f, 0, 0, 11.726039f, 0,
    0, 12.247449f, 0, 0, 0, 0, 0, 0, 0, -13.247642f, 0, 0, -12.727922f, 5.196152f, 0.73484695f,
    -12.208194f, 7.2f, 1.2727922f, -11.688456f, 8.632497f, 1.8f, -11.168706f, 9.748846f, 2.32379f,
    -13.247642f, 0, 0, -12.727922f, 0, 0, -12.208194f, -0.73484695f, 0, -11.688456f, -1.2727922f,
    0, -11.168706f, -1.8f, 0, -10.648944f, -10.648944f, 10.648944f, 2.8460498f, -10.129166f,
    11.384199f, 3.3674917f, -9.60937f, 11.984991f, 3.8884444f, -9.089555f, 12.470766f, 4.4090815f,
    -8.569715f, 12.854571f, 4.929503f, -8.049845f, -2.32379f, 0, -10.129166f, -2.8460498f, 0,
    -9.60937f, -3.3674917f, 0, -9.089555f, -3.8884444f, 0, -8.569715f, -4.4090815f, 0, -8.049845f,
    -4.929503f, 13.145342f, 5.4497705f, -7.52994f, 13.349157f, 5.9699244f, -9.913627f, 13.469967f,
    0, 9.178235f, 13.509996f, -9.913627f, 5.9699244f, 13.469967f, -7.52994f, 5.4497705f,
    13.349157f, 0, -7.52994f, -5.4497705f, 0, 0, -5.9699244f, 0, 9.178235f, 0, 0, 5.9699244f, 0,
    0, 5.4497705f, 7.52994f, 0, -8.049845f, 4.929503f, 13.145342f, -8.569715f, 4.4090815f,
    12.854571f, -9.089555f, 3.8884444f, 12.470766f, -9.60937f, 3.3674917f, 11.984991f,
    -10.129166f, 2.8460498f, 11.384199f, -10.648944f, 4.929503f, 8.049845f, 0, 4.4090815f,
    8.569715f, 0, 3.8884444f, 9.089555f, 0, 3.3674917f, 9.60937f, 0, 2.8460498f, 10.129166f, 0,
    2.32379f, 2.32379f, 10.648944f, -11.168706f, 1.8f, 9.748846f, -11.688456f, 1.2727922f,
    8.632497f, -12.208194f, 0.73484695f, 7.2f, -12.727922f, 0, 5.196152f, -13.247642f, 0,
    10.648944f, 0, 1.8f, 11.168706f, 0, 1.2727922f, 11.688456f, 0, 0.73484695f, 12.208194f, 0, 0,
    12.727922f, 0, 0, 13.247642f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -14.247807f, 0, 0, -13.72953f, 5.3851647f, 0.7328281f,
    -13.2112465f, 7.4734097f, 1.2692956f, -12.692955f, 8.975275f, 1.7950549f, -12.174655f,
    10.154364f, 2.317406f, -14.247807f, 0, 0, -13.72953f, 0, 0, -13.2112465f, -0.7328281f, 0,
    -12.692955f, -1.2692956f, 0, -12.174655f, -1.7950549f, 0, -11.656344f, -11.656344f,
    11.113889f, 2.838231f, -11.138023f, 11.907047f, 3.3582404f, -10.619688f, 12.565385f,
    3.8777618f, -10.101338f, 13.109228f, 4.396969f, -9.582971f, 13.552367f, 4.9159603f,
    -9.064583f, -2.317406f, 0, -11.138023f, -2.838231f, 0, -10.619688f, -3.3582404f, 0,
    -10.101338f, -3.8777618f, 0, -9.582971f, -4.396969f, 0, -9.064583f, -4.9159603f, 13.904436f,
    5.4347987f, -8.546171f, 14.172221f, 5.9535236f, -8.02773f, 14.360439f, 6.4721627f,
    -10.619688f, 14.472196f, 0, 9.886392f, 14.509256f, -10.619688f, 6.4721627f, 14.472196f, 0,
    -8.546171f, -5.4347987f, 0, -8.02773f, -5.9535236f, 0, 0, -6.4721627f, 0, 9.886392f, 0, 0,
    6.4721627f, 0, 0, -8.02773f, 5.9535236f, 14.360439f, -8.546171f, 5.4347987f, 14.172221f,
    -9.064583f, 4.9159603f, 13.904436f, -9.582971f, 4.396969f, 13.552367f, -10.101338f,
    3.8777618f, 13.109228f, -10.619688f, 5.9535236f, 8.02773f, 0, 5.4347987f, 8.546171f, 0,
    4.9159603f, 9.064583f, 0, 4.396969f, 9.582971f, 0, 3.8777618f, 10.101338f, 0, 3.3582404f,
    3.3582404f, 12.565385f, -11.138023f, 2.838231f, 11.907047f, -11.656344f, 2.317406f,
    11.113889f, -12.174655f, 1.7950549f, 10.154364f, -12.692955f, 1.2692956f, 8.975275f,
    -13.2112465f, 0.7328281f, 10.619688f, 0, 2.838231f, 11.138023f, 0, 2.317406f, 11.656344f, 0,
    1.7950549f, 12.174655f, 0, 1.2692956f, 12.692955f, 0, 0.7328281f, 13.2112465f, 7.4734097f,
    -13.72953f, 0, 5.3851647f, -14.247807f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 13.72953f, 0,
    0, 14.247807f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -15.247951f, 0, 0, -14.73092f, 5.5677643f,
    0.7310833f, -14.213883f, 7.737058f, 1.2662734f, -13.696841f, 9.305171f, 1.790781f,
    -13.179791f, 10.543833f, 2.3118882f, -15.247951f, 0, 0, -14.73092f, 0, 0, -14.213883f,
    -0.7310833f, 0, -13.696841f, -1.2662734f, 0, -13.179791f, -1.790781f, 0, -12.662734f,
    -12.662734f, 11.559442f, 2.8314734f, -12.145668f, 12.406895f, 3.3502445f, -11.628592f,
    13.11882f, 3.868529f, -11.111504f, 13.716338f, 4.3865f, -10.594403f, 14.213883f, 4.904256f,
    -10.077288f, -2.3118882f, 0, -12.145668f, -2.8314734f, 0, -11.628592f, -3.3502445f, 0,
    -11.111504f, -3.868529f, 0, -10.594403f, -4.3865f, 0, -10.077288f, -4.904256f, 14.621666f,
    5.421859f, -9.560154f, 14.947033f, 5.9393487f, -9.043001f, 15.195281f, 6.456753f, -8.525823f,
    15.370146f, 6.97409f, -11.325893f, 15.474116f, 0, 10.594403f, 15.508618f, 0, -9.560154f,
    -5.421859f, 0, -9.043001f, -5.9393487f, 0, -8.525823f, -6.456753f, 0, 0, -6.97409f, 0,
    10.594403f, 0, 0, -11.325893f, 6.97409f, 15.474116f, -8.525823f, 6.456753f, 15.370146f,
    -9.043001f, 5.9393487f, 15.195281f, -9.560154f, 5.421859f, 14.947033f, -10.077288f, 4.904256f,
    14.621666f, -10.594403f, 6.97409f, 0, 0, 6.456753f, 8.525823f, 0, 5.9393487f, 9.043001f, 0,
    5.421859f, 9.560154f, 0, 4.904256f, 10.077288f, 0, 4.3865f, 4.3865f, 14.213883f, -11.111504f,
    3.868529f, 13.716338f, -11.628592f, 3.3502445f, 13.11882f, -12.145668f, 2.8314734f,
    12.406895f, -12.662734f, 2.3118882f, 11.559442f, -13.179791f, 1.790781f, 10.594403f, 0,
    3.868529f, 11.111504f, 0, 3.3502445f, 11.628592f, 0, 2.8314734f, 12.145668f, 0, 2.3118882f,
    12.662734f, 0, 1.790781f, 13.179791f, 10.543833f, -13.696841f, 1.2662734f, 9.305171f,
    -14.213883f, 0.7310833f, 7.737058f, -14.73092f, 0, 5.5677643f, -15.247951f, 0, 0, 0, 0, 0, 0,
    1.2662734f, 13.696841f, 0, 0.7310833f, 14.213883f, 0, 0, 14.73092f, 0, 0, 15.247951f, 0, 0, 0,
    0
};
/* clang-format on */
/* @generated end gradv */
#define SHLI_GRADV_MASK(t) ((__mmask16) * (t))

/* Chunk c (0..5) of band l: r = c1 P[tap 1] + c2 P[tap 2] + Y[k] w, two FMAs and a product
   (P = a_l Y_{l-1}, Y = band l, both band order; w lane j = the per-band vector's component
   (16 c + j) % 3). The taps are SHLI_GRADV_TAP plus ly = 2l on the y lanes (one vector per
   c % 3), so only the coefficients are per band. */
#define SHLI_GRADV_TAPS(c, t, ly)                                                                  \
  _mm512_add_epi32(_mm512_loadu_si512((const void *)(SHLI_GRADV_TAP + 32 * (c) + 16 * (t))), (ly))
/* bands 1..7: P (<= 13 lanes) and Y (<= 15 lanes) in one zmm each */
#define SHLI_GRADV_CHUNK1(c, w, ly)                                                                \
  r = _mm512_fmadd_ps(_mm512_loadu_ps(cf + 32 * (c)),                                              \
                      _mm512_permutexvar_ps(SHLI_GRADV_TAPS(c, 0, ly), p0),                        \
                      _mm512_fmadd_ps(_mm512_loadu_ps(cf + 32 * (c) + 16),                         \
                                      _mm512_permutexvar_ps(SHLI_GRADV_TAPS(c, 1, ly), p0),        \
                                      _mm512_mul_ps(_mm512_permutexvar_ps(iy##c, q0), (w))))
/* bands 8..15: two zmm each */
#define SHLI_GRADV_CHUNK2(c, w, ly)                                                                \
  r = _mm512_fmadd_ps(_mm512_loadu_ps(cf + 32 * (c)),                                              \
                      _mm512_permutex2var_ps(p0, SHLI_GRADV_TAPS(c, 0, ly), p1),                   \
                      _mm512_fmadd_ps(_mm512_loadu_ps(cf + 32 * (c) + 16),                         \
                                      _mm512_permutex2var_ps(p0, SHLI_GRADV_TAPS(c, 1, ly), p1),   \
                                      _mm512_mul_ps(_mm512_permutex2var_ps(q0, iy##c, q1), (w))))
#define SHLI_GRADV_STORE(c)                                                                        \
  if (nc == (c) + 1) {                                                                             \
    _mm512_mask_storeu_ps(ol + 16 * (c), SHLI_GRADV_MASK(SHLI_GRADV_LASTM + l), r);                \
    break;                                                                                         \
  }                                                                                                \
  _mm512_storeu_ps(ol + 16 * (c), r)
/* per band: w lanes for chunks c % 3 == 0, 1, 2 (b u + e v; vK lane j = v[(K + j) % 3]), and 2l
   on the y lanes */
#define SHLI_GRADV_BAND(l, b, e)                                                                   \
  w0 = _mm512_mul_ps(_mm512_set1_ps(b), u0);                                                       \
  w1 = _mm512_mul_ps(_mm512_set1_ps(b), u1);                                                       \
  w2 = _mm512_mul_ps(_mm512_set1_ps(b), u2);                                                       \
  if (v3) {                                                                                        \
    w0 = _mm512_fmadd_ps(_mm512_set1_ps(e), s0, w0);                                               \
    w1 = _mm512_fmadd_ps(_mm512_set1_ps(e), s1, w1);                                               \
    w2 = _mm512_fmadd_ps(_mm512_set1_ps(e), s2, w2);                                               \
  }                                                                                                \
  ly0 = _mm512_maskz_set1_epi32((__mmask16)0x2492, 2 * (l));                                       \
  ly1 = _mm512_maskz_set1_epi32((__mmask16)0x9249, 2 * (l));                                       \
  ly2 = _mm512_maskz_set1_epi32((__mmask16)0x4924, 2 * (l))
/* lane j = (a, b, c)[j % 3] */
#define SHLI_GRADV_AOS(a, b, c)                                                                    \
  _mm512_mask_blend_ps((__mmask16)0x4924, _mm512_mask_blend_ps((__mmask16)0x2492, (a), (b)), (c))

/* AVX-512 gradient pass for 1..16 bands (C only), with optional per-band weights: from Y (y,
   n * n floats) at the unit direction u = (nx, ny, nz), for coefficient i of band l
     out_grad[i] = a_l grad H_l^m(u) + (b_l u + e_l v) Y_i
   (H_l the solid harmonic |d|^l Y_l; its Cartesian derivatives are at most two terms of band
   l-1, tables by tools/gen_grad_simd.py). bw == NULL: a_l = ir, b_l = -l ir, e_l = 0, the
   gradient of Y(d / |d|) with ir = 1 / |d|, and out_y is not written. Otherwise bw[4 l ..] =
   (kv_l, a_l, b_l, e_l), v = v3 (3 floats; NULL: e_l = 0) and out_y[i] = kv_l Y_i: the light
   kernels' weights, at no cost per output (out_y may be y, but from band 8 each band's load
   then waits on the previous band's store: the lights pass a copy). Lanes follow the output
   array, so each 16-float chunk of the AoS gradient is three permutes, two FMAs and a
   product. */
SHLIGHT_CPU_INLINE void shli_sh_grad_avx512(int n, const float *y, float nx, float ny, float nz,
                                            float ir, const float *bw, const float *v3,
                                            float *out_y, float (*out_grad)[3]) {
  float *o = &out_grad[0][0];
  __m512 vx = _mm512_set1_ps(nx), vy = _mm512_set1_ps(ny), vz = _mm512_set1_ps(nz);
  __m512 u0, u1, u2, s0, s1, s2, w0, w1, w2, p0, p1, q0, q1, r, yp0, yp1, av;
  __m512 yb[8];
  __m512i ly0, ly1, ly2;
  __m512i iy0 = _mm512_loadu_si512((const void *)(SHLI_GRADV_IY));
  __m512i iy1 = _mm512_loadu_si512((const void *)(SHLI_GRADV_IY + 16));
  __m512i iy2 = _mm512_loadu_si512((const void *)(SHLI_GRADV_IY + 32));
  __m512i iy3, iy4, iy5;
  float y0 = y[0];
  int l, nc, l1 = n < 8 ? n : 8;
  /* bands 1..7 of Y before the first store: a load whose address matches an earlier store's
     modulo 4096 waits for it (out_grad 32 KiB after y, one build of the bench: n = 10 80 -> 102
     ns; with these loads first 80.6); bands 8..15 (two zmm each) would spill */
  SHLI_UNROLL_BANDS
  for (l = 0; l < 8; ++l) {
    yb[l] = _mm512_setzero_ps();
    if (l > 0 && l < n) {
      yb[l] = _mm512_maskz_loadu_ps(SHLI_GRADV_MASK(SHLI_GRADV_YM + 2 * l), y + l * l);
    }
  }
  u0 = SHLI_GRADV_AOS(vx, vy, vz);
  u1 = SHLI_GRADV_AOS(vy, vz, vx);
  u2 = SHLI_GRADV_AOS(vz, vx, vy);
  s0 = s1 = s2 = _mm512_setzero_ps();
  if (v3) {
    __m512 gx = _mm512_set1_ps(v3[0]), gy = _mm512_set1_ps(v3[1]), gz = _mm512_set1_ps(v3[2]);
    s0 = SHLI_GRADV_AOS(gx, gy, gz);
    s1 = SHLI_GRADV_AOS(gy, gz, gx);
    s2 = SHLI_GRADV_AOS(gz, gx, gy);
  }
  /* band 0: (b_0 u + e_0 v) Y_0 */
  if (bw) {
    o[0] = (bw[2] * nx + (v3 ? bw[3] * v3[0] : 0.0f)) * y0;
    o[1] = (bw[2] * ny + (v3 ? bw[3] * v3[1] : 0.0f)) * y0;
    o[2] = (bw[2] * nz + (v3 ? bw[3] * v3[2] : 0.0f)) * y0;
    out_y[0] = bw[0] * y0;
  } else {
    o[0] = 0.0f;
    o[1] = 0.0f;
    o[2] = 0.0f;
  }
  yp0 = _mm512_maskz_mov_ps((__mmask16)1, _mm512_set1_ps(y0));
  yp1 = _mm512_setzero_ps();
  av = _mm512_set1_ps(ir);
  SHLI_UNROLL_BANDS
  for (l = 1; l < l1; ++l) {
    const float *cf = SHLI_GRADV_COEF + 32 * SHLI_GRADV_CH0[l];
    float *ol = o + 3 * l * l;
    q0 = yb[l];
    if (bw) {
      av = _mm512_set1_ps(bw[4 * l + 1]);
      SHLI_GRADV_BAND(l, bw[4 * l + 2], bw[4 * l + 3]);
      _mm512_mask_storeu_ps(out_y + l * l, SHLI_GRADV_MASK(SHLI_GRADV_YM + 2 * l),
                            _mm512_mul_ps(q0, _mm512_set1_ps(bw[4 * l])));
    } else {
      SHLI_GRADV_BAND(l, -SHLI_GRADV_LF[l] * ir, 0.0f);
    }
    p0 = _mm512_mul_ps(yp0, av);
    nc = SHLI_GRADV_CH0[l + 1] - SHLI_GRADV_CH0[l];
    do {
      SHLI_GRADV_CHUNK1(0, w0, ly0);
      SHLI_GRADV_STORE(0);
      SHLI_GRADV_CHUNK1(1, w1, ly1);
      SHLI_GRADV_STORE(1);
      SHLI_GRADV_CHUNK1(2, w2, ly2);
      _mm512_mask_storeu_ps(ol + 32, SHLI_GRADV_MASK(SHLI_GRADV_LASTM + l), r);
    } while (0);
    yp0 = q0;
  }
  if (n <= 8) {
    return;
  }
  iy3 = _mm512_loadu_si512((const void *)(SHLI_GRADV_IY + 48));
  iy4 = _mm512_loadu_si512((const void *)(SHLI_GRADV_IY + 64));
  iy5 = _mm512_loadu_si512((const void *)(SHLI_GRADV_IY + 80));
  SHLI_UNROLL_BANDS
  for (l = 8; l < n; ++l) {
    const float *cf = SHLI_GRADV_COEF + 32 * SHLI_GRADV_CH0[l];
    float *ol = o + 3 * l * l;
    q0 = _mm512_maskz_loadu_ps(SHLI_GRADV_MASK(SHLI_GRADV_YM + 2 * l), y + l * l);
    q1 = _mm512_maskz_loadu_ps(SHLI_GRADV_MASK(SHLI_GRADV_YM + 2 * l + 1), y + l * l + 16);
    if (bw) {
      __m512 kv = _mm512_set1_ps(bw[4 * l]);
      av = _mm512_set1_ps(bw[4 * l + 1]);
      SHLI_GRADV_BAND(l, bw[4 * l + 2], bw[4 * l + 3]);
      _mm512_storeu_ps(out_y + l * l, _mm512_mul_ps(q0, kv));
      _mm512_mask_storeu_ps(out_y + l * l + 16, SHLI_GRADV_MASK(SHLI_GRADV_YM + 2 * l + 1),
                            _mm512_mul_ps(q1, kv));
    } else {
      SHLI_GRADV_BAND(l, -SHLI_GRADV_LF[l] * ir, 0.0f);
    }
    p0 = _mm512_mul_ps(yp0, av);
    p1 = _mm512_mul_ps(yp1, av);
    nc = SHLI_GRADV_CH0[l + 1] - SHLI_GRADV_CH0[l];
    do {
      SHLI_GRADV_CHUNK2(0, w0, ly0);
      _mm512_storeu_ps(ol, r);
      SHLI_GRADV_CHUNK2(1, w1, ly1);
      _mm512_storeu_ps(ol + 16, r);
      SHLI_GRADV_CHUNK2(2, w2, ly2);
      _mm512_storeu_ps(ol + 32, r);
      SHLI_GRADV_CHUNK2(3, w0, ly0);
      SHLI_GRADV_STORE(3);
      SHLI_GRADV_CHUNK2(4, w1, ly1);
      SHLI_GRADV_STORE(4);
      SHLI_GRADV_CHUNK2(5, w2, ly2);
      _mm512_mask_storeu_ps(ol + 80, SHLI_GRADV_MASK(SHLI_GRADV_LASTM + l), r);
    } while (0);
    yp0 = q0;
    yp1 = q1;
  }
}

#undef SHLI_GRADV_CHUNK1
#undef SHLI_GRADV_TAPS
#undef SHLI_GRADV_BAND
#undef SHLI_GRADV_AOS
#undef SHLI_GRADV_CHUNK2
#undef SHLI_GRADV_STORE

#else
#define SHLIGHT_SIMD_EVAL 0
#endif

/* Large band counts run out of line in C: a file that includes shlight.h carries the small
   Horner forms only and calls the implementation (SHLIGHT_IMPLEMENTATION) for n > 6. */
#define SHLIGHT_OUTLINE_EVAL 1
SHLIGHT_API void shli_sh_eval_outline(int n, float dx, float dy, float dz, float *out_y);

/* Y_i at the unit direction (dx, dy, dz) for n > 6: the across-m SIMD cores with AVX-512,
   otherwise the double Reinsch-form core (C calls it out of line: shli_sh_eval_outline). */
SHLIGHT_INLINE void shli_sh_eval_big(int n, float dx, float dy, float dz, float *out_y) {
  shli_real x = SHLIGHT_REAL(dx);
  shli_real y = SHLIGHT_REAL(dy);
  shli_real z = SHLIGHT_REAL(dz);
  shli_real e;
  shli_real k;
  shli_real az;
  float sg;
#if SHLIGHT_SIMD_EVAL
  if (n <= SHLIGHT_UNROLLED_BANDS) {
#ifdef __AVX512VL__
    shli_sh_eval_avx512_16y(n, dx, dy, dz, out_y);
#else
    shli_sh_eval_avx512_16(n, dx, dy, dz, out_y);
#endif
  } else {
    shli_sh_eval_avx512(n, dx, dy, dz, out_y);
  }
  return;
#endif
  e = x * x + y * y + z * z - 1.0;
  k = 1.0 + e * (-0.5 + 0.375 * e);
  x = x * k;
  y = y * k;
  z = z * k;
  az = SHLIGHT_ABSR(z);
  sg = SHLIGHT_SIGN1(z);
  shli_sh_core(n, x, y, z, (x * x + y * y) / (1.0 + az), sg, out_y);
}

/* Y_i at a unit direction (dx, dy, dz) for n = 1..6: float Horner forms, n = 4..6 across the
   outputs with AVX-512VL. */
SHLIGHT_INLINE void shli_sh_eval_small(int n, float dx, float dy, float dz, float *out_y) {
#if SHLIGHT_SIMD_EVAL
#ifdef __AVX512VL__
  if (n >= 4 && n <= 6) {
    /* n^2 scalar stores bound the Horner form (bench, ratio to the loop, scalar / lanes:
       n = 3 0.37-0.49 / 0.55, 4 0.44 / 0.35, 5 0.49 / 0.45, 6 0.49 / 0.37) */
    shli_sh_eval_avx512_poly(n, dx, dy, dz, out_y);
    return;
  }
#endif
#endif
  switch (n) {
  /* up to 6 bands, float Horner forms straight from d are within the targets (docs/accuracy.md): no
     normalisation, no division, no double */
  case 1:
    shli_sh_poly_1(dx, dy, dz, out_y);
    return;
#if SHLIGHT_MAX_BANDS >= 2
  case 2:
    shli_sh_poly_2(dx, dy, dz, out_y);
    return;
#endif
#if SHLIGHT_MAX_BANDS >= 3
  case 3:
    shli_sh_poly_3(dx, dy, dz, out_y);
    return;
#endif
#if SHLIGHT_MAX_BANDS >= 4
  case 4:
    shli_sh_poly_4(dx, dy, dz, out_y);
    return;
#endif
#if SHLIGHT_MAX_BANDS >= 5
  case 5:
    shli_sh_poly_5(dx, dy, dz, out_y);
    return;
#endif
#if SHLIGHT_MAX_BANDS >= 6
  case 6:
    shli_sh_poly_6(dx, dy, dz, out_y);
    return;
#endif
  default:
    break;
  }
}

/* Y_i at the direction (dx, dy, dz), any d (the contract of shl_sh_eval), n in 1..max. */
SHLIGHT_INLINE void shli_sh_eval_any(int n, float dx, float dy, float dz, float *out_y) {
  float q = dx * dx + dy * dy + dz * dz;
  shli_real x;
  shli_real y;
  shli_real z;
  shli_real r;
  if (!(SHLIGHT_ABSF(q - 1.0f) <= 1.0e-6f)) {
    /* not unit to float precision (|d|^2 of a float-normalised d is within 4e-7 of 1): zero,
       NaN or infinite d becomes (0, 0, 1), any other d is normalised (scaled by its largest
       component first, so denormal and huge d work) */
    x = SHLIGHT_ABSR(SHLIGHT_REAL(dx));
    y = SHLIGHT_ABSR(SHLIGHT_REAL(dy));
    z = SHLIGHT_ABSR(SHLIGHT_REAL(dz));
    r = SHLIGHT_MAXR(x, SHLIGHT_MAXR(y, z));
    if (!(x + y + z > 0.0 && r <= SHLIGHT_REAL_MAX)) {
      dx = 0.0f;
      dy = 0.0f;
      dz = 1.0f;
    } else {
      x = SHLIGHT_REAL(dx) / r;
      y = SHLIGHT_REAL(dy) / r;
      z = SHLIGHT_REAL(dz) / r;
      r = SHLIGHT_SQRTR(x * x + y * y + z * z);
      dx = SHLIGHT_FLOAT(x / r);
      dy = SHLIGHT_FLOAT(y / r);
      dz = SHLIGHT_FLOAT(z / r);
    }
  }
  if (n <= 6) {
    shli_sh_eval_small(n, dx, dy, dz, out_y);
  } else {
    shli_sh_eval_big(n, dx, dy, dz, out_y);
  }
}

/* Y_i at the direction (dx, dy, dz): the one evaluation path of shl_sh_eval and
   shl_sh_eval_grad. In C, a unit d with n <= 6 runs inline and everything else out of line
   (shli_sh_eval_outline, the implementation's shli_sh_eval_any). */
SHLIGHT_INLINE void shli_sh_eval_xyz(int n, float dx, float dy, float dz, float *out_y) {
  n = shli_bands(n);
  if (n < 1) {
    return;
  }
#if SHLIGHT_OUTLINE_EVAL
  if (n <= 6 && SHLIGHT_ABSF(dx * dx + dy * dy + dz * dz - 1.0f) <= 1.0e-6f) {
    shli_sh_eval_small(n, dx, dy, dz, out_y);
    return;
  }
  shli_sh_eval_outline(n, dx, dy, dz, out_y);
#else
  shli_sh_eval_any(n, dx, dy, dz, out_y);
#endif
}

SHLIGHT_INLINE void shl_sh_eval(int n, const float d[3], float *out_y) {
  shli_sh_eval_xyz(n, d[0], d[1], d[2], out_y);
}

/* >>gradient --------------------------------------------------------------------------------
   Cartesian gradient of Y_i(d / |d|) with respect to d, pole-free: with H_l the solid
   harmonic (|d|^l Y_l), grad Y_l = (grad H_l(u) - l Y_l(u) u) / |d| at u = d / |d|, and each
   Cartesian derivative of H_l^m is at most two terms of band l-1 (tools/gen_basis.py derives
   and checks them). No division by sin(theta) anywhere. */

/* Run-time loop of the gradient for n > SHLIGHT_UNROLLED_BANDS (C only): coefficients A, B, C
   of band l computed on the way (three square roots in double per order m, no table); every
   output times ib (see shli_sh_grad). */
SHLIGHT_CPU_INLINE void shli_sh_grad_loop(int n, const float *y, float nx, float ny, float nz,
                                          float ir, float ib, float (*out_grad)[3]) {
  int l;
  int m;
  double f;
  int b;
  int p;
  float lr;
  float q;
  float ca;
  float cb;
  float cc;
  float ap;
  float bp;
  float gx;
  float gy;
  float gz;
  out_grad[0][0] = 0.0f;
  out_grad[0][1] = 0.0f;
  out_grad[0][2] = 0.0f;
  for (l = 1; l < n; ++l) {
    lr = SHLIGHT_ITOF(l) * ir;
    b = l * (l + 1);
    p = (l - 1) * l;
    for (m = 0; m <= l; ++m) {
      f = (double)(2 * l + 1) / (double)(2 * l - 1);
      ca = m >= 1 ? (float)(-0.5 * sqrt(f * (double)(l + m) * (double)(l + m - 1))) : 0.0f;
      cb = m + 1 < l ? (float)(0.5 * sqrt(f * (double)(l - m) * (double)(l - m - 1))) : 0.0f;
      cc = (float)sqrt(f * (double)(l - m) * (double)(l + m));
      ap = m == 1 ? ca * 1.41421356f : ca;
      bp = m == 0 ? cb * 1.41421356f : cb;
      /* cosine type, index b + m */
      gx = 0.0f;
      gy = 0.0f;
      gz = 0.0f;
      if (m >= 1) {
        gx = gx + ap * y[p + m - 1];
      }
      if (m >= 2) {
        gy = gy - ca * y[p - m + 1];
      }
      if (m + 1 <= l - 1) {
        gx = gx + bp * y[p + m + 1];
        gy = gy + bp * y[p - m - 1];
      }
      if (m <= l - 1) {
        gz = cc * y[p + m];
      }
      q = lr * y[b + m];
      out_grad[b + m][0] = (gx * ir - q * nx) * ib;
      out_grad[b + m][1] = (gy * ir - q * ny) * ib;
      out_grad[b + m][2] = (gz * ir - q * nz) * ib;
      if (m >= 1) {
        /* sine type, index b - m */
        gx = 0.0f;
        gy = ap * y[p + m - 1];
        gz = 0.0f;
        if (m >= 2) {
          gx = gx + ca * y[p - m + 1];
        }
        if (m + 1 <= l - 1) {
          gx = gx + cb * y[p - m - 1];
          gy = gy - cb * y[p + m + 1];
        }
        if (m <= l - 1) {
          gz = cc * y[p - m];
        }
        q = lr * y[b - m];
        out_grad[b - m][0] = (gx * ir - q * nx) * ib;
        out_grad[b - m][1] = (gy * ir - q * ny) * ib;
        out_grad[b - m][2] = (gz * ir - q * nz) * ib;
      }
    }
  }
}

/* @generated begin gradient */
SHLIGHT_INLINE void shli_sh_grad(int n, const float *y, float nx, float ny, float nz, float ir,
                                 float ib, float (*out_grad)[3]) {
  float r[29];
  float lr;
  float q;
#if SHLIGHT_MAX_BANDS > SHLIGHT_UNROLLED_BANDS
  if (n > SHLIGHT_UNROLLED_BANDS) {
    shli_sh_grad_loop(n, y, nx, ny, nz, ir, ib, out_grad);
    return;
  }
#endif
  lr = 0.0f;
  q = 0.0f;
  SHLIGHT_SET3(out_grad[0], 0.0f, 0.0f, 0.0f);
#if SHLIGHT_MAX_BANDS > 1
  if (n > 1) {
    lr = 1.0f * ir;
    r[0] = y[0] * ir;
    q = lr * y[1];
    SHLIGHT_SET3(out_grad[1], -q * nx * ib, (-1.73205081f * r[0] - q * ny) * ib, -q * nz * ib);
    q = lr * y[2];
    SHLIGHT_SET3(out_grad[2], -q * nx * ib, -q * ny * ib, (1.73205081f * r[0] - q * nz) * ib);
    q = lr * y[3];
    SHLIGHT_SET3(out_grad[3], (-1.73205081f * r[0] - q * nx) * ib, -q * ny * ib, -q * nz * ib);
  }
#endif
#if SHLIGHT_MAX_BANDS > 2
  if (n > 2) {
    lr = 2.0f * ir;
    r[0] = y[1] * ir;
    r[1] = y[2] * ir;
    r[2] = y[3] * ir;
    q = lr * y[4];
    SHLIGHT_SET3(out_grad[4], (-2.23606798f * r[0] - q * nx) * ib,
                 (-2.23606798f * r[2] - q * ny) * ib, -q * nz * ib);
    q = lr * y[5];
    SHLIGHT_SET3(out_grad[5], -q * nx * ib, (-2.23606798f * r[1] - q * ny) * ib,
                 (2.23606798f * r[0] - q * nz) * ib);
    q = lr * y[6];
    SHLIGHT_SET3(out_grad[6], (1.29099445f * r[2] - q * nx) * ib,
                 (1.29099445f * r[0] - q * ny) * ib, (2.5819889f * r[1] - q * nz) * ib);
    q = lr * y[7];
    SHLIGHT_SET3(out_grad[7], (-2.23606798f * r[1] - q * nx) * ib, -q * ny * ib,
                 (2.23606798f * r[2] - q * nz) * ib);
    q = lr * y[8];
    SHLIGHT_SET3(out_grad[8], (-2.23606798f * r[2] - q * nx) * ib,
                 (2.23606798f * r[0] - q * ny) * ib, -q * nz * ib);
  }
#endif
#if SHLIGHT_MAX_BANDS > 3
  if (n > 3) {
    lr = 3.0f * ir;
    r[0] = y[4] * ir;
    r[1] = y[5] * ir;
    r[2] = y[6] * ir;
    r[3] = y[7] * ir;
    r[4] = y[8] * ir;
    q = lr * y[9];
    SHLIGHT_SET3(out_grad[9], (-3.24037035f * r[0] - q * nx) * ib,
                 (-3.24037035f * r[4] - q * ny) * ib, -q * nz * ib);
    q = lr * y[10];
    SHLIGHT_SET3(out_grad[10], (-2.64575131f * r[1] - q * nx) * ib,
                 (-2.64575131f * r[3] - q * ny) * ib, (2.64575131f * r[0] - q * nz) * ib);
    q = lr * y[11];
    SHLIGHT_SET3(out_grad[11], (0.836660027f * r[0] - q * nx) * ib,
                 (-2.89827535f * r[2] + -0.836660027f * r[4] - q * ny) * ib,
                 (3.34664011f * r[1] - q * nz) * ib);
    q = lr * y[12];
    SHLIGHT_SET3(out_grad[12], (2.04939015f * r[3] - q * nx) * ib,
                 (2.04939015f * r[1] - q * ny) * ib, (3.54964787f * r[2] - q * nz) * ib);
    q = lr * y[13];
    SHLIGHT_SET3(out_grad[13], (-2.89827535f * r[2] + 0.836660027f * r[4] - q * nx) * ib,
                 (0.836660027f * r[0] - q * ny) * ib, (3.34664011f * r[3] - q * nz) * ib);
    q = lr * y[14];
    SHLIGHT_SET3(out_grad[14], (-2.64575131f * r[3] - q * nx) * ib,
                 (2.64575131f * r[1] - q * ny) * ib, (2.64575131f * r[4] - q * nz) * ib);
    q = lr * y[15];
    SHLIGHT_SET3(out_grad[15], (-3.24037035f * r[4] - q * nx) * ib,
                 (3.24037035f * r[0] - q * ny) * ib, -q * nz * ib);
  }
#endif
#if SHLIGHT_MAX_BANDS > 4
  if (n > 4) {
    lr = 4.0f * ir;
    r[0] = y[9] * ir;
    r[1] = y[10] * ir;
    r[2] = y[11] * ir;
    r[3] = y[12] * ir;
    r[4] = y[13] * ir;
    r[5] = y[14] * ir;
    r[6] = y[15] * ir;
    q = lr * y[16];
    SHLIGHT_SET3(out_grad[16], (-4.24264069f * r[0] - q * nx) * ib,
                 (-4.24264069f * r[6] - q * ny) * ib, -q * nz * ib);
    q = lr * y[17];
    SHLIGHT_SET3(out_grad[17], (-3.67423461f * r[1] - q * nx) * ib,
                 (-3.67423461f * r[5] - q * ny) * ib, (3.0f * r[0] - q * nz) * ib);
    q = lr * y[18];
    SHLIGHT_SET3(out_grad[18], (-3.10529502f * r[2] + 0.801783726f * r[0] - q * nx) * ib,
                 (-3.10529502f * r[4] + -0.801783726f * r[6] - q * ny) * ib,
                 (3.92792202f * r[1] - q * nz) * ib);
    q = lr * y[19];
    SHLIGHT_SET3(out_grad[19], (1.38873015f * r[1] - q * nx) * ib,
                 (-3.58568583f * r[3] + -1.38873015f * r[5] - q * ny) * ib,
                 (4.39155033f * r[2] - q * nz) * ib);
    q = lr * y[20];
    SHLIGHT_SET3(out_grad[20], (2.7774603f * r[4] - q * nx) * ib, (2.7774603f * r[2] - q * ny) * ib,
                 (4.53557368f * r[3] - q * nz) * ib);
    q = lr * y[21];
    SHLIGHT_SET3(out_grad[21], (-3.58568583f * r[3] + 1.38873015f * r[5] - q * nx) * ib,
                 (1.38873015f * r[1] - q * ny) * ib, (4.39155033f * r[4] - q * nz) * ib);
    q = lr * y[22];
    SHLIGHT_SET3(out_grad[22], (-3.10529502f * r[4] + 0.801783726f * r[6] - q * nx) * ib,
                 (3.10529502f * r[2] + 0.801783726f * r[0] - q * ny) * ib,
                 (3.92792202f * r[5] - q * nz) * ib);
    q = lr * y[23];
    SHLIGHT_SET3(out_grad[23], (-3.67423461f * r[5] - q * nx) * ib,
                 (3.67423461f * r[1] - q * ny) * ib, (3.0f * r[6] - q * nz) * ib);
    q = lr * y[24];
    SHLIGHT_SET3(out_grad[24], (-4.24264069f * r[6] - q * nx) * ib,
                 (4.24264069f * r[0] - q * ny) * ib, -q * nz * ib);
  }
#endif
#if SHLIGHT_MAX_BANDS > 5
  if (n > 5) {
    lr = 5.0f * ir;
    r[0] = y[16] * ir;
    r[1] = y[17] * ir;
    r[2] = y[18] * ir;
    r[3] = y[19] * ir;
    r[4] = y[20] * ir;
    r[5] = y[21] * ir;
    r[6] = y[22] * ir;
    r[7] = y[23] * ir;
    r[8] = y[24] * ir;
    q = lr * y[25];
    SHLIGHT_SET3(out_grad[25], (-5.24404424f * r[0] - q * nx) * ib,
                 (-5.24404424f * r[8] - q * ny) * ib, -q * nz * ib);
    q = lr * y[26];
    SHLIGHT_SET3(out_grad[26], (-4.69041576f * r[1] - q * nx) * ib,
                 (-4.69041576f * r[7] - q * ny) * ib, (3.31662479f * r[0] - q * nz) * ib);
    q = lr * y[27];
    SHLIGHT_SET3(out_grad[27], (-4.13655788f * r[2] + 0.78173596f * r[0] - q * nx) * ib,
                 (-4.13655788f * r[6] + -0.78173596f * r[8] - q * ny) * ib,
                 (4.42216639f * r[1] - q * nz) * ib);
    q = lr * y[28];
    SHLIGHT_SET3(out_grad[28], (-3.58236421f * r[3] + 1.3540064f * r[1] - q * nx) * ib,
                 (-3.58236421f * r[5] + -1.3540064f * r[7] - q * ny) * ib,
                 (5.06622805f * r[2] - q * nz) * ib);
    q = lr * y[29];
    SHLIGHT_SET3(out_grad[29], (1.91485422f * r[2] - q * nx) * ib,
                 (-4.28174419f * r[4] + -1.91485422f * r[6] - q * ny) * ib,
                 (5.4160256f * r[3] - q * nz) * ib);
    q = lr * y[30];
    SHLIGHT_SET3(out_grad[30], (3.49602949f * r[5] - q * nx) * ib,
                 (3.49602949f * r[3] - q * ny) * ib, (5.52770798f * r[4] - q * nz) * ib);
    q = lr * y[31];
    SHLIGHT_SET3(out_grad[31], (-4.28174419f * r[4] + 1.91485422f * r[6] - q * nx) * ib,
                 (1.91485422f * r[2] - q * ny) * ib, (5.4160256f * r[5] - q * nz) * ib);
    q = lr * y[32];
    SHLIGHT_SET3(out_grad[32], (-3.58236421f * r[5] + 1.3540064f * r[7] - q * nx) * ib,
                 (3.58236421f * r[3] + 1.3540064f * r[1] - q * ny) * ib,
                 (5.06622805f * r[6] - q * nz) * ib);
    q = lr * y[33];
    SHLIGHT_SET3(out_grad[33], (-4.13655788f * r[6] + 0.78173596f * r[8] - q * nx) * ib,
                 (4.13655788f * r[2] + 0.78173596f * r[0] - q * ny) * ib,
                 (4.42216639f * r[7] - q * nz) * ib);
    q = lr * y[34];
    SHLIGHT_SET3(out_grad[34], (-4.69041576f * r[7] - q * nx) * ib,
                 (4.69041576f * r[1] - q * ny) * ib, (3.31662479f * r[8] - q * nz) * ib);
    q = lr * y[35];
    SHLIGHT_SET3(out_grad[35], (-5.24404424f * r[8] - q * nx) * ib,
                 (5.24404424f * r[0] - q * ny) * ib, -q * nz * ib);
  }
#endif
#if SHLIGHT_MAX_BANDS > 6
  if (n > 6) {
    lr = 6.0f * ir;
    r[0] = y[25] * ir;
    r[1] = y[26] * ir;
    r[2] = y[27] * ir;
    r[3] = y[28] * ir;
    r[4] = y[29] * ir;
    r[5] = y[30] * ir;
    r[6] = y[31] * ir;
    r[7] = y[32] * ir;
    r[8] = y[33] * ir;
    r[9] = y[34] * ir;
    r[10] = y[35] * ir;
    q = lr * y[36];
    SHLIGHT_SET3(out_grad[36], (-6.244998f * r[0] - q * nx) * ib,
                 (-6.244998f * r[10] - q * ny) * ib, -q * nz * ib);
    q = lr * y[37];
    SHLIGHT_SET3(out_grad[37], (-5.70087713f * r[1] - q * nx) * ib,
                 (-5.70087713f * r[9] - q * ny) * ib, (3.60555128f * r[0] - q * nz) * ib);
    q = lr * y[38];
    SHLIGHT_SET3(out_grad[38], (-5.15663738f * r[2] + 0.768706115f * r[0] - q * nx) * ib,
                 (-5.15663738f * r[8] + -0.768706115f * r[10] - q * ny) * ib,
                 (4.86172435f * r[1] - q * nz) * ib);
    q = lr * y[39];
    SHLIGHT_SET3(out_grad[39], (-4.61223669f * r[3] + 1.33143805f * r[1] - q * nx) * ib,
                 (-4.61223669f * r[7] + -1.33143805f * r[9] - q * ny) * ib,
                 (5.64881323f * r[2] - q * nz) * ib);
    q = lr * y[40];
    SHLIGHT_SET3(out_grad[40], (-4.06761042f * r[4] + 1.88293774f * r[2] - q * nx) * ib,
                 (-4.06761042f * r[6] + -1.88293774f * r[8] - q * ny) * ib,
                 (6.14964892f * r[3] - q * nz) * ib);
    q = lr * y[41];
    SHLIGHT_SET3(out_grad[41], (2.43086217f * r[3] - q * nx) * ib,
                 (-4.981785f * r[5] + -2.43086217f * r[7] - q * ny) * ib,
                 (6.43145678f * r[4] - q * nz) * ib);
    q = lr * y[42];
    SHLIGHT_SET3(out_grad[42], (4.21037679f * r[6] - q * nx) * ib,
                 (4.21037679f * r[4] - q * ny) * ib, (6.52268768f * r[5] - q * nz) * ib);
    q = lr * y[43];
    SHLIGHT_SET3(out_grad[43], (-4.981785f * r[5] + 2.43086217f * r[7] - q * nx) * ib,
                 (2.43086217f * r[3] - q * ny) * ib, (6.43145678f * r[6] - q * nz) * ib);
    q = lr * y[44];
    SHLIGHT_SET3(out_grad[44], (-4.06761042f * r[6] + 1.88293774f * r[8] - q * nx) * ib,
                 (4.06761042f * r[4] + 1.88293774f * r[2] - q * ny) * ib,
                 (6.14964892f * r[7] - q * nz) * ib);
    q = lr * y[45];
    SHLIGHT_SET3(out_grad[45], (-4.61223669f * r[7] + 1.33143805f * r[9] - q * nx) * ib,
                 (4.61223669f * r[3] + 1.33143805f * r[1] - q * ny) * ib,
                 (5.64881323f * r[8] - q * nz) * ib);
    q = lr * y[46];
    SHLIGHT_SET3(out_grad[46], (-5.15663738f * r[8] + 0.768706115f * r[10] - q * nx) * ib,
                 (5.15663738f * r[2] + 0.768706115f * r[0] - q * ny) * ib,
                 (4.86172435f * r[9] - q * nz) * ib);
    q = lr * y[47];
    SHLIGHT_SET3(out_grad[47], (-5.70087713f * r[9] - q * nx) * ib,
                 (5.70087713f * r[1] - q * ny) * ib, (3.60555128f * r[10] - q * nz) * ib);
    q = lr * y[48];
    SHLIGHT_SET3(out_grad[48], (-6.244998f * r[10] - q * nx) * ib, (6.244998f * r[0] - q * ny) * ib,
                 -q * nz * ib);
  }
#endif
#if SHLIGHT_MAX_BANDS > 7
  if (n > 7) {
    lr = 7.0f * ir;
    r[0] = y[36] * ir;
    r[1] = y[37] * ir;
    r[2] = y[38] * ir;
    r[3] = y[39] * ir;
    r[4] = y[40] * ir;
    r[5] = y[41] * ir;
    r[6] = y[42] * ir;
    r[7] = y[43] * ir;
    r[8] = y[44] * ir;
    r[9] = y[45] * ir;
    r[10] = y[46] * ir;
    r[11] = y[47] * ir;
    r[12] = y[48] * ir;
    q = lr * y[49];
    SHLIGHT_SET3(out_grad[49], (-7.24568837f * r[0] - q * nx) * ib,
                 (-7.24568837f * r[12] - q * ny) * ib, -q * nz * ib);
    q = lr * y[50];
    SHLIGHT_SET3(out_grad[50], (-6.70820393f * r[1] - q * nx) * ib,
                 (-6.70820393f * r[11] - q * ny) * ib, (3.87298335f * r[0] - q * nz) * ib);
    q = lr * y[51];
    SHLIGHT_SET3(out_grad[51], (-6.17065013f * r[2] + 0.759554525f * r[0] - q * nx) * ib,
                 (-6.17065013f * r[10] + -0.759554525f * r[12] - q * ny) * ib,
                 (5.26234812f * r[1] - q * nz) * ib);
    q = lr * y[52];
    SHLIGHT_SET3(out_grad[52], (-5.63300712f * r[3] + 1.31558703f * r[1] - q * nx) * ib,
                 (-5.63300712f * r[9] + -1.31558703f * r[11] - q * ny) * ib,
                 (6.17065013f * r[2] - q * nz) * ib);
    q = lr * y[53];
    SHLIGHT_SET3(out_grad[53], (-5.09524665f * r[4] + 1.86052102f * r[2] - q * nx) * ib,
                 (-5.09524665f * r[8] + -1.86052102f * r[10] - q * ny) * ib,
                 (6.7936622f * r[3] - q * nz) * ib);
    q = lr * y[54];
    SHLIGHT_SET3(out_grad[54], (-4.55732715f * r[5] + 2.40192231f * r[3] - q * nx) * ib,
                 (-4.55732715f * r[7] + -2.40192231f * r[9] - q * ny) * ib,
                 (7.20576692f * r[4] - q * nz) * ib);
    q = lr * y[55];
    SHLIGHT_SET3(out_grad[55], (2.94174203f * r[4] - q * nx) * ib,
                 (-5.6839856f * r[6] + -2.94174203f * r[8] - q * ny) * ib,
                 (7.44208408f * r[5] - q * nz) * ib);
    q = lr * y[56];
    SHLIGHT_SET3(out_grad[56], (4.92247592f * r[7] - q * nx) * ib,
                 (4.92247592f * r[5] - q * ny) * ib, (7.51920618f * r[6] - q * nz) * ib);
    q = lr * y[57];
    SHLIGHT_SET3(out_grad[57], (-5.6839856f * r[6] + 2.94174203f * r[8] - q * nx) * ib,
                 (2.94174203f * r[4] - q * ny) * ib, (7.44208408f * r[7] - q * nz) * ib);
    q = lr * y[58];
    SHLIGHT_SET3(out_grad[58], (-4.55732715f * r[7] + 2.40192231f * r[9] - q * nx) * ib,
                 (4.55732715f * r[5] + 2.40192231f * r[3] - q * ny) * ib,
                 (7.20576692f * r[8] - q * nz) * ib);
    q = lr * y[59];
    SHLIGHT_SET3(out_grad[59], (-5.09524665f * r[8] + 1.86052102f * r[10] - q * nx) * ib,
                 (5.09524665f * r[4] + 1.86052102f * r[2] - q * ny) * ib,
                 (6.7936622f * r[9] - q * nz) * ib);
    q = lr * y[60];
    SHLIGHT_SET3(out_grad[60], (-5.63300712f * r[9] + 1.31558703f * r[11] - q * nx) * ib,
                 (5.63300712f * r[3] + 1.31558703f * r[1] - q * ny) * ib,
                 (6.17065013f * r[10] - q * nz) * ib);
    q = lr * y[61];
    SHLIGHT_SET3(out_grad[61], (-6.17065013f * r[10] + 0.759554525f * r[12] - q * nx) * ib,
                 (6.17065013f * r[2] + 0.759554525f * r[0] - q * ny) * ib,
                 (5.26234812f * r[11] - q * nz) * ib);
    q = lr * y[62];
    SHLIGHT_SET3(out_grad[62], (-6.70820393f * r[11] - q * nx) * ib,
                 (6.70820393f * r[1] - q * ny) * ib, (3.87298335f * r[12] - q * nz) * ib);
    q = lr * y[63];
    SHLIGHT_SET3(out_grad[63], (-7.24568837f * r[12] - q * nx) * ib,
                 (7.24568837f * r[0] - q * ny) * ib, -q * nz * ib);
  }
#endif
#if SHLIGHT_MAX_BANDS > 8
  if (n > 8) {
    lr = 8.0f * ir;
    r[0] = y[49] * ir;
    r[1] = y[50] * ir;
    r[2] = y[51] * ir;
    r[3] = y[52] * ir;
    r[4] = y[53] * ir;
    r[5] = y[54] * ir;
    r[6] = y[55] * ir;
    r[7] = y[56] * ir;
    r[8] = y[57] * ir;
    r[9] = y[58] * ir;
    r[10] = y[59] * ir;
    r[11] = y[60] * ir;
    r[12] = y[61] * ir;
    r[13] = y[62] * ir;
    r[14] = y[63] * ir;
    q = lr * y[64];
    SHLIGHT_SET3(out_grad[64], (-8.24621125f * r[0] - q * nx) * ib,
                 (-8.24621125f * r[14] - q * ny) * ib, -q * nz * ib);
    q = lr * y[65];
    SHLIGHT_SET3(out_grad[65], (-7.71362431f * r[1] - q * nx) * ib,
                 (-7.71362431f * r[13] - q * ny) * ib, (4.12310563f * r[0] - q * nz) * ib);
    q = lr * y[66];
    SHLIGHT_SET3(out_grad[66], (-7.18099343f * r[2] + 0.752772653f * r[0] - q * nx) * ib,
                 (-7.18099343f * r[12] + -0.752772653f * r[14] - q * ny) * ib,
                 (5.63323471f * r[1] - q * nz) * ib);
    q = lr * y[67];
    SHLIGHT_SET3(out_grad[67], (-6.64830806f * r[3] + 1.30384048f * r[1] - q * nx) * ib,
                 (-6.64830806f * r[11] + -1.30384048f * r[13] - q * ny) * ib,
                 (6.64830806f * r[2] - q * nz) * ib);
    q = lr * y[68];
    SHLIGHT_SET3(out_grad[68], (-6.11555394f * r[4] + 1.84390889f * r[2] - q * nx) * ib,
                 (-6.11555394f * r[10] + -1.84390889f * r[12] - q * ny) * ib,
                 (7.37563557f * r[3] - q * nz) * ib);
    q = lr * y[69];
    SHLIGHT_SET3(out_grad[69], (-5.58271141f * r[5] + 2.38047614f * r[3] - q * nx) * ib,
                 (-5.58271141f * r[9] + -2.38047614f * r[11] - q * ny) * ib,
                 (7.89514619f * r[4] - q * nz) * ib);
    q = lr * y[70];
    SHLIGHT_SET3(out_grad[70], (-5.04975247f * r[6] + 2.91547595f * r[4] - q * nx) * ib,
                 (-5.04975247f * r[8] + -2.91547595f * r[10] - q * ny) * ib,
                 (8.24621125f * r[5] - q * nz) * ib);
    q = lr * y[71];
    SHLIGHT_SET3(out_grad[71], (3.44963766f * r[5] - q * nx) * ib,
                 (-6.38748777f * r[7] + -3.44963766f * r[9] - q * ny) * ib,
                 (8.44985207f * r[6] - q * nz) * ib);
    q = lr * y[72];
    SHLIGHT_SET3(out_grad[72], (5.63323471f * r[8] - q * nx) * ib,
                 (5.63323471f * r[6] - q * ny) * ib, (8.51665036f * r[7] - q * nz) * ib);
    q = lr * y[73];
    SHLIGHT_SET3(out_grad[73], (-6.38748777f * r[7] + 3.44963766f * r[9] - q * nx) * ib,
                 (3.44963766f * r[5] - q * ny) * ib, (8.44985207f * r[8] - q * nz) * ib);
    q = lr * y[74];
    SHLIGHT_SET3(out_grad[74], (-5.04975247f * r[8] + 2.91547595f * r[10] - q * nx) * ib,
                 (5.04975247f * r[6] + 2.91547595f * r[4] - q * ny) * ib,
                 (8.24621125f * r[9] - q * nz) * ib);
    q = lr * y[75];
    SHLIGHT_SET3(out_grad[75], (-5.58271141f * r[9] + 2.38047614f * r[11] - q * nx) * ib,
                 (5.58271141f * r[5] + 2.38047614f * r[3] - q * ny) * ib,
                 (7.89514619f * r[10] - q * nz) * ib);
    q = lr * y[76];
    SHLIGHT_SET3(out_grad[76], (-6.11555394f * r[10] + 1.84390889f * r[12] - q * nx) * ib,
                 (6.11555394f * r[4] + 1.84390889f * r[2] - q * ny) * ib,
                 (7.37563557f * r[11] - q * nz) * ib);
    q = lr * y[77];
    SHLIGHT_SET3(out_grad[77], (-6.64830806f * r[11] + 1.30384048f * r[13] - q * nx) * ib,
                 (6.64830806f * r[3] + 1.30384048f * r[1] - q * ny) * ib,
                 (6.64830806f * r[12] - q * nz) * ib);
    q = lr * y[78];
    SHLIGHT_SET3(out_grad[78], (-7.18099343f * r[12] + 0.752772653f * r[14] - q * nx) * ib,
                 (7.18099343f * r[2] + 0.752772653f * r[0] - q * ny) * ib,
                 (5.63323471f * r[13] - q * nz) * ib);
    q = lr * y[79];
    SHLIGHT_SET3(out_grad[79], (-7.71362431f * r[13] - q * nx) * ib,
                 (7.71362431f * r[1] - q * ny) * ib, (4.12310563f * r[14] - q * nz) * ib);
    q = lr * y[80];
    SHLIGHT_SET3(out_grad[80], (-8.24621125f * r[14] - q * nx) * ib,
                 (8.24621125f * r[0] - q * ny) * ib, -q * nz * ib);
  }
#endif
#if SHLIGHT_MAX_BANDS > 9
  if (n > 9) {
    lr = 9.0f * ir;
    r[0] = y[64] * ir;
    r[1] = y[65] * ir;
    r[2] = y[66] * ir;
    r[3] = y[67] * ir;
    r[4] = y[68] * ir;
    r[5] = y[69] * ir;
    r[6] = y[70] * ir;
    r[7] = y[71] * ir;
    r[8] = y[72] * ir;
    r[9] = y[73] * ir;
    r[10] = y[74] * ir;
    r[11] = y[75] * ir;
    r[12] = y[76] * ir;
    r[13] = y[77] * ir;
    r[14] = y[78] * ir;
    r[15] = y[79] * ir;
    r[16] = y[80] * ir;
    q = lr * y[81];
    SHLIGHT_SET3(out_grad[81], (-9.246621f * r[0] - q * nx) * ib,
                 (-9.246621f * r[16] - q * ny) * ib, -q * nz * ib);
    q = lr * y[82];
    SHLIGHT_SET3(out_grad[82], (-8.71779789f * r[1] - q * nx) * ib,
                 (-8.71779789f * r[15] - q * ny) * ib, (4.35889894f * r[0] - q * nz) * ib);
    q = lr * y[83];
    SHLIGHT_SET3(out_grad[83], (-8.1889452f * r[2] + 0.747545002f * r[0] - q * nx) * ib,
                 (-8.1889452f * r[14] + -0.747545002f * r[16] - q * ny) * ib,
                 (5.98036001f * r[1] - q * nz) * ib);
    q = lr * y[84];
    SHLIGHT_SET3(out_grad[84], (-7.66005683f * r[3] + 1.29478592f * r[1] - q * nx) * ib,
                 (-7.66005683f * r[13] + -1.29478592f * r[15] - q * ny) * ib,
                 (7.09183458f * r[2] - q * nz) * ib);
    q = lr * y[85];
    SHLIGHT_SET3(out_grad[85], (-7.13112482f * r[4] + 1.83110381f * r[2] - q * nx) * ib,
                 (-7.13112482f * r[12] + -1.83110381f * r[14] - q * ny) * ib,
                 (7.91127267f * r[3] - q * nz) * ib);
    q = lr * y[86];
    SHLIGHT_SET3(out_grad[86], (-6.60213869f * r[5] + 2.36394486f * r[3] - q * nx) * ib,
                 (-6.60213869f * r[11] + -2.36394486f * r[13] - q * ny) * ib,
                 (8.5233244f * r[4] - q * nz) * ib);
    q = lr * y[87];
    SHLIGHT_SET3(out_grad[87], (-6.0730843f * r[6] + 2.89522934f * r[4] - q * nx) * ib,
                 (-6.0730843f * r[10] + -2.89522934f * r[12] - q * ny) * ib,
                 (8.97054002f * r[5] - q * nz) * ib);
    q = lr * y[88];
    SHLIGHT_SET3(out_grad[88], (-5.54394211f * r[7] + 3.42568156f * r[5] - q * nx) * ib,
                 (-5.54394211f * r[9] + -3.42568156f * r[11] - q * ny) * ib,
                 (9.27678951f * r[6] - q * nz) * ib);
    q = lr * y[89];
    SHLIGHT_SET3(out_grad[89], (3.95563634f * r[6] - q * nx) * ib,
                 (-7.09183458f * r[8] + -3.95563634f * r[10] - q * ny) * ib,
                 (9.45577943f * r[7] - q * nz) * ib);
    q = lr * y[90];
    SHLIGHT_SET3(out_grad[90], (6.34312968f * r[9] - q * nx) * ib,
                 (6.34312968f * r[7] - q * ny) * ib, (9.51469452f * r[8] - q * nz) * ib);
    q = lr * y[91];
    SHLIGHT_SET3(out_grad[91], (-7.09183458f * r[8] + 3.95563634f * r[10] - q * nx) * ib,
                 (3.95563634f * r[6] - q * ny) * ib, (9.45577943f * r[9] - q * nz) * ib);
    q = lr * y[92];
    SHLIGHT_SET3(out_grad[92], (-5.54394211f * r[9] + 3.42568156f * r[11] - q * nx) * ib,
                 (5.54394211f * r[7] + 3.42568156f * r[5] - q * ny) * ib,
                 (9.27678951f * r[10] - q * nz) * ib);
    q = lr * y[93];
    SHLIGHT_SET3(out_grad[93], (-6.0730843f * r[10] + 2.89522934f * r[12] - q * nx) * ib,
                 (6.0730843f * r[6] + 2.89522934f * r[4] - q * ny) * ib,
                 (8.97054002f * r[11] - q * nz) * ib);
    q = lr * y[94];
    SHLIGHT_SET3(out_grad[94], (-6.60213869f * r[11] + 2.36394486f * r[13] - q * nx) * ib,
                 (6.60213869f * r[5] + 2.36394486f * r[3] - q * ny) * ib,
                 (8.5233244f * r[12] - q * nz) * ib);
    q = lr * y[95];
    SHLIGHT_SET3(out_grad[95], (-7.13112482f * r[12] + 1.83110381f * r[14] - q * nx) * ib,
                 (7.13112482f * r[4] + 1.83110381f * r[2] - q * ny) * ib,
                 (7.91127267f * r[13] - q * nz) * ib);
    q = lr * y[96];
    SHLIGHT_SET3(out_grad[96], (-7.66005683f * r[13] + 1.29478592f * r[15] - q * nx) * ib,
                 (7.66005683f * r[3] + 1.29478592f * r[1] - q * ny) * ib,
                 (7.09183458f * r[14] - q * nz) * ib);
    q = lr * y[97];
    SHLIGHT_SET3(out_grad[97], (-8.1889452f * r[14] + 0.747545002f * r[16] - q * nx) * ib,
                 (8.1889452f * r[2] + 0.747545002f * r[0] - q * ny) * ib,
                 (5.98036001f * r[15] - q * nz) * ib);
    q = lr * y[98];
    SHLIGHT_SET3(out_grad[98], (-8.71779789f * r[15] - q * nx) * ib,
                 (8.71779789f * r[1] - q * ny) * ib, (4.35889894f * r[16] - q * nz) * ib);
    q = lr * y[99];
    SHLIGHT_SET3(out_grad[99], (-9.246621f * r[16] - q * nx) * ib, (9.246621f * r[0] - q * ny) * ib,
                 -q * nz * ib);
  }
#endif
#if SHLIGHT_MAX_BANDS > 10
  if (n > 10) {
    lr = 10.0f * ir;
    r[0] = y[81] * ir;
    r[1] = y[82] * ir;
    r[2] = y[83] * ir;
    r[3] = y[84] * ir;
    r[4] = y[85] * ir;
    r[5] = y[86] * ir;
    r[6] = y[87] * ir;
    r[7] = y[88] * ir;
    r[8] = y[89] * ir;
    r[9] = y[90] * ir;
    r[10] = y[91] * ir;
    r[11] = y[92] * ir;
    r[12] = y[93] * ir;
    r[13] = y[94] * ir;
    r[14] = y[95] * ir;
    r[15] = y[96] * ir;
    r[16] = y[97] * ir;
    r[17] = y[98] * ir;
    r[18] = y[99] * ir;
    q = lr * y[100];
    SHLIGHT_SET3(out_grad[100], (-10.2469508f * r[0] - q * nx) * ib,
                 (-10.2469508f * r[18] - q * ny) * ib, -q * nz * ib);
    q = lr * y[101];
    SHLIGHT_SET3(out_grad[101], (-9.72111105f * r[1] - q * nx) * ib,
                 (-9.72111105f * r[17] - q * ny) * ib, (4.58257569f * r[0] - q * nz) * ib);
    q = lr * y[102];
    SHLIGHT_SET3(out_grad[102], (-9.19525049f * r[2] + 0.743391942f * r[0] - q * nx) * ib,
                 (-9.19525049f * r[16] + -0.743391942f * r[18] - q * ny) * ib,
                 (6.3078898f * r[1] - q * nz) * ib);
    q = lr * y[103];
    SHLIGHT_SET3(out_grad[103], (-8.6693653f * r[3] + 1.28759261f * r[1] - q * nx) * ib,
                 (-8.6693653f * r[15] + -1.28759261f * r[17] - q * ny) * ib,
                 (7.50789059f * r[2] - q * nz) * ib);
    q = lr * y[104];
    SHLIGHT_SET3(out_grad[104], (-8.14345071f * r[4] + 1.82093094f * r[2] - q * nx) * ib,
                 (-8.14345071f * r[14] + -1.82093094f * r[16] - q * ny) * ib,
                 (8.41051973f * r[3] - q * nz) * ib);
    q = lr * y[105];
    SHLIGHT_SET3(out_grad[105], (-7.61750063f * r[5] + 2.35081173f * r[3] - q * nx) * ib,
                 (-7.61750063f * r[13] + -2.35081173f * r[15] - q * ny) * ib,
                 (9.10465468f * r[4] - q * nz) * ib);
    q = lr * y[106];
    SHLIGHT_SET3(out_grad[106], (-7.09150715f * r[6] + 2.87914461f * r[4] - q * nx) * ib,
                 (-7.09150715f * r[12] + -2.87914461f * r[14] - q * ny) * ib,
                 (9.63546082f * r[5] - q * nz) * ib);
    q = lr * y[107];
    SHLIGHT_SET3(out_grad[107], (-6.56545986f * r[7] + 3.40664984f * r[5] - q * nx) * ib,
                 (-6.56545986f * r[11] + -3.40664984f * r[13] - q * ny) * ib,
                 (10.0289056f * r[6] - q * nz) * ib);
    q = lr * y[108];
    SHLIGHT_SET3(out_grad[108], (-6.03934468f * r[8] + 3.93366041f * r[6] - q * nx) * ib,
                 (-6.03934468f * r[10] + -3.93366041f * r[12] - q * ny) * ib,
                 (10.3007409f * r[7] - q * nz) * ib);
    q = lr * y[109];
    SHLIGHT_SET3(out_grad[109], (4.46035165f * r[7] - q * nx) * ib,
                 (-7.79676046f * r[9] + -4.46035165f * r[11] - q * ny) * ib,
                 (10.4604518f * r[8] - q * nz) * ib);
    q = lr * y[110];
    SHLIGHT_SET3(out_grad[110], (7.05243519f * r[10] - q * nx) * ib,
                 (7.05243519f * r[8] - q * ny) * ib, (10.5131497f * r[9] - q * nz) * ib);
    q = lr * y[111];
    SHLIGHT_SET3(out_grad[111], (-7.79676046f * r[9] + 4.46035165f * r[11] - q * nx) * ib,
                 (4.46035165f * r[7] - q * ny) * ib, (10.4604518f * r[10] - q * nz) * ib);
    q = lr * y[112];
    SHLIGHT_SET3(out_grad[112], (-6.03934468f * r[10] + 3.93366041f * r[12] - q * nx) * ib,
                 (6.03934468f * r[8] + 3.93366041f * r[6] - q * ny) * ib,
                 (10.3007409f * r[11] - q * nz) * ib);
    q = lr * y[113];
    SHLIGHT_SET3(out_grad[113], (-6.56545986f * r[11] + 3.40664984f * r[13] - q * nx) * ib,
                 (6.56545986f * r[7] + 3.40664984f * r[5] - q * ny) * ib,
                 (10.0289056f * r[12] - q * nz) * ib);
    q = lr * y[114];
    SHLIGHT_SET3(out_grad[114], (-7.09150715f * r[12] + 2.87914461f * r[14] - q * nx) * ib,
                 (7.09150715f * r[6] + 2.87914461f * r[4] - q * ny) * ib,
                 (9.63546082f * r[13] - q * nz) * ib);
    q = lr * y[115];
    SHLIGHT_SET3(out_grad[115], (-7.61750063f * r[13] + 2.35081173f * r[15] - q * nx) * ib,
                 (7.61750063f * r[5] + 2.35081173f * r[3] - q * ny) * ib,
                 (9.10465468f * r[14] - q * nz) * ib);
    q = lr * y[116];
    SHLIGHT_SET3(out_grad[116], (-8.14345071f * r[14] + 1.82093094f * r[16] - q * nx) * ib,
                 (8.14345071f * r[4] + 1.82093094f * r[2] - q * ny) * ib,
                 (8.41051973f * r[15] - q * nz) * ib);
    q = lr * y[117];
    SHLIGHT_SET3(out_grad[117], (-8.6693653f * r[15] + 1.28759261f * r[17] - q * nx) * ib,
                 (8.6693653f * r[3] + 1.28759261f * r[1] - q * ny) * ib,
                 (7.50789059f * r[16] - q * nz) * ib);
    q = lr * y[118];
    SHLIGHT_SET3(out_grad[118], (-9.19525049f * r[16] + 0.743391942f * r[18] - q * nx) * ib,
                 (9.19525049f * r[2] + 0.743391942f * r[0] - q * ny) * ib,
                 (6.3078898f * r[17] - q * nz) * ib);
    q = lr * y[119];
    SHLIGHT_SET3(out_grad[119], (-9.72111105f * r[17] - q * nx) * ib,
                 (9.72111105f * r[1] - q * ny) * ib, (4.58257569f * r[18] - q * nz) * ib);
    q = lr * y[120];
    SHLIGHT_SET3(out_grad[120], (-10.2469508f * r[18] - q * nx) * ib,
                 (10.2469508f * r[0] - q * ny) * ib, -q * nz * ib);
  }
#endif
#if SHLIGHT_MAX_BANDS > 11
  if (n > 11) {
    lr = 11.0f * ir;
    r[0] = y[100] * ir;
    r[1] = y[101] * ir;
    r[2] = y[102] * ir;
    r[3] = y[103] * ir;
    r[4] = y[104] * ir;
    r[5] = y[105] * ir;
    r[6] = y[106] * ir;
    r[7] = y[107] * ir;
    r[8] = y[108] * ir;
    r[9] = y[109] * ir;
    r[10] = y[110] * ir;
    r[11] = y[111] * ir;
    r[12] = y[112] * ir;
    r[13] = y[113] * ir;
    r[14] = y[114] * ir;
    r[15] = y[115] * ir;
    r[16] = y[116] * ir;
    r[17] = y[117] * ir;
    r[18] = y[118] * ir;
    r[19] = y[119] * ir;
    r[20] = y[120] * ir;
    q = lr * y[121];
    SHLIGHT_SET3(out_grad[121], (-11.2472219f * r[0] - q * nx) * ib,
                 (-11.2472219f * r[20] - q * ny) * ib, -q * nz * ib);
    q = lr * y[122];
    SHLIGHT_SET3(out_grad[122], (-10.7238053f * r[1] - q * nx) * ib,
                 (-10.7238053f * r[19] - q * ny) * ib, (4.79583152f * r[0] - q * nz) * ib);
    q = lr * y[123];
    SHLIGHT_SET3(out_grad[123], (-10.2003735f * r[2] + 0.74001287f * r[0] - q * nx) * ib,
                 (-10.2003735f * r[18] + -0.74001287f * r[20] - q * ny) * ib,
                 (6.61887633f * r[1] - q * nz) * ib);
    q = lr * y[124];
    SHLIGHT_SET3(out_grad[124], (-9.67692395f * r[3] + 1.28173989f * r[1] - q * nx) * ib,
                 (-9.67692395f * r[17] + -1.28173989f * r[19] - q * ny) * ib,
                 (7.90117532f * r[2] - q * nz) * ib);
    q = lr * y[125];
    SHLIGHT_SET3(out_grad[125], (-9.15345368f * r[4] + 1.81265393f * r[2] - q * nx) * ib,
                 (-9.15345368f * r[16] + -1.81265393f * r[18] - q * ny) * ib,
                 (8.88015444f * r[3] - q * nz) * ib);
    q = lr * y[126];
    SHLIGHT_SET3(out_grad[126], (-8.62995889f * r[5] + 2.34012617f * r[3] - q * nx) * ib,
                 (-8.62995889f * r[15] + -2.34012617f * r[17] - q * ny) * ib,
                 (9.64858736f * r[4] - q * nz) * ib);
    q = lr * y[127];
    SHLIGHT_SET3(out_grad[127], (-8.10643483f * r[6] + 2.86605752f * r[4] - q * nx) * ib,
                 (-8.10643483f * r[14] + -2.86605752f * r[16] - q * ny) * ib,
                 (10.2539191f * r[5] - q * nz) * ib);
    q = lr * y[128];
    SHLIGHT_SET3(out_grad[128], (-7.58287544f * r[7] + 3.39116499f * r[5] - q * nx) * ib,
                 (-7.58287544f * r[13] + -3.39116499f * r[15] - q * ny) * ib,
                 (10.7238053f * r[6] - q * nz) * ib);
    q = lr * y[129];
    SHLIGHT_SET3(out_grad[129], (-7.05927286f * r[8] + 3.91578004f * r[6] - q * nx) * ib,
                 (-7.05927286f * r[12] + -3.91578004f * r[14] - q * ny) * ib,
                 (11.0754985f * r[7] - q * nz) * ib);
    q = lr * y[130];
    SHLIGHT_SET3(out_grad[130], (-6.5356167f * r[9] + 4.44007722f * r[7] - q * nx) * ib,
                 (-6.5356167f * r[11] + -4.44007722f * r[13] - q * ny) * ib,
                 (11.3200202f * r[8] - q * nz) * ib);
    q = lr * y[131];
    SHLIGHT_SET3(out_grad[131], (4.96415724f * r[8] - q * nx) * ib,
                 (-8.50210058f * r[10] + -4.96415724f * r[12] - q * ny) * ib,
                 (11.4642301f * r[9] - q * nz) * ib);
    q = lr * y[132];
    SHLIGHT_SET3(out_grad[132], (7.76132046f * r[11] - q * nx) * ib,
                 (7.76132046f * r[9] - q * ny) * ib, (11.5118986f * r[10] - q * nz) * ib);
    q = lr * y[133];
    SHLIGHT_SET3(out_grad[133], (-8.50210058f * r[10] + 4.96415724f * r[12] - q * nx) * ib,
                 (4.96415724f * r[8] - q * ny) * ib, (11.4642301f * r[11] - q * nz) * ib);
    q = lr * y[134];
    SHLIGHT_SET3(out_grad[134], (-6.5356167f * r[11] + 4.44007722f * r[13] - q * nx) * ib,
                 (6.5356167f * r[9] + 4.44007722f * r[7] - q * ny) * ib,
                 (11.3200202f * r[12] - q * nz) * ib);
    q = lr * y[135];
    SHLIGHT_SET3(out_grad[135], (-7.05927286f * r[12] + 3.91578004f * r[14] - q * nx) * ib,
                 (7.05927286f * r[8] + 3.91578004f * r[6] - q * ny) * ib,
                 (11.0754985f * r[13] - q * nz) * ib);
    q = lr * y[136];
    SHLIGHT_SET3(out_grad[136], (-7.58287544f * r[13] + 3.39116499f * r[15] - q * nx) * ib,
                 (7.58287544f * r[7] + 3.39116499f * r[5] - q * ny) * ib,
                 (10.7238053f * r[14] - q * nz) * ib);
    q = lr * y[137];
    SHLIGHT_SET3(out_grad[137], (-8.10643483f * r[14] + 2.86605752f * r[16] - q * nx) * ib,
                 (8.10643483f * r[6] + 2.86605752f * r[4] - q * ny) * ib,
                 (10.2539191f * r[15] - q * nz) * ib);
    q = lr * y[138];
    SHLIGHT_SET3(out_grad[138], (-8.62995889f * r[15] + 2.34012617f * r[17] - q * nx) * ib,
                 (8.62995889f * r[5] + 2.34012617f * r[3] - q * ny) * ib,
                 (9.64858736f * r[16] - q * nz) * ib);
    q = lr * y[139];
    SHLIGHT_SET3(out_grad[139], (-9.15345368f * r[16] + 1.81265393f * r[18] - q * nx) * ib,
                 (9.15345368f * r[4] + 1.81265393f * r[2] - q * ny) * ib,
                 (8.88015444f * r[17] - q * nz) * ib);
    q = lr * y[140];
    SHLIGHT_SET3(out_grad[140], (-9.67692395f * r[17] + 1.28173989f * r[19] - q * nx) * ib,
                 (9.67692395f * r[3] + 1.28173989f * r[1] - q * ny) * ib,
                 (7.90117532f * r[18] - q * nz) * ib);
    q = lr * y[141];
    SHLIGHT_SET3(out_grad[141], (-10.2003735f * r[18] + 0.74001287f * r[20] - q * nx) * ib,
                 (10.2003735f * r[2] + 0.74001287f * r[0] - q * ny) * ib,
                 (6.61887633f * r[19] - q * nz) * ib);
    q = lr * y[142];
    SHLIGHT_SET3(out_grad[142], (-10.7238053f * r[19] - q * nx) * ib,
                 (10.7238053f * r[1] - q * ny) * ib, (4.79583152f * r[20] - q * nz) * ib);
    q = lr * y[143];
    SHLIGHT_SET3(out_grad[143], (-11.2472219f * r[20] - q * nx) * ib,
                 (11.2472219f * r[0] - q * ny) * ib, -q * nz * ib);
  }
#endif
#if SHLIGHT_MAX_BANDS > 12
  if (n > 12) {
    lr = 12.0f * ir;
    r[0] = y[121] * ir;
    r[1] = y[122] * ir;
    r[2] = y[123] * ir;
    r[3] = y[124] * ir;
    r[4] = y[125] * ir;
    r[5] = y[126] * ir;
    r[6] = y[127] * ir;
    r[7] = y[128] * ir;
    r[8] = y[129] * ir;
    r[9] = y[130] * ir;
    r[10] = y[131] * ir;
    r[11] = y[132] * ir;
    r[12] = y[133] * ir;
    r[13] = y[134] * ir;
    r[14] = y[135] * ir;
    r[15] = y[136] * ir;
    r[16] = y[137] * ir;
    r[17] = y[138] * ir;
    r[18] = y[139] * ir;
    r[19] = y[140] * ir;
    r[20] = y[141] * ir;
    r[21] = y[142] * ir;
    r[22] = y[143] * ir;
    q = lr * y[144];
    SHLIGHT_SET3(out_grad[144], (-12.2474487f * r[0] - q * nx) * ib,
                 (-12.2474487f * r[22] - q * ny) * ib, -q * nz * ib);
    q = lr * y[145];
    SHLIGHT_SET3(out_grad[145], (-11.7260394f * r[1] - q * nx) * ib,
                 (-11.7260394f * r[21] - q * ny) * ib, (5.0f * r[0] - q * nz) * ib);
    q = lr * y[146];
    SHLIGHT_SET3(out_grad[146], (-11.2046186f * r[2] + 0.737209781f * r[0] - q * nx) * ib,
                 (-11.2046186f * r[20] + -0.737209781f * r[22] - q * ny) * ib,
                 (6.91564075f * r[1] - q * nz) * ib);
    q = lr * y[147];
    SHLIGHT_SET3(out_grad[147], (-10.6831847f * r[3] + 1.2768848f * r[1] - q * nx) * ib,
                 (-10.6831847f * r[19] + -1.2768848f * r[21] - q * ny) * ib,
                 (8.27515927f * r[2] - q * nz) * ib);
    q = lr * y[148];
    SHLIGHT_SET3(out_grad[148], (-10.1617356f * r[4] + 1.8057878f * r[2] - q * nx) * ib,
                 (-10.1617356f * r[18] + -1.8057878f * r[20] - q * ny) * ib,
                 (9.32504808f * r[3] - q * nz) * ib);
    q = lr * y[149];
    SHLIGHT_SET3(out_grad[149], (-9.6402688f * r[5] + 2.33126202f * r[3] - q * nx) * ib,
                 (-9.6402688f * r[17] + -2.33126202f * r[19] - q * ny) * ib,
                 (10.1617356f * r[4] - q * nz) * ib);
    q = lr * y[150];
    SHLIGHT_SET3(out_grad[150], (-9.11878138f * r[6] + 2.8552012f * r[4] - q * nx) * ib,
                 (-9.11878138f * r[16] + -2.8552012f * r[18] - q * ny) * ib,
                 (10.8347268f * r[5] - q * nz) * ib);
    q = lr * y[151];
    SHLIGHT_SET3(out_grad[151], (-8.59726954f * r[7] + 3.37831962f * r[5] - q * nx) * ib,
                 (-8.59726954f * r[15] + -3.37831962f * r[17] - q * ny) * ib,
                 (11.3731186f * r[6] - q * nz) * ib);
    q = lr * y[152];
    SHLIGHT_SET3(out_grad[152], (-8.07572853f * r[8] + 3.90094749f * r[6] - q * nx) * ib,
                 (-8.07572853f * r[14] + -3.90094749f * r[16] - q * ny) * ib,
                 (11.7953565f * r[7] - q * nz) * ib);
    q = lr * y[153];
    SHLIGHT_SET3(out_grad[153], (-7.55415233f * r[9] + 4.42325868f * r[7] - q * nx) * ib,
                 (-7.55415233f * r[13] + -4.42325868f * r[15] - q * ny) * ib,
                 (12.1135928f * r[8] - q * nz) * ib);
    q = lr * y[154];
    SHLIGHT_SET3(out_grad[154], (-7.0325331f * r[10] + 4.94535355f * r[8] - q * nx) * ib,
                 (-7.0325331f * r[12] + -4.94535355f * r[14] - q * ny) * ib,
                 (12.3358791f * r[9] - q * nz) * ib);
    q = lr * y[155];
    SHLIGHT_SET3(out_grad[155], (5.46729406f * r[9] - q * nx) * ib,
                 (-9.20774721f * r[11] + -5.46729406f * r[13] - q * ny) * ib,
                 (12.4673487f * r[10] - q * nz) * ib);
    q = lr * y[156];
    SHLIGHT_SET3(out_grad[156], (8.46989554f * r[12] - q * nx) * ib,
                 (8.46989554f * r[10] - q * ny) * ib, (12.5108648f * r[11] - q * nz) * ib);
    q = lr * y[157];
    SHLIGHT_SET3(out_grad[157], (-9.20774721f * r[11] + 5.46729406f * r[13] - q * nx) * ib,
                 (5.46729406f * r[9] - q * ny) * ib, (12.4673487f * r[12] - q * nz) * ib);
    q = lr * y[158];
    SHLIGHT_SET3(out_grad[158], (-7.0325331f * r[12] + 4.94535355f * r[14] - q * nx) * ib,
                 (7.0325331f * r[10] + 4.94535355f * r[8] - q * ny) * ib,
                 (12.3358791f * r[13] - q * nz) * ib);
    q = lr * y[159];
    SHLIGHT_SET3(out_grad[159], (-7.55415233f * r[13] + 4.42325868f * r[15] - q * nx) * ib,
                 (7.55415233f * r[9] + 4.42325868f * r[7] - q * ny) * ib,
                 (12.1135928f * r[14] - q * nz) * ib);
    q = lr * y[160];
    SHLIGHT_SET3(out_grad[160], (-8.07572853f * r[14] + 3.90094749f * r[16] - q * nx) * ib,
                 (8.07572853f * r[8] + 3.90094749f * r[6] - q * ny) * ib,
                 (11.7953565f * r[15] - q * nz) * ib);
    q = lr * y[161];
    SHLIGHT_SET3(out_grad[161], (-8.59726954f * r[15] + 3.37831962f * r[17] - q * nx) * ib,
                 (8.59726954f * r[7] + 3.37831962f * r[5] - q * ny) * ib,
                 (11.3731186f * r[16] - q * nz) * ib);
    q = lr * y[162];
    SHLIGHT_SET3(out_grad[162], (-9.11878138f * r[16] + 2.8552012f * r[18] - q * nx) * ib,
                 (9.11878138f * r[6] + 2.8552012f * r[4] - q * ny) * ib,
                 (10.8347268f * r[17] - q * nz) * ib);
    q = lr * y[163];
    SHLIGHT_SET3(out_grad[163], (-9.6402688f * r[17] + 2.33126202f * r[19] - q * nx) * ib,
                 (9.6402688f * r[5] + 2.33126202f * r[3] - q * ny) * ib,
                 (10.1617356f * r[18] - q * nz) * ib);
    q = lr * y[164];
    SHLIGHT_SET3(out_grad[164], (-10.1617356f * r[18] + 1.8057878f * r[20] - q * nx) * ib,
                 (10.1617356f * r[4] + 1.8057878f * r[2] - q * ny) * ib,
                 (9.32504808f * r[19] - q * nz) * ib);
    q = lr * y[165];
    SHLIGHT_SET3(out_grad[165], (-10.6831847f * r[19] + 1.2768848f * r[21] - q * nx) * ib,
                 (10.6831847f * r[3] + 1.2768848f * r[1] - q * ny) * ib,
                 (8.27515927f * r[20] - q * nz) * ib);
    q = lr * y[166];
    SHLIGHT_SET3(out_grad[166], (-11.2046186f * r[20] + 0.737209781f * r[22] - q * nx) * ib,
                 (11.2046186f * r[2] + 0.737209781f * r[0] - q * ny) * ib,
                 (6.91564075f * r[21] - q * nz) * ib);
    q = lr * y[167];
    SHLIGHT_SET3(out_grad[167], (-11.7260394f * r[21] - q * nx) * ib,
                 (11.7260394f * r[1] - q * ny) * ib, (5.0f * r[22] - q * nz) * ib);
    q = lr * y[168];
    SHLIGHT_SET3(out_grad[168], (-12.2474487f * r[22] - q * nx) * ib,
                 (12.2474487f * r[0] - q * ny) * ib, -q * nz * ib);
  }
#endif
#if SHLIGHT_MAX_BANDS > 13
  if (n > 13) {
    lr = 13.0f * ir;
    r[0] = y[144] * ir;
    r[1] = y[145] * ir;
    r[2] = y[146] * ir;
    r[3] = y[147] * ir;
    r[4] = y[148] * ir;
    r[5] = y[149] * ir;
    r[6] = y[150] * ir;
    r[7] = y[151] * ir;
    r[8] = y[152] * ir;
    r[9] = y[153] * ir;
    r[10] = y[154] * ir;
    r[11] = y[155] * ir;
    r[12] = y[156] * ir;
    r[13] = y[157] * ir;
    r[14] = y[158] * ir;
    r[15] = y[159] * ir;
    r[16] = y[160] * ir;
    r[17] = y[161] * ir;
    r[18] = y[162] * ir;
    r[19] = y[163] * ir;
    r[20] = y[164] * ir;
    r[21] = y[165] * ir;
    r[22] = y[166] * ir;
    r[23] = y[167] * ir;
    r[24] = y[168] * ir;
    q = lr * y[169];
    SHLIGHT_SET3(out_grad[169], (-13.2476413f * r[0] - q * nx) * ib,
                 (-13.2476413f * r[24] - q * ny) * ib, -q * nz * ib);
    q = lr * y[170];
    SHLIGHT_SET3(out_grad[170], (-12.7279221f * r[1] - q * nx) * ib,
                 (-12.7279221f * r[23] - q * ny) * ib, (5.19615242f * r[0] - q * nz) * ib);
    q = lr * y[171];
    SHLIGHT_SET3(out_grad[171], (-12.208194f * r[2] + 0.734846923f * r[0] - q * nx) * ib,
                 (-12.208194f * r[22] + -0.734846923f * r[24] - q * ny) * ib,
                 (7.2f * r[1] - q * nz) * ib);
    q = lr * y[172];
    SHLIGHT_SET3(out_grad[172], (-11.6884558f * r[3] + 1.27279221f * r[1] - q * nx) * ib,
                 (-11.6884558f * r[21] + -1.27279221f * r[23] - q * ny) * ib,
                 (8.63249674f * r[2] - q * nz) * ib);
    q = lr * y[173];
    SHLIGHT_SET3(out_grad[173], (-11.1687063f * r[4] + 1.8f * r[2] - q * nx) * ib,
                 (-11.1687063f * r[20] + -1.8f * r[22] - q * ny) * ib,
                 (9.74884609f * r[3] - q * nz) * ib);
    q = lr * y[174];
    SHLIGHT_SET3(out_grad[174], (-10.6489436f * r[5] + 2.32379001f * r[3] - q * nx) * ib,
                 (-10.6489436f * r[19] + -2.32379001f * r[21] - q * ny) * ib,
                 (10.6489436f * r[4] - q * nz) * ib);
    q = lr * y[175];
    SHLIGHT_SET3(out_grad[175], (-10.1291658f * r[6] + 2.84604989f * r[4] - q * nx) * ib,
                 (-10.1291658f * r[18] + -2.84604989f * r[20] - q * ny) * ib,
                 (11.3841996f * r[5] - q * nz) * ib);
    q = lr * y[176];
    SHLIGHT_SET3(out_grad[176], (-9.60937043f * r[7] + 3.36749165f * r[5] - q * nx) * ib,
                 (-9.60937043f * r[17] + -3.36749165f * r[19] - q * ny) * ib,
                 (11.9849906f * r[6] - q * nz) * ib);
    q = lr * y[177];
    SHLIGHT_SET3(out_grad[177], (-9.08955444f * r[8] + 3.88844442f * r[6] - q * nx) * ib,
                 (-9.08955444f * r[16] + -3.88844442f * r[18] - q * ny) * ib,
                 (12.4707658f * r[7] - q * nz) * ib);
    q = lr * y[178];
    SHLIGHT_SET3(out_grad[178], (-8.56971411f * r[9] + 4.40908154f * r[7] - q * nx) * ib,
                 (-8.56971411f * r[15] + -4.40908154f * r[17] - q * ny) * ib,
                 (12.8545712f * r[8] - q * nz) * ib);
    q = lr * y[179];
    SHLIGHT_SET3(out_grad[179], (-8.04984472f * r[10] + 4.92950302f * r[8] - q * nx) * ib,
                 (-8.04984472f * r[14] + -4.92950302f * r[16] - q * ny) * ib,
                 (13.1453414f * r[9] - q * nz) * ib);
    q = lr * y[180];
    SHLIGHT_SET3(out_grad[180], (-7.52994024f * r[11] + 5.44977064f * r[9] - q * nx) * ib,
                 (-7.52994024f * r[13] + -5.44977064f * r[15] - q * ny) * ib,
                 (13.3491573f * r[10] - q * nz) * ib);
    q = lr * y[181];
    SHLIGHT_SET3(out_grad[181], (5.96992462f * r[10] - q * nx) * ib,
                 (-9.91362699f * r[12] + -5.96992462f * r[14] - q * ny) * ib,
                 (13.4699666f * r[11] - q * nz) * ib);
    q = lr * y[182];
    SHLIGHT_SET3(out_grad[182], (9.17823512f * r[13] - q * nx) * ib,
                 (9.17823512f * r[11] - q * ny) * ib, (13.5099963f * r[12] - q * nz) * ib);
    q = lr * y[183];
    SHLIGHT_SET3(out_grad[183], (-9.91362699f * r[12] + 5.96992462f * r[14] - q * nx) * ib,
                 (5.96992462f * r[10] - q * ny) * ib, (13.4699666f * r[13] - q * nz) * ib);
    q = lr * y[184];
    SHLIGHT_SET3(out_grad[184], (-7.52994024f * r[13] + 5.44977064f * r[15] - q * nx) * ib,
                 (7.52994024f * r[11] + 5.44977064f * r[9] - q * ny) * ib,
                 (13.3491573f * r[14] - q * nz) * ib);
    q = lr * y[185];
    SHLIGHT_SET3(out_grad[185], (-8.04984472f * r[14] + 4.92950302f * r[16] - q * nx) * ib,
                 (8.04984472f * r[10] + 4.92950302f * r[8] - q * ny) * ib,
                 (13.1453414f * r[15] - q * nz) * ib);
    q = lr * y[186];
    SHLIGHT_SET3(out_grad[186], (-8.56971411f * r[15] + 4.40908154f * r[17] - q * nx) * ib,
                 (8.56971411f * r[9] + 4.40908154f * r[7] - q * ny) * ib,
                 (12.8545712f * r[16] - q * nz) * ib);
    q = lr * y[187];
    SHLIGHT_SET3(out_grad[187], (-9.08955444f * r[16] + 3.88844442f * r[18] - q * nx) * ib,
                 (9.08955444f * r[8] + 3.88844442f * r[6] - q * ny) * ib,
                 (12.4707658f * r[17] - q * nz) * ib);
    q = lr * y[188];
    SHLIGHT_SET3(out_grad[188], (-9.60937043f * r[17] + 3.36749165f * r[19] - q * nx) * ib,
                 (9.60937043f * r[7] + 3.36749165f * r[5] - q * ny) * ib,
                 (11.9849906f * r[18] - q * nz) * ib);
    q = lr * y[189];
    SHLIGHT_SET3(out_grad[189], (-10.1291658f * r[18] + 2.84604989f * r[20] - q * nx) * ib,
                 (10.1291658f * r[6] + 2.84604989f * r[4] - q * ny) * ib,
                 (11.3841996f * r[19] - q * nz) * ib);
    q = lr * y[190];
    SHLIGHT_SET3(out_grad[190], (-10.6489436f * r[19] + 2.32379001f * r[21] - q * nx) * ib,
                 (10.6489436f * r[5] + 2.32379001f * r[3] - q * ny) * ib,
                 (10.6489436f * r[20] - q * nz) * ib);
    q = lr * y[191];
    SHLIGHT_SET3(out_grad[191], (-11.1687063f * r[20] + 1.8f * r[22] - q * nx) * ib,
                 (11.1687063f * r[4] + 1.8f * r[2] - q * ny) * ib,
                 (9.74884609f * r[21] - q * nz) * ib);
    q = lr * y[192];
    SHLIGHT_SET3(out_grad[192], (-11.6884558f * r[21] + 1.27279221f * r[23] - q * nx) * ib,
                 (11.6884558f * r[3] + 1.27279221f * r[1] - q * ny) * ib,
                 (8.63249674f * r[22] - q * nz) * ib);
    q = lr * y[193];
    SHLIGHT_SET3(out_grad[193], (-12.208194f * r[22] + 0.734846923f * r[24] - q * nx) * ib,
                 (12.208194f * r[2] + 0.734846923f * r[0] - q * ny) * ib,
                 (7.2f * r[23] - q * nz) * ib);
    q = lr * y[194];
    SHLIGHT_SET3(out_grad[194], (-12.7279221f * r[23] - q * nx) * ib,
                 (12.7279221f * r[1] - q * ny) * ib, (5.19615242f * r[24] - q * nz) * ib);
    q = lr * y[195];
    SHLIGHT_SET3(out_grad[195], (-13.2476413f * r[24] - q * nx) * ib,
                 (13.2476413f * r[0] - q * ny) * ib, -q * nz * ib);
  }
#endif
#if SHLIGHT_MAX_BANDS > 14
  if (n > 14) {
    lr = 14.0f * ir;
    r[0] = y[169] * ir;
    r[1] = y[170] * ir;
    r[2] = y[171] * ir;
    r[3] = y[172] * ir;
    r[4] = y[173] * ir;
    r[5] = y[174] * ir;
    r[6] = y[175] * ir;
    r[7] = y[176] * ir;
    r[8] = y[177] * ir;
    r[9] = y[178] * ir;
    r[10] = y[179] * ir;
    r[11] = y[180] * ir;
    r[12] = y[181] * ir;
    r[13] = y[182] * ir;
    r[14] = y[183] * ir;
    r[15] = y[184] * ir;
    r[16] = y[185] * ir;
    r[17] = y[186] * ir;
    r[18] = y[187] * ir;
    r[19] = y[188] * ir;
    r[20] = y[189] * ir;
    r[21] = y[190] * ir;
    r[22] = y[191] * ir;
    r[23] = y[192] * ir;
    r[24] = y[193] * ir;
    r[25] = y[194] * ir;
    r[26] = y[195] * ir;
    q = lr * y[196];
    SHLIGHT_SET3(out_grad[196], (-14.2478068f * r[0] - q * nx) * ib,
                 (-14.2478068f * r[26] - q * ny) * ib, -q * nz * ib);
    q = lr * y[197];
    SHLIGHT_SET3(out_grad[197], (-13.7295302f * r[1] - q * nx) * ib,
                 (-13.7295302f * r[25] - q * ny) * ib, (5.38516481f * r[0] - q * nz) * ib);
    q = lr * y[198];
    SHLIGHT_SET3(out_grad[198], (-13.2112466f * r[2] + 0.732828109f * r[0] - q * nx) * ib,
                 (-13.2112466f * r[24] + -0.732828109f * r[26] - q * ny) * ib,
                 (7.47340965f * r[1] - q * nz) * ib);
    q = lr * y[199];
    SHLIGHT_SET3(out_grad[199], (-12.6929552f * r[3] + 1.26929552f * r[1] - q * nx) * ib,
                 (-12.6929552f * r[23] + -1.26929552f * r[25] - q * ny) * ib,
                 (8.97527468f * r[2] - q * nz) * ib);
    q = lr * y[200];
    SHLIGHT_SET3(out_grad[200], (-12.1746549f * r[4] + 1.79505494f * r[2] - q * nx) * ib,
                 (-12.1746549f * r[22] + -1.79505494f * r[24] - q * ny) * ib,
                 (10.1543641f * r[3] - q * nz) * ib);
    q = lr * y[201];
    SHLIGHT_SET3(out_grad[201], (-11.6563446f * r[5] + 2.31740596f * r[3] - q * nx) * ib,
                 (-11.6563446f * r[21] + -2.31740596f * r[23] - q * ny) * ib,
                 (11.1138885f * r[4] - q * nz) * ib);
    q = lr * y[202];
    SHLIGHT_SET3(out_grad[202], (-11.138023f * r[6] + 2.83823106f * r[4] - q * nx) * ib,
                 (-11.138023f * r[20] + -2.83823106f * r[22] - q * ny) * ib,
                 (11.9070474f * r[5] - q * nz) * ib);
    q = lr * y[203];
    SHLIGHT_SET3(out_grad[203], (-10.6196882f * r[7] + 3.35824028f * r[5] - q * nx) * ib,
                 (-10.6196882f * r[19] + -3.35824028f * r[21] - q * ny) * ib,
                 (12.5653845f * r[6] - q * nz) * ib);
    q = lr * y[204];
    SHLIGHT_SET3(out_grad[204], (-10.1013384f * r[8] + 3.87776186f * r[6] - q * nx) * ib,
                 (-10.1013384f * r[18] + -3.87776186f * r[20] - q * ny) * ib,
                 (13.1092277f * r[7] - q * nz) * ib);
    q = lr * y[205];
    SHLIGHT_SET3(out_grad[205], (-9.58297101f * r[9] + 4.39696865f * r[7] - q * nx) * ib,
                 (-9.58297101f * r[17] + -4.39696865f * r[19] - q * ny) * ib,
                 (13.5523676f * r[8] - q * nz) * ib);
    q = lr * y[206];
    SHLIGHT_SET3(out_grad[206], (-9.06458309f * r[10] + 4.9159604f * r[8] - q * nx) * ib,
                 (-9.06458309f * r[16] + -4.9159604f * r[18] - q * ny) * ib,
                 (13.9044357f * r[9] - q * nz) * ib);
    q = lr * y[207];
    SHLIGHT_SET3(out_grad[207], (-8.5461709f * r[11] + 5.43479871f * r[9] - q * nx) * ib,
                 (-8.5461709f * r[15] + -5.43479871f * r[17] - q * ny) * ib,
                 (14.1722211f * r[10] - q * nz) * ib);
    q = lr * y[208];
    SHLIGHT_SET3(out_grad[208], (-8.02772972f * r[12] + 5.9535237f * r[10] - q * nx) * ib,
                 (-8.02772972f * r[14] + -5.9535237f * r[16] - q * ny) * ib,
                 (14.3604395f * r[11] - q * nz) * ib);
    q = lr * y[209];
    SHLIGHT_SET3(out_grad[209], (6.47216261f * r[11] - q * nx) * ib,
                 (-10.6196882f * r[13] + -6.47216261f * r[15] - q * ny) * ib,
                 (14.4721956f * r[12] - q * nz) * ib);
    q = lr * y[210];
    SHLIGHT_SET3(out_grad[210], (9.88639169f * r[14] - q * nx) * ib,
                 (9.88639169f * r[12] - q * ny) * ib, (14.5092563f * r[13] - q * nz) * ib);
    q = lr * y[211];
    SHLIGHT_SET3(out_grad[211], (-10.6196882f * r[13] + 6.47216261f * r[15] - q * nx) * ib,
                 (6.47216261f * r[11] - q * ny) * ib, (14.4721956f * r[14] - q * nz) * ib);
    q = lr * y[212];
    SHLIGHT_SET3(out_grad[212], (-8.02772972f * r[14] + 5.9535237f * r[16] - q * nx) * ib,
                 (8.02772972f * r[12] + 5.9535237f * r[10] - q * ny) * ib,
                 (14.3604395f * r[15] - q * nz) * ib);
    q = lr * y[213];
    SHLIGHT_SET3(out_grad[213], (-8.5461709f * r[15] + 5.43479871f * r[17] - q * nx) * ib,
                 (8.5461709f * r[11] + 5.43479871f * r[9] - q * ny) * ib,
                 (14.1722211f * r[16] - q * nz) * ib);
    q = lr * y[214];
    SHLIGHT_SET3(out_grad[214], (-9.06458309f * r[16] + 4.9159604f * r[18] - q * nx) * ib,
                 (9.06458309f * r[10] + 4.9159604f * r[8] - q * ny) * ib,
                 (13.9044357f * r[17] - q * nz) * ib);
    q = lr * y[215];
    SHLIGHT_SET3(out_grad[215], (-9.58297101f * r[17] + 4.39696865f * r[19] - q * nx) * ib,
                 (9.58297101f * r[9] + 4.39696865f * r[7] - q * ny) * ib,
                 (13.5523676f * r[18] - q * nz) * ib);
    q = lr * y[216];
    SHLIGHT_SET3(out_grad[216], (-10.1013384f * r[18] + 3.87776186f * r[20] - q * nx) * ib,
                 (10.1013384f * r[8] + 3.87776186f * r[6] - q * ny) * ib,
                 (13.1092277f * r[19] - q * nz) * ib);
    q = lr * y[217];
    SHLIGHT_SET3(out_grad[217], (-10.6196882f * r[19] + 3.35824028f * r[21] - q * nx) * ib,
                 (10.6196882f * r[7] + 3.35824028f * r[5] - q * ny) * ib,
                 (12.5653845f * r[20] - q * nz) * ib);
    q = lr * y[218];
    SHLIGHT_SET3(out_grad[218], (-11.138023f * r[20] + 2.83823106f * r[22] - q * nx) * ib,
                 (11.138023f * r[6] + 2.83823106f * r[4] - q * ny) * ib,
                 (11.9070474f * r[21] - q * nz) * ib);
    q = lr * y[219];
    SHLIGHT_SET3(out_grad[219], (-11.6563446f * r[21] + 2.31740596f * r[23] - q * nx) * ib,
                 (11.6563446f * r[5] + 2.31740596f * r[3] - q * ny) * ib,
                 (11.1138885f * r[22] - q * nz) * ib);
    q = lr * y[220];
    SHLIGHT_SET3(out_grad[220], (-12.1746549f * r[22] + 1.79505494f * r[24] - q * nx) * ib,
                 (12.1746549f * r[4] + 1.79505494f * r[2] - q * ny) * ib,
                 (10.1543641f * r[23] - q * nz) * ib);
    q = lr * y[221];
    SHLIGHT_SET3(out_grad[221], (-12.6929552f * r[23] + 1.26929552f * r[25] - q * nx) * ib,
                 (12.6929552f * r[3] + 1.26929552f * r[1] - q * ny) * ib,
                 (8.97527468f * r[24] - q * nz) * ib);
    q = lr * y[222];
    SHLIGHT_SET3(out_grad[222], (-13.2112466f * r[24] + 0.732828109f * r[26] - q * nx) * ib,
                 (13.2112466f * r[2] + 0.732828109f * r[0] - q * ny) * ib,
                 (7.47340965f * r[25] - q * nz) * ib);
    q = lr * y[223];
    SHLIGHT_SET3(out_grad[223], (-13.7295302f * r[25] - q * nx) * ib,
                 (13.7295302f * r[1] - q * ny) * ib, (5.38516481f * r[26] - q * nz) * ib);
    q = lr * y[224];
    SHLIGHT_SET3(out_grad[224], (-14.2478068f * r[26] - q * nx) * ib,
                 (14.2478068f * r[0] - q * ny) * ib, -q * nz * ib);
  }
#endif
#if SHLIGHT_MAX_BANDS > 15
  if (n > 15) {
    lr = 15.0f * ir;
    r[0] = y[196] * ir;
    r[1] = y[197] * ir;
    r[2] = y[198] * ir;
    r[3] = y[199] * ir;
    r[4] = y[200] * ir;
    r[5] = y[201] * ir;
    r[6] = y[202] * ir;
    r[7] = y[203] * ir;
    r[8] = y[204] * ir;
    r[9] = y[205] * ir;
    r[10] = y[206] * ir;
    r[11] = y[207] * ir;
    r[12] = y[208] * ir;
    r[13] = y[209] * ir;
    r[14] = y[210] * ir;
    r[15] = y[211] * ir;
    r[16] = y[212] * ir;
    r[17] = y[213] * ir;
    r[18] = y[214] * ir;
    r[19] = y[215] * ir;
    r[20] = y[216] * ir;
    r[21] = y[217] * ir;
    r[22] = y[218] * ir;
    r[23] = y[219] * ir;
    r[24] = y[220] * ir;
    r[25] = y[221] * ir;
    r[26] = y[222] * ir;
    r[27] = y[223] * ir;
    r[28] = y[224] * ir;
    q = lr * y[225];
    SHLIGHT_SET3(out_grad[225], (-15.2479507f * r[0] - q * nx) * ib,
                 (-15.2479507f * r[28] - q * ny) * ib, -q * nz * ib);
    q = lr * y[226];
    SHLIGHT_SET3(out_grad[226], (-14.7309199f * r[1] - q * nx) * ib,
                 (-14.7309199f * r[27] - q * ny) * ib, (5.56776436f * r[0] - q * nz) * ib);
    q = lr * y[227];
    SHLIGHT_SET3(out_grad[227], (-14.2138835f * r[2] + 0.731083277f * r[0] - q * nx) * ib,
                 (-14.2138835f * r[26] + -0.731083277f * r[28] - q * ny) * ib,
                 (7.73705816f * r[1] - q * nz) * ib);
    q = lr * y[228];
    SHLIGHT_SET3(out_grad[228], (-13.6968408f * r[3] + 1.26627338f * r[1] - q * nx) * ib,
                 (-13.6968408f * r[25] + -1.26627338f * r[27] - q * ny) * ib,
                 (9.30517098f * r[2] - q * nz) * ib);
    q = lr * y[229];
    SHLIGHT_SET3(out_grad[229], (-13.1797912f * r[4] + 1.79078099f * r[2] - q * nx) * ib,
                 (-13.1797912f * r[24] + -1.79078099f * r[26] - q * ny) * ib,
                 (10.543833f * r[3] - q * nz) * ib);
    q = lr * y[230];
    SHLIGHT_SET3(out_grad[230], (-12.6627338f * r[5] + 2.31188832f * r[3] - q * nx) * ib,
                 (-12.6627338f * r[23] + -2.31188832f * r[25] - q * ny) * ib,
                 (11.5594416f * r[4] - q * nz) * ib);
    q = lr * y[231];
    SHLIGHT_SET3(out_grad[231], (-12.1456676f * r[6] + 2.83147336f * r[4] - q * nx) * ib,
                 (-12.1456676f * r[22] + -2.83147336f * r[24] - q * ny) * ib,
                 (12.4068946f * r[5] - q * nz) * ib);
    q = lr * y[232];
    SHLIGHT_SET3(out_grad[232], (-11.6285914f * r[7] + 3.35024446f * r[5] - q * nx) * ib,
                 (-11.6285914f * r[21] + -3.35024446f * r[23] - q * ny) * ib,
                 (13.1188204f * r[6] - q * nz) * ib);
    q = lr * y[233];
    SHLIGHT_SET3(out_grad[233], (-11.1115038f * r[8] + 3.86852908f * r[6] - q * nx) * ib,
                 (-11.1115038f * r[20] + -3.86852908f * r[22] - q * ny) * ib,
                 (13.7163381f * r[7] - q * nz) * ib);
    q = lr * y[234];
    SHLIGHT_SET3(out_grad[234], (-10.5944032f * r[9] + 4.38649966f * r[7] - q * nx) * ib,
                 (-10.5944032f * r[19] + -4.38649966f * r[21] - q * ny) * ib,
                 (14.2138835f * r[8] - q * nz) * ib);
    q = lr * y[235];
    SHLIGHT_SET3(out_grad[235], (-10.0772875f * r[10] + 4.90425572f * r[8] - q * nx) * ib,
                 (-10.0772875f * r[18] + -4.90425572f * r[20] - q * ny) * ib,
                 (14.6216655f * r[9] - q * nz) * ib);
    q = lr * y[236];
    SHLIGHT_SET3(out_grad[236], (-9.56015438f * r[11] + 5.4218587f * r[9] - q * nx) * ib,
                 (-9.56015438f * r[17] + -5.4218587f * r[19] - q * ny) * ib,
                 (14.9470329f * r[10] - q * nz) * ib);
    q = lr * y[237];
    SHLIGHT_SET3(out_grad[237], (-9.04300072f * r[12] + 5.93934862f * r[10] - q * nx) * ib,
                 (-9.04300072f * r[16] + -5.93934862f * r[18] - q * ny) * ib,
                 (15.1952806f * r[11] - q * nz) * ib);
    q = lr * y[238];
    SHLIGHT_SET3(out_grad[238], (-8.52582284f * r[13] + 6.45675268f * r[11] - q * nx) * ib,
                 (-8.52582284f * r[15] + -6.45675268f * r[17] - q * ny) * ib,
                 (15.3701457f * r[12] - q * nz) * ib);
    q = lr * y[239];
    SHLIGHT_SET3(out_grad[239], (6.97408998f * r[12] - q * nx) * ib,
                 (-11.3258934f * r[14] + -6.97408998f * r[16] - q * ny) * ib,
                 (15.4741163f * r[13] - q * nz) * ib);
    q = lr * y[240];
    SHLIGHT_SET3(out_grad[240], (10.5944032f * r[15] - q * nx) * ib,
                 (10.5944032f * r[13] - q * ny) * ib, (15.5086183f * r[14] - q * nz) * ib);
    q = lr * y[241];
    SHLIGHT_SET3(out_grad[241], (-11.3258934f * r[14] + 6.97408998f * r[16] - q * nx) * ib,
                 (6.97408998f * r[12] - q * ny) * ib, (15.4741163f * r[15] - q * nz) * ib);
    q = lr * y[242];
    SHLIGHT_SET3(out_grad[242], (-8.52582284f * r[15] + 6.45675268f * r[17] - q * nx) * ib,
                 (8.52582284f * r[13] + 6.45675268f * r[11] - q * ny) * ib,
                 (15.3701457f * r[16] - q * nz) * ib);
    q = lr * y[243];
    SHLIGHT_SET3(out_grad[243], (-9.04300072f * r[16] + 5.93934862f * r[18] - q * nx) * ib,
                 (9.04300072f * r[12] + 5.93934862f * r[10] - q * ny) * ib,
                 (15.1952806f * r[17] - q * nz) * ib);
    q = lr * y[244];
    SHLIGHT_SET3(out_grad[244], (-9.56015438f * r[17] + 5.4218587f * r[19] - q * nx) * ib,
                 (9.56015438f * r[11] + 5.4218587f * r[9] - q * ny) * ib,
                 (14.9470329f * r[18] - q * nz) * ib);
    q = lr * y[245];
    SHLIGHT_SET3(out_grad[245], (-10.0772875f * r[18] + 4.90425572f * r[20] - q * nx) * ib,
                 (10.0772875f * r[10] + 4.90425572f * r[8] - q * ny) * ib,
                 (14.6216655f * r[19] - q * nz) * ib);
    q = lr * y[246];
    SHLIGHT_SET3(out_grad[246], (-10.5944032f * r[19] + 4.38649966f * r[21] - q * nx) * ib,
                 (10.5944032f * r[9] + 4.38649966f * r[7] - q * ny) * ib,
                 (14.2138835f * r[20] - q * nz) * ib);
    q = lr * y[247];
    SHLIGHT_SET3(out_grad[247], (-11.1115038f * r[20] + 3.86852908f * r[22] - q * nx) * ib,
                 (11.1115038f * r[8] + 3.86852908f * r[6] - q * ny) * ib,
                 (13.7163381f * r[21] - q * nz) * ib);
    q = lr * y[248];
    SHLIGHT_SET3(out_grad[248], (-11.6285914f * r[21] + 3.35024446f * r[23] - q * nx) * ib,
                 (11.6285914f * r[7] + 3.35024446f * r[5] - q * ny) * ib,
                 (13.1188204f * r[22] - q * nz) * ib);
    q = lr * y[249];
    SHLIGHT_SET3(out_grad[249], (-12.1456676f * r[22] + 2.83147336f * r[24] - q * nx) * ib,
                 (12.1456676f * r[6] + 2.83147336f * r[4] - q * ny) * ib,
                 (12.4068946f * r[23] - q * nz) * ib);
    q = lr * y[250];
    SHLIGHT_SET3(out_grad[250], (-12.6627338f * r[23] + 2.31188832f * r[25] - q * nx) * ib,
                 (12.6627338f * r[5] + 2.31188832f * r[3] - q * ny) * ib,
                 (11.5594416f * r[24] - q * nz) * ib);
    q = lr * y[251];
    SHLIGHT_SET3(out_grad[251], (-13.1797912f * r[24] + 1.79078099f * r[26] - q * nx) * ib,
                 (13.1797912f * r[4] + 1.79078099f * r[2] - q * ny) * ib,
                 (10.543833f * r[25] - q * nz) * ib);
    q = lr * y[252];
    SHLIGHT_SET3(out_grad[252], (-13.6968408f * r[25] + 1.26627338f * r[27] - q * nx) * ib,
                 (13.6968408f * r[3] + 1.26627338f * r[1] - q * ny) * ib,
                 (9.30517098f * r[26] - q * nz) * ib);
    q = lr * y[253];
    SHLIGHT_SET3(out_grad[253], (-14.2138835f * r[26] + 0.731083277f * r[28] - q * nx) * ib,
                 (14.2138835f * r[2] + 0.731083277f * r[0] - q * ny) * ib,
                 (7.73705816f * r[27] - q * nz) * ib);
    q = lr * y[254];
    SHLIGHT_SET3(out_grad[254], (-14.7309199f * r[27] - q * nx) * ib,
                 (14.7309199f * r[1] - q * ny) * ib, (5.56776436f * r[28] - q * nz) * ib);
    q = lr * y[255];
    SHLIGHT_SET3(out_grad[255], (-15.2479507f * r[28] - q * nx) * ib,
                 (15.2479507f * r[0] - q * ny) * ib, -q * nz * ib);
  }
#endif
}
/* @generated end gradient */

#if SHLIGHT_SIMD_EVAL
/* shl_sh_eval_grad for 3..16 bands with AVX-512 (C only; n = 2 is faster on the exact path,
   15.4 against 13.0 ns): 1 if |d|^2 is in [1e-30, 1e30] and the result is written, 0 (nothing
   written) otherwise: zero, NaN, Inf, tiny or huge d take the exact path. */
SHLIGHT_CPU_INLINE int shli_sh_eval_grad_avx512(int n, const float d[3], float *out_y,
                                                float (*out_grad)[3]) {
  /* |d|^2 in [1e-30, 1e30] (not NaN): the double square root and division, which the whole
     kernel waits on, replaced by rsqrt14 and one Newton step on the FMA residual, in double
     (|d|^2 of floats to 2^-53, 1 / |d| to 6e-9, a tenth of a float ulp, so each component
     of d / |d| is within about one float rounding, as on the exact path; a float prologue
     was as fast but 2 ulp off, which the Horner forms of n = 5, 6 turn into 1e-6) */
  __m128d xd = _mm_set_sd((double)d[0]);
  __m128d yd = _mm_set_sd((double)d[1]);
  __m128d zd = _mm_set_sd((double)d[2]);
  __m128d td = _mm_fmadd_sd(xd, xd, _mm_fmadd_sd(yd, yd, _mm_mul_sd(zd, zd)));
  double t = _mm_cvtsd_f64(td);
  if (t >= 1.0e-30 && t <= 1.0e30) {
    __m128d r0 = _mm_rsqrt14_sd(td, td);
    __m128d e = _mm_fmsub_sd(_mm_mul_sd(td, r0), r0, _mm_set_sd(1.0));
    __m128d rd = _mm_fnmadd_sd(_mm_mul_sd(r0, _mm_set_sd(0.5)), e, r0);
    float fx = (float)_mm_cvtsd_f64(_mm_mul_sd(xd, rd));
    float fy = (float)_mm_cvtsd_f64(_mm_mul_sd(yd, rd));
    float fz = (float)_mm_cvtsd_f64(_mm_mul_sd(zd, rd));
    float rf = (float)_mm_cvtsd_f64(rd);
    shli_sh_eval_xyz(n, fx, fy, fz, out_y);
    shli_sh_grad_avx512(n, out_y, fx, fy, fz, rf, 0, 0, 0, out_grad);
    return 1;
  }
  return 0;
}

#endif

SHLIGHT_INLINE void shl_sh_eval_grad(int n, const float d[3], float *out_y, float (*out_grad)[3]) {
  shli_real x = SHLIGHT_REAL(d[0]);
  shli_real y = SHLIGHT_REAL(d[1]);
  shli_real z = SHLIGHT_REAL(d[2]);
  shli_real mx = SHLIGHT_ABSR(x);
  shli_real im;
  shli_real iu;
  float ir;
  float ib;
  n = shli_bands(n);
  if (n < 1) {
    return;
  }
#if SHLIGHT_SIMD_EVAL
  /* n = 3, 4: 25.0 -> 18.2 and 38.7 -> 25.2 ns against the exact path and the scalar gradient */
  if (n >= 3 && n <= SHLIGHT_UNROLLED_BANDS && shli_sh_eval_grad_avx512(n, d, out_y, out_grad)) {
    return;
  }
#endif
#if SHLIGHT_REAL_WIDE
  /* double: squares of floats neither overflow nor underflow, no scaling needed */
  SHLIGHT_UNUSED(mx);
  iu = x * x + y * y + z * z;
  im = 1.0;
  if (!(iu > 0.0 && iu <= 1.0e300)) {
    /* zero, NaN or infinite (|d|^2 of a finite float is below 1.2e77) */
    x = 0.0;
    y = 0.0;
    z = 1.0;
    im = 0.0;
    iu = 1.0;
  }
#else
  if (SHLIGHT_ABSR(y) > mx) {
    mx = SHLIGHT_ABSR(y);
  }
  if (SHLIGHT_ABSR(z) > mx) {
    mx = SHLIGHT_ABSR(z);
  }
  if (!(SHLIGHT_ABSR(x) + SHLIGHT_ABSR(y) + SHLIGHT_ABSR(z) > 0.0 && mx <= SHLIGHT_REAL_MAX)) {
    /* zero, NaN (the sum is NaN) or infinite */
    x = 0.0;
    y = 0.0;
    z = 1.0;
    im = 0.0;
  } else {
    im = 1.0 / mx;
    x = x * im;
    y = y * im;
    z = z * im;
  }
  iu = x * x + y * y + z * z;
#endif
  iu = 1.0 / SHLIGHT_SQRTR(iu);
  x = x * iu;
  y = y * iu;
  z = z * iu;
  /* 1 / |d| (0 for the substituted direction); below |d| = 1e-30 the projection runs at unit
     radius and 1 / |d| is applied afterwards as two finite factors, so entries that fit in a
     float stay exact and the others overflow to +-inf (never inf * 0 or inf - inf) */
  iu = iu * im;
  ir = SHLIGHT_FLOAT(iu);
  ib = 1.0f;
  if (iu > 1.0e30) {
    ir = SHLIGHT_FLOAT(SHLIGHT_SQRTR(iu));
    ib = ir;
  }
  shli_sh_eval_xyz(n, SHLIGHT_FLOAT(x), SHLIGHT_FLOAT(y), SHLIGHT_FLOAT(z), out_y);
#if SHLIGHT_SIMD_EVAL
  if (n >= 5 && n <= SHLIGHT_UNROLLED_BANDS && ib == 1.0f) {
    shli_sh_grad_avx512(n, out_y, SHLIGHT_FLOAT(x), SHLIGHT_FLOAT(y), SHLIGHT_FLOAT(z), ir, 0, 0, 0,
                        out_grad);
    return;
  }
#endif
  /* one call (a second inlined copy and a rescaling loop over out_grad cost a shader ~100x
     its compile time): ib = 1 leaves every output exact */
  shli_sh_grad(n, out_y, SHLIGHT_FLOAT(x), SHLIGHT_FLOAT(y), SHLIGHT_FLOAT(z), ir, ib, out_grad);
}

#ifdef SHLIGHT_REFERENCE_FORMS
SHLIGHT_INLINE void shl_sh_eval_grad_spherical(int n, const float d[3], float *out_y,
                                               float *out_dtheta, float *out_dphi) {
  shli_real x = SHLIGHT_REAL(d[0]);
  shli_real y = SHLIGHT_REAL(d[1]);
  shli_real z = SHLIGHT_REAL(d[2]);
  shli_real mx = SHLIGHT_ABSR(x);
  shli_real r;
  shli_real st;
  shli_real cp;
  shli_real sp;
  shli_real pc = 1.0;
  shli_real ps = 0.0;
  shli_real wc = 0.0;
  shli_real ws = 0.0;
  shli_real qc;
  shli_real xm = 0.28209479177387814;
  shli_real x1;
  shli_real x2;
  shli_real xl;
  shli_real z1;
  shli_real z2;
  shli_real zl;
  shli_real al;
  shli_real be;
  shli_real fm;
  int m;
  int l;
  int b;
  n = shli_bands(n);
  if (n < 1) {
    return;
  }
  if (SHLIGHT_ABSR(y) > mx) {
    mx = SHLIGHT_ABSR(y);
  }
  if (SHLIGHT_ABSR(z) > mx) {
    mx = SHLIGHT_ABSR(z);
  }
  if (!(SHLIGHT_ABSR(x) + SHLIGHT_ABSR(y) + SHLIGHT_ABSR(z) > 0.0 && mx <= SHLIGHT_REAL_MAX)) {
    x = 0.0;
    y = 0.0;
    z = 1.0;
    mx = 1.0;
  }
  x = x / mx;
  y = y / mx;
  z = z / mx;
  r = SHLIGHT_SQRTR(x * x + y * y + z * z);
  x = x / r;
  y = y / r;
  z = z / r;
  st = SHLIGHT_SQRTR(x * x + y * y);
  cp = 1.0;
  sp = 0.0;
  if (st > 0.0) {
    cp = x / st;
    sp = y / st;
  }
  for (m = 0; m < n; ++m) {
    fm = SHLIGHT_REAL(SHLIGHT_ITOF(m));
    if (m > 0) {
      /* w = (x + iy)^(m-1) e^(i phi) = sin^(m-1) e^(i m phi); p = (x + iy)^m */
      wc = pc * cp - ps * sp;
      ws = pc * sp + ps * cp;
      qc = x * pc - y * ps;
      ps = x * ps + y * pc;
      pc = qc;
      xm = xm * -SHLIGHT_SQRTR((2.0 * fm + 1.0) / (2.0 * fm));
      if (m == 1) {
        xm = xm * 1.4142135623730951;
      }
    }
    x2 = 0.0;
    x1 = 0.0;
    z2 = 0.0;
    z1 = 0.0;
    for (l = m; l < n; ++l) {
      if (l == m) {
        xl = xm;
        zl = 0.0;
      } else {
        al = SHLIGHT_SQRTR(SHLIGHT_REAL(SHLIGHT_ITOF((2 * l + 1) * (2 * l - 1))) /
                           SHLIGHT_REAL(SHLIGHT_ITOF((l - m) * (l + m))));
        be = 0.0;
        if (l > m + 1) {
          be = SHLIGHT_SQRTR(SHLIGHT_REAL(SHLIGHT_ITOF((2 * l + 1) * (l + m - 1) * (l - m - 1))) /
                             SHLIGHT_REAL(SHLIGHT_ITOF((2 * l - 3) * (l - m) * (l + m))));
        }
        xl = al * z * x1 - be * x2;
        zl = al * (z * z1 - st * x1) - be * z2;
      }
      b = l * (l + 1);
      out_y[b + m] = SHLIGHT_FLOAT(xl * pc);
      out_dtheta[b + m] = SHLIGHT_FLOAT(fm * z * xl * wc + zl * pc);
      out_dphi[b + m] = SHLIGHT_FLOAT(-fm * xl * ps);
      if (m > 0) {
        out_y[b - m] = SHLIGHT_FLOAT(xl * ps);
        out_dtheta[b - m] = SHLIGHT_FLOAT(fm * z * xl * ws + zl * ps);
        out_dphi[b - m] = SHLIGHT_FLOAT(fm * xl * pc);
      }
      x2 = x1;
      x1 = xl;
      z2 = z1;
      z1 = zl;
    }
  }
}
#endif

#ifdef SHLIGHT_REFERENCE_FORMS
SHLIGHT_INLINE void shl_sh_grad_from_spherical(int n, const float d[3], const float *dtheta,
                                               const float *dphi, float (*out_grad)[3]) {
  shli_real x = SHLIGHT_REAL(d[0]);
  shli_real y = SHLIGHT_REAL(d[1]);
  shli_real z = SHLIGHT_REAL(d[2]);
  shli_real rxy2 = x * x + y * y;
  shli_real r2 = rxy2 + z * z;
  shli_real rxy = SHLIGHT_SQRTR(rxy2);
  float tx = 0.0f;
  float ty = 0.0f;
  float tz = 0.0f;
  float px = 0.0f;
  float py = 0.0f;
  int i;
  n = shli_bands(n);
  if (n < 1) {
    return;
  }
  if (rxy > 0.0 && r2 <= SHLIGHT_REAL_MAX) {
    tx = SHLIGHT_FLOAT(z * x / (r2 * rxy));
    ty = SHLIGHT_FLOAT(z * y / (r2 * rxy));
    tz = SHLIGHT_FLOAT(-rxy / r2);
    px = SHLIGHT_FLOAT(-y / rxy2);
    py = SHLIGHT_FLOAT(x / rxy2);
  }
  for (i = 0; i < n * n; ++i) {
    out_grad[i][0] = dtheta[i] * tx + dphi[i] * px;
    out_grad[i][1] = dtheta[i] * ty + dphi[i] * py;
    out_grad[i][2] = dtheta[i] * tz;
  }
}
#endif

/* >>zonal -----------------------------------------------------------------------------------
   Zonal harmonics (ZH) of a uniform spherical cap and the ZH -> SH rotation (docs/math.md section
   2, [GRAD] eq. 9-11, 14-16 with correction E4 (docs/math.md section 12) applied). A sphere of
   radius r seen from distance d covers the cap of half-angle a, s = sin a = min(r / d, 1), alpha =
   cos a. The unit-radiance cap about +z projects onto band l as L_0 = sqrt(pi) (1 - alpha)  =
   sqrt(pi) s^2 / (1 + alpha) L_l = sqrt(pi / (2l+1)) (P_{l-1}(alpha) - P_{l+1}(alpha)) = sqrt(pi
   (2l+1)) / (l (l+1)) s^2 P'_l(alpha)                       (l >= 1) The second forms have no
   cancellation: alpha = sqrt((d - r)(d + r)) / d, and P'_{l+1} = P'_{l-1} + (2l+1) P_l sums
   positive terms near alpha = 1 (small caps). The printed first forms lose everything to 1 - alpha
   for small caps (float: every L_l = 0 below s = 2.4e-4); shl_zh_cap_printed keeps them as the
   comparison point. Common domain of the cap kernels: r and d in float; r <= 0 or NaN (no light),
   NaN or infinite d: every output 0. d <= r (the point on or inside the sphere): the hemisphere, s
   = 1, alpha = 0, which is the limit at the sphere's surface. Internal precision shli_real (double
   in C, float in GLSL). */

/* Per band l < 64: (2l+1)/(l+1), l/(l+1), 1/(l(l+1)) (0 for l = 0), sqrt(4 pi/(2l+1)),
   sqrt(pi(2l+1)): the Legendre recurrence and the ZH normalisations without divisions
   (tools/gen_basis.py; the GLSL twin holds the first 16 bands). */
/* @generated begin zh_tab */
/* clang-format off */
static const shli_real SHLI_ZH_TAB[320] = {
  1.0, 0.0, 0.0, 3.5449077018110318, 1.7724538509055159,
  1.5, 0.5, 0.5, 2.046653415892977, 3.0699801238394655,
  1.6666666666666667, 0.6666666666666666, 0.16666666666666666, 1.5853309190424043, 3.963327297606011,
  1.75, 0.75, 0.08333333333333333, 1.3398491713813576, 4.689472099834751,
  1.8, 0.8, 0.05, 1.1816359006036774, 5.317361552716548,
  1.8333333333333333, 0.8333333333333334, 0.03333333333333333, 1.0688298875771143, 5.878564381674128,
  1.8571428571428572, 0.8571428571428571, 0.023809523809523808, 0.9831804988974527, 6.390673242833443,
  1.875, 0.875, 0.017857142857142856, 0.9152912328637689, 6.864684246478267,
  1.8888888888888888, 0.8888888888888888, 0.013888888888888888, 0.8597664051548494, 7.308014443816219,
  1.9, 0.9, 0.011111111111111112, 0.8132576019143845, 7.7259472181866515,
  1.9090909090909092, 0.9090909090909091, 0.00909090909090909, 0.7735622797705238, 8.1224039375905,
  1.9166666666666667, 0.9166666666666666, 0.007575757575757576, 0.7391643523295388, 8.500390051789697,
  1.9230769230769231, 0.9230769230769231, 0.00641025641025641, 0.7089815403622064, 8.86226925452758,
  1.9285714285714286, 0.9285714285714286, 0.005494505494505495, 0.682217805297659, 9.209940371518396,
  1.9333333333333333, 0.9333333333333333, 0.004761904761904762, 0.6582728344942353, 9.544956100166413,
  1.9375, 0.9375, 0.004166666666666667, 0.6366842184408109, 9.868605385832568,
  1.9411764705882353, 0.9411764705882353, 0.003676470588235294, 0.6170892233105644, 10.181972184624312,
  1.9444444444444444, 0.9444444444444444, 0.0032679738562091504, 0.5991987653610963, 10.485978393819185,
  1.9473684210526316, 0.9473684210526315, 0.0029239766081871343, 0.5827792362686951, 10.78141587097086,
  1.95, 0.95, 0.002631578947368421, 0.5676395257004349, 11.06897075115848,
  1.9523809523809523, 0.9523809523809523, 0.002380952380952381, 0.5536215713397219, 11.349242212464297,
  1.9545454545454546, 0.9545454545454546, 0.0021645021645021645, 0.5405933564872216, 11.622757164475265,
  1.9565217391304348, 0.9565217391304348, 0.001976284584980237, 0.5284436396808014, 11.889981892818033,
  1.9583333333333333, 0.9583333333333334, 0.0018115942028985507, 0.5170779317854871, 12.151331396958948,
  1.96, 0.96, 0.0016666666666666668, 0.5064153859730045, 12.407176956338612,
  1.9615384615384615, 0.9615384615384616, 0.0015384615384615385, 0.4963863654563491, 12.657852319136902,
  1.962962962962963, 0.9629629629629629, 0.0014245014245014246, 0.4869305210668145, 12.903658808270585,
  1.9642857142857142, 0.9642857142857143, 0.0013227513227513227, 0.47799525700117707, 13.14486956753237,
  1.9655172413793103, 0.9655172413793104, 0.0012315270935960591, 0.46953449538577935, 13.381733118494711,
  1.9666666666666666, 0.9666666666666667, 0.0011494252873563218, 0.46150767322631336, 13.614476360176244,
  1.967741935483871, 0.967741935483871, 0.001075268817204301, 0.4538789217899773, 13.843307114594309,
  1.96875, 0.96875, 0.0010080645161290322, 0.44661639046045254, 14.068416299504255,
  1.9696969696969697, 0.9696969696969697, 0.000946969696969697, 0.43969168593737223, 14.289979792964598,
  1.9705882352941178, 0.9705882352941176, 0.00089126559714795, 0.4330794042246407, 14.508160041525464,
  1.9714285714285715, 0.9714285714285714, 0.0008403361344537816, 0.42675673779283463, 14.723107453852794,
  1.9722222222222223, 0.9722222222222222, 0.0007936507936507937, 0.42070314404994585, 14.934961613773078,
  1.972972972972973, 0.972972972972973, 0.0007507507507507507, 0.4149000641243619, 15.14385234053921,
  1.9736842105263157, 0.9736842105263158, 0.0007112375533428165, 0.4093306831785954, 15.349900619197326,
  1.9743589743589745, 0.9743589743589743, 0.0006747638326585695, 0.4039797251945956, 15.55321941999193,
  1.975, 0.975, 0.000641025641025641, 0.39883327652070694, 15.753914422567926,
  1.975609756097561, 0.975609756097561, 0.0006097560975609756, 0.3938786335345591, 15.952084658149644,
  1.9761904761904763, 0.9761904761904762, 0.0005807200929152149, 0.38910417062104186, 16.147823080773236,
  1.9767441860465116, 0.9767441860465116, 0.0005537098560354374, 0.38449922533937375, 16.341217076923385,
  1.9772727272727273, 0.9772727272727273, 0.0005285412262156448, 0.3800539981954647, 16.532348921502717,
  1.9777777777777779, 0.9777777777777777, 0.000505050505050505, 0.37575946487379114, 16.721296186883706,
  1.9782608695652173, 0.9782608695652174, 0.0004830917874396135, 0.3716072991387248, 16.90813211081198,
  1.9787234042553192, 0.9787234042553191, 0.00046253469010175765, 0.3675898049055887, 17.09292592810987,
  1.9791666666666667, 0.9791666666666666, 0.0004432624113475177, 0.3636998562198054, 17.275743170440755,
  1.9795918367346939, 0.9795918367346939, 0.00042517006802721087, 0.35993084407864623, 17.45664593781434,
  1.98, 0.98, 0.00040816326530612246, 0.3562766291923714, 17.635693145022387,
  1.9803921568627452, 0.9803921568627451, 0.000392156862745098, 0.3527314999163799, 17.812940745777187,
  1.9807692307692308, 0.9807692307692307, 0.0003770739064856712, 0.3492901346984507, 17.98844193697021,
  1.9811320754716981, 0.9811320754716981, 0.000362844702467344, 0.34594756847932034, 18.162247345164317,
  1.9814814814814814, 0.9814814814814815, 0.00034940600978336826, 0.3426991625639729, 18.33440519717255,
  1.981818181818182, 0.9818181818181818, 0.0003367003367003367, 0.33954057754775097, 18.504961476352427,
  1.9821428571428572, 0.9821428571428571, 0.0003246753246753247, 0.33646774893785564, 18.673960066050988,
  1.9824561403508771, 0.9824561403508771, 0.0003132832080200501, 0.33347686515873765, 18.841442881468677,
  1.9827586206896552, 0.9827586206896551, 0.00030248033877797946, 0.33056434767069076, 19.00744999106472,
  1.9830508474576272, 0.9830508474576272, 0.0002922267679719462, 0.32772683296581756, 19.172019728500327,
  1.9833333333333334, 0.9833333333333333, 0.0002824858757062147, 0.32496115623539035, 19.335188796005728,
  1.9836065573770492, 0.9836065573770492, 0.000273224043715847, 0.32226433652827563, 19.496992359960675,
  1.9838709677419355, 0.9838709677419355, 0.00026441036488630354, 0.319633563242172, 19.65746413939358,
  1.9841269841269842, 0.9841269841269841, 0.0002560163850486431, 0.3170661838084809, 19.816636488030053,
  1.984375, 0.984375, 0.000248015873015873, 0.31455969244813353, 19.97454047045648
};
/* clang-format on */
/* @generated end zh_tab */

/* Geometry of a sphere seen from a point, in shli_real: (dx, dy, dz) = c - x, r = radius.
   out_g[0..2]: unit axis (c - x) / |c - x|, (0, 0, 1) when x == c;
   out_g[3]: 1 / |c - x|, capped at 1e20 (0 when x == c); out_g[4]: s^2 = min(r / |c - x|, 1)^2;
   out_g[5]: alpha = sqrt((d - r)(d + r)) / d, 0 on or inside the sphere;
   out_g[6]: 1 for a light, 0 for none (rr <= 0 or NaN, c - x NaN or infinite: out_g[0..5]
   then hold the values of an empty cap about +z). With shli_real = float (GLSL) the
   difference is scaled by its largest component first, so |c - x|^2 neither overflows nor
   underflows; double needs no scaling (squares of floats fit). */
SHLIGHT_INLINE void shli_cap_frame(shli_real dx, shli_real dy, shli_real dz, shli_real r,
                                   shli_real *out_g) {
  shli_real rr = r;
  shli_real mx = 1.0;
  shli_real dd;
  shli_real sm = SHLIGHT_ABSR(dx) + SHLIGHT_ABSR(dy) + SHLIGHT_ABSR(dz);
  shli_real u;
  shli_real iu;
  shli_real s;
  out_g[0] = 0.0;
  out_g[1] = 0.0;
  out_g[2] = 1.0;
  out_g[3] = 0.0;
  out_g[4] = 0.0;
  out_g[5] = 1.0;
  out_g[6] = 0.0;
  if (!(rr > 0.0) || !(sm <= SHLIGHT_REAL_MAX)) {
    return;
  }
  out_g[6] = 1.0;
  if (!(sm > 0.0)) {
    /* x == c: inside, the hemisphere about +z */
    out_g[4] = 1.0;
    out_g[5] = 0.0;
    return;
  }
#if !SHLIGHT_REAL_WIDE
  mx = SHLIGHT_ABSR(dx);
  if (SHLIGHT_ABSR(dy) > mx) {
    mx = SHLIGHT_ABSR(dy);
  }
  if (SHLIGHT_ABSR(dz) > mx) {
    mx = SHLIGHT_ABSR(dz);
  }
  iu = 1.0 / mx;
  dx = dx * iu;
  dy = dy * iu;
  dz = dz * iu;
  rr = rr * iu;
#endif
  u = SHLIGHT_SQRTR(dx * dx + dy * dy + dz * dz);
  iu = 1.0 / u;
  out_g[0] = dx * iu;
  out_g[1] = dy * iu;
  out_g[2] = dz * iu;
  /* dd = |c - x| unscaled: d - r is then exact near the surface (Sterbenz), with no second
     rounding of r; the relative forms (d -+ r) / d neither overflow nor underflow */
  dd = mx * u;
  out_g[3] = 1.0e20;
  if (dd > 1.0e-20) {
    out_g[3] = iu / mx;
  }
  if (r >= dd) {
    out_g[4] = 1.0;
    out_g[5] = 0.0;
  } else {
    s = rr * iu;
    out_g[4] = s * s;
#if SHLIGHT_REAL_WIDE
    /* double: (d - r)(d + r) of floats neither overflows nor underflows; one division less */
    out_g[5] = SHLIGHT_SQRTR((dd - r) * (dd + r)) * iu;
#else
    out_g[5] = SHLIGHT_SQRTR(((dd - r) / dd) * ((dd + r) / dd));
#endif
  }
}

SHLIGHT_INLINE void shl_zh_cap(int n, float r, float d, float *out_zh) {
  shli_real g[8];
  shli_real f;
  shli_real al;
  shli_real fl;
  shli_real pm = 1.0;
  shli_real pl;
  shli_real pn;
  shli_real dm = 0.0;
  shli_real dl = 1.0;
  shli_real dn;
  int l;
  n = shli_bands(n);
  if (n < 1) {
    return;
  }
  shli_cap_frame(0.0, 0.0, SHLIGHT_REAL(d), SHLIGHT_REAL(r), g);
  if (!(SHLIGHT_REAL(d) >= 0.0)) {
    g[4] = 0.0; /* negative d: no light (a NaN d is caught by shli_cap_frame) */
  }
  al = g[5];
  f = g[4];
  out_zh[0] = SHLIGHT_FLOAT(1.7724538509055160 * f / (1.0 + al));
  pl = al;
  fl = 1.0;
  for (l = 1; l < n; ++l) {
    /* pl = P_l, pm = P_{l-1}, dl = P'_l, dm = P'_{l-1}; fl = l */
    out_zh[l] = SHLIGHT_FLOAT(f * dl * (SHLI_ZH_TAB[5 * l + 2] * SHLI_ZH_TAB[5 * l + 4]));
    dn = dm + (2.0 * fl + 1.0) * pl;
    pn = SHLI_ZH_TAB[5 * l] * al * pl - SHLI_ZH_TAB[5 * l + 1] * pm;
    dm = dl;
    dl = dn;
    pm = pl;
    pl = pn;
    fl = fl + 1.0;
  }
}

SHLIGHT_INLINE void shl_zh_cap_derivative(int n, float r, float d, float *out_dzh) {
  shli_real g[8];
  shli_real s;
  shli_real al;
  shli_real pm = 1.0;
  shli_real pl = 1.0;
  shli_real pn;
  int l;
  n = shli_bands(n);
  if (n < 1) {
    return;
  }
  shli_cap_frame(0.0, 0.0, SHLIGHT_REAL(d), SHLIGHT_REAL(r), g);
  if (!(SHLIGHT_REAL(d) >= 0.0)) {
    g[4] = 0.0;
  }
  s = SHLIGHT_SQRTR(g[4]);
  al = g[5];
  for (l = 0; l < n; ++l) {
    /* pl = P_l, pm = P_{l-1} */
    out_dzh[l] = SHLIGHT_FLOAT(SHLI_ZH_TAB[5 * l + 4] * pl * s);
    pn = SHLI_ZH_TAB[5 * l] * al * pl - SHLI_ZH_TAB[5 * l + 1] * pm;
    pm = pl;
    pl = pn;
  }
}

#ifdef SHLIGHT_REFERENCE_FORMS
SHLIGHT_INLINE void shl_zh_cap_printed(int n, float r, float d, float *out_zh) {
  float s = 0.0f;
  float al;
  float fl;
  float pm = 1.0f;
  float pl;
  float pn;
  int l;
  n = shli_bands(n);
  if (n < 1) {
    return;
  }
  if (r > 0.0f && d >= 0.0f && d <= 3.4028234e38f) {
    s = 1.0f;
    if (d > r) {
      s = r / d;
    }
  }
  al = SHLIGHT_FLOAT(SHLIGHT_SQRTR(SHLIGHT_REAL(1.0f - s * s)));
  out_zh[0] = 1.77245385f * (1.0f - al);
  /* walk P_{l-1}, P_l, P_{l+1} */
  pl = al;
  fl = 1.0f;
  for (l = 1; l < n; ++l) {
    pn = ((2.0f * fl + 1.0f) * al * pl - fl * pm) / (fl + 1.0f);
    out_zh[l] =
        SHLIGHT_FLOAT(SHLIGHT_SQRTR(SHLIGHT_REAL(3.14159265f / (2.0f * fl + 1.0f)))) * (pm - pn);
    pm = pl;
    pl = pn;
    fl = fl + 1.0f;
  }
}
#endif

SHLIGHT_INLINE void shl_zh_rotate(int n, const float *zh, const float dir[3], float *out_sh) {
  shli_real g[8];
  shli_real t;
  float k;
  int l;
  int m;
  int b;
  n = shli_bands(n);
  if (n < 1) {
    return;
  }
  shli_cap_frame(SHLIGHT_REAL(dir[0]), SHLIGHT_REAL(dir[1]), SHLIGHT_REAL(dir[2]), 1.0, g);
  shli_sh_eval_xyz(n, SHLIGHT_FLOAT(g[0]), SHLIGHT_FLOAT(g[1]), SHLIGHT_FLOAT(g[2]), out_sh);
  for (l = 0; l < n; ++l) {
    k = SHLIGHT_FLOAT(SHLI_ZH_TAB[5 * l + 3]);
    b = l * (l + 1);
    if (!(SHLIGHT_ABSR(SHLIGHT_REAL(zh[l])) >= 1.0e30)) {
      k = k * zh[l];
      for (m = -l; m <= l; ++m) {
        out_sh[b + m] = k * out_sh[b + m];
      }
    } else {
      /* |sqrt(4 pi / (2l+1)) Y_l^m| <= 1 (Unsold): k Y first, so a zh[l] near FLT_MAX does
         not overflow before the product that fits; the rounding of k Y (1 + 1e-7 for l = 0)
         can still carry it past FLT_MAX: saturated */
      for (m = -l; m <= l; ++m) {
        t = SHLIGHT_REAL(k * out_sh[b + m]) * SHLIGHT_REAL(zh[l]);
        if (t > SHLIGHT_REAL_MAX) {
          t = SHLIGHT_REAL_MAX;
        }
        if (t < -SHLIGHT_REAL_MAX) {
          t = -SHLIGHT_REAL_MAX;
        }
        out_sh[b + m] = SHLIGHT_FLOAT(t);
      }
    }
  }
}

SHLIGHT_INLINE void shl_sh_rotate(int n, const float R[9], const float *sh, float *out_sh) {
  shli_real pc[2 * SHLIGHT_MAX_BANDS];
  shli_real ps[2 * SHLIGHT_MAX_BANDS];
  shli_real ca[SHLIGHT_MAX_BANDS];
  shli_real sa[SHLIGHT_MAX_BANDS];
  shli_real cg[SHLIGHT_MAX_BANDS];
  shli_real sg[SHLIGHT_MAX_BANDS];
  shli_real u1[SHLIGHT_MAX_BANDS];
  shli_real u2[SHLIGHT_MAX_BANDS];
  shli_real v1[SHLIGHT_MAX_BANDS];
  shli_real v2[SHLIGHT_MAX_BANDS];
  shli_real q1[SHLIGHT_MAX_BANDS];
  shli_real b2[SHLIGHT_MAX_BANDS];
  shli_real bc;
  shli_real sb;
  shli_real cb;
  shli_real c1;
  shli_real s1;
  shli_real t;
  shli_real h;
  shli_real bq;
  shli_real uq;
  shli_real vq;
  shli_real qq;
  shli_real w;
  shli_real ac;
  shli_real as;
  shli_real yc;
  shli_real ys;
  shli_real fl;
  shli_real fm;
  shli_real fp;
  int mp;
  int l;
  int m;
  int k;
  int q;
  n = shli_bands(n);
  if (n < 1) {
    return;
  }
  /* beta: sin from R's third column (accurate near 0 and pi), cos = R_22 */
  sb = SHLIGHT_SQRTR(SHLIGHT_REAL(R[2]) * SHLIGHT_REAL(R[2]) +
                     SHLIGHT_REAL(R[5]) * SHLIGHT_REAL(R[5]));
  cb = SHLIGHT_REAL(R[8]);
  h = SHLIGHT_SQRTR(sb * sb + cb * cb);
  c1 = 1.0;
  s1 = 0.0;
  if (sb > 0.0) {
    c1 = SHLIGHT_REAL(R[2]) / sb;
    s1 = SHLIGHT_REAL(R[5]) / sb;
  }
  if (h > 0.0) {
    sb = sb / h;
    cb = cb / h;
  } else {
    cb = 1.0;
  }
  /* alpha's cos, sin: c1, s1; gamma's: the second row of Rz(-alpha) R = (sin g, cos g, 0) */
  ca[0] = 1.0;
  sa[0] = 0.0;
  t = SHLIGHT_REAL(R[1]) * (-s1) + SHLIGHT_REAL(R[4]) * c1;
  w = SHLIGHT_REAL(R[0]) * (-s1) + SHLIGHT_REAL(R[3]) * c1;
  h = SHLIGHT_SQRTR(t * t + w * w);
  cg[0] = 1.0;
  sg[0] = 0.0;
  if (h > 0.0) {
    t = t / h;
    w = w / h;
  } else {
    t = 1.0;
  }
  /* no constant index above 0: GLSL rejects it at SHLIGHT_MAX_BANDS = 1 even where unreached */
  for (m = 1; m < n; ++m) {
    ca[m] = ca[m - 1] * c1 - sa[m - 1] * s1;
    sa[m] = sa[m - 1] * c1 + ca[m - 1] * s1;
    cg[m] = cg[m - 1] * t - sg[m - 1] * w;
    sg[m] = sg[m - 1] * t + cg[m - 1] * w;
  }
  /* half angles: cos(beta / 2), sin(beta / 2), each from the better-conditioned side */
  if (cb >= 0.0) {
    c1 = SHLIGHT_SQRTR(0.5 * (1.0 + cb));
    s1 = 0.5 * sb / c1;
  } else {
    s1 = SHLIGHT_SQRTR(0.5 * (1.0 - cb));
    c1 = 0.5 * sb / s1;
  }
  pc[0] = 1.0;
  ps[0] = 1.0;
  for (k = 1; k < 2 * n - 1; ++k) {
    pc[k] = pc[k - 1] * c1;
    ps[k] = ps[k - 1] * s1;
  }
  bc = 1.0;
  for (mp = 0; mp < n; ++mp) {
    fp = SHLIGHT_ITOR(mp);
    /* b2[m] = C(2q, q + p), q = max(m, m'), p = min(m, m'), by ratios from C(2m', m') */
    b2[0] = bc;
    for (m = 0; m + 1 < n; ++m) {
      fm = SHLIGHT_ITOR(m);
      if (m < mp) {
        b2[m + 1] = b2[m] * (fp - fm) / (fp + fm + 1.0);
      } else {
        b2[m + 1] =
            b2[m] * (2.0 * fm + 2.0) * (2.0 * fm + 1.0) / ((fm + fp + 1.0) * (fm - fp + 1.0));
      }
    }
    bc = bc * (2.0 * fp + 2.0) * (2.0 * fp + 1.0) / ((fp + 1.0) * (fp + 1.0));
    for (l = mp; l < n; ++l) {
      fl = SHLIGHT_ITOR(l);
      k = l * (l + 1);
      /* carry the pairs started below band l: d^l = ((2l - 1) (l (l - 1) cos b -+ m m')
         d^(l-1) - l S_(l-1) d^(l-2)) / ((l - 1) S_l), S_l = sqrt((l^2 - m^2)(l^2 - m'^2)) */
      q = l;
      if (l == mp) {
        q = 0;
      }
      if (l == 1 && mp == 0) {
        u2[0] = u1[0];
        v2[0] = v1[0];
        q1[0] = 1.0;
        u1[0] = cb;
        v1[0] = cb;
        q = 1;
      }
      w = (2.0 * fl - 1.0) * fl * (fl - 1.0) * cb;
      h = (2.0 * fl - 1.0) * fp;
      for (m = 0; m < q && l > 1; ++m) {
        fm = SHLIGHT_ITOR(m);
        qq = SHLIGHT_SQRTR((fl * fl - fm * fm) * (fl * fl - fp * fp));
        t = 1.0 / ((fl - 1.0) * qq);
        uq = ((w - h * fm) * u1[m] - fl * q1[m] * u2[m]) * t;
        vq = ((w + h * fm) * v1[m] - fl * q1[m] * v2[m]) * t;
        u2[m] = u1[m];
        v2[m] = v1[m];
        u1[m] = uq;
        v1[m] = vq;
        q1[m] = qq;
      }
      /* start the pairs whose band l = max(m, m') is this one:
         u = d^q_{m' m} = +-B c^(q+p) s^(q-p), v = (-1)^m d^q_{m',-m} = (-1)^m' B c^(q-p) s^(q+p) */
      for (m = q; m <= l; ++m) {
        bq = SHLIGHT_SQRTR(b2[m]);
        uq = bq * pc[mp + m] * ps[l + l - mp - m];
        vq = bq * pc[l + l - mp - m] * ps[mp + m];
        if (mp > m && (mp - m) % 2 == 1) {
          uq = -uq;
        }
        if (mp % 2 == 1) {
          vq = -vq;
        }
        u2[m] = 0.0;
        v2[m] = 0.0;
        q1[m] = 0.0;
        u1[m] = uq;
        v1[m] = vq;
      }
      /* row m' of band l's real y rotation (cos block u + v, sin block u - v; sqrt 2 u where m
         or m' is 0) on the input after its z rotation by gamma */
      yc = 0.0;
      ys = 0.0;
      for (m = 1; m <= l; ++m) {
        ac = SHLIGHT_REAL(sh[k + m]);
        as = SHLIGHT_REAL(sh[k - m]);
        yc = yc + (u1[m] + v1[m]) * (ac * cg[m] - as * sg[m]);
        ys = ys + (u1[m] - v1[m]) * (ac * sg[m] + as * cg[m]);
      }
      ac = u1[0] * SHLIGHT_REAL(sh[k]);
      /* the output's z rotation (alpha) */
      if (mp == 0) {
        out_sh[k] = SHLIGHT_FLOAT(ac + 0.7071067811865476 * yc);
      } else {
        yc = yc + 1.4142135623730951 * ac;
        out_sh[k + mp] = SHLIGHT_FLOAT(yc * ca[mp] - ys * sa[mp]);
        out_sh[k - mp] = SHLIGHT_FLOAT(yc * sa[mp] + ys * ca[mp]);
      }
    }
  }
}

/* >>light -----------------------------------------------------------------------------------
   Unit-radiance lights seen from a shading point x: their SH (the projection of the
   indicator of the light's solid angle, so out_sh[0] = Omega Y_0^0 and the irradiance of a
   normal n follows by convolution with the clamped cosine) and its gradient with respect to
   x, out_grad[i][k] = d out_sh[i] / d x_k.
   Sphere light (centre c, radius r; [GRAD] eq. 9-14, docs/math.md section 2-3): with d = |c - x|,
   s = min(r / d, 1), alpha = sqrt((d - r)(d + r)) / d, w = (c - x) / d, and
     q_0 = 1 / (1 + alpha),  q_l = P'_l(alpha) / (l (l+1))                 (l >= 1)
     out_sh[l,m] = 2 pi s^2 q_l Y_l^m(w)        [= sqrt(4 pi / (2l+1)) L_l Y_l^m(w)]
     grad_x      = -2 pi s^2 q_l grad_d Y_l^m(w) + 2 pi s^2 P_l(alpha) / (d alpha) Y_l^m(w) w
   (docs/math.md section 3, "complete coefficient gradient, simplified"), grad_d Y from the
   pole-free Cartesian gradient of >>gradient. Inside and on the surface (d <= r): the value at the
   nearest surface point, i.e. the hemisphere about w; it is constant along rays from c, so its
   gradient is the rotational term only (radial derivative 0). The exact gradient is unbounded as d
   -> r+ (1 / alpha, genuinely singular); outside it stays finite because alpha >= ~1e-8 (C) / ~3e-4
   (GLSL) for any d > r representable. x == c: the hemisphere about +z, gradient 0. r <= 0 or NaN,
   NaN or infinite x or c: zeros (no light). 1 / |c - x| is capped at 1e20 in the gradient.
   Triangle light as a sphere ([GRAD] eq. 24-28): the sphere at the centroid with the
   triangle's area (r_s = sqrt(|e1 x e2| / (2 pi))), weighted by |cos gamma|, cos gamma the
   cosine between the triangle's normal and w (two-sided). This is the paper's far-field
   model: exact in L_0 only as d / sqrt(area) -> inf (docs/math.md section 4 table). The exact solid
   angle is shl_triangle_solid_angle. */

/* @generated begin light_idx */
#if SHLIGHT_SIMD_EVAL
/* clang-format off */
static const int SHLI_LIGHT_BAND[256] = {
  0, 1, 1, 1, 2, 2, 2, 2, 2, 3, 3, 3, 3, 3, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4, 4, 5, 5, 5, 5, 5, 5, 5,
  5, 5, 5, 5, 6, 6, 6, 6, 6, 6, 6, 6, 6, 6, 6, 6, 6, 7, 7, 7, 7, 7, 7, 7, 7, 7, 7, 7, 7, 7, 7, 7,
  8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 9, 9, 9, 9, 9, 9, 9, 9, 9, 9, 9, 9, 9, 9, 9,
  9, 9, 9, 9, 10, 10, 10, 10, 10, 10, 10, 10, 10, 10, 10, 10, 10, 10, 10, 10, 10, 10, 10, 10, 10, 11, 11, 11, 11, 11, 11, 11,
  11, 11, 11, 11, 11, 11, 11, 11, 11, 11, 11, 11, 11, 11, 11, 11, 12, 12, 12, 12, 12, 12, 12, 12, 12, 12, 12, 12, 12, 12, 12, 12,
  12, 12, 12, 12, 12, 12, 12, 12, 12, 13, 13, 13, 13, 13, 13, 13, 13, 13, 13, 13, 13, 13, 13, 13, 13, 13, 13, 13, 13, 13, 13, 13,
  13, 13, 13, 13, 14, 14, 14, 14, 14, 14, 14, 14, 14, 14, 14, 14, 14, 14, 14, 14, 14, 14, 14, 14, 14, 14, 14, 14, 14, 14, 14, 14,
  14, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15
};
/* clang-format on */
#endif

SHLIGHT_INLINE void shli_sh_band_weights(int n, const float *kv, const float *kg, const float *ka,
                                         const float *kb, const float *wg, float *io_sh,
                                         float (*io_grad)[3]) {
  float y;
  int i;
  int l;
  l = 0;
#if SHLIGHT_MAX_BANDS > SHLIGHT_UNROLLED_BANDS
  for (l = SHLIGHT_UNROLLED_BANDS; l < n; ++l) {
    for (i = l * l; i < (l + 1) * (l + 1); ++i) {
      y = io_sh[i];
      io_sh[i] = kv[l] * y;
      io_grad[i][0] = kg[l] * io_grad[i][0] + (ka[l] * wg[0] + kb[l] * wg[3]) * y;
      io_grad[i][1] = kg[l] * io_grad[i][1] + (ka[l] * wg[1] + kb[l] * wg[4]) * y;
      io_grad[i][2] = kg[l] * io_grad[i][2] + (ka[l] * wg[2] + kb[l] * wg[5]) * y;
    }
  }
#endif
  l = 0;
  for (i = 0; i < 1; ++i) {
    y = io_sh[i];
    io_sh[i] = kv[l] * y;
    io_grad[i][0] = kg[l] * io_grad[i][0] + (ka[l] * wg[0] + kb[l] * wg[3]) * y;
    io_grad[i][1] = kg[l] * io_grad[i][1] + (ka[l] * wg[1] + kb[l] * wg[4]) * y;
    io_grad[i][2] = kg[l] * io_grad[i][2] + (ka[l] * wg[2] + kb[l] * wg[5]) * y;
  }
#if SHLIGHT_MAX_BANDS > 1
  if (n > 1) {
    l = 1;
    for (i = 1; i < 4; ++i) {
      y = io_sh[i];
      io_sh[i] = kv[l] * y;
      io_grad[i][0] = kg[l] * io_grad[i][0] + (ka[l] * wg[0] + kb[l] * wg[3]) * y;
      io_grad[i][1] = kg[l] * io_grad[i][1] + (ka[l] * wg[1] + kb[l] * wg[4]) * y;
      io_grad[i][2] = kg[l] * io_grad[i][2] + (ka[l] * wg[2] + kb[l] * wg[5]) * y;
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 2
  if (n > 2) {
    l = 2;
    for (i = 4; i < 9; ++i) {
      y = io_sh[i];
      io_sh[i] = kv[l] * y;
      io_grad[i][0] = kg[l] * io_grad[i][0] + (ka[l] * wg[0] + kb[l] * wg[3]) * y;
      io_grad[i][1] = kg[l] * io_grad[i][1] + (ka[l] * wg[1] + kb[l] * wg[4]) * y;
      io_grad[i][2] = kg[l] * io_grad[i][2] + (ka[l] * wg[2] + kb[l] * wg[5]) * y;
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 3
  if (n > 3) {
    l = 3;
    for (i = 9; i < 16; ++i) {
      y = io_sh[i];
      io_sh[i] = kv[l] * y;
      io_grad[i][0] = kg[l] * io_grad[i][0] + (ka[l] * wg[0] + kb[l] * wg[3]) * y;
      io_grad[i][1] = kg[l] * io_grad[i][1] + (ka[l] * wg[1] + kb[l] * wg[4]) * y;
      io_grad[i][2] = kg[l] * io_grad[i][2] + (ka[l] * wg[2] + kb[l] * wg[5]) * y;
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 4
  if (n > 4) {
    l = 4;
    for (i = 16; i < 25; ++i) {
      y = io_sh[i];
      io_sh[i] = kv[l] * y;
      io_grad[i][0] = kg[l] * io_grad[i][0] + (ka[l] * wg[0] + kb[l] * wg[3]) * y;
      io_grad[i][1] = kg[l] * io_grad[i][1] + (ka[l] * wg[1] + kb[l] * wg[4]) * y;
      io_grad[i][2] = kg[l] * io_grad[i][2] + (ka[l] * wg[2] + kb[l] * wg[5]) * y;
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 5
  if (n > 5) {
    l = 5;
    for (i = 25; i < 36; ++i) {
      y = io_sh[i];
      io_sh[i] = kv[l] * y;
      io_grad[i][0] = kg[l] * io_grad[i][0] + (ka[l] * wg[0] + kb[l] * wg[3]) * y;
      io_grad[i][1] = kg[l] * io_grad[i][1] + (ka[l] * wg[1] + kb[l] * wg[4]) * y;
      io_grad[i][2] = kg[l] * io_grad[i][2] + (ka[l] * wg[2] + kb[l] * wg[5]) * y;
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 6
  if (n > 6) {
    l = 6;
    for (i = 36; i < 49; ++i) {
      y = io_sh[i];
      io_sh[i] = kv[l] * y;
      io_grad[i][0] = kg[l] * io_grad[i][0] + (ka[l] * wg[0] + kb[l] * wg[3]) * y;
      io_grad[i][1] = kg[l] * io_grad[i][1] + (ka[l] * wg[1] + kb[l] * wg[4]) * y;
      io_grad[i][2] = kg[l] * io_grad[i][2] + (ka[l] * wg[2] + kb[l] * wg[5]) * y;
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 7
  if (n > 7) {
    l = 7;
    for (i = 49; i < 64; ++i) {
      y = io_sh[i];
      io_sh[i] = kv[l] * y;
      io_grad[i][0] = kg[l] * io_grad[i][0] + (ka[l] * wg[0] + kb[l] * wg[3]) * y;
      io_grad[i][1] = kg[l] * io_grad[i][1] + (ka[l] * wg[1] + kb[l] * wg[4]) * y;
      io_grad[i][2] = kg[l] * io_grad[i][2] + (ka[l] * wg[2] + kb[l] * wg[5]) * y;
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 8
  if (n > 8) {
    l = 8;
    for (i = 64; i < 81; ++i) {
      y = io_sh[i];
      io_sh[i] = kv[l] * y;
      io_grad[i][0] = kg[l] * io_grad[i][0] + (ka[l] * wg[0] + kb[l] * wg[3]) * y;
      io_grad[i][1] = kg[l] * io_grad[i][1] + (ka[l] * wg[1] + kb[l] * wg[4]) * y;
      io_grad[i][2] = kg[l] * io_grad[i][2] + (ka[l] * wg[2] + kb[l] * wg[5]) * y;
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 9
  if (n > 9) {
    l = 9;
    for (i = 81; i < 100; ++i) {
      y = io_sh[i];
      io_sh[i] = kv[l] * y;
      io_grad[i][0] = kg[l] * io_grad[i][0] + (ka[l] * wg[0] + kb[l] * wg[3]) * y;
      io_grad[i][1] = kg[l] * io_grad[i][1] + (ka[l] * wg[1] + kb[l] * wg[4]) * y;
      io_grad[i][2] = kg[l] * io_grad[i][2] + (ka[l] * wg[2] + kb[l] * wg[5]) * y;
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 10
  if (n > 10) {
    l = 10;
    for (i = 100; i < 121; ++i) {
      y = io_sh[i];
      io_sh[i] = kv[l] * y;
      io_grad[i][0] = kg[l] * io_grad[i][0] + (ka[l] * wg[0] + kb[l] * wg[3]) * y;
      io_grad[i][1] = kg[l] * io_grad[i][1] + (ka[l] * wg[1] + kb[l] * wg[4]) * y;
      io_grad[i][2] = kg[l] * io_grad[i][2] + (ka[l] * wg[2] + kb[l] * wg[5]) * y;
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 11
  if (n > 11) {
    l = 11;
    for (i = 121; i < 144; ++i) {
      y = io_sh[i];
      io_sh[i] = kv[l] * y;
      io_grad[i][0] = kg[l] * io_grad[i][0] + (ka[l] * wg[0] + kb[l] * wg[3]) * y;
      io_grad[i][1] = kg[l] * io_grad[i][1] + (ka[l] * wg[1] + kb[l] * wg[4]) * y;
      io_grad[i][2] = kg[l] * io_grad[i][2] + (ka[l] * wg[2] + kb[l] * wg[5]) * y;
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 12
  if (n > 12) {
    l = 12;
    for (i = 144; i < 169; ++i) {
      y = io_sh[i];
      io_sh[i] = kv[l] * y;
      io_grad[i][0] = kg[l] * io_grad[i][0] + (ka[l] * wg[0] + kb[l] * wg[3]) * y;
      io_grad[i][1] = kg[l] * io_grad[i][1] + (ka[l] * wg[1] + kb[l] * wg[4]) * y;
      io_grad[i][2] = kg[l] * io_grad[i][2] + (ka[l] * wg[2] + kb[l] * wg[5]) * y;
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 13
  if (n > 13) {
    l = 13;
    for (i = 169; i < 196; ++i) {
      y = io_sh[i];
      io_sh[i] = kv[l] * y;
      io_grad[i][0] = kg[l] * io_grad[i][0] + (ka[l] * wg[0] + kb[l] * wg[3]) * y;
      io_grad[i][1] = kg[l] * io_grad[i][1] + (ka[l] * wg[1] + kb[l] * wg[4]) * y;
      io_grad[i][2] = kg[l] * io_grad[i][2] + (ka[l] * wg[2] + kb[l] * wg[5]) * y;
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 14
  if (n > 14) {
    l = 14;
    for (i = 196; i < 225; ++i) {
      y = io_sh[i];
      io_sh[i] = kv[l] * y;
      io_grad[i][0] = kg[l] * io_grad[i][0] + (ka[l] * wg[0] + kb[l] * wg[3]) * y;
      io_grad[i][1] = kg[l] * io_grad[i][1] + (ka[l] * wg[1] + kb[l] * wg[4]) * y;
      io_grad[i][2] = kg[l] * io_grad[i][2] + (ka[l] * wg[2] + kb[l] * wg[5]) * y;
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 15
  if (n > 15) {
    l = 15;
    for (i = 225; i < 256; ++i) {
      y = io_sh[i];
      io_sh[i] = kv[l] * y;
      io_grad[i][0] = kg[l] * io_grad[i][0] + (ka[l] * wg[0] + kb[l] * wg[3]) * y;
      io_grad[i][1] = kg[l] * io_grad[i][1] + (ka[l] * wg[1] + kb[l] * wg[4]) * y;
      io_grad[i][2] = kg[l] * io_grad[i][2] + (ka[l] * wg[2] + kb[l] * wg[5]) * y;
    }
  }
#endif
}

SHLIGHT_INLINE void shli_sh_zero_grad(int n, float *out_sh, float (*out_grad)[3]) {
#if SHLIGHT_MAX_BANDS > SHLIGHT_UNROLLED_BANDS
  int i;
  for (i = SHLIGHT_UNROLLED_BANDS * SHLIGHT_UNROLLED_BANDS; i < n * n; ++i) {
    out_sh[i] = 0.0f;
    SHLIGHT_SET3(out_grad[i], 0.0f, 0.0f, 0.0f);
  }
#endif
  out_sh[0] = 0.0f;
  SHLIGHT_SET3(out_grad[0], 0.0f, 0.0f, 0.0f);
#if SHLIGHT_MAX_BANDS > 1
  if (n > 1) {
    out_sh[1] = 0.0f;
    SHLIGHT_SET3(out_grad[1], 0.0f, 0.0f, 0.0f);
    out_sh[2] = 0.0f;
    SHLIGHT_SET3(out_grad[2], 0.0f, 0.0f, 0.0f);
    out_sh[3] = 0.0f;
    SHLIGHT_SET3(out_grad[3], 0.0f, 0.0f, 0.0f);
  }
#endif
#if SHLIGHT_MAX_BANDS > 2
  if (n > 2) {
    out_sh[4] = 0.0f;
    SHLIGHT_SET3(out_grad[4], 0.0f, 0.0f, 0.0f);
    out_sh[5] = 0.0f;
    SHLIGHT_SET3(out_grad[5], 0.0f, 0.0f, 0.0f);
    out_sh[6] = 0.0f;
    SHLIGHT_SET3(out_grad[6], 0.0f, 0.0f, 0.0f);
    out_sh[7] = 0.0f;
    SHLIGHT_SET3(out_grad[7], 0.0f, 0.0f, 0.0f);
    out_sh[8] = 0.0f;
    SHLIGHT_SET3(out_grad[8], 0.0f, 0.0f, 0.0f);
  }
#endif
#if SHLIGHT_MAX_BANDS > 3
  if (n > 3) {
    out_sh[9] = 0.0f;
    SHLIGHT_SET3(out_grad[9], 0.0f, 0.0f, 0.0f);
    out_sh[10] = 0.0f;
    SHLIGHT_SET3(out_grad[10], 0.0f, 0.0f, 0.0f);
    out_sh[11] = 0.0f;
    SHLIGHT_SET3(out_grad[11], 0.0f, 0.0f, 0.0f);
    out_sh[12] = 0.0f;
    SHLIGHT_SET3(out_grad[12], 0.0f, 0.0f, 0.0f);
    out_sh[13] = 0.0f;
    SHLIGHT_SET3(out_grad[13], 0.0f, 0.0f, 0.0f);
    out_sh[14] = 0.0f;
    SHLIGHT_SET3(out_grad[14], 0.0f, 0.0f, 0.0f);
    out_sh[15] = 0.0f;
    SHLIGHT_SET3(out_grad[15], 0.0f, 0.0f, 0.0f);
  }
#endif
#if SHLIGHT_MAX_BANDS > 4
  if (n > 4) {
    out_sh[16] = 0.0f;
    SHLIGHT_SET3(out_grad[16], 0.0f, 0.0f, 0.0f);
    out_sh[17] = 0.0f;
    SHLIGHT_SET3(out_grad[17], 0.0f, 0.0f, 0.0f);
    out_sh[18] = 0.0f;
    SHLIGHT_SET3(out_grad[18], 0.0f, 0.0f, 0.0f);
    out_sh[19] = 0.0f;
    SHLIGHT_SET3(out_grad[19], 0.0f, 0.0f, 0.0f);
    out_sh[20] = 0.0f;
    SHLIGHT_SET3(out_grad[20], 0.0f, 0.0f, 0.0f);
    out_sh[21] = 0.0f;
    SHLIGHT_SET3(out_grad[21], 0.0f, 0.0f, 0.0f);
    out_sh[22] = 0.0f;
    SHLIGHT_SET3(out_grad[22], 0.0f, 0.0f, 0.0f);
    out_sh[23] = 0.0f;
    SHLIGHT_SET3(out_grad[23], 0.0f, 0.0f, 0.0f);
    out_sh[24] = 0.0f;
    SHLIGHT_SET3(out_grad[24], 0.0f, 0.0f, 0.0f);
  }
#endif
#if SHLIGHT_MAX_BANDS > 5
  if (n > 5) {
    out_sh[25] = 0.0f;
    SHLIGHT_SET3(out_grad[25], 0.0f, 0.0f, 0.0f);
    out_sh[26] = 0.0f;
    SHLIGHT_SET3(out_grad[26], 0.0f, 0.0f, 0.0f);
    out_sh[27] = 0.0f;
    SHLIGHT_SET3(out_grad[27], 0.0f, 0.0f, 0.0f);
    out_sh[28] = 0.0f;
    SHLIGHT_SET3(out_grad[28], 0.0f, 0.0f, 0.0f);
    out_sh[29] = 0.0f;
    SHLIGHT_SET3(out_grad[29], 0.0f, 0.0f, 0.0f);
    out_sh[30] = 0.0f;
    SHLIGHT_SET3(out_grad[30], 0.0f, 0.0f, 0.0f);
    out_sh[31] = 0.0f;
    SHLIGHT_SET3(out_grad[31], 0.0f, 0.0f, 0.0f);
    out_sh[32] = 0.0f;
    SHLIGHT_SET3(out_grad[32], 0.0f, 0.0f, 0.0f);
    out_sh[33] = 0.0f;
    SHLIGHT_SET3(out_grad[33], 0.0f, 0.0f, 0.0f);
    out_sh[34] = 0.0f;
    SHLIGHT_SET3(out_grad[34], 0.0f, 0.0f, 0.0f);
    out_sh[35] = 0.0f;
    SHLIGHT_SET3(out_grad[35], 0.0f, 0.0f, 0.0f);
  }
#endif
#if SHLIGHT_MAX_BANDS > 6
  if (n > 6) {
    out_sh[36] = 0.0f;
    SHLIGHT_SET3(out_grad[36], 0.0f, 0.0f, 0.0f);
    out_sh[37] = 0.0f;
    SHLIGHT_SET3(out_grad[37], 0.0f, 0.0f, 0.0f);
    out_sh[38] = 0.0f;
    SHLIGHT_SET3(out_grad[38], 0.0f, 0.0f, 0.0f);
    out_sh[39] = 0.0f;
    SHLIGHT_SET3(out_grad[39], 0.0f, 0.0f, 0.0f);
    out_sh[40] = 0.0f;
    SHLIGHT_SET3(out_grad[40], 0.0f, 0.0f, 0.0f);
    out_sh[41] = 0.0f;
    SHLIGHT_SET3(out_grad[41], 0.0f, 0.0f, 0.0f);
    out_sh[42] = 0.0f;
    SHLIGHT_SET3(out_grad[42], 0.0f, 0.0f, 0.0f);
    out_sh[43] = 0.0f;
    SHLIGHT_SET3(out_grad[43], 0.0f, 0.0f, 0.0f);
    out_sh[44] = 0.0f;
    SHLIGHT_SET3(out_grad[44], 0.0f, 0.0f, 0.0f);
    out_sh[45] = 0.0f;
    SHLIGHT_SET3(out_grad[45], 0.0f, 0.0f, 0.0f);
    out_sh[46] = 0.0f;
    SHLIGHT_SET3(out_grad[46], 0.0f, 0.0f, 0.0f);
    out_sh[47] = 0.0f;
    SHLIGHT_SET3(out_grad[47], 0.0f, 0.0f, 0.0f);
    out_sh[48] = 0.0f;
    SHLIGHT_SET3(out_grad[48], 0.0f, 0.0f, 0.0f);
  }
#endif
#if SHLIGHT_MAX_BANDS > 7
  if (n > 7) {
    out_sh[49] = 0.0f;
    SHLIGHT_SET3(out_grad[49], 0.0f, 0.0f, 0.0f);
    out_sh[50] = 0.0f;
    SHLIGHT_SET3(out_grad[50], 0.0f, 0.0f, 0.0f);
    out_sh[51] = 0.0f;
    SHLIGHT_SET3(out_grad[51], 0.0f, 0.0f, 0.0f);
    out_sh[52] = 0.0f;
    SHLIGHT_SET3(out_grad[52], 0.0f, 0.0f, 0.0f);
    out_sh[53] = 0.0f;
    SHLIGHT_SET3(out_grad[53], 0.0f, 0.0f, 0.0f);
    out_sh[54] = 0.0f;
    SHLIGHT_SET3(out_grad[54], 0.0f, 0.0f, 0.0f);
    out_sh[55] = 0.0f;
    SHLIGHT_SET3(out_grad[55], 0.0f, 0.0f, 0.0f);
    out_sh[56] = 0.0f;
    SHLIGHT_SET3(out_grad[56], 0.0f, 0.0f, 0.0f);
    out_sh[57] = 0.0f;
    SHLIGHT_SET3(out_grad[57], 0.0f, 0.0f, 0.0f);
    out_sh[58] = 0.0f;
    SHLIGHT_SET3(out_grad[58], 0.0f, 0.0f, 0.0f);
    out_sh[59] = 0.0f;
    SHLIGHT_SET3(out_grad[59], 0.0f, 0.0f, 0.0f);
    out_sh[60] = 0.0f;
    SHLIGHT_SET3(out_grad[60], 0.0f, 0.0f, 0.0f);
    out_sh[61] = 0.0f;
    SHLIGHT_SET3(out_grad[61], 0.0f, 0.0f, 0.0f);
    out_sh[62] = 0.0f;
    SHLIGHT_SET3(out_grad[62], 0.0f, 0.0f, 0.0f);
    out_sh[63] = 0.0f;
    SHLIGHT_SET3(out_grad[63], 0.0f, 0.0f, 0.0f);
  }
#endif
#if SHLIGHT_MAX_BANDS > 8
  if (n > 8) {
    out_sh[64] = 0.0f;
    SHLIGHT_SET3(out_grad[64], 0.0f, 0.0f, 0.0f);
    out_sh[65] = 0.0f;
    SHLIGHT_SET3(out_grad[65], 0.0f, 0.0f, 0.0f);
    out_sh[66] = 0.0f;
    SHLIGHT_SET3(out_grad[66], 0.0f, 0.0f, 0.0f);
    out_sh[67] = 0.0f;
    SHLIGHT_SET3(out_grad[67], 0.0f, 0.0f, 0.0f);
    out_sh[68] = 0.0f;
    SHLIGHT_SET3(out_grad[68], 0.0f, 0.0f, 0.0f);
    out_sh[69] = 0.0f;
    SHLIGHT_SET3(out_grad[69], 0.0f, 0.0f, 0.0f);
    out_sh[70] = 0.0f;
    SHLIGHT_SET3(out_grad[70], 0.0f, 0.0f, 0.0f);
    out_sh[71] = 0.0f;
    SHLIGHT_SET3(out_grad[71], 0.0f, 0.0f, 0.0f);
    out_sh[72] = 0.0f;
    SHLIGHT_SET3(out_grad[72], 0.0f, 0.0f, 0.0f);
    out_sh[73] = 0.0f;
    SHLIGHT_SET3(out_grad[73], 0.0f, 0.0f, 0.0f);
    out_sh[74] = 0.0f;
    SHLIGHT_SET3(out_grad[74], 0.0f, 0.0f, 0.0f);
    out_sh[75] = 0.0f;
    SHLIGHT_SET3(out_grad[75], 0.0f, 0.0f, 0.0f);
    out_sh[76] = 0.0f;
    SHLIGHT_SET3(out_grad[76], 0.0f, 0.0f, 0.0f);
    out_sh[77] = 0.0f;
    SHLIGHT_SET3(out_grad[77], 0.0f, 0.0f, 0.0f);
    out_sh[78] = 0.0f;
    SHLIGHT_SET3(out_grad[78], 0.0f, 0.0f, 0.0f);
    out_sh[79] = 0.0f;
    SHLIGHT_SET3(out_grad[79], 0.0f, 0.0f, 0.0f);
    out_sh[80] = 0.0f;
    SHLIGHT_SET3(out_grad[80], 0.0f, 0.0f, 0.0f);
  }
#endif
#if SHLIGHT_MAX_BANDS > 9
  if (n > 9) {
    out_sh[81] = 0.0f;
    SHLIGHT_SET3(out_grad[81], 0.0f, 0.0f, 0.0f);
    out_sh[82] = 0.0f;
    SHLIGHT_SET3(out_grad[82], 0.0f, 0.0f, 0.0f);
    out_sh[83] = 0.0f;
    SHLIGHT_SET3(out_grad[83], 0.0f, 0.0f, 0.0f);
    out_sh[84] = 0.0f;
    SHLIGHT_SET3(out_grad[84], 0.0f, 0.0f, 0.0f);
    out_sh[85] = 0.0f;
    SHLIGHT_SET3(out_grad[85], 0.0f, 0.0f, 0.0f);
    out_sh[86] = 0.0f;
    SHLIGHT_SET3(out_grad[86], 0.0f, 0.0f, 0.0f);
    out_sh[87] = 0.0f;
    SHLIGHT_SET3(out_grad[87], 0.0f, 0.0f, 0.0f);
    out_sh[88] = 0.0f;
    SHLIGHT_SET3(out_grad[88], 0.0f, 0.0f, 0.0f);
    out_sh[89] = 0.0f;
    SHLIGHT_SET3(out_grad[89], 0.0f, 0.0f, 0.0f);
    out_sh[90] = 0.0f;
    SHLIGHT_SET3(out_grad[90], 0.0f, 0.0f, 0.0f);
    out_sh[91] = 0.0f;
    SHLIGHT_SET3(out_grad[91], 0.0f, 0.0f, 0.0f);
    out_sh[92] = 0.0f;
    SHLIGHT_SET3(out_grad[92], 0.0f, 0.0f, 0.0f);
    out_sh[93] = 0.0f;
    SHLIGHT_SET3(out_grad[93], 0.0f, 0.0f, 0.0f);
    out_sh[94] = 0.0f;
    SHLIGHT_SET3(out_grad[94], 0.0f, 0.0f, 0.0f);
    out_sh[95] = 0.0f;
    SHLIGHT_SET3(out_grad[95], 0.0f, 0.0f, 0.0f);
    out_sh[96] = 0.0f;
    SHLIGHT_SET3(out_grad[96], 0.0f, 0.0f, 0.0f);
    out_sh[97] = 0.0f;
    SHLIGHT_SET3(out_grad[97], 0.0f, 0.0f, 0.0f);
    out_sh[98] = 0.0f;
    SHLIGHT_SET3(out_grad[98], 0.0f, 0.0f, 0.0f);
    out_sh[99] = 0.0f;
    SHLIGHT_SET3(out_grad[99], 0.0f, 0.0f, 0.0f);
  }
#endif
#if SHLIGHT_MAX_BANDS > 10
  if (n > 10) {
    out_sh[100] = 0.0f;
    SHLIGHT_SET3(out_grad[100], 0.0f, 0.0f, 0.0f);
    out_sh[101] = 0.0f;
    SHLIGHT_SET3(out_grad[101], 0.0f, 0.0f, 0.0f);
    out_sh[102] = 0.0f;
    SHLIGHT_SET3(out_grad[102], 0.0f, 0.0f, 0.0f);
    out_sh[103] = 0.0f;
    SHLIGHT_SET3(out_grad[103], 0.0f, 0.0f, 0.0f);
    out_sh[104] = 0.0f;
    SHLIGHT_SET3(out_grad[104], 0.0f, 0.0f, 0.0f);
    out_sh[105] = 0.0f;
    SHLIGHT_SET3(out_grad[105], 0.0f, 0.0f, 0.0f);
    out_sh[106] = 0.0f;
    SHLIGHT_SET3(out_grad[106], 0.0f, 0.0f, 0.0f);
    out_sh[107] = 0.0f;
    SHLIGHT_SET3(out_grad[107], 0.0f, 0.0f, 0.0f);
    out_sh[108] = 0.0f;
    SHLIGHT_SET3(out_grad[108], 0.0f, 0.0f, 0.0f);
    out_sh[109] = 0.0f;
    SHLIGHT_SET3(out_grad[109], 0.0f, 0.0f, 0.0f);
    out_sh[110] = 0.0f;
    SHLIGHT_SET3(out_grad[110], 0.0f, 0.0f, 0.0f);
    out_sh[111] = 0.0f;
    SHLIGHT_SET3(out_grad[111], 0.0f, 0.0f, 0.0f);
    out_sh[112] = 0.0f;
    SHLIGHT_SET3(out_grad[112], 0.0f, 0.0f, 0.0f);
    out_sh[113] = 0.0f;
    SHLIGHT_SET3(out_grad[113], 0.0f, 0.0f, 0.0f);
    out_sh[114] = 0.0f;
    SHLIGHT_SET3(out_grad[114], 0.0f, 0.0f, 0.0f);
    out_sh[115] = 0.0f;
    SHLIGHT_SET3(out_grad[115], 0.0f, 0.0f, 0.0f);
    out_sh[116] = 0.0f;
    SHLIGHT_SET3(out_grad[116], 0.0f, 0.0f, 0.0f);
    out_sh[117] = 0.0f;
    SHLIGHT_SET3(out_grad[117], 0.0f, 0.0f, 0.0f);
    out_sh[118] = 0.0f;
    SHLIGHT_SET3(out_grad[118], 0.0f, 0.0f, 0.0f);
    out_sh[119] = 0.0f;
    SHLIGHT_SET3(out_grad[119], 0.0f, 0.0f, 0.0f);
    out_sh[120] = 0.0f;
    SHLIGHT_SET3(out_grad[120], 0.0f, 0.0f, 0.0f);
  }
#endif
#if SHLIGHT_MAX_BANDS > 11
  if (n > 11) {
    out_sh[121] = 0.0f;
    SHLIGHT_SET3(out_grad[121], 0.0f, 0.0f, 0.0f);
    out_sh[122] = 0.0f;
    SHLIGHT_SET3(out_grad[122], 0.0f, 0.0f, 0.0f);
    out_sh[123] = 0.0f;
    SHLIGHT_SET3(out_grad[123], 0.0f, 0.0f, 0.0f);
    out_sh[124] = 0.0f;
    SHLIGHT_SET3(out_grad[124], 0.0f, 0.0f, 0.0f);
    out_sh[125] = 0.0f;
    SHLIGHT_SET3(out_grad[125], 0.0f, 0.0f, 0.0f);
    out_sh[126] = 0.0f;
    SHLIGHT_SET3(out_grad[126], 0.0f, 0.0f, 0.0f);
    out_sh[127] = 0.0f;
    SHLIGHT_SET3(out_grad[127], 0.0f, 0.0f, 0.0f);
    out_sh[128] = 0.0f;
    SHLIGHT_SET3(out_grad[128], 0.0f, 0.0f, 0.0f);
    out_sh[129] = 0.0f;
    SHLIGHT_SET3(out_grad[129], 0.0f, 0.0f, 0.0f);
    out_sh[130] = 0.0f;
    SHLIGHT_SET3(out_grad[130], 0.0f, 0.0f, 0.0f);
    out_sh[131] = 0.0f;
    SHLIGHT_SET3(out_grad[131], 0.0f, 0.0f, 0.0f);
    out_sh[132] = 0.0f;
    SHLIGHT_SET3(out_grad[132], 0.0f, 0.0f, 0.0f);
    out_sh[133] = 0.0f;
    SHLIGHT_SET3(out_grad[133], 0.0f, 0.0f, 0.0f);
    out_sh[134] = 0.0f;
    SHLIGHT_SET3(out_grad[134], 0.0f, 0.0f, 0.0f);
    out_sh[135] = 0.0f;
    SHLIGHT_SET3(out_grad[135], 0.0f, 0.0f, 0.0f);
    out_sh[136] = 0.0f;
    SHLIGHT_SET3(out_grad[136], 0.0f, 0.0f, 0.0f);
    out_sh[137] = 0.0f;
    SHLIGHT_SET3(out_grad[137], 0.0f, 0.0f, 0.0f);
    out_sh[138] = 0.0f;
    SHLIGHT_SET3(out_grad[138], 0.0f, 0.0f, 0.0f);
    out_sh[139] = 0.0f;
    SHLIGHT_SET3(out_grad[139], 0.0f, 0.0f, 0.0f);
    out_sh[140] = 0.0f;
    SHLIGHT_SET3(out_grad[140], 0.0f, 0.0f, 0.0f);
    out_sh[141] = 0.0f;
    SHLIGHT_SET3(out_grad[141], 0.0f, 0.0f, 0.0f);
    out_sh[142] = 0.0f;
    SHLIGHT_SET3(out_grad[142], 0.0f, 0.0f, 0.0f);
    out_sh[143] = 0.0f;
    SHLIGHT_SET3(out_grad[143], 0.0f, 0.0f, 0.0f);
  }
#endif
#if SHLIGHT_MAX_BANDS > 12
  if (n > 12) {
    out_sh[144] = 0.0f;
    SHLIGHT_SET3(out_grad[144], 0.0f, 0.0f, 0.0f);
    out_sh[145] = 0.0f;
    SHLIGHT_SET3(out_grad[145], 0.0f, 0.0f, 0.0f);
    out_sh[146] = 0.0f;
    SHLIGHT_SET3(out_grad[146], 0.0f, 0.0f, 0.0f);
    out_sh[147] = 0.0f;
    SHLIGHT_SET3(out_grad[147], 0.0f, 0.0f, 0.0f);
    out_sh[148] = 0.0f;
    SHLIGHT_SET3(out_grad[148], 0.0f, 0.0f, 0.0f);
    out_sh[149] = 0.0f;
    SHLIGHT_SET3(out_grad[149], 0.0f, 0.0f, 0.0f);
    out_sh[150] = 0.0f;
    SHLIGHT_SET3(out_grad[150], 0.0f, 0.0f, 0.0f);
    out_sh[151] = 0.0f;
    SHLIGHT_SET3(out_grad[151], 0.0f, 0.0f, 0.0f);
    out_sh[152] = 0.0f;
    SHLIGHT_SET3(out_grad[152], 0.0f, 0.0f, 0.0f);
    out_sh[153] = 0.0f;
    SHLIGHT_SET3(out_grad[153], 0.0f, 0.0f, 0.0f);
    out_sh[154] = 0.0f;
    SHLIGHT_SET3(out_grad[154], 0.0f, 0.0f, 0.0f);
    out_sh[155] = 0.0f;
    SHLIGHT_SET3(out_grad[155], 0.0f, 0.0f, 0.0f);
    out_sh[156] = 0.0f;
    SHLIGHT_SET3(out_grad[156], 0.0f, 0.0f, 0.0f);
    out_sh[157] = 0.0f;
    SHLIGHT_SET3(out_grad[157], 0.0f, 0.0f, 0.0f);
    out_sh[158] = 0.0f;
    SHLIGHT_SET3(out_grad[158], 0.0f, 0.0f, 0.0f);
    out_sh[159] = 0.0f;
    SHLIGHT_SET3(out_grad[159], 0.0f, 0.0f, 0.0f);
    out_sh[160] = 0.0f;
    SHLIGHT_SET3(out_grad[160], 0.0f, 0.0f, 0.0f);
    out_sh[161] = 0.0f;
    SHLIGHT_SET3(out_grad[161], 0.0f, 0.0f, 0.0f);
    out_sh[162] = 0.0f;
    SHLIGHT_SET3(out_grad[162], 0.0f, 0.0f, 0.0f);
    out_sh[163] = 0.0f;
    SHLIGHT_SET3(out_grad[163], 0.0f, 0.0f, 0.0f);
    out_sh[164] = 0.0f;
    SHLIGHT_SET3(out_grad[164], 0.0f, 0.0f, 0.0f);
    out_sh[165] = 0.0f;
    SHLIGHT_SET3(out_grad[165], 0.0f, 0.0f, 0.0f);
    out_sh[166] = 0.0f;
    SHLIGHT_SET3(out_grad[166], 0.0f, 0.0f, 0.0f);
    out_sh[167] = 0.0f;
    SHLIGHT_SET3(out_grad[167], 0.0f, 0.0f, 0.0f);
    out_sh[168] = 0.0f;
    SHLIGHT_SET3(out_grad[168], 0.0f, 0.0f, 0.0f);
  }
#endif
#if SHLIGHT_MAX_BANDS > 13
  if (n > 13) {
    out_sh[169] = 0.0f;
    SHLIGHT_SET3(out_grad[169], 0.0f, 0.0f, 0.0f);
    out_sh[170] = 0.0f;
    SHLIGHT_SET3(out_grad[170], 0.0f, 0.0f, 0.0f);
    out_sh[171] = 0.0f;
    SHLIGHT_SET3(out_grad[171], 0.0f, 0.0f, 0.0f);
    out_sh[172] = 0.0f;
    SHLIGHT_SET3(out_grad[172], 0.0f, 0.0f, 0.0f);
    out_sh[173] = 0.0f;
    SHLIGHT_SET3(out_grad[173], 0.0f, 0.0f, 0.0f);
    out_sh[174] = 0.0f;
    SHLIGHT_SET3(out_grad[174], 0.0f, 0.0f, 0.0f);
    out_sh[175] = 0.0f;
    SHLIGHT_SET3(out_grad[175], 0.0f, 0.0f, 0.0f);
    out_sh[176] = 0.0f;
    SHLIGHT_SET3(out_grad[176], 0.0f, 0.0f, 0.0f);
    out_sh[177] = 0.0f;
    SHLIGHT_SET3(out_grad[177], 0.0f, 0.0f, 0.0f);
    out_sh[178] = 0.0f;
    SHLIGHT_SET3(out_grad[178], 0.0f, 0.0f, 0.0f);
    out_sh[179] = 0.0f;
    SHLIGHT_SET3(out_grad[179], 0.0f, 0.0f, 0.0f);
    out_sh[180] = 0.0f;
    SHLIGHT_SET3(out_grad[180], 0.0f, 0.0f, 0.0f);
    out_sh[181] = 0.0f;
    SHLIGHT_SET3(out_grad[181], 0.0f, 0.0f, 0.0f);
    out_sh[182] = 0.0f;
    SHLIGHT_SET3(out_grad[182], 0.0f, 0.0f, 0.0f);
    out_sh[183] = 0.0f;
    SHLIGHT_SET3(out_grad[183], 0.0f, 0.0f, 0.0f);
    out_sh[184] = 0.0f;
    SHLIGHT_SET3(out_grad[184], 0.0f, 0.0f, 0.0f);
    out_sh[185] = 0.0f;
    SHLIGHT_SET3(out_grad[185], 0.0f, 0.0f, 0.0f);
    out_sh[186] = 0.0f;
    SHLIGHT_SET3(out_grad[186], 0.0f, 0.0f, 0.0f);
    out_sh[187] = 0.0f;
    SHLIGHT_SET3(out_grad[187], 0.0f, 0.0f, 0.0f);
    out_sh[188] = 0.0f;
    SHLIGHT_SET3(out_grad[188], 0.0f, 0.0f, 0.0f);
    out_sh[189] = 0.0f;
    SHLIGHT_SET3(out_grad[189], 0.0f, 0.0f, 0.0f);
    out_sh[190] = 0.0f;
    SHLIGHT_SET3(out_grad[190], 0.0f, 0.0f, 0.0f);
    out_sh[191] = 0.0f;
    SHLIGHT_SET3(out_grad[191], 0.0f, 0.0f, 0.0f);
    out_sh[192] = 0.0f;
    SHLIGHT_SET3(out_grad[192], 0.0f, 0.0f, 0.0f);
    out_sh[193] = 0.0f;
    SHLIGHT_SET3(out_grad[193], 0.0f, 0.0f, 0.0f);
    out_sh[194] = 0.0f;
    SHLIGHT_SET3(out_grad[194], 0.0f, 0.0f, 0.0f);
    out_sh[195] = 0.0f;
    SHLIGHT_SET3(out_grad[195], 0.0f, 0.0f, 0.0f);
  }
#endif
#if SHLIGHT_MAX_BANDS > 14
  if (n > 14) {
    out_sh[196] = 0.0f;
    SHLIGHT_SET3(out_grad[196], 0.0f, 0.0f, 0.0f);
    out_sh[197] = 0.0f;
    SHLIGHT_SET3(out_grad[197], 0.0f, 0.0f, 0.0f);
    out_sh[198] = 0.0f;
    SHLIGHT_SET3(out_grad[198], 0.0f, 0.0f, 0.0f);
    out_sh[199] = 0.0f;
    SHLIGHT_SET3(out_grad[199], 0.0f, 0.0f, 0.0f);
    out_sh[200] = 0.0f;
    SHLIGHT_SET3(out_grad[200], 0.0f, 0.0f, 0.0f);
    out_sh[201] = 0.0f;
    SHLIGHT_SET3(out_grad[201], 0.0f, 0.0f, 0.0f);
    out_sh[202] = 0.0f;
    SHLIGHT_SET3(out_grad[202], 0.0f, 0.0f, 0.0f);
    out_sh[203] = 0.0f;
    SHLIGHT_SET3(out_grad[203], 0.0f, 0.0f, 0.0f);
    out_sh[204] = 0.0f;
    SHLIGHT_SET3(out_grad[204], 0.0f, 0.0f, 0.0f);
    out_sh[205] = 0.0f;
    SHLIGHT_SET3(out_grad[205], 0.0f, 0.0f, 0.0f);
    out_sh[206] = 0.0f;
    SHLIGHT_SET3(out_grad[206], 0.0f, 0.0f, 0.0f);
    out_sh[207] = 0.0f;
    SHLIGHT_SET3(out_grad[207], 0.0f, 0.0f, 0.0f);
    out_sh[208] = 0.0f;
    SHLIGHT_SET3(out_grad[208], 0.0f, 0.0f, 0.0f);
    out_sh[209] = 0.0f;
    SHLIGHT_SET3(out_grad[209], 0.0f, 0.0f, 0.0f);
    out_sh[210] = 0.0f;
    SHLIGHT_SET3(out_grad[210], 0.0f, 0.0f, 0.0f);
    out_sh[211] = 0.0f;
    SHLIGHT_SET3(out_grad[211], 0.0f, 0.0f, 0.0f);
    out_sh[212] = 0.0f;
    SHLIGHT_SET3(out_grad[212], 0.0f, 0.0f, 0.0f);
    out_sh[213] = 0.0f;
    SHLIGHT_SET3(out_grad[213], 0.0f, 0.0f, 0.0f);
    out_sh[214] = 0.0f;
    SHLIGHT_SET3(out_grad[214], 0.0f, 0.0f, 0.0f);
    out_sh[215] = 0.0f;
    SHLIGHT_SET3(out_grad[215], 0.0f, 0.0f, 0.0f);
    out_sh[216] = 0.0f;
    SHLIGHT_SET3(out_grad[216], 0.0f, 0.0f, 0.0f);
    out_sh[217] = 0.0f;
    SHLIGHT_SET3(out_grad[217], 0.0f, 0.0f, 0.0f);
    out_sh[218] = 0.0f;
    SHLIGHT_SET3(out_grad[218], 0.0f, 0.0f, 0.0f);
    out_sh[219] = 0.0f;
    SHLIGHT_SET3(out_grad[219], 0.0f, 0.0f, 0.0f);
    out_sh[220] = 0.0f;
    SHLIGHT_SET3(out_grad[220], 0.0f, 0.0f, 0.0f);
    out_sh[221] = 0.0f;
    SHLIGHT_SET3(out_grad[221], 0.0f, 0.0f, 0.0f);
    out_sh[222] = 0.0f;
    SHLIGHT_SET3(out_grad[222], 0.0f, 0.0f, 0.0f);
    out_sh[223] = 0.0f;
    SHLIGHT_SET3(out_grad[223], 0.0f, 0.0f, 0.0f);
    out_sh[224] = 0.0f;
    SHLIGHT_SET3(out_grad[224], 0.0f, 0.0f, 0.0f);
  }
#endif
#if SHLIGHT_MAX_BANDS > 15
  if (n > 15) {
    out_sh[225] = 0.0f;
    SHLIGHT_SET3(out_grad[225], 0.0f, 0.0f, 0.0f);
    out_sh[226] = 0.0f;
    SHLIGHT_SET3(out_grad[226], 0.0f, 0.0f, 0.0f);
    out_sh[227] = 0.0f;
    SHLIGHT_SET3(out_grad[227], 0.0f, 0.0f, 0.0f);
    out_sh[228] = 0.0f;
    SHLIGHT_SET3(out_grad[228], 0.0f, 0.0f, 0.0f);
    out_sh[229] = 0.0f;
    SHLIGHT_SET3(out_grad[229], 0.0f, 0.0f, 0.0f);
    out_sh[230] = 0.0f;
    SHLIGHT_SET3(out_grad[230], 0.0f, 0.0f, 0.0f);
    out_sh[231] = 0.0f;
    SHLIGHT_SET3(out_grad[231], 0.0f, 0.0f, 0.0f);
    out_sh[232] = 0.0f;
    SHLIGHT_SET3(out_grad[232], 0.0f, 0.0f, 0.0f);
    out_sh[233] = 0.0f;
    SHLIGHT_SET3(out_grad[233], 0.0f, 0.0f, 0.0f);
    out_sh[234] = 0.0f;
    SHLIGHT_SET3(out_grad[234], 0.0f, 0.0f, 0.0f);
    out_sh[235] = 0.0f;
    SHLIGHT_SET3(out_grad[235], 0.0f, 0.0f, 0.0f);
    out_sh[236] = 0.0f;
    SHLIGHT_SET3(out_grad[236], 0.0f, 0.0f, 0.0f);
    out_sh[237] = 0.0f;
    SHLIGHT_SET3(out_grad[237], 0.0f, 0.0f, 0.0f);
    out_sh[238] = 0.0f;
    SHLIGHT_SET3(out_grad[238], 0.0f, 0.0f, 0.0f);
    out_sh[239] = 0.0f;
    SHLIGHT_SET3(out_grad[239], 0.0f, 0.0f, 0.0f);
    out_sh[240] = 0.0f;
    SHLIGHT_SET3(out_grad[240], 0.0f, 0.0f, 0.0f);
    out_sh[241] = 0.0f;
    SHLIGHT_SET3(out_grad[241], 0.0f, 0.0f, 0.0f);
    out_sh[242] = 0.0f;
    SHLIGHT_SET3(out_grad[242], 0.0f, 0.0f, 0.0f);
    out_sh[243] = 0.0f;
    SHLIGHT_SET3(out_grad[243], 0.0f, 0.0f, 0.0f);
    out_sh[244] = 0.0f;
    SHLIGHT_SET3(out_grad[244], 0.0f, 0.0f, 0.0f);
    out_sh[245] = 0.0f;
    SHLIGHT_SET3(out_grad[245], 0.0f, 0.0f, 0.0f);
    out_sh[246] = 0.0f;
    SHLIGHT_SET3(out_grad[246], 0.0f, 0.0f, 0.0f);
    out_sh[247] = 0.0f;
    SHLIGHT_SET3(out_grad[247], 0.0f, 0.0f, 0.0f);
    out_sh[248] = 0.0f;
    SHLIGHT_SET3(out_grad[248], 0.0f, 0.0f, 0.0f);
    out_sh[249] = 0.0f;
    SHLIGHT_SET3(out_grad[249], 0.0f, 0.0f, 0.0f);
    out_sh[250] = 0.0f;
    SHLIGHT_SET3(out_grad[250], 0.0f, 0.0f, 0.0f);
    out_sh[251] = 0.0f;
    SHLIGHT_SET3(out_grad[251], 0.0f, 0.0f, 0.0f);
    out_sh[252] = 0.0f;
    SHLIGHT_SET3(out_grad[252], 0.0f, 0.0f, 0.0f);
    out_sh[253] = 0.0f;
    SHLIGHT_SET3(out_grad[253], 0.0f, 0.0f, 0.0f);
    out_sh[254] = 0.0f;
    SHLIGHT_SET3(out_grad[254], 0.0f, 0.0f, 0.0f);
    out_sh[255] = 0.0f;
    SHLIGHT_SET3(out_grad[255], 0.0f, 0.0f, 0.0f);
  }
#endif
}
/* @generated end light_idx */

#if SHLIGHT_SIMD_EVAL
/* The per-band light weights on 16 coefficients at a time (C only, AVX-512, n <= 16): one
   permute gives each lane the weight of its band (SHLI_LIGHT_BAND). */
#if defined(__GNUC__) || defined(__clang__)
#define SHLI_LIGHT_FORCE __attribute__((always_inline)) /* literal n specialises */
#else
#define SHLI_LIGHT_FORCE
#endif
#define SHLI_LIGHT_M16(k) ((__mmask16)((k) >= 16 ? 0xFFFFu : (1u << (k)) - 1u))
#define SHLI_LIGHT_IDX(t, c) _mm512_loadu_si512((const void *)((t) + (c)))

/* io[i] = k[l] io[i] for the coefficients i < n * n of band l. */
SHLI_LIGHT_FORCE SHLIGHT_CPU_INLINE void shli_light_scale_avx512(int n, const float *k, float *io) {
  __m512 kv = _mm512_maskz_loadu_ps(SHLI_LIGHT_M16(n), k);
  int nn = n * n;
  int c;
  for (c = 0; c < nn; c += 16) {
    __mmask16 m = SHLI_LIGHT_M16(nn - c);
    _mm512_mask_storeu_ps(
        io + c, m,
        _mm512_mul_ps(_mm512_maskz_loadu_ps(m, io + c),
                      _mm512_permutexvar_ps(SHLI_LIGHT_IDX(SHLI_LIGHT_BAND, c), kv)));
  }
}
#endif

/* ZH factors of the cap (g from shli_cap_frame) applied in place to Y in out_sh, scaled by
   wgt: out_sh[l,m] = wgt 2 pi s^2 q_l Y_l^m. */
SHLIGHT_INLINE void shli_cap_light_apply(int n, const shli_real *g, shli_real wgt, float *io_sh) {
  shli_real f = 6.283185307179586 * g[4] * wgt;
  shli_real al = g[5];
  shli_real fl;
  shli_real pm = 1.0;
  shli_real pl;
  shli_real pn;
  shli_real dm = 0.0;
  shli_real dl = 1.0;
  shli_real dn;
  float k;
  int l;
  int m;
  int b;
#if SHLIGHT_SIMD_EVAL
  if (n >= 3 && n <= SHLIGHT_UNROLLED_BANDS) {
    /* the weights first, then 16 coefficients per multiply (n = 2: the scalar loop is faster) */
    float kw[SHLIGHT_UNROLLED_BANDS];
    kw[0] = SHLIGHT_FLOAT(f / (1.0 + al));
    pl = al;
    fl = 1.0;
    for (l = 1; l < n; ++l) {
      kw[l] = SHLIGHT_FLOAT(f * dl * SHLI_ZH_TAB[5 * l + 2]);
      dn = dm + (2.0 * fl + 1.0) * pl;
      pn = SHLI_ZH_TAB[5 * l] * al * pl - SHLI_ZH_TAB[5 * l + 1] * pm;
      dm = dl;
      dl = dn;
      pm = pl;
      pl = pn;
      fl = fl + 1.0;
    }
    shli_light_scale_avx512(n, kw, io_sh);
    return;
  }
#endif
  io_sh[0] = SHLIGHT_FLOAT(f / (1.0 + al)) * io_sh[0];
  pl = al;
  fl = 1.0;
  for (l = 1; l < n; ++l) {
    /* pl = P_l, pm = P_{l-1}, dl = P'_l, dm = P'_{l-1}; fl = l */
    k = SHLIGHT_FLOAT(f * dl * SHLI_ZH_TAB[5 * l + 2]);
    b = l * (l + 1);
    for (m = -l; m <= l; ++m) {
      io_sh[b + m] = k * io_sh[b + m];
    }
    dn = dm + (2.0 * fl + 1.0) * pl;
    pn = SHLI_ZH_TAB[5 * l] * al * pl - SHLI_ZH_TAB[5 * l + 1] * pm;
    dm = dl;
    dl = dn;
    pm = pl;
    pl = pn;
    fl = fl + 1.0;
  }
}

/* Y and the unit-radius gradient scaled by ir at the unit direction (nx, ny, nz): the
   evaluation and gradient passes of shl_sh_eval_grad without its input normalisation (the
   portable path of the lights; with AVX-512 they take shli_sh_grad_avx512 up to 16 bands). */
SHLIGHT_INLINE void shli_sh_eval_grad_unit(int n, float nx, float ny, float nz, float ir,
                                           float *out_y, float (*out_grad)[3]) {
  shli_sh_eval_xyz(n, nx, ny, nz, out_y);
  shli_sh_grad(n, out_y, nx, ny, nz, ir, 1.0f, out_grad);
}

/* Cap light and gradient from g (shli_cap_frame), times the weight wgt whose gradient with
   respect to x is (gw0, gw1, gw2): out_sh = wgt S, out_grad = wgt grad S + S grad wgt. Per band
   l the double recurrence gives four float weights: kv = wgt f q_l (values), kg = -kv / d (of
   the unit-radius gradient of Y), ka = wgt h P_l (of Y w, the radial term) and kb = f q_l (of
   Y grad wgt); the products with w and grad wgt are formed in float. */
SHLIGHT_INLINE void shli_cap_light_grad(int n, const shli_real *g, shli_real wgt, shli_real gw0,
                                        shli_real gw1, shli_real gw2, float *io_sh,
                                        float (*io_grad)[3]) {
  shli_real f = 6.283185307179586 * g[4];
  shli_real fw = f * wgt;
  shli_real ir = g[3];
  shli_real al = g[5];
  shli_real h = 0.0;
  shli_real fl;
  shli_real pm = 1.0;
  shli_real pl = 1.0;
  shli_real pn;
  shli_real dm = 0.0;
  shli_real dl = 0.0;
  shli_real dn;
  shli_real q;
  shli_real q0 = 1.0 / (1.0 + al);
  float nx = SHLIGHT_FLOAT(g[0]);
  float ny = SHLIGHT_FLOAT(g[1]);
  float nz = SHLIGHT_FLOAT(g[2]);
  float wg[6];
  int l;
  float kv[SHLIGHT_MAX_BANDS];
  float kg[SHLIGHT_MAX_BANDS];
  float ka[SHLIGHT_MAX_BANDS];
  float kb[SHLIGHT_MAX_BANDS];
  wg[0] = nx;
  wg[1] = ny;
  wg[2] = nz;
  wg[3] = SHLIGHT_FLOAT(gw0);
  wg[4] = SHLIGHT_FLOAT(gw1);
  wg[5] = SHLIGHT_FLOAT(gw2);
  if (al > 0.0) {
    h = fw * ir / al;
  }
  /* value wgt f q_l Y; gradient wgt (-f q_l ir grad1 Y + h P_l Y w) + f q_l Y grad wgt */
  fl = 0.0;
  for (l = 0; l < n; ++l) {
    /* pl = P_l, pm = P_{l-1}, dl = P'_l, dm = P'_{l-1}; fl = l; q = q_l */
    q = dl * SHLI_ZH_TAB[5 * l + 2];
    if (l == 0) {
      q = q0;
    }
    kv[l] = SHLIGHT_FLOAT(fw * q);
    kg[l] = SHLIGHT_FLOAT(-fw * q * ir);
    ka[l] = SHLIGHT_FLOAT(h * pl);
    kb[l] = SHLIGHT_FLOAT(f * q);
    dn = dm + (2.0 * fl + 1.0) * pl;
    pn = SHLI_ZH_TAB[5 * l] * al * pl - SHLI_ZH_TAB[5 * l + 1] * pm;
    dm = dl;
    dl = dn;
    pm = pl;
    pl = pn;
    fl = fl + 1.0;
  }
  shli_sh_eval_grad_unit(n, nx, ny, nz, 1.0f, io_sh, io_grad);
  shli_sh_band_weights(n, kv, kg, ka, kb, wg, io_sh, io_grad);
}

#if SHLIGHT_SIMD_EVAL
/* shli_cap_light_grad for n <= 16 (C only, AVX-512): the same weights in double, then Y by the
   basis kernel and the weighted gradient in one pass (shli_sh_grad_avx512 with bw: P of band l
   times kg, Y times ka - l kg along w and kb along grad wgt), which also writes the values kv Y.
   Forced inline (as the helpers above), so a literal n at the call specialises it as it does
   the value path. */
SHLI_LIGHT_FORCE SHLIGHT_CPU_INLINE void
shli_cap_light_grad_avx512(int n, const shli_real *g, shli_real wgt, shli_real gw0, shli_real gw1,
                           shli_real gw2, float *io_sh, float (*io_grad)[3]) {
  shli_real f = 6.283185307179586 * g[4];
  shli_real fw = f * wgt;
  shli_real ir = g[3];
  shli_real al = g[5];
  shli_real h = 0.0;
  shli_real fl = 0.0;
  shli_real pm = 1.0;
  shli_real pl = 1.0;
  shli_real pn;
  shli_real dm = 0.0;
  shli_real dl = 0.0;
  shli_real dn;
  shli_real q = 1.0 / (1.0 + al);
  shli_real nk;
  shli_real ln;
  float bw[4 * SHLIGHT_UNROLLED_BANDS];
  float ys[SHLIGHT_UNROLLED_BANDS * SHLIGHT_UNROLLED_BANDS];
  float wg[6];
  int l;
  wg[0] = (float)g[0];
  wg[1] = (float)g[1];
  wg[2] = (float)g[2];
  wg[3] = (float)gw0;
  wg[4] = (float)gw1;
  wg[5] = (float)gw2;
  if (al > 0.0) {
    h = fw * ir / al;
  }
  nk = -fw * ir;
  ln = 0.0;
  for (l = 0; l < n; ++l) {
    if (l > 0) {
      q = dl * SHLI_ZH_TAB[5 * l + 2];
    }
    /* kv, then a = kg, b = ka - l kg, e = kb of shli_sh_grad_avx512 */
    bw[4 * l] = (float)(fw * q);
    bw[4 * l + 1] = (float)(nk * q);
    bw[4 * l + 2] = (float)(h * pl - ln * q);
    bw[4 * l + 3] = (float)(f * q);
    ln = ln + nk;
    dn = dm + (2.0 * fl + 1.0) * pl;
    pn = SHLI_ZH_TAB[5 * l] * al * pl - SHLI_ZH_TAB[5 * l + 1] * pm;
    dm = dl;
    dl = dn;
    pm = pl;
    pl = pn;
    fl = fl + 1.0;
  }
  /* Y in a scratch array: the pass's weighted values go to io_sh while it still loads Y (in
     place, each band's load waited on the previous band's masked store: +23 ns at n = 10) */
  shli_sh_eval_xyz(n, wg[0], wg[1], wg[2], ys);
  shli_sh_grad_avx512(n, ys, wg[0], wg[1], wg[2], 1.0f, bw,
                      (wg[3] != 0.0f || wg[4] != 0.0f || wg[5] != 0.0f) ? wg + 3 : 0, io_sh,
                      io_grad);
}
#endif

SHLIGHT_INLINE void shl_sphere_light(int n, const float x[3], const float c[3], float r,
                                     float *out_sh) {
  shli_real g[8];
  int i;
  n = shli_bands(n);
  if (n < 1) {
    return;
  }
  shli_cap_frame(SHLIGHT_REAL(c[0]) - SHLIGHT_REAL(x[0]), SHLIGHT_REAL(c[1]) - SHLIGHT_REAL(x[1]),
                 SHLIGHT_REAL(c[2]) - SHLIGHT_REAL(x[2]), SHLIGHT_REAL(r), g);
  if (g[6] == 0.0) {
    for (i = 0; i < n * n; ++i) {
      out_sh[i] = 0.0f;
    }
    return;
  }
  shli_sh_eval_xyz(n, SHLIGHT_FLOAT(g[0]), SHLIGHT_FLOAT(g[1]), SHLIGHT_FLOAT(g[2]), out_sh);
  shli_cap_light_apply(n, g, 1.0, out_sh);
}

SHLIGHT_INLINE void shl_sphere_light_grad(int n, const float x[3], const float c[3], float r,
                                          float *out_sh, float (*out_grad)[3]) {
  shli_real g[8];
  int i;
  n = shli_bands(n);
  if (n < 1) {
    return;
  }
  shli_cap_frame(SHLIGHT_REAL(c[0]) - SHLIGHT_REAL(x[0]), SHLIGHT_REAL(c[1]) - SHLIGHT_REAL(x[1]),
                 SHLIGHT_REAL(c[2]) - SHLIGHT_REAL(x[2]), SHLIGHT_REAL(r), g);
  if (g[6] == 0.0) {
#if SHLIGHT_BY_BANDS
    shli_sh_zero_grad(n, out_sh, out_grad);
#else
    for (i = 0; i < n * n; ++i) {
      out_sh[i] = 0.0f;
      out_grad[i][0] = 0.0f;
      out_grad[i][1] = 0.0f;
      out_grad[i][2] = 0.0f;
    }
#endif
    return;
  }
#if SHLIGHT_SIMD_EVAL
  if (n <= SHLIGHT_UNROLLED_BANDS) {
    shli_cap_light_grad_avx512(n, g, 1.0, 0.0, 0.0, 0.0, out_sh, out_grad);
    return;
  }
#endif
  shli_cap_light_grad(n, g, 1.0, 0.0, 0.0, 0.0, out_sh, out_grad);
}

/* Triangle as a sphere ([GRAD] eq. 24-25): out_g as shli_cap_frame for the sphere at the
   centroid with radius sqrt(|e1 x e2| / (2 pi)) seen from x, and out_g[7] = n_t . w = -cos gamma
   (n_t = unit (p1 - p0) x (p2 - p0), w the unit axis from x to the centroid); the weight is
   |out_g[7]|. out_nt: n_t (0 for a zero-area triangle, which gives out_g[6] = 0: no light;
   as do NaN and infinite input). */
SHLIGHT_INLINE void shli_tri_frame(const float x[3], const float p0[3], const float p1[3],
                                   const float p2[3], shli_real *out_g, shli_real *out_nt) {
  shli_real ax = SHLIGHT_REAL(p1[0]) - SHLIGHT_REAL(p0[0]);
  shli_real ay = SHLIGHT_REAL(p1[1]) - SHLIGHT_REAL(p0[1]);
  shli_real az = SHLIGHT_REAL(p1[2]) - SHLIGHT_REAL(p0[2]);
  shli_real bx = SHLIGHT_REAL(p2[0]) - SHLIGHT_REAL(p0[0]);
  shli_real by = SHLIGHT_REAL(p2[1]) - SHLIGHT_REAL(p0[1]);
  shli_real bz = SHLIGHT_REAL(p2[2]) - SHLIGHT_REAL(p0[2]);
  shli_real mx;
  shli_real sc = 1.0;
  shli_real nx = ay * bz - az * by;
  shli_real ny = az * bx - ax * bz;
  shli_real nz = ax * by - ay * bx;
  shli_real ar = SHLIGHT_SQRTR(nx * nx + ny * ny + nz * nz);
  shli_real rs = 0.0;
  shli_real cx =
      (SHLIGHT_REAL(p0[0]) - SHLIGHT_REAL(x[0]) + (SHLIGHT_REAL(p1[0]) - SHLIGHT_REAL(x[0])) +
       (SHLIGHT_REAL(p2[0]) - SHLIGHT_REAL(x[0]))) /
      3.0;
  shli_real cy =
      (SHLIGHT_REAL(p0[1]) - SHLIGHT_REAL(x[1]) + (SHLIGHT_REAL(p1[1]) - SHLIGHT_REAL(x[1])) +
       (SHLIGHT_REAL(p2[1]) - SHLIGHT_REAL(x[1]))) /
      3.0;
  shli_real cz =
      (SHLIGHT_REAL(p0[2]) - SHLIGHT_REAL(x[2]) + (SHLIGHT_REAL(p1[2]) - SHLIGHT_REAL(x[2])) +
       (SHLIGHT_REAL(p2[2]) - SHLIGHT_REAL(x[2]))) /
      3.0;
  out_nt[0] = 0.0;
  out_nt[1] = 0.0;
  out_nt[2] = 0.0;
  if (!(ar > 0.0 && ar <= SHLIGHT_REAL_MAX)) {
    /* the area overflowed (edges above ~1.3e19 in C, ~4e9 with float squares in GLSL),
       underflowed, or is 0 or NaN: again with the edges scaled to ~1, |e1 x e2| =
       sc^2 |e1/sc x e2/sc| (a zero-area triangle stays 0) */
    mx = SHLIGHT_MAXR(SHLIGHT_MAXR(SHLIGHT_ABSR(ax), SHLIGHT_ABSR(ay)), SHLIGHT_ABSR(az));
    mx = SHLIGHT_MAXR(
        mx, SHLIGHT_MAXR(SHLIGHT_MAXR(SHLIGHT_ABSR(bx), SHLIGHT_ABSR(by)), SHLIGHT_ABSR(bz)));
    if (mx > 0.0 && mx <= SHLIGHT_REAL_MAX) {
      sc = mx;
      mx = 1.0 / mx;
      ax = ax * mx;
      ay = ay * mx;
      az = az * mx;
      bx = bx * mx;
      by = by * mx;
      bz = bz * mx;
      nx = ay * bz - az * by;
      ny = az * bx - ax * bz;
      nz = ax * by - ay * bx;
      ar = SHLIGHT_SQRTR(nx * nx + ny * ny + nz * nz);
    }
  }
  if (ar > 0.0 && ar <= SHLIGHT_REAL_MAX) {
    rs = sc * SHLIGHT_SQRTR(ar * 0.15915494309189535);
    out_nt[0] = nx / ar;
    out_nt[1] = ny / ar;
    out_nt[2] = nz / ar;
  }
  shli_cap_frame(cx, cy, cz, rs, out_g);
  out_g[7] = out_nt[0] * out_g[0] + out_nt[1] * out_g[1] + out_nt[2] * out_g[2];
}

SHLIGHT_INLINE void shl_triangle_light(int n, const float x[3], const float p0[3],
                                       const float p1[3], const float p2[3], float *out_sh) {
  shli_real g[8];
  shli_real nt[3];
  int i;
  n = shli_bands(n);
  if (n < 1) {
    return;
  }
  shli_tri_frame(x, p0, p1, p2, g, nt);
  if (g[6] == 0.0) {
    for (i = 0; i < n * n; ++i) {
      out_sh[i] = 0.0f;
    }
    return;
  }
  shli_sh_eval_xyz(n, SHLIGHT_FLOAT(g[0]), SHLIGHT_FLOAT(g[1]), SHLIGHT_FLOAT(g[2]), out_sh);
  shli_cap_light_apply(n, g, SHLIGHT_ABSR(g[7]), out_sh);
}

SHLIGHT_INLINE void shl_triangle_light_grad(int n, const float x[3], const float p0[3],
                                            const float p1[3], const float p2[3], float *out_sh,
                                            float (*out_grad)[3]) {
  shli_real g[8];
  shli_real nt[3];
  shli_real sg = 0.0;
  shli_real cg;
  int i;
  n = shli_bands(n);
  if (n < 1) {
    return;
  }
  shli_tri_frame(x, p0, p1, p2, g, nt);
  if (g[6] == 0.0) {
#if SHLIGHT_BY_BANDS
    shli_sh_zero_grad(n, out_sh, out_grad);
#else
    for (i = 0; i < n * n; ++i) {
      out_sh[i] = 0.0f;
      out_grad[i][0] = 0.0f;
      out_grad[i][1] = 0.0f;
      out_grad[i][2] = 0.0f;
    }
#endif
    return;
  }
  /* cg = n_t . w = -cos gamma; grad_x |cg| = -sign(cg) (n_t - cg w) / d */
  cg = g[7];
  if (cg > 0.0) {
    sg = -g[3];
  }
  if (cg < 0.0) {
    sg = g[3];
  }
#if SHLIGHT_SIMD_EVAL
  if (n <= SHLIGHT_UNROLLED_BANDS) {
    shli_cap_light_grad_avx512(n, g, SHLIGHT_ABSR(cg), sg * (nt[0] - cg * g[0]),
                               sg * (nt[1] - cg * g[1]), sg * (nt[2] - cg * g[2]), out_sh,
                               out_grad);
    return;
  }
#endif
  shli_cap_light_grad(n, g, SHLIGHT_ABSR(cg), sg * (nt[0] - cg * g[0]), sg * (nt[1] - cg * g[1]),
                      sg * (nt[2] - cg * g[2]), out_sh, out_grad);
}

/* atan2(y, x) in shli_real from the shims alone, so C and GLSL run the same code (GLSL's
   atan is a driver approximation: llvmpipe's is off by 3.4e-6). Octant reduction to
   t = min / max in [0, 1], two half-angle steps t -> t / (1 + sqrt(1 + t^2)) to
   t <= tan(pi / 16), then the Taylor series to t^15: relative error <= 4e-13 (below the float
   rounding floor by 5 orders; C double, GLSL float rounding). atan2(0, 0) = 0; y = -0 counts as
   +0 (atan2(-0, x < 0) = +pi). Inputs must be finite. */
SHLIGHT_INLINE shli_real shli_atan2r(shli_real y, shli_real x) {
  shli_real ay = SHLIGHT_ABSR(y);
  shli_real ax = SHLIGHT_ABSR(x);
  shli_real t;
  shli_real t2;
  shli_real a;
  if (!(ax > 0.0 || ay > 0.0)) {
    return 0.0;
  }
  if (ay > ax) {
    t = ax / ay;
  } else {
    t = ay / ax;
  }
  t = t / (1.0 + SHLIGHT_SQRTR(1.0 + t * t));
  t = t / (1.0 + SHLIGHT_SQRTR(1.0 + t * t));
  t2 = t * t;
  a = -0.066666666666666667;
  a = 0.076923076923076923 + t2 * a;
  a = -0.090909090909090909 + t2 * a;
  a = 0.11111111111111111 + t2 * a;
  a = -0.14285714285714286 + t2 * a;
  a = 0.2 + t2 * a;
  a = -0.33333333333333333 + t2 * a;
  a = 4.0 * (t + t * (t2 * a));
  if (ay > ax) {
    a = 1.5707963267948966 - a;
  }
  if (x < 0.0) {
    a = 3.1415926535897932 - a;
  }
  if (y < 0.0) {
    a = -a;
  }
  return a;
}

SHLIGHT_INLINE float shl_triangle_solid_angle(const float x[3], const float p0[3],
                                              const float p1[3], const float p2[3]) {
  shli_real ax = SHLIGHT_REAL(p0[0]) - SHLIGHT_REAL(x[0]);
  shli_real ay = SHLIGHT_REAL(p0[1]) - SHLIGHT_REAL(x[1]);
  shli_real az = SHLIGHT_REAL(p0[2]) - SHLIGHT_REAL(x[2]);
  shli_real bx = SHLIGHT_REAL(p1[0]) - SHLIGHT_REAL(x[0]);
  shli_real by = SHLIGHT_REAL(p1[1]) - SHLIGHT_REAL(x[1]);
  shli_real bz = SHLIGHT_REAL(p1[2]) - SHLIGHT_REAL(x[2]);
  shli_real cx = SHLIGHT_REAL(p2[0]) - SHLIGHT_REAL(x[0]);
  shli_real cy = SHLIGHT_REAL(p2[1]) - SHLIGHT_REAL(x[1]);
  shli_real cz = SHLIGHT_REAL(p2[2]) - SHLIGHT_REAL(x[2]);
  shli_real ux = SHLIGHT_REAL(p1[0]) - SHLIGHT_REAL(p0[0]);
  shli_real uy = SHLIGHT_REAL(p1[1]) - SHLIGHT_REAL(p0[1]);
  shli_real uz = SHLIGHT_REAL(p1[2]) - SHLIGHT_REAL(p0[2]);
  shli_real vx = SHLIGHT_REAL(p2[0]) - SHLIGHT_REAL(p0[0]);
  shli_real vy = SHLIGHT_REAL(p2[1]) - SHLIGHT_REAL(p0[1]);
  shli_real vz = SHLIGHT_REAL(p2[2]) - SHLIGHT_REAL(p0[2]);
  shli_real mx;
  shli_real la = SHLIGHT_SQRTR(ax * ax + ay * ay + az * az);
  shli_real lb = SHLIGHT_SQRTR(bx * bx + by * by + bz * bz);
  shli_real lc = SHLIGHT_SQRTR(cx * cx + cy * cy + cz * cz);
  shli_real nm = ax * (uy * vz - uz * vy) + ay * (uz * vx - ux * vz) + az * (ux * vy - uy * vx);
  shli_real dn = la * lb * lc + (ax * bx + ay * by + az * bz) * lc +
                 (ax * cx + ay * cy + az * cz) * lb + (bx * cx + by * cy + bz * cz) * la;
  mx = SHLIGHT_ABSR(nm) + SHLIGHT_ABSR(dn);
  if (!(mx <= SHLIGHT_REAL_MAX) || !(mx >= 1.0e-30)) {
    /* the degree-3 products overflowed (|p_i - x| above ~7e12 in C, ~1e12 in GLSL) or are
       tiny, or NaN: Omega is scale-invariant, so again with everything scaled by the largest
       component of the p_i - x */
    mx = SHLIGHT_MAXR(SHLIGHT_MAXR(SHLIGHT_ABSR(ax), SHLIGHT_ABSR(ay)), SHLIGHT_ABSR(az));
    mx = SHLIGHT_MAXR(
        mx, SHLIGHT_MAXR(SHLIGHT_MAXR(SHLIGHT_ABSR(bx), SHLIGHT_ABSR(by)), SHLIGHT_ABSR(bz)));
    mx = SHLIGHT_MAXR(
        mx, SHLIGHT_MAXR(SHLIGHT_MAXR(SHLIGHT_ABSR(cx), SHLIGHT_ABSR(cy)), SHLIGHT_ABSR(cz)));
    if (!(mx > 0.0 && mx <= SHLIGHT_REAL_MAX)) {
      return 0.0f;
    }
    mx = 1.0 / mx;
    ax = ax * mx;
    ay = ay * mx;
    az = az * mx;
    bx = bx * mx;
    by = by * mx;
    bz = bz * mx;
    cx = cx * mx;
    cy = cy * mx;
    cz = cz * mx;
    ux = ux * mx;
    uy = uy * mx;
    uz = uz * mx;
    vx = vx * mx;
    vy = vy * mx;
    vz = vz * mx;
    la = SHLIGHT_SQRTR(ax * ax + ay * ay + az * az);
    lb = SHLIGHT_SQRTR(bx * bx + by * by + bz * bz);
    lc = SHLIGHT_SQRTR(cx * cx + cy * cy + cz * cz);
    nm = ax * (uy * vz - uz * vy) + ay * (uz * vx - ux * vz) + az * (ux * vy - uy * vx);
    dn = la * lb * lc + (ax * bx + ay * by + az * bz) * lc + (ax * cx + ay * cy + az * cz) * lb +
         (bx * cx + by * cy + bz * cz) * la;
    if (!(SHLIGHT_ABSR(nm) + SHLIGHT_ABSR(dn) <= SHLIGHT_REAL_MAX)) {
      return 0.0f;
    }
  }
  return SHLIGHT_FLOAT(2.0 * shli_atan2r(nm, dn));
}

/* >>grid ------------------------------------------------------------------------------------
   SH lighting on a regular 3D grid ([GRAD] sec. 5, after [WCZR20]): the SH coefficients of
   many sphere lights and their spatial gradients at the vertices of a grid (shl_grid_build,
   CPU), then reconstruction at any point from the 8 corners of its cell (kernels with GLSL
   twins: trilinear, first-order Taylor, Hermite; shl_grid_sample gathers the corners on the
   CPU).
   Grid: vertex (ix, iy, iz), 0 <= ix < nx ..., index v = ix + nx (iy + ny iz), position
     p_k = float(double(origin[k]) + double(i_k) double(spacing[k]))    (exact product, one
   rounding: the same bits whatever the compiler's FMA contraction). Storage: sh[v n^2 + i],
   grad[v n^2 + i][k] = d sh[v n^2 + i] / d x_k (float[3] per coefficient: 4 floats per
   coefficient with gradients, 1 without).
   Light j: centre c_j, radius r_j, intensity I_j (NULL: every I_j = 1); its contribution
   I_j shl_sphere_light(_grad) (see >>light: inside a light, the hemisphere).
   Culling (shl_grid.cull = eps >= 0; 0: every light reaches every vertex): light j is skipped
   at the vertices farther than R_j = max(r_j sqrt(2 pi |I_j| / eps), 2 r_j) from c_j (test in
   double: |c - p|^2 > R_j^2). Error bound, per skipped light and coefficient of band l
   (solid angle Omega = 2 pi (1 - alpha) <= 2 pi r^2 / d^2 < eps / |I|, |Z_l| <= Omega for the
   cap's ZH (|P_l| <= 1), |Y_l^m| <= sqrt((2l+1) / 4 pi)):
     |I_j sh_i| <= eps sqrt((2l+1) / (4 pi))
     |I_j grad sh_i| <= (eps / d) sqrt((2l+1) / (4 pi)) (sqrt(l (l+1)) + 2 / alpha),
   d > R_j >= 2 r_j so alpha >= sqrt(3) / 2 and the last factor <= l + 1 + 2.31; (the first
   term bounds the rotational part by the sum rule sum_m |grad_S Y_l^m|^2 =
   l (l+1) (2l+1) / 4 pi, the second the radial part 2 pi s^2 P_l / (d alpha) Y). The error at
   a vertex is at most the number of lights skipped there times these. The L2 norm over all
   n^2 coefficients is also <= |I_j| sqrt(Omega) < sqrt(eps |I_j|) (Bessel).
   Orders: SHLIGHT_GRID_FORWARD loops the vertices, then the lights (all lights, culling
   test per pair); SHLIGHT_GRID_REVERSED loops the lights, then the vertices of the box around
   the culling sphere (all vertices when eps = 0). Both add the lights to a vertex in index
   order with the same arithmetic: the two orders and 1 or 2 threads give the same bits.
   Threads: 2 splits the vertices into two z slabs (pthreads; define SHLIGHT_NO_THREADS, or a
   platform without <pthread.h> (not __unix__ / __APPLE__), and the work runs in the calling
   thread; a failed pthread_create runs the second slab in the caller too). glibc >= 2.34 has
   pthreads in libc; older systems link with -pthread.
   Reconstruction: the cell of p is (i0, i0+1) per axis with i0 = min(floor(u), dims - 2),
   u = (p - origin) / spacing clamped to [0, dims - 1], fraction f = u - i0 in [0, 1]; an axis
   with dims = 1 has f = 0 and both corners equal. Corner k of the cell: bit 0 x, bit 1 y,
   bit 2 z (k = cx + 2 cy + 4 cz); c8[k n^2 + i], g8[k n^2 + i][axis]. GLSL twins:
   c8 is float[8 * SHLIGHT_MAX_COEFFS], g8 vec3[8 * SHLIGHT_MAX_COEFFS].
   - trilinear: exact for multilinear data, error O(h^2), C0.
   - Taylor (first order from the nearest corner, [AKDS04]; ties f = 0.5 go to corner 1):
     exact for linear data, error O(h^2), discontinuous at the mid-planes of the cell.
   - Hermite: the tensor-product cubic Hermite interpolant (tricubic Hermite, 64 conditions)
     whose values and gradients at the corners are the grid's, and whose mixed derivatives,
     which the grid does not store, are estimated inside the cell from the gradients:
       h_x h_y f_xy ~ ((G_x(cx,1,cz) - G_x(cx,0,cz)) + (G_y(1,cy,cz) - G_y(0,cy,cz))) / 2,
       h_x h_y h_z f_xyz ~ (D_yz G_x(cx) + D_xz G_y(cy) + D_xy G_z(cz)) / 3,
     G_a = h_a g_a, D the differences across the cell (so the mixed estimates on a face use
     that face's data only: the interpolant is C0 across cells). It reproduces the
     corner values and gradients exactly, every polynomial of total degree <= 2 exactly, and
     has error O(h^3) (zero mixed derivatives would leave O(h^2)). Evaluated as one linear
     combination of the 32 corner data with weights computed once per call (32 FMA per
     coefficient). The seed and [WCZR20] do not spell out their mixed-derivative treatment;
     this is ours. */

SHLIGHT_INLINE void shl_grid_trilinear(int n, const float *c8, const float f[3], float *out_sh) {
  float x1 = f[0];
  float x0 = 1.0f - f[0];
  float y1 = f[1];
  float y0 = 1.0f - f[1];
  float z1 = f[2];
  float z0 = 1.0f - f[2];
  float a;
  float b;
  float c;
  float d;
  int nn;
  int i;
  n = shli_bands(n);
  if (n < 1) {
    return;
  }
  nn = n * n;
  for (i = 0; i < nn; ++i) {
    a = x0 * c8[i] + x1 * c8[nn + i];
    b = x0 * c8[2 * nn + i] + x1 * c8[3 * nn + i];
    c = x0 * c8[4 * nn + i] + x1 * c8[5 * nn + i];
    d = x0 * c8[6 * nn + i] + x1 * c8[7 * nn + i];
    a = y0 * a + y1 * b;
    c = y0 * c + y1 * d;
    out_sh[i] = z0 * a + z1 * c;
  }
}

SHLIGHT_INLINE void shl_grid_taylor(int n, const float *c8, const float (*g8)[3], const float f[3],
                                    const float cell[3], float *out_sh) {
  int cx = 0;
  int cy = 0;
  int cz = 0;
  int o;
  int nn;
  int i;
  float dx;
  float dy;
  float dz;
  n = shli_bands(n);
  if (n < 1) {
    return;
  }
  if (f[0] >= 0.5f) {
    cx = 1;
  }
  if (f[1] >= 0.5f) {
    cy = 1;
  }
  if (f[2] >= 0.5f) {
    cz = 1;
  }
  dx = (f[0] - SHLIGHT_ITOF(cx)) * cell[0];
  dy = (f[1] - SHLIGHT_ITOF(cy)) * cell[1];
  dz = (f[2] - SHLIGHT_ITOF(cz)) * cell[2];
  nn = n * n;
  o = (cx + 2 * cy + 4 * cz) * nn;
  for (i = 0; i < nn; ++i) {
    out_sh[i] = c8[o + i] + (g8[o + i][0] * dx + g8[o + i][1] * dy + g8[o + i][2] * dz);
  }
}

SHLIGHT_INLINE void shl_grid_hermite(int n, const float *c8, const float (*g8)[3], const float f[3],
                                     const float cell[3], float *out_sh) {
  float ha[6];
  float hb[6];
  float sb[3];
  float wv[8];
  float wx[8];
  float wy[8];
  float wz[8];
  float t;
  float u;
  float ax;
  float ay;
  float az;
  float bx;
  float by;
  float bz;
  float sx;
  float sy;
  float sz;
  float s;
  int j;
  int k;
  int cx;
  int cy;
  int cz;
  int o;
  int nn;
  int i;
  n = shli_bands(n);
  if (n < 1) {
    return;
  }
  /* per axis j: value bases ha[2j + c] and slope bases hb[2j + c] of corner c, sb = their
     sum of slopes t (1 - t) (1 - 2t) */
  for (j = 0; j < 3; ++j) {
    t = f[j];
    u = 1.0f - t;
    ha[2 * j] = u * u * (1.0f + 2.0f * t);
    ha[2 * j + 1] = t * t * (1.0f + 2.0f * u);
    hb[2 * j] = t * u * u;
    hb[2 * j + 1] = -(t * t * u);
    sb[j] = hb[2 * j] + hb[2 * j + 1];
  }
  for (k = 0; k < 8; ++k) {
    cx = k % 2;
    cy = (k / 2) % 2;
    cz = k / 4;
    ax = ha[cx];
    ay = ha[2 + cy];
    az = ha[4 + cz];
    bx = hb[cx];
    by = hb[2 + cy];
    bz = hb[4 + cz];
    sx = SHLIGHT_ITOF(2 * cx - 1);
    sy = SHLIGHT_ITOF(2 * cy - 1);
    sz = SHLIGHT_ITOF(2 * cz - 1);
    wv[k] = ax * ay * az;
    wx[k] = cell[0] * bx *
            (ay * az + 0.5f * (sb[1] * sy * az + sb[2] * sz * ay) +
             0.33333333f * (sb[1] * sb[2] * sy * sz));
    wy[k] = cell[1] * by *
            (ax * az + 0.5f * (sb[0] * sx * az + sb[2] * sz * ax) +
             0.33333333f * (sb[0] * sb[2] * sx * sz));
    wz[k] = cell[2] * bz *
            (ax * ay + 0.5f * (sb[0] * sx * ay + sb[1] * sy * ax) +
             0.33333333f * (sb[0] * sb[1] * sx * sy));
  }
  nn = n * n;
  for (i = 0; i < nn; ++i) {
    s = 0.0f;
    for (k = 0; k < 8; ++k) {
      o = k * nn + i;
      s = s + (wv[k] * c8[o] + wx[k] * g8[o][0] + wy[k] * g8[o][1] + wz[k] * g8[o][2]);
    }
    out_sh[i] = s;
  }
}

/* CPU only (declared here, defined with SHLIGHT_IMPLEMENTATION). */

/* >>edge ------------------------------------------------------------------------------------
   Area lights without tables ([AREA], docs/math.md section 7): axial moments of polygons, the
   moment M^e(P, r) = integral over the solid angle of P, clipped to the hemisphere u.r >= 0, of
   (u.r)^e. Two exact identities carry everything here (docs/math.md section 7.1 and this header's
   derivation in docs/area-lights.md):
   - Arvo (integer e): (e+1) M = [e even] Omega + sum_i w_i F(Phi_i, c_i, delta_i, e-1), with
     the edge integral F of [AREA] eq. 3 (corrections E10, E11 applied), F's exact O(e) recurrence
     or the paper's O(1) peak fits (Lorentzian, Lorentzian-Pearson, ellipsoid; corrections E12-E17).
   - Stokes in the azimuth about r (any real e >= 0, derived for shlight): with the 1-form
     (x^(e+1) - 1)/(e+1) dpsi, x = u.r, the pole term vanishes and
       (e+1) M = -sum_i sgn(w_i) integral over theta in the edge's arc of (1 - h(theta)) dtheta,
       h = (c^2 cos^2 theta / (1 - c^2 sin^2 theta))^((e+1)/2), tan theta = tan phi / |w_i|,
     an integrand in [0, 1] with no cancellation against a solid-angle term. Its integral is
     taken with a fixed 5-node Gauss-Legendre rule on each half-arc after the graded change of
     variables pi/2 - |theta| = beta sinh(s), beta = atan(|w| sqrt(e+1)) / 2 (the boundary layer
     of 1 - h sits at |theta| -> pi/2 with width ~ |w| sqrt(e+1)): constant cost for every e. */

/* Polygons of any vertex count (C, SHLIGHT_POLYGON_ANY): each polygon function takes nv in
   [3, SHLIGHT_POLYGON_MAX] in one piece; above that it cuts the polygon into fan pieces
   (v0, v_i, ..., v_m) of at most SHLIGHT_POLYGON_MAX vertices whose fan triangles
   (v0, v_j, v_j+1) all turn the same way as seen from the shading point (the sign of
   det(v0, v_j, v_j+1)), calls itself on each piece and adds the pieces with their signs: a
   piece of one turning sense has one winding, so the function's (non-negative) value for it is
   its integral, and the fan edges v0 -> v_i cancel between neighbours. The sum is relative to
   the whole polygon's orientation (the sum of the dets, the sign each kernel takes from its
   vector area), then clamped at 0 as in one piece: a non-convex or self-overlapping polygon is
   integrated with its winding number (the region turned twice counts twice, a part turned
   against the whole subtracts), the same rule the one-piece kernels follow. O(1) memory (one
   piece, 96 bytes); cost about (nv - 2) / (SHLIGHT_POLYGON_MAX - 2) pieces of the kernel
   (a convex polygon: 1 + 2 ceil((nv - 2) / 6) / nv more edges than vertices). NaN or infinite
   vertices, or a polygon whose dets sum to zero (seen edge-on): 0, as in one piece. GLSL keeps
   the compile-time maximum SHLIGHT_POLYGON_MAX (its arrays are that long); there nv above it
   returns -1 (no real result is negative). */
typedef struct {
  float p[SHLIGHT_POLYGON_MAX][3]; /* the current piece */
  double sum;                      /* the signed sum of the pieces' values so far */
  int np;                          /* the current piece's vertex count */
  int sg;                          /* its turning sense (+1, -1; 0: all its triangles flat) */
  int st;                          /* the whole polygon's orientation (+1, -1; 0: none) */
  int next;                        /* the fan index the next piece starts from */
} shli_fan;

/* det(v0, v_i, v_i+1) in double (exact products of floats up to rounding of the sums) */
SHLIGHT_CPU_INLINE double shli_fan_det(const float (*v)[3], int i) {
  double ax = (double)v[0][0];
  double ay = (double)v[0][1];
  double az = (double)v[0][2];
  double bx = (double)v[i][0];
  double by = (double)v[i][1];
  double bz = (double)v[i][2];
  double cx = (double)v[i + 1][0];
  double cy = (double)v[i + 1][1];
  double cz = (double)v[i + 1][2];
  return ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx);
}

/* starts the pieces of v[0..nv-1]: st = the sign of the summed dets, 0 when it is zero, not
   finite or a vertex is not finite (then no piece follows and the sum stays 0) */
SHLIGHT_CPU_INLINE void shli_fan_begin(shli_fan *f, const float (*v)[3], int nv) {
  double o = 0.0;
  int i;
  f->sum = 0.0;
  f->np = 0;
  f->sg = 0;
  f->st = 0;
  f->next = nv;
  for (i = 0; i < nv; ++i) {
    if (!(fabs((double)v[i][0]) + fabs((double)v[i][1]) + fabs((double)v[i][2]) < 1.0e300)) {
      return;
    }
  }
  for (i = 1; i + 1 < nv; ++i) {
    o = o + shli_fan_det(v, i);
  }
  if (o > 0.0 || o < 0.0) {
    f->st = o > 0.0 ? 1 : -1;
    f->next = 1;
  }
}

/* the next piece into f->p, f->np, f->sg; returns 0 when there is none left */
SHLIGHT_CPU_INLINE int shli_fan_next(shli_fan *f, const float (*v)[3], int nv) {
  int i = f->next;
  int m = i;
  int s;
  int k;
  double t;
  if (i + 1 >= nv) {
    return 0;
  }
  f->sg = 0;
  while (m + 1 < nv && m - i < SHLIGHT_POLYGON_MAX - 2) {
    t = shli_fan_det(v, m);
    s = t > 0.0 ? 1 : (t < 0.0 ? -1 : 0);
    if (s != 0 && f->sg != 0 && s != f->sg) {
      break;
    }
    if (f->sg == 0) {
      f->sg = s;
    }
    m = m + 1;
  }
  f->np = m - i + 2;
  for (k = 0; k < 3; ++k) {
    f->p[0][k] = v[0][k];
  }
  for (s = i; s <= m; ++s) {
    for (k = 0; k < 3; ++k) {
      f->p[s - i + 1][k] = v[s][k];
    }
  }
  f->next = m;
  return 1;
}

/* the signed sum relative to the whole polygon's orientation, clamped at 0 */
SHLIGHT_CPU_INLINE float shli_fan_end(const shli_fan *f) {
  double r = (double)f->st * f->sum;
  return r > 0.0 ? (float)r : 0.0f;
}

SHLIGHT_CPU_INLINE float shli_fan_moment(const float (*v)[3], int nv, const float axis[3],
                                         float exponent, shl_edge_method method);
SHLIGHT_CPU_INLINE float shli_fan_phong(const float (*v)[3], int nv, const float nrm[3],
                                        const float view[3], float exponent,
                                        shl_edge_method method);
SHLIGHT_CPU_INLINE float shli_fan_phong2(const float (*v)[3], int nv, const float nrm[3],
                                         const float view[3], float exponent,
                                         shl_edge_method method);
SHLIGHT_CPU_INLINE float shli_fan_ggx_ndf(const float (*v)[3], int nv, const float axis[3],
                                          float alpha);
SHLIGHT_CPU_INLINE float shli_fan_ggx(const float (*v)[3], int nv, const float nrm[3],
                                      const float view[3], float alpha);
SHLIGHT_CPU_INLINE float shli_fan_beckmann_taylor(const float (*v)[3], int nv, const float nrm[3],
                                                  const float view[3], float alpha);
SHLIGHT_CPU_INLINE float shli_fan_beckmann_ndf(const float (*v)[3], int nv, const float axis[3],
                                               float alpha);
SHLIGHT_CPU_INLINE float shli_fan_blinn_phong(const float (*v)[3], int nv, const float nrm[3],
                                              const float view[3], float exponent, int subedges);
SHLIGHT_CPU_INLINE float shli_fan_beckmann(const float (*v)[3], int nv, const float nrm[3],
                                           const float view[3], float alpha, int subedges);

/* Horner expm1 for |t| <= 0.25 (relative error < 1e-15 in double), exp(t) - 1 beyond. */
SHLIGHT_INLINE shli_real shli_expm1r(shli_real t) {
  shli_real p;
  if (!(SHLIGHT_ABSR(t) <= 0.25)) {
    return SHLIGHT_EXPR(t) - 1.0;
  }
  p = 2.5052108385441719e-8;
  p = 2.7557319223985891e-7 + t * p;
  p = 2.7557319223985891e-6 + t * p;
  p = 2.4801587301587302e-5 + t * p;
  p = 1.9841269841269841e-4 + t * p;
  p = 1.3888888888888889e-3 + t * p;
  p = 8.3333333333333333e-3 + t * p;
  p = 4.1666666666666667e-2 + t * p;
  p = 0.16666666666666667 + t * p;
  p = 0.5 + t * p;
  return t + t * (t * p);
}

/* The edge integrand of [AREA] eq. 5-6: I(x) = sum over k = nf, nf - 2, ..., >= 0 of x^k,
   x = c cos(phi), in the expm1 form f (1 - x^m) / (1 - x^2) (m = nf + 2 for even nf, nf + 1
   with f = x for odd nf) with its limit f m / 2 at x^2 = 1 (docs/math.md section 7.1). */
SHLIGHT_INLINE shli_real shli_edge_isum(shli_real x, int nf) {
  shli_real f = 1.0;
  shli_real x2 = x * x;
  shli_real l;
  int m = nf + 2;
  if (nf - 2 * (nf / 2) == 1) {
    f = x;
    m = nf + 1;
  }
  if (!(x2 < 1.0)) {
    return f * SHLIGHT_ITOR(m / 2);
  }
  if (!(x2 > 1.0e-30)) {
    return f;
  }
  l = SHLIGHT_LOGR(x2);
  return f * (shli_expm1r(0.5 * SHLIGHT_ITOR(m) * l) / shli_expm1r(l));
}

/* F by the exact recurrence T_k = (x_B^(k-1) y_B - x_A^(k-1) y_A) / k + c^2 (k-1)/k T_(k-2),
   T_0 = phi, T_1 = y_B - y_A, from the arc's end points in the edge plane (x = u.r = c cos,
   y = u.(n x r) = c sin) and its length phi: no angle placement, so it stays exact when c is
   tiny. Powers below 1e-30 are flushed to 0 so large nf never runs on subnormals. Cost O(nf). */
SHLIGHT_INLINE shli_real shli_edge_exact_xy(shli_real xa, shli_real ya, shli_real xb, shli_real yb,
                                            shli_real c2, shli_real phi, int nf) {
  shli_real t = phi;
  shli_real pwa = xa;
  shli_real pwb = xb;
  shli_real sum;
  int k = 2;
  if (nf - 2 * (nf / 2) == 1) {
    t = yb - ya;
    pwa = xa * xa;
    pwb = xb * xb;
    k = 3;
  }
  sum = t;
  while (k <= nf) {
    t = (pwb * yb - pwa * ya) / SHLIGHT_ITOR(k) + c2 * (SHLIGHT_ITOR(k - 1) / SHLIGHT_ITOR(k)) * t;
    sum = sum + t;
    pwa = pwa * xa * xa;
    pwb = pwb * xb * xb;
    if (SHLIGHT_ABSR(pwa) < 1.0e-30) {
      pwa = 0.0;
    }
    if (SHLIGHT_ABSR(pwb) < 1.0e-30) {
      pwb = 0.0;
    }
    k = k + 2;
  }
  return sum;
}

/* F over [pa, pb] inside [-pi/2, pi/2] (pb - pa = Phi, pa = -delta), c in [0, 1], order nf >= 0:
   the recurrence above at the arc's end points. */
SHLIGHT_INLINE shli_real shli_edge_exact(shli_real pa, shli_real pb, shli_real c, int nf) {
  return shli_edge_exact_xy(c * SHLIGHT_COSR(pa), c * SHLIGHT_SINR(pa), c * SHLIGHT_COSR(pb),
                            c * SHLIGHT_SINR(pb), c * c, pb - pa, nf);
}

/* The paper's O(1) fits of F over [pa, pb] inside [-pi/2, pi/2], nf >= 3, c in (1.0e-3, 1]:
   peak I_max = I(0), floor I_min = I(pi/2), half width x_w of eq. 7 (correction E12 (docs/math.md
   section 12): level (I_max + I_min) / 2), the fit passing through (x_w, I(x_w)); Lorentzian with
   the atan2 form of eq. 12 (E13); Lorentzian-Pearson with b = a / 2, the corrected antiderivative
   (E14) and the blend factor clamped to [0, 1] (E17); single ellipsoid eq. 15-16, 18 (its
   degenerate a_E = 1 falls back to the Lorentzian). */
SHLIGHT_INLINE shli_real shli_edge_fit(shli_real pa, shli_real pb, shli_real c, int nf,
                                       int method) {
  int odd = nf - 2 * (nf / 2);
  shli_real imin = 1.0;
  shli_real imax = shli_edge_isum(c, nf);
  shli_real phi = pb - pa;
  shli_real xw;
  shli_real xw0 = 0.78539816339744831;
  shli_real yw;
  shli_real q;
  shli_real a;
  shli_real sa;
  shli_real pl;
  shli_real sl;
  shli_real tl;
  shli_real fl;
  shli_real b;
  shli_real sb;
  shli_real pp;
  shli_real sp;
  shli_real tp;
  shli_real fp;
  shli_real xt;
  shli_real it;
  shli_real il;
  shli_real ip;
  shli_real al;
  shli_real cw;
  if (odd == 1) {
    imin = 0.0;
    xw0 = 1.0471975511965977;
    q = c - c / SHLIGHT_ITOR(nf);
    xw = xw0 * SHLIGHT_SQRTR(SHLIGHT_MAXR(0.0, 1.0 - q * q));
  } else {
    q = SHLIGHT_MAXR(0.0, c - c / SHLIGHT_ITOR(nf - 1));
    xw = xw0 * SHLIGHT_POWR(SHLIGHT_MAXR(0.0, 1.0 - SHLIGHT_POWR(q, 2.5)), 0.45);
  }
  xw = SHLIGHT_MAXR(xw, 1.0e-4);
  yw = (shli_edge_isum(c * SHLIGHT_COSR(xw), nf) - imin) / (imax - imin);
  yw = SHLIGHT_MINR(SHLIGHT_MAXR(yw, 1.0e-12), 1.0 - 1.0e-12);
  a = SHLIGHT_MAXR((1.0 - yw - 0.40528473456935109 * xw * xw) / (yw * xw * xw), 1.0e-9);
  sa = SHLIGHT_SQRTR(a);
  pl = 1.0 / (1.0 + 2.4674011002723397 * a);
  sl = (imax - imin) / (1.0 - pl);
  tl = imin - sl * pl;
  fl = sl / sa * shli_atan2r(sa * phi, 1.0 + a * pa * pb) + tl * phi;
  if (method == SHLIGHT_EDGE_LORENTZ_PEARSON) {
    b = 0.5 * a;
    sb = SHLIGHT_SQRTR(b);
    pp = 1.0 / ((1.0 + 2.4674011002723397 * b) * (1.0 + 2.4674011002723397 * b));
    sp = (imax - imin) / (1.0 - pp);
    tp = imin - sp * pp;
    fp = sp * (0.5 * (pb / (1.0 + b * pb * pb) - pa / (1.0 + b * pa * pa)) +
               shli_atan2r(sb * phi, 1.0 + b * pa * pb) / (2.0 * sb)) +
         tp * phi;
    xt = xw + 0.3946 * xw0 * (1.0 - SHLIGHT_POWR(SHLIGHT_MAXR(0.0, 1.0 - xw / xw0), 12.0));
    xt = SHLIGHT_MINR(xt, 1.5707963267948966);
    it = shli_edge_isum(c * SHLIGHT_COSR(xt), nf);
    il = sl / (1.0 + a * xt * xt) + tl;
    ip = sp / ((1.0 + b * xt * xt) * (1.0 + b * xt * xt)) + tp;
    al = 0.0;
    if (SHLIGHT_ABSR(ip - il) > 1.0e-30) {
      al = SHLIGHT_MINR(SHLIGHT_MAXR((ip - it) / (ip - il), 0.0), 1.0);
    }
    return al * fl + (1.0 - al) * fp;
  }
  if (method == SHLIGHT_EDGE_ELLIPSOID) {
    cw = SHLIGHT_COSR(xw);
    cw = cw * cw;
    a = yw * (1.0 - cw) / (cw * (1.0 - yw));
    if (!(SHLIGHT_ABSR(1.0 - a) > 1.0e-6) || !(a > 0.0)) {
      return fl;
    }
    sa = SHLIGHT_SQRTR(a);
    sl = (imax - imin) / (1.0 - a);
    tl = imin - sl * a;
    return sl * sa *
               shli_atan2r(sa * SHLIGHT_SINR(phi), a * SHLIGHT_COSR(pa) * SHLIGHT_COSR(pb) +
                                                       SHLIGHT_SINR(pa) * SHLIGHT_SINR(pb)) +
           tl * phi;
  }
  return fl;
}

SHLIGHT_INLINE float shl_edge_integral(float phi, float c, float delta, float exponent,
                                       shl_edge_method method) {
  shli_real cc = SHLIGHT_MINR(SHLIGHT_MAXR(SHLIGHT_REAL(c), 0.0), 1.0);
  shli_real p = SHLIGHT_MINR(SHLIGHT_MAXR(SHLIGHT_REAL(phi), 0.0), 3.1415926535897932);
  shli_real lo = -SHLIGHT_REAL(delta);
  shli_real hi;
  shli_real sum = 0.0;
  shli_real sg = 1.0;
  shli_real a;
  shli_real b;
  int nf;
  int piece = 0;
  if (!(exponent >= 0.0f) || !(SHLIGHT_ABSR(lo) < 1.0e6) || !(p >= 0.0) || !(cc >= 0.0)) {
    return 0.0f;
  }
  nf = SHLIGHT_FTOI(SHLIGHT_MINR(SHLIGHT_REAL(exponent), 1.0e6) + 0.5);
  /* shift lo into [-pi/2, pi/2) */
  while (lo >= 1.5707963267948966) {
    lo = lo - 3.1415926535897932;
    if (nf - 2 * (nf / 2) == 1) {
      sg = -sg;
    }
  }
  while (lo < -1.5707963267948966) {
    lo = lo + 3.1415926535897932;
    if (nf - 2 * (nf / 2) == 1) {
      sg = -sg;
    }
  }
  hi = lo + p;
  while (piece < 3 && hi > lo) {
    a = lo;
    b = SHLIGHT_MINR(hi, 1.5707963267948966);
    if (nf <= 2 || cc < 1.0e-3 || method < SHLIGHT_EDGE_LORENTZ ||
        method > SHLIGHT_EDGE_ELLIPSOID) {
      sum = sum + sg * shli_edge_exact(a, b, cc, nf);
    } else {
      sum = sum + sg * shli_edge_fit(a, b, cc, nf, method);
    }
    lo = -1.5707963267948966;
    hi = hi - 3.1415926535897932;
    if (nf - 2 * (nf / 2) == 1) {
      sg = -sg;
    }
    piece = piece + 1;
  }
  return SHLIGHT_FLOAT(sum);
}

/* Sutherland-Hodgman clip of the polygon (io_px, io_py, io_pz)[0..nv-1] to the half-space
   p.m >= 0 (a plane through the shading point), in place; returns the new vertex count (at
   most SHLIGHT_CLIP_MAX vertices are kept). Non-convex input gives overlapping edges along
   the plane, which cancel in every edge sum here. */
SHLIGHT_INLINE int shli_poly_clip(shli_real *io_px, shli_real *io_py, shli_real *io_pz, int nv,
                                  shli_real mx, shli_real my, shli_real mz) {
  shli_real tx[SHLIGHT_CLIP_MAX];
  shli_real ty[SHLIGHT_CLIP_MAX];
  shli_real tz[SHLIGHT_CLIP_MAX];
  shli_real da;
  shli_real db;
  shli_real t;
  int i;
  int j;
  int k = 0;
  for (i = 0; i < nv; ++i) {
    j = i + 1;
    if (j == nv) {
      j = 0;
    }
    da = io_px[i] * mx + io_py[i] * my + io_pz[i] * mz;
    db = io_px[j] * mx + io_py[j] * my + io_pz[j] * mz;
    if (da >= 0.0 && k < SHLIGHT_CLIP_MAX) {
      tx[k] = io_px[i];
      ty[k] = io_py[i];
      tz[k] = io_pz[i];
      k = k + 1;
    }
    if (((da >= 0.0 && db < 0.0) || (da < 0.0 && db >= 0.0)) && k < SHLIGHT_CLIP_MAX) {
      t = da / (da - db);
      tx[k] = io_px[i] + t * (io_px[j] - io_px[i]);
      ty[k] = io_py[i] + t * (io_py[j] - io_py[i]);
      tz[k] = io_pz[i] + t * (io_pz[j] - io_pz[i]);
      k = k + 1;
    }
  }
  for (i = 0; i < k; ++i) {
    io_px[i] = tx[i];
    io_py[i] = ty[i];
    io_pz[i] = tz[i];
  }
  return k;
}

/* The FAST method (SHLIGHT_EDGE_FAST): the Stokes form above in float, laid out for SIMD.
   Per edge the two half-arcs in |theta| each get a 4-node Gauss-Legendre rule after the
   rational grading pi/2 - |theta| = beta t / (1 - t) (t in [0, 1)), beta =
   1.5 x / (1 + 0.6366 x), x = |w| sqrt(e + 1): no transcendental in the grading, and the
   nodes of all edges are independent, so the C edge loop runs SHLIGHT_LANES edges per block
   (one AVX register per quantity) with polynomial atan2 / sin / log1p / exp (C only, below;
   GLSL calls its built-ins). Chosen by experiment (numpy, 1500 random half-arcs, e = 3..1e4,
   per half-arc error in units of the normalised lobe): sinh grading K = 4: max 7.8e-4,
   rational K = 4, beta factor 1.5: max 8.2e-4, p95 2.1e-4, with half the transcendentals. */

/* GCC keeps -ftrapping-math by default and then will not if-convert a float compare-and-select,
   so the FAST edge loop would stay scalar; the FAST functions are compiled without it (no
   value changes: it only lets the compiler evaluate both arms of a select). Clang's default. */
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC push_options
#pragma GCC optimize("no-trapping-math")
#endif

/* float <-> bits and the polynomial transcendentals of the FAST path (C only, branch-free so
   that the edge loop vectorises; GLSL uses atan, sin, log and exp). */
SHLIGHT_CPU_INLINE int shli_fbits(float x) {
  int i;
  memcpy(&i, &x, sizeof i);
  return i;
}
SHLIGHT_CPU_INLINE float shli_bitsf(int i) {
  float x;
  memcpy(&x, &i, sizeof x);
  return x;
}
/* atan2(y, x), |error| < 6e-7 rad (degree-13 odd fit on [0, 1]); atan2(0, 0) = 0 */
SHLIGHT_CPU_INLINE float shli_fatan2(float y, float x) {
  float ax = fabsf(x);
  float ay = fabsf(y);
  float mx = ax > ay ? ax : ay;
  float mn = ax > ay ? ay : ax;
  float a = mn / (mx > 1.0e-30f ? mx : 1.0e-30f);
  float s = a * a;
  float r = 0.0080076919f;
  r = -0.0374455431f + s * r;
  r = 0.0843572751f + s * r;
  r = -0.135123653f + s * r;
  r = 0.198873758f + s * r;
  r = -0.333270201f + s * r;
  r = 0.999999419f + s * r;
  r = a * r;
  r = ay > ax ? 1.57079633f - r : r;
  r = x < 0.0f ? 3.14159265f - r : r;
  return y < 0.0f ? -r : r;
}
/* sqrt(x) for x >= 0 without errno (relative error < 5e-6): bit-trick reciprocal square root
   and two Newton steps; sqrt(0) = 0 */
SHLIGHT_CPU_INLINE float shli_fsqrt(float x) {
  float y = shli_bitsf(0x5f375a86 - (shli_fbits(x) >> 1));
  y = y * (1.5f - 0.5f * x * y * y);
  y = y * (1.5f - 0.5f * x * y * y);
  return x * y;
}
/* sin(u) for u in [0, pi/2]: Taylor to u^11, |error| < 6e-8, relative accuracy kept at 0 */
SHLIGHT_CPU_INLINE float shli_fsin(float u) {
  float s = u * u;
  float p = -2.50521084e-8f;
  p = 2.75573192e-6f + s * p;
  p = -1.98412698e-4f + s * p;
  p = 8.33333333e-3f + s * p;
  p = -0.166666667f + s * p;
  return u + u * (s * p);
}
/* log(1 + y) for y in [0, 1e30]: exponent split of v = 1 + y about sqrt(1/2), 2 atanh series
   to s^7 (relative error < 1e-7), and the rounding of 1 + y put back: (y - (v - 1)) / v. */
SHLIGHT_CPU_INLINE float shli_flog1p(float y) {
  float v = 1.0f + y;
  int iv = shli_fbits(v);
  int k = (iv - 0x3f3504f3) >> 23;
  float f = shli_bitsf(iv - k * 8388608);
  float s = (f - 1.0f) / (f + 1.0f);
  float s2 = s * s;
  float p = 0.142857143f;
  p = 0.2f + s2 * p;
  p = 0.333333333f + s2 * p;
  p = 2.0f * s + 2.0f * s * (s2 * p);
  return (float)k * 0.693147181f + p + (y - (v - 1.0f)) / v;
}
/* exp(z) for z <= 0 (clamped at -87): 2^k by the exponent bits, Taylor to f^6 on
   |f| <= ln2 / 2 (relative error < 2e-7). The clamp max(z, -87) is an integer min of the
   bit patterns (for z <= 0 a larger magnitude is a larger signed int): GCC vectorises it
   (vpminsd), where a float select keeps the edge loop scalar (3.6k instead of 1.3k
   instructions per quad) and the earlier 0.5 (z - 87 + |z + 87|) lost z to rounding below
   -1e9 (exp of garbage, up to 1e26, at exponents >= 3e9). The callers pass z <= 0 only (a
   positive z would be clamped to -87). */
SHLIGHT_CPU_INLINE float shli_fexp(float z) {
  int bz = shli_fbits(z);
  int bc = -1028784128; /* the bits of -87.0f, 0xc2ae0000 */
  float x;
  bz = bz < bc ? bz : bc;
  x = shli_bitsf(bz);
  int k = (int)(x * 1.44269504f - 0.5f);
  float f = x - (float)k * 0.693145752f - (float)k * 1.42860677e-6f;
  float p = 1.38888889e-3f;
  p = 8.33333333e-3f + f * p;
  p = 4.16666667e-2f + f * p;
  p = 0.166666667f + f * p;
  p = 0.5f + f * p;
  p = 1.0f + f * (1.0f + f * p);
  return p * shli_bitsf((k + 127) * 8388608);
}

/* (1 - h) d|theta|/dt at the graded node t of the FAST rule */
SHLIGHT_INLINE float shli_fast_node(float t, float beta, float c2, float w2, float hm) {
  float r = 1.0f / (1.0f - t);
  float su = SHLIGHT_FSIN(beta * t * r);
  float q = SHLIGHT_MAXR(c2 * su * su, 1.0e-30f);
  float y = w2 / q;
  y = SHLIGHT_MINR(y, 1.0e30f);
  return (1.0f - SHLIGHT_FEXP(-hm * SHLIGHT_FLOG1P(y))) * beta * r * r;
}

/* integral of (1 - h) over |theta| in [lo, hi] inside [0, pi/2] (empty when hi <= lo) */
SHLIGHT_INLINE float shli_fast_half(float lo, float hi, float beta, float c2, float w2, float hm) {
  float ulo = 1.57079633f - SHLIGHT_MAXR(hi, lo);
  float uhi = 1.57079633f - lo;
  float tl = ulo / (ulo + beta);
  float th = uhi / (uhi + beta);
  float m = 0.5f * (tl + th);
  float r = 0.5f * (th - tl);
  float s = 0.652145155f * (shli_fast_node(m - 0.339981044f * r, beta, c2, w2, hm) +
                            shli_fast_node(m + 0.339981044f * r, beta, c2, w2, hm));
  s = s + 0.347854845f * (shli_fast_node(m - 0.861136312f * r, beta, c2, w2, hm) +
                          shli_fast_node(m + 0.861136312f * r, beta, c2, w2, hm));
  return r * s;
}

/* Sutherland-Hodgman clip in float of (io_px, io_py, io_pz)[0..nv-1] to p.m >= 0, in place;
   returns the new vertex count (the float twin of shli_poly_clip). Nothing cut (the common
   case): no copy. */
SHLIGHT_INLINE int shli_fast_clip(float *io_px, float *io_py, float *io_pz, int nv, float mx,
                                  float my, float mz) {
  float tx[SHLIGHT_CLIP_MAX];
  float ty[SHLIGHT_CLIP_MAX];
  float tz[SHLIGHT_CLIP_MAX];
  float d[SHLIGHT_CLIP_MAX];
  float dmin = 0.0f;
  float t;
  int i;
  int j;
  int k = 0;
  for (i = 0; i < nv; ++i) {
    d[i] = io_px[i] * mx + io_py[i] * my + io_pz[i] * mz;
    dmin = SHLIGHT_MINR(dmin, d[i]);
  }
  if (dmin >= 0.0f) {
    return nv;
  }
  for (i = 0; i < nv; ++i) {
    j = i + 1;
    if (j == nv) {
      j = 0;
    }
    if (d[i] >= 0.0f && k < SHLIGHT_CLIP_MAX) {
      tx[k] = io_px[i];
      ty[k] = io_py[i];
      tz[k] = io_pz[i];
      k = k + 1;
    }
    if (((d[i] >= 0.0f && d[j] < 0.0f) || (d[i] < 0.0f && d[j] >= 0.0f)) && k < SHLIGHT_CLIP_MAX) {
      t = d[i] / (d[i] - d[j]);
      tx[k] = io_px[i] + t * (io_px[j] - io_px[i]);
      ty[k] = io_py[i] + t * (io_py[j] - io_py[i]);
      tz[k] = io_pz[i] + t * (io_pz[j] - io_pz[i]);
      k = k + 1;
    }
  }
  for (i = 0; i < k; ++i) {
    io_px[i] = tx[i];
    io_py[i] = ty[i];
    io_pz[i] = tz[i];
  }
  return k;
}

/* (e + 1) M^e by the FAST method of the polygon (io_px, io_py, io_pz)[0..nv-1] (shading point
   at the origin; overwritten), clipped to u.n >= 0 first when clip_n != 0, then to u.r >= 0
   (n, r unit). The polygon is scaled by its largest coordinate first (any finite size works in
   float). nv outside [3, SHLIGHT_POLYGON_MAX], a non-finite vertex, e NaN or >= 1e30: 0;
   e < 0: 0. Three passes: the edges' arcs in theta (SHLIGHT_LANES edges at a time,
   branch-free, no sqrt: C's sqrtf may set errno, which stops vectorisation; the edge normal
   a x b stays unnormalised and |w| sin(Phi) = |n.r|), the non-empty half-arcs gathered, then
   their 4-node rules (SHLIGHT_LANES half-arcs at a time). */
SHLIGHT_INLINE float shli_fast_moment(float *io_px, float *io_py, float *io_pz, int nv, int clip_n,
                                      float nx, float ny, float nz, float rx, float ry, float rz,
                                      float e) {
  float qx[SHLIGHT_FAST_PAD];
  float qy[SHLIGHT_FAST_PAD];
  float qz[SHLIGHT_FAST_PAD];
  float eta[SHLIGHT_LANES];
  float etb[SHLIGHT_LANES];
  float ebe[SHLIGHT_LANES];
  float ew2[SHLIGHT_LANES];
  float esg[SHLIGHT_LANES];
  float edi[SHLIGHT_LANES];
  float hlo[2 * SHLIGHT_LANES];
  float hhi[2 * SHLIGHT_LANES];
  float hbe[2 * SHLIGHT_LANES];
  float hw2[2 * SHLIGHT_LANES];
  float hsg[2 * SHLIGHT_LANES];
  float val[SHLIGHT_LANES];
  float ox = 0.0f;
  float oy = 0.0f;
  float oz = 0.0f;
  float orient;
  float sum = 0.0f;
  float l = 0.0f;
  float ee = SHLIGHT_MAXR(e, 0.0f);
  float hm = 0.5f * (ee + 1.0f);
  float ax;
  float ay;
  float az;
  float bx;
  float by;
  float bz;
  float cx;
  float cy;
  float cz;
  float nn;
  float nr;
  float xa;
  float xb;
  float ta;
  float dt;
  float w2;
  float x;
  float g;
  int nc = nv;
  int nh;
  int i;
  int j;
  int i0;
  int h0;
  if (nv < 3 || nv > SHLIGHT_POLYGON_MAX || !(e < 1.0e30f)) {
    return 0.0f;
  }
  for (i = 0; i < nv; ++i) {
    l = SHLIGHT_MAXR(l, SHLIGHT_ABSF(io_px[i]) + SHLIGHT_ABSF(io_py[i]) + SHLIGHT_ABSF(io_pz[i]));
  }
  if (!(l > 0.0f) || !(l <= 3.4028234e38f)) {
    return 0.0f; /* zero, NaN or infinite vertices */
  }
  l = 1.0f / l;
  for (i = 0; i < nv; ++i) {
    io_px[i] = io_px[i] * l;
    io_py[i] = io_py[i] * l;
    io_pz[i] = io_pz[i] * l;
  }
  for (i = 0; i < nv; ++i) {
    j = i + 1;
    if (j == nv) {
      j = 0;
    }
    ox = ox + io_py[i] * io_pz[j] - io_pz[i] * io_py[j];
    oy = oy + io_pz[i] * io_px[j] - io_px[i] * io_pz[j];
    oz = oz + io_px[i] * io_py[j] - io_py[i] * io_px[j];
  }
  orient = ox * io_px[0] + oy * io_py[0] + oz * io_pz[0];
  if (clip_n != 0) {
    nc = shli_fast_clip(io_px, io_py, io_pz, nc, nx, ny, nz);
  }
  nc = shli_fast_clip(io_px, io_py, io_pz, nc, rx, ry, rz);
  if (nc < 3 || !(orient != 0.0f)) {
    return 0.0f;
  }
  for (i = 0; i < nc; ++i) {
    l = SHLIGHT_SQRTF(io_px[i] * io_px[i] + io_py[i] * io_py[i] + io_pz[i] * io_pz[i]);
    if (!(l > 0.0f)) {
      return 0.0f;
    }
    qx[i] = io_px[i] / l;
    qy[i] = io_py[i] / l;
    qz[i] = io_pz[i] / l;
  }
  /* closing vertex, then point edges (0 by construction) up to a whole block */
  for (i = nc; i < SHLIGHT_FAST_PAD; ++i) {
    qx[i] = qx[0];
    qy[i] = qy[0];
    qz[i] = qz[0];
  }
  for (i0 = 0; i0 < nc; i0 = i0 + SHLIGHT_LANES) {
    /* pass 1, SHLIGHT_LANES edges a -> b: the arc [ta, tb] in theta, the grading scale beta,
       w^2, sgn(w); an edge on the clip circle u.r = 0 (c = 0, integrand 1) gives its arc
       length directly, a point edge or r in the edge's plane (w = 0, integrand 0) nothing */
    for (j = 0; j < SHLIGHT_LANES; ++j) {
      ax = qx[i0 + j];
      ay = qy[i0 + j];
      az = qz[i0 + j];
      bx = qx[i0 + j + 1];
      by = qy[i0 + j + 1];
      bz = qz[i0 + j + 1];
      cx = ay * bz - az * by;
      cy = az * bx - ax * bz;
      cz = ax * by - ay * bx;
      nn = cx * cx + cy * cy + cz * cz;
      nr = cx * rx + cy * ry + cz * rz;
      xa = ax * rx + ay * ry + az * rz;
      xb = bx * rx + by * ry + bz * rz;
      w2 = nr * nr / SHLIGHT_MAXR(nn, 1.0e-36f);
      w2 = SHLIGHT_MINR(w2, 1.0f);
      ta = SHLIGHT_FATAN2(ax * (cy * rz - cz * ry) + ay * (cz * rx - cx * rz) +
                              az * (cx * ry - cy * rx),
                          SHLIGHT_ABSF(nr) * SHLIGHT_MAXR(xa, 0.0f));
      dt = SHLIGHT_FATAN2(SHLIGHT_ABSF(nr), ax * bx + ay * by + az * bz - xa * xb);
      x = SHLIGHT_FSQRT(w2 * (ee + 1.0f));
      g = 1.5f * x / (1.0f + 0.63662f * x);
      eta[j] = ta;
      etb[j] = SHLIGHT_MINR(ta + dt, 1.57079633f);
      ebe[j] = SHLIGHT_MAXR(g, 1.0e-20f);
      ew2[j] = w2;
      g = nr < 0.0f ? -1.0f : 1.0f;
      x = (SHLIGHT_ABSF(xa) < 1.0e-5f && SHLIGHT_ABSF(xb) < 1.0e-5f) ? 1.0f : 0.0f;
      x = (nn > 1.0e-36f && nr != 0.0f) ? x : -1.0f;
      esg[j] = x == 0.0f ? g : 0.0f;
      edi[j] = x > 0.0f ? g * dt : 0.0f;
    }
    /* pass 2: their non-empty half-arcs in |theta| (padding lanes are point edges: none) */
    nh = 0;
    for (j = 0; j < SHLIGHT_MINR(SHLIGHT_LANES, nc - i0); ++j) {
      sum = sum + edi[j];
      if (esg[j] != 0.0f && eta[j] < 0.0f) {
        hlo[nh] = SHLIGHT_MAXR(-etb[j], 0.0f);
        hhi[nh] = -eta[j];
        hbe[nh] = ebe[j];
        hw2[nh] = ew2[j];
        hsg[nh] = esg[j];
        nh = nh + 1;
      }
      if (esg[j] != 0.0f && etb[j] > 0.0f) {
        hlo[nh] = SHLIGHT_MAXR(eta[j], 0.0f);
        hhi[nh] = etb[j];
        hbe[nh] = ebe[j];
        hw2[nh] = ew2[j];
        hsg[nh] = esg[j];
        nh = nh + 1;
      }
    }
    for (j = nh; j < SHLIGHT_LANES * ((nh + SHLIGHT_LANES - 1) / SHLIGHT_LANES); ++j) {
      hlo[j] = 0.0f;
      hhi[j] = 0.0f;
      hbe[j] = 1.0f;
      hw2[j] = 0.0f;
      hsg[j] = 0.0f;
    }
    /* pass 3: the half-arcs' rules, SHLIGHT_LANES at a time */
    for (h0 = 0; h0 < nh; h0 = h0 + SHLIGHT_LANES) {
      for (j = 0; j < SHLIGHT_LANES; ++j) {
        val[j] = hsg[h0 + j] * shli_fast_half(hlo[h0 + j], hhi[h0 + j], hbe[h0 + j],
                                              1.0f - hw2[h0 + j], hw2[h0 + j], hm);
      }
      for (j = 0; j < SHLIGHT_LANES; ++j) {
        sum = sum + val[j];
      }
    }
  }
  if (orient < 0.0f) {
    sum = -sum;
  }
  return SHLIGHT_MAXR(sum, 0.0f);
}

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC pop_options
#endif

/* The integrand at the graded node s of a Stokes edge integral (see >>edge), times du/ds;
   t = c2 sin^2 u. kind 0: the moment's 1 - h, 1 - (t / (p + t))^q with p = w^2,
   q = (e + 1) / 2. kind 1: the Beckmann cap CDF 1 - exp(-p / t) with p = w^2 / alpha^2; for
   q > 0 (q = alpha^2) the function 1 - exp(-p / t) (1 + q p / t) instead (shli_half_image,
   kind 1). */
SHLIGHT_INLINE shli_real shli_stokes_node(shli_real s, shli_real beta, shli_real c2, shli_real p,
                                          shli_real q, int kind) {
  shli_real es = SHLIGHT_EXPR(s);
  shli_real u = 0.5 * beta * (es - 1.0 / es);
  shli_real su = SHLIGHT_SINR(u);
  shli_real t = c2 * su * su;
  shli_real g = 1.0;
  if (t > 0.0) {
    if (kind == 0) {
      g = -shli_expm1r(q * SHLIGHT_LOGR(t / (p + t)));
    } else {
      g = -shli_expm1r(-SHLIGHT_MINR(p / t, 700.0));
      if (q > 0.0) {
        g = 1.0 - SHLIGHT_EXPR(-SHLIGHT_MINR(p / t, 700.0)) * (1.0 + q * p / t);
      }
    }
  }
  return g * 0.5 * beta * (es + 1.0 / es);
}

/* r times the 5-node Gauss-Legendre sum of the kind's graded integrand on [m - r, m + r] in s */
SHLIGHT_INLINE shli_real shli_stokes_gl5(shli_real m, shli_real r, shli_real beta, shli_real c2,
                                         shli_real p, shli_real q, int kind) {
  shli_real sum = 0.56888888888888889 * shli_stokes_node(m, beta, c2, p, q, kind);
  sum = sum +
        0.47862867049936647 * (shli_stokes_node(m - 0.53846931010568309 * r, beta, c2, p, q, kind) +
                               shli_stokes_node(m + 0.53846931010568309 * r, beta, c2, p, q, kind));
  sum = sum +
        0.23692688505618909 * (shli_stokes_node(m - 0.90617984593866399 * r, beta, c2, p, q, kind) +
                               shli_stokes_node(m + 0.90617984593866399 * r, beta, c2, p, q, kind));
  return r * sum;
}

/* integral of the kind's integrand over |theta| in [lo, hi] inside [0, pi/2]: 5-node
   Gauss-Legendre in s, pi/2 - |theta| = beta sinh(s). lev > 0 (the adaptive rule of
   SHLIGHT_EDGE_EXACT at non-integer exponents): at level l = 1, 2, ..., lev the composite rule
   on 2^l equal panels, the one at s0 cut geometrically into l + 1 (an hp mesh: the integrand is
   analytic in s except for the branch point |cos theta|^(e+1) at theta = pi/2, s = s0, which
   the geometric cut resolves), until two successive levels differ by at most
   SHLIGHT_ADAPT_TOL (the error estimate: the accepted finer level is well inside it). */
SHLIGHT_INLINE shli_real shli_stokes_half(shli_real lo, shli_real hi, shli_real beta, shli_real c2,
                                          shli_real p, shli_real q, int kind, int lev) {
  shli_real z0 = (1.5707963267948966 - hi) / beta;
  shli_real z1 = (1.5707963267948966 - lo) / beta;
  shli_real s0 = SHLIGHT_LOGR(z0 + SHLIGHT_SQRTR(z0 * z0 + 1.0));
  shli_real s1 = SHLIGHT_LOGR(z1 + SHLIGHT_SQRTR(z1 * z1 + 1.0));
  shli_real r = 0.5 * (s1 - s0);
  shli_real cur;
  shli_real prev;
  shli_real h;
  int np = 1;
  int l;
  int k;
  if (!(r > 0.0)) {
    return 0.0;
  }
  cur = shli_stokes_gl5(0.5 * (s0 + s1), r, beta, c2, p, q, kind);
  for (l = 1; l <= lev; ++l) {
    prev = cur;
    np = 2 * np;
    h = (s1 - s0) / SHLIGHT_ITOR(np);
    cur = 0.0;
    for (k = 1; k < np; ++k) {
      cur = cur + shli_stokes_gl5(s0 + (SHLIGHT_ITOR(k) + 0.5) * h, 0.5 * h, beta, c2, p, q, kind);
    }
    /* the panel at s0 (theta = pi/2, where h has the branch point |cos|^(e+1) for non-integer
       e) cut geometrically toward s0: l panels, ratio 0.15, then the rest */
    for (k = 0; k < l; ++k) {
      cur = cur + shli_stokes_gl5(s0 + 0.575 * h, 0.425 * h, beta, c2, p, q, kind);
      h = 0.15 * h;
    }
    cur = cur + shli_stokes_gl5(s0 + 0.5 * h, 0.5 * h, beta, c2, p, q, kind);
    if (SHLIGHT_ABSR(cur - prev) <= SHLIGHT_ADAPT_TOL) {
      return cur;
    }
  }
  return cur;
}

/* The arc theta in [ta, tb] of an edge: the halves on either side of theta = 0, each by
   shli_stokes_half (the integrand is even in theta; lev as there). */
SHLIGHT_INLINE shli_real shli_stokes_arc(shli_real ta, shli_real tb, shli_real beta, shli_real c2,
                                         shli_real p, shli_real q, int kind, int lev) {
  if (ta < 0.0 && tb > 0.0) {
    return shli_stokes_half(0.0, -ta, beta, c2, p, q, kind, lev) +
           shli_stokes_half(0.0, tb, beta, c2, p, q, kind, lev);
  }
  if (tb <= 0.0) {
    return shli_stokes_half(-tb, -ta, beta, c2, p, q, kind, lev);
  }
  return shli_stokes_half(ta, tb, beta, c2, p, q, kind, lev);
}

/* One edge a -> b (unit vectors, the arc inside u.r >= 0) of the polygon moment about the unit
   axis r, exponent e: Stokes form (method QUADRATURE) returns sgn(w) times the arc integral
   of 1 - h; every other method returns w F(Phi, c, delta, e - 1) of Arvo's form (0 for e = 0). */
SHLIGHT_INLINE shli_real shli_edge_term(shli_real ax, shli_real ay, shli_real az, shli_real bx,
                                        shli_real by, shli_real bz, shli_real rx, shli_real ry,
                                        shli_real rz, shli_real e, int method) {
  shli_real nx = ay * bz - az * by;
  shli_real ny = az * bx - ax * bz;
  shli_real nz = ax * by - ay * bx;
  shli_real sp = SHLIGHT_SQRTR(nx * nx + ny * ny + nz * nz);
  shli_real cp = ax * bx + ay * by + az * bz;
  shli_real w;
  shli_real tx;
  shli_real ty;
  shli_real tz;
  shli_real xa;
  shli_real xb;
  shli_real ya;
  shli_real yb;
  shli_real c2;
  shli_real aw;
  shli_real ta;
  shli_real tb;
  shli_real beta;
  shli_real hm;
  shli_real g;
  shli_real pa;
  shli_real pb;
  int nf;
  int lev = 0;
  if (!(sp > 1.0e-30)) {
    return 0.0;
  }
  if (method == SHLIGHT_EDGE_STOKES_ADAPT) {
    lev = SHLIGHT_ADAPT_LEVELS;
  }
  xa = ax * rx + ay * ry + az * rz;
  xb = bx * rx + by * ry + bz * rz;
  if (SHLIGHT_ABSR(xa) < 1.0e-5 && SHLIGHT_ABSR(xb) < 1.0e-5) {
    /* an edge on the clip circle u.r = 0 (made by the clip): its normal is +-r, c = 0; the
       end points' rounding would otherwise decide where its arc lies */
    w = SHLIGHT_REAL(SHLIGHT_SIGN1(nx * rx + ny * ry + nz * rz));
    if (method != SHLIGHT_EDGE_QUADRATURE && lev == 0 &&
        (!(e >= 1.0) || SHLIGHT_FTOI(e + 0.5) - 2 * (SHLIGHT_FTOI(e + 0.5) / 2) == 0)) {
      return 0.0;
    }
    return w * shli_atan2r(sp, cp);
  }
  nx = nx / sp;
  ny = ny / sp;
  nz = nz / sp;
  w = nx * rx + ny * ry + nz * rz;
  tx = ny * rz - nz * ry;
  ty = nz * rx - nx * rz;
  tz = nx * ry - ny * rx;
  ya = ax * tx + ay * ty + az * tz;
  yb = bx * tx + by * ty + bz * tz;
  c2 = SHLIGHT_MAXR(1.0 - w * w, 0.0);
  aw = SHLIGHT_ABSR(w);
  if (method == SHLIGHT_EDGE_QUADRATURE || lev > 0) {
    if (!(aw > 0.0)) {
      return 0.0;
    }
    if (c2 < 1.0e-12) { /* h <= c^(e+1) <= 1e-6: the integrand is 1 over the whole arc */
      g = shli_atan2r(aw * sp, cp - xa * xb);
      if (w < 0.0) {
        g = -g;
      }
      return g;
    }
    /* theta_B from the arc length in theta, atan2(|w| sin Phi, cos Phi - x_A x_B): exact also
       for c -> 0, where x and y vanish along the whole edge */
    ta = shli_atan2r(ya, aw * SHLIGHT_MAXR(xa, 0.0));
    tb = SHLIGHT_MINR(ta + shli_atan2r(aw * sp, cp - xa * xb), 1.5707963267948966);
    hm = 0.5 * (e + 1.0);
    beta = 0.5 * shli_atan2r(aw * SHLIGHT_SQRTR(e + 1.0), 1.0);
    g = shli_stokes_arc(ta, tb, beta, c2, w * w, hm, 0, lev);
    if (w < 0.0) {
      g = -g;
    }
    return g;
  }
  if (!(e >= 1.0)) {
    return 0.0;
  }
  nf = SHLIGHT_FTOI(e + 0.5) - 1;
  if (c2 < 1.0e-12) { /* r along the edge normal: F = Phi (even order) or 0 (odd), to c^2 */
    if (nf - 2 * (nf / 2) == 1) {
      return 0.0;
    }
    return w * shli_atan2r(sp, cp);
  }
  pa = shli_atan2r(ya, SHLIGHT_MAXR(xa, 0.0));
  pb = pa + shli_atan2r(sp, cp);
  pb = SHLIGHT_MINR(pb, 1.5707963267948966);
  if (nf <= 2 || c2 < 1.0e-6 || method == SHLIGHT_EDGE_EXACT || method == SHLIGHT_EDGE_AUTO) {
    return w * shli_edge_exact_xy(xa, ya, xb, yb, c2, shli_atan2r(sp, cp), nf);
  }
  return w * shli_edge_fit(pa, pb, SHLIGHT_SQRTR(c2), nf, method);
}

/* The shared start of every polygon sum: the orientation of the (unclipped, planar) polygon
   as seen from the shading point, sign of (vector area) . (a vertex); the clip to u.r >= 0;
   the clipped vertices normalised in place. Returns +-(clipped vertex count), the sign the
   orientation's, or 0 when nothing usable is left (< 3 vertices, zero area, a vertex at the
   shading point). */
SHLIGHT_INLINE int shli_poly_clip_unit(shli_real *io_px, shli_real *io_py, shli_real *io_pz, int nv,
                                       shli_real rx, shli_real ry, shli_real rz) {
  shli_real ox = 0.0;
  shli_real oy = 0.0;
  shli_real oz = 0.0;
  shli_real orient;
  shli_real l;
  int nc;
  int i;
  int j;
  for (i = 0; i < nv; ++i) {
    j = i + 1;
    if (j == nv) {
      j = 0;
    }
    ox = ox + io_py[i] * io_pz[j] - io_pz[i] * io_py[j];
    oy = oy + io_pz[i] * io_px[j] - io_px[i] * io_pz[j];
    oz = oz + io_px[i] * io_py[j] - io_py[i] * io_px[j];
  }
  orient = ox * io_px[0] + oy * io_py[0] + oz * io_pz[0];
  nc = shli_poly_clip(io_px, io_py, io_pz, nv, rx, ry, rz);
  if (nc < 3 || !(orient != 0.0)) {
    return 0;
  }
  for (i = 0; i < nc; ++i) {
    l = SHLIGHT_SQRTR(io_px[i] * io_px[i] + io_py[i] * io_py[i] + io_pz[i] * io_pz[i]);
    if (!(l > 0.0)) {
      return 0;
    }
    io_px[i] = io_px[i] / l;
    io_py[i] = io_py[i] / l;
    io_pz[i] = io_pz[i] / l;
  }
  if (orient < 0.0) {
    return -nc;
  }
  return nc;
}

/* Moment (e+1)-normalised pieces of one polygon already in the arrays (shading point at the
   origin), clipped to u.r >= 0; returns M^e. e integer for the Arvo-form methods. */
SHLIGHT_INLINE shli_real shli_polygon_moment_r(shli_real *io_px, shli_real *io_py, shli_real *io_pz,
                                               int nv, shli_real rx, shli_real ry, shli_real rz,
                                               shli_real e, int method) {
  shli_real ax;
  shli_real ay;
  shli_real az;
  shli_real bx;
  shli_real by;
  shli_real bz;
  shli_real omega = 0.0;
  shli_real sum = 0.0;
  shli_real cx;
  shli_real cy;
  shli_real cz;
  int nc = shli_poly_clip_unit(io_px, io_py, io_pz, nv, rx, ry, rz);
  int sg = 1;
  int i;
  int j;
  if (nc == 0) {
    return 0.0;
  }
  if (nc < 0) {
    nc = -nc;
    sg = -1;
  }
  for (i = 0; i < nc; ++i) {
    j = i + 1;
    if (j == nc) {
      j = 0;
    }
    ax = io_px[i];
    ay = io_py[i];
    az = io_pz[i];
    bx = io_px[j];
    by = io_py[j];
    bz = io_pz[j];
    sum = sum + shli_edge_term(ax, ay, az, bx, by, bz, rx, ry, rz, e, method);
    if (method != SHLIGHT_EDGE_QUADRATURE && method != SHLIGHT_EDGE_STOKES_ADAPT && i > 0 &&
        j > 0) {
      /* fan triangle (p0, a, b): 2 atan2(p0 . (a x b), 1 + p0.a + a.b + b.p0) */
      cx = ay * bz - az * by;
      cy = az * bx - ax * bz;
      cz = ax * by - ay * bx;
      omega = omega + 2.0 * shli_atan2r(io_px[0] * cx + io_py[0] * cy + io_pz[0] * cz,
                                        1.0 + io_px[0] * ax + io_py[0] * ay + io_pz[0] * az +
                                            ax * bx + ay * by + az * bz + bx * io_px[0] +
                                            by * io_py[0] + bz * io_pz[0]);
    }
  }
  if (method != SHLIGHT_EDGE_QUADRATURE && method != SHLIGHT_EDGE_STOKES_ADAPT &&
      SHLIGHT_FTOI(e + 0.5) - 2 * (SHLIGHT_FTOI(e + 0.5) / 2) == 0) {
    sum = sum + omega;
  }
  if (sg < 0) {
    sum = -sum;
  }
  return SHLIGHT_MAXR(sum, 0.0) / (e + 1.0);
}

SHLIGHT_INLINE float shl_polygon_moment(const float (*v)[3], int nv, const float axis[3],
                                        float exponent, shl_edge_method method) {
  shli_real px[SHLIGHT_CLIP_MAX];
  shli_real py[SHLIGHT_CLIP_MAX];
  shli_real pz[SHLIGHT_CLIP_MAX];
  float fx[SHLIGHT_CLIP_MAX];
  float fy[SHLIGHT_CLIP_MAX];
  float fz[SHLIGHT_CLIP_MAX];
  shli_real rx = SHLIGHT_REAL(axis[0]);
  shli_real ry = SHLIGHT_REAL(axis[1]);
  shli_real rz = SHLIGHT_REAL(axis[2]);
  shli_real l = SHLIGHT_SQRTR(rx * rx + ry * ry + rz * rz);
  shli_real e = SHLIGHT_REAL(exponent);
  int i;
  int mth = method;
  if (mth < SHLIGHT_EDGE_EXACT || mth > SHLIGHT_EDGE_FAST) {
    mth = SHLIGHT_EDGE_AUTO; /* an unknown method id */
  }
#if SHLIGHT_POLYGON_ANY
  if (nv > SHLIGHT_POLYGON_MAX) {
    return shli_fan_moment(v, nv, axis, exponent, method);
  }
#endif
  if (nv > SHLIGHT_POLYGON_MAX) {
    return -1.0f;
  }
  if (nv < 3 || nv > SHLIGHT_POLYGON_MAX || !(l > 0.0) || !(l < SHLIGHT_REAL_MAX) ||
      !(e < 1.0e30)) {
    return 0.0f;
  }
  if (!(e > 0.0)) {
    e = 0.0;
  }
  rx = rx / l;
  ry = ry / l;
  rz = rz / l;
  for (i = 0; i < nv; ++i) {
    px[i] = SHLIGHT_REAL(v[i][0]);
    py[i] = SHLIGHT_REAL(v[i][1]);
    pz[i] = SHLIGHT_REAL(v[i][2]);
    if (!(SHLIGHT_ABSR(px[i]) + SHLIGHT_ABSR(py[i]) + SHLIGHT_ABSR(pz[i]) < SHLIGHT_REAL_MAX)) {
      return 0.0f;
    }
    fx[i] = v[i][0];
    fy[i] = v[i][1];
    fz[i] = v[i][2];
  }
#if SHLIGHT_EDGE_FAST_ON
  if (mth == SHLIGHT_EDGE_FAST) {
    return shli_fast_moment(fx, fy, fz, nv, 0, SHLIGHT_FLOAT(rx), SHLIGHT_FLOAT(ry),
                            SHLIGHT_FLOAT(rz), SHLIGHT_FLOAT(rx), SHLIGHT_FLOAT(ry),
                            SHLIGHT_FLOAT(rz), SHLIGHT_FLOAT(e)) /
           SHLIGHT_FLOAT(e + 1.0);
  }
#else
  if (mth == SHLIGHT_EDGE_FAST) {
    mth = SHLIGHT_EDGE_QUADRATURE;
  }
#endif
  if (mth == SHLIGHT_EDGE_AUTO) {
    mth = SHLIGHT_EDGE_STOKES_ADAPT;
    if (e <= 16.0 && e == SHLIGHT_ITOR(SHLIGHT_FTOI(e))) {
      mth = SHLIGHT_EDGE_EXACT;
    }
  }
  if (mth == SHLIGHT_EDGE_EXACT && (e > 65536.0 || e != SHLIGHT_ITOR(SHLIGHT_FTOI(e)))) {
    mth = SHLIGHT_EDGE_STOKES_ADAPT;
  }
  if (mth != SHLIGHT_EDGE_QUADRATURE && mth != SHLIGHT_EDGE_STOKES_ADAPT && e > 65536.0) {
    mth = SHLIGHT_EDGE_QUADRATURE;
  }
  if (mth != SHLIGHT_EDGE_QUADRATURE && mth != SHLIGHT_EDGE_STOKES_ADAPT) {
    e = SHLIGHT_ITOR(SHLIGHT_FTOI(e + 0.5));
  }
  return SHLIGHT_FLOAT(shli_polygon_moment_r(px, py, pz, nv, rx, ry, rz, e, mth));
}

/* (e+1)/(2 pi) M^e of the polygon (io_px, io_py, io_pz)[0..nv-1] clipped to the horizon
   u.n >= 0 and to u.r >= 0 (n, r unit); the arrays are overwritten. */
SHLIGHT_INLINE shli_real shli_phong_arrays(shli_real *io_px, shli_real *io_py, shli_real *io_pz,
                                           int nv, shli_real nx, shli_real ny, shli_real nz,
                                           shli_real rx, shli_real ry, shli_real rz,
                                           shli_real exponent, int method) {
  float fx[SHLIGHT_CLIP_MAX];
  float fy[SHLIGHT_CLIP_MAX];
  float fz[SHLIGHT_CLIP_MAX];
  shli_real e = exponent;
  int i;
  int nc;
  int mth = method;
  if (mth < SHLIGHT_EDGE_EXACT || mth > SHLIGHT_EDGE_FAST) {
    mth = SHLIGHT_EDGE_AUTO; /* an unknown method id */
  }
#if SHLIGHT_EDGE_FAST_ON
  if (mth == SHLIGHT_EDGE_FAST && nv >= 3 && nv <= SHLIGHT_POLYGON_MAX) {
    for (i = 0; i < nv; ++i) {
      fx[i] = SHLIGHT_FLOAT(io_px[i]);
      fy[i] = SHLIGHT_FLOAT(io_py[i]);
      fz[i] = SHLIGHT_FLOAT(io_pz[i]);
    }
    return 0.15915494309189534 *
           SHLIGHT_REAL(shli_fast_moment(fx, fy, fz, nv, 1, SHLIGHT_FLOAT(nx), SHLIGHT_FLOAT(ny),
                                         SHLIGHT_FLOAT(nz), SHLIGHT_FLOAT(rx), SHLIGHT_FLOAT(ry),
                                         SHLIGHT_FLOAT(rz), SHLIGHT_FLOAT(e)));
  }
#else
  if (mth == SHLIGHT_EDGE_FAST) {
    mth = SHLIGHT_EDGE_QUADRATURE;
  }
#endif
  if (nv < 3 || nv > SHLIGHT_POLYGON_MAX || !(e < 1.0e30)) {
    return 0.0;
  }
  if (!(e > 0.0)) {
    e = 0.0;
  }
  for (i = 0; i < nv; ++i) {
    if (!(SHLIGHT_ABSR(io_px[i]) + SHLIGHT_ABSR(io_py[i]) + SHLIGHT_ABSR(io_pz[i]) <
          SHLIGHT_REAL_MAX)) {
      return 0.0;
    }
  }
  nc = shli_poly_clip(io_px, io_py, io_pz, nv, nx, ny, nz);
  if (nc < 3) {
    return 0.0;
  }
  if (mth == SHLIGHT_EDGE_AUTO) {
    mth = SHLIGHT_EDGE_STOKES_ADAPT;
    if (e <= 16.0 && e == SHLIGHT_ITOR(SHLIGHT_FTOI(e))) {
      mth = SHLIGHT_EDGE_EXACT;
    }
  }
  if (mth == SHLIGHT_EDGE_EXACT && (e > 65536.0 || e != SHLIGHT_ITOR(SHLIGHT_FTOI(e)))) {
    mth = SHLIGHT_EDGE_STOKES_ADAPT;
  }
  if (mth != SHLIGHT_EDGE_QUADRATURE && mth != SHLIGHT_EDGE_STOKES_ADAPT && e > 65536.0) {
    mth = SHLIGHT_EDGE_QUADRATURE;
  }
  if (mth != SHLIGHT_EDGE_QUADRATURE && mth != SHLIGHT_EDGE_STOKES_ADAPT) {
    e = SHLIGHT_ITOR(SHLIGHT_FTOI(e + 0.5));
  }
  return (e + 1.0) * 0.15915494309189534 *
         shli_polygon_moment_r(io_px, io_py, io_pz, nc, rx, ry, rz, e, mth);
}

/* the same for a polygon given as vertices */
SHLIGHT_INLINE shli_real shli_polygon_phong_r(const float (*v)[3], int nv, shli_real nx,
                                              shli_real ny, shli_real nz, shli_real rx,
                                              shli_real ry, shli_real rz, shli_real exponent,
                                              int method) {
  shli_real px[SHLIGHT_CLIP_MAX];
  shli_real py[SHLIGHT_CLIP_MAX];
  shli_real pz[SHLIGHT_CLIP_MAX];
  int i;
  if (nv < 3 || nv > SHLIGHT_POLYGON_MAX) {
    return 0.0;
  }
  for (i = 0; i < nv; ++i) {
    px[i] = SHLIGHT_REAL(v[i][0]);
    py[i] = SHLIGHT_REAL(v[i][1]);
    pz[i] = SHLIGHT_REAL(v[i][2]);
  }
  return shli_phong_arrays(px, py, pz, nv, nx, ny, nz, rx, ry, rz, exponent, method);
}

SHLIGHT_INLINE float shl_polygon_phong(const float (*v)[3], int nv, const float nrm[3],
                                       const float view[3], float exponent,
                                       shl_edge_method method) {
  float fx[SHLIGHT_CLIP_MAX];
  float fy[SHLIGHT_CLIP_MAX];
  float fz[SHLIGHT_CLIP_MAX];
  shli_real nx = SHLIGHT_REAL(nrm[0]);
  shli_real ny = SHLIGHT_REAL(nrm[1]);
  shli_real nz = SHLIGHT_REAL(nrm[2]);
  shli_real dv =
      nx * SHLIGHT_REAL(view[0]) + ny * SHLIGHT_REAL(view[1]) + nz * SHLIGHT_REAL(view[2]);
  shli_real rx = 2.0 * dv * nx - SHLIGHT_REAL(view[0]);
  shli_real ry = 2.0 * dv * ny - SHLIGHT_REAL(view[1]);
  shli_real rz = 2.0 * dv * nz - SHLIGHT_REAL(view[2]);
  shli_real l = SHLIGHT_SQRTR(rx * rx + ry * ry + rz * rz);
  int i;
#if SHLIGHT_POLYGON_ANY
  if (nv > SHLIGHT_POLYGON_MAX) {
    return shli_fan_phong(v, nv, nrm, view, exponent, method);
  }
#endif
  if (nv > SHLIGHT_POLYGON_MAX) {
    return -1.0f;
  }
  if (!(dv > 0.0) || !(l > 0.0) || !(l < SHLIGHT_REAL_MAX)) {
    return 0.0f;
  }
#if SHLIGHT_EDGE_FAST_ON
  if (method == SHLIGHT_EDGE_FAST && nv >= 3 && nv <= SHLIGHT_POLYGON_MAX) {
    for (i = 0; i < nv; ++i) {
      fx[i] = v[i][0];
      fy[i] = v[i][1];
      fz[i] = v[i][2];
    }
    return 0.159154943f * shli_fast_moment(fx, fy, fz, nv, 1, nrm[0], nrm[1], nrm[2],
                                           SHLIGHT_FLOAT(rx / l), SHLIGHT_FLOAT(ry / l),
                                           SHLIGHT_FLOAT(rz / l), exponent);
  }
#endif
  return SHLIGHT_FLOAT(shli_polygon_phong_r(v, nv, nx, ny, nz, rx / l, ry / l, rz / l,
                                            SHLIGHT_REAL(exponent), method));
}

/* log(1 + x) for x > -1 in shli_real from the shims alone (GLSL has no log1p): 2 atanh(z),
   z = x / (2 + x), series to z^15 for |x| <= 0.25 (relative error < 1e-16), log beyond. */
SHLIGHT_INLINE shli_real shli_log1pr(shli_real x) {
  shli_real z;
  shli_real z2;
  shli_real p;
  if (!(SHLIGHT_ABSR(x) <= 0.25)) {
    return SHLIGHT_LOGR(1.0 + x);
  }
  z = x / (2.0 + x);
  z2 = z * z;
  p = 0.066666666666666667;
  p = 0.076923076923076923 + z2 * p;
  p = 0.090909090909090909 + z2 * p;
  p = 0.11111111111111111 + z2 * p;
  p = 0.14285714285714286 + z2 * p;
  p = 0.2 + z2 * p;
  p = 0.33333333333333333 + z2 * p;
  return 2.0 * (z + z * (z2 * p));
}

SHLIGHT_INLINE float shl_lobe_to_sg(float exponent) {
  shli_real e = SHLIGHT_REAL(exponent);
  if (!(e > 0.0)) {
    return 0.0f;
  }
  if (!(e < 1.0e30)) {
    return exponent;
  }
  return SHLIGHT_FLOAT(0.69314718055994531 / -shli_expm1r(-0.69314718055994531 / e));
}

SHLIGHT_INLINE float shl_sg_to_lobe(float lambda) {
  shli_real l = SHLIGHT_REAL(lambda);
  if (!(l > 0.69314718055994531)) {
    return 0.0f;
  }
  if (!(l < 1.0e30)) {
    return lambda;
  }
  return SHLIGHT_FLOAT(-0.69314718055994531 / shli_log1pr(-0.69314718055994531 / l));
}

SHLIGHT_INLINE float shl_lobe_product(const float r1[3], float exponent1, const float r2[3],
                                      float exponent2, float *out_axis, float *out_exponent) {
  shli_real l1 = SHLIGHT_REAL(shl_lobe_to_sg(exponent1));
  shli_real l2 = SHLIGHT_REAL(shl_lobe_to_sg(exponent2));
  shli_real a[8];
  shli_real b[8];
  shli_real px;
  shli_real py;
  shli_real pz;
  shli_real lp;
  shli_real c1;
  shli_real c2;
  shli_real mu = 0.0;
  out_axis[0] = r1[0];
  out_axis[1] = r1[1];
  out_axis[2] = r1[2];
  out_exponent[0] = 0.0f;
  if (!(exponent1 >= 0.0f) || !(exponent2 >= 0.0f)) {
    return 0.0f;
  }
  /* the axes normalised in shli_real: a float-normalised axis (|r|^2 - 1 ~ 5e-8) raised to
     n ~ 1e8 would move mu by e^2.4 */
  shli_cap_frame(SHLIGHT_REAL(r1[0]), SHLIGHT_REAL(r1[1]), SHLIGHT_REAL(r1[2]), 1.0, a);
  shli_cap_frame(SHLIGHT_REAL(r2[0]), SHLIGHT_REAL(r2[1]), SHLIGHT_REAL(r2[2]), 1.0, b);
  px = l1 * a[0] + l2 * b[0];
  py = l1 * a[1] + l2 * b[1];
  pz = l1 * a[2] + l2 * b[2];
  lp = SHLIGHT_SQRTR(px * px + py * py + pz * pz);
  if (!(lp > 1.0e-30) || !(lp < 1.0e30)) {
    return 0.0f;
  }
  px = px / lp;
  py = py / lp;
  pz = pz / lp;
  out_axis[0] = SHLIGHT_FLOAT(px);
  out_axis[1] = SHLIGHT_FLOAT(py);
  out_axis[2] = SHLIGHT_FLOAT(pz);
  out_exponent[0] = shl_sg_to_lobe(SHLIGHT_FLOAT(lp));
  c1 = px * a[0] + py * a[1] + pz * a[2];
  c2 = px * b[0] + py * b[1] + pz * b[2];
  /* cosines of unit vectors: <= 1, so mu <= 1 for any exponents (rounding can give 1 + 1e-16,
     which n ~ 1e30 would blow up) */
  c1 = SHLIGHT_MINR(c1, 1.0);
  c2 = SHLIGHT_MINR(c2, 1.0);
  if (c1 > 0.0 && c2 > 0.0) {
    mu = SHLIGHT_POWR(c1, SHLIGHT_REAL(exponent1)) * SHLIGHT_POWR(c2, SHLIGHT_REAL(exponent2));
  }
  return SHLIGHT_FLOAT(mu);
}

SHLIGHT_INLINE float shl_polygon_phong_double_axis(const float (*v)[3], int nv, const float nrm[3],
                                                   const float view[3], float exponent,
                                                   shl_edge_method method) {
  shli_real nx = SHLIGHT_REAL(nrm[0]);
  shli_real ny = SHLIGHT_REAL(nrm[1]);
  shli_real nz = SHLIGHT_REAL(nrm[2]);
  shli_real dv =
      nx * SHLIGHT_REAL(view[0]) + ny * SHLIGHT_REAL(view[1]) + nz * SHLIGHT_REAL(view[2]);
  shli_real rx = 2.0 * dv * nx - SHLIGHT_REAL(view[0]);
  shli_real ry = 2.0 * dv * ny - SHLIGHT_REAL(view[1]);
  shli_real rz = 2.0 * dv * nz - SHLIGHT_REAL(view[2]);
  shli_real l = SHLIGHT_SQRTR(rx * rx + ry * ry + rz * rz);
  shli_real e = SHLIGHT_REAL(exponent);
  shli_real l1;
  shli_real l2 = SHLIGHT_REAL(shl_lobe_to_sg(1.0f));
  shli_real lp;
  shli_real np;
  shli_real c1;
  shli_real c2;
  shli_real px;
  shli_real py;
  shli_real pz;
#if SHLIGHT_POLYGON_ANY
  if (nv > SHLIGHT_POLYGON_MAX) {
    return shli_fan_phong2(v, nv, nrm, view, exponent, method);
  }
#endif
  if (nv > SHLIGHT_POLYGON_MAX) {
    return -1.0f;
  }
  if (!(dv > 0.0) || !(l > 0.0) || !(l < SHLIGHT_REAL_MAX) || !(e >= 0.0) || !(e < 1.0e30)) {
    return 0.0f;
  }
  rx = rx / l;
  ry = ry / l;
  rz = rz / l;
  if (e > 1.0e6) {
    /* the product's limit (relative error ~ 1 / e): the cosine held at the mirror direction;
       the SG road loses the axis to float rounding of lambda above ~1e12 */
    c2 = SHLIGHT_MAXR(rx * nx + ry * ny + rz * nz, 0.0);
    return SHLIGHT_FLOAT(c2 * shli_polygon_phong_r(v, nv, nx, ny, nz, rx, ry, rz, e, method));
  }
  l1 = SHLIGHT_REAL(shl_lobe_to_sg(exponent));
  px = l1 * rx + l2 * nx;
  py = l1 * ry + l2 * ny;
  pz = l1 * rz + l2 * nz;
  lp = SHLIGHT_SQRTR(px * px + py * py + pz * pz);
  px = px / lp;
  py = py / lp;
  pz = pz / lp;
  np = SHLIGHT_REAL(shl_sg_to_lobe(SHLIGHT_FLOAT(lp)));
  c1 = px * rx + py * ry + pz * rz;
  c2 = px * nx + py * ny + pz * nz;
  if (!(c1 > 0.0) || !(c2 > 0.0)) {
    return 0.0f;
  }
  /* mu (e+1)/(2 pi) M^np(rp) = mu (e+1)/(np+1) * [(np+1)/(2 pi) M^np(rp)] */
  return SHLIGHT_FLOAT(SHLIGHT_POWR(c1, e) * c2 * (e + 1.0) / (np + 1.0) *
                       shli_polygon_phong_r(v, nv, nx, ny, nz, px, py, pz, np, method));
}

/* the ellipse light's two octagons (see shl_ellipse_phong) for unit n and r */
SHLIGHT_INLINE shli_real shli_ellipse_phong_r(shli_real cx, shli_real cy, shli_real cz,
                                              shli_real ux, shli_real uy, shli_real uz,
                                              shli_real vx, shli_real vy, shli_real vz,
                                              shli_real nx, shli_real ny, shli_real nz,
                                              shli_real rx, shli_real ry, shli_real rz,
                                              shli_real exponent, int method) {
  shli_real px[SHLIGHT_CLIP_MAX];
  shli_real py[SHLIGHT_CLIP_MAX];
  shli_real pz[SHLIGHT_CLIP_MAX];
  shli_real cs;
  shli_real sn;
  shli_real sum = 0.0;
  int j;
  int h;
  for (h = 0; h < 2; ++h) {
    for (j = 0; j < 8; ++j) {
      cs = 1.0539686339182901 * SHLIGHT_COSR(0.39269908169872415 * SHLIGHT_ITOR(2 * j + h));
      sn = 1.0539686339182901 * SHLIGHT_SINR(0.39269908169872415 * SHLIGHT_ITOR(2 * j + h));
      px[j] = cx + cs * ux + sn * vx;
      py[j] = cy + cs * uy + sn * vy;
      pz[j] = cz + cs * uz + sn * vz;
    }
    sum = sum + shli_phong_arrays(px, py, pz, 8, nx, ny, nz, rx, ry, rz, exponent, method);
  }
  return 0.5 * sum;
}

SHLIGHT_INLINE float shl_ellipse_phong(const float c[3], const float a1[3], const float a2[3],
                                       const float nrm[3], const float view[3], float exponent,
                                       shl_edge_method method) {
  shli_real nx = SHLIGHT_REAL(nrm[0]);
  shli_real ny = SHLIGHT_REAL(nrm[1]);
  shli_real nz = SHLIGHT_REAL(nrm[2]);
  shli_real dv =
      nx * SHLIGHT_REAL(view[0]) + ny * SHLIGHT_REAL(view[1]) + nz * SHLIGHT_REAL(view[2]);
  shli_real rx = 2.0 * dv * nx - SHLIGHT_REAL(view[0]);
  shli_real ry = 2.0 * dv * ny - SHLIGHT_REAL(view[1]);
  shli_real rz = 2.0 * dv * nz - SHLIGHT_REAL(view[2]);
  shli_real l = SHLIGHT_SQRTR(rx * rx + ry * ry + rz * rz);
  if (!(dv > 0.0) || !(l > 0.0) || !(l < SHLIGHT_REAL_MAX)) {
    return 0.0f;
  }
  return SHLIGHT_FLOAT(shli_ellipse_phong_r(
      SHLIGHT_REAL(c[0]), SHLIGHT_REAL(c[1]), SHLIGHT_REAL(c[2]), SHLIGHT_REAL(a1[0]),
      SHLIGHT_REAL(a1[1]), SHLIGHT_REAL(a1[2]), SHLIGHT_REAL(a2[0]), SHLIGHT_REAL(a2[1]),
      SHLIGHT_REAL(a2[2]), nx, ny, nz, rx / l, ry / l, rz / l, SHLIGHT_REAL(exponent), method));
}

SHLIGHT_INLINE float shl_sphere_phong(const float c[3], float r, const float nrm[3],
                                      const float view[3], float exponent, shl_edge_method method) {
  shli_real nx = SHLIGHT_REAL(nrm[0]);
  shli_real ny = SHLIGHT_REAL(nrm[1]);
  shli_real nz = SHLIGHT_REAL(nrm[2]);
  shli_real dv =
      nx * SHLIGHT_REAL(view[0]) + ny * SHLIGHT_REAL(view[1]) + nz * SHLIGHT_REAL(view[2]);
  shli_real rx = 2.0 * dv * nx - SHLIGHT_REAL(view[0]);
  shli_real ry = 2.0 * dv * ny - SHLIGHT_REAL(view[1]);
  shli_real rz = 2.0 * dv * nz - SHLIGHT_REAL(view[2]);
  shli_real l = SHLIGHT_SQRTR(rx * rx + ry * ry + rz * rz);
  shli_real cx = SHLIGHT_REAL(c[0]);
  shli_real cy = SHLIGHT_REAL(c[1]);
  shli_real cz = SHLIGHT_REAL(c[2]);
  shli_real d = SHLIGHT_SQRTR(cx * cx + cy * cy + cz * cz);
  shli_real rr = SHLIGHT_REAL(r);
  shli_real rho;
  shli_real sg;
  shli_real a;
  shli_real b;
  shli_real ux;
  shli_real uy;
  shli_real uz;
  if (!(dv > 0.0) || !(l > 0.0) || !(l < SHLIGHT_REAL_MAX) || !(rr > 0.0) ||
      !(rr < SHLIGHT_REAL_MAX) || !(d < SHLIGHT_REAL_MAX)) {
    return 0.0f;
  }
  rx = rx / l;
  ry = ry / l;
  rz = rz / l;
  if (!(d > rr)) {
    cx = rx;
    cy = ry;
    cz = rz;
    d = 1.0;
    rho = 1.0e4;
  } else {
    rho = rr * d / SHLIGHT_SQRTR((d - rr) * (d + rr));
  }
  ux = cx / d;
  uy = cy / d;
  uz = cz / d;
  /* Duff et al. 2017 orthonormal basis about (ux, uy, uz) */
  sg = SHLIGHT_REAL(SHLIGHT_SIGN1(uz));
  a = -1.0 / (sg + uz);
  b = ux * uy * a;
  return SHLIGHT_FLOAT(shli_ellipse_phong_r(
      cx, cy, cz, rho * (1.0 + sg * ux * ux * a), rho * sg * b, -rho * sg * ux, rho * b,
      rho * (sg + uy * uy * a), -rho * uy, nx, ny, nz, rx, ry, rz, SHLIGHT_REAL(exponent), method));
}

/* The shared start of the half-vector NDF integrals (shl_polygon_ggx_ndf,
   shl_polygon_beckmann_ndf): checks nv >= 3 (C: any count; GLSL: at most SHLIGHT_POLYGON_MAX, above
   it -1), the axis (non-zero, finite) and alpha (not NaN); loads the vertices into io_px, io_py,
   io_pz (a NaN or infinite one: 0) and clips them to u.axis >= 0 and normalises them
   (shli_poly_clip_unit). Writes out_par: [0..2] the unit axis, [3] the polygon's orientation (+1 or
   -1: the sign of the edge sum), [4] alpha clamped to [1e-4, 1]. Returns the clipped vertex count,
   or 0 (the caller returns 0; out_par is then not all written). */
SHLIGHT_INLINE int shli_poly_load_clip(const float (*v)[3], int nv, const float axis[3],
                                       float alpha, shli_real *io_px, shli_real *io_py,
                                       shli_real *io_pz, shli_real *out_par) {
  shli_real rx = SHLIGHT_REAL(axis[0]);
  shli_real ry = SHLIGHT_REAL(axis[1]);
  shli_real rz = SHLIGHT_REAL(axis[2]);
  shli_real l = SHLIGHT_SQRTR(rx * rx + ry * ry + rz * rz);
  shli_real al = SHLIGHT_REAL(alpha);
  int i;
  int nc;
  out_par[3] = 1.0;
  if (nv < 3 || nv > SHLIGHT_POLYGON_MAX || !(l > 0.0) || !(l < SHLIGHT_REAL_MAX) || !(al == al)) {
    return 0;
  }
  rx = rx / l;
  ry = ry / l;
  rz = rz / l;
  out_par[0] = rx;
  out_par[1] = ry;
  out_par[2] = rz;
  out_par[4] = SHLIGHT_MINR(SHLIGHT_MAXR(al, 1.0e-4), 1.0);
  for (i = 0; i < nv; ++i) {
    io_px[i] = SHLIGHT_REAL(v[i][0]);
    io_py[i] = SHLIGHT_REAL(v[i][1]);
    io_pz[i] = SHLIGHT_REAL(v[i][2]);
    if (!(SHLIGHT_ABSR(io_px[i]) + SHLIGHT_ABSR(io_py[i]) + SHLIGHT_ABSR(io_pz[i]) <
          SHLIGHT_REAL_MAX)) {
      return 0;
    }
  }
  nc = shli_poly_clip_unit(io_px, io_py, io_pz, nv, rx, ry, rz);
  if (nc < 0) {
    nc = -nc;
    out_par[3] = -1.0;
  }
  return nc;
}

SHLIGHT_INLINE float shl_polygon_ggx_ndf(const float (*v)[3], int nv, const float axis[3],
                                         float alpha) {
  shli_real px[SHLIGHT_CLIP_MAX];
  shli_real py[SHLIGHT_CLIP_MAX];
  shli_real pz[SHLIGHT_CLIP_MAX];
  shli_real par[5];
  shli_real rx;
  shli_real ry;
  shli_real rz;
  shli_real a2;
  shli_real sum = 0.0;
  shli_real nx;
  shli_real ny;
  shli_real nz;
  shli_real sp;
  shli_real cp;
  shli_real w;
  shli_real q;
  shli_real t;
  int i;
  int j;
  int nc = shli_poly_load_clip(v, nv, axis, alpha, px, py, pz, par);
#if SHLIGHT_POLYGON_ANY
  if (nv > SHLIGHT_POLYGON_MAX) {
    return shli_fan_ggx_ndf(v, nv, axis, alpha);
  }
#endif
  if (nv > SHLIGHT_POLYGON_MAX) {
    return -1.0f;
  }
  if (nc == 0) {
    return 0.0f;
  }
  rx = par[0];
  ry = par[1];
  rz = par[2];
  a2 = par[4] * par[4];
  for (i = 0; i < nc; ++i) {
    j = i + 1;
    if (j == nc) {
      j = 0;
    }
    nx = py[i] * pz[j] - pz[i] * py[j];
    ny = pz[i] * px[j] - px[i] * pz[j];
    nz = px[i] * py[j] - py[i] * px[j];
    sp = SHLIGHT_SQRTR(nx * nx + ny * ny + nz * nz);
    cp = px[i] * px[j] + py[i] * py[j] + pz[i] * pz[j];
    if (sp > 1.0e-30) {
      w = (nx * rx + ny * ry + nz * rz) / sp;
      w = SHLIGHT_MINR(SHLIGHT_MAXR(w, -1.0), 1.0);
      q = SHLIGHT_SQRTR(w * w + a2 * (1.0 - w * w));
      t = SHLIGHT_ABSR(w) / q *
          shli_atan2r(q * sp, cp - (1.0 - a2) * (px[i] * rx + py[i] * ry + pz[i] * rz) *
                                       (px[j] * rx + py[j] * ry + pz[j] * rz));
      if (w < 0.0) {
        t = -t;
      }
      sum = sum + t;
    }
  }
  return SHLIGHT_FLOAT(SHLIGHT_MAXR(par[3] * sum, 0.0) * 0.15915494309189534);
}

/* GGX polygon lights (shl_polygon_ggx). The light's integral
     L = integral over P (clipped to n.l > 0) of f(v, l) (n.l) dl = int D(h) G2(l, v) / (4 n.v) dl
   becomes, with dl = 4 (h.v) dh (h = (l + v) / |l + v|),
     L = integral over H(P) of D(h) (h.n) w(h) dh,   w(h) = G2(l(h), v) (h.v) / ((n.v) (h.n)).
   w is smooth and D (h.n) is the peaked part, so w is split into its first-order Taylor
   expansion about the point h* of H(P) closest to n and a remainder:
     L = w* A + g.(M1 - h* A) + integral over P of k(l) (w - w* - g.(h - h*)) dl,
   A = int_H D (h.n) dh, M1 = int_H D (h.n) h dh (both exact up to a 1D quadrature, below),
   k = D (h.n) / (4 h.v) (so that k dl = D (h.n) dh), g the gradient of w at h* (central
   differences), and the remainder by cubature over P: a fan from the direction of the vertex
   centroid, triangles wider than 53 deg split 1 -> 4 at their edge midpoints, a 7-point
   degree-5 rule on each piece (the remainder is second order where D is narrow and smooth where
   D is wide).
   A and M1 by Stokes along the boundary of H(P), the image of P's great arcs l(t) = cos t a +
   sin t b, t in [0, Phi], under l -> l + v (homogeneous: no normalisation needed), with
   Q = l + v, Q_z = Q.n, |Q_xy|^2 = |Q|^2 - Q_z^2, c = 1 - alpha^2:
     A      = (1 / 2 pi) sum over edges of int (Q x l').n / (|Q_xy|^2 + alpha^2 Q_z^2) dt
              (the NDF closed form of shl_polygon_ggx_ndf, whose edges are great arcs, holds
              only for v = 0: the image of a great arc is a conic here);
     M1.g   = -sum over edges of int [g_n Psi(t_h) (Q x l').n / |Q_xy|^2
                                      - (1/2) F(t_h) g_t.(Q x l') / |Q|^2] dt,
              t_h = Q_z / |Q|, I(t) = int_0^t s^2 D(s) ds = (alpha^2 / pi) t^3 J(c t^2),
              Psi = I(t) - I(1), F = 2 I(t) / t^2 (the azimuthal 1-form for the normal part,
              the divergence identity div(F(u.n) a_t) = -(a.u) (t F' + 2 F) for a tangential g_t).
   Each edge integrand peaks (width ~ alpha) where l passes the mirror direction; it is taken with
   the graded rule t = t0 + wd sinh(s), t0 the peak of |Q_xy|^2 + alpha^2 Q_z^2 (one Newton step
   from the mirror direction's projection on the edge's great circle, taken only when it is
   shorter than pi: the denominator has period 2 pi, so a longer step means its quadratic model
   fails there, e.g. f2 ~ 1e-5 d0 on small lights far from the lobe gave steps of ~1e4 rad,
   where t0 + wd sinh(s) keeps only a few bits of the arc in float: the GLSL twin was then off
   by up to 8 %), wd = its half width, 5-node Gauss-Legendre on each side of t0. */

/* Beckmann's Smith Lambda at the direction cosine c (0 < c <= 1), roughness alpha:
   (erf(a) - 1) / 2 + exp(-a^2) / (2 a sqrt(pi)), a = c / (alpha sqrt(1 - c^2)), with erfc by
   Abramowitz-Stegun 7.1.26 (absolute error 1.5e-7, so Lambda is within 1e-7): no erf needed
   in GLSL. a is floored at 1e-30 only (Lambda ~ 0.28 / a: G2 ~ 3.5 a falls like n.v, so
   G2 / (n.v) stays finite and tends to its limit at views grazing to 1e-16; a floor at 1e-6
   held G2 while 1 / (n.v) grew). */
SHLIGHT_INLINE shli_real shli_beckmann_lambda(shli_real c, shli_real alpha) {
  shli_real s2 = 1.0 - c * c;
  shli_real a;
  shli_real t;
  shli_real p;
  if (!(s2 > 0.0)) {
    return 0.0;
  }
  a = SHLIGHT_MAXR(c / (alpha * SHLIGHT_SQRTR(s2)), 1.0e-30);
  t = 1.0 / (1.0 + 0.3275911 * a);
  p = t *
      (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429))));
  return 0.5 * SHLIGHT_EXPR(-a * a) * (0.56418958354775629 / a - p);
}

/* Beckmann NDF (ndf = 1 of the helpers below): the scaled integral (pi / alpha^2) I(t) with
   I(t) = int_0^t s^2 D_B(s) ds = exp(1 / alpha^2) erfc(1 / (alpha t)) / (2 sqrt(pi) alpha)
   (u = 1 / s: I = exp(1 / alpha^2) / (pi alpha^2) int_{1/t}^inf exp(-u^2 / alpha^2) du), written
   with erfcx(x) = exp(x^2) erfc(x) = 2 / (1 + 2 x) p((x - 2) / (x + 2)) (Weideman 1994, L = 2)
   at x = 1 / (alpha t) >= 1: (pi / alpha^2) I(t) = sqrt(pi) t E p(z) / (alpha^2 (alpha t + 2)),
   E = exp(-tan^2 t / alpha^2), z = (1 - 2 alpha t) / (1 + 2 alpha t) in [-1/3, 1). p: the
   degree-14 Chebyshev fit of (1 + 2x) erfcx(x) / 2 on z in [-1/3, 1] (mpmath), relative error
   9e-12 for every x >= 1. et = E, at = alpha t. */
SHLIGHT_INLINE shli_real shli_beck_i(shli_real t, shli_real et, shli_real at, shli_real a2) {
  shli_real z = (1.0 - 2.0 * at) / (1.0 + 2.0 * at);
  shli_real p;
  p = 1.653978468591848e-05;
  p = -0.00010318949224549979 + z * p;
  p = 0.00017624229959215334 + z * p;
  p = 7.319183804664685e-05 + z * p;
  p = -0.00024355655667775413 + z * p;
  p = -0.0007155524025357445 + z * p;
  p = 0.0006349526378748344 + z * p;
  p = 0.004359972791898658 + z * p;
  p = -0.004016780184587048 + z * p;
  p = -0.027109944299521422 + z * p;
  p = 0.08202562922023758 + z * p;
  p = -0.08301519969842093 + z * p;
  p = -0.046381913173553224 + z * p;
  p = 0.6384891907791029 + z * p;
  return 1.7724538509055160 * t * et * p / (a2 * (at + 2.0));
}

/* J(y) = sum over k >= 1 of k / (2k + 1) y^(k-1) = (1 / (1 - y) - atanh(sqrt y) / sqrt y) / (2 y),
   y in [0, 1), omy = 1 - y formed by the caller without cancellation; series below 0.1. */
SHLIGHT_INLINE shli_real shli_ggx_j(shli_real y, shli_real omy) {
  shli_real x;
  shli_real p;
  if (y < 0.1) { /* 13 terms: the rest < 1e-13 */
    p = 0.48148148148148145;
    p = 0.48 + y * p;
    p = 0.4782608695652174 + y * p;
    p = 0.47619047619047616 + y * p;
    p = 0.47368421052631576 + y * p;
    p = 0.47058823529411764 + y * p;
    p = 0.4666666666666667 + y * p;
    p = 0.46153846153846156 + y * p;
    p = 0.45454545454545453 + y * p;
    p = 0.4444444444444444 + y * p;
    p = 0.42857142857142855 + y * p;
    p = 0.4 + y * p;
    p = 0.3333333333333333 + y * p;
    return p;
  }
  x = SHLIGHT_SQRTR(y);
  return (1.0 / omy - 0.5 * SHLIGHT_LOGR((1.0 + x) * (1.0 + x) / omy) / x) / (2.0 * y);
}

/* w(l) = G2(l, v) (h.v) / ((n.v)(h.n)), h = (l + v) / |l + v|, l unit; 0 below the horizon.
   lamv = Lambda(n.v); ndf 0: GGX's Lambda, 1: Beckmann's (shli_beckmann_lambda, al = alpha). */
SHLIGHT_INLINE shli_real shli_ggx_w(shli_real lx, shli_real ly, shli_real lz, shli_real vx,
                                    shli_real vy, shli_real vz, shli_real nx, shli_real ny,
                                    shli_real nz, shli_real a2, shli_real lamv, shli_real al,
                                    int ndf) {
  shli_real nl = lx * nx + ly * ny + lz * nz;
  shli_real hx = lx + vx;
  shli_real hy = ly + vy;
  shli_real hz = lz + vz;
  shli_real nh = hx * nx + hy * ny + hz * nz;
  shli_real hv = hx * vx + hy * vy + hz * vz;
  shli_real nv = vx * nx + vy * ny + vz * nz;
  shli_real laml;
  if (!(nl > 0.0) || !(nh > 0.0)) {
    return 0.0;
  }
  if (ndf == 0) {
    laml = 0.5 * (SHLIGHT_SQRTR(nl * nl + a2 * (1.0 - nl * nl)) / nl - 1.0);
  } else {
    laml = shli_beckmann_lambda(nl, al);
  }
  return hv / ((1.0 + lamv + laml) * nv * nh);
}

/* One side [lo, hi] (in s) of an edge's graded rule: adds the A and M1.g integrands (see
   above) at t = t0 + wd sinh(s), 5-node Gauss-Legendre, to io_am[0] and io_am[1]. ndf 0: GGX,
   1: Beckmann (the cap CDF 1 - exp(-u), u = tan^2 / alpha^2 = |Q_xy|^2 / (alpha^2 Q_z^2), in
   the A form; shli_beck_i in the M1 form; al = alpha). */
SHLIGHT_INLINE void shli_ggx_side(shli_real lo, shli_real hi, shli_real t0, shli_real wd,
                                  shli_real ax, shli_real ay, shli_real az, shli_real bx,
                                  shli_real by, shli_real bz, shli_real vx, shli_real vy,
                                  shli_real vz, shli_real nx, shli_real ny, shli_real nz,
                                  shli_real a2, shli_real gx, shli_real gy, shli_real gz,
                                  shli_real i1, shli_real al, int ndf, shli_real *io_am) {
  shli_real xs[5];
  shli_real ws[5];
  shli_real hl = 0.5 * (hi - lo);
  shli_real gn = gx * nx + gy * ny + gz * nz;
  shli_real tx = gx - gn * nx;
  shli_real ty = gy - gn * ny;
  shli_real tz = gz - gn * nz;
  shli_real s;
  shli_real es;
  shli_real jw;
  shli_real ct;
  shli_real st;
  shli_real dx;
  shli_real dy;
  shli_real dz;
  shli_real qx;
  shli_real qy;
  shli_real qz;
  shli_real cx;
  shli_real cy;
  shli_real cz;
  shli_real qn;
  shli_real qq;
  shli_real qxy;
  shli_real dn;
  shli_real cn;
  shli_real th;
  shli_real it;
  shli_real m;
  shli_real u;
  shli_real e;
  int j;
  xs[0] = -0.90617984593866399;
  xs[1] = -0.53846931010568309;
  xs[2] = 0.0;
  xs[3] = 0.53846931010568309;
  xs[4] = 0.90617984593866399;
  ws[0] = 0.23692688505618909;
  ws[1] = 0.47862867049936647;
  ws[2] = 0.56888888888888889;
  ws[3] = 0.47862867049936647;
  ws[4] = 0.23692688505618909;
  if (!(hi > lo)) {
    return;
  }
  for (j = 0; j < 5; ++j) {
    s = lo + hl * (xs[j] + 1.0);
    es = SHLIGHT_EXPR(s);
    jw = ws[j] * hl * wd * 0.5 * (es + 1.0 / es);
    s = t0 + wd * 0.5 * (es - 1.0 / es);
    ct = SHLIGHT_COSR(s);
    st = SHLIGHT_SINR(s);
    /* l = ct a + st b, l' = -st a + ct b, Q = l + v */
    dx = ct * bx - st * ax;
    dy = ct * by - st * ay;
    dz = ct * bz - st * az;
    qx = ct * ax + st * bx + vx;
    qy = ct * ay + st * by + vy;
    qz = ct * az + st * bz + vz;
    cx = qy * dz - qz * dy;
    cy = qz * dx - qx * dz;
    cz = qx * dy - qy * dx;
    cn = cx * nx + cy * ny + cz * nz;
    qn = qx * nx + qy * ny + qz * nz;
    qq = qx * qx + qy * qy + qz * qz;
    qxy = SHLIGHT_MAXR(qq - qn * qn, 0.0);
    dn = qxy + a2 * qn * qn;
    if (ndf != 0 && !(qn > 0.0)) {
      dn = 0.0;
    }
    if (dn > 0.0 && qq > 0.0) {
      th = qn / SHLIGHT_SQRTR(qq);
      if (ndf == 0) {
        io_am[0] = io_am[0] + jw * cn / dn;
        /* I(t_h) pi / alpha^2 = t^3 J(c t^2), 1 - c t^2 = dn / qq */
        it = th * th * th * shli_ggx_j((1.0 - a2) * th * th, dn / qq);
      } else {
        /* (1 - exp(-u)) / |Q_xy|^2, u = |Q_xy|^2 / (alpha^2 Q_z^2); a series below u = 0.1
           (truncation u^7 / 8! < 3e-12) */
        u = qxy / (a2 * qn * qn);
        e = SHLIGHT_EXPR(-u);
        if (u < 0.1) {
          m = 1.0 / 5040.0;
          m = 1.0 / 720.0 - u * m;
          m = 1.0 / 120.0 - u * m;
          m = 1.0 / 24.0 - u * m;
          m = 1.0 / 6.0 - u * m;
          m = 0.5 - u * m;
          m = (1.0 - u * m) / (a2 * qn * qn);
        } else {
          m = (1.0 - e) / qxy;
        }
        io_am[0] = io_am[0] + jw * cn * m;
        it = shli_beck_i(th, e, al * th, a2);
      }
      m = -(tx * cx + ty * cy + tz * cz) / qq * it / (th * th);
      if (qxy > 1.0e-30 * qq) {
        m = m + gn * (it - i1) * cn / qxy;
      }
      io_am[1] = io_am[1] + jw * m;
    }
  }
}

/* The remainder's integral, k(l) (w(l) - w* - g.(h - h*)) with k = D (h.n) / (4 h.v), over the
   spherical triangle of the directions (a, b, c) (any lengths, a non-negative combination
   spans it) by the 7-point degree-5 rule of Dunavant on the flat triangle and the Jacobian
   det(a, b, c) / |p|^3 of the radial projection. */
SHLIGHT_INLINE shli_real shli_ggx_tri(shli_real ax, shli_real ay, shli_real az, shli_real bx,
                                      shli_real by, shli_real bz, shli_real cx, shli_real cy,
                                      shli_real cz, shli_real vx, shli_real vy, shli_real vz,
                                      shli_real nx, shli_real ny, shli_real nz, shli_real a2,
                                      shli_real lamv, shli_real ws, shli_real hx, shli_real hy,
                                      shli_real hz, shli_real gx, shli_real gy, shli_real gz,
                                      shli_real al, int ndf) {
  shli_real tr[7];
  shli_real ts[7];
  shli_real tw[7];
  shli_real c = 1.0 - a2;
  shli_real res = 0.0;
  shli_real det;
  shli_real qx;
  shli_real qy;
  shli_real qz;
  shli_real q;
  shli_real dx;
  shli_real dy;
  shli_real dz;
  shli_real f1;
  shli_real f2;
  shli_real d;
  shli_real d0;
  shli_real w;
  int k;
  tr[0] = 0.33333333333333333;
  ts[0] = 0.33333333333333333;
  tw[0] = 0.1125;
  tr[1] = 0.059715871789769820;
  ts[1] = 0.47014206410511509;
  tr[2] = 0.47014206410511509;
  ts[2] = 0.059715871789769820;
  tr[3] = 0.47014206410511509;
  ts[3] = 0.47014206410511509;
  tr[4] = 0.79742698535308732;
  ts[4] = 0.10128650732345634;
  tr[5] = 0.10128650732345634;
  ts[5] = 0.79742698535308732;
  tr[6] = 0.10128650732345634;
  ts[6] = 0.10128650732345634;
  tw[1] = 0.066197076394253090;
  tw[2] = 0.066197076394253090;
  tw[3] = 0.066197076394253090;
  tw[4] = 0.062969590272413576;
  tw[5] = 0.062969590272413576;
  tw[6] = 0.062969590272413576;
  bx = bx - ax;
  by = by - ay;
  bz = bz - az;
  cx = cx - ax;
  cy = cy - ay;
  cz = cz - az;
  det = ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx);
  for (k = 0; k < 7; ++k) {
    qx = ax + tr[k] * bx + ts[k] * cx;
    qy = ay + tr[k] * by + ts[k] * cy;
    qz = az + tr[k] * bz + ts[k] * cz;
    q = SHLIGHT_SQRTR(qx * qx + qy * qy + qz * qz);
    qx = qx / q;
    qy = qy / q;
    qz = qz / q;
    dx = qx + vx;
    dy = qy + vy;
    dz = qz + vz;
    f2 = dx * dx + dy * dy + dz * dz;
    d = dx * nx + dy * ny + dz * nz;
    d0 = (f2 - c * d * d) / f2; /* 1 - c (h.n)^2 */
    f1 = SHLIGHT_SQRTR(f2);
    w = shli_ggx_w(qx, qy, qz, vx, vy, vz, nx, ny, nz, a2, lamv, al, ndf) - ws -
        (gx * (dx / f1 - hx) + gy * (dy / f1 - hy) + gz * (dz / f1 - hz));
    if (ndf == 0) {
      /* D = alpha^2 / (pi (1 - c (h.n)^2)^2), (h.n) / (h.v) = d / (l + v).v */
      res = res + tw[k] * det / (q * q * q) * a2 * d /
                      (12.566370614359173 * d0 * d0 * (dx * vx + dy * vy + dz * vz)) * w;
    } else if (d > 0.0) {
      /* D_B (h.n) / (4 h.v) = exp(-(f2 - d^2) / (alpha^2 d^2)) f2^2 / (4 pi alpha^2 d^3 (l + v).v),
         d = (l + v).n, f2 = |l + v|^2 */
      res = res + tw[k] * det / (q * q * q) * SHLIGHT_EXPR(-(f2 - d * d) / (a2 * d * d)) * f2 * f2 /
                      (12.566370614359173 * a2 * d * d * d * (dx * vx + dy * vy + dz * vz)) * w;
    }
  }
  return res;
}

/* The body of shl_polygon_ggx (ndf 0) and shl_polygon_beckmann (ndf 1): the same
   clipping, Taylor point, Stokes edges and remainder fan, the NDF and Lambda switched inside
   the helpers (derivation above). */
SHLIGHT_INLINE float shli_mf_taylor(const float (*v)[3], int nv, const float nrm[3],
                                    const float view[3], float alpha, int ndf) {
  shli_real px[SHLIGHT_CLIP_MAX];
  shli_real py[SHLIGHT_CLIP_MAX];
  shli_real pz[SHLIGHT_CLIP_MAX];
  shli_real am[2];
  shli_real tr[7];
  shli_real ts[7];
  shli_real tw[7];
  shli_real nx = SHLIGHT_REAL(nrm[0]);
  shli_real ny = SHLIGHT_REAL(nrm[1]);
  shli_real nz = SHLIGHT_REAL(nrm[2]);
  shli_real vx = SHLIGHT_REAL(view[0]);
  shli_real vy = SHLIGHT_REAL(view[1]);
  shli_real vz = SHLIGHT_REAL(view[2]);
  shli_real ln = SHLIGHT_SQRTR(nx * nx + ny * ny + nz * nz);
  shli_real lv = SHLIGHT_SQRTR(vx * vx + vy * vy + vz * vz);
  shli_real al = SHLIGHT_REAL(alpha);
  shli_real a2;
  shli_real c;
  shli_real nv2;
  shli_real lamv;
  shli_real rx;
  shli_real ry;
  shli_real rz;
  shli_real sx;
  shli_real sy;
  shli_real sz;
  shli_real hx;
  shli_real hy;
  shli_real hz;
  shli_real ws;
  shli_real gx = 0.0;
  shli_real gy = 0.0;
  shli_real gz = 0.0;
  shli_real t1x;
  shli_real t1y;
  shli_real t1z;
  shli_real t2x;
  shli_real t2y;
  shli_real t2z;
  shli_real ex;
  shli_real ey;
  shli_real ez;
  shli_real bx;
  shli_real by;
  shli_real bz;
  shli_real se;
  shli_real phi;
  shli_real t0;
  shli_real ct;
  shli_real st;
  shli_real qx;
  shli_real qy;
  shli_real qz;
  shli_real dx;
  shli_real dy;
  shli_real dz;
  shli_real f1;
  shli_real f2;
  shli_real d0;
  shli_real wd;
  shli_real sa;
  shli_real sb;
  shli_real best = -2.0;
  shli_real d;
  shli_real q;
  shli_real sg;
  shli_real i1;
  shli_real aa;
  shli_real res = 0.0;
  shli_real w;
  shli_real sp;
  int inside = 1;
  int np;
  int nc;
  int i;
  int j;
  int k;
  if (nv < 3 || nv > SHLIGHT_POLYGON_MAX || !(ln > 0.0) || !(ln < SHLIGHT_REAL_MAX) ||
      !(lv > 0.0) || !(lv < SHLIGHT_REAL_MAX) || !(al == al)) {
    return 0.0f;
  }
  nx = nx / ln;
  ny = ny / ln;
  nz = nz / ln;
  vx = vx / lv;
  vy = vy / lv;
  vz = vz / lv;
  nv2 = nx * vx + ny * vy + nz * vz;
  if (!(nv2 > 0.0)) {
    return 0.0f;
  }
  al = SHLIGHT_MINR(SHLIGHT_MAXR(al, 1.0e-4), 1.0);
  a2 = al * al;
  c = 1.0 - a2;
  if (ndf == 0) {
    lamv = 0.5 * (SHLIGHT_SQRTR(nv2 * nv2 + a2 * (1.0 - nv2 * nv2)) / nv2 - 1.0);
  } else {
    lamv = shli_beckmann_lambda(nv2, al);
  }
  for (i = 0; i < nv; ++i) {
    px[i] = SHLIGHT_REAL(v[i][0]);
    py[i] = SHLIGHT_REAL(v[i][1]);
    pz[i] = SHLIGHT_REAL(v[i][2]);
    if (!(SHLIGHT_ABSR(px[i]) + SHLIGHT_ABSR(py[i]) + SHLIGHT_ABSR(pz[i]) < SHLIGHT_REAL_MAX)) {
      return 0.0f;
    }
  }
  nc = shli_poly_clip_unit(px, py, pz, nv, nx, ny, nz);
  if (nc == 0) {
    return 0.0f;
  }
  if (nc < 0) { /* reverse to the positive orientation */
    nc = -nc;
    for (i = 0; i < nc / 2; ++i) {
      j = nc - 1 - i;
      q = px[i];
      px[i] = px[j];
      px[j] = q;
      q = py[i];
      py[i] = py[j];
      py[j] = q;
      q = pz[i];
      pz[i] = pz[j];
      pz[j] = q;
    }
  }
  /* the mirror direction r; the point l* of the polygon closest to it */
  rx = 2.0 * nv2 * nx - vx;
  ry = 2.0 * nv2 * ny - vy;
  rz = 2.0 * nv2 * nz - vz;
  sx = rx;
  sy = ry;
  sz = rz;
  for (i = 0; i < nc; ++i) {
    j = i + 1;
    if (j == nc) {
      j = 0;
    }
    ex = py[i] * pz[j] - pz[i] * py[j];
    ey = pz[i] * px[j] - px[i] * pz[j];
    ez = px[i] * py[j] - py[i] * px[j];
    if (ex * rx + ey * ry + ez * rz < 0.0) {
      inside = 0;
    }
  }
  if (inside == 0) {
    for (i = 0; i < nc; ++i) {
      j = i + 1;
      if (j == nc) {
        j = 0;
      }
      d = px[i] * rx + py[i] * ry + pz[i] * rz;
      if (d > best) {
        best = d;
        sx = px[i];
        sy = py[i];
        sz = pz[i];
      }
      ex = py[i] * pz[j] - pz[i] * py[j];
      ey = pz[i] * px[j] - px[i] * pz[j];
      ez = px[i] * py[j] - py[i] * px[j];
      se = ex * ex + ey * ey + ez * ez;
      if (se > 1.0e-30) {
        d = (ex * rx + ey * ry + ez * rz) / se;
        qx = rx - d * ex;
        qy = ry - d * ey;
        qz = rz - d * ez;
        q = SHLIGHT_SQRTR(qx * qx + qy * qy + qz * qz);
        if (q > 1.0e-15) {
          qx = qx / q;
          qy = qy / q;
          qz = qz / q;
          /* inside the arc: (a x p).e >= 0 and (p x b).e >= 0 */
          d = qx * rx + qy * ry + qz * rz;
          if (d > best &&
              ex * (py[i] * qz - pz[i] * qy) + ey * (pz[i] * qx - px[i] * qz) +
                      ez * (px[i] * qy - py[i] * qx) >=
                  0.0 &&
              ex * (qy * pz[j] - qz * py[j]) + ey * (qz * px[j] - qx * pz[j]) +
                      ez * (qx * py[j] - qy * px[j]) >=
                  0.0) {
            best = d;
            sx = qx;
            sy = qy;
            sz = qz;
          }
        }
      }
    }
  }
  /* h* and w*, and the gradient g of w(h) at h* by central differences in the frame of Duff et
     al. (2017) about h* */
  hx = sx + vx;
  hy = sy + vy;
  hz = sz + vz;
  q = SHLIGHT_SQRTR(hx * hx + hy * hy + hz * hz);
  hx = hx / q;
  hy = hy / q;
  hz = hz / q;
  ws = shli_ggx_w(sx, sy, sz, vx, vy, vz, nx, ny, nz, a2, lamv, al, ndf);
  sg = SHLIGHT_REAL(SHLIGHT_SIGN1(hz));
  q = -1.0 / (sg + hz);
  d = hx * hy * q;
  t1x = 1.0 + sg * hx * hx * q;
  t1y = sg * d;
  t1z = -sg * hx;
  t2x = d;
  t2y = sg + hy * hy * q;
  t2z = -hy;
  for (k = 0; k < 4; ++k) {
    d = 1.0e-3;
    if (k == 1 || k == 3) {
      d = -1.0e-3;
    }
    if (k < 2) {
      ex = t1x;
      ey = t1y;
      ez = t1z;
    } else {
      ex = t2x;
      ey = t2y;
      ez = t2z;
    }
    qx = hx + d * ex;
    qy = hy + d * ey;
    qz = hz + d * ez;
    q = qx * qx + qy * qy + qz * qz;
    f1 = 2.0 * (qx * vx + qy * vy + qz * vz) / q;
    w = shli_ggx_w(f1 * qx - vx, f1 * qy - vy, f1 * qz - vz, vx, vy, vz, nx, ny, nz, a2, lamv, al,
                   ndf) /
        (2.0 * d);
    gx = gx + w * ex;
    gy = gy + w * ey;
    gz = gz + w * ez;
  }
  /* A and M1.g along the edges */
  if (ndf == 0) {
    i1 = shli_ggx_j(c, a2);
  } else {
    i1 = shli_beck_i(1.0, 1.0, al, a2);
  }
  am[0] = 0.0;
  am[1] = 0.0;
  for (i = 0; i < nc; ++i) {
    j = i + 1;
    if (j == nc) {
      j = 0;
    }
    ex = py[i] * pz[j] - pz[i] * py[j];
    ey = pz[i] * px[j] - px[i] * pz[j];
    ez = px[i] * py[j] - py[i] * px[j];
    se = SHLIGHT_SQRTR(ex * ex + ey * ey + ez * ez);
    if (se > 1.0e-30) {
      phi = shli_atan2r(se, px[i] * px[j] + py[i] * py[j] + pz[i] * pz[j]);
      ex = ex / se;
      ey = ey / se;
      ez = ez / se;
      bx = ey * pz[i] - ez * py[i];
      by = ez * px[i] - ex * pz[i];
      bz = ex * py[i] - ey * px[i];
      t0 = shli_atan2r(rx * bx + ry * by + rz * bz, rx * px[i] + ry * py[i] + rz * pz[i]);
      for (k = 0; k < 2; ++k) {
        ct = SHLIGHT_COSR(t0);
        st = SHLIGHT_SINR(t0);
        qx = ct * px[i] + st * bx + vx;
        qy = ct * py[i] + st * by + vy;
        qz = ct * pz[i] + st * bz + vz;
        dx = ct * bx - st * px[i];
        dy = ct * by - st * py[i];
        dz = ct * bz - st * pz[i];
        /* Dn = Q.M.Q, M = 1 - c n n; Dn'/2 = Q.M.Q', Dn''/2 = Q'.M.Q' - (Q - v).M.Q */
        d = qx * nx + qy * ny + qz * nz;
        q = dx * nx + dy * ny + dz * nz;
        d0 = qx * qx + qy * qy + qz * qz - c * d * d;
        f1 = qx * dx + qy * dy + qz * dz - c * d * q;
        f2 = dx * dx + dy * dy + dz * dz - c * q * q - d0 +
             (vx * qx + vy * qy + vz * qz - c * (vx * nx + vy * ny + vz * nz) * d);
        if (k == 0 && SHLIGHT_ABSR(f1) < 3.1415926535897932 * f2) { /* |step| < pi, above */
          t0 = t0 - f1 / f2;
        }
      }
      wd = 10.0;
      if (f2 > 1.0e-2 * d0) {
        wd = SHLIGHT_MINR(SHLIGHT_SQRTR(d0 / f2), 10.0);
      }
      wd = SHLIGHT_MAXR(wd, 1.0e-7);
      sa = -t0 / wd;
      sb = (phi - t0) / wd;
      sa = SHLIGHT_REAL(SHLIGHT_SIGN1(sa)) *
           SHLIGHT_LOGR(SHLIGHT_ABSR(sa) + SHLIGHT_SQRTR(sa * sa + 1.0));
      sb = SHLIGHT_REAL(SHLIGHT_SIGN1(sb)) *
           SHLIGHT_LOGR(SHLIGHT_ABSR(sb) + SHLIGHT_SQRTR(sb * sb + 1.0));
      /* both sides of the peak when it lies inside the arc */
      for (k = 0; k < 2; ++k) {
        f1 = sa;
        f2 = sb;
        if (sa < 0.0 && sb > 0.0) {
          f1 = 0.0;
          if (k == 0) {
            f1 = sa;
            f2 = 0.0;
          }
        } else if (k == 1) {
          f2 = sa;
        }
        shli_ggx_side(f1, f2, t0, wd, px[i], py[i], pz[i], bx, by, bz, vx, vy, vz, nx, ny, nz, a2,
                      gx, gy, gz, i1, al, ndf, am);
      }
    }
  }
  aa = am[0] * 0.15915494309189534;
  /* the remainder: a fan from the vertex centroid's direction, a triangle with a side over 53
     deg (cos < 0.6; Beckmann: 26 deg, cos < 0.9, halving its worst error / albedo on
     bench_beckmann's sampler from 0.11 to 0.049) split 1 -> 4 at its edge midpoints, the 7-point
     degree-5 rule (Dunavant) on each piece */
  sx = 0.0;
  sy = 0.0;
  sz = 0.0;
  for (i = 0; i < nc; ++i) {
    sx = sx + px[i];
    sy = sy + py[i];
    sz = sz + pz[i];
  }
  q = SHLIGHT_SQRTR(sx * sx + sy * sy + sz * sz);
  if (!(q > 1.0e-6)) { /* no usable centroid direction: the fan from the first vertex */
    sx = px[0];
    sy = py[0];
    sz = pz[0];
    q = 1.0;
  }
  sx = sx / q;
  sy = sy / q;
  sz = sz / q;
  sp = 0.6;
  if (ndf != 0) {
    sp = 0.9;
  }
  for (i = 0; i < nc; ++i) {
    j = i + 1;
    if (j == nc) {
      j = 0;
    }
    tr[0] = sx + px[i];
    ts[0] = sy + py[i];
    tw[0] = sz + pz[i];
    tr[1] = px[i] + px[j];
    ts[1] = py[i] + py[j];
    tw[1] = pz[i] + pz[j];
    tr[2] = px[j] + sx;
    ts[2] = py[j] + sy;
    tw[2] = pz[j] + sz;
    np = 1;
    if (sx * px[i] + sy * py[i] + sz * pz[i] < sp || sx * px[j] + sy * py[j] + sz * pz[j] < sp ||
        px[i] * px[j] + py[i] * py[j] + pz[i] * pz[j] < sp) {
      np = 4;
    }
    for (k = 0; k < np; ++k) {
      /* (c, m0, m2), (m0, a, m1), (m2, m1, b), (m0, m1, m2): c centroid, a b the edge */
      tr[3] = tr[0];
      ts[3] = ts[0];
      tw[3] = tw[0];
      tr[4] = tr[1];
      ts[4] = ts[1];
      tw[4] = tw[1];
      tr[5] = tr[2];
      ts[5] = ts[2];
      tw[5] = tw[2];
      if (k == 0) {
        tr[3] = sx;
        ts[3] = sy;
        tw[3] = sz;
        tr[4] = tr[0];
        ts[4] = ts[0];
        tw[4] = tw[0];
      } else if (k == 1) {
        tr[3] = tr[0];
        ts[3] = ts[0];
        tw[3] = tw[0];
        tr[4] = px[i];
        ts[4] = py[i];
        tw[4] = pz[i];
        tr[5] = tr[1];
        ts[5] = ts[1];
        tw[5] = tw[1];
      } else if (k == 2) {
        tr[3] = tr[2];
        ts[3] = ts[2];
        tw[3] = tw[2];
        tr[5] = px[j];
        ts[5] = py[j];
        tw[5] = pz[j];
      }
      if (np == 1) {
        tr[4] = px[i];
        ts[4] = py[i];
        tw[4] = pz[i];
        tr[5] = px[j];
        ts[5] = py[j];
        tw[5] = pz[j];
      }
      res = res + shli_ggx_tri(tr[3], ts[3], tw[3], tr[4], ts[4], tw[4], tr[5], ts[5], tw[5], vx,
                               vy, vz, nx, ny, nz, a2, lamv, ws, hx, hy, hz, gx, gy, gz, al, ndf);
    }
  }
  q = aa * ws - am[1] * a2 * 0.31830988618379067 - (gx * hx + gy * hy + gz * hz) * aa + res;
  return SHLIGHT_FLOAT(SHLIGHT_MAXR(q, 0.0));
}

SHLIGHT_INLINE float shl_polygon_ggx(const float (*v)[3], int nv, const float nrm[3],
                                     const float view[3], float alpha) {
#if SHLIGHT_POLYGON_ANY
  if (nv > SHLIGHT_POLYGON_MAX) {
    return shli_fan_ggx(v, nv, nrm, view, alpha);
  }
#endif
  if (nv > SHLIGHT_POLYGON_MAX) {
    return -1.0f;
  }
  return shli_mf_taylor(v, nv, nrm, view, alpha, 0);
}

SHLIGHT_INLINE float shl_polygon_beckmann(const float (*v)[3], int nv, const float nrm[3],
                                          const float view[3], float alpha) {
#if SHLIGHT_POLYGON_ANY
  if (nv > SHLIGHT_POLYGON_MAX) {
    return shli_fan_beckmann_taylor(v, nv, nrm, view, alpha);
  }
#endif
  if (nv > SHLIGHT_POLYGON_MAX) {
    return -1.0f;
  }
  return shli_mf_taylor(v, nv, nrm, view, alpha, 1);
}

/* ---- microfacet polygon lights in half-vector space ([AREA] sec. 8; docs/area-lights.md). With h
   = (l + v) / |l + v| and dl = 4 (h.l) dh, the reflected radiance of a unit-radiance polygon
   becomes an integral over the image H(P) of the light in half-vector space: integral over P of
   D(h) G2 / (4 (n.v)) dl = integral over H(P) of D(h) (h.n) Y(h) dh, Y = G2 (h.v) / ((n.v) (h.n)).
   D (h.n) over H(P) is a moment (Blinn-Phong: (e+2)/(2 pi) M^(e+1)) or the Stokes form of a radial
   CDF (Beckmann), both sums over H(P)'s edges; Y is held at one representative direction. H maps
   great arcs to spherical conics (the cone through the circle {l + v}), not great arcs: each light
   edge is cut into k sub-edges whose mapped end points are joined by great arcs (the split of
   [AREA] sec. 8.1). */

/* One edge a -> b (unit, the arc inside u.r >= 0) of the Stokes form of the Beckmann NDF about
   the unit axis r, roughness alpha: sgn(w) times the integral over the arc's theta of the cap
   CDF (the polygon's integral of D_B (u.r) is the edge sum / (2 pi)); the edge set-up of
   shli_edge_term's QUADRATURE branch, grading beta = atan(|w| sqrt(2) / alpha) / 2 (the
   Blinn-Phong grading at e + 1 = 2 / alpha^2, the exponent of equal width). sa: as
   shli_stokes_node's q, kind 1 (0: the CDF). */
SHLIGHT_INLINE shli_real shli_beckmann_edge(shli_real ax, shli_real ay, shli_real az, shli_real bx,
                                            shli_real by, shli_real bz, shli_real rx, shli_real ry,
                                            shli_real rz, shli_real alpha, shli_real sa) {
  shli_real nx = ay * bz - az * by;
  shli_real ny = az * bx - ax * bz;
  shli_real nz = ax * by - ay * bx;
  shli_real sp = SHLIGHT_SQRTR(nx * nx + ny * ny + nz * nz);
  shli_real cp = ax * bx + ay * by + az * bz;
  shli_real w;
  shli_real tx;
  shli_real ty;
  shli_real tz;
  shli_real xa;
  shli_real xb;
  shli_real ya;
  shli_real c2;
  shli_real aw;
  shli_real ta;
  shli_real tb;
  shli_real beta;
  shli_real b;
  shli_real g;
  if (!(sp > 1.0e-30)) {
    return 0.0;
  }
  xa = ax * rx + ay * ry + az * rz;
  xb = bx * rx + by * ry + bz * rz;
  if (SHLIGHT_ABSR(xa) < 1.0e-5 && SHLIGHT_ABSR(xb) < 1.0e-5) {
    /* an edge on the clip circle u.r = 0: the CDF is 1 along it */
    w = SHLIGHT_REAL(SHLIGHT_SIGN1(nx * rx + ny * ry + nz * rz));
    return w * shli_atan2r(sp, cp);
  }
  nx = nx / sp;
  ny = ny / sp;
  nz = nz / sp;
  w = nx * rx + ny * ry + nz * rz;
  tx = ny * rz - nz * ry;
  ty = nz * rx - nx * rz;
  tz = nx * ry - ny * rx;
  ya = ax * tx + ay * ty + az * tz;
  c2 = SHLIGHT_MAXR(1.0 - w * w, 0.0);
  aw = SHLIGHT_ABSR(w);
  if (!(aw > 0.0)) {
    return 0.0;
  }
  if (c2 < 1.0e-12) { /* the arc hugs the equator of r: the CDF is 1 along it */
    g = shli_atan2r(aw * sp, cp - xa * xb);
  } else {
    ta = shli_atan2r(ya, aw * SHLIGHT_MAXR(xa, 0.0));
    tb = SHLIGHT_MINR(ta + shli_atan2r(aw * sp, cp - xa * xb), 1.5707963267948966);
    b = w * w / (alpha * alpha);
    beta = 0.5 * shli_atan2r(aw * 1.4142135623730951, alpha);
    g = shli_stokes_arc(ta, tb, beta, c2, b, sa, 1, 0);
  }
  if (w < 0.0) {
    g = -g;
  }
  return g;
}

SHLIGHT_INLINE float shl_polygon_beckmann_ndf(const float (*v)[3], int nv, const float axis[3],
                                              float alpha) {
  shli_real px[SHLIGHT_CLIP_MAX];
  shli_real py[SHLIGHT_CLIP_MAX];
  shli_real pz[SHLIGHT_CLIP_MAX];
  shli_real par[5];
  shli_real sum = 0.0;
  int i;
  int j;
  int nc = shli_poly_load_clip(v, nv, axis, alpha, px, py, pz, par);
#if SHLIGHT_POLYGON_ANY
  if (nv > SHLIGHT_POLYGON_MAX) {
    return shli_fan_beckmann_ndf(v, nv, axis, alpha);
  }
#endif
  if (nv > SHLIGHT_POLYGON_MAX) {
    return -1.0f;
  }
  if (nc == 0) {
    return 0.0f;
  }
  for (i = 0; i < nc; ++i) {
    j = i + 1;
    if (j == nc) {
      j = 0;
    }
    sum = sum + shli_beckmann_edge(px[i], py[i], pz[i], px[j], py[j], pz[j], par[0], par[1], par[2],
                                   par[4], 0.0);
  }
  return SHLIGHT_FLOAT(SHLIGHT_MAXR(par[3] * sum, 0.0) * 0.15915494309189534);
}

/* The split points of the light edge a -> b (unit vectors, arc angle phi in (0, pi)) for k
   sub-edges (k - 1 points), as fractions of the arc's angle in (0, 1), ascending, in io_split;
   returns their count. p is the point of the edge's great circle nearest the mirror direction r
   ([AREA] Algorithm 1: where the image of the circle bends most). k = 2: one split at p when
   p lies inside the arc, none otherwise (the paper). k >= 3: p is one split and the other
   k - 2 are shared between its two sides in proportion to their angles, graded toward p
   quadratically (fraction tp (1 - u^2) and tp + (1 - tp) u^2, u uniform); with p outside the
   arc, k - 1 uniform splits. bal != 0: p is first moved toward the arc's midpoint p_m by the
   paper's balancing heuristic (Algorithm 2), p <- normalise((1 - km) p + km p_m), km =
   min(2 |n_e . v| m, 1), n_e the edge's unit normal, m the roughness (Beckmann alpha, or
   sqrt(2 / (e + 2)) for Blinn-Phong). */
SHLIGHT_INLINE int shli_half_splits(shli_real ax, shli_real ay, shli_real az, shli_real bx,
                                    shli_real by, shli_real bz, shli_real rx, shli_real ry,
                                    shli_real rz, shli_real vx, shli_real vy, shli_real vz,
                                    shli_real m, int k, int bal, shli_real *io_split) {
  shli_real nx = ay * bz - az * by;
  shli_real ny = az * bx - ax * bz;
  shli_real nz = ax * by - ay * bx;
  shli_real sp = SHLIGHT_SQRTR(nx * nx + ny * ny + nz * nz);
  shli_real cp = ax * bx + ay * by + az * bz;
  shli_real phi;
  shli_real w;
  shli_real qx;
  shli_real qy;
  shli_real qz;
  shli_real lq;
  shli_real pa;
  shli_real pb;
  shli_real km;
  shli_real mx;
  shli_real my;
  shli_real mz;
  shli_real cx;
  shli_real cy;
  shli_real cz;
  shli_real tp = 0.5;
  shli_real u;
  int inside = 0;
  int ns = 0;
  int nl;
  int nr;
  int j;
  if (k < 2 || !(sp > 1.0e-12)) {
    return 0;
  }
  phi = shli_atan2r(sp, cp);
  nx = nx / sp;
  ny = ny / sp;
  nz = nz / sp;
  w = nx * rx + ny * ry + nz * rz;
  qx = rx - w * nx;
  qy = ry - w * ny;
  qz = rz - w * nz;
  lq = SHLIGHT_SQRTR(qx * qx + qy * qy + qz * qz);
  if (lq > 1.0e-12) {
    qx = qx / lq;
    qy = qy / lq;
    qz = qz / lq;
    pa = qx * ax + qy * ay + qz * az;
    pb = qx * bx + qy * by + qz * bz;
    if (pa - cp * pb > 0.0 && pb - cp * pa > 0.0) {
      inside = 1;
      if (bal != 0) {
        km = SHLIGHT_MINR(2.0 * SHLIGHT_ABSR(nx * vx + ny * vy + nz * vz) * m, 1.0);
        mx = ax + bx;
        my = ay + by;
        mz = az + bz;
        lq = SHLIGHT_SQRTR(mx * mx + my * my + mz * mz);
        qx = (1.0 - km) * qx + km * mx / lq;
        qy = (1.0 - km) * qy + km * my / lq;
        qz = (1.0 - km) * qz + km * mz / lq;
      }
      cx = ay * qz - az * qy;
      cy = az * qx - ax * qz;
      cz = ax * qy - ay * qx;
      tp = shli_atan2r(SHLIGHT_SQRTR(cx * cx + cy * cy + cz * cz), ax * qx + ay * qy + az * qz) /
           phi;
      tp = SHLIGHT_MINR(SHLIGHT_MAXR(tp, 0.0), 1.0);
    }
  }
  if (inside == 0) {
    if (k == 2) {
      return 0;
    }
    for (j = 1; j < k; ++j) {
      io_split[ns] = SHLIGHT_ITOR(j) / SHLIGHT_ITOR(k);
      ns = ns + 1;
    }
    return ns;
  }
  nl = SHLIGHT_FTOI(SHLIGHT_ITOR(k - 2) * tp + 0.5);
  nr = k - 2 - nl;
  for (j = 1; j <= nl; ++j) {
    u = 1.0 - SHLIGHT_ITOR(j) / SHLIGHT_ITOR(nl + 1);
    io_split[ns] = tp * (1.0 - u * u);
    ns = ns + 1;
  }
  io_split[ns] = tp;
  ns = ns + 1;
  for (j = 1; j <= nr; ++j) {
    u = SHLIGHT_ITOR(j) / SHLIGHT_ITOR(nr + 1);
    io_split[ns] = tp + (1.0 - tp) * u * u;
    ns = ns + 1;
  }
  return ns;
}

/* integral along the great arc a -> b (unit, inside t = u.n >= 0, b != -a) of t^p (u.c)^j ds
   (j = 0 or 1, p >= 0), or for j = 2 of E(t) / t^2, E = exp(-(1 - t^2) / (t^2 p^2)) (Beckmann,
   p = alpha): t = R cos(s - s0) along the arc; the arc is cut at the peak s0 and each side
   integrated by 8-node Gauss-Legendre in x after the graded change d = beta sinh(x) of the
   distance d to the peak, beta = 1 / sqrt(p + 1) (the peak's width; alpha / sqrt 2 for
   j = 2). */
SHLIGHT_INLINE shli_real shli_half_arc(shli_real ax, shli_real ay, shli_real az, shli_real bx,
                                       shli_real by, shli_real bz, shli_real nx, shli_real ny,
                                       shli_real nz, shli_real cx, shli_real cy, shli_real cz,
                                       shli_real p, int j) {
  shli_real ex = ay * bz - az * by;
  shli_real ey = az * bx - ax * bz;
  shli_real ez = ax * by - ay * bx;
  shli_real sp = SHLIGHT_SQRTR(ex * ex + ey * ey + ez * ez);
  shli_real cp = ax * bx + ay * by + az * bz;
  shli_real phi;
  shli_real ux;
  shli_real uy;
  shli_real uz;
  shli_real ta;
  shli_real tb;
  shli_real ca;
  shli_real cb;
  shli_real rr;
  shli_real s0;
  shli_real beta;
  shli_real lo;
  shli_real hi;
  shli_real x0;
  shli_real x1;
  shli_real xm;
  shli_real xr;
  shli_real x;
  shli_real d;
  shli_real s;
  shli_real t;
  shli_real f;
  shli_real sum = 0.0;
  shli_real gx;
  shli_real gw;
  int side;
  int q;
  if (!(sp > 1.0e-30)) {
    return 0.0;
  }
  phi = shli_atan2r(sp, cp);
  ux = (bx - cp * ax) / sp;
  uy = (by - cp * ay) / sp;
  uz = (bz - cp * az) / sp;
  ta = ax * nx + ay * ny + az * nz;
  tb = ux * nx + uy * ny + uz * nz;
  ca = ax * cx + ay * cy + az * cz;
  cb = ux * cx + uy * cy + uz * cz;
  rr = SHLIGHT_SQRTR(ta * ta + tb * tb);
  if (!(rr > 0.0)) {
    return 0.0;
  }
  s0 = SHLIGHT_MINR(SHLIGHT_MAXR(shli_atan2r(tb, ta), 0.0), phi);
  beta = 1.0 / SHLIGHT_SQRTR(p + 1.0);
  if (j == 2) {
    beta = 0.70710678118654752 * p;
  }
  for (side = 0; side < 2; ++side) {
    lo = 0.0;
    hi = phi - s0;
    if (side == 1) {
      hi = s0;
    }
    if (hi > 0.0) {
      x0 = SHLIGHT_LOGR(lo / beta + SHLIGHT_SQRTR(lo * lo / (beta * beta) + 1.0));
      x1 = SHLIGHT_LOGR(hi / beta + SHLIGHT_SQRTR(hi * hi / (beta * beta) + 1.0));
      xm = 0.5 * (x0 + x1);
      xr = 0.5 * (x1 - x0);
      for (q = 0; q < 8; ++q) {
        gx = 0.18343464249564980;
        gw = 0.36268378337836198;
        if (q == 2 || q == 3) {
          gx = 0.52553240991632899;
          gw = 0.31370664587788727;
        }
        if (q == 4 || q == 5) {
          gx = 0.79666647741362674;
          gw = 0.22238103445337447;
        }
        if (q == 6 || q == 7) {
          gx = 0.96028985649753623;
          gw = 0.10122853629037626;
        }
        if (q - 2 * (q / 2) == 1) {
          gx = -gx;
        }
        x = xm + xr * gx;
        d = 0.5 * beta * (SHLIGHT_EXPR(x) - SHLIGHT_EXPR(-x));
        s = s0 + d;
        if (side == 1) {
          s = s0 - d;
        }
        t = SHLIGHT_MAXR(ta * SHLIGHT_COSR(s) + tb * SHLIGHT_SINR(s), 0.0);
        f = 1.0;
        if (p > 0.0) {
          f = 0.0;
        }
        if (t > 0.0 && p > 0.0) {
          f = SHLIGHT_EXPR(p * SHLIGHT_LOGR(t));
        }
        if (j == 2) {
          f = 0.0;
          if (t > 0.0) {
            f = SHLIGHT_EXPR(-SHLIGHT_MINR((1.0 - t * t) / (t * t * p * p), 700.0)) / (t * t);
          }
        }
        if (j == 1) {
          f = f * (ca * SHLIGHT_COSR(s) + cb * SHLIGHT_SINR(s));
        }
        sum = sum + xr * gw * f * 0.5 * beta * (SHLIGHT_EXPR(x) + SHLIGHT_EXPR(-x));
      }
    }
  }
  return sum;
}

/* The integrals over the image in half-vector space of the clipped light polygon (io_px, io_py,
   io_pz)[0..nc-1] (unit vertices above the horizon of the unit normal n, view v unit with
   n.v > 0; the arrays are only read), signed by the light's winding: each edge cut into
   sub-edges at shli_half_splits' points, every end point mapped by H(l) = normalise(l + v),
   consecutive images joined by great arcs; one walk for every kind.
   kind 0, Blinn-Phong over the image polygon without a held factor: with
   n.l = 2 (h.v)(h.n) - n.v, the integrand D (n.l) (h.v) = (e+2)/(2 pi) [2 t^(e+1) (h.v)^2 -
   (n.v) t^e (h.v)], t = h.n, is a polynomial in h times a power of t; its integrals follow
   from two moments (exponents e + 1 and e - 1, QUADRATURE edge terms) and two line integrals
   per arc (shli_half_arc) by the surface divergence theorem applied to t^a P(v) and
   t^a (h.v) P(v), P(v) = v - (v.h) h the tangential part of v.
   kinds 2 and 3, the image's NDF measures (the split's own error, tests/test_microfacet): kind 2
   (par = e) (e+2)/(2 pi) M^(e+1), QUADRATURE terms at exponent e + 1, the integral of
   D_Blinn (h.n); kind 3 (par = alpha) the integral of D_B (h.n) (shli_beckmann_edge).
   kind 1, K = the integral of D_B(h) (h.v) over the image polygon, by the surface divergence
   identity for g(t) P(v) with (t^2 g)' = t D_B: g = E(t) / (2 pi t^2), E = exp(-(1 - t^2) / (t^2
   alpha^2)), and K = (n.v) (integral of g') - sum over arcs (v.m) (line integral of g), m the
   outward conormal; the integral of the radial g' by the Stokes form with the closed-form 2 pi
   (g(1) - g(t)) = 1 - E / t^2 (shli_beckmann_edge with sa = alpha^2). par = alpha. */
SHLIGHT_INLINE shli_real shli_half_image(shli_real *io_px, shli_real *io_py, shli_real *io_pz,
                                         int nc, shli_real nx, shli_real ny, shli_real nz,
                                         shli_real vx, shli_real vy, shli_real vz, shli_real m,
                                         int k, int bal, shli_real par, int kind) {
  shli_real st[SHLIGHT_HALF_K];
  shli_real rx;
  shli_real ry;
  shli_real rz;
  shli_real dv = nx * vx + ny * vy + nz * vz;
  shli_real ex;
  shli_real ey;
  shli_real ez;
  shli_real sp;
  shli_real cp;
  shli_real phi;
  shli_real ux;
  shli_real uy;
  shli_real uz;
  shli_real hax;
  shli_real hay;
  shli_real haz;
  shli_real hbx;
  shli_real hby;
  shli_real hbz;
  shli_real tx;
  shli_real ty;
  shli_real tz;
  shli_real cs;
  shli_real sn;
  shli_real l;
  shli_real a1 = 0.0;
  shli_real a0 = 0.0;
  shli_real pp = 0.0;
  shli_real qq = 0.0;
  shli_real mx;
  shli_real my;
  shli_real mz;
  shli_real j1;
  shli_real j2;
  int ns;
  int i;
  int j;
  int jj;
  rx = 2.0 * dv * nx - vx;
  ry = 2.0 * dv * ny - vy;
  rz = 2.0 * dv * nz - vz;
  /* the edge sum over the image polygon: sub-edge end points mapped by H, joined by arcs */
  for (i = 0; i < nc; ++i) {
    j = i + 1;
    if (j == nc) {
      j = 0;
    }
    ex = io_py[i] * io_pz[j] - io_pz[i] * io_py[j];
    ey = io_pz[i] * io_px[j] - io_px[i] * io_pz[j];
    ez = io_px[i] * io_py[j] - io_py[i] * io_px[j];
    sp = SHLIGHT_SQRTR(ex * ex + ey * ey + ez * ez);
    cp = io_px[i] * io_px[j] + io_py[i] * io_py[j] + io_pz[i] * io_pz[j];
    ns = 0;
    phi = 0.0;
    ux = 0.0;
    uy = 0.0;
    uz = 0.0;
    if (sp > 1.0e-12) {
      ns = shli_half_splits(io_px[i], io_py[i], io_pz[i], io_px[j], io_py[j], io_pz[j], rx, ry, rz,
                            vx, vy, vz, m, k, bal, st);
      phi = shli_atan2r(sp, cp);
      ux = (io_px[j] - cp * io_px[i]) / sp;
      uy = (io_py[j] - cp * io_py[i]) / sp;
      uz = (io_pz[j] - cp * io_pz[i]) / sp;
    }
    hax = io_px[i] + vx;
    hay = io_py[i] + vy;
    haz = io_pz[i] + vz;
    l = SHLIGHT_SQRTR(hax * hax + hay * hay + haz * haz);
    if (!(l > 1.0e-30)) {
      return 0.0;
    }
    hax = hax / l;
    hay = hay / l;
    haz = haz / l;
    for (jj = 0; jj <= ns; ++jj) {
      tx = io_px[j];
      ty = io_py[j];
      tz = io_pz[j];
      if (jj < ns) {
        cs = SHLIGHT_COSR(st[jj] * phi);
        sn = SHLIGHT_SINR(st[jj] * phi);
        tx = cs * io_px[i] + sn * ux;
        ty = cs * io_py[i] + sn * uy;
        tz = cs * io_pz[i] + sn * uz;
      }
      hbx = tx + vx;
      hby = ty + vy;
      hbz = tz + vz;
      l = SHLIGHT_SQRTR(hbx * hbx + hby * hby + hbz * hbz);
      if (!(l > 1.0e-30)) {
        return 0.0;
      }
      hbx = hbx / l;
      hby = hby / l;
      hbz = hbz / l;
      if (kind == 0 || kind == 2) {
        a1 = a1 + shli_edge_term(hax, hay, haz, hbx, hby, hbz, nx, ny, nz, par + 1.0,
                                 SHLIGHT_EDGE_QUADRATURE);
        if (kind == 0 && par > 0.0) {
          a0 = a0 + shli_edge_term(hax, hay, haz, hbx, hby, hbz, nx, ny, nz, par - 1.0,
                                   SHLIGHT_EDGE_QUADRATURE);
        }
      } else if (kind == 1) {
        a1 = a1 + shli_beckmann_edge(hax, hay, haz, hbx, hby, hbz, nx, ny, nz, par, par * par);
      } else {
        a1 = a1 + shli_beckmann_edge(hax, hay, haz, hbx, hby, hbz, nx, ny, nz, par, 0.0);
      }
      mx = hay * hbz - haz * hby;
      my = haz * hbx - hax * hbz;
      mz = hax * hby - hay * hbx;
      l = SHLIGHT_SQRTR(mx * mx + my * my + mz * mz);
      if (kind < 2 && l > 1.0e-30) {
        l = -(mx * vx + my * vy + mz * vz) / l; /* outward conormal: -(a x b) */
        if (kind == 0) {
          pp = pp + l * shli_half_arc(hax, hay, haz, hbx, hby, hbz, nx, ny, nz, vx, vy, vz, par, 0);
          qq = qq + l * shli_half_arc(hax, hay, haz, hbx, hby, hbz, nx, ny, nz, vx, vy, vz,
                                      par + 1.0, 1);
        } else {
          pp = pp + l * shli_half_arc(hax, hay, haz, hbx, hby, hbz, nx, ny, nz, vx, vy, vz, par, 2);
        }
      }
      hax = hbx;
      hay = hby;
      haz = hbz;
    }
  }
  /* J1 = integral of t^e (h.v), J2 = of t^(e+1) (h.v)^2 over the image (surface divergence
     identities, docs/accuracy.md): (a+2) J1(a) = a (n.v) M^(a-1) - sum (v.m) line(t^a),
     (a+3) J2(a) = a (n.v) J1(a-1) + M^a - sum (v.m) line(t^a (h.v)), m the outward
     conormal */
  if (kind >= 2) {
    return a1 * 0.15915494309189534;
  }
  if (kind != 0) {
    /* (n.v) (integral of g') - sum (v.m) line(g), g = E / (2 pi t^2) */
    return (dv * a1 - pp) * 0.15915494309189534;
  }
  j1 = (dv * a0 - pp) / (par + 2.0);
  j2 = ((par + 1.0) * dv * j1 + a1 / (par + 2.0) - qq) / (par + 4.0);
  return (par + 2.0) * 0.15915494309189534 * (2.0 * j2 - dv * j1);
}

/* The common body of shl_polygon_blinn_phong (kind 0, par = e) and shl_polygon_beckmann_subedges
   (kind 1, par = alpha): clip to the horizon, the representative direction l* (the point of the
   clipped light nearest the mirror direction r: r itself when every edge sees r on the same
   side, else the nearest vertex or in-arc foot point; used for Beckmann's held G2), then the
   sums over the sub-edge image polygon in half-vector space (shli_half_image). par already
   clamped. */
SHLIGHT_INLINE shli_real shli_half_light(const float (*v)[3], int nv, const float nrm[3],
                                         const float view[3], shli_real par, int subedges,
                                         int kind) {
  shli_real px[SHLIGHT_CLIP_MAX];
  shli_real py[SHLIGHT_CLIP_MAX];
  shli_real pz[SHLIGHT_CLIP_MAX];
  shli_real nx = SHLIGHT_REAL(nrm[0]);
  shli_real ny = SHLIGHT_REAL(nrm[1]);
  shli_real nz = SHLIGHT_REAL(nrm[2]);
  shli_real vx = SHLIGHT_REAL(view[0]);
  shli_real vy = SHLIGHT_REAL(view[1]);
  shli_real vz = SHLIGHT_REAL(view[2]);
  shli_real ln = SHLIGHT_SQRTR(nx * nx + ny * ny + nz * nz);
  shli_real lv = SHLIGHT_SQRTR(vx * vx + vy * vy + vz * vz);
  shli_real dv;
  shli_real rx;
  shli_real ry;
  shli_real rz;
  shli_real ex;
  shli_real ey;
  shli_real ez;
  shli_real le;
  shli_real wr;
  shli_real qx;
  shli_real qy;
  shli_real qz;
  shli_real best;
  shli_real lsx;
  shli_real lsy;
  shli_real lsz;
  shli_real cp;
  shli_real l;
  shli_real m;
  shli_real sum = 0.0;
  shli_real hn;
  shli_real hv;
  shli_real nl;
  int npos = 0;
  int nneg = 0;
  int nc;
  int sg = 1;
  int k;
  int bal = 0;
  int i;
  int j;
  if (nv < 3 || nv > SHLIGHT_POLYGON_MAX || !(ln > 0.0) || !(ln < SHLIGHT_REAL_MAX) ||
      !(lv > 0.0) || !(lv < SHLIGHT_REAL_MAX)) {
    return 0.0;
  }
  nx = nx / ln;
  ny = ny / ln;
  nz = nz / ln;
  vx = vx / lv;
  vy = vy / lv;
  vz = vz / lv;
  dv = nx * vx + ny * vy + nz * vz;
  if (!(dv > 0.0)) {
    return 0.0;
  }
  rx = 2.0 * dv * nx - vx;
  ry = 2.0 * dv * ny - vy;
  rz = 2.0 * dv * nz - vz;
  for (i = 0; i < nv; ++i) {
    px[i] = SHLIGHT_REAL(v[i][0]);
    py[i] = SHLIGHT_REAL(v[i][1]);
    pz[i] = SHLIGHT_REAL(v[i][2]);
    if (!(SHLIGHT_ABSR(px[i]) + SHLIGHT_ABSR(py[i]) + SHLIGHT_ABSR(pz[i]) < SHLIGHT_REAL_MAX)) {
      return 0.0;
    }
  }
  nc = shli_poly_clip_unit(px, py, pz, nv, nx, ny, nz);
  if (nc == 0) {
    return 0.0;
  }
  if (nc < 0) {
    nc = -nc;
    sg = -1;
  }
  k = subedges;
  if (k < -SHLIGHT_HALF_K) { /* clamped before the sign is taken: no -INT_MIN */
    k = -SHLIGHT_HALF_K;
  }
  if (k < 0) {
    k = -k;
  } else {
    bal = 1;
  }
  if (k > SHLIGHT_HALF_K) {
    k = SHLIGHT_HALF_K;
  }
  if (k < 1) {
    k = 1;
  }
  m = par;
  if (kind == 0) {
    m = SHLIGHT_SQRTR(2.0 / (par + 2.0));
  }
  /* l*: r inside (every edge plane sees it on one side), else the nearest boundary point */
  lsx = px[0];
  lsy = py[0];
  lsz = pz[0];
  best = -2.0;
  for (i = 0; i < nc; ++i) {
    j = i + 1;
    if (j == nc) {
      j = 0;
    }
    ex = py[i] * pz[j] - pz[i] * py[j];
    ey = pz[i] * px[j] - px[i] * pz[j];
    ez = px[i] * py[j] - py[i] * px[j];
    le = ex * ex + ey * ey + ez * ez;
    wr = ex * rx + ey * ry + ez * rz;
    if (wr > 0.0) {
      npos = npos + 1;
    }
    if (wr < 0.0) {
      nneg = nneg + 1;
    }
    if (px[i] * rx + py[i] * ry + pz[i] * rz > best) {
      best = px[i] * rx + py[i] * ry + pz[i] * rz;
      lsx = px[i];
      lsy = py[i];
      lsz = pz[i];
    }
    if (le > 1.0e-30) {
      qx = rx - wr / le * ex;
      qy = ry - wr / le * ey;
      qz = rz - wr / le * ez;
      l = SHLIGHT_SQRTR(qx * qx + qy * qy + qz * qz);
      cp = px[i] * px[j] + py[i] * py[j] + pz[i] * pz[j];
      if (l > 1.0e-12) {
        qx = qx / l;
        qy = qy / l;
        qz = qz / l;
        hn = qx * px[i] + qy * py[i] + qz * pz[i];
        hv = qx * px[j] + qy * py[j] + qz * pz[j];
        if (hn - cp * hv > 0.0 && hv - cp * hn > 0.0 && qx * rx + qy * ry + qz * rz > best) {
          best = qx * rx + qy * ry + qz * rz;
          lsx = qx;
          lsy = qy;
          lsz = qz;
        }
      }
    }
  }
  if (npos == 0 || nneg == 0) {
    lsx = rx;
    lsy = ry;
    lsz = rz;
  }
  sum = shli_half_image(px, py, pz, nc, nx, ny, nz, vx, vy, vz, m, k, bal, par, kind);
  if (sg < 0) {
    sum = -sum;
  }
  sum = SHLIGHT_MAXR(sum, 0.0);
  if (kind == 0) {
    return sum;
  }
  /* G2 held at l* */
  nl = SHLIGHT_MAXR(lsx * nx + lsy * ny + lsz * nz, 0.0);
  return sum / ((1.0 + shli_beckmann_lambda(dv, par) + shli_beckmann_lambda(nl, par)) * dv);
}

SHLIGHT_INLINE float shl_polygon_blinn_phong(const float (*v)[3], int nv, const float nrm[3],
                                             const float view[3], float exponent, int subedges) {
  shli_real e = SHLIGHT_REAL(exponent);
#if SHLIGHT_POLYGON_ANY
  if (nv > SHLIGHT_POLYGON_MAX) {
    return shli_fan_blinn_phong(v, nv, nrm, view, exponent, subedges);
  }
#endif
  if (nv > SHLIGHT_POLYGON_MAX) {
    return -1.0f;
  }
  if (!(e == e)) {
    return 0.0f;
  }
  e = SHLIGHT_MINR(SHLIGHT_MAXR(e, 0.0), 1.0e6);
  return SHLIGHT_FLOAT(shli_half_light(v, nv, nrm, view, e, subedges, 0));
}

SHLIGHT_INLINE float shl_polygon_beckmann_subedges(const float (*v)[3], int nv, const float nrm[3],
                                                   const float view[3], float alpha, int subedges) {
  shli_real al = SHLIGHT_REAL(alpha);
#if SHLIGHT_POLYGON_ANY
  if (nv > SHLIGHT_POLYGON_MAX) {
    return shli_fan_beckmann(v, nv, nrm, view, alpha, subedges);
  }
#endif
  if (nv > SHLIGHT_POLYGON_MAX) {
    return -1.0f;
  }
  if (!(al == al)) {
    return 0.0f;
  }
  al = SHLIGHT_MINR(SHLIGHT_MAXR(al, 1.0e-4), 1.0);
  return SHLIGHT_FLOAT(shli_half_light(v, nv, nrm, view, al, subedges, 1));
}

/* the fan pieces of the polygon functions above SHLIGHT_POLYGON_MAX vertices (C only; see the
   start of >>edge) */
#define SHLIGHT_FAN_SUM_(call)                                                                     \
  shli_fan f;                                                                                      \
  shli_fan_begin(&f, v, nv);                                                                       \
  while (shli_fan_next(&f, v, nv)) {                                                               \
    if (f.sg != 0) {                                                                               \
      f.sum = f.sum + (double)f.sg * (double)(call);                                               \
    }                                                                                              \
  }                                                                                                \
  return shli_fan_end(&f)
#define SHLIGHT_FAN_P_ ((const float(*)[3])f.p)
SHLIGHT_CPU_INLINE float shli_fan_moment(const float (*v)[3], int nv, const float axis[3],
                                         float exponent, shl_edge_method method) {
  SHLIGHT_FAN_SUM_(shl_polygon_moment(SHLIGHT_FAN_P_, f.np, axis, exponent, method));
}
SHLIGHT_CPU_INLINE float shli_fan_phong(const float (*v)[3], int nv, const float nrm[3],
                                        const float view[3], float exponent,
                                        shl_edge_method method) {
  SHLIGHT_FAN_SUM_(shl_polygon_phong(SHLIGHT_FAN_P_, f.np, nrm, view, exponent, method));
}
SHLIGHT_CPU_INLINE float shli_fan_phong2(const float (*v)[3], int nv, const float nrm[3],
                                         const float view[3], float exponent,
                                         shl_edge_method method) {
  SHLIGHT_FAN_SUM_(
      shl_polygon_phong_double_axis(SHLIGHT_FAN_P_, f.np, nrm, view, exponent, method));
}
SHLIGHT_CPU_INLINE float shli_fan_ggx_ndf(const float (*v)[3], int nv, const float axis[3],
                                          float alpha) {
  SHLIGHT_FAN_SUM_(shl_polygon_ggx_ndf(SHLIGHT_FAN_P_, f.np, axis, alpha));
}
SHLIGHT_CPU_INLINE float shli_fan_ggx(const float (*v)[3], int nv, const float nrm[3],
                                      const float view[3], float alpha) {
  SHLIGHT_FAN_SUM_(shl_polygon_ggx(SHLIGHT_FAN_P_, f.np, nrm, view, alpha));
}
SHLIGHT_CPU_INLINE float shli_fan_beckmann_taylor(const float (*v)[3], int nv, const float nrm[3],
                                                  const float view[3], float alpha) {
  SHLIGHT_FAN_SUM_(shl_polygon_beckmann(SHLIGHT_FAN_P_, f.np, nrm, view, alpha));
}
SHLIGHT_CPU_INLINE float shli_fan_beckmann_ndf(const float (*v)[3], int nv, const float axis[3],
                                               float alpha) {
  SHLIGHT_FAN_SUM_(shl_polygon_beckmann_ndf(SHLIGHT_FAN_P_, f.np, axis, alpha));
}
SHLIGHT_CPU_INLINE float shli_fan_blinn_phong(const float (*v)[3], int nv, const float nrm[3],
                                              const float view[3], float exponent, int subedges) {
  SHLIGHT_FAN_SUM_(shl_polygon_blinn_phong(SHLIGHT_FAN_P_, f.np, nrm, view, exponent, subedges));
}
SHLIGHT_CPU_INLINE float shli_fan_beckmann(const float (*v)[3], int nv, const float nrm[3],
                                           const float view[3], float alpha, int subedges) {
  SHLIGHT_FAN_SUM_(shl_polygon_beckmann_subedges(SHLIGHT_FAN_P_, f.np, nrm, view, alpha, subedges));
}
#undef SHLIGHT_FAN_SUM_
#undef SHLIGHT_FAN_P_

/* >>brdf ------------------------------------------------------------------------------------
   ZH of circularly symmetric BRDF lobes, convolution with SH / ZH radiance, irradiance,
   windowing and band selection (docs/math.md section 5-6; [SSF] sec. 3.3 with correction E7
   (docs/math.md section 12); [HVL] sec. 4.2, 6.3, Appendix B). A lobe f(w . c) about its axis c
   (the normal for Lambert and the microfacet lobes, the mirror direction for Phong) has ZH
   coefficients f_l = 2 pi int_0^pi f(cos t) Y_l^0(t) sin t dt; its SH about c are sqrt(4 pi /
   (2l+1)) f_l Y_l^m(c) (shl_zh_rotate). Cosine powers (Lambert, Phong, Blinn-Phong) use the
   factorial-free recurrence of docs/math.md sec. 5: Lambda_l(e) = (e+1) int_0^1 x^e P_l(x) dx,
   Lambda_0 = 1, Lambda_1 = (e+1)/(e+2), Lambda_{l+2} = Lambda_l (e-l)/(e+l+3), in shli_real (double
   in C: within one float rounding of a binary128 quadrature reference for e in [0, 1e4] and n <=
   64, tests/test_brdf). The microfacet lobes (GGX, Beckmann: the projected NDF D(h)(n . h), which
   integrates to 1) use the substitution tan^2 t = alpha^2 v, after which f_l = K_l int w(v) P_l((1
   + alpha^2 v)^-1/2) dv with w(v) = (1+v)^-2 (GGX) or e^-v (Beckmann), and the trapezoidal rule in
   u = ln v (step h = min(0.35, 6 / (n+1)), u from -18 to where the weight is spent, both tails
   added in closed form): exponentially accurate for these smooth, decaying integrands.
   Measured against a long double quadrature in t: at the float rounding floor (shl_zh_ggx).
   Convolution: for radiance L (SH) and a lobe F (SH), int L F = sum_i L_i F_i (shl_sh_dot).
   For a ZH lobe f about the axis w, sum_l sqrt(4 pi / (2l+1)) f_l sum_m L_lm Y_lm(w)
   (shl_sh_conv_zh, O(n^2)). For two ZH, a about axis u and b about axis v, the addition
   theorem sum_m Y_lm(u) Y_lm(v) = (2l+1)/(4 pi) P_l(u . v) leaves
     int A B = sum_l a_l b_l P_l(u . v)                   (shl_zh_dot_zh, O(n))
   (no sqrt(4 pi / (2l+1)) factor: the two rotations' factors cancel against the theorem's).
   Irradiance of a ZH radiance L about w at a normal n, z = w . n (docs/math.md section 6):
     E(z) = sum_l A_l K_l L_l P_l(z), A_l = pi Lambda_l(1)   (A_0 = pi, A_1 = 2pi/3, A_2 = pi/4)
   which for n = 3 is [HVL] Appendix B 2x2 form c3 L2 z^2 + 2 c2 L1 z + c4 L0 - c5 L2. */

/* out_zh[l] = scale K_l Lambda_l(e), l < n (n already clamped, >= 1), e in [0, 1e30]. */
SHLIGHT_INLINE void shli_zh_lambda(int n, shli_real e, shli_real scale, float *out_zh) {
  shli_real pm2 = 1.0;
  shli_real pm1 = 1.0;
  shli_real c = 1.0;
  shli_real fl = 0.0;
  int l;
  for (l = 0; l < n; ++l) {
    if (l == 1) {
      c = (e + 1.0) / (e + 2.0);
    } else if (l > 1) {
      c = pm2 * ((e - fl + 2.0) / (e + fl + 1.0));
    }
    out_zh[l] = SHLIGHT_FLOAT(scale * (SHLI_ZH_TAB[5 * l + 4] * 0.15915494309189535) * c);
    pm2 = pm1;
    pm1 = c;
    fl = fl + 1.0;
  }
}

/* The exponent as the cosine-power kernels use it: NaN or < 0 -> 0, > 1e30 -> 1e30. */
SHLIGHT_INLINE shli_real shli_zh_exponent(float exponent) {
  shli_real e = SHLIGHT_REAL(exponent);
  if (!(e >= 0.0)) {
    e = 0.0;
  }
  if (e > 1.0e30) {
    e = 1.0e30;
  }
  return e;
}

SHLIGHT_INLINE void shl_zh_phong(int n, float exponent, float *out_zh) {
  n = shli_bands(n);
  if (n < 1) {
    return;
  }
  shli_zh_lambda(n, shli_zh_exponent(exponent), 1.0, out_zh);
}

SHLIGHT_INLINE void shl_zh_cosine_power(int n, float exponent, float *out_zh) {
  shli_real e;
  n = shli_bands(n);
  if (n < 1) {
    return;
  }
  e = shli_zh_exponent(exponent);
  shli_zh_lambda(n, e, 6.283185307179586 / (e + 1.0), out_zh);
}

SHLIGHT_INLINE void shl_zh_lambert(int n, float *out_zh) {
  shl_zh_phong(n, 1.0f, out_zh);
}

SHLIGHT_INLINE void shl_zh_blinn_phong(int n, float exponent, float *out_zh) {
  float e = exponent;
  if (!(e >= 0.0f)) {
    e = 0.0f;
  }
  shl_zh_phong(n, e + 1.0f, out_zh);
}

/* Trapezoidal rule in u = ln v for the microfacet ZH (see >>brdf); kind 0: GGX, 1: Beckmann.
   alpha already in [1e-6, 1e4]. */
SHLIGHT_INLINE void shli_zh_ndf(int n, shli_real alpha, int kind, float *out_zh) {
  shli_real acc[SHLIGHT_MAX_BANDS];
  shli_real a2 = alpha * alpha;
  shli_real h = 6.0 / (SHLIGHT_REAL(SHLIGHT_ITOF(n)) + 1.0);
  shli_real u = -18.0;
  shli_real v;
  shli_real vmax = 45.0;
  shli_real wt;
  shli_real x;
  shli_real pm;
  shli_real pl;
  shli_real pn;
  int l;
  int k;
  int more = 1;
  if (h > 0.35) {
    h = 0.35;
  }
  if (kind == 0) {
    vmax = 65659969.13733051; /* e^18 / min(alpha^2, 1): where x < 1e-8 and 1 - F < 1.5e-8 */
    if (a2 < 1.0) {
      vmax = vmax / a2;
    }
  }
  /* left tail (u < -18 - h/2): P_l = 1 to O(alpha^2 v), its weight in closed form */
  v = SHLIGHT_EXPR(u - 0.5 * h);
  wt = v * (1.0 - 0.5 * v);
  if (kind == 0) {
    wt = v / (1.0 + v);
  }
  for (l = 0; l < n; ++l) {
    acc[l] = wt;
  }
  k = 0;
  while (more == 1) {
    v = SHLIGHT_EXPR(u);
    x = 1.0 / SHLIGHT_SQRTR(1.0 + a2 * v);
    if (kind == 0) {
      wt = h * v / ((1.0 + v) * (1.0 + v));
    } else {
      wt = h * v * SHLIGHT_EXPR(-v);
    }
    if (v > vmax || k > 4000) {
      /* right tail (u > last node + h/2): GGX's 1 - F = 1 / (1 + v) at x = 0 (Beckmann's is
         below 3e-20) */
      more = 0;
      x = 0.0;
      wt = 0.0;
      if (kind == 0) {
        wt = 1.0 / (1.0 + SHLIGHT_EXPR(u - 0.5 * h));
      }
    }
    pm = 1.0;
    pl = x;
    acc[0] = acc[0] + wt;
    for (l = 1; l < n; ++l) {
      acc[l] = acc[l] + wt * pl;
      pn = SHLI_ZH_TAB[5 * l] * x * pl - SHLI_ZH_TAB[5 * l + 1] * pm;
      pm = pl;
      pl = pn;
    }
    u = u + h;
    k = k + 1;
  }
  for (l = 0; l < n; ++l) {
    out_zh[l] = SHLIGHT_FLOAT(acc[l] * (SHLI_ZH_TAB[5 * l + 4] * 0.15915494309189535));
  }
}

/* Delta lobe (alpha -> 0): out_zh[l] = K_l. */
SHLIGHT_INLINE void shli_zh_delta(int n, float *out_zh) {
  int l;
  for (l = 0; l < n; ++l) {
    out_zh[l] = SHLIGHT_FLOAT(SHLI_ZH_TAB[5 * l + 4] * 0.15915494309189535);
  }
}

SHLIGHT_INLINE void shl_zh_ggx(int n, float alpha, float *out_zh) {
  shli_real a = SHLIGHT_REAL(alpha);
  n = shli_bands(n);
  if (n < 1) {
    return;
  }
  if (!(a >= 1.0e-6)) {
    shli_zh_delta(n, out_zh);
    return;
  }
  if (a > 1.0e4) {
    a = 1.0e4;
  }
  shli_zh_ndf(n, a, 0, out_zh);
}

SHLIGHT_INLINE void shl_zh_beckmann(int n, float alpha, float *out_zh) {
  shli_real a = SHLIGHT_REAL(alpha);
  n = shli_bands(n);
  if (n < 1) {
    return;
  }
  if (!(a >= 1.0e-6)) {
    shli_zh_delta(n, out_zh);
    return;
  }
  if (a > 1.0e4) {
    a = 1.0e4;
  }
  shli_zh_ndf(n, a, 1, out_zh);
}

SHLIGHT_INLINE float shl_sh_dot(int n, const float *a, const float *b) {
  shli_real s0 = 0.0;
  shli_real s1 = 0.0;
  shli_real s2 = 0.0;
  shli_real s3 = 0.0;
  int i = 0;
  int nn;
  n = shli_bands(n);
  nn = n * n;
  while (i + 3 < nn) {
    s0 = s0 + SHLIGHT_REAL(a[i]) * SHLIGHT_REAL(b[i]);
    s1 = s1 + SHLIGHT_REAL(a[i + 1]) * SHLIGHT_REAL(b[i + 1]);
    s2 = s2 + SHLIGHT_REAL(a[i + 2]) * SHLIGHT_REAL(b[i + 2]);
    s3 = s3 + SHLIGHT_REAL(a[i + 3]) * SHLIGHT_REAL(b[i + 3]);
    i = i + 4;
  }
  while (i < nn) {
    s0 = s0 + SHLIGHT_REAL(a[i]) * SHLIGHT_REAL(b[i]);
    i = i + 1;
  }
  return SHLIGHT_FLOAT((s0 + s1) + (s2 + s3));
}

#if SHLIGHT_MAX_COEFFS > SHLI_YBUF_COEFFS
/* C only, for n^2 > SHLI_YBUF_COEFFS: Y_i(d) of shli_sh_eval_xyz's portable path (the same
   normalisation and recurrence as shli_sh_core_loop) consumed as it is produced, without an
   n^2 buffer. io == NULL: returns sum_i a[i] w_l Y_i accumulated in double, w_l = float(
   sqrt(4 pi / (2l+1)) zh[l]) (zh != NULL) or 1: the values and the rounding of the buffered
   kernels (Y and w_l Y in float, the sum in double). io != NULL, returns 0: e != 0:
   io[i stride] += e Y_i; e == 0: io[i stride] = Y_i. */
SHLIGHT_CPU_INLINE shli_real shli_sh_ystream(int n, float dx, float dy, float dz, const float *a,
                                             const float *zh, float e, float *io,
                                             ptrdiff_t stride) {
  shli_real x = SHLIGHT_REAL(dx), y = SHLIGHT_REAL(dy), z = SHLIGHT_REAL(dz);
  shli_real r2 = x * x + y * y + z * z - 1.0, kk = 1.0 + r2 * (-0.5 + 0.375 * r2);
  shli_real t, pc = 1.0, ps = 0.0, qc, xa, dd, s = 0.0;
  float wl[SHLIGHT_MAX_BANDS], ec, es, oc, os, sw, sg, xf;
  int m, l, j, b;
  x = x * kk;
  y = y * kk;
  z = z * kk;
  sg = SHLIGHT_SIGN1(z);
  t = (x * x + y * y) / (1.0 + SHLIGHT_ABSR(z));
  for (l = 0; l < n; ++l)
    wl[l] = zh ? SHLIGHT_FLOAT(SHLI_ZH_TAB[5 * l + 3] * SHLIGHT_REAL(zh[l])) : 1.0f;
  for (m = 0; m < n; ++m) {
    if (m > 0) {
      qc = x * pc - y * ps;
      ps = x * ps + y * pc;
      pc = qc;
    }
    ec = SHLIGHT_FLOAT(pc);
    es = SHLIGHT_FLOAT(ps);
    oc = sg * ec;
    os = sg * es;
    xa = SHLIGHT_REAL(SHLI_SH_DIAG[m]);
    dd = 0.0;
    for (l = m; l < n; ++l) {
      if (l > m) {
        j = 3 * ((l * (l - 1)) / 2 + m);
        dd = SHLI_SH_TAB[j + 2] * dd - (SHLI_SH_TAB[j] * t) * xa;
        xa = SHLI_SH_TAB[j + 1] * xa + dd;
        sw = ec;
        ec = oc;
        oc = sw;
        sw = es;
        es = os;
        os = sw;
      }
      xf = l > m ? SHLIGHT_FLOAT(xa) : SHLI_SH_DIAG[m];
      b = l * (l + 1);
      if (io && e != 0.0f) {
        io[(b + m) * stride] = io[(b + m) * stride] + e * (xf * ec);
        if (m > 0) io[(b - m) * stride] = io[(b - m) * stride] + e * (xf * es);
      } else if (io) {
        io[(b + m) * stride] = xf * ec;
        if (m > 0) io[(b - m) * stride] = xf * es;
      } else {
        s = s + SHLIGHT_REAL(a[b + m]) * SHLIGHT_REAL(wl[l] * (xf * ec));
        if (m > 0) s = s + SHLIGHT_REAL(a[b - m]) * SHLIGHT_REAL(wl[l] * (xf * es));
      }
    }
  }
  return s;
}
#endif

/* shl_sh_conv_zh on a unit axis (ux, uy, uz) given in shli_real. */
SHLIGHT_INLINE float shli_sh_conv_zh_xyz(int n, const float *sh, const float *zh, shli_real ux,
                                         shli_real uy, shli_real uz) {
  float ysh[SHLI_YBUF_COEFFS];
  float k;
  int l;
  int m;
  int b;
#if SHLIGHT_MAX_COEFFS > SHLI_YBUF_COEFFS
  if (n * n > SHLI_YBUF_COEFFS) {
    return SHLIGHT_FLOAT(shli_sh_ystream(n, SHLIGHT_FLOAT(ux), SHLIGHT_FLOAT(uy), SHLIGHT_FLOAT(uz),
                                         sh, zh, 0.0f, 0, 1));
  }
#endif
  shli_sh_eval_xyz(n, SHLIGHT_FLOAT(ux), SHLIGHT_FLOAT(uy), SHLIGHT_FLOAT(uz), ysh);
  /* the rotated lobe in place, then one dot (independent add chains, see shl_sh_dot) */
  for (l = 0; l < n; ++l) {
    b = l * (l + 1);
    k = SHLIGHT_FLOAT(SHLI_ZH_TAB[5 * l + 3] * SHLIGHT_REAL(zh[l]));
    for (m = -l; m <= l; ++m) {
      ysh[b + m] = k * ysh[b + m];
    }
  }
  return shl_sh_dot(n, sh, ysh);
}

SHLIGHT_INLINE float shl_sh_conv_zh(int n, const float *sh, const float *zh, const float w[3]) {
  shli_real g[8];
  n = shli_bands(n);
  if (n < 1) {
    return 0.0f;
  }
  shli_cap_frame(SHLIGHT_REAL(w[0]), SHLIGHT_REAL(w[1]), SHLIGHT_REAL(w[2]), 1.0, g);
  return shli_sh_conv_zh_xyz(n, sh, zh, g[0], g[1], g[2]);
}

/* Cosine between two directions, each normalised in shli_real (zero, NaN or infinite: +z),
   clamped to [-1, 1]. */
SHLIGHT_INLINE shli_real shli_cos_between(const float a[3], const float b[3]) {
  shli_real ga[8];
  shli_real gb[8];
  shli_real c;
  shli_cap_frame(SHLIGHT_REAL(a[0]), SHLIGHT_REAL(a[1]), SHLIGHT_REAL(a[2]), 1.0, ga);
  shli_cap_frame(SHLIGHT_REAL(b[0]), SHLIGHT_REAL(b[1]), SHLIGHT_REAL(b[2]), 1.0, gb);
  c = ga[0] * gb[0] + ga[1] * gb[1] + ga[2] * gb[2];
  if (c > 1.0) {
    c = 1.0;
  }
  if (c < -1.0) {
    c = -1.0;
  }
  return c;
}

/* sum_l zh_a[l] zh_b[l] P_l(c), c in [-1, 1], n >= 1. */
SHLIGHT_INLINE float shli_zh_dot_c(int n, const float *zh_a, const float *zh_b, shli_real c) {
  shli_real s;
  shli_real pm = 1.0;
  shli_real pl;
  shli_real pn;
  int l;
  s = SHLIGHT_REAL(zh_a[0]) * SHLIGHT_REAL(zh_b[0]);
  pl = c;
  for (l = 1; l < n; ++l) {
    s = s + SHLIGHT_REAL(zh_a[l]) * SHLIGHT_REAL(zh_b[l]) * pl;
    pn = SHLI_ZH_TAB[5 * l] * c * pl - SHLI_ZH_TAB[5 * l + 1] * pm;
    pm = pl;
    pl = pn;
  }
  return SHLIGHT_FLOAT(s);
}

SHLIGHT_INLINE float shl_zh_dot_zh(int n, const float *zh_a, const float u[3], const float *zh_b,
                                   const float v[3]) {
  n = shli_bands(n);
  if (n < 1) {
    return 0.0f;
  }
  return shli_zh_dot_c(n, zh_a, zh_b, shli_cos_between(u, v));
}

/* z clamped to [-1, 1]; NaN: 0 (the horizon). */
SHLIGHT_INLINE shli_real shli_clamp_cos(float z) {
  shli_real c = SHLIGHT_REAL(z);
  if (!(c >= -1.0 && c <= 1.0)) {
    if (c > 1.0) {
      c = 1.0;
    } else if (c < -1.0) {
      c = -1.0;
    } else {
      c = 0.0;
    }
  }
  return c;
}

SHLIGHT_INLINE float shl_zh_irradiance_quadratic(const float *zh3, float z) {
  shli_real c = shli_clamp_cos(z);
  shli_real l2 = SHLIGHT_REAL(zh3[2]);
  return SHLIGHT_FLOAT(0.7431238683011271 * l2 * c * c +
                       2.0 * 0.5116633539732443 * SHLIGHT_REAL(zh3[1]) * c +
                       0.8862269254527579 * SHLIGHT_REAL(zh3[0]) - 0.2477079561003757 * l2);
}

SHLIGHT_INLINE float shl_zh_irradiance(int n, const float *zh, float z) {
  shli_real c;
  shli_real s;
  shli_real pm = 1.0;
  shli_real pl;
  shli_real pn;
  shli_real lm2 = 1.0;
  shli_real lm1 = 1.0;
  shli_real lam;
  shli_real fl = 1.0;
  int l;
  n = shli_bands(n);
  if (n < 1) {
    return 0.0f;
  }
  c = shli_clamp_cos(z);
  /* A_l K_l = pi Lambda_l(1) sqrt(pi (2l+1)) / (2 pi) */
  s = 0.5 * SHLI_ZH_TAB[4] * SHLIGHT_REAL(zh[0]);
  pl = c;
  for (l = 1; l < n; ++l) {
    if (l == 1) {
      lam = 0.6666666666666666;
    } else {
      lam = lm2 * ((3.0 - fl) / (fl + 2.0));
    }
    s = s + 0.5 * SHLI_ZH_TAB[5 * l + 4] * lam * SHLIGHT_REAL(zh[l]) * pl;
    pn = SHLI_ZH_TAB[5 * l] * c * pl - SHLI_ZH_TAB[5 * l + 1] * pm;
    pm = pl;
    pl = pn;
    lm2 = lm1;
    lm1 = lam;
    fl = fl + 1.0;
  }
  return SHLIGHT_FLOAT(s);
}

/* sin(pi t) for t in [0, 1] from the shims alone (Taylor to x^17 after folding to [0, 1/2]:
   absolute error < 1e-13). */
SHLIGHT_INLINE shli_real shli_sinpi(shli_real t) {
  shli_real x;
  shli_real x2;
  shli_real p;
  if (t > 0.5) {
    t = 1.0 - t;
  }
  x = 3.141592653589793 * t;
  x2 = x * x;
  p = 2.8114572543455206e-15;
  p = -7.647163731819816e-13 + x2 * p;
  p = 1.6059043836821613e-10 + x2 * p;
  p = -2.505210838544172e-08 + x2 * p;
  p = 2.7557319223985893e-06 + x2 * p;
  p = -0.0001984126984126984 + x2 * p;
  p = 0.008333333333333333 + x2 * p;
  p = -0.16666666666666666 + x2 * p;
  return x + x * (x2 * p);
}

SHLIGHT_INLINE void shl_sh_window(int n, shl_window_kind kind, float width, float *io_zh) {
  shli_real w = SHLIGHT_REAL(width);
  shli_real t;
  shli_real sg;
  int l;
  n = shli_bands(n);
  if (n < 1 || (kind != 1 && kind != 2)) {
    return;
  }
  if (!(w > 0.0)) {
    w = SHLIGHT_REAL(SHLIGHT_ITOF(n));
  }
  for (l = 1; l < n; ++l) {
    t = SHLIGHT_REAL(SHLIGHT_ITOF(l)) / w;
    sg = 0.0;
    if (t < 1.0) {
      if (kind == 1) {
        /* (1 + cos(pi t)) / 2 = 1 - sin(pi t / 2)^2 */
        sg = shli_sinpi(0.5 * t);
        sg = 1.0 - sg * sg;
      } else if (t > 0.0) {
        sg = shli_sinpi(t) / (3.141592653589793 * t);
      } else {
        /* width = +inf: t = 0, sinc(0) = 1 (not 0 / 0) */
        sg = 1.0;
      }
    }
    io_zh[l] = SHLIGHT_FLOAT(SHLIGHT_REAL(io_zh[l]) * sg);
  }
}

SHLIGHT_INLINE int shl_zh_bands_for(int n, const float *zh, float target) {
  shli_real tot = 0.0;
  shli_real tail = 0.0;
  shli_real t = SHLIGHT_REAL(target);
  shli_real q;
  int l;
  int m;
  n = shli_bands(n);
  if (n < 1) {
    return 1;
  }
  for (l = 0; l < n; ++l) {
    tot = tot + SHLIGHT_REAL(zh[l]) * SHLIGHT_REAL(zh[l]);
  }
  if (!(tot > 0.0)) {
    return 1;
  }
  if (!(t >= 0.0)) {
    return n;
  }
  m = n;
  /* m: the smallest count found so far; tail = energy of the bands >= m - 1 when tested */
  for (l = n - 1; l >= 1; --l) {
    q = SHLIGHT_REAL(zh[l]);
    tail = tail + q * q;
    if (tail <= t * tot) {
      m = l;
    } else {
      break;
    }
  }
  return m;
}

/* >>hvl -------------------------------------------------------------------------------------
   Harmonics Virtual Lights ([HVL] sec. 5; docs/math.md section 6, corrections E8, E9). An HVL j is
   a sphere of radius r at y with normal n_j and power Phi_j, whose emission towards the shading
   point x is the reconstruction of an SH emission function F' (the BRDF projected without the
   cosine, in world axes). With w_j = (y - x) / |y - x| and n_x the normal at x:
     eq. 20  L_j = Phi_j (F' . Y(-w_j)) G_j(-w_j)                      (shl_hvl_radiance)
     eq. 21  G_j = max(0, n_j . -w_j) H(n_x, w_j) / (pi r^2)            (shl_hvl_geometric)
     eq. 19  L_o = L_j (L . F), L = the SH of the unit cap that the sphere subtends at x
             (shl_zh_cap rotated to w_j; shl_hvl_contribution, O(n^2)), or with a ZH lobe F
             about its own axis, shl_zh_dot_zh (shl_hvl_contribution_zh, O(n)).
   H is the fraction of the cap (half-angle a, sin a = s = min(r/d, 1), d = |y - x|) above the
   horizon of n_x, with beta the angle between n_x and w_j. Exact (docs/math.md section 6, two-cap
   intersection), rewritten without cancellation for small caps: with c = cos beta,
   t = c / s, k = cos a / sin beta, both in the crossing range |c| < s,
     H = D / (pi (1 - cos a)) + acos(-t k) / pi,   D = acos(t k) - acos(t)
   where sin D = t (s - c)(s + c) / (sin^2 beta (sqrt(1 - t^2 k^2) + k sqrt(1 - t^2))) and
   cos D = t^2 k + sqrt(1 - t^2 k^2) sqrt(1 - t^2) (no difference of nearly equal angles),
   1 - cos a = s^2 / (1 + cos a); H = 1 for c >= s, 0 for c <= -s (shl_hvl_horizon). The cheap
   variant is [HVL] smoothstep (eq. 22) with the clamp corrected (correction E8 (docs/math.md
   section 12): lower bound pi/2 - a, S clamped to [0, 1]): max abs error 0.039-0.089 against the
   exact H (shl_hvl_horizon_smoothstep). The angles use the own atan2 of >>light. */

/* exact H for the cosine c (in [-1, 1]) between the normal and the axis */
SHLIGHT_INLINE float shli_hvl_h(shli_real c, float r, float d) {
  shli_real q[8];
  shli_real s;
  shli_real al;
  shli_real sb2;
  shli_real t;
  shli_real k;
  shli_real tk;
  shli_real st;
  shli_real stk;
  shli_real sd;
  shli_real cd;
  shli_real hh;
  shli_cap_frame(0.0, 0.0, SHLIGHT_REAL(d), SHLIGHT_REAL(r), q);
  s = SHLIGHT_SQRTR(q[4]);
  al = q[5];
  if (!(SHLIGHT_REAL(d) >= 0.0) || !(s > 0.0)) {
    s = 0.0;
  }
  if (c >= s) {
    if (c > 0.0 || s > 0.0) {
      return 1.0f;
    }
    return 0.5f;
  }
  if (c <= -s) {
    return 0.0f;
  }
  sb2 = (1.0 - c) * (1.0 + c);
  t = c / s;
  k = al / SHLIGHT_SQRTR(sb2);
  tk = t * k;
  st = SHLIGHT_SQRTR((1.0 - t) * (1.0 + t));
  stk = SHLIGHT_SQRTR((1.0 - tk) * (1.0 + tk));
  sd = t * (s - c) * (s + c) / (sb2 * (stk + k * st));
  cd = t * tk + stk * st;
  hh = shli_atan2r(sd, cd) * (1.0 + al) / (3.141592653589793 * s * s) +
       shli_atan2r(stk, -tk) * 0.3183098861837907;
  if (hh < 0.0) {
    hh = 0.0;
  }
  if (hh > 1.0) {
    hh = 1.0;
  }
  return SHLIGHT_FLOAT(hh);
}

SHLIGHT_INLINE float shl_hvl_horizon(const float nrm[3], const float w[3], float r, float d) {
  return shli_hvl_h(shli_cos_between(nrm, w), r, d);
}

/* smoothstep H for the cosine c */
SHLIGHT_INLINE float shli_hvl_hs(shli_real c, float r, float d) {
  shli_real q[8];
  shli_real s;
  shli_real a;
  shli_real be;
  shli_real xx;
  shli_cap_frame(0.0, 0.0, SHLIGHT_REAL(d), SHLIGHT_REAL(r), q);
  s = SHLIGHT_SQRTR(q[4]);
  if (!(SHLIGHT_REAL(d) >= 0.0) || !(s > 0.0)) {
    if (c > 0.0) {
      return 1.0f;
    }
    if (c < 0.0) {
      return 0.0f;
    }
    return 0.5f;
  }
  a = shli_atan2r(s, q[5]);
  be = shli_atan2r(SHLIGHT_SQRTR((1.0 - c) * (1.0 + c)), c);
  if (be < 1.5707963267948966 - a) {
    be = 1.5707963267948966 - a;
  }
  if (be > 1.5707963267948966 + a) {
    be = 1.5707963267948966 + a;
  }
  xx = (1.5707963267948966 + a - be) / (2.0 * a);
  if (xx < 0.0) {
    xx = 0.0;
  }
  if (xx > 1.0) {
    xx = 1.0;
  }
  return SHLIGHT_FLOAT(xx * xx * (3.0 - 2.0 * xx));
}

#ifdef SHLIGHT_REFERENCE_FORMS
SHLIGHT_INLINE float shl_hvl_horizon_smoothstep(const float nrm[3], const float w[3], float r,
                                                float d) {
  return shli_hvl_hs(shli_cos_between(nrm, w), r, d);
}
#endif

SHLIGHT_INLINE float shl_hvl_geometric(const float x[3], const float nrm[3], const float y[3],
                                       const float light_nrm[3], float r, int exact) {
  shli_real g[8];
  shli_real gn[8];
  shli_real cj;
  shli_real cx;
  shli_real hh;
  shli_real rr = SHLIGHT_REAL(r);
  if (!(rr > 0.0)) {
    return 0.0f;
  }
  shli_cap_frame(SHLIGHT_REAL(y[0]) - SHLIGHT_REAL(x[0]), SHLIGHT_REAL(y[1]) - SHLIGHT_REAL(x[1]),
                 SHLIGHT_REAL(y[2]) - SHLIGHT_REAL(x[2]), rr, g);
  if (!(g[6] > 0.0)) {
    return 0.0f;
  }
  shli_cap_frame(SHLIGHT_REAL(light_nrm[0]), SHLIGHT_REAL(light_nrm[1]), SHLIGHT_REAL(light_nrm[2]),
                 1.0, gn);
  cj = -(gn[0] * g[0] + gn[1] * g[1] + gn[2] * g[2]);
  if (!(cj > 0.0)) {
    return 0.0f;
  }
  if (cj > 1.0) {
    cj = 1.0;
  }
  shli_cap_frame(SHLIGHT_REAL(nrm[0]), SHLIGHT_REAL(nrm[1]), SHLIGHT_REAL(nrm[2]), 1.0, gn);
  cx = gn[0] * g[0] + gn[1] * g[1] + gn[2] * g[2];
  if (cx > 1.0) {
    cx = 1.0;
  }
  if (cx < -1.0) {
    cx = -1.0;
  }
  /* d = 1 / g[3] (x == y: g[3] = 0 and d = 1e30 would be wrong; shli_cap_frame then holds
     the inside cap, s = 1, which d = 0 reproduces) */
  hh = 0.0;
  if (g[3] > 0.0) {
    hh = 1.0 / g[3];
  }
  if (exact != 0) {
    hh = SHLIGHT_REAL(shli_hvl_h(cx, r, SHLIGHT_FLOAT(hh)));
  } else {
    hh = SHLIGHT_REAL(shli_hvl_hs(cx, r, SHLIGHT_FLOAT(hh)));
  }
  /* divided by r twice: no overflow of 1 / r^2 before the product (r down to denormals) */
  hh = cj * hh / (3.141592653589793 * rr);
  if (!(hh < SHLIGHT_REAL_MAX * rr)) {
    return SHLIGHT_FLOAT(SHLIGHT_REAL_MAX);
  }
  return SHLIGHT_FLOAT(hh / rr);
}

/* F' . Y(u) for a unit u given in shli_real, n >= 1. */
SHLIGHT_INLINE float shli_hvl_emission_xyz(int n, const float *femit, shli_real ux, shli_real uy,
                                           shli_real uz) {
  float ysh[SHLI_YBUF_COEFFS];
  if (n == 1) {
    return SHLIGHT_FLOAT(0.28209479177387814 * SHLIGHT_REAL(femit[0]));
  }
#if SHLIGHT_MAX_COEFFS > SHLI_YBUF_COEFFS
  if (n * n > SHLI_YBUF_COEFFS) {
    return SHLIGHT_FLOAT(shli_sh_ystream(n, SHLIGHT_FLOAT(ux), SHLIGHT_FLOAT(uy), SHLIGHT_FLOAT(uz),
                                         femit, 0, 0.0f, 0, 1));
  }
#endif
  shli_sh_eval_xyz(n, SHLIGHT_FLOAT(ux), SHLIGHT_FLOAT(uy), SHLIGHT_FLOAT(uz), ysh);
  return shl_sh_dot(n, femit, ysh);
}

SHLIGHT_INLINE float shl_hvl_emission(int n, const float *femit, const float dir[3]) {
  shli_real g[8];
  n = shli_bands(n);
  if (n < 1) {
    return 0.0f;
  }
  shli_cap_frame(SHLIGHT_REAL(dir[0]), SHLIGHT_REAL(dir[1]), SHLIGHT_REAL(dir[2]), 1.0, g);
  return shli_hvl_emission_xyz(n, femit, g[0], g[1], g[2]);
}

SHLIGHT_INLINE float shl_hvl_radiance(int n, const float *femit, float power, const float x[3],
                                      const float nrm[3], const float y[3],
                                      const float light_nrm[3], float r, int exact) {
  shli_real g[8];
  float gj;
  n = shli_bands(n);
  if (n < 1) {
    return 0.0f;
  }
  gj = shl_hvl_geometric(x, nrm, y, light_nrm, r, exact);
  if (!(gj > 0.0f)) {
    return 0.0f;
  }
  shli_cap_frame(SHLIGHT_REAL(x[0]) - SHLIGHT_REAL(y[0]), SHLIGHT_REAL(x[1]) - SHLIGHT_REAL(y[1]),
                 SHLIGHT_REAL(x[2]) - SHLIGHT_REAL(y[2]), 1.0, g);
  return power * shli_hvl_emission_xyz(n, femit, g[0], g[1], g[2]) * gj;
}

/* The cap of HVL j (centre y, radius r) seen from x, shared by the contribution kernels:
   out_g the cap frame of shli_cap_frame (axis w_j = out_g[0..2]), out_zh its ZH (n >= 1 bands,
   shl_zh_cap). Returns 0 (nothing written to out_zh) when the cap is empty: r <= 0, NaN or
   infinite input. */
SHLIGHT_INLINE int shli_hvl_cap(int n, const float x[3], const float y[3], float r, float *out_zh,
                                shli_real *out_g) {
  shli_real dd = 0.0;
  shli_cap_frame(SHLIGHT_REAL(y[0]) - SHLIGHT_REAL(x[0]), SHLIGHT_REAL(y[1]) - SHLIGHT_REAL(x[1]),
                 SHLIGHT_REAL(y[2]) - SHLIGHT_REAL(x[2]), SHLIGHT_REAL(r), out_g);
  if (!(out_g[6] > 0.0)) {
    return 0;
  }
  if (out_g[3] > 0.0) {
    dd = 1.0 / out_g[3];
  }
  shl_zh_cap(n, r, SHLIGHT_FLOAT(dd), out_zh);
  return 1;
}

SHLIGHT_INLINE float shl_hvl_contribution(int n, float lj, const float *fsh, const float x[3],
                                          const float y[3], float r) {
  float zh[SHLIGHT_MAX_BANDS];
  shli_real g[8];
  n = shli_bands(n);
  if (n < 1 || shli_hvl_cap(n, x, y, r, zh, g) == 0) {
    return 0.0f;
  }
  return lj * shli_sh_conv_zh_xyz(n, fsh, zh, g[0], g[1], g[2]);
}

SHLIGHT_INLINE float shl_hvl_contribution_zh(int n, float lj, const float *fzh,
                                             const float faxis[3], const float x[3],
                                             const float y[3], float r) {
  float zh[SHLIGHT_MAX_BANDS];
  shli_real g[8];
  shli_real ga[8];
  shli_real c;
  n = shli_bands(n);
  if (n < 1 || shli_hvl_cap(n, x, y, r, zh, g) == 0) {
    return 0.0f;
  }
  shli_cap_frame(SHLIGHT_REAL(faxis[0]), SHLIGHT_REAL(faxis[1]), SHLIGHT_REAL(faxis[2]), 1.0, ga);
  c = g[0] * ga[0] + g[1] * ga[1] + g[2] * ga[2];
  if (c > 1.0) {
    c = 1.0;
  }
  if (c < -1.0) {
    c = -1.0;
  }
  return lj * shli_zh_dot_c(n, zh, fzh, c);
}

SHLIGHT_INLINE float shl_hvl_radius_neighbours(int count, const float p[3], float dist,
                                               const float (*pn)[3], const float *dn, float eps) {
  shli_real sw = 0.0;
  shli_real sd = 0.0;
  shli_real e = SHLIGHT_REAL(eps);
  shli_real dx;
  shli_real dy;
  shli_real dz;
  shli_real dd;
  shli_real wt;
  int i;
  if (count > 8) {
    count = 8;
  }
  if (!(e >= 1.0e-20)) {
    e = 1.0e-20;
  }
  for (i = 0; i < count; ++i) {
    dx = SHLIGHT_REAL(pn[i][0]) - SHLIGHT_REAL(p[0]);
    dy = SHLIGHT_REAL(pn[i][1]) - SHLIGHT_REAL(p[1]);
    dz = SHLIGHT_REAL(pn[i][2]) - SHLIGHT_REAL(p[2]);
    dd = SHLIGHT_SQRTR(dx * dx + dy * dy + dz * dz);
    wt = 1.0 / (SHLIGHT_ABSR(SHLIGHT_REAL(dist) - SHLIGHT_REAL(dn[i])) + e);
    if (dd <= SHLIGHT_REAL_MAX && wt > 0.0 && wt <= 1.0e21) {
      sw = sw + wt;
      sd = sd + wt * dd;
    }
  }
  if (!(sw > 0.0)) {
    return 0.0f;
  }
  return SHLIGHT_FLOAT(sd / sw);
}

SHLIGHT_INLINE float shl_hvl_radius_fov(float d, float fov, int hvl_count) {
  shli_real dd = SHLIGHT_REAL(d);
  shli_real f = SHLIGHT_REAL(fov);
  shli_real g;
  if (hvl_count < 1) {
    hvl_count = 1;
  }
  if (!(dd >= 0.0) || !(f >= 0.0)) {
    return 0.0f;
  }
  g = 1.4142135623730951 * f / SHLIGHT_SQRTR(SHLIGHT_REAL(SHLIGHT_ITOF(hvl_count)));
  /* d g (1 + g^2 / 3) with the overflow test before the product (float in GLSL) */
  f = 1.0 + g * g / 3.0;
  g = dd * g;
  if (!(g <= SHLIGHT_REAL_MAX / f)) {
    return SHLIGHT_FLOAT(SHLIGHT_REAL_MAX);
  }
  g = g * f;
  if (g > SHLIGHT_REAL_MAX) {
    g = SHLIGHT_REAL_MAX;
  }
  return SHLIGHT_FLOAT(g);
}

SHLIGHT_INLINE float shl_hvl_radius_fov_tan(float d, float fov, int hvl_count) {
  shli_real dd = SHLIGHT_REAL(d);
  shli_real f = SHLIGHT_REAL(fov);
  shli_real g;
  if (hvl_count < 1) {
    hvl_count = 1;
  }
  if (!(dd >= 0.0) || !(f >= 0.0)) {
    return 0.0f;
  }
  g = 1.4142135623730951 * f / SHLIGHT_SQRTR(SHLIGHT_REAL(SHLIGHT_ITOF(hvl_count)));
  if (g > 1.5707) {
    g = 1.5707;
  }
  /* tan g = sin(pi t) / sin(pi (1/2 - t)), t = g / pi in [0, 1/2] */
  g = g * 0.3183098861837907;
  g = shli_sinpi(g) / shli_sinpi(0.5 - g);
  if (g > 1.0 && !(dd <= SHLIGHT_REAL_MAX / g)) {
    return SHLIGHT_FLOAT(SHLIGHT_REAL_MAX);
  }
  g = dd * g;
  if (g > SHLIGHT_REAL_MAX) {
    g = SHLIGHT_REAL_MAX;
  }
  return SHLIGHT_FLOAT(g);
}

/* >>brdftab ---------------------------------------------------------------------------------
   Kautz-style BRDF SH tables ([HVL] sec. 4.2, [KSS02]): for outgoing directions w_o on a
   grid, the SH (n bands, the >>basis convention) of F(w_i) = cos(theta_i) f_s(w_o, w_i) and of
   F'(w_i) = f_s(w_o, w_i), in the local frame (normal +z, tangent +x), w_i over the upper
   hemisphere (both are 0 below it). Built on the CPU (shl_brdf_table_build, the CPU-only part
   of this section after >>grid's CPU declarations); the lookup kernels below have GLSL twins.
   Table layout (the CPU struct shl_brdf_table, the file format and the GPU layout contract):
     data[((p * n_theta + t) * 2 + k) * n^2 + i]
   p < n_phi, t < n_theta, k = 0: F (with the cosine), k = 1: F' (without), i < n^2 the SH
   index. Outgoing grid (SHLT grid 1, the only one): sample t at the theta_o where the grid
   variable u(theta_o) = t / (n_theta - 1) (n_theta = 1: theta_o = 0), with
     U(d) = (pi/2 - d) + c ln((pi/2 + d0) / (d + d0)),  u = U(d) / U(0),  d = pi/2 - theta_o,
   c = 0.05, d0 = 1e-6 (shli_brdf_grid_u): the end samples are theta_o = 0 and 90 degrees; the
   step is uniform in theta_o at normal incidence and uniform in ln(cos theta_o) towards
   grazing, where F' of a microfacet BRDF grows like ln(1 / cos theta_o) (linear in u there,
   so interpolated almost exactly) and where a sharp lobe is cut by the horizon. At 90 samples:
   1.43 deg steps at 0 deg, 1.14 deg at 80 deg, 0.38 deg at 89 deg, then cos theta_o stepping
   by a factor 1.67 (0.05 deg steps at 89.9 deg). The last sample holds F and F' at cos theta_o = d0
   (F' diverges at exactly 90 degrees; shl_brdf_table_theta gives the sample angles). Sample p at
   phi_o = 2 pi p / n_phi (p = 0: phi_o = 0). n_phi = 1: an isotropic table, sampled at phi_o = 0
   ([HVL] eq. 17-18); n_phi > 1: anisotropic, periodic in phi_o. On a GPU the same flat float
   array is an SSBO (std430 float[]), or an RGBA32F texture of n_theta * n_phi * 2 * n^2 / 4 texels
   read linearly (n^2 * 2 floats per sample: whole texels for every n >= 2), in the same order.
   Lookup (shl_brdf_table_cell, shl_brdf_table_lookup): d = atan2(w_z, |w_xy|) (own atan2, see
   >>light; w_z < 0 clamps to the horizon, w_xy = 0 is normal incidence), linear in u between
   the two bracketing samples over the whole range [0, 90] degrees; anisotropic tables also
   linear in phi_o = atan2(w_y, w_x) (periodic). Isotropic tables are rotated about z by phi_o
   (shl_sh_rotate_z): the result is the SH of F in the local frame for that w_o, whatever its
   azimuth. Error: the interpolation error of the tabulated function, O(h^2) in the sample step
   (docs/brdf-tables.md has it against theta_o for each model), plus float rounding. */

/* shli_brdf_grid_u: the table grid variable u in [0, 1] (see >>brdftab) of d = pi/2 - theta_o
   in [0, pi/2]: u(pi/2) = 0 (normal incidence), u(0) = 1 (grazing). */
SHLIGHT_INLINE shli_real shli_brdf_grid_u(shli_real d) {
  return ((1.5707963267948966 - d) +
          0.05 * SHLIGHT_LOGR((1.5707963267948966 + 0.000001) / (d + 0.000001))) *
         0.4377994232697314;
}

SHLIGHT_INLINE void shl_sh_rotate_z(int n, float c1, float s1, float *io_sh) {
  shli_real cm = 1.0;
  shli_real sm = 0.0;
  shli_real t;
  shli_real a;
  shli_real b;
  int l;
  int m;
  int k;
  n = shli_bands(n);
  for (m = 1; m < n; ++m) {
    t = cm * SHLIGHT_REAL(c1) - sm * SHLIGHT_REAL(s1);
    sm = sm * SHLIGHT_REAL(c1) + cm * SHLIGHT_REAL(s1);
    cm = t;
    for (l = m; l < n; ++l) {
      k = l * (l + 1);
      a = SHLIGHT_REAL(io_sh[k + m]);
      b = SHLIGHT_REAL(io_sh[k - m]);
      io_sh[k + m] = SHLIGHT_FLOAT(a * cm - b * sm);
      io_sh[k - m] = SHLIGHT_FLOAT(a * sm + b * cm);
    }
  }
}

SHLIGHT_INLINE void shl_brdf_table_cell(int n_theta, int n_phi, const float wo[3], int *out_idx,
                                        float *out_w) {
  shli_real x = SHLIGHT_REAL(wo[0]);
  shli_real y = SHLIGHT_REAL(wo[1]);
  shli_real z = SHLIGHT_REAL(wo[2]);
  shli_real rho = SHLIGHT_SQRTR(x * x + y * y);
  shli_real u;
  shli_real v;
  float ft = 0.0f;
  float fp = 0.0f;
  int t0 = 0;
  int t1 = 0;
  int p0 = 0;
  int p1 = 0;
  int j;
  for (j = 0; j < 4; ++j) {
    out_idx[j] = 0;
    out_w[j] = 0.0f;
  }
  if (n_theta < 1 || n_phi < 1 || n_theta > 4096 || n_phi > 4096) {
    return;
  }
  if (z < 0.0) {
    z = 0.0;
  }
  if (n_theta > 1) {
    u = 1.5707963267948966;
    if (rho > 0.0) {
      u = shli_atan2r(z, rho);
    }
    u = shli_brdf_grid_u(u) * SHLIGHT_REAL(SHLIGHT_ITOF(n_theta - 1));
    if (!(u > 0.0)) {
      u = 0.0;
    }
    t0 = SHLIGHT_FTOI(u);
    if (t0 > n_theta - 2) {
      t0 = n_theta - 2;
    }
    ft = SHLIGHT_FLOAT(u - SHLIGHT_REAL(SHLIGHT_ITOF(t0)));
    if (ft > 1.0f) {
      ft = 1.0f;
    }
    t1 = t0 + 1;
  }
  if (n_phi > 1) {
    v = shli_atan2r(y, x);
    if (v < 0.0) {
      v = v + 6.2831853071795865;
    }
    v = v * (SHLIGHT_REAL(SHLIGHT_ITOF(n_phi)) * 0.15915494309189534);
    if (!(v > 0.0)) {
      v = 0.0;
    }
    p0 = SHLIGHT_FTOI(v);
    if (p0 > n_phi - 1) {
      p0 = n_phi - 1;
    }
    fp = SHLIGHT_FLOAT(v - SHLIGHT_REAL(SHLIGHT_ITOF(p0)));
    if (fp > 1.0f) {
      fp = 1.0f;
    }
    p1 = p0 + 1;
    if (p1 == n_phi) {
      p1 = 0;
    }
  }
  out_idx[0] = p0 * n_theta + t0;
  out_idx[1] = p0 * n_theta + t1;
  out_idx[2] = p1 * n_theta + t0;
  out_idx[3] = p1 * n_theta + t1;
  out_w[0] = (1.0f - ft) * (1.0f - fp);
  out_w[1] = ft * (1.0f - fp);
  out_w[2] = (1.0f - ft) * fp;
  out_w[3] = ft * fp;
}

SHLIGHT_INLINE void shl_brdf_table_lookup(int n, int n_theta, int n_phi, int which,
                                          const float *tab, const float wo[3], float *out_sh) {
  int idx[4];
  float w[4];
  float rho;
  int nn;
  int i;
  int o0;
  int o1;
  int o2;
  int o3;
  n = shli_bands(n);
  if (n < 1) {
    return;
  }
  nn = n * n;
  if (n_theta < 1 || n_phi < 1 || n_theta > 4096 || n_phi > 4096 ||
      n_theta * n_phi > 1073741823 / nn) {
    for (i = 0; i < nn; ++i) {
      out_sh[i] = 0.0f;
    }
    return;
  }
  if (which != 1) {
    which = 0;
  }
  shl_brdf_table_cell(n_theta, n_phi, wo, idx, w);
  o0 = (2 * idx[0] + which) * nn;
  o1 = (2 * idx[1] + which) * nn;
  o2 = (2 * idx[2] + which) * nn;
  o3 = (2 * idx[3] + which) * nn;
  for (i = 0; i < nn; ++i) {
    out_sh[i] =
        (w[0] * tab[o0 + i] + w[1] * tab[o1 + i]) + (w[2] * tab[o2 + i] + w[3] * tab[o3 + i]);
  }
  if (n_phi == 1) {
    rho = SHLIGHT_FLOAT(SHLIGHT_SQRTR(SHLIGHT_REAL(wo[0]) * SHLIGHT_REAL(wo[0]) +
                                      SHLIGHT_REAL(wo[1]) * SHLIGHT_REAL(wo[1])));
    if (rho > 0.0f) {
      shl_sh_rotate_z(n, wo[0] / rho, wo[1] / rho, out_sh);
    }
  }
}

/* >>ssf -------------------------------------------------------------------------------------
   Screen-space SH filter for instant global illumination with virtual point lights (VPLs):
   [SSF] (Segovia & Wald) on top of instant radiosity (Keller 1997), n x m interleaved
   sampling (Keller & Heidrich 2001) and IGI's discontinuity filter (Wald et al. 2002).
   VPL. A VPL j at y with normal n_y and flux Phi is a cosine emitter: its radiant intensity
   towards the unit direction u is Phi max(0, n_y . u) / pi (the 1/pi makes the emitted flux,
   the intensity integrated over the hemisphere, equal to Phi). Seen from a receiver x, with
   d = |y - x| and w = (y - x) / d, it is a delta of incoming radiance in the direction w,
     L_j(w') = e delta(w' - w),  e = Phi max(0, n_y . -w) / (pi max(d^2, dmin^2))
   (dmin: the clamp distance, the usual bound on the 1/d^2 singularity of VPLs; the paper's
   sec. 3.2 leaves this constant to the VPL generation). So its SH coefficients ([SSF] eq. 1)
   are e Y_i(w) (shl_ssf_vpl_sh) and its irradiance at a normal n is e max(0, n . w)
   (shl_ssf_vpl_irradiance); a Lambertian receiver of albedo kd reflects kd / pi of that.
   A VPL made from a spot light of intensity I (W/sr) through a shadow-map texel of solid angle
   dw that lands on a Lambertian surface of albedo kd has Phi = kd I dw: the texel's footprint
   dA = d^2 dw / cos(theta_in) receives the irradiance I cos(theta_in) / d^2, so the cosines
   cancel (on a normal-mapped surface the irradiance takes the mapped normal's cosine and Phi
   = kd I dw cos(theta_s) / cos(theta_in)). Through a square pinhole image of w x w texels with
   tan(a) on the half-side (a: the cone's half-angle), the texel centred at the image-plane
   point (u, v) (plane at distance 1) has dw ~ (2 tan(a) / w)^2 / (1 + u^2 + v^2)^(3/2) (its
   midpoint value; exactly F(u1, v1) - F(u0, v1) - F(u1, v0) + F(u0, v0) with F(u, v) =
   atan(u v / sqrt(1 + u^2 + v^2)) over its corners); texels outside the cone carry no flux.
   Interleaved sampling ([SSF] sec. 2.3). The VPLs are split into n_int m_int disjoint sets,
   set s holding the VPLs j with j mod (n_int m_int) = s; pixel (px, py) uses set
   s = (py mod m_int) n_int + (px mod n_int) (shl_ssf_interleave), so every n_int x m_int tile
   of pixels uses every VPL exactly once. For sets that are spread over the scene rather than
   clustered, order the VPLs of a w x h shadow map (w, h multiples of n_int, m_int) so that
   texel (tx, ty) is VPL ((ty / m_int) (w / n_int) + tx / n_int) n_int m_int + (ty mod m_int)
   n_int + tx mod n_int: each set is then a regular sub-lattice of the map. A pixel's estimate
   scales the flux of its set by n_int m_int (an unbiased estimate of the sum over all VPLs).
   Filter ([SSF] sec. 3). Per pixel the SH of the incoming radiance of its set (RGB: three
   SH vectors), then the box filter over the n_int x m_int window around the pixel with the
   discontinuity weight of shl_ssf_weight (geometric normals and positions: the filter must not
   look at a normal map), sum w_k L_k / sum w_k; finally the irradiance at the normal-mapped
   normal from the filtered SH (shl_ssf_irradiance, the convolution with the clamped cosine;
   for RGB rotate the cosine once, shl_zh_cosine_power(n, 1) + shl_zh_rotate, and take
   shl_sh_dot per channel). Filtering the irradiance instead (classical IGI) averages values
   that belong to different shading normals and blurs normal-map detail; the SH keep the
   direction until the normal is applied. */

/* The VPL seen from x (see >>ssf): out_g the frame of shli_cap_frame with the unit direction
   w = out_g[0..2] from x to y; returns e, or 0 when the VPL adds nothing. */
SHLIGHT_INLINE shli_real shli_ssf_vpl(const float x[3], const float nx[3], const float y[3],
                                      const float ny[3], float flux, float dmin, shli_real *out_g) {
  shli_real gn[8];
  shli_real f = SHLIGHT_REAL(flux);
  shli_real dm = SHLIGHT_REAL(dmin);
  shli_real cy;
  shli_real id2;
  shli_cap_frame(SHLIGHT_REAL(y[0]) - SHLIGHT_REAL(x[0]), SHLIGHT_REAL(y[1]) - SHLIGHT_REAL(x[1]),
                 SHLIGHT_REAL(y[2]) - SHLIGHT_REAL(x[2]), 1.0, out_g);
  if (!(f > 0.0) || !(f <= SHLIGHT_REAL_MAX) || !(out_g[6] > 0.0) || !(out_g[3] > 0.0)) {
    return 0.0;
  }
  /* below the receiver's geometric plane: the surface itself blocks the VPL */
  if (SHLIGHT_REAL(nx[0]) * out_g[0] + SHLIGHT_REAL(nx[1]) * out_g[1] +
          SHLIGHT_REAL(nx[2]) * out_g[2] <
      0.0) {
    return 0.0;
  }
  shli_cap_frame(SHLIGHT_REAL(ny[0]), SHLIGHT_REAL(ny[1]), SHLIGHT_REAL(ny[2]), 1.0, gn);
  cy = -(gn[0] * out_g[0] + gn[1] * out_g[1] + gn[2] * out_g[2]);
  if (!(cy > 0.0)) {
    return 0.0;
  }
  if (cy > 1.0) {
    cy = 1.0;
  }
  /* 1 / max(d, 1e-18)^2, then the clamp: 1 / max(d^2, dmin^2) without dividing by dmin = 0 */
  id2 = SHLIGHT_MINR(out_g[3], 1.0e18);
  id2 = id2 * id2;
  if (dm > 0.0 && dm * dm * id2 > 1.0) {
    id2 = 1.0 / (dm * dm);
  }
  return f * cy * id2 * 0.3183098861837907;
}

SHLIGHT_INLINE void shl_ssf_vpl_sh(int n, const float x[3], const float nrm[3], const float y[3],
                                   const float light_nrm[3], float flux, float dmin, float *io_sh) {
  float ysh[SHLI_YBUF_COEFFS];
  shli_real g[8];
  float e;
  int nn;
  int i;
  n = shli_bands(n);
  if (n < 1) {
    return;
  }
  e = SHLIGHT_FLOAT(shli_ssf_vpl(x, nrm, y, light_nrm, flux, dmin, g));
  if (!(e > 0.0f)) {
    return;
  }
#if SHLIGHT_MAX_COEFFS > SHLI_YBUF_COEFFS
  if (n * n > SHLI_YBUF_COEFFS) {
    shli_sh_ystream(n, SHLIGHT_FLOAT(g[0]), SHLIGHT_FLOAT(g[1]), SHLIGHT_FLOAT(g[2]), io_sh, 0, e,
                    io_sh, 1);
    return;
  }
#endif
  shli_sh_eval_xyz(n, SHLIGHT_FLOAT(g[0]), SHLIGHT_FLOAT(g[1]), SHLIGHT_FLOAT(g[2]), ysh);
  nn = n * n;
  for (i = 0; i < nn; ++i) {
    io_sh[i] = io_sh[i] + e * ysh[i];
  }
}

SHLIGHT_INLINE float shl_ssf_vpl_irradiance(const float x[3], const float nrm[3],
                                            const float shading_nrm[3], const float y[3],
                                            const float light_nrm[3], float flux, float dmin) {
  shli_real g[8];
  shli_real gs[8];
  shli_real e;
  shli_real c;
  e = shli_ssf_vpl(x, nrm, y, light_nrm, flux, dmin, g);
  if (!(e > 0.0)) {
    return 0.0f;
  }
  shli_cap_frame(SHLIGHT_REAL(shading_nrm[0]), SHLIGHT_REAL(shading_nrm[1]),
                 SHLIGHT_REAL(shading_nrm[2]), 1.0, gs);
  c = gs[0] * g[0] + gs[1] * g[1] + gs[2] * g[2];
  if (!(c > 0.0)) {
    return 0.0f;
  }
  if (c > 1.0) {
    c = 1.0;
  }
  return SHLIGHT_FLOAT(e * c);
}

/* p mod k in [0, k) for any int p and k >= 1, with % on non-negative operands only (GLSL leaves
   % of negative operands undefined). */
SHLIGHT_INLINE int shli_ssf_mod(int p, int k) {
  if (p >= 0) {
    return p % k;
  }
  return (k - 1) - (-1 - p) % k;
}

SHLIGHT_INLINE int shl_ssf_interleave(int px, int py, int tile_x, int tile_y, int nvpl,
                                      int *out_range) {
  int s;
  int st;
  if (tile_x < 1) {
    tile_x = 1;
  }
  if (tile_x > 256) {
    tile_x = 256;
  }
  if (tile_y < 1) {
    tile_y = 1;
  }
  if (tile_y > 256) {
    tile_y = 256;
  }
  st = tile_x * tile_y;
  s = shli_ssf_mod(py, tile_y) * tile_x + shli_ssf_mod(px, tile_x);
  out_range[0] = s;
  out_range[1] = st;
  if (nvpl <= s) {
    return 0;
  }
  return (nvpl - 1 - s) / st + 1;
}

SHLIGHT_INLINE float shl_ssf_weight(const float p[3], const float p_nrm[3], const float q[3],
                                    const float q_nrm[3], float max_dist, float min_cos) {
  shli_real ga[8];
  shli_real gb[8];
  shli_real dx = SHLIGHT_REAL(q[0]) - SHLIGHT_REAL(p[0]);
  shli_real dy = SHLIGHT_REAL(q[1]) - SHLIGHT_REAL(p[1]);
  shli_real dz = SHLIGHT_REAL(q[2]) - SHLIGHT_REAL(p[2]);
  shli_real md = SHLIGHT_REAL(max_dist);
  shli_real c;
  shli_real da;
  shli_real db;
  if (!(SHLIGHT_ABSR(dx) + SHLIGHT_ABSR(dy) + SHLIGHT_ABSR(dz) <= SHLIGHT_REAL_MAX) ||
      !(md >= 0.0)) {
    return 0.0f;
  }
  shli_cap_frame(SHLIGHT_REAL(p_nrm[0]), SHLIGHT_REAL(p_nrm[1]), SHLIGHT_REAL(p_nrm[2]), 1.0, ga);
  shli_cap_frame(SHLIGHT_REAL(q_nrm[0]), SHLIGHT_REAL(q_nrm[1]), SHLIGHT_REAL(q_nrm[2]), 1.0, gb);
  if (!(ga[6] > 0.0) || !(gb[6] > 0.0)) {
    return 0.0f;
  }
  c = ga[0] * gb[0] + ga[1] * gb[1] + ga[2] * gb[2];
  if (c > 1.0) {
    c = 1.0;
  }
  if (!(c >= SHLIGHT_REAL(min_cos)) && !(SHLIGHT_REAL(min_cos) <= -1.0)) {
    return 0.0f;
  }
  da = SHLIGHT_ABSR(ga[0] * dx + ga[1] * dy + ga[2] * dz);
  db = SHLIGHT_ABSR(gb[0] * dx + gb[1] * dy + gb[2] * dz);
  if (da > md || db > md) {
    return 0.0f;
  }
  return 1.0f;
}

SHLIGHT_INLINE float shl_ssf_irradiance(int n, const float *sh, const float nrm[3]) {
  float zh[SHLIGHT_MAX_BANDS];
  n = shli_bands(n);
  if (n < 1) {
    return 0.0f;
  }
  shl_zh_cosine_power(n, 1.0f, zh);
  return shl_sh_conv_zh(n, sh, zh, nrm);
}

#ifdef __cplusplus
extern "C" {
#endif

/* CPU-only part of >>brdftab (declared here, defined with SHLIGHT_IMPLEMENTATION): analytic
   BRDFs, table build by quadrature, the SHLT table file, the MERL measured-BRDF loader.
   Analytic BRDFs (shl_brdf_params.model), w_o, w_i unit, local frame, both above the surface
   (z > 0; f_s = 0 otherwise), kd = diffuse albedo, ks = specular scale:
     SHLIGHT_BRDF_LAMBERT      kd / pi
     SHLIGHT_BRDF_PHONG        kd / pi + ks (e + 1) / (2 pi) max(0, r . w_i)^e, r = the mirror
                               direction of w_o, e = exponent (the lobe of docs/math.md section 5:
   its integral over the sphere is ks, so albedo <= kd + ks) SHLIGHT_BRDF_BLINN_PHONG  kd / pi + ks
   D F G2 / (4 cos_i cos_o), D = (e + 2) / (2 pi) (n.h)^e, G2 with Beckmann's Lambda at alpha =
   sqrt(2 / (e + 2)) (Walter et al. 2007's equivalence) SHLIGHT_BRDF_BECKMANN     kd / pi + ks D F
   G2 / (4 cos_i cos_o), anisotropic Beckmann D (alpha_x, alpha_y) and its exact Smith Lambda (erf)
     SHLIGHT_BRDF_GGX          the same with the anisotropic GGX (Trowbridge-Reitz) D and Lambda
   h = normalise(w_i + w_o); G2 = 1 / (1 + Lambda(w_o) + Lambda(w_i)) (height-correlated
   Smith); F = f0 + (1 - f0) (1 - w_i . h)^5 (Schlick; w_i . h taken as the mean of w_i . h
   and w_o . h, equal for unit input, so that f stays exactly reciprocal for float input a few
   ulp off unit). Alpha is the slope roughness (GGX alpha = roughness^2 in the usual artist
   mapping). All five are reciprocal. Phong, Beckmann and GGX keep albedo <= kd + ks
   (tests/test_brdftab: max 0.981 Phong e = 50, 0.997 GGX alpha 0.05, 1 + 1e-7 Beckmann alpha
   0.05, with ks = 1, f0 = 1); Blinn-Phong does not quite, since Beckmann's Lambda is not its
   own: albedo up to 1.068 ks at e = 10, 1.0015 ks at e = 500 (at cos theta_o = 1e-6). */
/* SHLT file: version written and the only one read (version 1 files, of the cell-centred grid
   of earlier releases, give SHLIGHT_EVERSION: rebuild them); header bytes before the payload;
   the outgoing grid id recorded in the header (1: the grid of >>brdftab, the only one). */
/* cos(theta_o) of the last (90 degree) sample's outgoing direction, in double (F' of the
   microfacet models diverges like ln(1 / cos theta_o) at exactly 90 degrees) */
/* shl_brdf_table_build's parameter domain: Phong / Blinn-Phong exponents up to
   SHLIGHT_BRDF_MAX_EXPONENT, Beckmann / GGX alpha from SHLIGHT_BRDF_MIN_ALPHA to 4 */

#ifdef __cplusplus
}
#endif

#endif /* SHLIGHT_H */

/* ================================== implementation ================================== */
#if defined(SHLIGHT_IMPLEMENTATION) && !defined(SHLIGHT_IMPLEMENTATION_DONE)
#define SHLIGHT_IMPLEMENTATION_DONE

SHLIGHT_API const char *shl_result_string(shl_result r) {
  switch (r) {
  case SHLIGHT_OK:
    return "SHLIGHT_OK: success";
  case SHLIGHT_EINVAL:
    return "SHLIGHT_EINVAL: an invalid argument";
  case SHLIGHT_ENOMEM:
    return "SHLIGHT_ENOMEM: an allocation failed";
  case SHLIGHT_ELENGTH:
    return "SHLIGHT_ELENGTH: loaders: input truncated, or longer than its header says";
  case SHLIGHT_EMAGIC:
    return "SHLIGHT_EMAGIC: loaders: not the expected file type (magic bytes)";
  case SHLIGHT_EVERSION:
    return "SHLIGHT_EVERSION: loaders: unsupported format version";
  case SHLIGHT_EDIMS:
    return "SHLIGHT_EDIMS: loaders: zero, negative, oversized or inconsistent dimensions";
  case SHLIGHT_ENONFINITE:
    return "SHLIGHT_ENONFINITE: NaN or infinity in the data";
  case SHLIGHT_ECHECKSUM:
    return "SHLIGHT_ECHECKSUM: loaders: checksum mismatch";
  case SHLIGHT_ESTORAGE:
    return "SHLIGHT_ESTORAGE: the caller's buffer is missing or too small (size reported)";
  default:
    break;
  }
  return "unknown shl_result";
}

SHLIGHT_API void shli_sh_eval_outline(int n, float dx, float dy, float dz, float *out_y) {
  shli_sh_eval_any(n, dx, dy, dz, out_y);
}

/* SIMD layer of the batch kernels: SHLI_V is one vector of SHLI_W floats. */
#if !defined(SHLIGHT_NO_SIMD) && defined(__AVX512F__)
#include <immintrin.h>
#define SHLI_W 16
typedef __m512 SHLI_V;
#define SHLI_VLOAD(p) _mm512_loadu_ps(p)
#define SHLI_VSTORE(p, v) _mm512_storeu_ps((p), (v))
#define SHLI_VSTREAM(p, v) _mm512_stream_ps((p), (v))
#define SHLI_VSFENCE() _mm_sfence()
#define SHLI_VSET(c) _mm512_set1_ps(c)
#define SHLI_VADD(a, b) _mm512_add_ps((a), (b))
#define SHLI_VMUL(a, b) _mm512_mul_ps((a), (b))
#define SHLI_VDIV(a, b) _mm512_div_ps((a), (b))
#define SHLI_VSQRT(a) _mm512_sqrt_ps(a)
#define SHLI_VMADD(a, b, c) _mm512_fmadd_ps((a), (b), (c))
#define SHLI_VNMADD(a, b, c) _mm512_fnmadd_ps((a), (b), (c))
/* separate multiply and add, never contracted to an FMA (the _round_ forms are builtins, not
   a * b expressions): on Zen 4 a zmm FMA competes with the stores for the register-file read
   ports (bench: 8 FMA + 8 stores take 23 cycles, 8 multiplies + 8 stores 17), and the batch
   kernels of 7..16 bands are store-heavy, so there products and sums stay separate */
#define SHLI_VMULS(a, b) _mm512_mul_round_ps((a), (b), _MM_FROUND_CUR_DIRECTION)
#define SHLI_VMADDS(a, b, c)                                                                       \
  _mm512_add_round_ps(SHLI_VMULS((a), (b)), (c), _MM_FROUND_CUR_DIRECTION)
#define SHLI_VFMS2(a, b, c, d)                                                                     \
  _mm512_sub_round_ps(SHLI_VMULS((a), (b)), SHLI_VMULS((c), (d)), _MM_FROUND_CUR_DIRECTION)
#define SHLI_VFMA2(a, b, c, d)                                                                     \
  _mm512_add_round_ps(SHLI_VMULS((a), (b)), SHLI_VMULS((c), (d)), _MM_FROUND_CUR_DIRECTION)
/* SHLI_VSGN(a): the sign of a in a form that SHLI_VFLIP(v, s) applies to v (v times sign(a),
   bit-exact): the sign bit and a XOR on the SIMD paths, which leaves the multiply pipes free */
#define SHLI_VSGN(a)                                                                               \
  _mm512_castsi512_ps(_mm512_and_si512(_mm512_castps_si512(a), _mm512_set1_epi32((int)0x80000000u)))
#define SHLI_VFLIP(v, s)                                                                           \
  _mm512_castsi512_ps(_mm512_xor_si512(_mm512_castps_si512(v), _mm512_castps_si512(s)))
#define SHLI_VABS(a)                                                                               \
  _mm512_castsi512_ps(_mm512_and_si512(_mm512_castps_si512(a), _mm512_set1_epi32(0x7fffffff)))
#define SHLI_VSIGN1(a)                                                                             \
  _mm512_castsi512_ps(_mm512_or_si512(                                                             \
      _mm512_and_si512(_mm512_castps_si512(a), _mm512_set1_epi32((int)0x80000000u)),               \
      _mm512_castps_si512(_mm512_set1_ps(1.0f))))
#elif !defined(SHLIGHT_NO_SIMD) && defined(__AVX2__) && defined(__FMA__)
#include <immintrin.h>
#define SHLI_W 8
typedef __m256 SHLI_V;
#define SHLI_VLOAD(p) _mm256_loadu_ps(p)
#define SHLI_VSTORE(p, v) _mm256_storeu_ps((p), (v))
#define SHLI_VSTREAM(p, v) _mm256_stream_ps((p), (v))
#define SHLI_VSFENCE() _mm_sfence()
#define SHLI_VSET(c) _mm256_set1_ps(c)
#define SHLI_VADD(a, b) _mm256_add_ps((a), (b))
#define SHLI_VMUL(a, b) _mm256_mul_ps((a), (b))
#define SHLI_VDIV(a, b) _mm256_div_ps((a), (b))
#define SHLI_VSQRT(a) _mm256_sqrt_ps(a)
#define SHLI_VMADD(a, b, c) _mm256_fmadd_ps((a), (b), (c))
#define SHLI_VNMADD(a, b, c) _mm256_fnmadd_ps((a), (b), (c))
#define SHLI_VMULS(a, b) _mm256_mul_ps((a), (b))
#define SHLI_VMADDS(a, b, c) _mm256_fmadd_ps((a), (b), (c))
#define SHLI_VFMS2(a, b, c, d) _mm256_fmsub_ps((a), (b), _mm256_mul_ps((c), (d)))
#define SHLI_VFMA2(a, b, c, d) _mm256_fmadd_ps((a), (b), _mm256_mul_ps((c), (d)))
#define SHLI_VABS(a) _mm256_andnot_ps(_mm256_set1_ps(-0.0f), (a))
#define SHLI_VSGN(a) _mm256_and_ps((a), _mm256_set1_ps(-0.0f))
#define SHLI_VFLIP(v, s) _mm256_xor_ps((v), (s))
#define SHLI_VSIGN1(a) _mm256_or_ps(_mm256_and_ps((a), _mm256_set1_ps(-0.0f)), _mm256_set1_ps(1.0f))
#elif !defined(SHLIGHT_NO_SIMD) && (defined(__SSE2__) || defined(_M_X64))
#include <emmintrin.h>
#define SHLI_W 4
typedef __m128 SHLI_V;
#define SHLI_VLOAD(p) _mm_loadu_ps(p)
#define SHLI_VSTORE(p, v) _mm_storeu_ps((p), (v))
#define SHLI_VSTREAM(p, v) _mm_stream_ps((p), (v))
#define SHLI_VSFENCE() _mm_sfence()
#define SHLI_VSET(c) _mm_set1_ps(c)
#define SHLI_VADD(a, b) _mm_add_ps((a), (b))
#define SHLI_VMUL(a, b) _mm_mul_ps((a), (b))
#define SHLI_VDIV(a, b) _mm_div_ps((a), (b))
#define SHLI_VSQRT(a) _mm_sqrt_ps(a)
#define SHLI_VMADD(a, b, c) _mm_add_ps(_mm_mul_ps((a), (b)), (c))
#define SHLI_VNMADD(a, b, c) _mm_sub_ps((c), _mm_mul_ps((a), (b)))
#define SHLI_VMULS(a, b) _mm_mul_ps((a), (b))
#define SHLI_VMADDS(a, b, c) _mm_add_ps(_mm_mul_ps((a), (b)), (c))
#define SHLI_VFMS2(a, b, c, d) _mm_sub_ps(_mm_mul_ps((a), (b)), _mm_mul_ps((c), (d)))
#define SHLI_VFMA2(a, b, c, d) _mm_add_ps(_mm_mul_ps((a), (b)), _mm_mul_ps((c), (d)))
#define SHLI_VABS(a) _mm_andnot_ps(_mm_set1_ps(-0.0f), (a))
#define SHLI_VSGN(a) _mm_and_ps((a), _mm_set1_ps(-0.0f))
#define SHLI_VFLIP(v, s) _mm_xor_ps((v), (s))
#define SHLI_VSIGN1(a) _mm_or_ps(_mm_and_ps((a), _mm_set1_ps(-0.0f)), _mm_set1_ps(1.0f))
#else
#define SHLI_W 1
typedef float SHLI_V;
#define SHLI_VLOAD(p) (*(p))
#define SHLI_VSTORE(p, v) (*(p) = (v))
#define SHLI_VSTREAM(p, v) (*(p) = (v))
#define SHLI_VSFENCE() ((void)0)
#define SHLI_VSET(c) (c)
#define SHLI_VADD(a, b) ((a) + (b))
#define SHLI_VMUL(a, b) ((a) * (b))
#define SHLI_VDIV(a, b) ((a) / (b))
#define SHLI_VSQRT(a) sqrtf(a)
#define SHLI_VMADD(a, b, c) ((a) * (b) + (c))
#define SHLI_VNMADD(a, b, c) ((c) - (a) * (b))
#define SHLI_VMULS(a, b) ((a) * (b))
#define SHLI_VMADDS(a, b, c) ((a) * (b) + (c))
#define SHLI_VFMS2(a, b, c, d) ((a) * (b) - (c) * (d))
#define SHLI_VFMA2(a, b, c, d) ((a) * (b) + (c) * (d))
#define SHLI_VABS(a) fabsf(a)
#define SHLI_VSIGN1(a) (signbit(a) ? -1.0f : 1.0f)
#define SHLI_VSGN(a) (signbit(a) ? -1.0f : 1.0f)
#define SHLI_VFLIP(v, s) ((v) * (s))
#endif

/* @generated begin batch */
/* clang-format off */
static const float SHLI_SH_BRS[376] = {
    0.2820948f, -0.48860252f, 0.54627424f, -0.5900436f, 0.6258357f, -0.6563821f, 0.6831841f,
    -0.70716274f, 0.72892666f, -0.74890095f, 0.76739514f, -0.7846421f, 0.800822f, -0.8160771f,
    0.83052206f, -0.8442507f, -0.48860252f, 0.48860252f, 0, 1.9364917f, 1.2909944f, 0.6454972f,
    1.0925485f, -1.0925485f, 0, 1.9720266f, 1.183216f, 0.7888106f, 2.09165f, 1.67332f, 0.41833f,
    -1.4453057f, 1.4453057f, 0, 1.9843135f, 1.1338934f, 0.85042006f, 2.04939f, 1.4638501f,
    0.58554006f, 2.291288f, 1.963961f, 0.32732683f, 1.7701308f, -1.7701308f, 0, 1.9899749f,
    1.1055416f, 0.88443327f, 2.0310097f, 1.3540064f, 0.6770032f, 2.1712406f, 1.6887426f,
    0.4824979f, 2.4874685f, 2.2110832f, 0.2763854f, -2.0756624f, 2.0756624f, 0, 1.9930434f,
    1.0871146f, 0.90592885f, 2.021315f, 1.2862914f, 0.7350236f, 2.113942f, 1.5374123f,
    0.57652956f, 2.3013682f, 1.8829378f, 0.4184306f, 2.6739483f, 2.4308622f, 0.24308622f,
    2.366619f, -2.366619f, 0, 1.9948914f, 1.0741723f, 0.92071915f, 2.0155644f, 1.2403474f,
    0.7752171f, 2.081666f, 1.4411534f, 0.6405126f, 2.20794f, 1.6984155f, 0.50952464f, 2.4308622f,
    2.0568833f, 0.3739788f, 2.8504386f, 2.631174f, 0.2192645f, -2.6459606f, 2.6459606f, 0,
    1.9960899f, 1.0645813f, 0.93150866f, 2.0118694f, 1.2071217f, 0.8047478f, 2.0615528f,
    1.3743685f, 0.6871843f, 2.1532216f, 1.5790292f, 0.57419246f, 2.304886f, 1.8439089f,
    0.46097723f, 2.5570416f, 2.2161026f, 0.34093887f, 3.0178044f, 2.8166173f, 0.20118695f,
    2.9157066f, -2.9157066f, 0, 1.9969112f, 1.0571883f, 0.9397229f, 2.0093532f, 1.1819724f,
    0.8273807f, 2.0481224f, 1.3252556f, 0.7228667f, 2.1180441f, 1.49509f, 0.6229542f, 2.2291772f,
    1.7046648f, 0.5245123f, 2.4016364f, 1.9778181f, 0.42381817f, 2.6791375f, 2.3639448f,
    0.31519264f, 3.1770663f, 2.99018f, 0.18688625f, -3.1773176f, 3.1773176f, 0, 1.9974984f,
    1.051315f, 0.94618344f, 2.0075614f, 1.1622725f, 0.84528905f, 2.0386882f, 1.2875926f,
    0.7510957f, 2.0939474f, 1.4327008f, 0.66124654f, 2.1794496f, 1.6059102f, 0.5735393f,
    2.3065126f, 1.820931f, 0.48558158f, 2.4968731f, 2.10263f, 0.39424312f, 2.7970574f, 2.5026302f,
    0.2944271f, 3.329164f, 3.153945f, 0.17521916f, 3.4318953f, -3.4318953f, 0, 1.9979328f,
    1.0465362f, 0.9513966f, 2.0062404f, 1.146423f, 0.85981727f, 2.0317986f, 1.2577801f,
    0.77401847f, 2.0766559f, 1.3844373f, 0.69221866f, 2.144761f, 1.5319722f, 0.61278886f,
    2.2430449f, 1.7089865f, 0.5340583f, 2.3837686f, 1.9297174f, 0.45405117f, 2.590045f,
    2.2200387f, 0.37000644f, 2.9109592f, 2.6337252f, 0.27723423f, 3.47491f, 3.3094382f,
    0.16547191f, -3.6802976f, 3.6802976f, 0, 1.9982631f, 1.042572f, 0.95569104f, 2.0052378f,
    1.1333953f, 0.87184256f, 2.0266087f, 1.2335879f, 0.7930208f, 2.0637972f, 1.3459548f,
    0.7178425f, 2.1194782f, 1.4744196f, 0.6450586f, 2.1981657f, 1.6247312f, 0.57343453f,
    2.3073955f, 1.8057878f, 0.5016077f, 2.4602096f, 2.0323472f, 0.42786255f, 2.6809514f,
    2.331262f, 0.3496893f, 3.0210898f, 2.7583864f, 0.26270348f, 3.614994f, 3.4578204f,
    0.15717365f, 3.9232106f, -3.9232106f, 0, 1.9985201f, 1.0392305f, 0.95928967f, 2.0044594f,
    1.1224972f, 0.8819621f, 2.0225997f, 1.2135597f, 0.80903983f, 2.0539596f, 1.3145342f,
    0.7394255f, 2.1004202f, 1.4282857f, 0.67213446f, 2.1650636f, 1.5588458f, 0.6062178f,
    2.2528179f, 1.7121415f, 0.5406763f, 2.3717082f, 1.8973666f, 0.47434166f, 2.5354629f,
    2.1297886f, 0.40567404f, 2.7695587f, 2.4372115f, 0.33234704f, 3.1277163f, 2.8774989f,
    0.2502173f, 3.75f, 3.6f, 0.15f, -4.1611934f, 4.1611934f, 0, 1.9987241f, 1.0363754f,
    0.96234864f, 2.0038424f, 1.1132458f, 0.8905966f, 2.0194368f, 1.1967033f, 0.8227335f,
    2.0462565f, 1.2883837f, 0.75787276f, 2.0856655f, 1.3904436f, 0.6952218f, 2.1398475f,
    1.5058186f, 0.6340289f, 2.2121823f, 1.6386535f, 0.5735287f, 2.3079278f, 1.7950549f,
    0.5128728f, 2.4355323f, 1.9845079f, 0.45102453f, 2.6093478f, 2.2227776f, 0.38657004f,
    2.8559148f, 2.5385911f, 0.3173239f, 3.231099f, 2.9917583f, 0.23934066f, 3.8804243f,
    3.7367048f, 0.14371942f, 4.3947096f, -4.3947096f, 0, 1.9988886f, 1.0339079f, 0.9649807f,
    2.0033455f, 1.105294f, 0.8980514f, 2.016897f, 1.1823189f, 0.83457804f, 2.040107f, 1.2662734f,
    0.77383375f, 2.07399f, 1.3588212f, 0.715169f, 2.1201415f, 1.4621665f, 0.65797496f, 2.1809661f,
    1.5793204f, 0.6016459f, 2.2600784f, 1.7145423f, 0.54553616f, 2.3630173f, 1.8741173f,
    0.48890013f, 2.4986107f, 2.0678158f, 0.43079495f, 2.6817904f, 2.3118882f, 0.36990213f,
    2.9401073f, 2.6359582f, 0.30414903f, 3.331481f, 3.1017237f, 0.22975731f, 4.006691f, 3.868529f,
    0.13816175f, -4.624151f, 4.624151f, 0
};
/* clang-format on */
/* clang-format off */
static const float SHLI_SH_BPOLY[63] = {
    0.2820948f, 0, 0, 0.48860252f, 0, 0, -0.48860252f, 0, 0, -0.31539157f, 0.9461747f, 0,
    -1.0925485f, 0, 0, 0.54627424f, 0, 0, -1.119529f, 1.8658817f, 0, 0.4570458f, -2.285229f, 0,
    1.4453057f, 0, 0, -0.5900436f, 0, 0, 0.31735665f, -3.1735663f, 3.7024941f, 2.0071397f,
    -4.683326f, 0, -0.47308734f, 3.3116114f, 0, -1.7701308f, 0, 0, 0.6258357f, 0, 0, 1.7542548f,
    -8.1865225f, 7.3678703f, -0.45294666f, 6.3412533f, -9.51188f, -2.3967683f, 7.190305f, 0,
    0.4892383f, -4.403145f, 0, 2.0756624f, 0, 0, -0.6563821f, 0, 0
};
/* clang-format on */
/* @generated end batch */

/* The batch kernels of n <= SHLIGHT_UNROLLED_BANDS, nv = 1 or 2 vectors of directions a call
   (two: independent chains side by side, and the two stores of a row one 128-byte pair of
   lines); output i of lane j of vector v at out[i stride + v SHLI_W + j]; nt: streaming
   (non-temporal) stores, for outputs far larger than the caches.
   n <= SHLI_SH_BPOLY_BANDS: the Horner forms in z^2 times (x + iy)^m, d taken as unit, one
   body instantiated per literal n so that its loops unroll and the table loads fold to
   constants (straight-line code from one source; it pays there: bench/bench_batch.c).
   7..16 bands: the float Reinsch form of the scalar kernel per column m at t = 1 - |z| / |d|
   (X_l^m, then Y = X U, X V with the parity sign folded into U, V by a XOR, SHLI_VFLIP) as a
   loop over run-time n, two bands a trip so that the parity of l - m is fixed in the body;
   products and sums kept apart (SHLI_VMULS, SHLI_VFMS2, SHLI_VMADDS: never FMAs on AVX-512, see
   there); column 0, the longest chain, spread over the others (its band m runs with column m).
   Bit for bit the straight-line kernels this replaces. */
#define SHLI_SH_BPOLY_BANDS 6
#if defined(__clang__)
#define SHLI_UNROLL_BATCH _Pragma("unroll")
#define SHLI_BATCH_INLINE static inline __attribute__((always_inline))
#elif defined(__GNUC__) && __GNUC__ >= 8
#define SHLI_UNROLL_BATCH _Pragma("GCC unroll 16")
#define SHLI_BATCH_INLINE static inline __attribute__((always_inline))
#else
#define SHLI_UNROLL_BATCH
#define SHLI_BATCH_INLINE SHLIGHT_CPU_INLINE
#endif
#define SHLI_BSTORE(p, e)                                                                          \
  do {                                                                                             \
    if (nt)                                                                                        \
      SHLI_VSTREAM((p), (e));                                                                      \
    else                                                                                           \
      SHLI_VSTORE((p), (e));                                                                       \
  } while (0)
SHLI_BATCH_INLINE void shli_sh_batch_poly(int n, int nv, int nt, const float *px, const float *py,
                                          const float *pz, float *out, ptrdiff_t stride) {
  SHLI_V x[2], y[2], z[2], z2[2], pc[2], ps[2], e[2], qc;
  int v, m, l, k;
  SHLI_UNROLL_BATCH
  for (v = 0; v < nv; ++v) {
    x[v] = SHLI_VLOAD(px + v * SHLI_W);
    y[v] = SHLI_VLOAD(py + v * SHLI_W);
    z[v] = SHLI_VLOAD(pz + v * SHLI_W);
    z2[v] = SHLI_VMUL(z[v], z[v]);
    pc[v] = x[v];
    ps[v] = y[v];
  }
  SHLI_UNROLL_BATCH
  for (m = 0; m < n; ++m) {
    SHLI_UNROLL_BATCH
    for (v = 0; v < nv; ++v) {
      if (m == 2) {
        pc[v] = SHLI_VNMADD(y[v], y[v], SHLI_VMUL(x[v], x[v]));
        ps[v] = SHLI_VMUL(SHLI_VADD(x[v], x[v]), y[v]);
      } else if (m >= 3) {
        qc = SHLI_VNMADD(y[v], ps[v], SHLI_VMUL(x[v], pc[v]));
        ps[v] = SHLI_VMADD(x[v], ps[v], SHLI_VMUL(y[v], pc[v]));
        pc[v] = qc;
      }
    }
    SHLI_UNROLL_BATCH
    for (l = m; l < n; ++l) {
      const float *c = SHLI_SH_BPOLY + 3 * ((l * (l + 1)) / 2 + m);
      float *po = out + (ptrdiff_t)(l * (l + 1) + m) * stride;
      float *pq = out + (ptrdiff_t)(l * (l + 1) - m) * stride;
      int top = (l - m) / 2;
      SHLI_UNROLL_BATCH
      for (v = 0; v < nv; ++v) {
        e[v] = SHLI_VSET(c[top]);
        SHLI_UNROLL_BATCH
        for (k = top - 1; k >= 0; --k)
          e[v] = c[k] != 0.0f ? SHLI_VMADD(e[v], z2[v], SHLI_VSET(c[k])) : SHLI_VMUL(e[v], z2[v]);
        if ((l - m) & 1) e[v] = SHLI_VMUL(e[v], z[v]);
      }
      SHLI_UNROLL_BATCH
      for (v = 0; v < nv; ++v)
        SHLI_BSTORE(po + v * SHLI_W, m ? SHLI_VMUL(e[v], pc[v]) : e[v]);
      if (m > 0) {
        SHLI_UNROLL_BATCH
        for (v = 0; v < nv; ++v)
          SHLI_BSTORE(pq + v * SHLI_W, SHLI_VMUL(e[v], ps[v]));
      }
    }
  }
}
#if !SHLIGHT_BATCH_COMPACT
/* 7..16 bands unrolled (instantiated per literal n: the constants fold, the straight-line code
   the decode-bound kernel needs): the loop below with every band of every column spelled out */
#define SHLI_BSTOREI(i, v, e) SHLI_VSTORE(out + (ptrdiff_t)(i)*stride + (v)*SHLI_W, (e))
/* one Reinsch step (band l, column m) of vector v: from the state xa, dd of band l - 1 */
#define SHLI_BSTEPU(l, m, v, xa, dd)                                                               \
  do {                                                                                             \
    const float *c_ = SHLI_SH_BRS + 16 + 3 * (((l) * ((l)-1)) / 2 + (m));                          \
    if ((l) == (m) + 1) {                                                                          \
      (dd) = SHLI_VMULS(SHLI_VSET(c_[0]), t[v]);                                                   \
      (xa) = SHLI_VADD(SHLI_VSET(c_[1]), (dd));                                                    \
    } else {                                                                                       \
      SHLI_V e_ = SHLI_VMULS(t[v], (xa));                                                          \
      (dd) = SHLI_VFMS2(SHLI_VSET(c_[2]), (dd), SHLI_VSET(c_[0]), e_);                             \
      (xa) = SHLI_VMADDS(SHLI_VSET(c_[1]), (xa), (dd));                                            \
    }                                                                                              \
  } while (0)
/* the column-0 steps due before unit u of the other columns */
#define SHLI_COL0()                                                                                \
  while (s0 < n - 1 && s0 * nu < (n - 1) * u) {                                                    \
    ++s0;                                                                                          \
    SHLI_UNROLL_BATCH                                                                              \
    for (v = 0; v < nv; ++v)                                                                       \
      SHLI_BSTEPU(s0, 0, v, x0[v], d0[v]);                                                         \
    SHLI_UNROLL_BATCH                                                                              \
    for (v = 0; v < nv; ++v)                                                                       \
      SHLI_BSTOREI(s0 *(s0 + 1), v, (s0 & 1) ? SHLI_VFLIP(x0[v], sg[v]) : x0[v]);                  \
  }
SHLI_BATCH_INLINE void shli_sh_batch_rsu(int n, int nv, const float *px, const float *py,
                                         const float *pz, float *out, ptrdiff_t stride) {
  SHLI_V x[2], y[2], t[2], sg[2], pc[2], ps[2], gc[2], gs[2], xa[2], dd[2], x0[2], d0[2], qc;
  int v, m, l, s0 = 0, u = 0, nu = (n * (n - 1)) / 2; /* column 0: steps done; other units */
  SHLI_UNROLL_BATCH
  for (v = 0; v < nv; ++v) {
    SHLI_V z = SHLI_VLOAD(pz + v * SHLI_W), s2, ir, az;
    x[v] = SHLI_VLOAD(px + v * SHLI_W);
    y[v] = SHLI_VLOAD(py + v * SHLI_W);
    s2 = SHLI_VMADD(x[v], x[v], SHLI_VMUL(y[v], y[v]));
    ir = SHLI_VDIV(SHLI_VSET(1.0f), SHLI_VSQRT(SHLI_VMADD(z, z, s2)));
    az = SHLI_VMUL(SHLI_VABS(z), ir);
    t[v] = SHLI_VDIV(SHLI_VMUL(s2, SHLI_VMUL(ir, ir)), SHLI_VADD(SHLI_VSET(1.0f), az));
    sg[v] = SHLI_VSGN(z);
    x[v] = SHLI_VMUL(x[v], ir);
    y[v] = SHLI_VMUL(y[v], ir);
    pc[v] = x[v];
    ps[v] = y[v];
    x0[v] = t[v];
    d0[v] = t[v];
    SHLI_BSTOREI(0, v, SHLI_VSET(SHLI_SH_BRS[0]));
  }
  /* column 0 (the longest chain) is spread evenly over the nu steps of the other columns
     (their first rows count as one): its step s0 + 1 runs once s0 / (n - 1) < u / nu */
  SHLI_UNROLL_BATCH
  for (m = 1; m < n; ++m) {
    const float k = SHLI_SH_BRS[m];
    SHLI_COL0();
    SHLI_UNROLL_BATCH
    for (v = 0; v < nv; ++v) {
      if (m >= 2) {
        qc = SHLI_VFMS2(x[v], pc[v], y[v], ps[v]);
        ps[v] = SHLI_VFMA2(x[v], ps[v], y[v], pc[v]);
        pc[v] = qc;
      }
      gc[v] = SHLI_VFLIP(pc[v], sg[v]);
      gs[v] = SHLI_VFLIP(ps[v], sg[v]);
    }
    SHLI_UNROLL_BATCH
    for (v = 0; v < nv; ++v)
      SHLI_BSTOREI(m * m + 2 * m, v, SHLI_VMULS(SHLI_VSET(k), pc[v]));
    SHLI_UNROLL_BATCH
    for (v = 0; v < nv; ++v)
      SHLI_BSTOREI(m * m, v, SHLI_VMULS(SHLI_VSET(k), ps[v]));
    ++u;
    SHLI_UNROLL_BATCH
    for (l = m + 1; l < n; ++l) {
      SHLI_COL0();
      ++u;
      SHLI_UNROLL_BATCH
      for (v = 0; v < nv; ++v) /* the vectors' statements alternate: independent chains */
        SHLI_BSTEPU(l, m, v, xa[v], dd[v]);
      /* the vectors' stores to one row are adjacent (one 128-byte pair of lines) */
      SHLI_UNROLL_BATCH
      for (v = 0; v < nv; ++v)
        SHLI_BSTOREI(l * (l + 1) + m, v, SHLI_VMULS(xa[v], ((l - m) & 1) ? gc[v] : pc[v]));
      SHLI_UNROLL_BATCH
      for (v = 0; v < nv; ++v)
        SHLI_BSTOREI(l * (l + 1) - m, v, SHLI_VMULS(xa[v], ((l - m) & 1) ? gs[v] : ps[v]));
    }
  }
  u = nu;
  SHLI_COL0();
}
#undef SHLI_BSTEPU
#undef SHLI_COL0
#endif
#undef SHLI_BSTOREI
/* one Reinsch step of every vector: X~, D~ of the previous band to this one's (constants c) */
#define SHLI_BSTEP(c, xa, dd)                                                                      \
  do {                                                                                             \
    SHLI_UNROLL_BATCH                                                                              \
    for (v = 0; v < nv; ++v) {                                                                     \
      SHLI_V e_ = SHLI_VMULS(t[v], (xa)[v]);                                                       \
      (dd)[v] = SHLI_VFMS2(SHLI_VSET((c)[2]), (dd)[v], SHLI_VSET((c)[0]), e_);                     \
      (xa)[v] = SHLI_VMADDS(SHLI_VSET((c)[1]), (xa)[v], (dd)[v]);                                  \
    }                                                                                              \
  } while (0)
/* rows l (l + 1) + m (at po) and - m (at pq) of band l, then po, pq to band l + 1 */
#define SHLI_BROWS(cu, su)                                                                         \
  do {                                                                                             \
    SHLI_UNROLL_BATCH                                                                              \
    for (v = 0; v < nv; ++v)                                                                       \
      SHLI_BSTORE(po + v * SHLI_W, SHLI_VMULS(xa[v], (cu)[v]));                                    \
    SHLI_UNROLL_BATCH                                                                              \
    for (v = 0; v < nv; ++v)                                                                       \
      SHLI_BSTORE(pq + v * SHLI_W, SHLI_VMULS(xa[v], (su)[v]));                                    \
    po += dl;                                                                                      \
    pq += dl;                                                                                      \
    dl += 2 * stride;                                                                              \
  } while (0)
SHLI_BATCH_INLINE void shli_sh_batch_rs(int n, int nv, int nt, const float *px, const float *py,
                                        const float *pz, float *out, ptrdiff_t stride) {
  SHLI_V x[2], y[2], t[2], sg[2], pc[2], ps[2], gc[2], gs[2], xa[2], dd[2], x0[2], d0[2], qc;
  const float *c;
  float *po, *pq;
  ptrdiff_t dl;
  int v, m, l;
  SHLI_UNROLL_BATCH
  for (v = 0; v < nv; ++v) {
    SHLI_V z = SHLI_VLOAD(pz + v * SHLI_W), s2, ir, az;
    x[v] = SHLI_VLOAD(px + v * SHLI_W);
    y[v] = SHLI_VLOAD(py + v * SHLI_W);
    s2 = SHLI_VMADD(x[v], x[v], SHLI_VMUL(y[v], y[v]));
    ir = SHLI_VDIV(SHLI_VSET(1.0f), SHLI_VSQRT(SHLI_VMADD(z, z, s2)));
    az = SHLI_VMUL(SHLI_VABS(z), ir);
    t[v] = SHLI_VDIV(SHLI_VMUL(s2, SHLI_VMUL(ir, ir)), SHLI_VADD(SHLI_VSET(1.0f), az));
    sg[v] = SHLI_VSGN(z);
    x[v] = SHLI_VMUL(x[v], ir);
    y[v] = SHLI_VMUL(y[v], ir);
    pc[v] = x[v];
    ps[v] = y[v];
    SHLI_BSTORE(out + v * SHLI_W, SHLI_VSET(SHLI_SH_BRS[0]));
    d0[v] = SHLI_VMULS(SHLI_VSET(SHLI_SH_BRS[16]), t[v]); /* column 0, band 1 */
    x0[v] = SHLI_VADD(SHLI_VSET(SHLI_SH_BRS[17]), d0[v]);
  }
  for (m = 1; m < n; ++m) {
    const float k = SHLI_SH_BRS[m];
    c = SHLI_SH_BRS + 16 + 3 * ((m * (m - 1)) / 2);
    if (m > 1) SHLI_BSTEP(c, x0, d0);
    po = out + (ptrdiff_t)(m * (m + 1)) * stride;
    SHLI_UNROLL_BATCH
    for (v = 0; v < nv; ++v)
      SHLI_BSTORE(po + v * SHLI_W, (m & 1) ? SHLI_VFLIP(x0[v], sg[v]) : x0[v]);
    SHLI_UNROLL_BATCH
    for (v = 0; v < nv; ++v) {
      if (m >= 2) {
        qc = SHLI_VFMS2(x[v], pc[v], y[v], ps[v]);
        ps[v] = SHLI_VFMA2(x[v], ps[v], y[v], pc[v]);
        pc[v] = qc;
      }
      gc[v] = SHLI_VFLIP(pc[v], sg[v]);
      gs[v] = SHLI_VFLIP(ps[v], sg[v]);
    }
    po = out + (ptrdiff_t)(m * m + 2 * m) * stride;
    pq = out + (ptrdiff_t)(m * m) * stride;
    SHLI_UNROLL_BATCH
    for (v = 0; v < nv; ++v)
      SHLI_BSTORE(po + v * SHLI_W, SHLI_VMULS(SHLI_VSET(k), pc[v]));
    SHLI_UNROLL_BATCH
    for (v = 0; v < nv; ++v)
      SHLI_BSTORE(pq + v * SHLI_W, SHLI_VMULS(SHLI_VSET(k), ps[v]));
    if (m + 1 >= n) break;
    /* band m + 1 (l - m odd): the first step of the column */
    c = SHLI_SH_BRS + 16 + 3 * (((m + 1) * m) / 2 + m);
    SHLI_UNROLL_BATCH
    for (v = 0; v < nv; ++v) {
      dd[v] = SHLI_VMULS(SHLI_VSET(c[0]), t[v]);
      xa[v] = SHLI_VADD(SHLI_VSET(c[1]), dd[v]);
    }
    po = out + (ptrdiff_t)((m + 1) * (m + 2) + m) * stride;
    pq = out + (ptrdiff_t)((m + 1) * (m + 2) - m) * stride;
    dl = (ptrdiff_t)(2 * m + 4) * stride;
    SHLI_BROWS(gc, gs);
    for (l = m + 2; l + 1 < n; l += 2) {
      c += 3 * (l - 1);
      SHLI_BSTEP(c, xa, dd);
      SHLI_BROWS(pc, ps);
      c += 3 * l;
      SHLI_BSTEP(c, xa, dd);
      SHLI_BROWS(gc, gs);
    }
    if (l < n) {
      c += 3 * (l - 1);
      SHLI_BSTEP(c, xa, dd);
      SHLI_BROWS(pc, ps);
    }
  }
}
#undef SHLI_BSTEP
#undef SHLI_BROWS
#undef SHLI_BSTORE
typedef void (*shli_sh_batch_fn)(const float *, const float *, const float *, float *, ptrdiff_t);
/* [0]: one vector, [1]: two, [2]: two with streaming stores */
#define SHLI_SH_BATCH_N(N)                                                                         \
  static void shli_sh_batch1_##N(const float *x, const float *y, const float *z, float *out,       \
                                 ptrdiff_t stride) {                                               \
    shli_sh_batch_poly((N), 1, 0, x, y, z, out, stride);                                           \
  }                                                                                                \
  static void shli_sh_batch2_##N(const float *x, const float *y, const float *z, float *out,       \
                                 ptrdiff_t stride) {                                               \
    shli_sh_batch_poly((N), 2, 0, x, y, z, out, stride);                                           \
  }                                                                                                \
  static void shli_sh_batch2s_##N(const float *x, const float *y, const float *z, float *out,      \
                                  ptrdiff_t stride) {                                              \
    shli_sh_batch_poly((N), 2, 1, x, y, z, out, stride);                                           \
  }
SHLI_SH_BATCH_N(1)
SHLI_SH_BATCH_N(2)
SHLI_SH_BATCH_N(3)
SHLI_SH_BATCH_N(4)
SHLI_SH_BATCH_N(5)
SHLI_SH_BATCH_N(6)
#undef SHLI_SH_BATCH_N
static const shli_sh_batch_fn SHLI_SH_BATCHP[3][SHLI_SH_BPOLY_BANDS + 1] = {
    {0, shli_sh_batch1_1, shli_sh_batch1_2, shli_sh_batch1_3, shli_sh_batch1_4, shli_sh_batch1_5,
     shli_sh_batch1_6},
    {0, shli_sh_batch2_1, shli_sh_batch2_2, shli_sh_batch2_3, shli_sh_batch2_4, shli_sh_batch2_5,
     shli_sh_batch2_6},
    {0, shli_sh_batch2s_1, shli_sh_batch2s_2, shli_sh_batch2s_3, shli_sh_batch2s_4,
     shli_sh_batch2s_5, shli_sh_batch2s_6}};
/* 7..16 bands: unrolled (or, SHLIGHT_BATCH_COMPACT, the loop), one or two vectors a call
   ([n - 7]); the loop form with streaming stores (memory-bound there: unrolling would not pay) */
#if SHLIGHT_BATCH_COMPACT
static void shli_sh_batch_rs1(int n, const float *x, const float *y, const float *z, float *out,
                              ptrdiff_t stride) {
  shli_sh_batch_rs(n, 1, 0, x, y, z, out, stride);
}
static void shli_sh_batch_rs2(int n, const float *x, const float *y, const float *z, float *out,
                              ptrdiff_t stride) {
  shli_sh_batch_rs(n, 2, 0, x, y, z, out, stride);
}
#define SHLI_SH_BATCH_N(N)                                                                         \
  static void shli_sh_batch1_##N(const float *x, const float *y, const float *z, float *out,       \
                                 ptrdiff_t stride) {                                               \
    shli_sh_batch_rs1((N), x, y, z, out, stride);                                                  \
  }                                                                                                \
  static void shli_sh_batch2_##N(const float *x, const float *y, const float *z, float *out,       \
                                 ptrdiff_t stride) {                                               \
    shli_sh_batch_rs2((N), x, y, z, out, stride);                                                  \
  }
#else
#define SHLI_SH_BATCH_N(N)                                                                         \
  static void shli_sh_batch1_##N(const float *x, const float *y, const float *z, float *out,       \
                                 ptrdiff_t stride) {                                               \
    shli_sh_batch_rsu((N), 1, x, y, z, out, stride);                                               \
  }                                                                                                \
  static void shli_sh_batch2_##N(const float *x, const float *y, const float *z, float *out,       \
                                 ptrdiff_t stride) {                                               \
    shli_sh_batch_rsu((N), 2, x, y, z, out, stride);                                               \
  }
#endif
SHLI_SH_BATCH_N(7)
SHLI_SH_BATCH_N(8)
SHLI_SH_BATCH_N(9)
SHLI_SH_BATCH_N(10)
SHLI_SH_BATCH_N(11)
SHLI_SH_BATCH_N(12)
SHLI_SH_BATCH_N(13)
SHLI_SH_BATCH_N(14)
SHLI_SH_BATCH_N(15)
SHLI_SH_BATCH_N(16)
#undef SHLI_SH_BATCH_N
static const shli_sh_batch_fn SHLI_SH_BATCHR[2][10] = {
    {shli_sh_batch1_7, shli_sh_batch1_8, shli_sh_batch1_9, shli_sh_batch1_10, shli_sh_batch1_11,
     shli_sh_batch1_12, shli_sh_batch1_13, shli_sh_batch1_14, shli_sh_batch1_15, shli_sh_batch1_16},
    {shli_sh_batch2_7, shli_sh_batch2_8, shli_sh_batch2_9, shli_sh_batch2_10, shli_sh_batch2_11,
     shli_sh_batch2_12, shli_sh_batch2_13, shli_sh_batch2_14, shli_sh_batch2_15,
     shli_sh_batch2_16}};
static void shli_sh_batch_rs2s(int n, const float *x, const float *y, const float *z, float *out,
                               ptrdiff_t stride) {
  shli_sh_batch_rs(n, 2, 1, x, y, z, out, stride);
}
/* one vector of directions, n <= SHLIGHT_UNROLLED_BANDS */
static void shli_sh_batch_vec1(int n, const float *x, const float *y, const float *z, float *out,
                               ptrdiff_t stride) {
  if (n <= SHLI_SH_BPOLY_BANDS)
    SHLI_SH_BATCHP[0][n](x, y, z, out, stride);
  else
    SHLI_SH_BATCHR[0][n - 7](x, y, z, out, stride);
}
/* streaming stores from this much output on (bytes; bench/bench_batch.c: below it the rows
   stay in the caches and plain stores win) */
#define SHLI_BATCH_STREAM_BYTES (256.0 * 1024.0)

/* Batch loop for n > SHLIGHT_UNROLLED_BANDS: the generated kernels' math with table constants. */
static void shli_sh_batch_loop(int n, SHLI_V x, SHLI_V y, SHLI_V z, float *out, ptrdiff_t stride) {
  SHLI_V s2 = SHLI_VMADD(x, x, SHLI_VMUL(y, y));
  SHLI_V ir = SHLI_VDIV(SHLI_VSET(1.0f), SHLI_VSQRT(SHLI_VMADD(z, z, s2)));
  SHLI_V az = SHLI_VMUL(SHLI_VABS(z), ir);
  SHLI_V t = SHLI_VDIV(SHLI_VMUL(s2, SHLI_VMUL(ir, ir)), SHLI_VADD(SHLI_VSET(1.0f), az));
  SHLI_V sg = SHLI_VSIGN1(z);
  SHLI_V pc = SHLI_VSET(1.0f), ps = SHLI_VSET(0.0f), ec, es, oc, os, sw, xa, dd, k;
  int m, l, j;
  ptrdiff_t b;
  x = SHLI_VMUL(x, ir);
  y = SHLI_VMUL(y, ir);
  for (m = 0; m < n; ++m) {
    if (m > 0) {
      SHLI_V qc = SHLI_VNMADD(y, ps, SHLI_VMUL(x, pc));
      ps = SHLI_VMADD(x, ps, SHLI_VMUL(y, pc));
      pc = qc;
    }
    ec = pc;
    es = ps;
    oc = SHLI_VMUL(sg, pc);
    os = SHLI_VMUL(sg, ps);
    k = SHLI_VSET(SHLI_SH_DIAG[m]);
    SHLI_VSTORE(out + (ptrdiff_t)(m * m + 2 * m) * stride, SHLI_VMUL(k, ec));
    if (m > 0) SHLI_VSTORE(out + (ptrdiff_t)(m * m) * stride, SHLI_VMUL(k, es));
    xa = k;
    dd = SHLI_VSET(0.0f);
    for (l = m + 1; l < n; ++l) {
      j = 3 * ((l * (l - 1)) / 2 + m);
      dd = SHLI_VNMADD(SHLI_VSET((float)SHLI_SH_TAB[j]), SHLI_VMUL(t, xa),
                       SHLI_VMUL(SHLI_VSET((float)SHLI_SH_TAB[j + 2]), dd));
      xa = SHLI_VMADD(SHLI_VSET((float)SHLI_SH_TAB[j + 1]), xa, dd);
      sw = ec;
      ec = oc;
      oc = sw;
      sw = es;
      es = os;
      os = sw;
      b = (ptrdiff_t)l * (l + 1);
      SHLI_VSTORE(out + (b + m) * stride, SHLI_VMUL(xa, ec));
      if (m > 0) SHLI_VSTORE(out + (b - m) * stride, SHLI_VMUL(xa, es));
    }
  }
}

SHLIGHT_API void shl_sh_eval_batch(int n, int count, const float *x, const float *y, const float *z,
                                   float *out_y) {
  int j;
  n = shli_bands(n);
  if (n < 1 || count <= 0) return;
  if (count < SHLI_W) {          /* too few for one vector: the scalar kernel, strided */
    float tmp[SHLI_YBUF_COEFFS]; /* <= 8 KB; more bands streamed (16 KB stack rule) */
    int i;
#if SHLIGHT_MAX_COEFFS > SHLI_YBUF_COEFFS
    if (n * n > SHLI_YBUF_COEFFS) {
      for (j = 0; j < count; ++j)
        shli_sh_ystream(n, x[j], y[j], z[j], NULL, NULL, 0.0f, out_y + j, (ptrdiff_t)count);
      return;
    }
#endif
    for (j = 0; j < count; ++j) {
      float d[3];
      d[0] = x[j];
      d[1] = y[j];
      d[2] = z[j];
      shl_sh_eval(n, d, tmp);
      for (i = 0; i < n * n; ++i)
        out_y[(ptrdiff_t)i * count + j] = tmp[i];
    }
    return;
  }
  if (n <= SHLIGHT_UNROLLED_BANDS && count >= 2 * SHLI_W) {
    /* two vectors a call, the last pair overlapping the previous one (the same values
       rewritten). An output far larger than the caches (rows count floats apart, written once
       and not read back here) goes out by streaming stores: count a multiple of SHLI_W puts
       every row at the same alignment, so the pairs from j0 on are aligned; the vectors before
       j0 and after the last pair are plain (overlapping) stores */
    int nt = count % SHLI_W == 0 && (size_t)out_y % sizeof(float) == 0 &&
             (double)count * (double)(n * n) * sizeof(float) >= SHLI_BATCH_STREAM_BYTES;
    int j0 =
        nt ? (int)((((size_t)0 - (size_t)out_y) % (sizeof(float) * SHLI_W)) / sizeof(float)) : 0;
    if (nt) {
      if (j0 > 0) shli_sh_batch_vec1(n, x, y, z, out_y, (ptrdiff_t)count);
      for (j = j0; j + 2 * SHLI_W <= count; j += 2 * SHLI_W) {
        if (n <= SHLI_SH_BPOLY_BANDS)
          SHLI_SH_BATCHP[2][n](x + j, y + j, z + j, out_y + j, (ptrdiff_t)count);
        else
          shli_sh_batch_rs2s(n, x + j, y + j, z + j, out_y + j, (ptrdiff_t)count);
      }
      SHLI_VSFENCE();
      for (; j < count; j += SHLI_W) {
        if (j > count - SHLI_W) j = count - SHLI_W;
        shli_sh_batch_vec1(n, x + j, y + j, z + j, out_y + j, (ptrdiff_t)count);
      }
      return;
    }
    for (j = 0;; j += 2 * SHLI_W) {
      if (j > count - 2 * SHLI_W) j = count - 2 * SHLI_W;
      if (n <= SHLI_SH_BPOLY_BANDS)
        SHLI_SH_BATCHP[1][n](x + j, y + j, z + j, out_y + j, (ptrdiff_t)count);
      else
        SHLI_SH_BATCHR[1][n - 7](x + j, y + j, z + j, out_y + j, (ptrdiff_t)count);
      if (j + 2 * SHLI_W >= count) break;
    }
    return;
  }
  for (j = 0;; j += SHLI_W) {
    /* the last vector overlaps the previous one instead of running a scalar tail: the
       overlapping lanes are computed twice and written with the same values */
    if (j > count - SHLI_W) j = count - SHLI_W;
    if (n <= SHLIGHT_UNROLLED_BANDS)
      shli_sh_batch_vec1(n, x + j, y + j, z + j, out_y + j, (ptrdiff_t)count);
    else
      shli_sh_batch_loop(n, SHLI_VLOAD(x + j), SHLI_VLOAD(y + j), SHLI_VLOAD(z + j), out_y + j,
                         (ptrdiff_t)count);
    if (j + SHLI_W >= count) break;
  }
}

/* The accurate path: the Reinsch-form recurrence of the kernels, all in double, one rounding
   per output (Y = X U formed in double). */
static void shli_sh_core_accurate(int n, double x, double y, double t, double sg, float *out_y) {
  double pc = 1.0, ps = 0.0, ec, es, oc, os, sw, xa, dd, xm = 0.28209479177387814;
  int m, l, j, b;
  for (m = 0; m < n; ++m) {
    if (m > 0) {
      double qc = x * pc - y * ps;
      ps = x * ps + y * pc;
      pc = qc;
      xm *= -sqrt((2.0 * m + 1.0) / (2.0 * m)) * (m == 1 ? 1.4142135623730951 : 1.0);
    }
    ec = pc;
    es = ps;
    oc = sg * ec;
    os = sg * es;
    xa = xm;
    out_y[m * m + 2 * m] = (float)(xa * ec);
    if (m > 0) out_y[m * m] = (float)(xa * es);
    dd = 0.0;
    for (l = m + 1; l < n; ++l) {
      j = 3 * ((l * (l - 1)) / 2 + m);
      dd = SHLI_SH_TAB[j + 2] * dd - (SHLI_SH_TAB[j] * t) * xa;
      xa = SHLI_SH_TAB[j + 1] * xa + dd;
      sw = ec, ec = oc, oc = sw;
      sw = es, es = os, os = sw;
      b = l * (l + 1);
      out_y[b + m] = (float)(xa * ec);
      if (m > 0) out_y[b - m] = (float)(xa * es);
    }
  }
}

SHLIGHT_API void shl_sh_eval_accurate(int n, const float d[3], float *out_y) {
  double x = (double)d[0], y = (double)d[1], z = (double)d[2];
  double mx = fabs(x) > fabs(y) ? fabs(x) : fabs(y);
  double r, ir;
  n = shli_bands(n);
  if (n < 1) return;
  mx = fabs(z) > mx ? fabs(z) : mx;
  if (!(fabs(x) + fabs(y) + fabs(z) > 0.0 && mx <= SHLIGHT_REAL_MAX)) {
    /* zero, NaN (the sum is NaN) or infinite: Y(0,0,1) */
    x = 0.0;
    y = 0.0;
    z = 1.0;
    mx = 1.0;
  }
  x /= mx;
  y /= mx;
  z /= mx;
  r = sqrt(x * x + y * y + z * z);
  ir = 1.0 / r;
  x *= ir;
  y *= ir;
  z *= ir;
  shli_sh_core_accurate(n, x, y, (x * x + y * y) / (1.0 + fabs(z)), copysign(1.0, z), out_y);
}

/* >>grid implementation ------------------------------------------------------------ */
/* (paste inside the SHLIGHT_IMPLEMENTATION part) */
#include <stdlib.h>
#if !defined(SHLIGHT_NO_THREADS) && (defined(__unix__) || defined(__APPLE__))
#include <pthread.h>
#define SHLI_GRID_PTHREADS 1
#else
#define SHLI_GRID_PTHREADS 0
#endif

typedef struct shli_grid_job {
  const shl_grid *g;
  const float (*centres)[3];
  const float *radii;
  const float *intensity;
  const double *cut2; /* per light: squared culling radius (< 0: the light is skipped) */
  int nlights;
  float *out_sh;
  float (*out_grad)[3];
  int order;
  int z0; /* vertex slab iz in [z0, z1) */
  int z1;
} shli_grid_job;

static void shli_grid_vertex(const shl_grid *g, int ix, int iy, int iz, float p[3]) {
  p[0] = (float)((double)g->origin[0] + (double)ix * (double)g->spacing[0]);
  p[1] = (float)((double)g->origin[1] + (double)iy * (double)g->spacing[1]);
  p[2] = (float)((double)g->origin[2] + (double)iz * (double)g->spacing[2]);
}

/* light j at vertex (ix, iy, iz): culling test and accumulation */
static void shli_grid_add(const shli_grid_job *jb, int j, int ix, int iy, int iz, float *tsh,
                          float (*tg)[3]) {
  const shl_grid *g = jb->g;
  int n = g->n, nn = n * n, i;
  size_t v = (size_t)ix + (size_t)g->dims[0] * ((size_t)iy + (size_t)g->dims[1] * (size_t)iz);
  float p[3], w = jb->intensity ? jb->intensity[j] : 1.0f;
  float *o = jb->out_sh + v * (size_t)nn;
  double dx, dy, dz;
  shli_grid_vertex(g, ix, iy, iz, p);
  if (jb->cut2[j] < 0.0) return;
  dx = (double)jb->centres[j][0] - (double)p[0];
  dy = (double)jb->centres[j][1] - (double)p[1];
  dz = (double)jb->centres[j][2] - (double)p[2];
  if (dx * dx + dy * dy + dz * dz > jb->cut2[j]) return;
  if (jb->out_grad) {
    float(*og)[3] = jb->out_grad + v * (size_t)nn;
    shl_sphere_light_grad(n, p, jb->centres[j], jb->radii[j], tsh, tg);
    for (i = 0; i < nn; ++i) {
      o[i] += w * tsh[i];
      og[i][0] += w * tg[i][0];
      og[i][1] += w * tg[i][1];
      og[i][2] += w * tg[i][2];
    }
  } else {
    shl_sphere_light(n, p, jb->centres[j], jb->radii[j], tsh);
    for (i = 0; i < nn; ++i)
      o[i] += w * tsh[i];
  }
}

/* index range [lo, hi] of the vertices within distance rad of c along one axis */
static void shli_grid_range(double c, double rad, float org, float sp, int dims, int *lo, int *hi) {
  double a, b;
  if (dims == 1 || !(rad < 1e30)) {
    *lo = 0;
    *hi = dims - 1;
    return;
  }
  a = floor((c - rad - (double)org) / (double)sp) - 1.0; /* widened by one: the exact test */
  b = ceil((c + rad - (double)org) / (double)sp) + 1.0;  /* is done per vertex */
  if (a < 0.0) a = 0.0;
  if (b > (double)(dims - 1)) b = (double)(dims - 1);
  if (a > b) {
    *lo = 1;
    *hi = 0;
    return;
  }
  *lo = (int)a;
  *hi = (int)b;
}

static void *shli_grid_run(void *arg) {
  const shli_grid_job *jb = (const shli_grid_job *)arg;
  const shl_grid *g = jb->g;
  float *tsh = (float *)malloc(sizeof(float) * (size_t)(g->n * g->n) * 4u);
  float(*tg)[3];
  int ix, iy, iz, j;
  if (!tsh) return (void *)1;
  tg = (float(*)[3])(void *)(tsh + g->n * g->n);
  if (jb->order == SHLIGHT_GRID_FORWARD) {
    for (iz = jb->z0; iz < jb->z1; ++iz)
      for (iy = 0; iy < g->dims[1]; ++iy)
        for (ix = 0; ix < g->dims[0]; ++ix)
          for (j = 0; j < jb->nlights; ++j)
            shli_grid_add(jb, j, ix, iy, iz, tsh, tg);
  } else {
    for (j = 0; j < jb->nlights; ++j) {
      int x0, x1, y0, y1, zl, zh;
      double rad = jb->cut2[j] < 0.0 ? -1.0 : sqrt(jb->cut2[j]);
      if (rad < 0.0) continue;
      shli_grid_range((double)jb->centres[j][0], rad, g->origin[0], g->spacing[0], g->dims[0], &x0,
                      &x1);
      shli_grid_range((double)jb->centres[j][1], rad, g->origin[1], g->spacing[1], g->dims[1], &y0,
                      &y1);
      shli_grid_range((double)jb->centres[j][2], rad, g->origin[2], g->spacing[2], g->dims[2], &zl,
                      &zh);
      if (zl < jb->z0) zl = jb->z0;
      if (zh > jb->z1 - 1) zh = jb->z1 - 1;
      for (iz = zl; iz <= zh; ++iz)
        for (iy = y0; iy <= y1; ++iy)
          for (ix = x0; ix <= x1; ++ix)
            shli_grid_add(jb, j, ix, iy, iz, tsh, tg);
    }
  }
  free(tsh);
  return NULL;
}

static int shli_grid_valid(const shl_grid *g) {
  int k, dims[3];
  if (!g || g->n < 1 || g->n > SHLIGHT_MAX_BANDS || g->dims[0] < 1 || g->dims[1] < 1 ||
      g->dims[2] < 1)
    return 0;
  if (!(g->cull >= 0.0f)) return 0;
  dims[0] = g->dims[0];
  dims[1] = g->dims[1];
  dims[2] = g->dims[2];
  for (k = 0; k < 3; ++k) {
    if (!(fabs((double)g->origin[k]) <= 3.4e38)) return 0;
    if (dims[k] > 1 && !(g->spacing[k] > 0.0f && (double)g->spacing[k] <= 3.4e38)) return 0;
  }
  return 1;
}

SHLIGHT_API shl_result shl_grid_build(const shl_grid *g, const float (*centres)[3],
                                      const float *radii, const float *intensity, int nlights,
                                      int sum_order, int threads, float *out_sh,
                                      float (*out_grad)[3]) {
  shli_grid_job jb[2];
  double *cut2;
  size_t nv, nn, k;
  int j, nt = threads > 2 ? 2 : threads;
  void *rc0 = NULL, *rc1 = NULL;
  if (!shli_grid_valid(g) || !out_sh || nlights < 0 || threads < 1 ||
      (nlights > 0 && (!centres || !radii)) ||
      (sum_order != SHLIGHT_GRID_FORWARD && sum_order != SHLIGHT_GRID_REVERSED))
    return SHLIGHT_EINVAL;
  nn = (size_t)g->n * (size_t)g->n;
  nv = (size_t)g->dims[0] * (size_t)g->dims[1] * (size_t)g->dims[2];
  cut2 = (double *)malloc(sizeof(double) * (size_t)(nlights > 0 ? nlights : 1));
  if (!cut2) return SHLIGHT_ENOMEM;
  for (k = 0; k < nv * nn; ++k)
    out_sh[k] = 0.0f;
  if (out_grad)
    for (k = 0; k < nv * nn; ++k)
      out_grad[k][0] = out_grad[k][1] = out_grad[k][2] = 0.0f;
  for (j = 0; j < nlights; ++j) {
    double r = (double)radii[j], w = intensity ? fabs((double)intensity[j]) : 1.0;
    double s =
        fabs((double)centres[j][0]) + fabs((double)centres[j][1]) + fabs((double)centres[j][2]);
    double rc = 1e300;
    if (!(r > 0.0) || !(s <= 3.4e38) || !(w <= 3.4e38)) {
      cut2[j] = -1.0; /* no light */
      continue;
    }
    if (g->cull > 0.0f) {
      rc = r * sqrt(6.283185307179586 * w / (double)g->cull);
      if (rc < 2.0 * r) rc = 2.0 * r;
    }
    cut2[j] = rc < 1e150 ? rc * rc : 1e300;
  }
  for (j = 0; j < 2; ++j) {
    jb[j].g = g;
    jb[j].centres = centres;
    jb[j].radii = radii;
    jb[j].intensity = intensity;
    jb[j].cut2 = cut2;
    jb[j].nlights = nlights;
    jb[j].out_sh = out_sh;
    jb[j].out_grad = out_grad;
    jb[j].order = sum_order;
  }
  if (nt < 2 || g->dims[2] < 2) {
    jb[0].z0 = 0;
    jb[0].z1 = g->dims[2];
    rc0 = shli_grid_run(&jb[0]);
  } else {
    jb[0].z0 = 0;
    jb[0].z1 = g->dims[2] / 2;
    jb[1].z0 = g->dims[2] / 2;
    jb[1].z1 = g->dims[2];
#if SHLI_GRID_PTHREADS
    {
      pthread_t th;
      if (pthread_create(&th, NULL, shli_grid_run, &jb[1]) == 0) {
        rc0 = shli_grid_run(&jb[0]);
        pthread_join(th, &rc1);
      } else {
        rc0 = shli_grid_run(&jb[0]);
        rc1 = shli_grid_run(&jb[1]);
      }
    }
#else
    rc0 = shli_grid_run(&jb[0]);
    rc1 = shli_grid_run(&jb[1]);
#endif
  }
  free(cut2);
  return (rc0 || rc1) ? SHLIGHT_ENOMEM : SHLIGHT_OK;
}

SHLIGHT_API shl_result shl_grid_sample(const shl_grid *g, const float *sh, const float (*grad)[3],
                                       const float p[3], shl_grid_method method, float *out_sh) {
  /* the corners are gathered and reconstructed in chunks of s^2 coefficients (s <= 8: 8 KB
     of stack for any n, no heap): each output coefficient depends only on its own corner
     values and on weights that depend only on f and the spacing, so the chunks give the same
     bits as one call on all n^2 coefficients */
  float c8[8 * 64], g8[8 * 64][3], f[3];
  int lo[3], hi[3], dims[3], k, c, n, nn, i0, s, ss, i;
  size_t v[8];
  if (!shli_grid_valid(g) || !sh || !out_sh || !p ||
      (method != SHLIGHT_GRID_TRILINEAR && method != SHLIGHT_GRID_TAYLOR &&
       method != SHLIGHT_GRID_HERMITE) ||
      (method != SHLIGHT_GRID_TRILINEAR && !grad))
    return SHLIGHT_EINVAL;
  n = g->n;
  nn = n * n;
  dims[0] = g->dims[0];
  dims[1] = g->dims[1];
  dims[2] = g->dims[2];
  for (k = 0; k < 3; ++k) {
    double u = 0.0, fl;
    if (dims[k] > 1) u = ((double)p[k] - (double)g->origin[k]) / (double)g->spacing[k];
    if (!(u >= 0.0)) u = 0.0; /* NaN too */
    if (u > (double)(dims[k] - 1)) u = (double)(dims[k] - 1);
    fl = floor(u);
    if (fl > (double)(dims[k] - 2)) fl = (double)(dims[k] - 2);
    if (fl < 0.0) fl = 0.0;
    lo[k] = (int)fl;
    hi[k] = dims[k] > 1 ? lo[k] + 1 : lo[k];
    f[k] = dims[k] > 1 ? (float)(u - fl) : 0.0f;
  }
  for (c = 0; c < 8; ++c) {
    int ix = (c & 1) ? hi[0] : lo[0], iy = (c & 2) ? hi[1] : lo[1], iz = (c & 4) ? hi[2] : lo[2];
    v[c] = (size_t)ix + (size_t)g->dims[0] * ((size_t)iy + (size_t)g->dims[1] * (size_t)iz);
  }
  for (i0 = 0; i0 < nn; i0 += ss) {
    s = 8;
    while (s * s > nn - i0)
      --s;
    ss = s * s;
    for (c = 0; c < 8; ++c) {
      for (i = 0; i < ss; ++i) {
        size_t src = v[c] * (size_t)nn + (size_t)(i0 + i);
        c8[c * ss + i] = sh[src];
        if (method != SHLIGHT_GRID_TRILINEAR) {
          g8[c * ss + i][0] = grad[src][0];
          g8[c * ss + i][1] = grad[src][1];
          g8[c * ss + i][2] = grad[src][2];
        }
      }
    }
    if (method == SHLIGHT_GRID_TRILINEAR) {
      shl_grid_trilinear(s, c8, f, out_sh + i0);
    } else if (method == SHLIGHT_GRID_TAYLOR) {
      shl_grid_taylor(s, c8, (const float(*)[3])g8, f, g->spacing, out_sh + i0);
    } else {
      shl_grid_hermite(s, c8, (const float(*)[3])g8, f, g->spacing, out_sh + i0);
    }
  }
  return SHLIGHT_OK;
}

/* ---- CPU-only part of >>brdftab: analytic BRDFs, table build, SHLT file, MERL loader ---- */
#include <stdlib.h>
#include <string.h>

#define SHLI_PI 3.14159265358979323846

static double shli_brdf_lambda(int ggx, double ax, double ay, const double w[3]) {
  double t2 = (ax * w[0]) * (ax * w[0]) + (ay * w[1]) * (ay * w[1]);
  double a;
  if (t2 <= 0.0) {
    return 0.0;
  }
  if (ggx) {
    return 0.5 * (sqrt(1.0 + t2 / (w[2] * w[2])) - 1.0);
  }
  a = w[2] / sqrt(t2); /* 1 / (alpha tan theta), Beckmann */
  if (a > 26.0) {
    return 0.0; /* both terms below 1e-295 */
  }
  return 0.5 * (-erfc(a) + exp(-a * a) / (a * sqrt(SHLI_PI)));
}

/* f_s in double; spec_only: without the kd / pi term */
static double shli_brdf_f(const shl_brdf_params *b, const double wo[3], const double wi[3],
                          int spec_only) {
  double f = 0.0;
  double e = (double)b->exponent;
  double h[3];
  double hl;
  double d;
  double ax;
  double ay;
  double c;
  double g2;
  double fr;
  int ggx;
  if (!(wo[2] > 0.0) || !(wi[2] > 0.0)) {
    return 0.0;
  }
  if (!spec_only) {
    f = (double)b->kd / SHLI_PI;
  }
  if (b->model == SHLIGHT_BRDF_LAMBERT || !(b->ks != 0.0f)) {
    return f;
  }
  if (b->model == SHLIGHT_BRDF_PHONG) {
    c = 2.0 * wo[2] * wi[2] - (wo[0] * wi[0] + wo[1] * wi[1] + wo[2] * wi[2]);
    if (c > 0.0) {
      f += (double)b->ks * (e + 1.0) / (2.0 * SHLI_PI) * pow(c, e);
    }
    return f;
  }
  h[0] = wi[0] + wo[0];
  h[1] = wi[1] + wo[1];
  h[2] = wi[2] + wo[2];
  hl = sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
  if (!(hl > 0.0)) {
    return f;
  }
  h[0] /= hl;
  h[1] /= hl;
  h[2] /= hl;
  if (b->model == SHLIGHT_BRDF_BLINN_PHONG) {
    ax = ay = sqrt(2.0 / (e + 2.0));
    d = (e + 2.0) / (2.0 * SHLI_PI) * pow(h[2], e);
    ggx = 0;
  } else if (b->model == SHLIGHT_BRDF_BECKMANN || b->model == SHLIGHT_BRDF_GGX) {
    double sx;
    double sy;
    ax = (double)b->alpha_x;
    ay = (double)b->alpha_y;
    if (!(ax > 0.0) || !(ay > 0.0)) {
      return f;
    }
    sx = h[0] / ax;
    sy = h[1] / ay;
    ggx = b->model == SHLIGHT_BRDF_GGX;
    if (ggx) {
      double s = sx * sx + sy * sy + h[2] * h[2];
      d = 1.0 / (SHLI_PI * ax * ay * s * s);
    } else {
      double h2 = h[2] * h[2];
      d = exp(-(sx * sx + sy * sy) / h2) / (SHLI_PI * ax * ay * h2 * h2);
    }
  } else {
    return 0.0;
  }
  g2 = 1.0 / (1.0 + shli_brdf_lambda(ggx, ax, ay, wo) + shli_brdf_lambda(ggx, ax, ay, wi));
  /* 1 - (w_i . h): the mean of w_i . h and w_o . h (equal for unit inputs), so that float
     inputs a few ulp off unit keep f exactly reciprocal */
  c = 1.0 - 0.5 * ((wi[0] + wo[0]) * h[0] + (wi[1] + wo[1]) * h[1] + (wi[2] + wo[2]) * h[2]);
  if (c < 0.0) {
    c = 0.0;
  }
  fr = (double)b->f0 + (1.0 - (double)b->f0) * (c * c) * (c * c) * c;
  return f + (double)b->ks * d * fr * g2 / (4.0 * wi[2] * wo[2]);
}

SHLIGHT_API float shl_brdf_eval(const shl_brdf_params *brdf, const float wo[3], const float wi[3]) {
  double o[3];
  double i[3];
  int k;
  if (!brdf || !wo || !wi) {
    return 0.0f;
  }
  for (k = 0; k < 3; ++k) {
    o[k] = (double)wo[k];
    i[k] = (double)wi[k];
  }
  return (float)shli_brdf_f(brdf, o, i, 0);
}

SHLIGHT_API size_t shl_brdf_table_size(int n, int n_theta, int n_phi) {
  if (n < 1 || n > SHLIGHT_MAX_BANDS || n_theta < 1 || n_theta > SHLIGHT_BRDF_TABLE_MAX_SAMPLES ||
      n_phi < 1 || n_phi > SHLIGHT_BRDF_TABLE_MAX_SAMPLES) {
    return 0;
  }
  if ((double)n_phi * (double)n_theta * 2.0 * (double)n * (double)n * 4.0 + 64.0 >
      (double)(size_t)-1) {
    return 0; /* the file length would overflow size_t (32-bit hosts) */
  }
  return (size_t)n_phi * (size_t)n_theta * 2u * (size_t)n * (size_t)n;
}

static int shli_brdf_table_valid(const shl_brdf_table *t) {
  return shl_brdf_table_size(t->n, t->n_theta, t->n_phi) != 0 &&
         t->flags == (t->n_phi > 1 ? SHLIGHT_BRDF_TABLE_ANISO : 0);
}

/* Gauss-Legendre nodes and weights on [-1, 1], q <= 512 (Newton from Tricomi's guess, double) */
static void shli_gauss_legendre(int q, double *x, double *w) {
  int i;
  int k;
  int it;
  for (i = 0; i < (q + 1) / 2; ++i) {
    double z = cos(SHLI_PI * ((double)i + 0.75) / ((double)q + 0.5));
    double p0 = 1.0;
    double p1 = 0.0;
    double dp = 1.0;
    for (it = 0; it < 100; ++it) {
      double dz;
      p0 = 1.0;
      p1 = 0.0;
      for (k = 1; k <= q; ++k) {
        double p2 = p1;
        p1 = p0;
        p0 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p2) / k;
      }
      dp = q * (z * p0 - p1) / (z * z - 1.0);
      dz = p0 / dp;
      z -= dz;
      if (fabs(dz) < 1e-16) {
        break;
      }
    }
    p0 = 1.0;
    p1 = 0.0;
    for (k = 1; k <= q; ++k) {
      double p2 = p1;
      p1 = p0;
      p0 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p2) / k;
    }
    dp = q * (z * p0 - p1) / (z * z - 1.0);
    x[i] = -z;
    x[q - 1 - i] = z;
    w[i] = w[q - 1 - i] = 2.0 / ((1.0 - z * z) * dp * dp);
  }
}

/* the integrand source of a build: an analytic BRDF (kd / pi split off) or a MERL channel */
typedef struct shli_tabsrc {
  const shl_brdf_params *brdf;
  const shl_merl *merl;
  int channel;
  double width; /* lobe width in radians (specular frame break points) */
  double gmax;  /* the lobe is 0 beyond this angle from r (pi: no limit) */
  int half;     /* 1: an isotropic microfacet lobe, the half-vector quadrature (width: alpha) */
} shli_tabsrc;

static double shli_merl_f(const shl_merl *m, int c, const double wo[3], const double wi[3]);

static double shli_src_f(const shli_tabsrc *s, const double wo[3], const double wi[3]) {
  if (s->brdf) {
    return shli_brdf_f(s->brdf, wo, wi, 1);
  }
  return shli_merl_f(s->merl, s->channel, wo, wi);
}

/* adds weight a f(wi) [cos_i Y(wi), Y(wi)] to acc[0 .. 2 nn) */
static void shli_tab_node(int n, double *acc, float *y, double a, const double wi[3]) {
  float d[3];
  int nn = n * n;
  int i;
  double ac = a * wi[2];
  d[0] = (float)wi[0];
  d[1] = (float)wi[1];
  d[2] = (float)wi[2];
  shl_sh_eval(n, d, y);
  for (i = 0; i < nn; ++i) {
    acc[i] += ac * (double)y[i];
    acc[nn + i] += a * (double)y[i];
  }
}

/* the kd / pi term: Gauss-Legendre in cos(theta_i) x uniform phi_i, exact for degree <= n */
static void shli_tab_diffuse(int n, double kd, double *acc, float *y) {
  double x[40];
  double w[40];
  int qz = n / 2 + 2;
  int np = n + 2;
  int i;
  int j;
  double wi[3];
  shli_gauss_legendre(qz, x, w);
  for (i = 0; i < qz; ++i) {
    double z = 0.5 * (x[i] + 1.0);
    double s = sqrt((1.0 - z) * (1.0 + z));
    for (j = 0; j < np; ++j) {
      double ph = 2.0 * SHLI_PI * ((double)j + 0.5) / (double)np;
      wi[0] = s * cos(ph);
      wi[1] = s * sin(ph);
      wi[2] = z;
      shli_tab_node(n, acc, y, kd / SHLI_PI * 0.5 * w[i] * 2.0 * SHLI_PI / (double)np, wi);
    }
  }
}

/* one node of the specular-frame quadrature: w_i = cos(g) r + sin(g) (cos(ps) e1 + sin(ps) e2),
   weight wgt */
static void shli_tab_arc(int n, const shli_tabsrc *src, const double wo[3], const double fr[9],
                         double cg, double sg, double ps, double wgt, double *acc, float *y) {
  double wi[3];
  double cp = cos(ps);
  double sp = sin(ps);
  double f;
  int k;
  for (k = 0; k < 3; ++k) {
    wi[k] = cg * fr[k] + sg * (cp * fr[3 + k] + sp * fr[6 + k]);
  }
  if (!(wi[2] > 0.0)) {
    return;
  }
  f = shli_src_f(src, wo, wi);
  if (f != 0.0) {
    shli_tab_node(n, acc, y, wgt * f, wi);
  }
}

/* the specular-frame quadrature (see shl_brdf_table_build) at order q; nodes generated on the
   fly (no scratch arrays: the whole build stays within a few KB of stack) */
static void shli_tab_spec(int n, const shli_tabsrc *src, const double wo[3], int q, double *acc,
                          float *y, const double *xg, const double *wg) {
  double fr[9]; /* r, e1, e2 */
  double br[8];
  double st;
  double ct;
  double gmax;
  double gh;
  int nb = 0;
  int p;
  int i;
  int j;
  int k;
  fr[0] = -wo[0];
  fr[1] = -wo[1];
  fr[2] = wo[2];
  ct = fr[2];
  st = sqrt(fr[0] * fr[0] + fr[1] * fr[1]);
  if (st > 1e-300) {
    fr[3] = -ct * fr[0] / st; /* (z - ct r) / st */
    fr[4] = -ct * fr[1] / st;
    fr[5] = st;
    fr[6] = -fr[1] / st; /* r x e1 */
    fr[7] = fr[0] / st;
    fr[8] = 0.0;
  } else {
    fr[3] = 1.0;
    fr[4] = 0.0;
    fr[5] = 0.0;
    fr[6] = 0.0;
    fr[7] = 1.0;
    fr[8] = 0.0;
  }
  gh = 0.5 * SHLI_PI - atan2(st, ct);
  gmax = 0.5 * SHLI_PI + atan2(st, ct);
  if (gmax > SHLI_PI) {
    gmax = SHLI_PI;
  }
  if (gmax > src->gmax) {
    gmax = src->gmax;
  }
  br[nb++] = 0.0;
  br[nb++] = gmax;
  if (gh > 0.0 && gh < gmax) {
    br[nb++] = gh;
  }
  for (k = 0; k < 4; ++k) {
    double b = src->width * 2.0 * pow(3.0, (double)k);
    if (b < gmax) {
      br[nb++] = b;
    }
  }
  for (i = 1; i < nb; ++i) { /* insertion sort */
    double v = br[i];
    for (j = i; j > 0 && br[j - 1] > v; --j) {
      br[j] = br[j - 1];
    }
    br[j] = v;
  }
  for (p = 0; p + 1 < nb; ++p) {
    double g0 = br[p];
    double g1 = br[p + 1];
    if (!(g1 - g0 > 1e-12)) {
      continue;
    }
    for (i = 0; i < q; ++i) {
      /* g = g0 + (g1 - g0) s^2 (3 - 2 s): smooth through the square-root ends of the arc
         length where a circle meets or leaves the horizon */
      double s = 0.5 * (xg[i] + 1.0);
      double g = g0 + (g1 - g0) * s * s * (3.0 - 2.0 * s);
      double sg = sin(g);
      double cg = cos(g);
      double wgi = 0.5 * wg[i] * (g1 - g0) * 6.0 * s * (1.0 - s) * sg;
      double cs; /* the arc above the horizon: cos(psi) > cs */
      double pm;
      if (st > 1e-300 && sg > 0.0) {
        cs = -cg * ct / (sg * st);
      } else {
        cs = cg > 0.0 ? -2.0 : 2.0;
      }
      if (cs >= 1.0) {
        continue;
      }
      /* the arc: 2q uniform nodes round a full circle; a partial arc (-pm, pm) in panels at
         0, +-w/2, +-3w/2, +-9w/2 (the lobe of a grazing w_o is narrow in psi) and graded towards
         the ends, q nodes each */
      if (cs <= -1.0) {
        for (j = 0; j < 2 * q; ++j) {
          shli_tab_arc(n, src, wo, fr, cg, sg, 2.0 * SHLI_PI * ((double)j + 0.5) / (double)(2 * q),
                       wgi * 2.0 * SHLI_PI / (double)(2 * q), acc, y);
        }
      } else {
        double ab[8];
        double la;
        int nab = 0;
        int pa;
        pm = acos(cs);
        ab[nab++] = 0.0;
        for (k = 0; k < 3; ++k) {
          double v = 0.5 * src->width * pow(3.0, (double)k);
          if (v < pm) {
            ab[nab++] = v;
          }
        }
        la = pm - ab[nab - 1]; /* graded towards the horizon, where F' of a grazing w_o has a
                                  near-logarithmic peak (1 / cos_i until Lambda_i ~ Lambda_o) */
        ab[nab++] = pm - la / 4.0;
        ab[nab++] = pm - la / 16.0;
        ab[nab++] = pm - la / 64.0;
        ab[nab++] = pm;
        for (pa = 0; pa + 1 < nab; ++pa) {
          double a0 = ab[pa];
          double a1 = ab[pa + 1];
          for (j = 0; j < q; ++j) {
            double v = 0.5 * (a0 + a1) + 0.5 * (a1 - a0) * xg[j];
            double wj = wgi * 0.5 * (a1 - a0) * wg[j];
            shli_tab_arc(n, src, wo, fr, cg, sg, v, wj, acc, y);
            shli_tab_arc(n, src, wo, fr, cg, sg, -v, wj, acc, y);
          }
        }
      }
    }
  }
}

/* one node of the half-vector quadrature: h = ct z + st (cos(ph) a + sin(ph) b), w_i the
   mirror of w_o about h, weight wgt 4 (w_o . h) (the Jacobian d w_i / d h) */
static void shli_tab_hnode(int n, const shli_tabsrc *src, const double wo[3], const double *a,
                           const double *b, double ct, double st, double ph, double wgt,
                           double *acc, float *y) {
  double h[3];
  double wi[3];
  double cp = cos(ph);
  double sp = sin(ph);
  double oh;
  double f;
  int k;
  for (k = 0; k < 2; ++k) {
    h[k] = st * (cp * a[k] + sp * b[k]);
  }
  h[2] = ct;
  oh = wo[0] * h[0] + wo[1] * h[1] + wo[2] * h[2];
  for (k = 0; k < 3; ++k) {
    wi[k] = 2.0 * oh * h[k] - wo[k];
  }
  if (!(wi[2] > 0.0) || !(oh > 0.0)) {
    return;
  }
  f = shli_src_f(src, wo, wi);
  if (f != 0.0) {
    shli_tab_node(n, acc, y, 4.0 * oh * wgt * f, wi);
  }
}

#define SHLI_HALF_GRADE 3

/* the half-vector quadrature of an isotropic microfacet lobe (see shl_brdf_table_build) at
   order q: w_i = 2 (w_o . h) h - w_o, d w_i = 4 (w_o . h) d h, h = cos(t) z + sin(t) (cos(ph) a
   + sin(ph) b) with a the azimuth of w_o. D depends on t only, with the width alpha whatever
   theta_o (no foreshortening), and w_i is above the horizon iff cos(ph) > cs(t) =
   -cos_o cos(2t) / (sin_o sin(2t)): full circles for t < (pi/2 - theta_o) / 2, arcs
   (-pm, pm) up to t = (pi/2 + theta_o) / 2. */
static void shli_tab_half(int n, const shli_tabsrc *src, const double wo[3], int q, double *acc,
                          float *y, const double *xg, const double *wg) {
  double br[24];
  double top;
  double ax[3];
  double bx[3];
  double so = sqrt(wo[0] * wo[0] + wo[1] * wo[1]);
  double co = wo[2];
  double eps = atan2(co, so); /* pi/2 - theta_o */
  double t1 = 0.5 * eps;
  double tmax = 0.5 * SHLI_PI - 0.5 * eps;
  int nb = 0;
  int p;
  int i;
  int j;
  int k;
  if (so > 1e-300) {
    ax[0] = wo[0] / so;
    ax[1] = wo[1] / so;
  } else {
    ax[0] = 1.0;
    ax[1] = 0.0;
  }
  ax[2] = 0.0;
  bx[0] = -ax[1];
  bx[1] = ax[0];
  bx[2] = 0.0;
  br[nb++] = 0.0;
  br[nb++] = tmax;
  if (t1 > 0.0 && t1 < tmax) {
    br[nb++] = t1;
  }
  top = t1 > 0.5 * tmax ? t1 : 0.5 * tmax;
  for (k = 0; k < 8; ++k) {
    double b = atan(src->width * pow(3.0, (double)k));
    if (b < tmax) {
      br[nb++] = b;
      top = b > top ? b : top;
    }
  }
  /* graded towards tmax, the backscatter direction w_i = w_o on the horizon's side of w_o,
     down to (pi/2 - theta_o) / 2: F' of a grazing w_o peaks there like 1 / (cos_i + cos_o) */
  for (k = 0; k < 12 && (tmax - top) > 0.5 * eps; ++k) {
    top = tmax - 0.25 * (tmax - top);
    br[nb++] = top;
  }
  for (i = 1; i < nb; ++i) { /* insertion sort */
    double v = br[i];
    for (j = i; j > 0 && br[j - 1] > v; --j) {
      br[j] = br[j - 1];
    }
    br[j] = v;
  }
  for (p = 0; p + 1 < nb; ++p) {
    double g0 = br[p];
    double g1 = br[p + 1];
    if (!(g1 - g0 > 1e-15)) {
      continue;
    }
    for (i = 0; i < q; ++i) {
      double s = 0.5 * (xg[i] + 1.0);
      double t = g0 + (g1 - g0) * s * s * (3.0 - 2.0 * s);
      double st = sin(t);
      double ct = cos(t);
      double wgi = 0.5 * wg[i] * (g1 - g0) * 6.0 * s * (1.0 - s) * st;
      double cs;
      double ab[24];
      int nab = 0;
      int pa;
      double pm;
      double la;
      if (so > 1e-300 && st > 0.0) {
        cs = -co * (ct * ct - st * st) / (so * 2.0 * st * ct);
      } else {
        cs = ct * ct > st * st ? -2.0 : 2.0;
      }
      if (cs >= 1.0) {
        continue;
      }
      if (cs <= -1.0) {
        for (j = 0; j < 2 * q; ++j) {
          shli_tab_hnode(n, src, wo, ax, bx, ct, st,
                         2.0 * SHLI_PI * ((double)j + 0.5) / (double)(2 * q),
                         wgi * 2.0 * SHLI_PI / (double)(2 * q), acc, y);
        }
        continue;
      }
      /* the arc (-pm, pm), graded geometrically towards its ends, where w_i meets the
         horizon (F' of a grazing w_o peaks there like 1 / (cos_i + delta)) */
      pm = acos(cs);
      ab[nab++] = 0.0;
      la = pm;
      for (k = 0; k < SHLI_HALF_GRADE; ++k) {
        la *= 0.25;
        ab[nab++] = pm - la;
      }
      ab[nab++] = pm;
      for (pa = 0; pa + 1 < nab; ++pa) {
        double a0 = ab[pa];
        double a1 = ab[pa + 1];
        for (j = 0; j < q; ++j) {
          double v = 0.5 * (a0 + a1) + 0.5 * (a1 - a0) * xg[j];
          double wj = wgi * 0.5 * (a1 - a0) * wg[j];
          shli_tab_hnode(n, src, wo, ax, bx, ct, st, v, wj, acc, y);
          shli_tab_hnode(n, src, wo, ax, bx, ct, st, -v, wj, acc, y);
        }
      }
    }
  }
}

/* theta_o of sample t of an n_theta-sample grid (see >>brdftab), in double: u(d) = t / (n - 1)
   solved for d by bisection (u is monotone), d = pi/2 - theta_o */
static double shli_grid_d(int n_theta, int t) {
  double target;
  double lo = 0.0;
  double hi = 0.5 * SHLI_PI;
  int it;
  if (n_theta < 2 || t <= 0) {
    return 0.5 * SHLI_PI;
  }
  if (t >= n_theta - 1) {
    return 0.0;
  }
  target = (double)t / (double)(n_theta - 1);
  for (it = 0; it < 200 && hi - lo > 1e-17; ++it) {
    double mid = 0.5 * (lo + hi);
    if (shli_brdf_grid_u(mid) > target) {
      lo = mid; /* u decreases with d */
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

SHLIGHT_API float shl_brdf_table_theta(int n_theta, int t) {
  if (n_theta < 1 || n_theta > SHLIGHT_BRDF_TABLE_MAX_SAMPLES || t < 0 || t >= n_theta) {
    return -1.0f;
  }
  return (float)(0.5 * SHLI_PI - shli_grid_d(n_theta, t));
}

/* the SH of F and F' at one outgoing direction wo (unit, wo_z > 0) into acc (2 n^2 doubles):
   the kd / pi term exactly, the rest by the specular-frame quadrature at order q */
static void shli_tab_project(int n, const shli_tabsrc *src, double kd, int spec, const double wo[3],
                             int q, const double *xg, const double *wg, double *acc, float *y) {
  memset(acc, 0, (size_t)(2 * n * n) * sizeof(double));
  if (kd != 0.0) {
    shli_tab_diffuse(n, kd, acc, y);
  }
  if (spec && src->half) {
    shli_tab_half(n, src, wo, q, acc, y, xg, wg);
  } else if (spec) {
    shli_tab_spec(n, src, wo, q, acc, y, xg, wg);
  }
}

static shl_result shli_tab_build(shl_brdf_table *t, const shli_tabsrc *src, double kd,
                                 int quad_order, float *out_err_est) {
  double xg[256];
  double wg[256];
  double xg2[128];
  double wg2[128];
  double xg4[64];
  double wg4[64];
  double acc_s[2 * 256];
  float y_s[256];
  double *acc = acc_s;
  float *y = y_s;
  void *heap = NULL;
  double err = 0.0;
  int n = t->n;
  int nn = n * n;
  int q2 = quad_order / 2 > 0 ? quad_order / 2 : 1;
  int q4 = quad_order / 4 > 0 ? quad_order / 4 : 1;
  int spec = src->merl != NULL ||
             (src->brdf && src->brdf->model != SHLIGHT_BRDF_LAMBERT && src->brdf->ks != 0.0f);
  int p;
  int ti;
  int i;
  if (nn > 256) {
    heap = malloc((size_t)nn * (2 * sizeof(double) + sizeof(float)));
    if (!heap) {
      return SHLIGHT_ENOMEM;
    }
    acc = (double *)heap;
    y = (float *)(acc + 2 * nn);
  }
  shli_gauss_legendre(quad_order, xg, wg);
  shli_gauss_legendre(q2, xg2, wg2);
  shli_gauss_legendre(q4, xg4, wg4);
  for (p = 0; p < t->n_phi; ++p) {
    double ph = 2.0 * SHLI_PI * (double)p / (double)t->n_phi;
    for (ti = 0; ti < t->n_theta; ++ti) {
      double d = shli_grid_d(t->n_theta, ti);
      double wo[3];
      float *out = t->data + (size_t)(p * t->n_theta + ti) * 2u * (size_t)nn;
      if (d < SHLIGHT_BRDF_TABLE_GRAZING) {
        d = SHLIGHT_BRDF_TABLE_GRAZING; /* the last sample: F' diverges at 90 degrees */
      }
      wo[0] = cos(d) * cos(ph);
      wo[1] = cos(d) * sin(ph);
      wo[2] = sin(d);
      double e1 = 0.0; /* |T(q/2) - T(q/4)|, max over the sample */
      double e2 = 0.0; /* |T(q) - T(q/2)| */
      double mx = 0.0;
      double es;
      if (spec && out_err_est) {
        shli_tab_project(n, src, kd, spec, wo, q4, xg4, wg4, acc, y);
        for (i = 0; i < 2 * nn; ++i) {
          out[i] = (float)acc[i]; /* the quarter-order table, compared below */
        }
        shli_tab_project(n, src, kd, spec, wo, q2, xg2, wg2, acc, y);
        for (i = 0; i < 2 * nn; ++i) {
          e1 = fabs(acc[i] - (double)out[i]) > e1 ? fabs(acc[i] - (double)out[i]) : e1;
          out[i] = (float)acc[i]; /* the half-order table */
        }
      }
      shli_tab_project(n, src, kd, spec, wo, quad_order, xg, wg, acc, y);
      for (i = 0; i < 2 * nn; ++i) {
        if (spec && out_err_est) {
          e2 = fabs(acc[i] - (double)out[i]) > e2 ? fabs(acc[i] - (double)out[i]) : e2;
        }
        mx = fabs(acc[i]) > mx ? fabs(acc[i]) : mx;
        out[i] = (float)acc[i];
      }
      if (spec && out_err_est) {
        /* geometric convergence seen from the last two halvings, the float rounding floor */
        es = e2 < e1 ? pow(e2, 2.5) / pow(e1, 1.5) : e2;
        if (es < mx * 5.9604644775390625e-8) {
          es = mx * 5.9604644775390625e-8;
        }
        if (es > err) {
          err = es;
        }
      }
    }
  }
  if (out_err_est) {
    *out_err_est = (float)err;
  }
  free(heap);
  return SHLIGHT_OK;
}

SHLIGHT_API shl_result shl_brdf_table_build(shl_brdf_table *t, const shl_brdf_params *brdf,
                                            int quad_order, float *out_err_est) {
  shli_tabsrc src;
  int micro;
  if (!t || !t->data || !brdf || !shli_brdf_table_valid(t) || quad_order < 2 || quad_order > 256) {
    return SHLIGHT_EINVAL;
  }
  if (brdf->model < SHLIGHT_BRDF_LAMBERT || brdf->model > SHLIGHT_BRDF_GGX ||
      !(brdf->kd >= 0.0f && brdf->kd < 3.4e38f) || !(brdf->ks >= 0.0f && brdf->ks < 3.4e38f)) {
    return SHLIGHT_EINVAL;
  }
  micro = brdf->model == SHLIGHT_BRDF_BECKMANN || brdf->model == SHLIGHT_BRDF_GGX;
  if ((brdf->model == SHLIGHT_BRDF_PHONG || brdf->model == SHLIGHT_BRDF_BLINN_PHONG) &&
      !(brdf->exponent >= 0.0f && brdf->exponent <= SHLIGHT_BRDF_MAX_EXPONENT)) {
    return SHLIGHT_EINVAL;
  }
  if (micro && !(brdf->alpha_x >= SHLIGHT_BRDF_MIN_ALPHA && brdf->alpha_x <= 4.0f &&
                 brdf->alpha_y >= SHLIGHT_BRDF_MIN_ALPHA && brdf->alpha_y <= 4.0f)) {
    return SHLIGHT_EINVAL;
  }
  if (brdf->model >= SHLIGHT_BRDF_BLINN_PHONG && !(brdf->f0 >= 0.0f && brdf->f0 <= 1.0f)) {
    return SHLIGHT_EINVAL;
  }
  src.brdf = brdf;
  src.merl = NULL;
  src.channel = 0;
  src.gmax = SHLI_PI;
  if (brdf->model == SHLIGHT_BRDF_PHONG) {
    src.width = 1.0 / sqrt((double)brdf->exponent + 1.0);
    src.gmax = 0.5 * SHLI_PI;
  } else if (brdf->model == SHLIGHT_BRDF_BLINN_PHONG) {
    src.width = 2.0 / sqrt((double)brdf->exponent + 2.0);
  } else {
    src.width = 2.0 * (double)(brdf->alpha_x > brdf->alpha_y ? brdf->alpha_x : brdf->alpha_y);
  }
  src.half = 0;
  if (brdf->model == SHLIGHT_BRDF_BLINN_PHONG) {
    src.half = 1;
    src.width = sqrt(2.0 / ((double)brdf->exponent + 2.0));
  } else if (micro && brdf->alpha_x == brdf->alpha_y) {
    src.half = 1;
    src.width = (double)brdf->alpha_x;
  }
  return shli_tab_build(t, &src, (double)brdf->kd, quad_order, out_err_est);
}

/* ---- MERL ---- */
static double shli_merl_f(const shl_merl *m, int c, const double wo[3], const double wi[3]) {
  double h[3];
  double hl;
  double th;
  double ph;
  double d[3];
  double tmp[3];
  double td;
  double pd;
  double u[3];
  int nd[3];
  int i0[3];
  int i1[3];
  double fr[3];
  double v = 0.0;
  int k;
  int a;
  int b;
  int e;
  int extra = 0;
  int bad = 0;
  if (!(wo[2] > 0.0) || !(wi[2] > 0.0)) {
    return 0.0;
  }
  h[0] = wi[0] + wo[0];
  h[1] = wi[1] + wo[1];
  h[2] = wi[2] + wo[2];
  hl = sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
  for (k = 0; k < 3; ++k) {
    h[k] /= hl;
  }
  th = acos(h[2] > 1.0 ? 1.0 : h[2]);
  ph = atan2(h[1], h[0]);
  /* w_i rotated by -phi_h about z, then by -theta_h about y */
  tmp[0] = wi[0] * cos(ph) + wi[1] * sin(ph);
  tmp[1] = -wi[0] * sin(ph) + wi[1] * cos(ph);
  tmp[2] = wi[2];
  d[0] = tmp[0] * cos(th) - tmp[2] * sin(th);
  d[1] = tmp[1];
  d[2] = tmp[0] * sin(th) + tmp[2] * cos(th);
  td = acos(d[2] > 1.0 ? 1.0 : (d[2] < -1.0 ? -1.0 : d[2]));
  pd = atan2(d[1], d[0]);
  if (pd < 0.0) {
    pd += SHLI_PI;
  }
  nd[0] = m->n_theta_h;
  nd[1] = m->n_theta_d;
  nd[2] = m->n_phi_d;
  u[0] = sqrt(th / (0.5 * SHLI_PI)) * (double)nd[0];
  u[1] = td / (0.5 * SHLI_PI) * (double)nd[1];
  u[2] = pd / SHLI_PI * (double)nd[2];
  for (k = 0; k < 3; ++k) {
    double f0;
    if (!(u[k] > 0.0)) {
      u[k] = 0.0;
    }
    f0 = floor(u[k]);
    if (f0 > (double)(nd[k] - 1)) {
      f0 = (double)(nd[k] - 1);
    }
    i0[k] = (int)f0;
    fr[k] = u[k] - f0;
    if (fr[k] > 1.0) {
      fr[k] = 1.0;
    }
    i1[k] = i0[k] + 1;
    if (i1[k] >= nd[k]) {
      i1[k] = k == 2 ? 0 : nd[k] - 1; /* periodic in phi_d, clamped in the thetas */
    }
  }
  if (u[1] > (double)(nd[1] - 1) && nd[1] >= 2) {
    /* beyond the last theta_d layer (MERL: 89 to 90 degrees): linear extrapolation from the
       last two layers (of f cos theta_h cos theta_d, below), when all 8 samples are valid */
    i0[1] = nd[1] - 2;
    i1[1] = nd[1] - 1;
    fr[1] = u[1] - (double)(nd[1] - 2);
    if (fr[1] > 2.0) {
      fr[1] = 2.0;
    }
    extra = 1;
  }
  /* trilinear in f cos(theta_h) cos(theta_d) = f (cos_i + cos_o) / 2, which stays smooth where
     f of a rough surface grows like 1 / (cos_i + cos_o) at grazing, divided by the query's
     factor (floored at 1e-6); over the valid (positive) samples only, the weights renormalised:
     near the horizon the grid mixes valid samples with invalid ones (negative in MERL files, 0
     where a direction of the sample lies below the surface), which would otherwise pull the value
     towards 0; with no valid sample in the cell, the nearest theta_d layer below that has one
     (extrapolation by holding along theta_d, where the sampled configurations end first) */
  for (;;) {
    double ws = 0.0;
    double ch[2];
    double cd[2];
    double q = cos(th) * cos(td);
    for (k = 0; k < 2; ++k) {
      double sh = (double)(k ? i1[0] : i0[0]) / (double)nd[0];
      ch[k] = cos(sh * sh * 0.5 * SHLI_PI);
      cd[k] = cos((double)(k ? i1[1] : i0[1]) / (double)nd[1] * 0.5 * SHLI_PI);
    }
    if (q < 1e-6) {
      q = 1e-6;
    }
    for (a = 0; a < 2; ++a) {
      for (b = 0; b < 2; ++b) {
        for (e = 0; e < 2; ++e) {
          size_t ih = (size_t)(a ? i1[0] : i0[0]);
          size_t id = (size_t)(b ? i1[1] : i0[1]);
          size_t ip = (size_t)(e ? i1[2] : i0[2]);
          double w =
              (a ? fr[0] : 1.0 - fr[0]) * (b ? fr[1] : 1.0 - fr[1]) * (e ? fr[2] : 1.0 - fr[2]);
          double s =
              (double)
                  m->data[(((size_t)c * (size_t)nd[0] + ih) * (size_t)nd[1] + id) * (size_t)nd[2] +
                          ip];
          if (s > 0.0 && w != 0.0) {
            v += w * s * ch[a] * cd[b];
            ws += w;
          } else if (w != 0.0) {
            bad = 1;
          }
        }
      }
    }
    if (extra && bad) { /* an invalid sample: hold the last layer instead */
      extra = 0;
      bad = 0;
      v = 0.0;
      i0[1] = nd[1] - 1;
      fr[1] = 0.0;
      continue;
    }
    if (ws > 0.0) {
      return v / (ws * q);
    }
    if (i0[1] == 0) {
      return 0.0;
    }
    i0[1] -= 1; /* one theta_d layer down, both corners on it */
    i1[1] = i0[1];
    fr[1] = 0.0;
  }
}

static int shli_merl_valid(const shl_merl *m) {
  return m && m->data && m->n_theta_h >= 1 && m->n_theta_h <= SHLIGHT_MERL_MAX_DIM &&
         m->n_theta_d >= 1 && m->n_theta_d <= SHLIGHT_MERL_MAX_DIM && m->n_phi_d >= 1 &&
         m->n_phi_d <= SHLIGHT_MERL_MAX_DIM;
}

SHLIGHT_API float shl_merl_eval(const shl_merl *m, int c, const float wo[3], const float wi[3]) {
  double o[3];
  double i[3];
  int k;
  if (!shli_merl_valid(m) || c < 0 || c > 2 || !wo || !wi) {
    return 0.0f;
  }
  for (k = 0; k < 3; ++k) {
    o[k] = (double)wo[k];
    i[k] = (double)wi[k];
  }
  return (float)shli_merl_f(m, c, o, i);
}

SHLIGHT_API shl_result shl_brdf_table_build_merl(shl_brdf_table *t, const shl_merl *m, int c,
                                                 int quad_order, float *out_err_est) {
  shli_tabsrc src;
  if (!t || !t->data || !shli_brdf_table_valid(t) || t->n_phi != 1 || !shli_merl_valid(m) ||
      c < 0 || c > 2 || quad_order < 2 || quad_order > 256) {
    return SHLIGHT_EINVAL;
  }
  src.brdf = NULL;
  src.merl = m;
  src.half = 0;
  src.channel = c;
  src.width = 0.1;
  src.gmax = SHLI_PI;
  return shli_tab_build(t, &src, 0.0, quad_order, out_err_est);
}

/* ---- byte access and CRC-32 ---- */
static unsigned long shli_rd32(const unsigned char *p) {
  return (unsigned long)p[0] | ((unsigned long)p[1] << 8) | ((unsigned long)p[2] << 16) |
         ((unsigned long)p[3] << 24);
}
static void shli_wr32(unsigned char *p, unsigned long v) {
  p[0] = (unsigned char)(v & 0xffu);
  p[1] = (unsigned char)((v >> 8) & 0xffu);
  p[2] = (unsigned char)((v >> 16) & 0xffu);
  p[3] = (unsigned char)((v >> 24) & 0xffu);
}
static int shli_rdi32(const unsigned char *p) {
  unsigned long v = shli_rd32(p);
  return v >= 0x80000000ul ? -(int)(0xfffffffful - v) - 1 : (int)v;
}
static float shli_rdf32(const unsigned char *p) {
  unsigned long v = shli_rd32(p);
  unsigned int u = (unsigned int)v;
  float f;
  memcpy(&f, &u, sizeof f); /* IEEE-754 binary32 host, as everywhere in shlight */
  return f;
}
static double shli_rdf64(const unsigned char *p) {
  unsigned long lo = shli_rd32(p);
  unsigned long hi = shli_rd32(p + 4);
  double d;
  unsigned char b[8];
  int k;
  for (k = 0; k < 4; ++k) {
    b[k] = (unsigned char)((lo >> (8 * k)) & 0xffu);
    b[4 + k] = (unsigned char)((hi >> (8 * k)) & 0xffu);
  }
  { /* little-endian bytes to the host's order */
    const unsigned int one = 1u;
    unsigned char le;
    memcpy(&le, &one, 1);
    if (!le) {
      for (k = 0; k < 4; ++k) {
        unsigned char s = b[k];
        b[k] = b[7 - k];
        b[7 - k] = s;
      }
    }
  }
  memcpy(&d, b, sizeof d);
  return d;
}

static const unsigned long shli_crc_nibble[16] = {
    0x00000000ul, 0x1db71064ul, 0x3b6e20c8ul, 0x26d930acul, 0x76dc4190ul, 0x6b6b51f4ul,
    0x4db26158ul, 0x5005713cul, 0xedb88320ul, 0xf00f9344ul, 0xd6d6a3e8ul, 0xcb61b38cul,
    0x9b64c2b0ul, 0x86d3d2d4ul, 0xa00ae278ul, 0xbdbdf21cul};

/* CRC-32 update (state pre- and post-inverted by the caller) */
static unsigned long shli_crc32(unsigned long crc, const unsigned char *p, size_t len) {
  size_t i;
  for (i = 0; i < len; ++i) {
    crc ^= p[i];
    crc = (crc >> 4) ^ shli_crc_nibble[crc & 15u];
    crc = (crc >> 4) ^ shli_crc_nibble[crc & 15u];
  }
  return crc & 0xfffffffful;
}

SHLIGHT_API shl_result shl_brdf_table_write(const shl_brdf_table *t, void *buf, size_t cap,
                                            size_t *out_len) {
  unsigned char *b = (unsigned char *)buf;
  size_t count;
  size_t need;
  size_t i;
  unsigned long crc;
  if (!t || !t->data || !out_len || !shli_brdf_table_valid(t)) {
    return SHLIGHT_EINVAL;
  }
  count = shl_brdf_table_size(t->n, t->n_theta, t->n_phi);
  need = SHLIGHT_BRDF_TABLE_HEADER + 4u * count;
  *out_len = need;
  for (i = 0; i < count; ++i) {
    if (!(fabsf(t->data[i]) <= 3.4028235e38f)) {
      return SHLIGHT_ENONFINITE;
    }
  }
  if (!b || cap < need) {
    return SHLIGHT_ESTORAGE;
  }
  memcpy(b, "SHLT", 4);
  shli_wr32(b + 4, SHLIGHT_BRDF_TABLE_VERSION);
  shli_wr32(b + 8, (unsigned long)t->n);
  shli_wr32(b + 12, (unsigned long)t->n_theta);
  shli_wr32(b + 16, (unsigned long)t->n_phi);
  shli_wr32(b + 20, (unsigned long)t->flags);
  shli_wr32(b + 24, (unsigned long)count);
  shli_wr32(b + 28, SHLIGHT_BRDF_TABLE_GRID);
  shli_wr32(b + 32, 0);
  for (i = 0; i < count; ++i) {
    unsigned int u;
    memcpy(&u, t->data + i, sizeof u);
    shli_wr32(b + SHLIGHT_BRDF_TABLE_HEADER + 4u * i, (unsigned long)u);
  }
  crc = shli_crc32(0xfffffffful, b, 36);
  crc = shli_crc32(crc, b + SHLIGHT_BRDF_TABLE_HEADER, 4u * count) ^ 0xfffffffful;
  shli_wr32(b + 36, crc);
  return SHLIGHT_OK;
}

SHLIGHT_API shl_result shl_brdf_table_read(const void *buf, size_t len, float *storage,
                                           size_t storage_floats, shl_brdf_table *out_table) {
  const unsigned char *b = (const unsigned char *)buf;
  shl_brdf_table t;
  unsigned long count;
  unsigned long flags;
  unsigned long crc;
  size_t want;
  size_t i;
  if (!out_table || !buf) {
    return SHLIGHT_EINVAL;
  }
  if (len < 8) {
    return SHLIGHT_ELENGTH;
  }
  if (memcmp(b, "SHLT", 4) != 0) {
    return SHLIGHT_EMAGIC;
  }
  if (shli_rd32(b + 4) != SHLIGHT_BRDF_TABLE_VERSION) {
    return SHLIGHT_EVERSION; /* version 1: the old cell-centred grid */
  }
  if (len < SHLIGHT_BRDF_TABLE_HEADER) {
    return SHLIGHT_ELENGTH;
  }
  t.n = shli_rdi32(b + 8);
  t.n_theta = shli_rdi32(b + 12);
  t.n_phi = shli_rdi32(b + 16);
  flags = shli_rd32(b + 20);
  t.flags = flags > 1ul ? -1 : (int)flags;
  t.data = NULL;
  count = shli_rd32(b + 24);
  want = shl_brdf_table_size(t.n, t.n_theta, t.n_phi);
  if (want == 0 || !shli_brdf_table_valid(&t) || (size_t)count != want ||
      shli_rd32(b + 28) != SHLIGHT_BRDF_TABLE_GRID || shli_rd32(b + 32) != 0ul) {
    return SHLIGHT_EDIMS;
  }
  if ((len - SHLIGHT_BRDF_TABLE_HEADER) % 4u != 0 ||
      (len - SHLIGHT_BRDF_TABLE_HEADER) / 4u != want) {
    return SHLIGHT_ELENGTH;
  }
  crc = shli_crc32(0xfffffffful, b, 36);
  crc = shli_crc32(crc, b + SHLIGHT_BRDF_TABLE_HEADER, 4u * want) ^ 0xfffffffful;
  if (crc != shli_rd32(b + 36)) {
    return SHLIGHT_ECHECKSUM;
  }
  for (i = 0; i < want; ++i) {
    if (!(fabsf(shli_rdf32(b + SHLIGHT_BRDF_TABLE_HEADER + 4u * i)) <= 3.4028235e38f)) {
      return SHLIGHT_ENONFINITE;
    }
  }
  *out_table = t;
  if (!storage || storage_floats < want) {
    return SHLIGHT_ESTORAGE;
  }
  for (i = 0; i < want; ++i) {
    storage[i] = shli_rdf32(b + SHLIGHT_BRDF_TABLE_HEADER + 4u * i);
  }
  out_table->data = storage;
  return SHLIGHT_OK;
}

SHLIGHT_API shl_result shl_merl_read(const void *buf, size_t len, float *storage,
                                     size_t storage_floats, shl_merl *out_merl) {
  static const double scale[3] = {1.0 / 1500.0, 1.15 / 1500.0, 1.66 / 1500.0};
  const unsigned char *b = (const unsigned char *)buf;
  shl_merl m;
  size_t per;
  size_t i;
  if (!out_merl || !buf) {
    return SHLIGHT_EINVAL;
  }
  if (len < 12) {
    return SHLIGHT_ELENGTH;
  }
  m.n_theta_h = shli_rdi32(b);
  m.n_theta_d = shli_rdi32(b + 4);
  m.n_phi_d = shli_rdi32(b + 8);
  m.data = NULL;
  if (m.n_theta_h < 1 || m.n_theta_h > SHLIGHT_MERL_MAX_DIM || m.n_theta_d < 1 ||
      m.n_theta_d > SHLIGHT_MERL_MAX_DIM || m.n_phi_d < 1 || m.n_phi_d > SHLIGHT_MERL_MAX_DIM) {
    return SHLIGHT_EDIMS;
  }
  if ((double)m.n_theta_h * (double)m.n_theta_d * (double)m.n_phi_d * 24.0 + 64.0 >
      (double)(size_t)-1) {
    return SHLIGHT_EDIMS; /* 32-bit hosts: the length would overflow size_t */
  }
  per = (size_t)m.n_theta_h * (size_t)m.n_theta_d * (size_t)m.n_phi_d;
  if ((len - 12) % 24u != 0 || (len - 12) / 24u != per) {
    return SHLIGHT_ELENGTH;
  }
  for (i = 0; i < 3 * per; ++i) {
    if (!(fabs(shli_rdf64(b + 12 + 8 * i) * scale[i / per]) <= 3.4028234663852886e38)) {
      return SHLIGHT_ENONFINITE; /* NaN, infinity, or beyond float once scaled */
    }
  }
  *out_merl = m;
  if (!storage || storage_floats < 3 * per) {
    return SHLIGHT_ESTORAGE;
  }
  for (i = 0; i < 3 * per; ++i) {
    storage[i] = (float)(shli_rdf64(b + 12 + 8 * i) * scale[i / per]);
  }
  out_merl->data = storage;
  return SHLIGHT_OK;
}

#endif /* SHLIGHT_IMPLEMENTATION */

/*
------------------------------------------------------------------------------
This software is available under 2 licenses -- choose whichever you prefer.
ALTERNATIVE A - MIT License. Copyright (c) 2026 the shlight authors.
Permission is hereby granted, free of charge, to any person obtaining a copy of this software
and associated documentation files (the "Software"), to deal in the Software without
restriction, including without limitation the rights to use, copy, modify, merge, publish,
distribute, sublicense, and/or sell copies of the Software, and to permit persons to whom the
Software is furnished to do so, subject to the following conditions: The above copyright notice
and this permission notice shall be included in all copies or substantial portions of the
Software. THE SOFTWARE IS PROVIDED "AS IS", WITHOUT WARRANTY OF ANY KIND, EXPRESS OR IMPLIED,
INCLUDING BUT NOT LIMITED TO THE WARRANTIES OF MERCHANTABILITY, FITNESS FOR A PARTICULAR PURPOSE
AND NONINFRINGEMENT. IN NO EVENT SHALL THE AUTHORS OR COPYRIGHT HOLDERS BE LIABLE FOR ANY CLAIM,
DAMAGES OR OTHER LIABILITY, WHETHER IN AN ACTION OF CONTRACT, TORT OR OTHERWISE, ARISING FROM,
OUT OF OR IN CONNECTION WITH THE SOFTWARE OR THE USE OR OTHER DEALINGS IN THE SOFTWARE.
ALTERNATIVE B - Public Domain (www.unlicense.org). Anyone is free to copy, modify, publish, use,
compile, sell, or distribute this software, either in source code form or as a compiled binary,
for any purpose, commercial or non-commercial, and by any means.
------------------------------------------------------------------------------
*/
