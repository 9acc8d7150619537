#!/usr/bin/env python3
"""Rewrites the benchmark tables of docs/speed.md, docs/accuracy.md and docs/area-lights.md (between
<!-- bench:NAME --> markers) from what `make bench` and the `make bench-*` targets leave in
bench/out/: `speed` and `accuracy` from basis.csv, `light` from light.md, `grid` from grid.md;
any other marker NAME takes bench/out/NAME.md as written. A marker whose input is missing is
left as it is. Usage: python3 bench/readme_tables.py (from anywhere)."""
import csv
import os
import re

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
NS = [1, 2, 3, 4, 5, 6, 8, 10, 16, 32, 64]


def fmt(x, dig=2):
    return ('%.' + str(dig) + 'g') % x if x < 1000 else '%d' % round(x)


def tables():
    rows = list(csv.DictReader(open(os.path.join(ROOT, 'bench/out/basis.csv'))))
    R = {(r['variant'], int(r['n'])): r for r in rows}
    head = ['| n | ' + ' | '.join(str(n) for n in NS) + ' |', '|---|' + '---|' * len(NS)]
    sp = list(head)
    spec = [('eval', 'ns', '`shl_sh_eval`, ns'), ('eval', 'ratio_to_loop', '  ratio to the loop'),
            ('eval_rt', 'ratio_to_loop', '`shl_sh_eval`, n at run time: ratio'),
            ('accurate', 'ratio_to_loop', '`shl_sh_eval_accurate`: ratio'),
            ('batch16', 'ratio_to_loop', '`shl_sh_eval_batch`, 16 directions: ratio per direction'),
            ('batch32', 'ratio_to_loop', '`shl_sh_eval_batch`, 32 directions: ratio per direction'),
            ('batch', 'ratio_to_loop', '`shl_sh_eval_batch`, 1024 directions: ratio per direction'),
            ('grad', 'ns', '`shl_sh_eval_grad`, ns'),
            ('grad_sph', 'ns', 'paper: spherical partials + Jacobian, ns'),
            ('loop', 'ns', 'plain loop (yardstick), ns')]
    for var, col, label in spec:
        cells = [fmt(float(R[(var, n)][col]), 3 if col == 'ns' else 2) if (var, n) in R else '-'
                 for n in NS]
        sp.append('| ' + label + ' | ' + ' | '.join(cells) + ' |')
    cells = []
    for n in NS:
        g, e, er = R.get(('grad', n)), R.get(('eval', n)), R.get(('eval_rt', n))
        cells.append('%.1f / %.1f' % (float(g['ns']) / float(e['ns']), float(g['ns']) / float(er['ns'])))
    sp.append('| value+gradient / value (literal n / run-time n) | ' + ' | '.join(cells) + ' |')
    ac = ['| max abs error | ' + ' | '.join(str(n) for n in NS) + ' |', '|---|' + '---|' * len(NS)]
    for var, label in [('eval', '`shl_sh_eval`'), ('accurate', '`shl_sh_eval_accurate`'),
                       ('batch', '`shl_sh_eval_batch`'), ('loop', 'plain float loop (yardstick)')]:
        cells = [fmt(max(float(R[(var, n)]['max_err_random']), float(R[(var, n)]['max_err_pole'])))
                 for n in NS]
        ac.append('| ' + label + ', random and near-pole | ' + ' | '.join(cells) + ' |')
    cells = [fmt(max(float(R[('grad', n)]['grad_err_random']), float(R[('grad', n)]['grad_err_pole'])))
             for n in NS]
    ac.append('| `shl_sh_eval_grad`: error / max abs grad, abs d in [0.1, 10] | ' + ' | '.join(cells) + ' |')
    light = open(os.path.join(ROOT, 'bench/out/light.md')).read().split('\n')
    kept = []
    for l in light:  # the tables and the solid-angle line, blank lines between blocks
        if l.startswith('|') or l.startswith('shl_triangle_solid'):
            if kept and (kept[-1].startswith('|') != l.startswith('|')):
                kept.append('')
            kept.append(l)
        elif kept and kept[-1] != '':
            kept.append('')
    light = [l for i, l in enumerate(kept) if not (l == '' and (i + 1 == len(kept) or kept[i + 1] == ''))]
    grid = open(os.path.join(ROOT, 'bench/out/grid.md')).read().rstrip('\n').split('\n')
    grid = ['    ' + l for l in grid]  # a preformatted block
    return {'speed': '\n'.join(sp), 'accuracy': '\n'.join(ac), 'light': '\n'.join(light),
            'grid': '\n'.join(grid)}


def main():
    try:
        computed = tables()
    except (IOError, OSError, KeyError) as e:  # no basis / light / grid run: other markers only
        print('bench/out incomplete (%s): only the bench/out/NAME.md markers are rewritten' % e)
        computed = {}
    for doc in ('docs/speed.md', 'docs/accuracy.md', 'docs/area-lights.md'):
        path = os.path.join(ROOT, doc)
        text = open(path).read()
        for name in re.findall(r'<!-- bench:([a-z_0-9]+) -->', text):
            body = computed.get(name)
            src = os.path.join(ROOT, 'bench/out', name + '.md')
            if body is None and os.path.exists(src):
                body = open(src).read().rstrip('\n')
            if body is None:
                continue
            text = re.sub(r'(<!-- bench:%s -->\n)(?:.*?\n)?(<!-- /bench:%s -->)' % (name, name),
                          lambda m: m.group(1) + body + '\n' + m.group(2), text, flags=re.S)
        open(path, 'w').write(text)
        print('wrote', doc)


if __name__ == '__main__':
    main()
