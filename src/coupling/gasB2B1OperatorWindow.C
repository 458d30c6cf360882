/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
-------------------------------------------------------------------------------
    gasB2B1Operator's window and halo: the part of the lattice a rank's
    rows reach, and the exchange of its other ranks' cells.
\*---------------------------------------------------------------------------*/

#include "gasB2B1Operator.H"
#include "Pstream.H"
#include "PstreamBuffers.H"
#include <algorithm>
#include <utility>

// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

void Foam::gasB2B1Operator::coveringRange
(
    const std::vector<bool>& mark,
    bool periodic,
    label& first,
    label& length
)
{
    const label n = label(mark.size());
    label lo = -1, hi = -1;
    for (label i = 0; i < n; ++i)
    {
        if (!mark[i]) continue;
        if (lo < 0) lo = i;
        hi = i;
    }
    first = 0;
    length = lo < 0 ? 0 : hi - lo + 1;
    if (lo < 0) return;
    first = lo;
    if (!periodic) return;

    // On a circle: the complement of the longest run of unmarked positions
    // (counted from a marked position, so that no run is cut by the seam)
    if (std::find(mark.begin(), mark.end(), false) == mark.end())
    {
        first = 0;
        length = n;
        return;
    }
    label gapEnd = -1, gapLen = 0;
    label run = 0;
    for (label s = 0; s < n; ++s)
    {
        const label i = (lo + s) % n;
        if (!mark[i])
        {
            if (++run > gapLen)
            {
                gapLen = run;
                gapEnd = i;
            }
        }
        else
        {
            run = 0;
        }
    }
    first = (gapEnd + 1) % n;
    length = n - gapLen;
}


// * * * * * * * * * * * * * * Private Functions * * * * * * * * * * * * * * //

void Foam::gasB2B1Operator::buildWindow()
{
    const label nk = label(latOf_.size());
    std::vector<label> coord[3];
    for (label d = 0; d < 3; ++d) coord[d].resize(nk);
    for (label k = 0; k < nk; ++k)
    {
        const label g = latOf_[k];
        coord[0][k] = g % N_[0];
        coord[1][k] = (g/N_[0]) % N_[1];
        coord[2][k] = g/(N_[0]*N_[1]);
    }

    for (label d = 0; d < 3; ++d)
    {
        if (!active_[d])
        {
            // One cell across: the identity
            c0_[d] = v0_[d] = 0;
            nc_[d] = nv_[d] = 1;
            start_[d] = {0, 1};
            cell_[d] = {0};
            D_[d] = {0.0};
            M_[d] = {1.0};
            W_[d] = {1.0};
            continue;
        }
        const label n = N_[d];
        std::vector<label> gStart, gCell;
        std::vector<double> gD, gM, gW;
        table1D(n, periodic_[d], gStart, gCell, gD, gM, gW);
        const label nvAll = label(gStart.size()) - 1;

        // The vertices reaching an own cell's position, the cells that
        // every vertex of their range reaches
        std::vector<bool> own(n, false), needV(nvAll, false), needC(n, false);
        for (label k = 0; k < nk; ++k) own[coord[d][k]] = true;
        for (label v = 0; v < nvAll; ++v)
        {
            for (label e = gStart[v]; e < gStart[v + 1]; ++e)
            {
                if (own[gCell[e]]) needV[v] = true;
            }
        }
        coveringRange(needV, periodic_[d], v0_[d], nv_[d]);
        for (label l = 0; l < nv_[d]; ++l)
        {
            const label v = (v0_[d] + l) % nvAll;
            for (label e = gStart[v]; e < gStart[v + 1]; ++e)
            {
                needC[gCell[e]] = true;
            }
        }
        coveringRange(needC, periodic_[d], c0_[d], nc_[d]);

        // The window's rows: the whole lattice's, in the same order, on
        // window cells
        start_[d].assign(1, 0);
        cell_[d].clear();
        D_[d].clear();
        M_[d].clear();
        W_[d].clear();
        for (label l = 0; l < nv_[d]; ++l)
        {
            const label v = (v0_[d] + l) % nvAll;
            for (label e = gStart[v]; e < gStart[v + 1]; ++e)
            {
                cell_[d].push_back((gCell[e] - c0_[d] + n) % n);
                D_[d].push_back(gD[e]);
                M_[d].push_back(gM[e]);
                W_[d].push_back(gW[e]);
            }
            start_[d].push_back(label(cell_[d].size()));
        }
    }

    win_.resize(nk);
    for (label k = 0; k < nk; ++k)
    {
        label w[3];
        for (label d = 0; d < 3; ++d)
        {
            w[d] = (coord[d][k] - c0_[d] + N_[d]) % N_[d];
        }
        win_[k] = w[0] + nc_[0]*(w[1] + nc_[1]*w[2]);
    }
}


Foam::label Foam::gasB2B1Operator::globalOfWindow(label w) const
{
    const label l[3] =
        {w % nc_[0], (w/nc_[0]) % nc_[1], w/(nc_[0]*nc_[1])};
    label g[3];
    for (label d = 0; d < 3; ++d) g[d] = (c0_[d] + l[d]) % N_[d];
    return g[0] + N_[0]*(g[1] + N_[1]*g[2]);
}


void Foam::gasB2B1Operator::buildHalo()
{
    nHalo_ = 0;
    haloProcs_.clear();
    const label nW = nWindowCells();

    // The cells within reach of an own row: own cells forward to the
    // vertices (any entry counts), those back to the cells
    std::vector<double> ones[3];
    const std::vector<double>* F[3];
    for (label d = 0; d < 3; ++d)
    {
        ones[d].assign(cell_[d].size(), 1.0);
        F[d] = &ones[d];
    }
    std::vector<double> ownW(nW, 0.0), reachV, reachC;
    for (const label w : win_) ownW[w] = 1;
    forward(ownW, reachV, F);
    for (double& r : reachV) r = r > 0 ? 1 : 0;
    backward(reachV, reachC, F);

    labelList haloWin(nW), haloGlobal(nW);
    label nh = 0;
    for (label w = 0; w < nW; ++w)
    {
        if (reachC[w] > 0 && ownW[w] == 0)
        {
            haloWin[nh] = w;
            haloGlobal[nh++] = globalOfWindow(w);
        }
    }
    haloWin.setSize(nh);
    haloGlobal.setSize(nh);
    nHalo_ = nh;

    const label nProcs = Pstream::parRun() ? Pstream::nProcs() : 1;
    const label me = Pstream::myProcNo();
    sendTo_.setSize(nProcs);
    recvInto_.setSize(nProcs);
    if (!Pstream::parRun())
    {
        if (nh)
        {
            FatalErrorInFunction
                << nh << " cells within reach of the B2B1 rows are no"
                << " unknown of this run: the lattice is not full"
                << exit(FatalError);
        }
        return;
    }

    // Ask every other rank for the halo's cells; each answers with those
    // it owns (the positions in the question) and keeps its unknowns
    std::vector<std::pair<label, label>> byGlobal(latOf_.size());
    for (size_t k = 0; k < latOf_.size(); ++k)
    {
        byGlobal[k] = {latOf_[k], label(k)};
    }
    std::sort(byGlobal.begin(), byGlobal.end());

    PstreamBuffers ask(Pstream::commsTypes::nonBlocking);
    for (label p = 0; p < nProcs; ++p)
    {
        if (p == me) continue;
        UOPstream toP(p, ask);
        toP << haloGlobal;
    }
    ask.finishedSends();
    PstreamBuffers answer(Pstream::commsTypes::nonBlocking);
    for (label p = 0; p < nProcs; ++p)
    {
        if (p == me) continue;
        UIPstream fromP(p, ask);
        const labelList wanted(fromP);
        labelList found(wanted.size()), mine(wanted.size());
        label nf = 0;
        forAll(wanted, i)
        {
            const auto it = std::lower_bound
            (
                byGlobal.begin(), byGlobal.end(),
                std::pair<label, label>(wanted[i], -1)
            );
            if (it != byGlobal.end() && it->first == wanted[i])
            {
                found[nf] = i;
                mine[nf++] = it->second;
            }
        }
        found.setSize(nf);
        mine.setSize(nf);
        sendTo_[p] = mine;
        UOPstream toP(p, answer);
        toP << found;
    }
    answer.finishedSends();

    labelList owners(nh, 0);
    for (label p = 0; p < nProcs; ++p)
    {
        if (p == me) continue;
        UIPstream fromP(p, answer);
        const labelList found(fromP);
        labelList& into = recvInto_[p];
        into.setSize(found.size());
        forAll(found, i)
        {
            into[i] = haloWin[found[i]];
            ++owners[found[i]];
        }
        if (found.size() || sendTo_[p].size()) haloProcs_.append(p);
    }
    forAll(owners, i)
    {
        if (owners[i] != 1)
        {
            FatalErrorInFunction
                << "lattice cell " << haloGlobal[i] << " of the B2B1 halo"
                << " has " << owners[i] << " owning ranks (one expected):"
                << " the lattice is not full" << exit(FatalError);
        }
    }
}


void Foam::gasB2B1Operator::toWindow
(
    const std::vector<double>* const* v,
    const std::vector<label>* at,
    std::vector<double>* const* w,
    label nf
) const
{
    // Unknown k's value of field f
    auto value = [&](label f, label k)
    {
        return (*v[f])[at ? (*at)[k] : k];
    };
    const label nW = nWindowCells();
    for (label f = 0; f < nf; ++f)
    {
        // Cells out of reach stay zero
        if (label(w[f]->size()) != nW) w[f]->assign(nW, 0.0);
        std::vector<double>& wf = *w[f];
        const label n = label(win_.size());
        for (label k = 0; k < n; ++k) wf[win_[k]] = value(f, k);
    }
    if (!Pstream::parRun()) return;

    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    for (const label p : haloProcs_)
    {
        const labelList& ks = sendTo_[p];
        if (ks.empty()) continue;
        List<scalar> send(nf*ks.size());
        label i = 0;
        for (label f = 0; f < nf; ++f)
        {
            for (const label k : ks) send[i++] = value(f, k);
        }
        UOPstream toP(p, pBufs);
        toP << send;
    }
    pBufs.finishedSends();
    for (const label p : haloProcs_)
    {
        const labelList& into = recvInto_[p];
        if (into.empty()) continue;
        UIPstream fromP(p, pBufs);
        const List<scalar> recv(fromP);
        label i = 0;
        for (label f = 0; f < nf; ++f)
        {
            for (const label pos : into) (*w[f])[pos] = recv[i++];
        }
    }
}


// ************************************************************************* //
