/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "bsmsModelSpec.H"
#include "dictionaryChecks.H"
#include "polyMesh.H"
#include "emptyPolyPatch.H"
#include "wedgePolyPatch.H"
#include "processorPolyPatch.H"
#include "wordRes.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::bsmsModelSpec::nState() const
{
    label n = 0;
    for (const label c : inputComponents) n += c;
    return n;
}


Foam::label Foam::bsmsModelSpec::nOut() const
{
    label n = 0;
    for (const word& f : outputFields)
    {
        const label i = inputFields.find(f);
        n += (i < 0 ? 0 : inputComponents[i]);
    }
    return n;
}


Foam::labelList Foam::bsmsModelSpec::outputInState() const
{
    labelList start(inputFields.size(), 0);
    for (label i = 1; i < inputFields.size(); ++i)
    {
        start[i] = start[i - 1] + inputComponents[i - 1];
    }
    DynamicList<label> m;
    for (const word& f : outputFields)
    {
        const label i = inputFields.find(f);
        for (label c = 0; c < inputComponents[i]; ++c) m.append(start[i] + c);
    }
    return labelList(std::move(m));
}


void Foam::bsmsModelSpec::check(const dictionary& dict) const
{
    using namespace dictionaryChecks;
    if (inputFields.empty())
    {
        badEntry(dict, "inputFields", "()", "a non-empty list of field names");
    }
    if (outputFields.empty())
    {
        badEntry(dict, "outputFields", "()", "a non-empty list of field names");
    }
    for (const word& f : outputFields)
    {
        if (!inputFields.found(f))
        {
            OStringStream os;
            os << "fields among inputFields " << inputFields
               << " (a rollout feeds the outputs back as inputs)";
            badEntry(dict, "outputFields", f, os.str());
        }
    }
    if (inputComponents.size() != inputFields.size())
    {
        badEntry
        (
            dict, "inputComponents", entryText(dict, "inputComponents"),
            "one component count (1 or 3) per input field"
        );
    }
    for (const label c : inputComponents)
    {
        if (c != 1 && c != 3)
        {
            badEntry
            (
                dict, "inputComponents", name(c),
                "1 (volScalarField) or 3 (volVectorField) per input field"
            );
        }
    }
    if (model != "bsms" && model != "mgn")
    {
        badEntry(dict, "model", model, "one of 2(bsms mgn)");
    }
}


Foam::bsmsModelSpec Foam::bsmsModelSpec::read(const dictionary& dict)
{
    using namespace dictionaryChecks;
    bsmsModelSpec s;
    s.model = getAs<word>(dict, "model", "one of 2(bsms mgn)");
    s.latent = getLabelAtLeast(dict, "latent", 128, 1);
    s.hidden = getLabelAtLeast(dict, "hidden", 128, 1);
    s.messagePasses = getLabelAtLeast(dict, "messagePasses", 15, 1);
    if (dict.isDict("levels")) s.levels = dict.subDict("levels");
    s.inputFields = getAs<wordList>(dict, "inputFields", "a list of field names");
    s.inputComponents =
        getAs<labelList>(dict, "inputComponents", "a list of 1 or 3 per input field");
    s.outputFields =
        getAs<wordList>(dict, "outputFields", "a list of field names");
    s.nodeTypes = getAsOrDefault<List<wordRe>>
    (
        dict, "nodeTypes", List<wordRe>(), "a list of patch names or regular expressions"
    );
    s.increment =
        getWordOf(dict, "predict", "increment", {"increment", "state"})
     == "increment";
    s.deltaT = getPositive(dict, "deltaT");
    s.check(dict);
    for (const word k : {"inputMin", "inputMax"})
    {
        if (!dict.found(k, keyType::LITERAL)) continue;
        const List<scalar> v(getAs<List<scalar>>(dict, k, "a list of numbers"));
        if (v.size() != s.nState())
        {
            badEntry(dict, k, entryText(dict, k),
                "one number per state component (" + name(s.nState()) + ")");
        }
        (k == "inputMin" ? s.inputMin : s.inputMax) = v;
    }
    if (s.inputMin.size() != s.inputMax.size())
    {
        missingEntry(dict, s.inputMin.empty() ? "inputMin" : "inputMax",
            "inputMin and inputMax together");
    }
    return s;
}


void Foam::bsmsModelSpec::write(Ostream& os) const
{
    os.writeEntry("model", model);
    os.writeEntry("latent", latent);
    os.writeEntry("hidden", hidden);
    os.writeEntry("messagePasses", messagePasses);
    os.beginBlock("levels");
    levels.write(os, false);
    os.endBlock();
    os.writeEntry("inputFields", inputFields);
    os.writeEntry("inputComponents", inputComponents);
    os.writeEntry("outputFields", outputFields);
    os.writeEntry("nodeTypes", nodeTypes);
    os.writeEntry("predict", word(increment ? "increment" : "state"));
    os.writeEntry("deltaT", deltaT);
    if (inputMin.size())
    {
        os.writeEntry("inputMin", inputMin);
        os.writeEntry("inputMax", inputMax);
    }
}


gnnTorch::trainerSettings Foam::bsmsModelSpec::settings() const
{
    gnnTorch::trainerSettings s;
    s.model = model;
    s.nIn = nIn();
    s.nOut = nOut();
    s.latent = latent;
    s.hidden = hidden;
    s.nMessagePasses = messagePasses;
    return s;
}


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::List<Foam::wordRe> Foam::defaultNodeTypes(const polyMesh& mesh)
{
    DynamicList<wordRe> t;
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if
        (
            isA<emptyPolyPatch>(pp) || isA<wedgePolyPatch>(pp)
         || isA<processorPolyPatch>(pp)
        )
        {
            continue;
        }
        t.append(wordRe(pp.name()));
    }
    return List<wordRe>(std::move(t));
}


std::vector<double> Foam::nodeTypeColumns
(
    const polyMesh& mesh,
    const List<wordRe>& types
)
{
    const label nT = types.size();
    std::vector<double> cols(std::size_t(mesh.nCells())*nT, 0.0);
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        forAll(types, t)
        {
            if (!types[t].match(pp.name())) continue;
            for (const label c : pp.faceCells())
            {
                cols[std::size_t(c)*nT + t] = 1.0;
            }
        }
    }
    return cols;
}


Foam::fileName Foam::bsmsSpecFile(const fileName& checkpoint)
{
    return checkpoint.path()/(checkpoint.nameLessExt() + "Dict");
}

// ************************************************************************* //
