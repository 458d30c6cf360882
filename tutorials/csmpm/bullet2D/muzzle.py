#!/usr/bin/python3
"""bullet2D: muzzle speeds against the ideal gun of Lagrange's problem.

    muzzle.py heavy_solid.dat light_solid.dat ...

Reads bin/tools/plotCsmpm.py's NAME_solid.dat of each run (the bullet's centre and
momentum per written time; its caseInfo next to it gives rhoS, pC, rhoC
and the air's pressure pA),
finds where the bullet's base has moved 0.8 (the base at the muzzle,
x = 1; its base is the centre less the centre's initial distance from
x = 0.2) and the bullet's speed there (linear in the centre's position
between the written times), and prints it against two estimates:

  (m + C/3) dv/dt = A (p_mean(x) - p_front(v)),
  p_mean = pC (0.2/(0.2 + x))^1.4,

Lagrange's approximation (the chamber gas, mass C per unit depth, expands
isentropically and uniformly, its velocity rising linearly from the
breech to the base: its kinetic energy C v^2/6), bore A = 0.2, bullet mass
m = rhoS 0.15 x 0.2; p_front is the air's pA (the air at rest: an upper
bound) or the quasi-steady pressure behind the shock a piston at speed v
drives into air at rest (pressure pA, sound speed 1 at any pA: the air's
temperature does not change with it):
  p_front = pA (1 + g(g+1)/4 M^2 + g M sqrt(1 + ((g+1)/4)^2 M^2)),  M = v.
Integrated with RK4 in steps of 1e-5.  A run that stops before the base
reaches the muzzle is compared at its last written time with the first
estimate over the same travel.

The blast: the largest pressure over the written times in the cell at
45 degrees off the axis, 0.5 from where the bullet leaves into the open
air (x = 1, or the silencer's end x = 1.4): (exit + 0.35, 0.85), as
(p_max - pA)/pA.  Writes muzzle.dat.
"""
import math, os, re, sys

g = 1.4


def estimate(rhoS, pC, rhoC, pA, shock, travel=0.8):
    A, L0 = 0.2, 0.2
    m = rhoS*0.15*0.2; C = rhoC*L0*0.2
    def acc(x, v):
        pm = pC*(L0/(L0 + x))**g
        pf = pA*((1 + g*(g + 1)/4*v*v + g*v*math.sqrt(1 + ((g + 1)/4*v)**2))
                 if shock and v > 0 else 1.0)
        return A*(pm - pf)/(m + C/3)
    x = v = t = 0.0; h = 1e-5
    while x < travel:
        k1 = (v, acc(x, v))
        k2 = (v + 0.5*h*k1[1], acc(x + 0.5*h*k1[0], v + 0.5*h*k1[1]))
        k3 = (v + 0.5*h*k2[1], acc(x + 0.5*h*k2[0], v + 0.5*h*k2[1]))
        k4 = (v + h*k3[1], acc(x + h*k3[0], v + h*k3[1]))
        x += h*(k1[0] + 2*k2[0] + 2*k3[0] + k4[0])/6
        v += h*(k1[1] + 2*k2[1] + 2*k3[1] + k4[1])/6
        t += h
    return v, t


def measured(path):
    rows = []
    for line in open(path):
        s = line.split()
        if s and s[0] not in ('#', 'frag'):
            t, M, px, cx = float(s[0]), float(s[2]), float(s[3]), float(s[5])
            rows.append((t, cx, px/M))
    c0 = rows[0][1]
    rows = [(t, cx, v, cx - c0) for t, cx, v in rows]
    for (t0, c_0, v0, _), (t1, c_1, v1, _) in zip(rows, rows[1:]):
        b0, b1 = c_0 - (c0 - 0.2), c_1 - (c0 - 0.2)
        if b0 < 1 <= b1:
            f = (1 - b0)/(b1 - b0)
            return t0 + f*(t1 - t0), v0 + f*(v1 - v0), rows
    return None, None, rows


def internalField(path):
    s = open(path).read()
    i, e = s.index('internalField'), s.index('boundaryField')
    return s[i:e]


def blast(case, exitX, pA):
    """The peak overpressure (p_max - pA)/pA at the probe and its time"""
    cells = re.findall(r'\(([-\d.e+]+) ([-\d.e+]+) [-\d.e+]+\)',
                       internalField(os.path.join(case, '0', 'C')))
    px, py = exitX + 0.35, 0.85
    c = min(range(len(cells)), key=lambda k: (float(cells[k][0]) - px)**2
            + (float(cells[k][1]) - py)**2)
    peak, tPeak = pA, None
    for t in os.listdir(case):
        if not re.fullmatch(r'[0-9.e+-]+', t) or float(t) == 0 \
                or not os.path.isfile(os.path.join(case, t, 'p')):
            continue
        f = internalField(os.path.join(case, t, 'p'))
        m = re.search(r'List<scalar>\s*\d+\s*\(', f)
        p = float(f[m.end():].split()[c]) if m else \
            float(re.search(r'uniform\s+([^;]+);', f).group(1))
        if p > peak:
            peak, tPeak = p, float(t)
    return (peak - pA)/pA, tPeak


out = ['# run rhoS muzzle_time muzzle_speed lagrange_ambient '
       'lagrange_pistonShock (speeds; times in brackets) '
       'blast_overpressure (time)']
for path in sys.argv[1:]:
    run = os.path.basename(path).replace('_solid.dat', '')
    info = open(os.path.join(os.path.dirname(path) or '.', 'run', run,
                             'caseInfo')).read().split()
    rhoS, pC, rhoC = float(info[3]), float(info[4]), float(info[5])
    pA = float(info[6]) if len(info) > 6 else 1.0
    silencer = len(info) > 7 and info[7] == '1'
    b, tb = blast(os.path.join(os.path.dirname(path) or '.', 'run', run),
                  1.4 if silencer else 1.0, pA)
    blastText = (f'blast at 0.5 from the exit {b:.3f} pA (t {tb:g})'
                 if tb is not None else 'no blast at the probe yet')
    tm, vm, rows = measured(path)
    va, ta = estimate(rhoS, pC, rhoC, pA, False)
    vs, ts = estimate(rhoS, pC, rhoC, pA, True)
    if tm is None:
        d = rows[-1][3]
        vd, td = estimate(rhoS, pC, rhoC, pA, False, d)
        print(f'  {run} (rhoS {rhoS:g}): the base did not reach the muzzle by '
              f't = {rows[-1][0]:g} (speed then {rows[-1][2]:.4f} after a '
              f'travel of {d:.4f}; Lagrange with the air at rest in front '
              f'{vd:.3f} (t {td:.3f}) there); '
              f'muzzle estimates {va:.3f} (t {ta:.3f}) / {vs:.3f} (t {ts:.3f}); '
              f'{blastText}')
        out.append(f'{run} {rhoS:g} nan nan {va:.5f} ({ta:.4f}) {vs:.5f} '
                   f'({ts:.4f}) end: t {rows[-1][0]:g} travel {d:.5f} speed '
                   f'{rows[-1][2]:.5f} lagrange_ambient_same_travel {vd:.5f} '
                   f'({td:.4f}) blast {b:.5f} ({tb})')
        continue
    print(f'  {run} (rhoS {rhoS:g}): muzzle speed {vm:.3f} at t = {tm:.3f}; '
          f'Lagrange with the air (p {pA:g}) at rest in front {va:.3f} (t {ta:.3f}), with the '
          f'piston shock in front {vs:.3f} (t {ts:.3f}); '
          f'speed at the end t = {rows[-1][0]:g}: {rows[-1][2]:.3f}; {blastText}')
    out.append(f'{run} {rhoS:g} {tm:.5f} {vm:.5f} {va:.5f} ({ta:.4f}) '
               f'{vs:.5f} ({ts:.4f}) {b:.5f} ({tb})')
open('muzzle.dat', 'w').write('\n'.join(out) + '\n')
