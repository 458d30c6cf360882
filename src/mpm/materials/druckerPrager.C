/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "druckerPrager.H"
#include "henckyStrain.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

#include <cmath>

namespace Foam
{
    defineTypeNameAndDebug(druckerPrager, 0);
    addToRunTimeSelectionTable(mpmMaterial, druckerPrager, dictionary);
}


Foam::druckerPrager::druckerPrager(const word& name, const dictionary& dict)
:
    mpmMaterial(name, dict),
    phi_(0),
    psi_(0),
    c_(0),
    M_(0),
    Mpsi_(0),
    k_(0)
{
    using namespace dictionaryChecks;

    const string allowedPhi("an angle in degrees, 0 < frictionAngle < 90");
    phi_ = getAs<scalar>(dict, "frictionAngle", allowedPhi);
    if (!(phi_ > 0 && phi_ < 90))
    {
        badEntry(dict, "frictionAngle", Foam::name(phi_), allowedPhi);
    }

    const string allowedPsi
    (
        "an angle in degrees, 0 <= dilatancyAngle <= frictionAngle ("
      + Foam::name(phi_) + ")"
    );
    psi_ = getAsOrDefault<scalar>(dict, "dilatancyAngle", 0, allowedPsi);
    if (!(psi_ >= 0 && psi_ <= phi_))
    {
        badEntry(dict, "dilatancyAngle", Foam::name(psi_), allowedPsi);
    }

    const string allowedC("a finite number >= 0 and <= 1e30 [Pa]");
    c_ = getAsOrDefault<scalar>(dict, "cohesion", 0, allowedC);
    if (!(c_ >= 0 && c_ <= 1e30))
    {
        badEntry(dict, "cohesion", Foam::name(c_), allowedC);
    }

    const scalar deg = constant::mathematical::pi/180;
    const scalar sPhi = std::sin(phi_*deg);
    const scalar sPsi = std::sin(psi_*deg);
    M_ = 6*sPhi/(3 - sPhi);
    Mpsi_ = 6*sPsi/(3 - sPsi);
    k_ = 6*c_*std::cos(phi_*deg)/(3 - sPhi);

    Info<< "    druckerPrager: q <= " << M_ << " p + " << k_
        << " Pa, plastic potential slope " << Mpsi_ << endl;
}


void Foam::druckerPrager::stress
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


void Foam::druckerPrager::plasticStress
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
    const scalar K = lambda + 2*mu/3;
    const scalar qPerDev = std::sqrt(6.0)*mu;
    const scalar denom = 3*mu + K*M_*Mpsi_;

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
            const scalar pTrial = -K*epsV;
            const scalar f = qTrial - M_*pTrial - k_;

            if (f > 0)
            {
                const scalar dGamma = f/denom;
                vector epsNew;
                if (3*mu*dGamma < qTrial)
                {
                    // Cone: q = q_tr - 3 mu dGamma along the trial
                    // deviator, p = p_tr + K M_psi dGamma
                    const scalar scale = 1 - 3*mu*dGamma/qTrial;
                    const scalar epsVNew = epsV - Mpsi_*dGamma;
                    epsNew = (epsVNew/3)*vector::one + scale*e;
                    epsilonP[p] += dGamma;
                }
                else
                {
                    // Apex: q = 0, p = -k/M
                    const scalar epsVNew = k_/(M_*K);
                    epsNew = (epsVNew/3)*vector::one;
                    epsilonP[p] += std::sqrt(2.0/3.0)*mag(e);
                }
                Fp = henckyStrain::withPrincipalStrains(Fp, Q, eps, epsNew);
                // det F_e changes by exp(trace change): F_p takes it
                Jp[p] *= std::exp
                (
                    epsV - (epsNew.x() + epsNew.y() + epsNew.z())
                );
                eps = epsNew;
            }
        }

        const scalar Jtot = std::exp(eps.x() + eps.y() + eps.z())*Jp[p];
        sigma[p] = henckyStrain::fromPrincipal
        (
            henckyStrain::kirchhoff(eps, lambda, mu), Q
        )/Jtot;
        energyDensity[p] = henckyStrain::energy(eps, lambda, mu);
    }
}


Foam::scalar Foam::druckerPrager::maxWaveSpeed
(
    const UList<tensor>& F,
    const UList<symmTensor>& sigma
) const
{
    scalar Ks = 0;
    forAll(F, p)
    {
        Ks = max(Ks, det(F[p])*maxAbsEigen(sigma[p]));
    }
    return std::sqrt((lambda_ + 2*mu_ + Ks)/rho_);
}


// ************************************************************************* //
