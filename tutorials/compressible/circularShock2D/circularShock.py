#!/usr/bin/python3
"""circularShock2D: errors and pictures of a run of the circular shock on
the unit square with N x N cells (blockMesh's single block: cell i + N j
has its centre at ((i + 1/2)/N, (j + 1/2)/N)), against the radial
reference of radialReference.py (r rho u p) linearly interpolated at the
cell centres' radii r = |x - (0.5, 0.5)|.

Usage:
    circularShock.py error <case> <reference>
        one line for the latest time of <case>:
        "N n L1 a e338 b symDiag c symX d symY e" with
          a = sum |rho - rho_ref| dx dy   (L1 over the square)
          b = sum (rho - rho_ref)^2 / (sum rho_ref)^2   (the dissertation's
              (3.38), rho_b = the reference at the cell centres)
          c = max |rho(x, y) - rho(y, x)|      (diagonal mirror)
          d = max |rho(x, y) - rho(1 - x, y)|  (mirror in x = 1/2)
          e = max |rho(x, y) - rho(x, 1 - y)|  (mirror in y = 1/2)
    circularShock.py plot <out.png> <reference> <label>=<case> ...
        per run a row: the density image at the latest time and rho of
        every cell against r with the reference line
"""

import os
import re
import sys

import numpy as np

CENTRE = (0.5, 0.5)


def latestTime(case):
    times = []
    for d in os.listdir(case):
        try:
            times.append((float(d), d))
        except ValueError:
            pass
    if not times:
        sys.exit("circularShock.py: no time directory in %s" % case)
    return max(times)[1]


def readScalar(path):
    text = open(path).read()
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(",
                  text)
    if not m:
        sys.exit("circularShock.py: no nonuniform internalField in %s" % path)
    n = int(m.group(1))
    values = np.array(text[m.end():].split(None, n)[:n], dtype=float)
    if len(values) != n:
        sys.exit("circularShock.py: %s: %d values, expected %d"
                 % (path, len(values), n))
    return values


def density(case):
    """rho[j, i] at the latest time, the time's name and N"""
    time = latestTime(case)
    rho = readScalar(os.path.join(case, time, "rho"))
    n = int(round(np.sqrt(len(rho))))
    if n*n != len(rho):
        sys.exit("circularShock.py: %s: %d cells is not N x N"
                 % (case, len(rho)))
    return rho.reshape(n, n), time, n


def radii(n):
    c = (np.arange(n) + 0.5)/n
    x, y = np.meshgrid(c, c)            # [j, i]: x varies along i
    return np.hypot(x - CENTRE[0], y - CENTRE[1])


def measures(rho, ref):
    n = rho.shape[0]
    rhoRef = np.interp(radii(n), ref[:, 0], ref[:, 1])
    return {
        "L1": np.sum(np.abs(rho - rhoRef))/n**2,
        "e338": np.sum((rho - rhoRef)**2)/np.sum(rhoRef)**2,
        "symDiag": np.max(np.abs(rho - rho.T)),
        "symX": np.max(np.abs(rho - rho[:, ::-1])),
        "symY": np.max(np.abs(rho - rho[::-1, :])),
    }


def error(case, refPath):
    rho, _, n = density(case)
    m = measures(rho, np.loadtxt(refPath))
    print("N %d L1 %.4e e338 %.4e symDiag %.3e symX %.3e symY %.3e"
          % (n, m["L1"], m["e338"], m["symDiag"], m["symX"], m["symY"]))


def plot(out, refPath, runs):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ref = np.loadtxt(refPath)
    fig, axes = plt.subplots(len(runs), 2, figsize=(11, 4.6*len(runs)),
                             gridspec_kw={"width_ratios": [1, 1.35]},
                             squeeze=False)
    for (ai, ar), run in zip(axes, runs):
        label, case = run.split("=", 1)
        rho, time, n = density(case)
        m = measures(rho, ref)
        edges = np.linspace(0, 1, n + 1)
        im = ai.pcolormesh(edges, edges, rho, cmap="viridis", vmin=0.1,
                           vmax=1.0, shading="flat", rasterized=True)
        ai.set_aspect("equal")
        ai.set_title("%s: rho, t = %s" % (label, time), fontsize=10)
        ai.set_xlabel("x")
        ai.set_ylabel("y")
        fig.colorbar(im, ax=ai, fraction=0.046, pad=0.04)
        ar.plot(radii(n).ravel(), rho.ravel(), ".", ms=1.2, alpha=0.35,
                color="tab:blue", rasterized=True,
                label="cells (%d x %d)" % (n, n))
        ar.plot(ref[:, 0], ref[:, 1], "k-", lw=0.9,
                label="radial reference (%d cells)" % len(ref))
        ar.set_xlim(0, 0.72)
        ar.set_xlabel("r = |x - (0.5, 0.5)|")
        ar.set_ylabel("rho")
        ar.grid(alpha=0.3)
        ar.legend(fontsize=8, markerscale=6)
        ar.set_title("%s: L1 %.3g, e(3.38) %.3g" % (label, m["L1"],
                                                     m["e338"]), fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    print("Picture: %s" % os.path.abspath(out))


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    cmd, args = sys.argv[1], sys.argv[2:]
    if cmd == "error" and len(args) == 2:
        error(args[0], args[1])
    elif cmd == "plot" and len(args) >= 3:
        plot(args[0], args[1], args[2:])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
