/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Description
    Neighbour search against brute force (random, lattice, clustered sets,
    points exactly on cell faces and pairs exactly at the radius, within a
    body and between bodies), no allocation in steady state, and results
    independent of the number of OpenMP threads.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testHelpers.H"
#include "neighbourList.H"
#include "smoothingKernel.H"
#include <algorithm>
#include <cmath>

#ifdef _OPENMP
#include <omp.h>
#endif

using namespace Foam;
using namespace Foam::meshless;

namespace
{

double distSqr(const label dim, const double* a, const double* b)
{
    return dim == 2 ? distanceSqr<2>(a, b) : distanceSqr<3>(a, b);
}

//- Check a neighbour list against the O(N^2) answer
void expectBruteForce
(
    const label dim,
    const std::vector<double>& xA,
    const std::vector<double>& xB,
    const double radius,
    const bool self,
    const std::string& what
)
{
    const label nA = label(xA.size())/dim;
    const label nB = label(xB.size())/dim;

    cellLinkedList cells(dim, radius);
    cells.build(xB.data(), nB);
    neighbourList list;
    list.build(cells, xA.data(), nA, self);

    ASSERT_EQ(list.size(), nA);
    label nPairs = 0;
    for (label i = 0; i < nA; ++i)
    {
        std::vector<label> expected;
        for (label j = 0; j < nB; ++j)
        {
            if (self && i == j) continue;
            const double r2 =
                distSqr(dim, xA.data() + i*dim, xB.data() + j*dim);
            if (r2 <= radius*radius) expected.push_back(j);
        }
        std::vector<label> found(list.begin(i), list.end(i));
        std::sort(found.begin(), found.end());
        ASSERT_EQ(found, expected) << what << ": particle " << i;
        nPairs += label(expected.size());
    }
    EXPECT_EQ(list.nPairs(), nPairs) << what;
    EXPECT_GT(nPairs, 0) << what << ": a test with no pair tests nothing";
}

} // End anonymous namespace


class neighbourSearch : public ::testing::TestWithParam<label> {};

TEST_P(neighbourSearch, randomSetWithinABody)
{
    const label dim = GetParam();
    const auto x = meshlessTest::randomPoints(dim, 3000, 1.0, 1);
    expectBruteForce(dim, x, x, dim == 2 ? 0.03 : 0.08, true, "random");
}


TEST_P(neighbourSearch, latticeWithPairsExactlyAtTheRadius)
{
    // Spacing 0.25 and radius 0.5 are exact in binary: many pairs lie at
    // exactly the radius, and lattice points sit on the grid's cell faces
    const label dim = GetParam();
    const auto x = meshlessTest::latticePoints(dim, dim == 2 ? 40 : 14, 0.25);
    expectBruteForce(dim, x, x, 0.5, true, "lattice r = 2 dx");
    expectBruteForce(dim, x, x, 0.25, true, "lattice r = dx");
}


TEST_P(neighbourSearch, clusteredSetWithFarOutliers)
{
    const label dim = GetParam();
    const auto x = meshlessTest::clusteredPoints(dim, 4000, 5);
    expectBruteForce(dim, x, x, dim == 2 ? 0.01 : 0.03, true, "clustered");

    // The outliers must not blow the grid up
    cellLinkedList cells(dim, 0.01);
    cells.build(x.data(), label(x.size())/dim);
    EXPECT_LE
    (
        cells.nCellsTotal(),
        cellLinkedList::maxCellsPerParticle*label(x.size())/dim + 64
    );
}


TEST_P(neighbourSearch, pointsExactlyOnCellFacesOfAnotherBody)
{
    const label dim = GetParam();
    const double radius = 0.1;
    const auto xB = meshlessTest::randomPoints(dim, 2000, 1.0, 7);

    cellLinkedList cells(dim, radius);
    cells.build(xB.data(), label(xB.size())/dim);

    // Points on the faces, edges and corners of B's grid, inside and just
    // outside it
    std::vector<double> xA;
    const label n = dim == 2 ? 14 : 8;
    for (label k = 0; k < (dim == 3 ? n : 1); ++k)
    {
        for (label j = -1; j < n; ++j)
        {
            for (label i = -1; i < n; ++i)
            {
                xA.push_back(cells.origin(0) + i*cells.cellSize());
                xA.push_back(cells.origin(1) + j*cells.cellSize());
                if (dim == 3) xA.push_back(cells.origin(2) + k*cells.cellSize());
            }
        }
    }
    expectBruteForce(dim, xA, xB, radius, false, "on cell faces");
}


TEST_P(neighbourSearch, betweenBodiesOfDifferentResolution)
{
    // A fine solid inside a coarse fluid (multi-resolution), both ways
    const label dim = GetParam();
    const auto fluid = meshlessTest::randomPoints(dim, 2000, 1.0, 2);
    auto solid = meshlessTest::randomPoints(dim, 1500, 0.3, 3);
    for (auto& v : solid) v += 0.35;
    const double r = dim == 2 ? 0.05 : 0.1;
    expectBruteForce(dim, fluid, solid, r, false, "fluid-solid");
    expectBruteForce(dim, solid, fluid, r, false, "solid-fluid");
}


TEST_P(neighbourSearch, emptyAndSingleParticleSets)
{
    const label dim = GetParam();
    std::vector<double> none;
    std::vector<double> one(dim, 0.5);
    cellLinkedList cells(dim, 0.1);
    cells.build(none.data(), 0);
    neighbourList list;
    list.build(cells, one.data(), 1, false);
    EXPECT_EQ(list.nPairs(), 0);

    cells.build(one.data(), 1);
    list.build(cells, one.data(), 1, true);
    EXPECT_EQ(list.nNeighbours(0), 0);
    list.build(cells, one.data(), 1, false);
    EXPECT_EQ(list.nNeighbours(0), 1);
}


TEST_P(neighbourSearch, cellOrderSortsTheParticles)
{
    const label dim = GetParam();
    particleSet set("fluid", dim);
    const auto x = meshlessTest::randomPoints(dim, 5000, 1.0, 9);
    set.resize(5000);
    std::copy(x.begin(), x.end(), set.positions().data());

    cellLinkedList cells(dim, 0.05);
    cells.build(set.positions().data(), set.size());
    set.reorder(cells.order());
    cells.build(set.positions().data(), set.size());

    // After the reorder the particles are in cell order, and the search still
    // agrees with brute force
    for (label i = 1; i < set.size(); ++i)
    {
        ASSERT_LE(cells.cellOf(i - 1), cells.cellOf(i));
    }
    std::vector<double> xs(set.positions().data(), set.positions().data() + x.size());
    expectBruteForce(dim, xs, xs, 0.05, true, "cell-sorted");
}


TEST_P(neighbourSearch, rebuildInSteadyStateDoesNotAllocate)
{
    const label dim = GetParam();
    auto x = meshlessTest::randomPoints(dim, 20000, 1.0, 4);
    const label n = label(x.size())/dim;
    cellLinkedList cells(dim, 0.03);
    neighbourList list;
    cells.build(x.data(), n);
    list.build(cells, x.data(), n, true);

    const label* sorted = cells.sortedData();
    const label* starts = cells.cellStartData();
    const label* offsets = list.offsetData();
    const label* index = list.indexData();

    // Particles move a little (same count, similar neighbours): buffers stay
    for (label step = 0; step < 5; ++step)
    {
        for (auto& v : x) v *= 0.999;
        cells.build(x.data(), n);
        list.build(cells, x.data(), n, true);
        EXPECT_EQ(cells.sortedData(), sorted);
        EXPECT_EQ(cells.cellStartData(), starts);
        EXPECT_EQ(list.offsetData(), offsets);
        EXPECT_EQ(list.indexData(), index);
    }
}


#ifdef _OPENMP
TEST_P(neighbourSearch, resultsDoNotDependOnTheThreadCount)
{
    const label dim = GetParam();
    const auto x = meshlessTest::clusteredPoints(dim, 20000, 8);
    const label n = label(x.size())/dim;
    dictionary dict =
        meshlessTest::dictFrom("type wendlandC2; smoothingLength 0.01;");
    autoPtr<smoothingKernel> W = smoothingKernel::New(dict, dim, 0.01);

    auto run = [&](const int nThreads, std::vector<label>& idx,
                   std::vector<double>& sums)
    {
        omp_set_num_threads(nThreads);
        cellLinkedList cells(dim, W->radius());
        cells.build(x.data(), n);
        neighbourList list;
        list.build(cells, x.data(), n, false);
        idx.assign(list.indexData(), list.indexData() + list.nPairs());

        // A kernel sum per particle, gathered over its own list
        sums.assign(n, 0);
        #pragma omp parallel for schedule(static)
        for (label i = 0; i < n; ++i)
        {
            double s = 0;
            for (const label* j = list.begin(i); j != list.end(i); ++j)
            {
                s += W->W(std::sqrt(distSqr(dim, &x[i*dim], &x[*j*dim])));
            }
            sums[i] = s;
        }
    };

    const int maxThreads = omp_get_max_threads();
    std::vector<label> idx1, idx2;
    std::vector<double> sum1, sum2;
    run(1, idx1, sum1);
    run(2, idx2, sum2);
    omp_set_num_threads(maxThreads);

    ASSERT_EQ(idx1, idx2);
    for (label i = 0; i < n; ++i)
    {
        // Bitwise equal, not merely close
        ASSERT_EQ(sum1[i], sum2[i]) << "particle " << i;
    }
}
#endif


INSTANTIATE_TEST_SUITE_P
(
    dims,
    neighbourSearch,
    ::testing::Values(2, 3),
    [](const ::testing::TestParamInfo<label>& info)
    {
        return std::to_string(info.param) + "D";
    }
);
