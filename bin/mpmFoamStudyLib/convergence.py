"""Convergence of a study's error with a size setting: the observed order
of every series of points that differ only in that setting, as a table
(convergence.csv, convergence.md) and a log-log plot (errorVsSize.png).

studyDict:

    convergence
    {
        size    dx;         // the setting whose labels are the sizes h
        // by   (kernel mesh);   // optional: the settings that name a
                                 //   series (default: every other one
                                 //   that varies)
        // minPoints 3;     // optional: fit only series with this many
    }

The observed order of a series is the slope of the least-squares line
through (log h, log error); the last pair's order, log(e1/e2)/log(h1/h2)
over its two smallest sizes, is given beside it.
"""

import csv
import math
import os

from .foamDict import DictError, toText
from .report import logAxes


class ConvergenceSpec:
    def __init__(self, d, study):
        where = "convergence"
        if not isinstance(d, dict):
            raise DictError("%s: a dictionary { size <setting>; } expected, "
                            "found %s" % (where, toText(d)))
        size = d.get("size")
        if size is None:
            raise DictError("%s/size: missing (the setting whose labels are "
                            "the sizes h)" % where)
        self.size = str(size)
        if self.size not in study.byName:
            raise DictError("%s/size: '%s' is not a setting (settings: %s)"
                            % (where, self.size, " ".join(study.byName)))
        setting = study.byName[self.size]
        for v in setting.values:
            try:
                h = float(setting.label(v))
            except ValueError:
                h = -1.0
            if not (h > 0 and math.isfinite(h)):
                raise DictError(
                    "%s/size: setting '%s' has the label '%s' for %s; every "
                    "label must be a positive size (give 'labels')"
                    % (where, self.size, setting.label(v), toText(v)))
        by = d.get("by")
        if by is None:
            self.by = None
        else:
            self.by = [str(b) for b in (by if isinstance(by, list) else [by])]
            for b in self.by:
                if b not in study.byName or b == self.size:
                    raise DictError("%s/by: '%s' is not a setting other than "
                                    "the size (settings: %s)"
                                    % (where, b, " ".join(study.byName)))
        mp = d.get("minPoints", "2")
        try:
            self.minPoints = int(str(mp))
        except ValueError:
            self.minPoints = 0
        if self.minPoints < 2:
            raise DictError("%s/minPoints: %s; an integer of at least 2"
                            % (where, toText(mp)))

    def seriesNames(self, study):
        if self.by is not None:
            return self.by
        return [n for n in study.varying(True) if n != self.size]


def fitOrder(hs, es):
    """Least-squares slope of log e against log h (None for < 2 sizes)."""
    if len(hs) < 2:
        return None
    x = [math.log(h) for h in hs]
    y = [math.log(e) for e in es]
    mx, my = sum(x) / len(x), sum(y) / len(y)
    sxx = sum((a - mx) ** 2 for a in x)
    if sxx == 0:
        return None
    return sum((a - mx) * (b - my) for a, b in zip(x, y)) / sxx


def series(study, results):
    """[(name dict, [(h, error, result)] sorted by h decreasing)]: the
    finished points grouped by the series settings."""
    spec = study.convergence
    names = spec.seriesNames(study)
    groups = {}
    order = []
    for r in results:
        if r.get("status") != "ok" or r.get("reference"):
            continue
        e = r.get("error")
        if not isinstance(e, float) or not (e > 0 and math.isfinite(e)):
            continue
        lab = r.get("labels", {})
        key = tuple(lab.get(n, "-") for n in names)
        if key not in groups:
            groups[key] = []
            order.append(key)
        groups[key].append((float(lab[spec.size]), e, r))
    out = []
    for key in order:
        pts = sorted(groups[key], key=lambda t: -t[0])
        out.append((dict(zip(names, key)), pts))
    return out


def orders(study, results):
    """Rows: the series' names, sizes, errors, fitted and last-pair
    orders (None where the series has too few sizes)."""
    rows = []
    for name, pts in series(study, results):
        hs = [p[0] for p in pts]
        es = [p[1] for p in pts]
        enough = len(set(hs)) >= study.convergence.minPoints
        fit = fitOrder(hs, es) if enough else None
        last = (math.log(es[-2] / es[-1]) / math.log(hs[-2] / hs[-1])
                if enough and hs[-2] != hs[-1] else None)
        rows.append({"series": name, "h": hs, "error": es, "order": fit,
                     "lastOrder": last, "points": [p[2]["point"]
                                                   for p in pts]})
    return rows


def _f(x, spec="%.3f"):
    return "-" if x is None else spec % x


def _seriesText(name):
    """'kernel umls mesh strip' (settings left as the case has them out)."""
    return " ".join("%s %s" % (k, v) for k, v in name.items()
                    if v != "(case)") or "all"


def write(study, results, studyDir):
    """convergence.csv, convergence.md; returns the summary lines."""
    spec = study.convergence
    rows = orders(study, results)
    names = spec.seriesNames(study)
    with open(os.path.join(studyDir, "convergence.csv"), "w",
              newline="") as f:
        w = csv.writer(f)
        w.writerow(names + ["n_sizes", "order", "last_order", "h",
                            study.error.name])
        for r in rows:
            w.writerow([r["series"][n] for n in names] +
                       [len(r["h"]), _f(r["order"], "%.12g"),
                        _f(r["lastOrder"], "%.12g"),
                        " ".join("%.6g" % h for h in r["h"]),
                        " ".join("%.10g" % e for e in r["error"])])
    sizes = sorted({h for r in rows for h in r["h"]}, reverse=True)
    head = names + ["h = %g" % h for h in sizes] + ["order (fit)",
                                                    "order (last pair)"]
    md = ["# Study %s: convergence of %s with %s" % (
        study.name, study.error.name, spec.size), "",
        "The order is the slope of the least-squares line through "
        "(log h, log error); the last pair's from its two smallest sizes.",
        "",
        "| " + " | ".join(head) + " |", "|" + "|".join("---" for _ in head)
        + "|"]
    for r in rows:
        byH = dict(zip(r["h"], r["error"]))
        md.append("| " + " | ".join(
            [r["series"][n] for n in names] +
            [_f(byH.get(h), "%.3e") for h in sizes] +
            [_f(r["order"], "%.2f"), _f(r["lastOrder"], "%.2f")]) + " |")
    with open(os.path.join(studyDir, "convergence.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    lines = ["Observed order of %s in %s:" % (study.error.name, spec.size)]
    for r in rows:
        lines.append("  %-40s order %s (last pair %s) over %d sizes"
                     % (_seriesText(r["series"]), _f(r["order"], "%.2f"),
                        _f(r["lastOrder"], "%.2f"), len(r["h"])))
    return lines


def plot(study, results, path):
    """One line per series: its colour from every series setting but the
    last, its marker and line style from the last (with 'by (kernel
    mesh)', a colour per kernel and a marker per mesh); the legend beside
    the axes."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    spec = study.convergence
    names = spec.seriesNames(study)
    rows = orders(study, results)
    head, last = (names[:-1], names[-1:]) if len(names) > 1 else (names, [])

    def key(r, ns):
        return tuple(r["series"][n] for n in ns)
    cvals, mvals = [], []
    for r in rows:
        if key(r, head) not in cvals:
            cvals.append(key(r, head))
        if key(r, last) not in mvals:
            mvals.append(key(r, last))
    cmap = plt.get_cmap("tab10")
    markers = "osD^v<>ph*"
    styles = ["-", "--", ":", "-."]
    fig, ax = plt.subplots(figsize=(11, 6.5))
    for r in rows:
        ci = cvals.index(key(r, head))
        mi = mvals.index(key(r, last))
        ax.plot(r["h"], r["error"], markers[mi % len(markers)] +
                styles[mi % len(styles)], color=cmap(ci % 10), ms=5,
                label="%s: %s" % (_seriesText(r["series"]),
                                  "order %s" % _f(r["order"], "%.2f")))
    logAxes(ax, bool(rows))
    ax.set_xlabel(spec.size)
    ax.set_ylabel(study.error.name)
    ax.set_title("%s: error against %s (order: least-squares slope)"
                 % (study.name, spec.size))
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=6, loc="upper left", bbox_to_anchor=(1.01, 1.0),
              borderaxespad=0)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
