// Unit tests for src/rbdPacking/contactResolution/lcp/orderingCache: a
// pattern seen before gives AMD's ordering without computing it again,
// another pattern (also one of the same size) is ordered anew, and the
// least recently used pattern leaves first

#include <gtest/gtest.h>
#include "orderingCache.H"

#include <Eigen/OrderingMethods>

#include <vector>

using namespace Foam;

namespace
{
    typedef Eigen::SparseMatrix<double> sparse;

    //- A symmetric matrix with the pattern of a chain of n contacts, plus
    //  the extra couplings (i, j)
    sparse chain
    (
        const int n,
        const std::vector<std::pair<int, int>>& extra = {},
        const double scale = 1
    )
    {
        std::vector<Eigen::Triplet<double>> t;
        for (int i = 0; i < n; ++i)
        {
            t.emplace_back(i, i, 4*scale);
            if (i + 1 < n)
            {
                t.emplace_back(i, i + 1, -scale);
                t.emplace_back(i + 1, i, -scale);
            }
        }
        for (const auto& e : extra)
        {
            t.emplace_back(e.first, e.second, -0.5*scale);
            t.emplace_back(e.second, e.first, -0.5*scale);
        }
        sparse A(n, n);
        A.setFromTriplets(t.begin(), t.end());
        A.makeCompressed();
        return A;
    }

    std::vector<int> indices(const rbd::orderingCache::permutation& p)
    {
        return std::vector<int>
        (
            p.indices().data(), p.indices().data() + p.indices().size()
        );
    }

    std::vector<int> amd(const sparse& A)
    {
        rbd::orderingCache::permutation p;
        Eigen::AMDOrdering<int>()(A, p);
        return indices(p);
    }
}


TEST(orderingCache, aRepeatedPatternIsAHitWithAMDsOrdering)
{
    rbd::orderingCache cache;
    const sparse A = chain(30, {{0, 17}, {5, 29}, {3, 12}});

    EXPECT_EQ(indices(cache.order(A)), amd(A));
    EXPECT_EQ(cache.hits(), 0);

    // Same pattern, other values (the next step of the same island)
    const sparse B = chain(30, {{0, 17}, {5, 29}, {3, 12}}, 2.5);
    EXPECT_EQ(indices(cache.order(B)), amd(A));
    EXPECT_EQ(cache.hits(), 1);
    EXPECT_EQ(cache.lookups(), 2);
}


TEST(orderingCache, anotherPatternOfTheSameSizeIsOrderedAnew)
{
    rbd::orderingCache cache;
    const sparse A = chain(30, {{0, 17}, {5, 29}});
    const sparse B = chain(30, {{0, 18}, {5, 29}});
    ASSERT_EQ(A.nonZeros(), B.nonZeros());

    cache.order(A);
    EXPECT_EQ(indices(cache.order(B)), amd(B));
    EXPECT_EQ(cache.hits(), 0);

    // Both are remembered now
    EXPECT_EQ(indices(cache.order(A)), amd(A));
    EXPECT_EQ(indices(cache.order(B)), amd(B));
    EXPECT_EQ(cache.hits(), 2);
}


TEST(orderingCache, theLeastRecentlyUsedPatternLeavesFirst)
{
    rbd::orderingCache cache(2);
    const sparse A = chain(10);
    const sparse B = chain(11);
    const sparse C = chain(12);

    cache.order(A);
    cache.order(B);
    cache.order(A);         // hit: A is now the most recent
    cache.order(C);         // evicts B
    EXPECT_EQ(cache.hits(), 1);

    cache.order(A);
    EXPECT_EQ(cache.hits(), 2);
    cache.order(B);
    EXPECT_EQ(cache.hits(), 2);
    EXPECT_EQ(indices(cache.order(B)), amd(B));
    EXPECT_EQ(cache.hits(), 3);
}


TEST(orderingCache, anUncompressedMatrixIsOrderedLikeItsCompressedForm)
{
    rbd::orderingCache cache;
    const sparse A = chain(20, {{2, 15}});
    sparse U(A);
    U.uncompress();
    ASSERT_FALSE(U.isCompressed());

    EXPECT_EQ(indices(cache.order(U)), amd(A));
    EXPECT_EQ(indices(cache.order(A)), amd(A));
    EXPECT_EQ(cache.hits(), 1);
}
