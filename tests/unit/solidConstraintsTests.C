/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Description
    Solid boundary conditions (solidConstraints) on particles of a unit cube
    built in memory: each particle takes the first constraint whose region
    holds it; clamped particles sit at X0 with no velocity; a prescribed
    displacement table moves its particles by d(t) with velocity d'(t); a
    load table is shared in proportion to mass (sum of m a = F(t)); only
    loaded and unconstrained particles are free; bad input names the
    constraint or keyword. On a face: clamped particles take minus their
    mirror images' displacement and velocity (the displacement of the odd
    extension vanishes on the face), a load's resultant acts on the face
    (sum m a = F, first moment at the face) through moving least squares
    weights. A motion constraint puts its particles where a
    solidBodyMotionFunction (a roll) takes them, with the velocity omega x r
    (1e-8), and at their reference positions at time 0. Contact with a
    wall (solidWallContact): a particle overlapping the floor by g is
    pushed out by k g along the face's normal, none that clears it, none
    above a gap in the floor (a notch: the tile test).

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testHelpers.H"
#include "unitCube.H"
#include "solidConstraints.H"
#include "smoothingKernel.H"
#include "septernion.H"
#include "solidWallContact.H"

using namespace Foam;
using namespace Foam::meshless;

namespace
{

//- A 3D lattice of 10^3 particles in the unit cube, unequal masses
struct solidBlock
{
    particleSet set;
    particleField* X0;

    solidBlock()
    :
        set("block", 3)
    {
        const std::vector<double> x =
            meshlessTest::latticePoints(3, 10, 0.1);
        set.resize(label(x.size())/3);
        particleField& pos = set.positions();
        for (label i = 0; i < set.size(); ++i)
        {
            for (label c = 0; c < 3; ++c) pos(i, c) = x[3*i + c] + 0.05;
        }
        particleField& m = set.addField("mass", particleField::kind::scalar);
        for (label i = 0; i < set.size(); ++i) m(i, 0) = 1 + 0.01*(i % 7);
        X0 = &set.addField("X0", particleField::kind::vector);
        std::copy(pos.data(), pos.data() + 3*set.size(), X0->data());
        set.addField("volume", particleField::kind::scalar).fill(1e-3);
    }
};


autoPtr<smoothingKernel> blockKernel()
{
    return smoothingKernel::New
    (
        meshlessTest::dictFrom("type cubicSpline; smoothingLengthRatio 1.2;"),
        3,
        0.1
    );
}

const char* constraintsText =
    "constraints"
    "{"
    "    root { type clamped; region { type box; min (-1 -1 -1); max (0.2 2 2); } }"
    "    push"
    "    {"
    "        type displacement;"
    "        region { type box; min (0.4 -1 -1); max (0.6 2 2); }"
    "        displacement table ((0 (0 0 0)) (1 (0 0.2 0)) (2 (0 0.2 0)));"
    "    }"
    "    tip"
    "    {"
    "        type load;"
    "        region { type box; min (0.8 -1 -1); max (2 2 2); }"
    "        force table ((0 (0 0 0)) (1 (0 0 -30)) (5 (0 0 -30)));"
    "    }"
    "}";

} // End anonymous namespace


TEST(solidConstraints, eachKindOnItsParticles)
{
    meshlessTest::unitCube cube(4);
    solidBlock b;
    const dictionary dict(meshlessTest::dictFrom(constraintsText));
    const solidConstraints sc(dict, b.set, *b.X0, cube.mesh);

    ASSERT_EQ(sc.size(), 3);
    EXPECT_EQ(sc.count()[0], 200);      // x = 0.05, 0.15
    EXPECT_EQ(sc.count()[1], 200);      // x = 0.45, 0.55
    EXPECT_EQ(sc.count()[2], 200);      // x = 0.85, 0.95

    particleField& x = b.set.positions();
    particleField& U = b.set.addField("U", particleField::kind::vector);
    x.fill(7);
    U.fill(3);
    sc.prescribe(0.5, *b.X0, x, U);

    scalar loadedMass = 0;
    label nFree = 0;
    for (label i = 0; i < b.set.size(); ++i)
    {
        const scalar X = (*b.X0)(i, 0);
        if (X < 0.2)
        {
            for (label c = 0; c < 3; ++c)
            {
                EXPECT_EQ(x(i, c), (*b.X0)(i, c));
                EXPECT_EQ(U(i, c), 0);
            }
            EXPECT_FALSE(sc.isFree(i));
        }
        else if (X > 0.4 && X < 0.6)
        {
            EXPECT_NEAR(x(i, 1) - (*b.X0)(i, 1), 0.1, 1e-12);
            EXPECT_NEAR(U(i, 1), 0.2, 1e-6);       // the table's slope
            EXPECT_NEAR(U(i, 0), 0, 1e-12);
            EXPECT_FALSE(sc.isFree(i));
        }
        else
        {
            EXPECT_EQ(x(i, 0), 7);                // untouched
            EXPECT_TRUE(sc.isFree(i));
            ++nFree;
            if (X > 0.8) loadedMass += b.set.field("mass")(i, 0);
        }
    }
    EXPECT_EQ(nFree, 600);

    // The load: uniform acceleration F/M, so sum m a = F
    particleField acc("acc", particleField::kind::vector, 3);
    acc.resize(b.set.size());
    acc.fill(0);
    sc.addLoads(2.0, acc);
    scalar Fz = 0;
    for (label i = 0; i < b.set.size(); ++i)
    {
        Fz += b.set.field("mass")(i, 0)*acc(i, 2);
        if ((*b.X0)(i, 0) < 0.8) EXPECT_EQ(acc(i, 2), 0);
    }
    EXPECT_NEAR(Fz, -30, 1e-12);
    EXPECT_NEAR(acc(b.set.size() - 1, 2), -30/loadedMass, 1e-12);
}


TEST(solidConstraints, onAFace)
{
    meshlessTest::unitCube cube(4);
    solidBlock b;
    const autoPtr<smoothingKernel> W = blockKernel();
    const dictionary dict(meshlessTest::dictFrom
    (
        "constraints"
        "{"
        "    root"
        "    {"
        "        type clamped;"
        "        region { type box; min (-1 -1 -1); max (0.2 2 2); }"
        "        face { point (0.2 0 0); normal (-2 0 0); }"
        "    }"
        "    tip"
        "    {"
        "        type load;"
        "        region { type box; min (0.8 -1 -1); max (2 2 2); }"
        "        face { point (1 0 0); normal (1 0 0); }"
        "        force table ((0 (0 0 0)) (1 (0 6 -30)) (5 (0 6 -30)));"
        "    }"
        "}"
    ));
    const solidConstraints sc(dict, b.set, *b.X0, cube.mesh, &W());

    // Any motion of the free particles: the clamped ones (x = 0.05, 0.15)
    // mirror those at x = 0.35, 0.25 with the opposite displacement
    particleField& x = b.set.positions();
    particleField& U = b.set.addField("U", particleField::kind::vector);
    for (label i = 0; i < b.set.size(); ++i)
    {
        for (label c = 0; c < 3; ++c)
        {
            x(i, c) = (*b.X0)(i, c) + 0.01*std::sin(7*i + c);
            U(i, c) = std::cos(3*i + c);
        }
    }
    sc.prescribe(0.5, *b.X0, x, U);
    label nMirrored = 0;
    for (label i = 0; i < b.set.size(); ++i)
    {
        if ((*b.X0)(i, 0) > 0.2) continue;
        ++nMirrored;
        EXPECT_FALSE(sc.isFree(i));
        for (label j = 0; j < b.set.size(); ++j)
        {
            if
            (
                std::abs((*b.X0)(j, 0) - (0.4 - (*b.X0)(i, 0))) < 1e-9
             && std::abs((*b.X0)(j, 1) - (*b.X0)(i, 1)) < 1e-9
             && std::abs((*b.X0)(j, 2) - (*b.X0)(i, 2)) < 1e-9
            )
            {
                for (label c = 0; c < 3; ++c)
                {
                    EXPECT_NEAR
                    (
                        x(i, c) - (*b.X0)(i, c),
                      -(x(j, c) - (*b.X0)(j, c)),
                        1e-15
                    );
                    EXPECT_EQ(U(i, c), -U(j, c));
                }
            }
        }
    }
    EXPECT_EQ(nMirrored, 200);

    // The load: the force F in total, its resultant on the face x = 1
    particleField acc("acc", particleField::kind::vector, 3);
    acc.resize(b.set.size());
    acc.fill(0);
    sc.addLoads(2.0, acc);
    const particleField& m = b.set.field("mass");
    scalar Fy = 0, Fz = 0, Mz = 0;
    for (label i = 0; i < b.set.size(); ++i)
    {
        Fy += m(i, 0)*acc(i, 1);
        Fz += m(i, 0)*acc(i, 2);
        Mz += m(i, 0)*acc(i, 2)*(*b.X0)(i, 0);
    }
    EXPECT_NEAR(Fy, 6, 1e-10);
    EXPECT_NEAR(Fz, -30, 1e-10);
    EXPECT_NEAR(Mz/Fz, 1.0, 1e-10);     // not 0.9, the loaded particles'

    // No particle at a clamped particle's mirror image: an error naming it
    const std::string noImage = meshlessTest::fatalMessage([&]()
    {
        solidBlock c;
        const dictionary d(meshlessTest::dictFrom
        (
            "constraints { root { type clamped;"
            " region { type box; min (-1 -1 -1); max (0.2 2 2); }"
            " face { point (0.23 0 0); normal (1 0 0); } } }"
        ));
        solidConstraints sc(d, c.set, *c.X0, cube.mesh, &W());
    });
    EXPECT_NE(noImage.find("mirror image"), std::string::npos) << noImage;
    EXPECT_NE(noImage.find("root"), std::string::npos) << noImage;
}


TEST(solidConstraints, badInputNamesTheConstraint)
{
    meshlessTest::unitCube cube(2);
    auto failure = [&](const std::string& text)
    {
        return meshlessTest::fatalMessage([&]()
        {
            solidBlock b;
            const dictionary d(meshlessTest::dictFrom(text));
            solidConstraints sc(d, b.set, *b.X0, cube.mesh);
        });
    };

    const std::string empty = failure
    (
        "constraints { nowhere { type clamped;"
        " region { type box; min (5 5 5); max (6 6 6); } } }"
    );
    EXPECT_NE(empty.find("nowhere"), std::string::npos) << empty;

    const std::string kind = failure
    (
        "constraints { root { type glued;"
        " region { type box; min (0 0 0); max (1 1 1); } } }"
    );
    EXPECT_NE(kind.find("glued"), std::string::npos) << kind;
    EXPECT_NE(kind.find("clamped"), std::string::npos) << kind;

    const std::string noForce = failure
    (
        "constraints { tip { type load;"
        " region { type box; min (0 0 0); max (1 1 1); } } }"
    );
    EXPECT_NE(noForce.find("force"), std::string::npos) << noForce;

    const std::string notDict = failure
    (
        "constraints { foot { type motion; motion rotatingMotion;"
        " region { type box; min (0 0 0); max (1 1 1); } } }"
    );
    EXPECT_NE(notDict.find("foot"), std::string::npos) << notDict;
    EXPECT_NE(notDict.find("'motion'"), std::string::npos) << notDict;

    const std::string unknown = failure
    (
        "constraints { foot { type motion;"
        " motion { solidBodyMotionFunction spinning; }"
        " region { type box; min (0 0 0); max (1 1 1); } } }"
    );
    EXPECT_NE(unknown.find("spinning"), std::string::npos) << unknown;
}


// ************************************************************************* //


TEST(solidConstraints, motionFollowsTheRigidTransformation)
{
    // A roll about the z axis through (0.5, 0, 0): theta(t) = 4 deg sin(w t)
    meshlessTest::unitCube cube(4);
    solidBlock b;
    const dictionary dict(meshlessTest::dictFrom
    (
        "constraints"
        "{"
        "    foot"
        "    {"
        "        type motion;"
        "        region { type box; min (-1 -1 -1); max (2 0.2 2); }"
        "        motion"
        "        {"
        "            solidBodyMotionFunction oscillatingRotatingMotion;"
        "            oscillatingRotatingMotionCoeffs"
        "            { origin (0.5 0 0); amplitude (0 0 4); omega 5; }"
        "        }"
        "    }"
        "}"
    ));
    const solidConstraints sc(dict, b.set, *b.X0, cube.mesh);
    ASSERT_EQ(sc.count()[0], 200);      // y = 0.05, 0.15

    particleField& x = b.set.positions();
    particleField& U = b.set.addField("U", particleField::kind::vector);
    x.fill(7);
    U.fill(3);
    const scalar t = 0.3;
    sc.prescribe(t, *b.X0, x, U);

    const scalar A = 4*constant::mathematical::pi/180, w = 5;
    const scalar theta = A*std::sin(w*t), omega = A*w*std::cos(w*t);
    const scalar c = std::cos(theta), s = std::sin(theta);
    label nMoved = 0;
    for (label i = 0; i < b.set.size(); ++i)
    {
        const scalar X = (*b.X0)(i, 0) - 0.5, Y = (*b.X0)(i, 1);
        if (Y > 0.2)
        {
            EXPECT_EQ(x(i, 0), 7);
            EXPECT_TRUE(sc.isFree(i));
            continue;
        }
        ++nMoved;
        EXPECT_FALSE(sc.isFree(i));
        // Rotation by theta about the origin's z axis (counterclockwise)
        const scalar rx = x(i, 0) - 0.5, ry = x(i, 1);
        const scalar sense = 1;
        EXPECT_NEAR(rx, c*X - sense*s*Y, 1e-12);
        EXPECT_NEAR(ry, sense*s*X + c*Y, 1e-12);
        EXPECT_NEAR(x(i, 2), (*b.X0)(i, 2), 1e-12);
        // Velocity omega x r (central difference over 2e-6 s)
        EXPECT_NEAR(U(i, 0), -sense*omega*ry, 1e-8);
        EXPECT_NEAR(U(i, 1), sense*omega*rx, 1e-8);
        EXPECT_NEAR(U(i, 2), 0, 1e-8);
    }
    EXPECT_EQ(nMoved, 200);

    // At t = 0 the particles are at their reference positions
    sc.prescribe(0, *b.X0, x, U);
    for (label i = 0; i < b.set.size(); ++i)
    {
        if ((*b.X0)(i, 1) > 0.2) continue;
        for (label k = 0; k < 3; ++k)
        {
            EXPECT_NEAR(x(i, k), (*b.X0)(i, k), 1e-14);
        }
    }
}


TEST(solidWallContact, pushesOverlappingParticlesOutOfTheFloor)
{
    // A floor below y = 0: 3 layers of wall particles of spacing 4 mm,
    // normals (0, -1) into it, depths (k + 1/2) dxw; a notch: no wall
    // particles at x in (-2, 6) mm (columns at 0 and 4 mm left out). Solid
    // particles of spacing 1 mm (half 0.5 mm) at
    //   0: x = -10 mm, y = 0.2 mm: overlaps by 0.3 mm -> k (-0.3 mm) (0,-1)
    //   1: x = -10 mm, y = 0.5 mm: touches, no force
    //   2: x = 13 mm, y = -1 mm: its extent 1.5 mm inside -> k (-1.5 mm)
    //   3: x = 2 mm, y = 0.2 mm: above the notch, no floor under it
    //   4: x = -10 mm, y = 3 mm: clear
    const double dxw = 0.004, ds = 0.001, k = 1e9;
    std::vector<double> wall, n, depth;
    for (int i = -10; i <= 10; ++i)
    {
        if (i == 0 || i == 1) continue;
        for (int l = 0; l < 3; ++l)
        {
            wall.push_back(i*dxw);
            wall.push_back(-(l + 0.5)*dxw);
            n.push_back(0);
            n.push_back(-1);
            depth.push_back((l + 0.5)*dxw);
        }
    }
    const std::vector<double> solid =
        {-0.010, 0.0002, -0.010, 0.0005, 0.013, -0.001, 0.002, 0.0002,
         -0.010, 0.003};
    meshlessTest::pairFixture fx(2);
    fx.addBody(solid, ds*ds);
    fx.addBody(wall, dxw*dxw);
    autoPtr<smoothingKernel> W
    (
        meshlessTest::kernel
        (
            2, dxw, "type cubicSpline; smoothingLengthRatio 1.2;"
        )
    );
    const neighbourRelation& rel = fx.relate(0, 1, *W);
    std::vector<double> acc(solid.size(), 0.0);
    const label touching = solidWallContact::addAccelerations<2>
    (
        rel, fx.x(0).data(), fx.x(1).data(), n.data(), depth.data(), dxw,
        0.5*ds, k, nullptr, acc.data()
    );
    EXPECT_EQ(touching, 2);
    const double expected[5][2] =
        {{0, k*0.0003}, {0, 0}, {0, k*0.0015}, {0, 0}, {0, 0}};
    for (int i = 0; i < 5; ++i)
    {
        EXPECT_EQ(acc[2*i], 0.0) << i;
        EXPECT_NEAR(acc[2*i + 1], expected[i][1], 1e-6*k*ds) << i;
    }

    // A particle that is not active (one that started against the wall)
    // is left alone
    std::fill(acc.begin(), acc.end(), 0.0);
    const std::vector<double> active = {0, 1, 1, 1, 1};
    EXPECT_EQ
    (
        (solidWallContact::addAccelerations<2>
        (
            rel, fx.x(0).data(), fx.x(1).data(), n.data(), depth.data(),
            dxw, 0.5*ds, k, active.data(), acc.data()
        )),
        1
    );
    EXPECT_EQ(acc[1], 0.0);

    // The gaps: -0.3 mm, 0 (touching), -1.5 mm, none (the notch), 2.5 mm
    std::vector<double> gap;
    solidWallContact::gaps<2>
    (
        rel, fx.x(0).data(), fx.x(1).data(), n.data(), depth.data(), dxw,
        0.5*ds, gap
    );
    const double expectedGap[5] = {-0.0003, 0, -0.0015, GREAT, 0.0025};
    for (int i = 0; i < 5; ++i)
    {
        EXPECT_NEAR(gap[i], expectedGap[i], 1e-12) << i;
    }
}
