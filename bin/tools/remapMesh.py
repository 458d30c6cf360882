#!/usr/bin/python3
"""remapMesh.py: move a blockMesh's vertex planes along one axis to make a
graded or an irregular mesh of the same topology (for convergence studies
on the mesh families of a 1D bar or a block).

  remapMesh.py [-case DIR] -family uniform|graded|irregular [-axis x|y|z]
               [-knots 'X0 X1 ...'] [-ratio 'R ...'] [-jitter J] [-seed S]

The distinct coordinates of the points along the axis are the vertex
planes.  Between consecutive knots (default: the first and the last
plane; every knot must be a plane) the planes are moved, the knots stay:

  uniform    nothing moves
  graded     geometric cell sizes, the last R times the first (default 4:
             the smallest at the interval's start; R < 1 puts it at the
             end; 1 leaves the interval uniform); one R for every
             interval, or one per interval
  irregular  each plane moved by a uniform random share in [-J, J] of the
             interval's cell size (default J 0.3: cells between 0.4 and
             1.6 of it); reproducible from the seed

Writes constant/polyMesh/points in place and prints the smallest and the
largest cell size along the axis.
"""
import argparse
import random
import re
import sys

AXES = {"x": 0, "y": 1, "z": 2}
NUMBER = r"[-+0-9.eE]+"


def readPoints(path):
    text = open(path).read()
    m = re.search(r"\n(\d+)\s*\n\(\s*\n", text)
    if m is None:
        sys.exit("remapMesh.py: %s: no point list found" % path)
    n = int(m.group(1))
    start = m.end()
    tri = re.compile(r"\((%s) (%s) (%s)\)" % (NUMBER, NUMBER, NUMBER))
    pts = []
    pos = start
    for _ in range(n):
        mm = tri.search(text, pos)
        if mm is None:
            sys.exit("remapMesh.py: %s: %d points expected, found %d"
                     % (path, n, len(pts)))
        pts.append([float(mm.group(k)) for k in (1, 2, 3)])
        pos = mm.end()
    end = text.index(")", pos)      # the list's own closing bracket
    return text[:m.start()], pts, text[end + 1:]


def writePoints(path, head, pts, tail):
    with open(path, "w") as f:
        f.write(head)
        f.write("\n%d\n(\n" % len(pts))
        for p in pts:
            f.write("(%.17g %.17g %.17g)\n" % tuple(p))
        f.write(")\n")
        f.write(tail)


def newPlanes(planes, knots, family, ratios, jitter, rng):
    out = dict((x, x) for x in planes)
    for (a, b), ratio in zip(zip(knots[:-1], knots[1:]), ratios):
        inside = [x for x in planes if a <= x <= b]
        m = len(inside) - 1
        if m < 1:
            continue
        if family == "graded" and m > 1:
            q = ratio ** (1.0 / (m - 1))
            total = sum(q ** i for i in range(m))
            s = 0.0
            for i, x in enumerate(inside[1:-1], start=1):
                s += q ** (i - 1)
                out[x] = a + (b - a) * s / total
        elif family == "irregular":
            h = (b - a) / m
            for i, x in enumerate(inside[1:-1], start=1):
                out[x] = a + i * h + rng.uniform(-jitter, jitter) * h
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("-case", default=".")
    ap.add_argument("-family", required=True,
                    choices=("uniform", "graded", "irregular"))
    ap.add_argument("-axis", default="x", choices=sorted(AXES))
    ap.add_argument("-knots", default=None)
    ap.add_argument("-ratio", default="4")
    ap.add_argument("-jitter", type=float, default=0.3)
    ap.add_argument("-seed", type=int, default=1)
    a = ap.parse_args()
    if not 0 <= a.jitter < 0.5:
        sys.exit("remapMesh.py: -jitter %g: in [0, 0.5) (planes must keep "
                 "their order)" % a.jitter)
    path = a.case + "/constant/polyMesh/points"
    head, pts, tail = readPoints(path)
    k = AXES[a.axis]
    tol = 1e-9 * (max(p[k] for p in pts) - min(p[k] for p in pts))
    planes = []
    for x in sorted(p[k] for p in pts):
        if not planes or x - planes[-1] > tol:
            planes.append(x)

    def plane(x):
        best = min(planes, key=lambda y: abs(y - x))
        if abs(best - x) > tol:
            return None
        return best
    knots = [planes[0], planes[-1]]
    if a.knots:
        knots = []
        for t in a.knots.split():
            y = plane(float(t))
            if y is None:
                sys.exit("remapMesh.py: -knots: %s is not a vertex plane "
                         "along %s (the mesh must have one there)"
                         % (t, a.axis))
            knots.append(y)
        knots = sorted(set(knots) | {planes[0], planes[-1]})
    try:
        ratios = [float(r) for r in a.ratio.split()]
    except ValueError:
        ratios = []
    if len(ratios) == 1:
        ratios *= len(knots) - 1
    if len(ratios) != len(knots) - 1 or not all(r > 0 for r in ratios):
        sys.exit("remapMesh.py: -ratio '%s': one positive number, or one "
                 "per interval (%d)" % (a.ratio, len(knots) - 1))
    rng = random.Random(a.seed)
    moved = newPlanes(planes, knots, a.family, ratios, a.jitter, rng)
    for p in pts:
        p[k] = moved[plane(p[k])]
    writePoints(path, head, pts, tail)
    xs = sorted(moved.values())
    sizes = [y - x for x, y in zip(xs[:-1], xs[1:])]
    print("remapMesh.py: %s along %s, %d planes: cell sizes %.6g to %.6g"
          % (a.family, a.axis, len(planes), min(sizes), max(sizes)))


if __name__ == "__main__":
    main()
