/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "closeCenter.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace bsmsSeedings
{
    defineTypeNameAndDebug(closeCenter, 0);
    addToRunTimeSelectionTable(bsmsSeeding, closeCenter, dictionary);
}
}


Foam::bsmsSeedings::closeCenter::closeCenter(const dictionary& dict)
:
    bsmsSeeding(dict)
{}


// Algorithm 2 CloseCenter, lines 5-8 for one cluster idx:
//   Xbar = average(X[idx]),  s = idx[argmin ||X[idx] - Xbar||_2]
Foam::label Foam::bsmsSeedings::closeCenter::seed
(
    const meshGraph& g,
    const labelUList& clusterNodes
) const
{
    const pointField& x = g.positions();
    vector centre(Zero);
    for (const label i : clusterNodes) centre += x[i];
    centre /= scalar(clusterNodes.size());

    label best = clusterNodes[0];
    scalar bestD2 = magSqr(x[best] - centre);
    for (const label i : clusterNodes)
    {
        const scalar d2 = magSqr(x[i] - centre);
        if (d2 < bestD2)
        {
            bestD2 = d2;
            best = i;
        }
    }
    return best;
}


// ************************************************************************* //
