/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "upwind1.H"
#include "splitLineFluxes.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace gasFluxSchemes
{
    defineTypeNameAndDebug(upwind1, 0);
    addToRunTimeSelectionTable(gasFluxScheme, upwind1, dictionary);
}
}


// The lines' fluxes, in a function cloned for the CPU (cpuClones.H)
makeLineFluxes(upwind1)


// ************************************************************************* //
