/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "contactEdges.H"
#include "boundBox.H"
#include "DynamicList.H"
#include <cmath>

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

    // Bins of size h >= radius, at most about 8 n of them
    const boundBox bb(x, false);
    const vector span = bb.span();
    scalar h = radius;
    label nb[3];
    for (;;)
    {
        double total = 1;
        for (direction d = 0; d < 3; ++d)
        {
            nb[d] = label(std::floor(span[d]/h)) + 1;
            total *= nb[d];
        }
        if (total <= 8.0*n + 27) break;
        h *= 2;
    }
    auto binOf = [&](const point& p, label ijk[3])
    {
        for (direction d = 0; d < 3; ++d)
        {
            ijk[d] = min(label((p[d] - bb.min()[d])/h), nb[d] - 1);
        }
    };

    // Counting sort of the nodes by bin
    const label nBins = nb[0]*nb[1]*nb[2];
    labelList binStart(nBins + 1, Zero);
    labelList binOfNode(n);
    for (label i = 0; i < n; ++i)
    {
        label ijk[3];
        binOf(x[i], ijk);
        binOfNode[i] = ijk[0] + nb[0]*(ijk[1] + nb[1]*ijk[2]);
        ++binStart[binOfNode[i] + 1];
    }
    for (label b = 0; b < nBins; ++b) binStart[b + 1] += binStart[b];
    labelList fill(SubList<label>(binStart, nBins));
    labelList sorted(n);
    for (label i = 0; i < n; ++i) sorted[fill[binOfNode[i]]++] = i;

    // Pairs (i < j) in neighbouring bins, different clusters, within radius
    const scalar r2 = radius*radius;
    DynamicList<label> a, b;
    for (label i = 0; i < n; ++i)
    {
        label ijk[3];
        binOf(x[i], ijk);
        for (label dk = -1; dk <= 1; ++dk)
        for (label dj = -1; dj <= 1; ++dj)
        for (label di = -1; di <= 1; ++di)
        {
            const label bi = ijk[0] + di, bj = ijk[1] + dj, bk = ijk[2] + dk;
            if
            (
                bi < 0 || bj < 0 || bk < 0
             || bi >= nb[0] || bj >= nb[1] || bk >= nb[2]
            )
            {
                continue;
            }
            const label bin = bi + nb[0]*(bj + nb[1]*bk);
            for (label m = binStart[bin]; m < binStart[bin + 1]; ++m)
            {
                const label j = sorted[m];
                if (j <= i || cluster[j] == cluster[i]) continue;
                if (magSqr(x[j] - x[i]) < r2)
                {
                    a.append(i);
                    b.append(j);
                }
            }
        }
    }

    return meshGraph(x, a, b);
}


// ************************************************************************* //
