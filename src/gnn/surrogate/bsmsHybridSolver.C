/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "bsmsHybridSolver.H"
#include "dictionaryChecks.H"
#include "volFields.H"
#include "surfaceFields.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "IOdictionary.H"

#include <chrono>
#include <cmath>
#include <cstdlib>

using namespace Foam::dictionaryChecks;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- A label entry that must be there, >= 1
Foam::label requiredCount(const Foam::dictionary& d, const Foam::word& key)
{
    const Foam::string allowed("a whole number >= 1");
    if (!d.found(key, Foam::keyType::LITERAL))
    {
        missingEntry(d, key, allowed);
    }
    const Foam::scalar v = getAs<Foam::scalar>(d, key, allowed);
    if (!(v >= 1 && v < 1e9 && v == std::floor(v)))
    {
        badEntry(d, key, entryText(d, key), allowed);
    }
    return Foam::label(v);
}


//- Copy the regular field files of time directory from into to (not
//  uniform/ or any other directory)
void copyFieldFiles(const Foam::fileName& from, const Foam::fileName& to)
{
    Foam::mkDir(to);
    for (const Foam::fileName& f : Foam::readDir(from, Foam::fileName::FILE))
    {
        Foam::cp(from/f, to/f);
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructor  * * * * * * * * * * * * * * //

bool Foam::bsmsHybridSolver::active(const dictionary& controlDict)
{
    return controlDict.found("bsmsHybrid", keyType::LITERAL);
}


Foam::bsmsHybridSolver::bsmsHybridSolver
(
    const fvMesh& mesh,
    const dictionary& controlDict,
    const scalar modelDeltaT
)
:
    mesh_(mesh),
    modelSteps_(1),
    solverSteps_(1),
    solverDeltaT_(0),
    modelDeltaT_(modelDeltaT),
    phaseModelSteps_(1),
    controlDict_(controlDict),
    dir_(mesh.time().path()/"bsmsHybrid"),
    lastSolverTime_(mesh.time().path()/mesh.time().timeName())
{
    if (!controlDict.isDict("bsmsHybrid"))
    {
        badEntry
        (
            controlDict, "bsmsHybrid", entryText(controlDict, "bsmsHybrid"),
            "a sub-dictionary { modelSteps N; solverSteps M; solver name;"
            " deltaT dt; }"
        );
    }
    const dictionary& d = controlDict.subDict("bsmsHybrid");
    if (Pstream::parRun())
    {
        FatalIOErrorInFunction(d)
            << "Entry 'bsmsHybrid' in " << d.name() << ": a hybrid rollout"
            << " runs serially (the solver phases would each need the"
            << " state decomposed); run bsmsFoam without -parallel"
            << exit(FatalIOError);
    }
    modelSteps_ = requiredCount(d, "modelSteps");
    solverSteps_ = requiredCount(d, "solverSteps");
    solver_ = getAsOrDefault<word>
    (
        d, "solver", controlDict.get<word>("application"),
        "the name of a solver application"
    );
    if (solver_ == "bsmsFoam")
    {
        badEntry(d, "solver", solver_, "the solver the model replaces");
    }
    solverDeltaT_ = getPositive
    (
        d, "deltaT", controlDict.get<scalar>("deltaT")
    );
    const scalar span = solverSteps_*solverDeltaT_;
    const scalar ratio = span/modelDeltaT_;
    phaseModelSteps_ = label(std::round(ratio));
    if (phaseModelSteps_ < 1 || mag(ratio - phaseModelSteps_) > 1e-6*ratio)
    {
        FatalIOErrorInFunction(d)
            << "Entries 'solverSteps' " << solverSteps_ << " and 'deltaT' "
            << solverDeltaT_ << " in " << d.name() << ": a solver phase"
            << " spans " << span << ", which is not a whole number of model"
            << " steps of " << modelDeltaT_ << nl
            << "    allowed: solverSteps x deltaT = k x " << modelDeltaT_
            << " for a whole k >= 1 (e.g. solverSteps "
            << max(label(1), label(std::round(modelDeltaT_/solverDeltaT_)))
            << ")" << exit(FatalIOError);
    }
    controlDict_.remove("bsmsHybrid");
    controlDict_.remove("functions");
    controlDict_.remove("bsmsModel");
    controlDict_.remove("bsmsRangeWarning");
    makeSubCase();
    Info<< "Hybrid rollout: " << modelSteps_ << " model steps, then "
        << solverSteps_ << " steps of " << solver_ << " (deltaT "
        << solverDeltaT_ << ", " << phaseModelSteps_ << " model step(s)),"
        << " in " << dir_ << nl;
}


// * * * * * * * * * * * * * * * Private Functions * * * * * * * * * * * * * //

void Foam::bsmsHybridSolver::makeSubCase() const
{
    const fileName casePath(mesh_.time().path());
    if (isDir(dir_)) rmDir(dir_);
    mkDir(dir_/"system");
    ln("../constant", dir_/"constant");
    for (const fileName& f : readDir(casePath/"system", fileName::FILE))
    {
        if (f != "controlDict") ln("../../system"/f, dir_/"system"/f);
    }
}


void Foam::bsmsHybridSolver::writeControlDict
(
    const scalar t0,
    const scalar t1
) const
{
    dictionary d(controlDict_);
    d.set("application", solver_);
    d.set("startFrom", word("startTime"));
    d.set("startTime", t0);
    d.set("stopAt", word("endTime"));
    d.set("endTime", t1);
    d.set("deltaT", solverDeltaT_);
    d.set("adjustTimeStep", false);
    d.set("writeControl", word("runTime"));
    d.set("writeInterval", modelDeltaT_);
    d.set("timePrecision", 12);
    OFstream os(dir_/"system"/"controlDict");
    IOobject::writeBanner(os);
    os  << "FoamFile\n{\n    version 2.0;\n    format ascii;\n"
        << "    class dictionary;\n    object controlDict;\n}\n\n"
        << "// A hybrid rollout's solver phase, written by bsmsFoam" << nl;
    d.write(os, false);
}


Foam::word Foam::bsmsHybridSolver::solverTimeName(const scalar t) const
{
    // The solver sums its steps, so its time names can differ from t in
    // the last digits (32.500000004 for 32.5): the nearest within 1e-6 of a
    // model step
    word best;
    scalar bestDist = 1e-6*modelDeltaT_;
    for (const fileName& d : readDir(dir_, fileName::DIRECTORY))
    {
        scalar v;
        if (readScalar(d, v) && mag(v - t) <= bestDist)
        {
            bestDist = mag(v - t);
            best = d;
        }
    }
    return best;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bsmsHybridSolver::runPhase(const wordList& outputs)
{
    const Time& runTime = mesh_.time();
    const scalar t0 = runTime.value();
    const scalar t1 = t0 + phaseModelSteps_*modelDeltaT_;
    const word tName(Time::timeName(t0, 12));
    const fileName start(dir_/tName);

    // The solver's last fields, the model's outputs over them
    copyFieldFiles(lastSolverTime_, start);
    if (lastSolverTime_.path() == dir_ && lastSolverTime_ != start)
    {
        rmDir(lastSolverTime_);
    }
    for (const word& f : outputs)
    {
        const IOobject io
        (
            f, fileName("bsmsHybrid")/tName, mesh_,
            IOobject::NO_READ, IOobject::NO_WRITE, false
        );
        if (mesh_.foundObject<volScalarField>(f))
        {
            volScalarField(io, mesh_.lookupObject<volScalarField>(f)).write();
        }
        else
        {
            volVectorField(io, mesh_.lookupObject<volVectorField>(f)).write();
        }
    }
    if (mesh_.foundObject<surfaceScalarField>("phi"))
    {
        surfaceScalarField
        (
            IOobject
            (
                "phi", fileName("bsmsHybrid")/tName, mesh_,
                IOobject::NO_READ, IOobject::NO_WRITE, false
            ),
            mesh_.lookupObject<surfaceScalarField>("phi")
        ).write();
    }
    writeControlDict(t0, t1);

    const fileName log(dir_/("log." + solver_ + "." + tName));
    const std::string cmd =
        "cd '" + dir_ + "' && " + solver_ + " > '" + log + "' 2>&1";
    const auto ts = std::chrono::steady_clock::now();
    const int rc = std::system(cmd.c_str());
    solverSeconds_ += std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - ts
    ).count();
    ++nPhases_;
    const word endName(solverTimeName(t1));
    lastSolverTime_ = dir_/endName;
    if (rc != 0 || endName.empty())
    {
        FatalErrorInFunction
            << "The hybrid rollout's solver phase " << nPhases_ << " ("
            << solver_ << " from t = " << t0 << " to " << t1 << ") failed"
            << (rc != 0 ? " (exit status " + Foam::name(rc) + ")" : "")
            << (endName.size() ? "" : ", no time " + Time::timeName(t1, 12))
            << "; see " << log << exit(FatalError);
    }
}


void Foam::bsmsHybridSolver::readBack
(
    const wordList& names,
    const label k
)
{
    const Time& runTime = mesh_.time();
    const scalar t = runTime.value();
    const word tName(solverTimeName(t));
    if (tName.empty())
    {
        FatalErrorInFunction
            << "The hybrid rollout's solver wrote no time "
            << Time::timeName(t, 12)
            << " in " << dir_ << " (model time " << k << " of its phase)"
            << exit(FatalError);
    }
    for (const word& f : names)
    {
        const IOobject io
        (
            f, fileName("bsmsHybrid")/tName, mesh_,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        );
        if (mesh_.foundObject<volScalarField>(f))
        {
            volScalarField& v =
                const_cast<volScalarField&>(mesh_.lookupObject<volScalarField>(f));
            v == volScalarField(io, mesh_);
        }
        else
        {
            volVectorField& v =
                const_cast<volVectorField&>(mesh_.lookupObject<volVectorField>(f));
            v == volVectorField(io, mesh_);
        }
    }
    // The solver's own fields (p, phi, ...) of this time for the next
    // handover
    if (k == phaseModelSteps_)
    {
        lastSolverTime_ = dir_/tName;
    }
}

// ************************************************************************* //
