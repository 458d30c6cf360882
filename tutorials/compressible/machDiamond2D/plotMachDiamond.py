#!/usr/bin/python3
"""machDiamond2D: schlieren pictures and the shock cells on the jet's axis.

    plotMachDiamond.py CASE

Reads the cell centres (CASE/0/C, postProcess -func writeCellCentres) and
rho, p, U of every written time after 0.  Writes machDiamond2D.png (the
numerical schlieren exp(-15 |grad rho|/max |grad rho|) of every written
time, side by side) and machDiamond2D_axis.png (p and the Mach number on
the axis x = 0.5 at the last time), prints the pressure maxima on the axis
(where the crossing shocks compress the jet), their spacing, the total gas
mass and the largest Mach number, and writes them to axis.dat.
"""
import os, re, sys
import numpy as np
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

case = sys.argv[1]
nx, ny, dx, M, pJ, rhoJ, uJ = open(f'{case}/caseInfo').read().split()
nx, ny, dx, M = int(nx), int(ny), float(dx), float(M)
pJ, rhoJ, uJ = float(pJ), float(rhoJ), float(uJ)
num = r'[-+]?\d+\.?\d*(?:[eE][-+]?\d+)?'

def internal(t, name):
    s = open(f'{case}/{t}/{name}').read()
    s = s[s.index('internalField'):]
    if s.split()[1] == 'uniform':
        raise ValueError(f'{t}/{name} is uniform')
    body = re.search(r'\d+\s*\((.*?)\n\)\s*;', s, re.S).group(1)
    if '(' in body:
        return np.array([[float(v) for v in m] for m in
                         re.findall(rf'\(({num}) ({num}) ({num})\)', body)])
    return np.array([float(v) for v in body.split()])

C = internal('0', 'C')
I = np.floor(C[:, 0]/dx).astype(int); J = np.floor(C[:, 1]/dx).astype(int)
def grid(v):
    g = np.zeros((ny, nx) + v.shape[1:]); g[J, I] = v
    return g

times = sorted((d for d in os.listdir(case)
                if re.fullmatch(num, d) and float(d) > 0), key=float)
if not times:
    sys.exit('plotMachDiamond.py: no written time in ' + case)

fig, ax = plt.subplots(1, len(times), figsize=(2.4*len(times), 4.2),
                       squeeze=False)
for a, t in zip(ax[0], times):
    r = grid(internal(t, 'rho'))
    gy, gx = np.gradient(r, dx)
    g = np.hypot(gx, gy)
    a.imshow(np.exp(-15*g/g.max()), origin='lower', extent=(0, 1, 0, 1.5),
             cmap='gray', vmin=0, vmax=1)
    a.set_title(f't = {t}'); a.set_xticks([]); a.set_yticks([])
fig.suptitle(f'Mach {M:g} jet at {pJ:g} x the ambient pressure', fontsize=9)
fig.tight_layout()
fig.savefig('machDiamond2D.png', dpi=120)

t = times[-1]
p = grid(internal(t, 'p')); r = grid(internal(t, 'rho'))
U = grid(internal(t, 'U'))
i0 = nx//2
pa = 0.5*(p[:, i0 - 1] + p[:, i0])
ra = 0.5*(r[:, i0 - 1] + r[:, i0])
va = 0.5*(U[:, i0 - 1, 1] + U[:, i0, 1])
Ma = va/np.sqrt(1.4*pa/ra)
y = (np.arange(ny) + 0.5)*dx
# pressure maxima on the axis above 1.2 times the ambient pressure, in the
# supersonic jet (Mach > 1: not behind its head)
peaks = [j for j in range(2, ny - 2) if pa[j] == pa[j - 2:j + 3].max()
         and pa[j] > 1.2 and Ma[j] > 1]
# where the lip shocks first meet on the axis: p first above the ambient 1
jx = next((j for j in range(ny) if pa[j] > 1.0), None)
yx = y[jx - 1] + (1.0 - pa[jx - 1])/(pa[jx] - pa[jx - 1])*dx if jx else float('nan')
# oblique-shock estimate: the shock turning the jet to the ambient pressure
# (p2/p1 = 1/pRatio) leaves the lip at the angle theta, meets the axis at
# (h/2)/tan(theta), h = 1/8 the nozzle's width
g = 1.4
s2 = (1 + (1/pJ - 1)*(g + 1)/(2*g))/(M*M)
th = np.arcsin(np.sqrt(s2))
yEst = (1/16)/np.tan(th)
mass = (internal(t, 'rho')*dx*dx).sum()
with open('axis.dat', 'w') as f:
    f.write(f'# t = {t}: lip shocks meet the axis at y = {yx:.4f} (oblique-shock'
            f' estimate {yEst:.4f}, shock angle {np.degrees(th):.2f} deg)\n')
    f.write(f'# pressure maxima on the axis x = 0.5 (y, p, Mach)\n')
    for j in peaks:
        f.write(f'{y[j]:.4f} {pa[j]:.4f} {Ma[j]:.4f}\n')
print(f'  t = {t}: the lip shocks meet the axis at y = {yx:.4f} (p first'
      f' above 1); oblique-shock estimate {yEst:.4f} (shock angle'
      f' {np.degrees(th):.2f} deg)')
print(f'  t = {t}: pressure maxima on the axis at y =',
      ', '.join(f'{y[j]:.3f} (p {pa[j]:.2f})' for j in peaks))
if len(peaks) > 1:
    print('  spacing', ', '.join(f'{y[b] - y[a]:.3f}'
                                 for a, b in zip(peaks, peaks[1:])))
print(f'  largest Mach number on the axis {Ma.max():.3f}; gas mass {mass:.6f}'
      f' (per unit depth); rho in [{r.min():.4f}, {r.max():.4f}],'
      f' p in [{p.min():.4f}, {p.max():.4f}]')
fig, a = plt.subplots(figsize=(7, 3.5))
a.plot(y, pa, label='p'); a.plot(y, Ma, label='Mach')
for j in peaks:
    a.axvline(y[j], color='gray', lw=0.5)
a.axhline(1, color='k', lw=0.5, ls=':')
a.set_xlabel('y (height above the nozzle)'); a.legend()
a.set_title(f'on the jet axis x = 0.5, t = {t}')
fig.tight_layout()
fig.savefig('machDiamond2D_axis.png', dpi=110)
