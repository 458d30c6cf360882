/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "periodicLine.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace gasBoundaries
{
    defineTypeNameAndDebug(periodicLine, 0);
    addToRunTimeSelectionTable(gasBoundary, periodicLine, dictionary);
}
}

Foam::gasBoundaries::periodicLine::periodicLine
(
    const word& patchName,
    const dictionary& dict,
    const idealGas& gas,
    const primitiveState& initial
)
:
    gasBoundary(patchName, gas)
{}


void Foam::gasBoundaries::periodicLine::fillGhosts
(
    const gasLine& line,
    bool high
) const
{
    const label G = line.G, L = line.L;
    for (label k = 1; k <= G; ++k)
    {
        const label g = high ? G + L - 1 + k : G - k;
        const label s = high ? G + k - 1 : G + L - k;
        for (int c = 0; c < 5; ++c) line.q[c][g] = line.q[c][s];
    }
}


Foam::scalar Foam::gasBoundaries::periodicLine::faceVelocity
(
    const double qEdge[5],
    label normal
) const
{
    return qEdge[1 + normal]/qEdge[0];
}


// ************************************************************************* //
