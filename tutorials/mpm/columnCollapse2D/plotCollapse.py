#!/usr/bin/python3
"""columnCollapse2D: run-out of the collapsing columns against time and
against the scaling law of Lube et al. (2005) for quasi-2D channels,
    (L - L0)/L0 = 1.2 a      (a < 1.8)
    (L - L0)/L0 = 1.9 a^2/3  (a > 2.8)
Usage: plotCollapse.py CASE...  (cases written by makeCase.py)

The front L(t) is the largest x of the particles that have another particle
within two lattice spacings (a particle thrown off alone is not the front;
the cut is printed); the run-out is its advance over the start, L - L0,
with L0 the column's length from the mpmSetParticlesDict box.  Writes
runout.dat, columnCollapse2D_runout.png, columnCollapse2D_deposits.png and
prints one line per case: a, measured, law, difference.
"""
import os
import re
import sys
import numpy as np
sys.path.insert(0, os.path.join(os.environ["MPMFOAM_DIR"], "bin", "tools"))
from particlePairs import hasNeighbour  # noqa: E402 (numpy only)
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def field(path):
    """Rows of a lagrangian ascii field (scalars or vectors)"""
    rows = []
    with open(path) as f:
        body = False
        for line in f:
            s = line.strip()
            if not body:
                if s == "(":
                    body = True
                continue
            if s == ")":
                break
            rows.append([float(v) for v in s.split(")")[0].strip("(").split()])
    return np.array(rows)


def law(a):
    return 1.2*a if a < 2.3 else 1.9*a**(2.0/3.0)


def case(d):
    txt = open(os.path.join(d, "system/mpmSetParticlesDict")).read()
    L0, H0 = [float(v) for v in re.search(r"max\s+\(([^)]*)\)", txt).group(1).split()[:2]]
    s = float(re.search(r"spacing\s+([0-9.eE+-]+);", txt).group(1))
    times = sorted((t for t in os.listdir(d) if re.fullmatch(r"[0-9.e+-]+", t)
                    and os.path.isdir(os.path.join(d, t, "lagrangian"))), key=float)
    t, front, nIso = [], [], 0
    for tt in times:
        P = field(os.path.join(d, tt, "lagrangian/mpmCloud/positions"))[:, :2]
        ok = hasNeighbour(P, 2*s, strict=True)
        t.append(float(tt))
        front.append(P[ok, 0].max())
        nIso = (~ok).sum()
    front = np.array(front)
    runout = (front - front[0])/L0
    last = times[-1]
    P = field(os.path.join(d, last, "lagrangian/mpmCloud/positions"))
    eps = field(os.path.join(d, last, "lagrangian/mpmCloud/epsilonP"))[:, 0]
    return dict(name=d, a=H0/L0, L0=L0, H0=H0, s=s, t=np.array(t), runout=runout,
                nIso=nIso, P=P, eps=eps, last=last)


cases = [case(d) for d in sys.argv[1:]]
with open("runout.dat", "w") as f:
    f.write("# t [s]" + "".join(f"\t(L-L0)/L0 a={c['a']:g} [-]" for c in cases) + "\n")
    for i in range(min(len(c["t"]) for c in cases)):
        f.write(f"{cases[0]['t'][i]:g}" + "".join(f"\t{c['runout'][i]:.5f}" for c in cases) + "\n")

fig, ax = plt.subplots(figsize=(7, 4.5))
for c in cases:
    l, = ax.plot(c["t"], c["runout"], "o-", ms=3, label=f"a = {c['a']:g}, umlsMpmFoam")
    ax.axhline(law(c["a"]), color=l.get_color(), ls="--",
               label=f"a = {c['a']:g}, Lube et al. (2005): {law(c['a']):.2f}")
    ax.axhspan(0.85*law(c["a"]), 1.15*law(c["a"]), color=l.get_color(), alpha=0.1)
ax.set_xlabel("t [s]")
ax.set_ylabel("run-out (L - L0)/L0 [-]")
ax.set_title("Granular column collapse (Drucker-Prager, phi = 21 deg), band: law +-15 %")
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig("columnCollapse2D_runout.png", dpi=100)

fig, ax = plt.subplots(len(cases), 1, figsize=(9, 2.6*len(cases)))
for a_, c in zip(np.atleast_1d(ax), cases):
    sc = a_.scatter(c["P"][:, 0], c["P"][:, 1], c=c["eps"], s=2, cmap="viridis",
                    vmin=0, vmax=np.percentile(c["eps"], 98))
    a_.add_patch(plt.Rectangle((0, 0), c["L0"], c["H0"], fill=False, ls="--", color="k"))
    a_.axvline(c["L0"]*(1 + law(c["a"])), color="r", ls=":", label="law")
    a_.axvline(c["L0"]*(1 + c["runout"][-1]), color="k", ls="-", lw=0.8, label="measured front")
    a_.set_aspect("equal")
    a_.set_xlim(0, c["L0"]*(1 + 1.3*law(c["a"])))
    a_.set_ylim(0, 1.05*c["H0"])
    a_.set_title(f"a = {c['a']:g}: deposit at t = {c['last']} s (dashed: initial column)", fontsize=9)
    a_.legend(fontsize=7, loc="upper right")
    fig.colorbar(sc, ax=a_, label="equivalent plastic strain")
np.atleast_1d(ax)[-1].set_xlabel("x [m]")
fig.tight_layout()
fig.savefig("columnCollapse2D_deposits.png", dpi=100)

for c in cases:
    m, L = c["runout"][-1], law(c["a"])
    print(f"a = {c['a']:g}: (L - L0)/L0 = {m:.3f} at t = {c['last']} s, law {L:.3f},"
          f" difference {100*(m/L - 1):+.1f} % ({c['nIso']} isolated particles"
          f" beyond 2 spacings ignored)")
