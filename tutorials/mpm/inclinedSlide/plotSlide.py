#!/usr/bin/python3
"""inclinedSlide: the distance slid along the slope by the particle at the
block's centre, s(t) = D(t) . t (t = (cos 30, -sin 30), D its
displacement), against s(t) = g (sin 30 - mu cos 30) t^2/2.  Prints per
friction coefficient the slid distance at the end, the largest relative
deviation from the analytic curve over the window where that curve has
passed two cells (0.04 m, so the landing transient of the first
milliseconds is a small part of it), and the acceleration fitted over that
window; for mu > tan 30 the distance slid against the frictionless one.
Writes inclinedSlide.png."""
import glob
import re
import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

g = 9.81
theta = np.radians(30.0)
tHat = np.array([np.cos(theta), -np.sin(theta)])
window = 0.04          # two cells of 0.02 m

summary = []
runs = sorted(glob.glob("runs/mu*"), key=lambda d: float(d[len("runs/mu"):]))
fig, ax = plt.subplots(figsize=(7, 5))
print(f"{'mu':>5} {'a analytic':>11} {'a fitted':>9} {'s(T) [m]':>9} "
      f"{'s_exact(T)':>10} {'max dev [%]':>11} {'window [s]':>14}  min distance [m]")
for d in runs:
    mu = float(d[len("runs/mu"):])
    c = np.loadtxt(f"{d}/postProcessing/centre/0/centre.dat")
    t = c[:, 0]
    s = c[:, 4:6] @ tHat
    a = g*(np.sin(theta) - mu*np.cos(theta))
    log = open(f"{d}/log.umlsMpmFoam").read()
    m = re.search(r"smallest particle-patch distance ([-0-9.e+]+) m", log)
    dmin = float(m.group(1)) if m else float("nan")
    T = t[-1]
    if a > 0:
        exact = 0.5*a*t**2
        w = exact >= window
        # relative to the curve at each time
        devRel = (np.abs(s[w] - exact[w])/exact[w]).max()*100 if w.any() else np.nan
        A = np.vstack([np.ones(w.sum()), t[w], 0.5*t[w]**2]).T
        fit = np.linalg.lstsq(A, s[w], rcond=None)[0][2] if w.sum() > 3 else np.nan
        print(f"{mu:5.2f} {a:11.4f} {fit:9.4f} {s[-1]:9.5f} {0.5*a*T**2:10.5f} "
              f"{devRel:11.3f} {t[w][0]:6.3f}-{T:6.3f}  {dmin:.4e}")
        summary.append(f"slide mu {mu:g}: max deviation {devRel:.3f} %, fitted/analytic "
                       f"acceleration {fit/a:.5f}, min distance {dmin:.4e} m")
        ax.plot(t, exact, "k--", lw=0.8)
    else:
        free = 0.5*g*np.sin(theta)*T**2
        print(f"{mu:5.2f} {'stuck':>11} {'':>9} {s[-1]:9.2e} {'0':>10} "
              f"moved {abs(s[-1])/free*100:.4f} % of the frictionless {free:.4f} m"
              f"  {dmin:.4e}")
        summary.append(f"stuck mu {mu:g}: moved {abs(s[-1])/free*100:.4f} % of the "
                       f"frictionless distance, min distance {dmin:.4e} m")
    ax.plot(t, s, label=f"mu = {mu:g}")
ax.set_xlabel("t [s]")
ax.set_ylabel("distance slid along the slope [m]")
ax.set_title("inclinedSlide: block on a 30 degree slope (dashed: analytic)")
ax.legend()
fig.tight_layout()
fig.savefig("inclinedSlide.png", dpi=100)
print("\n".join(summary))
