/* lights.c - several lights in one 3-band SH, shaded at many normals; the gradient of an SH
   function; rotating SH; a quad light with Lambert and GGX. The sphere, rotation and Lambert
   results are checked against closed forms. C99 and C++11 clean. Build and run: make example */
#define SHLIGHT_IMPLEMENTATION
#include "../shlight.h"

#include <math.h>
#include <stdio.h>

#define PI 3.14159265358979323846

static double rel(double a, double b) {
  return fabs(a - b) / fabs(b);
}

int main(void) {
  enum { N = 3, NC = N * N };
  const float x[3] = {0.0f, 0.0f, 0.0f}; /* the shading point */
  const float c1[3] = {0.0f, 0.0f, 3.0f}, c2[3] = {2.0f, 1.0f, 1.0f}, r1 = 0.5f, r2 = 0.3f;
  const float p0[3] = {-1.0f, -1.0f, 8.0f}, p1[3] = {1.0f, -1.0f, 8.0f}, p2[3] = {0.0f, 1.0f, 8.0f};
  float sh[NC], tmp[NC], cosine[N];
  unsigned seed = 1u;
  double lo = 1e30, hi = 0.0, sum = 0.0;
  int i, k, bad = 0; /* checks off by more than float rounding allows */

  /* 1. Unit-radiance lights add linearly: two spheres and a triangle in one SH. */
  shl_sphere_light(N, x, c1, r1, sh);
  shl_sphere_light(N, x, c2, r2, tmp);
  for (i = 0; i < NC; ++i)
    sh[i] += tmp[i];
  shl_triangle_light(N, x, p0, p1, p2, tmp); /* a model: good far away (see the check below) */
  for (i = 0; i < NC; ++i)
    sh[i] += tmp[i];
  /* irradiance E(nrm) = light SH against the clamped cosine turned to nrm (no 1/pi in E) */
  shl_zh_cosine_power(N, 1.0f, cosine);
  for (i = 0; i < 1000; ++i) {
    float nrm[3];
    double e;
    for (k = 0; k < 3; ++k) { /* any non-zero vector: shl_sh_conv_zh normalises it */
      seed = seed * 1664525u + 1013904223u;
      nrm[k] = (float)(seed >> 8) / 8388608.0f - 1.0f;
    }
    e = (double)shl_sh_conv_zh(N, sh, cosine, nrm);
    sum += e;
    lo = e < lo ? e : lo;
    hi = e > hi ? e : hi;
  }
  /* a white Lambertian surface reflects E / pi. Facing away from small lights 3 bands ring
     below 0 (windowing, shl_zh_window, damps it here but does not remove it): clamp. */
  printf("1000 normals: irradiance min %.4f mean %.4f max %.4f\n", lo, sum / 1000.0, hi);

  /* checks: coefficient 0 of a sphere light is its solid angle 2 pi (1 - cos a) times Y_0^0;
     irradiance of a sphere above the horizon is pi sin^2(a) cos(theta) (16 bands here, the
     clamped cosine's truncation is what is left); coefficient 0 of the triangle model against
     the exact solid angle */
  {
    const float nrm[3] = {0.6f, 0.0f, 0.8f};
    float big[16 * 16], cz[16];
    double d = 3.0, ca = sqrt(1.0 - (0.5 / d) * (0.5 / d));
    double exact0 = 2.0 * PI * (1.0 - ca) * 0.28209479177387814;
    double d2 = sqrt(6.0), exact_e = PI * (0.3 / d2) * (0.3 / d2) * (0.6 * 2.0 + 0.8) / d2;
    shl_sphere_light(N, x, c1, r1, tmp);
    shl_sphere_light(16, x, c2, r2, big);
    shl_zh_cosine_power(16, 1.0f, cz);
    printf("sphere: coefficient 0 rel. error %.1e; irradiance at 16 bands %.1e, at 3 bands "
           "%.1e\n",
           rel(tmp[0], exact0), rel(shl_sh_conv_zh(16, big, cz, nrm), exact_e),
           rel(shl_sh_conv_zh(3, big, cz, nrm), exact_e));
    bad += rel(tmp[0], exact0) > 1e-6;
    shl_triangle_light(N, x, p0, p1, p2, tmp);
    printf("triangle model at distance 5.6 sqrt(area): coefficient 0 rel. error %.1e\n",
           rel((double)tmp[0] / 0.28209479177387814, shl_triangle_solid_angle(x, p0, p1, p2)));
  }

  /* 2. Value and gradient of the SH function f(d) = sum_i sh[i] Y_i(d) (e.g. the brightest
     direction's ascent) in one call, without the n^2 basis gradients; d need not be unit, the
     gradient is d/dd of f(d/|d|). */
  {
    const float d[3] = {0.3f, -0.5f, 0.81f};
    float g[3];
    float f = shl_sh_eval_dot_grad(N, sh, d, g);
    printf("f(d) = %.5f, grad f at d: %.5f %.5f %.5f\n", (double)f, (double)g[0], (double)g[1],
           (double)g[2]);
  }

  /* 3. Rotation: R row-major; rotating a light's SH by R equals the light moved to R c. */
  {
    const float cz = 0.7648422f, sz = 0.6442177f, cx = 0.9210610f, sx = 0.3894183f;
    const float R[9] = {cz, -sz * cx, sz * sx, sz, cz * cx, -cz * sx, 0.0f, sx, cx}; /* Rz Rx */
    float rot[NC], moved[NC], rc[3];
    double err = 0.0;
    for (k = 0; k < 3; ++k)
      rc[k] = R[3 * k] * c2[0] + R[3 * k + 1] * c2[1] + R[3 * k + 2] * c2[2];
    shl_sphere_light(N, x, c2, r2, tmp);
    shl_sh_rotate(N, R, tmp, rot);
    shl_sphere_light(N, x, rc, r2, moved);
    for (i = 0; i < NC; ++i) {
      double e = fabs((double)rot[i] - (double)moved[i]);
      err = e > err ? e : err;
    }
    printf("rotated SH against the moved light: max abs difference %.1e (coefficient 0 %.4f)\n",
           err, (double)moved[0]);
    bad += err > 1e-7;
  }

  /* 4. A unit square light at height 1, centred above the point: no SH. Lambert: the cosine
     moment is the irradiance; its closed form is the form factor of four 0.5 x 0.5 corner
     rectangles times pi. GGX: f (n.l) integrated over the light, Fresnel 1. */
  {
    const float quad[4][3] = {
        {-0.5f, -0.5f, 1.0f}, {0.5f, -0.5f, 1.0f}, {0.5f, 0.5f, 1.0f}, {-0.5f, 0.5f, 1.0f}};
    const float nrm[3] = {0.0f, 0.0f, 1.0f}, view[3] = {0.5f, 0.0f, 0.8660254f};
    double q = sqrt(1.25), exact = 4.0 * (0.5 / q) * atan(0.5 / q);
    float e = shl_polygon_moment(quad, 4, nrm, 1.0f, SHLIGHT_EDGE_AUTO);
    printf("quad: irradiance %.7f, closed form %.7f (rel. %.1e); GGX (alpha 0.25) %.5f, "
           "fast %.5f\n",
           (double)e, exact, rel(e, exact), (double)shl_polygon_ggx(quad, 4, nrm, view, 0.25f),
           (double)shl_polygon_ggx_fast(quad, 4, nrm, view, 0.25f));
    bad += rel(e, exact) > 1e-6;
  }
  printf("closed-form checks: %s\n", bad ? "FAILED" : "ok");
  return bad != 0;
}
