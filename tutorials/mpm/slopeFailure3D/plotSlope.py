#!/usr/bin/python3
"""slopeFailure3D: run-out against time of the umls (tetrahedra) and
bspline2 (hexahedra) runs, pictures of the equivalent plastic strain and
of the mean normal stress, and the count of failure surfaces.
Usage: plotSlope.py UMLS_CASE BSPLINE2_CASE

Run-out: the front is the largest x of the particles that have another
particle within two lattice spacings (one thrown off alone is not the
front); the run-out distance is the front's advance over its start (the
toe, to within a particle spacing).  Pictures: particles of the slice z < spacing (next to one side wall;
the slice is plane strain, the rollers hold the sides) at the last time
and at two earlier ones.  Failure surfaces: the equivalent plastic strain
of the last time drawn on the particles' initial positions; along the
crest's top layer (initial y > H - 1 m, x < crest) the x-intervals where
it exceeds 0.5 are the scarps where failure surfaces reached the ground,
counted when separated by less strained ground (< 0.5) at least 2
spacings long.  More than one: retrogressive.  The count is printed for
every written time too (the surfaces of a retrogressive slide form one
after the other; a block between two can be remoulded by the end).  The retreat of the
rearmost such point over the three pictured times is printed too.
Writes runout.dat, slopeFailure3D_runout.png,
slopeFailure3D_epsilonP.png, slopeFailure3D_meanStress.png; prints the
numbers.
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
    """Values of a lagrangian ascii field (scalar, vector, symmTensor),
    one row per particle; uniform lists N{v} too"""
    txt = open(path).read()
    txt = txt[txt.index("}", txt.index("FoamFile")) + 1:]
    m = re.search(r"^\s*(\d+)\s*\{([^}]*)\}", txt, re.M)
    if m:
        v = [float(x) for x in m.group(2).strip("() ").split()]
        return np.tile(v, (int(m.group(1)), 1))
    body = txt[txt.index("(") + 1:txt.rindex(")")]
    rows = []
    for line in body.splitlines():
        s = line.strip()
        if s:
            rows.append([float(x) for x in s.split(")")[0].strip("(").split()])
    return np.array(rows)


def slope(d):
    p = dict(l.split() for l in open(os.path.join(d, "slope")))
    return {k: (v if k == "kernel" else float(v)) for k, v in p.items()}


def case(d):
    g = slope(d)
    times = sorted((t for t in os.listdir(d) if re.fullmatch(r"[0-9.e+-]+", t)
                    and os.path.isdir(os.path.join(d, t, "lagrangian"))), key=float)
    cl = lambda t, f: field(os.path.join(d, t, "lagrangian/mpmCloud", f))
    t, front, eps = [], [], {}
    for tt in times:
        P = cl(tt, "positions")[:, :3]
        ok = hasNeighbour(P, 2*g["spacing"], strict=True)
        t.append(float(tt))
        front.append(P[ok, 0].max())
        eps[tt] = cl(tt, "epsilonP")[np.argsort(cl(tt, "origId")[:, 0].astype(int)), 0]
    P0 = cl(times[0], "positions")[:, :3]
    id0 = cl(times[0], "origId")[:, 0].astype(int)
    snaps = {}
    for tt in (times[len(times)//3], times[2*len(times)//3], times[-1]):
        ids = cl(tt, "origId")[:, 0].astype(int)
        o = np.argsort(ids)
        s = cl(tt, "sigma")
        snaps[tt] = dict(P=cl(tt, "positions")[o, :3], eps=cl(tt, "epsilonP")[o, 0],
                         p=((s[:, 0] + s[:, 3] + s[:, 5])/3)[o])
    P0 = P0[np.argsort(id0)]
    front = np.array(front)
    return dict(name=d, g=g, t=np.array(t), runout=front - front[0], P0=P0,
                snaps=snaps, last=times[-1], eps=eps)


def scarps(c, thr=0.5, t=None):
    """x-intervals of the crest's top layer (initial positions) where
    epsilonP > thr at time t (default the last), separated by >= 2
    spacings of ground below thr"""
    g = c["g"]
    P0, e = c["P0"], c["eps"][c["last"] if t is None else t]
    top = (P0[:, 1] > g["H"] - 1.0) & (P0[:, 0] < g["crest"])
    xs = np.round(P0[top, 0]/g["spacing"]).astype(int)
    cols = np.unique(xs)
    emax = np.array([e[top][xs == k].max() for k in cols])
    runs, cur, gap = [], None, 0
    for k, v in zip(cols, emax):
        if v > thr:
            if cur is None or gap >= 2:
                cur = [k, k]
                runs.append(cur)
            cur[1] = k
            gap = 0
        elif cur is not None:
            gap += 1
    return [((r[0] - 0.5)*g["spacing"], (r[1] + 0.5)*g["spacing"]) for r in runs]


cases = [case(d) for d in sys.argv[1:3]]
label = {"umls": "UMLS-MPM (umls, tetrahedra)", "bspline2": "standard MPM (bspline2, hexahedra)"}

with open("runout.dat", "w") as f:
    f.write("# t [s]" + "".join(f"\trunout {c['g']['kernel']} [m]" for c in cases) + "\n")
    for i in range(min(len(c["t"]) for c in cases)):
        f.write(f"{cases[0]['t'][i]:g}" + "".join(f"\t{c['runout'][i]:.4f}" for c in cases) + "\n")

fig, ax = plt.subplots(figsize=(7, 4.5))
for c in cases:
    ax.plot(c["t"], c["runout"], "o-", ms=3, label=label[c["g"]["kernel"]])
ax.set_xlabel("t [s]")
ax.set_ylabel("run-out distance [m]")
ax.set_title("3D slope failure in sensitive clay (dissertation 2.3.4, Fig. 2.23)")
ax.legend()
fig.tight_layout()
fig.savefig("slopeFailure3D_runout.png", dpi=100)

for key, fname, cmap, title in (("eps", "slopeFailure3D_epsilonP.png", "viridis",
                                 "equivalent plastic strain"),
                                ("p", "slopeFailure3D_meanStress.png", "coolwarm",
                                 "mean normal stress [kPa]")):
    times = list(cases[0]["snaps"].keys())
    fig, ax = plt.subplots(len(times) + (key == "eps"), len(cases),
                           figsize=(7*len(cases), 2.3*(len(times) + (key == "eps"))), squeeze=False)
    for j, c in enumerate(cases):
        g = c["g"]
        vals = {t: c["snaps"][t][key]*(1e-3 if key == "p" else 1) for t in c["snaps"]}
        for i, t in enumerate(c["snaps"]):
            s = c["snaps"][t]
            m = s["P"][:, 2] < g["spacing"]
            if key == "eps":
                kw = dict(vmin=0, vmax=2)
            else:
                kw = dict(vmin=-200, vmax=0)
            sc = ax[i, j].scatter(s["P"][m, 0], s["P"][m, 1], c=vals[t][m], s=2, cmap=cmap, **kw)
            ax[i, j].set_aspect("equal")
            ax[i, j].set_title(f"{label[g['kernel']]}, t = {t} s", fontsize=9)
            fig.colorbar(sc, ax=ax[i, j], label=title, shrink=0.8)
        if key == "eps":
            m = c["P0"][:, 2] < g["spacing"]
            sc = ax[-1, j].scatter(c["P0"][m, 0], c["P0"][m, 1], c=vals[c["last"]][m], s=2,
                                   cmap=cmap, vmin=0, vmax=2)
            for a0, a1 in scarps(c):
                ax[-1, j].axvspan(a0, a1, ymin=0.9, color="r", alpha=0.4)
            ax[-1, j].set_aspect("equal")
            ax[-1, j].set_title(f"t = {c['last']} s on the initial positions (red: scarps)", fontsize=9)
            fig.colorbar(sc, ax=ax[-1, j], label=title, shrink=0.8)
    for a_ in ax.flat:
        a_.set_xlim(0, max(c["P0"][:, 0].max() for c in cases) + max(c["runout"].max() for c in cases) + 1)
    fig.tight_layout()
    fig.savefig(fname, dpi=90)

def backScarp(c, t, thr=0.5):
    """Initial x of the rearmost crest-top particle with epsilonP > thr"""
    g = c["g"]
    top = (c["P0"][:, 1] > g["H"] - 1.0) & (c["P0"][:, 0] < g["crest"])
    hit = top & (c["snaps"][t]["eps"] > thr)
    return c["P0"][hit, 0].min() if hit.any() else float("nan")


for c in cases:
    print(f"{c['g']['kernel']}: rearmost crest point with epsilonP > 0.5 (initial x, crest edge at"
          f" {c['g']['crest']:g} m): " + ", ".join(f"t = {t} s: {backScarp(c, t):.2f} m"
                                                  for t in c["snaps"]))
r = [c["runout"][-1] for c in cases]
for c in cases:
    sc = scarps(c)
    print(f"{c['g']['kernel']}: run-out {c['runout'][-1]:.3f} m at t = {c['last']} s;"
          f" {len(sc)} failure surface(s) reaching the crest at x = "
          + ", ".join(f"[{a:.2f}, {b:.2f}]" for a, b in sc) + " m"
          + (" (retrogressive)" if len(sc) > 1 else ""))
    n = {t: len(scarps(c, t=t)) for t in c["eps"]}
    tm = max(n, key=lambda t: (n[t], -float(t)))
    print(f"{c['g']['kernel']}: failure surfaces reaching the crest at each written time: "
          + " ".join(f"{t}: {n[t]}" for t in n) + f"; most {n[tm]} (first at t = {tm} s"
          + (": x = " + ", ".join(f"[{a:.2f}, {b:.2f}]" for a, b in scarps(c, t=tm)) + " m" if n[tm] else "")
          + ")")
print(f"run-out difference between the kernels: {100*abs(r[0] - r[1])/max(r):.1f} %"
      f" of the larger ({abs(r[0] - r[1]):.3f} m)")
