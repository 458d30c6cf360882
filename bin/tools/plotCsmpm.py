#!/usr/bin/python3
"""CSMPM tutorials (shellExplosion2D, bullet2D, cylindersMach3): schlieren
pictures with the particles drawn on them, and the solid's numbers.

    plotCsmpm.py CASE NAME [-times t1,t2,...] [-box x0,x1,y0,y1]
                 [-minFragment 20]

Reads the cell centres (CASE/0/C, postProcess -func writeCellCentres), the
gas density and the cloud (positions, U, mass) of every written time.
Writes NAME_schlieren.png: the numerical schlieren exp(-15 |grad rho| /
max |grad rho|) of the chosen times (default: four spread over the run)
with the particles in red (cells outside the mesh are grey), and
NAME_solid.dat: per written time the number of fragments (particles
joined when closer than 1.5 cells, connected components of the
neighbour graph, of at least minFragment particles), the solid's mass,
momentum and centre, the largest particle speed and the number of strays
(the particles of smaller clusters), and per fragment its mass, centre
and velocity.
The last time's lines are printed.  A 3D case is drawn in its mid-plane
z = const (the cells there, the particles within a cell of it); its
fragments and totals are the whole cloud's.
"""
import os, re, sys
import numpy as np
from particlePairs import clusters
from csmpmCase import cloudField
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

case, name = sys.argv[1], sys.argv[2]
opts = {k.lstrip('-'): v for k, v in zip(sys.argv[3::2], sys.argv[4::2])}
minFrag = int(opts.get('minFragment', 20))
num = r'[-+]?\d+\.?\d*(?:[eE][-+]?\d+)?'
dx = float(open(f'{case}/caseInfo').read().split()[2])


def internal(t, field):
    s = open(f'{case}/{t}/{field}').read()
    s = s[s.index('internalField'):]
    body = re.search(r'\d+\s*\((.*?)\n\)\s*;', s, re.S).group(1)
    if '(' in body:
        return np.array([[float(v) for v in m] for m in
                         re.findall(rf'\(({num}) ({num}) ({num})\)', body)])
    return np.array([float(v) for v in body.split()])


def cloud(t, field):
    return cloudField(case, t, field)


def fragments(x, h):
    """Labels of the particles' clusters: joined when closer than h
    (bin/tools/particlePairs.py: numpy only)."""
    return clusters(x, h)


C = internal('0', 'C')
zs = np.unique(np.floor(C[:, 2]/dx + 1e-9).astype(int))
is3D = len(zs) > 1
if is3D:                        # the cells of the mid-plane
    zMid = (zs[len(zs)//2] + 0.5)*dx
    plane = np.abs(C[:, 2] - zMid) < 0.5*dx
else:
    plane = np.ones(len(C), dtype=bool)
C = C[plane]
lo = C[:, :2].min(axis=0) - 0.5*dx
I = np.rint((C[:, 0] - lo[0])/dx - 0.5).astype(int)
J = np.rint((C[:, 1] - lo[1])/dx - 0.5).astype(int)
nx, ny = I.max() + 1, J.max() + 1
ext = (lo[0], lo[0] + nx*dx, lo[1], lo[1] + ny*dx)
times = sorted((d for d in os.listdir(case)
                if re.fullmatch(num, d) and os.path.exists(f'{case}/{d}/rho')),
               key=float)

rows = []
with open(f'{name}_solid.dat', 'w') as f:
    f.write('# t fragments mass momentum_x momentum_y centre_x centre_y '
            'maxParticleSpeed strays\n#   then per fragment (>= %d '
            'particles): "frag" mass centre_x centre_y U_x U_y\n' % minFrag)
    for t in times:
        x = cloud(t, 'positions'); U = cloud(t, 'U'); m = cloud(t, 'mass')
        if len(x) == 0:
            continue
        lab = fragments(x, 1.5*dx)
        M = m.sum(); P = (m[:, None]*U).sum(axis=0)
        c = (m[:, None]*x).sum(axis=0)/M
        frs = []
        strays = 0
        for L in np.unique(lab):
            k = lab == L
            if k.sum() < minFrag:
                strays += int(k.sum())
                continue
            mk = m[k].sum()
            frs.append((mk, *((m[k][:, None]*x[k]).sum(axis=0)/mk)[:2],
                        *((m[k][:, None]*U[k]).sum(axis=0)/mk)[:2]))
        frs.sort(key=lambda r: -r[0])
        vmax = np.sqrt((U**2).sum(axis=1)).max()
        row = (float(t), len(frs), M, P[0], P[1], c[0], c[1], vmax, strays)
        rows.append((row, frs, t))
        f.write('%.6g %d %.10g %.6e %.6e %.6f %.6f %.6f %d\n' % row)
        for r in frs:
            f.write('  frag %.6g %.5f %.5f %.5f %.5f\n' % r)
if rows:
    row, frs, t = rows[-1]
    print('  t = %g: %d fragments (>= %d particles) and %d strays, solid '
          'mass %.10g, momentum (%.3e %.3e), largest particle speed %.4f'
          % (row[0], row[1], minFrag, row[8], row[2], row[3], row[4],
             row[7]))

if 'times' in opts:
    pick = opts['times'].split(',')
else:
    ts = [t for t in times if float(t) > 0]
    pick = [ts[min(len(ts) - 1, round(k*(len(ts) - 1)/3))] for k in range(4)]
    pick = sorted(set(pick), key=float)
box = [float(v) for v in opts['box'].split(',')] if 'box' in opts else ext
wide = (box[1] - box[0]) > 1.5*(box[3] - box[2])
n = len(pick)
fig, ax = plt.subplots(n if wide else 1, 1 if wide else n, squeeze=False,
                       figsize=(9, n*(8.6*(box[3] - box[2])/(box[1] - box[0])
                                     + 0.4)) if wide else (3.2*n, 3.4))
for a, t in zip(ax.flat, pick):
    r = np.full((ny, nx), np.nan); r[J, I] = internal(t, 'rho')[plane]
    gy, gx = np.gradient(r, dx)
    g = np.hypot(gx, gy)
    S = np.exp(-15*g/np.nanmax(g))
    cm = plt.get_cmap('gray').copy(); cm.set_bad('0.6')
    a.imshow(np.ma.masked_invalid(S), origin='lower', extent=ext, cmap=cm,
             vmin=0, vmax=1, interpolation='nearest')
    x = cloud(t, 'positions')
    if len(x) and is3D:
        x = x[np.abs(x[:, 2] - zMid) < dx]
    if len(x):
        a.plot(x[:, 0], x[:, 1], '.', ms=0.8, color='tab:red')
    a.set_xlim(box[0], box[1]); a.set_ylim(box[2], box[3])
    a.set_title(f't = {t}', fontsize=9)
    a.set_xticks([]); a.set_yticks([])
fig.tight_layout()
fig.savefig(f'{name}_schlieren.png', dpi=120)
