"""One point of a study: a fresh copy of the case with the point's settings
(foamDictionary -set), the setup commands, the timed solver, the post
commands, the cost and the error.  A failing step records the point as
failed with its log; it never stops the study."""

import json
import math
import os
import re
import shutil
import signal
import subprocess
import threading
import time

from . import measures
from .foamDict import DictError, asNumber, setEntry, toText
from .measures import MeasureError
from .studyDict import CASE, logName

# Run outputs that a copy of the case leaves out (unless 'copy' names them)
_SKIP = re.compile(r"^(study|processor[0-9]+|postProcessing|VTK|log\..*|"
                   r".*\.png|dynamicCode|__pycache__)$")


def _why(log):
    """The first lines of a FOAM FATAL ERROR in a log, or its last line."""
    try:
        with open(log, errors="replace") as f:
            lines = [l.strip() for l in f]
    except OSError:
        return ""
    for k, l in enumerate(lines):
        if "FOAM FATAL" in l:
            msg = [m for m in lines[k + 1:k + 8] if m]
            return ": " + " ".join(msg[:3])[:300]
    tail = [l for l in lines if l]
    return (": " + tail[-1][:300]) if tail else ""


class PointFailed(Exception):
    def __init__(self, stage, message, log=None):
        if log:
            message += _why(log)
        Exception.__init__(self, message)
        self.stage = stage
        self.log = log


def _isTimeDir(name):
    try:
        float(name)
    except ValueError:
        return False
    return name not in ("0",)


def copyCase(study, dest):
    """A fresh copy of the case: the 'copy' list, or everything but run
    outputs (time directories other than 0, logs, postProcessing, ...)."""
    if os.path.exists(dest):
        shutil.rmtree(dest)
    os.makedirs(dest)
    names = study.copy or [n for n in sorted(os.listdir(study.caseDir))
                           if not _SKIP.match(n) and not _isTimeDir(n)]
    for n in names:
        src = os.path.join(study.caseDir, str(n))
        dst = os.path.join(dest, str(n))
        if os.path.isdir(src):
            shutil.copytree(src, dst, symlinks=True)
        else:
            os.makedirs(os.path.dirname(dst), exist_ok=True)
            shutil.copy2(src, dst)


def pointEnv(study, point, studyDir):
    env = dict(os.environ)
    env["STUDY_CASE"] = study.caseDir
    env["STUDY_DIR"] = studyDir
    env["STUDY_POINT"] = str(point.index)
    for s in study.settings:
        v = point.values[s.name]
        env["STUDY_" + re.sub(r"[^A-Za-z0-9_]", "_", s.name)] = \
            "" if v is CASE else toText(v)
    return env


def numericNames(point):
    """Settings with a numeric value, by name, for error expressions."""
    out = {}
    for name, v in point.values.items():
        x = asNumber(v) if v is not CASE else None
        if x is not None and re.match(r"^[A-Za-z_][A-Za-z0-9_]*$", name):
            out[name] = x
    return out


def _logNames(commands, taken):
    """log.<first word> per command, made unique with .2, .3 ..."""
    out = []
    for c in commands:
        base = "log." + logName(c)
        name, k = base, 1
        while name in taken:
            k += 1
            name = "%s.%d" % (base, k)
        taken.add(name)
        out.append(name)
    return out


def runCommand(command, cwd, env, logName, stage, timeout=None):
    log = os.path.join(cwd, logName)
    rc, _ = measures.runCapture(command, cwd, env, log, timeout)
    if rc != 0:
        raise PointFailed(stage, "'%s' %s" % (command, "ran past the "
                          "timeout" if rc == "timeout" else "exited with "
                          "status %s" % rc), log)


def timedCommand(command, cwd, env, logPath, timeout=None):
    """(status, wall s, cpu s) of a command: wall from a monotonic clock
    around the process, cpu (user + system) from its own rusage."""
    with open(logPath, "w") as log:
        t0 = time.perf_counter()
        # bash runs a simple command by exec: the rusage is the solver's
        p = subprocess.Popen(["/bin/bash", "-c", command],
                             cwd=cwd, env=env, stdout=log,
                             stderr=subprocess.STDOUT, start_new_session=True)
        timedOut = []

        def kill():
            timedOut.append(True)
            try:
                os.killpg(p.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        timer = threading.Timer(timeout, kill) if timeout else None
        if timer:
            timer.start()
        try:
            _, status, ru = os.wait4(p.pid, 0)
        except KeyboardInterrupt:
            kill()      # its own session: ^C does not reach it
            os.wait4(p.pid, 0)
            raise
        finally:
            if timer:
                timer.cancel()
        wall = time.perf_counter() - t0
        p.returncode = os.waitstatus_to_exitcode(status)
    if timedOut:
        return "timeout", wall, ru.ru_utime + ru.ru_stime
    return p.returncode, wall, ru.ru_utime + ru.ru_stime


def prepareCopy(study, point, pdir, env):
    copyCase(study, pdir)
    for s in study.settings:
        v = point.values[s.name]
        if v is CASE:
            continue
        try:
            setEntry(pdir, s.file, s.entry, toText(v))
        except DictError as e:
            raise PointFailed("settings", "setting %s: %s" % (s.name, e))
    taken = {study.solverLog}
    setupLogs = _logNames(study.setup, taken)
    for c, lg in zip(study.setup, setupLogs):
        runCommand(c, pdir, env, lg, "setup", study.timeout)
    return taken


def runPoint(study, point, studyDir, keep=False, repeat=1):
    """Run one point; returns its result (a dict, also written to
    <point>/result.json)."""
    pdir = os.path.join(studyDir, point.tag)
    env = pointEnv(study, point, studyDir)
    res = {"point": point.index, "key": point.key(),
           "labels": point.labels(), "reference": point.reference,
           "status": "ok", "dir": pdir}
    t0 = time.time()
    try:
        walls, cpus = [], []
        for r in range(repeat):
            taken = prepareCopy(study, point, pdir, env)
            solverLog = os.path.join(pdir, study.solverLog)
            rc, wall, cpu = timedCommand(study.solver, pdir, env, solverLog,
                                         study.timeout)
            if rc != 0:
                raise PointFailed("solver", "'%s' %s" % (
                    study.solver, "ran past the timeout of %g s"
                    % study.timeout if rc == "timeout"
                    else "exited with status %s" % rc), solverLog)
            walls.append(wall)
            cpus.append(cpu)
        res["walls"] = walls
        res["wall"] = min(walls)
        res["cpu"] = min(cpus)
        for k, m in study.cost.items():
            try:
                res[k] = measures.cost(m, pdir, env, k)
            except MeasureError as e:
                raise PointFailed("cost", "cost/%s: %s" % (k, e))
        n = res.get("cells", res.get("particles"))
        if n is not None and "steps" in res:
            res["updates"] = n * res["steps"]
        for c, lg in zip(study.post, _logNames(study.post, taken)):
            runCommand(c, pdir, env, lg, "post", study.timeout)
        measureError(study, point, pdir, env, res)
    except PointFailed as e:
        res["status"] = "failed"
        res["stage"] = e.stage
        res["message"] = str(e)
        res["log"] = e.log
    except MeasureError as e:
        res["status"] = "failed"
        res["stage"] = "error"
        res["message"] = str(e)
        res["log"] = None
    res["elapsed"] = time.time() - t0
    os.makedirs(pdir, exist_ok=True)
    with open(os.path.join(pdir, "result.json"), "w") as f:
        json.dump(res, f, indent=1)
    if not keep and res["status"] == "ok":
        clean(pdir)
    return res


def measureError(study, point, pdir, env, res):
    e = study.error
    names = numericNames(point)
    if e.type == "monitor":
        res["error"] = measures.monitorError(e, pdir, names)
        return
    text, where = measures.sourceText(e.measure, pdir, env, "log.error",
                                      study.timeout)
    value = measures.extract(e.measure, text, where)
    if not math.isfinite(value):
        raise MeasureError("error: %s is not finite (in %s)" % (value, where))
    if e.type == "command":
        res["error"] = measures.valueError(e, value, names)
    else:
        res["value"] = value        # the error follows from the finest point


def clean(pdir):
    """Keep only the logs and result.json of a finished point."""
    for n in os.listdir(pdir):
        if n.startswith("log.") or n == "result.json":
            continue
        p = os.path.join(pdir, n)
        if os.path.isdir(p) and not os.path.islink(p):
            shutil.rmtree(p)
        else:
            os.remove(p)


def finestErrors(study, results):
    """Errors of a 'finest' study: |value - value of the finest point|
    (relative: divided by |finest value|).  The finest point is the one the
    studyDict names, else the ok point with the most updates (or the
    longest wall time).  It becomes a reference point."""
    e = study.error
    ok = [r for r in results if r["status"] == "ok" and "value" in r]
    if not ok:
        return None
    if e.finest is not None:
        sel = [p.index for p in study.points if study._matches(p, e.finest)]
        fin = [r for r in ok if r["point"] in sel]
        if not fin:
            for r in results:
                r.pop("error", None)
            return None
        fin = fin[0]
    else:
        fin = max(ok, key=lambda r: (r.get("updates", 0), r["wall"]))
    ref = fin["value"]
    for r in ok:
        d = abs(r["value"] - ref)
        if e.relative:
            d = d / abs(ref) if ref != 0 else float("inf")
        r["error"] = d
    fin["reference"] = True
    fin["finest"] = True
    return fin
