/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "graphNetLayers.H"
#include "bsmsModel.H"
#include "mgnModel.H"
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace gnnTorch
{

// * * * * * * * * * * * * * * * graphNetConfig  * * * * * * * * * * * * * //

std::vector<std::int64_t> graphNetConfig::codes() const
{
    const std::int64_t t = (type == "bsms" ? 1 : type == "mgn" ? 2 : 0);
    std::vector<std::int64_t> c
    {
        t, nIn, nOut, latent, hidden, nMessagePasses, nLevels
    };
    // Only when set, so the checkpoints of mesh-only models read as before
    if (world) c.push_back(world);
    return c;
}


std::string graphNetConfig::str() const
{
    std::ostringstream os;
    os  << "type " << type << ", nIn " << nIn << ", nOut " << nOut
        << ", latent " << latent << ", hidden " << hidden;
    if (type == "mgn") os << ", nMessagePasses " << nMessagePasses;
    else os << ", nLevels " << nLevels;
    if (world) os << ", world " << world;
    return os.str();
}


// * * * * * * * * * * * * * * * * * * mlp  * * * * * * * * * * * * * * * * //

mlpImpl::mlpImpl(int nIn, int hidden, int nOut, bool layerNorm)
{
    l1_ = register_module("l1", torch::nn::Linear(nIn, hidden));
    l2_ = register_module("l2", torch::nn::Linear(hidden, hidden));
    l3_ = register_module("l3", torch::nn::Linear(hidden, nOut));
    if (layerNorm)
    {
        norm_ = register_module
        (
            "norm",
            torch::nn::LayerNorm
            (
                torch::nn::LayerNormOptions(std::vector<std::int64_t>{nOut})
            )
        );
    }
}


torch::Tensor mlpImpl::forward(const torch::Tensor& x)
{
    torch::Tensor y = l3_(torch::relu(l2_(torch::relu(l1_(x)))));
    return norm_ ? norm_(y) : y;
}


// * * * * * * * * * * * * * * * graphTensors * * * * * * * * * * * * * * * //

graphTensors::graphTensors(const bsmsData::level& g, const int dim)
:
    nNodes(g.nNodes)
{
    const std::int64_t E = g.nDirectedEdges();
    std::vector<std::int64_t> recv(E);
    for (std::int64_t i = 0; i < g.nNodes; ++i)
    {
        for (std::int64_t k = g.offsets[i]; k < g.offsets[i + 1]; ++k)
        {
            recv[k] = i;
        }
    }
    const auto i64 = torch::TensorOptions().dtype(torch::kInt64);
    receivers = torch::tensor(recv, i64);
    senders = torch::tensor(g.neighbours, i64);

    // dx_ij = x_i - x_j in double, then scaled by the mean length
    std::vector<double> attr(E*(dim + 1));
    double meanLength = 0;
    for (std::int64_t k = 0; k < E; ++k)
    {
        const double* xi = &g.positions[3*recv[k]];
        const double* xj = &g.positions[3*g.neighbours[k]];
        double len2 = 0;
        for (int d = 0; d < dim; ++d)
        {
            const double dx = xi[d] - xj[d];
            attr[k*(dim + 1) + d] = dx;
            len2 += dx*dx;
        }
        attr[k*(dim + 1) + dim] = std::sqrt(len2);
        meanLength += std::sqrt(len2);
    }
    if (E > 0) meanLength /= double(E);
    h = meanLength > 0 ? meanLength : 1.0;
    for (double& a : attr) a /= h;
    edgeAttr =
        torch::tensor(attr, torch::TensorOptions().dtype(torch::kFloat64))
       .reshape({E, dim + 1})
       .to(torch::kFloat32);
}


torch::Tensor graphTensors::sumAtReceivers(const torch::Tensor& e) const
{
    return torch::zeros({e.size(0), nNodes, e.size(2)}, e.options())
        .index_add_(1, receivers, e);
}


// * * * * * * * * * * * * * * * worldTensors  * * * * * * * * * * * * * * //

worldTensors::worldTensors
(
    const graphTensors& g,
    const std::vector<const bsmsData::world*>& frames,
    const int l,
    const int dim
)
:
    nBatch(std::int64_t(frames.size()))
{
    const std::int64_t N = g.nNodes;
    const std::int64_t E = g.receivers.numel();
    const std::int64_t* recv = g.receivers.data_ptr<std::int64_t>();
    const std::int64_t* send = g.senders.data_ptr<std::int64_t>();
    const int nA = dim + 1;

    // (x_i - x_j)/h and its length, for a frame's positions
    auto offset = [&](const double* xi, const double* xj, double* out)
    {
        double len2 = 0;
        for (int d = 0; d < dim; ++d)
        {
            const double dx = (xi[d] - xj[d])/g.h;
            out[d] = dx;
            len2 += dx*dx;
        }
        out[dim] = std::sqrt(len2);
    };

    std::vector<double> mesh(nBatch*E*nA);
    std::vector<std::int64_t> wr, ws;
    std::vector<double> wa;
    std::size_t nWorld = 0;
    for (const bsmsData::world* w : frames)
    {
        if (w && l < std::int64_t(w->levels.size()))
        {
            nWorld += w->levels[l].neighbours.size();
        }
    }
    wr.reserve(nWorld);
    ws.reserve(nWorld);
    wa.reserve(nWorld*nA);
    for (std::int64_t b = 0; b < nBatch; ++b)
    {
        const bsmsData::world* w = frames[b];
        if (!w || l >= std::int64_t(w->levels.size()))
        {
            throw std::runtime_error
            (
                "worldTensors: frame " + std::to_string(b) + " has no level "
              + std::to_string(l)
            );
        }
        const bsmsData::worldLevel& f = w->levels[l];
        if
        (
            std::int64_t(f.positions.size()) != 3*N
         || std::int64_t(f.offsets.size()) != N + 1
        )
        {
            throw std::runtime_error
            (
                "worldTensors: frame " + std::to_string(b) + " level "
              + std::to_string(l) + " has "
              + std::to_string(f.positions.size()/3) + " nodes, the level "
              + std::to_string(N)
            );
        }
        const double* x = f.positions.data();
        for (std::int64_t k = 0; k < E; ++k)
        {
            offset(x + 3*recv[k], x + 3*send[k], &mesh[(b*E + k)*nA]);
        }
        for (std::int64_t i = 0; i < N; ++i)
        {
            for (std::int64_t k = f.offsets[i]; k < f.offsets[i + 1]; ++k)
            {
                const std::int64_t j = f.neighbours[k];
                if (j < 0 || j >= N)
                {
                    throw std::runtime_error
                    (
                        "worldTensors: world edge to node "
                      + std::to_string(j) + " of " + std::to_string(N)
                    );
                }
                wr.push_back(b*N + i);
                ws.push_back(b*N + j);
                wa.resize(wa.size() + nA);
                offset(x + 3*i, x + 3*j, &wa[wa.size() - nA]);
            }
        }
    }
    const auto i64 = torch::TensorOptions().dtype(torch::kInt64);
    const auto f64 = torch::TensorOptions().dtype(torch::kFloat64);
    const std::int64_t C = std::int64_t(wr.size());
    meshAttr = torch::tensor(mesh, f64).reshape({nBatch, E, nA}).to(torch::kFloat32);
    receivers = torch::tensor(wr, i64);
    senders = torch::tensor(ws, i64);
    attr = torch::tensor(wa, f64).reshape({C, nA}).to(torch::kFloat32);
}


torch::Tensor worldTensors::sumAtReceivers
(
    const torch::Tensor& e,
    const std::int64_t n
) const
{
    return torch::zeros({nBatch*n, e.size(1)}, e.options())
        .index_add_(0, receivers, e)
        .reshape({nBatch, n, e.size(1)});
}


// * * * * * * * * * * * * * * transitionTensors * * * * * * * * * * * * * //

transitionTensors::transitionTensors(const bsmsData::transition& t)
:
    nFine(t.nFine),
    nCoarse(t.nCoarse)
{
    const std::int64_t T = std::int64_t(t.senders.size());
    std::vector<std::int64_t> recv(T);
    std::vector<double> rowSum(t.nFine, 0.0);
    for (std::int64_t j = 0; j < t.nCoarse; ++j)
    {
        for (std::int64_t k = t.offsets[j]; k < t.offsets[j + 1]; ++k)
        {
            recv[k] = j;
            rowSum[t.senders[k]] += t.C[k];
        }
    }
    std::vector<double> cUp(T);
    for (std::int64_t k = 0; k < T; ++k)
    {
        const double s = rowSum[t.senders[k]];
        if (!(s > 0))
        {
            throw std::runtime_error
            (
                "transitionTensors: a fine node without pooled neighbour"
                " (the pooling is not 2-CC)"
            );
        }
        cUp[k] = t.C[k]/s;
    }
    for (std::int64_t i = 0; i < t.nFine; ++i)
    {
        if (!(rowSum[i] > 0))
        {
            throw std::runtime_error
            (
                "transitionTensors: fine node " + std::to_string(i)
              + " has no pooled neighbour (the pooling is not 2-CC)"
            );
        }
    }
    const auto i64 = torch::TensorOptions().dtype(torch::kInt64);
    const auto f64 = torch::TensorOptions().dtype(torch::kFloat64);
    coarse = torch::tensor(recv, i64);
    fine = torch::tensor(t.senders, i64);
    down = torch::tensor(t.C, f64).to(torch::kFloat32).reshape({T, 1});
    up = torch::tensor(cUp, f64).to(torch::kFloat32).reshape({T, 1});
}


torch::Tensor transitionTensors::downsample(const torch::Tensor& v) const
{
    return torch::zeros({v.size(0), nCoarse, v.size(2)}, v.options())
        .index_add_(1, coarse, v.index_select(1, fine)*down);
}


torch::Tensor transitionTensors::upsample(const torch::Tensor& v) const
{
    return torch::zeros({v.size(0), nFine, v.size(2)}, v.options())
        .index_add_(1, fine, v.index_select(1, coarse)*up);
}


// * * * * * * * * * * * * * * * graphNetwork * * * * * * * * * * * * * * * //

void graphNetwork::setWorlds(const std::vector<const bsmsData::world*>&)
{
    throw std::runtime_error
    (
        "graph network: " + config().str() + " has no world edges (moving"
        " bodies need a BSMS-GNN with world 1)"
    );
}


std::int64_t graphNetwork::nParameters() const
{
    std::int64_t n = 0;
    for (const torch::Tensor& p : parameters()) n += p.numel();
    return n;
}


std::shared_ptr<graphNetwork> newGraphNetwork
(
    const bsmsData::hierarchy& h,
    const graphNetConfig& config
)
{
    const std::string bad = h.check();
    if (!bad.empty())
    {
        throw std::runtime_error("graph network: bad hierarchy: " + bad);
    }
    if (config.nIn < 1 || config.nOut < 1 || config.latent < 1
     || config.hidden < 1)
    {
        throw std::runtime_error
        (
            "graph network: sizes must be positive (" + config.str() + ")"
        );
    }
    if (config.type == "bsms")
    {
        return std::make_shared<bsmsModel>(h, config);
    }
    if (config.type == "mgn")
    {
        if (config.world)
        {
            throw std::runtime_error
            (
                "graph network: moving bodies (world edges) need BSMS-GNN,"
                " not mgn (" + config.str() + ")"
            );
        }
        return std::make_shared<mgnModel>(h, config);
    }
    throw std::runtime_error
    (
        "graph network: unknown type '" + config.type
      + "' (allowed: bsms, mgn)"
    );
}

} // End namespace gnnTorch

// ************************************************************************* //
