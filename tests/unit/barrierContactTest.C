/*---------------------------------------------------------------------------*\
  mpmFoam: unit tests of the barrier contact (barrierContact): the barrier
  b(d) = -(d - dHat)^2 ln(d/dHat), its derivatives against finite
  differences, the friction mollifier's limits, the nearest points of
  segments and triangles against sampling, the force on a particle near a
  wall and the implicit friction's sliding and sticking limits, a contact
  surface inside the mesh (a faceZone) pushing from both sides and
  refusing a step through it, and the path-face intersection.
\*---------------------------------------------------------------------------*/

#include "barrierContact.H"
#include "testMeshes.H"
#include "IStringStream.H"
#include "dictionary.H"

#include <gtest/gtest.h>
#include <cmath>
#include <random>

using namespace Foam;

namespace
{

dictionary dictOf(const std::string& text)
{
    IStringStream is(text);
    return dictionary(is);
}

} // End anonymous namespace


TEST(barrierContact, barrierSignsAndSupport)
{
    const scalar dHat = 0.01;
    for (const scalar r : {0.01, 0.1, 0.5, 0.9, 0.999})
    {
        const scalar d = r*dHat;
        EXPECT_GT(barrierContact::barrier(d, dHat), 0) << d;
        EXPECT_LT(barrierContact::barrierD1(d, dHat), 0) << d;  // repels
        EXPECT_GT(barrierContact::barrierD2(d, dHat), 0) << d;  // convex
    }
    for (const scalar d : {dHat, 1.5*dHat, 10*dHat})
    {
        EXPECT_EQ(barrierContact::barrier(d, dHat), 0);
        EXPECT_EQ(barrierContact::barrierD1(d, dHat), 0);
        EXPECT_EQ(barrierContact::barrierD2(d, dHat), 0);
    }
    // C2 at dHat: b, b', b'' -> 0 from below
    const scalar d = dHat*(1 - 1e-6);
    EXPECT_LT(barrierContact::barrier(d, dHat), 1e-15);
    EXPECT_LT(std::abs(barrierContact::barrierD1(d, dHat)), 1e-12);
    EXPECT_LT(barrierContact::barrierD2(d, dHat), 1e-5);
    // Unbounded at the wall
    EXPECT_GT(barrierContact::barrier(1e-12*dHat, dHat), 20*dHat*dHat);
    EXPECT_GT(-barrierContact::barrierD1(1e-9*dHat, dHat), 1e8*dHat);
    // Magnitude at d = dHat/2: -(dHat/2)^2 ln(1/2)
    EXPECT_NEAR
    (
        barrierContact::barrier(0.5*dHat, dHat),
        0.25*dHat*dHat*std::log(2.0), 1e-18
    );
}


TEST(barrierContact, derivativesMatchFiniteDifferences)
{
    const scalar dHat = 0.004;
    for (const scalar r : {0.05, 0.2, 0.5, 0.8, 0.95})
    {
        const scalar d = r*dHat;
        const scalar h = 1e-6*dHat;
        const scalar fd1 =
            (barrierContact::barrier(d + h, dHat)
           - barrierContact::barrier(d - h, dHat))/(2*h);
        const scalar fd2 =
            (barrierContact::barrierD1(d + h, dHat)
           - barrierContact::barrierD1(d - h, dHat))/(2*h);
        EXPECT_NEAR(barrierContact::barrierD1(d, dHat), fd1, 1e-7*std::abs(fd1))
            << "d/dHat " << r;
        EXPECT_NEAR(barrierContact::barrierD2(d, dHat), fd2, 1e-7*std::abs(fd2))
            << "d/dHat " << r;
    }
}


TEST(barrierContact, mollifierLimits)
{
    EXPECT_EQ(barrierContact::mollifier(0), 0);
    EXPECT_DOUBLE_EQ(barrierContact::mollifier(1), 1);
    EXPECT_EQ(barrierContact::mollifier(2), 1);
    EXPECT_EQ(barrierContact::mollifier(1e6), 1);
    // Slope 2 at rest (the viscous ramp), 0 at s = 1 (C1 join)
    const scalar h = 1e-7;
    EXPECT_NEAR(barrierContact::mollifier(h)/h, 2, 1e-6);
    EXPECT_NEAR((1 - barrierContact::mollifier(1 - h))/h, 0, 1e-6);
    scalar last = 0;
    for (label i = 1; i <= 100; ++i)
    {
        const scalar f = barrierContact::mollifier(0.01*i);
        EXPECT_GT(f, last);
        last = f;
    }
}


TEST(barrierContact, nearestPointsAgainstSampling)
{
    std::mt19937 gen(3);
    std::uniform_real_distribution<double> u(-1, 1);
    auto rv = [&]() { return vector(u(gen), u(gen), u(gen)); };
    const label n = 400;
    for (label trial = 0; trial < 200; ++trial)
    {
        const vector a = rv(), b = rv(), c = rv(), x = 2*rv();
        const vector q = barrierContact::nearestOnTriangle(a, b, c, x);
        // q lies on the triangle: its barycentric coordinates are >= 0
        const vector nrm = (b - a) ^ (c - a);
        const scalar A = mag(nrm);
        const scalar la = (((b - q) ^ (c - q)) & nrm)/(A*A);
        const scalar lb = (((c - q) ^ (a - q)) & nrm)/(A*A);
        const scalar lc = (((a - q) ^ (b - q)) & nrm)/(A*A);
        EXPECT_GT(min(la, min(lb, lc)), -1e-9);
        EXPECT_NEAR(la + lb + lc, 1, 1e-9);
        // No sample of the triangle is nearer
        scalar best = GREAT;
        for (label i = 0; i <= n; ++i)
        for (label j = 0; i + j <= n; ++j)
        {
            const vector s = a + (scalar(i)/n)*(b - a) + (scalar(j)/n)*(c - a);
            best = min(best, mag(x - s));
        }
        EXPECT_LE(mag(x - q), best + 1e-12);
        EXPECT_GT(mag(x - q), best - 5.0/n);

        const vector qs = barrierContact::nearestOnSegment(a, b, x);
        scalar bestS = GREAT;
        for (label i = 0; i <= 10*n; ++i)
        {
            bestS = min(bestS, mag(x - (a + (scalar(i)/(10*n))*(b - a))));
        }
        EXPECT_LE(mag(x - qs), bestS + 1e-12);
        EXPECT_GT(mag(x - qs), bestS - 1.0/n);
    }
}


// A particle above the floor y = 0 of a 2D triangle mesh: the barrier
// force points up with magnitude kappa |b'(d)|; the implicit friction
// slides (u = u_t - dt B/m) or nearly stops (u solves the ramp)
TEST(barrierContact, forceAndFrictionOnAFloor)
{
    auto mesh = testMeshes::plane(4, false, 0.0);
    const scalar x1 = mesh->bbMax().x();
    List<barrierContact::face> faces(1);
    faces[0].a = vector(0, 0, 0);
    faces[0].b = vector(x1, 0, 0);
    faces[0].c = faces[0].b;
    faces[0].nOut = vector(0, -1, 0);
    faces[0].patch = 0;
    faces[0].segment = true;
    const scalar h = x1/4;
    const scalar dHat = 0.25*h;
    const scalar mu = 0.5;
    const scalar epsV = 1e-3;
    barrierContact contact
    (
        *mesh, faces, wordList({"floor"}),
        dictOf
        (
            "dHat " + std::to_string(dHat) + "; friction 0.5; epsV 1e-3;"
        )
    );
    const scalar E = 1e6;
    contact.setMaterials(scalarList(1, E));

    mpmParticles P;
    const scalar d = 0.5*dHat;
    const vector xp(1.3*h, d, 0);
    const label c = mesh->findCell(xp, 0);
    ASSERT_GE(c, 0);
    ASSERT_TRUE(contact.nearWall(c));
    P.append(xp, vector(2, -1, 0), tensor::I, 1.0, 1e-4, 0, c);

    // Weights: the barycentric ones of the particle's cell
    kernelWeights kw;
    kw.clear();
    mpmMeshView::shapeValues sv;
    mesh->shapeFunctions(c, xp, sv);
    for (label i = 0; i < sv.n; ++i)
    {
        kw.append(mesh->cellVertices()[mesh->cellBegin(c) + i], sv.B[i], sv.gradB[i]);
    }
    kw.start.append(kw.vertex.size());

    List<vector> f(1);
    contact.forces(P, kw, f);
    const scalar kappa = E*1e-4/(dHat*dHat);
    const scalar lambda = -kappa*barrierContact::barrierD1(d, dHat);
    EXPECT_NEAR(f[0].x(), 0, 1e-12*lambda);
    EXPECT_NEAR(f[0].y(), lambda, 1e-10*lambda);
    EXPECT_EQ(contact.nWithin(), 1);
    EXPECT_NEAR(contact.minDistance(), d, 1e-12);

    // The step check: a displacement shorter than d passes, one through
    // the wall is refused (out of the mesh: dist -1)
    {
        scalar dist = 0;
        List<vector> vg(1, vector(0.3, -1, 0));
        EXPECT_EQ(contact.check(P, vg, 0.5*d, dist), -1);
        EXPECT_EQ(contact.check(P, vg, 2*d, dist), 0);
        EXPECT_EQ(dist, -1);
    }

    // The vertices' friction bounds sum to mu lambda
    scalar Bsum = 0;
    for (const label i : contact.touched()) Bsum += contact.vertexBound()[i];
    EXPECT_NEAR(Bsum, mu*lambda, 1e-10*lambda);

    // Sliding: u_t large, the vertex loses dt B/m of tangential speed and
    // keeps its normal velocity
    const label nV = mesh->nVertices();
    scalarList mass(nV, 1.0);
    List<vector> vel(nV, vector(10, -0.3, 0));
    const scalar dt = 1e-5;
    const labelList touched(contact.touched());
    contact.friction(mass, touched, dt, vel);
    for (const label i : touched)
    {
        const scalar B = contact.vertexBound()[i];
        EXPECT_NEAR(vel[i].x(), 10 - dt*B, 1e-9) << "vertex " << i;
        EXPECT_NEAR(vel[i].y(), -0.3, 1e-12);
    }

    // Sticking: u_t below dt B/m: the speed left u solves
    // m (u - u_t) = -dt B f1(u/epsV), below epsV
    const scalar ut = 1e-3;
    vel = vector(ut, 0, 0);
    contact.friction(mass, touched, 1.0, vel);
    for (const label i : touched)
    {
        const scalar B = contact.vertexBound()[i];
        const scalar uu = vel[i].x();
        EXPECT_GE(uu, 0);
        EXPECT_LT(uu, ut);
        if (B > 1e-6)
        {
            EXPECT_LT(uu, epsV);
            EXPECT_NEAR(uu - ut, -B*barrierContact::mollifier(uu/epsV), 1e-12);
        }
    }
    contact.resetVertices(touched);
    for (label i = 0; i < nV; ++i) EXPECT_EQ(contact.vertexBound()[i], 0);
}


// An internal floor (a faceZone's faces: surface index past the patches)
// at y = 2 across the 4 x 4 mesh: the barrier pushes a particle away from
// it on either side, and a step through it, which stays inside the mesh,
// is refused (distance 0) while a shorter one passes
TEST(barrierContact, internalZoneFloor)
{
    auto mesh = testMeshes::plane(4, false, 0.0);
    const scalar x1 = mesh->bbMax().x();
    const scalar y0 = 0.5*(mesh->bbMin().y() + mesh->bbMax().y());
    List<barrierContact::face> faces(1);
    faces[0].a = vector(0, y0, 0);
    faces[0].b = vector(x1, y0, 0);
    faces[0].c = faces[0].b;
    faces[0].nOut = vector(0, 1, 0);
    faces[0].patch = 0;         // no patches: zone 0
    faces[0].segment = true;
    const scalar h = x1/4;
    const scalar dHat = 0.25*h;
    barrierContact contact
    (
        *mesh, faces, wordList(),
        dictOf("dHat " + std::to_string(dHat) + ";"), wordList({"floor"})
    );
    contact.setMaterials(scalarList(1, 1e6));
    EXPECT_EQ(contact.zoneNames().size(), 1);

    const scalar d = 0.5*dHat;
    const scalar kappa = 1e6*1e-4/(dHat*dHat);
    const scalar lambda = -kappa*barrierContact::barrierD1(d, dHat);
    for (const scalar side : {1.0, -1.0})
    {
        mpmParticles P;
        const vector xp(1.3*h, y0 + side*d, 0);
        const label c = mesh->findCell(xp, 0);
        ASSERT_GE(c, 0);
        ASSERT_TRUE(contact.nearWall(c));
        P.append(xp, vector(0, -side, 0), tensor::I, 1.0, 1e-4, 0, c);

        kernelWeights kw;
        kw.clear();
        mpmMeshView::shapeValues sv;
        mesh->shapeFunctions(c, xp, sv);
        for (label i = 0; i < sv.n; ++i)
        {
            kw.append(mesh->cellVertices()[mesh->cellBegin(c) + i], sv.B[i], sv.gradB[i]);
        }
        kw.start.append(kw.vertex.size());

        List<vector> f(1);
        contact.forces(P, kw, f);
        EXPECT_NEAR(f[0].x(), 0, 1e-12*lambda) << "side " << side;
        EXPECT_NEAR(f[0].y(), side*lambda, 1e-10*lambda) << "side " << side;

        // Towards the floor: half the distance passes; twice the distance
        // (through the floor, still inside the mesh) is refused
        scalar dist = -2;
        const List<vector> vg(1, vector(0.2, -side, 0));
        EXPECT_EQ(contact.check(P, vg, 0.5*d, dist), -1) << "side " << side;
        EXPECT_EQ(contact.check(P, vg, 2*d, dist), 0) << "side " << side;
        EXPECT_EQ(dist, 0) << "side " << side;
        // Away from it: any length inside the mesh passes
        const List<vector> away(1, vector(0, side, 0));
        EXPECT_EQ(contact.check(P, away, 0.5*h, dist), -1) << "side " << side;
    }
}


// The path x0 -> x1 against a triangle and a segment: crossing, missing
// beside, stopping short, parallel
TEST(barrierContact, pathMeetsFaces)
{
    barrierContact::face t;
    t.a = vector(0, 0, 0);
    t.b = vector(1, 0, 0);
    t.c = vector(0, 1, 0);
    t.nOut = vector(0, 0, 1);
    t.patch = 0;
    t.segment = false;
    EXPECT_TRUE(barrierContact::pathMeets(t, vector(0.2, 0.2, 1), vector(0.2, 0.2, -1)));
    EXPECT_TRUE(barrierContact::pathMeets(t, vector(0.2, 0.2, -0.1), vector(0.3, 0.1, 0.1)));
    EXPECT_FALSE(barrierContact::pathMeets(t, vector(0.6, 0.6, 1), vector(0.6, 0.6, -1)));   // beside
    EXPECT_FALSE(barrierContact::pathMeets(t, vector(0.2, 0.2, 1), vector(0.2, 0.2, 0.01))); // short
    EXPECT_FALSE(barrierContact::pathMeets(t, vector(0.2, 0.2, 1), vector(0.3, 0.2, 1)));    // parallel

    barrierContact::face s;
    s.a = vector(0, 0, 0);
    s.b = vector(1, 0, 0);
    s.c = s.b;
    s.nOut = vector(0, 1, 0);
    s.patch = 0;
    s.segment = true;
    EXPECT_TRUE(barrierContact::pathMeets(s, vector(0.5, 1, 0), vector(0.4, -1, 0)));
    EXPECT_FALSE(barrierContact::pathMeets(s, vector(1.5, 1, 0), vector(1.5, -1, 0)));   // beside
    EXPECT_FALSE(barrierContact::pathMeets(s, vector(0.5, 1, 0), vector(0.5, 0.1, 0)));  // short
    EXPECT_FALSE(barrierContact::pathMeets(s, vector(0, 1, 0), vector(1, 1, 0)));        // parallel
}


// Bad settings: FatalIOError naming the entry
TEST(barrierContact, badEntries)
{
    auto mesh = testMeshes::plane(2, false, 0.0);
    List<barrierContact::face> faces(1);
    faces[0].a = vector(0, 0, 0);
    faces[0].b = vector(1, 0, 0);
    faces[0].c = faces[0].b;
    faces[0].nOut = vector(0, -1, 0);
    faces[0].patch = 0;
    faces[0].segment = true;
    FatalIOError.throwExceptions(true);
    for (const char* text : {"dHat 0;", "dHat -1;", "friction -0.1;", "stiffness 0;", "epsV 0;"})
    {
        bool threw = false;
        try
        {
            barrierContact c(*mesh, faces, wordList({"w"}), dictOf(text));
        }
        catch (const Foam::IOerror& e)
        {
            threw = true;
            const std::string key = std::string(text).substr(0, std::string(text).find(' '));
            EXPECT_NE(std::string(e.message()).find("'" + key + "'"), std::string::npos)
                << e.message();
        }
        EXPECT_TRUE(threw) << text;
    }
    FatalIOError.throwExceptions(false);
}


// ************************************************************************* //
