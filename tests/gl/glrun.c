/* glrun.c - run GLSL functions over arrays on a headless GL context (see glrun.h). */
#include "glrun.h"
#include "glctx.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define GLRUN_GROUP 64 /* compute local_size_x */
#define GLRUN_W 256    /* fragment grid width */
#define GLRUN_MAX_OUT 8

static const char *version_cs = "#version 450", *version_fs = "#version 330";
static int ctx_state;   /* 0: not tried, 1: open, -1: failed (not retried) */
static int named_lines; /* GL_ARB_shading_language_include: #line 1 "file" */
static char *last_log;

/* ---- growable string ---- */
struct sbuf {
  char *p;
  size_t len, cap;
  int oom;
};

static void sb_put(struct sbuf *b, const char *s, size_t n) {
  if (b->oom) return;
  if (b->len + n + 1 > b->cap) {
    size_t cap = b->cap ? b->cap : 4096;
    char *p;
    while (b->len + n + 1 > cap)
      cap *= 2;
    if (!(p = realloc(b->p, cap))) {
      b->oom = 1;
      return;
    }
    b->p = p, b->cap = cap;
  }
  memcpy(b->p + b->len, s, n);
  b->len += n;
  b->p[b->len] = '\0';
}

static void sb_puts(struct sbuf *b, const char *s) {
  sb_put(b, s, strlen(s));
}

static void sb_printf(struct sbuf *b, const char *fmt, ...) {
  char tmp[1024];
  int n;
  va_list ap;
  va_start(ap, fmt);
  n = vsnprintf(tmp, sizeof tmp, fmt, ap);
  va_end(ap);
  if (n < 0 || (size_t)n >= sizeof tmp)
    b->oom = 1; /* only used for short lines */
  else
    sb_put(b, tmp, (size_t)n);
}

/* ---- context ---- */
static int ensure_ctx(const char *backend) {
  if (ctx_state == 0) {
    ctx_state = glctx_open(backend) ? -1 : 1;
    if (ctx_state == 1) named_lines = glctx_has_extension("GL_ARB_shading_language_include");
  }
  return ctx_state == 1 ? 0 : -1;
}

int glrun_open(const char *backend) {
  return ensure_ctx(backend);
}

void glrun_close(void) {
  if (ctx_state == 1) glctx_close();
  ctx_state = 0;
  free(last_log);
  last_log = NULL;
}

const char *glrun_backend(void) {
  return ensure_ctx(NULL) ? "" : glctx_backend();
}

const char *glrun_renderer(void) {
  return ensure_ctx(NULL) ? "(no context)" : (const char *)gl.GetString(GL_RENDERER);
}

void glrun_set_versions(const char *compute_version, const char *fragment_version) {
  if (compute_version) version_cs = compute_version;
  if (fragment_version) version_fs = fragment_version;
}

const char *glrun_last_log(void) {
  return last_log ? last_log : "";
}

static void set_log(const char *text) {
  free(last_log);
  last_log = text ? malloc(strlen(text) + 1) : NULL;
  if (last_log) strcpy(last_log, text);
}

/* ---- source assembly ---- */
static int is_es(const char *version) {
  size_t n = strlen(version);
  while (n && (version[n - 1] == ' ' || version[n - 1] == '\n'))
    n--;
  return n >= 2 && !strncmp(version + n - 2, "es", 2);
}

static const char *base_name(const char *path) {
  const char *s = strrchr(path, '/');
  return s ? s + 1 : path;
}

/* Appends one part. With named lines: `#line 1 "name"`; otherwise (ES) the part number k is
 * encoded in the line numbers, k*100000 + line, since Mesa prints the source number as 0. */
static void add_part(struct sbuf *b, struct sbuf *legend, int named, int k, const char *name,
                     const char *text) {
  if (named) {
    sb_printf(b, "#line 1 \"%s\"\n", name);
  } else {
    sb_printf(b, "#line %d %d\n", k * 100000 + 1, k);
    sb_printf(legend, "  lines %dxxxxx: %s\n", k, name);
  }
  sb_puts(b, text);
  if (!*text || text[strlen(text) - 1] != '\n') sb_puts(b, "\n");
}

static char *read_file(const char *path) {
  FILE *f = fopen(path, "rb");
  char *s = NULL;
  long n;
  if (f && fseek(f, 0, SEEK_END) == 0 && (n = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0 &&
      (s = malloc((size_t)n + 1)) != NULL) {
    if (fread(s, 1, (size_t)n, f) == (size_t)n) {
      s[n] = '\0';
    } else {
      free(s);
      s = NULL;
    }
  }
  if (!s) fprintf(stderr, "glrun: cannot read %s\n", path);
  if (f) fclose(f);
  return s;
}

/* Returns a malloc'd source or NULL; *legend_out receives the part legend (or NULL). */
static char *build_source(const char *version, const char *defines, const char *const *files,
                          int nfiles, const char *prefix, const char *main_src, const char *suffix,
                          char **legend_out) {
  struct sbuf b = {0}, legend = {0};
  int named = named_lines && !is_es(version), k = 0, i;
  sb_printf(&b, "%s\n", version);
  if (named) sb_puts(&b, "#extension GL_ARB_shading_language_include : enable\n");
  if (is_es(version)) sb_puts(&b, "precision highp float;\nprecision highp int;\n");
  add_part(&b, &legend, named, ++k, "defines", defines ? defines : "");
  for (i = 0; i < nfiles; i++) {
    char *text = read_file(files[i]);
    if (!text) {
      free(b.p), free(legend.p);
      return NULL;
    }
    add_part(&b, &legend, named, ++k, base_name(files[i]), text);
    free(text);
  }
  add_part(&b, &legend, named, ++k, "glrun_prefix", prefix);
  add_part(&b, &legend, named, ++k, "main_src", main_src);
  add_part(&b, &legend, named, ++k, "glrun_main", suffix);
  if (b.oom || legend.oom) {
    fprintf(stderr, "glrun: out of memory\n");
    free(b.p), free(legend.p);
    return NULL;
  }
  *legend_out = legend.p;
  return b.p;
}

/* Compiles and links; prints the info log (with file names) and keeps it on failure. */
static GLuint build_program(const char *vs_src, GLenum type, const char *src, const char *legend) {
  GLuint prog = gl.CreateProgram(), sh[2] = {0, 0};
  GLint ok = 1, len = 0;
  struct sbuf log = {0};
  char *text;
  int i;
  sh[0] = gl.CreateShader(type);
  if (vs_src) sh[1] = gl.CreateShader(GL_VERTEX_SHADER);
  for (i = 0; i < 2 && ok && sh[i]; i++) {
    const char *s = i ? vs_src : src;
    gl.ShaderSource(sh[i], 1, &s, NULL);
    gl.CompileShader(sh[i]);
    gl.GetShaderiv(sh[i], GL_COMPILE_STATUS, &ok);
    gl.GetShaderiv(sh[i], GL_INFO_LOG_LENGTH, &len);
    if (!ok && len > 0 && (text = malloc((size_t)len)) != NULL) {
      gl.GetShaderInfoLog(sh[i], len, NULL, text);
      sb_printf(&log, "glrun: %s shader does not compile:\n", i ? "vertex" : "kernel");
      sb_puts(&log, text);
      free(text);
    }
    gl.AttachShader(prog, sh[i]);
  }
  if (ok) {
    gl.LinkProgram(prog);
    gl.GetProgramiv(prog, GL_LINK_STATUS, &ok);
    gl.GetProgramiv(prog, GL_INFO_LOG_LENGTH, &len);
    if (!ok && len > 0 && (text = malloc((size_t)len)) != NULL) {
      gl.GetProgramInfoLog(prog, len, NULL, text);
      sb_puts(&log, "glrun: program does not link:\n");
      sb_puts(&log, text);
      free(text);
    }
  }
  for (i = 0; i < 2; i++)
    if (sh[i]) gl.DeleteShader(sh[i]); /* flagged; freed with the program */
  if (!ok) {
    if (!log.p) sb_puts(&log, "glrun: shader build failed (no log)\n");
    if (legend) { /* numbered #line (ES): which part a line number belongs to */
      sb_puts(&log, "source parts (line = part * 100000 + line in part):\n");
      sb_puts(&log, legend);
    }
    fputs(log.p ? log.p : "glrun: shader build failed\n", stderr);
    set_log(log.p ? log.p : "shader build failed");
    gl.DeleteProgram(prog);
    prog = 0;
  } else {
    set_log("");
  }
  free(log.p);
  return prog;
}

static GLuint make_program(const char *version, const char *vs_body, const char *defines,
                           const char *const *files, int nfiles, const char *prefix,
                           const char *main_src, const char *suffix) {
  char *legend = NULL, *src;
  struct sbuf vs = {0};
  GLuint prog = 0;
  if (!(src = build_source(version, defines, files, nfiles, prefix, main_src, suffix, &legend)))
    return 0;
  if (vs_body) {
    sb_puts(&vs, version);
    sb_puts(&vs, "\n");
    sb_puts(&vs, vs_body);
  }
  if (vs.oom)
    fprintf(stderr, "glrun: out of memory\n");
  else
    prog = build_program(vs.p, vs_body ? GL_FRAGMENT_SHADER : GL_COMPUTE_SHADER, src, legend);
  free(src), free(legend), free(vs.p);
  return prog;
}

static int gl_failed(const char *what) {
  GLenum e = gl.GetError();
  if (e == GL_NO_ERROR) return 0;
  while (gl.GetError() != GL_NO_ERROR) {
  }
  fprintf(stderr, "glrun: %s: GL error 0x%04x\n", what, e);
  return 1;
}

static int bad_args(const char *fn, const char *why) {
  fprintf(stderr, "glrun: %s: %s\n", fn, why);
  return -1;
}

/* ---- compute path ---- */
static const char CS_PREFIX[] =
    "layout(local_size_x = 64) in;\n"
    "layout(std430, binding = 0) readonly buffer glrun_in_block { float glrun_in[]; };\n"
    "layout(std430, binding = 1) writeonly buffer glrun_out_block { float glrun_out[]; };\n"
    "int glrun_item = 0;\n"
    "#define in_float(j) glrun_in[glrun_item * GLRUN_IN_STRIDE + (j)]\n"
    "#define in_vec4(k) vec4(in_float(4 * (k)), in_float(4 * (k) + 1), in_float(4 * (k) + 2), "
    "in_float(4 * (k) + 3))\n"
    "#define out_float(j, v) (glrun_out[glrun_item * GLRUN_OUT_STRIDE + (j)] = (v))\n"
    "void glrun_put4(int k, vec4 v) {\n"
    "  out_float(4 * k, v.x); out_float(4 * k + 1, v.y);\n"
    "  out_float(4 * k + 2, v.z); out_float(4 * k + 3, v.w);\n"
    "}\n"
    "#define out_vec4(k, v) glrun_put4(k, v)\n"
    "void glrun_main(int item);\n";
static const char CS_MAIN[] = "void main() {\n"
                              "  glrun_item = int(gl_GlobalInvocationID.x);\n"
                              "  if (glrun_item < GLRUN_COUNT) glrun_main(glrun_item);\n"
                              "}\n";

int glrun_compute(const char *defines, const char *const *files, int nfiles, const char *main_src,
                  const float *in, size_t n_in, float *out, size_t n_out, int count) {
  const unsigned qnan = 0x7fc00000u; /* unwritten outputs read back as NaN */
  float fill;
  struct sbuf prefix = {0};
  GLuint prog, buf[2] = {0, 0};
  int rc = -1;
  if (count < 1 || count > 65535 * GLRUN_GROUP) return bad_args("glrun_compute", "bad count");
  if (!main_src || !out || !n_out || (n_in && !in) || nfiles < 0 || (nfiles && !files))
    return bad_args("glrun_compute", "bad arguments");
  if (n_in / (size_t)count > 0x7fffffff || n_out / (size_t)count > 0x7fffffff)
    return bad_args("glrun_compute", "too many floats per item");
  if (ensure_ctx(NULL)) return -1;
  sb_printf(&prefix, "#define GLRUN_COUNT %d\n#define GLRUN_IN_STRIDE %d\n", count,
            (int)(n_in / (size_t)count));
  sb_printf(&prefix, "#define GLRUN_OUT_STRIDE %d\n", (int)(n_out / (size_t)count));
  sb_puts(&prefix, CS_PREFIX);
  prog = prefix.oom
             ? 0
             : make_program(version_cs, NULL, defines, files, nfiles, prefix.p, main_src, CS_MAIN);
  free(prefix.p);
  if (!prog) return -1;
  gl_failed("before glrun_compute");
  memcpy(&fill, &qnan, sizeof fill);
  gl.GenBuffers(2, buf);
  gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, buf[0]);
  gl.BufferData(GL_SHADER_STORAGE_BUFFER, (GLsizeiptr)(sizeof(float) * (n_in ? n_in : 1)),
                n_in ? in : NULL, GL_STATIC_DRAW);
  gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, buf[1]);
  gl.BufferData(GL_SHADER_STORAGE_BUFFER, (GLsizeiptr)(sizeof(float) * n_out), NULL,
                GL_STREAM_READ);
  gl.ClearBufferData(GL_SHADER_STORAGE_BUFFER, GL_R32F, GL_RED, GL_FLOAT, &fill);
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buf[0]);
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, buf[1]);
  gl.UseProgram(prog);
  gl.DispatchCompute((GLuint)(count + GLRUN_GROUP - 1) / GLRUN_GROUP, 1, 1);
  gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT); /* shader writes -> glGetBufferSubData */
  gl.GetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, (GLsizeiptr)(sizeof(float) * n_out), out);
  if (!gl_failed("glrun_compute")) rc = 0;
  gl.UseProgram(0);
  gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  gl.DeleteBuffers(2, buf);
  gl.DeleteProgram(prog);
  return rc;
}

/* ---- fragment path ---- */
static const char VS_BODY[] = /* one triangle covering the viewport, no vertex buffer */
    "void main() {\n"
    "  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));\n"
    "  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);\n"
    "}\n";
static const char FS_PREFIX[] =
    "#define GLRUN_IN_STRIDE (4 * GLRUN_IN_VEC4)\n"
    "#define GLRUN_OUT_STRIDE (4 * GLRUN_OUT_VEC4)\n"
    "vec4 glrun_ov[GLRUN_OUT_VEC4];\n"
    "ivec2 glrun_px = ivec2(0);\n"
    "#define in_vec4(k) texelFetch(glrun_tex, ivec2(glrun_px.x * GLRUN_IN_VEC4 + (k), "
    "glrun_px.y), 0)\n"
    "#define in_float(j) in_vec4((j) / 4)[(j) % 4]\n"
    "#define out_vec4(k, v) (glrun_ov[k] = (v))\n"
    "#define out_float(j, v) (glrun_ov[(j) / 4][(j) % 4] = (v))\n"
    "void glrun_main(int item);\n";

int glrun_fragment(const char *defines, const char *const *files, int nfiles, const char *main_src,
                   const float *in, int in_vec4_per_item, float *out, int out_vec4_per_item,
                   int count) {
  struct sbuf prefix = {0}, suffix = {0};
  GLint max_tex = 0, max_draw = 0;
  GLuint prog, tex[1 + GLRUN_MAX_OUT] = {0}, fbo = 0, vao = 0;
  GLenum bufs[GLRUN_MAX_OUT];
  int w = count < GLRUN_W ? count : GLRUN_W, h, k, i, c, rc = -1;
  size_t per_in = (size_t)in_vec4_per_item * 4, per_out = (size_t)out_vec4_per_item * 4;
  float *padded = NULL, *px = NULL;
  if (count < 1 || !main_src || !out || (in_vec4_per_item && !in) || nfiles < 0 ||
      (nfiles && !files))
    return bad_args("glrun_fragment", "bad arguments");
  if (ensure_ctx(NULL)) return -1;
  h = (count + w - 1) / w;
  gl.GetIntegerv(GL_MAX_TEXTURE_SIZE, &max_tex);
  gl.GetIntegerv(GL_MAX_DRAW_BUFFERS, &max_draw);
  if (in_vec4_per_item < 0 || in_vec4_per_item > max_tex / w)
    return bad_args("glrun_fragment", "in_vec4_per_item out of range");
  if (out_vec4_per_item < 1 || out_vec4_per_item > GLRUN_MAX_OUT || out_vec4_per_item > max_draw)
    return bad_args("glrun_fragment", "out_vec4_per_item out of range (1..8)");
  if (h > max_tex) return bad_args("glrun_fragment", "count too large");

  sb_printf(&prefix, "#define GLRUN_COUNT %d\n#define GLRUN_W %d\n", count, w);
  sb_printf(&prefix, "#define GLRUN_IN_VEC4 %d\n#define GLRUN_OUT_VEC4 %d\n", in_vec4_per_item,
            out_vec4_per_item);
  if (in_vec4_per_item) sb_puts(&prefix, "uniform highp sampler2D glrun_tex;\n");
  for (k = 0; k < out_vec4_per_item; k++)
    sb_printf(&prefix, "layout(location = %d) out vec4 glrun_o%d;\n", k, k);
  sb_puts(&prefix, FS_PREFIX);
  sb_puts(&suffix, "void main() {\n"
                   "  glrun_px = ivec2(gl_FragCoord.xy);\n"
                   "  for (int k = 0; k < GLRUN_OUT_VEC4; k++)\n"
                   "    glrun_ov[k] = vec4(uintBitsToFloat(0x7fc00000u)); /* unwritten: NaN */\n"
                   "  glrun_main(glrun_px.y * GLRUN_W + glrun_px.x);\n");
  for (k = 0; k < out_vec4_per_item; k++)
    sb_printf(&suffix, "  glrun_o%d = glrun_ov[%d];\n", k, k);
  sb_puts(&suffix, "}\n");
  prog = prefix.oom || suffix.oom ? 0
                                  : make_program(version_fs, VS_BODY, defines, files, nfiles,
                                                 prefix.p, main_src, suffix.p);
  free(prefix.p), free(suffix.p);
  if (!prog) return -1;

  px = malloc(sizeof(float) * 4 * (size_t)w * (size_t)h);
  if (in_vec4_per_item && (size_t)w * (size_t)h != (size_t)count) {
    padded = calloc((size_t)w * (size_t)h * per_in, sizeof(float)); /* zero inputs past count */
    if (padded) memcpy(padded, in, sizeof(float) * per_in * (size_t)count);
  }
  if (!px || (in_vec4_per_item && (size_t)w * (size_t)h != (size_t)count && !padded)) {
    fprintf(stderr, "glrun: out of memory\n");
    goto done;
  }
  gl_failed("before glrun_fragment");
  gl.GenTextures(1 + out_vec4_per_item, tex);
  for (k = 0; k <= out_vec4_per_item; k++) {
    gl.BindTexture(GL_TEXTURE_2D, tex[k]);
    /* the default MIN_FILTER wants mipmaps: the texture would be incomplete, texelFetch 0 */
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    if (k == 0) /* input: item (x, y) owns texels x * in_vec4_per_item + 0.. of row y */
      gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, w * (in_vec4_per_item ? in_vec4_per_item : 1), h,
                    0, GL_RGBA, GL_FLOAT, in_vec4_per_item ? (padded ? padded : in) : NULL);
    else
      gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, w, h, 0, GL_RGBA, GL_FLOAT, NULL);
  }
  gl.GenFramebuffers(1, &fbo);
  gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
  for (k = 0; k < out_vec4_per_item; k++) {
    bufs[k] = GL_COLOR_ATTACHMENT0 + (GLenum)k;
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, bufs[k], GL_TEXTURE_2D, tex[1 + k], 0);
  }
  gl.DrawBuffers(out_vec4_per_item, bufs);
  if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    fprintf(stderr, "glrun: RGBA32F framebuffer incomplete\n");
    goto done;
  }
  gl.GenVertexArrays(1, &vao);
  gl.BindVertexArray(vao); /* core profile: drawing needs a bound (empty) VAO */
  gl.Viewport(0, 0, w, h);
  gl.UseProgram(prog);
  if (in_vec4_per_item) gl.Uniform1i(gl.GetUniformLocation(prog, "glrun_tex"), 0);
  gl.ActiveTexture(GL_TEXTURE0);
  gl.BindTexture(GL_TEXTURE_2D, tex[0]);
  gl.DrawArrays(GL_TRIANGLES, 0, 3);
  for (k = 0; k < out_vec4_per_item; k++) { /* float readback: exact and unclamped */
    gl.ReadBuffer(bufs[k]);
    gl.ReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, px);
    for (i = 0; i < count; i++)
      for (c = 0; c < 4; c++)
        out[(size_t)i * per_out + 4 * (size_t)k + (size_t)c] = px[4 * i + c];
  }
  if (!gl_failed("glrun_fragment")) rc = 0;
done:
  gl.UseProgram(0);
  gl.BindVertexArray(0);
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  gl.BindTexture(GL_TEXTURE_2D, 0);
  if (vao) gl.DeleteVertexArrays(1, &vao);
  if (fbo) gl.DeleteFramebuffers(1, &fbo);
  if (tex[0]) gl.DeleteTextures(1 + out_vec4_per_item, tex);
  gl.DeleteProgram(prog);
  free(padded), free(px);
  return rc;
}
