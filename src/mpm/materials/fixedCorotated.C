/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "fixedCorotated.H"
#include "addToRunTimeSelectionTable.H"

#include <cmath>

namespace Foam
{
    defineTypeNameAndDebug(fixedCorotated, 0);
    addToRunTimeSelectionTable(mpmMaterial, fixedCorotated, dictionary);
}


Foam::fixedCorotated::fixedCorotated(const word& name, const dictionary& dict)
:
    mpmMaterial(name, dict)
{}


Foam::tensor Foam::fixedCorotated::polarRotation(const tensor& F)
{
    const scalar tol = 1e-14;
    const label maxIter = 100;

    tensor R(F);
    scalar prevDelta = GREAT;
    for (label it = 0; it < maxIter; ++it)
    {
        // R^{-T} = cof(R)/det(R)
        const tensor RinvT(cof(R)/det(R));

        // Frobenius-norm scaling: balances the largest and smallest
        // singular values, so that the iteration converges in a few steps
        // even for strongly stretched F
        const scalar zeta = std::sqrt(mag(RinvT)/mag(R));

        const tensor Rn(0.5*(zeta*R + RinvT/zeta));
        const scalar delta = mag(Rn - R);
        R = Rn;

        if (delta <= tol*mag(R))
        {
            break;
        }
        // Quadratic convergence ended at round-off: no further gain
        if (delta < 1e-6*mag(R) && delta >= prevDelta)
        {
            break;
        }
        prevDelta = delta;
    }
    return R;
}


void Foam::fixedCorotated::stress
(
    const UList<tensor>& F,
    UList<symmTensor>& sigma,
    UList<scalar>& energyDensity
) const
{
    const scalar lambda = lambda_;
    const scalar mu = mu_;
    forAll(F, p)
    {
        const tensor& Fp = F[p];
        const scalar J = det(Fp);
        if (!(J > 0))
        {
            inverted(p, Fp, J);
        }

        // J - 1 = I1 + I2 + I3 (the invariants of H = F - I): no
        // cancellation at small strains, unlike det(F) - 1
        const tensor H(Fp - tensor::I);
        const scalar Jm1 = jacobianMinusOne(H);

        const tensor FmR(Fp - polarRotation(Fp));

        // (F - R) F^T = F F^T - R S R^T is symmetric
        sigma[p] =
            (2*mu*symm(FmR & Fp.T()) + lambda*J*Jm1*symmTensor::I)/J;
        energyDensity[p] = mu*magSqr(FmR) + 0.5*lambda*sqr(Jm1);
    }
}


Foam::scalar Foam::fixedCorotated::maxWaveSpeed
(
    const UList<tensor>& F,
    const UList<symmTensor>& sigma
) const
{
    // Kirchhoff stress tau_i = 2 mu (l_i - 1) l_i + lambda J (J - 1) per
    // principal stretch l_i: d tau_i/d ln l_i = 2 mu (2 l_i^2 - l_i)
    // + lambda J (2 J - 1), growing with J^2 when stretched
    scalar K = 0;
    forAll(F, p)
    {
        const scalar J = det(F[p]);
        const scalar l2 = maxStretchSqr(F[p]);
        K = max
        (
            K,
            2*mu_*max(2*l2 - std::sqrt(l2), scalar(0))
          + lambda_*J*mag(2*J - 1) + J*maxAbsEigen(sigma[p])
        );
    }
    return std::sqrt(K/rho_);
}


// ************************************************************************* //
