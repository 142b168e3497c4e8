/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Description
    Density filter (ULPH eq. 24 and its MLS variant): on a lattice of water
    with a free surface and the hydrostatic density rho0 (1 + g y/c0^2),
    MLS keeps every particle's density (a linear field) while Shepard raises
    the top row's, the kick that keeps still water's surface oscillating;
    both keep a uniform density; a particle with one neighbour (a spray
    droplet: A singular) falls back to the Shepard value; 3D as well. With
    wall particles below the water (a source of their own, with their
    masses and volumes) both keep the hydrostatic density of the bottom
    row, which Shepard without them lowers.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "densityFilter.H"
#include "smoothingKernel.H"
#include "testHelpers.H"
#include <cmath>
#include <memory>

using namespace Foam;
using namespace Foam::meshless;
using effects::densityFilter;

namespace
{

//- Water on a lattice of spacing dx below a free surface at y = 0:
//  nx (x ny [x nz]) particles, centres at -(k + 1/2) dx
struct water
{
    label dim;
    double dx;
    label nx, ny;
    std::vector<double> x, rho, mass, xWall, wallMass;
    autoPtr<smoothingKernel> W;
    std::unique_ptr<meshlessTest::pairFixture> fx;
    pairContext ctx;

    water(const label d, const label nx, const label ny, const double dx_)
    :
        dim(d),
        dx(dx_),
        nx(nx),
        ny(ny),
        W
        (
            smoothingKernel::New
            (
                meshlessTest::dictFrom
                (
                    "type gaussian; smoothingLengthRatio 1.2; horizon 3;"
                ),
                d,
                dx_
            )
        )
    {
        const label nz = d == 3 ? nx : 1;
        for (label k = 0; k < nz; ++k)
        for (label j = 0; j < ny; ++j)
        for (label i = 0; i < nx; ++i)
        {
            x.push_back(i*dx);
            x.push_back(-(j + 0.5)*dx);
            if (d == 3) x.push_back(k*dx);
        }
    }

    label size() const { return label(x.size())/dim; }

    //- Densities f(x), masses rho V, and the context over them, with
    //  wallRows rows of wall particles (density f, volume dx^dim) below
    template<class Field>
    void set(const Field& f, const label wallRows = 0)
    {
        const label n = size();
        rho.resize(n);
        mass.resize(n);
        for (label p = 0; p < n; ++p)
        {
            rho[p] = f(&x[p*dim]);
            mass[p] = rho[p]*std::pow(dx, dim);
        }
        // The body's own relation (its volumes are m/rho: none given)
        fx.reset(new meshlessTest::pairFixture(dim));
        fx->addBody(x, 0.0);
        fx->relate
        (
            0, 0, *W, 0,
            neighbourRelation::separation | neighbourRelation::kernelValue
        );
        ctx.dim = dim;
        ctx.W = W.get();
        ctx.n = n;
        ctx.rho = rho.data();
        ctx.mass = mass.data();
        ctx.sources = {{fx->sources(0)[0].rel, nullptr}};
        ctx.massSrc = {mass.data()};
        ctx.wallSource = {false};
        if (wallRows == 0) return;

        xWall.clear();
        wallMass.clear();
        const label nz = dim == 3 ? nx : 1;
        for (label k = 0; k < nz; ++k)
        for (label j = ny; j < ny + wallRows; ++j)
        for (label i = 0; i < nx; ++i)
        {
            xWall.push_back(i*dx);
            xWall.push_back(-(j + 0.5)*dx);
            if (dim == 3) xWall.push_back(k*dx);
            wallMass.push_back(f(&xWall[xWall.size() - dim])*std::pow(dx, dim));
        }
        fx->addBody(xWall, std::pow(dx, dim));
        const neighbourRelation& toWall = fx->relate
        (
            0, 1, *W, 0,
            neighbourRelation::separation | neighbourRelation::kernelValue
        );
        ctx.sources.push_back(fx->source(toWall));
        ctx.massSrc.push_back(wallMass.data());
        ctx.wallSource.push_back(true);
    }

    std::vector<double> filtered(const densityFilter::methodType m) const
    {
        std::vector<double> out(size());
        densityFilter::filter(ctx, m, out.data());
        return out;
    }
};

const double rho0 = 1000, g = 9.81, c0 = 20;

//- Hydrostatic density (Tait linearised): rho0 (1 + g depth/c0^2)
double hydrostatic(const double* x)
{
    return rho0*(1 - g*x[1]/(c0*c0));
}

} // End anonymous namespace


TEST(densityFilter, mlsKeepsHydrostaticDensityShepardRaisesTheSurface)
{
    water w(2, 30, 12, 0.005);
    w.set(hydrostatic);
    const auto mls = w.filtered(densityFilter::methodType::MLS);
    const auto shepard = w.filtered(densityFilter::methodType::Shepard);

    double mlsErr = 0;
    for (label p = 0; p < w.size(); ++p)
    {
        mlsErr = std::max(mlsErr, std::abs(mls[p] - w.rho[p]));
    }
    EXPECT_LT(mlsErr, 1e-10*rho0);

    // The top row's middle particle: Shepard averages in the denser water
    // below, raising its density by a fraction of rho0 g dx/c0^2
    const label top = 15;
    const double step = rho0*g*w.dx/(c0*c0);
    EXPECT_GT(shepard[top] - w.rho[top], 0.2*step);
}


TEST(densityFilter, bothKeepAUniformDensity)
{
    water w(2, 20, 10, 0.005);
    w.set([](const double*) { return rho0; });
    for (const auto m :
        {densityFilter::methodType::MLS, densityFilter::methodType::Shepard})
    {
        const auto out = w.filtered(m);
        for (label p = 0; p < w.size(); ++p)
        {
            EXPECT_NEAR(out[p], rho0, 1e-10*rho0);
        }
    }
}


TEST(densityFilter, mlsKeepsHydrostaticDensity3D)
{
    water w(3, 9, 6, 0.005);
    w.set(hydrostatic);
    const auto mls = w.filtered(densityFilter::methodType::MLS);
    for (label p = 0; p < w.size(); ++p)
    {
        EXPECT_NEAR(mls[p], w.rho[p], 1e-10*rho0);
    }
}


TEST(densityFilter, wallParticlesKeepTheBottomRowsDensity)
{
    // Three rows of wall particles below: the bottom row's neighbourhood
    // is symmetric in y again, so both methods keep the hydrostatic
    // density there; without the wall Shepard averages in only the
    // lighter water above and lowers it
    for (const label dim : {2, 3})
    {
        const label nx = dim == 2 ? 20 : 9, ny = 8;
        water w(dim, nx, ny, 0.005);
        w.set(hydrostatic);
        const auto alone = w.filtered(densityFilter::methodType::Shepard);
        w.set(hydrostatic, 3);
        ASSERT_GT(w.ctx.sources[1].rel->nPairs(), 0);
        const auto mls = w.filtered(densityFilter::methodType::MLS);
        const auto shepard = w.filtered(densityFilter::methodType::Shepard);
        const double step = rho0*g*w.dx/(c0*c0);
        for (label p = 0; p < w.size(); ++p)
        {
            EXPECT_NEAR(mls[p], w.rho[p], 1e-10*rho0) << dim << "D, " << p;
            const label row = p/nx % ny;
            if (row >= ny - 3)
            {
                EXPECT_NEAR(shepard[p], w.rho[p], 1e-10*rho0)
                    << dim << "D, " << p;
                if (row == ny - 1)
                {
                    EXPECT_LT(alone[p] - w.rho[p], -0.2*step)
                        << dim << "D, " << p;
                }
            }
        }
    }
}


TEST(densityFilter, aDropletFallsBackToShepard)
{
    // Two particles 1.5 dx apart: A of either is singular (collinear), so
    // MLS must give the Shepard value, not a NaN
    water w(2, 2, 1, 0.005);
    w.x = {0, 0, 1.5*0.005, 0};
    w.set([](const double* x) { return x[0] > 0 ? 1010.0 : 990.0; });
    const auto mls = w.filtered(densityFilter::methodType::MLS);
    const auto shepard = w.filtered(densityFilter::methodType::Shepard);
    for (label p = 0; p < 2; ++p)
    {
        EXPECT_TRUE(std::isfinite(mls[p]));
        EXPECT_DOUBLE_EQ(mls[p], shepard[p]);
    }
}


// ************************************************************************* //
