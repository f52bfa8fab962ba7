// Unit tests for src/rbdPacking/world/simulationControls: defaults, the
// known entries (including every LCP solver's Coeffs), range errors

#include <gtest/gtest.h>
#include "simulationControls.H"
#include "lcpSolver.H"
#include "IStringStream.H"

using namespace Foam;

namespace
{
    dictionary parse(const std::string& text)
    {
        IStringStream is(text);
        return dictionary(is);
    }
}


TEST(simulationControls, defaults)
{
    const rbd::simulationControls c(parse(""));
    EXPECT_DOUBLE_EQ(c.deltaT, 0.025);
    EXPECT_DOUBLE_EQ(c.proximity, 0.1);
    EXPECT_DOUBLE_EQ(c.neighbourSkin, 0.5);
    EXPECT_DOUBLE_EQ(c.contactTolerance, 1e-4);
    EXPECT_EQ(c.sleepVelocity, 0);
}


TEST(simulationControls, acceptsTheCoeffsOfEverySelectableSolver)
{
    const wordList names(rbd::lcpSolver::coeffsNames());
    EXPECT_NE(names.find("blockPivotingCoeffs"), -1);
    EXPECT_NE(names.find("baraffCoeffs"), -1);
    for (const word& name : names)
    {
        const rbd::simulationControls c(parse(name + " { }"));
        EXPECT_TRUE(c.dict.found(name));
    }
}


TEST(simulationControlsDeath, unknownEntryListsTheAllowedOnes)
{
    EXPECT_EXIT
    (
        rbd::simulationControls(parse("dantzigCoeffs { }")),
        ::testing::ExitedWithCode(1),
        "Unknown entry 'dantzigCoeffs'(.|\n)*blockPivotingCoeffs"
    );
}


TEST(simulationControlsDeath, skinOutOfRange)
{
    EXPECT_EXIT
    (
        rbd::simulationControls(parse("neighbourSkin 10;")),
        ::testing::ExitedWithCode(1),
        "neighbourSkin(.|\n)*10"
    );
}


// ************************************************************************* //
