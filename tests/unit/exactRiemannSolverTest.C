// Unit tests of the exact Riemann solver (the compressible solver's
// reference): Toro's five tests (his Table 4.3: star pressure, velocity and
// densities, printed to 5-6 significant digits), the Rankine-Hugoniot
// conditions across the Sod shock, continuity through rarefaction fans.

#include "exactRiemannSolver.H"

#include <gtest/gtest.h>
#include <cmath>
#include <stdexcept>

using Foam::exactRiemannSolver;
using state = exactRiemannSolver::state;

namespace
{
struct toroTest
{
    state L, R;
    double pStar, uStar, rhoStarL, rhoStarR;
};

// Toro, Riemann Solvers and Numerical Methods for Fluid Dynamics, 3rd ed.,
// Tables 4.1 and 4.3 (gamma = 1.4)
const toroTest toro[5] =
{
    {{1, 0, 1}, {0.125, 0, 0.1}, 0.30313, 0.92745, 0.42632, 0.26557},
    {{1, -2, 0.4}, {1, 2, 0.4}, 0.00189, 0.0, 0.02185, 0.02185},
    {{1, 0, 1000}, {1, 0, 0.01}, 460.894, 19.5975, 0.57506, 5.99924},
    {{1, 0, 0.01}, {1, 0, 100}, 46.0950, -6.19633, 5.99242, 0.57511},
    {{5.99924, 19.5975, 460.894}, {5.99242, -6.19633, 46.0950},
        1691.64, 8.68975, 14.2823, 31.0426},
};

// The table's values are rounded to 5-6 digits: compare to half a unit in
// the last printed digit, relative, with an absolute floor for 0.00189
void expectTable(double computed, double printed, double floor)
{
    const double tol = std::max(6e-5*std::abs(printed), floor);
    EXPECT_NEAR(computed, printed, tol);
}
}


TEST(exactRiemannSolver, toroStarStates)
{
    for (int i = 0; i < 5; ++i)
    {
        SCOPED_TRACE("Toro test " + std::to_string(i + 1));
        const exactRiemannSolver rs(toro[i].L, toro[i].R, 1.4);
        expectTable(rs.pStar(), toro[i].pStar, 5e-6);
        expectTable(rs.uStar(), toro[i].uStar, 5e-6);
        expectTable(rs.rhoStarLeft(), toro[i].rhoStarL, 5e-6);
        expectTable(rs.rhoStarRight(), toro[i].rhoStarR, 5e-6);
        EXPECT_LE(rs.iterations(), 20);
    }
}


// Symmetric data: the contact does not move, to round-off
TEST(exactRiemannSolver, symmetricDataGiveZeroVelocity)
{
    const exactRiemannSolver rs(toro[1].L, toro[1].R, 1.4);
    EXPECT_NEAR(rs.uStar(), 0, 1e-14);
}


// Sod: mass, momentum and energy fluxes balance across the right shock
TEST(exactRiemannSolver, sodShockSatisfiesRankineHugoniot)
{
    const double g = 1.4;
    const exactRiemannSolver rs(toro[0].L, toro[0].R, g);
    const state R = toro[0].R;
    const state S{rs.rhoStarRight(), rs.uStar(), rs.pStar()};
    // Shock speed from the mass jump
    const double s = (S.rho*S.u - R.rho*R.u)/(S.rho - R.rho);
    auto E = [g](const state& q) { return q.p/(g - 1) + 0.5*q.rho*q.u*q.u; };
    const double mom = S.rho*S.u*(S.u - s) + S.p - (R.rho*R.u*(R.u - s) + R.p);
    const double en = (E(S) + S.p)*S.u - s*E(S) - ((E(R) + R.p)*R.u - s*E(R));
    EXPECT_NEAR(mom, 0, 1e-12);
    EXPECT_NEAR(en, 0, 1e-12);
    // And the sampled solution jumps there
    const state before = rs.sample(s - 1e-9);
    const state after = rs.sample(s + 1e-9);
    EXPECT_NEAR(before.rho, S.rho, 1e-12);
    EXPECT_NEAR(after.rho, R.rho, 1e-12);
}


// The rarefaction fan joins the left and star states continuously
TEST(exactRiemannSolver, rarefactionFanIsContinuous)
{
    const double g = 1.4;
    const exactRiemannSolver rs(toro[0].L, toro[0].R, g);
    const state L = toro[0].L;
    const double cL = std::sqrt(g*L.p/L.rho);
    const double head = L.u - cL;
    const double cStar = cL*std::pow(rs.pStar()/L.p, (g - 1)/(2*g));
    const double tail = rs.uStar() - cStar;
    for (const double s : {head, tail})
    {
        const state a = rs.sample(s - 1e-10);
        const state b = rs.sample(s + 1e-10);
        EXPECT_NEAR(a.rho, b.rho, 1e-9);
        EXPECT_NEAR(a.u, b.u, 1e-9);
        EXPECT_NEAR(a.p, b.p, 1e-9);
    }
    // Isentropic inside the fan: p / rho^gamma constant
    const state mid = rs.sample(0.5*(head + tail));
    EXPECT_NEAR(mid.p/std::pow(mid.rho, g), L.p/std::pow(L.rho, g), 1e-12);
}


TEST(exactRiemannSolver, badDataThrow)
{
    EXPECT_THROW(exactRiemannSolver({1, 0, 1}, {0, 0, 1}, 1.4), std::invalid_argument);
    EXPECT_THROW(exactRiemannSolver({1, 0, -1}, {1, 0, 1}, 1.4), std::invalid_argument);
    // Strong expansion: vacuum generated
    EXPECT_THROW(exactRiemannSolver({1, -20, 1}, {1, 20, 1}, 1.4), std::invalid_argument);
}
