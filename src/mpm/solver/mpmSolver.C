/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "mpmSolver.H"
#include "mpmParallel.H"
#include "barrierContact.H"
#include "dictionaryChecks.H"
#include "Pstream.H"
#include "ops.H"
#include <algorithm>

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::mpmSolver::readSettings(const dictionary& dict)
{
    using namespace dictionaryChecks;

    gravity_ = mesh_.inPlane
    (
        getAsOrDefault<vector>(dict, "gravity", vector::zero, "a vector (gx gy gz)")
    );
    CFL_ = getPositive(dict, "CFL", 0.5);
    if (CFL_ > 1)
    {
        badEntry(dict, "CFL", Foam::name(CFL_), "a number 0 < CFL <= 1");
    }
    maxDeltaT_ = getPositive(dict, "maxDeltaT", 1e30);
    massCancellation_ =
        kernel_->nonNegativeWeights()
      ? 0
      : getAsOrDefault<scalar>
        (
            dict, "massCancellation", kernel_->defaultMassCancellation(),
            "a number 0 <= massCancellation <= 1"
        );
    if (!(massCancellation_ >= 0 && massCancellation_ <= 1))
    {
        badEntry(dict, "massCancellation", Foam::name(massCancellation_),
            "a number 0 <= massCancellation <= 1");
    }
    if (kernel_->nonNegativeWeights() && dict.found("massCancellation"))
    {
        IOWarningInFunction(dict)
            << "massCancellation has no effect with the kernel "
            << kernel_->type() << ": its weights are never negative, so no "
            << "vertex mass cancels" << endl;
    }
    maxSteps_ = getInRange(dict, "maxSteps", 1e9, 0, 1e15);

    // The F-bar average's weights: the kernel's, or convex (non-negative)
    // by default where the kernel's weights cancel (ring supports)
    const word fbarAverage
    (
        getWordOf
        (
            dict, "FbarAverage",
            kernel_->defaultMassCancellation() > 0 ? "convex" : "kernel",
            {"kernel", "convex"}
        )
    );
    fbarConvex_ = (fbarAverage == "convex");

    // The length of CFL h/c: the shortest vertex size (mean edge), or the
    // kernel's own (for mlsRing and umls the narrowest support h_v)
    const word stepLength
    (
        getWordOf(dict, "stepLength", "vertex", {"vertex", "kernel"})
    );
    hMin_ =
        stepLength == "kernel"
      ? kernel_->stepLength()
      : kernel_->mpmKernel::stepLength();

    // USL by default (Algorithm 1); MUSL for a kernel whose vertices at a
    // free surface can hold a vanishing mass (linear)
    const word scheme
    (
        getWordOf
        (
            dict, "updateScheme",
            kernel_->vanishingVertexMass() ? "MUSL" : "USL",
            {"USL", "MUSL"}
        )
    );
    musl_ = (scheme == "MUSL");

    const dictionary* md = dict.findDict("materials", keyType::LITERAL);
    if (!md || md->empty())
    {
        missingEntry(dict, "materials",
            "a sub-dictionary with one sub-dictionary per material,"
            " e.g. materials { steel { type linearElastic; rho 7800;"
            " E 2e11; nu 0.3; } }");
    }
    for (const entry& e : *md)
    {
        if (!e.isDict())
        {
            badEntry(*md, e.keyword(), entryText(*md, e.keyword()),
                "a material sub-dictionary { type ...; rho ...; E ...; nu ...; }");
        }
        materials_.append(mpmMaterial::New(e.keyword(), e.dict()));
    }
}


void Foam::mpmSolver::updateStress
(
    mpmParticles& P,
    const bool returnMap
)
{
    if (anyFbar_)
    {
        // The averaged volume ratio Jbar of the F-bar particles
        const label nP = P.size();
        Fbar_.setSize(nP);
        Jbar_.setSize(nP);
        piBar_.setSize(nP);
        forAll(materials_, k)
        {
            if (!materials_[k].Fbar()) continue;
            for (label p = materialStart_[k]; p < materialStart_[k + 1]; ++p)
            {
                Jbar_[p] = det(P.F[p])*P.Jp[p];
            }
        }
        fbarAverage(P, Jbar_);
    }

    forAll(materials_, k)
    {
        const label b = materialStart_[k];
        const label n = materialStart_[k + 1] - b;
        if (n == 0) continue;
        const mpmMaterial& mat = materials_[k];
        if (mat.Fbar())
        {
            fbarStress(P, k, returnMap);
            continue;
        }
        SubList<tensor> F(P.F, n, b);
        SubList<symmTensor> sigma(P.sigma, n, b);
        SubList<scalar> psi(P.psi, n, b);
        if (mat.plastic())
        {
            // Return mapping and stress, one call per material range
            SubList<scalar> epsilonP(P.epsilonP, n, b);
            SubList<scalar> Jp(P.Jp, n, b);
            mat.plasticStress(F, epsilonP, Jp, sigma, psi, returnMap);
        }
        else
        {
            mat.stress(F, sigma, psi);
        }
    }

    if (anyFbar_)
    {
        // The mean stress averaged as Jbar was (the transpose of that
        // average, the same operator for one density)
        fbarAverage(P, piBar_);
        const symmTensor Id(symm(tensor::I - mesh_.offAxes()));
        forAll(materials_, k)
        {
            if (!materials_[k].Fbar()) continue;
            for (label p = materialStart_[k]; p < materialStart_[k + 1]; ++p)
            {
                P.sigma[p] += piBar_[p]*Id;
            }
        }
        fbarStabilise(P);
    }
}


Foam::scalar Foam::mpmSolver::mechanicalEnergy
(
    const mpmParticles& P,
    scalar& kinetic,
    scalar& strain
) const
{
    scalar grav = 0;
    kinetic = 0;
    strain = 0;
    forAll(P.x, p)
    {
        kinetic += 0.5*P.m[p]*magSqr(P.v[p]);
        strain += P.V0[p]*P.psi[p];
        grav -= P.m[p]*(gravity_ & P.x[p]);
    }
    if (par_)
    {
        // One reduction (a synchronisation point) for the three sums
        const mpmParallel::exchangeTimer timer;
        vector sums(kinetic, strain, grav);
        reduce(sums, sumOp<vector>());
        kinetic = sums.x();
        strain = sums.y();
        grav = sums.z();
    }
    return kinetic + strain + grav;
}


bool Foam::mpmSolver::agreed(const bool ok, const char* what)
{
    if (!par_) return ok;
    const mpmParallel::exchangeTimer timer;
    const bool all = returnReduce(ok, andOp<bool>());
    if (!all && ok)
    {
        failure_ = string("a particle of another rank ") + what;
    }
    return all;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::mpmSolver::mpmSolver
(
    const mpmMeshView& mesh,
    const dictionary& dict,
    const mpmGridBoundary& boundary
)
:
    mesh_(mesh),
    par_(nullptr),
    located_(false),
    kernel_(mpmKernel::New(dict, mesh)),
    transfer_(mpmTransfer::New(dict, mesh)),
    boundary_(boundary),
    actuators_(mpmActuator::readAll(dict, mesh)),
    time_(0),
    stepDt_(0),
    gravity_(Zero),
    CFL_(0.5),
    maxDeltaT_(1e30),
    maxSteps_(1e9),
    massCancellation_(0),
    musl_(false),
    hMin_(0),   // set by readSettings
    grid_(mesh.nVertices()),
    anyFbar_(false),
    fbarConvex_(false),
    inversion_(dict, mesh.offAxes()),
    treatedStep_(0),
    treatedTotal_(0),
    particleSteps_(0),
    departed_{0, Zero, Zero, 0, 0, 0},
    departedStep_(0),
    departedCount_(0),
    wallMomentum_(Zero),
    wallMomentumStep_(Zero),
    contact_(nullptr),
    contactDt_(GREAT),
    contactDtNext_(-1),
    cLast_(0),
    cMaterial_(-1),
    vLast_(0),
    energy0_(0),
    energyGrowthBound_(0)
{
    readSettings(dict);
    if (transfer_->affine() && !kernel_->invertibleMoments())
    {
        dictionaryChecks::badEntry
        (
            dict, "transfer",
            word(transfer_->type()) + " (with kernel " + kernel_->type() + ")",
            "PIC or FLIP with kernel " + kernel_->type() + "; APIC needs an"
            " invertible second moment D_p of the weights (2.36), which the "
            + kernel_->type() + " kernel lacks (use kernel umls or mlsRing"
            " for APIC)"
        );
    }
    transfer_->setMomentFloor(kernel_->momentFloor());
    forAll(materials_, k)
    {
        if (materials_[k].Fbar()) anyFbar_ = true;
    }
    if (anyFbar_)
    {
        fbarMass_.setSize(mesh_.nVertices(), Zero);
        fbarSum_.setSize(mesh_.nVertices(), Zero);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::label Foam::mpmSolver::materialIndex
(
    const word& name,
    const dictionary& dict
) const
{
    forAll(materials_, k)
    {
        if (materials_[k].name() == name) return k;
    }
    wordList names(materials_.size());
    forAll(materials_, k) names[k] = materials_[k].name();
    OStringStream allowed;
    allowed << "one of the materials of constant/mpmProperties " << names;
    dictionaryChecks::badEntry(dict, "material", name, allowed.str());
    return -1;
}


void Foam::mpmSolver::setParallel(const mpmParallel& par)
{
    if (&par.view() != &mesh_)
    {
        FatalErrorInFunction
            << "The MPM solver of a -parallel run needs the parallel grid's"
            << " view (mpmParallel::view())" << exit(FatalError);
    }
    par_ = &par;
    reduce(hMin_, minOp<scalar>());
}


void Foam::mpmSolver::setContact(barrierContact& contact)
{
    contact_ = &contact;
    scalarList E(materials_.size());
    forAll(materials_, k) E[k] = materials_[k].E();
    contact_->setMaterials(E);
}


void Foam::mpmSolver::initialise(mpmParticles& P)
{
    P.hasContact = (contact_ != nullptr);
    P.fContact.setSize(P.size(), Zero);
    materialStart_ = P.sortByMaterial(materials_.size());
    if (contact_) contact_->invalidate();
    contactDtNext_ = -1;
    forAll(P.x, p)
    {
        // A cloud edited by hand or written by a broken run: values
        // beyond 1e30 overflow the energies (m |v|^2) and stresses
        const scalar big = 1e30;
        const char* bad = nullptr;
        if (!(cmptMax(cmptMag(P.x[p])) <= big)) bad = "position";
        else if (!(cmptMax(cmptMag(P.v[p])) <= big)) bad = "U";
        else if (!(cmptMax(cmptMag(P.F[p])) <= big)) bad = "F";
        else if (!(cmptMax(cmptMag(P.B[p])) <= big)) bad = "B";
        else if (!(P.m[p] > 0 && P.m[p] <= big)) bad = "mass";
        else if (!(P.V0[p] > 0 && P.V0[p] <= big)) bad = "V0";
        else if (!(det(P.F[p]) > 0)) bad = "F (det F <= 0)";
        else if (!(P.Jp[p] > 0 && P.Jp[p] <= big)) bad = "Jp";
        else if (!(P.epsilonP[p] >= 0 && P.epsilonP[p] <= big))
        {
            bad = "epsilonP";
        }
        if (bad)
        {
            FatalErrorInFunction
                << "Particle " << p << " of the MPM cloud has a non-finite,"
                << " out-of-range (beyond 1e30) or non-physical " << bad
                << ": x " << P.x[p] << ", U " << P.v[p] << ", F " << P.F[p]
                << ", mass " << P.m[p] << ", V0 " << P.V0[p] << ", Jp "
                << P.Jp[p] << ", epsilonP " << P.epsilonP[p]
                << exit(FatalError);
        }
        const label c = mesh_.findCell(P.x[p], P.cell[p]);
        if (c < 0)
        {
            FatalErrorInFunction
                << "Particle " << p << " at " << P.x[p]
                << " lies outside the mesh" << exit(FatalError);
        }
        if (par_ && c >= par_->nOwnedCells())
        {
            FatalErrorInFunction
                << "Particle " << p << " (id " << P.id[p] << ") at "
                << P.x[p] << " of processor " << Pstream::myProcNo()
                << "'s cloud lies in a cell of another processor: the"
                << " cloud does not belong to this decomposition"
                << exit(FatalError);
        }
        P.cell[p] = c;
        P.V[p] = det(P.F[p])*P.Jp[p]*P.V0[p];
    }
    // The stress of the state read (no return mapping: a restart
    // continues from the state written); F-bar averages with the weights
    // at the particles' positions
    if (anyFbar_)
    {
        kernel_->compute(P.x, P.cell, kw_);
    }
    const List<symmTensor> sigmaRead(anyFbar_ ? P.sigma : List<symmTensor>());
    const List<scalar> psiRead(anyFbar_ ? P.psi : List<scalar>());
    updateStress(P, false);

    // F-bar materials keep the stresses of a cloud that has them (a
    // restart): the average that made them used the weights of the step
    // that wrote them, which the weights at the written positions only
    // approximate (to 1e-7 in F after a restart otherwise)
    forAll(materials_, k)
    {
        if (!materials_[k].Fbar()) continue;
        bool stressed = false;
        for (label p = materialStart_[k]; p < materialStart_[k + 1]; ++p)
        {
            if (magSqr(sigmaRead[p]) > 0) { stressed = true; break; }
        }
        if (!stressed) continue;
        for (label p = materialStart_[k]; p < materialStart_[k + 1]; ++p)
        {
            P.sigma[p] = sigmaRead[p];
            P.psi[p] = psiRead[p];
        }
    }

    // The energy bound: the energy in motion at the start plus what
    // gravity can release over the mesh's extent along g
    scalar kinetic = 0, strain = 0;
    energy0_ = mechanicalEnergy(P, kinetic, strain);
    scalar release = 0;
    if (magSqr(gravity_) > 0)
    {
        const vector gHat = gravity_/mag(gravity_);
        scalar lo = GREAT, hi = -GREAT;
        for (const vector& xv : mesh_.vertices())
        {
            lo = min(lo, gHat & xv);
            hi = max(hi, gHat & xv);
        }
        scalar mass = 0;
        for (const scalar m : P.m) mass += m;
        if (par_)
        {
            reduce(lo, minOp<scalar>());
            reduce(hi, maxOp<scalar>());
            reduce(mass, sumOp<scalar>());
        }
        release = mass*mag(gravity_)*(hi - lo);
    }
    energyGrowthBound_ = kinetic + strain + release;

    // Particles in cells touching the mesh boundary have one-sided 1-rings:
    // MLS weights can turn negative there (Fig. 2.6)
    if (!kernel_->nonNegativeAtBoundary())
    {
        const labelList& cv = mesh_.cellVertices();
        label nOneSided = 0;
        forAll(P.x, p)
        {
            const label c = P.cell[p];
            for (label i = mesh_.cellBegin(c); i < mesh_.cellEnd(c); ++i)
            {
                if (mesh_.boundaryVertex(cv[i])) { ++nOneSided; break; }
            }
        }
        label nP = P.size();
        if (par_)
        {
            reduce(nOneSided, sumOp<label>());
            reduce(nP, sumOp<label>());
        }
        if (nOneSided)
        {
            WarningInFunction
                << nOneSided << " of " << nP << " particles lie in cells"
                << " touching the mesh boundary, where the " << kernel_->type()
                << " kernel's 1-ring is one-sided and weights can turn"
                << " negative. Mesh an extra layer of cells outside the"
                << " material (dissertation Fig. 2.6) unless a grid condition"
                << " holds those vertices." << endl;
        }
    }
}


Foam::scalar Foam::mpmSolver::deltaT(const mpmParticles& P) const
{
    // A deformed state's estimate counts where it exceeds the reference
    // speed by more than this factor: small strains keep the reference
    // speed (and the results of the reference-speed step)
    const scalar deformedMargin = 1.5;

    // Per material (-1: no particle of it here)
    scalarList cK(materials_.size(), scalar(-1));
    forAll(materials_, k)
    {
        const label b = materialStart_[k];
        const label n = materialStart_[k + 1] - b;
        if (n == 0) continue;
        const mpmMaterial& mat = materials_[k];
        cK[k] = max
        (
            mat.waveSpeed(),
            mat.maxWaveSpeed
            (
                SubList<tensor>(P.F, n, b), SubList<symmTensor>(P.sigma, n, b)
            )/deformedMargin
        );
    }
    scalar vMax2 = 0;
    for (const vector& v : P.v) vMax2 = max(vMax2, magSqr(v));
    for (const mpmActuator& a : actuators_)
    {
        vMax2 = max(vMax2, sqr(a.maxSpeed()));
    }
    if (par_)
    {
        // One gather and scatter for the speeds and |v|max
        const mpmParallel::exchangeTimer timer;
        cK.append(vMax2);
        Pstream::listCombineGather(cK, maxEqOp<scalar>());
        Pstream::listCombineScatter(cK);
        vMax2 = cK.last();
        cK.setSize(materials_.size());
    }
    scalar cMax = 0;
    cMaterial_ = -1;
    forAll(cK, k)
    {
        if (cK[k] < 0) continue;
        if (cK[k] > cMax || cMaterial_ < 0)
        {
            cMax = cK[k];
            cMaterial_ = k;
        }
    }
    cLast_ = cMax;
    vLast_ = std::sqrt(vMax2);
    const scalar speed = cMax + vLast_;
    const scalar dt =
        min(maxDeltaT_, speed > 0 ? CFL_*hMin_/speed : maxDeltaT_);

    // The barrier's spring and step filter (barrierContact)
    contactDt_ = GREAT;
    if (contact_)
    {
        scalar dtc =
            contactDtNext_ >= 0 ? contactDtNext_ : contact_->maxDeltaT(P, CFL_);
        if (par_)
        {
            const mpmParallel::exchangeTimer timer;
            reduce(dtc, minOp<scalar>());
        }
        if (dtc < dt)
        {
            contactDt_ = dtc;
            return dtc;
        }
    }
    return dt;
}


Foam::string Foam::mpmSolver::deltaTReason() const
{
    OStringStream os;
    os  << "dt = CFL h_min/(c + |v|max) with CFL " << CFL_ << ", h_min "
        << hMin_ << " m, c = " << cLast_ << " m/s";
    if (cMaterial_ >= 0)
    {
        const mpmMaterial& mat = materials_[cMaterial_];
        os  << " (material " << mat.name() << ": E " << mat.E() << ", nu "
            << mat.nu() << ", rho " << mat.rho() << "; reference speed "
            << mat.waveSpeed() << " m/s)";
    }
    os  << ", |v|max = " << vLast_ << " m/s";
    if (maxDeltaT_ < 1e30) os << ", maxDeltaT " << maxDeltaT_;
    if (contactDt_ < GREAT)
    {
        os  << "; limited to " << contactDt_ << " s by the barrier contact"
            << " (CFL sqrt(m_p/(kappa_p b''(d))) and the step filter"
            << " d/(2 v_n) of the particles near the contact patches)";
    }
    return os.str();
}


bool Foam::mpmSolver::energyBounded(const mpmParticles& P)
{
    scalar kinetic = 0, strain = 0;
    const scalar E = mechanicalEnergy(P, kinetic, strain);
    // The actuators' work on the material is energy it may hold
    const scalar W = actuators_.empty() ? scalar(0) : actuatorWork();
    const scalar growth = E - energy0_ - W;
    if
    (
        std::isfinite(E)
     && (energyGrowthBound_ <= 0 || growth <= energyGrowthBound_)
    )
    {
        return true;
    }
    OStringStream os;
    os  << "the mechanical energy (kinetic + strain + gravitational) grew"
        << " from " << energy0_ << " to " << E << ", by more than the "
        << energyGrowthBound_ << " the system can hold";
    if (!actuators_.empty()) os << " with the actuators' work " << W;
    os  << ": the discretisation"
        << " is unstable (" << deltaTReason().c_str() << "). A lower CFL"
        << " (above the kernel's limit?) or the FLIP/PIC transfer (APIC"
        << " at extreme deformation?) may keep it bounded";
    failure_ = os.str();
    return false;
}


void Foam::mpmSolver::removeDeparted(mpmParticles& P)
{
    // What they carry out, as conservation() counts it
    mpmParticles out;
    forAll(leaving_, p)
    {
        if (leaving_[p]) out.appendFrom(P, p);
    }
    const totals t = localTotals(out);
    departed_.mass += t.mass;
    departed_.momentum += t.momentum;
    departed_.angularMomentum += t.angularMomentum;
    departed_.kinetic += t.kinetic;
    departed_.strain += t.strain;
    departed_.gravitational += t.gravitational;

    P.remove(leaving_);
    removed_ = leaving_;
    leaving_.clear();
    materialStart_ = P.sortByMaterial(materials_.size());
    if (contact_) contact_->invalidate();
}


bool Foam::mpmSolver::beginStep(mpmParticles& P)
{
    const label nP = P.size();
    failure_.clear();
    removed_.clear();
    wallMomentumStep_ = Zero;

    // 1. Locate (walk from the previous cell; in parallel the last
    // step's migration located them, unless one had left the mesh)
    const bool located = located_;
    located_ = false;
    label nLeaving = 0;
    for (label p = 0; p < nP && !located; ++p)
    {
        const label c = mesh_.findCell(P.x[p], P.cell[p]);
        if (c < 0 && boundary_.hasOutlets() && boundary_.throughOutlet(P.x[p]))
        {
            // Out through an outlet: it leaves the scene
            if (leaving_.empty()) leaving_.setSize(nP, false);
            leaving_[p] = true;
            ++nLeaving;
            continue;
        }
        if (c < 0 || (par_ && c >= par_->nOwnedCells()))
        {
            failure_ = "particle " + Foam::name(p) + " at "
                + Foam::name(P.x[p]) + " has left the mesh";
            break;
        }
        P.cell[p] = c;
    }
    if (!agreed(failure_.empty(), "has left the mesh"))
    {
        leaving_.clear();
        return false;
    }
    departedStep_ = nLeaving;
    if (par_) reduce(departedStep_, sumOp<label>());
    departedCount_ += departedStep_;
    if (nLeaving) removeDeparted(P);

    // Weights, active vertices
    kernel_->compute(P.x, P.cell, kw_);
    grid_.activate(kw_);

    // 2. P2G: mass and momentum, then the velocity v* of each vertex; the
    // grid update starts from v~ = v*
    transfer_->p2g(P, kw_, grid_);
    if (par_)
    {
        // Each copy of a shared vertex holds the sum over the ranks
        par_->sumShared(grid_.mass, &grid_.isActive);
        par_->sumShared(grid_.velocity, &grid_.isActive);
    }
    if (massCancellation_ > 0) sumAbsMass(P);
    // v* = p / m, with the same cancelled-mass guard as the grid update:
    // a vertex whose signed weights cancel would otherwise get a velocity
    // far larger than any particle's (seen on graded tetrahedra)
    const scalar tiny = VSMALL;
    for (const label i : grid_.active)
    {
        const scalar m = updateMass(i);
        if (mag(m) > tiny)
        {
            grid_.velocity[i] /= m;
            grid_.newVelocity[i] = grid_.velocity[i];
        }
        else
        {
            grid_.velocity[i] = Zero;
            grid_.newVelocity[i] = Zero;
        }
    }
    return true;
}


void Foam::mpmSolver::sumAbsMass(const mpmParticles& P)
{
    const label nP = P.size();
    for (label p = 0; p < nP; ++p)
    {
        const scalar mp = P.m[p];
        for (label k = kw_.start[p]; k < kw_.start[p + 1]; ++k)
        {
            grid_.absMass[kw_.vertex[k]] += mag(kw_.w[k])*mp;
        }
    }
    if (par_) par_->sumShared(grid_.absMass, &grid_.isActive);
}


void Foam::mpmSolver::gridUpdate(const mpmParticles& P, const scalar dt)
{
    const label nP = P.size();
    stepDt_ = dt;

    // 3.-5. Internal (2.8) and gravity (2.9) forces
    const bool gravity = magSqr(gravity_) > 0;
    for (label p = 0; p < nP; ++p)
    {
        const symmTensor Vs = P.V[p]*P.sigma[p];
        const scalar mp = P.m[p];
        const vector mg = mp*gravity_;
        for (label k = kw_.start[p]; k < kw_.start[p + 1]; ++k)
        {
            const label i = kw_.vertex[k];
            vector f = grid_.force[i] - (Vs & kw_.gradW[k]);
            if (gravity) f += kw_.w[k]*mg;
            grid_.force[i] = f;
        }
    }
    // Barrier contact forces (external particle forces, by the weights)
    if (contact_)
    {
        fContact_.setSize(nP);
        contact_->forces(P, kw_, fContact_);
        for (label p = 0; p < nP; ++p)
        {
            const vector& fc = fContact_[p];
            if (fc.x() == 0 && fc.y() == 0 && fc.z() == 0) continue;
            for (label k = kw_.start[p]; k < kw_.start[p + 1]; ++k)
            {
                grid_.force[kw_.vertex[k]] += kw_.w[k]*fc;
            }
        }
        if (par_ && contact_->friction() > 0)
        {
            par_->sumShared(contact_->vertexBound(), &grid_.isActive);
            par_->sumShared(contact_->vertexNormal(), &grid_.isActive);
        }
    }
    if (par_) par_->sumShared(grid_.force, &grid_.isActive);

    // 6. Grid update (2.11) from v~ (v*, or v* with the coupling's change)
    // and boundary conditions
    const scalar tiny = VSMALL;
    for (const label i : grid_.active)
    {
        const scalar m = updateMass(i);
        if (mag(m) > tiny)
        {
            grid_.newVelocity[i] =
                mesh_.inPlane(grid_.newVelocity[i] + (dt/m)*grid_.force[i]);
        }
    }

    // The contact's friction on v~ (implicit), and its share per particle
    if (contact_ && contact_->friction() > 0)
    {
        // In parallel every active vertex (a shared one may have been
        // touched on another rank only)
        const UList<label>& vs =
            par_ ? UList<label>(grid_.active) : UList<label>(contact_->touched());
        contact_->friction(grid_.mass, vs, dt, grid_.newVelocity);
        contact_->frictionShare(P, kw_, fContact_);
        contact_->resetVertices(vs);
    }
    applyBoundary();
}


void Foam::mpmSolver::updateVertexShare()
{
    // Each copy of a vertex held by several ranks counts its share.  Every
    // copy sends its value, active or not: the inactive ones send 0
    vertexShare_.setSize(mesh_.nVertices());
    vertexShare_ = 0;
    for (const label i : grid_.active) vertexShare_[i] = 1;
    par_->sumShared(vertexShare_, &grid_.isActive);
    for (const label i : grid_.active)
    {
        vertexShare_[i] = 1/vertexShare_[i];
    }
}


void Foam::mpmSolver::applyBoundary()
{
    const UList<scalar>* share = nullptr;
    if (par_)
    {
        updateVertexShare();
        share = &vertexShare_;
    }
    wallMomentumStep_ +=
        boundary_.apply(grid_.isActive, grid_.mass, grid_.newVelocity, share);
    for (mpmActuator& a : actuators_)
    {
        a.apply
        (
            time_, stepDt_, mesh_.vertices(), grid_.active, grid_.mass,
            grid_.newVelocity, share
        );
    }
}


Foam::scalar Foam::mpmSolver::gridKineticEnergy()
{
    scalar K = 0;
    if (par_)
    {
        updateVertexShare();
        for (const label i : grid_.active)
        {
            K += 0.5*vertexShare_[i]*grid_.mass[i]*magSqr(grid_.newVelocity[i]);
        }
        reduce(K, sumOp<scalar>());
    }
    else
    {
        for (const label i : grid_.active)
        {
            K += 0.5*grid_.mass[i]*magSqr(grid_.newVelocity[i]);
        }
    }
    return K;
}


Foam::vector Foam::mpmSolver::wallMomentum() const
{
    vector M = wallMomentum_;
    if (par_) reduce(M, sumOp<vector>());
    return M;
}


Foam::scalar Foam::mpmSolver::actuatorWork() const
{
    scalar W = 0;
    for (const mpmActuator& a : actuators_) W += a.work();
    if (par_) reduce(W, sumOp<scalar>());
    return W;
}


bool Foam::mpmSolver::step(mpmParticles& P, const scalar dt)
{
    if (!beginStep(P)) return false;
    gridUpdate(P, dt);
    return endStep(P, dt);
}


bool Foam::mpmSolver::endStep(mpmParticles& P, const scalar dt)
{
    const label nP = P.size();
    const List<vector>& xv = mesh_.vertices();
    const scalar tiny = VSMALL;

    for (const label i : grid_.active)
    {
        if (!std::isfinite(magSqr(grid_.newVelocity[i])))
        {
            failure_ = "non-finite grid velocity at vertex " + Foam::name(i)
                + " at " + Foam::name(xv[i]);
            break;
        }
    }
    if (!agreed(failure_.empty(), "has a non-finite grid velocity"))
    {
        return false;
    }

    // MUSL: G2P first, then the velocity gradient from grid velocities
    // re-projected from the updated particles (bounded by the particle
    // velocities, so vertices with a tiny mass cannot amplify round-off)
    if (musl_)
    {
        savedV_ = P.v;
        if (transfer_->affine()) savedB_ = P.B;
        transfer_->g2p(kw_, grid_, P);

        for (const label i : grid_.active) grid_.force[i] = Zero;
        for (label p = 0; p < nP; ++p)
        {
            const vector mv = P.m[p]*P.v[p];
            for (label k = kw_.start[p]; k < kw_.start[p + 1]; ++k)
            {
                grid_.force[kw_.vertex[k]] += kw_.w[k]*mv;
            }
        }
        if (par_) par_->sumShared(grid_.force, &grid_.isActive);
        for (const label i : grid_.active)
        {
            const scalar m = updateMass(i);
            grid_.force[i] = mag(m) > tiny ? mesh_.inPlane(grid_.force[i]/m) : Zero;
        }
        boundary_.apply(grid_.isActive, grid_.force);
    }
    const List<vector>& vGrad = musl_ ? grid_.force : grid_.newVelocity;

    // 8. Deformation gradients (2.15), checked before anything is kept,
    // and the grid velocity at the particles for the positions (2.13),
    // in one pass over the weights
    Fnew_.setSize(nP);
    Jnew_.setSize(nP);
    vGrid_.setSize(nP);
    label nTreated = 0;
    for (label p = 0; p < nP; ++p)
    {
        tensor gradV(Zero);
        vector vg(Zero);
        for (label k = kw_.start[p]; k < kw_.start[p + 1]; ++k)
        {
            const label i = kw_.vertex[k];
            gradV += vGrad[i]*kw_.gradW[k];
            vg += kw_.w[k]*grid_.newVelocity[i];
        }
        vGrid_[p] = vg;
        Fnew_[p] = (I + dt*gradV) & P.F[p];
        scalar J = det(Fnew_[p]);
        // A particle that would invert clamped (inversionClamp); one that
        // stays proper, however crushed, follows its material
        if
        (
            inversion_.on() && !(J > 0) && std::isfinite(J)
         && inversion_.apply(Fnew_[p])
        )
        {
            ++nTreated;
            J = det(Fnew_[p]);
        }
        Jnew_[p] = J;
        if (!(J > 0) || !std::isfinite(J))
        {
            failure_ = "particle " + Foam::name(p) + " at "
                + Foam::name(P.x[p]) + " would invert: det F = "
                + Foam::name(J)
                + (
                    inversion_.on()
                  ? string(" (a non-finite deformation)")
                  : string
                    (
                        " (time step too large, or the material is crushed;"
                        " the treatment clamp of the entry 'inversion' of"
                        " mpmProperties would clamp the particle)"
                    )
                );
            break;
        }
    }
    // More treated particles than the share allowed: the scene, not a
    // few particles, is crushed (every rank sees the same sums)
    label nAll = nP;
    if (par_)
    {
        reduce(nTreated, sumOp<label>());
        reduce(nAll, sumOp<label>());
    }
    if (failure_.empty() && nTreated > inversion_.maxShare()*nAll)
    {
        failure_ = Foam::name(nTreated) + " of " + Foam::name(nAll)
            + " particles would invert in this step (more than"
            " maxShare " + Foam::name(inversion_.maxShare()) + " of them,"
            " entry 'inversion' of mpmProperties): the time step is too"
            " large or the material too soft for its load";
    }
    if (contact_ && failure_.empty())
    {
        // No particle may reach a contact patch
        scalar d = 0;
        const label p = contact_->check(P, vGrid_, dt, d);
        if (p >= 0)
        {
            failure_ = "particle " + Foam::name(p) + " (id "
                + Foam::name(P.id[p]) + ") at " + Foam::name(P.x[p])
                + (d < 0
                    ? string(" would leave the mesh near the contact patches")
                    : " would reach a contact patch (distance "
                    + Foam::name(d) + " m)")
                + ": the barrier did not stop it (dHat "
                + Foam::name(contact_->dHat()) + " m; a larger stiffness,"
                " dHat or a smaller CFL may)";
        }
    }
    if (!agreed(failure_.empty(), "would invert or reach a contact patch"))
    {
        if (musl_)
        {
            P.v = savedV_;
            if (transfer_->affine()) P.B = savedB_;
        }
        return false;
    }

    // Positions (2.13): x_p + dt sum w v~_i (linear reproduction)
    for (label p = 0; p < nP; ++p)
    {
        P.x[p] += dt*vGrid_[p];
    }
    if (contact_)
    {
        forAll(fContact_, p) P.fContact[p] = fContact_[p];
    }

    // 7. G2P velocities (and B) (USL: after the gradient)
    if (!musl_)
    {
        transfer_->g2p(kw_, grid_, P);
    }

    // 9., 10. Volume (2.16) and stress (2.10); for plastic materials the
    // return mapping projects the trial F onto the yield surface, keeping
    // det(F) Jp and so the volume (Jp = 1 for elastic materials)
    for (label p = 0; p < nP; ++p)
    {
        P.F[p] = Fnew_[p];
        P.V[p] = Jnew_[p]*P.Jp[p]*P.V0[p];
    }
    updateStress(P, true);

    // The barrier's limit for the next step, from this step's distances
    if (contact_) contactDtNext_ = contact_->maxDeltaT(P, CFL_);

    // Particles in another rank's cell move there (one outside all cells
    // stays: the next step's locate stops the run, as serial)
    if (par_)
    {
        const label before = P.size();
        located_ = par_->migrate(P);
        const label sent = par_->nMigrated();
        if (sent || P.size() != before - sent)
        {
            materialStart_ = P.sortByMaterial(materials_.size());
            if (contact_) contact_->invalidate();
        }
    }

    treatedStep_ = nTreated;
    treatedTotal_ += nTreated;
    particleSteps_ += nAll;
    wallMomentum_ += wallMomentumStep_;
    time_ += dt;
    return true;
}


void Foam::mpmSolver::checkpoint(const mpmParticles& P)
{
    saved_.P = P;
    saved_.materialStart = materialStart_;
    saved_.treatedTotal = treatedTotal_;
    saved_.particleSteps = particleSteps_;
    saved_.time = time_;
    saved_.wallMomentum = wallMomentum_;
    saved_.departed = departed_;
    saved_.contactDtNext = contactDtNext_;
    saved_.departedBefore = departedCount_ - departedStep_;
    saved_.departedCount = departedCount_;
}


void Foam::mpmSolver::rollback(mpmParticles& P)
{
    P = saved_.P;
    materialStart_ = saved_.materialStart;
    treatedTotal_ = saved_.treatedTotal;
    particleSteps_ = saved_.particleSteps;
    time_ = saved_.time;
    wallMomentum_ = saved_.wallMomentum;
    departed_ = saved_.departed;
    contactDtNext_ = saved_.contactDtNext;
    departedCount_ = saved_.departedCount;
    // (cells as at the checkpoint: the next beginStep locates again)
    located_ = false;
    leaving_.clear();
    removed_.clear();
    if (contact_) contact_->invalidate();
}


void Foam::mpmSolver::substepsDone()
{
    treatedStep_ = label(treatedTotal_ - saved_.treatedTotal);
    departedStep_ = label(departedCount_ - saved_.departedBefore);
}


void Foam::mpmSolver::logParticleEvents(const word& timeName) const
{
    if (treatedStep_ > 0)
    {
        Info<< "    inversion clamp: " << treatedStep_ << " particles at t = "
            << timeName << " (" << treatedTotal_ << " particle-steps in"
            << " this run)" << nl;
    }
    if (departedStep_ > 0)
    {
        const totals d = departed();
        Info<< "    outlets: " << departedStep_ << " particles left at"
            << " t = " << timeName << "; out in this run: mass " << d.mass
            << ", momentum " << d.momentum << ", energy "
            << d.kinetic + d.strain + d.gravitational << nl;
    }
}


void Foam::mpmSolver::summaryParticleEvents() const
{
    if (inversion_.on())
    {
        Info<< "Inversion clamp (minStretch "
            << Foam::name(inversion_.minStretch()).c_str() << "): " << treatedTotal_
            << " of " << particleSteps_ << " particle-steps treated (share "
            << (particleSteps_ > 0 ? treatedTotal_/particleSteps_ : 0)
            << ")" << nl;
    }
    if (returnReduce(boundary_.size() > 0, orOp<bool>()))
    {
        Info<< "Walls: the grid conditions took momentum " << wallMomentum()
            << " from the solid in this run" << nl;
    }
    if (boundary_.hasOutlets() || par_)
    {
        const totals d = departed();
        if (d.mass > 0)
        {
            Info<< "Outlets: out in this run mass " << d.mass
                << ", momentum " << d.momentum << ", kinetic energy "
                << d.kinetic << ", strain energy " << d.strain << nl;
        }
    }
}


Foam::mpmSolver::totals Foam::mpmSolver::localTotals
(
    const mpmParticles& P
) const
{
    totals t{0, Zero, Zero, 0, 0, 0};
    const bool affine = transfer_->affine();
    forAll(P.x, p)
    {
        const scalar m = P.m[p];
        t.mass += m;
        t.momentum += m*P.v[p];
        t.angularMomentum += P.x[p] ^ (m*P.v[p]);
        if (affine)
        {
            // Definition 2.2.4: sum_p m_p (B_p)^T : epsilon
            const tensor& B = P.B[p];
            t.angularMomentum += m*vector
            (
                B.zy() - B.yz(),
                B.xz() - B.zx(),
                B.yx() - B.xy()
            );
        }
        t.kinetic += 0.5*m*magSqr(P.v[p]);
        t.strain += P.V0[p]*P.psi[p];
        t.gravitational -= m*(gravity_ & P.x[p]);
    }
    return t;
}


Foam::mpmSolver::totals Foam::mpmSolver::sumOverRanks(totals t) const
{
    if (par_)
    {
        // One gather and scatter for all the sums
        const mpmParallel::exchangeTimer timer;
        scalarList sums(10);
        sums[0] = t.mass;
        sums[7] = t.kinetic;
        sums[8] = t.strain;
        sums[9] = t.gravitational;
        for (direction c = 0; c < 3; ++c)
        {
            sums[1 + c] = t.momentum[c];
            sums[4 + c] = t.angularMomentum[c];
        }
        Pstream::listCombineGather(sums, plusEqOp<scalar>());
        Pstream::listCombineScatter(sums);
        t.mass = sums[0];
        t.kinetic = sums[7];
        t.strain = sums[8];
        t.gravitational = sums[9];
        for (direction c = 0; c < 3; ++c)
        {
            t.momentum[c] = sums[1 + c];
            t.angularMomentum[c] = sums[4 + c];
        }
    }
    return t;
}


Foam::mpmSolver::totals Foam::mpmSolver::conservation
(
    const mpmParticles& P
) const
{
    return sumOverRanks(localTotals(P));
}


Foam::mpmSolver::totals Foam::mpmSolver::departed() const
{
    return sumOverRanks(departed_);
}


// ************************************************************************* //
