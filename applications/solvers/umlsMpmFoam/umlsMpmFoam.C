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

Usage
    umlsMpmFoam [-case dir]

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "mpmMeshView.H"
#include "mpmSolver.H"
#include "mpmState.H"
#include "mpmCloudIO.H"
#include "dictionaryChecks.H"
#include "clockTime.H"
#include "cloud.H"

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Explicit material point method (UMLS-MPM) for solids on the mesh;"
        " settings in constant/mpmProperties"
    );
    argList::noParallel();

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

    const mpmMeshView view(mesh);
    Info<< "MPM mesh view: " << view.dim() << "D, " << view.nVertices()
        << " vertices, " << view.nCells() << " cells" << nl;

    const mpmGridBoundary boundary
    (
        mesh, view, mpmProperties.subOrEmptyDict("boundary")
    );
    Info<< "MPM grid conditions on " << boundary.size() << " vertices" << nl;

    mpmSolver solver(view, mpmProperties, boundary);

    mpmParticles P;
    if (!mpmCloudIO::read(mesh, cloudName, P))
    {
        FatalErrorInFunction
            << "No particles: " << runTime.timePath()/cloud::prefix/cloudName
            << " holds no MPM cloud. Seed one with mpmSetParticles."
            << exit(FatalError);
    }
    if (P.size() == 0)
    {
        FatalErrorInFunction
            << "No particles: the MPM cloud "
            << runTime.timePath()/cloud::prefix/cloudName
            << " holds no particle. Seed some with mpmSetParticles."
            << exit(FatalError);
    }
    solver.initialise(P);
    Info<< "Particles: " << P.size() << nl << endl;

    // The last time whose cloud is on disk (for messages)
    word lastWritten(runTime.timeName());

    // For function objects (mpmConservation)
    mpmState state(mesh, solver, P);

    clockTime clock;
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
                << "  particles = " << P.size() << nl;
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
    Info<< nl << "Particle-steps per second: "
        << (wall > 0 ? scalar(P.size())*steps/wall : 0) << " ("
        << steps << " steps, " << P.size() << " particles, " << wall
        << " s)" << nl << "End" << nl << endl;

    return 0;
}

// ************************************************************************* //
