#!/usr/bin/python3
"""Checks of the 1D CSMPM runs against exact gas dynamics.

  check.py shock CASE TIME U XW VW   a shock driven into gas at rest
      (rho 1, p 1, gamma 1.4) by a rigid wall (a piston) moving at VW = -U
      from XW at t = 0, or gas moving at +U onto a wall at rest (VW = 0)
      at XW: prints the
      exact post-shock pressure and shock position and the numerical ones
      (shock: the first cell from the left above the mean of the two
      pressures; plateau: mean pressure from 5 cells behind the shock to 5
      cells before the wall), as 'xerr <cells> perr <relative>'
  check.py slab CASE TIME DP RHOS LEN   mean slab velocity (particles)
      against DP/(RHOS LEN) TIME: prints 'aerr <relative>'
  check.py rarefaction CASE TIME U XB   a piston (the slab's back face at
      XB at t = 0) moving away at -U from gas at rest (rho 1, p 1) on its
      right: the exact simple wave behind it, p = (1 - (gamma - 1)/2
      U/c)^(2 gamma/(gamma - 1)), u = -U between the piston and the wave's
      tail at XB + (c - (gamma + 1)/2 U) t; the numerical plateau (mean
      from 5 cells behind the piston to 5 cells before the tail): prints
      'perr <relative> uerr <relative>'
"""
import math, re, sys

def internal(path):
    s = open(path).read()
    s = s[s.index('internalField'):]
    m = re.search(r'\d+\s*\((.*?)\)\s*;', s, re.S)
    return m.group(1).split()

def particles(case, t, name):
    s = open(f'{case}/{t}/lagrangian/mpmCloud/{name}').read()
    s = s[s.index('(') + 1:]
    return s

g = 1.4
mode = sys.argv[1]
if mode == 'shock':
    case, t, U, xw = sys.argv[2], sys.argv[3], float(sys.argv[4]), float(sys.argv[5])
    rho = p = 1.0
    A = 2/((g + 1)*rho); B = (g - 1)/(g + 1)*p
    lo, hi = p, 1000*p
    for _ in range(200):
        mid = 0.5*(lo + hi)
        if (mid - p)*math.sqrt(A/(mid + B)) < U: lo = mid
        else: hi = mid
    ps = 0.5*(lo + hi); r = (g - 1)/(g + 1)
    rhos = rho*(ps/p + r)/(r*ps/p + 1)
    S = rho*U/(rhos - rho)          # shock speed relative to the wall
    P = [float(v) for v in internal(f'{case}/{t}/p')]
    n = len(P)
    L = float(open(f'{case}/caseInfo').read().split()[0])
    dx = L/n
    tt = float(t)
    vw = float(sys.argv[6])
    xwall = xw + vw*tt
    xs = xwall - S*tt
    mid = 0.5*(p + ps)
    k = next(i for i in range(n) if P[i] > mid)
    xnum = k*dx
    # plateau between the shock and the wall (the wall's own position)
    i0, i1 = k + 5, int(xwall/dx) - 5
    plat = sum(P[i0:i1])/max(1, i1 - i0)
    print(f'exact p* {ps:.6f} shock at {xs:.5f}; numerical {xnum:.5f}, plateau {plat:.6f} (cells {i0}-{i1})')
    print(f'xerr {abs(xnum - xs)/dx:.3f} perr {abs(plat - ps)/ps:.3e}')
elif mode == 'slab':
    case, t, dp, rhoS, Ls = sys.argv[2], sys.argv[3], float(sys.argv[4]), float(sys.argv[5]), float(sys.argv[6])
    Us = re.findall(r'\(\s*([-\d.e+]+)\s+[-\d.e+]+\s+[-\d.e+]+\s*\)', particles(case, t, 'U'))
    ms = [float(v) for v in particles(case, t, 'mass').split(')')[0].split()]
    v = sum(m*float(u) for m, u in zip(ms, Us))/sum(ms)
    ex = dp/(rhoS*Ls)*float(t)
    print(f'slab velocity {v:.6e}, exact {ex:.6e}')
    print(f'aerr {abs(v - ex)/abs(ex):.3e}')
elif mode == 'rarefaction':
    case, t, U, xb = sys.argv[2], sys.argv[3], float(sys.argv[4]), float(sys.argv[5])
    c = math.sqrt(g)
    ps = (1 - (g - 1)/2*U/c)**(2*g/(g - 1))
    P = [float(v) for v in internal(f'{case}/{t}/p')]
    u = [float(v) for v in re.findall(r'\(\s*([-\d.e+]+)\s', ' '.join(internal(f'{case}/{t}/U')))]
    n = len(P)
    L = float(open(f'{case}/caseInfo').read().split()[0])
    dx = L/n
    tt = float(t)
    i0 = int((xb - U*tt)/dx) + 5
    i1 = int((xb + (c - (g + 1)/2*U)*tt)/dx) - 5
    plat = sum(P[i0:i1])/max(1, i1 - i0)
    uplat = sum(u[i0:i1])/max(1, i1 - i0)
    print(f'exact p {ps:.6f} u {-U}; numerical plateau p {plat:.6f} u {uplat:.6f} (cells {i0}-{i1})')
    print(f'perr {abs(plat - ps)/ps:.3e} uerr {abs(uplat + U)/U:.3e}')
