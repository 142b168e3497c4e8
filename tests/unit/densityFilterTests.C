/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Description
    Density filter (ULPH eq. 24 and its MLS variant): on a lattice of water
    with a free surface and the hydrostatic density rho0 (1 + g y/c0^2),
    MLS keeps every particle's density (a linear field) while Shepard raises
    the top row's, the kick that keeps still water's surface oscillating;
    both keep a uniform density; a particle with one neighbour (a spray
    droplet: A singular) falls back to the Shepard value; 3D as well.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "densityFilter.H"
#include "smoothingKernel.H"
#include "cellLinkedList.H"
#include "testHelpers.H"
#include <cmath>

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
    std::vector<double> x, rho, mass;
    autoPtr<smoothingKernel> W;
    autoPtr<cellLinkedList> cells;
    neighbourList own;
    pairContext ctx;

    water(const label d, const label nx, const label ny, const double dx_)
    :
        dim(d),
        dx(dx_),
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

    //- Densities f(x), masses rho V, and the context over them
    template<class Field>
    void set(const Field& f)
    {
        const label n = size();
        rho.resize(n);
        mass.resize(n);
        for (label p = 0; p < n; ++p)
        {
            rho[p] = f(&x[p*dim]);
            mass[p] = rho[p]*std::pow(dx, dim);
        }
        cells.reset(new cellLinkedList(dim, W->radius()));
        cells->build(x.data(), n);
        own.build(*cells, x.data(), n, true);
        ctx.dim = dim;
        ctx.W = W.get();
        ctx.n = n;
        ctx.x = x.data();
        ctx.rho = rho.data();
        ctx.mass = mass.data();
        ctx.sources = {{&own, x.data(), nullptr}};
        ctx.massSrc = {mass.data()};
        ctx.wallSource = {false};
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
