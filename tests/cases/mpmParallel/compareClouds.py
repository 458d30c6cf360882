#!/usr/bin/python3
"""Compare two MPM clouds particle by particle, matched by the field id.

Usage: compareClouds.py <cloudDirA> <cloudDirB> [field ...]

Reads the ascii lagrangian files (positions: "(x y z) cell"; vector,
tensor and scalar IOFields) and prints one line:
    <max relative difference> <particles> <fields compared> <worst field>
The difference of a field is the largest |a - b| over the particles and
components, relative to the largest |a| of that field (positions: to the
cloud's extent).  Exit status 2 if the particles differ (count or ids) or
there are none: a check must not pass on nothing.
"""
import re
import sys

NUM = r'[-+0-9.eE]+'


def body(path):
    """The entries of an OpenFOAM list file, as lists of floats."""
    text = open(path).read()
    text = re.sub(r'FoamFile\s*\{[^}]*\}', '', text, count=1)
    text = re.sub(r'//.*', '', text)
    m = re.search(r'(\d+)\s*\(', text)
    if not m:
        # uniform form n{value}
        m = re.search(r'(\d+)\s*\{([^}]*)\}', text)
        n = int(m.group(1))
        vals = [float(x) for x in re.findall(NUM, m.group(2))]
        return [vals] * n
    n = int(m.group(1))
    rest = text[m.end():]
    entries = []
    if n == 0:
        return entries
    if rest.lstrip().startswith('('):
        for line in re.finditer(r'\(([^()]*)\)([^\n(]*)', rest):
            if len(entries) == n:
                break
            vals = [float(x) for x in re.findall(NUM, line.group(1))]
            entries.append(vals)
    else:
        for tok in re.findall(NUM, rest)[:n]:
            entries.append([float(tok)])
    if len(entries) != n:
        raise SystemExit('%s: read %d of %d entries' % (path, len(entries), n))
    return entries


def main():
    a, b = sys.argv[1], sys.argv[2]
    fields = sys.argv[3:] or ['positions', 'U', 'F', 'B', 'sigma', 'volume',
                              'mass', 'V0', 'psi']
    ida = [int(v[0]) for v in body(a + '/id')]
    idb = [int(v[0]) for v in body(b + '/id')]
    if not ida or sorted(ida) != sorted(idb) or len(set(ida)) != len(ida):
        print('inf %d 0 ids' % len(ida))
        sys.exit(2)
    posb = {i: k for k, i in enumerate(idb)}
    order = [posb[i] for i in ida]
    worst, worstField = 0.0, '-'
    for f in fields:
        fa, fb = body(a + '/' + f), body(b + '/' + f)
        scale = max((abs(x) for v in fa for x in v), default=0.0)
        if f == 'positions':
            scale = max(max(v) - min(v) for v in zip(*fa))
        diff = 0.0
        for k, e in enumerate(fa):
            o = fb[order[k]]
            for x, y in zip(e, o):
                diff = max(diff, abs(x - y))
        rel = diff/scale if scale > 0 else diff
        if rel >= worst:
            worst, worstField = rel, f
    print('%.3e %d %d %s' % (worst, len(ida), len(fields), worstField))


main()
