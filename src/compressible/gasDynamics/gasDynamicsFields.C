/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
-------------------------------------------------------------------------------
Description
    gasDynamics: the volFields and the lattice arrays (reading and checking
    the initial state, copying between them, derived output, totals).

\*---------------------------------------------------------------------------*/

#include "gasDynamics.H"
#include "fvc.H"
#include "gasLimits.H"

// * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

Foam::IOobject Foam::gasDynamics::readIO
(
    const fvMesh& mesh,
    const word& name
)
{
    return IOobject
    (
        name,
        mesh.time().timeName(),
        mesh,
        IOobject::MUST_READ,
        IOobject::AUTO_WRITE
    );
}


Foam::IOobject Foam::gasDynamics::newIO
(
    const fvMesh& mesh,
    const word& name,
    bool write
)
{
    return IOobject
    (
        name,
        mesh.time().timeName(),
        mesh,
        IOobject::NO_READ,
        write ? IOobject::AUTO_WRITE : IOobject::NO_WRITE
    );
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::gasDynamics::checkField
(
    const volScalarField& f,
    const word& what
) const
{
    auto stop = [&](const word& where, label i, scalar v, const point& x)
    {
        FatalIOError
        (
            FUNCTION_NAME, __FILE__, __LINE__, f.objectPath(), -1
        )   << where.c_str() << " of " << f.objectPath() << " has the value "
            << v << (where == "internalField" ? " in cell " : " at face ")
            << i << " at " << x << nl
            << "    allowed: a finite " << what.c_str() << " > 0, "
            << gasLimits::rangeText().c_str() << exit(FatalIOError);
    };
    forAll(f, celli)
    {
        if (!gasLimits::inRange(f[celli]))
        {
            stop("internalField", celli, f[celli], mesh_.cellCentres()[celli]);
        }
    }
    forAll(f.boundaryField(), patchi)
    {
        const fvPatchScalarField& pf = f.boundaryField()[patchi];
        forAll(pf, facei)
        {
            if (!gasLimits::inRange(pf[facei]))
            {
                stop
                (
                    "boundaryField/" + pf.patch().name() + " value", facei,
                    pf[facei], pf.patch().Cf()[facei]
                );
            }
        }
    }
}


Foam::tmp<Foam::volScalarField> Foam::gasDynamics::readDensity() const
{
    // p first: rho = p/(R T) of values out of range would overflow
    checkField(p_, "pressure");

    IOobject rhoIO(readIO(mesh_, "rho"));
    if (rhoIO.typeHeaderOk<volScalarField>(true))
    {
        Info<< "Reading rho" << nl;
        auto trho = tmp<volScalarField>::New(rhoIO, mesh_);
        checkField(trho(), "density");
        return trho;
    }
    Info<< "Reading T (rho = p/(R T))" << nl;
    volScalarField T(readIO(mesh_, "T"), mesh_);
    checkField(T, "temperature");
    auto trho = tmp<volScalarField>::New
    (
        newIO(mesh_, "rho", true),
        mesh_,
        dimensionedScalar("zero", dimDensity, 0.0)
    );
    volScalarField& rho = trho.ref();
    rho.primitiveFieldRef() = p_.primitiveField()/(gas_.R()*T.primitiveField());
    forAll(rho.boundaryField(), patchi)
    {
        rho.boundaryFieldRef()[patchi] ==
            p_.boundaryField()[patchi]/(gas_.R()*T.boundaryField()[patchi]);
    }

    // The density p/(R T) must be in range too: name T, the field given
    forAll(rho, celli)
    {
        if (!gasLimits::inRange(rho[celli]))
        {
            FatalIOError
            (
                FUNCTION_NAME, __FILE__, __LINE__, T.objectPath(), -1
            )   << "internalField of " << T.objectPath() << " has the value "
                << T[celli] << " in cell " << celli << " at "
                << mesh_.cellCentres()[celli] << ": with p " << p_[celli]
                << " and R " << gas_.R() << " the density p/(R T) is "
                << rho[celli] << nl
                << "    allowed: a finite temperature > 0 that gives a"
                << " density " << gasLimits::rangeText().c_str()
                << exit(FatalIOError);
        }
    }
    forAll(rho.boundaryField(), patchi)
    {
        const fvPatchScalarField& rb = rho.boundaryField()[patchi];
        forAll(rb, facei)
        {
            if (!gasLimits::inRange(rb[facei]))
            {
                FatalIOError
                (
                    FUNCTION_NAME, __FILE__, __LINE__, T.objectPath(), -1
                )   << "boundaryField/" << rb.patch().name() << " value of "
                    << T.objectPath() << " has the value "
                    << T.boundaryField()[patchi][facei] << " at face "
                    << facei << ": the density p/(R T) there is "
                    << rb[facei] << nl
                    << "    allowed: a finite temperature > 0 that gives a"
                    << " density " << gasLimits::rangeText().c_str()
                    << exit(FatalIOError);
            }
        }
    }
    return trho;
}


void Foam::gasDynamics::checkInitial() const
{
    // p and rho (or T) are checked as they are read (readDensity); here the
    // velocity and what the three give together
    auto checkU = [&](const vector& u, const word& where, label i)
    {
        if (!gasLimits::velocityOk(u))
        {
            FatalIOError
            (
                FUNCTION_NAME, __FILE__, __LINE__, Uf_.objectPath(), -1
            )   << where.c_str() << " of " << Uf_.objectPath()
                << " has the value " << u
                << (where == "internalField" ? " in cell " : " at face ")
                << i << nl << "    allowed: a finite velocity with |U| <= "
                << gasLimits::maxValue << exit(FatalIOError);
        }
    };
    forAll(Uf_, celli)
    {
        checkU(Uf_[celli], "internalField", celli);
    }
    forAll(Uf_.boundaryField(), patchi)
    {
        const fvPatchVectorField& ub = Uf_.boundaryField()[patchi];
        forAll(ub, facei)
        {
            checkU
            (
                ub[facei], "boundaryField/" + ub.patch().name() + " value",
                facei
            );
        }
    }
    forAll(rho_, celli)
    {
        const string why = gasLimits::checkState
        (
            rho_[celli], Uf_[celli], p_[celli], gas_.gamma()
        );
        if (!why.empty())
        {
            FatalIOError
            (
                FUNCTION_NAME, __FILE__, __LINE__, p_.objectPath(), -1
            )   << "The initial state (internalField of p, U and rho or T)"
                << " in cell " << celli << " at "
                << mesh_.cellCentres()[celli] << ": " << why.c_str()
                << exit(FatalIOError);
        }
    }
}


void Foam::gasDynamics::fromFields()
{
    const auto& lat = view_.latticeOf();
    forAll(rho_, celli)
    {
        const label i = lat[celli];
        const vector& u = Uf_[celli];
        U_.q[0][i] = rho_[celli];
        U_.q[1][i] = rho_[celli]*u.x();
        U_.q[2][i] = rho_[celli]*u.y();
        U_.q[3][i] = rho_[celli]*u.z();
        U_.q[4][i] =
            gas_.totalEnergy(rho_[celli], u.x(), u.y(), u.z(), p_[celli]);
    }
}


void Foam::gasDynamics::toFields()
{
    const auto& lat = view_.latticeOf();
    scalarField& rho = rho_.primitiveFieldRef();
    vectorField& U = Uf_.primitiveFieldRef();
    scalarField& p = p_.primitiveFieldRef();
    vectorField& rhoU = rhoU_.primitiveFieldRef();
    scalarField& rhoE = rhoE_.primitiveFieldRef();
    forAll(rho, celli)
    {
        const label i = lat[celli];
        const double r = U_.q[0][i];
        rho[celli] = r;
        rhoU[celli] = vector(U_.q[1][i], U_.q[2][i], U_.q[3][i]);
        U[celli] = rhoU[celli]/r;
        rhoE[celli] = U_.q[4][i];
        p[celli] = gas_.pressure
        (
            r, U_.q[1][i], U_.q[2][i], U_.q[3][i], U_.q[4][i]
        );
    }
}


bool Foam::gasDynamics::exactRestart(bool read)
{
    rhoU_.writeOpt() = IOobject::AUTO_WRITE;
    rhoE_.writeOpt() = IOobject::AUTO_WRITE;
    if (!read)
    {
        return false;
    }
    IOobject uIO(readIO(mesh_, "rhoU"));
    IOobject eIO(readIO(mesh_, "rhoE"));
    if
    (
        !uIO.typeHeaderOk<volVectorField>(true)
     || !eIO.typeHeaderOk<volScalarField>(true)
    )
    {
        return false;
    }
    const volVectorField rhoU(uIO, mesh_);
    const volScalarField rhoE(eIO, mesh_);

    // Only a state that is the one p, U and rho describe (not a stale
    // rhoE beside a p edited since)
    const auto& lat = view_.latticeOf();
    scalar pMax = 0, uMax = 0, dp = 0, du = 0;
    forAll(rho_, celli)
    {
        const scalar r = rho_[celli];
        const vector& m = rhoU[celli];
        const scalar p = gas_.pressure(r, m.x(), m.y(), m.z(), rhoE[celli]);
        pMax = max(pMax, mag(p_[celli]));
        uMax = max(uMax, mag(Uf_[celli]));
        dp = max(dp, mag(p - p_[celli]));
        du = max(du, mag(m/r - Uf_[celli]));
    }
    reduce(pMax, maxOp<scalar>());
    reduce(uMax, maxOp<scalar>());
    reduce(dp, maxOp<scalar>());
    reduce(du, maxOp<scalar>());
    if (dp > 1e-10*pMax || du > 1e-10*max(uMax, VSMALL))
    {
        WarningInFunction
            << rhoU.objectPath() << " and " << rhoE.objectPath()
            << " differ from p, U and rho by " << dp << " Pa, " << du
            << " m/s: the state is taken from p, U and rho" << endl;
        return false;
    }
    forAll(rho_, celli)
    {
        const label i = lat[celli];
        U_.q[1][i] = rhoU[celli].x();
        U_.q[2][i] = rhoU[celli].y();
        U_.q[3][i] = rhoU[celli].z();
        U_.q[4][i] = rhoE[celli];
    }
    toFields();
    Info<< "Gas state from rho, rhoU and rhoE (exact restart)" << nl;
    return true;
}


void Foam::gasDynamics::updateDerived()
{
    phi_ = fvc::interpolate(rhoU_) & mesh_.Sf();
    rho_.correctBoundaryConditions();
    Uf_.correctBoundaryConditions();
    p_.correctBoundaryConditions();
    rhoU_.correctBoundaryConditions();
    rhoE_.correctBoundaryConditions();

    forAll(T_, celli)
    {
        T_[celli] = gas_.temperature(rho_[celli], p_[celli]);
        Mach_[celli] =
            mag(Uf_[celli])/gas_.soundSpeed(rho_[celli], p_[celli]);
    }
    T_.correctBoundaryConditions();
    Mach_.correctBoundaryConditions();

    const volScalarField magGrad(mag(fvc::grad(rho_)));
    const scalar maxGrad = max(gMax(magGrad.primitiveField()), VSMALL);
    schlieren_.primitiveFieldRef() =
        exp(-schlierenScale_*magGrad.primitiveField()/maxGrad);
    schlieren_.correctBoundaryConditions();
}


void Foam::gasDynamics::totals
(
    scalar& mass,
    vector& momentum,
    scalar& energy
) const
{
    const scalar V = view_.cellVolume();
    mass = 0;
    energy = 0;
    momentum = Zero;
    for (const label i : view_.latticeOf())
    {
        mass += U_.q[0][i];
        momentum += vector(U_.q[1][i], U_.q[2][i], U_.q[3][i]);
        energy += U_.q[4][i];
    }
    reduce(mass, sumOp<scalar>());
    reduce(momentum, sumOp<vector>());
    reduce(energy, sumOp<scalar>());
    mass *= V;
    momentum *= V;
    energy *= V;
}


void Foam::gasDynamics::crossed
(
    scalar& mass,
    vector& momentum,
    scalar& energy
) const
{
    mass = crossed_[0];
    momentum = vector(crossed_[1], crossed_[2], crossed_[3]);
    energy = crossed_[4];
    reduce(mass, sumOp<scalar>());
    reduce(momentum, sumOp<vector>());
    reduce(energy, sumOp<scalar>());
}


// ************************************************************************* //
