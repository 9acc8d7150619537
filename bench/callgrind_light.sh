#!/bin/sh
# callgrind_light.sh - x86 instructions per light of the sphere / triangle light kernels with
# and without the gradient (bench/bench_light.c --count-only), -O3 -march=x86-64-v3 (valgrind
# 3.19 cannot decode AVX-512, so the AVX-512 paths of the timed build are not what runs here:
# n >= 5 takes the scalar-generated / AVX2 code). Only the wrappers bw_* and what they call
# are counted (--toggle-collect). Writes bench/out/light_instr.md. Run from the repository
# root: sh bench/callgrind_light.sh ["2 3 4 16"]
set -eu
CC=${CC:-gcc}
NS=${1:-"2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 32 64"}
BIN=build/bench/bench_light_cg
. bench/callgrind_lib.sh
command -v valgrind >/dev/null || { echo "callgrind_light.sh: valgrind not found" >&2; exit 1; }
mkdir -p build/bench bench/out
if [ ! -x "$BIN" ] || [ bench/bench_light.c -nt "$BIN" ] || [ bench/bench_util.h -nt "$BIN" ] ||
  [ shlight.h -nt "$BIN" ]; then
  cg_build bench_light -lquadmath -lm
fi
REV=$(git rev-parse --short HEAD 2>/dev/null || echo "?")
git diff --quiet HEAD -- shlight.h 2>/dev/null || REV="$REV+dirty, blob $(git hash-object shlight.h | cut -c1-10)"
count() { # variant n -> instructions per call
  K=256
  cg_run build/bench/cgl.out --count-only "$1" "$2" $K
  tot=$(cg_total build/bench/cgl.out)
  awk -v t="$tot" -v k=$K 'BEGIN { printf "%.0f", t / k }'
}
{
  echo "### x86 instructions per light (callgrind, \`$CC -O3 -march=x86-64-v3\`, shlight.h at $REV, 256 configurations)"
  echo
  echo "| n | sh_eval | sh_eval_grad | sphere | sphere+grad | ratio | triangle | triangle+grad | ratio |"
  echo "|---|---|---|---|---|---|---|---|---|"
  for n in $NS; do
    e=$(count eval "$n"); eg=$(count evgrad "$n"); a=$(count sph "$n"); b=$(count sphg "$n")
    c=$(count tri "$n"); d=$(count trig "$n")
    echo "| $n | $e | $eg | $a | $b | $(awk -v a="$a" -v b="$b" 'BEGIN { printf "%.2f", b / a }') | $c | $d | $(awk -v a="$c" -v b="$d" 'BEGIN { printf "%.2f", b / a }') |"
  done
  echo
  echo "shl_triangle_solid_angle: $(count solid 0) instructions"
} >bench/out/light_instr.md
cat bench/out/light_instr.md
