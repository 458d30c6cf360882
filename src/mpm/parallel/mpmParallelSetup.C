/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "mpmParallel.H"
#include "polyMesh.H"
#include "processorPolyPatch.H"
#include "PstreamBuffers.H"
#include "Map.H"

#include <algorithm>

// * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

Foam::labelListList Foam::mpmParallel::holders(const labelList& globals)
{
    const label nProcs = Pstream::nProcs();

    // Ask the directory rank of each number
    List<DynamicList<label>> ask(nProcs);
    for (const label g : globals) ask[g % nProcs].append(g);

    PstreamBuffers toDir(Pstream::commsTypes::nonBlocking);
    for (label proc = 0; proc < nProcs; ++proc)
    {
        if (ask[proc].size())
        {
            UOPstream os(proc, toDir);
            os << static_cast<const labelList&>(ask[proc]);
        }
    }
    labelList sizes;
    toDir.finishedSends(sizes);

    // The directory: the ranks asking about each of its numbers (in rank
    // order, as received)
    List<labelList> asked(nProcs);
    Map<label> slot;
    DynamicList<DynamicList<label>> ranks;
    for (label proc = 0; proc < nProcs; ++proc)
    {
        if (!sizes[proc]) continue;
        UIPstream is(proc, toDir);
        is >> asked[proc];
        for (const label g : asked[proc])
        {
            auto iter = slot.find(g);
            label s;
            if (iter.found()) s = iter.val();
            else
            {
                s = ranks.size();
                slot.insert(g, s);
                ranks.append(DynamicList<label>());
            }
            ranks[s].append(proc);
        }
    }

    PstreamBuffers fromDir(Pstream::commsTypes::nonBlocking);
    for (label proc = 0; proc < nProcs; ++proc)
    {
        if (asked[proc].empty()) continue;
        labelListList answer(asked[proc].size());
        forAll(asked[proc], k)
        {
            answer[k] = ranks[slot[asked[proc][k]]];
        }
        UOPstream os(proc, fromDir);
        os << answer;
    }
    fromDir.finishedSends(sizes);

    List<labelListList> answers(nProcs);
    for (label proc = 0; proc < nProcs; ++proc)
    {
        if (!sizes[proc]) continue;
        UIPstream is(proc, fromDir);
        is >> answers[proc];
    }
    labelListList result(globals.size());
    labelList cursor(nProcs, Zero);
    forAll(globals, i)
    {
        const label d = globals[i] % nProcs;
        result[i] = answers[d][cursor[d]++];
    }
    return result;
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::mpmParallel::buildHalo(const mpmMeshView& own)
{
    const label me = Pstream::myProcNo();
    const label nProcs = Pstream::nProcs();
    const labelList& cv = own.cellVertices();

    // Vertices on processor patches and the ranks sharing them
    List<bool> onProc(nMeshVertices_, false);
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if (!isA<processorPolyPatch>(pp)) continue;
        for (const label p : pp.meshPoints())
        {
            const label v = own.pointVertex()[p];
            if (v >= 0) onProc[v] = true;
        }
    }
    labelList bVerts(nMeshVertices_);
    label nb = 0;
    forAll(onProc, v)
    {
        if (onProc[v]) bVerts[nb++] = v;
    }
    bVerts.setSize(nb);
    nProcBoundaryVertices_ = nb;
    const labelListList sharers(holders(labelList(labelUIndList(globalVertex_, bVerts))));
    labelList bIndex(nMeshVertices_, -1);
    forAll(bVerts, k) bIndex[bVerts[k]] = k;

    // The own cells around them go to the ranks sharing those vertices
    List<DynamicList<label>> sendCells(nProcs);
    labelList lastSent(nProcs, -1);
    for (label c = 0; c < nOwnedCells_; ++c)
    {
        for (label i = own.cellBegin(c); i < own.cellEnd(c); ++i)
        {
            const label k = bIndex[cv[i]];
            if (k < 0) continue;
            for (const label s : sharers[k])
            {
                if (s != me && lastSent[s] != c)
                {
                    lastSent[s] = c;
                    sendCells[s].append(c);
                }
            }
        }
    }

    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    for (label s = 0; s < nProcs; ++s)
    {
        if (sendCells[s].empty()) continue;
        labelList shapes(sendCells[s].size());
        DynamicList<label> gv;
        DynamicList<vector> xv;
        forAll(sendCells[s], j)
        {
            const label c = sendCells[s][j];
            shapes[j] = own.shape(c);
            for (label i = own.cellBegin(c); i < own.cellEnd(c); ++i)
            {
                gv.append(globalVertex_[cv[i]]);
                xv.append(own.vertices()[cv[i]]);
            }
        }
        UOPstream os(s, pBufs);
        os  << static_cast<const labelList&>(sendCells[s]) << shapes
            << static_cast<const labelList&>(gv)
            << static_cast<const List<vector>&>(xv);
    }
    labelList sizes;
    pBufs.finishedSends(sizes);

    // The extended view: own cells and vertices first, then the halo
    Map<label> vertexOf(2*nb + 16);
    forAll(globalVertex_, v) vertexOf.insert(globalVertex_[v], v);
    DynamicList<vector> verts(own.vertices());
    DynamicList<label> gvAll(globalVertex_);
    List<mpmMeshView::shapeType> shapes0(nOwnedCells_);
    for (label c = 0; c < nOwnedCells_; ++c) shapes0[c] = own.shape(c);
    DynamicList<mpmMeshView::shapeType> shapes(shapes0);
    DynamicList<label> start(nOwnedCells_ + 1);
    for (label c = 0; c <= nOwnedCells_; ++c)
    {
        start.append(c < nOwnedCells_ ? own.cellBegin(c) : cv.size());
    }
    DynamicList<label> cells(cv);
    DynamicList<label> hProc, hCell;

    for (label s = 0; s < nProcs; ++s)
    {
        if (!sizes[s]) continue;
        UIPstream is(s, pBufs);
        labelList rc, rs, rg;
        List<vector> rx;
        is >> rc >> rs >> rg >> rx;
        label k = 0;
        forAll(rc, j)
        {
            const mpmMeshView::shapeType sh =
                static_cast<mpmMeshView::shapeType>(rs[j]);
            for (label i = 0; i < mpmMeshView::nShapeVertices(sh); ++i, ++k)
            {
                auto iter = vertexOf.find(rg[k]);
                label v;
                if (iter.found()) v = iter.val();
                else
                {
                    v = verts.size();
                    vertexOf.insert(rg[k], v);
                    verts.append(rx[k]);
                    gvAll.append(rg[k]);
                }
                cells.append(v);
            }
            shapes.append(sh);
            start.append(cells.size());
            hProc.append(s);
            hCell.append(rc[j]);
        }
    }
    haloProc_.transfer(hProc);
    haloCell_.transfer(hCell);
    globalVertex_.transfer(gvAll);
    nHaloVertices_ = verts.size() - nMeshVertices_;

    view_.reset
    (
        new mpmMeshView
        (
            own.dim(), own.axes(), verts, shapes, start, cells
        )
    );
    view_->setPointVertex(own.pointVertex());
}


void Foam::mpmParallel::buildSharing()
{
    const label me = Pstream::myProcNo();
    const label nProcs = Pstream::nProcs();
    const mpmMeshView& v = view_();
    const label nV = v.nVertices();

    // Candidates: the vertices of the own cells sent as halo (a vertex of
    // another rank's halo is one of them) and the halo vertices; the own
    // cells sent are those touching a processor-patch vertex
    List<bool> cand(nV, false);
    for (label i = nMeshVertices_; i < nV; ++i) cand[i] = true;
    {
        List<bool> onProc(nMeshVertices_, false);
        for (const polyPatch& pp : mesh_.boundaryMesh())
        {
            if (!isA<processorPolyPatch>(pp)) continue;
            for (const label p : pp.meshPoints())
            {
                const label k = v.pointVertex()[p];
                if (k >= 0) onProc[k] = true;
            }
        }
        const labelList& cv = v.cellVertices();
        for (label c = 0; c < nOwnedCells_; ++c)
        {
            bool touches = false;
            for (label i = v.cellBegin(c); i < v.cellEnd(c); ++i)
            {
                if (onProc[cv[i]]) { touches = true; break; }
            }
            if (!touches) continue;
            for (label i = v.cellBegin(c); i < v.cellEnd(c); ++i)
            {
                cand[cv[i]] = true;
            }
        }
    }
    DynamicList<label> candidates;
    forAll(cand, i)
    {
        if (cand[i]) candidates.append(i);
    }
    const labelListList hs
    (
        holders(labelList(labelUIndList(globalVertex_, candidates)))
    );

    // Neighbour ranks and, per neighbour, the common vertices by number
    labelList nbrIndex(nProcs, -1);
    DynamicList<label> nbrs;
    List<DynamicList<label>> common(nProcs);
    DynamicList<label> shared;
    DynamicList<label> sharedHolders;
    forAll(candidates, k)
    {
        if (hs[k].size() < 2) continue;
        shared.append(k);
        for (const label r : hs[k])
        {
            if (r == me) continue;
            if (nbrIndex[r] < 0)
            {
                nbrIndex[r] = 0;
                nbrs.append(r);
            }
            common[r].append(candidates[k]);
        }
    }
    std::sort(nbrs.begin(), nbrs.end());
    nbrProcs_ = nbrs;
    nbrVertices_.setSize(nbrProcs_.size());
    List<Map<label>> position(nbrProcs_.size());
    forAll(nbrProcs_, q)
    {
        const label r = nbrProcs_[q];
        nbrIndex[r] = q;
        labelList& list = nbrVertices_[q];
        list = common[r];
        std::sort
        (
            list.begin(), list.end(),
            [&](const label a, const label b)
            {
                return globalVertex_[a] < globalVertex_[b];
            }
        );
        forAll(list, j) position[q].insert(list[j], j);
    }

    // The copies of each shared vertex in rank order
    sharedVertex_.setSize(shared.size());
    sumStart_.setSize(shared.size() + 1);
    sumStart_[0] = 0;
    DynamicList<label> sn, sp;
    forAll(shared, s)
    {
        const label k = shared[s];
        const label i = candidates[k];
        sharedVertex_[s] = i;
        for (const label r : hs[k])
        {
            if (r == me)
            {
                sn.append(-1);
                sp.append(-1);
            }
            else
            {
                const label q = nbrIndex[r];
                sn.append(q);
                sp.append(position[q][i]);
            }
        }
        sumStart_[s + 1] = sn.size();
    }
    sumNbr_.transfer(sn);
    sumPos_.transfer(sp);
}


// ************************************************************************* //
