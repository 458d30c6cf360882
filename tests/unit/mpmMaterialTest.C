// Unit tests of the MPM constitutive models: linearElastic, neoHookean,
// fixedCorotated
//  - rest state, small-strain limit, objectivity, P = dPsi/dF, uniaxial E
//  - the polar decomposition of fixedCorotated
//  - bad dictionaries and inverted particles stop with a clear message

#include "mpmMaterial.H"
#include "fixedCorotated.H"
#include "IStringStream.H"

#include <gtest/gtest.h>
#include <cmath>
#include <functional>
#include <iostream>
#include <random>

using namespace Foam;

namespace
{

const scalar E0 = 1e6;
const scalar nu0 = 0.3;

dictionary dictOf(const std::string& text)
{
    IStringStream is(text);
    return dictionary(is);
}

autoPtr<mpmMaterial> material(const word& type, scalar nu = nu0)
{
    const dictionary d
    (
        dictOf
        (
            "type " + type + "; rho 1000; E " + std::to_string(E0)
          + "; nu " + std::to_string(nu) + ";"
        )
    );
    return mpmMaterial::New("m", d);
}

struct response
{
    symmTensor sigma;
    scalar psi;
};

response evaluate(const mpmMaterial& m, const tensor& F)
{
    List<tensor> Fl(1, F);
    List<symmTensor> sigma(1, symmTensor::zero);
    List<scalar> psi(1, scalar(0));
    m.stress(Fl, sigma, psi);
    return {sigma[0], psi[0]};
}

// First Piola-Kirchhoff stress from the Cauchy stress: P = J sigma F^{-T}
tensor piola(const symmTensor& sigma, const tensor& F)
{
    return det(F)*(tensor(sigma) & inv(F).T());
}

tensor randomTensor(std::mt19937& gen, scalar a)
{
    std::uniform_real_distribution<double> u(-a, a);
    tensor t;
    for (direction i = 0; i < tensor::nComponents; ++i) t[i] = u(gen);
    return t;
}

// Rotation by angle about axis (Rodrigues)
tensor rotation(vector axis, scalar angle)
{
    axis /= mag(axis);
    const tensor K
    (
        0, -axis.z(), axis.y(),
        axis.z(), 0, -axis.x(),
        -axis.y(), axis.x(), 0
    );
    return tensor::I + std::sin(angle)*K + (1 - std::cos(angle))*(K & K);
}

// A general F with J > 0: a large, non-symmetric deformation
tensor generalF(unsigned seed)
{
    std::mt19937 gen(seed);
    tensor F(tensor::I + randomTensor(gen, 0.4));
    return F;
}

// The FatalIOError message of f(), or "" if it did not stop
std::string ioErrorOf(std::function<void()> f)
{
    FatalIOError.throwExceptions();
    std::string msg;
    try
    {
        f();
    }
    catch (const Foam::IOerror& err)
    {
        msg = err.message();
    }
    FatalIOError.dontThrowExceptions();
    return msg;
}

// The FatalError message of f(), or "" if it did not stop
std::string errorOf(std::function<void()> f)
{
    FatalError.throwExceptions();
    std::string msg;
    try
    {
        f();
    }
    catch (const Foam::error& err)
    {
        msg = err.message();
    }
    FatalError.dontThrowExceptions();
    return msg;
}

const wordList allModels{"linearElastic", "neoHookean", "fixedCorotated"};
const wordList hyperelastic{"neoHookean", "fixedCorotated"};

} // End anonymous namespace


// Lame parameters and the wave speed for E = 1e6, nu = 0.25, rho = 1000:
// lambda = mu = 4e5, c = sqrt(1.2e6/1000) = sqrt(1200)
TEST(mpmMaterial, lameParametersAndWaveSpeed)
{
    const auto m = material("linearElastic", 0.25);
    EXPECT_EQ(m->name(), "m");
    EXPECT_DOUBLE_EQ(m->rho(), 1000);
    EXPECT_NEAR(m->lambda(), 4e5, 1e-9*E0);
    EXPECT_NEAR(m->mu(), 4e5, 1e-9*E0);
    EXPECT_NEAR(m->waveSpeed(), std::sqrt(1200.0), 1e-12*std::sqrt(1200.0));
    EXPECT_FALSE(m->plastic());
}


// F = I is the stress-free rest state of every model.  Exact in exact
// arithmetic; 1e-12 E leaves room for the rounding of (B - I), ln(1) and the
// polar decomposition of I only
TEST(mpmMaterial, restStateIsStressFree)
{
    for (const word& type : allModels)
    {
        const auto m = material(type);
        const response r = evaluate(*m, tensor::I);
        EXPECT_LT(mag(r.sigma), 1e-12*E0) << type;
        EXPECT_LT(std::abs(r.psi), 1e-12*E0) << type;
        std::cout << "  " << type << ": |sigma(I)|/E = " << mag(r.sigma)/E0
            << ", |Psi(I)|/E = " << std::abs(r.psi)/E0 << std::endl;
    }
}


// Small-strain limit: for F = I + eps G, the nonlinear models differ from
// linear elasticity by O(E eps^2), i.e. a relative error O(eps) = 1e-7
// (plus rounding ~1e-16/eps = 1e-9 from forming F F^T - I).  1e-5 is far
// above both and far below the O(1) error of a wrong modulus or sign
TEST(mpmMaterial, smallStrainLimitIsLinearElastic)
{
    const scalar eps = 1e-7;
    std::mt19937 gen(7);
    const auto lin = material("linearElastic");
    for (label sample = 0; sample < 5; ++sample)
    {
        const tensor F(tensor::I + eps*randomTensor(gen, 1));
        const response rl = evaluate(*lin, F);
        for (const word& type : hyperelastic)
        {
            const auto m = material(type);
            const response r = evaluate(*m, F);
            const scalar err = mag(r.sigma - rl.sigma)/mag(rl.sigma);
            const scalar errPsi = std::abs(r.psi - rl.psi)/std::abs(rl.psi);
            EXPECT_LT(err, 1e-5) << type << " sample " << sample;
            // Psi = O(E eps^2): its relative difference is also O(eps)
            EXPECT_LT(errPsi, 1e-5) << type << " sample " << sample;
            if (sample == 0)
            {
                std::cout << "  " << type << " vs linearElastic at eps = "
                    << eps << ": stress rel. error " << err
                    << ", energy rel. error " << errPsi << std::endl;
            }
        }
    }
}


// Objectivity: sigma(QF) = Q sigma(F) Q^T and Psi(QF) = Psi(F) for a finite
// rotation Q.  Both sides are O(1) rounding apart (~1e-15 relative, more
// through the polar decomposition and the conditioning of F); 1e-10 is well
// above that and far below the O(1) error of a non-objective model
TEST(mpmMaterial, hyperelasticModelsAreObjective)
{
    const tensor Q(rotation(vector(1, -2, 0.5), 1.1));
    ASSERT_NEAR(det(Q), 1, 1e-14);
    for (const word& type : hyperelastic)
    {
        const auto m = material(type);
        scalar worst = 0, worstPsi = 0;
        for (unsigned seed = 1; seed <= 5; ++seed)
        {
            const tensor F(generalF(seed));
            ASSERT_GT(det(F), 0.1);
            const response r = evaluate(*m, F);
            const response rq = evaluate(*m, Q & F);
            const tensor expected(Q & tensor(r.sigma) & Q.T());
            const scalar err = mag(tensor(rq.sigma) - expected)/mag(r.sigma);
            const scalar errPsi = std::abs(rq.psi - r.psi)/std::abs(r.psi);
            EXPECT_LT(err, 1e-10) << type << " seed " << seed;
            EXPECT_LT(errPsi, 1e-10) << type << " seed " << seed;
            worst = max(worst, err);
            worstPsi = max(worstPsi, errPsi);
        }
        std::cout << "  " << type << ": objectivity rel. error stress "
            << worst << ", energy " << worstPsi << std::endl;
    }
}


// linearElastic is not objective: a rigid rotation (no deformation at all)
// gets a stress of order E (1 - cos angle).  This is why it is for small
// strains and rotations only
TEST(mpmMaterial, linearElasticIsNotObjective)
{
    const auto m = material("linearElastic");
    const scalar angle = 0.5;
    const tensor Q(rotation(vector(0, 0, 1), angle));
    const response r = evaluate(*m, Q);
    // Expected: eps = (cos - 1)(e_x e_x + e_y e_y), |sigma| ~ E (1 - cos)
    EXPECT_GT(mag(r.sigma), 0.1*E0*(1 - std::cos(angle)));
    std::cout << "  linearElastic: |sigma(Q)|/E = " << mag(r.sigma)/E0
        << " for a rigid rotation of " << angle << " rad" << std::endl;

    // The hyperelastic models give zero for the same rigid rotation
    for (const word& type : hyperelastic)
    {
        EXPECT_LT(mag(evaluate(*material(type), Q).sigma), 1e-12*E0) << type;
    }
}


// The stress is the derivative of the energy, P = dPsi/dF, by central
// differences with step h = 1e-5: truncation ~ h^2 |Psi'''| ~ 1e-10 E and
// rounding ~ 1e-16 |Psi|/h ~ 1e-11 E, so ~1e-10 relative; 1e-6 leaves a
// large margin but catches any wrong term (O(1) relative)
TEST(mpmMaterial, stressIsEnergyDerivative)
{
    const scalar h = 1e-5;
    for (const word& type : allModels)
    {
        const auto m = material(type);
        scalar worst = 0;
        for (unsigned seed = 11; seed <= 15; ++seed)
        {
            const tensor F(generalF(seed));
            ASSERT_GT(det(F), 0.1);
            const response r = evaluate(*m, F);

            // linearElastic has no current/reference distinction: its sigma
            // is itself dPsi/dF
            const tensor P
            (
                type == "linearElastic" ? tensor(r.sigma) : piola(r.sigma, F)
            );

            tensor Pfd;
            for (direction i = 0; i < tensor::nComponents; ++i)
            {
                tensor Fp(F), Fm(F);
                Fp[i] += h;
                Fm[i] -= h;
                Pfd[i] = (evaluate(*m, Fp).psi - evaluate(*m, Fm).psi)/(2*h);
            }
            const scalar err = mag(P - Pfd)/mag(P);
            EXPECT_LT(err, 1e-6) << type << " seed " << seed;
            worst = max(worst, err);
        }
        std::cout << "  " << type << ": |P - dPsi/dF|/|P| = " << worst
            << std::endl;
    }
}


// Uniaxial stress: eps_xx = e, eps_yy = eps_zz = -nu e gives sigma_xx = E e
// and all other components zero, Psi = E e^2/2.  Algebraic identities, so
// only rounding: forming 1 + e and subtracting 1 again costs ~1e-16/e =
// 1e-13 relative; 1e-11 leaves a margin of 100
TEST(mpmMaterial, linearElasticUniaxialReproducesE)
{
    const auto m = material("linearElastic");
    const scalar e = 1e-3;
    const tensor F
    (
        1 + e, 0, 0,
        0, 1 - nu0*e, 0,
        0, 0, 1 - nu0*e
    );
    const response r = evaluate(*m, F);
    const scalar s = E0*e;
    EXPECT_NEAR(r.sigma.xx(), s, 1e-11*s);
    for (direction i = 1; i < symmTensor::nComponents; ++i)
    {
        EXPECT_NEAR(r.sigma[i], 0, 1e-11*s) << "component " << label(i);
    }
    EXPECT_NEAR(r.psi, 0.5*E0*e*e, 1e-11*0.5*E0*e*e);
    std::cout << "  linearElastic uniaxial: sigma_xx/(E e) - 1 = "
        << r.sigma.xx()/s - 1 << ", max |other|/(E e) = "
        << max(max(mag(r.sigma.yy()), mag(r.sigma.zz())),
               max(mag(r.sigma.xy()), max(mag(r.sigma.xz()), mag(r.sigma.yz()))))/s
        << std::endl;
}


// The rotation of the polar decomposition: orthogonal, det +1, R^T F
// symmetric positive definite, for stretches up to 1e4 : 1e-2 (the
// iteration stops at 1e-14 relative; 1e-13 and 1e-12 allow for the
// conditioning of F).  Plane strain (F_zz = 1) keeps the out-of-plane
// components of R and the out-of-plane shear stresses exactly zero and
// R_zz = 1 to round-off
TEST(mpmMaterial, fixedCorotatedPolarDecomposition)
{
    const tensor Q1(rotation(vector(1, 1, 0), 0.7));
    const tensor Q2(rotation(vector(0, 1, 3), -1.3));
    const List<tensor> Fs
    {
        generalF(21),
        Q1 & tensor(1.5, 0, 0, 0, 0.7, 0, 0, 0, 1.2) & Q2,
        Q1 & tensor(1e4, 0, 0, 0, 1e-2, 0, 0, 0, 1) & Q2,
        tensor(1.2, 0.3, 0, -0.4, 0.9, 0, 0, 0, 1)
    };
    scalar worst = 0;
    forAll(Fs, k)
    {
        const tensor& F = Fs[k];
        const tensor R(fixedCorotated::polarRotation(F));
        const tensor S(R.T() & F);
        const scalar orth = mag((R.T() & R) - tensor::I);
        const scalar asym = mag(S - S.T())/mag(S);
        EXPECT_LT(orth, 1e-13) << "F " << k;
        EXPECT_NEAR(det(R), 1, 1e-13) << "F " << k;
        EXPECT_LT(asym, 1e-12) << "F " << k;
        // S positive definite: its quadratic form along a few directions
        for (const vector& d : {vector(1, 0, 0), vector(0, 1, 0),
            vector(0, 0, 1), vector(1, -1, 1)})
        {
            EXPECT_GT(d & S & d, 0) << "F " << k;
        }
        worst = max(worst, max(orth, asym));
    }
    std::cout << "  polar decomposition: max(|R^T R - I|, |S - S^T|/|S|) = "
        << worst << std::endl;

    const tensor& F2D = Fs[3];
    const tensor R2D(fixedCorotated::polarRotation(F2D));
    EXPECT_NEAR(R2D.zz(), 1, 1e-14);
    EXPECT_EQ(R2D.xz(), 0);
    EXPECT_EQ(R2D.zy(), 0);
    EXPECT_EQ(R2D.yz(), 0);
    EXPECT_EQ(R2D.zx(), 0);
    const response r = evaluate(*material("fixedCorotated"), F2D);
    EXPECT_EQ(r.sigma.xz(), 0);
    EXPECT_EQ(r.sigma.yz(), 0);
}


// One call updates a list; each entry equals its single evaluation
TEST(mpmMaterial, listEvaluation)
{
    for (const word& type : allModels)
    {
        const auto m = material(type);
        List<tensor> F(4);
        forAll(F, p) F[p] = generalF(31 + p);
        List<symmTensor> sigma(F.size());
        List<scalar> psi(F.size());
        m->stress(F, sigma, psi);
        forAll(F, p)
        {
            const response r = evaluate(*m, F[p]);
            EXPECT_EQ(sigma[p], r.sigma) << type << " particle " << p;
            EXPECT_EQ(psi[p], r.psi) << type << " particle " << p;
        }
    }
}


// Bad dictionaries stop with a FatalIOError naming the entry and what is
// allowed
TEST(mpmMaterial, badInputMessages)
{
    const auto check = [](const std::string& text, const std::string& key,
        const std::vector<std::string>& expected)
    {
        const std::string msg = ioErrorOf([&]
        {
            const dictionary d(dictOf(text));
            mpmMaterial::New("m", d);
        });
        EXPECT_NE(msg.find("'" + key + "'"), std::string::npos)
            << text << ": " << msg;
        for (const std::string& e : expected)
        {
            EXPECT_NE(msg.find(e), std::string::npos) << text << ": " << msg;
        }
    };

    check("type neoHookean; rho 1000; E -1e6; nu 0.3;", "E",
        {"-1e+06", "a finite number > 0"});
    check("type neoHookean; rho 1000; nu 0.3;", "E",
        {"missing", "a finite number > 0"});
    check("type neoHookean; rho 1000; E abc; nu 0.3;", "E",
        {"abc", "a finite number > 0"});
    check("type linearElastic; rho 1000; E 1e6; nu 0.5;", "nu",
        {"0.5", "-1 < nu < 0.5"});
    check("type linearElastic; rho 1000; E 1e6; nu 0.7;", "nu",
        {"0.7", "-1 < nu < 0.5"});
    check("type linearElastic; rho 1000; E 1e6; nu -1;", "nu",
        {"-1 < nu < 0.5"});
    check("type fixedCorotated; rho 0; E 1e6; nu 0.3;", "rho",
        {"a finite number > 1e-30"});
    // Values that overflow the wave speed or the stresses
    check("type neoHookean; rho 1000; E 1e300; nu 0.3;", "E",
        {"1e+300", "<= 1e+30"});
    check("type neoHookean; rho 1e300; E 1e6; nu 0.3;", "rho",
        {"1e+300", "<= 1e+30"});
    check("type neoHookean; rho 1e-200; E 1e6; nu 0.3;", "rho",
        {"1e-200", "> 1e-30"});
    check("type rubber; rho 1000; E 1e6; nu 0.3;", "type",
        {"rubber", "fixedCorotated", "linearElastic", "neoHookean"});
    check("rho 1000; E 1e6; nu 0.3;", "type",
        {"missing", "linearElastic"});
}


// An inverted (J < 0) or collapsed (J = 0) particle stops with a FatalError
// naming the particle's index and J, never a NaN stress
TEST(mpmMaterial, invertedParticleStops)
{
    const tensor inverted(-1, 0, 0, 0, 1, 0, 0, 0, 1);
    const tensor collapsed(1, 0, 0, 0, 0, 0, 0, 0, 1);
    for (const word& type : hyperelastic)
    {
        const auto m = material(type);
        for (const tensor& bad : {inverted, collapsed})
        {
            List<tensor> F(3, tensor::I);
            F[2] = bad;
            List<symmTensor> sigma(3);
            List<scalar> psi(3);
            const std::string msg = errorOf([&]{ m->stress(F, sigma, psi); });
            EXPECT_NE(msg.find("particle 2"), std::string::npos)
                << type << ": " << msg;
            EXPECT_NE(msg.find("J = det(F) = " + std::string(det(bad) < 0 ? "-1" : "0")),
                std::string::npos) << type << ": " << msg;
            EXPECT_NE(msg.find("J"), std::string::npos) << type << ": " << msg;
        }
    }
}


// ************************************************************************* //


// The wave speed of the current state: the reference speed at F = I (the
// time step of small-strain runs is unchanged), larger when stretched or
// crushed: the Kirchhoff P-wave modulus of each model, and an upper bound
// of the exact one (the Gershgorin bound of the largest stretch and the
// geometric |tau| term only add)
TEST(mpmMaterial, currentWaveSpeed)
{
    for (const word type : {"linearElastic", "neoHookean", "fixedCorotated"})
    {
        const auto m = material(type);
        List<tensor> F(2, tensor::I);
        List<symmTensor> sigma(2, symmTensor::zero);
        List<scalar> psi(2, scalar(0));
        m->stress(F, sigma, psi);
        EXPECT_DOUBLE_EQ(m->maxWaveSpeed(F, sigma), m->waveSpeed()) << type;

        // Stretched to J = 20 in the plane (plane strain, F_zz = 1)
        const scalar s = std::sqrt(20.0);
        F[1] = tensor(s, 0, 0, 0, s, 0, 0, 0, 1);
        m->stress(F, sigma, psi);
        const scalar c = m->maxWaveSpeed(F, sigma);
        EXPECT_TRUE(std::isfinite(c)) << type;
        EXPECT_GT(c, 2*m->waveSpeed()) << type;

        // The fastest particle sets it: the same as that particle alone
        List<tensor> F1(1, F[1]);
        List<symmTensor> sigma1(1, sigma[1]);
        EXPECT_DOUBLE_EQ(c, m->maxWaveSpeed(F1, sigma1)) << type;
    }

    // neoHookean, uniaxial stretch l: d tau/d ln l = 2 mu l^2 + lambda
    // exactly (diagonal F: Gershgorin is exact); plus J |sigma|
    const auto m = material("neoHookean");
    const scalar l = 1.5;
    List<tensor> F(1, tensor(l, 0, 0, 0, 1, 0, 0, 0, 1));
    List<symmTensor> sigma(1, symmTensor::zero);
    List<scalar> psi(1, scalar(0));
    m->stress(F, sigma, psi);
    const scalar tauMax = l*max(max(mag(sigma[0].xx()), mag(sigma[0].yy())),
        mag(sigma[0].zz()));
    const scalar K = 2*m->mu()*l*l + m->lambda() + tauMax;
    EXPECT_NEAR(m->maxWaveSpeed(F, sigma), std::sqrt(K/m->rho()),
        1e-12*std::sqrt(K/m->rho()));
}
