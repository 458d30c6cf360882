/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "latticeRing.H"
#include "PstreamBuffers.H"
#include "UIPstream.H"
#include "UOPstream.H"
#include "PstreamReduceOps.H"
#include "labelVector.H"
#include <algorithm>
#include <map>
#include <array>

// * * * * * * * * * * * * * * Private Functions * * * * * * * * * * * * * * //

void Foam::latticeRing::buildCopies
(
    const labelListList& lists,
    label nEntities,
    copies& c
) const
{
    // entity -> (rank, neighbour index, position)
    std::map<label, std::vector<std::array<label, 3>>> at;
    forAll(lists, q)
    {
        forAll(lists[q], j)
        {
            at[lists[q][j]].push_back({nbrProcs_[q], label(q), label(j)});
        }
    }
    const label me = Pstream::myProcNo();
    c.entity.setSize(label(at.size()));
    c.start.setSize(label(at.size()) + 1);
    DynamicList<label> nbr, pos;
    label s = 0;
    c.start[0] = 0;
    for (auto& kv : at)
    {
        if (kv.first < 0 || kv.first >= nEntities)
        {
            FatalErrorInFunction
                << "Shared entity " << kv.first << " outside 0.."
                << nEntities << exit(FatalError);
        }
        kv.second.push_back({me, -1, -1});
        std::sort
        (
            kv.second.begin(), kv.second.end(),
            [](const std::array<label, 3>& a, const std::array<label, 3>& b)
            {
                return a[0] < b[0];
            }
        );
        c.entity[s] = kv.first;
        for (const auto& e : kv.second)
        {
            nbr.append(e[1]);
            pos.append(e[2]);
        }
        c.start[++s] = nbr.size();
    }
    c.nbr.transfer(nbr);
    c.pos.transfer(pos);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::latticeRing::latticeRing(const cartesianMesh& lattice)
:
    lat_(lattice)
{
    // This rank's box in the global lattice: offset from the smallest
    // origin over the ranks
    vector gOrigin(lat_.origin());
    reduce(gOrigin, minOp<vector>());
    gOrigin_ = gOrigin;
    for (label d = 0; d < 3; ++d)
    {
        sh_[d] = lat_.active(d) ? 1 : 0;
        off_[d] = lat_.active(d)
            ? label(std::lround((lat_.origin()[d] - gOrigin[d])/lat_.dx(d)))
            : 0;
        nE_[d] = lat_.n(d) + 2*sh_[d];
        N_[d] = off_[d] + lat_.n(d);
    }
    if (lat_.nCells() != lat_.n(0)*lat_.n(1)*lat_.n(2))
    {
        FatalErrorInFunction
            << "Processor " << Pstream::myProcNo() << " holds "
            << lat_.nCells() << " cells, not a full box of the lattice ("
            << lat_.n(0) << " x " << lat_.n(1) << " x " << lat_.n(2)
            << "): the solid's deposits of a -parallel CSMPM run need a"
            << " box decomposition (simple or hierarchical) of a mesh"
            << " without holes." << nl
            << "    simple and hierarchical tilt their axes by the coeffs'"
            << " delta (0.001 unless given), which cuts a lattice of more"
            << " than about 1/delta cells across a split direction off the"
            << " box: give delta 1e-8 in decomposeParDict's coeffs"
            << exit(FatalError);
    }
    {
        labelVector Nv(N_[0], N_[1], N_[2]);
        reduce(Nv, maxOp<labelVector>());
        for (label d = 0; d < 3; ++d) N_[d] = Nv[d];
    }
    strideE_[0] = 1;
    strideE_[1] = nE_[0];
    strideE_[2] = nE_[0]*nE_[1];
    for (label d = 0; d < 3; ++d)
    {
        for (label e = 0; e < 3; ++e)
        {
            fdim_[d][e] = nE_[e] + ((e == d && lat_.active(d)) ? 1 : 0);
        }
        nFacesE_[d] =
            lat_.active(d) ? fdim_[d][0]*fdim_[d][1]*fdim_[d][2] : 0;
    }

    // Every rank's box
    List<labelList> boxes(Pstream::nProcs());
    boxes[Pstream::myProcNo()] = labelList
    ({
        off_[0], off_[1], off_[2], lat_.n(0), lat_.n(1), lat_.n(2)
    });
    Pstream::gatherList(boxes);
    Pstream::scatterList(boxes);

    // Grown box of rank r clipped to the global lattice: cells [lo, hi)
    auto grown = [&](label r, label d, label& lo, label& hi)
    {
        lo = max(label(0), boxes[r][d] - sh_[d]);
        hi = min(N_[d], boxes[r][d] + boxes[r][3 + d] + sh_[d]);
    };
    const label me = Pstream::myProcNo();
    auto toE = [&](label d, label g) { return g - (off_[d] - sh_[d]); };

    DynamicList<label> nbrs;
    DynamicList<labelList> cellLists, faceLists[3];
    for (label r = 0; r < Pstream::nProcs(); ++r)
    {
        if (r == me) continue;
        label lo[3], hi[3];
        bool cellsOverlap = true;
        for (label d = 0; d < 3; ++d)
        {
            label a0, a1, b0, b1;
            grown(me, d, a0, a1);
            grown(r, d, b0, b1);
            lo[d] = max(a0, b0);
            hi[d] = min(a1, b1);
            if (lo[d] >= hi[d]) cellsOverlap = false;
        }
        DynamicList<label> cells;
        if (cellsOverlap)
        {
            for (label k = lo[2]; k < hi[2]; ++k)
            for (label j = lo[1]; j < hi[1]; ++j)
            for (label i = lo[0]; i < hi[0]; ++i)
            {
                cells.append(cellE(toE(0, i), toE(1, j), toE(2, k)));
            }
        }
        // Faces of direction d: positions lo..hi along d (inclusive), the
        // cells' range across
        DynamicList<label> faces[3];
        for (label d = 0; d < 3; ++d)
        {
            if (!lat_.active(d)) continue;
            label flo[3], fhi[3];
            bool ok = true;
            for (label e = 0; e < 3; ++e)
            {
                label a0, a1, b0, b1;
                grown(me, e, a0, a1);
                grown(r, e, b0, b1);
                flo[e] = max(a0, b0);
                fhi[e] = min(a1, b1) + (e == d ? 1 : 0);
                if (flo[e] >= fhi[e]) ok = false;
            }
            if (!ok) continue;
            for (label k = flo[2]; k < fhi[2]; ++k)
            for (label j = flo[1]; j < fhi[1]; ++j)
            for (label i = flo[0]; i < fhi[0]; ++i)
            {
                faces[d].append(faceE(d, toE(0, i), toE(1, j), toE(2, k)));
            }
        }
        if (cells.size() || faces[0].size() || faces[1].size() || faces[2].size())
        {
            nbrs.append(r);
            cellLists.append(labelList(cells));
            for (label d = 0; d < 3; ++d) faceLists[d].append(labelList(faces[d]));
        }
    }
    nbrProcs_.transfer(nbrs);
    nbrCells_.transfer(cellLists);
    buildCopies(nbrCells_, nCellsE(), cellCopies_);
    for (label d = 0; d < 3; ++d)
    {
        nbrFaces_[d].transfer(faceLists[d]);
        buildCopies(nbrFaces_[d], max(nFacesE_[d], label(1)), faceCopies_[d]);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::latticeRing::cellOf(label idx) const
{
    label i, j, k;
    lat_.ijk(idx, i, j, k);
    return cellE(i + sh_[0], j + sh_[1], k + sh_[2]);
}


void Foam::latticeRing::combine
(
    const std::vector<std::vector<double>*>& cellArrays,
    const std::vector<bool>& isMin,
    std::vector<double>* const faceArrays[3]
) const
{
    if (!Pstream::parRun()) return;
    const label nA = label(cellArrays.size());
    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    forAll(nbrProcs_, q)
    {
        const labelList& cl = nbrCells_[q];
        label n = nA*cl.size();
        for (label d = 0; d < 3; ++d)
        {
            if (faceArrays[d]) n += nbrFaces_[d][q].size();
        }
        List<scalar> send(n);
        label k = 0;
        for (label a = 0; a < nA; ++a)
        {
            const std::vector<double>& v = *cellArrays[a];
            for (const label e : cl) send[k++] = v[e];
        }
        for (label d = 0; d < 3; ++d)
        {
            if (!faceArrays[d]) continue;
            const std::vector<double>& v = *faceArrays[d];
            for (const label f : nbrFaces_[d][q]) send[k++] = v[f];
        }
        UOPstream os(nbrProcs_[q], pBufs);
        os << send;
    }
    pBufs.finishedSends();
    List<List<scalar>> recv(nbrProcs_.size());
    forAll(nbrProcs_, q)
    {
        UIPstream is(nbrProcs_[q], pBufs);
        is >> recv[q];
    }

    // Cells: array a of neighbour q at a*|cells_q| + pos
    const copies& cc = cellCopies_;
    for (label a = 0; a < nA; ++a)
    {
        std::vector<double>& v = *cellArrays[a];
        forAll(cc.entity, s)
        {
            const label e = cc.entity[s];
            double r = 0;
            for (label k = cc.start[s]; k < cc.start[s + 1]; ++k)
            {
                const label q = cc.nbr[k];
                const double x = q < 0
                    ? v[e] : recv[q][a*nbrCells_[q].size() + cc.pos[k]];
                if (k == cc.start[s]) r = x;
                else r = isMin[a] ? (x < r ? x : r) : r + x;
            }
            v[e] = r;
        }
    }
    // Faces of d after the cells and the faces of the lower directions
    for (label d = 0; d < 3; ++d)
    {
        if (!faceArrays[d]) continue;
        std::vector<double>& v = *faceArrays[d];
        const copies& fc = faceCopies_[d];
        forAll(fc.entity, s)
        {
            const label f = fc.entity[s];
            double r = 0;
            for (label k = fc.start[s]; k < fc.start[s + 1]; ++k)
            {
                const label q = fc.nbr[k];
                double x;
                if (q < 0)
                {
                    x = v[f];
                }
                else
                {
                    label o = nA*nbrCells_[q].size();
                    for (label e = 0; e < d; ++e)
                    {
                        if (faceArrays[e]) o += nbrFaces_[e][q].size();
                    }
                    x = recv[q][o + fc.pos[k]];
                }
                r = (k == fc.start[s]) ? x : r + x;
            }
            v[f] = r;
        }
    }
}


// ************************************************************************* //
