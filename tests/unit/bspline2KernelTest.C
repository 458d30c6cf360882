// Unit tests of the quadratic B-spline kernel bspline2 (3.32) on uniform
// Cartesian lattices:
//  - the weights are the tensor product of N2 in the interior
//  - partition of unity and linear reproduction (sum w = 1, sum w x_v = x_p,
//    sum grad w = 0, sum x_v grad w^T = I) to round-off at random points of
//    the whole mesh, boundary half-cells included (the fold), 1D, 2D, 3D,
//    anisotropic spacing, shifted origin, a 2D mesh in the x-z plane
//  - the boundary fold: linear interpolation within half a cell of the end
//  - C1: w and grad w continuous across faces, across the midpoints where
//    the stencil shifts, and where the fold starts (linear jumps: the check
//    can fail)
//  - a lattice with a notch (holes): sum w = 1 and sum grad w = 0 still
//  - APIC next to the notch (where the weights do not reproduce linear
//    functions): P2G/G2P round trips of a uniform velocity keep the
//    momentum and the kinetic energy to round-off (before the moments were
//    taken about the weights' centre the momentum grew every trip)
//  - APIC at the lattice's end: the fold's D_p vanishes at the end node,
//    and a particle that took B at half a cell from it and nears it gives
//    the grid bounded velocities only with the kernel's momentFloor
//    (without it, 1e8 times the field's)
//  - graded, perturbed, simplex and one-cell-thick meshes stop with a
//    FatalIOError naming the entry kernel and the first offending cell

#include "testMeshes.H"
#include "bspline2Kernel.H"
#include "mpmTransfer.H"
#include "mpmParticles.H"
#include "mpmGrid.H"
#include "IStringStream.H"

#include <gtest/gtest.h>
#include <functional>
#include <map>
#include <cstdio>

using namespace Foam;

namespace
{

autoPtr<mpmKernel> kernel(const word& name, const mpmMeshView& m)
{
    IStringStream is("kernel " + name + ";");
    const dictionary d(is);
    return mpmKernel::New(d, m);
}

// A lattice of n[a] cells of size h[a] along the solution axes axes[a]
// (a < dim), from origin; cells where keep(i, j, k) is false are left
// out, and so are the vertices of no cell
std::unique_ptr<mpmMeshView> lattice
(
    label dim,
    FixedList<label, 3> axes,
    const label n[3],
    const scalar h[3],
    const vector& origin,
    std::function<bool(label, label, label)> keep =
        [](label, label, label) { return true; }
)
{
    const label N0 = n[0] + 1;
    const label N1 = dim > 1 ? n[1] + 1 : 1;
    const label N2 = dim > 2 ? n[2] + 1 : 1;
    auto id = [&](label i, label j, label k) { return i + N0*(j + N1*k); };
    labelList vertexOf(N0*N1*N2, -1);
    DynamicList<vector> v;
    DynamicList<mpmMeshView::shapeType> s;
    DynamicList<label> start{0}, cv;
    auto vert = [&](label i, label j, label k)
    {
        label& r = vertexOf[id(i, j, k)];
        if (r < 0)
        {
            r = v.size();
            vector x(origin);
            x[axes[0]] += i*h[0];
            if (dim > 1) x[axes[1]] += j*h[1];
            if (dim > 2) x[axes[2]] += k*h[2];
            v.append(x);
        }
        return r;
    };
    for (label k = 0; k < (dim > 2 ? n[2] : 1); ++k)
        for (label j = 0; j < (dim > 1 ? n[1] : 1); ++j)
            for (label i = 0; i < n[0]; ++i)
            {
                if (!keep(i, j, k)) continue;
                if (dim == 1)
                {
                    s.append(mpmMeshView::SEGMENT);
                    cv.append({vert(i, 0, 0), vert(i + 1, 0, 0)});
                }
                else if (dim == 2)
                {
                    s.append(mpmMeshView::QUAD);
                    cv.append({vert(i, j, 0), vert(i + 1, j, 0),
                               vert(i + 1, j + 1, 0), vert(i, j + 1, 0)});
                }
                else
                {
                    s.append(mpmMeshView::HEX);
                    cv.append
                    ({
                        vert(i, j, k), vert(i + 1, j, k),
                        vert(i + 1, j + 1, k), vert(i, j + 1, k),
                        vert(i, j, k + 1), vert(i + 1, j, k + 1),
                        vert(i + 1, j + 1, k + 1), vert(i, j + 1, k + 1)
                    });
                }
                start.append(cv.size());
            }
    return std::unique_ptr<mpmMeshView>
    (
        new mpmMeshView(dim, axes, List<vector>(v), List<mpmMeshView::shapeType>(s),
            labelList(start), labelList(cv))
    );
}

struct weightsAt
{
    std::map<label, std::pair<scalar, vector>> wv;
    label n = 0;
    scalar wMax = 0;
    scalar gMax = 0;
};

weightsAt evaluate(const mpmKernel& k, const vector& x, label guess = 0)
{
    const mpmMeshView& m = k.mesh();
    const label c = m.findCell(x, guess);
    EXPECT_GE(c, 0) << "point " << x << " not found";
    kernelWeights kw;
    k.compute(List<vector>(1, x), labelList(1, max(c, label(0))), kw);
    weightsAt r;
    r.n = kw.start[1] - kw.start[0];
    for (label i = kw.start[0]; i < kw.start[1]; ++i)
    {
        // (vector's default constructor does not zero it)
        auto& e = r.wv.emplace
        (
            kw.vertex[i], std::make_pair(0.0, vector::zero)
        ).first->second;
        e.first += kw.w[i];
        e.second += kw.gradW[i];
        r.wMax = max(r.wMax, std::abs(kw.w[i]));
        r.gMax = max(r.gMax, mag(kw.gradW[i]));
    }
    return r;
}

// Largest changes of w and grad w between two evaluations, relative to
// their magnitudes
std::pair<scalar, scalar> jump(const weightsAt& a, const weightsAt& b)
{
    std::map<label, std::pair<scalar, vector>> all = a.wv;
    for (const auto& e : b.wv) all.emplace(e.first, std::make_pair(0.0, vector::zero));
    scalar dw = 0, dg = 0;
    for (const auto& e : all)
    {
        const auto ia = a.wv.find(e.first);
        const auto ib = b.wv.find(e.first);
        const scalar wa = ia == a.wv.end() ? 0 : ia->second.first;
        const scalar wb = ib == b.wv.end() ? 0 : ib->second.first;
        const vector ga = ia == a.wv.end() ? vector::zero : ia->second.second;
        const vector gb = ib == b.wv.end() ? vector::zero : ib->second.second;
        dw = max(dw, std::abs(wa - wb));
        dg = max(dg, mag(ga - gb));
    }
    return {dw/max(a.wMax, b.wMax), dg/max(a.gMax, b.gMax)};
}

// The identities at x (over the solution axes); returns min w.  Linear
// reproduction only if 'linear' (not on lattices with holes)
scalar checkIdentities
(
    const mpmKernel& k,
    const vector& x,
    const std::string& what,
    bool linear = true
)
{
    const mpmMeshView& m = k.mesh();
    const weightsAt r = evaluate(k, x);
    scalar sw = 0, wmin = GREAT, hMin = GREAT;
    vector swx(Zero), sg(Zero);
    tensor sxg(Zero);
    for (const auto& e : r.wv)
    {
        const vector& xv = m.vertices()[e.first];
        sw += e.second.first;
        swx += e.second.first*xv;
        sg += e.second.second;
        sxg += xv*e.second.second;
        wmin = min(wmin, e.second.first);
        hMin = min(hMin, m.vertexSize()[e.first]);
    }
    EXPECT_NEAR(sw, 1, 1e-12) << what << " at " << x;
    for (label a = 0; a < m.dim(); ++a)
    {
        const label i = m.axis(a);
        // Gradients are O(1/h): sums of them to 1e-12/h
        EXPECT_NEAR(sg[i]*hMin, 0, 1e-12) << what << " at " << x;
        if (!linear) continue;
        EXPECT_NEAR(swx[i], x[i], 1e-12*(1 + mag(x))) << what << " at " << x;
        for (label b = 0; b < m.dim(); ++b)
        {
            const label j = m.axis(b);
            EXPECT_NEAR(sxg(i, j), i == j ? 1 : 0, 1e-11*(1 + mag(x)/hMin))
                << what << " at " << x << " component " << i << j;
        }
    }
    return wmin;
}

// Random points in the box [lo, hi] over the given axes
std::vector<vector> samples
(
    label dim,
    const FixedList<label, 3>& axes,
    const vector& lo,
    const vector& hi,
    label n,
    unsigned seed
)
{
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<vector> p;
    for (label i = 0; i < n; ++i)
    {
        vector x(lo);
        for (label a = 0; a < dim; ++a)
        {
            const label d = axes[a];
            x[d] = lo[d] + u(gen)*(hi[d] - lo[d]);
        }
        p.push_back(x);
    }
    return p;
}

struct latticeCase
{
    std::string name;
    label dim;
    FixedList<label, 3> axes;
    label n[3];
    scalar h[3];
    vector origin;
};

std::vector<latticeCase> latticeCases()
{
    return
    {
        {"1D", 1, {0, 1, 2}, {9, 1, 1}, {0.5, 1, 1}, vector(-2, 0, 0)},
        {"1D two cells", 1, {0, 1, 2}, {2, 1, 1}, {1, 1, 1}, vector(0, 0, 0)},
        {"2D x-y", 2, {0, 1, 2}, {7, 5, 1}, {0.3, 0.7, 1}, vector(1, -3, 0.5)},
        {"2D x-z", 2, {0, 2, 1}, {6, 4, 1}, {0.25, 0.4, 1}, vector(0, 0.1, 2)},
        {"3D", 3, {0, 1, 2}, {5, 4, 6}, {0.2, 0.35, 0.15}, vector(-0.5, 0.25, 3)},
    };
}

vector corner(const latticeCase& lc, bool high)
{
    vector x(lc.origin);
    if (high)
    {
        for (label a = 0; a < lc.dim; ++a) x[lc.axes[a]] += lc.n[a]*lc.h[a];
    }
    return x;
}

} // End anonymous namespace


// In the interior the weights are the tensor product of (3.32), with
// 3^dim entries per particle
TEST(bspline2Kernel, tensorProductOfN2)
{
    const label n[3] = {6, 6, 6};
    const scalar h[3] = {0.5, 0.25, 2};
    auto m = lattice(3, {0, 1, 2}, n, h, vector(1, 2, 3));
    auto k = kernel("bspline2", *m);
    for (const vector& x : samples(3, {0, 1, 2}, vector(2, 2.5, 7), vector(3.5, 3, 13), 50, 5))
    {
        const weightsAt r = evaluate(*k, x);
        EXPECT_EQ(r.n, 27);
        for (const auto& e : r.wv)
        {
            const vector& xv = m->vertices()[e.first];
            scalar w = 1;
            vector g(Zero);
            scalar N[3], dN[3];
            for (label d = 0; d < 3; ++d)
            {
                const scalar r = (x[d] - xv[d])/h[d];
                N[d] = bspline2::N(r);
                dN[d] = bspline2::dN(r)/h[d];
                w *= N[d];
            }
            g = vector(dN[0]*N[1]*N[2], N[0]*dN[1]*N[2], N[0]*N[1]*dN[2]);
            EXPECT_NEAR(e.second.first, w, 1e-14) << x;
            EXPECT_LT(mag(e.second.second - g), 1e-13) << x;
        }
    }
}


// Identities at random points of the whole mesh, boundary half-cells
// included; weights never negative
TEST(bspline2Kernel, partitionOfUnityAndLinearReproduction)
{
    for (const latticeCase& lc : latticeCases())
    {
        auto m = lattice(lc.dim, lc.axes, lc.n, lc.h, lc.origin);
        auto k = kernel("bspline2", *m);
        const vector lo = corner(lc, false), hi = corner(lc, true);
        scalar wmin = GREAT;
        std::vector<vector> pts = samples(lc.dim, lc.axes, lo, hi, 400, 3);
        // The corners and the ends themselves
        pts.push_back(lo);
        pts.push_back(hi);
        for (const vector& x : pts)
        {
            wmin = min(wmin, checkIdentities(*k, x, "bspline2 " + lc.name));
            EXPECT_EQ(evaluate(*k, x).n, label(std::pow(3, lc.dim)));
        }
        std::cout << "  " << lc.name << ": min w = " << wmin << std::endl;
        EXPECT_GE(wmin, 0) << lc.name;
    }
}


// Within half a cell of an end the two end nodes carry the weights of
// linear interpolation (1 - s, s) and the gradient +-1/h (the fold)
TEST(bspline2Kernel, boundaryFoldIsLinearInterpolation)
{
    const label n[3] = {8, 1, 1};
    const scalar h[3] = {0.5, 1, 1};
    auto m = lattice(1, {0, 1, 2}, n, h, vector(1, 0, 0));
    auto k = kernel("bspline2", *m);
    for (const scalar s : {0.0, 0.1, 0.3, 0.49})
    {
        // Low end: nodes at x = 1 and 1.5; high end: x = 5 and 4.5
        for (const bool high : {false, true})
        {
            const scalar x = high ? 5 - s*0.5 : 1 + s*0.5;
            const weightsAt r = evaluate(*k, vector(x, 0, 0));
            scalar wEnd = 0, wNext = 0, gEnd = 0, others = 0;
            for (const auto& e : r.wv)
            {
                const scalar xv = m->vertices()[e.first].x();
                if (std::abs(xv - (high ? 5 : 1)) < 1e-12)
                {
                    wEnd = e.second.first;
                    gEnd = e.second.second.x();
                }
                else if (std::abs(xv - (high ? 4.5 : 1.5)) < 1e-12)
                {
                    wNext = e.second.first;
                }
                else
                {
                    others += std::abs(e.second.first) + std::abs(e.second.second.x());
                }
            }
            EXPECT_NEAR(wEnd, 1 - s, 1e-14) << s << (high ? " high" : " low");
            EXPECT_NEAR(wNext, s, 1e-14) << s << (high ? " high" : " low");
            EXPECT_NEAR(gEnd, high ? 2 : -2, 1e-13) << s;
            EXPECT_EQ(others, 0) << s;
        }
    }
}


// C1: w and grad w across faces (integer lattice coordinate), midpoints
// (half-integer: the stencil shifts) and where the fold starts (1/2 and
// n - 1/2), crossing by 2e-9 of a cell along each axis, the other
// coordinates random: changes < 1e-6 of the magnitudes (a C1 function
// changes by O(1e-8): |N''| <= 2; round-off O(1e-15/2e-9) = 1e-6 is not
// reached either: measured 8e-9); the linear kernel's gradient
// jumps by O(1) across the same faces
TEST(bspline2Kernel, C1AcrossFacesAndStencilShifts)
{
    std::mt19937 gen(17);
    std::uniform_real_distribution<double> u(0, 1);
    for (const latticeCase& lc : latticeCases())
    {
        auto m = lattice(lc.dim, lc.axes, lc.n, lc.h, lc.origin);
        auto k = kernel("bspline2", *m);
        auto lin = kernel("linear", *m);
        scalar maxW = 0, maxG = 0, linG = 0;
        label nCross = 0;
        for (label a = 0; a < lc.dim; ++a)
        {
            const label d = lc.axes[a];
            for (label twice = 1; twice < 2*lc.n[a]; ++twice)
            {
                const scalar s = 0.5*twice;   // faces and midpoints
                vector x(lc.origin);
                for (label b = 0; b < lc.dim; ++b)
                {
                    x[lc.axes[b]] += u(gen)*lc.n[b]*lc.h[b];
                }
                x[d] = lc.origin[d] + s*lc.h[a];
                vector dx(Zero);
                dx[d] = 1e-9*lc.h[a];
                const auto j = jump(evaluate(*k, x - dx), evaluate(*k, x + dx));
                maxW = max(maxW, j.first);
                maxG = max(maxG, j.second);
                if (twice % 2 == 0)
                {
                    const auto jl =
                        jump(evaluate(*lin, x - dx), evaluate(*lin, x + dx));
                    linG = max(linG, jl.second);
                }
                ++nCross;
            }
        }
        std::cout << "  " << lc.name << ": " << nCross << " crossings, max"
                  << " jump w " << maxW << ", grad w " << maxG
                  << "; linear grad w " << linG << std::endl;
        EXPECT_LT(maxW, 1e-6) << lc.name;
        EXPECT_LT(maxG, 1e-6) << lc.name;
        EXPECT_GT(linG, 0.1) << lc.name;
    }
}


// A lattice with a notch (2D: the corner 3 x 2 cells out; 3D: a 2 x 2 x 2
// block out): the nodes inside the notch have no vertex; sum w = 1 and
// sum grad w = 0 still hold (renormalised); in a box every node has one
TEST(bspline2Kernel, latticeWithNotch)
{
    {
        const label n[3] = {8, 6, 1};
        const scalar h[3] = {0.5, 0.5, 1};
        auto box = lattice(2, {0, 1, 2}, n, h, vector::zero);
        auto kb = kernel("bspline2", *box);
        EXPECT_TRUE(dynamic_cast<const bspline2Kernel&>(*kb).complete());
        EXPECT_EQ(dynamic_cast<const bspline2Kernel&>(*kb).latticeVertex().size(), 9*7);

        auto notched = lattice(2, {0, 1, 2}, n, h, vector::zero,
            [](label i, label j, label) { return !(i >= 5 && j >= 4); });
        auto k = kernel("bspline2", *notched);
        const bspline2Kernel& bk = dynamic_cast<const bspline2Kernel&>(*k);
        EXPECT_FALSE(bk.complete());
        // The node (7, 5) lies inside the notch; (4, 3) is a vertex
        EXPECT_EQ(bk.latticeVertex()[bk.latticeIndex(7, 5, 0)], -1);
        const label v = bk.latticeVertex()[bk.latticeIndex(4, 3, 0)];
        ASSERT_GE(v, 0);
        EXPECT_LT(mag(notched->vertices()[v] - vector(2, 1.5, 0)), 1e-14);
        label nIn = 0;
        for (const vector& x : samples(2, {0, 1, 2}, vector::zero, vector(4, 3, 0), 300, 8))
        {
            if (x.x() > 2.5 && x.y() > 2) continue;   // in the notch
            const scalar wmin = checkIdentities(*k, x, "2D notch", false);
            EXPECT_GE(wmin, 0);
            ++nIn;
        }
        EXPECT_GT(nIn, 200);
    }
    {
        const label n[3] = {4, 4, 4};
        const scalar h[3] = {1, 1, 1};
        auto notched = lattice(3, {0, 1, 2}, n, h, vector::zero,
            [](label i, label j, label k) { return !(i >= 2 && j >= 2 && k >= 2); });
        auto k = kernel("bspline2", *notched);
        EXPECT_FALSE(dynamic_cast<const bspline2Kernel&>(*k).complete());
        for (const vector& x : samples(3, {0, 1, 2}, vector::zero, vector(4, 4, 4), 200, 9))
        {
            if (x.x() > 2 && x.y() > 2 && x.z() > 2) continue;
            checkIdentities(*k, x, "3D notch", false);
        }
    }
}


// APIC with bspline2 along the wall of a notch (the bore of a gun: the
// nodes beyond the wall are missing, the weights renormalised, sum w x_v !=
// x_p): particles moving at a uniform velocity through 20 P2G / G2P round
// trips keep their momentum and kinetic energy to round-off (the affine
// moments about x_p fed the velocity back: +0.6 % momentum per trip here)
TEST(bspline2Kernel, apicMomentumNextToNotch)
{
    const label n[3] = {8, 6, 1};
    const scalar h[3] = {0.5, 0.5, 1};
    auto notched = lattice(2, {0, 1, 2}, n, h, vector::zero,
        [](label i, label j, label) { return !(i >= 5 && j >= 4); });
    IStringStream is("kernel bspline2; transfer APIC;");
    const dictionary dict(is);
    auto k = mpmKernel::New(dict, *notched);
    auto T = mpmTransfer::New(dict, *notched);

    // 2 x 2 particles per cell in the row of cells under the notch's floor
    // (y in [1.5, 2]), x in [2.5, 4]
    mpmParticles P;
    for (label i = 5; i < 8; ++i)
    for (label a = 0; a < 2; ++a)
    for (label b = 0; b < 2; ++b)
    {
        const vector x((i + 0.25 + 0.5*a)*h[0], (3 + 0.25 + 0.5*b)*h[1], 0);
        P.append(x, vector(1, 0.3, 0), tensor::I, 1.0 + 0.1*a, 0.25*h[0]*h[1], 0, 0);
    }
    const label nP = P.size();
    auto momentum = [&]()
    {
        vector s(Zero);
        for (label p = 0; p < nP; ++p) s += P.m[p]*P.v[p];
        return s;
    };
    auto kinetic = [&]()
    {
        scalar e = 0;
        for (label p = 0; p < nP; ++p) e += 0.5*P.m[p]*magSqr(P.v[p]);
        return e;
    };
    const vector m0 = momentum();
    const scalar e0 = kinetic();
    mpmGrid grid(notched->nVertices());
    kernelWeights kw;
    for (label trip = 0; trip < 20; ++trip)
    {
        k->compute(P.x, labelList(nP, 0), kw);
        grid.activate(kw);
        T->p2g(P, kw, grid);
        vector mg(Zero);
        for (const label i : grid.active)
        {
            mg += grid.velocity[i];
            grid.newVelocity[i] = grid.velocity[i]/grid.mass[i];
        }
        EXPECT_LT(mag(mg - m0), 1e-12*mag(m0)) << "P2G, trip " << trip;
        T->g2p(kw, grid, P);
        EXPECT_LT(mag(momentum() - m0), 1e-12*mag(m0)) << "G2P, trip " << trip;
        EXPECT_LE(kinetic(), e0*(1 + 1e-12)) << "G2P, trip " << trip;
    }
}


// APIC at the lattice's end (an outlet: particles reach the end before they
// leave).  The fold's D_p along x is xi (1 - xi) h^2 at xi cells from the
// end.  A particle takes B from the grid field v = (x, 0, 0) at xi = 0.4
// (B_xx = D_p there), moves to xi = 1e-9 and deposits again: with C = B
// D_p^-1 at its new place the node beside the end gets v_p + C h, about
// 0.24/1e-9 h = 1.2e8; with bspline2's momentFloor (h^2/8) C is at most
// 0.24/0.125 = 1.92 and every node's velocity stays below |v_p| + 1.92 h
// < 5 (the field spans 0..4)
TEST(bspline2Kernel, apicMomentFloorAtLatticeEnd)
{
    const label n[3] = {8, 6, 1};
    const scalar h[3] = {0.5, 0.5, 1};
    auto m = lattice(2, {0, 1, 2}, n, h, vector::zero);
    IStringStream is("kernel bspline2; transfer APIC;");
    const dictionary dict(is);
    auto k = mpmKernel::New(dict, *m);
    auto T = mpmTransfer::New(dict, *m);
    const vector floor = k->momentFloor();
    EXPECT_DOUBLE_EQ(floor.x(), 0.125*h[0]*h[0]);
    EXPECT_DOUBLE_EQ(floor.y(), 0.125*h[1]*h[1]);

    auto largestNodeSpeed = [&](bool floored)
    {
        T->setMomentFloor(floored ? floor : vector::zero);
        mpmParticles P;
        const scalar xOld = 4 - 0.4*h[0];
        P.append(vector(xOld, 1.6, 0), vector(xOld, 0, 0), tensor::I, 1.0,
                 0.25*h[0]*h[1], 0, 0);
        mpmGrid grid(m->nVertices());
        kernelWeights kw;
        k->compute(P.x, labelList(1, 0), kw);
        grid.activate(kw);
        T->p2g(P, kw, grid);
        for (const label i : grid.active)
        {
            grid.newVelocity[i] = vector(m->vertices()[i].x(), 0, 0);
        }
        T->g2p(kw, grid, P);
        P.x[0] = vector(4 - 1e-9*h[0], 1.6, 0);
        mpmGrid grid2(m->nVertices());
        k->compute(P.x, labelList(1, 0), kw);
        grid2.activate(kw);
        T->p2g(P, kw, grid2);
        scalar vmax = 0;
        for (const label i : grid2.active)
        {
            if (grid2.mass[i] > 0)
            {
                vmax = max(vmax, mag(grid2.velocity[i]/grid2.mass[i]));
            }
        }
        return vmax;
    };
    const scalar withFloor = largestNodeSpeed(true);
    const scalar without = largestNodeSpeed(false);
    EXPECT_LT(withFloor, 5) << "with bspline2's momentFloor";
    EXPECT_GT(without, 1e6) << "without the floor (the defect it guards)";
}


// Reused weights: a second call with fewer particles has the right rows
TEST(bspline2Kernel, reusedWeights)
{
    const label n[3] = {5, 5, 1};
    const scalar h[3] = {1, 1, 1};
    auto m = lattice(2, {0, 1, 2}, n, h, vector::zero);
    auto k = kernel("bspline2", *m);
    kernelWeights kw;
    const auto pts = samples(2, {0, 1, 2}, vector::zero, vector(5, 5, 0), 20, 1);
    k->compute(List<vector>(pts.begin(), pts.end()), labelList(20, 0), kw);
    EXPECT_EQ(kw.nParticles(), 20);
    k->compute(List<vector>(3, vector(2.2, 1.7, 0)), labelList(3, 0), kw);
    EXPECT_EQ(kw.nParticles(), 3);
    EXPECT_EQ(kw.vertex.size(), 27);
    scalar sw = 0;
    for (label i = kw.start[2]; i < kw.start[3]; ++i) sw += kw.w[i];
    EXPECT_NEAR(sw, 1, 1e-14);
}


// Meshes that are not uniform Cartesian lattices
TEST(bspline2Kernel, badMeshIsFatalIOError)
{
    struct badCase
    {
        std::string name;
        std::unique_ptr<mpmMeshView> mesh;
        std::string why;
    };
    std::vector<badCase> cases;
    cases.push_back({"1D graded 1.1", testMeshes::line(testMeshes::graded(8, 1.1)), "first offending cell: 1 "});
    {
        // One cell of a uniform 1D lattice moved by 1 % of h
        std::vector<double> xs{0, 1, 2, 3.01, 4, 5, 6};
        cases.push_back({"1D one vertex moved", testMeshes::line(xs), "first offending cell: 2 "});
    }
    cases.push_back({"2D quads perturbed", testMeshes::plane(6, true, 0.1), "its size along"});
    cases.push_back({"2D quads graded", testMeshes::plane(6, true, 0.0, 1.05), "first offending cell: 1 "});
    cases.push_back({"2D triangles", testMeshes::plane(4, false, 0.0), "it is a triangle"});
    cases.push_back({"3D tets", testMeshes::box(3, false, 0.0), "it is a tet"});
    cases.push_back({"3D hexes perturbed", testMeshes::box(3, true, 0.05), "its size along"});
    {
        const label n[3] = {5, 1, 4};
        const scalar h[3] = {1, 1, 1};
        cases.push_back({"3D one cell thick", lattice(3, {0, 1, 2}, n, h, vector::zero), "cell(s) along y"});
    }

    FatalIOError.throwExceptions();
    for (const badCase& bc : cases)
    {
        try
        {
            kernel("bspline2", *bc.mesh);
            ADD_FAILURE() << "no error for " << bc.name;
        }
        catch (const Foam::IOerror& err)
        {
            const std::string msg = err.message();
            EXPECT_NE(msg.find("'kernel'"), std::string::npos) << bc.name << ": " << msg;
            EXPECT_NE(msg.find("bspline2"), std::string::npos) << bc.name << ": " << msg;
            EXPECT_NE(msg.find("first offending cell"), std::string::npos) << bc.name << ": " << msg;
            EXPECT_NE(msg.find("allowed:"), std::string::npos) << bc.name << ": " << msg;
            EXPECT_NE(msg.find(bc.why), std::string::npos) << bc.name << ": " << msg;
        }
    }
    FatalIOError.dontThrowExceptions();

    // A uniform mesh whose points carry 6-digit round-off passes
    std::vector<double> xs;
    for (int i = 0; i <= 30; ++i)
    {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.6g", i/3.0);
        xs.push_back(std::stod(buf));
    }
    auto m = testMeshes::line(xs);
    EXPECT_NO_THROW(kernel("bspline2", *m));
}
