/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "metisDecomposition.H"
#include "addToRunTimeSelectionTable.H"
#include "dictionaryChecks.H"

#include <metis.h>

// * * * * * * * * * * * * * * Static Data Members  * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(metisDecomposition, 0);

    // Registered as "metis", replacing Debian's stub of that name. The
    // removable form uses HashTable::set (overrides) and removes the entry
    // when this library is unloaded.
    static decompositionMethod::
        addRemovabledictionaryConstructorToTable<metisDecomposition>
        addMetisDictionary_("metis");

    static decompositionMethod::
        addRemovabledictionaryRegionConstructorToTable<metisDecomposition>
        addMetisDictionaryRegion_("metis");
}

const Foam::Enum<Foam::metisDecomposition::algorithm>
Foam::metisDecomposition::algorithmNames
({
    { algorithm::kWay, "k-way" },
    { algorithm::recursive, "recursive" },
});

const Foam::Enum<Foam::metisDecomposition::objectiveType>
Foam::metisDecomposition::objectiveNames
({
    { objectiveType::cut, "cut" },
    { objectiveType::volume, "volume" },
});


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::metisDecomposition::readCoeffs()
{
    using namespace dictionaryChecks;
    const dictionary& d = coeffsDict_;

    method_ = getEnum(d, "method", algorithmNames, algorithm::kWay);
    objective_ = getEnum(d, "objective", objectiveNames, objectiveType::cut);
    const bool kWay = (method_ == algorithm::kWay);

    ufactor_ = getLabelAtLeast(d, "ufactor", (kWay ? 30 : 1), 1);
    niter_ = getLabelAtLeast(d, "niter", 10, 1);
    ncuts_ = getLabelAtLeast(d, "ncuts", 1, 1);
    seed_ = getLabelAtLeast(d, "seed", -1, -1);
    contiguous_ = getAsOrDefault<bool>(d, "contiguous", false, "true or false");
    minimizeConnectivity_ =
        getAsOrDefault<bool>(d, "minimizeConnectivity", false, "true or false");

    if (!kWay)
    {
        if (objective_ != objectiveType::cut)
        {
            badEntry(d, "objective", "volume (with method recursive)",
                "cut; the volume objective needs method k-way");
        }
        if (contiguous_)
        {
            badEntry(d, "contiguous", "true (with method recursive)",
                "false; contiguous subdomains need method k-way");
        }
        if (minimizeConnectivity_)
        {
            badEntry(d, "minimizeConnectivity", "true (with method recursive)",
                "false; minimizeConnectivity needs method k-way");
        }
    }

    processorWeights_.clear();
    if (d.found("processorWeights", keyType::LITERAL))
    {
        const string allowed
        (
            "a list of numberOfSubdomains = " + Foam::name(nDomains_)
          + " positive numbers"
        );
        const List<scalar> w(getAs<List<scalar>>(d, "processorWeights", allowed));
        if (w.size() != nDomains_)
        {
            badEntry(d, "processorWeights", entryText(d, "processorWeights"),
                allowed + " (found " + Foam::name(w.size()) + ")");
        }
        for (const scalar x : w)
        {
            if (!(x > 0) || !std::isfinite(x))
            {
                badEntry(d, "processorWeights",
                    entryText(d, "processorWeights"), allowed);
            }
        }
        processorWeights_ = w/sum(w);
    }
}


Foam::label Foam::metisDecomposition::decomposeSerial
(
    const labelList& adjncy,
    const labelList& xadj,
    const List<scalar>& cellWeights,
    labelList& decomp
) const
{
    static_assert
    (
        sizeof(idx_t) == sizeof(label),
        "METIS idx_t must have the size of OpenFOAM's label"
    );

    const label nCells = xadj.size() - 1;
    decomp.setSize(max(nCells, 0));
    decomp = 0;

    if (nCells <= 0 || nDomains_ == 1)
    {
        return 0;
    }

    if (nDomains_ > nCells)
    {
        FatalErrorInFunction
            << "Cannot split " << nCells << " cells into "
            << nDomains_ << " METIS subdomains" << exit(FatalError);
    }

    // Vertex weights: integers, the smallest weight mapped to 1
    List<idx_t> vwgt;
    if (cellWeights.size())
    {
        if (cellWeights.size() != nCells)
        {
            FatalErrorInFunction
                << "Number of cell weights " << cellWeights.size()
                << " does not equal the number of cells " << nCells
                << exit(FatalError);
        }
        const scalar minW = min(cellWeights);
        if (!(minW > 0))
        {
            FatalErrorInFunction
                << "Cell weights must be positive; smallest found " << minW
                << exit(FatalError);
        }
        if (sum(cellWeights)/minW > scalar(labelMax))
        {
            FatalErrorInFunction
                << "Cell weights span too wide a range for METIS's integer "
                << "weights: sum/min = " << sum(cellWeights)/minW
                << exit(FatalError);
        }
        vwgt.setSize(nCells);
        forAll(cellWeights, i)
        {
            vwgt[i] = static_cast<idx_t>(std::lround(cellWeights[i]/minW));
        }
    }

    List<real_t> tpwgts;
    if (processorWeights_.size())
    {
        tpwgts.setSize(nDomains_);
        forAll(tpwgts, i)
        {
            tpwgts[i] = static_cast<real_t>(processorWeights_[i]);
        }
    }

    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_NUMBERING] = 0;
    options[METIS_OPTION_UFACTOR] = ufactor_;
    options[METIS_OPTION_NITER] = niter_;
    options[METIS_OPTION_NCUTS] = ncuts_;
    options[METIS_OPTION_SEED] = seed_;
    if (method_ == algorithm::kWay)
    {
        options[METIS_OPTION_OBJTYPE] =
            (objective_ == objectiveType::volume ? METIS_OBJTYPE_VOL : METIS_OBJTYPE_CUT);
        options[METIS_OPTION_CONTIG] = contiguous_;
        options[METIS_OPTION_MINCONN] = minimizeConnectivity_;
    }

    idx_t nVertices = nCells;
    idx_t nConstraints = 1;
    idx_t nParts = nDomains_;
    idx_t objval = 0;

    // METIS takes non-const pointers but does not modify the graph
    idx_t* xadjPtr = const_cast<idx_t*>(xadj.cdata());
    idx_t* adjncyPtr = const_cast<idx_t*>(adjncy.cdata());
    idx_t* vwgtPtr = vwgt.size() ? vwgt.data() : nullptr;
    real_t* tpwgtsPtr = tpwgts.size() ? tpwgts.data() : nullptr;

    const int status =
    (
        method_ == algorithm::kWay
      ? METIS_PartGraphKway
        (
            &nVertices, &nConstraints, xadjPtr, adjncyPtr,
            vwgtPtr, nullptr, nullptr, &nParts, tpwgtsPtr, nullptr,
            options, &objval, decomp.data()
        )
      : METIS_PartGraphRecursive
        (
            &nVertices, &nConstraints, xadjPtr, adjncyPtr,
            vwgtPtr, nullptr, nullptr, &nParts, tpwgtsPtr, nullptr,
            options, &objval, decomp.data()
        )
    );

    if (status != METIS_OK)
    {
        FatalErrorInFunction
            << "METIS (" << algorithmNames[method_] << ") failed: "
            << (
                   status == METIS_ERROR_INPUT ? "input error"
                 : status == METIS_ERROR_MEMORY ? "out of memory"
                 : "error"
               )
            << " (status " << status << ") on a graph of "
            << nCells << " cells into " << nDomains_ << " parts"
            << exit(FatalError);
    }

    if (debug)
    {
        Info<< "metis " << algorithmNames[method_]
            << ": objective value " << objval << endl;
    }

    return objval;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::metisDecomposition::metisDecomposition(const dictionary& decompDict)
:
    metisLikeDecomp("metis", decompDict, selectionType::NULL_DICT)
{
    readCoeffs();
}


Foam::metisDecomposition::metisDecomposition
(
    const dictionary& decompDict,
    const word& regionName
)
:
    metisLikeDecomp("metis", decompDict, regionName, selectionType::NULL_DICT)
{
    readCoeffs();
}


// ************************************************************************* //
