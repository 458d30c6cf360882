/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "mlsRingKernel.H"
#include "addToRunTimeSelectionTable.H"
#include "dictionaryChecks.H"

namespace Foam
{
    defineTypeNameAndDebug(mlsRingKernel, 0);
    addToRunTimeSelectionTable(mpmKernel, mlsRingKernel, dictionary);
}


namespace
{
using namespace Foam;

enum class supportSize { mean, maxEdge };
const Enum<supportSize> supportSizeNames
({
    { supportSize::mean, "mean" },
    { supportSize::maxEdge, "maxEdge" },
});

// Invert the symmetric (n x n, n <= 4) moment matrix M in place by
// Gauss-Jordan elimination with partial pivoting.  Returns the smallest
// pivot relative to the largest diagonal entry (0: singular).
// Closed-form inverse of the symmetric 3 x 3 moment matrix (2D); returns
// |det| relative to the product of the diagonal (0: singular)
scalar invertMoment3(const scalar M[4][4], scalar Minv[4][4])
{
    const scalar c00 = M[1][1]*M[2][2] - M[1][2]*M[1][2];
    const scalar c01 = M[0][2]*M[1][2] - M[0][1]*M[2][2];
    const scalar c02 = M[0][1]*M[1][2] - M[0][2]*M[1][1];
    const scalar det = M[0][0]*c00 + M[0][1]*c01 + M[0][2]*c02;
    const scalar scale = std::abs(M[0][0]*M[1][1]*M[2][2]);
    if (det == 0 || scale == 0) return 0;
    const scalar r = 1/det;
    Minv[0][0] = c00*r;
    Minv[0][1] = Minv[1][0] = c01*r;
    Minv[0][2] = Minv[2][0] = c02*r;
    Minv[1][1] = (M[0][0]*M[2][2] - M[0][2]*M[0][2])*r;
    Minv[1][2] = Minv[2][1] = (M[0][2]*M[0][1] - M[0][0]*M[1][2])*r;
    Minv[2][2] = (M[0][0]*M[1][1] - M[0][1]*M[0][1])*r;
    return std::abs(det)/scale;
}


scalar invertMoment(const label n, scalar M[4][4], scalar Minv[4][4])
{
    scalar A[4][8];
    scalar diagMax = 0;
    for (label i = 0; i < n; ++i)
    {
        diagMax = max(diagMax, std::abs(M[i][i]));
        for (label j = 0; j < n; ++j)
        {
            A[i][j] = M[i][j];
            A[i][n + j] = (i == j);
        }
    }
    scalar minPivot = GREAT;
    for (label k = 0; k < n; ++k)
    {
        label p = k;
        for (label i = k + 1; i < n; ++i)
        {
            if (std::abs(A[i][k]) > std::abs(A[p][k])) p = i;
        }
        const scalar piv = A[p][k];
        minPivot = min(minPivot, std::abs(piv));
        if (piv == 0) return 0;
        if (p != k)
        {
            for (label j = 0; j < 2*n; ++j) std::swap(A[k][j], A[p][j]);
        }
        const scalar inv = 1/piv;
        for (label j = 0; j < 2*n; ++j) A[k][j] *= inv;
        for (label i = 0; i < n; ++i)
        {
            if (i == k) continue;
            const scalar f = A[i][k];
            if (f == 0) continue;
            for (label j = 0; j < 2*n; ++j) A[i][j] -= f*A[k][j];
        }
    }
    for (label i = 0; i < n; ++i)
    {
        for (label j = 0; j < n; ++j) Minv[i][j] = A[i][n + j];
    }
    return diagMax > 0 ? minPivot/diagMax : 0;
}

} // End anonymous namespace


Foam::mlsRingKernel::mlsRingKernel
(
    const dictionary& dict,
    const mpmMeshView& mesh,
    const bool diminish
)
:
    mpmKernel(dict, mesh),
    diminish_(diminish),
    h_
    (
        dictionaryChecks::getEnum
        (
            dict, "supportSize", supportSizeNames, supportSize::maxEdge
        ) == supportSize::mean
      ? mesh.vertexSize() : mesh.vertexMaxEdge()
    ),
    slot_(mesh.nVertices(), -1)
{}


Foam::mlsRingKernel::mlsRingKernel
(
    const dictionary& dict,
    const mpmMeshView& mesh
)
:
    mlsRingKernel(dict, mesh, false)
{}


// (2.22) MLS weights over the 1-ring; with diminish_, sample weights times
// (2.29) eta_vp = sum_{n in N0} B_np A_vn
void Foam::mlsRingKernel::compute
(
    const UList<vector>& x,
    const labelUList& cells,
    kernelWeights& out
) const
{
    out.clear();

    const label dim = mesh_.dim();
    const label n = dim + 1;
    label ax[3] = {0, 0, 0};
    for (label a = 0; a < dim; ++a) ax[a] = mesh_.axis(a);

    const List<vector>& vx = mesh_.vertices();
    const scalarList& h = h_;
    const labelList& cv = mesh_.cellVertices();
    const labelList& nbr = mesh_.vertexNeighbours();

    DynamicList<label>& ring = ring_;
    DynamicList<scalar>& eta = eta_;
    DynamicList<scalar>& d = d_;
    DynamicList<vector>& dx = dx_;
    mpmMeshView::shapeValues sv;

    forAll(x, p)
    {
        const label c = cells[p];
        const vector& xp = x[p];
        mesh_.shapeFunctions(c, xp, sv);

        ring.clear();
        eta.clear();
        auto add = [&](const label v, const scalar e)
        {
            label s = slot_[v];
            if (s < 0)
            {
                s = ring.size();
                slot_[v] = s;
                ring.append(v);
                eta.append(0);
            }
            eta[s] += e;
        };

        // N0 with A_vv = 1, then the edge neighbours: eta accumulates B_n
        // over the cell vertices n adjacent to (or equal to) v
        const label b = mesh_.cellBegin(c);
        for (label i = 0; i < sv.n; ++i)
        {
            add(cv[b + i], sv.B[i]);
        }
        for (label i = 0; i < sv.n; ++i)
        {
            const label v = cv[b + i];
            for (label k = mesh_.vertexBegin(v); k < mesh_.vertexEnd(v); ++k)
            {
                add(nbr[k], sv.B[i]);
            }
        }

        // Sample weights and the moment matrix M = sum d P P^T
        scalar M[4][4] = {{0}};
        d.setSize(ring.size());
        dx.setSize(ring.size());
        forAll(ring, s)
        {
            const label v = ring[s];
            slot_[v] = -1;
            vector P(Zero);
            for (label a = 0; a < dim; ++a) P[a] = vx[v][ax[a]] - xp[ax[a]];
            dx[s] = P;
            const scalar r = mag(P)/h[v];
            const scalar e = diminish_ ? max(eta[s], scalar(0)) : scalar(1);
            d[s] = e*bSpline(r);
            if (d[s] == 0) continue;
            const scalar ds = d[s];
            M[0][0] += ds;
            for (label i = 0; i < dim; ++i)
            {
                M[0][i + 1] += ds*P[i];
                for (label j = 0; j <= i; ++j) M[i + 1][j + 1] += ds*P[i]*P[j];
            }
        }
        // Symmetric: mirror the first row and the position block's lower
        // triangle
        for (label i = 1; i < n; ++i)
        {
            M[i][0] = M[0][i];
            for (label j = 1; j < i; ++j) M[j][i] = M[i][j];
        }

        scalar Minv[4][4];
        const scalar conditioning =
            (n == 3) ? invertMoment3(M, Minv) : invertMoment(n, M, Minv);
        if (conditioning < 1e-12)
        {
            FatalErrorInFunction
                << type() << " kernel: the moment matrix of the particle at "
                << xp << " in cell " << c << " is singular (its ring of "
                << ring.size() << " vertices is degenerate)"
                << exit(FatalError);
        }

        // [w_vp, grad w_vp] = d_vp M^-1 P_v
        forAll(ring, s)
        {
            if (d[s] == 0) continue;
            const label v = ring[s];
            const scalar P[4] = {1, dx[s][0], dx[s][1], dx[s][2]};
            scalar q[4] = {0, 0, 0, 0};
            for (label i = 0; i < n; ++i)
            {
                for (label j = 0; j < n; ++j) q[i] += Minv[i][j]*P[j];
            }
            vector g(Zero);
            for (label a = 0; a < dim; ++a) g[ax[a]] = d[s]*q[a + 1];
            out.append(v, d[s]*q[0], g);
        }
        out.endParticle();
    }
}


// ************************************************************************* //
