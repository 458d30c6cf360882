#!/usr/bin/python3
"""Compare two clouds (ascii) particle by particle (matched by id):
prints 'field: max |diff| / max |value|' for U, F and fContact."""
import re, sys
import numpy as np
def body(path):
    s = open(path).read()
    return s[s.index('}') + 1:]
def vecs(path):
    return np.array([[float(x) for x in n.split()]
                     for n in re.findall(r'\(([^()]*)\)', body(path).split('(', 1)[1])])
def labels(path):
    m = re.search(r'\n(\d+)\s*\n\(([^)]*)\)', body(path))
    return np.array([int(x) for x in m.group(2).split()])
a, b = sys.argv[1], sys.argv[2]
ia, ib = np.argsort(labels(a + '/id')), np.argsort(labels(b + '/id'))
worst = 0
for f in ['U', 'F', 'fContact']:
    x, y = vecs(f'{a}/{f}')[ia], vecs(f'{b}/{f}')[ib]
    r = np.abs(x - y).max()/max(np.abs(x).max(), 1e-300)
    worst = max(worst, r)
    print(f'{f}: {x.shape[0]} particles, max |diff|/max |value| = {r:.3e}')
print(f'largest relative difference {worst:.3e}')
