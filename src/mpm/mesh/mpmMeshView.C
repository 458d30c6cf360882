/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "mpmMeshView.H"
#include "error.H"
#include "ListOps.H"
#include "DynamicList.H"

#include <algorithm>
#include <limits>

// * * * * * * * * * * * * * * * Local tables  * * * * * * * * * * * * * * //

namespace
{
using Foam::label;

// Edges of each shape, as pairs of local vertex indices
const label segmentEdges[][2] = {{0, 1}};
const label triEdges[][2] = {{0, 1}, {1, 2}, {2, 0}};
const label quadEdges[][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
const label tetEdges[][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
const label hexEdges[][2] =
{
    {0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4},
    {0, 4}, {1, 5}, {2, 6}, {3, 7}
};

// Faces of each shape, local vertex indices, -1 padded.  Simplices: face k
// is opposite vertex k.  Quad/hex: faces at xi_d = 0 and 1 for d = 0, 1, 2.
const label segmentFaces[][4] = {{1, -1, -1, -1}, {0, -1, -1, -1}};
const label triFaces[][4] = {{1, 2, -1, -1}, {2, 0, -1, -1}, {0, 1, -1, -1}};
const label quadFaces[][4] =
    {{0, 3, -1, -1}, {1, 2, -1, -1}, {0, 1, -1, -1}, {3, 2, -1, -1}};
const label tetFaces[][4] =
    {{1, 2, 3, -1}, {0, 2, 3, -1}, {0, 1, 3, -1}, {0, 1, 2, -1}};
const label hexFaces[][4] =
{
    {0, 3, 7, 4}, {1, 2, 6, 5}, {0, 1, 5, 4}, {3, 2, 6, 7},
    {0, 1, 2, 3}, {4, 5, 6, 7}
};

struct shapeTable
{
    label nEdges;
    const label (*edges)[2];
    label nFaces;
    const label (*faces)[4];
};

const shapeTable tables[] =
{
    {1, segmentEdges, 2, segmentFaces},
    {3, triEdges, 3, triFaces},
    {4, quadEdges, 4, quadFaces},
    {6, tetEdges, 4, tetFaces},
    {12, hexEdges, 6, hexFaces}
};

// Reference coordinates of the multilinear vertices
const Foam::scalar quadRef[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
const Foam::scalar hexRef[8][3] =
{
    {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
    {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}
};

// Solve the small system A y = r (n <= 3) by Gaussian elimination with
// partial pivoting; returns false if A is singular
bool smallSolve(Foam::label n, Foam::scalar A[3][3], Foam::scalar r[3])
{
    for (Foam::label k = 0; k < n; ++k)
    {
        Foam::label p = k;
        for (Foam::label i = k + 1; i < n; ++i)
        {
            if (std::abs(A[i][k]) > std::abs(A[p][k])) p = i;
        }
        if (A[p][k] == 0) return false;
        if (p != k)
        {
            for (Foam::label j = 0; j < n; ++j) std::swap(A[k][j], A[p][j]);
            std::swap(r[k], r[p]);
        }
        for (Foam::label i = k + 1; i < n; ++i)
        {
            const Foam::scalar f = A[i][k]/A[k][k];
            for (Foam::label j = k; j < n; ++j) A[i][j] -= f*A[k][j];
            r[i] -= f*r[k];
        }
    }
    for (Foam::label k = n - 1; k >= 0; --k)
    {
        for (Foam::label j = k + 1; j < n; ++j) r[k] -= A[k][j]*r[j];
        r[k] /= A[k][k];
    }
    return true;
}

// Inverse of the n x n matrix T (n <= 3): closed form in 1D and 2D, column
// by column in 3D; false if T is singular
bool invertSmall
(
    Foam::label n,
    const Foam::scalar T[3][3],
    Foam::scalar Tinv[3][3]
)
{
    if (n == 1)
    {
        if (T[0][0] == 0) return false;
        Tinv[0][0] = 1/T[0][0];
        return true;
    }
    if (n == 2)
    {
        const Foam::scalar det = T[0][0]*T[1][1] - T[0][1]*T[1][0];
        if (det == 0) return false;
        const Foam::scalar r = 1/det;
        Tinv[0][0] = T[1][1]*r;
        Tinv[0][1] = -T[0][1]*r;
        Tinv[1][0] = -T[1][0]*r;
        Tinv[1][1] = T[0][0]*r;
        return true;
    }
    for (Foam::label j = 0; j < n; ++j)
    {
        Foam::scalar A[3][3], r[3] = {0, 0, 0};
        for (Foam::label a = 0; a < n; ++a)
            for (Foam::label b = 0; b < n; ++b) A[a][b] = T[a][b];
        r[j] = 1;
        if (!smallSolve(n, A, r)) return false;
        for (Foam::label a = 0; a < n; ++a) Tinv[a][j] = r[a];
    }
    return true;
}

// B = N and grad B = J^-T dN/dxi of a hex (the axes of a 3D mesh are
// x, y, z)
inline void hexGradients
(
    const Foam::scalar Ji[3][3],
    const Foam::scalar* N,
    const Foam::vector* dN,
    Foam::mpmMeshView::shapeValues& sv
)
{
    for (Foam::label i = 0; i < 8; ++i)
    {
        const Foam::vector& d = dN[i];
        sv.B[i] = N[i];
        sv.gradB[i] = Foam::vector
        (
            Ji[0][0]*d[0] + Ji[1][0]*d[1] + Ji[2][0]*d[2],
            Ji[0][1]*d[0] + Ji[1][1]*d[1] + Ji[2][1]*d[2],
            Ji[0][2]*d[0] + Ji[1][2]*d[1] + Ji[2][2]*d[2]
        );
    }
}

// B = N and grad B = J^-T dN/dxi of a quad (D = 2) or hex (D = 3)
template<int D>
inline void cubeGradients
(
    const Foam::scalar Ji[3][3],
    const Foam::scalar* N,
    const Foam::vector* dN,
    const Foam::label nv,
    const Foam::FixedList<Foam::label, 3>& axes,
    Foam::mpmMeshView::shapeValues& sv
)
{
    for (Foam::label i = 0; i < nv; ++i)
    {
        Foam::vector g(Foam::Zero);
        for (int a = 0; a < D; ++a)
        {
            Foam::scalar t = 0;
            for (int b = 0; b < D; ++b) t += Ji[b][a]*dN[i][b];
            g[axes[a]] = t;
        }
        sv.B[i] = N[i];
        sv.gradB[i] = g;
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

const char* Foam::mpmMeshView::shapeName(shapeType s)
{
    static const char* names[] = {"segment", "triangle", "quad", "tet", "hex"};
    return names[s];
}


Foam::label Foam::mpmMeshView::nShapeVertices(shapeType s)
{
    static const label n[] = {2, 3, 4, 4, 8};
    return n[s];
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

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

    // Vertex -> cells (compressed rows)
    labelList vcStart(nV + 1, Zero);
    for (const label v : cellVertices_) ++vcStart[v + 1];
    for (label v = 0; v < nV; ++v) vcStart[v + 1] += vcStart[v];
    labelList vcCells(vcStart[nV]);
    {
        labelList fill(SubList<label>(vcStart, nV));
        for (label c = 0; c < nC; ++c)
        {
            for (label i = cellStart_[c]; i < cellStart_[c + 1]; ++i)
            {
                vcCells[fill[cellVertices_[i]]++] = c;
            }
        }
    }

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


void Foam::mpmMeshView::multilinear
(
    shapeType s,
    const vector& xi,
    scalar* N,
    vector* dNdxi
) const
{
    // Products of (1 - xi_d) or xi_d by the vertices' reference corners
    // (quadRef, hexRef), written out: the same products, no branches
    const scalar a[2] = {1 - xi[0], xi[0]};
    const scalar b[2] = {1 - xi[1], xi[1]};
    const scalar sg[2] = {-1, 1};
    static const label cx[8] = {0, 1, 1, 0, 0, 1, 1, 0};
    static const label cy[8] = {0, 0, 1, 1, 0, 0, 1, 1};
    static const label cz[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    if (s == QUAD)
    {
        for (label i = 0; i < 4; ++i)
        {
            const scalar ai = a[cx[i]], bi = b[cy[i]];
            N[i] = ai*bi;
            dNdxi[i] = vector(sg[cx[i]]*bi, ai*sg[cy[i]], 0);
        }
    }
    else
    {
        const scalar c[2] = {1 - xi[2], xi[2]};
        for (label i = 0; i < 8; ++i)
        {
            const scalar ai = a[cx[i]], bi = b[cy[i]], ci = c[cz[i]];
            N[i] = ai*bi*ci;
            dNdxi[i] =
                vector(sg[cx[i]]*bi*ci, ai*sg[cy[i]]*ci, ai*bi*sg[cz[i]]);
        }
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


bool Foam::mpmMeshView::isoparametric
(
    const label c,
    const vector& x,
    vector& xi
) const
{
    const label n = dim_;
    const cellMap& m = cellMap_[c];
    const mapType k = mapType_[c];
    if (k == DEGENERATE) degenerate(c);

    // The affine map: exact for parallelograms and parallelepipeds, the
    // first Newton step from the centre otherwise
    scalar d[3];
    for (label a = 0; a < n; ++a) d[a] = x[axes_[a]] - m.x0[a];
    xi = Zero;
    for (label b = 0; b < n; ++b)
    {
        scalar t = 0;
        for (label a = 0; a < n; ++a) t += m.A[b][a]*d[a];
        xi[b] = t;
    }
    if (k == AFFINE) return true;

    // Curved cell: Newton on the isoparametric map from the affine guess
    const shapeType s = shapes_[c];
    const label* cv = &cellVertices_[cellStart_[c]];
    const label nv = nShapeVertices(s);
    scalar xl[8][3];
    for (label i = 0; i < nv; ++i)
    {
        const vector& xv = vertices_[cv[i]];
        for (label a = 0; a < n; ++a) xl[i][a] = xv[axes_[a]];
    }
    scalar size2 = 0;
    for (label a = 0; a < n; ++a) size2 += sqr(xl[nv - 2][a] - xl[0][a]);

    // Keep the iterate near the cell: far outside, the map folds
    for (label b = 0; b < n; ++b)
    {
        xi[b] = max(scalar(-2), min(scalar(3), scalar(0.5) + xi[b]));
    }
    scalar N[8];
    vector dN[8];
    for (label iter = 0; iter < 30; ++iter)
    {
        multilinear(s, xi, N, dN);
        scalar r[3] = {0, 0, 0};
        scalar J[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
        for (label i = 0; i < nv; ++i)
        {
            for (label a = 0; a < n; ++a)
            {
                r[a] += N[i]*xl[i][a];
                for (label b = 0; b < n; ++b) J[a][b] += xl[i][a]*dN[i][b];
            }
        }
        scalar res2 = 0;
        for (label a = 0; a < n; ++a)
        {
            r[a] = x[axes_[a]] - r[a];
            res2 += r[a]*r[a];
        }
        // Converged to round-off: no further step
        if (res2 <= 1e-28*size2) return true;
        if (!smallSolve(n, J, r)) degenerate(c);
        scalar step = 0;
        for (label a = 0; a < n; ++a)
        {
            xi[a] = max(scalar(-2), min(scalar(3), xi[a] + r[a]));
            step = max(step, std::abs(r[a]));
        }
        if (step < 1e-14) break;
    }

    // Converged? (Far outside a distorted cell Newton may not be.)
    multilinear(s, xi, N, dN);
    scalar res2 = 0;
    for (label a = 0; a < n; ++a)
    {
        scalar xr = 0;
        for (label i = 0; i < nv; ++i) xr += N[i]*xl[i][a];
        res2 += sqr(xr - x[axes_[a]]);
    }
    return res2 <= 1e-20*size2;
}


Foam::scalar Foam::mpmMeshView::outside
(
    const label c,
    const vector& x,
    label& exitFace
) const
{
    const shapeType s = shapes_[c];
    const label n = dim_;
    scalar out = 0;
    exitFace = -1;

    if (s == SEGMENT || s == TRIANGLE || s == TET)
    {
        // The barycentric coordinates as shapeFunctions computes them
        if (mapType_[c] == DEGENERATE) degenerate(c);
        const cellMap& m = cellMap_[c];
        scalar d[3];
        for (label a = 0; a < n; ++a) d[a] = x[axes_[a]] - m.x0[a];
        scalar lsum = 0;
        for (label j = 0; j < n; ++j)
        {
            scalar l = 0;
            for (label a = 0; a < n; ++a) l += m.A[j][a]*d[a];
            lsum += l;
            if (-l > out) { out = -l; exitFace = j + 1; }
        }
        // Vertex 0 comes first in shapeFunctions' scan: same tie order
        const scalar l0 = 1 - lsum;
        if (-l0 > out || (-l0 == out && out > 0))
        {
            out = -l0;
            exitFace = 0;
        }
        return out;
    }

    vector xi;
    const bool converged = isoparametric(c, x, xi);
    for (label a = 0; a < n; ++a)
    {
        if (-xi[a] > out) { out = -xi[a]; exitFace = 2*a; }
        if (xi[a] - 1 > out) { out = xi[a] - 1; exitFace = 2*a + 1; }
    }
    if (!converged)
    {
        // Not this cell: head the walk the way the last iterate points
        out = max(out, scalar(1));
        if (exitFace < 0) exitFace = 0;
    }
    return out;
}


template<bool gradients>
void Foam::mpmMeshView::evaluate
(
    const label c,
    const vector& x,
    shapeValues& sv
) const
{
    const shapeType s = shapes_[c];
    const label n = dim_;
    sv.n = nShapeVertices(s);
    const cellMap& m = cellMap_[c];

    if (s == SEGMENT || s == TRIANGLE || s == TET)
    {
        // Barycentric: l_j = (T^-1 (x - x0))_j, T columns x_j - x0, whose
        // inverse (rows: grad l_j) the cell map holds
        if (mapType_[c] == DEGENERATE) degenerate(c);
        scalar d[3];
        for (label a = 0; a < n; ++a) d[a] = x[axes_[a]] - m.x0[a];
        scalar lsum = 0;
        vector gsum(Zero);
        for (label j = 0; j < n; ++j)
        {
            scalar l = 0;
            for (label a = 0; a < n; ++a) l += m.A[j][a]*d[a];
            sv.B[j + 1] = l;
            lsum += l;
            if (gradients)
            {
                vector g(Zero);
                for (label a = 0; a < n; ++a) g[axes_[a]] = m.A[j][a];
                sv.gradB[j + 1] = g;
                gsum += g;
            }
        }
        sv.B[0] = 1 - lsum;
        if (gradients) sv.gradB[0] = -gsum;

        sv.outside = 0;
        sv.exitFace = -1;
        for (label i = 0; i < sv.n; ++i)
        {
            if (-sv.B[i] > sv.outside)
            {
                sv.outside = -sv.B[i];
                sv.exitFace = i;     // face opposite vertex i
            }
        }
        return;
    }

    // Quad / hex: reference coordinates, then grad N = J^-T dN/dxi with
    // J^-1 from the cell map (affine) or at the point (curved)
    const label nv = sv.n;
    vector xi;
    const bool converged = isoparametric(c, x, xi);
    scalar N[8];
    vector dN[8];
    multilinear(s, xi, N, dN);

    scalar Jc[3][3];
    const scalar (*Ji)[3] = m.A;
    if (!gradients)
    {
        for (label i = 0; i < nv; ++i) sv.B[i] = N[i];
    }
    else if (mapType_[c] != AFFINE)
    {
        const label* cv = &cellVertices_[cellStart_[c]];
        scalar J[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
        for (label i = 0; i < nv; ++i)
        {
            const vector& xv = vertices_[cv[i]];
            for (label a = 0; a < n; ++a)
                for (label b = 0; b < n; ++b) J[a][b] += xv[axes_[a]]*dN[i][b];
        }
        if (!invertSmall(n, J, Jc)) degenerate(c);
        Ji = Jc;
    }
    if (!gradients) {}
    else if (n == 3) hexGradients(Ji, N, dN, sv);
    else cubeGradients<2>(Ji, N, dN, nv, axes_, sv);

    sv.outside = 0;
    sv.exitFace = -1;
    for (label a = 0; a < n; ++a)
    {
        if (-xi[a] > sv.outside) { sv.outside = -xi[a]; sv.exitFace = 2*a; }
        if (xi[a] - 1 > sv.outside) { sv.outside = xi[a] - 1; sv.exitFace = 2*a + 1; }
    }
    if (!converged)
    {
        // Not this cell: head the walk the way the last iterate points
        sv.outside = max(sv.outside, scalar(1));
        if (sv.exitFace < 0) sv.exitFace = 0;
    }
}


void Foam::mpmMeshView::shapeFunctions
(
    const label c,
    const vector& x,
    shapeValues& sv
) const
{
    evaluate<true>(c, x, sv);
}


void Foam::mpmMeshView::shapeValuesOnly
(
    const label c,
    const vector& x,
    shapeValues& sv
) const
{
    evaluate<false>(c, x, sv);
}


Foam::label Foam::mpmMeshView::findCell(const vector& x, const label start) const
{
    const scalar tol = 1e-12;
    const label nC = nCells();
    if (nC == 0) return -1;

    label c = (start >= 0 && start < nC) ? start : 0;
    label exitFace = -1;
    const label maxSteps = 100 + 4*label(std::pow(scalar(nC), 1.0/dim_) + 1);
    for (label step = 0; step < maxSteps; ++step)
    {
        if (outside(c, x, exitFace) <= tol)
        {
            return c;
        }
        const label n = faceNeighbour(c, exitFace);
        if (n < 0)
        {
            break;
        }
        c = n;
    }

    // The walk ended on the boundary or cycled: search every cell
    for (label d = 0; d < nC; ++d)
    {
        if (outside(d, x, exitFace) <= tol)
        {
            return d;
        }
    }
    return -1;
}


// ************************************************************************* //
