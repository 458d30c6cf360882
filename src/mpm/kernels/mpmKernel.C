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
    OStringStream allowed;
    allowed << "one of " << dictionaryConstructorTablePtr_->sortedToc();
    const word name
    (
        dictionaryChecks::getAs<word>(dict, "kernel", allowed.str())
    );
    auto cstrIter = dictionaryConstructorTablePtr_->cfind(name);
    if (!cstrIter.found())
    {
        dictionaryChecks::badEntry(dict, "kernel", name, allowed.str());
    }
    Info<< "MPM kernel: " << name << endl;
    return cstrIter()(dict, mesh);
}


// ************************************************************************* //
