/* glrun.h - run GLSL functions on arrays of inputs and read the results back, for tests that
 * compare shlight's GLSL kernels with their C twins. One call per run; the GL context (see
 * glctx.h) is opened on first use and reused until glrun_close().
 *
 * Shader source, in this order (each part after the header preceded by `#line 1 "<name>"`,
 * so compile errors read `"shl_basis.glsl":12(3): error: ...`):
 *   version line; `#extension GL_ARB_shading_language_include : enable` (needed for named
 *   #line; desktop GLSL only, ES versions get numbered #lines and a legend on failure);
 *   `precision highp float; precision highp int;` for ES versions; `defines` ("defines");
 *   each of `files` read from disk, relative to the working directory (named by basename);
 *   the harness prefix below ("glrun_prefix"); `main_src` ("main_src"); the harness main.
 *
 * Data layout, the same for both paths: item i (0 <= i < count) owns the floats
 * in[i*IN .. i*IN+IN-1] and out[i*OUT .. i*OUT+OUT-1], where IN/OUT are floats per item.
 * `main_src` defines `void glrun_main(int item)` (declared by the harness; `main` is the
 * harness's) and uses, for its own item:
 *   in_float(j)       the item's input float j            (0 <= j < GLRUN_IN_STRIDE)
 *   in_vec4(k)        its floats 4k..4k+3 as a vec4
 *   out_float(j, v)   write output float j                (0 <= j < GLRUN_OUT_STRIDE)
 *   out_vec4(k, v)    write output floats 4k..4k+3
 *   GLRUN_COUNT, GLRUN_IN_STRIDE, GLRUN_OUT_STRIDE   (int macros)
 * Outputs that the shader does not write read back as NaN. So one main_src can serve both
 * paths, e.g.
 *   "void glrun_main(int item) {\n"
 *   "  float y[4];\n"
 *   "  toy_poly(in_vec4(0).xyz, y);\n"
 *   "  out_vec4(0, vec4(y[0], y[1], y[2], y[3]));\n"
 *   "}\n"
 *
 * Compute path: `#version 450` by default, local_size_x = 64, ceil(count / 64) groups; the
 * buffers are also visible as `float glrun_in[]` (std430, binding 0) and `float glrun_out[]`
 * (binding 1); IN = n_in / count, OUT = n_out / count. Compute shaders keep denormals.
 * Fragment path: `#version 330` by default (GLSL ES 3.00 class code); items are pixels of a
 * W x H grid (W = min(count, 256)), inputs texels of an RGBA32F texture read with texelFetch,
 * outputs go to up to 8 RGBA32F colour attachments; IN = 4 * in_vec4_per_item (0..64),
 * OUT = 4 * out_vec4_per_item (1..8). Pixels past `count` in the last row run with zero
 * inputs and are discarded. llvmpipe's fragment stage flushes denormal arithmetic results
 * to zero (a plain copy passes them through). Only "#version 300 es" enforces the ES rules
 * (no implicit int -> float, ...); Mesa compiles it in the desktop 4.5 context.
 *
 * All functions return 0 on success and -1 on failure, with a message (and the compiler's
 * info log) on stderr. */
#ifndef SHLIGHT_GLRUN_H
#define SHLIGHT_GLRUN_H

#include <stddef.h>

/* Open the context now on the given backend ("osmesa", "egl"; NULL: SHLIGHT_GL_BACKEND, else
 * osmesa). Optional: the run functions open the default one on first use. */
int glrun_open(const char *backend);

/* Release the context (call before exit so leak checkers stay quiet). */
void glrun_close(void);

/* Backend name ("osmesa" / "egl") and GL_RENDERER of the context (opened if needed);
 * "" / "(no context)" when no context can be created. For test reports; valid until
 * glrun_close(). */
const char *glrun_backend(void);
const char *glrun_renderer(void);

/* #version lines used by later runs; NULL keeps the current one. Defaults "#version 450"
 * (compute) and "#version 330" (fragment); e.g. "#version 310 es", "#version 300 es".
 * The strings are not copied: pass literals or storage that outlives the runs. */
void glrun_set_versions(const char *compute_version, const char *fragment_version);

/* Compiler/linker log of the last failed build ("" when the last build succeeded). */
const char *glrun_last_log(void);

/* Compute path: n_in floats in (may be NULL when n_in is 0), n_out floats out, count items
 * (1 .. 4,194,240). defines may be NULL; files may be NULL when nfiles is 0. */
int glrun_compute(const char *defines, const char *const *files, int nfiles, const char *main_src,
                  const float *in, size_t n_in, float *out, size_t n_out, int count);

/* Fragment path: in holds count * in_vec4_per_item * 4 floats (NULL when in_vec4_per_item is
 * 0), out receives count * out_vec4_per_item * 4 floats. count: 1 .. 256 * 16384. */
int glrun_fragment(const char *defines, const char *const *files, int nfiles, const char *main_src,
                   const float *in, int in_vec4_per_item, float *out, int out_vec4_per_item,
                   int count);

#endif
