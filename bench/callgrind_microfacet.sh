#!/bin/sh
# callgrind_microfacet.sh - x86 instructions per quad light of shl_polygon_blinn_phong and
# shl_polygon_beckmann_subedges by sub-edge count k (bench/bench_microfacet.c --count-only), with
# shl_polygon_phong (QUADRATURE) as the baseline; -O3 -march=x86-64-v3 (valgrind cannot decode
# AVX-512). Only the wrapper bw_mf and what it calls are counted. Writes
# bench/out/microfacet_instr.md. Run from the repository root: sh bench/callgrind_microfacet.sh
set -eu
CC=${CC:-gcc}
. bench/callgrind_lib.sh
cg_build bench_microfacet -lm
count() {
  cg_run build/bench/cgm.out --count-only "$1" "$2" "$3" 96
  tot=$(cg_total build/bench/cgm.out)
  awk -v t="$tot" 'BEGIN { printf "%.0f", t / 96 }'
}
{
  echo "### x86 instructions per quad light (callgrind, \`$CC -O3 -march=x86-64-v3\`, 96 random quads)"
  echo
  echo "| kernel | parameter | k=1 | k=-2 | k=2 | k=4 | k=8 |"
  echo "|---|---|---|---|---|---|---|"
  for p in 30 1000; do
    printf '| Blinn-Phong | e=%s |' "$p"
    for k in 1 -2 2 4 8; do printf ' %s |' "$(count 0 $k $p)"; done
    echo
  done
  for p in 0.4 0.1; do
    printf '| Beckmann | alpha=%s |' "$p"
    for k in 1 -2 2 4 8; do printf ' %s |' "$(count 1 $k $p)"; done
    echo
  done
  printf '| Phong (QUADRATURE), baseline | e=30 | %s | | | | |\n' "$(count 2 1 30)"
} >bench/out/microfacet_instr.md
cat bench/out/microfacet_instr.md
