"""The Pareto front of a study (lowest error for the cost) and the cheapest
point that reaches a target error."""

import math


def costOf(r, axis):
    v = r.get(axis)
    return v if isinstance(v, (int, float)) and math.isfinite(v) else None


def candidates(results, axis):
    """Finished, non-reference points with a finite error and cost."""
    out = []
    for r in results:
        if r.get("status") != "ok" or r.get("reference"):
            continue
        e = r.get("error")
        if not isinstance(e, (int, float)) or not math.isfinite(e):
            continue
        if costOf(r, axis) is None:
            continue
        out.append(r)
    return out


def dominates(a, b, axis):
    """a is at most as costly and at most as wrong as b, and better in
    one of the two."""
    ca, cb = costOf(a, axis), costOf(b, axis)
    ea, eb = a["error"], b["error"]
    return ca <= cb and ea <= eb and (ca < cb or ea < eb)


def markFront(results, axis):
    """Set r['front'] (True/False) on every result; returns the front
    sorted by cost.  Points that are not candidates get False."""
    cand = candidates(results, axis)
    for r in results:
        r["front"] = False
    front = []
    for r in cand:
        if not any(dominates(q, r, axis) for q in cand if q is not r):
            r["front"] = True
            front.append(r)
    front.sort(key=lambda r: (costOf(r, axis), r["error"]))
    return front


def cheapest(results, axis, target):
    """The cheapest candidate with error <= target (the lower error on a
    tie), or None."""
    ok = [r for r in candidates(results, axis) if r["error"] <= target]
    if not ok:
        return None
    return min(ok, key=lambda r: (costOf(r, axis), r["error"]))
