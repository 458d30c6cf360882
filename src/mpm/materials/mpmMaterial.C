/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "mpmMaterial.H"
#include "dictionaryChecks.H"
#include "Switch.H"

#include <cmath>

namespace Foam
{
    defineTypeNameAndDebug(mpmMaterial, 0);
    defineRunTimeSelectionTable(mpmMaterial, dictionary);
}


Foam::mpmMaterial::mpmMaterial(const word& name, const dictionary& dict)
:
    name_(name),
    rho_(dictionaryChecks::getInRange(dict, "rho", 1e-30, 1e30)),
    E_(dictionaryChecks::getInRange(dict, "E", 0, 1e30)),
    nu_(0),
    lambda_(0),
    mu_(0),
    Fbar_(false)
{
    // nu = 0.5 is incompressible (lambda infinite), nu <= -1 makes the
    // shear modulus non-positive
    const string allowed("-1 < nu < 0.5");
    nu_ = dictionaryChecks::getAs<scalar>(dict, "nu", allowed);
    if (!(nu_ > -1 && nu_ < 0.5))
    {
        dictionaryChecks::badEntry(dict, "nu", Foam::name(nu_), allowed);
    }

    lambda_ = E_*nu_/((1 + nu_)*(1 - 2*nu_));
    mu_ = E_/(2*(1 + nu_));

    // A word (on, off, true, false, yes, no), not a number
    const string allowedFbar("on or off");
    const word fbar
    (
        dictionaryChecks::getAsOrDefault<word>(dict, "Fbar", "off", allowedFbar)
    );
    const Switch sw(fbar, true);
    if (!sw.valid())
    {
        dictionaryChecks::badEntry(dict, "Fbar", fbar, allowedFbar);
    }
    Fbar_ = bool(sw);
    if (Fbar_)
    {
        Info<< "    " << name_ << ": F-bar on" << endl;
    }
}


Foam::autoPtr<Foam::mpmMaterial> Foam::mpmMaterial::New
(
    const word& name,
    const dictionary& dict
)
{
    word selected;
    const auto cstr = dictionaryChecks::selectConstructor
    (
        dict, "type", *dictionaryConstructorTablePtr_, selected
    );
    Info<< "MPM material " << name << ": " << selected << endl;
    return cstr(name, dict);
}


Foam::scalar Foam::mpmMaterial::waveSpeed() const
{
    return std::sqrt((lambda_ + 2*mu_)/rho_);
}


void Foam::mpmMaterial::plasticStress
(
    UList<tensor>&,
    UList<scalar>&,
    UList<scalar>&,
    UList<symmTensor>&,
    UList<scalar>&,
    const bool
) const
{
    FatalErrorInFunction
        << "Material " << name_ << " (" << type() << ") is elastic: it has"
        << " no return mapping (plastic() is false)" << exit(FatalError);
}


void Foam::mpmMaterial::inverted
(
    const label p,
    const tensor& F,
    const scalar J
) const
{
    FatalErrorInFunction
        << "Material " << name_ << " (" << type() << "): particle " << p
        << " has J = det(F) = " << J << " (must be > 0: the particle"
        << " is inverted or collapsed)" << nl
        << "    F = " << F << nl
        << exit(FatalError);
    std::abort();   // not reached
}


// ************************************************************************* //
