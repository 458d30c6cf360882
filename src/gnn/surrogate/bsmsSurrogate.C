/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "bsmsSurrogate.H"
#include "bsmsFieldIO.H"
#include "volFields.H"
#include "Time.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"
#include <chrono>
#include <cstdio>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(bsmsSurrogate, 0);
    addToRunTimeSelectionTable(functionObject, bsmsSurrogate, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::bsmsSurrogate::checkRange()
{
    if (!range_) return;
    for (const string& m : range_->check(state_, modelTime_))
    {
        WarningInFunction
            << type() << ' ' << name() << ": " << m.c_str() << endl;
    }
}


void Foam::functionObjects::bsmsSurrogate::start()
{
    model_.reset(new bsmsGatheredModel(mesh_, modelFile_, dict_, "model"));
    const bsmsModelSpec& spec = model_->spec();

    // From the run's start: function objects first execute after the first
    // solver step, so the start state is read from the start time's files
    // (which the solver read too); later: the solver's current fields
    const scalar t0 = time_.startTime().value();
    if (startTime_ <= t0 + 1e-9*max(mag(t0), scalar(1)))
    {
        labelList comps(spec.inputComponents);
        state_ = model_->gather
        (
            readFieldState
            (
                time_.path()/time_.timeName(t0), spec.inputFields,
                mesh_.nCells(), comps, dict_, "model"
            )
        );
        modelTime_ = t0;
    }
    else
    {
        state_ = model_->gather
        (
            registryState
            (
                mesh_, spec.inputFields, spec.inputComponents, dict_, "model"
            )
        );
        modelTime_ = time_.value();
    }
    nModelSteps_ = 0;
    modelSeconds_ = 0;
    if (model_->holdsModel())
    {
        range_.reset
        (
            new bsmsInputRange(model_->model().inputRange(rangeWarning_))
        );
    }
    checkRange();

    // The prediction and error fields of the outputs
    forAll(spec.inputFields, i)
    {
        const word& f = spec.inputFields[i];
        if (!spec.outputFields.found(f)) continue;
        for (const word& suffix : {word("_gnn"), word("_gnnError")})
        {
            const word n(f + suffix);
            if (mesh_.foundObject<regIOobject>(n)) continue;
            IOobject io
            (
                n, time_.timeName(), mesh_,
                IOobject::NO_READ, IOobject::NO_WRITE, true
            );
            if (spec.inputComponents[i] == 1)
            {
                const auto& s = mesh_.lookupObject<volScalarField>(f);
                auto* p = new volScalarField(io, s);
                p->store();
            }
            else
            {
                const auto& v = mesh_.lookupObject<volVectorField>(f);
                auto* p = new volVectorField(io, v);
                p->store();
            }
        }
    }

    const fileName dir
    (
        time_.globalPath()/"postProcessing"/name()/time_.timeName()
    );
    if (!Pstream::master()) return;
    mkDir(dir);
    file_.reset(new OFstream(dir/"bsmsSurrogate.dat"));
    file_() << "# model " << modelFile_ << ", deltaT " << spec.deltaT
        << ", from t = " << modelTime_ << nl
        << "# time modelSteps";
    for (const word& f : spec.outputFields) file_() << " RMSE_" << f;
    file_() << " modelStepSeconds" << endl;

    Info<< type() << ' ' << name() << ": model " << modelFile_ << " ("
        << spec.model << ", levels " << model_->levelSizes().c_str()
        << "), deltaT " << spec.deltaT << ", rollout from t = "
        << modelTime_ << endl;
}


Foam::List<Foam::scalar> Foam::functionObjects::bsmsSurrogate::rmse() const
{
    const bsmsModelSpec& spec = model_->spec();
    const std::vector<double> solver
    (
        model_->gather
        (
            registryState
            (
                mesh_, spec.inputFields, spec.inputComponents, dict_, "model"
            )
        )
    );
    const label nS = spec.nState();
    List<scalar> r(spec.outputFields.size(), scalar(0));
    if (!model_->holdsModel())
    {
        Pstream::scatter(r);
        return r;
    }
    const label nCells = model_->nGlobalCells();
    label o = 0;
    forAll(spec.inputFields, i)
    {
        const label j = spec.outputFields.find(spec.inputFields[i]);
        const label nc = spec.inputComponents[i];
        if (j >= 0)
        {
            double sum = 0;
            label nUsed = 0;
            for (label c = 0; c < nc; ++c)
            {
                if (!model_->model().used(o + c)) continue;
                ++nUsed;
                for (label k = 0; k < nCells; ++k)
                {
                    const std::size_t q = std::size_t(k)*nS + o + c;
                    const double d = state_[q] - solver[q];
                    sum += d*d;
                }
            }
            r[j] = std::sqrt(sum/(double(nCells)*max(nUsed, 1)));
        }
        o += nc;
    }
    if (Pstream::parRun()) Pstream::scatter(r);
    return r;
}


void Foam::functionObjects::bsmsSurrogate::updateFields()
{
    const bsmsModelSpec& spec = model_->spec();
    setFields
    (
        mesh_, model_->scatter(state_), spec.inputFields, spec.inputComponents,
        spec.outputFields, "_gnn"
    );
    forAll(spec.inputFields, i)
    {
        const word& f = spec.inputFields[i];
        if (!spec.outputFields.found(f)) continue;
        if (spec.inputComponents[i] == 1)
        {
            auto& e = mesh_.lookupObjectRef<volScalarField>(f + "_gnnError");
            e = mesh_.lookupObject<volScalarField>(f + "_gnn")
              - mesh_.lookupObject<volScalarField>(f);
        }
        else
        {
            auto& e = mesh_.lookupObjectRef<volVectorField>(f + "_gnnError");
            e = mesh_.lookupObject<volVectorField>(f + "_gnn")
              - mesh_.lookupObject<volVectorField>(f);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::bsmsSurrogate::bsmsSurrogate
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    startTime_(-GREAT),
    modelTime_(0),
    nModelSteps_(0),
    modelSeconds_(0),
    failed_(false),
    rangeWarning_(2)
{
    read(dict);
}


Foam::functionObjects::bsmsSurrogate::~bsmsSurrogate() = default;


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::bsmsSurrogate::read(const dictionary& dict)
{
    using namespace dictionaryChecks;
    fvMeshFunctionObject::read(dict);
    dict_ = dict;
    modelFile_ = getAsOrDefault<fileName>
    (
        dict, "model", fileName("constant/bsmsModel.pt"), "a file name"
    );
    modelFile_.expand();
    if (!modelFile_.isAbsolute()) modelFile_ = time_.globalPath()/modelFile_;
    startTime_ = getAsOrDefault<scalar>
    (
        dict, "startTime", time_.startTime().value(), "a time"
    );
    if (!std::isfinite(startTime_) || mag(startTime_) > 1e30)
    {
        badEntry(dict, "startTime", Foam::name(startTime_),
            "a finite time of magnitude <= 1e30");
    }
    rangeWarning_ = getInRange(dict, "rangeWarning", 2, 0, 1e30);
    return true;
}


bool Foam::functionObjects::bsmsSurrogate::execute()
{
    const scalar t = time_.value();
    if (!model_)
    {
        if (t >= startTime_ - 1e-9*max(mag(startTime_), scalar(1))) start();
        return true;
    }
    if (failed_) return true;

    const bsmsModelSpec& spec = model_->spec();
    const scalar eps = 1e-6*spec.deltaT;
    bool reached = false;
    while (t >= modelTime_ + spec.deltaT - eps)
    {
        const auto t0 = std::chrono::steady_clock::now();
        std::vector<double> next(state_);
        const bool finite = model_->advance(next);
        const double sec = std::chrono::duration<double>
        (
            std::chrono::steady_clock::now() - t0
        ).count();
        modelSeconds_ += sec;
        modelTime_ += spec.deltaT;
        ++nModelSteps_;
        if (!finite)
        {
            WarningInFunction
                << type() << ' ' << name() << ": the model predicted"
                << " non-finite values at t = " << modelTime_ << " (model"
                << " step " << nModelSteps_ << "); the rollout stops and"
                << " keeps its last good state (t = "
                << modelTime_ - spec.deltaT << "); the solver goes on"
                << endl;
            if (range_)
            {
                for (const string& m : range_->summary())
                {
                    Info<< type() << ' ' << name() << ": " << m.c_str() << nl;
                }
            }
            if (file_.valid())
            {
                file_() << "# non-finite prediction at t = " << modelTime_
                    << "; rollout stopped" << endl;
            }
            // The state kept is the last good one: so are its time and step
            modelTime_ -= spec.deltaT;
            --nModelSteps_;
            failed_ = true;
            return true;
        }
        state_.swap(next);
        checkRange();
        reached = mag(t - modelTime_) < eps;

        if (reached)
        {
            const List<scalar> r(rmse());
            char buf[64];
            if (file_.valid())
            {
                file_() << time_.timeName() << ' ' << nModelSteps_;
                for (const scalar e : r)
                {
                    std::snprintf(buf, sizeof(buf), " %.6e", e);
                    file_() << buf;
                }
                std::snprintf(buf, sizeof(buf), " %.6e", sec);
                file_() << buf << endl;
            }
            Info<< type() << ' ' << name() << ": model step "
                << nModelSteps_ << ", RMSE " << spec.outputFields << ' '
                << r << nl;
        }
    }
    return true;
}


bool Foam::functionObjects::bsmsSurrogate::write()
{
    if (!model_) return true;
    updateFields();
    const bsmsModelSpec& spec = model_->spec();
    for (const word& f : spec.outputFields)
    {
        mesh_.lookupObject<regIOobject>(f + "_gnn").write();
        mesh_.lookupObject<regIOobject>(f + "_gnnError").write();
    }
    Info<< type() << ' ' << name() << ": wrote";
    for (const word& f : spec.outputFields) Info<< ' ' << f << "_gnn";
    Info<< " (model time " << modelTime_ << ", " << nModelSteps_
        << " model steps, " << 1e3*modelSeconds_/max(nModelSteps_, label(1))
        << " ms per step)" << endl;
    return true;
}

// ************************************************************************* //
