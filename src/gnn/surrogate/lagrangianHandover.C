/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "lagrangianHandover.H"
#include "meshGraph.H"
#include "mpmCloudIO.H"
#include "mpmMaterial.H"
#include "fvMesh.H"
#include "IOdictionary.H"
#include "IOField.H"
#include "Map.H"
#include "cloud.H"

// * * * * * * * * * * * * * * * * Constructor  * * * * * * * * * * * * * * //

Foam::lagrangianHandover::lagrangianHandover
(
    const fvMesh& mesh,
    const word& cloudName,
    const lagrangianRecording& r,
    const dictionary& hybridDict
)
:
    mesh_(mesh),
    cloudName_(cloudName),
    r_(r)
{
    // Only an elastic state is F alone
    IOdictionary props
    (
        IOobject
        (
            "mpmProperties", mesh.time().constant(), mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        )
    );
    const dictionary& mats = props.subDict("materials");
    for (const entry& e : mats)
    {
        if (!e.isDict()) continue;
        if (mpmMaterial::New(e.keyword(), e.dict())->plastic())
        {
            FatalIOErrorInFunction(hybridDict)
                << "Entry 'bsmsHybrid' in " << hybridDict.name() << ": a"
                << " hybrid rollout hands the model's positions to the"
                << " solver, which needs F rebuilt from them; that is the"
                << " whole state of an elastic material only, but the"
                << " material '" << e.keyword() << "' (type "
                << e.dict().get<word>("type") << ") of " << props.name()
                << " is plastic: its plastic strain and Jp cannot be"
                << " rebuilt from positions" << nl
                << "    allowed: bsmsHybrid with elastic materials only;"
                << " a pure rollout (no bsmsHybrid) otherwise"
                << exit(FatalIOError);
        }
    }

    // The solver's state at the start
    const fileName dir
    (
        mesh.time().timePath()/cloud::prefix/cloudName
    );
    for (const char* f : {"mass", "V0", "F", "material"})
    {
        if (!isFile(dir/f))
        {
            FatalIOErrorInFunction(hybridDict)
                << "Entry 'bsmsHybrid' in " << hybridDict.name() << ": the"
                << " handover to the solver needs the solver's cloud at the"
                << " start time (mass, V0, F, material beside the"
                << " positions), but " << dir/f << " is missing: start"
                << " from a time the solver wrote"
                << exit(FatalIOError);
        }
    }
    indexParticles(dir);

    const meshGraph g(r.referenceGraph());
    offsets_ = g.offsets();
    neighbours_ = g.neighbours();
}


// * * * * * * * * * * * * * * * Private Functions * * * * * * * * * * * * * //

void Foam::lagrangianHandover::indexParticles(const fileName& where)
{
    mpmCloudIO::read(mesh_, cloudName_, P_);
    Map<label> byId(2*P_.size());
    forAll(P_.id, p) byId.insert(P_.id[p], p);
    const labelList& ids = r_.ids();
    particle_.setSize(ids.size());
    forAll(ids, i)
    {
        const auto it = byId.cfind(ids[i]);
        if (!it.found() || P_.size() != ids.size())
        {
            FatalErrorInFunction
                << "The solver's cloud " << where << " holds "
                << P_.size() << " particles, not the model's "
                << ids.size() << " material points"
                << (it.found() ? "" : " (no id " + Foam::name(ids[i]) + ")")
                << ": a hybrid rollout needs every material point to stay"
                << " in the solver's cloud" << exit(FatalError);
        }
        particle_[i] = it();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

// The handover's F: the affine fit of the mesh's deformation around each
// point (dissertation 4.2: the Lagrangian mesh carries the body's
// deformation; F = dx/dX)
Foam::tensorField Foam::lagrangianHandover::deformationGradients
(
    const pointField& X,
    const pointField& x,
    const labelList& offsets,
    const labelList& neighbours,
    const label nPoints,
    const Vector<label>& solutionD,
    label& bad
)
{
    bad = -1;
    tensorField F(nPoints, tensor::I);
    for (label i = 0; i < nPoints; ++i)
    {
        tensor A(Zero), B(Zero);
        for (label k = offsets[i]; k < offsets[i + 1]; ++k)
        {
            const label j = neighbours[k];
            const vector dX(X[j] - X[i]);
            const vector dx(x[j] - x[i]);
            A += dx*dX;
            B += dX*dX;
        }
        // An empty direction maps to itself
        const scalar scale = max(tr(B), VSMALL);
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (solutionD[d] == -1)
            {
                A(d, d) += scale;
                B(d, d) += scale;
            }
        }
        if (!(det(B) > 1e-12*pow3(scale)))
        {
            if (bad < 0) bad = i;
            continue;
        }
        F[i] = A & inv(B);
    }
    return F;
}


void Foam::lagrangianHandover::write
(
    const pointField& x,
    const pointField& xPrev,
    const scalar deltaT
)
{
    // The deformation since the solver's last state, fitted on the mesh
    // edges, times the solver's F there: the fit's own error scales with
    // the increment, not with the whole strain (a third to a sixth of the
    // whole fit's on deformingPlate over 1 to 4 model steps)
    const label nP = r_.nPoints();
    pointField xLast(nP);
    forAll(particle_, i) xLast[i] = P_.x[particle_[i]];
    label bad = -1;
    const tensorField dF
    (
        deformationGradients
        (
            xLast, x, offsets_, neighbours_, nP, mesh_.solutionD(), bad
        )
    );
    if (bad >= 0)
    {
        FatalErrorInFunction
            << "Material point " << bad << " (id " << r_.ids()[bad] << ") has"
            << " mesh edges that do not span the mesh's directions: its F"
            << " cannot be fitted for the handover at t = "
            << mesh_.time().timeName() << " (meshRadius "
            << r_.meshRadius() << " too small?)" << exit(FatalError);
    }
    for (label i = 0; i < nP; ++i)
    {
        const label p = particle_[i];
        const label c = mesh_.findCell(x[i]);
        if (c < 0)
        {
            FatalErrorInFunction
                << "The model moved material point " << i << " (id "
                << r_.ids()[i] << ") to " << x[i] << ", outside the mesh,"
                << " at t = " << mesh_.time().timeName() << ": the solver"
                << " cannot take the state over" << exit(FatalError);
        }
        if (!(det(dF[i]) > 0))
        {
            FatalErrorInFunction
                << "The model's positions invert the body at material point "
                << i << " (id " << r_.ids()[i] << ", det dF " << det(dF[i])
                << ") at t = " << mesh_.time().timeName() << ": the solver"
                << " cannot take the state over" << exit(FatalError);
        }
        P_.x[p] = x[i];
        P_.cell[p] = c;
        P_.v[p] = (x[i] - xPrev[i])/deltaT;
        const tensor F(dF[i] & P_.F[p]);
        P_.F[p] = F;
        P_.B[p] = Zero;
        P_.sigma[p] = Zero;
        P_.psi[p] = 0;
        P_.V[p] = det(F)*P_.Jp[p]*P_.V0[p];
    }
    mpmCloudIO::write(mesh_, cloudName_, P_);
}


void Foam::lagrangianHandover::read(pointField& x)
{
    indexParticles
    (
        mesh_.time().timePath()/cloud::prefix/cloudName_
    );
    x.setSize(r_.nNodes());
    forAll(particle_, i)
    {
        x[i] = P_.x[particle_[i]];
    }
    r_.moveActuators(mesh_.time().value(), x);
}


// ************************************************************************* //
