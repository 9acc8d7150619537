#!/usr/bin/env bash
# tests/run.sh - everything `make test` (and CI) runs. Each step prints its own
# "N passed, N failed" line (steps without one count as one check); the sums close the run.
# SHLIGHT_TEST_QUICK=1 skips the sanitizer builds and runs. Run from the repository root.
set -u
cd "$(dirname "$0")/.."
MAKE=${MAKE:-make}
PY=${PYTHON:-python3}
mkdir -p build/logs
total_pass=0
total_fail=0
t0=$(date +%s)

step() { # step NAME COMMAND...
  local name=$1
  shift
  local log="build/logs/${name}.log" s=$(date +%s)
  "$@" >"$log" 2>&1
  local rc=$?
  local line
  line=$(grep -E '^(.*: )?[0-9]+ passed, [0-9]+ failed' "$log" | tail -n 1 | sed -E 's/^.*: //')
  local p=0 f=0
  if [ -n "$line" ]; then
    p=$(echo "$line" | sed -E 's/^([0-9]+) passed.*/\1/')
    f=$(echo "$line" | sed -E 's/^[0-9]+ passed, ([0-9]+) failed.*/\1/')
    if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then f=1; fi
  elif [ "$rc" -eq 0 ]; then
    p=1
  else
    f=1
  fi
  total_pass=$((total_pass + p))
  total_fail=$((total_fail + f))
  printf '%-5s %-28s %5s passed, %3s failed  (%ss)\n' "$([ "$f" -eq 0 ] && echo ok || echo FAIL)" \
    "$name" "$p" "$f" "$(($(date +%s) - s))"
  if [ "$f" -ne 0 ]; then
    echo "----- tail of $log"
    tail -n 40 "$log"
    echo "-----"
  fi
}

backends=""
pkg-config --exists osmesa && backends="$backends osmesa"
pkg-config --exists egl && backends="$backends egl"

# The second lane: the sanitizer build and runs and the -march=native variants run one after
# another in the background, niced, so they take the core that the
# single-threaded steps leave idle (each was on the critical path: the run took 684 s). It
# starts with the sanitizer build and waits for build-tests before it runs the native
# binaries. Logs and exit statuses land in build/logs/lane/, reported as steps at the end.
asan_targets="build/tests/asan/test_basis build/tests/asan/test_glm build/tests/asan/fuzz_replay \
  build/tests/asan/test_light build/tests/asan/test_grid build/tests/asan/test_edge \
  build/tests/asan/test_microfacet build/tests/asan/test_ggx build/tests/asan/test_brdf \
  build/tests/asan/test_gl_smoke build/tests/asan/test_brdftab build/tests/asan/fuzz_replay_brdftab \
  build/tests/asan/test_ssf build/tests/asan/fuzz_replay_scene \
  build/tests/asan/test_contracts build/tests/asan/fuzz_replay_families build/tests/asan/test_ggx_lanes"
lane_step() { # NAME COMMAND...: run in the lane, keep its log, exit status and time
  local name=$1 s=$(date +%s) rc=0
  shift
  "$@" >"build/logs/lane/$name.log" 2>&1 || rc=$?
  echo "(second lane: $(($(date +%s) - s)) s)" >>"build/logs/lane/$name.log"
  echo "$rc" >"build/logs/lane/$name.rc"
}
lane() {
  if [ "${SHLIGHT_TEST_QUICK:-0}" != 1 ]; then
    lane_step asan-ubsan-build $MAKE -s -j1 $asan_targets
  fi
  while [ ! -e build/logs/lane/tests-built ]; do sleep 1; done
  lane_step test_basis-march-native build/tests/native/test_basis
  lane_step test_light-march-native build/tests/native/test_light
  lane_step test_grid-march-native build/tests/native/test_grid
  lane_step test_brdf-march-native build/tests/native/test_brdf
  lane_step test_ggx-march-native build/tests/native/test_ggx
  lane_step test_microfacet-march-native build/tests/native/test_microfacet
  [ "${SHLIGHT_TEST_QUICK:-0}" != 1 ] || return 0
  lane_step asan-ubsan $MAKE -s test-asan
  lane_step asan-ubsan-light build/tests/asan/test_light
  lane_step asan-ubsan-grid build/tests/asan/test_grid
  lane_step asan-ubsan-edge env SHLIGHT_TEST_QUICK=1 build/tests/asan/test_edge
  lane_step asan-ubsan-microfacet build/tests/asan/test_microfacet
  lane_step asan-ubsan-ggx build/tests/asan/test_ggx
  lane_step asan-ubsan-ggx-lanes build/tests/asan/test_ggx_lanes
  lane_step asan-ubsan-brdf build/tests/asan/test_brdf
  lane_step asan-ubsan-ssf build/tests/asan/test_ssf
  lane_step asan-ubsan-fuzz-replay-scene build/tests/asan/fuzz_replay_scene tests/corpus/scene
  lane_step asan-ubsan-contracts build/tests/asan/test_contracts
  lane_step asan-ubsan-fuzz-replay-families build/tests/asan/fuzz_replay_families tests/corpus/families
  lane_step asan-ubsan-brdftab build/tests/asan/test_brdftab
  lane_step asan-ubsan-fuzz-replay-brdftab build/tests/asan/fuzz_replay_brdftab tests/corpus/brdftab
  lane_step asan-ubsan-gl $MAKE -s gl-test-asan
}
lane_show() { # NAME: the lane's log and exit status for that step (none recorded: failed)
  cat "build/logs/lane/$1.log" 2>/dev/null
  return "$(cat "build/logs/lane/$1.rc" 2>/dev/null || echo 1)"
}
rm -rf build/logs/lane
mkdir -p build/logs/lane
(renice -n 19 $BASHPID >/dev/null 2>&1; lane) &
lane_pid=$!
step generated-code-fresh $PY tools/gen_basis.py --check
step mirror-check $PY tools/check_mirror.py -q
step glsl-one-include bash tools/glsl_one_check.sh
step mirror-checker-selftest bash tools/tests_mirror/run.sh
step glslang-450-330-300es bash tools/glsl_validate.sh
step format-check $MAKE -s format-check
# the header's size budgets (bench/budgets.sh: fails at 1.5x a budget)
step budgets bash bench/budgets.sh --check
step example $MAKE -s example
# every code block of README.md and docs/*.md: C programs built with ASan/UBSan and run, GLSL
# through glslang; the API index names every public function
step docs-examples $PY tools/check_docs.py
step compile-matrix $MAKE -s -j2 compile-matrix
step build-tests $MAKE -s -j2 build/tests/test_basis build/tests/test_glm build/tests/test_glsl \
  build/tests/test_gl_smoke build/tests/fuzz_replay build/tests/native/test_basis \
  build/tests/native-novl/test_simd_novl \
  build/tests/test_light build/tests/native/test_light build/tests/selftest_lightref \
  build/tests/test_grid build/tests/native/test_grid build/tests/test_grid_glsl \
  build/tests/test_edge build/tests/selftest_arearef build/tests/test_edge_glsl \
  build/tests/test_microfacet build/tests/test_microfacet_glsl \
  build/tests/test_ggx build/tests/test_ggx_glsl build/tests/fit_ggx_fast \
  build/tests/v3/test_ggx_lanes build/tests/native/test_ggx build/tests/native/test_microfacet \
  build/tests/test_brdf build/tests/native/test_brdf build/tests/test_brdf_glsl \
  build/tests/test_brdftab build/tests/fuzz_replay_brdftab build/tests/test_brdftab_glsl \
  build/tests/test_rotate build/tests/native/test_rotate build/tests/generic/test_rotate build/tests/test_rotate_glsl \
  build/tests/test_ssf build/tests/test_ssf_glsl \
  build/render/shlrender build/tools/merl_write build/tests/fuzz_replay_scene build/tests/test_rd_core \
  build/tests/test_contracts build/tests/fuzz_random build/tests/fuzz_replay_families
touch build/logs/lane/tests-built
step test_basis build/tests/test_basis
step test_simd_novl build/tests/native-novl/test_simd_novl
step test_light build/tests/test_light
step test_grid build/tests/test_grid
step test_edge build/tests/test_edge
step test_microfacet build/tests/test_microfacet
step test_ggx build/tests/test_ggx
step test_ggx_lanes build/tests/v3/test_ggx_lanes
step ggx-fast-fit-fresh build/tests/fit_ggx_fast --check tools/ggx_fast_coef.txt shlight.h
step arearef-selftest build/tests/selftest_arearef
step test_brdf build/tests/test_brdf
step test_ssf build/tests/test_ssf
step test_rd_core build/tests/test_rd_core build/logs/rd_core.png
step png-independent-decode $PY tests/png_check.py build/logs/rd_core.png 40 24
step fuzz-corpus-replay-scene build/tests/fuzz_replay_scene tests/corpus/scene
step test_glm build/tests/test_glm
step fuzz-corpus-replay build/tests/fuzz_replay tests/corpus/basis
step test_brdftab build/tests/test_brdftab
step test_contracts build/tests/test_contracts
# the short bounded fuzz run of the other families (40000 random inputs each, ~25 s) and
# their seed corpus (tests/corpus/families); `make fuzz-families-long` is the long run
step fuzz-families build/tests/fuzz_random 40000 1
step fuzz-corpus-replay-families build/tests/fuzz_replay_families tests/corpus/families
# stack: every public function <= 16 KB (own frame + deepest static call chain, gcc
step stack-usage $PY tools/stack_usage.py
step test_rotate build/tests/test_rotate
step test_rotate_native build/tests/native/test_rotate
step test_rotate_generic build/tests/generic/test_rotate
# in the foreground: it balances the two lanes (both ~555 s)
step lightref-selftest build/tests/selftest_lightref
step fuzz-corpus-replay-brdftab build/tests/fuzz_replay_brdftab tests/corpus/brdftab
# every GLSL check runs on the first backend (OSMesa); the second (EGL) runs the same llvmpipe
# compiler, so it gets every harness with test_glsl's band-count subset (SHLIGHT_GLSL_SUBSET)
first=1
for b in $backends; do
  sub=""
  [ $first = 1 ] || sub="SHLIGHT_GLSL_SUBSET=1"
  first=0
  step "gl-smoke-$b" env SHLIGHT_GL_BACKEND=$b build/tests/test_gl_smoke
  step "glsl-vs-c-$b" env SHLIGHT_GL_BACKEND=$b $sub build/tests/test_glsl
  step "glsl-grid-vs-c-$b" env SHLIGHT_GL_BACKEND=$b build/tests/test_grid_glsl
  step "glsl-edge-vs-c-$b" env SHLIGHT_GL_BACKEND=$b $sub build/tests/test_edge_glsl
  # the microfacet twins on the first backend only (~8 s of llvmpipe compile)
  [ -n "$sub" ] || step "glsl-microfacet-vs-c-$b" env SHLIGHT_GL_BACKEND=$b build/tests/test_microfacet_glsl
  # GGX polygon lights: first backend only (the second runs the same llvmpipe compiler)
  [ -n "$sub" ] || step "glsl-ggx-vs-c-$b" env SHLIGHT_GL_BACKEND=$b build/tests/test_ggx_glsl
  step "glsl-brdf-vs-c-$b" env SHLIGHT_GL_BACKEND=$b build/tests/test_brdf_glsl
  step "glsl-ssf-vs-c-$b" env SHLIGHT_GL_BACKEND=$b build/tests/test_ssf_glsl
  # the renderer: every scene and pass GL vs CPU on the first backend, cornell on the second
  rsc=""
  [ -z "$sub" ] || rsc="cornell"
  step "render-$b" env SHLIGHT_RENDER_SCENES="$rsc" bash tests/test_render.sh $b
  step "glsl-brdftab-vs-c-$b" env SHLIGHT_GL_BACKEND=$b build/tests/test_brdftab_glsl
  step "glsl-rotate-vs-c-$b" env SHLIGHT_GL_BACKEND=$b build/tests/test_rotate_glsl
done
# GLSL compile budgets (llvmpipe, compile + link + first draw, CPU s) at 2x, the one include
step glsl-compile-budget bash bench/glsl_budget.sh --no-run --check 2 --one-include
# glslang SPIR-V size of values + gradient at n = 16 at 2x its budget
step glsl-spirv-budget bash bench/glsl_spirv.sh --check 2
# the second lane's steps, in its order (the -march=native variants run the same tests on this
# machine's SIMD paths, AVX-512 / AVX2 kernels, with FMA contraction)
wait "$lane_pid"
for n in test_basis-march-native test_light-march-native test_grid-march-native \
  test_brdf-march-native test_ggx-march-native test_microfacet-march-native; do
  step "$n" lane_show "$n"
done
if [ "${SHLIGHT_TEST_QUICK:-0}" != 1 ]; then
  for n in asan-ubsan-build asan-ubsan asan-ubsan-light asan-ubsan-grid asan-ubsan-edge \
    asan-ubsan-microfacet asan-ubsan-ggx asan-ubsan-ggx-lanes asan-ubsan-brdf asan-ubsan-ssf \
    asan-ubsan-fuzz-replay-scene asan-ubsan-contracts asan-ubsan-fuzz-replay-families asan-ubsan-brdftab asan-ubsan-fuzz-replay-brdftab asan-ubsan-gl; do
    step "$n" lane_show "$n"
  done
fi
echo "time: $(($(date +%s) - t0)) s"
echo "$total_pass passed, $total_fail failed"
[ "$total_fail" -eq 0 ]
