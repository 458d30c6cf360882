/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "FLIPTransfer.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(FLIPTransfer, 0);
    addToRunTimeSelectionTable(mpmTransfer, FLIPTransfer, dictionary);
}


Foam::FLIPTransfer::FLIPTransfer
(
    const dictionary& dict,
    const mpmMeshView& mesh
)
:
    mpmTransfer(dict, mesh),
    flipRatio_
    (
        dictionaryChecks::getAsOrDefault<scalar>
        (
            dict, "flipRatio", 0.99, "a number 0 <= flipRatio <= 1"
        )
    )
{
    if (!(flipRatio_ >= 0 && flipRatio_ <= 1))
    {
        dictionaryChecks::badEntry(dict, "flipRatio", Foam::name(flipRatio_),
            "a number 0 <= flipRatio <= 1");
    }
}


// (2.14) FLIP increment, blended with PIC
void Foam::FLIPTransfer::g2p
(
    const kernelWeights& kw,
    const mpmGrid& grid,
    mpmParticles& P
) const
{
    const scalar r = flipRatio_;
    const label nP = P.size();
    for (label p = 0; p < nP; ++p)
    {
        vector vPic(Zero), dv(Zero);
        for (label k = kw.start[p]; k < kw.start[p + 1]; ++k)
        {
            const label i = kw.vertex[k];
            vPic += kw.w[k]*grid.newVelocity[i];
            dv += kw.w[k]*(grid.newVelocity[i] - grid.velocity[i]);
        }
        P.v[p] = r*(P.v[p] + dv) + (1 - r)*vPic;
    }
}


// ************************************************************************* //
