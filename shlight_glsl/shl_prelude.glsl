// shl_prelude.glsl - the GLSL side of shlight.h's >>prelude (math shims): include first.
// The host defines SHLIGHT_MAX_BANDS (the band count the shader is built for) before it.
// Internal precision: shli_real is float in GLSL (double in C); see docs/accuracy.md for the accuracy.
#ifndef SHL_PRELUDE_GLSL
#define SHL_PRELUDE_GLSL
#ifndef SHLIGHT_MAX_BANDS
#define SHLIGHT_MAX_BANDS 4
#endif
#if SHLIGHT_MAX_BANDS < 1 || SHLIGHT_MAX_BANDS > 16
#error "shlight GLSL: SHLIGHT_MAX_BANDS must be in [1, 16] (the straight-line kernels)"
#endif
#define SHLIGHT_UNROLLED_BANDS 16
#define SHLIGHT_MAX_COEFFS (SHLIGHT_MAX_BANDS * SHLIGHT_MAX_BANDS)
#define SHLI_YBUF_COEFFS SHLIGHT_MAX_COEFFS
#define shli_real float
#define SHLIGHT_FLOAT(x) (x)
#define SHLIGHT_REAL(x) (x)
#define SHLIGHT_ITOF(i) float(i)
#define SHLIGHT_SQRTR(x) sqrt(x)
#define SHLIGHT_ABSR(x) abs(x)
#define SHLIGHT_REAL_MAX 3.4028234e38
#define SHLIGHT_REAL_WIDE 0
#define SHLIGHT_UNUSED(x)
#define SHLIGHT_BY_BANDS 1
#define SHLIGHT_FLAT_LOOPS 1
#define SHLIGHT_SET3(o, a, b, c) o = vec3((a), (b), (c))
#define SHLIGHT_UNROLL(k)
#define SHLIGHT_ALWAYS_INLINE
#ifndef SHLIGHT_BRDF_TABLE_FLOATS
#define SHLIGHT_BRDF_TABLE_FLOATS (2 * 90 * SHLIGHT_MAX_COEFFS)
#endif
#define SHLIGHT_SIGN1(x) ((x) < 0.0 ? -1.0 : 1.0)
#define SHLIGHT_SIMD_EVAL 0
#define SHLIGHT_ROTATE_FAST 0 /* C: shl_sh_rotate's vector path for n <= 8 */
#define SHLIGHT_OUTLINE_EVAL 0 /* C: the large band counts run out of line, in the implementation */
#define SHLIGHT_FTOI(x) int(x)
#define SHLIGHT_ITOR(i) float(i)
#define SHLIGHT_MAXR(a, b) max((a), (b))
#define SHLIGHT_MINR(a, b) min((a), (b))
#define SHLIGHT_EXPR(x) exp(x)
#define SHLIGHT_LOGR(x) log(x)
#define SHLIGHT_SINR(x) sin(x)
#define SHLIGHT_COSR(x) cos(x)
#define SHLIGHT_POWR(x, y) pow((x), (y))
#define SHLIGHT_SQRTF(x) sqrt(x)
#define SHLIGHT_ABSF(x) abs(x)
#define SHLIGHT_FATAN2(y, x) atan((y), (x))
#define SHLIGHT_FSIN(x) sin(x)
#define SHLIGHT_FSQRT(x) sqrt(x)
#define SHLIGHT_FLOG1P(x) ((x) < 0.01 ? (x) * (1.0 - (x) * (0.5 - (x) * (0.33333333 - 0.25 * (x)))) : log(1.0 + (x)))
#define SHLIGHT_FEXP(x) exp(x)
#define SHLIGHT_MEXP(x) exp(x)
#define SHLIGHT_MLOG(x) log(x)
#define SHLIGHT_MSIN(x) sin(x)
#define SHLIGHT_MCOS(x) cos(x)
#define SHLIGHT_EDGE_EXACT 0
#define SHLIGHT_EDGE_LORENTZ 1
#define SHLIGHT_EDGE_LORENTZ_PEARSON 2
#define SHLIGHT_EDGE_ELLIPSOID 3
#define SHLIGHT_EDGE_AUTO 4
#define SHLIGHT_EDGE_QUADRATURE 5
#define SHLIGHT_POLYGON_MAX 8
#define SHLIGHT_POLYGON_ANY 0
#define SHLIGHT_GGX_LANES 0
#define shl_edge_method int
#define shl_window_kind int
#define SHLIGHT_CLIP_MAX 20
#define SHLIGHT_EDGE_FAST 6
#define SHLIGHT_EDGE_STOKES_ADAPT 105
#define SHLIGHT_ADAPT_LEVELS 7
#define SHLIGHT_ADAPT_TOL 2.0e-6
#ifndef SHLIGHT_EDGE_FAST_ON
#define SHLIGHT_EDGE_FAST_ON 0
#endif
#define SHLIGHT_LANES 1
#define SHLIGHT_FAST_PAD (SHLIGHT_CLIP_MAX + SHLIGHT_LANES)
#define SHLIGHT_HALF_K 8
#define SHLIGHT_GGX_TOL 1.0e-3
#define SHLIGHT_GGX_SPLITS 128
#define SHLIGHT_GGX_DEPTH 8
#define SHLIGHT_GGX_HOR 4.0
#define SHLIGHT_GGX_KAP 1.25
#define SHLIGHT_GGX_GRADE 0.8
#define SHLIGHT_GGX_GSPLITS 512
#define SHLIGHT_GGX_XSPLITS 512
#define SHLIGHT_GGX_GDEPTH 16
#endif
