#!/usr/bin/python3
"""riemannProblems: one picture per problem, riemannProblems_<problem>.png,
with rho, U and p against x at the end time: the exact solution (a line, at
the cell centres) and each stepper's cells (markers), from
<problem>/<stepper>/postProcessing/riemannCompare/<time>/profile.dat
(columns x rho U p rhoExact Uexact pExact).

Usage: plotRiemannProblems.py [riemannProblems.dat]
    (the table Allrun writes: which problems and steppers ran)
"""

import glob
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

TITLES = {
    "sod": "Sod",
    "lax": "Lax",
    "toro1": "Toro test 1 (sonic rarefaction)",
    "toro2": "Toro test 2 (123 problem, near vacuum)",
    "toro3": "Toro test 3 (left half of the blast wave)",
    "toro4": "Toro test 4 (two colliding shocks)",
    "toro5": "Toro test 5 (stationary contact)",
}
MARKERS = {"explicit": ("o", "tab:blue"), "semiImplicit": ("x", "tab:red")}


def latestProfile(run):
    """profile.dat of the latest compared time of one run, or None"""
    files = glob.glob(os.path.join(run, "postProcessing", "riemannCompare",
                                   "*", "profile.dat"))
    if not files:
        return None
    return max(files, key=lambda f: float(os.path.basename(os.path.dirname(f))))


def main():
    table = sys.argv[1] if len(sys.argv) > 1 else "riemannProblems.dat"
    runs = {}
    with open(table) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            words = line.split()
            runs.setdefault(words[0], []).append((words[1], words[3]))

    for problem, steppers in runs.items():
        fig, axes = plt.subplots(3, 1, figsize=(7, 9), sharex=True)
        exactDrawn = False
        time = None
        for stepper, l1rho in steppers:
            path = latestProfile(os.path.join(problem, stepper))
            if path is None:
                print("plotRiemannProblems: %s/%s: no profile (run failed)"
                      % (problem, stepper))
                continue
            time = os.path.basename(os.path.dirname(path))
            d = np.loadtxt(path, comments="#")
            x = d[:, 0]
            if not exactDrawn:
                for k, ax in enumerate(axes):
                    ax.plot(x, d[:, 4 + k], "k-", lw=1.0, label="exact")
                exactDrawn = True
            marker, colour = MARKERS.get(stepper, ("s", "tab:green"))
            for k, ax in enumerate(axes):
                ax.plot(x, d[:, 1 + k], marker, color=colour, ms=2.5,
                        mfc="none", mew=0.7, ls="none",
                        label="%s, L1(rho) %s" % (stepper, l1rho))
        if not exactDrawn:
            plt.close(fig)
            print("plotRiemannProblems: %s: no picture" % problem)
            continue
        for ax, name in zip(axes, ("rho", "U", "p")):
            ax.set_ylabel(name)
            ax.grid(alpha=0.3)
        axes[0].legend(fontsize=8)
        axes[-1].set_xlabel("x")
        axes[0].set_title("%s, t = %s" % (TITLES.get(problem, problem), time))
        fig.tight_layout()
        out = "riemannProblems_%s.png" % problem
        fig.savefig(out, dpi=110)
        plt.close(fig)
        print("Picture: %s" % os.path.abspath(out))


if __name__ == "__main__":
    main()
