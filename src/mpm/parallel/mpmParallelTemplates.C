/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "mpmParallel.H"
#include "PstreamBuffers.H"
#include "ops.H"

#include <chrono>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

template<class T, class CombineOp>
void Foam::mpmParallel::combineShared
(
    UList<T>& values,
    const CombineOp& op,
    const List<bool>* active
) const
{
    const exchangeTimer timer;

    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    forAll(nbrProcs_, q)
    {
        const labelList& list = nbrVertices_[q];
        List<T> send(list.size());
        forAll(list, j) send[j] = values[list[j]];
        UOPstream os(nbrProcs_[q], pBufs);
        os << send;
    }
    pBufs.finishedSends();
    List<List<T>> recv(nbrProcs_.size());
    forAll(nbrProcs_, q)
    {
        UIPstream is(nbrProcs_[q], pBufs);
        is >> recv[q];
    }

    // Every copy combines the same values in the same (rank) order, so
    // all copies end bit-identical
    forAll(sharedVertex_, s)
    {
        const label i = sharedVertex_[s];
        if (active && !(*active)[i]) continue;
        T result = Zero;
        for (label k = sumStart_[s]; k < sumStart_[s + 1]; ++k)
        {
            const label q = sumNbr_[k];
            const T& x = q < 0 ? values[i] : recv[q][sumPos_[k]];
            result = (k == sumStart_[s]) ? x : op(result, x);
        }
        values[i] = result;
    }

}


template<class T>
void Foam::mpmParallel::sumShared
(
    UList<T>& values,
    const List<bool>* active
) const
{
    combineShared(values, plusOp<T>(), active);
}


// ************************************************************************* //
