"""Particle neighbours with numpy only (the project's Python tools need
numpy and matplotlib, nothing else: etc/install-dependencies).

    pairs(x, r)          the index pairs (i < j) of the points closer than
                         or as close as r (strict=True: closer than r): the points hashed into cells of
                         size r, each cell's points tested against its own
                         and half of its neighbour cells' (3^d - 1)/2
    clusters(x, r)       labels 0..k-1 of the connected components of the
                         graph those pairs make (union-find: roots hooked
                         to the smaller root, paths halved, until every
                         pair shares its root)
    hasNeighbour(x, r)   True where another point lies within r (strict:
                         closer than r)

x is an (n, d) array, d = 2 or 3.  Used by bin/tools/plotCsmpm.py
(fragments), tutorials/mpm/columnCollapse2D/plotCollapse.py and
tutorials/mpm/slopeFailure3D/plotSlope.py (isolated particles).
"""
import itertools
import numpy as np


def pairs(x, r, strict=False):
    x = np.asarray(x, dtype=float)
    n, d = x.shape
    if n < 2:
        return np.zeros((0, 2), dtype=np.int64)
    c = np.floor((x - x.min(axis=0))/r).astype(np.int64)
    span = c.max(axis=0) + 3
    stride = np.cumprod(np.concatenate(([1], span[:-1])))
    key = (c + 1) @ stride
    order = np.argsort(key, kind='stable')
    sk = key[order]
    cells, start, count = np.unique(sk, return_index=True, return_counts=True)
    out = []
    r2 = r*r
    for off in itertools.product((-1, 0, 1), repeat=d):
        off = np.array(off)
        # half of the offsets (lexicographically >= 0) visits every pair
        # of cells once; the own cell (all zero) keeps i < j below
        nz = off[off != 0]
        if len(nz) and nz[0] < 0:
            continue
        nk = key + off @ stride
        pos = np.searchsorted(cells, nk)
        pos = np.minimum(pos, len(cells) - 1)
        hit = cells[pos] == nk
        i = np.nonzero(hit)[0]
        if len(i) == 0:
            continue
        s = start[pos[i]]
        m = count[pos[i]]
        ii = np.repeat(i, m)
        first = np.repeat(np.cumsum(m) - m, m)
        jj = order[np.repeat(s, m) + np.arange(m.sum()) - first]
        if not nz.size:
            keep = ii < jj
            ii, jj = ii[keep], jj[keep]
        dx = x[ii] - x[jj]
        dd = (dx*dx).sum(axis=1)
        close = dd < r2 if strict else dd <= r2
        out.append(np.stack((np.minimum(ii, jj)[close],
                             np.maximum(ii, jj)[close]), axis=1))
    if not out:
        return np.zeros((0, 2), dtype=np.int64)
    return np.concatenate(out)


def clusters(x, r):
    n = len(x)
    p = pairs(x, r)
    lab = np.arange(n)
    i, j = p[:, 0], p[:, 1]
    while True:
        while True:
            nxt = lab[lab]
            if np.array_equal(nxt, lab):
                break
            lab = nxt
        a, b = lab[i], lab[j]
        diff = a != b
        if not diff.any():
            break
        lo = np.minimum(a[diff], b[diff])
        hi = np.maximum(a[diff], b[diff])
        np.minimum.at(lab, hi, lo)
    return np.unique(lab, return_inverse=True)[1]


def hasNeighbour(x, r, strict=False):
    ok = np.zeros(len(x), dtype=bool)
    p = pairs(x, r, strict)
    ok[p[:, 0]] = True
    ok[p[:, 1]] = True
    return ok
