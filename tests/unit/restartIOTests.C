/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Description
    Writing and reading clouds for restarts: the messages of damaged clouds
    (lagrangianIO), the restart manifest's check (restartManifest), and the
    atomic time directories (atomicTimeWriter), including a write killed
    half-way (a forked child that exits without committing).

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testHelpers.H"
#include "lagrangianIO.H"
#include "restartManifest.H"
#include "atomicTimeWriter.H"
#include "Time.H"
#include "OSspecific.H"
#include "OFstream.H"
#include "IFstream.H"
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

using namespace Foam;
using namespace Foam::meshless;
using meshlessTest::fatalMessage;

namespace
{

//- A case directory of its own per test, with a Time on it
struct testCase
{
    fileName root;
    word name;
    autoPtr<Time> runTime;

    explicit testCase(const word& caseName)
    :
        root("/tmp/meshlessUnitTests." + std::to_string(pid())),
        name(caseName)
    {
        rmDir(root/name, true);
        mkDir(root/name);
        dictionary controlDict;
        controlDict.add("deltaT", 0.1);
        controlDict.add("writeControl", "timeStep");
        controlDict.add("writeInterval", 1);
        controlDict.add("writePrecision", 17);
        runTime.reset
        (
            new Time(controlDict, root, name, "system", "constant", false, false)
        );
    }

    ~testCase()
    {
        rmDir(root/name, true);
    }

    Time& time() { return runTime(); }
    fileName path() const { return root/name; }
};


//- A 2D set of n particles with a scalar and a vector field
void fill(particleSet& set, const label n)
{
    set.resize(n);
    particleField& x = set.positions();
    particleField& p = set.addField("p", particleField::kind::scalar);
    particleField& U = set.addField("U", particleField::kind::vector);
    for (label i = 0; i < n; ++i)
    {
        x(i, 0) = 0.1*i;
        x(i, 1) = 0.01*i*i;
        p(i, 0) = 1000 + i;
        U(i, 0) = 0.5*i;
        U(i, 1) = -0.25*i;
    }
}


std::string readText(const fileName& f)
{
    std::ifstream is(f);
    std::stringstream ss;
    ss << is.rdbuf();
    return ss.str();
}


void writeText(const fileName& f, const std::string& text)
{
    std::ofstream os(f);
    os << text;
}


//- Write the set at time name t through an atomic write, as the time loop
//  does (with a manifest)
void writeTime(Time& runTime, const particleSet& set, const scalar t, const label index)
{
    runTime.setTime(t, index);
    atomicTimeWriter writer(runTime);
    writer.begin();
    {
        atomicTimeWriter::timeNameScope scope(runTime, writer.instance());
        writer.writeTimeState();
        lagrangianIO::write(set, runTime, runTime.timeName(), 0);
        UPtrList<const particleSet> sets(1);
        sets.set(0, &set);
        restartManifest::write(sets, runTime, runTime.timeName());
    }
    writer.commit();
}

} // End anonymous namespace


TEST(lagrangianIO, roundTripAndWrongLengthNamesFileFieldAndSizes)
{
    testCase c("wrongLength");
    particleSet set("water", 2);
    fill(set, 12);
    lagrangianIO::write(set, c.time(), "0", 0);

    particleSet back("water", 2);
    lagrangianIO::read(back, c.time(), "0");
    ASSERT_EQ(back.size(), 12);
    EXPECT_EQ(back.field("U")(4, 1), -1.0);
    EXPECT_EQ(back.field("p")(11, 0), 1011.0);
    EXPECT_EQ(back.positions()(3, 0), 0.1*3);

    // A field one entry short
    const fileName pFile(c.path()/"0/lagrangian/water/p");
    std::string text = readText(pFile);
    const size_t at = text.find("\n12\n(");
    ASSERT_NE(at, std::string::npos) << text;
    text.replace(at, 5, "\n11\n(");
    text.erase(text.find("1011\n"), 5);
    writeText(pFile, text);

    particleSet bad("water", 2);
    const std::string msg =
        fatalMessage([&]() { lagrangianIO::read(bad, c.time(), "0"); });
    EXPECT_NE(msg.find("IOerror"), std::string::npos) << msg;
    EXPECT_NE(msg.find("0/lagrangian/water/p]"), std::string::npos) << msg;
    EXPECT_NE(msg.find("Field p of cloud water has 11 entries"), std::string::npos)
        << msg;
    EXPECT_NE(msg.find("expected 12 entries"), std::string::npos) << msg;
}


TEST(lagrangianIO, idCountNamesFile)
{
    testCase c("idCount");
    particleSet set("gate", 2);
    fill(set, 3);
    lagrangianIO::write(set, c.time(), "0", 0);
    const fileName idFile(c.path()/"0/lagrangian/gate/id");
    std::string text = readText(idFile);
    const size_t at = text.find("3(0 1 2)");
    ASSERT_NE(at, std::string::npos) << text;
    text.replace(at, 8, "2(0 1)");
    writeText(idFile, text);

    particleSet bad("gate", 2);
    const std::string msg =
        fatalMessage([&]() { lagrangianIO::read(bad, c.time(), "0"); });
    EXPECT_NE(msg.find("[file: " + idFile), std::string::npos) << msg;
    EXPECT_NE(msg.find("id field of cloud gate has 2 entries"), std::string::npos)
        << msg;
    EXPECT_NE(msg.find("expected 3 ids"), std::string::npos) << msg;
}


TEST(lagrangianIO, truncatedPositionsNameFileAndParticle)
{
    testCase c("truncated");
    particleSet set("water", 2);
    fill(set, 6);
    lagrangianIO::write(set, c.time(), "0", 0);
    const fileName posFile(c.path()/"0/lagrangian/water/positions");
    const std::string text = readText(posFile);

    // Cut in the fourth particle's line
    const size_t line = text.find("(0.30000000000000004");
    ASSERT_NE(line, std::string::npos) << text;
    writeText(posFile, text.substr(0, line + 6));
    particleSet bad("water", 2);
    std::string msg =
        fatalMessage([&]() { lagrangianIO::read(bad, c.time(), "0"); });
    EXPECT_NE(msg.find("[file: " + posFile), std::string::npos) << msg;
    EXPECT_NE(msg.find("Particle 3 of 6"), std::string::npos) << msg;
    EXPECT_NE(msg.find("truncated"), std::string::npos) << msg;

    // Only the header
    writeText(posFile, text.substr(0, text.find("\n6\n")));
    msg = fatalMessage([&]() { lagrangianIO::read(bad, c.time(), "0"); });
    EXPECT_NE(msg.find("particle count"), std::string::npos) << msg;
    EXPECT_NE(msg.find("truncated"), std::string::npos) << msg;

    // Empty
    writeText(posFile, "");
    msg = fatalMessage([&]() { lagrangianIO::read(bad, c.time(), "0"); });
    EXPECT_NE(msg.find("[file: " + posFile), std::string::npos) << msg;
    EXPECT_NE(msg.find("header"), std::string::npos) << msg;
}


TEST(restartManifest, completeTimePassesMissingFieldNamesDirBodyFieldAndEarlier)
{
    testCase c("manifest");
    particleSet set("water", 2);
    fill(set, 4);
    writeTime(c.time(), set, 0.1, 1);
    writeTime(c.time(), set, 0.2, 2);

    // Complete: no error
    EXPECT_EQ(fatalMessage([&]()
    {
        restartManifest::checkBody(c.time(), "0.2", "water");
    }), "");
    EXPECT_TRUE(restartManifest::found(c.time(), "0.2"));
    EXPECT_EQ(restartManifest::problem(c.time(), "0.2", {"water"}), "");

    // A field deleted: the time, body, field, expectation and 0.1
    rm(c.path()/"0.2/lagrangian/water/U");
    std::string msg = fatalMessage([&]()
    {
        restartManifest::checkBody(c.time(), "0.2", "water");
    });
    EXPECT_NE(msg.find("IOerror"), std::string::npos) << msg;
    EXPECT_NE(msg.find("Restart time directory 0.2 is incomplete"), std::string::npos)
        << msg;
    EXPECT_NE(msg.find("body water"), std::string::npos) << msg;
    EXPECT_NE(msg.find("0.2/lagrangian/water/U"), std::string::npos) << msg;
    EXPECT_NE(msg.find("expected a vectorField of 4 entries"), std::string::npos)
        << msg;
    EXPECT_NE(msg.find("latest earlier complete time directory is 0.1"), std::string::npos)
        << msg;
    EXPECT_EQ(restartManifest::latestComplete(c.time(), "0.2", {"water"}), "0.1");

    // A field of the wrong length
    writeTime(c.time(), set, 0.2, 2);
    const fileName pFile(c.path()/"0.2/lagrangian/water/p");
    std::string text = readText(pFile);
    ASSERT_NE(text.find("4(1000 1001 1002 1003)"), std::string::npos) << text;
    text.replace(text.find("4(1000 1001 1002 1003)"), 22, "3(1000 1001 1002)");
    writeText(pFile, text);
    msg = fatalMessage([&]()
    {
        restartManifest::checkBody(c.time(), "0.2", "water");
    });
    EXPECT_NE(msg.find("it has 3 entries"), std::string::npos) << msg;
    EXPECT_NE(msg.find("a scalarField of 4 entries"), std::string::npos) << msg;

    // uniform/time is listed too
    writeTime(c.time(), set, 0.2, 2);
    rm(c.path()/"0.2/uniform/time");
    msg = fatalMessage([&]()
    {
        restartManifest::checkBody(c.time(), "0.2", "water");
    });
    EXPECT_NE(msg.find("uniform/time"), std::string::npos) << msg;

    // No earlier complete time
    rm(c.path()/"0.1/lagrangian/water/positions");
    msg = fatalMessage([&]()
    {
        restartManifest::checkBody(c.time(), "0.2", "water");
    });
    EXPECT_NE(msg.find("No earlier time directory is complete"), std::string::npos)
        << msg;
}


TEST(restartManifest, seededTimeIsNotChecked)
{
    testCase c("seeded");
    particleSet set("water", 2);
    fill(set, 3);
    lagrangianIO::write(set, c.time(), "0", 0);
    rm(c.path()/"0/lagrangian/water/U");
    EXPECT_FALSE(restartManifest::found(c.time(), "0"));
    EXPECT_EQ(fatalMessage([&]()
    {
        restartManifest::checkBody(c.time(), "0", "water");
    }), "");
}


TEST(atomicTimeWriter, commitRenamesReplacesAndPurges)
{
    testCase c("commit");
    particleSet set("water", 2);
    fill(set, 3);
    writeTime(c.time(), set, 0.1, 1);
    EXPECT_TRUE(isDir(c.path()/"0.1/lagrangian/water"));
    EXPECT_TRUE(isFile(c.path()/"0.1/uniform/time"));
    EXPECT_FALSE(isDir(c.path()/".incomplete.0.1", false));

    // The header names the time, not the temporary directory
    EXPECT_NE
    (
        readText(c.path()/"0.1/lagrangian/water/U").find("\"0.1/lagrangian/water\""),
        std::string::npos
    );

    // A time written again replaces the old content as a whole
    writeText(c.path()/"0.1/lagrangian/water/stale", "x");
    writeTime(c.time(), set, 0.1, 1);
    EXPECT_FALSE(isFile(c.path()/"0.1/lagrangian/water/stale"));
    EXPECT_TRUE(isFile(c.path()/"0.1/lagrangian/water/positions"));

    // purgeWrite 2 keeps the last two times this writer wrote
    const_cast<dictionary&>(c.time().controlDict()).set("purgeWrite", 2);
    atomicTimeWriter writer(c.time());
    for (label k = 2; k <= 4; ++k)
    {
        c.time().setTime(0.1*k, k);
        writer.begin();
        writer.writeTimeState();
        writer.commit();
    }
    EXPECT_TRUE(isDir(c.path()/"0.1"));     // not this writer's
    EXPECT_FALSE(isDir(c.path()/"0.2"));
    EXPECT_TRUE(isDir(c.path()/"0.3"));
    EXPECT_TRUE(isDir(c.path()/"0.4"));
}


TEST(atomicTimeWriter, killedWriteLeavesNoTimeAndIsRemovedNextStart)
{
    testCase c("killed");
    particleSet set("water", 2);
    fill(set, 50);
    writeTime(c.time(), set, 0.1, 1);

    // A child process writes 0.2 and dies before the commit (as if killed)
    std::cout.flush();
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0)
    {
        c.time().setTime(0.2, 2);
        atomicTimeWriter writer(c.time());
        writer.begin();
        {
            atomicTimeWriter::timeNameScope scope(c.time(), writer.instance());
            writer.writeTimeState();
            lagrangianIO::write(set, c.time(), c.time().timeName(), 0);
        }
        ::_exit(0);
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(WIFEXITED(status));

    // The time scan sees 0.1 only; the partial write is hidden
    const instantList times(Time::findTimes(c.path(), "constant"));
    ASSERT_EQ(times.size(), 1);
    EXPECT_EQ(times[0].name(), "0.1");
    EXPECT_FALSE(isDir(c.path()/"0.2"));
    EXPECT_TRUE(isDir(c.path()/".incomplete.0.2", false));

    // The next start removes it
    EXPECT_EQ(atomicTimeWriter::removeLeftovers(c.time()), 1);
    EXPECT_FALSE(isDir(c.path()/".incomplete.0.2", false));
    EXPECT_TRUE(isDir(c.path()/"0.1"));
}


// ************************************************************************* //
