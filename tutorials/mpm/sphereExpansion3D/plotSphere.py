#!/usr/bin/python3
"""sphereExpansion3D: the contact force magnitude of the particles at six
stages (dissertation Fig. 2.25: t = 0, 0.004, 0.006, 0.012, 0.016 s and the
end), the kinetic and strain energy against time, and the checks: the
largest distance of a particle from the centre at the written times
(below the radius 0.5 m: no particle left the sphere), the kinetic energy
at the end against the initial strain energy (taken as the total energy
of the first step: the release turns strain into kinetic energy)."""
import glob
import os
import re
import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

def field(path):
    s = open(path).read()
    s = s[s.index('}') + 1:]
    m = re.search(r'(\d+)\s*\{\s*\(([^()]*)\)\s*\}', s)
    if m:   # a uniform list: N{(x y z)}
        return np.tile([float(x) for x in m.group(2).split()], (int(m.group(1)), 1))
    rows = re.findall(r'\(([^()]*)\)', s.split('(', 1)[1])
    return np.array([[float(x) for x in r.split()] for r in rows])

def positions(path):
    s = open(path).read()
    s = s[s.index('}') + 1:]
    return np.array([[float(x) for x in m.split()]
                     for m in re.findall(r'\(([^()]*)\)\s*-?\d+', s)])

times = sorted((d for d in os.listdir('.')
                if re.fullmatch(r'[0-9.e+-]+', d)
                and os.path.isdir(f'{d}/lagrangian/mpmCloud')), key=float)
rmax = 0.0
for t in times:
    x = positions(f'{t}/lagrangian/mpmCloud/positions')
    rmax = max(rmax, np.sqrt((x**2).sum(axis=1)).max())
print(f"largest particle distance from the centre over {len(times)} written "
      f"times: {rmax:.4f} m (radius 0.5 m)")

rows = []
for f in sorted(glob.glob('postProcessing/conservation/*/conservation.dat'),
                key=lambda p: float(p.split('/')[2])):
    rows.append(np.loadtxt(f))
c = np.vstack(rows)
c = c[np.argsort(c[:, 0], kind='stable')]
t, K, S = c[:, 0], c[:, 11], c[:, 12]
E0 = K[0] + S[0]
print(f"initial strain energy (total of the first step) {E0:.6g} J; at "
      f"t = {t[-1]:g} s kinetic {K[-1]:.4g} J = {K[-1]/E0*100:.3e} % of it, "
      f"strain {S[-1]:.4g} J; largest total energy {np.max(K + S):.6g} J")

fig, ax = plt.subplots(figsize=(7, 4))
ax.semilogy(t, K, label='kinetic')
ax.semilogy(t, S, label='strain')
ax.set_xlabel('t [s]')
ax.set_ylabel('energy [J]')
ax.set_title('sphereExpansion3D: energies')
ax.legend()
fig.tight_layout()
fig.savefig('energies.png', dpi=100)

stages = [s for s in ['0', '0.004', '0.006', '0.012', '0.016'] if s in times]
stages.append(times[-1])
fig = plt.figure(figsize=(12, 8))
fmax = 0
data = []
for s in stages:
    x = positions(f'{s}/lagrangian/mpmCloud/positions')
    fc = f'{s}/lagrangian/mpmCloud/fContact'
    fm = np.sqrt((field(fc)**2).sum(axis=1)) if os.path.exists(fc) else np.zeros(len(x))
    fmax = max(fmax, fm.max())
    data.append((s, x, fm))
for k, (s, x, fm) in enumerate(data):
    a = fig.add_subplot(2, 3, k + 1, projection='3d')
    sc = a.scatter(x[:, 0], x[:, 1], x[:, 2], c=fm, s=2, cmap='jet',
                   vmin=0, vmax=fmax if fmax > 0 else 1)
    a.set_xlim(-0.5, 0.5); a.set_ylim(-0.5, 0.5); a.set_zlim(-0.5, 0.5)
    a.set_title(f't = {float(s):g} s, max {fm.max():.3g} N')
    a.set_xticks([]); a.set_yticks([]); a.set_zticks([])
fig.colorbar(sc, ax=fig.axes, shrink=0.6, label='contact force magnitude [N]')
fig.savefig('sphereExpansion3D.png', dpi=90)
for s, x, fm in data:
    print(f"t = {float(s):g} s: {np.count_nonzero(fm)} particles in contact, "
          f"largest contact force {fm.max():.4g} N")
