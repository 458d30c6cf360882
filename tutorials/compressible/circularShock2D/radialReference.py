#!/usr/bin/python3
"""circularShock2D: the radially symmetric reference solution of the
circular shock (a cylindrical Riemann problem; gamma 1.4):

    r < 0.2: rho 1, p 1;  r > 0.2: rho 0.125, p 0.1;  u 0

solved as the 1D Euler equations in r with the cylindrical geometry, in the
finite-volume form with exact annulus areas and volumes (per radian),

    d/dt (V_i q_i) + A_{i+1/2} F_{i+1/2} - A_{i-1/2} F_{i-1/2} = V_i S_i,
    A = r_face, V_i = r_i dr, S = (0, p/r_i, 0),

q = (rho, rho u, rho E).  The geometric source p/r_i balances the pressure
part of the momentum fluxes exactly (a uniform state at rest stays so), and
A = 0 at r = 0 makes the axis a closed end (mirror ghost cells for the
reconstruction).  Second order: MUSCL reconstruction of rho, u, p with the
monotonized-central limiter, HLLC fluxes, SSP Runge-Kutta 3 at CFL 0.4.
The outer end (r = 0.75, beyond the box's corner distance 0.707) has
zero-gradient ghosts; no wave reaches it by t = 0.15.  The discontinuity
r = 0.2 is a cell face when 0.2 N/0.75 is a whole number (N = 6000: face
1600).

Usage:
    radialReference.py [-cells N] [-time T] [-out FILE]
        writes FILE (default radialReference.dat): r rho u p at the N cell
        centres at time T (defaults N = 6000, T = 0.15); prints the steps
        and the total mass change (round-off: the scheme is conservative)
"""

import argparse
import time as clock

import numpy as np

GAMMA = 1.4
R_MAX = 0.75
R0 = 0.2
INSIDE = (1.0, 0.0, 1.0)
OUTSIDE = (0.125, 0.0, 0.1)


def primitive(q):
    rho = q[0]
    u = q[1]/rho
    p = (GAMMA - 1)*(q[2] - 0.5*rho*u*u)
    return rho, u, p


def limitedSlope(a, b):
    """Monotonized central: minmod(2a, 2b, (a + b)/2)"""
    s = np.sign(a)
    m = np.minimum(np.minimum(2*np.abs(a), 2*np.abs(b)), 0.5*np.abs(a + b))
    return np.where(a*b > 0, s*m, 0.0)


def hllc(rl, ul, pl, rr, ur, pr):
    """HLLC flux (Toro 10.4) with Davis/Einfeldt-type wave speed bounds"""
    cl = np.sqrt(GAMMA*pl/rl)
    cr = np.sqrt(GAMMA*pr/rr)
    sl = np.minimum(ul - cl, ur - cr)
    sr = np.maximum(ul + cl, ur + cr)
    el = pl/(GAMMA - 1) + 0.5*rl*ul*ul
    er = pr/(GAMMA - 1) + 0.5*rr*ur*ur
    ss = (pr - pl + rl*ul*(sl - ul) - rr*ur*(sr - ur)) \
        / (rl*(sl - ul) - rr*(sr - ur))

    fl = np.array([rl*ul, rl*ul*ul + pl, (el + pl)*ul])
    fr = np.array([rr*ur, rr*ur*ur + pr, (er + pr)*ur])
    ql = np.array([rl, rl*ul, el])
    qr = np.array([rr, rr*ur, er])

    def star(r, u, p, e, s):
        k = r*(s - u)/(s - ss)
        return np.array([k, k*ss, k*(e/r + (ss - u)*(ss + p/(r*(s - u))))])

    fsl = fl + sl*(star(rl, ul, pl, el, sl) - ql)
    fsr = fr + sr*(star(rr, ur, pr, er, sr) - qr)
    return np.where(sl >= 0, fl,
                    np.where(ss >= 0, fsl, np.where(sr > 0, fsr, fr)))


class Radial:
    def __init__(self, n):
        self.n = n
        self.dr = R_MAX/n
        self.r = (np.arange(n) + 0.5)*self.dr
        self.faces = np.arange(n + 1)*self.dr
        self.vol = self.r*self.dr

    def initial(self):
        """Cell averages of the initial state (exact area fractions)"""
        lo, hi = self.faces[:-1], self.faces[1:]
        frac = np.clip((R0**2 - lo**2)/(hi**2 - lo**2), 0, 1)
        rho = frac*INSIDE[0] + (1 - frac)*OUTSIDE[0]
        p = frac*INSIDE[2] + (1 - frac)*OUTSIDE[2]
        return np.array([rho, np.zeros(self.n), p/(GAMMA - 1)])

    def rhs(self, q):
        rho, u, p = primitive(q)
        # two ghosts each end: mirror at the axis, zero gradient outside
        def pad(v, odd):
            s = -1.0 if odd else 1.0
            return np.concatenate(([s*v[1], s*v[0]], v, [v[-1], v[-1]]))
        w = [pad(rho, False), pad(u, True), pad(p, False)]
        left, right = [], []
        for v in w:
            d = limitedSlope(v[1:-1] - v[:-2], v[2:] - v[1:-1])
            # faces 0..n: left state from cell j - 1, right from cell j
            left.append((v[1:-1] + 0.5*d)[:-1])
            right.append((v[1:-1] - 0.5*d)[1:])
        F = hllc(left[0], left[1], left[2], right[0], right[1], right[2])
        AF = F*self.faces
        dq = -(AF[:, 1:] - AF[:, :-1])/self.vol
        dq[1] += p/self.r
        return dq

    def maxSpeed(self, q):
        rho, u, p = primitive(q)
        return np.max(np.abs(u) + np.sqrt(GAMMA*p/rho))

    def solve(self, tEnd, cfl=0.4):
        q = self.initial()
        mass0 = np.sum(q[0]*self.vol)
        t = 0.0
        steps = 0
        while t < tEnd*(1 - 1e-14):
            dt = min(cfl*self.dr/self.maxSpeed(q), tEnd - t)
            q1 = q + dt*self.rhs(q)
            q2 = 0.75*q + 0.25*(q1 + dt*self.rhs(q1))
            q = q/3 + 2.0/3*(q2 + dt*self.rhs(q2))
            t += dt
            steps += 1
        mass = np.sum(q[0]*self.vol)
        return q, steps, (mass - mass0)/mass0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("-cells", type=int, default=6000)
    ap.add_argument("-time", type=float, default=0.15)
    ap.add_argument("-out", default="radialReference.dat")
    a = ap.parse_args()

    start = clock.time()
    solver = Radial(a.cells)
    q, steps, dm = solver.solve(a.time)
    rho, u, p = primitive(q)
    np.savetxt(a.out, np.column_stack((solver.r, rho, u, p)), fmt="%.10g",
               header="circularShock2D radial reference: %d cells on r in"
               " [0, %g], t = %g, MUSCL (MC) + HLLC + SSP-RK3, CFL 0.4\n"
               "r rho u p" % (a.cells, R_MAX, a.time))
    print("radialReference: %d cells, t = %g, %d steps, mass change %.1e,"
          " %.1f s -> %s" % (a.cells, a.time, steps, dm,
                             clock.time() - start, a.out))


if __name__ == "__main__":
    main()
