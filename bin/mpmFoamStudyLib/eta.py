"""The time left in a study: a fit of the points run so far, so that a
resolution sweep's last, largest points are not estimated by the mean of
its first, smallest ones.

log(seconds) = c + sum over numeric settings of k_s log(value_s)
                 + sum over the other settings of f_(s, value)
by ridge-regularised least squares (a small ridge keeps a value not seen
yet at the average); before there are enough points, the mean."""

import math

from .foamDict import asNumber, toText
from .studyDict import CASE


class Estimator:
    def __init__(self, study):
        self.columns = []           # (setting, kind, value or None)
        for s in study.settings:
            vals = []
            for p in study.points:
                v = p.values[s.name]
                t = None if v is CASE else toText(v)
                if t not in vals:
                    vals.append(t)
            if len(vals) < 2:
                continue
            nums = [asNumber(v) if v is not None else None for v in vals]
            if all(x is not None and x > 0 for x in nums):
                self.columns.append((s.name, "log", None))
            else:
                for v in vals[1:]:
                    self.columns.append((s.name, "is", v))
        self.x, self.y = [], []

    def features(self, point):
        f = [1.0]
        for name, kind, val in self.columns:
            v = point.values[name]
            if kind == "log":
                f.append(math.log(asNumber(v)))
            else:
                f.append(1.0 if v is not CASE and toText(v) == val else 0.0)
        return f

    def add(self, point, seconds):
        self.x.append(self.features(point))
        self.y.append(math.log(max(seconds, 1e-3)))

    def remaining(self, points):
        """Seconds that the given points will take."""
        if not self.y:
            return 0.0
        n = len(self.x[0])
        if len(self.y) < n + 1:
            mean = sum(math.exp(y) for y in self.y) / len(self.y)
            return mean * len(points)
        beta = _ridge(self.x, self.y, 1e-3)
        total = 0.0
        ymax = max(self.y) + 5.0       # no estimate beyond e^5 x the slowest
        for p in points:
            f = self.features(p)
            total += math.exp(min(sum(a * b for a, b in zip(f, beta)), ymax))
        return total


def _ridge(X, y, lam):
    """argmin |X b - y|^2 + lam |b[1:]|^2 by Gaussian elimination."""
    n = len(X[0])
    A = [[sum(r[i] * r[j] for r in X) + (lam if i == j and i else 0.0)
          for j in range(n)] for i in range(n)]
    b = [sum(r[i] * v for r, v in zip(X, y)) for i in range(n)]
    for c in range(n):
        piv = max(range(c, n), key=lambda r: abs(A[r][c]))
        A[c], A[piv] = A[piv], A[c]
        b[c], b[piv] = b[piv], b[c]
        if abs(A[c][c]) < 1e-300:
            continue
        for r in range(c + 1, n):
            m = A[r][c] / A[c][c]
            if m:
                for k in range(c, n):
                    A[r][k] -= m * A[c][k]
                b[r] -= m * b[c]
    out = [0.0] * n
    for c in range(n - 1, -1, -1):
        s = b[c] - sum(A[c][k] * out[k] for k in range(c + 1, n))
        out[c] = s / A[c][c] if abs(A[c][c]) > 1e-300 else 0.0
    return out
