/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "meshGraph.H"
#include "polyMesh.H"
#include <algorithm>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(meshGraph, 0);
}

const Foam::Enum<Foam::meshGraph::nodeType> Foam::meshGraph::nodeTypeNames
({
    { nodeType::cells, "cells" },
    { nodeType::points, "points" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::meshGraph::build(const label n, const labelUList& a, const labelUList& b)
{
    if (a.size() != b.size())
    {
        FatalErrorInFunction
            << "Edge lists of different lengths " << a.size() << " and "
            << b.size() << exit(FatalError);
    }

    // Count both directions, then fill
    offsets_.setSize(n + 1);
    offsets_ = 0;
    forAll(a, e)
    {
        const label i = a[e], j = b[e];
        if (i < 0 || i >= n || j < 0 || j >= n)
        {
            FatalErrorInFunction
                << "Edge " << e << " (" << i << ' ' << j << ") refers to a "
                << "node outside 0.." << n - 1 << exit(FatalError);
        }
        if (i == j) continue;
        ++offsets_[i + 1];
        ++offsets_[j + 1];
    }
    for (label i = 0; i < n; ++i) offsets_[i + 1] += offsets_[i];

    labelList fill(SubList<label>(offsets_, n));
    neighbours_.setSize(offsets_[n]);
    forAll(a, e)
    {
        const label i = a[e], j = b[e];
        if (i == j) continue;
        neighbours_[fill[i]++] = j;
        neighbours_[fill[j]++] = i;
    }

    // Sort each row and drop duplicates, compacting in place
    label out = 0;
    for (label i = 0; i < n; ++i)
    {
        label* begin = neighbours_.begin() + offsets_[i];
        label* end = neighbours_.begin() + offsets_[i + 1];
        std::sort(begin, end);
        end = std::unique(begin, end);
        offsets_[i] = out;
        for (const label* p = begin; p != end; ++p) neighbours_[out++] = *p;
    }
    offsets_[n] = out;
    neighbours_.setSize(out);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshGraph::meshGraph
(
    const pointField& positions,
    const labelUList& a,
    const labelUList& b
)
:
    positions_(positions)
{
    build(positions_.size(), a, b);
}


Foam::meshGraph::meshGraph
(
    pointField&& positions,
    labelList&& offsets,
    labelList&& neighbours
)
:
    positions_(std::move(positions)),
    offsets_(std::move(offsets)),
    neighbours_(std::move(neighbours))
{
    if (offsets_.size() != positions_.size() + 1 || (debug && !valid()))
    {
        FatalErrorInFunction
            << "Inconsistent CSR graph: " << positions_.size() << " nodes, "
            << offsets_.size() << " row offsets" << exit(FatalError);
    }
}


Foam::meshGraph::meshGraph(const polyMesh& mesh, const nodeType type)
{
    if (type == nodeType::cells)
    {
        // One edge per internal face: its owner and neighbour cells
        const label nInt = mesh.nInternalFaces();
        positions_ = mesh.cellCentres();
        build
        (
            mesh.nCells(),
            SubList<label>(mesh.faceOwner(), nInt),
            mesh.faceNeighbour()
        );
    }
    else
    {
        // Every edge of the mesh's faces is an edge of a cell
        const edgeList& edges = mesh.edges();
        labelList a(edges.size()), b(edges.size());
        forAll(edges, e)
        {
            a[e] = edges[e].start();
            b[e] = edges[e].end();
        }
        positions_ = mesh.points();
        build(mesh.nPoints(), a, b);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::meshGraph::adjacent(const label i, const label j) const
{
    const label* begin = neighbours_.cdata() + offsets_[i];
    const label* end = neighbours_.cdata() + offsets_[i + 1];
    return std::binary_search(begin, end, j);
}


bool Foam::meshGraph::valid() const
{
    const label n = nNodes();
    if (offsets_.size() != n + 1 || offsets_[0] != 0) return false;
    if (offsets_[n] != neighbours_.size()) return false;
    for (label i = 0; i < n; ++i)
    {
        if (offsets_[i + 1] < offsets_[i]) return false;
        for (label k = offsets_[i]; k < offsets_[i + 1]; ++k)
        {
            const label j = neighbours_[k];
            if (j < 0 || j >= n || j == i) return false;
            if (k > offsets_[i] && neighbours_[k - 1] >= j) return false;
            if (!adjacent(j, i)) return false;
        }
    }
    return true;
}


Foam::label Foam::meshGraph::bfs
(
    const label seed,
    labelList& dist,
    labelList& order
) const
{
    const label* off = offsets_.cdata();
    const label* nbr = neighbours_.cdata();
    label* d = dist.data();
    label* q = order.data();

    d[seed] = 0;
    q[0] = seed;
    label head = 0, tail = 1;
    while (head < tail)
    {
        const label i = q[head++];
        const label di = d[i] + 1;
        for (label k = off[i]; k < off[i + 1]; ++k)
        {
            const label j = nbr[k];
            if (d[j] < 0)
            {
                d[j] = di;
                q[tail++] = j;
            }
        }
    }
    return tail;
}


// Algorithm 4 DetermineCluster.  The remaining set R is scanned in node
// order: the first node not yet in a cluster is the start s of a BFS, and
// the nodes it reaches (D[n] < infinity) form its cluster C.  One BFS per
// cluster, O(N + E) in all.
Foam::label Foam::meshGraph::clusterOf(labelList& cluster) const
{
    const label n = nNodes();
    cluster.setSize(n);
    cluster = -1;
    labelList queue(n);
    const label* off = offsets_.cdata();
    const label* nbr = neighbours_.cdata();

    label nClusters = 0;
    for (label s = 0; s < n; ++s)
    {
        if (cluster[s] >= 0) continue;
        cluster[s] = nClusters;
        queue[0] = s;
        label head = 0, tail = 1;
        while (head < tail)
        {
            const label i = queue[head++];
            for (label k = off[i]; k < off[i + 1]; ++k)
            {
                const label j = nbr[k];
                if (cluster[j] < 0)
                {
                    cluster[j] = nClusters;
                    queue[tail++] = j;
                }
            }
        }
        ++nClusters;
    }
    return nClusters;
}


Foam::label Foam::meshGraph::clusters(labelList& offsets, labelList& nodes) const
{
    const label n = nNodes();
    labelList cluster;
    const label nClusters = clusterOf(cluster);

    // Counting sort by cluster: nodes ascending within each cluster
    offsets.setSize(nClusters + 1);
    offsets = 0;
    for (label i = 0; i < n; ++i) ++offsets[cluster[i] + 1];
    for (label k = 0; k < nClusters; ++k) offsets[k + 1] += offsets[k];
    labelList fill(SubList<label>(offsets, nClusters));
    nodes.setSize(n);
    for (label i = 0; i < n; ++i) nodes[fill[cluster[i]]++] = i;

    return nClusters;
}


Foam::label Foam::meshGraph::nComponents() const
{
    labelList offsets, nodes;
    return clusters(offsets, nodes);
}


// ************************************************************************* //
