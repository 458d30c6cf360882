/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "jacobiPCG.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"
#include <cmath>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

double Foam::jacobiPCG::gSum(double x)
{
    if (Pstream::parRun()) reduce(x, sumOp<double>());
    return x;
}


Foam::label Foam::jacobiPCG::solve
(
    const product& A,
    const std::vector<double>& diag,
    const std::vector<double>& b,
    std::vector<double>& x,
    double tol,
    label maxIter,
    double& relResidual
) const
{
    const label n = label(b.size());
    r_.resize(n);
    z_.resize(n);
    p_.resize(n);

    double bNorm = 0;
    for (label i = 0; i < n; ++i) bNorm += b[i]*b[i];
    bNorm = std::sqrt(gSum(bNorm));
    if (bNorm == 0)
    {
        x.assign(n, 0.0);
        relResidual = 0;
        return 0;
    }

    A(x, Ap_);
    double rz = 0, rr = 0;
    for (label i = 0; i < n; ++i)
    {
        r_[i] = b[i] - Ap_[i];
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
        A(p_, Ap_);
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
