/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

// mpmSolver::fbarAverage, the F-bar average A f over the kernel support:
//  - it keeps a constant (both weightings);
//  - A is self-adjoint in the mass inner product <f, g> = sum_p m_p f_p g_p;
//  - with FbarAverage convex (|w|/sum |w|) it is a contraction: the
//    power iteration's ratio |A f| / |f| stays <= 1.  With the ring
//    supports' own weights (both signs; vertices near the block's free
//    surfaces whose mass sum w m_p nearly cancels) it is not: the ratio
//    exceeds 1, the volume-ratio pattern it amplifies is the mode that
//    blew up slopeFailure3D on tetrahedra at h = 0.4 m

#include <gtest/gtest.h>
#include "testMeshes.H"
#include "testHelpers.H"
#include "mpmSolver.H"

#include <random>

using namespace Foam;

namespace
{

// A block of particles (spacing s) inside a mesh of perturbed tetrahedra,
// with free surfaces inside the mesh
mpmParticles block(const mpmMeshView& mesh, const scalar lo, const scalar hi, const scalar s)
{
    mpmParticles P;
    const label n = label((hi - lo)/s);
    for (label k = 0; k < n; ++k)
        for (label j = 0; j < n; ++j)
            for (label i = 0; i < n; ++i)
            {
                const vector x
                (
                    lo + (i + 0.5)*s, lo + (j + 0.5)*s, lo + (k + 0.5)*s
                );
                P.append(x, Zero, tensor::I, s*s*s, s*s*s, 0, mesh.findCell(x, 0));
            }
    return P;
}

scalar massNorm(const mpmParticles& P, const scalarList& f)
{
    scalar s = 0;
    forAll(f, p) s += P.m[p]*f[p]*f[p];
    return std::sqrt(s);
}

struct averageProperties
{
    scalar constantError = 0;   //!< max |A 1 - 1|
    scalar asymmetry = 0;       //!< |<A f, g> - <f, A g>| / (|f| |g|)
    scalar growth = 0;          //!< largest |A f| / |f| of a power iteration
};

averageProperties measure(const std::string& average)
{
    auto mesh = testMeshes::box(6, false, 0.2);
    const mpmGridBoundary free;
    const dictionary dict
    (
        testHelpers::dictOf
        (
            "kernel mlsRing; supportSize ring; gradient derivative;"
            "sampleWeight adaptive; transfer FLIP; flipRatio 1;"
            "FbarAverage " + average + ";"
            "materials { clay { type neoHookean; rho 1; E 100; nu 0.45;"
            " Fbar on; } }"
        )
    );
    mpmSolver solver(*mesh, dict, free);
    mpmParticles P = block(*mesh, 1.1, 4.9, 0.2);
    solver.initialise(P);

    averageProperties r;
    const label nP = P.size();
    scalarList one(nP, 1.0);
    solver.fbarAverage(P, one);
    forAll(one, p) r.constantError = max(r.constantError, mag(one[p] - 1));

    std::mt19937 gen(3);
    std::uniform_real_distribution<double> u(-1, 1);
    scalarList f(nP), g(nP);
    forAll(f, p) { f[p] = u(gen); g[p] = u(gen); }
    scalarList Af(f), Ag(g);
    solver.fbarAverage(P, Af);
    solver.fbarAverage(P, Ag);
    scalar fAg = 0, gAf = 0;
    forAll(f, p) { fAg += P.m[p]*f[p]*Ag[p]; gAf += P.m[p]*g[p]*Af[p]; }
    r.asymmetry = mag(fAg - gAf)/(massNorm(P, f)*massNorm(P, g));

    for (label it = 0; it < 60; ++it)
    {
        const scalar before = massNorm(P, f);
        solver.fbarAverage(P, f);
        const scalar after = massNorm(P, f);
        r.growth = max(r.growth, after/before);
        forAll(f, p) f[p] /= after;
    }
    return r;
}

} // namespace


TEST(fbarAverage, convexIsAContractionKernelWeightsAreNot)
{
    const averageProperties convex = measure("convex");
    const averageProperties signedW = measure("kernel");
    std::cout << "  ring supports on tetrahedra, F-bar average with |w|/sum|w|: "
        << "|A1 - 1| " << convex.constantError << ", asymmetry "
        << convex.asymmetry << ", largest |Af|/|f| " << convex.growth
        << "; with the kernel's weights: " << signedW.constantError << ", "
        << signedW.asymmetry << ", " << signedW.growth << std::endl;
    EXPECT_LT(convex.constantError, 1e-12);
    EXPECT_LT(signedW.constantError, 1e-10);
    EXPECT_LT(convex.asymmetry, 1e-12);
    EXPECT_LT(signedW.asymmetry, 1e-10);
    EXPECT_LE(convex.growth, 1 + 1e-12);
    EXPECT_GT(signedW.growth, 1.01);
}
