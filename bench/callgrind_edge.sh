#!/bin/sh
# callgrind_edge.sh - x86 instructions per quad light of each shl_polygon_phong method
# (bench/bench_edge.c --count-only), -O3 -march=x86-64-v3 (valgrind cannot decode AVX-512).
# Only the wrapper bw_phong and what it calls are counted (--toggle-collect). Writes
# bench/out/edge_instr.md. Run from the repository root: sh bench/callgrind_edge.sh
set -eu
CC=${CC:-gcc}
. bench/callgrind_lib.sh
cg_build bench_edge -lm
ES="1 10 100 1000 10000"
{
  echo "### x86 instructions per quad light (callgrind, \`$CC -O3 -march=x86-64-v3\`, 256 random quads, doubly clipped Phong)"
  echo
  printf '| method |'; for e in $ES; do printf ' e=%s |' "$e"; done; echo
  printf '|---|'; for e in $ES; do printf -- '---|'; done; echo
  for m in 0 1 2 3 5 6 4; do
    case $m in 0) n=exact ;; 1) n=Lorentzian ;; 2) n=Lorentzian-Pearson ;; 3) n=ellipsoid ;;
      4) n=auto ;; 5) n="quadrature (Stokes)" ;; 6) n="fast (Stokes, float SIMD)" ;; esac
    printf '| %s |' "$n"
    for e in $ES; do
      K=256
      cg_run build/bench/cg.out --count-only $m $e $K
      tot=$(cg_total build/bench/cg.out)
      printf ' %s |' "$(awk -v t="$tot" -v k=$K 'BEGIN { printf "%.0f", t / k }')"
    done
    echo
  done
} >bench/out/edge_instr.md
cat bench/out/edge_instr.md
