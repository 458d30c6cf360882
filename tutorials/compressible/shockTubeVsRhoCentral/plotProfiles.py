#!/usr/bin/python3
"""Density, velocity and pressure of Sod's shock tube at t = 0.2 from the
riemannCompare profiles of each run directory, against the exact solution.

    plotProfiles.py <dir>... <out.png>
"""
import glob
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def profile(d):
    f = sorted(glob.glob(d + "/postProcessing/riemannCompare/*/profile.dat"))[-1]
    cols = list(zip(*[[float(v) for v in l.split()] for l in open(f)
                      if not l.startswith("#")]))
    return cols


dirs, out = sys.argv[1:-1], sys.argv[-1]
fig, axs = plt.subplots(1, 3, figsize=(13, 4))
first = True
for d in dirs:
    x, rho, U, p, rhoE, UE, pE = profile(d)
    if first:
        for ax, v in zip(axs, (rhoE, UE, pE)):
            ax.plot(x, v, "k-", lw=1, label="exact")
        first = False
    for ax, v in zip(axs, (rho, U, p)):
        ax.plot(x, v, ".", ms=2, label=d)
for ax, name in zip(axs, ("rho", "U", "p")):
    ax.set_xlabel("x")
    ax.set_title(name)
    ax.legend(fontsize=7)
fig.tight_layout()
fig.savefig(out, dpi=110)
print("wrote " + out)
