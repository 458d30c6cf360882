/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
-------------------------------------------------------------------------------
    barrierContact: the geometry (nearest points of segments and
    triangles, a path against a face, the mean edge)
\*---------------------------------------------------------------------------*/

#include "barrierContact.H"
#include "ops.H"

// * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

Foam::vector Foam::barrierContact::nearestOnSegment
(
    const vector& a,
    const vector& b,
    const vector& x
)
{
    const vector ab = b - a;
    const scalar l2 = magSqr(ab);
    if (l2 <= 0) return a;
    const scalar t = min(max(((x - a) & ab)/l2, scalar(0)), scalar(1));
    return a + t*ab;
}


Foam::vector Foam::barrierContact::nearestOnTriangle
(
    const vector& a,
    const vector& b,
    const vector& c,
    const vector& x
)
{
    // The Voronoi regions of the triangle's vertices, edges and interior,
    // told apart by the projections of x - a, x - b, x - c on the edges
    const vector ab = b - a;
    const vector ac = c - a;

    const vector ax = x - a;
    const scalar d1 = ab & ax;
    const scalar d2 = ac & ax;
    if (d1 <= 0 && d2 <= 0) return a;

    const vector bx = x - b;
    const scalar d3 = ab & bx;
    const scalar d4 = ac & bx;
    if (d3 >= 0 && d4 <= d3) return b;

    // Edge ab
    const scalar vc = d1*d4 - d3*d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0)
    {
        return a + (d1/(d1 - d3))*ab;
    }

    const vector cx = x - c;
    const scalar d5 = ab & cx;
    const scalar d6 = ac & cx;
    if (d6 >= 0 && d5 <= d6) return c;

    // Edge ac
    const scalar vb = d5*d2 - d1*d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0)
    {
        return a + (d2/(d2 - d6))*ac;
    }

    // Edge bc
    const scalar va = d3*d6 - d5*d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    {
        const scalar w = (d4 - d3)/((d4 - d3) + (d5 - d6));
        return b + w*(c - b);
    }

    // Interior: barycentric coordinates from the areas
    const scalar sum = va + vb + vc;
    if (!(mag(sum) > 0)) return a;     // degenerate triangle
    return a + (vb/sum)*ab + (vc/sum)*ac;
}


bool Foam::barrierContact::pathMeets
(
    const face& f,
    const vector& x0,
    const vector& x1
)
{
    const vector r = x1 - x0;
    if (f.segment)
    {
        // Two segments of one plane: x0 + t r = a + u s, t, u in [0, 1]
        const vector s = f.b - f.a;
        const vector rs = r ^ s;
        const scalar rs2 = magSqr(rs);
        if (!(rs2 > 0)) return false;       // parallel
        const vector q = f.a - x0;
        const scalar t = ((q ^ s) & rs)/rs2;
        const scalar u = ((q ^ r) & rs)/rs2;
        return t >= 0 && t <= 1 && u >= 0 && u <= 1;
    }

    // Triangle: x0 + t r = a + u (b - a) + v (c - a), by Cramer's rule
    const vector e1 = f.b - f.a;
    const vector e2 = f.c - f.a;
    const vector pv = r ^ e2;
    const scalar det = e1 & pv;
    if (!(mag(det) > 0)) return false;      // parallel
    const vector tv = x0 - f.a;
    const scalar u = (tv & pv)/det;
    if (u < 0 || u > 1) return false;
    const vector qv = tv ^ e1;
    const scalar v = (r & qv)/det;
    if (v < 0 || u + v > 1) return false;
    const scalar t = (e2 & qv)/det;
    return t >= 0 && t <= 1;
}


Foam::scalar Foam::barrierContact::meanEdge(const UList<face>& faces)
{
    scalar sum = 0;
    for (const face& f : faces)
    {
        sum += f.segment
            ? mag(f.b - f.a)
            : (mag(f.b - f.a) + mag(f.c - f.b) + mag(f.a - f.c))/3;
    }
    return faces.size() ? sum/faces.size() : 0;
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::vector Foam::barrierContact::nearest(const face& f, const vector& x) const
{
    return f.segment
        ? nearestOnSegment(f.a, f.b, x)
        : nearestOnTriangle(f.a, f.b, f.c, x);
}


// ************************************************************************* //
