#!/usr/bin/env bash
# glsl_validate.sh - offline validation of shlight's shared GLSL with glslangValidator (no GL).
#
# usage: tools/glsl_validate.sh [--allow-warnings] [FILE.glsl ...]
#
# The files are concatenated in the order given, as one shader, for each of
#   #version 450     compute stub   layout(local_size_x = 1) in; void main() {}
#   #version 330     fragment stub  out vec4 o; void main() { o = vec4(0.0); }
#   #version 300 es  fragment stub  (plus precision highp float; precision highp int;)
# with #define SHLIGHT_MAX_BANDS 4 and again with 8: six runs, one line each, then
# "N passed, N failed". Each file is preceded by #line 1 "<basename>"
# (GL_GOOGLE_cpp_style_line_directive), so errors read `shl_basis.glsl:12: ...`.
# glslangValidator runs in link mode (-l), which also reports recursion.
# Warnings (e.g. reserved `__` identifiers) fail a run unless --allow-warnings is given.
#
# Files: the arguments; else $SHLIGHT_GLSL_FILES (space separated); else
# shlight_glsl/shl_prelude.glsl followed by the other shlight_glsl/shl_*.glsl in the order of
# shlight_glsl/MODULES if it exists (one module a line: shl_basis.glsl, shl_basis or basis;
# `#` starts a comment; modules it does not list follow alphabetically, with a note), else
# alphabetically.
#
# Exit status: 0 all passed, 1 a run failed (or MODULES names a missing file), 2 usage error.
# $GLSLANG_VALIDATOR overrides the validator binary.
set -u
export LC_ALL=C

validator=${GLSLANG_VALIDATOR:-glslangValidator}
allow_warnings=0
if [ "${1:-}" = "--allow-warnings" ]; then
  allow_warnings=1
  shift
fi
case "${1:-}" in -*) sed -n '2,/^set -u/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 2 ;; esac

files=()
bad_modules=0
if [ $# -gt 0 ]; then
  files=("$@")
elif [ -n "${SHLIGHT_GLSL_FILES:-}" ]; then
  read -r -a files <<<"$SHLIGHT_GLSL_FILES"
else
  dir="$(cd "$(dirname "$0")/.." && pwd)/shlight_glsl"
  [ -f "$dir/shl_prelude.glsl" ] && files+=("$dir/shl_prelude.glsl")
  listed=" shl_prelude.glsl "
  if [ -f "$dir/MODULES" ]; then
    while IFS= read -r line || [ -n "$line" ]; do
      name=$(printf '%s' "${line%%#*}" | tr -d ' \t\r')
      [ -n "$name" ] || continue
      name=${name%.glsl}
      case $name in shl_*) ;; *) name="shl_$name" ;; esac
      case $listed in *" $name.glsl "*) continue ;; esac
      listed="$listed$name.glsl "
      if [ -f "$dir/$name.glsl" ]; then
        files+=("$dir/$name.glsl")
      else
        echo "FAIL shlight_glsl/MODULES lists $name, but shlight_glsl/$name.glsl does not exist"
        bad_modules=1
      fi
    done <"$dir/MODULES"
  fi
  for f in "$dir"/shl_*.glsl; do # sorted by byte value (LC_ALL=C above)
    [ -f "$f" ] || continue
    case $listed in *" $(basename "$f") "*) continue ;; esac
    [ -f "$dir/MODULES" ] && echo "note: $(basename "$f") is not in shlight_glsl/MODULES; appended"
    files+=("$f")
  done
fi

if [ ${#files[@]} -eq 0 ]; then
  echo "glsl_validate: no GLSL files (give files, set SHLIGHT_GLSL_FILES or fill shlight_glsl/)" >&2
  exit 2
fi
for f in "${files[@]}"; do
  [ -r "$f" ] || { echo "glsl_validate: cannot read $f" >&2; exit 2; }
done
command -v "$validator" >/dev/null 2>&1 || {
  echo "glsl_validate: $validator not found (Debian: apt-get install glslang-tools)" >&2
  exit 2
}

names=()
for f in "${files[@]}"; do names+=("$(basename "$f")"); done
echo "files: ${names[*]}"

tmp=$(mktemp -d) || exit 2
trap 'rm -rf "$tmp"' EXIT
passed=0
failed=$bad_modules
for bands in 4 8; do
  for version in "450" "330" "300 es"; do
    {
      echo "#version $version"
      echo "#extension GL_GOOGLE_cpp_style_line_directive : require"
      case $version in *es) printf 'precision highp float;\nprecision highp int;\n' ;; esac
      echo "#define SHLIGHT_MAX_BANDS $bands"
      # the 8-band runs also compile the FAST edge method (off by default in GLSL)
      [ "$bands" = 8 ] && echo "#define SHLIGHT_EDGE_FAST_ON 1"
      for f in "${files[@]}"; do
        echo "#line 1 \"$(basename "$f")\""
        cat "$f"
        echo
      done
      echo '#line 1 "validate_stub"'
      if [ "$version" = 450 ]; then
        echo 'layout(local_size_x = 1) in; void main() {}'
      else
        echo 'out vec4 o; void main() { o = vec4(0.0); }'
      fi
    } >"$tmp/src"
    stage=frag
    [ "$version" = 450 ] && stage=comp
    "$validator" -l --stdin -S "$stage" <"$tmp/src" >"$tmp/log" 2>&1
    rc=$?
    label=$(printf '#version %-6s %-8s SHLIGHT_MAX_BANDS=%s' "$version" "($stage)" "$bands")
    if [ $rc -eq 0 ] && { [ $allow_warnings = 1 ] || ! grep -q '^WARNING' "$tmp/log"; }; then
      echo "ok   $label"
      passed=$((passed + 1))
    else
      echo "FAIL $label"
      grep -v -e '^stdin$' -e '^[[:space:]]*$' "$tmp/log" | sed 's/^/       /'
      failed=$((failed + 1))
    fi
  done
done
echo "$passed passed, $failed failed"
[ $failed -eq 0 ]
