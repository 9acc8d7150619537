# tests/gl/gl.mk - headless GLSL harness (tests/gl/glctx.c, glrun.c) and its self-test.
# Included by the top Makefile; paths are relative to the repository root. Standalone:
#   make -f tests/gl/gl.mk gl-test          build/tests/test_gl_smoke on OSMesa and on EGL
#   make -f tests/gl/gl.mk gl-test-asan     the same with -fsanitize=address,undefined
#   make -f tests/gl/gl.mk glsl-validate    tools/glsl_validate.sh [$(GLSL_VALIDATE_FILES)]
# A GLSL test of your own:
#   build/tests/test_x: tests/test_x.c $(GL_SRCS) $(GL_HDRS)
#   	$(CC) $(CFLAGS) $(GL_CFLAGS) -o $@ tests/test_x.c $(GL_SRCS) $(LDFLAGS) $(GL_LIBS)
# GL_CFLAGS comes after CFLAGS: it adds -ffp-contract=off, which anything compared with GLSL
# bit for bit needs (llvmpipe never fuses a*b+c).

GL_SAVED_DEFAULT_GOAL := $(.DEFAULT_GOAL)

GL_BUILD ?= build
CFLAGS ?= -std=c99 -O2 -g -Wall -Wextra -Wpedantic -Wconversion
GL_ASAN_FLAGS ?= -fsanitize=address,undefined -fno-sanitize-recover=undefined \
                 -fno-omit-frame-pointer

# backends: whatever pkg-config finds (OSMesa is gone from Mesa >= 25.1)
GL_HAVE_OSMESA := $(shell pkg-config --exists osmesa && echo yes)
GL_HAVE_EGL := $(shell pkg-config --exists egl && echo yes)
GL_PKGS := $(strip $(if $(GL_HAVE_OSMESA),osmesa) $(if $(GL_HAVE_EGL),egl))
GL_BACKENDS := $(if $(GL_HAVE_OSMESA),osmesa) $(if $(GL_HAVE_EGL),egl)

GL_CFLAGS := -D_POSIX_C_SOURCE=200809L -ffp-contract=off \
             $(if $(GL_PKGS),$(shell pkg-config --cflags $(GL_PKGS))) \
             $(if $(GL_HAVE_OSMESA),,-DGLCTX_NO_OSMESA) $(if $(GL_HAVE_EGL),,-DGLCTX_NO_EGL)
GL_LIBS := $(if $(GL_PKGS),$(shell pkg-config --libs $(GL_PKGS))) -lm
GL_SRCS := tests/gl/glctx.c tests/gl/glrun.c
GL_HDRS := tests/gl/glctx.h tests/gl/glrun.h
GL_SMOKE_DEPS := tests/gl/test_gl_smoke.c tests/gl/toy.glsl tests/tl.h $(GL_SRCS) $(GL_HDRS)

$(GL_BUILD)/tests/test_gl_smoke: $(GL_SMOKE_DEPS)
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(GL_CFLAGS) -o $@ tests/gl/test_gl_smoke.c $(GL_SRCS) $(LDFLAGS) $(GL_LIBS)

$(GL_BUILD)/tests/asan/test_gl_smoke: $(GL_SMOKE_DEPS)
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(GL_ASAN_FLAGS) $(GL_CFLAGS) -o $@ tests/gl/test_gl_smoke.c $(GL_SRCS) \
	    $(LDFLAGS) $(GL_LIBS)

.PHONY: gl-test gl-test-asan glsl-validate
gl-test: $(GL_BUILD)/tests/test_gl_smoke
	@set -e; for b in $(GL_BACKENDS); do SHLIGHT_GL_BACKEND=$$b $<; done

# LSan: libOSMesa leaks 480 bytes in OSMesaCreateContextAttribs (Mesa bug) -> lsan.supp.
# Never add ASAN_OPTIONS=fast_unwind_on_malloc=0: it deadlocks in llvmpipe's JIT.
gl-test-asan: $(GL_BUILD)/tests/asan/test_gl_smoke
	@set -e; for b in $(GL_BACKENDS); do \
	    SHLIGHT_GL_BACKEND=$$b LSAN_OPTIONS=suppressions=tests/gl/lsan.supp:print_suppressions=0 \
	    UBSAN_OPTIONS=print_stacktrace=1 $<; done

glsl-validate:
	tools/glsl_validate.sh $(GLSL_VALIDATE_FILES)

# do not become the including Makefile's default goal
.DEFAULT_GOAL := $(GL_SAVED_DEFAULT_GOAL)
