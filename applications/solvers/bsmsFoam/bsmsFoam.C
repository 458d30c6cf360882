/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
-------------------------------------------------------------------------------
Application
    bsmsFoam

Group
    mpmFoam solvers

Description
    Advances a case with a trained BSMS-GNN (or MeshGraphNets) model alone,
    no flow solver: from the start time's fields, every model step (the
    model's deltaT, which replaces the controlDict's) predicts the output
    fields, and the written times are ordinary time directories
    (foamToVTK, ParaView).  Input fields that are not outputs keep their
    start values; boundary values follow the fields' boundary conditions
    (with U among the outputs, the face flux phi = flux(U) is kept for
    those that need it, such as inletOutlet, and written).

    The log shows each model step's time and wall-clock cost, and at the
    end the mean cost per model step and per unit of simulated time (to
    compare with the solver the model replaces).  A model of moving bodies
    (graph lagrangian in its model dictionary) advances the case's MPM
    cloud instead (bsmsFoamLagrangian.H).  A non-finite prediction
    writes the last good state and stops with a message (exit status 1);
    if the first step fails, the start time's files are left as they are.

    A state outside the range the model was trained on (an input field
    more than bsmsRangeWarning standard deviations of the training inputs
    beyond the training range that bsmsTrain recorded, see bsmsInputRange)
    gives a warning naming the field, the value, the cell and the range,
    once per field; the end of the log says how far each such field went.

    Parallel runs (decomposePar, mpirun -np N bsmsFoam -parallel,
    reconstructPar) give the serial run's predictions bit for bit: the
    model sees the whole mesh's graph, so each step the ranks' fields are
    gathered on the master (in the undecomposed cell order, by the
    processors' cellProcAddressing), the master advances the model built
    on the undecomposed mesh and scatters the prediction back (see
    bsmsGatheredModel).  The model's cost is the serial run's.

Usage
    bsmsFoam [-case dir] [-model file] [-rangeWarning nStd] [-parallel]

    The model (default constant/bsmsModel.pt, with its model dictionary
    constant/bsmsModelDict beside it, both written by bsmsTrain) can also be
    named in system/controlDict:
    \verbatim
        bsmsModel   "constant/bsmsModel.pt";
        bsmsRangeWarning 2;     // standard deviations; default 2
        bsmsHybrid              // optional: a hybrid rollout
        {
            modelSteps  4;      // N model steps, then
            solverSteps 50;     // M steps of the solver, from its state on
            solver      pimpleFoam;
            deltaT      0.02;   // the solver's step
            reportJump  yes;    // the model's own steps beside each phase
        }
    \endverbatim
    Hybrid rollout (bsmsHybridSolver): every N model steps the state goes
    back to the solver, which runs M of its own steps (a whole number of
    model steps; or solverModelSteps K, K model steps' time) as its own
    process on the case's files, and the model goes on from the solver's
    state; the solver's model times are read back and written like the
    model's.  Without bsmsHybrid the rollout is pure (N = infinity; a
    hybrid whose N exceeds the run's steps is the pure rollout bit for
    bit).  Each handover's log line gives the solver's phase, its cost
    and (reportJump, default yes) the jump it removed: how far the
    model's own steps over the phase would lie from the solver's state,
    RMS per output field.  The log's last lines give the solver phases'
    share of the cost.  Serial only.  For a model of moving bodies the
    handover rebuilds the MPM state from the predicted points
    (lagrangianHandover: F from the deformation of the graph's mesh, U
    from the last two predicted positions, stress from F through the
    material; elastic materials only), and the solver, umlsMpmFoam,
    takes solverModelSteps (it chooses its own step).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "OSspecific.H"
#include "bsmsGatheredModel.H"
#include "bsmsFieldIO.H"
#include "bsmsHybridSolver.H"
#include "dictionaryChecks.H"
#include "bsmsFoamLagrangian.H"
#include "bsmsReuseMemory.H"
#include "IFstream.H"

#include <chrono>
#include <cstdio>

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Advance a case with a trained BSMS-GNN model alone (no solver)"
    );
    argList::addOption
    (
        "model",
        "file",
        "the checkpoint (default: bsmsModel in system/controlDict, else"
        " constant/bsmsModel.pt)"
    );
    argList::addOption
    (
        "rangeWarning",
        "nStd",
        "warn when an input field lies more than nStd standard deviations"
        " of the training inputs beyond the training range (default:"
        " bsmsRangeWarning in system/controlDict, else 2)"
    );

    #include "setRootCase.H"

    // torch's buffers reused step after step, not faulted in again
    bsmsReuseMemory();

    #include "createTime.H"
    #include "createMesh.H"

    const dictionary& controlDict = runTime.controlDict();
    fileName modelFile("constant/bsmsModel.pt");
    controlDict.readIfPresent("bsmsModel", modelFile);
    args.readIfPresent("model", modelFile);
    scalar rangeWarning = dictionaryChecks::getInRange
    (
        controlDict, "bsmsRangeWarning", 2, 0, 1e30
    );
    if (args.readIfPresent("rangeWarning", rangeWarning))
    {
        if (!(rangeWarning > 0 && rangeWarning <= 1e30))
        {
            FatalErrorInFunction
                << "-rangeWarning " << rangeWarning << ": a number of"
                << " standard deviations > 0 is needed" << exit(FatalError);
        }
    }
    modelFile.expand();
    if (!modelFile.isAbsolute()) modelFile = runTime.globalPath()/modelFile;

    // A model of moving bodies (graph lagrangian): bsmsFoamLagrangian.H
    {
        const fileName specFile(bsmsSpecFile(modelFile));
        if (isFile(specFile))
        {
            IFstream is(specFile);
            dictionary spec(is);
            spec.name() = specFile;
            if (spec.lookupOrDefault<word>("graph", "cells") == "lagrangian")
            {
                return bsmsFoamLagrangian(runTime, mesh, modelFile, spec);
            }
        }
    }

    std::unique_ptr<bsmsGatheredModel> model
    (
        new bsmsGatheredModel(mesh, modelFile, controlDict, "bsmsModel")
    );
    const bsmsModelSpec& spec = model->spec();
    Info<< "Model " << modelFile << ": " << spec.model << ", levels (nodes "
        << model->levelSizes().c_str() << "), inputs " << spec.inputFields
        << ", outputs " << spec.outputFields << ", deltaT " << spec.deltaT
        << nl << endl;

    // The fields, read from the start time and written with the case
    PtrList<volScalarField> scalars;
    PtrList<volVectorField> vectors;
    forAll(spec.inputFields, i)
    {
        const word& f = spec.inputFields[i];
        IOobject io
        (
            f, runTime.timeName(), mesh,
            IOobject::MUST_READ,
            spec.outputFields.found(f)
          ? IOobject::AUTO_WRITE : IOobject::NO_WRITE
        );
        if (!io.typeHeaderOk<volScalarField>(false))
        {
            FatalIOErrorInFunction(controlDict)
                << "The model " << modelFile << " (entry 'bsmsModel') reads"
                << " the field '" << f << "', which the case lacks at time "
                << runTime.timeName() << " (" << io.objectPath() << ")"
                << exit(FatalIOError);
        }
        const word expected
        (
            spec.inputComponents[i] == 1 ? "volScalarField" : "volVectorField"
        );
        if (io.headerClassName() != expected)
        {
            FatalIOErrorInFunction(controlDict)
                << "The model " << modelFile << " (entry 'bsmsModel') reads"
                << " the field " << f << " with " << spec.inputComponents[i]
                << " component(s) (" << expected << "), but the case's "
                << io.objectPath() << " is a " << io.headerClassName()
                << ": the model does not match the case's fields"
                << exit(FatalIOError);
        }
        if (spec.inputComponents[i] == 1)
        {
            scalars.append(new volScalarField(io, mesh));
        }
        else
        {
            vectors.append(new volVectorField(io, mesh));
        }
    }

    // The face flux of U for boundary conditions that need one
    // (inletOutlet, ...): phi = flux of the predicted U, written with it
    autoPtr<surfaceScalarField> phi;
    if (spec.outputFields.found("U") && mesh.foundObject<volVectorField>("U"))
    {
        const volVectorField& U = mesh.lookupObject<volVectorField>("U");
        phi.reset
        (
            new surfaceScalarField
            (
                IOobject
                (
                    "phi", runTime.timeName(), mesh,
                    IOobject::NO_READ, IOobject::AUTO_WRITE
                ),
                fvc::flux(U)
            )
        );
    }

    // This rank's state; the whole mesh's (global) on the model's rank
    std::vector<double> state
    (
        registryState(mesh, spec.inputFields, spec.inputComponents,
            controlDict, "bsmsModel")
    );
    std::vector<double> global(model->gather(state));

    // The training range of the inputs: the start state, then each step's
    // (checked on the model's rank, on the whole mesh's state)
    std::unique_ptr<bsmsInputRange> rangePtr
    (
        model->holdsModel()
      ? new bsmsInputRange(model->model().inputRange(rangeWarning))
      : nullptr
    );
    auto checkRange = [&](const scalar t)
    {
        if (!rangePtr) return;
        for (const string& m : rangePtr->check(global, t))
        {
            WarningIn("bsmsFoam") << "Model " << modelFile.name() << ": "
                << m.c_str() << endl;
        }
    };
    auto rangeSummary = [&]()
    {
        if (!rangePtr) return;
        for (const string& m : rangePtr->summary())
        {
            Info<< "Model " << modelFile.name() << ": " << m.c_str() << nl;
        }
    };
    if (rangePtr && !rangePtr->active())
    {
        WarningInFunction << "Model " << modelFile << " holds no input"
            << " statistics (never trained?): its inputs are not checked"
            << " against a training range" << endl;
    }
    checkRange(runTime.value());

    // Hybrid rollout: every N model steps the solver's M steps
    std::unique_ptr<bsmsHybridSolver> hybrid
    (
        bsmsHybridSolver::active(controlDict)
      ? new bsmsHybridSolver(mesh, controlDict, spec.deltaT)
      : nullptr
    );

    runTime.setDeltaT(spec.deltaT);
    const auto t0 = std::chrono::steady_clock::now();
    label nModelSteps = 0;
    label nSolverTimes = 0;
    label sinceHandover = 0;
    double modelSeconds = 0;
    double jumpSeconds = 0;
    std::size_t nState = 0;
    for (const label c : spec.inputComponents) nState += c;
    char buf[300];
    // The solver's phase from the current time, if one is due and fits
    // before the end time: its model times read back, written as ours
    auto solverPhase = [&]()
    {
        if (!hybrid || sinceHandover < hybrid->modelSteps()) return;
        const scalar tEnd =
            runTime.value() + hybrid->phaseModelSteps()*spec.deltaT;
        if (tEnd > runTime.endTime().value() + 0.5*spec.deltaT) return;
        // The model's own steps over the phase, for the jump
        std::vector<double> shadow(global);
        bool shadowOk = hybrid->reportJump();
        const auto tj = std::chrono::steady_clock::now();
        for (label k = 0; shadowOk && k < hybrid->phaseModelSteps(); ++k)
        {
            shadowOk = model->advance(shadow);
        }
        jumpSeconds += std::chrono::duration<double>
        (
            std::chrono::steady_clock::now() - tj
        ).count();
        const scalar tStart = runTime.value();
        const double s0 = hybrid->solverSeconds();

        hybrid->runPhase(spec.outputFields);
        for (label k = 1; k <= hybrid->phaseModelSteps(); ++k)
        {
            ++runTime;
            hybrid->readBack(spec.inputFields, k);
            if (phi.valid())
            {
                phi() = fvc::flux(mesh.lookupObject<volVectorField>("U"));
            }
            state = registryState(mesh, spec.inputFields,
                spec.inputComponents, controlDict, "bsmsModel");
            global = model->gather(state);
            checkRange(runTime.value());
            ++nSolverTimes;
            Info<< "Time = " << runTime.timeName() << "  solver phase "
                << hybrid->nPhases() << nl;
            runTime.write();
        }
        std::snprintf
        (
            buf, sizeof(buf),
            "Handover %d at t = %g: %s to t = %g, %.3f s",
            int(hybrid->nPhases()), tStart, hybrid->solver().c_str(),
            runTime.value(), hybrid->solverSeconds() - s0
        );
        Info<< buf;
        if (hybrid->reportJump() && !shadowOk)
        {
            Info<< "; the model alone went non-finite over the phase";
        }
        else if (hybrid->reportJump())
        {
            // Per output field: RMS over cells and components of the
            // solver's state less the model's own
            Info<< "; the model alone would lie";
            label o = 0;
            forAll(spec.inputFields, i)
            {
                const label nc = spec.inputComponents[i];
                if (spec.outputFields.found(spec.inputFields[i]))
                {
                    double sum = 0;
                    for (std::size_t c = 0; c < global.size(); c += nState)
                    {
                        for (label d = 0; d < nc; ++d)
                        {
                            sum += sqr(global[c + o + d] - shadow[c + o + d]);
                        }
                    }
                    std::snprintf
                    (
                        buf, sizeof(buf), " %s RMS %.3e",
                        spec.inputFields[i].c_str(),
                        std::sqrt(sum/max(double(global.size()/nState*nc), 1.0))
                    );
                    Info<< buf;
                }
                o += nc;
            }
            Info<< " from it: the jump removed";
        }
        Info<< nl;
        sinceHandover = 0;
    };
    while (runTime.run())
    {
        solverPhase();
        if (!runTime.run()) break;
        ++runTime;
        ++sinceHandover;
        const auto ts = std::chrono::steady_clock::now();
        std::vector<double> next(global);
        const bool finite = model->advance(next);
        const double sec = std::chrono::duration<double>
        (
            std::chrono::steady_clock::now() - ts
        ).count();
        modelSeconds += sec;
        ++nModelSteps;

        if (!finite)
        {
            const scalar tBad = runTime.value();
            runTime.setTime(runTime.value() - spec.deltaT, runTime.timeIndex());
            rangeSummary();
            if (nModelSteps > 1)
            {
                setFields(mesh, state, spec.inputFields, spec.inputComponents,
                    spec.outputFields);
                runTime.writeNow();
            }
            FatalErrorInFunction
                << "The model predicted non-finite values at t = " << tBad
                << " (model step " << nModelSteps << "); the last good state"
                << (nModelSteps > 1 ? " is written at t = " : " is the start"
                    " time t = ")
                << runTime.timeName()
                << (nModelSteps > 1 ? "" : ", whose files are left as they are")
                << exit(FatalError);
        }
        global.swap(next);
        checkRange(runTime.value());
        state = model->scatter(global);
        setFields(mesh, state, spec.inputFields, spec.inputComponents,
            spec.outputFields);
        if (phi.valid())
        {
            phi() = fvc::flux(mesh.lookupObject<volVectorField>("U"));
        }

        std::snprintf(buf, sizeof(buf), "model step %.1f ms", 1e3*sec);
        Info<< "Time = " << runTime.timeName() << "  " << buf << nl;
        runTime.write();
    }

    const double wall = std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - t0
    ).count() - jumpSeconds;
    const scalar simulated = (nModelSteps + nSolverTimes)*spec.deltaT;
    std::snprintf
    (
        buf, sizeof(buf),
        "%d model steps in %.3f s (%.2f ms per step, model only %.2f ms);"
        " %.4f s per unit of simulated time",
        int(nModelSteps), wall,
        1e3*(wall - (hybrid ? hybrid->solverSeconds() : 0))
       /max(nModelSteps, label(1)),
        1e3*modelSeconds/max(nModelSteps, label(1)),
        wall/max(simulated, SMALL)
    );
    Info<< nl << buf << nl;
    if (hybrid)
    {
        Info<< hybrid->summary(nSolverTimes, nModelSteps, jumpSeconds).c_str() << nl;
    }
    rangeSummary();
    Info<< "ExecutionTime = " << runTime.elapsedCpuTime() << " s"
        << "  ClockTime = " << runTime.elapsedClockTime() << " s"
        << nl << nl << "End" << nl << endl;
    return 0;
}


// ************************************************************************* //
