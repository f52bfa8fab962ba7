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
    const neighbourList::adjacencyList& adj = nl.adjacency();
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


TEST(neighbourList, incrementalUpdatesNeverMissAPairWithinTheCutoff)
{
    // 200 bodies in a box, some falling fast through the others, the rest
    // jiggling, new bodies appended on the way: after every update each
    // pair closer than the cutoff is listed, every listed pair had its
    // snapshots within cutoff + skin, the clearance of unlisted pairs holds,
    // and only the bodies that moved skin/2 (and the new ones) were listed
    // again
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> U(0, 0.08);
    std::normal_distribution<double> jiggle(0, 2e-4);
    const scalar cutoff = 0.011;
    const scalar skin = 0.003;
    pointField x(200);
    for (point& p : x)
    {
        p = point(U(rng), U(rng), U(rng));
    }
    neighbourList nl(skin);
    nl.update(x, cutoff);
    pointField x0(x);

    label relistedSeen = nl.nRelisted();
    for (label step = 0; step < 400; ++step)
    {
        const label nBefore = x.size();
        forAll(x, i)
        {
            if (i % 20 == 0)
            {
                x[i].z() -= 1e-3;   // falling through the box
            }
            else
            {
                x[i] += vector(jiggle(rng), jiggle(rng), jiggle(rng));
            }
        }
        if (step % 50 == 0)
        {
            x.append(point(U(rng), U(rng), 0.08));
        }

        label expectRelisted = x.size() - nBefore;
        for (label i = 0; i < nBefore; ++i)
        {
            if (mag(x[i] - x0[i]) > 0.5*skin)
            {
                ++expectRelisted;
            }
        }
        nl.update(x, cutoff);
        EXPECT_EQ(nl.nRelisted() - relistedSeen, expectRelisted);
        relistedSeen = nl.nRelisted();
        x0.setSize(x.size());
        forAll(x, i)
        {
            if (i >= nBefore || mag(x[i] - x0[i]) > 0.5*skin)
            {
                x0[i] = x[i];
            }
        }

        const DynamicList<labelPair>& pairs = nl.pairs();
        EXPECT_TRUE(std::is_sorted(pairs.begin(), pairs.end()));
        std::vector<std::pair<label, label>> listed(sorted(pairs));
        for (const auto& pr : listed)
        {
            EXPECT_LT(mag(x0[pr.first] - x0[pr.second]), cutoff + skin);
        }
        DynamicList<labelPair> close;
        neighbourList::bruteForce(x, cutoff, close);
        for (const labelPair& pr : close)
        {
            ASSERT_TRUE
            (
                std::binary_search
                (
                    listed.begin(), listed.end(),
                    std::make_pair(pr.first(), pr.second())
                )
            ) << "step " << step << ": pair (" << pr.first() << " " << pr.second()
              << ") within the cutoff"
              << " is not listed";
        }
        // Unlisted pairs keep the clearance the step control is given
        forAll(x, i)
        {
            for (label k = i + 1; k < x.size(); ++k)
            {
                if
                (
                    !std::binary_search
                    (
                        listed.begin(), listed.end(), std::make_pair(i, k)
                    )
                )
                {
                    EXPECT_GE
                    (
                        mag(x[i] - x[k]) - cutoff,
                        nl.unlistedClearance() - 1e-12
                    );
                }
            }
        }
    }
    // The falling bodies (10, 1 mm a step: skin/2 every other step) were
    // listed again about 200 times each; the whole list was never built
    // again (that would be 200 bodies or more at each of the 400 updates)
    EXPECT_GT(nl.nRelisted(), 200 + 10*150);
    EXPECT_LT(nl.nRelisted(), 200*400/4);
}


TEST(neighbourList, listDoesNotDependOnTheOrderOfUpdates)
{
    // The same final snapshots reached by one update or by many give the
    // same pairs (neighbours kept in ascending order)
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> U(0, 0.05);
    pointField x(80);
    for (point& p : x)
    {
        p = point(U(rng), U(rng), U(rng));
    }
    neighbourList stepwise(0.002);
    stepwise.update(x, 0.011);
    // Move every body by more than skin/2, in two halves
    pointField y(x);
    for (label i = 0; i < y.size(); i += 2)
    {
        y[i].x() += 0.0015;
    }
    stepwise.update(y, 0.011);
    for (label i = 1; i < y.size(); i += 2)
    {
        y[i].y() -= 0.0015;
    }
    stepwise.update(y, 0.011);

    neighbourList once(0.002);
    once.update(y, 0.011);
    EXPECT_EQ(sorted(stepwise.pairs()), sorted(once.pairs()));
    EXPECT_TRUE
    (
        std::equal
        (
            stepwise.pairs().begin(), stepwise.pairs().end(),
            once.pairs().begin(), once.pairs().end()
        )
    );
}
