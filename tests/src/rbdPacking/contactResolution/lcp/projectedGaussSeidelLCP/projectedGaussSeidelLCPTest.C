// Unit tests for src/rbdPacking/contactResolution/lcp/projectedGaussSeidelLCP:
// against the enumeration reference on random (also singular) problems,
// over-relaxation, warm start, the sweep cap

#include <gtest/gtest.h>
#include "rbdPacking/contactResolution/lcp/lcpTestProblems.H"
#include "projectedGaussSeidelLCP.H"
#include "rbdPacking/contactResolution/lcp/enumerationLCP/enumerationLCP.H"

using namespace Foam;
using namespace lcpTest;

TEST(projectedGaussSeidelLCP, matchesEnumerationOnRandomProblems)
{
    // Tight tolerance and a generous cap: PGS converges on solvable PSD
    // problems, slowly on the ill-conditioned ones
    const rbd::projectedGaussSeidelLCP solver
    (
        parse("tolerance 1e-11; maxIterations 50000;")
    );
    const rbd::enumerationLCP reference(dictionary::null);
    rng gen(1977);
    for (int trial = 0; trial < 120; ++trial)
    {
        const kind k =
            trial % 3 == 0 ? kind::regular
          : trial % 3 == 1 ? kind::duplicated
          : kind::overdetermined;
        const problem p = randomProblem(gen, k, 9);

        Vec fRef, f;
        ASSERT_TRUE(reference.solve(p.A, p.b, fRef).converged);
        const rbd::lcpResult r = solver.solve(p.A, p.b, f);
        EXPECT_TRUE(r.converged) << trial;
        EXPECT_GE(f.minCoeff(), 0) << trial;
        EXPECT_LE
        (
            (w(p, f) - w(p, fRef)).cwiseAbs().maxCoeff(),
            1e-7*wScale(p, fRef)
        ) << trial;
    }
}


TEST(projectedGaussSeidelLCP, overRelaxationConvergesFaster)
{
    // The pyramid of 30 spheres: omega = 1.5 against plain Gauss-Seidel
    const scene s = spherePyramid();
    const rbd::projectedGaussSeidelLCP plain(parse("tolerance 1e-8;"));
    const rbd::projectedGaussSeidelLCP sor
    (
        parse("tolerance 1e-8; relaxation 1.5;")
    );
    Vec f1, f2;
    const rbd::lcpResult r1 = plain.solve(s.p.A, s.p.b, f1);
    const rbd::lcpResult r2 = sor.solve(s.p.A, s.p.b, f2);
    EXPECT_TRUE(r1.converged);
    EXPECT_TRUE(r2.converged);
    EXPECT_LT(r2.iterations, r1.iterations);
    EXPECT_LE
    (
        (w(s.p, f1) - w(s.p, f2)).cwiseAbs().maxCoeff(), 1e-6*gravity
    );
}


TEST(projectedGaussSeidelLCP, warmStartFromSolutionTakesOneSweep)
{
    const scene s = spherePyramid();
    const rbd::projectedGaussSeidelLCP cold(parse("tolerance 1e-9;"));
    const rbd::projectedGaussSeidelLCP warm
    (
        parse("tolerance 1e-9; warmStart yes;")
    );
    Vec f;
    const rbd::lcpResult rCold = cold.solve(s.p.A, s.p.b, f);
    ASSERT_TRUE(rCold.converged);
    EXPECT_GT(rCold.iterations, 1);

    // Warm: from the converged forces, one sweep confirms them
    const rbd::lcpResult rWarm = warm.solve(s.p.A, s.p.b, f);
    EXPECT_TRUE(rWarm.converged);
    EXPECT_EQ(rWarm.iterations, 1);

    // Cold ignores the f passed in
    const rbd::lcpResult rCold2 = cold.solve(s.p.A, s.p.b, f);
    EXPECT_EQ(rCold2.iterations, rCold.iterations);
}


TEST(projectedGaussSeidelLCP, stopsAtSweepCapOnInfeasibleProblem)
{
    Mat A(2, 2);
    A << 1, -1, -1, 1;
    const rbd::projectedGaussSeidelLCP solver(parse("maxIterations 50;"));
    Vec f;
    const rbd::lcpResult r = solver.solve(A, Eigen::Vector2d(-1, -2), f);
    EXPECT_FALSE(r.converged);
    EXPECT_EQ(r.iterations, 50);
    EXPECT_TRUE(f.allFinite());
    EXPECT_GE(f.minCoeff(), 0);
}


TEST(projectedGaussSeidelLCP, contactWithoutEffectKeepsZeroForce)
{
    // A zero row (a contact that moves nothing) with b < 0 cannot be
    // helped; it gets no force and the rest is still solved
    Mat A = Mat::Zero(2, 2);
    A(1, 1) = 2;
    const rbd::projectedGaussSeidelLCP solver(parse("maxIterations 20;"));
    Vec f;
    const rbd::lcpResult r = solver.solve(A, Eigen::Vector2d(-1, -4), f);
    EXPECT_EQ(f(0), 0);
    EXPECT_DOUBLE_EQ(f(1), 2);
    EXPECT_FALSE(r.converged);
    EXPECT_EQ(r.iterations, 20);
}


// ************************************************************************* //
