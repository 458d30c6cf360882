/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "bsmsTrainSettings.H"
#include "dictionaryChecks.H"
#include "polyMesh.H"
#include "Time.H"
#include "OStringStream.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;
using namespace dictionaryChecks;

//- gradientShards when the dictionary does not say: this many, or one per
//  rank with more ranks, but at most the batch
const label defaultShards = 4;


wordList getWords(const dictionary& dict, const word& key)
{
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


//- The model: type, sizes, levels, fields, node types, what is predicted
bsmsModelSpec readModelSpec(const dictionary& dict, const polyMesh& mesh)
{
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
    const word p
    (
        getAsOrDefault<word>(dict, "predict", "increment", "increment or state")
    );
    if (p != "increment" && p != "state")
    {
        badEntry(dict, "predict", p, "increment or state");
    }
    spec.increment = (p == "increment");
    return spec;
}


//- The optimiser, normalisation, noise and rollout settings
void readTrainer(const dictionary& dict, bsmsTrainSettings& t)
{
    gnnTorch::trainerSettings& s = t.trainer;
    bsmsTrainSettings::readOptimiser(dict, s, t.noise);

    // Rollout training (graphNetTrainer): the loss over K model steps
    t.rolloutSteps = getLabelAtLeast(dict, "rolloutSteps", 1, 1);
    if (t.rolloutSteps > 1000)
    {
        badEntry
        (
            dict, "rolloutSteps", name(t.rolloutSteps),
            "a number of model steps per training sample from 1 to 1000"
        );
    }
    if (t.rolloutSteps > 1 && !t.spec.increment)
    {
        badEntry
        (
            dict, "rolloutSteps", name(t.rolloutSteps),
            "1 with 'predict state' (a rollout is trained on increments)"
        );
    }
    s.rolloutSteps = int(t.rolloutSteps);
    s.rolloutBackprop = getAsOrDefault<bool>
    (
        dict, "rolloutBackprop", true, "true or false"
    );
}


} // End anonymous namespace


// * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

void Foam::bsmsTrainSettings::readOptimiser
(
    const dictionary& dict,
    gnnTorch::trainerSettings& s,
    scalar& noise
)
{
    using namespace dictionaryChecks;
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
    const string allowedFrom("a step >= 0 and <= 1e300");
    s.decayFrom = getAsOrDefault<scalar>(dict, "decayFrom", 0, allowedFrom);
    if (!(s.decayFrom >= 0 && s.decayFrom <= 1e300))
    {
        badEntry(dict, "decayFrom", name(s.decayFrom), allowedFrom);
    }
    const string allowedNoise("a finite number >= 0 and <= 1e30");
    noise = getAsOrDefault<scalar>(dict, "noise", 0, allowedNoise);
    if (!(noise >= 0 && noise <= 1e30))
    {
        badEntry(dict, "noise", name(noise), allowedNoise);
    }
    s.normAccumulations = getLabelAtLeast(dict, "normAccumulations", 1000, 1);
    s.seed = getLabelAtLeast(dict, "seed", 0, 0);
}


void Foam::bsmsTrainSettings::readBatch
(
    const dictionary& dict,
    const label nRanks,
    const label rank,
    bsmsTrainSettings& t
)
{
    t.nSteps = getLabelAtLeast(dict, "steps", 2000, 1);
    t.batch = getLabelAtLeast(dict, "batch", 1, 1);
    if (t.batch < nRanks)
    {
        badEntry
        (
            dict, "batch", name(t.batch),
            "a batch of at least the number of ranks (" + name(nRanks)
          + "): each rank trains on its share of every step's batch"
        );
    }
    // The batch in shards (graphNetTrainer::trainShards): forward and
    // backward per shard, the shards' gradients added in shard order, so
    // that any number of ranks up to gradientShards trains bit for bit as
    // one rank does
    t.nShards = getLabelAtLeast
    (
        dict, "gradientShards", min(t.batch, max(defaultShards, nRanks)), 1
    );
    if (t.nShards > t.batch || t.nShards < nRanks)
    {
        badEntry
        (
            dict, "gradientShards", name(t.nShards),
            "from the number of ranks (" + name(nRanks) + ") to batch ("
          + name(t.batch) + "): every rank takes whole shards of each batch"
        );
    }
    t.shardFirst = rank*t.nShards/nRanks;
    t.nMineShards = (rank + 1)*t.nShards/nRanks - t.shardFirst;
    t.shareFirst = t.shardFirst*t.batch/t.nShards;
    t.nMine = (t.shardFirst + t.nMineShards)*t.batch/t.nShards - t.shareFirst;
}

void Foam::bsmsTrainSettings::readRun
(
    const dictionary& dict,
    const Time& runTime,
    bsmsTrainSettings& t
)
{
    using namespace dictionaryChecks;
    t.maxTrainTime = getPositive(dict, "maxTrainTime", 1e30);
    t.checkpointInterval =
        getLabelAtLeast(dict, "checkpointInterval", t.nSteps, 1);
    t.printInterval =
        getLabelAtLeast(dict, "printInterval", max(t.nSteps/20, 1), 1);
    t.checkpoint = getAsOrDefault<fileName>
    (
        dict, "checkpoint", fileName("constant/bsmsModel.pt"), "a file name"
    );
    t.checkpoint.expand();
    if (!t.checkpoint.isAbsolute())
    {
        t.checkpoint = runTime.path()/t.checkpoint;
    }
}


// * * * * * * * * * * * * * * * * Constructor  * * * * * * * * * * * * * * //

Foam::bsmsTrainSettings Foam::bsmsTrainSettings::read
(
    const dictionary& dict,
    const polyMesh& mesh,
    const Time& runTime,
    const label nRanks,
    const label rank
)
{
    bsmsTrainSettings t;
    t.spec = readModelSpec(dict, mesh);
    readTrainer(dict, t);
    readBatch(dict, nRanks, rank, t);
    readRun(dict, runTime, t);
    t.startTime = getAsOrDefault<scalar>(dict, "startTime", -GREAT, "a time");
    t.cases = getCases(dict, fileNameList(1, fileName(".")));

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
        t.validationCases = getCases(vd, fileNameList());
        t.validationInterval = getLabelAtLeast(vd, "interval", labelMax, 1);
    }
    return t;
}

// ************************************************************************* //
