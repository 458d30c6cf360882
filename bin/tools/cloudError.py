#!/usr/bin/python3
"""The error of a case's MPM cloud against a reference case's, frame by frame.

Usage: cloudError.py CASE REFERENCE [-after T] [-cloud NAME] [-steps FILE]

For every time written in CASE after T (default: CASE's first time that is
not 0, its start frame) that REFERENCE also has (to 1e-9), the material
points are matched by id and the RMS of their position error per
component is taken (field x, the positions as computed):
    RMSE(t) = sqrt(sum_p |x_p - x_ref,p|^2 / (3 N))
RMSE-all is the same over all those frames together, as bsmsTrain's
rollouts report it.  Prints one line "frames RMSE-all maxRMSE" ([m]);
with -steps, also writes "time RMSE" per frame to FILE.  Stops with a
message if no frame is compared, or the ids differ.
"""
import os
import re
import struct
import sys


def field(path, width, code):
    """The values of an IOField (ascii or binary), width numbers each."""
    raw = open(path, 'rb').read()
    head = raw.index(b'FoamFile')
    end = raw.index(b'}', head)
    binary = b'binary' in raw[head:end]
    m = re.compile(rb'\s(\d+)\s*\(').search(raw, end + 1)
    n, start = int(m.group(1)), m.end()
    if binary:
        size = struct.calcsize('<' + code)
        flat = struct.unpack('<%d%s' % (n*width, code),
                             raw[start:start + n*width*size])
    else:
        text = raw[start:].decode()
        flat = [float(t) if code == 'd' else int(t)
                for t in re.findall(r'[-+0-9.eE]+', text)[:n*width]]
    return [tuple(flat[i*width:(i + 1)*width]) for i in range(n)]


def times(case, cloud):
    """The case's written times holding the cloud's x and id, sorted."""
    out = []
    for d in os.listdir(case):
        try:
            t = float(d)
        except ValueError:
            continue
        c = os.path.join(case, d, 'lagrangian', cloud)
        if os.path.isfile(c + '/x') and os.path.isfile(c + '/id'):
            out.append((t, c))
    return sorted(out)


def positions(c):
    """The cloud's positions by id."""
    x = field(c + '/x', 3, 'd')
    ids = [i[0] for i in field(c + '/id', 1, 'i')]
    return dict(zip(ids, x))


def main(argv):
    args = argv[1:]
    opts = {'-after': None, '-cloud': 'mpmCloud', '-steps': None}
    pos = []
    while args:
        a = args.pop(0)
        if a in opts:
            if not args:
                sys.exit('cloudError.py: %s needs a value' % a)
            opts[a] = args.pop(0)
        else:
            pos.append(a)
    if len(pos) != 2:
        sys.exit(__doc__)
    case, ref = pos
    mine = times(case, opts['-cloud'])
    theirs = times(ref, opts['-cloud'])
    after = float(opts['-after']) if opts['-after'] is not None else \
        min((t for t, _ in mine if t > 0), default=0)
    total, n, worst, rows = 0.0, 0, 0.0, []
    for t, c in mine:
        if t <= after + 1e-9:
            continue
        match = [r for s, r in theirs if abs(s - t) <= 1e-9*max(1, abs(t))]
        if not match:
            continue
        a, b = positions(c), positions(match[0])
        if set(a) != set(b):
            sys.exit('cloudError.py: the ids at t = %g differ (%d and %d'
                     ' points)' % (t, len(a), len(b)))
        s = sum((a[i][d] - b[i][d])**2 for i in a for d in range(3))
        rmse = (s/(3*len(a)))**0.5
        rows.append((t, rmse))
        total += s
        n += 3*len(a)
        worst = max(worst, rmse)
    if not rows:
        sys.exit('cloudError.py: no frame of %s after t = %g is in %s'
                 % (case, after, ref))
    if opts['-steps']:
        with open(opts['-steps'], 'w') as f:
            f.write('# time RMSE [m] against %s\n' % ref)
            for t, e in rows:
                f.write('%.9g %.6e\n' % (t, e))
    print(len(rows), '%.6e' % (total/n)**0.5, '%.6e' % worst)


if __name__ == '__main__':
    main(sys.argv)
