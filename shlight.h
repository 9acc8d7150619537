/* shlight.h - v0.7.0 - analytic spherical-harmonics lighting - MIT or public domain (see end)

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
     e = shl_zh_dot_zh(4, cap, axis, lobe, nrm);      3'. O(n), one sphere: shl_zh_cap, axis c - x
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
     >>generated  last: the tables and unrolled kernels written by tools/gen_basis.py (each
                  section declares what it uses at its `@generated NAME` line)

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
     Derivations: docs/derivations.md; measured accuracy and speed: docs/accuracy.md, docs/speed.md.
*/
#ifndef SHLIGHT_H
#define SHLIGHT_H

/* >>options ---------------------------------------------------------------------------------
   SHLIGHT_MAX_BANDS       largest band count the functions accept (default 64; tables hold 64)
   SHLIGHT_UNROLLED_BANDS  straight-line generated code for n <= this (16); run-time loop above
   SHLIGHT_NO_SIMD         batch evaluation, the GGX / Beckmann polygon lights (edges and
                           remainder) without SSE2 / AVX2 / AVX-512 intrinsics
   SHLIGHT_BATCH_COMPACT   default 1: shl_sh_eval_batch runs 7..16 bands as one loop; 0 unrolls
                           it per band count (the batch at 7..16 bands 10-20 % faster when its
                           output stays in L1, at 3.5x the implementation's compile time, 7.7
                           against 2.2 s, and +200 KB of .text, gcc 12 -O2)
   SHLIGHT_STATIC          the CPU-only functions become static (private to one file)
   SHLIGHT_ROTATE_FAST     default 1 with GCC / Clang: shl_sh_rotate's vector path for n <= 8;
                           0: the portable kernel (the GLSL twin's body) at every n
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
   AVX-512, n > 32, sin theta < 0.32: runs with MXCSR FTZ + DAZ (restored; values < 1e-22 may be 0).
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

/* shl_sh_eval_dot_grad: f = sum_i sh[i] Y_i(d / |d|), returned, and out_grad[k] = df / dd_k
   without the n^2 basis gradients (GLSL: their terms summed band by band). d as shl_sh_eval_grad
   (zero, NaN or inf: f at (0,0,1), zero gradient; tiny |d|: the same overflow). n: 1..64
   (GLSL 16; n < 1: 0, zero gradient); sh: n * n floats (NaN: NaN f, gradient; inf: NaN or inf).
   Accuracy: 1e-7 of sum_i |sh[i]| max|Y_i| (f), max|grad Y_i| (gradient). Cost: llvmpipe
   2-3.4x shl_sh_eval (shl_sh_eval_grad: 3-6x, docs/glsl.md); C: shl_sh_eval_grad and the n^2
   sums (n <= 16: 3.1x its time), above one streaming pass, no buffer (0.86-0.92x its time). */
SHLIGHT_INLINE float shl_sh_eval_dot_grad(int n, const float *sh, const float d[3],
                                          float out_grad[3]);

/* ---- zonal --------------------------------------------------------------------------------- */
/* shl_zh_cap: ZH coefficients L_l, l < n, of the unit-radiance cap that a sphere of radius r
   subtends at distance d (its centre on +z): out_zh[l] = int_cap Y_l^0. Stable s^2 P'_l form
   (see >>zonal), any s from 1e-30 to 1: relative error at the float rounding floor in C.
   Small caps: L_l -> pi s^2 K_l (a point light). r <= 0, NaN r or d, infinite d: zeros;
   d <= r: the hemisphere. out_zh: n floats. Cost: O(n), one sqrt and 2 divisions per band. */
SHLIGHT_INLINE void shl_zh_cap(int n, float r, float d, float *out_zh);

/* shl_zh_cap_derivative: derivative of shl_zh_cap with respect to the half-angle a,
   out_dzh[l] = dL_l / da = sqrt(pi (2l+1)) P_l(alpha) s (docs/derivations.md section 2: the paper's
   eq. 16 is O'_l = -(2l+1) P_l, no division by alpha^2 - 1). Chain with da/dd = -s / (d alpha), or
   use shl_sphere_light_grad, which does it for the full SH. Same domain as shl_zh_cap; d <= r: the
   value at a = pi/2 (s = 1, alpha = 0). out_dzh: n floats. Cost: O(n), one sqrt per band. */
SHLIGHT_INLINE void shl_zh_cap_derivative(int n, float r, float d, float *out_dzh);

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
   out_sh = Y(R d). n: bands, 1..SHLIGHT_MAX_BANDS (64 in C; GLSL: written for n <= 16); n < 1
   writes nothing, n > max is clamped. sh and out_sh must not overlap.
   Method (docs/rotation.md): portable kernel (any n; GLSL): zyz angles without inverse
   trigonometry, Wigner's d by its three-term recurrence in l, one row at a time (O(n) work
   space). C with GCC / Clang, n <= 8 (SHLIGHT_ROTATE_FAST, default 1 there), R near a rotation
   (below): bands 1 and 2 from R as given, bands 3..7 by z rotations and constant +90 degree
   turns about x in float vectors (2 square roots, 1 division).
   R: a rotation. d: the root sum of squares of |r0|^2 - 1, |r1|^2 - 1, r0 . r1 and the 3
   entries of r0 x r1 - r2 (r_i: R's rows; float rounding of a rotation: <= 1.6e-7, computed in
   float from a unit quaternion: <= 8.0e-7). Where d <= 1e-6 (computed in float with AVX2 and
   FMA at n <= 3: within 1.2e-7 of d; else in double), the C n <= 8 path takes R as given: the
   result is within 3 d of the nearest rotation's (measured 2.4 d). Any other R, and every R in
   the portable kernel, is read as the exact rotation given by R's third column and R_00, R_01,
   R_10, R_11 (within 1e-7 of a float-rounded R; any finite matrix gives a rotation, an
   all-zero R the identity; R_20, R_21 not read); NaN in a read entry gives NaN in every band
   above 0.
   Accuracy (C; against a long-double re-projection, tests/test_rotate.c): per band, |error| /
   |input band| <= 4.6e-8 in the portable kernel (n = 1..64, double inside: the float rounding
   of the output); the n <= 8 path on float-rounded rotations 1.6e-7 at n <= 3, 3e-7 at n =
   4..8 (float inside; measured 2.6e-7), 8e-7 on rotations moved by 3 ulps per entry; band
   energy kept to 2.5e-7. GLSL (float inside): within 1.8e-6 of C per band at n = 16.
   Cost: n <= 8 (C, GCC / Clang): 61 / 162 / 273 / 339 / 405 / 582 instructions at n = 2 / 3 /
   4 / 5 / 6 / 8 (gcc -O3 -march=x86-64-v3), 4.2 / 15 / 26 / 40 / 48 / 71 ns; DirectXMath's
   XMSHRotate (n <= 6) 79 / 222 / 304 / 463 / 665 instructions, 4.3 / 18.3 / 30 / 45 / 67 ns.
   Portable kernel (also R off a rotation: orthonormalise it): n^3 / 3 steps of the two
   recurrences and of the row dot products, ~0.75k / 1.6k / 3.0k / 15k instructions at n = 2 /
   3 / 4 / 8, 8.7 us at n = 16, 0.47 ms at n = 64. Stack: 7.5 KB at SHLIGHT_MAX_BANDS = 64. */
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
   radial term 2 pi s^2 P_l(alpha) / (d alpha) Y w (docs/derivations.md section 3). Singular only as
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
   triangle's normal and the direction from x to the centroid. A model: its error is set by
   distance / sqrt(area) (docs/accuracy.md: 0.18 at 2, 2.4e-2 at 5, 1.5e-3 at 20, 5.7e-5 at 100,
   equilateral; a 10:1 sliver ~10x worse). x closer to the centroid than r_s: the hemisphere (as
   shl_sphere_light) times |cos gamma|; x == centroid: axis +z.
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
   van Oosterom-Strackee in the edge form with atan2 (docs/derivations.md section 4, correction E6
   (docs/derivations.md section 12)): Omega = 2 atan2(N, D), R_i = p_i - x, N = R_0 . ((p1 - p0) x
   (p2 - p0)), D = |R0||R1||R2| + (R0.R1)|R2| + (R0.R2)|R1| + (R1.R2)|R0|, in shli_real. Positive
   when x is behind the triangle, i.e. on the side opposite to n = (p1 - p0) x (p2 - p0) (p0, p1, p2
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
                                      shl_grid_order sum_order, int threads, float *out_sh,
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
   + pi) = (-1)^n I(p) (docs/derivations.md section 7.2); orders n <= 2 and c < 1.0e-3 always take
   the exact path (closed forms; the fits are 0/0 there). Degenerate: c clamped to [0, 1], Phi to
   [0, pi]; NaN input -> 0; n > 1.0e6 clamped. Accuracy: EXACT matches long double quadrature to
   1.0e-12 relative to F(-pi/2, pi/2) in C (double inside); the fits' errors are in
   docs/area-lights.md. */
SHLIGHT_INLINE float shl_edge_integral(float phi, float c, float delta, float exponent,
                                       shl_edge_method method);

/* shl_polygon_moment: the axial moment of [AREA] eq. 1, integral over the solid angle of the
   polygon v[0..nv-1] (vertices relative to the shading point, any winding, two-sided), clipped
   to the hemisphere u.axis > 0, of (u.axis)^exponent (exponent 1 about the normal:
   irradiance; Lambert: / pi). nv >= 3, any count in C (fan pieces of at most 8 vertices above
   SHLIGHT_POLYGON_MAX = 8, see >>edge; GLSL: at most SHLIGHT_POLYGON_MAX, above it -1). A
   non-convex or self-overlapping (planar) polygon is integrated with its winding number
   relative to its net orientation (a region wound twice counts twice). axis any non-zero
   vector (normalised inside); exponent >= 0 real. method:
   - SHLIGHT_EDGE_EXACT: exact at every real exponent. Integer exponents up to 65536: Arvo's
     form with the O(e) recurrence (double inside in C); any other exponent: the Stokes form
     (see >>edge) with an adaptive composite Gauss-Legendre rule run until two levels agree to
     1e-9 (measured: 5.5e-8 of the normalised lobe against cubature for exponents
     0.3..9999.5, the float output's rounding). ~61k x86 instructions per doubly clipped quad
     at e = 777.7 (GCC -O3 -march=x86-64-v3).
   - SHLIGHT_EDGE_LORENTZ / _LORENTZ_PEARSON / _ELLIPSOID: Arvo's form with the paper's O(1)
     fits of F (errata fixed), exponent rounded to the nearest integer; above 65536 they take
     QUADRATURE (no float-to-int conversion of huge exponents).
   - SHLIGHT_EDGE_QUADRATURE: the Stokes form (see >>edge), O(1), any real exponent.
   - SHLIGHT_EDGE_AUTO: the recurrence for integer exponents <= 16, EXACT's adaptive rule
     above: exact everywhere, continuous at its switch (jump < 1e-7 relative, measured).
     2.5k instructions per quad at e = 10, 64k at 100 (FAST is the constant-time road).
   - SHLIGHT_EDGE_FAST: the Stokes form in float with a 4-node rational-graded rule per
     half-arc and polynomial transcendentals, SIMD over 8 edges in C: O(1), any real exponent
     (finite to 1e30), ~1.3k x86 instructions per doubly clipped quad (GCC -O3
     -march=x86-64-v3), p95 1e-4 and max 1.5e-3 of the normalised lobe (docs/accuracy.md). GLSL:
   only with SHLIGHT_EDGE_FAST_ON 1 defined by the host, else it means QUADRATURE.
   - any other value (an unknown method id): SHLIGHT_EDGE_AUTO.
   Degenerate: nv < 3, zero axis, NaN anywhere, a polygon through the shading point or reduced
   to < 3 vertices by the clip: 0; NaN exponent or exponent >= 1e30: 0 (the limit of the
   moment); negative exponent: treated as 0. Result >= 0 (GLSL nv > SHLIGHT_POLYGON_MAX: -1).
   Accuracy and cost: docs/area-lights.md. */
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
   (docs/derivations.md section 12)): lambda = ln 2 / (1 - 2^(-1/n)), in the stable form ln 2 /
   -expm1(-ln
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
   (clamped lobes, docs/derivations.md 7.3). r1, r2: any finite non-zero vectors, normalised here in
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
   of the rest of the BRDF and an adaptive cubature of its remainder (docs/area-lights.md). nrm
   and view any non-zero vectors (normalised inside), nv >= 3 (C: any count, fan pieces above
   SHLIGHT_POLYGON_MAX; GLSL: above it -1), alpha clamped to [1e-4, 1]. Degenerate inputs give
   0: nv < 3, NaN or infinite input, zero normal or view, view at or below the horizon, NaN
   alpha, a light entirely below the horizon (exactly 0: clipped first), a polygon through the
   shading point. Result >= 0. Accuracy against long double cubature on the LTC comparison's
   sampler (bench/bench_ggx.c): median relative error 5e-6 to 4e-5 at roughness 0.05 to 1 (LTC:
   7e-5 to 0.11), max error / albedo <= 3.3e-3 there, 1e-2 at other roughness (measured 6.6e-3);
   wide lights at views 85-89.9 deg mostly <= 1e-2 (up to 0.63: docs/area-lights.md). Cost:
   5.8k x86 instructions per quad on that sampler's mean in C with AVX2 and FMA (edges and
   remainder in double lanes), 12.55k portable; ~1.5M at the split budget, ~8.8M past 88.85
   deg. */
SHLIGHT_INLINE float shl_polygon_ggx(const float (*v)[3], int nv, const float nrm[3],
                                     const float view[3], float alpha);

/* shl_polygon_ggx_fast: the same integral as shl_polygon_ggx (GGX microfacet BRDF, F = 1,
   height-correlated G2, over the polygon clipped to nrm.l > 0), approximated by a linearly
   transformed cosine (Heitz et al. 2016) with no table: the transform (4 parameters in the view
   frame) and the magnitude (the directional albedo times a factor) are closed-form polynomials
   in r = sqrt(alpha) and nrm.view (a set for r <= 0.25, one for r >= 0.3, interpolated
   between: continuous in alpha), fitted by tools/fit_ggx_fast.c to polygon integrals of
   shl_polygon_ggx. The polygon is clipped to the horizon before the transform: no light comes
   from below it. Inputs and degenerate results as
   shl_polygon_ggx (nv < 3, NaN / Inf input, zero normal or view, view at or below the horizon, NaN
   alpha, a light wholly below the horizon (exactly 0), a polygon through the shading point: 0; C:
   any nv, GLSL: above SHLIGHT_POLYGON_MAX -1); alpha clamped to [1e-4, 1]. Result >= 0. Accuracy
   against long double cubature on the LTC comparison's sampler (docs/area-lights.md "Fast GGX
   polygon lights"): median relative error 3.6e-5, 5.2e-4, 2.4e-3, 6.3e-3, 1.7e-2, 1.9e-2, 1.1e-2 at
   roughness 0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1; max error / albedo 4.0e-3 to 4.3e-2 (worst at
   roughness 0.2). Cost: 1,250 to 1,290 x86 instructions per quad, ~1,650 for r in (0.25, 0.3)
   (gcc -O3; ~10x fewer than shl_polygon_ggx). */
SHLIGHT_INLINE float shl_polygon_ggx_fast(const float (*v)[3], int nv, const float nrm[3],
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
   max error / albedo <= 4.9e-2 (grazing views, lights straddling the horizon; up to 6.7e-2 in
   test_microfacet's grazing set). Cost: 9.6k x86 instructions per quad with AVX2 and FMA, 26k
   portable (shl_polygon_beckmann_subedges k = 8: ~220k).
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
   with G2 not held (worst 4.9e-2 of the albedo on bench_ggx's sampler, 26k instructions): prefer
   it. */
SHLIGHT_INLINE float shl_polygon_beckmann_subedges(const float (*v)[3], int nv, const float nrm[3],
                                                   const float view[3], float alpha, int subedges);

/* ---- brdf ---------------------------------------------------------------------------------- */
/* windows of shl_zh_window */
typedef enum shl_window_kind {
  SHLIGHT_WINDOW_NONE = 0,
  SHLIGHT_WINDOW_HANNING = 1,
  SHLIGHT_WINDOW_LANCZOS = 2
} shl_window_kind;

#define SHLIGHT_WINDOW_NONE 0

/* shl_zh_phong: ZH of the normalised Phong lobe (e+1)/(2 pi) max(0, cos t)^e about its axis:
   out_zh[l] = K_l Lambda_l(e) (docs/derivations.md section 5; the printed products of [SSF] sec.
   3.3.2).
   exponent: any real >= 0 (non-integer too); NaN or negative: 0 (the uniform hemisphere
   1/(2 pi)); above 1e30: 1e30, where every Lambda_l rounds to 1 (the Dirac limit, out_zh[l] =
   K_l). out_zh[0] = K_0 = 0.2820948 always (unit integral). Accuracy: within one float rounding
   of the exact value (binary128 quadrature) for e in [0, 1e4], n <= 64. out_zh: n floats.
   Cost: O(n), one division per band. */
SHLIGHT_INLINE void shl_zh_phong(int n, float exponent, float *out_zh);

/* shl_zh_cosine_power: ZH of the unnormalised clamped cosine power max(0, cos t)^e:
   out_zh[l] = 2 pi K_l Lambda_l(e) / (e+1) = sqrt(pi (2l+1)) int_0^1 x^e P_l(x) dx. Domain and
   accuracy as shl_zh_phong (e = 0: the hemisphere indicator, out_zh[0] = sqrt(pi); e = 1: the
   clamped cosine, out_zh = A_l K_l of docs/derivations.md section 6, for irradiance by
   shl_sh_conv_zh; above 1e30: 1e30, each coefficient ~2 pi K_l 1e-30). n floats. O(n). */
SHLIGHT_INLINE void shl_zh_cosine_power(int n, float exponent, float *out_zh);

/* shl_zh_lambert: ZH of the Lambert lobe max(0, cos t) / pi (k_d = 1; the BRDF times the
   cosine) about the normal: out_zh[l] = K_l Lambda_l(1) = (1/pi) K_l A_l with the
   Ramamoorthi-Hanrahan A_l (correction E7 (docs/derivations.md section 12): [SSF] even-l formula is
   off by 2, 16, 192, ...): 0.2820948, 0.3257350, 0.1576958, 0, -0.0352618, 0, 0.0158923, ...
   Multiply by pi for the clamped cosine (irradiance). Accuracy: one float rounding. out_zh: n
   floats. Cost: O(n). */
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
   functions, ZH zh_a about axis_a and ZH zh_b about axis_b (n floats each):
   sum_l zh_a[l] zh_b[l] P_l(axis_a . axis_b) (see >>brdf; equal to shl_sh_dot of the two rotated
   SH). Use it when the lobe is circularly symmetric about its own axis (Phong about the mirror
   direction, a microfacet lobe about the normal) and the radiance is a ZH (a sphere light's
   cap, an HVL). axis_a, axis_b: any finite non-zero vectors; zero, NaN or infinite: +z. n < 1: 0.
   Cost: O(n): two normalisations, n Legendre steps, 3n flops. */
SHLIGHT_INLINE float shl_zh_dot_zh(int n, const float *zh_a, const float axis_a[3],
                                   const float *zh_b, const float axis_b[3]);

/* shl_zh_irradiance_quadratic: irradiance E = int L(w) max(0, n . w) dw of a 3-band ZH radiance
   zh3 = (L_0, L_1, L_2) about an axis w_l, at a normal with z = w_l . n: [HVL] Appendix B,
   E = sigma^T M sigma, sigma = (z, 1), M = ((c3 L2, c2 L1), (c2 L1, c4 L0 - c5 L2)), i.e.
   c3 L2 z^2 + 2 c2 L1 z + c4 L0 - c5 L2 with the exact constants c2 = sqrt(3 pi)/6,
   c3 = 3 sqrt(5 pi)/16, c4 = sqrt(pi)/2, c5 = sqrt(5 pi)/16 (the printed 6-digit values
   differ by <= 1.1e-6). z outside [-1, 1]: clamped; NaN: 0. Cost: 5 flops. */
SHLIGHT_INLINE float shl_zh_irradiance_quadratic(const float *zh3, float z);

/* shl_sh_irradiance_matrix: the irradiance of a 3-band SH radiance as a quadratic form
   (Ramamoorthi, Hanrahan 2001, with this header's Condon-Shortley signs): for a unit normal
   (x, y, z), E = v^T M v with v = (x, y, z, 1), M = out_m (row-major, symmetric), equal to
   shl_sh_conv_zh(3, sh, (pi, 2pi/3, pi/4) / K_l, nrm). sh: the first 9 coefficients (bands
   0..2) of an SH of any band count; NaN / inf coefficients propagate. Accuracy: 2e-8 of
   sum |sh| against cubature. Ringing: behind a point light E dips to -3.7 % of its peak; window
   the SH (shl_zh_window) or clamp. GLSL: SHLIGHT_MAX_BANDS >= 3. Cost: 10 multiplies per SH,
   then per normal v^T M v (16 multiply-adds; no basis evaluation). */
SHLIGHT_INLINE void shl_sh_irradiance_matrix(const float *sh, float out_m[16]);

/* shl_zh_irradiance: the same for n bands, E(z) = sum_l A_l K_l L_l P_l(z), A_l = pi
   Lambda_l(1) (docs/derivations.md section 6): the exact irradiance of the band-limited radiance
   (its bands >= n are zero, so the clamped cosine's are not needed). zh: n floats; z as
   shl_zh_irradiance_quadratic. n < 1: 0. Cost: O(n). */
SHLIGHT_INLINE float shl_zh_irradiance(int n, const float *zh, float z);

/* shl_zh_window: multiplies band l of a ZH (io_zh, n floats) by a window sigma_l against
   ringing (Sloan, "Stupid SH tricks"; [HVL] sec. 4.2): kind SHLIGHT_WINDOW_HANNING (1):
   sigma_l = (1 + cos(pi l / width)) / 2; SHLIGHT_WINDOW_LANCZOS (2): sigma_l = sinc(l / width)
   = sin(pi l / width) / (pi l / width); both 0 for l >= width. width: the window's band count,
   > 0 (typically n, or n + 1 to keep the last band); <= 0 or NaN: n; +inf: sigma_l = 1 (the
   limit; every band kept). Another kind
   (SHLIGHT_WINDOW_NONE): unchanged. For an SH vector multiply its band l by the sigma_l that
   this returns for a ZH of ones. Measured on a cap (half-angle 30 deg, n = 8; tests/test_brdf,
   bench/out/brdf.md): see docs/accuracy.md. Cost: O(n). */
SHLIGHT_INLINE void shl_zh_window(int n, shl_window_kind kind, float width, float *io_zh);

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
   fov / sqrt(hvl_count) <= 0.41 (correction E9 (docs/derivations.md section 12); the paper's 0.2 is
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
   out_w[j] its weight, j < 4. Isotropic tables (n_phi = 1) with n_theta >= 4: cubic in the
   grid variable u, samples t0 - 1 .. t0 + 2 (t0 .. t0 + 3 in the first cell, t0 - 2 .. t0 + 1
   in the last) with their Lagrange weights (some negative; 4th order in the step: Phong
   e = 1000 at 90 samples within 5.2e-5 of the coefficient norm, 2.1e-3 when linear). Otherwise
   bilinear: (t0, p0), (t0 + 1, p0), (t0, p1), (t0 + 1, p1) with p1 = (p0 + 1) mod n_phi
   (n_theta = 2, 3 isotropic: weight 0 at j = 2, 3, indices repeating j = 0, 1); n_theta = 1
   puts all weight on t = 0. The weights add up to 1 (to float rounding). The samples
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
   memory, not in the caches. Smaller outputs past L1 (up to 10 bands) prefetch the next lines
   for writing. An output that is in no cache and cannot stream (count not a multiple of the
   width) pays a read of each line from memory: n = 16, count 1000, 2.0 of the loop
   (docs/speed-batch.md). */
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
   - anisotropic Beckmann / GGX, over the half vector in stretched slopes (h_x / alpha_x,
     h_y / alpha_y) / h_z = tan(u) (cos(ph), sin(ph)), where D is the isotropic one of width 1:
     outer ph (panels graded towards where the horizon's cut turns, and towards the smaller
     alpha's axis), inner u up to the horizon in closed form (panels at atan(3^k), -2 <= k < 8,
     graded towards the end; alpha > 1: both graded about w_i = z, where Lambda(w_i) has a
     near branch point), quad_order Gauss-Legendre nodes per panel;
   - Phong, in the frame whose pole is the mirror direction r of w_o: panels of the angle g from
     r with break points at 2, 6, 18, 54 lobe widths (width: 1/sqrt(e + 1)), where the circle of
     angle g about r first meets the horizon (g = pi/2 - theta_o) and where it leaves it;
     quad_order Gauss-Legendre nodes per panel after the same substitution; on each circle only
     the arc above the horizon (end points in closed form): 2 quad_order uniform nodes round a
     whole circle, else panels at 0, +-w/2, +-3w/2, +-9w/2 and graded towards the arc's ends
     (pm - L/4, /16, /64), quad_order Gauss-Legendre nodes each.
   Every panel's integrand is smooth, so the error falls geometrically with quad_order
   (docs/brdf-tables.md has the error against quad_order).
   Outgoing samples on the grid of >>brdftab (shl_brdf_table_theta), the last one at
   cos theta_o = SHLIGHT_BRDF_TABLE_GRAZING. Y by shl_sh_eval in float at the float-rounded
   node; the table rounds to float. Stack: about 15.3 KB deep (gcc -O2 -fstack-usage: 12.6 KB in
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
   to e = 1e6, Phong at q = 32 up to e = 1e6; anisotropic Beckmann / GGX at q = 24 for alphas
   in [1e-3, 4] (any ratio), every theta_o and phi_o (docs/brdf-tables.md). quad_order
   in [2, 256]. Returns SHLIGHT_EINVAL (data untouched) for NULL t / data / brdf, n, n_theta, n_phi
   out of range (see shl_brdf_table_size), flags != (n_phi > 1 ? ANISO : 0), an unknown model,
   negative or non-finite kd / ks, a Phong / Blinn-Phong exponent outside [0,
   SHLIGHT_BRDF_MAX_EXPONENT] (larger ones, up to 1e27, used to give non-finite tables), alpha
   outside [SHLIGHT_BRDF_MIN_ALPHA, 4] for Beckmann / GGX, f0 outside [0, 1] (microfacet models),
   quad_order out of range; SHLIGHT_ENOMEM when n > 16 and the 2 n^2-double accumulator (on the
   stack up to 16 bands) cannot be allocated. Cost: per sample, up to ~20 t panels x q x (2q .. 8q)
   nodes (isotropic microfacet), 4 .. 121 ph panels x q x (up to ~34 u panels x q) (anisotropic)
   or ~12 panels x q x (2q .. 14q) (specular frame), x 1.31 with
   out_err_est, each node one BRDF evaluation, one shl_sh_eval and 2 n^2 FMA. Measured, 90 samples,
   n = 9, one core of a loaded machine: GGX q = 16 0.18 s (alpha 1) .. 0.27 s (alpha 1e-3), q = 32
   0.75 .. 1.1 s; Phong 1000 q = 32 0.55 s; GGX (0.05, 0.2), 90 x 4 samples, q = 16 3.3 s. */
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
   linear along phi_d (periodic), then theta_d, then theta_h (trilinear inside the valid grid).
   Reconstruction (for grazing directions): the interpolant is of f cos(theta_h) cos(theta_d)
   = f (cos_i + cos_o) / 2, divided by the query's (cos_i + cos_o) / 2 (floored at 1e-9), so
   that the 1 / (cos_i + cos_o) growth of f at grazing is carried by the factor; only valid
   samples (> 0; MERL marks invalid ones negative) are used: where one of the two samples
   along an axis is invalid or beyond the grid (theta_h past the last sample, 88 deg in MERL
   files; theta_d past 89 deg), extrapolation from the valid one and its neighbours on the
   other side: quadratic through 3 samples where the second differences at the first two agree
   in sign and differ by at most the first's magnitude (noise does not pass this), else linear
   through 2, else the valid one held; with none in reach, the theta_d
   coordinate steps down a layer at a time (held along theta_d); 0 if none; negative
   extrapolations give 0. Invalid m or c: 0. Cost: ~100 flops, 2 acos, 2 atan2, 2 cos per
   sample read (8 inside the grid, up to 125 at its edges). Tables of a MERL file of GGX (alpha
   0.15 .. 1) are within 2x of the interior error at every theta_o (docs/brdf-tables.md). */
SHLIGHT_API float shl_merl_eval(const shl_merl *m, int c, const float wo[3], const float wi[3]);

/* shl_brdf_table_build_merl: shl_brdf_table_build for channel c of a measured BRDF (tables
   must be isotropic: n_phi = 1, flags 0): the whole BRDF by the half-vector quadrature of
   isotropic microfacet lobes (MERL data are isotropic), its panels at atan(0.01 3^k) and graded
   towards the horizon. Errors as shl_brdf_table_build (EINVAL also for an invalid m / c). */
SHLIGHT_API shl_result shl_brdf_table_build_merl(shl_brdf_table *t, const shl_merl *m, int c,
                                                 int quad_order, float *out_err_est);

/* ================================================================================================
   END OF THE API: stop here if you only want the API. The implementation follows.
   ================================================================================================
 */

/* >>numerics --------------------------------------------------------------------------------
   Domains and degenerate inputs: each public function's contract in >>api says what it
   accepts and what anything else gives (each case has a named test in tests/); n < 1 writes
   nothing, n > SHLIGHT_MAX_BANDS is taken as SHLIGHT_MAX_BANDS, in debug and release alike.
   The basis's Legendre part runs in shli_real (double in C, float in GLSL) with a Reinsch-type
   modified recurrence in t = 1 - |z|, which keeps the error growth linear in l at the poles
   instead of quadratic (docs/accuracy.md).
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
#ifndef SHLIGHT_BY_BANDS /* 1 in a C build: the GLSL shapes (tests/bands_impl.c holds them to C) \
                          */
#define SHLIGHT_BY_BANDS 0
#endif
/* 1 (GLSL): per-coefficient sums over several arrays as one flat run-time loop, which shader
   compilers do not unroll into huge bodies; 0 (C): nested loops (the same sums, same order) */
#define SHLIGHT_FLAT_LOOPS 0
/* SHLIGHT_UNROLL(k): unroll the next loop fully when its trip count is a constant <= k (gcc -O2
   does not on its own, nor clang for "GCC unroll"); SHLIGHT_ALWAYS_INLINE: inline the next kernel
   at every call site, so its constant arguments specialise it (GLSL: both empty) */
#define SHLIGHT_UNROLL_(x) _Pragma(#x)
#if defined(__clang__)
#define SHLIGHT_UNROLL(k) SHLIGHT_UNROLL_(clang loop unroll(full))
#elif defined(__GNUC__) && __GNUC__ >= 8
#define SHLIGHT_UNROLL(k) SHLIGHT_UNROLL_(GCC unroll k)
#else
#define SHLIGHT_UNROLL(k)
#endif
#if defined(__GNUC__) || defined(__clang__)
#define SHLIGHT_ALWAYS_INLINE __attribute__((always_inline))
#else
#define SHLIGHT_ALWAYS_INLINE
#endif
#define SHLIGHT_SET3(o, a, b, c) \
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
/* the microfacet polygon lights' double transcendentals: shlight's own polynomials in C (>>edge),
   the built-ins in GLSL */
#define SHLIGHT_MEXP(x) shli_mexp(x)
#define SHLIGHT_MLOG(x) shli_mlog(x)
#define SHLIGHT_MSIN(x) shli_msincos((x), 0)
#define SHLIGHT_MCOS(x) shli_msincos((x), 1)
#define SHLIGHT_POLYGON_ANY 1 /* C: any nv >= 3 (fan pieces); GLSL 0: above the max gives -1 */
/* 1 in C with AVX2 and FMA (GCC / Clang, not SHLIGHT_NO_SIMD): the GGX / Beckmann lights' edges
   and remainder in double lanes (shli_ggx_edges4, shli_ggx_tri4); GLSL 0 */
#if !defined(SHLIGHT_NO_SIMD) && defined(__AVX2__) && defined(__FMA__) && \
    (defined(__GNUC__) || defined(__clang__))
#define SHLIGHT_GGX_LANES 1
#else
#define SHLIGHT_GGX_LANES 0
#endif
#define SHLIGHT_CLIP_MAX 20           /* after two plane clips of a non-convex 8-gon (<= 2.25 nv) */
#define SHLIGHT_EDGE_STOKES_ADAPT 105 /* internal: EXACT's adaptive Stokes rule */
#define SHLIGHT_ADAPT_LEVELS 7        /* its most halvings (128 panels of 5 nodes per half-arc) */
#define SHLIGHT_ADAPT_TOL 1.0e-9      /* its stop: two successive levels this close (GLSL 2e-6) */
#define SHLIGHT_EDGE_FAST_ON \
  1                     /* GLSL: 0 unless the host defines it (compile cost, docs/accuracy.md) */
#define SHLIGHT_LANES 8 /* edges per block of the FAST edge loop (GLSL: 1) */
#define SHLIGHT_FAST_PAD (SHLIGHT_CLIP_MAX + SHLIGHT_LANES)
/* shl_polygon_ggx's and shl_polygon_beckmann's adaptive remainder (internal): a piece is split
   1 -> 4 where its error estimate exceeds SHLIGHT_GGX_TOL G1(view) (at most SHLIGHT_GGX_SPLITS
   splits, SHLIGHT_GGX_DEPTH levels below a fan triangle); the lobe near the horizon (n.l* <
   SHLIGHT_GGX_HOR alpha): graded about h*, up to GSPLITS (XSPLITS at n.v < 0.02) / GDEPTH */
#define SHLIGHT_GGX_TOL 1.0e-3
#define SHLIGHT_GGX_SPLITS 128
#define SHLIGHT_GGX_DEPTH 8
#define SHLIGHT_GGX_HOR 4.0
#define SHLIGHT_GGX_KAP 1.25
#define SHLIGHT_GGX_GRADE 0.8
#define SHLIGHT_GGX_GSPLITS 512
#define SHLIGHT_GGX_XSPLITS 2048
#define SHLIGHT_GGX_GDEPTH 16
#define SHLIGHT_HALF_K \
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

/* Tables of >>generated are read through accessors: SHLI_TAB_DECL(T, name, N) declares
   shli_tab_name() (a pointer to the whole T[N]), SHLI_NAME #defines read it, SHLI_TAB_FN defines it
   after the table. (docs/derivations.md sec. 13.1) */
#define SHLI_TAB_FN(name) SHLIGHT_CPU_INLINE const shli_tab_##name##_t *shli_tab_##name(void)
#define SHLI_TAB_DECL(T, name, N) \
  typedef T shli_tab_##name##_t[N]; \
  SHLI_TAB_FN(name)

/* @generated sh_tab: defined in >>generated at the end of the file */
SHLI_TAB_DECL(shli_real, sh_rsq, 128);
#define SHLI_SH_RSQ (*shli_tab_sh_rsq())
SHLI_TAB_DECL(shli_real, sh_s12, 128);
#define SHLI_SH_S12 (*shli_tab_sh_s12())
SHLI_TAB_DECL(float, sh_diag, 64);
#define SHLI_SH_DIAG (*shli_tab_sh_diag())

/* Reinsch constants of step l, column m (closed forms; docs/derivations.md sec. 13.52) */
SHLIGHT_CPU_INLINE void shli_sh_reinsch(int l, int m, shli_real *out_a, shli_real *out_g,
                                        shli_real *out_c) {
  shli_real q = SHLI_SH_RSQ[l - m] * SHLI_SH_RSQ[l + m];
  shli_real gq = SHLI_SH_S12[2 * l + 1] * q;
  *out_a = SHLI_SH_S12[2 * l] * q;
  *out_g = gq * (shli_real)(l + m);
  *out_c = gq * (shli_real)(l - m - 1);
}

/* Run-time loop for any n (docs/derivations.md sec. 13.53) */
SHLIGHT_CPU_INLINE void shli_sh_core_loop(int n, shli_real x, shli_real y, shli_real z, shli_real t,
                                          float sg, float *out_y) {
  shli_real pc = 1.0;
  shli_real ps = 0.0;
  shli_real qc;
  shli_real xa;
  shli_real dd;
  shli_real q;
  shli_real gq;
  shli_real fg;
  shli_real fc;
  const shli_real *qa;
  const shli_real *qb;
  const shli_real *sl;
  float *o;
  float ec;
  float es;
  float oc;
  float os;
  float sw;
  float k;
  float xf;
  int m;
  int l;
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
    /* step l (docs/derivations.md sec. 13.64) */
    qa = SHLI_SH_RSQ + 1;
    qb = SHLI_SH_RSQ + 2 * m + 1;
    sl = SHLI_SH_S12 + 2 * m + 2;
    fg = SHLIGHT_REAL(2 * m + 1);
    fc = 0.0;
    o = out_y + m * (m + 1);
    for (l = m + 1; l < n; ++l) {
      q = qa[0] * qb[0];
      gq = sl[1] * q;
      dd = (gq * fc) * dd - ((sl[0] * q) * t) * xa;
      xa = (gq * fg) * xa + dd;
      xf = SHLIGHT_FLOAT(xa);
      sw = ec;
      ec = oc;
      oc = sw;
      sw = es;
      es = os;
      os = sw;
      o = o + 2 * l;
      o[m] = xf * ec;
      if (m > 0) {
        o[-m] = xf * es;
      }
      qa = qa + 1;
      qb = qb + 1;
      sl = sl + 2;
      fg = fg + 1.0;
      fc = fc + 1.0;
    }
  }
}

/* @generated basis: defined in >>generated at the end of the file */
SHLIGHT_INLINE void shli_sh_poly_1(float x, float y, float z, float *out_y);
SHLIGHT_INLINE void shli_sh_poly_2(float x, float y, float z, float *out_y);
SHLIGHT_INLINE void shli_sh_poly_3(float x, float y, float z, float *out_y);
SHLIGHT_INLINE void shli_sh_poly_4(float x, float y, float z, float *out_y);
SHLIGHT_INLINE void shli_sh_poly_5(float x, float y, float z, float *out_y);
SHLIGHT_INLINE void shli_sh_poly_6(float x, float y, float z, float *out_y);
SHLIGHT_INLINE void shli_sh_core(int n, shli_real x, shli_real y, shli_real z, shli_real t,
                                 float sg, float *out_y);

/* Across-m SIMD core (C only, AVX-512): one 16-lane register holds X_l^m of every order m of band
   l; float lanes, SHLIGHT_NO_SIMD selects the double scalar kernel.
   (docs/derivations.md sec. 13.2) */
#if !defined(SHLIGHT_NO_SIMD) && defined(__AVX512F__)
#define SHLIGHT_SIMD_EVAL 1
#include <immintrin.h>
/* @generated lanes: defined in >>generated at the end of the file */
#if SHLIGHT_SIMD_EVAL
SHLI_TAB_DECL(float, sh_lanek, 190);
#define SHLI_SH_LANEK (*shli_tab_sh_lanek())
SHLI_TAB_DECL(float, sh_rsqf, 128);
#define SHLI_SH_RSQF (*shli_tab_sh_rsqf())
SHLI_TAB_DECL(float, sh_rsqr, 79);
#define SHLI_SH_RSQR (*shli_tab_sh_rsqr())
SHLI_TAB_DECL(int, sh_laner, 31);
#define SHLI_SH_LANER (*shli_tab_sh_laner())
SHLI_TAB_DECL(float, sh_lanes_s, 720);
#define SHLI_SH_LANES_S (*shli_tab_sh_lanes_s())
#endif
/* @generated plane: defined in >>generated at the end of the file */
#if SHLIGHT_SIMD_EVAL
SHLI_TAB_DECL(float, sh_planes, 120);
#define SHLI_SH_PLANES (*shli_tab_sh_planes())
SHLI_TAB_DECL(int, sh_ptap, 40);
#define SHLI_SH_PTAP (*shli_tab_sh_ptap())
SHLI_TAB_DECL(int, sh_podd, 5);
#define SHLI_SH_PODD (*shli_tab_sh_podd())
#endif
#ifdef __AVX512VL__
/* n = 4..6 (C only, AVX-512VL): the Horner forms of shli_sh_poly_<n> across the outputs, lane i =
   output i; same coefficients and input as shli_sh_poly_<n>. (docs/derivations.md sec. 13.3) */
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

/* Full unrolling with a literal n (docs/derivations.md sec. 13.54) */
#if defined(__clang__)
#define SHLI_UNROLL_BANDS _Pragma("unroll")
#elif defined(__GNUC__) && __GNUC__ >= 8
#define SHLI_UNROLL_BANDS _Pragma("GCC unroll 16")
#else
#define SHLI_UNROLL_BANDS
#endif

/* n <= 16 with AVX-512VL, 256-bit registers (docs/derivations.md sec. 13.55) */
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

/* The order lanes of the 512-bit across-m cores for n <= 16 at (x, y, z), |d| ~ 1: lv[0..1] (x +
   iy)^m renormalised, lv[2..3] the same times sg, lv[4] = t. (docs/derivations.md sec. 13.4) */
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

/* n > 16: band l's step in chunk h (16 orders), constants as in shli_sh_reinsch, then the cosines
   and the sines; xv, dd, cc, ss: named registers. (docs/derivations.md sec. 13.5) */
#define SHLI_SH_CHUNK512(h, xv, dd, cc, ss) \
  do { \
    __mmask16 mk = (__mmask16) ~((__mmask64)0xFFFF << (l - 16 * (h))); \
    __m512 gq = _mm512_maskz_mul_ps( \
               mk, _mm512_mul_ps(sq, _mm512_loadu_ps(SHLI_SH_RSQF + l + 16 * (h))), \
               _mm512_loadu_ps(SHLI_SH_RSQR + 63 - l + 16 * (h))), \
           ys; \
    __m512 at = _mm512_mul_ps(gq, wt); \
    __m512 cn = _mm512_mul_ps(gq, _mm512_loadu_ps(SHLI_SH_LANEK + 64 + 16 * (h)-l)); \
    __m512 gg = \
        _mm512_mask_mul_ps(one, mk, gq, _mm512_loadu_ps(SHLI_SH_LANEK + 63 + 16 * (h) + l)); \
    int top = l < 16 * (h) + 15 ? l : 16 * (h) + 15; /* largest order of the chunk in band l */ \
    int lo = (h) > 0 ? 16 * (h) : 1;                 /* smallest sine order of the chunk */ \
    dd = _mm512_fnmsub_ps(at, xv, _mm512_mul_ps(cn, dd)); /* D = c D - alpha t X, cn = -c */ \
    xv = _mm512_fmadd_ps(gg, xv, dd); \
    ys = _mm512_permutexvar_ps( \
        _mm512_loadu_si512((const void *)(SHLI_SH_LANER + 15 - (top - 16 * (h)))), \
        _mm512_mul_ps(xv, ss)); \
    _mm512_mask_storeu_ps(out_y + l * l + l - top, (__mmask16)((2u << (top - lo)) - 1u), ys); \
    _mm512_mask_storeu_ps(out_y + l * l + l + 16 * (h), \
                          (__mmask16)((2u << (top - 16 * (h))) - 1u), _mm512_mul_ps(xv, cc)); \
  } while (0)
/* band l (then l + 1) in the chunks 0 .. nk - 1; P: the parity's order lanes, c or co */
#define SHLI_SH_BAND512(nk, P) \
  do { \
    __m512 sq = _mm512_set1_ps((float)SHLI_SH_S12[2 * l + 1]); /* s2_l */ \
    __m512 wt = _mm512_mul_ps(_mm512_set1_ps((float)(2 * l - 1)), vt); \
    SHLI_SH_CHUNK512(0, x0, d0, P##0, P##s0); \
    if ((nk) > 1) { \
      SHLI_SH_CHUNK512(1, x1, d1, P##1, P##s1); \
    } \
    if ((nk) > 2) { \
      SHLI_SH_CHUNK512(2, x2, d2, P##2, P##s2); \
    } \
    if ((nk) > 3) { \
      SHLI_SH_CHUNK512(3, x3, d3, P##3, P##s3); \
    } \
    ++l; \
  } while (0)
/* bands up to e (exclusive) with nk chunks, two a trip (even, odd) from an even l */
#define SHLI_SH_BANDS512(nk, end) \
  for (; l + 1 < (end);) { \
    SHLI_SH_BAND512(nk, e); \
    SHLI_SH_BAND512(nk, o); \
  } \
  if (l < (end)) { \
    SHLI_SH_BAND512(nk, e); \
  }
SHLIGHT_CPU_INLINE void shli_sh_eval_avx512(int n, float x, float y, float z, float *out_y) {
  static const unsigned short bits[4] = {0xAAAA, 0xCCCC, 0xF0F0, 0xFF00};
  /* float prologue (docs/derivations.md sec. 13.56) */
  float s2 = x * x + y * y;
  float ez = (z - 1.0f) * (z + 1.0f) + s2;
  float k = 1.0f + ez * (-0.5f + 0.375f * ez);
  float cr = x * k, ci = y * k, q;
  /* chunk h: lanes j hold m = 16 h + j; e0.., es0..: (x + iy)^m times sg^m (even bands),
     o0.., os0..: times sg^(m + 1) (odd bands) */
  __m512 e0, e1, e2, e3, es0, es1, es2, es3, o0, o1, o2, o3, os0, os1, os2, os3;
  __m512 x0, x1, x2, x3, d0, d1, d2, d3, vs, vt, vc, vi, one = _mm512_set1_ps(1.0f);
  __mmask16 odd = (__mmask16)0xAAAA;
  int b, l, ftz = n > 32 && s2 < 0.1f;
  unsigned csr = 0;
  if (ftz) { /* FTZ + DAZ near the poles (docs/speed.md sec. 1.3) */
    csr = _mm_getcsr();
    _mm_setcsr(csr | 0x8040u);
  }
  vt = _mm512_set1_ps(s2 / (1.0f + fabsf(z)));
  vs = _mm512_set1_ps(copysignf(1.0f, z));
  e0 = one;
  es0 = _mm512_setzero_ps();
  /* (x + iy)^j by lanes (docs/derivations.md sec. 13.65) */
  for (b = 0; b < 4; ++b) {
    __m512 nc, ns;
    vc = _mm512_set1_ps(cr);
    vi = _mm512_set1_ps(ci);
    nc = _mm512_fmsub_ps(e0, vc, _mm512_mul_ps(es0, vi));
    ns = _mm512_fmadd_ps(es0, vc, _mm512_mul_ps(e0, vi));
    e0 = _mm512_mask_mov_ps(e0, (__mmask16)bits[b], nc);
    es0 = _mm512_mask_mov_ps(es0, (__mmask16)bits[b], ns);
    q = cr * cr - ci * ci;
    ci = 2.0f * cr * ci;
    cr = q;
  }
  vc = _mm512_set1_ps(cr);
  vi = _mm512_set1_ps(ci);
  e1 = _mm512_fmsub_ps(e0, vc, _mm512_mul_ps(es0, vi));
  es1 = _mm512_fmadd_ps(es0, vc, _mm512_mul_ps(e0, vi));
  /* chunks 2, 3 only if read: subnormal near the poles (docs/speed.md sec. 1.3) */
  e2 = e3 = es2 = es3 = _mm512_setzero_ps();
  if (n > 32) {
    e2 = _mm512_fmsub_ps(e1, vc, _mm512_mul_ps(es1, vi));
    es2 = _mm512_fmadd_ps(es1, vc, _mm512_mul_ps(e1, vi));
  }
  if (n > 48) {
    e3 = _mm512_fmsub_ps(e2, vc, _mm512_mul_ps(es2, vi));
    es3 = _mm512_fmadd_ps(es2, vc, _mm512_mul_ps(e2, vi));
  }
  /* parity: X_l^m(z) = sg^(l-m) X_l^m(|z|); sg^m into the odd lanes (16 h is even), sg^l per
     band through the odd-band copies */
  e0 = _mm512_mask_mul_ps(e0, odd, e0, vs);
  e1 = _mm512_mask_mul_ps(e1, odd, e1, vs);
  e2 = _mm512_mask_mul_ps(e2, odd, e2, vs);
  e3 = _mm512_mask_mul_ps(e3, odd, e3, vs);
  es0 = _mm512_mask_mul_ps(es0, odd, es0, vs);
  es1 = _mm512_mask_mul_ps(es1, odd, es1, vs);
  es2 = _mm512_mask_mul_ps(es2, odd, es2, vs);
  es3 = _mm512_mask_mul_ps(es3, odd, es3, vs);
  o0 = _mm512_mul_ps(e0, vs);
  o1 = _mm512_mul_ps(e1, vs);
  o2 = _mm512_mul_ps(e2, vs);
  o3 = _mm512_mul_ps(e3, vs);
  os0 = _mm512_mul_ps(es0, vs);
  os1 = _mm512_mul_ps(es1, vs);
  os2 = _mm512_mul_ps(es2, vs);
  os3 = _mm512_mul_ps(es3, vs);
  x0 = _mm512_loadu_ps(SHLI_SH_DIAG);
  x1 = _mm512_loadu_ps(SHLI_SH_DIAG + 16);
  x2 = _mm512_loadu_ps(SHLI_SH_DIAG + 32);
  x3 = _mm512_loadu_ps(SHLI_SH_DIAG + 48);
  d0 = _mm512_setzero_ps();
  d1 = d0;
  d2 = d0;
  d3 = d0;
  out_y[0] = SHLI_SH_DIAG[0];
  l = 1;
  SHLI_SH_BAND512(1, o); /* bands 1..15: chunk 0 */
  SHLI_SH_BANDS512(1, 16)
  SHLI_SH_BANDS512(2, n < 32 ? n : 32)
  SHLI_SH_BANDS512(3, n < 48 ? n : 48)
  SHLI_SH_BANDS512(4, n)
  if (ftz) {
    _mm_setcsr(csr);
  }
}
#undef SHLI_SH_BANDS512
#undef SHLI_SH_BAND512
#undef SHLI_SH_CHUNK512
/* AVX-512 gradient pass tables for 2..16 bands (C only; tools/gen_grad_simd.py): lanes follow the
   output array. (docs/derivations.md sec. 13.6) */
#if defined(__GNUC__) || defined(__clang__)
#define SHLI_GRADV_ALIGN __attribute__((aligned(64)))
#else
#define SHLI_GRADV_ALIGN
#endif
/* @generated gradv: defined in >>generated at the end of the file */
SHLI_TAB_DECL(short, gradv_ch0, 17);
#define SHLI_GRADV_CH0 (*shli_tab_gradv_ch0())
SHLI_TAB_DECL(float, gradv_lf, 16);
#define SHLI_GRADV_LF (*shli_tab_gradv_lf())
SHLI_TAB_DECL(unsigned short, gradv_lastm, 16);
#define SHLI_GRADV_LASTM (*shli_tab_gradv_lastm())
SHLI_TAB_DECL(unsigned short, gradv_ym, 32);
#define SHLI_GRADV_YM (*shli_tab_gradv_ym())
SHLI_TAB_DECL(int, gradv_iy, 96);
#define SHLI_GRADV_IY (*shli_tab_gradv_iy())
SHLI_TAB_DECL(int, gradv_tap, 192);
#define SHLI_GRADV_TAP (*shli_tab_gradv_tap())
SHLI_TAB_DECL(float, gradv_coef, 1760);
#define SHLI_GRADV_COEF (*shli_tab_gradv_coef())
#define SHLI_GRADV_MASK(t) ((__mmask16) * (t))

/* chunk c of band l (docs/derivations.md sec. 13.57) */
#define SHLI_GRADV_TAPS(c, t, ly) \
  _mm512_add_epi32(_mm512_loadu_si512((const void *)(SHLI_GRADV_TAP + 32 * (c) + 16 * (t))), (ly))
/* bands 1..7: P (<= 13 lanes) and Y (<= 15 lanes) in one zmm each */
#define SHLI_GRADV_CHUNK1(c, w, ly) \
  r = _mm512_fmadd_ps(_mm512_loadu_ps(cf + 32 * (c)), \
                      _mm512_permutexvar_ps(SHLI_GRADV_TAPS(c, 0, ly), p0), \
                      _mm512_fmadd_ps(_mm512_loadu_ps(cf + 32 * (c) + 16), \
                                      _mm512_permutexvar_ps(SHLI_GRADV_TAPS(c, 1, ly), p0), \
                                      _mm512_mul_ps(_mm512_permutexvar_ps(iy##c, q0), (w))))
/* bands 8..15: two zmm each */
#define SHLI_GRADV_CHUNK2(c, w, ly) \
  r = _mm512_fmadd_ps(_mm512_loadu_ps(cf + 32 * (c)), \
                      _mm512_permutex2var_ps(p0, SHLI_GRADV_TAPS(c, 0, ly), p1), \
                      _mm512_fmadd_ps(_mm512_loadu_ps(cf + 32 * (c) + 16), \
                                      _mm512_permutex2var_ps(p0, SHLI_GRADV_TAPS(c, 1, ly), p1), \
                                      _mm512_mul_ps(_mm512_permutex2var_ps(q0, iy##c, q1), (w))))
#define SHLI_GRADV_STORE(c) \
  if (nc == (c) + 1) { \
    _mm512_mask_storeu_ps(ol + 16 * (c), SHLI_GRADV_MASK(SHLI_GRADV_LASTM + l), r); \
    break; \
  } \
  _mm512_storeu_ps(ol + 16 * (c), r)
/* per band: w lanes for chunks c % 3 == 0, 1, 2 (b u + e v; vK lane j = v[(K + j) % 3]), and 2l
   on the y lanes */
#define SHLI_GRADV_BAND(l, b, e) \
  w0 = _mm512_mul_ps(_mm512_set1_ps(b), u0); \
  w1 = _mm512_mul_ps(_mm512_set1_ps(b), u1); \
  w2 = _mm512_mul_ps(_mm512_set1_ps(b), u2); \
  if (v3) { \
    w0 = _mm512_fmadd_ps(_mm512_set1_ps(e), s0, w0); \
    w1 = _mm512_fmadd_ps(_mm512_set1_ps(e), s1, w1); \
    w2 = _mm512_fmadd_ps(_mm512_set1_ps(e), s2, w2); \
  } \
  ly0 = _mm512_maskz_set1_epi32((__mmask16)0x2492, 2 * (l)); \
  ly1 = _mm512_maskz_set1_epi32((__mmask16)0x9249, 2 * (l)); \
  ly2 = _mm512_maskz_set1_epi32((__mmask16)0x4924, 2 * (l))
/* lane j = (a, b, c)[j % 3] */
#define SHLI_GRADV_AOS(a, b, c) \
  _mm512_mask_blend_ps((__mmask16)0x4924, _mm512_mask_blend_ps((__mmask16)0x2492, (a), (b)), (c))

/* AVX-512 gradient pass for 1..16 bands (C only): out_grad[i] = a_l grad H_l^m(u) + (b_l u + e_l v)
   Y_i; bw == NULL: the gradient of Y(d / |d|) (out_y not written), else bw[4 l ..] = (kv_l, a_l,
   b_l, e_l) and out_y[i] = kv_l Y_i. (docs/derivations.md sec. 13.7) */
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
  /* bands 1..7 of Y loaded first (docs/derivations.md sec. 13.58) */
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
    /* lanes: docs/derivations.md sec. 13.66 */
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
    /* not unit: normalised, or (0, 0, 1) (docs/derivations.md sec. 13.59) */
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

/* Y_i at (dx, dy, dz), the one evaluation path (docs/derivations.md sec. 13.63) */
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

/* >>gradient ---------------------------------------------------------------------------------
   Cartesian gradient of Y_i(d / |d|), pole-free, through the solid harmonics.
   (docs/derivations.md sec. 13.8) */

/* Gradient for n > 16 (C only; docs/derivations.md sec. 13.60) */
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

/* @generated gradient: defined in >>generated at the end of the file */
SHLIGHT_INLINE void shli_sh_grad(int n, const float *y, float nx, float ny, float nz, float ir,
                                 float ib, float (*out_grad)[3]);
SHLIGHT_INLINE void shli_sh_grad_band(int l, const float *y, float nx, float ny, float nz, float ir,
                                      float ib, float *out_gb);

#if SHLIGHT_SIMD_EVAL
/* shl_sh_eval_grad, 3..16 bands, AVX-512: 1 if written (docs/derivations.md sec. 13.61) */
SHLIGHT_CPU_INLINE int shli_sh_eval_grad_avx512(int n, const float d[3], float *out_y,
                                                float (*out_grad)[3]) {
  /* |d|^2 in [1e-30, 1e30]: rsqrt14 and one Newton step in double (1 / |d| to 6e-9).
     (docs/derivations.md sec. 13.9) */
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

/* d of shl_sh_eval_grad: out_g[0..2] d / |d| (or (0,0,1)), [3], [4] ir, ib: 1 / |d| = ir ib */
SHLIGHT_INLINE void shli_sh_grad_frame(const float d[3], float *out_g) {
  shli_real x = SHLIGHT_REAL(d[0]);
  shli_real y = SHLIGHT_REAL(d[1]);
  shli_real z = SHLIGHT_REAL(d[2]);
  shli_real mx = SHLIGHT_ABSR(x);
  shli_real im;
  shli_real iu;
  float ir;
  float ib;
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
  /* 1 / |d| = ir ib (docs/derivations.md sec. 13.62) */
  iu = iu * im;
  ir = SHLIGHT_FLOAT(iu);
  ib = 1.0f;
  if (iu > 1.0e30) {
    ir = SHLIGHT_FLOAT(SHLIGHT_SQRTR(iu));
    ib = ir;
  }
  out_g[0] = SHLIGHT_FLOAT(x);
  out_g[1] = SHLIGHT_FLOAT(y);
  out_g[2] = SHLIGHT_FLOAT(z);
  out_g[3] = ir;
  out_g[4] = ib;
}

SHLIGHT_INLINE void shl_sh_eval_grad(int n, const float d[3], float *out_y, float (*out_grad)[3]) {
  float g[8];
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
  shli_sh_grad_frame(d, g);
  shli_sh_eval_xyz(n, g[0], g[1], g[2], out_y);
#if SHLIGHT_SIMD_EVAL
  if (n >= 5 && n <= SHLIGHT_UNROLLED_BANDS && g[4] == 1.0f) {
    shli_sh_grad_avx512(n, out_y, g[0], g[1], g[2], g[3], 0, 0, 0, out_grad);
    return;
  }
#endif
  /* one call (a second inlined copy and a rescaling loop over out_grad cost a shader ~100x
     its compile time): ib = 1 leaves every output exact */
  shli_sh_grad(n, out_y, g[0], g[1], g[2], g[3], g[4], out_grad);
}

#if !SHLIGHT_BY_BANDS || SHLIGHT_MAX_BANDS > SHLIGHT_UNROLLED_BANDS
/* C, n > 16: one pass over the values as the Reinsch recurrence makes them (column m, band l),
   each y_lj added to f and the radial sum and, by the terms of band l + 1 transposed, to the
   three Cartesian sums (docs/derivations.md sec. 3); no buffer */
#define SHLI_S(i) ((shli_real)sh[i])
SHLIGHT_CPU_INLINE float shli_sh_dot_grad_stream(int n, const float *sh, const float d[3],
                                                 float *out_grad) {
  float g[8];
  shli_real x, y, z, t, pc = 1.0, ps = 0.0, s[5] = {0.0, 0.0, 0.0, 0.0, 0.0}, v, xa, dd, ra, rg;
  shli_real rc, s2, ca, cp, cb, bp, cd, cc, yc, ys, ec, es, oc, os, sw, sg, fa, fb;
  const shli_real *q = SHLI_SH_RSQ;
  int m, l, b, j, u;
  shli_sh_grad_frame(d, g);
  x = (shli_real)g[0], y = (shli_real)g[1], z = (shli_real)g[2], sg = (shli_real)SHLIGHT_SIGN1(z);
  t = (x * x + y * y) / (1.0 + SHLIGHT_ABSR(z));
  for (m = 0; m < n; ++m) {
    if (m > 0) {
      v = x * pc - y * ps;
      ps = x * ps + y * pc;
      pc = v;
    }
    ec = pc, es = ps, oc = sg * pc, os = sg * ps, xa = (shli_real)SHLI_SH_DIAG[m], dd = 0.0;
    fa = m == 0 ? 1.4142135623730951 : 1.0, fb = m == 1 ? 1.4142135623730951 : 1.0;
    for (l = m; l < n; ++l) {
      if (l > m) {
        shli_sh_reinsch(l, m, &ra, &rg, &rc);
        dd = rc * dd - (ra * t) * xa;
        xa = rg * xa + dd;
        sw = ec, ec = oc, oc = sw, sw = es, es = os, os = sw;
      }
      b = l * (l + 1), yc = xa * ec, ys = m > 0 ? xa * es : 0.0;
      v = SHLI_S(b + m) * yc + (m > 0 ? SHLI_S(b - m) * ys : 0.0);
      s[0] += v, s[1] += l * v;
      if (l + 1 < n) { /* band u = l + 1, orders j - 1, j, j + 1: sqrt(a b) = a b q[a] q[b] */
        u = l + 1, j = m, b = u * (u + 1), s2 = SHLI_SH_S12[2 * u + 1];
        ca = -0.5 * s2 * (u + j + 1) * (u + j) * q[u + j + 1] * q[u + j];
        cp = ca * fa;
        cb = j >= 1 ? 0.5 * s2 * (u - j + 1) * (u - j) * q[u - j + 1] * q[u - j] : 0.0;
        bp = cb * fb;
        cd = j >= 2 ? cb : 0.0;
        cc = s2 * (u - j) * (u + j) * q[u - j] * q[u + j];
        s[2] += yc * (cp * SHLI_S(b + j + 1) + bp * SHLI_S(b + j - 1)) +
                ys * (ca * SHLI_S(b - j - 1) + cd * SHLI_S(b - j + 1));
        s[3] += yc * (cp * SHLI_S(b - j - 1) - cd * SHLI_S(b - j + 1)) +
                ys * (bp * SHLI_S(b + j - 1) - ca * SHLI_S(b + j + 1));
        s[4] += cc * (yc * SHLI_S(b + j) + ys * SHLI_S(b - j));
      }
    }
  }
  for (j = 0; j < 3; ++j)
    out_grad[j] = SHLIGHT_FLOAT((s[j + 2] - s[1] * (shli_real)g[j]) * (shli_real)g[3]) * g[4];
  return SHLIGHT_FLOAT(s[0]);
}
#undef SHLI_S

/* C: shl_sh_eval_grad and the sums, four independent partial sums per output (overflow: again
   at d / |d|, times ir ib) */
SHLIGHT_CPU_INLINE float shli_sh_dot_grad_c(int n, const float *sh, const float d[3],
                                            float *out_grad) {
  float y[256], gr[256][3], g[8] = {0.0f, 0.0f, 0.0f, 1.0f, 1.0f, 0.0f, 0.0f, 0.0f};
  shli_real s[4][4], t[4], c;
  int i, j, k, p;
  if (n > SHLIGHT_UNROLLED_BANDS) {
    return shli_sh_dot_grad_stream(n, sh, d, out_grad);
  }
  for (p = 0; p < 2; ++p) {
    shl_sh_eval_grad(n, p ? g : d, y, gr);
    for (i = 0; i < 16; ++i)
      s[i >> 2][i & 3] = 0.0;
    for (i = 0; i < n * n; ++i) {
      j = i & 3;
      c = (shli_real)sh[i];
      s[0][j] += c * (shli_real)y[i];
      s[1][j] += c * (shli_real)gr[i][0];
      s[2][j] += c * (shli_real)gr[i][1];
      s[3][j] += c * (shli_real)gr[i][2];
    }
    for (k = 0; k < 4; ++k)
      t[k] = (s[k][0] + s[k][1]) + (s[k][2] + s[k][3]);
    for (k = 0; k < 3; ++k)
      out_grad[k] = SHLIGHT_FLOAT(t[k + 1] * (shli_real)g[3]) * g[4];
    c = t[1] + t[2] + t[3];
    if (c - c == 0.0) break;
    shli_sh_grad_frame(d, g);
  }
  return SHLIGHT_FLOAT(t[0]);
}
#endif

/* band l (1..15) of shl_sh_eval_dot_grad: shli_sh_grad_band at u = 0, 1 / |d| = 1 (folded)
   times sh, added to io_g; returns the band's share of f */
SHLIGHT_INLINE float shli_sh_grad_dot_band(int l, const float *y, const float *sh, float io_g[3]) {
  float gb[93];
  float cs[31];
  float v = 0.0f;
  int k;
  shli_sh_grad_band(l, y, 0.0f, 0.0f, 0.0f, 1.0f, 1.0f, gb);
  for (k = 0; k < 31; ++k) {
    cs[k] = 0.0f;
    if (k >= 15 - l && k <= 15 + l) {
      cs[k] = sh[l * l + l + k - 15];
    }
  }
  for (k = 0; k < 31; ++k) {
    if (k >= 15 - l && k <= 15 + l) {
      io_g[0] = io_g[0] + cs[k] * gb[3 * k];
      io_g[1] = io_g[1] + cs[k] * gb[3 * k + 1];
      io_g[2] = io_g[2] + cs[k] * gb[3 * k + 2];
      v = v + cs[k] * y[l * l + l + k - 15];
    }
  }
  return v;
}

SHLIGHT_INLINE float shl_sh_eval_dot_grad(int n, const float *sh, const float d[3],
                                          float out_grad[3]) {
  float ysh[SHLI_YBUF_COEFFS];
  float vb[SHLIGHT_MAX_BANDS];
  float g[8];
  float f = 0.0f;
  float t = 0.0f;
  int l;
  n = shli_bands(n);
  SHLIGHT_SET3(out_grad, 0.0f, 0.0f, 0.0f);
  if (n < 1) {
    return 0.0f;
  }
#if !SHLIGHT_BY_BANDS || SHLIGHT_MAX_BANDS > SHLIGHT_UNROLLED_BANDS
  if (!SHLIGHT_BY_BANDS || n > SHLIGHT_UNROLLED_BANDS) {
    return shli_sh_dot_grad_c(n, sh, d, out_grad);
  }
#endif
  shli_sh_grad_frame(d, g);
  shli_sh_eval_xyz(n, g[0], g[1], g[2], ysh);
  /* a band per trip; the arrays vb and cs make Mesa unroll the loops (docs/glsl.md) */
  for (l = 0; l < SHLIGHT_MAX_BANDS; ++l) {
    vb[l] = 0.0f;
    if (l == 0) {
      vb[l] = sh[0] * ysh[0];
    } else if (l < n) {
      vb[l] = shli_sh_grad_dot_band(l, ysh, sh, out_grad);
    }
  }
  for (l = 0; l < SHLIGHT_MAX_BANDS; ++l) {
    f = f + vb[l];
    t = t + SHLIGHT_ITOF(l) * vb[l];
  }
  for (l = 0; l < 3; ++l) {
    out_grad[l] = ((out_grad[l] - t * g[l]) * g[3]) * g[4];
  }
  return f;
}

/* >>zonal ------------------------------------------------------------------------------------
   ZH of a uniform spherical cap (cancellation-free forms) and ZH -> SH rotation.
   (docs/derivations.md sec. 13.10) */

/* Per band l < 64: (2l+1)/(l+1), l/(l+1), 1/(l(l+1)) (0 for l = 0), sqrt(4 pi/(2l+1)),
   sqrt(pi(2l+1)): the Legendre recurrence and the ZH normalisations without divisions
   (tools/gen_basis.py; the GLSL twin holds the first 16 bands). */
/* @generated zh_tab: defined in >>generated at the end of the file */
SHLI_TAB_DECL(shli_real, zh_tab, 320);
#define SHLI_ZH_TAB (*shli_tab_zh_tab())

/* Geometry of a sphere seen from a point (shli_real), (dx, dy, dz) = c - x: out_g[0..2] unit axis,
   [3] 1 / |c - x|, [4] s^2, [5] alpha, [6] 1 for a light, 0 for none.
   (docs/derivations.md sec. 13.11) */
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

/* shl_sh_rotate's C-only path for n <= 8 (GCC / Clang; docs/derivations.md sec. 13.67) */
#ifndef SHLIGHT_ROTATE_FAST
#if defined(__GNUC__) || defined(__clang__)
#define SHLIGHT_ROTATE_FAST 1
#else
#define SHLIGHT_ROTATE_FAST 0
#endif
#endif
#if SHLIGHT_ROTATE_FAST
#if defined(__AVX__)
#include <immintrin.h>
#elif defined(__SSE2__)
#include <emmintrin.h>
#endif
#define SHLI_ROT_FAST_BANDS 8
/* how far from a rotation R may be and still be taken as given (see the contract) */
#define SHLI_ROT_ORTH 1e-6
/* clang-format off */
static const double SHLI_ROT_X90[320] = {
.61237244,.7905694,0,0,.7905694,-.61237244,0,0,0,0,0,0,0,0,0,0,-.25,-.96824584,0,0,-.96824584,.25,0,
0,0,0,0,0,0,0,0,0,0,0,0,0,0,-1,0,0,0,0,0,0,0,0,0,0,-.61237244,-.7905694,0,0,-.7905694,.61237244,0,0,
0,0,0,0,0,0,0,0,.375,.559017,.73951,0,.559017,.5,-.6614378,0,.73951,-.6614378,.125,0,0,0,0,0,0,0,0,
0,.35355339,.93541435,0,0,.93541435,-.35355339,0,0,0,0,0,0,0,-.35355339,-.93541435,0,0,-.93541435,
.35355339,0,0,0,0,0,0,0,0,0,.75,.6614378,0,0,.6614378,-.75,0,0,0,0,0,0,0,0,0,0,-.48412292,-.6614378,
-.572822,0,-.5229125,-.30618622,.79549513,0,-.70156076,.6846532,-.19764235,0,0,0,0,0,.125,.40504629,
.90571105,0,.40504629,.8125,-.41926275,0,.90571105,-.41926275,.0625,0,0,0,0,0,0,0,0,0,0,.5,.8660254,
0,0,.8660254,-.5,0,0,0,0,0,.48412292,.5229125,.70156076,0,.6614378,.30618622,-.6846532,0,.572822,
-.79549513,.19764235,0,0,0,0,0,-.3125,-.45285552,-.49607837,-.67169329,-.45285552,-.53125,-.1711633,
.69526861,-.49607837,-.1711633,.8125,-.2538762,-.67169329,.69526861,-.2538762,.03125,0,0,0,0,
-.19764235,-.5625,-.80282704,0,-.4330127,-.6846532,.586302,0,-.87945295,.4635124,-.108253175,0,0,
.19764235,.4330127,.87945295,0,.5625,.6846532,-.4635124,0,.80282704,-.586302,.108253175,0,0,0,0,
-.625,-.59292706,-.5077524,0,-.59292706,-.0625,.80282704,0,-.5077524,.80282704,-.3125,0,0,0,0,0,
.41339864,.5740992,.53855275,.45768183,.42961647,.41984465,-.103644525,-.7927282,.47495888,
.07328775,-.78125,.3983609,.64725985,-.6991205,.298106,-.0584634,-.078125,-.24356964,-.44879396,
-.8562443,-.24356964,-.609375,-.5700449,.49435288,-.44879396,-.5700449,.671875,-.149053,-.8562443,
.49435288,-.149053,.015625,0,0,0,0,0,-.3125,-.586302,-.7473913,0,-.586302,-.5,.63737744,0,-.7473913,
.63737744,-.1875,-.41339864,-.42961647,-.47495888,-.64725985,-.5740992,-.41984465,-.07328775,
.6991205,-.53855275,.103644525,.78125,-.298106,-.45768183,.7927282,-.3983609,.0584634
};
/* clang-format on */
#if defined(__clang__)
#define SHLI_ROT_UNROLL _Pragma("unroll")
#elif defined(__GNUC__) && __GNUC__ >= 8
#define SHLI_ROT_UNROLL _Pragma("GCC unroll 16")
#else
#define SHLI_ROT_UNROLL
#endif
#define SHLI_ROT_FORCE __attribute__((always_inline))
#define SHLI_ROT_NOINLINE static __attribute__((noinline, unused))
/* GCC's SLP vectoriser off where it costs time */
#if defined(__GNUC__) && !defined(__clang__) && defined(__AVX512F__)
#define SHLI_ROT_NOSLP __attribute__((optimize("no-tree-slp-vectorize")))
#else
#define SHLI_ROT_NOSLP
#endif
#if defined(__GNUC__) && !defined(__clang__)
#define SHLI_ROT_SCALAR __attribute__((optimize("no-tree-slp-vectorize")))
#else
#define SHLI_ROT_SCALAR
#endif
typedef double shli_rot_v4 __attribute__((vector_size(32)));
typedef float shli_rot_v8 __attribute__((vector_size(32)));
typedef __INT32_TYPE__ shli_rot_i8 __attribute__((vector_size(32)));

/* d <= SHLI_ROT_ORTH (NaN fails); near2: 2 entries of r0 x r1 - r2 given */
SHLI_ROT_FORCE SHLIGHT_CPU_INLINE int shli_rot_near2(const float R[9], double x0, double x1) {
  double r00 = (double)R[0];
  double r01 = (double)R[1];
  double r02 = (double)R[2];
  double r10 = (double)R[3];
  double r11 = (double)R[4];
  double r12 = (double)R[5];
  double e0 = r00 * r00 + (r01 * r01 + (r02 * r02 - 1.0));
  double e1 = r10 * r10 + (r11 * r11 + (r12 * r12 - 1.0));
  double e2 = r00 * r10 + (r01 * r11 + r02 * r12);
  double x2 = r00 * r11 - (r01 * r10 + (double)R[8]);
  double s2 = e0 * e0 + e1 * e1 + e2 * e2 + x0 * x0 + x1 * x1 + x2 * x2;
  return s2 <= SHLI_ROT_ORTH * SHLI_ROT_ORTH;
}
#if defined(__AVX2__) && defined(__FMA__)
/* d in float lanes (docs/derivations.md sec. 13.67) */
#define SHLI_ROT_NP(a, b, c, d, e, f) \
  _mm256_permutevar8x32_ps(z, _mm256_setr_epi32(a, b, c, d, e, f, 7, 7))
SHLI_ROT_FORCE SHLIGHT_CPU_INLINE int shli_rot_near(const float R[9]) {
  __m256 r = _mm256_loadu_ps(R);
  __m256 r1 = _mm256_loadu_ps(R + 1);
  __m256 z = _mm256_blend_ps(r, _mm256_setzero_ps(), 0x80);
  __m256 c = _mm256_permutevar8x32_ps(r1, _mm256_setr_epi32(0, 0, 5, 0, 7, 6, 0, 0));
  __m256 v = _mm256_fmsub_ps(
      r,
      _mm256_xor_ps(SHLI_ROT_NP(0, 4, 4, 3, 0, 0), _mm256_setr_ps(0, 0, -0.0f, 0, 0, -0.0f, 0, 0)),
      _mm256_blend_ps(c, _mm256_setr_ps(1, 0, 0, 1, 0, 0, 0, 0), 0xcb));
  __m128 t;
  v = _mm256_fmadd_ps(r1, SHLI_ROT_NP(1, 5, 7, 4, 7, 7), v);
  v = _mm256_fmadd_ps(
      SHLI_ROT_NP(2, 0, 1, 5, 1, 2),
      _mm256_xor_ps(SHLI_ROT_NP(2, 3, 5, 5, 3, 3), _mm256_setr_ps(0, 0, 0, 0, -0.0f, 0, 0, 0)), v);
  v = _mm256_mul_ps(v, v);
  t = _mm_add_ps(_mm256_castps256_ps128(v), _mm256_extractf128_ps(v, 1));
  t = _mm_add_ps(t, _mm_movehl_ps(t, t));
  t = _mm_add_ss(t, _mm_movehdup_ps(t));
  return _mm_cvtss_f32(t) <= (float)(SHLI_ROT_ORTH * SHLI_ROT_ORTH);
}
#undef SHLI_ROT_NP
/* band 1 in float lanes 1..3, lane 0 sh[0] */
SHLI_ROT_FORCE SHLIGHT_CPU_INLINE void shli_rot_b1f(const float R[9], const float *sh,
                                                    float *out_sh) {
  __m256 r = _mm256_loadu_ps(R);
  __m128 o = _mm_mul_ps(_mm256_castps256_ps128(
                            _mm256_permutevar8x32_ps(r, _mm256_setr_epi32(0, 4, 7, 1, 0, 0, 0, 0))),
                        _mm_broadcast_ss(sh + 1));
  o = _mm_fmadd_ps(_mm256_castps256_ps128(
                       _mm256_permutevar8x32_ps(r, _mm256_setr_epi32(0, 3, 6, 0, 0, 0, 0, 0))),
                   _mm_broadcast_ss(sh + 3), o);
  o = _mm_fnmadd_ps(_mm256_castps256_ps128(_mm256_permutevar8x32_ps(
                        _mm256_loadu_ps(R + 1), _mm256_setr_epi32(0, 4, 7, 1, 0, 0, 0, 0))),
                    _mm_broadcast_ss(sh + 2), o);
  o = _mm_xor_ps(o, _mm_set_ps(0.0f, -0.0f, 0.0f, 0.0f));
  _mm_storeu_ps(out_sh, _mm_blend_ps(o, _mm_load_ss(sh), 1));
}
/* n >= 4: band 2 in float lanes; writes out_sh[4 .. 11] */
#define SHLI_ROT_P(v, a, b, c, d, e, f) \
  _mm256_permutevar8x32_ps(v, _mm256_setr_epi32(a, b, c, d, e, f, 0, 0))
SHLI_ROT_FORCE SHLIGHT_CPU_INLINE void shli_rot_b2v(const float R[9], const float *sh,
                                                    float *out_sh) {
  const float k = 0.57735026918962576f;
  __m256 rl = _mm256_loadu_ps(R);
  __m256 rh = _mm256_loadu_ps(R + 1);
  __m256 a = _mm256_loadu_ps(sh + 4);
  __m256 s = _mm256_broadcast_ss(sh + 6);
  /* columns x, y, z of C (twice) times R's entries r_0j, r_1j */
  __m256 u = _mm256_mul_ps(
      _mm256_fmadd_ps(SHLI_ROT_P(a, 4, 0, 3, 4, 0, 3), _mm256_setr_ps(1, 1, -1, 1, 1, -1, 0, 0),
                      _mm256_mul_ps(s, _mm256_setr_ps(-k, 0, 0, -k, 0, 0, 0, 0))),
      SHLI_ROT_P(rl, 0, 0, 0, 3, 3, 3));
  __m256 d;
  u = _mm256_fmadd_ps(_mm256_fmadd_ps(SHLI_ROT_P(a, 0, 4, 1, 0, 4, 1),
                                      _mm256_setr_ps(1, -1, -1, 1, -1, -1, 0, 0),
                                      _mm256_mul_ps(s, _mm256_setr_ps(0, -k, 0, 0, -k, 0, 0, 0))),
                      SHLI_ROT_P(rl, 1, 1, 1, 4, 4, 4), u);
  u = _mm256_fmadd_ps(_mm256_mul_ps(SHLI_ROT_P(a, 3, 1, 2, 3, 1, 2),
                                    _mm256_setr_ps(-1, -1, 2 * k, -1, -1, 2 * k, 0, 0)),
                      SHLI_ROT_P(rl, 2, 2, 2, 5, 5, 5), u);
  d = _mm256_mul_ps(SHLI_ROT_P(u, 0, 3, 0, 0, 0, 3), SHLI_ROT_P(rl, 3, 6, 0, 6, 0, 3));
  d = _mm256_fmadd_ps(SHLI_ROT_P(u, 1, 4, 1, 1, 1, 4), SHLI_ROT_P(rl, 4, 7, 1, 7, 1, 4), d);
  d = _mm256_fmadd_ps(SHLI_ROT_P(u, 2, 5, 2, 2, 2, 5), SHLI_ROT_P(rh, 4, 7, 1, 7, 1, 4), d);
  d = _mm256_fmadd_ps(
      d, _mm256_setr_ps(1, -1, -0.86602540378443865f, -1, 0.5f, 0, 0, 0),
      _mm256_mul_ps(SHLI_ROT_P(d, 0, 0, 5, 0, 5, 0),
                    _mm256_setr_ps(0, 0, -0.86602540378443865f, 0, -0.5f, 0, 0, 0)));
  _mm256_storeu_ps(out_sh + 4, d);
}
#undef SHLI_ROT_P
#else
#if defined(__SSE2__)
/* band 1 in float lanes (out 3, -, 1, -2), then into place */
#define SHLI_ROT_B1SSE 1
#define SHLI_ROT_SB(x, a, b, c, d) _mm_shuffle_ps(x, x, (a) | (b) << 2 | (c) << 4 | (d) << 6)
SHLI_ROT_FORCE SHLIGHT_CPU_INLINE void shli_rot_b1f(const float R[9], const float *sh,
                                                    float *out_sh) {
  __m128 a = _mm_loadu_ps(R);
  __m128 s = _mm_loadu_ps(sh);
  __m128 o = _mm_mul_ps(_mm_shuffle_ps(a, _mm_loadu_ps(R + 4), 0xc5), SHLI_ROT_SB(s, 1, 1, 1, 1));
  o = _mm_add_ps(
      o, _mm_mul_ps(_mm_shuffle_ps(a, _mm_loadu_ps(R + 3), 0xc0), SHLI_ROT_SB(s, 3, 3, 3, 3)));
  o = _mm_sub_ps(
      o, _mm_mul_ps(_mm_shuffle_ps(a, _mm_loadu_ps(R + 5), 0xca), SHLI_ROT_SB(s, 2, 2, 2, 2)));
  o = _mm_xor_ps(o, _mm_set_ps(-0.0f, 0.0f, 0.0f, 0.0f));
  _mm_storeu_ps(out_sh, _mm_shuffle_ps(_mm_shuffle_ps(s, o, 0x20), o, 0x38));
}
#undef SHLI_ROT_SB
#endif
SHLI_ROT_FORCE SHLIGHT_CPU_INLINE int shli_rot_near(const float R[9]) {
  double r02 = (double)R[2];
  double r12 = (double)R[5];
  return shli_rot_near2(R, (double)R[1] * r12 - (r02 * (double)R[4] + (double)R[6]),
                        r02 * (double)R[3] - ((double)R[0] * r12 + (double)R[7]));
}
#endif

/* n = 4..8: bands 3..7 in float lanes */
#if defined(__AVX2__) && defined(__FMA__)
#define SHLI_ROT_FMA(a, b, c) ((shli_rot_v8)_mm256_fmadd_ps((__m256)(a), (__m256)(b), (__m256)(c)))
#define SHLI_ROT_FMAD(a, b, c) \
  ((shli_rot_v4)_mm256_fmadd_pd((__m256d)(a), (__m256d)(b), (__m256d)(c)))
#else
#define SHLI_ROT_FMA(a, b, c) ((a) * (b) + (c))
#define SHLI_ROT_FMAD(a, b, c) ((a) * (b) + (c))
#endif
/* 128 bits widened with zeros */
#if defined(__clang__) || (defined(__GNUC__) && __GNUC__ >= 10)
#define SHLI_ROT_ZEXT(x) _mm256_zextps128_ps256(x)
#else
#define SHLI_ROT_ZEXT(x) _mm256_insertf128_ps(_mm256_setzero_ps(), x, 0)
#endif
#if defined(__clang__)
#define SHLI_ROT_SW(v) __builtin_shufflevector(v, v, 1, 0, 3, 2, 5, 4, 7, 6)
#else
#define SHLI_ROT_SW(v) __builtin_shuffle(v, __extension__(shli_rot_i8){1, 0, 3, 2, 5, 4, 7, 6})
#endif
/* X(+90)'s column pairs a, b interleaved; a lane pair of w broadcast */
SHLI_ROT_FORCE SHLIGHT_CPU_INLINE void shli_rot_xc(const double *a, const double *b,
                                                   shli_rot_v8 *o) {
  shli_rot_v8 r = {(float)a[0], (float)b[0], (float)a[1], (float)b[1],
                   (float)a[2], (float)b[2], (float)a[3], (float)b[3]};
  *o = r;
}
SHLI_ROT_FORCE SHLIGHT_CPU_INLINE void shli_rot_bc(const double *w, shli_rot_v8 *o) {
#if defined(__AVX__)
  *o = (shli_rot_v8)_mm256_castpd_ps(_mm256_broadcast_sd(w));
#else
  float f[2];
  memcpy(f, w, 8);
  {
    shli_rot_v8 r = {f[0], f[1], f[0], f[1], f[0], f[1], f[0], f[1]};
    *o = r;
  }
#endif
}
#if defined(__SSE2__) && !defined(__AVX__)
#define SHLI_ROT_SSE 1
/* shufps (x, y, i), then (t, t, j) */
#define SHLI_ROT_SH(t, x, y, i, j) (t = _mm_shuffle_ps(x, y, i), _mm_shuffle_ps(t, t, j))
/* the first c (1..4) floats of x, zero-filled; stored */
SHLI_ROT_FORCE SHLIGHT_CPU_INLINE __m128 shli_rot_ld(const float *x, int c) {
  __m128 a =
      c == 2 || c == 3 ? _mm_castsi128_ps(_mm_loadl_epi64((const __m128i *)x)) : _mm_load_ss(x);
  return c > 3 ? _mm_loadu_ps(x) : c < 3 ? a : _mm_movelh_ps(a, _mm_load_ss(x + 2));
}
SHLI_ROT_FORCE SHLIGHT_CPU_INLINE void shli_rot_st(float *x, __m128 v, int c) {
  if (c > 3) {
    _mm_storeu_ps(x, v);
    return;
  }
  if (c > 1) {
    _mm_storel_epi64((__m128i *)x, _mm_castps_si128(v));
  }
  if (c != 2) {
    _mm_store_ss(x + c - 1, c > 1 ? _mm_movehl_ps(v, v) : v);
  }
}
#endif
/* band l (3..7, a literal: the loops unroll); cs: C0, S0, C1, .. S2 */
SHLI_ROT_FORCE SHLIGHT_CPU_INLINE void shli_rot_bandf(int l, const shli_rot_v8 *cs, const float *sh,
                                                      float *out_sh) {
  const double *t = SHLI_ROT_X90 + 64 * (l - 3);
  int b = l * l + l;
  shli_rot_v8 w1;
  shli_rot_v8 w2;
  double wm[8];
  int i;
  int k;
#if defined(__AVX2__)
#define SHLI_ROT_PM(j) ((j) <= l ? -1 : 0)
#define SHLI_ROT_QM(j) ((j) >= 7 - l && (j) < 7 ? -1 : 0)
  __m256i pm = _mm256_setr_epi32(SHLI_ROT_PM(0), SHLI_ROT_PM(1), SHLI_ROT_PM(2), SHLI_ROT_PM(3),
                                 SHLI_ROT_PM(4), SHLI_ROT_PM(5), SHLI_ROT_PM(6), SHLI_ROT_PM(7));
  __m256i qm = _mm256_setr_epi32(SHLI_ROT_QM(0), SHLI_ROT_QM(1), SHLI_ROT_QM(2), SHLI_ROT_QM(3),
                                 SHLI_ROT_QM(4), SHLI_ROT_QM(5), SHLI_ROT_QM(6), SHLI_ROT_QM(7));
  __m256i rv = _mm256_setr_epi32(7, 6, 5, 4, 3, 2, 1, 0);
#undef SHLI_ROT_PM
#undef SHLI_ROT_QM
  /* m >= 0 and m <= 0 (reversed, m = 0 zero) in lanes |m|, interleaved */
  __m256 p = _mm256_maskload_ps(sh + b, pm);
  __m256 q = _mm256_permutevar8x32_ps(_mm256_maskload_ps(sh + b - 7, qm), rv);
  shli_rot_v8 v1 = (shli_rot_v8)_mm256_blend_ps(p, q, 0xaa);
  shli_rot_v8 v2 = (shli_rot_v8)_mm256_blend_ps(q, p, 0xaa);
#elif defined(SHLI_ROT_SSE)
  /* from sh + b, b - 3, b + 4 (l - 3 floats), b - 7 (masked) */
  __m128 h[4], y, p = _mm_loadu_ps(sh + b), q = _mm_loadu_ps(sh + b - 3), ph = _mm_setzero_ps();
  __m128 qh = ph;
  shli_rot_v8 v1;
  shli_rot_v8 v2;
  h[0] = SHLI_ROT_SH(y, p, q, 0x28, 0xd8);
  h[2] =
      _mm_and_ps(SHLI_ROT_SH(y, p, q, 0x5d, 0x60), _mm_castsi128_ps(_mm_setr_epi32(0, -1, -1, -1)));
  if (l > 3) {
    ph = shli_rot_ld(sh + b + 4, l - 3);
    qh = _mm_and_ps(_mm_loadu_ps(sh + b - 7),
                    _mm_castsi128_ps(_mm_setr_epi32(-(l > 6), -(l > 5), -(l > 4), -1)));
  }
  h[1] = SHLI_ROT_SH(y, ph, qh, 0x28, 0xd8);
  h[3] = SHLI_ROT_SH(y, ph, qh, 0x7d, 0x72);
  memcpy(&v1, h, 32);
  memcpy(&v2, h + 2, 32);
#else
#define SHLI_ROT_IN(m) ((m) <= l && (m) >= -l ? sh[b + (m)] : 0.0f)
  shli_rot_v8 v1 = {SHLI_ROT_IN(0), SHLI_ROT_IN(-1), SHLI_ROT_IN(2), SHLI_ROT_IN(-3),
                    SHLI_ROT_IN(4), SHLI_ROT_IN(-5), SHLI_ROT_IN(6), SHLI_ROT_IN(-7)};
  shli_rot_v8 v2 = {
      0.0f,           SHLI_ROT_IN(1),  SHLI_ROT_IN(-2), SHLI_ROT_IN(3), SHLI_ROT_IN(-4),
      SHLI_ROT_IN(5), SHLI_ROT_IN(-6), SHLI_ROT_IN(7)};
#undef SHLI_ROT_IN
#endif
  SHLI_ROT_UNROLL
  for (i = 0; i < 3; ++i) {
    w1 = SHLI_ROT_FMA(v1, cs[2 * i], -(v2 * cs[2 * i + 1]));
    w2 = SHLI_ROT_FMA(v2, cs[2 * i], v1 * cs[2 * i + 1]);
    if (i == 2) {
      break;
    }
    v1 = l % 2 ? SHLI_ROT_SW(w1) : w1;
    v2 = l % 2 ? w2 : SHLI_ROT_SW(w2);
    memcpy(wm, &v1, 32);
    memcpy(wm + 4, &v2, 32);
#if defined(__clang__) && defined(__AVX__)
    /* keeps the broadcasts loads: clang would turn them into lane permutes */
    __asm__ volatile("" : : "r"(wm) : "memory");
#endif
    shli_rot_bc(wm, &v1);
    shli_rot_xc(t, t + 48, &w1);
    v1 = v1 * w1;
    shli_rot_bc(wm + 4, &v2);
    shli_rot_xc(t + 32, t + 16, &w2);
    v2 = v2 * w2;
    SHLI_ROT_UNROLL
    for (k = 1; k <= l / 2; ++k) {
      shli_rot_v8 x;
      shli_rot_v8 c;
      shli_rot_bc(wm + k, &x);
      shli_rot_xc(t + 4 * k, t + 48 + 4 * k, &c);
      v1 = SHLI_ROT_FMA(x, c, v1);
      shli_rot_bc(wm + 4 + k, &x);
      shli_rot_xc(t + 32 + 4 * k, t + 16 + 4 * k, &c);
      v2 = SHLI_ROT_FMA(x, c, v2);
    }
  }
#if defined(__AVX2__)
  _mm256_maskstore_ps(out_sh + b, pm, _mm256_blend_ps((__m256)w1, (__m256)w2, 0xaa));
  _mm256_maskstore_ps(out_sh + b - 7, qm,
                      _mm256_permutevar8x32_ps(_mm256_blend_ps((__m256)w2, (__m256)w1, 0xaa), rv));
#elif defined(SHLI_ROT_SSE)
  /* m <= 0 first, whole halves (lanes past -l and m = 0 overwritten after) */
  memcpy(h, &w1, 32);
  memcpy(h + 2, &w2, 32);
  if (l > 3) {
    _mm_storeu_ps(out_sh + b - 7, SHLI_ROT_SH(y, h[1], h[3], 0x27, 0xd8));
  }
  _mm_storeu_ps(out_sh + b - 3, SHLI_ROT_SH(y, h[0], h[2], 0xa7, 0xd8));
  _mm_storeu_ps(out_sh + b, SHLI_ROT_SH(y, h[0], h[2], 0xd8, 0xd8));
  if (l > 3) {
    shli_rot_st(out_sh + b + 4, SHLI_ROT_SH(y, h[1], h[3], 0xd8, 0xd8), l - 3);
  }
#else
  SHLI_ROT_UNROLL
  for (i = 0; i < 8; ++i) {
    if (i <= l) {
      out_sh[b + i] = i % 2 ? w2[i] : w1[i];
    }
    if (i > 0 && i <= l) {
      out_sh[b - i] = i % 2 ? w1[i] : w2[i];
    }
  }
#endif
}
/* bands 3 .. n - 1 of Rz(alpha) Ry(beta) Rz(gamma) */
SHLI_ROT_FORCE SHLIGHT_CPU_INLINE void shli_rot_high(int n, const float *sh, float *out_sh,
                                                     double ca, double sa, double cb, double sb,
                                                     double cg, double sg) {
  shli_rot_v4 p[16];
  shli_rot_v8 cs[6];
  int i;
#if defined(__SSE2__) && !defined(__AVX__)
  /* by register pairs (scalar stores read back as vectors stall) */
  shli_rot_v4 zr;
  shli_rot_v4 zi;
  __m128d z[4];
  z[0] = _mm_unpacklo_pd(_mm_set_sd(cg), _mm_set_sd(-cb));
  z[1] = _mm_set_sd(-ca);
  z[2] = _mm_unpacklo_pd(_mm_set_sd(sg), _mm_set_sd(-sb));
  z[3] = _mm_set_sd(-sa);
  memcpy(&zr, z, 32);
  memcpy(&zi, z + 2, 32);
#else
  shli_rot_v4 zr = {cg, -cb, -ca, 0.0};
  shli_rot_v4 zi = {sg, -sb, -sa, 0.0};
#endif
  /* p[j], p[8 + j]: cos, (-1)^j sin of j t */
  p[8] = zr - zr;
  for (i = 0; i < 8; ++i) {
    p[i] = p[8];
    p[8 + i] = p[8];
  }
  p[0] = p[8] + 1.0;
  p[1] = zr;
  p[9] = -zi;
  p[2] = SHLI_ROT_FMAD(zr, zr + zr, p[0] - 2.0);
  p[10] = (zr + zr) * zi;
  p[3] = SHLI_ROT_FMAD(zr * zr, 4.0 * zr, -3.0 * zr);
  p[11] = SHLI_ROT_FMAD(zr * zr, -4.0 * zi, zi);
  if (n > 4) {
    shli_rot_v4 c2 = SHLI_ROT_FMAD(zr, 4.0 * zr, p[0] - 3.0);
    p[4] = SHLI_ROT_FMAD(p[2], c2, -p[0]);
    p[12] = p[10] * c2;
  }
  if (n > 5) {
    p[5] = SHLI_ROT_FMAD(p[2], p[3], p[10] * p[11]);
    p[13] = SHLI_ROT_FMAD(p[2], p[11], -(p[10] * p[3]));
  }
  if (n > 6) {
    p[6] = SHLI_ROT_FMAD(p[3], p[3] + p[3], -p[0]);
    p[14] = -2.0 * p[11] * p[3];
    p[7] = SHLI_ROT_FMAD(p[3], p[4], p[11] * p[12]);
    p[15] = SHLI_ROT_FMAD(p[11], p[4], -(p[3] * p[12]));
  }
#if defined(__AVX2__) && defined(__FMA__)
  if (n == 4) {
    /* j <= 3 straight from cos t, sin t */
    __m256d a[6];
    a[0] = _mm256_set1_pd(cg);
    a[1] = _mm256_set1_pd(sg);
    a[2] = _mm256_set1_pd(-cb);
    a[3] = _mm256_set1_pd(-sb);
    a[4] = _mm256_set1_pd(-ca);
    a[5] = _mm256_set1_pd(-sa);
    SHLI_ROT_UNROLL
    for (i = 0; i < 3; ++i) {
      __m256d c = a[2 * i];
      __m256d c2 = _mm256_mul_pd(c, c);
      __m256d u = _mm256_fmadd_pd(c, _mm256_setr_pd(0, 1, 0, -3), _mm256_setr_pd(1, 0, -1, 0));
      __m256d v = _mm256_fmadd_pd(c, _mm256_setr_pd(0, 0, 0, 4), _mm256_setr_pd(0, 0, 2, 0));
      __m256d w = _mm256_fmadd_pd(c, _mm256_setr_pd(0, 0, 2, 0), _mm256_setr_pd(0, -1, 0, 1));
      cs[2 * i] = (shli_rot_v8)_mm256_castps128_ps256(_mm256_cvtpd_ps(_mm256_fmadd_pd(c2, v, u)));
      w = _mm256_fmadd_pd(c2, _mm256_setr_pd(0, 0, 0, -4), w);
      cs[2 * i + 1] =
          (shli_rot_v8)_mm256_castps128_ps256(_mm256_cvtpd_ps(_mm256_mul_pd(a[2 * i + 1], w)));
    }
  } else
#endif
#if defined(__AVX__)
  {
    /* 4 x 8 transposes (lanes j >= n zero) */
    __m128 f[16];
    __m256 y[4];
    for (i = 0; i < 16; ++i) {
      f[i] = _mm256_cvtpd_ps((__m256d)p[i]);
    }
    SHLI_ROT_UNROLL
    for (i = 0; i < 2; ++i) {
      __m256 t0;
      __m256 t1;
      __m256 t2;
      __m256 t3;
      int a;
      SHLI_ROT_UNROLL
      for (a = 0; a < 4; ++a) {
        y[a] = SHLI_ROT_ZEXT(f[8 * i + a]);
        if (a + 4 < n) {
          y[a] = _mm256_insertf128_ps(y[a], f[8 * i + a + 4], 1);
        }
      }
      t0 = _mm256_unpacklo_ps(y[0], y[1]);
      t1 = _mm256_unpackhi_ps(y[0], y[1]);
      t2 = _mm256_unpacklo_ps(y[2], y[3]);
      t3 = _mm256_unpackhi_ps(y[2], y[3]);
      cs[i] = (shli_rot_v8)_mm256_shuffle_ps(t0, t2, 0x44);
      cs[2 + i] = (shli_rot_v8)_mm256_shuffle_ps(t0, t2, 0xee);
      cs[4 + i] = (shli_rot_v8)_mm256_shuffle_ps(t1, t3, 0x44);
    }
  }
#else
  SHLI_ROT_UNROLL
  for (i = 0; i < 6; ++i) {
    const shli_rot_v4 *r = p + 8 * (i % 2);
    int q = i / 2;
    shli_rot_v8 c = {(float)r[0][q], (float)r[1][q], (float)r[2][q], (float)r[3][q],
                     (float)r[4][q], (float)r[5][q], (float)r[6][q], (float)r[7][q]};
    cs[i] = c;
  }
#endif
  /* literal band numbers; the longest chain first */
  if (n > 7) {
    shli_rot_bandf(7, cs, sh, out_sh);
  }
  if (n > 6) {
    shli_rot_bandf(6, cs, sh, out_sh);
  }
  if (n > 5) {
    shli_rot_bandf(5, cs, sh, out_sh);
  }
  if (n > 4) {
    shli_rot_bandf(4, cs, sh, out_sh);
  }
  shli_rot_bandf(3, cs, sh, out_sh);
}
/* n = 4, 5, 6 and 7..8: one function each */
#define SHLI_ROT_HIGH_N(name, nn) \
  SHLI_ROT_NOINLINE SHLI_ROT_NOSLP void name(int n, const float *sh, float *out_sh, double ca, \
                                             double sa, double cb, double sb, double cg, \
                                             double sg) { \
    shli_rot_high(nn, sh, out_sh, ca, sa, cb, sb, cg, sg); \
  }
SHLI_ROT_HIGH_N(shli_sh_rotate_h4, ((void)n, 4))
SHLI_ROT_HIGH_N(shli_sh_rotate_h5, ((void)n, 5))
SHLI_ROT_HIGH_N(shli_sh_rotate_h6, ((void)n, 6))
SHLI_ROT_HIGH_N(shli_sh_rotate_h8, (n < 7 ? 7 : n))

/* the portable kernel, out of line: its 7 KB frame is set up only where it runs */
SHLIGHT_INLINE void shli_sh_rotate_any(int n, const float R[9], const float *sh, float *out_sh);
SHLI_ROT_NOINLINE void shli_sh_rotate_slow(int n, const float R[9], const float *sh,
                                           float *out_sh) {
  shli_sh_rotate_any(n, R, sh, out_sh);
}

/* bands 0..2 (n <= 3: those present) of a rotation R (shli_rot_near) as given */
SHLI_ROT_FORCE SHLIGHT_CPU_INLINE void shli_rot_b012(int n, const float R[9], const float *sh,
                                                     float *out_sh) {
  double r00 = (double)R[0];
  double r01 = (double)R[1];
  double r02 = (double)R[2];
  double r10 = (double)R[3];
  double r11 = (double)R[4];
  double r12 = (double)R[5];
  double r20 = (double)R[6];
  double r21 = (double)R[7];
  double r22 = (double)R[8];
  out_sh[0] = sh[0];
  if (n < 2) {
    return;
  }
  /* band 1: Y_1 = sqrt(3 / (4 pi)) (-y, z, -x), so R's entries, signed and permuted */
  {
    double am = (double)sh[1];
    double a0 = (double)sh[2];
    double ap = (double)sh[3];
    out_sh[1] = (float)(r11 * am - r12 * a0 + r10 * ap);
    out_sh[2] = (float)(r22 * a0 - r21 * am - r20 * ap);
    out_sh[3] = (float)(r01 * am - r02 * a0 + r00 * ap);
  }
  if (n < 3) {
    return;
  }
  /* band 2 = w^T C w rotated to R C R^T (docs/rotation.md, method 2) */
  {
    double s = (double)sh[6] * 0.57735026918962576;
    double a2 = (double)sh[8];
    double cxy = (double)sh[4];
    double cyz = -(double)sh[5];
    double cxz = -(double)sh[7];
    double cxx = a2 - s;
    double cyy = -a2 - s;
    double u0 = cxx * r00 + cxy * r01 + cxz * r02;
    double u1 = cxy * r00 + cyy * r01 + cyz * r02;
    double u2 = cxz * r00 + cyz * r01 + 2.0 * s * r02;
    double v0 = cxx * r10 + cxy * r11 + cxz * r12;
    double v1 = cxy * r10 + cyy * r11 + cyz * r12;
    double v2 = cxz * r10 + cyz * r11 + 2.0 * s * r12;
    double p00 = r00 * u0 + r01 * u1 + r02 * u2;
    double p11 = r10 * v0 + r11 * v1 + r12 * v2;
    out_sh[4] = (float)(r10 * u0 + r11 * u1 + r12 * u2);
    out_sh[5] = (float)(-(r20 * v0 + r21 * v1 + r22 * v2));
    out_sh[6] = (float)(-0.86602540378443865 * (p00 + p11));
    out_sh[7] = (float)(-(r20 * u0 + r21 * u1 + r22 * u2));
    out_sh[8] = (float)(0.5 * (p00 - p11));
  }
}

/* n in [1, 3]: bands 0..2 (R near a rotation) or the portable kernel */
SHLI_ROT_NOINLINE SHLI_ROT_SCALAR void shli_sh_rotate_small(int n, const float R[9],
                                                            const float *sh, float *out_sh) {
  if (!shli_rot_near(R)) {
    shli_sh_rotate_slow(n, R, sh, out_sh);
    return;
  }
#if defined(__AVX2__) && defined(__FMA__) || defined(SHLI_ROT_B1SSE)
  if (n == 2) {
    shli_rot_b1f(R, sh, out_sh);
    return;
  }
#endif
  shli_rot_b012(n, R, sh, out_sh);
}

/* n in [4, 8]: angles, bands 0..2, then h4 .. h8; else the portable kernel */
SHLI_ROT_NOINLINE SHLI_ROT_SCALAR void shli_sh_rotate_mid(int n, const float R[9], const float *sh,
                                                          float *out_sh) {
  double r00 = (double)R[0];
  double r01 = (double)R[1];
  double r02 = (double)R[2];
  double r10 = (double)R[3];
  double r11 = (double)R[4];
  double r12 = (double)R[5];
  double r22 = (double)R[8];
  double ca = 1.0;
  double sa = 0.0;
  double sb = 0.0;
  double cb;
  double cg;
  double sg;
  double s2;
  double hg;
  double fb;
  double f;
  /* the zyz angles (docs/rotation.md, method 1); cg, sg shared with the check */
  cg = r11 * r02 - r01 * r12;
  sg = r10 * r02 - r00 * r12;
  if (!shli_rot_near2(R, cg + (double)R[6], sg - (double)R[7])) {
    shli_sh_rotate_slow(n, R, sh, out_sh);
    return;
  }
  s2 = r02 * r02 + r12 * r12;
  fb = 1.5 - 0.5 * (r22 * r22 + s2);
  hg = cg * cg + sg * sg;
  cb = r22 * fb;
  if (s2 > 0.0 && hg > 0.0) {
    double fg;
#if defined(__SSE2__)
    /* both in one instruction, no errno branch */
    __m128d x = _mm_set_pd(hg, s2);
    __m128d v = _mm_mul_pd(_mm_sqrt_pd(x), _mm_div_pd(_mm_set1_pd(1.0), x));
    f = _mm_cvtsd_f64(v);
    fg = _mm_cvtsd_f64(_mm_unpackhi_pd(v, v));
#else
    f = 1.0 / sqrt(s2);
    fg = 1.0 / sqrt(hg);
#endif
    ca = r02 * f;
    sa = r12 * f;
    sb = s2 * (f * fb);
    cg = cg * fg;
    sg = sg * fg;
  } else {
    f = 1.5 - 0.5 * (r11 * r11 + r10 * r10);
    cg = r11 * f;
    sg = r10 * f;
  }
#if defined(__AVX2__) && defined(__FMA__)
  shli_rot_b1f(R, sh, out_sh);
  shli_rot_b2v(R, sh, out_sh);
#else
  shli_rot_b012(3, R, sh, out_sh);
#endif
  switch (n) {
  case 4:
    shli_sh_rotate_h4(n, sh, out_sh, ca, sa, cb, sb, cg, sg);
    break;
  case 5:
    shli_sh_rotate_h5(n, sh, out_sh, ca, sa, cb, sb, cg, sg);
    break;
  case 6:
    shli_sh_rotate_h6(n, sh, out_sh, ca, sa, cb, sb, cg, sg);
    break;
  default:
    shli_sh_rotate_h8(n, sh, out_sh, ca, sa, cb, sb, cg, sg);
  }
}

/* n in 1..SHLIGHT_MAX_BANDS */
SHLIGHT_CPU_INLINE void shli_sh_rotate_fast(int n, const float R[9], const float *sh,
                                            float *out_sh) {
  if (n > SHLI_ROT_FAST_BANDS) {
    shli_sh_rotate_slow(n, R, sh, out_sh);
  } else if (n > 3) {
    shli_sh_rotate_mid(n, R, sh, out_sh);
  } else {
    shli_sh_rotate_small(n, R, sh, out_sh);
  }
}
#endif

/* shl_sh_rotate's portable kernel, n in 1..SHLIGHT_MAX_BANDS (the method: see the contract) */
SHLIGHT_INLINE void shli_sh_rotate_any(int n, const float R[9], const float *sh, float *out_sh) {
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
  /* not h > 0: a NaN R_22 must reach the output as NaN */
  if (!(h <= 0.0)) {
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
  if (!(h <= 0.0)) {
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

/* shl_sh_rotate: n clamped, then the vector path (C, GCC / Clang) or the portable kernel */
SHLIGHT_INLINE void shl_sh_rotate(int n, const float R[9], const float *sh, float *out_sh) {
  n = shli_bands(n);
  if (n < 1) {
    return;
  }
#if SHLIGHT_ROTATE_FAST
  shli_sh_rotate_fast(n, R, sh, out_sh);
#else
  shli_sh_rotate_any(n, R, sh, out_sh);
#endif
}

/* >>light ------------------------------------------------------------------------------------
   Unit-radiance sphere and triangle lights seen from x: SH and gradient with respect to x.
   (docs/derivations.md sec. 13.12) */

/* @generated light_idx: defined in >>generated at the end of the file */
SHLIGHT_INLINE void shli_sh_band_weights(int n, const float *kv, const float *kg, const float *ka,
                                         const float *kb, const float *wg, float *io_sh,
                                         float (*io_grad)[3]);
SHLIGHT_INLINE void shli_sh_zero_grad(int n, float *out_sh, float (*out_grad)[3]);
#if SHLIGHT_SIMD_EVAL
SHLI_TAB_DECL(int, light_band, 256);
#define SHLI_LIGHT_BAND (*shli_tab_light_band())
#endif

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

/* Cap light and gradient from g (shli_cap_frame) times the weight wgt (gradient gw0..2): out_sh =
   wgt S, out_grad = wgt grad S + S grad wgt. (docs/derivations.md sec. 13.13) */
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
/* shli_cap_light_grad for n <= 16 (C only, AVX-512): the same weights, then one shli_sh_grad_avx512
   pass with bw. (docs/derivations.md sec. 13.14) */
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

/* Triangle as a sphere: out_g as shli_cap_frame for the centroid sphere of the same area, out_g[7]
   = n_t . w; out_nt: n_t (0 for a zero-area triangle). (docs/derivations.md sec. 13.15) */
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

/* atan2(y, x) in shli_real from the shims alone (C and GLSL alike): relative error <= 4e-13;
   atan2(0, 0) = 0; finite input. (docs/derivations.md sec. 13.16) */
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

/* >>grid -------------------------------------------------------------------------------------
   SH of many sphere lights and their gradients at the vertices of a 3D grid (shl_grid_build, CPU),
   reconstruction in a cell from its 8 corners (trilinear, Taylor, Hermite).
   (docs/derivations.md sec. 13.17) */

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
#if SHLIGHT_FLAT_LOOPS
  /* GLSL: one flat loop over (i, k), k fastest, with the same sums as the nested loop below,
     which shader compilers unroll into 8 n^2 terms (llvmpipe: 13 s to compile at n = 5,
     against 0.3 s for this form); C keeps the nested loop (2x faster with gcc at n = 9) */
  s = 0.0f;
  i = 0;
  k = 0;
  for (j = 0; j < 8 * nn; ++j) {
    o = k * nn + i;
    s = s + (wv[k] * c8[o] + wx[k] * g8[o][0] + wy[k] * g8[o][1] + wz[k] * g8[o][2]);
    k = k + 1;
    if (k == 8) {
      out_sh[i] = s;
      s = 0.0f;
      k = 0;
      i = i + 1;
    }
  }
#else
  for (i = 0; i < nn; ++i) {
    s = 0.0f;
    for (k = 0; k < 8; ++k) {
      o = k * nn + i;
      s = s + (wv[k] * c8[o] + wx[k] * g8[o][0] + wy[k] * g8[o][1] + wz[k] * g8[o][2]);
    }
    out_sh[i] = s;
  }
#endif
}

/* CPU only (declared here, defined with SHLIGHT_IMPLEMENTATION). */

/* >>edge -------------------------------------------------------------------------------------
   Area lights without tables: axial moments of polygons by Arvo's edge integrals (integer e) or the
   Stokes form (any e >= 0). (docs/derivations.md sec. 13.18) */

/* Polygons above SHLIGHT_POLYGON_MAX vertices (C): cut into same-turning fan pieces, summed with
   their signs (winding number); GLSL: -1. (docs/derivations.md sec. 13.19) */
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
SHLIGHT_CPU_INLINE float shli_fan_ggx_fast(const float (*v)[3], int nv, const float nrm[3],
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
   with f = x for odd nf) with its limit f m / 2 at x^2 = 1 (docs/derivations.md section 7.1). */
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

/* The paper's O(1) fits of F over [pa, pb] (Lorentzian, Lorentzian-Pearson, ellipsoid), corrected.
   (docs/derivations.md sec. 13.20) */
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

/* The FAST method: the Stokes form in float, 4-node rules after a rational grading, SHLIGHT_LANES
   edges per block. (docs/derivations.md sec. 13.21) */

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
/* exp(z) for z <= 0 (clamped at -87 by an integer min of the bit patterns), relative error < 2e-7.
   (docs/derivations.md sec. 13.22) */
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

/* (e + 1) M^e by the FAST method of the polygon (shading point at the origin; overwritten), clipped
   to u.n >= 0 when clip_n != 0, then to u.r >= 0. Bad input: 0. (docs/derivations.md sec. 13.23) */
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

/* integral of the kind's integrand over |theta| in [lo, hi]: 5-node Gauss-Legendre in s, pi/2 -
   |theta| = beta sinh(s); lev > 0: adaptive composite rule. (docs/derivations.md sec. 13.24) */
SHLIGHT_INLINE shli_real shli_stokes_half(shli_real lo, shli_real hi, shli_real beta, shli_real c2,
                                          shli_real p, shli_real q, int kind, int lev) {
  shli_real z0 = (1.5707963267948966 - hi) / beta;
  shli_real z1 = (1.5707963267948966 - lo) / beta;
  shli_real s0 = SHLIGHT_LOGR(z0 + SHLIGHT_SQRTR(z0 * z0 + 1.0));
  shli_real s1 = SHLIGHT_LOGR(z1 + SHLIGHT_SQRTR(z1 * z1 + 1.0));
  shli_real h = s1 - s0;
  shli_real hg = h;
  shli_real cur = 0.0;
  shli_real prev = 0.0;
  shli_real pm;
  shli_real pr;
  int np = 1;
  int l = 0;
  int k = 0;
  if (!(h > 0.0)) {
    return 0.0;
  }
  /* one loop over the panels of every level, one call of the 5-node rule.
     (docs/derivations.md sec. 13.25) */
  while (l <= lev) {
    if (k < np - 1) {
      pm = s0 + (SHLIGHT_ITOR(k + 1) + 0.5) * h;
      pr = 0.5 * h;
    } else if (k < np + l - 1) {
      pm = s0 + 0.575 * hg;
      pr = 0.425 * hg;
      hg = 0.15 * hg;
    } else {
      pm = s0 + 0.5 * hg;
      pr = 0.5 * hg;
    }
    cur = cur + shli_stokes_gl5(pm, pr, beta, c2, p, q, kind);
    k = k + 1;
    if (k == np + l) {
      if (l == lev || (l > 0 && SHLIGHT_ABSR(cur - prev) <= SHLIGHT_ADAPT_TOL)) {
        return cur;
      }
      prev = cur;
      cur = 0.0;
      l = l + 1;
      np = 2 * np;
      h = (s1 - s0) / SHLIGHT_ITOR(np);
      hg = h;
      k = 0;
    }
  }
  return cur;
}

/* The arc theta in [ta, tb] of an edge: the halves on either side of theta = 0, each by
   shli_stokes_half (the integrand is even in theta; lev as there), from one call site. */
SHLIGHT_INLINE shli_real shli_stokes_arc(shli_real ta, shli_real tb, shli_real beta, shli_real c2,
                                         shli_real p, shli_real q, int kind, int lev) {
  shli_real lo = ta;
  shli_real hi = tb;
  shli_real hi2 = 0.0;
  shli_real sum = 0.0;
  int nh = 1;
  int k;
  if (ta < 0.0 && tb > 0.0) {
    lo = 0.0;
    hi = -ta;
    hi2 = tb;
    nh = 2;
  } else if (tb <= 0.0) {
    lo = -tb;
    hi = -ta;
  }
  for (k = 0; k < nh; ++k) {
    sum = sum + shli_stokes_half(lo, hi, beta, c2, p, q, kind, lev);
    hi = hi2;
  }
  return sum;
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

/* Shared start of every polygon sum: clips, orientation, normalisation; returns +-(clipped vertex
   count) or 0. (docs/derivations.md sec. 13.26) */
SHLIGHT_INLINE int shli_poly_clip_unit2(shli_real *io_px, shli_real *io_py, shli_real *io_pz,
                                        int nv, shli_real nx, shli_real ny, shli_real nz, int npre,
                                        shli_real rx, shli_real ry, shli_real rz) {
  shli_real ox = 0.0;
  shli_real oy = 0.0;
  shli_real oz = 0.0;
  shli_real orient = 0.0;
  shli_real mx = nx;
  shli_real my = ny;
  shli_real mz = nz;
  shli_real l;
  int nc = nv;
  int pass = 1 - npre;
  int i;
  int j;
  while (pass < 2) {
    if (pass == 1) { /* vertex i carried in m (GLSL: no unrolling by the arrays' bound) */
      mx = io_px[0];
      my = io_py[0];
      mz = io_pz[0];
      for (i = 0; i < nc; ++i) {
        j = i + 1;
        if (j == nc) {
          j = 0;
        }
        ox = ox + my * io_pz[j] - mz * io_py[j];
        oy = oy + mz * io_px[j] - mx * io_pz[j];
        oz = oz + mx * io_py[j] - my * io_px[j];
        mx = io_px[j];
        my = io_py[j];
        mz = io_pz[j];
      }
      orient = ox * io_px[0] + oy * io_py[0] + oz * io_pz[0];
      mx = rx;
      my = ry;
      mz = rz;
    }
    nc = shli_poly_clip(io_px, io_py, io_pz, nc, mx, my, mz);
    if (nc < 3) {
      return 0;
    }
    pass = pass + 1;
  }
  if (!(orient != 0.0)) {
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

/* shli_poly_clip_unit2 without the horizon clip */
SHLIGHT_INLINE int shli_poly_clip_unit(shli_real *io_px, shli_real *io_py, shli_real *io_pz, int nv,
                                       shli_real rx, shli_real ry, shli_real rz) {
  return shli_poly_clip_unit2(io_px, io_py, io_pz, nv, rx, ry, rz, 0, rx, ry, rz);
}

/* Moment (e+1)-normalised pieces of one polygon already in the arrays (shading point at the
   origin), clipped to u.n >= 0 when npre = 1 (Phong's horizon), then to u.r >= 0; returns
   M^e. e integer for the Arvo-form methods. */
SHLIGHT_INLINE shli_real shli_polygon_moment_r(shli_real *io_px, shli_real *io_py, shli_real *io_pz,
                                               int nv, shli_real nx, shli_real ny, shli_real nz,
                                               int npre, shli_real rx, shli_real ry, shli_real rz,
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
  int nc = shli_poly_clip_unit2(io_px, io_py, io_pz, nv, nx, ny, nz, npre, rx, ry, rz);
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
  return SHLIGHT_FLOAT(shli_polygon_moment_r(px, py, pz, nv, rx, ry, rz, 0, rx, ry, rz, e, mth));
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
  /* the clip to u.n >= 0 happens in shli_polygon_moment_r (one clip call site) */
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
         shli_polygon_moment_r(io_px, io_py, io_pz, nv, nx, ny, nz, 1, rx, ry, rz, e, mth);
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

/* Shared start of the half-vector NDF integrals: checks, load, clip and normalise; out_par [0..2]
   axis, [3] orientation, [4] alpha; returns the clipped count or 0.
   (docs/derivations.md sec. 13.27) */
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

/* 64-bit unsigned for the bit patterns of doubles (the compiler's own name where it has one:
   long long is not C++98) */
#if defined(__UINT64_TYPE__)
typedef __UINT64_TYPE__ shli_u64;
#else
typedef unsigned long long shli_u64;
#endif
/* The microfacet polygon lights' double transcendentals (C): own polynomials, relative error below
   1e-15. (docs/derivations.md sec. 13.28) */
/* their polynomials, for double and for the edges' double lanes (shli_ggx_edges4) alike */
#define SHLI_MEXP_POLY(p, r, K) \
  p = K(2.08767569878681e-09); \
  p = 2.505210838544172e-08 + r * p; \
  p = 2.755731922398589e-07 + r * p; \
  p = 2.7557319223985893e-06 + r * p; \
  p = 2.48015873015873e-05 + r * p; \
  p = 0.0001984126984126984 + r * p; \
  p = 0.001388888888888889 + r * p; \
  p = 0.008333333333333333 + r * p; \
  p = 0.041666666666666664 + r * p; \
  p = 0.16666666666666666 + r * p; \
  p = 0.5 + r * p; \
  p = 1.0 + r * (1.0 + r * p)
#define SHLI_MLOG_POLY(p, z, K) \
  p = K(1.0 / 17.0); \
  p = 1.0 / 15.0 + z * p; \
  p = 1.0 / 13.0 + z * p; \
  p = 1.0 / 11.0 + z * p; \
  p = 1.0 / 9.0 + z * p; \
  p = 1.0 / 7.0 + z * p; \
  p = 0.2 + z * p; \
  p = 1.0 / 3.0 + z * p
#define SHLI_MLOG_END(e, s, z, p) \
  ((e)*0.6931471803691238 + ((e)*1.9082149292705877e-10 + 2.0 * (s) + 2.0 * (s) * ((z) * (p))))
#define SHLI_MSINCOS_POLY(s, c, r, z, K) \
  s = K(-7.647163731819816e-13); \
  s = 1.6059043836821613e-10 + z * s; \
  s = -2.505210838544172e-08 + z * s; \
  s = 2.7557319223985893e-06 + z * s; \
  s = -0.0001984126984126984 + z * s; \
  s = 0.008333333333333333 + z * s; \
  s = -0.16666666666666666 + z * s; \
  s = r + r * (z * s); \
  c = K(4.779477332387385e-14); \
  c = -1.1470745597729725e-11 + z * c; \
  c = 2.08767569878681e-09 + z * c; \
  c = -2.755731922398589e-07 + z * c; \
  c = 2.48015873015873e-05 + z * c; \
  c = -0.001388888888888889 + z * c; \
  c = 0.041666666666666664 + z * c; \
  c = 1.0 - 0.5 * z + z * z * c
SHLIGHT_CPU_INLINE double shli_mexp(double x) {
  double kd;
  double r;
  double p;
  shli_u64 b;
  x = x < -708.0 ? -708.0 : (x > 709.0 ? 709.0 : x);
  kd = (x * 1.4426950408889634 + 6755399441055744.0) - 6755399441055744.0;
  r = x - kd * 0.6931471803691238 - kd * 1.9082149292705877e-10;
  SHLI_MEXP_POLY(p, r, SHLIGHT_REAL);
  b = (shli_u64)((int)kd + 1023) << 52;
  memcpy(&r, &b, sizeof r);
  return p * r;
}
SHLIGHT_CPU_INLINE double shli_mlog(double x) {
  shli_u64 b;
  int e;
  double m;
  double s;
  double z;
  double p;
  memcpy(&b, &x, sizeof b);
  e = (int)(b >> 52) - 1023;
  b = (b & (((shli_u64)0xfffffu << 32) | 0xffffffffu)) | ((shli_u64)0x3ff00000u << 32);
  memcpy(&m, &b, sizeof m);
  if (m > 1.4142135623730951) {
    m = 0.5 * m;
    e = e + 1;
  }
  s = (m - 1.0) / (m + 1.0);
  z = s * s;
  SHLI_MLOG_POLY(p, z, SHLIGHT_REAL);
  return SHLI_MLOG_END((double)e, s, z, p);
}
/* sin (odd 0) or cos (odd 1) of t: r and the quadrant, then the pair (sin r, cos r) */
SHLIGHT_CPU_INLINE double shli_msincos(double t, int odd) {
  double kd = (t * 0.63661977236758134 + 6755399441055744.0) - 6755399441055744.0;
  double r = t - kd * 1.5707963267341256 - kd * 6.077100506506192e-11;
  double z = r * r;
  double s;
  double c;
  int q = ((int)kd + odd) & 3;
  SHLI_MSINCOS_POLY(s, c, r, z, SHLIGHT_REAL);
  r = (q & 1) != 0 ? c : s;
  return (q & 2) != 0 ? -r : r;
}

/* GGX polygon lights (shl_polygon_ggx): the half-vector integral, w split into its first-order
   Taylor expansion at h* (A, M1 by Stokes) and a remainder by cubature over P.
   (docs/derivations.md sec. 13.29) */

/* Beckmann's Smith Lambda at the direction cosine c (0 < c <= 1), erfc by Abramowitz-Stegun 7.1.26
   (Lambda within 1e-7). (docs/derivations.md sec. 13.30) */
SHLIGHT_INLINE shli_real shli_beckmann_lambda(shli_real c, shli_real alpha) {
  shli_real s2 = 1.0 - c * c;
  shli_real a;
  shli_real t;
  shli_real p;
  a = c / (alpha * SHLIGHT_SQRTR(SHLIGHT_MAXR(s2, 0.0))); /* c >= 1: 0 */
  a = SHLIGHT_MAXR(SHLIGHT_MINR(a, 1.0e10), 1.0e-30);
  t = 1.0 / (1.0 + 0.3275911 * a);
  p = t *
      (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429))));
  return 0.5 * SHLIGHT_EXPR(-a * a) * (0.56418958354775629 / a - p);
}

/* Beckmann NDF: the scaled integral (pi / alpha^2) I(t) through erfcx (relative error 9e-12).
   (docs/derivations.md sec. 13.31) */
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
  return (1.0 / omy - 0.5 * SHLIGHT_MLOG((1.0 + x) * (1.0 + x) / omy) / x) / (2.0 * y);
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
  shli_real r;
  if (ndf == 0) {
    laml = 0.5 * (SHLIGHT_SQRTR(nl * nl + a2 * (1.0 - nl * nl)) / nl - 1.0);
  } else {
    laml = shli_beckmann_lambda(nl, al);
  }
  r = hv / ((1.0 + lamv + laml) * nv * nh);
  if (!(nl > 0.0) || !(nh > 0.0)) {
    r = 0.0;
  }
  return r;
}

/* One edge's graded rule on [sa, sb] (split at s = 0), adding the A and M1.g integrands to
   io_am[0..1]. (docs/derivations.md sec. 13.32) */
SHLIGHT_INLINE void shli_ggx_side(shli_real sa, shli_real sb, shli_real t0, shli_real wd,
                                  shli_real ax, shli_real ay, shli_real az, shli_real bx,
                                  shli_real by, shli_real bz, shli_real vx, shli_real vy,
                                  shli_real vz, shli_real nx, shli_real ny, shli_real nz,
                                  shli_real a2, shli_real gx, shli_real gy, shli_real gz,
                                  shli_real i1, shli_real al, int ndf, shli_real *io_am) {
  shli_real xs[9];
  shli_real ws[9];
  shli_real lo;
  shli_real hi;
  shli_real hl;
  shli_real gn = gx * nx + gy * ny + gz * nz;
  shli_real tx = gx - gn * nx;
  shli_real ty = gy - gn * ny;
  shli_real tz = gz - gn * nz;
  shli_real ex = ay * bz - az * by;
  shli_real ey = az * bx - ax * bz;
  shli_real ez = ax * by - ay * bx;
  shli_real en = ex * nx + ey * ny + ez * nz;
  shli_real et = ex * tx + ey * ty + ez * tz;
  shli_real an1 = ax * (ny * vz - nz * vy) + ay * (nz * vx - nx * vz) + az * (nx * vy - ny * vx);
  shli_real bn1 = bx * (ny * vz - nz * vy) + by * (nz * vx - nx * vz) + bz * (nx * vy - ny * vx);
  shli_real at1 = ax * (ty * vz - tz * vy) + ay * (tz * vx - tx * vz) + az * (tx * vy - ty * vx);
  shli_real bt1 = bx * (ty * vz - tz * vy) + by * (tz * vx - tx * vz) + bz * (tx * vy - ty * vx);
  shli_real s;
  shli_real es;
  shli_real jw;
  shli_real ct;
  shli_real st;
  shli_real qx;
  shli_real qy;
  shli_real qz;
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
  int k;
  int nd;
  int ng = ndf != 0 || al < 0.02 ? 5 : 4; /* Gauss-Legendre nodes per side: xs[0..3], xs[4..8] */
  xs[0] = -0.86113631159405258;
  xs[1] = -0.33998104358485626;
  xs[2] = -xs[1];
  xs[3] = -xs[0];
  ws[0] = 0.34785484513745386;
  ws[1] = 0.65214515486254614;
  ws[2] = ws[1];
  ws[3] = ws[0];
  xs[4] = -0.90617984593866399;
  xs[5] = -0.53846931010568309;
  xs[6] = 0.0;
  xs[7] = -xs[5];
  xs[8] = -xs[4];
  ws[4] = 0.23692688505618909;
  ws[5] = 0.47862867049936647;
  ws[6] = 0.56888888888888889;
  ws[7] = ws[5];
  ws[8] = ws[4];
  for (nd = 0; nd < 2 * ng; ++nd) {
    k = nd / ng;
    j = nd - ng * k + 4 * (ng - 4);
    lo = sa;
    hi = sb;
    if (sa < 0.0 && sb > 0.0) {
      if (k == 0) {
        hi = 0.0;
      } else {
        lo = 0.0;
      }
    } else if (k == 1) {
      hi = sa;
    }
    if (!(hi > lo)) {
      continue;
    }
    hl = 0.5 * (hi - lo);
    s = lo + hl * (xs[j] + 1.0);
    es = SHLIGHT_MEXP(s);
    jw = ws[j] * hl * wd * 0.5 * (es + 1.0 / es);
    s = t0 + wd * 0.5 * (es - 1.0 / es);
    ct = SHLIGHT_MCOS(s);
    st = SHLIGHT_MSIN(s);
    qx = ct * ax + st * bx + vx;
    qy = ct * ay + st * by + vy;
    qz = ct * az + st * bz + vz;
    qn = qx * nx + qy * ny + qz * nz;
    qq = qx * qx + qy * qy + qz * qz;
    cn = en + ct * bn1 - st * an1;
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
        e = SHLIGHT_MEXP(-u);
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
      m = -(et + ct * bt1 - st * at1) * it / (qn * qn);
      if (qxy > 1.0e-30 * qq) {
        m = m + gn * (it - i1) * cn / qxy;
      }
      io_am[1] = io_am[1] + jw * m;
    }
  }
}

/* SHLIGHT_GGX_LANES: shli_mf_taylor's edges in double lanes, the setup of 4 edges at a time and
   an edge's Gauss nodes 4 at a time, the portable kernels' algebra and polynomials
   (tests/test_ggx_lanes.c holds the two together) */
#if SHLIGHT_GGX_LANES
#include <immintrin.h>
typedef __m256d shli_v4d;
#define SHLI_V4(x) _mm256_set1_pd(x)
#define SHLI_V4SEL(m, a, b) _mm256_blendv_pd((b), (a), (m)) /* m ? a : b, by m's sign bit */
#define SHLI_V4CMP(a, op, b) _mm256_cmp_pd((a), SHLI_V4(b), _CMP_##op##_OQ)
#define SHLI_V4SG(q, b) _mm256_and_pd((shli_v4d)_mm256_slli_epi64((q), b), SHLI_V4(-0.0))
#define SHLI_V4I(x) ((__m256i)(x))
SHLIGHT_ALWAYS_INLINE static inline shli_v4d shli_exp4(shli_v4d x) {
  shli_v4d t;
  shli_v4d p;
  x = _mm256_min_pd(_mm256_max_pd(x, SHLI_V4(-708.0)), SHLI_V4(709.0));
  t = x * 1.4426950408889634 + 6755399441056767.0; /* 1.5 2^52 + 1023: 2^k's exponent bits */
  p = t - 6755399441056767.0;
  x = x - p * 0.6931471803691238 - p * 1.9082149292705877e-10;
  SHLI_MEXP_POLY(p, x, SHLI_V4);
  return p * (shli_v4d)_mm256_slli_epi64(SHLI_V4I(t), 52);
}
SHLIGHT_ALWAYS_INLINE static inline shli_v4d shli_log4(shli_v4d x) { /* x > 0 */
  shli_v4d m = _mm256_or_pd(_mm256_andnot_pd(SHLI_V4(-HUGE_VAL), x), SHLI_V4(1.0));
  shli_v4d e =
      (shli_v4d)(_mm256_srli_epi64(SHLI_V4I(x), 52) | SHLI_V4I(SHLI_V4(4503599627370496.0)));
  shli_v4d g = SHLI_V4CMP(m, GT, 1.4142135623730951);
  shli_v4d z;
  m = SHLI_V4SEL(g, 0.5 * m, m);
  e = e - 4503599627371519.0 + _mm256_and_pd(g, SHLI_V4(1.0)); /* 2^52 + 1023 */
  m = (m - 1.0) / (m + 1.0);
  z = m * m;
  SHLI_MLOG_POLY(x, z, SHLI_V4);
  return SHLI_MLOG_END(e, m, z, x);
}
SHLIGHT_ALWAYS_INLINE static inline void shli_sincos4(shli_v4d t, shli_v4d *out_s,
                                                      shli_v4d *out_c) {
  shli_v4d u = t * 0.63661977236758134 + 6755399441055744.0; /* the quadrant in the low bits */
  shli_v4d r = u - 6755399441055744.0;
  shli_v4d q1 = (shli_v4d)_mm256_slli_epi64(SHLI_V4I(u), 63);
  shli_v4d z;
  shli_v4d s;
  shli_v4d c;
  r = t - r * 1.5707963267341256 - r * 6.077100506506192e-11;
  z = r * r;
  SHLI_MSINCOS_POLY(s, c, r, z, SHLI_V4);
  *out_s = _mm256_xor_pd(SHLI_V4SEL(q1, c, s), SHLI_V4SG(SHLI_V4I(u), 62));
  *out_c = _mm256_xor_pd(SHLI_V4SEL(q1, s, c), SHLI_V4SG(SHLI_V4I(u + 1.0), 62));
}
/* shli_atan2r in lanes (the same steps; atan2(0, 0) = 0) */
SHLIGHT_ALWAYS_INLINE static inline shli_v4d shli_atan2_4(shli_v4d y, shli_v4d x) {
  shli_v4d ay = _mm256_andnot_pd(SHLI_V4(-0.0), y);
  shli_v4d ax = _mm256_andnot_pd(SHLI_V4(-0.0), x);
  shli_v4d g = _mm256_cmp_pd(ay, ax, _CMP_GT_OQ);
  shli_v4d t = SHLI_V4SEL(g, ax / ay, ay / ax);
  shli_v4d t2;
  shli_v4d a;
  t = t / (1.0 + _mm256_sqrt_pd(1.0 + t * t));
  t = t / (1.0 + _mm256_sqrt_pd(1.0 + t * t));
  t2 = t * t;
  a = SHLI_V4(-0.066666666666666667);
  a = 0.076923076923076923 + t2 * a;
  a = -0.090909090909090909 + t2 * a;
  a = 0.11111111111111111 + t2 * a;
  a = -0.14285714285714286 + t2 * a;
  a = 0.2 + t2 * a;
  a = -0.33333333333333333 + t2 * a;
  a = 4.0 * (t + t * (t2 * a));
  a = SHLI_V4SEL(g, 1.5707963267948966 - a, a);
  a = SHLI_V4SEL(SHLI_V4CMP(x, LT, 0.0), 3.1415926535897932 - a, a);
  a = SHLI_V4SEL(SHLI_V4CMP(y, LT, 0.0), -a, a);
  return _mm256_and_pd(_mm256_or_pd(SHLI_V4CMP(ax, GT, 0.0), SHLI_V4CMP(ay, GT, 0.0)), a);
}
/* shli_mf_taylor's edge loop in lanes: the setup (the edge's arc, the grading about the
   integrand's peak) of 4 edges at a time, then an edge's Gauss nodes 4 at a time
   (shli_ggx_side); the same algebra and polynomials, the sums in another order */
SHLIGHT_CPU_INLINE void shli_ggx_edges4(const shli_real *px, const shli_real *py,
                                        const shli_real *pz, int nc, shli_real rx, shli_real ry,
                                        shli_real rz, shli_real vx, shli_real vy, shli_real vz,
                                        shli_real nx, shli_real ny, shli_real nz, shli_real a2,
                                        shli_real gx, shli_real gy, shli_real gz, shli_real i1,
                                        shli_real al, int ndf, shli_real *io_am) {
  /* Gauss-Legendre nodes, weights (4 and 5 per side); shli_beck_i's fit */
  static const double xw[2][10] = {{-.86113631159405258, -.33998104358485626, .33998104358485626,
                                    .86113631159405258, 0, .34785484513745386, .65214515486254614,
                                    .65214515486254614, .34785484513745386, 0},
                                   {-.90617984593866399, -.53846931010568309, 0, .53846931010568309,
                                    .90617984593866399, .23692688505618909, .47862867049936647,
                                    .56888888888888889, .47862867049936647, .23692688505618909}};
  static const double bk[14] = {
      .6384891907791029,      -.046381913173553224,   -.08301519969842093,   .08202562922023758,
      -.027109944299521422,   -.004016780184587048,   .004359972791898658,   .0006349526378748344,
      -.0007155524025357445,  -.00024355655667775413, 7.319183804664685e-05, .00017624229959215334,
      -.00010318949224549979, 1.653978468591848e-05};
  double w[11][4]; /* per lane: a, b (the tangent), sa, sb, t0, wd, |a x b| */
  double ns[12];
  double nw[12];
  shli_real c = 1.0 - a2;
  shli_real gn = gx * nx + gy * ny + gz * nz;
  shli_real tx = gx - gn * nx, ty = gy - gn * ny, tz = gz - gn * nz;
  shli_real ux = ny * vz - nz * vy, uy = nz * vx - nx * vz, uz = nx * vy - ny * vx; /* n x v */
  shli_real hx = ty * vz - tz * vy, hy = tz * vx - tx * vz, hz = tx * vy - ty * vx; /* t x v */
  shli_real lo, hl;
  shli_v4d ax, ay, az, bx, by, bz, ex, ey, ez, se, phi, t0, ct, st, qx, qy, qz, dx, dy, dz, d, q;
  shli_v4d d0, f1, f2, wd, s, jw, qn, qq, qxy, cn, th, it, m, u, e;
  shli_v4d sm[2] = {SHLI_V4(0.0), SHLI_V4(0.0)}; /* A and M1.g */
  int g = ndf != 0 || al < 0.02;                 /* 4 + g nodes per side */
  int i, j, k, l, cnt;
  for (i = 0; i < nc; i += 4) {
    for (k = 0; k < 4; ++k) { /* edge i + k from vertex j to j + 1 (idle lanes: the last edge) */
      j = i + k < nc ? i + k : nc - 1;
      w[0][k] = px[j];
      w[1][k] = py[j];
      w[2][k] = pz[j];
      j = j + 1 < nc ? j + 1 : 0;
      w[3][k] = px[j];
      w[4][k] = py[j];
      w[5][k] = pz[j];
    }
    ax = _mm256_loadu_pd(w[0]);
    ay = _mm256_loadu_pd(w[1]);
    az = _mm256_loadu_pd(w[2]);
    bx = _mm256_loadu_pd(w[3]);
    by = _mm256_loadu_pd(w[4]);
    bz = _mm256_loadu_pd(w[5]);
    ex = ay * bz - az * by;
    ey = az * bx - ax * bz;
    ez = ax * by - ay * bx;
    se = _mm256_sqrt_pd(ex * ex + ey * ey + ez * ez);
    phi = shli_atan2_4(se, ax * bx + ay * by + az * bz);
    ex = ex / se;
    ey = ey / se;
    ez = ez / se;
    bx = ey * az - ez * ay;
    by = ez * ax - ex * az;
    bz = ex * ay - ey * ax;
    t0 = shli_atan2_4(rx * bx + ry * by + rz * bz, rx * ax + ry * ay + rz * az);
    t0 = t0 + _mm256_and_pd(_mm256_cmp_pd(t0, 0.5 * phi - 3.1415926535897932, _CMP_LT_OQ),
                            SHLI_V4(6.2831853071795865));
    for (k = 0; k < 2; ++k) { /* the Newton step (k = 0), then d0 and f2 where it went */
      shli_sincos4(t0, &st, &ct);
      qx = ct * ax + st * bx + vx;
      qy = ct * ay + st * by + vy;
      qz = ct * az + st * bz + vz;
      dx = ct * bx - st * ax;
      dy = ct * by - st * ay;
      dz = ct * bz - st * az;
      d = qx * nx + qy * ny + qz * nz;
      q = dx * nx + dy * ny + dz * nz;
      d0 = qx * qx + qy * qy + qz * qz - c * d * d;
      f1 = qx * dx + qy * dy + qz * dz - c * d * q;
      f2 = dx * dx + dy * dy + dz * dz - c * q * q - d0 +
           (vx * qx + vy * qy + vz * qz - c * (vx * nx + vy * ny + vz * nz) * d);
      if (k == 0) {
        s = _mm256_cmp_pd(_mm256_andnot_pd(SHLI_V4(-0.0), f1), 3.1415926535897932 * f2, _CMP_LT_OQ);
        t0 = t0 - _mm256_and_pd(s, f1 / f2);
      }
    }
    wd = SHLI_V4SEL(_mm256_cmp_pd(f2, 1.0e-2 * d0, _CMP_GT_OQ),
                    _mm256_min_pd(_mm256_sqrt_pd(d0 / f2), SHLI_V4(10.0)), SHLI_V4(10.0));
    wd = _mm256_max_pd(wd, SHLI_V4(1.0e-7));
    _mm256_storeu_pd(w[3], bx);
    _mm256_storeu_pd(w[4], by);
    _mm256_storeu_pd(w[5], bz);
    for (k = 0; k < 2; ++k) { /* sa, sb: asinh(-t0 / wd), asinh((phi - t0) / wd) */
      s = (phi - t0) / wd;
      if (k == 0) {
        s = -t0 / wd;
      }
      d = _mm256_andnot_pd(SHLI_V4(-0.0), s);
      _mm256_storeu_pd(w[6 + k], _mm256_or_pd(_mm256_and_pd(SHLI_V4(-0.0), s),
                                              shli_log4(d + _mm256_sqrt_pd(s * s + 1.0))));
    }
    _mm256_storeu_pd(w[8], t0);
    _mm256_storeu_pd(w[9], wd);
    _mm256_storeu_pd(w[10], se);
    for (l = 0; l < 4 && i + l < nc; ++l) { /* the edges' nodes (shli_ggx_side) */
      if (!(w[10][l] > 1.0e-30)) {
        continue;
      }
      ax = SHLI_V4(w[0][l]);
      ay = SHLI_V4(w[1][l]);
      az = SHLI_V4(w[2][l]);
      bx = SHLI_V4(w[3][l]);
      by = SHLI_V4(w[4][l]);
      bz = SHLI_V4(w[5][l]);
      ex = ay * bz - az * by;
      ey = az * bx - ax * bz;
      ez = ax * by - ay * bx;
      d0 = ex * nx + ey * ny + ez * nz; /* e.n, e.t */
      f1 = ex * tx + ey * ty + ez * tz;
      dx = ax * ux + ay * uy + az * uz; /* a.(n x v), b.(n x v) */
      dy = bx * ux + by * uy + bz * uz;
      dz = ax * hx + ay * hy + az * hz; /* a.(t x v), b.(t x v) */
      f2 = bx * hx + by * hy + bz * hz;
      cnt = 0;
      for (k = 0; k < 2; ++k) { /* [sa, 0] and [0, sb] across s = 0, else [sa, sb] */
        lo = k == 0 ? w[6][l] : 0.0;
        hl = k == 0 && w[7][l] > 0.0 && w[6][l] < 0.0 ? -0.5 * w[6][l] : 0.5 * (w[7][l] - lo);
        if (k == 1 && !(w[7][l] > 0.0 && w[6][l] < 0.0)) {
          hl = 0.0;
        }
        if (hl > 0.0) { /* 4 nodes, the fifth (g = 1) after them */
          _mm256_storeu_pd(ns + cnt, lo + hl * (_mm256_loadu_pd(xw[g]) + 1.0));
          _mm256_storeu_pd(nw + cnt, _mm256_loadu_pd(xw[g] + 5) * (hl * 0.5 * w[9][l]));
          ns[cnt + 4] = lo + hl * (xw[g][4] + 1.0);
          nw[cnt + 4] = xw[g][9] * hl * 0.5 * w[9][l];
          cnt = cnt + 4 + g;
        }
      }
      for (j = cnt; (j & 3) != 0; ++j) { /* idle lanes: weight 0 */
        ns[j] = ns[0];
        nw[j] = 0.0;
      }
      for (j = 0; j < cnt; j += 4) {
        e = shli_exp4(_mm256_loadu_pd(ns + j));
        jw = _mm256_loadu_pd(nw + j) * (e + 1.0 / e);
        shli_sincos4(w[8][l] + 0.5 * w[9][l] * (e - 1.0 / e), &st, &ct);
        qx = ct * ax + st * bx + vx;
        qy = ct * ay + st * by + vy;
        qz = ct * az + st * bz + vz;
        qn = qx * nx + qy * ny + qz * nz;
        qq = qx * qx + qy * qy + qz * qz;
        cn = d0 + ct * dy - st * dx;
        qxy = _mm256_max_pd(qq - qn * qn, SHLI_V4(0.0));
        d = qxy + a2 * qn * qn;
        th = qn / _mm256_sqrt_pd(qq);
        if (ndf == 0) {
          u = (1.0 - a2) * th * th; /* J(u), shli_ggx_j: the series below 0.1 */
          m = SHLI_V4(13.0 / 27.0);
          for (k = 12; k > 0; --k) {
            m = (double)k / (double)(2 * k + 1) + u * m;
          }
          e = _mm256_sqrt_pd(u);
          it = qq / d;
          e = (it - 0.5 * shli_log4((1.0 + e) * (1.0 + e) * it) / e) / (2.0 * u);
          it = th * th * th * SHLI_V4SEL(SHLI_V4CMP(u, LT, 0.1), m, e);
          m = cn / d;
        } else { /* the Beckmann branch and shli_beck_i */
          d = _mm256_and_pd(SHLI_V4CMP(qn, GT, 0.0), d);
          u = qxy / (a2 * qn * qn);
          e = shli_exp4(-u);
          m = 1.0 / 120.0 - u * (1.0 / 720.0 - u * (1.0 / 5040.0));
          m = 0.5 - u * (1.0 / 6.0 - u * (1.0 / 24.0 - u * m));
          m = cn *
              SHLI_V4SEL(SHLI_V4CMP(u, LT, 0.1), (1.0 - u * m) / (a2 * qn * qn), (1.0 - e) / qxy);
          u = al * th;
          q = (1.0 - 2.0 * u) / (1.0 + 2.0 * u);
          it = SHLI_V4(bk[13]);
          for (k = 12; k >= 0; --k) {
            it = bk[k] + q * it;
          }
          it = 1.7724538509055160 * th * e * it / (a2 * (u + 2.0));
        }
        e = _mm256_and_pd(SHLI_V4CMP(d, GT, 0.0), SHLI_V4CMP(qq, GT, 0.0));
        sm[0] = sm[0] + _mm256_and_pd(e, jw * m);
        m = -(f1 + ct * f2 - st * dz) * it / (qn * qn) +
            _mm256_and_pd(_mm256_cmp_pd(qxy, 1.0e-30 * qq, _CMP_GT_OQ), gn * (it - i1) * cn / qxy);
        sm[1] = sm[1] + _mm256_and_pd(e, jw * m);
      }
    }
  }
  sm[0] = _mm256_hadd_pd(sm[0], sm[1]); /* (A0 + A1, M0 + M1, A2 + A3, M2 + M3) */
  io_am[0] = io_am[0] + sm[0][0] + sm[0][2];
  io_am[1] = io_am[1] + sm[0][1] + sm[0][3];
}
/* shli_ggx_tri in lanes: 7 nodes as 2 blocks of 4 (the 8th weight 0), the same algebra (with
   shli_ggx_w's; Beckmann's Lambda by shli_exp4), the sums in another order */
SHLIGHT_CPU_INLINE void shli_ggx_tri4(shli_real ax, shli_real ay, shli_real az, shli_real bx,
                                      shli_real by, shli_real bz, shli_real cx, shli_real cy,
                                      shli_real cz, shli_real vx, shli_real vy, shli_real vz,
                                      shli_real nx, shli_real ny, shli_real nz, shli_real a2,
                                      shli_real lamv, shli_real ws, shli_real hx, shli_real hy,
                                      shli_real hz, shli_real gx, shli_real gy, shli_real gz,
                                      shli_real al, int ndf, shli_real *out_q) {
  /* r, s (q = a + r (b - a) + s (c - a)); the weights of degree 5 and 2 */
  static const double tn[4][8] = {
      {.33333333333333333, .05971587178976982, .47014206410511509, .47014206410511509,
       .79742698535308732, .10128650732345634, .10128650732345634, 0},
      {.33333333333333333, .47014206410511509, .05971587178976982, .47014206410511509,
       .10128650732345634, .79742698535308732, .10128650732345634, 0},
      {.1125, .06619707639425309, .06619707639425309, .06619707639425309, .062969590272413576,
       .062969590272413576, .062969590272413576, 0},
      {.24206145913796356, 0, 0, 0, .08597951362067881, .08597951362067881, .08597951362067881, 0}};
  shli_real nv = vx * nx + vy * ny + vz * nz, det;
  shli_v4d qx, qy, qz, q, dx, dy, dz, d, d0, f1, f2, nl, hv, r, m, f;
  shli_v4d s0 = SHLI_V4(0.0), s1 = s0;
  int j;
  bx = bx - ax;
  by = by - ay;
  bz = bz - az;
  cx = cx - ax;
  cy = cy - ay;
  cz = cz - az;
  det = (ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx)) *
        0.079577471545947668;
  ws = ws - gx * hx - gy * hy - gz * hz;
  for (j = 0; j < 8; j += 4) {
    f1 = _mm256_loadu_pd(tn[0] + j);
    f2 = _mm256_loadu_pd(tn[1] + j);
    qx = ax + f1 * bx + f2 * cx;
    qy = ay + f1 * by + f2 * cy;
    qz = az + f1 * bz + f2 * cz;
    q = _mm256_sqrt_pd(qx * qx + qy * qy + qz * qz);
    qx = qx / q;
    qy = qy / q;
    qz = qz / q;
    dx = qx + vx;
    dy = qy + vy;
    dz = qz + vz;
    f2 = dx * dx + dy * dy + dz * dz;
    d = dx * nx + dy * ny + dz * nz;
    d0 = (f2 - (1.0 - a2) * d * d) / f2;
    f1 = _mm256_sqrt_pd(f2);
    nl = qx * nx + qy * ny + qz * nz;
    hv = dx * vx + dy * vy + dz * vz;
    if (ndf == 0) { /* shli_ggx_w: Lambda(l) */
      r = 0.5 * (_mm256_sqrt_pd(nl * nl + a2 * (1.0 - nl * nl)) / nl - 1.0);
    } else { /* shli_beckmann_lambda */
      r = nl / (al * _mm256_sqrt_pd(_mm256_max_pd(1.0 - nl * nl, SHLI_V4(0.0))));
      r = _mm256_max_pd(_mm256_min_pd(r, SHLI_V4(1.0e10)), SHLI_V4(1.0e-30));
      m = 1.0 / (1.0 + 0.3275911 * r);
      m = m * (0.254829592 +
               m * (-0.284496736 + m * (1.421413741 + m * (-1.453152027 + m * 1.061405429))));
      r = 0.5 * shli_exp4(-r * r) * (0.56418958354775629 / r - m);
    }
    r = hv / ((1.0 + lamv + r) * nv * d);
    r = _mm256_and_pd(_mm256_and_pd(SHLI_V4CMP(nl, GT, 0.0), SHLI_V4CMP(d, GT, 0.0)), r);
    r = (r - ws - (gx * dx + gy * dy + gz * dz) / f1) * det / (q * q * q); /* w - w* - g.dh */
    if (ndf == 0) {
      f = r * a2 * d / (d0 * d0 * hv);
    } else {
      f = r * shli_exp4(-(f2 - d * d) / (a2 * d * d)) * f2 * f2 / (a2 * d * d * d * hv);
      f = _mm256_and_pd(SHLI_V4CMP(d, GT, 0.0), f);
    }
    s0 = s0 + _mm256_loadu_pd(tn[2] + j) * f;
    s1 = s1 + _mm256_loadu_pd(tn[3] + j) * f;
  }
  s0 = _mm256_hadd_pd(s0, s1);
  out_q[0] = s0[0] + s0[2];
  out_q[1] = s0[1] + s0[3];
}
#endif

/* The remainder's integral over a spherical triangle: out_q[0] degree 5 (Dunavant, 7 points),
   out_q[1] degree 2 (error estimate); nn = 7. (docs/derivations.md sec. 13.33) */
SHLIGHT_INLINE void shli_ggx_tri(shli_real ax, shli_real ay, shli_real az, shli_real bx,
                                 shli_real by, shli_real bz, shli_real cx, shli_real cy,
                                 shli_real cz, shli_real vx, shli_real vy, shli_real vz,
                                 shli_real nx, shli_real ny, shli_real nz, shli_real a2,
                                 shli_real lamv, shli_real ws, shli_real hx, shli_real hy,
                                 shli_real hz, shli_real gx, shli_real gy, shli_real gz,
                                 shli_real al, int ndf, int nn, shli_real *out_q) {
  shli_real nr;
  shli_real ns;
  shli_real nw;
  shli_real np;
  shli_real nq;
  shli_real c = 1.0 - a2;
  shli_real f = 0.0;
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
  bx = bx - ax;
  by = by - ay;
  bz = bz - az;
  cx = cx - ax;
  cy = cy - ay;
  cz = cz - az;
  out_q[0] = 0.0;
  out_q[1] = 0.0;
  /* det(a, b, c) / (4 pi), g.h* */
  det = (ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx)) *
        0.079577471545947668;
  ws = ws - gx * hx - gy * hy - gz * hz;
  SHLIGHT_UNROLL(7)
  for (k = 0; k < nn; ++k) {
    /* node k: (1/3, 1/3); (q, p), (p, q), (p, p) for k = 1..3 and 4..6 (selects, no arrays) */
    np = 0.33333333333333333;
    nq = np;
    nw = 0.1125;
    if (k > 0) {
      np = 0.47014206410511509;
      nq = 0.059715871789769820;
      nw = 0.066197076394253090;
    }
    if (k > 3) {
      np = 0.10128650732345634;
      nq = 0.79742698535308732;
      nw = 0.062969590272413576;
    }
    nr = np;
    ns = np;
    if (k == 1 || k == 4) {
      nr = nq;
    }
    if (k == 2 || k == 5) {
      ns = nq;
    }
    qx = ax + nr * bx + ns * cx;
    qy = ay + nr * by + ns * cy;
    qz = az + nr * bz + ns * cz;
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
        (gx * dx + gy * dy + gz * dz) / f1;
    if (ndf == 0) {
      /* D = alpha^2 / (pi (1 - c (h.n)^2)^2), (h.n) / (h.v) = d / (l + v).v */
      f = det / (q * q * q) * a2 * d / (d0 * d0 * (dx * vx + dy * vy + dz * vz)) * w;
    } else {
      /* D_B (h.n) / (4 h.v) = exp(-(f2 - d^2) / (alpha^2 d^2)) f2^2 / (4 pi alpha^2 d^3 (l + v).v),
         d = (l + v).n, f2 = |l + v|^2; 0 for d <= 0 */
      f = det / (q * q * q) * SHLIGHT_MEXP(-(f2 - d * d) / (a2 * d * d)) * f2 * f2 /
          (a2 * d * d * d * (dx * vx + dy * vy + dz * vz)) * w;
      if (!(d > 0.0)) {
        f = 0.0;
      }
    }
    out_q[0] = out_q[0] + nw * f;
    /* the embedded degree-2 rule: the centroid 0.48412, the three outer nodes 0.17196 each */
    if (k == 0) {
      out_q[1] = out_q[1] + 0.24206145913796356 * f;
    } else if (k > 3) {
      out_q[1] = out_q[1] + 0.085979513620678810 * f;
    }
  }
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
  shli_real rq[2];
  int dg[SHLIGHT_GGX_GDEPTH];
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
  shli_real ax;
  shli_real ay;
  shli_real az;
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
  shli_real lsx;
  shli_real lsy;
  shli_real lsz;
  shli_real nls;
  shli_real pc;
  shli_real tol;
  shli_real ori = 1.0;
  shli_real ox = 0.0;
  shli_real oy = 0.0;
  shli_real oz = 0.0;
  int spl;
  int npk;
  int nsp;
  int dmin;
  int dep;
  int dmax;
  int smax;
  int it;
  int it2;
  int inside = 1;
  int nk;
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
  /* negative orientation: every edge and remainder term changes sign with it (with l', det):
     the sum is multiplied by ori at the end, the arrays are not reversed */
  if (nc < 0) {
    nc = -nc;
    ori = -1.0;
  }
  /* the mirror direction r; one loop over the edges: whether r lies inside the polygon, the
     point l* of its vertices and arcs closest to r (used if not), the sum of the vertices */
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
    ax = px[i];
    ay = py[i];
    az = pz[i];
    bx = px[j];
    by = py[j];
    bz = pz[j];
    d = ax * rx + ay * ry + az * rz;
    if (d > best) {
      best = d;
      sx = ax;
      sy = ay;
      sz = az;
    }
    ox = ox + ax;
    oy = oy + ay;
    oz = oz + az;
    ex = ay * bz - az * by;
    ey = az * bx - ax * bz;
    ez = ax * by - ay * bx;
    if (ori * (ex * rx + ey * ry + ez * rz) < 0.0) {
      inside = 0;
    }
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
            ex * (ay * qz - az * qy) + ey * (az * qx - ax * qz) + ez * (ax * qy - ay * qx) >= 0.0 &&
            ex * (qy * bz - qz * by) + ey * (qz * bx - qx * bz) + ez * (qx * by - qy * bx) >= 0.0) {
          best = d;
          sx = qx;
          sy = qy;
          sz = qz;
        }
      }
    }
  }
  if (inside != 0) {
    sx = rx;
    sy = ry;
    sz = rz;
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
  /* nk = 4; in GLSL a count it cannot fold: loops kept rolled (docs/glsl.md) */
  nk = SHLIGHT_FLAT_LOOPS == 0 || nc > 0 ? 4 : 0;
  for (k = 0; k < nk; ++k) {
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
  /* graded: lobe near the horizon or n.l*, n.v < 0.06; n.v < 0.02: all alpha, g = 0 */
  d = 2.0 * (hx * vx + hy * vy + hz * vz);
  lsx = d * hx - vx;
  lsy = d * hy - vy;
  lsz = d * hz - vz;
  nls = lsx * nx + lsy * ny + lsz * nz;
  pc = -2.0;
  if ((nls < SHLIGHT_GGX_HOR * al || SHLIGHT_MAXR(nls, nv2) < 0.06) && (al < 0.25 || nv2 < 0.02) &&
      ndf == 0) {
    pc = SHLIGHT_GGX_KAP * SHLIGHT_MAXR(al, 0.02);
    if (nv2 < 0.02) {
      gx = 0.0;
      gy = 0.0;
      gz = 0.0;
    }
  }
  /* A and M1.g along the edges */
  if (ndf == 0) {
    i1 = shli_ggx_j(c, a2);
  } else {
    i1 = shli_beck_i(1.0, 1.0, al, a2);
  }
  am[0] = 0.0;
  am[1] = 0.0;
#if SHLIGHT_GGX_LANES
  shli_ggx_edges4(px, py, pz, nc, rx, ry, rz, vx, vy, vz, nx, ny, nz, a2, gx, gy, gz, i1, al, ndf,
                  am);
#endif
  for (i = 0; i < nc * (1 - SHLIGHT_GGX_LANES); ++i) { /* C with AVX2: no trips, the lanes above */
    j = i + 1;
    if (j == nc) {
      j = 0;
    }
    ax = px[i];
    ay = py[i];
    az = pz[i];
    bx = px[j];
    by = py[j];
    bz = pz[j];
    ex = ay * bz - az * by;
    ey = az * bx - ax * bz;
    ez = ax * by - ay * bx;
    se = SHLIGHT_SQRTR(ex * ex + ey * ey + ez * ez);
    if (se > 1.0e-30) {
      phi = shli_atan2r(se, ax * bx + ay * by + az * bz);
      ex = ex / se;
      ey = ey / se;
      ez = ez / se;
      /* b: the unit tangent of the edge's great circle at a */
      bx = ey * az - ez * ay;
      by = ez * ax - ex * az;
      bz = ex * ay - ey * ax;
      t0 = shli_atan2r(rx * bx + ry * by + rz * bz, rx * ax + ry * ay + rz * az);
      if (t0 < 0.5 * phi - 3.1415926535897932) { /* within pi of the arc's middle */
        t0 = t0 + 6.2831853071795865;
      }
      for (k = 0; k < nk / 2; ++k) {
        ct = SHLIGHT_MCOS(t0);
        st = SHLIGHT_MSIN(t0);
        qx = ct * ax + st * bx + vx;
        qy = ct * ay + st * by + vy;
        qz = ct * az + st * bz + vz;
        dx = ct * bx - st * ax;
        dy = ct * by - st * ay;
        dz = ct * bz - st * az;
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
           SHLIGHT_MLOG(SHLIGHT_ABSR(sa) + SHLIGHT_SQRTR(sa * sa + 1.0));
      sb = SHLIGHT_REAL(SHLIGHT_SIGN1(sb)) *
           SHLIGHT_MLOG(SHLIGHT_ABSR(sb) + SHLIGHT_SQRTR(sb * sb + 1.0));
      shli_ggx_side(sa, sb, t0, wd, ax, ay, az, bx, by, bz, vx, vy, vz, nx, ny, nz, a2, gx, gy, gz,
                    i1, al, ndf, am);
    }
  }
  aa = am[0] * 0.15915494309189534;
  /* the remainder: the fan from the vertex centroid's direction, its adaptive pieces
     (docs/derivations.md sec. 13.29) */
  sx = ox;
  sy = oy;
  sz = oz;
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
  sp = 0.4;
  if (ndf != 0) {
    sp = 0.9;
  }
  tol = SHLIGHT_GGX_TOL / (1.0 + lamv);
  if (ndf != 0) { /* Beckmann: the fixed pieces (adaptive ones measured mixed on its sampler) */
    tol = 1.0e30;
  }
  rq[0] = 0.0;
  rq[1] = 0.0;
  nsp = 0;
  dmax = SHLIGHT_GGX_DEPTH;
  smax = SHLIGHT_GGX_SPLITS;
  if (pc > 0.0) {
    dmax = SHLIGHT_GGX_GDEPTH;
    smax = SHLIGHT_GGX_GSPLITS;
    if (nv2 < 0.02) {
      smax = SHLIGHT_GGX_XSPLITS;
    }
  }
  if (al < 0.05 && ndf == 0 && nls > 2.0 * SHLIGHT_GGX_HOR * al) {
    nc = 0; /* a narrow lobe well above the horizon: no remainder (second order in alpha) */
  }
  for (i = 0; i < nc; ++i) {
    j = i + 1;
    if (j == nc) {
      j = 0;
    }
    ax = px[i];
    ay = py[i];
    az = pz[i];
    bx = px[j];
    by = py[j];
    bz = pz[j];
    dmin = 0;
    if (sx * ax + sy * ay + sz * az < sp || sx * bx + sy * by + sz * bz < sp ||
        ax * bx + ay * by + az * bz < sp) {
      dmin = 1;
    }
    dep = 0;
    for (it = 0; it < 5 + 4 * SHLIGHT_GGX_XSPLITS; ++it) {
      /* the piece's vertices (tr, ts, tw)[0..2] from (centroid, a, b) down its path */
      tr[0] = sx;
      ts[0] = sy;
      tw[0] = sz;
      tr[1] = ax;
      ts[1] = ay;
      tw[1] = az;
      tr[2] = bx;
      ts[2] = by;
      tw[2] = bz;
      for (k = 0; k < dep; ++k) {
        tr[3] = tr[0] + tr[1];
        ts[3] = ts[0] + ts[1];
        tw[3] = tw[0] + tw[1];
        tr[4] = tr[1] + tr[2];
        ts[4] = ts[1] + ts[2];
        tw[4] = tw[1] + tw[2];
        tr[5] = tr[2] + tr[0];
        ts[5] = ts[2] + ts[0];
        tw[5] = tw[2] + tw[0];
        for (it2 = 3; it2 < 6; ++it2) { /* unit midpoints */
          q = SHLIGHT_SQRTR(tr[it2] * tr[it2] + ts[it2] * ts[it2] + tw[it2] * tw[it2] + 1.0e-30);
          tr[it2] = tr[it2] / q;
          ts[it2] = ts[it2] / q;
          tw[it2] = tw[it2] / q;
        }
        if (dg[k] != 0) {
          tr[0] = tr[3];
          ts[0] = ts[3];
          tw[0] = tw[3];
        }
        if (dg[k] == 2) {
          tr[0] = tr[5];
          ts[0] = ts[5];
          tw[0] = tw[5];
        }
        if (dg[k] != 1) {
          tr[1] = tr[3];
          ts[1] = ts[3];
          tw[1] = tw[3];
        }
        if (dg[k] >= 2) {
          tr[1] = tr[4];
          ts[1] = ts[4];
          tw[1] = tw[4];
        }
        if (dg[k] == 0) {
          tr[2] = tr[5];
          ts[2] = ts[5];
          tw[2] = tw[5];
        }
        if (dg[k] == 1) {
          tr[2] = tr[4];
          ts[2] = ts[4];
          tw[2] = tw[4];
        }
        if (dg[k] == 3) {
          tr[2] = tr[5];
          ts[2] = ts[5];
          tw[2] = tw[5];
        }
      }
      /* graded: radius over |l + v| against KAP max(alpha, 0.02) + GRADE |h - h*| */
      npk = 0;
      if (pc > 0.0) {
        ex = tr[0] + tr[1] + tr[2];
        ey = ts[0] + ts[1] + ts[2];
        ez = tw[0] + tw[1] + tw[2];
        q = SHLIGHT_SQRTR(ex * ex + ey * ey + ez * ez);
        ex = ex / q;
        ey = ey / q;
        ez = ez / q;
        d = 1.0;
        for (k = 0; k < 3; ++k) {
          d = SHLIGHT_MINR(d, ex * tr[k] + ey * ts[k] + ez * tw[k]);
        }
        ex = ex + vx;
        ey = ey + vy;
        ez = ez + vz;
        q = SHLIGHT_SQRTR(ex * ex + ey * ey + ez * ez);
        f1 = SHLIGHT_SQRTR(SHLIGHT_MAXR(2.0 - 2.0 * (ex * hx + ey * hy + ez * hz) / q, 0.0));
        f2 = q * (pc + SHLIGHT_GGX_GRADE * f1);
        if (2.0 - 2.0 * d > f2 * f2) {
          npk = 1;
        }
      }
      /* split: 1 forced (a wide fan triangle), 2 graded or by the estimate (counted); a piece
         the graded rule splits is not evaluated */
      spl = 0;
      if (dep < dmin) {
        spl = 1;
      } else if (dep < dmax && npk != 0) {
        spl = 2;
        if (nsp >= smax) { /* budget spent: left out */
          spl = 0;
          rq[0] = 0.0;
        }
      } else {
#if SHLIGHT_GGX_LANES
        shli_ggx_tri4(tr[0], ts[0], tw[0], tr[1], ts[1], tw[1], tr[2], ts[2], tw[2], vx, vy, vz, nx,
                      ny, nz, a2, lamv, ws, hx, hy, hz, gx, gy, gz, al, ndf, rq);
#else
        shli_ggx_tri(tr[0], ts[0], tw[0], tr[1], ts[1], tw[1], tr[2], ts[2], tw[2], vx, vy, vz, nx,
                     ny, nz, a2, lamv, ws, hx, hy, hz, gx, gy, gz, al, ndf, nk + 3, rq);
#endif
        if (dep < dmax && nsp < smax && SHLIGHT_ABSR(rq[0] - rq[1]) > tol) {
          spl = 2;
        }
      }
      if (spl != 0) {
        if (spl == 2) {
          nsp = nsp + 1;
        }
        dg[dep] = 0;
        dep = dep + 1;
      } else {
        res = res + rq[0];
        /* the next piece: up past the last children, then the next sibling */
        for (k = 0; k < SHLIGHT_GGX_GDEPTH; ++k) {
          if (dep == 0 || dg[dep - 1] != 3) {
            break;
          }
          dep = dep - 1;
        }
        if (dep == 0) {
          break;
        }
        dg[dep - 1] = dg[dep - 1] + 1;
      }
    }
  }
  q = ori * (aa * ws - am[1] * a2 * 0.31830988618379067 - (gx * hx + gy * hy + gz * hz) * aa + res);
  return SHLIGHT_FLOAT(SHLIGHT_MINR(SHLIGHT_MAXR(q, 0.0), 1.0));
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

/* ---- fast GGX polygon lights (shl_polygon_ggx_fast; docs/area-lights.md "Fast GGX"): a linearly
   transformed cosine (Heitz et al. 2016) with no table. In the view frame (x toward the view,
   z = nrm) the lobe is M = R S, R the rotation in the xz-plane taking z to the unit axis
   (ux, 0, uz), S = ((a, 0, 0), (0, c, 0), (d, 0, 1)); the polygon is mapped by M^-1 =
   S^-1 R^T, clipped to the shading horizon (the plane (M^T z).y >= 0 in the mapped space, so no
   light from below the horizon) and to the cosine's z >= 0, and its cosine integral taken.
   a, c, d, the axis and the magnitude (the directional albedo) are closed-form fits in alpha
   and n.v (tools/fit_ggx_fast.c, fitted to polygon integrals of shl_polygon_ggx). */

/* The cosine integral over the polygon (io_px, io_py, io_pz)[0..nv-1] (the view frame's
   coordinates, overwritten) mapped by M^-1 as above, divided by pi: in [0, 1]. */
SHLIGHT_INLINE shli_real shli_ltc_ff(shli_real *io_px, shli_real *io_py, shli_real *io_pz, int nv,
                                     shli_real a, shli_real c, shli_real d, shli_real ux,
                                     shli_real uz) {
  shli_real wx;
  shli_real wz;
  shli_real cx;
  shli_real cy;
  shli_real cz;
  shli_real sp;
  shli_real sum = 0.0;
  shli_real ia = 1.0 / a;
  shli_real ic = 1.0 / c;
  shli_real hx = uz * d - ux * a;
  int nc = nv;
  int i;
  int j;
  for (i = 0; i < nv; ++i) {
    wx = (uz * io_px[i] - ux * io_pz[i]) * ia;
    wz = ux * io_px[i] + uz * io_pz[i];
    io_px[i] = wx;
    io_py[i] = io_py[i] * ic;
    io_pz[i] = wz - d * wx;
    if (!(hx * wx + uz * io_pz[i] >= 0.0) || !(io_pz[i] >= 0.0)) {
      nc = 0;
    }
  }
  if (nc == 0) { /* a vertex below either plane: clip */
    nc = shli_poly_clip_unit2(io_px, io_py, io_pz, nv, hx, 0.0, uz, 1, 0.0, 0.0, 1.0);
  } else { /* nothing to clip: orientation (shli_poly_clip_unit2's) and unit vertices */
    cx = 0.0;
    cy = 0.0;
    cz = 0.0;
    for (i = 0; i < nv; ++i) {
      j = i + 1;
      if (j == nv) {
        j = 0;
      }
      cx = cx + io_py[i] * io_pz[j] - io_pz[i] * io_py[j];
      cy = cy + io_pz[i] * io_px[j] - io_px[i] * io_pz[j];
      cz = cz + io_px[i] * io_py[j] - io_py[i] * io_px[j];
    }
    sp = cx * io_px[0] + cy * io_py[0] + cz * io_pz[0];
    for (i = 0; i < nv; ++i) {
      wx = SHLIGHT_SQRTR(io_px[i] * io_px[i] + io_py[i] * io_py[i] + io_pz[i] * io_pz[i]);
      if (!(wx > 0.0) || !(sp != 0.0)) {
        return 0.0;
      }
      wx = 1.0 / wx;
      io_px[i] = io_px[i] * wx;
      io_py[i] = io_py[i] * wx;
      io_pz[i] = io_pz[i] * wx;
    }
    if (sp < 0.0) {
      nc = -nv;
    }
  }
  for (i = 0; i < nc || i < -nc; ++i) {
    j = i + 1;
    if (j == nc || j == -nc) {
      j = 0;
    }
    cx = io_py[i] * io_pz[j] - io_pz[i] * io_py[j];
    cy = io_pz[i] * io_px[j] - io_px[i] * io_pz[j];
    cz = io_px[i] * io_py[j] - io_py[i] * io_px[j];
    sp = SHLIGHT_SQRTR(cx * cx + cy * cy + cz * cz);
    if (sp > 1.0e-30) {
      sum = sum + shli_atan2r(sp, io_px[i] * io_px[j] + io_py[i] * io_py[j] + io_pz[i] * io_pz[j]) *
                      cz / sp;
    }
  }
  if (nc < 0) {
    sum = -sum;
  }
  return SHLIGHT_MAXR(sum, 0.0) * 0.15915494309189534;
}

/* @fit ggx_fast begin: written by tools/fit_ggx_fast.c (emit), checked by its --check */
/* The fit of shl_polygon_ggx_fast (docs/area-lights.md): out_fit[0..4] a / alpha, g, d, P,
   k (low set: 1), degree 7 in x and 5 (low set: 7) in y = 2 mu - 1; out_fit[5] the albedo,
   degree 8 in x and 6 in 2 tau - 1. Per set, per output: rows of x-powers down to 0, each of
   y-powers down to 0. */
/* clang-format off */
static const shli_real SHLI_GGX_FAST_FIT[622] = {
  48.234318,14.083175,-77.58525,-9.565446,24.94422,2.18531,-17.115768,-5.204073,28.152754,3.4853196,
  -9.806126,-0.3161379,-79.5572,-23.871393,129.19554,15.550671,-41.681957,-3.3799565,21.443367,
  6.208293,-35.616455,-3.514215,12.762803,-0.09192495,38.478367,12.818616,-64.219185,-7.840121,
  21.150818,1.3320019,-7.0364275,-1.9935185,12.091924,0.528603,-4.558748,0.08479369,-4.6702304,
  -2.3297753,8.65813,1.3567837,-3.2000368,-0.41201264,0.2279602,0.44974208,-0.871561,0.019737553,
  0.31496698,1.8104783,-103.79392,-22.919329,136.24883,33.40543,-38.105495,-10.156947,16.257746,
  0.84541214,-28.652113,-6.9968696,10.428071,3.3069258,166.72935,39.11184,-219.32832,-55.715767,
  61.403248,16.975006,-9.99529,1.2201446,25.335686,7.0362644,-10.982811,-3.8880746,-77.413765,
  -19.654896,102.77594,27.398258,-28.983974,-8.593892,-3.1712353,-1.6438711,-1.685738,-1.3858993,
  2.2732804,1.3257632,9.102374,2.5906734,-12.5003395,-3.5501819,3.6284125,1.7728807,1.3254638,
  0.29028112,-1.0654882,-0.00049047795,0.094010614,0.23497783,-6.527444,-0.3014821,8.549859,
  0.78904384,-2.7406552,-0.14812239,1.974483,0.21461508,-2.4135618,-0.6803399,0.7731569,0.17090097,
  10.905095,0.5243554,-14.1635685,-1.1783719,4.6369643,-0.14296216,-2.203328,-0.11412735,2.3962212,
  0.8639344,-0.6117777,-0.3352966,-5.5888896,-0.3583876,7.1522346,0.3598783,-2.4984648,0.74191135,
  0.43646157,-0.07357994,-0.32416287,-0.23631264,-0.33317617,0.53170186,0.84602386,0.16106385,
  -1.0914507,0.05443511,0.46202806,-0.46102157,0.10683625,0.020975066,-0.100211374,-0.010092901,
  0.29472575,-0.33337295,-3.4658344,3.3734112,3.1145473,-3.2146244,-0.37557673,0.33904478,1.655289,
  -2.9448025,0.28334555,1.8978622,-0.89821804,-0.12693445,6.537312,-5.7325993,-7.065486,6.4924355,
  1.2288922,-0.8498405,-3.4435866,5.3385563,0.16984624,-3.835001,1.842203,0.34676784,-3.2056453,
  2.1672332,4.9123106,-3.9074633,-1.3824172,0.8597669,1.898267,-2.5245554,-0.5900171,2.309753,
  -1.3837427,-0.44879892,0.12939946,0.22486745,-0.98182195,0.6088613,0.5392538,-0.84651244,
  -0.12279706,0.098673195,0.17783703,-0.35584098,0.42445683,0.72787607,0.24927612,-0.8422532,
  0.52826583,0.29123297,-0.2741944,0.0450908,0.08441563,0.1669517,-0.2305231,-0.022498736,
  0.021212162,0.01900078,-0.664675,1.7358055,-0.87444216,-0.6301568,0.53722054,-0.10208758,
  0.0046036923,-0.3935841,0.3056211,0.060254216,-0.0041422453,-0.037735928,0.5091679,-1.1097882,
  0.41361755,0.45999852,-0.33393,0.061534572,-0.06532856,0.25172535,-0.14441222,-0.009109741,
  -0.010541088,0.012902316,-0.08833924,0.20205443,-0.06514819,-0.10856642,0.0684358,-0.0083270585,
  0.009661042,-0.031794738,0.0304433,-0.020940077,0.002348345,1.0034132,9.835902,48.1581632,
  30.166459,-52.541296,-41.316869,10.769987,8.002907,-45.17718,-132.71917,-30.154295,156.41694,
  82.130065,-36.67466,-19.730955,64.56232,102.42002,-62.114617,-146.75708,-15.90914,45.96161,
  14.345896,-26.592668,13.021951,94.5904,22.190078,-57.61072,-26.12346,-1.5325818,-8.703993,
  -39.186673,-27.588628,30.543792,38.056654,10.0328205,0.2797772,3.186378,1.3912543,-5.5386212,
  -4.1844916,-6.486798,-9.401535,-2.7765352,5.763625,10.4877256,-2.9211789,-9.704074,4.3800608,
  9.091201,2.425776,-3.63134,-4.3461437,5.216728,5.4819515,-5.079845,-5.7678623,-1.870434,0.9043915,
  0.9265271,-1.8953462,-1.67848643,2.3982167,3.0252141,0.52835815,-7.5485115,-10.115052,22.788317,
  6.762949,-12.72251,-0.26181465,0.54813695,0.51379204,6.0858912,-9.8333645,-2.296222,8.084302,
  -0.6884669,-1.2289176,-0.3162792,0.1645788,11.959713,16.336138,-37.13763,-10.63245,21.150671,
  0.17128235,-1.1037134,-0.7456866,-9.719004,15.082574,4.2226243,-12.661755,0.90301204,2.0114357,
  0.40399626,-0.22826049,-3.6905901,-7.9366302,14.875597,5.089677,-9.193972,0.058476202,0.6198007,
  0.22910675,4.5017605,-6.0347834,-2.7823553,5.348511,-0.11724225,-0.84501445,-0.06135959,
  0.018027667,-0.41372925,1.7760371,-1.2283928,-1.0646989,0.95944273,0.041795712,-0.019731257,
  -0.057209354,-0.7197259,0.9083131,0.4089186,-0.70859444,-0.009150315,0.10786715,0.024048043,
  1.9851645,-29.766481,22.742403,20.172861,-24.85898,-0.24713807,7.1867156,-0.24318413,-0.6310753,
  -16.31273,10.812418,14.108145,-10.137271,-2.3730044,2.3411808,0.15411036,-0.15857242,53.98522,
  -38.76312,-40.75695,42.657146,3.700646,-12.390524,0.035019863,1.035849,31.132795,-17.034575,
  -29.795921,16.360209,6.8071613,-3.9173467,-0.57600254,0.24356456,-26.894058,17.273273,23.423824,
  -19.023684,-4.236999,5.4953938,0.26659942,-0.41337422,-17.333834,6.1261673,18.95615,-5.957038,
  -5.597435,1.4161671,0.52307963,-0.027797224,0.79046124,-1.6377757,-0.22495,1.7596573,-0.1946675,
  -0.51539934,0.017074445,0.08123768,0.7503995,-0.27586132,-0.8642429,0.24957058,0.28306654,
  -0.057672568,-0.034117047,0.014032825,6.255294,-7.8284082,-4.078718,7.041815,-0.14864081,
  -1.3920618,0.15323208,0.046225984,5.46993,-6.819351,-3.5107756,6.3114467,-0.35498095,-1.237804,
  0.18390846,0.039691564,-8.527217,10.844047,5.547578,-9.636467,0.018051002,1.9472941,-0.16428901,
  -0.0672967,-8.037508,9.925724,5.5042987,-9.371904,0.2570772,1.9015113,-0.22692531,-0.06644354,
  2.3772335,-3.3321257,-1.2811626,2.7410645,-0.02397412,-0.5205772,0.0025358282,0.016044216,2.84348,
  -3.5246027,-2.1284971,3.5104768,-0.03008071,-0.7245258,0.0953074,-0.014058542,0.04508782,
  0.026149478,-0.1893709,0.13594103,0.054339506,-0.121630855,0.13082221,-0.075367674,-0.1158173,
  0.13162689,0.118533745,-0.17548342,0.033105806,-0.022444883,0.06967873,-0.03980717,-2.3034945,
  2.7277572,1.6319531,-2.45394,-0.079846315,0.5117978,-0.034843847,-0.018541278,-2.5192866,
  2.4925084,2.4911664,-2.7000098,-0.40063587,0.6515008,-0.021349732,-0.026036091,3.5962574,
  -5.0526257,-1.4412913,3.9212234,-0.45817348,-0.6609004,0.090451695,0.020742418,4.307697,
  -4.6497574,-3.8216598,4.831807,0.31757426,-1.0397242,0.06272737,0.034843016,-1.5285524,3.0325737,
  -0.75373536,-1.5527241,0.77071965,0.08673603,-0.0328666,-0.01950475,-2.2406528,2.857426,1.3979721,
  -2.6388373,0.27537015,0.3514273,0.024414081,-0.04361551,0.16770819,-0.6194324,0.63208026,
  -0.108279414,-0.06601046,-0.05331631,0.065029345,-0.020485625,0.38465932,-0.60974747,
  0.00014983486,0.31060523,-0.024556177,-0.07820525,0.021763789,0.99701256,13.189937,13.559884,
  -103.45519,-280.69385,-287.14996,-135.64996,-25.344433,-50.659504,60.644382,829.3341,1700.8037,
  1516.1082,640.64594,107.2671,24.628283,-635.01404,-2780.9304,-4441.4624,-3387.4463,-1248.354,
  -181.12297,196.4711,1838.7156,5129.382,6502.3584,4140.3535,1274.0369,149.00478,-488.05215,
  -2725.7766,-5718.613,-5807.6074,-2968.524,-691.7768,-49.95731,531.758,2331.224,3957.579,3220.6392,
  1218.5074,143.47562,-12.588985,-301.1867,-1147.3116,-1664.5409,-1081.6243,-232.11563,52.68624,
  21.55082,74.23208,282.7423,396.58588,213.90363,-14.796999,-54.127144,-13.552275,2.0181463,
  -16.138498,-49.621387,-30.334785,20.048779,25.089012,6.14298
};
/* clang-format on */
/* sum_ij SHLI_GGX_FAST_FIT[at + cols i + j] x^(rows - 1 - i) y^(cols - 1 - j) by Horner */
SHLIGHT_ALWAYS_INLINE
SHLIGHT_INLINE shli_real shli_ggx_fast_poly(int at, int rows, int cols, shli_real x, shli_real y) {
  shli_real u;
  shli_real t = 0.0;
  int i;
  int a;
  SHLIGHT_UNROLL(9)
  for (i = 0; i < rows; ++i) {
    a = at + cols * i;
    u = SHLI_GGX_FAST_FIT[a];
    u = SHLI_GGX_FAST_FIT[a + 1] + y * u;
    u = SHLI_GGX_FAST_FIT[a + 2] + y * u;
    u = SHLI_GGX_FAST_FIT[a + 3] + y * u;
    u = SHLI_GGX_FAST_FIT[a + 4] + y * u;
    u = SHLI_GGX_FAST_FIT[a + 5] + y * u;
    if (cols > 6) {
      u = SHLI_GGX_FAST_FIT[a + 6] + y * u;
    }
    if (cols > 7) {
      u = SHLI_GGX_FAST_FIT[a + 7] + y * u;
    }
    t = u + x * t;
  }
  return t;
}
/* one set: the high one (at 0) or the low one (at 303; k = 1) */
SHLIGHT_ALWAYS_INLINE
SHLIGHT_INLINE void shli_ggx_fast_set(int at, int cols, shli_real x, shli_real r, shli_real mu,
                                      shli_real tau, shli_real *out_fit) {
  shli_real y = 2.0 * mu - 1.0;
  shli_real z = 2.0 * tau - 1.0;
  shli_real t = 1.0 - tau;
  int b = at + 32 * cols;
  out_fit[0] = shli_ggx_fast_poly(at, 8, cols, x, y);
  out_fit[1] = shli_ggx_fast_poly(at + 8 * cols, 8, cols, x, y);
  out_fit[2] = shli_ggx_fast_poly(at + 16 * cols, 8, cols, x, y);
  out_fit[3] = shli_ggx_fast_poly(at + 24 * cols, 8, cols, x, y);
  out_fit[4] = 1.0;
  if (at == 0) {
    out_fit[4] = shli_ggx_fast_poly(b, 8, cols, x, y);
    b = b + 8 * cols;
  }
  out_fit[5] = t / SHLIGHT_SQRTR(t * t + tau * tau) + r * r * shli_ggx_fast_poly(b, 9, 7, x, z);
}
/* the low set for r <= 0.25, the high set for r >= 0.3, between them their outputs interpolated
   linearly in r (continuous in roughness) */
SHLIGHT_INLINE void shli_ggx_fast_fit(shli_real r, shli_real mu, shli_real tau,
                                      shli_real *out_fit) {
  shli_real hi[6];
  shli_real w = (r - 0.25) / (0.3 - 0.25);
  int i;
  if (w < 1.0) {
    shli_ggx_fast_set(303, 8, r * (2.0 / 0.35) - 1.0, r, mu, tau, out_fit);
  }
  if (w > 0.0) {
    shli_ggx_fast_set(0, 6, 2.0 * r - 1.0, r, mu, tau, hi);
    for (i = 0; i < 6; ++i) {
      if (w < 1.0) {
        hi[i] = out_fit[i] + w * (hi[i] - out_fit[i]);
      }
      out_fit[i] = hi[i];
    }
  }
}
/* @fit ggx_fast end */

SHLIGHT_INLINE float shl_polygon_ggx_fast(const float (*v)[3], int nv, const float nrm[3],
                                          const float view[3], float alpha) {
  shli_real px[SHLIGHT_CLIP_MAX];
  shli_real py[SHLIGHT_CLIP_MAX];
  shli_real pz[SHLIGHT_CLIP_MAX];
  shli_real par[6];
  shli_real nx = SHLIGHT_REAL(nrm[0]);
  shli_real ny = SHLIGHT_REAL(nrm[1]);
  shli_real nz = SHLIGHT_REAL(nrm[2]);
  shli_real vx = SHLIGHT_REAL(view[0]);
  shli_real vy = SHLIGHT_REAL(view[1]);
  shli_real vz = SHLIGHT_REAL(view[2]);
  shli_real ln = SHLIGHT_SQRTR(nx * nx + ny * ny + nz * nz);
  shli_real lv = SHLIGHT_SQRTR(vx * vx + vy * vy + vz * vz);
  shli_real al = SHLIGHT_REAL(alpha);
  shli_real mu;
  shli_real s;
  shli_real tx;
  shli_real ty;
  shli_real tz;
  shli_real bx;
  shli_real by;
  shli_real bz;
  shli_real x;
  shli_real y;
  shli_real z;
  shli_real ux;
  shli_real q;
  int i;
#if SHLIGHT_POLYGON_ANY
  if (nv > SHLIGHT_POLYGON_MAX) {
    return shli_fan_ggx_fast(v, nv, nrm, view, alpha);
  }
#endif
  if (nv > SHLIGHT_POLYGON_MAX) {
    return -1.0f;
  }
  if (nv < 3 || !(ln > 0.0) || !(ln < SHLIGHT_REAL_MAX) || !(lv > 0.0) ||
      !(lv < SHLIGHT_REAL_MAX) || !(al == al)) {
    return 0.0f;
  }
  nx = nx / ln;
  ny = ny / ln;
  nz = nz / ln;
  vx = vx / lv;
  vy = vy / lv;
  vz = vz / lv;
  mu = nx * vx + ny * vy + nz * vz;
  if (!(mu > 0.0)) {
    return 0.0f;
  }
  mu = SHLIGHT_MINR(mu, 1.0);
  al = SHLIGHT_MINR(SHLIGHT_MAXR(al, 1.0e-4), 1.0);
  /* the view frame: t toward the view in the tangent plane (any tangent at normal view, the
     frame of Duff et al. 2017), b = n x t */
  tx = vx - mu * nx;
  ty = vy - mu * ny;
  tz = vz - mu * nz;
  s = SHLIGHT_SQRTR(tx * tx + ty * ty + tz * tz);
  if (s > 1.0e-7) {
    tx = tx / s;
    ty = ty / s;
    tz = tz / s;
  } else {
    q = -1.0 / (SHLIGHT_REAL(SHLIGHT_SIGN1(nz)) + nz);
    tx = 1.0 + SHLIGHT_REAL(SHLIGHT_SIGN1(nz)) * nx * nx * q;
    ty = SHLIGHT_REAL(SHLIGHT_SIGN1(nz)) * nx * ny * q;
    tz = -SHLIGHT_REAL(SHLIGHT_SIGN1(nz)) * nx;
  }
  bx = ny * tz - nz * ty;
  by = nz * tx - nx * tz;
  bz = nx * ty - ny * tx;
  s = SHLIGHT_SQRTR(SHLIGHT_MAXR(1.0 - mu * mu, 0.0));
  for (i = 0; i < nv; ++i) {
    x = SHLIGHT_REAL(v[i][0]);
    y = SHLIGHT_REAL(v[i][1]);
    z = SHLIGHT_REAL(v[i][2]);
    if (!(SHLIGHT_ABSR(x) + SHLIGHT_ABSR(y) + SHLIGHT_ABSR(z) < SHLIGHT_REAL_MAX)) {
      return 0.0f;
    }
    px[i] = x * tx + y * ty + z * tz;
    py[i] = x * bx + y * by + z * bz;
    pz[i] = x * nx + y * ny + z * nz;
  }
  shli_ggx_fast_fit(SHLIGHT_SQRTR(al), mu, al * s / (mu + al * s), par);
  ux = -s * par[3];
  q = SHLIGHT_SQRTR(ux * ux + mu * mu);
  x = al * SHLIGHT_MAXR(par[0], 0.05);
  q = shli_ltc_ff(px, py, pz, nv, x, x * SHLIGHT_MAXR(mu + (1.0 - mu) * par[1], 1.0e-3), par[2],
                  ux / q, mu / q);
  return SHLIGHT_FLOAT(SHLIGHT_MAXR(par[4] * par[5] * q, 0.0));
}

/* ---- microfacet polygon lights in half-vector space: each light edge cut into sub-edges whose
   images are joined by great arcs. (docs/derivations.md sec. 13.34) */

/* One edge a -> b of the Stokes form of the Beckmann NDF about r: sgn(w) times the integral of the
   cap CDF over the arc. (docs/derivations.md sec. 13.35) */
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

/* The split points (fractions of the arc, ascending, in io_split) of the light edge a -> b for k
   sub-edges; returns their count. (docs/derivations.md sec. 13.36) */
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

/* integral along the great arc a -> b of t^p (u.c)^j ds (j = 0, 1), or of E(t) / t^2 (j = 2),
   graded 8-node Gauss-Legendre about the peak. (docs/derivations.md sec. 13.37) */
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

/* The integrals over the half-vector image of the clipped light polygon (signed by its winding) for
   kinds 0..3. (docs/derivations.md sec. 13.38) */
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

/* Common body of shl_polygon_blinn_phong (kind 0, par = e) and shl_polygon_beckmann_subedges (kind
   1, par = alpha). (docs/derivations.md sec. 13.39) */
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
#define SHLIGHT_FAN_SUM_(call) \
  shli_fan f; \
  shli_fan_begin(&f, v, nv); \
  while (shli_fan_next(&f, v, nv)) { \
    if (f.sg != 0) { \
      f.sum = f.sum + (double)f.sg * (double)(call); \
    } \
  } \
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
SHLIGHT_CPU_INLINE float shli_fan_ggx_fast(const float (*v)[3], int nv, const float nrm[3],
                                           const float view[3], float alpha) {
  SHLIGHT_FAN_SUM_(shl_polygon_ggx_fast(SHLIGHT_FAN_P_, f.np, nrm, view, alpha));
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

/* >>brdf -------------------------------------------------------------------------------------
   ZH of circularly symmetric BRDF lobes, convolution, irradiance, windowing, band selection.
   (docs/derivations.md sec. 13.40) */

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
/* C only, n^2 > SHLI_YBUF_COEFFS: Y_i(d) consumed as produced (no n^2 buffer). io == NULL: returns
   sum_i a[i] w_l Y_i; else io[i stride] += e Y_i (e == 0: =). (docs/derivations.md sec. 13.41) */
SHLIGHT_CPU_INLINE shli_real shli_sh_ystream(int n, float dx, float dy, float dz, const float *a,
                                             const float *zh, float e, float *io,
                                             ptrdiff_t stride) {
  shli_real x = SHLIGHT_REAL(dx), y = SHLIGHT_REAL(dy), z = SHLIGHT_REAL(dz);
  shli_real r2 = x * x + y * y + z * z - 1.0, kk = 1.0 + r2 * (-0.5 + 0.375 * r2);
  shli_real t, pc = 1.0, ps = 0.0, qc, xa, dd, s = 0.0, ra, rg, rc;
  float wl[SHLIGHT_MAX_BANDS], ec, es, oc, os, sw, sg, xf;
  int m, l, b;
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
        shli_sh_reinsch(l, m, &ra, &rg, &rc);
        dd = rc * dd - (ra * t) * xa;
        xa = rg * xa + dd;
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

SHLIGHT_INLINE float shl_zh_dot_zh(int n, const float *zh_a, const float axis_a[3],
                                   const float *zh_b, const float axis_b[3]) {
  n = shli_bands(n);
  if (n < 1) {
    return 0.0f;
  }
  return shli_zh_dot_c(n, zh_a, zh_b, shli_cos_between(axis_a, axis_b));
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

SHLIGHT_INLINE void shl_sh_irradiance_matrix(const float *sh, float out_m[16]) {
  /* c1 = sqrt(15 pi) / 16, c2 = sqrt(3 pi) / 6; 3 sqrt(5 pi) / 16, sqrt(pi) / 2, sqrt(5 pi) / 16 */
  shli_real c1 = 0.4290427654048917;
  shli_real c2 = 0.5116633539732443;
  out_m[0] = SHLIGHT_FLOAT(c1 * SHLIGHT_REAL(sh[8]));
  out_m[1] = SHLIGHT_FLOAT(c1 * SHLIGHT_REAL(sh[4]));
  out_m[2] = SHLIGHT_FLOAT(-c1 * SHLIGHT_REAL(sh[7]));
  out_m[3] = SHLIGHT_FLOAT(-c2 * SHLIGHT_REAL(sh[3]));
  out_m[5] = -out_m[0];
  out_m[6] = SHLIGHT_FLOAT(-c1 * SHLIGHT_REAL(sh[5]));
  out_m[7] = SHLIGHT_FLOAT(-c2 * SHLIGHT_REAL(sh[1]));
  out_m[10] = SHLIGHT_FLOAT(0.7431238683011271 * SHLIGHT_REAL(sh[6]));
  out_m[11] = SHLIGHT_FLOAT(c2 * SHLIGHT_REAL(sh[2]));
  out_m[15] = SHLIGHT_FLOAT(0.8862269254527579 * SHLIGHT_REAL(sh[0]) -
                            0.2477079561003757 * SHLIGHT_REAL(sh[6]));
  out_m[4] = out_m[1];
  out_m[8] = out_m[2];
  out_m[9] = out_m[6];
  out_m[12] = out_m[3];
  out_m[13] = out_m[7];
  out_m[14] = out_m[11];
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

SHLIGHT_INLINE void shl_zh_window(int n, shl_window_kind kind, float width, float *io_zh) {
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

/* >>hvl --------------------------------------------------------------------------------------
   Harmonics Virtual Lights: eq. 19-21 with the exact horizon fraction H (or the corrected
   smoothstep). (docs/derivations.md sec. 13.42) */

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

/* >>brdftab ----------------------------------------------------------------------------------
   BRDF SH tables: data[((p * n_theta + t) * 2 + k) * n^2 + i] (k = 0: F with the cosine, 1: F');
   grid of shli_brdf_grid_u; lookup cubic / linear in u, linear in phi_o.
   (docs/derivations.md sec. 13.43) */

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
  if (n_phi == 1 && n_theta >= 4) {
    /* isotropic: cubic in u, the Lagrange polynomial through samples t0 - 1 .. t0 + 2, the
       stencil shifted inwards in the first and last cells (no extrapolation) */
    p0 = -1;
    if (t0 == 0) {
      p0 = 0;
    }
    if (t0 == n_theta - 2) {
      p0 = -2;
    }
    fp = ft - SHLIGHT_ITOF(p0);
    for (j = 0; j < 4; ++j) {
      out_idx[j] = t0 + p0 + j;
    }
    out_w[0] = (1.0f - fp) * (fp - 2.0f) * (fp - 3.0f) * 0.16666667f;
    out_w[1] = fp * (fp - 2.0f) * (fp - 3.0f) * 0.5f;
    out_w[2] = fp * (fp - 1.0f) * (3.0f - fp) * 0.5f;
    out_w[3] = fp * (fp - 1.0f) * (fp - 2.0f) * 0.16666667f;
    return;
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

/* >>ssf --------------------------------------------------------------------------------------
   Screen-space SH filter for virtual point lights (VPLs): VPL SH, interleaved sampling, the
   discontinuity filter. (docs/derivations.md sec. 13.44) */

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

/* CPU-only part of >>brdftab (SHLIGHT_IMPLEMENTATION): analytic BRDFs (Lambert, Phong, Blinn-Phong,
   Beckmann, GGX), table build, SHLT files, MERL loader. (docs/derivations.md sec. 13.45) */
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
#define SHLI_VMADDS(a, b, c) \
  _mm512_add_round_ps(SHLI_VMULS((a), (b)), (c), _MM_FROUND_CUR_DIRECTION)
#define SHLI_VFMS2(a, b, c, d) \
  _mm512_sub_round_ps(SHLI_VMULS((a), (b)), SHLI_VMULS((c), (d)), _MM_FROUND_CUR_DIRECTION)
#define SHLI_VFMA2(a, b, c, d) \
  _mm512_add_round_ps(SHLI_VMULS((a), (b)), SHLI_VMULS((c), (d)), _MM_FROUND_CUR_DIRECTION)
/* SHLI_VSGN(a): the sign of a in a form that SHLI_VFLIP(v, s) applies to v (v times sign(a),
   bit-exact): the sign bit and a XOR on the SIMD paths, which leaves the multiply pipes free */
#define SHLI_VSGN(a) \
  _mm512_castsi512_ps(_mm512_and_si512(_mm512_castps_si512(a), _mm512_set1_epi32((int)0x80000000u)))
#define SHLI_VFLIP(v, s) \
  _mm512_castsi512_ps(_mm512_xor_si512(_mm512_castps_si512(v), _mm512_castps_si512(s)))
#define SHLI_VABS(a) \
  _mm512_castsi512_ps(_mm512_and_si512(_mm512_castps_si512(a), _mm512_set1_epi32(0x7fffffff)))
#define SHLI_VSIGN1(a) \
  _mm512_castsi512_ps(_mm512_or_si512( \
      _mm512_and_si512(_mm512_castps_si512(a), _mm512_set1_epi32((int)0x80000000u)), \
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

/* @generated batch: defined in >>generated at the end of the file */
SHLI_TAB_DECL(float, sh_brs, 376);
#define SHLI_SH_BRS (*shli_tab_sh_brs())
SHLI_TAB_DECL(float, sh_bpoly, 63);
#define SHLI_SH_BPOLY (*shli_tab_sh_bpoly())

/* Batch kernels of n <= SHLIGHT_UNROLLED_BANDS, nv = 1 or 2 vectors a call: output i of lane j of
   vector v at out[i stride + v SHLI_W + j]; nt: streaming stores.
   (docs/derivations.md sec. 13.46) */
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
#define SHLI_BSTORE(p, e) \
  do { \
    if (nt) \
      SHLI_VSTREAM((p), (e)); \
    else \
      SHLI_VSTORE((p), (e)); \
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
#define SHLI_BSTEPU(l, m, v, xa, dd) \
  do { \
    const float *c_ = SHLI_SH_BRS + 16 + 3 * (((l) * ((l)-1)) / 2 + (m)); \
    if ((l) == (m) + 1) { \
      (dd) = SHLI_VMULS(SHLI_VSET(c_[0]), t[v]); \
      (xa) = SHLI_VADD(SHLI_VSET(c_[1]), (dd)); \
    } else { \
      SHLI_V a_ = SHLI_VMULS(SHLI_VSET(c_[0]), t[v]); \
      (dd) = SHLI_VNMADD(a_, (xa), SHLI_VMULS(SHLI_VSET(c_[2]), (dd))); \
      (xa) = SHLI_VMADDS(SHLI_VSET(c_[1]), (xa), (dd)); \
    } \
  } while (0)
/* the column-0 steps due before unit u of the other columns */
#define SHLI_COL0() \
  while (s0 < n - 1 && s0 * nu < (n - 1) * u) { \
    ++s0; \
    SHLI_UNROLL_BATCH \
    for (v = 0; v < nv; ++v) \
      SHLI_BSTEPU(s0, 0, v, x0[v], d0[v]); \
    SHLI_UNROLL_BATCH \
    for (v = 0; v < nv; ++v) \
      SHLI_BSTOREI(s0 *(s0 + 1), v, (s0 & 1) ? SHLI_VFLIP(x0[v], sg[v]) : x0[v]); \
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
/* one Reinsch step of every vector: X~, D~ of the previous band to this one's (constants c),
   D = c D - (alpha t) X with alpha t off the chain: two FMA latencies a band, not four */
#define SHLI_BSTEP(c, xa, dd) \
  do { \
    SHLI_UNROLL_BATCH \
    for (v = 0; v < nv; ++v) { \
      SHLI_V a_ = SHLI_VMULS(SHLI_VSET((c)[0]), t[v]); \
      (dd)[v] = SHLI_VNMADD(a_, (xa)[v], SHLI_VMULS(SHLI_VSET((c)[2]), (dd)[v])); \
      (xa)[v] = SHLI_VMADDS(SHLI_VSET((c)[1]), (xa)[v], (dd)[v]); \
    } \
  } while (0)
/* rows l (l + 1) + m (at po) and - m (at pq) of band l, then po, pq to band l + 1 */
#define SHLI_BROWS(cu, su) \
  do { \
    SHLI_UNROLL_BATCH \
    for (v = 0; v < nv; ++v) \
      SHLI_BSTORE(po + v * SHLI_W, SHLI_VMULS(xa[v], (cu)[v])); \
    SHLI_UNROLL_BATCH \
    for (v = 0; v < nv; ++v) \
      SHLI_BSTORE(pq + v * SHLI_W, SHLI_VMULS(xa[v], (su)[v])); \
    po += dl; \
    pq += dl; \
    dl += 2 * stride; \
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
#define SHLI_SH_BATCH_N(N) \
  static void shli_sh_batch1_##N(const float *x, const float *y, const float *z, float *out, \
                                 ptrdiff_t stride) { \
    shli_sh_batch_poly((N), 1, 0, x, y, z, out, stride); \
  } \
  static void shli_sh_batch2_##N(const float *x, const float *y, const float *z, float *out, \
                                 ptrdiff_t stride) { \
    shli_sh_batch_poly((N), 2, 0, x, y, z, out, stride); \
  } \
  static void shli_sh_batch2s_##N(const float *x, const float *y, const float *z, float *out, \
                                  ptrdiff_t stride) { \
    shli_sh_batch_poly((N), 2, 1, x, y, z, out, stride); \
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
#define SHLI_SH_BATCH_N(N) \
  static void shli_sh_batch1_##N(const float *x, const float *y, const float *z, float *out, \
                                 ptrdiff_t stride) { \
    shli_sh_batch_rs1((N), x, y, z, out, stride); \
  } \
  static void shli_sh_batch2_##N(const float *x, const float *y, const float *z, float *out, \
                                 ptrdiff_t stride) { \
    shli_sh_batch_rs2((N), x, y, z, out, stride); \
  }
#else
#define SHLI_SH_BATCH_N(N) \
  static void shli_sh_batch1_##N(const float *x, const float *y, const float *z, float *out, \
                                 ptrdiff_t stride) { \
    shli_sh_batch_rsu((N), 1, x, y, z, out, stride); \
  } \
  static void shli_sh_batch2_##N(const float *x, const float *y, const float *z, float *out, \
                                 ptrdiff_t stride) { \
    shli_sh_batch_rsu((N), 2, x, y, z, out, stride); \
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
/* Below it, for outputs larger than L1: each pair prefetches the next pair's lines for writing.
   (docs/derivations.md sec. 13.47) */
#define SHLI_BATCH_PREFETCH_BANDS 10
#if defined(__GNUC__) || defined(__clang__)
#define SHLI_PREFETCHW(p) __builtin_prefetch((p), 1, 3)
#define SHLI_BATCH_NOINLINE static __attribute__((noinline))
#else
#define SHLI_PREFETCHW(p) ((void)0)
#define SHLI_BATCH_NOINLINE static
#endif

/* An output far larger than the caches (rows count floats apart, written once and not read
   back here) goes out by streaming stores: count a multiple of SHLI_W puts every row at the
   same alignment, so the pairs from j0 on are aligned; the vectors before j0 and after the last
   pair are plain (overlapping) stores */
SHLI_BATCH_NOINLINE void shli_sh_batch_nt(int n, int count, const float *x, const float *y,
                                          const float *z, float *out_y) {
  int j0 = (int)((((size_t)0 - (size_t)out_y) % (sizeof(float) * SHLI_W)) / sizeof(float)), j;
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
}
/* the pairs of vectors of one call (count >= 2 SHLI_W, kernel f2, plain stores), each
   prefetching the next pair's lines for writing (one a row per 64 bytes: the line after a pair
   is the next pair's first) */
SHLI_BATCH_NOINLINE void shli_sh_batch_pf(shli_sh_batch_fn f2, int n, int count, const float *x,
                                          const float *y, const float *z, float *out_y) {
  int j, i, k;
  for (j = 0;; j += 2 * SHLI_W) {
    if (j > count - 2 * SHLI_W) j = count - 2 * SHLI_W;
    if (j + 4 * SHLI_W <= count) {
      const float *pp = out_y + j + 2 * SHLI_W;
      for (i = 0; i < n * n; ++i, pp += count)
        for (k = 0; k < 2 * SHLI_W; k += 16)
          SHLI_PREFETCHW(pp + k);
    }
    f2(x + j, y + j, z + j, out_y + j, (ptrdiff_t)count);
    if (j + 2 * SHLI_W >= count) break;
  }
}

/* Batch loop for n > SHLIGHT_UNROLLED_BANDS: the generated kernels' math with table constants. */
static void shli_sh_batch_big(int n, const float *px, const float *py, const float *pz, float *out,
                              ptrdiff_t stride) {
  SHLI_V x = SHLI_VLOAD(px), y = SHLI_VLOAD(py), z = SHLI_VLOAD(pz);
  SHLI_V s2 = SHLI_VMADD(x, x, SHLI_VMUL(y, y));
  SHLI_V ir = SHLI_VDIV(SHLI_VSET(1.0f), SHLI_VSQRT(SHLI_VMADD(z, z, s2)));
  SHLI_V az = SHLI_VMUL(SHLI_VABS(z), ir);
  SHLI_V t = SHLI_VDIV(SHLI_VMUL(s2, SHLI_VMUL(ir, ir)), SHLI_VADD(SHLI_VSET(1.0f), az));
  SHLI_V sg = SHLI_VSIGN1(z);
  SHLI_V pc = SHLI_VSET(1.0f), ps = SHLI_VSET(0.0f), ec, es, oc, os, sw, xa, dd, k;
  float fa, fg, fc;
  int m, l;
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
    fa = (float)(2 * m + 1);
    fg = fa;
    fc = 0.0f;
    for (l = m + 1; l < n; ++l) {
      /* alpha, g, c in float: s2_l q = s2_l / sqrt((l - m)(l + m)) times 2l - 1, l + m, l - m - 1
       */
      float gq = (float)(SHLI_SH_S12[2 * l + 1] * SHLI_SH_RSQ[l - m] * SHLI_SH_RSQ[l + m]);
      dd = SHLI_VNMADD(SHLI_VSET(gq * fa), SHLI_VMUL(t, xa), SHLI_VMUL(SHLI_VSET(gq * fc), dd));
      xa = SHLI_VMADD(SHLI_VSET(gq * fg), xa, dd);
      fa += 2.0f;
      fg += 1.0f;
      fc += 1.0f;
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

/* n > SHLIGHT_UNROLLED_BANDS: one vector a call, the last overlapping the previous one */
SHLI_BATCH_NOINLINE void shli_sh_batch_loop(int n, int count, const float *x, const float *y,
                                            const float *z, float *out_y) {
  int j;
  for (j = 0;; j += SHLI_W) {
    if (j > count - SHLI_W) j = count - SHLI_W;
    shli_sh_batch_big(n, x + j, y + j, z + j, out_y + j, (ptrdiff_t)count);
    if (j + SHLI_W >= count) break;
  }
}

/* count < SHLI_W, too few for one vector: the scalar kernel, strided (a function of its own:
   its 8 KB buffer would otherwise enlarge the frame of every call of the vector paths) */
SHLI_BATCH_NOINLINE void shli_sh_batch_few(int n, int count, const float *x, const float *y,
                                           const float *z, float *out_y) {
  float tmp[SHLI_YBUF_COEFFS]; /* <= 8 KB; more bands streamed (16 KB stack rule) */
  int i, j;
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
}

/* n <= SHLIGHT_UNROLLED_BANDS, count >= 2 SHLI_W: two vectors a call */
SHLI_BATCH_NOINLINE void shli_sh_batch_pairs(int n, int count, const float *x, const float *y,
                                             const float *z, float *out_y) {
  int j;
  /* two vectors a call, the last pair overlapping the previous one (the same values
     rewritten); outputs larger than L1 go to shli_sh_batch_nt or shli_sh_batch_pf */
  shli_sh_batch_fn f2 = n <= SHLI_SH_BPOLY_BANDS ? SHLI_SH_BATCHP[1][n] : SHLI_SH_BATCHR[1][n - 7];
  double bytes = (double)count * (double)(n * n) * sizeof(float);
  if (bytes > 32768.0) {
    if (count % SHLI_W == 0 && (size_t)out_y % sizeof(float) == 0 &&
        bytes >= SHLI_BATCH_STREAM_BYTES) {
      shli_sh_batch_nt(n, count, x, y, z, out_y);
      return;
    }
    if (SHLI_W >= 4 && n <= SHLI_BATCH_PREFETCH_BANDS &&
        bytes > (n <= SHLI_SH_BPOLY_BANDS ? 32768.0 : 65536.0) &&
        !(count % 1024 == 0 && (n * n > 9 || bytes <= 49152.0))) {
      shli_sh_batch_pf(f2, n, count, x, y, z, out_y);
      return;
    }
  }
  for (j = 0;; j += 2 * SHLI_W) {
    if (j > count - 2 * SHLI_W) j = count - 2 * SHLI_W;
    f2(x + j, y + j, z + j, out_y + j, (ptrdiff_t)count);
    if (j + 2 * SHLI_W >= count) break;
  }
}

SHLIGHT_API void shl_sh_eval_batch(int n, int count, const float *x, const float *y, const float *z,
                                   float *out_y) {
  int j;
  n = shli_bands(n);
  if (n < 1 || count <= 0) return;
  if (count < SHLI_W) {
    shli_sh_batch_few(n, count, x, y, z, out_y);
    return;
  }
  if (n <= SHLIGHT_UNROLLED_BANDS && count >= 2 * SHLI_W) {
    shli_sh_batch_pairs(n, count, x, y, z, out_y);
    return;
  }
  /* one vector a call; the last vector overlaps the previous one instead of running a scalar
     tail: the overlapping lanes are computed twice and written with the same values */
  if (n > SHLIGHT_UNROLLED_BANDS) {
    shli_sh_batch_loop(n, count, x, y, z, out_y);
    return;
  }
  for (j = 0;; j += SHLI_W) {
    if (j > count - SHLI_W) j = count - SHLI_W;
    shli_sh_batch_vec1(n, x + j, y + j, z + j, out_y + j, (ptrdiff_t)count);
    if (j + SHLI_W >= count) break;
  }
}

/* The accurate path: the Reinsch-form recurrence of the kernels, all in double, one rounding
   per output (Y = X U formed in double). */
static void shli_sh_core_accurate(int n, double x, double y, double t, double sg, float *out_y) {
  double pc = 1.0, ps = 0.0, ec, es, oc, os, sw, xa, dd, ra, rg, rc, fg, fc,
         xm = 0.28209479177387814;
  int m, l, b;
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
    fg = 2.0 * m + 1.0;
    fc = 0.0;
    for (l = m + 1; l < n; ++l) {
      /* shli_sh_reinsch with l + m, l - m - 1 counted in double (no int conversions) */
      double q = SHLI_SH_RSQ[l - m] * SHLI_SH_RSQ[l + m], gq = SHLI_SH_S12[2 * l + 1] * q;
      ra = SHLI_SH_S12[2 * l] * q;
      rg = gq * fg;
      rc = gq * fc;
      fg += 1.0;
      fc += 1.0;
      dd = rc * dd - (ra * t) * xa;
      xa = rg * xa + dd;
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
  shl_grid_order order;
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
                                      shl_grid_order sum_order, int threads, float *out_sh,
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
  int half;     /* 1: an isotropic microfacet lobe, the half-vector quadrature (width: alpha);
                   2: an anisotropic one (Beckmann / GGX), the stretched half-vector quadrature */
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

/* sorts the nb panel break points br[] of the quadratures below in place (insertion sort: a
   few dozen values) */
static void shli_sort_breaks(double *br, int nb) {
  int i;
  int j;
  for (i = 1; i < nb; ++i) {
    double v = br[i];
    for (j = i; j > 0 && br[j - 1] > v; --j) {
      br[j] = br[j - 1];
    }
    br[j] = v;
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
  shli_sort_breaks(br, nb);
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

/* the half-vector quadrature of an isotropic microfacet lobe at order q.
   (docs/derivations.md sec. 13.48) */
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
  shli_sort_breaks(br, nb);
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

/* one node of the stretched half-vector quadrature: h along (sx, sy, 1) (slopes), w_i the mirror
   of w_o about h, weight wgt 4 (w_o . h) */
static void shli_tab_snode(int n, const shli_tabsrc *src, const double wo[3], double sx, double sy,
                           double wgt, double *acc, float *y) {
  double hl = 1.0 / sqrt(1.0 + sx * sx + sy * sy);
  double h[3];
  double wi[3];
  double oh;
  double f;
  int k;
  h[0] = sx * hl;
  h[1] = sy * hl;
  h[2] = hl;
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

/* the half-vector quadrature of an anisotropic microfacet lobe at order q, in stretched slopes.
   (docs/derivations.md sec. 13.49) */
static void shli_tab_aniso(int n, const shli_tabsrc *src, const double wo[3], int q, double *acc,
                           float *y, const double *xg, const double *wg) {
  double br[128];
  double ub[40];
  double ax = (double)src->brdf->alpha_x;
  double ay = (double)src->brdf->alpha_y;
  double co = wo[2];
  double nw = sqrt(ax * ax * wo[0] * wo[0] + ay * ay * wo[1] * wo[1]);
  double ph0 = atan2(ax * wo[0], -ay * wo[1]);
  double c0 = cos(ph0);
  double s0 = sin(ph0);
  double w0 = nw > 0.0 ? co * sqrt(ax * ax * c0 * c0 + ay * ay * s0 * s0) / nw : 4.0;
  double amax = ax > ay ? ax : ay;
  double xn = wo[0] / ((1.0 + co) * ax);
  double yn = wo[1] / ((1.0 + co) * ay);
  double rn = sqrt(xn * xn + yn * yn);
  double phn = atan2(yn, xn);
  double dn = 0.25 / (amax * amax);
  int nb = 0;
  int p;
  int i;
  int j;
  int k;
  for (k = 0; k <= 4; ++k) {
    br[nb++] = ph0 + 0.5 * SHLI_PI * (double)k;
  }
  for (k = 1; k < 15; ++k) {
    double d = 0.5 * SHLI_PI * pow(0.25, (double)k);
    if (d < 0.25 * w0) {
      break;
    }
    br[nb++] = ph0 + d;
    br[nb++] = ph0 + 2.0 * SHLI_PI - d;
    br[nb++] = ph0 + SHLI_PI - d;
    br[nb++] = ph0 + SHLI_PI + d;
  }
  /* the azimuth of h, atan2(alpha_y sin(ph), alpha_x cos(ph)), turns alpha_y / alpha_x times
     faster than ph about the stretched axis of the smaller alpha: graded towards it (1/3) */
  for (k = 0; k < 12; ++k) {
    double rho = ax < ay ? ax / ay : ay / ax;
    double d = rho * pow(3.0, (double)k);
    double c = ax < ay ? 0.0 : 0.5 * SHLI_PI;
    int m;
    if (d > 0.4 * SHLI_PI) {
      break;
    }
    for (m = 0; m < 4; ++m) {
      double v = c + (m & 1 ? SHLI_PI : 0.0) + (m & 2 ? -d : d) - ph0;
      v -= 2.0 * SHLI_PI * floor(v / (2.0 * SHLI_PI));
      br[nb++] = ph0 + v;
    }
  }
  /* alpha > 1: Lambda(w_i) has a branch point within ~1 / alpha of w_i = z, whose half vector
     has the stretched slope (xn, yn) (radius rn, azimuth phn): graded towards it in ph and u */
  if (amax > 1.0 && rn > dn) {
    for (k = 0; k < 6; ++k) {
      double d = atan(dn * pow(3.0, (double)k) / rn);
      int m;
      if (d > 0.25 * SHLI_PI) {
        break;
      }
      for (m = 0; m < 2; ++m) {
        double v = phn + (m ? -d : d) - ph0;
        v -= 2.0 * SHLI_PI * floor(v / (2.0 * SHLI_PI));
        br[nb++] = ph0 + v;
      }
    }
  }
  shli_sort_breaks(br, nb);
  for (p = 0; p + 1 < nb; ++p) {
    double g0 = br[p];
    double g1 = br[p + 1];
    if (!(g1 - g0 > 1e-15)) {
      continue;
    }
    for (i = 0; i < q; ++i) {
      double ph = 0.5 * (g0 + g1) + 0.5 * (g1 - g0) * xg[i];
      double wp = 0.5 * (g1 - g0) * wg[i];
      double cp = cos(ph);
      double sp = sin(ph);
      double vx = ax * cp;
      double vy = ay * sp;
      double vw = vx * wo[0] + vy * wo[1];
      double v2 = vx * vx + vy * vy;
      double sq = sqrt(vw * vw + co * co * v2);
      double rmax = vw > 0.0 ? (vw + sq) / (co * v2) : co / (sq - vw);
      double umax = atan(rmax);
      double top = 0.5 * umax;
      int nu = 0;
      int pu;
      ub[nu++] = 0.0;
      ub[nu++] = umax;
      for (k = -2; k < 8; ++k) {
        double b = atan(pow(3.0, (double)k));
        if (b < umax) {
          ub[nu++] = b;
          top = b > top ? b : top;
        }
      }
      for (k = 0; k < 12 && (umax - top) > 0.5 * co; ++k) {
        top = umax - 0.25 * (umax - top);
        ub[nu++] = top;
      }
      if (amax > 1.0) {
        for (k = 0; k < 6; ++k) {
          double d = dn * pow(3.0, (double)k);
          if (rn + d < rmax) {
            ub[nu++] = atan(rn + d);
          }
          if (rn - d > 0.0 && rn - d < rmax) {
            ub[nu++] = atan(rn - d);
          }
        }
      }
      shli_sort_breaks(ub, nu);
      for (pu = 0; pu + 1 < nu; ++pu) {
        double a0 = ub[pu];
        double a1 = ub[pu + 1];
        if (!(a1 - a0 > 1e-15)) {
          continue;
        }
        for (j = 0; j < q; ++j) {
          double s = 0.5 * (xg[j] + 1.0);
          double u = a0 + (a1 - a0) * s * s * (3.0 - 2.0 * s);
          double tu = tan(u);
          double cu = cos(u);
          double sx = ax * tu * cp;
          double sy = ay * tu * sp;
          double c3 = 1.0 / (1.0 + sx * sx + sy * sy);
          double wu = 0.5 * wg[j] * (a1 - a0) * 6.0 * s * (1.0 - s);
          shli_tab_snode(n, src, wo, sx, sy, wp * wu * ax * ay * tu / (cu * cu) * c3 * sqrt(c3),
                         acc, y);
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
  if (spec && src->half == 2) {
    shli_tab_aniso(n, src, wo, q, acc, y, xg, wg);
  } else if (spec && src->half) {
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
  } else if (micro) {
    src.half = 2; /* anisotropic: the stretched half-vector rule (alphas from brdf) */
  }
  return shli_tab_build(t, &src, (double)brdf->kd, quad_order, out_err_est);
}

/* ---- MERL ---- */
/* MERL reconstruction, one axis at a time: linear from valid samples, extrapolated at the edges
   (shli_merl_extrap); none valid: returns 0. (docs/derivations.md sec. 13.50) */
typedef struct shli_merlq {
  const shl_merl *m;
  int c;
  double u[3]; /* index coordinates: theta_h, theta_d, phi_d */
  int ih;      /* the theta_h and theta_d indices of the line being read */
  int id;
} shli_merlq;

static int shli_merl_get(const shli_merlq *q, int axis, int j, double *out);

/* the value e cells beyond the valid sample j (value v0), away from its neighbours j + dir,
   j + 2 dir, j + 3 dir: quadratic through the first three where the curvature is seen by the
   data (the second differences at j + dir and j + 2 dir have the same sign and differ by at most
   the first's magnitude), else linear from two, else v0 held */
static double shli_merl_extrap(const shli_merlq *q, int axis, int j, int dir, double v0, double e) {
  double v1 = 0.0;
  double v2 = 0.0;
  double v3 = 0.0;
  double d2;
  double d3;
  if (!shli_merl_get(q, axis, j + dir, &v1)) {
    return v0;
  }
  if (shli_merl_get(q, axis, j + 2 * dir, &v2) && shli_merl_get(q, axis, j + 3 * dir, &v3)) {
    d2 = v0 - 2.0 * v1 + v2;
    d3 = v1 - 2.0 * v2 + v3;
    if (d2 * d3 > 0.0 && fabs(d2 - d3) <= fabs(d2)) {
      return v0 + e * (v0 - v1) + 0.5 * e * (e + 1.0) * d2;
    }
  }
  return v0 + e * (v0 - v1);
}

static int shli_merl_axis(const shli_merlq *q, int axis, double *out) {
  int nj = axis == 0 ? q->m->n_theta_h : (axis == 1 ? q->m->n_theta_d : q->m->n_phi_d);
  double x = q->u[axis];
  double f0 = floor(x);
  double fr;
  double v0 = 0.0;
  double v1 = 0.0;
  int j0;
  int ok0;
  int ok1;
  if (nj == 1) {
    return shli_merl_get(q, axis, 0, out);
  }
  if (axis < 2 && f0 > (double)(nj - 2)) {
    f0 = (double)(nj - 2);
  }
  j0 = (int)f0;
  fr = x - f0;
  ok0 = shli_merl_get(q, axis, j0, &v0);
  ok1 = shli_merl_get(q, axis, j0 + 1, &v1);
  if (ok0 && ok1) {
    *out = (1.0 - fr) * v0 + fr * v1;
    return 1;
  }
  if (ok0) {
    *out = shli_merl_extrap(q, axis, j0, -1, v0, fr);
    return 1;
  }
  if (ok1) {
    *out = shli_merl_extrap(q, axis, j0 + 1, 1, v1, 1.0 - fr);
    return 1;
  }
  return 0;
}

/* axis 2 (phi_d, periodic): the sample (ih, id, j) times cos theta_h cos theta_d of the sample,
   valid when > 0; axes 1 and 0: the reconstruction along the next axis at index j */
static int shli_merl_get(const shli_merlq *q, int axis, int j, double *out) {
  const shl_merl *m = q->m;
  shli_merlq r = *q;
  if (axis == 2) {
    double s;
    double sh = (double)q->ih / (double)m->n_theta_h;
    j %= m->n_phi_d;
    if (j < 0) {
      j += m->n_phi_d;
    }
    s = (double)
            m->data[(((size_t)q->c * (size_t)m->n_theta_h + (size_t)q->ih) * (size_t)m->n_theta_d +
                     (size_t)q->id) *
                        (size_t)m->n_phi_d +
                    (size_t)j];
    *out = s * cos(sh * sh * 0.5 * SHLI_PI) *
           cos((double)q->id / (double)m->n_theta_d * 0.5 * SHLI_PI);
    return s > 0.0;
  }
  if (j < 0 || j >= (axis == 0 ? m->n_theta_h : m->n_theta_d)) {
    return 0;
  }
  if (axis == 0) {
    r.ih = j;
  } else {
    r.id = j;
  }
  return shli_merl_axis(&r, axis + 1, out);
}

static double shli_merl_f(const shl_merl *m, int c, const double wo[3], const double wi[3]) {
  double h[3];
  double hl;
  double th;
  double ph;
  double d[3];
  double tmp[3];
  double td;
  double pd;
  double v = 0.0;
  double qf;
  shli_merlq q;
  int k;
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
  q.m = m;
  q.c = c;
  q.ih = 0;
  q.id = 0;
  q.u[0] = sqrt(th / (0.5 * SHLI_PI)) * (double)m->n_theta_h;
  q.u[1] = td / (0.5 * SHLI_PI) * (double)m->n_theta_d;
  q.u[2] = pd / SHLI_PI * (double)m->n_phi_d;
  for (k = 0; k < 3; ++k) {
    if (!(q.u[k] > 0.0)) {
      q.u[k] = 0.0;
    }
  }
  if (q.u[2] >= (double)m->n_phi_d) {
    q.u[2] -= (double)m->n_phi_d;
  }
  /* f (cos_i + cos_o) / 2 is reconstructed, then divided by the query's factor (floored at 1e-9).
     (docs/derivations.md sec. 13.51) */
  for (;;) {
    if (shli_merl_axis(&q, 0, &v)) {
      break;
    }
    if (q.u[1] < 1.0) {
      return 0.0;
    }
    q.u[1] = floor(q.u[1]) - 1.0;
  }
  qf = 0.5 * (wi[2] + wo[2]); /* = cos(theta_h) cos(theta_d), exactly */
  if (qf < 1e-9) {
    qf = 1e-9;
  }
  return v > 0.0 ? v / qf : 0.0;
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
  src.half = 1;
  src.channel = c;
  src.width = 0.01; /* panel breaks at atan(0.01 3^k): lobes down to about 0.01 rad */
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

/* >>generated ------------------------------------------------------------------------------
   Written by tools/gen_basis.py (edit the generator, not these lines; `--check` in CI): the
   tables and unrolled kernels whose prototypes and table accessors (SHLI_TAB_DECL) the
   sections above declare at their `@generated NAME` lines. */
#ifndef SHLIGHT_GENERATED_H
#define SHLIGHT_GENERATED_H

#undef SHLI_SH_RSQ
#undef SHLI_SH_S12
#undef SHLI_SH_DIAG
/* @generated begin sh_tab */
/* clang-format off */
static const shli_real SHLI_SH_RSQ[128] = {
  0.0, 1.0, 0.7071067811865475, 0.5773502691896258,
  0.5, 0.4472135954999579, 0.4082482904638631, 0.3779644730092272,
  0.35355339059327373, 0.3333333333333333, 0.31622776601683794, 0.30151134457776363,
  0.2886751345948129, 0.2773500981126146, 0.2672612419124244, 0.2581988897471611,
  0.25, 0.24253562503633297, 0.23570226039551587, 0.22941573387056174,
  0.22360679774997896, 0.2182178902359924, 0.21320071635561041, 0.20851441405707477,
  0.20412414523193154, 0.2, 0.19611613513818404, 0.19245008972987526,
  0.1889822365046136, 0.18569533817705186, 0.18257418583505536, 0.1796053020267749,
  0.17677669529663687, 0.17407765595569785, 0.17149858514250882, 0.1690308509457033,
  0.16666666666666666, 0.1643989873053573, 0.16222142113076254, 0.16012815380508713,
  0.15811388300841897, 0.15617376188860607, 0.1543033499620919, 0.15249857033260467,
  0.15075567228888181, 0.14907119849998599, 0.14744195615489714, 0.14586499149789456,
  0.14433756729740646, 0.14285714285714285, 0.1414213562373095, 0.14002800840280097,
  0.1386750490563073, 0.13736056394868904, 0.13608276348795434, 0.13483997249264842,
  0.1336306209562122, 0.13245323570650439, 0.13130643285972254, 0.13018891098082389,
  0.12909944487358055, 0.12803687993289598, 0.1270001270001905, 0.1259881576697424,
  0.125, 0.12403473458920847, 0.12309149097933272, 0.12216944435630522,
  0.12126781251816648, 0.1203858530857692, 0.11952286093343936, 0.11867816581938533,
  0.11785113019775793, 0.11704114719613057, 0.11624763874381928, 0.11547005383792514,
  0.11470786693528087, 0.11396057645963795, 0.11322770341445956, 0.1125087900926024,
  0.11180339887498948, 0.1111111111111111, 0.11043152607484653, 0.10976425998969035,
  0.1091089451179962, 0.10846522890932808, 0.10783277320343841, 0.10721125348377948,
  0.10660035817780521, 0.105999788000636, 0.10540925533894598, 0.10482848367219183,
  0.10425720702853739, 0.10369516947304253, 0.10314212462587934, 0.10259783520851541,
  0.10206207261596577, 0.10153461651336192, 0.10101525445522107, 0.10050378152592121,
  0.1, 0.09950371902099892, 0.09901475429766744, 0.09853292781642932,
  0.09805806756909202, 0.09759000729485333, 0.09712858623572641, 0.09667364890456635,
  0.09622504486493763, 0.09578262852211514, 0.09534625892455924, 0.0949157995752499,
  0.0944911182523068, 0.09407208683835973, 0.0936585811581694, 0.09325048082403138,
  0.09284766908852593, 0.09245003270420485, 0.09205746178983235, 0.09166984970282113,
  0.09128709291752768, 0.09090909090909091, 0.09053574604251853, 0.09016696346674323,
  0.08980265101338746, 0.08944271909999159, 0.0890870806374748, 0.08873565094161139
};
/* clang-format on */
/* clang-format off */
static const shli_real SHLI_SH_S12[128] = {
  0.0, 0.0, 1.7320508075688772, 1.7320508075688772,
  3.872983346207417, 1.2909944487358056, 5.916079783099616, 1.1832159566199232,
  7.937253933193772, 1.1338934190276817, 9.9498743710662, 1.1055415967851334,
  11.958260743101398, 1.087114613009218, 13.96424004376894, 1.0741723110591492,
  15.968719422671311, 1.0645812948447542, 17.97220075561143, 1.0571882797418488,
  19.974984355438178, 1.0513149660756937, 21.97726097583591, 1.0465362369445672,
  23.979157616563597, 1.0425720702853738, 25.98076211353316, 1.0392304845413265,
  27.982137159266443, 1.0363754503432017, 29.9833287011299, 1.0339078862458586,
  31.984371183438952, 1.031753909143192, 33.98529093593286, 1.0298573010888745,
  35.98610843089316, 1.0281745265969475, 37.986839826445156, 1.0266713466606798,
  39.98749804626441, 1.0253204627247285, 41.98809355043403, 1.024099842693513,
  43.98863489584554, 1.0229915092057102, 45.98912915026767, 1.021980647783726,
  47.989582202807306, 1.021054940485262, 49.98999899979995, 1.020204061220407,
  51.99038372622383, 1.019419288749487, 53.99073994677235, 1.0186932065428747,
  55.991070716677676, 1.0180194675759577, 57.99137866959192, 1.0173926082384548,
  59.99166608788257, 1.01680789979462, 61.99193495931547, 1.0162612288412374,
  63.99218702310463, 1.0157490003667402, 65.99242380758567, 1.015268058578241,
  67.9926466612383, 1.014815621809527, 69.99285677838846, 1.0143892286722966,
  71.99305522062528, 1.0139866932482433, 73.9932429347437, 1.0136060675992289,
  75.99342076785332, 1.0132456102380443, 77.99358948016176, 1.0129037594826202,
  79.9937497558403, 1.0125791108334214, 81.99390221229869, 1.0122703976826999,
  83.99404740813482, 1.0119764747968052, 85.99418584997477, 1.0116963041173501,
  87.99431799837987, 1.0114289425101135, 89.99444427296609, 1.0111735311569225,
  91.9945650568554, 1.0109292863390702, 93.99468070055879, 1.010695491403858,
  95.99479152537391, 1.010471489740778, 97.99489782636645, 1.0102566786223346,
  99.99499987499375, 1.0100505037878156, 101.99509792141973, 1.009852454667522,
  103.99519219656263, 1.0096620601608022, 105.99528291391084, 1.009478884894389,
  107.99537027113709, 1.0093025258984774, 109.99545445153632, 1.009132609647122,
  111.99553562530964, 1.008968789417204, 113.99561395071304, 1.008810742926664,
  115.99568957508723, 1.0086581702181499, 117.99576263578281, 1.0085107917588274,
  119.99583326099285, 1.0083683467310325, 121.99590157050359, 1.008230591491765,
  123.99596767637244, 1.0080972981818899, 125.99603168354153, 1.0079682534683323
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
SHLI_TAB_FN(sh_rsq) {
  return &SHLI_SH_RSQ;
}
SHLI_TAB_FN(sh_s12) {
  return &SHLI_SH_S12;
}
SHLI_TAB_FN(sh_diag) {
  return &SHLI_SH_DIAG;
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

SHLIGHT_INLINE void shli_sh_core_col(int m, shli_real t, shli_real k, float *out_xs) {
  shli_real dd = 0.0;
  shli_real xa = 0.0;
  shli_real gp = 1.0;
  shli_real al;
  shli_real g;
  int l;
  for (l = 0; l < 16; ++l) {
    out_xs[l] = 0.0f;
    if (l > m) {
      al = SHLIGHT_SQRTR(SHLIGHT_ITOR((2 * l + 1) * (2 * l - 1)) / SHLIGHT_ITOR((l - m) * (l + m)));
      g = SHLIGHT_SQRTR(SHLIGHT_ITOR((2 * l + 1) * (l + m)) / SHLIGHT_ITOR((2 * l - 1) * (l - m)));
      if (l == m + 1) {
        dd = -al * k * t;
        xa = g * k + dd;
      } else {
        dd = SHLIGHT_SQRTR(SHLIGHT_ITOR((2 * l + 1) * (l + m - 1) * (l - m - 1)) /
                           SHLIGHT_ITOR((2 * l - 3) * (l - m) * (l + m))) /
                 gp * dd -
             al * (t * xa);
        xa = g * xa + dd;
      }
      gp = g;
      out_xs[l] = SHLIGHT_FLOAT(xa);
    }
  }
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
#if SHLIGHT_BY_BANDS
#if SHLIGHT_MAX_BANDS > 1
  if (n > 1) {
    float xs[16];
    int l;
    shli_sh_core_col(0, t, 0.28209479177387814, xs);
    for (l = 1; l < SHLIGHT_MAX_BANDS; ++l) {
      if (n > l) {
        out_y[l * l + l] = l % 2 == 1 ? sg * xs[l] : xs[l];
      }
    }
  }
#endif
#else
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
#if SHLIGHT_BY_BANDS
#if SHLIGHT_MAX_BANDS > 2
  if (n > 2) {
    float xs[16];
    int l;
    shli_sh_core_col(1, t, -0.48860251190291987, xs);
    for (l = 2; l < SHLIGHT_MAX_BANDS; ++l) {
      if (n > l) {
        out_y[l * l + l + 1] = xs[l] * ((l - 1) % 2 == 1 ? gc : fc);
        out_y[l * l + l - 1] = xs[l] * ((l - 1) % 2 == 1 ? gs : fs);
      }
    }
  }
#endif
#else
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
#if SHLIGHT_BY_BANDS
#if SHLIGHT_MAX_BANDS > 3
  if (n > 3) {
    float xs[16];
    int l;
    shli_sh_core_col(2, t, 0.5462742152960395, xs);
    for (l = 3; l < SHLIGHT_MAX_BANDS; ++l) {
      if (n > l) {
        out_y[l * l + l + 2] = xs[l] * ((l - 2) % 2 == 1 ? gc : fc);
        out_y[l * l + l - 2] = xs[l] * ((l - 2) % 2 == 1 ? gs : fs);
      }
    }
  }
#endif
#else
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
#if SHLIGHT_BY_BANDS
#if SHLIGHT_MAX_BANDS > 4
  if (n > 4) {
    float xs[16];
    int l;
    shli_sh_core_col(3, t, -0.5900435899266435, xs);
    for (l = 4; l < SHLIGHT_MAX_BANDS; ++l) {
      if (n > l) {
        out_y[l * l + l + 3] = xs[l] * ((l - 3) % 2 == 1 ? gc : fc);
        out_y[l * l + l - 3] = xs[l] * ((l - 3) % 2 == 1 ? gs : fs);
      }
    }
  }
#endif
#else
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
#if SHLIGHT_BY_BANDS
#if SHLIGHT_MAX_BANDS > 5
  if (n > 5) {
    float xs[16];
    int l;
    shli_sh_core_col(4, t, 0.625835735449176, xs);
    for (l = 5; l < SHLIGHT_MAX_BANDS; ++l) {
      if (n > l) {
        out_y[l * l + l + 4] = xs[l] * ((l - 4) % 2 == 1 ? gc : fc);
        out_y[l * l + l - 4] = xs[l] * ((l - 4) % 2 == 1 ? gs : fs);
      }
    }
  }
#endif
#else
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
#if SHLIGHT_BY_BANDS
#if SHLIGHT_MAX_BANDS > 6
  if (n > 6) {
    float xs[16];
    int l;
    shli_sh_core_col(5, t, -0.65638205684017, xs);
    for (l = 6; l < SHLIGHT_MAX_BANDS; ++l) {
      if (n > l) {
        out_y[l * l + l + 5] = xs[l] * ((l - 5) % 2 == 1 ? gc : fc);
        out_y[l * l + l - 5] = xs[l] * ((l - 5) % 2 == 1 ? gs : fs);
      }
    }
  }
#endif
#else
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

#if !defined(SHLIGHT_NO_SIMD) && defined(__AVX512F__)
#undef SHLI_SH_LANEK
#undef SHLI_SH_RSQF
#undef SHLI_SH_RSQR
#undef SHLI_SH_LANER
#undef SHLI_SH_LANES_S
/* @generated begin lanes */
#if SHLIGHT_SIMD_EVAL
/* clang-format off */
static const float SHLI_SH_LANEK[190] = {
    -63, -62, -61, -6e+01f, -59, -58, -57, -56, -55, -54, -53, -52, -51, -5e+01f, -49, -48, -47,
    -46, -45, -44, -43, -42, -41, -4e+01f, -39, -38, -37, -36, -35, -34, -33, -32, -31, -3e+01f,
    -29, -28, -27, -26, -25, -24, -23, -22, -21, -2e+01f, -19, -18, -17, -16, -15, -14, -13, -12,
    -11, -1e+01f, -9, -8, -7, -6, -5, -4, -3, -2, -1, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 1e+01f, 11,
    12, 13, 14, 15, 16, 17, 18, 19, 2e+01f, 21, 22, 23, 24, 25, 26, 27, 28, 29, 3e+01f, 31, 32,
    33, 34, 35, 36, 37, 38, 39, 4e+01f, 41, 42, 43, 44, 45, 46, 47, 48, 49, 5e+01f, 51, 52, 53,
    54, 55, 56, 57, 58, 59, 6e+01f, 61, 62, 63, 64, 65, 66, 67, 68, 69, 7e+01f, 71, 72, 73, 74,
    75, 76, 77, 78, 79, 8e+01f, 81, 82, 83, 84, 85, 86, 87, 88, 89, 9e+01f, 91, 92, 93, 94, 95,
    96, 97, 98, 99, 1e+02f, 101, 102, 103, 104, 105, 106, 107, 108, 109, 1.1e+02f, 111, 112, 113,
    114, 115, 116, 117, 118, 119, 1.2e+02f, 121, 122, 123, 124, 125, 126
};
/* clang-format on */
/* clang-format off */
static const float SHLI_SH_RSQF[128] = {
    0, 1, 0.70710677f, 0.57735026f, 0.5f, 0.4472136f, 0.40824828f, 0.37796447f, 0.35355338f,
    0.33333334f, 0.31622776f, 0.30151135f, 0.28867513f, 0.2773501f, 0.26726124f, 0.2581989f,
    0.25f, 0.24253562f, 0.23570226f, 0.22941573f, 0.2236068f, 0.2182179f, 0.21320072f, 0.2085144f,
    0.20412414f, 0.2f, 0.19611613f, 0.19245009f, 0.18898223f, 0.18569534f, 0.18257418f,
    0.1796053f, 0.17677669f, 0.17407766f, 0.17149858f, 0.16903085f, 0.16666667f, 0.16439898f,
    0.16222142f, 0.16012816f, 0.15811388f, 0.15617377f, 0.15430336f, 0.15249857f, 0.15075567f,
    0.1490712f, 0.14744195f, 0.145865f, 0.14433756f, 0.14285715f, 0.14142136f, 0.14002801f,
    0.13867505f, 0.13736056f, 0.13608277f, 0.13483997f, 0.13363062f, 0.13245323f, 0.13130644f,
    0.13018891f, 0.12909944f, 0.12803689f, 0.12700012f, 0.12598816f, 0.125f, 0.12403473f,
    0.12309149f, 0.12216944f, 0.12126781f, 0.120385855f, 0.11952286f, 0.11867817f, 0.11785113f,
    0.11704115f, 0.11624764f, 0.11547005f, 0.114707865f, 0.11396058f, 0.1132277f, 0.11250879f,
    0.1118034f, 0.11111111f, 0.11043153f, 0.10976426f, 0.10910895f, 0.10846523f, 0.107832775f,
    0.107211255f, 0.10660036f, 0.10599979f, 0.10540926f, 0.104828484f, 0.1042572f, 0.10369517f,
    0.10314213f, 0.10259783f, 0.10206208f, 0.10153462f, 0.101015255f, 0.10050378f, 0.1f,
    0.09950372f, 0.09901475f, 0.09853293f, 0.09805807f, 0.09759001f, 0.097128585f, 0.09667365f,
    0.096225046f, 0.09578263f, 0.09534626f, 0.0949158f, 0.09449112f, 0.09407209f, 0.09365858f,
    0.09325048f, 0.09284767f, 0.09245003f, 0.09205746f, 0.09166985f, 0.09128709f, 0.09090909f,
    0.090535745f, 0.09016696f, 0.08980265f, 0.08944272f, 0.089087084f, 0.08873565f
};
/* clang-format on */
/* clang-format off */
static const float SHLI_SH_RSQR[79] = {
    0.12598816f, 0.12700012f, 0.12803689f, 0.12909944f, 0.13018891f, 0.13130644f, 0.13245323f,
    0.13363062f, 0.13483997f, 0.13608277f, 0.13736056f, 0.13867505f, 0.14002801f, 0.14142136f,
    0.14285715f, 0.14433756f, 0.145865f, 0.14744195f, 0.1490712f, 0.15075567f, 0.15249857f,
    0.15430336f, 0.15617377f, 0.15811388f, 0.16012816f, 0.16222142f, 0.16439898f, 0.16666667f,
    0.16903085f, 0.17149858f, 0.17407766f, 0.17677669f, 0.1796053f, 0.18257418f, 0.18569534f,
    0.18898223f, 0.19245009f, 0.19611613f, 0.2f, 0.20412414f, 0.2085144f, 0.21320072f, 0.2182179f,
    0.2236068f, 0.22941573f, 0.23570226f, 0.24253562f, 0.25f, 0.2581989f, 0.26726124f, 0.2773501f,
    0.28867513f, 0.30151135f, 0.31622776f, 0.33333334f, 0.35355338f, 0.37796447f, 0.40824828f,
    0.4472136f, 0.5f, 0.57735026f, 0.70710677f, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0
};
/* clang-format on */
/* clang-format off */
static const int SHLI_SH_LANER[31] = {
    15, 14, 13, 12, 11, 10, 9, 8, 7, 6, 5, 4, 3, 2, 1, 0, -1, -2, -3, -4, -5, -6, -7, -8, -9, -10,
    -11, -12, -13, -14, -15
};
/* clang-format on */
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
#if SHLIGHT_SIMD_EVAL
SHLI_TAB_FN(sh_lanek) {
  return &SHLI_SH_LANEK;
}
SHLI_TAB_FN(sh_rsqf) {
  return &SHLI_SH_RSQF;
}
SHLI_TAB_FN(sh_rsqr) {
  return &SHLI_SH_RSQR;
}
SHLI_TAB_FN(sh_laner) {
  return &SHLI_SH_LANER;
}
SHLI_TAB_FN(sh_lanes_s) {
  return &SHLI_SH_LANES_S;
}
#endif

#undef SHLI_SH_PLANES
#undef SHLI_SH_PTAP
#undef SHLI_SH_PODD
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
#if SHLIGHT_SIMD_EVAL
SHLI_TAB_FN(sh_planes) {
  return &SHLI_SH_PLANES;
}
SHLI_TAB_FN(sh_ptap) {
  return &SHLI_SH_PTAP;
}
SHLI_TAB_FN(sh_podd) {
  return &SHLI_SH_PODD;
}
#endif

#undef SHLI_GRADV_CH0
#undef SHLI_GRADV_LF
#undef SHLI_GRADV_LASTM
#undef SHLI_GRADV_YM
#undef SHLI_GRADV_IY
#undef SHLI_GRADV_TAP
#undef SHLI_GRADV_COEF
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
    -8.717798f, 4.358899f, 0.747545f, -8.188945f, 5.98036f, 1.294786f, -7.6600566f, 7.0918345f,
    1.8311038f, -7.131125f, 7.9112725f, 2.3639448f, -9.246621f, 0, 0, -8.717798f, 0, 0,
    -8.188945f, -0.747545f, 0, -7.6600566f, -1.294786f, 0, -7.131125f, -1.8311038f, 0,
    -6.6021385f, -6.6021385f, 8.523324f, 2.8952293f, -6.0730844f, 8.97054f, 3.4256816f,
    -5.543942f, 9.27679f, 3.9556363f, -7.0918345f, 9.455779f, 0, 6.3431296f, 9.514694f,
    -7.0918345f, 3.9556363f, -2.3639448f, 0, -6.0730844f, -2.8952293f, 0, -5.543942f, -3.4256816f,
    0, 0, -3.9556363f, 0, 6.3431296f, 0, 0, 3.9556363f, 0, 9.455779f, -5.543942f, 3.4256816f,
    9.27679f, -6.0730844f, 2.8952293f, 8.97054f, -6.6021385f, 2.3639448f, 8.523324f, -7.131125f,
    1.8311038f, 7.9112725f, -7.6600566f, 1.294786f, 7.0918345f, 0, 3.4256816f, 5.543942f, 0,
    2.8952293f, 6.0730844f, 0, 2.3639448f, 6.6021385f, 0, 1.8311038f, 7.131125f, 0, 1.294786f,
    7.6600566f, 0, -8.188945f, 0.747545f, 5.98036f, -8.717798f, 0, 4.358899f, -9.246621f, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0.747545f, 8.188945f, 0, 0, 8.717798f, 0, 0, 9.246621f, 0, 0, 0, 0, 0, 0, 0,
    0, 0, -10.246951f, 0, 0, -9.721111f, 4.582576f, 0.74339193f, -9.1952505f, 6.30789f,
    1.2875926f, -8.669365f, 7.5078907f, 1.820931f, -8.143451f, 8.41052f, 2.3508117f, -10.246951f,
    0, 0, -9.721111f, 0, 0, -9.1952505f, -0.74339193f, 0, -8.669365f, -1.2875926f, 0, -8.143451f,
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
    10.723805f, 3.91578f, -7.059273f, 11.075499f, 4.4400773f, -6.535617f, 11.32002f, 4.964157f,
    -8.502101f, -2.3401263f, 0, -8.106435f, -2.8660576f, 0, -7.5828753f, -3.391165f, 0,
    -7.059273f, -3.91578f, 0, -6.535617f, -4.4400773f, 0, 0, -4.964157f, 11.464231f, 0,
    7.7613206f, 11.511899f, -8.502101f, 4.964157f, 11.464231f, -6.535617f, 4.4400773f, 11.32002f,
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
    -1.8057878f, 0, -9.640269f, -9.640269f, 10.161736f, 2.8552012f, -9.118781f, 10.834726f,
    3.3783197f, -8.59727f, 11.373118f, 3.9009476f, -8.075728f, 11.795357f, 4.423259f, -7.5541525f,
    12.113593f, 4.9453535f, -7.032533f, -2.331262f, 0, -9.118781f, -2.8552012f, 0, -8.59727f,
    -3.3783197f, 0, -8.075728f, -3.9009476f, 0, -7.5541525f, -4.423259f, 0, -7.032533f,
    -4.9453535f, 12.335879f, 5.467294f, -9.207747f, 12.467349f, 0, 8.469895f, 12.510865f,
    -9.207747f, 5.467294f, 12.467349f, -7.032533f, 4.9453535f, 12.335879f, -7.5541525f, 4.423259f,
    12.113593f, 0, 0, -5.467294f, 0, 8.469895f, 0, 0, 5.467294f, 0, 0, 4.9453535f, 7.032533f, 0,
    4.423259f, 7.5541525f, 0, -8.075728f, 3.9009476f, 11.795357f, -8.59727f, 3.3783197f,
    11.373118f, -9.118781f, 2.8552012f, 10.834726f, -9.640269f, 2.331262f, 10.161736f,
    -10.161736f, 1.8057878f, 9.325048f, -10.683185f, 3.9009476f, 8.075728f, 0, 3.3783197f,
    8.59727f, 0, 2.8552012f, 9.118781f, 0, 2.331262f, 9.640269f, 0, 1.8057878f, 10.161736f, 0,
    1.2768848f, 1.2768848f, 8.275159f, -11.204618f, 0.7372098f, 6.915641f, -11.726039f, 0, 5,
    -12.247449f, 0, 0, 0, 0, 0, 0, 0, 10.683185f, 0, 0.7372098f, 11.204618f, 0, 0, 11.726039f, 0,
    0, 12.247449f, 0, 0, 0, 0, 0, 0, 0, -13.247642f, 0, 0, -12.727922f, 5.196152f, 0.73484695f,
    -12.208194f, 7.2f, 1.2727922f, -11.688456f, 8.632497f, 1.8f, -11.168706f, 9.748846f, 2.32379f,
    -13.247642f, 0, 0, -12.727922f, 0, 0, -12.208194f, -0.73484695f, 0, -11.688456f, -1.2727922f,
    0, -11.168706f, -1.8f, 0, -10.648944f, -10.648944f, 10.648944f, 2.8460498f, -10.129166f,
    11.384199f, 3.3674917f, -9.60937f, 11.984991f, 3.8884444f, -9.089555f, 12.470766f, 4.4090815f,
    -8.569715f, 12.854571f, 4.929503f, -8.049845f, -2.32379f, 0, -10.129166f, -2.8460498f, 0,
    -9.60937f, -3.3674917f, 0, -9.089555f, -3.8884444f, 0, -8.569715f, -4.4090815f, 0, -8.049845f,
    -4.929503f, 13.145341f, 5.4497705f, -7.52994f, 13.349157f, 5.9699244f, -9.913627f, 13.469967f,
    0, 9.178235f, 13.509996f, -9.913627f, 5.9699244f, 13.469967f, -7.52994f, 5.4497705f,
    13.349157f, 0, -7.52994f, -5.4497705f, 0, 0, -5.9699244f, 0, 9.178235f, 0, 0, 5.9699244f, 0,
    0, 5.4497705f, 7.52994f, 0, -8.049845f, 4.929503f, 13.145341f, -8.569715f, 4.4090815f,
    12.854571f, -9.089555f, 3.8884444f, 12.470766f, -9.60937f, 3.3674917f, 11.984991f,
    -10.129166f, 2.8460498f, 11.384199f, -10.648944f, 4.929503f, 8.049845f, 0, 4.4090815f,
    8.569715f, 0, 3.8884444f, 9.089555f, 0, 3.3674917f, 9.60937f, 0, 2.8460498f, 10.129166f, 0,
    2.32379f, 2.32379f, 10.648944f, -11.168706f, 1.8f, 9.748846f, -11.688456f, 1.2727922f,
    8.632497f, -12.208194f, 0.73484695f, 7.2f, -12.727922f, 0, 5.196152f, -13.247642f, 0,
    10.648944f, 0, 1.8f, 11.168706f, 0, 1.2727922f, 11.688456f, 0, 0.73484695f, 12.208194f, 0, 0,
    12.727922f, 0, 0, 13.247642f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -14.247807f, 0, 0, -13.72953f, 5.3851647f, 0.7328281f,
    -13.2112465f, 7.4734097f, 1.2692956f, -12.692955f, 8.975275f, 1.7950549f, -12.174655f,
    10.154365f, 2.317406f, -14.247807f, 0, 0, -13.72953f, 0, 0, -13.2112465f, -0.7328281f, 0,
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
    11.113889f, -12.174655f, 1.7950549f, 10.154365f, -12.692955f, 1.2692956f, 8.975275f,
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
SHLI_TAB_FN(gradv_ch0) {
  return &SHLI_GRADV_CH0;
}
SHLI_TAB_FN(gradv_lf) {
  return &SHLI_GRADV_LF;
}
SHLI_TAB_FN(gradv_lastm) {
  return &SHLI_GRADV_LASTM;
}
SHLI_TAB_FN(gradv_ym) {
  return &SHLI_GRADV_YM;
}
SHLI_TAB_FN(gradv_iy) {
  return &SHLI_GRADV_IY;
}
SHLI_TAB_FN(gradv_tap) {
  return &SHLI_GRADV_TAP;
}
SHLI_TAB_FN(gradv_coef) {
  return &SHLI_GRADV_COEF;
}
#endif

/* @generated begin gradient */
/* output i of shli_sh_grad_lines from its terms in band l-1 (a: x, b: y, c: z) */
#define SHLI_G3(i, a, b, c) \
  q = lr * y[i]; \
  SHLIGHT_SET3(out_grad[i], (a - q * nx) * ib, (b - q * ny) * ib, (c - q * nz) * ib)
#define SHLI_G2(i, a, b) \
  q = lr * y[i]; \
  SHLIGHT_SET3(out_grad[i], (a - q * nx) * ib, (b - q * ny) * ib, -q * nz * ib)
SHLIGHT_CPU_INLINE void shli_sh_grad_lines(int n, const float *y, float nx, float ny, float nz,
                                           float ir, float ib, float (*out_grad)[3]) {
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
    SHLIGHT_SET3(out_grad[1], -q * nx * ib, (-1.7320508f * r[0] - q * ny) * ib, -q * nz * ib);
    q = lr * y[2];
    SHLIGHT_SET3(out_grad[2], -q * nx * ib, -q * ny * ib, (1.7320508f * r[0] - q * nz) * ib);
    q = lr * y[3];
    SHLIGHT_SET3(out_grad[3], (-1.7320508f * r[0] - q * nx) * ib, -q * ny * ib, -q * nz * ib);
  }
#endif
#if SHLIGHT_MAX_BANDS > 2
  if (n > 2) {
    lr = 2.0f * ir;
    r[0] = y[1] * ir;
    r[1] = y[2] * ir;
    r[2] = y[3] * ir;
    SHLI_G2(4, -2.236068f * r[0], -2.236068f * r[2]);
    q = lr * y[5];
    SHLIGHT_SET3(out_grad[5], -q * nx * ib, (-2.236068f * r[1] - q * ny) * ib,
                 (2.236068f * r[0] - q * nz) * ib);
    SHLI_G3(6, 1.2909944f * r[2], 1.2909944f * r[0], 2.5819888f * r[1]);
    q = lr * y[7];
    SHLIGHT_SET3(out_grad[7], (-2.236068f * r[1] - q * nx) * ib, -q * ny * ib,
                 (2.236068f * r[2] - q * nz) * ib);
    SHLI_G2(8, -2.236068f * r[2], 2.236068f * r[0]);
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
    SHLI_G2(9, -3.2403703f * r[0], -3.2403703f * r[4]);
    SHLI_G3(10, -2.6457512f * r[1], -2.6457512f * r[3], 2.6457512f * r[0]);
    SHLI_G3(11, 0.83666f * r[0], -2.8982754f * r[2] + -0.83666f * r[4], 3.34664f * r[1]);
    SHLI_G3(12, 2.04939f * r[3], 2.04939f * r[1], 3.5496478f * r[2]);
    SHLI_G3(13, -2.8982754f * r[2] + 0.83666f * r[4], 0.83666f * r[0], 3.34664f * r[3]);
    SHLI_G3(14, -2.6457512f * r[3], 2.6457512f * r[1], 2.6457512f * r[4]);
    SHLI_G2(15, -3.2403703f * r[4], 3.2403703f * r[0]);
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
    SHLI_G2(16, -4.2426405f * r[0], -4.2426405f * r[6]);
    SHLI_G3(17, -3.6742346f * r[1], -3.6742346f * r[5], 3.0f * r[0]);
    SHLI_G3(18, -3.105295f * r[2] + 0.80178374f * r[0], -3.105295f * r[4] + -0.80178374f * r[6],
            3.927922f * r[1]);
    SHLI_G3(19, 1.3887302f * r[1], -3.5856857f * r[3] + -1.3887302f * r[5], 4.3915505f * r[2]);
    SHLI_G3(20, 2.7774603f * r[4], 2.7774603f * r[2], 4.5355735f * r[3]);
    SHLI_G3(21, -3.5856857f * r[3] + 1.3887302f * r[5], 1.3887302f * r[1], 4.3915505f * r[4]);
    SHLI_G3(22, -3.105295f * r[4] + 0.80178374f * r[6], 3.105295f * r[2] + 0.80178374f * r[0],
            3.927922f * r[5]);
    SHLI_G3(23, -3.6742346f * r[5], 3.6742346f * r[1], 3.0f * r[6]);
    SHLI_G2(24, -4.2426405f * r[6], 4.2426405f * r[0]);
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
    SHLI_G2(25, -5.2440443f * r[0], -5.2440443f * r[8]);
    SHLI_G3(26, -4.690416f * r[1], -4.690416f * r[7], 3.3166249f * r[0]);
    SHLI_G3(27, -4.136558f * r[2] + 0.78173596f * r[0], -4.136558f * r[6] + -0.78173596f * r[8],
            4.4221663f * r[1]);
    SHLI_G3(28, -3.5823643f * r[3] + 1.3540064f * r[1], -3.5823643f * r[5] + -1.3540064f * r[7],
            5.066228f * r[2]);
    SHLI_G3(29, 1.9148542f * r[2], -4.281744f * r[4] + -1.9148542f * r[6], 5.4160256f * r[3]);
    SHLI_G3(30, 3.4960294f * r[5], 3.4960294f * r[3], 5.527708f * r[4]);
    SHLI_G3(31, -4.281744f * r[4] + 1.9148542f * r[6], 1.9148542f * r[2], 5.4160256f * r[5]);
    SHLI_G3(32, -3.5823643f * r[5] + 1.3540064f * r[7], 3.5823643f * r[3] + 1.3540064f * r[1],
            5.066228f * r[6]);
    SHLI_G3(33, -4.136558f * r[6] + 0.78173596f * r[8], 4.136558f * r[2] + 0.78173596f * r[0],
            4.4221663f * r[7]);
    SHLI_G3(34, -4.690416f * r[7], 4.690416f * r[1], 3.3166249f * r[8]);
    SHLI_G2(35, -5.2440443f * r[8], 5.2440443f * r[0]);
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
    SHLI_G2(36, -6.244998f * r[0], -6.244998f * r[10]);
    SHLI_G3(37, -5.700877f * r[1], -5.700877f * r[9], 3.6055512f * r[0]);
    SHLI_G3(38, -5.156637f * r[2] + 0.76870614f * r[0], -5.156637f * r[8] + -0.76870614f * r[10],
            4.8617244f * r[1]);
    SHLI_G3(39, -4.6122365f * r[3] + 1.3314381f * r[1], -4.6122365f * r[7] + -1.3314381f * r[9],
            5.6488132f * r[2]);
    SHLI_G3(40, -4.0676103f * r[4] + 1.8829378f * r[2], -4.0676103f * r[6] + -1.8829378f * r[8],
            6.149649f * r[3]);
    SHLI_G3(41, 2.4308622f * r[3], -4.981785f * r[5] + -2.4308622f * r[7], 6.4314566f * r[4]);
    SHLI_G3(42, 4.2103767f * r[6], 4.2103767f * r[4], 6.522688f * r[5]);
    SHLI_G3(43, -4.981785f * r[5] + 2.4308622f * r[7], 2.4308622f * r[3], 6.4314566f * r[6]);
    SHLI_G3(44, -4.0676103f * r[6] + 1.8829378f * r[8], 4.0676103f * r[4] + 1.8829378f * r[2],
            6.149649f * r[7]);
    SHLI_G3(45, -4.6122365f * r[7] + 1.3314381f * r[9], 4.6122365f * r[3] + 1.3314381f * r[1],
            5.6488132f * r[8]);
    SHLI_G3(46, -5.156637f * r[8] + 0.76870614f * r[10], 5.156637f * r[2] + 0.76870614f * r[0],
            4.8617244f * r[9]);
    SHLI_G3(47, -5.700877f * r[9], 5.700877f * r[1], 3.6055512f * r[10]);
    SHLI_G2(48, -6.244998f * r[10], 6.244998f * r[0]);
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
    SHLI_G2(49, -7.2456884f * r[0], -7.2456884f * r[12]);
    SHLI_G3(50, -6.708204f * r[1], -6.708204f * r[11], 3.8729835f * r[0]);
    SHLI_G3(51, -6.17065f * r[2] + 0.7595545f * r[0], -6.17065f * r[10] + -0.7595545f * r[12],
            5.262348f * r[1]);
    SHLI_G3(52, -5.633007f * r[3] + 1.315587f * r[1], -5.633007f * r[9] + -1.315587f * r[11],
            6.17065f * r[2]);
    SHLI_G3(53, -5.095247f * r[4] + 1.8605211f * r[2], -5.095247f * r[8] + -1.8605211f * r[10],
            6.793662f * r[3]);
    SHLI_G3(54, -4.5573273f * r[5] + 2.4019222f * r[3], -4.5573273f * r[7] + -2.4019222f * r[9],
            7.205767f * r[4]);
    SHLI_G3(55, 2.941742f * r[4], -5.6839857f * r[6] + -2.941742f * r[8], 7.4420843f * r[5]);
    SHLI_G3(56, 4.922476f * r[7], 4.922476f * r[5], 7.519206f * r[6]);
    SHLI_G3(57, -5.6839857f * r[6] + 2.941742f * r[8], 2.941742f * r[4], 7.4420843f * r[7]);
    SHLI_G3(58, -4.5573273f * r[7] + 2.4019222f * r[9], 4.5573273f * r[5] + 2.4019222f * r[3],
            7.205767f * r[8]);
    SHLI_G3(59, -5.095247f * r[8] + 1.8605211f * r[10], 5.095247f * r[4] + 1.8605211f * r[2],
            6.793662f * r[9]);
    SHLI_G3(60, -5.633007f * r[9] + 1.315587f * r[11], 5.633007f * r[3] + 1.315587f * r[1],
            6.17065f * r[10]);
    SHLI_G3(61, -6.17065f * r[10] + 0.7595545f * r[12], 6.17065f * r[2] + 0.7595545f * r[0],
            5.262348f * r[11]);
    SHLI_G3(62, -6.708204f * r[11], 6.708204f * r[1], 3.8729835f * r[12]);
    SHLI_G2(63, -7.2456884f * r[12], 7.2456884f * r[0]);
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
    SHLI_G2(64, -8.246211f * r[0], -8.246211f * r[14]);
    SHLI_G3(65, -7.7136245f * r[1], -7.7136245f * r[13], 4.1231055f * r[0]);
    SHLI_G3(66, -7.1809936f * r[2] + 0.7527726f * r[0], -7.1809936f * r[12] + -0.7527726f * r[14],
            5.6332345f * r[1]);
    SHLI_G3(67, -6.6483083f * r[3] + 1.3038405f * r[1], -6.6483083f * r[11] + -1.3038405f * r[13],
            6.6483083f * r[2]);
    SHLI_G3(68, -6.115554f * r[4] + 1.8439089f * r[2], -6.115554f * r[10] + -1.8439089f * r[12],
            7.3756356f * r[3]);
    SHLI_G3(69, -5.582711f * r[5] + 2.3804762f * r[3], -5.582711f * r[9] + -2.3804762f * r[11],
            7.8951464f * r[4]);
    SHLI_G3(70, -5.049752f * r[6] + 2.9154758f * r[4], -5.049752f * r[8] + -2.9154758f * r[10],
            8.246211f * r[5]);
    SHLI_G3(71, 3.4496377f * r[5], -6.387488f * r[7] + -3.4496377f * r[9], 8.449852f * r[6]);
    SHLI_G3(72, 5.6332345f * r[8], 5.6332345f * r[6], 8.51665f * r[7]);
    SHLI_G3(73, -6.387488f * r[7] + 3.4496377f * r[9], 3.4496377f * r[5], 8.449852f * r[8]);
    SHLI_G3(74, -5.049752f * r[8] + 2.9154758f * r[10], 5.049752f * r[6] + 2.9154758f * r[4],
            8.246211f * r[9]);
    SHLI_G3(75, -5.582711f * r[9] + 2.3804762f * r[11], 5.582711f * r[5] + 2.3804762f * r[3],
            7.8951464f * r[10]);
    SHLI_G3(76, -6.115554f * r[10] + 1.8439089f * r[12], 6.115554f * r[4] + 1.8439089f * r[2],
            7.3756356f * r[11]);
    SHLI_G3(77, -6.6483083f * r[11] + 1.3038405f * r[13], 6.6483083f * r[3] + 1.3038405f * r[1],
            6.6483083f * r[12]);
    SHLI_G3(78, -7.1809936f * r[12] + 0.7527726f * r[14], 7.1809936f * r[2] + 0.7527726f * r[0],
            5.6332345f * r[13]);
    SHLI_G3(79, -7.7136245f * r[13], 7.7136245f * r[1], 4.1231055f * r[14]);
    SHLI_G2(80, -8.246211f * r[14], 8.246211f * r[0]);
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
    SHLI_G2(81, -9.246621f * r[0], -9.246621f * r[16]);
    SHLI_G3(82, -8.717798f * r[1], -8.717798f * r[15], 4.358899f * r[0]);
    SHLI_G3(83, -8.188945f * r[2] + 0.747545f * r[0], -8.188945f * r[14] + -0.747545f * r[16],
            5.98036f * r[1]);
    SHLI_G3(84, -7.6600566f * r[3] + 1.294786f * r[1], -7.6600566f * r[13] + -1.294786f * r[15],
            7.0918345f * r[2]);
    SHLI_G3(85, -7.131125f * r[4] + 1.8311038f * r[2], -7.131125f * r[12] + -1.8311038f * r[14],
            7.9112725f * r[3]);
    SHLI_G3(86, -6.6021385f * r[5] + 2.3639448f * r[3], -6.6021385f * r[11] + -2.3639448f * r[13],
            8.523324f * r[4]);
    SHLI_G3(87, -6.0730844f * r[6] + 2.8952293f * r[4], -6.0730844f * r[10] + -2.8952293f * r[12],
            8.97054f * r[5]);
    SHLI_G3(88, -5.543942f * r[7] + 3.4256816f * r[5], -5.543942f * r[9] + -3.4256816f * r[11],
            9.27679f * r[6]);
    SHLI_G3(89, 3.9556363f * r[6], -7.0918345f * r[8] + -3.9556363f * r[10], 9.455779f * r[7]);
    SHLI_G3(90, 6.3431296f * r[9], 6.3431296f * r[7], 9.514694f * r[8]);
    SHLI_G3(91, -7.0918345f * r[8] + 3.9556363f * r[10], 3.9556363f * r[6], 9.455779f * r[9]);
    SHLI_G3(92, -5.543942f * r[9] + 3.4256816f * r[11], 5.543942f * r[7] + 3.4256816f * r[5],
            9.27679f * r[10]);
    SHLI_G3(93, -6.0730844f * r[10] + 2.8952293f * r[12], 6.0730844f * r[6] + 2.8952293f * r[4],
            8.97054f * r[11]);
    SHLI_G3(94, -6.6021385f * r[11] + 2.3639448f * r[13], 6.6021385f * r[5] + 2.3639448f * r[3],
            8.523324f * r[12]);
    SHLI_G3(95, -7.131125f * r[12] + 1.8311038f * r[14], 7.131125f * r[4] + 1.8311038f * r[2],
            7.9112725f * r[13]);
    SHLI_G3(96, -7.6600566f * r[13] + 1.294786f * r[15], 7.6600566f * r[3] + 1.294786f * r[1],
            7.0918345f * r[14]);
    SHLI_G3(97, -8.188945f * r[14] + 0.747545f * r[16], 8.188945f * r[2] + 0.747545f * r[0],
            5.98036f * r[15]);
    SHLI_G3(98, -8.717798f * r[15], 8.717798f * r[1], 4.358899f * r[16]);
    SHLI_G2(99, -9.246621f * r[16], 9.246621f * r[0]);
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
    SHLI_G2(100, -10.246951f * r[0], -10.246951f * r[18]);
    SHLI_G3(101, -9.721111f * r[1], -9.721111f * r[17], 4.582576f * r[0]);
    SHLI_G3(102, -9.1952505f * r[2] + 0.74339193f * r[0],
            -9.1952505f * r[16] + -0.74339193f * r[18], 6.30789f * r[1]);
    SHLI_G3(103, -8.669365f * r[3] + 1.2875926f * r[1], -8.669365f * r[15] + -1.2875926f * r[17],
            7.5078907f * r[2]);
    SHLI_G3(104, -8.143451f * r[4] + 1.820931f * r[2], -8.143451f * r[14] + -1.820931f * r[16],
            8.41052f * r[3]);
    SHLI_G3(105, -7.617501f * r[5] + 2.3508117f * r[3], -7.617501f * r[13] + -2.3508117f * r[15],
            9.104654f * r[4]);
    SHLI_G3(106, -7.091507f * r[6] + 2.8791447f * r[4], -7.091507f * r[12] + -2.8791447f * r[14],
            9.635461f * r[5]);
    SHLI_G3(107, -6.5654597f * r[7] + 3.4066498f * r[5], -6.5654597f * r[11] + -3.4066498f * r[13],
            10.028906f * r[6]);
    SHLI_G3(108, -6.039345f * r[8] + 3.9336605f * r[6], -6.039345f * r[10] + -3.9336605f * r[12],
            10.300741f * r[7]);
    SHLI_G3(109, 4.4603515f * r[7], -7.7967606f * r[9] + -4.4603515f * r[11], 10.460452f * r[8]);
    SHLI_G3(110, 7.0524354f * r[10], 7.0524354f * r[8], 10.513149f * r[9]);
    SHLI_G3(111, -7.7967606f * r[9] + 4.4603515f * r[11], 4.4603515f * r[7], 10.460452f * r[10]);
    SHLI_G3(112, -6.039345f * r[10] + 3.9336605f * r[12], 6.039345f * r[8] + 3.9336605f * r[6],
            10.300741f * r[11]);
    SHLI_G3(113, -6.5654597f * r[11] + 3.4066498f * r[13], 6.5654597f * r[7] + 3.4066498f * r[5],
            10.028906f * r[12]);
    SHLI_G3(114, -7.091507f * r[12] + 2.8791447f * r[14], 7.091507f * r[6] + 2.8791447f * r[4],
            9.635461f * r[13]);
    SHLI_G3(115, -7.617501f * r[13] + 2.3508117f * r[15], 7.617501f * r[5] + 2.3508117f * r[3],
            9.104654f * r[14]);
    SHLI_G3(116, -8.143451f * r[14] + 1.820931f * r[16], 8.143451f * r[4] + 1.820931f * r[2],
            8.41052f * r[15]);
    SHLI_G3(117, -8.669365f * r[15] + 1.2875926f * r[17], 8.669365f * r[3] + 1.2875926f * r[1],
            7.5078907f * r[16]);
    SHLI_G3(118, -9.1952505f * r[16] + 0.74339193f * r[18], 9.1952505f * r[2] + 0.74339193f * r[0],
            6.30789f * r[17]);
    SHLI_G3(119, -9.721111f * r[17], 9.721111f * r[1], 4.582576f * r[18]);
    SHLI_G2(120, -10.246951f * r[18], 10.246951f * r[0]);
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
    SHLI_G2(121, -11.247222f * r[0], -11.247222f * r[20]);
    SHLI_G3(122, -10.723805f * r[1], -10.723805f * r[19], 4.7958317f * r[0]);
    SHLI_G3(123, -10.200374f * r[2] + 0.7400129f * r[0], -10.200374f * r[18] + -0.7400129f * r[20],
            6.6188765f * r[1]);
    SHLI_G3(124, -9.676924f * r[3] + 1.2817398f * r[1], -9.676924f * r[17] + -1.2817398f * r[19],
            7.9011755f * r[2]);
    SHLI_G3(125, -9.153454f * r[4] + 1.8126539f * r[2], -9.153454f * r[16] + -1.8126539f * r[18],
            8.880155f * r[3]);
    SHLI_G3(126, -8.629959f * r[5] + 2.3401263f * r[3], -8.629959f * r[15] + -2.3401263f * r[17],
            9.648587f * r[4]);
    SHLI_G3(127, -8.106435f * r[6] + 2.8660576f * r[4], -8.106435f * r[14] + -2.8660576f * r[16],
            10.253919f * r[5]);
    SHLI_G3(128, -7.5828753f * r[7] + 3.391165f * r[5], -7.5828753f * r[13] + -3.391165f * r[15],
            10.723805f * r[6]);
    SHLI_G3(129, -7.059273f * r[8] + 3.91578f * r[6], -7.059273f * r[12] + -3.91578f * r[14],
            11.075499f * r[7]);
    SHLI_G3(130, -6.535617f * r[9] + 4.4400773f * r[7], -6.535617f * r[11] + -4.4400773f * r[13],
            11.32002f * r[8]);
    SHLI_G3(131, 4.964157f * r[8], -8.502101f * r[10] + -4.964157f * r[12], 11.464231f * r[9]);
    SHLI_G3(132, 7.7613206f * r[11], 7.7613206f * r[9], 11.511899f * r[10]);
    SHLI_G3(133, -8.502101f * r[10] + 4.964157f * r[12], 4.964157f * r[8], 11.464231f * r[11]);
    SHLI_G3(134, -6.535617f * r[11] + 4.4400773f * r[13], 6.535617f * r[9] + 4.4400773f * r[7],
            11.32002f * r[12]);
    SHLI_G3(135, -7.059273f * r[12] + 3.91578f * r[14], 7.059273f * r[8] + 3.91578f * r[6],
            11.075499f * r[13]);
    SHLI_G3(136, -7.5828753f * r[13] + 3.391165f * r[15], 7.5828753f * r[7] + 3.391165f * r[5],
            10.723805f * r[14]);
    SHLI_G3(137, -8.106435f * r[14] + 2.8660576f * r[16], 8.106435f * r[6] + 2.8660576f * r[4],
            10.253919f * r[15]);
    SHLI_G3(138, -8.629959f * r[15] + 2.3401263f * r[17], 8.629959f * r[5] + 2.3401263f * r[3],
            9.648587f * r[16]);
    SHLI_G3(139, -9.153454f * r[16] + 1.8126539f * r[18], 9.153454f * r[4] + 1.8126539f * r[2],
            8.880155f * r[17]);
    SHLI_G3(140, -9.676924f * r[17] + 1.2817398f * r[19], 9.676924f * r[3] + 1.2817398f * r[1],
            7.9011755f * r[18]);
    SHLI_G3(141, -10.200374f * r[18] + 0.7400129f * r[20], 10.200374f * r[2] + 0.7400129f * r[0],
            6.6188765f * r[19]);
    SHLI_G3(142, -10.723805f * r[19], 10.723805f * r[1], 4.7958317f * r[20]);
    SHLI_G2(143, -11.247222f * r[20], 11.247222f * r[0]);
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
    SHLI_G2(144, -12.247449f * r[0], -12.247449f * r[22]);
    SHLI_G3(145, -11.726039f * r[1], -11.726039f * r[21], 5.0f * r[0]);
    SHLI_G3(146, -11.204618f * r[2] + 0.7372098f * r[0], -11.204618f * r[20] + -0.7372098f * r[22],
            6.915641f * r[1]);
    SHLI_G3(147, -10.683185f * r[3] + 1.2768848f * r[1], -10.683185f * r[19] + -1.2768848f * r[21],
            8.275159f * r[2]);
    SHLI_G3(148, -10.161736f * r[4] + 1.8057878f * r[2], -10.161736f * r[18] + -1.8057878f * r[20],
            9.325048f * r[3]);
    SHLI_G3(149, -9.640269f * r[5] + 2.331262f * r[3], -9.640269f * r[17] + -2.331262f * r[19],
            10.161736f * r[4]);
    SHLI_G3(150, -9.118781f * r[6] + 2.8552012f * r[4], -9.118781f * r[16] + -2.8552012f * r[18],
            10.834726f * r[5]);
    SHLI_G3(151, -8.59727f * r[7] + 3.3783197f * r[5], -8.59727f * r[15] + -3.3783197f * r[17],
            11.373118f * r[6]);
    SHLI_G3(152, -8.075728f * r[8] + 3.9009476f * r[6], -8.075728f * r[14] + -3.9009476f * r[16],
            11.795357f * r[7]);
    SHLI_G3(153, -7.5541525f * r[9] + 4.423259f * r[7], -7.5541525f * r[13] + -4.423259f * r[15],
            12.113593f * r[8]);
    SHLI_G3(154, -7.032533f * r[10] + 4.9453535f * r[8], -7.032533f * r[12] + -4.9453535f * r[14],
            12.335879f * r[9]);
    SHLI_G3(155, 5.467294f * r[9], -9.207747f * r[11] + -5.467294f * r[13], 12.467349f * r[10]);
    SHLI_G3(156, 8.469895f * r[12], 8.469895f * r[10], 12.510865f * r[11]);
    SHLI_G3(157, -9.207747f * r[11] + 5.467294f * r[13], 5.467294f * r[9], 12.467349f * r[12]);
    SHLI_G3(158, -7.032533f * r[12] + 4.9453535f * r[14], 7.032533f * r[10] + 4.9453535f * r[8],
            12.335879f * r[13]);
    SHLI_G3(159, -7.5541525f * r[13] + 4.423259f * r[15], 7.5541525f * r[9] + 4.423259f * r[7],
            12.113593f * r[14]);
    SHLI_G3(160, -8.075728f * r[14] + 3.9009476f * r[16], 8.075728f * r[8] + 3.9009476f * r[6],
            11.795357f * r[15]);
    SHLI_G3(161, -8.59727f * r[15] + 3.3783197f * r[17], 8.59727f * r[7] + 3.3783197f * r[5],
            11.373118f * r[16]);
    SHLI_G3(162, -9.118781f * r[16] + 2.8552012f * r[18], 9.118781f * r[6] + 2.8552012f * r[4],
            10.834726f * r[17]);
    SHLI_G3(163, -9.640269f * r[17] + 2.331262f * r[19], 9.640269f * r[5] + 2.331262f * r[3],
            10.161736f * r[18]);
    SHLI_G3(164, -10.161736f * r[18] + 1.8057878f * r[20], 10.161736f * r[4] + 1.8057878f * r[2],
            9.325048f * r[19]);
    SHLI_G3(165, -10.683185f * r[19] + 1.2768848f * r[21], 10.683185f * r[3] + 1.2768848f * r[1],
            8.275159f * r[20]);
    SHLI_G3(166, -11.204618f * r[20] + 0.7372098f * r[22], 11.204618f * r[2] + 0.7372098f * r[0],
            6.915641f * r[21]);
    SHLI_G3(167, -11.726039f * r[21], 11.726039f * r[1], 5.0f * r[22]);
    SHLI_G2(168, -12.247449f * r[22], 12.247449f * r[0]);
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
    SHLI_G2(169, -13.247642f * r[0], -13.247642f * r[24]);
    SHLI_G3(170, -12.727922f * r[1], -12.727922f * r[23], 5.196152f * r[0]);
    SHLI_G3(171, -12.208194f * r[2] + 0.73484695f * r[0],
            -12.208194f * r[22] + -0.73484695f * r[24], 7.2f * r[1]);
    SHLI_G3(172, -11.688456f * r[3] + 1.2727922f * r[1], -11.688456f * r[21] + -1.2727922f * r[23],
            8.632497f * r[2]);
    SHLI_G3(173, -11.168706f * r[4] + 1.8f * r[2], -11.168706f * r[20] + -1.8f * r[22],
            9.748846f * r[3]);
    SHLI_G3(174, -10.648944f * r[5] + 2.32379f * r[3], -10.648944f * r[19] + -2.32379f * r[21],
            10.648944f * r[4]);
    SHLI_G3(175, -10.129166f * r[6] + 2.8460498f * r[4], -10.129166f * r[18] + -2.8460498f * r[20],
            11.384199f * r[5]);
    SHLI_G3(176, -9.60937f * r[7] + 3.3674917f * r[5], -9.60937f * r[17] + -3.3674917f * r[19],
            11.984991f * r[6]);
    SHLI_G3(177, -9.089555f * r[8] + 3.8884444f * r[6], -9.089555f * r[16] + -3.8884444f * r[18],
            12.470766f * r[7]);
    SHLI_G3(178, -8.569715f * r[9] + 4.4090815f * r[7], -8.569715f * r[15] + -4.4090815f * r[17],
            12.854571f * r[8]);
    SHLI_G3(179, -8.049845f * r[10] + 4.929503f * r[8], -8.049845f * r[14] + -4.929503f * r[16],
            13.145341f * r[9]);
    SHLI_G3(180, -7.52994f * r[11] + 5.4497705f * r[9], -7.52994f * r[13] + -5.4497705f * r[15],
            13.349157f * r[10]);
    SHLI_G3(181, 5.9699244f * r[10], -9.913627f * r[12] + -5.9699244f * r[14], 13.469967f * r[11]);
    SHLI_G3(182, 9.178235f * r[13], 9.178235f * r[11], 13.509996f * r[12]);
    SHLI_G3(183, -9.913627f * r[12] + 5.9699244f * r[14], 5.9699244f * r[10], 13.469967f * r[13]);
    SHLI_G3(184, -7.52994f * r[13] + 5.4497705f * r[15], 7.52994f * r[11] + 5.4497705f * r[9],
            13.349157f * r[14]);
    SHLI_G3(185, -8.049845f * r[14] + 4.929503f * r[16], 8.049845f * r[10] + 4.929503f * r[8],
            13.145341f * r[15]);
    SHLI_G3(186, -8.569715f * r[15] + 4.4090815f * r[17], 8.569715f * r[9] + 4.4090815f * r[7],
            12.854571f * r[16]);
    SHLI_G3(187, -9.089555f * r[16] + 3.8884444f * r[18], 9.089555f * r[8] + 3.8884444f * r[6],
            12.470766f * r[17]);
    SHLI_G3(188, -9.60937f * r[17] + 3.3674917f * r[19], 9.60937f * r[7] + 3.3674917f * r[5],
            11.984991f * r[18]);
    SHLI_G3(189, -10.129166f * r[18] + 2.8460498f * r[20], 10.129166f * r[6] + 2.8460498f * r[4],
            11.384199f * r[19]);
    SHLI_G3(190, -10.648944f * r[19] + 2.32379f * r[21], 10.648944f * r[5] + 2.32379f * r[3],
            10.648944f * r[20]);
    SHLI_G3(191, -11.168706f * r[20] + 1.8f * r[22], 11.168706f * r[4] + 1.8f * r[2],
            9.748846f * r[21]);
    SHLI_G3(192, -11.688456f * r[21] + 1.2727922f * r[23], 11.688456f * r[3] + 1.2727922f * r[1],
            8.632497f * r[22]);
    SHLI_G3(193, -12.208194f * r[22] + 0.73484695f * r[24], 12.208194f * r[2] + 0.73484695f * r[0],
            7.2f * r[23]);
    SHLI_G3(194, -12.727922f * r[23], 12.727922f * r[1], 5.196152f * r[24]);
    SHLI_G2(195, -13.247642f * r[24], 13.247642f * r[0]);
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
    SHLI_G2(196, -14.247807f * r[0], -14.247807f * r[26]);
    SHLI_G3(197, -13.72953f * r[1], -13.72953f * r[25], 5.3851647f * r[0]);
    SHLI_G3(198, -13.2112465f * r[2] + 0.7328281f * r[0],
            -13.2112465f * r[24] + -0.7328281f * r[26], 7.4734097f * r[1]);
    SHLI_G3(199, -12.692955f * r[3] + 1.2692956f * r[1], -12.692955f * r[23] + -1.2692956f * r[25],
            8.975275f * r[2]);
    SHLI_G3(200, -12.174655f * r[4] + 1.7950549f * r[2], -12.174655f * r[22] + -1.7950549f * r[24],
            10.154365f * r[3]);
    SHLI_G3(201, -11.656344f * r[5] + 2.317406f * r[3], -11.656344f * r[21] + -2.317406f * r[23],
            11.113889f * r[4]);
    SHLI_G3(202, -11.138023f * r[6] + 2.838231f * r[4], -11.138023f * r[20] + -2.838231f * r[22],
            11.907047f * r[5]);
    SHLI_G3(203, -10.619688f * r[7] + 3.3582404f * r[5], -10.619688f * r[19] + -3.3582404f * r[21],
            12.565385f * r[6]);
    SHLI_G3(204, -10.101338f * r[8] + 3.8777618f * r[6], -10.101338f * r[18] + -3.8777618f * r[20],
            13.109228f * r[7]);
    SHLI_G3(205, -9.582971f * r[9] + 4.396969f * r[7], -9.582971f * r[17] + -4.396969f * r[19],
            13.552367f * r[8]);
    SHLI_G3(206, -9.064583f * r[10] + 4.9159603f * r[8], -9.064583f * r[16] + -4.9159603f * r[18],
            13.904436f * r[9]);
    SHLI_G3(207, -8.546171f * r[11] + 5.4347987f * r[9], -8.546171f * r[15] + -5.4347987f * r[17],
            14.172221f * r[10]);
    SHLI_G3(208, -8.02773f * r[12] + 5.9535236f * r[10], -8.02773f * r[14] + -5.9535236f * r[16],
            14.360439f * r[11]);
    SHLI_G3(209, 6.4721627f * r[11], -10.619688f * r[13] + -6.4721627f * r[15], 14.472196f * r[12]);
    SHLI_G3(210, 9.886392f * r[14], 9.886392f * r[12], 14.509256f * r[13]);
    SHLI_G3(211, -10.619688f * r[13] + 6.4721627f * r[15], 6.4721627f * r[11], 14.472196f * r[14]);
    SHLI_G3(212, -8.02773f * r[14] + 5.9535236f * r[16], 8.02773f * r[12] + 5.9535236f * r[10],
            14.360439f * r[15]);
    SHLI_G3(213, -8.546171f * r[15] + 5.4347987f * r[17], 8.546171f * r[11] + 5.4347987f * r[9],
            14.172221f * r[16]);
    SHLI_G3(214, -9.064583f * r[16] + 4.9159603f * r[18], 9.064583f * r[10] + 4.9159603f * r[8],
            13.904436f * r[17]);
    SHLI_G3(215, -9.582971f * r[17] + 4.396969f * r[19], 9.582971f * r[9] + 4.396969f * r[7],
            13.552367f * r[18]);
    SHLI_G3(216, -10.101338f * r[18] + 3.8777618f * r[20], 10.101338f * r[8] + 3.8777618f * r[6],
            13.109228f * r[19]);
    SHLI_G3(217, -10.619688f * r[19] + 3.3582404f * r[21], 10.619688f * r[7] + 3.3582404f * r[5],
            12.565385f * r[20]);
    SHLI_G3(218, -11.138023f * r[20] + 2.838231f * r[22], 11.138023f * r[6] + 2.838231f * r[4],
            11.907047f * r[21]);
    SHLI_G3(219, -11.656344f * r[21] + 2.317406f * r[23], 11.656344f * r[5] + 2.317406f * r[3],
            11.113889f * r[22]);
    SHLI_G3(220, -12.174655f * r[22] + 1.7950549f * r[24], 12.174655f * r[4] + 1.7950549f * r[2],
            10.154365f * r[23]);
    SHLI_G3(221, -12.692955f * r[23] + 1.2692956f * r[25], 12.692955f * r[3] + 1.2692956f * r[1],
            8.975275f * r[24]);
    SHLI_G3(222, -13.2112465f * r[24] + 0.7328281f * r[26], 13.2112465f * r[2] + 0.7328281f * r[0],
            7.4734097f * r[25]);
    SHLI_G3(223, -13.72953f * r[25], 13.72953f * r[1], 5.3851647f * r[26]);
    SHLI_G2(224, -14.247807f * r[26], 14.247807f * r[0]);
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
    SHLI_G2(225, -15.247951f * r[0], -15.247951f * r[28]);
    SHLI_G3(226, -14.73092f * r[1], -14.73092f * r[27], 5.5677643f * r[0]);
    SHLI_G3(227, -14.213883f * r[2] + 0.7310833f * r[0], -14.213883f * r[26] + -0.7310833f * r[28],
            7.737058f * r[1]);
    SHLI_G3(228, -13.696841f * r[3] + 1.2662734f * r[1], -13.696841f * r[25] + -1.2662734f * r[27],
            9.305171f * r[2]);
    SHLI_G3(229, -13.179791f * r[4] + 1.790781f * r[2], -13.179791f * r[24] + -1.790781f * r[26],
            10.543833f * r[3]);
    SHLI_G3(230, -12.662734f * r[5] + 2.3118882f * r[3], -12.662734f * r[23] + -2.3118882f * r[25],
            11.559442f * r[4]);
    SHLI_G3(231, -12.145668f * r[6] + 2.8314734f * r[4], -12.145668f * r[22] + -2.8314734f * r[24],
            12.406895f * r[5]);
    SHLI_G3(232, -11.628592f * r[7] + 3.3502445f * r[5], -11.628592f * r[21] + -3.3502445f * r[23],
            13.11882f * r[6]);
    SHLI_G3(233, -11.111504f * r[8] + 3.868529f * r[6], -11.111504f * r[20] + -3.868529f * r[22],
            13.716338f * r[7]);
    SHLI_G3(234, -10.594403f * r[9] + 4.3865f * r[7], -10.594403f * r[19] + -4.3865f * r[21],
            14.213883f * r[8]);
    SHLI_G3(235, -10.077288f * r[10] + 4.904256f * r[8], -10.077288f * r[18] + -4.904256f * r[20],
            14.621666f * r[9]);
    SHLI_G3(236, -9.560154f * r[11] + 5.421859f * r[9], -9.560154f * r[17] + -5.421859f * r[19],
            14.947033f * r[10]);
    SHLI_G3(237, -9.043001f * r[12] + 5.9393487f * r[10], -9.043001f * r[16] + -5.9393487f * r[18],
            15.195281f * r[11]);
    SHLI_G3(238, -8.525823f * r[13] + 6.456753f * r[11], -8.525823f * r[15] + -6.456753f * r[17],
            15.370146f * r[12]);
    SHLI_G3(239, 6.97409f * r[12], -11.325893f * r[14] + -6.97409f * r[16], 15.474116f * r[13]);
    SHLI_G3(240, 10.594403f * r[15], 10.594403f * r[13], 15.508618f * r[14]);
    SHLI_G3(241, -11.325893f * r[14] + 6.97409f * r[16], 6.97409f * r[12], 15.474116f * r[15]);
    SHLI_G3(242, -8.525823f * r[15] + 6.456753f * r[17], 8.525823f * r[13] + 6.456753f * r[11],
            15.370146f * r[16]);
    SHLI_G3(243, -9.043001f * r[16] + 5.9393487f * r[18], 9.043001f * r[12] + 5.9393487f * r[10],
            15.195281f * r[17]);
    SHLI_G3(244, -9.560154f * r[17] + 5.421859f * r[19], 9.560154f * r[11] + 5.421859f * r[9],
            14.947033f * r[18]);
    SHLI_G3(245, -10.077288f * r[18] + 4.904256f * r[20], 10.077288f * r[10] + 4.904256f * r[8],
            14.621666f * r[19]);
    SHLI_G3(246, -10.594403f * r[19] + 4.3865f * r[21], 10.594403f * r[9] + 4.3865f * r[7],
            14.213883f * r[20]);
    SHLI_G3(247, -11.111504f * r[20] + 3.868529f * r[22], 11.111504f * r[8] + 3.868529f * r[6],
            13.716338f * r[21]);
    SHLI_G3(248, -11.628592f * r[21] + 3.3502445f * r[23], 11.628592f * r[7] + 3.3502445f * r[5],
            13.11882f * r[22]);
    SHLI_G3(249, -12.145668f * r[22] + 2.8314734f * r[24], 12.145668f * r[6] + 2.8314734f * r[4],
            12.406895f * r[23]);
    SHLI_G3(250, -12.662734f * r[23] + 2.3118882f * r[25], 12.662734f * r[5] + 2.3118882f * r[3],
            11.559442f * r[24]);
    SHLI_G3(251, -13.179791f * r[24] + 1.790781f * r[26], 13.179791f * r[4] + 1.790781f * r[2],
            10.543833f * r[25]);
    SHLI_G3(252, -13.696841f * r[25] + 1.2662734f * r[27], 13.696841f * r[3] + 1.2662734f * r[1],
            9.305171f * r[26]);
    SHLI_G3(253, -14.213883f * r[26] + 0.7310833f * r[28], 14.213883f * r[2] + 0.7310833f * r[0],
            7.737058f * r[27]);
    SHLI_G3(254, -14.73092f * r[27], 14.73092f * r[1], 5.5677643f * r[28]);
    SHLI_G2(255, -15.247951f * r[28], 15.247951f * r[0]);
  }
#endif
}
#undef SHLI_G3
#undef SHLI_G2

SHLIGHT_INLINE void shli_sh_grad_band(int l, const float *y, float nx, float ny, float nz, float ir,
                                      float ib, float *out_gb) {
  float rb[31];
  shli_real f = SHLIGHT_ITOR(2 * l + 1) / SHLIGHT_ITOR(2 * l - 1);
  shli_real a;
  float lr = SHLIGHT_ITOF(l) * ir;
  float ca;
  float cb;
  float cc;
  float ap;
  float bp;
  float q;
  float gx;
  float gy;
  int k;
  int m;
  int am;
  for (k = 0; k < 31; ++k) {
    rb[k] = 0.0f;
    if (k >= 16 - l && k <= 14 + l) {
      rb[k] = y[l * l - l + k - 15] * ir;
    }
  }
  for (k = 0; k < 31; ++k) {
    m = k - 15;
    am = m < 0 ? -m : m;
    if (am <= l) {
      a = -0.5 * SHLIGHT_SQRTR(f * SHLIGHT_ITOR(l + am) * SHLIGHT_ITOR(l + am - 1));
      ca = SHLIGHT_FLOAT(a);
      ap = am == 1 ? SHLIGHT_FLOAT(a * 1.4142135623730951) : ca;
      a = 0.5 * SHLIGHT_SQRTR(f * SHLIGHT_ITOR((l - am) * (l - am - 1)));
      cb = SHLIGHT_FLOAT(a);
      bp = am == 0 ? SHLIGHT_FLOAT(a * 1.4142135623730951) : cb;
      cc = SHLIGHT_FLOAT(SHLIGHT_SQRTR(f * SHLIGHT_ITOR(l - am) * SHLIGHT_ITOR(l + am)));
      if (m >= 0) {
        gx = (am >= 1 ? ap * rb[k - 1] : 0.0f) + (am + 1 < l ? bp * rb[k + 1] : 0.0f);
        gy = (am >= 2 ? -ca * rb[31 - k] : 0.0f) + (am + 1 < l ? bp * rb[29 - k] : 0.0f);
      } else {
        gx = (am >= 2 ? ca * rb[k + 1] : 0.0f) + (am + 1 < l ? cb * rb[k - 1] : 0.0f);
        gy = ap * rb[29 - k] + (am + 1 < l ? -cb * rb[31 - k] : 0.0f);
      }
      q = lr * y[l * l + l + m];
      out_gb[3 * k] = (gx - q * nx) * ib;
      out_gb[3 * k + 1] = (gy - q * ny) * ib;
      out_gb[3 * k + 2] = (cc * rb[k] - q * nz) * ib;
    }
  }
}

SHLIGHT_INLINE void shli_sh_grad_bands(int n, const float *y, float nx, float ny, float nz,
                                       float ir, float ib, float (*out_grad)[3]) {
  float gb[93];
  int k;
  SHLIGHT_SET3(out_grad[0], 0.0f, 0.0f, 0.0f);
#if SHLIGHT_MAX_BANDS > 1
  if (n > 1) {
    shli_sh_grad_band(1, y, nx, ny, nz, ir, ib, gb);
    for (k = 14; k <= 16; ++k) {
      SHLIGHT_SET3(out_grad[k - 13], gb[3 * k], gb[3 * k + 1], gb[3 * k + 2]);
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 2
  if (n > 2) {
    shli_sh_grad_band(2, y, nx, ny, nz, ir, ib, gb);
    for (k = 13; k <= 17; ++k) {
      SHLIGHT_SET3(out_grad[k - 9], gb[3 * k], gb[3 * k + 1], gb[3 * k + 2]);
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 3
  if (n > 3) {
    shli_sh_grad_band(3, y, nx, ny, nz, ir, ib, gb);
    for (k = 12; k <= 18; ++k) {
      SHLIGHT_SET3(out_grad[k - 3], gb[3 * k], gb[3 * k + 1], gb[3 * k + 2]);
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 4
  if (n > 4) {
    shli_sh_grad_band(4, y, nx, ny, nz, ir, ib, gb);
    for (k = 11; k <= 19; ++k) {
      SHLIGHT_SET3(out_grad[k + 5], gb[3 * k], gb[3 * k + 1], gb[3 * k + 2]);
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 5
  if (n > 5) {
    shli_sh_grad_band(5, y, nx, ny, nz, ir, ib, gb);
    for (k = 10; k <= 20; ++k) {
      SHLIGHT_SET3(out_grad[k + 15], gb[3 * k], gb[3 * k + 1], gb[3 * k + 2]);
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 6
  if (n > 6) {
    shli_sh_grad_band(6, y, nx, ny, nz, ir, ib, gb);
    for (k = 9; k <= 21; ++k) {
      SHLIGHT_SET3(out_grad[k + 27], gb[3 * k], gb[3 * k + 1], gb[3 * k + 2]);
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 7
  if (n > 7) {
    shli_sh_grad_band(7, y, nx, ny, nz, ir, ib, gb);
    for (k = 8; k <= 22; ++k) {
      SHLIGHT_SET3(out_grad[k + 41], gb[3 * k], gb[3 * k + 1], gb[3 * k + 2]);
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 8
  if (n > 8) {
    shli_sh_grad_band(8, y, nx, ny, nz, ir, ib, gb);
    for (k = 7; k <= 23; ++k) {
      SHLIGHT_SET3(out_grad[k + 57], gb[3 * k], gb[3 * k + 1], gb[3 * k + 2]);
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 9
  if (n > 9) {
    shli_sh_grad_band(9, y, nx, ny, nz, ir, ib, gb);
    for (k = 6; k <= 24; ++k) {
      SHLIGHT_SET3(out_grad[k + 75], gb[3 * k], gb[3 * k + 1], gb[3 * k + 2]);
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 10
  if (n > 10) {
    shli_sh_grad_band(10, y, nx, ny, nz, ir, ib, gb);
    for (k = 5; k <= 25; ++k) {
      SHLIGHT_SET3(out_grad[k + 95], gb[3 * k], gb[3 * k + 1], gb[3 * k + 2]);
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 11
  if (n > 11) {
    shli_sh_grad_band(11, y, nx, ny, nz, ir, ib, gb);
    for (k = 4; k <= 26; ++k) {
      SHLIGHT_SET3(out_grad[k + 117], gb[3 * k], gb[3 * k + 1], gb[3 * k + 2]);
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 12
  if (n > 12) {
    shli_sh_grad_band(12, y, nx, ny, nz, ir, ib, gb);
    for (k = 3; k <= 27; ++k) {
      SHLIGHT_SET3(out_grad[k + 141], gb[3 * k], gb[3 * k + 1], gb[3 * k + 2]);
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 13
  if (n > 13) {
    shli_sh_grad_band(13, y, nx, ny, nz, ir, ib, gb);
    for (k = 2; k <= 28; ++k) {
      SHLIGHT_SET3(out_grad[k + 167], gb[3 * k], gb[3 * k + 1], gb[3 * k + 2]);
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 14
  if (n > 14) {
    shli_sh_grad_band(14, y, nx, ny, nz, ir, ib, gb);
    for (k = 1; k <= 29; ++k) {
      SHLIGHT_SET3(out_grad[k + 195], gb[3 * k], gb[3 * k + 1], gb[3 * k + 2]);
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 15
  if (n > 15) {
    shli_sh_grad_band(15, y, nx, ny, nz, ir, ib, gb);
    for (k = 0; k <= 30; ++k) {
      SHLIGHT_SET3(out_grad[k + 225], gb[3 * k], gb[3 * k + 1], gb[3 * k + 2]);
    }
  }
#endif
}

SHLIGHT_INLINE void shli_sh_grad(int n, const float *y, float nx, float ny, float nz, float ir,
                                 float ib, float (*out_grad)[3]) {
#if SHLIGHT_BY_BANDS
#if SHLIGHT_MAX_BANDS > SHLIGHT_UNROLLED_BANDS
  if (n > SHLIGHT_UNROLLED_BANDS) {
    shli_sh_grad_loop(n, y, nx, ny, nz, ir, ib, out_grad);
    return;
  }
#endif
  shli_sh_grad_bands(n, y, nx, ny, nz, ir, ib, out_grad);
#else
  shli_sh_grad_lines(n, y, nx, ny, nz, ir, ib, out_grad);
#endif
}
/* @generated end gradient */

#undef SHLI_ZH_TAB
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
SHLI_TAB_FN(zh_tab) {
  return &SHLI_ZH_TAB;
}

#undef SHLI_LIGHT_BAND
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
  int i;
#if SHLIGHT_MAX_BANDS > SHLIGHT_UNROLLED_BANDS
  for (i = SHLIGHT_UNROLLED_BANDS * SHLIGHT_UNROLLED_BANDS; i < n * n; ++i) {
    out_sh[i] = 0.0f;
    SHLIGHT_SET3(out_grad[i], 0.0f, 0.0f, 0.0f);
  }
#endif
  out_sh[0] = 0.0f;
  SHLIGHT_SET3(out_grad[0], 0.0f, 0.0f, 0.0f);
#if SHLIGHT_MAX_BANDS > 1
  if (n > 1) {
    for (i = 1; i < 4; ++i) {
      out_sh[i] = 0.0f;
      SHLIGHT_SET3(out_grad[i], 0.0f, 0.0f, 0.0f);
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 2
  if (n > 2) {
    for (i = 4; i < 9; ++i) {
      out_sh[i] = 0.0f;
      SHLIGHT_SET3(out_grad[i], 0.0f, 0.0f, 0.0f);
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 3
  if (n > 3) {
    for (i = 9; i < 16; ++i) {
      out_sh[i] = 0.0f;
      SHLIGHT_SET3(out_grad[i], 0.0f, 0.0f, 0.0f);
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 4
  if (n > 4) {
    for (i = 16; i < 25; ++i) {
      out_sh[i] = 0.0f;
      SHLIGHT_SET3(out_grad[i], 0.0f, 0.0f, 0.0f);
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 5
  if (n > 5) {
    for (i = 25; i < 36; ++i) {
      out_sh[i] = 0.0f;
      SHLIGHT_SET3(out_grad[i], 0.0f, 0.0f, 0.0f);
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 6
  if (n > 6) {
    for (i = 36; i < 49; ++i) {
      out_sh[i] = 0.0f;
      SHLIGHT_SET3(out_grad[i], 0.0f, 0.0f, 0.0f);
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 7
  if (n > 7) {
    for (i = 49; i < 64; ++i) {
      out_sh[i] = 0.0f;
      SHLIGHT_SET3(out_grad[i], 0.0f, 0.0f, 0.0f);
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 8
  if (n > 8) {
    for (i = 64; i < 81; ++i) {
      out_sh[i] = 0.0f;
      SHLIGHT_SET3(out_grad[i], 0.0f, 0.0f, 0.0f);
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 9
  if (n > 9) {
    for (i = 81; i < 100; ++i) {
      out_sh[i] = 0.0f;
      SHLIGHT_SET3(out_grad[i], 0.0f, 0.0f, 0.0f);
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 10
  if (n > 10) {
    for (i = 100; i < 121; ++i) {
      out_sh[i] = 0.0f;
      SHLIGHT_SET3(out_grad[i], 0.0f, 0.0f, 0.0f);
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 11
  if (n > 11) {
    for (i = 121; i < 144; ++i) {
      out_sh[i] = 0.0f;
      SHLIGHT_SET3(out_grad[i], 0.0f, 0.0f, 0.0f);
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 12
  if (n > 12) {
    for (i = 144; i < 169; ++i) {
      out_sh[i] = 0.0f;
      SHLIGHT_SET3(out_grad[i], 0.0f, 0.0f, 0.0f);
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 13
  if (n > 13) {
    for (i = 169; i < 196; ++i) {
      out_sh[i] = 0.0f;
      SHLIGHT_SET3(out_grad[i], 0.0f, 0.0f, 0.0f);
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 14
  if (n > 14) {
    for (i = 196; i < 225; ++i) {
      out_sh[i] = 0.0f;
      SHLIGHT_SET3(out_grad[i], 0.0f, 0.0f, 0.0f);
    }
  }
#endif
#if SHLIGHT_MAX_BANDS > 15
  if (n > 15) {
    for (i = 225; i < 256; ++i) {
      out_sh[i] = 0.0f;
      SHLIGHT_SET3(out_grad[i], 0.0f, 0.0f, 0.0f);
    }
  }
#endif
}
/* @generated end light_idx */
#if SHLIGHT_SIMD_EVAL
SHLI_TAB_FN(light_band) {
  return &SHLI_LIGHT_BAND;
}
#endif

#endif /* SHLIGHT_GENERATED_H */

/* C-only tables of the implementation */
#if defined(SHLIGHT_IMPLEMENTATION) && !defined(SHLIGHT_GENERATED_IMPLEMENTATION_DONE)
#define SHLIGHT_GENERATED_IMPLEMENTATION_DONE

#undef SHLI_SH_BRS
#undef SHLI_SH_BPOLY
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
SHLI_TAB_FN(sh_brs) {
  return &SHLI_SH_BRS;
}
SHLI_TAB_FN(sh_bpoly) {
  return &SHLI_SH_BPOLY;
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
