#!/usr/bin/env bash
# bench/glsl_spirv.sh [GLSL_DIR] - glslang SPIR-V size (glslangValidator -G: OpenGL SPIR-V,
# plain and -Os) of a fragment shader that calls shl_sh_eval (values) or shl_sh_eval_grad
# (values + gradient) at n = 4, 9, 16 bands and consumes every output with a constant index.
#   bench/glsl_spirv.sh [--check F] [GLSL_DIR]
# --check F: exit 1 when a row with a budget (values + gradient, n = 16: 150,000 bytes, plain)
# is over F times it (CI: F = 2); ends with "N passed, N failed".
set -eu
cd "$(dirname "$0")/.."
factor=""
if [ "${1:-}" = "--check" ]; then
  factor=$2
  shift 2
fi
dir=${1:-shlight_glsl}
passed=0
failed=0
validator=${GLSLANG_VALIDATOR:-glslangValidator}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
printf '%-28s %10s %10s %10s\n' "shader" "bytes" "-Os bytes" "budget"
for kind in values gradient; do
  for n in 4 9 16; do
    {
      printf '#version 450\n#define SHLIGHT_MAX_BANDS %d\n' "$n"
      cat "$dir/shl_prelude.glsl" "$dir/shl_basis.glsl"
      [ "$kind" = gradient ] && cat "$dir/shl_gradient.glsl"
      printf 'layout(location = 0) in vec3 v_dir;\nlayout(location = 0) out vec4 o_col;\n'
      printf 'void main() {\n  float y[SHLIGHT_MAX_COEFFS];\n  vec3 g[SHLIGHT_MAX_COEFFS];\n'
      printf '  float a = 0.0;\n  vec3 b = vec3(0.0);\n'
      if [ "$kind" = gradient ]; then
        printf '  shl_sh_eval_grad(SHLIGHT_MAX_BANDS, v_dir, y, g);\n'
        for ((i = 0; i < n * n; i++)); do printf '  a += y[%d];\n  b += g[%d];\n' "$i" "$i"; done
      else
        printf '  shl_sh_eval(SHLIGHT_MAX_BANDS, v_dir, y);\n'
        for ((i = 0; i < n * n; i++)); do printf '  a += y[%d];\n' "$i"; done
      fi
      printf '  o_col = vec4(b, a);\n}\n'
    } >"$tmp/s.frag"
    "$validator" -G -o "$tmp/a.spv" "$tmp/s.frag" >/dev/null
    "$validator" -G -Os -o "$tmp/b.spv" "$tmp/s.frag" >/dev/null
    label="values"
    [ "$kind" = gradient ] && label="values + gradient"
    bytes=$(stat -c %s "$tmp/a.spv")
    budget=""
    [ "$kind" = gradient ] && [ "$n" = 16 ] && budget=150000
    printf '%-28s %10d %10d %10s\n' "$label, n = $n" "$bytes" "$(stat -c %s "$tmp/b.spv")" "$budget"
    if [ -n "$factor" ] && [ -n "$budget" ]; then
      if awk -v b="$bytes" -v l="$budget" -v f="$factor" 'BEGIN { exit !(b <= l * f) }'; then
        passed=$((passed + 1))
      else
        echo "FAIL $label, n = $n: $bytes bytes > $factor x $budget"
        failed=$((failed + 1))
      fi
    fi
  done
done
if [ -n "$factor" ]; then
  echo "$passed passed, $failed failed"
  [ "$failed" -eq 0 ]
fi
