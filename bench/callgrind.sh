#!/bin/sh
# callgrind.sh - instructions per call of each shlight basis variant (bench/bench_basis.c).
#
# valgrind 3.19 cannot decode AVX-512, so this builds a separate -O3 -march=x86-64-v3 (AVX2+FMA)
# binary; the batch kernel therefore runs its 8-lane AVX2 path here (16 lanes in the timed build).
# Each (variant, n) runs `bench_basis_cg --count-only VARIANT N K` under
#   valgrind --tool=callgrind --toggle-collect='bw_*'
# so only the instructions executed inside the wrapper bw_* (and everything it calls) are
# counted: the timing loop and the function-pointer call are not (the row `empty` shows the
# wrapper's own cost, its `ret`).  -Wl,-z,now binds symbols at load time, so no lazy-binding
# work lands in the first call.  Per call = total / K; batch: per direction = total / (K * 1024).
#
# Usage: sh bench/callgrind.sh [N-LIST] [VARIANT-LIST]     (run from the repository root)
#   defaults: N-LIST "1 2 ... 16 32 64", VARIANT-LIST "eval eval_rt accurate batch batch16 grad
#   grad_sph dotgrad loop empty".  Env: CC (gcc), JOBS (2 parallel valgrinds), OUT (bench/out).
# Writes $OUT/instr.md (markdown table) and $OUT/instr.csv (variant,n,instr; read by
# bench_basis --callgrind).
set -eu
CC=${CC:-gcc}
JOBS=${JOBS:-2}
OUT=${OUT:-bench/out}
NS=${1:-"1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 32 64"}
VS=${2:-"eval eval_rt accurate batch batch16 grad grad_sph dotgrad loop empty"}
BIN=build/bench/bench_basis_cg
CGFLAGS="-std=c99 -O3 -march=x86-64-v3 -ffp-contract=fast -DNDEBUG"

command -v valgrind >/dev/null || { echo "callgrind.sh: valgrind not found" >&2; exit 1; }
mkdir -p build/bench "$OUT"
if [ ! -x "$BIN" ] || [ bench/bench_basis.c -nt "$BIN" ] || [ shlight.h -nt "$BIN" ]; then
  echo "callgrind.sh: building $BIN ($CC $CGFLAGS)" >&2
  $CC $CGFLAGS -DBENCH_FLAGS="\"$CC $CGFLAGS\"" -Wl,-z,now -o "$BIN" bench/bench_basis.c \
    -lquadmath -lm
fi
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

# K: enough calls to average over the directions' branches, few enough to stay fast.
kfor() { # variant n
  case $1 in
  batch) echo 2 ;;
  batch16) echo $((2048 / ($2 * $2) + 16)) ;;
  grad | grad_sph | dotgrad) echo $((20000 / ($2 * $2) + 16)) ;;
  *) echo $((100000 / ($2 * $2) + 32)) ;;
  esac
}
for v in $VS; do for n in $NS; do echo "$v $n $(kfor "$v" "$n")"; done; done >"$TMP/jobs"

# one valgrind per job, $JOBS at a time; each writes its total to $TMP/v_n.tot
xargs -P "$JOBS" -L 1 sh -c '
  f="'"$TMP"'/$0_$1"
  valgrind --tool=callgrind --toggle-collect="bw_*" --callgrind-out-file="$f.cg" \
    '"$BIN"' --count-only "$0" "$1" "$2" >"$f.log" 2>&1 || { echo "failed: $0 $1" >&2; exit 1; }
  tot=$(sed -n "s/^totals: *//p;s/^summary: *//p" "$f.cg" | head -n 1)
  echo "$2 ${tot:-0}" >"$f.tot"' <"$TMP/jobs"

{
  REV=$(git rev-parse --short HEAD 2>/dev/null || echo "?")
  git diff --quiet HEAD -- shlight.h 2>/dev/null ||
    REV="$REV+dirty, blob $(git hash-object shlight.h | cut -c1-10)"
  echo "### instructions per call (callgrind, \`$CC $CGFLAGS\`; shlight.h at $REV; batch: per direction)"
  echo
  printf '| variant |'; for n in $NS; do printf ' n=%s |' "$n"; done; echo
  printf '|---|'; for n in $NS; do printf -- '---|'; done; echo
} >"$OUT/instr.md"
echo "variant,n,instr" >"$OUT/instr.csv"
for v in $VS; do
  printf '| %s |' "$v" >>"$OUT/instr.md"
  for n in $NS; do
    read -r k tot <"$TMP/${v}_$n.tot"
    case $v in
    batch) d=$((k * 1024)) ;;
    batch16) d=$((k * 16)) ;;
    *) d=$k ;;
    esac
    per=$(awk -v t="$tot" -v d="$d" 'BEGIN { x = t / d; printf (x < 10 ? "%.2f" : "%.0f"), x }')
    printf ' %s |' "$per" >>"$OUT/instr.md"
    echo "$v,$n,$per" >>"$OUT/instr.csv"
  done
  echo >>"$OUT/instr.md"
done
cat "$OUT/instr.md"
