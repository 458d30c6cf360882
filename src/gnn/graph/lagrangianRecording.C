/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "lagrangianRecording.H"
#include "spatialHash.H"
#include "mpmActuator.H"
#include "Time.H"
#include "IOField.H"
#include "IOdictionary.H"
#include "cloud.H"
#include "dictionaryChecks.H"
#include "SortableList.H"
#include "SubField.H"

#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- A field of the cloud at time dir t; FatalIOError on dict if absent
template<class T>
tmp<Field<T>> readCloudField
(
    const Time& runTime,
    const word& cloudName,
    const word& name,
    const word& t,
    const dictionary& dict
)
{
    IOobject io
    (
        name, t, cloud::prefix/cloudName, runTime,
        IOobject::MUST_READ, IOobject::NO_WRITE, false
    );
    if (!io.typeHeaderOk<IOField<T>>(false))
    {
        FatalIOErrorInFunction(dict)
            << "The recording " << runTime.path() << " has no field '"
            << name << "' of the cloud '" << cloudName << "' (entry 'cloud'"
            << " in " << dict.name() << ") at t = " << t << ": expected "
            << io.objectPath() << exit(FatalIOError);
    }
    const IOField<T> f(io);
    return tmp<Field<T>>::New(f);
}


//- Points on the faces of a box of size L with its lower corner at the
//  origin: a lattice with at most spacing h between neighbours along each
//  axis, the points with an index at either end.  L is rounded to 1e-12 m,
//  so that boxes of one size at different places give the same lattice
//  bit for bit (and so one pooling: closeCenter breaks the ties of a
//  symmetric lattice by round-off)
pointField boxSurface(const vector& size, const scalar h)
{
    vector L;
    label n[3];
    for (direction a = 0; a < 3; ++a)
    {
        L[a] = std::round(size[a]*1e12)/1e12;
        n[a] = max(label(2), label(std::ceil(L[a]/h - 1e-9)) + 1);
    }
    DynamicList<point> pts;
    for (label i = 0; i < n[0]; ++i)
    for (label j = 0; j < n[1]; ++j)
    for (label k = 0; k < n[2]; ++k)
    {
        const bool face =
            i == 0 || i == n[0] - 1 || j == 0 || j == n[1] - 1
         || k == 0 || k == n[2] - 1;
        if (!face) continue;
        pts.append
        (
            vector
            (
                L.x()*i/(n[0] - 1), L.y()*j/(n[1] - 1), L.z()*k/(n[2] - 1)
            )
        );
    }
    return pointField(std::move(pts));
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::lagrangianRecording::lagrangianRecording
(
    const Time& runTime,
    const instantList& frames,
    const dictionary& dict
)
:
    dir_(runTime.path()),
    nPoints_(0),
    meshRadius_(0),
    worldRadius_(0)
{
    using namespace dictionaryChecks;

    const word cloudName
    (
        getAsOrDefault<word>(dict, "cloud", "mpmCloud", "a cloud name")
    );
    meshRadius_ = getPositive(dict, "meshRadius");
    worldRadius_ = getPositive(dict, "worldRadius");
    if (frames.empty())
    {
        FatalIOErrorInFunction(dict)
            << "The recording " << dir_ << " has no written time to read"
            << " (" << dict.name() << ")" << exit(FatalIOError);
    }

    // constant/mpmProperties: the actuators and the clamps
    const IOdictionary mpmProperties
    (
        IOobject
        (
            "mpmProperties", runTime.constant(), runTime,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        )
    );
    const labelList xyz({0, 1, 2});
    {
        PtrList<mpmActuator> read(mpmActuator::readAll(mpmProperties, xyz));
        actuators_.transfer(read);
    }
    const PtrList<mpmActuator>& actuators = actuators_;
    scalar spacing = 0;
    if (actuators.size())
    {
        if (!dict.found("actuatorSpacing", keyType::LITERAL))
        {
            missingEntry(dict, "actuatorSpacing",
                "a spacing > 0 [m] of the actuators' nodes (the recording"
                " has actuators)");
        }
        spacing = getPositive(dict, "actuatorSpacing");
    }
    DynamicList<Pair<vector>> clamps;
    if (const dictionary* bd = mpmProperties.findDict("boundary"))
    {
        for (const entry& e : *bd)
        {
            if
            (
                e.isDict() && e.dict().found("box", keyType::LITERAL)
             && e.dict().lookupOrDefault<word>("type", "free") == "fixed"
            )
            {
                clamps.append(e.dict().get<Pair<vector>>("box"));
            }
        }
    }

    // The material points of every frame, in the order of their ids
    labelList order;
    labelList ids0;
    List<pointField> points(frames.size());
    forAll(frames, k)
    {
        const word& t = frames[k].name();
        const labelField id
        (
            readCloudField<label>(runTime, cloudName, "id", t, dict)
        );
        const vectorField x
        (
            readCloudField<vector>(runTime, cloudName, "x", t, dict)
        );
        if (x.size() != id.size())
        {
            FatalIOErrorInFunction(dict)
                << "The recording " << dir_ << " at t = " << t << " has "
                << x.size() << " positions x and " << id.size() << " ids of"
                << " the cloud '" << cloudName << "' (" << dict.name() << ")"
                << exit(FatalIOError);
        }
        SortableList<label> sorted(id);
        if (k == 0)
        {
            ids0 = sorted;
        }
        else if (labelList(sorted) != ids0)
        {
            FatalIOErrorInFunction(dict)
                << "The recording " << dir_ << " holds " << sorted.size()
                << " material points at t = " << t << " and "
                << ids0.size() << " at t = " << frames[0].name() << ", or"
                << " other ids: a node must be the same point in every"
                << " frame (" << dict.name() << ")" << exit(FatalIOError);
        }
        points[k] = pointField(x, sorted.indices());
    }
    nPoints_ = ids0.size();
    ids_ = ids0;

    // The actuators' nodes, relative to their boxes' lower corners
    List<pointField>& actNodes = actuatorNodes_;
    actNodes.setSize(actuators.size());
    label nAct = 0;
    forAll(actuators, a)
    {
        const Pair<vector>& b = actuators[a].box0();
        actNodes[a] = boxSurface(b.second() - b.first(), spacing);
        nAct += actNodes[a].size();
    }

    const label n = nPoints_ + nAct;
    times_.setSize(frames.size());
    x_.setSize(frames.size());
    forAll(frames, k)
    {
        times_[k] = frames[k].value();
        pointField& xk = x_[k];
        xk.setSize(n);
        SubField<point>(xk, nPoints_) = points[k];
        moveActuators(times_[k], xk);
    }

    X_ = x_[0];
    {
        // The actuators' X: the lattice relative to the box's lower
        // corner, the same wherever the box is (one pooling for all cases;
        // X enters only the mesh edges within a body)
        label o = nPoints_;
        forAll(actuators, a)
        {
            for (const point& p : actNodes[a]) X_[o++] = p;
        }
    }
    kind_.setSize(n, lagrangianGraph::nodeKind::free);
    body_.setSize(n, 0);
    for (label i = 0; i < nPoints_; ++i)
    {
        for (const Pair<vector>& b : clamps)
        {
            const point& p = X_[i];
            if
            (
                p.x() >= b.first().x() && p.x() <= b.second().x()
             && p.y() >= b.first().y() && p.y() <= b.second().y()
             && p.z() >= b.first().z() && p.z() <= b.second().z()
            )
            {
                kind_[i] = lagrangianGraph::nodeKind::fixed;
            }
        }
    }
    {
        label o = nPoints_;
        forAll(actuators, a)
        {
            for (label m = 0; m < actNodes[a].size(); ++m, ++o)
            {
                kind_[o] = lagrangianGraph::nodeKind::actuator;
                body_[o] = a + 1;
            }
        }
    }
}


Foam::lagrangianRecording::~lagrangianRecording()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::lagrangianRecording::moveActuators
(
    const scalar t,
    pointField& x
) const
{
    label o = nPoints_;
    forAll(actuators_, a)
    {
        const vector d =
            actuators_[a].box0().first() + actuators_[a].displacement(t);
        for (const point& p : actuatorNodes_[a]) x[o++] = d + p;
    }
}


Foam::meshGraph Foam::lagrangianRecording::referenceGraph() const
{
    // All pairs closer than meshRadius in X, then those within one body
    const spatialHash hash(X_, meshRadius_);
    DynamicList<label> a, b;
    hash.pairs(labelList(), a, b);
    label m = 0;
    forAll(a, e)
    {
        if (body_[a[e]] == body_[b[e]])
        {
            a[m] = a[e];
            b[m] = b[e];
            ++m;
        }
    }
    a.setSize(m);
    b.setSize(m);
    return meshGraph(X_, a, b);
}


Foam::lagrangianGraph Foam::lagrangianRecording::graph(const label k) const
{
    lagrangianGraph g(referenceGraph(), kind_, worldRadius_);
    if (k > 0) g.move(x_[k - 1]);
    g.move(x_[k]);
    return g;
}


// ************************************************************************* //
