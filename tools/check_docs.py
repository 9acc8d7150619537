#!/usr/bin/env python3
"""check_docs.py - every code block of README.md and docs/*.md builds and runs.

usage: python3 tools/check_docs.py [-k] [-v] [FILE.md ...]     (default: README.md docs/*.md)

Fenced blocks, by their info string:
  ```c            a complete C program: built with
                  gcc -std=c99 -pedantic -Wall -Wextra -Werror -fsanitize=address,undefined
                  -I<repository root> ... -lm, then run (exit status 0, no sanitizer report).
  ```c fragment   statements: each becomes the body of a function of one program per file
                  (shlight.h with SHLIGHT_IMPLEMENTATION, <stdio.h>, <stdlib.h>, <string.h>,
                  <math.h> included first), built with the same flags (unused variables
                  allowed) and run in order.
  ```glsl         a complete shader, `#version` first: glslangValidator -l -I<root>; the stage
                  is the second word of the info string (frag, vert, comp; default frag).
  ```glsl fragment  declarations at file scope: `#version 450`, SHLIGHT_MAX_BANDS 4 and every
                  module of shlight_glsl/MODULES are put before it, an empty compute main after.
  anything else (sh, text, no info string) is not checked.
Errors point at the markdown line (#line directives). Also checked, one result each: every
public function of shlight.h is named in README.md's API index; README.md has at most 300
lines; no internal references ("seed 00N", "issue N", "MATH.md") in the checked files.
Ends with "N passed, N failed"; exit status 1 if anything failed. -k keeps build/docs/.
"""
import glob
import os
import re
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, 'build', 'docs')
CC = os.environ.get('CC', 'gcc')
CFLAGS = ['-std=c99', '-pedantic', '-Wall', '-Wextra', '-Werror', '-fsanitize=address,undefined',
          '-fno-sanitize-recover=all', '-g1', '-O1', '-I' + ROOT]
LIBS = ['-lm', '-pthread']
GLSLANG = os.environ.get('GLSLANG_VALIDATOR', 'glslangValidator')
verbose = False


def blocks(path):
    """(info words, first line number of the body, body text) of each fenced block."""
    out, cur = [], None
    for i, line in enumerate(open(path, encoding='utf-8').read().split('\n'), 1):
        m = re.match(r'^(\s*)(```+|~~~+)\s*(.*)$', line)
        if cur is None and m:
            cur = (m.group(2), m.group(3).split(), i + 1, [])
        elif cur is not None and m and m.group(2).startswith(cur[0][:3]) and not m.group(3):
            out.append((cur[1], cur[2], '\n'.join(cur[3]) + '\n'))
            cur = None
        elif cur is not None:
            cur[3].append(line)
    return out


def run(cmd, **kw):
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, cwd=ROOT, **kw)
    return p.returncode, p.stdout.decode('utf-8', 'replace')


def rel(path):
    return os.path.relpath(path, ROOT)


def check_c(path, line, body, k):
    src = os.path.join(OUT, '%s_%d.c' % (re.sub(r'\W', '_', rel(path)), k))
    exe = src[:-2]
    with open(src, 'w') as f:
        f.write('#line %d "%s"\n%s' % (line, rel(path), body))
    rc, log = run([CC] + CFLAGS + ['-o', exe, src] + LIBS)
    if rc == 0:
        rc, log2 = run([exe], timeout=300)
        log += log2
    return rc, log


def check_c_fragments(path, frags):
    src = os.path.join(OUT, '%s_fragments.c' % re.sub(r'\W', '_', rel(path)))
    exe = src[:-2]
    parts = ['#define SHLIGHT_IMPLEMENTATION\n#include "shlight.h"\n#include "tests/ref/published.h"\n#include <math.h>\n'
             '#include <stdio.h>\n#include <stdlib.h>\n#include <string.h>\n']
    for k, (line, body) in enumerate(frags):
        parts.append('static void fragment_%d(void) {\n#line %d "%s"\n%s}\n'
                     % (k, line, rel(path), body))
    parts.append('int main(void) {\n')
    parts += ['  fragment_%d();\n' % k for k in range(len(frags))]
    parts.append('  return 0;\n}\n')
    with open(src, 'w') as f:
        f.write(''.join(parts))
    rc, log = run([CC] + CFLAGS + ['-Wno-unused-variable', '-Wno-unused-but-set-variable',
                                   '-o', exe, src] + LIBS)
    if rc == 0:
        rc, log2 = run([exe], timeout=300)
        log += log2
    return rc, log


def modules():
    names = ['shl_prelude.glsl']
    for l in open(os.path.join(ROOT, 'shlight_glsl', 'MODULES')):
        l = l.split('#')[0].strip()
        if l:
            names.append(l if l.endswith('.glsl') else ('shl_%s.glsl' % l.replace('shl_', '')))
    return names


def check_glsl(path, line, body, k, info):
    stage = info[1] if len(info) > 1 and info[1] in ('frag', 'vert', 'comp') else 'frag'
    if len(info) > 1 and info[1] == 'fragment':
        stage = 'comp'
        head = ['#version 450', '#extension GL_GOOGLE_include_directive : require',
                '#define SHLIGHT_MAX_BANDS 4']
        head += ['#include "shlight_glsl/%s"' % m for m in modules()]
        body = '\n'.join(head) + '\n#line %d\n' % (line - 1) + body + \
            'layout(local_size_x = 1) in;\nvoid main() {}\n'
    src = os.path.join(OUT, '%s_%d.%s' % (re.sub(r'\W', '_', rel(path)), k, stage))
    with open(src, 'w') as f:
        f.write(body)
    if not body.lstrip().startswith('#version'):
        return 1, '%s:%d: a complete shader starts with #version\n' % (rel(path), line)
    return run([GLSLANG, '-l', '-I' + ROOT, src])


def public_functions():
    names = set()
    for l in open(os.path.join(ROOT, 'shlight.h'), encoding='utf-8'):
        m = re.match(r'^(SHLIGHT_API|SHLIGHT_INLINE)\b[^;(]*\b(shl_[a-z0-9_]+)\(', l)
        if m:
            names.add(m.group(2))
    return sorted(names)


def main(argv):
    global verbose
    keep = '-k' in argv
    verbose = '-v' in argv
    files = [a for a in argv if not a.startswith('-')]
    if not files:
        files = [os.path.join(ROOT, 'README.md')] + sorted(glob.glob(os.path.join(ROOT, 'docs', '*.md')))
    os.makedirs(OUT, exist_ok=True)
    passed = failed = 0

    def report(ok, what, log=''):
        nonlocal passed, failed
        if ok:
            passed += 1
        else:
            failed += 1
        print('%-4s %s' % ('ok' if ok else 'FAIL', what))
        if log and (not ok or verbose):
            print('\n'.join('     ' + l for l in log.rstrip().split('\n')[:30]))

    internal = re.compile(r'[Ss]eed 00[0-9]|\b[Ii]ssue #?[0-9]+|\bMATH\.md')
    for path in files:
        path = os.path.abspath(path)
        bl = blocks(path)
        frags = []
        for k, (info, line, body) in enumerate(bl):
            lang = info[0].lower() if info else ''
            where = '%s:%d' % (rel(path), line - 1)
            if lang == 'c' and len(info) > 1 and info[1] == 'fragment':
                frags.append((line, body))
            elif lang == 'c':
                rc, log = check_c(path, line, body, k)
                report(rc == 0, '%s C program builds (ASan, UBSan, -Werror) and runs' % where, log)
            elif lang == 'glsl':
                rc, log = check_glsl(path, line, body, k, info)
                report(rc == 0, '%s GLSL validates (glslang)' % where, log)
        if frags:
            rc, log = check_c_fragments(path, frags)
            report(rc == 0, '%s: %d C fragments build and run' % (rel(path), len(frags)), log)
        bad = [('%s:%d: %s' % (rel(path), i, l.strip())) for i, l in
               enumerate(open(path, encoding='utf-8').read().split('\n'), 1) if internal.search(l)]
        report(not bad, '%s: no internal references' % rel(path), '\n'.join(bad))

    readme = os.path.join(ROOT, 'README.md')
    if readme in [os.path.abspath(f) for f in files]:
        text = open(readme, encoding='utf-8').read()
        nlines = text.count('\n')
        report(nlines <= 300, 'README.md: %d lines (at most 300)' % nlines)
        index = text.split('## API index', 1)[-1]
        missing = [f for f in public_functions() if ('`%s(' % f) not in index]
        report(not missing, 'README.md: API index names all %d public functions of shlight.h'
               % len(public_functions()), 'missing: ' + ' '.join(missing) if missing else '')
    if not keep:
        shutil.rmtree(OUT, ignore_errors=True)
    print('%d passed, %d failed' % (passed, failed))
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
