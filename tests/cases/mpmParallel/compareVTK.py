#!/usr/bin/python3
"""Compare two foamToVTK particle files (.vtp, -ascii) matched by id.

Usage: compareVTK.py <a.vtp> <b.vtp>

Prints: <max relative difference> <particles> <arrays compared> <worst>
Every point array (and Points) but origId/origProcId (OpenFOAM's own
counters, which depend on the process) is compared; the difference is
relative to the array's largest magnitude.  foamToVTK writes Float32, so
equal doubles give equal text and doubles that differ in the 13th digit
may differ by one unit of the 7th.  Exit status 2 if the particle sets
differ.
"""
import sys
import xml.etree.ElementTree as ET


def arrays(path):
    root = ET.parse(path).getroot()
    piece = root.find('.//Piece')
    out = {}
    pts = piece.find('Points/DataArray')
    out['Points'] = (3, [float(x) for x in pts.text.split()])
    for da in piece.findall('PointData/DataArray'):
        nc = int(da.get('NumberOfComponents', '1'))
        out[da.get('Name')] = (nc, [float(x) for x in da.text.split()])
    return out


a, b = arrays(sys.argv[1]), arrays(sys.argv[2])
ida = [int(x) for x in a['id'][1]]
idb = [int(x) for x in b['id'][1]]
if sorted(ida) != sorted(idb) or set(a) != set(b):
    print('inf %d 0 particles-or-arrays' % len(ida))
    sys.exit(2)
pos = {i: k for k, i in enumerate(idb)}
worst, name = 0.0, '-'
n = 0
for key, (nc, va) in a.items():
    if key in ('origId', 'origProcId'):
        continue
    vb = b[key][1]
    scale = max((abs(x) for x in va), default=0.0) or 1.0
    d = 0.0
    for k, i in enumerate(ida):
        kb = pos[i]
        for c in range(nc):
            d = max(d, abs(va[nc*k + c] - vb[nc*kb + c]))
    n += 1
    if d/scale >= worst:
        worst, name = d/scale, key
print('%.3e %d %d %s' % (worst, len(ida), n, name))
