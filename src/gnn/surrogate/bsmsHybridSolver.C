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
#include <cstdio>
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


//- Write a registered object to file, whatever its instance (the header,
//  its data, the end divider)
void writeFile(const Foam::regIOobject& obj, const Foam::fileName& file)
{
    Foam::OFstream os(file);
    obj.writeHeader(os);
    obj.writeData(os);
    Foam::IOobject::writeEndDivider(os);
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
    const scalar modelDeltaT,
    const bool solverChoosesStep
)
:
    mesh_(mesh),
    modelSteps_(1),
    solverSteps_(1),
    solverDeltaT_(0),
    modelDeltaT_(modelDeltaT),
    solverChoosesStep_(solverChoosesStep),
    reportJump_(true),
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
    solver_ = getAsOrDefault<word>
    (
        d, "solver", controlDict.get<word>("application"),
        "the name of a solver application"
    );
    if (solver_ == "bsmsFoam")
    {
        badEntry(d, "solver", solver_, "the solver the model replaces");
    }
    reportJump_ = getAsOrDefault<bool>
    (
        d, "reportJump", true, "yes or no (true or false)"
    );
    const bool inModelSteps = d.found("solverModelSteps", keyType::LITERAL);
    if (solverChoosesStep_)
    {
        // The solver's step is its own (CFL): the phase in model steps
        for (const char* key : {"solverSteps", "deltaT"})
        {
            if (d.found(key, keyType::LITERAL))
            {
                badEntry
                (
                    d, key, entryText(d, key),
                    "no such entry: " + solver_ + " chooses its own time"
                    " step, so a phase is given as solverModelSteps K"
                    " (K model steps' time)"
                );
            }
        }
        phaseModelSteps_ = requiredCount(d, "solverModelSteps");
        solverSteps_ = -1;
    }
    else if (inModelSteps)
    {
        if (d.found("solverSteps", keyType::LITERAL))
        {
            badEntry
            (
                d, "solverSteps", entryText(d, "solverSteps"),
                "either solverSteps or solverModelSteps, not both"
            );
        }
        phaseModelSteps_ = requiredCount(d, "solverModelSteps");
        solverDeltaT_ = getPositive
        (
            d, "deltaT", controlDict.get<scalar>("deltaT")
        );
        const scalar steps = phaseModelSteps_*modelDeltaT_/solverDeltaT_;
        solverSteps_ = label(std::round(steps));
        if (solverSteps_ < 1 || mag(steps - solverSteps_) > 1e-6*steps)
        {
            badEntry
            (
                d, "deltaT", entryText(d, "deltaT"),
                "a solver step that divides the phase of "
              + Foam::name(phaseModelSteps_) + " model steps of "
              + Foam::name(modelDeltaT_)
            );
        }
    }
    else
    {
        solverSteps_ = requiredCount(d, "solverSteps");
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
    }
    controlDict_.remove("bsmsHybrid");
    controlDict_.remove("functions");
    controlDict_.remove("bsmsModel");
    controlDict_.remove("bsmsRangeWarning");
    makeSubCase();
    Info<< "Hybrid rollout: " << modelSteps_ << " model steps, then ";
    if (solverChoosesStep_)
    {
        Info<< phaseModelSteps_ << " model step(s) of " << solver_
            << " (its own time step)";
    }
    else
    {
        Info<< solverSteps_ << " steps of " << solver_ << " (deltaT "
            << solverDeltaT_ << ", " << phaseModelSteps_ << " model step(s))";
    }
    Info<< ", in " << dir_ << nl;
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
    if (solverChoosesStep_)
    {
        // Its own step, cut to land on the model's times
        d.set("writeControl", word("adjustableRunTime"));
    }
    else
    {
        d.set("deltaT", solverDeltaT_);
        d.set("adjustTimeStep", false);
        d.set("writeControl", word("runTime"));
    }
    d.set("writeInterval", modelDeltaT_);
    d.set("timePrecision", 12);
    OFstream os(dir_/"system"/"controlDict");
    os.precision(15);
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

Foam::fileName Foam::bsmsHybridSolver::startPhase()
{
    const word tName(Time::timeName(mesh_.time().value(), 12));
    const fileName start(dir_/tName);

    // The solver's last fields, for the handed-over ones to go over; the
    // earlier phases' time directories go
    copyFieldFiles(lastSolverTime_, start);
    for (const fileName& d : readDir(dir_, fileName::DIRECTORY))
    {
        scalar v;
        if (d != tName && readScalar(d, v)) rmDir(dir_/d);
    }
    return start;
}


void Foam::bsmsHybridSolver::solve()
{
    const Time& runTime = mesh_.time();
    const scalar t0 = runTime.value();
    const scalar t1 = t0 + phaseModelSteps_*modelDeltaT_;
    const word tName(Time::timeName(t0, 12));
    writeControlDict(t0, t1);

    lastLog_ = dir_/("log." + solver_ + "." + tName);
    const std::string cmd =
        "cd '" + dir_ + "' && " + solver_ + " > '" + lastLog_ + "' 2>&1";
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
            << "; see " << lastLog_ << exit(FatalError);
    }
}


void Foam::bsmsHybridSolver::runPhase(const wordList& outputs)
{
    const fileName start(startPhase());
    // Written by hand: regIOobject::write puts any object that is not in
    // system/ or constant/ into the current time's directory of the case
    for (const word& f : outputs)
    {
        if (const auto* sf = mesh_.findObject<volScalarField>(f))
        {
            writeFile(*sf, start/f);
        }
        else
        {
            writeFile(mesh_.lookupObject<volVectorField>(f), start/f);
        }
    }
    if (const auto* phi = mesh_.findObject<surfaceScalarField>("phi"))
    {
        writeFile(*phi, start/"phi");
    }
    // The solver's old times of the handed-over fields belong to its own
    // last state, a phase old, not to the model's: without them it starts
    // as from a fresh start (backward: one Euler step)
    wordList handed(outputs);
    handed.append("phi");
    for (const word& f : handed)
    {
        for (const word old : {f + "_0", f + "_0_0"})
        {
            if (isFile(start/old)) rm(start/old);
        }
    }
    solve();
}


Foam::fileName Foam::bsmsHybridSolver::phaseTime(const label k)
{
    const scalar t = mesh_.time().value();
    const word tName(solverTimeName(t));
    if (tName.empty())
    {
        FatalErrorInFunction
            << "The hybrid rollout's solver wrote no time "
            << Time::timeName(t, 12)
            << " in " << dir_ << " (model time " << k << " of its phase)"
            << exit(FatalError);
    }
    // The solver's own fields (p, phi, ...) of this time for the next
    // handover
    if (k == phaseModelSteps_)
    {
        lastSolverTime_ = dir_/tName;
    }
    return dir_/tName;
}


std::string Foam::bsmsHybridSolver::summary
(
    const label nSolverTimes,
    const label nModelSteps,
    const double jumpSeconds
) const
{
    char buf[300];
    std::snprintf
    (
        buf, sizeof(buf),
        "Hybrid rollout: %d solver phases (%d model times) in %.3f s"
        " (the solver's processes, start-up included), %d model steps;"
        " the jumps' model steps %.3f s (not counted above)",
        int(nPhases_), int(nSolverTimes), solverSeconds_, int(nModelSteps),
        jumpSeconds
    );
    return buf;
}


void Foam::bsmsHybridSolver::readBack
(
    const wordList& names,
    const label k
)
{
    const word tName(phaseTime(k).name());
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
}

// ************************************************************************* //
