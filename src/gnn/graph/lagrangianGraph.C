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
    radius_(radius)
{
    if (!(radius > 0) || !std::isfinite(radius))
    {
        FatalErrorInFunction
            << "World-edge radius " << radius << " is not a finite number > 0"
            << exit(FatalError);
    }
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
    DynamicList<label> a, b;
    spatialHash(x_, radius_).pairs(body_, a, b);
    return meshGraph(x_, a, b);
}


// ************************************************************************* //
