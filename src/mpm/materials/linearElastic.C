/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "linearElastic.H"
#include "addToRunTimeSelectionTable.H"

#include <cmath>

namespace Foam
{
    defineTypeNameAndDebug(linearElastic, 0);
    addToRunTimeSelectionTable(mpmMaterial, linearElastic, dictionary);
}


Foam::linearElastic::linearElastic(const word& name, const dictionary& dict)
:
    mpmMaterial(name, dict)
{}


void Foam::linearElastic::stress
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
        const symmTensor eps(symm(F[p]) - symmTensor::I);
        const scalar trEps = tr(eps);
        sigma[p] = lambda*trEps*symmTensor::I + 2*mu*eps;
        energyDensity[p] = mu*(eps && eps) + 0.5*lambda*trEps*trEps;
    }
}


Foam::scalar Foam::linearElastic::maxWaveSpeed
(
    const UList<tensor>& F,
    const UList<symmTensor>& sigma
) const
{
    // The stress increment of a velocity gradient L over dt is
    // (lambda + 2 mu) symm(L F) dt, acting on the current volume J V0: the
    // Kirchhoff modulus J sqrt(max stretch^2) (lambda + 2 mu)
    const scalar M = lambda_ + 2*mu_;
    scalar K = 0;
    forAll(F, p)
    {
        const scalar J = det(F[p]);
        K = max
        (
            K,
            J*(std::sqrt(maxStretchSqr(F[p]))*M + maxAbsEigen(sigma[p]))
        );
    }
    return std::sqrt(K/rho_);
}


// ************************************************************************* //
