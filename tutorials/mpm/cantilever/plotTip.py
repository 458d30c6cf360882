#!/usr/bin/python3
"""cantilever: tip deflection against the static Timoshenko value, and the
rotated meshes against the 0-degree one (dissertation Fig. 2.17, 2.18).

Usage: plotTip.py caseDir [caseDir ...]   (the first is the reference)
Prints, per case, the mean tip deflection over whole periods and its
difference from the static value 0.704 m (plane strain), and, for the
others, the RMSE of the tip history against the first case relative to the
first case's largest deflection.  Writes cantilever.png."""
import sys
import os
import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

static = 0.704   # Timoshenko, plane strain (E' = E/(1 - nu^2)), m


def tip(case):
    c = np.loadtxt(os.path.join(case, "postProcessing/tip/0/tip.dat"))
    return c[:, 0], -c[:, 5]    # deflection downwards, positive


def meanOverPeriods(t, d):
    # Whole periods: between the first and the last upper turning point
    # (local minima of the deflection, near zero)
    i = [k for k in range(1, len(d) - 1) if d[k] <= d[k - 1] and d[k] < d[k + 1]]
    i = [k for k in i if d[k] < 0.25*d.max()]
    lo, hi = (0, len(d) - 1) if len(i) < 1 else (0, i[-1])
    return np.trapz(d[lo:hi + 1], t[lo:hi + 1])/(t[hi] - t[lo])


cases = sys.argv[1:] or ["."]
label = lambda c: os.path.basename(os.path.normpath(c))
t0, d0 = tip(cases[0])
fig, ax = plt.subplots(figsize=(8, 5))
for c in cases:
    t, d = tip(c)
    m = meanOverPeriods(t, d)
    line = (f"{label(c)}: mean tip deflection {m:.5f} m, "
            f"{100*(m/static - 1):+.2f} % from the static Timoshenko {static} m; "
            f"largest {d.max():.4f} m")
    if c != cases[0]:
        rmse = np.sqrt(np.mean((np.interp(t0, t, d) - d0)**2))/d0.max()
        line += f"; RMSE against {label(cases[0])}: {100*rmse:.2f} %"
    print(line)
    ax.plot(t, d, label=label(c))
ax.axhline(static, color="k", ls="--", lw=0.8, label="static Timoshenko (plane strain)")
ax.set_xlabel("t [s]")
ax.set_ylabel("tip deflection [m]")
ax.invert_yaxis()
ax.legend()
ax.set_title("Cantilever under its own weight, UMLS-MPM")
fig.tight_layout()
fig.savefig("cantilever.png", dpi=100)
