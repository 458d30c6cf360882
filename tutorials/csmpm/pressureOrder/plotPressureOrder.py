#!/usr/bin/python3
"""pressureOrder: the picture of the B1B0/B2B1 ablation.

Usage: plotPressureOrder.py <table> <out.png>

<table> is Allrun's run/pressureOrder.dat (rows: run N steps CG L1 e338
symDiag symX wall cpu).  Left: L1(rho) against N for each run kind (B1B0,
B2B1 through the coupled system, gas: the gas-only semiImplicit stepper),
log-log, with the observed orders between neighbouring resolutions; right:
shockMpmFoam's CPU seconds against N.  Prints the orders and the relative
difference of B2B1 to B1B0 at each N.
"""

import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.ticker
import matplotlib.pyplot as plt
import numpy as np


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    rows = {}
    for line in open(sys.argv[1]):
        if line.startswith("#") or not line.strip():
            continue
        f = line.split()
        rows.setdefault(f[0], []).append(
            (int(f[1]), float(f[4]), float(f[9]), float(f[3])))
    style = {"B1B0": ("o-", "C0"), "B2B1": ("s-", "C3"),
             "gas": ("x--", "0.5")}
    label = {"B1B0": "coupled, gas B1B0", "B2B1": "coupled, gas B2B1",
             "gas": "gas only (semiImplicit)"}
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(10, 4.2))
    for kind in ("B1B0", "B2B1", "gas"):
        if kind not in rows:
            continue
        r = sorted(rows[kind])
        n = np.array([a[0] for a in r], float)
        l1 = np.array([a[1] for a in r])
        cpu = np.array([a[2] for a in r])
        m, c = style[kind]
        ax.loglog(n, l1, m, color=c, label=label[kind])
        bx.loglog(n, cpu, m, color=c, label=label[kind])
        orders = np.log(l1[:-1]/l1[1:])/np.log(n[1:]/n[:-1])
        print("%-5s L1 %s  orders %s" % (
            kind, " ".join("%.4e" % x for x in l1),
            " ".join("%.2f" % x for x in orders)))
        if kind != "gas":
            for i in range(len(orders)):
                ax.annotate("%.2f" % orders[i],
                            (np.sqrt(n[i]*n[i + 1]),
                             np.sqrt(l1[i]*l1[i + 1])),
                            textcoords="offset points",
                            xytext=(0, 8 if kind == "B1B0" else -14),
                            color=c, fontsize=8, ha="center")
    ns = sorted(set(x[0] for r in rows.values() for x in r))
    for a in (ax, bx):
        a.set_xticks(ns)
        a.set_xticklabels([str(x) for x in ns])
        a.xaxis.set_minor_locator(matplotlib.ticker.NullLocator())
    if "B1B0" in rows and "B2B1" in rows:
        a = dict((x[0], x[1]) for x in rows["B1B0"])
        b = dict((x[0], x[1]) for x in rows["B2B1"])
        for n in sorted(set(a) & set(b)):
            print("N %4d: (B2B1 - B1B0)/B1B0 = %+.2f %%"
                  % (n, 100*(b[n] - a[n])/a[n]))
    ax.set_xlabel("N (cells a side)")
    ax.set_ylabel("L1(rho) against the radial reference")
    ax.set_title("circular shock, t = 0.15")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    bx.set_xlabel("N (cells a side)")
    bx.set_ylabel("shockMpmFoam CPU [s]")
    bx.set_title("cost")
    bx.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=110)


if __name__ == "__main__":
    main()
