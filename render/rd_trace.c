/* rd_trace.c - ray casting (triangles: Moeller-Trumbore in double; spheres: the stable
 * quadratic), the procedural normal map, and the G-buffers of the camera and of light views. */
#include "rd.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static void cross3(const double a[3], const double b[3], double o[3]) {
  o[0] = a[1] * b[2] - a[2] * b[1];
  o[1] = a[2] * b[0] - a[0] * b[2];
  o[2] = a[0] * b[1] - a[1] * b[0];
}
static void normf(float v[3]) {
  double l = sqrt((double)v[0] * v[0] + (double)v[1] * v[1] + (double)v[2] * v[2]);
  if (l > 0) {
    v[0] = (float)(v[0] / l);
    v[1] = (float)(v[1] / l);
    v[2] = (float)(v[2] / l);
  } else {
    v[0] = v[1] = 0.0f;
    v[2] = 1.0f;
  }
}

/* Procedural normal map: bumps of slope amp * sin(2 pi f u) along the two tangents of a
 * frame built from the unperturbed normal (Duff et al. 2017), u the position along them. */
static void bump(const rd_material *m, const float p[3], const float ng[3], float n[3]) {
  float t1[3], t2[3], s = ng[2] >= 0 ? 1.0f : -1.0f, a = -1.0f / (s + ng[2]), b = ng[0] * ng[1] * a,
                      u, v, su, sv;
  const float tau = 6.2831853f;
  t1[0] = 1.0f + s * ng[0] * ng[0] * a;
  t1[1] = s * b;
  t1[2] = -s * ng[0];
  t2[0] = b;
  t2[1] = s + ng[1] * ng[1] * a;
  t2[2] = -ng[1];
  u = rd_dot(p, t1);
  v = rd_dot(p, t2);
  su = m->bump_amp * sinf(tau * m->bump_freq * u) * cosf(0.5f * tau * m->bump_freq * v);
  sv = m->bump_amp * sinf(tau * m->bump_freq * v) * cosf(0.5f * tau * m->bump_freq * u);
  n[0] = ng[0] + su * t1[0] + sv * t2[0];
  n[1] = ng[1] + su * t1[1] + sv * t2[1];
  n[2] = ng[2] + su * t1[2] + sv * t2[2];
  normf(n);
}

int rd_trace(const rd_scene *s, const float o[3], const float d[3], float tmin, float tmax,
             rd_hit *h) {
  double best = tmax, bu = 0, bv = 0;
  int bi = -1, bs = -1, i;
  for (i = 0; i < s->ntris; i++) {
    const rd_tri *t = &s->tris[i];
    double e1[3], e2[3], pv[3], tv[3], qv[3], det, u, v, tt, dd[3] = {d[0], d[1], d[2]};
    int k;
    for (k = 0; k < 3; k++) {
      e1[k] = (double)t->p[1][k] - t->p[0][k];
      e2[k] = (double)t->p[2][k] - t->p[0][k];
      tv[k] = (double)o[k] - t->p[0][k];
    }
    cross3(dd, e2, pv);
    det = e1[0] * pv[0] + e1[1] * pv[1] + e1[2] * pv[2];
    if (fabs(det) < 1e-300) continue;
    u = (tv[0] * pv[0] + tv[1] * pv[1] + tv[2] * pv[2]) / det;
    if (u < 0 || u > 1) continue;
    cross3(tv, e1, qv);
    v = (dd[0] * qv[0] + dd[1] * qv[1] + dd[2] * qv[2]) / det;
    if (v < 0 || u + v > 1) continue;
    tt = (e2[0] * qv[0] + e2[1] * qv[1] + e2[2] * qv[2]) / det;
    if (tt > tmin && tt < best) {
      best = tt;
      bi = i;
      bu = u;
      bv = v;
    }
  }
  for (i = 0; i < s->nspheres; i++) {
    const rd_sphere *sp = &s->spheres[i];
    double oc[3] = {(double)o[0] - sp->c[0], (double)o[1] - sp->c[1], (double)o[2] - sp->c[2]};
    double b = oc[0] * d[0] + oc[1] * d[1] + oc[2] * d[2];
    /* c - b^2 in the form that keeps precision for far spheres: |oc - b d|^2 - r^2 */
    double q[3] = {oc[0] - b * d[0], oc[1] - b * d[1], oc[2] - b * d[2]};
    double disc = (double)sp->r * sp->r - (q[0] * q[0] + q[1] * q[1] + q[2] * q[2]), sq, tt;
    if (disc < 0) continue;
    sq = sqrt(disc);
    tt = -b - sq;
    if (!(tt > tmin)) tt = -b + sq;
    if (tt > tmin && tt < best) {
      best = tt;
      bs = i;
      bi = -1;
    }
  }
  if (bi < 0 && bs < 0) return 0;
  if (h) {
    int k;
    float gn[3];
    h->t = (float)best;
    for (k = 0; k < 3; k++)
      h->p[k] = (float)((double)o[k] + best * d[k]);
    if (bs >= 0) {
      const rd_sphere *sp = &s->spheres[bs];
      for (k = 0; k < 3; k++)
        gn[k] = h->ng[k] = (h->p[k] - sp->c[k]) / sp->r;
      h->mat = sp->mat;
    } else {
      const rd_tri *t = &s->tris[bi];
      double e1[3], e2[3], fn[3];
      for (k = 0; k < 3; k++) {
        e1[k] = (double)t->p[1][k] - t->p[0][k];
        e2[k] = (double)t->p[2][k] - t->p[0][k];
        h->ng[k] = (float)((1 - bu - bv) * t->n[0][k] + bu * t->n[1][k] + bv * t->n[2][k]);
      }
      cross3(e1, e2, fn);
      for (k = 0; k < 3; k++)
        gn[k] = (float)fn[k];
      h->mat = t->mat;
    }
    normf(gn);
    normf(h->ng);
    /* two-sided: the normals face the ray's origin */
    if (rd_dot(gn, d) > 0)
      for (k = 0; k < 3; k++)
        gn[k] = -gn[k];
    if (rd_dot(h->ng, gn) < 0)
      for (k = 0; k < 3; k++)
        h->ng[k] = -h->ng[k];
    if (h->mat >= 0 && h->mat < s->nmats && s->mats[h->mat].bump_freq > 0)
      bump(&s->mats[h->mat], h->p, h->ng, h->n);
    else
      memcpy(h->n, h->ng, sizeof h->n);
  }
  return 1;
}

void rd_gbuf_free(rd_gbuf *g) {
  free(g->pos);
  free(g->nrm);
  free(g->gnrm);
  free(g->depth);
  free(g->mat);
  memset(g, 0, sizeof *g);
}

int rd_gbuffer_view(const rd_scene *s, const float eye[3], const float dir[3], const float up[3],
                    float fov_y, int w, int h, rd_gbuf *g) {
  float f[3] = {dir[0], dir[1], dir[2]}, r[3], u[3], th = tanf(0.5f * fov_y);
  size_t n = (size_t)w * (size_t)h;
  int x, y, k;
  memset(g, 0, sizeof *g);
  if (w <= 0 || h <= 0 || w > 16384 || h > 16384 || !(th > 0) || !isfinite(th)) return -1;
  normf(f);
  r[0] = f[1] * up[2] - f[2] * up[1];
  r[1] = f[2] * up[0] - f[0] * up[2];
  r[2] = f[0] * up[1] - f[1] * up[0];
  if (rd_dot(r, r) < 1e-12f) { /* up parallel to dir: any perpendicular */
    float a[3] = {fabsf(f[0]) < 0.9f ? 1.0f : 0.0f, fabsf(f[0]) < 0.9f ? 0.0f : 1.0f, 0.0f};
    r[0] = f[1] * a[2] - f[2] * a[1];
    r[1] = f[2] * a[0] - f[0] * a[2];
    r[2] = f[0] * a[1] - f[1] * a[0];
  }
  normf(r);
  u[0] = r[1] * f[2] - r[2] * f[1];
  u[1] = r[2] * f[0] - r[0] * f[2];
  u[2] = r[0] * f[1] - r[1] * f[0];
  g->w = w;
  g->h = h;
  memcpy(g->eye, eye, sizeof g->eye);
  g->pos = (float *)malloc(n * 3 * sizeof(float));
  g->nrm = (float *)malloc(n * 3 * sizeof(float));
  g->gnrm = (float *)malloc(n * 3 * sizeof(float));
  g->depth = (float *)malloc(n * sizeof(float));
  g->mat = (int *)malloc(n * sizeof(int));
  if (!g->pos || !g->nrm || !g->gnrm || !g->depth || !g->mat) {
    rd_gbuf_free(g);
    return -1;
  }
  for (y = 0; y < h; y++) {
    for (x = 0; x < w; x++) {
      size_t i = (size_t)y * (size_t)w + (size_t)x;
      float sx = (2.0f * ((float)x + 0.5f) / (float)w - 1.0f) * th * (float)w / (float)h;
      float sy = (1.0f - 2.0f * ((float)y + 0.5f) / (float)h) * th, d[3];
      rd_hit hit;
      for (k = 0; k < 3; k++)
        d[k] = f[k] + sx * r[k] + sy * u[k];
      normf(d);
      if (rd_trace(s, eye, d, 1e-6f, INFINITY, &hit)) {
        memcpy(g->pos + 3 * i, hit.p, sizeof hit.p);
        memcpy(g->nrm + 3 * i, hit.n, sizeof hit.n);
        memcpy(g->gnrm + 3 * i, hit.ng, sizeof hit.ng);
        g->depth[i] = hit.t;
        g->mat[i] = hit.mat;
      } else {
        memset(g->pos + 3 * i, 0, 3 * sizeof(float));
        memset(g->nrm + 3 * i, 0, 3 * sizeof(float));
        memset(g->gnrm + 3 * i, 0, 3 * sizeof(float));
        g->depth[i] = -1.0f;
        g->mat[i] = -1;
      }
    }
    rd_progress("g-buffer", y + 1, h);
  }
  return 0;
}

int rd_gbuffer(const rd_scene *s, int w, int h, rd_gbuf *g) {
  float d[3];
  int k;
  for (k = 0; k < 3; k++)
    d[k] = s->cam.target[k] - s->cam.eye[k];
  return rd_gbuffer_view(s, s->cam.eye, d, s->cam.up, s->cam.fov_y, w, h, g);
}
