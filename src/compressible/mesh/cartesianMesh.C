/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "cartesianMesh.H"
#include "boundBox.H"
#include "processorPolyPatch.H"
#include "PstreamBuffers.H"
#include "UIPstream.H"
#include "UOPstream.H"
#include <algorithm>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

[[noreturn]] void notCartesian
(
    const Foam::fvMesh& mesh,
    Foam::label celli,
    const Foam::string& why
)
{
    using namespace Foam;
    // The file: the mesh's points (constant/polyMesh/points), made by
    // system/blockMeshDict
    const fileName pointsFile
    (
        mesh.time().path()/mesh.pointsInstance()/polyMesh::meshSubDir
       /"points"
    );
    FatalIOError
    (
        FUNCTION_NAME, __FILE__, __LINE__, pointsFile, -1
    )   << "The mesh of " << mesh.time().path()
        << " is not a uniform Cartesian (blockMesh-like) mesh: "
        << pointsFile << nl
        << "    first offending cell: " << celli
        << " at " << mesh.cellCentres()[celli] << nl
        << "    " << why.c_str() << nl
        << "    The WENO gas solver (and the solids coupled to it) needs"
        << " axis-aligned hexahedra of one size on a regular lattice." << nl
        << "    allowed: blockMesh blocks with equal spacing (entries"
        << " 'blocks' of system/blockMeshDict: simpleGrading (1 1 1), the"
        << " same cell size in every block)"
        << exit(FatalIOError);
    std::abort();
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::cartesianMesh::build()
{
    const pointField& pts = mesh_.points();
    const labelListList& cellPts = mesh_.cellPoints();
    const cellList& cells = mesh_.cells();
    const label nC = mesh_.nCells();

    if (nC == 0)
    {
        FatalErrorInFunction
            << "The mesh of " << mesh_.time().path() << " has no cells"
            << exit(FatalError);
    }

    // Reference size from the first cell
    const boundBox bb0(pts, cellPts[0], false);
    for (label d = 0; d < 3; ++d)
    {
        dx_[d] = bb0.span()[d];
    }
    if (Pstream::parRun())
    {
        // Every rank computes with the master's cell size, so that the
        // arithmetic is the serial run's (whose first cell is the master's)
        vector dxv(dx_[0], dx_[1], dx_[2]);
        Pstream::scatter(dxv);
        for (label d = 0; d < 3; ++d) dx_[d] = dxv[d];
    }
    const scalar h = min(min(dx_[0], dx_[1]), dx_[2]);
    const scalar tol = 1e-6*h;

    // Every cell: 8 points, 6 faces, points at the corners of its box,
    // box the size of the first
    boundBox all;
    for (label c = 0; c < nC; ++c)
    {
        if (cellPts[c].size() != 8 || cells[c].size() != 6)
        {
            notCartesian
            (
                mesh_, c,
                "it has " + Foam::name(cellPts[c].size()) + " points and "
              + Foam::name(cells[c].size()) + " faces (a hexahedron has 8"
                " and 6)"
            );
        }
        const boundBox bb(pts, cellPts[c], false);
        for (label d = 0; d < 3; ++d)
        {
            if (mag(bb.span()[d] - dx_[d]) > tol)
            {
                notCartesian
                (
                    mesh_, c,
                    "its size along " + string(1, "xyz"[d])
                  + " is " + Foam::name(bb.span()[d])
                  + ", the first cell's is " + Foam::name(dx_[d])
                );
            }
        }
        for (const label pi : cellPts[c])
        {
            for (label d = 0; d < 3; ++d)
            {
                const scalar x = pts[pi][d];
                if (mag(x - bb.min()[d]) > tol && mag(x - bb.max()[d]) > tol)
                {
                    notCartesian
                    (
                        mesh_, c,
                        "its point " + Foam::name(pi)
                      + " is not on a corner of an axis-aligned box"
                    );
                }
            }
        }
        all.add(bb);
    }

    origin_ = all.min();
    const Vector<label> solD = mesh_.solutionD();
    nDims_ = 0;
    for (label d = 0; d < 3; ++d)
    {
        n_[d] = label(std::round(all.span()[d]/dx_[d]));
        active_[d] = (solD[d] == 1);
        if (active_[d]) ++nDims_;
    }
    stride_[0] = 1;
    stride_[1] = n_[0];
    stride_[2] = n_[0]*n_[1];

    cellAt_.assign(n_[0]*n_[1]*n_[2], -1);
    latticeOf_.assign(nC, -1);

    const vectorField& C = mesh_.cellCentres();
    for (label c = 0; c < nC; ++c)
    {
        label ijk[3];
        for (label d = 0; d < 3; ++d)
        {
            const scalar s = (C[c][d] - origin_[d])/dx_[d] - 0.5;
            ijk[d] = label(std::round(s));
            if (mag(s - ijk[d]) > 1e-6 || ijk[d] < 0 || ijk[d] >= n_[d])
            {
                notCartesian(mesh_, c, "it is not on the common lattice");
            }
        }
        const label idx = ijk[0] + n_[0]*(ijk[1] + n_[1]*ijk[2]);
        if (cellAt_[idx] != -1)
        {
            notCartesian(mesh_, c, "another cell occupies its place");
        }
        cellAt_[idx] = c;
        latticeOf_[c] = idx;
    }

    // The face of cell c whose outward normal is +-e_d
    const vectorField& Cf = mesh_.faceCentres();
    auto endFace = [&](label c, label d, scalar sign) -> label
    {
        for (const label f : cells[c])
        {
            vector dc = Cf[f] - C[c];
            if (mag(dc[d] - sign*0.5*dx_[d]) < tol)
            {
                dc[d] = 0;
                if (mag(dc) < tol) return f;
            }
        }
        notCartesian(mesh_, c, "no face found on its side");
    };

    // Segments: maximal runs of cells along each active direction
    const label nInternal = mesh_.nInternalFaces();
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    for (label d = 0; d < 3; ++d)
    {
        nFaces_[d] = 0;
        if (!active_[d]) continue;
        lowFaceOf_[d].assign(cellAt_.size(), -1);

        const label e1 = (d + 1) % 3, e2 = (d + 2) % 3;
        for (label b = 0; b < n_[e2]; ++b)
        {
            for (label a = 0; a < n_[e1]; ++a)
            {
                const label base = a*stride_[e1] + b*stride_[e2];
                label m = 0;
                while (m < n_[d])
                {
                    if (cellAt_[base + m*stride_[d]] < 0) { ++m; continue; }
                    segment s;
                    s.start = base + m*stride_[d];
                    label L = 0;
                    while
                    (
                        m + L < n_[d]
                     && cellAt_[base + (m + L)*stride_[d]] >= 0
                    )
                    {
                        lowFaceOf_[d][base + (m + L)*stride_[d]] =
                            nFaces_[d] + L;
                        ++L;
                    }
                    s.length = L;
                    s.faceOffset = nFaces_[d];
                    nFaces_[d] += L + 1;

                    const label c0 = cellAt_[s.start];
                    const label c1 = cellAt_[s.start + (L - 1)*stride_[d]];
                    s.lowFace = endFace(c0, d, -1);
                    s.highFace = endFace(c1, d, 1);
                    if (s.lowFace < nInternal || s.highFace < nInternal)
                    {
                        notCartesian
                        (
                            mesh_, s.lowFace < nInternal ? c0 : c1,
                            "an internal face of it leads off the lattice"
                        );
                    }
                    s.lowPatch = patches.whichPatch(s.lowFace);
                    s.highPatch = patches.whichPatch(s.highFace);
                    segments_[d].push_back(s);
                    m += L;
                }
            }
        }
    }
}


void Foam::cartesianMesh::buildProcessorEnds()
{
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    const label nInternal = mesh_.nInternalFaces();
    std::vector<procEnd> endAt
    (
        mesh_.nFaces() - nInternal, procEnd{-1, -1, false}
    );
    for (label d = 0; d < 3; ++d)
    {
        for (size_t si = 0; si < segments_[d].size(); ++si)
        {
            const segment& s = segments_[d][si];
            endAt[s.lowFace - nInternal] = procEnd{d, label(si), false};
            endAt[s.highFace - nInternal] = procEnd{d, label(si), true};
        }
    }
    forAll(patches, pi)
    {
        if (!isA<processorPolyPatch>(patches[pi])) continue;
        const polyPatch& pp = patches[pi];
        procPatches_.push_back(pi);
        procSlot0_.push_back(nGhostSlots_);
        procEnds_.emplace_back();
        forAll(pp, j)
        {
            const procEnd& e = endAt[pp.start() + j - nInternal];
            if (e.d < 0)
            {
                FatalErrorInFunction
                    << "Processor face " << pp.start() + j << " of patch "
                    << pp.name() << " is not the end of a lattice line"
                    << exit(FatalError);
            }
            procEnds_.back().push_back(e);
            segment& s = segments_[e.d][e.seg];
            (e.high ? s.highGhost : s.lowGhost) = nGhostSlots_ + j;
        }
        nGhostSlots_ += pp.size();
    }
}


void Foam::cartesianMesh::exchangeGhosts
(
    const std::vector<double> (&q)[5],
    label depth,
    std::vector<double>& ghost
) const
{
    if (!Pstream::parRun()) return;
    ghost.resize(nGhostSlots_*depth*5);
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();

    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    for (size_t p = 0; p < procPatches_.size(); ++p)
    {
        const auto& pp =
            refCast<const processorPolyPatch>(patches[procPatches_[p]]);
        const auto& ends = procEnds_[p];
        List<scalar> send(label(ends.size())*depth*5);
        label n = 0;
        for (const procEnd& e : ends)
        {
            const segment& s = segments_[e.d][e.seg];
            const label st = stride_[e.d];
            for (label k = 0; k < depth; ++k)
            {
                const label m = e.high ? s.length - 1 - k : k;
                const label idx = s.start + m*st;
                for (int c = 0; c < 5; ++c) send[n++] = q[c][idx];
            }
        }
        UOPstream toNbr(pp.neighbProcNo(), pBufs);
        toNbr << send;
    }
    pBufs.finishedSends();
    for (size_t p = 0; p < procPatches_.size(); ++p)
    {
        const auto& pp =
            refCast<const processorPolyPatch>(patches[procPatches_[p]]);
        UIPstream fromNbr(pp.neighbProcNo(), pBufs);
        List<scalar> recv(fromNbr);
        const label off = procSlot0_[p]*depth*5;
        forAll(recv, n) ghost[off + n] = recv[n];
    }
}


Foam::label Foam::cartesianMesh::slotCell(label j) const
{
    label p = label(procSlot0_.size()) - 1;
    while (procSlot0_[p] > j) --p;
    const procEnd& e = procEnds_[p][j - procSlot0_[p]];
    const segment& s = segments_[e.d][e.seg];
    return s.start + (e.high ? s.length - 1 : 0)*stride_[e.d];
}


void Foam::cartesianMesh::exchangeSlots
(
    const std::vector<double>& mine,
    std::vector<double>& theirs
) const
{
    theirs.resize(nGhostSlots_);
    if (!Pstream::parRun()) return;
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    for (size_t p = 0; p < procPatches_.size(); ++p)
    {
        const auto& pp =
            refCast<const processorPolyPatch>(patches[procPatches_[p]]);
        List<scalar> send(pp.size());
        forAll(send, j) send[j] = mine[procSlot0_[p] + j];
        UOPstream toNbr(pp.neighbProcNo(), pBufs);
        toNbr << send;
    }
    pBufs.finishedSends();
    for (size_t p = 0; p < procPatches_.size(); ++p)
    {
        const auto& pp =
            refCast<const processorPolyPatch>(patches[procPatches_[p]]);
        UIPstream fromNbr(pp.neighbProcNo(), pBufs);
        List<scalar> recv(fromNbr);
        forAll(recv, j) theirs[procSlot0_[p] + j] = recv[j];
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::cartesianMesh::cartesianMesh(const fvMesh& mesh)
:
    mesh_(mesh)
{
    build();
    buildProcessorEnds();

    label nSeg = 0;
    for (label d = 0; d < 3; ++d) nSeg += segments_[d].size();
    Info<< "Cartesian view: " << nDims_ << "D, lattice "
        << n_[0] << " x " << n_[1] << " x " << n_[2]
        << ", " << nCells() << " cells of " << dx_[0] << " x " << dx_[1]
        << " x " << dx_[2] << ", " << nSeg << " line segments" << nl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::cartesianMesh::segment& Foam::cartesianMesh::segmentOfFace
(
    label d,
    label f
) const
{
    const auto& segs = segments_[d];
    auto it = std::upper_bound
    (
        segs.begin(), segs.end(), f,
        [](label face, const segment& s) { return face < s.faceOffset; }
    );
    return *(it - 1);
}


// ************************************************************************* //
