/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "bsmsTrainerFacade.H"
#include "graphNetTrainer.H"

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
    return n;
}

trainerConfig configOf(const trainerSettings& s)
{
    trainerConfig c;
    c.lr = s.lr;
    c.lrMin = s.lrMin;
    c.lrDecay = s.lrDecay;
    c.decaySteps = s.decaySteps;
    c.noiseStd = s.noiseStd;
    c.normAccumulations = s.normAccumulations;
    c.seed = s.seed;
    return c;
}

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
    return impl_->trainer.trainStep(x, y);
}


double bsmsTrainerFacade::loss
(
    const std::vector<double>& x,
    const std::vector<double>& y
)
{
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
    return impl_->trainer.predict(x);
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
