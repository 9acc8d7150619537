/* rd_scene.c - scenes: the text format, a Wavefront OBJ loader and the built-in scenes.
 *
 * Text format: one directive per line, '#' starts a comment, numbers are decimal floats.
 *   camera  ex ey ez  tx ty tz  ux uy uz  fov_deg        (vertical field of view)
 *   bands   n                                            (SH bands of the SH passes, 1..16)
 *   material name kd r g b [ks r g b] [phong e] [ggx alpha] [bumps freq amp]
 *   sphere  x y z r  mat
 *   triangle  x y z  x y z  x y z  mat
 *   quad    x y z  x y z  x y z  x y z  mat            (two triangles, vertices in order)
 *   obj     file.obj mat [scale s] [translate x y z]   (v / vn / f; path relative to the scene)
 *   light sphere   x y z r                 radiance r g b
 *   light triangle x y z x y z x y z       radiance r g b
 *   light polygon  N  x y z (N times)      radiance r g b   (3 <= N <= 8, planar)
 *   light disc     cx cy cz nx ny nz r     radiance r g b
 *   light spot     px py pz dx dy dz half_angle_deg  intensity r g b
 * Materials are referred to by name after their definition. Errors stop the load with
 * "file:line: message"; nothing is half-loaded. */
#include "rd.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define RD_MAX_TRIS 4000000
#define RD_MAX_ITEMS 100000

typedef struct {
  const char *file;
  int line;
  char *err;
  size_t errlen;
} perr;

static int fail(perr *e, const char *fmt, ...) {
  va_list ap;
  int k = snprintf(e->err, e->errlen, "%s:%d: ", e->file, e->line);
  va_start(ap, fmt);
  if (k >= 0 && (size_t)k < e->errlen) vsnprintf(e->err + k, e->errlen - (size_t)k, fmt, ap);
  va_end(ap);
  return -1;
}

static int grow(void **p, int n, int *cap, size_t elem) {
  void *q;
  int c;
  if (n < *cap) return 0;
  c = *cap ? 2 * *cap : 16;
  q = realloc(*p, (size_t)c * elem);
  if (!q) return -1;
  *p = q;
  *cap = c;
  return 0;
}

typedef struct {
  rd_scene *s;
  int capm, capt, caps, capl;
} builder;

static int add_mat(builder *b, const rd_material *m) {
  if (b->s->nmats >= RD_MAX_ITEMS || grow((void **)&b->s->mats, b->s->nmats, &b->capm, sizeof *m))
    return -1;
  b->s->mats[b->s->nmats] = *m;
  return b->s->nmats++;
}
static int add_tri(builder *b, const float p0[3], const float p1[3], const float p2[3],
                   const float (*n)[3], int mat) {
  rd_tri *t;
  int k;
  if (b->s->ntris >= RD_MAX_TRIS || grow((void **)&b->s->tris, b->s->ntris, &b->capt, sizeof *t))
    return -1;
  t = &b->s->tris[b->s->ntris++];
  for (k = 0; k < 3; k++) {
    t->p[0][k] = p0[k];
    t->p[1][k] = p1[k];
    t->p[2][k] = p2[k];
  }
  if (n)
    memcpy(t->n, n, sizeof t->n);
  else {
    double e1[3], e2[3], c[3], l;
    for (k = 0; k < 3; k++) {
      e1[k] = (double)p1[k] - p0[k];
      e2[k] = (double)p2[k] - p0[k];
    }
    c[0] = e1[1] * e2[2] - e1[2] * e2[1];
    c[1] = e1[2] * e2[0] - e1[0] * e2[2];
    c[2] = e1[0] * e2[1] - e1[1] * e2[0];
    l = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    for (k = 0; k < 3; k++)
      t->n[0][k] = t->n[1][k] = t->n[2][k] = l > 0 ? (float)(c[k] / l) : (k == 2 ? 1.0f : 0.0f);
  }
  t->mat = mat;
  return 0;
}
static int add_quad(builder *b, const float p0[3], const float p1[3], const float p2[3],
                    const float p3[3], int mat) {
  return add_tri(b, p0, p1, p2, NULL, mat) || add_tri(b, p0, p2, p3, NULL, mat) ? -1 : 0;
}
static int add_sphere(builder *b, const float c[3], float r, int mat) {
  rd_sphere *sp;
  if (b->s->nspheres >= RD_MAX_ITEMS ||
      grow((void **)&b->s->spheres, b->s->nspheres, &b->caps, sizeof *sp))
    return -1;
  sp = &b->s->spheres[b->s->nspheres++];
  memcpy(sp->c, c, sizeof sp->c);
  sp->r = r;
  sp->mat = mat;
  return 0;
}
static int add_light(builder *b, const rd_light *l) {
  if (b->s->nlights >= RD_MAX_ITEMS ||
      grow((void **)&b->s->lights, b->s->nlights, &b->capl, sizeof *l))
    return -1;
  b->s->lights[b->s->nlights++] = *l;
  return 0;
}

void rd_scene_free(rd_scene *s) {
  free(s->mats);
  free(s->tris);
  free(s->spheres);
  free(s->lights);
  memset(s, 0, sizeof *s);
}

static void ext(rd_scene *s, const float p[3], float r) {
  int k;
  for (k = 0; k < 3; k++) {
    if (p[k] - r < s->bmin[k]) s->bmin[k] = p[k] - r;
    if (p[k] + r > s->bmax[k]) s->bmax[k] = p[k] + r;
  }
}
void rd_scene_finish(rd_scene *s) {
  int i, k;
  for (k = 0; k < 3; k++) {
    s->bmin[k] = INFINITY;
    s->bmax[k] = -INFINITY;
  }
  for (i = 0; i < s->ntris; i++)
    for (k = 0; k < 3; k++)
      ext(s, s->tris[i].p[k], 0);
  for (i = 0; i < s->nspheres; i++)
    ext(s, s->spheres[i].c, s->spheres[i].r);
  for (i = 0; i < s->nlights; i++) {
    const rd_light *l = &s->lights[i];
    if (l->type == RD_LIGHT_TRIANGLE || l->type == RD_LIGHT_POLYGON)
      for (k = 0; k < l->nv; k++)
        ext(s, l->v[k], 0);
    else
      ext(s, l->c, l->type == RD_LIGHT_SPOT ? 0 : l->r);
  }
  if (!(s->bmin[0] <= s->bmax[0]))
    for (k = 0; k < 3; k++)
      s->bmin[k] = s->bmax[k] = 0;
}

/* ---- tokenizer ------------------------------------------------------------------------- */
typedef struct {
  const char *p, *end;
} toks;
/* next token into buf (at most n-1 chars); returns 0 at the end of the line */
static int tok(toks *t, char *buf, size_t n) {
  size_t k = 0;
  while (t->p < t->end && (*t->p == ' ' || *t->p == '\t' || *t->p == '\r'))
    t->p++;
  if (t->p >= t->end || *t->p == '#') return 0;
  while (t->p < t->end && !isspace((unsigned char)*t->p)) {
    if (k + 1 < n) buf[k++] = *t->p;
    t->p++;
  }
  buf[k] = 0;
  return 1;
}
static int num(toks *t, perr *e, const char *what, float *out) {
  char b[64], *end;
  double v;
  if (!tok(t, b, sizeof b)) return fail(e, "missing %s", what);
  errno = 0;
  v = strtod(b, &end);
  if (*end || end == b) return fail(e, "%s: not a number: '%s'", what, b);
  if (!isfinite(v) || fabs(v) > 1e30) return fail(e, "%s: out of range: '%s'", what, b);
  *out = (float)v;
  return 0;
}
static int vec(toks *t, perr *e, const char *what, float v[3]) {
  return num(t, e, what, v) || num(t, e, what, v + 1) || num(t, e, what, v + 2) ? -1 : 0;
}
static int find_mat(const rd_scene *s, const char *name) {
  int i;
  for (i = 0; i < s->nmats; i++)
    if (!strcmp(s->mats[i].name, name)) return i;
  return -1;
}
static int mat_ref(toks *t, perr *e, const rd_scene *s, int *m) {
  char b[64];
  if (!tok(t, b, sizeof b)) return fail(e, "missing material name");
  if ((*m = find_mat(s, b)) < 0) return fail(e, "unknown material '%s'", b);
  return 0;
}
static int end_of_line(toks *t, perr *e) {
  char b[64];
  if (tok(t, b, sizeof b)) return fail(e, "unexpected '%s'", b);
  return 0;
}
static int nonneg3(perr *e, const char *what, const float v[3], float hi) {
  if (v[0] < 0 || v[1] < 0 || v[2] < 0 || v[0] > hi || v[1] > hi || v[2] > hi)
    return fail(e, "%s must be in [0, %g]", what, (double)hi);
  return 0;
}

static int load_obj(builder *b, const char *path, int mat, float scale, const float tr[3], perr *e);

static int parse_line(builder *b, toks *t, const char *dir, perr *e) {
  rd_scene *s = b->s;
  char kw[32];
  if (!tok(t, kw, sizeof kw)) return 0;
  if (!strcmp(kw, "camera")) {
    float fov;
    if (vec(t, e, "camera eye", s->cam.eye) || vec(t, e, "camera target", s->cam.target) ||
        vec(t, e, "camera up", s->cam.up) || num(t, e, "camera fov", &fov))
      return -1;
    if (!(fov > 0.1f && fov < 179.0f)) return fail(e, "camera fov must be in (0.1, 179) degrees");
    s->cam.fov_y = fov * 3.14159265f / 180.0f;
    return end_of_line(t, e);
  }
  if (!strcmp(kw, "bands")) {
    float n;
    if (num(t, e, "bands", &n)) return -1;
    if (n != floorf(n) || n < 1 || n > 16) return fail(e, "bands must be an integer in [1, 16]");
    s->bands = (int)n;
    return end_of_line(t, e);
  }
  if (!strcmp(kw, "material")) {
    rd_material m;
    char w[64];
    memset(&m, 0, sizeof m);
    if (!tok(t, w, sizeof w)) return fail(e, "missing material name");
    if (strlen(w) >= sizeof m.name)
      return fail(e, "material name longer than %d characters", (int)sizeof m.name - 1);
    if (find_mat(s, w) >= 0) return fail(e, "material '%s' defined twice", w);
    snprintf(m.name, sizeof m.name, "%s", w);
    while (tok(t, w, sizeof w)) {
      if (!strcmp(w, "kd")) {
        if (vec(t, e, "kd", m.kd) || nonneg3(e, "kd", m.kd, 1)) return -1;
      } else if (!strcmp(w, "ks")) {
        if (vec(t, e, "ks", m.ks) || nonneg3(e, "ks", m.ks, 1)) return -1;
      } else if (!strcmp(w, "phong")) {
        if (num(t, e, "phong exponent", &m.exponent)) return -1;
        if (!(m.exponent >= 0 && m.exponent <= 1e4f))
          return fail(e, "phong exponent must be in [0, 1e4]");
        m.brdf = RD_BRDF_PHONG;
      } else if (!strcmp(w, "ggx")) {
        if (num(t, e, "ggx roughness", &m.roughness)) return -1;
        if (!(m.roughness >= 1e-3f && m.roughness <= 1))
          return fail(e, "ggx roughness must be in [1e-3, 1]");
        m.brdf = RD_BRDF_GGX;
      } else if (!strcmp(w, "bumps")) {
        if (num(t, e, "bump frequency", &m.bump_freq) || num(t, e, "bump amplitude", &m.bump_amp))
          return -1;
        if (!(m.bump_freq >= 0 && m.bump_freq <= 1e4f && m.bump_amp >= 0 && m.bump_amp <= 10))
          return fail(e, "bumps: frequency in [0, 1e4], amplitude in [0, 10]");
      } else
        return fail(e, "unknown material attribute '%s'", w);
    }
    if (m.kd[0] + m.ks[0] > 1 || m.kd[1] + m.ks[1] > 1 || m.kd[2] + m.ks[2] > 1)
      return fail(e, "kd + ks must not exceed 1 (energy conservation)");
    return add_mat(b, &m) < 0 ? fail(e, "too many materials") : 0;
  }
  if (!strcmp(kw, "sphere")) {
    float c[3], r;
    int m;
    if (vec(t, e, "sphere centre", c) || num(t, e, "sphere radius", &r) || mat_ref(t, e, s, &m))
      return -1;
    if (!(r > 0)) return fail(e, "sphere radius must be > 0");
    return end_of_line(t, e) ? -1 : add_sphere(b, c, r, m) ? fail(e, "too many spheres") : 0;
  }
  if (!strcmp(kw, "triangle") || !strcmp(kw, "quad")) {
    float p[4][3];
    int nv = kw[0] == 't' ? 3 : 4, k, m;
    for (k = 0; k < nv; k++)
      if (vec(t, e, "vertex", p[k])) return -1;
    if (mat_ref(t, e, s, &m) || end_of_line(t, e)) return -1;
    if (nv == 3 ? add_tri(b, p[0], p[1], p[2], NULL, m) : add_quad(b, p[0], p[1], p[2], p[3], m))
      return fail(e, "too many triangles");
    return 0;
  }
  if (!strcmp(kw, "obj")) {
    char f[512], w[32], full[1024];
    float sc = 1, tr[3] = {0, 0, 0};
    int m;
    if (!tok(t, f, sizeof f)) return fail(e, "missing obj file name");
    if (mat_ref(t, e, s, &m)) return -1;
    while (tok(t, w, sizeof w)) {
      if (!strcmp(w, "scale")) {
        if (num(t, e, "scale", &sc)) return -1;
        if (!(sc > 0)) return fail(e, "scale must be > 0");
      } else if (!strcmp(w, "translate")) {
        if (vec(t, e, "translate", tr)) return -1;
      } else
        return fail(e, "unknown obj option '%s'", w);
    }
    if (!dir) return fail(e, "obj: this scene text has no folder to read files from");
    if (f[0] == '/' || !dir[0])
      snprintf(full, sizeof full, "%s", f);
    else
      snprintf(full, sizeof full, "%s/%s", dir, f);
    return load_obj(b, full, m, sc, tr, e);
  }
  if (!strcmp(kw, "light")) {
    rd_light l;
    char ty[32], w[32];
    memset(&l, 0, sizeof l);
    if (!tok(t, ty, sizeof ty)) return fail(e, "missing light type");
    if (!strcmp(ty, "sphere")) {
      l.type = RD_LIGHT_SPHERE;
      if (vec(t, e, "light centre", l.c) || num(t, e, "light radius", &l.r)) return -1;
      if (!(l.r > 0)) return fail(e, "light radius must be > 0");
    } else if (!strcmp(ty, "triangle")) {
      int k;
      l.type = RD_LIGHT_TRIANGLE;
      l.nv = 3;
      for (k = 0; k < 3; k++)
        if (vec(t, e, "light vertex", l.v[k])) return -1;
    } else if (!strcmp(ty, "polygon")) {
      float nv;
      int k;
      l.type = RD_LIGHT_POLYGON;
      if (num(t, e, "polygon vertex count", &nv)) return -1;
      if (nv != floorf(nv) || nv < 3 || nv > RD_MAX_POLY)
        return fail(e, "polygon vertex count must be an integer in [3, %d]", RD_MAX_POLY);
      l.nv = (int)nv;
      for (k = 0; k < l.nv; k++)
        if (vec(t, e, "light vertex", l.v[k])) return -1;
    } else if (!strcmp(ty, "disc")) {
      l.type = RD_LIGHT_DISC;
      if (vec(t, e, "disc centre", l.c) || vec(t, e, "disc normal", l.n) ||
          num(t, e, "disc radius", &l.r))
        return -1;
      if (!(rd_dot(l.n, l.n) > 1e-12f)) return fail(e, "disc normal must be non-zero");
      if (!(l.r > 0)) return fail(e, "disc radius must be > 0");
    } else if (!strcmp(ty, "spot")) {
      float a;
      l.type = RD_LIGHT_SPOT;
      if (vec(t, e, "spot position", l.c) || vec(t, e, "spot direction", l.n) ||
          num(t, e, "spot half-angle", &a))
        return -1;
      if (!(rd_dot(l.n, l.n) > 1e-12f)) return fail(e, "spot direction must be non-zero");
      if (!(a > 0.5f && a < 89.5f))
        return fail(e, "spot half-angle must be in (0.5, 89.5) degrees");
      l.angle = a * 3.14159265f / 180.0f;
    } else
      return fail(e, "unknown light type '%s' (sphere, triangle, polygon, disc, spot)", ty);
    if (!tok(t, w, sizeof w) || strcmp(w, l.type == RD_LIGHT_SPOT ? "intensity" : "radiance"))
      return fail(e, "expected '%s r g b'", l.type == RD_LIGHT_SPOT ? "intensity" : "radiance");
    if (vec(t, e, "light colour", l.radiance) || nonneg3(e, "light colour", l.radiance, 1e12f) ||
        end_of_line(t, e))
      return -1;
    if (l.type == RD_LIGHT_DISC || l.type == RD_LIGHT_SPOT) { /* in double: no overflow */
      double len =
          sqrt((double)l.n[0] * l.n[0] + (double)l.n[1] * l.n[1] + (double)l.n[2] * l.n[2]);
      l.n[0] = (float)(l.n[0] / len);
      l.n[1] = (float)(l.n[1] / len);
      l.n[2] = (float)(l.n[2] / len);
    }
    return add_light(b, &l) ? fail(e, "too many lights") : 0;
  }
  return fail(e, "unknown directive '%s'", kw);
}

static void scene_defaults(rd_scene *s, const char *name) {
  memset(s, 0, sizeof *s);
  snprintf(s->name, sizeof s->name, "%s", name);
  s->bands = 5;
  s->cam.eye[2] = 3;
  s->cam.up[1] = 1;
  s->cam.fov_y = 45.0f * 3.14159265f / 180.0f;
}

int rd_scene_parse(const char *text, size_t len, const char *dir, const char *name, rd_scene *out,
                   char *err, size_t errlen) {
  builder b;
  perr e;
  const char *p = text, *end = text + len;
  e.file = name;
  e.line = 0;
  e.err = err;
  e.errlen = errlen;
  memset(&b, 0, sizeof b);
  scene_defaults(out, name);
  b.s = out;
  while (p < end) {
    const char *nl = (const char *)memchr(p, '\n', (size_t)(end - p));
    toks t;
    t.p = p;
    t.end = nl ? nl : end;
    e.line++;
    if (memchr(p, 0, (size_t)(t.end - p))) {
      fail(&e, "NUL byte in scene text");
      rd_scene_free(out);
      return -1;
    }
    if (parse_line(&b, &t, dir, &e)) {
      rd_scene_free(out);
      return -1;
    }
    p = nl ? nl + 1 : end;
  }
  if (out->ntris + out->nspheres == 0) {
    e.line = 0;
    snprintf(err, errlen, "%s: the scene has no geometry (sphere, triangle, quad or obj)", name);
    rd_scene_free(out);
    return -1;
  }
  rd_scene_finish(out);
  return 0;
}

static char *read_file(const char *path, size_t *n) {
  FILE *f = fopen(path, "rb");
  char *buf = NULL;
  size_t cap = 0, len = 0;
  if (!f) return NULL;
  for (;;) {
    size_t got;
    if (len + 65536 > cap) {
      char *q;
      if (cap > ((size_t)1 << 30)) { /* 1 GiB: refuse */
        free(buf);
        fclose(f);
        return NULL;
      }
      cap = cap ? 2 * cap : 65536 * 2;
      q = (char *)realloc(buf, cap);
      if (!q) {
        free(buf);
        fclose(f);
        return NULL;
      }
      buf = q;
    }
    got = fread(buf + len, 1, cap - len, f);
    len += got;
    if (got == 0) break;
  }
  fclose(f);
  *n = len;
  return buf;
}

int rd_scene_load(const char *path, rd_scene *out, char *err, size_t errlen) {
  size_t n = 0;
  char *text = read_file(path, &n), dir[512];
  const char *slash = strrchr(path, '/'), *base = slash ? slash + 1 : path;
  char name[64];
  int rc;
  size_t k;
  if (!text) {
    snprintf(err, errlen, "%s: cannot read the file", path);
    memset(out, 0, sizeof *out);
    return -1;
  }
  snprintf(dir, sizeof dir, "%.*s", slash ? (int)(slash - path) : 0, path);
  snprintf(name, sizeof name, "%s", base);
  for (k = 0; name[k]; k++)
    if (name[k] == '.') name[k] = 0;
  rc = rd_scene_parse(text, n, dir, path, out, err, errlen);
  if (!rc) snprintf(out->name, sizeof out->name, "%s", name);
  free(text);
  return rc;
}

/* ---- OBJ: v, vn, f (v, v/vt, v//vn, v/vt/vn; negative indices), polygons fan-triangulated */
static int obj_index(const char *s, int n, int *out) {
  char *end;
  long v = strtol(s, &end, 10);
  if (end == s) return -1;
  if (v < 0) v += n + 1;
  if (v < 1 || v > n) return -1;
  *out = (int)v - 1;
  return 0;
}
static int load_obj(builder *b, const char *path, int mat, float scale, const float tr[3],
                    perr *e) {
  size_t len = 0;
  char *text = read_file(path, &len);
  float(*v)[3] = NULL, (*vn)[3] = NULL;
  int nv = 0, nn = 0, capv = 0, capn = 0, line = 0, rc = 0;
  const char *p, *end;
  if (!text) return fail(e, "cannot read obj file '%s'", path);
  p = text;
  end = text + len;
  while (p < end && !rc) {
    const char *nl = (const char *)memchr(p, '\n', (size_t)(end - p));
    toks t;
    char kw[16];
    t.p = p;
    t.end = nl ? nl : end;
    line++;
    if (tok(&t, kw, sizeof kw)) {
      if (!strcmp(kw, "v") || !strcmp(kw, "vn")) {
        float x[3];
        int isn = kw[1] == 'n';
        if (vec(&t, e, isn ? "obj normal" : "obj vertex", x))
          rc = -1;
        else if (grow(isn ? (void **)&vn : (void **)&v, isn ? nn : nv, isn ? &capn : &capv,
                      sizeof x) ||
                 (isn ? nn : nv) >= RD_MAX_TRIS)
          rc = fail(e, "%s:%d: too many vertices", path, line);
        else if (isn)
          memcpy(vn[nn++], x, sizeof x);
        else {
          v[nv][0] = x[0] * scale + tr[0];
          v[nv][1] = x[1] * scale + tr[1];
          v[nv][2] = x[2] * scale + tr[2];
          nv++;
        }
      } else if (!strcmp(kw, "f")) {
        int vi[64], ni[64], k = 0, hasn = 1;
        char w[64];
        while (tok(&t, w, sizeof w)) {
          const char *s1 = strchr(w, '/'), *s2 = s1 ? strchr(s1 + 1, '/') : NULL;
          if (k >= 64) {
            rc = fail(e, "%s:%d: face with more than 64 vertices", path, line);
            break;
          }
          if (obj_index(w, nv, &vi[k])) {
            rc = fail(e, "%s:%d: bad vertex index '%s'", path, line, w);
            break;
          }
          if (s2 && s2[1]) {
            if (obj_index(s2 + 1, nn, &ni[k])) {
              rc = fail(e, "%s:%d: bad normal index '%s'", path, line, w);
              break;
            }
          } else
            hasn = 0;
          k++;
        }
        if (!rc && k < 3) rc = fail(e, "%s:%d: face with fewer than 3 vertices", path, line);
        for (int j = 1; !rc && j + 1 < k; j++) {
          float nrm[3][3];
          int q;
          if (hasn)
            for (q = 0; q < 3; q++) {
              int id = ni[q == 0 ? 0 : j + q - 1];
              float l = sqrtf(rd_dot(vn[id], vn[id]));
              nrm[q][0] = l > 0 ? vn[id][0] / l : 0;
              nrm[q][1] = l > 0 ? vn[id][1] / l : 0;
              nrm[q][2] = l > 0 ? vn[id][2] / l : 1;
            }
          if (add_tri(b, v[vi[0]], v[vi[j]], v[vi[j + 1]], hasn ? (const float(*)[3])nrm : NULL,
                      mat))
            rc = fail(e, "%s:%d: too many triangles", path, line);
        }
      }
      /* other statements (vt, o, g, s, usemtl, mtllib, l, p) are ignored */
    }
    p = nl ? nl + 1 : end;
  }
  free(v);
  free(vn);
  free(text);
  return rc;
}

/* ---- built-in scenes ---------------------------------------------------------------------- */
static int mk_mat(builder *b, const char *name, float r, float g, float bl) {
  rd_material m;
  memset(&m, 0, sizeof m);
  snprintf(m.name, sizeof m.name, "%s", name);
  m.kd[0] = r;
  m.kd[1] = g;
  m.kd[2] = bl;
  return add_mat(b, &m);
}
static void P(float p[3], float x, float y, float z) {
  p[0] = x;
  p[1] = y;
  p[2] = z;
}
static int box_quad(builder *b, float x0, float y0, float z0, float x1, float y1, float z1,
                    float x2, float y2, float z2, float x3, float y3, float z3, int m) {
  float a[3], c[3], d[3], e[3];
  P(a, x0, y0, z0);
  P(c, x1, y1, z1);
  P(d, x2, y2, z2);
  P(e, x3, y3, z3);
  return add_quad(b, a, c, d, e, m);
}
/* axis-aligned box [lo, hi], rotated by `ang` about the vertical through its centre */
static int add_box(builder *b, const float lo[3], const float hi[3], float ang, int m) {
  float c[8][3], cx = 0.5f * (lo[0] + hi[0]), cz = 0.5f * (lo[2] + hi[2]), cs = cosf(ang),
                 sn = sinf(ang);
  static const int f[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                              {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
  int i;
  for (i = 0; i < 8; i++) {
    float x = (i & 1) ? hi[0] : lo[0], y = (i & 2) ? hi[1] : lo[1], z = (i & 4) ? hi[2] : lo[2];
    c[i][0] = cx + cs * (x - cx) - sn * (z - cz);
    c[i][1] = y;
    c[i][2] = cz + sn * (x - cx) + cs * (z - cz);
  }
  for (i = 0; i < 6; i++)
    if (add_quad(b, c[f[i][0]], c[f[i][1]], c[f[i][2]], c[f[i][3]], m)) return -1;
  return 0;
}
static int add_torus(builder *b, const float c[3], float R, float r, int nu, int nv, int m) {
  int i, j;
  const float tau = 6.2831853f;
  for (i = 0; i < nu; i++)
    for (j = 0; j < nv; j++) {
      float p[4][3], n[4][3];
      int k;
      for (k = 0; k < 4; k++) {
        float u = tau * (float)(i + (k == 1 || k == 2)) / (float)nu;
        float v = tau * (float)(j + (k >= 2)) / (float)nv;
        n[k][0] = cosf(v) * cosf(u);
        n[k][1] = sinf(v);
        n[k][2] = cosf(v) * sinf(u);
        p[k][0] = c[0] + (R + r * cosf(v)) * cosf(u);
        p[k][1] = c[1] + r * sinf(v);
        p[k][2] = c[2] + (R + r * cosf(v)) * sinf(u);
      }
      {
        float n0[3][3] = {
            {n[0][0], n[0][1], n[0][2]}, {n[1][0], n[1][1], n[1][2]}, {n[2][0], n[2][1], n[2][2]}};
        float n1[3][3] = {
            {n[0][0], n[0][1], n[0][2]}, {n[2][0], n[2][1], n[2][2]}, {n[3][0], n[3][1], n[3][2]}};
        if (add_tri(b, p[0], p[1], p[2], (const float(*)[3])n0, m) ||
            add_tri(b, p[0], p[2], p[3], (const float(*)[3])n1, m))
          return -1;
      }
    }
  return 0;
}
static void camera(rd_scene *s, float ex, float ey, float ez, float tx, float ty, float tz,
                   float fov_deg) {
  P(s->cam.eye, ex, ey, ez);
  P(s->cam.target, tx, ty, tz);
  P(s->cam.up, 0, 1, 0);
  s->cam.fov_y = fov_deg * 3.14159265f / 180.0f;
}
static rd_light light_sphere(float x, float y, float z, float r, float cr, float cg, float cb) {
  rd_light l;
  memset(&l, 0, sizeof l);
  l.type = RD_LIGHT_SPHERE;
  P(l.c, x, y, z);
  l.r = r;
  P(l.radiance, cr, cg, cb);
  return l;
}

/* Cornell-like box [0,1]^3 open towards -z; spot light under the ceiling (RSM passes), a
 * ceiling quad light (area pass) and two small sphere lights (grid pass); normal-mapped
 * floor. */
static int build_cornell(builder *b) {
  rd_scene *s = b->s;
  int white = mk_mat(b, "white", 0.75f, 0.75f, 0.75f), red = mk_mat(b, "red", 0.7f, 0.12f, 0.1f),
      green = mk_mat(b, "green", 0.12f, 0.6f, 0.15f), floor = mk_mat(b, "floor", 0.7f, 0.7f, 0.65f);
  float lo[3], hi[3];
  rd_light l;
  if (white < 0 || red < 0 || green < 0 || floor < 0) return -1;
  s->mats[floor].bump_freq = 6.0f;
  s->mats[floor].bump_amp = 0.6f;
  if (box_quad(b, 0, 0, 0, 1, 0, 0, 1, 0, 1, 0, 0, 1, floor) || /* floor */
      box_quad(b, 0, 1, 0, 0, 1, 1, 1, 1, 1, 1, 1, 0, white) || /* ceiling */
      box_quad(b, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1, white) || /* back */
      box_quad(b, 0, 0, 0, 0, 0, 1, 0, 1, 1, 0, 1, 0, green) || /* x = 0: right in the view */
      box_quad(b, 1, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, red))     /* x = 1: left */
    return -1;
  P(lo, 0.55f, 0, 0.45f);
  P(hi, 0.85f, 0.6f, 0.75f);
  if (add_box(b, lo, hi, 0.3f, white)) return -1;
  P(lo, 0.3f, 0.18f, 0.35f);
  if (add_sphere(b, lo, 0.18f, white)) return -1;
  memset(&l, 0, sizeof l);
  l.type = RD_LIGHT_SPOT;
  P(l.c, 0.5f, 0.98f, 0.5f);
  P(l.n, 0, -1, 0);
  l.angle = 60.0f * 3.14159265f / 180.0f;
  P(l.radiance, 1.0f, 0.95f, 0.85f);
  if (add_light(b, &l)) return -1;
  memset(&l, 0, sizeof l);
  l.type = RD_LIGHT_POLYGON;
  l.nv = 4;
  P(l.v[0], 0.35f, 0.995f, 0.35f);
  P(l.v[1], 0.65f, 0.995f, 0.35f);
  P(l.v[2], 0.65f, 0.995f, 0.65f);
  P(l.v[3], 0.35f, 0.995f, 0.65f);
  P(l.radiance, 4, 4, 4);
  if (add_light(b, &l)) return -1;
  l = light_sphere(0.2f, 0.8f, 0.3f, 0.05f, 20, 16, 12);
  if (add_light(b, &l)) return -1;
  l = light_sphere(0.8f, 0.85f, 0.25f, 0.04f, 12, 16, 24);
  if (add_light(b, &l)) return -1;
  camera(s, 0.5f, 0.5f, -1.2f, 0.5f, 0.5f, 0.5f, 45);
  return 0;
}

/* A plane with spheres and tori; a spot, two sphere lights and a disc. */
static int build_spheres(builder *b) {
  rd_scene *s = b->s;
  int ground = mk_mat(b, "ground", 0.6f, 0.6f, 0.6f), m1 = mk_mat(b, "blue", 0.2f, 0.3f, 0.7f),
      m2 = mk_mat(b, "orange", 0.8f, 0.45f, 0.1f), m3 = mk_mat(b, "grey", 0.5f, 0.5f, 0.5f);
  float c[3];
  rd_light l;
  if (ground < 0 || m1 < 0 || m2 < 0 || m3 < 0) return -1;
  if (box_quad(b, -4, 0, -4, -4, 0, 4, 4, 0, 4, 4, 0, -4, ground)) return -1;
  P(c, -1.2f, 0.6f, 0);
  if (add_sphere(b, c, 0.6f, m1)) return -1;
  P(c, 0.4f, 0.35f, 0.8f);
  if (add_sphere(b, c, 0.35f, m3)) return -1;
  P(c, 1.0f, 0.3f, -0.4f);
  if (add_torus(b, c, 0.55f, 0.22f, 32, 16, m2)) return -1;
  P(c, -0.2f, 0.15f, -1.2f);
  if (add_torus(b, c, 0.35f, 0.12f, 24, 12, m1)) return -1;
  l = light_sphere(-0.3f, 1.8f, 0.5f, 0.25f, 6, 6, 5);
  if (add_light(b, &l)) return -1;
  l = light_sphere(1.6f, 1.2f, 1.0f, 0.15f, 4, 6, 9);
  if (add_light(b, &l)) return -1;
  memset(&l, 0, sizeof l);
  l.type = RD_LIGHT_DISC;
  P(l.c, 0.5f, 2.2f, -0.5f);
  P(l.n, 0, -1, 0);
  l.r = 0.5f;
  P(l.radiance, 3, 3, 3);
  if (add_light(b, &l)) return -1;
  memset(&l, 0, sizeof l);
  l.type = RD_LIGHT_SPOT;
  P(l.c, 0, 3.0f, 1.5f);
  P(l.n, 0, -0.894f, -0.447f);
  l.angle = 45.0f * 3.14159265f / 180.0f;
  P(l.radiance, 10, 10, 9);
  if (add_light(b, &l)) return -1;
  camera(s, 0, 2.2f, 4.2f, 0, 0.3f, 0, 45);
  return 0;
}

/* [GRAD]'s setting: many small lights over a plane with objects: 10 x 10 sphere lights and
 * 20 triangle lights in a layer above. */
static int build_manylights(builder *b) {
  rd_scene *s = b->s;
  int ground = mk_mat(b, "ground", 0.7f, 0.7f, 0.7f), m1 = mk_mat(b, "white", 0.8f, 0.8f, 0.8f),
      m2 = mk_mat(b, "tan", 0.7f, 0.55f, 0.35f), i, j;
  float c[3];
  if (ground < 0 || m1 < 0 || m2 < 0) return -1;
  if (box_quad(b, -3, 0, -3, -3, 0, 3, 3, 0, 3, 3, 0, -3, ground)) return -1;
  P(c, -0.8f, 0.5f, 0);
  if (add_sphere(b, c, 0.5f, m1)) return -1;
  P(c, 0.9f, 0.25f, 0.3f);
  if (add_torus(b, c, 0.5f, 0.2f, 32, 16, m2)) return -1;
  for (i = 0; i < 10; i++)
    for (j = 0; j < 10; j++) {
      float x = -2.25f + 0.5f * (float)i, z = -2.25f + 0.5f * (float)j;
      float h = 1.2f + 0.25f * (float)((i * 7 + j * 3) % 4);
      rd_light l = light_sphere(x, h, z, 0.04f + 0.01f * (float)((i + j) % 3),
                                0.6f + 0.4f * (float)(i % 3 == 0), 0.6f + 0.4f * (float)(j % 2),
                                0.6f + 0.4f * (float)((i + j) % 3 == 1));
      for (int k = 0; k < 3; k++)
        l.radiance[k] *= 30.0f;
      if (add_light(b, &l)) return -1;
    }
  for (i = 0; i < 20; i++) {
    rd_light l;
    float x = -2.0f + 0.21f * (float)i, z = 1.8f * cosf(0.7f * (float)i), y = 1.0f;
    memset(&l, 0, sizeof l);
    l.type = RD_LIGHT_TRIANGLE;
    l.nv = 3;
    P(l.v[0], x, y, z);
    P(l.v[1], x + 0.12f, y + 0.02f, z);
    P(l.v[2], x + 0.05f, y - 0.01f, z + 0.1f);
    P(l.radiance, 20, 14, 8);
    if (add_light(b, &l)) return -1;
  }
  camera(s, 0, 2.6f, 4.0f, 0, 0.2f, 0, 50);
  return 0;
}

/* glossy floor (Phong left, GGX right) under a polygon, a sphere and a disc light */
static int build_glossy(builder *b) {
  rd_scene *s = b->s;
  int phong = mk_mat(b, "phong", 0.25f, 0.25f, 0.3f), ggx = mk_mat(b, "ggx", 0.3f, 0.25f, 0.2f),
      wall = mk_mat(b, "wall", 0.6f, 0.6f, 0.6f), ball = mk_mat(b, "ball", 0.5f, 0.2f, 0.2f);
  float c[3];
  rd_light l;
  if (phong < 0 || ggx < 0 || wall < 0 || ball < 0) return -1;
  s->mats[phong].brdf = RD_BRDF_PHONG;
  s->mats[phong].exponent = 60.0f;
  P(s->mats[phong].ks, 0.6f, 0.6f, 0.6f);
  s->mats[ggx].brdf = RD_BRDF_GGX;
  s->mats[ggx].roughness = 0.25f;
  P(s->mats[ggx].ks, 0.6f, 0.6f, 0.6f);
  if (box_quad(b, -3, 0, -3, -3, 0, 3, 0, 0, 3, 0, 0, -3, phong) ||
      box_quad(b, 0, 0, -3, 0, 0, 3, 3, 0, 3, 3, 0, -3, ggx) ||
      box_quad(b, -3, 0, -3, 3, 0, -3, 3, 3, -3, -3, 3, -3, wall))
    return -1;
  P(c, 0.0f, 0.4f, 0.2f);
  if (add_sphere(b, c, 0.4f, ball)) return -1;
  memset(&l, 0, sizeof l);
  l.type = RD_LIGHT_POLYGON;
  l.nv = 4;
  P(l.v[0], -2.0f, 0.3f, -2.9f);
  P(l.v[1], -0.8f, 0.3f, -2.9f);
  P(l.v[2], -0.8f, 1.5f, -2.9f);
  P(l.v[3], -2.0f, 1.5f, -2.9f);
  P(l.radiance, 5, 5, 4.5f);
  if (add_light(b, &l)) return -1;
  l = light_sphere(1.4f, 0.9f, -2.0f, 0.3f, 6, 4, 2.5f);
  if (add_light(b, &l)) return -1;
  memset(&l, 0, sizeof l);
  l.type = RD_LIGHT_DISC;
  P(l.c, 0.2f, 1.2f, -2.9f);
  P(l.n, 0, 0, 1);
  l.r = 0.35f;
  P(l.radiance, 3, 4, 6);
  if (add_light(b, &l)) return -1;
  camera(s, 0, 1.3f, 3.5f, 0, 0.3f, -1.0f, 45);
  return 0;
}

int rd_scene_builtin(const char *name, rd_scene *out) {
  builder b;
  int rc;
  memset(&b, 0, sizeof b);
  scene_defaults(out, name);
  b.s = out;
  if (!strcmp(name, "cornell"))
    rc = build_cornell(&b);
  else if (!strcmp(name, "spheres"))
    rc = build_spheres(&b);
  else if (!strcmp(name, "manylights"))
    rc = build_manylights(&b);
  else if (!strcmp(name, "glossy"))
    rc = build_glossy(&b);
  else
    rc = -1;
  if (rc) {
    rd_scene_free(out);
    return -1;
  }
  rd_scene_finish(out);
  return 0;
}
