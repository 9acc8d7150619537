/* Fixture for tools/check_mirror.py: a miniature shlight.h that mirrors
   shlight_glsl/ correctly.  Not the real library. */
#ifndef SHLIGHT_H
#define SHLIGHT_H

#define SHLIGHT_INLINE static inline
#define SHLIGHT_RESTRICT restrict
#ifndef SHLIGHT_MAX_BANDS
#define SHLIGHT_MAX_BANDS 3
#endif
#define SHLIGHT_MAX_COEFFS (SHLIGHT_MAX_BANDS * SHLIGHT_MAX_BANDS)
#define SHLIGHT_SQRT(x) sqrtf(x)
#define SHLIGHT_ITOF(x) ((float)(x))
#define SHLIGHT_FTOI(x) ((int)(x))
#define SHLIGHT_API extern

#ifdef __cplusplus
extern "C" {
#endif

/* >>prelude  shims and types; no kernels in this section */
typedef double shli_real; /* internal precision: double in C, float in GLSL */
typedef struct shl_sh4 {
    float c[4];
} shl_sh4;

SHLIGHT_API void shl_sh_eval_accurate(int n, const float d[3], float *out_y);

/* >>basis ----------------------------------------------------------------
   Real SH basis.  The line "// >>not_an_anchor" below is inside this comment
   and does not start a section. */

static const float SHLI_K[9] = {
    0.28209479177387814f, 0.4886025119029199f, 0.4886025119029199f,
    0.4886025119029199f, 1.0925484305920792f, 1.0925484305920792f,
    0.31539156525252005f, 1.0925484305920792f, 0.5462742152960396f,
};
#if SHLIGHT_MAX_BANDS > 1
static const int SHLI_BAND[SHLIGHT_MAX_COEFFS] = { 0, 1, 1, 1, 2, 2, 2, 2, 2 };
#endif

SHLIGHT_INLINE float shli_sq(float x) { return x * x; }

/* evaluates n bands at unit d */
SHLIGHT_INLINE void shl_sh_eval(int n, const float d[3], float *SHLIGHT_RESTRICT out_y)
{
    float x = d[0], y = d[1], z = d[2];
    if (n < 1) {
        return;
    }
    out_y[0] = SHLI_K[0];
    if (n > 1) {
        out_y[1] = -SHLI_K[1] * y;
        out_y[2] = SHLI_K[2] * z;
        out_y[3] = -SHLI_K[3] * x;
    }
#if SHLIGHT_MAX_BANDS > 2
    if (n > 2) {
        out_y[4] = SHLI_K[4] * x * y;
        out_y[5] = -SHLI_K[5] * y * z;
        out_y[6] = SHLI_K[6] * (3.0f * shli_sq(z) - 1.0f);
        out_y[7] = -SHLI_K[7] * x * z;
        out_y[8] = SHLI_K[8] * (x * x - y * y);
    }
#endif
}

SHLIGHT_INLINE float shl_sh_dot(int n, const float *a, const float *b)
{
    float s = 0.0f;
    int i;
    for (i = 0; i < n * n; ++i) {
        s += a[i] * b[i];
    }
    return (n & 1) == 0 ? s : s * 1.0f; /* binary & and ?: are fine */
}

#if SHLIGHT_MAX_BANDS > 1
SHLIGHT_INLINE void shl_sh4_scale(shl_sh4 s, float k, float out_v[3], float *io_acc,
                                  const float (*dirs)[3], int count)
{
    int i = count;
    int half_i = i >> 1;
    i >>= 1;
    out_v[0] = s.c[1] * k;
    out_v[1] = s.c[2] * -1.5e-3f;
    out_v[2] = (s.c[3] + 1.0e5f) * SHLIGHT_ITOF(half_i + i);
    io_acc[0] += SHLIGHT_SQRT(dirs[0][0] * dirs[0][0]);
}
#else
SHLIGHT_INLINE void shl_sh4_scale(shl_sh4 s, float k, float out_v[3], float *io_acc,
                                  const float (*dirs)[3], int count)
{
    out_v[0] = s.c[0] * k;
    out_v[1] = 0.0f;
    out_v[2] = 0.0f;
    io_acc[0] += SHLIGHT_ITOF(count);
}
#endif

/* >>gradient ------------------------------------------------------------ */

SHLIGHT_INLINE void shl_sh_eval_grad(int n, const float d[3], float *out_y,
                                     float (*out_grad)[3])
{
    int i;
    shl_sh_eval(n, d, out_y);
    for (i = 0; i < n * n; i++) {
        out_grad[i][0] = 0.0f;
        out_grad[i][1] = 0.0f;
        out_grad[i][2] = 0.0f;
    }
}

SHLIGHT_INLINE shl_sh4 shl_sh4_make(float c0)
{
    shl_sh4 r;
    r.c[0] = c0;
    r.c[1] = 0.0f;
    r.c[2] = 0.0f;
    r.c[3] = SHLIGHT_ITOF(SHLIGHT_FTOI(c0 * 2.0f)) * 0.5f;
    return r;
}

/* a scalar typedef passes by value under its own name; its tables compare as float */
static const shli_real SHLI_R[3] = { 0.5, 0.25, 0.125 };

SHLIGHT_INLINE shli_real shli_lerp(shli_real a, shli_real b, shli_real t)
{
    return a + (b - a) * t * SHLI_R[0];
}

#ifdef __cplusplus
}
#endif

#if defined(SHLIGHT_IMPLEMENTATION) && !defined(SHLIGHT_IMPLEMENTATION_DONE)
#define SHLIGHT_IMPLEMENTATION_DONE
/* >>impl: after the stop line, ignored */
#include <math.h>
SHLIGHT_INLINE double shl_not_mirrored(const double *p) { return *p + sizeof(double); }
void shl_sh_eval_accurate(int n, const float d[3], float *out_y) { (void)n; (void)d; (void)out_y; }
#endif

#endif /* SHLIGHT_H */
