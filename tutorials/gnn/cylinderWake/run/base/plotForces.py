#!/usr/bin/python3
"""Plot the force coefficients and the lift spectrum of cylinderWake2D.

Usage (from the case directory, or give the case directory):
    /usr/bin/python3 plotForces.py [caseDir] [-startTime T] [-o file.png]

Writes cylinderWake2D.png:
  top:    Cl and Cd against time (postProcessing/forceCoeffs/*/coefficient.dat)
  bottom: power spectrum of Cl against the Strouhal number St = f D / U,
          with the dominant peak marked.
The spectrum is read from the spectrum function object's output
(postProcessing/spectrum/<time>/spectrum.dat and peaks.dat) when present;
otherwise it is computed here from coefficient.dat (samples after startTime,
linear detrend, Hann window, zero padding, parabolic peak interpolation).
The Strouhal number of the lift oscillation is printed as "St = ...".
"""

import glob
import os
import re
import sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

D = 1.0      # cylinder diameter (reference length)
UINF = 1.0   # inflow speed (reference speed)


def time_dirs(pattern):
    """Files matching pattern, one per time directory, latest time last."""
    def key(path):
        try:
            return float(os.path.basename(os.path.dirname(path)))
        except ValueError:
            return -1.0
    return sorted(glob.glob(pattern), key=key)


def read_table(path):
    """Tab-separated OpenFOAM table: (column names, data array).

    The names come from the last '#' comment line before the data.
    """
    names, rows = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                if not rows:
                    names = [n.strip() for n in line[1:].split("\t")]
                continue
            if line.strip():
                rows.append([float(v) for v in line.split()])
    return names, np.array(rows)


def read_coefficients(case):
    """Time, Cd, Cl from all coefficient.dat files (restarts appended)."""
    files = time_dirs(os.path.join(case, "postProcessing", "forceCoeffs",
                                   "*", "coefficient.dat"))
    if not files:
        sys.exit("plotForces.py: no postProcessing/forceCoeffs/*/"
                 "coefficient.dat in " + case)
    t, cd, cl = [], [], []
    for path in files:
        names, data = read_table(path)
        if data.size == 0:
            continue
        col = {n.split()[0]: i for i, n in enumerate(names) if n}
        t.append(data[:, col["Time"]])
        cd.append(data[:, col["Cd"]])
        cl.append(data[:, col["Cl"]])
    t, cd, cl = (np.concatenate(a) for a in (t, cd, cl))
    # keep the last value of repeated times (restarts)
    _, idx = np.unique(t[::-1], return_index=True)
    idx = len(t) - 1 - idx
    return t[idx], cd[idx], cl[idx]


def spectrum_start_time(case):
    """startTime of the spectrum function object: from Allrun's
    system/allrunSettings if present, else from system/controlDict."""
    for name in ("allrunSettings", "controlDict"):
        try:
            text = open(os.path.join(case, "system", name)).read()
        except OSError:
            continue
        m = re.search(r"\bspectrum\s*\{[^}]*?\bstartTime\s+([-+0-9.eE]+)\s*;",
                      text)
        if m:
            return float(m.group(1))
    return None


def parabolic_peak(x, y, k):
    """Vertex of the parabola through (x, y) at k-1, k, k+1."""
    if 0 < k < len(y) - 1:
        a, b, c = y[k - 1], y[k], y[k + 1]
        den = a - 2.0*b + c
        if den != 0.0:
            p = 0.5*(a - c)/den
            return x[k] + p*(x[1] - x[0]), b - 0.25*(a - c)*p
    return x[k], y[k]


def compute_spectrum(t, s, start, pad=16):
    """One-sided PSD of s(t) for t >= start: (f, power, peak f, peak power)."""
    sel = t >= start
    t, s = t[sel], s[sel]
    if len(t) < 16:
        sys.exit("plotForces.py: fewer than 16 samples after t = %g" % start)
    # resample to uniform steps (the run's steps may vary)
    n = len(t)
    dt = (t[-1] - t[0])/(n - 1)
    tu = t[0] + dt*np.arange(n)
    s = np.interp(tu, t, s)
    s = s - np.polyval(np.polyfit(tu, s, 1), tu)     # linear detrend
    w = np.hanning(n)
    nfft = 1 << int(np.ceil(np.log2(n*pad)))          # zero padding
    X = np.fft.rfft(s*w, nfft)
    f = np.fft.rfftfreq(nfft, dt)
    power = 2.0*dt*np.abs(X)**2/np.sum(w**2)
    k = int(np.argmax(power[1:])) + 1
    # parabola through the log power (exact for a Gaussian-like peak)
    fp, lp = parabolic_peak(f, np.log(power + 1e-300), k)
    return f, power, fp, np.exp(lp), (t[0], t[-1])


def read_spectrum(case):
    """Cl spectrum from the spectrum function object, or None."""
    files = time_dirs(os.path.join(case, "postProcessing", "spectrum", "*",
                                   "spectrum.dat"))
    if not files:
        return None
    path = files[-1]
    names, data = read_table(path)
    if data.size == 0:
        return None
    trange = None
    with open(path) as fh:
        for line in fh:
            m = re.match(r"#.*\bfrom t = ([-+0-9.eE]+) to ([-+0-9.eE]+)", line)
            if m:
                trange = (float(m.group(1)), float(m.group(2)))
                break
    icl = [i for i, n in enumerate(names) if n.split()[:1] == ["Cl"]]
    if not icl:
        return None
    f, power = data[:, 0], data[:, icl[0]]
    fp, pp = None, None
    peaks = os.path.join(os.path.dirname(path), "peaks.dat")
    if os.path.isfile(peaks):
        with open(peaks) as fh:
            for line in fh:
                v = line.split()
                if line.startswith("#") or len(v) < 5:
                    continue
                if v[0] == "Cl" and v[1] == "1":
                    fp, pp = float(v[2]), float(v[4])
                    break
    if fp is None:
        k = int(np.argmax(power[1:])) + 1
        fp, pp = parabolic_peak(f, power, k)
    return f, power, fp, pp, os.path.relpath(path, case), trange


def main(argv):
    case, start, out = ".", None, None
    args = list(argv)
    while args:
        a = args.pop(0)
        if a == "-startTime":
            start = float(args.pop(0))
        elif a == "-o":
            out = args.pop(0)
        elif a in ("-h", "-help", "--help"):
            print(__doc__)
            return 0
        else:
            case = a
    out = out or os.path.join(case, "cylinderWake2D.png")

    t, cd, cl = read_coefficients(case)

    spec = None if start is not None else read_spectrum(case)
    if spec is not None:
        f, power, fp, pp, source, trange = spec
        label = "spectrum function object (%s)" % source
        start = trange[0] if trange else spectrum_start_time(case)
        if trange:
            label += ", t = %.4g to %.4g" % trange
    else:
        if start is None:
            start = spectrum_start_time(case)
        if start is None or start >= t[-1]:
            start = t[0] + 0.5*(t[-1] - t[0])
        f, power, fp, pp, (t0, t1) = compute_spectrum(t, cl, start)
        label = "numpy: Hann, linear detrend, t = %.4g to %.4g" % (t0, t1)

    St = fp*D/UINF
    sel = t >= (start if start is not None else t[0])
    print("Cl amplitude  = %.4f" % (0.5*(cl[sel].max() - cl[sel].min())))
    print("Cd mean       = %.4f" % cd[sel].mean())
    print("St = %.4f   (f = %.5f 1/s, from %s)" % (St, fp, label))

    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(8, 8))
    ax1.plot(t, cl, lw=0.8, label="$C_l$")
    ax1.plot(t, cd, lw=0.8, label="$C_d$")
    if start is not None:
        ax1.axvline(start, color="gray", ls="--", lw=0.8,
                    label="spectrum start")
    # y range without the impulsive start (huge Cd in the first steps)
    late = t >= min(5.0, 0.5*t[-1])
    lo = min(cl[late].min(), cd[late].min())
    hi = max(cl[late].max(), cd[late].max())
    ax1.set_ylim(lo - 0.15*(hi - lo), hi + 0.15*(hi - lo))
    ax1.set_xlabel("t U / D")
    ax1.set_ylabel("coefficient")
    ax1.set_title("Cylinder wake, Re = 100")
    ax1.legend(loc="lower right", fontsize=8)
    ax1.grid(alpha=0.3)

    st = f*D/UINF
    ax2.semilogy(st, power, lw=0.9, label="$C_l$ power spectrum")
    ax2.plot([St], [pp], "rv", label="peak St = %.4f" % St)
    ax2.axvline(0.165, color="gray", ls=":", lw=0.8,
                label="reference St = 0.165")
    ax2.set_xlim(0.0, 1.0)
    top = power[st <= 1.0].max()
    ax2.set_ylim(top*1e-8, top*10)
    ax2.set_xlabel("St = f D / U")
    ax2.set_ylabel("PSD")
    ax2.set_title(label, fontsize=9)
    ax2.legend(fontsize=8)
    ax2.grid(alpha=0.3)

    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print("Wrote " + out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
