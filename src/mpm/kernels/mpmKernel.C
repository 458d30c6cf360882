/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "mpmKernel.H"
#include "dictionaryChecks.H"

#include <algorithm>

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
    return *std::min_element(h.begin(), h.end());
}


// ************************************************************************* //
