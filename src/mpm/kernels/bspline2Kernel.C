/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "bspline2Kernel.H"
#include "addToRunTimeSelectionTable.H"
#include "dictionary.H"
#include "OStringStream.H"

#include <cmath>

namespace Foam
{
    defineTypeNameAndDebug(bspline2Kernel, 0);
    addToRunTimeSelectionTable(mpmKernel, bspline2Kernel, dictionary);
}


namespace
{
//- A vertex's lattice coordinate may be this far (in cells) from an
//  integer (see the class description)
const Foam::scalar latticeTolerance = 1e-4;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::bspline2Kernel::build(const dictionary& dict)
{
    const mpmMeshView& m = mesh_;
    const List<vector>& X = m.vertices();
    const labelList& cv = m.cellVertices();
    dim_ = m.dim();
    static const char* axisName = "xyz";

    auto centre = [&](const label c)
    {
        vector xc(Zero);
        for (label i = m.cellBegin(c); i < m.cellEnd(c); ++i) xc += X[cv[i]];
        return xc/scalar(max(label(1), m.cellEnd(c) - m.cellBegin(c)));
    };

    auto stop = [&](const label c, const string& why)
    {
        OStringStream where;
        where << c;
        if (c >= 0 && c < m.nCells()) where << " at " << centre(c);
        FatalIOErrorInFunction(dict)
            << "Entry 'kernel' in " << dict.name() << " has the value "
            << typeName << ", which needs a uniform Cartesian mesh: every"
            << " cell an axis-aligned box of one size on one lattice." << nl
            << "    first offending cell: " << where.str().c_str() << nl
            << "    " << why.c_str() << nl
            << "    allowed: kernel " << typeName << " on blockMesh-like"
            << " meshes (hexahedra, or quadrilaterals/segments of a 2D/1D"
            << " mesh, of one common size per axis, e.g. blocks with"
            << " simpleGrading (1 1 1) and equal spacing, at least 2 cells"
            << " along each solution axis); on other meshes kernel umls,"
            << " mlsRing or linear" << nl
            << exit(FatalIOError);
    };

    for (label a = 0; a < 3; ++a)
    {
        axis_[a] = a < dim_ ? m.axis(a) : 0;
        origin_[a] = 0;
        h_[a] = 1;
        rh_[a] = 1;
        n_[a] = 0;
        stride_[a] = 0;
    }

    if (m.nCells() == 0)
    {
        stop(-1, "the mesh has no cells");
    }

    const mpmMeshView::shapeType want =
        dim_ == 1 ? mpmMeshView::SEGMENT
      : dim_ == 2 ? mpmMeshView::QUAD
      : mpmMeshView::HEX;

    auto span = [&](const label c, const label a)
    {
        scalar lo = GREAT, hi = -GREAT;
        for (label i = m.cellBegin(c); i < m.cellEnd(c); ++i)
        {
            lo = min(lo, X[cv[i]][axis_[a]]);
            hi = max(hi, X[cv[i]][axis_[a]]);
        }
        return hi - lo;
    };

    // Spacing from cell 0, then from the extent of the lattice
    if (m.shape(0) != want)
    {
        stop(0, string("it is a ") + mpmMeshView::shapeName(m.shape(0))
          + "; the " + Foam::name(dim_) + "D lattice needs "
          + mpmMeshView::shapeName(want) + " cells");
    }
    label nNodes = 1;
    scalar h0[3] = {1, 1, 1};
    for (label a = 0; a < dim_; ++a)
    {
        const label d = axis_[a];
        h0[a] = span(0, a);
        const scalar extent = m.bbMax()[d] - m.bbMin()[d];
        if (!(h0[a] > 0))
        {
            stop(0, string("its size along ") + axisName[d] + " is zero");
        }
        n_[a] = label(std::round(extent/h0[a]));
        if (n_[a] < 2)
        {
            stop(0, string("the mesh has ") + Foam::name(n_[a])
              + " cell(s) along " + axisName[d] + "; the three-node"
              " stencil needs at least 2");
        }
        origin_[a] = m.bbMin()[d];
        h_[a] = extent/n_[a];
        rh_[a] = 1/h_[a];
        stride_[a] = nNodes;
        nNodes *= n_[a] + 1;
    }

    // Every cell the shape and size of cell 0 (the first offending cell of
    // a graded mesh is the first of another size)
    for (label c = 0; c < m.nCells(); ++c)
    {
        if (m.shape(c) != want)
        {
            stop(c, string("it is a ") + mpmMeshView::shapeName(m.shape(c))
              + "; the " + Foam::name(dim_) + "D lattice needs "
              + mpmMeshView::shapeName(want) + " cells");
        }
        for (label a = 0; a < dim_; ++a)
        {
            const scalar hc = span(c, a);
            // (a size is the difference of two points: twice the
            // tolerance of one)
            if (std::abs(hc - h0[a]) > 2*latticeTolerance*h0[a])
            {
                stop(c, string("its size along ") + axisName[axis_[a]]
                  + " is " + Foam::name(hc) + ", cell 0's is "
                  + Foam::name(h0[a]) + " (relative tolerance "
                  + Foam::name(2*latticeTolerance) + ")");
            }
        }
    }

    // Lattice place of every vertex
    labelList idx(dim_*m.nVertices());
    List<bool> onLattice(m.nVertices());
    forAll(X, v)
    {
        bool ok = true;
        for (label a = 0; a < dim_; ++a)
        {
            const scalar s = (X[v][axis_[a]] - origin_[a])*rh_[a];
            const label i = label(std::round(s));
            idx[dim_*v + a] = i;
            ok = ok && std::abs(s - i) <= latticeTolerance;
        }
        onLattice[v] = ok;
    }

    // Every cell: the 2^dim corners of one lattice box
    latticeVertex_.setSize(nNodes, -1);
    const label nCorners = 1 << dim_;
    for (label c = 0; c < m.nCells(); ++c)
    {
        label lo[3] = {labelMax, labelMax, labelMax};
        for (label i = m.cellBegin(c); i < m.cellEnd(c); ++i)
        {
            const label v = cv[i];
            if (!onLattice[v])
            {
                OStringStream os;
                os  << "its vertex at " << X[v] << " is off the lattice of"
                    << " spacing";
                for (label a = 0; a < dim_; ++a) os << ' ' << h_[a];
                os  << " (from cell 0 and the mesh's extent) by more than "
                    << latticeTolerance << " of a cell";
                stop(c, os.str());
            }
            for (label a = 0; a < dim_; ++a)
            {
                lo[a] = min(lo[a], idx[dim_*v + a]);
            }
        }
        label corners = 0;
        for (label i = m.cellBegin(c); i < m.cellEnd(c); ++i)
        {
            const label v = cv[i];
            label code = 0, node = 0;
            for (label a = 0; a < dim_; ++a)
            {
                const label k = idx[dim_*v + a] - lo[a];
                if (k > 1)
                {
                    stop(c, string("its size along ") + axisName[axis_[a]]
                      + " is " + Foam::name(span(c, a))
                      + ", the lattice spacing (cell 0) is "
                      + Foam::name(h_[a]));
                }
                code |= k << a;
                node += idx[dim_*v + a]*stride_[a];
            }
            corners |= 1 << code;
            if (latticeVertex_[node] >= 0 && latticeVertex_[node] != v)
            {
                stop(c, "two of the mesh's vertices share the lattice node"
                  " of its vertex at " + Foam::name(X[v]));
            }
            latticeVertex_[node] = v;
        }
        if (corners != (1 << nCorners) - 1)
        {
            label a = 0;
            while (a + 1 < dim_ && span(c, a) > 0.5*h_[a]) ++a;
            stop(c, string("it is not an axis-aligned box of the lattice")
              + " (its size along " + axisName[axis_[a]] + " is "
              + Foam::name(span(c, a)) + ", the lattice spacing "
              + Foam::name(h_[a]) + ")");
        }
    }

    label nMissing = 0;
    for (const label v : latticeVertex_)
    {
        if (v < 0) ++nMissing;
    }
    complete_ = (nMissing == 0);

    Info<< "bspline2 kernel: lattice of";
    for (label a = 0; a < dim_; ++a)
    {
        Info<< (a ? " x " : " ") << n_[a];
    }
    Info<< " cells, spacing";
    for (label a = 0; a < dim_; ++a)
    {
        Info<< ' ' << axisName[axis_[a]] << ' ' << h_[a];
    }
    if (complete_)
    {
        Info<< ", every node a vertex" << endl;
    }
    else
    {
        Info<< ", " << nMissing << " of " << nNodes << " nodes outside the"
            << " mesh (their weights are renormalised away)" << endl;
    }
}


template<int D>
inline void Foam::bspline2Kernel::stencils
(
    const vector& x,
    long b[3],
    double w[3][3],
    double dw[3][3]
) const
{
    for (int a = 0; a < D; ++a)
    {
        // (3.32) along each solution axis, at lattice coordinate s
        const double s = (x[axis_[a]] - origin_[a])*rh_[a];
        bspline2::boundedStencil(s, n_[a], b[a], w[a], dw[a]);
        for (int k = 0; k < 3; ++k)
        {
            dw[a][k] *= rh_[a];
        }
    }
}


template<int D>
void Foam::bspline2Kernel::computeBox
(
    const UList<vector>& x,
    kernelWeights& out
) const
{
    constexpr label K1 = D > 1 ? 3 : 1;
    constexpr label K2 = D > 2 ? 3 : 1;
    constexpr label K = 3*K1*K2;
    const label nP = x.size();

    // Sized once to the working size; no reallocation afterwards
    out.start.setSize(nP + 1);
    out.vertex.setSize(nP*K);
    out.w.setSize(nP*K);
    out.gradW.setSize(nP*K);
    label* __restrict st = out.start.data();
    label* __restrict vv = out.vertex.data();
    scalar* __restrict ww = out.w.data();
    vector* __restrict gg = out.gradW.data();
    const label* __restrict lv = latticeVertex_.cdata();
    const label a0 = axis_[0], a1 = axis_[1], a2 = axis_[2];
    const label s1 = stride_[1], s2 = stride_[2];

    for (label p = 0; p < nP; ++p)
    {
        long b[3] = {0, 0, 0};
        double w[3][3], dw[3][3];
        stencils<D>(x[p], b, w, dw);

        label e = p*K;
        st[p] = e;
        const label base =
            label(b[0]) + (D > 1 ? label(b[1])*s1 : 0)
          + (D > 2 ? label(b[2])*s2 : 0);

        for (label k2 = 0; k2 < K2; ++k2)
        {
            const double w2 = D > 2 ? w[2][k2] : 1;
            const double d2 = D > 2 ? dw[2][k2] : 0;
            for (label k1 = 0; k1 < K1; ++k1)
            {
                const double w1 = D > 1 ? w[1][k1] : 1;
                const double d1 = D > 1 ? dw[1][k1] : 0;
                const double w12 = w1*w2;
                const double g1 = d1*w2;
                const double g2 = w1*d2;
                const label row = base + k1*s1 + k2*s2;
                for (label k0 = 0; k0 < 3; ++k0, ++e)
                {
                    // w = prod N, grad w by the product rule
                    vv[e] = lv[row + k0];
                    ww[e] = w[0][k0]*w12;
                    vector g(Zero);
                    g[a0] = dw[0][k0]*w12;
                    if (D > 1) g[a1] = w[0][k0]*g1;
                    if (D > 2) g[a2] = w[0][k0]*g2;
                    gg[e] = g;
                }
            }
        }
    }
    st[nP] = nP*K;
}


template<int D>
void Foam::bspline2Kernel::computeHoles
(
    const UList<vector>& x,
    kernelWeights& out
) const
{
    constexpr label K1 = D > 1 ? 3 : 1;
    constexpr label K2 = D > 2 ? 3 : 1;
    const label a0 = axis_[0], a1 = axis_[1], a2 = axis_[2];

    out.clear();
    label vtx[27];
    scalar wl[27];
    vector gl[27];
    forAll(x, p)
    {
        long b[3] = {0, 0, 0};
        double w[3][3], dw[3][3];
        stencils<D>(x[p], b, w, dw);
        const label base =
            label(b[0]) + (D > 1 ? label(b[1])*stride_[1] : 0)
          + (D > 2 ? label(b[2])*stride_[2] : 0);

        label m = 0;
        scalar S = 0;
        vector G(Zero);
        for (label k2 = 0; k2 < K2; ++k2)
        {
            for (label k1 = 0; k1 < K1; ++k1)
            {
                const double w1 = D > 1 ? w[1][k1] : 1;
                const double d1 = D > 1 ? dw[1][k1] : 0;
                const double w2 = D > 2 ? w[2][k2] : 1;
                const double d2 = D > 2 ? dw[2][k2] : 0;
                const label row = base + k1*stride_[1] + k2*stride_[2];
                for (label k0 = 0; k0 < 3; ++k0)
                {
                    const label v = latticeVertex_[row + k0];
                    if (v < 0) continue;
                    vector g(Zero);
                    g[a0] = dw[0][k0]*w1*w2;
                    if (D > 1) g[a1] = w[0][k0]*d1*w2;
                    if (D > 2) g[a2] = w[0][k0]*w1*d2;
                    vtx[m] = v;
                    wl[m] = w[0][k0]*w1*w2;
                    gl[m] = g;
                    S += wl[m];
                    G += g;
                    ++m;
                }
            }
        }
        // The particle's own cell's corners all exist and carry weight:
        // S > 0.  w/S and its gradient (g - (w/S) G)/S
        const scalar rS = 1/S;
        for (label i = 0; i < m; ++i)
        {
            const scalar wi = wl[i]*rS;
            out.append(vtx[i], wi, (gl[i] - wi*G)*rS);
        }
        out.endParticle();
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::bspline2Kernel::bspline2Kernel
(
    const dictionary& dict,
    const mpmMeshView& mesh
)
:
    mpmKernel(dict, mesh),
    dim_(mesh.dim()),
    complete_(true)
{
    build(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bspline2Kernel::compute
(
    const UList<vector>& x,
    const labelUList&,
    kernelWeights& out
) const
{
    if (complete_)
    {
        if (dim_ == 1) computeBox<1>(x, out);
        else if (dim_ == 2) computeBox<2>(x, out);
        else computeBox<3>(x, out);
    }
    else
    {
        if (dim_ == 1) computeHoles<1>(x, out);
        else if (dim_ == 2) computeHoles<2>(x, out);
        else computeHoles<3>(x, out);
    }
}


Foam::vector Foam::bspline2Kernel::momentFloor() const
{
    vector f(Zero);
    for (label a = 0; a < dim_; ++a)
    {
        f[axis_[a]] = 0.125*h_[a]*h_[a];
    }
    return f;
}


// ************************************************************************* //
