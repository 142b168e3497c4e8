/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Description
    ULPH fluid equations: the pair force of the momentum equation (eq. 23)
    conserves linear momentum to round-off in a closed box without walls
    (random positions, pressures, viscous stresses); the Tait equation of
    state and its inverse; the continuity equation's rate for a uniform
    expansion; the viscous stress of a simple shear. The force of a set of
    ghost particles on the fluid (per fluid particle, summed by
    sumInOrder) is the direct sum of eq. 58's pair forces and the opposite
    of the reaction on the ghosts, so fluid and ghosts together conserve
    momentum.

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
    meshlessTest::pairFixture fx;
    std::vector<pairSource> sources;
    particleField Minv;

    blob(const label perSide, const double dx, const double jitter)
    :
        n(0),
        W(meshlessTest::kernel(Dim, dx)),
        fx(Dim),
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
        fx.addBody(x, V);
        fx.relate(0, 0, *W);
        sources = fx.sources(0);
        Minv.resize(n);
        std::vector<char> degenerate(n, 1);
        ulphOperators::shapeTensorInverse<Dim>
        (
            n, sources, Minv.data(), 0, degenerate.data()
        );
        EXPECT_EQ(meshlessTest::countFlags(degenerate), 0);
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
        b.n, b.rho.data(), S.data(), b.sources, {S.data()}, dU.data()
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
        b.n, U.data(), b.rho.data(), b.Minv.data(), b.sources, {U.data()},
        drho.data()
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
        b.n, U.data(), b.Minv.data(), b.sources, {U.data()}, mu, tau.data()
    );
    for (label i = 0; i < b.n; ++i)
    {
        EXPECT_NEAR(tau[4*i + 1], mu*shear, 1e-12);
        EXPECT_NEAR(tau[4*i + 2], mu*shear, 1e-12);
        EXPECT_NEAR(tau[4*i + 0], 0, 1e-12);
        EXPECT_NEAR(tau[4*i + 3], 0, 1e-12);
    }
}


namespace
{

//- A perturbed lattice split into fluid (x < half the block) and ghost
//  particles (a wall or a coupled solid), with random densities, volumes
//  and stress-times-M^-1 tensors on both sides
template<int Dim>
struct fluidAndGhosts
{
    const double dx = 0.01;
    autoPtr<smoothingKernel> W;
    meshlessTest::pairFixture fx;
    std::vector<double> rhoF, SF, SG;
    const neighbourRelation* ff;
    const neighbourRelation* fg;
    const neighbourRelation* gf;

    fluidAndGhosts()
    :
        W(meshlessTest::kernel(Dim, dx)),
        fx(Dim)
    {
        const label perSide = Dim == 2 ? 20 : 8;
        std::vector<double> all = meshlessTest::latticePoints(Dim, perSide, dx);
        std::mt19937_64 gen(23);
        std::uniform_real_distribution<double> u(-1, 1);
        for (auto& v : all) v += 0.25*dx*u(gen);
        std::vector<double> xF, xG, VF, VG;
        const double V0 = std::pow(dx, Dim);
        for (size_t i = 0; i < all.size()/Dim; ++i)
        {
            const bool fluid = all[i*Dim] < 0.5*perSide*dx;
            auto& x = fluid ? xF : xG;
            x.insert(x.end(), &all[i*Dim], &all[i*Dim] + Dim);
            (fluid ? VF : VG).push_back(V0*(1 + 0.05*u(gen)));
        }
        fx.addBody(xF, VF);
        fx.addBody(xG, VG);
        ff = &fx.relate(0, 0, *W);
        fg = &fx.relate(0, 1, *W);
        gf = &fx.relate(1, 0, *W);
        for (label i = 0; i < fx.size(0); ++i)
        {
            rhoF.push_back(1000*(1 + 0.01*u(gen)));
        }
        SF.resize(fx.size(0)*Dim*Dim);
        SG.resize(fx.size(1)*Dim*Dim);
        for (auto& v : SF) v = 1e4*u(gen);
        for (auto& v : SG) v = 1e4*u(gen);
    }

    label nF() const { return fx.size(0); }
    label nG() const { return fx.size(1); }
};


template<int Dim>
void expectGhostForceIsTheDirectSumAndTheReactionsOpposite()
{
    fluidAndGhosts<Dim> c;
    ASSERT_GT(c.fg->nPairs(), 0);
    std::vector<double> f(c.nF()*Dim), R(c.nG()*Dim);
    ulphEquations::ghostForceOnFluid<Dim>
    (
        c.nF(), c.fx.V(0), c.SF.data(), c.fx.source(*c.fg), c.SG.data(),
        f.data()
    );
    ulphEquations::reactionOnGhosts<Dim>
    (
        *c.gf, c.fx.V(1), c.SG.data(), c.fx.V(0), c.SF.data(), R.data()
    );

    // Per fluid particle: V_I sum_S w (S_I + S_S) x_IS V_S over every ghost
    // within the kernel's radius (O(N^2))
    const particleField& xF = c.fx.x(0);
    const particleField& xG = c.fx.x(1);
    double scaleAll = 0;
    for (label i = 0; i < c.nF(); ++i)
    {
        vectorD<Dim> direct = vectorD<Dim>::Zero();
        double scale = 0;
        for (label s = 0; s < c.nG(); ++s)
        {
            vectorD<Dim> xis;
            for (label d = 0; d < Dim; ++d) xis(d) = xG(s, d) - xF(i, d);
            const double r = xis.norm();
            if (r > c.W->radius()) continue;
            const vectorD<Dim> t =
                (c.W->W(r)*c.fx.V(1)[s])
               *((ctens<Dim>(c.SF.data(), i) + ctens<Dim>(c.SG.data(), s))*xis);
            direct += t;
            scale += t.cwiseAbs().sum();
        }
        direct *= c.fx.V(0)[i];
        scale *= c.fx.V(0)[i];
        scaleAll += scale;
        for (label d = 0; d < Dim; ++d)
        {
            EXPECT_NEAR(f[i*Dim + d], direct(d), 1e-12*scale + 1e-300)
                << "fluid particle " << i;
        }
    }
    ASSERT_GT(scaleAll, 0);

    // Action and reaction: the fluid's total equals minus the ghosts'
    const vectorD<Dim> onFluid = sumInOrder<Dim>(f.data(), c.nF());
    const vectorD<Dim> onGhosts = sumInOrder<Dim>(R.data(), c.nG());
    EXPECT_GT(onFluid.norm(), 1e-6*scaleAll) << "a force to balance";
    for (label d = 0; d < Dim; ++d)
    {
        EXPECT_LT(std::abs(onFluid(d) + onGhosts(d)), 1e-12*scaleAll) << d;
    }
}


template<int Dim>
void expectFluidAndGhostsConserveMomentum()
{
    // The momentum equation over the fluid and the ghosts (eq. 23 and 58):
    // sum m_I dU_I over the fluid plus the reactions on the ghosts vanish
    fluidAndGhosts<Dim> c;
    const std::vector<pairSource> sources = c.fx.sources(0);
    ASSERT_EQ(sources.size(), 2u);
    std::vector<double> dU(c.nF()*Dim), R(c.nG()*Dim);
    ulphEquations::momentum<Dim>
    (
        c.nF(), c.rhoF.data(), c.SF.data(), sources,
        {c.SF.data(), c.SG.data()}, dU.data()
    );
    ulphEquations::reactionOnGhosts<Dim>
    (
        *c.gf, c.fx.V(1), c.SG.data(), c.fx.V(0), c.SF.data(), R.data()
    );
    double total[3] = {0, 0, 0}, scale = 0;
    for (label i = 0; i < c.nF(); ++i)
    {
        const double m = c.rhoF[i]*c.fx.V(0)[i];
        for (label d = 0; d < Dim; ++d)
        {
            total[d] += m*dU[i*Dim + d];
            scale += std::abs(m*dU[i*Dim + d]);
        }
    }
    for (label s = 0; s < c.nG(); ++s)
    {
        for (label d = 0; d < Dim; ++d)
        {
            total[d] += R[s*Dim + d];
            scale += std::abs(R[s*Dim + d]);
        }
    }
    ASSERT_GT(scale, 0);
    for (label d = 0; d < Dim; ++d)
    {
        EXPECT_LT(std::abs(total[d]), 1e-12*scale) << "component " << d;
    }
}

} // End anonymous namespace


TEST(ulphEquations, ghostForceIsTheDirectSumAndTheReactionsOpposite2D)
{
    expectGhostForceIsTheDirectSumAndTheReactionsOpposite<2>();
}

TEST(ulphEquations, ghostForceIsTheDirectSumAndTheReactionsOpposite3D)
{
    expectGhostForceIsTheDirectSumAndTheReactionsOpposite<3>();
}

TEST(ulphEquations, fluidAndGhostsConserveMomentum2D)
{
    expectFluidAndGhostsConserveMomentum<2>();
}

TEST(ulphEquations, fluidAndGhostsConserveMomentum3D)
{
    expectFluidAndGhostsConserveMomentum<3>();
}
