/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "densityVariation.H"
#include "dictionaryChecks.H"
#include <cstring>

using namespace Foam::dictionaryChecks;

namespace
{

// splitmix64: a well-mixed 64-bit hash step
inline std::uint64_t mix(std::uint64_t z)
{
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30))*0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27))*0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

inline std::uint64_t bitsOf(double v)
{
    // (+0 and -0 are one position)
    if (v == 0) v = 0;
    std::uint64_t b;
    std::memcpy(&b, &v, sizeof(b));
    return b;
}

}


Foam::densityVariation::densityVariation(const dictionary& region)
{
    const dictionary* d = region.findDict("densityVariation", keyType::LITERAL);
    if (!d) return;
    amplitude_ = getInRange(*d, "amplitude", 0, 0.9);
    const label s = getLabelAtLeast(*d, "seed", 0, 0);
    seed_ = std::uint64_t(s);
}


Foam::scalar Foam::densityVariation::xi(const vector& x) const
{
    std::uint64_t h = mix(seed_);
    for (direction k = 0; k < 3; ++k)
    {
        h = mix(h ^ bitsOf(x[k]));
    }
    // 53 random bits to [0, 1], then [-1, 1]
    const double u = double(h >> 11)*(1.0/9007199254740991.0);
    return 2*u - 1;
}


// ************************************************************************* //
