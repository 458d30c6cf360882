/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
-------------------------------------------------------------------------------
Application
    shockMpmFoam

Group
    mpmFoam solvers

Description
    Compressible inviscid flow with shocks on uniform Cartesian (blockMesh)
    meshes: finite-difference WENO with local Lax-Friedrichs flux splitting,
    explicit or semi-implicit (time-split, implicit pressure) time stepping
    (dissertation ch. 3, 3.2.1-3.2.5 and 3.2.9).  With no particles in the
    case it is a pure gas solver.

    With constant/mpmProperties and an MPM cloud (mpmSetParticles) the gas
    is coupled two-way to MPM solids on its lattice (CSMPM, 3.2.2-3.2.8,
    csmpmStepper in src/coupling): one pressure system for gas and solid,
    the semiImplicit stepper required.  The cloud (with J^g), alphaSolid
    and Rsolid are written at the write times.  The log gives per step the
    CG iterations and residual, the solid and interface cells and the gas
    + solid totals of mass, momentum and energy (the solid's kinetic and
    elastic energy), and the parts at the write times.  Without
    constant/mpmProperties nothing of the coupling is built or run.

    Reads system/shockMpmDict, constant/thermophysicalProperties and the
    initial fields p, U and rho (or T), e.g. from setFields.  Writes rho, U,
    p, T, Mach and schlieren; restarts from any written time.

    In parallel (decomposePar with method simple or hierarchical, then
    mpirun -np N shockMpmFoam -parallel) each rank holds a box of the
    lattice; WENO ghost cells come from the neighbour ranks at each flux
    evaluation and the time step is the minimum over the ranks, so the
    explicit stepper gives the serial fields bit for bit; the semiImplicit
    stepper's pressure system couples across processor faces and its CG
    sums over the ranks, so it agrees with serial to round-off.  With
    solids (2D, 3D) the coupled step runs across the ranks too: the MPM
    grid is the rank's cells and a halo (mpmParallel), the solid's
    deposits on the lattice are summed over the ranks, the coupled
    system's solid part over the ranks holding a node; particles move to
    the rank of their new cell, every rank writes its cloud (with J^g), so
    reconstructPar merges it and a parallel run restarts from any written
    time.  The results agree with serial to round-off
    (tests/cases/csmpmParallel).  A 1D coupled case and a processor
    directory without its cloud stop with a FatalError.

Usage
    shockMpmFoam [-case dir] [-parallel]

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "gasDynamics.H"
#include "csmpmStepper.H"
#include "IFstream.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "WENO-LLF compressible flow (explicit or semi-implicit) on"
        " Cartesian blockMesh meshes"
    );

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    // Parallel: the lattice lines must cross processor boundaries whole,
    // which box decompositions guarantee
    if (Pstream::parRun())
    {
        const fileName dictPath
        (
            runTime.globalPath()/runTime.system()/"decomposeParDict"
        );
        IFstream is(dictPath);
        if (!is.good())
        {
            FatalErrorInFunction
                << "Cannot read " << dictPath << " to check the"
                << " decomposition method (simple or hierarchical needed)"
                << exit(FatalError);
        }
        const dictionary decompDict(is);
        const word method(decompDict.get<word>("method"));
        if (method != "simple" && method != "hierarchical")
        {
            FatalIOErrorInFunction(decompDict)
                << "system/decomposeParDict: method " << method
                << " is not a decomposition into boxes." << nl
                << "    allowed for shockMpmFoam -parallel: simple,"
                << " hierarchical" << exit(FatalIOError);
        }
    }

    gasDynamics gas(mesh);

    // Solids: the coupled stepper replaces the gas's (which it keeps for
    // the gas's time step); nothing of it exists in a gas-only case
    csmpmStepper* coupled = nullptr;
    if (csmpmStepper::caseHasSolid(mesh))
    {
        autoPtr<gasStepper> gasOnly
        (
            gasStepper::New(gas.dict().subDict("gas"), gas.op())
        );
        coupled = new csmpmStepper
        (
            mesh, gas.dict(), gas.op(), std::move(gasOnly), gas.state()
        );
        gas.setStepper(autoPtr<gasStepper>(coupled));
        // (the gas + solid totals below include what crossed the patches)
        gas.logTotals(false);
        if (coupled->freshStart())
        {
            // The gas in cells the solid partly covers fills the open
            // volume only (a restart's fields hold it so already)
            gas.scaleState(coupled->openFractions());
        }
        // rhoU and rhoE written too, read back at a restart: it continues
        // bit for bit
        gas.exactRestart(!coupled->freshStart());
    }

    // The controlDict's deltaT only matters to Time::run(), which would stop
    // before the first step if it exceeded the end time: use the stable one
    runTime.setDeltaT
    (
        min(gas.stableDeltaT(), runTime.endTime().value() - runTime.value()),
        false
    );

    Info<< "Starting time loop" << nl << endl;

    while (runTime.run())
    {
        if (coupled)
        {
            // The solid's step too small to reach endTime within maxSteps
            // (constant/mpmProperties): the state is good, write and stop
            const scalar dtSolid = coupled->solver().deltaT
            (
                coupled->particles()
            );
            const scalar remaining =
                runTime.endTime().value() - runTime.value();
            if (!(dtSolid > 0) || remaining > coupled->solver().maxSteps()*dtSolid)
            {
                gas.toFields();
                gas.updateDerived();
                runTime.writeNow();
                coupled->write();
                FatalErrorInFunction
                    << "The solid's time step " << dtSolid << " s at t = "
                    << runTime.timeName() << " would need more steps to"
                    << " reach endTime than maxSteps "
                    << coupled->solver().maxSteps() << " (constant/"
                    << "mpmProperties): "
                    << coupled->solver().deltaTReason().c_str() << nl
                    << "    A stiffer or lighter solid needs smaller steps;"
                    << " raise maxSteps or soften the material. The state"
                    << " at t = " << runTime.timeName() << " is written"
                    << exit(FatalError);
            }
        }
        gas.step(runTime);
        if (coupled)
        {
            coupled->solver().logParticleEvents(runTime.timeName());
            // Every step: gas + solid totals (the solid's energy kinetic
            // plus elastic, psi V0); at write times the parts as well
            scalar m, ke;
            vector mom;
            coupled->solidTotals(m, mom, ke);
            const scalar se = coupled->solidStrainEnergy();
            scalar gm, ge;
            vector gmom;
            gas.totals(gm, gmom, ge);
            const scalar sc = coupled->lattice().scale();
            // What left through outlets (mpmGridBoundary) and the
            // momentum the solid's walls took count with the solid, what
            // crossed the gas's patches (its walls' momentum too) with
            // the gas, so that the budget closes
            const mpmSolver::totals out = coupled->solver().departed();
            const vector wallMom = coupled->solver().wallMomentum();
            scalar gmOut, geOut;
            vector gmomOut;
            gas.crossed(gmOut, gmomOut, geOut);
            Info<< "    gas + solid (step): mass "
                << gm + gmOut + sc*(m + out.mass)
                << ", momentum "
                << gmom + gmomOut + sc*(mom + out.momentum + wallMom)
                << ", energy "
                << ge + geOut + sc*(ke + se + out.kinetic + out.strain)
                << nl;
            if (runTime.writeTime())
            {
                coupled->write();
                Info<< "    solid totals: mass " << sc*m << ", momentum "
                    << sc*mom << ", elastic energy " << sc*se
                    << ", kinetic energy " << sc*ke << nl
                    << "    gas + solid: mass " << gm + sc*m << ", momentum "
                    << gmom + sc*mom << nl;
            }
        }
        runTime.write();
    }

    gas.summary();
    if (coupled)
    {
        coupled->summary();
        coupled->solver().summaryParticleEvents();
    }
    Info<< "ExecutionTime = " << runTime.elapsedCpuTime() << " s"
        << "  ClockTime = " << runTime.elapsedClockTime() << " s"
        << nl << nl << "End" << nl << endl;

    return 0;
}


// ************************************************************************* //
