#!/usr/bin/env bash
# bench/budgets.sh - the header's size budgets, as a new user meets them (gcc -O2, default
# target): the header's size; the .text and build time of small user files; the .text and
# build time of the implementation file. Prints a markdown table. With --check, exits 1 when a
# figure exceeds its budget by more than 1.5x (CI). Run from the repository root.
#   bash bench/budgets.sh [--check] [--out FILE]
set -u
cd "$(dirname "$0")/.."
CC=${CC:-gcc}
check=0
out=""
while [ $# -gt 0 ]; do
  case $1 in
  --check) check=1 ;;
  --out) out=$2; shift ;;
  *) echo "usage: bash bench/budgets.sh [--check] [--out FILE]" >&2; exit 2 ;;
  esac
  shift
done
dir=build/budgets
mkdir -p "$dir"
hdr=$(pwd)/shlight.h

cat >"$dir/user_fixed.c" <<'C'
#include "shlight.h"
void user_fixed(const float *d, float *y);
void user_fixed(const float *d, float *y) { shl_sh_eval(4, d, y); }
C
cat >"$dir/user_runtime.c" <<'C'
#include "shlight.h"
void user_runtime(int n, const float *d, float *y);
void user_runtime(int n, const float *d, float *y) { shl_sh_eval(n, d, y); }
C
cat >"$dir/user_sphere.c" <<'C'
#include "shlight.h"
void user_sphere(const float *x, const float *c, float r, float *y);
void user_sphere(const float *x, const float *c, float r, float *y) {
  shl_sphere_light(4, x, c, r, y);
}
C
cat >"$dir/user_all.c" <<'C'
#include "shlight.h"
void user_all(int n, const float *d, const float *x, const float *c, float r, float *y);
void user_all(int n, const float *d, const float *x, const float *c, float r, float *y) {
  shl_sh_eval(4, d, y);
  shl_sh_eval(n, d, y);
  shl_sphere_light(4, x, c, r, y);
}
C
cat >"$dir/impl.c" <<'C'
#define SHLIGHT_IMPLEMENTATION
#include "shlight.h"
C

# text FILE: bytes of executable code in an object file (the .text* sections)
text() { size -A "$1" | awk '$1 ~ /^\.text/ {s += $2} END {print s + 0}'; }
# cpu SECONDS of user + system time of one compile, best of 3 (the machine may be shared)
compile() { # SRC OBJ
  local best=""
  for _ in 1 2 3; do
    local t
    t=$( { /usr/bin/time -f '%U %S' "$CC" -std=c99 -O2 -I. -c "$1" -o "$2" >/dev/null; } 2>&1 |
      tail -n 1 | awk '{printf "%.2f", $1 + $2}')
    if [ -z "$best" ] || awk -v a="$t" -v b="$best" 'BEGIN{exit !(a < b)}'; then best=$t; fi
  done
  echo "$best"
}

rows=()
fail=0
row() { # NAME VALUE BUDGET UNIT
  local verdict
  verdict=$(awk -v v="$2" -v b="$3" 'BEGIN{ if (v <= b) print "met"; else if (v <= 1.5 * b) print "over (< 1.5x)"; else print "FAIL (> 1.5x)" }')
  case $verdict in FAIL*) fail=$((fail + 1)) ;; esac
  rows+=("| $1 | $2 $4 | $3 $4 | $verdict |")
}

hb=$(wc -c <"$hdr")
row "shlight.h size" "$((hb / 1024))" 600 KB
for u in user_fixed user_runtime user_sphere user_all; do
  t=$(compile "$dir/$u.c" "$dir/$u.o")
  row "$u.c .text (gcc -O2)" "$(text "$dir/$u.o")" 8192 B
  row "$u.c build (CPU)" "$t" 0.2 s
done
t=$(compile "$dir/impl.c" "$dir/impl.o")
row "implementation .text (gcc -O2)" "$(( $(text "$dir/impl.o") / 1024 ))" 250 KB
row "implementation build (CPU)" "$t" 2.5 s

{
  echo "Budgets ($($CC --version | head -n 1), -std=c99 -O2, $(uname -m)); user files as in bench/budgets.sh"
  echo
  echo "| figure | measured | budget | |"
  echo "|---|---|---|---|"
  printf '%s\n' "${rows[@]}"
} | tee ${out:+"$out"}
if [ $check -eq 1 ]; then
  echo "budgets: $(( ${#rows[@]} - fail )) passed, $fail failed"
  [ $fail -eq 0 ]
fi
