/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "mpmMeshView.H"
#include "error.H"
#include "ListOps.H"
#include "DynamicList.H"
#include "mpmMeshShapes.H"

#include <algorithm>
#include <limits>

using namespace Foam::mpmMeshShapes;


// * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

const char* Foam::mpmMeshView::shapeName(shapeType s)
{
    static const char* names[] = {"segment", "triangle", "quad", "tet", "hex"};
    return names[s];
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::mpmMeshView::vertexCells
(
    labelList& start,
    labelList& cells
) const
{
    const label nV = vertices_.size();
    start.setSize(nV + 1);
    start = Zero;
    for (const label v : cellVertices_) ++start[v + 1];
    for (label v = 0; v < nV; ++v) start[v + 1] += start[v];
    cells.setSize(start[nV]);
    labelList fill(SubList<label>(start, nV));
    for (label c = 0; c < shapes_.size(); ++c)
    {
        for (label i = cellStart_[c]; i < cellStart_[c + 1]; ++i)
        {
            cells[fill[cellVertices_[i]]++] = c;
        }
    }
}


void Foam::mpmMeshView::build()
{
    const label nV = vertices_.size();
    const label nC = shapes_.size();

    // Bounding box
    bbMin_ = vector::uniform(GREAT);
    bbMax_ = vector::uniform(-GREAT);
    for (const vector& v : vertices_)
    {
        bbMin_ = min(bbMin_, v);
        bbMax_ = max(bbMax_, v);
    }

    labelList vcStart, vcCells;
    vertexCells(vcStart, vcCells);

    auto cellHas = [&](const label c, const label v)
    {
        for (label i = cellStart_[c]; i < cellStart_[c + 1]; ++i)
        {
            if (cellVertices_[i] == v) return true;
        }
        return false;
    };

    // Face neighbours: the other cell around a face's first vertex that
    // holds all the face's vertices
    cellFaceStart_.setSize(nC + 1);
    cellFaceStart_[0] = 0;
    for (label c = 0; c < nC; ++c)
    {
        cellFaceStart_[c + 1] = cellFaceStart_[c] + tables[shapes_[c]].nFaces;
    }
    cellFaceNeighbour_.setSize(cellFaceStart_[nC], -1);
    for (label c = 0; c < nC; ++c)
    {
        const shapeTable& t = tables[shapes_[c]];
        const label* cv = &cellVertices_[cellStart_[c]];
        for (label f = 0; f < t.nFaces; ++f)
        {
            const label v0 = cv[t.faces[f][0]];
            for (label k = vcStart[v0]; k < vcStart[v0 + 1]; ++k)
            {
                const label d = vcCells[k];
                if (d == c) continue;
                bool all = true;
                for (label j = 1; j < 4 && t.faces[f][j] >= 0; ++j)
                {
                    if (!cellHas(d, cv[t.faces[f][j]])) { all = false; break; }
                }
                if (all)
                {
                    cellFaceNeighbour_[cellFaceStart_[c] + f] = d;
                    break;
                }
            }
        }
    }

    // Boundary vertices: those of faces without a neighbour
    boundaryVertex_.setSize(nV, false);
    for (label c = 0; c < nC; ++c)
    {
        const shapeTable& t = tables[shapes_[c]];
        const label* cv = &cellVertices_[cellStart_[c]];
        for (label f = 0; f < t.nFaces; ++f)
        {
            if (cellFaceNeighbour_[cellFaceStart_[c] + f] >= 0) continue;
            for (label j = 0; j < 4 && t.faces[f][j] >= 0; ++j)
            {
                boundaryVertex_[cv[t.faces[f][j]]] = true;
            }
        }
    }

    // Vertex adjacency along the cells' edges
    vertexStart_.setSize(nV + 1);
    vertexStart_[0] = 0;
    DynamicList<label> nbrs(8*nV);
    DynamicList<label> local(64);
    for (label v = 0; v < nV; ++v)
    {
        local.clear();
        for (label k = vcStart[v]; k < vcStart[v + 1]; ++k)
        {
            const label c = vcCells[k];
            const shapeTable& t = tables[shapes_[c]];
            const label* cv = &cellVertices_[cellStart_[c]];
            for (label e = 0; e < t.nEdges; ++e)
            {
                const label a = cv[t.edges[e][0]];
                const label b = cv[t.edges[e][1]];
                if (a == v) local.append(b);
                else if (b == v) local.append(a);
            }
        }
        std::sort(local.begin(), local.end());
        const label n = std::unique(local.begin(), local.end()) - local.begin();
        for (label i = 0; i < n; ++i) nbrs.append(local[i]);
        vertexStart_[v + 1] = nbrs.size();
    }
    vertexNeighbours_.transfer(nbrs);

    // Local sizes: mean and longest edge
    vertexSize_.setSize(nV, Zero);
    vertexMaxEdge_.setSize(nV, Zero);
    for (label v = 0; v < nV; ++v)
    {
        const label n = vertexStart_[v + 1] - vertexStart_[v];
        if (n == 0)
        {
            FatalErrorInFunction
                << "Vertex " << v << " at " << vertices_[v]
                << " belongs to no cell edge" << exit(FatalError);
        }
        scalar s = 0, smax = 0;
        for (label k = vertexStart_[v]; k < vertexStart_[v + 1]; ++k)
        {
            const scalar l =
                distance(vertices_[v], vertices_[vertexNeighbours_[k]]);
            s += l;
            smax = max(smax, l);
        }
        vertexSize_[v] = s/n;
        vertexMaxEdge_[v] = smax;
    }

    buildMaps();

    // A walk longer than a few mesh widths has cycled (findCell)
    walkSteps_ =
        100 + 4*label(std::pow(scalar(nCells()), 1.0/max(dim_, label(1))) + 1);
}


void Foam::mpmMeshView::buildMaps()
{
    const label nC = shapes_.size();
    const label n = dim_;
    mapType_.setSize(nC);
    cellMap_.setSize(nC);
    for (label c = 0; c < nC; ++c)
    {
        const shapeType s = shapes_[c];
        const label* cv = &cellVertices_[cellStart_[c]];
        const label nv = nShapeVertices(s);
        cellMap& m = cellMap_[c];
        for (label a = 0; a < 3; ++a)
        {
            m.x0[a] = 0;
            for (label b = 0; b < 3; ++b) m.A[a][b] = 0;
        }
        scalar xl[8][3];
        scalar big = 0;
        for (label i = 0; i < nv; ++i)
        {
            const vector& xv = vertices_[cv[i]];
            for (label a = 0; a < n; ++a)
            {
                xl[i][a] = xv[axes_[a]];
                big = max(big, std::abs(xl[i][a]));
            }
        }

        // The affine part from vertex 0: T columns x_j - x_0 for the
        // simplex vertices j = 1..dim, or for the quad/hex vertices at
        // unit xi_0, xi_1 (, xi_2)
        static const label qv[3] = {1, 3, 4};
        scalar T[3][3];
        for (label a = 0; a < n; ++a)
        {
            for (label j = 0; j < n; ++j)
            {
                const label v = (s == QUAD || s == HEX) ? qv[j] : j + 1;
                T[a][j] = xl[v][a] - xl[0][a];
            }
        }

        // Quads and hexes are affine when every vertex lies where the
        // affine part puts it, to a few units of round-off of the
        // coordinates (blockMesh's parallelograms are, to the last bits)
        bool affine = true;
        if (s == QUAD || s == HEX)
        {
            const scalar tol = 16*std::numeric_limits<scalar>::epsilon()*big;
            const scalar (*ref)[3] = hexRef;
            scalar qref[4][3];
            if (s == QUAD)
            {
                for (label i = 0; i < 4; ++i)
                {
                    qref[i][0] = quadRef[i][0];
                    qref[i][1] = quadRef[i][1];
                    qref[i][2] = 0;
                }
                ref = qref;
            }
            for (label i = 0; i < nv && affine; ++i)
            {
                for (label a = 0; a < n; ++a)
                {
                    scalar xa = xl[0][a];
                    for (label j = 0; j < n; ++j) xa += ref[i][j]*T[a][j];
                    if (std::abs(xa - xl[i][a]) > tol) { affine = false; break; }
                }
            }
        }

        if (affine)
        {
            for (label a = 0; a < n; ++a) m.x0[a] = xl[0][a];
            mapType_[c] = invertSmall(n, T, m.A) ? AFFINE : DEGENERATE;
            continue;
        }

        // Curved: the centre and the inverse Jacobian there (the first
        // Newton step from xi = 1/2)
        scalar N[8];
        vector dN[8];
        multilinear(s, vector::uniform(0.5), N, dN);
        scalar J[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
        for (label i = 0; i < nv; ++i)
        {
            for (label a = 0; a < n; ++a)
            {
                m.x0[a] += N[i]*xl[i][a];
                for (label b = 0; b < n; ++b) J[a][b] += xl[i][a]*dN[i][b];
            }
        }
        mapType_[c] = invertSmall(n, J, m.A) ? CURVED : DEGENERATE;
    }
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::mpmMeshView::mpmMeshView
(
    const label dim,
    const FixedList<label, 3>& axes,
    const List<vector>& vertices,
    const List<shapeType>& shapes,
    const labelList& cellStart,
    const labelList& cellVertices
)
:
    dim_(dim),
    axes_(axes),
    vertices_(vertices),
    shapes_(shapes),
    cellStart_(cellStart),
    cellVertices_(cellVertices),
    pointVertex_(identity(vertices.size()))
{
    build();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::mpmMeshView::degenerate(const label c) const
{
    const shapeType s = shapes_[c];
    FatalErrorInFunction
        << "Degenerate " << shapeName(s) << " cell " << c
        << (s == QUAD || s == HEX
            ? " (singular isoparametric map)" : " (zero volume)")
        << exit(FatalError);
}


// ************************************************************************* //
