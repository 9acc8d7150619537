#!/usr/bin/env bash
# Self-test for tools/check_mirror.py.
#
# good/ is a small correct pair (fake shlight.h + shlight_glsl/).  Each bad case
# copies it to a temporary directory, applies literal text edits, runs the
# checker and asserts its exit status, its number of failed checks and that
# the expected messages appear.  Usage: tools/tests_mirror/run.sh [-v]
set -u
HERE=$(cd "$(dirname "$0")" && pwd)
CHECK="$HERE/../check_mirror.py"
PY=${PYTHON:-python3}
# resolve version-manager shims (pyenv) once: ~3x faster start per call
PY=$("$PY" -c 'import sys; print(sys.executable)') || { echo "run.sh: no python3" >&2; exit 2; }
VERBOSE=0
[ "${1:-}" = "-v" ] && VERBOSE=1
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
passed=0
failed=0
CUR=
NAME=

# variant NAME: fresh copy of good/ in $CUR
variant() {
    NAME=$1
    CUR="$TMP/$1"
    rm -rf "$CUR"
    cp -R "$HERE/good" "$CUR"
}

# edit FILE OLD NEW: replace the first occurrence of the literal OLD (must exist)
edit() {
    local f="$CUR/$1" s
    s=$(cat "$f") || exit 2
    if [[ "$s" != *"$2"* ]]; then
        echo "run.sh: case $NAME: edit of $1 did not apply" >&2
        exit 2
    fi
    printf '%s\n' "${s/"$2"/"$3"}" > "$f"
}

# both OLD NEW: the same edit in the C header and in shl_basis.glsl
both() {
    edit shlight.h "$1" "$2"
    edit shlight_glsl/shl_basis.glsl "$1" "$2"
}

# expect RC NFAILED [SUBSTRING...] [-- CHECKER OPTIONS]: run the checker on $CUR
expect() {
    local want_rc=$1 want_failed=$2
    shift 2
    local subs=() opts=()
    while [ $# -gt 0 ]; do
        if [ "$1" = "--" ]; then shift; opts=("$@"); break; fi
        subs+=("$1")
        shift
    done
    local out rc why=""
    out=$("$PY" "$CHECK" --root "$CUR" "${opts[@]}" 2>&1)
    rc=$?
    local last
    last=$(printf '%s\n' "$out" | tail -n 1)
    if ! printf '%s\n' "$last" | grep -Eq '^[0-9]+ passed, [0-9]+ failed$'; then
        why="last line is not 'N passed, N failed': $last"
    elif [ "$rc" != "$want_rc" ]; then
        why="exit status $rc, expected $want_rc"
    elif [ "$want_failed" != "-" ] && [ "${last#* passed, }" != "$want_failed failed" ]; then
        why="'$last', expected $want_failed failed"
    else
        local s
        for s in "${subs[@]+"${subs[@]}"}"; do
            if ! printf '%s\n' "$out" | grep -Fq -- "$s"; then
                why="missing in output: $s"
                break
            fi
        done
    fi
    if [ -z "$why" ]; then
        passed=$((passed + 1))
        echo "ok    $NAME"
        [ $VERBOSE = 1 ] && printf '%s\n' "$out" | grep -v '^ok ' | sed 's/^/        /'
    else
        failed=$((failed + 1))
        echo "FAIL  $NAME: $why"
        printf '%s\n' "$out" | sed 's/^/        /'
    fi
    return 0
}

# lintcase NAME STATEMENT SUBSTRING: insert STATEMENT into shl_sh_dot on both
# sides (so signature and body still agree) and expect exactly the lint check to fail
lintcase() {
    variant "lint_$1"
    both "float s = 0.0f;" "float s = 0.0f; $2"
    expect 1 1 "FAIL  basis: shl_sh_dot lint" "$3"
}

# ---------------------------------------------------------------- good pairs
variant good
expect 0 0 "ok    basis: shl_sh_eval body" "ok    basis: table SHLI_K" "ok    gradient: order" \
    "30 passed, 0 failed" "shlg_sum4 GLSL-only helper"

variant good_quiet
out=$("$PY" "$CHECK" --root "$CUR" -q); rc=$?
if [ $rc = 0 ] && [ "$out" = "30 passed, 0 failed" ]; then
    passed=$((passed + 1)); echo "ok    $NAME"
else
    failed=$((failed + 1)); echo "FAIL  $NAME: -q printed: $out"
fi

variant good_ifdef_stop      # the other form of the stop line
edit shlight.h "#if defined(SHLIGHT_IMPLEMENTATION) && !defined(SHLIGHT_IMPLEMENTATION_DONE)" \
    "#ifdef SHLIGHT_IMPLEMENTATION"
expect 0 0

variant good_line_anchor     # // comment anchors work too
edit shlight.h "/* >>gradient ----" "// >>gradient
/* ----"
expect 0 0

variant good_comments_whitespace   # comments and layout do not matter
edit shlight_glsl/shl_gradient.glsl "    shl_sh_eval(n, d, out_y);" "    shl_sh_eval( n,d,
        out_y ) /* comment */ ; // another"
expect 0 0

variant good_tricky_subset   # legal expressions that look like forbidden ones
both "float s = 0.0f;" "float s = 0.0f; int t = (n) * 2; int u = t++ * 2; t = t & 1; u = -t * -u;
    s = s * SHLIGHT_ITOF(t) + -1.0f * a[0] * (b[0]) == 0.0f ? s : -s; s = s * (s) + (t & u) * 1.0f;"
expect 0 0

variant good_double_literal_allowed   # allowed unless --require-f-suffix
both "float s = 0.0f;" "float s = 0.5;"
expect 0 0

# ---------------------------------------------------------------- signatures
variant renamed_param
edit shlight_glsl/shl_basis.glsl "float b[SHLIGHT_MAX_COEFFS])" "float c[SHLIGHT_MAX_COEFFS])"
expect 1 1 "FAIL  basis: shl_sh_dot signature" "param 3 name: C \`b\`" "shl_basis.glsl:"

variant wrong_qualifier      # C float out_v[3] is an output vec3
edit shlight_glsl/shl_basis.glsl "out vec3 out_v" "vec3 out_v"
expect 1 1 "FAIL  basis: shl_sh4_scale@79 signature" "param 3 \`out_v\`"

variant wrong_array_type     # float (*out_grad)[3] is out vec3 out_grad[N], not float[N]
edit shlight_glsl/shl_gradient.glsl "out vec3 out_grad[" "out float out_grad["
expect 1 1 "FAIL  gradient: shl_sh_eval_grad signature" "out vec3[N] out_grad"

variant c_output_not_named_out
edit shlight.h "float *io_acc" "float *acc"
edit shlight_glsl/shl_basis.glsl "inout float io_acc" "inout float acc"
expect 1 1 "FAIL  basis: shl_sh4_scale@79 signature" "must be named out_* or io_*"

variant param_count
edit shlight_glsl/shl_basis.glsl "float shli_sq(float x)" "float shli_sq(float x, float y)"
expect 1 1 "FAIL  basis: shli_sq signature" "parameter count: C 1"

variant return_type
edit shlight_glsl/shl_gradient.glsl "shl_sh4 shl_sh4_make" "float shl_sh4_make"
expect 1 1 "FAIL  gradient: shl_sh4_make signature" "return type: C \`shl_sh4\`"

variant c_return_pointer
edit shlight.h "SHLIGHT_INLINE float shli_sq(float x)" "SHLIGHT_INLINE float *shli_sq(float x)"
expect 1 1 "FAIL  basis: shli_sq signature" "C return type \`float *\` not allowed"

# ---------------------------------------------------------------- order / presence
variant swapped_order
edit shlight_glsl/shl_basis.glsl "float shli_sq(float x) { return x * x; }" ""
edit shlight_glsl/shl_basis.glsl "float shlg_sum4" "float shli_sq(float x) { return x * x; }
float shlg_sum4"
expect 1 1 "FAIL  basis: order" "C has \`shli_sq\`" "GLSL order: shl_sh_eval shli_sq"

variant missing_function
edit shlight_glsl/shl_gradient.glsl "shl_sh4 shl_sh4_make(float c0)" "shl_sh4 shlg_make(float c0)"
expect 1 1 "FAIL  gradient: shl_sh4_make present" "kernel has no GLSL function"

variant extra_function
edit shlight_glsl/shl_gradient.glsl "shl_sh4 shl_sh4_make" "float shl_extra(float x) { return x; }
shl_sh4 shl_sh4_make"
expect 1 1 "FAIL  gradient: shl_extra extra" "GLSL-only helpers are named shlg_*"

variant missing_else_branch  # C has two #if/#else definitions, GLSL only one
edit shlight_glsl/shl_basis.glsl "#else
void shl_sh4_scale" "#else
void shlg_scale_unused"
expect 1 1 "FAIL  basis: shl_sh4_scale@91 present"

variant missing_module_file
rm "$CUR/shlight_glsl/shl_gradient.glsl"
expect 1 1 "FAIL  gradient: module file" "shl_gradient.glsl missing"

variant orphan_glsl_file
printf 'float shl_x(float a) { return a; }\n' > "$CUR/shlight_glsl/shl_lighting.glsl"
expect 1 1 "FAIL  shl_lighting.glsl: module" "no section \`/* >>lighting */\`"

variant kernel_before_anchor
edit shlight.h "/* >>prelude" "SHLIGHT_INLINE int shl_early(int a) { return a; }
/* >>prelude"
expect 1 1 "FAIL  header: structure" "kernel \`shl_early\` lies before the first >>module anchor"

variant duplicate_anchor
edit shlight.h "/* >>gradient ----" "/* >>basis ----"
expect 1 - "FAIL  header: structure" "anchor >>basis repeats"

variant no_stop_line         # without the stop line the implementation part is scanned
edit shlight.h "#if defined(SHLIGHT_IMPLEMENTATION) && !defined(SHLIGHT_IMPLEMENTATION_DONE)" "#if 1"
expect 1 - "FAIL  impl: module file"

# ---------------------------------------------------------------- bodies
variant changed_token
edit shlight_glsl/shl_basis.glsl "out_y[2] = SHLI_K[2] * z;" "out_y[2] = SHLI_K[2] * y;"
expect 1 1 "FAIL  basis: shl_sh_eval body" "C \`z\` vs GLSL \`y\`" "shlight.h:54" "shl_basis.glsl:25"

variant changed_pp_in_body
edit shlight_glsl/shl_basis.glsl "#if SHLIGHT_MAX_BANDS > 2" "#if SHLIGHT_MAX_BANDS > 3"
expect 1 1 "FAIL  basis: shl_sh_eval body" "C \`2\` vs GLSL \`3\`"

variant pp_line_break_in_body  # the end of a preprocessor line is a token
edit shlight_glsl/shl_basis.glsl "#if SHLIGHT_MAX_BANDS > 2
    if (n > 2) {" "#if SHLIGHT_MAX_BANDS > 2 if (n > 2)
    {"
expect 1 1 "FAIL  basis: shl_sh_eval body" "C \`<newline>\` vs GLSL \`if\`"

variant changed_literal
edit shlight_glsl/shl_gradient.glsl "* 0.5f;" "* 0.50f;"
expect 1 1 "FAIL  gradient: shl_sh4_make body" "C \`0.5f\` vs GLSL \`0.50f\`"

variant missing_statement
edit shlight_glsl/shl_basis.glsl "    i >>= 1;
" ""
expect 1 1 "FAIL  basis: shl_sh4_scale@79 body"

# ---------------------------------------------------------------- lint, one construct each
lintcase arrow          "s = p->x;"                 "forbidden \`->\`"
lintcase address_of     "s = s + (&s)[0];"          "unary \`&\` (address-of)"
lintcase deref          "s = *a;"                   "unary \`*\` (dereference)"
lintcase deref_return   "return *a;"                "unary \`*\` (dereference)"
lintcase pointer_decl   "const float *p = a;"       "pointer declaration \`float *\`"
lintcase unsigned       "unsigned u = 1;"           "forbidden keyword \`unsigned\`"
lintcase double         "double t = 0.0f;"          "forbidden keyword \`double\`"
lintcase long           "long t = 0;"               "forbidden keyword \`long\`"
lintcase short          "short t = 0;"              "forbidden keyword \`short\`"
lintcase char           "char t = 0;"               "forbidden keyword \`char\`"
lintcase goto           "goto done;"                "forbidden keyword \`goto\`"
lintcase sizeof         "s = s + sizeof(s);"        "forbidden keyword \`sizeof\`"
lintcase static         "static float t = 0.0f;"    "forbidden keyword \`static\`"
lintcase struct_kw      "struct shl_sh4 t;"         "forbidden keyword \`struct\`"
lintcase brace_init     "float t[2] = { 0.0f, 1.0f };" "brace initialiser"
lintcase double_us      "float my__t = 0.0f;"       "contains \`__\`"
lintcase gl_prefix      "float gl_t = 0.0f;"        "reserved gl_ prefix"
lintcase cast_float     "s = (float)n;"             "C cast \`( float )\`"
lintcase cast_int       "int t = (int)s;"           "C cast \`( int )\`"
lintcase cast_struct    "shl_sh4 t = (shl_sh4)s;"   "C cast \`( shl_sh4 )\`"
lintcase cast_alias     "s = (shli_real)s;"         "C cast \`( shli_real )\`"
lintcase pointer_alias  "shli_real *p;"             "pointer declaration \`shli_real *\`"
lintcase reserved_input "float input = 0.0f;"       "GLSL reserved word \`input\`"
lintcase reserved_sample "float sample = 0.0f;"     "GLSL reserved word \`sample\`"
lintcase reserved_filter "float filter = 0.0f;"     "GLSL reserved word \`filter\`"
lintcase reserved_out   "float out = 0.0f;"         "GLSL reserved word \`out\`"
lintcase reserved_vec3  "float vec3 = 0.0f;"        "GLSL reserved word \`vec3\`"
lintcase float_no_dot   "s = 1f;"                   "float literal \`1f\`"
lintcase float_dot_only "s = 2.f;"                  "float literal \`2.f\`"
lintcase float_leading  "s = .5f;"                  "float literal \`.5f\`"
lintcase float_exp      "s = 1e5f;"                 "float literal \`1e5f\`"
lintcase int_suffix_u   "int t = 1u;"               "integer literal \`1u\` with a suffix"
lintcase int_suffix_l   "int t = 1l;"               "integer literal \`1l\` with a suffix"
lintcase hex            "int t = 0x10;"             "hex literal \`0x10\`"
lintcase octal          "int t = 010;"              "octal literal \`010\`"
lintcase call_sqrtf     "s = sqrtf(s);"             "call to \`sqrtf\` not allowed"
lintcase call_sqrt      "s = sqrt(s);"              "call to \`sqrt\` not allowed"
lintcase call_abs       "s = abs(s);"               "call to \`abs\` not allowed"
lintcase call_glsl_only "s = shlg_sum4(a);"         "call to \`shlg_sum4\` not allowed"
lintcase constructor    "s = float(n);"             "constructor \`float(\` is not C"
lintcase recursion      "s = shl_sh_dot(n, a, b);"  "recursion: \`shl_sh_dot\` calls itself"
lintcase calls_later    "shl_sh_eval_grad(n, a, a, a);" "calls \`shl_sh_eval_grad\`, which is defined later"
lintcase calls_unknown  "s = shl_nope(s);"          "calls \`shl_nope\`, which is not a kernel"
lintcase string         "s = s + 'a';"              "string/char literal"

variant lint_reserved_param  # reserved word as a parameter name (signature, not body)
both "shli_sq(float x) { return x * x; }" "shli_sq(float filter) { return filter * filter; }"
expect 1 1 "FAIL  basis: shli_sq lint" "GLSL reserved word \`filter\`"

variant lint_line_numbers    # lint reports file:line of the C side
edit shlight.h "    out_y[3] = -SHLI_K[3] * x;" "    out_y[3] = -SHLI_K[3] * (float)x;"
edit shlight_glsl/shl_basis.glsl "    out_y[3] = -SHLI_K[3] * x;" "    out_y[3] = -SHLI_K[3] * (float)x;"
expect 1 1 "FAIL  basis: shl_sh_eval lint" "shlight.h:55: C cast"

variant lint_require_f_suffix   # opt-in: unsuffixed float literals are doubles in C
both "float s = 0.0f;" "float s = 0.5;"
expect 1 2 "FAIL  basis: shl_sh_dot lint" "float literal \`0.5\` without f suffix is a double" \
    "FAIL  gradient: table SHLI_R" "float literal \`0.125\` without f suffix" -- --require-f-suffix

# ---------------------------------------------------------------- tables
variant table_value
edit shlight_glsl/shl_basis.glsl "float[4](0.28209479177387814, 0.4886025119029199" \
    "float[4](0.28209479177387814, 0.4886"
expect 1 1 "FAIL  basis: table SHLI_K" "value 1: C \`0.4886025119029199f\`"

variant table_value_same_float32   # 0.48860252 rounds to the same float
edit shlight_glsl/shl_basis.glsl "float[4](0.28209479177387814, 0.4886025119029199" \
    "float[4](0.28209479177387814, 0.48860252"
expect 0 0

variant table_int_value
edit shlight_glsl/shl_basis.glsl "(0, 1, 1, 1, 2, 2, 2, 2, 2)" "(0, 1, 1, 1, 2, 2, 2, 2, 3)"
expect 1 1 "FAIL  basis: table SHLI_BAND" "value 8: C \`2\`"

variant table_too_long
edit shlight_glsl/shl_basis.glsl "(0, 1, 1, 1, 2, 2, 2, 2, 2)" "(0, 1, 1, 1, 2, 2, 2, 2, 2, 3)"
expect 1 1 "FAIL  basis: table SHLI_BAND" "GLSL has 10 values"

variant table_size_vs_count
edit shlight_glsl/shl_basis.glsl "const float SHLI_K[4] = float[4]" "const float SHLI_K[5] = float[5]"
expect 1 1 "FAIL  basis: table SHLI_K" "GLSL size 5 but 4 values"

variant table_type
edit shlight_glsl/shl_basis.glsl "const int SHLI_BAND[SHLIGHT_MAX_COEFFS] = int[SHLIGHT_MAX_COEFFS](0, 1, 1, 1, 2, 2, 2, 2, 2)" \
    "const float SHLI_BAND[SHLIGHT_MAX_COEFFS] = float[SHLIGHT_MAX_COEFFS](0.0, 1.0, 1.0, 1.0, 2.0, 2.0, 2.0, 2.0, 2.0)"
expect 1 1 "FAIL  basis: table SHLI_BAND" "type: C \`int\`"

variant table_int_literal_in_float_table   # GLSL ES has no implicit int -> float
edit shlight.h "0.28209479177387814f, 0.4886025119029199f, 0.4886025119029199f," "1, 0.4886025119029199f, 0.4886025119029199f,"
edit shlight_glsl/shl_basis.glsl "float[4](0.28209479177387814," "float[4](1,"
expect 1 1 "FAIL  basis: table SHLI_K" "shlight.h:34: integer literal \`1\` in a float table" \
    "shl_basis.glsl:6: integer literal \`1\` in a float table"

variant table_alias_value   # shli_real table compared as float
edit shlight_glsl/shl_gradient.glsl "float[3](0.5, 0.25, 0.125)" "float[3](0.5, 0.25, 0.1251)"
expect 1 1 "FAIL  gradient: table SHLI_R" "value 2: C \`0.125\`"

variant table_missing
edit shlight_glsl/shl_basis.glsl "const float SHLI_K[" "const float SHLG_K["
expect 1 1 "FAIL  basis: table SHLI_K" "table has no GLSL counterpart"

variant table_cpu_only
edit shlight_glsl/shl_basis.glsl "const int SHLI_BAND[" "const int SHLG_BAND["
expect 0 0 "used by C-only helpers alone"

variant table_extra
edit shlight_glsl/shl_basis.glsl "const float SHLG_ONLY[2]" "const float SHLI_ONLY[2]"
expect 1 1 "FAIL  basis: table SHLI_ONLY" "GLSL table has no C counterpart"

# a region under >>generated after the implementation counts at its section's marker line
SH4_DEF='SHLIGHT_INLINE shl_sh4 shl_sh4_make(float c0)
{
    shl_sh4 r;
    r.c[0] = c0;
    r.c[1] = 0.0f;
    r.c[2] = 0.0f;
    r.c[3] = SHLIGHT_ITOF(SHLIGHT_FTOI(c0 * 2.0f)) * 0.5f;
    return r;
}'
SH4_MARK='/* @generated sh4: defined in >>generated at the end of the file */
SHLIGHT_INLINE shl_sh4 shl_sh4_make(float c0);'
SH4_GEN='#endif /* SHLIGHT_H */

/* >>generated: the generated regions */
/* @generated begin sh4 */
'"$SH4_DEF"'
/* @generated end sh4 */'

variant generated_region
edit shlight.h "$SH4_DEF" "$SH4_MARK"
edit shlight.h "#endif /* SHLIGHT_H */" "$SH4_GEN"
expect 0 0 "ok    gradient: shl_sh4_make body" "ok    gradient: order"

variant generated_region_order   # the marker after shli_lerp: the order check sees it there
edit shlight.h "$SH4_DEF" ""
edit shlight.h "#ifdef __cplusplus
}" "$SH4_MARK
#ifdef __cplusplus
}"
edit shlight.h "#endif /* SHLIGHT_H */" "$SH4_GEN"
expect 1 1 "FAIL  gradient: order" "C has \`shli_lerp\`"

variant generated_region_unmarked   # no marker: the kernel sits in a section >>generated
edit shlight.h "$SH4_DEF" ""
edit shlight.h "#endif /* SHLIGHT_H */" "$SH4_GEN"
expect 1 2 "FAIL  gradient: shl_sh4_make extra"

echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
