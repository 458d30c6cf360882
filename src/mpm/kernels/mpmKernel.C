/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "mpmKernel.H"
#include "dictionaryChecks.H"

namespace Foam
{
    defineTypeNameAndDebug(mpmKernel, 0);
    defineRunTimeSelectionTable(mpmKernel, dictionary);
}


Foam::mpmKernel::mpmKernel(const dictionary&, const mpmMeshView& mesh)
:
    mesh_(mesh)
{}


Foam::autoPtr<Foam::mpmKernel> Foam::mpmKernel::New
(
    const dictionary& dict,
    const mpmMeshView& mesh
)
{
    word selected;
    const auto cstr = dictionaryChecks::selectConstructor
    (
        dict, "kernel", *dictionaryConstructorTablePtr_, selected
    );
    Info<< "MPM kernel: " << selected << endl;
    return cstr(dict, mesh);
}


Foam::scalar Foam::mpmKernel::stepLength() const
{
    const scalarList& h = mesh_.vertexSize();
    scalar m = GREAT;
    forAll(h, v) m = min(m, h[v]);
    return m;
}


// ************************************************************************* //
