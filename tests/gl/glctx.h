/* glctx.h - a headless OpenGL 4.5 core context for shlight's GLSL tests.
 *
 * Two backends, chosen at run time: "osmesa" (the default) and "egl" (EGL with Mesa's
 * surfaceless platform: no display, no config, no surface). Both give llvmpipe on a machine
 * without a GPU. GL entry points are loaded into the struct `gl` (call `gl.CreateShader(...)`);
 * there is no GLEW/GLAD and no link-time dependency on libGL.
 *
 * Environment:
 *   SHLIGHT_GL_BACKEND=osmesa|egl  backend when glctx_open() gets NULL (default osmesa,
 *                                  egl in a build without OSMesa)
 *   SHLIGHT_GL_ANY_RENDERER=1      accept a renderer other than llvmpipe (e.g. a real GPU)
 * Build: -DGLCTX_NO_OSMESA or -DGLCTX_NO_EGL leave a backend out (OSMesa is gone from
 * Mesa >= 25.1); link with `pkg-config --libs osmesa egl` (or the one that is left). */
#ifndef SHLIGHT_GLCTX_H
#define SHLIGHT_GLCTX_H

#include <GL/glcorearb.h> /* must come before GL/osmesa.h (which pulls in GL/gl.h) */

/* X(pointer type, name without the gl prefix): every GL function the harness uses. */
#define GLCTX_FUNCS(X) \
  X(PFNGLGETSTRINGPROC, GetString) \
  X(PFNGLGETSTRINGIPROC, GetStringi) \
  X(PFNGLGETINTEGERVPROC, GetIntegerv) \
  X(PFNGLGETERRORPROC, GetError) \
  X(PFNGLCREATESHADERPROC, CreateShader) \
  X(PFNGLSHADERSOURCEPROC, ShaderSource) \
  X(PFNGLCOMPILESHADERPROC, CompileShader) \
  X(PFNGLGETSHADERIVPROC, GetShaderiv) \
  X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog) \
  X(PFNGLDELETESHADERPROC, DeleteShader) \
  X(PFNGLCREATEPROGRAMPROC, CreateProgram) \
  X(PFNGLATTACHSHADERPROC, AttachShader) \
  X(PFNGLLINKPROGRAMPROC, LinkProgram) \
  X(PFNGLGETPROGRAMIVPROC, GetProgramiv) \
  X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog) \
  X(PFNGLDELETEPROGRAMPROC, DeleteProgram) \
  X(PFNGLUSEPROGRAMPROC, UseProgram) \
  X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation) \
  X(PFNGLUNIFORM1IPROC, Uniform1i) \
  X(PFNGLGENBUFFERSPROC, GenBuffers) \
  X(PFNGLDELETEBUFFERSPROC, DeleteBuffers) \
  X(PFNGLBINDBUFFERPROC, BindBuffer) \
  X(PFNGLBINDBUFFERBASEPROC, BindBufferBase) \
  X(PFNGLBUFFERDATAPROC, BufferData) \
  X(PFNGLCLEARBUFFERDATAPROC, ClearBufferData) \
  X(PFNGLGETBUFFERSUBDATAPROC, GetBufferSubData) \
  X(PFNGLDISPATCHCOMPUTEPROC, DispatchCompute) \
  X(PFNGLMEMORYBARRIERPROC, MemoryBarrier) \
  X(PFNGLGENTEXTURESPROC, GenTextures) \
  X(PFNGLDELETETEXTURESPROC, DeleteTextures) \
  X(PFNGLACTIVETEXTUREPROC, ActiveTexture) \
  X(PFNGLBINDTEXTUREPROC, BindTexture) \
  X(PFNGLTEXIMAGE2DPROC, TexImage2D) \
  X(PFNGLTEXPARAMETERIPROC, TexParameteri) \
  X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers) \
  X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers) \
  X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer) \
  X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D) \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus) \
  X(PFNGLDRAWBUFFERSPROC, DrawBuffers) \
  X(PFNGLREADBUFFERPROC, ReadBuffer) \
  X(PFNGLREADPIXELSPROC, ReadPixels) \
  X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays) \
  X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays) \
  X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray) \
  X(PFNGLVIEWPORTPROC, Viewport) \
  X(PFNGLDRAWARRAYSPROC, DrawArrays) \
  X(PFNGLFINISHPROC, Finish) \
  X(PFNGLUNIFORM2IPROC, Uniform2i) \
  X(PFNGLUNIFORM3FPROC, Uniform3f)

#define GLCTX_MEMBER(type, name) type name;
struct glctx_gl {
  GLCTX_FUNCS(GLCTX_MEMBER)
};
#undef GLCTX_MEMBER

/* The loaded entry points; valid between a successful glctx_open() and glctx_close(). */
extern struct glctx_gl gl;

/* Create a GL 4.5 core context, make it current on this thread and load `gl`.
 * backend: "osmesa" or "egl"; NULL or "" reads SHLIGHT_GL_BACKEND, else "osmesa".
 * Prints one line "glctx: <backend> | <GL_RENDERER> | <GL_VERSION>" to stdout and refuses
 * (returns -1) a renderer that does not start with "llvmpipe" unless SHLIGHT_GL_ANY_RENDERER=1.
 * Returns 0 on success (also when a context is already open), -1 with a message on stderr. */
int glctx_open(const char *backend);

/* Destroy the context (no-op when none is open). */
void glctx_close(void);

/* "osmesa" or "egl" while a context is open, else "". */
const char *glctx_backend(void);

/* 1 when the current context lists the extension in GL_EXTENSIONS (the getprocs return
 * non-NULL stubs for unknown names, so a NULL check proves nothing). */
int glctx_has_extension(const char *name);

#endif
