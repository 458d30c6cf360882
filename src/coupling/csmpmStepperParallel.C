/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "csmpmStepper.H"
#include "mpmCloudIO.H"
#include "fvMesh.H"
#include "cloud.H"
#include "globalIndex.H"
#include "PstreamReduceOps.H"
#include <unordered_map>
#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::csmpmStepper::checkParallelCloud(bool found, bool idsRead)
{
    const Time& runTime = fvMesh_.time();
    if (!returnReduce(found, orOp<bool>()))
    {
        FatalErrorInFunction
            << "No particles: no processor directory holds an MPM cloud at "
            << runTime.timeName() << " (e.g. "
            << runTime.timePath()/cloud::prefix/cloudName_ << "), but"
            << " constant/mpmProperties exists. Seed one with"
            << " mpmSetParticles before decomposePar, or remove"
            << " constant/mpmProperties for a gas-only run"
            << exit(FatalError);
    }
    // A processor directory without its cloud: fewer particles than the
    // undecomposed cloud of the same time (decomposePar's input)
    const label nRanks = returnReduce(P_.size(), sumOp<label>());
    label nRoot = -1;
    if (Pstream::master())
    {
        nRoot = mpmCloudIO::countParticles
        (
            runTime.globalPath()/runTime.timeName()/cloud::prefix/cloudName_
        );
    }
    Pstream::scatter(nRoot);
    if (nRoot >= 0 && nRoot != nRanks)
    {
        FatalErrorInFunction
            << "The processor directories' clouds at " << runTime.timeName()
            << " hold " << nRanks << " particles; the undecomposed cloud "
            << runTime.globalPath()/runTime.timeName()/cloud::prefix
              /cloudName_ << " holds " << nRoot << ". A processor"
            << " directory lacks its cloud (or holds another"
            << " decomposition's): run decomposePar -force again"
            << exit(FatalError);
    }
    // Without the undecomposed cloud (a time written in parallel: every
    // rank writes its cloud, empty or not) every rank must hold one
    if (nRoot < 0 && !returnReduce(found, andOp<bool>()))
    {
        if (!found)
        {
            Pout<< "No MPM cloud in "
                << runTime.timePath()/cloud::prefix/cloudName_ << endl;
        }
        FatalErrorInFunction
            << "A processor directory lacks its MPM cloud at "
            << runTime.timeName() << " (the ranks without it are listed"
            << " above), and the case has no undecomposed cloud there to"
            << " tell an empty subdomain: the parallel run writes every"
            << " rank's cloud. Restart from another time, or decompose"
            << " again" << exit(FatalError);
    }
    if (nRanks == 0)
    {
        FatalErrorInFunction
            << "No particles: the MPM cloud at " << runTime.timeName()
            << " holds no particle. Seed some with mpmSetParticles"
            << exit(FatalError);
    }
    // A cloud without ids: number the particles across the ranks (the
    // deposit orders by id)
    if (!returnReduce(idsRead, andOp<bool>()))
    {
        const globalIndex gi(P_.size());
        forAll(P_.id, p) P_.id[p] = gi.toGlobal(p);
    }
}


// (3.20): J^g_{n+1} = J^g_n V_{n+1}/V_n with the volumes of G2P
void Foam::csmpmStepper::updateJg()
{
    if (!par_.valid())
    {
        forAll(P_.x, p) Jg_[p] *= P_.V[p]/Vold_[p];
        return;
    }

    // The particles before G2P by id; those still here update in place,
    // those that left send (id, J^g, V_old) to all ranks
    std::unordered_map<label, label> at;
    at.reserve(2*idOld_.size());
    forAll(idOld_, q) at[idOld_[q]] = q;
    const label nP = P_.size();
    List<scalar> JgNew(nP, scalar(-1));
    List<bool> stayed(idOld_.size(), false);
    DynamicList<label> missing;
    forAll(P_.x, p)
    {
        const auto it = at.find(P_.id[p]);
        if (it == at.end())
        {
            missing.append(p);
            continue;
        }
        const label q = it->second;
        JgNew[p] = Jg_[q]*(P_.V[p]/Vold_[q]);
        stayed[q] = true;
    }
    DynamicList<scalar> left;
    forAll(stayed, q)
    {
        if (stayed[q]) continue;
        left.append(scalar(idOld_[q]));
        left.append(Jg_[q]);
        left.append(Vold_[q]);
    }
    if (returnReduce(left.size(), sumOp<label>()) > 0)
    {
        List<List<scalar>> all(Pstream::nProcs());
        all[Pstream::myProcNo()] = left;
        Pstream::gatherList(all);
        Pstream::scatterList(all);
        std::unordered_map<label, std::pair<scalar, scalar>> moved;
        for (const List<scalar>& l : all)
        {
            for (label k = 0; k + 2 < l.size(); k += 3)
            {
                moved[label(std::llround(l[k]))] = {l[k + 1], l[k + 2]};
            }
        }
        for (const label p : missing)
        {
            const auto it = moved.find(P_.id[p]);
            if (it == moved.end())
            {
                FatalErrorInFunction
                    << "Particle id " << P_.id[p] << " arrived on processor "
                    << Pstream::myProcNo() << " without its J^g"
                    << exit(FatalError);
            }
            JgNew[p] = it->second.first*(P_.V[p]/it->second.second);
        }
    }
    else if (missing.size())
    {
        FatalErrorInFunction
            << missing.size() << " particles arrived on processor "
            << Pstream::myProcNo() << " without their J^g" << exit(FatalError);
    }

    Jg_.setSize(nP);
    forAll(JgNew, p) Jg_[p] = JgNew[p];
    lambdaG_.setSize(nP);
    forAll(P_.x, p)
    {
        lambdaG_[p] = lambdaGiven_
            ? lambdaValue_ : solver_.materials()[P_.material[p]].lambda();
    }
    pg_.setSize(nP);
    Kg_.setSize(nP);
    Vold_.setSize(nP);
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

    // mergeCoveredCells
    const double theta = 0.5;
    for (const auto& ou : order)
    {
        const label i = ou.second;
        const double o = open(i);
        if (!(o < theta)) continue;
        label best = -1;
        double oBest = o;
        for (label d = 0; d < 3; ++d)
        {
            if (!mesh_.active(d)) continue;
            for (label h = 0; h < 2; ++h)
            {
                const label j = nbr(i, d, h);
                if (j < 0) continue;
                const double oj = open(j);
                if (oj > oBest)
                {
                    oBest = oj;
                    best = j;
                }
            }
        }
        if (best < 0) continue;
        const double r = o/oBest;
        for (int c = 0; c < 5; ++c)
        {
            const double keep = r*U.q[c][best];
            U.q[c][best] += U.q[c][i] - keep;
            U.q[c][i] = keep;
        }
    }

    // repairNearSolid
    label nRepaired = 0;
    for (const auto& ou : order)
    {
        const label c = ou.second;
        label around[7] = {c, -1, -1, -1, -1, -1, -1};
        label nA = 1;
        for (label d = 0; d < 3; ++d)
        {
            if (!mesh_.active(d)) continue;
            for (label h = 0; h < 2; ++h)
            {
                const label j = nbr(c, d, h);
                if (j >= 0) around[nA++] = j;
            }
        }
        for (label a = 0; a < nA; ++a)
        {
            const label i = around[a];
            if (U.admissible(i, gamma_)) continue;
            label best = -1;
            double mBest = 0;
            for (label d = 0; d < 3; ++d)
            {
                if (!mesh_.active(d)) continue;
                for (label h = 0; h < 2; ++h)
                {
                    const label j = nbr(i, d, h);
                    if (j < 0) continue;
                    if (U.q[0][j] > mBest && U.admissible(j, gamma_))
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

    // The rank's own cells back
    forAll(sent, k)
    {
        for (int q = 0; q < 5; ++q) out.q[q][sent[k]] = U.q[q][mineStart + k];
    }
    return nRepaired;
}


// ************************************************************************* //
