// toy.glsl - self-test kernel of the GLSL harness; its C twin is toy_poly() in
// tests/gl/test_gl_smoke.c (same body). Written like a shared shlight module: no #version,
// an include guard, float literals with a dot, valid as GLSL 450, 330 and 300 es.
#ifndef TOY_GLSL
#define TOY_GLSL

#ifndef TOY_SCALE
#define TOY_SCALE 1.0
#endif

void toy_poly(vec3 d, out float out_y[4])
{
    float x = d.x;
    float y = d.y;
    float z = d.z;
    out_y[0] = TOY_SCALE * 0.5;
    out_y[1] = TOY_SCALE * (x * y - z);
    out_y[2] = TOY_SCALE * (3.0 * z * z - 1.0);
    out_y[3] = TOY_SCALE * x * (x * x - 3.0 * y * y);
}

#endif
