/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Description
    Seeding: the lattice (origin, offset, round-off at box ends, 2D plane,
    one lattice for every box), readPositiveLabel, and on a unit cube of
    4^3 hexes built in memory (no case on disk): region selection and its
    errors, set operations against counts of lattice points, and the wall
    layers' count in closed form, distances and normals.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testHelpers.H"
#include "unitCube.H"
#include "seedLattice.H"
#include "seedRegion.H"
#include "wallLayers.H"
#include "dictionaryChecks.H"
#include "Time.H"
#include "polyMesh.H"
#include "cellModel.H"
#include "meshSearch.H"
#include <cmath>
#include <set>

using namespace Foam;
using namespace Foam::meshless;
using meshlessTest::unitCube;

namespace
{

//- A point for a test's failure message
std::string str(const point& p)
{
    return "(" + std::to_string(p.x()) + " " + std::to_string(p.y()) + " "
        + std::to_string(p.z()) + ")";
}


//- Index of a coordinate on a lattice, -1e9 when off the lattice
label latticeIndex(const scalar x, const scalar origin, const scalar dx)
{
    const scalar f = (x - origin)/dx - 0.5;
    const label i = label(std::round(f));
    return std::abs(f - i) < 1e-9 ? i : label(-1e9);
}


//- Lattice points of the cube at spacing dx, offset 1/2
pointField cubeLattice(const scalar dx)
{
    const seedLattice lattice(point::zero, dx, vector::uniform(0.5), 3, 0);
    return lattice.points(boundBox(point::zero, point::one));
}


//- Points of the lattice inside a region
std::set<label> selected
(
    const seedRegion& region,
    const unitCube& cube,
    const pointField& pts
)
{
    labelList cells(pts.size());
    forAll(pts, i) cells[i] = cube.search.findCell(pts[i]);
    boolList in;
    region.inside(pts, cells, in);
    std::set<label> s;
    forAll(pts, i)
    {
        if (in[i] && cells[i] >= 0) s.insert(i);
    }
    return s;
}

const char* sphereDict =
    "type sphere; centre (0.52 0.47 0.5); radius 0.33;";
const char* boxDict =
    "type box; min (0.11 0.23 0.05); max (0.61 0.84 0.72);";

bool inSphere(const point& p)
{
    return mag(p - point(0.52, 0.47, 0.5)) < 0.33;
}

bool inBox(const point& p)
{
    return boundBox(point(0.11, 0.23, 0.05), point(0.61, 0.84, 0.72))
        .contains(p);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Lattice * * * * * * * * * * * * * * * * //

TEST(seedLattice, pointsSitAtOriginPlusIndexPlusOffsetTimesSpacing)
{
    const seedLattice lattice
    (
        point(-1, 2, 0.5), 0.1, vector(0.5, 0.25, 0), 3, 0
    );
    const point p = lattice.at(3, -2, 7);
    EXPECT_NEAR(p.x(), -1 + 3.5*0.1, 1e-15);
    EXPECT_NEAR(p.y(), 2 + (-2 + 0.25)*0.1, 1e-15);
    EXPECT_NEAR(p.z(), 0.5 + 7*0.1, 1e-15);
    EXPECT_DOUBLE_EQ(lattice.cellVolume(), 0.1*0.1*0.1);
}


TEST(seedLattice, boxEndsOnLatticePointsSurviveRoundOff)
{
    // 0.3/0.1 is 2.9999999999999996: the point at 0.3 must be kept
    const seedLattice lattice(point::zero, 0.1, vector::zero, 3, 0);
    label lo, hi;
    lattice.range(0, 0.1, 0.3, lo, hi);
    EXPECT_EQ(lo, 1);
    EXPECT_EQ(hi, 3);

    const tmp<pointField> pts =
        lattice.points(boundBox(point(0.1, 0.1, 0.1), point(0.3, 0.3, 0.3)));
    EXPECT_EQ(pts().size(), 27);
}


TEST(seedLattice, twoDimensionalPointsLieInThePlane)
{
    const seedLattice lattice(point(0, 0, -3), 0.25, vector::uniform(0.5), 2,
                              0.125);
    const tmp<pointField> pts =
        lattice.points(boundBox(point(0, 0, -10), point(1, 0.5, 10)));
    ASSERT_EQ(pts().size(), 4*2);
    for (const point& p : pts())
    {
        EXPECT_EQ(p.z(), 0.125);
    }
    EXPECT_DOUBLE_EQ(lattice.cellVolume(), 0.25*0.25);
    EXPECT_EQ(lattice.at(1, 1, 99).z(), 0.125);
}


TEST(seedLattice, everyBoxSelectsFromTheSameLattice)
{
    // A box that starts off the lattice gets the case's lattice points,
    // not a lattice of its own: bodies line up whatever their regions
    const scalar dx = 0.1;
    const seedLattice lattice(point::zero, dx, vector::uniform(0.5), 3, 0);
    const tmp<pointField> sub =
        lattice.points(boundBox(point(0.33, 0.071, 0.5), point(0.9, 0.4, 1)));
    ASSERT_GT(sub().size(), 0);
    for (const point& p : sub())
    {
        for (direction d = 0; d < 3; ++d)
        {
            EXPECT_NE(latticeIndex(p[d], 0, dx), label(-1e9)) << str(p);
        }
    }
    // x in [0.33, 0.9]: 0.35 .. 0.85 (6), y in [0.071, 0.4]: 0.15 .. 0.35
    // (3), z in [0.5, 1]: 0.55 .. 0.95 (5)
    EXPECT_EQ(sub().size(), 6*3*5);
}


TEST(seedLattice, emptyWhenTheBoxHoldsNoPoint)
{
    const seedLattice lattice(point::zero, 1, vector::uniform(0.5), 3, 0);
    EXPECT_EQ
    (
        lattice.points(boundBox(point(0.6, 0, 0), point(1.4, 5, 5)))().size(),
        0
    );
}


TEST(dictionaryChecks, readPositiveLabelNamesKeywordAndExpectation)
{
    const dictionary good = meshlessTest::dictFrom("layers 3;");
    EXPECT_EQ(readPositiveLabel(good, "layers"), 3);

    const std::string msg = meshlessTest::fatalMessage([]
    {
        const dictionary d = meshlessTest::dictFrom("layers 0;");
        readPositiveLabel(d, "layers");
    });
    EXPECT_NE(msg.find("IOerror"), std::string::npos) << msg;
    EXPECT_NE(msg.find("layers"), std::string::npos) << msg;
    EXPECT_NE(msg.find("> 0"), std::string::npos) << msg;
}


// * * * * * * * * * * * * * * * * Regions * * * * * * * * * * * * * * * * //

TEST(seedRegion, surfacesAndSetOperationsSelectTheRightPoints)
{
    unitCube cube(4);
    const pointField pts(cubeLattice(0.05));
    ASSERT_EQ(pts.size(), 20*20*20);

    label nSphere = 0, nBox = 0, nBoth = 0;
    for (const point& p : pts)
    {
        nSphere += inSphere(p);
        nBox += inBox(p);
        nBoth += inSphere(p) && inBox(p);
    }
    ASSERT_GT(nBoth, 0);
    ASSERT_LT(nBoth, nBox);

    auto count = [&](const std::string& text)
    {
        const dictionary d = meshlessTest::dictFrom(text);
        return label(selected(seedRegion::New(d, cube.mesh)(), cube, pts)
            .size());
    };
    const std::string S = std::string("{") + sphereDict + "}";
    const std::string B = std::string("{") + boxDict + "}";

    EXPECT_EQ(count("type mesh;"), pts.size());
    EXPECT_EQ(count(sphereDict), nSphere);
    EXPECT_EQ(count(boxDict), nBox);
    EXPECT_EQ(count("type union; regions (" + S + B + ");"),
              nSphere + nBox - nBoth);
    EXPECT_EQ(count("type intersection; regions (" + S + B + ");"), nBoth);
    EXPECT_EQ(count("type difference; regions (" + S + B + ");"),
              nSphere - nBoth);
    EXPECT_EQ(count("type difference; regions ({type mesh;}" + B + S + ");"),
              pts.size() - nSphere - nBox + nBoth);
}


TEST(seedRegion, setOperationBoundsFollowTheOperation)
{
    unitCube cube(2);
    const std::string S = std::string("{") + sphereDict + "}";
    const std::string B = std::string("{") + boxDict + "}";
    auto bounds = [&](const std::string& text)
    {
        const dictionary d = meshlessTest::dictFrom(text);
        return seedRegion::New(d, cube.mesh)->bounds();
    };
    const boundBox sphere(point(0.19, 0.14, 0.17), point(0.85, 0.80, 0.83));
    const boundBox box(point(0.11, 0.23, 0.05), point(0.61, 0.84, 0.72));

    const boundBox u = bounds("type union; regions (" + S + B + ");");
    const boundBox i = bounds("type intersection; regions (" + S + B + ");");
    const boundBox d = bounds("type difference; regions (" + S + B + ");");
    for (direction c = 0; c < 3; ++c)
    {
        EXPECT_NEAR(u.min()[c], min(sphere.min()[c], box.min()[c]), 1e-12);
        EXPECT_NEAR(u.max()[c], max(sphere.max()[c], box.max()[c]), 1e-12);
        EXPECT_NEAR(i.min()[c], max(sphere.min()[c], box.min()[c]), 1e-12);
        EXPECT_NEAR(i.max()[c], min(sphere.max()[c], box.max()[c]), 1e-12);
        EXPECT_NEAR(d.min()[c], sphere.min()[c], 1e-12);
        EXPECT_NEAR(d.max()[c], sphere.max()[c], 1e-12);
    }
}


TEST(seedRegion, errorsNameWhatIsWrong)
{
    unitCube cube(1);
    auto message = [&](const std::string& text)
    {
        return meshlessTest::fatalMessage([&]
        {
            const dictionary d = meshlessTest::dictFrom(text);
            seedRegion::New(d, cube.mesh);
        });
    };

    const std::string unknown = message("type blob;");
    EXPECT_NE(unknown.find("IOerror"), std::string::npos) << unknown;
    for
    (
        const char* name
      : {"blob", "mesh", "cellZone", "union", "intersection", "difference",
         "searchableBox", "sphere", "cylinder", "triSurfaceMesh"}
    )
    {
        EXPECT_NE(unknown.find(name), std::string::npos) << name << unknown;
    }

    const std::string zone = message("type cellZone; zone water;");
    EXPECT_NE(zone.find("water"), std::string::npos) << zone;

    const std::string plate =
        message("type plate; origin (0 0 0); span (1 1 0);");
    EXPECT_NE(plate.find("encloses no volume"), std::string::npos) << plate;

    const std::string one = message("type union; regions ({type mesh;});");
    EXPECT_NE(one.find("at least two"), std::string::npos) << one;

    const std::string file = message("type triSurfaceMesh; file \"no.stl\";");
    EXPECT_NE(file.find("no.stl"), std::string::npos) << file;
    EXPECT_NE(file.find("'file'"), std::string::npos) << file;
}


// * * * * * * * * * * * * * * * Wall layers  * * * * * * * * * * * * * * * //

TEST(wallLayers, closedCubeCountDistancesAndNormals)
{
    // Unit cube at dx = 1/4, 2 layers: 2 layers behind each face (4x4),
    // along each edge the points of the 2x2 corner square within 2 dx
    // (3 of 4), at each corner those of the 2x2x2 cube (4 of 8)
    unitCube cube(4);
    const scalar dx = 0.25;
    const dictionary dict = meshlessTest::dictFrom("patches (walls); layers 2;");
    const wallLayers walls(dict, cube.mesh);
    const seedLattice lattice(point::zero, dx, vector::uniform(0.5), 3, 0);

    DynamicList<point> pts;
    DynamicList<vector> normals;
    DynamicList<scalar> dist;
    walls.seed(lattice, cube.search, pts, normals, dist);

    EXPECT_EQ(pts.size(), 6*2*16 + 12*3*4 + 8*4);
    forAll(pts, i)
    {
        // Nearest point of the cube and its distance, by hand
        const point q(min(max(pts[i], point::zero), point::one));
        const scalar d = mag(pts[i] - q);
        EXPECT_NEAR(dist[i], d, 1e-12) << str(pts[i]);
        EXPECT_LE(dist[i], 2*dx + 1e-12);
        EXPECT_NEAR(mag(normals[i]), 1, 1e-12);
        EXPECT_LT(mag(normals[i] - (pts[i] - q)/d), 1e-9) << str(pts[i]);
    }
}


TEST(wallLayers, patchAndLayerErrors)
{
    unitCube cube(1);
    const std::string patch = meshlessTest::fatalMessage([&]
    {
        const dictionary d = meshlessTest::dictFrom("patches (wal); layers 2;");
        wallLayers(d, cube.mesh);
    });
    EXPECT_NE(patch.find("wal "), std::string::npos) << patch;
    EXPECT_NE(patch.find("walls"), std::string::npos) << patch;

    const std::string layers = meshlessTest::fatalMessage([&]
    {
        const dictionary d = meshlessTest::dictFrom("patches (walls); layers 0;");
        wallLayers(d, cube.mesh);
    });
    EXPECT_NE(layers.find("layers"), std::string::npos) << layers;
    EXPECT_NE(layers.find("> 0"), std::string::npos) << layers;
}

// ************************************************************************* //
