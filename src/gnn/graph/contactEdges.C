/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "contactEdges.H"
#include "spatialHash.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::meshGraph Foam::contactEdges(const meshGraph& g, const scalar radius)
{
    if (!(radius > 0))
    {
        FatalErrorInFunction
            << "Contact radius " << radius << " is not > 0" << exit(FatalError);
    }

    const label n = g.nNodes();
    const pointField& x = g.positions();
    if (n == 0) return meshGraph(x, labelList(), labelList());

    // Cluster of every node
    labelList cOff, cNodes;
    const label nClusters = g.clusters(cOff, cNodes);
    labelList cluster(n);
    for (label k = 0; k < nClusters; ++k)
    {
        for (label m = cOff[k]; m < cOff[k + 1]; ++m) cluster[cNodes[m]] = k;
    }

    // Pairs of different clusters within radius (O(N), spatialHash)
    DynamicList<label> a, b;
    spatialHash(x, radius).pairs(cluster, a, b);

    return meshGraph(x, a, b);
}


// ************************************************************************* //
