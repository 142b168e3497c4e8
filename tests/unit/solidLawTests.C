/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Description
    Constitutive laws of the NOSB-PD solid: the Hughes-Winget update is
    objective (a pure rotation creates no stress and carries a prestress
    along as Q sigma Q^T), hypoelastic gives linear elasticity for a small
    strain in 3D, plane strain and plane stress, and the Drucker-Prager
    return mapping lands on the yield surface (cone and apex) and leaves
    admissible states alone, follows the closed form of the flow rule with
    dilation, keeps a plane strain particle admissible along a long path of
    stretch, shear and rotation, and carries a yielded state through a
    rigid rotation without further flow.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testHelpers.H"
#include "hughesWinget.H"
#include "druckerPrager.H"
#include "mathematicalConstants.H"
#include <random>

using namespace Foam;
using namespace Foam::meshless;

namespace
{

//- Rotation by angle about a unit axis (Rodrigues)
tensor rotation(const vector& axis, const scalar angle)
{
    const vector k = axis/mag(axis);
    const tensor Kx(0, -k.z(), k.y(), k.z(), 0, -k.x(), -k.y(), k.x(), 0);
    return tensor::I + std::sin(angle)*Kx + (1 - std::cos(angle))*(Kx & Kx);
}

scalar maxAbs(const tensor& T)
{
    return cmptMax(cmptMag(T));
}

autoPtr<constitutiveLaw> law
(
    particleSet& set,
    const std::string& entries
)
{
    return constitutiveLaw::New
    (
        meshlessTest::dictFrom("constitutiveLaw { " + entries + " }"),
        set.dim(),
        set
    );
}

//- Stored Cauchy stress of particle i (3D set)
tensor storedSigma(const particleSet& set, const label i)
{
    tensor s;
    for (direction c = 0; c < 9; ++c) s[c] = set.field("sigma")(i, c);
    return s;
}

} // End anonymous namespace


TEST(hughesWinget, rotationGivesNoStrainAndTheRotation)
{
    const tensor Q = rotation(vector(1, 2, 3), 0.7);
    const hughesWinget::increment inc = hughesWinget::update(tensor::I, Q);
    EXPECT_LT(maxAbs(inc.gamma), 1e-14);
    EXPECT_LT(maxAbs(inc.R - Q), 1e-14);
}


TEST(hypoelastic, pureRotationIsStressFree)
{
    // 90 degrees in 9 steps about a skew axis, from a stress-free state
    particleSet set("solid", 3);
    set.resize(1);
    autoPtr<constitutiveLaw> L = law(set, "type hypoelastic; E 2e11; nu 0.3;");
    const vector axis(0.3, -1, 0.4);
    tensor Fold(tensor::I);
    for (label k = 1; k <= 9; ++k)
    {
        const tensor F = rotation(axis, k*constant::mathematical::pi/18);
        EXPECT_LT(maxAbs(L->stress(0, Fold, F)), 1e-13*2e11);
        L->commit(0, Fold, F);
        Fold = F;
    }
    EXPECT_LT(maxAbs(storedSigma(set, 0)), 1e-13*2e11);
}


TEST(hypoelastic, rotationCarriesAPrestress)
{
    particleSet set("solid", 3);
    set.resize(1);
    autoPtr<constitutiveLaw> L = law(set, "type hypoelastic; E 2e11; nu 0.3;");
    const tensor sigma0(3e6, 1e6, -2e6, 1e6, -4e6, 0.5e6, -2e6, 0.5e6, 1e6);
    for (direction c = 0; c < 9; ++c) set.field("sigma")(0, c) = sigma0[c];

    const tensor Q = rotation(vector(0, 0.2, 1), 1.1);
    const tensor expect = Q & sigma0 & Q.T();
    // P = J sigma F^-T with J = 1, F^-T = Q
    EXPECT_LT(maxAbs(L->stress(0, tensor::I, Q) - (expect & Q)), 1e-9*4e6);
    L->commit(0, tensor::I, Q);
    EXPECT_LT(maxAbs(storedSigma(set, 0) - expect), 1e-9*4e6);
}


TEST(hypoelastic, smallStrainIsLinearElasticity)
{
    const scalar E = 1e9, nu = 0.3, e = 1e-6;
    const scalar G = E/(2*(1 + nu)), lambda = 2*G*nu/(1 - 2*nu);
    const tensor H(e, 0.4*e, 0, 0.4*e, -0.5*e, 0, 0, 0, 0);

    // plane strain: sigma_zz = lambda tr(eps); plane stress: 0 and the
    // in-plane lambda* = 2 lambda G/(lambda + 2G)
    for (const word plane : {"strain", "stress"})
    {
        particleSet set("solid", 2);
        set.resize(1);
        autoPtr<constitutiveLaw> L =
            law(set, "type hypoelastic; E 1e9; nu 0.3; plane " + plane + ";");
        L->commit(0, tensor::I, tensor::I + H);
        const particleField& s = set.field("sigma");
        const scalar lp =
            plane == "strain" ? lambda : 2*lambda*G/(lambda + 2*G);
        const scalar tol = 1e-5*E*e;
        EXPECT_NEAR(s(0, 0), lp*0.5*e + 2*G*e, tol) << plane;
        EXPECT_NEAR(s(0, 1), 2*G*0.4*e, tol) << plane;
        EXPECT_NEAR(s(0, 3), lp*0.5*e - G*e, tol) << plane;
        EXPECT_NEAR
        (
            set.field("sigmaZZ")(0, 0),
            plane == "strain" ? lambda*0.5*e : 0,
            tol
        ) << plane;
    }
}


TEST(druckerPrager, returnMappingStaysOnTheYieldSurface)
{
    // Paper Table 4: E 30 MPa, nu 0.25, phi 13, c 5 kPa, psi 0
    const label n = 400;
    particleSet set("soil", 3);
    set.resize(n);
    autoPtr<constitutiveLaw> L = law
    (
        set,
        "type druckerPrager; E 30e6; nu 0.25; frictionAngle 13;"
        " cohesion 5e3; dilationAngle 0;"
    );
    const auto& dp = dynamic_cast<const constitutiveLaws::druckerPrager&>(L());
    const scalar kc = dp.cohesionTerm();

    std::mt19937 gen(7);
    std::uniform_real_distribution<scalar> u(-1, 1);
    label nElastic = 0, nPlastic = 0, nApex = 0;
    for (label i = 0; i < n; ++i)
    {
        // Strain steps from 1e-6 (elastic) to 1e-2 (far beyond yield)
        const scalar size = std::pow(10, -6 + 4*(0.5*u(gen) + 0.5));
        tensor H;
        for (direction c = 0; c < 9; ++c) H[c] = size*u(gen);
        H = symm(H);
        const tensor F = tensor::I + H;

        // The elastic trial of this step from a stress-free state
        particleSet probe("probe", 3);
        probe.resize(1);
        autoPtr<constitutiveLaw> elastic =
            law(probe, "type hypoelastic; E 30e6; nu 0.25;");
        elastic->commit(0, tensor::I, F);
        const tensor trial = storedSigma(probe, 0);

        L->commit(i, tensor::I, F);
        const tensor s = storedSigma(set, i);
        const scalar ep = set.field("plasticStrain")(i, 0);
        if (dp.yieldFunction(trial) <= 0)
        {
            ++nElastic;
            EXPECT_LT(maxAbs(s - trial), 1e-12*maxAbs(trial));
            EXPECT_EQ(ep, 0);
        }
        else
        {
            const tensor d = dev(s);
            std::sqrt(0.5*(d && d)) < 1e-9*kc ? ++nApex : ++nPlastic;
            EXPECT_NEAR(dp.yieldFunction(s), 0, 1e-9*kc);
            EXPECT_GT(ep, 0);
            // psi = 0: no plastic volume change, so I1 keeps its trial value
            // on the cone
            if (std::sqrt(0.5*(d && d)) > 1e-9*kc)
            {
                EXPECT_NEAR(tr(s), tr(trial), 1e-9*kc);
            }
        }
    }
    // The sample covers all three cases
    EXPECT_GT(nElastic, 20);
    EXPECT_GT(nPlastic, 20);
    EXPECT_GT(nApex, 5);
}


TEST(druckerPrager, dilatantReturnFollowsTheFlowRule)
{
    // psi > 0: the closed form sigma = trial - dLambda (G s/q + 3 K a_psi I)
    // with dLambda = f_trial/(G + 9 K a_phi a_psi) lands on f = 0, and the
    // plastic volume change is 9 K a_psi dLambda in I1; beyond the apex
    // (q_trial <= G dLambda) it returns to the apex I1 = k_c/a_phi
    const scalar E = 30e6, nu = 0.25;
    const scalar G = E/(2*(1 + nu)), K = E/(3*(1 - 2*nu));
    const scalar deg = constant::mathematical::pi/180;
    auto slope = [](const scalar a)
    {
        const scalar t = std::tan(a);
        return t/std::sqrt(9 + 12*t*t);
    };
    const scalar aPhi = slope(30*deg), aPsi = slope(10*deg);

    const label n = 300;
    particleSet set("soil", 3);
    set.resize(n);
    autoPtr<constitutiveLaw> L = law
    (
        set,
        "type druckerPrager; E 30e6; nu 0.25; frictionAngle 30;"
        " cohesion 5e3; dilationAngle 10;"
    );
    const auto& dp = dynamic_cast<const constitutiveLaws::druckerPrager&>(L());
    const scalar kc = dp.cohesionTerm();

    std::mt19937 gen(11);
    std::uniform_real_distribution<scalar> u(-1, 1);
    label nCone = 0, nApex = 0;
    for (label i = 0; i < n; ++i)
    {
        const scalar size = std::pow(10, -5 + 3*(0.5*u(gen) + 0.5));
        tensor H;
        for (direction c = 0; c < 9; ++c) H[c] = size*u(gen);
        H = symm(H);
        const tensor F = tensor::I + H;

        particleSet probe("probe", 3);
        probe.resize(1);
        autoPtr<constitutiveLaw> elastic =
            law(probe, "type hypoelastic; E 30e6; nu 0.25;");
        elastic->commit(0, tensor::I, F);
        const tensor trial = storedSigma(probe, 0);
        const scalar fTrial = dp.yieldFunction(trial);
        if (fTrial <= 0) continue;

        L->commit(i, tensor::I, F);
        const tensor s = storedSigma(set, i);
        const tensor st = dev(trial);
        const scalar qt = std::sqrt(0.5*(st && st));
        const scalar dLambda = fTrial/(G + 9*K*aPhi*aPsi);
        if (qt - G*dLambda > 0)
        {
            ++nCone;
            const tensor expect =
                trial - dLambda*(G/qt*st + 3*K*aPsi*tensor::I);
            EXPECT_LT(maxAbs(s - expect), 1e-9*maxAbs(trial));
            EXPECT_NEAR(tr(trial) - tr(s), 9*K*aPsi*dLambda, 1e-9*kc);
            EXPECT_NEAR(dp.yieldFunction(s), 0, 1e-9*kc);
        }
        else
        {
            ++nApex;
            EXPECT_LT(maxAbs(s - kc/(3*aPhi)*tensor::I), 1e-9*kc);
        }
    }
    EXPECT_GT(nCone, 20);
    EXPECT_GT(nApex, 5);
}


TEST(druckerPrager, planeStrainPathStaysOnOrInsideTheCone)
{
    // A 2D plane strain particle through 400 random steps of stretch,
    // shear and rotation, loaded far beyond yield (the baffle's root): the
    // committed stress (with sigma_zz) is admissible after every step, on
    // the yield surface whenever the step flowed, and the plastic strain
    // never decreases
    particleSet set("soil", 2);
    set.resize(1);
    autoPtr<constitutiveLaw> L = law
    (
        set,
        "type druckerPrager; E 30e6; nu 0.25; plane strain;"
        " frictionAngle 13; cohesion 5e3; dilationAngle 0;"
    );
    const auto& dp = dynamic_cast<const constitutiveLaws::druckerPrager&>(L());
    const scalar kc = dp.cohesionTerm();
    const particleField& sig = set.field("sigma");
    const particleField& ep = set.field("plasticStrain");
    auto cauchy = [&]()
    {
        return tensor
        (
            sig(0, 0), sig(0, 1), 0,
            sig(0, 2), sig(0, 3), 0,
            0, 0, set.field("sigmaZZ")(0, 0)
        );
    };

    std::mt19937 gen(3);
    std::uniform_real_distribution<scalar> u(-1, 1);
    tensor Fold(tensor::I);
    label nFlow = 0;
    for (label k = 0; k < 400; ++k)
    {
        // Increment of up to 2e-3 (E eps ~ 12 c): many steps flow
        const tensor Q = rotation(vector(0, 0, 1), 0.02*u(gen));
        tensor H(Zero);
        H.xx() = 2e-3*u(gen);
        H.xy() = 2e-3*u(gen);
        H.yx() = 2e-3*u(gen);
        H.yy() = 2e-3*u(gen);
        const tensor F = (Q & (tensor::I + H)) & Fold;
        const scalar ep0 = ep(0, 0);

        L->commit(0, Fold, F);
        const tensor s = cauchy();
        EXPECT_LE(dp.yieldFunction(s), 1e-9*kc) << "step " << k;
        EXPECT_GE(ep(0, 0), ep0);
        if (ep(0, 0) > ep0)
        {
            ++nFlow;
            EXPECT_NEAR(dp.yieldFunction(s), 0, 1e-9*kc) << "step " << k;
        }
        Fold = F;
    }
    EXPECT_GT(nFlow, 50);
}


TEST(druckerPrager, rotationOfAYieldedStateIsObjective)
{
    // Yield in simple shear, then rotate rigidly in steps: the stress is
    // carried as Q sigma Q^T, stays on the yield surface and the plastic
    // strain does not grow
    particleSet set("soil", 3);
    set.resize(1);
    autoPtr<constitutiveLaw> L = law
    (
        set,
        "type druckerPrager; E 30e6; nu 0.25; frictionAngle 13;"
        " cohesion 5e3; dilationAngle 0;"
    );
    const auto& dp = dynamic_cast<const constitutiveLaws::druckerPrager&>(L());
    const scalar kc = dp.cohesionTerm();
    const tensor F0(1, 2e-3, 0, 0, 1, 0, 0, 0, 1);
    L->commit(0, tensor::I, F0);
    const tensor sigma0 = storedSigma(set, 0);
    const scalar ep0 = set.field("plasticStrain")(0, 0);
    ASSERT_GT(ep0, 0);
    ASSERT_NEAR(dp.yieldFunction(sigma0), 0, 1e-9*kc);

    tensor Fold = F0;
    const vector axis(0.2, -0.5, 1);
    for (label k = 1; k <= 12; ++k)
    {
        const tensor F = rotation(axis, k*constant::mathematical::pi/24) & F0;
        L->commit(0, Fold, F);
        Fold = F;
    }
    const tensor Q = rotation(axis, constant::mathematical::pi/2);
    EXPECT_LT(maxAbs(storedSigma(set, 0) - (Q & sigma0 & Q.T())), 1e-9*kc);
    EXPECT_NEAR(dp.yieldFunction(storedSigma(set, 0)), 0, 1e-9*kc);
    EXPECT_NEAR(set.field("plasticStrain")(0, 0), ep0, 1e-15);
}


TEST(druckerPrager, badInputNamesTheKeyword)
{
    particleSet set("soil", 2);
    set.resize(1);
    const std::string planeStress = meshlessTest::fatalMessage([&]
    {
        law(set, "type druckerPrager; E 30e6; nu 0.25; plane stress;"
            " frictionAngle 13; cohesion 5e3; dilationAngle 0;");
    });
    EXPECT_NE(planeStress.find("plane stress"), std::string::npos) << planeStress;

    const std::string angle = meshlessTest::fatalMessage([&]
    {
        law(set, "type druckerPrager; E 30e6; nu 0.25; plane strain;"
            " frictionAngle 95; cohesion 5e3; dilationAngle 0;");
    });
    EXPECT_NE(angle.find("'frictionAngle'"), std::string::npos) << angle;

    const std::string dilation = meshlessTest::fatalMessage([&]
    {
        law(set, "type druckerPrager; E 30e6; nu 0.25; plane strain;"
            " frictionAngle 13; cohesion 5e3; dilationAngle 20;");
    });
    EXPECT_NE(dilation.find("'dilationAngle'"), std::string::npos) << dilation;
}


// ************************************************************************* //
