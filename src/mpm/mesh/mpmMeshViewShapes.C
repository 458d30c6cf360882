/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
-------------------------------------------------------------------------------
    mpmMeshView: local coordinates, shape functions and point location
    (the per-particle work; construction is in mpmMeshView.C)
\*---------------------------------------------------------------------------*/

#include "mpmMeshView.H"
#include "mpmMeshShapes.H"
#include "error.H"

#include <algorithm>
#include <limits>

using namespace Foam::mpmMeshShapes;

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

inline void Foam::mpmMeshView::affineLocal
(
    const cellMap& m,
    const vector& x,
    vector& xi
) const
{
    // The sums in the order of the general loop (b over rows, a over the
    // axes), written out per dimension
    xi = Zero;
    if (dim_ == 3)
    {
        const scalar d0 = x[axes_[0]] - m.x0[0];
        const scalar d1 = x[axes_[1]] - m.x0[1];
        const scalar d2 = x[axes_[2]] - m.x0[2];
        for (label b = 0; b < 3; ++b)
        {
            xi[b] = m.A[b][0]*d0 + m.A[b][1]*d1 + m.A[b][2]*d2;
        }
    }
    else if (dim_ == 2)
    {
        const scalar d0 = x[axes_[0]] - m.x0[0];
        const scalar d1 = x[axes_[1]] - m.x0[1];
        xi[0] = m.A[0][0]*d0 + m.A[0][1]*d1;
        xi[1] = m.A[1][0]*d0 + m.A[1][1]*d1;
    }
    else
    {
        xi[0] = m.A[0][0]*(x[axes_[0]] - m.x0[0]);
    }
}


namespace
{

// The multilinear values alone (no derivatives): the products of
// mpmMeshView::multilinear, in its order
inline void multilinearValues
(
    const bool hex,
    const Foam::vector& xi,
    Foam::scalar* N
)
{
    const Foam::scalar a0 = 1 - xi[0], a1 = xi[0];
    const Foam::scalar b0 = 1 - xi[1], b1 = xi[1];
    if (!hex)
    {
        N[0] = a0*b0; N[1] = a1*b0; N[2] = a1*b1; N[3] = a0*b1;
        return;
    }
    const Foam::scalar c0 = 1 - xi[2], c1 = xi[2];
    N[0] = a0*b0*c0; N[1] = a1*b0*c0; N[2] = a1*b1*c0; N[3] = a0*b1*c0;
    N[4] = a0*b0*c1; N[5] = a1*b0*c1; N[6] = a1*b1*c1; N[7] = a0*b1*c1;
}

} // End anonymous namespace


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


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

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
    affineLocal(m, x, xi);
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
    bool converged = true;
    if (mapType_[c] == AFFINE) affineLocal(cellMap_[c], x, xi);
    else converged = isoparametric(c, x, xi);
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
    bool converged = true;
    if (mapType_[c] == AFFINE) affineLocal(m, x, xi);
    else converged = isoparametric(c, x, xi);
    scalar N[8];
    vector dN[8];
    if (gradients) multilinear(s, xi, N, dN);
    else multilinearValues(s == HEX, xi, sv.B.data());

    scalar Jc[3][3];
    const scalar (*Ji)[3] = m.A;
    if (!gradients) {}
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
    for (label step = 0; step < walkSteps_; ++step)
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
