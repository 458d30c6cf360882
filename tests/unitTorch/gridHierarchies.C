// OpenFOAM side of the torch unit tests' graphs (see gridHierarchies.H)

#include "gridHierarchies.H"
#include "bsmsExport.H"
#include "bsmsPooling.H"

bsmsData::hierarchy gridHierarchies::grid(int nx, int ny, int minNodes)
{
    using namespace Foam;
    pointField x(nx*ny);
    DynamicList<label> a, b;
    for (label j = 0; j < ny; ++j)
    {
        for (label i = 0; i < nx; ++i)
        {
            const label n = i + nx*j;
            x[n] = point(i, j, 0);
            if (i + 1 < nx) { a.append(n); b.append(n + 1); }
            if (j + 1 < ny) { a.append(n); b.append(n + nx); }
        }
    }
    const meshGraph g(x, a, b);
    bsmsPooling levels("closeCenter", minNodes);
    levels.build(g);
    return bsmsExport(levels, 2);
}
