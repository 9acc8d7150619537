#!/usr/bin/env python3
"""plot_speed.py - speed-against-error plots (SVG) from the bench tables of docs/speed.md and
docs/accuracy.md (written there by bench/readme_tables.py from the `make bench*` outputs):

  docs/plot_basis.svg   basis kernels: ns per call (x) against max abs error (y), one point per n
  docs/plot_area.svg    Phong polygon lights: ns per quad (x) against max error (y), per method
  docs/plot_lights.svg  sphere / triangle lights: ns per call against the band count

Python 3 standard library only. Run from the repository root: python3 bench/plot_speed.py"""
import math
import re

COLORS = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#17becf", "#7f7f7f"]


def section(path, name):
    text = open(path).read()
    m = re.search(r"<!-- bench:%s -->(.*?)<!-- /bench:%s -->" % (name, name), text, re.S)
    return m.group(1) if m else ""


def rows(md):
    out = []
    for line in md.split("\n"):
        if line.startswith("|") and not re.match(r"^\|[-| ]+\|$", line):
            out.append([c.strip() for c in line.strip().strip("|").split("|")])
    return out


def num(s):
    try:
        return float(s.split()[0].replace("`", ""))
    except (ValueError, IndexError):
        return None


def svg_plot(path, title, xlabel, ylabel, series, xlog=True, ylog=True, lines=True):
    """series: [(label, [(x, y, tag)])]; log axes; points joined in order"""
    W, H, L, R, T, B = 760, 460, 70, 200, 40, 50
    xs = [p[0] for _, pts in series for p in pts]
    ys = [p[1] for _, pts in series for p in pts]
    fx = (lambda v: math.log10(v)) if xlog else (lambda v: v)
    fy = (lambda v: math.log10(v)) if ylog else (lambda v: v)
    x0, x1 = math.floor(fx(min(xs))), math.ceil(fx(max(xs)))
    y0, y1 = math.floor(fy(min(ys))), math.ceil(fy(max(ys)))
    if x1 == x0:
        x1 += 1
    if y1 == y0:
        y1 += 1
    px = lambda v: L + (fx(v) - x0) / (x1 - x0) * (W - L - R)
    py = lambda v: H - B - (fy(v) - y0) / (y1 - y0) * (H - T - B)
    o = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" '
         'font-size="12">' % (W, H), '<rect width="100%" height="100%" fill="white"/>',
         '<text x="%d" y="22" font-size="15">%s</text>' % (L, title)]
    for k in range(int(x0), int(x1) + 1):
        X = L + (k - x0) / (x1 - x0) * (W - L - R)
        o.append('<line x1="%.1f" y1="%d" x2="%.1f" y2="%d" stroke="#ddd"/>' % (X, T, X, H - B))
        o.append('<text x="%.1f" y="%d" text-anchor="middle">%s</text>' %
                 (X, H - B + 16, ("1e%d" % k) if xlog else str(k)))
    for k in range(int(y0), int(y1) + 1):
        Y = H - B - (k - y0) / (y1 - y0) * (H - T - B)
        o.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="#ddd"/>' % (L, Y, W - R, Y))
        o.append('<text x="%d" y="%.1f" text-anchor="end">%s</text>' %
                 (L - 6, Y + 4, ("1e%d" % k) if ylog else str(k)))
    o.append('<rect x="%d" y="%d" width="%d" height="%d" fill="none" stroke="black"/>' %
             (L, T, W - L - R, H - T - B))
    o.append('<text x="%d" y="%d" text-anchor="middle">%s</text>' % ((L + W - R) // 2, H - 12, xlabel))
    o.append('<text x="16" y="%d" transform="rotate(-90 16 %d)" text-anchor="middle">%s</text>' %
             ((T + H - B) // 2, (T + H - B) // 2, ylabel))
    for i, (label, pts) in enumerate(series):
        c = COLORS[i % len(COLORS)]
        if lines:
            o.append('<polyline fill="none" stroke="%s" stroke-width="1.5" points="%s"/>' %
                     (c, " ".join("%.1f,%.1f" % (px(x), py(y)) for x, y, _ in pts)))
        for x, y, tag in pts:
            o.append('<circle cx="%.1f" cy="%.1f" r="3" fill="%s"><title>%s</title></circle>' %
                     (px(x), py(y), c, tag))
            if tag:
                o.append('<text x="%.1f" y="%.1f" font-size="9" fill="%s">%s</text>' %
                         (px(x) + 4, py(y) - 4, c, tag))
        o.append('<text x="%d" y="%d" fill="%s">%s</text>' % (W - R + 10, T + 16 + 18 * i, c, label))
    o.append("</svg>")
    open(path, "w").write("\n".join(o) + "\n")
    print("wrote", path)


def basis():
    sp = rows(section("docs/speed.md", "speed"))
    ac = rows(section("docs/accuracy.md", "accuracy"))
    ns = [int(c) for c in sp[0][1:]]
    get = lambda tab, key: next(r for r in tab if r[0].startswith(key))
    loop = [num(c) for c in get(sp, "plain loop")[1:]]
    ev = [num(c) for c in get(sp, "`shl_sh_eval`, ns")[1:]]
    acc_r = [num(c) for c in get(sp, "`shl_sh_eval_accurate`")[1:]]
    b32 = [num(c) for c in get(sp, "`shl_sh_eval_batch`, 32")[1:]]
    gr = [num(c) for c in get(sp, "`shl_sh_eval_grad`, ns")[1:]]
    e_ev = [num(c) for c in get(ac, "`shl_sh_eval`,")[1:]]
    e_acc = [num(c) for c in get(ac, "`shl_sh_eval_accurate`")[1:]]
    e_b = [num(c) for c in get(ac, "`shl_sh_eval_batch`")[1:]]
    e_g = [num(c) for c in get(ac, "`shl_sh_eval_grad`")[1:]]
    tag = lambda n: "n=%d" % n if n in (1, 4, 16, 64) else ""
    pts = lambda t, e: [(t[i], e[i], tag(ns[i])) for i in range(len(ns)) if t[i] and e[i] and e[i] > 1e-20]
    svg_plot("docs/plot_basis.svg", "SH basis: time against error, n = 1..64 (Zen 4, gcc -O3 -march=native)",
             "ns per direction", "max abs error (binary128 reference)",
             [("shl_sh_eval", pts(ev, e_ev)),
              ("shl_sh_eval_accurate", pts([acc_r[i] * loop[i] for i in range(len(ns))], e_acc)),
              ("shl_sh_eval_batch (32)", pts([b32[i] * loop[i] for i in range(len(ns))], e_b)),
              ("shl_sh_eval_grad (rel.)", pts(gr, e_g))])


def area():
    tab = rows(section("docs/speed.md", "edge"))
    series = {}
    for r in tab:
        if len(r) >= 6 and num(r[2]) and num(r[5]) and r[0] != "method":
            series.setdefault(r[0], []).append((num(r[2]), max(num(r[5]), 1e-9), ""))
    for k in series:
        series[k].sort()
    svg_plot("docs/plot_area.svg", "Phong quad lights: time against max error (exponents 1 to 1e4, one point each)",
             "ns per quad", "max error (normalised lobe, cubature reference)",
             list(series.items()), lines=False)


def lights():
    tab = rows(section("docs/speed.md", "light"))
    hdr = tab[0]
    data = [r for r in tab[1:] if len(r) == len(hdr) and num(r[0])]
    series = []
    for col in ("sphere", "sphere+grad", "triangle", "triangle+grad", "sh_eval"):
        j = hdr.index(col)
        series.append((col, [(num(r[0]), num(r[j]), "") for r in data if num(r[j])]))
    svg_plot("docs/plot_lights.svg", "Sphere and triangle lights: ns per call against bands",
             "bands n", "ns per call", series, xlog=False, ylog=True)


if __name__ == "__main__":
    basis()
    area()
    lights()
