/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
-------------------------------------------------------------------------------
Application
    umlsMpmFoam

Group
    mpmFoam solvers

Description
    Explicit material point method for solids on the case's mesh, with the
    unstructured moving least squares kernel (UMLS-MPM, dissertation ch. 2)
    or the linear / mlsRing kernels, PIC, FLIP or APIC transfers, and
    elastic materials.  Settings: constant/mpmProperties (see mpmSolver.H).
    Particles: the lagrangian cloud <startTime>/lagrangian/<cloudName>,
    made by mpmSetParticles; written at every write time, so the run
    restarts from any of them.

    The log shows each step's number, time, dt, active vertices and
    particles.  A step that would go non-finite or invert a particle is
    refused: the last good state is written and the run stops with a
    message saying where and why.  So does a time step that would need
    more than maxSteps steps to reach endTime (a wave speed or a particle
    velocity out of scale).  A run whose mechanical energy grows beyond
    what the system holds (an unstable step) stops with a message naming
    the last good time written.

    -parallel (decomposePar, then mpirun -np N umlsMpmFoam -parallel):
    each rank holds the particles in its cells and writes them to
    processor<N>/<time>/lagrangian/<cloudName>, so reconstructPar merges
    them and a parallel run restarts from any written time.  The rank's
    grid is its cells plus a halo of the other ranks' cells around its
    processor patches (positions fixed at the start), so the linear,
    mlsRing and umls kernels are the serial ones; the vertex sums of mass,
    momentum and force are completed over the ranks sharing a vertex (in
    rank order, so every copy holds the same value), particles that move
    into another rank's cell move to that rank after each step, dt is the
    smallest over the ranks and a refused step on one rank stops all
    (src/mpm/parallel/mpmParallel.H).  The particles' order differs from
    the serial run's: the cloud's field id (seeding order) matches them.
    Decompositions it cannot take (1D meshes, processorCyclic patches, a
    processor mesh without pointProcAddressing), a processor directory
    without the cloud and a case decomposed for another number of ranks
    stop with a FatalError.  With particle-weighted decomposition
    (mpmCellWeights) the ranks get equal shares of the particles.  The
    log's last lines give the time spent in the exchanges.

Usage
    umlsMpmFoam [-case dir] [-parallel]

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "mpmMeshView.H"
#include "mpmSolver.H"
#include "barrierContact.H"
#include "mpmState.H"
#include "mpmCloudIO.H"
#include "dictionaryChecks.H"
#include "clockTime.H"
#include "cloud.H"
#include "mpmParallel.H"
#include "globalIndex.H"

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Explicit material point method (UMLS-MPM) for solids on the mesh;"
        " settings in constant/mpmProperties"
    );

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    IOdictionary mpmProperties
    (
        IOobject
        (
            "mpmProperties",
            runTime.constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    );
    const word cloudName
    (
        mpmProperties.getOrDefault<word>("cloudName", "mpmCloud")
    );
    const label logInterval =
        dictionaryChecks::getLabelAtLeast(mpmProperties, "logInterval", 1, 1);

    // -parallel: the rank's cells and the halo of its neighbours' cells
    autoPtr<mpmParallel> par;
    autoPtr<mpmMeshView> serialView;
    if (Pstream::parRun())
    {
        par.reset(new mpmParallel(mesh));
    }
    else
    {
        serialView.reset(new mpmMeshView(mesh));
    }
    const mpmMeshView& view = par.valid() ? par->view() : serialView();
    Info<< "MPM mesh view: " << view.dim() << "D, "
        << returnReduce(par.valid() ? par->nMeshVertices() : view.nVertices(), sumOp<label>())
        << " vertices" << (par.valid() ? " (counting shared ones per rank)" : "")
        << ", " << returnReduce(mesh.nCells(), sumOp<label>()) << " cells"
        << nl;

    const mpmGridBoundary boundary
    (
        mesh, view, mpmProperties.subOrEmptyDict("boundary"), par.get()
    );
    Info<< "MPM grid conditions on " << boundary.size() << " vertices"
        << (par.valid() ? " (of the master rank)" : "") << nl;

    mpmSolver solver(view, mpmProperties, boundary);
    if (par.valid()) solver.setParallel(par());

    // Barrier frictional contact with patches (optional)
    autoPtr<barrierContact> contact;
    if (mpmProperties.found("contact", keyType::LITERAL))
    {
        if (!mpmProperties.isDict("contact"))
        {
            dictionaryChecks::badEntry
            (
                mpmProperties, "contact",
                dictionaryChecks::entryText(mpmProperties, "contact"),
                "a sub-dictionary contact { patches (...); dHat ...;"
                " friction ...; }"
            );
        }
        contact.reset
        (
            new barrierContact
            (
                mesh, view, mpmProperties.subDict("contact"), par.get()
            )
        );
        solver.setContact(contact());
    }

    mpmParticles P;
    bool idsRead = true;
    const bool found = mpmCloudIO::read(mesh, cloudName, P, &idsRead);
    if (Pstream::parRun())
    {
        // Every rank writes its cloud (empty or not) at each write time;
        // decomposePar writes none for a rank without particles
        if (!returnReduce(found, orOp<bool>()))
        {
            FatalErrorInFunction
                << "No particles: no processor directory holds an MPM cloud"
                << " at " << runTime.timeName() << " (e.g. "
                << runTime.timePath()/cloud::prefix/cloudName << "). Seed"
                << " one with mpmSetParticles before decomposePar"
                << exit(FatalError);
        }
        // A processor directory without its cloud: the ranks hold fewer
        // particles than the undecomposed cloud of the same time (where
        // the case has one: decomposePar's input)
        const label nRanks = returnReduce(P.size(), sumOp<label>());
        label nRoot = -1;
        if (Pstream::master())
        {
            nRoot = mpmCloudIO::countParticles
            (
                runTime.globalPath()/runTime.timeName()/cloud::prefix
               /cloudName
            );
        }
        Pstream::scatter(nRoot);
        if (nRoot >= 0 && nRoot != nRanks)
        {
            FatalErrorInFunction
                << "The processor directories' clouds at "
                << runTime.timeName() << " hold " << nRanks << " particles;"
                << " the undecomposed cloud "
                << runTime.globalPath()/runTime.timeName()/cloud::prefix
                  /cloudName << " holds " << nRoot << ". A processor"
                << " directory lacks its cloud (or holds another"
                << " decomposition's): run decomposePar -force again"
                << exit(FatalError);
        }
        // Without the undecomposed cloud (a time this solver wrote in
        // parallel: every rank writes its cloud, empty or not) every rank
        // must hold one
        if (nRoot < 0 && !returnReduce(found, andOp<bool>()))
        {
            if (!found)
            {
                Pout<< "No MPM cloud in " << runTime.timePath()/cloud::prefix
                    /cloudName << endl;
            }
            FatalErrorInFunction
                << "A processor directory lacks its MPM cloud at "
                << runTime.timeName() << " (the ranks without it are"
                << " listed above), and the case has no undecomposed cloud"
                << " there to tell an empty subdomain: the parallel run"
                << " writes every rank's cloud. Restart from another time,"
                << " or decompose again" << exit(FatalError);
        }
        if (!found && P.size() == 0)
        {
            Pout<< "No MPM particles in this subdomain at the start" << endl;
        }

        // A cloud without ids: number the particles across the ranks
        if (!returnReduce(idsRead, andOp<bool>()))
        {
            const globalIndex gi(P.size());
            forAll(P.id, p) P.id[p] = gi.toGlobal(p);
        }
    }
    else if (!found)
    {
        FatalErrorInFunction
            << "No particles: " << runTime.timePath()/cloud::prefix/cloudName
            << " holds no MPM cloud. Seed one with mpmSetParticles."
            << exit(FatalError);
    }
    if (returnReduce(P.size(), sumOp<label>()) == 0)
    {
        FatalErrorInFunction
            << "No particles: the MPM cloud "
            << runTime.timePath()/cloud::prefix/cloudName
            << " holds no particle. Seed some with mpmSetParticles."
            << exit(FatalError);
    }
    solver.initialise(P);
    solver.setTime(runTime.value());
    for (const mpmActuator& a : solver.actuators())
    {
        Info<< "MPM actuator " << a.name() << ": box at t = "
            << runTime.timeName() << ' ' << a.box(runTime.value())
            << ", fastest speed on its path " << a.maxSpeed() << " m/s"
            << nl;
    }
    Info<< "Particles: " << returnReduce(P.size(), sumOp<label>()) << nl
        << endl;

    // The last time whose cloud is on disk (for messages)
    word lastWritten(runTime.timeName());

    // For function objects (mpmConservation)
    mpmState state(mesh, solver, P);

    clockTime clock;
    const scalar cpu0 = runTime.elapsedCpuTime();
    label steps = 0;
    Info<< "Starting time loop" << nl << endl;

    while (runTime.run())
    {
        scalar dt = solver.deltaT(P);

        // A step too small to reach endTime in maxSteps steps: the state
        // is still good, so it is written before stopping
        const scalar remaining = runTime.endTime().value() - runTime.value();
        if (!(dt > 0) || remaining > solver.maxSteps()*dt)
        {
            mpmCloudIO::write(mesh, cloudName, P);
            FatalIOErrorInFunction(mpmProperties)
                << "The time step " << dt << " s at t = "
                << runTime.timeName() << " would need more steps to reach"
                << " endTime " << runTime.endTime().value() << " than"
                << " maxSteps " << solver.maxSteps() << " (entry 'maxSteps'"
                << " in " << mpmProperties.name() << "): "
                << solver.deltaTReason().c_str() << nl
                << "    Check the materials' E and rho and the particle"
                << " velocities. The state at t = " << runTime.timeName()
                << " is written" << exit(FatalIOError);
        }
        // Never past endTime (a vanishing wave speed gives a huge dt)
        if (remaining > 0) dt = min(dt, remaining);
        runTime.setDeltaT(dt);
        ++runTime;
        const scalar dtUsed = runTime.deltaTValue();

        if (!solver.step(P, dtUsed))
        {
            // The particles still hold the previous step's state
            runTime.setTime(runTime.value() - dtUsed, runTime.timeIndex() - 1);
            mpmCloudIO::write(mesh, cloudName, P);
            FatalErrorInFunction
                << "Step at t = " << runTime.value() + dtUsed << " refused: "
                << solver.failure().c_str() << nl
                << "    The last good state is written at t = "
                << runTime.timeName() << exit(FatalError);
        }
        ++steps;
        solver.logParticleEvents(runTime.timeName());
        if (!solver.energyBounded(P))
        {
            FatalErrorInFunction
                << "Unstable at t = " << runTime.timeName() << ": "
                << solver.failure().c_str() << nl
                << "    The last good state written is at t = "
                << lastWritten << exit(FatalError);
        }

        if (runTime.timeIndex() % logInterval == 0 || runTime.writeTime())
        {
            Info<< "Step " << runTime.timeIndex() << "  t = "
                << runTime.timeName() << "  dt = " << dtUsed
                << "  active vertices = " << solver.nActive()
                << "  particles = "
                << (par.valid() ? returnReduce(P.size(), sumOp<label>()) : P.size());
            if (contact.valid())
            {
                Info<< "  within dHat = "
                    << returnReduce(contact->nWithin(), sumOp<label>())
                    << "  min distance = "
                    << returnReduce(contact->minDistance(), minOp<scalar>());
                if (contact->friction() > 0)
                {
                    Info<< "  friction work = "
                        << returnReduce(contact->frictionWork(), sumOp<scalar>());
                }
            }
            for (const mpmActuator& a : solver.actuators())
            {
                Info<< "  actuator " << a.name() << ": displacement "
                    << a.displacement(runTime.value()) << " force "
                    << returnReduce(a.force(), sumOp<vector>());
            }
            if (solver.actuators().size())
            {
                Info<< "  actuator work " << solver.actuatorWork();
            }
            Info<< nl;
        }

        if (runTime.writeTime())
        {
            mpmCloudIO::write(mesh, cloudName, P);
            lastWritten = runTime.timeName();
            Info<< "    written, ExecutionTime = "
                << runTime.elapsedCpuTime() << " s" << nl;
        }
        runTime.write();
    }

    const scalar wall = clock.elapsedTime();
    const label nTotal = returnReduce(P.size(), sumOp<label>());
    Info<< nl << "Particle-steps per second: "
        << (wall > 0 ? scalar(nTotal)*steps/wall : 0) << " ("
        << steps << " steps, " << nTotal << " particles, " << wall
        << " s)" << nl;
    solver.kernel().report();
    const scalar cpu = runTime.elapsedCpuTime() - cpu0;
    Info<< "Time loop CPU: " << returnReduce(cpu, maxOp<scalar>()) << " s";
    if (par.valid())
    {
        Info<< " on the busiest rank, "
            << returnReduce(cpu, sumOp<scalar>())/Pstream::nProcs()
            << " s on average";
    }
    Info<< nl;
    solver.summaryParticleEvents();
    if (par.valid())
    {
        const scalar comm = mpmParallel::commTime();
        Info<< "Exchanges (grid sums, migration, reductions): "
            << returnReduce(comm, maxOp<scalar>()) << " s on the busiest"
            << " rank, " << returnReduce(comm, sumOp<scalar>())/Pstream::nProcs()
            << " s on average, of " << wall << " s; their CPU time "
            << returnReduce(mpmParallel::commCpuTime(), maxOp<scalar>())
            << " s on the busiest rank" << nl
            << "Particles moved between ranks: "
            << returnReduce(par->nMigratedTotal(), sumOp<label>())
            << " in " << steps << " steps (the busiest rank sent "
            << returnReduce(par->nMigratedTotal(), maxOp<label>()) << ")"
            << nl;
    }
    if (contact.valid())
    {
        const label calls = max(contact->nForceCalls(), label(1));
        Info<< "Contact: smallest particle-patch distance "
            << returnReduce(contact->minDistance(), minOp<scalar>())
            << " m (dHat " << contact->dHat() << " m); force evaluation "
            << returnReduce(contact->forceTime(), maxOp<scalar>())/calls
            << " s per step on the busiest rank; at the last step "
            << returnReduce(contact->nWithin(), sumOp<label>())
            << " particles within dHat, "
            << returnReduce(contact->nExamined(), sumOp<label>())
            << " examined (in cells near the patches); per step on average "
            << returnReduce(contact->nWithinSum(), sumOp<scalar>())/calls
            << " within dHat, "
            << returnReduce(contact->nExaminedSum(), sumOp<scalar>())/calls
            << " examined" << nl;
        if (contact->friction() > 0)
        {
            Info<< "Contact: friction work "
                << returnReduce(contact->frictionWork(), sumOp<scalar>())
                << " J in this run" << nl;
        }
    }
    Info<< "End" << nl << endl;

    return 0;
}

// ************************************************************************* //
