/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "bsmsSeeding.H"
#include "dictionaryChecks.H"
#include "IStringStream.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(bsmsSeeding, 0);
    defineRunTimeSelectionTable(bsmsSeeding, dictionary);
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::bsmsSeeding> Foam::bsmsSeeding::New(const dictionary& dict)
{
    word selected;
    const auto cstr = dictionaryChecks::selectConstructor
    (
        dict, "seeding", *dictionaryConstructorTablePtr_, selected
    );
    return cstr(dict);
}


Foam::autoPtr<Foam::bsmsSeeding> Foam::bsmsSeeding::New(const word& name)
{
    dictionary dict;
    dict.add("seeding", name);
    return New(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bsmsSeeding::reserve(const label n) const
{
    if (dist_.size() != n)
    {
        dist_.setSize(n);
        dist_ = -1;
        order_.setSize(n);
    }
}


Foam::labelList Foam::bsmsSeeding::seeds
(
    const meshGraph& g,
    const labelUList& clusterOffsets,
    const labelUList& clusterNodes
) const
{
    reserve(g.nNodes());
    const label nClusters = clusterOffsets.size() - 1;
    labelList result(nClusters);
    for (label k = 0; k < nClusters; ++k)
    {
        const label b = clusterOffsets[k];
        const SubList<label> nodes
        (
            clusterNodes, clusterOffsets[k + 1] - b, b
        );
        result[k] = nodes.size() == 1 ? nodes[0] : seed(g, nodes);
    }
    return result;
}


// ************************************************************************* //
