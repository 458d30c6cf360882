/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "lagrangianGraph.H"
#include "spatialHash.H"

#include <cmath>

// * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * * //

const Foam::Enum<Foam::lagrangianGraph::nodeKind>
Foam::lagrangianGraph::nodeKindNames
({
    { nodeKind::free, "free" },
    { nodeKind::actuator, "actuator" },
    { nodeKind::fixed, "fixed" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::lagrangianGraph::checkedRadius(const scalar radius)
{
    if (!(radius > 0) || !std::isfinite(radius))
    {
        FatalErrorInFunction
            << "World-edge radius " << radius << " is not a finite number > 0"
            << exit(FatalError);
    }
    return radius;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::lagrangianGraph::lagrangianGraph
(
    const meshGraph& reference,
    const List<nodeKind>& kind,
    const scalar radius
)
:
    mesh_(reference),
    body_(reference.nNodes()),
    nBodies_(0),
    kind_(kind),
    x_(reference.positions()),
    xPrev_(reference.positions()),
    radius_(checkedRadius(radius)),
    hash_(radius_)
{
    if (kind.size() != reference.nNodes())
    {
        FatalErrorInFunction
            << kind.size() << " node kinds for " << reference.nNodes()
            << " nodes" << exit(FatalError);
    }
    nBodies_ = mesh_.clusterOf(body_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::vectorField> Foam::lagrangianGraph::velocity
(
    const scalar dt
) const
{
    if (!(dt > 0))
    {
        FatalErrorInFunction
            << "Model step " << dt << " is not > 0" << exit(FatalError);
    }
    return (x_ - xPrev_)/dt;
}


void Foam::lagrangianGraph::move(const pointField& x)
{
    if (x.size() != nNodes())
    {
        FatalErrorInFunction
            << x.size() << " world positions for " << nNodes() << " nodes"
            << exit(FatalError);
    }
    xPrev_.transfer(x_);
    x_ = x;
}


Foam::meshGraph Foam::lagrangianGraph::worldEdges() const
{
    // The hash and the pair lists keep their memory from step to step
    hash_.build(x_);
    a_.clear();
    b_.clear();
    hash_.pairs(body_, a_, b_);
    return meshGraph(x_, a_, b_);
}


// ************************************************************************* //
