#!/usr/bin/env python3
"""Plots the lookup error of BRDF SH tables against theta_o as an SVG (stdlib only).
Input: the markdown written by `build/tests/ref_brdftab l` (make brdftab-ref), on stdin or as
the first argument; output: docs/brdf-tables-error.svg (or the second argument). One line per
table (model, samples), the max of F and F' at each theta_o, log scale; the x axis is
-log10(90.01 - theta_o) so that the grazing end is visible."""
import math
import os
import sys

COLORS = ['#1f77b4', '#aec7e8', '#2ca02c', '#98df8a', '#d62728', '#ff9896', '#9467bd', '#c5b0d5']


def parse(text):
    degs, rows = None, []
    for ln in text.splitlines():
        if ln.startswith('| model'):
            degs = [float(c) for c in ln.strip('|').split('|')[2:] if c.strip()]
        elif ln.startswith('| ') and degs and not ln.startswith('|---'):
            cells = [c.strip() for c in ln.strip().strip('|').split('|')]
            errs = [max(float(v) for v in c.split()) for c in cells[2:2 + len(degs)]]
            rows.append(('%s, %s samples' % (cells[0], cells[1]), errs))
    return degs, rows


def main():
    src = open(sys.argv[1]).read() if len(sys.argv) > 1 else sys.stdin.read()
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), '..', 'docs', 'brdf-tables-error.svg')
    degs, rows = parse(src)
    w, h, l, r, t, b = 760, 420, 70, 200, 20, 50
    xs = [-math.log10(90.01 - d) for d in degs]
    x0, x1, y0, y1 = min(xs), max(xs), -8.0, -1.0

    def px(x):
        return l + (x - x0) / (x1 - x0) * (w - l - r)

    def py(y):
        return t + (y1 - y) / (y1 - y0) * (h - t - b)

    s = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" '
         'font-size="11">' % (w, h), '<rect width="100%" height="100%" fill="white"/>']
    for e in range(int(y0), int(y1) + 1):
        s.append('<line x1="%d" x2="%d" y1="%.1f" y2="%.1f" stroke="#ddd"/>' % (l, w - r, py(e), py(e)))
        s.append('<text x="%d" y="%.1f" text-anchor="end">1e%d</text>' % (l - 4, py(e) + 4, e))
    for d, x in zip(degs, xs):
        if d in (0.05, 20.0, 70.0, 85.0, 89.0, 89.5, 89.9, 89.99):
            s.append('<text x="%.1f" y="%d" text-anchor="middle">%g</text>' % (px(x), h - b + 16, d))
    s.append('<text x="%d" y="%d" text-anchor="middle">theta_o (deg), axis -log10(90.01 - theta_o)'
             '</text>' % ((l + w - r) // 2, h - 10))
    s.append('<line x1="%d" x2="%d" y1="%.1f" y2="%.1f" stroke="black" stroke-dasharray="4,3"/>'
             % (l, w - r, py(-3), py(-3)))
    for i, (name, errs) in enumerate(rows):
        c = COLORS[i % len(COLORS)]
        pts = ' '.join('%.1f,%.1f' % (px(x), py(math.log10(max(e, 1e-8))))
                       for x, e in zip(xs, errs))
        s.append('<polyline fill="none" stroke="%s" stroke-width="1.5" points="%s"/>' % (c, pts))
        s.append('<text x="%d" y="%d" fill="%s">%s</text>' % (w - r + 8, t + 14 + 16 * i, c, name))
    s.append('<text x="%d" y="%.1f">1e-3</text>' % (w - r + 8, py(-3) + 4))
    s.append('</svg>')
    open(out, 'w').write('\n'.join(s) + '\n')
    print('wrote', out)


if __name__ == '__main__':
    main()
