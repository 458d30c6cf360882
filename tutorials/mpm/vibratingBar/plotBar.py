#!/usr/bin/python3
"""vibratingBar: centre of mass against (2.37), energy, first-mode frequency.

Usage: plotBar.py [caseDir ...]   (default: .)
One case: writes vibratingBar.png and prints RMSE, energy drift, frequency.
Several cases (a resolution study): also writes convergence.png and prints
the observed orders between successive resolutions.
"""
import sys
import os
import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

L, E, rho, v0 = 25.0, 100.0, 1.0, 0.75
beta1 = np.pi/(2*L)
omega1 = beta1*np.sqrt(E/rho)
amplitude = v0/(beta1*L*omega1)


def analysis(case):
    d = np.loadtxt(os.path.join(case, "postProcessing/conservation/0/conservation.dat"))
    t, x, Etot = d[:, 0], d[:, 2], d[:, 14]
    exact = L/2 + amplitude*np.sin(omega1*t)
    rmse = np.sqrt(np.mean((x - exact)**2))/amplitude
    drift = (Etot.max() - Etot.min())/Etot[0]
    f = float("nan")
    peaks = os.path.join(case, "postProcessing/spectrum/0/peaks.dat")
    if os.path.exists(peaks):
        for line in open(peaks):
            if line.startswith("xCM"):
                f = float(line.split()[2])
                break
    return dict(t=t, x=x, exact=exact, E=d[:, 11:15], rmse=rmse, drift=drift, f=f)


def dxOf(case):
    p = os.path.join(case, "system/meshSettings")
    n = 60
    if os.path.exists(p):
        n = int(open(p).read().split()[1].rstrip(";"))
    return 30.0/n


cases = sys.argv[1:] or ["."]
results = [(dxOf(c), analysis(c)) for c in cases]

for dx, r in results:
    print(f"dx = {dx:g} m: CM RMSE = {100*r['rmse']:.3f} % of the amplitude, "
          f"energy drift = {100*r['drift']:.3f} %, first-mode f = {r['f']:.5f} Hz "
          f"(exact {omega1/(2*np.pi):.5f}, error {100*abs(r['f']/(omega1/(2*np.pi)) - 1):.2f} %)")

dx, r = results[-1]
fig, ax = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
ax[0].plot(r["t"], r["exact"] - L/2, "k--", label="exact (2.37)")
ax[0].plot(r["t"], r["x"] - L/2, label=f"UMLS-MPM, dx = {dx:g} m")
ax[0].set_ylabel("centre of mass - L/2 [m]")
ax[0].legend()
ax[0].set_title(f"Vibrating bar: RMSE {100*r['rmse']:.3f} % of the amplitude")
for k, name in enumerate(["kinetic", "strain", "gravitational", "total"]):
    if name != "gravitational":
        ax[1].plot(r["t"], r["E"][:, k], label=name)
ax[1].set_xlabel("t [s]")
ax[1].set_ylabel("energy [J per unit area]")
ax[1].legend()
ax[1].set_title(f"total energy drift {100*r['drift']:.3f} %")
fig.tight_layout()
fig.savefig("vibratingBar.png", dpi=100)

if len(results) > 1:
    dxs = np.array([d for d, _ in results])
    errs = np.array([r["rmse"] for _, r in results])
    orders = np.log(errs[:-1]/errs[1:])/np.log(dxs[:-1]/dxs[1:])
    for i, o in enumerate(orders):
        print(f"observed order dx {dxs[i]:g} -> {dxs[i+1]:g}: {o:.2f}")
    fig, ax = plt.subplots(figsize=(6, 5))
    ax.loglog(dxs, 100*errs, "o-", label="UMLS-MPM")
    ax.loglog(dxs, 100*errs[0]*(dxs/dxs[0])**2, "k:", label="second order")
    ax.set_xlabel("dx [m]")
    ax.set_ylabel("CM RMSE [% of amplitude]")
    ax.legend()
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig("convergence.png", dpi=100)
