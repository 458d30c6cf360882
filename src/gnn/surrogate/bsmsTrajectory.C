/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "bsmsTrajectory.H"
#include "bsmsFieldIO.H"
#include "TimePaths.H"
#include "instantList.H"
#include "DynamicList.H"
#include "dictionary.H"
#include <chrono>
#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Fill r.rmse50 and r.rmseAll from r.mse
void rolloutMeans(Foam::bsmsRolloutErrors& r)
{
    const std::size_t n = r.mse.size();
    double sum = 0, sum50 = 0;
    for (std::size_t k = 0; k < n; ++k)
    {
        sum += r.mse[k];
        if (k < 50) sum50 += r.mse[k];
    }
    r.rmse50 = std::sqrt(sum50/std::min(n, std::size_t(50)));
    r.rmseAll = std::sqrt(sum/n);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::bsmsTrajectory Foam::bsmsTrajectory::read
(
    const fileName& caseName,
    const fileName& root,
    const scalar tStart,
    const bsmsModelSpec& spec,
    labelList& comps,
    const label nCells,
    const dictionary& dict
)
{
    bsmsTrajectory tr;
    tr.dir = caseName;
    tr.dir.expand();
    if (!tr.dir.isAbsolute()) tr.dir = root/tr.dir;
    tr.dir.clean();
    DynamicList<instant> times;
    for (const instant& t : TimePaths::findTimes(tr.dir))
    {
        if (t.name() != "constant" && t.value() >= tStart - SMALL)
        {
            times.append(t);
        }
    }
    if (times.size() < 2)
    {
        FatalIOErrorInFunction(dict)
            << "The case " << tr.dir << " (entry 'cases' in " << dict.name()
            << ") has " << times.size() << " written time(s) from t = "
            << (tStart > -GREAT ? tStart : 0) << " (entry 'startTime')"
            << " on; at least 2 are"
            << " needed for a training pair (no pairs: empty dataset)"
            << exit(FatalIOError);
    }
    for (const instant& t : times)
    {
        tr.times.append(t.value());
        tr.states.push_back
        (
            readFieldState
            (
                tr.dir/t.name(), spec.inputFields, nCells, comps, dict,
                "inputFields"
            )
        );
    }
    return tr;
}


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::bsmsRolloutErrors Foam::bsmsValidate
(
    bsmsSurrogateModel& m,
    const bsmsTrajectory& tr
)
{
    bsmsRolloutErrors r;
    const label n = tr.states.size() - 1;

    // RMSE-1: every step from the recorded state
    double sum1 = 0;
    for (label k = 0; k < n; ++k)
    {
        std::vector<double> s(tr.states[k]);
        m.advance(s);
        sum1 += m.outputMse(s, tr.states[k + 1]);
    }
    r.rmse1 = std::sqrt(sum1/n);

    // The rollout
    std::vector<double> s(tr.states[0]);
    const auto t0 = std::chrono::steady_clock::now();
    for (label k = 0; k < n; ++k)
    {
        m.advance(s);
        r.mse.push_back(m.outputMse(s, tr.states[k + 1]));
    }
    r.secondsPerStep = std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - t0
    ).count()/n;
    rolloutMeans(r);
    return r;
}


Foam::bsmsRolloutErrors Foam::bsmsPersistence
(
    const bsmsSurrogateModel& m,
    const bsmsTrajectory& tr
)
{
    bsmsRolloutErrors r;
    for (std::size_t k = 1; k < tr.states.size(); ++k)
    {
        r.mse.push_back(m.outputMse(tr.states[0], tr.states[k]));
    }
    rolloutMeans(r);
    return r;
}

// ************************************************************************* //
