/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "mlsRingKernel.H"
#include "addToRunTimeSelectionTable.H"
#include "dictionaryChecks.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"

#include <algorithm>

namespace Foam
{
    defineTypeNameAndDebug(mlsRingKernel, 0);
    addToRunTimeSelectionTable(mpmKernel, mlsRingKernel, dictionary);
}


namespace
{
using namespace Foam;

enum class supportSize { mean, maxEdge, graded };
const Enum<supportSize> supportSizeNames
({
    { supportSize::mean, "mean" },
    { supportSize::maxEdge, "maxEdge" },
    { supportSize::graded, "graded" },
});

// The weights' gradient: the slope of the fit (2.22), the derivative of
// the weights with eta held at its value (continuous across faces), or
// their whole derivative (eta's gradient jumps across faces)
// (the order is gradient_'s: 0, 1, 2)
enum class gradientKind { fit, heldEta, derivative };
const Enum<gradientKind> gradientNames
({
    { gradientKind::fit, "fit" },
    { gradientKind::heldEta, "heldEta" },
    { gradientKind::derivative, "derivative" },
});

// The vertex sizes a graded sizing field starts from
const Enum<supportSize> gradedFromNames
({
    { supportSize::mean, "mean" },
    { supportSize::maxEdge, "maxEdge" },
});

// h_v of every vertex: its own edges (mean or longest), or the graded
// sizing field over the longest edges (chapter 5: supports that follow
// the mesh's sizes smoothly, never narrower than a vertex's own need)
scalarList supportSizes(const dictionary& dict, const mpmMeshView& mesh)
{
    const supportSize s = dictionaryChecks::getEnum
    (
        dict, "supportSize", supportSizeNames, supportSize::maxEdge
    );
    if (s == supportSize::mean) return mesh.vertexSize();
    if (s == supportSize::maxEdge) return mesh.vertexMaxEdge();

    const scalar g =
        dictionaryChecks::getInRange(dict, "supportGradient", 0.25, 0, 1);
    const bool fromMean = dictionaryChecks::getEnum
    (
        dict, "gradedFrom", gradedFromNames, supportSize::maxEdge
    ) == supportSize::mean;
    const scalarList& need =
        fromMean ? mesh.vertexSize() : mesh.vertexMaxEdge();
    scalarList h(mesh.gradedSize(need, g));
    scalar raised = 1;
    forAll(h, v) raised = max(raised, h[v]/need[v]);
    Info<< "MLS supports: graded sizing field over the vertices' "
        << (fromMean ? "mean" : "longest") << " edges, gradient " << g
        << ": h_v up to " << returnReduce(raised, maxOp<scalar>())
        << " times the vertex's own" << endl;
    return h;
}

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


// Inverse of the symmetric 4 x 4 moment matrix (3D) M = [a b^T; b C] by
// its Schur complement S = C - b b^T/a (M is positive semi-definite: d >= 0,
// so no pivoting is needed): M^-1 = [(1 + b.u)/a, -u^T; -u, S^-1] with
// u = S^-1 b/a.  Returns |det M| relative to the product of the diagonal
// (0: singular), as invertMoment3 does.
scalar invertMoment4(const scalar M[4][4], scalar Minv[4][4])
{
    const scalar a = M[0][0];
    if (!(a > 0)) return 0;
    const scalar ra = 1/a;
    const scalar b0 = M[1][0], b1 = M[2][0], b2 = M[3][0];
    const scalar s00 = M[1][1] - b0*b0*ra;
    const scalar s01 = M[2][1] - b1*b0*ra;
    const scalar s02 = M[3][1] - b2*b0*ra;
    const scalar s11 = M[2][2] - b1*b1*ra;
    const scalar s12 = M[3][2] - b2*b1*ra;
    const scalar s22 = M[3][3] - b2*b2*ra;
    const scalar c00 = s11*s22 - s12*s12;
    const scalar c01 = s02*s12 - s01*s22;
    const scalar c02 = s01*s12 - s02*s11;
    const scalar detS = s00*c00 + s01*c01 + s02*c02;
    const scalar scale = std::abs(M[1][1]*M[2][2]*M[3][3]);
    if (detS == 0 || scale == 0) return 0;
    const scalar r = 1/detS;
    const scalar i00 = c00*r, i01 = c01*r, i02 = c02*r;
    const scalar i11 = (s00*s22 - s02*s02)*r;
    const scalar i12 = (s02*s01 - s00*s12)*r;
    const scalar i22 = (s00*s11 - s01*s01)*r;
    const scalar u0 = (i00*b0 + i01*b1 + i02*b2)*ra;
    const scalar u1 = (i01*b0 + i11*b1 + i12*b2)*ra;
    const scalar u2 = (i02*b0 + i12*b1 + i22*b2)*ra;
    Minv[0][0] = (1 + b0*u0 + b1*u1 + b2*u2)*ra;
    Minv[0][1] = Minv[1][0] = -u0;
    Minv[0][2] = Minv[2][0] = -u1;
    Minv[0][3] = Minv[3][0] = -u2;
    Minv[1][1] = i00;
    Minv[1][2] = Minv[2][1] = i01;
    Minv[1][3] = Minv[3][1] = i02;
    Minv[2][2] = i11;
    Minv[2][3] = Minv[3][2] = i12;
    Minv[3][3] = i22;
    // det M = a det S; the diagonal's product a M11 M22 M33
    return std::abs(detS)/scale;
}


// Invert the symmetric (n x n, n <= 4) moment matrix M by Gauss-Jordan
// elimination with partial pivoting.  Returns the smallest pivot relative to
// the largest diagonal entry (0: singular).
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

// The three edge neighbours in a hexahedron of its vertex i (ascending),
// and the adjacency mask of that vertex in its own cell's ring: itself
// and those three
constexpr unsigned char hexOthers[8][3] =
{
    {1, 3, 4}, {0, 2, 5}, {1, 3, 6}, {0, 2, 7},
    {0, 5, 7}, {1, 4, 6}, {2, 5, 7}, {3, 4, 6}
};

constexpr unsigned hexMask(const label i)
{
    return (1u << i) | (1u << hexOthers[i][0]) | (1u << hexOthers[i][1])
      | (1u << hexOthers[i][2]);
}

const unsigned hexCellMask[8] =
{
    hexMask(0), hexMask(1), hexMask(2), hexMask(3),
    hexMask(4), hexMask(5), hexMask(6), hexMask(7)
};


// The derivative of w_vp = d_vp (M^-1 [1, P_v])_0 in x_p with eta held,
// P_v = x_v - x_p: d/dx_a of d_v, of M (through d_u and P_u) and of P_v
// give, after sum_u d_u P_u = M e_0 cancels two of the terms,
//     dw_v/dx_a = d_v q_v,a+1 + dd_v,a alpha_v - d_v T_a . q_v
// with q_v = M^-1 [1, P_v], alpha_v = q_v,0 and
//     T_a = sum_u dd_u,a alpha_u [1, P_u], dd_u = grad_xp d_u.
// The first term is the fit's slope (2.22); the others make the gradient
// the weights' own, so that sum_p V_p grad w_vp integrates to the
// boundary on any mesh (the fit's slope does only where the ring is
// symmetric: on irregular meshes the bar's frequency then stays off by
// ~0.5 % however fine the mesh).  Holding eta keeps the gradient
// continuous where particles cross faces; the identities hold for any
// fixed sample weights, so they hold for it.  With eta's own gradient in
// dd_u (gradient derivative) the same formula is the whole derivative.
template<int D>
inline void derivativeTerms
(
    const label ns,
    const scalar* __restrict__ dd,
    const scalar* __restrict__ dx,
    const scalar Minv[4][4],
    scalar T[D][D + 1]
)
{
    constexpr label n = D + 1;
    for (label a = 0; a < D; ++a)
        for (label i = 0; i < n; ++i) T[a][i] = 0;
    for (label s = 0; s < ns; ++s)
    {
        const scalar* P = dx + D*s;
        scalar alpha = Minv[0][0];
        for (label j = 0; j < D; ++j) alpha += Minv[0][j + 1]*P[j];
        for (label a = 0; a < D; ++a)
        {
            const scalar c = dd[D*s + a]*alpha;
            T[a][0] += c;
            for (label j = 0; j < D; ++j) T[a][j + 1] += c*P[j];
        }
    }
}


// Moment matrix M = sum_s d_s P_s P_s^T, P_s = [1, x_v - x_p] (dx: D per
// sample), summed over the samples in order
template<int D>
inline void momentMatrix
(
    const label ns,
    const scalar* __restrict__ d,
    const scalar* __restrict__ dx,
    scalar M[4][4]
)
{
    constexpr label n = D + 1;
    scalar m[n][n];
    for (label i = 0; i < n; ++i)
        for (label j = 0; j < n; ++j) m[i][j] = 0;
    for (label s = 0; s < ns; ++s)
    {
        const scalar ds = d[s];
        const scalar* P = dx + D*s;
        m[0][0] += ds;
        for (label i = 0; i < D; ++i)
        {
            m[0][i + 1] += ds*P[i];
            for (label j = 0; j <= i; ++j) m[i + 1][j + 1] += ds*P[i]*P[j];
        }
    }
    for (label i = 0; i < n; ++i)
    {
        for (label j = i; j < n; ++j)
        {
            const scalar mij = (i == 0 || j == 0) ? m[0][max(i, j)] : m[j][i];
            M[i][j] = M[j][i] = mij;
        }
    }
}


// The samples of one particle over its cell's ring: the ring vertices
// inside their support, with d_vp = eta_vp N(r/h_v) (eta only with
// diminish) and the offsets x_v - x_p.  Compiled per number NV of the
// cell's vertices, so that the loops over them unroll.
template<int D>
struct ringSamples
{
    const bool diminish;
    const scalar* B;            //!< shape values of the cell's vertices
    const label* ringVertex;    //!< the ring (cell vertices first)
    const unsigned char* ringAdj;
    const vector* vx;
    const label* ax;
    const scalar* xpa;
    const scalar* support2;
    const scalar* h;
    label* __restrict__ sv;
    scalar* __restrict__ sd;
    scalar* __restrict__ sx;
    //- Where not null: grad_xp d_s (D per sample), with eta held or, where
    //  gradB is not null, with eta's own gradient
    scalar* __restrict__ sdd;
    const vector* gradB;

    // (2.29) eta_vp = sum_{n in N0} B_np A_vn, the set bits of the mask
    // visited lowest first (the sums of a scan over the cell's vertices);
    // subset sums when NV <= 4
    template<int NV>
    label gather(const label nRing) const
    {
        scalar subset[16];
        if (NV <= 4 && diminish)
        {
            subset[0] = 0;
            for (label i = 0; i < NV; ++i)
            {
                const label m0 = 1 << i;
                for (label m = 0; m < m0; ++m) subset[m0 + m] = subset[m] + B[i];
            }
        }

        // Locals: the stores below cannot change them
        scalar xp[D];
        label axis[D];
        for (label a = 0; a < D; ++a)
        {
            xp[a] = xpa[a];
            // The axes of a 3D view are x, y, z (checked at construction)
            axis[a] = (D == 3) ? a : ax[a];
        }
        const label* __restrict__ ring = ringVertex;
        const unsigned char* __restrict__ adj = ringAdj;
        const vector* __restrict__ xv = vx;
        const scalar* __restrict__ s2 = support2;
        const scalar* __restrict__ hv = h;
        label* __restrict__ svOut = sv;
        scalar* __restrict__ sdOut = sd;
        scalar* __restrict__ sxOut = sx;

        label ns = 0;
        for (label s = 0; s < nRing; ++s)
        {
            const label v = ring[s];
            scalar P[D];
            for (label a = 0; a < D; ++a) P[a] = xv[v][axis[a]] - xp[a];
            // |P|^2 summed from the first axis (no leading 0 +: the same
            // sum, one add fewer)
            scalar r2 = P[0]*P[0];
            for (label a = 1; a < D; ++a) r2 += P[a]*P[a];
            // Outside the support: d = 0 (support2 has slack for round-off)
            if (r2 >= s2[v]) continue;

            scalar e = 1;
            if (diminish)
            {
                const unsigned mask = adj[s];
                if (NV == 8 && s < NV && mask == hexCellMask[s])
                {
                    // A vertex of a hexahedron and its three neighbours
                    // in it: the sum below, unrolled
                    const unsigned char* o = hexOthers[s];
                    e = B[s] + B[o[0]] + B[o[1]] + B[o[2]];
                }
                else if (s < NV)
                {
                    // A cell vertex: its own B first, then the others
                    e = B[s];
                    for (unsigned m = mask & ~(1u << s); m; m &= m - 1)
                    {
                        e += B[__builtin_ctz(m)];
                    }
                }
                else if (NV <= 4)
                {
                    e = subset[mask];
                }
                else
                {
                    e = 0;
                    for (unsigned m = mask; m; m &= m - 1)
                    {
                        e += B[__builtin_ctz(m)];
                    }
                }
                e = max(e, scalar(0));
            }
            const scalar r = std::sqrt(r2);
            const scalar ds = e*Foam::mlsRingKernel::bSpline(r/hv[v]);
            if (ds == 0) continue;

            if (sdd)
            {
                // e grad N = -e N'(r/h)/(h r) P: 2e/h^2 inside r < h/2,
                // finite at r = 0
                const scalar rho = r/hv[v];
                const scalar c = rho < 0.5
                    ? 2*e/(hv[v]*hv[v])
                    : e*(1.5 - rho)/(hv[v]*r);
                for (label a = 0; a < D; ++a) sdd[D*ns + a] = c*P[a];
                if (gradB && diminish && e > 0)
                {
                    // + N grad eta, grad eta = sum over the mask of grad B
                    const scalar Nv = ds/e;
                    for (unsigned m = adj[s]; m; m &= m - 1)
                    {
                        const vector& gB = gradB[__builtin_ctz(m)];
                        for (label a = 0; a < D; ++a)
                        {
                            sdd[D*ns + a] += Nv*gB[axis[a]];
                        }
                    }
                }
            }
            svOut[ns] = v;
            sdOut[ns] = ds;
            for (label a = 0; a < D; ++a) sxOut[D*ns + a] = P[a];
            ++ns;
        }
        return ns;
    }
};

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
    gradient_
    (
        static_cast<int>
        (
            dictionaryChecks::getEnum
            (
                dict, "gradient", gradientNames, gradientKind::fit
            )
        )
    ),
    h_(supportSizes(dict, mesh)),
    support2_(h_.size()),
    rings_(mesh),
    sampleVertex_(rings_.maxSize),
    sampleD_(rings_.maxSize),
    sampleDx_(mesh.dim()*rings_.maxSize),
    sampleDD_(gradient_ == 0 ? 0 : mesh.dim()*rings_.maxSize)
{
    // bSpline(r) = 0 for r >= 1.5: the slack keeps every vertex with
    // |x_v - x_p|/h_v < 1.5 despite round-off in the squares
    forAll(h_, v)
    {
        support2_[v] = sqr(1.5*h_[v])*(1 + 1e-10);
    }
    // computeDim<3> writes the gradients as (x y z)
    if
    (
        mesh.dim() == 3
     && (mesh.axis(0) != 0 || mesh.axis(1) != 1 || mesh.axis(2) != 2)
    )
    {
        FatalErrorInFunction
            << "3D mesh view with solution axes (" << mesh.axis(0) << ' '
            << mesh.axis(1) << ' ' << mesh.axis(2) << "), not (0 1 2)"
            << exit(FatalError);
    }
}


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
template<int D>
void Foam::mlsRingKernel::computeDim
(
    const UList<vector>& x,
    const labelUList& cells,
    kernelWeights& out
) const
{
    constexpr label n = D + 1;
    label ax[3] = {0, 0, 0};
    for (label a = 0; a < D; ++a) ax[a] = mesh_.axis(a);

    const List<vector>& vx = mesh_.vertices();
    const scalarList& h = h_;
    const scalarList& support2 = support2_;
    const labelList& ringStart = rings_.start;
    const labelList& ringVertex = rings_.vertex;
    const List<unsigned char>& ringAdj = rings_.adjacent;

    // The rings bound the weights: room for all, written in place
    const label nP = x.size();
    label bound = 0;
    for (label p = 0; p < nP; ++p) bound += rings_.size(cells[p]);
    out.start.setSize(nP + 1);
    out.vertex.setSize(bound);
    out.w.setSize(bound);
    out.gradW.setSize(bound);
    label* __restrict__ vOut = out.vertex.data();
    scalar* __restrict__ wOut = out.w.data();
    vector* __restrict__ gOut = out.gradW.data();

    // One particle's sample weights d_vp and offsets x_v - x_p
    label* __restrict__ sv_ = sampleVertex_.data();
    scalar* __restrict__ sd = sampleD_.data();
    scalar* __restrict__ sx = sampleDx_.data();
    scalar* __restrict__ sdd = gradient_ == 0 ? nullptr : sampleDD_.data();
    const bool etaGradient = gradient_ == 2;

    mpmMeshView::shapeValues sv;
    label k = 0;
    out.start[0] = 0;
    for (label p = 0; p < nP; ++p)
    {
        const label c = cells[p];
        const vector& xp = x[p];
        if (etaGradient)
        {
            mesh_.shapeFunctions(c, xp, sv);
        }
        else
        {
            mesh_.shapeValuesOnly(c, xp, sv);   // eta needs B only
        }
        scalar xpa[D];
        for (label a = 0; a < D; ++a) xpa[a] = xp[ax[a]];

        const label rb = ringStart[c];
        const label re = ringStart[c + 1];
        const ringSamples<D> rs
        {
            diminish_, sv.B.cdata(), ringVertex.cdata() + rb,
            ringAdj.cdata() + rb, vx.cdata(), ax, xpa, support2.cdata(),
            h.cdata(), sv_, sd, sx, sdd,
            etaGradient ? sv.gradB.cdata() : nullptr
        };
        label ns = 0;
        switch (sv.n)
        {
            case 2: ns = rs.template gather<2>(re - rb); break;
            case 3: ns = rs.template gather<3>(re - rb); break;
            case 4: ns = rs.template gather<4>(re - rb); break;
            default: ns = rs.template gather<8>(re - rb); break;
        }

        scalar M[4][4];
        momentMatrix<D>(ns, sd, sx, M);

        scalar Minv[4][4] = {{0}};
        const scalar conditioning =
            (n == 3) ? invertMoment3(M, Minv)
          : (n == 4) ? invertMoment4(M, Minv)
          : invertMoment(n, M, Minv);
        if (conditioning < 1e-12)
        {
            FatalErrorInFunction
                << type() << " kernel: the moment matrix of the particle at "
                << xp << " in cell " << c << " is singular (its ring of "
                << re - rb << " vertices is degenerate)"
                << exit(FatalError);
        }

        // [w_vp, grad w_vp] = d_vp M^-1 P_v, column by column (the
        // transpose makes the sums over j contiguous: vectorised)
        scalar MinvT[n][n];
        for (label i = 0; i < n; ++i)
            for (label j = 0; j < n; ++j) MinvT[j][i] = Minv[i][j];

        // gradient heldEta, derivative: T_a = sum_u dd_u,a alpha_u [1, P_u],
        // alpha_u = (M^-1 [1, P_u])_0 (see derivativeTerms)
        scalar T[D][n];
        if (sdd) derivativeTerms<D>(ns, sdd, sx, Minv, T);

        for (label s = 0; s < ns; ++s)
        {
            const scalar* P = sx + D*s;
            scalar q[n];
            for (label i = 0; i < n; ++i) q[i] = MinvT[0][i];
            for (label j = 0; j < D; ++j)
            {
                for (label i = 0; i < n; ++i) q[i] += MinvT[j + 1][i]*P[j];
            }
            const scalar ds = sd[s];
            scalar g[D];
            for (label a = 0; a < D; ++a) g[a] = ds*q[a + 1];
            if (sdd)
            {
                for (label a = 0; a < D; ++a)
                {
                    scalar Tq = 0;
                    for (label i = 0; i < n; ++i) Tq += T[a][i]*q[i];
                    g[a] += sdd[D*s + a]*q[0] - ds*Tq;
                }
            }
            vOut[k] = sv_[s];
            wOut[k] = ds*q[0];
            if (D == 3)
            {
                // The solution axes of a 3D mesh are x, y, z
                gOut[k] = vector(g[0], g[1], g[2]);
            }
            else
            {
                vector& gk = gOut[k];
                gk = Zero;
                for (label a = 0; a < D; ++a) gk[ax[a]] = g[a];
            }
            ++k;
        }
        out.start[p + 1] = k;
    }
    out.vertex.setSize(k);
    out.w.setSize(k);
    out.gradW.setSize(k);
}


void Foam::mlsRingKernel::compute
(
    const UList<vector>& x,
    const labelUList& cells,
    kernelWeights& out
) const
{
    switch (mesh_.dim())
    {
        case 1: computeDim<1>(x, cells, out); break;
        case 2: computeDim<2>(x, cells, out); break;
        default: computeDim<3>(x, cells, out); break;
    }
}


Foam::scalar Foam::mlsRingKernel::stepLength() const
{
    return *std::min_element(h_.begin(), h_.end());
}


// ************************************************************************* //
