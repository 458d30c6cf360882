/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "mpmParallel.H"
#include "polyMesh.H"
#include "processorPolyPatch.H"
#include "processorCyclicPolyPatch.H"
#include "labelIOList.H"
#include "PstreamBuffers.H"
#include "Map.H"
#include "ops.H"

#include <algorithm>
#include <chrono>

// * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

Foam::scalar& Foam::mpmParallel::commTime()
{
    static scalar t = 0;
    return t;
}


Foam::scalar& Foam::mpmParallel::commCpuTime()
{
    static scalar t = 0;
    return t;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::mpmParallel::mpmParallel(const polyMesh& mesh)
:
    mesh_(mesh),
    nOwnedCells_(mesh.nCells()),
    nMeshVertices_(0),
    nProcBoundaryVertices_(0),
    nHaloVertices_(0),
    nMigrated_(0),
    nMigratedTotal_(0)
{
    if (mesh.nSolutionD() == 1)
    {
        FatalErrorInFunction
            << "Mesh " << mesh.objectPath() << " is 1D: the MPM solver runs"
            << " 1D meshes serially only (run it without -parallel)"
            << exit(FatalError);
    }
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (isA<processorCyclicPolyPatch>(pp))
        {
            FatalErrorInFunction
                << "Mesh " << mesh.objectPath() << ": patch " << pp.name()
                << " is a processorCyclic patch (a cyclic patch split between"
                << " ranks); the MPM grid has no cyclic conditions. Decompose"
                << " a mesh without cyclic patches" << exit(FatalError);
        }
    }

    IOobject io
    (
        "pointProcAddressing",
        mesh.facesInstance(),
        polyMesh::meshSubDir,
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (!io.typeHeaderOk<labelIOList>(true))
    {
        FatalErrorInFunction
            << "The processor mesh lacks " << io.objectPath() << ", which"
            << " numbers its points as the undecomposed mesh does; the MPM"
            << " grid joins the ranks' copies of a vertex by it. Decompose"
            << " the case with decomposePar" << exit(FatalError);
    }
    const labelIOList addr(io);
    if (addr.size() != mesh.nPoints())
    {
        FatalErrorInFunction
            << "File " << io.objectPath() << " lists " << addr.size()
            << " points for the " << mesh.nPoints() << " of the processor"
            << " mesh: it belongs to another decomposition. Decompose the"
            << " case again (decomposePar -force)" << exit(FatalError);
    }

    const mpmMeshView own(mesh);
    nMeshVertices_ = own.nVertices();
    globalVertex_.setSize(nMeshVertices_, -1);
    forAll(own.pointVertex(), p)
    {
        const label v = own.pointVertex()[p];
        if (v >= 0 && globalVertex_[v] < 0) globalVertex_[v] = addr[p];
    }

    buildHalo(own);
    buildSharing();

    // Sizes and boundary marks of the vertices from the ranks holding all
    // their cells (those holding the vertex in their mesh)
    const mpmMeshView& v = view_();
    const label nV = v.nVertices();
    scalarList h(nV, scalar(-1)), hMax(nV, scalar(-1)), bnd(nV, scalar(-1));
    for (label i = 0; i < nMeshVertices_; ++i)
    {
        h[i] = v.vertexSize()[i];
        hMax[i] = v.vertexMaxEdge()[i];
        bnd[i] = v.boundaryVertex(i) ? 1 : 0;
    }
    maxShared(h);
    maxShared(hMax);
    maxShared(bnd);
    List<bool> boundary(nV);
    forAll(bnd, i) boundary[i] = bnd[i] > 0.5;
    view_->setVertexData(h, hMax, boundary);
    view_->setSharedMax([this](UList<scalar>& f) { maxShared(f); });
    view_->setGlobalRingReach([this]() { return globalRingReach(); });

    Info<< "MPM parallel grid on " << Pstream::nProcs() << " ranks: per rank"
        << " (largest) " << returnReduce(nOwnedCells_, maxOp<label>())
        << " cells, " << returnReduce(nProcBoundaryVertices_, maxOp<label>())
        << " processor-patch vertices, "
        << returnReduce(nHaloVertices_, maxOp<label>()) << " halo vertices in "
        << returnReduce(haloProc_.size(), maxOp<label>()) << " halo cells, "
        << returnReduce(sharedVertex_.size(), maxOp<label>())
        << " vertices (" << returnReduce(nValuesSent(), maxOp<label>())
        << " values sent per exchange) shared with "
        << returnReduce(nbrProcs_.size(), maxOp<label>())
        << " neighbour ranks" << nl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::mpmParallel::maxShared(UList<scalar>& values) const
{
    combineShared(values, maxOp<scalar>(), nullptr);
}


Foam::scalarList Foam::mpmParallel::globalRingReach() const
{
    // Each rank's own cells (shape, global vertex numbers) and the
    // positions of their vertices, gathered on the master, which builds
    // the whole mesh's view once and answers every rank at its vertices
    const mpmMeshView& v = view_();
    const label me = Pstream::myProcNo();
    List<labelList> shapes(Pstream::nProcs());
    List<labelList> cellGlobal(Pstream::nProcs());
    List<List<vector>> cellPoints(Pstream::nProcs());
    List<labelList> asked(Pstream::nProcs());
    {
        labelList& s = shapes[me];
        labelList& g = cellGlobal[me];
        List<vector>& x = cellPoints[me];
        s.setSize(nOwnedCells_);
        const label nCV = v.cellBegin(nOwnedCells_);
        g.setSize(nCV);
        x.setSize(nCV);
        for (label c = 0; c < nOwnedCells_; ++c)
        {
            s[c] = v.shape(c);
            for (label i = v.cellBegin(c); i < v.cellEnd(c); ++i)
            {
                g[i] = globalVertex_[v.cellVertices()[i]];
                x[i] = v.vertices()[v.cellVertices()[i]];
            }
        }
        asked[me] = globalVertex_;
    }
    Pstream::gatherList(shapes);
    Pstream::gatherList(cellGlobal);
    Pstream::gatherList(cellPoints);
    Pstream::gatherList(asked);

    scalarList mine;
    if (Pstream::master())
    {
        Map<label> index;
        DynamicList<vector> points;
        DynamicList<mpmMeshView::shapeType> allShapes;
        DynamicList<label> start(1, label(0));
        DynamicList<label> cellVertices;
        forAll(shapes, p)
        {
            label i = 0;
            for (const label s : shapes[p])
            {
                const label n =
                    mpmMeshView::nShapeVertices(mpmMeshView::shapeType(s));
                for (label k = 0; k < n; ++k, ++i)
                {
                    const label g = cellGlobal[p][i];
                    if (!index.found(g))
                    {
                        index.insert(g, points.size());
                        points.append(cellPoints[p][i]);
                    }
                    cellVertices.append(index[g]);
                }
                allShapes.append(mpmMeshView::shapeType(s));
                start.append(cellVertices.size());
            }
        }
        const mpmMeshView whole
        (
            v.dim(), v.axes(), points, allShapes, start, cellVertices
        );
        const scalarList reach(whole.ringReach());
        forAll(asked, p)
        {
            scalarList answer(asked[p].size(), GREAT);
            forAll(answer, j)
            {
                const auto it = index.cfind(asked[p][j]);
                if (it.found()) answer[j] = reach[*it];
            }
            if (p == 0)
            {
                mine.transfer(answer);
            }
            else
            {
                OPstream toRank(Pstream::commsTypes::scheduled, p);
                toRank << answer;
            }
        }
    }
    else
    {
        IPstream fromMaster
        (
            Pstream::commsTypes::scheduled, Pstream::masterNo()
        );
        fromMaster >> mine;
    }
    return mine;
}


bool Foam::mpmParallel::migrate(mpmParticles& P) const
{
    const mpmMeshView& v = view_();
    const label nP = P.size();
    bool ok = true;

    List<mpmParticles> out(nbrProcs_.size());
    List<bool> leave(nP, false);
    label nLeave = 0;
    for (label p = 0; p < nP; ++p)
    {
        const label c = v.findCell(P.x[p], P.cell[p]);
        if (c < 0)
        {
            ok = false;     // left the mesh: the next step stops
        }
        else if (c < nOwnedCells_)
        {
            P.cell[p] = c;
        }
        else
        {
            const label h = c - nOwnedCells_;
            const label q =
                std::lower_bound
                (
                    nbrProcs_.begin(), nbrProcs_.end(), haloProc_[h]
                ) - nbrProcs_.begin();
            P.cell[p] = haloCell_[h];
            out[q].appendFrom(P, p);
            leave[p] = true;
            ++nLeave;
        }
    }
    if (nLeave) P.remove(leave);
    nMigrated_ = nLeave;
    nMigratedTotal_ += nLeave;

    const exchangeTimer timer;
    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    forAll(nbrProcs_, q)
    {
        const mpmParticles& Q = out[q];
        UOPstream os(nbrProcs_[q], pBufs);
        os  << Q.x << Q.v << Q.B << Q.F << Q.m << Q.V0 << Q.V << Q.sigma
            << Q.psi << Q.epsilonP << Q.Jp << Q.material << Q.cell << Q.id
            << Q.fContact;
    }
    pBufs.finishedSends();
    forAll(nbrProcs_, q)
    {
        UIPstream is(nbrProcs_[q], pBufs);
        mpmParticles Q;
        List<vector> x, vel, fContact;
        List<tensor> B, F;
        scalarList m, V0, V, psi, epsilonP, Jp;
        List<symmTensor> sigma;
        labelList material, cell, id;
        is >> x >> vel >> B >> F >> m >> V0 >> V >> sigma >> psi >> epsilonP
            >> Jp >> material >> cell >> id >> fContact;
        Q.x = x; Q.v = vel; Q.B = B; Q.F = F; Q.m = m; Q.V0 = V0; Q.V = V;
        Q.sigma = sigma; Q.psi = psi; Q.epsilonP = epsilonP; Q.Jp = Jp;
        Q.material = material; Q.cell = cell; Q.id = id;
        Q.fContact = fContact;
        forAll(x, p) P.appendFrom(Q, p);
    }

    return ok;
}


// ************************************************************************* //
