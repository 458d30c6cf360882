/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "mpmParticleProbe.H"
#include "mpmState.H"
#include "fvMesh.H"
#include "Time.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(mpmParticleProbe, 0);
    addToRunTimeSelectionTable(functionObject, mpmParticleProbe, dictionary);
}
}


Foam::functionObjects::mpmParticleProbe::mpmParticleProbe
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    interval_(1)
{
    read(dict);
}


bool Foam::functionObjects::mpmParticleProbe::read(const dictionary& dict)
{
    using namespace dictionaryChecks;
    fvMeshFunctionObject::read(dict);
    points_ = getAs<List<point>>(dict, "points", "a non-empty list of points ((x y z) ...)");
    if (points_.empty())
    {
        badEntry(dict, "points", "()", "a non-empty list of points ((x y z) ...)");
    }
    interval_ = getLabelAtLeast(dict, "interval", 1, 1);
    particles_.clear();
    return true;
}


bool Foam::functionObjects::mpmParticleProbe::execute()
{
    if (!mesh_.foundObject<mpmState>("mpmState"))
    {
        FatalErrorInFunction
            << "mpmParticleProbe '" << name() << "' needs an MPM solver"
            << " (umlsMpmFoam); none is running" << exit(FatalError);
    }
    const mpmParticles& P =
        mesh_.lookupObject<mpmState>("mpmState").particles();

    if (particles_.empty())
    {
        particles_.setSize(points_.size(), -1);
        start_.setSize(points_.size());
        forAll(points_, i)
        {
            scalar best = GREAT;
            forAll(P.x, p)
            {
                const scalar d = magSqr(P.x[p] - points_[i]);
                if (d < best) { best = d; particles_[i] = p; }
            }
            if (particles_[i] < 0)
            {
                FatalErrorInFunction
                    << "mpmParticleProbe '" << name() << "': no particles"
                    << exit(FatalError);
            }
            start_[i] = P.x[particles_[i]];
            Info<< type() << ' ' << name() << ": probe " << i << " at "
                << points_[i] << " follows particle " << particles_[i]
                << " at " << start_[i] << endl;
        }
    }

    if (time_.timeIndex() % interval_ != 0)
    {
        return true;
    }

    forAll(particles_, i)
    {
        const label p = particles_[i];
        const vector D = P.x[p] - start_[i];
        const word pre(Foam::name(i) + "_");
        setResult(pre + "Dx", D.x());
        setResult(pre + "Dy", D.y());
        setResult(pre + "Dz", D.z());
        setResult(pre + "sxx", P.sigma[p].xx());
        setResult(pre + "syy", P.sigma[p].yy());
        setResult(pre + "sxy", P.sigma[p].xy());
    }

    if (Pstream::master())
    {
        if (!file_)
        {
            const fileName dir
            (
                time_.globalPath()/functionObject::outputPrefix/name()
               /time_.timeName(time_.startTime().value())
            );
            mkDir(dir);
            file_.reset(new OFstream(dir/(name() + ".dat")));
            file_().precision(12);
            OFstream& os = file_();
            os  << "# particles followed:";
            forAll(particles_, i)
            {
                os << " probe " << i << " = particle " << particles_[i]
                   << " starting at " << start_[i] << ';';
            }
            os  << nl << "# t [s]";
            forAll(particles_, i)
            {
                const word s(Foam::name(i));
                os  << "\tx" << s << " [m]\ty" << s << " [m]\tz" << s << " [m]"
                    << "\tDx" << s << " [m]\tDy" << s << " [m]\tDz" << s << " [m]"
                    << "\tUx" << s << " [m/s]\tUy" << s << " [m/s]\tUz" << s << " [m/s]"
                    << "\tsxx" << s << " [Pa]\tsyy" << s << " [Pa]\tszz" << s << " [Pa]"
                    << "\tsxy" << s << " [Pa]\tsyz" << s << " [Pa]\tsxz" << s << " [Pa]"
                    << "\tJ" << s << " [-]";
            }
            os  << nl;
        }
        OFstream& os = file_();
        os  << time_.value();
        forAll(particles_, i)
        {
            const label p = particles_[i];
            const vector& x = P.x[p];
            const vector D = x - start_[i];
            const vector& v = P.v[p];
            const symmTensor& s = P.sigma[p];
            os  << '\t' << x.x() << '\t' << x.y() << '\t' << x.z()
                << '\t' << D.x() << '\t' << D.y() << '\t' << D.z()
                << '\t' << v.x() << '\t' << v.y() << '\t' << v.z()
                << '\t' << s.xx() << '\t' << s.yy() << '\t' << s.zz()
                << '\t' << s.xy() << '\t' << s.yz() << '\t' << s.xz()
                << '\t' << det(P.F[p]);
        }
        // Flushed every line: a run stopped by a FatalError keeps its
        // history up to the last step
        os  << endl;
    }
    return true;
}


// ************************************************************************* //
