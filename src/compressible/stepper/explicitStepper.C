/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "explicitStepper.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace gasSteppers
{
    defineTypeNameAndDebug(explicitStepper, 0);
    addToRunTimeSelectionTable(gasStepper, explicitStepper, dictionary);
}
}


Foam::gasSteppers::explicitStepper::explicitStepper
(
    const dictionary& dict,
    eulerOperator& op
)
:
    gasStepper(dict, op)
{}


Foam::scalar Foam::gasSteppers::explicitStepper::stableDeltaT
(
    const gasState& U,
    scalar CFL,
    scalar& speed,
    word& limiter
) const
{
    limiter = "|u|+c";
    const scalar rate = acousticRate(U, speed);
    return rate > 0 ? CFL/rate : GREAT;
}


bool Foam::gasSteppers::explicitStepper::advance
(
    const gasState& U,
    scalar dt,
    gasState& out,
    report& rep
)
{
    return rungeKutta(U, dt, false, out, rep);
}


// ************************************************************************* //
