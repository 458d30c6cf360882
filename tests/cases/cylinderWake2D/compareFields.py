#!/usr/bin/python3
"""Largest difference between two ASCII OpenFOAM volVectorField (or
volScalarField) files' internal fields, relative to the largest magnitude
in the first.  Prints: <relative difference> <cells>"""
import sys


def internalField(path):
    with open(path) as f:
        text = f.read()
    i = text.index("internalField")
    rest = text[i:]
    if rest.split(None, 2)[1] == "uniform":
        raise SystemExit(f"{path}: uniform internalField")
    # nonuniform List<type> N ( ... )
    start = rest.index("(")
    n = int(rest[:start].split()[-1])
    body = rest[start + 1:]
    values = []
    if body.lstrip().startswith("("):
        pos = 0
        for _ in range(n):
            a = body.index("(", pos)
            b = body.index(")", a)
            values.append([float(x) for x in body[a + 1:b].split()])
            pos = b + 1
    else:
        values = [[float(x)] for x in body.split(")")[0].split()[:n]]
    if len(values) != n:
        raise SystemExit(f"{path}: read {len(values)} of {n} values")
    return values


a = internalField(sys.argv[1])
b = internalField(sys.argv[2])
if len(a) != len(b):
    raise SystemExit(f"different sizes {len(a)} and {len(b)}")
scale = max(sum(x * x for x in v) ** 0.5 for v in a)
diff = max(sum((x - y) ** 2 for x, y in zip(u, v)) ** 0.5 for u, v in zip(a, b))
print(f"{diff / scale:.3e} {len(a)}")
