/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "gasB2B1Operator.H"
#include "Pstream.H"
#include <cmath>
#include <algorithm>
#include <map>
#include <array>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    // Quadratic B-spline N^2 (support |t| < 3/2), in cell units
    inline double N2(double t)
    {
        t = std::abs(t);
        if (t <= 0.5) return 0.75 - t*t;
        if (t < 1.5) return 0.5*(1.5 - t)*(1.5 - t);
        return 0;
    }

    // Linear B-spline N^1 and its derivative
    inline double N1(double t)
    {
        return std::max(0.0, 1 - std::abs(t));
    }

    inline double dN1(double t)
    {
        if (t > -1 && t < 0) return 1;
        if (t > 0 && t < 1) return -1;
        return 0;
    }
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

// (3.32), (3.33): the 1D factors of int N^2_v d r_j and int N^2_v r_j
void Foam::gasB2B1Operator::table1D
(
    label n,
    bool periodic,
    std::vector<label>& start,
    std::vector<label>& cell,
    std::vector<double>& D,
    std::vector<double>& M,
    std::vector<double>& W
)
{
    const label nv = periodic ? n : n + 1;
    start.assign(1, 0);
    cell.clear();
    D.clear();
    M.clear();
    W.clear();

    // The pressure function of cell j (mirror images at a non-periodic
    // end, the images across the period else), and its derivative
    auto r = [&](label j, double x, bool deriv)
    {
        auto f = [&](double t) { return deriv ? dN1(t) : N1(t); };
        double s = 0;
        if (periodic)
        {
            for (label k = -3; k <= 3; ++k) s += f(x - (j + 0.5) - k*n);
        }
        else
        {
            s = f(x - (j + 0.5));
            if (j == 0) s += f(x + 0.5);
            if (j == n - 1) s += f(x - (n + 0.5));
        }
        return s;
    };
    auto inCell = [&](label c, double x)
    {
        if (!periodic) return x >= c && x <= c + 1 ? 1.0 : 0.0;
        double y = x - c;
        y -= n*std::floor(y/n);
        return y <= 1 ? 1.0 : 0.0;
    };

    // 3-point Gauss on each half cell: exact for these cubics
    const double gx[3] = {-std::sqrt(0.6), 0, std::sqrt(0.6)};
    const double gw[3] = {5.0/9, 8.0/9, 5.0/9};
    for (label v = 0; v < nv; ++v)
    {
        std::map<label, std::array<double, 3>> row;
        for (label c = v - 3; c <= v + 2; ++c)
        {
            label j = c;
            if (periodic) j = ((c % n) + n) % n;
            else if (c < 0 || c >= n) continue;
            std::array<double, 3>& e = row[j];
            e = {0, 0, 0};
        }
        for (auto& kv : row)
        {
            const label j = kv.first;
            std::array<double, 3>& e = kv.second;
            for (label h = 0; h < 6; ++h)
            {
                const double a = v - 1.5 + 0.5*h, b = a + 0.5;
                // Within the lattice only (a periodic one has no ends)
                if (!periodic && (b <= 0 || a >= n)) continue;
                const double mid = 0.5*(a + b), half = 0.25;
                for (int q = 0; q < 3; ++q)
                {
                    const double x = mid + half*gx[q];
                    const double wq = half*gw[q]*N2(x - v);
                    e[0] += wq*r(j, x, true);
                    e[1] += wq*r(j, x, false);
                    e[2] += wq*inCell(j, x);
                }
            }
        }
        for (const auto& kv : row)
        {
            const std::array<double, 3>& e = kv.second;
            if (std::abs(e[0]) + std::abs(e[1]) + e[2] < 1e-15) continue;
            cell.push_back(kv.first);
            D.push_back(e[0]);
            M.push_back(e[1]);
            W.push_back(e[2]);
        }
        start.push_back(label(cell.size()));
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::gasB2B1Operator::gasB2B1Operator
(
    const cartesianMesh& mesh,
    const label N[3],
    const bool periodic[3],
    const std::vector<label>& cells,
    const std::vector<label>& global
)
:
    latOf_(global),
    local_(cells),
    nHalo_(0)
{
    V_ = mesh.cellVolume();
    for (label d = 0; d < 3; ++d)
    {
        active_[d] = mesh.active(d);
        periodic_[d] = active_[d] && periodic[d];
        N_[d] = active_[d] ? N[d] : 1;
        A_[d] = V_/mesh.dx(d);
    }
    buildWindow();
    for (label d = 0; d < 3; ++d)
    {
        D2_[d].resize(D_[d].size());
        M2_[d].resize(M_[d].size());
        for (size_t e = 0; e < D_[d].size(); ++e)
        {
            D2_[d][e] = D_[d][e]*D_[d][e];
            M2_[d][e] = M_[d][e]*M_[d][e];
        }
    }
    buildHalo();
    const std::vector<double> ones(size_t(nWindowCells()), 1.0);
    const std::vector<double>* F[3] = {&W_[0], &W_[1], &W_[2]};
    forward(ones, Wsum_, F);
}


// * * * * * * * * * * * * * * Private Functions * * * * * * * * * * * * * * //

void Foam::gasB2B1Operator::contract
(
    const std::vector<double>& in,
    std::vector<double>& out,
    label dims[3],
    label a,
    const std::vector<double>& F,
    bool transpose
) const
{
    label inner = 1, outer = 1;
    for (label e = 0; e < a; ++e) inner *= dims[e];
    for (label e = a + 1; e < 3; ++e) outer *= dims[e];
    const label nc = nc_[a], nv = nv_[a];
    const std::vector<label>& st = start_[a];
    const std::vector<label>& cl = cell_[a];
    if (!transpose)
    {
        out.assign(size_t(inner*nv*outer), 0.0);
        for (label o = 0; o < outer; ++o)
        {
            for (label v = 0; v < nv; ++v)
            {
                double* y = out.data() + inner*(v + nv*o);
                for (label e = st[v]; e < st[v + 1]; ++e)
                {
                    const double f = F[e];
                    const double* x = in.data() + inner*(cl[e] + nc*o);
                    for (label i = 0; i < inner; ++i) y[i] += f*x[i];
                }
            }
        }
        dims[a] = nv;
    }
    else
    {
        out.assign(size_t(inner*nc*outer), 0.0);
        for (label o = 0; o < outer; ++o)
        {
            for (label v = 0; v < nv; ++v)
            {
                const double* x = in.data() + inner*(v + nv*o);
                for (label e = st[v]; e < st[v + 1]; ++e)
                {
                    const double f = F[e];
                    double* y = out.data() + inner*(cl[e] + nc*o);
                    for (label i = 0; i < inner; ++i) y[i] += f*x[i];
                }
            }
        }
        dims[a] = nc;
    }
}


void Foam::gasB2B1Operator::forward
(
    const std::vector<double>& in,
    std::vector<double>& out,
    const std::vector<double>* F[3]
) const
{
    label dims[3] = {nc_[0], nc_[1], nc_[2]};
    out = in;
    for (label a = 0; a < 3; ++a)
    {
        if (!active_[a]) continue;
        contract(out, a_, dims, a, *F[a], false);
        out.swap(a_);
    }
}


void Foam::gasB2B1Operator::backward
(
    const std::vector<double>& in,
    std::vector<double>& out,
    const std::vector<double>* F[3]
) const
{
    label dims[3] = {nv_[0], nv_[1], nv_[2]};
    out = in;
    for (label a = 2; a >= 0; --a)
    {
        if (!active_[a]) continue;
        contract(out, a_, dims, a, *F[a], true);
        out.swap(a_);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

// (3.35) into (3.37): the gas's lumped masses, C = theta^2/M, the source
// G^T theta u*/dt and the Jacobi diagonal of G^T C G
void Foam::gasB2B1Operator::setStep
(
    const std::vector<double>* q,
    const std::vector<double>& open,
    double dt,
    const vector& g,
    std::vector<double>& source,
    std::vector<double>& diag
)
{
    const label nV = nVertices();
    const std::vector<double>* FW[3] = {&W_[0], &W_[1], &W_[2]};
    std::vector<double>& mass = mass_;
    std::vector<double>& mom = mom_;
    // The window's advected gas and open fractions (per lattice cell)
    const label n = label(latOf_.size());
    const std::vector<double>* lat[5] = {&q[0], &q[1], &q[2], &q[3], &open};
    std::vector<double>* qw[5] = {&qw_[0], &qw_[1], &qw_[2], &qw_[3], &qw_[4]};
    toWindow(lat, &local_, qw, 5);
    forward(qw_[0], mass, FW);
    forward(qw_[4], theta_, FW);
    C_.resize(nV);
    for (label v = 0; v < nV; ++v)
    {
        mass[v] *= V_;
        theta_[v] /= Wsum_[v];
        // A vertex out of the rank's reach may have no gas in the window
        C_[v] = mass[v] > 0 ? theta_[v]*theta_[v]/mass[v] : 0;
    }
    diag_.assign(n, 0.0);
    for (label d = 0; d < 3; ++d)
    {
        if (!active_[d]) continue;
        forward(qw_[1 + d], mom, FW);
        // theta u* A/dt at each vertex
        for (label v = 0; v < nV; ++v)
        {
            const double u =
                mass[v] > 0 ? V_*mom[v]/mass[v] + dt*g[d] : 0;
            mom[v] = theta_[v]*u*A_[d]/dt;
        }
        const std::vector<double>* F[3];
        const std::vector<double>* F2[3];
        for (label e = 0; e < 3; ++e)
        {
            F[e] = e == d ? &D_[e] : &M_[e];
            F2[e] = e == d ? &D2_[e] : &M2_[e];
        }
        backward(mom, y_, F);
        for (label k = 0; k < n; ++k) source[k] += y_[win_[k]];

        // diag_j = sum_v C_v A^2 G_vj^2 (G's factors squared)
        b_.resize(nV);
        for (label v = 0; v < nV; ++v) b_[v] = C_[v]*A_[d]*A_[d];
        backward(b_, y_, F2);
        for (label k = 0; k < n; ++k) diag_[k] += y_[win_[k]];
    }
    for (label k = 0; k < n; ++k) diag[k] += diag_[k];
}


// (3.37), the gas's rows: y += G^T C G x (less the Jacobi diagonal that
// the caller's LDU product already applied)
void Foam::gasB2B1Operator::addProduct
(
    const std::vector<double>& x,
    std::vector<double>& y
) const
{
    const label n = label(latOf_.size());
    const label nV = nVertices();
    const std::vector<double>* xk[1] = {&x};
    std::vector<double>* xw[1] = {&x_};
    toWindow(xk, nullptr, xw, 1);
    for (label d = 0; d < 3; ++d)
    {
        if (!active_[d]) continue;
        const std::vector<double>* F[3];
        for (label e = 0; e < 3; ++e) F[e] = e == d ? &D_[e] : &M_[e];
        forward(x_, b_, F);
        const double A2 = A_[d]*A_[d];
        for (label v = 0; v < nV; ++v) b_[v] *= C_[v]*A2;
        backward(b_, y_, F);
        for (label k = 0; k < n; ++k) y[k] += y_[win_[k]];
    }
    for (label k = 0; k < n; ++k) y[k] -= diag_[k]*x[k];
}


// ************************************************************************* //
