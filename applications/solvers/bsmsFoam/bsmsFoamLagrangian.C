/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "bsmsFoamLagrangian.H"
#include "lagrangianStepper.H"
#include "lagrangianHandover.H"
#include "bsmsHybridSolver.H"
#include "IFstream.H"
#include "bsmsExport.H"
#include "bsmsTrainerFacade.H"
#include "dictionaryChecks.H"
#include "passiveParticleCloud.H"
#include "IOField.H"
#include "Map.H"

#include <chrono>
#include <cstdio>
#include <stdexcept>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- The frames to read: the first written time (X), the one a model step
//  before the start (if any) and the start; the index of the previous
//  frame in them in prev (-1 if none)
instantList rolloutFrames(const Time& runTime, const scalar deltaT, label& prev)
{
    const scalar t0 = runTime.value();
    const scalar tol = 1e-6*deltaT;
    DynamicList<instant> frames;
    prev = -1;
    const instant* first = nullptr;
    const instant* before = nullptr;
    // The list outlives the loop: first and before point into it
    const instantList times(runTime.times());
    for (const instant& t : times)
    {
        if (t.name() == "constant" || t.value() > t0 - tol) continue;
        if (!first) first = &t;
        if (mag(t.value() - (t0 - deltaT)) < tol) before = &t;
    }
    if (first && first != before) frames.append(*first);
    if (before)
    {
        prev = frames.size();
        frames.append(*before);
    }
    frames.append(instant(t0, runTime.timeName()));
    return instantList(std::move(frames));
}


//- The cloud's field U at the current time, in the order of ids
vectorField velocities
(
    const fvMesh& mesh,
    const word& cloudName,
    const labelList& ids
)
{
    IOobject io
    (
        "U", mesh.time().timeName(), cloud::prefix/cloudName, mesh,
        IOobject::MUST_READ, IOobject::NO_WRITE, false
    );
    IOobject idIO(io, "id");
    if
    (
        !io.typeHeaderOk<IOField<vector>>(false)
     || !idIO.typeHeaderOk<IOField<label>>(false)
    )
    {
        FatalErrorInFunction
            << "The case has no previous frame (t = "
            << mesh.time().timeName() << " minus the model step) and no"
            << " velocities of the cloud '" << cloudName << "' to start from:"
            << " expected " << io.objectPath() << " and its id"
            << exit(FatalError);
    }
    const IOField<vector> U(io);
    const IOField<label> id(idIO);
    Map<label> index(2*id.size());
    forAll(id, i) index.insert(id[i], i);
    vectorField out(ids.size());
    forAll(ids, i) out[i] = U[index[ids[i]]];
    return out;
}


//- Write the material points as the cloud at the current time
void writeCloud
(
    const fvMesh& mesh,
    const word& cloudName,
    const lagrangianRecording& r,
    const pointField& x,
    const pointField& xPrev,
    const scalar deltaT
)
{
    const label nP = r.nPoints();
    mesh.tetBasePtIs();
    passiveParticleCloud cloud(mesh, cloudName, IDLList<passiveParticle>());
    label nOutside = 0;
    for (label i = 0; i < nP; ++i)
    {
        label celli = mesh.findCell(x[i]);
        point p = x[i];
        if (celli < 0)
        {
            ++nOutside;
            celli = mesh.findNearestCell(x[i]);
            p = mesh.cellCentres()[celli];
        }
        cloud.addParticle(new passiveParticle(mesh, p, celli));
    }
    cloud.write();
    auto io = [&](const word& name)
    {
        return IOobject
        (
            name, mesh.time().timeName(), cloud::prefix/cloudName, mesh,
            IOobject::NO_READ, IOobject::NO_WRITE, false
        );
    };
    IOField<label>(io("id"), r.ids()).write();
    const SubField<point> xP(x, nP);
    IOField<vector>(io("x"), xP).write();
    IOField<vector>
    (
        io("U"), (xP - SubField<point>(xPrev, nP))/deltaT
    ).write();
    IOField<vector>(io("d"), xP - SubField<point>(r.X(), nP)).write();
    if (nOutside)
    {
        WarningInFunction
            << nOutside << " of " << nP << " predicted points lie outside"
            << " the mesh at t = " << mesh.time().timeName() << ": written"
            << " in their nearest cells (field x holds the prediction)"
            << endl;
    }
}


//- The solver's steps in its log (umlsMpmFoam's "Particle-steps per
//  second: R (S steps, ..."), -1 if not found
label solverStepsIn(const fileName& log)
{
    IFstream is(log);
    string line;
    label steps = -1;
    while (is.good() && is.getLine(line).good())
    {
        const auto at = line.find("Particle-steps per second:");
        if (at == string::npos) continue;
        const auto open = line.find('(', at);
        if (open != string::npos)
        {
            steps = label(std::atol(line.c_str() + open + 1));
        }
    }
    return steps;
}


//- RMS and largest distance between the first n points of a and b
std::pair<scalar, scalar> distances
(
    const pointField& a,
    const pointField& b,
    const label n
)
{
    scalar sum = 0, most = 0;
    for (label i = 0; i < n; ++i)
    {
        const scalar d2 = magSqr(a[i] - b[i]);
        sum += d2;
        most = max(most, d2);
    }
    return {std::sqrt(sum/max(n, label(1))), std::sqrt(most)};
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

int Foam::bsmsFoamLagrangian
(
    Time& runTime,
    const fvMesh& mesh,
    const fileName& modelFile,
    const dictionary& spec
)
{
    using namespace dictionaryChecks;
    if (Pstream::parRun())
    {
        FatalIOErrorInFunction(spec)
            << "The model " << modelFile << " (" << spec.name() << ": graph"
            << " lagrangian) moves material points, which bsmsFoam advances"
            << " serially for now: run it without -parallel"
            << exit(FatalIOError);
    }
    const scalar deltaT = getPositive(spec, "deltaT");
    const label nNodes = getLabelAtLeast(spec, "nNodes", 0, 1);
    const label nPoints = getLabelAtLeast(spec, "nPoints", 0, 1);
    const word cloudName
    (
        getAsOrDefault<word>(spec, "cloud", "mpmCloud", "a cloud name")
    );
    if (!spec.isDict("levels"))
    {
        missingEntry(spec, "levels", "the pooling's dictionary");
    }

    // The nodes: the case's cloud, its actuators
    label prev = -1;
    const instantList frames(rolloutFrames(runTime, deltaT, prev));
    const lagrangianRecording r(runTime, frames, spec);
    if (r.nNodes() != nNodes || r.nPoints() != nPoints)
    {
        FatalIOErrorInFunction(spec)
            << "The model " << modelFile << " was trained on nNodes "
            << nNodes << " (nPoints " << nPoints << " material points and "
            << nNodes - nPoints << " actuator nodes; entries 'nNodes' and"
            << " 'nPoints' in " << spec.name() << "), but the case has "
            << r.nNodes() << " (" << r.nPoints() << " material points of"
            << " the cloud '" << cloudName << "' at t = "
            << runTime.timeName() << " and " << r.nNodes() - r.nPoints()
            << " actuator nodes): a model is one set of nodes"
            << exit(FatalIOError);
    }
    const lagrangianStepper stepper(r, spec.subDict("levels"));

    // The network
    gnnTorch::bsmsTrainerFacade net
    (
        bsmsExport(stepper.pooling(), 3),
        lagrangianStepper::network
        (
            getLabelAtLeast(spec, "latent", 128, 1),
            getLabelAtLeast(spec, "hidden", 128, 1)
        )
    );
    try
    {
        net.load(modelFile);
    }
    catch (const std::exception& e)
    {
        FatalIOErrorInFunction(spec)
            << "The checkpoint " << modelFile << " is not the model that "
            << spec.name() << " describes on this case's graph: "
            << e.what() << exit(FatalIOError);
    }
    const lagrangianStepper::predictor model(lagrangianStepper::predictorOf(net));
    Info<< "Model " << modelFile << ": BSMS-GNN of moving bodies, "
        << r.nPoints() << " material points and " << r.nNodes() - r.nPoints()
        << " actuator nodes, levels of " << stepper.pooling().nLevels()
        << ", deltaT " << deltaT << nl;

    // The start: x_k and x_{k-1}
    const label nP = r.nPoints();
    pointField x(r.x(r.nFrames() - 1));
    pointField xPrev;
    if (prev >= 0)
    {
        xPrev = r.x(prev);
        Info<< "Start from t = " << runTime.timeName() << " and the frame"
            << " of t = " << r.times()[prev] << nl << endl;
    }
    else
    {
        const vectorField U(velocities(mesh, cloudName, r.ids()));
        xPrev = x;
        for (label i = 0; i < nP; ++i) xPrev[i] -= U[i]*deltaT;
        r.moveActuators(runTime.value() - deltaT, xPrev);
        Info<< "Start from t = " << runTime.timeName() << " with the"
            << " cloud's velocities (no frame one model step before)"
            << nl << endl;
    }

    // The rollout.  The case's function objects are the MPM solver's
    // monitors (mpmConservation, ...), which need its state: off
    if (runTime.functionObjects().size() || runTime.controlDict().found("functions"))
    {
        Info<< "The case's function objects are off (they monitor the MPM"
            << " solver's state, which a rollout does not have)" << nl << endl;
    }
    runTime.functionObjects().off();

    // Hybrid rollout: every N model steps the solver (umlsMpmFoam) runs
    // K model steps' time from the state rebuilt from the model's
    const dictionary& controlDict = runTime.controlDict();
    std::unique_ptr<bsmsHybridSolver> hybrid
    (
        bsmsHybridSolver::active(controlDict)
      ? new bsmsHybridSolver(mesh, controlDict, deltaT, true)
      : nullptr
    );
    std::unique_ptr<lagrangianHandover> handover
    (
        hybrid
      ? new lagrangianHandover
        (
            mesh, cloudName, r, controlDict.subDict("bsmsHybrid")
        )
      : nullptr
    );

    runTime.setDeltaT(deltaT);
    const auto t0 = std::chrono::steady_clock::now();
    label nSteps = 0;
    label nSolverTimes = 0;
    label sinceHandover = 0;
    double modelSeconds = 0;
    double jumpSeconds = 0;
    bool written = true;
    char buf[300];

    // One model step from xPrev, x at the current time into out; false
    // (node in bad) if not finite
    auto modelStep = [&]
    (
        const pointField& xp, const pointField& xk, const scalar t,
        pointField& out, label& bad
    )
    {
        pointField xNext(xk);
        r.moveActuators(t + deltaT, xNext);
        return stepper.step(model, xp, xk, xNext, out, bad);
    };

    // The solver's phase from the current time, if one is due and fits
    // before the end time: its model times read back, written as ours
    auto solverPhase = [&]()
    {
        if (!hybrid || sinceHandover < hybrid->modelSteps()) return;
        const label K = hybrid->phaseModelSteps();
        const scalar t1 = runTime.value() + K*deltaT;
        if (t1 > runTime.endTime().value() + 0.5*deltaT) return;
        const fileName here(runTime.timePath());
        const fileName start(hybrid->startPhase());
        handover->write(x, xPrev, deltaT);
        if (isDir(start/cloud::prefix)) rmDir(start/cloud::prefix);
        cp(here/cloud::prefix, start/cloud::prefix);
        if (!written) rmDir(here);

        // The model's own steps over the phase, for the jump
        pointField xs(x), xsPrev(xPrev);
        bool shadow = hybrid->reportJump();
        const auto tj = std::chrono::steady_clock::now();
        for (label k = 0; shadow && k < K; ++k)
        {
            pointField out;
            label bad = -1;
            shadow = modelStep(xsPrev, xs, runTime.value() + k*deltaT, out, bad);
            xsPrev.transfer(xs);
            xs.transfer(out);
        }
        jumpSeconds += std::chrono::duration<double>
        (
            std::chrono::steady_clock::now() - tj
        ).count();

        const double s0 = hybrid->solverSeconds();
        hybrid->solve();
        for (label k = 1; k <= K; ++k)
        {
            ++runTime;
            const fileName from(hybrid->phaseTime(k));
            ++nSolverTimes;
            written = runTime.writeTime();
            // The model goes on from the last two; others only if written
            if (k < K - 1 && !written) continue;
            mkDir(runTime.timePath());
            if (isDir(runTime.timePath()/cloud::prefix))
            {
                rmDir(runTime.timePath()/cloud::prefix);
            }
            cp(from/cloud::prefix, runTime.timePath()/cloud::prefix);
            pointField xNew;
            handover->read(xNew);
            xPrev.transfer(x);
            x.transfer(xNew);
            if (written)
            {
                runTime.writeNow();
            }
            else
            {
                rmDir(runTime.timePath());
            }
        }
        const label steps = solverStepsIn(hybrid->lastLog());
        std::snprintf
        (
            buf, sizeof(buf),
            "Handover %d at t = %g: %s to t = %g in %d steps, %.3f s",
            int(hybrid->nPhases()), t1 - K*deltaT, hybrid->solver().c_str(),
            runTime.value(), int(steps), hybrid->solverSeconds() - s0
        );
        Info<< buf;
        if (hybrid->reportJump())
        {
            if (shadow)
            {
                const auto d = distances(x, xs, r.nPoints());
                std::snprintf
                (
                    buf, sizeof(buf),
                    "; the model alone would lie RMS %.3e m (max %.3e m)"
                    " from it: the jump removed",
                    d.first, d.second
                );
                Info<< buf;
            }
            else
            {
                Info<< "; the model alone went non-finite over the phase";
            }
        }
        Info<< nl;
        sinceHandover = 0;
    };

    while (runTime.run())
    {
        solverPhase();
        if (!runTime.run()) break;
        pointField out;
        label bad = -1;
        const auto ts0 = std::chrono::steady_clock::now();
        const bool ok = modelStep(xPrev, x, runTime.value(), out, bad);
        const double sec = std::chrono::duration<double>
        (
            std::chrono::steady_clock::now() - ts0
        ).count();
        modelSeconds += sec;
        if (!ok)
        {
            if (!written)
            {
                writeCloud(mesh, cloudName, r, x, xPrev, deltaT);
            }
            FatalErrorInFunction
                << "The model predicted a non-finite displacement of node "
                << bad << " at t = " << runTime.value() + deltaT
                << " (model step " << nSteps + 1 << "); the last good state"
                << (nSteps ? " is written at t = " : " is the start time t = ")
                << runTime.timeName()
                << (nSteps ? "" : ", whose files are left as they are")
                << exit(FatalError);
        }
        ++runTime;
        ++nSteps;
        ++sinceHandover;
        xPrev.transfer(x);
        x.transfer(out);
        std::snprintf(buf, sizeof(buf), "model step %.1f ms", 1e3*sec);
        Info<< "Time = " << runTime.timeName() << "  " << buf << nl;
        written = runTime.writeTime();
        if (written)
        {
            writeCloud(mesh, cloudName, r, x, xPrev, deltaT);
            runTime.writeNow();
        }
    }

    const double wall = std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - t0
    ).count();
    const double wallCounted = wall - jumpSeconds;
    std::snprintf
    (
        buf, sizeof(buf),
        "%d model steps in %.3f s (%.2f ms per step, model only %.2f ms);"
        " %.4f s per unit of simulated time",
        int(nSteps), wallCounted,
        1e3*(wallCounted - (hybrid ? hybrid->solverSeconds() : 0))
       /max(nSteps, label(1)),
        1e3*modelSeconds/max(nSteps, label(1)),
        wallCounted/max((nSteps + nSolverTimes)*deltaT, SMALL)
    );
    Info<< nl << buf << nl;
    if (hybrid)
    {
        Info<< hybrid->summary(nSolverTimes, nSteps, jumpSeconds).c_str() << nl;
    }
    Info<< "ExecutionTime = " << runTime.elapsedCpuTime() << " s"
        << "  ClockTime = " << runTime.elapsedClockTime() << " s"
        << nl << nl << "End" << nl << endl;
    return 0;
}


// ************************************************************************* //
