/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "mpmParticles.H"
#include "error.H"
#include "SubList.H"

void Foam::mpmParticles::clear()
{
    x.clear(); v.clear(); B.clear(); F.clear(); m.clear(); V0.clear();
    V.clear(); sigma.clear(); psi.clear(); epsilonP.clear(); Jp.clear();
    material.clear(); cell.clear(); id.clear(); fContact.clear();
}


void Foam::mpmParticles::append
(
    const vector& position,
    const vector& velocity,
    const tensor& defGrad,
    const scalar mass,
    const scalar referenceVolume,
    const label materialIndex,
    const label celli
)
{
    x.append(position);
    v.append(velocity);
    B.append(tensor::zero);
    F.append(defGrad);
    m.append(mass);
    V0.append(referenceVolume);
    V.append(det(defGrad)*referenceVolume);
    sigma.append(symmTensor::zero);
    psi.append(0);
    epsilonP.append(0);
    Jp.append(1);
    material.append(materialIndex);
    cell.append(celli);
    id.append(id.size());
    fContact.append(vector::zero);
}


void Foam::mpmParticles::appendFrom(const mpmParticles& Q, const label p)
{
    x.append(Q.x[p]); v.append(Q.v[p]); B.append(Q.B[p]); F.append(Q.F[p]);
    m.append(Q.m[p]); V0.append(Q.V0[p]); V.append(Q.V[p]);
    sigma.append(Q.sigma[p]); psi.append(Q.psi[p]);
    epsilonP.append(Q.epsilonP[p]); Jp.append(Q.Jp[p]);
    material.append(Q.material[p]); cell.append(Q.cell[p]); id.append(Q.id[p]);
    fContact.append(Q.fContact[p]);
}


namespace
{
template<class T>
void permute(Foam::DynamicList<T>& a, const Foam::labelList& order)
{
    Foam::List<T> b(a.size());
    forAll(order, i) b[i] = a[order[i]];
    forAll(order, i) a[i] = b[i];
}
}


Foam::labelList Foam::mpmParticles::sortByMaterial(const label nMaterials)
{
    labelList start(nMaterials + 1, Zero);
    for (const label k : material)
    {
        if (k < 0 || k >= nMaterials)
        {
            FatalErrorInFunction
                << "Particle material index " << k << " is not one of the "
                << nMaterials << " materials" << exit(FatalError);
        }
        ++start[k + 1];
    }
    for (label k = 0; k < nMaterials; ++k) start[k + 1] += start[k];

    labelList order(size());
    labelList fill(SubList<label>(start, nMaterials));
    forAll(material, p) order[fill[material[p]]++] = p;

    permute(x, order); permute(v, order); permute(B, order); permute(F, order);
    permute(m, order); permute(V0, order); permute(V, order);
    permute(sigma, order); permute(psi, order); permute(epsilonP, order);
    permute(Jp, order); permute(material, order);
    permute(cell, order); permute(id, order);
    permute(fContact, order);
    return start;
}


namespace
{
template<class T>
void compact(Foam::DynamicList<T>& a, const Foam::UList<bool>& marked)
{
    Foam::label n = 0;
    forAll(a, i)
    {
        if (!marked[i]) a[n++] = a[i];
    }
    a.setSize(n);
}
}


void Foam::mpmParticles::remove(const UList<bool>& marked)
{
    compact(x, marked); compact(v, marked); compact(B, marked);
    compact(F, marked); compact(m, marked); compact(V0, marked);
    compact(V, marked); compact(sigma, marked); compact(psi, marked);
    compact(epsilonP, marked); compact(Jp, marked);
    compact(material, marked); compact(cell, marked); compact(id, marked);
    compact(fContact, marked);
}


// ************************************************************************* //
