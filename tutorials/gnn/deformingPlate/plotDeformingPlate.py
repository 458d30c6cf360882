#!/usr/bin/python3
"""gnn/deformingPlate: pictures of the held-out rollouts (run by Allrun).

run/deformingPlate.png, left: the RMSE of the material points' positions
against rollout step for every held-out trajectory, BSMS-GNN (solid) and
the two trivial baselines, holding the state (dashed) and moving on at the
last velocity (dotted); for the first held-out one also bsmsFoam's pure
(black) and hybrid (magenta) rollouts.  Right: the first held-out trajectory at its last
frame, the plate's mid-section z = 0.15 m (material points within 6 mm of
it), rolled out (red) and recorded by umlsMpmFoam (black).
"""
import glob
import os
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

here = os.path.dirname(os.path.abspath(__file__))
post = os.path.join(here, 'run', 'bsms', 'postProcessing', 'bsmsTrain')


def rows(path):
    out = []
    for line in open(path):
        if line.startswith('#') or not line.strip():
            continue
        out.append([float(v) for v in line.split()])
    return out


fig, (ax, bx) = plt.subplots(1, 2, figsize=(13, 4.5))
files = sorted(glob.glob(os.path.join(post, 'rollout_*.dat')))
for k, f in enumerate(files):
    name = os.path.basename(f)[len('rollout_'):-len('.dat')]
    r = rows(f)
    c = 'C%d' % k
    steps = [v[0] for v in r]
    ax.plot(steps, [1e3*v[1] for v in r], '-', color=c, label=name + ' BSMS-GNN')
    ax.plot(steps, [1e3*v[2] for v in r], '--', color=c, lw=0.8)
    ax.plot(steps, [1e3*v[3] for v in r], ':', color=c, lw=0.8)
# bsmsFoam's pure and hybrid rollouts of the first held-out case
# (Allrun: cloudError.py's error.dat, time and RMSE per frame)
for run, style in (('bsmsFoam', 'k-'), ('bsmsHybrid', 'm-')):
    f = os.path.join(here, 'run', run, 'error.dat')
    if os.path.isfile(f):
        r = rows(f)
        t0 = r[0][0] - 0.01
        ax.plot([round((v[0] - t0)/0.01) for v in r], [1e3*v[1] for v in r],
                style, lw=2 if run == 'bsmsHybrid' else 1,
                label=run + (' (hybrid)' if run == 'bsmsHybrid' else ' (pure)'))
ax.set_xlabel('rollout step (0.01 s each)')
ax.set_ylabel('RMSE of positions [mm]')
ax.set_title('held-out rollouts: BSMS-GNN (solid), hold (dashed), velocity (dotted)')
ax.legend(fontsize=7)

finals = sorted(glob.glob(os.path.join(post, 'final_*.dat')))
if finals:
    p = rows(finals[0])
    sel = [v for v in p if abs(v[5] - 0.15) < 0.006]
    bx.scatter([v[3] for v in sel], [v[4] for v in sel], s=6, c='k', label='umlsMpmFoam')
    bx.scatter([v[0] for v in sel], [v[1] for v in sel], s=6, c='r', marker='x',
               label='BSMS-GNN rollout')
    bx.set_aspect('equal')
    bx.set_xlabel('x [m]')
    bx.set_ylabel('y [m]')
    bx.set_title(os.path.basename(finals[0])[len('final_'):-len('.dat')]
                 + ': last frame, section z = 0.15 m')
    bx.legend(fontsize=8)
out = os.path.join(here, 'run', 'deformingPlate.png')
fig.tight_layout()
fig.savefig(out, dpi=90)
print('Wrote', out)
