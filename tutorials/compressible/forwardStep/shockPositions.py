#!/usr/bin/python3
"""forwardStep (mpmFoam tutorial): shock positions from the written fields.

Usage:
    shockPositions.py <caseDir> <time>
    shockPositions.py compare <caseA> <caseB> <time>
    shockPositions.py table <caseA> <caseB> <time>...

Reads the ascii fields rho and p of <time> (internalField uniform or
nonuniform List<scalar>) and the cell centres (the field C that
`postProcess -func writeCellCentres` writes; run here if no time of the case
has it yet), maps the cells to the i-j grid of the case (square cells,
dx = dy = 0.0125, x in [0, 3], y in [0, 1]; the step is x > 0.6, y < 0.2) and
measures along grid rows, at the faces between neighbouring cells:

  bowShock_yY_x   on the cell row whose centre is the first above y = Y
                  (Y = 0.3: centres at y = 0.30625; Y = 0.5: y = 0.50625),
                  the face x of the largest |rho(i+1) - rho(i)| upstream of
                  the step face (faces x < 0.6)
  standoff_yY     0.6 - bowShock_yY_x, the bow shock's stand-off distance
  topWallShock_x  on the row next to the top wall (centres y = 0.99375),
                  the face x of the largest pressure rise p(i+1) - p(i)
                  (the steepest point of the shock foot on the wall: Mach
                  stem or regular reflection); "none" if no rise reaches
                  half the inlet pressure
  topWallShock2_x the same for a second shock foot on the top wall, the
                  largest rise at least 8 cells from topWallShock_x (from
                  t = 3: the shock reflected from the step back up to the
                  wall); "none" if no rise reaches half the inlet pressure
  stepShock_x     on the row next to the top of the step (centres
                  y = 0.20625), faces x > 0.6 + 4 dx, the face x of the
                  largest pressure rise: the foot of the reflected shock
                  where it hits the step; "none" if no rise reaches half
                  the inlet pressure (the gradual recompression after the
                  corner's expansion stays below a tenth of it per cell)

Rises, not |jumps|: the flow goes in +x everywhere, so the pressure rises in
+x across every shock and falls across expansions.  Taking the steepest
face, not the first face of the smeared profile, makes the position
insensitive to how many cells a scheme smears a shock over.

Output: one "name value" line per quantity (grep for the name, value in
column 2), the jumps as "<name>_jump" (|drho| for the bow shock, dp over
the inlet pressure for the others), "dx 0.0125" and "#" comment lines
describing the rows.

compare: measures both cases at <time> and prints, per position,
"name valueA valueB differenceInCells"; the last line is "agree yes" or
"agree no" and the exit status is 0 if every position differs by at most
2 cells (a quantity that is "none" in both counts as agreeing).

table: the same comparison for several times as one table, a row per time
and position ("t name valueA valueB cells", "<-- more than 2 cells" where
they do not agree), ending in "agree yes" or "agree no"; exit status as for
compare.
"""
import sys
import os
import re
import glob
import subprocess
import numpy as np

DX = 0.0125
NX, NY = 240, 80                 # x in [0, 3], y in [0, 1]
STEP_X, STEP_Y = 0.6, 0.2
NSTEP_I, NSTEP_J = 48, 16        # cells i >= 48, j < 16 are inside the step
TOL_CELLS = 2.0
MIN_RISE = 0.5                   # weakest pressure rise (/ inlet p) taken as a shock
CORNER_CELLS = 4                 # faces this close to the corner are skipped
SEPARATION = 8                   # cells between the two top-wall shock feet


# --------------------------------------------------------------------------
# Reading OpenFOAM ascii fields

def timeDir(case, time):
    """The time directory of <case> whose value is <time>."""
    direct = os.path.join(case, str(time))
    if os.path.isdir(direct):
        return direct
    t = float(time)
    for d in glob.glob(os.path.join(case, "*")):
        name = os.path.basename(d)
        try:
            v = float(name)
        except ValueError:
            continue
        if os.path.isdir(d) and abs(v - t) <= 1e-9*max(1.0, abs(t)):
            return d
    raise SystemExit("shockPositions: no time %s in %s" % (time, case))


def readInternalField(path, nCells=None):
    """internalField of an ascii vol field: array (n,) or (n, 3)."""
    if not os.path.exists(path):
        raise SystemExit("shockPositions: no file %s" % path)
    with open(path) as f:
        text = f.read()
    m = re.search(r"^\s*internalField\s+", text, re.M)
    if m is None:
        raise SystemExit("shockPositions: no internalField in %s" % path)
    rest = text[m.end():]
    u = re.match(r"uniform\s+(\([^)]*\)|[^;\s]+)\s*;", rest)
    if u:
        value = np.array(u.group(1).strip("()").split(), dtype=float)
        if nCells is None:
            raise SystemExit("shockPositions: uniform %s needs the cell count"
                             % path)
        return np.tile(value, (nCells, 1)) if value.size > 1 \
            else np.full(nCells, value[0])
    n = re.match(r"nonuniform\s+List<(scalar|vector)>\s*(\d+)\s*\(", rest)
    if n is None:
        raise SystemExit("shockPositions: %s: internalField is neither uniform"
                         " nor an ascii nonuniform List<scalar|vector>" % path)
    kind, size = n.group(1), int(n.group(2))
    body = rest[n.end():]
    width = 3 if kind == "vector" else 1
    if kind == "vector":
        end = body.index("\n)")
        values = np.array(body[:end].replace("(", " ").replace(")", " ")
                          .split(), dtype=float)
    else:
        end = body.index(")")
        values = np.array(body[:end].split(), dtype=float)
    if values.size != size*width:
        raise SystemExit("shockPositions: %s: expected %d values, read %d"
                         % (path, size*width, values.size//width))
    return values.reshape(size, 3) if kind == "vector" else values


def blockCentres():
    """Cell centres of system/blockMeshDict's three blocks, in blockMesh's
    order (block by block, x fastest); only the fallback when no C can be
    written."""
    xs, ys = [], []
    for i0, j0, ni, nj in ((0, 0, 48, 16), (0, 16, 48, 64), (48, 16, 192, 64)):
        j, i = np.mgrid[j0:j0 + nj, i0:i0 + ni]
        xs.append(((i + 0.5)*DX).ravel())
        ys.append(((j + 0.5)*DX).ravel())
    return np.column_stack((np.concatenate(xs), np.concatenate(ys)))


def cellCentres(case, tdir):
    """(nCells, 2) cell centres: the field C of this time, of another time
    (the mesh does not move), one written now with postProcess, or the
    block structure."""
    candidates = [os.path.join(tdir, "C")] \
        + sorted(glob.glob(os.path.join(case, "*", "C")))
    for c in candidates:
        if os.path.exists(c):
            return readInternalField(c)[:, :2]
    time = os.path.basename(tdir)
    try:
        with open(os.path.join(case, "log.writeCellCentres"), "w") as log:
            subprocess.run(["postProcess", "-case", case, "-func",
                            "writeCellCentres", "-time", time],
                           stdout=log, stderr=subprocess.STDOUT, check=True)
        return readInternalField(os.path.join(tdir, "C"))[:, :2]
    except (OSError, subprocess.CalledProcessError, SystemExit) as err:
        sys.stderr.write("shockPositions: writeCellCentres failed (%s); cell"
                         " centres from the blockMeshDict structure\n" % err)
        return blockCentres()


class Grid:
    """The fields of one case and time on the i-j grid: f[j, i], NaN in
    the step."""

    def __init__(self, case, time):
        self.case, self.time = case, time
        self.tdir = timeDir(case, time)
        C = cellCentres(case, self.tdir)
        n = len(C)
        i = np.floor(C[:, 0]/DX).astype(int)
        j = np.floor(C[:, 1]/DX).astype(int)
        off = np.abs(C[:, 0] - (i + 0.5)*DX) + np.abs(C[:, 1] - (j + 0.5)*DX)
        if (off.max() > 1e-6 or i.min() < 0 or j.min() < 0 or i.max() >= NX
                or j.max() >= NY or n != NX*NY - (NX - NSTEP_I)*NSTEP_J):
            raise SystemExit("shockPositions: %s is not the forwardStep mesh"
                             " (16128 square cells of %g)" % (case, DX))
        self.i, self.j = i, j
        self.fields = {}
        self.nCells = n

    def __getitem__(self, name):
        if name not in self.fields:
            v = readInternalField(os.path.join(self.tdir, name), self.nCells)
            f = np.full((NY, NX), np.nan)
            f[self.j, self.i] = v
            self.fields[name] = f
        return self.fields[name]


# --------------------------------------------------------------------------
# Measurements

def rowAbove(y):
    """Index and centre of the first cell row whose centre is above y."""
    j = int(np.floor(y/DX - 0.5 + 1e-9)) + 1
    return j, (j + 0.5)*DX


def measure(g):
    """[(name, value or None, comment)] for case/time g."""
    out = []
    rho, p = g["rho"], g["p"]
    for y in (0.3, 0.5):
        j, yc = rowAbove(y)
        r = rho[j, :NSTEP_I]                     # centres x < 0.6
        d = np.abs(np.diff(r))                   # faces x = dx .. 0.5875
        k = int(np.argmax(d))
        x = (k + 1)*DX
        tag = "y%g" % y
        out.append(("bowShock_%s_x" % tag, x,
                    "row y = %.5f, largest |drho| at faces x < 0.6" % yc))
        out.append(("standoff_%s" % tag, STEP_X - x, "0.6 - bowShock_%s_x" % tag))
        out.append(("bowShock_%s_jump" % tag, d[k], "|drho| there"))

    pIn = np.nanmean(p[:, 0])                    # inlet pressure (1)

    def rise(row, i0, name, comment, exclude=None):
        dp = np.diff(p[row, i0:])/pIn
        if exclude is not None:
            k0 = exclude - i0
            dp[max(0, k0 - SEPARATION):max(0, k0 + SEPARATION + 1)] = -np.inf
        k = int(np.argmax(dp))
        out.append((name + "_x", (i0 + k + 1)*DX if dp[k] >= MIN_RISE
                    else None, comment))
        out.append((name + "_jump", max(dp[k], 0.0),
                    "dp/p_inlet there (shock if >= %g)" % MIN_RISE))
        return i0 + k

    first = rise(NY - 1, 0, "topWallShock",
                 "row y = %.5f, largest pressure rise" % ((NY - 0.5)*DX))
    rise(NY - 1, 0, "topWallShock2",
         "row y = %.5f, largest pressure rise %d cells or more from"
         " topWallShock_x" % ((NY - 0.5)*DX, SEPARATION), exclude=first)
    rise(NSTEP_J, NSTEP_I + CORNER_CELLS, "stepShock",
         "row y = %.5f, largest pressure rise at faces x > %g"
         % ((NSTEP_J + 0.5)*DX, STEP_X + CORNER_CELLS*DX))
    return out


def fmt(v):
    return "none" if v is None else "%.6g" % v


def report(case, time):
    g = Grid(case, time)
    print("# forwardStep shock positions: case %s, time %s" % (case, time))
    print("dx %g" % DX)
    for name, v, comment in measure(g):
        print("# %s: %s" % (name, comment))
        print("%s %s" % (name, fmt(v)))


def differences(caseA, caseB, time):
    """[(name, valueA, valueB, cells as text, agrees)] of the positions."""
    a = measure(Grid(caseA, time))
    b = dict((n, v) for n, v, _ in measure(Grid(caseB, time)))
    rows = []
    for name, va, _ in a:
        if name.endswith("_jump"):
            continue
        vb = b[name]
        if va is None and vb is None:
            cells, ok = "0", True
        elif va is None or vb is None:
            cells, ok = "inf", False
        else:
            c = abs(va - vb)/DX
            cells, ok = "%.2f" % c, c <= TOL_CELLS + 1e-9
        rows.append((name, va, vb, cells, ok))
    return rows


def compare(caseA, caseB, time):
    print("# forwardStep shock positions at time %s: %s against %s"
          % (time, caseA, caseB))
    print("# name  %s  %s  difference [cells of %g]" % (caseA, caseB, DX))
    ok = True
    for name, va, vb, cells, agrees in differences(caseA, caseB, time):
        ok = ok and agrees
        print("%s %s %s %s" % (name, fmt(va), fmt(vb), cells))
    print("agree %s" % ("yes" if ok else "no"))
    return 0 if ok else 1


def table(caseA, caseB, times):
    na = os.path.basename(os.path.abspath(caseA))
    nb = os.path.basename(os.path.abspath(caseB))
    wa, wb = max(len(na), 8), max(len(nb), 8)
    head = "%-4s %-16s %*s %*s %6s" % ("t", "position", wa, na, wb, nb, "cells")
    print(head)
    print("-"*len(head))
    ok = True
    for time in times:
        for name, va, vb, cells, agrees in differences(caseA, caseB, time):
            ok = ok and agrees
            print("%-4s %-16s %*s %*s %6s%s"
                  % (time, name, wa, fmt(va), wb, fmt(vb), cells,
                     "" if agrees else "  <-- more than %g cells" % TOL_CELLS))
    print("agree %s" % ("yes" if ok else "no"))
    return 0 if ok else 1


def main(argv):
    if len(argv) == 4 and argv[0] == "compare":
        return compare(argv[1], argv[2], argv[3])
    if len(argv) >= 4 and argv[0] == "table":
        return table(argv[1], argv[2], argv[3:])
    if len(argv) == 2 and argv[0] != "compare":
        report(argv[0], argv[1])
        return 0
    sys.stderr.write(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
