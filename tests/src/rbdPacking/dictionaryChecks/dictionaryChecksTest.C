// Unit tests for src/rbdPacking/dictionaryChecks

#include <gtest/gtest.h>
#include "dictionaryChecks.H"
#include "IStringStream.H"

using namespace Foam;

namespace
{
    dictionary parse(const char* text)
    {
        IStringStream is(text);
        return dictionary(is);
    }
}

TEST(dictionaryChecks, readsValidValues)
{
    const dictionary d = parse("d 0.01; n 5; e 0.5; s column;");
    EXPECT_DOUBLE_EQ(rbd::getPositive(d, "d", "m"), 0.01);
    EXPECT_EQ(rbd::getPositiveLabel(d, "n"), 5);
    EXPECT_DOUBLE_EQ(rbd::getInRangeOrDefault(d, "e", 0.9, 0, 1, "-"), 0.5);
    EXPECT_DOUBLE_EQ(rbd::getInRangeOrDefault(d, "f", 0.9, 0, 1, "-"), 0.9);
    EXPECT_EQ
    (
        rbd::getChoiceOrDefault(d, "s", "x", wordList({"column", "x"})),
        "column"
    );
}

TEST(dictionaryChecksDeath, rejectsNegativeSize)
{
    const dictionary d = parse("d -0.01;");
    EXPECT_EXIT
    (
        rbd::getPositive(d, "d", "m"),
        ::testing::ExitedWithCode(1),
        "Bad entry 'd -0.01;'(.|\n)*allowed: a number > 0 \\[m\\]"
    );
}

TEST(dictionaryChecksDeath, rejectsUnknownChoiceListingValidOnes)
{
    const dictionary d = parse("s helix;");
    EXPECT_EXIT
    (
        rbd::getChoiceOrDefault(d, "s", "x", wordList({"column", "x"})),
        ::testing::ExitedWithCode(1),
        "helix(.|\n)*one of column \\| x"
    );
}

TEST(dictionaryChecksDeath, rejectsMisspeltKeyword)
{
    const dictionary d = parse("diamter 0.01;");
    EXPECT_EXIT
    (
        rbd::checkKnownEntries(d, wordList({"diameter"})),
        ::testing::ExitedWithCode(1),
        "Unknown entry 'diamter'"
    );
}

TEST(dictionaryChecksDeath, rejectsValuesAboveTheirBound)
{
    // An explicit bound, and the default one (GREAT) that keeps overflows
    // (a density of 1e300) and inf out of the arithmetic
    const dictionary d = parse("rho 1e300; n 2000000000; x 1e20;");
    EXPECT_EXIT
    (
        rbd::getPositive(d, "rho", "kg/m^3", 1e5),
        ::testing::ExitedWithCode(1),
        "Bad entry 'rho 1e\\+300;'(.|\n)*a number in \\(0, 100000\\]"
    );
    EXPECT_EXIT
    (
        rbd::getLabelOrDefault(d, "n", 100, 1, 100000),
        ::testing::ExitedWithCode(1),
        "Bad entry 'n 2000000000;'(.|\n)*a whole number in \\[1, 100000\\]"
    );
    EXPECT_EXIT
    (
        rbd::getNonNegativeOrDefault(d, "x", 0, "m"),
        ::testing::ExitedWithCode(1),
        "Bad entry 'x 1e\\+20;'(.|\n)*>= 0 \\[m\\] \\(below 1e\\+15\\)"
    );
    EXPECT_DOUBLE_EQ(rbd::getPositive(parse("a 1e5;"), "a", "-", 1e5), 1e5);
}


TEST(dictionaryChecks, readsSwitchesByTheirNames)
{
    const dictionary d = parse("a true; b off; c yes; d 0; e 1; f none;");
    EXPECT_TRUE(rbd::getSwitchOrDefault(d, "a", false));
    EXPECT_FALSE(rbd::getSwitchOrDefault(d, "b", true));
    EXPECT_TRUE(rbd::getSwitchOrDefault(d, "c", false));
    EXPECT_FALSE(rbd::getSwitchOrDefault(d, "d", true));
    EXPECT_TRUE(rbd::getSwitchOrDefault(d, "e", false));
    EXPECT_FALSE(rbd::getSwitchOrDefault(d, "f", true));
    EXPECT_TRUE(rbd::getSwitchOrDefault(d, "absent", true));
    EXPECT_FALSE(rbd::getSwitchOrDefault(d, "absent", false));
}


TEST(dictionaryChecksDeath, rejectsSwitchesThatAreNotOne)
{
    // A bare bool reads any label and any number as true or false
    const dictionary d =
        parse("n 2; x 0.5; w maybe; two true false; b { a 1; }");
    for (const char* key : {"n", "x", "w", "two", "b"})
    {
        EXPECT_EXIT
        (
            rbd::getSwitchOrDefault(d, key, true),
            ::testing::ExitedWithCode(1),
            "Bad entry '"
          + std::string(key)
          + " .*;'(.|\n)*allowed: true \\| false"
        ) << key;
    }
}
