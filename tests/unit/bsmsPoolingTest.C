// Unit tests of BSMS-GNN's graphs and bi-stride pooling (src/gnn): mesh
// graphs, Algorithm 4 clusters, the seeding heuristics (Algorithms 2 and
// 3), the enhancement (4.1) against dense matrix products, and the issue's
// acceptance points on 2D and 3D meshes, cell and point graphs: 2-CC, the
// number of connected components kept at every level, 35-65 % of the nodes
// kept per level, contact edges kept in all four cases of the proof in
// 4.2.2, no false edges between sticks head to tail, determinism.

#include "bsmsPooling.H"
#include "contactEdges.H"
#include "bsmsTestMeshes.H"
#include "IStringStream.H"

#include <gtest/gtest.h>
#include <numeric>
#include <vector>

using namespace Foam;
using namespace bsmsTestMeshes;

namespace
{

// Connected components by union-find (independent of meshGraph::clusters)
label components(const meshGraph& g)
{
    std::vector<label> parent(g.nNodes());
    std::iota(parent.begin(), parent.end(), 0);
    std::function<label(label)> root = [&](label i)
    {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    };
    label n = g.nNodes();
    for (label i = 0; i < g.nNodes(); ++i)
    {
        for (label k = g.offsets()[i]; k < g.offsets()[i + 1]; ++k)
        {
            const label a = root(i), b = root(g.neighbours()[k]);
            if (a != b) { parent[a] = b; --n; }
        }
    }
    return n;
}

// Nodes neither pooled nor next to a pooled node (2-CC: none)
label notCovered(const meshGraph& g, const labelUList& pooled)
{
    std::vector<char> in(g.nNodes(), 0);
    for (const label p : pooled) in[p] = 1;
    label bad = 0;
    for (label i = 0; i < g.nNodes(); ++i)
    {
        bool ok = in[i];
        for (label k = g.offsets()[i]; !ok && k < g.offsets()[i + 1]; ++k)
        {
            ok = in[g.neighbours()[k]];
        }
        bad += !ok;
    }
    return bad;
}

// Every acceptance property of a pooling's levels; returns the ratios
std::vector<double> checkLevels(const bsmsPooling& P, const std::string& what)
{
    SCOPED_TRACE(what);
    std::vector<double> ratios;
    const label c0 = components(P.graph(0));
    for (label l = 0; l < P.nLevels(); ++l)
    {
        const meshGraph& g = P.graph(l);
        EXPECT_TRUE(g.valid()) << "level " << l;
        EXPECT_EQ(components(g), c0) << "level " << l;
        if (l + 1 == P.nLevels()) break;
        EXPECT_EQ(notCovered(g, P.pooled(l)), 0) << "level " << l;
        const double r = double(P.graph(l + 1).nNodes())/g.nNodes();
        ratios.push_back(r);
        EXPECT_GE(r, 0.35) << "level " << l + 1 << " of " << g.nNodes();
        EXPECT_LE(r, 0.65) << "level " << l + 1 << " of " << g.nNodes();
    }
    EXPECT_LT(P.graph(P.nLevels() - 1).nNodes(), P.minNodes());
    EXPECT_GE(P.graph(P.nLevels() - 2).nNodes(), P.minNodes());
    return ratios;
}

// Dense boolean matrix of a graph plus the identity
std::vector<std::vector<int>> densePlusI(const meshGraph& g, bool withI)
{
    const label n = g.nNodes();
    std::vector<std::vector<int>> A(n, std::vector<int>(n, 0));
    for (label i = 0; i < n; ++i)
    {
        if (withI) A[i][i] = 1;
        for (label k = g.offsets()[i]; k < g.offsets()[i + 1]; ++k)
        {
            A[i][g.neighbours()[k]] = 1;
        }
    }
    return A;
}

std::vector<std::vector<int>> product
(
    const std::vector<std::vector<int>>& A,
    const std::vector<std::vector<int>>& B
)
{
    const size_t n = A.size();
    std::vector<std::vector<int>> C(n, std::vector<int>(n, 0));
    for (size_t i = 0; i < n; ++i)
        for (size_t k = 0; k < n; ++k)
            if (A[i][k])
                for (size_t j = 0; j < n; ++j)
                    C[i][j] |= B[k][j];
    return C;
}

// A random graph of n nodes with about n*deg/2 edges and some clusters
meshGraph randomGraph(label n, label nEdges, unsigned seed)
{
    std::mt19937 gen(seed);
    std::uniform_int_distribution<label> u(0, n - 1);
    std::uniform_real_distribution<double> x(0, 1);
    pointField pos(n);
    for (auto& p : pos) p = point(x(gen), x(gen), x(gen));
    labelList a(nEdges), b(nEdges);
    for (label e = 0; e < nEdges; ++e) { a[e] = u(gen); b[e] = u(gen); }
    return meshGraph(pos, a, b);
}

// All hop distances from s (-1: unreachable), by the test's own BFS
std::vector<label> hops(const meshGraph& g, label s)
{
    std::vector<label> d(g.nNodes(), -1);
    std::vector<label> q{s};
    d[s] = 0;
    for (size_t h = 0; h < q.size(); ++h)
    {
        const label i = q[h];
        for (label k = g.offsets()[i]; k < g.offsets()[i + 1]; ++k)
        {
            const label j = g.neighbours()[k];
            if (d[j] < 0) { d[j] = d[i] + 1; q.push_back(j); }
        }
    }
    return d;
}

template<class F>
std::string fatalIOMessage(F f)
{
    FatalIOError.throwExceptions();
    std::string msg;
    try { f(); }
    catch (const Foam::IOerror& err) { msg = err.message(); }
    FatalIOError.dontThrowExceptions();
    return msg;
}

} // End anonymous namespace


// ---------------------------------------------------------------- graphs --

// Cell graph: one edge per internal face; point graph: one per mesh edge.
// Counts for an n x m one-layer mesh and an n^3 block of hexes and of
// Freudenthal tets are exact combinatorics.
TEST(meshGraph, edgesOfMeshes)
{
    const meshGraph c2 = quads2D(5, 4).graph(meshGraph::nodeType::cells);
    EXPECT_EQ(c2.nNodes(), 20);
    EXPECT_EQ(c2.nEdges(), 4*4 + 5*3);
    EXPECT_TRUE(c2.valid());
    // Cell centres: cell (1, 2) at (1.5, 2.5, 0.5)
    EXPECT_NEAR(mag(c2.positions()[1 + 5*2] - point(1.5, 2.5, 0.5)), 0, 1e-12);
    EXPECT_TRUE(c2.adjacent(0, 1));
    EXPECT_TRUE(c2.adjacent(0, 5));
    EXPECT_FALSE(c2.adjacent(0, 6));

    const meshGraph p2 = quads2D(5, 4).graph(meshGraph::nodeType::points);
    EXPECT_EQ(p2.nNodes(), 2*6*5);
    EXPECT_EQ(p2.nEdges(), 2*(5*5 + 6*4) + 6*5);

    const label n = 4;
    const meshGraph c3 = hexes3D(n).graph(meshGraph::nodeType::cells);
    EXPECT_EQ(c3.nEdges(), 3*n*n*(n - 1));

    // Freudenthal: axis edges 3 n (n+1)^2, one diagonal per face of the
    // lattice 3 n^2 (n+1), one body diagonal per cube n^3
    const meshGraph p3 = tets3D(n).graph(meshGraph::nodeType::points);
    EXPECT_EQ(p3.nNodes(), (n + 1)*(n + 1)*(n + 1));
    EXPECT_EQ(p3.nEdges(), 3*n*(n + 1)*(n + 1) + 3*n*n*(n + 1) + n*n*n);
    const meshGraph c3t = tets3D(n).graph(meshGraph::nodeType::cells);
    EXPECT_EQ(c3t.nNodes(), 6*n*n*n);
    // Every internal triangle joins two tets: (4 * 6 n^3 - boundary)/2,
    // 2 n^2 boundary triangles per side
    EXPECT_EQ(c3t.nEdges(), (4*6*n*n*n - 6*2*n*n)/2);
}


TEST(meshGraph, fromArraysDropsDuplicatesAndSelfLoops)
{
    const pointField x(4, point::zero);
    const meshGraph g(x, labelList({0, 1, 1, 2, 3}), labelList({1, 0, 1, 3, 2}));
    EXPECT_EQ(g.nEdges(), 2);
    EXPECT_TRUE(g.valid());
    EXPECT_EQ(g.degree(1), 1);
    EXPECT_TRUE(g.adjacent(2, 3));
    EXPECT_FALSE(g.adjacent(1, 1));
}


// Algorithm 4: clusters ordered by their smallest node, nodes ascending;
// single nodes are clusters of their own
TEST(meshGraph, clustersAlgorithm4)
{
    const pointField x(7, point::zero);
    const meshGraph g(x, labelList({5, 0, 2, 6}), labelList({2, 3, 6, 4}));
    labelList off, nodes;
    ASSERT_EQ(g.clusters(off, nodes), 3);
    EXPECT_EQ(off, labelList({0, 2, 3, 7}));
    EXPECT_EQ(nodes, labelList({0, 3, 1, 2, 4, 5, 6}));
    EXPECT_EQ(components(g), 3);
}


// ---------------------------------------------------------------- seeding --

// closeCenter is the node nearest the cluster's centroid and minAve (with
// its pruned BFS) the node of least total hop distance, both exactly as a
// brute force over every node computes them, ties to the lowest index
TEST(bsmsSeeding, seedsMatchBruteForce)
{
    const auto cc = bsmsSeeding::New(word("closeCenter"));
    const auto ma = bsmsSeeding::New(word("minAve"));
    std::vector<meshGraph> graphs;
    for (unsigned s = 1; s <= 6; ++s) graphs.push_back(randomGraph(120, 150, s));
    graphs.push_back(triangles2D(9, 7).graph(meshGraph::nodeType::points));
    graphs.push_back(quads2D(8, 8).graph(meshGraph::nodeType::cells));

    label nChecked = 0;
    for (const meshGraph& g : graphs)
    {
        labelList off, nodes;
        g.clusters(off, nodes);
        const labelList sc = cc->seeds(g, off, nodes);
        const labelList sm = ma->seeds(g, off, nodes);
        for (label k = 0; k + 1 < off.size(); ++k)
        {
            vector centre(Zero);
            for (label m = off[k]; m < off[k + 1]; ++m) centre += g.positions()[nodes[m]];
            centre /= scalar(off[k + 1] - off[k]);
            label bestC = -1, bestM = -1;
            scalar dC = GREAT;
            label sumM = labelMax;
            for (label m = off[k]; m < off[k + 1]; ++m)
            {
                const label i = nodes[m];
                const scalar d = mag(g.positions()[i] - centre);
                if (d < dC) { dC = d; bestC = i; }
                const std::vector<label> h = hops(g, i);
                label sum = 0;
                for (label t = off[k]; t < off[k + 1]; ++t) sum += h[nodes[t]];
                if (sum < sumM) { sumM = sum; bestM = i; }
            }
            EXPECT_EQ(sc[k], bestC);
            EXPECT_EQ(sm[k], bestM);
            ++nChecked;
        }
    }
    EXPECT_GT(nChecked, 20);   // the random graphs have several clusters
}


// ----------------------------------------------------------- enhancement --

// (4.1) A_{l+1} = (A A)[I, I] and A^C_{l+1} = (A A^C A)[I, I] with A the
// graph plus the identity, self-loops dropped: the sparse products equal
// dense boolean products.  Sparse graphs (mean degree ~3) take the sparse
// product, dense ones (mean degree ~40 > 2 words of a bit row) the bit rows.
TEST(bsmsPooling, enhancementEqualsDenseProducts)
{
    for (unsigned s = 1; s <= 6; ++s)
    {
        const meshGraph g = randomGraph(80, s <= 3 ? 110 : 1600, s);
        const meshGraph c = randomGraph(80, 15, s + 100);
        labelList a, b;
        for (label i = 0; i < c.nNodes(); ++i)
        {
            for (label k = c.offsets()[i]; k < c.offsets()[i + 1]; ++k)
            {
                a.append(i);
                b.append(c.neighbours()[k]);
            }
        }
        const meshGraph contact(g.positions(), a, b);
        const bsmsPooling P("closeCenter", 10);
        const labelList I = P.select(g);
        const meshGraph coarse = bsmsPooling::enhance(g, I);
        const meshGraph coarseC = bsmsPooling::enhanceContact(g, contact, I);
        ASSERT_TRUE(coarse.valid());
        ASSERT_TRUE(coarseC.valid());

        const auto A = densePlusI(g, true);
        const auto AA = product(A, A);
        const auto ACA = product(product(A, densePlusI(contact, false)), A);
        label nA = 0, nC = 0;
        forAll(I, a)
        {
            forAll(I, b)
            {
                if (a == b) continue;
                EXPECT_EQ(coarse.adjacent(a, b), bool(AA[I[a]][I[b]]));
                EXPECT_EQ(coarseC.adjacent(a, b), bool(ACA[I[a]][I[b]]));
                nA += AA[I[a]][I[b]];
                nC += ACA[I[a]][I[b]];
            }
        }
        EXPECT_GT(nA, 0);
        EXPECT_GT(nC, 0);
    }
}


// ------------------------------------------------------------- acceptance --

// 2D and 3D meshes, cell and point graphs, both seedings: every level is a
// valid graph with the finest graph's number of components, the pooled
// nodes are 2-CC, each level keeps 35-65 % of the previous one's nodes,
// and the last level is the first with fewer than minNodes nodes
TEST(bsmsPooling, acceptanceOnMeshes)
{
    struct meshCase { const char* name; meshBuilder mesh; };
    std::vector<meshCase> meshes;
    meshes.push_back({"2D quads 60x50", quads2D(60, 50)});
    meshes.push_back({"2D perturbed triangles 2x40x30", triangles2D(40, 30)});
    meshes.push_back({"3D hexes 20^3", hexes3D(20)});
    meshes.push_back({"3D perturbed tets 6x9^3", tets3D(9)});
    // Two bodies and a lone cell: components must stay three
    meshBuilder parts;
    parts.block(30, 20, 1, point::zero, 1.0, meshBuilder::HEX);
    parts.block(25, 10, 1, point(0, 25, 0), 1.0, meshBuilder::PRISM, 0.2);
    parts.block(1, 1, 1, point(40, 40, 0), 1.0, meshBuilder::HEX);
    meshes.push_back({"2D two bodies and a lone cell", parts});

    for (const meshCase& m : meshes)
    {
        for (const auto type : {meshGraph::nodeType::cells, meshGraph::nodeType::points})
        {
            const meshGraph g = m.mesh.graph(type);
            for (const word seeding : {"closeCenter", "minAve"})
            {
                const std::string what = std::string(m.name) + ", "
                    + meshGraph::nodeTypeNames[type] + ", " + seeding;
                bsmsPooling P(seeding, 20);
                P.build(g);
                EXPECT_GE(P.nLevels(), 4) << what;
                const std::vector<double> r = checkLevels(P, what);
                std::ostringstream os;
                for (const double x : r) os << ' ' << x;
                std::cout << "  " << what << ": " << g.nNodes()
                    << " nodes, " << P.nLevels() << " levels, ratios" << os.str()
                    << std::endl;
            }
        }
    }
}


// Pure bi-stride (balance 0) on a 3D mesh: 2-CC and the components hold on
// every level, but once the enhancement has made the graph dense (few BFS
// frontiers) the smaller parity set falls far below 35 % of the nodes;
// the default balance keeps every level at 45-50 % (see bsmsPooling.H)
TEST(bsmsPooling, pureBiStrideUnbalancedOnDenseLevels)
{
    const meshGraph g = hexes3D(20).graph(meshGraph::nodeType::cells);
    bsmsPooling pure("closeCenter", 20, 32, 0), balanced("closeCenter", 20);
    pure.build(g);
    balanced.build(g);
    double pureMin = 1, balancedMin = 1;
    for (label l = 0; l + 1 < pure.nLevels(); ++l)
    {
        EXPECT_EQ(notCovered(pure.graph(l), pure.pooled(l)), 0);
        EXPECT_EQ(components(pure.graph(l + 1)), 1);
        pureMin = min(pureMin, double(pure.graph(l + 1).nNodes())/pure.graph(l).nNodes());
    }
    for (label l = 0; l + 1 < balanced.nLevels(); ++l)
    {
        balancedMin = min
        (
            balancedMin,
            double(balanced.graph(l + 1).nNodes())/balanced.graph(l).nNodes()
        );
    }
    std::cout << "  3D hexes 20^3: least ratio pure " << pureMin
        << ", balanced " << balancedMin << std::endl;
    EXPECT_LT(pureMin, 0.35);
    EXPECT_GE(balancedMin, 0.45);
}


// Same input, same levels: two builds give identical pooled nodes and CSR
TEST(bsmsPooling, deterministic)
{
    const meshGraph g = tets3D(6).graph(meshGraph::nodeType::cells);
    for (const word seeding : {"closeCenter", "minAve"})
    {
        bsmsPooling P1(seeding, 10), P2(seeding, 10);
        P1.build(g);
        P2.build(meshGraph(g));
        ASSERT_EQ(P1.nLevels(), P2.nLevels());
        for (label l = 0; l < P1.nLevels(); ++l)
        {
            EXPECT_EQ(P1.graph(l).offsets(), P2.graph(l).offsets());
            EXPECT_EQ(P1.graph(l).neighbours(), P2.graph(l).neighbours());
            if (l + 1 < P1.nLevels())
            {
                EXPECT_EQ(P1.pooled(l), P2.pooled(l));
            }
        }
    }
}


// The stopping rules: minNodes above the graph's size gives the finest
// level only; maxLevels caps the count; a graph of isolated nodes cannot
// shrink and stops at once; finestNodes follows the pooled lists down
TEST(bsmsPooling, stoppingRulesAndFinestNodes)
{
    const meshGraph g = quads2D(16, 16).graph(meshGraph::nodeType::cells);
    bsmsPooling big("closeCenter", 1000);
    big.build(g);
    EXPECT_EQ(big.nLevels(), 1);

    bsmsPooling capped("closeCenter", 1, 3);
    capped.build(g);
    EXPECT_EQ(capped.nLevels(), 3);

    const pointField x(5, point::zero);
    bsmsPooling lone("closeCenter", 2);
    lone.build(meshGraph(x, labelList(), labelList()));
    EXPECT_EQ(lone.nLevels(), 1);

    bsmsPooling P("closeCenter", 8);
    P.build(g);
    const label L = P.nLevels() - 1;
    const labelList fine = P.finestNodes(L);
    forAll(fine, k)
    {
        EXPECT_EQ(P.graph(L).positions()[k], g.positions()[fine[k]]);
    }
}


// ---------------------------------------------------------------- contact --

namespace
{
// The proof's assertion for every contact edge (i, j) of level l: some
// pooled i' in {i} + N(i) and j' in {j} + N(j) share a contact edge at
// level l + 1.  Counts the edges of each of the proof's four cases (i and
// j pooled; only i; only j; neither), i in the body of the lower cluster.
struct contactCount { label cases[4] = {0, 0, 0, 0}; label lost = 0; };

contactCount checkContacts
(
    const meshGraph& g,
    const meshGraph& contact,
    const labelUList& pooled,
    const meshGraph& coarseContact,
    const labelUList& clusterOf
)
{
    contactCount out;
    labelList coarseOf(g.nNodes(), -1);
    forAll(pooled, k) coarseOf[pooled[k]] = k;
    auto candidates = [&](label i)
    {
        labelList c;
        if (coarseOf[i] >= 0) c.append(coarseOf[i]);
        for (label k = g.offsets()[i]; k < g.offsets()[i + 1]; ++k)
        {
            const label n = g.neighbours()[k];
            if (coarseOf[n] >= 0) c.append(coarseOf[n]);
        }
        return c;
    };
    for (label i = 0; i < g.nNodes(); ++i)
    {
        for (label k = contact.offsets()[i]; k < contact.offsets()[i + 1]; ++k)
        {
            const label j = contact.neighbours()[k];
            if (clusterOf[i] > clusterOf[j]) continue;   // each edge once
            const bool pi = coarseOf[i] >= 0, pj = coarseOf[j] >= 0;
            ++out.cases[pi && pj ? 0 : pi ? 1 : pj ? 2 : 3];
            bool kept = false;
            for (const label a : candidates(i))
                for (const label b : candidates(j))
                    kept = kept || coarseContact.adjacent(a, b);
            out.lost += !kept;
        }
    }
    return out;
}

labelList clusterLabels(const meshGraph& g)
{
    labelList off, nodes, cl(g.nNodes());
    g.clusters(off, nodes);
    for (label k = 0; k + 1 < off.size(); ++k)
        for (label m = off[k]; m < off[k + 1]; ++m) cl[nodes[m]] = k;
    return cl;
}
}


// Two bodies with a gap, contact edges across it by proximity: at every
// level each contact edge survives (4.2.2), and the levels together meet
// all four cases of the proof.  The naive restriction A^C[I, I] (no
// enhancement) loses edges: the check can fail.
TEST(bsmsPooling, contactEdgesSurviveAllFourCases)
{
    struct contactScene { const char* name; meshGraph::nodeType type; meshBuilder mesh; scalar radius; };
    std::vector<contactScene> scenes;
    {
        // 3D: blocks of different sizes facing across x with a 0.2 gap,
        // the second shifted by half a cell in y (one-to-two contacts)
        meshBuilder m;
        m.block(8, 8, 8, point::zero, 1.0, meshBuilder::HEX);
        m.block(7, 9, 8, point(8.2, 0.5, 0), 1.0, meshBuilder::HEX);
        scenes.push_back({"3D hex cells", meshGraph::nodeType::cells, m, 1.35});
    }
    {
        // 2D: triangles above quads, 0.1 apart
        meshBuilder m;
        m.block(20, 10, 1, point::zero, 1.0, meshBuilder::HEX);
        m.block(17, 8, 1, point(1.3, 10.1, 0), 1.0, meshBuilder::PRISM, 0.2);
        scenes.push_back({"2D points", meshGraph::nodeType::points, m, 0.8});
    }

    for (const contactScene& s : scenes)
    {
        SCOPED_TRACE(s.name);
        const meshGraph g = s.mesh.graph(s.type);
        const meshGraph C = contactEdges(g, s.radius);
        ASSERT_GT(C.nEdges(), 10);
        EXPECT_EQ(components(g), 2);

        bsmsPooling P("closeCenter", 10);
        P.build(g, C);
        ASSERT_GE(P.nLevels(), 4);
        contactCount total;
        label naiveLost = 0;
        for (label l = 0; l + 1 < P.nLevels(); ++l)
        {
            const meshGraph& gl = P.graph(l);
            const labelList cl = clusterLabels(gl);
            const contactCount c = checkContacts
            (
                gl, P.contact(l), P.pooled(l), P.contact(l + 1), cl
            );
            EXPECT_EQ(c.lost, 0) << "level " << l;
            EXPECT_GT(P.contact(l + 1).nEdges(), 0) << "level " << l + 1;
            for (label k = 0; k < 4; ++k) total.cases[k] += c.cases[k];

            // Naive: contact edges of pooled pairs only
            labelList coarseOf(gl.nNodes(), -1);
            forAll(P.pooled(l), k) coarseOf[P.pooled(l)[k]] = k;
            labelList a, b;
            const meshGraph& Cl = P.contact(l);
            for (label i = 0; i < gl.nNodes(); ++i)
                for (label k = Cl.offsets()[i]; k < Cl.offsets()[i + 1]; ++k)
                    if (coarseOf[i] >= 0 && coarseOf[Cl.neighbours()[k]] >= 0)
                    {
                        a.append(coarseOf[i]);
                        b.append(coarseOf[Cl.neighbours()[k]]);
                    }
            const meshGraph naive(P.graph(l + 1).positions(), a, b);
            naiveLost += checkContacts(gl, Cl, P.pooled(l), naive, cl).lost;
        }
        std::cout << "  " << s.name << ": contact edges per case (both, i, j,"
            << " neither pooled) " << total.cases[0] << ' ' << total.cases[1]
            << ' ' << total.cases[2] << ' ' << total.cases[3]
            << "; naive restriction loses " << naiveLost << std::endl;
        for (label k = 0; k < 4; ++k)
        {
            EXPECT_GT(total.cases[k], 0) << "case " << k + 1;
        }
        EXPECT_GT(naiveLost, 0);
    }
}


// -------------------------------------------------------------- no false --

// Fig. 4.6: two sticks head to tail with a gap of 1e-3 (a thousandth of
// the finest spacing).  At no level does an edge join them, although the
// gap is far below every coarse level's edge lengths: a pooling by spatial
// proximity at those scales would join them.
TEST(bsmsPooling, noFalseEdgesBetweenSticks)
{
    const scalar gap = 1e-3;
    meshBuilder m;
    m.block(40, 1, 1, point::zero, 1.0, meshBuilder::HEX);
    m.block(40, 1, 1, point(40 + gap, 0, 0), 1.0, meshBuilder::HEX);
    for (const auto type : {meshGraph::nodeType::cells, meshGraph::nodeType::points})
    {
        SCOPED_TRACE(meshGraph::nodeTypeNames[type]);
        const meshGraph g = m.graph(type);
        ASSERT_EQ(components(g), 2);
        for (const word seeding : {"closeCenter", "minAve"})
        {
            bsmsPooling P(seeding, 4);
            P.build(g);
            ASSERT_GE(P.nLevels(), 4);
            for (label l = 0; l < P.nLevels(); ++l)
            {
                const meshGraph& gl = P.graph(l);
                const pointField& x = gl.positions();
                label cross = 0;
                scalar shortest = GREAT;
                for (label i = 0; i < gl.nNodes(); ++i)
                {
                    for (label k = gl.offsets()[i]; k < gl.offsets()[i + 1]; ++k)
                    {
                        const label j = gl.neighbours()[k];
                        cross += (x[i].x() < 40 + gap/2) != (x[j].x() < 40 + gap/2);
                        shortest = min(shortest, mag(x[i] - x[j]));
                    }
                }
                EXPECT_EQ(cross, 0) << seeding << " level " << l;
                EXPECT_EQ(components(gl), 2) << seeding << " level " << l;
                if (l > 0)
                {
                    // The gap is far below the level's shortest edge
                    EXPECT_GT(shortest, 100*gap) << seeding << " level " << l;
                }
            }
        }
    }
}


// ------------------------------------------------------------- bad input --

TEST(bsmsPooling, badDictionaryEntries)
{
    auto dictOf = [](const std::string& text)
    {
        IStringStream is(text);
        return dictionary(is);
    };
    std::string msg = fatalIOMessage([&]{ bsmsPooling P(dictOf("seeding random;")); });
    EXPECT_NE(msg.find("'seeding'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("random"), std::string::npos) << msg;
    EXPECT_NE(msg.find("closeCenter"), std::string::npos) << msg;
    EXPECT_NE(msg.find("minAve"), std::string::npos) << msg;

    msg = fatalIOMessage([&]{ bsmsPooling P(dictOf("minNodes 10;")); });
    EXPECT_NE(msg.find("'seeding' is missing"), std::string::npos) << msg;

    msg = fatalIOMessage([&]{ bsmsPooling P(dictOf("seeding minAve; minNodes 0;")); });
    EXPECT_NE(msg.find("'minNodes'"), std::string::npos) << msg;
    EXPECT_NE(msg.find(">= 1"), std::string::npos) << msg;

    msg = fatalIOMessage([&]{ bsmsPooling P(dictOf("seeding minAve; maxLevels two;")); });
    EXPECT_NE(msg.find("'maxLevels'"), std::string::npos) << msg;
}
