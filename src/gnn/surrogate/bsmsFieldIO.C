/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "bsmsFieldIO.H"
#include "IFstream.H"
#include "volFields.H"
#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

void checkComps
(
    labelList& comps,
    const label i,
    const label nComp,
    const word& field,
    const fileName& where,
    const dictionary& errDict,
    const word& entry
)
{
    if (comps.size() <= i)
    {
        comps.resize(i + 1, nComp);
        return;
    }
    if (comps[i] != nComp)
    {
        FatalIOErrorInFunction(errDict)
            << "The field " << field << " (entry '" << entry << "' in "
            << errDict.name() << ") has " << nComp << " component(s) in "
            << where << ", but " << comps[i] << " in the model or the"
            << " other times (volScalarField: 1, volVectorField: 3)"
            << exit(FatalIOError);
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

std::vector<double> Foam::readFieldState
(
    const fileName& timeDir,
    const wordList& names,
    const label nCells,
    labelList& comps,
    const dictionary& errDict,
    const word& entry
)
{
    List<std::vector<double>> vals(names.size());
    label nState = 0;
    forAll(names, i)
    {
        const fileName file(timeDir/names[i]);
        IFstream is(file);
        if (!is.good())
        {
            FatalIOErrorInFunction(errDict)
                << "The field file " << file << " (entry '" << entry
                << "' in " << errDict.name() << ") does not exist or cannot"
                << " be read" << exit(FatalIOError);
        }
        const dictionary d(is, true);
        word cls;
        if (d.found("FoamFile")) d.subDict("FoamFile").readIfPresent("class", cls);
        label nComp = 0;
        if (cls == "volScalarField")
        {
            const scalarField v("internalField", d, nCells);
            vals[i].assign(v.begin(), v.end());
            nComp = 1;
        }
        else if (cls == "volVectorField")
        {
            const vectorField v("internalField", d, nCells);
            vals[i].reserve(3*nCells);
            for (const vector& x : v)
            {
                for (direction c = 0; c < 3; ++c) vals[i].push_back(x[c]);
            }
            nComp = 3;
        }
        else
        {
            FatalIOErrorInFunction(errDict)
                << "The field file " << file << " (entry '" << entry
                << "' in " << errDict.name() << ") is of class '" << cls
                << "'; volScalarField or volVectorField expected"
                << exit(FatalIOError);
        }
        checkComps(comps, i, nComp, names[i], timeDir, errDict, entry);
        nState += nComp;
    }

    std::vector<double> s(std::size_t(nCells)*nState);
    label o = 0;
    forAll(names, i)
    {
        const label nc = comps[i];
        for (label k = 0; k < nCells; ++k)
        {
            for (label c = 0; c < nc; ++c)
            {
                s[std::size_t(k)*nState + o + c] = vals[i][k*nc + c];
            }
        }
        o += nc;
    }
    return s;
}


std::vector<double> Foam::registryState
(
    const fvMesh& mesh,
    const wordList& names,
    const labelList& comps,
    const dictionary& errDict,
    const word& entry
)
{
    const label nCells = mesh.nCells();
    label nState = 0;
    for (const label c : comps) nState += c;
    std::vector<double> s(std::size_t(nCells)*nState);
    label o = 0;
    forAll(names, i)
    {
        const word& f = names[i];
        if (const auto* sf = mesh.findObject<volScalarField>(f))
        {
            labelList cs(comps);
            checkComps(cs, i, 1, f, mesh.time().timeName(), errDict, entry);
            for (label k = 0; k < nCells; ++k)
            {
                s[std::size_t(k)*nState + o] = (*sf)[k];
            }
        }
        else if (const auto* vf = mesh.findObject<volVectorField>(f))
        {
            labelList cs(comps);
            checkComps(cs, i, 3, f, mesh.time().timeName(), errDict, entry);
            for (label k = 0; k < nCells; ++k)
            {
                for (direction c = 0; c < 3; ++c)
                {
                    s[std::size_t(k)*nState + o + c] = (*vf)[k][c];
                }
            }
        }
        else
        {
            FatalIOErrorInFunction(errDict)
                << "The case has no volScalarField or volVectorField '" << f
                << "' (entry '" << entry << "' in " << errDict.name()
                << "; the model reads " << names << ")"
                << exit(FatalIOError);
        }
        o += comps[i];
    }
    return s;
}


void Foam::setFields
(
    const fvMesh& mesh,
    const std::vector<double>& state,
    const wordList& names,
    const labelList& comps,
    const wordList& which,
    const word& suffix
)
{
    const label nCells = mesh.nCells();
    label nState = 0;
    for (const label c : comps) nState += c;
    label o = 0;
    forAll(names, i)
    {
        const word f(names[i] + suffix);
        if (!which.found(names[i]))
        {
        }
        else if (comps[i] == 1)
        {
            auto& fld = mesh.lookupObjectRef<volScalarField>(f);
            for (label k = 0; k < nCells; ++k)
            {
                fld.primitiveFieldRef()[k] = state[std::size_t(k)*nState + o];
            }
            fld.correctBoundaryConditions();
        }
        else
        {
            auto& fld = mesh.lookupObjectRef<volVectorField>(f);
            vectorField& v = fld.primitiveFieldRef();
            for (label k = 0; k < nCells; ++k)
            {
                for (direction c = 0; c < 3; ++c)
                {
                    v[k][c] = state[std::size_t(k)*nState + o + c];
                }
            }
            fld.correctBoundaryConditions();
        }
        o += comps[i];
    }
}


bool Foam::allFinite(const std::vector<double>& v)
{
    for (const double x : v)
    {
        if (!std::isfinite(x)) return false;
    }
    return true;
}

// ************************************************************************* //
