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
    // (a rank whose gas is at rest but for round-off, e.g. denormal
    // velocities ahead of a shock, would overflow CFL/rate)
    return rate > CFL/GREAT ? CFL/rate : GREAT;
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
