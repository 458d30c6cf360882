"""Numbers of one point of a study: cost measures read from logs, files or
commands (regex or count), the mesh's cell count, and the error measures
(a command's number, a monitor column against an exact expression)."""

import glob
import gzip
import math
import os
import re
import subprocess


class MeasureError(Exception):
    """A number that could not be read; the message says from where."""


def runCapture(command, cwd, env, logPath, timeout=None):
    """Run a shell command in cwd, its output to logPath; (rc, output)."""
    with open(logPath, "w") as log:
        try:
            p = subprocess.run(["/bin/bash", "-c", command], cwd=cwd, env=env,
                               stdout=log, stderr=subprocess.STDOUT,
                               timeout=timeout)
            rc = p.returncode
        except subprocess.TimeoutExpired:
            rc = "timeout"
    with open(logPath, errors="replace") as log:
        return rc, log.read()


def _files(pointDir, pattern):
    paths = sorted(glob.glob(os.path.join(pointDir, pattern)))
    return [p for p in paths if os.path.isfile(p)]


def sourceText(m, pointDir, env, logName, timeout=None):
    """(text, where) of a measure's source: its command's output or its
    file (a glob: the last match in sorted order)."""
    if m.command is not None:
        log = os.path.join(pointDir, logName)
        rc, out = runCapture(m.command, pointDir, env, log, timeout)
        if rc != 0:
            raise MeasureError("'%s' failed (exit %s); see %s"
                               % (m.command, rc, log))
        return out, log
    paths = _files(pointDir, m.file)
    if not paths:
        raise MeasureError("no file %s in %s" % (m.file, pointDir))
    with open(paths[-1], errors="replace") as f:
        return f.read(), paths[-1]


def extract(m, text, where):
    """The number of a regex measure (last match, first group) or the
    count of a count measure."""
    if m.kind == "count":
        return float(len(m.regex.findall(text)))
    last = None
    for last in m.regex.finditer(text):
        pass
    if last is None:
        raise MeasureError("regex '%s' matches nothing in %s"
                           % (m.regex.pattern, where))
    s = last.group(1) if last.groups() else last.group(0)
    try:
        x = float(s)
    except ValueError:
        raise MeasureError("regex '%s' found '%s' in %s: not a number"
                           % (m.regex.pattern, s, where))
    return x


def meshCells(pointDir, env):
    """Cells of the case's mesh: the note of constant/polyMesh/owner
    (blockMesh writes nCells there); else checkMesh's count."""
    for name in ("owner", "owner.gz"):
        path = os.path.join(pointDir, "constant", "polyMesh", name)
        if os.path.isfile(path):
            opener = gzip.open if name.endswith(".gz") else open
            with opener(path, "rb") as f:
                head = f.read(4096).decode("ascii", "replace")
            mm = re.search(r"nCells:\s*([0-9]+)", head)
            if mm:
                return float(mm.group(1))
    return checkMeshCells(pointDir, env)


def checkMeshCells(pointDir, env):
    log = os.path.join(pointDir, "log.checkMesh")
    rc, out = runCapture("checkMesh -constant", pointDir, env, log)
    mm = re.findall(r"^\s*cells:\s+([0-9]+)", out, re.MULTILINE)
    if rc != 0 or not mm:
        raise MeasureError("checkMesh gave no cell count; see %s" % log)
    return float(mm[-1])


def cost(m, pointDir, env, name):
    if m.kind == "mesh":
        return meshCells(pointDir, env)
    if m.kind == "checkMesh":
        return checkMeshCells(pointDir, env)
    text, where = sourceText(m, pointDir, env, "log.cost-" + name)
    return extract(m, text, where)


# ---------------------------------------------------------------------------
# Expressions of the error measures

_MATH = {k: getattr(math, k) for k in dir(math) if not k.startswith("_")}
_MATH.update(abs=abs, min=min, max=max)


def evaluate(expr, names, where):
    """A Python arithmetic expression (math's functions, pi, e and the
    given names) as a float."""
    ns = dict(_MATH)
    ns.update(names)
    try:
        v = eval(compile(str(expr), where, "eval"), {"__builtins__": {}}, ns)
        return float(v)
    except Exception as e:  # an expression of the user's: say which
        raise MeasureError("%s: cannot evaluate '%s' (%s: %s)"
                           % (where, expr, type(e).__name__, e))


def readMonitor(path):
    """(column names, rows) of a function object's .dat file: whitespace
    columns, the last '#' line before the data names them (tab-separated
    where tabs are used, with units in brackets)."""
    names, rows = [], []
    with open(path) as f:
        for line in f:
            s = line.strip()
            if not s:
                continue
            if s.startswith("#"):
                if not rows:
                    h = s.lstrip("#").strip()
                    parts = h.split("\t") if "\t" in h else h.split()
                    names = [re.sub(r"\s*\[.*\]\s*$", "", p).strip()
                             for p in parts]
                continue
            try:
                rows.append([float(x) for x in s.split()])
            except ValueError:
                continue    # a text column (e.g. a signal name): skip line
    return names, rows


def _column(names, spec, path):
    try:
        return int(spec)
    except ValueError:
        pass
    if spec in names:
        return names.index(spec)
    raise MeasureError("column '%s' is not in %s (columns: %s)"
                       % (spec, path, ", ".join(names) or "unnamed"))


def monitorError(e, pointDir, names):
    """Norm over the rows of |column - exact(t)| (divided by scale, or by
    max |exact| when relative)."""
    paths = _files(pointDir, e.file)
    if not paths:
        raise MeasureError("no monitor file %s in %s" % (e.file, pointDir))
    path = paths[-1]
    cols, rows = readMonitor(path)
    ci = _column(cols, e.column, path)
    ti = _column(cols, e.timeColumn, path)
    if e.timeRange:
        rows = [r for r in rows
                if e.timeRange[0] <= r[ti] <= e.timeRange[1]]
    rows = [r for r in rows if len(r) > max(ci, ti)]
    if not rows:
        raise MeasureError("%s: no rows (in the time range)" % path)
    ns = dict(names)
    ns.update(e.constants)
    diffs, ex = [], []
    exactText = str(e.exact)
    for r in rows:
        if exactText == "first":
            x = rows[0][ci]
        else:
            ns["t"] = r[ti]
            x = evaluate(exactText, ns, "error/exact")
        diffs.append(abs(r[ci] - x))
        ex.append(abs(x))
    if any(not math.isfinite(d) for d in diffs):
        raise MeasureError("%s: column %s is not finite" % (path, e.column))
    if e.norm == "rms":
        v = math.sqrt(sum(d * d for d in diffs) / len(diffs))
    elif e.norm == "max":
        v = max(diffs)
    elif e.norm == "mean":
        v = sum(diffs) / len(diffs)
    else:
        v = diffs[-1]
    return v / _divisor(e, ns, ex)


def _divisor(e, ns, exactValues):
    if e.scale is not None:
        s = evaluate(str(e.scale), ns, "error/scale")
        if not s > 0:
            raise MeasureError("error/scale: %g is not positive" % s)
        return s
    if e.relative:
        s = max(exactValues)
        if not s > 0:
            raise MeasureError("error relative: the exact value is 0")
        return s
    return 1.0


def valueError(e, value, names):
    """|value - exact| (scaled) of a command measure with an exact value;
    the value itself when there is none."""
    if e.exact is None:
        return value
    ns = dict(names)
    ns.update(e.constants)
    x = evaluate(str(e.exact), ns, "error/exact")
    return abs(value - x) / _divisor(e, ns, [abs(x)])
