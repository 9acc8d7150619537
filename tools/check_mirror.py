#!/usr/bin/env python3
"""check_mirror.py - check that the GLSL kernels mirror the C kernels of shlight.h.

Python 3 standard library only.  Usage:

    python3 tools/check_mirror.py [--root DIR] [-q] [--require-f-suffix]

DIR (default: the parent of tools/) holds shlight.h and shlight_glsl/.

What is checked (DESIGN.md section 4):
  * modules   shlight.h is cut into sections by anchor comments `/* >>name ... */`
              (a comment whose text starts with `>>` + a lowercase word); a section
              runs to the next anchor; only the declaration part counts (up to the
              first `#ifdef SHLIGHT_IMPLEMENTATION` / `#if defined(SHLIGHT_IMPLEMENTATION)`).
              Section X is mirrored by shlight_glsl/shl_X.glsl.  A section without
              kernels needs no file; a .glsl file without a section is an error.
  * kernels   every C function definition introduced by SHLIGHT_INLINE.  The GLSL
              file must define the same functions in the same order; extra GLSL
              functions are errors unless named shlg_* (GLSL-only helpers, listed
              but not compared).  File-level #if/#else/#endif are seen through.
  * signature parameter names/order and types through the fixed C <-> GLSL table,
              equal return types.
  * body      token for token identical (comments/whitespace aside; preprocessor
              lines inside bodies included).
  * lint      the C99/GLSL common subset on every C kernel (see lint_kernel()).
  * tables    `static const float|int NAME[N] = {..};` <-> `const float NAME[N] =
              float[N](..);` (values compared as float32 / int; GLSL may be a prefix).
Choices beyond the bare rules (see the self-test tools/tests_mirror/run.sh):
  * by-value types named shl_* or shli_* (structs, and scalar typedefs such as
    `typedef double shli_real;` which the GLSL prelude #defines) map to the same
    name in GLSL; the pointer/array forms also take int and those types.
  * a table whose C element type is a scalar typedef of float/double compares
    as a float table; float tables must not hold integer literals (ES 3.00).
  * prefix tables: GLSL may have fewer values than C; a literal GLSL size must
    equal its value count.  GLSL-only tables are named shlg_* / SHLG_*.
  * lint also rejects octal literals, string/char literals, `struct` in bodies,
    gl_-prefixed names, GLSL type constructors (`float(x)`), calls to kernels
    defined later; --require-f-suffix additionally rejects unsuffixed float
    literals in C (they are doubles there).
  * the stop line may carry more conditions (`#if defined(SHLIGHT_IMPLEMENTATION) && ...`).
  * #if conditions around whole kernels are not compared; only which kernels
    exist (alternatives under #if/#else are paired in order, labelled name@line).
  * checks counted: signature, body, lint, order, table; plus failures for a
    missing/extra function, a missing module file, an orphan .glsl file and
    header structure problems.  `--` lines (not counted) list GLSL-only helpers.
Output: one line per check (`ok    ...` / `FAIL  ...` + indented details), then
`N passed, N failed`.  Exit status 1 if anything failed.
"""

import argparse
import os
import re
import struct
import sys
from collections import namedtuple

# --------------------------------------------------------------------------
# Tokeniser
# --------------------------------------------------------------------------

Tok = namedtuple("Tok", "kind text line pp")
# kind: id num op str ppbeg ppend ; pp: token belongs to a preprocessor line

OPS = sorted("""
>>= <<= ... -> ++ -- << >> <= >= == != && || ^^ *= /= %= += -= &= ^= |= ## ::
{ } [ ] ( ) ; , . ? : + - * / % < > = ! ~ & | ^ #
""".split(), key=len, reverse=True)
ID_RE = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
NUM_RE = re.compile(r"\.?[0-9](?:[eEpP][+-]|[0-9A-Za-z_.])*")
STR_RE = re.compile(r'"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'')


class Source:
    """A tokenised file: tokens plus comments (for anchors)."""

    def __init__(self, path, rel, text):
        self.path = path
        self.rel = rel
        self.toks, self.comments = tokenize(text)


CPU_ONLY = set()
KERNEL_IDS = set()


def tokenize(text):
    toks = []
    comments = []  # (token index, line, body, in_pp)
    i, n, line = 0, len(text), 1
    bol, in_pp = True, False
    while i < n:
        c = text[i]
        if c == "\\" and (text.startswith("\n", i + 1) or text.startswith("\r\n", i + 1)):
            i += 2 if text[i + 1] == "\n" else 3
            line += 1
            continue
        if c == "\n":
            if in_pp:
                toks.append(Tok("ppend", "\\n", line, True))
                in_pp = False
            line += 1
            i += 1
            bol = True
            continue
        if c in " \t\r\f\v":
            i += 1
            continue
        if text.startswith("/*", i):
            j = text.find("*/", i + 2)
            if j < 0:
                j = n
            body = text[i + 2:j]
            comments.append((len(toks), line, body, in_pp))
            line += body.count("\n")
            i = j + 2
            continue
        if text.startswith("//", i):
            j = text.find("\n", i)
            if j < 0:
                j = n
            comments.append((len(toks), line, text[i + 2:j], in_pp))
            i = j
            continue
        if c == "#" and bol and not in_pp:
            toks.append(Tok("ppbeg", "#", line, True))
            in_pp = True
            bol = False
            i += 1
            continue
        bol = False
        m = ID_RE.match(text, i)
        if m:
            toks.append(Tok("id", m.group(), line, in_pp))
            i = m.end()
            continue
        m = NUM_RE.match(text, i)
        if m:
            toks.append(Tok("num", m.group(), line, in_pp))
            i = m.end()
            continue
        m = STR_RE.match(text, i)
        if m:
            toks.append(Tok("str", m.group(), line, in_pp))
            i = m.end()
            continue
        for op in OPS:
            if text.startswith(op, i):
                toks.append(Tok("op", op, line, in_pp))
                i += len(op)
                break
        else:
            toks.append(Tok("op", c, line, in_pp))  # stray character
            i += 1
    if in_pp:
        toks.append(Tok("ppend", "\\n", line, True))
    return toks, comments


def is_op(t, text):
    return t is not None and t.kind == "op" and t.text == text


# --------------------------------------------------------------------------
# Top-level extraction (functions and ';'-terminated declarations)
# --------------------------------------------------------------------------

Func = namedtuple("Func", "name name_tok prefix params body start src")
# prefix: tokens before the name; params: list of token lists; body: tokens '{'..'}'


def match_close(toks, i, hi, open_, close):
    """Index of the token closing toks[i] (ignoring preprocessor tokens), or None."""
    depth = 0
    for j in range(i, hi):
        t = toks[j]
        if t.pp or t.kind != "op":
            continue
        if t.text == open_:
            depth += 1
        elif t.text == close:
            depth -= 1
            if depth == 0:
                return j
    return None


def split_commas(toks):
    """Split a token list at top-level commas."""
    parts, cur, depth = [], [], 0
    for t in toks:
        if t.kind == "op" and t.text in "([{":
            depth += 1
        elif t.kind == "op" and t.text in ")]}":
            depth -= 1
        if depth == 0 and is_op(t, ","):
            parts.append(cur)
            cur = []
        else:
            cur.append(t)
    parts.append(cur)
    return parts


def extract(src, lo, hi, problems):
    """Functions and declarations at file level in src.toks[lo:hi].

    Preprocessor lines at file level are skipped (#if blocks are seen through)."""
    toks = src.toks
    funcs, decls = [], []
    cur, cur_start = [], lo
    i = lo
    while i < hi:
        t = toks[i]
        if t.kind == "ppbeg":
            while i < hi and toks[i].kind != "ppend":
                i += 1
            i += 1
            continue
        if not cur:
            cur_start = i
        if is_op(t, ";"):
            if cur:
                decls.append((cur, cur_start))
            cur = []
            i += 1
            continue
        if is_op(t, "{"):
            if cur and is_op(cur[-1], ")"):
                j = match_close(toks, i, hi, "{", "}")
                if j is None:
                    problems.append("%s:%d: unterminated function body" % (src.rel, t.line))
                    j = hi - 1
                f = make_func(src, cur, toks[i:j + 1], cur_start, problems)
                if f:
                    funcs.append(f)
                cur = []
                i = j + 1
                continue
            if cur and cur[-1].kind == "str":  # extern "C" {
                cur = []
                i += 1
                continue
            j = match_close(toks, i, hi, "{", "}")
            if j is None:
                j = hi - 1
            cur.extend(x for x in toks[i:j + 1] if not x.pp)
            i = j + 1
            continue
        if is_op(t, "}"):  # closes extern "C" {
            cur = []
            i += 1
            continue
        cur.append(t)
        i += 1
    return funcs, decls


def make_func(src, decl, body, start, problems):
    close = len(decl) - 1
    depth = 0
    open_ = None
    for k in range(close, -1, -1):
        if is_op(decl[k], ")"):
            depth += 1
        elif is_op(decl[k], "("):
            depth -= 1
            if depth == 0:
                open_ = k
                break
    if open_ is None or open_ == 0 or decl[open_ - 1].kind != "id":
        problems.append("%s:%d: cannot parse function header" % (src.rel, decl[0].line))
        return None
    name_tok = decl[open_ - 1]
    ptoks = decl[open_ + 1:close]
    params = split_commas(ptoks) if ptoks else []
    if len(params) == 1 and [t.text for t in params[0]] == ["void"]:
        params = []
    return Func(name_tok.text, name_tok, decl[:open_ - 1], params, body, start, src)


# --------------------------------------------------------------------------
# Header sections
# --------------------------------------------------------------------------

ANCHOR_RE = re.compile(r"[\s*!/]*>>([a-z][a-z0-9_]*)\b")


def find_stop(toks, start=0):
    """Index of the first `#ifdef SHLIGHT_IMPLEMENTATION` / `#if defined(...)` line."""
    for k in range(start, len(toks)):
        t = toks[k]
        if t.kind != "ppbeg":
            continue
        d = []
        for u in toks[k + 1:k + 8]:
            if u.kind == "ppend":
                break
            d.append(u.text)
        if d[:2] == ["ifdef", "SHLIGHT_IMPLEMENTATION"]:
            return k
        if d[:1] == ["if"] and (d[1:5] == ["defined", "(", "SHLIGHT_IMPLEMENTATION", ")"]
                                or d[1:3] == ["defined", "SHLIGHT_IMPLEMENTATION"]):
            return k
    return len(toks)


# --------------------------------------------------------------------------
# Signatures
# --------------------------------------------------------------------------

Param = namedtuple("Param", "qual type name array")  # array: bool ([N])


def fmt_param(p):
    return "%s %s%s %s" % (p.qual, p.type, "[N]" if p.array else "", p.name)


def joined(toks):
    return " ".join(t.text for t in toks)


ARR = r"\[(?: [^\[\]]+)? \]"


def out_qual(name):
    if name.startswith("out_"):
        return "out"
    if name.startswith("io_"):
        return "inout"
    return None


def map_c_param(toks):
    """C parameter -> Param, or an error string."""
    s = " ".join(t.text for t in toks if t.text != "SHLIGHT_RESTRICT")
    m = re.match(r"^(int|float|shli?_\w+) (\w+)$", s)
    if m:
        return Param("in", m.group(1), m.group(2), False)
    m = re.match(r"^const float (\w+) \[ 3 \]$", s)
    if m:
        return Param("in", "vec3", m.group(1), False)
    m = re.match(r"^float (\w+) \[ 3 \]$", s)
    if m:
        q = out_qual(m.group(1))
        if not q:
            return "writable 3-vector `%s` must be named out_* or io_*" % s
        return Param(q, "vec3", m.group(1), False)
    m = re.match(r"^const float \( \* (\w+) \) \[ 3 \]$", s)
    if m:
        return Param("in", "vec3", m.group(1), True)
    m = re.match(r"^float \( \* (\w+) \) \[ 3 \]$", s)
    if m:
        q = out_qual(m.group(1))
        if not q:
            return "writable array `%s` must be named out_* or io_*" % s
        return Param(q, "vec3", m.group(1), True)
    m = re.match(r"^const (int|float|shli?_\w+) (?:\* (\w+)|(\w+) %s)$" % ARR, s)
    if m:
        return Param("in", m.group(1), m.group(2) or m.group(3), True)
    m = re.match(r"^(int|float|shli?_\w+) (?:\* (\w+)|(\w+) %s)$" % ARR, s)
    if m:
        name = m.group(2) or m.group(3)
        q = out_qual(name)
        if not q:
            return "writable array `%s` must be named out_* or io_*" % s
        return Param(q, m.group(1), name, True)
    return "C parameter `%s` has no GLSL mapping" % s


PRECISION = {"lowp", "mediump", "highp"}


def map_glsl_param(toks):
    ts = [t.text for t in toks if t.text not in PRECISION]
    s = " ".join(ts)
    qual, const = None, False
    while ts and ts[0] in ("in", "out", "inout", "const"):
        q = ts.pop(0)
        if q == "const":
            const = True
        elif qual:
            return "GLSL parameter `%s`: two qualifiers" % s
        else:
            qual = q
    qual = qual or "in"
    if const and qual != "in":
        return "GLSL parameter `%s`: const on an output" % s
    if not ts or not ID_RE.fullmatch(ts[0]):
        return "GLSL parameter `%s` not understood" % s
    typ = ts.pop(0)
    array = False
    name = None
    while ts:
        if ts[0] == "[":
            if "]" not in ts:
                return "GLSL parameter `%s` not understood" % s
            k = ts.index("]")
            if k == 1:
                return "GLSL parameter `%s`: unsized array" % s
            if array:
                return "GLSL parameter `%s`: array of arrays" % s
            array = True
            del ts[:k + 1]
        elif name is None and ID_RE.fullmatch(ts[0]):
            name = ts.pop(0)
        else:
            return "GLSL parameter `%s` not understood" % s
    if name is None:
        return "GLSL parameter `%s` has no name" % s
    return Param(qual, typ, name, array)


def c_return(f):
    """Return type tokens after SHLIGHT_INLINE."""
    pre = [t.text for t in f.prefix]
    k = len(pre) - 1 - pre[::-1].index("SHLIGHT_INLINE")
    return pre[k + 1:]


def glsl_return(f):
    pre = [t.text for t in f.prefix if t.text not in PRECISION]
    return pre[-1:] if pre else []


def check_signature(cf, gf):
    """List of problem strings (empty = ok)."""
    out = []
    cl = "%s:%d" % (cf.src.rel, cf.name_tok.line)
    gl = "%s:%d" % (gf.src.rel, gf.name_tok.line)
    cret = c_return(cf)
    gret = glsl_return(gf)
    if len(cret) != 1 or not (cret[0] in ("float", "int", "void") or re.fullmatch(r"shli?_\w+", cret[0])):
        out.append("%s: C return type `%s` not allowed (float, int, void or a shl_/shli_ type)"
                   % (cl, " ".join(cret)))
    elif cret != gret:
        out.append("return type: C `%s` (%s) vs GLSL `%s` (%s)"
                   % (" ".join(cret), cl, " ".join(gret), gl))
    if len(cf.params) != len(gf.params):
        out.append("parameter count: C %d (%s) vs GLSL %d (%s)"
                   % (len(cf.params), cl, len(gf.params), gl))
    for k in range(max(len(cf.params), len(gf.params))):
        ct = cf.params[k] if k < len(cf.params) else None
        gt = gf.params[k] if k < len(gf.params) else None
        cp = map_c_param(ct) if ct else None
        gp = map_glsl_param(gt) if gt else None
        cline = "%s:%d" % (cf.src.rel, ct[0].line) if ct else cl
        gline = "%s:%d" % (gf.src.rel, gt[0].line) if gt else gl
        if isinstance(cp, str):
            out.append("param %d: %s: %s" % (k + 1, cline, cp))
        if isinstance(gp, str):
            out.append("param %d: %s: %s" % (k + 1, gline, gp))
        if isinstance(cp, str) or isinstance(gp, str):
            continue
        if cp is None or gp is None:
            continue
        if cp.name != gp.name:
            out.append("param %d name: C `%s` (%s) vs GLSL `%s` (%s)"
                       % (k + 1, cp.name, cline, gp.name, gline))
        elif cp != gp:
            out.append("param %d `%s`: C `%s` means `%s` (%s) but GLSL has `%s` (%s)"
                       % (k + 1, cp.name, joined(ct), fmt_param(cp), cline, fmt_param(gp), gline))
    return out


# --------------------------------------------------------------------------
# Bodies
# --------------------------------------------------------------------------

def show_tok(t):
    return "<end>" if t is None else ("<newline>" if t.kind == "ppend" else t.text)


def context(toks, k, width=5):
    a = max(0, k - width)
    parts = [show_tok(t) for t in toks[a:k]]
    parts.append("[" + show_tok(toks[k] if k < len(toks) else None) + "]")
    parts += [show_tok(t) for t in toks[k + 1:k + 1 + width]]
    return ("... " if a > 0 else "") + " ".join(parts) + (" ..." if k + 1 + width < len(toks) else "")


def check_body(cf, gf):
    a, b = cf.body, gf.body
    for k in range(max(len(a), len(b))):
        ta = a[k] if k < len(a) else None
        tb = b[k] if k < len(b) else None
        if ta is None or tb is None or (ta.kind, ta.text) != (tb.kind, tb.text):
            la = "%s:%d" % (cf.src.rel, (ta or a[-1]).line)
            lb = "%s:%d" % (gf.src.rel, (tb or b[-1]).line)
            return ["first difference at body token %d: C `%s` vs GLSL `%s`" % (k + 1, show_tok(ta), show_tok(tb)),
                    "C    %s: %s" % (la, context(a, k)),
                    "GLSL %s: %s" % (lb, context(b, k))]
    return []


# --------------------------------------------------------------------------
# Lint
# --------------------------------------------------------------------------

C_KEYWORDS = set("""auto break case char const continue default do double else enum extern
float for goto if inline int long register restrict return short signed sizeof static struct
switch typedef union unsigned void volatile while _Bool _Complex _Imaginary""".split())

FORBIDDEN_C = set("""unsigned double long short char goto sizeof static signed register auto
extern volatile restrict inline typedef enum union struct _Bool _Complex _Imaginary""".split())

# GLSL 4.50 (section 3.6) and GLSL ES 3.00 (section 3.7) keywords and reserved words.
GLSL_WORDS = set("""
attribute const uniform varying buffer shared coherent volatile restrict readonly writeonly
atomic_uint layout centroid flat smooth noperspective patch sample break continue do for while
switch case default if else subroutine in out inout float double int void bool true false
invariant precise discard return
mat2 mat3 mat4 dmat2 dmat3 dmat4 mat2x2 mat2x3 mat2x4 dmat2x2 dmat2x3 dmat2x4 mat3x2 mat3x3
mat3x4 dmat3x2 dmat3x3 dmat3x4 mat4x2 mat4x3 mat4x4 dmat4x2 dmat4x3 dmat4x4
vec2 vec3 vec4 ivec2 ivec3 ivec4 bvec2 bvec3 bvec4 dvec2 dvec3 dvec4 uint uvec2 uvec3 uvec4
lowp mediump highp precision
sampler1D sampler2D sampler3D samplerCube sampler1DShadow sampler2DShadow samplerCubeShadow
sampler1DArray sampler2DArray sampler1DArrayShadow sampler2DArrayShadow isampler1D isampler2D
isampler3D isamplerCube isampler1DArray isampler2DArray usampler1D usampler2D usampler3D
usamplerCube usampler1DArray usampler2DArray sampler2DRect sampler2DRectShadow isampler2DRect
usampler2DRect samplerBuffer isamplerBuffer usamplerBuffer sampler2DMS isampler2DMS usampler2DMS
sampler2DMSArray isampler2DMSArray usampler2DMSArray samplerCubeArray samplerCubeArrayShadow
isamplerCubeArray usamplerCubeArray
image1D iimage1D uimage1D image2D iimage2D uimage2D image3D iimage3D uimage3D image2DRect
iimage2DRect uimage2DRect imageCube iimageCube uimageCube imageBuffer iimageBuffer uimageBuffer
image1DArray iimage1DArray uimage1DArray image2DArray iimage2DArray uimage2DArray imageCubeArray
iimageCubeArray uimageCubeArray image2DMS iimage2DMS uimage2DMS image2DMSArray iimage2DMSArray
uimage2DMSArray struct
common partition active asm class union enum typedef template this resource goto inline
noinline public static extern external interface long short half fixed unsigned superp input
output hvec2 hvec3 hvec4 fvec2 fvec3 fvec4 sampler3DRect filter sizeof cast namespace using
packed
""".split())
# keywords that mean the same in C and GLSL and may appear in kernel bodies
COMMON_WORDS = set("const break continue do for while switch case default if else return "
                   "void float int bool true false".split())
GLSL_RESERVED = GLSL_WORDS - COMMON_WORDS - FORBIDDEN_C
GLSL_TYPES = set(w for w in GLSL_WORDS if re.search(r"vec|mat|sampler|image|^uint$", w))

SHIM_RE = re.compile(r"SHLIGHT_[A-Z0-9_]+")
FLOAT_RE = re.compile(r"[0-9]+\.[0-9]+(?:[eE][+-]?[0-9]+)?[fF]?")
INT_RE = re.compile(r"0|[1-9][0-9]*")
NOT_CALLS = {"if", "while", "for", "switch", "return", "sizeof", "else", "do", "case"}


def lint_literal(s, require_f=False):
    """Problem string for a numeric literal, or None."""
    if s[:2] in ("0x", "0X"):
        return "hex literal `%s`" % s
    is_float = "." in s or re.search(r"[eE]", s) or s[-1] in "fF"
    if is_float:
        if not FLOAT_RE.fullmatch(s):
            return "float literal `%s`: write digits on both sides of the dot (e.g. 2.0f, 1.0e5f)" % s
        if require_f and s[-1] not in "fF":
            return "float literal `%s` without f suffix is a double in C" % s
        return None
    if INT_RE.fullmatch(s):
        return None
    if re.fullmatch(r"[0-9]+[uUlL]+", s):
        return "integer literal `%s` with a suffix" % s
    if re.fullmatch(r"0[0-9]+", s):
        return "octal literal `%s`" % s
    return "malformed number `%s`" % s


def operand_end(toks, k):
    """Does toks[k] end an operand (so a following * or & is binary)?"""
    if k < 0:
        return False
    t = toks[k]
    if t.kind in ("num", "str"):
        return True
    if t.kind == "id":
        return t.text not in C_KEYWORDS or t.text in ("true", "false")
    if t.kind == "op":
        if t.text in (")", "]"):
            return True
        if t.text in ("++", "--"):
            return operand_end(toks, k - 1)
    return False


def lint_ident(name, line, rel, out):
    if name in FORBIDDEN_C:
        out.append("%s:%d: forbidden keyword `%s`" % (rel, line, name))
    elif name in GLSL_RESERVED and not SHIM_RE.fullmatch(name):
        out.append("%s:%d: GLSL reserved word `%s` used as identifier" % (rel, line, name))
    if "__" in name:
        out.append("%s:%d: identifier `%s` contains `__`" % (rel, line, name))
    elif name.startswith("gl_"):
        out.append("%s:%d: identifier `%s` uses the reserved gl_ prefix" % (rel, line, name))


def lint_kernel(f, type_names, kernel_index, earlier, require_f=False):
    """Problems in C kernel f.  earlier: {name: Func} of kernels defined before f;
    kernel_index: {name: Func} of all kernels (for 'defined later' messages)."""
    rel = f.src.rel
    out = []
    names = [f.name_tok]
    for p in f.params:
        ids = [t for t in p if t.kind == "id" and t.text not in C_KEYWORDS
               and t.text not in type_names and not SHIM_RE.fullmatch(t.text)]
        names += ids[-1:]
    for t in names:
        lint_ident(t.text, t.line, rel, out)
    toks = [t for t in f.body if not t.pp]
    type_words = (C_KEYWORDS - {"return", "case", "else", "do", "if", "while", "for", "switch",
                                "break", "continue", "default", "goto", "sizeof"}) | type_names
    for k, t in enumerate(toks):
        prev = toks[k - 1] if k > 0 else None
        nxt = toks[k + 1] if k + 1 < len(toks) else None
        where = "%s:%d" % (rel, t.line)
        if t.kind == "str":
            out.append("%s: string/char literal %s" % (where, t.text))
        elif t.kind == "num":
            p = lint_literal(t.text, require_f)
            if p:
                out.append("%s: %s" % (where, p))
        elif t.kind == "id":
            lint_ident(t.text, t.line, rel, out)
            if is_op(nxt, "(") and t.text not in NOT_CALLS:
                name = t.text
                if SHIM_RE.fullmatch(name):
                    pass
                elif name in ("float", "int", "bool") or name in GLSL_TYPES:
                    out.append("%s: constructor `%s(` is not C (convert with SHLIGHT_ITOF / SHLIGHT_FTOI)"
                               % (where, name))
                elif name in FORBIDDEN_C or name in GLSL_RESERVED:
                    pass  # already reported
                elif re.match(r"shli?_", name):
                    if name == f.name:
                        out.append("%s: recursion: `%s` calls itself" % (where, name))
                    elif name in earlier or name in CPU_ONLY:
                        pass
                    elif name in kernel_index:
                        g = kernel_index[name]
                        out.append("%s: calls `%s`, which is defined later (%s:%d)"
                                   % (where, name, g.src.rel, g.name_tok.line))
                    else:
                        out.append("%s: calls `%s`, which is not a kernel (SHLIGHT_INLINE) defined earlier"
                                   % (where, name))
                else:
                    out.append("%s: call to `%s` not allowed (math goes through SHLIGHT_ shims; "
                               "other calls must be shl_/shli_ kernels)" % (where, name))
        elif t.kind == "op":
            if t.text == "->":
                out.append("%s: forbidden `->`" % where)
            elif t.text == "&" and not operand_end(toks, k - 1):
                out.append("%s: unary `&` (address-of)" % where)
            elif t.text == "*" and not operand_end(toks, k - 1):
                if prev is not None and prev.kind == "id" and prev.text in type_words:
                    out.append("%s: pointer declaration `%s *`" % (where, prev.text))
                else:
                    out.append("%s: unary `*` (dereference)" % where)
            elif t.text == "*" and prev is not None and prev.kind == "id" and prev.text in type_names:
                out.append("%s: pointer declaration `%s *`" % (where, prev.text))
            elif t.text == "=" and is_op(nxt, "{"):
                out.append("%s: brace initialiser `= {` (GLSL 3.30 / ES 3.00 have none)" % where)
            elif t.text == "(":
                j = k + 1
                words = 0
                while j < len(toks) and ((toks[j].kind == "id" and toks[j].text in type_words)
                                         or is_op(toks[j], "*")):
                    words += toks[j].kind == "id"
                    j += 1
                if words and j < len(toks) and is_op(toks[j], ")"):
                    out.append("%s: C cast `%s` (use SHLIGHT_ITOF / SHLIGHT_FTOI)"
                               % (where, joined(toks[k:j + 1])))
            elif t.text in ("#", "##"):
                out.append("%s: stray `%s`" % (where, t.text))
    return out


# --------------------------------------------------------------------------
# Tables
# --------------------------------------------------------------------------

Table = namedtuple("Table", "name type size values line src")
# size: C: size tokens; GLSL: (declared size tokens, constructor size tokens)
# values: list of token lists

# scalar typedefs of the header (e.g. `typedef double shli_real;` -> float class);
# filled by run().  A table of such a type is compared like a float table.
SCALAR_ALIASES = {}


def table_class(typ):
    if typ in ("float", "int"):
        return typ
    return SCALAR_ALIASES.get(typ)


def parse_c_table(d, src):
    ts = [t.text for t in d]
    k = 0
    quals = set()
    while k < len(ts) and ts[k] in ("static", "const"):
        quals.add(ts[k])
        k += 1
    if quals != {"static", "const"} or len(ts) < k + 6:
        return None
    if table_class(ts[k]) is None or d[k + 1].kind != "id" or ts[k + 2] != "[":
        return None
    typ, name = ts[k], ts[k + 1]
    if "]" not in ts[k + 2:]:
        return None
    e = ts.index("]", k + 2)
    size = d[k + 3:e]
    if ts[e + 1:e + 3] != ["=", "{"] or ts[-1] != "}":
        return None
    vals = split_commas(d[e + 3:-1])
    if vals and not vals[-1]:
        vals.pop()  # trailing comma
    return Table(name, typ, size, vals, d[k + 1].line, src)


def parse_glsl_table(d, src):
    dd = [t for t in d if t.text not in PRECISION]
    ts = [t.text for t in dd]
    if len(ts) < 8 or ts[0] != "const" or table_class(ts[1]) is None:
        return None
    typ = ts[1]
    k = 2
    sizes = []
    name = None
    while k < len(ts) and ts[k] != "=":
        if ts[k] == "[":
            if "]" not in ts[k:]:
                return None
            e = ts.index("]", k)
            sizes.append(dd[k + 1:e])
            k = e + 1
        elif dd[k].kind == "id" and name is None:
            name = dd[k]
            k += 1
        else:
            return None
    if name is None or len(sizes) != 1 or k >= len(ts):
        return None
    k += 1
    if ts[k:k + 2] != [typ, "["] or "]" not in ts[k:]:
        return None
    e = ts.index("]", k)
    csize = dd[k + 2:e]
    if e + 1 >= len(ts) or ts[e + 1] != "(" or ts[-1] != ")":
        return None
    vals = split_commas(dd[e + 2:-1])
    return Table(name.text, typ, (sizes[0], csize), vals, name.line, src)


def size_literal(toks):
    if len(toks) == 1 and toks[0].kind == "num" and INT_RE.fullmatch(toks[0].text):
        return int(toks[0].text)
    return None


def value_key(vtoks, typ):
    key = []
    for t in vtoks:
        if t.kind == "num":
            s = t.text.rstrip("fF") if not t.text[:2].lower() == "0x" else t.text
            try:
                if typ == "float":
                    v = struct.unpack("<f", struct.pack("<f", float(s)))[0]
                else:
                    v = int(s, 0)
                key.append(("num", v))
                continue
            except (ValueError, OverflowError):
                pass
        key.append((t.kind, t.text))
    return tuple(key)


def check_table(ct, gt, require_f=False):
    out = []
    cl = "%s:%d" % (ct.src.rel, ct.line)
    gl = "%s:%d" % (gt.src.rel, gt.line)
    if table_class(ct.type) != table_class(gt.type):
        return ["type: C `%s` (%s) vs GLSL `%s` (%s)" % (ct.type, cl, gt.type, gl)]
    for side, tab, req_f in (("C", ct, require_f), ("GLSL", gt, False)):
        for v in tab.values:
            for t in v:
                if t.kind == "num":
                    cls = table_class(tab.type)
                    p = lint_literal(t.text, req_f and cls == "float")
                    if p is None and cls == "int" and not INT_RE.fullmatch(t.text):
                        p = "non-integer literal `%s` in an int table" % t.text
                    if p is None and cls == "float" and INT_RE.fullmatch(t.text):
                        p = "integer literal `%s` in a float table" % t.text
                    if p:
                        out.append("%s:%d: %s" % (tab.src.rel, t.line, p))
            if not v:
                out.append("%s:%d: empty value" % (tab.src.rel, tab.line))
    decl, ctor = gt.size
    nd, nc = size_literal(decl), size_literal(ctor)
    gc, cc = len(gt.values), len(ct.values)
    if nd is not None and nd != gc:
        out.append("%s: GLSL size %d but %d values" % (gl, nd, gc))
    if nc is not None and nc != gc:
        out.append("%s: GLSL constructor size %d but %d values" % (gl, nc, gc))
    if decl and ctor and nd is None and nc is None and joined(decl) != joined(ctor):
        out.append("%s: GLSL sizes differ: [%s] vs [%s]" % (gl, joined(decl), joined(ctor)))
    ncs = size_literal(ct.size)
    if ncs is not None and cc > ncs:
        out.append("%s: C size %d but %d values" % (cl, ncs, cc))
    if gc > cc:
        out.append("GLSL has %d values (%s), C only %d (%s)" % (gc, gl, cc, cl))
    for k in range(min(gc, cc)):
        if value_key(ct.values[k], table_class(ct.type)) != value_key(gt.values[k], table_class(gt.type)):
            out.append("value %d: C `%s` (%s:%d) vs GLSL `%s` (%s:%d)"
                       % (k, joined(ct.values[k]), ct.src.rel, ct.values[k][0].line,
                          joined(gt.values[k]), gt.src.rel, gt.values[k][0].line))
            break
    return out


# --------------------------------------------------------------------------
# Driver
# --------------------------------------------------------------------------

class Report:
    def __init__(self, quiet):
        self.quiet = quiet
        self.passed = 0
        self.failed = 0

    def check(self, label, problems):
        if problems:
            self.failed += 1
            print("FAIL  " + label)
            for p in problems:
                print("      " + p)
        else:
            self.passed += 1
            if not self.quiet:
                print("ok    " + label)

    def note(self, label):
        if not self.quiet:
            print("--    " + label)


def pair_up(cs, gs):
    """Pair items by (name, occurrence).  Returns pairs, c-only, g-only."""
    def keyed(items):
        seen = {}
        res = []
        for x in items:
            n = seen.get(x.name, 0)
            seen[x.name] = n + 1
            res.append(((x.name, n), x))
        return res
    ck, gk = keyed(cs), keyed(gs)
    gmap = dict(gk)
    cmap = dict(ck)
    pairs = [(c, gmap[k]) for k, c in ck if k in gmap]
    conly = [c for k, c in ck if k not in gmap]
    gonly = [g for k, g in gk if k not in cmap]
    return pairs, conly, gonly


def read(path, root):
    with open(path, "r", encoding="utf-8", errors="replace") as fh:
        return Source(path, os.path.relpath(path, root), fh.read())


def struct_names(text):
    names = set(re.findall(r"\bstruct\s+([A-Za-z_]\w*)", text))
    names |= set(re.findall(r"\}\s*([A-Za-z_]\w*)\s*;", text))
    names |= set(re.findall(r"\btypedef\s+(?:struct\s+\w+|\w+)\s+([A-Za-z_]\w*)\s*;", text))
    return {n for n in names if n not in C_KEYWORDS}


def run(root, quiet, require_f=False):
    rep = Report(quiet)
    hpath = os.path.join(root, "shlight.h")
    gdir = os.path.join(root, "shlight_glsl")
    if not os.path.isfile(hpath):
        rep.check("header: %s" % hpath, ["not found"])
        return rep
    hsrc = read(hpath, root)
    toks = hsrc.toks
    stop = find_stop(toks)
    with open(hpath, "r", encoding="utf-8", errors="replace") as fh:
        htext = fh.read()
    if stop < len(toks):  # type names come from the declaration part only
        htext = "".join(htext.splitlines(True)[:toks[stop].line - 1])
    types = struct_names(htext)
    SCALAR_ALIASES.clear()
    for ctype, alias in re.findall(r"\btypedef\s+(float|double|int)\s+([A-Za-z_]\w*)\s*;", htext):
        SCALAR_ALIASES[alias] = "int" if ctype == "int" else "float"

    # the generated part: an anchor `>>generated` after the implementation opens a second
    # declaration part (to the next SHLIGHT_IMPLEMENTATION line) that holds the @generated
    # regions; a region there counts at the line `@generated NAME: defined in >>generated`
    # of its section (its place for the order of kernels and the section it belongs to)
    gen_lo = gen_hi = len(toks)
    for idx, line, body, in_pp in hsrc.comments:
        m = ANCHOR_RE.match(body)
        if not in_pp and idx >= stop and m and m.group(1) == "generated":
            gen_lo = idx
            gen_hi = find_stop(toks, idx)
            break
    markers = {}  # region name -> token index of its marker in its section
    regions = []  # (begin token index, end token index, name) of regions in the generated part
    opened = {}
    for idx, line, body, in_pp in hsrc.comments:
        m = re.match(r"\s*@generated (\w+): defined in >>generated", body)
        if m and idx < stop:
            markers[m.group(1)] = idx
        m = re.match(r"\s*@generated (begin|end) (\w+)", body)
        if m and gen_lo <= idx <= gen_hi:  # (a comment's index is that of the next token)
            if m.group(1) == "begin":
                opened[m.group(2)] = idx
            elif m.group(2) in opened:
                regions.append((opened.pop(m.group(2)), idx, m.group(2)))

    def vpos(start):
        """(place in the section order, tie-break) of an item starting at token start"""
        for lo, hi, name in regions:
            if lo <= start < hi and name in markers:
                return (markers[name], start)
        return (start, 0)

    def in_decl(idx):
        return idx < stop or gen_lo <= idx < gen_hi

    # sections
    anchors = []  # (name, token index, line)
    for idx, line, body, in_pp in hsrc.comments:
        if in_pp or not in_decl(idx):
            continue
        m = ANCHOR_RE.match(body)
        if m:
            anchors.append((m.group(1), idx, line))
    structural = []
    seen = {}
    for name, idx, line in anchors:
        if name in seen:
            structural.append("%s:%d: anchor >>%s repeats the one at line %d" % (hsrc.rel, line, name, seen[name]))
        else:
            seen[name] = line

    problems = []
    cfuncs, cdecls = extract(hsrc, 0, stop, problems)
    if gen_lo < gen_hi:
        gfuncs_, gdecls_ = extract(hsrc, gen_lo, gen_hi, problems)
        cfuncs = sorted(cfuncs + gfuncs_, key=lambda f: vpos(f.start))
        cdecls = sorted(cdecls + gdecls_, key=lambda d: vpos(d[1]))

    def section_of(start):
        sec = None
        start = vpos(start)[0]
        for name, idx, line in anchors:
            if idx <= start:
                sec = name
            else:
                break
        return sec

    modules = []  # ordered unique names
    for name, _, _ in anchors:
        if name not in modules:
            modules.append(name)
    kernels = {m: [] for m in modules}
    tables = {m: [] for m in modules}
    all_kernels = []
    for d, _ in cdecls:
        # a function declared SHLIGHT_API in the declaration part is C only (defined with
        # SHLIGHT_IMPLEMENTATION): kernels may call it under a C-only #if branch
        if d and d[0].text == "SHLIGHT_API":
            for k in range(len(d) - 1):
                if d[k].kind == "id" and re.match(r"shli?_", d[k].text) and is_op(d[k + 1], "("):
                    CPU_ONLY.add(d[k].text)
                    break
    for f in cfuncs:
        if "SHLIGHT_CPU_INLINE" in [t.text for t in f.prefix]:
            CPU_ONLY.add(f.name)  # C-only helper (run-time loops): no GLSL twin
            rep.note("%s:%d: `%s` is SHLIGHT_CPU_INLINE: C only, not mirrored"
                     % (hsrc.rel, f.name_tok.line, f.name))
            continue
        if "SHLIGHT_INLINE" not in [t.text for t in f.prefix]:
            rep.note("%s:%d: `%s` is defined without SHLIGHT_INLINE: not a kernel"
                     % (hsrc.rel, f.name_tok.line, f.name))
            continue
        sec = section_of(f.start)
        all_kernels.append(f)
        KERNEL_IDS.update(t.text for t in f.body if t.kind == "id")
        if sec is None:
            structural.append("%s:%d: kernel `%s` lies before the first >>module anchor"
                              % (hsrc.rel, f.name_tok.line, f.name))
        else:
            kernels[sec].append(f)
    for d, start in cdecls:
        t = parse_c_table(d, hsrc)
        if t:
            sec = section_of(start)
            if sec is None:
                structural.append("%s:%d: table `%s` lies before the first >>module anchor"
                                  % (hsrc.rel, t.line, t.name))
            else:
                tables[sec].append(t)
    if structural or problems:
        rep.check("header: structure", structural + problems)

    kernel_index = {}
    for f in all_kernels:
        kernel_index.setdefault(f.name, f)
    earlier_of = {}
    defined = {}
    for f in all_kernels:
        earlier_of[id(f)] = dict(defined)
        defined.setdefault(f.name, f)

    glsl_files = []
    if os.path.isdir(gdir):
        # shlight.glsl: the one-include bundle of the modules (tools/gen_glsl_one.py --check)
        glsl_files = sorted(x for x in os.listdir(gdir) if x.endswith(".glsl") and
                            x != "shlight.glsl")

    for mod in modules:
        ks = kernels[mod]
        gpath = os.path.join(gdir, "shl_%s.glsl" % mod)
        nnames = {}
        for f in ks:
            nnames[f.name] = nnames.get(f.name, 0) + 1

        def label(f):
            # alternatives under #if/#else share a name: tell them apart by line
            if nnames.get(f.name, 0) > 1:
                return "%s: %s@%d" % (mod, f.name, f.name_tok.line)
            return "%s: %s" % (mod, f.name)

        def lint(f):
            rep.check(label(f) + " lint",
                      lint_kernel(f, types, kernel_index, earlier_of[id(f)], require_f))
        if not os.path.isfile(gpath):
            if ks:
                rep.check("%s: module file" % mod,
                          ["%s missing (section has %d kernels)" % (os.path.relpath(gpath, root), len(ks))])
                for f in ks:
                    lint(f)
            continue
        gsrc = read(gpath, root)
        gproblems = []
        gfuncs, gdecls = extract(gsrc, 0, len(gsrc.toks), gproblems)
        if gproblems:
            rep.check("%s: %s parse" % (mod, gsrc.rel), gproblems)
        helpers = [g for g in gfuncs if g.name.startswith("shlg_")]
        gks = [g for g in gfuncs if not g.name.startswith("shlg_")]
        pairs, conly, gonly = pair_up(ks, gks)
        partner = {id(c): g for c, g in pairs}
        for f in ks:
            g = partner.get(id(f))
            if g is None:
                rep.check(label(f) + " present",
                          ["%s:%d: kernel has no GLSL function in %s"
                           % (hsrc.rel, f.name_tok.line, gsrc.rel)])
            else:
                rep.check(label(f) + " signature", check_signature(f, g))
                rep.check(label(f) + " body", check_body(f, g))
            lint(f)
        for g in gonly:
            rep.check("%s: %s extra" % (mod, g.name),
                      ["%s:%d: GLSL function has no C kernel in section >>%s (GLSL-only helpers are named shlg_*)"
                       % (gsrc.rel, g.name_tok.line, mod)])
        for g in helpers:
            rep.note("%s: %s GLSL-only helper (%s:%d), not compared" % (mod, g.name, gsrc.rel, g.name_tok.line))
        # order of the common kernels
        corder = [c for c in ks if id(c) in partner]
        gpos = {id(g): k for k, g in enumerate(gks)}
        gorder = sorted((partner[id(c)] for c in corder), key=lambda g: gpos[id(g)])
        oprob = []
        for c, g in zip(corder, gorder):
            if c.name != g.name:
                oprob.append("C has `%s` (%s:%d) where GLSL has `%s` (%s:%d)"
                             % (c.name, hsrc.rel, c.name_tok.line, g.name, gsrc.rel, g.name_tok.line))
                oprob.append("C order:    " + " ".join(x.name for x in corder))
                oprob.append("GLSL order: " + " ".join(x.name for x in gorder))
                break
        rep.check("%s: order" % mod, oprob)
        # tables
        gtabs = [t for t in (parse_glsl_table(d, gsrc) for d, _ in gdecls) if t]
        tpairs, tconly, tgonly = pair_up(tables[mod], gtabs)
        tpartner = {id(c): g for c, g in tpairs}
        for ct in tables[mod]:
            gt = tpartner.get(id(ct))
            if gt is None and ct.name not in KERNEL_IDS:
                rep.note("%s:%d: table %s is used by C-only helpers alone: not mirrored"
                         % (hsrc.rel, ct.line, ct.name))
            elif gt is None:
                rep.check("%s: table %s" % (mod, ct.name),
                          ["%s:%d: table has no GLSL counterpart in %s" % (hsrc.rel, ct.line, gsrc.rel)])
            else:
                rep.check("%s: table %s" % (mod, ct.name), check_table(ct, gt, require_f))
        for gt in tgonly:
            if gt.name.lower().startswith("shlg_"):
                continue
            rep.check("%s: table %s" % (mod, gt.name),
                      ["%s:%d: GLSL table has no C counterpart (GLSL-only tables are named shlg_*/SHLG_*)"
                       % (gsrc.rel, gt.line)])

    for fn in glsl_files:
        m = re.fullmatch(r"shl_([a-z][a-z0-9_]*)\.glsl", fn)
        if not m or m.group(1) not in modules:
            rep.check("%s: module" % fn,
                      ["shlight_glsl/%s has no section `/* >>%s */` in shlight.h"
                       % (fn, m.group(1) if m else fn[:-5])])
    return rep


def main(argv=None):
    ap = argparse.ArgumentParser(description="Check that shlight_glsl/*.glsl mirror the kernels of shlight.h.")
    ap.add_argument("--root", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                    help="directory holding shlight.h and shlight_glsl/ (default: repo root)")
    ap.add_argument("-q", action="store_true", help="print only failures and the summary")
    ap.add_argument("--require-f-suffix", action="store_true",
                    help="also require the f suffix on float literals in C kernels and tables "
                         "(an unsuffixed literal is a double in C)")
    a = ap.parse_args(argv)
    rep = run(os.path.abspath(a.root), a.q, require_f=a.require_f_suffix)
    print("%d passed, %d failed" % (rep.passed, rep.failed))
    return 1 if rep.failed else 0


if __name__ == "__main__":
    sys.exit(main())
