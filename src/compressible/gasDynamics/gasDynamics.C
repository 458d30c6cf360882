/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "gasDynamics.H"
#include "dictionaryChecks.H"
#include "fvc.H"
#include "gasLimits.H"
#include "OStringStream.H"
#include "processorGhosts.H"
#include "processorPolyPatch.H"

using namespace Foam::dictionaryChecks;

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::gasDynamics::timeToNextWrite() const
{
    const Time& rt = mesh_.time();
    const dictionary& cd = rt.controlDict();
    const word wc(cd.getOrDefault<word>("writeControl", "timeStep"));
    if (wc != "adjustable" && wc != "adjustableRunTime")
    {
        return GREAT;
    }
    const scalar wi = cd.get<scalar>("writeInterval");
    const scalar t0 = rt.startTime().value();
    const scalar rel = (rt.value() - t0)/wi;
    const scalar next = (std::floor(rel + 1e-9) + 1)*wi + t0;
    return next - rt.value();
}


Foam::scalar Foam::gasDynamics::minDeltaT() const
{
    const Time& rt = mesh_.time();
    return gasLimits::minDeltaTFraction
       *(rt.endTime().value() - rt.startTime().value());
}


Foam::string Foam::gasDynamics::fastestCell() const
{
    const scalar g = gas_.gamma();
    scalar best = -1;
    label bi = -1;
    for (const label i : view_.latticeOf())
    {
        const double rho = U_.q[0][i];
        const double p = gas_.pressure
        (
            rho, U_.q[1][i], U_.q[2][i], U_.q[3][i], U_.q[4][i]
        );
        const double c = std::sqrt(std::abs(g*p/rho));
        double r = 0;
        for (label d = 0; d < 3; ++d)
        {
            if (view_.active(d))
            {
                r += (std::abs(U_.q[1 + d][i]/rho) + c)/view_.dx(d);
            }
        }
        if (r > best)
        {
            best = r;
            bi = i;
        }
    }
    if (bi < 0) return "none";
    const label celli = view_.cellAt()[bi];
    const double rho = U_.q[0][bi];
    const vector u(U_.q[1][bi]/rho, U_.q[2][bi]/rho, U_.q[3][bi]/rho);
    const double p = gas_.pressure
    (
        rho, U_.q[1][bi], U_.q[2][bi], U_.q[3][bi], U_.q[4][bi]
    );
    OStringStream os;
    os  << "cell " << celli << " at " << mesh_.cellCentres()[celli]
        << ": rho " << rho << ", U " << u << ", p " << p
        << ", sound speed " << std::sqrt(std::abs(g*p/rho))
        << ", cell size " << vector(view_.dx(0), view_.dx(1), view_.dx(2));
    return os.str();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::gasDynamics::gasDynamics(const fvMesh& mesh)
:
    mesh_(mesh),
    dict_
    (
        IOobject
        (
            "shockMpmDict",
            mesh.time().system(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    gas_(mesh.time()),
    view_(mesh),
    CFL_(0.5),
    maxDeltaT_(GREAT),
    maxRetries_(5),
    schlierenScale_(15),
    p_(readIO(mesh, "p"), mesh),
    Uf_(readIO(mesh, "U"), mesh),
    rho_(readDensity()),
    rhoU_
    (
        newIO(mesh, "rhoU", false),
        mesh,
        dimensionedVector("zero", dimDensity*dimVelocity, Zero)
    ),
    rhoE_
    (
        newIO(mesh, "rhoE", false),
        mesh,
        dimensionedScalar("zero", dimPressure, 0.0)
    ),
    T_
    (
        newIO(mesh, "T", true),
        mesh,
        dimensionedScalar("zero", dimTemperature, 0.0)
    ),
    Mach_
    (
        newIO(mesh, "Mach", true),
        mesh,
        dimensionedScalar("zero", dimless, 0.0)
    ),
    schlieren_
    (
        newIO(mesh, "schlieren", true),
        mesh,
        dimensionedScalar("one", dimless, 1.0)
    ),
    phi_
    (
        IOobject
        (
            "phi",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        mesh,
        dimensionedScalar("zero", dimMass/dimTime, 0.0)
    ),
    nSteps_(0),
    nFallback_(0),
    nRetries_(0),
    nExplicitFallback_(0),
    nExplicitSubsteps_(0),
    cgTotal_(0),
    nCornerCells_(0),
    cornerMass_(0),
    cornerEnergy_(0)
{
    // A field built from a tmp does not keep its write option
    rho_.writeOpt() = IOobject::AUTO_WRITE;

    Info<< "Ideal gas: gamma " << gas_.gamma() << ", R " << gas_.R() << nl;
    checkInitial();

    if (!dict_.isDict("gas"))
    {
        missingEntry(dict_, "gas", "a sub-dictionary with the gas settings");
    }
    const dictionary& gasDict = dict_.subDict("gas");
    CFL_ = getPositive(gasDict, "CFL", 0.5);
    if (CFL_ > 1)
    {
        badEntry(gasDict, "CFL", Foam::name(CFL_), "0 < CFL <= 1");
    }
    maxDeltaT_ = getPositive(gasDict, "maxDeltaT", GREAT);
    maxRetries_ = getLabelAtLeast(gasDict, "maxRetries", 5, 0);
    schlierenScale_ = getPositive(gasDict, "schlierenScale", 15);

    scheme_ = gasFluxScheme::New(gasDict);

    // Boundary conditions of the patches the lines end on
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    bcs_.setSize(patches.size());
    const dictionary& bDict = dict_.subOrEmptyDict("boundaries");
    Info<< "Gas boundaries:" << nl;
    for (label d = 0; d < 3; ++d)
    {
        if (!view_.active(d)) continue;
        for (const auto& s : view_.segments(d))
        {
            for (const label pi : {s.lowPatch, s.highPatch})
            {
                if (bcs_.set(pi)) continue;
                const polyPatch& pp = patches[pi];
                if (isA<processorPolyPatch>(pp))
                {
                    // Ghosts from the neighbour rank (parallel runs)
                    bcs_.set
                    (
                        pi,
                        new gasBoundaries::processorGhosts(pp.name(), gas_)
                    );
                    continue;
                }
                gasBoundary::primitiveState st{0, Zero, 0};
                const scalarField& pb = p_.boundaryField()[pi];
                const scalarField& rb = rho_.boundaryField()[pi];
                const vectorField& ub = Uf_.boundaryField()[pi];
                if (pp.size())
                {
                    st.p = average(pb);
                    st.rho = average(rb);
                    st.U = average(ub);
                }
                bcs_.set
                (
                    pi,
                    gasBoundary::New
                    (
                        pp.name(), pp.type(), bDict, gas_, st
                    )
                );
                Info<< "    " << pp.name() << " (" << pp.type() << "): "
                    << bcs_[pi].type() << nl;
            }
        }
    }
    forAll(bcs_, pi)
    {
        if
        (
            bcs_.set(pi)
         && (
                bcs_[pi].kindOf() == gasBoundary::kind::inlet
             || bcs_[pi].kindOf() == gasBoundary::kind::outlet
            )
        )
        {
            openPatches_ = true;
        }
    }
    reduce(openPatches_, orOp<bool>());
    logTotals_ = getAsOrDefault<bool>
    (
        gasDict, "logTotals", openPatches_, "true or false"
    );

    // A periodic line must be periodic at both ends and span the domain
    for (label d = 0; d < 3; ++d)
    {
        if (!view_.active(d)) continue;
        for (const auto& s : view_.segments(d))
        {
            const bool lo =
                bcs_[s.lowPatch].kindOf() == gasBoundary::kind::periodic;
            const bool hi =
                bcs_[s.highPatch].kindOf() == gasBoundary::kind::periodic;
            if ((lo || hi) && !(lo && hi && s.length == view_.n(d)))
            {
                FatalIOErrorInFunction(dict_)
                    << "A line along " << "xyz"[d] << " starting at cell "
                    << view_.cellAt()[s.start] << " ends on patches "
                    << patches[s.lowPatch].name() << " and "
                    << patches[s.highPatch].name() << nl
                    << "    allowed: periodic conditions on both ends of"
                    << " lines that span the whole domain" << nl
                    << exit(FatalIOError);
            }
        }
    }

    op_.reset(new eulerOperator(view_, gas_, scheme_(), bcs_));
    stepper_ = gasStepper::New(gasDict, op_());

    corners_.reset
    (
        new wallCorners
        (
            view_, gas_, bcs_,
            getEnum
            (
                gasDict, "cornerTreatment", wallCorners::treatmentNames,
                wallCorners::treatment::none
            ),
            getLabelAtLeast(gasDict, "cornerResetCells", 0, 0),
            scheme_->nGhost()
        )
    );
    if (corners_->type() != wallCorners::treatment::none)
    {
        Info<< "Convex wall corners: " << label(corners_->corners().size())
            << ", treatment "
            << wallCorners::treatmentNames[corners_->type()]
            << " (up to " << corners_->nResetCells() << " wall cells)" << nl;
    }

    U_.resize(view_.nLattice());
    Unew_.resize(view_.nLattice());
    fromFields();
    toFields();
    updateDerived();

    // A stable step that small would take more than 1e12 steps: stop now,
    // naming what sets it, instead of running without end
    if (maxDeltaT_ < minDeltaT())
    {
        badEntry
        (
            gasDict, "maxDeltaT", Foam::name(maxDeltaT_),
            "a number >= 1e-12 (endTime - startTime) = "
          + Foam::name(minDeltaT()) + " (endTime "
          + Foam::name(mesh.time().endTime().value()) + ", startTime "
          + Foam::name(mesh.time().startTime().value())
          + "): a smaller step would need more than 1e12 steps"
        );
    }
    const scalar dt0 = stableDeltaT();
    if (!(dt0 >= minDeltaT()))
    {
        FatalIOErrorInFunction(dict_)
            << "The initial state's stable time step " << dt0
            << " (CFL " << CFL_ << ") is below 1e-12 of the time span"
            << " endTime - startTime = "
            << mesh.time().endTime().value() - mesh.time().startTime().value()
            << ": the run would take more than 1e12 steps." << nl
            << "    The fastest waves: " << fastestCell().c_str() << nl
            << "    allowed: CFL, maxDeltaT, gamma and initial fields"
            << " (internalField of p, U and rho or T) whose stable time step"
            << " is >= " << minDeltaT() << exit(FatalIOError);
    }

    Info<< "Gas solver: stepper " << gasDict.get<word>("stepper")
        << ", scheme " << gasDict.get<word>("scheme")
        << ", " << gasStepper::rkOrderNames
           [
               getEnum
               (
                   gasDict, "timeIntegration", gasStepper::rkOrderNames,
                   gasStepper::rkOrder::RK3
               )
           ]
        << ", CFL " << CFL_ << nl;
    scalar m, e;
    vector mom;
    totals(m, mom, e);
    const label prec = Info().precision(17);
    Info<< "Initial totals: mass " << m << ", momentum " << mom
        << ", energy " << e << nl << endl;
    Info().precision(prec);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::gasDynamics::stableDeltaT() const
{
    word limiter;
    scalar speed = 0;
    scalar dt = stepper_->stableDeltaT(U_, CFL_, speed, limiter);
    reduce(dt, minOp<scalar>());
    return min(dt, maxDeltaT_);
}


void Foam::gasDynamics::step(Time& runTime)
{
    word limiter;
    scalar speed = 0;
    scalar dt = stepper_->stableDeltaT(U_, CFL_, speed, limiter);
    if (Pstream::parRun())
    {
        // Every rank takes the same step: the serial one, min over all cells
        reduce(dt, minOp<scalar>());
        reduce(speed, maxOp<scalar>());
    }
    dt = min(dt, maxDeltaT_);
    if (!(dt >= minDeltaT()))
    {
        // The waves got so fast that the run would not end: stop cleanly
        toFields();
        updateDerived();
        runTime.writeNow();
        stepper_->writeState();
        FatalErrorInFunction
            << "The stable time step " << dt << " at time "
            << runTime.timeName() << " (CFL " << CFL_ << ", limited by "
            << limiter.c_str() << ", max speed " << speed << ") is below"
            << " 1e-12 of the time span endTime - startTime = "
            << runTime.endTime().value() - runTime.startTime().value()
            << ": the run would not end." << nl
            << "    The fastest waves: " << fastestCell().c_str() << nl
            << "    The last good state is written at time "
            << runTime.timeName() << exit(FatalError);
    }

    // Land on write times and the end time without exceeding the CFL step
    const scalar toWrite = timeToNextWrite();
    const scalar toEnd = runTime.endTime().value() - runTime.value();
    const scalar target = min(toWrite, toEnd);
    if (target > 0 && target < GREAT)
    {
        const scalar n = std::ceil(target/dt - 1e-9);
        dt = target/max(n, scalar(1));
    }

    gasStepper::report rep;
    label tries = 0;
    stepper_->clearCrossed();
    while (!stepper_->advance(U_, dt, Unew_, rep))
    {
        stepper_->clearCrossed();
        if (tries == maxRetries_)
        {
            // Write the last good state and stop
            toFields();
            updateDerived();
            runTime.writeNow();
        stepper_->writeState();
            const label celli =
                rep.failedCell >= 0 ? view_.cellAt()[rep.failedCell] : -1;
            FatalErrorInFunction
                << "The gas state failed in the step from time "
                << runTime.timeName() << " (dt " << dt << ", after "
                << tries << " halvings): " << rep.failure.c_str() << nl
                << "    in cell " << celli << " at "
                << (celli >= 0 ? mesh_.cellCentres()[celli] : vector::zero)
                << " (on processor " << Pstream::myProcNo() << ")" << nl;
            if (rep.explicitFallbacks > 0)
            {
                FatalError
                    << "    (an explicit fallback step, after: "
                    << rep.fallbackReason.c_str() << ")" << nl;
            }
            FatalError
                << "    The last good state is written at time "
                << runTime.timeName() << exit(FatalError);
        }
        ++tries;
        ++nRetries_;
        dt *= 0.5;
        Info<< "    step failed (" << rep.failure.c_str() << " in cell "
            << (rep.failedCell >= 0 ? view_.cellAt()[rep.failedCell] : -1)
            << "); retrying with dt "
            << dt << nl;
        rep = gasStepper::report();
    }

    nCornerCells_ += corners_->correct(Unew_, cornerMass_, cornerEnergy_);

    runTime.setDeltaT(dt, false);
    ++runTime;
    std::swap(U_, Unew_);
    toFields();
    for (int c = 0; c < 5; ++c) crossed_[c] += stepper_->crossed()[c];

    ++nSteps_;
    nFallback_ += rep.fallbackCells;
    cgTotal_ += rep.cgIterations;
    nExplicitFallback_ += rep.explicitFallbacks;
    nExplicitSubsteps_ += rep.explicitSubsteps;

    Info<< "Step " << runTime.timeIndex() << "  Time = " << runTime.timeName()
        << "  dt = " << dt << "  maxSpeed = " << speed << " (" << limiter
        << ")";
    if (rep.cgIterations > 0)
    {
        Info<< "  CG iterations = " << rep.cgIterations;
    }
    if (rep.fallbackCells > 0)
    {
        Info<< "  firstOrderCells = " << rep.fallbackCells;
    }
    if (rep.explicitFallbacks > 0)
    {
        Info<< "  explicitFallback = " << rep.explicitSubsteps
            << " substeps (" << rep.fallbackReason.c_str() << ")";
    }
    if (!rep.info.empty())
    {
        Info<< "  " << rep.info.c_str();
    }
    Info<< nl;

    if (logTotals_)
    {
        scalar m, e, mc, ec;
        vector mom, momc;
        totals(m, mom, e);
        crossed(mc, momc, ec);
        const label prec = Info().precision(15);
        Info<< "    totals + crossed (step): mass " << m + mc << ", momentum "
            << mom + momc << ", energy " << e + ec << nl;
        Info().precision(prec);
    }

    if (runTime.writeTime())
    {
        updateDerived();
        scalar m, e;
        vector mom;
        totals(m, mom, e);
        Info<< "    totals: mass " << m << ", momentum " << mom
            << ", energy " << e << nl
            << "    ExecutionTime = " << runTime.elapsedCpuTime() << " s"
            << "  ClockTime = " << runTime.elapsedClockTime() << " s"
            << nl;
    }
}


void Foam::gasDynamics::summary() const
{
    Info<< nl << "Gas solver summary: " << nSteps_ << " steps, "
        << view_.nCells() << " cells, " << scalar(nSteps_)*view_.nCells()
        << " cell updates";
    if (cgTotal_ > 0)
    {
        Info<< ", CG iterations " << cgTotal_ << " (mean "
            << scalar(cgTotal_)/max(nSteps_, label(1)) << " per step)";
    }
    Info<< ", first-order fallback cells " << nFallback_
        << ", halved steps " << nRetries_;
    if (nExplicitFallback_ > 0)
    {
        Info<< ", explicit fallback steps " << nExplicitFallback_ << " ("
            << nExplicitSubsteps_ << " acoustic sub-steps)";
    }
    Info<< nl;
    {
        scalar m, e;
        vector mom;
        crossed(m, mom, e);
        Info<< "    crossed the patches (outward; walls take momentum):"
            << " mass " << m << ", momentum " << mom << ", energy " << e
            << nl;
    }
    if (corners_->type() == wallCorners::treatment::entropyReset)
    {
        Info<< "Corner entropy resets: " << nCornerCells_ << " cells; mass "
            << "added " << cornerMass_ << ", energy added " << cornerEnergy_
            << " (not conservative)" << nl;
    }
    else if (corners_->type() == wallCorners::treatment::entropyTransfer)
    {
        Info<< "Corner entropy transfers: " << nCornerCells_ << " cells;"
            << " mass moved " << cornerMass_ << ", energy moved "
            << cornerEnergy_ << " (conservative)" << nl;
    }
}


// ************************************************************************* //
