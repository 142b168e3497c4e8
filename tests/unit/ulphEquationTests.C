/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Description
    ULPH fluid equations: the pair force of the momentum equation (eq. 23)
    conserves linear momentum to round-off in a closed box without walls
    (random positions, pressures, viscous stresses); the Tait equation of
    state and its inverse; the continuity equation's rate for a uniform
    expansion; the viscous stress of a simple shear.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testHelpers.H"
#include "ulphEquations.H"
#include <random>

using namespace Foam;
using namespace Foam::meshless;

namespace
{

template<int Dim>
struct blob
{
    label n;
    std::vector<double> x, V, rho, m;
    autoPtr<smoothingKernel> W;
    cellLinkedList cells;
    neighbourList list;
    std::vector<neighbourSource> sources;
    particleField Minv;

    blob(const label perSide, const double dx, const double jitter)
    :
        n(0),
        W(smoothingKernel::New
        (
            meshlessTest::dictFrom("type gaussian; smoothingLengthRatio 1.2;"),
            Dim, dx
        )),
        cells(Dim, W->radius()),
        Minv("Minv", particleField::kind::tensor, Dim)
    {
        x = meshlessTest::latticePoints(Dim, perSide, dx);
        n = label(x.size())/Dim;
        std::mt19937_64 gen(5);
        std::uniform_real_distribution<double> u(-1, 1);
        for (auto& v : x) v += jitter*dx*u(gen);
        const double V0 = Dim == 2 ? dx*dx : dx*dx*dx;
        for (label i = 0; i < n; ++i)
        {
            rho.push_back(1000*(1 + 0.01*u(gen)));
            V.push_back(V0*(1 + 0.05*u(gen)));
            m.push_back(rho.back()*V.back());
        }
        cells.build(x.data(), n);
        list.build(cells, x.data(), n, true);
        sources = {{&list, x.data(), V.data()}};
        Minv.resize(n);
        ulphOperators::shapeTensorInverse<Dim>(x.data(), n, sources, *W, Minv);
    }
};


template<int Dim>
void expectMomentumConserved()
{
    blob<Dim> b(Dim == 2 ? 20 : 8, 0.01, 0.3);
    std::mt19937_64 gen(9);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<double> p(b.n), tau(b.n*Dim*Dim), S(b.n*Dim*Dim);
    for (auto& v : p) v = 1e4*u(gen);
    for (label i = 0; i < b.n; ++i)
    {
        // A symmetric viscous stress
        for (label a = 0; a < Dim; ++a)
            for (label c = a; c < Dim; ++c)
            {
                const double v = 10*u(gen);
                tau[i*Dim*Dim + a*Dim + c] = v;
                tau[i*Dim*Dim + c*Dim + a] = v;
            }
    }
    ulphEquations::stressTimesMinv<Dim>
    (
        b.n, p.data(), tau.data(), b.Minv.data(), S.data()
    );
    std::vector<double> dU(b.n*Dim);
    ulphEquations::momentum<Dim>
    (
        b.n, b.x.data(), b.rho.data(), S.data(), b.sources, {S.data()}, *b.W,
        dU.data()
    );

    double total[3] = {0, 0, 0}, scale = 0;
    for (label i = 0; i < b.n; ++i)
    {
        for (label d = 0; d < Dim; ++d)
        {
            total[d] += b.m[i]*dU[i*Dim + d];
            scale += std::abs(b.m[i]*dU[i*Dim + d]);
        }
    }
    ASSERT_GT(scale, 0);
    for (label d = 0; d < Dim; ++d)
    {
        EXPECT_LT(std::abs(total[d]), 1e-12*scale) << "component " << d;
    }
}

} // End anonymous namespace


TEST(ulphEquations, pairForceConservesMomentum2D)
{
    expectMomentumConserved<2>();
}

TEST(ulphEquations, pairForceConservesMomentum3D)
{
    expectMomentumConserved<3>();
}


TEST(ulphEquations, taitEquationOfState)
{
    // 1 % compression of water with c0 = 40: p = c0^2 rho0/7 (1.01^7 - 1)
    const double p = ulphEquations::taitPressure(1010, 1000, 40, 7);
    EXPECT_NEAR(p, 1600*1000/7.0*(std::pow(1.01, 7) - 1), 1e-9);
    EXPECT_NEAR(ulphEquations::taitDensity(p, 1000, 40, 7), 1010, 1e-9);
    EXPECT_EQ(ulphEquations::taitPressure(1000, 1000, 40, 7), 0);
    // Small compressions: p ~ c0^2 (rho - rho0)
    EXPECT_NEAR(ulphEquations::taitPressure(1000.001, 1000, 40, 7), 1.6, 1e-5);
}


TEST(ulphEquations, continuityOfAUniformExpansion)
{
    // u = e x: div u = 2e in 2D, so Drho/Dt = -2 e rho at every particle
    blob<2> b(16, 0.01, 0.2);
    const double e = 0.3;
    std::vector<double> U(b.x.size()), drho(b.n);
    for (size_t k = 0; k < U.size(); ++k) U[k] = e*b.x[k];
    ulphEquations::continuity<2>
    (
        b.n, b.x.data(), U.data(), b.rho.data(), b.Minv.data(), b.sources,
        {U.data()}, *b.W, drho.data()
    );
    for (label i = 0; i < b.n; ++i)
    {
        EXPECT_NEAR(drho[i], -2*e*b.rho[i], 1e-9*b.rho[i]);
    }
}


TEST(ulphEquations, viscousStressOfASimpleShear)
{
    // u = (gamma y, 0): tau_xy = mu gamma, no normal stress (eq. 4-5)
    blob<2> b(16, 0.01, 0.2);
    const double shear = 2.0, mu = 1e-3;
    std::vector<double> U(b.x.size(), 0.0), tau(b.n*4);
    for (label i = 0; i < b.n; ++i) U[2*i] = shear*b.x[2*i + 1];
    ulphEquations::viscousStress<2>
    (
        b.n, b.x.data(), U.data(), b.Minv.data(), b.sources, {U.data()},
        *b.W, mu, tau.data()
    );
    for (label i = 0; i < b.n; ++i)
    {
        EXPECT_NEAR(tau[4*i + 1], mu*shear, 1e-12);
        EXPECT_NEAR(tau[4*i + 2], mu*shear, 1e-12);
        EXPECT_NEAR(tau[4*i + 0], 0, 1e-12);
        EXPECT_NEAR(tau[4*i + 3], 0, 1e-12);
    }
}
