/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "bsmsPooling.H"
#include "dictionaryChecks.H"
#include "DynamicList.H"
#include <algorithm>
#include <chrono>
#include <vector>
#include <cstdint>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
using namespace Foam;

// Map from fine node to its index among the pooled nodes (-1: not pooled)
labelList coarseIndex(const label nFine, const labelUList& pooled)
{
    labelList coarseOf(nFine, -1);
    forAll(pooled, k) coarseOf[pooled[k]] = k;
    return coarseOf;
}

// Positions of the pooled nodes
pointField pooledPositions(const meshGraph& g, const labelUList& pooled)
{
    pointField x(pooled.size());
    forAll(pooled, k) x[k] = g.positions()[pooled[k]];
    return x;
}

// Close the row of coarse node k: sort its neighbours
inline void sortRow(DynamicList<label>& nbrs, const label begin)
{
    std::sort(nbrs.begin() + begin, nbrs.end());
}

// (A A)[I, I] by bit rows, for dense levels: row q of the mask holds the
// pooled nodes of {q} + N(q); coarse row k is the OR of the masks of {p} +
// N(p), p = I[k].  Costs nFine (d + 1) bit sets and nc (d + 1) nc/64 word
// ORs instead of the nc (d + 1)^2 visits of the sparse product.
void denseSquare
(
    const meshGraph& g,
    const labelUList& pooled,
    const labelUList& coarseOf,
    labelList& offsets,
    DynamicList<label>& nbrs
)
{
    const label n = g.nNodes(), nc = pooled.size();
    const label words = (nc + 63)/64;
    const label* off = g.offsets().cdata();
    const label* nbr = g.neighbours().cdata();

    std::vector<uint64_t> mask(size_t(n)*words, 0);
    auto set = [&](uint64_t* row, const label c)
    {
        if (c >= 0) row[c >> 6] |= uint64_t(1) << (c & 63);
    };
    for (label q = 0; q < n; ++q)
    {
        uint64_t* row = mask.data() + size_t(q)*words;
        set(row, coarseOf[q]);
        for (label m = off[q]; m < off[q + 1]; ++m) set(row, coarseOf[nbr[m]]);
    }

    std::vector<uint64_t> acc(words);
    for (label k = 0; k < nc; ++k)
    {
        offsets[k] = nbrs.size();
        const label p = pooled[k];
        const uint64_t* row = mask.data() + size_t(p)*words;
        for (label w = 0; w < words; ++w) acc[w] = row[w];
        for (label m = off[p]; m < off[p + 1]; ++m)
        {
            row = mask.data() + size_t(nbr[m])*words;
            for (label w = 0; w < words; ++w) acc[w] |= row[w];
        }
        acc[k >> 6] &= ~(uint64_t(1) << (k & 63));   // no self-loop
        for (label w = 0; w < words; ++w)
        {
            for (uint64_t bits = acc[w]; bits; bits &= bits - 1)
            {
                nbrs.append(64*w + __builtin_ctzll(bits));
            }
        }
    }
    offsets[nc] = nbrs.size();
}


double secondsSince(const std::chrono::steady_clock::time_point& t0)
{
    return std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - t0
    ).count();
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bsmsPooling::bsmsPooling(const dictionary& dict)
:
    seeding_(bsmsSeeding::New(dict)),
    minNodes_(dictionaryChecks::getLabelAtLeast(dict, "minNodes", 100, 1)),
    maxLevels_(dictionaryChecks::getLabelAtLeast(dict, "maxLevels", 32, 1)),
    balance_(0.45)
{
    const string allowed("a number in [0, 0.5]");
    balance_ = dictionaryChecks::getAsOrDefault<scalar>
    (
        dict, "balance", balance_, allowed
    );
    if (!(balance_ >= 0 && balance_ <= 0.5))
    {
        dictionaryChecks::badEntry(dict, "balance", name(balance_), allowed);
    }
}


Foam::bsmsPooling::bsmsPooling
(
    const word& seeding,
    const label minNodes,
    const label maxLevels,
    const scalar balance
)
:
    seeding_(bsmsSeeding::New(seeding)),
    minNodes_(minNodes),
    maxLevels_(maxLevels),
    balance_(balance)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

// Bi-stride pooling (4.2.2): per cluster (Algorithm 4), a seed (Algorithm 2
// or 3), a BFS from it, and the nodes of every other BFS frontier; topped
// up to half the cluster when that set is below balance_ of it.
Foam::labelList Foam::bsmsPooling::select(const meshGraph& g) const
{
    const label n = g.nNodes();
    labelList cOff, cNodes;
    g.clusters(cOff, cNodes);
    const labelList seeds(seeding_->seeds(g, cOff, cNodes));

    labelList dist(n, -1);
    labelList order(n);
    labelList rest(n);
    std::vector<char> keep(n, 0);
    forAll(seeds, k)
    {
        // The clusters are disjoint: dist is still -1 on this one
        const label reached = g.bfs(seeds[k], dist, order);
        label nEven = 0;
        for (label m = 0; m < reached; ++m)
        {
            nEven += (dist[order[m]] % 2 == 0);
        }
        // The smaller parity set, even on a tie or when the odd one is
        // empty (a single-node cluster)
        const label nOdd = reached - nEven;
        const label parity = (nEven <= nOdd || nOdd == 0) ? 0 : 1;
        const label nKept = parity == 0 ? nEven : reached - nEven;
        label nRest = 0;
        for (label m = 0; m < reached; ++m)
        {
            const label i = order[m];
            if (dist[i] % 2 == parity)
            {
                keep[i] = 1;
            }
            else
            {
                rest[nRest++] = i;
            }
        }

        // Few frontiers (dense coarse levels): add nodes of the other
        // frontiers, evenly spaced in BFS order, up to half the cluster.
        // A superset of a 2-CC set is 2-CC.
        const label half = reached/2;
        if (nKept < balance_*reached && nKept < half)
        {
            const label nAdd = half - nKept;
            for (label t = 0; t < nAdd; ++t)
            {
                const label m = label((int64_t(2*t + 1)*nRest)/(2*nAdd));
                keep[rest[m]] = 1;
            }
        }
    }

    label nKept = 0;
    for (const char k : keep) nKept += k;
    labelList pooled(nKept);
    nKept = 0;
    for (label i = 0; i < n; ++i)
    {
        if (keep[i]) pooled[nKept++] = i;
    }
    return pooled;
}


// (4.1) A'_{l+1} = A_l A_l,  A_{l+1} = A'_{l+1}[I, I]: coarse node k joins
// every pooled node r != I[k] reachable in at most two hops of A_l (with
// its self-loops: q in {p} + N(p), r in {q} + N(q)).
Foam::meshGraph Foam::bsmsPooling::enhance
(
    const meshGraph& g,
    const labelUList& pooled
)
{
    const label nc = pooled.size();
    const labelList coarseOf(coarseIndex(g.nNodes(), pooled));
    const label* off = g.offsets().cdata();
    const label* nbr = g.neighbours().cdata();
    const label* cOf = coarseOf.cdata();

    labelList offsets(nc + 1);
    DynamicList<label> nbrs(2*g.neighbours().size());

    // Dense levels (mean degree above twice the words of a bit row, masks
    // under 256 MB): bit rows; else the sparse product
    const label words = (nc + 63)/64;
    const double meanDegree =
        double(g.neighbours().size())/max(g.nNodes(), label(1));
    if (meanDegree > 2*words && double(g.nNodes())*words*8 < 256e6)
    {
        denseSquare(g, pooled, coarseOf, offsets, nbrs);
        return meshGraph
        (
            pooledPositions(g, pooled),
            std::move(offsets),
            labelList(std::move(nbrs))
        );
    }

    labelList stamp(nc, -1);
    for (label k = 0; k < nc; ++k)
    {
        offsets[k] = nbrs.size();
        const label p = pooled[k];
        auto reach = [&](const label q)
        {
            const label cq = cOf[q];
            if (cq >= 0 && cq != k && stamp[cq] != k)
            {
                stamp[cq] = k;
                nbrs.append(cq);
            }
            for (label m = off[q]; m < off[q + 1]; ++m)
            {
                const label c = cOf[nbr[m]];
                if (c >= 0 && c != k && stamp[c] != k)
                {
                    stamp[c] = k;
                    nbrs.append(c);
                }
            }
        };
        reach(p);
        for (label m = off[p]; m < off[p + 1]; ++m) reach(nbr[m]);
        sortRow(nbrs, offsets[k]);
    }
    offsets[nc] = nbrs.size();

    return meshGraph
    (
        pooledPositions(g, pooled),
        std::move(offsets),
        labelList(std::move(nbrs))
    );
}


// (4.1) A^C_{l+1} = A_l A^C_l A_l,  A^C_{l+1} = A^C_{l+1}[I, I]: coarse node
// k joins every pooled node r != I[k] with a chain p - q ~ c - r, where
// q in {p} + N(p), c a contact neighbour of q, r in {c} + N(c).
Foam::meshGraph Foam::bsmsPooling::enhanceContact
(
    const meshGraph& g,
    const meshGraph& contact,
    const labelUList& pooled
)
{
    if (contact.nNodes() != g.nNodes())
    {
        FatalErrorInFunction
            << "Contact graph of " << contact.nNodes() << " nodes for a "
            << "graph of " << g.nNodes() << exit(FatalError);
    }
    const label nc = pooled.size();
    const labelList coarseOf(coarseIndex(g.nNodes(), pooled));
    const label* off = g.offsets().cdata();
    const label* nbr = g.neighbours().cdata();
    const label* cOff = contact.offsets().cdata();
    const label* cNbr = contact.neighbours().cdata();
    const label* cOf = coarseOf.cdata();

    labelList stamp(nc, -1);
    labelList offsets(nc + 1);
    DynamicList<label> nbrs(contact.neighbours().size());

    for (label k = 0; k < nc; ++k)
    {
        offsets[k] = nbrs.size();
        auto add = [&](const label r)
        {
            const label c = cOf[r];
            if (c >= 0 && c != k && stamp[c] != k)
            {
                stamp[c] = k;
                nbrs.append(c);
            }
        };
        // From q (p or a mesh neighbour of p) over its contact edges
        auto fromq = [&](const label q)
        {
            for (label m = cOff[q]; m < cOff[q + 1]; ++m)
            {
                const label c = cNbr[m];
                add(c);
                for (label t = off[c]; t < off[c + 1]; ++t) add(nbr[t]);
            }
        };
        const label p = pooled[k];
        fromq(p);
        for (label m = off[p]; m < off[p + 1]; ++m) fromq(nbr[m]);
        sortRow(nbrs, offsets[k]);
    }
    offsets[nc] = nbrs.size();

    return meshGraph
    (
        pooledPositions(g, pooled),
        std::move(offsets),
        labelList(std::move(nbrs))
    );
}


void Foam::bsmsPooling::build(const meshGraph& fine)
{
    DynamicList<meshGraph*> graphs;
    DynamicList<labelList> pooled;
    DynamicList<scalar> seconds;

    graphs.append(new meshGraph(fine));
    seconds.append(0);

    while
    (
        graphs.size() < maxLevels_
     && graphs.last()->nNodes() >= minNodes_
    )
    {
        const auto t0 = std::chrono::steady_clock::now();
        const meshGraph& g = *graphs.last();
        labelList I(select(g));
        if (I.size() == g.nNodes())
        {
            // Only single-node clusters are left
            break;
        }
        graphs.append(new meshGraph(enhance(g, I)));
        pooled.append(std::move(I));
        seconds.append(secondsSince(t0));
    }

    graphs_.setSize(graphs.size());
    forAll(graphs, l) graphs_.set(l, graphs[l]);
    pooled_.transfer(pooled);
    seconds_.transfer(seconds);
    setContact(meshGraph(fine.positions(), labelList(), labelList()));
}


void Foam::bsmsPooling::build(const meshGraph& fine, const meshGraph& contact)
{
    if (contact.nNodes() != fine.nNodes())
    {
        FatalErrorInFunction
            << "Contact graph of " << contact.nNodes() << " nodes for a "
            << "graph of " << fine.nNodes() << exit(FatalError);
    }
    build(fine);
    if (contact.nEdges() > 0) setContact(contact);
}


void Foam::bsmsPooling::setContact(const meshGraph& contact)
{
    if (graphs_.empty() || contact.nNodes() != graphs_[0].nNodes())
    {
        FatalErrorInFunction
            << "Contact graph of " << contact.nNodes() << " nodes for "
            << (graphs_.empty() ? label(0) : graphs_[0].nNodes())
            << " finest nodes (levels built?)" << exit(FatalError);
    }
    const bool withContact = contact.nEdges() > 0;
    contacts_.setSize(graphs_.size());
    contacts_.set(0, new meshGraph(contact));
    for (label l = 0; l + 1 < graphs_.size(); ++l)
    {
        contacts_.set
        (
            l + 1,
            withContact
          ? new meshGraph(enhanceContact(graphs_[l], contacts_[l], pooled_[l]))
          : new meshGraph(graphs_[l + 1].positions(), labelList(), labelList())
        );
    }
}


Foam::labelList Foam::bsmsPooling::finestNodes(const label l) const
{
    labelList nodes(identity(graphs_[l].nNodes()));
    for (label m = l - 1; m >= 0; --m)
    {
        forAll(nodes, k) nodes[k] = pooled_[m][nodes[k]];
    }
    return nodes;
}


// ************************************************************************* //
