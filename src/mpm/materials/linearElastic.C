/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "linearElastic.H"
#include "addToRunTimeSelectionTable.H"

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


// ************************************************************************* //
