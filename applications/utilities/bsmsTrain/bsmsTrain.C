/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
-------------------------------------------------------------------------------
Application
    bsmsTrain

Group
    mpmFoam utilities

Description
    Trains a BSMS-GNN (or the MeshGraphNets baseline) to advance a case's
    fields by one written time: from the input fields at written time t_k
    of a recorded case it predicts the output fields at t_{k+1}.  The graph
    is the cell graph of the current case's mesh (nodes = cell centres,
    edges = internal faces), pooled into levels as bsmsLevels does; every
    recorded case must be on this mesh.

    Training pairs: every two consecutive written times (the 0 directory
    included, times before startTime left out) of every case.  A sample is node-major: for each cell the
    components of the fields in the order given (volScalarField: one,
    volVectorField: three).  Each step draws `batch` pairs (with
    replacement, from a generator seeded by (seed, step), so that a
    resumed run draws what an uninterrupted one would) and takes one Adam
    step on the one-step L2 loss of the normalised outputs, with Gaussian
    noise of standard deviation `noise` on the inputs (graphNetTrainer;
    none on input components that are constant over all the data, such as
    the empty direction's velocity component of a 2D case).

    Progress every printInterval steps:
        step 100/2000  loss 1.23e-03  lr 1.00e-04  ETA 12 s
    (loss: the mean training loss of the steps since the previous line).
    Checkpoints every checkpointInterval steps and at the end; an existing
    checkpoint is resumed from its step (unless -fresh), and training
    continues up to `steps`.

Usage
    bsmsTrain [-case dir] [-dict file] [-fresh]

    system/bsmsTrainDict:
    \verbatim
        cases         ("." "../run2"); // recorded cases, relative to this one
        startTime     0.1;            // first time used (default: all)
        inputFields   (U p);
        outputFields  (U p);
        model         bsms;           // bsms | mgn
        latent        128;
        hidden        128;
        messagePasses 15;             // mgn only
        levels        { seeding closeCenter; minNodes 100; }
        steps         2000;
        batch         1;
        lr            1e-4;
        lrMin         1e-6;
        lrDecay       0.1;
        decaySteps    5e6;
        noise         0;
        normAccumulations 1000;
        seed          0;
        checkpoint    "constant/bsmsModel.pt";
        checkpointInterval 1000;
        printInterval 100;
    \endverbatim
    Everything but inputFields and outputFields has the default shown
    (checkpointInterval: steps; printInterval: steps/20).  Bad entries, a
    field missing from a case's time directory, a case with fewer than two
    written times and a checkpoint that does not match stop with a
    FatalIOError naming the file and the entry.  Serial only.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "polyMesh.H"
#include "IOdictionary.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "dictionaryChecks.H"
#include "meshGraph.H"
#include "bsmsPooling.H"
#include "bsmsExport.H"
#include "bsmsTrainerFacade.H"

#include <chrono>
#include <cstdio>
#include <random>
#include <stdexcept>

using namespace Foam;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- One field file's internal field: components per cell and the values
//  (cell-major)
struct fieldValues
{
    label nComp = 0;
    std::vector<double> values;
};


fieldValues readFieldFile
(
    const fileName& file,
    const label nCells,
    const dictionary& trainDict,
    const word& key
)
{
    IFstream is(file);
    if (!is.good())
    {
        FatalIOErrorInFunction(trainDict)
            << "The field file " << file << " (entry '" << key << "' in "
            << trainDict.name() << ") does not exist or cannot be read"
            << exit(FatalIOError);
    }
    const dictionary d(is, true);
    word cls;
    if (d.found("FoamFile")) d.subDict("FoamFile").readIfPresent("class", cls);

    fieldValues f;
    if (cls == "volScalarField")
    {
        const scalarField v("internalField", d, nCells);
        f.nComp = 1;
        f.values.assign(v.begin(), v.end());
    }
    else if (cls == "volVectorField")
    {
        const vectorField v("internalField", d, nCells);
        f.nComp = 3;
        f.values.reserve(3*nCells);
        for (const vector& x : v)
        {
            for (direction c = 0; c < 3; ++c) f.values.push_back(x[c]);
        }
    }
    else
    {
        FatalIOErrorInFunction(trainDict)
            << "The field file " << file << " (entry '" << key << "' in "
            << trainDict.name() << ") is of class '" << cls
            << "'; volScalarField or volVectorField expected"
            << exit(FatalIOError);
    }
    return f;
}


//- The fields of one time directory as one node-major sample; nComp is
//  set from the first call and checked on the others
std::vector<double> readSample
(
    const fileName& timeDir,
    const wordList& names,
    const label nCells,
    const dictionary& trainDict,
    const word& key,
    label& nComp
)
{
    List<fieldValues> fs(names.size());
    label n = 0;
    forAll(names, i)
    {
        fs[i] = readFieldFile(timeDir/names[i], nCells, trainDict, key);
        n += fs[i].nComp;
    }
    if (nComp == 0) nComp = n;
    if (n != nComp)
    {
        FatalIOErrorInFunction(trainDict)
            << "The fields " << names << " (entry '" << key << "') in "
            << timeDir << " have " << n << " components, other times "
            << nComp << exit(FatalIOError);
    }
    std::vector<double> s(std::size_t(nCells)*n);
    label o = 0;
    for (const fieldValues& f : fs)
    {
        for (label i = 0; i < nCells; ++i)
        {
            for (label c = 0; c < f.nComp; ++c)
            {
                s[std::size_t(i)*n + o + c] = f.values[i*f.nComp + c];
            }
        }
        o += f.nComp;
    }
    return s;
}


wordList getWords(const dictionary& dict, const word& key)
{
    using namespace dictionaryChecks;
    const wordList w
    (
        getAs<wordList>(dict, key, "a list of field names, e.g. (U p)")
    );
    if (w.empty())
    {
        badEntry(dict, key, "()", "a non-empty list of field names");
    }
    return w;
}


double secondsSince(const std::chrono::steady_clock::time_point& t0)
{
    return std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - t0
    ).count();
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Train a BSMS-GNN (or MeshGraphNets) model that advances the fields"
        " of recorded cases by one written time; settings in"
        " system/bsmsTrainDict"
    );
    argList::noParallel();
    #include "addDictOption.H"
    argList::addBoolOption
    (
        "fresh",
        "start anew even if the checkpoint exists (it is overwritten)"
    );

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createPolyMesh.H"

    using namespace dictionaryChecks;

    const word dictName("bsmsTrainDict");
    #include "setSystemMeshDictionaryIO.H"
    const IOdictionary dict(dictIO);

    // Settings
    const fileNameList caseNames
    (
        getAsOrDefault<fileNameList>
        (
            dict, "cases", fileNameList(1, fileName(".")),
            "a list of case directories"
        )
    );
    if (caseNames.empty())
    {
        badEntry(dict, "cases", "()", "a non-empty list of case directories");
    }
    const wordList inNames(getWords(dict, "inputFields"));
    const wordList outNames(getWords(dict, "outputFields"));

    const word model
    (
        getAsOrDefault<word>(dict, "model", "bsms", "one of 2(bsms mgn)")
    );
    if (model != "bsms" && model != "mgn")
    {
        badEntry(dict, "model", model, "one of 2(bsms mgn)");
    }

    gnnTorch::trainerSettings s;
    s.model = model;
    s.latent = getLabelAtLeast(dict, "latent", 128, 1);
    s.hidden = getLabelAtLeast(dict, "hidden", 128, 1);
    s.nMessagePasses = getLabelAtLeast(dict, "messagePasses", 15, 1);
    s.lr = getPositive(dict, "lr", 1e-4);
    s.lrMin = getPositive(dict, "lrMin", 1e-6);
    s.lrDecay = getPositive(dict, "lrDecay", 0.1);
    s.decaySteps = getPositive(dict, "decaySteps", 5e6);
    {
        const scalar noise =
            getAsOrDefault<scalar>(dict, "noise", 0, "a number >= 0");
        if (!(noise >= 0)) badEntry(dict, "noise", name(noise), "a number >= 0");
        if (noise > 0) s.noiseStd.assign(1, noise);
    }
    s.normAccumulations = getLabelAtLeast(dict, "normAccumulations", 1000, 1);
    s.seed = getLabelAtLeast(dict, "seed", 0, 0);

    const label nSteps = getLabelAtLeast(dict, "steps", 2000, 1);
    const label batch = getLabelAtLeast(dict, "batch", 1, 1);
    const label ckInterval =
        getLabelAtLeast(dict, "checkpointInterval", nSteps, 1);
    const label printInterval =
        getLabelAtLeast(dict, "printInterval", max(nSteps/20, 1), 1);
    fileName checkpoint
    (
        getAsOrDefault<fileName>
        (
            dict, "checkpoint", fileName("constant/bsmsModel.pt"),
            "a file name"
        )
    );
    checkpoint.expand();
    if (!checkpoint.isAbsolute()) checkpoint = runTime.path()/checkpoint;

    const scalar tStart =
        getAsOrDefault<scalar>(dict, "startTime", -GREAT, "a time");

    dictionary levelsDict;
    levelsDict.add("seeding", word("closeCenter"));
    if (dict.found("levels", keyType::LITERAL))
    {
        if (!dict.isDict("levels"))
        {
            badEntry
            (
                dict, "levels", entryText(dict, "levels"),
                "a sub-dictionary of bsmsLevels settings"
            );
        }
        levelsDict = dict.subDict("levels");
    }

    // The graph (cells of this case's mesh) and its levels
    const label nCells = mesh.nCells();
    const int dim = mesh.geometricD()[2] < 0 ? 2 : 3;
    const auto t0 = std::chrono::steady_clock::now();
    const meshGraph fine(mesh, meshGraph::nodeType::cells);
    bsmsData::hierarchy h;
    if (model == "bsms")
    {
        bsmsPooling P(levelsDict);
        P.build(fine);
        h = bsmsExport(P, dim);
    }
    else
    {
        h = bsmsExport(fine, dim);
    }
    {
        const std::string err = h.check();
        if (!err.empty())
        {
            FatalErrorInFunction
                << "Inconsistent graph hierarchy: " << err.c_str()
                << exit(FatalError);
        }
    }
    Info<< "Graph: " << nCells << " cells, " << h.levels.size()
        << " levels (nodes";
    for (const auto& l : h.levels) Info<< ' ' << label(l.nNodes);
    Info<< "), dim " << dim << ", "
        << secondsSince(t0) << " s" << nl << endl;

    // The training pairs
    label nIn = 0, nOut = 0;
    std::vector<std::vector<double>> inputs, targets;
    for (const fileName& cn : caseNames)
    {
        fileName dir(cn);
        dir.expand();
        if (!dir.isAbsolute()) dir = runTime.path()/dir;
        dir.clean();
        // The written times (findTimes also lists "constant")
        DynamicList<instant> times;
        for (const instant& t : TimePaths::findTimes(dir))
        {
            if (t.name() != "constant" && t.value() >= tStart - SMALL)
            {
                times.append(t);
            }
        }
        if (times.size() < 2)
        {
            FatalIOErrorInFunction(dict)
                << "The case " << dir << " (entry 'cases' in "
                << dict.name() << ") has " << times.size()
                << " written time(s); at least 2 are needed for a"
                << " training pair (no pairs)" << exit(FatalIOError);
        }
        for (label k = 0; k + 1 < times.size(); ++k)
        {
            inputs.push_back
            (
                readSample
                (
                    dir/times[k].name(), inNames, nCells, dict,
                    "inputFields", nIn
                )
            );
            targets.push_back
            (
                readSample
                (
                    dir/times[k + 1].name(), outNames, nCells, dict,
                    "outputFields", nOut
                )
            );
        }
        Info<< "Case " << dir << ": " << times.size() << " times, "
            << times.size() - 1 << " pairs" << nl;
    }
    const label nPairs = inputs.size();
    Info<< nPairs << " training pairs, " << nIn << " input and " << nOut
        << " output components per node" << nl << endl;

    s.nIn = nIn;
    s.nOut = nOut;

    // No noise on input components that are constant over the data (the
    // empty direction's velocity in 2D, say): the normaliser scales them by
    // its epsilon, so noise there would swamp every other input
    if (!s.noiseStd.empty())
    {
        const double noise = s.noiseStd[0];
        s.noiseStd.assign(nIn, noise);
        label nConst = 0;
        for (label c = 0; c < nIn; ++c)
        {
            const double v0 = inputs[0][c];
            bool constant = true;
            for (const auto& x : inputs)
            {
                for (label i = c; constant && i < label(x.size()); i += nIn)
                {
                    constant = x[i] == v0;
                }
                if (!constant) break;
            }
            if (constant)
            {
                s.noiseStd[c] = 0;
                ++nConst;
            }
        }
        Info<< "Input noise " << noise << " on " << nIn - nConst << " of "
            << nIn << " components (none on those constant in the data)"
            << nl;
    }

    // The trainer, resumed from the checkpoint if there is one
    std::unique_ptr<gnnTorch::bsmsTrainerFacade> T;
    try
    {
        T.reset(new gnnTorch::bsmsTrainerFacade(h, s));
    }
    catch (const std::exception& e)
    {
        FatalErrorInFunction
            << "Cannot build the model: " << e.what() << exit(FatalError);
    }
    Info<< "Model " << T->describe().c_str() << ", "
        << label(T->nParameters()) << " parameters" << nl;
    if (!args.found("fresh") && isFile(checkpoint))
    {
        try
        {
            T->load(checkpoint);
        }
        catch (const std::exception& e)
        {
            FatalIOErrorInFunction(dict)
                << "Cannot resume from the checkpoint " << checkpoint
                << " (entry 'checkpoint' in " << dict.name() << "): "
                << e.what() << nl << "    (use -fresh to start anew)"
                << exit(FatalIOError);
        }
        Info<< "Resumed from " << checkpoint << " at step "
            << label(T->step()) << nl;
    }
    Info<< endl;

    auto save = [&]()
    {
        mkDir(checkpoint.path());
        try
        {
            T->save(checkpoint);
        }
        catch (const std::exception& e)
        {
            FatalIOErrorInFunction(dict)
                << "Cannot write the checkpoint " << checkpoint
                << " (entry 'checkpoint'): " << e.what()
                << exit(FatalIOError);
        }
    };

    // Training
    const label start = T->step();
    if (start >= nSteps)
    {
        Info<< "The checkpoint is at step " << start << " >= steps "
            << nSteps << ": nothing to train" << nl;
    }
    const auto tTrain = std::chrono::steady_clock::now();
    double lossSum = 0;
    label lossCount = 0;
    char buf[200];
    std::vector<double> x, y;
    for (label step = start; step < nSteps; ++step)
    {
        std::mt19937_64 rng(s.seed*0x9E3779B97F4A7C15ULL + std::uint64_t(step));
        std::uniform_int_distribution<label> pick(0, nPairs - 1);
        x.clear();
        y.clear();
        for (label b = 0; b < batch; ++b)
        {
            const label k = pick(rng);
            x.insert(x.end(), inputs[k].begin(), inputs[k].end());
            y.insert(y.end(), targets[k].begin(), targets[k].end());
        }
        double l = 0;
        try
        {
            l = T->trainStep(x, y);
        }
        catch (const std::exception& e)
        {
            FatalErrorInFunction
                << "Training step " << step + 1 << ": " << e.what()
                << exit(FatalError);
        }
        lossSum += l;
        ++lossCount;

        const label done = step + 1;
        if (done % printInterval == 0 || done == nSteps)
        {
            const double el = secondsSince(tTrain);
            const double eta = el/(done - start)*(nSteps - done);
            std::snprintf
            (
                buf, sizeof(buf), "step %d/%d  loss %.3e  lr %.3e  ETA %.0f s",
                int(done), int(nSteps), lossSum/lossCount,
                T->learningRate(), eta
            );
            Info<< buf << endl;
            lossSum = 0;
            lossCount = 0;
        }
        if (done % ckInterval == 0 || done == nSteps)
        {
            save();
            Info<< "Wrote the checkpoint " << checkpoint << " at step "
                << done << endl;
        }
    }
    if (nSteps > start)
    {
        std::snprintf
        (
            buf, sizeof(buf), "%d steps in %.2f s (%.4f s per step)",
            int(nSteps - start), secondsSince(tTrain),
            secondsSince(tTrain)/(nSteps - start)
        );
        Info<< nl << buf << nl;
    }

    // The loss on every pair without noise
    {
        double sum = 0;
        for (label k = 0; k < nPairs; ++k)
        {
            sum += T->loss(inputs[k], targets[k]);
        }
        std::snprintf(buf, sizeof(buf), "%.6e", sum/nPairs);
        Info<< "Final one-step loss over " << nPairs << " pairs (no noise): "
            << buf << nl;
    }

    Info<< nl << "End" << nl << endl;
    return 0;
}


// ************************************************************************* //
