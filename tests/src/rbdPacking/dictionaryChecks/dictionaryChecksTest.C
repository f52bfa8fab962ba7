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
