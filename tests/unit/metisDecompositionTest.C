// Unit tests of the METIS decomposition method (registered as "metis")

#include "decompositionMethod.H"
#include "metisDecomposition.H"
#include "IStringStream.H"

#include <gtest/gtest.h>

using namespace Foam;

namespace
{

// Cell graph of an nx x ny grid of squares, cell centres at (i+0.5, j+0.5)
void gridGraph(label nx, label ny, labelListList& cc, pointField& centres)
{
    cc.setSize(nx*ny);
    centres.setSize(nx*ny);
    for (label j = 0; j < ny; ++j)
    {
        for (label i = 0; i < nx; ++i)
        {
            const label c = i + nx*j;
            DynamicList<label> nbr(4);
            if (i > 0) nbr.append(c - 1);
            if (i < nx - 1) nbr.append(c + 1);
            if (j > 0) nbr.append(c - nx);
            if (j < ny - 1) nbr.append(c + nx);
            cc[c] = nbr;
            centres[c] = point(i + 0.5, j + 0.5, 0);
        }
    }
}

label edgeCut(const labelListList& cc, const labelList& part)
{
    label cut = 0;
    forAll(cc, c)
    {
        for (const label n : cc[c])
        {
            if (n > c && part[n] != part[c]) ++cut;
        }
    }
    return cut;
}

autoPtr<decompositionMethod> method(const std::string& text)
{
    IStringStream is(text);
    const dictionary dict(is);
    return decompositionMethod::New(dict);
}

}


// The loaded library's "metis" is the real method, not Debian's stub
TEST(metisDecomposition, registeredAsMetis)
{
    auto m = method("numberOfSubdomains 2; method metis;");
    EXPECT_TRUE(isA<metisDecomposition>(m()));
}


// k-way on a 40 x 40 grid into 4: balanced within METIS's default 3 % and a
// cut well below the 3 x 40 = 120 faces of strips (the optimum is 80)
TEST(metisDecomposition, kWayBalancesAndCutsLittle)
{
    labelListList cc;
    pointField centres;
    gridGraph(40, 40, cc, centres);

    auto m = method("numberOfSubdomains 4; method metis; metisCoeffs { method k-way; }");
    const labelList part = m->decompose(cc, centres, scalarField());

    ASSERT_EQ(part.size(), 1600);
    labelList count(4, Zero);
    for (const label p : part)
    {
        ASSERT_GE(p, 0);
        ASSERT_LT(p, 4);
        ++count[p];
    }
    for (const label n : count)
    {
        EXPECT_LE(n, 1.03*400);
    }
    const label cut = edgeCut(cc, part);
    EXPECT_LT(cut, 120) << "edge cut " << cut;
}


// processorWeights (3 1): the first subdomain gets three quarters of the cells
TEST(metisDecomposition, processorWeightsSetSubdomainSizes)
{
    labelListList cc;
    pointField centres;
    gridGraph(40, 40, cc, centres);

    for (const char* alg : {"k-way", "recursive"})
    {
        auto m = method
        (
            std::string("numberOfSubdomains 2; method metis; metisCoeffs { method ")
          + alg + "; processorWeights (3 1); }"
        );
        const labelList part = m->decompose(cc, centres, scalarField());
        label n0 = 0;
        for (const label p : part) n0 += (p == 0);
        EXPECT_NEAR(n0/1600.0, 0.75, 0.03) << alg;
    }
}


// Cell weights: the heavy half of the grid (weight 3) is split over more cells
TEST(metisDecomposition, cellWeightsBalanceWeightNotCount)
{
    labelListList cc;
    pointField centres;
    gridGraph(40, 40, cc, centres);
    scalarField w(1600, 1.0);
    forAll(w, c)
    {
        if (centres[c].x() < 20) w[c] = 3.0;
    }

    auto m = method("numberOfSubdomains 2; method metis;");
    const labelList part = m->decompose(cc, centres, w);
    scalar w0 = 0, w1 = 0;
    forAll(part, c)
    {
        (part[c] == 0 ? w0 : w1) += w[c];
    }
    EXPECT_NEAR(w0/(w0 + w1), 0.5, 0.03);
}


// Bad metisCoeffs entries stop with a FatalIOError naming entry and allowed
TEST(metisDecomposition, badCoefficientsAreFatalIOErrors)
{
    FatalIOError.throwExceptions();

    const std::pair<std::string, std::string> cases[] =
    {
        {"method k-ways;", "'method'"},
        {"ufactor 0;", "an integer >= 1"},
        {"processorWeights (1 2 3);", "numberOfSubdomains = 2"},
        {"method recursive; objective volume;", "needs method k-way"},
        {"contiguous maybe;", "'contiguous'"},
    };
    for (const auto& c : cases)
    {
        try
        {
            method("numberOfSubdomains 2; method metis; metisCoeffs { " + c.first + " }");
            ADD_FAILURE() << "no error for: " << c.first;
        }
        catch (const Foam::IOerror& err)
        {
            EXPECT_NE(err.message().find(c.second), std::string::npos)
                << "message for '" << c.first << "' lacks '" << c.second
                << "': " << err.message();
        }
    }

    FatalIOError.dontThrowExceptions();
}
