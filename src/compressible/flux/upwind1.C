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


void Foam::gasFluxSchemes::upwind1::lineFluxes
(
    const gasLine& line,
    double* F[5]
) const
{
    physicalFluxes(line);
    if (characteristic_ && !line.advective)
    {
        characteristicLineFluxes<upwind1Reconstruction>
        (
            line, f_, lambda_, un_, c_, F
        );
    }
    else
    {
        splitLineFluxes<upwind1Reconstruction>(line, f_, lambda_, F);
    }
}


// ************************************************************************* //
