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

void Foam::bsmsPstreamSum::operator()(std::vector<float>& values)
{
    if (!Pstream::parRun() || Pstream::nProcs() == 1) return;

    const auto t0 = std::chrono::steady_clock::now();
    buf_.setSize(label(values.size()));
    std::copy(values.begin(), values.end(), buf_.begin());
    Pstream::listCombineGather(buf_, plusEqOp<floatScalar>());
    Pstream::listCombineScatter(buf_);
    std::copy(buf_.begin(), buf_.end(), values.begin());
    seconds_ += std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - t0
    ).count();
    bytes_ = values.size()*sizeof(float);
    ++nCalls_;
}


// ************************************************************************* //
