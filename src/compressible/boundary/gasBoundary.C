/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "gasBoundary.H"
#include "dictionaryChecks.H"

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
    primitiveState s(deflt);
    s.rho = getPositive(dict, "rho", deflt.rho);
    s.U = getAsOrDefault<vector>(dict, "U", deflt.U, "a vector (ux uy uz)");
    s.p = getPositive(dict, "p", deflt.p);
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
