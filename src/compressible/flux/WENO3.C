/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "WENO3.H"
#include "splitLineFluxes.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace gasFluxSchemes
{
    defineTypeNameAndDebug(WENO3, 0);
    addToRunTimeSelectionTable(gasFluxScheme, WENO3, dictionary);
}
}


// The lines' fluxes, in a function cloned for the CPU (cpuClones.H)
makeLineFluxes(WENO3)


// ************************************************************************* //
