#!/usr/bin/python3
# compareFields.py <dirA> <dirB> [skip ...]: compares every field file both
# time directories hold (internalField and boundaryField values), except the
# names given after the directories.  Values below 1e-300 in magnitude count
# as 0: OpenFOAM's scalar reading (decomposePar, reconstructPar, a restart)
# rounds such underflows to zero, so a reconstructed field has 0 where the
# processor file holds e.g. 8e-302.
# Prints "<maxRel> <maxScaled> <nValues> <nFiles> <worstFile>": maxRel the
# largest |a - b|/max(|a|, |b|) value by value, maxScaled the largest
# |a - b|/max|a| of a file.  Comparing no file at all is an error (exit 1,
# "inf inf 0 0 (none)"): a check must not pass on nothing.
import os, re, sys

num = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")

def values(path):
    body = open(path).read().split("FoamFile", 1)[-1]
    body = body.split("}", 1)[1] if "}" in body else body
    v = [float(x) for x in num.findall(body)]
    return [0.0 if abs(x) < 1e-300 else x for x in v]

a, b, skip = sys.argv[1], sys.argv[2], set(sys.argv[3:])
worst, scaled, worstFile, n, files = 0.0, 0.0, "-", 0, 0
for name in sorted(os.listdir(a)):
    pa, pb = os.path.join(a, name), os.path.join(b, name)
    if name in skip or not os.path.isfile(pa) or not os.path.isfile(pb):
        continue
    va, vb = values(pa), values(pb)
    files += 1
    if len(va) != len(vb):
        print("inf inf 0 %d %s(length)" % (files, name))
        sys.exit(0)
    big = max([abs(x) for x in va] + [1e-300])
    for x, y in zip(va, vb):
        if x != y:
            d = abs(x - y)/max(abs(x), abs(y))
            if d > worst:
                worst, worstFile = d, name
            scaled = max(scaled, abs(x - y)/big)
    n += len(va)
if files == 0:
    print("inf inf 0 0 (none)")
    sys.stderr.write("compareFields.py: no field file in both %s and %s\n" % (a, b))
    sys.exit(1)
print("%.3e %.3e %d %d %s" % (worst, scaled, n, files, worstFile))
