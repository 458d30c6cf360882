// Unit tests of the elastoplastic MPM materials henckyJ2 and druckerPrager:
// one particle in homogeneous deformation, driven by increments of F as the
// MPM step applies them (F_trial = dF F_e, then the return mapping)
//  - henckyJ2 in uniaxial strain and pure shear (fixed principal axes)
//    against the analytic elastic-perfectly-plastic and softening curves
//  - henckyJ2 in simple shear (rotating axes) against a run with 100x
//    smaller increments; the yield function after every return; det F_p = 1;
//    objectivity under a superposed rotation; plane strain stays plane
//  - druckerPrager: cone and apex returns, the triaxial-compression peak
//    q/p = 6 sin(phi)/(3 - sin(phi)), the plastic volume in Jp
//  - particles inside the yield surface leave the return mapping untouched
//  - bad plastic parameters stop with a FatalIOError naming the entry

#include "mpmMaterial.H"
#include "henckyJ2.H"
#include "druckerPrager.H"
#include "henckyStrain.H"
#include "testHelpers.H"

#include <gtest/gtest.h>
#include <cmath>
#include <functional>
#include <iostream>
#include <random>
#include <vector>

using namespace Foam;
using testHelpers::dictOf;

namespace
{

// The clay of section 2.3.4, with nu = 0.3 (nu = 0.499 below where said)
const std::string clay =
    "type henckyJ2; rho 2150; E 25e6; nu 0.3; kappaP 40.82e3;"
    " kappaR 2.45e3; eta 5;";
const std::string clayPerfect =
    "type henckyJ2; rho 2150; E 25e6; nu 0.3; kappaP 40.82e3;";

autoPtr<mpmMaterial> material(const std::string& text)
{
    const dictionary d(dictOf(text));
    return mpmMaterial::New("m", d);
}

// One particle's state
struct particle
{
    tensor F = tensor::I;
    scalar epsP = 0;
    scalar Jp = 1;
    symmTensor sigma = symmTensor::zero;
    scalar psi = 0;
    bool returned = false;      //!< whether the last step changed F
};

// One step: F_trial = dF F_e, then return mapping and stress
void step(const mpmMaterial& m, particle& P, const tensor& dF)
{
    List<tensor> F(1, dF & P.F);
    List<scalar> epsP(1, P.epsP);
    List<scalar> Jp(1, P.Jp);
    List<symmTensor> sigma(1, symmTensor::zero);
    List<scalar> psi(1, scalar(0));
    const tensor Ftrial(F[0]);
    m.plasticStress(F, epsP, Jp, sigma, psi, true);
    P.returned = (F[0] != Ftrial);
    P.F = F[0];
    P.epsP = epsP[0];
    P.Jp = Jp[0];
    P.sigma = sigma[0];
    P.psi = psi[0];
}

// Kirchhoff stress tau = det(F_e) Jp sigma
symmTensor kirchhoff(const particle& P)
{
    return det(P.F)*P.Jp*P.sigma;
}

scalar qOf(const symmTensor& tau)
{
    return std::sqrt(1.5)*mag(dev(tau));
}

scalar pOf(const symmTensor& tau)
{
    return -tr(tau)/3;
}

// The equivalent plastic strain of a radial path with total equivalent
// trial stress qTot: the root of qTot - 3 mu x = kappa(x) (bisection to
// round-off; 0 while elastic)
scalar analyticEpsQ(const henckyJ2& m, const scalar qTot)
{
    if (qTot <= m.kappaP()) return 0;
    scalar lo = 0, hi = qTot/(3*m.mu());
    for (int i = 0; i < 200; ++i)
    {
        const scalar x = 0.5*(lo + hi);
        if (qTot - 3*m.mu()*x - m.kappa(x) > 0) lo = x; else hi = x;
    }
    return 0.5*(lo + hi);
}

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

// The largest yield function after a return, relative to kappa, and the
// largest |det F_e/det F_trial - 1| over all steps (henckyJ2)
struct returnChecks
{
    scalar fMax = 0;
    scalar detMax = 0;
    label nReturns = 0;

    void add(const henckyJ2& m, const particle& P, const tensor& Ftrial)
    {
        if (!P.returned) return;
        ++nReturns;
        const scalar k = m.kappa(P.epsP);
        fMax = max(fMax, mag(qOf(kirchhoff(P)) - k)/k);
        detMax = max(detMax, mag(det(P.F)/det(Ftrial) - 1));
        EXPECT_EQ(P.Jp, 1);
    }
};


// Radial paths with fixed principal axes: F = diag(l1(s), l2(s), l3(s)),
// s = 0..1 in n increments; returns the largest relative error of sigma
// and of eps_q against the analytic curve
void radialPath
(
    const henckyJ2& m,
    const std::function<vector(scalar)>& logStretch,
    const label n,
    scalar& errSigma,
    scalar& errEpsQ,
    scalar& epsQEnd,
    returnChecks& rc
)
{
    const scalar mu = m.mu();
    const scalar K = m.lambda() + 2*mu/3;
    particle P;
    vector epsPrev(Zero);
    errSigma = 0;
    errEpsQ = 0;
    for (label i = 1; i <= n; ++i)
    {
        const vector eps(logStretch(scalar(i)/n));
        const vector d(eps - epsPrev);
        epsPrev = eps;
        const tensor dF
        (
            std::exp(d.x()), 0, 0,
            0, std::exp(d.y()), 0,
            0, 0, std::exp(d.z())
        );
        const tensor Ftrial(dF & P.F);
        step(m, P, dF);
        rc.add(m, P, Ftrial);

        // Analytic: total deviatoric log strain e along a fixed direction,
        // q = q_tot - 3 mu eps_q = kappa(eps_q) once yielding
        const scalar trEps = eps.x() + eps.y() + eps.z();
        const vector e(eps - (trEps/3)*vector::one);
        const scalar qTot = std::sqrt(6.0)*mu*mag(e);
        const scalar epsQ = analyticEpsQ(m, qTot);
        const scalar q = qTot - 3*mu*epsQ;
        const vector tauP
        (
            K*trEps*vector::one
          + (mag(e) > 0 ? std::sqrt(2.0/3.0)*q/mag(e) : 0)*e
        );
        const symmTensor sigmaA
        (
            tauP.x(), 0, 0, tauP.y(), 0, tauP.z()
        );
        const symmTensor sigmaAn(sigmaA/std::exp(trEps));
        errSigma = max(errSigma, mag(P.sigma - sigmaAn)/mag(sigmaAn));
        errEpsQ = max
        (
            errEpsQ,
            mag(P.epsP - epsQ)/max(epsQ, m.kappaP()/(3*mu))
        );
        epsQEnd = P.epsP;
    }
}


// Simple shear F = I + gamma e_x e_y to gamma = 1 in increments dGamma,
// optionally with a superposed rotation R(t); the final state
particle simpleShear
(
    const mpmMaterial& m,
    const scalar dGamma,
    const std::function<tensor(scalar)>& R,
    returnChecks* rc = nullptr
)
{
    const label n = label(std::round(1/dGamma));
    particle P;
    P.F = R(0);
    for (label i = 0; i < n; ++i)
    {
        const tensor S(1, dGamma, 0, 0, 1, 0, 0, 0, 1);
        const scalar g0 = scalar(i)/n;
        const scalar g1 = scalar(i + 1)/n;
        const tensor dF(R(g1) & S & R(g0).T());
        const tensor Ftrial(dF & P.F);
        step(m, P, dF);
        if (rc) rc->add(refCast<const henckyJ2>(m), P, Ftrial);
    }
    return P;
}

tensor noRotation(scalar)
{
    return tensor::I;
}

} // End anonymous namespace


// The eigen-decomposition behind the log strains: exact reconstruction,
// orthonormal vectors, also for repeated and nearly equal eigenvalues
TEST(mpmPlasticity, jacobiEigenDecomposition)
{
    std::mt19937 gen(3);
    std::uniform_real_distribution<double> u(-1, 1);
    scalar errA = 0, errQ = 0;
    for (int t = 0; t < 200; ++t)
    {
        symmTensor A(u(gen), u(gen), u(gen), u(gen), u(gen), u(gen));
        if (t % 3 == 1) A = 1e-9*A + symmTensor::I;     // nearly equal
        if (t % 3 == 2) A = symmTensor(2, 0, 0, 2, 0, 1e-7*u(gen));
        vector d;
        tensor Q;
        henckyStrain::eigenSymm(A, d, Q);
        errA = max(errA, mag(henckyStrain::fromPrincipal(d, Q) - A)/mag(A));
        errQ = max(errQ, mag((Q.T() & Q) - tensor::I));
    }
    std::cout << "    Jacobi: |Q D Q^T - A|/|A| " << errA
        << ", |Q^T Q - I| " << errQ << std::endl;
    EXPECT_LT(errA, 1e-14);
    EXPECT_LT(errQ, 1e-14);
}


// Uniaxial strain F = diag(l, 1, 1), compressed to l = 0.5, and pure shear
// F = diag(l, 1/l, 1) to l = 1.6: the analytic curves of perfect plasticity
// and of the softening clay to 1e-8, for coarse and fine increments (the
// radial return is exact on a fixed-axes path)
TEST(mpmPlasticity, henckyJ2AnalyticCurves)
{
    const auto uniaxial = [](scalar s) { return vector(std::log(1 - 0.5*s), 0, 0); };
    const auto shear = [](scalar s)
    {
        const scalar l = std::log(1 + 0.6*s);
        return vector(l, -l, 0);
    };
    for (const std::string& text : {clayPerfect, clay})
    {
        const autoPtr<mpmMaterial> mp(material(text));
        const henckyJ2& m = refCast<const henckyJ2>(mp());
        for (const label n : {20, 400})
        {
            for (int path = 0; path < 2; ++path)
            {
                scalar eS = 0, eQ = 0, epsQ = 0;
                returnChecks rc;
                radialPath
                (
                    m, path == 0
                  ? std::function<vector(scalar)>(uniaxial)
                  : std::function<vector(scalar)>(shear),
                    n, eS, eQ, epsQ, rc
                );
                std::cout << "    henckyJ2 eta " << m.eta() << ", "
                    << (path == 0 ? "uniaxial strain" : "pure shear")
                    << ", " << n << " increments: max rel. error sigma "
                    << eS << ", eps_q " << eQ << " (final eps_q " << epsQ
                    << ", kappa " << m.kappa(epsQ) << "); " << rc.nReturns
                    << " returns, max |f|/kappa " << rc.fMax
                    << ", max |det F_p - 1| " << rc.detMax << std::endl;
                EXPECT_LT(eS, 1e-8);
                EXPECT_LT(eQ, 1e-8);
                EXPECT_GT(rc.nReturns, n/2);
                EXPECT_LT(rc.fMax, 1e-10);
                EXPECT_LT(rc.detMax, 1e-12);
                // The path reaches well into plasticity (softening: kappa
                // well below the peak)
                EXPECT_GT(epsQ, 0.2);
                if (m.eta() > 0)
                {
                    EXPECT_LT(m.kappa(epsQ), 0.5*m.kappaP());
                }
            }
        }
    }
}


// Simple shear (principal axes rotate): the final stress and eps_q
// converge to a run with 100x smaller increments than the finest, first
// order in the increment; yield function and det F_p after every return
TEST(mpmPlasticity, henckyJ2SimpleShearConverges)
{
    const autoPtr<mpmMaterial> mp(material(clay));
    const scalar dRef = 0.0025/100;
    const particle ref = simpleShear(mp(), dRef, noRotation);
    std::cout << "    simple shear to gamma = 1: reference (dGamma " << dRef
        << ") sigma_xy " << ref.sigma.xy() << " Pa, eps_q " << ref.epsP
        << std::endl;
    std::vector<scalar> errs;
    for (const scalar d : {0.02, 0.01, 0.005, 0.0025})
    {
        returnChecks rc;
        const particle P = simpleShear(mp(), d, noRotation, &rc);
        const scalar eS = mag(P.sigma - ref.sigma)/mag(ref.sigma);
        const scalar eQ = mag(P.epsP - ref.epsP)/ref.epsP;
        std::cout << "    dGamma " << d << ": rel. error sigma " << eS
            << ", eps_q " << eQ << "; max |f|/kappa " << rc.fMax
            << ", max |det F_p - 1| " << rc.detMax << std::endl;
        errs.push_back(eS);
        EXPECT_LT(rc.fMax, 1e-10);
        EXPECT_LT(rc.detMax, 1e-12);
    }
    // First order: each halving of the increment at least 1.6x closer
    for (size_t i = 1; i < errs.size(); ++i)
    {
        EXPECT_LT(errs[i], errs[i - 1]/1.6);
    }
    EXPECT_LT(errs.back(), 1e-2);
    EXPECT_GT(ref.epsP, 0.3);
}


// A rotation superposed on the simple-shear path (about a 3D axis, up to
// 2 rad) rotates the stress, sigma* = R sigma R^T, and leaves eps_q
TEST(mpmPlasticity, henckyJ2Objective)
{
    const autoPtr<mpmMaterial> mp(material(clay));
    const auto R = [](scalar s) { return rotation(vector(1, 2, 3), 2*s); };
    const particle P = simpleShear(mp(), 0.01, noRotation);
    const particle Pr = simpleShear(mp(), 0.01, R);
    const tensor R1(R(1));
    const symmTensor rotated(symm(R1 & tensor(P.sigma) & R1.T()));
    const scalar eS = mag(Pr.sigma - rotated)/mag(P.sigma);
    const scalar eQ = mag(Pr.epsP - P.epsP)/P.epsP;
    std::cout << "    superposed rotation: rel. error sigma " << eS
        << ", eps_q " << eQ << std::endl;
    // Round-off: F to 1e-16 relative, amplified by E/|sigma| ~ 1e4 (the
    // clay's stresses are 2e-4 E) over 100 steps; measured 3.2e-10
    EXPECT_LT(eS, 2e-9);
    EXPECT_LT(eQ, 1e-10);
}


// Plane strain: F_e keeps F_xz = F_yz = F_zx = F_zy = 0 exactly; the
// elastic stretch across the plane F_zz changes with the flow (shear with
// compression in the plane: the trial deviator has a zz part)
TEST(mpmPlasticity, planeStrainStaysPlane)
{
    const autoPtr<mpmMaterial> mp(material(clay));
    particle P;
    for (int i = 0; i < 100; ++i)
    {
        step(mp(), P, tensor(0.998, 0.01, 0, 0, 1, 0, 0, 0, 1));
    }
    EXPECT_GT(P.epsP, 0.1);
    EXPECT_EQ(P.F.xz(), 0);
    EXPECT_EQ(P.F.yz(), 0);
    EXPECT_EQ(P.F.zx(), 0);
    EXPECT_EQ(P.F.zy(), 0);
    EXPECT_EQ(P.sigma.xz(), 0);
    EXPECT_EQ(P.sigma.yz(), 0);
    EXPECT_GT(mag(P.F.zz() - 1), 1e-6);
}


// Inside the yield surface the return mapping leaves F, eps_q and Jp
// untouched (bit for bit), and the stress is the Hencky elastic one
TEST(mpmPlasticity, elasticParticlesNotReturned)
{
    for (const std::string& text :
        {clay, std::string("type druckerPrager; rho 1600; E 1e7; nu 0.3;"
            " frictionAngle 30; cohesion 1e3;")})
    {
        const autoPtr<mpmMaterial> mp(material(text));
        EXPECT_TRUE(mp->plastic());
        std::mt19937 gen(5);
        std::uniform_real_distribution<double> u(-1e-4, 1e-4);
        for (int t = 0; t < 100; ++t)
        {
            tensor dF(tensor::I);
            for (direction c = 0; c < 9; ++c) dF[c] += u(gen);
            dF = 0.998*dF;  // a little compression (inside the cone)
            particle P;
            P.epsP = 0.1;
            step(mp(), P, dF);
            EXPECT_FALSE(P.returned);
            EXPECT_EQ(P.epsP, 0.1);
            EXPECT_EQ(P.Jp, 1);
            EXPECT_TRUE(P.F == dF);

            List<tensor> Fl(1, dF);
            List<symmTensor> s(1);
            List<scalar> psi(1);
            mp->stress(Fl, s, psi);
            EXPECT_LT(mag(s[0] - P.sigma), 1e-12*mag(s[0]));
        }
    }

    // Elastic materials have no return mapping
    const autoPtr<mpmMaterial> nh
    (
        material("type neoHookean; rho 1000; E 1e6; nu 0.3;")
    );
    EXPECT_FALSE(nh->plastic());
}


// Drucker-Prager, triaxial compression: isotropic compression, then
// isochoric axial compression (lateral stretches equal: tau_2 = tau_3, the
// compression meridian): once yielding, q/p = 6 sin(phi)/(3 - sin(phi)) (c = 0) and
// q = M p + k (c > 0) to 1e-8; the plastic volume ln Jp = M_psi eps_q
TEST(mpmPlasticity, druckerPragerTriaxialPeak)
{
    for (const scalar phi : {20.0, 30.0, 40.0})
    {
        for (const scalar c : {0.0, 5e3})
        {
            const std::string text =
                "type druckerPrager; rho 1600; E 1e7; nu 0.3; frictionAngle "
              + std::to_string(phi) + "; dilatancyAngle "
              + std::to_string(phi/3) + "; cohesion " + std::to_string(c)
              + ";";
            const autoPtr<mpmMaterial> mp(material(text));
            const druckerPrager& m = refCast<const druckerPrager>(mp());
            const scalar s = std::sin(phi*M_PI/180);
            const scalar Mexact = 6*s/(3 - s);
            EXPECT_LT(mag(m.M() - Mexact), 1e-15);

            particle P;
            step(m, P, 0.99*tensor::I);
            EXPECT_FALSE(P.returned);
            scalar err = 0, errV = 0, errJ = 0;
            label nPlastic = 0;
            scalar Jtot = det(P.F);
            for (int i = 0; i < 200; ++i)
            {
                const scalar a = 0.998, r = 1/std::sqrt(a);
                const tensor dF(a, 0, 0, 0, r, 0, 0, 0, r);
                Jtot *= det(dF);
                step(m, P, dF);
                errJ = max(errJ, mag(det(P.F)*P.Jp/Jtot - 1));
                if (!P.returned) continue;
                ++nPlastic;
                const symmTensor tau(kirchhoff(P));
                EXPECT_LT(mag(tau.yy() - tau.zz()), 1e-9*mag(tau));
                const scalar q = qOf(tau), p = pOf(tau);
                err = max(err, mag(q - m.M()*p - m.k())/(m.M()*p + m.k()));
                errV = max(errV, mag(std::log(P.Jp) - m.Mpsi()*P.epsP));
            }
            const symmTensor tau(kirchhoff(P));
            std::cout << "    druckerPrager phi " << phi << ", c " << c
                << ": " << nPlastic << " plastic steps, q/p " << qOf(tau)/pOf(tau)
                << " (M " << Mexact << "), max |q - M p - k|/(M p + k) "
                << err << ", max |ln Jp - M_psi eps_q| " << errV
                << ", max |det(F_e) Jp/J - 1| " << errJ << std::endl;
            EXPECT_GT(nPlastic, 100);
            EXPECT_LT(err, 1e-8);
            EXPECT_LT(errV, 1e-12);
            EXPECT_LT(errJ, 1e-12);
            if (c == 0)
            {
                EXPECT_LT(mag(qOf(tau)/pOf(tau) - Mexact), 1e-8*Mexact);
            }
        }
    }
}


// Random trial states: every return lands on the cone (f = 0, q > 0) or at
// the apex (q = 0, p = -k/M); both occur; det(F_e) Jp is kept
TEST(mpmPlasticity, druckerPragerConeOrApex)
{
    for (const scalar c : {0.0, 2e4})
    {
        const autoPtr<mpmMaterial> mp
        (
            material
            (
                "type druckerPrager; rho 1600; E 1e7; nu 0.3;"
                " frictionAngle 35; dilatancyAngle 10; cohesion "
              + std::to_string(c) + ";"
            )
        );
        const druckerPrager& m = refCast<const druckerPrager>(mp());
        std::mt19937 gen(11);
        std::uniform_real_distribution<double> u(-0.02, 0.02);
        label nCone = 0, nApex = 0;
        scalar fMax = 0, apexErr = 0, jErr = 0;
        const scalar scale = m.E()*0.02;
        for (int t = 0; t < 2000; ++t)
        {
            tensor dF(tensor::I);
            for (direction k = 0; k < 9; ++k) dF[k] += u(gen);
            // Mostly compression, some tension
            dF *= 1 + 0.01*(u(gen) - 0.005);
            particle P;
            step(m, P, dF);
            jErr = max(jErr, mag(det(P.F)*P.Jp/det(dF) - 1));
            if (!P.returned) continue;
            const symmTensor tau(kirchhoff(P));
            const scalar q = qOf(tau), p = pOf(tau);
            if (q > 1e-9*scale)
            {
                ++nCone;
                fMax = max(fMax, mag(q - m.M()*p - m.k())/(m.M()*mag(p) + m.k()));
            }
            else
            {
                ++nApex;
                apexErr = max(apexErr, mag(p + m.k()/m.M())/scale);
            }
        }
        std::cout << "    druckerPrager c " << c << ": " << nCone
            << " cone returns (max |f|/(M|p| + k) " << fMax << "), " << nApex
            << " apex returns (max |p + k/M|/(0.02 E) " << apexErr
            << "), max |det(F_e) Jp/det F_trial - 1| " << jErr << std::endl;
        EXPECT_GT(nCone, 100);
        EXPECT_GT(nApex, 10);
        EXPECT_LT(fMax, 1e-10);
        EXPECT_LT(apexErr, 1e-12);
        EXPECT_LT(jErr, 1e-12);
    }
}


// Bad plastic parameters stop with a FatalIOError naming the entry
TEST(mpmPlasticity, badInputMessages)
{
    const auto check = [](const std::string& text, const std::string& key,
        const std::vector<std::string>& expected)
    {
        const std::string msg = testHelpers::ioErrorOf([&]
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
    const std::string j2 = "type henckyJ2; rho 2000; E 1e7; nu 0.3; ";
    check(j2, "kappaP", {"missing"});
    check(j2 + "kappaP -1;", "kappaP", {"-1", "> 0"});
    check(j2 + "kappaP 0;", "kappaP", {"> 0"});
    check(j2 + "kappaP 1e3; kappaR 2e3;", "kappaR", {"2000", "<= kappaP"});
    check(j2 + "kappaP 1e3; kappaR -1;", "kappaR", {"-1", ">= 0"});
    check(j2 + "kappaP 1e3; eta -5;", "eta", {"-5", ">= 0"});
    check(j2 + "kappaP 1e3; eta abc;", "eta", {"abc"});

    const std::string dp = "type druckerPrager; rho 2000; E 1e7; nu 0.3; ";
    check(dp, "frictionAngle", {"missing", "0 < frictionAngle < 90"});
    check(dp + "frictionAngle 0;", "frictionAngle", {"0 < frictionAngle < 90"});
    check(dp + "frictionAngle 90;", "frictionAngle", {"90"});
    check(dp + "frictionAngle -10;", "frictionAngle", {"-10"});
    check(dp + "frictionAngle 30; dilatancyAngle 35;", "dilatancyAngle",
        {"35", "<= frictionAngle (30)"});
    check(dp + "frictionAngle 30; dilatancyAngle -1;", "dilatancyAngle",
        {"-1", "0 <= dilatancyAngle"});
    check(dp + "frictionAngle 30; cohesion -100;", "cohesion",
        {"-100", ">= 0"});

    // F-bar switch, every material
    check(j2 + "kappaP 1e3; Fbar maybe;", "Fbar", {"maybe", "on or off"});
    check("type neoHookean; rho 1000; E 1e6; nu 0.3; Fbar 2;", "Fbar",
        {"on or off"});
    EXPECT_TRUE(material(j2 + "kappaP 1e3; Fbar on;")->Fbar());
    EXPECT_FALSE(material(j2 + "kappaP 1e3;")->Fbar());
}
