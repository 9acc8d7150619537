#!/bin/sh
# callgrind_ggx.sh - x86 instructions per quad light of shl_polygon_ggx (bench/bench_ggx.c
# --count-only: one pass over the 1,750 quads of the LTC comparison's sampler), -O3
# -march=x86-64-v3 (valgrind 3.19 cannot decode AVX-512). Only the wrapper bw_ggx and what it
# calls are counted (--toggle-collect). Writes bench/out/ggx_instr.md. Run from the repository
# root: sh bench/callgrind_ggx.sh
set -eu
CC=${CC:-gcc}
. bench/callgrind_lib.sh
cg_quads1750 ggx shl_polygon_ggx
