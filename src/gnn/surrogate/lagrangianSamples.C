/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "lagrangianSamples.H"
#include "Time.H"
#include "dictionaryChecks.H"

#include <chrono>
#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- Every written time of the case of runTime
instantList writtenTimes(const Time& runTime)
{
    DynamicList<instant> out;
    for (const instant& t : runTime.times())
    {
        if (t.name() != "constant") out.append(t);
    }
    return instantList(std::move(out));
}


//- Whether two recordings have the same nodes: counts, X (to 1e-9 of
//  the extent; an actuator's X is relative to its box, so a box of the
//  same size elsewhere has the same nodes) and the kinds: then they have
//  one graph and one pooling, which the model's levels and the frames'
//  world edges rely on
bool sameNodes(const lagrangianRecording& a, const lagrangianRecording& b)
{
    if (a.nNodes() != b.nNodes() || a.nPoints() != b.nPoints()) return false;
    const scalar tol = 1e-9*max(mag(max(a.X()) - min(a.X())), SMALL);
    for (label i = 0; i < a.nNodes(); ++i)
    {
        if (mag(a.X()[i] - b.X()[i]) > tol || a.kind()[i] != b.kind()[i])
        {
            return false;
        }
    }
    return true;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::lagrangianSamples::lagrangianSamples
(
    const fileNameList& cases,
    const fileName& root,
    const dictionary& dict,
    const dictionary& levels
)
:
    deltaT_(0)
{
    if (cases.empty())
    {
        FatalIOErrorInFunction(dict)
            << "No recorded case (entry 'cases' in " << dict.name() << ")"
            << exit(FatalIOError);
    }
    for (const fileName& cn : cases)
    {
        fileName dir(cn);
        dir.expand();
        if (!dir.isAbsolute()) dir = root/dir;
        dir.clean();
        if (!isFile(dir/"system"/"controlDict"))
        {
            FatalIOErrorInFunction(dict)
                << "The recording " << dir << " (entry 'cases' in "
                << dict.name() << ") is not a case: it has no"
                << " system/controlDict" << exit(FatalIOError);
        }
        const Time caseTime
        (
            Time::controlDictName, dir.path(), dir.name(), "system",
            "constant", false, false
        );
        const instantList frames(writtenTimes(caseTime));
        if (frames.size() < 3)
        {
            FatalIOErrorInFunction(dict)
                << "The recording " << dir << " (entry 'cases' in "
                << dict.name() << ") has " << frames.size() << " written"
                << " time(s); a sample needs 3 (the velocity of the last"
                << " step and the next frame)" << exit(FatalIOError);
        }
        recordings_.append(new lagrangianRecording(caseTime, frames, dict));
        const lagrangianRecording& r = recordings_.last();

        // Uniform frames: the model time step
        const scalarList& t = r.times();
        if (deltaT_ == 0) deltaT_ = t[1] - t[0];
        for (label k = 0; k + 1 < t.size(); ++k)
        {
            if (mag(t[k + 1] - t[k] - deltaT_) > 1e-6*deltaT_)
            {
                FatalIOErrorInFunction(dict)
                    << "The frames of " << dir << " (entry 'cases' in "
                    << dict.name() << ") are not " << deltaT_ << " apart: "
                    << t[k] << " to " << t[k + 1] << " (the model step is"
                    << " the interval of the first case's frames)"
                    << exit(FatalIOError);
            }
        }

        // The same nodes as the first case
        const lagrangianRecording& r0 = recordings_[0];
        const bool same = ::sameNodes(r, r0);
        if (!same)
        {
            FatalIOErrorInFunction(dict)
                << "The recording " << dir << " (entry 'cases' in "
                << dict.name() << ") has other nodes than " << r0.dir()
                << ": " << r.nPoints() << " material points and "
                << r.nNodes() - r.nPoints() << " actuator nodes against "
                << r0.nPoints() << " and " << r0.nNodes() - r0.nPoints()
                << ", or material points at other places, actuators of"
                << " another size, or other kinds."
                << " One model is one set of nodes" << exit(FatalIOError);
        }
    }

    stepper_.reset(new lagrangianStepper(recordings_[0], levels));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

std::vector<std::pair<Foam::label, Foam::label>>
Foam::lagrangianSamples::samples() const
{
    std::vector<std::pair<label, label>> s;
    forAll(recordings_, c)
    {
        for (label k = 1; k + 1 < recordings_[c].nFrames(); ++k)
        {
            s.push_back({c, k});
        }
    }
    return s;
}


bool Foam::lagrangianSamples::sameNodes(const lagrangianSamples& other) const
{
    return ::sameNodes(recordings_[0], other.recordings_[0]);
}


void Foam::lagrangianSamples::sample
(
    const label c,
    const label k,
    const scalar sigma,
    std::mt19937_64& gen,
    std::vector<double>& x,
    std::vector<double>& y,
    bsmsData::world& w,
    const predictor* model,
    const label j
) const
{
    const lagrangianRecording& r = recordings_[c];
    const List<lagrangianGraph::nodeKind>& kind = r.kind();
    pointField xk(r.x(k));
    pointField xkm1(r.x(k - 1));
    if (model && j > 0 && k - j >= 1)
    {
        // The model's own frames k-1, k from the recorded k-1-j, k-j
        pointField a(r.x(k - 1 - j)), b(r.x(k - j)), next;
        label bad = -1;
        for (label m = k - j; m < k; ++m)
        {
            if (!stepper_->step(*model, a, b, r.x(m + 1), next, bad)) break;
            a.transfer(b);
            b.transfer(next);
        }
        if (bad < 0)
        {
            xkm1 = a;
            xk = b;
        }
    }
    if (sigma > 0)
    {
        std::normal_distribution<double> normal(0, sigma);
        forAll(xk, i)
        {
            if (kind[i] == lagrangianGraph::nodeKind::actuator) continue;
            for (direction d = 0; d < 3; ++d) xk[i][d] += normal(gen);
        }
    }
    const label n = xk.size();
    const std::size_t x0 = x.size(), y0 = y.size();
    x.resize(x0 + nIn*n);
    y.resize(y0 + nOut*n);
    stepper_->inputs(xkm1, xk, r.x(k + 1), &x[x0]);
    const pointField& xNext = r.x(k + 1);
    for (label i = 0; i < n; ++i)
    {
        for (direction d = 0; d < 3; ++d)
        {
            y[y0 + nOut*i + d] = xNext[i][d] - xk[i][d];
        }
    }
    w = stepper_->world(xk);
}


Foam::lagrangianSamples::errors Foam::lagrangianSamples::rollout
(
    const label c,
    const predictor& model,
    pointField& xLast
) const
{
    const lagrangianRecording& r = recordings_[c];
    const label nP = r.nPoints();
    const label K = r.nFrames();

    errors e;
    double sumModel = 0, sumHold = 0, sumVel = 0;
    const double perFrame = 3.0*nP;
    pointField xPrev(r.x(0)), x(r.x(1));
    double seconds = 0;
    for (label k = 1; k + 1 < K; ++k)
    {
        const pointField& truth = r.x(k + 1);
        const auto t0 = std::chrono::steady_clock::now();
        pointField xNext;
        label bad = -1;
        const bool ok = stepper_->step(model, xPrev, x, truth, xNext, bad);
        seconds += std::chrono::duration<double>
        (
            std::chrono::steady_clock::now() - t0
        ).count();
        if (!ok)
        {
            xLast = x;
            FatalErrorInFunction
                << "The rollout of " << r.dir() << " predicted a non-finite"
                << " displacement of node " << bad << " at step " << k
                << " (t = " << r.times()[k] << "); the last good state is"
                << " that of t = " << r.times()[k] << exit(FatalError);
        }
        double sm = 0, sh = 0, sv = 0;
        const pointField& x1 = r.x(1);
        const pointField& x0 = r.x(0);
        for (label i = 0; i < nP; ++i)
        {
            sm += magSqr(xNext[i] - truth[i]);
            sh += magSqr(x1[i] - truth[i]);
            sv += magSqr(x1[i] + scalar(k)*(x1[i] - x0[i]) - truth[i]);
        }
        sumModel += sm;
        sumHold += sh;
        sumVel += sv;
        e.perStep.push_back(std::sqrt(sm/perFrame));
        e.holdPerStep.push_back(std::sqrt(sh/perFrame));
        e.velocityPerStep.push_back(std::sqrt(sv/perFrame));
        xPrev.transfer(x);
        x.transfer(xNext);
    }
    const double nSteps = max(K - 2, label(1));
    e.model = std::sqrt(sumModel/(perFrame*nSteps));
    e.hold = std::sqrt(sumHold/(perFrame*nSteps));
    e.velocity = std::sqrt(sumVel/(perFrame*nSteps));
    e.secondsPerStep = seconds/nSteps;
    xLast = x;
    return e;
}


// ************************************************************************* //
