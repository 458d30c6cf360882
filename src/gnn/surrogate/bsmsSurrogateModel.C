/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "bsmsSurrogateModel.H"
#include "polyMesh.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "meshGraph.H"
#include "bsmsPooling.H"
#include "bsmsExport.H"
#include <chrono>
#include <stdexcept>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bsmsSurrogateModel::bsmsSurrogateModel
(
    const polyMesh& mesh,
    const bsmsModelSpec& spec,
    const gnnTorch::trainerSettings& s
)
:
    mesh_(mesh),
    spec_(spec),
    types_(nodeTypeColumns(mesh, spec.nodeTypes)),
    outInState_(spec.outputInState()),
    used_(spec.nState(), 1.0)
{
    {
        label o = 0;
        for (const label nc : spec_.inputComponents)
        {
            if (nc == 3)
            {
                for (direction d = 0; d < 3; ++d)
                {
                    if (mesh.geometricD()[d] < 0) used_[o + d] = 0;
                }
            }
            o += nc;
        }
    }

    const auto t0 = std::chrono::steady_clock::now();
    const int dim = mesh.nGeometricD() < 3 ? 2 : 3;
    const meshGraph fine(mesh, meshGraph::nodeType::cells);
    if (spec_.model == "bsms")
    {
        dictionary levelsDict(spec_.levels);
        if (!levelsDict.found("seeding"))
        {
            levelsDict.add("seeding", word("closeCenter"));
        }
        bsmsPooling P(levelsDict);
        P.build(fine);
        graph_ = bsmsExport(P, dim);
    }
    else
    {
        graph_ = bsmsExport(fine, dim);
    }
    const std::string err = graph_.check();
    if (!err.empty())
    {
        FatalErrorInFunction
            << "Inconsistent graph hierarchy: " << err.c_str()
            << exit(FatalError);
    }
    buildSeconds_ = std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - t0
    ).count();

    gnnTorch::trainerSettings ts(s);
    const gnnTorch::trainerSettings sizes(spec_.settings());
    ts.model = sizes.model;
    ts.nIn = sizes.nIn;
    ts.nOut = sizes.nOut;
    ts.latent = sizes.latent;
    ts.hidden = sizes.hidden;
    ts.nMessagePasses = sizes.nMessagePasses;
    // Rollout training advances the outputs' state columns of the input
    // (x = [state, node types]), not the empty direction
    ts.outputColumns.clear();
    ts.outputMask.clear();
    for (const label c : outInState_)
    {
        ts.outputColumns.push_back(c);
        ts.outputMask.push_back(used_[c]);
    }
    try
    {
        net_.reset(new gnnTorch::bsmsTrainerFacade(graph_, ts));
    }
    catch (const std::exception& e)
    {
        FatalErrorInFunction
            << "Cannot build the model: " << e.what() << exit(FatalError);
    }
}


std::unique_ptr<Foam::bsmsSurrogateModel> Foam::bsmsSurrogateModel::load
(
    const polyMesh& mesh,
    const fileName& checkpoint,
    const dictionary& errDict,
    const word& entry
)
{
    const fileName specFile(bsmsSpecFile(checkpoint));
    for (const fileName& f : {checkpoint, specFile})
    {
        if (!isFile(f))
        {
            FatalIOErrorInFunction(errDict)
                << "The model file " << f << " (entry '" << entry << "' in "
                << errDict.name() << ") does not exist; bsmsTrain writes the"
                << " checkpoint and its model dictionary "
                << specFile.name() << " beside it" << exit(FatalIOError);
        }
    }
    IFstream is(specFile);
    dictionary specDict(is, true);
    specDict.name() = specFile;
    const bsmsModelSpec spec(bsmsModelSpec::read(specDict));

    std::unique_ptr<bsmsSurrogateModel> m
    (
        new bsmsSurrogateModel(mesh, spec, gnnTorch::trainerSettings())
    );
    try
    {
        m->net().load(checkpoint);
    }
    catch (const std::exception& e)
    {
        FatalIOErrorInFunction(errDict)
            << "The model " << checkpoint << " (entry '" << entry << "' in "
            << errDict.name() << ") does not match this case: " << e.what()
            << exit(FatalIOError);
    }
    return m;
}


Foam::bsmsSurrogateModel::~bsmsSurrogateModel() = default;


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::bsmsSurrogateModel::nCells() const
{
    return mesh_.nCells();
}


Foam::string Foam::bsmsSurrogateModel::levelSizes() const
{
    OStringStream os;
    for (std::size_t l = 0; l < graph_.levels.size(); ++l)
    {
        if (l) os << ' ';
        os << label(graph_.levels[l].nNodes);
    }
    return os.str();
}


Foam::bsmsInputRange Foam::bsmsSurrogateModel::inputRange
(
    const double nStd
) const
{
    std::vector<double> mean, std;
    const long n = long(net_->inputStatistics(mean, std));
    return bsmsInputRange(spec_, used_, mean, std, n, nStd);
}


void Foam::bsmsSurrogateModel::appendInput
(
    const std::vector<double>& state,
    std::vector<double>& x
) const
{
    const label nS = spec_.nState();
    const label nT = spec_.nTypes();
    const label n = nCells();
    x.reserve(x.size() + std::size_t(n)*(nS + nT));
    for (label k = 0; k < n; ++k)
    {
        const double* s = state.data() + std::size_t(k)*nS;
        for (label c = 0; c < nS; ++c) x.push_back(used_[c]*s[c]);
        const double* t = types_.data() + std::size_t(k)*nT;
        x.insert(x.end(), t, t + nT);
    }
}


void Foam::bsmsSurrogateModel::appendTarget
(
    const std::vector<double>& state0,
    const std::vector<double>& state1,
    std::vector<double>& y
) const
{
    const label nS = spec_.nState();
    const label n = nCells();
    y.reserve(y.size() + std::size_t(n)*outInState_.size());
    for (label k = 0; k < n; ++k)
    {
        const std::size_t o = std::size_t(k)*nS;
        for (const label c : outInState_)
        {
            y.push_back
            (
                used_[c]
              * (spec_.increment ? state1[o + c] - state0[o + c] : state1[o + c])
            );
        }
    }
}


void Foam::bsmsSurrogateModel::advance(std::vector<double>& state)
{
    x_.clear();
    appendInput(state, x_);
    const std::vector<double> q(net_->predict(x_));
    const label nS = spec_.nState();
    const label nO = outInState_.size();
    const label n = nCells();
    for (label k = 0; k < n; ++k)
    {
        const std::size_t o = std::size_t(k)*nS;
        for (label j = 0; j < nO; ++j)
        {
            const label c = outInState_[j];
            if (!used_[c]) continue;
            const double v = q[std::size_t(k)*nO + j];
            double& s = state[o + c];
            s = spec_.increment ? s + v : v;
        }
    }
}


double Foam::bsmsSurrogateModel::outputMse
(
    const std::vector<double>& a,
    const std::vector<double>& b
) const
{
    const label nS = spec_.nState();
    const label n = nCells();
    double sum = 0, nUsed = 0;
    for (const label c : outInState_) nUsed += used_[c];
    for (label k = 0; k < n; ++k)
    {
        const std::size_t o = std::size_t(k)*nS;
        for (const label c : outInState_)
        {
            const double d = used_[c]*(a[o + c] - b[o + c]);
            sum += d*d;
        }
    }
    return sum/(double(n)*max(nUsed, 1.0));
}

// ************************************************************************* //
