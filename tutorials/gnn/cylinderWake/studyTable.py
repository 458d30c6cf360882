#!/usr/bin/python3
"""gnn/cylinderWake study: the README's table of the measured front.

Usage: studyTable.py [study dir]   (default: study/bsms)

From mpmFoamStudy's results.csv and each point's kept logs (log.bsmsTrain,
log.solver): the settings, the training budget (steps) and its measured
time, RMSE-all, the inference cost (the timed solver's wall time over the
30 simulated time units, and bsmsFoam's own time per model step), the
reference pimpleFoam's cost (the recording's time step) and the front flag.
"""
import csv
import os
import re
import sys

sdir = sys.argv[1] if len(sys.argv) > 1 else os.path.join("study", "bsms")
rows = list(csv.DictReader(open(os.path.join(sdir, "results.csv"))))
SPAN = 30.0     # t = 30..60: system/controlDict


def grep(path, pattern):
    try:
        with open(path, errors="replace") as f:
            found = [re.search(pattern, l) for l in f]
    except OSError:
        return None
    found = [m for m in found if m]
    return found[-1].groups() if found else None


def pdir(r):
    return os.path.join(sdir, "p%03d" % int(r["point"]))


ok = [r for r in rows if r["status"] == "ok"]
truth = [r for r in ok if r["solver"] == "pimpleFoam" and r["substeps"] == "14"]
pimpleWall = float(truth[0]["wall_s"]) if truth else None

head = ["point", "solver", "width", "levels", "training budget [steps]",
        "training time [s]", "RMSE-all [m/s]", "wall (CPU) time, t = 30..60 [s]",
        "wall per unit time [s]", "ms per model step (model only)",
        "pimpleFoam's cost per unit time [s]", "speed-up", "on front"]
print("| " + " | ".join(head) + " |")
print("|" + "---|"*len(head))
for r in sorted(ok, key=lambda r: float(r["wall_s"])):
    p = pdir(r)
    wall = float(r["wall_s"])
    if r["solver"] == "bsmsFoam":
        t = grep(os.path.join(p, "log.bsmsTrain"),
                 r"^Training: (\d+) steps in ([\d.]+) s")
        m = grep(os.path.join(p, "log.solver"),
                 r"model steps in \S+ s \(([\d.]+) ms per step, model only ([\d.]+) ms")
        n = r.get("N", "(case)")
        solver = "bsmsFoam" if n in ("0", "(case)") else \
            "bsmsFoam, hybrid N %s K %s" % (
                n, r.get("K") if r.get("K") not in (None, "(case)") else "1")
        width, levels = r["width"], r["levels"]
        budget = t[0] if t else r["trainSteps"]
        train = t[1] if t else "-"
        perStep = "%s (%s)" % m if m else "-"
    else:
        solver = "pimpleFoam, %s steps per model step" % r["substeps"]
        if r.get("ranks") not in (None, "(case)", "1"):
            solver += ", %s ranks" % r["ranks"]
        width = levels = budget = train = perStep = "-"
    print("| " + " | ".join([
        r["point"], solver, width, levels, budget, train,
        "%.4g" % float(r["RMSE-all"]), "%.2f (%.2f)" % (wall, float(r["cpu_s"])),
        "%.4f" % (wall/SPAN),
        perStep,
        "%.4f" % (pimpleWall/SPAN) if pimpleWall else "-",
        "%.2f" % (pimpleWall/wall) if pimpleWall else "-",
        "reference" if r["reference"] != "no" else r["front"]]) + " |")
bad = [r for r in rows if r["status"] != "ok"]
for r in bad:
    print("\npoint %s: %s (see %s)" % (r["point"], r["status"], r["log"]))
