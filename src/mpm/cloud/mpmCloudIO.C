/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "mpmCloudIO.H"
#include "passiveParticleCloud.H"
#include "IOField.H"
#include "Time.H"
#include "ListOps.H"

#include <fstream>
#include <sstream>
#include <string>

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
    // Every rank builds the tet base points (collective), particles or not
    mesh.tetBasePtIs();
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
    writeField(mesh, cloudName, "id", P.id);
    // The positions as computed: the cloud's barycentric coordinates give
    // them back to round-off only, these bit for bit (exact restarts)
    writeField(mesh, cloudName, "x", P.x);
    if (P.hasContact)
    {
        writeField(mesh, cloudName, "fContact", P.fContact);
    }
}


Foam::label Foam::mpmCloudIO::countParticles(const fileName& dir)
{
    for (const char* name : {"id", "U"})
    {
        std::ifstream is((dir/name).c_str());
        if (!is.good()) continue;
        std::stringstream ss;
        ss << is.rdbuf();
        const std::string text(ss.str());
        // The list's size follows the header's closing brace
        std::string::size_type pos = text.find("FoamFile");
        pos = (pos == std::string::npos) ? 0 : text.find('}', pos);
        if (pos == std::string::npos) return -1;
        pos = text.find_first_of("0123456789", pos);
        if (pos == std::string::npos) return -1;
        return std::stol(text.substr(pos, 20));
    }
    return -1;
}


bool Foam::mpmCloudIO::read
(
    const polyMesh& mesh,
    const word& cloudName,
    mpmParticles& P,
    bool* idsRead
)
{
    P.clear();
    IOobject probe
    (
        fieldIO(mesh, cloudName, "U", IOobject::MUST_READ)
    );
    const bool here = probe.typeHeaderOk<IOField<vector>>(false);

    // In parallel the cloud's constructor is collective (tet base points):
    // every rank builds one if any rank holds the cloud (decomposePar
    // writes none for a subdomain without particles)
    if (!returnReduce(here, orOp<bool>()))
    {
        return false;
    }
    passiveParticleCloud cloud(mesh, cloudName);
    if (!here)
    {
        return false;
    }
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
    readFieldOrDefault
    (
        mesh, cloudName, "fContact", n, vector(Zero), P.fContact
    );
    const bool ids =
        fieldIO(mesh, cloudName, "id", IOobject::MUST_READ)
       .typeHeaderOk<IOField<label>>(false);
    if (ids)
    {
        readField(mesh, cloudName, "id", n, P.id);
    }
    else
    {
        P.id = identity(n);
    }
    if (idsRead) *idsRead = ids;

    // The exact positions where written beside the cloud's own (those of
    // the barycentric coordinates), if they are the same points: a cloud
    // edited or moved since keeps its barycentric positions
    IOobject xIO(fieldIO(mesh, cloudName, "x", IOobject::MUST_READ));
    if (xIO.typeHeaderOk<IOField<vector>>(false))
    {
        IOField<vector> xf(xIO);
        bool same = xf.size() == n;
        const scalar tol = 1e-9*mag(mesh.bounds().span());
        for (label p = 0; same && p < n; ++p)
        {
            same = mag(xf[p] - P.x[p]) <= tol;
        }
        if (same)
        {
            forAll(xf, p) P.x[p] = xf[p];
        }
    }
    return true;
}


// ************************************************************************* //
