/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "bsmsTrainingRun.H"
#include "OSspecific.H"
#include "Pstream.H"
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <random>
#include <stdexcept>

// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

double Foam::secondsSince(const std::chrono::steady_clock::time_point& t0)
{
    return std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - t0
    ).count();
}


//- CPU seconds of this process (all its threads)
double Foam::cpuSeconds()
{
    timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9*t.tv_nsec;
}


//- A /proc/self/status entry in MB (VmRSS, VmHWM), 0 if unknown
double Foam::procStatusMB(const std::string& key)
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


void Foam::checkRanksAgree(const std::uint64_t hash)
{
    if (!Pstream::parRun()) return;
    const label nRanks = Pstream::nProcs();
    char buf[40];
    std::snprintf
    (
        buf, sizeof(buf), "%016llx", static_cast<unsigned long long>(hash)
    );
    List<word> hashes(nRanks);
    hashes[Pstream::myProcNo()] = buf;
    Pstream::gatherList(hashes);
    if (!Pstream::master()) return;
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


// * * * * * * * * * * * * * * * * Constructor  * * * * * * * * * * * * * * //

Foam::bsmsTrainingRun::bsmsTrainingRun
(
    const bsmsTrainSettings& t,
    const bsmsTrainingData& d,
    bsmsSurrogateModel& m,
    const std::vector<double>& noiseStd,
    const dictionary& dict,
    const fileName& casePath
)
:
    t_(t),
    d_(d),
    m_(m),
    noiseStd_(noiseStd),
    dict_(dict),
    parallel_(Pstream::parRun()),
    master_(Pstream::master()),
    outDir_(casePath/"postProcessing"/"bsmsTrain"),
    resumed_(m.net().step() > 0)
{
    if (master_)
    {
        mkDir(outDir_);
        if (!openHistory(lossFile_, "loss.dat"))
        {
            lossFile_() << "# step loss lr" << nl;
        }
    }
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::bsmsTrainingRun::openHistory
(
    autoPtr<OFstream>& file,
    const word& name
) const
{
    // A resumed run (a curriculum's next stage, or an interrupted one)
    // adds to the history of the run it resumes
    const bool append = resumed_ && isFile(outDir_/name);
    file.reset
    (
        new OFstream
        (
            outDir_/name, IOstream::ASCII, IOstream::currentVersion,
            IOstream::UNCOMPRESSED, append
        )
    );
    return append;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bsmsTrainingRun::save()
{
    if (!master_) return;
    mkDir(t_.checkpoint.path());
    try
    {
        m_.net().save(t_.checkpoint);
    }
    catch (const std::exception& e)
    {
        FatalIOErrorInFunction(dict_)
            << "Cannot write the checkpoint " << t_.checkpoint
            << " (entry 'checkpoint'): " << e.what()
            << exit(FatalIOError);
    }
    OFstream os(bsmsSpecFile(t_.checkpoint));
    os  << "// Model dictionary of " << t_.checkpoint.name()
        << ", written by bsmsTrain" << nl;
    t_.spec.write(os);
}


void Foam::bsmsTrainingRun::reportPersistence() const
{
    for (const bsmsTrajectory& tr : d_.valid)
    {
        if (!master_) break;
        const bsmsRolloutErrors r = bsmsPersistence(m_, tr);
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
}


void Foam::bsmsTrainingRun::validate(const label step, const bool last)
{
    if (d_.valid.empty() || !master_) return;
    if (!validationFile_.valid() && !openHistory(validationFile_, "validation.dat"))
    {
        validationFile_()
            << "# step case RMSE-1 RMSE-50 RMSE-all inferenceSecondsPerStep"
            << nl;
    }
    char buf[300];
    for (const bsmsTrajectory& tr : d_.valid)
    {
        const bsmsRolloutErrors r = bsmsValidate(m_, tr);
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
        validationFile_() << buf << endl;
        if (!last) continue;
        OFstream os(outDir_/("rollout_" + tr.dir.name() + ".dat"));
        os  << "# rollout of the model at training step " << step
            << " from t = " << tr.times[0] << " (deltaT "
            << t_.spec.deltaT << ")" << nl
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


void Foam::bsmsTrainingRun::assembleBatch(const label step)
{
    const label nState = t_.spec.nState();
    const label K = t_.rolloutSteps;
    const bool noise = t_.noise > 0;
    std::mt19937_64 rng
    (
        t_.trainer.seed*0x9E3779B97F4A7C15ULL + std::uint64_t(step)
    );
    std::uniform_int_distribution<label> pick(0, label(d_.samples.size()) - 1);
    std::normal_distribution<double> gauss(0.0, 1.0);
    x_.clear();
    y_.clear();
    // The samples of this rank's shards; the draws of all (the same
    // stream on every rank)
    for (label b = 0; b < t_.batch; ++b)
    {
        const auto& pr = d_.samples[pick(rng)];
        const bsmsTrajectory& tr = d_.train[pr.first];
        const label k = pr.second;
        if (b < t_.shareFirst || b >= t_.shareFirst + t_.nMine)
        {
            if (noise)
            {
                const std::size_t nx = tr.states[k].size();
                for (std::size_t i = 0; i < nx; ++i)
                {
                    if (noiseStd_[i % nState] > 0) gauss(rng);
                }
            }
            continue;
        }
        noisy_ = tr.states[k];
        if (noise)
        {
            for (std::size_t i = 0; i < noisy_.size(); ++i)
            {
                const double sd = noiseStd_[i % nState];
                if (sd > 0) noisy_[i] += sd*gauss(rng);
            }
        }
        m_.appendInput(noisy_, x_);
        // Step 0 from the noisy input (the noise corrected), the further
        // steps the recording's increments
        m_.appendTarget(noisy_, tr.states[k + 1], y_);
        for (label j = 1; j < K; ++j)
        {
            m_.appendTarget(tr.states[k + j], tr.states[k + j + 1], y_);
        }
    }
}


Foam::label Foam::bsmsTrainingRun::run()
{
    const label start = m_.net().step();
    const label nSteps = t_.nSteps;
    if (start >= nSteps)
    {
        Info<< "The checkpoint is at step " << start << " >= steps "
            << nSteps << ": nothing to train" << nl;
    }
    rssTrain = procStatusMB("VmRSS");
    const auto tTrain = std::chrono::steady_clock::now();
    double lossSum = 0;
    label lossCount = 0;
    char buf[300];
    label step = start;
    while (step < nSteps)
    {
        assembleBatch(step);
        double l = 0;
        try
        {
            l = m_.net().trainShards
            (
                x_, y_, t_.shardFirst, t_.nMineShards, t_.nShards, t_.batch,
                rankSum_
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
        if (master_)
        {
            std::snprintf
            (
                buf, sizeof(buf), "%d %.9e %.6e", int(step), l,
                m_.net().learningRate()
            );
            lossFile_() << buf << nl;
        }

        const double el = secondsSince(tTrain) - validationSeconds;
        // The master's clock decides, for all ranks
        bool outOfTime = el >= t_.maxTrainTime;
        if (parallel_) Pstream::scatter(outOfTime);
        const bool last = step == nSteps || outOfTime;
        if (step % t_.printInterval == 0 || last)
        {
            const double eta = min
            (
                el/(step - start)*(nSteps - step), t_.maxTrainTime - el
            );
            std::snprintf
            (
                buf, sizeof(buf), "step %d/%d  loss %.3e  lr %.3e  ETA %.0f s",
                int(step), int(nSteps), lossSum/lossCount,
                m_.net().learningRate(), max(eta, 0.0)
            );
            Info<< buf << endl;
            lossSum = 0;
            lossCount = 0;
        }
        if (step % t_.checkpointInterval == 0 || last)
        {
            save();
            Info<< "Wrote the checkpoint " << t_.checkpoint << " at step "
                << step << endl;
        }
        if (step % t_.validationInterval == 0 || last)
        {
            const auto tv = std::chrono::steady_clock::now();
            validate(step, last);
            validationSeconds += secondsSince(tv);
        }
        if (outOfTime)
        {
            Info<< "The training budget maxTrainTime " << t_.maxTrainTime
                << " s is spent at step " << step << endl;
            break;
        }
    }
    return step;
}


// ************************************************************************* //
