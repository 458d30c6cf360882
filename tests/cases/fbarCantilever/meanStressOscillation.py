#!/usr/bin/python3
# Particle-to-particle oscillation of the mean stress of an MPM cloud:
# the RMS over particles of p_i minus the mean p of its neighbours within
# radius r (in the x-y plane), and the RMS of p itself, p = tr(sigma)/3.
#
#   meanStressOscillation.py <time>/lagrangian/<cloud> <r>
import re
import sys


def readList(path):
    txt = open(path).read()
    m = re.search(r'\n(\d+)\n\(\n', txt)
    n = int(m.group(1))
    lines = txt[m.end():].split('\n')[:n]
    return [[float(v) for v in re.sub(r'[()]', ' ', l).split()] for l in lines]


cloud, r = sys.argv[1], float(sys.argv[2])
x = readList(cloud + '/positions')
s = readList(cloud + '/sigma')         # xx xy xz yy yz zz
p = [(a[0] + a[3] + a[5])/3 for a in s]
osc = 0.0
ref = 0.0
for i in range(len(x)):
    acc, n = 0.0, 0
    for j in range(len(x)):
        if j != i and (x[i][0] - x[j][0])**2 + (x[i][1] - x[j][1])**2 <= r*r:
            acc += p[j]
            n += 1
    if n:
        osc += (p[i] - acc/n)**2
    ref += p[i]**2
print("%.6g %.6g" % ((osc/len(x))**0.5, (ref/len(x))**0.5))
