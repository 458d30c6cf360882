/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "mpmConservation.H"
#include "mpmState.H"
#include "fvMesh.H"
#include "Time.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(mpmConservation, 0);
    addToRunTimeSelectionTable(functionObject, mpmConservation, dictionary);
}
}


Foam::functionObjects::mpmConservation::mpmConservation
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


bool Foam::functionObjects::mpmConservation::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    interval_ = dictionaryChecks::getLabelAtLeast(dict, "interval", 1, 1);
    return true;
}


bool Foam::functionObjects::mpmConservation::execute()
{
    if (time_.timeIndex() % interval_ != 0)
    {
        return true;
    }
    if (!mesh_.foundObject<mpmState>("mpmState"))
    {
        FatalErrorInFunction
            << "mpmConservation '" << name() << "' needs an MPM solver"
            << " (umlsMpmFoam); none is running" << exit(FatalError);
    }
    const mpmState& state = mesh_.lookupObject<mpmState>("mpmState");
    const mpmParticles& P = state.particles();
    const mpmSolver::totals t = state.solver().conservation(P);

    vector xCM(Zero);
    forAll(P.x, p) xCM += P.m[p]*P.x[p];
    reduce(xCM, sumOp<vector>());
    xCM /= max(t.mass, VSMALL);
    const scalar total = t.kinetic + t.strain + t.gravitational;

    setResult("mass", t.mass);
    setResult("xCM", xCM.x());
    setResult("yCM", xCM.y());
    setResult("zCM", xCM.z());
    setResult("px", t.momentum.x());
    setResult("py", t.momentum.y());
    setResult("pz", t.momentum.z());
    setResult("Lx", t.angularMomentum.x());
    setResult("Ly", t.angularMomentum.y());
    setResult("Lz", t.angularMomentum.z());
    setResult("kinetic", t.kinetic);
    setResult("strain", t.strain);
    setResult("gravitational", t.gravitational);
    setResult("total", total);

    // Actuators: displacement and this step's force on the material, and
    // their work (which the material's energy may gain)
    const PtrList<mpmActuator>& acts = state.solver().actuators();
    List<vector> actForce(acts.size());
    forAll(acts, k) actForce[k] = returnReduce(acts[k].force(), sumOp<vector>());
    const scalar actWork = acts.empty() ? 0 : state.solver().actuatorWork();

    // Outlets: what left the scene through them
    const bool outlets =
        returnReduce(state.solver().boundary().hasOutlets(), orOp<bool>());
    const mpmSolver::totals out =
        outlets
      ? state.solver().departed()
      : mpmSolver::totals{0, Zero, Zero, 0, 0, 0};
    const scalar outEnergy = out.kinetic + out.strain + out.gravitational;
    if (outlets)
    {
        setResult("outMass", out.mass);
        setResult("outEnergy", outEnergy);
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
            file_().precision(16);
            file_()
                << "# MPM conservation; 2D: per unit depth, 1D: per unit area"
                << nl
                << "# t [s]\tmass [kg]\txCM [m]\tyCM [m]\tzCM [m]"
                << "\tpx [kg m/s]\tpy [kg m/s]\tpz [kg m/s]"
                << "\tLx [kg m2/s]\tLy [kg m2/s]\tLz [kg m2/s]"
                << "\tkinetic [J]\tstrain [J]\tgravitational [J]\ttotal [J]";
            for (const mpmActuator& a : acts)
            {
                const word& n = a.name();
                file_()
                    << '\t' << n << "_dx [m]\t" << n << "_dy [m]\t" << n
                    << "_dz [m]\t" << n << "_Fx [N]\t" << n << "_Fy [N]\t"
                    << n << "_Fz [N]";
            }
            if (acts.size()) file_() << "\tactuatorWork [J]";
            if (outlets)
            {
                file_()
                    << "\toutMass [kg]\toutPx [kg m/s]\toutPy [kg m/s]"
                    << "\toutPz [kg m/s]\toutEnergy [J]";
            }
            file_() << nl;
        }
        OFstream& os = file_();
        os  << time_.value() << '\t' << t.mass << '\t'
            << xCM.x() << '\t' << xCM.y() << '\t' << xCM.z() << '\t'
            << t.momentum.x() << '\t' << t.momentum.y() << '\t'
            << t.momentum.z() << '\t'
            << t.angularMomentum.x() << '\t' << t.angularMomentum.y() << '\t'
            << t.angularMomentum.z() << '\t'
            << t.kinetic << '\t' << t.strain << '\t' << t.gravitational
            << '\t' << total;
        forAll(acts, k)
        {
            const vector d = acts[k].displacement(time_.value());
            const vector& f = actForce[k];
            os  << '\t' << d.x() << '\t' << d.y() << '\t' << d.z()
                << '\t' << f.x() << '\t' << f.y() << '\t' << f.z();
        }
        if (acts.size()) os << '\t' << actWork;
        if (outlets)
        {
            os  << '\t' << out.mass << '\t' << out.momentum.x() << '\t'
                << out.momentum.y() << '\t' << out.momentum.z() << '\t'
                << outEnergy;
        }
        os  << endl;   // flushed: kept if the run stops
    }
    return true;
}


// ************************************************************************* //
