// Unit tests of Foam::powerSpectrum (the core of the spectrum function object)

#include "powerSpectrum.H"

#include <gtest/gtest.h>
#include <cmath>
#include <random>

using Foam::powerSpectrum;

namespace
{
const double pi = 3.14159265358979323846;

powerSpectrum::options defaults()
{
    return powerSpectrum::options();
}

// Times with steps drawn uniformly from [0.5, 1.5] dt0 (adaptive stepping)
std::vector<double> nonUniformTimes(double T, double dt0, unsigned seed)
{
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> step(0.5*dt0, 1.5*dt0);
    std::vector<double> t{0.0};
    while (t.back() < T)
    {
        t.push_back(t.back() + step(gen));
    }
    return t;
}
}


// The acceptance test: two sines, noise, non-uniform time steps;
// both frequencies found within one frequency bin (1/T).
TEST(powerSpectrum, twoSinesWithNoiseAndNonUniformSteps)
{
    const double f1 = 3.1, a1 = 1.0;
    const double f2 = 7.7, a2 = 0.5;
    const std::vector<double> t = nonUniformTimes(20.0, 0.01, 1);

    std::mt19937 gen(2);
    std::normal_distribution<double> noise(0.0, 0.3);
    std::vector<double> y(t.size());
    for (std::size_t i = 0; i < t.size(); ++i)
    {
        y[i] = a1*std::sin(2*pi*f1*t[i]) + a2*std::sin(2*pi*f2*t[i] + 0.4)
             + noise(gen);
    }

    const powerSpectrum ps(t, y, defaults());
    const double bin = ps.resolution();
    ASSERT_NEAR(bin, 1.0/20.0, 0.002);

    const std::vector<powerSpectrum::peak> pk = ps.peaks(2);
    ASSERT_EQ(pk.size(), 2u);
    // Strongest is the larger sine
    EXPECT_NEAR(pk[0].frequency, f1, bin);
    EXPECT_NEAR(pk[1].frequency, f2, bin);
    // The power ratio follows the amplitudes squared (4), within 30 %: the
    // peak bins carry noise and the picket-fence loss of a 4x padded Hann
    EXPECT_NEAR(pk[0].power/pk[1].power, 4.0, 1.2);
}


// Parseval: the integral of the one-sided density is the mean square, A^2/2
// for a sine. Many periods in the window: the Hann weighting changes the
// mean square by O(1/periods) only, hence 1 %.
TEST(powerSpectrum, sineCarriesHalfAmplitudeSquared)
{
    const double A = 2.5, f = 5.0;
    std::vector<double> t, y;
    for (int i = 0; i < 4000; ++i)
    {
        t.push_back(0.005*i);
        y.push_back(A*std::sin(2*pi*f*t.back()));
    }
    const powerSpectrum ps(t, y, defaults());
    EXPECT_NEAR(ps.totalPower(), 0.5*A*A, 0.01*0.5*A*A);

    powerSpectrum::options rect = defaults();
    rect.window = powerSpectrum::windowType::none;
    const powerSpectrum pr(t, y, rect);
    EXPECT_NEAR(pr.totalPower(), 0.5*A*A, 0.01*0.5*A*A);
}


// A linear drift (a lift coefficient settling, say) must not hide the
// oscillation: linear detrending removes it, the peak is the sine.
TEST(powerSpectrum, linearTrendIsRemoved)
{
    const double f = 0.2;
    std::vector<double> t, y;
    for (int i = 0; i < 3000; ++i)
    {
        t.push_back(0.05*i);
        y.push_back(0.1*std::sin(2*pi*f*t.back()) + 3.0 + 0.5*t.back());
    }
    const powerSpectrum ps(t, y, defaults());
    const std::vector<powerSpectrum::peak> pk = ps.peaks(1);
    ASSERT_EQ(pk.size(), 1u);
    EXPECT_NEAR(pk[0].frequency, f, ps.resolution());
    // Without detrending the ramp's leakage dominates the low bins
    powerSpectrum::options raw = defaults();
    raw.detrend = powerSpectrum::detrendType::none;
    const powerSpectrum pr(t, y, raw);
    EXPECT_GT(pr.power()[0], 100*ps.power()[0]);
}


// Resampling reproduces a linear signal exactly and keeps the end points
TEST(powerSpectrum, resampleIsExactForLines)
{
    const std::vector<double> t = nonUniformTimes(3.0, 0.1, 5);
    std::vector<double> y;
    for (const double x : t) y.push_back(2.0 - 4.0*x);

    const std::vector<double> u = powerSpectrum::resample(t, y, 57);
    ASSERT_EQ(u.size(), 57u);
    const double dt = (t.back() - t.front())/56.0;
    for (std::size_t i = 0; i < u.size(); ++i)
    {
        EXPECT_NEAR(u[i], 2.0 - 4.0*(t.front() + dt*i), 1e-12);
    }
}


// The Hann window is symmetric, zero at both ends and one in the middle
TEST(powerSpectrum, hannWindowShape)
{
    const std::vector<double> w = powerSpectrum::hann(101);
    EXPECT_NEAR(w.front(), 0.0, 1e-15);
    EXPECT_NEAR(w.back(), 0.0, 1e-15);
    EXPECT_NEAR(w[50], 1.0, 1e-15);
    for (std::size_t i = 0; i < w.size(); ++i)
    {
        EXPECT_NEAR(w[i], w[w.size() - 1 - i], 1e-15);
    }
}


// Bad records are refused with a message, never a silent NaN
TEST(powerSpectrum, badInputThrows)
{
    const powerSpectrum::options o = defaults();
    EXPECT_THROW(powerSpectrum({0, 1, 2}, {1, 2, 3}, o), std::invalid_argument);
    EXPECT_THROW(powerSpectrum({0, 1, 1, 2}, {1, 2, 3, 4}, o), std::invalid_argument);
    EXPECT_THROW(powerSpectrum({0, 1, 2, 3}, {1, NAN, 3, 4}, o), std::invalid_argument);
    EXPECT_THROW(powerSpectrum({0, 1, 2, 3}, {1, 2, 3}, o), std::invalid_argument);
}
