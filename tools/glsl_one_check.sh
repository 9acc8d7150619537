#!/usr/bin/env bash
# tools/glsl_one_check.sh - the one include shlight_glsl/shlight.glsl: fresh (tools/gen_glsl_one.py
# --check) and compiling with glslang as a user writes it (`#version` first, then
# SHLIGHT_MAX_BANDS, then the file) in GLSL 450, 330 and ES 300 (default precision from the
# file), whole and narrowed to one module (SHLIGHT_GLSL_ONLY + SHLIGHT_GLSL_LIGHT: its
# dependencies follow). Prints "N passed, N failed".
set -u
cd "$(dirname "$0")/.."
validator=${GLSLANG_VALIDATOR:-glslangValidator}
pass=0
fail=0
if python3 tools/gen_glsl_one.py --check; then pass=$((pass + 1)); else fail=$((fail + 1)); fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for v in "450" "330" "300 es"; do
  for narrow in "" "#define SHLIGHT_GLSL_ONLY
#define SHLIGHT_GLSL_LIGHT"; do
    f="$tmp/t.frag"
    {
      printf '#version %s\n#define SHLIGHT_MAX_BANDS 9\n%s\n' "$v" "$narrow"
      cat shlight_glsl/shlight.glsl
      printf 'out vec4 o;\nvoid main() {\n  float y[SHLIGHT_MAX_COEFFS];\n'
      printf '  vec3 g[SHLIGHT_MAX_COEFFS];\n'
      printf '  shl_sphere_light_grad(9, vec3(0.0), vec3(0.0, 0.0, 3.0), 0.5, y, g);\n'
      printf '  o = vec4(y[4], g[7]);\n}\n'
    } >"$f"
    if "$validator" -S frag "$f" >"$tmp/log" 2>&1; then
      echo "ok    #version $v${narrow:+ (narrowed to light)}"
      pass=$((pass + 1))
    else
      echo "FAIL  #version $v${narrow:+ (narrowed to light)}"
      head -20 "$tmp/log"
      fail=$((fail + 1))
    fi
  done
done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
