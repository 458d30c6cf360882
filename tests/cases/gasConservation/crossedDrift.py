#!/usr/bin/python3
"""Largest relative change of the gas's totals plus what crossed the
patches, from shockMpmFoam's log: the "Initial totals" line, then every
step's "totals + crossed (step)" line:

    crossedDrift.py <log>
prints  mass <d>  momentum <d>  energy <d>  steps <n>  crossedMass <c>
with d = max_t |Q(t) - Q(0)| / |Q(0)| (momentum over the initial mass
times 1 m/s when the initial momentum is zero) and c the relative mass that
left by the end (so that a check knows something crossed)."""
import re
import sys

num = r"([-+0-9.eE]+)"
vec = r"\(([^)]*)\)"
pat = re.compile(r"mass " + num + ", momentum " + vec + ", energy " + num)
rows, first = [], None
for line in open(sys.argv[1]):
    if line.startswith("Initial totals:") or "totals + crossed (step):" in line:
        m = pat.search(line)
        if m:
            rows.append((float(m.group(1)),
                         [float(v) for v in m.group(2).split()],
                         float(m.group(3))))
if len(rows) < 2 or not rows[0]:
    print("mass inf momentum inf energy inf steps 0 crossedMass 0")
    sys.exit(1)
m0, p0, e0 = rows[0]
pn = sum(v * v for v in p0) ** 0.5 or abs(m0)
dm = max(abs(r[0] - m0) for r in rows) / abs(m0)
dp = max(sum((a - b) ** 2 for a, b in zip(r[1], p0)) ** 0.5 for r in rows) / pn
de = max(abs(r[2] - e0) for r in rows) / abs(e0)
# what left: the summary's "crossed the patches" mass
left = 0.0
for line in open(sys.argv[1]):
    if "crossed the patches" in line:
        left = float(re.search(r"mass " + num, line).group(1))
print("mass %.3e momentum %.3e energy %.3e steps %d crossedMass %.3e"
      % (dm, dp, de, len(rows) - 1, left / abs(m0)))
