// Fixture: mirror of the >>gradient section.
void shl_sh_eval_grad(int n, highp vec3 d, out float out_y[SHLIGHT_MAX_COEFFS],
                      out vec3 out_grad[SHLIGHT_MAX_COEFFS])
{
    int i;
    shl_sh_eval(n, d, out_y);
    for (i = 0; i < n * n; i++) {
        out_grad[i][0] = 0.0f;
        out_grad[i][1] = 0.0f;
        out_grad[i][2] = 0.0f;
    }
}

shl_sh4 shl_sh4_make(float c0)
{
    shl_sh4 r;
    r.c[0] = c0;
    r.c[1] = 0.0f;
    r.c[2] = 0.0f;
    r.c[3] = SHLIGHT_ITOF(SHLIGHT_FTOI(c0 * 2.0f)) * 0.5f;
    return r;
}

const float SHLI_R[3] = float[3](0.5, 0.25, 0.125);

shli_real shli_lerp(shli_real a, shli_real b, shli_real t)
{
    return a + (b - a) * t * SHLI_R[0];
}
