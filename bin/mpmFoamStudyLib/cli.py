"""Command line of mpmFoamStudy: read and check the studyDict, run the
points with a progress line each, write the table, the plot and the
answers for the target errors."""

import argparse
import datetime
import json
import os
import shutil
import socket
import subprocess
import sys
import time

from . import front as fr
from . import convergence, report, runner
from .eta import Estimator
from .foamDict import DictError
from .studyDict import Study


def parseArgs(argv, doc):
    p = argparse.ArgumentParser(
        prog="mpmFoamStudy", description=doc,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("-case", default=".", metavar="DIR",
                   help="the case directory (default: .)")
    p.add_argument("-dict", default="system/studyDict", metavar="FILE",
                   help="the studyDict, relative to the case (default: "
                        "system/studyDict)")
    p.add_argument("-target", action="append", default=[], metavar="E",
                   help="report the cheapest point with error <= E; repeat "
                        "it or give a comma list (default: the studyDict's "
                        "targets)")
    p.add_argument("-only", metavar="N",
                   help="run only these points (1-based: 3 or 2,5-7); the "
                        "others keep their stored results where their "
                        "settings are unchanged")
    p.add_argument("-keep", action="store_true",
                   help="keep each point's case copy (default: only its "
                        "logs and result.json)")
    p.add_argument("-dry-run", dest="dryRun", action="store_true",
                   help="check the studyDict against the case and list the "
                        "points and commands; run nothing")
    p.add_argument("-repeat", type=int, metavar="N",
                   help="run the solver N times per point (a fresh copy "
                        "each time) and keep the lowest wall time (default: "
                        "the studyDict's repeat, else 1)")
    p.add_argument("-report", action="store_true",
                   help="only remake the report from the stored results")
    return p.parse_args(argv)


def parseOnly(text, n):
    out = set()
    for part in text.split(","):
        part = part.strip()
        if not part:
            continue
        try:
            if "-" in part:
                a, b = part.split("-", 1)
                out.update(range(int(a), int(b) + 1))
            else:
                out.add(int(part))
        except ValueError:
            raise DictError("-only %s: '%s' is not a point number or a "
                            "range a-b" % (text, part))
    bad = sorted(k for k in out if not 1 <= k <= n)
    if bad:
        raise DictError("-only %s: no point %s (the study has points 1 to "
                        "%d)" % (text, bad[0], n))
    return out


def parseTargets(items):
    out = []
    for it in items:
        for t in it.split(","):
            if not t.strip():
                continue
            try:
                x = float(t)
            except ValueError:
                raise DictError("-target %s: not a number" % t)
            if not x > 0:
                raise DictError("-target %s: not positive" % t)
            out.append(x)
    return out


def loadLine():
    try:
        out = subprocess.run(["uptime"], stdout=subprocess.PIPE,
                             universal_newlines=True).stdout.strip()
    except OSError:
        out = "load average: %.2f, %.2f, %.2f" % os.getloadavg()
    return out


def toolkitVersion():
    """The toolkit's git commit (with '+ changes' for a modified tree)."""
    top = os.environ.get("MPMFOAM_DIR")
    if not top:
        return "unknown (MPMFOAM_DIR not set)"
    try:
        head = subprocess.run(["git", "-C", top, "rev-parse", "--short",
                               "HEAD"], stdout=subprocess.PIPE,
                              stderr=subprocess.DEVNULL,
                              universal_newlines=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", top, "status", "--porcelain",
                                "--untracked-files=no", "src",
                                "applications"], stdout=subprocess.PIPE,
                               stderr=subprocess.DEVNULL,
                               universal_newlines=True).stdout.strip()
    except OSError:
        return "unknown"
    return (head or "unknown") + (" + changes in src/ or applications/"
                                  if dirty else "")


def duration(s):
    if s < 90:
        return "%.0f s" % s
    if s < 5400:
        return "%.0f min" % (s / 60)
    return "%.1f h" % (s / 3600)


def dryRun(study, studyDir):
    print("study %s: %d points, output in %s" % (study.name,
                                                 len(study.points), studyDir))
    for s in study.settings:
        print("  setting %-12s %s: %s" % (s.name, s.file, s.entry))
    print("  prepare: %s" % ("; ".join(study.prepare) or "-"))
    print("  setup:   %s" % ("; ".join(study.setup) or "-"))
    print("  solver:  %s (timed%s)" % (study.solver, ", %d times"
                                       % study.repeat if study.repeat > 1
                                       else ""))
    print("  post:    %s" % ("; ".join(study.post) or "-"))
    print("  error:   %s (%s)" % (study.error.name, study.error.type))
    for p in study.points:
        print("point %d/%d  %s%s" % (p.index, len(study.points), p.text(),
                                     "  (reference)" if p.reference else ""))
    print("dry run: the studyDict and the case agree; nothing was run")


def storedResult(studyDir, point):
    path = os.path.join(studyDir, point.tag, "result.json")
    if not os.path.isfile(path):
        return None
    try:
        with open(path) as f:
            r = json.load(f)
    except (OSError, ValueError):
        return None
    if r.get("key") != point.key():
        return None     # the studyDict changed since
    r["reference"] = point.reference
    r["labels"] = point.labels()
    return r


def notRun(point):
    return {"point": point.index, "labels": point.labels(),
            "reference": point.reference, "status": "not run"}


def progress(study, point, r, k, n, elapsed, eta):
    vary = study.textNames(point.reference)
    if r["status"] == "ok":
        if "error" in r:
            what = "error %.3e" % r["error"]
        else:
            what = "value %.6g" % r["value"]
        what += "  wall %.3f s" % r["wall"]
        if len(r.get("walls", [])) > 1:
            what += " (of %s)" % " ".join("%.3f" % w for w in r["walls"])
    else:
        what = "FAILED (%s; %s)" % (r.get("stage"), os.path.relpath(
            r["log"], study.caseDir) if r.get("log") else "see below")
    print("point %d/%d  %s  %s  elapsed %s  ETA %s"
          % (k, n, point.text(vary), what, duration(elapsed),
             duration(eta)), flush=True)
    if r["status"] != "ok":
        print("    %s" % r.get("message"), flush=True)


def main(argv, doc):
    args = parseArgs(argv, doc)
    try:
        study = Study(args.case, args.dict)
        study.checkCase()
        targets = parseTargets(args.target) or study.targets
        only = parseOnly(args.only, len(study.points)) if args.only else None
    except DictError as e:
        print("mpmFoamStudy: %s" % e, file=sys.stderr)
        return 1
    repeat = args.repeat or study.repeat
    if repeat < 1:
        print("mpmFoamStudy: -repeat %d: at least 1" % repeat,
              file=sys.stderr)
        return 1
    studyDir = os.path.join(study.caseDir, "study", study.name)
    if args.dryRun:
        dryRun(study, studyDir)
        return 0
    axis = study.plotCost
    load = loadLine()
    info = [("host", socket.gethostname()),
            ("started", datetime.datetime.now().strftime("%Y-%m-%d %H:%M")),
            ("load at the start (uptime)", load),
            ("toolkit", toolkitVersion()),
            ("solver runs per point", repeat)]
    results = []
    infoPath = os.path.join(studyDir, "study.json")
    if args.report:
        results = [storedResult(studyDir, p) or notRun(p)
                   for p in study.points]
        if os.path.isfile(infoPath):
            with open(infoPath) as f:
                info = [tuple(x) for x in json.load(f)]
    else:
        if only is None and os.path.isdir(studyDir):
            shutil.rmtree(studyDir)
        os.makedirs(studyDir, exist_ok=True)
        print("mpmFoamStudy %s: %d points%s; %s" % (
            study.name, len(study.points), "" if only is None else
            " (running %d)" % len(only), load), flush=True)
        env = dict(os.environ, STUDY_CASE=study.caseDir, STUDY_DIR=studyDir)
        for k, c in enumerate(study.prepare):
            log = os.path.join(studyDir, "log.prepare.%d" % (k + 1))
            rc, _ = runner.measures.runCapture(c, study.caseDir, env, log)
            if rc != 0:
                print("mpmFoamStudy: prepare command '%s' failed (exit %s); "
                      "see %s" % (c, rc, log), file=sys.stderr)
                return 1
        t0 = time.time()
        todo = [p for p in study.points if only is None or p.index in only]
        done = 0
        est = Estimator(study)
        for p in study.points:
            if p not in todo:
                results.append(storedResult(studyDir, p) or notRun(p))
                continue
            r = runner.runPoint(study, p, studyDir, args.keep, repeat)
            results.append(r)
            done += 1
            est.add(p, r["elapsed"])
            el = time.time() - t0
            progress(study, p, r, p.index, len(study.points), el,
                     est.remaining(todo[done:]))
            report.writeCsv(study, results, os.path.join(studyDir,
                                                         "results.csv"))
        info.append(("study wall time", duration(time.time() - t0)))
        info.append(("load at the end (uptime)", loadLine()))
        if only is not None:
            info.append(("points run", args.only))
        with open(infoPath, "w") as f:
            json.dump(info, f)
    if study.error.type == "finest":
        fin = runner.finestErrors(study, results)
        if fin is not None:
            info.append(("finest point (the error's reference)",
                         "%d, value %.10g" % (fin["point"], fin["value"])))
    fr.markFront(results, axis)
    report.writeCsv(study, results, os.path.join(studyDir, "results.csv"))
    report.writeMarkdown(study, results, targets, axis, info,
                         os.path.join(studyDir, "results.md"))
    png = os.path.join(studyDir, "errorVsCost.png")
    try:
        report.plot(study, results, targets, axis, png)
    except ImportError as e:
        print("mpmFoamStudy: no plot (%s)" % e, file=sys.stderr)
        png = None
    written = "results.csv, results.md" + (", errorVsCost.png" if png else "")
    orderLines = []
    if study.convergence is not None:
        orderLines = convergence.write(study, results, studyDir)
        written += ", convergence.csv, convergence.md"
        try:
            convergence.plot(study, results,
                             os.path.join(studyDir, "errorVsSize.png"))
            written += ", errorVsSize.png"
        except ImportError as e:
            print("mpmFoamStudy: no plot (%s)" % e, file=sys.stderr)
    print()
    for line in report.summaryLines(study, results, targets, axis):
        print(line)
    for line in orderLines:
        print(line)
    print("wrote %s/%s" % (studyDir, written))
    nOk = sum(1 for r in results if r.get("status") == "ok")
    return 0 if nOk else 1
