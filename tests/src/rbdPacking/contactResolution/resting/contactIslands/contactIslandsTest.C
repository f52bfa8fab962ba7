// The islands of src/rbdPacking/contactResolution/resting/contactIslands:
// contacts connected through moving bodies, walls and sleepers joining
// nothing

#include <gtest/gtest.h>
#include "contactIslands.H"

using namespace Foam;
using namespace Foam::rbd;

namespace
{
    contact between(const label i, const label k)
    {
        contact c;
        c.i = i;
        c.k = k;
        return c;
    }

    std::vector<label> ids(std::initializer_list<label> l)
    {
        return std::vector<label>(l);
    }
}


TEST(contactIslands, twoStacksAreTwoIslandsInContactOrder)
{
    // Bodies 0-1 and 2-3 stacked on the floor, listed interleaved
    const List<contact> cs
    ({
        between(0, tubeBottom), between(2, tubeBottom), between(1, 0),
        between(3, 2), between(1, tubeWall)
    });
    const boolList fixed(4, false);
    contactIslands islands;
    islands.build(cs, fixed, 4);
    ASSERT_EQ(islands.size(), 2);
    EXPECT_EQ(islands.contacts(0), ids({0, 2, 4}));
    EXPECT_EQ(islands.contacts(1), ids({1, 3}));
}


TEST(contactIslands, aSleeperJoinsNothing)
{
    // 0 and 1 both rest on sleeper 2: two islands; awake, one
    const List<contact> cs({between(0, 2), between(1, 2)});
    boolList fixed(3, false);
    fixed[2] = true;
    contactIslands islands;
    islands.build(cs, fixed, 3);
    EXPECT_EQ(islands.size(), 2);

    fixed[2] = false;
    islands.build(cs, fixed, 3);
    ASSERT_EQ(islands.size(), 1);
    EXPECT_EQ(islands.contacts(0), ids({0, 1}));
}


TEST(contactIslands, aBuildForgetsTheLastOne)
{
    // A chain 0-1-2-3-4 joined, then the same bodies apart: the second
    // build finds no trace of the first (the buffers were restored)
    const boolList fixed(5, false);
    contactIslands islands;
    islands.build
    (
        List<contact>
        ({
            between(1, 0), between(2, 1), between(3, 2), between(4, 3)
        }),
        fixed, 5
    );
    ASSERT_EQ(islands.size(), 1);
    EXPECT_EQ(islands.contacts(0).size(), 4u);

    const List<contact> apart
    ({
        between(0, tubeBottom), between(1, tubeBottom), between(2, tubeWall),
        between(3, tubeBottom), between(4, tubeWall)
    });
    islands.build(apart, fixed, 5);
    ASSERT_EQ(islands.size(), 5);
    for (label s = 0; s < 5; ++s)
    {
        EXPECT_EQ(islands.contacts(s), ids({s}));
    }

    // More bodies than before
    islands.build(List<contact>({between(7, 6)}), boolList(8, false), 8);
    ASSERT_EQ(islands.size(), 1);
    EXPECT_EQ(islands.contacts(0), ids({0}));
}
