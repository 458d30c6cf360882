/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "normaliser.H"
#include <stdexcept>

namespace gnnTorch
{

normaliserImpl::normaliserImpl
(
    std::int64_t nComp,
    std::int64_t maxAccumulations,
    double epsilon
)
:
    nComp_(nComp),
    maxAccumulations_(maxAccumulations),
    epsilon_(epsilon)
{
    const auto f64 = torch::TensorOptions().dtype(torch::kFloat64);
    const auto i64 = torch::TensorOptions().dtype(torch::kInt64);
    calls_ = register_buffer("calls", torch::zeros({}, i64));
    count_ = register_buffer("count", torch::zeros({}, i64));
    sum_ = register_buffer("sum", torch::zeros({nComp}, f64));
    sumSq_ = register_buffer("sumSq", torch::zeros({nComp}, f64));
}


void normaliserImpl::accumulate(const torch::Tensor& x)
{
    if (x.size(-1) != nComp_)
    {
        throw std::runtime_error
        (
            "normaliser: " + std::to_string(x.size(-1))
          + " components given, " + std::to_string(nComp_) + " expected"
        );
    }
    if (calls_.item<std::int64_t>() >= maxAccumulations_) return;
    torch::NoGradGuard noGrad;
    const torch::Tensor d = x.detach().reshape({-1, nComp_})
        .to(torch::kFloat64);
    calls_ += 1;
    count_ += d.size(0);
    sum_ += d.sum(0);
    sumSq_ += (d*d).sum(0);
}


void normaliserImpl::accumulateParts
(
    const std::vector<std::int64_t>& counts,
    const double* sums,
    const double* sumSqs
)
{
    if (calls_.item<std::int64_t>() >= maxAccumulations_) return;
    torch::NoGradGuard noGrad;
    const auto f64 = torch::TensorOptions().dtype(torch::kFloat64);
    calls_ += 1;
    for (std::size_t k = 0; k < counts.size(); ++k)
    {
        count_ += counts[k];
        sum_ += torch::from_blob
        (
            const_cast<double*>(sums + k*nComp_), {nComp_}, f64
        );
        sumSq_ += torch::from_blob
        (
            const_cast<double*>(sumSqs + k*nComp_), {nComp_}, f64
        );
    }
}


torch::Tensor normaliserImpl::mean() const
{
    const double n = std::max<double>(count_.item<std::int64_t>(), 1);
    return (sum_/n).to(torch::kFloat32);
}


torch::Tensor normaliserImpl::std() const
{
    const double n = std::max<double>(count_.item<std::int64_t>(), 1);
    const torch::Tensor m = sum_/n;
    const torch::Tensor var = torch::clamp_min(sumSq_/n - m*m, 0.0);
    return torch::clamp_min(torch::sqrt(var), epsilon_).to(torch::kFloat32);
}


torch::Tensor normaliserImpl::forward(const torch::Tensor& x) const
{
    return (x - mean())/std();
}


torch::Tensor normaliserImpl::inverse(const torch::Tensor& x) const
{
    return x*std() + mean();
}

} // End namespace gnnTorch

// ************************************************************************* //
