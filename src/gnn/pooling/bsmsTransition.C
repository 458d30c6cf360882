/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "bsmsTransition.H"
#include "bsmsPooling.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

// 4.3.2 Downsampling: Ahat_ij = A_ij/sum_j A_ij, what_ij = w_i Ahat_ij,
// C_ij = what_ij/sum_i what_ij, next weight w_j = sum_i what_ij; A with
// self-loops.  Upsampling by the row-normalised C (see the header).
Foam::bsmsTransition::bsmsTransition
(
    const meshGraph& g,
    const labelUList& pooled,
    const scalarUList& w
)
:
    nFine_(g.nNodes()),
    nCoarse_(pooled.size())
{
    if (w.size() != nFine_)
    {
        FatalErrorInFunction
            << w.size() << " weights for a level of " << nFine_ << " nodes"
            << exit(FatalError);
    }
    const label* off = g.offsets().cdata();
    const label* nbr = g.neighbours().cdata();

    // what_ij: sender i's weight shared equally over {i} + N(i)
    scalarList share(nFine_);
    for (label i = 0; i < nFine_; ++i)
    {
        share[i] = w[i]/scalar(off[i + 1] - off[i] + 1);
    }

    // C by receiver: senders {p} + N(p), ascending
    downOffsets_.setSize(nCoarse_ + 1);
    label nEntries = 0;
    for (label k = 0; k < nCoarse_; ++k)
    {
        downOffsets_[k] = nEntries;
        nEntries += g.degree(pooled[k]) + 1;
    }
    downOffsets_[nCoarse_] = nEntries;
    downSenders_.setSize(nEntries);
    downC_.setSize(nEntries);
    coarseWeights_.setSize(nCoarse_);
    labelList upCount(nFine_ + 1, Zero);

    for (label k = 0; k < nCoarse_; ++k)
    {
        const label p = pooled[k];
        label e = downOffsets_[k];
        bool selfDone = false;
        for (label m = off[p]; m <= off[p + 1]; ++m)
        {
            // Merge p itself into its sorted neighbours
            if (!selfDone && (m == off[p + 1] || nbr[m] > p))
            {
                downSenders_[e++] = p;
                selfDone = true;
            }
            if (m < off[p + 1]) downSenders_[e++] = nbr[m];
        }

        scalar W = 0;
        for (label s = downOffsets_[k]; s < downOffsets_[k + 1]; ++s)
        {
            W += share[downSenders_[s]];
        }
        coarseWeights_[k] = W;
        for (label s = downOffsets_[k]; s < downOffsets_[k + 1]; ++s)
        {
            const label i = downSenders_[s];
            downC_[s] = share[i]/W;
            ++upCount[i + 1];
        }
    }

    // The same table by sender (transpose): receivers ascending
    upOffsets_.setSize(nFine_ + 1);
    upOffsets_[0] = 0;
    for (label i = 0; i < nFine_; ++i)
    {
        upOffsets_[i + 1] = upOffsets_[i] + upCount[i + 1];
    }
    labelList fill(SubList<label>(upOffsets_, nFine_));
    upReceivers_.setSize(nEntries);
    upC_.setSize(nEntries);
    for (label k = 0; k < nCoarse_; ++k)
    {
        for (label e = downOffsets_[k]; e < downOffsets_[k + 1]; ++e)
        {
            const label f = fill[downSenders_[e]]++;
            upReceivers_[f] = k;
            upC_[f] = downC_[e];
        }
    }

    // Row normalisation: sum_j C_ij > 0 for every node of a 2-CC pooling
    for (label i = 0; i < nFine_; ++i)
    {
        scalar rowSum = 0;
        for (label e = upOffsets_[i]; e < upOffsets_[i + 1]; ++e)
        {
            rowSum += upC_[e];
        }
        if (!(rowSum > 0))
        {
            FatalErrorInFunction
                << "Node " << i << " has no pooled neighbour: the pooled "
                << "nodes are not a 2-CC pooling of the graph"
                << exit(FatalError);
        }
        for (label e = upOffsets_[i]; e < upOffsets_[i + 1]; ++e)
        {
            upC_[e] /= rowSum;
        }
    }
}


// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

Foam::PtrList<Foam::bsmsTransition> Foam::bsmsTransition::chain
(
    const bsmsPooling& levels
)
{
    const label n = levels.nLevels() - 1;
    PtrList<bsmsTransition> result(n);
    scalarList w(levels.graph(0).nNodes(), 1.0);
    for (label l = 0; l < n; ++l)
    {
        result.set
        (
            l, new bsmsTransition(levels.graph(l), levels.pooled(l), w)
        );
        w = result[l].coarseWeights();
    }
    return result;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bsmsTransition::downsample
(
    const scalar* fine,
    scalar* coarse,
    const label nComp
) const
{
    const label* off = downOffsets_.cdata();
    const label* src = downSenders_.cdata();
    const scalar* c = downC_.cdata();
    for (label j = 0; j < nCoarse_; ++j)
    {
        scalar* out = coarse + j*nComp;
        for (label d = 0; d < nComp; ++d) out[d] = 0;
        for (label e = off[j]; e < off[j + 1]; ++e)
        {
            const scalar* in = fine + src[e]*nComp;
            for (label d = 0; d < nComp; ++d) out[d] += c[e]*in[d];
        }
    }
}


void Foam::bsmsTransition::upsample
(
    const scalar* coarse,
    scalar* fine,
    const label nComp
) const
{
    const label* off = upOffsets_.cdata();
    const label* src = upReceivers_.cdata();
    const scalar* c = upC_.cdata();
    for (label i = 0; i < nFine_; ++i)
    {
        scalar* out = fine + i*nComp;
        for (label d = 0; d < nComp; ++d) out[d] = 0;
        for (label e = off[i]; e < off[i + 1]; ++e)
        {
            const scalar* in = coarse + src[e]*nComp;
            for (label d = 0; d < nComp; ++d) out[d] += c[e]*in[d];
        }
    }
}


// ************************************************************************* //
