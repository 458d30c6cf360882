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

    labelList cluster;
    g.clusterOf(cluster);

    // Pairs of different clusters within radius (O(N), spatialHash)
    DynamicList<label> a, b;
    spatialHash(x, radius).pairs(cluster, a, b);

    return meshGraph(x, a, b);
}


// ************************************************************************* //
