/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
-------------------------------------------------------------------------------
Application
    mpmKernelProbe

Group
    mpmFoam utilities

Description
    Evaluates the MPM transfer kernels (linear, mlsRing, umls, bspline2: see
    mpmKernel.H) at probe points on the case's mesh, as the solver would for
    particles at those points, and writes every weight w_vp and gradient
    grad w_vp: the kernel verification of dissertation 2.1.3.5 (Figs 2.5,
    2.7) on any mesh the MPM view takes (1D, 2D, 3D).

    Each probe point is located in the mesh (walking from the previous
    point's cell); a point outside the mesh stops with a FatalIOError naming
    the entry \c points, \c line or \c random.  For each kernel one file
        postProcessing/<outputName>/<kernel>.dat
    holds one row per (point, vertex) that the kernel returns (for
    mlsRing and umls the ring vertices with a non-zero sample weight, for
    linear the vertices of the point's cell):
        point  px py pz  vertex  vx vy vz  w  gradWx gradWy gradWz
    (point: index in the probe list; vertex: index in the MPM mesh view,
    which in 1D numbers the nodes by increasing coordinate).  Lines starting
    with # are the header.

    Per kernel the log gives a sanity line with the worst MLS identities
    over the points: max |sum_v w_vp - 1| (partition of unity),
    max |sum_v w_vp x_v - x_p| (linear reproduction, over the solution
    axes), max |sum_v grad w_vp|, max |sum_v x_v (grad w_vp)^T - I| (over
    the solution axes) and the smallest weight.

Usage
    mpmKernelProbe [-case dir] [-dict file]

    system/mpmKernelProbeDict:
    \verbatim
        kernels     (linear mlsRing umls);      // one or more

        // either explicit points
        points      ((1.2 0.5 0.5) (3.7 0.5 0.5));

        // or evenly spaced points on a line, start and end included
        line
        {
            start   (0.5 0.5 0.5);
            end     (3.5 0.5 0.5);
            nPoints 301;
        }

        // or uniform random points in a box (a fixed seed: reproducible)
        random
        {
            min     (1 1 1);
            max     (3 3 3);
            nPoints 1000;
            seed    1;
        }

        outputName  mpmKernelProbe;     // optional
    \endverbatim
    \table
        Property   | Description                                  | Required | Default
        kernels    | list of kernels: linear, mlsRing, umls, bspline2 (uniform Cartesian meshes) | yes |
        points     | probe points ((x y z) ...)                   | one of points, line, random |
        line       | start, end [m] and nPoints (>= 2)             | one of points, line, random |
        random     | min, max [m], nPoints (>= 2), seed (default 1) | one of points, line, random |
        outputName | output directory under postProcessing/       | no  | mpmKernelProbe
    \endtable
    Other entries of the dictionary are passed to the kernels (none reads
    any today).  Bad or missing entries stop with a FatalIOError naming the
    entry and what is allowed.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "polyMesh.H"
#include "IOdictionary.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "mpmMeshView.H"
#include "mpmKernel.H"
#include "dictionaryChecks.H"
#include "Random.H"

using namespace Foam;

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Write the MPM kernel weights and gradients at probe points;"
        " settings in system/mpmKernelProbeDict"
    );
    argList::noParallel();
    #include "addDictOption.H"

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createPolyMesh.H"

    using namespace dictionaryChecks;

    const word dictName("mpmKernelProbeDict");
    #include "setSystemMeshDictionaryIO.H"
    const IOdictionary probeDict(dictIO);

    // Kernels: checked against the kernels the library provides
    OStringStream kernelsAllowed;
    kernelsAllowed
        << "a non-empty list of distinct kernels, each one of "
        << mpmKernel::dictionaryConstructorTablePtr_->sortedToc();
    const wordList kernels
    (
        getAs<wordList>(probeDict, "kernels", kernelsAllowed.str())
    );
    if (kernels.empty())
    {
        badEntry(probeDict, "kernels", "()", kernelsAllowed.str());
    }
    forAll(kernels, i)
    {
        if (!mpmKernel::dictionaryConstructorTablePtr_->found(kernels[i]))
        {
            badEntry(probeDict, "kernels", kernels[i], kernelsAllowed.str());
        }
        for (label j = 0; j < i; ++j)
        {
            if (kernels[j] == kernels[i])
            {
                badEntry(probeDict, "kernels",
                    kernels[i] + " (twice)", kernelsAllowed.str());
            }
        }
    }

    // Probe points: 'points', 'line' or 'random'
    const string pointsAllowed
    (
        "one of 'points ((x y z) ...);',"
        " 'line { start (x y z); end (x y z); nPoints N; }' (N >= 2) or"
        " 'random { min (x y z); max (x y z); nPoints N; seed S; }'"
    );
    label nGiven = 0;
    word pointsKey;
    for (const word key : {"points", "line", "random"})
    {
        if (probeDict.found(key, keyType::LITERAL))
        {
            ++nGiven;
            pointsKey = key;
        }
    }
    if (nGiven == 0)
    {
        missingEntry(probeDict, "points", pointsAllowed);
    }
    if (nGiven > 1)
    {
        badEntry(probeDict, pointsKey, "more than one way to give points",
            pointsAllowed);
    }

    List<vector> pts;
    if (pointsKey == "points")
    {
        pts = getAs<List<vector>>
        (
            probeDict, "points", "a non-empty list of points ((x y z) ...)"
        );
        if (pts.empty())
        {
            badEntry(probeDict, "points", "()",
                "a non-empty list of points ((x y z) ...)");
        }
    }
    else
    {
        const dictionary* ld = probeDict.findDict(pointsKey, keyType::LITERAL);
        if (!ld)
        {
            badEntry(probeDict, pointsKey, entryText(probeDict, pointsKey),
                pointsAllowed);
        }
        if (!ld->found("nPoints", keyType::LITERAL))
        {
            missingEntry(*ld, "nPoints", "an integer >= 2");
        }
        const label n = getLabelAtLeast(*ld, "nPoints", 2, 2);
        pts.setSize(n);
        if (pointsKey == "line")
        {
            const vector start = getAs<vector>(*ld, "start", "a point (x y z)");
            const vector end = getAs<vector>(*ld, "end", "a point (x y z)");
            forAll(pts, i)
            {
                pts[i] = start + (end - start)*(scalar(i)/scalar(n - 1));
            }
            pts.last() = end;
        }
        else
        {
            // Uniform random points in a box (reproducible: fixed seed);
            // the directions that are not solved stay at the box's middle
            const vector lo = getAs<vector>(*ld, "min", "a point (x y z)");
            const vector hi = getAs<vector>(*ld, "max", "a point (x y z)");
            const label seed = getAsOrDefault<label>(*ld, "seed", 1, "an integer");
            Random rnd(seed);
            forAll(pts, i)
            {
                const vector r = rnd.sample01<vector>();
                pts[i] = lo + cmptMultiply(hi - lo, r);
            }
        }
    }

    const fileName outDir
    (
        runTime.globalPath()/"postProcessing"
       /getAsOrDefault<word>
        (
            probeDict, "outputName", "mpmKernelProbe", "a directory name (word)"
        )
    );

    const mpmMeshView view(mesh);
    Info<< "MPM mesh view: " << view.dim() << "D, " << view.nVertices()
        << " vertices, " << view.nCells() << " cells" << nl;

    // Locate the points, each walk starting from the previous point's cell
    labelList cells(pts.size(), -1);
    label guess = 0;
    forAll(pts, i)
    {
        const label c = view.findCell(pts[i], guess);
        if (c < 0)
        {
            OStringStream found, allowed;
            found << "point " << i << " at " << pts[i]
                << ", outside the mesh";
            allowed << "points inside the mesh, bounds " << mesh.bounds();
            badEntry(probeDict, pointsKey, found.str(), allowed.str());
        }
        cells[i] = c;
        guess = c;
    }
    Info<< "Probe points: " << pts.size() << " (from '" << pointsKey << "')"
        << nl << endl;

    mkDir(outDir);

    const List<vector>& vx = view.vertices();

    for (const word& kernelName : kernels)
    {
        dictionary kernelDict(probeDict);
        kernelDict.set("kernel", kernelName);
        const autoPtr<mpmKernel> kernel(mpmKernel::New(kernelDict, view));

        kernelWeights kw;
        kernel->compute(pts, cells, kw);
        kernel->report();

        const fileName outFile(outDir/(kernelName + ".dat"));
        OFstream os(outFile);
        os.precision(16);
        os  << "# mpmKernelProbe: kernel " << kernelName << " on "
            << view.dim() << "D mesh of " << runTime.path()
            << " (" << view.nVertices() << " vertices, " << view.nCells()
            << " cells), " << pts.size() << " points from '" << pointsKey
            << "'" << nl
            << "# one row per (point, vertex); w and grad w as the solver"
            << " uses them (grad w: the MLS gradient estimate)" << nl
            << "# point[-] px[m] py[m] pz[m] vertex[-] vx[m] vy[m] vz[m]"
            << " w[-] gradWx[1/m] gradWy[1/m] gradWz[1/m]" << nl;

        scalar errPU = 0, errLin = 0, errGrad = 0, errId = 0, wMin = GREAT;
        const tensor Isol = I - view.offAxes();
        label nMax = 0;
        forAll(pts, p)
        {
            const vector& xp = pts[p];
            scalar sw = 0;
            vector swx(Zero), sg(Zero);
            tensor sxg(Zero);
            nMax = max(nMax, kw.start[p + 1] - kw.start[p]);
            for (label i = kw.start[p]; i < kw.start[p + 1]; ++i)
            {
                const label v = kw.vertex[i];
                const scalar w = kw.w[i];
                const vector& g = kw.gradW[i];
                sw += w;
                swx += w*vx[v];
                sg += g;
                sxg += vx[v]*g;
                wMin = min(wMin, w);
                os  << p << ' ' << xp.x() << ' ' << xp.y() << ' ' << xp.z()
                    << ' ' << v << ' ' << vx[v].x() << ' ' << vx[v].y()
                    << ' ' << vx[v].z() << ' ' << w << ' ' << g.x() << ' '
                    << g.y() << ' ' << g.z() << nl;
            }
            errPU = max(errPU, mag(sw - 1));
            errLin = max(errLin, view.distance(swx, xp));
            errGrad = max(errGrad, mag(view.inPlane(sg)));
            // sum x_v (grad w)^T = I over the solution axes
            const tensor dI = (Isol & sxg & Isol) - Isol;
            errId = max(errId, cmptMax(cmptMag(dI)));
        }

        Info<< "kernel " << kernelName << ": " << pts.size() << " points, "
            << kw.vertex.size() << " weights (at most " << nMax
            << " per point); max |sum w - 1| = " << errPU
            << ", max |sum w x_v - x_p| = " << errLin
            << " m, max |sum grad w| = " << errGrad
            << " 1/m, max |sum x_v grad w - I| = " << errId
            << ", min w = " << wMin << nl
            << "    written " << outFile << nl << endl;
    }

    Info<< "End" << nl << endl;

    return 0;
}

// ************************************************************************* //
