#!/usr/bin/python3
"""fallingCube3D: height of the centre of mass and the energies; the
lowest particle over the written times (it must stay above the floor).
Writes fallingCube3D.png and prints the numbers."""
import glob
import os
import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

d = np.loadtxt("postProcessing/conservation/0/conservation.dat")
t, m, y, E = d[:, 0], d[:, 1], d[:, 3], d[:, 11:15]

lowest = np.inf
for f in glob.glob("[0-9]*/lagrangian/mpmCloud/positions"):
    with open(f) as fh:
        for line in fh:
            if line.startswith("(") and len(line.split()) >= 4:
                lowest = min(lowest, float(line.strip("()\n").split()[1]))
first = np.argmin(np.where(t < 0.45, y, np.inf))
rebound = y[first:][t[first:] < 0.75].max()
print(f"mass: largest relative change {np.abs(m/m[0] - 1).max():.3e}")
print(f"lowest particle over the written times: y = {lowest:.4f} m (floor y = 0)")
print(f"centre of mass: start {y[0]:.4f} m, lowest {y[first]:.4f} m at t = {t[first]:.3f} s, "
      f"rebound to {rebound:.4f} m")
print(f"total energy: start {E[0, 3]:.4g} J, largest {E[:, 3].max():.4g} J "
      f"({100*(E[:, 3].max()/E[0, 3] - 1):+.2f} %), end {E[-1, 3]:.4g} J")

fig, ax = plt.subplots(2, 1, figsize=(7, 7), sharex=True)
ax[0].plot(t, y)
ax[0].set_ylabel("centre of mass height [m]")
ax[0].set_title("Elastic cube falling onto a floor (3D tetrahedra, UMLS-MPM + APIC)")
for k, name in enumerate(["kinetic", "strain", "gravitational", "total"]):
    ax[1].plot(t, E[:, k], label=name)
ax[1].set_xlabel("t [s]")
ax[1].set_ylabel("energy [J]")
ax[1].legend()
fig.tight_layout()
fig.savefig("fallingCube3D.png", dpi=100)
