/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "mpmGrid.H"

Foam::mpmGrid::mpmGrid(const label nVertices)
:
    mass(nVertices, Zero),
    absMass(nVertices, Zero),
    velocity(nVertices, Zero),
    force(nVertices, Zero),
    newVelocity(nVertices, Zero),
    isActive(nVertices, false)
{}


void Foam::mpmGrid::activate(const kernelWeights& kw)
{
    for (const label i : active)
    {
        mass[i] = 0;
        absMass[i] = 0;
        velocity[i] = Zero;
        force[i] = Zero;
        newVelocity[i] = Zero;
        isActive[i] = false;
    }
    active.clear();
    for (const label i : kw.vertex)
    {
        if (!isActive[i])
        {
            isActive[i] = true;
            active.append(i);
        }
    }
}


// ************************************************************************* //
