// Unit tests for src/rbdPacking/dictionaryChecks inWords, and the messages
// that print lists: words, not OpenFOAM's list syntax "2(a b)"

#include <gtest/gtest.h>
#include "dictionaryChecks.H"
#include "pelletShape.H"
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


TEST(inWords, listsAsASentence)
{
    EXPECT_EQ(rbd::inWords(wordList()), "");
    EXPECT_EQ(rbd::inWords(wordList({"shrink"})), "shrink");
    EXPECT_EQ(rbd::inWords(wordList({"bridges", "caps"})), "bridges or caps");
    EXPECT_EQ
    (
        rbd::inWords(wordList({"a", "b", "c"})), "a, b or c"
    );
    EXPECT_EQ
    (
        rbd::inWords(wordList({"a", "b", "c"}), "and"), "a, b and c"
    );
}


TEST(inWordsDeath, selectorsNameTheChoicesInWords)
{
    EXPECT_EXIT
    (
        rbd::pelletShape::New(parse("shape helix;")),
        ::testing::ExitedWithCode(1),
        "allowed: cylinder, cylinderWithHoles, (.)*, sphere(,| or) "
    );
    EXPECT_EXIT
    (
        rbd::pelletShape::New(parse("shape helix;")),
        ::testing::ExitedWithCode(1),
        "allowed: [a-zA-Z]"
    );
    EXPECT_EXIT
    (
        rbd::lcpSolver::New(parse("lcpSolver dantzig;")),
        ::testing::ExitedWithCode(1),
        "Valid lcpSolver types: baraff, blockPivoting, (.)* or [a-zA-Z]"
    );
}
