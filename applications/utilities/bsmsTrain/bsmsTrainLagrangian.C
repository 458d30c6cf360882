/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "bsmsTrainLagrangian.H"
#include "bsmsTrainSettings.H"
#include "bsmsTrainingRun.H"
#include "lagrangianSamples.H"
#include "bsmsExport.H"
#include "bsmsTrainerFacade.H"
#include "bsmsPstreamSum.H"
#include "dictionaryChecks.H"
#include "OFstream.H"
#include "OSspecific.H"

#include <chrono>
#include <cstdio>
#include <random>
#include <stdexcept>

using namespace Foam;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The settings of a Lagrangian training: the batch, run and optimiser
//  entries as the mesh graphs' (bsmsTrainSettings), and its own
struct lagrangianSettings
{
    //- steps, batch, gradientShards and this rank's share, maxTrainTime,
    //  printInterval, checkpoint; the trainer (optimiser, sizes) and noise
    //  (on the positions [m])
    bsmsTrainSettings common;
    fileNameList cases;
    fileNameList validationCases;
    dictionary levels;
    //- Most model steps a sample's input is rolled out by the model
    //  (1: the recorded frames only)
    label rolloutSteps = 1;

    static lagrangianSettings read
    (
        const dictionary& dict,
        const Time& runTime,
        const label nRanks,
        const label rank
    )
    {
        using namespace dictionaryChecks;
        lagrangianSettings s;
        s.cases = getAs<fileNameList>(dict, "cases", "a list of recorded cases");
        if (const dictionary* vd = dict.findDict("validation"))
        {
            s.validationCases =
                getAs<fileNameList>(*vd, "cases", "a list of recorded cases");
        }
        s.levels.add("seeding", word("closeCenter"));
        s.levels.add("minNodes", label(100));
        if (const dictionary* ld = dict.findDict("levels"))
        {
            s.levels = *ld;
        }
        gnnTorch::trainerSettings& t = s.common.trainer;
        t = lagrangianStepper::network
        (
            getLabelAtLeast(dict, "latent", 128, 1),
            getLabelAtLeast(dict, "hidden", 128, 1)
        );
        bsmsTrainSettings::readOptimiser(dict, t, s.common.noise);
        bsmsTrainSettings::readBatch(dict, nRanks, rank, s.common);
        bsmsTrainSettings::readRun(dict, runTime, s.common);
        s.rolloutSteps = getLabelAtLeast(dict, "rolloutSteps", 1, 1);
        return s;
    }
};


//- The model dictionary beside the checkpoint: what the model is
void writeModelDict
(
    const fileName& file,
    const lagrangianSettings& s,
    const lagrangianSamples& data,
    const dictionary& dict
)
{
    OFstream os(file);
    const lagrangianRecording& r = data.recording(0);
    os  << "FoamFile { version 2.0; format ascii; class dictionary;"
        << " object bsmsModelDict; }" << nl << nl
        << "// BSMS-GNN of moving bodies, written by bsmsTrain" << nl
        << "model           bsms;" << nl
        << "graph           lagrangian;" << nl
        << "cloud           "
        << dict.lookupOrDefault<word>("cloud", "mpmCloud") << ';' << nl
        << "meshRadius      " << r.meshRadius() << ';' << nl
        << "worldRadius     " << r.worldRadius() << ';' << nl;
    if (dict.found("actuatorSpacing"))
    {
        os  << "actuatorSpacing " << dict.get<scalar>("actuatorSpacing")
            << ';' << nl;
    }
    os  << "nNodes          " << r.nNodes() << ';' << nl
        << "nPoints         " << r.nPoints() << ';' << nl
        << "latent          " << s.common.trainer.latent << ';' << nl
        << "hidden          " << s.common.trainer.hidden << ';' << nl
        << "deltaT          " << data.deltaT() << ';' << nl
        << "levels" << nl << s.levels << nl;
}


} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

int Foam::bsmsTrainLagrangian
(
    const Time& runTime,
    const dictionary& dict,
    const bool fresh
)
{
    const bool parallel = Pstream::parRun();
    const label nRanks = parallel ? Pstream::nProcs() : 1;
    const label rank = parallel ? Pstream::myProcNo() : 0;
    const lagrangianSettings s
    (
        lagrangianSettings::read(dict, runTime, nRanks, rank)
    );
    const bsmsTrainSettings& c = s.common;

    // Data: the recordings, one graph for all
    const auto t0 = std::chrono::steady_clock::now();
    const lagrangianSamples data(s.cases, runTime.path(), dict, s.levels);
    autoPtr<lagrangianSamples> valid;
    if (s.validationCases.size())
    {
        valid.reset
        (
            new lagrangianSamples
            (
                s.validationCases, runTime.path(), dict, s.levels
            )
        );
        if (!valid->sameNodes(data))
        {
            FatalIOErrorInFunction(dict)
                << "The validation cases (entry 'validation' in "
                << dict.name() << ") have other nodes than the training"
                << " cases" << exit(FatalIOError);
        }
    }
    const auto samples = data.samples();
    const lagrangianRecording& r0 = data.recording(0);
    Info<< "Moving bodies: " << data.nCases() << " recorded cases, "
        << label(samples.size()) << " training samples; per case "
        << r0.nPoints() << " material points and "
        << r0.nNodes() - r0.nPoints() << " actuator nodes; model step "
        << data.deltaT() << " s (the frame interval)" << nl
        << "Graph: levels of " << data.pooling().nLevels() << " (nodes";
    for (label l = 0; l < data.pooling().nLevels(); ++l)
    {
        Info<< ' ' << data.pooling().graph(l).nNodes();
    }
    Info<< "), read and built in " << secondsSince(t0) << " s" << nl;

    // The model, resumed from its checkpoint unless fresh
    const bsmsData::hierarchy h = bsmsExport(data.pooling(), 3);
    gnnTorch::bsmsTrainerFacade net(h, c.trainer);
    Info<< "Model " << net.describe().c_str() << ", "
        << label(net.nParameters()) << " parameters" << nl;
    if (!fresh && isFile(c.checkpoint))
    {
        try
        {
            net.load(c.checkpoint);
        }
        catch (const std::exception& e)
        {
            FatalIOErrorInFunction(dict)
                << "The checkpoint " << c.checkpoint << " (entry"
                << " 'checkpoint' in " << dict.name() << ") is not a model"
                << " of these recordings (another mesh, node count or"
                << " size?): " << e.what() << nl
                << "    Remove it or run with -fresh" << exit(FatalIOError);
        }
        Info<< "Resumed from " << c.checkpoint << " at step " << label(net.step())
            << nl;
    }
    Info<< endl;
    if (parallel)
    {
        gnnTorch::setNumThreads(1);
        Info<< "Parallel run: " << nRanks << " ranks, synchronous data"
            << " parallel: every rank reads the recordings and trains on its"
            << " shards of every step's batch (this rank " << c.nMineShards
            << " of " << c.nShards << " shards, " << c.nMine << " samples),"
            << " the shards' gradients summed over the ranks each step; "
            << gnnTorch::numThreads() << " torch thread per rank" << nl
            << endl;
    }
    Info<< "Batch of " << c.batch << " in " << c.nShards << " gradient shards"
        << " (the same training on any number of ranks up to " << c.nShards
        << ")" << nl << endl;

    // Training (the master writes the loss history)
    const bool master = Pstream::master();
    const fileName outDir(runTime.path()/"postProcessing"/"bsmsTrain");
    autoPtr<OFstream> lossFile;
    if (master)
    {
        mkDir(outDir);
        // A resumed run adds to the loss history of the run it resumes
        const bool resumed = net.step() > 0 && isFile(outDir/"loss.dat");
        lossFile.reset
        (
            new OFstream
            (
                outDir/"loss.dat", IOstream::ASCII, IOstream::currentVersion,
                IOstream::UNCOMPRESSED, resumed
            )
        );
        if (!resumed) lossFile() << "# step\tloss\tlr" << nl;
    }
    std::vector<double> x, y;
    std::vector<bsmsData::world> worlds(c.nMine);
    std::vector<const bsmsData::world*> ptrs(c.nMine);
    for (label b = 0; b < c.nMine; ++b) ptrs[b] = &worlds[b];
    bsmsPstreamSum rankSum;
    // The model as a predictor (a rollout's steps, rolled inputs)
    const lagrangianStepper::predictor model(lagrangianStepper::predictorOf(net));
    if (s.rolloutSteps > 1)
    {
        Info<< "Rolled inputs: after the normalisers' "
            << label(c.trainer.normAccumulations) << " steps, each sample's"
            << " input is the model's own, rolled out 0 to "
            << s.rolloutSteps - 1 << " model steps from the recorded frames"
            << " (target: the recorded next frame)" << nl << endl;
    }
    const auto tTrain = std::chrono::steady_clock::now();
    label step = label(net.step());
    const label start = step;
    double lossSum = 0;
    label lossN = 0;
    std::vector<std::pair<std::size_t, label>> draws(c.batch);
    while (step < c.nSteps && secondsSince(tTrain) < c.maxTrainTime)
    {
        // The step's draws (sample, rolled steps) from a generator seeded
        // by (seed, step), every sample's noise from one seeded by (seed,
        // step, sample): a resumed run draws what an uninterrupted one
        // would, and every rank what it needs of the same batch
        const std::uint64_t seed = c.trainer.seed*1000003ull + std::uint64_t(step);
        std::mt19937_64 gen(seed);
        std::uniform_int_distribution<std::size_t> pick(0, samples.size() - 1);
        const bool rolled =
            s.rolloutSteps > 1 && step >= c.trainer.normAccumulations;
        for (label b = 0; b < c.batch; ++b)
        {
            const std::size_t i = pick(gen);
            label j = 0;
            if (rolled)
            {
                std::uniform_int_distribution<label> roll
                (
                    0, min(s.rolloutSteps - 1, samples[i].second - 1)
                );
                j = roll(gen);
            }
            draws[b] = {i, j};
        }
        x.clear();
        y.clear();
        for (label m = 0; m < c.nMine; ++m)
        {
            const label b = c.shareFirst + m;
            const auto& sk = samples[draws[b].first];
            std::mt19937_64 noiseGen(seed*0x9E3779B97F4A7C15ull + std::uint64_t(b));
            data.sample
            (
                sk.first, sk.second, c.noise, noiseGen, x, y, worlds[m],
                rolled ? &model : nullptr, draws[b].second
            );
        }
        const double loss = net.trainShards
        (
            x, y, c.shardFirst, c.nMineShards, c.nShards, c.batch, rankSum,
            ptrs
        );
        ++step;
        if (master)
        {
            lossFile() << step << '\t' << loss << '\t' << net.learningRate() << nl;
        }
        lossSum += loss;
        ++lossN;
        if (step % c.printInterval == 0 || step == c.nSteps)
        {
            const double el = secondsSince(tTrain);
            char buf[160];
            std::snprintf
            (
                buf, sizeof(buf),
                "step %d/%d  loss %.3e  lr %.2e  %.3f s per step",
                int(step), int(c.nSteps), lossSum/lossN, net.learningRate(),
                el/max(step - start, label(1))
            );
            Info<< buf << endl;
            lossSum = 0;
            lossN = 0;
        }
    }
    const double trainSeconds = secondsSince(tTrain);
    if (step > start)
    {
        Info<< nl << "Trained " << step - start << " steps in "
            << trainSeconds << " s (" << trainSeconds/(step - start)
            << " s per step)" << nl;
        if (parallel)
        {
            Info<< "Communication: " << rankSum.nCalls() << " gradient sums,"
                << " " << rankSum.seconds() << " s on the master" << nl;
        }
        if (master)
        {
            mkDir(c.checkpoint.path());
            net.save(c.checkpoint);
            writeModelDict
            (
                c.checkpoint.path()/"bsmsModelDict", s, data, dict
            );
        }
        Info<< "Wrote " << c.checkpoint << " and its bsmsModelDict" << nl;
    }
    checkRanksAgree(net.parameterHash());

    // Validation rollouts against the trivial baselines (the master)
    if (valid.valid() && master)
    {
        OFstream vFile(outDir/"validation.dat");
        vFile
            << "# case\tsteps\tRMSE-all model [m]\thold [m]\tvelocity [m]"
            << "\tmodel/hold\tmodel/velocity\tseconds per model step" << nl;
        for (label c = 0; c < valid->nCases(); ++c)
        {
            pointField xLast;
            const lagrangianSamples::errors e = valid->rollout(c, model, xLast);
            const fileName name(valid->recording(c).dir().name());
            Info<< "Rollout of " << name << ": " << e.perStep.size()
                << " model steps, RMSE-all of positions " << e.model
                << " m; holding the state " << e.hold << " m (ratio "
                << e.model/max(e.hold, VSMALL) << "), moving on at the last"
                << " velocity " << e.velocity << " m (ratio "
                << e.model/max(e.velocity, VSMALL) << "); "
                << e.secondsPerStep << " s per model step" << nl;
            vFile
                << name << '\t' << label(e.perStep.size()) << '\t' << e.model
                << '\t' << e.hold << '\t' << e.velocity << '\t'
                << e.model/max(e.hold, VSMALL) << '\t'
                << e.model/max(e.velocity, VSMALL) << '\t' << e.secondsPerStep
                << nl;
            OFstream rFile(outDir/("rollout_" + name + ".dat"));
            rFile
                << "# step\tRMSE model [m]\tholding the state [m]"
                << "\tmoving on at the last velocity [m]" << nl;
            for (std::size_t k = 0; k < e.perStep.size(); ++k)
            {
                rFile
                    << k + 1 << '\t' << e.perStep[k] << '\t'
                    << e.holdPerStep[k] << '\t' << e.velocityPerStep[k] << nl;
            }

            // The material points at the rollout's last frame, the model's
            // and the recording's, for pictures side by side
            const lagrangianRecording& rec = valid->recording(c);
            const pointField& truth = rec.x(rec.nFrames() - 1);
            OFstream fFile(outDir/("final_" + name + ".dat"));
            fFile
                << "# t = " << rec.times().last() << ": x y z of the rollout"
                << " [m], x y z of the recording [m]" << nl;
            for (label i = 0; i < rec.nPoints(); ++i)
            {
                fFile
                    << xLast[i].x() << ' ' << xLast[i].y() << ' '
                    << xLast[i].z() << ' ' << truth[i].x() << ' '
                    << truth[i].y() << ' ' << truth[i].z() << nl;
            }
        }
    }

    Info<< nl << "End" << nl << endl;
    return 0;
}


// ************************************************************************* //
