/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "mpmMeshView.H"
#include "mpmMeshShapes.H"
#include "DynamicList.H"

using namespace Foam::mpmMeshShapes;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
using namespace Foam;

// Distance from p to the segment [a, b] (vectors over the solution axes)
scalar segmentDistance(const vector& p, const vector& a, const vector& b)
{
    const vector e = b - a;
    const scalar ee = e & e;
    const scalar t =
        ee > 0 ? min(max(((p - a) & e)/ee, scalar(0)), scalar(1)) : 0;
    return mag(p - a - t*e);
}

// Distance from p to the triangle (a, b, c): to its plane where p projects
// inside it, else to its nearest edge
scalar triangleDistance
(
    const vector& p,
    const vector& a,
    const vector& b,
    const vector& c
)
{
    const vector n = (b - a) ^ (c - a);
    const scalar nn = n & n;
    if (nn > 0)
    {
        const vector q = p - ((p - a) & n)/nn*n;
        if
        (
            (((b - a) ^ (q - a)) & n) >= 0
         && (((c - b) ^ (q - b)) & n) >= 0
         && (((a - c) ^ (q - c)) & n) >= 0
        )
        {
            return mag(p - q);
        }
    }
    return min
    (
        segmentDistance(p, a, b),
        min(segmentDistance(p, b, c), segmentDistance(p, c, a))
    );
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalarList Foam::mpmMeshView::ringReach() const
{
    return globalRingReach_ ? globalRingReach_() : ringReachOfView();
}


Foam::scalarList Foam::mpmMeshView::ringReachOfView() const
{
    const label nV = nVertices();
    const label nC = nCells();

    labelList vcStart, vcCells;
    vertexCells(vcStart, vcCells);

    // Cells whose 1-ring holds v: those with a vertex in v's closed
    // neighbourhood (cellRings: a cell's ring is its vertices and their
    // edge neighbours), stamped with v
    labelList stamp(nC, -1);
    DynamicList<label> inRing(256);
    scalarList reach(nV, GREAT);
    for (label v = 0; v < nV; ++v)
    {
        inRing.clear();
        auto addCellsOf = [&](const label u)
        {
            for (label k = vcStart[u]; k < vcStart[u + 1]; ++k)
            {
                const label c = vcCells[k];
                if (stamp[c] != v)
                {
                    stamp[c] = v;
                    inRing.append(c);
                }
            }
        };
        addCellsOf(v);
        for (label k = vertexStart_[v]; k < vertexStart_[v + 1]; ++k)
        {
            addCellsOf(vertexNeighbours_[k]);
        }

        // Faces to a cell without v in its ring (domain boundaries are no
        // crossings)
        const vector& xv = vertices_[v];
        scalar r = GREAT;
        for (const label c : inRing)
        {
            const shapeTable& t = tables[shapes_[c]];
            const label* cv = &cellVertices_[cellStart_[c]];
            for (label f = 0; f < t.nFaces; ++f)
            {
                const label d = cellFaceNeighbour_[cellFaceStart_[c] + f];
                if (d < 0 || stamp[d] == v) continue;
                const label* fv = t.faces[f];
                const vector a = delta(vertices_[cv[fv[0]]], xv);
                if (fv[1] < 0)
                {
                    r = min(r, mag(a));
                }
                else if (fv[2] < 0)
                {
                    const vector b = delta(vertices_[cv[fv[1]]], xv);
                    r = min(r, segmentDistance(Zero, a, b));
                }
                else
                {
                    const vector b = delta(vertices_[cv[fv[1]]], xv);
                    const vector e = delta(vertices_[cv[fv[2]]], xv);
                    r = min(r, triangleDistance(Zero, a, b, e));
                    if (fv[3] >= 0)
                    {
                        const vector g = delta(vertices_[cv[fv[3]]], xv);
                        r = min(r, triangleDistance(Zero, a, e, g));
                    }
                }
            }
        }
        reach[v] = r;
    }
    return reach;
}


// ************************************************************************* //
