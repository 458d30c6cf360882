/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "mpmCloudIO.H"
#include "passiveParticleCloud.H"
#include "IOField.H"
#include "Time.H"

namespace
{
using namespace Foam;

IOobject fieldIO
(
    const polyMesh& mesh,
    const word& cloudName,
    const word& name,
    const IOobject::readOption r
)
{
    return IOobject
    (
        name,
        mesh.time().timeName(),
        cloud::prefix/cloudName,
        mesh,
        r,
        IOobject::NO_WRITE,
        false
    );
}

template<class T>
void writeField
(
    const polyMesh& mesh,
    const word& cloudName,
    const word& name,
    const UList<T>& values
)
{
    IOField<T> f(fieldIO(mesh, cloudName, name, IOobject::NO_READ), values.size());
    forAll(values, i) f[i] = values[i];
    f.write();
}

template<class T>
void readField
(
    const polyMesh& mesh,
    const word& cloudName,
    const word& name,
    const label n,
    DynamicList<T>& values
)
{
    IOField<T> f(fieldIO(mesh, cloudName, name, IOobject::MUST_READ));
    if (f.size() != n)
    {
        FatalErrorInFunction
            << "File " << f.objectPath() << ": field " << name
            << " of cloud " << cloudName << " has "
            << f.size() << " values for " << n << " particles"
            << exit(FatalError);
    }
    values.setSize(n);
    forAll(f, i) values[i] = f[i];
}

//- readField, or every value \c deflt when the file is absent (a cloud
//  written before the field existed)
template<class T>
void readFieldOrDefault
(
    const polyMesh& mesh,
    const word& cloudName,
    const word& name,
    const label n,
    const T& deflt,
    DynamicList<T>& values
)
{
    IOobject io(fieldIO(mesh, cloudName, name, IOobject::MUST_READ));
    if (io.typeHeaderOk<IOField<T>>(false))
    {
        readField(mesh, cloudName, name, n, values);
    }
    else
    {
        values.setSize(n);
        forAll(values, i) values[i] = deflt;
    }
}

} // End anonymous namespace


void Foam::mpmCloudIO::write
(
    const polyMesh& mesh,
    const word& cloudName,
    const mpmParticles& P
)
{
    passiveParticleCloud cloud(mesh, cloudName, IDLList<passiveParticle>());
    forAll(P.x, p)
    {
        cloud.addParticle(new passiveParticle(mesh, P.x[p], P.cell[p]));
    }
    cloud.write();

    writeField(mesh, cloudName, "U", P.v);
    writeField(mesh, cloudName, "F", P.F);
    writeField(mesh, cloudName, "B", P.B);
    writeField(mesh, cloudName, "sigma", P.sigma);
    writeField(mesh, cloudName, "psi", P.psi);
    writeField(mesh, cloudName, "volume", P.V);
    writeField(mesh, cloudName, "V0", P.V0);
    writeField(mesh, cloudName, "mass", P.m);
    writeField(mesh, cloudName, "material", P.material);
    writeField(mesh, cloudName, "epsilonP", P.epsilonP);
    writeField(mesh, cloudName, "Jp", P.Jp);
}


bool Foam::mpmCloudIO::read
(
    const polyMesh& mesh,
    const word& cloudName,
    mpmParticles& P
)
{
    P.clear();
    IOobject probe
    (
        fieldIO(mesh, cloudName, "U", IOobject::MUST_READ)
    );
    if (!probe.typeHeaderOk<IOField<vector>>(false))
    {
        return false;
    }

    passiveParticleCloud cloud(mesh, cloudName);
    for (const passiveParticle& p : cloud)
    {
        P.x.append(p.position());
        P.cell.append(p.cell());
    }
    const label n = P.x.size();
    readField(mesh, cloudName, "U", n, P.v);
    readField(mesh, cloudName, "F", n, P.F);
    readField(mesh, cloudName, "B", n, P.B);
    readField(mesh, cloudName, "sigma", n, P.sigma);
    readField(mesh, cloudName, "psi", n, P.psi);
    readField(mesh, cloudName, "volume", n, P.V);
    readField(mesh, cloudName, "V0", n, P.V0);
    readField(mesh, cloudName, "mass", n, P.m);
    readField(mesh, cloudName, "material", n, P.material);
    readFieldOrDefault(mesh, cloudName, "epsilonP", n, scalar(0), P.epsilonP);
    readFieldOrDefault(mesh, cloudName, "Jp", n, scalar(1), P.Jp);
    return true;
}


// ************************************************************************* //
