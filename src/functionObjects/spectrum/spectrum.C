/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "spectrum.H"
#include "dictionaryChecks.H"
#include "volFields.H"
#include "interpolationCellPoint.H"
#include "OFstream.H"
#include "addToRunTimeSelectionTable.H"

#include <stdexcept>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(spectrum, 0);
    addToRunTimeSelectionTable(functionObject, spectrum, dictionary);
}
}

namespace
{
    const Foam::Enum<Foam::powerSpectrum::windowType> windowNames
    ({
        { Foam::powerSpectrum::windowType::hann, "hann" },
        { Foam::powerSpectrum::windowType::none, "none" },
    });

    const Foam::Enum<Foam::powerSpectrum::detrendType> detrendNames
    ({
        { Foam::powerSpectrum::detrendType::linear, "linear" },
        { Foam::powerSpectrum::detrendType::mean, "mean" },
        { Foam::powerSpectrum::detrendType::none, "none" },
    });
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::spectrum::locateProbes(const dictionary& dict)
{
    probeCells_.setSize(probeLocations_.size());
    forAll(probeLocations_, i)
    {
        probeCells_[i] = mesh_.findCell(probeLocations_[i]);
        const label nFound =
            returnReduce(label(probeCells_[i] >= 0 ? 1 : 0), sumOp<label>());
        if (nFound == 0)
        {
            OStringStream found;
            found << probeLocations_[i] << " (probe " << i
                << ") lies outside the mesh";
            OStringStream allowed;
            allowed << "points inside the mesh, bounds " << mesh_.bounds();
            dictionaryChecks::badEntry
            (
                dict, "probeLocations", found.str(), allowed.str()
            );
        }
        if (nFound > 1)
        {
            // A point on a processor boundary: keep the lowest processor's
            const label owner = returnReduce
            (
                probeCells_[i] >= 0 ? Pstream::myProcNo() : Pstream::nProcs(),
                minOp<label>()
            );
            if (Pstream::myProcNo() != owner)
            {
                probeCells_[i] = -1;
            }
        }
    }
}


Foam::wordList Foam::functionObjects::spectrum::makeSignalNames() const
{
    DynamicList<word> names;
    for (const Pair<word>& r : results_)
    {
        names.append(r.second());
    }
    for (const word& f : fieldNames_)
    {
        const bool isScalar = mesh_.foundObject<volScalarField>(f);
        const bool isVector = mesh_.foundObject<volVectorField>(f);
        if (!isScalar && !isVector)
        {
            FatalErrorInFunction
                << "spectrum '" << name() << "': field " << f
                << " is neither a volScalarField nor a volVectorField" << nl
                << "    available volScalarFields: "
                << mesh_.sortedNames<volScalarField>() << nl
                << "    available volVectorFields: "
                << mesh_.sortedNames<volVectorField>() << nl
                << exit(FatalError);
        }
        forAll(probeLocations_, i)
        {
            const word suffix("_p" + Foam::name(i));
            if (isScalar)
            {
                names.append(f + suffix);
            }
            else
            {
                names.append(f + "_x" + suffix);
                names.append(f + "_y" + suffix);
                names.append(f + "_z" + suffix);
            }
        }
    }
    return wordList(std::move(names));
}


bool Foam::functionObjects::spectrum::sample(List<scalar>& vals) const
{
    vals.setSize(signalNames_.size());
    label k = 0;

    for (const Pair<word>& r : results_)
    {
        scalar v = 0;
        if (!getObjectResult<scalar>(r.first(), r.second(), v))
        {
            return false;
        }
        vals[k++] = v;
    }

    for (const word& f : fieldNames_)
    {
        if (mesh_.foundObject<volScalarField>(f))
        {
            interpolationCellPoint<scalar> interp
            (
                mesh_.lookupObject<volScalarField>(f)
            );
            forAll(probeLocations_, i)
            {
                scalar v = 0;
                if (probeCells_[i] >= 0)
                {
                    v = interp.interpolate(probeLocations_[i], probeCells_[i]);
                }
                vals[k++] = returnReduce(v, sumOp<scalar>());
            }
        }
        else
        {
            interpolationCellPoint<vector> interp
            (
                mesh_.lookupObject<volVectorField>(f)
            );
            forAll(probeLocations_, i)
            {
                vector v(Zero);
                if (probeCells_[i] >= 0)
                {
                    v = interp.interpolate(probeLocations_[i], probeCells_[i]);
                }
                reduce(v, sumOp<vector>());
                vals[k++] = v.x();
                vals[k++] = v.y();
                vals[k++] = v.z();
            }
        }
    }
    return true;
}


void Foam::functionObjects::spectrum::restoreRecord()
{
    wordList names;
    if (!getProperty("signals", names) || names.empty())
    {
        return;
    }
    List<scalar> t;
    getProperty("times", t);

    const scalar now = time_.value();
    label n = 0;
    while (n < t.size() && t[n] <= now + SMALL*max(mag(now), scalar(1)))
    {
        ++n;
    }

    signalNames_ = names;
    values_.setSize(names.size());
    times_ = SubList<scalar>(t, n);
    forAll(names, s)
    {
        List<scalar> v;
        getProperty("values_" + names[s], v);
        if (v.size() < n)
        {
            WarningInFunction
                << "spectrum '" << name() << "': saved record of "
                << names[s] << " is incomplete; starting a new record"
                << endl;
            signalNames_.clear();
            values_.clear();
            times_.clear();
            return;
        }
        values_[s] = SubList<scalar>(v, n);
    }
    Info<< type() << ' ' << name() << ": continuing a record of "
        << n << " samples from the restart time" << endl;
}


void Foam::functionObjects::spectrum::writeSpectra()
{
    if (times_.size() < 4)
    {
        Info<< type() << ' ' << name() << ": " << times_.size()
            << " samples after startTime " << startTime_
            << ", too few for a spectrum" << endl;
        return;
    }

    const std::vector<double> t(times_.begin(), times_.end());
    List<std::unique_ptr<powerSpectrum>> spectra(signalNames_.size());
    forAll(signalNames_, s)
    {
        const std::vector<double> y(values_[s].begin(), values_[s].end());
        try
        {
            spectra[s].reset(new powerSpectrum(t, y, options_));
        }
        catch (const std::exception& e)
        {
            FatalErrorInFunction
                << "spectrum '" << name() << "', signal " << signalNames_[s]
                << ": " << e.what() << exit(FatalError);
        }
    }

    if (!Pstream::master())
    {
        return;
    }

    const fileName dir
    (
        time_.globalPath()/functionObject::outputPrefix/name()/startTimeName_
    );
    mkDir(dir);

    const powerSpectrum& ref = *spectra[0];
    const bool strouhal = referenceLength_ > 0;
    const scalar stFactor = strouhal ? referenceLength_/referenceSpeed_ : 0;

    {
        OFstream os(dir/(name() + ".dat"));
        os.precision(8);
        os  << "# spectrum: one-sided power spectral density, window "
            << windowNames[options_.window] << ", detrend "
            << detrendNames[options_.detrend] << ", zero padding "
            << label(options_.zeroPadding) << nl
            << "# samples: " << times_.size() << " from t = " << times_.first()
            << " to " << times_.last() << " s, resampled to "
            << label(ref.nSamples()) << " at dt = " << ref.sampleInterval()
            << " s; resolution 1/T = " << ref.resolution() << " 1/s" << nl
            << "# f [1/s]";
        if (strouhal) os << "\tSt [-]";
        for (const word& s : signalNames_)
        {
            os << '\t' << s << " [signal^2 s]";
        }
        os  << nl;

        const std::vector<double>& f = ref.frequency();
        for (std::size_t k = 0; k < f.size(); ++k)
        {
            os  << f[k];
            if (strouhal) os << '\t' << f[k]*stFactor;
            forAll(spectra, s)
            {
                os << '\t' << spectra[s]->power()[k];
            }
            os  << nl;
        }
    }

    OFstream ps(dir/"peaks.dat");
    ps.precision(8);
    ps  << "# dominant frequencies, strongest first; resolution 1/T = "
        << ref.resolution() << " 1/s" << nl
        << "# signal\trank\tf [1/s]\tSt [-]\tpower [signal^2 s]" << nl;

    Info<< type() << ' ' << name() << " (t " << times_.first() << " to "
        << times_.last() << ", " << times_.size() << " samples, df "
        << ref.resolution() << "):" << nl;
    forAll(spectra, s)
    {
        const std::vector<powerSpectrum::peak> pk =
            spectra[s]->peaks(std::size_t(nPeaks_));
        Info<< "    " << signalNames_[s] << ":";
        for (std::size_t r = 0; r < pk.size(); ++r)
        {
            const scalar St = pk[r].frequency*stFactor;
            ps  << signalNames_[s] << '\t' << r + 1 << '\t'
                << pk[r].frequency << '\t' << (strouhal ? St : scalar(0))
                << '\t' << pk[r].power << nl;
            Info<< " f" << r + 1 << " = " << pk[r].frequency;
            if (strouhal) Info<< " (St " << St << ")";
        }
        Info<< nl;
    }
    Info<< endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::functionObjects::spectrum::spectrum
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    startTime_(0),
    nPeaks_(3),
    referenceLength_(0),
    referenceSpeed_(0),
    startTimeName_(runTime.timeName()),
    warnedMissing_(false)
{
    read(dict);
    restoreRecord();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

bool Foam::functionObjects::spectrum::read(const dictionary& dict)
{
    using namespace dictionaryChecks;

    fvMeshFunctionObject::read(dict);

    results_ = getAsOrDefault<List<Pair<word>>>
    (
        dict, "results", List<Pair<word>>(),
        "a list of (functionObjectName resultName) pairs"
    );
    fieldNames_ = getAsOrDefault<wordList>
    (
        dict, "fields", wordList(), "a list of field names"
    );

    if (results_.empty() && fieldNames_.empty())
    {
        FatalIOErrorInFunction(dict)
            << "spectrum '" << this->name() << "' in " << dict.name()
            << " has no signal: both 'results' and 'fields' are missing"
            << " or empty" << nl
            << "    allowed: results ((functionObjectName resultName) ...)"
            << " and/or fields (name ...) with probeLocations ((x y z) ...)"
            << nl << exit(FatalIOError);
    }

    probeLocations_.clear();
    if (fieldNames_.size())
    {
        probeLocations_ = getAs<List<point>>
        (
            dict, "probeLocations",
            "a non-empty list of points ((x y z) ...), needed by 'fields'"
        );
        if (probeLocations_.empty())
        {
            badEntry(dict, "probeLocations", "()",
                "a non-empty list of points ((x y z) ...), needed by 'fields'");
        }
    }

    startTime_ = getAsOrDefault<scalar>(dict, "startTime", 0, "a number");
    options_.window =
        getEnum(dict, "window", windowNames, powerSpectrum::windowType::hann);
    options_.detrend =
        getEnum(dict, "detrend", detrendNames, powerSpectrum::detrendType::linear);
    options_.zeroPadding = std::size_t(getLabelAtLeast(dict, "zeroPadding", 4, 1));
    nPeaks_ = getLabelAtLeast(dict, "nPeaks", 3, 1);

    referenceLength_ = 0;
    referenceSpeed_ = 0;
    const bool hasL = dict.found("referenceLength", keyType::LITERAL);
    const bool hasU = dict.found("referenceSpeed", keyType::LITERAL);
    if (hasL != hasU)
    {
        const word missing(hasL ? "referenceSpeed" : "referenceLength");
        missingEntry(dict, missing,
            "referenceLength and referenceSpeed together (for St = f L/U),"
            " or neither");
    }
    if (hasL)
    {
        referenceLength_ = getPositive(dict, "referenceLength", 1);
        referenceSpeed_ = getPositive(dict, "referenceSpeed", 1);
    }

    locateProbes(dict);
    return true;
}


bool Foam::functionObjects::spectrum::execute()
{
    const scalar t = time_.value();
    if (t < startTime_)
    {
        return true;
    }
    if (signalNames_.empty())
    {
        signalNames_ = makeSignalNames();
        values_.setSize(signalNames_.size());
    }

    List<scalar> vals;
    if (!sample(vals))
    {
        if (!warnedMissing_)
        {
            WarningInFunction
                << "spectrum '" << name() << "': a result in 'results' is"
                << " not (yet) available at t = " << t << "; list this"
                << " function object after the one producing it."
                << " Skipping such steps." << endl;
            warnedMissing_ = true;
        }
        return true;
    }

    if (times_.size() && t <= times_.last())
    {
        return true;  // same time executed twice (e.g. at the end)
    }
    times_.append(t);
    forAll(vals, s)
    {
        values_[s].append(vals[s]);
    }
    return true;
}


bool Foam::functionObjects::spectrum::write()
{
    if (!time_.writeTime())
    {
        return true;
    }

    // Save the record with this write time, for restarts
    setProperty("signals", signalNames_);
    setProperty("times", List<scalar>(times_));
    forAll(signalNames_, s)
    {
        setProperty("values_" + signalNames_[s], List<scalar>(values_[s]));
    }

    writeSpectra();
    return true;
}


bool Foam::functionObjects::spectrum::end()
{
    writeSpectra();
    return true;
}


// ************************************************************************* //
