/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "bsmsReuseMemory.H"

// A C library header first: it defines __GLIBC__ where the library is glibc
#include <cstdlib>
#ifdef __GLIBC__
#include <malloc.h>
#endif

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

bool Foam::bsmsReuseMemory()
{
#ifdef __GLIBC__
    const int MB = 1024*1024;
    // Each tried: one refused leaves the others set
    const bool mmap = mallopt(M_MMAP_THRESHOLD, 32*MB) == 1;
    const bool trim = mallopt(M_TRIM_THRESHOLD, 512*MB) == 1;
    const bool pad = mallopt(M_TOP_PAD, 64*MB) == 1;
    return mmap && trim && pad;
#else
    return false;
#endif
}


// ************************************************************************* //
