#!/bin/sh
# callgrind_beckmann.sh - x86 instructions per quad light of shl_polygon_beckmann_taylor
# (bench/bench_beckmann.c --count-only: one pass over the 1,750 quads of bench_ggx's sampler),
# -O3 -march=x86-64-v3 (valgrind 3.19 cannot decode AVX-512). Only the wrapper bw_beck and what
# it calls are counted (--toggle-collect). Writes bench/out/beckmann_instr.md. Run from the
# repository root: sh bench/callgrind_beckmann.sh
set -eu
CC=${CC:-gcc}
BIN=build/bench/bench_beckmann_cg
mkdir -p build/bench bench/out
$CC -std=c99 -O3 -march=x86-64-v3 -ffp-contract=fast -DNDEBUG -Wl,-z,now -o "$BIN" bench/bench_beckmann.c -lm
K=1
valgrind --tool=callgrind --toggle-collect='bw_*' --callgrind-out-file=build/bench/cg_beckmann.out \
  "$BIN" --count-only $K >/dev/null 2>&1
tot=$(sed -n 's/^totals: *//p;s/^summary: *//p' build/bench/cg_beckmann.out | head -n 1)
{
  echo "### x86 instructions per quad light (callgrind, \`$CC -O3 -march=x86-64-v3\`, the 1,750 quads of bench_beckmann)"
  echo
  echo "| kernel | instructions per quad |"
  echo "|---|---|"
  echo "| shl_polygon_beckmann_taylor | $(awk -v t="$tot" -v k=$K 'BEGIN { printf "%.0f", t / (k * 1750) }') |"
} >bench/out/beckmann_instr.md
cat bench/out/beckmann_instr.md
