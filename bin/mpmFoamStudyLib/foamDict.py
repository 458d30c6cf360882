"""OpenFOAM dictionaries for mpmFoamStudy: a small reader of the syntax
(entries, sub-dictionaries, lists, quoted strings, comments) and the calls
of OpenFOAM's own foamDictionary that read and set entries of a case.

The studyDict is first expanded by `foamDictionary -expand` (so #include,
$var and #calc work as in any OpenFOAM dictionary), then parsed here.
Values are kept as OpenFOAM text items: str (a word or number), Quoted (a
string written in double quotes), list, or dict, so that a value goes back
to foamDictionary -set exactly as the user wrote it.
"""

import os
import shutil
import subprocess


class DictError(Exception):
    """A studyDict or case dictionary problem; the message names the file
    and the entry."""


class Quoted(str):
    """A string that was written in double quotes."""


# ---------------------------------------------------------------------------
# Tokenizer and parser

_PUNCT = "{}();"


def tokenize(text, fileName="<text>"):
    """Tokens of OpenFOAM dictionary text: punctuation, Quoted strings and
    words.  A word may hold balanced parentheses (div(phi,U), L1(rho)), as
    OpenFOAM's own reader allows.  Inside quotes \\" is a quote and a
    backslash before a newline joins lines; other backslashes stay."""
    toks = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if c.isspace():
            i += 1
        elif text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j + 1
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            if j < 0:
                raise DictError("%s: unterminated /* comment" % fileName)
            i = j + 2
        elif c in _PUNCT:
            toks.append(c)
            i += 1
        elif c == '"':
            j = i + 1
            buf = []
            while True:
                if j >= n:
                    raise DictError("%s: unterminated string" % fileName)
                d = text[j]
                if d == "\\" and j + 1 < n and text[j + 1] in '"\n':
                    if text[j + 1] == '"':
                        buf.append('"')
                    j += 2
                    continue
                if d == '"':
                    break
                buf.append(d)
                j += 1
            toks.append(Quoted("".join(buf)))
            i = j + 1
        else:
            j = i
            depth = 0
            while j < n:
                d = text[j]
                if d.isspace() or d in '{};"':
                    break
                if d == "(":
                    depth += 1
                elif d == ")":
                    if depth == 0:
                        break
                    depth -= 1
                j += 1
            toks.append(text[i:j])
            i = j
    return _joinSlashes(toks)


def _isWord(tok):
    return not isinstance(tok, Quoted) and tok not in _PUNCT


def _joinSlashes(toks):
    """OpenFOAM reads '/' as an operator and foamDictionary -expand writes
    system/shockMpmDict as 'system / shockMpmDict': join such words again
    (file names and entry paths are what a studyDict writes that way)."""
    out = []
    k = 0
    while k < len(toks):
        t = toks[k]
        if (t == "/" and _isWord(t) and out and _isWord(out[-1])
                and k + 1 < len(toks) and _isWord(toks[k + 1])):
            out[-1] = out[-1] + "/" + toks[k + 1]
            k += 2
            continue
        out.append(t)
        k += 1
    return out


def _isPunct(tok, p):
    return not isinstance(tok, Quoted) and tok == p


class _Parser:
    def __init__(self, toks, fileName):
        self.toks = toks
        self.pos = 0
        self.fileName = fileName

    def peek(self):
        return self.toks[self.pos] if self.pos < len(self.toks) else None

    def take(self):
        tok = self.peek()
        if tok is None:
            raise DictError("%s: unexpected end of file" % self.fileName)
        self.pos += 1
        return tok

    def dictionary(self, closing):
        d = {}
        while True:
            tok = self.peek()
            if tok is None:
                if closing:
                    raise DictError("%s: missing '}'" % self.fileName)
                return d
            if closing and _isPunct(tok, "}"):
                self.pos += 1
                return d
            if _isPunct(tok, ";"):
                self.pos += 1
                continue
            key = self.take()
            if not isinstance(key, Quoted) and key in _PUNCT:
                raise DictError("%s: '%s' where a keyword was expected"
                                % (self.fileName, key))
            if self.peek() is not None and _isPunct(self.peek(), "{"):
                self.pos += 1
                d[str(key)] = self.dictionary(True)
                continue
            items = []
            while True:
                tok = self.peek()
                if tok is None:
                    raise DictError("%s: entry '%s' lacks its ';'"
                                    % (self.fileName, key))
                if _isPunct(tok, ";"):
                    self.pos += 1
                    break
                if _isPunct(tok, "}"):
                    raise DictError("%s: entry '%s' lacks its ';'"
                                    % (self.fileName, key))
                items.append(self.item())
            if str(key).startswith("#"):
                continue    # a directive foamDictionary did not expand
            d[str(key)] = items[0] if len(items) == 1 else items
        return d

    def item(self):
        tok = self.take()
        if isinstance(tok, Quoted):
            return tok
        if tok == "(":
            out = []
            while True:
                t = self.peek()
                if t is None:
                    raise DictError("%s: missing ')'" % self.fileName)
                if _isPunct(t, ")"):
                    self.pos += 1
                    return out
                out.append(self.item())
        if tok == "{":
            return self.dictionary(True)
        if tok in ");}":
            raise DictError("%s: unexpected '%s'" % (self.fileName, tok))
        return tok


def parse(text, fileName="<text>"):
    """The dictionary of OpenFOAM text (FoamFile header left out)."""
    d = _Parser(tokenize(text, fileName), fileName).dictionary(False)
    d.pop("FoamFile", None)
    return d


# ---------------------------------------------------------------------------
# Values back to OpenFOAM text

def toText(value):
    """OpenFOAM text of a parsed value (for foamDictionary -set)."""
    if isinstance(value, Quoted):
        return '"%s"' % value.replace('"', '\\"')
    if isinstance(value, dict):
        return "{ %s }" % " ".join("%s %s;" % (k, toText(v))
                                   for k, v in value.items())
    if isinstance(value, list):
        return "(%s)" % " ".join(toText(v) for v in value)
    return str(value)


def toLabel(value):
    """Short human text of a value (tables, progress lines)."""
    if isinstance(value, list):
        return "(%s)" % " ".join(toLabel(v) for v in value)
    if isinstance(value, dict):
        return toText(value)
    return str(value)


def asNumber(value):
    """float of a value, or None if it is not a number."""
    if isinstance(value, (list, dict)):
        return None
    try:
        return float(value)
    except (TypeError, ValueError):
        return None


# ---------------------------------------------------------------------------
# foamDictionary

def foamDictionaryPath():
    exe = shutil.which("foamDictionary")
    if exe is None:
        raise DictError("foamDictionary is not on PATH: source "
                        "$MPMFOAM_DIR/etc/bashrc first")
    return exe


def _run(args, cwd=None):
    p = subprocess.run([foamDictionaryPath()] + args, cwd=cwd,
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       universal_newlines=True)
    return p.returncode, p.stdout


def _foamMessage(out):
    """The first lines of a FOAM FATAL (IO) ERROR message."""
    lines = [l.strip() for l in out.splitlines()]
    for k, l in enumerate(lines):
        if "FOAM FATAL" in l:
            msg = [m for m in lines[k + 1:k + 6] if m]
            return " ".join(msg[:2])
    return " ".join(l for l in lines if l)[-300:]


def readStudyDict(path):
    """Parse a studyDict after foamDictionary -expand."""
    if not os.path.isfile(path):
        raise DictError("studyDict %s: no such file" % path)
    rc, out = _run(["-expand", path])
    if rc != 0:
        raise DictError("studyDict %s: foamDictionary -expand failed: %s"
                        % (path, _foamMessage(out)))
    return parse(out, path)


def entryExists(caseDir, fileName, entry):
    """(True, '') if foamDictionary finds the entry in caseDir/fileName,
    else (False, its message).  Function entries are not expanded, as when
    the entry is set."""
    rc, out = _run(["-disableFunctionEntries", "-entry", entry,
                    fileName], cwd=caseDir)
    return rc == 0, ("" if rc == 0 else _foamMessage(out))


def parentExists(caseDir, fileName, entry):
    """Whether the sub-dictionary that would hold a new entry exists."""
    parent = entry.rsplit("/", 1)[0] if "/" in entry else ""
    if not parent:
        return True, ""
    return entryExists(caseDir, fileName, parent)


def setEntry(caseDir, fileName, entry, valueText):
    """foamDictionary -entry entry -set value file in caseDir.  Function
    entries (#include, $var) are left as they are, not expanded into the
    file: a blockMeshDict's ($nCells 1 1) still follows nCells."""
    rc, out = _run(["-disableFunctionEntries", "-entry", entry, "-set",
                    valueText, fileName], cwd=caseDir)
    if rc != 0:
        raise DictError("%s: foamDictionary -entry %s -set %s failed: %s"
                        % (fileName, entry, valueText, _foamMessage(out)))
