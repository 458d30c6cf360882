/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "minAve.H"
#include "closeCenter.H"
#include "addToRunTimeSelectionTable.H"
#include <limits>

namespace Foam
{
namespace bsmsSeedings
{
    defineTypeNameAndDebug(minAve, 0);
    addToRunTimeSelectionTable(bsmsSeeding, minAve, dictionary);
}
}


Foam::bsmsSeedings::minAve::minAve(const dictionary& dict)
:
    bsmsSeeding(dict)
{}


int64_t Foam::bsmsSeedings::minAve::distanceSum
(
    const meshGraph& g,
    const label c,
    const label n,
    const int64_t bestSum,
    const label bestNode
) const
{
    const label* off = g.offsets().cdata();
    const label* nbr = g.neighbours().cdata();
    label* d = dist_.data();
    label* q = order_.data();

    d[c] = 0;
    q[0] = c;
    label head = 0, tail = 1;
    label depth = 0;
    int64_t sum = 0;
    bool pruned = false;
    while (head < tail)
    {
        const label i = q[head++];
        if (d[i] > depth)
        {
            // Every node within d[i] hops is queued now (exactly those):
            // the other n - tail are at least d[i] + 1 hops away
            depth = d[i];
            const int64_t bound = sum + int64_t(n - tail)*(depth + 1);
            if (bound > bestSum || (bound == bestSum && c > bestNode))
            {
                pruned = true;
                break;
            }
        }
        const label di = d[i] + 1;
        for (label k = off[i]; k < off[i + 1]; ++k)
        {
            const label j = nbr[k];
            if (d[j] < 0)
            {
                d[j] = di;
                q[tail++] = j;
                sum += di;
            }
        }
    }

    // Leave the scratch clean
    for (label m = 0; m < tail; ++m) d[q[m]] = -1;
    return pruned ? -1 : sum;
}


// Algorithm 3 MinAve for one cluster idx:
//   D_c = D[idx, idx],  s = idx[argmin average(D_c, dim = 1)]
// (the average over the cluster's nodes is the sum over a constant count).
Foam::label Foam::bsmsSeedings::minAve::seed
(
    const meshGraph& g,
    const labelUList& clusterNodes
) const
{
    reserve(g.nNodes());
    const label n = clusterNodes.size();

    // Start from the centroid's node: usually close to the optimum, so
    // most other candidates stop early
    const label first = closeCenter(dictionary()).seed(g, clusterNodes);
    const int64_t none = std::numeric_limits<int64_t>::max();
    label bestNode = first;
    int64_t bestSum = distanceSum(g, first, n, none, -1);

    for (const label c : clusterNodes)
    {
        if (c == first) continue;
        const int64_t s = distanceSum(g, c, n, bestSum, bestNode);
        if (s >= 0 && (s < bestSum || (s == bestSum && c < bestNode)))
        {
            bestSum = s;
            bestNode = c;
        }
    }
    return bestNode;
}


// ************************************************************************* //
