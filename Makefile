# shlight - build, test, bench. Targets:
#   make example      build and run examples/hello_sh and examples/lights (C99 and C++11)
#   make test         everything CI runs; ends with "N passed, N failed"
#   make bench        speed against error tables (bench/out/), callgrind instruction counts
#   make fuzz         libFuzzer run of the basis entry point (FUZZ_SECONDS, default 60)
#   make fuzz-brdftab libFuzzer run of the BRDF table loaders (SHLT, MERL), niced, one core
#   make gen          regenerate the straight-line code and the GLSL twins (tools/gen_basis.py)
#   make format       clang-format the hand-written sources
CC ?= gcc
CXX ?= g++
PYTHON ?= /usr/bin/python3
BUILD := build
WARN := -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Wdouble-promotion -Wcast-qual \
        -Wstrict-prototypes -Wmissing-prototypes -Werror
WARNXX := -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Wdouble-promotion -Wcast-qual -Werror
CFLAGS ?= -std=c99 -O2 -g
LDLIBS := -lm

.DEFAULT_GOAL := all
.PHONY: all example test test-glsl-full bench fuzz gen format format-check compile-matrix clean

all: $(BUILD)/examples/hello_sh $(BUILD)/examples/lights $(BUILD)/examples/lights_cxx

include tests/gl/gl.mk
-include tests/tests.mk
-include bench/bench.mk

$(BUILD)/examples/hello_sh: examples/hello_sh.c shlight.h
	@mkdir -p $(@D)
	$(CC) -std=c99 -O2 $(WARN) -o $@ $< $(LDLIBS)

$(BUILD)/examples/lights: examples/lights.c shlight.h
	@mkdir -p $(@D)
	$(CC) -std=c99 -O2 $(WARN) -o $@ $< $(LDLIBS)

$(BUILD)/examples/lights_cxx: examples/lights.c shlight.h
	@mkdir -p $(@D)
	$(CXX) -std=c++11 -O2 $(WARNXX) -x c++ -o $@ $< $(LDLIBS)

example: $(BUILD)/examples/hello_sh $(BUILD)/examples/lights $(BUILD)/examples/lights_cxx
	$(BUILD)/examples/hello_sh
	$(BUILD)/examples/lights

# the implementation, compiled once for the GL tests (they include shlight.h without it)
$(BUILD)/tests/impl_c.o: tests/impl_c.c shlight.h
	@mkdir -p $(@D)
	$(CC) -std=c99 -O2 -g1 -ffp-contract=off $(WARN) -c -o $@ tests/impl_c.c

# GLSL twins against C on llvmpipe
$(BUILD)/tests/test_glsl: tests/test_glsl.c shlight.h tests/tl.h $(GL_SRCS) $(GL_HDRS) $(BUILD)/tests/impl_c.o
	@mkdir -p $(@D)
	$(CC) -std=c99 -O2 -g1 -Wall -Wextra -Wpedantic -Wconversion -Werror $(GL_CFLAGS) \
	    -o $@ tests/test_glsl.c $(GL_SRCS) $(BUILD)/tests/impl_c.o $(GL_LIBS)

# compile matrix: C99/C11/C++98/11/17/20, gcc and clang, SHLIGHT_STATIC, two TUs linked
MATRIX_DIR := $(BUILD)/matrix
MATRIX_C := gcc-c99 gcc-c11 clang-c99 clang-c11
MATRIX_CXX := g++-c++98 g++-c++11 g++-c++17 g++-c++20 clang++-c++98 clang++-c++11 clang++-c++17 \
              clang++-c++20
MATRIX_SIMD := x86-64 x86-64-v3 native
MATRIX_DEPS := tests/matrix_a.c tests/matrix_b.c shlight.h
# one target per configuration, so `make -j2 compile-matrix` uses both cores
$(MATRIX_DIR)/c-%.ok: $(MATRIX_DEPS)
	@mkdir -p $(@D)
	@set -e; cc=$(word 1,$(subst -, ,$*)); std=$(word 2,$(subst -, ,$*)); o=$(MATRIX_DIR)/$*; \
	  $$cc -std=$$std -O1 $(WARN) -c tests/matrix_a.c -o $$o-a.o; \
	  $$cc -std=$$std -O1 $(WARN) -c tests/matrix_b.c -o $$o-b.o; \
	  $$cc -o $$o-ab $$o-a.o $$o-b.o -lm; $$o-ab; \
	  $$cc -std=$$std -O1 $(WARN) -DSHLIGHT_STATIC -DSHLIGHT_NO_SIMD -o $$o-st tests/matrix_a.c \
	    -DMATRIX_ALONE -lm; $$o-st; touch $@
$(MATRIX_DIR)/cxx-%.ok: $(MATRIX_DEPS)
	@mkdir -p $(@D)
	@set -e; cxx=$(word 1,$(subst -, ,$*)); std=$(word 2,$(subst -, ,$*)); o=$(MATRIX_DIR)/$*; \
	  $$cxx -x c++ -std=$$std -O1 $(WARNXX) -c tests/matrix_a.c -o $$o-a.o; \
	  $$cxx -x c++ -std=$$std -O1 $(WARNXX) -c tests/matrix_b.c -o $$o-b.o; \
	  $$cxx -o $$o-ab $$o-a.o $$o-b.o -lm; $$o-ab; touch $@
$(MATRIX_DIR)/simd-%.ok: $(MATRIX_DEPS)
	@mkdir -p $(@D)
	@set -e; gcc -std=c99 -O2 -march=$* $(WARN) -o $(MATRIX_DIR)/simd_$* tests/matrix_a.c \
	  -DMATRIX_ALONE -lm; $(MATRIX_DIR)/simd_$*; touch $@
MATRIX_OKS := $(MATRIX_C:%=$(MATRIX_DIR)/c-%.ok) $(MATRIX_CXX:%=$(MATRIX_DIR)/cxx-%.ok) \
              $(MATRIX_SIMD:%=$(MATRIX_DIR)/simd-%.ok)
compile-matrix:
	@rm -f $(MATRIX_OKS)
	@$(MAKE) --no-print-directory $(MATRIX_OKS)
	@echo "compile matrix: 1 passed, 0 failed"

gen:
	$(PYTHON) tools/gen_basis.py

FORMAT_FILES := shlight.h render/*.c render/*.h examples/*.c tests/*.c tests/*.h tests/*.cpp tests/gl/*.c tests/gl/*.h bench/*.c bench/*.h
format:
	clang-format -i $(wildcard $(FORMAT_FILES))
format-check:
	clang-format --dry-run -Werror $(wildcard $(FORMAT_FILES))

test:
	bash tests/run.sh

# the GLSL-vs-C test with the shaders the default run leaves out (the 16-band gradient: ~85 s
# of llvmpipe compile)
test-glsl-full: $(BUILD)/tests/test_glsl
	SHLIGHT_GLSL_FULL=1 $(BUILD)/tests/test_glsl

clean:
	rm -rf $(BUILD)

$(BUILD)/tests/test_grid_glsl: tests/test_grid_glsl.c shlight.h tests/tl.h $(GL_SRCS) $(GL_HDRS) $(BUILD)/tests/impl_c.o
	@mkdir -p $(@D)
	$(CC) -std=c99 -O2 -g1 -Wall -Wextra -Wpedantic -Werror $(GL_CFLAGS) \
	    -o $@ tests/test_grid_glsl.c $(GL_SRCS) $(BUILD)/tests/impl_c.o $(GL_LIBS)

$(BUILD)/tests/test_edge_glsl: tests/test_edge_glsl.c shlight.h tests/tl.h $(GL_SRCS) $(GL_HDRS) $(BUILD)/tests/impl_c.o
	@mkdir -p $(@D)
	$(CC) -std=c99 -O2 -g1 -Wall -Wextra -Wpedantic -Werror $(GL_CFLAGS) \
	    -o $@ tests/test_edge_glsl.c $(GL_SRCS) $(BUILD)/tests/impl_c.o $(GL_LIBS) -lm

$(BUILD)/tests/test_microfacet_glsl: tests/test_microfacet_glsl.c shlight.h tests/tl.h $(GL_SRCS) $(GL_HDRS) $(BUILD)/tests/impl_c.o
	@mkdir -p $(@D)
	$(CC) -std=c99 -O2 -g1 -Wall -Wextra -Wpedantic -Werror $(GL_CFLAGS) \
	    -o $@ tests/test_microfacet_glsl.c $(GL_SRCS) $(BUILD)/tests/impl_c.o $(GL_LIBS) -lm

$(BUILD)/tests/test_ggx_glsl: tests/test_ggx_glsl.c tests/ref/ggxcases.h shlight.h tests/tl.h $(GL_SRCS) $(GL_HDRS) $(BUILD)/tests/impl_c.o
	@mkdir -p $(@D)
	$(CC) -std=c99 -O2 -g1 -Wall -Wextra -Wpedantic -Werror $(GL_CFLAGS) \
	    -o $@ tests/test_ggx_glsl.c $(GL_SRCS) $(BUILD)/tests/impl_c.o $(GL_LIBS) -lm

$(BUILD)/tests/test_brdf_glsl: tests/test_brdf_glsl.c shlight.h tests/tl.h $(GL_SRCS) $(GL_HDRS) $(BUILD)/tests/impl_c.o
	@mkdir -p $(@D)
	$(CC) -std=c99 -O2 -g1 -Wall -Wextra -Wpedantic -Werror $(GL_CFLAGS) \
	    -o $@ tests/test_brdf_glsl.c $(GL_SRCS) $(BUILD)/tests/impl_c.o $(GL_LIBS)

$(BUILD)/tests/test_brdftab_glsl: tests/test_brdftab_glsl.c shlight.h tests/tl.h $(GL_SRCS) $(GL_HDRS) $(BUILD)/tests/impl_c.o
	@mkdir -p $(@D)
	$(CC) -std=c99 -O2 -g1 -Wall -Wextra -Wpedantic -Werror $(GL_CFLAGS) \
	    -o $@ tests/test_brdftab_glsl.c $(GL_SRCS) $(BUILD)/tests/impl_c.o $(GL_LIBS)

$(BUILD)/tests/test_rotate_glsl: tests/test_rotate_glsl.c shlight.h tests/tl.h $(GL_SRCS) $(GL_HDRS) $(BUILD)/tests/impl_c.o
	@mkdir -p $(@D)
	$(CC) -std=c99 -O2 -g1 -Wall -Wextra -Wpedantic -Werror $(GL_CFLAGS) \
	    -o $@ tests/test_rotate_glsl.c $(GL_SRCS) $(BUILD)/tests/impl_c.o $(GL_LIBS)

# shlrender: the headless renderer (render/), on the tests' GL context (tests/gl/glctx.c)
# (application code: double where it helps, so no -Wdouble-promotion)
RENDER_SRCS := $(wildcard render/*.c)
RENDER_OBJS := $(patsubst render/%.c,$(BUILD)/render/%.o,$(RENDER_SRCS))
RENDER_WARN := $(filter-out -Wdouble-promotion,$(WARN))
RENDER_CFLAGS := -std=c99 -O2 -g1 $(RENDER_WARN) $(GL_CFLAGS) -DRD_GLSL_DIR='"$(CURDIR)/shlight_glsl"'
$(BUILD)/render/%.o: render/%.c render/rd.h shlight.h tests/gl/glctx.h
	@mkdir -p $(@D)
	$(CC) $(RENDER_CFLAGS) -c -o $@ $<
$(BUILD)/render/glctx.o: tests/gl/glctx.c tests/gl/glctx.h
	@mkdir -p $(@D)
	$(CC) $(RENDER_CFLAGS) -c -o $@ $<
$(BUILD)/render/shlrender: $(RENDER_OBJS) $(BUILD)/render/glctx.o
	$(CC) -o $@ $^ $(GL_LIBS) -lpthread

# merl_write: a MERL-format BRDF file from an analytic model (shlrender --brdf; tests/test_render.sh)
$(BUILD)/tools/merl_write: tools/merl_write.c shlight.h
	@mkdir -p $(@D)
	$(CC) -std=c99 -O2 -g1 $(RENDER_WARN) -o $@ tools/merl_write.c -lm

# the scene parser's fuzz target: replay (CI, plain and ASan/UBSan) and libFuzzer (make fuzz-scene)
FUZZ_SCENE_DEPS := tests/fuzz_scene.c tests/fuzz_replay.c render/rd_scene.c render/rd.h
$(BUILD)/tests/fuzz_replay_scene: $(FUZZ_SCENE_DEPS)
	@mkdir -p $(@D)
	$(CC) -std=c99 -O2 -g1 $(RENDER_WARN) -Wno-missing-prototypes -o $@ tests/fuzz_replay.c \
	    tests/fuzz_scene.c render/rd_scene.c -lm
$(BUILD)/tests/asan/fuzz_replay_scene: $(FUZZ_SCENE_DEPS)
	@mkdir -p $(@D)
	$(CC) -std=c99 -O1 -g1 -fsanitize=address,undefined -fno-sanitize-recover=undefined \
	    -o $@ tests/fuzz_replay.c tests/fuzz_scene.c render/rd_scene.c -lm
$(BUILD)/tests/fuzz_scene: tests/fuzz_scene.c render/rd_scene.c render/rd.h
	@mkdir -p $(@D)
	clang -std=c99 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
	    -o $@ tests/fuzz_scene.c render/rd_scene.c -lm
.PHONY: fuzz-scene
fuzz-scene: $(BUILD)/tests/fuzz_scene
	@mkdir -p $(BUILD)/fuzz/scene
	nice $< -max_len=2048 -max_total_time=$(or $(FUZZ_SECONDS),60) $(BUILD)/fuzz/scene tests/corpus/scene

$(BUILD)/tests/test_ssf_glsl: tests/test_ssf_glsl.c shlight.h tests/tl.h $(GL_SRCS) $(GL_HDRS) $(BUILD)/tests/impl_c.o
	@mkdir -p $(@D)
	$(CC) -std=c99 -O2 -g1 -Wall -Wextra -Wpedantic -Werror $(GL_CFLAGS) \
	    -o $@ tests/test_ssf_glsl.c $(GL_SRCS) $(BUILD)/tests/impl_c.o $(GL_LIBS) -lm

# docs/renderer.md's first command: render the default scene (every pass, GL and CPU) to out/
.PHONY: render-example render-results
render-example: $(BUILD)/render/shlrender
	$(BUILD)/render/shlrender --scene cornell --size 256x192 --gt 1 --out out
# docs/renderer.md's results table and images: every scene at 160x120 with the full ground
# truth (opt-in: minutes on 2 cores); writes build/render/results/*.md and PNGs
render-results: $(BUILD)/render/shlrender
	@mkdir -p $(BUILD)/render/results
	@set -e; for s in cornell spheres manylights glossy; do \
	  $(BUILD)/render/shlrender --scene $$s --size 160x120 --gt 2 --reps 5 \
	    --out $(BUILD)/render/results | tee $(BUILD)/render/results/$$s.md; done
$(BUILD)/tests/test_rd_core: tests/test_rd_core.c render/rd_core.c render/rd.h tests/tl.h
	@mkdir -p $(@D)
	$(CC) -std=c99 -O2 -g1 $(RENDER_WARN) -Wno-missing-prototypes -D_POSIX_C_SOURCE=200809L \
	    -o $@ tests/test_rd_core.c render/rd_core.c -lm -lpthread
