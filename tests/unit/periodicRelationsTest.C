/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Description
    Periodic directions of the neighbour relations (periodicBox, the
    periodic cell list, neighbourList, neighbourRelation, sceneRelations):

      - on a periodic lattice (2D, 3D; with 3 or more cells per period and
        with 2, where a query visits every cell) every particle has the
        neighbour count and the sorted pair distances of an interior
        particle of a large non-periodic lattice;
      - inner relations on random points in a periodic box (every direction
        periodic, or only some; with and without a skin) are the
        brute-force minimum-image O(N^2) sets, x_ij the minimum image to
        1e-14, and the lists are the same for 1 and 2 OpenMP threads;
      - updateGeometry() after the points moved across the boundary (out
        of the box) gives the brute-force minimum-image x_ij;
      - a contact relation between two bodies in the periodic box likewise,
        at build and after a move;
      - periodicBox::wrap (what the scene applies to the bodies' positions)
        brings positions outside the box, also several periods away or a
        round-off below min, into [min, max) by whole periods;
      - a search radius not below half a period, and periodic directions
        set after the first relation, are errors.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testHelpers.H"
#include "neighbourRelation.H"
#include "sceneRelations.H"
#include <algorithm>
#include <cmath>
#include <random>

#ifdef _OPENMP
#include <omp.h>
#endif

using namespace Foam;
using namespace Foam::meshless;

namespace
{

const unsigned allGeometry =
    neighbourRelation::separation
  | neighbourRelation::kernelValue
  | neighbourRelation::kernelGradient;


//- A position field of dim components from flat coordinates
std::unique_ptr<particleField> field
(
    const label dim,
    const std::vector<double>& x
)
{
    std::unique_ptr<particleField> f
    (
        new particleField("positions", particleField::kind::vector, dim)
    );
    f->resize(label(x.size())/dim);
    std::copy(x.begin(), x.end(), f->data());
    return f;
}


//- Minimum image of b - a, written independently of periodicBox
void minimumImage
(
    const periodicBox& box,
    const label dim,
    const double* a,
    const double* b,
    double* d
)
{
    for (label c = 0; c < dim; ++c)
    {
        d[c] = b[c] - a[c];
        if (box.periodic(c))
        {
            const double L = box.max(c) - box.min(c);
            d[c] -= L*std::round(d[c]/L);
        }
    }
}


//- Minimum-image neighbours of every point of A among B's, O(N^2), sorted
std::vector<std::vector<label>> bruteForce
(
    const periodicBox& box,
    const particleField& xA,
    const particleField& xB,
    const double radius,
    const bool inner
)
{
    const label dim = xA.nComponents();
    std::vector<std::vector<label>> nbrs(xA.size());
    for (label i = 0; i < xA.size(); ++i)
    {
        for (label j = 0; j < xB.size(); ++j)
        {
            if (inner && i == j) continue;
            double d[3];
            minimumImage
            (
                box, dim, xA.data() + i*dim, xB.data() + j*dim, d
            );
            double r2 = 0;
            for (label c = 0; c < dim; ++c) r2 += d[c]*d[c];
            if (r2 <= radius*radius) nbrs[i].push_back(j);
        }
    }
    return nbrs;
}


//- Every cached x_ij, r, W, dW/dr is the minimum-image evaluation
void expectMinimumImageGeometry
(
    const periodicBox& box,
    const neighbourRelation& rel,
    const std::string& what
)
{
    const label dim = rel.dim();
    ASSERT_TRUE(rel.xij() && rel.r() && rel.w() && rel.dw()) << what;
    for (label i = 0; i < rel.size(); ++i)
    {
        for (label q = rel.offset(i); q < rel.offset(i + 1); ++q)
        {
            const label j = rel.index(q);
            double d[3];
            minimumImage
            (
                box, dim, rel.pointsA().data() + i*dim,
                rel.pointsB().data() + j*dim, d
            );
            double r2 = 0;
            for (label c = 0; c < dim; ++c)
            {
                ASSERT_NEAR(rel.xij()[q*dim + c], d[c], 1e-14)
                    << what << ": particle " << i << ", neighbour " << j;
                r2 += d[c]*d[c];
            }
            const double r = std::sqrt(r2);
            ASSERT_NEAR(rel.r()[q], r, 1e-14) << what << ": pair " << q;
            const double s = rel.kernel().W(0);
            ASSERT_NEAR(rel.w()[q], rel.kernel().W(r), 1e-12*s) << what;
            ASSERT_NEAR
            (
                rel.dw()[q], rel.kernel().dWdr(r), 1e-12*s/rel.kernel().h()
            ) << what;
        }
    }
}


//- The relation's rows are the brute-force minimum-image sets and its
//  geometry the minimum-image evaluation
void expectBruteForce
(
    const periodicBox& box,
    const neighbourRelation& rel,
    const std::string& what
)
{
    const auto expected = bruteForce
    (
        box, rel.pointsA(), rel.pointsB(), rel.cellsB().radius(), rel.inner()
    );
    ASSERT_EQ(rel.size(), rel.pointsA().size()) << what;
    label nPairs = 0;
    for (label i = 0; i < rel.size(); ++i)
    {
        std::vector<label> found
        (
            rel.indexData() + rel.offset(i),
            rel.indexData() + rel.offset(i + 1)
        );
        std::sort(found.begin(), found.end());
        ASSERT_EQ(found, expected[i]) << what << ": particle " << i;
        nPairs += label(found.size());
    }
    EXPECT_EQ(rel.nPairs(), nPairs) << what;
    EXPECT_GT(nPairs, 0) << what << ": a test with no pair tests nothing";
    expectMinimumImageGeometry(box, rel, what);
}


//- Number of pairs q = (i, j) whose minimum image differs from x_j - x_i
//  (the pairs across the period: a test must have some)
label pairsAcross(const neighbourRelation& rel)
{
    const label dim = rel.dim();
    label n = 0;
    for (label i = 0; i < rel.size(); ++i)
    {
        for (label q = rel.offset(i); q < rel.offset(i + 1); ++q)
        {
            const label j = rel.index(q);
            for (label c = 0; c < dim; ++c)
            {
                const double raw = rel.pointsB()(j, c) - rel.pointsA()(i, c);
                if (std::abs(raw - rel.xij()[q*dim + c]) > 1e-9)
                {
                    ++n;
                    break;
                }
            }
        }
    }
    return n;
}


//- Random points uniform in the box (non-periodic directions: [0, 1))
std::vector<double> pointsIn
(
    const periodicBox& box,
    const label dim,
    const label n,
    const unsigned seed
)
{
    std::mt19937_64 gen(seed);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<double> x(size_t(n)*dim);
    for (label i = 0; i < n; ++i)
    {
        for (label c = 0; c < dim; ++c)
        {
            const double lo = box.periodic(c) ? box.min(c) : 0;
            const double hi = box.periodic(c) ? box.max(c) : 1;
            x[i*dim + c] = lo + (hi - lo)*u(gen);
        }
    }
    return x;
}


//- Move every point by a random displacement of at most 'amount' per
//  component, and the points near the box's faces out of it; the number
//  of points left outside the box
label moveAcross
(
    const periodicBox& box,
    particleField& x,
    const double amount,
    const unsigned seed
)
{
    std::mt19937_64 gen(seed);
    std::uniform_real_distribution<double> u(-amount, amount);
    const label dim = x.nComponents();
    label outside = 0;
    for (label i = 0; i < x.size(); ++i)
    {
        bool out = false;
        for (label c = 0; c < dim; ++c)
        {
            double& v = x(i, c);
            v += u(gen);
            if (box.periodic(c))
            {
                // Points within 'amount' of a face cross it
                if (v - box.min(c) < amount) v = box.min(c) - 0.5*amount;
                else if (box.max(c) - v < amount) v = box.max(c) + 0.5*amount;
                out = out || v < box.min(c) || v >= box.max(c);
            }
        }
        outside += out;
    }
    return outside;
}


//- Sorted distances of particle i's pairs
std::vector<double> sortedDistances(const neighbourRelation& rel, const label i)
{
    std::vector<double> r(rel.r() + rel.offset(i), rel.r() + rel.offset(i + 1));
    std::sort(r.begin(), r.end());
    return r;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Lattices  * * * * * * * * * * * * * * * //

class periodicRelations : public ::testing::TestWithParam<label> {};

TEST_P(periodicRelations, latticeParticlesAllSeeAnInteriorNeighbourhood)
{
    const label dim = GetParam();
    const double dx = 0.01;
    autoPtr<smoothingKernel> W = meshlessTest::kernel
    (
        dim, dx, "type wendlandC2; smoothingLengthRatio 1.3;"
    );
    const double radius = W->radius();

    // Reference: the centre particle of a large non-periodic lattice
    const label nBig = 2*label(std::ceil(radius/dx)) + 5;
    std::unique_ptr<particleField> big =
        field(dim, meshlessTest::latticePoints(dim, nBig, dx));
    sceneRelations plain;
    neighbourRelation& ref =
        plain.inner("big", *big, *W, 0, false, allGeometry);
    plain.update(ref);
    const label centre = dim == 2
        ? (nBig/2)*nBig + nBig/2
        : ((nBig/2)*nBig + nBig/2)*nBig + nBig/2;
    const std::vector<double> expected = sortedDistances(ref, centre);
    ASSERT_GT(expected.size(), 8u);

    // nPerSide 6: periods of 2.3 radii, 2 cells (a query visits all);
    // 8 and 11: 3 and 4 cells, the stencil across the period
    for (const label nPerSide : {6, 8, 11})
    {
        const std::string what = "lattice " + std::to_string(nPerSide);
        periodicBox box;
        const double origin = -0.37;
        for (label d = 0; d < dim; ++d)
        {
            box.set(d, origin, origin + nPerSide*dx);
        }
        // Points at a quarter spacing from the cell faces, shifted into
        // the box
        std::vector<double> x = meshlessTest::latticePoints(dim, nPerSide, dx);
        for (double& v : x) v += origin + 0.25*dx;
        std::unique_ptr<particleField> xf = field(dim, x);

        sceneRelations relations;
        relations.setPeriodic(box, nullptr);
        neighbourRelation& rel =
            relations.inner("lattice", *xf, *W, 0, false, allGeometry);
        relations.update(rel);

        for (label i = 0; i < rel.size(); ++i)
        {
            const std::vector<double> r = sortedDistances(rel, i);
            ASSERT_EQ(r.size(), expected.size()) << what << ": particle " << i;
            for (size_t k = 0; k < r.size(); ++k)
            {
                ASSERT_NEAR(r[k], expected[k], 1e-12)
                    << what << ": particle " << i << ", pair " << k;
            }
        }
        EXPECT_GT(pairsAcross(rel), 0) << what;
        expectBruteForce(box, rel, what);
        if (nPerSide == 6)
        {
            EXPECT_EQ(rel.cellsB().nCells(0), 2) << what;
        }
        else
        {
            EXPECT_GE(rel.cellsB().nCells(0), 3) << what;
        }
    }
}


// * * * * * * * * * * * * * Random points, brute force  * * * * * * * * * //

TEST_P(periodicRelations, innerRelationIsTheMinimumImageBruteForce)
{
    const label dim = GetParam();
    const label n = dim == 2 ? 1200 : 1500;

    // Every direction periodic, then only x (and z in 3D), bounds off zero
    for (const bool all : {true, false})
    {
        periodicBox box;
        box.set(0, 0.2, 1.2);
        if (all) box.set(1, -0.5, 0.4);
        if (dim == 3) box.set(2, -1.0, -0.1);

        for (const double skin : {0.0, 0.3})
        {
            const std::string what =
                std::string(all ? "all periodic" : "some periodic")
              + ", skin " + std::to_string(skin);
            const double dx = dim == 2 ? 1/std::sqrt(n) : 1/std::cbrt(n);
            autoPtr<smoothingKernel> W = meshlessTest::kernel
            (
                dim, dx, "type wendlandC2; smoothingLengthRatio 1.3;"
            );
            std::unique_ptr<particleField> x =
                field(dim, pointsIn(box, dim, n, 7 + dim + 2*all));

            sceneRelations relations;
            relations.setPeriodic(box, nullptr);
            neighbourRelation& rel = relations.inner
            (
                "random", *x, *W, skin, true,
                allGeometry | neighbourRelation::reversePairs
            );
            relations.update();
            EXPECT_EQ(rel.builds(), 1) << what;
            expectBruteForce(box, rel, what);
            EXPECT_GT(pairsAcross(rel), 0) << what;

            // Reverse pairs: (i, j) and (j, i), x_ji = -x_ij
            for (label i = 0; i < rel.size(); ++i)
            {
                for (label q = rel.offset(i); q < rel.offset(i + 1); ++q)
                {
                    const label p = rel.reverse()[q];
                    ASSERT_GE(p, 0) << what;
                    ASSERT_EQ(rel.index(p), i) << what;
                    for (label c = 0; c < dim; ++c)
                    {
                        ASSERT_NEAR
                        (
                            rel.xij()[p*dim + c], -rel.xij()[q*dim + c], 1e-14
                        ) << what;
                    }
                }
            }
        }
    }
}


TEST_P(periodicRelations, listsAreTheSameForAnyThreadCount)
{
    #ifdef _OPENMP
    const label dim = GetParam();
    periodicBox box;
    for (label d = 0; d < dim; ++d) box.set(d, 0, 1);
    const label n = 2000;
    const double dx = dim == 2 ? 1/std::sqrt(n) : 1/std::cbrt(n);
    autoPtr<smoothingKernel> W = meshlessTest::kernel(dim, dx);
    std::unique_ptr<particleField> x = field(dim, pointsIn(box, dim, n, 5));

    std::vector<label> idx[2];
    std::vector<double> xij[2];
    const int old = omp_get_max_threads();
    for (const int t : {1, 2})
    {
        omp_set_num_threads(t);
        sceneRelations relations;
        relations.setPeriodic(box, nullptr);
        neighbourRelation& rel =
            relations.inner("threads", *x, *W, 0, true, allGeometry);
        relations.update();
        idx[t - 1].assign(rel.indexData(), rel.indexData() + rel.nPairs());
        xij[t - 1].assign(rel.xij(), rel.xij() + size_t(rel.nPairs())*dim);
    }
    omp_set_num_threads(old);
    EXPECT_EQ(idx[0], idx[1]);
    EXPECT_EQ(xij[0], xij[1]);
    #else
    GTEST_SKIP() << "built without OpenMP";
    #endif
}


// * * * * * * * * * * * * * * Moved points  * * * * * * * * * * * * * * * //

TEST_P(periodicRelations, updateGeometryAfterAMoveAcrossIsTheMinimumImage)
{
    const label dim = GetParam();
    const label n = dim == 2 ? 1000 : 1500;
    periodicBox box;
    box.set(0, -0.3, 0.7);
    box.set(1, 0, 1);
    if (dim == 3) box.set(2, 0.5, 1.5);
    const double dx = dim == 2 ? 1/std::sqrt(n) : 1/std::cbrt(n);
    autoPtr<smoothingKernel> W = meshlessTest::kernel
    (
        dim, dx, "type wendlandC2; smoothingLengthRatio 1.3;"
    );
    const double skin = 0.3;
    std::unique_ptr<particleField> x = field(dim, pointsIn(box, dim, n, 21));

    sceneRelations relations;
    relations.setPeriodic(box, nullptr);
    neighbourRelation& rel =
        relations.inner("moved", *x, *W, skin, true, allGeometry);
    relations.update();

    // Within the skin: each point at most skin*radius/4 per component
    const double amount = 0.25*skin*W->radius()/std::sqrt(double(dim));
    const label outside = moveAcross(box, *x, amount, 22);
    ASSERT_GT(outside, 0) << "no point left the box: the test tests nothing";

    rel.updateGeometry();
    expectMinimumImageGeometry(box, rel, "after the move");
    EXPECT_GT(pairsAcross(rel), 0);

    // A fresh build at the moved (unwrapped) points: the brute-force sets
    relations.update();
    EXPECT_EQ(rel.builds(), 2);
    expectBruteForce(box, rel, "rebuilt at points outside the box");
}


TEST_P(periodicRelations, contactRelationIsTheMinimumImageBruteForce)
{
    const label dim = GetParam();
    periodicBox box;
    box.set(0, 0, 1);
    box.set(1, -1, 0.2);
    if (dim == 3) box.set(2, 0, 0.8);
    const double dx = dim == 2 ? 0.03 : 0.07;
    autoPtr<smoothingKernel> W = meshlessTest::kernel
    (
        dim, dx, "type wendlandC2; smoothingLengthRatio 1.3;"
    );
    const double skin = 0.25;
    std::unique_ptr<particleField> a = field(dim, pointsIn(box, dim, 700, 31));
    std::unique_ptr<particleField> b = field(dim, pointsIn(box, dim, 900, 32));

    sceneRelations relations;
    relations.setPeriodic(box, nullptr);
    neighbourRelation& ab =
        relations.contact("a to b", *a, *b, *W, skin, true, true, allGeometry);
    neighbourRelation& ba =
        relations.contact("b to a", *b, *a, *W, skin, true, true, allGeometry);
    relations.update();
    EXPECT_FALSE(ab.inner());
    expectBruteForce(box, ab, "a among b");
    expectBruteForce(box, ba, "b among a");
    EXPECT_GT(pairsAcross(ab), 0);

    const double amount = 0.25*skin*W->radius()/std::sqrt(double(dim));
    ASSERT_GT(moveAcross(box, *a, amount, 33), 0);
    ASSERT_GT(moveAcross(box, *b, amount, 34), 0);
    ab.updateGeometry();
    ba.updateGeometry();
    expectMinimumImageGeometry(box, ab, "a among b, moved");
    expectMinimumImageGeometry(box, ba, "b among a, moved");

    relations.update();
    expectBruteForce(box, ab, "a among b, rebuilt");
    expectBruteForce(box, ba, "b among a, rebuilt");
}


INSTANTIATE_TEST_SUITE_P(dims, periodicRelations, ::testing::Values(2, 3));


// * * * * * * * * * * * * * * * * Wrapping  * * * * * * * * * * * * * * * //

TEST(periodicBox, wrapBringsPositionsIntoTheBoxByWholePeriods)
{
    periodicBox box;
    box.set(0, -0.3, 0.7);
    box.set(2, 1.0, 1.1);
    EXPECT_TRUE(box.any());
    EXPECT_FALSE(box.periodic(1));

    const double far[] =
    {
        -0.3, 0.7, 0.6999999999, -0.3 - 1e-17, -0.30000000000000004,
        0.7 + 1e-17, 3.25, -7.9, 1e6 + 0.1, -1e6, 0.2
    };
    std::vector<double> x;
    for (const double v : far)
    {
        x.push_back(v);           // x: period 1
        x.push_back(v);           // y: not periodic
        x.push_back(1.0 + 0.01*v); // z: period 0.1
    }
    const std::vector<double> before = x;
    const label n = label(x.size())/3;
    const label changed = box.wrap(x.data(), n, 3);
    EXPECT_GT(changed, 0);

    for (label i = 0; i < n; ++i)
    {
        for (label c = 0; c < 3; ++c)
        {
            const double v = x[i*3 + c];
            const double v0 = before[i*3 + c];
            if (!box.periodic(c))
            {
                EXPECT_EQ(v, v0) << "y is not periodic: unchanged";
                continue;
            }
            EXPECT_GE(v, box.min(c)) << "point " << i << " from " << v0;
            EXPECT_LT(v, box.max(c)) << "point " << i << " from " << v0;
            // By a whole number of periods (to round-off of the far ones)
            const double L = box.length(c);
            const double k = (v0 - v)/L;
            EXPECT_NEAR(k, std::round(k), 1e-6) << "point " << i;
            if (v0 >= box.min(c) && v0 < box.max(c))
            {
                EXPECT_EQ(v, v0) << "a point in the box does not move";
            }
        }
    }
    // x = max is min
    EXPECT_EQ(x[1*3], -0.3);

    // Wrapping twice changes nothing
    const std::vector<double> once = x;
    EXPECT_EQ(box.wrap(x.data(), n, 3), 0);
    EXPECT_EQ(x, once);
}


TEST(periodicBox, minimumImageIsTheNearestImage)
{
    periodicBox box;
    box.set(0, 0, 2);
    box.set(1, -1, 0);
    double d[2] = {1.9, -0.6};
    box.minimumImage<2>(d);
    EXPECT_NEAR(d[0], -0.1, 1e-15);
    EXPECT_NEAR(d[1], 0.4, 1e-15);
    double e[2] = {-5.3, 0.2};
    box.minimumImage<2>(e);
    EXPECT_NEAR(e[0], 0.7, 1e-14);
    EXPECT_NEAR(e[1], 0.2, 1e-15);
}


// * * * * * * * * * * * * * * * * Errors  * * * * * * * * * * * * * * * * //

TEST(periodicRelations, shortPeriodsAndLateSettingsAreErrors)
{
    const label dim = 2;
    const double dx = 0.1;
    autoPtr<smoothingKernel> W = meshlessTest::kernel
    (
        dim, dx, "type wendlandC2; smoothingLengthRatio 1.3;"
    );
    std::unique_ptr<particleField> x =
        field(dim, meshlessTest::latticePoints(dim, 5, dx));

    // Period 0.5 < 2 x 0.26 (support) x 1.0, with the skin 0.3 also
    const dictionary d = meshlessTest::dictFrom("x (0 0.5);");
    for (const double skin : {0.0, 0.3})
    {
        periodicBox box;
        box.set(0, 0, skin > 0 ? 0.6 : 0.5);
        sceneRelations relations;
        relations.setPeriodic(box, &d);
        const std::string msg = meshlessTest::fatalMessage([&]()
        {
            relations.inner("short", *x, *W, skin, true, allGeometry);
        });
        EXPECT_NE(msg.find("IOerror"), std::string::npos) << msg;
        EXPECT_NE(msg.find("periodic direction x"), std::string::npos) << msg;
        EXPECT_NE(msg.find("twice its search radius"), std::string::npos)
            << msg;
        EXPECT_NE(msg.find("'short'"), std::string::npos) << msg;
    }

    // Set after a relation exists
    sceneRelations relations;
    relations.inner("first", *x, *W, 0, true, allGeometry);
    periodicBox box;
    box.set(0, 0, 1);
    const std::string msg = meshlessTest::fatalMessage([&]()
    {
        relations.setPeriodic(box, nullptr);
    });
    EXPECT_NE(msg.find("expected them first"), std::string::npos) << msg;
}


// ************************************************************************* //
