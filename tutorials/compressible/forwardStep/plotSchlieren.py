#!/usr/bin/python3
"""forwardStep (mpmFoam tutorial): numerical schlieren images.

Usage: plotSchlieren.py [-o outDir] [-sideBySide] <caseDir>... [<time>...]

Arguments that are numbers are times, the others case directories; without
times, every written time after 0.  Per case, writes
<outDir>/forwardStep_<case name>.png (outDir: the current directory) with
one image per time, stacked vertically, earliest on top.  With -sideBySide
(two or more cases), writes instead the single picture
<outDir>/forwardStep_sideBySide.png: one column per case in the order given
(Allrun: rhoCentralFoam left, shockMpmFoam right), the times stacked
vertically; without times, the times written by every case.

The image is S = exp(-15 |grad rho| / max |grad rho|) (max over that time's
fluid cells), drawn in grey from black (S = 0, steep density gradient) to
white (S = 1, uniform flow).  rho is read from the ascii field of the time
and put on the Cartesian i-j grid of the case from the cell centres (see
shockPositions.py: field C, written with postProcess -func
writeCellCentres when missing); grad rho is by central differences, one-sided
next to the step, whose cells (x > 0.6, y < 0.2) are left blank (grey).
Computed from rho for every solver alike, so shockMpmFoam's own schlieren
field is not used.
"""
import sys
import os
import glob
import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from shockPositions import Grid, DX, NX, NY, STEP_X, STEP_Y  # noqa: E402

K = 15.0


def maskedDiff(f, axis):
    """df/dx along axis: central where both neighbours are fluid (not NaN),
    one-sided where only one is, 0 where none is; NaN in NaN cells."""
    g = np.moveaxis(f, axis, 0)
    n = g.shape[0]
    lo = np.full_like(g, np.nan)
    hi = np.full_like(g, np.nan)
    lo[1:] = g[:-1]
    hi[:-1] = g[1:]
    central = (hi - lo)/(2*DX)
    fwd = (hi - g)/DX
    bwd = (g - lo)/DX
    d = np.where(np.isfinite(central), central,
                 np.where(np.isfinite(fwd), fwd,
                          np.where(np.isfinite(bwd), bwd, 0.0)))
    d[np.isnan(g)] = np.nan
    assert n == d.shape[0]
    return np.moveaxis(d, 0, axis)


def schlieren(rho):
    gx = maskedDiff(rho, 1)
    gy = maskedDiff(rho, 0)
    mag = np.hypot(gx, gy)
    return np.exp(-K*mag/np.nanmax(mag))


def writtenTimes(case):
    times = []
    for d in glob.glob(os.path.join(case, "*")):
        try:
            t = float(os.path.basename(d))
        except ValueError:
            continue
        if t > 0 and os.path.exists(os.path.join(d, "rho")):
            times.append((t, os.path.basename(d)))
    return [name for _, name in sorted(times)]


def drawPanel(ax, case, t, cmap):
    """The schlieren image of <case> at time <t> on the axes <ax>."""
    S = schlieren(Grid(case, t)["rho"])
    ax.imshow(S, origin="lower", extent=(0, NX*DX, 0, NY*DX), cmap=cmap,
              vmin=0, vmax=1, interpolation="nearest")
    ax.plot([STEP_X, STEP_X, NX*DX], [0, STEP_Y, STEP_Y], "k-", lw=0.8)
    ax.set_xlim(0, NX*DX)
    ax.set_ylim(0, NY*DX)


def grayMap():
    cmap = plt.get_cmap("gray").copy()
    cmap.set_bad("0.7")
    return cmap


def caseName(case):
    return os.path.basename(os.path.abspath(case))


def plotCase(case, times, outDir):
    name = caseName(case)
    times = times or writtenTimes(case)
    if not times:
        raise SystemExit("plotSchlieren: no written times in %s" % case)
    n = len(times)
    fig, axes = plt.subplots(n, 1, figsize=(9, 3.05*n + 0.5), squeeze=False)
    cmap = grayMap()
    for ax, t in zip(axes[:, 0], times):
        drawPanel(ax, case, t, cmap)
        ax.set_title("t = %s" % t, fontsize=10)
        ax.set_ylabel("y")
    axes[-1, 0].set_xlabel("x")
    fig.suptitle("forwardStep, Mach 3: numerical schlieren "
                 "exp(-%g |grad rho| / max |grad rho|), %s" % (K, name),
                 fontsize=11)
    fig.tight_layout(rect=(0, 0, 1, 1 - 0.35/(3.05*n + 0.5)))
    out = os.path.join(outDir, "forwardStep_%s.png" % name)
    fig.savefig(out, dpi=110)
    plt.close(fig)
    print("plotSchlieren: wrote %s (times %s)" % (out, " ".join(times)))


def plotSideBySide(cases, times, outDir):
    """One column per case, one row per time."""
    if not times:
        common = None
        for case in cases:
            w = writtenTimes(case)
            common = w if common is None \
                else [t for t in common if any(float(t) == float(s)
                                               for s in w)]
        times = common
    if not times:
        raise SystemExit("plotSchlieren: no time written by all of %s"
                         % " ".join(cases))
    names = [caseName(c) for c in cases]
    n, m = len(times), len(cases)
    fig, axes = plt.subplots(n, m, figsize=(7.2*m, 2.5*n + 0.6),
                             squeeze=False, sharex=True, sharey=True)
    cmap = grayMap()
    for r, t in enumerate(times):
        for c, case in enumerate(cases):
            ax = axes[r, c]
            drawPanel(ax, case, t, cmap)
            ax.set_title("%s, t = %s" % (names[c], t), fontsize=10)
            if c == 0:
                ax.set_ylabel("y")
    for ax in axes[-1, :]:
        ax.set_xlabel("x")
    fig.suptitle("forwardStep, Mach 3: numerical schlieren exp(-%g |grad rho|"
                 " / max |grad rho|), %s" % (K, " | ".join(names)),
                 fontsize=11)
    fig.tight_layout(rect=(0, 0, 1, 1 - 0.4/(2.5*n + 0.6)))
    out = os.path.join(outDir, "forwardStep_sideBySide.png")
    fig.savefig(out, dpi=100)
    plt.close(fig)
    print("plotSchlieren: wrote %s (%s; times %s)"
          % (out, " | ".join(names), " ".join(times)))


def main(argv):
    outDir = "."
    sideBySide = False
    while argv and argv[0] in ("-o", "-sideBySide"):
        if argv[0] == "-sideBySide":
            sideBySide, argv = True, argv[1:]
        elif len(argv) >= 2:
            outDir, argv = argv[1], argv[2:]
        else:
            sys.stderr.write(__doc__)
            return 2
    cases, times = [], []
    for a in argv:
        try:
            float(a)
            times.append(a)
        except ValueError:
            cases.append(a)
    if not cases or any(a in ("-h", "-help", "--help") for a in cases):
        sys.stderr.write(__doc__)
        return 0 if cases else 2
    if sideBySide:
        if len(cases) < 2:
            sys.stderr.write("plotSchlieren: -sideBySide needs two or more"
                             " cases\n")
            return 2
        plotSideBySide(cases, times, outDir)
        return 0
    for case in cases:
        plotCase(case, times, outDir)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
