#!/usr/bin/python3
"""bullet2D: muzzle speeds against the ideal gun of Lagrange's problem.

    muzzle.py heavy_solid.dat light_solid.dat ...

Reads bin/tools/plotCsmpm.py's NAME_solid.dat of each run (the bullet's centre and
momentum per written time; its caseInfo next to it gives rhoS, pC, rhoC),
finds where the bullet's base has moved 0.8 (the base at the muzzle,
x = 1; its base is the centre less the centre's initial distance from
x = 0.2) and the bullet's speed there (linear in the centre's position
between the written times), and prints it against two estimates:

  (m + C/3) dv/dt = A (p_mean(x) - p_front(v)),
  p_mean = pC (0.2/(0.2 + x))^1.4,

Lagrange's approximation (the chamber gas, mass C per unit depth, expands
isentropically and uniformly, its velocity rising linearly from the
breech to the base: its kinetic energy C v^2/6), bore A = 0.2, bullet mass
m = rhoS 0.15 x 0.2; p_front is the air's 1 ('vacuum-like', an upper bound)
or the quasi-steady pressure behind the shock a piston at speed v drives
into air at rest (p 1, sound speed 1):
  p_front = 1 + g(g+1)/4 M^2 + g M sqrt(1 + ((g+1)/4)^2 M^2),  M = v.
Integrated with RK4 in steps of 1e-5.  A run that stops before the base
reaches the muzzle is compared at its last written time with the first
estimate over the same travel.  Writes muzzle.dat.
"""
import math, os, sys

g = 1.4


def estimate(rhoS, pC, rhoC, shock, travel=0.8):
    A, L0 = 0.2, 0.2
    m = rhoS*0.15*0.2; C = rhoC*L0*0.2
    def acc(x, v):
        pm = pC*(L0/(L0 + x))**g
        pf = (1 + g*(g + 1)/4*v*v + g*v*math.sqrt(1 + ((g + 1)/4*v)**2)
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


out = ['# run rhoS muzzle_time muzzle_speed lagrange_ambient '
       'lagrange_pistonShock (speeds; times in brackets)']
for path in sys.argv[1:]:
    run = os.path.basename(path).replace('_solid.dat', '')
    info = open(os.path.join(os.path.dirname(path) or '.', 'run', run,
                             'caseInfo')).read().split()
    rhoS, pC, rhoC = float(info[3]), float(info[4]), float(info[5])
    tm, vm, rows = measured(path)
    va, ta = estimate(rhoS, pC, rhoC, False)
    vs, ts = estimate(rhoS, pC, rhoC, True)
    if tm is None:
        d = rows[-1][3]
        vd, td = estimate(rhoS, pC, rhoC, False, d)
        print(f'  {run} (rhoS {rhoS:g}): the base did not reach the muzzle by '
              f't = {rows[-1][0]:g} (speed then {rows[-1][2]:.4f} after a '
              f'travel of {d:.4f}; Lagrange with the ambient 1 in front '
              f'{vd:.3f} (t {td:.3f}) there); '
              f'muzzle estimates {va:.3f} (t {ta:.3f}) / {vs:.3f} (t {ts:.3f})')
        out.append(f'{run} {rhoS:g} nan nan {va:.5f} ({ta:.4f}) {vs:.5f} '
                   f'({ts:.4f}) end: t {rows[-1][0]:g} travel {d:.5f} speed '
                   f'{rows[-1][2]:.5f} lagrange_ambient_same_travel {vd:.5f} '
                   f'({td:.4f})')
        continue
    print(f'  {run} (rhoS {rhoS:g}): muzzle speed {vm:.3f} at t = {tm:.3f}; '
          f'Lagrange with the ambient 1 in front {va:.3f} (t {ta:.3f}), with the '
          f'piston shock in front {vs:.3f} (t {ts:.3f}); '
          f'speed at the end t = {rows[-1][0]:g}: {rows[-1][2]:.3f}')
    out.append(f'{run} {rhoS:g} {tm:.5f} {vm:.5f} {va:.5f} ({ta:.4f}) '
               f'{vs:.5f} ({ts:.4f})')
open('muzzle.dat', 'w').write('\n'.join(out) + '\n')
