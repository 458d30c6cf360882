/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "APICTransfer.H"
#include "addToRunTimeSelectionTable.H"
#include "dictionaryChecks.H"

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
{
    if (dict.getOrDefault<word>("kernel", word::null) == "linear")
    {
        dictionaryChecks::badEntry
        (
            dict, "transfer", "APIC (with kernel linear)",
            "PIC or FLIP with kernel linear; APIC needs an invertible second"
            " moment D_p of the weights, which the linear kernel lacks at"
            " vertices (use kernel umls or mlsRing for APIC)"
        );
    }
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
        tensor D(Q);
        for (label k = kw.start[p]; k < kw.start[p + 1]; ++k)
        {
            const vector d = mesh_.delta(xv[kw.vertex[k]], xp);
            D += kw.w[k]*(d*d);
        }
        const tensor C = P.B[p] & (inv(D) - Q);

        const scalar mp = P.m[p];
        for (label k = kw.start[p]; k < kw.start[p + 1]; ++k)
        {
            const label i = kw.vertex[k];
            const scalar wm = kw.w[k]*mp;
            grid.mass[i] += wm;
            grid.velocity[i] +=
                wm*(P.v[p] + (C & mesh_.delta(xv[i], xp)));
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
        vector v(Zero);
        tensor B(Zero);
        for (label k = kw.start[p]; k < kw.start[p + 1]; ++k)
        {
            const label i = kw.vertex[k];
            const vector wv = kw.w[k]*grid.newVelocity[i];
            v += wv;
            B += wv*mesh_.delta(xv[i], xp);
        }
        P.v[p] = v;
        P.B[p] = B;
    }
}


// ************************************************************************* //
