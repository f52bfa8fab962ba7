// Unit tests for src/rbdPacking/contactResolution/lcp/blockPivotingLCP:
// pure block pivoting (no baraff fallback) against the enumeration
// reference on random regular, singular and pellet-scale problems, and on
// two degenerate islands recorded from a bed; the
// guess changes the work, not the answer; sparse and dense input agree;
// the fallback to baraff and the report of a capped solve

#include <gtest/gtest.h>
#include "rbdPacking/contactResolution/lcp/lcpTestProblems.H"
#include "blockPivotingLCP.H"
#include "enumerationLCP.H"
#include <fstream>

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


// Two islands of 140 contacts from a 347-sphere bed at N = 5.6 (Table 3
// properties, at 118 pellets), written by the solver when it failed them
// (tolerance 1e-9, before candidates were accepted within ten times the
// tolerance once the exchanges cycle): singular (rank 127 and 130), feasible
// (checked with an LP), degenerate. File: n nnz eps, then the triplets
// (row col value) of A, then b_i and the previous step's guess per row.
namespace
{
    struct recordedIsland
    {
        Eigen::SparseMatrix<double> A;
        Vec b;
        std::vector<bool> guess;
    };

    recordedIsland readIsland(const std::string& name)
    {
        recordedIsland p;
        const char* root = getenv("RBD_PACKING_DIR");
        EXPECT_NE(root, nullptr) << "RBD_PACKING_DIR not set";
        std::ifstream is
        (
            std::string(root ? root : ".")
          + "/tests/src/rbdPacking/contactResolution/lcp/blockPivotingLCP/"
          + "data/" + name + ".lcp"
        );
        EXPECT_TRUE(is.good()) << name;
        label n = 0, nnz = 0;
        double eps;
        is >> n >> nnz >> eps;
        std::vector<Eigen::Triplet<double>> t;
        for (label k = 0; k < nnz; ++k)
        {
            label r, c;
            double v;
            is >> r >> c >> v;
            t.emplace_back(r, c, v);
        }
        p.A.resize(n, n);
        p.A.setFromTriplets(t.begin(), t.end());
        p.b.resize(n);
        p.guess.resize(n);
        for (label k = 0; k < n; ++k)
        {
            label g;
            is >> p.b(k) >> g;
            p.guess[k] = g > 0;
        }
        EXPECT_TRUE(is.good()) << name;
        return p;
    }

    //- Violation of f, computed here from w = A f + b: the largest of
    //  -f_i/fRef, -w_i/wRef and |f_i w_i|/(fRef wRef)
    double independentViolation(const recordedIsland& p, const Vec& f)
    {
        const Vec w(p.A*f + p.b);
        const double wRef = p.b.cwiseAbs().maxCoeff();
        const double fRef = f.cwiseAbs().maxCoeff();
        return std::max
        ({
            -f.minCoeff()/fRef,
            -w.minCoeff()/wRef,
            f.cwiseProduct(w).cwiseAbs().maxCoeff()/(wRef*fRef)
        });
    }
}


TEST(blockPivotingLCP, solvesADegenerateBedIsland)
{
    const rbd::blockPivotingLCP pure(parse(pureDict));
    const recordedIsland p = readIsland("bedIsland140a");
    for (const bool warm : {true, false})
    {
        Vec f;
        const rbd::lcpResult r =
            pure.solve(p.A, p.b, warm ? p.guess : std::vector<bool>(), f);
        EXPECT_TRUE(r.converged) << "warm " << warm;
        EXPECT_GT(f.maxCoeff(), 0);
        EXPECT_LE(independentViolation(p, f), 1e-8) << "warm " << warm;
    }
}


TEST(blockPivotingLCP, reportsAnUnsolvedDegenerateIslandWithItsBestCandidate)
{
    // The second island is not solved within 1e-8 (ten times the default
    // tolerance) by the defaults (its best candidates stop at 1.5e-8 cold
    // and 2.5e-6 warm; with 30 smoothing sweeps the warm start solves it
    // exactly): the solver must say so, and return its best candidate,
    // f >= 0 with a small violation
    const rbd::blockPivotingLCP pure(parse(pureDict));
    const recordedIsland p = readIsland("bedIsland140b");
    for (const bool warm : {true, false})
    {
        Vec f;
        const rbd::lcpResult r =
            pure.solve(p.A, p.b, warm ? p.guess : std::vector<bool>(), f);
        const double v = independentViolation(p, f);
        EXPECT_EQ(r.converged, v <= 1e-8) << "warm " << warm;
        EXPECT_NEAR(r.maxViolation, v, 1e-12 + 1e-6*v);
        EXPECT_GE(f.minCoeff(), 0);
        EXPECT_LE(v, 1e-5) << "warm " << warm;
    }
    const rbd::blockPivotingLCP smoother
    (
        parse("fallbackSize 0; smoothingSweeps 30;")
    );
    Vec f;
    EXPECT_TRUE(smoother.solve(p.A, p.b, p.guess, f).converged);
    EXPECT_LE(independentViolation(p, f), 1e-8);
}
