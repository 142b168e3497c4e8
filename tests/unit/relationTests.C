/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Description
    Neighbour relations (neighbourRelation, sceneRelations) and the one
    pair loop (gather):

      - inner and contact relations in 2D and 3D, on random and clustered
        points (with far outliers), with and without a skin, and on
        lattices with pairs exactly at the search radius: the neighbour
        sets are the brute-force O(N^2) sets, and the cached x_ij, r, W and
        dW/dr are bitwise the direct evaluation;
      - reverse() maps pair (i, j) to (j, i);
      - updateGeometry() after the points moved (within the skin) is the
        direct evaluation at the new points, and holds every pair of a
        fresh relation with the same values;
      - sceneRelations: a static relation is built once by update(), a
        moving one once per update(), update(rel) builds a relation once per
        update, the same request gives the same relation;
      - pairKernel: 'own' is the body's kernel, 'mean' and 'max' give the
        mean and the larger smoothing length and symmetric relations (i of
        A sees j of B exactly when j sees i) for bodies of different
        spacing, where 'own' does not;
      - gather visits the sources in order and every row in the relation's
        order; its results (the ULPH shape tensor, divergence and pair
        forces) are bitwise the same for 1 and 2 OpenMP threads, and so is
        sumInOrder of per-particle forces.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testHelpers.H"
#include "neighbourRelation.H"
#include "sceneRelations.H"
#include "ulphEquations.H"
#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <set>
#include <utility>

#ifdef _OPENMP
#include <omp.h>
#endif

using namespace Foam;
using namespace Foam::meshless;

namespace
{

const unsigned allGeometry = meshlessTest::pairFixture::allGeometry;

//- The neighbours of every point of A among B's within radius (inner: A is
//  B, a point not its own neighbour), O(N^2), sorted
std::vector<std::vector<label>> bruteForce
(
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
            const double* a = xA.data() + i*dim;
            const double* b = xB.data() + j*dim;
            const double r2 =
                dim == 2 ? distanceSqr<2>(a, b) : distanceSqr<3>(a, b);
            if (r2 <= radius*radius) nbrs[i].push_back(j);
        }
    }
    return nbrs;
}


//- x_ij, r_ij as the relation computes them: x_j - x_i, sqrt of the sum of
//  squares in component order
double separation
(
    const particleField& xA,
    const particleField& xB,
    const label i,
    const label j,
    double* d
)
{
    double s = 0;
    for (label c = 0; c < xA.nComponents(); ++c)
    {
        d[c] = xB(j, c) - xA(i, c);
        s += d[c]*d[c];
    }
    return std::sqrt(s);
}


//- Every cached value of pair q = (i, j) equals the direct evaluation
void expectPairGeometry
(
    const neighbourRelation& rel,
    const label i,
    const label q,
    const std::string& what
)
{
    const label dim = rel.dim();
    const label j = rel.index(q);
    double d[3];
    const double r = separation(rel.pointsA(), rel.pointsB(), i, j, d);
    if (rel.xij())
    {
        for (label c = 0; c < dim; ++c)
        {
            EXPECT_EQ(rel.xij()[q*dim + c], d[c]) << what << ": pair " << q;
        }
        EXPECT_EQ(rel.r()[q], r) << what << ": pair " << q;
    }
    if (rel.w())
    {
        EXPECT_EQ(rel.w()[q], rel.kernel().W(r)) << what << ": pair " << q;
    }
    if (rel.dw())
    {
        EXPECT_EQ(rel.dw()[q], rel.kernel().dWdr(r)) << what << ": " << q;
    }
}


//- A relation's rows are the brute-force sets, in the relation's search
//  radius, and every pair's cached geometry (what 'cached' names, nothing
//  else) is the direct evaluation
void expectBruteForce
(
    const neighbourRelation& rel,
    const std::string& what,
    const unsigned cached = allGeometry
)
{
    const bool sep = cached & neighbourRelation::separation;
    EXPECT_EQ(rel.xij() != nullptr, sep) << what;
    EXPECT_EQ(rel.r() != nullptr, sep) << what;
    EXPECT_EQ
    (
        rel.w() != nullptr, bool(cached & neighbourRelation::kernelValue)
    ) << what;
    EXPECT_EQ
    (
        rel.dw() != nullptr, bool(cached & neighbourRelation::kernelGradient)
    ) << what;

    const auto expected = bruteForce
    (
        rel.pointsA(), rel.pointsB(), rel.cellsB().radius(), rel.inner()
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
        for (label q = rel.offset(i); q < rel.offset(i + 1); ++q)
        {
            expectPairGeometry(rel, i, q, what);
        }
    }
    EXPECT_EQ(rel.nPairs(), nPairs) << what;
    EXPECT_GT(nPairs, 0) << what << ": a test with no pair tests nothing";
}


//- Points of the named kind in [0, 1)^dim (clustered: with far outliers)
std::vector<double> points
(
    const label dim,
    const label n,
    const bool clustered,
    const unsigned seed
)
{
    return clustered
        ? meshlessTest::clusteredPoints(dim, n, seed)
        : meshlessTest::randomPoints(dim, n, 1.0, seed);
}

} // End anonymous namespace


// * * * * * * * * * * * * * Relations against brute force  * * * * * * * * //

class neighbourRelations : public ::testing::TestWithParam<label> {};

TEST_P(neighbourRelations, innerRelationIsTheBruteForceSet)
{
    const label dim = GetParam();
    const label n = dim == 2 ? 1500 : 2000;
    for (const bool clustered : {false, true})
    {
        for (const double skin : {0.0, 0.3})
        {
            const std::string what =
                std::string(clustered ? "clustered" : "random")
              + ", skin " + std::to_string(skin);
            // About 20 (2D) or 40 (3D) neighbours at the mean spacing of
            // the random points, fewer than 200 within the clusters
            const double dx =
                clustered
              ? (dim == 2 ? 0.01 : 0.02)
              : (dim == 2 ? 1/std::sqrt(n) : 1/std::cbrt(n));
            autoPtr<smoothingKernel> W = meshlessTest::kernel
            (
                dim, dx, "type wendlandC2; smoothingLengthRatio 1.3;"
            );
            meshlessTest::pairFixture fx(dim);
            fx.addBody(points(dim, n, clustered, 3 + dim), dx);
            const neighbourRelation& rel = fx.relate
            (
                0, 0, *W, skin, allGeometry | neighbourRelation::reversePairs
            );
            EXPECT_TRUE(rel.inner());
            EXPECT_EQ(rel.builds(), 1);
            EXPECT_DOUBLE_EQ(rel.cellsB().radius(), W->radius()*(1 + skin));
            expectBruteForce(rel, what);
        }
    }
}


TEST_P(neighbourRelations, contactRelationIsTheBruteForceSet)
{
    // Random points among clustered ones and the reverse, different
    // counts, with and without a skin
    const label dim = GetParam();
    for (const double skin : {0.0, 0.25})
    {
        const double dx = 0.03;
        autoPtr<smoothingKernel> W = meshlessTest::kernel(dim, dx);
        meshlessTest::pairFixture fx(dim);
        fx.addBody(points(dim, 700, false, 11), dx);
        fx.addBody(points(dim, 900, true, 12), dx);
        const neighbourRelation& ab = fx.relate(0, 1, *W, skin);
        const neighbourRelation& ba = fx.relate(1, 0, *W, skin);
        EXPECT_FALSE(ab.inner());
        expectBruteForce(ab, "random among clustered");
        expectBruteForce(ba, "clustered among random");

        // Contact of a set with a copy of itself: its own point counts
        meshlessTest::pairFixture same(dim);
        const std::vector<double> x = points(dim, 500, false, 13);
        same.addBody(x, dx);
        same.addBody(x, dx);
        const neighbourRelation& c = same.relate(0, 1, *W, skin);
        expectBruteForce(c, "a copy");
        for (label i = 0; i < c.size(); ++i)
        {
            EXPECT_TRUE
            (
                std::count
                (
                    c.indexData() + c.offset(i),
                    c.indexData() + c.offset(i + 1),
                    i
                ) == 1
            ) << "the copy of " << i << " is its neighbour";
        }
    }
}


TEST_P(neighbourRelations, pairsExactlyAtTheRadius)
{
    // A lattice of spacing 1/4 with a kernel of support 2 h = 1/2: the
    // search radius (with skins 0 and 1/2: 1/2 and 3/4) is a whole
    // number of spacings and every distance is exact; pairs at exactly the
    // radius are neighbours (W = 0 there), the next ones are not
    const label dim = GetParam();
    const double dx = 0.25;
    autoPtr<smoothingKernel> W = meshlessTest::kernel
    (
        dim, dx, "type wendlandC2; smoothingLengthRatio 1;"
    );
    ASSERT_EQ(W->radius(), 0.5);
    for (const double skin : {0.0, 0.5})
    {
        meshlessTest::pairFixture fx(dim);
        const label nSide = 9;
        fx.addBody(meshlessTest::latticePoints(dim, nSide, dx), 1.0);
        const neighbourRelation& rel = fx.relate(0, 0, *W, skin);
        ASSERT_EQ(rel.cellsB().radius(), skin == 0 ? 0.5 : 0.75);
        expectBruteForce(rel, "lattice, skin " + std::to_string(skin));

        // The middle particle: its neighbour along x at the radius
        const label k = skin == 0 ? 2 : 3;
        label mid = 0;
        for (label d = dim - 1; d >= 0; --d) mid = mid*nSide + nSide/2;
        bool atRadius = false, beyond = false;
        for (label q = rel.offset(mid); q < rel.offset(mid + 1); ++q)
        {
            atRadius = atRadius || rel.index(q) == mid + k;
            beyond = beyond || rel.index(q) == mid + k + 1;
            if (rel.index(q) == mid + k)
            {
                EXPECT_EQ(rel.r()[q], k*dx);
                EXPECT_EQ(rel.w()[q], 0.0);
                EXPECT_EQ(rel.dw()[q], 0.0);
            }
        }
        EXPECT_TRUE(atRadius) << "skin " << skin;
        EXPECT_FALSE(beyond) << "skin " << skin;
    }
}


TEST_P(neighbourRelations, reverseMapsEachPairToItsMirror)
{
    const label dim = GetParam();
    for (const bool clustered : {false, true})
    {
        const double dx = clustered ? 0.01 : 0.04;
        autoPtr<smoothingKernel> W = meshlessTest::kernel(dim, dx);
        meshlessTest::pairFixture fx(dim);
        fx.addBody(points(dim, 1200, clustered, 21), 1.0);
        const neighbourRelation& rel = fx.relate
        (
            0, 0, *W, 0.1, allGeometry | neighbourRelation::reversePairs
        );
        ASSERT_GT(rel.nPairs(), 0);
        const label* rev = rel.reverse();
        for (label i = 0; i < rel.size(); ++i)
        {
            for (label q = rel.offset(i); q < rel.offset(i + 1); ++q)
            {
                const label j = rel.index(q);
                const label p = rev[q];
                ASSERT_GE(p, rel.offset(j)) << "pair " << q;
                ASSERT_LT(p, rel.offset(j + 1)) << "pair " << q;
                EXPECT_EQ(rel.index(p), i);
                EXPECT_EQ(rev[p], q);
                for (label c = 0; c < dim; ++c)
                {
                    EXPECT_EQ(rel.xij()[p*dim + c], -rel.xij()[q*dim + c]);
                }
                EXPECT_EQ(rel.r()[p], rel.r()[q]);
                EXPECT_EQ(rel.w()[p], rel.w()[q]);
            }
        }
    }
}


TEST_P(neighbourRelations, updateGeometryAfterMovingIsAFreshComputation)
{
    // Lists with a skin of half the kernel's radius; every point moves by
    // at most a fifth of the radius, so no pair enters the kernel's
    // support unseen. updateGeometry keeps the lists and caches the
    // geometry at the new points, as a fresh relation computes it
    const label dim = GetParam();
    const double dx = 0.04;
    autoPtr<smoothingKernel> W = meshlessTest::kernel(dim, dx);
    meshlessTest::pairFixture fx(dim);
    fx.addBody(meshlessTest::randomPoints(dim, 1000, 1.0, 31), 1.0);
    neighbourRelation& rel = fx.relate
    (
        0, 0, *W, 0.5, allGeometry | neighbourRelation::reversePairs
    );
    const std::vector<label> before
    (
        rel.indexData(), rel.indexData() + rel.nPairs()
    );
    const std::vector<double> rBefore(rel.r(), rel.r() + rel.nPairs());

    std::mt19937_64 gen(32);
    std::uniform_real_distribution<double> u(-1, 1);
    particleField& x = fx.x(0);
    const double step = 0.2*W->radius()/std::sqrt(dim);
    std::vector<double> moved;
    for (label i = 0; i < x.size(); ++i)
    {
        for (label c = 0; c < dim; ++c)
        {
            x(i, c) += step*u(gen);
            moved.push_back(x(i, c));
        }
    }
    fx.updateGeometry();
    EXPECT_EQ(rel.builds(), 1);
    ASSERT_EQ(rel.nPairs(), label(before.size()));
    EXPECT_TRUE(std::equal(before.begin(), before.end(), rel.indexData()));
    label changed = 0;
    for (label i = 0; i < rel.size(); ++i)
    {
        for (label q = rel.offset(i); q < rel.offset(i + 1); ++q)
        {
            expectPairGeometry(rel, i, q, "updated");
            changed += rel.r()[q] != rBefore[q];
        }
    }
    EXPECT_GT(changed, rel.nPairs()/2) << "the points did move";

    // A fresh relation at the moved points, without a skin: each of its
    // pairs is one of the updated lists', with the same cached values
    meshlessTest::pairFixture fresh(dim);
    fresh.addBody(moved, 1.0);
    const neighbourRelation& f = fresh.relate(0, 0, *W);
    ASSERT_GT(f.nPairs(), 0);
    for (label i = 0; i < f.size(); ++i)
    {
        for (label p = f.offset(i); p < f.offset(i + 1); ++p)
        {
            const label* row = rel.indexData() + rel.offset(i);
            const label* end = rel.indexData() + rel.offset(i + 1);
            const label* it = std::find(row, end, f.index(p));
            ASSERT_NE(it, end) << "pair " << i << " " << f.index(p);
            const label q = label(it - rel.indexData());
            for (label c = 0; c < dim; ++c)
            {
                EXPECT_EQ(rel.xij()[q*dim + c], f.xij()[p*dim + c]);
            }
            EXPECT_EQ(rel.r()[q], f.r()[p]);
            EXPECT_EQ(rel.w()[q], f.w()[p]);
            EXPECT_EQ(rel.dw()[q], f.dw()[p]);
        }
    }

    // Rebuilt, the lists are the brute-force sets at the new points again
    fx.rebuild();
    EXPECT_EQ(rel.builds(), 2);
    expectBruteForce(rel, "rebuilt after moving");
}


TEST_P(neighbourRelations, onlyTheRequestedGeometryIsCached)
{
    const label dim = GetParam();
    autoPtr<smoothingKernel> W = meshlessTest::kernel(dim, 0.05);
    meshlessTest::pairFixture fx(dim);
    fx.addBody(meshlessTest::randomPoints(dim, 400, 1.0, 41), 1.0);
    neighbourRelation& none = fx.relate(0, 0, *W, 0, 0);
    EXPECT_GT(none.nPairs(), 0);
    EXPECT_EQ(none.xij(), nullptr);
    EXPECT_EQ(none.r(), nullptr);
    EXPECT_EQ(none.w(), nullptr);
    EXPECT_EQ(none.dw(), nullptr);

    neighbourRelation& values =
        fx.relate(0, 0, *W, 0, neighbourRelation::kernelValue);
    EXPECT_EQ(values.xij(), nullptr);
    EXPECT_NE(values.w(), nullptr);
    EXPECT_EQ(values.dw(), nullptr);

    // More geometry asked for later: cached from the next build
    none.cache(allGeometry);
    none.updateGeometry();
    expectBruteForce(none, "cached later");
}


INSTANTIATE_TEST_SUITE_P
(
    dims,
    neighbourRelations,
    ::testing::Values(2, 3),
    [](const ::testing::TestParamInfo<label>& info)
    {
        return std::to_string(info.param) + "D";
    }
);


// * * * * * * * * * * * * * * * * sceneRelations  * * * * * * * * * * * * * //

namespace
{

particleField pointField(const label dim, const std::vector<double>& x)
{
    particleField f("x", particleField::kind::vector, dim);
    f.resize(label(x.size())/dim);
    std::copy(x.begin(), x.end(), f.data());
    return f;
}

} // End anonymous namespace


TEST(sceneRelations, staticBuiltOnceMovingOncePerUpdate)
{
    const label dim = 2;
    autoPtr<smoothingKernel> W = meshlessTest::kernel(dim, 0.03);
    particleField wall =
        pointField(dim, meshlessTest::randomPoints(dim, 300, 1.0, 51));
    particleField fluid =
        pointField(dim, meshlessTest::randomPoints(dim, 400, 1.0, 52));

    sceneRelations rels;
    neighbourRelation& ww =
        rels.inner("wall", wall, *W, 0, false, allGeometry);
    neighbourRelation& ff =
        rels.inner("fluid", fluid, *W, 0.1, true, allGeometry);
    neighbourRelation& fw = rels.contact
    (
        "fluidWall", fluid, wall, *W, 0.1, true, false, allGeometry
    );
    neighbourRelation& wf = rels.contact
    (
        "wallFluid", wall, fluid, *W, 0, false, true,
        neighbourRelation::separation
    );
    EXPECT_EQ(rels.size(), 4);
    EXPECT_TRUE(ww.isStatic());
    EXPECT_FALSE(ff.isStatic());
    EXPECT_FALSE(fw.isStatic());
    EXPECT_FALSE(wf.isStatic());
    for (label r = 0; r < rels.size(); ++r) EXPECT_EQ(rels[r].builds(), 0);

    // The same points, kernel and radius: the same relation (more cached)
    EXPECT_EQ(&rels.inner("again", fluid, *W, 0.1, true, 0), &ff);
    EXPECT_EQ
    (
        &rels.contact
        (
            "again", wall, fluid, *W, 0, false, true,
            neighbourRelation::kernelValue
        ),
        &wf
    );
    EXPECT_NE(&rels.inner("other skin", fluid, *W, 0.2, true, 0), &ff);
    EXPECT_EQ(rels.size(), 5);

    // Set-up: one relation built now, once
    rels.update(ww);
    rels.update(ww);
    EXPECT_EQ(ww.builds(), 1);
    EXPECT_EQ(ff.builds(), 0);
    expectBruteForce(ww, "static wall");

    std::mt19937_64 gen(53);
    std::uniform_real_distribution<double> u(-0.01, 0.01);
    for (label step = 1; step <= 3; ++step)
    {
        // The fluid moves, the relations follow at the next update
        for (label i = 0; i < fluid.size(); ++i)
        {
            for (label c = 0; c < dim; ++c) fluid(i, c) += u(gen);
        }
        rels.update();
        EXPECT_EQ(ww.builds(), 1) << "step " << step;
        EXPECT_EQ(ff.builds(), step) << "step " << step;
        EXPECT_EQ(fw.builds(), step) << "step " << step;
        EXPECT_EQ(wf.builds(), step) << "step " << step;

        // Asking again within the step builds nothing
        rels.update(ff);
        rels.update(wf);
        EXPECT_EQ(ff.builds(), step);
        EXPECT_EQ(wf.builds(), step);

        expectBruteForce(ff, "moving fluid, step " + std::to_string(step));
        expectBruteForce(fw, "fluid-wall, step " + std::to_string(step));
        expectBruteForce
        (
            wf, "wall-fluid, step " + std::to_string(step),
            neighbourRelation::separation | neighbourRelation::kernelValue
        );
    }
}


TEST(sceneRelations, pairKernelRules)
{
    // Bodies of spacing 0.01 and 0.017 with the same kernel type: 'own' is
    // the asking body's kernel, 'mean' and 'max' the mean and the larger
    // smoothing length, of the asking body's type, one per pair of kernels
    const std::string dict = "type wendlandC2; smoothingLengthRatio 1.3;";
    const double dxA = 0.01, dxB = 0.017;
    autoPtr<smoothingKernel> Wa = meshlessTest::kernel(2, dxA, dict);
    autoPtr<smoothingKernel> Wb = meshlessTest::kernel(2, dxB, dict);
    const dictionary dA = meshlessTest::dictFrom(dict);
    const dictionary dB = meshlessTest::dictFrom(dict);

    sceneRelations rels;
    typedef sceneRelations::smoothingRule rule;
    EXPECT_EQ(&rels.pairKernel(dA, *Wa, *Wb, rule::own), Wa.get());
    EXPECT_EQ(&rels.pairKernel(dB, *Wb, *Wa, rule::own), Wb.get());
    EXPECT_EQ(&rels.pairKernel(dA, *Wa, *Wa, rule::mean), Wa.get())
        << "one smoothing length: the body's kernel";

    const smoothingKernel& meanAB = rels.pairKernel(dA, *Wa, *Wb, rule::mean);
    const smoothingKernel& meanBA = rels.pairKernel(dB, *Wb, *Wa, rule::mean);
    const smoothingKernel& maxAB = rels.pairKernel(dA, *Wa, *Wb, rule::max);
    const smoothingKernel& maxBA = rels.pairKernel(dB, *Wb, *Wa, rule::max);
    EXPECT_EQ(&rels.pairKernel(dA, *Wa, *Wb, rule::mean), &meanAB) << "kept";
    EXPECT_DOUBLE_EQ(meanAB.h(), 0.5*(Wa->h() + Wb->h()));
    EXPECT_EQ(meanAB.h(), meanBA.h());
    EXPECT_EQ(meanAB.radius(), meanBA.radius());
    EXPECT_DOUBLE_EQ(maxAB.h(), Wb->h());
    EXPECT_EQ(maxAB.h(), maxBA.h());
    EXPECT_EQ(maxAB.radius(), maxBA.radius());
    EXPECT_EQ(meanAB.dim(), 2);
    EXPECT_DOUBLE_EQ(meanAB.W(0.3*meanAB.h()), meanBA.W(0.3*meanBA.h()));

    // The asking body's kernel type
    autoPtr<smoothingKernel> Wg = meshlessTest::kernel(2, dxA);
    const smoothingKernel& mixed = rels.pairKernel
    (
        meshlessTest::dictFrom("type gaussian; smoothingLengthRatio 1.2;"),
        *Wg, *Wb, rule::max
    );
    EXPECT_DOUBLE_EQ(mixed.h(), Wb->h());
    EXPECT_DOUBLE_EQ(mixed.radius(), 3*Wb->h()) << "a Gaussian's horizon";

    // Relations of the two bodies both ways (two interleaved random sets)
    particleField xA =
        pointField(2, meshlessTest::randomPoints(2, 3000, 0.5, 61));
    particleField xB =
        pointField(2, meshlessTest::randomPoints(2, 1000, 0.5, 62));
    const auto pairs =
        [&](const smoothingKernel& Wab, const smoothingKernel& Wba)
    {
        sceneRelations r;
        neighbourRelation& ab =
            r.contact("AB", xA, xB, Wab, 0, false, false, 0);
        neighbourRelation& ba =
            r.contact("BA", xB, xA, Wba, 0, false, false, 0);
        r.update();
        std::set<std::pair<label, label>> sAB, sBA;
        for (label i = 0; i < ab.size(); ++i)
        {
            for (label q = ab.offset(i); q < ab.offset(i + 1); ++q)
            {
                sAB.insert({i, ab.index(q)});
            }
        }
        for (label j = 0; j < ba.size(); ++j)
        {
            for (label q = ba.offset(j); q < ba.offset(j + 1); ++q)
            {
                sBA.insert({ba.index(q), j});
            }
        }
        EXPECT_GT(sAB.size(), 0u);
        return std::make_pair(sAB, sBA);
    };
    const auto mean = pairs(meanAB, meanBA);
    EXPECT_TRUE(mean.first == mean.second) << "mean: symmetric";
    const auto max = pairs(maxAB, maxBA);
    EXPECT_TRUE(max.first == max.second) << "max: symmetric";
    EXPECT_GT(max.first.size(), mean.first.size());
    const auto own = pairs(*Wa, *Wb);
    EXPECT_FALSE(own.first == own.second) << "own: each side its own h";
    EXPECT_LT(own.first.size(), own.second.size());
}


// * * * * * * * * * * * * * * * * * gather  * * * * * * * * * * * * * * * * //

namespace
{

//- Records the (source, neighbour) sequence a particle's sum visits
struct visitOrder
{
    typedef std::vector<std::pair<label, label>> sum;
    typedef label source;
    std::vector<sum>* out;

    sum start(const label) const { return sum(); }
    source at(const pairSource&, const label k) const { return k; }
    void pair
    (
        sum& s, const source& k, const pairView& v, const label,
        const label q
    ) const
    {
        s.push_back({k, v.j[q]});
    }
    void finish(const label i, sum& s) const { (*out)[i] = s; }
};


//- What the ULPH fluid computes from one cloud with a wall, bit by bit
struct ulphResults
{
    std::vector<label> index;
    std::vector<double> Minv, div, dU, f;
    std::vector<char> degenerate;
    Eigen::Vector2d total;
};


ulphResults ulphOnRandomCloud(const int nThreads)
{
    #ifdef _OPENMP
    omp_set_num_threads(nThreads);
    #endif
    const double dx = 0.02;
    autoPtr<smoothingKernel> W = meshlessTest::kernel(2, dx);
    meshlessTest::pairFixture fx(2);
    std::vector<double> wall;
    for (label i = -2; i < 55; ++i)
    {
        for (label r = 1; r <= 3; ++r)
        {
            wall.push_back(i*dx);
            wall.push_back(-r*dx);
        }
    }
    fx.addBody(meshlessTest::randomPoints(2, 2500, 1.0, 71), dx*dx);
    fx.addBody(wall, dx*dx);
    fx.relate(0, 0, *W);
    const neighbourRelation& fw = fx.relate(0, 1, *W);
    const label n = fx.size(0), nW = fx.size(1);
    const std::vector<pairSource> sources = fx.sources(0);

    std::mt19937_64 gen(72);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<double> U(2*n), UW(2*nW), rho(n), S(4*n), SW(4*nW);
    for (auto& v : U) v = u(gen);
    for (auto& v : UW) v = u(gen);
    for (auto& v : rho) v = 1000*(1 + 0.01*u(gen));
    for (auto& v : SW) v = 1e3*u(gen);

    ulphResults res;
    const neighbourRelation& ff = *sources[0].rel;
    res.index.assign(ff.indexData(), ff.indexData() + ff.nPairs());
    res.Minv.resize(4*n);
    res.degenerate.resize(n);
    ulphOperators::shapeTensorInverse<2>
    (
        n, sources, res.Minv.data(), 0, res.degenerate.data()
    );
    res.div.resize(n);
    ulphOperators::divergence<2>
    (
        n, sources, res.Minv.data(), U.data(), {U.data(), UW.data()},
        res.div.data()
    );
    std::vector<double> p(n);
    for (auto& v : p) v = 1e3*u(gen);
    ulphEquations::stressTimesMinv<2>
    (
        n, p.data(), nullptr, res.Minv.data(), S.data()
    );
    res.dU.resize(2*n);
    ulphEquations::momentum<2>
    (
        n, rho.data(), S.data(), sources, {S.data(), SW.data()},
        res.dU.data()
    );
    res.f.resize(2*n);
    ulphEquations::ghostForceOnFluid<2>
    (
        n, fx.V(0), S.data(), fx.source(fw), SW.data(), res.f.data()
    );
    res.total = sumInOrder<2>(res.f.data(), n);
    return res;
}


template<class T>
bool bitwiseEqual(const std::vector<T>& a, const std::vector<T>& b)
{
    return a.size() == b.size()
        && std::memcmp(a.data(), b.data(), a.size()*sizeof(T)) == 0;
}

} // End anonymous namespace


TEST(gather, visitsSourcesInOrderAndRowsInTheRelationsOrder)
{
    autoPtr<smoothingKernel> W = meshlessTest::kernel(3, 0.05);
    meshlessTest::pairFixture fx(3);
    fx.addBody(meshlessTest::randomPoints(3, 500, 1.0, 81), 1.0);
    fx.addBody(meshlessTest::clusteredPoints(3, 300, 82), 1.0);
    fx.relate(0, 0, *W);
    fx.relate(0, 1, *W);
    fx.relate(0, 1, *W, 0.5);
    const std::vector<pairSource> sources = fx.sources(0);
    ASSERT_EQ(sources.size(), 3u);

    std::vector<visitOrder::sum> seen(fx.size(0));
    gather(fx.size(0), sources, visitOrder{&seen});
    label nPairs = 0;
    for (label i = 0; i < fx.size(0); ++i)
    {
        visitOrder::sum expected;
        for (label k = 0; k < 3; ++k)
        {
            const neighbourRelation& rel = *sources[k].rel;
            for (label q = rel.offset(i); q < rel.offset(i + 1); ++q)
            {
                expected.push_back({k, rel.index(q)});
            }
        }
        EXPECT_EQ(seen[i], expected) << "particle " << i;
        nPairs += label(expected.size());
    }
    EXPECT_GT(nPairs, 0);

    // One relation's rows alone
    const neighbourRelation& fw = *sources[1].rel;
    std::vector<visitOrder::sum> one(fx.size(0));
    gather(fw, fx.V(1), visitOrder{&one});
    for (label i = 0; i < fx.size(0); ++i)
    {
        ASSERT_EQ(label(one[i].size()), fw.offset(i + 1) - fw.offset(i));
        for (const auto& kj : one[i]) EXPECT_EQ(kj.first, 0);
    }
}


TEST(gather, resultsDoNotDependOnTheThreadCount)
{
    #ifdef _OPENMP
    const int saved = omp_get_max_threads();
    #endif
    const ulphResults one = ulphOnRandomCloud(1);
    const ulphResults two = ulphOnRandomCloud(2);
    #ifdef _OPENMP
    omp_set_num_threads(saved);
    #endif

    EXPECT_GT(one.index.size(), 0u);
    EXPECT_TRUE(bitwiseEqual(one.index, two.index)) << "neighbour lists";
    EXPECT_TRUE(bitwiseEqual(one.degenerate, two.degenerate));
    EXPECT_TRUE(bitwiseEqual(one.Minv, two.Minv)) << "shape tensors";
    EXPECT_TRUE(bitwiseEqual(one.div, two.div)) << "divergence";
    EXPECT_TRUE(bitwiseEqual(one.dU, two.dU)) << "momentum";
    EXPECT_TRUE(bitwiseEqual(one.f, two.f)) << "ghost forces";
    EXPECT_EQ(one.total(0), two.total(0)) << "sumInOrder";
    EXPECT_EQ(one.total(1), two.total(1)) << "sumInOrder";
    EXPECT_NE(one.total.norm(), 0.0) << "a wall force to sum";

    // sumInOrder is the plain sum in particle order
    double s[2] = {0, 0};
    for (size_t i = 0; i < one.f.size()/2; ++i)
    {
        s[0] += one.f[2*i];
        s[1] += one.f[2*i + 1];
    }
    EXPECT_EQ(one.total(0), s[0]);
    EXPECT_EQ(one.total(1), s[1]);
}


TEST(gather, sumInOrderIsDeterministic)
{
    // Terms of very different magnitudes, where the order of a sum shows
    std::mt19937_64 gen(91);
    std::uniform_real_distribution<double> u(-1, 1);
    const label n = 10000;
    std::vector<double> v(3*n);
    for (size_t k = 0; k < v.size(); ++k)
    {
        v[k] = u(gen)*std::pow(10.0, k % 17);
    }
    const Eigen::Vector3d a = sumInOrder<3>(v.data(), n);
    const Eigen::Vector3d b = sumInOrder<3>(v.data(), n);
    double s[3] = {0, 0, 0};
    for (label i = 0; i < n; ++i)
    {
        for (label d = 0; d < 3; ++d) s[d] += v[3*i + d];
    }
    for (label d = 0; d < 3; ++d)
    {
        EXPECT_EQ(a(d), b(d));
        EXPECT_EQ(a(d), s[d]) << "particle order";
    }
    EXPECT_EQ(sumInOrder<2>(v.data(), 0).norm(), 0.0);
}


// ************************************************************************* //
