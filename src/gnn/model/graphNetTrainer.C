/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "graphNetTrainer.H"
#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

namespace gnnTorch
{

// * * * * * * * * * * * * * * * * Constructor  * * * * * * * * * * * * * * //

graphNetTrainer::graphNetTrainer
(
    const bsmsData::hierarchy& h,
    const graphNetConfig& netConfig,
    const trainerConfig& config
)
:
    netConfig_(netConfig),
    config_(config)
{
    if
    (
        !config_.noiseStd.empty()
     && config_.noiseStd.size() != 1
     && int(config_.noiseStd.size()) != netConfig_.nIn
    )
    {
        throw std::runtime_error
        (
            "graphNetTrainer: noiseStd has "
          + std::to_string(config_.noiseStd.size())
          + " values; give none, one, or one per input component ("
          + std::to_string(netConfig_.nIn) + ")"
        );
    }
    if (config_.rolloutSteps < 1)
    {
        throw std::runtime_error
        (
            "graphNetTrainer: rolloutSteps "
          + std::to_string(config_.rolloutSteps) + " < 1"
        );
    }
    if (config_.rolloutSteps > 1)
    {
        bool ok =
            int(config_.outputColumns.size()) == netConfig_.nOut
         && int(config_.outputMask.size()) == netConfig_.nOut;
        for (std::size_t j = 0; ok && j < config_.outputColumns.size(); ++j)
        {
            ok = config_.outputColumns[j] >= 0
              && config_.outputColumns[j] < netConfig_.nIn;
        }
        if (!ok)
        {
            throw std::runtime_error
            (
                "graphNetTrainer: rolloutSteps > 1 needs one input column"
                " in [0, " + std::to_string(netConfig_.nIn) + ") and one"
                " mask value per output (" + std::to_string(netConfig_.nOut)
              + "), given " + std::to_string(config_.outputColumns.size())
              + " and " + std::to_string(config_.outputMask.size())
            );
        }
    }
    if (netConfig_.world && config_.rolloutSteps > 1)
    {
        throw std::runtime_error
        (
            "graphNetTrainer: a model of moving bodies (world edges) trains"
            " on the one-step loss only (rolloutSteps "
          + std::to_string(config_.rolloutSteps) + "): a rollout would need"
            " the world edges of its own predicted frames"
        );
    }
    torch::manual_seed(config_.seed);
    net_ = newGraphNetwork(h, netConfig_);
    inNorm_ = normaliser(netConfig_.nIn, config_.normAccumulations);
    outNorm_ = normaliser(netConfig_.nOut, config_.normAccumulations);
    optimizer_.reset
    (
        new torch::optim::Adam
        (
            net_->parameters(), torch::optim::AdamOptions(config_.lr)
        )
    );
}


// * * * * * * * * * * * * * * Private Functions * * * * * * * * * * * * * * //

torch::Tensor graphNetTrainer::checked
(
    const torch::Tensor& x,
    const int nComp
) const
{
    const bool ok =
        (x.dim() == 2 || x.dim() == 3)
     && x.size(-1) == nComp
     && x.size(-2) == net_->nNodes();
    if (!ok)
    {
        throw std::runtime_error
        (
            "graphNetTrainer: expected [nodes, " + std::to_string(nComp)
          + "] or [batch, nodes, " + std::to_string(nComp) + "] with "
          + std::to_string(net_->nNodes()) + " nodes, got "
          + c10::str(x.sizes())
        );
    }
    return x.to(torch::kFloat32);
}


torch::Tensor graphNetTrainer::fromPlain
(
    const std::vector<double>& x,
    const int nComp
) const
{
    const std::int64_t n = net_->nNodes()*nComp;
    if (std::int64_t(x.size()) % n != 0 || x.empty())
    {
        throw std::runtime_error
        (
            "graphNetTrainer: " + std::to_string(x.size())
          + " values are not a whole number of samples of "
          + std::to_string(net_->nNodes()) + " nodes x "
          + std::to_string(nComp) + " components"
        );
    }
    return torch::tensor(x, torch::TensorOptions().dtype(torch::kFloat64))
        .reshape({-1, net_->nNodes(), nComp}).to(torch::kFloat32);
}


// * * * * * * * * * * * * * * * * * Training  * * * * * * * * * * * * * * * //

double graphNetTrainer::learningRate() const
{
    return
        config_.lrMin
      + (config_.lr - config_.lrMin)
       *std::pow
        (
            config_.lrDecay,
            std::max(double(step_) - config_.decayFrom, 0.0)/config_.decaySteps
        );
}


torch::Tensor graphNetTrainer::bySteps(const torch::Tensor& y) const
{
    const std::int64_t K = config_.rolloutSteps;
    if (K == 1) return y;
    if (y.dim() != 3 || y.size(0) % K != 0)
    {
        throw std::runtime_error
        (
            "graphNetTrainer: rolloutSteps " + std::to_string(K) + " needs"
            " the targets as [samples x " + std::to_string(K) + ", nodes,"
            " outputs], got " + c10::str(y.sizes())
        );
    }
    return y.reshape({-1, K, y.size(1), y.size(2)});
}


torch::Tensor graphNetTrainer::firstStep(const torch::Tensor& y) const
{
    return config_.rolloutSteps == 1 ? y : y.select(1, 0);
}


torch::Tensor graphNetTrainer::trainingLoss
(
    torch::Tensor x,
    const torch::Tensor& y
)
{
    const std::int64_t K = config_.rolloutSteps;
    if (K == 1)
    {
        return torch::mse_loss(net_->forward(inNorm_->forward(x)), outNorm_->forward(y));
    }
    if (x.dim() == 2) x = x.unsqueeze(0);
    const torch::Tensor cols = torch::tensor(config_.outputColumns, torch::kInt64);
    std::vector<float> m(config_.outputMask.begin(), config_.outputMask.end());
    const torch::Tensor mask = torch::tensor(m, x.options());
    // Rollout over K steps: r_j = true_j - x_j on the output columns
    torch::Tensor total, r;
    for (std::int64_t j = 0; j < K; ++j)
    {
        const torch::Tensor target = j ? y.select(1, j) + r : y.select(1, 0);
        const torch::Tensor pred = net_->forward(inNorm_->forward(x));
        const torch::Tensor l = torch::mse_loss(pred, outNorm_->forward(target));
        total = j ? total + l : l;
        if (j + 1 < K)
        {
            const torch::Tensor p = outNorm_->inverse(pred)*mask;
            r = (target - p)*mask;
            x = torch::index_add(x, -1, cols, p);
            if (!config_.rolloutBackprop)
            {
                x = x.detach();
                r = r.detach();
            }
        }
    }
    return total/double(K);
}


torch::Tensor graphNetTrainer::prepare(torch::Tensor x, const torch::Tensor& yIn)
{
    if (step_ < config_.normAccumulations)
    {
        const torch::Tensor y = firstStep(yIn);
        inNorm_->accumulate(x);
        outNorm_->accumulate(y);
    }

    // Noise (4.4.2.5), reproducible from (seed, step)
    if (!config_.noiseStd.empty())
    {
        std::vector<float> s(netConfig_.nIn);
        for (int c = 0; c < netConfig_.nIn; ++c)
        {
            s[c] = float
            (
                config_.noiseStd.size() == 1
              ? config_.noiseStd[0] : config_.noiseStd[c]
            );
        }
        auto gen = at::detail::createCPUGenerator
        (
            config_.seed*0x9E3779B97F4A7C15ULL + std::uint64_t(step_) + 1
        );
        x = x + torch::randn(x.sizes(), gen, x.options())
           *torch::tensor(s, x.options());
    }

    for (auto& group : optimizer_->param_groups())
    {
        static_cast<torch::optim::AdamOptions&>(group.options())
            .lr(learningRate());
    }
    return x;
}


double graphNetTrainer::trainStep
(
    const torch::Tensor& xIn,
    const torch::Tensor& yIn
)
{
    const torch::Tensor y = bySteps(checked(yIn, netConfig_.nOut));
    const torch::Tensor x = prepare(checked(xIn, netConfig_.nIn), y);

    net_->train();
    optimizer_->zero_grad();
    const torch::Tensor l = trainingLoss(x, y);
    l.backward();
    optimizer_->step();
    ++step_;
    return l.item<double>();
}


double graphNetTrainer::trainStep
(
    const std::vector<double>& x,
    const std::vector<double>& y
)
{
    return trainStep(fromPlain(x, netConfig_.nIn), fromPlain(y, netConfig_.nOut));
}


double graphNetTrainer::loss(const torch::Tensor& xIn, const torch::Tensor& yIn)
{
    const torch::Tensor x = checked(xIn, netConfig_.nIn);
    const torch::Tensor y = checked(yIn, netConfig_.nOut);
    torch::NoGradGuard noGrad;
    net_->eval();
    const torch::Tensor pred = net_->forward(inNorm_->forward(x));
    return torch::mse_loss(pred, outNorm_->forward(y)).item<double>();
}


double graphNetTrainer::trainShards
(
    const torch::Tensor& xIn,
    const torch::Tensor& yIn,
    const std::int64_t first,
    const std::int64_t nMine,
    const std::int64_t nShards,
    const std::int64_t nTotal,
    const std::function<void(std::vector<float>&)>& sumOverRanks,
    const std::function<void(std::vector<double>&)>& sumOverRanksD,
    const std::function<void(std::int64_t, std::int64_t)>& selectShard
)
{
    torch::Tensor x = checked(xIn, netConfig_.nIn);
    torch::Tensor y = checked(yIn, netConfig_.nOut);
    if (x.dim() == 2) x = x.unsqueeze(0);
    if (y.dim() == 2) y = y.unsqueeze(0);
    // [n, K, N, nOut] with K = rolloutSteps > 1
    y = bySteps(y);
    // Shard k: samples [off(k), off(k + 1)) of the batch
    auto off = [nTotal, nShards](const std::int64_t k)
    {
        return k*nTotal/nShards;
    };
    if
    (
        nShards < 1 || nShards > nTotal || nMine < 1 || first < 0
     || first + nMine > nShards
     || x.size(0) != off(first + nMine) - off(first)
     || y.size(0) != x.size(0)
    )
    {
        throw std::runtime_error
        (
            "graphNetTrainer: shards [" + std::to_string(first) + ", "
          + std::to_string(first + nMine) + ") of " + std::to_string(nShards)
          + " of a batch of " + std::to_string(nTotal) + " samples, given "
          + std::to_string(x.size(0)) + " input and "
          + std::to_string(y.size(0)) + " target samples"
        );
    }
    const std::int64_t nIn = netConfig_.nIn, nOut = netConfig_.nOut;
    auto mine = [&](const torch::Tensor& t, const std::int64_t k)
    {
        return t.narrow(0, off(k) - off(first), off(k + 1) - off(k));
    };

    // Normaliser statistics of every shard, then added in shard order
    if (step_ < config_.normAccumulations && inNorm_->accumulating())
    {
        torch::NoGradGuard noGrad;
        const std::int64_t stride = 2*(nIn + nOut);
        std::vector<double>& st = statBuf_;
        st.assign(nShards*stride, 0.0);
        for (std::int64_t k = first; k < first + nMine; ++k)
        {
            double* o = st.data() + k*stride;
            auto put = [&o](const torch::Tensor& d, const std::int64_t nc)
            {
                const torch::Tensor s = d.sum(0).contiguous();
                const torch::Tensor q = (d*d).sum(0).contiguous();
                std::copy(s.data_ptr<double>(), s.data_ptr<double>() + nc, o);
                std::copy(q.data_ptr<double>(), q.data_ptr<double>() + nc, o + nc);
                o += 2*nc;
            };
            put(mine(x, k).detach().reshape({-1, nIn}).to(torch::kFloat64), nIn);
            put(firstStep(mine(y, k)).detach().reshape({-1, nOut}).to(torch::kFloat64), nOut);
        }
        sumOverRanksD(st);
        const std::int64_t nNodes = x.size(1);
        std::vector<std::int64_t> counts(nShards);
        std::vector<double> sx(nShards*nIn), qx(nShards*nIn);
        std::vector<double> sy(nShards*nOut), qy(nShards*nOut);
        for (std::int64_t k = 0; k < nShards; ++k)
        {
            counts[k] = (off(k + 1) - off(k))*nNodes;
            const double* o = st.data() + k*stride;
            std::copy(o, o + nIn, sx.begin() + k*nIn);
            std::copy(o + nIn, o + 2*nIn, qx.begin() + k*nIn);
            o += 2*nIn;
            std::copy(o, o + nOut, sy.begin() + k*nOut);
            std::copy(o + nOut, o + 2*nOut, qy.begin() + k*nOut);
        }
        inNorm_->accumulateParts(counts, sx.data(), qx.data());
        outNorm_->accumulateParts(counts, sy.data(), qy.data());
    }

    for (auto& group : optimizer_->param_groups())
    {
        static_cast<torch::optim::AdamOptions&>(group.options())
            .lr(learningRate());
    }

    // Forward and backward of each of this rank's shards; the gradients
    // and loss of shard k in slot k of the buffer (zero elsewhere)
    net_->train();
    std::vector<torch::Tensor> params = net_->parameters();
    std::int64_t nValues = 1;
    for (const torch::Tensor& p : params) nValues += p.numel();
    std::vector<float>& buf = shardBuf_;
    buf.assign(nShards*nValues, 0.0f);
    for (std::int64_t k = first; k < first + nMine; ++k)
    {
        torch::Tensor xs = mine(x, k);
        const torch::Tensor ys = mine(y, k);
        // Noise (4.4.2.5), reproducible from (seed, step, shard)
        if (!config_.noiseStd.empty())
        {
            std::vector<float> sd(nIn);
            for (int c = 0; c < nIn; ++c)
            {
                sd[c] = float
                (
                    config_.noiseStd.size() == 1
                  ? config_.noiseStd[0] : config_.noiseStd[c]
                );
            }
            auto gen = at::detail::createCPUGenerator
            (
                config_.seed*0x9E3779B97F4A7C15ULL + std::uint64_t(step_) + 1
              + std::uint64_t(k)*0xD1B54A32D192ED03ULL
            );
            xs = xs + torch::randn(xs.sizes(), gen, xs.options())
               *torch::tensor(sd, xs.options());
        }
        if (selectShard)
        {
            selectShard(off(k) - off(first), off(k + 1) - off(k));
        }
        optimizer_->zero_grad();
        const torch::Tensor l = trainingLoss(xs, ys);
        l.backward();

        torch::NoGradGuard noGrad;
        float* o = buf.data() + k*nValues;
        for (const torch::Tensor& p : params)
        {
            if (p.grad().defined())
            {
                const torch::Tensor g =
                    p.grad().to(torch::kFloat32).contiguous();
                std::copy
                (
                    g.data_ptr<float>(), g.data_ptr<float>() + g.numel(), o
                );
            }
            o += p.numel();
        }
        *o = l.item<float>();
    }

    sumOverRanks(buf);

    // The batch's gradient and loss: the shards in order, weighted by their
    // share of the batch (double, rounded to float once)
    double loss = 0;
    {
        torch::NoGradGuard noGrad;
        std::vector<double> w(nShards);
        for (std::int64_t k = 0; k < nShards; ++k)
        {
            w[k] = double(off(k + 1) - off(k))/double(nTotal);
        }
        std::int64_t o = 0;
        std::vector<float>& g = gradBuf_;
        for (torch::Tensor& p : params)
        {
            const std::int64_t n = p.numel();
            if (!p.grad().defined())
            {
                // Not in the graph (the same on every rank and shard)
                o += n;
                continue;
            }
            g.resize(n);
            for (std::int64_t i = 0; i < n; ++i)
            {
                double s = 0;
                for (std::int64_t k = 0; k < nShards; ++k)
                {
                    s += w[k]*double(buf[k*nValues + o + i]);
                }
                g[i] = float(s);
            }
            p.mutable_grad().copy_
            (
                torch::from_blob
                (
                    g.data(), p.sizes(),
                    torch::TensorOptions().dtype(torch::kFloat32)
                )
            );
            o += n;
        }
        for (std::int64_t k = 0; k < nShards; ++k)
        {
            loss += w[k]*double(buf[k*nValues + o]);
        }
    }
    optimizer_->step();
    ++step_;
    return double(float(loss));
}


std::vector<float> graphNetTrainer::parameterValues() const
{
    std::vector<float> v;
    for (const torch::Tensor& p : net_->parameters())
    {
        const torch::Tensor c = p.detach().to(torch::kFloat32).contiguous();
        v.insert(v.end(), c.data_ptr<float>(), c.data_ptr<float>() + c.numel());
    }
    return v;
}


// * * * * * * * * * * * * * * * * * Inference * * * * * * * * * * * * * * * //

torch::Tensor graphNetTrainer::predict(const torch::Tensor& xIn)
{
    const torch::Tensor x = checked(xIn, netConfig_.nIn);
    torch::NoGradGuard noGrad;
    net_->eval();
    return outNorm_->inverse(net_->forward(inNorm_->forward(x)));
}


std::vector<double> graphNetTrainer::predict(const std::vector<double>& x)
{
    const torch::Tensor q =
        predict(fromPlain(x, netConfig_.nIn)).to(torch::kFloat64).contiguous();
    return std::vector<double>(q.data_ptr<double>(), q.data_ptr<double>() + q.numel());
}


// * * * * * * * * * * * * * * * * Checkpoints * * * * * * * * * * * * * * * //

void graphNetTrainer::save(const std::string& file) const
{
    torch::serialize::OutputArchive root, net, in, out, opt;
    net_->save(net);
    inNorm_->save(in);
    outNorm_->save(out);
    optimizer_->save(opt);
    root.write("net", net);
    root.write("inputNormaliser", in);
    root.write("outputNormaliser", out);
    root.write("optimizer", opt);
    root.write("step", torch::tensor(step_));
    root.write("config", torch::tensor(netConfig_.codes()));
    root.write("nNodes", torch::tensor(net_->nNodes()));
    root.write("seed", torch::tensor(std::int64_t(config_.seed)));
    root.save_to(file);
}


void graphNetTrainer::load(const std::string& file)
{
    if (!std::ifstream(file).good())
    {
        throw std::runtime_error
        (
            "graphNetTrainer: cannot read the model file '" + file + "'"
        );
    }
    torch::serialize::InputArchive root;
    try
    {
        root.load_from(file);
    }
    catch (const c10::Error& e)
    {
        throw std::runtime_error
        (
            "graphNetTrainer: '" + file + "' is not a model checkpoint"
        );
    }

    torch::Tensor codes, nNodes, step;
    if
    (
        !root.try_read("config", codes)
     || !root.try_read("nNodes", nNodes)
     || !root.try_read("step", step)
    )
    {
        throw std::runtime_error
        (
            "graphNetTrainer: '" + file + "' is not a model checkpoint"
            " (no config, nNodes or step)"
        );
    }
    const std::vector<std::int64_t> mine = netConfig_.codes();
    const std::vector<std::int64_t> theirs
    (
        codes.data_ptr<std::int64_t>(),
        codes.data_ptr<std::int64_t>() + codes.numel()
    );
    if (theirs != mine)
    {
        graphNetConfig c;
        if (theirs.size() == 7)
        {
            c.type = theirs[0] == 1 ? "bsms" : theirs[0] == 2 ? "mgn" : "?";
            c.nIn = int(theirs[1]); c.nOut = int(theirs[2]);
            c.latent = int(theirs[3]); c.hidden = int(theirs[4]);
            c.nMessagePasses = int(theirs[5]); c.nLevels = int(theirs[6]);
        }
        throw std::runtime_error
        (
            "graphNetTrainer: the model in '" + file + "' (" + c.str()
          + ") does not match this one (" + netConfig_.str() + ")"
        );
    }
    if (nNodes.item<std::int64_t>() != net_->nNodes())
    {
        throw std::runtime_error
        (
            "graphNetTrainer: the model in '" + file + "' was trained on "
          + std::to_string(nNodes.item<std::int64_t>()) + " nodes, this graph"
            " has " + std::to_string(net_->nNodes())
        );
    }

    torch::serialize::InputArchive net, in, out, opt;
    root.read("net", net);
    root.read("inputNormaliser", in);
    root.read("outputNormaliser", out);
    root.read("optimizer", opt);
    net_->load(net);
    inNorm_->load(in);
    outNorm_->load(out);
    optimizer_->load(opt);
    step_ = step.item<std::int64_t>();
    torch::Tensor seed;
    if (root.try_read("seed", seed))
    {
        config_.seed = std::uint64_t(seed.item<std::int64_t>());
    }
}

} // End namespace gnnTorch

// ************************************************************************* //
