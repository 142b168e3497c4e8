/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Description
    Wall repulsion (Monaghan 1994 Lennard-Jones boundary force): its value
    against the formula, zero beyond the range, only from wall sources (not
    from a coupled body's ghosts), and a particle thrown at a wall lattice
    turns at the distance where the force's potential equals its kinetic
    energy, never reaching the wall's surface, and leaves with the speed it
    came with.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "wallRepulsion.H"
#include "cellLinkedList.H"
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


//- A 2D context of particles xF (none of their own neighbours) with two
//  ghost sources: the given wall and a coupled body
struct twoSources
{
    cellLinkedList wallCells, bodyCells;
    neighbourList own, toWall, toBody;
    pairContext ctx;

    twoSources
    (
        const std::vector<double>& xF,
        const std::vector<double>& xWall,
        const std::vector<double>& xBody,
        const double radius
    )
    :
        wallCells(2, radius),
        bodyCells(2, radius)
    {
        const label n = label(xF.size())/2;
        wallCells.build(xWall.data(), label(xWall.size())/2);
        bodyCells.build(xBody.data(), label(xBody.size())/2);
        toWall.build(wallCells, xF.data(), n, false);
        toBody.build(bodyCells, xF.data(), n, false);
        own.build(bodyCells, xF.data(), 0, false);
        ctx.dim = 2;
        ctx.n = n;
        ctx.x = xF.data();
        ctx.sources =
        {
            {&own, xF.data(), nullptr},
            {&toWall, xWall.data(), nullptr},
            {&toBody, xBody.data(), nullptr}
        };
        ctx.wallSource = {false, true, false};
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
        std::vector<double> x = {x0, 0.5*dx}, u = {0, -v0}, a = {0, 0};
        const double dt = 2e-8;
        double yMin = x[1];
        const auto accel = [&]()
        {
            a = {0, 0};
            twoSources s(x, xWall, {1e3, 1e3}, 3*dx);
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
