# bench/bench.mk - benchmarks (DESIGN.md section 6). Included by the top Makefile; alone:
#   make -f bench/bench.mk               builds build/bench/bench_basis
#   make -f bench/bench.mk bench-basis   callgrind counts, then the timed run (tables in bench/out/)
#   (`make bench` in the top Makefile runs bench-basis)
#   make -f bench/bench.mk bench-basis BENCH_ARGS=--quick
# Run from the repository root. Variables are BENCH_-prefixed so the including Makefile's
# CC / CFLAGS are left alone; include this after the including Makefile's default target.

BENCH_CC ?= gcc
BENCH_CFLAGS ?= -std=c99 -O3 -march=native -ffp-contract=fast -DNDEBUG
BENCH_WARN ?= -Wall -Wextra
BENCH_LDLIBS ?= -lquadmath -lm
BENCH_ARGS ?=
BENCH_CG_NS ?= 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 32 64
# which shlight.h was measured: commit, "+dirty" and the file's git blob id when the working
# copy differs from the commit
BENCH_REV := $(shell git rev-parse --short HEAD 2>/dev/null)$(shell git diff --quiet HEAD -- shlight.h 2>/dev/null || echo "+dirty, blob `git hash-object shlight.h | cut -c1-10`")

build/bench/bench_basis: bench/bench_basis.c shlight.h tests/ref/published.h tests/ref/shref.h
	@mkdir -p build/bench
	$(BENCH_CC) $(BENCH_CFLAGS) $(BENCH_WARN) -DBENCH_FLAGS='"$(BENCH_CC) $(BENCH_CFLAGS)"' \
	  -DBENCH_REV='"$(BENCH_REV)"' \
	  -o $@ bench/bench_basis.c $(BENCH_LDLIBS)

bench-basis: build/bench/bench_basis
	CC=$(BENCH_CC) sh bench/callgrind.sh "$(BENCH_CG_NS)"
	build/bench/bench_basis --callgrind bench/out/instr.csv $(BENCH_ARGS)

bench: bench-basis

.PHONY: bench bench-basis

# shl_sh_eval_batch at any count (count 16 .. 65536, n = 3, 6, 10, 16); bench/baseline.sh runs it
# against an older shlight.h in the same run
bench-batch: build/bench/bench_batch
	@mkdir -p bench/out
	build/bench/bench_batch | tee bench/out/batch.md

bench: bench-batch
.PHONY: bench-batch

# the store floors of the batch's output layout (bandwidth of one core to L1 / L2 / memory, and
# the batch's store pattern without arithmetic): docs/speed-batch.md
build/bench/bench_store: bench/bench_store.c bench/bench_util.h
	@mkdir -p build/bench
	$(BENCH_CC) $(BENCH_CFLAGS) $(BENCH_WARN) -o $@ bench/bench_store.c -lm

bench-store: build/bench/bench_store
	@mkdir -p bench/out
	build/bench/bench_store | tee bench/out/store.md
.PHONY: bench-store

# the bench programs that need only -lm (their extra headers are listed with each)
build/bench/bench_%: bench/bench_%.c shlight.h bench/bench_util.h
	@mkdir -p build/bench
	$(BENCH_CC) $(BENCH_CFLAGS) $(BENCH_WARN) -o $@ $(filter %.c,$^) -lm

# bench_area NAME: bench-NAME runs bench/callgrind_NAME.sh, then the timed build/bench/bench_NAME,
# and shows bench/out/NAME.md
define bench_area
bench-$(1): build/bench/bench_$(1)
	@mkdir -p bench/out
	CC=$$(BENCH_CC) sh bench/callgrind_$(1).sh
	build/bench/bench_$(1)
	cat bench/out/$(1).md

bench: bench-$(1)
.PHONY: bench-$(1)
endef

build/bench/bench_light: bench/bench_light.c shlight.h tests/ref/published.h bench/bench_util.h tests/ref/lightref.h \
  tests/ref/shref.h
	@mkdir -p build/bench
	$(BENCH_CC) $(BENCH_CFLAGS) $(BENCH_WARN) -DBENCH_FLAGS='"$(BENCH_CC) $(BENCH_CFLAGS)"' \
	  -DBENCH_REV='"$(BENCH_REV)"' -o $@ bench/bench_light.c $(BENCH_LDLIBS)

bench-light: build/bench/bench_light
	@mkdir -p bench/out
	CC=$(BENCH_CC) sh bench/callgrind_light.sh
	build/bench/bench_light
	cat bench/out/light_instr.md

bench: bench-light
.PHONY: bench-light

build/bench/bench_grid: bench/bench_grid.c shlight.h
	@mkdir -p build/bench
	$(BENCH_CC) $(BENCH_CFLAGS) -o $@ bench/bench_grid.c -lm -pthread

bench-grid: build/bench/bench_grid
	build/bench/bench_grid | tee bench/out/grid.md

bench: bench-grid
.PHONY: bench-grid

build/bench/bench_edge: tests/ref/arearef.h
$(eval $(call bench_area,edge))

build/bench/bench_microfacet: tests/ref/arearef.h
$(eval $(call bench_area,microfacet))

build/bench/bench_ggx: tests/ref/arearef.h tests/ref/ggxcases.h tests/test_ggx_portable.c
$(eval $(call bench_area,ggx))


bench-brdf: build/bench/bench_brdf
	@mkdir -p bench/out
	build/bench/bench_brdf

bench: bench-brdf
.PHONY: bench-brdf

build/bench/bench_brdftab: bench/bench_brdftab.c shlight.h tests/ref/shref.h
	@mkdir -p build/bench
	$(BENCH_CC) $(BENCH_CFLAGS) $(BENCH_WARN) -o $@ bench/bench_brdftab.c $(BENCH_LDLIBS)

bench-brdftab: build/bench/bench_brdftab
	@mkdir -p bench/out
	build/bench/bench_brdftab && cat bench/out/brdftab.md

bench: bench-brdftab
.PHONY: bench-brdftab

# the GLSL solid angle's float error, reproduced by a float twin of the C kernel
SOLID_N ?= 2000000
build/bench/solid_angle_float: bench/solid_angle_float.c
	@mkdir -p build/bench
	$(BENCH_CC) -std=c99 -O2 -ffp-contract=off $(BENCH_WARN) -o $@ bench/solid_angle_float.c \
	  -lquadmath -lm

bench-solid-float: build/bench/solid_angle_float
	build/bench/solid_angle_float $(SOLID_N)
.PHONY: bench-solid-float

# shl_sh_rotate against its portable kernel (a second translation unit,
# tests/test_rotate_portable.c), re-projection and stored band matrices; DirectXMath's
# XMSHRotate joins with a C++ build, see docs/rotation.md
build/bench/bench_rotate: bench/bench_rotate.c tests/test_rotate_portable.c shlight.h bench/bench_util.h
	@mkdir -p build/bench
	$(BENCH_CC) $(BENCH_CFLAGS) $(BENCH_WARN) -o $@ bench/bench_rotate.c tests/test_rotate_portable.c -lm

bench-rotate: build/bench/bench_rotate
	@mkdir -p bench/out
	build/bench/bench_rotate

bench: bench-rotate
.PHONY: bench-rotate

build/bench/bench_beckmann: tests/ref/arearef.h tests/ref/ggxcases.h
$(eval $(call bench_area,beckmann))

# GLSL compile and run budgets on the headless GL context (bench/glsl_budget.sh)
build/bench/glsl_budget: bench/glsl_budget.c $(GL_SRCS) $(GL_HDRS)
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(GL_CFLAGS) -o $@ bench/glsl_budget.c $(GL_SRCS) $(LDFLAGS) $(GL_LIBS)
