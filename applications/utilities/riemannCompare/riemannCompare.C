/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
-------------------------------------------------------------------------------
Application
    riemannCompare

Group
    mpmFoam utilities

Description
    Compares the fields of a 1D shock-tube case with the exact solution of
    its Riemann problem (exactRiemannSolver.H) at the cell centres, at each
    selected time: the check of any compressible solver (rhoCentralFoam,
    shockMpmFoam) on the classical test problems.

    gamma and R come from constant/thermophysicalProperties (idealGas.H:
    direct 'gamma'/'R' or rhoCentralFoam's 'mixture' form).  At each time
    the utility reads U (its x component) and p, and rho if the time has
    one, else rho = p/(R T) from T.  The exact solution is sampled at the x
    of the cell centres (on meshes that are not 1D the y and z of the
    centres are ignored); at time 0 (only with -withZero) it is the initial
    data, the left state for x < x0.

    The errors are the integral norms over the internal field
        L1(f) = sum_c |f_c - f_exact(x_c)| dx_c
    with dx_c the cell's extent along x (on [0, 1] the mean absolute
    error).  For each time
        postProcessing/riemannCompare/<time>/profile.dat
    holds, sorted by x, the columns
        x rho U p rhoExact Uexact pExact
    and
        postProcessing/riemannCompare/<time>/errors.dat
    the columns
        time nCells length L1(rho) L1(U) L1(p)
    (lines starting with # are the header; 16 significant digits).  The log
    gives per time the line
        L1(rho) = 1.234e-03  L1(U) = ...  L1(p) = ...

Usage
    riemannCompare [-case dir] [-dict file] [-time ranges] [-latestTime]
        [-withZero]

    system/riemannCompareDict:
    \verbatim
        x0          0.5;                    // initial discontinuity [m]
        left        { rho 1;     U 0; p 1;   }
        right       { rho 0.125; U 0; p 0.1; }
        direction   x;                      // optional; only x
    \endverbatim
    \table
        Property  | Description                          | Required | Default
        x0        | initial discontinuity [m]            | yes |
        left      | rho > 0, U (x velocity), p > 0: x < x0 | yes |
        right     | the same for x > x0                  | yes |
        direction | the tube's axis: x                   | no  | x
    \endtable
    Bad or missing entries (rho and p must be in [1e-20, 1e20], |U| <=
    1e20, as shockMpmFoam's input: gasLimits.H), and states whose solution
    has a vacuum, stop with a FatalIOError naming the file and the entry.
    Serial only.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "timeSelector.H"
#include "Time.H"
#include "fvMesh.H"
#include "columnFvMesh.H"
#include "volFields.H"
#include "IOdictionary.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "SortableList.H"
#include "dictionaryChecks.H"
#include "exactRiemannSolver.H"
#include "idealGas.H"
#include "gasLimits.H"

#include <cstdio>
#include <stdexcept>

using namespace Foam;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The state in sub-dictionary \c key (left or right) of \c dict
exactRiemannSolver::state readState(const dictionary& dict, const word& key)
{
    using namespace dictionaryChecks;

    const string allowed
    (
        "a sub-dictionary { rho R; U Ux; p P; } with rho > 0 [kg/m3],"
        " U the x velocity [m/s] and p > 0 [Pa]"
    );
    const dictionary* sd = dict.findDict(key, keyType::LITERAL);
    if (!sd)
    {
        if (dict.found(key, keyType::LITERAL))
        {
            badEntry(dict, key, entryText(dict, key), allowed);
        }
        missingEntry(dict, key, allowed);
    }

    // The solver's input range (gasLimits.H): beyond it the exact solver's
    // wave speeds and sampled energies overflow
    const string inRange("a finite number > 0 " + gasLimits::rangeText());
    const string uAllowed
    (
        "a finite number (the x velocity [m/s]) with |U| <= "
      + Foam::name(gasLimits::maxValue)
    );
    exactRiemannSolver::state s;
    s.rho = getAs<scalar>(*sd, "rho", inRange);
    if (!gasLimits::inRange(s.rho))
    {
        badEntry(*sd, "rho", Foam::name(s.rho), inRange);
    }
    s.u = getAs<scalar>(*sd, "U", uAllowed);
    if (!(std::abs(s.u) <= gasLimits::maxValue))
    {
        badEntry(*sd, "U", Foam::name(s.u), uAllowed);
    }
    s.p = getAs<scalar>(*sd, "p", inRange);
    if (!gasLimits::inRange(s.p))
    {
        badEntry(*sd, "p", Foam::name(s.p), inRange);
    }
    return s;
}


//- One value with the log's format
std::string sci(const scalar v)
{
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%.3e", v);
    return buf;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Compare a 1D shock-tube case with the exact Riemann solution;"
        " settings in system/riemannCompareDict"
    );
    argList::noParallel();
    timeSelector::addOptions(false, true);
    #include "addDictOption.H"

    #include "setRootCase.H"
    #include "createTime.H"
    instantList timeDirs = timeSelector::select0(runTime, args);
    #include "createMesh.H"

    using namespace dictionaryChecks;

    const word dictName("riemannCompareDict");
    #include "setSystemMeshDictionaryIO.H"
    const IOdictionary cmpDict(dictIO);

    // The problem
    const word direction
    (
        getAsOrDefault<word>(cmpDict, "direction", "x", "x")
    );
    if (direction != "x")
    {
        badEntry(cmpDict, "direction", direction,
            "x (the tube along x; no other direction is supported)");
    }
    const scalar x0 = getAs<scalar>
    (
        cmpDict, "x0", "a finite number (the initial discontinuity [m])"
    );
    if (!std::isfinite(x0))
    {
        badEntry(cmpDict, "x0", Foam::name(x0),
            "a finite number (the initial discontinuity [m])");
    }
    const exactRiemannSolver::state left(readState(cmpDict, "left"));
    const exactRiemannSolver::state right(readState(cmpDict, "right"));

    const idealGas gas(runTime);

    autoPtr<exactRiemannSolver> exactPtr;
    try
    {
        exactPtr.reset(new exactRiemannSolver(left, right, gas.gamma()));
    }
    catch (const std::invalid_argument& e)
    {
        FatalIOErrorInFunction(cmpDict)
            << "Entries 'left' and 'right' in " << cmpDict.objectPath()
            << " (gamma = " << gas.gamma() << "): " << e.what() << nl
            << "    allowed: states whose Riemann problem has no vacuum"
            << exit(FatalIOError);
    }
    const exactRiemannSolver& exact = *exactPtr;

    Info<< "Riemann problem along x, x0 = " << x0 << nl
        << "    left  rho " << left.rho << " U " << left.u << " p " << left.p
        << nl
        << "    right rho " << right.rho << " U " << right.u << " p "
        << right.p << nl
        << "    gamma " << gas.gamma() << ", R " << gas.R()
        << " (constant/thermophysicalProperties)" << nl
        << "    p* " << exact.pStar() << ", u* " << exact.uStar()
        << ", rho*L " << exact.rhoStarLeft() << ", rho*R "
        << exact.rhoStarRight() << nl << endl;

    if (mesh.nSolutionD() != 1)
    {
        Info<< "Note: the mesh has " << mesh.nSolutionD()
            << " solution directions; only the x of the cell centres is"
            << " used" << nl << endl;
    }

    const fileName outRoot
    (
        runTime.globalPath()/"postProcessing"/"riemannCompare"
    );

    label nCompared = 0;

    forAll(timeDirs, timei)
    {
        runTime.setTime(timeDirs[timei], timei);
        Info<< "Time = " << runTime.timeName() << endl;

        mesh.readUpdate();

        IOobject pIO
        (
            "p", runTime.timeName(), mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE
        );
        IOobject UIO
        (
            "U", runTime.timeName(), mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE
        );
        IOobject rhoIO
        (
            "rho", runTime.timeName(), mesh,
            IOobject::READ_IF_PRESENT, IOobject::NO_WRITE
        );
        IOobject TIO
        (
            "T", runTime.timeName(), mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE
        );

        const bool hasRho = rhoIO.typeHeaderOk<volScalarField>(true);
        string missing;
        if (!pIO.typeHeaderOk<volScalarField>(true))
        {
            missing += (missing.empty() ? "" : ", ") + string("p");
        }
        if (!UIO.typeHeaderOk<volVectorField>(true))
        {
            missing += (missing.empty() ? "" : ", ") + string("U");
        }
        if (!hasRho && !TIO.typeHeaderOk<volScalarField>(true))
        {
            missing += (missing.empty() ? "" : ", ") + string("rho or T");
        }
        if (!missing.empty())
        {
            Info<< "    no field " << missing.c_str() << ": skipped" << nl
                << endl;
            continue;
        }

        const volScalarField p(pIO, mesh);
        const volVectorField U(UIO, mesh);
        scalarField rho;
        if (hasRho)
        {
            rho = volScalarField(rhoIO, mesh).primitiveField();
            Info<< "    rho read" << nl;
        }
        else
        {
            const volScalarField T(TIO, mesh);
            rho = p.primitiveField()/(gas.R()*T.primitiveField());
            Info<< "    rho = p/(R T) from p and T" << nl;
        }

        // Cell centres and extents along x
        const scalarField xc(mesh.C().primitiveField().component(vector::X));
        scalarField dx(mesh.nCells());
        {
            const labelListList& cellPts = mesh.cellPoints();
            const pointField& pts = mesh.points();
            forAll(cellPts, celli)
            {
                scalar lo = GREAT, hi = -GREAT;
                for (const label pointi : cellPts[celli])
                {
                    lo = min(lo, pts[pointi].x());
                    hi = max(hi, pts[pointi].x());
                }
                dx[celli] = hi - lo;
            }
        }

        // The exact solution at the cell centres
        const scalar t = runTime.value();
        List<exactRiemannSolver::state> ex(mesh.nCells());
        if (t > 0)
        {
            const std::vector<double> xs(xc.cbegin(), xc.cend());
            const std::vector<exactRiemannSolver::state> s
            (
                exact.sample(xs, x0, t)
            );
            forAll(ex, celli)
            {
                ex[celli] = s[celli];
            }
        }
        else
        {
            forAll(ex, celli)
            {
                ex[celli] = xc[celli] < x0 ? left : right;
            }
        }

        // Errors
        const scalarField Ux(U.primitiveField().component(vector::X));
        const scalarField& pc = p.primitiveField();
        scalar l1Rho = 0, l1U = 0, l1p = 0;
        forAll(ex, celli)
        {
            l1Rho += mag(rho[celli] - ex[celli].rho)*dx[celli];
            l1U += mag(Ux[celli] - ex[celli].u)*dx[celli];
            l1p += mag(pc[celli] - ex[celli].p)*dx[celli];
        }

        const fileName outDir(outRoot/runTime.timeName());
        mkDir(outDir);

        // Profile, sorted by x
        {
            SortableList<scalar> xs(xc);
            const labelList& order = xs.indices();

            OFstream os(outDir/"profile.dat");
            os.precision(16);
            os  << "# riemannCompare: " << runTime.path().c_str()
                << ", time " << t
                << ", " << mesh.nCells() << " cells" << nl
                << "# exact: x0 " << x0 << ", left (rho U p) = ("
                << left.rho << ' ' << left.u << ' ' << left.p
                << "), right = (" << right.rho << ' ' << right.u << ' '
                << right.p << "), gamma " << gas.gamma() << nl
                << "# rho " << (hasRho ? "read" : "= p/(R T)")
                << "; exact values at the cell centres" << nl
                << "# x[m] rho[kg/m3] U[m/s] p[Pa]"
                << " rhoExact[kg/m3] Uexact[m/s] pExact[Pa]" << nl;
            for (const label celli : order)
            {
                os  << xc[celli] << ' ' << rho[celli] << ' ' << Ux[celli]
                    << ' ' << pc[celli] << ' ' << ex[celli].rho << ' '
                    << ex[celli].u << ' ' << ex[celli].p << nl;
            }
        }

        // Error norms
        {
            OFstream os(outDir/"errors.dat");
            os.precision(16);
            os  << "# riemannCompare: " << runTime.path().c_str() << nl
                << "# L1(f) = sum_c |f_c - f_exact(x_c)| dx_c;"
                << " length = sum_c dx_c" << nl
                << "# time[s] nCells length[m] L1(rho)[kg/m2] L1(U)[m2/s]"
                << " L1(p)[Pa m]" << nl
                << t << ' ' << mesh.nCells() << ' ' << sum(dx) << ' '
                << l1Rho << ' ' << l1U << ' ' << l1p << nl;
        }

        Info<< "L1(rho) = " << sci(l1Rho).c_str()
            << "  L1(U) = " << sci(l1U).c_str()
            << "  L1(p) = " << sci(l1p).c_str() << nl
            << "    written " << outDir << nl << endl;

        ++nCompared;
    }

    if (!nCompared)
    {
        FatalErrorInFunction
            << "No selected time of " << runTime.path()
            << " has the fields p, U and rho or T" << nl
            << exit(FatalError);
    }

    Info<< "End" << nl << endl;

    return 0;
}

// ************************************************************************* //
