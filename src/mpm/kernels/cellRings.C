/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "cellRings.H"
#include "DynamicList.H"

Foam::cellRings::cellRings(const mpmMeshView& mesh)
:
    start(mesh.nCells() + 1),
    maxSize(0)
{
    static_assert
    (
        mpmMeshView::maxCellVertices <= 8,
        "the adjacency masks hold one bit per cell vertex"
    );

    const labelList& cv = mesh.cellVertices();
    const labelList& nbr = mesh.vertexNeighbours();

    // Per vertex: its slot in the current ring, or -1
    labelList slot(mesh.nVertices(), -1);
    DynamicList<label> ring(64);
    DynamicList<unsigned char> mask(64);
    DynamicList<label> allVertex(16*mesh.nCells());
    DynamicList<unsigned char> allMask(16*mesh.nCells());

    start[0] = 0;
    for (label c = 0; c < mesh.nCells(); ++c)
    {
        ring.clear();
        mask.clear();
        auto add = [&](const label v, const label i)
        {
            label s = slot[v];
            if (s < 0)
            {
                s = ring.size();
                slot[v] = s;
                ring.append(v);
                mask.append(0);
            }
            mask[s] |= static_cast<unsigned char>(1u << i);
        };

        const label b = mesh.cellBegin(c);
        const label nv = mesh.cellEnd(c) - b;
        for (label i = 0; i < nv; ++i)
        {
            add(cv[b + i], i);
        }
        for (label i = 0; i < nv; ++i)
        {
            const label v = cv[b + i];
            for (label k = mesh.vertexBegin(v); k < mesh.vertexEnd(v); ++k)
            {
                add(nbr[k], i);
            }
        }
        for (const label v : ring) slot[v] = -1;
        allVertex.append(ring);
        allMask.append(mask);
        start[c + 1] = allVertex.size();
        maxSize = max(maxSize, ring.size());
    }
    vertex.transfer(allVertex);
    adjacent.transfer(allMask);
}


// ************************************************************************* //
