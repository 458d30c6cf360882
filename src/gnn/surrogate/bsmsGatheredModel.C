/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "bsmsGatheredModel.H"
#include "Time.H"
#include "polyMesh.H"
#include "labelIOList.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "IPstream.H"
#include "OPstream.H"
#include "bsmsFieldIO.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Pstream::parRun() off for a scope (the master's serial work on the
//  undecomposed mesh must not communicate)
class serialScope
{
    const bool old_;
public:
    serialScope() : old_(Foam::Pstream::parRun()) { Foam::Pstream::parRun() = false; }
    ~serialScope() { Foam::Pstream::parRun() = old_; }
};

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::bsmsGatheredModel::readAddressing()
{
    IOobject io
    (
        "cellProcAddressing",
        mesh_.facesInstance(),
        polyMesh::meshSubDir,
        mesh_,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (!io.typeHeaderOk<labelIOList>(true))
    {
        FatalErrorInFunction
            << "The processor mesh lacks " << io.objectPath() << ", which"
            << " maps its cells to the undecomposed mesh that the GNN model"
            << " runs on; decompose the case with decomposePar"
            << exit(FatalError);
    }
    const labelIOList addr(io);
    if (addr.size() != mesh_.nCells())
    {
        FatalErrorInFunction
            << io.objectPath() << " has " << addr.size() << " entries for "
            << mesh_.nCells() << " cells of the processor mesh"
            << exit(FatalError);
    }

    if (Pstream::master())
    {
        procCells_.setSize(Pstream::nProcs());
        procCells_[0] = addr;
        for (int p = Pstream::firstSlave(); p <= Pstream::lastSlave(); ++p)
        {
            IPstream is(Pstream::commsTypes::blocking, p);
            is >> procCells_[p];
        }
        // Each undecomposed cell once
        nGlobal_ = mesh0_->nCells();
        labelList seen(nGlobal_, 0);
        label nSeen = 0;
        forAll(procCells_, p)
        {
            for (const label c : procCells_[p])
            {
                if (c < 0 || c >= nGlobal_ || seen[c]++)
                {
                    FatalErrorInFunction
                        << "processor" << p << "'s cellProcAddressing (in "
                        << io.objectPath().path() << " of that processor)"
                        << " names the undecomposed cell " << c << " twice"
                        << " or outside the " << nGlobal_ << " cells of "
                        << time0_().path()/"constant/polyMesh"
                        << ": the decomposition is not of this mesh"
                        << exit(FatalError);
                }
                ++nSeen;
            }
        }
        if (nSeen != nGlobal_)
        {
            FatalErrorInFunction
                << "The processors' cellProcAddressing covers " << nSeen
                << " of the " << nGlobal_ << " cells of the undecomposed"
                << " mesh: the decomposition is not of this mesh"
                << exit(FatalError);
        }
    }
    else
    {
        OPstream os(Pstream::commsTypes::blocking, Pstream::masterNo());
        os << static_cast<const labelList&>(addr);
    }
    Pstream::scatter(nGlobal_);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bsmsGatheredModel::bsmsGatheredModel
(
    const fvMesh& mesh,
    const fileName& checkpoint,
    const dictionary& errDict,
    const word& entry
)
:
    mesh_(mesh),
    nGlobal_(mesh.nCells())
{
    if (!Pstream::parRun())
    {
        model_ = bsmsSurrogateModel::load(mesh, checkpoint, errDict, entry);
        spec_ = model_->spec();
        return;
    }

    // Every rank: the files exist and the model dictionary (the spec)
    const fileName specFile(bsmsSpecFile(checkpoint));
    for (const fileName& f : {checkpoint, specFile})
    {
        if (!isFile(f))
        {
            FatalIOErrorInFunction(errDict)
                << "The model file " << f << " (entry '" << entry << "' in "
                << errDict.name() << ") does not exist; bsmsTrain writes the"
                << " checkpoint and its model dictionary "
                << specFile.name() << " beside it" << exit(FatalIOError);
        }
    }
    {
        IFstream is(specFile);
        dictionary specDict(is, true);
        specDict.name() = specFile;
        spec_ = bsmsModelSpec::read(specDict);
    }

    // The master: the undecomposed mesh
    if (Pstream::master())
    {
        const Time& rt = mesh.time();
        serialScope serial;
        time0_.reset
        (
            new Time
            (
                rt.rootPath(), rt.globalCaseName(), "system", "constant",
                false, false
            )
        );
        mesh0_.reset
        (
            new polyMesh
            (
                IOobject
                (
                    polyMesh::defaultRegion,
                    mesh.facesInstance(),
                    time0_(),
                    IOobject::MUST_READ
                )
            )
        );
    }
    readAddressing();

    if (Pstream::master())
    {
        serialScope serial;
        Info<< "Parallel run: the model runs on the master on the"
            << " undecomposed mesh (" << nGlobal_ << " cells) of "
            << time0_().path() << endl;
        model_ = bsmsSurrogateModel::load(mesh0_(), checkpoint, errDict, entry);
    }
}


Foam::bsmsGatheredModel::~bsmsGatheredModel()
{
    model_.reset();
    mesh0_.clear();
    time0_.clear();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::string Foam::bsmsGatheredModel::levelSizes() const
{
    return model_ ? model_->levelSizes() : string();
}


std::vector<double> Foam::bsmsGatheredModel::gather
(
    const std::vector<double>& local
) const
{
    if (!Pstream::parRun()) return local;

    const std::size_t nS = spec_.nState();
    if (!Pstream::master())
    {
        OPstream os(Pstream::commsTypes::blocking, Pstream::masterNo());
        os << scalarList(local.begin(), local.end());
        return std::vector<double>();
    }
    std::vector<double> global(std::size_t(nGlobal_)*nS);
    forAll(procCells_, p)
    {
        scalarList v;
        if (p == Pstream::masterNo())
        {
            v = scalarList(local.begin(), local.end());
        }
        else
        {
            IPstream is(Pstream::commsTypes::blocking, p);
            is >> v;
        }
        const labelList& cells = procCells_[p];
        forAll(cells, k)
        {
            for (std::size_t c = 0; c < nS; ++c)
            {
                global[std::size_t(cells[k])*nS + c] = v[k*nS + c];
            }
        }
    }
    return global;
}


std::vector<double> Foam::bsmsGatheredModel::scatter
(
    const std::vector<double>& global
) const
{
    if (!Pstream::parRun()) return global;

    const std::size_t nS = spec_.nState();
    if (!Pstream::master())
    {
        IPstream is(Pstream::commsTypes::blocking, Pstream::masterNo());
        scalarList v(is);
        return std::vector<double>(v.begin(), v.end());
    }
    std::vector<double> mine;
    forAll(procCells_, p)
    {
        const labelList& cells = procCells_[p];
        scalarList v(cells.size()*nS);
        forAll(cells, k)
        {
            for (std::size_t c = 0; c < nS; ++c)
            {
                v[k*nS + c] = global[std::size_t(cells[k])*nS + c];
            }
        }
        if (p == Pstream::masterNo())
        {
            mine.assign(v.begin(), v.end());
        }
        else
        {
            OPstream os(Pstream::commsTypes::blocking, p);
            os << v;
        }
    }
    return mine;
}


bool Foam::bsmsGatheredModel::advance(std::vector<double>& global)
{
    bool finite = true;
    if (model_)
    {
        model_->advance(global);
        finite = allFinite(global);
    }
    if (Pstream::parRun()) Pstream::scatter(finite);
    return finite;
}

// ************************************************************************* //
