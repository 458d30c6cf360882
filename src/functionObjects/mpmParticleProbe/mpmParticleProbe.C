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

    // The particles are followed by their id (in a -parallel run they
    // move between the ranks; the rank holding one reports it)
    auto findId = [&P](const label id)
    {
        forAll(P.id, p)
        {
            if (P.id[p] == id) return p;
        }
        return label(-1);
    };

    if (particles_.empty())
    {
        particles_.setSize(points_.size(), -1);
        start_.setSize(points_.size());
        forAll(points_, i)
        {
            scalar best = GREAT;
            label bestId = labelMax;
            forAll(P.x, p)
            {
                const scalar d = magSqr(P.x[p] - points_[i]);
                if (d < best || (d == best && P.id[p] < bestId))
                {
                    best = d;
                    bestId = P.id[p];
                }
            }
            const scalar gBest = returnReduce(best, minOp<scalar>());
            const label id = returnReduce
            (
                best == gBest ? bestId : labelMax, minOp<label>()
            );
            if (id == labelMax)
            {
                FatalErrorInFunction
                    << "mpmParticleProbe '" << name() << "': no particles"
                    << exit(FatalError);
            }
            particles_[i] = id;
            const label p = findId(id);
            start_[i] = p >= 0 ? P.x[p] : vector::zero;
            reduce(start_[i], sumOp<vector>());
            Info<< type() << ' ' << name() << ": probe " << i << " at "
                << points_[i] << " follows particle " << particles_[i]
                << " (id) at " << start_[i] << endl;
        }
    }

    if (time_.timeIndex() % interval_ != 0)
    {
        return true;
    }

    // Per probe: x, v, sigma, det F of the particle (summed over the
    // ranks: only its rank contributes)
    const label nVal = 16;
    scalarList values(nVal*particles_.size(), Zero);
    forAll(particles_, i)
    {
        const label p = findId(particles_[i]);
        if (p < 0) continue;
        scalar* d = &values[nVal*i];
        for (direction c = 0; c < 3; ++c)
        {
            d[c] = P.x[p][c];
            d[3 + c] = P.v[p][c];
        }
        for (direction c = 0; c < 6; ++c) d[6 + c] = P.sigma[p][c];
        d[12] = det(P.F[p]);
        d[13] = 1;
    }
    if (Pstream::parRun())
    {
        Pstream::listCombineGather(values, plusEqOp<scalar>());
        Pstream::listCombineScatter(values);
    }
    List<vector> xs(particles_.size()), vs(particles_.size());
    List<symmTensor> ss(particles_.size());
    scalarList Js(particles_.size());
    forAll(particles_, i)
    {
        const scalar* d = &values[nVal*i];
        if (d[13] < 0.5)
        {
            FatalErrorInFunction
                << "mpmParticleProbe '" << name() << "': particle "
                << particles_[i] << " (id) is gone" << exit(FatalError);
        }
        for (direction c = 0; c < 3; ++c)
        {
            xs[i][c] = d[c];
            vs[i][c] = d[3 + c];
        }
        for (direction c = 0; c < 6; ++c) ss[i][c] = d[6 + c];
        Js[i] = d[12];
    }

    forAll(particles_, i)
    {
        const vector D = xs[i] - start_[i];
        const word pre("probe" + Foam::name(i) + "_");
        setResult(pre + "Dx", D.x());
        setResult(pre + "Dy", D.y());
        setResult(pre + "Dz", D.z());
        setResult(pre + "sxx", ss[i].xx());
        setResult(pre + "syy", ss[i].yy());
        setResult(pre + "sxy", ss[i].xy());
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
                os << " probe " << i << " = particle (id) " << particles_[i]
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
            const vector& x = xs[i];
            const vector D = x - start_[i];
            const vector& v = vs[i];
            const symmTensor& s = ss[i];
            os  << '\t' << x.x() << '\t' << x.y() << '\t' << x.z()
                << '\t' << D.x() << '\t' << D.y() << '\t' << D.z()
                << '\t' << v.x() << '\t' << v.y() << '\t' << v.z()
                << '\t' << s.xx() << '\t' << s.yy() << '\t' << s.zz()
                << '\t' << s.xy() << '\t' << s.yz() << '\t' << s.xz()
                << '\t' << Js[i];
        }
        // Flushed every line: a run stopped by a FatalError keeps its
        // history up to the last step
        os  << endl;
    }
    return true;
}


// ************************************************************************* //
