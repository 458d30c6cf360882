/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "csmpmStepper.H"
#include "mpmCloudIO.H"
#include "semiImplicitStepper.H"
#include "dictionaryChecks.H"
#include "fvMesh.H"
#include "volFields.H"
#include "IOField.H"
#include "cloud.H"
#include "OSspecific.H"
#include <chrono>

namespace
{
    using stageClock = std::chrono::steady_clock;
    double secondsSince(const stageClock::time_point& t0)
    {
        return std::chrono::duration<double>(stageClock::now() - t0).count();
    }
}

namespace Foam
{
    defineTypeNameAndDebug(csmpmStepper, 0);
}

const Foam::Enum<Foam::csmpmStepper::stepOrder>
Foam::csmpmStepper::stepOrderNames
({
    { stepOrder::couplingFirst, "couplingFirst" },
    { stepOrder::mpmFirst, "mpmFirst" },
});

const Foam::Enum<Foam::csmpmStepper::gasOrder>
Foam::csmpmStepper::gasOrderNames
({
    { gasOrder::B1B0, "B1B0" },
    { gasOrder::B2B1, "B2B1" },
});


namespace
{
    const Foam::dictionary& gasDictOf(const Foam::dictionary& d)
    {
        return d.subDict("gas");
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::csmpmStepper::csmpmStepper
(
    const fvMesh& mesh,
    const dictionary& shockMpmDict,
    eulerOperator& op,
    autoPtr<gasStepper>&& gasOnly,
    const gasState& U
)
:
    gasStepper(gasDictOf(shockMpmDict), op),
    fvMesh_(mesh),
    mpmDict_
    (
        IOobject
        (
            "mpmProperties",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    cloudName_(mpmDict_.getOrDefault<word>("cloudName", "mpmCloud")),
    par_(Pstream::parRun() ? new mpmParallel(mesh) : nullptr),
    serialView_(Pstream::parRun() ? nullptr : new mpmMeshView(mesh)),
    view_(par_.valid() ? par_->view() : serialView_()),
    boundary_
    (
        mesh, view_, mpmDict_.subOrEmptyDict("boundary"), par_.get()
    ),
    solver_(view_, mpmDict_, boundary_),
    gasOnly_(std::move(gasOnly)),
    order_(stepOrder::couplingFirst),
    tol_(1e-10),
    maxIter_(1000),
    lattice_(op.mesh(), view_, Pstream::parRun())
{
    const dictionary& gasDict = gasDictOf(shockMpmDict);
    const word stepper(gasDict.getOrDefault<word>("stepper", "explicit"));
    if (stepper != "semiImplicit")
    {
        FatalIOErrorInFunction(gasDict)
            << gasDict.name() << ": entry 'stepper' is " << stepper
            << ", but a case with solids (constant/mpmProperties) needs the"
            << " pressure system of the coupling." << nl
            << "    allowed: semiImplicit" << exit(FatalIOError);
    }
    if (par_.valid()) solver_.setParallel(par_());
    tol_ = dictionaryChecks::getPositive(gasDict, "CGtolerance", 1e-10);
    maxIter_ =
        dictionaryChecks::getLabelAtLeast(gasDict, "CGmaxIter", 1000, 1);

    g_ = dictionaryChecks::getBoundedVector
    (
        gasDict, "gravity", Zero, 1e10, "an acceleration [m/s^2]"
    );
    gravity_ = magSqr(g_) > 0;
    if (mag(g_ - solver_.gravity()) > 1e-12*max(mag(g_), mag(solver_.gravity())))
    {
        WarningInFunction
            << "The gas's gravity " << g_ << " (" << gasDict.name()
            << ") differs from the solid's " << solver_.gravity()
            << " (constant/mpmProperties): buoyancy needs the same on both"
            << endl;
    }

    const dictionary& cDict = shockMpmDict.subOrEmptyDict("coupling");
    order_ = dictionaryChecks::getEnum
    (
        cDict, "order", stepOrderNames, stepOrder::couplingFirst
    );
    {
        localGradient_ =
            dictionaryChecks::getWordOf
            (
                cDict, "solidUpdate", "eliminated",
                {"eliminated", "localGradient"}
            )
         == "localGradient";
        if (localGradient_ && Pstream::parRun())
        {
            FatalIOErrorInFunction(cDict)
                << cDict.name() << ": solidUpdate localGradient (the"
                << " ablation of Fig. 3.3) runs serially only." << nl
                << "    allowed with -parallel: eliminated"
                << exit(FatalIOError);
        }
    }

    bool idsRead = true;
    const bool found = mpmCloudIO::read(mesh, cloudName_, P_, &idsRead);
    if (Pstream::parRun())
    {
        checkParallelCloud(found, idsRead);
    }
    else if (!found || P_.size() == 0)
    {
        FatalErrorInFunction
            << "No particles: " << mesh.time().timePath()/cloud::prefix
            /cloudName_ << " holds no MPM cloud, but constant/mpmProperties"
            << " exists. Seed one with mpmSetParticles, or remove"
            << " constant/mpmProperties for a gas-only run"
            << exit(FatalError);
    }
    checkInside();
    solver_.initialise(P_);
    solver_.setTime(mesh.time().value());
    readGhost(cDict, gasDict);
    {
        scalar mMin = GREAT;
        forAll(P_.m, p) mMin = min(mMin, P_.m[p]);
        if (Pstream::parRun()) reduce(mMin, minOp<scalar>());
        nodeMassMin_ = 1e-3*mMin;
    }
    (void)U;

    const label nLat = mesh_.nLattice();
    Ustar_.resize(nLat);
    unknownOf_.assign(nLat, -1);
    for (size_t k = 0; k < cells_.size(); ++k) unknownOf_[cells_[k]] = label(k);
    p_.assign(cells_.size(), 0.0);
    if (!freshStart_) readSolidFractions();
    openCell_.assign(nLat, 1.0);
    if (auto* semi = dynamic_cast<gasSteppers::semiImplicitStepper*>(&gasOnly_()))
    {
        semi->setOpenFractions(&openCell_);
    }
    if (par_.valid())
    {
        // The gas's couplings across processor faces; T x over the ranks
        sys_.gas.mesh = &mesh_;
        sys_.gas.slotUnknown.resize(mesh_.nGhostSlots());
        for (label j = 0; j < mesh_.nGhostSlots(); ++j)
        {
            sys_.gas.slotUnknown[j] = unknownOf_[mesh_.slotCell(j)];
        }
        sys_.par = par_.get();
        for (label d = 0; d < 3; ++d)
        {
            if (!mesh_.active(d)) continue;
            slotLo_[d].assign(mesh_.nLattice(), -1);
            slotHi_[d].assign(mesh_.nLattice(), -1);
            const label st = mesh_.stride(d);
            for (const auto& s : mesh_.segments(d))
            {
                if (s.lowGhost >= 0) slotLo_[d][s.start] = s.lowGhost;
                if (s.highGhost >= 0)
                {
                    slotHi_[d][s.start + (s.length - 1)*st] = s.highGhost;
                }
            }
        }
    }
    for (label d = 0; d < 3; ++d)
    {
        if (!mesh_.active(d)) continue;
        const label nf = mesh_.nFaces(d);
        uStarF_[d].assign(nf, 0.0);
        rhoF_[d].assign(nf, 0.0);
        uF_[d].assign(nf, 0.0);
        pF_[d].assign(nf, 0.0);
        usF_[d].assign(nf, 0.0);
    }

    // Ambient ghost pressure needs the gas state at the particles
    const word init
    (
        dictionaryChecks::getWordOf
        (
            cDict, "ghostInit", "ambient", {"ambient", "unstressed"}
        )
    );
    if (init == "ambient" && !Jg_.size())
    {
        // J^g from p^g = p_gas: J^g = 1 - p/lambda^g (3.17)
        Jg_.setSize(P_.size());
        forAll(P_.x, p)
        {
            label ijk[3] = {0, 0, 0};
            for (label d = 0; d < 3; ++d)
            {
                if (!mesh_.active(d)) continue;
                const scalar s =
                    (P_.x[p][d] - mesh_.origin()[d])/mesh_.dx(d);
                ijk[d] = min(max(label(std::floor(s)), 0), mesh_.n(d) - 1);
            }
            const label i =
                ijk[0] + mesh_.n(0)*(ijk[1] + mesh_.n(1)*ijk[2]);
            const double rho = U.q[0][i];
            const double pa = (gamma_ - 1)*(U.q[4][i] - 0.5*(U.q[1][i]
                *U.q[1][i] + U.q[2][i]*U.q[2][i] + U.q[3][i]*U.q[3][i])/rho);
            Jg_[p] = 1 - pa/lambdaG_[p];
            if (!(Jg_[p] > 0))
            {
                FatalIOErrorInFunction(cDict)
                    << "The ambient pressure " << pa << " Pa at particle "
                    << p << " is above the ghost matrix's lambda^g "
                    << lambdaG_[p] << " Pa: J^g = 1 - p/lambda^g would be "
                    << Jg_[p] << ". Raise ghostLambda (in " << cDict.name()
                    << ") or use ghostInit unstressed" << exit(FatalIOError);
            }
        }
    }
    else if (!Jg_.size())
    {
        Jg_.setSize(P_.size());
        Jg_ = 1;
    }
    pg_.setSize(P_.size());
    Kg_.setSize(P_.size());
    Vold_.setSize(P_.size());
    checkInlets(shockMpmDict);
    gasOrder_ = dictionaryChecks::getEnum
    (
        cDict, "gasPressureOrder", gasOrderNames, gasOrder::B1B0
    );
    if (gasOrder_ == gasOrder::B2B1) setGasB2B1(cDict);
    audit_.setOn
    (
        dictionaryChecks::getAsOrDefault<bool>
        (
            cDict, "energyAudit", false, "true or false"
        )
    );
    maxSubsteps_ =
        dictionaryChecks::getLabelAtLeast(cDict, "solidSubsteps", 1, 1);

    Info<< "CSMPM coupling: " << returnReduce(P_.size(), sumOp<label>())
        << " particles, "
        << view_.nVertices() << " MPM nodes on the gas lattice, order "
        << stepOrderNames[order_] << ", kernel " << solver_.kernel().type()
        << ", gas pressure order " << gasOrderNames[gasOrder_];
    if (maxSubsteps_ > 1)
    {
        Info<< ", up to " << maxSubsteps_ << " solid substeps a step";
    }
    Info<< nl;
}


void Foam::csmpmStepper::setGasB2B1(const dictionary& cDict)
{
    // The whole lattice: its size, and the global index of each own cell
    // (-parallel: the rank's box's offset in it)
    label N[3], off[3] = {0, 0, 0};
    for (label d = 0; d < 3; ++d) N[d] = mesh_.n(d);
    if (Pstream::parRun())
    {
        const latticeRing& ring = lattice_.ring();
        for (label d = 0; d < 3; ++d)
        {
            N[d] = ring.N(d);
            off[d] = ring.off(d);
        }
    }
    const label nAll = returnReduce(mesh_.nCells(), sumOp<label>());
    if
    (
        nAll != N[0]*N[1]*N[2]
     || !returnReduce(mesh_.nCells() == mesh_.nLattice(), andOp<bool>())
    )
    {
        FatalIOErrorInFunction(cDict)
            << cDict.name() << ": gasPressureOrder B2B1 needs a mesh that"
            << " fills its lattice's box (" << nAll << " cells of "
            << N[0]*N[1]*N[2] << " lattice positions)." << nl
            << "    allowed on this mesh: B1B0" << exit(FatalIOError);
    }
    std::vector<label> global(cells_.size());
    for (size_t k = 0; k < cells_.size(); ++k)
    {
        const label i = cells_[k];
        const label a = i % mesh_.n(0);
        const label b = (i/mesh_.n(0)) % mesh_.n(1);
        const label c = i/(mesh_.n(0)*mesh_.n(1));
        global[k] = (a + off[0]) + N[0]*((b + off[1]) + N[1]*(c + off[2]));
    }
    // Periodic directions wrap (every line of a direction alike in a box;
    // a rank whose lines end on processor patches at both ends cannot
    // tell, another can)
    const PtrList<gasBoundary>& bcs = op_.boundaries();
    bool periodic[3] = {false, false, false};
    for (label d = 0; d < 3; ++d)
    {
        if (!mesh_.active(d)) continue;
        for (const auto& s : mesh_.segments(d))
        {
            if (s.lowGhost < 0)
            {
                periodic[d] = bcs[s.lowPatch].kindOf()
                    == gasBoundary::kind::periodic;
                break;
            }
        }
        if (Pstream::parRun()) reduce(periodic[d], orOp<bool>());
    }
    gasB2B1_.reset
    (
        new gasB2B1Operator(mesh_, N, periodic, cells_, global)
    );
    openLat_.assign(mesh_.nLattice(), 1.0);
    // The largest rank's window: what a rank holds and works on
    const label nW = returnReduce(gasB2B1_->nWindowCells(), maxOp<label>());
    Info<< "    gas B2B1: the largest rank's window " << nW << " of "
        << N[0]*N[1]*N[2] << " lattice cells, "
        << returnReduce(gasB2B1_->nVertices(), maxOp<label>())
        << " velocity nodes, "
        << returnReduce(gasB2B1_->nHaloCells(), maxOp<label>())
        << " halo cells from up to "
        << returnReduce(gasB2B1_->nHaloRanks(), maxOp<label>())
        << " ranks" << nl;
}


void Foam::csmpmStepper::readGhost
(
    const dictionary& cDict,
    const dictionary& gasDict
)
{
    lambdaGiven_ = cDict.found("ghostLambda");
    lambdaValue_ = lambdaGiven_
        ? dictionaryChecks::getPositive(cDict, "ghostLambda") : 0;
    setLambdaG(cDict);

    // J^g from the cloud on a restart
    IOobject io
    (
        "Jg",
        fvMesh_.time().timeName(),
        cloud::prefix/cloudName_,
        fvMesh_,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (io.typeHeaderOk<IOField<scalar>>(false))
    {
        IOField<scalar> f(io);
        if (f.size() != P_.size())
        {
            FatalErrorInFunction
                << f.objectPath() << " holds " << f.size() << " values for "
                << P_.size() << " particles" << exit(FatalError);
        }
        Jg_.setSize(f.size());
        forAll(f, p) Jg_[p] = f[p];
        freshStart_ = false;
    }
    if (Pstream::parRun())
    {
        // A rank without particles has no J^g: a restart if any has
        freshStart_ = !returnReduce(!freshStart_, orOp<bool>());
    }
}


void Foam::csmpmStepper::setLambdaG(const dictionary& cDict)
{
    lambdaG_.setSize(P_.size());
    const bool given = lambdaGiven_;
    const scalar lg = lambdaValue_;
    forAll(P_.x, p)
    {
        lambdaG_[p] =
            given ? lg : solver_.materials()[P_.material[p]].lambda();
        if (!(lambdaG_[p] > 0))
        {
            FatalIOErrorInFunction(cDict)
                << "The material " << solver_.materials()[P_.material[p]]
                   .name() << " has lambda " << lambdaG_[p] << " <= 0 (nu "
                << solver_.materials()[P_.material[p]].nu() << "), so the"
                << " ghost matrix (3.17) would not resist compression: set"
                << " ghostLambda > 0 in " << cDict.name()
                << exit(FatalIOError);
        }
    }

}


void Foam::csmpmStepper::checkInlets(const dictionary& shockMpmDict) const
{
    // The cells next to an inlet face hold the inflow state the inlet
    // imposes: a solid there would be pushed through the boundary
    const PtrList<gasBoundary>& bcs = op_.boundaries();
    std::vector<char> inletCell(mesh_.nLattice(), 0);
    std::vector<label> inletPatch(mesh_.nLattice(), -1);
    for (label d = 0; d < 3; ++d)
    {
        if (!mesh_.active(d)) continue;
        const label st = mesh_.stride(d);
        for (const auto& s : mesh_.segments(d))
        {
            if (bcs[s.lowPatch].kindOf() == gasBoundary::kind::inlet)
            {
                inletCell[s.start] = 1;
                inletPatch[s.start] = s.lowPatch;
            }
            if (bcs[s.highPatch].kindOf() == gasBoundary::kind::inlet)
            {
                const label last = s.start + (s.length - 1)*st;
                inletCell[last] = 1;
                inletPatch[last] = s.highPatch;
            }
        }
    }
    forAll(P_.x, p)
    {
        label ijk[3] = {0, 0, 0};
        for (label d = 0; d < 3; ++d)
        {
            if (!mesh_.active(d)) continue;
            const scalar s = (P_.x[p][d] - mesh_.origin()[d])/mesh_.dx(d);
            ijk[d] = min(max(label(std::floor(s)), 0), mesh_.n(d) - 1);
        }
        const label i = ijk[0] + mesh_.n(0)*(ijk[1] + mesh_.n(1)*ijk[2]);
        if (inletCell[i])
        {
            const dictionary& bDict = shockMpmDict.subDict("boundaries");
            FatalIOErrorInFunction(bDict)
                << "Particle " << p << " at " << P_.x[p] << " lies in a cell"
                << " on the inlet patch "
                << bcs[inletPatch[i]].patchName() << " (entry '"
                << bcs[inletPatch[i]].patchName() << "' of "
                << bDict.name() << "): seed the solid at least one cell"
                << " away from inlets (system/mpmSetParticlesDict)"
                << exit(FatalIOError);
        }
    }
}


void Foam::csmpmStepper::checkInside() const
{
    // Each particle within the lattice box of its cell (to 1e-6 of a
    // spacing): the lattice cell the coupling deposits it on is the cell
    // the mesh files it under
    const std::vector<label>& latticeOf = mesh_.latticeOf();
    const scalar tol = 1e-6;
    forAll(P_.x, p)
    {
        const label c = P_.cell[p];
        label ijk[3] = {-1, -1, -1};
        bool inside = c >= 0 && c < label(latticeOf.size());
        if (inside)
        {
            mesh_.ijk(latticeOf[c], ijk[0], ijk[1], ijk[2]);
        }
        for (label d = 0; inside && d < 3; ++d)
        {
            const scalar s = (P_.x[p][d] - mesh_.origin()[d])/mesh_.dx(d);
            inside = s >= ijk[d] - tol && s <= ijk[d] + 1 + tol;
        }
        if (inside) continue;

        const fileName cloudFile
        (
            fvMesh_.time().timePath()/cloud::prefix/cloudName_/"coordinates"
        );
        vector lo(Zero), hi(Zero);
        for (label d = 0; d < 3; ++d)
        {
            lo[d] = mesh_.origin()[d];
            hi[d] = lo[d] + mesh_.n(d)*mesh_.dx(d);
        }
        FatalIOError
        (
            FUNCTION_NAME, __FILE__, __LINE__, cloudFile, -1
        )   << "Particle " << p << " (id " << P_.id[p] << ") of the cloud "
            << cloudFile << " lies at " << P_.x[p] << ", outside its cell "
            << c << " of the gas lattice (the lattice spans " << lo
            << " to " << hi << ")." << nl
            << "    The particles were seeded by the entry 'regions' of "
            << fvMesh_.time().path()/fvMesh_.time().system()
            /"mpmSetParticlesDict" << " (or the"
            << " cloud was written for another mesh)." << nl
            << "    allowed: particles inside the cells of this blockMesh;"
            << " seed them again with mpmSetParticles" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::csmpmStepper::caseHasSolid(const fvMesh& mesh)
{
    // (the case's constant directory, also for a processor mesh)
    return isFile
    (
        mesh.time().globalPath()/mesh.time().constant()/"mpmProperties"
    );
}


Foam::scalar Foam::csmpmStepper::stableDeltaT
(
    const gasState& U,
    scalar CFL,
    scalar& speed,
    word& limiter
) const
{
    // The gas's own limit from its state per open volume, each face's
    // pressure difference weighted by its open share: a cell the solid
    // covers holds only its open volume's share of the gas
    // (mergeCoveredCells), and its pressure difference to its neighbours
    // over that share would set a step 1/sqrt(open) shorter than its gas,
    // whose faces the solid mostly blocks, needs; so would a cavity of thin
    // gas inside the solid (cylindersMach3 at 200 per unit length: a step
    // 10 times shorter than the flow's CFL)
    for (int c = 0; c < 5; ++c) Uopen_.q[c] = U.q[c];
    for (const label i : openSet_) openCell_[i] = 1;
    openSet_ = phiCells_;
    for (const label i : phiCells_)
    {
        openCell_[i] = max(1 - phiCell_[i], 0.0);
        const double o = max(1 - phiCell_[i], gasVolumeMin_);
        for (int c = 0; c < 5; ++c) Uopen_.q[c][i] /= o;
    }
    const scalar dtGas = gasOnly_->stableDeltaT(Uopen_, CFL, speed, limiter);
    // (with solidSubsteps, up to that many of the solid's steps, in which
    // no particle moves further than the gas's CFL allows the flow)
    const scalar dtWaves = solver_.deltaT(P_);
    scalar dtSolid = dtWaves;
    std::string why("solid elastic waves");
    if (maxSubsteps_ > 1)
    {
        const scalar v = solver_.maxSpeed();
        dtSolid = maxSubsteps_*dtWaves;
        why += " x " + std::to_string(maxSubsteps_);
        if (v*dtSolid > CFL*solver_.hMin())
        {
            dtSolid = max(dtWaves, CFL*solver_.hMin()/v);
            why = "solid particle speed";
        }
    }
    if (dtSolid < dtGas)
    {
        limiter = why;
        return dtSolid;
    }
    return dtGas;
}


void Foam::csmpmStepper::compactRemoved(DynamicList<scalar>& f) const
{
    const List<bool>& gone = solver_.removed();
    label n = 0;
    forAll(gone, p)
    {
        if (!gone[p]) f[n++] = f[p];
    }
    f.setSize(n);
}


bool Foam::csmpmStepper::advance
(
    const gasState& U,
    scalar dt,
    gasState& out,
    report& rep
)
{
    // The solid's substeps (solidSubsteps): as many as its elastic waves
    // need in the gas's step; the first takes the coupled step's impulse
    label nSub = 1;
    if (maxSubsteps_ > 1)
    {
        nSub = max(label(1), label(std::ceil(dt/solver_.deltaT(P_) - 1e-9)));
    }
    const scalar h1 = dt/nSub;

    // 1. P2G: nodal masses and v*
    if (audit_.on()) auditMark(-1, U, true);
    auto t0 = stageClock::now();
    if (!solver_.beginStep(P_))
    {
        rep.failure = solver_.failure();
        return false;
    }
    if (solver_.removed().size())
    {
        // Particles that left through an outlet: their J^g and lambda^g go
        compactRemoved(Jg_);
        compactRemoved(lambdaG_);
    }
    if (nSub > 1)
    {
        // What a refused later substep goes back to
        solver_.checkpoint(P_);
        JgSaved_ = Jg_;
        lambdaGSaved_ = lambdaG_;
    }
    if (par_.valid())
    {
        // Every copy of a node: the nodal mass of all the ranks' particles
        // (a copy no particle of its rank touches holds none)
        const mpmGrid& grid = solver_.grid();
        massAll_.setSize(grid.mass.size());
        forAll(massAll_, i) massAll_[i] = grid.isActive[i] ? grid.mass[i] : 0;
        par_->maxShared(massAll_);
    }
    forAll(P_.x, p)
    {
        pg_[p] = -lambdaG_[p]*(Jg_[p] - 1);     // (3.17)
        Kg_[p] = lambdaG_[p]*Jg_[p];            // (3.24)
    }

    // 2. Interfaces: reflective share of each face (3.2.3)
    lattice_.deposit(P_, pg_, Kg_);
    couplingFaces();
    stageTime_[0] += secondsSince(t0);
    if (audit_.on()) auditMark(csmpmEnergyAudit::p2g, U, false);

    // 3. Advection with blended fluxes (3.10-3.12)
    t0 = stageClock::now();
    for (label d = 0; d < 3; ++d)
    {
        if (mesh_.active(d))
        {
            op_.setPassable(d, &openEff_[d]);
        }
    }
    const bool advected = rungeKutta(U, dt, true, Ustar_, rep);
    for (label d = 0; d < 3; ++d) op_.setPassable(d, nullptr);
    stageTime_[1] += secondsSince(t0);
    if (!advected) return false;
    if (audit_.on()) auditMark(csmpmEnergyAudit::advection, Ustar_, false);

    // 6'. Ablation order: the MPM grid update before the coupled solve
    t0 = stageClock::now();
    if (order_ == stepOrder::mpmFirst)
    {
        solver_.gridUpdate(P_, h1);
    }
    stageTime_[3] += secondsSince(t0);

    // 4.-5. The coupled solve
    t0 = stageClock::now();
    const bool solved = pressureStep(U, dt, out, rep);
    stageTime_[2] += secondsSince(t0);
    if (!solved) return false;
    if (audit_.on()) auditMark(csmpmEnergyAudit::coupledSolve, out, false);

    // 6. The MPM grid update after it (3.2.8)
    t0 = stageClock::now();
    if (order_ == stepOrder::couplingFirst)
    {
        solver_.gridUpdate(P_, h1);
    }
    else
    {
        solver_.applyBoundary();
    }
    stageTime_[3] += secondsSince(t0);
    if (audit_.on()) auditMark(csmpmEnergyAudit::gridUpdate, out, false);

    // 7. G2P; J^g by (3.20) with the velocity gradient that updates F
    t0 = stageClock::now();
    forAll(P_.x, p) Vold_[p] = P_.V[p];
    if (par_.valid()) idOld_ = P_.id;
    const bool moved = solver_.endStep(P_, h1);
    if (moved)
    {
        updateJg();
    }
    stageTime_[4] += secondsSince(t0);
    if (!moved)
    {
        rep.failure = solver_.failure();
        return false;
    }
    if (audit_.on()) auditMark(csmpmEnergyAudit::g2p, out, true);

    // The solid's substeps after the first, to the gas's step
    lastSubsteps_ = 1;
    if (nSub > 1 && !solidSubsteps(dt, h1, rep))
    {
        return false;
    }

    if (audit_.on())
    {
        auditMark(csmpmEnergyAudit::solidSubsteps, out, true);
        audit_.accept();
    }

    ++nSteps_;
    cgTotal_ += rep.cgIterations;
    cgMax_ = max(cgMax_, rep.cgIterations);
    rep.info = "CG residual " + std::to_string(rep.cgResidual)
      + "  solidCells " + std::to_string(lattice_.nSolidCells())
      + "  interfaceFaces " + std::to_string(lattice_.nInterfaceFaces());
    if (lastSubsteps_ > 1)
    {
        rep.info += "  solidSubsteps " + std::to_string(lastSubsteps_);
    }
    nSubsteps_ += lastSubsteps_;
    if (lastRepaired_)
    {
        nRepaired_ += lastRepaired_;
        rep.info += "  repairedCells " + std::to_string(lastRepaired_);
    }
    return true;
}


bool Foam::csmpmStepper::solidSubsteps
(
    scalar dt,
    scalar done,
    report& rep
)
{
    // Equal substeps over what is left of dt, each within the elastic-wave
    // step of the state it starts from (a bound on their number: a state
    // whose waves sped up that much is refused, and the gas step halved)
    label n = 1;
    const label most = 4*maxSubsteps_;
    while (done < dt*(1 - 1e-12))
    {
        const scalar left = dt - done;
        const scalar m = std::ceil(left/solver_.deltaT(P_) - 1e-9);
        if (n + m > most)
        {
            rep.failure = "the solid's elastic waves would need more than "
                + std::to_string(most) + " substeps (4 x solidSubsteps)";
            rollbackSubsteps();
            return false;
        }
        const scalar h = left/max(m, scalar(1));

        auto t0 = stageClock::now();
        bool ok = solver_.beginStep(P_);
        if (ok && solver_.removed().size())
        {
            compactRemoved(Jg_);
            compactRemoved(lambdaG_);
        }
        stageTime_[0] += secondsSince(t0);
        if (ok)
        {
            t0 = stageClock::now();
            solver_.gridUpdate(P_, h);
            stageTime_[3] += secondsSince(t0);

            t0 = stageClock::now();
            if (Vold_.size() < P_.size()) Vold_.setSize(P_.size());
            forAll(P_.x, p) Vold_[p] = P_.V[p];
            if (par_.valid()) idOld_ = P_.id;
            ok = solver_.endStep(P_, h);
            if (ok) updateJg();
            stageTime_[4] += secondsSince(t0);
        }
        if (!ok)
        {
            rep.failure = std::string(solver_.failure())
                + " (solid substep " + std::to_string(n + 1) + ")";
            rollbackSubsteps();
            return false;
        }
        done += h;
        ++n;
    }
    lastSubsteps_ = n;
    solver_.substepsDone();
    return true;
}


void Foam::csmpmStepper::rollbackSubsteps()
{
    solver_.rollback(P_);
    Jg_ = JgSaved_;
    lambdaG_ = lambdaGSaved_;
    const label nP = P_.size();
    if (pg_.size() < nP) pg_.setSize(nP);
    if (Kg_.size() < nP) Kg_.setSize(nP);
    if (Vold_.size() < nP) Vold_.setSize(nP);
}


void Foam::csmpmStepper::auditMark
(
    label stage,
    const gasState& S,
    bool particles
)
{
    // The gas: its total energy on the lattice, with what crossed its
    // patches in this step so far
    scalar gas = 0;
    for (const label i : mesh_.latticeOf()) gas += S.q[4][i];
    gas = gas*mesh_.cellVolume() + crossed_[4];
    if (Pstream::parRun()) reduce(gas, sumOp<scalar>());

    // The solid: kinetic energy of the particles, or of the grid nodes
    // (between P2G and G2P: nothing moves the particles or removes any)
    const scalar sc = lattice_.scale();
    if (stage > csmpmEnergyAudit::p2g && stage < csmpmEnergyAudit::g2p)
    {
        audit_.mark(stage, gas, sc*solver_.gridKineticEnergy());
        return;
    }
    scalar kinetic;
    if (particles)
    {
        scalar m;
        vector mom;
        solidTotals(m, mom, kinetic);

        scalar ghost = 0;
        forAll(P_.x, p)
        {
            ghost += 0.5*lambdaG_[p]*(P_.V[p]/Jg_[p])*sqr(Jg_[p] - 1);
        }
        if (Pstream::parRun()) reduce(ghost, sumOp<scalar>());
        audit_.markGhost(stage >= 0, sc*ghost);
    }
    else
    {
        kinetic = solver_.gridKineticEnergy();
    }
    // The particles' elastic energy, and what left through outlets
    const mpmSolver::totals out = solver_.departed();
    audit_.mark
    (
        stage,
        gas,
        sc*kinetic,
        sc*out.kinetic,
        sc*(solidStrainEnergy() + out.strain)
    );
}


void Foam::csmpmStepper::setSolidFractions()
{
    if (label(phiCell_.size()) != mesh_.nLattice())
    {
        phiCell_.assign(mesh_.nLattice(), 0.0);
    }
    for (const label i : phiCells_) phiCell_[i] = 0;
    phiCells_ = lattice_.touchedCells();
    for (const label i : phiCells_) phiCell_[i] = lattice_.phi(i);
}


// A restart's solid fractions: those of the last step before the write
// (alphaSolid), by which that step's merges scaled the covered cells' gas
// and the first step's limit (stableDeltaT) divides it, as the run that
// went on did; none (the cells' content taken as it is) if not written
void Foam::csmpmStepper::readSolidFractions()
{
    IOobject io
    (
        "alphaSolid",
        fvMesh_.time().timeName(),
        fvMesh_,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (!io.typeHeaderOk<volScalarField>(true)) return;
    const volScalarField alpha(io, fvMesh_);
    phiCell_.assign(mesh_.nLattice(), 0.0);
    phiCells_.clear();
    const auto& latticeOf = mesh_.latticeOf();
    forAll(alpha, c)
    {
        if (alpha[c] > 0)
        {
            const label i = latticeOf[c];
            phiCell_[i] = alpha[c];
            phiCells_.push_back(i);
        }
    }
}


std::vector<double> Foam::csmpmStepper::openFractions()
{
    forAll(P_.x, p)
    {
        pg_[p] = -lambdaG_[p]*(Jg_[p] - 1);
        Kg_[p] = lambdaG_[p]*Jg_[p];
    }
    lattice_.deposit(P_, pg_, Kg_);
    setSolidFractions();
    std::vector<double> a(mesh_.nLattice(), 1.0);
    for (label i = 0; i < mesh_.nLattice(); ++i)
    {
        a[i] = max(1 - lattice_.phi(i), gasVolumeMin_);
    }
    return a;
}


void Foam::csmpmStepper::solidTotals
(
    scalar& m,
    vector& mom,
    scalar& kinetic
) const
{
    m = 0;
    mom = Zero;
    kinetic = 0;
    forAll(P_.x, p)
    {
        m += P_.m[p];
        mom += P_.m[p]*P_.v[p];
        kinetic += 0.5*P_.m[p]*magSqr(P_.v[p]);
    }
    if (Pstream::parRun())
    {
        reduce(m, sumOp<scalar>());
        reduce(mom, sumOp<vector>());
        reduce(kinetic, sumOp<scalar>());
    }
}


Foam::scalar Foam::csmpmStepper::solidStrainEnergy() const
{
    scalar e = 0;
    forAll(P_.x, p) e += P_.psi[p]*P_.V0[p];
    if (Pstream::parRun()) reduce(e, sumOp<scalar>());
    return e;
}


void Foam::csmpmStepper::write() const
{
    audit_.report(("to t = " + fvMesh_.time().timeName()).c_str());
    mpmCloudIO::write(fvMesh_, cloudName_, P_);
    IOField<scalar> Jg
    (
        IOobject
        (
            "Jg",
            fvMesh_.time().timeName(),
            cloud::prefix/cloudName_,
            fvMesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        Jg_.size()
    );
    forAll(Jg_, p) Jg[p] = Jg_[p];
    Jg.write();

    volScalarField alpha
    (
        IOobject
        (
            "alphaSolid",
            fvMesh_.time().timeName(),
            fvMesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        fvMesh_,
        dimensionedScalar(dimless, Zero)
    );
    volScalarField R
    (
        IOobject
        (
            "Rsolid",
            fvMesh_.time().timeName(),
            fvMesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        fvMesh_,
        dimensionedScalar(dimless, Zero)
    );
    const auto& latticeOf = mesh_.latticeOf();
    forAll(alpha, c)
    {
        const label i = latticeOf[c];
        alpha[c] = lattice_.phi(i);
        scalar r = 0;
        for (label d = 0; d < 3; ++d)
        {
            if (!mesh_.active(d)) continue;
            const label f = mesh_.lowFaceOf(d)[i];
            r = max(r, max(lattice_.R(d)[f], lattice_.R(d)[f + 1]));
        }
        R[c] = r;
    }
    alpha.write();
    R.write();
}


void Foam::csmpmStepper::summary() const
{
    Info<< "CSMPM coupling summary: " << nSteps_ << " coupled steps, "
        << returnReduce(P_.size(), sumOp<label>()) << " particles, CG iterations mean "
        << scalar(cgTotal_)/max(nSteps_, label(1)) << ", max " << cgMax_
        << ", gas cells next to the solid repaired (pooled with a"
        << " neighbour) " << nRepaired_ << nl;
    if (maxSubsteps_ > 1)
    {
        Info<< "CSMPM solid substeps: " << nSubsteps_ << " in "
            << nSteps_ << " coupled steps (mean "
            << scalar(nSubsteps_)/max(nSteps_, label(1))
            << ", solidSubsteps " << maxSubsteps_ << ")" << nl;
    }
    if (par_.valid())
    {
        Info<< "CSMPM parallel: particles moved to another rank "
            << returnReduce(par_->nMigratedTotal(), sumOp<label>())
            << ", MPM grid exchanges " << returnReduce
               (
                   mpmParallel::commTime(), maxOp<scalar>()
               ) << " s (largest over the ranks)" << nl;
    }
    const char* names[5] =
        {"P2G and interfaces", "advection", "coupled solve",
         "MPM grid update", "G2P"};
    double total = 0;
    for (const double t : stageTime_) total += t;
    Info<< "CSMPM cost per step (wall ms):";
    for (label k = 0; k < 5; ++k)
    {
        Info<< "  " << names[k] << " "
            << 1e3*stageTime_[k]/max(nSteps_, label(1));
    }
    Info<< "  total " << 1e3*total/max(nSteps_, label(1)) << nl;
    audit_.report("the run");
}


// ************************************************************************* //
