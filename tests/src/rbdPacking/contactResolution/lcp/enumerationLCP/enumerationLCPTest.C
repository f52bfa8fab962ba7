// Unit tests for the tests' reference LCP solver (enumerationLCP, beside
// this file): closed forms, the smallest active set, the size limit

#include <gtest/gtest.h>
#include "rbdPacking/contactResolution/lcp/lcpTestProblems.H"
#include "rbdPacking/contactResolution/lcp/enumerationLCP/enumerationLCP.H"

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


namespace
{
    //- Expect f to solve the LCP p: f >= 0, w = A f + b >= 0 and
    //  f_i w_i = 0, to within tol of the scales of f and w
    void expectSolution(const problem& p, const Vec& f, const std::string& what)
    {
        const double tol = 1e-9;
        const Vec wf = w(p, f);
        const double fScale = max(f.cwiseAbs().maxCoeff(), VSMALL);
        const double ws = wScale(p, f);
        EXPECT_GE(f.minCoeff(), 0) << what;
        EXPECT_GE(wf.minCoeff(), -tol*ws) << what;
        EXPECT_LE(f.cwiseProduct(wf).cwiseAbs().maxCoeff(), tol*fScale*ws)
            << what;
    }
}


TEST(enumerationLCP, picksASmallestActiveSetForRedundantContacts)
{
    // Four copies of a floor contact: any split of m g among them solves
    // the LCP; the reference picks a smallest active set, one contact
    // carrying all of m g
    const scene s = sphereOnFloor(4);
    const rbd::enumerationLCP solver(dictionary::null);
    Vec f;
    const rbd::lcpResult r = solver.solve(s.p.A, s.p.b, f);
    EXPECT_TRUE(r.converged);
    expectSolution(s.p, f, "four copies");
    EXPECT_NEAR(f.sum(), 2*gravity, 1e-12);
    EXPECT_EQ((f.array() > 0).count(), 1);
}


TEST(enumerationLCP, solvesRandomSolvableProblems)
{
    // Solvable by construction (lcpTestProblems.H), up to 12 contacts,
    // also singular: every one converges to a solution, and the reported
    // violation is that of the solution returned
    const rbd::enumerationLCP solver(dictionary::null);
    rng gen(2024);
    const kind kinds[] =
        {kind::regular, kind::overdetermined, kind::duplicated};
    for (int trial = 0; trial < 120; ++trial)
    {
        const kind k = kinds[trial % 3];
        const problem p = randomProblem(gen, k, 12);
        const std::string what =
            "trial " + std::to_string(trial) + ", "
          + std::to_string(p.b.size()) + " contacts";
        Vec f;
        const rbd::lcpResult r = solver.solve(p.A, p.b, f);
        EXPECT_TRUE(r.converged) << what;
        expectSolution(p, f, what);
        EXPECT_DOUBLE_EQ
        (
            r.maxViolation, rbd::lcpSolver::violation(p.A, p.b, f)
        ) << what;
    }
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
