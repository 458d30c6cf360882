// Unit tests of the gas solver's input limits (gasLimits.H) and state
// checks (gasState): values that overflow the scheme's arithmetic (1e300),
// NaN, zero and negative values are refused with a message saying what is
// wrong; gamma and R out of range (also a Cp so large that gamma rounds to
// 1, and a molWeight of 1e300) stop idealGas with a FatalIOError naming the
// entry; an inadmissible lattice state says why (non-finite, non-positive,
// beyond the representable range).

#include "gasLimits.H"
#include "gasState.H"
#include "idealGas.H"
#include "testHelpers.H"

#include <gtest/gtest.h>
#include <limits>
#include <string>

using namespace Foam;
using testHelpers::dictOf;

namespace
{

bool has(const std::string& s, const std::string& part)
{
    return s.find(part) != std::string::npos;
}

} // End anonymous namespace


// In range: the classical cases (Sod, LeBlanc's right state); out: the
// fuzzed values, and combinations whose sound speed or energy overflow
TEST(gasRobustness, stateChecks)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(gasLimits::checkState(1, vector(0, 0, 0), 1, 1.4).empty());
    EXPECT_TRUE
    (
        gasLimits::checkState(1e-3, vector(0, 0, 0), 6.7e-11, 5.0/3).empty()
    );
    EXPECT_TRUE(gasLimits::checkState(1, vector(1e20, 0, 0), 1, 1.4).empty());

    EXPECT_TRUE(has(gasLimits::checkState(1e300, Zero, 1, 1.4), "density"));
    EXPECT_TRUE(has(gasLimits::checkState(0, Zero, 1, 1.4), "density"));
    EXPECT_TRUE(has(gasLimits::checkState(-1, Zero, 1, 1.4), "density"));
    EXPECT_TRUE(has(gasLimits::checkState(nan, Zero, 1, 1.4), "density"));
    EXPECT_TRUE(has(gasLimits::checkState(1, Zero, 1e300, 1.4), "pressure"));
    EXPECT_TRUE(has(gasLimits::checkState(1, Zero, nan, 1.4), "pressure"));
    EXPECT_TRUE
    (
        has(gasLimits::checkState(1, vector(-1e300, 0, 0), 1, 1.4), "velocity")
    );
    EXPECT_TRUE
    (
        has(gasLimits::checkState(1, vector(0, nan, 0), 1, 1.4), "velocity")
    );
    // Each component in range, |U| not
    EXPECT_FALSE(gasLimits::velocityOk(vector(9e19, 9e19, 9e19)));
    EXPECT_TRUE(gasLimits::velocityOk(vector(5e19, 5e19, 5e19)));
}


// gamma and R in range, in both forms; the entry is named otherwise
TEST(gasRobustness, idealGasLimits)
{
    const idealGas ok(dictOf("gamma 1.6666666667; R 1;"));
    EXPECT_NEAR(ok.gamma(), 5.0/3, 1e-9);

    std::string m = testHelpers::ioErrorOf
    (
        []{ idealGas g(dictOf("gamma 1e300; R 1;")); }
    );
    EXPECT_TRUE(has(m, "'gamma'")) << m;
    EXPECT_TRUE(has(m, "1e+300")) << m;
    EXPECT_TRUE(has(m, "<= 100")) << m;

    m = testHelpers::ioErrorOf([]{ idealGas g(dictOf("gamma nan; R 1;")); });
    EXPECT_TRUE(has(m, "'gamma'")) << m;

    m = testHelpers::ioErrorOf([]{ idealGas g(dictOf("gamma 1.4; R 1e300;")); });
    EXPECT_TRUE(has(m, "'R'")) << m;
    EXPECT_TRUE(has(m, "1e-20")) << m;

    // Cp of 1e300: gamma = Cp/(Cp - R) rounds to 1
    m = testHelpers::ioErrorOf
    (
        []
        {
            idealGas g
            (
                dictOf
                (
                    "mixture { specie { molWeight 28.96; }"
                    " thermodynamics { Cp 1e300; Hf 0; } }"
                )
            );
        }
    );
    EXPECT_TRUE(has(m, "'Cp'")) << m;
    EXPECT_TRUE(has(m, "molWeight")) << m;
    EXPECT_TRUE(has(m, "gamma")) << m;

    // molWeight of 1e300: R = RR/molWeight of 8e-297
    m = testHelpers::ioErrorOf
    (
        []
        {
            idealGas g
            (
                dictOf
                (
                    "mixture { specie { molWeight 1e300; }"
                    " thermodynamics { Cp 1004.5; Hf 0; } }"
                )
            );
        }
    );
    EXPECT_TRUE(has(m, "'molWeight'")) << m;
    EXPECT_TRUE(has(m, "R = RR/molWeight")) << m;
}


// A lattice cell is admissible with rho, p > 0, finite and in range; the
// reason is given otherwise
TEST(gasRobustness, admissibleStates)
{
    const double g = 1.4;
    gasState S;
    S.resize(6);
    auto set = [&](label i, double rho, double u, double p)
    {
        S.q[0][i] = rho;
        S.q[1][i] = rho*u;
        S.q[2][i] = 0;
        S.q[3][i] = 0;
        S.q[4][i] = p/(g - 1) + 0.5*rho*u*u;
    };
    set(0, 1, 0, 1);
    set(1, 1, 0, -1e-3);
    set(2, -1, 0, 1);
    set(3, 1e90, 0, 1);
    set(4, 1e-10, 1e36, 1e61);                  // rho E 7.5e61, E/rho 7.5e71
    set(5, 1e-30, 1.4e45, 1e58);                // rho E 1e60, E/rho 1e90
    EXPECT_TRUE(S.admissible(0, g));
    EXPECT_TRUE(S.whyInadmissible(0, g).empty());
    EXPECT_FALSE(S.admissible(1, g));
    EXPECT_TRUE(has(S.whyInadmissible(1, g), "non-positive pressure"));
    EXPECT_FALSE(S.admissible(2, g));
    EXPECT_TRUE(has(S.whyInadmissible(2, g), "non-positive density"));
    EXPECT_FALSE(S.admissible(3, g));
    EXPECT_TRUE(has(S.whyInadmissible(3, g), "representable range"));
    EXPECT_TRUE(S.admissible(4, g));
    EXPECT_FALSE(S.admissible(5, g));
    EXPECT_TRUE(has(S.whyInadmissible(5, g), "representable range"));

    S.q[0][0] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(S.admissible(0, g));
    EXPECT_TRUE(has(S.whyInadmissible(0, g), "non-finite"));
}
