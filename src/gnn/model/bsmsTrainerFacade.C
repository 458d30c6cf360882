/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "bsmsTrainerFacade.H"
#include "graphNetTrainer.H"
#include <cfenv>

namespace gnnTorch
{

struct bsmsTrainerFacade::impl
{
    graphNetTrainer trainer;

    impl(const bsmsData::hierarchy& h, const graphNetConfig& n, const trainerConfig& c)
    :
        trainer(h, n, c)
    {}
};


namespace
{

graphNetConfig netOf(const trainerSettings& s)
{
    graphNetConfig n;
    n.type = s.model;
    n.nIn = s.nIn;
    n.nOut = s.nOut;
    n.latent = s.latent;
    n.hidden = s.hidden;
    n.nMessagePasses = s.nMessagePasses;
    n.nLevels = s.nLevels;
    n.world = s.world;
    return n;
}

trainerConfig configOf(const trainerSettings& s)
{
    trainerConfig c;
    c.lr = s.lr;
    c.lrMin = s.lrMin;
    c.lrDecay = s.lrDecay;
    c.decaySteps = s.decaySteps;
    c.decayFrom = s.decayFrom;
    c.noiseStd = s.noiseStd;
    c.normAccumulations = s.normAccumulations;
    c.seed = s.seed;
    c.rolloutSteps = s.rolloutSteps;
    c.rolloutBackprop = s.rolloutBackprop;
    c.outputColumns = s.outputColumns;
    c.outputMask = s.outputMask;
    return c;
}

//- Floating-point traps off for the life of the object (the torch kernels
//  may overflow on out-of-range inputs; the callers check the results),
//  restored with the exception flags cleared
class fpeTrapsOff
{
    int traps_;
public:
    fpeTrapsOff()
    :
        traps_(fegetexcept())
    {
        fedisableexcept(FE_ALL_EXCEPT);
    }
    ~fpeTrapsOff()
    {
        feclearexcept(FE_ALL_EXCEPT);
        feenableexcept(traps_);
    }
    fpeTrapsOff(const fpeTrapsOff&) = delete;
    void operator=(const fpeTrapsOff&) = delete;
};

} // End anonymous namespace


bsmsTrainerFacade::bsmsTrainerFacade
(
    const bsmsData::hierarchy& h,
    const trainerSettings& s
)
:
    impl_(new impl(h, netOf(s), configOf(s)))
{}


bsmsTrainerFacade::~bsmsTrainerFacade() = default;


double bsmsTrainerFacade::trainStep
(
    const std::vector<double>& x,
    const std::vector<double>& y
)
{
    fpeTrapsOff noTraps;
    return impl_->trainer.trainStep(x, y);
}


double bsmsTrainerFacade::trainShards
(
    const std::vector<double>& x,
    const std::vector<double>& y,
    const std::int64_t first,
    const std::int64_t nMine,
    const std::int64_t nShards,
    const std::int64_t nTotal,
    rankSum& sum,
    const std::vector<const bsmsData::world*>& frames
)
{
    fpeTrapsOff noTraps;
    auto& t = impl_->trainer;
    std::function<void(std::int64_t, std::int64_t)> select;
    if (!frames.empty())
    {
        select = [&t, &frames](const std::int64_t b, const std::int64_t n)
        {
            t.net().setWorlds
            (
                std::vector<const bsmsData::world*>
                (
                    frames.begin() + b, frames.begin() + b + n
                )
            );
        };
    }
    const std::int64_t nNodes = t.net().nNodes();
    const auto X = torch::tensor(x, torch::kFloat64)
        .reshape({-1, nNodes, t.netConfig().nIn});
    const auto Y = torch::tensor(y, torch::kFloat64)
        .reshape({-1, nNodes, t.netConfig().nOut});
    return t.trainShards
    (
        X, Y, first, nMine, nShards, nTotal,
        [&sum](std::vector<float>& v) { sum(v); },
        [&sum](std::vector<double>& v) { sum(v); },
        select
    );
}


std::uint64_t bsmsTrainerFacade::parameterHash() const
{
    const std::vector<float> v = impl_->trainer.parameterValues();
    const unsigned char* b = reinterpret_cast<const unsigned char*>(v.data());
    std::uint64_t h = 14695981039346656037ULL;
    for (std::size_t i = 0; i < v.size()*sizeof(float); ++i)
    {
        h = (h ^ b[i])*1099511628211ULL;
    }
    return h;
}


void setNumThreads(const int n)
{
    torch::set_num_threads(n);
}


int numThreads()
{
    return torch::get_num_threads();
}


void bsmsTrainerFacade::setWorlds
(
    const std::vector<const bsmsData::world*>& frames
)
{
    impl_->trainer.net().setWorlds(frames);
}


double bsmsTrainerFacade::loss
(
    const std::vector<double>& x,
    const std::vector<double>& y
)
{
    fpeTrapsOff noTraps;
    auto& t = impl_->trainer;
    const std::int64_t n = t.net().nNodes();
    const auto X = torch::tensor(x, torch::kFloat64)
        .reshape({-1, n, t.netConfig().nIn});
    const auto Y = torch::tensor(y, torch::kFloat64)
        .reshape({-1, n, t.netConfig().nOut});
    return t.loss(X, Y);
}


std::vector<double> bsmsTrainerFacade::predict(const std::vector<double>& x)
{
    fpeTrapsOff noTraps;
    return impl_->trainer.predict(x);
}


std::int64_t bsmsTrainerFacade::inputStatistics
(
    std::vector<double>& mean,
    std::vector<double>& std
) const
{
    fpeTrapsOff noTraps;
    normaliser& n = impl_->trainer.inputNormaliser();
    const torch::Tensor m = n->mean().to(torch::kFloat64).contiguous();
    const torch::Tensor s = n->std().to(torch::kFloat64).contiguous();
    mean.assign(m.data_ptr<double>(), m.data_ptr<double>() + m.numel());
    std.assign(s.data_ptr<double>(), s.data_ptr<double>() + s.numel());
    return n->nSamples();
}


void bsmsTrainerFacade::save(const std::string& file) const
{
    impl_->trainer.save(file);
}


void bsmsTrainerFacade::load(const std::string& file)
{
    impl_->trainer.load(file);
}


std::int64_t bsmsTrainerFacade::step() const
{
    return impl_->trainer.step();
}


double bsmsTrainerFacade::learningRate() const
{
    return impl_->trainer.learningRate();
}


std::int64_t bsmsTrainerFacade::nParameters() const
{
    return impl_->trainer.net().nParameters();
}


std::string bsmsTrainerFacade::describe() const
{
    return impl_->trainer.netConfig().str();
}

} // End namespace gnnTorch

// ************************************************************************* //
