#!/usr/bin/python3
"""blastOrder: pressure with the particles for two runs at the time of the
largest pressure at the solid.  plotBlastOrder.py CASE1 CASE2"""
import os, re, sys, subprocess
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt
num = r'[-+]?\d+\.?\d*(?:[eE][-+]?\d+)?'
cases = sys.argv[1:3]
def field(c, t, name, n):
    s = open(f'{c}/{t}/{name}').read()
    s = s[s.index('internalField'):]
    m = re.search(r'nonuniform List<scalar>\s*(\d+)\s*\((.*?)\)\s*;', s, re.S)
    if m:
        return [float(v) for v in m.group(2).split()]
    return [float(re.search(rf'uniform\s+({num})', s).group(1))]*(n*n)
out = subprocess.run([sys.executable, os.path.join(os.path.dirname(sys.argv[0]) or '.', 'peak.py'), cases[0]],
                     capture_output=True, text=True).stdout
t = re.search(r'\(t = ([^)]*)\)', out).group(1)
fig, ax = plt.subplots(1, 2, figsize=(11, 5))
for a, c in zip(ax, cases):
    n = int(open(f'{c}/caseInfo').read().split()[0])
    p = field(c, t, 'p', n)
    img = [p[j*n:(j + 1)*n] for j in range(n)]
    im = a.imshow(img, origin='lower', extent=(0, 1, 0, 1), cmap='viridis')
    s = open(f'{c}/{t}/lagrangian/mpmCloud/positions').read()
    xy = re.findall(rf'\(({num}) ({num}) {num}\)', s)
    a.plot([float(x) for x, y in xy], [float(y) for x, y in xy], '.', ms=1, color='w')
    a.set_title(f'{c}: p at t = {t}, max {max(p):.2f}')
    fig.colorbar(im, ax=a, shrink=0.8)
fig.tight_layout()
fig.savefig('blastOrder.png', dpi=100)
