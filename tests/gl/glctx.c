/* glctx.c - headless OpenGL 4.5 core context: OSMesa or EGL surfaceless (see glctx.h). */
#include "glctx.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct glctx_gl gl;

typedef void (*glctx_proc)(void);
static const char *cur_backend = "";
static void (*close_fn)(void);

static int load(glctx_proc (*getproc)(const char *)) {
  int missing = 0;
#define GLCTX_LOAD_ONE(type, name) \
  gl.name = (type)getproc("gl" #name); \
  if (!gl.name) { \
    fprintf(stderr, "glctx: no entry point gl" #name "\n"); \
    missing++; \
  }
  GLCTX_FUNCS(GLCTX_LOAD_ONE)
#undef GLCTX_LOAD_ONE
  return missing ? -1 : 0;
}

#ifndef GLCTX_NO_OSMESA
#include <GL/osmesa.h>
static OSMesaContext os_ctx;
static unsigned char os_pixel[4]; /* 1x1 default framebuffer; results go to FBOs and SSBOs */
static glctx_proc os_getproc(const char *name) {
  return (glctx_proc)OSMesaGetProcAddress(name);
}
static void os_close(void) {
  OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
  OSMesaDestroyContext(os_ctx);
}
static int os_open(void) {
  /* clang-format off */
  const int attr[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0, OSMESA_STENCIL_BITS, 0,
                      OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                      OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 5, 0};
  /* clang-format on */
  if (!(os_ctx = OSMesaCreateContextAttribs(attr, NULL)))
    return fprintf(stderr, "glctx: OSMesaCreateContextAttribs(4.5 core) failed\n"), -1;
  close_fn = os_close;
  if (!OSMesaMakeCurrent(os_ctx, os_pixel, GL_UNSIGNED_BYTE, 1, 1))
    return fprintf(stderr, "glctx: OSMesaMakeCurrent failed\n"), -1;
  return load(os_getproc);
}
#endif

#ifndef GLCTX_NO_EGL
#include <EGL/egl.h>
#include <EGL/eglext.h>
#if defined(__SANITIZE_ADDRESS__) /* gcc */
#define GLCTX_ASAN 1
#elif defined(__has_feature) /* clang */
#if __has_feature(address_sanitizer)
#define GLCTX_ASAN 1
#endif
#endif
static EGLDisplay egl_dpy = EGL_NO_DISPLAY;
static EGLContext egl_ctx = EGL_NO_CONTEXT;
static glctx_proc egl_getproc(const char *name) {
  return (glctx_proc)eglGetProcAddress(name);
}
static void egl_close(void) {
  eglMakeCurrent(egl_dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (egl_ctx != EGL_NO_CONTEXT) eglDestroyContext(egl_dpy, egl_ctx);
#ifndef GLCTX_ASAN /* eglTerminate unloads swrast_dri.so: LSan could not symbolise its blocks */
  eglTerminate(egl_dpy);
#endif
  eglReleaseThread();
  egl_dpy = EGL_NO_DISPLAY, egl_ctx = EGL_NO_CONTEXT;
}
static int egl_open(void) {
  /* clang-format off */
  const EGLint attr[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                         EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                         EGL_NONE};
  /* clang-format on */
  /* Mesa's surfaceless platform needs no X11, Wayland or /dev/dri (falls back to llvmpipe) */
  egl_dpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
  if (egl_dpy == EGL_NO_DISPLAY || !eglInitialize(egl_dpy, NULL, NULL))
    return fprintf(stderr, "glctx: EGL surfaceless display: error 0x%x\n", eglGetError()), -1;
  close_fn = egl_close;
  /* EGL_KHR_no_config_context + EGL_KHR_surfaceless_context: no config, no surface */
  if (!eglBindAPI(EGL_OPENGL_API) ||
      (egl_ctx = eglCreateContext(egl_dpy, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attr)) ==
          EGL_NO_CONTEXT ||
      !eglMakeCurrent(egl_dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, egl_ctx))
    return fprintf(stderr, "glctx: EGL 4.5 core context: error 0x%x\n", eglGetError()), -1;
  return load(egl_getproc);
}
#endif

int glctx_open(const char *backend) {
  const char *any = getenv("SHLIGHT_GL_ANY_RENDERER"), *renderer;
  int rc = -1;
  if (close_fn) return 0;
  if (!backend || !*backend) backend = getenv("SHLIGHT_GL_BACKEND");
  if (!backend || !*backend)
#ifndef GLCTX_NO_OSMESA
    backend = "osmesa";
#else
    backend = "egl";
#endif
#ifndef GLCTX_NO_OSMESA
  if (!strcmp(backend, "osmesa")) cur_backend = "osmesa", rc = os_open();
#endif
#ifndef GLCTX_NO_EGL
  if (!strcmp(backend, "egl")) cur_backend = "egl", rc = egl_open();
#endif
  if (!*cur_backend) fprintf(stderr, "glctx: backend '%s' is not built in\n", backend);
  if (rc) return glctx_close(), -1;
  renderer = (const char *)gl.GetString(GL_RENDERER);
  printf("glctx: %s | %s | %s\n", cur_backend, renderer ? renderer : "?",
         (const char *)gl.GetString(GL_VERSION));
  fflush(stdout);
  if (!renderer || (strncmp(renderer, "llvmpipe", 8) && !(any && !strcmp(any, "1")))) {
    fprintf(stderr, "glctx: renderer is not llvmpipe (set SHLIGHT_GL_ANY_RENDERER=1 to accept)\n");
    return glctx_close(), -1;
  }
  return 0;
}

void glctx_close(void) {
  if (close_fn) close_fn();
  close_fn = NULL;
  cur_backend = "";
  memset(&gl, 0, sizeof gl);
}

const char *glctx_backend(void) {
  return cur_backend;
}

int glctx_has_extension(const char *name) {
  GLint i, n = 0;
  gl.GetIntegerv(GL_NUM_EXTENSIONS, &n);
  for (i = 0; i < n; i++)
    if (!strcmp((const char *)gl.GetStringi(GL_EXTENSIONS, (GLuint)i), name)) return 1;
  return 0;
}
