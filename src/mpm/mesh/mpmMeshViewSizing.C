/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "mpmMeshView.H"
#include "error.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"

#include <queue>
#include <utility>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

// Chapter 5's sizing field: the smallest h >= need with
// h_u >= h_v - g |x_u - x_v| along every edge.  Largest first (a max-plus
// Dijkstra): a value popped is final, each edge relaxes once per change.
void Foam::mpmMeshView::limitSizeGradient
(
    scalarList& h,
    const scalar gradient
) const
{
    typedef std::pair<scalar, label> entry;
    std::priority_queue<entry> queue;
    forAll(h, v) queue.push(entry(h[v], v));
    while (!queue.empty())
    {
        const entry top = queue.top();
        queue.pop();
        const label v = top.second;
        if (top.first < h[v]) continue;     // superseded by a larger value
        for (label i = vertexStart_[v]; i < vertexStart_[v + 1]; ++i)
        {
            const label u = vertexNeighbours_[i];
            const scalar hu =
                top.first - gradient*mag(vertices_[u] - vertices_[v]);
            if (hu > h[u])
            {
                h[u] = hu;
                queue.push(entry(hu, u));
            }
        }
    }
}


Foam::scalarList Foam::mpmMeshView::gradedSize
(
    const scalarList& need,
    const scalar gradient
) const
{
    if (need.size() != nVertices() || !(gradient > 0))
    {
        FatalErrorInFunction
            << "sizes for " << need.size() << " of " << nVertices()
            << " vertices, gradient " << gradient << " (must be > 0)"
            << exit(FatalError);
    }
    scalarList h(need);
    limitSizeGradient(h, gradient);
    if (!sharedMax_) return h;

    // Each rank holds some edges of its shared vertices: exchange the
    // maxima and relax again until no copy changes anywhere
    for (label round = 0; ; ++round)
    {
        const scalarList before(h);
        sharedMax_(h);
        bool changed = false;
        forAll(h, v) changed = changed || h[v] != before[v];
        if (!returnReduce(changed, orOp<bool>())) break;
        if (round > nVertices() + 100)
        {
            FatalErrorInFunction
                << "the graded sizing field did not settle across the ranks"
                << " after " << round << " exchanges" << exit(FatalError);
        }
        limitSizeGradient(h, gradient);
    }
    return h;
}


// ************************************************************************* //
