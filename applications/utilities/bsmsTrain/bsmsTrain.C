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

    Rollout training (rolloutSteps K > 1, increment models only): a sample
    is K consecutive model steps from a recorded time t_k (t_k .. t_{k+K}
    recorded), the model rolled out K steps from the (noisy) state at t_k
    and the loss the mean normalised state error over those steps
    (graphNetTrainer): what a rollout does to its own errors is trained
    on.  rolloutBackprop false detaches each step's input (the model
    still sees its own rolled-out states, at one step's cost of memory).
    A step costs about K one-step steps.

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
        decayFrom     0;              // the step the decay counts from
        noise         0;
        rolloutSteps  1;              // model steps per training sample
        rolloutBackprop true;         // gradient through the rollout
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
    lrDecay in (0, 1], decaySteps in [1, 1e300], decayFrom in [0, 1e300]
    (a resumed stage that anneals from its own first step: lr at that
    step, then the decay), noise in [0, 1e30] (the
    network computes in single precision).
    bsmsTrain writes the model dictionary (bsmsModelSpec) beside the
    checkpoint: constant/bsmsModel.pt -> constant/bsmsModelDict, with the
    training range of every state component (inputMin, inputMax: the
    smallest and largest value over the training states), against which
    bsmsFoam and bsmsSurrogate check the states they are fed.  Bad entries, a
    field missing from a case's time directory, a case with fewer than two
    written times and a checkpoint that does not match stop with a
    FatalIOError naming the file and the entry.  Every step's loss goes to
    postProcessing/bsmsTrain/loss.dat (step, loss, learning rate).  A
    resumed run (the next stage of a curriculum, say rolloutSteps 4 after
    one-step training) adds to loss.dat and validation.dat.

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

#include "bsmsReuseMemory.H"
#include "argList.H"
#include "Time.H"
#include "polyMesh.H"
#include "IOdictionary.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "dictionaryChecks.H"
#include "bsmsTrainSettings.H"
#include "bsmsFieldIO.H"
#include "bsmsSurrogateModel.H"
#include "bsmsTrajectory.H"
#include "bsmsTrainingRun.H"
#include "bsmsTrainLagrangian.H"
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

// * * * * * * * * * * * * * * * * Stage: data * * * * * * * * * * * * * * * //

//- The recorded cases; fills in the spec's components, model time step and
//  training range
bsmsTrainingData readData
(
    bsmsTrainSettings& t,
    const Time& runTime,
    const polyMesh& mesh,
    const dictionary& dict
)
{
    bsmsModelSpec& spec = t.spec;
    bsmsTrainingData d;
    const label nCells = mesh.nCells();
    labelList comps;
    for (const fileName& cn : t.cases)
    {
        d.train.push_back
        (
            bsmsTrajectory::read
            (
                cn, runTime.path(), t.startTime, spec, comps, nCells, dict
            )
        );
        Info<< "Case " << d.train.back().dir << ": "
            << d.train.back().times.size() << " times, "
            << d.train.back().times.size() - 1 << " pairs" << nl;
    }
    for (const fileName& cn : t.validationCases)
    {
        d.valid.push_back
        (
            bsmsTrajectory::read
            (
                cn, runTime.path(), t.startTime, spec, comps, nCells, dict
            )
        );
        Info<< "Validation case " << d.valid.back().dir << ": "
            << d.valid.back().times.size() - 1 << " rollout steps" << nl;
    }
    spec.inputComponents = comps;
    spec.check(dict);

    // The model time step: the interval of the written times (uniform)
    spec.deltaT = d.train[0].times[1] - d.train[0].times[0];
    for (const bsmsTrajectory& tr : d.train)
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

    const label K = t.rolloutSteps;
    for (label c = 0; c < label(d.train.size()); ++c)
    {
        for (label k = 0; k + K < d.train[c].times.size(); ++k)
        {
            d.samples.push_back({c, k});
        }
    }
    if (d.samples.empty())
    {
        FatalIOErrorInFunction(dict)
            << "rolloutSteps " << K << " (entry 'rolloutSteps' in "
            << dict.name() << ") needs a case with at least " << K + 1
            << " written times; the longest has "
            << d.train[0].times.size() << exit(FatalIOError);
    }

    // The training range per state component, for the model dictionary
    // (bsmsInputRange checks rollout states against it)
    const label nState = spec.nState();
    spec.inputMin.setSize(nState, GREAT);
    spec.inputMax.setSize(nState, -GREAT);
    for (const bsmsTrajectory& tr : d.train)
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
    Info<< label(d.samples.size())
        << (K == 1 ? " training pairs" : " training samples") << "; per node "
        << nState << " input field components " << spec.inputFields << ", "
        << spec.nTypes() << " node types " << spec.nodeTypes << ", "
        << spec.nOut() << " outputs " << spec.outputFields << " ("
        << (spec.increment ? "increment" : "state") << " over deltaT "
        << spec.deltaT << ")" << nl;
    if (K > 1)
    {
        Info<< "Rollout training: " << K << " model steps per sample ("
            << (t.trainer.rolloutBackprop ? "gradient through the rollout"
              : "each step's input detached") << ")" << nl;
    }
    Info<< endl;
    return d;
}


// * * * * * * * * * * * * * * * * Stage: model  * * * * * * * * * * * * * * //

//- Noise on the state components that vary in the data (and are used)
std::vector<double> noiseLevels
(
    const bsmsSurrogateModel& m,
    const bsmsTrainingData& d,
    const scalar noise
)
{
    const label nState = m.spec().nState();
    std::vector<double> noiseStd(nState, 0.0);
    if (!(noise > 0)) return noiseStd;
    label nVar = 0;
    for (label c = 0; c < nState; ++c)
    {
        const double v0 = d.train[0].states[0][c];
        // Unused components count as constant
        bool constant = true;
        if (m.used(c))
        {
            for (const bsmsTrajectory& tr : d.train)
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
    return noiseStd;
}


//- Resume from the checkpoint if there is one (and not -fresh)
void resume
(
    bsmsSurrogateModel& m,
    const fileName& checkpoint,
    const dictionary& dict,
    const bool fresh
)
{
    if (fresh || !isFile(checkpoint)) return;
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


// * * * * * * * * * * * * * * * Stage: report  * * * * * * * * * * * * * * //

//- Time, CPU, communication and memory of the training
void reportCosts
(
    const bsmsTrainingRun& run,
    const label nSteps,
    const double seconds,
    const double cpu,
    const double wall,
    const double rssStart,
    const label nRanks
)
{
    const bool parallel = Pstream::parRun();
    char buf[300];
    std::snprintf
    (
        buf, sizeof(buf),
        "Training: %d steps in %.2f s (%.4f s per step; validation"
        " %.1f s not counted)",
        int(nSteps), seconds, seconds/nSteps, run.validationSeconds
    );
    Info<< nl << buf << nl;
    // The CPU time of the training (validation included): on a loaded
    // machine the cores a run actually got
    const scalar cpuAll = parallel ? returnReduce(scalar(cpu), sumOp<scalar>()) : cpu;
    std::snprintf
    (
        buf, sizeof(buf),
        "Training CPU time: %.2f s in this process, %.2f s summed"
        " over the %d rank(s) (%.2f cores on average)",
        cpu, cpuAll, int(nRanks), cpuAll/max(wall, 1e-30)
    );
    Info<< buf << nl;
    if (parallel)
    {
        // The share of the time in the gradient sum (waiting for the
        // slower rank included), master and the most of any rank
        const bsmsPstreamSum& rs = run.rankSum();
        const scalar commMaster = rs.seconds();
        const scalar commMax = returnReduce(scalar(rs.seconds()), maxOp<scalar>());
        std::snprintf
        (
            buf, sizeof(buf),
            "Communication: %d gradient sums of %.3f MB, %.3f s on the"
            " master (%.1f %% of the training time; the most of any"
            " rank %.3f s), waiting for the slower rank included",
            int(rs.nCalls()), rs.bytes()/1e6, commMaster,
            100*commMaster/max(seconds, 1e-30), commMax
        );
        Info<< buf << nl;
    }
    const double peak = procStatusMB("VmHWM");
    std::snprintf
    (
        buf, sizeof(buf),
        "Memory: peak resident %.1f MB; %.1f MB before the model,"
        " %.1f MB before training; training peak %.1f MB above that",
        peak, rssStart, run.rssTrain, peak - run.rssTrain
    );
    Info<< buf << nl;
}


//- The one-step loss on every recorded pair without noise (ranks share)
void reportFinalLoss(bsmsSurrogateModel& m, const bsmsTrainingData& d)
{
    const label nRanks = Pstream::parRun() ? Pstream::nProcs() : 1;
    const label rank = Pstream::parRun() ? Pstream::myProcNo() : 0;
    std::vector<std::pair<label, label>> pairs;
    for (label c = 0; c < label(d.train.size()); ++c)
    {
        for (label k = 0; k + 1 < d.train[c].times.size(); ++k)
        {
            pairs.push_back({c, k});
        }
    }
    const label nPairs = pairs.size();
    double sum = 0;
    std::vector<double> x, y;
    // Parallel: every rank a contiguous share of the pairs
    for (label p = rank*nPairs/nRanks; p < (rank + 1)*nPairs/nRanks; ++p)
    {
        const bsmsTrajectory& tr = d.train[pairs[p].first];
        const label k = pairs[p].second;
        x.clear();
        y.clear();
        m.appendInput(tr.states[k], x);
        m.appendTarget(tr.states[k], tr.states[k + 1], y);
        sum += m.net().loss(x, y);
    }
    if (Pstream::parRun()) reduce(sum, sumOp<scalar>());
    char buf[100];
    std::snprintf(buf, sizeof(buf), "%.6e", sum/nPairs);
    Info<< "Final one-step loss over " << nPairs << " pairs (no noise): "
        << buf << nl;
}


//- The training range recorded in the model dictionary
void reportTrainingRange
(
    const bsmsTrainSettings& t,
    const bsmsSurrogateModel& m
)
{
    const bsmsModelSpec& spec = t.spec;
    Info<< "Training range of the inputs (inputMin, inputMax of "
        << bsmsSpecFile(t.checkpoint).name() << "):";
    char buf[200];
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

    // torch's buffers reused step after step, not faulted in again
    bsmsReuseMemory();

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

    const word dictName("bsmsTrainDict");
    #include "setSystemMeshDictionaryIO.H"
    IOdictionary dict(dictIO);
    // Parallel: the master reads the dictionary and sends it on; the file
    // name in the other ranks' error messages
    static_cast<dictionary&>(dict).name() = dict.objectPath();

    // Moving bodies: the Lagrangian path (bsmsTrainLagrangian.H)
    if (dict.lookupOrDefault<word>("graph", "cells") == "lagrangian")
    {
        return bsmsTrainLagrangian(runTime, dict, args.found("fresh"));
    }

    // Settings and data
    bsmsTrainSettings t(bsmsTrainSettings::read(dict, mesh, runTime, nRanks, rank));
    const bsmsTrainingData d(readData(t, runTime, mesh, dict));

    // The model, resumed from the checkpoint if there is one
    const double rssStart = procStatusMB("VmRSS");
    bsmsSurrogateModel m(mesh, t.spec, t.trainer);
    const std::vector<double> noiseStd(noiseLevels(m, d, t.noise));
    Info<< "Graph: " << mesh.nCells() << " cells, " << m.graph().levels.size()
        << " levels (nodes " << m.levelSizes().c_str() << "), "
        << m.buildSeconds() << " s" << nl
        << "Model " << m.net().describe().c_str() << ", "
        << label(m.net().nParameters()) << " parameters" << nl;
    resume(m, t.checkpoint, dict, args.found("fresh"));
    Info<< endl;

    if (parallel)
    {
        gnnTorch::setNumThreads(1);
        Info<< "Parallel run: " << nRanks << " ranks, synchronous data"
            << " parallel on the undecomposed case's data (processor"
            << " directories are not used): each rank trains on its shards"
            << " of every step's batch of " << t.batch << " (this rank "
            << t.nMineShards << " of " << t.nShards << " shards, " << t.nMine
            << " pairs), the shards' gradients summed over the ranks each"
            << " step (Pstream, " << t.nShards << " x "
            << label(m.net().nParameters()) + 1 << " floats); "
            << gnnTorch::numThreads() << " torch thread per rank" << nl
            << endl;
    }
    Info<< "Batch of " << t.batch << " in " << t.nShards << " gradient shards"
        << " (the same training on any number of ranks up to " << t.nShards
        << ")" << nl << endl;

    // Training
    bsmsTrainingRun run(t, d, m, noiseStd, dict, runTime.path());
    run.reportPersistence();
    const label start = m.net().step();
    const auto tTrain = std::chrono::steady_clock::now();
    const double cpuTrain = cpuSeconds();
    const label step = run.run();
    if (step > start)
    {
        reportCosts
        (
            run, step - start, secondsSince(tTrain) - run.validationSeconds,
            cpuSeconds() - cpuTrain, secondsSince(tTrain), rssStart, nRanks
        );
    }
    else if (!d.valid.empty())
    {
        run.validate(step, true);
    }

    reportFinalLoss(m, d);
    checkRanksAgree(m.net().parameterHash());
    reportTrainingRange(t, m);

    Info<< nl << "End" << nl << endl;
    return 0;
}


// ************************************************************************* //
