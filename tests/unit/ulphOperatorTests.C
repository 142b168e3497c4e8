/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Description
    ULPH non-local operators (eq. 12-15): gradient and divergence of linear
    fields are exact (1e-10) on lattices and randomly perturbed particles in
    2D and 3D, at every particle (interior and boundary), also when the
    neighbours come from two bodies; a free-slip wall passes only its
    normal velocity to the divergence; the documented fallback for degenerate
    shape tensors gives exact derivatives along resolved directions, zero
    across, and no NaN; the full support's eigenvalue is the interior
    particle's; an eigenvalue floor of a tenth of it keeps the operators
    exact on lattices (boundaries and corners included) and bounds M^-1 of
    a thin jet. The operators run over the relations' cached geometry
    (pairSource), so their results follow the points when a relation is
    rebuilt after the particles moved.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testHelpers.H"
#include "ulphOperators.H"
#include <cmath>
#include <random>

using namespace Foam;
using namespace Foam::meshless;

namespace
{

struct cloud
{
    label dim;
    std::vector<double> x;
    std::vector<double> V;
    label size() const { return label(x.size())/dim; }
};

cloud lattice(const label dim, const label n, const double dx, const double jitter)
{
    cloud c{dim, meshlessTest::latticePoints(dim, n, dx), {}};
    std::mt19937_64 gen(17);
    std::uniform_real_distribution<double> u(-jitter*dx, jitter*dx);
    for (auto& v : c.x) v += u(gen);
    c.V.assign(c.size(), dim == 2 ? dx*dx : dx*dx*dx);
    return c;
}

//- A cloud's own relation as the one neighbour source of its operators
struct ownNeighbours
{
    meshlessTest::pairFixture fx;
    std::vector<pairSource> sources;

    ownNeighbours(const cloud& c, const smoothingKernel& W)
    :
        fx(c.dim)
    {
        fx.addBody(c.x, c.V);
        fx.relate(0, 0, W);
        sources = fx.sources(0);
    }
};

//- M^-1 of a cloud's particles over sources; the number of particles that
//  needed the fallback or the floor
template<int Dim>
label shapeTensorInverse
(
    const label n,
    const std::vector<pairSource>& sources,
    particleField& Minv,
    const double lambdaFloor = 0
)
{
    Minv.resize(n);
    std::vector<char> degenerate(n, 2);
    ulphOperators::shapeTensorInverse<Dim>
    (
        n, sources, Minv.data(), lambdaFloor, degenerate.data()
    );
    for (const char d : degenerate)
    {
        EXPECT_TRUE(d == 0 || d == 1) << "every particle flagged";
    }
    return meshlessTest::countFlags(degenerate);
}

//- A jet one particle thick: n particles along x at y = 0.5, volumes dx^2
cloud jet(const label n, const double dx)
{
    cloud c{2, {}, {}};
    for (label i = 0; i < n; ++i)
    {
        c.x.push_back(i*dx);
        c.x.push_back(0.5);
    }
    c.V.assign(n, dx*dx);
    return c;
}

autoPtr<smoothingKernel> ulphKernel(const label dim, const double dx)
{
    // The paper's kernel: Gaussian, h = 1.2 dx, horizon 3h
    return meshlessTest::kernel(dim, dx);
}

//- f = a + b.x per particle
std::vector<double> linearScalar(const cloud& c, const double* b)
{
    std::vector<double> f(c.size());
    for (label i = 0; i < c.size(); ++i)
    {
        f[i] = 0.7;
        for (label d = 0; d < c.dim; ++d) f[i] += b[d]*c.x[i*c.dim + d];
    }
    return f;
}

//- u = c + A x per particle, A row-major
std::vector<double> linearVector(const cloud& c, const double* A)
{
    std::vector<double> u(c.x.size());
    for (label i = 0; i < c.size(); ++i)
    {
        for (label a = 0; a < c.dim; ++a)
        {
            u[i*c.dim + a] = 0.3*(a + 1);
            for (label b = 0; b < c.dim; ++b)
            {
                u[i*c.dim + a] += A[a*c.dim + b]*c.x[i*c.dim + b];
            }
        }
    }
    return u;
}

template<int Dim>
void expectExact
(
    const cloud& c,
    const double dx,
    const std::string& what,
    const double floorRatio = 0
)
{
    autoPtr<smoothingKernel> W = ulphKernel(Dim, dx);
    const double lambdaFloor =
        floorRatio*correctionMatrix::fullSupportEigenvalue<Dim>(*W, dx);
    const ownNeighbours own(c, *W);
    const std::vector<pairSource>& sources = own.sources;

    particleField Minv("Minv", particleField::kind::tensor, Dim);
    const label nDegenerate =
        shapeTensorInverse<Dim>(c.size(), sources, Minv, lambdaFloor);
    EXPECT_EQ(nDegenerate, 0) << what;

    const double b[3] = {2.0, -3.0, 0.5};
    const auto f = linearScalar(c, b);
    std::vector<double> grad(c.x.size());
    ulphOperators::gradient<Dim>
    (
        c.size(), sources, Minv.data(), f.data(), {f.data()}, grad.data()
    );

    const double A[9] = {1.0, 2.0, -0.5, 3.0, -1.0, 0.25, 0.4, -2.0, 1.5};
    double ADim[9];
    for (label a = 0; a < Dim; ++a)
        for (label bb = 0; bb < Dim; ++bb) ADim[a*Dim + bb] = A[a*3 + bb];
    const auto u = linearVector(c, ADim);
    std::vector<double> gradU(c.size()*Dim*Dim), divU(c.size());
    ulphOperators::vectorGradient<Dim>
    (
        c.size(), sources, Minv.data(), u.data(), {u.data()}, gradU.data()
    );
    ulphOperators::divergence<Dim>
    (
        c.size(), sources, Minv.data(), u.data(), {u.data()}, divU.data()
    );
    double trace = 0;
    for (label a = 0; a < Dim; ++a) trace += ADim[a*Dim + a];

    double errGrad = 0, errGradU = 0, errDiv = 0;
    for (label i = 0; i < c.size(); ++i)
    {
        for (label d = 0; d < Dim; ++d)
        {
            errGrad = std::max(errGrad, std::abs(grad[i*Dim + d] - b[d]));
        }
        for (label k = 0; k < Dim*Dim; ++k)
        {
            errGradU =
                std::max(errGradU, std::abs(gradU[i*Dim*Dim + k] - ADim[k]));
        }
        errDiv = std::max(errDiv, std::abs(divU[i] - trace));
    }
    EXPECT_LT(errGrad, 1e-10) << what;
    EXPECT_LT(errGradU, 1e-10) << what;
    EXPECT_LT(errDiv, 1e-10) << what;
}

} // End anonymous namespace


TEST(ulphOperators, linearFieldsExactOnALattice2D)
{
    expectExact<2>(lattice(2, 20, 0.01, 0), 0.01, "2D lattice");
}

TEST(ulphOperators, linearFieldsExactOnALattice3D)
{
    expectExact<3>(lattice(3, 9, 0.01, 0), 0.01, "3D lattice");
}

TEST(ulphOperators, linearFieldsExactOnPerturbedParticles2D)
{
    expectExact<2>(lattice(2, 20, 0.01, 0.3), 0.01, "2D perturbed");
}

TEST(ulphOperators, linearFieldsExactOnPerturbedParticles3D)
{
    expectExact<3>(lattice(3, 9, 0.01, 0.3), 0.01, "3D perturbed");
}


TEST(ulphOperators, shapeTensorFloorKeepsLatticesExact)
{
    expectExact<2>(lattice(2, 20, 0.01, 0), 0.01, "2D lattice, floor", 0.1);
    expectExact<2>(lattice(2, 20, 0.01, 0.3), 0.01, "2D perturbed, floor", 0.1);
    expectExact<3>(lattice(3, 9, 0.01, 0), 0.01, "3D lattice, floor", 0.1);
}


template<int Dim>
void expectFullSupportEigenvalue(const label n)
{
    // The middle particle of a lattice has a full support: its M is
    // isotropic with the lattice sum's eigenvalue
    const double dx = 0.01;
    const cloud c = lattice(Dim, n, dx, 0);
    autoPtr<smoothingKernel> W = ulphKernel(Dim, dx);
    const ownNeighbours own(c, *W);
    const std::vector<pairSource>& sources = own.sources;
    particleField Minv("Minv", particleField::kind::tensor, Dim);
    shapeTensorInverse<Dim>(c.size(), sources, Minv);
    label mid = 0;
    for (label d = Dim - 1; d >= 0; --d) mid = mid*n + n/2;
    const double m = correctionMatrix::fullSupportEigenvalue<Dim>(*W, dx);
    for (label a = 0; a < Dim; ++a)
    {
        for (label b = 0; b < Dim; ++b)
        {
            EXPECT_NEAR
            (
                Minv(mid, a*Dim + b)*m, a == b ? 1.0 : 0.0, 1e-12
            ) << Dim << "D, component " << a << b;
        }
    }
}


TEST(ulphOperators, fullSupportEigenvalueIsTheInteriorParticles)
{
    expectFullSupportEigenvalue<2>(21);
    expectFullSupportEigenvalue<3>(11);
}


TEST(ulphOperators, shapeTensorFloorBoundsAThinJet)
{
    // A jet one particle thick: along it M is a fraction of a full
    // support's; with a floor of half the full support's eigenvalue the
    // inverse is bounded by 1/floor, derivatives along the jet shrink by
    // at most that ratio and stay of the right sign, across it zero
    const double dx = 0.01;
    const cloud c = jet(10, dx);
    autoPtr<smoothingKernel> W = ulphKernel(2, dx);
    const ownNeighbours own(c, *W);
    const std::vector<pairSource>& sources = own.sources;
    const double lambdaFloor =
        0.5*correctionMatrix::fullSupportEigenvalue<2>(*W, dx);

    particleField Minv("Minv", particleField::kind::tensor, 2);
    const label nFloor =
        shapeTensorInverse<2>(c.size(), sources, Minv, lambdaFloor);
    EXPECT_EQ(nFloor, c.size());

    const double b[2] = {2.0, -3.0};
    const auto f = linearScalar(c, b);
    std::vector<double> grad(c.x.size());
    ulphOperators::gradient<2>
    (
        c.size(), sources, Minv.data(), f.data(), {f.data()}, grad.data()
    );
    double smallest = 2.0;
    for (label i = 0; i < c.size(); ++i)
    {
        // Frobenius norm of M^-1 (only one nonzero eigenvalue here)
        double norm2 = 0;
        for (label k = 0; k < 4; ++k) norm2 += sqr(Minv(i, k));
        EXPECT_LE(std::sqrt(norm2)*lambdaFloor, 1 + 1e-12) << i;
        EXPECT_GT(grad[2*i], 0.0) << i;
        EXPECT_LE(grad[2*i], 2.0 + 1e-10) << i;
        EXPECT_EQ(grad[2*i + 1], 0.0) << i;
        smallest = std::min(smallest, grad[2*i]);
    }
    EXPECT_LT(smallest, 2.0 - 1e-3) << "the floor is active";
}


//- A fluid half (x < 0.1) and a wall half of one perturbed 2D lattice,
//  with the fluid's neighbour sources in both and its M^-1 over both
struct fluidAndWall
{
    const double dx = 0.01;
    cloud fluid{2, {}, {}}, wall{2, {}, {}};
    autoPtr<smoothingKernel> W;
    meshlessTest::pairFixture fx;
    const neighbourRelation* ff;
    const neighbourRelation* fw;
    std::vector<pairSource> both;
    particleField Minv;

    fluidAndWall()
    :
        W(ulphKernel(2, dx)),
        fx(2),
        Minv("Minv", particleField::kind::tensor, 2)
    {
        const cloud all = lattice(2, 20, dx, 0.25);
        for (label i = 0; i < all.size(); ++i)
        {
            cloud& c = all.x[2*i] < 0.1 ? fluid : wall;
            c.x.push_back(all.x[2*i]);
            c.x.push_back(all.x[2*i + 1]);
            c.V.push_back(all.V[i]);
        }
        fx.addBody(fluid.x, fluid.V);
        fx.addBody(wall.x, wall.V);
        ff = &fx.relate(0, 0, *W);
        fw = &fx.relate(0, 1, *W);
        both = fx.sources(0);
        EXPECT_EQ(both.size(), 2u);
        EXPECT_EQ(shapeTensorInverse<2>(fluid.size(), both, Minv), 0);
    }

    //- The fluid's divergence of uF, uW (wall normals n, or none)
    std::vector<double> divergence
    (
        const std::vector<double>& uF,
        const std::vector<double>& uW,
        const std::vector<double>& n
    ) const
    {
        std::vector<double> div(fluid.size());
        ulphOperators::divergence<2>
        (
            fluid.size(), both, Minv.data(), uF.data(),
            {uF.data(), uW.data()}, div.data(),
            {nullptr, n.empty() ? nullptr : n.data()}
        );
        return div;
    }
};


TEST(ulphOperators, neighboursFromTwoBodies)
{
    // The fluid's operators sum over both bodies and stay exact
    const fluidAndWall fw;
    EXPECT_GT(fw.fw->nPairs(), 0);
    const double b[2] = {-1.5, 4.0};
    const auto fF = linearScalar(fw.fluid, b);
    const auto fW = linearScalar(fw.wall, b);
    std::vector<double> grad(fw.fluid.x.size());
    ulphOperators::gradient<2>
    (
        fw.fluid.size(), fw.both, fw.Minv.data(), fF.data(),
        {fF.data(), fW.data()}, grad.data()
    );
    for (label i = 0; i < fw.fluid.size(); ++i)
    {
        EXPECT_NEAR(grad[2*i], b[0], 1e-10);
        EXPECT_NEAR(grad[2*i + 1], b[1], 1e-10);
    }
}


TEST(ulphOperators, freeSlipWallPassesOnlyItsNormalVelocity)
{
    // A free-slip wall (normals (1, 0)) stands for the fluid particle's own
    // mirror image: the wall's tangential velocities must not enter the
    // divergence, its normal velocity must
    const fluidAndWall fw;
    const label nF = fw.fluid.size(), nW = fw.wall.size();
    std::vector<double> normals(2*nW, 0.0);
    for (label j = 0; j < nW; ++j) normals[2*j] = 1;

    // Fluid in uniform motion along the wall; the wall's particles with
    // scattered tangential velocities, as the averaged ghost values are
    std::vector<double> uF(2*nF, 0.0), uW(2*nW, 0.0);
    for (label i = 0; i < nF; ++i) uF[2*i + 1] = 0.4;
    std::mt19937_64 gen(5);
    std::uniform_real_distribution<double> r(-1, 1);
    for (label j = 0; j < nW; ++j) uW[2*j + 1] = r(gen);

    const auto slip = fw.divergence(uF, uW, normals);
    const auto plain = fw.divergence(uF, uW, {});
    double errSlip = 0, devPlain = 0;
    for (label i = 0; i < nF; ++i)
    {
        errSlip = std::max(errSlip, std::abs(slip[i]));
        devPlain = std::max(devPlain, std::abs(plain[i]));
    }
    EXPECT_LT(errSlip, 1e-12) << "free slip: uniform tangential flow";
    EXPECT_GT(devPlain, 1) << "without the normals the wall's values count";

    // A wall moving along its normal: the same as without the projection
    std::fill(uF.begin(), uF.end(), 0.0);
    for (label j = 0; j < nW; ++j) uW[2*j] = 0.3, uW[2*j + 1] = 0;
    const auto slipN = fw.divergence(uF, uW, normals);
    const auto plainN = fw.divergence(uF, uW, {});
    double maxDiv = 0;
    for (label i = 0; i < nF; ++i)
    {
        EXPECT_NEAR(slipN[i], plainN[i], 1e-10);
        maxDiv = std::max(maxDiv, std::abs(slipN[i]));
    }
    EXPECT_GT(maxDiv, 1) << "the wall's normal motion reaches the fluid";
}


TEST(ulphOperators, degenerateShapeTensorsFallBackWithoutNaN)
{
    // Particles on a line (a thin jet) and one isolated particle
    const double dx = 0.01;
    cloud c = jet(10, dx);
    c.x.push_back(5.0);
    c.x.push_back(5.0);
    c.V.assign(c.size(), dx*dx);

    autoPtr<smoothingKernel> W = ulphKernel(2, dx);
    const ownNeighbours own(c, *W);
    const std::vector<pairSource>& sources = own.sources;

    particleField Minv("Minv", particleField::kind::tensor, 2);
    const label nDegenerate = shapeTensorInverse<2>(c.size(), sources, Minv);
    EXPECT_EQ(nDegenerate, c.size());

    const double b[2] = {2.0, -3.0};
    const auto f = linearScalar(c, b);
    std::vector<double> grad(c.x.size());
    ulphOperators::gradient<2>
    (
        c.size(), sources, Minv.data(), f.data(), {f.data()}, grad.data()
    );
    for (label i = 0; i < 10; ++i)
    {
        EXPECT_NEAR(grad[2*i], 2.0, 1e-10) << "along the line";
        EXPECT_EQ(grad[2*i + 1], 0.0) << "across the line";
    }
    EXPECT_EQ(grad[20], 0.0) << "isolated";
    EXPECT_EQ(grad[21], 0.0) << "isolated";
    for (label k = 0; k < 4; ++k)
    {
        EXPECT_EQ(Minv(10, k), 0.0) << "isolated: M^-1 = 0";
        for (label i = 0; i < 10; ++i)
        {
            EXPECT_TRUE(std::isfinite(Minv(i, k))) << i;
        }
    }
}


TEST(ulphOperators, exactAfterTheParticlesMoved)
{
    // The operators read the relations' cached geometry: after the
    // particles moved (a shear and a stretch of a perturbed lattice) they
    // are exact at the new positions, with the lists rebuilt, and with the
    // lists of a skin kept and only the geometry updated
    const double dx = 0.01;
    const cloud c = lattice(2, 16, dx, 0.3);
    autoPtr<smoothingKernel> W = ulphKernel(2, dx);
    for (const bool rebuild : {true, false})
    {
        meshlessTest::pairFixture fx(2);
        fx.addBody(c.x, c.V);
        const neighbourRelation& rel = fx.relate(0, 0, *W, 0.2);
        const label pairsBefore = rel.nPairs();
        particleField& x = fx.x(0);
        for (label i = 0; i < c.size(); ++i)
        {
            x(i, 0) += 0.1*x(i, 1);
            x(i, 1) *= 1.05;
        }
        if (rebuild)
        {
            fx.rebuild();
        }
        else
        {
            fx.updateGeometry();
            EXPECT_EQ(rel.nPairs(), pairsBefore);
        }
        EXPECT_EQ(rel.builds(), rebuild ? 2 : 1);

        particleField Minv("Minv", particleField::kind::tensor, 2);
        EXPECT_EQ(shapeTensorInverse<2>(c.size(), fx.sources(0), Minv), 0);
        const double b[2] = {-0.5, 1.25};
        std::vector<double> f(c.size()), grad(2*c.size());
        for (label i = 0; i < c.size(); ++i)
        {
            f[i] = 3 + b[0]*x(i, 0) + b[1]*x(i, 1);
        }
        ulphOperators::gradient<2>
        (
            c.size(), fx.sources(0), Minv.data(), f.data(), {f.data()},
            grad.data()
        );
        for (label i = 0; i < c.size(); ++i)
        {
            EXPECT_NEAR(grad[2*i], b[0], 1e-10) << i << " rebuilt " << rebuild;
            EXPECT_NEAR(grad[2*i + 1], b[1], 1e-10) << i;
        }
    }
}
