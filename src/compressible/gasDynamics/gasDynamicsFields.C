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

Foam::tmp<Foam::volScalarField> Foam::gasDynamics::readDensity() const
{
    IOobject rhoIO(readIO(mesh_, "rho"));
    if (rhoIO.typeHeaderOk<volScalarField>(true))
    {
        Info<< "Reading rho" << nl;
        return tmp<volScalarField>::New(rhoIO, mesh_);
    }
    Info<< "Reading T (rho = p/(R T))" << nl;
    volScalarField T(readIO(mesh_, "T"), mesh_);
    forAll(T, celli)
    {
        if (!(T[celli] > 0) || !std::isfinite(T[celli]))
        {
            FatalIOError
            (
                FUNCTION_NAME, __FILE__, __LINE__, T.objectPath(), -1
            )   << "internalField of " << T.objectPath() << " has the value "
                << T[celli] << " in cell " << celli << " at "
                << mesh_.cellCentres()[celli] << nl
                << "    allowed: a finite temperature > 0"
                << exit(FatalIOError);
        }
    }
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
    return trho;
}


void Foam::gasDynamics::checkInitial() const
{
    auto check = [&](const volScalarField& f, const char* what)
    {
        forAll(f, celli)
        {
            if (!(f[celli] > 0) || !std::isfinite(f[celli]))
            {
                FatalIOError
                (
                    FUNCTION_NAME, __FILE__, __LINE__, f.objectPath(), -1
                )   << "internalField of " << f.objectPath()
                    << " has the value " << f[celli] << " in cell "
                    << celli << " at " << mesh_.cellCentres()[celli] << nl
                    << "    allowed: a finite " << what << " > 0"
                    << exit(FatalIOError);
            }
        }
    };
    check(p_, "pressure");
    check(rho_, "density");
    forAll(Uf_, celli)
    {
        if (!std::isfinite(mag(Uf_[celli])))
        {
            FatalIOError
            (
                FUNCTION_NAME, __FILE__, __LINE__, Uf_.objectPath(), -1
            )   << "internalField of " << Uf_.objectPath() << " is not finite"
                << " in cell " << celli << exit(FatalIOError);
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
    mass *= V;
    momentum *= V;
    energy *= V;
}


// ************************************************************************* //
