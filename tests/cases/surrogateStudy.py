#!/usr/bin/python3
"""The numbers a surrogate study's case test checks, from mpmFoamStudy's
results.csv (tutorials/gnn/*/system/studyDict.quick).

Usage: surrogateStudy.py RESULTS.csv

Prints one line each:
    rows N OK              points, and those that finished
    reference N E          reference points, the first one's error
    cheap N MIN MAX        the solver's other serial points: count, errors
    parallel N D           the solver's points on more ranks, and the largest
                           relative difference of their error from the
                           serial point with the same other settings
    pure N E               bsmsFoam points with N 0 (the pure rollout)
    hybrids N MAX          bsmsFoam points with N > 0, their largest error
    frontWrong N           points whose front flag is not "undominated"
The error is the study's last column before "front" (its error's name).
"""
import csv
import sys

rows = list(csv.DictReader(open(sys.argv[1])))
cols = list(rows[0].keys()) if rows else []
errCol = cols[cols.index("front") - 1] if "front" in cols else None
ok = [r for r in rows if r["status"] == "ok"]
e = lambda r: float(r[errCol])
c = lambda r: float(r["wall_s"])
ranks = lambda r: r.get("ranks", "1") if r.get("ranks") != "(case)" else "1"
isModel = lambda r: r["solver"] == "bsmsFoam"
print("rows", len(rows), len(ok))

ref = [r for r in ok if r["reference"] == "yes"]
print("reference", len(ref), e(ref[0]) if ref else -1)

solver = [r for r in ok if not isModel(r) and r["reference"] != "yes"]
serial = [r for r in solver if ranks(r) == "1"]
print("cheap", len(serial), min(map(e, serial), default=-1),
      max(map(e, serial), default=-1))
rest = [n for n in cols if n not in ("ranks", "point") and n in rows[0]
        and cols.index(n) < cols.index("status")]
same = lambda a, b: all(a[n] == b[n] for n in rest)
diffs = [abs(e(p)/e(s) - 1) for p in solver if ranks(p) != "1"
         for s in serial if same(p, s)]
print("parallel", len(diffs), max(diffs, default=-1))

pure = [r for r in ok if isModel(r) and r["N"] == "0"]
hyb = [r for r in ok if isModel(r) and r["N"] != "0"]
print("pure", len(pure), e(pure[0]) if pure else -1)
print("hybrids", len(hyb), max(map(e, hyb), default=-1))

cand = [r for r in ok if r["reference"] != "yes"]


def dominated(r):
    return any(c(q) <= c(r) and e(q) <= e(r) and (c(q) < c(r) or e(q) < e(r))
               for q in cand if q is not r)


print("frontWrong", sum((r["front"] == "yes") == dominated(r) for r in cand))
