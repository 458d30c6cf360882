/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

// mpmSolver::checkpoint / rollback (the gas coupling's solid substeps undo
// the substeps they kept when a later one is refused): after a rollback
// the particles and the run's counters are those of the checkpoint, and
// the steps taken from there are the same, bit for bit, as those of a run
// that never took the detour

#include <gtest/gtest.h>
#include "testMeshes.H"
#include "testHelpers.H"
#include "mpmSolver.H"

using namespace Foam;

namespace
{

// A 2 x 2 m block of neoHookean particles (umls + APIC: B restored too) (2 x 2 per cell) in the middle
// of an 8 x 8 mesh of unit quads, spinning and stretching, under gravity
mpmParticles spinningBlock(const mpmMeshView& mesh)
{
    mpmParticles P;
    const label perCell = 2;
    const scalar h = 1.0/perCell;
    for (label j = 0; j < 2*perCell; ++j)
    {
        for (label i = 0; i < 2*perCell; ++i)
        {
            const vector x(3 + (i + 0.5)*h, 3 + (j + 0.5)*h, 0);
            const vector r = x - vector(4, 4, 0);
            const vector v(-0.3*r.y() + 0.1*r.x(), 0.3*r.x(), 0);
            P.append(x, v, tensor::I, h*h, h*h, 0, mesh.findCell(x, 0));
        }
    }
    return P;
}

dictionary solverDict()
{
    return testHelpers::dictOf
    (
        "kernel umls; transfer APIC; gravity (0 -1 0); CFL 0.4;"
        "materials { block { type neoHookean; rho 1; E 100; nu 0.3; } }"
    );
}

void expectSameParticles(const mpmParticles& A, const mpmParticles& B)
{
    ASSERT_EQ(A.size(), B.size());
    forAll(A.x, p)
    {
        EXPECT_EQ(A.x[p], B.x[p]) << "particle " << p;
        EXPECT_EQ(A.v[p], B.v[p]) << "particle " << p;
        EXPECT_EQ(A.B[p], B.B[p]) << "particle " << p;
        EXPECT_EQ(A.F[p], B.F[p]) << "particle " << p;
        EXPECT_EQ(A.V[p], B.V[p]) << "particle " << p;
        EXPECT_EQ(A.sigma[p], B.sigma[p]) << "particle " << p;
        EXPECT_EQ(A.cell[p], B.cell[p]) << "particle " << p;
        EXPECT_EQ(A.id[p], B.id[p]) << "particle " << p;
    }
}

} // namespace


TEST(mpmSolver, rollbackRestoresTheCheckpoint)
{
    auto mesh = testMeshes::plane(8, true, 0.0);
    const mpmGridBoundary free;
    const dictionary dict(solverDict());

    // The reference: three plain steps
    mpmSolver ref(*mesh, dict, free);
    mpmParticles R = spinningBlock(*mesh);
    ref.initialise(R);
    const scalar dt = ref.deltaT(R);
    ASSERT_GT(dt, 0);
    ASSERT_LT(dt, 0.05);

    // The detour: P2G, checkpoint, two steps kept, then back
    mpmSolver solver(*mesh, dict, free);
    mpmParticles P = spinningBlock(*mesh);
    solver.initialise(P);
    ASSERT_TRUE(solver.beginStep(P));
    solver.checkpoint(P);
    const mpmParticles atCheckpoint(P);
    solver.gridUpdate(P, dt);
    ASSERT_TRUE(solver.endStep(P, dt));
    ASSERT_TRUE(solver.step(P, dt));
    ASSERT_NE(P.x[0], atCheckpoint.x[0]);
    ASSERT_GT(solver.particleSteps(), 0);
    solver.rollback(P);
    expectSameParticles(P, atCheckpoint);
    EXPECT_EQ(solver.particleSteps(), 0);
    EXPECT_EQ(solver.time(), 0);

    // From there, the same steps as the reference, bit for bit
    for (label s = 0; s < 3; ++s)
    {
        ASSERT_TRUE(ref.step(R, dt));
        ASSERT_TRUE(solver.step(P, dt));
    }
    expectSameParticles(P, R);
    EXPECT_EQ(solver.particleSteps(), ref.particleSteps());
    EXPECT_EQ(solver.time(), ref.time());
    EXPECT_EQ(solver.treatedTotal(), ref.treatedTotal());
    const mpmSolver::totals a = solver.conservation(P);
    const mpmSolver::totals b = ref.conservation(R);
    EXPECT_EQ(a.momentum, b.momentum);
    EXPECT_EQ(a.kinetic, b.kinetic);
    EXPECT_EQ(a.strain, b.strain);
}


// ************************************************************************* //
