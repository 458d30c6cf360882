#!/usr/bin/python3
"""rotatingSquare: drift of the total linear and angular momentum (APIC,
Definition 2.2.4) and the energies, from the mpmConservation monitor.
Writes rotatingSquare.png and prints the largest relative drifts."""
import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

d = np.loadtxt("postProcessing/conservation/0/conservation.dat")
t, m = d[:, 0], d[:, 1]
p, L, E = d[:, 5:8], d[:, 8:11], d[:, 11:15]
# Linear momentum is zero in this case: measure it against the momentum
# scale sum m |v| of the initial motion (|v| = 1 m/s)
pScale = m[0]*1.0
dp = np.abs(p - p[0]).max(axis=1)/pScale
dL = np.abs(L[:, 2] - L[0, 2])/abs(L[0, 2])
steps = int(round(t[-1]/1e-5))
print(f"steps: {steps}")
print(f"linear momentum: max |P - P0| / (sum m |v0|) = {dp.max():.3e}")
print(f"angular momentum: max |Lz - Lz0| / |Lz0| = {dL.max():.3e}")
print(f"total energy: {E[0, 3]:.6g} -> {E[-1, 3]:.6g}")

fig, ax = plt.subplots(3, 1, figsize=(7, 9), sharex=True)
ax[0].semilogy(t, np.maximum(dp, 1e-18))
ax[0].set_ylabel("|P - P0| / (m |v0|)")
ax[0].set_title("Rotating square, UMLS-MPM + APIC")
ax[1].semilogy(t, np.maximum(dL, 1e-18))
ax[1].set_ylabel("|Lz - Lz0| / |Lz0|")
for k, name in enumerate(["kinetic", "strain"]):
    ax[2].plot(t, E[:, k], label=name)
ax[2].plot(t, E[:, 3], label="total")
ax[2].set_ylabel("energy [J/m]")
ax[2].set_xlabel("t [s]")
ax[2].legend()
fig.tight_layout()
fig.savefig("rotatingSquare.png", dpi=100)
