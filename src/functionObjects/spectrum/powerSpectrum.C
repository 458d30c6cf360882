/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "powerSpectrum.H"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

#include <fftw3.h>

// * * * * * * * * * * * * * * * Building blocks * * * * * * * * * * * * * //

std::vector<double> Foam::powerSpectrum::resample
(
    const std::vector<double>& t,
    const std::vector<double>& y,
    std::size_t n
)
{
    std::vector<double> out(n);
    const double t0 = t.front();
    const double dt = (t.back() - t0)/double(n - 1);

    std::size_t j = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
        const double ti = (i + 1 == n) ? t.back() : t0 + dt*double(i);
        while (j + 2 < t.size() && t[j + 1] < ti)
        {
            ++j;
        }
        const double s = (ti - t[j])/(t[j + 1] - t[j]);
        out[i] = (1 - s)*y[j] + s*y[j + 1];
    }
    return out;
}


void Foam::powerSpectrum::detrend(std::vector<double>& y, detrendType type)
{
    const std::size_t n = y.size();
    if (type == detrendType::none || n == 0)
    {
        return;
    }

    double mean = 0;
    for (const double v : y) mean += v;
    mean /= double(n);

    double slope = 0;
    if (type == detrendType::linear && n > 1)
    {
        // Least squares on x = i - (n-1)/2, which has zero mean
        const double xm = 0.5*double(n - 1);
        double sxy = 0, sxx = 0;
        for (std::size_t i = 0; i < n; ++i)
        {
            const double x = double(i) - xm;
            sxy += x*(y[i] - mean);
            sxx += x*x;
        }
        slope = sxy/sxx;
    }

    const double xm = 0.5*double(n - 1);
    for (std::size_t i = 0; i < n; ++i)
    {
        y[i] -= mean + slope*(double(i) - xm);
    }
}


std::vector<double> Foam::powerSpectrum::hann(std::size_t n)
{
    std::vector<double> w(n, 1.0);
    if (n > 1)
    {
        const double pi = 3.14159265358979323846;
        for (std::size_t i = 0; i < n; ++i)
        {
            w[i] = 0.5*(1 - std::cos(2*pi*double(i)/double(n - 1)));
        }
    }
    return w;
}


// * * * * * * * * * * * * * * * * Constructor * * * * * * * * * * * * * * //

Foam::powerSpectrum::powerSpectrum
(
    const std::vector<double>& t,
    const std::vector<double>& y,
    const options& opts
)
{
    if (t.size() != y.size())
    {
        throw std::invalid_argument
        (
            "powerSpectrum: " + std::to_string(t.size()) + " times but "
          + std::to_string(y.size()) + " values"
        );
    }
    if (t.size() < 4)
    {
        throw std::invalid_argument
        (
            "powerSpectrum: needs at least 4 samples, got "
          + std::to_string(t.size())
        );
    }
    for (std::size_t i = 1; i < t.size(); ++i)
    {
        if (!(t[i] > t[i - 1]))
        {
            throw std::invalid_argument
            (
                "powerSpectrum: sample times must increase strictly (sample "
              + std::to_string(i) + ")"
            );
        }
    }
    for (const double v : y)
    {
        if (!std::isfinite(v))
        {
            throw std::invalid_argument("powerSpectrum: non-finite sample value");
        }
    }
    if (opts.zeroPadding < 1)
    {
        throw std::invalid_argument("powerSpectrum: zeroPadding must be >= 1");
    }

    const std::size_t n = std::max<std::size_t>
    (
        opts.nResample ? opts.nResample : t.size(),
        4
    );
    nUniform_ = n;
    sampleInterval_ = (t.back() - t.front())/double(n - 1);
    duration_ = sampleInterval_*double(n);

    std::vector<double> u = resample(t, y, n);
    detrend(u, opts.detrend);

    const std::vector<double> w =
        (opts.window == windowType::hann) ? hann(n) : std::vector<double>(n, 1.0);

    double sumW2 = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
        u[i] *= w[i];
        sumW2 += w[i]*w[i];
    }

    const std::size_t nFFT = n*opts.zeroPadding;
    const std::size_t nBins = nFFT/2 + 1;

    double* in = fftw_alloc_real(nFFT);
    fftw_complex* out = fftw_alloc_complex(nBins);
    if (!in || !out)
    {
        fftw_free(in);
        fftw_free(out);
        throw std::runtime_error("powerSpectrum: FFTW could not allocate memory");
    }
    fftw_plan plan = fftw_plan_dft_r2c_1d(int(nFFT), in, out, FFTW_ESTIMATE);

    std::fill(in, in + nFFT, 0.0);
    std::copy(u.begin(), u.end(), in);
    fftw_execute(plan);

    const double fs = 1.0/sampleInterval_;
    const double norm = 1.0/(fs*sumW2);

    frequency_.resize(nBins);
    power_.resize(nBins);
    for (std::size_t k = 0; k < nBins; ++k)
    {
        const double re = out[k][0];
        const double im = out[k][1];
        const bool edge = (k == 0) || (nFFT % 2 == 0 && k == nBins - 1);
        frequency_[k] = double(k)*fs/double(nFFT);
        power_[k] = (edge ? 1.0 : 2.0)*norm*(re*re + im*im);
    }

    fftw_destroy_plan(plan);
    fftw_free(in);
    fftw_free(out);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

std::vector<Foam::powerSpectrum::peak> Foam::powerSpectrum::peaks
(
    std::size_t nPeaks,
    double minSeparation
) const
{
    std::vector<peak> maxima;
    const std::size_t nb = power_.size();
    for (std::size_t k = 1; k + 1 < nb; ++k)
    {
        if (power_[k] > power_[k - 1] && power_[k] >= power_[k + 1])
        {
            // Parabola through log P at k-1, k, k+1 (exact for a Gaussian
            // peak, close for the Hann main lobe)
            const double tiny = 1e-300;
            const double a = std::log(power_[k - 1] + tiny);
            const double b = std::log(power_[k] + tiny);
            const double c = std::log(power_[k + 1] + tiny);
            const double den = a - 2*b + c;
            double shift = (den < 0) ? 0.5*(a - c)/den : 0;
            shift = std::max(-0.5, std::min(0.5, shift));
            const double df = frequency_[1] - frequency_[0];
            maxima.push_back({frequency_[k] + shift*df, power_[k], k});
        }
    }

    std::sort
    (
        maxima.begin(), maxima.end(),
        [](const peak& p, const peak& q) { return p.power > q.power; }
    );

    const double minDf = minSeparation*resolution();
    std::vector<peak> result;
    for (const peak& p : maxima)
    {
        if (result.size() >= nPeaks) break;
        bool lobe = false;
        for (const peak& q : result)
        {
            if (std::abs(p.frequency - q.frequency) < minDf) { lobe = true; break; }
        }
        if (!lobe) result.push_back(p);
    }
    return result;
}


double Foam::powerSpectrum::totalPower() const
{
    if (frequency_.size() < 2) return 0;
    const double df = frequency_[1] - frequency_[0];
    double s = 0;
    for (const double p : power_) s += p;
    return s*df;
}


// ************************************************************************* //
