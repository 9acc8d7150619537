/* rd_gl.c - full-screen GLSL passes over the G-buffer (see rd_gl_pass in rd.h), on the
 * headless context of tests/gl/glctx.c (OSMesa or EGL surfaceless). */
#include "rd.h"

#include "../tests/gl/glctx.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifndef RD_GLSL_DIR
#define RD_GLSL_DIR "shlight_glsl"
#endif

static int opened;
/* the last program, kept for a draw with the same source (llvmpipe keeps its JIT code) */
static struct {
  char *src;
  GLuint prog, vs, fs;
} last;

static void last_free(void) {
  if (opened && last.prog) {
    gl.DeleteProgram(last.prog);
    gl.DeleteShader(last.vs);
    gl.DeleteShader(last.fs);
  }
  free(last.src);
  memset(&last, 0, sizeof last);
}

int rd_gl_open(const char *backend) {
  if (opened) return 0;
  /* the renderer runs on any GL 4.5 implementation (llvmpipe in CI, a GPU where one is) */
  setenv("SHLIGHT_GL_ANY_RENDERER", "1", 0);
  if (glctx_open(backend)) return -1;
  opened = 1;
  return 0;
}

void rd_gl_close(void) {
  last_free();
  if (opened) glctx_close();
  opened = 0;
}

const char *rd_gl_renderer(void) {
  const char *r = opened ? (const char *)gl.GetString(GL_RENDERER) : NULL;
  return r ? r : "(no context)";
}

/* growable string */
typedef struct {
  char *s;
  size_t n, cap;
} sbuf;
static int sadd(sbuf *b, const char *t, size_t n) {
  if (b->n + n + 1 > b->cap) {
    size_t c = b->cap ? b->cap : 4096;
    char *q;
    while (c < b->n + n + 1)
      c *= 2;
    q = (char *)realloc(b->s, c);
    if (!q) return -1;
    b->s = q;
    b->cap = c;
  }
  memcpy(b->s + b->n, t, n);
  b->n += n;
  b->s[b->n] = 0;
  return 0;
}
static int sadds(sbuf *b, const char *t) {
  return sadd(b, t, strlen(t));
}
static int sadd_file(sbuf *b, const char *name) {
  const char *dir = getenv("SHLIGHT_GLSL_DIR");
  char path[1024], buf[65536];
  FILE *f;
  size_t got;
  int rc = 0;
  snprintf(path, sizeof path, "%s/%s", dir && *dir ? dir : RD_GLSL_DIR, name);
  if (!(f = fopen(path, "rb"))) {
    fprintf(stderr, "shlrender: cannot read %s (set SHLIGHT_GLSL_DIR to shlight_glsl/)\n", path);
    return -1;
  }
  while ((got = fread(buf, 1, sizeof buf, f)) > 0)
    if (sadd(b, buf, got)) rc = -1;
  fclose(f);
  return rc ? rc : sadds(b, "\n");
}

static GLuint compile(GLenum type, const char *src, const char *what) {
  GLuint sh = gl.CreateShader(type);
  GLint ok = 0;
  gl.ShaderSource(sh, 1, &src, NULL);
  gl.CompileShader(sh);
  gl.GetShaderiv(sh, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[8192];
    gl.GetShaderInfoLog(sh, (GLsizei)sizeof log, NULL, log);
    fprintf(stderr, "shlrender: %s shader does not compile:\n%s\n", what, log);
    gl.DeleteShader(sh);
    return 0;
  }
  return sh;
}

static double now_ms(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}
static int cmp_d(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return x < y ? -1 : x > y;
}

static GLuint texture(int w, int h, const float *data) {
  GLuint t;
  gl.GenTextures(1, &t);
  gl.BindTexture(GL_TEXTURE_2D, t);
  gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, w, h, 0, GL_RGBA, GL_FLOAT, data);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  return t;
}

static const char *vs_src = "#version 450\n"
                            "void main() {\n"
                            "  vec2 p = vec2(float((gl_VertexID & 1) * 4 - 1),\n"
                            "                float((gl_VertexID & 2) * 2 - 1));\n"
                            "  gl_Position = vec4(p, 0.0, 1.0);\n"
                            "}\n";

int rd_gl_run(const rd_scene *s, const rd_gbuf *gb, const rd_gl_pass *p, float *const *out,
              int reps, double *ms) {
  sbuf src = {NULL, 0, 0};
  char line[256];
  int i, j, rc = -1, w = gb->w, h = gb->h;
  size_t npx = (size_t)w * (size_t)h;
  GLuint vs = 0, fs = 0, prog = 0, tex[3 + 4] = {0}, otex[8] = {0}, fbo = 0, vao = 0, ssbo[7] = {0};
  GLint ok = 0;
  float *tmp = NULL, *mats = NULL;
  double *t = NULL;
  rd_tm tm = {0, 0, 0};
  int held = 0; /* the gate: 0, 1 shared, 2 alone */
  if (!opened && rd_gl_open(NULL)) return -1;
  if (p->nout < 1 || p->nout > 8 || p->nbuf < 0 || p->nbuf > 6 || p->ninputs < 0 ||
      p->ninputs > 4) {
    fprintf(stderr, "shlrender: rd_gl_run: bad pass layout\n");
    return -1;
  }
  /* compile, JIT and read-back may overlap other processes' work; the timed draws may not */
  rd_gate_enter(0);
  held = 1;
  /* shader source */
  if (sadds(&src, "#version 450\n") || (p->defines && sadds(&src, p->defines)) || sadds(&src, "\n"))
    goto done;
  for (i = 0; i < p->ninclude; i++)
    if (sadd_file(&src, p->includes[i])) goto done;
  sadds(&src, "uniform sampler2D rd_pos;\nuniform sampler2D rd_nrm;\nuniform sampler2D rd_gnrm;\n");
  for (i = 0; i < p->ninputs; i++) {
    snprintf(line, sizeof line, "uniform sampler2D rd_in%d;\n", i);
    sadds(&src, line);
  }
  sadds(&src, "layout(std430, binding = 0) readonly buffer rd_mats_b { float rd_mats[]; };\n");
  for (i = 0; i < p->nbuf; i++) {
    snprintf(line, sizeof line,
             "layout(std430, binding = %d) readonly buffer rd_b%d { float rd_buf%d[]; };\n", i + 1,
             i + 1, i + 1);
    sadds(&src, line);
  }
  sadds(&src, "uniform vec3 rd_eye;\nuniform ivec2 rd_size;\n");
  for (i = 0; i < p->nout; i++) {
    snprintf(line, sizeof line, "layout(location = %d) out vec4 rd_out%d;\n", i, i);
    sadds(&src, line);
  }
  sadds(&src, "ivec2 rd_pixel() { return ivec2(gl_FragCoord.xy); }\n");
  if (sadds(&src, p->body)) goto done;
  /* program */
  tm = rd_tm_now();
  if (last.src && !strcmp(last.src, src.s)) {
    prog = last.prog;
    vs = last.vs;
    fs = last.fs;
    free(last.src);
    memset(&last, 0, sizeof last);
    gl.UseProgram(prog);
    tm = rd_tm_add(RD_TM_GL_COMPILE, tm);
    goto have_prog;
  }
  if (!(vs = compile(GL_VERTEX_SHADER, vs_src, "vertex")) ||
      !(fs = compile(GL_FRAGMENT_SHADER, src.s, "fragment")))
    goto done;
  prog = gl.CreateProgram();
  gl.AttachShader(prog, vs);
  gl.AttachShader(prog, fs);
  gl.LinkProgram(prog);
  gl.GetProgramiv(prog, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[8192];
    gl.GetProgramInfoLog(prog, (GLsizei)sizeof log, NULL, log);
    fprintf(stderr, "shlrender: link failed:\n%s\n", log);
    goto done;
  }
  gl.UseProgram(prog);
  tm = rd_tm_add(RD_TM_GL_COMPILE, tm);
have_prog:
  /* G-buffer and input textures */
  tmp = (float *)malloc(npx * 4 * sizeof(float));
  if (!tmp) goto done;
  for (j = 0; j < 3; j++) {
    const float *v = j == 0 ? gb->pos : j == 1 ? gb->nrm : gb->gnrm;
    static const char *names[3] = {"rd_pos", "rd_nrm", "rd_gnrm"};
    size_t k;
    for (k = 0; k < npx; k++) {
      tmp[4 * k] = v[3 * k];
      tmp[4 * k + 1] = v[3 * k + 1];
      tmp[4 * k + 2] = v[3 * k + 2];
      tmp[4 * k + 3] = j == 0 ? gb->depth[k] : j == 1 ? (float)gb->mat[k] : 0.0f;
    }
    gl.ActiveTexture((GLenum)(GL_TEXTURE0 + j));
    tex[j] = texture(w, h, tmp);
    gl.Uniform1i(gl.GetUniformLocation(prog, names[j]), j);
  }
  for (i = 0; i < p->ninputs; i++) {
    snprintf(line, sizeof line, "rd_in%d", i);
    gl.ActiveTexture((GLenum)(GL_TEXTURE0 + 3 + i));
    tex[3 + i] = texture(w, h, p->inputs[i]);
    gl.Uniform1i(gl.GetUniformLocation(prog, line), 3 + i);
  }
  gl.Uniform3f(gl.GetUniformLocation(prog, "rd_eye"), gb->eye[0], gb->eye[1], gb->eye[2]);
  gl.Uniform2i(gl.GetUniformLocation(prog, "rd_size"), w, h);
  /* materials (binding 0) and the pass's buffers */
  mats = (float *)calloc((size_t)(s->nmats > 0 ? s->nmats : 1) * 12, sizeof(float));
  if (!mats) goto done;
  for (i = 0; i < s->nmats; i++) {
    const rd_material *m = &s->mats[i];
    float *q = mats + 12 * i;
    memcpy(q, m->kd, 3 * sizeof(float));
    memcpy(q + 3, m->ks, 3 * sizeof(float));
    q[6] = (float)m->brdf;
    q[7] = m->exponent;
    q[8] = m->roughness;
    q[9] = m->bump_freq;
    q[10] = m->bump_amp;
  }
  gl.GenBuffers(1 + p->nbuf, ssbo);
  for (i = 0; i <= p->nbuf; i++) {
    const float *d = i == 0 ? mats : p->bufs[i - 1];
    size_t n = i == 0 ? (size_t)(s->nmats > 0 ? s->nmats : 1) * 12 : p->buf_floats[i - 1];
    static const float zero[4] = {0, 0, 0, 0};
    gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, ssbo[i]);
    gl.BufferData(GL_SHADER_STORAGE_BUFFER, (GLsizeiptr)((n ? n : 4) * sizeof(float)), n ? d : zero,
                  GL_STATIC_DRAW);
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, (GLuint)i, ssbo[i]);
  }
  /* targets */
  gl.GenFramebuffers(1, &fbo);
  gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
  {
    GLenum bufs[8];
    for (i = 0; i < p->nout; i++) {
      gl.ActiveTexture(GL_TEXTURE0 + 7);
      otex[i] = texture(w, h, NULL);
      gl.FramebufferTexture2D(GL_FRAMEBUFFER, (GLenum)(GL_COLOR_ATTACHMENT0 + i), GL_TEXTURE_2D,
                              otex[i], 0);
      bufs[i] = (GLenum)(GL_COLOR_ATTACHMENT0 + i);
    }
    gl.DrawBuffers(p->nout, bufs);
  }
  if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    fprintf(stderr, "shlrender: framebuffer incomplete\n");
    goto done;
  }
  gl.GenVertexArrays(1, &vao);
  gl.BindVertexArray(vao);
  if (reps < 1) reps = 1;
  t = (double *)malloc((size_t)reps * sizeof *t);
  if (!t) goto done;
  tm = rd_tm_add(RD_TM_GL_SETUP, tm);
  for (i = -1; i < reps; i++) {
    /* one warm-up draw of one pixel: the JIT compiles the shader on first use (the viewport
       is not part of what it compiles), then the timed draws of the whole image, alone */
    double t0;
    if (i == 0) {
      rd_gate_leave(0);
      held = 0;
      rd_gate_enter(1);
      held = 2;
      tm = rd_tm_now();
    }
    t0 = now_ms();
    if (i < 1) gl.Viewport(0, 0, i < 0 ? 1 : w, i < 0 ? 1 : h);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
    gl.Finish();
    if (i >= 0) t[i] = now_ms() - t0;
    tm = rd_tm_add(i < 0 ? RD_TM_GL_COMPILE : RD_TM_GL_DRAW, tm);
  }
  rd_gate_leave(1);
  held = 0;
  rd_gate_enter(0);
  held = 1;
  qsort(t, (size_t)reps, sizeof *t, cmp_d);
  if (ms) *ms = t[reps / 2];
  for (i = 0; i < p->nout; i++) {
    gl.ReadBuffer((GLenum)(GL_COLOR_ATTACHMENT0 + i));
    gl.ReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, out[i]);
  }
  if (gl.GetError() != GL_NO_ERROR) {
    fprintf(stderr, "shlrender: GL error in pass\n");
    goto done;
  }
  rc = 0;
done:
  if (tm.wall > 0) rd_tm_add(RD_TM_GL_SETUP, tm);
  if (held) rd_gate_leave(held == 2);
  if (opened) {
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    if (fbo) gl.DeleteFramebuffers(1, &fbo);
    if (vao) gl.DeleteVertexArrays(1, &vao);
    for (i = 0; i < 7; i++)
      if (tex[i]) gl.DeleteTextures(1, &tex[i]);
    for (i = 0; i < 8; i++)
      if (otex[i]) gl.DeleteTextures(1, &otex[i]);
    for (i = 0; i < 7; i++)
      if (ssbo[i]) gl.DeleteBuffers(1, &ssbo[i]);
    if (rc == 0 && prog) { /* kept for the next draw of the same source */
      last_free();
      last.src = src.s;
      src.s = NULL;
      last.prog = prog;
      last.vs = vs;
      last.fs = fs;
    } else {
      if (prog) gl.DeleteProgram(prog);
      if (vs) gl.DeleteShader(vs);
      if (fs) gl.DeleteShader(fs);
    }
  }
  free(src.s);
  free(tmp);
  free(mats);
  free(t);
  return rc;
}
