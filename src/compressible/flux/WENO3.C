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


void Foam::gasFluxSchemes::WENO3::lineFluxes
(
    const gasLine& line,
    double* F[5]
) const
{
    physicalFluxes(line);
    if (characteristic_ && !line.advective)
    {
        characteristicLineFluxes<WENO3Reconstruction>
        (
            line, f_, lambda_, un_, c_, F
        );
    }
    else
    {
        splitLineFluxes<WENO3Reconstruction>(line, f_, lambda_, F);
    }
}


// ************************************************************************* //
