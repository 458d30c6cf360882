// World (contact) edges of moving bodies (dissertation 4.2.2, Table 4.2's
// Lagrangian graphs): spatialHash finds exactly the pairs a brute-force
// search finds, on random clouds (with and without groups, tiny to huge
// extents) and on two meshed bodies pressed into contact and moved;
// lagrangianGraph keeps its mesh edges fixed while its world edges follow
// the world positions; the levels of a pooling built once take every
// frame's world edges by setContact as a fresh build would; bad input
// stops with a message.

#include "spatialHash.H"
#include "lagrangianGraph.H"
#include "contactEdges.H"
#include "bsmsPooling.H"
#include "bsmsExport.H"
#include "bsmsTestMeshes.H"

#include <gtest/gtest.h>
#include <random>
#include <set>
#include <utility>

using namespace Foam;
using namespace bsmsTestMeshes;

namespace
{

typedef std::set<std::pair<label, label>> edgeSet;

// All pairs i < j closer than r (and of different groups when given)
edgeSet bruteForce(const pointField& x, scalar r, const labelUList& group)
{
    edgeSet s;
    for (label i = 0; i < x.size(); ++i)
    {
        for (label j = i + 1; j < x.size(); ++j)
        {
            if (group.size() && group[i] == group[j]) continue;
            if (magSqr(x[j] - x[i]) < r*r) s.insert({i, j});
        }
    }
    return s;
}

// The pairs of the hash, each checked to be reported once with i < j
edgeSet hashed(const pointField& x, scalar r, const labelUList& group)
{
    DynamicList<label> a, b;
    spatialHash(x, r).pairs(group, a, b);
    edgeSet s;
    for (label e = 0; e < a.size(); ++e)
    {
        EXPECT_LT(a[e], b[e]);
        EXPECT_TRUE(s.insert({a[e], b[e]}).second) << "pair reported twice";
    }
    return s;
}

edgeSet edgesOf(const meshGraph& g)
{
    edgeSet s;
    for (label i = 0; i < g.nNodes(); ++i)
    {
        for (label k = g.offsets()[i]; k < g.offsets()[i + 1]; ++k)
        {
            if (i < g.neighbours()[k]) s.insert({i, g.neighbours()[k]});
        }
    }
    return s;
}

pointField randomCloud(label n, const point& lo, const vector& span, unsigned seed)
{
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> u(0, 1);
    pointField x(n);
    for (point& p : x)
    {
        p = lo + cmptMultiply(span, vector(u(gen), u(gen), u(gen)));
    }
    return x;
}

} // End anonymous namespace


// Random clouds: every radius from a few pairs to most of the cloud, the
// cloud's extent from 1e-6 to 1e6, some of it at negative coordinates
TEST(worldEdges, hashEqualsBruteForceOnRandomClouds)
{
    label nChecked = 0;
    for (const scalar scale : {1e-6, 1.0, 1e6})
    {
        for (const scalar r : {0.01, 0.05, 0.2, 0.7})
        {
            SCOPED_TRACE("scale " + std::to_string(scale) + " radius " + std::to_string(r));
            const pointField x = randomCloud
            (
                700, point(-0.3, -0.5, -0.1)*scale, vector(1, 1, 1)*scale,
                unsigned(7 + 100*r)
            );
            const edgeSet ref = bruteForce(x, r*scale, labelList());
            EXPECT_EQ(hashed(x, r*scale, labelList()), ref);
            labelList group(x.size());
            forAll(group, i) group[i] = (i*7919) % 4;
            EXPECT_EQ(hashed(x, r*scale, group), bruteForce(x, r*scale, group));
            nChecked += ref.size();
        }
    }
    // 2D (all points in one plane) and coincident points
    pointField x = randomCloud(400, point::zero, vector(1, 1, 0), 11);
    x.append(x[0]);
    x.append(x[0]);
    EXPECT_EQ(hashed(x, 0.08, labelList()), bruteForce(x, 0.08, labelList()));
    EXPECT_GT(nChecked, 10000);
}


// Two meshed bodies (tets and hexes) pressed into contact, then moved
// apart and rotated: the world edges are the brute-force pairs of
// different bodies at every configuration, the mesh edges never change
TEST(worldEdges, twoBodiesInContact)
{
    meshBuilder m;
    m.block(6, 5, 4, point::zero, 0.1, meshBuilder::TET, 0.2);
    m.block(4, 4, 4, point(0.62, 0.05, 0.02), 0.1, meshBuilder::HEX);
    const meshGraph g = m.graph(meshGraph::nodeType::points);
    List<lagrangianGraph::nodeKind> kind(g.nNodes(), lagrangianGraph::nodeKind::free);
    lagrangianGraph L(g, kind, 0.08);
    ASSERT_EQ(L.nBodies(), 2);
    const edgeSet meshEdges = edgesOf(L.meshEdges());

    // Body 1 pressed 0.03 into body 0, then 0.2 apart, then rotated back
    // into contact at another place
    const label nB0 = std::count(L.body().begin(), L.body().end(), 0);
    label worldTotal = 0;
    for (int config = 0; config < 3; ++config)
    {
        pointField x(L.X());
        forAll(x, i)
        {
            if (L.body()[i] != 1) continue;
            if (config == 0) x[i] += vector(-0.05, 0, 0);
            if (config == 1) x[i] += vector(0.2, 0, 0);
            if (config == 2)
            {
                const vector d = x[i] - point(0.82, 0.25, 0.22);
                x[i] = point(0.82, 0.25, 0.22)
                     + vector(d.x()*0.8 - d.y()*0.6, d.x()*0.6 + d.y()*0.8, d.z())
                     - vector(0.07, 0, 0);
            }
        }
        L.move(x);
        const meshGraph w = L.worldEdges();
        const edgeSet got = edgesOf(w);
        const edgeSet ref = bruteForce(x, 0.08, L.body());
        EXPECT_EQ(got, ref) << "configuration " << config;
        worldTotal += ref.size();
        if (config == 1) EXPECT_EQ(ref.size(), 0u);
        else EXPECT_GT(ref.size(), 20u);
        for (const auto& e : got)
        {
            EXPECT_NE(L.body()[e.first], L.body()[e.second]);
        }
        EXPECT_EQ(edgesOf(L.meshEdges()), meshEdges);
    }
    EXPECT_GT(nB0, 0);
    EXPECT_GT(worldTotal, 40);

    // Velocity over the last step, from the previous positions
    pointField x2(L.x());
    forAll(x2, i) x2[i] += vector(0, 0.01, 0);
    L.move(x2);
    const vectorField v(L.velocity(0.5));
    EXPECT_NEAR(max(mag(v - vector(0, 0.02, 0))), 0, 1e-12);

    // contactEdges (the static graphs of bsmsLevels) is the same search
    EXPECT_EQ(edgesOf(contactEdges(g, 0.08)), bruteForce(g.positions(), 0.08, L.body()));
}


// (4.1) by its definition: coarse nodes i', j' joined when a hop-contact-hop
// chain (hops optional) links them: a in {i'} + N(i'), b in {j'} + N(j'),
// (a, b) a contact edge of the fine level
edgeSet contactByDefinition
(
    const meshGraph& g,
    const meshGraph& contact,
    const labelUList& pooled
)
{
    labelList coarseOf(g.nNodes(), -1);
    forAll(pooled, k) coarseOf[pooled[k]] = k;
    auto images = [&](const label a)
    {
        std::vector<label> out;
        if (coarseOf[a] >= 0) out.push_back(coarseOf[a]);
        for (label k = g.offsets()[a]; k < g.offsets()[a + 1]; ++k)
        {
            const label c = coarseOf[g.neighbours()[k]];
            if (c >= 0) out.push_back(c);
        }
        return out;
    };
    edgeSet s;
    for (const auto& e : edgesOf(contact))
    {
        for (const label i : images(e.first))
        {
            for (const label j : images(e.second))
            {
                if (i != j) s.insert({min(i, j), max(i, j)});
            }
        }
    }
    return s;
}


// Moving bodies keep their levels (the pooling depends on the mesh edges
// only) and rebuild the contact edges of every level per frame: after
// setContact each level's contact edges are those of (4.1) from the
// frame's world edges (by definition, level by level) and of a fresh build
// with them, and the exported world holds every level's nodes at their
// world positions
TEST(worldEdges, contactLevelsPerFrame)
{
    meshBuilder m;
    m.block(6, 5, 4, point::zero, 0.1, meshBuilder::TET, 0.2);
    m.block(4, 4, 4, point(0.62, 0.05, 0.02), 0.1, meshBuilder::HEX);
    const meshGraph g = m.graph(meshGraph::nodeType::points);
    List<lagrangianGraph::nodeKind> kind(g.nNodes(), lagrangianGraph::nodeKind::free);
    lagrangianGraph L(g, kind, 0.08);

    bsmsPooling P("closeCenter", 10);
    P.build(g);
    ASSERT_GE(P.nLevels(), 3);
    for (label l = 0; l < P.nLevels(); ++l)
    {
        EXPECT_EQ(P.contact(l).nEdges(), 0);
    }
    label contactsSeen = 0;
    for (int config = 0; config < 2; ++config)
    {
        pointField x(L.X());
        forAll(x, i)
        {
            if (L.body()[i] == 1) x[i] += vector(config ? -0.05 : -0.02, 0.01*config, 0);
        }
        L.move(x);
        const meshGraph w = L.worldEdges();
        P.setContact(w);
        bsmsPooling fresh("closeCenter", 10);
        fresh.build(g, w);
        ASSERT_EQ(fresh.nLevels(), P.nLevels());
        for (label l = 0; l < P.nLevels(); ++l)
        {
            EXPECT_EQ(edgesOf(P.contact(l)), edgesOf(fresh.contact(l)))
                << "configuration " << config << " level " << l;
            if (l > 0)
            {
                EXPECT_EQ
                (
                    edgesOf(P.contact(l)),
                    contactByDefinition
                    (
                        P.graph(l - 1), P.contact(l - 1), P.pooled(l - 1)
                    )
                ) << "configuration " << config << " level " << l;
            }
            if (l + 1 < P.nLevels()) EXPECT_EQ(P.pooled(l), fresh.pooled(l));
            contactsSeen += P.contact(l).nEdges();
        }

        const bsmsData::hierarchy h = bsmsExport(P, 3);
        const bsmsData::world wd = bsmsExportWorld(P, x);
        EXPECT_EQ(h.check(wd), "");
        for (label l = 0; l < P.nLevels(); ++l)
        {
            const labelList finest(P.finestNodes(l));
            forAll(finest, k)
            {
                for (direction d = 0; d < 3; ++d)
                {
                    EXPECT_EQ(wd.levels[l].positions[3*k + d], x[finest[k]][d]);
                }
            }
            EXPECT_EQ(label(wd.levels[l].neighbours.size()), 2*P.contact(l).nEdges());
        }
    }
    EXPECT_GT(contactsSeen, 40);

    // A frame of other nodes is refused
    FatalError.throwExceptions();
    EXPECT_THROW(P.setContact(meshGraph(pointField(3), labelList(), labelList())), Foam::error);
    EXPECT_THROW(bsmsExportWorld(P, pointField(3)), Foam::error);
    FatalError.dontThrowExceptions();
}


TEST(worldEdges, badInput)
{
    FatalError.throwExceptions();
    const pointField x = randomCloud(10, point::zero, vector(1, 1, 1), 3);
    auto message = [](auto f)
    {
        try { f(); } catch (const Foam::error& e) { return std::string(e.message()); }
        return std::string("no error");
    };
    EXPECT_NE(message([&]{ spatialHash(x, 0); }).find("is not a finite number > 0"), std::string::npos);
    EXPECT_NE(message([&]{ spatialHash(x, -1); }).find("-1"), std::string::npos);
    pointField bad(x);
    bad[4] = point(0, GREAT*GREAT, 0);
    EXPECT_NE(message([&]{ spatialHash(bad, 0.1); }).find("Point 4"), std::string::npos);
    const meshGraph g(x, labelList({0, 1}), labelList({1, 2}));
    List<lagrangianGraph::nodeKind> kind(10, lagrangianGraph::nodeKind::free);
    EXPECT_NE(message([&]{ lagrangianGraph(g, kind, 0); }).find("World-edge radius 0"), std::string::npos);
    EXPECT_NE(message([&]{ lagrangianGraph(g, List<lagrangianGraph::nodeKind>(3), 0.1); }).find("3 node kinds for 10 nodes"), std::string::npos);
    lagrangianGraph L(g, kind, 0.1);
    EXPECT_NE(message([&]{ L.move(pointField(9)); }).find("9 world positions for 10 nodes"), std::string::npos);
    FatalError.dontThrowExceptions();
}
