/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
-------------------------------------------------------------------------------
Description
    densityVariation: the seeded heterogeneity of seeded masses.  Its xi
    must be uniform on [-1, 1] (mean 0, variance 1/3, no value outside),
    a function of the seed and the position only, and different for
    different seeds; bad entries stop naming them.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testHelpers.H"
#include "densityVariation.H"
#include "IStringStream.H"
#include <cmath>

using namespace Foam;

namespace
{

dictionary regionWith(const std::string& text)
{
    IStringStream is("densityVariation { " + text + " }");
    return dictionary(is);
}

}


TEST(DensityVariation, uniformOnMinusOneToOne)
{
    const densityVariation v(regionWith("amplitude 0.1; seed 7;"));
    // a lattice of positions, as mpmSetParticles seeds them
    const label n = 200;
    double sum = 0, sum2 = 0, lo = 1, hi = -1;
    label nBins[10] = {0};
    for (label i = 0; i < n; ++i)
    {
        for (label j = 0; j < n; ++j)
        {
            const vector x((i + 0.5)/n, (j + 0.5)/n, 0.5);
            const double xi = v.xi(x);
            sum += xi;
            sum2 += xi*xi;
            lo = std::min(lo, xi);
            hi = std::max(hi, xi);
            ++nBins[std::min(label((xi + 1)*5), label(9))];
        }
    }
    const double N = n*n;
    // mean 0 and variance 1/3 to 5 standard errors (sd of the mean
    // 1/sqrt(3N) = 1.4e-3; of the second moment sqrt(4/45/N) = 1.5e-3)
    EXPECT_NEAR(sum/N, 0, 5*1.45e-3);
    EXPECT_NEAR(sum2/N, 1.0/3.0, 5*1.5e-3);
    EXPECT_GE(lo, -1);
    EXPECT_LE(hi, 1);
    // every tenth of [-1, 1] within 5 sd of N/10 (sd sqrt(N 0.09) = 60)
    for (const label b : nBins) EXPECT_NEAR(b, N/10, 5*60.0);
    // the factor is 1 + a xi
    const vector x(0.3, 0.7, 0.1);
    EXPECT_DOUBLE_EQ(v.factor(x), 1 + 0.1*v.xi(x));
}


TEST(DensityVariation, reproducibleAndSeeded)
{
    const densityVariation a(regionWith("amplitude 0.05; seed 1;"));
    const densityVariation b(regionWith("amplitude 0.05; seed 1;"));
    const densityVariation c(regionWith("amplitude 0.05; seed 2;"));
    label same = 0;
    for (label i = 0; i < 1000; ++i)
    {
        const vector x(0.001*i, 0.5 - 0.0003*i, 0);
        EXPECT_EQ(a.xi(x), b.xi(x));
        if (a.xi(x) == c.xi(x)) ++same;
    }
    EXPECT_EQ(same, 0);
    // neighbouring particles are not correlated: the sign of xi at x and
    // at x + h agrees about half the time
    label agree = 0;
    for (label i = 0; i < 4000; ++i)
    {
        const vector x(0.00025*i, 0.1, 0);
        if ((a.xi(x) > 0) == (a.xi(x + vector(0.00025, 0, 0)) > 0)) ++agree;
    }
    EXPECT_NEAR(agree, 2000, 5*31.6);
}


TEST(DensityVariation, noneWithoutTheEntry)
{
    IStringStream is("material steel;");
    const densityVariation none{dictionary(is)};
    EXPECT_EQ(none.amplitude(), 0);
    EXPECT_EQ(none.factor(vector(0.1, 0.2, 0.3)), 1);
}


TEST(DensityVariation, badEntriesNamed)
{
    FatalIOError.throwExceptions(true);
    for (const char* text :
        {"amplitude 0; seed 1;", "amplitude 0.95; seed 1;",
         "amplitude -0.1;", "amplitude 0.1; seed -1;", "seed 1;"})
    {
        bool threw = false;
        try
        {
            densityVariation v(regionWith(text));
        }
        catch (const Foam::IOerror& e)
        {
            threw = true;
            const std::string t(text);
            const std::string key =
                std::string(t).find("seed -1") != std::string::npos
              ? "seed" : "amplitude";
            EXPECT_NE(std::string(e.message()).find("'" + key + "'"), std::string::npos)
                << e.message();
        }
        EXPECT_TRUE(threw) << text;
    }
    FatalIOError.throwExceptions(false);
}


// ************************************************************************* //
