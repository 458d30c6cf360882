/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "stateInlet.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace gasBoundaries
{
    defineTypeNameAndDebug(stateInlet, 0);
    addToRunTimeSelectionTable(gasBoundary, stateInlet, dictionary);
}
}

Foam::gasBoundaries::stateInlet::stateInlet
(
    const word& patchName,
    const dictionary& dict,
    const idealGas& gas,
    const primitiveState& initial
)
:
    gasBoundary(patchName, gas),
    state_(readState(dict, initial)),
    supersonic_(false)
{
    conserved(state_, q_);
    const scalar c = gas.soundSpeed(state_.rho, state_.p);
    supersonic_ = mag(state_.U) >= c;
    Info<< "    inlet " << patchName << ": rho " << state_.rho << ", U "
        << state_.U << ", p " << state_.p
        << (supersonic_ ? " (supersonic)" : " (subsonic)") << nl;
}


void Foam::gasBoundaries::stateInlet::fillGhosts
(
    const gasLine& line,
    bool high
) const
{
    const label G = line.G, L = line.L;
    const label edge = high ? G + L - 1 : G;
    double q[5];
    for (int c = 0; c < 5; ++c) q[c] = q_[c];
    if (!supersonic_)
    {
        const scalar pEdge = gas_.pressure
        (
            line.q[0][edge], line.q[1][edge], line.q[2][edge],
            line.q[3][edge], line.q[4][edge]
        );
        q[4] = gas_.totalEnergy
        (
            state_.rho, state_.U.x(), state_.U.y(), state_.U.z(), pEdge
        );
    }
    for (label k = 1; k <= G; ++k)
    {
        const label g = high ? G + L - 1 + k : G - k;
        for (int c = 0; c < 5; ++c) line.q[c][g] = q[c];
    }
}


Foam::scalar Foam::gasBoundaries::stateInlet::faceVelocity
(
    const double qEdge[5],
    label normal
) const
{
    return state_.U[normal];
}


// ************************************************************************* //
