#!/usr/bin/python3
"""Check the world and mesh edges of a bsmsLevels level-0 VTK file of a
Lagrangian graph against brute force.

Usage: vtkEdges.py <level0.vtk> <worldRadius>

Prints one line:
    <world edges> <brute-force world pairs> <missing> <extra>
    <mesh edges among material points>
World pairs by brute force: every actuator node (kind 1) and material
point (kind 0 or 2) closer than the radius, from the VTK's positions.
"""
import math
import sys


def read(path):
    lines = open(path).read().split('\n')
    k = 0
    pts, lines_, kinds, types = [], [], [], []
    while k < len(lines):
        w = lines[k].split()
        if w and w[0] == 'POINTS':
            n = int(w[1])
            pts = [tuple(map(float, lines[k + 1 + i].split())) for i in range(n)]
            k += n
        elif w and w[0] == 'LINES':
            m = int(w[1])
            lines_ = [tuple(map(int, lines[k + 1 + i].split()[1:])) for i in range(m)]
            k += m
        elif w and w[0] == 'SCALARS' and w[1] == 'edgeType':
            nCells = len(pts) + len(lines_)
            types = [int(lines[k + 2 + i]) for i in range(nCells)]
            k += nCells + 1
        elif w and w[0] == 'SCALARS' and w[1] == 'kind':
            kinds = [int(lines[k + 2 + i]) for i in range(len(pts))]
            k += len(pts) + 1
        k += 1
    return pts, lines_, types[len(pts):], kinds


pts, edges, types, kinds = read(sys.argv[1])
r = float(sys.argv[2])
world = {tuple(sorted(e)) for e, t in zip(edges, types) if t == 2}
act = [i for i, c in enumerate(kinds) if c == 1]
mat = [i for i, c in enumerate(kinds) if c != 1]
brute = set()
for i in act:
    xi = pts[i]
    for j in mat:
        if math.dist(xi, pts[j]) < r:
            brute.add(tuple(sorted((i, j))))
meshMat = sum(1 for e, t in zip(edges, types)
              if t == 1 and kinds[e[0]] != 1 and kinds[e[1]] != 1)
print(len(world), len(brute), len(brute - world), len(world - brute), meshMat)
