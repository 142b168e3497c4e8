/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Description
    Wall repulsion (Monaghan 1994 Lennard-Jones boundary force): its value
    against the formula, zero beyond the range, only from wall sources (not
    from a coupled body's ghosts), and a particle thrown at a wall lattice
    turns at the distance where the force's potential equals its kinetic
    energy, never reaching the wall's surface, and leaves with the speed it
    came with. The particle's relations follow it (geometry updated every
    step, lists rebuilt when it moved by half their skin).

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "wallRepulsion.H"
#include "testHelpers.H"
#include <cmath>

using namespace Foam;
using namespace Foam::meshless;
using effects::wallRepulsion;

namespace
{

//- Wall particles of a 2D floor: rows at y = -dx/2, -3dx/2, ... for
//  |x| <= 10 dx
std::vector<double> floorLattice(const double dx, const label nRows)
{
    std::vector<double> x;
    for (label r = 0; r < nRows; ++r)
    {
        for (label c = -10; c <= 10; ++c)
        {
            x.push_back(c*dx);
            x.push_back(-(r + 0.5)*dx);
        }
    }
    return x;
}


//- A 2D context of particles xF with their own relation and two ghost
//  sources: the given wall and a coupled body, searched within radius (a
//  Wendland kernel's support) grown by a skin; x() the particles'
//  positions, moved() after they moved
struct twoSources
{
    const double skin;
    autoPtr<smoothingKernel> W;
    meshlessTest::pairFixture fx;
    pairContext ctx;

    //- The particles' positions at the last build of the lists
    std::vector<double> xBuilt;

    twoSources
    (
        const std::vector<double>& xF,
        const std::vector<double>& xWall,
        const std::vector<double>& xBody,
        const double radius,
        const double skin_ = 0
    )
    :
        skin(skin_),
        W
        (
            meshlessTest::kernel
            (
                2, radius, "type wendlandC2; smoothingLengthRatio 0.5;"
            )
        ),
        fx(2)
    {
        fx.addBody(xF, 0.0);
        fx.addBody(xWall, 0.0);
        fx.addBody(xBody, 0.0);
        for (label b = 0; b < 3; ++b)
        {
            fx.relate(0, b, *W, skin, neighbourRelation::separation);
        }
        xBuilt = xF;
        ctx.dim = 2;
        ctx.W = W.get();
        ctx.n = fx.size(0);
        ctx.sources = fx.sources(0);
        ctx.wallSource = {false, true, false};
    }

    double* x() { return fx.x(0).data(); }

    //- The pair geometry at the particles' new positions, and the lists
    //  rebuilt when a particle moved by half the skin since their build
    void moved()
    {
        double d2 = 0;
        for (size_t k = 0; k < xBuilt.size(); k += 2)
        {
            d2 = std::max
            (
                d2, sqr(x()[k] - xBuilt[k]) + sqr(x()[k + 1] - xBuilt[k + 1])
            );
        }
        if (4*d2 >= sqr(skin*W->radius()))
        {
            fx.rebuild();
            xBuilt.assign(x(), x() + xBuilt.size());
        }
        else
        {
            fx.updateGeometry();
        }
    }
};

} // End anonymous namespace


TEST(wallRepulsion, lennardJonesValueAndRange)
{
    const double D = 9.81, r0 = 0.003;
    EXPECT_EQ(wallRepulsion::magnitude(r0, D, r0, 12, 4), 0);
    EXPECT_EQ(wallRepulsion::magnitude(2*r0, D, r0, 12, 4), 0);
    const double r = 0.5*r0;
    EXPECT_NEAR
    (
        wallRepulsion::magnitude(r, D, r0, 12, 4),
        D*(4096.0 - 16.0)/r,
        1e-12*D*4096/r
    );
    // Monotonic: stronger the closer
    EXPECT_GT
    (
        wallRepulsion::magnitude(0.8*r0, D, r0, 12, 4),
        wallRepulsion::magnitude(0.9*r0, D, r0, 12, 4)
    );
}


TEST(wallRepulsion, onlyWallsRepelAndOnlyWithinRange)
{
    const double r0 = 0.75e-3;
    // Particle 0 is 0.5 r0 from a wall particle and from a body particle;
    // particle 1 is 1.01 r0 from the wall particle only
    const std::vector<double> xF = {0, 0, 10e-3 + 1.01*r0, 0};
    const std::vector<double> xWall = {-0.5*r0, 0, 10e-3, 0};
    const std::vector<double> xBody = {0, 0.5*r0};
    twoSources s(xF, xWall, xBody, 3e-3);
    EXPECT_NEAR(s.W->radius(), 3e-3, 1e-15);
    EXPECT_EQ(s.ctx.sources[0].rel->nPairs(), 0) << "own: 10 mm apart";
    EXPECT_EQ(s.ctx.sources[1].rel->nPairs(), 2);
    EXPECT_EQ(s.ctx.sources[2].rel->nPairs(), 1);

    std::vector<double> a(4, 0);
    const label nPairs = wallRepulsion::add(s.ctx, 2, r0, 12, 4, a.data());
    EXPECT_EQ(nPairs, 1);
    const double expected = wallRepulsion::magnitude(0.5*r0, 2, r0, 12, 4);
    EXPECT_NEAR(a[0], expected, 1e-12*expected);   // away from the wall
    EXPECT_EQ(a[1], 0);                            // nothing from the body
    EXPECT_EQ(a[2], 0);
    EXPECT_EQ(a[3], 0);
}


TEST(wallRepulsion, particleThrownAtAFloorTurnsWherePotentialMatches)
{
    const double dx = 1e-3, r0 = 0.9*dx, D = 9.81, p1 = 12, p2 = 4;
    const double v0 = 2;
    const std::vector<double> xWall = floorLattice(dx, 4);

    // Turning point: D ((q^p1 - 1)/p1 - (q^p2 - 1)/p2) = v0^2/2, q = r0/r
    const auto potential = [&](const double q)
    {
        return D*((std::pow(q, p1) - 1)/p1 - (std::pow(q, p2) - 1)/p2);
    };
    double lo = 1, hi = 10;
    for (int it = 0; it < 200; ++it)
    {
        const double q = 0.5*(lo + hi);
        (potential(q) < 0.5*v0*v0 ? lo : hi) = q;
    }
    const double rMin = r0/lo;

    // Above a wall particle (only it within r0) and above a gap
    for (const double x0 : {0.0, 0.5*dx})
    {
        twoSources s({x0, 0.5*dx}, xWall, {1e3, 1e3}, 3*dx, 0.1);
        double* x = s.x();
        std::vector<double> u = {0, -v0}, a = {0, 0};
        const double dt = 2e-8;
        double yMin = x[1];
        const auto accel = [&]()
        {
            a = {0, 0};
            s.moved();
            wallRepulsion::add(s.ctx, D, r0, p1, p2, a.data());
        };
        accel();
        for (int step = 0; step < 200000 && u[1] <= 0; ++step)
        {
            // Velocity Verlet
            for (int d = 0; d < 2; ++d) u[d] += 0.5*dt*a[d];
            for (int d = 0; d < 2; ++d) x[d] += dt*u[d];
            accel();
            for (int d = 0; d < 2; ++d) u[d] += 0.5*dt*a[d];
            yMin = std::min(yMin, x[1]);
        }
        ASSERT_GT(u[1], 0) << "did not turn, x0 " << x0;
        // Out of range again: the speed it came with
        for (int step = 0; step < 200000 && x[1] < r0; ++step)
        {
            for (int d = 0; d < 2; ++d) u[d] += 0.5*dt*a[d];
            for (int d = 0; d < 2; ++d) x[d] += dt*u[d];
            accel();
            for (int d = 0; d < 2; ++d) u[d] += 0.5*dt*a[d];
        }
        EXPECT_NEAR(std::hypot(u[0], u[1]), v0, 1e-3*v0) << "x0 " << x0;
        EXPECT_GT(yMin, 0) << "reached the wall's surface, x0 " << x0;
        if (x0 == 0)
        {
            // One wall particle in range: the analytic turning point
            EXPECT_NEAR(yMin + 0.5*dx, rMin, 1e-3*rMin);
        }
    }
}
