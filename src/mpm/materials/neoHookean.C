/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "neoHookean.H"
#include "addToRunTimeSelectionTable.H"

#include <cmath>

namespace Foam
{
    defineTypeNameAndDebug(neoHookean, 0);
    addToRunTimeSelectionTable(mpmMaterial, neoHookean, dictionary);
}


Foam::neoHookean::neoHookean(const word& name, const dictionary& dict)
:
    mpmMaterial(name, dict)
{}


void Foam::neoHookean::stress
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

        // Near F = I the energy is O(|H|^2), H = F - I, while
        // tr(F^T F) - 3 and ln J are O(|H|) and cancel: formed from F and J
        // directly, their absolute rounding of ~1e-16 becomes a large
        // relative error at small strains.  Written in H, with
        // J - 1 = I1 + I2 + I3 (the invariants of H), it stays relative
        const tensor H(Fp - tensor::I);
        const scalar trH = tr(H);
        const scalar Jm1 = jacobianMinusOne(H);
        const scalar lnJ =
            (J > 0.5 && J < 2) ? std::log1p(Jm1) : std::log(J);

        // B - I = F F^T - I, B the left Cauchy-Green tensor
        const symmTensor BmI(twoSymm(H) + symm(H & H.T()));

        sigma[p] = (mu*BmI + lambda*lnJ*symmTensor::I)/J;

        // mu/2 (tr(F^T F) - 3) - mu ln J = mu/2 |H|^2 + mu (tr H - ln J)
        energyDensity[p] =
            0.5*mu*magSqr(H) + mu*(trH - lnJ) + 0.5*lambda*lnJ*lnJ;
    }
}


Foam::scalar Foam::neoHookean::maxWaveSpeed
(
    const UList<tensor>& F,
    const UList<symmTensor>& sigma
) const
{
    // Kirchhoff stress tau_i = mu (l_i^2 - 1) + lambda ln J per principal
    // stretch l_i: d tau_i/d ln l_i = 2 mu l_i^2 + lambda
    scalar K = 0;
    forAll(F, p)
    {
        const scalar J = det(F[p]);
        K = max
        (
            K,
            2*mu_*maxStretchSqr(F[p]) + lambda_ + J*maxAbsEigen(sigma[p])
        );
    }
    return std::sqrt(K/rho_);
}


// ************************************************************************* //
