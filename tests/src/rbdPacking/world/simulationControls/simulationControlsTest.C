// Unit tests for src/rbdPacking/world/simulationControls: defaults, the
// known entries (including every LCP solver's Coeffs), range errors, presets

#include <gtest/gtest.h>
#include "simulationControls.H"
#include "lcpSolver.H"
#include "IStringStream.H"
#include "OStringStream.H"

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
    EXPECT_DOUBLE_EQ(c.sleepVelocity, 0.001);
    EXPECT_DOUBLE_EQ(c.wakeVelocity, 0.3);
    EXPECT_EQ(c.restingFriction, "coupled");
    EXPECT_EQ(c.frictionRounds, 4);
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


TEST(simulationControls, endTimeGivenOrLeftToTheLoading)
{
    EXPECT_FALSE(rbd::simulationControls(parse("")).endTimeGiven);
    const rbd::simulationControls c(parse("endTime 12;"));
    EXPECT_TRUE(c.endTimeGiven);
    EXPECT_DOUBLE_EQ(c.endTime, 12);
}


TEST(simulationControls, wakeVelocityDefaultIsAtLeastRestingVelocity)
{
    EXPECT_DOUBLE_EQ
    (
        rbd::simulationControls(parse("restingVelocity 0.5;")).wakeVelocity,
        0.5
    );
}


TEST(simulationControlsDeath, wakeVelocityBelowRestingVelocity)
{
    EXPECT_EXIT
    (
        rbd::simulationControls(parse("wakeVelocity 0.001;")),
        ::testing::ExitedWithCode(1),
        "wakeVelocity 0.001(.|\n)*restingVelocity"
    );
}


TEST(simulationControls, presetDefaultIsTheBuiltInDefaults)
{
    const rbd::simulationControls none(parse(""));
    const rbd::simulationControls def(parse("preset default;"));
    EXPECT_EQ(none.preset, "default");
    EXPECT_EQ(def.preset, "default");
    EXPECT_EQ(def.deltaT, none.deltaT);
    EXPECT_EQ(def.restingVelocity, none.restingVelocity);
    EXPECT_EQ(def.proximity, none.proximity);
    EXPECT_EQ(def.contactTolerance, none.contactTolerance);
    EXPECT_EQ
    (
        rbd::lcpSolver::New(def.dict)->type(),
        rbd::lcpSolver::New(none.dict)->type()
    );
}


TEST(simulationControls, presetsOrderTheAccuracyKnobs)
{
    // Every knob of fast is looser than the default, of accurate tighter
    const rbd::simulationControls f(parse("preset fast;"));
    const rbd::simulationControls d(parse(""));
    const rbd::simulationControls a(parse("preset accurate;"));
    EXPECT_GT(f.deltaT, d.deltaT);
    EXPECT_LT(a.deltaT, d.deltaT);
    EXPECT_GT(f.restingVelocity, d.restingVelocity);
    EXPECT_LT(a.restingVelocity, d.restingVelocity);
    EXPECT_GT(f.contactTolerance, d.contactTolerance);
    EXPECT_LT(a.contactTolerance, d.contactTolerance);
    EXPECT_GE(f.proximity, d.proximity);
    EXPECT_LE(a.proximity, d.proximity);
    EXPECT_LT(f.frictionRounds, d.frictionRounds);
    EXPECT_GE(a.frictionRounds, d.frictionRounds);

    // ... and the values are the listed ones
    for (const word& name : rbd::simulationControls::presets)
    {
        const dictionary p(rbd::simulationControls::presetEntries(name));
        const rbd::simulationControls c(parse("preset " + name + ";"));
        EXPECT_EQ(c.preset, name);
        EXPECT_EQ(c.deltaT, p.getOrDefault<scalar>("deltaT", d.deltaT));
        EXPECT_EQ
        (
            c.proximity, p.getOrDefault<scalar>("proximity", d.proximity)
        );
    }
}


TEST(simulationControls, explicitEntriesOverrideThePreset)
{
    const rbd::simulationControls f
    (
        parse
        (
            "preset fast; deltaT 0.001; lcpSolver baraff;"
            "blockPivotingCoeffs { maxIterations 7; }"
        )
    );
    const dictionary p(rbd::simulationControls::presetEntries("fast"));
    EXPECT_EQ(f.deltaT, 0.001);
    EXPECT_EQ(f.restingVelocity, p.get<scalar>("restingVelocity"));
    EXPECT_EQ(rbd::lcpSolver::New(f.dict)->type(), "baraff");

    // A Coeffs block overrides coefficient by coefficient
    const rbd::simulationControls a
    (
        parse("preset accurate; blockPivotingCoeffs { maxIterations 7; }")
    );
    const dictionary& coeffs = a.dict.subDict("blockPivotingCoeffs");
    EXPECT_EQ(coeffs.get<label>("maxIterations"), 7);
    EXPECT_EQ
    (
        coeffs.get<scalar>("tolerance"),
        rbd::simulationControls::presetEntries("accurate")
            .subDict("blockPivotingCoeffs").get<scalar>("tolerance")
    );
    const rbd::simulationControls t
    (
        parse("preset accurate; blockPivotingCoeffs { tolerance 1e-5; }")
    );
    EXPECT_EQ
    (
        t.dict.subDict("blockPivotingCoeffs").get<scalar>("tolerance"), 1e-5
    );
}


TEST(simulationControls, logEchoesThePresetAndTheEffectiveValues)
{
    const rbd::simulationControls c(parse("preset fast; deltaT 0.04;"));
    OStringStream os;
    c.write(os);
    const std::string out(os.str());
    EXPECT_NE(out.find("preset"), std::string::npos);
    EXPECT_NE(out.find("fast"), std::string::npos);
    EXPECT_NE(out.find("0.04"), std::string::npos);
    const dictionary echoed(parse(out));
    EXPECT_EQ(echoed.get<word>("preset"), "fast");
    EXPECT_EQ(echoed.get<scalar>("deltaT"), 0.04);
    EXPECT_EQ(echoed.get<scalar>("contactTolerance"), c.contactTolerance);
}


TEST(simulationControlsDeath, unknownPresetListsTheAllowedOnes)
{
    EXPECT_EXIT
    (
        rbd::simulationControls(parse("preset quick;")),
        ::testing::ExitedWithCode(1),
        "preset(.|\n)*quick(.|\n)*fast(.|\n)*default(.|\n)*accurate"
    );
}


TEST(simulationControls, restingFrictionIsEchoed)
{
    const rbd::simulationControls c(parse("restingFriction staggered;"));
    EXPECT_EQ(c.restingFriction, "staggered");
    OStringStream os;
    c.write(os);
    EXPECT_EQ(parse(os.str()).get<word>("restingFriction"), "staggered");
}


TEST(simulationControlsDeath, unknownRestingFrictionListsTheAllowedOnes)
{
    EXPECT_EXIT
    (
        rbd::simulationControls(parse("restingFriction exact;")),
        ::testing::ExitedWithCode(1),
        "restingFriction(.|\n)*exact(.|\n)*coupled(.|\n)*staggered"
    );
}


TEST(simulationControls, frictionRoundsIsEchoed)
{
    const rbd::simulationControls c(parse("frictionRounds 2;"));
    EXPECT_EQ(c.frictionRounds, 2);
    OStringStream os;
    c.write(os);
    EXPECT_EQ(parse(os.str()).get<label>("frictionRounds"), 2);
}


TEST(simulationControlsDeath, frictionRoundsOutOfRange)
{
    EXPECT_EXIT
    (
        rbd::simulationControls(parse("frictionRounds 0;")),
        ::testing::ExitedWithCode(1),
        "frictionRounds(.|\n)*0"
    );
}


TEST(simulationControls, overlapSlopDefaultsToTheContactToleranceAndIsEchoed)
{
    const rbd::simulationControls c(parse(""));
    EXPECT_DOUBLE_EQ(c.overlapSlop, c.contactTolerance);
    const rbd::simulationControls t(parse("contactTolerance 1e-5;"));
    EXPECT_DOUBLE_EQ(t.overlapSlop, 1e-5);
    const rbd::simulationControls g(parse("overlapSlop 2e-3;"));
    EXPECT_DOUBLE_EQ(g.overlapSlop, 2e-3);
    OStringStream os;
    g.write(os);
    EXPECT_EQ(parse(os.str()).get<scalar>("overlapSlop"), 2e-3);
}


TEST(simulationControlsDeath, overlapSlopBelowTheContactTolerance)
{
    EXPECT_EXIT
    (
        rbd::simulationControls(parse("overlapSlop 1e-5;")),
        ::testing::ExitedWithCode(1),
        "overlapSlop 1e-05(.|\n)*allowed: a number in \\[0.0001, 0.01\\]"
    );
}


// ************************************************************************* //
