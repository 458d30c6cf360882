#!/usr/bin/python3
"""collidingDisks: momentum, energies and the stress at the left disk's
centre (dissertation Fig. 2.15).  Writes collidingDisks.png; prints the
momentum drift, the kinetic energy recovered after separation and the
stress before impact against its peak."""
import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

d = np.loadtxt("postProcessing/conservation/0/conservation.dat")
t, m, p, E = d[:, 0], d[:, 1], d[:, 5:8], d[:, 11:15]
# Total momentum is zero: measure drift against sum m |v0| (|v0| = 0.1 sqrt 2)
scale = m[0]*0.1*np.sqrt(2)
dp = np.abs(p - p[0]).max()/scale
K0 = E[0, 0]
after = t >= 2.6
print(f"momentum: max |P - P0| / (sum m |v0|) = {dp:.3e}")
print(f"kinetic energy after separation: K(t={t[-1]:g})/K0 = {E[-1, 0]/K0:.4f}, "
      f"mean over t >= 2.6: {E[after, 0].mean()/K0:.4f}")

c = np.loadtxt("postProcessing/centre/0/centre.dat")
tc = c[:, 0]
sxx, syy, sxy = c[:, 10], c[:, 11], c[:, 13]
vm = np.sqrt(sxx**2 - sxx*syy + syy**2 + 3*sxy**2)   # in-plane von Mises
before = tc < 1.4
print(f"left-disk centre: max von Mises before t = 1.4 s = {vm[before].max():.3e} Pa, "
      f"peak = {vm.max():.4g} Pa at t = {tc[vm.argmax()]:.3f} s")

fig, ax = plt.subplots(3, 1, figsize=(7, 9), sharex=True)
ax[0].plot(t, p[:, 0], label="total px")
ax[0].set_ylabel("momentum [kg m/s per m]")
ax[0].legend()
ax[0].set_title("Colliding disks, UMLS-MPM + FLIP")
ax[1].plot(t, E[:, 0], label="kinetic")
ax[1].plot(t, E[:, 1], label="strain")
ax[1].plot(t, E[:, 3], label="total")
ax[1].set_ylabel("energy [J per m]")
ax[1].legend()
ax[2].plot(tc, sxx, label="sigma_xx")
ax[2].plot(tc, syy, label="sigma_yy")
ax[2].plot(tc, sxy, label="sigma_xy")
ax[2].set_ylabel("stress at left centre [Pa]")
ax[2].set_xlabel("t [s]")
ax[2].legend()
fig.tight_layout()
fig.savefig("collidingDisks.png", dpi=100)
