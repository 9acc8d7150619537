#!/usr/bin/env python3
"""plot_ggx.py - the GGX polygon lights' speed-against-error plot (SVG) from the table between
the <!-- bench:ggx_speed --> markers of docs/area-lights.md (written there by
bench/readme_tables.py from bench/out/ggx_speed.md, which `make bench-ggx` writes):

  docs/plot_ggx.svg   x86 instructions per quad (x) against the median relative error and the
                      max error / albedo (y), one point per road and roughness

Python 3 standard library only. Run from the repository root: python3 bench/plot_ggx.py"""
from plot_speed import num, rows, section, svg_plot


def main():
    tab = rows(section("docs/area-lights.md", "ggx_speed"))
    series = {}
    for r in tab:
        if len(r) < 6 or num(r[0]) is None or num(r[2]) is None:
            continue
        road = r[1].replace("`", "").replace(" (measured externally)", " (ext.)")
        med = num(r[4])
        emax = num(r[5])
        tag = "r=%s" % r[0]
        if med:
            series.setdefault(road + ": median", []).append((num(r[2]), med, tag))
        if emax:
            series.setdefault(road + ": max", []).append((num(r[2]), emax, tag))
    if not series:
        print("docs/area-lights.md: no ggx_speed table, nothing plotted")
        return
    for k in series:
        series[k].sort()
    svg_plot("docs/plot_ggx.svg",
             "GGX quad lights: cost against error per roughness (gcc -O3 -march=x86-64-v3)",
             "x86 instructions per quad (callgrind)", "median rel. error; max error / albedo",
             sorted(series.items()), lines=False)


if __name__ == "__main__":
    main()
