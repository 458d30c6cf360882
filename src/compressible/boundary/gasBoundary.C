/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "gasBoundary.H"
#include "dictionaryChecks.H"
#include "gasLimits.H"

using namespace Foam::dictionaryChecks;

namespace Foam
{
    defineTypeNameAndDebug(gasBoundary, 0);
    defineRunTimeSelectionTable(gasBoundary, dictionary);
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::gasBoundary::primitiveState Foam::gasBoundary::readState
(
    const dictionary& dict,
    const primitiveState& deflt
)
{
    // Each value finite and in range (gasLimits.H), whether given here or
    // taken from the initial fields (which gasDynamics has checked)
    primitiveState s(deflt);
    const string allowedRange("a finite number > 0 " + gasLimits::rangeText());
    s.rho = getAsOrDefault<scalar>(dict, "rho", deflt.rho, allowedRange);
    if (!gasLimits::inRange(s.rho))
    {
        badEntry(dict, "rho", Foam::name(s.rho), allowedRange);
    }
    const string allowedU
    (
        "a vector (ux uy uz) with |U| <= " + Foam::name(gasLimits::maxValue)
    );
    s.U = getAsOrDefault<vector>(dict, "U", deflt.U, allowedU);
    if (!gasLimits::velocityOk(s.U))
    {
        badEntry(dict, "U", entryText(dict, "U"), allowedU);
    }
    s.p = getAsOrDefault<scalar>(dict, "p", deflt.p, allowedRange);
    if (!gasLimits::inRange(s.p))
    {
        badEntry(dict, "p", Foam::name(s.p), allowedRange);
    }
    return s;
}


void Foam::gasBoundary::conserved(const primitiveState& s, double q[5]) const
{
    q[0] = s.rho;
    q[1] = s.rho*s.U.x();
    q[2] = s.rho*s.U.y();
    q[3] = s.rho*s.U.z();
    q[4] = gas_.totalEnergy(s.rho, s.U.x(), s.U.y(), s.U.z(), s.p);
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::gasBoundary> Foam::gasBoundary::New
(
    const word& patchName,
    const word& patchType,
    const dictionary& boundaries,
    const idealGas& gas,
    const primitiveState& initial
)
{
    const entry* e = boundaries.findEntry(patchName, keyType::REGEX);

    word type;
    dictionary dict;
    if (e)
    {
        if (!e->isDict())
        {
            badEntry
            (
                boundaries, patchName, entryText(boundaries, patchName),
                "a sub-dictionary with 'type' (wall, inlet, outlet, periodic)"
            );
        }
        dict = e->dict();
    }
    else if
    (
        patchType == "wall" || patchType == "symmetryPlane"
     || patchType == "symmetry"
    )
    {
        dict.add("type", "wall");
    }
    else if (patchType == "cyclic")
    {
        dict.add("type", "periodic");
    }
    else
    {
        OStringStream allowed;
        allowed << "an entry " << patchName << " { type <t>; } with <t> one of "
            << dictionaryConstructorTablePtr_->sortedToc()
            << " (patches of type wall, symmetryPlane, symmetry and cyclic"
            << " need none)";
        missingEntry(boundaries, patchName, allowed.str());
    }
    dict.name() = boundaries.name() + '/' + patchName;

    word name;
    auto ctor = selectConstructor
    (
        dict, "type", *dictionaryConstructorTablePtr_, name
    );
    return autoPtr<gasBoundary>(ctor(patchName, dict, gas, initial));
}


// ************************************************************************* //
