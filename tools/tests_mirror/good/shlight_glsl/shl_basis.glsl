// Fixture: mirror of the >>basis section.
#ifndef SHL_BASIS_GLSL
#define SHL_BASIS_GLSL

/* a prefix of the C table is fine: sizes are literals, 4 < 9 */
const float SHLI_K[4] = float[4](0.28209479177387814, 0.4886025119029199,
                                 0.4886025119029199, 0.4886025119029199);
#if SHLIGHT_MAX_BANDS > 1
const int SHLI_BAND[SHLIGHT_MAX_COEFFS] = int[SHLIGHT_MAX_COEFFS](0, 1, 1, 1, 2, 2, 2, 2, 2);
#endif
const float SHLG_ONLY[2] = float[2](1.0, 2.0);

float shli_sq(float x) { return x * x; }

// evaluates n bands at unit d
void shl_sh_eval(int n, vec3 d, out float out_y[SHLIGHT_MAX_COEFFS])
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

float shlg_sum4(float a[SHLIGHT_MAX_COEFFS]) { return a[0] + a[1] + a[2] + a[3]; }

float shl_sh_dot(int n, in float a[SHLIGHT_MAX_COEFFS], float b[SHLIGHT_MAX_COEFFS])
{
    float s = 0.0f;
    int i;
    for (i = 0; i < n * n; ++i) {
        s += a[i] * b[i];
    }
    return (n & 1) == 0 ? s : s * 1.0f;
}

#if SHLIGHT_MAX_BANDS > 1
void shl_sh4_scale(shl_sh4 s, float k, out vec3 out_v, inout float io_acc[SHLIGHT_MAX_COEFFS],
                   vec3 dirs[SHLIGHT_MAX_COEFFS], int count)
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
void shl_sh4_scale(shl_sh4 s, float k, out vec3 out_v, inout float io_acc[SHLIGHT_MAX_COEFFS],
                   vec3 dirs[SHLIGHT_MAX_COEFFS], int count)
{
    out_v[0] = s.c[0] * k;
    out_v[1] = 0.0f;
    out_v[2] = 0.0f;
    io_acc[0] += SHLIGHT_ITOF(count);
}
#endif

#endif
