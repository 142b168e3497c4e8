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


TEST(particleSet, appendCopiesAndRemoveMarkedKeepEveryFieldWithItsId)
{
    particleSet s("fluid", 2);
    s.addField("p", particleField::kind::scalar);
    s.addField("U", particleField::kind::vector);
    s.resize(50);
    auto setData = [&](const label i, const double v)
    {
        s.positions()(i, 0) = v;
        s.positions()(i, 1) = -v;
        s.field("p")(i, 0) = 10*v;
        s.field("U")(i, 0) = 100*v;
        s.field("U")(i, 1) = 1000*v;
    };
    for (label i = 0; i < s.size(); ++i) setData(i, s.ids()[i]);

    // Copies of 3 particles: fresh ids, the originals' data
    const std::vector<label> from{4, 17, 4};
    const label first = s.appendCopies(from);
    EXPECT_EQ(first, 50);
    EXPECT_EQ(s.size(), 53);
    EXPECT_EQ(s.nextId(), 53);
    for (label k = 0; k < 3; ++k)
    {
        const label i = first + k;
        EXPECT_EQ(s.ids()[i], 50 + k);
        EXPECT_EQ(s.positions()(i, 0), s.positions()(from[k], 0));
        EXPECT_EQ(s.field("U")(i, 1), s.field("U")(from[k], 1));
        // Make each copy identify itself by its id again
        setData(i, s.ids()[i]);
    }

    // Remove every third particle: the others keep order, ids and data
    std::vector<char> marks(s.size(), 0);
    std::vector<label> kept;
    for (label i = 0; i < s.size(); ++i)
    {
        if (i % 3 == 0) marks[i] = 1;
        else kept.push_back(s.ids()[i]);
    }
    EXPECT_EQ(s.removeMarked(marks), 18);
    ASSERT_EQ(s.size(), label(kept.size()));
    for (label i = 0; i < s.size(); ++i)
    {
        const label id = s.ids()[i];
        EXPECT_EQ(id, kept[i]);
        EXPECT_EQ(s.positions()(i, 0), id);
        EXPECT_EQ(s.positions()(i, 1), -id);
        EXPECT_EQ(s.field("p")(i, 0), 10.0*id);
        EXPECT_EQ(s.field("U")(i, 0), 100.0*id);
        EXPECT_EQ(s.field("U")(i, 1), 1000.0*id);
        EXPECT_EQ(s.field("U").size(), s.size());
    }

    // Removed ids are never handed out again
    EXPECT_EQ(s.nextId(), 53);
    s.resize(s.size() + 1);
    EXPECT_EQ(s.ids().back(), 53);
}


TEST(particleSet, migrationEditsKeepEveryFieldWithItsId)
{
    // What a parallel run does to a set: another processor's particles
    // appended with their ids (halo or migrated), halos truncated, the
    // leaving particles removed with the holes filled from the end
    particleSet s("fluid", 2);
    particleField& p = s.addField("p", particleField::kind::scalar);
    particleField& U = s.addField("U", particleField::kind::vector);
    s.addScratchField("B", particleField::kind::tensor);
    s.resize(10);
    const label next = s.nextId();
    auto fill = [&](const label i)
    {
        const label id = s.ids()[i];
        p(i, 0) = 10.0*id;
        U(i, 0) = id + 0.5;
        U(i, 1) = -id;
        s.field("B")(i, 3) = 3.0*id;
        for (label d = 0; d < 2; ++d) s.positions()(i, d) = id*(d + 1);
    };
    for (label i = 0; i < s.size(); ++i) fill(i);

    const std::vector<label> theirs{100, 57, 203};
    const label first = s.appendIds(theirs.data(), label(theirs.size()));
    EXPECT_EQ(first, 10);
    EXPECT_EQ(s.size(), 13);
    EXPECT_EQ(s.nextId(), next);        // others' ids are not fresh ids
    for (label k = 0; k < 3; ++k)
    {
        EXPECT_EQ(s.ids()[first + k], theirs[k]);
        EXPECT_EQ(p(first + k, 0), 0.0);
        fill(first + k);
    }

    s.truncate(11);
    EXPECT_EQ(s.size(), 11);
    EXPECT_EQ(U.size(), 11);
    EXPECT_EQ(s.field("B").size(), 11);

    // Remove 0, 4 and the last (10): each other particle keeps its values
    s.removeUnordered({0, 4, 10});
    ASSERT_EQ(s.size(), 8);
    std::vector<label> ids = s.ids();
    std::sort(ids.begin(), ids.end());
    for (label i = 0; i < s.size(); ++i)
    {
        const label id = s.ids()[i];
        EXPECT_EQ(p(i, 0), 10.0*id);
        EXPECT_EQ(U(i, 0), id + 0.5);
        EXPECT_EQ(U(i, 1), -id);
        EXPECT_EQ(s.field("B")(i, 3), 3.0*id);
        EXPECT_EQ(s.positions()(i, 1), 2.0*id);
    }
    // The ids left are the first set's but the removed ones
    std::vector<label> seeded;
    for (label k = 0; k < 10; ++k) seeded.push_back(next - 10 + k);
    std::vector<label> kept;
    for (label k = 0; k < 10; ++k)
    {
        if (k != 0 && k != 4) kept.push_back(seeded[k]);
    }
    EXPECT_EQ(ids, kept);
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
