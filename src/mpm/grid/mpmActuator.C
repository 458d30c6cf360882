/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "mpmActuator.H"
#include "mpmMeshView.H"
#include "dictionary.H"
#include "dictionaryChecks.H"
#include "Tuple2.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::mpmActuator::mpmActuator
(
    const word& name,
    const dictionary& dict,
    const labelUList& axes
)
:
    name_(name),
    axes_(axes),
    velocity_(Zero),
    force_(Zero),
    nHeld_(0),
    work_(0),
    stepTime_(-GREAT)
{
    using namespace dictionaryChecks;

    box_ = getAs<Pair<vector>>
    (
        dict, "box", "two points ((xmin ymin zmin) (xmax ymax zmax))"
    );
    for (const label k : axes_)
    {
        if
        (
            !std::isfinite(box_.first()[k]) || !std::isfinite(box_.second()[k])
         || !(box_.first()[k] < box_.second()[k])
        )
        {
            badEntry(dict, "box", entryText(dict, "box"),
                "two finite points ((xmin ymin zmin) (xmax ymax zmax)) with"
                " min < max on the solution axes");
        }
    }

    const string pathAllowed
    (
        "a list ((t0 (dx dy dz)) (t1 (dx dy dz)) ...) of displacements [m]"
        " at increasing times [s], at least one point"
    );
    const List<Tuple2<scalar, vector>> path =
        getAs<List<Tuple2<scalar, vector>>>(dict, "path", pathAllowed);
    if (path.empty())
    {
        badEntry(dict, "path", "()", pathAllowed);
    }
    times_.setSize(path.size());
    displacement_.setSize(path.size());
    forAll(path, k)
    {
        times_[k] = path[k].first();
        displacement_[k] = path[k].second();
        bool finite = std::isfinite(times_[k]);
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            finite = finite && std::isfinite(displacement_[k][d]);
        }
        if (!finite || (k > 0 && !(times_[k] > times_[k - 1])))
        {
            badEntry(dict, "path", entryText(dict, "path"),
                pathAllowed + " (point " + Foam::name(k) + " has a time"
                " not above the one before, or a non-finite value)");
        }
    }
}


Foam::PtrList<Foam::mpmActuator> Foam::mpmActuator::readAll
(
    const dictionary& mpmProperties,
    const mpmMeshView& view
)
{
    labelList axes(view.dim());
    forAll(axes, a) axes[a] = view.axis(a);
    return readAll(mpmProperties, axes);
}


Foam::PtrList<Foam::mpmActuator> Foam::mpmActuator::readAll
(
    const dictionary& mpmProperties,
    const labelUList& axes
)
{
    PtrList<mpmActuator> all;
    if (!mpmProperties.found("actuators", keyType::LITERAL)) return all;
    if (!mpmProperties.isDict("actuators"))
    {
        dictionaryChecks::badEntry
        (
            mpmProperties, "actuators",
            dictionaryChecks::entryText(mpmProperties, "actuators"),
            "a sub-dictionary with one sub-dictionary per actuator,"
            " e.g. actuators { pusher { box (...); path (...); } }"
        );
    }
    const dictionary& ad = mpmProperties.subDict("actuators");
    for (const entry& e : ad)
    {
        if (!e.isDict())
        {
            dictionaryChecks::badEntry
            (
                ad, e.keyword(), dictionaryChecks::entryText(ad, e.keyword()),
                "an actuator sub-dictionary { box (...); path (...); }"
            );
        }
        all.append(new mpmActuator(e.keyword(), e.dict(), axes));
    }
    return all;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::vector Foam::mpmActuator::displacement(const scalar t) const
{
    const label n = times_.size();
    if (t <= times_[0]) return displacement_[0];
    if (t >= times_[n - 1]) return displacement_[n - 1];
    label k = 1;
    while (times_[k] < t) ++k;
    const scalar s = (t - times_[k - 1])/(times_[k] - times_[k - 1]);
    return (1 - s)*displacement_[k - 1] + s*displacement_[k];
}


Foam::scalar Foam::mpmActuator::maxSpeed() const
{
    scalar v = 0;
    for (label k = 1; k < times_.size(); ++k)
    {
        vector d = displacement_[k] - displacement_[k - 1];
        for (direction c = 0; c < vector::nComponents; ++c)
        {
            if (!axes_.found(c)) d[c] = 0;
        }
        v = max(v, mag(d)/(times_[k] - times_[k - 1]));
    }
    return v;
}


Foam::Pair<Foam::vector> Foam::mpmActuator::box(const scalar t) const
{
    const vector d = displacement(t);
    return Pair<vector>(box_.first() + d, box_.second() + d);
}


void Foam::mpmActuator::apply
(
    const scalar t,
    const scalar dt,
    const List<vector>& vertices,
    const UList<label>& active,
    const UList<scalar>& mass,
    UList<vector>& velocity,
    const UList<scalar>* share
)
{
    if (t != stepTime_)
    {
        stepTime_ = t;
        force_ = Zero;
        nHeld_ = 0;
    }
    const Pair<vector> b = box(t);
    // On the solution axes only (a 2D or 1D mesh view moves in its plane)
    const vector dv = (displacement(t + dt) - displacement(t))/dt;
    vector vAct(Zero);
    for (const label k : axes_) vAct[k] = dv[k];
    velocity_ = vAct;

    // Momentum added to the material at the held vertices
    vector dp(Zero);
    for (const label i : active)
    {
        const vector& x = vertices[i];
        bool in = true;
        for (const label k : axes_)
        {
            in = in && x[k] >= b.first()[k] && x[k] <= b.second()[k];
        }
        if (!in) continue;
        const scalar s = share ? (*share)[i] : scalar(1);
        dp += s*mass[i]*(vAct - velocity[i]);
        velocity[i] = vAct;
        ++nHeld_;
    }
    force_ += dp/dt;
    work_ += dp & vAct;
}


// ************************************************************************* //
