#!/usr/bin/env python3
"""tools/stack_usage.py - stack use of every public shlight function, measured by gcc.

Builds one translation unit that includes shlight.h with SHLIGHT_IMPLEMENTATION and takes the
address of every public function (so each static inline kernel is emitted as a function of its
own), with -fstack-usage (each function's own frame) and -fcallgraph-info=su (the static call
graph). Prints, per public function: its own frame, the deepest static call chain below it
(own frame + the largest sum of frames along any chain of direct calls; calls through function
pointers and calls to libm / libc are not counted) and that chain. Fails (exit 1) when a
function's deepest chain is above the limit (16 KB = 16384 bytes), or a frame is dynamic
(alloca / VLA: "dynamic" without "bounded" in the .su file), except the functions named with --allow (their rows
still print, marked "allowed").

Usage: python3 tools/stack_usage.py [--cc gcc] [--cflags "-O2"] [--limit 16384]
                                    [--allow NAME[,NAME...]] [--markdown]
Run from the repository root. Needs gcc >= 10 (-fcallgraph-info). Output in build/stack/.
"""
import argparse
import os
import re
import subprocess
import sys

DEF_RE = re.compile(r"^(?:SHLIGHT_[A-Z_]+ )+[a-z_ ]+\*?\s*\b(shl_[a-z0-9_]+)\(")


def public_functions(header):
    names = []
    with open(header) as f:
        for line in f:
            m = DEF_RE.match(line)
            if m and m.group(1) not in names:
                names.append(m.group(1))
    return names


def parse_su(path):
    frames, dynamic = {}, set()
    with open(path) as f:
        for line in f:
            parts = line.rstrip("\n").split("\t")
            if len(parts) < 3:
                continue
            name = parts[0].split(":")[-1]
            frames[name] = max(frames.get(name, 0), int(parts[1]))
            if "dynamic" in parts[2] and "bounded" not in parts[2]:
                dynamic.add(name)
    return frames, dynamic


def parse_ci(path):
    """VCG graph from -fcallgraph-info: node titles are names, edges caller -> callee."""
    titles, edges = {}, {}
    node_re = re.compile(r'node:\s*\{\s*title:\s*"([^"]+)"\s*label:\s*"([^"]*)"')
    edge_re = re.compile(r'edge:\s*\{\s*sourcename:\s*"([^"]+)"\s*targetname:\s*"([^"]+)"')
    with open(path) as f:
        text = f.read()
    for m in node_re.finditer(text):
        titles[m.group(1)] = m.group(1).split(":")[-1]
    for m in edge_re.finditer(text):
        src = titles.get(m.group(1), m.group(1).split(":")[-1])
        dst = titles.get(m.group(2), m.group(2).split(":")[-1])
        edges.setdefault(src, set()).add(dst)
    return edges


def deepest(name, frames, edges, memo, stack):
    if name in memo:
        return memo[name]
    if name in stack:  # recursion: counted once (shlight has none; reported if it appears)
        return (frames.get(name, 0), [name + " (recursive)"])
    stack.add(name)
    best = (0, [])
    for callee in sorted(edges.get(name, ())):
        if callee not in frames:  # external (libm, libc): not counted
            continue
        d = deepest(callee, frames, edges, memo, stack)
        if d[0] > best[0]:
            best = d
    stack.discard(name)
    res = (frames.get(name, 0) + best[0], [name] + best[1])
    memo[name] = res
    return res


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cc", default=os.environ.get("CC_STACK", "gcc"))
    ap.add_argument("--cflags", default="-O2")
    ap.add_argument("--limit", type=int, default=16384)
    ap.add_argument("--allow", default="")
    ap.add_argument("--markdown", action="store_true")
    ap.add_argument("--out", default="build/stack")
    a = ap.parse_args()
    allow = set(x for x in a.allow.split(",") if x)
    names = public_functions("shlight.h")
    os.makedirs(a.out, exist_ok=True)
    tu = os.path.join(a.out, "stack_tu.c")
    with open(tu, "w") as f:
        f.write("#define SHLIGHT_IMPLEMENTATION\n#include \"../../shlight.h\"\n")
        f.write("typedef void (*stack_fp)(void);\n")
        f.write("stack_fp stack_all[] = {\n")
        for n in names:
            f.write("  (stack_fp)%s,\n" % n)
        f.write("};\n")
    obj = os.path.join(a.out, "stack_tu.o")
    cmd = [a.cc, "-std=c99", "-c", "-w", "-fstack-usage", "-fcallgraph-info=su"]
    cmd += a.cflags.split() + ["-o", obj, tu]
    r = subprocess.run(cmd, cwd=os.getcwd())
    if r.returncode != 0:
        print("stack_usage: compile failed: " + " ".join(cmd))
        return 2
    frames, dynamic = parse_su(os.path.join(a.out, "stack_tu.su"))
    edges = parse_ci(os.path.join(a.out, "stack_tu.ci"))
    memo = {}
    rows = []
    for n in names:
        if n not in frames:
            rows.append((n, None, None, [], "not emitted"))
            continue
        total, chain = deepest(n, frames, edges, memo, set())
        dyn = [c for c in chain if c in dynamic]
        bad = total > a.limit or dyn
        status = "ok"
        if bad:
            status = "allowed" if n in allow else "OVER"
        if dyn:
            status += " (dynamic frame: %s)" % ",".join(dyn)
        rows.append((n, frames[n], total, chain, status))
    passed = sum(1 for r in rows if r[4].startswith("ok") or r[4].startswith("allowed"))
    failed = len(rows) - passed
    if a.markdown:
        print("| function | own frame (B) | deepest chain (B) | chain | status |")
        print("|---|---:|---:|---|---|")
        for n, own, total, chain, st in rows:
            ch = " > ".join("%s %d" % (c, frames.get(c, 0)) for c in chain[1:])
            print("| `%s` | %s | %s | %s | %s |" % (n, own, total, ch, st))
    else:
        print("%-34s %8s %8s  %-8s %s" % ("function", "own", "deepest", "status", "chain below"))
        for n, own, total, chain, st in rows:
            ch = " > ".join("%s %d" % (c, frames.get(c, 0)) for c in chain[1:])
            print("%-34s %8s %8s  %-8s %s" % (n, own, total, st, ch))
    print("stack_usage: %d public functions, limit %d bytes (%s %s)" %
          (len(rows), a.limit, a.cc, a.cflags))
    print("%d passed, %d failed" % (passed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
