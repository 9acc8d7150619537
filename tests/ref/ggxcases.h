/* ggxcases.h - the GGX quad-light sampler of the comparison that measured LTC's accuracy,
 * reimplemented for tests/test_ggx.c and bench/bench_ggx.c. Header-only C99, libm only,
 * deterministic (own SplitMix64 generator).
 *
 * One configuration: surface normal +z; view at theta_v uniform in [0, 88 deg] (azimuth 0: the
 * problem is symmetric about the normal); a quad light of one of three angular-size classes
 * drawn with equal probability, half-extents / distance uniform in 0.02-0.1 (small), 0.1-0.4
 * (medium), 0.4-1.2 (large), each of the two half-extents drawn on its own; distance 1-10;
 * light normal tilted by up to 60 deg (uniform angle, uniform azimuth) from facing the point,
 * random rotation about it; placement: 60 % with the centre direction within 1.5 angular
 * half-sizes (atan of the larger half-extent / distance) of the mirror direction, so the
 * mirror direction falls inside or near the light; 40 % uniform on the sphere with z in
 * [-0.25, 1] (some lights straddle the horizon). The note does not spell out its "near" and
 * tilt distributions; these are this file's choices. */
#ifndef GGXCASES_H
#define GGXCASES_H

#include <math.h>

typedef struct {
  double q[4][3]; /* quad vertices relative to the shading point, in order around the quad */
  double view[3]; /* unit, normal +z */
  int size_class; /* 0 small, 1 medium, 2 large */
  int mirror;     /* 1: placed about the mirror direction, 0: uniform with z >= -0.25 */
} ggxc_case;

typedef struct {
  unsigned long long s;
} ggxc_rng;

static double ggxc_rnd(ggxc_rng *r) {
  unsigned long long z = (r->s += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return (double)((z ^ (z >> 31)) >> 11) * (1.0 / 9007199254740992.0);
}
static void ggxc_unit(double a[3]) {
  double l = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  a[0] /= l, a[1] /= l, a[2] /= l;
}
static void ggxc_cross(const double a[3], const double b[3], double o[3]) {
  o[0] = a[1] * b[2] - a[2] * b[1], o[1] = a[2] * b[0] - a[0] * b[2],
  o[2] = a[0] * b[1] - a[1] * b[0];
}
static void ggxc_perp(const double w[3], double t1[3], double t2[3]) {
  double h[3] = {0, 0, 0};
  int k = 0;
  if (fabs(w[1]) < fabs(w[k])) k = 1;
  if (fabs(w[2]) < fabs(w[k])) k = 2;
  h[k] = 1;
  ggxc_cross(h, w, t1);
  ggxc_unit(t1);
  ggxc_cross(w, t1, t2);
}
/* the research sampler; tv_deg < 0: theta_v uniform in [0, 88 deg], else that angle */
static void ggxc_make(ggxc_rng *r, ggxc_case *c, double tv_deg) {
  const double pi = 3.14159265358979323846;
  double tv = tv_deg < 0 ? ggxc_rnd(r) * 88.0 * pi / 180 : tv_deg * pi / 180;
  double rr[3], d[3], t1[3], t2[3], nl[3], a1[3], a2[3], dist = 1 + 9 * ggxc_rnd(r),
                                                         u = ggxc_rnd(r);
  double lo, hi, ex, ey, ang, ph, tilt;
  int i, k;
  c->size_class = u < 1.0 / 3 ? 0 : u < 2.0 / 3 ? 1 : 2;
  c->mirror = ggxc_rnd(r) < 0.6;
  lo = c->size_class == 0 ? 0.02 : c->size_class == 1 ? 0.1 : 0.4;
  hi = c->size_class == 0 ? 0.1 : c->size_class == 1 ? 0.4 : 1.2;
  ex = lo + (hi - lo) * ggxc_rnd(r);
  ey = lo + (hi - lo) * ggxc_rnd(r);
  c->view[0] = sin(tv), c->view[1] = 0, c->view[2] = cos(tv);
  rr[0] = -c->view[0], rr[1] = 0, rr[2] = c->view[2];
  if (c->mirror) {
    ang = 1.5 * atan(ex > ey ? ex : ey) * sqrt(ggxc_rnd(r));
    ph = 2 * pi * ggxc_rnd(r);
    ggxc_perp(rr, t1, t2);
    for (k = 0; k < 3; k++)
      d[k] = cos(ang) * rr[k] + sin(ang) * (cos(ph) * t1[k] + sin(ph) * t2[k]);
  } else {
    double z = -0.25 + 1.25 * ggxc_rnd(r), p = 2 * pi * ggxc_rnd(r);
    d[0] = sqrt(1 - z * z) * cos(p), d[1] = sqrt(1 - z * z) * sin(p), d[2] = z;
  }
  tilt = (pi / 3) * ggxc_rnd(r);
  ph = 2 * pi * ggxc_rnd(r);
  ggxc_perp(d, t1, t2);
  for (k = 0; k < 3; k++)
    nl[k] = -cos(tilt) * d[k] + sin(tilt) * (cos(ph) * t1[k] + sin(ph) * t2[k]);
  ggxc_perp(nl, t1, t2);
  ph = 2 * pi * ggxc_rnd(r);
  for (k = 0; k < 3; k++)
    a1[k] = cos(ph) * t1[k] + sin(ph) * t2[k];
  ggxc_cross(nl, a1, a2);
  for (i = 0; i < 4; i++) {
    double sx = (i == 0 || i == 3) ? -1 : 1, sy = i < 2 ? -1 : 1;
    for (k = 0; k < 3; k++)
      c->q[i][k] = dist * (d[k] + sx * ex * a1[k] + sy * ey * a2[k]);
  }
}

#ifdef GGXC_HARD_CASES
#include <string.h>
/* The hard cases of tests/test_ggx.c (kind 0 straddling: the light's centre moved onto the
   horizon; 1 grazing view 85-88 deg; 2 large: half-extent 1.5 x distance, 113 deg across,
   facing the point near the mirror direction; 3 sliver: one side collapsed to 1 %). */
static void ggxc_hard(ggxc_rng *r, int kind, double q[4][3], double view[3]) {
  ggxc_case cs;
  int i, k;
  ggxc_make(r, &cs, kind == 1 ? 85 + 3 * ggxc_rnd(r) : -1);
  memcpy(q, cs.q, sizeof cs.q);
  memcpy(view, cs.view, sizeof cs.view);
  if (kind == 0) {
    double cz = (q[0][2] + q[1][2] + q[2][2] + q[3][2]) / 4;
    for (i = 0; i < 4; ++i)
      q[i][2] -= cz;
  } else if (kind == 2) {
    double d[3], t1[3], t2[3];
    d[0] = -view[0] + 0.3 * (ggxc_rnd(r) - 0.5);
    d[1] = 0.3 * (ggxc_rnd(r) - 0.5);
    d[2] = view[2] + 0.3 * (ggxc_rnd(r) - 0.5);
    ggxc_unit(d);
    ggxc_perp(d, t1, t2);
    for (i = 0; i < 4; ++i)
      for (k = 0; k < 3; ++k)
        q[i][k] = d[k] + ((i == 0 || i == 3) ? -1.5 : 1.5) * t1[k] + (i < 2 ? -1.5 : 1.5) * t2[k];
  } else if (kind == 3) {
    for (k = 0; k < 3; ++k) {
      double m0 = (q[0][k] + q[3][k]) / 2, m1 = (q[1][k] + q[2][k]) / 2;
      q[3][k] = m0 + 0.01 * (q[3][k] - m0), q[0][k] = m0 + 0.01 * (q[0][k] - m0);
      q[2][k] = m1 + 0.01 * (q[2][k] - m1), q[1][k] = m1 + 0.01 * (q[1][k] - m1);
    }
  }
}
#endif

#endif
