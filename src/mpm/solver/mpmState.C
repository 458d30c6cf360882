/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "mpmState.H"
#include "Time.H"

namespace Foam
{
    defineTypeNameAndDebug(mpmState, 0);
}

Foam::mpmState::mpmState
(
    const objectRegistry& obr,
    const mpmSolver& solver,
    const mpmParticles& particles
)
:
    regIOobject
    (
        IOobject
        (
            "mpmState",
            obr.time().timeName(),
            obr,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        )
    ),
    solver_(solver),
    particles_(particles)
{}

// ************************************************************************* //
