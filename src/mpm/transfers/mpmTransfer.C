/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "mpmTransfer.H"
#include "dictionaryChecks.H"

namespace Foam
{
    defineTypeNameAndDebug(mpmTransfer, 0);
    defineRunTimeSelectionTable(mpmTransfer, dictionary);
}


Foam::mpmTransfer::mpmTransfer(const dictionary&, const mpmMeshView& mesh)
:
    mesh_(mesh)
{}


Foam::autoPtr<Foam::mpmTransfer> Foam::mpmTransfer::New
(
    const dictionary& dict,
    const mpmMeshView& mesh
)
{
    word selected;
    const auto cstr = dictionaryChecks::selectConstructor
    (
        dict, "transfer", *dictionaryConstructorTablePtr_, selected
    );
    Info<< "MPM transfer: " << selected << endl;
    return cstr(dict, mesh);
}


void Foam::mpmTransfer::p2g
(
    const mpmParticles& P,
    const kernelWeights& kw,
    mpmGrid& grid
) const
{
    const label nP = P.size();
    for (label p = 0; p < nP; ++p)
    {
        const scalar mp = P.m[p];
        const vector mv = mp*P.v[p];
        for (label k = kw.start[p]; k < kw.start[p + 1]; ++k)
        {
            const label i = kw.vertex[k];
            const scalar w = kw.w[k];
            grid.mass[i] += w*mp;
            grid.velocity[i] += w*mv;
        }
    }
}


// ************************************************************************* //
