#!/usr/bin/python3
"""Largest relative change of the totals a volFieldValue function object
(volIntegrate of rho, rhoU, rhoE) wrote, over all steps:

    totalsDrift.py <file.dat>
prints  mass <d>  momentum <d>  energy <d>  steps <n>
with d = max_t |Q(t) - Q(0)| / |Q(0)| (momentum: the vector norm of the
change over the norm of the initial momentum, or over the initial mass
times the largest initial speed if that is zero)."""
import math
import sys

rows = []
for line in open(sys.argv[1]):
    if line.startswith("#"):
        continue
    rows.append([float(v) for v in line.replace("(", " ").replace(")", " ").split()])
r0 = rows[0]
m0, p0, e0 = r0[1], r0[2:5], r0[5]
pn = math.sqrt(sum(v * v for v in p0)) or abs(m0)
dm = max(abs(r[1] - m0) for r in rows) / abs(m0)
dp = max(math.sqrt(sum((a - b) ** 2 for a, b in zip(r[2:5], p0))) for r in rows) / pn
de = max(abs(r[5] - e0) for r in rows) / abs(e0)
print("mass %.3e momentum %.3e energy %.3e steps %d" % (dm, dp, de, len(rows) - 1))
