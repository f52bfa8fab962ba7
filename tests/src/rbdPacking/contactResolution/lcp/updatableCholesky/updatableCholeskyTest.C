// Unit tests for src/rbdPacking/contactResolution/lcp/updatableCholesky:
// every append and remove against a fresh Cholesky factorisation

#include <gtest/gtest.h>
#include "rbdPacking/contactResolution/lcp/lcpTestProblems.H"
#include "updatableCholesky.H"

#include <algorithm>

using namespace Foam;
using namespace lcpTest;

namespace
{
    //- S restricted to the index list
    Mat sub(const Mat& S, const std::vector<int>& idx)
    {
        Mat s(idx.size(), idx.size());
        for (std::size_t r = 0; r < idx.size(); ++r)
        {
            for (std::size_t c = 0; c < idx.size(); ++c)
            {
                s(r, c) = S(idx[r], idx[c]);
            }
        }
        return s;
    }

    //- Factor and solve agree with Eigen's LLT of S(idx, idx)
    void expectFactorOf
    (
        const rbd::updatableCholesky& chol,
        const Mat& S,
        const std::vector<int>& idx,
        rng& gen
    )
    {
        ASSERT_EQ(chol.size(), label(idx.size()));
        if (idx.empty())
        {
            return;
        }
        const Mat s = sub(S, idx);
        const Eigen::LLT<Mat> llt(s);
        const Mat Lref = llt.matrixL();
        const Mat L = chol.L();
        // The Cholesky factor with positive diagonal is unique
        EXPECT_LE((L - Lref).cwiseAbs().maxCoeff(), 1e-12);
        EXPECT_LE((L.triangularView<Eigen::StrictlyUpper>().toDenseMatrix())
            .cwiseAbs().maxCoeff(), 0);

        Vec x(idx.size());
        for (int i = 0; i < x.size(); ++i)
        {
            x(i) = uniform(gen, -1, 1);
        }
        const Vec ref = llt.solve(x);
        chol.solveInPlace(x);
        EXPECT_LE((x - ref).cwiseAbs().maxCoeff(), 1e-10);
    }
}


TEST(updatableCholesky, followsAppendsAndRemovals)
{
    rng gen(11);
    const int n = 12;
    const Mat B = Mat::NullaryExpr
    (
        n, n, [&]() { return uniform(gen, -1, 1); }
    );
    const Mat S = B*B.transpose() + 0.5*Mat::Identity(n, n);

    rbd::updatableCholesky chol(n);
    std::vector<int> idx;
    std::vector<int> out(n);
    for (int i = 0; i < n; ++i)
    {
        out[i] = i;
    }
    std::shuffle(out.begin(), out.end(), gen);

    // Random walk of appends (of a random index not in) and removals (of
    // a random position, first, middle and last included)
    for (int step = 0; step < 200; ++step)
    {
        const bool grow =
            idx.empty() || (!out.empty() && uniform(gen, 0, 1) < 0.55);
        if (grow)
        {
            const int j = out.back();
            out.pop_back();
            Vec c(idx.size());
            for (std::size_t k = 0; k < idx.size(); ++k)
            {
                c(k) = S(idx[k], j);
            }
            ASSERT_TRUE(chol.append(c, S(j, j), 1e-12));
            idx.push_back(j);
        }
        else
        {
            const int k = uniformInt(gen, 0, int(idx.size()) - 1);
            chol.remove(k);
            out.push_back(idx[k]);
            idx.erase(idx.begin() + k);
        }
        expectFactorOf(chol, S, idx, gen);
    }
}


TEST(updatableCholesky, refusesDependentColumn)
{
    // S = [1 1; 1 1] is singular: the second pivot is 0
    rbd::updatableCholesky chol(3);
    ASSERT_TRUE(chol.append(Vec(0), 1, 1e-12));
    EXPECT_FALSE(chol.append(Vec::Ones(1), 1, 1e-12));
    EXPECT_EQ(chol.size(), 1);
    EXPECT_DOUBLE_EQ(chol.L()(0, 0), 1);

    // and takes an independent one afterwards: S = [1 0.5; 0.5 1]
    ASSERT_TRUE(chol.append(Vec::Constant(1, 0.5), 1, 1e-12));
    EXPECT_DOUBLE_EQ(chol.L()(1, 0), 0.5);
    EXPECT_DOUBLE_EQ(chol.L()(1, 1), std::sqrt(0.75));
}


// ************************************************************************* //
