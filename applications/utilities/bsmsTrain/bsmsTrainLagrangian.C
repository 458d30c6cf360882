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
#include "dictionaryChecks.H"
#include "OFstream.H"
#include "OSspecific.H"

#include <chrono>
#include <cstdio>
#include <stdexcept>

using namespace Foam;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The settings of a Lagrangian training
struct lagrangianSettings
{
    fileNameList cases;
    fileNameList validationCases;
    dictionary levels;
    gnnTorch::trainerSettings trainer;
    label steps = 2000;
    label batch = 1;
    //- Most model steps a sample's input is rolled out by the model
    //  (1: the recorded frames only)
    label rolloutSteps = 1;
    scalar noise = 0;
    scalar maxTrainTime = 1e30;
    label printInterval = 100;
    fileName checkpoint;

    static lagrangianSettings read(const dictionary& dict, const Time& runTime)
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
        gnnTorch::trainerSettings& t = s.trainer;
        t.model = "bsms";
        t.world = 1;
        t.nIn = lagrangianSamples::nIn;
        t.nOut = lagrangianSamples::nOut;
        t.latent = getLabelAtLeast(dict, "latent", 128, 1);
        t.hidden = getLabelAtLeast(dict, "hidden", 128, 1);
        // lr .. seed and noise (on the positions [m]) as the mesh graphs'
        bsmsTrainSettings::readOptimiser(dict, t, s.noise);
        t.noiseStd = {0.0};
        s.steps = getLabelAtLeast(dict, "steps", 2000, 0);
        s.batch = getLabelAtLeast(dict, "batch", 1, 1);
        s.rolloutSteps = getLabelAtLeast(dict, "rolloutSteps", 1, 1);
        s.maxTrainTime = getPositive(dict, "maxTrainTime", 1e30);
        s.printInterval =
            getLabelAtLeast(dict, "printInterval", max(s.steps/20, label(1)), 1);
        s.checkpoint = getAsOrDefault<fileName>
        (
            dict, "checkpoint", "constant/bsmsModel.pt", "a file name"
        );
        s.checkpoint.expand();
        if (!s.checkpoint.isAbsolute()) s.checkpoint = runTime.path()/s.checkpoint;
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
        << "latent          " << s.trainer.latent << ';' << nl
        << "hidden          " << s.trainer.hidden << ';' << nl
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
    if (Pstream::parRun())
    {
        FatalIOErrorInFunction(dict)
            << "graph lagrangian (" << dict.name() << ") trains serially for"
            << " now; run bsmsTrain without -parallel" << exit(FatalIOError);
    }
    const lagrangianSettings s(lagrangianSettings::read(dict, runTime));

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
    gnnTorch::bsmsTrainerFacade net(h, s.trainer);
    Info<< "Model " << net.describe().c_str() << ", "
        << label(net.nParameters()) << " parameters" << nl;
    if (!fresh && isFile(s.checkpoint))
    {
        try
        {
            net.load(s.checkpoint);
        }
        catch (const std::exception& e)
        {
            FatalIOErrorInFunction(dict)
                << "The checkpoint " << s.checkpoint << " (entry"
                << " 'checkpoint' in " << dict.name() << ") is not a model"
                << " of these recordings (another mesh, node count or"
                << " size?): " << e.what() << nl
                << "    Remove it or run with -fresh" << exit(FatalIOError);
        }
        Info<< "Resumed from " << s.checkpoint << " at step " << label(net.step())
            << nl;
    }
    Info<< endl;

    // Training
    const fileName outDir(runTime.path()/"postProcessing"/"bsmsTrain");
    mkDir(outDir);
    // A resumed run adds to the loss history of the run it resumes
    const bool resumed = net.step() > 0 && isFile(outDir/"loss.dat");
    OFstream lossFile
    (
        outDir/"loss.dat", IOstream::ASCII, IOstream::currentVersion,
        IOstream::UNCOMPRESSED, resumed
    );
    if (!resumed) lossFile << "# step\tloss\tlr" << nl;
    std::vector<double> x, y;
    std::vector<bsmsData::world> worlds(s.batch);
    std::vector<const bsmsData::world*> ptrs(s.batch);
    // The model as a predictor (a rollout's steps, rolled inputs)
    const lagrangianSamples::predictor model =
        [&](const std::vector<double>& in, const bsmsData::world& w)
        {
            net.setWorlds({&w});
            return net.predict(in);
        };
    if (s.rolloutSteps > 1)
    {
        Info<< "Rolled inputs: after the normalisers' " << label(s.trainer.normAccumulations)
            << " steps, each sample's input is the model's own, rolled out"
            << " 0 to " << s.rolloutSteps - 1 << " model steps from the"
            << " recorded frames (target: the recorded next frame)" << nl
            << endl;
    }
    const auto tTrain = std::chrono::steady_clock::now();
    label step = label(net.step());
    const label start = step;
    double lossSum = 0;
    label lossN = 0;
    while (step < s.steps && secondsSince(tTrain) < s.maxTrainTime)
    {
        // The step's draws from a generator seeded by (seed, step): a
        // resumed run draws what an uninterrupted one would
        std::mt19937_64 gen(s.trainer.seed*1000003ull + std::uint64_t(step));
        std::uniform_int_distribution<std::size_t> pick(0, samples.size() - 1);
        const bool rolled =
            s.rolloutSteps > 1 && step >= s.trainer.normAccumulations;
        x.clear();
        y.clear();
        for (label b = 0; b < s.batch; ++b)
        {
            const auto& sk = samples[pick(gen)];
            label j = 0;
            if (rolled)
            {
                std::uniform_int_distribution<label> roll
                (
                    0, min(s.rolloutSteps - 1, sk.second - 1)
                );
                j = roll(gen);
            }
            data.sample
            (
                sk.first, sk.second, s.noise, gen, x, y, worlds[b],
                rolled ? &model : nullptr, j
            );
            ptrs[b] = &worlds[b];
        }
        net.setWorlds(ptrs);
        const double loss = net.trainStep(x, y);
        ++step;
        lossFile << step << '\t' << loss << '\t' << net.learningRate() << nl;
        lossSum += loss;
        ++lossN;
        if (step % s.printInterval == 0 || step == s.steps)
        {
            const double el = secondsSince(tTrain);
            char buf[160];
            std::snprintf
            (
                buf, sizeof(buf),
                "step %d/%d  loss %.3e  lr %.2e  %.3f s per step",
                int(step), int(s.steps), lossSum/lossN, net.learningRate(),
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
        mkDir(s.checkpoint.path());
        net.save(s.checkpoint);
        writeModelDict
        (
            s.checkpoint.path()/"bsmsModelDict", s, data, dict
        );
        Info<< "Wrote " << s.checkpoint << " and its bsmsModelDict" << nl;
    }

    // Validation rollouts against the trivial baselines
    if (valid.valid())
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
