#!/usr/bin/python3
"""The rolled-out cloud of bsmsFoam against bsmsTrain's final_<case>.dat.

Usage: cloudVsFinal.py <time>/lagrangian/mpmCloud final_<case>.dat
Prints: the cloud's points, the largest difference of its x from the
rollout's columns of final_<case>.dat (the material points in the order of
their id), the largest from the recording's columns [m].
"""
import re
import struct
import sys


def field(path, width, code):
    """The values of an IOField (ascii or binary), width numbers each."""
    raw = open(path, 'rb').read()
    head = raw.index(b'FoamFile')
    end = raw.index(b'}', head)
    binary = b'binary' in raw[head:end]
    m = re.compile(rb'\s(\d+)\s*\(').search(raw, end + 1)
    n, start = int(m.group(1)), m.end()
    if binary:
        size = struct.calcsize('<' + code)
        flat = struct.unpack('<%d%s' % (n*width, code), raw[start:start + n*width*size])
    else:
        text = raw[start:].decode()
        flat = [float(t) if code == 'd' else int(t)
                for t in re.findall(r'[-+0-9.eE]+', text)[:n*width]]
    return [tuple(flat[i*width:(i + 1)*width]) for i in range(n)]


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
