/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "mlsRingKernel.H"
#include "mlsMoments.H"
#include "ringSamples.H"
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
// The linearBlend entry: on by default for ring supports only, whose reach
// can leave fewer than dim + 1 vertices near a point (3D tetrahedra next to
// a wall); in [0, 0.5]
scalar linearBlendOf(const dictionary& dict, const bool ringSupports)
{
    const string allowed("a number 0 <= linearBlend <= 0.5");
    const scalar kappa1 = dictionaryChecks::getAsOrDefault<scalar>
    (
        dict, "linearBlend", ringSupports ? 3e-2 : 0, allowed
    );
    if (!(kappa1 >= 0 && kappa1 <= 0.5))
    {
        dictionaryChecks::badEntry
        (
            dict, "linearBlend", Foam::name(kappa1), allowed
        );
    }
    return kappa1;
}


// (2.22) [w_vp, grad w_vp] = d_vp M^-1 [1 P_v] of the samples, written at
// out[k, k + ns); with dd (gradient heldEta, derivative) the gradient is
// the weights' derivative: + dd_v alpha_v - d_v T q_v (derivativeTerms).
// With q = M^-1 [1 P] (M^-1 symmetric), T q = (T M^-1) [1 P], so each
// axis's gradient is d (M^-1_{a+1} - (T M^-1)_a) . [1 P] + dd_a q_0: the
// rows R_a are formed once per particle, one n-vector product per axis
// and sample
template<int D>
inline void mlsWeights
(
    const label ns,
    const label* __restrict__ sv,
    const scalar* __restrict__ sd,
    const scalar* __restrict__ sx,
    const scalar* __restrict__ sdd,
    const scalar Minv[4][4],
    const label ax[3],
    label* __restrict__ vOut,
    scalar* __restrict__ wOut,
    vector* __restrict__ gOut,
    label& k
)
{
    constexpr label n = D + 1;
    scalar W[n];
    for (label i = 0; i < n; ++i) W[i] = Minv[0][i];
    scalar R[D][n];
    for (label a = 0; a < D; ++a)
        for (label i = 0; i < n; ++i) R[a][i] = Minv[a + 1][i];
    if (sdd)
    {
        scalar T[D][n] = {{0}};
        derivativeTerms<D>(ns, sdd, sx, Minv, T);
        for (label a = 0; a < D; ++a)
        {
            for (label i = 0; i < n; ++i)
            {
                scalar u = 0;
                for (label l = 0; l < n; ++l) u += T[a][l]*Minv[l][i];
                R[a][i] -= u;
            }
        }
    }

    for (label s = 0; s < ns; ++s)
    {
        const scalar* P = sx + D*s;
        scalar q0 = W[0];
        for (label j = 0; j < D; ++j) q0 += W[j + 1]*P[j];
        const scalar ds = sd[s];
        scalar g[D];
        for (label a = 0; a < D; ++a)
        {
            scalar r = R[a][0];
            for (label j = 0; j < D; ++j) r += R[a][j + 1]*P[j];
            g[a] = ds*r;
        }
        if (sdd)
        {
            for (label a = 0; a < D; ++a) g[a] += sdd[D*s + a]*q0;
        }
        vOut[k] = sv[s];
        wOut[k] = ds*q0;
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
    linearBlend_(linearBlendOf(dict, ringSupports_)),
    nEvaluated_(0),
    nBlended_(0),
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
    nEvaluated_ += nP;
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
        const scalar kappa =
            (n == 3) ? invertMoment3(M, Minv)
          : (n == 4) ? invertMoment4(M, Minv)
          : (invertMoment(n, M, Minv) > 0 ? conditioning2(M) : 0);
        scalar dsdl = 0;
        const scalar share = linearShare(kappa, linearBlend_, dsdl);
        if (share == 0 && kappa < 1e-12)
        {
            FatalErrorInFunction
                << type() << " kernel: the moment matrix of the particle at "
                << xp << " in cell " << c << " is singular (its ring of "
                << re - rb << " vertices is degenerate)"
                << (ringSupports_
                  ? ": with supportSize ring, the ring reach leaves fewer "
                    "than dim + 1 vertices around this point (stretched "
                    "cells); a linearBlend > 0 blends into the cell's "
                    "linear weights there"
                  : "; a linearBlend > 0 blends into the cell's linear "
                    "weights there")
                << exit(FatalError);
        }

        const label k0 = k;
        if (share < 1)
        {
            mlsWeights<D>
            (
                ns, sv_, sd, sx, sdd, Minv, ax, vOut, wOut, gOut, k
            );
        }
        if (share > 0)
        {
            scalar gradLogKappa[D] = {0};
            if (sdd && dsdl != 0)
            {
                logConditioningGradient<D>
                (
                    ns, sd, sdd, sx, M, Minv, gradLogKappa
                );
            }
            vector gradShare = Zero;
            for (label a = 0; a < D; ++a)
            {
                gradShare[ax[a]] = dsdl*gradLogKappa[a];
            }
            blendLinear
            (
                c, xp, ringVertex.cdata() + rb, share, gradShare, k0,
                vOut, wOut, gOut, k
            );
            ++nBlended_;
        }
        out.start[p + 1] = k;
    }
    out.vertex.setSize(k);
    out.w.setSize(k);
    out.gradW.setSize(k);
}


// Where the moment matrix is ill-conditioned: the weights [k0, k) blend
// into the cell's linear shape functions N, w = (1 - s) w + s N and
// grad w = (1 - s) grad w + s grad N + (N - w) grad s.  Both reproduce
// linear fields, so the blend does, with its gradient's identities.
void Foam::mlsRingKernel::blendLinear
(
    const label c,
    const vector& xp,
    const label* cellVertex,
    const scalar share,
    const vector& gradShare,
    const label k0,
    label* vOut,
    scalar* wOut,
    vector* gOut,
    label& k
) const
{
    mpmMeshView::shapeValues lin;
    mesh_.shapeFunctions(c, xp, lin);
    for (label j = k0; j < k; ++j)
    {
        gOut[j] = (1 - share)*gOut[j] - wOut[j]*gradShare;
        wOut[j] *= 1 - share;
    }
    // The ring lists the cell's vertices first, in the cell's order
    for (label i = 0; i < lin.n; ++i)
    {
        const label v = cellVertex[i];
        label j = k0;
        while (j < k && vOut[j] != v) ++j;
        if (j == k)
        {
            vOut[k] = v;
            wOut[k] = 0;
            gOut[k] = Zero;
            ++k;
        }
        wOut[j] += share*lin.B[i];
        gOut[j] += share*lin.gradB[i] + lin.B[i]*gradShare;
    }
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


void Foam::mlsRingKernel::report() const
{
    if (linearBlend_ == 0) return;
    const scalar nAll = returnReduce(scalar(nEvaluated_), sumOp<scalar>());
    const scalar nBlend = returnReduce(scalar(nBlended_), sumOp<scalar>());
    Info<< type() << " kernel: " << nBlend << " of " << nAll
        << " particle evaluations ("
        << (nAll > 0 ? 100*nBlend/nAll : 0)
        << " %) blended into linear weights (conditioning below "
        << linearBlend_ << ")" << endl;
}


Foam::scalar Foam::mlsRingKernel::stepLength() const
{
    return *std::min_element(h_.begin(), h_.end());
}


// ************************************************************************* //
