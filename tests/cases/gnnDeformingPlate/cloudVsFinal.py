#!/usr/bin/python3
"""The rolled-out cloud of bsmsFoam against bsmsTrain's final_<case>.dat.

Usage: cloudVsFinal.py <time>/lagrangian/mpmCloud final_<case>.dat
Prints: the cloud's points, the largest difference of its x from the
rollout's columns of final_<case>.dat (the material points in the order of
their id), the largest from the recording's columns [m].
"""
import os
import sys

sys.path.insert(0, os.path.join(os.environ['MPMFOAM_DIR'], 'bin', 'tools'))
from cloudError import field  # noqa: E402


cloud, final = sys.argv[1], sys.argv[2]
x = field(cloud + '/x', 3, 'd')
ids = [i[0] for i in field(cloud + '/id', 1, 'i')]
ref = [tuple(map(float, l.split())) for l in open(final) if not l.startswith('#')]
if len(x) != len(ids) or len(x) != len(ref) or not x:
    print(len(x), 'nan', 'nan')
    sys.exit(0)
order = sorted(range(len(ids)), key=lambda i: ids[i])
dModel = max(abs(x[i][d] - ref[j][d]) for j, i in enumerate(order) for d in range(3))
dTruth = max(abs(x[i][d] - ref[j][3 + d]) for j, i in enumerate(order) for d in range(3))
print(len(x), '%.3e' % dModel, '%.3e' % dTruth)
