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


TEST(neighbourList, adjacencyListsEachPairOnBothBodies)
{
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> U(0, 0.1);
    pointField x(300);
    for (point& p : x)
    {
        p = point(U(rng), U(rng), U(rng));
    }
    neighbourList nl(0.002);
    nl.update(x, 0.011);
    const labelListList& adj = nl.adjacency();
    ASSERT_EQ(adj.size(), x.size());

    // Every pair appears on both bodies, and nothing else does
    std::vector<std::pair<label, label>> fromAdjacency;
    forAll(adj, i)
    {
        for (const label k : adj[i])
        {
            if (i < k)
            {
                fromAdjacency.emplace_back(i, k);
            }
            EXPECT_NE(std::find(adj[k].begin(), adj[k].end(), i), adj[k].end());
        }
    }
    std::sort(fromAdjacency.begin(), fromAdjacency.end());
    EXPECT_EQ(fromAdjacency, sorted(nl.pairs()));
    EXPECT_GT(fromAdjacency.size(), 100u);

    // A rebuild (a new body) renews it
    x.append(point(0.05, 0.05, 0.05));
    nl.update(x, 0.011);
    EXPECT_EQ(nl.adjacency().size(), x.size());
}
