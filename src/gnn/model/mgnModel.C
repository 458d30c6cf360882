/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "mgnModel.H"
#include <stdexcept>

namespace gnnTorch
{

mgnModel::mgnModel
(
    const bsmsData::hierarchy& h,
    const graphNetConfig& config
)
:
    config_(config),
    graph_(h.levels[0], h.dim)
{
    if (config_.nMessagePasses < 1)
    {
        throw std::runtime_error("mgnModel: nMessagePasses must be >= 1");
    }
    const int c = config_.latent;
    const int hid = config_.hidden;
    nodeEncoder_ =
        register_module("nodeEncoder", mlp(config_.nIn, hid, c, true));
    edgeEncoder_ =
        register_module("edgeEncoder", mlp(h.dim + 1, hid, c, true));
    decoder_ = register_module("decoder", mlp(c, hid, config_.nOut, false));
    for (int k = 0; k < config_.nMessagePasses; ++k)
    {
        edge_.push_back
        (
            register_module("edge" + std::to_string(k), mlp(3*c, hid, c, true))
        );
        node_.push_back
        (
            register_module("node" + std::to_string(k), mlp(2*c, hid, c, true))
        );
    }
}


torch::Tensor mgnModel::forward(const torch::Tensor& x)
{
    const bool batched = x.dim() == 3;
    torch::Tensor v = nodeEncoder_(batched ? x : x.unsqueeze(0));
    const std::int64_t B = v.size(0);
    torch::Tensor e = edgeEncoder_(graph_.edgeAttr).unsqueeze(0)
        .expand({B, -1, -1});
    for (std::size_t k = 0; k < edge_.size(); ++k)
    {
        e = e + edge_[k]
        (
            torch::cat
            (
                {
                    e,
                    v.index_select(1, graph_.receivers),
                    v.index_select(1, graph_.senders)
                },
                2
            )
        );
        v = v + node_[k](torch::cat({v, graph_.sumAtReceivers(e)}, 2));
    }
    torch::Tensor q = decoder_(v);
    return batched ? q : q.squeeze(0);
}

} // End namespace gnnTorch

// ************************************************************************* //
