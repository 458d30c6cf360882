"""The studyDict of mpmFoamStudy, read and checked: settings, points,
commands, cost and error measures.  Every problem stops the study before
it runs anything, with a message naming the studyDict entry (and the case
file and entry where a setting points at one that does not exist).

The format is documented in the header of bin/mpmFoamStudy.
"""

import itertools
import os
import re

from .convergence import ConvergenceSpec
from .foamDict import (DictError, asNumber, entryExists,
                       parentExists, readStudyDict, toLabel, toText)

CASE = None     # a point's value of a setting it leaves as the case has it


class Setting:
    def __init__(self, name, d, where):
        self.name = name
        self.file = _need(d, "file", where, str)
        self.entry = _need(d, "entry", where, str)
        self.new = _bool(d.get("new", "no"), where + "/new")
        values = d.get("values")
        if values is None:
            self.values = []
        elif isinstance(values, list):
            self.values = values
        else:
            self.values = [values]
        labels = d.get("labels")
        self.labels = {}
        if labels is not None:
            if not isinstance(labels, list) or len(labels) != len(self.values):
                raise DictError("%s/labels: a list of %d labels (one per "
                                "value) expected, found %s"
                                % (where, len(self.values), toText(labels)))
            self.labels = {toText(v): str(l)
                           for v, l in zip(self.values, labels)}

    def label(self, value):
        if value is CASE:
            return "(case)"
        return self.labels.get(toText(value), toLabel(value))


class Point:
    """One combination of setting values (CASE: as in the case)."""

    def __init__(self, index, values, settings):
        self.index = index
        self.values = values                # name -> item or CASE
        self.settings = settings
        self.reference = False

    @property
    def tag(self):
        return "p%03d" % self.index

    def labels(self):
        return {s.name: s.label(self.values[s.name]) for s in self.settings}

    def text(self, varyingOnly=None):
        """'name value  name value' (settings left as the case has them
        are left out)."""
        names = varyingOnly or [s.name for s in self.settings]
        return "  ".join("%s %s" % (n, self._setting(n).label(self.values[n]))
                         for n in names if self.values[n] is not CASE)

    def _setting(self, name):
        return [s for s in self.settings if s.name == name][0]

    def key(self):
        """Comparable identity of the point's values (stored results)."""
        return {s.name: (None if self.values[s.name] is CASE
                         else toText(self.values[s.name]))
                for s in self.settings}


class Measure:
    """A number read from the solver's log (default), a file or a
    command's output: the last match of a regex (its first group), or the
    count of a regex's matches."""

    def __init__(self, d, where, defaultFile=None):
        if isinstance(d, str) and d in ("mesh", "checkMesh"):
            self.kind = d
            return
        if not isinstance(d, dict):
            raise DictError("%s: a dictionary { regex ...; } or { count "
                            "...; } (or 'mesh', 'checkMesh' for cells) "
                            "expected, found %s" % (where, toText(d)))
        self.command = d.get("command")
        if self.command is not None and "file" in d:
            raise DictError("%s: give file or command, not both" % where)
        self.file = d.get("file", None if self.command else defaultFile)
        if "regex" in d and "count" in d:
            raise DictError("%s: give regex or count, not both" % where)
        if "regex" in d:
            self.kind = "regex"
            self.regex = _regex(d["regex"], where + "/regex")
        elif "count" in d:
            self.kind = "count"
            self.regex = _regex(d["count"], where + "/count")
        else:
            raise DictError("%s: no 'regex' or 'count' entry" % where)
        self.where = where


class ErrorSpec:
    TYPES = ("command", "monitor", "finest")

    def __init__(self, d, where):
        if not isinstance(d, dict):
            raise DictError("%s: a dictionary expected" % where)
        self.name = str(d.get("name", "error"))
        self.type = _need(d, "type", where, str)
        if self.type not in self.TYPES:
            raise DictError("%s/type: '%s' is not one of %s"
                            % (where, self.type, ", ".join(self.TYPES)))
        self.relative = _bool(d.get("relative", "no"), where + "/relative")
        self.constants = {}
        for k, v in (d.get("constants") or {}).items():
            x = asNumber(v)
            if x is None:
                raise DictError("%s/constants/%s: '%s' is not a number"
                                % (where, k, toText(v)))
            self.constants[k] = x
        self.exact = d.get("exact")
        self.scale = d.get("scale")
        if self.type in ("command", "finest"):
            if "regex" not in d:
                raise DictError("%s: type %s needs a 'regex' that extracts "
                                "the number" % (where, self.type))
            if "file" not in d and "command" not in d:
                raise DictError("%s: type %s needs a 'command' (its output "
                                "is searched) or a 'file'"
                                % (where, self.type))
            self.measure = Measure({k: d[k] for k in ("file", "command",
                                                      "regex") if k in d},
                                   where)
        if self.type == "monitor":
            self.file = _need(d, "file", where, str)
            self.column = _need(d, "column", where, str)
            self.timeColumn = str(d.get("timeColumn", "0"))
            if self.exact is None:
                raise DictError("%s: type monitor needs 'exact' (a number, "
                                "an expression in t, or 'first')" % where)
            self.norm = str(d.get("norm", "rms"))
            if self.norm not in ("rms", "max", "mean", "last"):
                raise DictError("%s/norm: '%s' is not one of rms, max, "
                                "mean, last" % (where, self.norm))
            tr = d.get("timeRange")
            self.timeRange = None
            if tr is not None:
                if not isinstance(tr, list) or len(tr) != 2 or \
                        None in map(asNumber, tr):
                    raise DictError("%s/timeRange: (t0 t1) expected, "
                                    "found %s" % (where, toText(tr)))
                self.timeRange = tuple(map(asNumber, tr))
        if self.type == "finest":
            self.finest = d.get("finest")
            if self.finest is not None and not isinstance(self.finest, dict):
                raise DictError("%s/finest: a dictionary of setting values "
                                "expected" % where)


class Study:
    def __init__(self, caseDir, dictPath):
        self.caseDir = os.path.abspath(caseDir)
        self.dictPath = dictPath
        path = dictPath if os.path.isabs(dictPath) else \
            os.path.join(self.caseDir, dictPath)
        d = readStudyDict(path)
        w = "studyDict %s: " % dictPath
        try:
            self._read(d)
        except DictError as e:
            raise DictError(w + str(e))

    # -- reading -------------------------------------------------------------
    def _read(self, d):
        self.name = str(d.get("studyName", "study"))
        if not re.match(r"^[A-Za-z0-9_.+-]+$", self.name):
            raise DictError("studyName: '%s' is not a plain file name"
                            % self.name)
        sd = d.get("settings")
        if not isinstance(sd, dict) or not sd:
            raise DictError("settings: a dictionary of at least one "
                            "setting expected")
        self.settings = []
        for name, s in sd.items():
            if not isinstance(s, dict):
                raise DictError("settings/%s: a dictionary { file ...; "
                                "entry ...; values (...); } expected" % name)
            self.settings.append(Setting(name, s, "settings/" + name))
        self.byName = {s.name: s for s in self.settings}
        self.prepare = _commands(d, "prepare")
        self.setup = _commands(d, "setup")
        self.post = _commands(d, "post")
        solver = d.get("solver")
        if not isinstance(solver, str) or not solver.strip():
            raise DictError("solver: the timed command (a word or a quoted "
                            "string) is missing")
        self.solver = str(solver)
        self.solverLog = str(d.get("solverLog", "log." + logName(self.solver)))
        if not re.match(r"^[A-Za-z0-9_.+-]+$", self.solverLog):
            raise DictError("solverLog: '%s' is not a plain file name"
                            % self.solverLog)
        self.copy = d.get("copy")
        if self.copy is not None and not isinstance(self.copy, list):
            self.copy = [self.copy]
        self.timeout = _positive(d.get("timeout"), "timeout")
        self.repeat = int(_positive(d.get("repeat", "1"), "repeat"))
        cost = d.get("cost", {})
        if not isinstance(cost, dict):
            raise DictError("cost: a dictionary expected")
        self.cost = {}
        for k in ("steps", "cells", "particles"):
            if k in cost:
                self.cost[k] = Measure(cost[k], "cost/" + k, self.solverLog)
                if cost[k] in ("mesh", "checkMesh") and k != "cells":
                    raise DictError("cost/%s: '%s' gives cells only"
                                    % (k, cost[k]))
        if "cells" in self.cost and "particles" in self.cost:
            raise DictError("cost: give cells or particles, not both")
        self.plotCost = str(cost.get("plot", "wall"))
        if self.plotCost not in ("wall", "cpu", "updates"):
            raise DictError("cost/plot: '%s' is not one of wall, cpu, "
                            "updates" % self.plotCost)
        if self.plotCost == "updates" and ("steps" not in self.cost or not
                                           ("cells" in self.cost or
                                            "particles" in self.cost)):
            raise DictError("cost/plot updates needs cost/steps and "
                            "cost/cells or cost/particles")
        if "error" not in d:
            raise DictError("error: the error measure is missing")
        self.error = ErrorSpec(d["error"], "error")
        self.targets = [_positive(t, "targets")
                        for t in _asList(d.get("targets", []))]
        self.colourBy = d.get("colourBy")
        if self.colourBy is not None and str(self.colourBy) not in self.byName:
            raise DictError("colourBy: '%s' is not a setting (settings: %s)"
                            % (toText(self.colourBy), " ".join(self.byName)))
        self._points(d)
        self.convergence = (ConvergenceSpec(d["convergence"], self)
                            if "convergence" in d else None)
        if self.error.type == "finest":
            sel = self.error.finest
            if sel is not None:
                hits = [p for p in self.points if self._matches(p, sel)]
                if len(hits) != 1:
                    raise DictError("error/finest: %s selects %d points; "
                                    "it must select one"
                                    % (toText(sel), len(hits)))

    def _points(self, d):
        if "points" in d:
            pts = _asList(d["points"])
            combos = []
            for k, pd in enumerate(pts):
                where = "points[%d]" % k
                if not isinstance(pd, dict):
                    raise DictError("%s: a dictionary { setting value; ... } "
                                    "expected, found %s" % (where, toText(pd)))
                for n in pd:
                    if n not in self.byName:
                        raise DictError("%s: '%s' is not a setting (settings:"
                                        " %s)" % (where, n,
                                                  " ".join(self.byName)))
                axes = []
                for s in self.settings:
                    v = pd.get(s.name, CASE)
                    axes.append(v if isinstance(v, list) else [v])
                combos.extend(itertools.product(*axes))
        else:
            axes = []
            for s in self.settings:
                if not s.values:
                    raise DictError("settings/%s/values: no values" % s.name)
                axes.append(s.values)
            combos = list(itertools.product(*axes))
        excl = _asList(d.get("exclude", []))
        for k, e in enumerate(excl):
            self._checkSelector(e, "exclude[%d]" % k)
        points = []
        for c in combos:
            p = Point(0, dict(zip([s.name for s in self.settings], c)),
                      self.settings)
            if any(self._matches(p, e) for e in excl):
                continue
            if any(p.key() == q.key() for q in points):
                continue
            points.append(p)
        if not points:
            raise DictError("no point left (points/exclude)")
        for k, p in enumerate(points):
            p.index = k + 1
        self.points = points
        refs = _asList(d.get("reference", []))
        for k, r in enumerate(refs):
            self._checkSelector(r, "reference[%d]" % k)
            hits = [p for p in points if self._matches(p, r)]
            if not hits:
                raise DictError("reference[%d]: %s matches no point"
                                % (k, toText(r)))
            for p in hits:
                p.reference = True
        if refs and all(p.reference for p in points):
            raise DictError("reference: every point is a reference; "
                            "nothing is left to compare")

    def _checkSelector(self, sel, where):
        if not isinstance(sel, dict):
            raise DictError("%s: a dictionary { setting value; } expected"
                            % where)
        for n in sel:
            if n not in self.byName:
                raise DictError("%s: '%s' is not a setting" % (where, n))

    def _matches(self, p, sel):
        """Whether point p has the values of selector sel (a list there
        means any of its values)."""
        for n, v in sel.items():
            pv = p.values[n]
            opts = v if isinstance(v, list) else [v]
            texts = [toText(o) for o in opts]
            if pv is CASE:
                if "(case)" not in texts and "case" not in texts:
                    return False
            elif toText(pv) not in texts:
                return False
        return True

    # -- checks against the case --------------------------------------------
    def checkCase(self):
        """Every setting's file and entry exist in the case (or its parent,
        for a 'new' entry): the same foamDictionary that will set them."""
        if not os.path.isdir(self.caseDir):
            raise DictError("case %s: no such directory" % self.caseDir)
        w = "studyDict %s: " % self.dictPath
        for s in self.settings:
            used = any(p.values[s.name] is not CASE for p in self.points)
            if not used:
                continue
            path = os.path.join(self.caseDir, s.file)
            if not os.path.isfile(path):
                raise DictError(w + "settings/%s/file: %s is not a file of "
                                "the case %s" % (s.name, s.file, self.caseDir))
            ok, msg = (parentExists if s.new else entryExists)(
                self.caseDir, s.file, s.entry)
            if not ok:
                what = "the dictionary that would hold" if s.new else "entry"
                raise DictError(w + "settings/%s/entry: %s %s not found in "
                                "%s (%s)%s" % (s.name, what, s.entry, s.file,
                                               msg, "" if s.new else
                                               "; 'new yes;' adds an entry"
                                               " the file lacks"))
        if self.copy:
            for c in self.copy:
                if not os.path.exists(os.path.join(self.caseDir, str(c))):
                    raise DictError(w + "copy: %s is not in the case %s"
                                    % (c, self.caseDir))

    def varying(self, compared=False):
        """Names of the settings that take more than one value (compared:
        over the points other than the references)."""
        pts = [p for p in self.points if not (compared and p.reference)]
        return [s.name for s in self.settings
                if len({toText(p.values[s.name]) if p.values[s.name]
                        is not CASE else None for p in pts}) > 1]

    def textNames(self, reference):
        """The settings that name a point in text: those that vary among
        the compared points; for a reference every setting it sets."""
        if reference:
            return [s.name for s in self.settings]
        return self.varying(True) or [s.name for s in self.settings]


# ---------------------------------------------------------------------------

def _need(d, key, where, kind):
    if key not in d:
        raise DictError("%s: no '%s' entry" % (where, key))
    v = d[key]
    if kind is str and (isinstance(v, (list, dict))):
        raise DictError("%s/%s: a word or a string expected, found %s"
                        % (where, key, toText(v)))
    return str(v)


def _bool(v, where):
    t = str(v).lower()
    if t in ("yes", "on", "true", "1"):
        return True
    if t in ("no", "off", "false", "0", "none"):
        return False
    raise DictError("%s: '%s' is not yes or no" % (where, toText(v)))


def _positive(v, where):
    if v is None:
        return None
    x = asNumber(v)
    if x is None or not x > 0:
        raise DictError("%s: '%s' is not a positive number" % (where,
                                                               toText(v)))
    return x


def _asList(v):
    if v is None:
        return []
    return v if isinstance(v, list) else [v]


def _commands(d, key):
    v = d.get(key, [])
    out = []
    for k, c in enumerate(_asList(v)):
        if isinstance(c, (list, dict)) or not str(c).strip():
            raise DictError("%s[%d]: a command (a word or a quoted string) "
                            "expected, found %s" % (key, k, toText(c)))
        out.append(str(c))
    return out


def _regex(v, where):
    if isinstance(v, (list, dict)):
        raise DictError("%s: a quoted regular expression expected" % where)
    try:
        return re.compile(str(v), re.MULTILINE)
    except re.error as e:
        raise DictError("%s: '%s' is not a regular expression (%s)"
                        % (where, v, e))


def logName(command):
    """log.<name> of a command: its first word without directories."""
    first = command.split()[0] if command.split() else "command"
    name = re.sub(r"[^A-Za-z0-9_.+-]", "", os.path.basename(first))
    return name or "command"
