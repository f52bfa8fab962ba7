// Unit tests for src/rbdPacking/contactResolution/lcp/blockPivotingLCP:
// pure block pivoting (no baraff fallback) against the enumeration
// reference on random regular, singular and pellet-scale problems; the
// guess changes the work, not the answer; sparse and dense input agree;
// the fallback to baraff and the report of a capped solve

#include <gtest/gtest.h>
#include "rbdPacking/contactResolution/lcp/lcpTestProblems.H"
#include "blockPivotingLCP.H"
#include "enumerationLCP.H"

using namespace Foam;
using namespace lcpTest;

namespace
{
    //- Block pivoting only: problems of any size are never handed over
    const char* pureDict = "fallbackSize 0;";

    //- Solve p with solver (guess: the active set to start from) and with
    //  enumeration; expect a converged, feasible f whose w agrees with the
    //  reference (w is unique for symmetric PSD A) to wTol of its scale.
    //  Returns the factorisations used.
    label compareWithEnumeration
    (
        const rbd::blockPivotingLCP& solver,
        const problem& p,
        const std::vector<bool>& guess,
        const double wTol,
        const std::string& what
    )
    {
        const rbd::enumerationLCP reference(dictionary::null);
        Vec fRef;
        EXPECT_TRUE(reference.solve(p.A, p.b, fRef).converged)
            << what << ": reference failed";

        Vec f;
        const rbd::lcpResult r =
            solver.solve(p.A.sparseView(), p.b, guess, f);
        EXPECT_TRUE(r.converged) << what << ": " << r.maxViolation;
        EXPECT_TRUE(f.allFinite()) << what;
        EXPECT_GE(f.minCoeff(), 0) << what;
        EXPECT_LE(r.maxViolation, 1e-8) << what;

        const double scale = wScale(p, fRef);
        EXPECT_LE((w(p, f) - w(p, fRef)).cwiseAbs().maxCoeff(), wTol*scale)
            << what;
        return r.iterations;
    }

    std::vector<bool> randomGuess(rng& gen, const label n)
    {
        std::vector<bool> guess(n);
        for (label i = 0; i < n; ++i)
        {
            guess[i] = uniform(gen, 0, 1) < 0.5;
        }
        return guess;
    }
}


TEST(blockPivotingLCP, matchesEnumerationOnRandomProblems)
{
    const rbd::blockPivotingLCP solver(parse(pureDict));
    rng gen(2024);
    for (int trial = 0; trial < 150; ++trial)
    {
        const problem p = randomProblem(gen, kind::regular);
        compareWithEnumeration
        (
            solver, p, {}, 1e-8, "regular " + std::to_string(trial)
        );
    }
}


TEST(blockPivotingLCP, matchesEnumerationOnSingularProblems)
{
    // Redundant contacts: A is singular, the regularisation picks one f
    const rbd::blockPivotingLCP solver(parse(pureDict));
    rng gen(35);
    for (int trial = 0; trial < 150; ++trial)
    {
        const problem p = randomProblem
        (
            gen,
            trial % 2 ? kind::overdetermined : kind::duplicated,
            10
        );
        compareWithEnumeration
        (
            solver, p, {}, 1e-7, "singular " + std::to_string(trial)
        );
    }
}


TEST(blockPivotingLCP, isScaleFreeAtPelletScale)
{
    const rbd::blockPivotingLCP solver(parse(pureDict));
    rng gen(11);
    for (int trial = 0; trial < 60; ++trial)
    {
        compareWithEnumeration
        (
            solver,
            randomProblem(gen, kind::pelletScale),
            {},
            1e-8,
            "pellet " + std::to_string(trial)
        );
    }
}


TEST(blockPivotingLCP, guessChangesTheWorkNotTheAnswer)
{
    const rbd::blockPivotingLCP solver(parse(pureDict));
    rng gen(5);
    for (int trial = 0; trial < 60; ++trial)
    {
        const problem p = randomProblem(gen, kind::regular);
        const label n = p.b.size();
        compareWithEnumeration
        (
            solver, p, randomGuess(gen, n), 1e-8,
            "random guess " + std::to_string(trial)
        );

        // Started from its own answer's active set, one factorisation
        Vec f;
        solver.solve(p.A.sparseView(), p.b, {}, f);
        std::vector<bool> exact(n);
        for (label i = 0; i < n; ++i)
        {
            exact[i] = f(i) > 0;
        }
        EXPECT_EQ
        (
            compareWithEnumeration(solver, p, exact, 1e-8, "exact guess"),
            1
        );
    }
}


TEST(blockPivotingLCP, denseAndSparseInputAgree)
{
    const rbd::blockPivotingLCP solver(parse(pureDict));
    const scene s = spherePyramid();
    Vec fDense, fSparse;
    const rbd::lcpResult rd = solver.solve(s.p.A, s.p.b, fDense);
    const rbd::lcpResult rs =
        solver.solve(s.p.A.sparseView(), s.p.b, {}, fSparse);
    EXPECT_TRUE(rd.converged);
    EXPECT_TRUE(rs.converged);
    EXPECT_EQ(fDense, fSparse);
    // 30 spheres at rest on the floor of a box
    EXPECT_LE(s.accelerations(fSparse).cwiseAbs().maxCoeff(), 1e-8*gravity);
}


TEST(blockPivotingLCP, handsAStuckSmallProblemToBaraff)
{
    // One factorisation allowed: a problem whose first candidate is not
    // the solution is finished by baraff when it is small enough, and
    // reported as not converged when it is not
    const rbd::blockPivotingLCP pure(parse(pureDict));
    rng gen(8);
    problem p;
    Vec f;
    do
    {
        p = randomProblem(gen, kind::regular);
    } while (pure.solve(p.A.sparseView(), p.b, {}, f).iterations < 2);

    const rbd::blockPivotingLCP handed
    (
        parse("maxIterations 1; fallbackIterations 1; fallbackSize 400;")
    );
    EXPECT_TRUE(handed.solve(p.A.sparseView(), p.b, {}, f).converged);
    EXPECT_LE(rbd::lcpSolver::violation(p.A, p.b, f), 1e-9);

    const rbd::blockPivotingLCP capped
    (
        parse("maxIterations 1; fallbackSize 0;")
    );
    const rbd::lcpResult r = capped.solve(p.A.sparseView(), p.b, {}, f);
    EXPECT_FALSE(r.converged);
    EXPECT_EQ(r.iterations, 1);
    EXPECT_GE(f.minCoeff(), 0);
    EXPECT_GT(r.maxViolation, 1e-9);
}


// ************************************************************************* //
