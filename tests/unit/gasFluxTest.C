// Unit tests of the gas solver's building blocks: the WENO reconstructions
// (exact on polynomials their stencils reproduce, design order on smooth
// data, no overshoot at a jump), consistency of every flux scheme in both
// variable sets (a uniform line returns the physical flux: this also checks
// that the characteristic eigenvectors are inverse to each other), the
// first-order fallback flux, the faces of a line taken 4 at a time giving
// the bits of one at a time, the Jacobi-PCG pressure system, and idealGas.

#include "WENO5.H"
#include "WENO3.H"
#include "upwind1.H"
#include "splitLineFluxes.H"
#include "pressureSystem.H"
#include "idealGas.H"
#include "testHelpers.H"

#include <gtest/gtest.h>
#include <cmath>
#include <vector>

using namespace Foam;
using testHelpers::dictOf;

namespace
{

// Physical Euler flux along direction n
void eulerFlux(const double q[5], int n, double gamma, double f[5])
{
    const double un = q[1 + n]/q[0];
    const double p = (gamma - 1)
       *(q[4] - 0.5*(q[1]*q[1] + q[2]*q[2] + q[3]*q[3])/q[0]);
    for (int c = 0; c < 5; ++c) f[c] = q[c]*un;
    f[1 + n] += p;
    f[4] += p*un;
}

// A line of full Euler fluxes along n over the buffers (ghosts included)
gasLine eulerLine
(
    std::vector<double> buf[5],
    label L,
    label G,
    int n,
    double gamma
)
{
    gasLine line;
    for (int c = 0; c < 5; ++c) line.q[c] = buf[c].data();
    line.L = L;
    line.G = G;
    line.normal = n;
    line.gamma = gamma;
    line.advective = false;
    return line;
}

} // End anonymous namespace


// Cell averages of a quadratic over unit cells: each three-cell candidate
// of WENO5 reproduces it, so any convex weights give the exact face value
TEST(gasFlux, WENO5ExactOnQuadratics)
{
    auto avg = [](double x) { return 3 + 2*x - x*x - 1.0/12.0; };
    for (double i : {0.0, 3.0, -7.5})
    {
        double v[5];
        for (int j = 0; j < 5; ++j) v[j] = avg(i - 2 + j);
        const double x = i + 0.5;
        EXPECT_NEAR
        (
            gasFluxSchemes::WENO5Reconstruction::face(v), 3 + 2*x - x*x,
            1e-12
        );
    }
}


// Cell averages of a line: both WENO3 candidates are exact
TEST(gasFlux, WENO3ExactOnLines)
{
    double v[3] = {1.5, 2.0, 2.5};      // 1.5 + 0.5 (x - i + 1)
    EXPECT_NEAR(gasFluxSchemes::WENO3Reconstruction::face(v), 2.25, 1e-14);
}


// On smooth data (cell averages of sin) the reconstruction error falls at
// the design order: > 4.5 for WENO5, > 1.9 for WENO3 between h = 0.1 and
// 0.025 (the bounds of the solver's acceptance on the same norms)
TEST(gasFlux, designOrderOnSmoothData)
{
    auto err = [](double h, int r)
    {
        double e = 0;
        for (double x0 = 0.05; x0 < 6.28; x0 += 0.1)
        {
            double v[5];
            for (int j = 0; j < 2*r - 1; ++j)
            {
                const double a = x0 + (j - r + 1)*h;
                v[j] = (std::cos(a - 0.5*h) - std::cos(a + 0.5*h))/h;
            }
            const double face =
                r == 3
              ? gasFluxSchemes::WENO5Reconstruction::face(v)
              : gasFluxSchemes::WENO3Reconstruction::face(v);
            e = std::max(e, std::abs(face - std::sin(x0 + 0.5*h)));
        }
        return e;
    };
    const double o5 = std::log(err(0.1, 3)/err(0.025, 3))/std::log(4.0);
    const double o3 = std::log(err(0.1, 2)/err(0.025, 2))/std::log(4.0);
    EXPECT_GT(o5, 4.5) << "WENO5 order " << o5;
    EXPECT_GT(o3, 1.9) << "WENO3 order " << o3;
}


// At a jump the left-biased reconstruction takes the smooth stencil: no
// overshoot, the value of the constant side to round-off
TEST(gasFlux, noOvershootAtAJump)
{
    const double v5[5] = {0, 0, 0, 1, 1};
    const double f5 = gasFluxSchemes::WENO5Reconstruction::face(v5);
    EXPECT_GE(f5, 0.0);
    EXPECT_LT(f5, 1e-12);
    const double v3[3] = {0, 0, 1};
    const double f3 = gasFluxSchemes::WENO3Reconstruction::face(v3);
    EXPECT_GE(f3, 0.0);
    EXPECT_LT(f3, 1e-12);
}


// A uniform line: every scheme, both variable sets and all three
// directions return the physical flux at every face (consistency; for the
// characteristic variables it needs R L = I at the face state)
TEST(gasFlux, uniformLineGivesPhysicalFlux)
{
    const double gamma = 1.4;
    const double rho = 1.3, u[3] = {0.7, -0.4, 0.25}, p = 2.1;
    const double q0[5] =
    {
        rho, rho*u[0], rho*u[1], rho*u[2],
        p/(gamma - 1) + 0.5*rho*(u[0]*u[0] + u[1]*u[1] + u[2]*u[2])
    };
    for (const char* scheme : {"upwind1", "WENO3", "WENO5"})
    {
        for (const char* vars : {"characteristic", "component"})
        {
            autoPtr<gasFluxScheme> s = gasFluxScheme::New
            (
                dictOf(std::string("scheme ") + scheme + "; variables "
                  + vars + ";")
            );
            const label L = 8, G = s->nGhost();
            std::vector<double> buf[5], Fb[5];
            for (int c = 0; c < 5; ++c)
            {
                buf[c].assign(L + 2*G, q0[c]);
                Fb[c].assign(L + 1, 0.0);
            }
            for (int n = 0; n < 3; ++n)
            {
                const gasLine line = eulerLine(buf, L, G, n, gamma);
                double* F[5];
                for (int c = 0; c < 5; ++c) F[c] = Fb[c].data();
                s->lineFluxes(line, F);
                double f[5];
                eulerFlux(q0, n, gamma, f);
                for (label m = 0; m <= L; ++m)
                {
                    for (int c = 0; c < 5; ++c)
                    {
                        EXPECT_NEAR(F[c][m], f[c], 1e-13*(1 + std::abs(f[c])))
                            << scheme << ' ' << vars << " dir " << n
                            << " face " << m << " comp " << c;
                    }
                }
            }
        }
    }
}


// The characteristic flux takes 4 faces at a time (lanes); every face must
// get the bits it gets alone (characteristicFaces<Recon, 1>), also where a
// face in the middle of a batch falls back to the component-wise flux
// (no positive pressure at its mean state) and at the line's last faces
template<class Recon>
void batchedEqualsOneByOne(const char* name)
{
    const double gamma = 1.4;
    const label L = 13, G = Recon::r, N = L + 2*G;
    std::vector<double> buf[5], f[5], lambda(N), un(N), cs(N);
    for (int c = 0; c < 5; ++c)
    {
        buf[c].resize(N);
        f[c].resize(N);
    }
    for (label i = 0; i < N; ++i)
    {
        // a smooth wave, a jump, and cells G + 5, G + 6 with (nearly) no
        // internal energy: the mean state at the face between them has
        // negative pressure
        const double x = 0.37*i;
        const double rho = (i < N/2 ? 1.0 : 0.125) + 0.1*std::sin(x);
        const double u[3] = {0.3 + 0.2*std::cos(x), -0.1*x, 0.05};
        double p = (i < N/2 ? 1.0 : 0.1) + 0.05*std::sin(2*x);
        const double ke = 0.5*rho*(u[0]*u[0] + u[1]*u[1] + u[2]*u[2]);
        double E = p/(gamma - 1) + ke;
        if (i == G + 5 || i == G + 6) E = 0.9*ke;
        buf[0][i] = rho;
        for (int d = 0; d < 3; ++d) buf[1 + d][i] = rho*u[d];
        buf[4][i] = E;
    }
    for (int n = 0; n < 3; ++n)
    {
        const gasLine line = eulerLine(buf, L, G, n, gamma);
        for (label i = 0; i < N; ++i)
        {
            double q[5], fi[5];
            for (int c = 0; c < 5; ++c) q[c] = buf[c][i];
            eulerFlux(q, n, gamma, fi);
            for (int c = 0; c < 5; ++c) f[c][i] = fi[c];
            const double pi = (gamma - 1)*(q[4] - 0.5*(q[1]*q[1]
              + q[2]*q[2] + q[3]*q[3])/q[0]);
            un[i] = q[1 + n]/q[0];
            cs[i] = std::sqrt(std::abs(gamma*pi/q[0]));
            lambda[i] = std::abs(un[i]) + cs[i];
        }
        std::vector<double> Fb[5], Fo[5];
        double* Fbp[5];
        double* Fop[5];
        for (int c = 0; c < 5; ++c)
        {
            Fb[c].assign(L + 1, 0.0);
            Fo[c].assign(L + 1, 0.0);
            Fbp[c] = Fb[c].data();
            Fop[c] = Fo[c].data();
        }
        characteristicLineFluxes<Recon>(line, f, lambda, un, cs, Fbp);
        const int perm[5] = {0, 1 + n, 1 + (n + 1) % 3, 1 + (n + 2) % 3, 4};
        const double* qp[5];
        const double* fp[5];
        for (int k = 0; k < 5; ++k)
        {
            qp[k] = buf[perm[k]].data();
            fp[k] = f[perm[k]].data();
        }
        for (label m = 0; m <= L; ++m)
        {
            characteristicFaces<Recon, 1>
            (
                line, qp, fp, perm, f, lambda, un.data(), cs.data(), Fop, m
            );
        }
        for (label m = 0; m <= L; ++m)
        {
            for (int c = 0; c < 5; ++c)
            {
                EXPECT_TRUE(std::isfinite(Fb[c][m]));
                EXPECT_EQ(Fb[c][m], Fo[c][m])
                    << name << " dir " << n << " face " << m << " comp " << c;
            }
        }
        // The fallback face did fall back: it is the component-wise flux
        double* Fcp[5];
        std::vector<double> Fc[5];
        for (int c = 0; c < 5; ++c)
        {
            Fc[c].assign(L + 1, 0.0);
            Fcp[c] = Fc[c].data();
        }
        componentFace<Recon>(line, f, lambda, Fcp, 6);
        for (int c = 0; c < 5; ++c)
        {
            EXPECT_EQ(Fb[c][6], Fc[c][6]) << name << " fallback comp " << c;
        }
    }
}

TEST(gasFlux, batchedFacesEqualOneByOne)
{
    batchedEqualsOneByOne<gasFluxSchemes::WENO5Reconstruction>("WENO5");
    batchedEqualsOneByOne<gasFluxSchemes::WENO3Reconstruction>("WENO3");
}


// The first-order fallback flux of two equal states is the physical flux;
// of different states it adds alpha/2 (qR - qL) of dissipation
TEST(gasFlux, firstOrderFlux)
{
    const double gamma = 1.4;
    const double q[5] = {1, 0.5, 0, 0, 2.5 + 0.125};
    double F[5], f[5];
    gasFluxScheme::firstOrderFlux(q, q, 0, gamma, false, F);
    eulerFlux(q, 0, gamma, f);
    for (int c = 0; c < 5; ++c) EXPECT_NEAR(F[c], f[c], 1e-15);

    // Advective flux of a state at rest: zero
    const double rest[5] = {1, 0, 0, 0, 2.5};
    gasFluxScheme::firstOrderFlux(rest, rest, 1, gamma, true, F);
    for (int c = 0; c < 5; ++c) EXPECT_EQ(F[c], 0.0);
}


// Jacobi-PCG on a 1D diffusion-reaction matrix (SPD): converges to the
// known solution in at most n iterations
TEST(gasFlux, pressureSystemSolves)
{
    const label n = 60;
    pressureSystem sys;
    sys.reset(n);
    for (label i = 0; i < n; ++i) sys.diag[i] = 0.1*(1 + i % 3);
    for (label i = 0; i + 1 < n; ++i) sys.couple(i, i + 1, 1.0 + 0.01*i);
    std::vector<double> xExact(n), b;
    for (label i = 0; i < n; ++i) xExact[i] = std::sin(0.3*i) + 2;
    sys.multiply(xExact, b);
    sys.source = b;
    std::vector<double> x(n, 0.0);
    double res = 0;
    const label it = sys.solve(x, 1e-12, 1000, res);
    EXPECT_LE(it, n);
    EXPECT_LE(res, 1e-12);
    for (label i = 0; i < n; ++i) EXPECT_NEAR(x[i], xExact[i], 1e-9);
}


// idealGas: both dictionary forms, and gamma <= 1 refused with the entry
TEST(gasFlux, idealGasReadsBothForms)
{
    const idealGas direct(dictOf("gamma 1.4; R 287;"));
    EXPECT_DOUBLE_EQ(direct.gamma(), 1.4);
    EXPECT_DOUBLE_EQ(direct.R(), 287);

    const idealGas mix
    (
        dictOf
        (
            "mixture { specie { molWeight 28.96; }"
            " thermodynamics { Cp 1004.5; Hf 0; } }"
        )
    );
    const double R = 8314.47006650545/28.96;
    EXPECT_NEAR(mix.R(), R, 1e-6*R);
    EXPECT_NEAR(mix.gamma(), 1004.5/(1004.5 - R), 1e-6);

    std::string m = testHelpers::ioErrorOf([]{ idealGas g(dictOf("gamma 1; R 1;")); });
    EXPECT_NE(m.find("'gamma'"), std::string::npos) << m;
    EXPECT_NE(m.find("> 1"), std::string::npos) << m;

    m = testHelpers::ioErrorOf([]{ idealGas g(dictOf("gamma 1.4; R -3;")); });
    EXPECT_NE(m.find("'R'"), std::string::npos) << m;
}
