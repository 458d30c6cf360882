// OpenFOAM side of the torch unit tests' graphs (see gridHierarchies.H)

#include "gridHierarchies.H"
#include "bsmsExport.H"
#include "bsmsPooling.H"
#include "lagrangianGraph.H"

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


bsmsData::hierarchy gridHierarchies::twoBodies
(
    int n,
    int minNodes,
    double radius,
    const std::vector<double>& shifts,
    std::vector<bsmsData::world>& frames
)
{
    using namespace Foam;
    pointField x(2*n*n);
    DynamicList<label> a, b;
    for (label body = 0; body < 2; ++body)
    {
        for (label j = 0; j < n; ++j)
        {
            for (label i = 0; i < n; ++i)
            {
                const label k = body*n*n + i + n*j;
                x[k] = point(i + body*(n + 1), j, 0);
                if (i + 1 < n) { a.append(k); b.append(k + 1); }
                if (j + 1 < n) { a.append(k); b.append(k + n); }
            }
        }
    }
    const meshGraph g(x, a, b);
    bsmsPooling levels("closeCenter", minNodes);
    levels.build(g);
    lagrangianGraph L
    (
        g,
        List<lagrangianGraph::nodeKind>(g.nNodes(), lagrangianGraph::nodeKind::free),
        radius
    );
    frames.clear();
    for (const double s : shifts)
    {
        pointField xs(x);
        for (label k = n*n; k < 2*n*n; ++k) xs[k].x() -= s;
        L.move(xs);
        levels.setContact(L.worldEdges());
        frames.push_back(bsmsExportWorld(levels, xs));
    }
    return bsmsExport(levels, 2);
}