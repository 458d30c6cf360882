/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "WENO5.H"
#include "splitLineFluxes.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace gasFluxSchemes
{
    defineTypeNameAndDebug(WENO5, 0);
    addToRunTimeSelectionTable(gasFluxScheme, WENO5, dictionary);
}
}


// The lines' fluxes, in a function cloned for the CPU (cpuClones.H)
makeLineFluxes(WENO5)


// ************************************************************************* //
