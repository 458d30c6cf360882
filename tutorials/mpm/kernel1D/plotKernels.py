#!/usr/bin/python3
"""kernel1D: the 1D kernels of mpmKernelProbe against dissertation 2.1.3.5.

Usage: plotKernels.py [-ratio R]      (run from the tutorial directory)

Reads uniform/ and shrinking/ postProcessing/{mpmKernelProbe,nodes}/<kernel>.dat
(columns: point px py pz vertex vx vy vz w gradWx gradWy gradWz) and
  - uniform: compares the umls kernel w and dw/dx of the node at x = 2 with
    (2.33)/(2.34), prints the largest errors, plots Fig. 2.5 (umls and the
    mlsRing ablation) -> kernel1D_uniform.png
  - shrinking (cycle [1, R, R^2, R]): plots the umls and mlsRing kernels and
    gradients of nodes 5-8 (Fig. 2.7) -> kernel1D_shrinking.png
  - both: the relative jumps of w and grad w across each probed node
    (x_n - 1e-6 to x_n + 1e-6): max over vertices of |w(x+) - w(x-)| over
    the largest |w| there, the same for grad w.
The lines starting with "uniform:" and "shrinking:" are what the case test
tests/cases/kernel1D reads.
"""
import sys
import os
import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

ratio = 1.5
args = sys.argv[1:]
if args[:1] == ["-ratio"] and len(args) == 2:
    ratio = float(args[1])
elif args:
    sys.exit(__doc__)


def load(case, kernel, out="mpmKernelProbe"):
    """(x of each point, dict vertex x -> (w, dw/dx) arrays over the points)"""
    d = np.loadtxt(os.path.join(case, "postProcessing", out, kernel + ".dat"),
                   ndmin=2)
    p = d[:, 0].astype(int)
    n = p.max() + 1
    px = np.zeros(n)
    px[p] = d[:, 1]
    kern = {}
    for vx in np.unique(d[:, 5]):
        w = np.zeros(n)
        g = np.zeros(n)
        sel = d[:, 5] == vx
        w[p[sel]] = d[sel, 8]
        g[p[sel]] = d[sel, 9]
        kern[vx] = (w, g)
    return px, kern


def jumps(case, kernel):
    """Per node crossing (point pairs 2i, 2i+1): x_n, relative jump of w,
    relative jump of grad w"""
    px, kern = load(case, kernel, "nodes")
    W = np.array([k[0] for k in kern.values()])     # vertices x points
    G = np.array([k[1] for k in kern.values()])
    rows = []
    for i in range(0, len(px) - 1, 2):
        a, b = i, i + 1
        jw = np.abs(W[:, a] - W[:, b]).max()/np.abs(W[:, [a, b]]).max()
        jg = np.abs(G[:, a] - G[:, b]).max()/np.abs(G[:, [a, b]]).max()
        rows.append((0.5*(px[a] + px[b]), jw, jg))
    return np.array(rows)


# (2.33), (2.34) as printed: pieces on (0.5, 1], (1, 1.5], ..., (3, 3.5];
# polynomial coefficients, highest power first
F = [
    ([0.25, -0.25, 0.0625, 0], [1, -6, 13.5, -13.75, 6.3125, -0.5625]),
    ([-1, 5, -9.5, 8.5, -3.3125, 0.3125, 0.0625], [-1, 4, -5.5, 3.25, -1.3125, 1.0625]),
    ([1, -12, 58.5, -148.25, 205.563, -147.063, 42.25], [1, -11, 47.5, -100.25, 103.313, -41.125]),
    ([1, -12, 58.5, -147.75, 202.563, -141.438, 39], [-1, 9, -31.5, 53.75, -45.3125, 16.125]),
    ([1, -19, 149.5, -623.5, 1453.31, -1794.19, 915.687], [-1, 16, -101.5, 318.75, -495.313, 304.188]),
    ([-0.25, 2.75, -10.0625, 12.25], [-1, 14, -77.5, 212.25, -288.313, 156.688]),
]
G = [
    ([-1, 3, -2.25, 0.5, 0], [1, -6, 13.5, -13.75, 6.3125, -0.5625]),
    ([-1, 5, -10.5, 11.5, -5.8125, 1.0625], [-1, 4, -5.5, 3.25, -1.3125, 1.0625]),
    ([-1, 9, -33.5, 65.75, -67.3125, 27.625], [-1, 11, -47.5, 100.25, -103.313, 41.125]),
    ([-1, 11, -49.5, 112.25, -125.313, 53.625], [1, -9, 31.5, -53.75, 45.3125, -16.125]),
    ([-1, 15, -90.5, 274.5, -417.813, 254.188], [1, -16, 101.5, -318.75, 495.313, -304.188]),
    ([1, -13, 62.25, -129.5, 98], [-1, 14, -77.5, 212.25, -288.313, 156.688]),
]


def analytic(pieces, x, sixteenths=False):
    """Evaluate (2.33) or (2.34) at x; sixteenths: coefficients rounded to
    the nearest 1/16 (the printed ones with three decimals, e.g. 205.563,
    are sixteenths rounded for print: 205.5625)"""
    y = np.zeros_like(x)
    for i, (num, den) in enumerate(pieces):
        if sixteenths:
            num = np.round(np.array(num)*16)/16
            den = np.round(np.array(den)*16)/16
        lo = 0.5 + 0.5*i
        sel = (x > lo) & (x <= lo + 0.5)
        y[sel] = np.polyval(num, x[sel])/np.polyval(den, x[sel])
    return y


def maxErr(a, b, sel):
    return np.abs(a[sel] - b[sel]).max()


# ---- uniform mesh -----------------------------------------------------------
px, umls = load("uniform", "umls")
_, ring = load("uniform", "mlsRing")
w2, g2 = umls[2.0]
f, g = analytic(F, px), analytic(G, px)
f16, g16 = analytic(F, px, True), analytic(G, px, True)
inner = (px > 0.5) & (px <= 1.5 + 1e-12)
outer = (px > 1.5 + 1e-12) & (px <= 3.5)
print(f"uniform: umls node x = 2 vs (2.33)/(2.34) on (0.5, 1.5]: "
      f"max |w - f| = {maxErr(w2, f, inner):.3e}, "
      f"max |dw/dx - g| = {maxErr(g2, g, inner):.3e} ({inner.sum()} points)")
print(f"uniform: umls node x = 2 vs (2.33)/(2.34) on (1.5, 3.5], coefficients "
      f"as printed: max |w - f| = {maxErr(w2, f, outer):.3e}, "
      f"max |dw/dx - g| = {maxErr(g2, g, outer):.3e}")
print(f"uniform: umls node x = 2 vs (2.33)/(2.34) on (1.5, 3.5], coefficients "
      f"in sixteenths: max |w - f| = {maxErr(w2, f16, outer):.3e}, "
      f"max |dw/dx - g| = {maxErr(g2, g16, outer):.3e}")
wr, gr = ring[2.0]
print(f"uniform: mlsRing node x = 2 differs from umls by up to "
      f"{np.abs(wr - w2).max():.3f} in w, {np.abs(gr - g2).max():.3f} in dw/dx")
ju = jumps("uniform", "umls")
jr = jumps("uniform", "mlsRing")
print(f"uniform: crossing nodes x = {ju[0, 0]:g} ... {ju[-1, 0]:g}: "
      f"umls max jump w {ju[:, 1].max():.2e}, grad w {ju[:, 2].max():.2e}; "
      f"mlsRing max jump w {jr[:, 1].max():.2e}, grad w {jr[:, 2].max():.2e}")

fig, ax = plt.subplots(2, 2, figsize=(11, 7), sharex=True)
xs = np.linspace(0.5, 3.5, 1201)[1:]
for col, (name, kern) in enumerate((("umls (with eta)", umls), ("mlsRing (no eta)", ring))):
    for vx in (1.0, 2.0, 3.0):
        if vx not in kern:
            continue
        w, gw = kern[vx]
        lw = 2 if vx == 2 else 1
        ax[0, col].plot(px, w, lw=lw, label=f"node x = {vx:g}")
        ax[1, col].plot(px, gw, lw=lw, label=f"node x = {vx:g}")
    ax[0, col].plot(xs, analytic(F, xs, True), "k--", lw=1, label="(2.33) (umls), node x = 2")
    ax[1, col].plot(xs, analytic(G, xs, True), "k--", lw=1, label="(2.34) (umls), node x = 2")
    ax[0, col].set_title(f"uniform 1D mesh, {name}")
    ax[0, col].set_ylabel("w")
    ax[1, col].set_ylabel("dw/dx [1/m]")
    ax[1, col].set_xlabel("particle x [m]")
    for a in ax[:, col]:
        for xn in (1, 2, 3):
            a.axvline(xn, color="0.85", lw=0.8, zorder=0)
        a.legend(fontsize=7)
fig.suptitle(f"Fig. 2.5: umls node x = 2 vs (2.33)/(2.34) on (0.5, 1.5]: "
             f"max error w {maxErr(w2, f, inner):.1e}, dw/dx {maxErr(g2, g, inner):.1e}",
             fontsize=10)
fig.tight_layout()
fig.savefig("kernel1D_uniform.png", dpi=120)

# ---- shrinking/expanding mesh -----------------------------------------------
ju = jumps("shrinking", "umls")
jr = jumps("shrinking", "mlsRing")
print(f"shrinking: R = {ratio:g}, jumps across the interior nodes "
      f"(relative, x_n -/+ 1e-6):")
print("shrinking:   node  x_n        umls w    umls dw/dx  mlsRing w  mlsRing dw/dx")
for k in range(len(ju)):
    print(f"shrinking:   {k + 1:4d}  {ju[k, 0]:9.4f}  {ju[k, 1]:.2e}  {ju[k, 2]:.2e}"
          f"    {jr[k, 1]:.2e}   {jr[k, 2]:.2e}")
kr = int(np.argmax(np.maximum(jr[:, 1], jr[:, 2])))
print(f"shrinking: umls max jump w {ju[:, 1].max():.2e}, grad w {ju[:, 2].max():.2e}; "
      f"mlsRing max jump w {jr[:, 1].max():.2e}, grad w {jr[:, 2].max():.2e} "
      f"(largest at node {kr + 1}, x = {jr[kr, 0]:g})")

px, umls = load("shrinking", "umls")
_, ring = load("shrinking", "mlsRing")
nodes = np.concatenate(([0.0], ju[:, 0]))       # node k at nodes[k]
# Merge the node probes (x_n -/+ 1e-6) into the curves, so that a jump shows
# as a vertical step exactly at its node
pn, umlsN = load("shrinking", "umls", "nodes")
_, ringN = load("shrinking", "mlsRing", "nodes")


def curve(kern, kernN, vx):
    x = np.concatenate((px, pn))
    w = np.concatenate((kern.get(vx, (np.zeros_like(px),)*2)[0],
                        kernN.get(vx, (np.zeros_like(pn),)*2)[0]))
    g = np.concatenate((kern.get(vx, (np.zeros_like(px),)*2)[1],
                        kernN.get(vx, (np.zeros_like(pn),)*2)[1]))
    o = np.argsort(x, kind="stable")
    sel = (x[o] >= px[0]) & (x[o] <= px[-1])
    return x[o][sel], w[o][sel], g[o][sel]


fig, ax = plt.subplots(2, 2, figsize=(12, 7), sharex=True)
for row, (name, kern, kernN, J) in enumerate(
        (("umls (with eta)", umls, umlsN, ju), ("mlsRing (no eta)", ring, ringN, jr))):
    for k in (5, 6, 7, 8):
        x, w, gw = curve(kern, kernN, nodes[k])
        ax[row, 0].plot(x, w, label=f"node {k}, x = {nodes[k]:g}")
        ax[row, 1].plot(x, gw, label=f"node {k}")
    for a in ax[row]:
        for xn in nodes:
            if px[0] <= xn <= px[-1]:
                a.axvline(xn, color="0.85", lw=0.8, zorder=0)
        # Where the kernel jumps (> 1e-3 relative): red dotted lines
        for (xn, jw, jg) in J:
            if max(jw, jg) > 1e-3 and px[0] <= xn <= px[-1]:
                a.axvline(xn, color="r", ls=":", lw=1.2, zorder=0)
        a.legend(fontsize=7)
    top = max(J[:, 1].max(), J[:, 2].max())
    ax[row, 0].set_title(f"{name}: largest jump at a node {top:.1e} (relative)"
                         + ("; red: jumps > 1e-3" if top > 1e-3 else ""), fontsize=9)
    ax[row, 0].set_ylabel("w")
    ax[row, 1].set_ylabel("dw/dx [1/m]")
ax[1, 0].set_xlabel("particle x [m]")
ax[1, 1].set_xlabel("particle x [m]")
fig.suptitle(f"Fig. 2.7: periodically shrinking/expanding 1D mesh, cell sizes "
             f"[1, R, R^2, R], R = {ratio:g} (grey: nodes)", fontsize=10)
fig.tight_layout()
fig.savefig("kernel1D_shrinking.png", dpi=120)
