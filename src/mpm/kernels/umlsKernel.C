/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "umlsKernel.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(umlsKernel, 0);
    addToRunTimeSelectionTable(mpmKernel, umlsKernel, dictionary);
}


Foam::umlsKernel::umlsKernel
(
    const dictionary& dict,
    const mpmMeshView& mesh
)
:
    mlsRingKernel(dict, mesh, true)
{}


// ************************************************************************* //
