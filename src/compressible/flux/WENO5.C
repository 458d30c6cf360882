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


void Foam::gasFluxSchemes::WENO5::lineFluxes
(
    const gasLine& line,
    double* F[5]
) const
{
    physicalFluxes(line);
    if (characteristic_ && !line.advective)
    {
        characteristicLineFluxes<WENO5Reconstruction>
        (
            line, f_, lambda_, un_, c_, F
        );
    }
    else
    {
        splitLineFluxes<WENO5Reconstruction>(line, f_, lambda_, F);
    }
}


// ************************************************************************* //
