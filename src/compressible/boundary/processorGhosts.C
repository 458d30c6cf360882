/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "processorGhosts.H"
#include "error.H"

namespace Foam
{
namespace gasBoundaries
{
    defineTypeNameAndDebug(processorGhosts, 0);
}
}


Foam::scalar Foam::gasBoundaries::processorGhosts::faceVelocity
(
    const double qEdge[5],
    label normal
) const
{
    FatalErrorInFunction
        << "Processor patch " << patchName_ << ": no boundary velocity"
       
        << exit(FatalError);
    return 0;
}


// ************************************************************************* //
