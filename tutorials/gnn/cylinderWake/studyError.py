#!/usr/bin/python3
"""gnn/cylinderWake study: RMSE-all of a point's run on the held-out inflow.

Usage: studyError.py [case] [recording]   (default: . and data/U1.0)

The error of what the timed solver wrote (bsmsFoam's rollout or the
reference pimpleFoam), against the recording at the same times:
sqrt(mean over the written times after the start of the MSE of U over
cells and the x and y components) -- bsmsTrain's RMSE-all (top-level
README), here over every written time after startTime.  Every recorded
time after the start must have been written; a missing or non-finite
field is an error (exit 1), never a number.
"""
import math
import os
import re
import sys

case = sys.argv[1] if len(sys.argv) > 1 else "."
rec = sys.argv[2] if len(sys.argv) > 2 else os.path.join(case, "data", "U1.0")


def die(msg):
    sys.exit("studyError: " + msg)


def startTime(path):
    m = re.search(r"^\s*startTime\s+([^;\s]+)\s*;",
                  open(os.path.join(path, "system", "controlDict")).read(), re.M)
    if not m:
        die("no startTime in %s/system/controlDict" % path)
    return float(m.group(1))


def times(path, after):
    """{time: directory name} of the times after 'after' with a U"""
    out = {}
    for n in os.listdir(path):
        try:
            t = float(n)
        except ValueError:
            continue
        if t > after + 1e-9 and os.path.isfile(os.path.join(path, n, "U")):
            out[t] = n
    return out


def match(want, have):
    """{recorded time: the point's directory} at most 1e-4 apart: a run
    of fixed steps drifts off the written times by round-off (pimpleFoam
    then writes 33.000001 for 33), 1e-4 is far below the model step 0.5"""
    out = {}
    hs = sorted(have)
    for t in want:
        near = min(hs, key=lambda h: abs(h - t)) if hs else None
        if near is not None and abs(near - t) <= 1e-4:
            out[t] = have[near]
    return out


def internalU(path):
    s = open(path).read()
    m = re.search(r"internalField\s+nonuniform\s+List<vector>\s*(\d+)\s*\(", s)
    if not m:
        die("%s: no nonuniform internalField" % path)
    n = int(m.group(1))
    v = re.findall(r"\(([^()]*)\)", s[m.end():])[:n]
    if len(v) != n:
        die("%s: %d of %d values" % (path, len(v), n))
    return [tuple(float(x) for x in t.split()[:2]) for t in v]


t0 = startTime(case)
want, have = times(rec, t0), times(case, t0)
if not want:
    die("no recorded times after %g in %s" % (t0, rec))
have = match(want, have)
missing = sorted(set(want) - set(have))
if missing:
    die("%s wrote %d of the %d recorded times after %g (first missing %g)"
        % (case, len(want) - len(missing), len(want), t0, missing[0]))
mse = []
for t in sorted(want):
    a = internalU(os.path.join(case, have[t], "U"))
    b = internalU(os.path.join(rec, want[t], "U"))
    if len(a) != len(b):
        die("t = %g: %d cells against the recording's %d" % (t, len(a), len(b)))
    s = sum((p[0] - q[0])**2 + (p[1] - q[1])**2 for p, q in zip(a, b))
    e = s/(2*len(a))
    if not math.isfinite(e):
        die("t = %g: non-finite U" % t)
    mse.append(e)
print("RMSE-1st = %.6e" % math.sqrt(mse[0]))
print("RMSE-all = %.10g (%d steps, t = %g..%g)"
      % (math.sqrt(sum(mse)/len(mse)), len(mse), min(want), max(want)))
