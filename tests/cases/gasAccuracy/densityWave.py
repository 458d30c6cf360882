#!/usr/bin/python3
"""Periodic density wave on [0, 1]: rho = rho0 (1 + a sin(2 pi x)), uniform
u and p (an entropy wave; the exact solution is its translation).

    densityWave.py init <case> <N> <u> <p> <a>   write 0/rho, 0/U, 0/p
    densityWave.py error <case> <u> <a>   L1 and Linf error of rho at the
                                          latest time
"""
import math
import re
import sys


def centres(n):
    return [(i + 0.5) / n for i in range(n)]


def field(name, cls, dims, values, patches):
    head = ("FoamFile { version 2.0; format ascii; class %s; object %s; }\n"
            "dimensions %s;\n" % (cls, name, dims))
    body = "internalField nonuniform List<%s>\n%d\n(\n%s\n);\n" % (
        "scalar" if cls == "volScalarField" else "vector", len(values),
        "\n".join(values))
    bf = "boundaryField\n{\n" + "".join(
        "    %s { type %s; }\n" % p for p in patches) + "}\n"
    return head + body + bf


PATCHES = [("left", "cyclic"), ("right", "cyclic"), ("sides", "empty")]


def init(case, n, u, p, a):
    import os
    os.makedirs(case + "/0", exist_ok=True)
    x = centres(n)
    rho = ["%.17g" % (1 + a * math.sin(2 * math.pi * xi)) for xi in x]
    open(case + "/0/rho", "w").write(
        field("rho", "volScalarField", "[1 -3 0 0 0 0 0]", rho, PATCHES))
    open(case + "/0/U", "w").write(
        field("U", "volVectorField", "[0 1 -1 0 0 0 0]",
              ["(%.17g 0 0)" % u] * n, PATCHES))
    open(case + "/0/p", "w").write(
        field("p", "volScalarField", "[1 -1 -2 0 0 0 0]",
              ["%.17g" % p] * n, PATCHES))


def read(path):
    text = open(path).read()
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*\d+\s*\(([^)]*)\)",
                  text)
    return [float(v) for v in m.group(1).split()]


def latest(case):
    """The latest time directory and its exact time value"""
    import os
    times = []
    for d in os.listdir(case):
        try:
            times.append((float(d), d))
        except ValueError:
            pass
    name = max(times)[1]
    t = float(re.search(r"\bvalue\s+([^;]+);",
                        open("%s/%s/uniform/time" % (case, name)).read()).group(1))
    return name, t


def error(case, u, a):
    time, t = latest(case)
    rho = read("%s/%s/rho" % (case, time))
    n = len(rho)
    e = [abs(r - (1 + a * math.sin(2 * math.pi * (x - u * t))))
         for r, x in zip(rho, centres(n))]
    print("N %d L1 %.6e Linf %.6e" % (n, sum(e) / n, max(e)))


if __name__ == "__main__":
    if sys.argv[1] == "init":
        init(sys.argv[2], int(sys.argv[3]), float(sys.argv[4]),
             float(sys.argv[5]), float(sys.argv[6]))
    else:
        error(sys.argv[2], float(sys.argv[3]), float(sys.argv[4]))
