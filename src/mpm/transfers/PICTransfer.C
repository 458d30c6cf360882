/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "PICTransfer.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(PICTransfer, 0);
    addToRunTimeSelectionTable(mpmTransfer, PICTransfer, dictionary);
}


Foam::PICTransfer::PICTransfer(const dictionary& dict, const mpmMeshView& mesh)
:
    mpmTransfer(dict, mesh)
{}


void Foam::PICTransfer::g2p
(
    const kernelWeights& kw,
    const mpmGrid& grid,
    mpmParticles& P
) const
{
    const label nP = P.size();
    for (label p = 0; p < nP; ++p)
    {
        vector v(Zero);
        for (label k = kw.start[p]; k < kw.start[p + 1]; ++k)
        {
            v += kw.w[k]*grid.newVelocity[kw.vertex[k]];
        }
        P.v[p] = v;
    }
}


// ************************************************************************* //
