#!/usr/bin/python3
"""pumpkin3D's table: python3 summary.py RUNDIR pumpkin...

Per pumpkin (RUNDIR/<pumpkin>, and pumpkin3D_<pumpkin>_solid.dat that
plotCsmpm.py wrote): lattice, ranks, particles, coupled steps, wall time,
fragments and strays at the last written time, the particles' plastic
strain there (epsilonP: mean, largest, the share of particles above 1e-3;
0 for an elastic material), the shape (the particles' mean distance from
the pumpkin's centre and its spread over the particles, at 0 and at the
end), and the energy audit's total (where the step's energy went,
relative to the starting energy).
"""
import os, re, sys
import numpy as np
sys.path.insert(0, os.path.join(os.environ['MPMFOAM_DIR'], 'bin', 'tools'))
from csmpmCase import NUM as num, cloudField, lastFragments, runFacts

centre = np.array([0.5, 0.5, 0.45])


def field(case, t, name):
    """A cloud field (N x 3 or N), None if not written"""
    if not os.path.exists(f'{case}/{t}/lagrangian/mpmCloud/{name}'):
        return None
    return cloudField(case, t, name)


def shape(case, t):
    r = np.linalg.norm(field(case, t, 'positions') - centre, axis=1)
    return r.mean(), r.std()


run = sys.argv[1]
print('# pumpkin n ranks particles steps wall_s fragments strays '
      'epsP_mean epsP_max yielded_share r_mean0 r_std0 r_mean r_std '
      'energy_total')
for p in sys.argv[2:]:
    case = f'{run}/{p}'
    n = int(open(f'{case}/caseInfo').read().split()[0])
    r = runFacts(case)
    times = sorted((d for d in os.listdir(case)
                    if re.fullmatch(num, d)
                    and os.path.isdir(f'{case}/{d}/lagrangian')), key=float)
    last = times[-1]
    frag, strays = lastFragments(f'pumpkin3D_{p}_solid.dat')
    eps = field(case, last, 'epsilonP')
    if eps is None:
        eps = np.zeros(1)
    r0 = shape(case, times[0])
    r1 = shape(case, last)
    nPart = len(field(case, last, 'mass'))
    print(f'{p} {n} {r["ranks"]} {nPart} {r["steps"]} {r["wall"]} {frag} {strays} '
          f'{eps.mean():.4g} {eps.max():.4g} {(eps > 1e-3).mean():.4g} '
          f'{r0[0]:.5f} {r0[1]:.5f} {r1[0]:.5f} {r1[1]:.5f} {r["energy"]}')
