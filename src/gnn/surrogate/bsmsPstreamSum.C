/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "bsmsPstreamSum.H"
#include "Pstream.H"
#include "ops.H"
#include <algorithm>
#include <chrono>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

namespace
{

// values summed over the ranks through buf (Pstream, up the tree adding,
// then the master's sum down); returns the seconds spent
template<class Type>
double sumOverRanks(std::vector<Type>& values, Foam::List<Type>& buf)
{
    using namespace Foam;
    const auto t0 = std::chrono::steady_clock::now();
    buf.setSize(label(values.size()));
    std::copy(values.begin(), values.end(), buf.begin());
    Pstream::listCombineGather(buf, plusEqOp<Type>());
    Pstream::listCombineScatter(buf);
    std::copy(buf.begin(), buf.end(), values.begin());
    return std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - t0
    ).count();
}

} // End anonymous namespace


void Foam::bsmsPstreamSum::operator()(std::vector<float>& values)
{
    if (!Pstream::parRun() || Pstream::nProcs() == 1) return;
    seconds_ += sumOverRanks(values, buf_);
    bytes_ = values.size()*sizeof(float);
    ++nCalls_;
}


void Foam::bsmsPstreamSum::operator()(std::vector<double>& values)
{
    if (!Pstream::parRun() || Pstream::nProcs() == 1) return;
    seconds_ += sumOverRanks(values, bufD_);
}


// ************************************************************************* //
