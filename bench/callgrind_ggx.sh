#!/bin/sh
# callgrind_ggx.sh - x86 instructions per quad light of shl_polygon_ggx and shl_polygon_ggx_fast
# (bench/bench_ggx.c --count-only: one pass over the 1,750 quads of the LTC comparison's sampler), -O3
# -march=x86-64-v3 (valgrind 3.19 cannot decode AVX-512). Only the wrapper bw_ggx and what it
# calls are counted (--toggle-collect). Writes bench/out/ggx_instr.md; then one run per
# roughness (its 250 quads) into bench/out/ggx_instr_rough.txt, one count per line in
# bench_ggx's roughness order (its speed-against-error table). Run from the repository
# root: sh bench/callgrind_ggx.sh
set -eu
CC=${CC:-gcc}
. bench/callgrind_lib.sh
cg_quads1750 ggx shl_polygon_ggx tests/test_ggx_portable.c
: >bench/out/ggx_instr_rough.txt
for r in 0 1 2 3 4 5 6; do
  cg_run "build/bench/cg_ggx_r$r.out" --count-only 1 $r
  awk -v t="$(cg_total "build/bench/cg_ggx_r$r.out")" 'BEGIN { printf "%.0f\n", t / 250 }' \
    >>bench/out/ggx_instr_rough.txt
done
cat bench/out/ggx_instr_rough.txt
# shl_polygon_ggx_fast, per roughness, into bench/out/ggx_fast_instr_rough.txt
: >bench/out/ggx_fast_instr_rough.txt
for r in 0 1 2 3 4 5 6; do
  cg_run "build/bench/cg_ggx_fast_r$r.out" --count-only 1 $r fast
  awk -v t="$(cg_total "build/bench/cg_ggx_fast_r$r.out")" 'BEGIN { printf "%.0f\n", t / 250 }' \
    >>bench/out/ggx_fast_instr_rough.txt
done
cat bench/out/ggx_fast_instr_rough.txt
