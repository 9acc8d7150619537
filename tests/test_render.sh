#!/usr/bin/env bash
# tests/test_render.sh [backend] - shlrender in CI: command-line and scene-file errors (exit
# codes, file:line messages), then every built-in scene and examples/scenes/room.scene through
# every pass at 64x48 with --check (each GL image against its CPU twin, per pass tolerance)
# and a quick ground truth. SHLIGHT_RENDER_SCENES overrides the scene list. Ends with
# "N passed, N failed". Run from the repository root after `make build/render/shlrender`.
set -u
R=build/render/shlrender
backend=${1:-osmesa}
pass=0
fail=0
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
ok() { pass=$((pass + 1)); }
ko() { fail=$((fail + 1)); echo "FAIL $*"; }
expect() { # expect CODE PATTERN ARGS... : exit code CODE and PATTERN in stderr
  local code=$1 pat=$2
  shift 2
  "$R" "$@" >"$t/out" 2>"$t/err"
  local rc=$?
  if [ "$rc" -eq "$code" ] && grep -q -- "$pat" "$t/err"; then ok; else
    ko "shlrender $* -> exit $rc (want $code, stderr matching '$pat'):"
    head -3 "$t/err"
  fi
}
expect 2 "unknown scene" --scene nosuch --paths cpu
expect 2 "unknown option" --frobnicate 1
expect 2 "bad value for --size" --size 3x2
expect 2 "bad value for --bands" --bands 0
expect 2 "bad value for --brdf-bands" --brdf-bands 17
expect 2 "unknown pass" --pass grid,nosuch
expect 2 "cannot read" --scene "$t/missing.scene"
printf 'material m kd 0.5 0.5 0.5\nsphere 0 0 0 1 mm\n' >"$t/bad1.scene"
expect 2 "bad1.scene:2: unknown material 'mm'" --scene "$t/bad1.scene" --paths cpu
printf 'material m kd 0.5 0.5 0.5\nsphere 0 0 0 -1 m\n' >"$t/bad2.scene"
expect 2 "bad2.scene:2: sphere radius must be > 0" --scene "$t/bad2.scene" --paths cpu
printf 'material m kd 0.5 0.5 0.5\nobj none.obj m\n' >"$t/bad3.scene"
expect 2 "bad3.scene:2: cannot read obj file" --scene "$t/bad3.scene" --paths cpu
printf 'v 0 0 0\nv 1 0 0\nf 1 2 3\n' >"$t/bad.obj"
printf 'material m kd 0.5 0.5 0.5\nobj bad.obj m\n' >"$t/bad4.scene"
expect 2 "bad.obj:3: bad vertex index" --scene "$t/bad4.scene" --paths cpu
expect 2 "cannot read the MERL BRDF" --brdf "$t/missing.binary" --paths cpu
printf 'MERL' >"$t/short.binary"
expect 2 "shl_merl_read failed" --brdf "$t/short.binary" --paths cpu
if "$R" --help | grep -q "usage: shlrender"; then ok; else ko "--help"; fi
# a CPU-only render of the example scene writes PNGs
if "$R" --scene examples/scenes/room.scene --pass preview --paths cpu --size 32x24 --out "$t/png" \
  >/dev/null && [ -s "$t/png/room_preview_headlight_cpu.png" ]; then ok; else ko "cpu-only PNG"; fi
# the hvl and ssf ground truths' SIMD lanes (AVX where the CPU has it; SSE2 with
# SHLIGHT_RENDER_NO_AVX=1) against their scalar loops, every sum bit for bit
# (SHLIGHT_RENDER_GT_CHECK), and the two paths' PNGs byte for byte (61x45: rows that end in a
# partial group)
mkdir -p "$t/avx" "$t/noavx"
SHLIGHT_RENDER_GT_CHECK=1 "$R" --scene cornell --pass hvl,ssf --paths cpu --size 61x45 --gt 1 \
  --reps 1 --out "$t/avx" 2>"$t/avx.err" >/dev/null
SHLIGHT_RENDER_GT_CHECK=1 SHLIGHT_RENDER_NO_AVX=1 "$R" --scene cornell --pass hvl,ssf \
  --paths cpu --size 61x45 --gt 1 --reps 1 --out "$t/noavx" 2>"$t/noavx.err" >/dev/null
for e in avx noavx; do
  grep 'lanes vs the scalar loop' "$t/$e.err"
  if [ "$(grep -cE 'lanes vs the scalar loop: 0 of [1-9][0-9]* sums differ' "$t/$e.err")" = 4 ] &&
    [ "$(grep -c 'lanes vs the scalar loop' "$t/$e.err")" = 4 ]; then ok; else
    ko "hvl / ssf ground truth lanes ($e) vs the scalar loop"
  fi
done
if cmp "$t/avx/cornell_hvl_gt_gt.png" "$t/noavx/cornell_hvl_gt_gt.png" &&
  cmp "$t/avx/cornell_ssf_gt_gt.png" "$t/noavx/cornell_ssf_gt_gt.png"; then ok; else
  ko "hvl / ssf ground truth: AVX and SSE2 PNGs differ"
fi
# every pass, GL against CPU
for s in ${SHLIGHT_RENDER_SCENES:-cornell spheres manylights glossy examples/scenes/room.scene}; do
  SHLIGHT_GL_BACKEND=$backend "$R" --scene "$s" --size 64x48 --gt 1 --reps 1 --check \
    >"$t/log" 2>&1
  rc=$?
  line=$(grep -E '^[0-9]+ passed, [0-9]+ failed' "$t/log" | tail -1)
  p=$(echo "$line" | sed -E 's/ passed.*//')
  f=$(echo "$line" | sed -E 's/.* passed, ([0-9]+) failed/\1/')
  grep -E '^(check|\|)' "$t/log"
  if [ -z "$line" ] || [ "$rc" -ne 0 ]; then
    ko "scene $s (exit $rc)"
    tail -5 "$t/log"
    [ -n "$line" ] && pass=$((pass + p)) && fail=$((fail + f))
  else
    pass=$((pass + p))
    fail=$((fail + f))
  fi
done
# glossy and measured receivers in the hvl pass (first backend only, ~6 s CPU): GGX floor and
# Phong ball (BRDF SH tables of the analytic models), the back wall measured: a MERL file that
# tools/merl_write writes from GGX alpha 0.3 + Lambert (32x32x64 samples: a small file),
# read back through shl_merl_read. --check holds GL to CPU on the BRDF-table pixels (tolerance
# in render/pass_hvl.c); the ground truth's convergence and each method's error are printed.
if [ -z "${SHLIGHT_RENDER_SCENES:-}" ]; then
  M=build/tools/merl_write
  if "$M" "$t/g.binary" 32 32 64 >"$t/mlog" 2>&1; then ok; else
    ko "merl_write"
    cat "$t/mlog"
  fi
  cat "$t/mlog"
  expect 4 "no material 'nosuch'" --scene examples/scenes/hvl_glossy.scene --pass hvl \
    --paths cpu --gt 0 --size 16x12 --brdf "$t/g.binary:nosuch"
  SHLIGHT_GL_BACKEND=$backend SHLIGHT_HVL_GT=64 "$R" --scene examples/scenes/hvl_glossy.scene \
    --pass hvl --size 64x48 --gt 1 --reps 1 --check --brdf "$t/g.binary:back" >"$t/log" 2>&1
  rc=$?
  grep -E '^(check|hvl gt convergence|hvl .* cpu:)' "$t/log"
  line=$(grep -E '^[0-9]+ passed, [0-9]+ failed' "$t/log" | tail -1)
  if [ -z "$line" ] || [ "$rc" -ne 0 ] || ! grep -q "measured, channel b" "$t/log" ||
    ! grep -q "table floor (GGX)" "$t/log" || ! grep -q "table ball (Phong)" "$t/log"; then
    ko "hvl glossy / measured (exit $rc)"
    tail -5 "$t/log"
  fi
  [ -n "$line" ] && pass=$((pass + $(echo "$line" | sed -E 's/ passed.*//'))) &&
    fail=$((fail + $(echo "$line" | sed -E 's/.* passed, ([0-9]+) failed/\1/')))
fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
