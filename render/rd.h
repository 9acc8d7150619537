/* rd.h - shlrender: a small headless renderer that runs shlight's GLSL includes on scenes, the
 * same frames on the CPU from the C kernels, and a ground truth, and compares them.
 *
 * Pipeline. The G-buffer is ray cast on the CPU (rd_gbuffer: exact, deterministic, the same
 * input for every path), then each pass shades it three ways:
 *   "gl"  a full-screen fragment shader built from shlight_glsl/ includes (rd_gl_run),
 *   "cpu" the same algorithm from the C kernels of shlight.h, pixel for pixel,
 *   "gt"  a ground truth (quadrature / Monte Carlo, same visibility assumptions as the method).
 * A pass hands every image to rd_emit(); the core writes PNGs, compares gl with cpu (the CI
 * check) and every method with gt (RMSE, PSNR, SSIM), and prints the results table.
 *
 * Units: radiance, linear RGB floats; positions in scene units; normals unit length.
 * Files: rd.h (this), rd_core.c (images, metrics, PNG, progress, results), rd_scene.c (text
 * format, OBJ, procedural scenes), rd_trace.c (ray casting, G-buffer, views), rd_gl.c (GL pass
 * runner), pass_*.c (one per pass), main.c (command line). */
#ifndef SHLIGHT_RD_H
#define SHLIGHT_RD_H
#include <pthread.h>
#include <stddef.h>
#include <stdio.h>

#define RD_MAX_POLY 8 /* polygon light vertices (= SHLIGHT_POLYGON_MAX) */

/* ---- scene ---------------------------------------------------------------------------- */
enum { RD_BRDF_LAMBERT = 0, RD_BRDF_PHONG = 1, RD_BRDF_GGX = 2 };
typedef struct {
  char name[32];
  float kd[3];     /* diffuse albedo, in [0, 1) */
  float ks[3];     /* specular albedo (Phong / GGX lobe), 0 for Lambert */
  int brdf;        /* RD_BRDF_* */
  float exponent;  /* Phong exponent (normalised lobe (e+1)/(2 pi) cos^e), RD_BRDF_PHONG */
  float roughness; /* GGX alpha, RD_BRDF_GGX */
  float bump_freq; /* procedural normal map: 0 none; else bumps of this spatial frequency */
  float bump_amp;  /* ... and this slope amplitude (tangent of the tilt, e.g. 0.5) */
} rd_material;

typedef struct {
  float p[3][3]; /* vertices */
  float n[3][3]; /* vertex normals (flat triangles: the face normal three times) */
  int mat;
} rd_tri;

typedef struct {
  float c[3], r;
  int mat;
} rd_sphere;

enum {
  RD_LIGHT_SPHERE = 0,   /* c, r; radiance */
  RD_LIGHT_TRIANGLE = 1, /* v[0..2], nv = 3; two-sided emitter */
  RD_LIGHT_POLYGON = 2,  /* v[0..nv-1], planar, nv <= RD_MAX_POLY; two-sided emitter */
  RD_LIGHT_DISC = 3,     /* c, n (unit), r; two-sided emitter */
  RD_LIGHT_SPOT = 4      /* point at c, direction n, cone half-angle `angle` (radians);
                            radiance[] is its intensity (W/sr), the source of the RSM passes */
};
typedef struct {
  int type;
  float radiance[3];
  float c[3], r, n[3], angle;
  float v[RD_MAX_POLY][3];
  int nv;
} rd_light;

typedef struct {
  float eye[3], target[3], up[3];
  float fov_y; /* vertical field of view, radians */
} rd_camera;

typedef struct {
  char name[64];
  rd_material *mats;
  int nmats;
  rd_tri *tris;
  int ntris;
  rd_sphere *spheres;
  int nspheres;
  rd_light *lights;
  int nlights;
  rd_camera cam;
  int bands;     /* SH bands the SH passes use ("bands N"; default 5) */
  float bmin[3]; /* bounds of all geometry and lights (rd_scene_finish) */
  float bmax[3];
} rd_scene;

/* Built-in scenes: "cornell", "spheres" (plane, spheres, tori), "manylights" (grid of many
 * small sphere/triangle lights), "glossy" (glossy floor under polygon/sphere/disc lights).
 * Returns 0, or -1 for an unknown name. */
int rd_scene_builtin(const char *name, rd_scene *out);
/* Parse the text format (see rd_scene.c and README) from a file / from memory. On error
 * returns -1, leaves *out empty (zeroed) and writes "file:line: message" into err (errlen
 * bytes). OBJ files named by the scene are read relative to the scene file's folder (`dir`;
 * "" the working directory; NULL refuses `obj` lines: for untrusted text, e.g. the fuzzer). */
int rd_scene_load(const char *path, rd_scene *out, char *err, size_t errlen);
int rd_scene_parse(const char *text, size_t len, const char *dir, const char *name, rd_scene *out,
                   char *err, size_t errlen);
void rd_scene_free(rd_scene *s);
/* Computes bounds; called by the loaders. */
void rd_scene_finish(rd_scene *s);

/* ---- ray casting and the G-buffer ------------------------------------------------------ */
typedef struct {
  float t;     /* distance along the unit ray */
  float p[3];  /* hit point */
  float n[3];  /* shading normal (interpolated, normal map applied) */
  float ng[3]; /* interpolated normal without the normal map */
  int mat;     /* material index */
} rd_hit;
/* Closest hit of o + t d, t in (tmin, tmax); d unit. Returns 1 on a hit (light geometry is
 * not part of the traced scene: lights are seen only through the passes). */
int rd_trace(const rd_scene *s, const float o[3], const float d[3], float tmin, float tmax,
             rd_hit *h);

typedef struct {
  int w, h;
  float *pos;   /* w*h*3, world position of the visible surface */
  float *nrm;   /* w*h*3, shading normal (normal-mapped where the material has bumps) */
  float *gnrm;  /* w*h*3, geometric (interpolated) normal, no normal map */
  float *depth; /* w*h, distance from the eye; -1 for background */
  int *mat;     /* w*h, material index; -1 for background */
  float eye[3]; /* the viewpoint (camera eye, or the light for an RSM view) */
} rd_gbuf;
/* Pixel (x, y), y = 0 the top row, index y*w + x; rays through pixel centres. */
int rd_gbuffer(const rd_scene *s, int w, int h, rd_gbuf *out);
/* The same from an arbitrary pinhole view (a spot light's reflective shadow map: eye = the
 * light, dir = its axis, fov_y = 2 * its cone half-angle). */
int rd_gbuffer_view(const rd_scene *s, const float eye[3], const float dir[3], const float up[3],
                    float fov_y, int w, int h, rd_gbuf *out);
void rd_gbuf_free(rd_gbuf *g);

/* ---- images, metrics, PNG -------------------------------------------------------------- */
typedef struct {
  int w, h;
  float *rgb; /* w*h*3 linear radiance */
} rd_image;
rd_image rd_image_new(int w, int h); /* zero-filled; rgb NULL on failure */
void rd_image_free(rd_image *im);
/* 8-bit sRGB PNG of exposure * rgb (clamped), written with stored deflate blocks (no zlib). */
int rd_png_write(const char *path, const rd_image *im, float exposure);
typedef struct {
  double rmse;   /* over the pixels with mask != 0 (mask NULL: all), RGB averaged */
  double psnr;   /* 20 log10(peak / rmse), peak = max reference value over the mask */
  double ssim;   /* mean SSIM of the luminance, 8x8 windows, stride 4, on the tone-mapped image */
  double maxrel; /* max |a - b| / peak */
} rd_metrics;
rd_metrics rd_compare(const rd_image *test, const rd_image *ref, const int *mask);
/* RMSE of a against ref over the surface pixels of material mat (-1: every surface pixel),
 * relative to the RMS of ref there; 0 when ref is zero there. */
double rd_relrmse(const rd_gbuf *gb, const rd_image *a, const rd_image *ref, int mat);
/* orthonormal frame (t, b) about the unit normal z (Duff et al. 2017), as the shaders do it */
void rd_frame(const float z[3], float t[3], float b[3]);

/* Terminal progress bar on stderr (only when stderr is a terminal, or SHLIGHT_PROGRESS=1). */
void rd_progress(const char *label, long done, long total);

/* ---- the run: options and results ------------------------------------------------------ */
typedef struct rd_result rd_result;
typedef struct {
  const rd_scene *scene;
  const rd_gbuf *gb;  /* camera G-buffer */
  int use_gl;         /* run the GLSL paths */
  int use_cpu;        /* run the CPU paths */
  int gt;             /* ground truth: 0 none, 1 quick (CI: few samples), 2 full (README) */
  int bands;          /* SH bands (scene default unless overridden on the command line) */
  int brdf_bands;     /* bands of the grid / hvl passes' BRDF SH tables (glossy; 0: 9) */
  int reps;           /* timed repetitions of each GL draw / CPU pass; the median is reported */
  const char *outdir; /* PNGs go to outdir/<scene>_<pass>_<method>_<path>.png; NULL: none */
  float exposure;     /* PNG exposure */
  /* --brdf FILE[:MAT]: a measured BRDF (shl_merl_read) for the hvl pass's receivers (NULL:
     none), and the material it replaces (NULL: every Phong / GGX material) */
  const struct shl_merl *merl;
  const char *merl_mat;
  /* results, filled by rd_emit */
  rd_result *res;
  int nres, capres;
} rd_run;

/* Hand one image to the core, which takes ownership of img.rgb.
 * pass: "grid", "hvl", "area", "ssf"; method: e.g. "hermite"; path: "gl", "cpu" or "gt".
 * ms: median time of the pass (GL: draw + glFinish, excluding compile and read-back; CPU:
 * per-thread CPU time); mem: bytes the method keeps per frame beyond the G-buffer (grid, SH
 * buffers); tol: for path "gl", the largest accepted max |gl - cpu| / peak(cpu) (the CI
 * check), ignored otherwise. Images of the same pass with path "gt" are the reference of every
 * method of that pass (an image with method "gt:<name>" is the reference only of <name>). */
void rd_emit(rd_run *run, const char *pass, const char *method, const char *path, rd_image img,
             double ms, size_t mem, double tol);
/* rd_emit for a "gl" image whose pixels of the materials m with sel[m] != 0 (nsel flags, copied)
 * are checked against tol_sel instead of tol (a kernel whose GL twin is less close to C, e.g.
 * area's GGX floor): the check then holds both, max |gl - cpu| over each set of pixels divided
 * by the peak of the whole CPU image; sel_name names the selected pixels in the report. */
void rd_emit_sel(rd_run *run, const char *pass, const char *method, const char *path, rd_image img,
                 double ms, size_t mem, double tol, const int *sel, int nsel, double tol_sel,
                 const char *sel_name);
/* Prints the table (markdown) and returns the number of failed gl-vs-cpu checks. */
int rd_report(rd_run *run, int markdown);
/* The number of gl-vs-cpu checks (methods with both a "gl" and a "cpu" image). */
int rd_report_checks(const rd_run *run);
void rd_run_free(rd_run *run);
/* The results emitted so far, written to f / read from f and emitted again (a pass that ran in
 * a process of its own hands its results to the parent). 0, or -1 on an I/O error. */
int rd_results_write(FILE *f, const rd_run *run);
int rd_results_read(FILE *f, rd_run *run);

/* Per-thread CPU time in milliseconds (for the CPU paths' timings). */
double rd_cpu_ms(void);

/* ---- threads --------------------------------------------------------------------------- */
#define RD_MAX_THREADS 64
/* SHLIGHT_THREADS, else the online CPUs; 1..RD_MAX_THREADS */
int rd_threads(void);
/* Calls fn(ctx, lo, hi) over [0, n) in pieces of `chunk` items, on rd_threads() threads (the
 * calling one included), each thread taking the next piece when it is done with one. fn must
 * write only the items lo..hi-1 (each item's result then does not depend on the threads).
 * label: a progress bar (rd_progress), or NULL. Returns the CPU ms of all the threads
 * together: the time one thread would take, the CPU column's meaning. */
double rd_parallel(long n, long chunk, void (*fn)(void *ctx, long lo, long hi), void *ctx,
                   const char *label);
/* rd_parallel for background work (a ground truth computed on a thread of its own while the
 * pass goes on): the rows' CPU time is counted as background (rd_tm); no progress bar. */
double rd_parallel_bg(long n, long chunk, void (*fn)(void *ctx, long lo, long hi), void *ctx,
                      const char *label);
/* 1 when a pass may compute its ground truth on a thread of its own, beside its GL work (the
 * pass processes run at the same time: main.c), else 0 */
int rd_bg_ok(void);
/* runs fn(arg) on a thread of its own when rd_bg_ok (returns 1: join *th), else here (returns
 * 0); *bg, which fn may read, says which before fn starts */
int rd_bg_start(pthread_t *th, void *(*fn)(void *), void *arg, int *bg);
/* 1 when a pass built with its AVX lanes (compiled != 0) may use them: the CPU has AVX and
 * SHLIGHT_RENDER_NO_AVX is not set (tests hold the two paths to the same bytes), else 0 */
int rd_use_avx(int compiled);
/* lowers the calling thread's priority (nice + RD_PAR_NICE) where the system allows it */
void rd_thread_nice(void);

/* The passes of a run with GL run in processes of their own, at the same time (main.c); the
 * gate keeps what is timed by the wall clock quiet. Work that may overlap others (the JIT, a
 * piece of rd_parallel) runs between rd_gate_enter(0) and rd_gate_leave(0), any number at
 * once; a timed section (the GL draws, the grid build) between rd_gate_enter(1) and
 * rd_gate_leave(1), alone: it waits until no piece runs (new compiles may start meanwhile: the
 * CPUs stay busy; new rows of rd_parallel, entered with rd_gate_enter(2), wait for it: a row is
 * short), and pieces wait while it runs.
 * Without rd_gate_share() (one process) these do nothing. rd_gate_share: 0, or -1 when the
 * shared memory is refused. rd_gate_renderer: 256 shared bytes (NULL without the gate). */
int rd_gate_share(void);
void rd_gate_enter(int excl);
void rd_gate_leave(int excl);
char *rd_gate_renderer(void);

/* ---- where the run's time goes (--timings) ---------------------------------------------- */
/* Wall and process CPU time (every thread, llvmpipe's included) spent in each part of a pass,
 * summed over the run: GL compile (compile, link and the first draw, where llvmpipe's JIT
 * runs), GL draws (the timed ones), GL setup (textures, buffers, read-back), ground truth. A
 * ground truth computed in the background (rd_parallel_bg) counts its own CPU time, and the
 * parts that run meanwhile leave it out; its wall time overlaps the pass's other parts. */
enum { RD_TM_GL_COMPILE = 0, RD_TM_GL_DRAW = 1, RD_TM_GL_SETUP = 2, RD_TM_GT = 3, RD_TM_N = 4 };
typedef struct {
  double wall, cpu; /* ms; cpu: the process's */
  double bg;        /* ms: the CPU time of the background work (rd_parallel_bg) so far */
} rd_tm;
rd_tm rd_tm_now(void);
/* adds the time since t0 to part `part`, less the CPU time of the background work meanwhile
   (it is counted where it belongs, rd_tm_add_ms); returns now (to chain parts) */
rd_tm rd_tm_add(int part, rd_tm t0);
void rd_tm_add_ms(int part, double wall_ms, double cpu_ms);
/* CPU ms of this thread, added to the background work's (a ground truth on a thread of its own) */
void rd_bg_add_cpu(double ms);
/* the totals so far (RD_TM_N entries); rd_tm_merge adds a pass process's totals */
void rd_tm_get(rd_tm *out);
void rd_tm_merge(const rd_tm *parts);

/* ---- GL passes ------------------------------------------------------------------------- */
/* A full-screen fragment pass at the G-buffer's resolution. The shader is, in order:
 *   "#version 450"; `defines`; each of `includes` (file names inside shlight_glsl/, e.g.
 *   "shl_prelude.glsl", "shl_basis.glsl"; the directory is SHLIGHT_GLSL_DIR or the build's);
 *   the runner's declarations:
 *     uniform sampler2D rd_pos;   // texelFetch: xyz position, w depth (-1 background)
 *     uniform sampler2D rd_nrm;   // xyz shading normal, w material index (-1 background)
 *     uniform sampler2D rd_gnrm;  // xyz geometric normal, w 0
 *     uniform sampler2D rd_in0 .. rd_in<ninputs-1>;   // the pass's extra RGBA32F inputs
 *     layout(std430, binding = 0) readonly buffer rd_mats_b { float rd_mats[]; };
 *        // 12 floats per material: kd rgb, ks rgb, brdf, exponent, roughness, bump freq,
 *        // bump amp, 0
 *     layout(std430, binding = k) readonly buffer rd_bk { float rd_bufk[]; };  k = 1..nbuf
 *     uniform vec3 rd_eye; uniform ivec2 rd_size;
 *     layout(location = j) out vec4 rd_outj;           // j = 0..nout-1
 *     ivec2 rd_pixel();  // this fragment's pixel, y = 0 the top row (matches rd_gbuf)
 *   then `body`, which defines void main() and writes every rd_outj.
 * Returns 0 and fills out[j] (w*h*4 floats each, caller's storage) and *ms (median draw +
 * glFinish time over `reps` draws after one warm-up), or -1 with a message on stderr. */
typedef struct {
  const char *defines;
  const char *const *includes;
  int ninclude;
  const char *body;
  const float *const *bufs; /* SSBO k+1 <- bufs[k] (buf_floats[k] floats; may be 0) */
  const size_t *buf_floats;
  int nbuf;                   /* 0..6 */
  const float *const *inputs; /* w*h*4 floats each, texelFetch at the pixel */
  int ninputs;                /* 0..4 */
  int nout;                   /* 1..8 */
} rd_gl_pass;
int rd_gl_open(const char *backend); /* "osmesa" | "egl" | NULL (SHLIGHT_GL_BACKEND) */
void rd_gl_close(void);
const char *rd_gl_renderer(void);
int rd_gl_run(const rd_scene *s, const rd_gbuf *gb, const rd_gl_pass *p, float *const *out,
              int reps, double *ms);

/* ---- passes ---------------------------------------------------------------------------- */
/* Each pass runs its methods on run->scene / run->gb on the paths run->use_gl / use_cpu, the
 * ground truth when run->gt, and hands every image to rd_emit. Returns 0, or -1 on an error
 * (message on stderr); a pass with nothing to do in the scene (no lights of its kind) emits
 * nothing and returns 0. */
int rd_pass_grid(rd_run *run);    /* sphere/triangle lights: per-pixel SH and the SH grid */
int rd_pass_area(rd_run *run);    /* polygon/sphere/disc area lights, Lambert + Phong/GGX */
int rd_pass_hvl(rd_run *run);     /* one-bounce GI from a spot light's RSM: VPLs vs HVLs */
int rd_pass_ssf(rd_run *run);     /* instant GI, interleaved VPLs, screen-space SH filter */
int rd_pass_preview(rd_run *run); /* albedo x head-light cosine: shows the G-buffer */

/* small vector helpers */
static inline float rd_dot(const float a[3], const float b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
#endif
