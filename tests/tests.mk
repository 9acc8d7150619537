# tests/tests.mk - SH basis tests: quad-reference accuracy tests, GLM rotation tests, fuzzing.
# Included by the top Makefile; paths are relative to the repository root. Standalone:
#   make -f tests/tests.mk tests-basis         build the three programs below
#   make -f tests/tests.mk tests-basis-run     build and run them (each ends "N passed, N failed")
#   make -f tests/tests.mk test-asan           the same three under -fsanitize=address,undefined
#   make -f tests/tests.mk fuzz                libFuzzer run (clang) for FUZZ_SECONDS (default 60)
#   make fuzz-families                          seeded random run of tests/fuzz_families.c (short)
#   make fuzz-families-long                     the same under ASan/UBSan (200000 inputs per
#                                               family), then libFuzzer for FUZZ_SECONDS
# Programs:
#   build/tests/test_basis    tests/test_basis.c vs tests/ref/shref.h (binary128, -lquadmath)
#   build/tests/test_glm      tests/test_glm.cpp (C++11, GLM rotations, header without IMPL)
#   build/tests/fuzz_replay   tests/fuzz_replay.c + tests/fuzz_basis.c: replays a corpus
#                             (default tests/corpus/basis) through the libFuzzer entry point
# Note: make predefines CC (= cc) and CXX (= g++), so the ?= below only matter with make -R.

TESTS_SAVED_DEFAULT_GOAL := $(.DEFAULT_GOAL)

CC ?= gcc
CXX ?= g++
CLANG ?= clang
TESTS_BUILD ?= build/tests
TESTS_WARN ?= -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Wdouble-promotion
TESTS_CFLAGS ?= -std=c99 -O2 -g1 $(TESTS_WARN) -ffp-contract=off
TESTS_CXXFLAGS ?= -std=c++11 -O2 -g1 $(TESTS_WARN) -ffp-contract=off
# -g1 (line tables only) for every test build: a test TU of the header compiles in 8.5 s of CPU
# instead of 12.3 s with -g. ASan: -O1 -g1 (-O2 -g took 87 s per binary on the 30k-line header)
TESTS_ASAN ?= -O1 -g1 -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer
TESTS_QUADLIBS ?= -lquadmath -lm
FUZZ_SECONDS ?= 60

TESTS_BASIS_DEPS := tests/test_basis.c tests/bands_impl.c tests/ref/published.h tests/ref/shref.h tests/tl.h shlight.h
TESTS_GLM_DEPS := tests/test_glm.cpp tests/impl_c.c tests/tl.h shlight.h
TESTS_FUZZ_DEPS := tests/fuzz_replay.c tests/fuzz_basis.c tests/ref/published.h shlight.h

$(TESTS_BUILD)/test_basis: $(TESTS_BASIS_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) -o $@ tests/test_basis.c tests/bands_impl.c $(TESTS_QUADLIBS)

$(TESTS_BUILD)/test_glm: $(TESTS_GLM_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) -c -o $@-impl.o tests/impl_c.c
	$(CXX) $(TESTS_CXXFLAGS) -o $@ tests/test_glm.cpp $@-impl.o -lm

$(TESTS_BUILD)/fuzz_replay: $(TESTS_FUZZ_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) -o $@ tests/fuzz_replay.c tests/fuzz_basis.c -lm

# sanitizer builds (gcc's ASan/UBSan; clang works too: make CC=clang CXX=clang++)
$(TESTS_BUILD)/asan/test_basis: $(TESTS_BASIS_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) $(TESTS_ASAN) -o $@ tests/test_basis.c tests/bands_impl.c $(TESTS_QUADLIBS)

$(TESTS_BUILD)/asan/test_glm: $(TESTS_GLM_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) $(TESTS_ASAN) -c -o $@-impl.o tests/impl_c.c
	$(CXX) $(TESTS_CXXFLAGS) $(TESTS_ASAN) -o $@ tests/test_glm.cpp $@-impl.o -lm

$(TESTS_BUILD)/asan/fuzz_replay: $(TESTS_FUZZ_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) $(TESTS_ASAN) -o $@ tests/fuzz_replay.c tests/fuzz_basis.c -lm

# libFuzzer binary (clang only)
$(TESTS_BUILD)/fuzz_basis: tests/fuzz_basis.c shlight.h
	@mkdir -p $(@D)
	$(CLANG) -std=c99 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
	    -o $@ tests/fuzz_basis.c -lm

.PHONY: tests-basis tests-basis-run test-asan fuzz
tests-basis: $(TESTS_BUILD)/test_basis $(TESTS_BUILD)/test_glm $(TESTS_BUILD)/fuzz_replay

tests-basis-run: tests-basis
	$(TESTS_BUILD)/test_basis
	$(TESTS_BUILD)/test_glm
	$(TESTS_BUILD)/fuzz_replay tests/corpus/basis

# Each program prints its own "N passed, N failed"; the last line sums them for tests/run.sh.
test-asan: $(TESTS_BUILD)/asan/test_basis $(TESTS_BUILD)/asan/test_glm $(TESTS_BUILD)/asan/fuzz_replay
	@p=0; f=0; for t in "$(TESTS_BUILD)/asan/test_basis" "$(TESTS_BUILD)/asan/test_glm" \
	    "$(TESTS_BUILD)/asan/fuzz_replay tests/corpus/basis"; do \
	  out=$$(UBSAN_OPTIONS=print_stacktrace=1 $$t 2>&1); rc=$$?; echo "$$out"; \
	  line=$$(echo "$$out" | grep -E '^[0-9]+ passed, [0-9]+ failed' | tail -n 1); \
	  if [ -n "$$line" ]; then p=$$((p + $${line%% *})); \
	    ff=$$(echo "$$line" | sed -E 's/^[0-9]+ passed, ([0-9]+) failed.*/\1/'); \
	  else ff=0; fi; \
	  if [ $$rc -ne 0 ] && [ $$ff -eq 0 ]; then ff=1; fi; f=$$((f + ff)); \
	done; echo "asan: $$p passed, $$f failed"; [ $$f -eq 0 ]

# copies the seed corpus into a scratch directory so that libFuzzer's additions stay out of git
fuzz: $(TESTS_BUILD)/fuzz_basis
	@mkdir -p $(TESTS_BUILD)/fuzz_corpus
	cp tests/corpus/basis/* $(TESTS_BUILD)/fuzz_corpus/
	$(TESTS_BUILD)/fuzz_basis -max_len=16 -max_total_time=$(FUZZ_SECONDS) \
	    -artifact_prefix=$(TESTS_BUILD)/ $(TESTS_BUILD)/fuzz_corpus

# do not become the including Makefile's default goal
.DEFAULT_GOAL := $(TESTS_SAVED_DEFAULT_GOAL)

# The same tests built for this machine's SIMD (AVX-512 / AVX2 paths of shl_sh_eval and the
# batch), with FMA contraction as a user's -O3 -march=native build would have it.
$(TESTS_BUILD)/native/test_basis: $(TESTS_BASIS_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) -march=native -ffp-contract=fast -o $@ tests/test_basis.c tests/bands_impl.c $(TESTS_QUADLIBS)

# The AVX-512F kernels a machine without AVX-512VL runs (512-bit across-m core, Horner forms),
# on this machine's SIMD with VL turned off; elsewhere the portable paths.
$(TESTS_BUILD)/native-novl/test_simd_novl: tests/test_simd_novl.c tests/ref/shref.h tests/tl.h shlight.h
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) -march=native -mno-avx512vl -ffp-contract=fast -o $@ tests/test_simd_novl.c $(TESTS_QUADLIBS)

# >>zonal / >>light: kernels against binary128 references (tests/ref/lightref.h), and the
# references' own self-checks
$(TESTS_BUILD)/test_light: tests/test_light.c tests/ref/published.h tests/ref/lightref.h tests/ref/shref.h tests/tl.h shlight.h
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) -o $@ tests/test_light.c $(TESTS_QUADLIBS)
$(TESTS_BUILD)/native/test_light: tests/test_light.c tests/ref/published.h tests/ref/lightref.h tests/ref/shref.h tests/tl.h shlight.h
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) -march=native -ffp-contract=fast -o $@ tests/test_light.c $(TESTS_QUADLIBS)
$(TESTS_BUILD)/selftest_lightref: tests/ref/selftest_lightref.c tests/ref/lightref.h tests/ref/shref.h
	@mkdir -p $(@D)
	$(CC) -std=c99 -O2 -g1 -o $@ tests/ref/selftest_lightref.c $(TESTS_QUADLIBS)
$(TESTS_BUILD)/asan/test_light: tests/test_light.c tests/ref/published.h tests/ref/lightref.h tests/ref/shref.h tests/tl.h shlight.h
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) $(TESTS_ASAN) -o $@ tests/test_light.c $(TESTS_QUADLIBS)

# >>grid: build orders, threads, culling bound, interpolation against per-point evaluation
TESTS_GRID_FLAGS := -Wno-conversion -Wno-double-promotion -pthread
$(TESTS_BUILD)/test_grid: tests/test_grid.c tests/tl.h shlight.h
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) $(TESTS_GRID_FLAGS) -o $@ tests/test_grid.c -lm
$(TESTS_BUILD)/native/test_grid: tests/test_grid.c tests/tl.h shlight.h
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) $(TESTS_GRID_FLAGS) -march=native -ffp-contract=fast -o $@ tests/test_grid.c -lm
$(TESTS_BUILD)/asan/test_grid: tests/test_grid.c tests/tl.h shlight.h
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) $(TESTS_GRID_FLAGS) $(TESTS_ASAN) -o $@ tests/test_grid.c -lm

# >>edge: edge integrals and polygon moments against long double cubature (tests/ref/arearef.h)
TESTS_EDGE_DEPS := tests/test_edge.c tests/ref/arearef.h tests/tl.h shlight.h
$(TESTS_BUILD)/test_edge: $(TESTS_EDGE_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) -Wno-double-promotion -o $@ tests/test_edge.c -lm
$(TESTS_BUILD)/native/test_edge: $(TESTS_EDGE_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) -Wno-double-promotion -march=native -ffp-contract=fast -o $@ tests/test_edge.c -lm
$(TESTS_BUILD)/asan/test_edge: $(TESTS_EDGE_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) -Wno-double-promotion $(TESTS_ASAN) -o $@ tests/test_edge.c -lm
# >>edge microfacet polygon lights (half-vector space) against long double cubature
TESTS_MF_DEPS := tests/test_microfacet.c tests/ref/arearef.h tests/ref/ggxcases.h tests/tl.h shlight.h
$(TESTS_BUILD)/test_microfacet: $(TESTS_MF_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) -Wno-double-promotion -o $@ tests/test_microfacet.c -lm
$(TESTS_BUILD)/asan/test_microfacet: $(TESTS_MF_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) -Wno-double-promotion $(TESTS_ASAN) -o $@ tests/test_microfacet.c -lm

# >>edge GGX polygon lights (shl_polygon_ggx) against long double cubature (tests/ref/arearef.h)
TESTS_GGX_DEPS := tests/test_ggx.c tests/ref/arearef.h tests/ref/ggxcases.h tests/tl.h shlight.h
$(TESTS_BUILD)/test_ggx: $(TESTS_GGX_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) -Wno-double-promotion -o $@ tests/test_ggx.c -lm
$(TESTS_BUILD)/asan/test_ggx: $(TESTS_GGX_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) -Wno-double-promotion $(TESTS_ASAN) -o $@ tests/test_ggx.c -lm
# native: the edges' Gauss nodes in AVX2 double lanes (C only) under the same asserted bounds
$(TESTS_BUILD)/native/test_ggx: $(TESTS_GGX_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) -Wno-double-promotion -march=native -ffp-contract=fast -o $@ tests/test_ggx.c -lm
$(TESTS_BUILD)/native/test_microfacet: $(TESTS_MF_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) -Wno-double-promotion -march=native -ffp-contract=fast -o $@ tests/test_microfacet.c -lm
# the edge lanes held to the portable kernel (tests/test_ggx_portable.c, SHLIGHT_NO_SIMD) call for
# call; x86-64-v3 (AVX2 + FMA) whatever the host, the program checks the CPU
TESTS_GGXL_DEPS := tests/test_ggx_lanes.c tests/test_ggx_portable.c tests/ref/ggxcases.h tests/tl.h shlight.h
$(TESTS_BUILD)/v3/test_ggx_lanes: $(TESTS_GGXL_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) -Wno-double-promotion -march=x86-64-v3 -o $@ tests/test_ggx_lanes.c tests/test_ggx_portable.c -lm
$(TESTS_BUILD)/asan/test_ggx_lanes: $(TESTS_GGXL_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) -Wno-double-promotion -march=x86-64-v3 $(TESTS_ASAN) -o $@ tests/test_ggx_lanes.c tests/test_ggx_portable.c -lm
# the fit behind shl_polygon_ggx_fast: --check compares the header's generated shli_ggx_fast_fit
# with tools/ggx_fast_coef.txt
$(TESTS_BUILD)/fit_ggx_fast: tools/fit_ggx_fast.c tests/ref/arearef.h tests/ref/ggxcases.h shlight.h
	@mkdir -p $(@D)
	$(CC) -std=c99 -O1 -Wall -Wextra -o $@ tools/fit_ggx_fast.c -lm
$(TESTS_BUILD)/selftest_arearef: tests/selftest_arearef.c tests/ref/arearef.h
	@mkdir -p $(@D)
	$(CC) -std=c99 -O2 -g1 -o $@ tests/selftest_arearef.c -lm

# >>brdf / >>hvl: lobes, convolution, irradiance, windows, horizon fraction against quadrature
$(TESTS_BUILD)/test_brdf: tests/test_brdf.c tests/ref/published.h tests/tl.h shlight.h
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) $(TESTS_GRID_FLAGS) -o $@ tests/test_brdf.c $(TESTS_QUADLIBS)
$(TESTS_BUILD)/native/test_brdf: tests/test_brdf.c tests/ref/published.h tests/tl.h shlight.h
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) $(TESTS_GRID_FLAGS) -march=native -ffp-contract=fast -o $@ tests/test_brdf.c $(TESTS_QUADLIBS)
$(TESTS_BUILD)/asan/test_brdf: tests/test_brdf.c tests/ref/published.h tests/tl.h shlight.h
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) $(TESTS_GRID_FLAGS) $(TESTS_ASAN) -o $@ tests/test_brdf.c $(TESTS_QUADLIBS)

# >>zonal: shl_sh_rotate against a long-double Gauss re-projection and its properties
# (tests/test_rotate.c; about 5 s of CPU, most of it the n = 64 reference)
# (with tests/test_rotate_portable.c: the portable kernel alone, to hold the C-only n <= 8 path to)
TESTS_ROTATE_DEPS := tests/test_rotate.c tests/test_rotate_portable.c tests/tl.h shlight.h
$(TESTS_BUILD)/test_rotate: $(TESTS_ROTATE_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) -o $@ tests/test_rotate.c tests/test_rotate_portable.c -lm
# native: the C-only n <= 8 path's AVX2 code (band loads by lane permutes) and FMA contraction
$(TESTS_BUILD)/native/test_rotate: $(TESTS_ROTATE_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) -march=native -ffp-contract=fast -o $@ tests/test_rotate.c tests/test_rotate_portable.c -lm
# generic: the n <= 8 path's generic vector code (what non-x86 targets compile), built on x86 by
# hiding the SSE macros from the header
$(TESTS_BUILD)/generic/test_rotate: $(TESTS_ROTATE_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) -U__SSE__ -U__SSE2__ -U__SSE_MATH__ -U__SSE2_MATH__ -o $@ tests/test_rotate.c tests/test_rotate_portable.c -lm
$(TESTS_BUILD)/asan/test_rotate: $(TESTS_ROTATE_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) $(TESTS_ASAN) -o $@ tests/test_rotate.c tests/test_rotate_portable.c -lm

# >>brdftab: BRDF SH tables against closed forms and quadrature, the SHLT / MERL loaders and
# their error paths (tests/test_brdftab.c); the loaders' fuzz corpus replayed (fuzz_brdftab.c)
TESTS_BRDFTAB_FLAGS := -Wno-conversion -Wno-double-promotion
TESTS_BRDFTAB_DEPS := tests/test_brdftab.c tests/ref/shref.h tests/tl.h shlight.h
TESTS_FUZZ_BRDFTAB_DEPS := tests/fuzz_replay.c tests/fuzz_brdftab.c shlight.h
$(TESTS_BUILD)/test_brdftab: $(TESTS_BRDFTAB_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) $(TESTS_BRDFTAB_FLAGS) -o $@ tests/test_brdftab.c $(TESTS_QUADLIBS)
$(TESTS_BUILD)/asan/test_brdftab: $(TESTS_BRDFTAB_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) $(TESTS_BRDFTAB_FLAGS) $(TESTS_ASAN) -o $@ tests/test_brdftab.c $(TESTS_QUADLIBS)
$(TESTS_BUILD)/fuzz_replay_brdftab: $(TESTS_FUZZ_BRDFTAB_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) -o $@ tests/fuzz_replay.c tests/fuzz_brdftab.c -lm
$(TESTS_BUILD)/asan/fuzz_replay_brdftab: $(TESTS_FUZZ_BRDFTAB_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) $(TESTS_ASAN) -o $@ tests/fuzz_replay.c tests/fuzz_brdftab.c -lm
$(TESTS_BUILD)/fuzz_brdftab: tests/fuzz_brdftab.c shlight.h
	@mkdir -p $(@D)
	$(CLANG) -std=c99 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
	    -o $@ tests/fuzz_brdftab.c -lm

# libFuzzer run of the two loaders on one core, niced (FUZZ_SECONDS, default 60); the seed
# corpus is copied to a scratch directory (tests/gen_brdftab_corpus.py rewrites the seeds)
.PHONY: fuzz-brdftab
fuzz-brdftab: $(TESTS_BUILD)/fuzz_brdftab
	@mkdir -p $(TESTS_BUILD)/fuzz_brdftab_corpus
	cp tests/corpus/brdftab/* $(TESTS_BUILD)/fuzz_brdftab_corpus/
	nice -n 19 $(TESTS_BUILD)/fuzz_brdftab -max_len=4096 -max_total_time=$(FUZZ_SECONDS) \
	    -print_final_stats=1 -artifact_prefix=$(TESTS_BUILD)/ $(TESTS_BUILD)/fuzz_brdftab_corpus

# opt-in (minutes): BRDF tables against the independent long-double reference tests/ref/brdfref.h,
# lookup error against theta_o and quadrature error against quad_order (markdown on stdout)
$(TESTS_BUILD)/ref_brdftab: tests/ref_brdftab.c tests/ref/brdfref.h shlight.h
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) $(TESTS_BRDFTAB_FLAGS) -o $@ tests/ref_brdftab.c -lm
.PHONY: brdftab-ref
brdftab-ref: $(TESTS_BUILD)/ref_brdftab
	nice $(TESTS_BUILD)/ref_brdftab

# >>ssf: VPL SH / irradiance, interleaving, filter weight against long double / binary128
# references (tests/test_ssf.c)
TESTS_SSF_DEPS := tests/test_ssf.c tests/ref/shref.h tests/tl.h shlight.h
$(TESTS_BUILD)/test_ssf: $(TESTS_SSF_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) -o $@ tests/test_ssf.c $(TESTS_QUADLIBS)
$(TESTS_BUILD)/asan/test_ssf: $(TESTS_SSF_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) $(TESTS_ASAN) -o $@ tests/test_ssf.c $(TESTS_QUADLIBS)

# >>contracts: out-of-domain contracts of the zonal / light / grid / lobe / HVL / SSF functions
# and the 16 KB stack restructurings (tests/test_contracts.c)
TESTS_CONTRACTS_DEPS := tests/test_contracts.c tests/tl.h shlight.h
$(TESTS_BUILD)/test_contracts: $(TESTS_CONTRACTS_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) -Wno-double-promotion -o $@ tests/test_contracts.c -lm
$(TESTS_BUILD)/native/test_contracts: $(TESTS_CONTRACTS_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) -Wno-double-promotion -march=native -ffp-contract=fast -o $@ tests/test_contracts.c -lm
$(TESTS_BUILD)/asan/test_contracts: $(TESTS_CONTRACTS_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) -Wno-double-promotion $(TESTS_ASAN) -fsanitize=float-cast-overflow -fno-sanitize-recover=all -o $@ tests/test_contracts.c -lm

# fuzz targets of the other families (tests/fuzz_families.c): seeded random driver (any
# compiler), corpus replay through tests/fuzz_replay.c (plain and ASan/UBSan with
# float-cast-overflow, no recover), libFuzzer binary (clang), a longer opt-in run
TESTS_FAM_DEPS := tests/fuzz_families.c tests/ref/published.h shlight.h
TESTS_FAM_FLAGS := -Wno-double-promotion -Wno-conversion
FUZZ_FAM_CALLS ?= 400
FUZZ_FAM_LONG_CALLS ?= 200000
$(TESTS_BUILD)/fuzz_random: tests/fuzz_random.c $(TESTS_FAM_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) $(TESTS_FAM_FLAGS) -o $@ tests/fuzz_random.c tests/fuzz_families.c -lm
$(TESTS_BUILD)/fuzz_replay_families: tests/fuzz_replay.c $(TESTS_FAM_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) $(TESTS_FAM_FLAGS) -o $@ tests/fuzz_replay.c tests/fuzz_families.c -lm
$(TESTS_BUILD)/asan/fuzz_replay_families: tests/fuzz_replay.c $(TESTS_FAM_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) $(TESTS_FAM_FLAGS) $(TESTS_ASAN) -fsanitize=float-cast-overflow \
	    -fno-sanitize-recover=all -o $@ tests/fuzz_replay.c tests/fuzz_families.c -lm
$(TESTS_BUILD)/asan/fuzz_random: tests/fuzz_random.c $(TESTS_FAM_DEPS)
	@mkdir -p $(@D)
	$(CC) $(TESTS_CFLAGS) $(TESTS_FAM_FLAGS) $(TESTS_ASAN) -fsanitize=float-cast-overflow \
	    -fno-sanitize-recover=all -o $@ tests/fuzz_random.c tests/fuzz_families.c -lm
$(TESTS_BUILD)/fuzz_families: $(TESTS_FAM_DEPS)
	@mkdir -p $(@D)
	$(CLANG) -std=c99 -g -O1 -fsanitize=fuzzer,address,undefined,float-cast-overflow \
	    -fno-sanitize-recover=all -o $@ tests/fuzz_families.c -lm

.PHONY: fuzz-families fuzz-families-long
# the short run CI does (in tests/run.sh): the random driver, FUZZ_FAM_CALLS inputs per family
fuzz-families: $(TESTS_BUILD)/fuzz_random
	$(TESTS_BUILD)/fuzz_random $(FUZZ_FAM_CALLS) 1
# opt-in: the random driver under ASan/UBSan for FUZZ_FAM_LONG_CALLS inputs per family, then
# libFuzzer (clang) for FUZZ_SECONDS on the seed corpus (its additions stay in build/)
fuzz-families-long: $(TESTS_BUILD)/asan/fuzz_random
	nice $(TESTS_BUILD)/asan/fuzz_random $(FUZZ_FAM_LONG_CALLS) 7
	if command -v $(CLANG) >/dev/null; then $(MAKE) $(TESTS_BUILD)/fuzz_families && \
	  mkdir -p $(TESTS_BUILD)/fuzz_corpus_families && \
	  cp tests/corpus/families/* $(TESTS_BUILD)/fuzz_corpus_families/ && \
	  nice $(TESTS_BUILD)/fuzz_families -max_len=512 -max_total_time=$(FUZZ_SECONDS) \
	    -artifact_prefix=$(TESTS_BUILD)/ $(TESTS_BUILD)/fuzz_corpus_families; fi
