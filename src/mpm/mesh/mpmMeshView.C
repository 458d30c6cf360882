/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "mpmMeshView.H"
#include "error.H"
#include "ListOps.H"
#include "DynamicList.H"

#include <algorithm>

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
}


void Foam::mpmMeshView::multilinear
(
    shapeType s,
    const vector& xi,
    scalar* N,
    vector* dNdxi
) const
{
    if (s == QUAD)
    {
        for (label i = 0; i < 4; ++i)
        {
            const scalar a = quadRef[i][0] ? xi[0] : 1 - xi[0];
            const scalar b = quadRef[i][1] ? xi[1] : 1 - xi[1];
            const scalar da = quadRef[i][0] ? 1 : -1;
            const scalar db = quadRef[i][1] ? 1 : -1;
            N[i] = a*b;
            dNdxi[i] = vector(da*b, a*db, 0);
        }
    }
    else
    {
        for (label i = 0; i < 8; ++i)
        {
            const scalar a = hexRef[i][0] ? xi[0] : 1 - xi[0];
            const scalar b = hexRef[i][1] ? xi[1] : 1 - xi[1];
            const scalar c = hexRef[i][2] ? xi[2] : 1 - xi[2];
            const scalar da = hexRef[i][0] ? 1 : -1;
            const scalar db = hexRef[i][1] ? 1 : -1;
            const scalar dc = hexRef[i][2] ? 1 : -1;
            N[i] = a*b*c;
            dNdxi[i] = vector(da*b*c, a*db*c, a*b*dc);
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

void Foam::mpmMeshView::shapeFunctions
(
    const label c,
    const vector& x,
    shapeValues& sv
) const
{
    const shapeType s = shapes_[c];
    const label* cv = &cellVertices_[cellStart_[c]];
    sv.n = nShapeVertices(s);

    if (s == SEGMENT || s == TRIANGLE || s == TET)
    {
        // Barycentric: solve T l = x - x0, T columns x_i - x0 (i >= 1)
        const label n = dim_;
        const vector& x0 = vertices_[cv[0]];
        scalar T[3][3], Tinv[3][3];
        for (label i = 0; i < n; ++i)
        {
            for (label j = 0; j < n; ++j)
            {
                T[i][j] = vertices_[cv[j + 1]][axes_[i]] - x0[axes_[i]];
            }
        }
        // Inverse (rows of T^-1 are grad l_j): closed form in 1D and 2D,
        // column by column in 3D
        bool singular = false;
        if (n == 1)
        {
            singular = (T[0][0] == 0);
            if (!singular) Tinv[0][0] = 1/T[0][0];
        }
        else if (n == 2)
        {
            const scalar det = T[0][0]*T[1][1] - T[0][1]*T[1][0];
            singular = (det == 0);
            if (!singular)
            {
                const scalar r = 1/det;
                Tinv[0][0] = T[1][1]*r;
                Tinv[0][1] = -T[0][1]*r;
                Tinv[1][0] = -T[1][0]*r;
                Tinv[1][1] = T[0][0]*r;
            }
        }
        if (singular)
        {
            FatalErrorInFunction
                << "Degenerate " << shapeName(s) << " cell " << c
                << " (zero volume)" << exit(FatalError);
        }
        for (label j = 0; n == 3 && j < n; ++j)
        {
            scalar A[3][3], r[3] = {0, 0, 0};
            for (label a = 0; a < n; ++a)
                for (label b = 0; b < n; ++b) A[a][b] = T[a][b];
            r[j] = 1;
            if (!smallSolve(n, A, r))
            {
                FatalErrorInFunction
                    << "Degenerate " << shapeName(s) << " cell " << c
                    << " (zero volume)" << exit(FatalError);
            }
            for (label a = 0; a < n; ++a) Tinv[a][j] = r[a];
        }
        scalar lsum = 0;
        vector gsum(Zero);
        for (label j = 0; j < n; ++j)
        {
            scalar l = 0;
            vector g(Zero);
            for (label a = 0; a < n; ++a)
            {
                l += Tinv[j][a]*(x[axes_[a]] - x0[axes_[a]]);
                g[axes_[a]] = Tinv[j][a];
            }
            sv.B[j + 1] = l;
            sv.gradB[j + 1] = g;
            lsum += l;
            gsum += g;
        }
        sv.B[0] = 1 - lsum;
        sv.gradB[0] = -gsum;

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

    // Quad / hex: Newton on the isoparametric map
    const label n = dim_;
    const label nv = sv.n;
    scalar N[8];
    vector dN[8];
    vector xi(0.5, 0.5, n == 3 ? 0.5 : 0);
    scalar J[3][3];
    for (label iter = 0; iter < 30; ++iter)
    {
        multilinear(s, xi, N, dN);
        scalar r[3] = {0, 0, 0};
        for (label a = 0; a < n; ++a)
        {
            for (label b = 0; b < n; ++b) J[a][b] = 0;
        }
        for (label i = 0; i < nv; ++i)
        {
            const vector& xv = vertices_[cv[i]];
            for (label a = 0; a < n; ++a)
            {
                r[a] += N[i]*xv[axes_[a]];
                for (label b = 0; b < n; ++b) J[a][b] += xv[axes_[a]]*dN[i][b];
            }
        }
        scalar res = 0;
        for (label a = 0; a < n; ++a)
        {
            r[a] = x[axes_[a]] - r[a];
            res += r[a]*r[a];
        }
        scalar A[3][3];
        for (label a = 0; a < n; ++a)
            for (label b = 0; b < n; ++b) A[a][b] = J[a][b];
        if (!smallSolve(n, A, r))
        {
            FatalErrorInFunction
                << "Degenerate " << shapeName(s) << " cell " << c
                << " (singular isoparametric map)" << exit(FatalError);
        }
        scalar step = 0;
        for (label a = 0; a < n; ++a)
        {
            // Keep the iterate near the cell: far outside, the map folds
            xi[a] = max(scalar(-2), min(scalar(3), xi[a] + r[a]));
            step = max(step, std::abs(r[a]));
        }
        if (step < 1e-14) break;
    }
    multilinear(s, xi, N, dN);

    // Converged? (Far outside a distorted cell Newton may not be.)
    scalar res2 = 0, size2 = 0;
    {
        vector xr(Zero);
        for (label i = 0; i < nv; ++i) xr += N[i]*vertices_[cv[i]];
        for (label a = 0; a < n; ++a)
        {
            res2 += sqr(xr[axes_[a]] - x[axes_[a]]);
            size2 += sqr(vertices_[cv[nv - 2]][axes_[a]] - vertices_[cv[0]][axes_[a]]);
        }
    }
    const bool converged = res2 <= 1e-20*size2;

    // Jacobian at the solution and gradients grad N = J^-T dN/dxi
    for (label a = 0; a < n; ++a)
        for (label b = 0; b < n; ++b) J[a][b] = 0;
    for (label i = 0; i < nv; ++i)
    {
        const vector& xv = vertices_[cv[i]];
        for (label a = 0; a < n; ++a)
            for (label b = 0; b < n; ++b) J[a][b] += xv[axes_[a]]*dN[i][b];
    }
    for (label i = 0; i < nv; ++i)
    {
        // Solve J^T g = dN/dxi
        scalar A[3][3], r[3];
        for (label a = 0; a < n; ++a)
        {
            for (label b = 0; b < n; ++b) A[a][b] = J[b][a];
            r[a] = dN[i][a];
        }
        smallSolve(n, A, r);
        vector g(Zero);
        for (label a = 0; a < n; ++a) g[axes_[a]] = r[a];
        sv.B[i] = N[i];
        sv.gradB[i] = g;
    }

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


Foam::label Foam::mpmMeshView::findCell(const vector& x, const label start) const
{
    const scalar tol = 1e-12;
    const label nC = nCells();
    if (nC == 0) return -1;

    shapeValues sv;
    label c = (start >= 0 && start < nC) ? start : 0;
    const label maxSteps = 100 + 4*label(std::pow(scalar(nC), 1.0/dim_) + 1);
    for (label step = 0; step < maxSteps; ++step)
    {
        shapeFunctions(c, x, sv);
        if (sv.outside <= tol)
        {
            return c;
        }
        const label n = faceNeighbour(c, sv.exitFace);
        if (n < 0)
        {
            break;
        }
        c = n;
    }

    // The walk ended on the boundary or cycled: search every cell
    for (label d = 0; d < nC; ++d)
    {
        shapeFunctions(d, x, sv);
        if (sv.outside <= tol)
        {
            return d;
        }
    }
    return -1;
}


// ************************************************************************* //
