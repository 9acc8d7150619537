#!/bin/sh
# callgrind_ggx.sh - x86 instructions per quad light of shl_polygon_ggx (bench/bench_ggx.c
# --count-only: one pass over the 1,750 quads of the LTC comparison's sampler), -O3
# -march=x86-64-v3 (valgrind 3.19 cannot decode AVX-512). Only the wrapper bw_ggx and what it
# calls are counted (--toggle-collect). Writes bench/out/ggx_instr.md. Run from the repository
# root: sh bench/callgrind_ggx.sh
set -eu
CC=${CC:-gcc}
BIN=build/bench/bench_ggx_cg
mkdir -p build/bench bench/out
$CC -std=c99 -O3 -march=x86-64-v3 -ffp-contract=fast -DNDEBUG -Wl,-z,now -o "$BIN" bench/bench_ggx.c -lm
K=1
valgrind --tool=callgrind --toggle-collect='bw_*' --callgrind-out-file=build/bench/cg_ggx.out \
  "$BIN" --count-only $K >/dev/null 2>&1
tot=$(sed -n 's/^totals: *//p;s/^summary: *//p' build/bench/cg_ggx.out | head -n 1)
{
  echo "### x86 instructions per quad light (callgrind, \`$CC -O3 -march=x86-64-v3\`, the 1,750 quads of bench_ggx)"
  echo
  echo "| kernel | instructions per quad |"
  echo "|---|---|"
  echo "| shl_polygon_ggx | $(awk -v t="$tot" -v k=$K 'BEGIN { printf "%.0f", t / (k * 1750) }') |"
} >bench/out/ggx_instr.md
cat bench/out/ggx_instr.md
