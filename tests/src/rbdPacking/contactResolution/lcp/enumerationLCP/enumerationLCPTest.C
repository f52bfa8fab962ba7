// Unit tests for src/rbdPacking/contactResolution/lcp/enumerationLCP, the
// reference solver: closed forms, the smallest active set, the size limit

#include <gtest/gtest.h>
#include "rbdPacking/contactResolution/lcp/lcpTestProblems.H"
#include "enumerationLCP.H"

using namespace Foam;
using namespace lcpTest;

TEST(enumerationLCP, closedFormsOfOneAndTwoContacts)
{
    const rbd::enumerationLCP solver(dictionary::null);
    Vec f;

    // a f + b = 0 for b < 0, f = 0 for b >= 0
    EXPECT_TRUE
    (
        solver.solve(Mat::Constant(1, 1, 2), Vec::Constant(1, -4), f)
       .converged
    );
    EXPECT_DOUBLE_EQ(f(0), 2);
    solver.solve(Mat::Constant(1, 1, 2), Vec::Constant(1, 1), f);
    EXPECT_EQ(f(0), 0);

    // A = [2 1; 1 2], b = (-3, 1): f = (1.5, 0), w = (0, 2.5)
    Mat A(2, 2);
    A << 2, 1, 1, 2;
    EXPECT_TRUE(solver.solve(A, Eigen::Vector2d(-3, 1), f).converged);
    EXPECT_NEAR(f(0), 1.5, 1e-14);
    EXPECT_EQ(f(1), 0);

    // b = (-3, -3): both active, f = (1, 1)
    EXPECT_TRUE(solver.solve(A, Eigen::Vector2d(-3, -3), f).converged);
    EXPECT_NEAR(f(0), 1, 1e-14);
    EXPECT_NEAR(f(1), 1, 1e-14);
}


TEST(enumerationLCP, picksASmallestActiveSetForRedundantContacts)
{
    // Four copies of a floor contact: one of them carries m g, the
    // first one tried; 1 + 4 sets tried (the empty set and 1-sets)
    const scene s = sphereOnFloor(4);
    const rbd::enumerationLCP solver(dictionary::null);
    Vec f;
    const rbd::lcpResult r = solver.solve(s.p.A, s.p.b, f);
    EXPECT_TRUE(r.converged);
    EXPECT_EQ(r.iterations, 2);
    EXPECT_NEAR(f(0), 2*gravity, 1e-12);
    EXPECT_EQ(f.tail(3), Vec::Zero(3));
}


TEST(enumerationLCP, findsNoSolutionOfInfeasibleProblem)
{
    // w_0 + w_1 = b_0 + b_1 < 0 for every f; all 4 sets tried
    Mat A(2, 2);
    A << 1, -1, -1, 1;
    const rbd::enumerationLCP solver(dictionary::null);
    Vec f;
    const rbd::lcpResult r = solver.solve(A, Eigen::Vector2d(-1, -2), f);
    EXPECT_FALSE(r.converged);
    EXPECT_EQ(r.iterations, 4);
    EXPECT_EQ(f, Vec::Zero(2));
}


TEST(enumerationLCPDeath, refusesMoreThanSixteenContacts)
{
    const rbd::enumerationLCP solver(dictionary::null);
    const Mat A = Mat::Identity(17, 17);
    const Vec b = -Vec::Ones(17);
    Vec f;
    EXPECT_EXIT
    (
        solver.solve(A, b, f),
        ::testing::ExitedWithCode(1),
        "limited to n <= 16 contacts; got n = 17"
    );
}


// ************************************************************************* //
