# callgrind_lib.sh - shared steps of the bench/callgrind_*.sh scripts; sourced (`. bench/callgrind_lib.sh`)
# from the repository root after `set -eu` and CC. -O3 -march=x86-64-v3: valgrind 3.19 cannot
# decode AVX-512. Only the wrappers bw_* and what they call are counted (--toggle-collect);
# -Wl,-z,now binds symbols at load time, so no lazy-binding cost lands in them.
CG_FLAGS="-std=c99 -O3 -march=x86-64-v3 -ffp-contract=fast -DNDEBUG"

# cg_build NAME [LIBS...]: bench/NAME.c -> BIN=build/bench/NAME_cg
cg_build() {
  BIN=build/bench/$1_cg
  src=bench/$1.c
  shift
  mkdir -p build/bench bench/out
  $CC $CG_FLAGS -Wl,-z,now -o "$BIN" "$src" "$@"
}

# cg_run OUT ARGS...: callgrind of "$BIN" ARGS... into OUT; cg_total OUT: its instruction total
cg_run() {
  out=$1
  shift
  valgrind --tool=callgrind --toggle-collect='bw_*' --callgrind-out-file="$out" \
    "$BIN" "$@" >/dev/null 2>&1
}
cg_total() {
  sed -n 's/^totals: *//p;s/^summary: *//p' "$1" | head -n 1
}

# cg_quads1750 NAME KERNEL [SRC...]: one pass (--count-only 1) of bench_NAME (linked with the
# SRCs) over the 1,750 quads of tests/ref/ggxcases.h; instructions per quad of KERNEL into
# bench/out/NAME_instr.md
cg_quads1750() {
  n=$1
  k=$2
  shift 2
  cg_build "bench_$n" "$@" -lm
  set -- "$n" "$k"
  K=1
  cg_run "build/bench/cg_$1.out" --count-only $K
  tot=$(cg_total "build/bench/cg_$1.out")
  {
    echo "### x86 instructions per quad light (callgrind, \`$CC -O3 -march=x86-64-v3\`, the 1,750 quads of bench_$1)"
    echo
    echo "| kernel | instructions per quad |"
    echo "|---|---|"
    echo "| $2 | $(awk -v t="$tot" -v k=$K 'BEGIN { printf "%.0f", t / (k * 1750) }') |"
  } >"bench/out/$1_instr.md"
  cat "bench/out/$1_instr.md"
}
