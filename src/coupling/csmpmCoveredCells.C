/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "csmpmStepper.H"
#include "PstreamReduceOps.H"
#include <unordered_map>
#include <unordered_set>
#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

// For a covered cell i no face neighbour of which is more open (inside a
// solid: the root of a post clamped to a wall, where the covered cells
// reach the wall), the open cell (open fraction at least theta) that takes
// what its gas does not hold: of those within two face steps beyond the
// nearest (paths through covered cells), the one holding the most gas, so
// that the ghost pressure's work on the trapped gas is not all put into a
// near-vacuum behind the solid; ties to the first found in the scan order
// of nbr, so that a serial run and the union of a parallel one agree; -1 if
// none within maxDepth steps.  Without it the trapped gas keeps that work
// until the steps drain it to a vacuum (cylindersMach3 at 296 per unit
// length)
template<class Nbr, class Open>
Foam::label nearestOpen
(
    const Foam::label i,
    const Foam::cartesianMesh& mesh,
    const Nbr& nbr,
    const Open& open,
    const double theta,
    const Foam::gasState& U
)
{
    using namespace Foam;
    const label maxDepth = 64, beyond = 2;
    std::vector<label> front{i}, next;
    std::unordered_set<label> seen{i};
    label best = -1, lastDepth = maxDepth;
    for (label depth = 1; depth <= lastDepth && !front.empty(); ++depth)
    {
        next.clear();
        for (const label u : front)
        {
            for (label d = 0; d < 3; ++d)
            {
                if (!mesh.active(d)) continue;
                for (label h = 0; h < 2; ++h)
                {
                    const label j = nbr(u, d, h);
                    if (j < 0 || !seen.insert(j).second) continue;
                    if (open(j) < theta)
                    {
                        next.push_back(j);
                    }
                    else if (best < 0 || U.q[0][j] > U.q[0][best])
                    {
                        if (best < 0) lastDepth = min(depth + beyond, maxDepth);
                        best = j;
                    }
                }
            }
        }
        front.swap(next);
    }
    return best;
}


// The rules of mergeCoveredCells and repairNearSolid on the cells of U,
// visited in the order of 'cells'; nbr(u, d, h) is u's face neighbour along
// direction d (h: 0 low, 1 high), -1 where there is none; open(u) its open
// fraction.  Shared by the serial run (the lattice's cells) and the
// parallel one (the cells near the solid gathered from all ranks)
template<class Nbr, class Open>
void mergeCovered
(
    const std::vector<Foam::label>& cells,
    const Foam::cartesianMesh& mesh,
    const Nbr& nbr,
    const Open& open,
    Foam::gasState& U
)
{
    using namespace Foam;
    const double theta = 0.5;
    for (const label i : cells)
    {
        const double o = open(i);
        if (!(o < theta)) continue;
        label best = -1;
        double oBest = o;
        for (label d = 0; d < 3; ++d)
        {
            if (!mesh.active(d)) continue;
            for (label h = 0; h < 2; ++h)
            {
                const label j = nbr(i, d, h);
                if (j < 0) continue;
                const double oj = open(j);
                // Ties (to round-off: symmetric bodies, and the sums of
                // a parallel run) go to the first neighbour in scan order
                if (oj > oBest*(1 + 1e-10))
                {
                    oBest = oj;
                    best = j;
                }
            }
        }
        if (best < 0)
        {
            best = nearestOpen(i, mesh, nbr, open, theta, U);
            if (best < 0) continue;
            oBest = open(best);
        }
        const double r = o/oBest;
        for (int c = 0; c < 5; ++c)
        {
            const double keep = r*U.q[c][best];
            U.q[c][best] += U.q[c][i] - keep;
            U.q[c][i] = keep;
        }
    }
}


template<class Nbr, class Open>
Foam::label repairNear
(
    const std::vector<Foam::label>& cells,
    const Foam::cartesianMesh& mesh,
    const Nbr& nbr,
    const Open& open,
    const double gamma,
    Foam::gasState& U
)
{
    using namespace Foam;
    label nRepaired = 0;
    for (const label c : cells)
    {
        // the solid cell and its face neighbours
        label around[7] = {c, -1, -1, -1, -1, -1, -1};
        label nA = 1;
        for (label d = 0; d < 3; ++d)
        {
            if (!mesh.active(d)) continue;
            for (label h = 0; h < 2; ++h)
            {
                const label j = nbr(c, d, h);
                if (j >= 0) around[nA++] = j;
            }
        }
        for (label a = 0; a < nA; ++a)
        {
            const label i = around[a];
            if (U.admissible(i, gamma)) continue;
            label best = -1;
            double mBest = 0;
            for (label d = 0; d < 3; ++d)
            {
                if (!mesh.active(d)) continue;
                for (label h = 0; h < 2; ++h)
                {
                    const label j = nbr(i, d, h);
                    if (j < 0) continue;
                    if
                    (
                        U.q[0][j] > mBest*(1 + 1e-10)
                     && U.admissible(j, gamma)
                    )
                    {
                        mBest = U.q[0][j];
                        best = j;
                    }
                }
            }
            if (best < 0) continue;
            const double oi = open(i);
            const double ob = open(best);
            for (label k = 0; k < 5; ++k)
            {
                const double sum = U.q[k][i] + U.q[k][best];
                U.q[k][i] = sum*oi/(oi + ob);
                U.q[k][best] = sum*ob/(oi + ob);
            }
            ++nRepaired;
        }
    }
    return nRepaired;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

// A cell the solid mostly covers (open fraction o < 1/2) keeps only the gas
// its open volume holds at the state of its most open neighbour (o_n > o):
// content o/o_n times the neighbour's; the rest of its mass, momentum and
// energy (or the deficit) goes to that neighbour; a covered cell no
// neighbour of which is more open (inside a solid) does the same with an
// open cell outside the solid, the fullest near it (nearestOpen).
// Conservative, and
// positive (the neighbour keeps (1 - o/o_n) of its content plus the cell's),
// so that the few gas a covered cell holds cannot be driven to a negative
// pressure by the pressure work around it
void Foam::csmpmStepper::mergeCoveredCells(gasState& out) const
{
    mergeCovered
    (
        phiCells_, mesh_, latticeNeighbour(),
        [this](label u) { return max(1 - phiCell_[u], gasVolumeMin_); },
        out
    );
}


// A cell next to the solid (it or a face neighbour has a solid fraction)
// whose gas the pressure step left inadmissible (a near-vacuum behind a
// body in a strong flow, a sliver of gas in a mixed cell) is pooled with
// the face neighbour holding the most gas: their summed mass, momentum and
// energy shared by their open volumes.  Conservative; the step fails as
// before if the pooled state is inadmissible too.  Returns the cells
// repaired
Foam::label Foam::csmpmStepper::repairNearSolid(gasState& out) const
{
    return repairNear
    (
        phiCells_, mesh_, latticeNeighbour(),
        [this](label u) { return max(1 - phiCell_[u], gasVolumeMin_); },
        gamma_, out
    );
}


// The face neighbour of lattice cell i along d (h: 0 low, 1 high) on the
// same lattice line; -1 at the line's end
std::function<Foam::label(Foam::label, Foam::label, Foam::label)>
Foam::csmpmStepper::latticeNeighbour() const
{
    return [this](label i, label d, label h) -> label
    {
        const label j = h ? i + mesh_.stride(d) : i - mesh_.stride(d);
        if (j < 0 || j >= mesh_.nLattice() || mesh_.cellAt()[j] < 0)
        {
            return -1;
        }
        const label f = mesh_.lowFaceOf(d)[i];
        const label fj = mesh_.lowFaceOf(d)[j];
        return (fj == f - 1 || fj == f + 1) ? j : -1;
    };
}


// mergeCoveredCells and repairNearSolid of the serial run, across the ranks:
// every rank sends the cells within two face steps of the solid's deposits
// it sees (its own and its ring's) and its cells at processor faces (the
// cells a merge or a repair reads or changes: a covered cell, its
// neighbours, theirs); every rank runs the serial algorithm on the union in
// the serial order (the touched cells by their first particle) and keeps
// its own cells' results
Foam::label Foam::csmpmStepper::mergeAndRepairParallel(gasState& out) const
{
    const latticeRing& ring = lattice_.ring();
    const std::vector<double>& VE = lattice_.VcellE();
    const std::vector<double>& keyE = lattice_.keyE();
    const label nLat = mesh_.nLattice();
    label sh[3], n[3], nE[3];
    for (label d = 0; d < 3; ++d)
    {
        sh[d] = ring.sh(d);
        n[d] = mesh_.n(d);
        nE[d] = ring.nE(d);
    }

    // The rank's cells to send
    std::vector<char> mark(nLat, 0);
    const label r2 = 2;
    for (label k = 0; k < nE[2]; ++k)
    for (label j = 0; j < nE[1]; ++j)
    for (label i = 0; i < nE[0]; ++i)
    {
        if (!(VE[ring.cellE(i, j, k)] > 0)) continue;
        const label lo[3] = {i - r2*sh[0], j - r2*sh[1], k - r2*sh[2]};
        const label hi[3] = {i + r2*sh[0], j + r2*sh[1], k + r2*sh[2]};
        for (label c = max(lo[2], sh[2]); c <= min(hi[2], sh[2] + n[2] - 1); ++c)
        for (label b = max(lo[1], sh[1]); b <= min(hi[1], sh[1] + n[1] - 1); ++b)
        for (label a = max(lo[0], sh[0]); a <= min(hi[0], sh[0] + n[0] - 1); ++a)
        {
            if (mag(a - i) + mag(b - j) + mag(c - k) > r2) continue;
            mark[(a - sh[0]) + n[0]*((b - sh[1]) + n[1]*(c - sh[2]))] = 1;
        }
    }
    for (label d = 0; d < 3; ++d)
    {
        if (!mesh_.active(d)) continue;
        for (label i = 0; i < nLat; ++i)
        {
            if (slotLo_[d][i] >= 0 || slotHi_[d][i] >= 0) mark[i] = 1;
        }
    }
    DynamicList<scalar> mine;
    DynamicList<label> sent;
    for (label i = 0; i < nLat; ++i)
    {
        if (!mark[i]) continue;
        label c[3];
        mesh_.ijk(i, c[0], c[1], c[2]);
        const label e = ring.cellOf(i);
        mine.append(scalar(ring.globalOf(c[0] + sh[0], c[1] + sh[1], c[2] + sh[2])));
        mine.append(lattice_.phi(i));
        mine.append(keyE[e]);
        for (int q = 0; q < 5; ++q) mine.append(out.q[q][i]);
        sent.append(i);
    }
    List<List<scalar>> all(Pstream::nProcs());
    all[Pstream::myProcNo()].transfer(mine);
    Pstream::gatherList(all);
    Pstream::scatterList(all);

    // The union
    label nU = 0;
    for (const List<scalar>& l : all) nU += l.size()/8;
    std::vector<label> gOf(nU);
    std::vector<double> phi(nU), key(nU);
    gasState U;
    U.resize(nU);
    std::unordered_map<label, label> at;
    at.reserve(2*nU);
    label mineStart = 0;
    {
        label u = 0;
        forAll(all, r)
        {
            if (r == Pstream::myProcNo()) mineStart = u;
            const List<scalar>& l = all[r];
            for (label k = 0; k + 7 < l.size(); k += 8, ++u)
            {
                gOf[u] = label(std::llround(l[k]));
                phi[u] = l[k + 1];
                key[u] = l[k + 2];
                for (int q = 0; q < 5; ++q) U.q[q][u] = l[k + 3 + q];
                at[gOf[u]] = u;
            }
        }
    }
    std::vector<std::pair<double, label>> order;
    for (label u = 0; u < nU; ++u)
    {
        if (key[u] < 1e300) order.emplace_back(key[u], u);
    }
    std::sort(order.begin(), order.end());

    const label N[3] = {ring.N(0), ring.N(1), ring.N(2)};
    const label gStride[3] = {1, N[0], N[0]*N[1]};
    // The face neighbour of u along d (h: 0 low, 1 high); -1 at the
    // lattice's end; FatalError if the union lacks it
    auto nbr = [&](label u, label d, label h) -> label
    {
        const label g = gOf[u];
        const label c = (g/gStride[d]) % N[d];
        if ((h == 0 && c == 0) || (h == 1 && c == N[d] - 1)) return -1;
        const auto it = at.find(g + (h ? 1 : -1)*gStride[d]);
        if (it == at.end())
        {
            FatalErrorInFunction
                << "The cell " << g + (h ? 1 : -1)*gStride[d] << " next to"
                << " the solid is missing from the gathered cells"
                << exit(FatalError);
        }
        return it->second;
    };
    auto open = [&](label u) { return max(1 - phi[u], gasVolumeMin_); };

    std::vector<label> cells(order.size());
    for (size_t k = 0; k < order.size(); ++k) cells[k] = order[k].second;
    mergeCovered(cells, mesh_, nbr, open, U);
    const label nRepaired = repairNear(cells, mesh_, nbr, open, gamma_, U);

    // The rank's own cells back
    forAll(sent, k)
    {
        for (int q = 0; q < 5; ++q) out.q[q][sent[k]] = U.q[q][mineStart + k];
    }
    return nRepaired;
}


// A gas cell anywhere that the coupled step left inadmissible (after the
// merges and the repairs near the solid): repaired by the same rule,
// pooled with its face neighbour holding the most gas (conservative), the
// cells in lattice order.  The gas that the blast ahead of a bullet drives
// out of a muzzle expands round the muzzle's edge: the cell at the wall
// behind the edge, emptied by the flow turning away from it, reached a
// negative pressure in the pressure step at any time step (csmpm/bullet2D,
// the light bullet at 80 per unit length, t = 0.478, before its nose left
// the bore).  Returns the cells repaired (0, and the state untouched,
// where every cell is admissible)
Foam::label Foam::csmpmStepper::repairAnywhere(gasState& out) const
{
    if (par_.valid()) return repairAnywhereParallel(out);
    std::vector<label> bad;
    for (const label i : cells_)
    {
        if (!out.admissible(i, gamma_)) bad.push_back(i);
    }
    if (bad.empty()) return 0;
    std::sort(bad.begin(), bad.end());
    return repairNear
    (
        bad, mesh_, latticeNeighbour(),
        [this](label u) { return max(1 - lattice_.phi(u), gasVolumeMin_); },
        gamma_, out
    );
}


// The same across the ranks: the global indices of the inadmissible cells
// to every rank, each rank's cells within two face steps of one (those a
// repair reads or changes) gathered from all ranks, the serial rule run on
// the union in global (the serial lattice's) order on every rank, each
// rank keeping its own cells' results
Foam::label Foam::csmpmStepper::repairAnywhereParallel(gasState& out) const
{
    const latticeRing& ring = lattice_.ring();
    const label nLat = mesh_.nLattice();
    label sh[3], n[3], off[3];
    for (label d = 0; d < 3; ++d)
    {
        sh[d] = ring.sh(d);
        n[d] = mesh_.n(d);
        off[d] = ring.off(d);
    }
    auto globalOfCell = [&](label i)
    {
        label c[3];
        mesh_.ijk(i, c[0], c[1], c[2]);
        return ring.globalOf(c[0] + sh[0], c[1] + sh[1], c[2] + sh[2]);
    };

    List<labelList> badAll(Pstream::nProcs());
    {
        DynamicList<label> b;
        for (const label i : cells_)
        {
            if (!out.admissible(i, gamma_)) b.append(globalOfCell(i));
        }
        badAll[Pstream::myProcNo()].transfer(b);
    }
    Pstream::gatherList(badAll);
    Pstream::scatterList(badAll);
    std::vector<label> badG;
    for (const labelList& l : badAll)
    {
        for (const label g : l) badG.push_back(g);
    }
    if (badG.empty()) return 0;
    std::sort(badG.begin(), badG.end());

    const label N[3] = {ring.N(0), ring.N(1), ring.N(2)};
    const label gStride[3] = {1, N[0], N[0]*N[1]};

    // The rank's cells within two face steps of a bad cell
    const label r2 = 2;
    std::vector<char> mark(nLat, 0);
    for (const label g : badG)
    {
        label c[3];
        for (label d = 0; d < 3; ++d) c[d] = (g/gStride[d]) % N[d];
        // in the rank's lattice coordinates (global = own + off)
        label lo[3], hi[3];
        for (label d = 0; d < 3; ++d)
        {
            const label a = c[d] - off[d];
            lo[d] = max(a - (mesh_.active(d) ? r2 : 0), label(0));
            hi[d] = min(a + (mesh_.active(d) ? r2 : 0), n[d] - 1);
        }
        for (label k = lo[2]; k <= hi[2]; ++k)
        for (label j = lo[1]; j <= hi[1]; ++j)
        for (label i = lo[0]; i <= hi[0]; ++i)
        {
            const label a0 = c[0] - off[0], a1 = c[1] - off[1],
                a2 = c[2] - off[2];
            if (mag(i - a0) + mag(j - a1) + mag(k - a2) > r2) continue;
            const label idx = i + n[0]*(j + n[1]*k);
            if (mesh_.cellAt()[idx] >= 0) mark[idx] = 1;
        }
    }
    DynamicList<scalar> mine;
    DynamicList<label> sent;
    for (label i = 0; i < nLat; ++i)
    {
        if (!mark[i]) continue;
        mine.append(scalar(globalOfCell(i)));
        mine.append(lattice_.phi(i));
        for (int q = 0; q < 5; ++q) mine.append(out.q[q][i]);
        sent.append(i);
    }
    List<List<scalar>> all(Pstream::nProcs());
    all[Pstream::myProcNo()].transfer(mine);
    Pstream::gatherList(all);
    Pstream::scatterList(all);

    label nU = 0;
    for (const List<scalar>& l : all) nU += l.size()/7;
    std::vector<label> gOf(nU);
    std::vector<double> phi(nU);
    gasState U;
    U.resize(nU);
    std::unordered_map<label, label> at;
    at.reserve(2*nU);
    label mineStart = 0;
    {
        label u = 0;
        forAll(all, r)
        {
            if (r == Pstream::myProcNo()) mineStart = u;
            const List<scalar>& l = all[r];
            for (label k = 0; k + 6 < l.size(); k += 7, ++u)
            {
                gOf[u] = label(std::llround(l[k]));
                phi[u] = l[k + 1];
                for (int q = 0; q < 5; ++q) U.q[q][u] = l[k + 2 + q];
                at[gOf[u]] = u;
            }
        }
    }
    auto nbr = [&](label u, label d, label h) -> label
    {
        const label g = gOf[u];
        const label c = (g/gStride[d]) % N[d];
        if ((h == 0 && c == 0) || (h == 1 && c == N[d] - 1)) return -1;
        const auto it = at.find(g + (h ? 1 : -1)*gStride[d]);
        // (a lattice position without a cell: no neighbour)
        return it == at.end() ? -1 : it->second;
    };
    auto open = [&](label u) { return max(1 - phi[u], gasVolumeMin_); };
    std::vector<label> cells;
    for (const label g : badG) cells.push_back(at.at(g));
    const label nRepaired = repairNear(cells, mesh_, nbr, open, gamma_, U);

    forAll(sent, k)
    {
        for (int q = 0; q < 5; ++q) out.q[q][sent[k]] = U.q[q][mineStart + k];
    }
    return nRepaired;
}


// ************************************************************************* //
