/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "pressureSystem.H"
#include "cartesianMesh.H"
#include "PstreamReduceOps.H"
#include <cmath>

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
}


double Foam::pressureSystem::gSum(double x)
{
    if (Pstream::parRun()) reduce(x, sumOp<double>());
    return x;
}


Foam::label Foam::pressureSystem::solve
(
    std::vector<double>& x,
    double tol,
    label maxIter,
    double& relResidual
) const
{
    const label n = size();
    r_.resize(n);
    z_.resize(n);
    p_.resize(n);

    double bNorm = 0;
    for (label i = 0; i < n; ++i) bNorm += source[i]*source[i];
    bNorm = std::sqrt(gSum(bNorm));
    if (bNorm == 0)
    {
        x.assign(n, 0.0);
        relResidual = 0;
        return 0;
    }

    multiply(x, Ap_);
    double rz = 0, rr = 0;
    for (label i = 0; i < n; ++i)
    {
        r_[i] = source[i] - Ap_[i];
        z_[i] = r_[i]/diag[i];
        p_[i] = z_[i];
        rz += r_[i]*z_[i];
        rr += r_[i]*r_[i];
    }
    rz = gSum(rz);
    rr = gSum(rr);

    label iter = 0;
    while (std::sqrt(rr) > tol*bNorm && iter < maxIter)
    {
        multiply(p_, Ap_);
        double pAp = 0;
        for (label i = 0; i < n; ++i) pAp += p_[i]*Ap_[i];
        pAp = gSum(pAp);
        if (!(pAp > 0) || !std::isfinite(pAp)) break;  // breakdown
        const double alpha = rz/pAp;
        double rzNew = 0;
        rr = 0;
        for (label i = 0; i < n; ++i)
        {
            x[i] += alpha*p_[i];
            r_[i] -= alpha*Ap_[i];
            z_[i] = r_[i]/diag[i];
            rzNew += r_[i]*z_[i];
            rr += r_[i]*r_[i];
        }
        rzNew = gSum(rzNew);
        rr = gSum(rr);
        const double beta = rzNew/rz;
        rz = rzNew;
        for (label i = 0; i < n; ++i) p_[i] = z_[i] + beta*p_[i];
        ++iter;
    }
    relResidual = std::sqrt(rr)/bNorm;
    return iter;
}


// ************************************************************************* //
