/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "henckyJ2.H"
#include "henckyStrain.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"

#include <cmath>

namespace Foam
{
    defineTypeNameAndDebug(henckyJ2, 0);
    addToRunTimeSelectionTable(mpmMaterial, henckyJ2, dictionary);
}


Foam::henckyJ2::henckyJ2(const word& name, const dictionary& dict)
:
    mpmMaterial(name, dict),
    kappaP_(dictionaryChecks::getInRange(dict, "kappaP", 0, 1e30)),
    kappaR_(kappaP_),
    eta_(0)
{
    using namespace dictionaryChecks;

    const string allowedR
    (
        "a finite number >= 0 and <= kappaP (" + Foam::name(kappaP_)
      + "): the residual strength cannot exceed the peak"
    );
    kappaR_ = getAsOrDefault<scalar>(dict, "kappaR", kappaP_, allowedR);
    if (!(kappaR_ >= 0 && kappaR_ <= kappaP_))
    {
        badEntry(dict, "kappaR", Foam::name(kappaR_), allowedR);
    }

    const string allowedEta
    (
        "a finite number >= 0 and <= 1e6 (0: perfect plasticity)"
    );
    eta_ = getAsOrDefault<scalar>(dict, "eta", 0, allowedEta);
    if (!(eta_ >= 0 && eta_ <= 1e6))
    {
        badEntry(dict, "eta", Foam::name(eta_), allowedEta);
    }

    Info<< "    henckyJ2: kappa = (" << kappaP_ << " - " << kappaR_
        << ") exp(-" << eta_ << " epsilonP) + " << kappaR_ << " Pa" << endl;
}


Foam::scalar Foam::henckyJ2::plasticIncrement
(
    const scalar qTrial,
    const scalar epsQ
) const
{
    const scalar threeMu = 3*mu_;

    // Perfect plasticity: closed form
    if (!(eta_ > 0) || kappaP_ == kappaR_)
    {
        return (qTrial - kappaP_)/threeMu;
    }

    // g(d) = qTrial - 3 mu d - kappa(epsQ + d): concave, g(0) > 0,
    // g(qTrial/(3 mu)) = -kappa < 0: one root in the bracket.  Newton from
    // the perfectly plastic estimate (g >= 0 there: kappa decreases),
    // bisection where a step leaves the bracket
    scalar lo = 0;
    scalar hi = qTrial/threeMu;
    scalar d = (qTrial - kappa(epsQ))/threeMu;
    const scalar dk = kappaP_ - kappaR_;
    const scalar tol = 1e-14*kappaP_;
    for (label it = 0; it < 200; ++it)
    {
        const scalar e = std::exp(-eta_*(epsQ + d));
        const scalar g = qTrial - threeMu*d - (dk*e + kappaR_);
        if (mag(g) <= tol)
        {
            break;
        }
        if (g > 0) lo = d; else hi = d;
        const scalar dg = -threeMu + eta_*dk*e;
        scalar dn = dg < 0 ? d - g/dg : 0.5*(lo + hi);
        if (!(dn > lo && dn < hi))
        {
            dn = 0.5*(lo + hi);
        }
        if (hi - lo <= 1e-16*hi)
        {
            break;
        }
        d = dn;
    }
    return d;
}


void Foam::henckyJ2::stress
(
    const UList<tensor>& F,
    UList<symmTensor>& sigma,
    UList<scalar>& energyDensity
) const
{
    forAll(F, p)
    {
        const scalar J = det(F[p]);
        if (!(J > 0))
        {
            inverted(p, F[p], J);
        }
        vector eps;
        tensor Q;
        henckyStrain::principalStrains(F[p], eps, Q);
        sigma[p] = henckyStrain::fromPrincipal
        (
            henckyStrain::kirchhoff(eps, lambda_, mu_), Q
        )/J;
        energyDensity[p] = henckyStrain::energy(eps, lambda_, mu_);
    }
}


void Foam::henckyJ2::plasticStress
(
    UList<tensor>& F,
    UList<scalar>& epsilonP,
    UList<scalar>& Jp,
    UList<symmTensor>& sigma,
    UList<scalar>& energyDensity,
    const bool returnMap
) const
{
    const scalar lambda = lambda_;
    const scalar mu = mu_;
    // q = sqrt(3/2) |dev tau| = sqrt(3/2) 2 mu |dev eps|
    const scalar qPerDev = std::sqrt(6.0)*mu;

    forAll(F, p)
    {
        tensor& Fp = F[p];
        const scalar J = det(Fp);
        if (!(J > 0))
        {
            inverted(p, Fp, J);
        }

        vector eps;
        tensor Q;
        henckyStrain::principalStrains(Fp, eps, Q);

        if (returnMap)
        {
            const scalar epsV = eps.x() + eps.y() + eps.z();
            const vector e(eps - (epsV/3)*vector::one);
            const scalar qTrial = qPerDev*mag(e);

            // (2.3.4) f = q - kappa(eps_q^p): outside, the radial return
            if (qTrial > kappa(epsilonP[p]))
            {
                const scalar dEpsQ = plasticIncrement(qTrial, epsilonP[p]);
                const scalar scale = 1 - 3*mu*dEpsQ/qTrial;
                const vector epsNew((epsV/3)*vector::one + scale*e);
                Fp = henckyStrain::withPrincipalStrains(Fp, Q, eps, epsNew);
                epsilonP[p] += dEpsQ;
                eps = epsNew;
            }
        }

        // Kirchhoff stress per current volume det(F_e) Jp (Jp = 1 here
        // unless a cloud says otherwise)
        const scalar Jtot = std::exp(eps.x() + eps.y() + eps.z())*Jp[p];
        sigma[p] = henckyStrain::fromPrincipal
        (
            henckyStrain::kirchhoff(eps, lambda, mu), Q
        )/Jtot;
        energyDensity[p] = henckyStrain::energy(eps, lambda, mu);
    }
}


Foam::scalar Foam::henckyJ2::maxWaveSpeed
(
    const UList<tensor>& F,
    const UList<symmTensor>& sigma
) const
{
    // tau_i = 2 mu eps_i + lambda tr(eps): d tau_i/d eps_i = lambda + 2 mu
    scalar K = 0;
    forAll(F, p)
    {
        K = max(K, det(F[p])*maxAbsEigen(sigma[p]));
    }
    return std::sqrt((lambda_ + 2*mu_ + K)/rho_);
}


// ************************************************************************* //
