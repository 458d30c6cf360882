#!/usr/bin/python3
"""sphereExpansion3D: the contact force magnitude of the particles at six
stages (dissertation Fig. 2.25: t = 0, 0.004, 0.006, 0.012, 0.016 s and the
end), the kinetic and strain energy and the friction work against time,
the energy budget (what friction took against what the rest of the
discretisation did; the friction work from log.umlsMpmFoam), and the
checks: the
largest distance of a particle from the centre at the written times
(below the radius 0.5 m: no particle left the sphere), the kinetic energy
at the end against the initial strain energy (sum of V0 psi of the
cloud at t = 0)."""
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

def scalars(path):
    s = open(path).read()
    s = s[s.index('}') + 1:]
    m = re.search(r'(\d+)\s*\{\s*([^{}()\s]+)\s*\}', s)
    if m:   # a uniform list: N{v}
        return np.full(int(m.group(1)), float(m.group(2)))
    body = s.split('(', 1)[1].rsplit(')', 1)[0]
    return np.array([float(v) for v in body.split()])

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
E0 = float(np.sum(scalars('0/lagrangian/mpmCloud/V0')
                  *scalars('0/lagrangian/mpmCloud/psi')))
E1 = K[0] + S[0]
print(f"initial strain energy (sum of V0 psi at t = 0) {E0:.6g} J; the first "
      f"step's total {E1:.6g} J; at t = {t[-1]:g} s kinetic {K[-1]:.4g} J = "
      f"{K[-1]/E0*100:.3e} % of it, strain {S[-1]:.4g} J; largest total "
      f"energy {np.max(K + S):.6g} J")

# The friction work (the contact's "friction work" of the logged steps,
# each run's total added to the next run's: a restart starts from 0)
tw, W = [], []
offset, last = 0.0, 0.0
for line in open('log.umlsMpmFoam'):
    if line.startswith('Starting time loop'):
        offset += last
        last = 0.0
    m = re.search(r'^Step \d+\s+t = (\S+).*friction work = (\S+)', line)
    if m:
        last = float(m.group(2))
        tw.append(float(m.group(1)))
        W.append(offset + last)
    m = re.search(r'^Contact: friction work (\S+) J', line)
    if m:
        last = float(m.group(1))
Wend = offset + last
# Before the first contact: the logged steps with nobody within dHat
tFirst = None
for line in open('log.umlsMpmFoam'):
    m = re.search(r'^Step \d+\s+t = (\S+).*within dHat = (\d+)', line)
    if m and int(m.group(2)) > 0:
        tFirst = float(m.group(1))
        break
E = K + S
print(f"friction work {Wend:.4g} J = {Wend/E0*100:.3g} % of the initial "
      f"strain energy; the energy lost otherwise (E0 - K - S - friction) "
      f"{E0 - E[-1] - Wend:.6g} J = {(E0 - E[-1] - Wend)/E0*100:.4g} %")
if tFirst is not None:
    k = max(np.searchsorted(t, tFirst) - 1, 0)
    print(f"before the first contact (t < {tFirst:.3g} s, no particle within "
          f"dHat): K + S fell to {E[k]/E0*100:.4g} % of E0 at t = {t[k]:.3g} s")
for T in [0.002, 0.005, 0.01, 0.02]:
    k = min(np.searchsorted(t, T), len(t) - 1)
    j = np.searchsorted(tw, T) - 1
    print(f"t = {t[k]:.3g} s: K + S = {E[k]/E0*100:.4g} % of E0, friction "
          f"work so far {W[j] if j >= 0 else 0:.4g} J")

fig, axes = plt.subplots(1, 2, figsize=(12, 4.5))
for ax, tEnd in zip(axes, [0.03, t[-1]]):
    ax.semilogy(t, K, label='kinetic')
    ax.semilogy(t, S, label='strain')
    ax.semilogy(t, np.maximum(E0 - E, 1e-3),
                label='lost: E0 - kinetic - strain')
    if W:
        ax.semilogy(tw, np.maximum(W, 1e-3), label='friction work')
    ax.axhline(E0, color='k', lw=0.5, ls='--', label='E0 (sum V0 psi at t = 0)')
    ax.set_xlim(0, tEnd)
    ax.set_ylim(1e-3, 2*E0)
    ax.set_xlabel('t [s]')
    ax.set_ylabel('energy [J]')
axes[0].set_title('sphereExpansion3D: energies, the impacts')
axes[1].set_title('to the end')
axes[0].legend(fontsize=8)
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
    sc = a.scatter(x[:, 0], x[:, 1], x[:, 2], c=fm, s=2 + 25*(fm > 0), cmap='jet',
                   vmin=0, vmax=fmax if fmax > 0 else 1)
    a.set_xlim(-0.5, 0.5); a.set_ylim(-0.5, 0.5); a.set_zlim(-0.5, 0.5)
    a.set_title(f't = {float(s):g} s, max {fm.max():.3g} N')
    a.set_xticks([]); a.set_yticks([]); a.set_zticks([])
fig.colorbar(sc, ax=fig.axes, shrink=0.6, label='contact force magnitude [N]')
fig.savefig('sphereExpansion3D.png', dpi=90)
for s, x, fm in data:
    print(f"t = {float(s):g} s: {np.count_nonzero(fm)} particles in contact, "
          f"largest contact force {fm.max():.4g} N")
