/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Description
    Smoothing kernels: normalisation over the support in 2D and 3D (1e-6),
    gradient antisymmetry and consistency with W, compact support,
    continuity at the cut-off, run-time selection and its errors.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testHelpers.H"
#include "smoothingKernel.H"
#include "mathematicalConstants.H"
#include <cmath>
#include <vector>
#include <random>

using namespace Foam;
using namespace Foam::meshless;

namespace
{

struct kernelCase
{
    std::string type;
    label dim;
};

std::ostream& operator<<(std::ostream& os, const kernelCase& k)
{
    return os << k.type << "_" << k.dim << "D";
}

autoPtr<smoothingKernel> makeKernel(const kernelCase& k, const scalar dx)
{
    dictionary dict = meshlessTest::dictFrom
    (
        "type " + k.type + "; smoothingLengthRatio 1.3;"
    );
    return smoothingKernel::New(dict, k.dim, dx);
}

//- Integral of W over its support by composite Simpson in r, split at the
//  integer q where the piecewise kernels have knots
scalar integrateOverSupport(const smoothingKernel& W)
{
    using constant::mathematical::pi;
    const scalar h = W.h();
    const label nPerUnit = 20000;
    scalar total = 0;
    for (scalar q0 = 0; q0 < W.qMax() - 1e-12; q0 += 1)
    {
        const scalar q1 = std::min(q0 + 1, W.qMax());
        const scalar a = q0*h;
        const scalar b = q1*h;
        const label n = 2*nPerUnit;
        const scalar dr = (b - a)/n;
        auto g = [&](scalar r)
        {
            const scalar shell = W.dim() == 2 ? 2*pi*r : 4*pi*r*r;
            // W at the right end of the support: the limit from inside
            const scalar rr = std::min(r, b*(1 - 1e-15));
            return W.W(rr)*shell;
        };
        scalar s = g(a) + g(b);
        for (label i = 1; i < n; ++i)
        {
            s += (i % 2 ? 4 : 2)*g(a + i*dr);
        }
        total += s*dr/3;
    }
    return total;
}

} // End anonymous namespace


class kernelTest : public ::testing::TestWithParam<kernelCase> {};

TEST_P(kernelTest, normalisedOverTheSupport)
{
    for (const scalar dx : {1e-3, 0.05, 1.0})
    {
        autoPtr<smoothingKernel> W = makeKernel(GetParam(), dx);
        EXPECT_NEAR(integrateOverSupport(W()), 1.0, 1e-6) << "dx " << dx;
    }
}


TEST_P(kernelTest, gradientIsAntisymmetricAndConsistentWithW)
{
    autoPtr<smoothingKernel> W = makeKernel(GetParam(), 0.01);
    const label dim = GetParam().dim;
    std::mt19937_64 gen(11);
    std::uniform_real_distribution<double> u(-W->radius(), W->radius());

    for (label k = 0; k < 1000; ++k)
    {
        double xi[3] = {u(gen), u(gen), dim == 3 ? u(gen) : 0.0};
        double xj[3] = {u(gen), u(gen), dim == 3 ? u(gen) : 0.0};
        double rij[3], rji[3];
        double r2 = 0;
        for (label d = 0; d < 3; ++d)
        {
            rij[d] = xi[d] - xj[d];
            rji[d] = xj[d] - xi[d];
            r2 += rij[d]*rij[d];
        }
        const double r = std::sqrt(r2);
        for (label d = 0; d < dim; ++d)
        {
            const double gi = W->gradFactor(r)*rij[d];
            const double gj = W->gradFactor(r)*rji[d];
            EXPECT_EQ(gi, -gj);
        }

        // dW/dr against a central difference of W, inside the support
        if (r > 1e-3*W->h() && r < W->radius()*(1 - 1e-3))
        {
            const double e = 1e-6*W->h();
            const double fd = (W->W(r + e) - W->W(r - e))/(2*e);
            const double scale = std::abs(W->dWdr(r)) + W->W(0)/W->h()*1e-6;
            EXPECT_NEAR(W->dWdr(r), fd, 1e-5*scale) << "r/h " << r/W->h();
        }
    }
}


TEST_P(kernelTest, compactSupport)
{
    autoPtr<smoothingKernel> W = makeKernel(GetParam(), 0.02);
    const scalar R = W->radius();
    EXPECT_NEAR(R, W->qMax()*1.3*0.02, 1e-15);
    for (const scalar f : {1.0, 1.0 + 1e-12, 1.5, 10.0})
    {
        EXPECT_EQ(W->W(f*R), 0.0);
        EXPECT_EQ(W->dWdr(f*R), 0.0);
    }
    for (const scalar f : {0.0, 0.3, 0.9, 0.999})
    {
        EXPECT_GT(W->W(f*R), 0.0) << f;
    }
    // Monotone decreasing over the support
    scalar prev = W->W(0);
    for (label k = 1; k <= 1000; ++k)
    {
        const scalar w = W->W(k*R/1000);
        EXPECT_LE(w, prev);
        prev = w;
    }
}


TEST_P(kernelTest, smoothAtTheCutOff)
{
    autoPtr<smoothingKernel> W = makeKernel(GetParam(), 0.02);
    const scalar R = W->radius();
    const scalar rIn = R*(1 - 1e-9);
    // W tends to 0 at the cut-off (continuity): 1e-9 inside, W is below
    // slope x distance, ~2e-12 W(0) for the Gaussian, far less for the others
    EXPECT_LT(W->W(rIn), 1e-10*W->W(0));

    // The slope tends to 0 too, relative to the largest slope. The Wendland
    // and cubic spline kernels are C1 and C2 there; the ULPH Gaussian
    // (eq. 17) is only C0: its slope jumps by 2 Q exp(-Q^2) = 7.4e-4 at the
    // horizon Q = 3, 0.09 % of its peak slope sqrt(2/e).
    scalar maxSlope = 0;
    for (label k = 0; k <= 10000; ++k)
    {
        maxSlope = std::max(maxSlope, std::abs(W->dWdr(k*R/10000)));
    }
    const scalar tol = GetParam().type == "gaussian" ? 1e-3 : 1e-12;
    EXPECT_LT(std::abs(W->dWdr(rIn)), tol*maxSlope);
}


TEST_P(kernelTest, evaluateOfManyEqualsWAndDWdr)
{
    // The relations' geometry evaluates a particle's distances in one call:
    // the same values as W and dWdr, to the bit, in and beyond the support
    autoPtr<smoothingKernel> W = makeKernel(GetParam(), 0.02);
    const scalar R = W->radius();
    std::vector<double> r;
    for (label k = 0; k <= 400; ++k) r.push_back(k*1.2*R/400);
    r.push_back(R);
    const label n = r.size();
    std::vector<double> w(n, -1), dw(n, -1), wOnly(n, -1), dwOnly(n, -1);
    W->evaluate(r.data(), n, w.data(), dw.data());
    W->evaluate(r.data(), n, wOnly.data(), nullptr);
    W->evaluate(r.data(), n, nullptr, dwOnly.data());
    for (label k = 0; k < n; ++k)
    {
        EXPECT_EQ(w[k], W->W(r[k])) << r[k];
        EXPECT_EQ(dw[k], W->dWdr(r[k])) << r[k];
        EXPECT_EQ(wOnly[k], w[k]);
        EXPECT_EQ(dwOnly[k], dw[k]);
    }
    EXPECT_EQ(w[n - 1], 0.0);
    EXPECT_GT(w[0], 0.0);
}


INSTANTIATE_TEST_SUITE_P
(
    kernels,
    kernelTest,
    ::testing::Values
    (
        kernelCase{"wendlandC2", 2}, kernelCase{"wendlandC2", 3},
        kernelCase{"cubicSpline", 2}, kernelCase{"cubicSpline", 3},
        kernelCase{"gaussian", 2}, kernelCase{"gaussian", 3}
    ),
    [](const ::testing::TestParamInfo<kernelCase>& info)
    {
        return info.param.type + std::to_string(info.param.dim) + "D";
    }
);


TEST(kernel, gaussianMatchesThePapersNormalisationIn2D)
{
    // ULPH paper eq. 18: alpha_2 = 1/(h^2 pi (1 - 10 e^-9)) for horizon 3h
    using constant::mathematical::pi;
    dictionary dict =
        meshlessTest::dictFrom("type gaussian; smoothingLength 0.5;");
    autoPtr<smoothingKernel> W = smoothingKernel::New(dict, 2, 1.0);
    const scalar h = 0.5;
    const scalar alpha = 1/(h*h*pi*(1 - 10*std::exp(-9.0)));
    EXPECT_NEAR(W->W(0), alpha*(1 - std::exp(-9.0)), 1e-14*alpha);
    EXPECT_DOUBLE_EQ(W->radius(), 1.5);
}


TEST(kernel, gaussianHorizonFromTheDictionary)
{
    dictionary dict = meshlessTest::dictFrom
    (
        "type gaussian; smoothingLength 1; horizon 2.5;"
    );
    autoPtr<smoothingKernel> W = smoothingKernel::New(dict, 3, 1.0);
    EXPECT_DOUBLE_EQ(W->radius(), 2.5);
    EXPECT_NEAR(integrateOverSupport(W()), 1.0, 1e-6);
}


TEST(kernel, unknownTypeListsTheValidNames)
{
    const std::string msg = meshlessTest::fatalMessage([]
    {
        dictionary d = meshlessTest::dictFrom
        (
            "type quintic; smoothingLengthRatio 1.2;"
        );
        smoothingKernel::New(d, 2, 0.01);
    });
    EXPECT_NE(msg.find("IOerror"), std::string::npos) << msg;
    EXPECT_NE(msg.find("quintic"), std::string::npos) << msg;
    for (const char* name : {"wendlandC2", "cubicSpline", "gaussian"})
    {
        EXPECT_NE(msg.find(name), std::string::npos) << msg;
    }
}


TEST(kernel, badSmoothingLengthIsAnIOError)
{
    const std::string missing = meshlessTest::fatalMessage([]
    {
        dictionary d = meshlessTest::dictFrom("type wendlandC2;");
        smoothingKernel::New(d, 2, 0.01);
    });
    EXPECT_NE(missing.find("smoothingLengthRatio"), std::string::npos)
        << missing;

    const std::string negative = meshlessTest::fatalMessage([]
    {
        dictionary d =
            meshlessTest::dictFrom("type wendlandC2; smoothingLength -1;");
        smoothingKernel::New(d, 2, 0.01);
    });
    EXPECT_NE(negative.find("smoothingLength"), std::string::npos) << negative;
    EXPECT_NE(negative.find("> 0"), std::string::npos) << negative;
}
