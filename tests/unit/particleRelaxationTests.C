/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Description
    Particle relaxation (particleRelaxation, seedParticles' 'relaxation'):

      - a perturbed lattice in a periodic unit square relaxes: the residual
        max h|Gamma| falls from O(1) to below 0.03, every particle stays
        in the period, and the kernel sum sum_j W_ij V_j is within 2 % of
        its lattice value everywhere;
      - the unperturbed periodic lattice is a fixed point (moves < 1e-12);
      - a constraint that refuses x >= 0.5 keeps a body in its half of
        the box (refused moves counted), against fixed particles in the
        other half;
      - the same seed gives the same particles, another seed others;
      - bad entries stop with a FatalIOError naming the keyword.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testHelpers.H"
#include "particleRelaxation.H"
#include <cmath>

using namespace Foam;
using namespace Foam::meshless;

namespace
{

periodicBox unitSquare(const bool x = true)
{
    periodicBox box;
    if (x) box.set(0, 0, 1);
    box.set(1, 0, 1);
    return box;
}


//- A lattice of spacing 1/nSide over [x0, x1) x [0, 1)
std::vector<double> lattice(const label nSide, const double x0 = 0, const double x1 = 1)
{
    const double dx = 1.0/nSide;
    std::vector<double> x;
    for (label j = 0; j < nSide; ++j)
    {
        for (label i = 0; x0 + (i + 0.5)*dx < x1; ++i)
        {
            x.push_back(x0 + (i + 0.5)*dx);
            x.push_back((j + 0.5)*dx);
        }
    }
    return x;
}


const particleRelaxation::constraint anywhere =
    [](const double*, const label n, std::vector<char>& ok)
    {
        ok.assign(n, 1);
    };


//- max_i |sum_j W_ij V - sigma| / sigma in a periodic unit square,
//  sigma the lattice's kernel sum
double kernelSumSpread
(
    const std::vector<double>& x,
    const double dx,
    const smoothingKernel& W
)
{
    const label n = label(x.size())/2;
    auto sum = [&](const std::vector<double>& y, const label i)
    {
        double s = 0;
        for (label j = 0; j < label(y.size())/2; ++j)
        {
            double r[2] = {y[2*i] - y[2*j], y[2*i + 1] - y[2*j + 1]};
            for (double& c : r) c -= std::floor(c + 0.5);
            s += W.W(std::sqrt(r[0]*r[0] + r[1]*r[1]))*dx*dx;
        }
        return s;
    };
    const std::vector<double> lat = lattice(label(std::round(1/dx)));
    const double sigma = sum(lat, 0);
    double worst = 0;
    for (label i = 0; i < n; ++i) worst = std::max(worst, std::abs(sum(x, i)/sigma - 1));
    return worst;
}

} // End namespace


TEST(particleRelaxation, perturbedPeriodicLatticeRelaxes)
{
    const label nSide = 30;
    const double dx = 1.0/nSide;
    particleRelaxation relax
    (
        meshlessTest::dictFrom("iterations 300;"), 2, dx, unitSquare()
    );
    std::vector<double> x = lattice(nSide);
    const size_t n = x.size()/2;
    relax.relax(x, dx*dx, {}, {}, anywhere);

    EXPECT_EQ(x.size(), 2*n);
    EXPECT_GT(relax.initialResidual(), 0.3);
    EXPECT_LT(relax.finalResidual(), 0.03);
    EXPECT_LT(relax.finalResidual(), relax.residual(x, dx*dx, {}, {}) + 1e-12);
    EXPECT_EQ(relax.refused(), 0);
    for (const double c : x)
    {
        EXPECT_GE(c, 0);
        EXPECT_LT(c, 1);
    }
    EXPECT_LT(kernelSumSpread(x, dx, relax.kernel()), 0.02);

    // The perturbation moved the particles off the lattice
    const std::vector<double> lat = lattice(nSide);
    double moved = 0;
    for (size_t k = 0; k < x.size(); ++k) moved = std::max(moved, std::abs(x[k] - lat[k]));
    EXPECT_GT(moved, 0.1*dx);
}


TEST(particleRelaxation, periodicLatticeIsAFixedPoint)
{
    const label nSide = 20;
    const double dx = 1.0/nSide;
    particleRelaxation relax
    (
        meshlessTest::dictFrom("iterations 50; perturbation 0;"),
        2, dx, unitSquare()
    );
    std::vector<double> x = lattice(nSide);
    const std::vector<double> x0 = x;
    relax.relax(x, dx*dx, {}, {}, anywhere);
    double moved = 0;
    for (size_t k = 0; k < x.size(); ++k) moved = std::max(moved, std::abs(x[k] - x0[k]));
    EXPECT_LT(moved, 1e-12);
    EXPECT_LT(relax.finalResidual(), 1e-10);
    // Stopped on the tolerance at the first iteration
    EXPECT_EQ(relax.iterationsDone(), 1);
}


TEST(particleRelaxation, constraintKeepsTheBodyInItsRegion)
{
    const label nSide = 20;
    const double dx = 1.0/nSide;
    particleRelaxation relax
    (
        meshlessTest::dictFrom("iterations 100;"), 2, dx, unitSquare(false)
    );
    // The body in x < 0.5, fixed particles (a wall) in x >= 0.5
    std::vector<double> x = lattice(nSide, 0, 0.5);
    const std::vector<double> wall = lattice(nSide, 0.5, 0.5 + 3*dx);
    const std::vector<double> Vw(wall.size()/2, dx*dx);
    const particleRelaxation::constraint left =
        [](const double* y, const label n, std::vector<char>& ok)
        {
            ok.resize(n);
            for (label i = 0; i < n; ++i) ok[i] = y[2*i] >= 0 && y[2*i] < 0.5;
        };
    relax.relax(x, dx*dx, wall, Vw, left);
    EXPECT_GT(relax.refused(), 0);
    for (size_t i = 0; i < x.size()/2; ++i)
    {
        EXPECT_GE(x[2*i], 0);
        EXPECT_LT(x[2*i], 0.5);
        EXPECT_GE(x[2*i + 1], 0);
        EXPECT_LT(x[2*i + 1], 1);
    }
}


TEST(particleRelaxation, seedMakesItReproducible)
{
    const double dx = 1.0/20;
    auto run = [&](const std::string& entries)
    {
        particleRelaxation relax
        (
            meshlessTest::dictFrom("iterations 20; " + entries), 2, dx, unitSquare()
        );
        std::vector<double> x = lattice(20);
        relax.relax(x, dx*dx, {}, {}, anywhere);
        return x;
    };
    const std::vector<double> a = run("seed 7;");
    const std::vector<double> b = run("seed 7;");
    const std::vector<double> c = run("seed 8;");
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
}


TEST(particleRelaxation, badEntriesAreFatalIOErrors)
{
    const double dx = 0.05;
    auto message = [&](const std::string& text)
    {
        return meshlessTest::fatalMessage
        (
            [&]() { particleRelaxation(meshlessTest::dictFrom(text), 2, dx); }
        );
    };
    EXPECT_NE(message("").find("iterations"), std::string::npos);
    EXPECT_NE(message("iterations 10; perturbation 0.6;").find("perturbation"), std::string::npos);
    EXPECT_NE(message("iterations 10; maxStep 0.8;").find("maxStep"), std::string::npos);
    EXPECT_NE(message("iterations 10; coefficient -1;").find("coefficient"), std::string::npos);
}

// ************************************************************************* //
