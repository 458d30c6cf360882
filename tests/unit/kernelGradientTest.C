// The MLS kernels' gradient options (mlsRingKernel: gradient fit |
// heldEta | derivative): identities, the derivative against finite
// differences of the weights, continuity across faces, and the integration
// constraint sum_p V_p grad w_vp = 0 for a vertex inside the body, which
// the fit's slope (2.22) breaks on irregular meshes

#include "kernelChecks.H"

namespace
{

using namespace Foam;

// Irregular meshes: 1D vertices moved by up to 0.2 cells, 2D triangles
// and 3D tetrahedra with vertices moved by up to 0.2
std::vector<std::pair<std::string, std::unique_ptr<mpmMeshView>>> irregularMeshes()
{
    std::vector<std::pair<std::string, std::unique_ptr<mpmMeshView>>> out;
    std::vector<double> xs;
    std::mt19937 gen(5);
    std::uniform_real_distribution<double> u(-0.2, 0.2);
    for (label i = 0; i <= 16; ++i)
    {
        xs.push_back(i + ((i > 0 && i < 16) ? u(gen) : 0.0));
    }
    out.emplace_back("1D irregular", testMeshes::line(xs));
    out.emplace_back("2D triangles", testMeshes::plane(8, false, 0.2));
    out.emplace_back("3D tets", testMeshes::box(5, false, 0.2));
    return out;
}

// The gradient of w_v along axis a by central differences, the particle
// kept in cell c (w is smooth inside a cell for every option)
std::map<label, vector> finiteDifference
(
    const mpmKernel& k,
    const vector& x,
    const label c,
    const scalar eps
)
{
    const mpmMeshView& m = k.mesh();
    std::map<label, vector> g;
    for (label a = 0; a < m.dim(); ++a)
    {
        const label ax = m.axis(a);
        vector xp(x), xm(x);
        xp[ax] += eps;
        xm[ax] -= eps;
        kernelWeights kp, km;
        k.compute(List<vector>(1, xp), labelList(1, c), kp);
        k.compute(List<vector>(1, xm), labelList(1, c), km);
        // (vector's default constructor leaves it unset: zero it)
        for (label i = kp.start[0]; i < kp.start[1]; ++i)
        {
            g.emplace(kp.vertex[i], vector::zero).first->second[ax] +=
                kp.w[i]/(2*eps);
        }
        for (label i = km.start[0]; i < km.start[1]; ++i)
        {
            g.emplace(km.vertex[i], vector::zero).first->second[ax] -=
                km.w[i]/(2*eps);
        }
    }
    return g;
}

// Largest |grad w - finite difference| over the weights of a point,
// relative to the largest |grad w|
scalar derivativeMismatch(const mpmKernel& k, const vector& x)
{
    const mpmMeshView& m = k.mesh();
    const label c = m.findCell(x, 0);
    const weightsAt r = evaluate(k, x, c);
    const auto fd = finiteDifference(k, x, c, 1e-6);
    scalar worst = 0;
    for (const auto& e : fd)
    {
        const auto it = r.wv.find(e.first);
        const vector g = it == r.wv.end() ? vector::zero : it->second.second;
        worst = max(worst, mag(g - e.second));
    }
    return worst/r.gMax;
}

// max over interior vertices of |sum_p V_p grad w_vp| / sum_p V_p |grad
// w_vp|, particles on a fine lattice (spacing s) over [lo, hi]^dim: the
// particle sum stands for the integral of grad w_v over the body, zero for
// a vertex whose support lies inside it
scalar integrationDefect
(
    const mpmKernel& k,
    const scalar lo,
    const scalar hi,
    const scalar s,
    const scalar margin
)
{
    const mpmMeshView& m = k.mesh();
    const label dim = m.dim();
    const label n = label((hi - lo)/s);
    DynamicList<vector> xs;
    for (label i = 0; i < n; ++i)
        for (label j = 0; j < (dim > 1 ? n : 1); ++j)
            for (label l = 0; l < (dim > 2 ? n : 1); ++l)
            {
                xs.append
                (
                    vector
                    (
                        lo + (i + 0.5)*s,
                        dim > 1 ? lo + (j + 0.5)*s : 0,
                        dim > 2 ? lo + (l + 0.5)*s : 0
                    )
                );
            }
    labelList cells(xs.size());
    label guess = 0;
    forAll(xs, p)
    {
        cells[p] = m.findCell(xs[p], guess);
        EXPECT_GE(cells[p], 0);
        guess = max(cells[p], label(0));
    }
    kernelWeights kw;
    k.compute(xs, cells, kw);
    std::map<label, std::pair<vector, scalar>> sum;
    forAll(xs, p)
    {
        for (label i = kw.start[p]; i < kw.start[p + 1]; ++i)
        {
            auto& e = sum.emplace
            (
                kw.vertex[i], std::make_pair(vector::zero, scalar(0))
            ).first->second;
            e.first += kw.gradW[i];
            e.second += mag(kw.gradW[i]);
        }
    }
    scalar worst = 0;
    label nv = 0;
    for (const auto& e : sum)
    {
        const vector& xv = m.vertices()[e.first];
        bool inside = true;
        for (label a = 0; a < dim; ++a)
        {
            const scalar c = xv[m.axis(a)];
            inside = inside && c > lo + margin && c < hi - margin;
        }
        if (!inside) continue;
        worst = max(worst, mag(e.second.first)/e.second.second);
        ++nv;
    }
    EXPECT_GT(nv, 0);
    return worst;
}

} // End anonymous namespace


// Every option keeps the MLS identities (sum grad w = 0, sum x_v grad w^T
// = I); 'derivative' is the weights' own gradient (finite differences
// agree to 1e-5 of |grad w|), 'fit' and 'heldEta' are not
TEST(kernelGradient, identitiesAndDerivative)
{
    for (const auto& mc : irregularMeshes())
    {
        const mpmMeshView& m = *mc.second;
        const scalar lo = m.bbMin().x() + 1.2, hi = m.bbMax().x() - 1.2;
        for (const char* g : {"fit", "heldEta", "derivative"})
        {
            auto k = kernel("umls", m, std::string("gradient ") + g + ";");
            scalar worst = 0;
            for (const vector& x : samples(m.dim(), lo, hi, 20, 11))
            {
                checkIdentities(*k, x, mc.first + " " + g);
                worst = max(worst, derivativeMismatch(*k, x));
            }
            std::cout << "  " << mc.first << ", gradient " << g
                << ": |grad w - finite difference| / |grad w| up to "
                << worst << std::endl;
            if (word(g) == "derivative")
            {
                EXPECT_LT(worst, 1e-5) << mc.first;
            }
            else
            {
                EXPECT_GT(worst, 1e-3) << mc.first << " " << g;
            }
        }
    }
}


// Crossing faces: 'fit' and 'heldEta' change grad w by < 1e-4 of its size
// (eta is continuous and held); 'derivative' jumps with eta's gradient
TEST(kernelGradient, continuityAcrossFaces)
{
    for (const auto& mc : irregularMeshes())
    {
        const mpmMeshView& m = *mc.second;
        for (const char* g : {"fit", "heldEta", "derivative"})
        {
            auto k = kernel("umls", m, std::string("gradient ") + g + ";");
            const crossings c = crossAtVertices(*k);
            const scalar worst = c.gradW;
            const label n = c.n;
            std::cout << "  " << mc.first << ", gradient " << g << ": "
                << n << " crossings, largest jump of grad w " << worst
                << std::endl;
            EXPECT_GT(n, 0) << mc.first;
            if (word(g) == "derivative")
            {
                EXPECT_GT(worst, 1e-2) << mc.first;
            }
            else
            {
                EXPECT_LT(worst, 1e-4) << mc.first << " " << g;
            }
        }
    }
}


// The integration constraint: sum_p V_p grad w_vp over a body that covers
// the vertex's support is 0 for the weights' own gradient (to the
// lattice's quadrature error), not for the fit's slope on an irregular
// mesh (and holding eta leaves part of it)
TEST(kernelGradient, integrationConstraint)
{
    for (const auto& mc : irregularMeshes())
    {
        const mpmMeshView& m = *mc.second;
        if (m.dim() == 3) continue;     // the 2D lattice is dense enough
        const scalar lo = m.bbMin().x() + 0.01, hi = m.bbMax().x() - 0.01;
        const scalar s = m.dim() == 1 ? 1e-3 : 8e-3;
        scalar defect[3];
        label i = 0;
        for (const char* g : {"fit", "heldEta", "derivative"})
        {
            auto k = kernel("umls", m, std::string("gradient ") + g + ";");
            defect[i] = integrationDefect(*k, lo, hi, s, 3);
            std::cout << "  " << mc.first << ", gradient " << g
                << ": |sum V grad w| / sum V |grad w| up to " << defect[i]
                << std::endl;
            ++i;
        }
        EXPECT_GT(defect[0], 1e-3) << mc.first << " fit";
        EXPECT_LT(defect[2], 1e-4) << mc.first << " derivative";
        EXPECT_LT(defect[2], 0.1*defect[0]) << mc.first;
    }
}


// A gradient that is not one of the three stops with a FatalIOError that
// names the entry
TEST(kernelGradient, badEntryIsFatalIOError)
{
    auto m = testMeshes::plane(4, false, 0.1);
    FatalIOError.throwExceptions();
    try
    {
        kernel("umls", *m, "gradient slope;");
        FAIL() << "gradient slope accepted";
    }
    catch (const Foam::IOerror& e)
    {
        const std::string msg = e.message();
        EXPECT_NE(msg.find("gradient"), std::string::npos) << msg;
        EXPECT_NE(msg.find("slope"), std::string::npos) << msg;
    }
    FatalIOError.dontThrowExceptions();
}


// supportSize ring: every interior vertex of a uniform line reaches two
// cells (its ring changes at the faces two cells away), of a uniform grid
// of squares sqrt(2) cells (the re-entrant corners of its 2-star)
TEST(kernelGradient, ringReachOfUniformMeshes)
{
    std::vector<double> xs;
    for (label i = 0; i <= 12; ++i) xs.push_back(0.5*i);
    const auto line = testMeshes::line(xs);
    const scalarList r1(line->ringReach());
    forAll(r1, v)
    {
        EXPECT_NEAR(r1[v], 1.0, 1e-12) << "line vertex " << v;
    }

    const auto grid = testMeshes::plane(8, true, 0);
    const scalarList r2(grid->ringReach());
    label n = 0;
    forAll(r2, v)
    {
        const vector& x = grid->vertices()[v];
        const scalar s = grid->vertexSize()[v];
        const vector lo = x - grid->bbMin(), hi = grid->bbMax() - x;
        if (min(min(lo.x(), lo.y()), min(hi.x(), hi.y())) < 3*s) continue;
        EXPECT_NEAR(r2[v], std::sqrt(2.0)*s, 1e-12*s) << "grid vertex " << v;
        ++n;
    }
    EXPECT_GT(n, 0);
}


// supportSize ring with the weights' own gradient: continuous across faces
// without eta (value and gradient), the derivative of the weights, and the
// integration constraint, on the irregular meshes, with either sample
// weight.  The same kernel over the vertices' longest edges jumps where
// the ring changes (2D, 3D).
TEST(kernelGradient, ringSupportsSmoothAndConsistent)
{
    for (const auto& mc : irregularMeshes())
    {
        const mpmMeshView& m = *mc.second;
        const scalar lo = m.bbMin().x() + 1.2, hi = m.bbMax().x() - 1.2;
        for (const char* w : {"quadratic", "cubic", "adaptive"})
        {
            auto k = kernel
            (
                "mlsRing", m,
                std::string("supportSize ring; gradient derivative; ")
              + "sampleWeight " + w + ";"
            );
            const std::string what = mc.first + ", ring, " + w;
            scalar worst = 0;
            for (const vector& x : samples(m.dim(), lo, hi, 20, 13))
            {
                checkIdentities(*k, x, what);
                worst = max(worst, derivativeMismatch(*k, x));
            }
            const crossings c = crossAtVertices(*k);
            std::cout << "  " << what << ": |grad w - finite difference| / "
                << "|grad w| up to " << worst << "; " << c.n
                << " crossings, largest jumps of w " << c.w
                << " and grad w " << c.gradW;
            EXPECT_LT(worst, 1e-5) << what;
            EXPECT_GT(c.n, 0) << what;
            EXPECT_LT(c.w, 1e-4) << what;
            EXPECT_LT(c.gradW, 1e-4) << what;
            if (m.dim() < 3)
            {
                const scalar defect = integrationDefect
                (
                    *k, m.bbMin().x() + 0.01, m.bbMax().x() - 0.01,
                    m.dim() == 1 ? 1e-3 : 8e-3, 3
                );
                std::cout << "; |sum V grad w| / sum V |grad w| up to "
                    << defect;
                EXPECT_LT(defect, 1e-4) << what;
            }
            std::cout << std::endl;
        }
        if (m.dim() > 1)
        {
            auto k = kernel("mlsRing", m, "gradient derivative;");
            const crossings c = crossAtVertices(*k);
            std::cout << "  " << mc.first << ", maxEdge: largest jump of "
                << "grad w " << c.gradW << std::endl;
            EXPECT_GT(c.gradW, 1e-2) << mc.first << " maxEdge";
        }
    }
}


// linearBlend: where the ring reach leaves the moments degenerate
// (stretched quadrilaterals: fewer than dim + 1 vertices within reach),
// the kernel stops without it and blends into the cell's linear shape
// functions with it: at a singular point the weights are the linear ones;
// everywhere the identities hold, the weights stay continuous across
// faces and their gradient is their derivative, the blend's share
// included (linearBlend 0.5 blends wide zones of the tetrahedra too)
TEST(kernelGradient, linearBlendWhereMomentsDegenerate)
{
    auto m = testMeshes::plane(8, true, 0, 1.3);
    const std::string ring =
        "supportSize ring; gradient derivative; sampleWeight adaptive; ";
    const scalar lo = m->bbMin().x() + 1e-3, hi = m->bbMax().x() - 1e-3;
    const std::vector<vector> pts = samples(2, lo, hi, 400, 17);

    // Without the blend: stops at some point, saying what to do
    vector singular(vector::max);
    {
        auto k = kernel("mlsRing", *m, ring + "linearBlend 0;");
        FatalError.throwExceptions();
        for (const vector& x : pts)
        {
            try
            {
                evaluate(*k, x);
            }
            catch (const Foam::error& e)
            {
                const std::string msg = e.message();
                EXPECT_NE(msg.find("linearBlend"), std::string::npos) << msg;
                singular = x;
                break;
            }
        }
        FatalError.dontThrowExceptions();
    }
    ASSERT_LT(singular.x(), GREAT) << "no singular moment matrix found";

    // With it (ring supports' default): the cell's linear weights there
    auto k = kernel("mlsRing", *m, ring);
    auto lin = kernel("linear", *m);
    const weightsAt a = evaluate(*k, singular), b = evaluate(*lin, singular);
    const auto j = jump(a, b);
    std::cout << "  stretched quadrilaterals: singular at " << singular
        << ", blended weights differ from the linear ones by " << j.first
        << std::endl;
    EXPECT_LT(j.first, 1e-12);

    scalar worst = 0;
    for (const vector& x : pts)
    {
        checkIdentities(*k, x, "stretched quadrilaterals, linearBlend");
        worst = max(worst, derivativeMismatch(*k, x));
    }
    const crossings c = crossAtVertices(*k);
    std::cout << "  |grad w - finite difference| / |grad w| up to " << worst
        << "; " << c.n << " crossings, largest jump of w " << c.w
        << std::endl;
    EXPECT_LT(worst, 1e-5);
    EXPECT_GT(c.n, 0);
    EXPECT_LT(c.w, 1e-4);

    // Wide blend zones on the perturbed tetrahedra: the derivative
    // includes grad s (without it the mismatch is of order 1)
    auto t = testMeshes::box(5, false, 0.2);
    auto kt = kernel("mlsRing", *t, ring + "linearBlend 0.5;");
    auto k0 = kernel("mlsRing", *t, ring + "linearBlend 0;");
    scalar worstT = 0, changed = 0;
    for (const vector& x : samples(3, 1.2, 3.8, 60, 19))
    {
        checkIdentities(*kt, x, "3D tets, linearBlend 0.5");
        worstT = max(worstT, derivativeMismatch(*kt, x));
        changed = max(changed, jump(evaluate(*kt, x), evaluate(*k0, x)).first);
    }
    std::cout << "  3D tets, linearBlend 0.5: weights changed by up to "
        << changed << ", |grad w - finite difference| / |grad w| up to "
        << worstT << std::endl;
    EXPECT_GT(changed, 1e-2);
    EXPECT_LT(worstT, 1e-5);
}
