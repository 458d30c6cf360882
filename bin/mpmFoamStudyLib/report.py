"""Output of a study: results.csv, results.md and errorVsCost.png."""

import csv
import math
import os

from . import front as fr

AXIS_TEXT = {"wall": "wall time of the solver [s]",
             "cpu": "CPU time of the solver [s]",
             "updates": "cell-updates (cells x steps)"}


def fmt(x, spec="%.4g"):
    if x is None:
        return "-"
    if isinstance(x, float):
        if not math.isfinite(x):
            return str(x)
        if x == int(x) and abs(x) < 1e15 and spec == "%.4g":
            return "%d" % x
        return spec % x
    return str(x)


def updatesName(study):
    return "particle-steps" if "particles" in study.cost else "cell-updates"


def axisText(study):
    if study.plotCost == "updates":
        return "%s (%s x steps)" % (updatesName(study),
                                    "particles" if "particles" in study.cost
                                    else "cells")
    return AXIS_TEXT[study.plotCost]


def columns(study):
    size = "n_particles" if "particles" in study.cost else "n_cells"
    return (["point"] + [s.name for s in study.settings] +
            ["status", "wall_s", "cpu_s", "n_steps", size,
             updatesName(study).replace("-", "_"), study.error.name] +
            (["value"] if study.error.type == "finest" else []) +
            ["front", "reference", "log"])


def row(study, r, precise=False):
    """A table row; precise: every digit of the errors (the CSV)."""
    size = "particles" if "particles" in study.cost else "cells"
    lab = r.get("labels", {})
    vals = [r["point"]] + [lab.get(s.name, "-") for s in study.settings]
    st = r.get("status", "not run")
    vals += [st, fmt(r.get("wall"), "%.4f" if precise else "%.3f"),
             fmt(r.get("cpu"), "%.4f" if precise else "%.3f"),
             fmt(r.get("steps")), fmt(r.get(size)), fmt(r.get("updates")),
             fmt(r.get("error"), "%.10g" if precise else "%.4e")]
    if study.error.type == "finest":
        vals.append(fmt(r.get("value"), "%.10g"))
    vals += ["yes" if r.get("front") else "no",
             ("finest" if r.get("finest") else "yes") if r.get("reference")
             else "no",
             os.path.relpath(r["log"], study.caseDir) if r.get("log") else
             os.path.relpath(r["dir"], study.caseDir) if r.get("dir") else "-"]
    return vals


def writeCsv(study, results, path):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(columns(study))
        for r in results:
            w.writerow(row(study, r, precise=True))


def _mdTable(head, rows):
    out = ["| " + " | ".join(head) + " |",
           "|" + "|".join("---" for _ in head) + "|"]
    out += ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]
    return out


def summaryLines(study, results, targets, axis):
    """Plain-text lines: the front, the targets, the references."""
    lines = []
    frontPts = [r for r in results if r.get("front")]
    frontPts.sort(key=lambda r: (fr.costOf(r, axis), r["error"]))
    lines.append("Pareto front (%s against %s), %d of %d points:"
                 % (study.error.name, axis, len(frontPts), len(results)))
    for r in frontPts:
        lines.append("  point %d  %s  %s %.4e  %s %s"
                     % (r["point"], _text(r, study), study.error.name,
                        r["error"], axis, fmt(fr.costOf(r, axis), "%.4g")))
    for t in targets:
        c = fr.cheapest(results, axis, t)
        if c is None:
            best = min((r["error"] for r in fr.candidates(results, axis)),
                       default=None)
            lines.append("target %s <= %g: no point reaches it (lowest "
                         "error %s)" % (study.error.name, t,
                                        fmt(best, "%.4e")))
        else:
            lines.append("target %s <= %g: cheapest point %d  %s  %s %.4e  "
                         "%s %s" % (study.error.name, t, c["point"],
                                    _text(c, study), study.error.name,
                                    c["error"], axis,
                                    fmt(fr.costOf(c, axis), "%.4g")))
    for ref in results:
        if not ref.get("reference") or ref.get("status") != "ok" or \
                ref.get("finest"):
            continue
        c = fr.cheapest(results, axis, ref["error"])
        head = ("reference point %d  %s  %s %.4e  wall %.3f s"
                % (ref["point"], _text(ref, study), study.error.name,
                   ref["error"], ref["wall"]))
        if c is None:
            lines.append(head + ": no point reaches its error")
        else:
            lines.append(head + ": equal accuracy at point %d  %s  %s %.4e  "
                         "wall %.3f s: wall ratio %.3f (CPU %.3f s / %.3f s "
                         "= %.3f)"
                         % (c["point"], _text(c, study), study.error.name,
                            c["error"], c["wall"], c["wall"] / ref["wall"],
                            c["cpu"], ref["cpu"], c["cpu"] / ref["cpu"]))
    failed = [r for r in results if r.get("status") == "failed"]
    for r in failed:
        lines.append("point %d FAILED (%s): %s" % (r["point"], r.get("stage"),
                                                   r.get("message")))
    return lines


def _text(r, study):
    vary = study.textNames(r.get("reference"))
    lab = r.get("labels", {})
    return "  ".join("%s %s" % (n, lab.get(n, "-")) for n in vary
                     if lab.get(n) != "(case)")


def writeMarkdown(study, results, targets, axis, info, path):
    out = ["# Study %s" % study.name, ""]
    out += ["- case: `%s`, studyDict `%s`" % (study.caseDir, study.dictPath),
            "- solver: `%s`; error: %s (%s)" % (study.solver, study.error.name,
                                               study.error.type),
            "- cost axis of the front: %s" % axisText(study)]
    for k, v in info:
        out.append("- %s: %s" % (k, v))
    out.append("")
    out += _mdTable(columns(study), [row(study, r) for r in results])
    out.append("")
    frontPts = sorted([r for r in results if r.get("front")],
                      key=lambda r: (fr.costOf(r, axis), r["error"]))
    vary = study.textNames(False)
    if frontPts:
        out += ["## Pareto front (%s against %s)" % (study.error.name, axis),
                ""]
        out += _mdTable(["point"] + vary + [study.error.name, "wall [s]",
                                            updatesName(study)],
                        [[r["point"]] + [r["labels"].get(n, "-")
                                         for n in vary] +
                         [fmt(r["error"], "%.4e"), fmt(r["wall"], "%.3f"),
                          fmt(r.get("updates"))] for r in frontPts])
        out.append("")
    out += ["## Summary", "", "```"]
    out += summaryLines(study, results, targets, axis) + ["```", ""]
    with open(path, "w") as f:
        f.write("\n".join(out))


def logAxes(ax, anything):
    """Log-log axes, or (nothing to draw: a log axis would fail) a note."""
    if anything:
        ax.set_xscale("log")
        ax.set_yscale("log")
    else:
        ax.text(0.5, 0.5, "no point finished with a positive error",
                ha="center", transform=ax.transAxes)


def plot(study, results, targets, axis, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    vary = study.varying(True)
    colourBy = str(study.colourBy) if study.colourBy else \
        (vary[0] if vary else None)
    rest = [n for n in vary if n != colourBy]
    markerBy = rest[0] if rest else None
    labelBy = rest[1:] if rest else []
    ok = [r for r in results if r.get("status") == "ok"
          and isinstance(r.get("error"), float) and r["error"] > 0
          and fr.costOf(r, axis) is not None]
    # a reference that is the truth itself (its error is round-off, a
    # millionth of the smallest other error, or 0: the error is measured
    # against its own run) is drawn as a line at its cost, not as a point
    # that would stretch the log axis
    others = [r["error"] for r in ok if not r.get("reference")]
    floor = 1e-6*min(others) if others else 0.0
    truths = [r for r in results if r.get("reference")
              and r.get("status") == "ok"
              and isinstance(r.get("error"), float) and r["error"] <= floor
              and fr.costOf(r, axis) is not None]
    ok = [r for r in ok if r not in truths]
    cmap = plt.get_cmap("tab10")
    markers = "osD^v<>ph*"

    def values(name):
        """The setting's values over the compared points (numbers in
        order)."""
        seen = []
        for r in results:
            v = r.get("labels", {}).get(name)
            if v is not None and v not in seen and not r.get("reference"):
                seen.append(v)
        try:
            return sorted(seen, key=float)
        except ValueError:
            return seen
    cvals = values(colourBy) if colourBy else []
    mvals = values(markerBy) if markerBy else []

    fig, ax = plt.subplots(figsize=(8, 6))
    for r in ok:
        lab = r["labels"]
        ci = cvals.index(lab[colourBy]) if lab.get(colourBy) in cvals else 0
        mi = mvals.index(lab[markerBy]) if lab.get(markerBy) in mvals else 0
        x, y = fr.costOf(r, axis), r["error"]
        if r.get("reference"):
            ax.plot(x, y, "*", ms=14, color="k", zorder=4)
            ax.axhline(y, color="k", lw=0.7, ls="--")
            ax.annotate("reference %d: %s" % (r["point"], _text(r, study)),
                        (x, y), fontsize=7, xytext=(-6, -12), ha="right",
                        textcoords="offset points")
            continue
        ax.plot(x, y, markers[mi % len(markers)], color=cmap(ci % 10),
                ms=6, alpha=0.85, zorder=3)
        if labelBy and (len(ok) <= 20 or r.get("front")):
            ax.annotate(" ".join("%s=%s" % (n, lab[n]) for n in labelBy
                                 if lab.get(n) != "(case)"), (x, y),
                        fontsize=6, xytext=(3, 3), textcoords="offset points")
    for r in truths:
        x = fr.costOf(r, axis)
        ax.axvline(x, color="k", lw=0.7, ls="--")
        ax.text(x, 0.98, " reference %d (error %.1e): %s"
                % (r["point"], r["error"], _text(r, study)), fontsize=7,
                rotation=90, va="top", ha="right",
                transform=ax.get_xaxis_transform())
    frontPts = sorted([r for r in ok if r.get("front")],
                      key=lambda r: fr.costOf(r, axis))
    if frontPts:
        xs, ys = [], []
        for k, r in enumerate(frontPts):
            if k:
                xs.append(fr.costOf(r, axis))
                ys.append(ys[-1])
            xs.append(fr.costOf(r, axis))
            ys.append(r["error"])
        ax.plot(xs, ys, "-", color="k", lw=1.2, zorder=2,
                label="Pareto front (%d points)" % len(frontPts))
        ax.plot([fr.costOf(r, axis) for r in frontPts],
                [r["error"] for r in frontPts], "o", ms=11, mfc="none",
                mec="k", mew=1.3, zorder=5)
    for t in targets:
        ax.axhline(t, color="grey", lw=0.8, ls=":")
        ax.text(0.005, t, "target %g" % t, fontsize=7, color="grey",
                va="bottom", transform=ax.get_yaxis_transform())
    # legends: colours and markers
    for k, v in enumerate(cvals):
        ax.plot([], [], "s", color=cmap(k % 10), label="%s %s" % (colourBy, v))
    for k, v in enumerate(mvals):
        ax.plot([], [], markers[k % len(markers)], color="grey",
                label="%s %s" % (markerBy, v))
    logAxes(ax, bool(ok))
    ax.set_xlabel(axisText(study))
    ax.set_ylabel(study.error.name)
    nf = sum(1 for r in results if r.get("status") == "failed")
    ax.set_title("%s: error against cost%s" % (
        study.name, "" if not nf else " (%d failed points not shown)" % nf))
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, loc="best")
    if labelBy:
        fig.text(0.01, 0.01, "labels: the settings a point sets of " +
                 " ".join(labelBy) +
                 (" (front points only)" if len(ok) > 20 else ""), fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
