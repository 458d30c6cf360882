// Unit tests of inversionClamp, the treatment of inverted or collapsed
// particles (Irving et al. 2004: the sign-corrected SVD with its stretches
// clamped from below)
//  - the signed SVD reproduces F, with U and V orthonormal and the sign of
//    det F on one stretch, for random, inverted and crushed F in 3D, 2D, 1D
//  - a clamped F is a proper deformation with every solved stretch at or
//    above the floor, the other stretches and the rotation kept
//  - plane strain: F_zz = 1 and the out-of-plane zeros untouched
//  - an F with every stretch above the floor is left alone, bit for bit
//  - the neoHookean energy never grows under the clamp
//  - bad dictionaries stop with the entry named

#include "inversionClamp.H"
#include "mpmMaterial.H"
#include "testHelpers.H"

#include <gtest/gtest.h>
#include <algorithm>
#include <random>
#include <vector>

using namespace Foam;
using testHelpers::dictOf;
using testHelpers::ioErrorOf;

namespace
{

const tensor none3D(Zero);
const tensor offZ(0, 0, 0, 0, 0, 0, 0, 0, 1);
const tensor offYZ(0, 0, 0, 0, 1, 0, 0, 0, 1);

inversionClamp clampOf(const tensor& offAxes, const std::string& text = "")
{
    return inversionClamp(dictOf(text), offAxes);
}

tensor randomF(std::mt19937& gen, const tensor& offAxes, const scalar scale)
{
    std::uniform_real_distribution<scalar> u(-scale, scale);
    tensor F(I);
    for (direction r = 0; r < 3; ++r)
    {
        for (direction c = 0; c < 3; ++c)
        {
            if (offAxes(r, r) == 0 && offAxes(c, c) == 0) F(r, c) += u(gen);
        }
    }
    return F;
}

vector column(const tensor& T, const label i)
{
    return vector(T(0, i), T(1, i), T(2, i));
}

// The SVD's stretches in ascending order, solved axes only
List<scalar> solvedStretches(const inversionClamp& c, const tensor& F)
{
    tensor U, V;
    vector s;
    bool off[3];
    c.signedSVD(F, U, s, V, off);
    std::vector<scalar> out;
    for (label i = 0; i < 3; ++i)
    {
        if (!off[i]) out.push_back(s[i]);
    }
    std::sort(out.begin(), out.end());
    List<scalar> l(out.size());
    forAll(l, i) l[i] = out[i];
    return l;
}

} // End anonymous namespace


TEST(inversionClamp, signedSVDReproducesF)
{
    std::mt19937 gen(7);
    for (const tensor& off : {none3D, offZ, offYZ})
    {
        const inversionClamp c(clampOf(off));
        for (label k = 0; k < 2000; ++k)
        {
            // from mild to strongly inverted deformations
            const tensor F = randomF(gen, off, k < 1000 ? 0.5 : 3.0);
            tensor U, V;
            vector s;
            bool offAxis[3];
            c.signedSVD(F, U, s, V, offAxis);

            tensor R(Zero);
            for (label i = 0; i < 3; ++i) R += s[i]*(column(U, i)*column(V, i));
            EXPECT_LT(mag(R - F), 1e-11*(1 + mag(F)));
            EXPECT_LT(mag((U.T() & U) - tensor(I)), 1e-11);
            EXPECT_LT(mag((V.T() & V) - tensor(I)), 1e-11);
            // the sign of det F on the stretches, at most one negative,
            // and never on an unsolved axis
            const scalar J = det(F);
            EXPECT_NEAR(s[0]*s[1]*s[2], J, 1e-10*(1 + mag(F)*mag(F)*mag(F)));
            label nNeg = 0;
            for (label i = 0; i < 3; ++i)
            {
                if (s[i] < 0) ++nNeg;
                if (offAxis[i])
                {
                    EXPECT_DOUBLE_EQ(s[i], 1);
                }
            }
            EXPECT_LE(nNeg, 1);
        }
    }
}


TEST(inversionClamp, clampedIsProperAboveTheFloor)
{
    std::mt19937 gen(11);
    for (const tensor& off : {none3D, offZ, offYZ})
    {
        const inversionClamp c(clampOf(off));
        label nClamped = 0;
        for (label k = 0; k < 2000; ++k)
        {
            const tensor F0 = randomF(gen, off, 2.0);
            tensor F(F0);
            const List<scalar> s0 = solvedStretches(c, F0);
            const bool changed = c.apply(F);
            const List<scalar> s1 = solvedStretches(c, F);
            EXPECT_EQ(changed, s0[0] < c.minStretch());
            if (!changed)
            {
                EXPECT_EQ(F, F0);
                continue;
            }
            ++nClamped;
            EXPECT_GT(det(F), 0);
            EXPECT_GE(s1[0], c.minStretch() - 1e-12);
            // the stretches above the floor are kept
            for (label i = 0; i < s0.size(); ++i)
            {
                if (s0[i] >= c.minStretch())
                {
                    bool found = false;
                    for (const scalar t : s1)
                    {
                        if (mag(t - s0[i]) < 1e-10*(1 + s0[i])) found = true;
                    }
                    EXPECT_TRUE(found) << "stretch " << s0[i] << " lost";
                }
            }
            // the unsolved axes untouched, bit for bit
            for (direction r = 0; r < 3; ++r)
            {
                for (direction q = 0; q < 3; ++q)
                {
                    if (off(r, r) != 0 || off(q, q) != 0)
                    {
                        EXPECT_EQ(F(r, q), F0(r, q));
                    }
                }
            }
        }
        // the sample holds many inverted and collapsed F
        EXPECT_GT(nClamped, 200);
    }
}


TEST(inversionClamp, reflectionAndCrushedParticles)
{
    const inversionClamp c(clampOf(offZ));
    // a plane-strain reflection: every stretch 1, det -1
    tensor F(-1, 0, 0, 0, 1, 0, 0, 0, 1);
    EXPECT_TRUE(c.apply(F));
    EXPECT_NEAR(det(F), c.minStretch(), 1e-14);
    EXPECT_EQ(F.zz(), 1);

    // crushed to nothing along x, rotated by 30 degrees
    const scalar a = M_PI/6;
    const tensor Rot
    (
        std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1
    );
    tensor G(Rot & tensor(1e-9, 0, 0, 0, 1.5, 0, 0, 0, 1));
    EXPECT_TRUE(c.apply(G));
    const tensor expected(Rot & tensor(c.minStretch(), 0, 0, 0, 1.5, 0, 0, 0, 1));
    EXPECT_LT(mag(G - expected), 1e-12);

    // the zero tensor (in plane): any proper state at the floor
    tensor Z(0, 0, 0, 0, 0, 0, 0, 0, 1);
    EXPECT_TRUE(c.apply(Z));
    EXPECT_NEAR(det(Z), sqr(c.minStretch()), 1e-14);

    // 3D: a particle crushed to a line
    const inversionClamp c3(clampOf(none3D));
    tensor L(2, 0, 0, 0, 1e-12, 0, 0, 0, -1e-12);
    EXPECT_TRUE(c3.apply(L));
    EXPECT_NEAR(det(L), 2*sqr(c3.minStretch()), 1e-12);
}


TEST(inversionClamp, energyNeverGrows)
{
    // The clamp moves a crushed stretch towards the rest state: where the
    // clamped particle's J < 1 the neoHookean energy falls (dPsi/ds =
    // (mu (s^2 - 1) + lambda ln J)/s < 0 on the way), for every proper F0
    const dictionary d(dictOf("type neoHookean; rho 1000; E 1e6; nu 0.3;"));
    autoPtr<mpmMaterial> m(mpmMaterial::New("m", d));
    const inversionClamp c(clampOf(offZ));
    std::mt19937 gen(5);
    for (label k = 0; k < 500; ++k)
    {
        const tensor F0 = randomF(gen, offZ, 1.0);
        tensor F(F0);
        if (!c.apply(F) || !(det(F0) > 0) || det(F) >= 1) continue;
        List<tensor> Fl{F, F0};
        List<symmTensor> sigma(2, symmTensor::zero);
        List<scalar> psi(2, scalar(0));
        m->stress(Fl, sigma, psi);
        EXPECT_LE(psi[0], psi[1] + 1e-9*mag(psi[1]));
    }
}


TEST(inversionClamp, badDictionaries)
{
    auto msgOf = [](const std::string& text)
    {
        return ioErrorOf([&]() { inversionClamp c(dictOf(text), none3D); });
    };
    EXPECT_EQ(msgOf(""), "");
    EXPECT_EQ(msgOf("inversion { treatment stop; }"), "");
    EXPECT_NE(msgOf("inversion { treatment freeze; }").find("treatment"), std::string::npos);
    EXPECT_NE(msgOf("inversion { minStretch 1; }").find("minStretch"), std::string::npos);
    EXPECT_NE(msgOf("inversion { minStretch 0; }").find("minStretch"), std::string::npos);
    EXPECT_NE(msgOf("inversion { maxShare 2; }").find("maxShare"), std::string::npos);
    EXPECT_NE(msgOf("inversion clamp;").find("inversion"), std::string::npos);

    const inversionClamp s(dictOf("inversion { treatment stop; }"), none3D);
    EXPECT_FALSE(s.on());
    const inversionClamp d(dictOf(""), none3D);
    EXPECT_TRUE(d.on());
    EXPECT_EQ(d.minStretch(), 0.1);
    EXPECT_EQ(d.maxShare(), 0.01);
}
