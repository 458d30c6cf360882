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
    of a recorded case it predicts the output fields at t_{k+1} (their
    increment by default; see bsmsModelSpec).  The graph is the cell graph
    of the current case's mesh (nodes = cell centres, edges = internal
    faces), pooled into levels as bsmsLevels does; every recorded case must
    be on this mesh.  Node inputs: the input fields and one 0/1 column per
    nodeTypes entry (cells on those patches).  The model's time step
    deltaT is the (uniform) interval of the written times.

    Training pairs: every two consecutive written times (the 0 directory
    included, times before startTime left out) of every case.  Each step
    draws `batch` pairs (with replacement, from a generator seeded by
    (seed, step), so that a resumed run draws what an uninterrupted one
    would) and takes one Adam step on the one-step L2 loss of the
    normalised outputs.  Gaussian noise of standard deviation `noise` is
    added to the input fields (none on components constant over all the
    data, such as the empty direction's velocity in 2D), and an increment
    target is taken from the noisy input, so that the model learns to
    correct its own rollout error (MeshGraphNets' noise injection).
    Training stops at `steps` or after `maxTrainTime` seconds of training,
    whichever comes first.

    Validation (optional): rollouts from the first time (>= startTime) of
    each validation case, every `interval` steps and at the end, with the
    root mean square errors of the output fields (physical units, over all
    cells and output components) as Table 4.5 of the dissertation uses
    them:
        RMSE-1   one-step error: each step predicted from the recorded state
        RMSE-50  rollout error over the first 50 steps:
                 sqrt(mean over steps 1..50 of the mean squared error)
        RMSE-all the same over the whole trajectory
    (components: not the empty direction's in 2D).  For reference the log
    gives the RMSE-50 and RMSE-all of holding the start state.
    Written to postProcessing/bsmsTrain/validation.dat (one line per
    validation) and, for the last one, the rollout error per step to
    postProcessing/bsmsTrain/rollout_<case>.dat.  The log reports the
    training time per step, the inference time per model step and the
    peak memory (resident set) of the process and of the training.

    Progress every printInterval steps:
        step 100/2000  loss 1.23e-03  lr 1.00e-04  ETA 12 s
    (loss: the mean training loss of the steps since the previous line).
    Checkpoints every checkpointInterval steps and at the end; an existing
    checkpoint is resumed from its step (unless -fresh), and training
    continues up to `steps`.

Usage
    bsmsTrain [-case dir] [-dict file] [-fresh]
    mpirun -np N bsmsTrain -parallel [-fresh]   (N <= batch)

    system/bsmsTrainDict:
    \verbatim
        cases         ("." "../run2"); // recorded cases, relative to this one
        startTime     0.1;            // first time used (default: all)
        inputFields   (U p);
        outputFields  (U p);          // among the inputFields
        nodeTypes     (inlet outlet wall); // default: every patch but empty
        predict       increment;      // increment | state
        model         bsms;           // bsms | mgn
        latent        128;
        hidden        128;
        messagePasses 15;             // mgn only
        levels        { seeding closeCenter; minNodes 100; }
        steps         2000;
        batch         1;
        gradientShards 4;             // min(batch, max(4, ranks))
        lr            1e-4;
        lrMin         1e-6;
        lrDecay       0.1;
        decaySteps    5e6;
        noise         0;
        normAccumulations 1000;
        seed          0;
        checkpoint    "constant/bsmsModel.pt";
        maxTrainTime  1e30;           // wall-clock budget [s]
        checkpointInterval 1000;
        printInterval 100;
        validation    { cases ("../held"); interval 1000; }
    \endverbatim
    Everything but inputFields and outputFields has the default shown
    (checkpointInterval: steps; printInterval: steps/20; no validation;
    gradientShards: 4, or the number of ranks if more, at most batch).
    lr and lrMin lie in (0, 1] (Adam moves a weight by up to lr a step),
    lrDecay in (0, 1], decaySteps in [1, 1e300], noise in [0, 1e30] (the
    network computes in single precision).
    bsmsTrain writes the model dictionary (bsmsModelSpec) beside the
    checkpoint: constant/bsmsModel.pt -> constant/bsmsModelDict, with the
    training range of every state component (inputMin, inputMax: the
    smallest and largest value over the training states), against which
    bsmsFoam and bsmsSurrogate check the states they are fed.  Bad entries, a
    field missing from a case's time directory, a case with fewer than two
    written times and a checkpoint that does not match stop with a
    FatalIOError naming the file and the entry.  Every step's loss goes to
    postProcessing/bsmsTrain/loss.dat (step, loss, learning rate).

    Gradient shards: every step's batch of B pairs is cut into
    gradientShards = S contiguous shards (shard k: pairs [k B/S,
    (k+1) B/S)).  Each shard goes through forward and backward alone, and
    the batch's gradient is the shards' gradients added in shard order,
    each weighted by its share of the batch (the loss is the batch mean),
    in double and rounded to float once; the normalisers' statistics are
    added shard by shard too (graphNetTrainer::trainShards).  So a step is
    a function of the batch and S only: any number of ranks up to S gives
    the same training bit for bit (with one torch thread per process).
    S = 1 is the plain whole-batch step.  The shards cost little: about 4 %
    more CPU time per step at S = 8 than at S = 1 on the cylinder wake.

    Parallel (-parallel): synchronous data-parallel training.  The data are
    the undecomposed case's: every rank reads the recorded cases from the case
    directory (no decomposePar; processor directories, if any, are not used)
    and sets up the mesh, the graph and the model as a serial run does (the
    whole mesh on every rank; the dictionaries are read by the master and sent
    to the others, as OpenFOAM does).  Each step every rank draws the step's
    pairs and noise from the same generator as a serial run (the same global
    batch) and assembles only the pairs of its shards (rank r of P: shards
    [r S/P, (r+1) S/P)).  The shards' gradients and losses travel in one
    float buffer of S slots, zero but for the rank's own shards, summed over
    the ranks with Pstream (bsmsPstreamSum; exact, since each value is
    non-zero on one rank), and every rank adds the slots in shard order
    before the same Adam step; while the normalisers accumulate, their
    per-shard statistics travel the same way (doubles).  So the ranks keep
    the same parameters (checked at the end by a hash of the parameters
    compared across the ranks) and the serial run's loss curve bit for bit
    when it has the same gradientShards.  The exchange is S x (parameters
    + 1) floats a step: fine for tens of ranks, not meant for hundreds.
    One torch thread per rank.  Only the master writes the checkpoint, the
    model dictionary and postProcessing/bsmsTrain, and runs the validation
    (the other ranks wait for it in the next gradient sum); the master's
    clock decides maxTrainTime.  The log gives the time spent in the
    gradient sums and the training's CPU time summed over the ranks.  A
    batch smaller than the number of ranks cannot be shared and stops with
    a FatalIOError on 'batch'; gradientShards below the number of ranks or
    above the batch with one on 'gradientShards'.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "polyMesh.H"
#include "IOdictionary.H"
#include "IFstream.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "dictionaryChecks.H"
#include "bsmsModelSpec.H"
#include "bsmsFieldIO.H"
#include "bsmsSurrogateModel.H"
#include "bsmsTrajectory.H"
#include "bsmsPstreamSum.H"
#include "Pstream.H"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <random>
#include <stdexcept>

using namespace Foam;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

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


fileNameList getCases(const dictionary& dict, const fileNameList& deflt)
{
    using namespace dictionaryChecks;
    const fileNameList c
    (
        getAsOrDefault<fileNameList>
        (
            dict, "cases", deflt, "a list of case directories"
        )
    );
    if (c.empty())
    {
        badEntry(dict, "cases", "()", "a non-empty list of case directories");
    }
    return c;
}


double secondsSince(const std::chrono::steady_clock::time_point& t0)
{
    return std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - t0
    ).count();
}


//- CPU seconds of this process (all its threads)
double cpuSeconds()
{
    timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9*t.tv_nsec;
}


//- A /proc/self/status entry in MB (VmRSS, VmHWM), 0 if unknown
double procStatusMB(const std::string& key)
{
    std::ifstream is("/proc/self/status");
    std::string k;
    while (is >> k)
    {
        if (k == key + ":")
        {
            double kB = 0;
            is >> kB;
            return kB/1024.0;
        }
        std::string rest;
        std::getline(is, rest);
    }
    return 0;
}


} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

//- gradientShards when the dictionary does not say: this many, or one per
//  rank with more ranks, but at most the batch
static const Foam::label defaultShards = 4;


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Train a BSMS-GNN (or MeshGraphNets) model that advances the fields"
        " of recorded cases by one written time; settings in"
        " system/bsmsTrainDict"
    );
    // -parallel: data-parallel training on the undecomposed case (no
    // processor directories needed)
    argList::noCheckProcessorDirectories();
    #include "addDictOption.H"
    argList::addBoolOption
    (
        "fresh",
        "start anew even if the checkpoint exists (it is overwritten)"
    );

    #include "setRootCase.H"

    // Parallel: every rank sets up on the undecomposed case (the global
    // case, not processor<N>), as a serial run does.  No function objects
    // (as createTime.H for a utility), the controlDict's libs loaded
    const bool parallel = Pstream::parRun();
    const label nRanks = parallel ? Pstream::nProcs() : 1;
    const label rank = parallel ? Pstream::myProcNo() : 0;

    Foam::Time runTime
    (
        Foam::Time::controlDictName, args.rootPath(), args.globalCaseName(),
        "system", "constant", false, true
    );
    #include "createPolyMesh.H"

    using namespace dictionaryChecks;

    const word dictName("bsmsTrainDict");
    #include "setSystemMeshDictionaryIO.H"
    IOdictionary dict(dictIO);
    // Parallel: the master reads the dictionary and sends it on; the file
    // name in the other ranks' error messages
    static_cast<dictionary&>(dict).name() = dict.objectPath();

    // The model
    bsmsModelSpec spec;
    spec.model = getAsOrDefault<word>(dict, "model", "bsms", "one of 2(bsms mgn)");
    if (spec.model != "bsms" && spec.model != "mgn")
    {
        badEntry(dict, "model", spec.model, "one of 2(bsms mgn)");
    }
    spec.latent = getLabelAtLeast(dict, "latent", 128, 1);
    spec.hidden = getLabelAtLeast(dict, "hidden", 128, 1);
    spec.messagePasses = getLabelAtLeast(dict, "messagePasses", 15, 1);
    spec.levels.add("seeding", word("closeCenter"));
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
        spec.levels = dict.subDict("levels");
    }
    spec.inputFields = getWords(dict, "inputFields");
    spec.outputFields = getWords(dict, "outputFields");
    spec.nodeTypes = getAsOrDefault<List<wordRe>>
    (
        dict, "nodeTypes", defaultNodeTypes(mesh),
        "a list of patch names or regular expressions"
    );
    for (const wordRe& t : spec.nodeTypes)
    {
        bool found = false;
        for (const polyPatch& pp : mesh.boundaryMesh())
        {
            found = found || t.match(pp.name());
        }
        if (!found)
        {
            OStringStream os;
            os << "patch names or regular expressions matching patches of "
               << mesh.boundaryMesh().names();
            badEntry(dict, "nodeTypes", t, os.str());
        }
    }
    {
        const word p
        (
            getAsOrDefault<word>(dict, "predict", "increment", "increment or state")
        );
        if (p != "increment" && p != "state")
        {
            badEntry(dict, "predict", p, "increment or state");
        }
        spec.increment = (p == "increment");
    }

    // Training settings
    gnnTorch::trainerSettings s;
    // Bounds that keep the single-precision network finite: Adam moves
    // each weight by up to lr per step (lr > 1 throws any O(1) weight
    // away), lrDecay > 1 grows lr without bound, noise beyond 1e30 leaves
    // the float range
    s.lr = getInRange(dict, "lr", 1e-4, 0, 1);
    s.lrMin = getInRange(dict, "lrMin", 1e-6, 0, 1);
    s.lrDecay = getInRange(dict, "lrDecay", 0.1, 0, 1);
    s.decaySteps = getInRange(dict, "decaySteps", 5e6, 0, 1e300);
    if (s.decaySteps < 1)
    {
        badEntry(dict, "decaySteps", name(s.decaySteps),
            "a number of steps >= 1 and <= 1e300");
    }
    const string allowedNoise("a finite number >= 0 and <= 1e30");
    const scalar noise =
        getAsOrDefault<scalar>(dict, "noise", 0, allowedNoise);
    if (!(noise >= 0 && noise <= 1e30))
    {
        badEntry(dict, "noise", name(noise), allowedNoise);
    }
    s.normAccumulations = getLabelAtLeast(dict, "normAccumulations", 1000, 1);
    s.seed = getLabelAtLeast(dict, "seed", 0, 0);

    const label nSteps = getLabelAtLeast(dict, "steps", 2000, 1);
    const label batch = getLabelAtLeast(dict, "batch", 1, 1);
    if (batch < nRanks)
    {
        badEntry
        (
            dict, "batch", name(batch),
            "a batch of at least the number of ranks (" + name(nRanks)
          + "): each rank trains on its share of every step's batch"
        );
    }
    // The batch in shards (graphNetTrainer::trainShards): forward and
    // backward per shard, the shards' gradients added in shard order, so
    // that any number of ranks up to gradientShards trains bit for bit as
    // one rank does
    const label nShards = getLabelAtLeast
    (
        dict, "gradientShards", min(batch, max(defaultShards, nRanks)), 1
    );
    if (nShards > batch || nShards < nRanks)
    {
        badEntry
        (
            dict, "gradientShards", name(nShards),
            "from the number of ranks (" + name(nRanks) + ") to batch ("
          + name(batch) + "): every rank takes whole shards of each batch"
        );
    }
    // This rank's shards [shardFirst, shardFirst + nMineShards), samples
    // [shareFirst, shareFirst + nMine) of every batch
    const label shardFirst = rank*nShards/nRanks;
    const label nMineShards = (rank + 1)*nShards/nRanks - shardFirst;
    const label shareFirst = shardFirst*batch/nShards;
    const label nMine =
        (shardFirst + nMineShards)*batch/nShards - shareFirst;
    const scalar maxTrainTime = getPositive(dict, "maxTrainTime", 1e30);
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

    const fileNameList caseNames(getCases(dict, fileNameList(1, fileName("."))));

    fileNameList validationCases;
    label validationInterval = labelMax;
    if (dict.found("validation", keyType::LITERAL))
    {
        if (!dict.isDict("validation"))
        {
            badEntry
            (
                dict, "validation", entryText(dict, "validation"),
                "a sub-dictionary { cases (...); interval N; }"
            );
        }
        const dictionary& vd = dict.subDict("validation");
        validationCases = getCases(vd, fileNameList());
        validationInterval = getLabelAtLeast(vd, "interval", labelMax, 1);
    }

    // The recorded cases
    const label nCells = mesh.nCells();
    labelList comps;
    std::vector<bsmsTrajectory> train, valid;
    for (const fileName& cn : caseNames)
    {
        train.push_back
        (
            bsmsTrajectory::read
            (
                cn, runTime.path(), tStart, spec, comps, nCells, dict
            )
        );
        Info<< "Case " << train.back().dir << ": "
            << train.back().times.size() << " times, "
            << train.back().times.size() - 1 << " pairs" << nl;
    }
    for (const fileName& cn : validationCases)
    {
        valid.push_back
        (
            bsmsTrajectory::read
            (
                cn, runTime.path(), tStart, spec, comps, nCells, dict
            )
        );
        Info<< "Validation case " << valid.back().dir << ": "
            << valid.back().times.size() - 1 << " rollout steps" << nl;
    }
    spec.inputComponents = comps;
    spec.check(dict);

    // The model time step: the interval of the written times (uniform)
    spec.deltaT = train[0].times[1] - train[0].times[0];
    for (const bsmsTrajectory& tr : train)
    {
        for (label k = 0; k + 1 < tr.times.size(); ++k)
        {
            const scalar dt = tr.times[k + 1] - tr.times[k];
            if (mag(dt - spec.deltaT) > 1e-4*spec.deltaT)
            {
                FatalIOErrorInFunction(dict)
                    << "The written times of " << tr.dir << " (entry 'cases'"
                    << " in " << dict.name() << ") are not uniform: "
                    << tr.times[k] << " to " << tr.times[k + 1]
                    << " is not the model time step " << spec.deltaT
                    << " of the first interval" << exit(FatalIOError);
            }
        }
    }

    std::vector<std::pair<label, label>> pairs;
    for (label c = 0; c < label(train.size()); ++c)
    {
        for (label k = 0; k + 1 < train[c].times.size(); ++k)
        {
            pairs.push_back({c, k});
        }
    }
    const label nPairs = pairs.size();
    const label nState = spec.nState();

    // The training range per state component, for the model dictionary
    // (bsmsInputRange checks rollout states against it)
    spec.inputMin.setSize(nState, GREAT);
    spec.inputMax.setSize(nState, -GREAT);
    for (const bsmsTrajectory& tr : train)
    {
        for (const auto& st : tr.states)
        {
            for (std::size_t i = 0; i < st.size(); ++i)
            {
                const label c = i % nState;
                spec.inputMin[c] = min(spec.inputMin[c], st[i]);
                spec.inputMax[c] = max(spec.inputMax[c], st[i]);
            }
        }
    }
    Info<< nPairs << " training pairs; per node " << nState
        << " input field components " << spec.inputFields << ", "
        << spec.nTypes() << " node types " << spec.nodeTypes << ", "
        << spec.nOut() << " outputs " << spec.outputFields << " ("
        << (spec.increment ? "increment" : "state") << " over deltaT "
        << spec.deltaT << ")" << nl << endl;

    // The model, resumed from the checkpoint if there is one
    const double rssStart = procStatusMB("VmRSS");
    bsmsSurrogateModel m(mesh, spec, s);
    // Noise on the state components that vary in the data (and are used)
    std::vector<double> noiseStd(nState, 0.0);
    if (noise > 0)
    {
        label nVar = 0;
        for (label c = 0; c < nState; ++c)
        {
            const double v0 = train[0].states[0][c];
            // Unused components count as constant
            bool constant = true;
            if (m.used(c))
            {
                for (const bsmsTrajectory& tr : train)
                {
                    for (const auto& x : tr.states)
                    {
                        for (std::size_t i = c; constant && i < x.size(); i += nState)
                        {
                            constant = x[i] == v0;
                        }
                    }
                }
            }
            if (!constant)
            {
                noiseStd[c] = noise;
                ++nVar;
            }
        }
        Info<< "Input noise " << noise << " on " << nVar << " of " << nState
            << " field components (none on those constant in the data or"
            << " in the empty direction)" << nl;
    }
    Info<< "Graph: " << nCells << " cells, " << m.graph().levels.size()
        << " levels (nodes " << m.levelSizes().c_str() << "), "
        << m.buildSeconds() << " s" << nl
        << "Model " << m.net().describe().c_str() << ", "
        << label(m.net().nParameters()) << " parameters" << nl;
    if (!args.found("fresh") && isFile(checkpoint))
    {
        try
        {
            m.net().load(checkpoint);
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
            << label(m.net().step()) << nl;
    }
    Info<< endl;

    bsmsPstreamSum rankSum;
    if (parallel)
    {
        gnnTorch::setNumThreads(1);
        Info<< "Parallel run: " << nRanks << " ranks, synchronous data"
            << " parallel on the undecomposed case's data (processor"
            << " directories are not used): each rank trains on its shards"
            << " of every step's batch of " << batch << " (this rank "
            << nMineShards << " of " << nShards << " shards, " << nMine
            << " pairs), the shards' gradients summed over the ranks each"
            << " step (Pstream, " << nShards << " x "
            << label(m.net().nParameters()) + 1 << " floats); "
            << gnnTorch::numThreads() << " torch thread per rank" << nl
            << endl;
    }
    Info<< "Batch of " << batch << " in " << nShards << " gradient shards"
        << " (the same training on any number of ranks up to " << nShards
        << ")" << nl << endl;
    const bool master = Pstream::master();

    auto save = [&]()
    {
        if (!master) return;
        mkDir(checkpoint.path());
        try
        {
            m.net().save(checkpoint);
        }
        catch (const std::exception& e)
        {
            FatalIOErrorInFunction(dict)
                << "Cannot write the checkpoint " << checkpoint
                << " (entry 'checkpoint'): " << e.what()
                << exit(FatalIOError);
        }
        OFstream os(bsmsSpecFile(checkpoint));
        os  << "// Model dictionary of " << checkpoint.name()
            << ", written by bsmsTrain" << nl;
        spec.write(os);
    };

    const fileName outDir(runTime.path()/"postProcessing"/"bsmsTrain");
    autoPtr<OFstream> lossFile;
    if (master)
    {
        mkDir(outDir);
        lossFile.reset(new OFstream(outDir/"loss.dat"));
        lossFile() << "# step loss lr" << nl;
    }
    // The reference a model must beat: the start state held (persistence)
    for (const bsmsTrajectory& tr : valid)
    {
        if (!master) break;
        const bsmsRolloutErrors r = bsmsPersistence(m, tr);
        char buf[200];
        std::snprintf
        (
            buf, sizeof(buf),
            "Validation %s, the start state held: RMSE-50 %.4e  RMSE-all %.4e",
            tr.dir.name().c_str(), r.rmse50, r.rmseAll
        );
        Info<< buf << nl;
    }
    Info<< endl;

    autoPtr<OFstream> validationFile;
    auto runValidation = [&](const label step, const bool last)
    {
        if (valid.empty() || !master) return;
        if (!validationFile.valid())
        {
            validationFile.reset(new OFstream(outDir/"validation.dat"));
            validationFile()
                << "# step case RMSE-1 RMSE-50 RMSE-all inferenceSecondsPerStep"
                << nl;
        }
        char buf[300];
        for (const bsmsTrajectory& tr : valid)
        {
            const bsmsRolloutErrors r = bsmsValidate(m, tr);
            std::snprintf
            (
                buf, sizeof(buf),
                "Validation %s at step %d: RMSE-1 %.4e  RMSE-50 %.4e"
                "  RMSE-all %.4e  (%d steps, %.2f ms per model step)",
                tr.dir.name().c_str(), int(step), r.rmse1, r.rmse50,
                r.rmseAll, int(r.mse.size()), 1e3*r.secondsPerStep
            );
            Info<< buf << endl;
            std::snprintf
            (
                buf, sizeof(buf), "%d %s %.6e %.6e %.6e %.6e", int(step),
                tr.dir.name().c_str(), r.rmse1, r.rmse50, r.rmseAll,
                r.secondsPerStep
            );
            validationFile() << buf << endl;
            if (last)
            {
                OFstream os(outDir/("rollout_" + tr.dir.name() + ".dat"));
                os  << "# rollout of the model at training step " << step
                    << " from t = " << tr.times[0] << " (deltaT "
                    << spec.deltaT << ")" << nl
                    << "# step time RMSE(step) RMSE(steps 1..step)" << nl;
                double sum = 0;
                for (std::size_t k = 0; k < r.mse.size(); ++k)
                {
                    sum += r.mse[k];
                    std::snprintf
                    (
                        buf, sizeof(buf), "%d %.6g %.6e %.6e", int(k + 1),
                        tr.times[k + 1], std::sqrt(r.mse[k]),
                        std::sqrt(sum/(k + 1))
                    );
                    os << buf << nl;
                }
            }
        }
    };

    // Training
    const label start = m.net().step();
    if (start >= nSteps)
    {
        Info<< "The checkpoint is at step " << start << " >= steps "
            << nSteps << ": nothing to train" << nl;
    }
    const double rssTrain = procStatusMB("VmRSS");
    const auto tTrain = std::chrono::steady_clock::now();
    const double cpuTrain = cpuSeconds();
    double validationSeconds = 0;
    double lossSum = 0;
    label lossCount = 0;
    char buf[300];
    std::vector<double> x, y, noisy;
    label step = start;
    while (step < nSteps)
    {
        std::mt19937_64 rng(s.seed*0x9E3779B97F4A7C15ULL + std::uint64_t(step));
        std::uniform_int_distribution<label> pick(0, nPairs - 1);
        std::normal_distribution<double> gauss(0.0, 1.0);
        x.clear();
        y.clear();
        // The samples of this rank's shards; the draws of all (the same
        // stream on every rank)
        for (label b = 0; b < batch; ++b)
        {
            const auto& pr = pairs[pick(rng)];
            const bsmsTrajectory& tr = train[pr.first];
            if (b < shareFirst || b >= shareFirst + nMine)
            {
                if (noise > 0)
                {
                    const std::size_t nx = tr.states[pr.second].size();
                    for (std::size_t i = 0; i < nx; ++i)
                    {
                        if (noiseStd[i % nState] > 0) gauss(rng);
                    }
                }
                continue;
            }
            noisy = tr.states[pr.second];
            if (noise > 0)
            {
                for (std::size_t i = 0; i < noisy.size(); ++i)
                {
                    const double sd = noiseStd[i % nState];
                    if (sd > 0) noisy[i] += sd*gauss(rng);
                }
            }
            m.appendInput(noisy, x);
            m.appendTarget(noisy, tr.states[pr.second + 1], y);
        }
        double l = 0;
        try
        {
            l = m.net().trainShards
            (
                x, y, shardFirst, nMineShards, nShards, batch, rankSum
            );
        }
        catch (const std::exception& e)
        {
            FatalErrorInFunction
                << "Training step " << step + 1 << ": " << e.what()
                << exit(FatalError);
        }
        if (!std::isfinite(l))
        {
            FatalErrorInFunction
                << "Training step " << step + 1 << ": the loss is " << l
                << "; the last checkpoint is kept (lower lr?)"
                << exit(FatalError);
        }
        lossSum += l;
        ++lossCount;
        ++step;
        if (master)
        {
            std::snprintf
            (
                buf, sizeof(buf), "%d %.9e %.6e", int(step), l,
                m.net().learningRate()
            );
            lossFile() << buf << nl;
        }

        const double el = secondsSince(tTrain) - validationSeconds;
        // The master's clock decides, for all ranks
        bool outOfTime = el >= maxTrainTime;
        if (parallel) Pstream::scatter(outOfTime);
        const bool last = step == nSteps || outOfTime;
        if (step % printInterval == 0 || last)
        {
            const double eta =
                min(el/(step - start)*(nSteps - step), maxTrainTime - el);
            std::snprintf
            (
                buf, sizeof(buf), "step %d/%d  loss %.3e  lr %.3e  ETA %.0f s",
                int(step), int(nSteps), lossSum/lossCount,
                m.net().learningRate(), max(eta, 0.0)
            );
            Info<< buf << endl;
            lossSum = 0;
            lossCount = 0;
        }
        if (step % ckInterval == 0 || last)
        {
            save();
            Info<< "Wrote the checkpoint " << checkpoint << " at step "
                << step << endl;
        }
        if (step % validationInterval == 0 || last)
        {
            const auto tv = std::chrono::steady_clock::now();
            runValidation(step, last);
            validationSeconds += secondsSince(tv);
        }
        if (outOfTime)
        {
            Info<< "The training budget maxTrainTime " << maxTrainTime
                << " s is spent at step " << step << endl;
            break;
        }
    }
    const double peak = procStatusMB("VmHWM");
    if (step > start)
    {
        const double el = secondsSince(tTrain) - validationSeconds;
        std::snprintf
        (
            buf, sizeof(buf),
            "Training: %d steps in %.2f s (%.4f s per step; validation"
            " %.1f s not counted)",
            int(step - start), el, el/(step - start), validationSeconds
        );
        Info<< nl << buf << nl;
        // The CPU time of the training (validation included): on a loaded
        // machine the cores a run actually got
        {
            const scalar cpu = cpuSeconds() - cpuTrain;
            const scalar cpuAll =
                parallel ? returnReduce(cpu, sumOp<scalar>()) : cpu;
            const double wall = secondsSince(tTrain);
            std::snprintf
            (
                buf, sizeof(buf),
                "Training CPU time: %.2f s in this process, %.2f s summed"
                " over the %d rank(s) (%.2f cores on average)",
                cpu, cpuAll, int(nRanks), cpuAll/max(wall, 1e-30)
            );
            Info<< buf << nl;
        }
        if (parallel)
        {
            // The share of the time in the gradient sum (waiting for the
            // slower rank included), master and the most of any rank
            const scalar commMaster = rankSum.seconds();
            const scalar commMax =
                returnReduce(scalar(rankSum.seconds()), maxOp<scalar>());
            std::snprintf
            (
                buf, sizeof(buf),
                "Communication: %d gradient sums of %.3f MB, %.3f s on the"
                " master (%.1f %% of the training time; the most of any"
                " rank %.3f s), waiting for the slower rank included",
                int(rankSum.nCalls()), rankSum.bytes()/1e6, commMaster,
                100*commMaster/max(el, 1e-30), commMax
            );
            Info<< buf << nl;
        }
        std::snprintf
        (
            buf, sizeof(buf),
            "Memory: peak resident %.1f MB; %.1f MB before the model,"
            " %.1f MB before training; training peak %.1f MB above that",
            peak, rssStart, rssTrain, peak - rssTrain
        );
        Info<< buf << nl;
    }
    else if (!valid.empty())
    {
        runValidation(step, true);
    }

    // The loss on every pair without noise
    {
        double sum = 0;
        // Parallel: every rank a contiguous share of the pairs
        const label p0 = rank*nPairs/nRanks;
        const label p1 = (rank + 1)*nPairs/nRanks;
        for (label p = p0; p < p1; ++p)
        {
            const auto& pr = pairs[p];
            const bsmsTrajectory& tr = train[pr.first];
            x.clear();
            y.clear();
            m.appendInput(tr.states[pr.second], x);
            m.appendTarget(tr.states[pr.second], tr.states[pr.second + 1], y);
            sum += m.net().loss(x, y);
        }
        if (parallel) reduce(sum, sumOp<scalar>());
        std::snprintf(buf, sizeof(buf), "%.6e", sum/nPairs);
        Info<< "Final one-step loss over " << nPairs << " pairs (no noise): "
            << buf << nl;
    }

    // The ranks hold the same model (the same gradients and Adam steps)
    if (parallel)
    {
        std::snprintf
        (
            buf, sizeof(buf), "%016llx",
            static_cast<unsigned long long>(m.net().parameterHash())
        );
        List<word> hashes(nRanks);
        hashes[rank] = buf;
        Pstream::gatherList(hashes);
        if (master)
        {
            label nSame = 0;
            for (const word& h : hashes) nSame += (h == hashes[0]);
            if (nSame != nRanks)
            {
                FatalErrorInFunction
                    << "The ranks' parameters differ after training (hashes "
                    << hashes << "): the data-parallel steps went out of"
                    << " step; the checkpoint is the master's"
                    << exit(FatalError);
            }
            Info<< "Parameters identical on all " << nRanks << " ranks"
                << " (hash " << hashes[0] << ")" << nl;
        }
    }

    // The training range recorded in the model dictionary
    {
        Info<< "Training range of the inputs (inputMin, inputMax of "
            << bsmsSpecFile(checkpoint).name() << "):";
        label o = 0;
        forAll(spec.inputFields, i)
        {
            for (label c = 0; c < spec.inputComponents[i]; ++c)
            {
                if (!m.used(o + c)) continue;
                std::snprintf
                (
                    buf, sizeof(buf), " %s%s [%.4g, %.4g]",
                    spec.inputFields[i].c_str(),
                    spec.inputComponents[i] == 3
                  ? (c == 0 ? "_x" : c == 1 ? "_y" : "_z") : "",
                    spec.inputMin[o + c], spec.inputMax[o + c]
                );
                Info<< buf;
            }
            o += spec.inputComponents[i];
        }
        Info<< nl;
    }

    Info<< nl << "End" << nl << endl;
    return 0;
}


// ************************************************************************* //
