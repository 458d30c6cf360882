#!/usr/bin/python3
"""machDiamond3D's koalas and table: python3 summary.py CASE

Each koala's particles are told apart by their mass (the densities go
1 : 4 : 9, the particles' volumes are equal).  For every written time,
machDiamond3D_koalas.dat gets each koala's mass still in the box, its
centre's height and its mean vertical velocity; machDiamond3D_koalas.png
draws height and velocity against time.  Printed (Allrun writes it to
machDiamond3D_summary.dat): lattice, ranks, particles, coupled steps,
halved steps, wall time, fragments and strays at the last written time
(machDiamond3D_solid.dat, plotCsmpm.py), each koala's rise (end - start
height) and vertical velocity at the end, and the energy audit's total
(where the step's energy went, relative to the starting energy).
"""
import os, re, sys
import numpy as np
sys.path.insert(0, os.path.join(os.environ['MPMFOAM_DIR'], 'bin', 'tools'))
from csmpmCase import NUM as num, cloudField, lastFragments, runFacts
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

case = sys.argv[1]
names = ('light', 'middle', 'heavy')
times = sorted((d for d in os.listdir(case)
                if re.fullmatch(num, d)
                and os.path.exists(f'{case}/{d}/lagrangian/mpmCloud/mass')),
               key=float)
m0 = cloudField(case, times[0], 'mass')
levels = np.unique(np.round(m0/m0.min(), 6))
if len(levels) != 3:
    sys.exit(f'summary.py: expected three particle masses (the koalas), '
             f'found {len(levels)} in {case}/{times[0]}')
rows = []
for t in times:
    m = cloudField(case, t, 'mass')
    x = cloudField(case, t, 'positions')
    U = cloudField(case, t, 'U')
    kind = np.searchsorted(levels, np.round(m/m0.min(), 6))
    row = [float(t)]
    for k in range(3):
        s = kind == k
        M = m[s].sum()
        row += [M, (m[s]*x[s, 1]).sum()/M if M > 0 else np.nan,
                (m[s]*U[s, 1]).sum()/M if M > 0 else np.nan]
    rows.append(row)
rows = np.array(rows)
with open('machDiamond3D_koalas.dat', 'w') as f:
    f.write('# t ' + ' '.join(f'{k}_mass {k}_y {k}_Uy' for k in names) + '\n')
    for r in rows:
        f.write(' '.join('%.8g' % v for v in r) + '\n')

fig, ax = plt.subplots(1, 2, figsize=(9, 3.4))
for k, name in enumerate(names):
    ax[0].plot(rows[:, 0], rows[:, 2 + 3*k], 'o-', ms=3, label=f'{name} ({[1, 4, 9][k]})')
    ax[1].plot(rows[:, 0], rows[:, 3 + 3*k], 'o-', ms=3, label=name)
ax[0].set_xlabel('t'); ax[0].set_ylabel('centre height y')
ax[1].set_xlabel('t'); ax[1].set_ylabel('mean vertical velocity')
ax[1].axhline(0, color='0.6', lw=0.8)
ax[0].legend(title='koala (density)', fontsize=8)
fig.tight_layout()
fig.savefig('machDiamond3D_koalas.png', dpi=110)

nx, ny = open(f'{case}/caseInfo').read().split()[:2]
r = runFacts(case)
frag, strays = lastFragments('machDiamond3D_solid.dat')
print('# nx ny ranks particles steps halved wall_s fragments strays '
      + ' '.join(f'{k}_rise {k}_Uy' for k in names) + ' energy_total')
print(f'{nx} {ny} {r["ranks"]} {len(m0)} {r["steps"]} {r["halved"]} {r["wall"]} '
      f'{frag} {strays} '
      + ' '.join('%.4g %.4g' % (rows[-1, 2 + 3*k] - rows[0, 2 + 3*k],
                                rows[-1, 3 + 3*k]) for k in range(3))
      + f' {r["energy"]}')
