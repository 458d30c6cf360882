#!/usr/bin/python3
"""Dictionary fuzz: every entry of a case's dictionaries set to a bad value.

    fuzz.py [-j N] [-timeout S] [-only TARGET[,TARGET]] [-entry SUBSTRING]
            [-mutations m1,m2] [-out DIR] targets_*.py ...

Each targets_<area>.py module defines TARGETS, a list of dicts:

    name      short name of the target (the application and its case)
    setup     bash run once in DIR/<name>/base: prepares a case that runs
              cleanly and quickly ($MPMFOAM_DIR, $MPMFOAM_TUTORIALS are set)
    run       bash run in a copy of base for every mutation; its exit status
              and output are what is classified (e.g. "mpmSetParticles &&
              umlsMpmFoam")
    files     {file: None | [prefixes]}: the dictionaries whose entries are
              mutated: every single-line entry 'keyword value;' (inside
              sub-dictionaries and lists of dictionaries too), or only those
              whose path (materials/disk/E) starts with one of the prefixes.
              A field value 'uniform v' gets 'uniform <bad>' (a vector its
              first component); 'libs' and 'dimensions' are left alone
    clean     optional bash run in base after the clean run (remove outputs)
    skip      optional [entry paths]: entries left alone (say why in a comment)
    foreign   optional [entry paths]: entries that OpenFOAM's own code reads
              and reports (say which in a comment): a FatalError that does
              not name them counts as 'foreign', not 'unnamed'
    timeout   optional, seconds for one run (default: -timeout)

Every leaf entry gets each mutation:

    negative  -1 (or minus the entry's number)      zero   0
    nan       nan                                   huge   1e300
    mhuge     -1e300                                word   fuzzWord
    list      (1 2 3)                               missing  entry removed

Each run is classified:

    ok           exit 0 and no non-finite number in its log
    named        non-zero exit with a FOAM FATAL (IO) ERROR whose message
                 names the entry (its keyword, as a word of its own, after
                 the case's paths and the lines that say where in the code
                 it was raised are removed) - what we want for bad input
    unnamed      non-zero exit with a FatalError that does not name the entry
    foreign      the same for an entry the target lists as 'foreign'
    signal       killed by a signal (SIGFPE, SIGSEGV, abort ...) or a stack
                 trace from a signal handler
    hang         did not end within the time limit
    nan          exit 0 but "nan" or "inf" in its log (not counted where the
                 mutation itself was nan: the run may echo it) or in a file
                 the run wrote
    other        non-zero exit without a FOAM FATAL message

Results: DIR/results.csv (target, file, entry, mutation, class, exit code,
seconds, the first line of the fatal message) and a summary per target and
class on stdout.  The exit status is 0 when no run is signal, hang, nan,
other or unnamed.
"""

import argparse
import csv
import importlib.util
import os
import re
import shutil
import signal
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

MUTATIONS = {
    "negative": None,           # computed from the entry's value
    "zero": "0",
    "nan": "nan",
    "huge": "1e300",
    "mhuge": "-1e300",
    "word": "fuzzWord",
    "list": "(1 2 3)",
    "missing": None,
}

# OpenFOAM's own bookkeeping entries, not the toolkit's settings
SKIP_KEYS = ("libs", "dimensions")

BAD_CLASSES = ("signal", "hang", "nan", "other", "unnamed")

NONFINITE = re.compile(r"(?<![A-Za-z_])[-+]?(nan|inf)(?![A-Za-z_])", re.IGNORECASE)
# what bash prints for a child of a command list that a signal killed, and
# what the C++ runtime prints for an uncaught exception
# (bash: "line 1: 1234 Floating point exception (core dumped) app"; not
# OpenFOAM's banner line "trapFpe: Floating point exception trapping ...")
SIGNAL_TEXT = re.compile(
    r"\b\d+ (Segmentation fault|Floating point exception|Bus error|"
    r"Illegal instruction|Aborted|Killed)|terminate called")


def bash(cmd, cwd, timeout=None, log=None):
    """Run cmd with bash in cwd, in its own process group; return (rc, secs, timed out)."""
    t0 = time.time()
    out = open(log, "w") if log else subprocess.DEVNULL
    p = subprocess.Popen(["bash", "-c", cmd], cwd=cwd, stdout=out,
                         stderr=subprocess.STDOUT, start_new_session=True,
                         env=dict(os.environ, FOAM_SIGFPE="true"))
    try:
        rc = p.wait(timeout=timeout)
        hung = False
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        rc = p.wait()
        hung = True
    if log:
        out.close()
    return rc, time.time() - t0, hung


ENTRY = re.compile(r"(?<![\w.#$])([A-Za-z_][\w:]*)[ \t]+([^;{}\n]*?)[ \t]*;")
OPEN = re.compile(r"(?:^|[\s;}])([A-Za-z_][\w:]*)?\s*\{|\}")


def find_entries(path):
    """Single-line entries 'keyword value;' of a dictionary file, as
    (path, line, start, end, value): path is the keyword with its enclosing
    sub-dictionaries (materials/disk/E), start:end the value's span."""
    found = []
    stack = []
    pending = ""
    in_comment = False
    for ln, line in enumerate(open(path).read().split("\n")):
        code = line
        if in_comment:
            if "*/" not in code:
                continue
            code = " " * (code.index("*/") + 2) + code[code.index("*/") + 2:]
            in_comment = False
        if "/*" in code:
            i = code.index("/*")
            j = code.find("*/", i + 2)
            if j < 0:
                code = code[:i]
                in_comment = True
            else:
                code = code[:i] + " " * (j + 2 - i) + code[j + 2:]
        if "//" in code:
            code = code[:code.index("//")]
        # a name alone on its line opens the sub-dictionary on the next line
        if re.fullmatch(r"\s*[A-Za-z_][\w:]*\s*", code):
            pending = code.strip()
            continue
        # walk the line: braces change the context, entries are recorded
        events = [(m.start(), "brace", m) for m in OPEN.finditer(code)]
        events += [(m.start(), "entry", m) for m in ENTRY.finditer(code)]
        for pos, kind, m in sorted(events, key=lambda e: e[0]):
            if kind == "brace":
                if m.group(0).endswith("{"):
                    stack.append(m.group(1) or pending)
                    pending = ""
                elif stack:
                    stack.pop()
            else:
                if "FoamFile" in stack or m.group(1) in ("FoamFile",):
                    continue
                ctx = [s for s in stack if s]
                found.append(("/".join(ctx + [m.group(1)]), ln, m.start(2), m.end(2), m.group(2)))
    return found


def mutate(path, entry, mutation):
    """Write the file with one entry mutated; return the text shown."""
    lines = open(path).read().split("\n")
    _, ln, a, b, value = entry
    line = lines[ln]
    if mutation == "missing":
        # remove 'keyword value;' (the keyword starts before the value)
        k = line.rfind(entry[0].split("/")[-1], 0, a)
        semi = line.index(";", b)
        lines[ln] = line[:k] + line[semi + 1:]
        shown = "(removed)"
    else:
        bad = bad_value(mutation, value)
        if value.startswith("uniform ("):
            inner = value[len("uniform ("):].split()
            shown = "uniform (" + " ".join([bad] + inner[1:])
        elif value.startswith("uniform "):
            shown = "uniform " + bad
        else:
            shown = bad
        lines[ln] = line[:a] + shown + line[b:]
    open(path, "w").write("\n".join(lines))
    return shown


def bad_value(mutation, current):
    if mutation == "negative":
        try:
            v = float(current.strip().rstrip(";"))
            return repr(-abs(v)) if v != 0 else "-1"
        except ValueError:
            return "-1"
    return MUTATIONS[mutation]


def classify(rc, hung, logtext, keyword, mutation="", written=(), paths=()):
    """The class of one run (see the module's doc) and a short reason."""
    if hung:
        return "hang", ""
    fatal = ""
    m = re.search(r"FOAM FATAL (IO )?ERROR.*", logtext, re.DOTALL)
    if m:
        fatal = m.group(0)
    first = ""
    if fatal:
        lines = [l.strip() for l in fatal.splitlines()[1:] if l.strip()]
        first = lines[0] if lines else ""
    # a FatalError that aborts (SIGABRT after its message) is still a FatalError
    aborted = rc in (-6, 134) and "FOAM aborting" in logtext and fatal
    if (rc < 0 or rc > 128) and not aborted:
        n = -rc if rc < 0 else rc - 128
        try:
            name = signal.Signals(n).name
        except ValueError:
            name = "signal %d" % n
        return "signal", "%s %s" % (name, first)
    s = SIGNAL_TEXT.search(logtext)
    if s:
        return "signal", s.group(0)
    if rc == 0:
        # a 'nan' the run only echoes (e.g. "Unknown function type nan")
        # is not a result
        n = NONFINITE.search(logtext) if mutation != "nan" else None
        if n:
            line = logtext[logtext.rfind("\n", 0, n.start()) + 1:logtext.find("\n", n.end())]
            return "nan", line.strip()
        for path in written:
            return "nan", "in " + path
        return "ok", ""
    if not fatal:
        return "other", "exit %d" % rc
    if names_entry(fatal, keyword, paths):
        return "named", first
    return "unnamed", first


# the lines of a FatalError that say where in the code it was raised (the
# function and the source file); the 'file:' line stays: OpenFOAM's parser
# names the entry's scope there (".../0/p.internalField at line 18")
WHERE_LINE = re.compile(r"^\s*(From function|From |in file )")


def names_entry(fatal, keyword, paths=()):
    """Whether the message of a FatalError names the entry's keyword as a
    word of its own.  The case's paths are removed first (a run's directory
    holds the entry's name), and so are the lines that only say where in
    the code it was raised: a message that prints the file's path does not name
    the entry by doing so.  An entry's scope in the dictionary
    (mpmProperties.materials.disk.E) names it."""
    text = fatal
    for p in sorted(set(paths), key=len, reverse=True):
        if p:
            text = text.replace(p, "<case>")
    body = "\n".join(l for l in text.splitlines()[1:] if not WHERE_LINE.match(l))
    word = r"(?<![\w])%s(?![\w])" % re.escape(keyword)
    return re.search(word, body) is not None


def nonfinite_outputs(run, t0, mutated):
    """Files the run wrote (time directories, postProcessing, lagrangian)
    that hold a non-finite number; logs and the mutated file left out."""
    found = []
    for root, dirs, files in os.walk(run):
        for f in files:
            p = os.path.join(root, f)
            rel = os.path.relpath(p, run)
            if f.startswith("log.") or rel == mutated or f.endswith((".pt", ".png")):
                continue
            try:
                if os.path.getmtime(p) < t0 or os.path.getsize(p) > 4 << 20:
                    continue
                with open(p, errors="replace") as fh:
                    text = fh.read()
            except OSError:
                continue
            body = text[text.find("}", text.find("FoamFile")) + 1:] if "FoamFile" in text else text
            if NONFINITE.search(body):
                found.append(rel)
    return found


def load_targets(paths):
    targets = []
    for p in paths:
        spec = importlib.util.spec_from_file_location(os.path.basename(p)[:-3], p)
        mod = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(mod)
        targets.extend(mod.TARGETS)
    return targets


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("-j", type=int, default=2, help="runs at once (default 2)")
    ap.add_argument("-timeout", type=float, default=60.0,
                    help="seconds a run may take (default 60)")
    ap.add_argument("-only", default="", help="comma-separated target names")
    ap.add_argument("-entry", default="", help="only entries containing this")
    ap.add_argument("-mutations", default=",".join(MUTATIONS),
                    help="comma-separated mutations (default all)")
    ap.add_argument("-out", default="fuzz", help="work and result directory")
    ap.add_argument("-keep", action="store_true", help="keep every run's copy")
    ap.add_argument("targets", nargs="+")
    a = ap.parse_args()

    mutations = [m for m in a.mutations.split(",") if m]
    for m in mutations:
        if m not in MUTATIONS:
            sys.exit("fuzz.py: unknown mutation '%s' (allowed: %s)" % (m, ", ".join(MUTATIONS)))
    targets = load_targets(a.targets)
    if a.only:
        names = a.only.split(",")
        targets = [t for t in targets if t["name"] in names]
    os.makedirs(a.out, exist_ok=True)
    out = os.path.abspath(a.out)

    jobs = []
    setup_failed = []
    for t in targets:
        tdir = os.path.join(out, t["name"])
        base = os.path.join(tdir, "base")
        shutil.rmtree(tdir, ignore_errors=True)
        os.makedirs(base)
        rc, secs, hung = bash("set -e\n" + t["setup"], base, timeout=900,
                              log=os.path.join(tdir, "log.setup"))
        if rc != 0:
            print("SETUP FAILED: %s (see %s/log.setup)" % (t["name"], tdir))
            setup_failed.append(t["name"])
            continue
        # the unmutated case must run cleanly: else every mutation is noise
        rc, secs, hung = bash(t["run"], base, timeout=t.get("timeout", a.timeout),
                              log=os.path.join(tdir, "log.base"))
        if rc != 0 or hung:
            print("BASE CASE FAILED: %s (exit %d%s; see %s/log.base)"
                  % (t["name"], rc, ", timed out" if hung else "", tdir))
            setup_failed.append(t["name"])
            continue
        print("target %s: base case runs in %.1f s" % (t["name"], secs), flush=True)
        # what the base run wrote is not part of the copies
        bash(t.get("clean", "true"), base)
        skip = set(t.get("skip", []))
        for fname in t["files"]:
            prefixes = t["files"][fname]
            for e in find_entries(os.path.join(base, fname)):
                key = e[0].split("/")[-1]
                if e[0] in skip or key in SKIP_KEYS:
                    continue
                if prefixes and not any(e[0].startswith(p) for p in prefixes):
                    continue
                if a.entry and a.entry not in e[0]:
                    continue
                for m in mutations:
                    jobs.append((t, fname, e, m))
    print("%d runs" % len(jobs), flush=True)

    t_start = time.time()
    done = [0]

    def one(job):
        t, fname, e, m = job
        tdir = os.path.join(out, t["name"])
        tag = "%s_%s_%d_%s" % (fname.replace("/", "."), e[0].replace("/", "."), e[1], m)
        run = os.path.join(tdir, tag)
        shutil.rmtree(run, ignore_errors=True)
        shutil.copytree(os.path.join(tdir, "base"), run, symlinks=True)
        shown = mutate(os.path.join(run, fname), e, m)
        log = os.path.join(run, "log.run")
        t0 = time.time()
        rc, secs, hung = bash(t["run"], run, timeout=t.get("timeout", a.timeout), log=log)
        with open(log, errors="replace") as f:
            text = f.read()
        cls, why = classify(rc, hung, text, e[0].split("/")[-1], m,
                            nonfinite_outputs(run, t0, fname) if rc == 0 else (),
                            (run, os.path.realpath(run), out, os.path.realpath(out)))
        if cls == "unnamed" and e[0] in t.get("foreign", []):
            cls = "foreign"
        result = (t["name"], fname, e[0], m, shown, cls, rc, round(secs, 2), why[:160])
        if cls in ("ok", "named", "foreign") and not a.keep:
            shutil.rmtree(run, ignore_errors=True)
        done[0] += 1
        el = time.time() - t_start
        eta = el / done[0] * (len(jobs) - done[0])
        if done[0] % 25 == 0 or cls in BAD_CLASSES:
            print("run %d/%d  %s %s %s = %s: %s %s  elapsed %.0f s  ETA %.0f s"
                  % (done[0], len(jobs), t["name"], fname, e[0], shown, cls,
                     why[:70], el, eta), flush=True)
        return result

    with ThreadPoolExecutor(max_workers=a.j) as ex:
        results = list(ex.map(one, jobs))

    with open(os.path.join(out, "results.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["target", "file", "entry", "mutation", "value", "class", "exit",
                    "seconds", "message"])
        w.writerows(results)

    classes = ["ok", "named", "foreign", "unnamed", "signal", "hang", "nan", "other"]
    print("\n%-28s %s" % ("target", " ".join("%8s" % c for c in classes)))
    for name in sorted(set(r[0] for r in results)):
        rs = [r for r in results if r[0] == name]
        print("%-28s %s" % (name, " ".join("%8d" % sum(r[5] == c for r in rs) for c in classes)))
    print("%-28s %s" % ("all", " ".join("%8d" % sum(r[5] == c for r in results) for c in classes)))
    print("wall %.0f s" % (time.time() - t_start))
    bad = [r for r in results if r[5] in BAD_CLASSES]
    for r in bad[:80]:
        print("BAD: %s %s %s = %s -> %s (exit %s): %s" % (r[0], r[1], r[2], r[4], r[5], r[6], r[8]))
    for name in setup_failed:
        print("BAD: target %s: its base case does not run" % name)
    return 1 if bad or setup_failed else 0


if __name__ == "__main__":
    sys.exit(main())
