#!/usr/bin/python3
"""cylinderWake: RMSE against rollout step and training time for BSMS-GNN and
MeshGraphNets, and the table of costs (run/results.md, run/results.dat).

Usage: plotCylinderWake.py <run dir> <held-out case name>
"""
import os
import re
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

run, held = sys.argv[1], sys.argv[2]
names = {"bsms": "BSMS-GNN", "mgn": "MeshGraphNets"}


def grep(path, pattern, cast=float):
    """Groups of the last match of pattern in a file (None if none)."""
    last = None
    with open(path) as f:
        for line in f:
            m = re.search(pattern, line)
            if m:
                last = m
    if last is None:
        raise SystemExit("no '%s' in %s" % (pattern, path))
    return [cast(g) for g in last.groups()]


def grepAll(path, pattern, cast=float):
    """Groups of every match of pattern in a file, in order."""
    with open(path) as f:
        return [[cast(g) for g in m.groups()]
                for m in (re.search(pattern, line) for line in f) if m]


def trainingTime(stages, step):
    """Training wall-clock time [s] at a step: the stages' (steps, seconds)
    in order, each at its own rate (a rollout stage's steps cost more)."""
    t, first = 0.0, 0
    for n, secs in stages:
        if step <= first + n:
            return t + (step - first)*secs/n
        t += secs
        first += n
    return t


def table(path):
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            rows.append(line.split())
    return rows


r = {}
for m in names:
    log = os.path.join(run, m, "log.bsmsTrain")
    # The training stages (bsmsTrain runs resumed one after the other)
    stages = [(int(n), s) for n, s in
              grepAll(log, r"Training: (\d+) steps in ([\d.]+) s \(")]
    if not stages:
        raise SystemExit("no 'Training:' line in %s" % log)
    steps = sum(n for n, _ in stages)
    secs = sum(s for _, s in stages)
    perStep = secs/steps
    peak, rss0, rssTrain, trainPeak = grep(
        log, r"Memory: peak resident ([\d.]+) MB; ([\d.]+) MB before the model, "
             r"([\d.]+) MB before training; training peak ([-\d.]+) MB above")
    e1, e50, eall, nroll, inferMs = grep(
        log, r"Validation \S+ at step \d+: RMSE-1 (\S+)  RMSE-50 (\S+)  RMSE-all (\S+)"
             r"  \((\d+) steps, ([\d.]+) ms per model step\)")
    nFoam, foamWall, foamMs, modelMs, foamPerUnit = grep(
        os.path.join(run, m + "Foam", "log.bsmsFoam"),
        r"(\d+) model steps in ([\d.]+) s \(([\d.]+) ms per step, model only ([\d.]+) ms\);"
        r" ([\d.]+) s per unit")
    levels = grep(log, r"levels \(nodes ([\d ]+)\)", str)[0]
    params = grep(log, r"(\d+) parameters", int)[0]
    r[m] = dict(steps=steps, secs=secs, perStep=perStep, stages=stages, peak=peak,
                trainPeak=trainPeak, rss0=rss0, e1=e1, e50=e50, eall=eall,
                nroll=nroll, inferMs=inferMs, foamWall=foamWall, foamMs=foamMs,
                modelMs=modelMs, foamPerUnit=foamPerUnit, levels=levels,
                params=params,
                rollout=table(os.path.join(run, m, "postProcessing", "bsmsTrain",
                                           "rollout_%s.dat" % held)),
                valid=table(os.path.join(run, m, "postProcessing", "bsmsTrain",
                                         "validation.dat")))

# pimpleFoam on the held-out case: the recording run's wall-clock time
# (serial; Allrun runs the held-out case alone)
pimpleClock = float(open(os.path.join(run, held, "recordWallTime")).read())
rollT = [float(row[1]) for row in r["bsms"]["rollout"]]
span = rollT[-1] - (rollT[0] - (rollT[1] - rollT[0]))
pimplePerUnit = pimpleClock/span

for m in names:
    r[m]["speedup"] = pimplePerUnit/r[m]["foamPerUnit"]

# The reference: the start state held over the rollout
held50, heldAll = grep(os.path.join(run, "bsms", "log.bsmsTrain"),
                       r"the start state held: RMSE-50 (\S+)  RMSE-all (\S+)")

# Plot
fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
for m, c in (("bsms", "C0"), ("mgn", "C3")):
    steps = [int(row[0]) for row in r[m]["rollout"]]
    ax[0].semilogy(steps, [float(row[2]) for row in r[m]["rollout"]], c,
                   label="%s (RMSE-all %.3g)" % (names[m], r[m]["eall"]))
    v = r[m]["valid"]
    ax[1].semilogy([trainingTime(r[m]["stages"], int(row[0]))/60 for row in v],
                   [float(row[4]) for row in v], c + "o-", label=names[m])
ax[0].axhline(heldAll, color="0.5", ls="--",
              label="start state held (RMSE-all %.3g)" % heldAll)
ax[0].set_xlabel("rollout step (model deltaT)")
ax[0].set_ylabel("RMSE of U against pimpleFoam [m/s]")
ax[0].set_title("held-out inflow %s: rollout from the recorded start" % held[1:])
ax[0].legend()
ax[1].set_xlabel("training wall-clock time [min]")
ax[1].set_ylabel("RMSE-all on the held-out case [m/s]")
ax[1].set_title("validation during training")
ax[1].legend()
fig.tight_layout()
fig.savefig(os.path.join(run, "cylinderWake.png"), dpi=110)

b, g = r["bsms"], r["mgn"]
rows = [
    ("graph levels (nodes)", b["levels"], g["levels"], None),
    ("parameters", b["params"], g["params"], b["params"]/g["params"]),
    ("training steps (one-step + rollout stage)", "%d (%s)" % (b["steps"], " + ".join(str(n) for n, _ in b["stages"])),
     "%d (%s)" % (g["steps"], " + ".join(str(n) for n, _ in g["stages"])), b["steps"]/g["steps"]),
    ("training time [s]", b["secs"], g["secs"], b["secs"]/g["secs"]),
    ("training time per step, over the stages [ms]", 1e3*b["perStep"], 1e3*g["perStep"], b["perStep"]/g["perStep"]),
    ("peak memory of the process [MB]", b["peak"], g["peak"], b["peak"]/g["peak"]),
    ("peak training memory above the loaded data [MB]", b["trainPeak"], g["trainPeak"],
     b["trainPeak"]/g["trainPeak"]),
    ("RMSE-1 [m/s]", b["e1"], g["e1"], b["e1"]/g["e1"]),
    ("RMSE-50 [m/s]", b["e50"], g["e50"], b["e50"]/g["e50"]),
    ("RMSE-all [m/s] (%d steps)" % b["nroll"], b["eall"], g["eall"], b["eall"]/g["eall"]),
    ("RMSE-50 / RMSE-all of holding the start state [m/s]", "%.4g / %.4g" % (held50, heldAll), "", None),
    ("inference time per model step [ms]", b["modelMs"], g["modelMs"], b["modelMs"]/g["modelMs"]),
    ("bsmsFoam wall time per unit simulated time [s]", b["foamPerUnit"], g["foamPerUnit"],
     b["foamPerUnit"]/g["foamPerUnit"]),
    ("speed-up against serial pimpleFoam (%.3f s per unit time), bsmsFoam on 1 thread" % pimplePerUnit,
     b["speedup"], g["speedup"], None),
]


def fmt(x):
    if isinstance(x, str):
        return x
    if isinstance(x, int):
        return "%d" % x
    return "%.4g" % x


with open(os.path.join(run, "results.md"), "w") as f:
    f.write("| cylinderWake, held-out inflow %s | BSMS-GNN | MeshGraphNets | BSMS/MGN |\n"
            % held[1:])
    f.write("|---|---|---|---|\n")
    for name, x, y, q in rows:
        f.write("| %s | %s | %s | %s |\n" % (name, fmt(x), fmt(y), "" if q is None else "%.3f" % q))
with open(os.path.join(run, "results.dat"), "w") as f:
    for m in names:
        for k in ("perStep", "peak", "trainPeak", "e1", "e50", "eall", "modelMs",
                  "foamPerUnit", "speedup", "steps"):
            f.write("%s_%s %.6g\n" % (m, k, r[m][k]))
    f.write("pimplePerUnit %.6g\n" % pimplePerUnit)
print(open(os.path.join(run, "results.md")).read())
