#!/usr/bin/python3
"""blastOrder: the pressure peaks of a run. peak.py CASE

For every written time after 0: the largest pressure over all cells, and
over the cells the solid touches (alphaSolid > 0) and their face
neighbours; prints the largest of each over the run, and the time."""
import os, re, sys
case = sys.argv[1]
num = r'[-+]?\d+\.?\d*(?:[eE][-+]?\d+)?'
def field(t, name):
    s = open(f'{case}/{t}/{name}').read()
    s = s[s.index('internalField'):]
    m = re.search(r'nonuniform List<scalar>\s*(\d+)\s*\((.*?)\)\s*;', s, re.S)
    if m:
        return [float(v) for v in m.group(2).split()]
    n = int(open(f'{case}/caseInfo').read().split()[0])
    v = float(re.search(rf'uniform\s+({num})', s).group(1))
    return [v]*(n*n)
n = int(open(f'{case}/caseInfo').read().split()[0])
times = sorted((float(d), d) for d in os.listdir(case)
               if re.fullmatch(num, d) and float(d) > 0)
best = (0, 0, '', '')
for _, t in times:
    p = field(t, 'p')
    a = field(t, 'alphaSolid')
    near = set()
    for k, v in enumerate(a):
        if v > 0:
            i, j = k % n, k // n
            for di, dj in ((0, 0), (1, 0), (-1, 0), (0, 1), (0, -1)):
                if 0 <= i + di < n and 0 <= j + dj < n:
                    near.add(i + di + n*(j + dj))
    pAll = max(p)
    pNear = max(p[k] for k in near) if near else 0
    print(f'  t = {t:8s} max p {pAll:10.4f}   max p at the solid {pNear:10.4f}')
    if pNear > best[1]:
        best = (pAll, pNear, t, '')
print(f'largest pressure at the solid: {best[1]:.4f} (t = {best[2]})')
