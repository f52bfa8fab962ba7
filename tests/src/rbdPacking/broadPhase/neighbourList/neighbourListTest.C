// Broad phase of src/rbdPacking/broadPhase against the O(n^2) reference

#include <gtest/gtest.h>
#include "neighbourList.H"
#include <algorithm>
#include <random>

using namespace Foam;
using namespace Foam::rbd;

namespace
{
    std::vector<std::pair<label, label>> sorted(const UList<labelPair>& ps)
    {
        std::vector<std::pair<label, label>> v;
        for (const labelPair& p : ps)
        {
            v.emplace_back(p.first(), p.second());
        }
        std::sort(v.begin(), v.end());
        return v;
    }
}


TEST(neighbourList, gridFindsExactlyTheBruteForcePairs)
{
    std::mt19937 rng(3);
    for (const scalar side : {0.05, 0.2, 1.0})
    {
        const scalar cutoff = 0.011*side/0.05;
        std::uniform_real_distribution<double> U(-side, side);
        pointField x(2000);
        for (point& p : x)
        {
            p = point(U(rng), U(rng), U(rng) + 0.5*side);
        }
        DynamicList<labelPair> grid, brute;
        neighbourList::gridPairs(x, cutoff, grid);
        neighbourList::bruteForce(x, cutoff, brute);
        EXPECT_EQ(sorted(grid), sorted(brute));
        EXPECT_GT(brute.size(), 0);
    }
}


TEST(neighbourList, verletListRebuildsOnlyWhenBodiesMoveHalfTheSkin)
{
    pointField x({point(0, 0, 0), point(0.02, 0, 0)});
    neighbourList list(0.004);

    EXPECT_TRUE(list.update(x, 0.011));
    EXPECT_EQ(list.pairs().size(), 0);   // 0.02 > 0.011 + 0.004

    x[1].x() -= 0.0019;                  // less than skin/2
    EXPECT_FALSE(list.update(x, 0.011));

    x[1].x() -= 0.0002;                  // 0.0021 in total
    EXPECT_TRUE(list.update(x, 0.011));
    EXPECT_EQ(list.pairs().size(), 0);   // 0.0179 > 0.015

    x[1].x() = 0.014;
    EXPECT_TRUE(list.update(x, 0.011));
    EXPECT_EQ(list.pairs().size(), 1);
}
