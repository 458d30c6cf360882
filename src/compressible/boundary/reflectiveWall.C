/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "reflectiveWall.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace gasBoundaries
{
    defineTypeNameAndDebug(reflectiveWall, 0);
    addToRunTimeSelectionTable(gasBoundary, reflectiveWall, dictionary);
}
}

Foam::gasBoundaries::reflectiveWall::reflectiveWall
(
    const word& patchName,
    const dictionary& dict,
    const idealGas& gas,
    const primitiveState& initial
)
:
    gasBoundary(patchName, gas)
{}


void Foam::gasBoundaries::reflectiveWall::fillGhosts
(
    const gasLine& line,
    bool high
) const
{
    const label G = line.G, L = line.L;
    for (label k = 1; k <= G; ++k)
    {
        const label g = high ? G + L - 1 + k : G - k;
        const label m = high ? G + L - k : G + k - 1;
        for (int c = 0; c < 5; ++c) line.q[c][g] = line.q[c][m];
        line.q[1 + line.normal][g] = -line.q[1 + line.normal][m];
    }
}


Foam::scalar Foam::gasBoundaries::reflectiveWall::faceVelocity
(
    const double qEdge[5],
    label normal
) const
{
    return 0;
}


// ************************************************************************* //
