#!/usr/bin/python3
"""Initial state of the conservation cases on the 40 x 40 unit square:
a density wave, a uniform drift and a pressure pulse (a weak blast), so
every conserved variable has fluxes through every face.

    initialState.py <case> periodic|walls|open
(open: patches of type patch, the gas drifting out through them)
"""
import math
import sys

case, kind = sys.argv[1], sys.argv[2]
import os
os.makedirs(case + "/0", exist_ok=True)
n = 40
patch = "cyclic" if kind == "periodic" else "zeroGradient"
walls = kind == "walls"


def write(name, cls, dims, values, vector=False):
    bf = "".join("    %s { type %s; }\n" % (p, patch if not (walls and vector)
                 else "slip") for p in ("left", "right", "bottom", "top"))
    open("%s/0/%s" % (case, name), "w").write(
        "FoamFile { version 2.0; format ascii; class %s; object %s; }\n"
        "dimensions %s;\ninternalField nonuniform List<%s>\n%d\n(\n%s\n);\n"
        "boundaryField\n{\n%s    frontAndBack { type empty; }\n}\n"
        % (cls, name, dims, "vector" if vector else "scalar", len(values),
           "\n".join(values), bf))


rho, U, p = [], [], []
for j in range(n):
    for i in range(n):
        x, y = (i + 0.5) / n, (j + 0.5) / n
        r2 = (x - 0.4) ** 2 + (y - 0.6) ** 2
        rho.append("%.17g" % (1 + 0.2 * math.sin(2 * math.pi * x)
                              * math.sin(2 * math.pi * y)))
        U.append("(%.17g %.17g 0)" % ((0.0, 0.0) if walls else (0.3, 0.2)))
        p.append("%.17g" % (1 + 2.0 * math.exp(-r2 / 0.005)))
write("rho", "volScalarField", "[1 -3 0 0 0 0 0]", rho)
write("U", "volVectorField", "[0 1 -1 0 0 0 0]", U, vector=True)
write("p", "volScalarField", "[1 -1 -2 0 0 0 0]", p)
