/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Description
    Elastic constants: the derived moduli against textbook relations for the
    papers' materials, and the checks on nu and the moduli.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testHelpers.H"
#include "elasticConstants.H"

using namespace Foam;
using namespace Foam::meshless;

TEST(elasticConstants, steelFromEAndNu)
{
    // ISPH paper clamped beam: E = 210 GPa, nu = 0.3
    elasticConstants c(meshlessTest::dictFrom("E 210e9; nu 0.3;"));
    EXPECT_DOUBLE_EQ(c.G(), 210e9/2.6);
    EXPECT_DOUBLE_EQ(c.K(), 210e9/1.2);
    EXPECT_NEAR(c.lambda(), 210e9*0.3/(1.3*0.4), 1e-6*c.lambda());
    // lambda + 2G = K + 4G/3 (two forms of the P-wave modulus)
    EXPECT_NEAR(c.lambda() + 2*c.G(), c.M(), 1e-9*c.M());
}


TEST(elasticConstants, plateFromBulkModulus)
{
    // ISPH paper oscillating plate: K = 3.25 MPa, nu = 0.3975
    elasticConstants c(meshlessTest::dictFrom("K 3.25e6; nu 0.3975;"));
    EXPECT_NEAR(c.K(), 3.25e6, 1e-6);
    EXPECT_NEAR(c.E(), 3*3.25e6*(1 - 2*0.3975), 1e-6);
    EXPECT_NEAR(c.waveSpeed(1000), std::sqrt(c.M()/1000), 1e-12);
}


TEST(elasticConstants, flagFromShearModulus)
{
    // Turek-Hron FSI2 flag: mu_s = 0.5 MPa, nu = 0.4
    elasticConstants c(meshlessTest::dictFrom("G 0.5e6; nu 0.4;"));
    EXPECT_NEAR(c.G(), 0.5e6, 1e-6);
    EXPECT_NEAR(c.E(), 1.4e6, 1e-6);
}


TEST(elasticConstants, badInputNamesTheKeywordAndTheRange)
{
    for (const char* nu : {"0.5", "0.7", "-1", "-2"})
    {
        const std::string msg = meshlessTest::fatalMessage([&]
        {
            elasticConstants
            (
                meshlessTest::dictFrom(std::string("E 1e6; nu ") + nu + ";")
            );
        });
        EXPECT_NE(msg.find("IOerror"), std::string::npos) << msg;
        EXPECT_NE(msg.find("'nu'"), std::string::npos) << msg;
        EXPECT_NE(msg.find("(-1, 0.5)"), std::string::npos) << msg;
    }

    const std::string negativeE = meshlessTest::fatalMessage([]
    {
        elasticConstants(meshlessTest::dictFrom("E -1e6; nu 0.3;"));
    });
    EXPECT_NE(negativeE.find("'E'"), std::string::npos) << negativeE;
    EXPECT_NE(negativeE.find("> 0"), std::string::npos) << negativeE;

    const std::string two = meshlessTest::fatalMessage([]
    {
        elasticConstants(meshlessTest::dictFrom("E 1e6; K 1e6; nu 0.3;"));
    });
    EXPECT_NE(two.find("exactly one"), std::string::npos) << two;

    const std::string none = meshlessTest::fatalMessage([]
    {
        elasticConstants(meshlessTest::dictFrom("nu 0.3;"));
    });
    EXPECT_NE(none.find("exactly one"), std::string::npos) << none;
}
