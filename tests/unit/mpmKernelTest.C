// Unit tests of the MPM transfer kernels: linear, mlsRing, umls
//  - MLS identities (partition of unity, linear reproduction, gradients)
//  - continuity of umls across faces, and the mlsRing jump (ablation)
//  - umls = (2.33)/(2.34) on the uniform 1D mesh

#include "kernelChecks.H"
#include "boundBox.H"

using namespace Foam;



// (2.33), (2.34): the kernel of the node at x = 2 on the uniform unit mesh
TEST(umlsKernel, matchesAnalytic1D)
{
    std::vector<double> xs;
    for (int i = -3; i <= 8; ++i) xs.push_back(i);
    auto m = testMeshes::line(xs);
    auto k = kernel("umls", *m);
    const label node = 5;   // x = 2
    ASSERT_EQ(m->vertices()[node].x(), 2.0);

    auto f = [](double x)
    {
        if (x <= 1)
            return 0.25*(0.5 - x)*(0.5 - x)*x
                /(x*x*x*x*x - 6*x*x*x*x + 13.5*x*x*x - 13.75*x*x + 6.3125*x - 0.5625);
        return (-std::pow(x, 6) + 5*std::pow(x, 5) - 9.5*std::pow(x, 4)
                + 8.5*x*x*x - 3.3125*x*x + 0.3125*x + 0.0625)
            /(-std::pow(x, 5) + 4*std::pow(x, 4) - 5.5*x*x*x + 3.25*x*x
                - 1.3125*x + 1.0625);
    };
    auto g = [](double x)
    {
        if (x <= 1)
            return -(0.5 - x)*(0.5 - x)*x*(x - 2)
                /(x*x*x*x*x - 6*x*x*x*x + 13.5*x*x*x - 13.75*x*x + 6.3125*x - 0.5625);
        return (-std::pow(x, 5) + 5*std::pow(x, 4) - 10.5*x*x*x + 11.5*x*x
                - 5.8125*x + 1.0625)
            /(-std::pow(x, 5) + 4*std::pow(x, 4) - 5.5*x*x*x + 3.25*x*x
                - 1.3125*x + 1.0625);
    };

    scalar errW = 0, errG = 0;
    for (int i = 1; i <= 200; ++i)
    {
        const double x = 0.5 + i*0.005;   // (0.5, 1.5]
        const weightsAt r = evaluate(*k, vector(x, 0, 0), 3);
        const auto it = r.wv.find(node);
        const scalar w = it == r.wv.end() ? 0 : it->second.first;
        const scalar gw = it == r.wv.end() ? 0 : it->second.second.x();
        errW = max(errW, std::abs(w - f(x)));
        errG = max(errG, std::abs(gw - g(x)));
    }
    EXPECT_LT(errW, 1e-6);
    EXPECT_LT(errG, 1e-6);
    RecordProperty("maxErrorW", std::to_string(errW));
    std::cout << "  umls vs (2.33)/(2.34): max |w - f| = " << errW
              << ", max |grad w - g| = " << errG << std::endl;
}


// The kernel is symmetric about its node: w(2 + s) = w(2 - s)
TEST(umlsKernel, symmetricAboutNode1D)
{
    std::vector<double> xs;
    for (int i = -3; i <= 8; ++i) xs.push_back(i);
    auto m = testMeshes::line(xs);
    auto k = kernel("umls", *m);
    for (int i = 1; i < 100; ++i)
    {
        const double s = 1.5*i/100.0 + 1e-7;
        const weightsAt a = evaluate(*k, vector(2 + s, 0, 0));
        const weightsAt b = evaluate(*k, vector(2 - s, 0, 0));
        EXPECT_NEAR(a.wv.at(5).first, b.wv.at(5).first, 1e-12) << s;
        EXPECT_NEAR(a.wv.at(5).second.x(), -b.wv.at(5).second.x(), 1e-10) << s;
    }
}


// Identities for every kernel on uniform, graded and perturbed meshes, away
// from the boundary layer (where the extra layer of cells exists)
TEST(mpmKernels, identitiesOnAllMeshes)
{
    struct meshCase
    {
        std::string name;
        std::unique_ptr<mpmMeshView> mesh;
        scalar lo, hi;
        bool nonNegative;
    };
    std::vector<meshCase> cases;
    cases.push_back({"1D uniform", testMeshes::line(testMeshes::graded(10, 1.0)), 1.0, 9.0, true});
    cases.push_back({"1D graded 1.3", testMeshes::line(testMeshes::graded(10, 1.3)), 1.0, 20.0, false});
    cases.push_back({"2D triangles perturbed", testMeshes::plane(8, false, 0.25), 1.3, 6.7, true});
    cases.push_back({"2D triangles graded", testMeshes::plane(8, false, 0.0, 1.2), 1.3, 10.0, true});
    cases.push_back({"2D quads perturbed", testMeshes::plane(8, true, 0.2), 1.3, 6.7, false});
    cases.push_back({"3D tets perturbed", testMeshes::box(5, false, 0.2), 1.3, 3.7, true});
    cases.push_back({"3D hexes perturbed", testMeshes::box(5, true, 0.15), 1.3, 3.7, false});

    for (const meshCase& mc : cases)
    {
        for (const char* kn : {"linear", "mlsRing", "umls"})
        {
            auto k = kernel(kn, *mc.mesh);
            scalar wmin = GREAT;
            for (const vector& x : samples(mc.mesh->dim(), mc.lo, mc.hi, 60, 3))
            {
                wmin = min(wmin, checkIdentities(*k, x, mc.name + " " + kn));
            }
            std::cout << "  " << mc.name << ", " << kn << ": min w = " << wmin
                      << std::endl;
            // Shape functions are never negative inside a cell; on simplex
            // meshes with the extra layer the umls weights are not either.
            // (Graded 1D and multilinear cells give small negative MLS
            // weights: printed above, not asserted.)
            if (word(kn) == "linear" || (word(kn) == "umls" && mc.nonNegative))
            {
                EXPECT_GE(wmin, -1e-12) << mc.name << " " << kn;
            }
        }
    }
}


// Crossing any interior face by 2e-6 h (from 1e-6 h before to 1e-6 h after,
// along the line between the two cell centres): umls changes w and grad w
// by < 1e-4 relative to their magnitudes; mlsRing, the ablation without
// eta, jumps by O(1) at the worst of the same crossings
TEST(mpmKernels, continuityAcrossFaces)
{
    // The shrinking/expanding 1D mesh of Fig. 2.4c, cycle [1, R, R^2, R]
    std::vector<double> cyc{0};
    const double R = 1.5;
    for (int i = 0; i < 16; ++i)
    {
        const double hs[4] = {1, R, R*R, R};
        cyc.push_back(cyc.back() + hs[i % 4]);
    }

    struct meshCase
    {
        std::string name;
        std::unique_ptr<mpmMeshView> mesh;
        bool ringJumps;
    };
    std::vector<meshCase> cases;
    cases.push_back({"1D uniform", testMeshes::line(testMeshes::graded(12, 1.0)), false});
    cases.push_back({"1D shrinking/expanding R = 1.5", testMeshes::line(cyc), true});
    cases.push_back({"2D triangles perturbed", testMeshes::plane(7, false, 0.25), true});
    cases.push_back({"2D quads perturbed", testMeshes::plane(7, true, 0.2), false});
    cases.push_back({"3D tets perturbed", testMeshes::box(4, false, 0.2), true});
    cases.push_back({"3D hexes perturbed", testMeshes::box(4, true, 0.15), false});

    for (const meshCase& mc : cases)
    {
        const mpmMeshView& m = *mc.mesh;
        auto u = kernel("umls", m);
        auto r = kernel("mlsRing", m);
        const labelList& cv = m.cellVertices();

        auto centre = [&](label c)
        {
            vector x(Zero);
            for (label i = m.cellBegin(c); i < m.cellEnd(c); ++i) x += m.vertices()[cv[i]];
            return x/scalar(m.cellEnd(c) - m.cellBegin(c));
        };

        scalar umlsW = 0, umlsG = 0, ringMax = 0;
        label nCrossings = 0;
        for (label c = 0; c < m.nCells(); ++c)
        {
            const vector cc = centre(c);
            for (label f = 0; f < m.nCellFaces(c); ++f)
            {
                const label d = m.faceNeighbour(c, f);
                if (d < c) continue;
                // The face's vertices: those of c also in d
                vector xf(Zero);
                label nf = 0;
                for (label i = m.cellBegin(c); i < m.cellEnd(c); ++i)
                {
                    for (label j = m.cellBegin(d); j < m.cellEnd(d); ++j)
                    {
                        if (cv[i] == cv[j]) { xf += m.vertices()[cv[i]]; ++nf; }
                    }
                }
                xf /= scalar(nf);
                // Stay clear of the boundary layer (one-sided rings)
                bool interior = true;
                for (label a = 0; a < m.dim(); ++a)
                {
                    const label k = m.axis(a);
                    const scalar span = m.bbMax()[k] - m.bbMin()[k];
                    interior = interior && xf[k] > m.bbMin()[k] + 0.15*span
                        && xf[k] < m.bbMax()[k] - 0.15*span;
                }
                if (!interior) continue;

                vector n = centre(d) - cc;
                const scalar h = mag(n);
                n /= h;
                const vector a = xf - 1e-6*h*n;
                const vector b = xf + 1e-6*h*n;
                if (m.findCell(a, c) != c || m.findCell(b, d) != d) continue;

                const auto ju = jump(evaluate(*u, a, c), evaluate(*u, b, d));
                const auto jr = jump(evaluate(*r, a, c), evaluate(*r, b, d));
                umlsW = max(umlsW, ju.first);
                umlsG = max(umlsG, ju.second);
                ringMax = max(ringMax, max(jr.first, jr.second));
                ++nCrossings;
            }
        }
        std::cout << "  " << mc.name << ": " << nCrossings << " crossings;"
                  << " umls max jump w " << umlsW << ", grad w " << umlsG
                  << "; mlsRing max jump " << ringMax << std::endl;
        EXPECT_GT(nCrossings, 0) << mc.name;
        EXPECT_LT(umlsW, 1e-4) << mc.name;
        EXPECT_LT(umlsG, 1e-4) << mc.name;
        // On simplex and size-cycling meshes the vertices leaving the 1-ring
        // still carry B-spline weight: mlsRing jumps there.  On uniform 1D
        // and on (perturbed) grids of quads/hexes they sit at two edges'
        // distance, outside the 1.5 h support, so mlsRing happens to be
        // continuous too (reported, not asserted).
        if (mc.ringJumps)
        {
            EXPECT_GT(ringMax, 0.05) << mc.name;
        }
    }
}


// Point location by walking, from far away cells
TEST(mpmMeshView, findCellWalks)
{
    for (const bool quads : {false, true})
    {
        auto m = testMeshes::plane(10, quads, 0.2);
        mpmMeshView::shapeValues sv;
        for (const vector& x : samples(2, 0.01, 9.99, 200, 9))
        {
            const label c = m->findCell(x, 0);
            ASSERT_GE(c, 0);
            m->shapeFunctions(c, x, sv);
            EXPECT_LE(sv.outside, 1e-12);
        }
        EXPECT_EQ(m->findCell(vector(-1, 5, 0), 3), -1);
    }
    auto t = testMeshes::box(4, false, 0.2);
    for (const vector& x : samples(3, 0.01, 3.99, 100, 4))
    {
        EXPECT_GE(t->findCell(x, 0), 0);
    }
}


// The capabilities the solver reads (mpmKernel::invertibleMoments, used to
// admit APIC) match the weights: D_p = sum w (x_v - x)(x_v - x)^T (2.36) at
// a particle on an interior vertex is singular for linear (all weight on
// that vertex) and well conditioned for the MLS kernels
TEST(mpmKernels, capabilitiesMatchWeights)
{
    std::vector<std::unique_ptr<mpmMeshView>> meshes;
    meshes.push_back(testMeshes::plane(8, false, 0.25));
    meshes.push_back(testMeshes::box(5, true, 0.15));
    for (const auto& m : meshes)
    {
        // An interior vertex near the middle
        const boundBox bb(m->vertices());
        label v = -1;
        scalar best = GREAT;
        forAll(m->vertices(), i)
        {
            const scalar d = mag(m->vertices()[i] - bb.centre());
            if (!m->boundaryVertex(i) && d < best) { best = d; v = i; }
        }
        ASSERT_GE(v, 0);
        const scalar h = m->vertexSize()[v];
        const vector x = m->vertices()[v] + 1e-9*h*vector(1, 1, m->dim() > 2 ? 1 : 0);
        for (const char* kn : {"linear", "mlsRing", "umls"})
        {
            auto k = kernel(kn, *m);
            const weightsAt r = evaluate(*k, x);
            tensor D(Zero);
            for (const auto& e : r.wv)
            {
                const vector d = m->vertices()[e.first] - x;
                D += e.second.first*(d*d);
            }
            // det of D over the solution axes, relative to h^(2 dim)
            scalar det = m->dim() == 2
                ? D.xx()*D.yy() - D.xy()*D.yx()
                : Foam::det(D);
            det /= std::pow(h, 2*m->dim());
            std::cout << "  " << m->dim() << "D, " << kn << ": det D_p / h^"
                << 2*m->dim() << " = " << det << std::endl;
            EXPECT_EQ(det > 1e-4, k->invertibleMoments()) << kn << " det " << det;
        }
        EXPECT_TRUE(kernel("linear", *m)->vanishingVertexMass());
        EXPECT_FALSE(kernel("umls", *m)->vanishingVertexMass());
        EXPECT_TRUE(kernel("linear", *m)->nonNegativeAtBoundary());
        EXPECT_FALSE(kernel("umls", *m)->nonNegativeAtBoundary());
    }
}


// stepLength (mpmProperties stepLength kernel): the shortest mean edge for
// linear, the narrowest support h_v for umls (the longest edge by
// default, the graded field with supportSize graded), never shorter
TEST(mpmKernels, stepLengthIsTheNarrowestSupport)
{
    auto m = testMeshes::plane(8, false, 0.2);
    scalar minMean = GREAT, minMax = GREAT;
    forAll(m->vertexSize(), v)
    {
        minMean = min(minMean, m->vertexSize()[v]);
        minMax = min(minMax, m->vertexMaxEdge()[v]);
    }
    EXPECT_DOUBLE_EQ(kernel("linear", *m)->stepLength(), minMean);
    EXPECT_DOUBLE_EQ(kernel("umls", *m)->stepLength(), minMax);
    EXPECT_DOUBLE_EQ
    (
        kernel("umls", *m, "supportSize mean;")->stepLength(), minMean
    );
    const scalar graded =
        kernel("umls", *m, "supportSize graded;")->stepLength();
    EXPECT_GE(graded, minMax);
    std::cout << "  perturbed triangles: shortest mean edge " << minMean
        << ", narrowest umls support " << minMax << ", graded " << graded
        << std::endl;
    EXPECT_GT(minMax, minMean);     // else the checks above tell nothing
}


TEST(mpmKernel, unknownKernelIsFatalIOError)
{
    auto m = testMeshes::line(testMeshes::graded(4, 1.0));
    FatalIOError.throwExceptions();
    try
    {
        kernel("cubic", *m);
        ADD_FAILURE() << "no error for kernel cubic";
    }
    catch (const Foam::IOerror& err)
    {
        EXPECT_NE(err.message().find("'kernel'"), std::string::npos) << err.message();
        EXPECT_NE(err.message().find("umls"), std::string::npos) << err.message();
    }
    FatalIOError.dontThrowExceptions();
}
