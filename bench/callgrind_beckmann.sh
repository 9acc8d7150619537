#!/bin/sh
# callgrind_beckmann.sh - x86 instructions per quad light of shl_polygon_beckmann
# (bench/bench_beckmann.c --count-only: one pass over the 1,750 quads of bench_ggx's sampler),
# -O3 -march=x86-64-v3 (valgrind 3.19 cannot decode AVX-512). Only the wrapper bw_beck and what
# it calls are counted (--toggle-collect). Writes bench/out/beckmann_instr.md. Run from the
# repository root: sh bench/callgrind_beckmann.sh
set -eu
CC=${CC:-gcc}
. bench/callgrind_lib.sh
cg_quads1750 beckmann shl_polygon_beckmann
