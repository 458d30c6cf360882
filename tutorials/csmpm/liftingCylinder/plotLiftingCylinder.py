#!/usr/bin/python3
"""liftingCylinder: the cylinder's trajectory and schlieren pictures.

    plotLiftingCylinder.py CASE

Reads the particle positions, velocities and masses of every written time
(CASE/<t>/lagrangian/mpmCloud) and the schlieren field; writes
trajectory.dat (t, centre x, centre y, velocity x, velocity y),
liftingCylinder_trajectory.png and liftingCylinder_schlieren.png.
"""
import os, re, sys
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

case = sys.argv[1]
num = r'[-+]?\d+\.?\d*(?:[eE][-+]?\d+)?'

def times():
    ts = []
    for d in os.listdir(case):
        try:
            ts.append((float(d), d))
        except ValueError:
            pass
    return [d for _, d in sorted(ts)]

def cloudVectors(t, name):
    s = open(f'{case}/{t}/lagrangian/mpmCloud/{name}').read()
    return [tuple(float(v) for v in m) for m in
            re.findall(rf'\(({num}) ({num}) ({num})\)', s)]

def cloudScalars(t, name):
    s = open(f'{case}/{t}/lagrangian/mpmCloud/{name}').read()
    s = s[s.index('}') + 1:]
    m = re.search(rf'(\d+)\s*\{{\s*({num})\s*\}}', s)
    if m:                                   # a uniform list: N{value}
        return [float(m.group(2))]*int(m.group(1))
    body = s[s.index('(') + 1:]
    return [float(v) for v in body.split(')')[0].split()]

def field(t, name):
    s = open(f'{case}/{t}/{name}').read()
    s = s[s.index('internalField'):]
    m = re.search(r'(\d+)\s*\((.*?)\)\s*;', s, re.S)
    return [float(v) for v in m.group(2).split()]

rows = []
for t in times():
    if not os.path.isdir(f'{case}/{t}/lagrangian/mpmCloud'):
        continue
    x = cloudVectors(t, 'positions')
    U = cloudVectors(t, 'U')
    m = cloudScalars(t, 'mass')
    M = sum(m)
    cx = sum(mi*p[0] for mi, p in zip(m, x))/M
    cy = sum(mi*p[1] for mi, p in zip(m, x))/M
    ux = sum(mi*u[0] for mi, u in zip(m, U))/M
    uy = sum(mi*u[1] for mi, u in zip(m, U))/M
    rows.append((float(t), cx, cy, ux, uy, t))
with open('trajectory.dat', 'w') as f:
    f.write('# t  centre_x  centre_y  U_x  U_y   (mass-weighted over the particles)\n')
    for r in rows:
        f.write('%.6g %.6f %.6f %.6f %.6f\n' % r[:5])
for r in rows:
    print('  t = %-8.4g centre (%.4f, %.4f)  velocity (%.4f, %.4f)' % r[:5])

fig, ax = plt.subplots(1, 2, figsize=(11, 4))
ax[0].plot([r[1] for r in rows], [r[2] for r in rows], 'o-')
ax[0].set_xlim(0, 1); ax[0].set_ylim(0, 0.2); ax[0].set_aspect('equal')
ax[0].set_xlabel('centre x'); ax[0].set_ylabel('centre y')
ax[0].set_title('cylinder centre in the channel')
ax[1].plot([r[0] for r in rows], [r[1] for r in rows], 'o-', label='x')
ax[1].plot([r[0] for r in rows], [r[2] for r in rows], 's-', label='y')
ax[1].set_xlabel('t'); ax[1].set_ylabel('centre'); ax[1].legend()
ax[1].set_title('centre against time')
fig.tight_layout()
fig.savefig('liftingCylinder_trajectory.png', dpi=110)

# Schlieren with the particles at three times
nx = int(open(f'{case}/caseInfo').read().split()[0])
ny = nx//5
pick = [rows[len(rows)//3][5], rows[(2*len(rows))//3][5], rows[-1][5]]
fig, ax = plt.subplots(len(pick), 1, figsize=(10, 2.4*len(pick)))
for a, t in zip(ax, pick):
    s = field(t, 'schlieren')
    img = [s[j*nx:(j + 1)*nx] for j in range(ny)]
    a.imshow(img, origin='lower', extent=(0, 1, 0, 0.2), cmap='gray',
             vmin=0, vmax=1)
    x = cloudVectors(t, 'positions')
    a.plot([p[0] for p in x], [p[1] for p in x], '.', ms=1.5, color='tab:red')
    a.set_title(f't = {t}')
    a.set_xlim(0, 1); a.set_ylim(0, 0.2)
fig.tight_layout()
fig.savefig('liftingCylinder_schlieren.png', dpi=110)
