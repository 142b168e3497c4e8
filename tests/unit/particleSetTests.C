/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Description
    particleSet: structure-of-arrays storage, stable ids through reordering,
    fields by name, 2D stored as 2D.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testHelpers.H"
#include <algorithm>
#include <random>

using namespace Foam;
using namespace Foam::meshless;

TEST(particleSet, dimensionSetsComponentCounts)
{
    particleSet s2("fluid", 2);
    particleSet s3("solid", 3);
    EXPECT_EQ(s2.positions().nComponents(), 2);
    EXPECT_EQ(s3.positions().nComponents(), 3);
    EXPECT_EQ(s2.addField("stress", particleField::kind::tensor).nComponents(), 4);
    EXPECT_EQ(s3.addField("stress", particleField::kind::tensor).nComponents(), 9);
    EXPECT_EQ(s2.addField("p", particleField::kind::scalar).nComponents(), 1);
}


TEST(particleSet, resizeGivesUniqueIdsAndZeroFields)
{
    particleSet s("fluid", 2);
    s.addField("p", particleField::kind::scalar);
    s.resize(10);
    s.resize(4);
    s.resize(7);
    std::vector<label> ids = s.ids();
    std::sort(ids.begin(), ids.end());
    EXPECT_TRUE(std::adjacent_find(ids.begin(), ids.end()) == ids.end());
    for (label i = 0; i < s.size(); ++i)
    {
        EXPECT_EQ(s.field("p")(i, 0), 0.0);
    }
}


TEST(particleSet, fieldAddedLaterHasTheSetsSize)
{
    particleSet s("fluid", 3);
    s.resize(5);
    particleField& U = s.addField("U", particleField::kind::vector);
    EXPECT_EQ(U.size(), 5);
    // Adding again returns the same field, not a copy
    EXPECT_EQ(&s.addField("U", particleField::kind::vector), &U);
}


TEST(particleSet, reorderKeepsIdsWithTheirData)
{
    particleSet s("fluid", 2);
    s.addField("p", particleField::kind::scalar);
    s.resize(100);
    for (label i = 0; i < s.size(); ++i)
    {
        // Data that identifies the particle by its id
        s.positions()(i, 0) = s.ids()[i];
        s.positions()(i, 1) = -s.ids()[i];
        s.field("p")(i, 0) = 10.0*s.ids()[i];
    }

    std::vector<label> order(s.size());
    for (label i = 0; i < s.size(); ++i) order[i] = i;
    std::mt19937 gen(3);
    std::shuffle(order.begin(), order.end(), gen);

    const std::vector<label> idsBefore = s.ids();
    s.reorder(order);

    for (label i = 0; i < s.size(); ++i)
    {
        const label id = s.ids()[i];
        EXPECT_EQ(id, idsBefore[order[i]]);
        EXPECT_EQ(s.positions()(i, 0), id);
        EXPECT_EQ(s.positions()(i, 1), -id);
        EXPECT_EQ(s.field("p")(i, 0), 10.0*id);
        EXPECT_EQ(s.findId(id), i);
    }
}


TEST(particleSet, reorderDoesNotMoveFieldStorage)
{
    particleSet s("fluid", 3);
    s.resize(1000);
    const double* before = s.positions().data();
    std::vector<label> order(s.size());
    for (label i = 0; i < s.size(); ++i) order[i] = s.size() - 1 - i;
    s.reorder(order);
    s.reorder(order);
    EXPECT_EQ(s.positions().data(), before);
}


TEST(particleSet, setIdsContinuesAfterTheLargest)
{
    particleSet s("fluid", 2);
    s.resize(3);
    s.setIds({7, 2, 40});
    s.resize(4);
    EXPECT_EQ(s.ids()[3], 41);
}


TEST(particleSet, errorsNameWhatIsWrong)
{
    particleSet s("fluid", 2);
    s.addField("p", particleField::kind::scalar);

    const std::string missing =
        meshlessTest::fatalMessage([&]{ s.field("rho"); });
    EXPECT_NE(missing.find("rho"), std::string::npos) << missing;
    EXPECT_NE(missing.find("positions"), std::string::npos) << missing;

    const std::string kindClash = meshlessTest::fatalMessage
    (
        [&]{ s.addField("p", particleField::kind::vector); }
    );
    EXPECT_NE(kindClash.find("scalar"), std::string::npos) << kindClash;

    const std::string badDim =
        meshlessTest::fatalMessage([]{ particleSet bad("x", 4); });
    EXPECT_NE(badDim.find("expected 2 or 3"), std::string::npos) << badDim;
}
