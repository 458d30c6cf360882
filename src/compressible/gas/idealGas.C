/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "idealGas.H"
#include "dictionaryChecks.H"
#include "thermodynamicConstants.H"

using namespace Foam::dictionaryChecks;

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
        gamma_ = getAs<scalar>(dict, "gamma", "a number > 1");
        R_ = getAs<scalar>(dict, "R", "a number > 0");
        if (!(gamma_ > 1) || !std::isfinite(gamma_))
        {
            badEntry(dict, "gamma", Foam::name(gamma_), "a number > 1");
        }
        if (!(R_ > 0) || !std::isfinite(R_))
        {
            badEntry(dict, "R", Foam::name(R_), "a number > 0");
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
    else
    {
        cv = getPositive(thermo, "Cv");
    }
    gamma_ = (cv + R_)/cv;
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
