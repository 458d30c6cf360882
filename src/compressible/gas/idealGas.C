/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "idealGas.H"
#include "dictionaryChecks.H"
#include "thermodynamicConstants.H"
#include "gasLimits.H"

using namespace Foam::dictionaryChecks;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// gamma - 1 >= 1e-6 keeps p/(gamma - 1) representable; gamma <= 100 keeps
// the sound speed, and so the time step, of states in range reasonable
inline bool gammaOk(const Foam::scalar g)
{
    return std::isfinite(g) && g >= Foam::gasLimits::minGamma
        && g <= Foam::gasLimits::maxGamma;
}

inline Foam::string gammaAllowed()
{
    return "a number > 1 (1 + 1e-06 <= gamma <= 100)";
}

inline Foam::string RAllowed()
{
    return "a number > 0 " + Foam::gasLimits::rangeText();
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::idealGas::idealGas(scalar gamma, scalar R)
:
    gamma_(gamma),
    R_(R)
{}


Foam::idealGas::idealGas(const dictionary& dict)
:
    gamma_(1.4),
    R_(287)
{
    const bool direct = dict.found("gamma") || dict.found("R");
    if (direct)
    {
        gamma_ = getAs<scalar>(dict, "gamma", gammaAllowed());
        R_ = getAs<scalar>(dict, "R", RAllowed());
        if (!gammaOk(gamma_))
        {
            badEntry(dict, "gamma", Foam::name(gamma_), gammaAllowed());
        }
        if (!gasLimits::inRange(R_))
        {
            badEntry(dict, "R", Foam::name(R_), RAllowed());
        }
        return;
    }

    if (!dict.isDict("mixture"))
    {
        missingEntry
        (
            dict,
            "mixture",
            "either 'gamma' and 'R', or a rhoCentralFoam-style 'mixture'"
            " with specie/molWeight and thermodynamics/Cp (or Cv)"
        );
    }
    const dictionary& mix = dict.subDict("mixture");
    if (!mix.isDict("specie") || !mix.isDict("thermodynamics"))
    {
        missingEntry
        (
            mix,
            mix.isDict("specie") ? "thermodynamics" : "specie",
            "sub-dictionaries specie (molWeight) and thermodynamics (Cp or Cv)"
        );
    }
    const dictionary& spec = mix.subDict("specie");
    const dictionary& thermo = mix.subDict("thermodynamics");

    const scalar W = getPositive(spec, "molWeight");
    R_ = constant::thermodynamic::RR/W;
    if (!gasLimits::inRange(R_))
    {
        badEntry
        (
            spec, "molWeight", Foam::name(W),
            "a molWeight that gives R = RR/molWeight "
          + gasLimits::rangeText() + " (here R = " + Foam::name(R_) + ")"
        );
    }

    scalar cv = 0;
    if (thermo.found("Cp"))
    {
        const scalar cp = getPositive(thermo, "Cp");
        cv = cp - R_;
        if (!(cv > 0))
        {
            badEntry
            (
                thermo,
                "Cp",
                Foam::name(cp),
                "Cp > R = RR/molWeight = " + Foam::name(R_)
              + " (gamma = Cp/(Cp - R) must be > 1)"
            );
        }
    }
    else if (thermo.found("Cv"))
    {
        cv = getPositive(thermo, "Cv");
    }
    else
    {
        missingEntry
        (
            thermo, "Cp",
            "Cp > R = RR/molWeight = " + Foam::name(R_)
          + ", or else an entry Cv > 0"
        );
    }
    gamma_ = (cv + R_)/cv;
    if (!gammaOk(gamma_))
    {
        // Cp (or Cv) so large against R that gamma rounds to 1, or so
        // close to R that gamma is huge: name the entry and both inputs
        const word key(thermo.found("Cp") ? "Cp" : "Cv");
        badEntry
        (
            thermo, key, entryText(thermo, key),
            "with molWeight " + Foam::name(W) + " (R = RR/molWeight = "
          + Foam::name(R_) + "): a value that gives gamma = "
          + (key == "Cp" ? "Cp/(Cp - R)" : "(Cv + R)/Cv") + " "
          + gammaAllowed() + "; here gamma = " + Foam::name(gamma_)
        );
    }
}


Foam::idealGas::idealGas(const Time& runTime)
:
    idealGas
    (
        IOdictionary
        (
            IOobject
            (
                "thermophysicalProperties",
                runTime.constant(),
                runTime,
                IOobject::MUST_READ,
                IOobject::NO_WRITE,
                false
            )
        )
    )
{}


// ************************************************************************* //
