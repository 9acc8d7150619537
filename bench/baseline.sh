#!/bin/sh
# baseline.sh - the basis benches against a baseline shlight.h, in the same run.
#
# Builds bench/bench_basis.c and bench/bench_batch.c twice, against ./shlight.h and against the
# shlight.h of git revision REV (default 78ec5f7, the kernels before the batch and size rework),
# with the flags of bench/bench.mk, then runs the two builds interleaved ROUNDS times (default
# 5) and prints, per round, their ratio tables side by side (each build's ratios are to the
# plain-loop yardstick of its own run, so machine load cancels to first order). Compare the
# medians over the rounds; the raw outputs stay in build/baseline/out/.
#
# Usage: sh bench/baseline.sh [REV] [ROUNDS]      (run from the repository root)
#   Env: BENCH_N (n list for bench_basis, default 3,6,10,16), BENCH_V (its variants, default
#   eval,batch,batch16,batch32,grad), CC (gcc).
set -eu
REV=${1:-78ec5f7}
ROUNDS=${2:-5}
CC=${CC:-gcc}
NL=${BENCH_N:-3,6,10,16}
VL=${BENCH_V:-eval,batch,batch16,batch32,grad}
FLAGS="-std=c99 -O3 -march=native -ffp-contract=fast -DNDEBUG"
B=build/baseline
mkdir -p "$B/bench" "$B/tests/ref" "$B/out" build/bench
git show "$REV:shlight.h" > "$B/shlight.h"
cp bench/bench_basis.c bench/bench_batch.c bench/bench_util.h "$B/bench/"
cp tests/ref/shref.h "$B/tests/ref/"
# the baseline build: bench_basis.c includes ../shlight.h, so a copy next to the old header
$CC $FLAGS -o "$B/bench_basis" "$B/bench/bench_basis.c" -lquadmath -lm
$CC $FLAGS -DBENCH_HEADER='"../shlight.h"' -o "$B/bench_batch" "$B/bench/bench_batch.c" -lm
$CC $FLAGS -o build/bench/bench_basis bench/bench_basis.c -lquadmath -lm
$CC $FLAGS -o build/bench/bench_batch bench/bench_batch.c -lm
r=1
while [ "$r" -le "$ROUNDS" ]; do
  for w in new base; do
    if [ "$w" = new ]; then bb=build/bench/bench_basis; bt=build/bench/bench_batch; else
      bb=$B/bench_basis; bt=$B/bench_batch; fi
    mkdir -p "$B/out/$w-$r"
    "$bb" --quick --no-error --n "$NL" --variants "$VL" --out "$B/out/$w-$r" > "$B/out/$w-$r/basis.txt"
    "$bt" --quick > "$B/out/$w-$r/batch.md"
  done
  echo "== round $r: ratio to the plain loop (new | $REV)"
  for w in new base; do
    echo "-- $w"
    awk '/^### ratio to the plain loop/ {p = 1} /^### value \+ gradient/ {p = 2} /^### / && !/ratio to the plain|value \+ gradient/ {p = 0} p' "$B/out/$w-$r/basis.txt"
    sed -n '/^### reuse/,$p' "$B/out/$w-$r/batch.md"
  done
  r=$((r + 1))
done
