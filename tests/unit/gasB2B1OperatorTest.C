// Unit tests of the 1D factors of the gas's B2B1 pressure system
// (gasB2B1Operator, dissertation (3.32)-(3.33)): quadratic B-spline
// velocities on the vertices, linear pressures on the cells.
//  - interior rows: D = int N2_v r_j' = (-1/6, -1/2, 1/2, 1/6) and M = int
//    N2_v r_j = (1, 11, 11, 1)/24 over the four cells around a vertex, W =
//    int_c N2_v = (1, 23, 23, 1)/48 (integrated by hand)
//  - every row, periodic or not, boundaries included: sum_j D = 0 (a
//    uniform pressure has no gradient: the mirror images at the ends make
//    the r_j a partition of unity) and sum_j M = sum_c W = int N2_v over
//    the lattice (1, 1/2 on an end vertex, 47/48 next to it)
//  - a linear pressure's gradient is exact away from the ends: sum_j D_j
//    x_j = int N2_v
//  - no checkerboard in the gradient's null space (the B1B0 collocated
//    central difference would have one): |sum_j D_j (-1)^j| = 2/3
//  - periodic: the W of each cell sum to one over the vertices

#include "gasB2B1Operator.H"

#include <gtest/gtest.h>
#include <cmath>
#include <map>

using namespace Foam;

namespace
{

struct table
{
    std::vector<label> start, cell;
    std::vector<double> D, M, W;
    table(label n, bool periodic)
    {
        gasB2B1Operator::table1D(n, periodic, start, cell, D, M, W);
    }
    label nv() const { return label(start.size()) - 1; }
};

}


TEST(gasB2B1Operator, interiorRows)
{
    const table t(12, false);
    ASSERT_EQ(t.nv(), 13);
    const label v = 6;
    std::map<label, label> at;
    for (label e = t.start[v]; e < t.start[v + 1]; ++e) at[t.cell[e]] = e;
    ASSERT_EQ(at.size(), 4u);
    const double D[4] = {-1.0/6, -0.5, 0.5, 1.0/6};
    const double M[4] = {1.0/24, 11.0/24, 11.0/24, 1.0/24};
    const double W[4] = {1.0/48, 23.0/48, 23.0/48, 1.0/48};
    for (label k = 0; k < 4; ++k)
    {
        ASSERT_EQ(at.count(v - 2 + k), 1u);
        const label e = at[v - 2 + k];
        EXPECT_NEAR(t.D[e], D[k], 1e-15);
        EXPECT_NEAR(t.M[e], M[k], 1e-15);
        EXPECT_NEAR(t.W[e], W[k], 1e-15);
    }
}


TEST(gasB2B1Operator, constantAndLinearPressures)
{
    for (const bool periodic : {false, true})
    {
        for (const label n : {4, 5, 12})
        {
            const table t(n, periodic);
            for (label v = 0; v < t.nv(); ++v)
            {
                double sD = 0, sM = 0, sW = 0, lin = 0;
                for (label e = t.start[v]; e < t.start[v + 1]; ++e)
                {
                    sD += t.D[e];
                    sM += t.M[e];
                    sW += t.W[e];
                    lin += t.D[e]*(t.cell[e] + 0.5);
                }
                EXPECT_NEAR(sD, 0, 1e-14) << "n " << n << " v " << v;
                EXPECT_NEAR(sM, sW, 1e-14) << "n " << n << " v " << v;
                // int N2_v over the lattice: 1 inside, 1/2 on an end,
                // 1 - 1/48 next to it (its tail beyond the end cut off)
                double full = 1;
                if (!periodic && (v == 0 || v == n)) full = 0.5;
                if (!periodic && (v == 1 || v == n - 1)) full = 47.0/48;
                EXPECT_NEAR(sW, full, 1e-14) << "n " << n << " v " << v;
                if (!periodic && v >= 2 && v <= n - 2)
                {
                    EXPECT_NEAR(lin, 1.0, 1e-14) << "n " << n << " v " << v;
                }
            }
        }
    }
}


TEST(gasB2B1Operator, noCheckerboardMode)
{
    const table t(8, true);
    for (label v = 0; v < t.nv(); ++v)
    {
        double g = 0;
        for (label e = t.start[v]; e < t.start[v + 1]; ++e)
        {
            g += t.D[e]*(t.cell[e] % 2 ? -1.0 : 1.0);
        }
        EXPECT_NEAR(std::abs(g), 2.0/3, 1e-14);
    }
}


TEST(gasB2B1Operator, periodicPartitionOfUnity)
{
    const table t(6, true);
    std::vector<double> sum(6, 0.0);
    for (label v = 0; v < t.nv(); ++v)
    {
        for (label e = t.start[v]; e < t.start[v + 1]; ++e)
        {
            sum[t.cell[e]] += t.W[e];
        }
    }
    for (const double s : sum) EXPECT_NEAR(s, 1.0, 1e-14);
}


// A rank's window along one direction: the shortest range holding the
// positions its rows reach; on a periodic direction an arc that may cross
// the seam, the whole circle where the gaps leave nothing out
TEST(gasB2B1Operator, windowCoveringRange)
{
    auto range = [](const std::vector<label>& marked, label n, bool periodic)
    {
        std::vector<bool> mark(n, false);
        for (const label i : marked) mark[i] = true;
        label first = -1, length = -1;
        gasB2B1Operator::coveringRange(mark, periodic, first, length);
        return std::make_pair(first, length);
    };
    using P = std::pair<label, label>;
    EXPECT_EQ(range({3, 4, 7}, 10, false), P(3, 5));
    EXPECT_EQ(range({0, 1, 9}, 10, false), P(0, 10));
    // Across the seam: 9, 0, 1 (the gap 2..8 left out)
    EXPECT_EQ(range({0, 1, 9}, 10, true), P(9, 3));
    // Two gaps: the longer (5..8) is left out, the arc 9..4
    EXPECT_EQ(range({0, 4, 9}, 10, true), P(9, 6));
    // A gap at the end only: no wrap needed
    EXPECT_EQ(range({2, 3, 4}, 10, true), P(2, 3));
    // Every position, and none
    EXPECT_EQ(range({0, 1, 2, 3}, 4, true), P(0, 4));
    EXPECT_EQ(range({}, 4, true).second, 0);
    EXPECT_EQ(range({}, 4, false).second, 0);
}
