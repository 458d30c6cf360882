/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "bsmsModel.H"
#include <stdexcept>

namespace gnnTorch
{

// * * * * * * * * * * * * * * bsmsMessagePass  * * * * * * * * * * * * * * //

bsmsMessagePassImpl::bsmsMessagePassImpl
(
    int dim,
    int latent,
    int hidden,
    bool world
)
{
    const int nA = dim + 1;
    edge_ = register_module
    (
        "edge", mlp((world ? 2*nA : nA) + 2*latent, hidden, latent, true)
    );
    if (world)
    {
        world_ = register_module
        (
            "world", mlp(nA + 2*latent, hidden, latent, true)
        );
    }
    node_ = register_module
    (
        "node", mlp((world ? 3 : 2)*latent, hidden, latent, true)
    );
}


// (4.2): e_ij = f^E(dx_ij, |dx_ij|, v_i, v_j); v_i += f^V(v_i, sum_j e_ij)
torch::Tensor bsmsMessagePassImpl::forward
(
    const torch::Tensor& v,
    const graphTensors& g,
    const worldTensors* w
)
{
    const std::int64_t B = v.size(0);
    torch::Tensor attr = g.edgeAttr.unsqueeze(0).expand({B, -1, -1});
    if (world_)
    {
        if (!w || w->nBatch != B)
        {
            throw std::runtime_error
            (
                "bsmsModel: a batch of " + std::to_string(B) + " samples"
                " needs as many frames of moving bodies (setWorlds), given "
              + std::to_string(w ? w->nBatch : 0)
            );
        }
        attr = torch::cat({attr, w->meshAttr}, 2);
    }
    const torch::Tensor e = edge_
    (
        torch::cat
        (
            {attr, v.index_select(1, g.receivers), v.index_select(1, g.senders)},
            2
        )
    );
    if (!world_)
    {
        return v + node_(torch::cat({v, g.sumAtReceivers(e)}, 2));
    }
    // (4.2) the world edge set: the batch flattened, node b N + i
    const torch::Tensor vf = v.reshape({-1, v.size(2)});
    const torch::Tensor ew = world_
    (
        torch::cat
        (
            {w->attr, vf.index_select(0, w->receivers), vf.index_select(0, w->senders)},
            1
        )
    );
    return v + node_
    (
        torch::cat
        (
            {v, g.sumAtReceivers(e), w->sumAtReceivers(ew, g.nNodes)}, 2
        )
    );
}


// * * * * * * * * * * * * * * * * bsmsModel  * * * * * * * * * * * * * * * //

bsmsModel::bsmsModel
(
    const bsmsData::hierarchy& h,
    const graphNetConfig& config
)
:
    config_(config),
    dim_(h.dim)
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
    const bool w = config_.world != 0;
    for (int l = 0; l + 1 < L; ++l)
    {
        down_.push_back
        (
            register_module
            (
                "down" + std::to_string(l), bsmsMessagePass(h.dim, c, hid, w)
            )
        );
    }
    bottom_ = register_module("bottom", bsmsMessagePass(h.dim, c, hid, w));
    for (int l = 0; l + 1 < L; ++l)
    {
        up_.push_back
        (
            register_module
            (
                "up" + std::to_string(l), bsmsMessagePass(h.dim, c, hid, w)
            )
        );
    }
}


void bsmsModel::setWorlds(const std::vector<const bsmsData::world*>& frames)
{
    if (!config_.world)
    {
        graphNetwork::setWorlds(frames);
    }
    worlds_.clear();
    for (int l = 0; l < nLevels(); ++l)
    {
        worlds_.emplace_back(levels_[l], frames, l, dim_);
    }
}


torch::Tensor bsmsModel::forward(const torch::Tensor& x)
{
    const bool batched = x.dim() == 3;
    torch::Tensor v = encoder_(batched ? x : x.unsqueeze(0));

    const int L = nLevels();
    auto world = [&](const int l) -> const worldTensors*
    {
        return config_.world && l < int(worlds_.size()) ? &worlds_[l] : nullptr;
    };
    std::vector<torch::Tensor> skip(L);
    for (int l = 0; l + 1 < L; ++l)
    {
        v = down_[l](v, levels_[l], world(l));
        skip[l] = v;
        v = transitions_[l].downsample(v);
    }
    v = bottom_(v, levels_[L - 1], world(L - 1));
    for (int l = L - 2; l >= 0; --l)
    {
        v = transitions_[l].upsample(v) + skip[l];
        v = up_[l](v, levels_[l], world(l));
    }
    torch::Tensor q = decoder_(v);
    return batched ? q : q.squeeze(0);
}

} // End namespace gnnTorch

// ************************************************************************* //
