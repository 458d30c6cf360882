#!/usr/bin/python3
"""Report of Allrun -study: the convergence of both solvers on Sod's shock
tube, shockMpmFoam's wall time to reach rhoCentralFoam's 1000-cell error,
and a PNG of error against wall time.

    studyReport.py study.dat errorVsCost.png
"""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = [l.split() for l in open(sys.argv[1]) if not l.startswith("#")]
rcf = {}
ours = []
for solver, n, co, err, wall in rows:
    if solver == "rhoCentralFoam":
        rcf.setdefault(co, []).append((int(n), float(err), float(wall)))
    else:
        ours.append((int(n), float(err), float(wall)))
ours.sort()

print("shockMpmFoam (WENO5, explicit, CFL 0.5):")
print("  %6s %12s %9s" % ("cells", "L1(rho)", "wall [s]"))
for n, e, w in ours:
    print("  %6d %12.4e %9.3f" % (n, e, w))
mono = all(b[1] <= a[1] for a, b in zip(ours, ours[1:]))
print("  error never increases with the cells: %s" % ("yes" if mono else "NO"))

for co in sorted(rcf):
    print("rhoCentralFoam (Kurganov, vanLeer, maxCo %s):" % co)
    for n, e, w in sorted(rcf[co]):
        print("  %6d %12.4e %9.3f" % (n, e, w))

ours1000 = [r for r in ours if r[0] == 1000][0]
for co in sorted(rcf):
    ref = [r for r in rcf[co] if r[0] == 1000][0]
    print("1000 cells: shockMpmFoam/rhoCentralFoam(maxCo %s) L1(rho) = "
          "%.4e/%.4e = %.3f" % (co, ours1000[1], ref[1], ours1000[1] / ref[1]))
    reach = [r for r in ours if r[1] <= ref[1]]
    if reach:
        n, e, w = min(reach, key=lambda r: r[2])
        print("equal accuracy vs maxCo %s: shockMpmFoam reaches %.4e with %d "
              "cells in %.3f s; rhoCentralFoam's 1000-cell run took %.3f s: "
              "ratio %.3f" % (co, ref[1], n, w, ref[2], w / ref[2]))

fig, ax = plt.subplots(figsize=(6, 4.5))
ax.loglog([r[2] for r in ours], [r[1] for r in ours], "o-",
          label="shockMpmFoam WENO5")
for n, e, w in ours:
    ax.annotate(str(n), (w, e), fontsize=7, textcoords="offset points",
                xytext=(3, 3))
for co, mk in zip(sorted(rcf), ("s--", "^--")):
    r = sorted(rcf[co])
    ax.loglog([x[2] for x in r], [x[1] for x in r], mk,
              label="rhoCentralFoam maxCo %s" % co)
    for n, e, w in r:
        ax.annotate(str(n), (w, e), fontsize=7, textcoords="offset points",
                    xytext=(3, -9))
ax.set_xlabel("wall time [s]")
ax.set_ylabel("L1(rho) at t = 0.2")
ax.set_title("Sod shock tube: error against cost")
ax.grid(True, which="both", alpha=0.3)
ax.legend()
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=120)
print("wrote %s" % sys.argv[2])
