// Fixture: GLSL prelude (shims + types).  Only GLSL-only helpers here.
#ifndef SHL_PRELUDE_GLSL
#define SHL_PRELUDE_GLSL
#ifndef SHLIGHT_MAX_BANDS
#define SHLIGHT_MAX_BANDS 3
#endif
#define SHLIGHT_MAX_COEFFS (SHLIGHT_MAX_BANDS * SHLIGHT_MAX_BANDS)
#define SHLIGHT_SQRT(x) sqrt(x)
#define shli_real float
#define SHLIGHT_ITOF(x) float(x)
#define SHLIGHT_FTOI(x) int(x)

struct shl_sh4 {
    float c[4];
};

float shlg_saturate(float x) { return clamp(x, 0.0, 1.0); }
#endif
