/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "mlsRingKernel.H"
#include "mlsMoments.H"
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
using namespace Foam::mlsMoments;

enum class supportSize { mean, maxEdge, graded, ring };
const Enum<supportSize> supportSizeNames
({
    { supportSize::mean, "mean" },
    { supportSize::maxEdge, "maxEdge" },
    { supportSize::graded, "graded" },
    { supportSize::ring, "ring" },
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

// The sample weight d_vp's profile over its support radius 1.5 h_v
enum class sampleWeightKind { quadratic, cubic, adaptive };
const Enum<sampleWeightKind> sampleWeightNames
({
    { sampleWeightKind::quadratic, "quadratic" },
    { sampleWeightKind::cubic, "cubic" },
    { sampleWeightKind::adaptive, "adaptive" },
});

// The vertex sizes a graded sizing field starts from
const Enum<supportSize> gradedFromNames
({
    { supportSize::mean, "mean" },
    { supportSize::maxEdge, "maxEdge" },
});

// supportSize ring: 1.5 h_v = the vertex's ring reach, so that its sample
// weight and the weight's gradient vanish on every face where it enters or
// leaves a particle's ring: the weights are then as smooth as the sample
// weight without eta, and their own derivative is continuous
scalarList ringSupports(const mpmMeshView& mesh)
{
    scalarList h(mesh.ringReach());
    const scalarList& own = mesh.vertexMaxEdge();
    scalar lo = GREAT, hi = 0;
    forAll(h, v)
    {
        h[v] = h[v] < GREAT ? h[v]/1.5 : own[v];
        lo = min(lo, h[v]/own[v]);
        hi = max(hi, h[v]/own[v]);
    }
    Info<< "MLS supports: 1.5 h_v = the reach of each vertex's ring, h_v "
        << returnReduce(lo, minOp<scalar>()) << " to "
        << returnReduce(hi, maxOp<scalar>())
        << " times the vertex's longest edge" << endl;
    return h;
}


// The supportSize entry (maxEdge when absent)
supportSize supportSizeOf(const dictionary& dict)
{
    return dictionaryChecks::getEnum
    (
        dict, "supportSize", supportSizeNames, supportSize::maxEdge
    );
}


// h_v of every vertex: its own edges (mean or longest), or the graded
// sizing field over the longest edges (chapter 5: supports that follow
// the mesh's sizes smoothly, never narrower than a vertex's own need)
scalarList supportSizes(const dictionary& dict, const mpmMeshView& mesh)
{
    const supportSize s = supportSizeOf(dict);
    if (s == supportSize::mean) return mesh.vertexSize();
    if (s == supportSize::maxEdge) return mesh.vertexMaxEdge();
    if (s == supportSize::ring) return ringSupports(mesh);

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


// The samples of one particle over its cell's ring: the ring vertices
// inside their support, with d_vp = eta_vp N(r/h_v) (eta only with
// diminish) and the offsets x_v - x_p.  Compiled per number NV of the
// cell's vertices, so that the loops over them unroll.
template<int D>
struct ringSamples
{
    const bool diminish;
    //- Sample weight profile: 0 quadratic, 1 cubic B-spline, 2 the bump
    //  (1 - q^2)^k_v, k_v = power[v]
    const int profile;
    const label* power;
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
            // The bump needs r^2 only; the B-splines r/h_v
            scalar ds, r = 0, rho = 0, t = 0, R2 = 0;
            if (profile == 2)
            {
                R2 = sqr(1.5*hv[v]);
                t = 1 - r2/R2;
                ds = e*Foam::mlsRingKernel::bumpOf(t, power[v]);
            }
            else
            {
                r = std::sqrt(r2);
                rho = r/hv[v];
                ds = e*
                (
                    profile == 0
                  ? Foam::mlsRingKernel::bSpline(rho)
                  : Foam::mlsRingKernel::cubicSpline(rho)
                );
            }
            if (ds == 0) continue;

            if (sdd)
            {
                // e grad N = -e N'(r/h)/(h r) P, finite at r = 0:
                // quadratic 2e/h^2 inside r < h/2; cubic N3(s), s = k r,
                // k = 4/(3h): e k^2 (2 - 1.5 s) inside s < 1; the bump
                // t^k, t = 1 - r^2/R^2: 2k e t^(k-1)/R^2
                scalar c;
                if (profile == 2)
                {
                    c = 2*power[v]*ds/(t*R2);
                }
                else if (profile == 1)
                {
                    const scalar k = 4/(3*hv[v]);
                    const scalar s = k*r;
                    c = s < 1 ? e*k*k*(2 - 1.5*s) : e*k*sqr(2 - s)/(2*r);
                }
                else
                {
                    c = rho < 0.5
                        ? 2*e/(hv[v]*hv[v])
                        : e*(1.5 - rho)/(hv[v]*r);
                }
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
    profile_
    (
        static_cast<int>
        (
            dictionaryChecks::getEnum
            (
                dict, "sampleWeight", sampleWeightNames,
                sampleWeightKind::quadratic
            )
        )
    ),
    ringSupports_(supportSizeOf(dict) == supportSize::ring),
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
    // sampleWeight adaptive: the bump's power from the support and the
    // vertex's mean edge s_v, so that its width follows s_v
    if (profile_ == 2)
    {
        power_.setSize(h_.size());
        label kMax = 0;
        forAll(h_, v)
        {
            power_[v] = max
            (
                label(3),
                label(std::round(1.5*sqr(1.5*h_[v]/mesh.vertexSize()[v])))
            );
            kMax = max(kMax, power_[v]);
        }
        Info<< "MLS sample weights: (1 - (r/1.5 h_v)^2)^k_v, k_v from 3 to "
            << returnReduce(kMax, maxOp<label>()) << endl;
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
    // eta's gradient (gradient derivative with eta) needs grad B; without
    // eta (mlsRing) the cell's shape functions are not needed at all
    const bool etaGradient = gradient_ == 2 && diminish_;

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
        else if (diminish_)
        {
            mesh_.shapeValuesOnly(c, xp, sv);   // eta needs B only
        }
        else
        {
            sv.n = mesh_.cellEnd(c) - mesh_.cellBegin(c);
        }
        scalar xpa[D];
        for (label a = 0; a < D; ++a) xpa[a] = xp[ax[a]];

        const label rb = ringStart[c];
        const label re = ringStart[c + 1];
        const ringSamples<D> rs
        {
            diminish_, profile_, power_.cdata(), sv.B.cdata(),
            ringVertex.cdata() + rb, ringAdj.cdata() + rb, vx.cdata(), ax,
            xpa, support2.cdata(), h.cdata(), sv_, sd, sx, sdd,
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
                << (ringSupports_
                  ? ": with supportSize ring, the ring reach leaves fewer "
                    "than dim + 1 vertices around this point (stretched "
                    "cells); umls (eta) or supportSize maxEdge runs there"
                  : "")
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
