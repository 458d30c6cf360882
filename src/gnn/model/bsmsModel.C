/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "bsmsModel.H"
#include <stdexcept>

namespace gnnTorch
{

// * * * * * * * * * * * * * * bsmsMessagePass  * * * * * * * * * * * * * * //

bsmsMessagePassImpl::bsmsMessagePassImpl(int dim, int latent, int hidden)
{
    edge_ = register_module
    (
        "edge", mlp(dim + 1 + 2*latent, hidden, latent, true)
    );
    node_ = register_module("node", mlp(2*latent, hidden, latent, true));
}


// (4.2): e_ij = f^E(dx_ij, |dx_ij|, v_i, v_j); v_i += f^V(v_i, sum_j e_ij)
torch::Tensor bsmsMessagePassImpl::forward
(
    const torch::Tensor& v,
    const graphTensors& g
)
{
    const std::int64_t B = v.size(0);
    const torch::Tensor attr =
        g.edgeAttr.unsqueeze(0).expand({B, -1, -1});
    const torch::Tensor e = edge_
    (
        torch::cat
        (
            {attr, v.index_select(1, g.receivers), v.index_select(1, g.senders)},
            2
        )
    );
    return v + node_(torch::cat({v, g.sumAtReceivers(e)}, 2));
}


// * * * * * * * * * * * * * * * * bsmsModel  * * * * * * * * * * * * * * * //

bsmsModel::bsmsModel
(
    const bsmsData::hierarchy& h,
    const graphNetConfig& config
)
:
    config_(config)
{
    if (config_.nLevels < 0)
    {
        throw std::runtime_error("bsmsModel: nLevels must be >= 0");
    }
    const int L =
        config_.nLevels == 0
      ? int(h.levels.size())
      : std::min(config_.nLevels, int(h.levels.size()));

    for (int l = 0; l < L; ++l)
    {
        levels_.emplace_back(h.levels[l], h.dim);
    }
    for (int l = 0; l + 1 < L; ++l)
    {
        transitions_.emplace_back(h.transitions[l]);
    }

    const int c = config_.latent;
    const int hid = config_.hidden;
    encoder_ = register_module("encoder", mlp(config_.nIn, hid, c, true));
    decoder_ = register_module("decoder", mlp(c, hid, config_.nOut, false));
    for (int l = 0; l + 1 < L; ++l)
    {
        down_.push_back
        (
            register_module
            (
                "down" + std::to_string(l), bsmsMessagePass(h.dim, c, hid)
            )
        );
    }
    bottom_ = register_module("bottom", bsmsMessagePass(h.dim, c, hid));
    for (int l = 0; l + 1 < L; ++l)
    {
        up_.push_back
        (
            register_module
            (
                "up" + std::to_string(l), bsmsMessagePass(h.dim, c, hid)
            )
        );
    }
}


torch::Tensor bsmsModel::forward(const torch::Tensor& x)
{
    const bool batched = x.dim() == 3;
    torch::Tensor v = encoder_(batched ? x : x.unsqueeze(0));

    const int L = nLevels();
    std::vector<torch::Tensor> skip(L);
    for (int l = 0; l + 1 < L; ++l)
    {
        v = down_[l](v, levels_[l]);
        skip[l] = v;
        v = transitions_[l].downsample(v);
    }
    v = bottom_(v, levels_[L - 1]);
    for (int l = L - 2; l >= 0; --l)
    {
        v = transitions_[l].upsample(v) + skip[l];
        v = up_[l](v, levels_[l]);
    }
    torch::Tensor q = decoder_(v);
    return batched ? q : q.squeeze(0);
}

} // End namespace gnnTorch

// ************************************************************************* //
