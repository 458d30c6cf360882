// Unit tests of BSMS-GNN's non-parametric transitions (4.3.2): the
// contribution table C on a hand-computed example, its columns summing to
// one, down- and up-sampling of constants (scalar and vector) at every
// level and through the whole hierarchy, and why the up-sampling divides by
// C's row sums (the literal C^T does not keep constants).

#include "bsmsTransition.H"
#include "bsmsPooling.H"
#include "bsmsTestMeshes.H"

#include <gtest/gtest.h>

using namespace Foam;
using namespace bsmsTestMeshes;

namespace
{
// A chain 0 - 1 - ... - (n-1) along x
meshGraph chain(label n)
{
    pointField x(n);
    labelList a(n - 1), b(n - 1);
    for (label i = 0; i < n; ++i) x[i] = point(i, 0, 0);
    for (label i = 0; i + 1 < n; ++i) { a[i] = i; b[i] = i + 1; }
    return meshGraph(x, a, b);
}
}


// Three nodes 0 - 1 - 2: the middle one is pooled.  Shares w_i/(deg_i + 1):
// 1/2, 1/3, 1/2; their sum 4/3 is the coarse weight; C = 3/8, 1/4, 3/8.
TEST(bsmsTransition, handComputedTable)
{
    const meshGraph g = chain(3);
    const bsmsPooling P("closeCenter", 1);
    const labelList I = P.select(g);
    ASSERT_EQ(I, labelList({1}));
    const bsmsTransition T(g, I, scalarList(3, 1.0));
    ASSERT_EQ(T.senders(), labelList({0, 1, 2}));
    // Sums of three exact binary fractions' quotients: 1e-15 is round-off
    EXPECT_NEAR(T.contributions()[0], 3.0/8, 1e-15);
    EXPECT_NEAR(T.contributions()[1], 1.0/4, 1e-15);
    EXPECT_NEAR(T.contributions()[2], 3.0/8, 1e-15);
    EXPECT_NEAR(T.coarseWeights()[0], 4.0/3, 1e-15);
    const scalarField down = T.downsample(scalarField({1.0, 2.0, 4.0}));
    EXPECT_NEAR(down[0], 3.0/8 + 2.0/4 + 4*3.0/8, 1e-15);
}


// On every level of 2D and 3D cell and point graphs (two bodies included):
// C's columns sum to one, the coarse weights are positive, and down- then
// up-sampling returns a constant scalar and a constant vector to 1e-12,
// level by level and through the whole hierarchy.  Each value is a sum of
// at most a few hundred terms of size <= 1 (machine epsilon 1.1e-16 each),
// about 1e-14 at worst per level and 1e-13 over ten levels: 1e-12 leaves a
// margin and still catches any wrong weight (errors of order 0.1).
TEST(bsmsTransition, constantsAndColumnSums)
{
    std::vector<std::pair<std::string, meshGraph>> graphs;
    graphs.emplace_back("2D quads, cells", quads2D(40, 30).graph(meshGraph::nodeType::cells));
    graphs.emplace_back("2D triangles, points", triangles2D(30, 20).graph(meshGraph::nodeType::points));
    graphs.emplace_back("3D tets, cells", tets3D(7).graph(meshGraph::nodeType::cells));
    graphs.emplace_back("3D hexes, points", hexes3D(12).graph(meshGraph::nodeType::points));
    meshBuilder two;
    two.block(10, 10, 1, point::zero, 1.0, meshBuilder::HEX);
    two.block(6, 6, 1, point(0, 12, 0), 1.0, meshBuilder::PRISM, 0.2);
    graphs.emplace_back("2D two bodies, cells", two.graph(meshGraph::nodeType::cells));

    for (const auto& gc : graphs)
    {
        SCOPED_TRACE(gc.first);
        bsmsPooling P("closeCenter", 10);
        P.build(gc.second);
        const PtrList<bsmsTransition> T = bsmsTransition::chain(P);
        ASSERT_EQ(T.size(), P.nLevels() - 1);
        ASSERT_GE(T.size(), 3);

        const vector c(1.5, -2, 3);
        vectorField v(P.graph(0).nNodes(), c);
        scalarField s(P.graph(0).nNodes(), 0.7);
        for (label l = 0; l < T.size(); ++l)
        {
            const bsmsTransition& t = T[l];
            ASSERT_EQ(t.nFine(), P.graph(l).nNodes());
            ASSERT_EQ(t.nCoarse(), P.graph(l + 1).nNodes());
            scalar worstCol = 0;
            for (label j = 0; j < t.nCoarse(); ++j)
            {
                scalar sum = 0;
                for (label e = t.offsets()[j]; e < t.offsets()[j + 1]; ++e)
                {
                    sum += t.contributions()[e];
                }
                worstCol = max(worstCol, mag(sum - 1));
            }
            EXPECT_LT(worstCol, 1e-12) << "level " << l;
            EXPECT_GT(min(t.coarseWeights()), 0) << "level " << l;

            // One level: down and up
            const scalarField mid = t.downsample(scalarField(t.nFine(), 0.7));
            const scalarField up = t.upsample(mid);
            EXPECT_LT(max(mag(up - 0.7)), 1e-12) << "level " << l;

            // Down through every level
            v = t.downsample(v);
            s = t.downsample(s);
            EXPECT_LT(max(mag(v - c)), 1e-12) << "level " << l + 1;
        }
        // ... and up again to the finest level
        for (label l = T.size() - 1; l >= 0; --l)
        {
            v = T[l].upsample(v);
            s = T[l].upsample(s);
        }
        ASSERT_EQ(v.size(), P.graph(0).nNodes());
        EXPECT_LT(max(mag(v - c)), 1e-12);
        EXPECT_LT(max(mag(s - 0.7)), 1e-12);
    }
}


// The literal up-sampling v_i = sum_j C_ij v_j (rows of C not normalised)
// on a uniform chain: every interior receiver has three senders of share
// 1/3, so C_ij = 1/3 and a constant 1 comes back as 1/3 at pooled nodes
// (one receiver: itself) and 2/3 between them (two receivers).  The
// normalised up-sampling returns 1 everywhere.
TEST(bsmsTransition, literalTransposeDoesNotKeepConstants)
{
    const label n = 21;
    const meshGraph g = chain(n);
    const bsmsPooling P("closeCenter", 1);
    const labelList I = P.select(g);
    const bsmsTransition T(g, I, scalarList(n, 1.0));

    // Literal C^T from the table by receiver
    scalarField literal(n, 0);
    for (label j = 0; j < T.nCoarse(); ++j)
    {
        for (label e = T.offsets()[j]; e < T.offsets()[j + 1]; ++e)
        {
            literal[T.senders()[e]] += T.contributions()[e];
        }
    }
    std::vector<char> pooled(n, 0);
    for (const label i : I) pooled[i] = 1;
    label nPooled = 0, nBetween = 0;
    for (label i = 3; i < n - 3; ++i)   // away from the chain's ends
    {
        // Three exact thirds: 1e-15 is round-off
        EXPECT_NEAR(literal[i], pooled[i] ? 1.0/3 : 2.0/3, 1e-15) << i;
        nPooled += pooled[i];
        nBetween += !pooled[i];
    }
    EXPECT_GT(nPooled, 5);
    EXPECT_GT(nBetween, 5);

    const scalarField up = T.upsample(scalarField(T.nCoarse(), 1.0));
    EXPECT_LT(max(mag(up - 1.0)), 1e-14);
}
