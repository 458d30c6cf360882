/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "APICTransfer.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(APICTransfer, 0);
    addToRunTimeSelectionTable(mpmTransfer, APICTransfer, dictionary);
}


Foam::APICTransfer::APICTransfer
(
    const dictionary& dict,
    const mpmMeshView& mesh
)
:
    mpmTransfer(dict, mesh)
{}


// The offset x_c - x_p of the weights' centre x_c = sum_i w_ip x_i from the
// particle: zero to round-off for a kernel that reproduces linear functions
// (the fold of bspline2 at the lattice's ends, umls, mlsRing); not where
// bspline2 drops the nodes of a hole and renormalises (a wall inside the
// lattice's box: a bore, a step).  There the moments about x_p would carry
// the particle's own velocity into B (sum_i w_ip (x_i - x_p) != 0), P2G
// would give it back as extra momentum m_p C (x_c - x_p), and a body
// sliding along such a wall would gain momentum and kinetic energy every
// step (the bullet of csmpm/bullet2D: 40 % more kinetic energy than the
// gas gave it by t = 0.3).  About x_c, P2G keeps the particle's momentum
// exactly and a uniform grid velocity gives B = 0
Foam::vector Foam::APICTransfer::centreOffset
(
    const kernelWeights& kw,
    const label p,
    const List<vector>& xv,
    const vector& xp
) const
{
    vector c(Zero);
    for (label k = kw.start[p]; k < kw.start[p + 1]; ++k)
    {
        c += kw.w[k]*mesh_.delta(xv[kw.vertex[k]], xp);
    }
    return c;
}


// (2.35) APIC P2G
void Foam::APICTransfer::p2g
(
    const mpmParticles& P,
    const kernelWeights& kw,
    mpmGrid& grid
) const
{
    const List<vector>& xv = mesh_.vertices();
    // D lives in the solution axes; the unit block on the other axes makes
    // it invertible and is removed again
    const tensor Q = mesh_.offAxes();
    const label nP = P.size();
    for (label p = 0; p < nP; ++p)
    {
        const vector& xp = P.x[p];
        // The moments about the weights' centre x_c = sum_i w_ip x_i
        // (x_p itself where the kernel reproduces linear functions)
        const vector c = centreOffset(kw, p, xv, xp);
        tensor D(Q);
        for (label k = kw.start[p]; k < kw.start[p + 1]; ++k)
        {
            const vector d = mesh_.delta(xv[kw.vertex[k]], xp) - c;
            D += kw.w[k]*(d*d);
        }
        if (floored_)
        {
            // The kernel's floor (bspline2 at the lattice's ends)
            for (direction a = 0; a < 3; ++a)
            {
                const label aa = 4*a;
                if (D[aa] < momentFloor_[a]) D[aa] = momentFloor_[a];
            }
        }
        const tensor C = P.B[p] & (inv(D) - Q);

        const scalar mp = P.m[p];
        for (label k = kw.start[p]; k < kw.start[p + 1]; ++k)
        {
            const label i = kw.vertex[k];
            const scalar wm = kw.w[k]*mp;
            grid.mass[i] += wm;
            grid.velocity[i] +=
                wm*(P.v[p] + (C & (mesh_.delta(xv[i], xp) - c)));
        }
    }
}


// (2.36) APIC G2P
void Foam::APICTransfer::g2p
(
    const kernelWeights& kw,
    const mpmGrid& grid,
    mpmParticles& P
) const
{
    const List<vector>& xv = mesh_.vertices();
    const label nP = P.size();
    for (label p = 0; p < nP; ++p)
    {
        const vector& xp = P.x[p];
        const vector c = centreOffset(kw, p, xv, xp);
        vector v(Zero);
        tensor B(Zero);
        for (label k = kw.start[p]; k < kw.start[p + 1]; ++k)
        {
            const label i = kw.vertex[k];
            const vector wv = kw.w[k]*grid.newVelocity[i];
            v += wv;
            B += wv*(mesh_.delta(xv[i], xp) - c);
        }
        P.v[p] = v;
        P.B[p] = B;
    }
}


// ************************************************************************* //
