#!/usr/bin/python3
"""shuOsher: initial fields, errors and pictures of the Shu-Osher problem
(a Mach 3 shock running into the entropy wave rho = 1 + 0.2 sin(5 x)) on
x in [-5, 5] with N uniform cells, point values at the cell centres
x_i = -5 + (i + 1/2) 10/N:

    x < -4:  rho 3.857143, u 2.629369, p 10.33333   (post-shock)
    x > -4:  rho 1 + 0.2 sin(5 x), u 0, p 1

Usage:
    shuOsher.py init <case> <N>
        the internalField of <case>/0/{rho,U,p} (the boundary conditions of
        those files stay: the left patch's fixedValue is the inlet's state)
    shuOsher.py profile <case> <out>
        x rho U p at the latest time of <case> into the text file <out>
    shuOsher.py error <profile> <reference profile>
        prints "L1(rho) a  L1zoom(rho) b  maxError(rho) c": a = sum |rho -
        rho_ref| dx over [-5, 5] (rho_ref linearly interpolated to the
        centres of <profile>; N_ref an even multiple of N puts each centre
        half-way between two reference centres), b the same sum over the
        entropy-wave region x in [0.5, 2.5], c = max |rho - rho_ref|
    shuOsher.py sample <reference profile> <out> <N> ...
        x rho_ref at the cell centres of each N (sorted, duplicates once):
        a small stand-in for the reference that gives the same errors for
        runs with those N (the case test's stored reference)
    shuOsher.py plot <out.png> <reference profile> <label>=<profile> ...
        rho against x for each profile with the reference line, and a zoom
        on x in [0.5, 2.5]
"""

import os
import re
import sys

import numpy as np

X0, X1 = -5.0, 5.0
XS = -4.0
POST = (3.857143, 2.629369, 10.33333)
ZOOM = (0.5, 2.5)


def centres(n):
    return X0 + (np.arange(n) + 0.5)*(X1 - X0)/n


def initialState(x):
    post = x < XS
    rho = np.where(post, POST[0], 1 + 0.2*np.sin(5*x))
    u = np.where(post, POST[1], 0.0)
    p = np.where(post, POST[2], 1.0)
    return rho, u, p


def setInternalField(path, values, vector):
    """Replace the internalField entry of an OpenFOAM field file"""
    text = open(path).read()
    if vector:
        body = "\n".join("(%.17g 0 0)" % v for v in values)
        kind = "vector"
    else:
        body = "\n".join("%.17g" % v for v in values)
        kind = "scalar"
    new = "internalField   nonuniform List<%s>\n%d\n(\n%s\n);" % (
        kind, len(values), body)
    text, n = re.subn(r"^internalField\s[^;]*;", lambda m: new, text,
                      count=1, flags=re.M)
    if n != 1:
        sys.exit("shuOsher.py: no internalField entry in %s" % path)
    open(path, "w").write(text)


def init(case, n):
    rho, u, p = initialState(centres(n))
    setInternalField(os.path.join(case, "0", "rho"), rho, False)
    setInternalField(os.path.join(case, "0", "U"), u, True)
    setInternalField(os.path.join(case, "0", "p"), p, False)


def latestTime(case):
    times = []
    for d in os.listdir(case):
        try:
            times.append((float(d), d))
        except ValueError:
            pass
    if not times:
        sys.exit("shuOsher.py: no time directory in %s" % case)
    return max(times)[1]


def readInternal(path):
    text = open(path).read()
    m = re.search(r"internalField\s+nonuniform\s+List<(scalar|vector)>"
                  r"\s*(\d+)\s*\(", text)
    if not m:
        sys.exit("shuOsher.py: no nonuniform internalField in %s" % path)
    n = int(m.group(2))
    body = text[m.end():]
    if m.group(1) == "scalar":
        values = np.array(body.split(None, n)[:n], dtype=float)
    else:
        nums = re.findall(r"\(([^()]*)\)", body[:body.index("\n)")])
        values = np.array([float(v.split()[0]) for v in nums[:n]])
    if len(values) != n:
        sys.exit("shuOsher.py: %s: %d values, expected %d"
                 % (path, len(values), n))
    return values


def profile(case, out):
    time = latestTime(case)
    rho = readInternal(os.path.join(case, time, "rho"))
    u = readInternal(os.path.join(case, time, "U"))
    p = readInternal(os.path.join(case, time, "p"))
    x = centres(len(rho))
    np.savetxt(out, np.column_stack((x, rho, u, p)), fmt="%.12g",
               header="Shu-Osher, %s at t = %s, %d cells\nx rho U p"
               % (case, time, len(rho)))


def errors(prof, ref):
    x, rho = prof[:, 0], prof[:, 1]
    dx = (X1 - X0)/len(x)
    e = np.abs(rho - np.interp(x, ref[:, 0], ref[:, 1]))
    zoom = (x > ZOOM[0]) & (x < ZOOM[1])
    return e.sum()*dx, e[zoom].sum()*dx, e.max()


def error(profPath, refPath):
    l1, l1zoom, emax = errors(np.loadtxt(profPath), np.loadtxt(refPath))
    print("L1(rho) %.4e  L1zoom(rho) %.4e  maxError(rho) %.4e"
          % (l1, l1zoom, emax))


def sample(refPath, out, ns):
    ref = np.loadtxt(refPath)
    x = np.unique(np.concatenate([centres(n) for n in ns]))
    np.savetxt(out, np.column_stack((x, np.interp(x, ref[:, 0], ref[:, 1]))),
               fmt="%.12g", header="Shu-Osher reference rho at t = 1.8 from"
               " %s (%d cells), at the centres of %s cells\nx rho"
               % (refPath, len(ref), ", ".join(str(n) for n in ns)))


def plot(out, refPath, runs):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ref = np.loadtxt(refPath)
    fig, (ax, az) = plt.subplots(2, 1, figsize=(8, 8.5))
    for a in (ax, az):
        a.plot(ref[:, 0], ref[:, 1], "k-", lw=0.9,
               label="reference (%d cells)" % len(ref))
    styles = ["o", "s", "^", "v", "D", "x", "+"]
    for k, run in enumerate(runs):
        label, path = run.split("=", 1)
        d = np.loadtxt(path)
        l1, l1zoom, _ = errors(d, ref)
        for a, ms in ((ax, 2.2), (az, 3.5)):
            a.plot(d[:, 0], d[:, 1], styles[k % len(styles)], ms=ms,
                   mfc="none", mew=0.7, ls="-", lw=0.4,
                   label="%s: L1 %.3g (zoom %.3g)" % (label, l1, l1zoom))
    ax.axvspan(ZOOM[0], ZOOM[1], color="0.9", zorder=0)
    zoom = (ref[:, 0] > ZOOM[0]) & (ref[:, 0] < ZOOM[1])
    lo, hi = ref[zoom, 1].min(), ref[zoom, 1].max()
    az.set_xlim(*ZOOM)
    az.set_ylim(lo - 0.25*(hi - lo), hi + 0.15*(hi - lo))
    for a in (ax, az):
        a.set_xlabel("x")
        a.set_ylabel("rho")
        a.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="lower left")
    ax.set_title("Shu-Osher, shockMpmFoam, t = 1.8")
    az.set_title("entropy-wave region x in [%g, %g]" % ZOOM, fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print("Picture: %s" % os.path.abspath(out))


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    cmd, args = sys.argv[1], sys.argv[2:]
    if cmd == "init" and len(args) == 2:
        init(args[0], int(args[1]))
    elif cmd == "profile" and len(args) == 2:
        profile(args[0], args[1])
    elif cmd == "error" and len(args) == 2:
        error(args[0], args[1])
    elif cmd == "sample" and len(args) >= 3:
        sample(args[0], args[1], [int(n) for n in args[2:]])
    elif cmd == "plot" and len(args) >= 3:
        plot(args[0], args[1], args[2:])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
