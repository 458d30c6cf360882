/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "attenuatedOutlet.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace gasBoundaries
{
    defineTypeNameAndDebug(attenuatedOutlet, 0);
    addToRunTimeSelectionTable(gasBoundary, attenuatedOutlet, dictionary);
}
}

Foam::gasBoundaries::attenuatedOutlet::attenuatedOutlet
(
    const word& patchName,
    const dictionary& dict,
    const idealGas& gas,
    const primitiveState& initial
)
:
    gasBoundary(patchName, gas),
    a_(dictionaryChecks::getAsOrDefault<scalar>
    (
        dict, "attenuation", 0, "a number in [0, 1)"
    ))
{
    if (!(a_ >= 0 && a_ < 1))
    {
        dictionaryChecks::badEntry
        (
            dict, "attenuation", Foam::name(a_), "a number in [0, 1)"
        );
    }
    conserved
    (
        readState(dict.subOrEmptyDict("farField"), initial),
        qFar_
    );
}


void Foam::gasBoundaries::attenuatedOutlet::fillGhosts
(
    const gasLine& line,
    bool high
) const
{
    const label G = line.G, L = line.L;
    const label edge = high ? G + L - 1 : G;
    for (label k = 1; k <= G; ++k)
    {
        const label g = high ? G + L - 1 + k : G - k;
        for (int c = 0; c < 5; ++c)
        {
            line.q[c][g] = (1 - a_)*line.q[c][edge] + a_*qFar_[c];
        }
    }
}


Foam::scalar Foam::gasBoundaries::attenuatedOutlet::faceVelocity
(
    const double qEdge[5],
    label normal
) const
{
    return qEdge[1 + normal]/qEdge[0];
}


// ************************************************************************* //
