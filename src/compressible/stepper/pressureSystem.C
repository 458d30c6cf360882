/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "pressureSystem.H"
#include "cartesianMesh.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::pressureSystem::reset(label n)
{
    diag.assign(n, 0.0);
    source.assign(n, 0.0);
    owner.clear();
    neighbour.clear();
    coeff.clear();
    remoteOwner.clear();
    remoteSlot.clear();
    remoteCoeff.clear();
    blocks.clear();
}


void Foam::pressureSystem::multiply
(
    const std::vector<double>& x,
    std::vector<double>& y
) const
{
    const label n = size();
    y.resize(n);
    for (label i = 0; i < n; ++i) y[i] = diag[i]*x[i];
    const label nf = label(coeff.size());
    for (label f = 0; f < nf; ++f)
    {
        const label i = owner[f], j = neighbour[f];
        y[i] -= coeff[f]*x[j];
        y[j] -= coeff[f]*x[i];
    }
    if (mesh && Pstream::parRun())
    {
        mine_.resize(slotUnknown.size());
        for (size_t j = 0; j < slotUnknown.size(); ++j)
        {
            mine_[j] = x[slotUnknown[j]];
        }
        mesh->exchangeSlots(mine_, theirs_);
        for (size_t f = 0; f < remoteCoeff.size(); ++f)
        {
            y[remoteOwner[f]] -= remoteCoeff[f]*theirs_[remoteSlot[f]];
        }
    }
    for (const block* b : blocks) b->addProduct(x, y);
}


Foam::label Foam::pressureSystem::solve
(
    std::vector<double>& x,
    double tol,
    label maxIter,
    double& relResidual
) const
{
    return cg_.solve
    (
        [this](const std::vector<double>& u, std::vector<double>& y)
        {
            multiply(u, y);
        },
        diag, source, x, tol, maxIter, relResidual
    );
}


// ************************************************************************* //
