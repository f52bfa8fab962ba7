// Unit tests for src/rbdPacking/contactResolution/lcp/blockPivotingLCP:
// pure block pivoting (no interior point, no baraff fallback) and the
// interior-point method on its own against the enumeration reference on
// random regular, singular and pellet-scale problems; two degenerate
// islands recorded from a bed, where the block exchanges cycle; the guess
// changes the work, not the answer; sparse and dense input agree; the
// fallback to baraff and the report of a capped solve; A given with its
// factors (body space) against enumeration and against contact space;
// the factor kept between two solves of the same A

#include <gtest/gtest.h>
#include "rbdPacking/contactResolution/lcp/lcpTestProblems.H"
#include "blockPivotingLCP.H"
#include "rbdPacking/contactResolution/lcp/enumerationLCP/enumerationLCP.H"
#include <fstream>

using namespace Foam;
using namespace lcpTest;

namespace
{
    //- Block pivoting only: no interior point, never handed to baraff
    const char* pureDict = "interiorPointIterations 0; fallbackSize 0;";

    //- One factorisation of block pivoting, then the interior point
    const char* interiorDict = "maxIterations 1; fallbackSize 0;";

    //- The defaults without baraff
    const char* noBaraffDict = "fallbackSize 0;";

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
        const std::string& what,
        const rbd::lcpFactors& factors = rbd::lcpFactors()
    )
    {
        const rbd::enumerationLCP reference(dictionary::null);
        Vec fRef;
        EXPECT_TRUE(reference.solve(p.A, p.b, fRef).converged)
            << what << ": reference failed";

        Vec f;
        const rbd::lcpResult r =
            solver.solve(p.A.sparseView(), factors, p.b, guess, f);
        EXPECT_TRUE(r.converged) << what << ": " << r.maxViolation;
        EXPECT_TRUE(f.allFinite()) << what;
        EXPECT_GE(f.minCoeff(), 0) << what;
        EXPECT_LE(r.maxViolation, 1e-8) << what;

        const double scale = wScale(p, fRef);
        EXPECT_LE((w(p, f) - w(p, fRef)).cwiseAbs().maxCoeff(), wTol*scale)
            << what;
        return r.iterations;
    }

    //- The contacts that carry a force in f
    std::vector<bool> activeSet(const Vec& f)
    {
        std::vector<bool> active(f.size());
        for (label i = 0; i < f.size(); ++i)
        {
            active[i] = f(i) > 0;
        }
        return active;
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
    // Redundant contacts: A is singular, the regularisation picks one f;
    // the block exchanges can cycle here, so the interior point is on
    const rbd::blockPivotingLCP solver(parse(noBaraffDict));
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


TEST(blockPivotingLCP, interiorPointMatchesEnumeration)
{
    // The block pivoting stops after its first candidate: the interior
    // point solves what that candidate leaves, on regular and singular
    // (redundant contacts) problems
    const rbd::blockPivotingLCP solver(parse(interiorDict));
    rng gen(77);
    label handedOver = 0;
    for (int trial = 0; trial < 120; ++trial)
    {
        const problem p =
            trial % 3 == 0 ? randomProblem(gen, kind::regular)
          : randomProblem
            (
                gen,
                trial % 3 == 1 ? kind::overdetermined : kind::duplicated,
                10
            );
        const label iterations = compareWithEnumeration
        (
            solver, p, {}, 1e-6, "trial " + std::to_string(trial)
        );
        handedOver += iterations > 1;
    }
    // The interior point did the work in most of them (58 of 120 when
    // written)
    EXPECT_GT(handedOver, 40);
}


TEST(blockPivotingLCP, withoutExchangesTheInteriorPointAnswers)
{
    // exchanges false (exchangeRecord: a large island whose exchanges
    // have not been converging): the interior point at once, which says
    // so (newtonSteps), and the block exchanges only where it fails; the
    // answer agrees with enumeration either way. With exchanges, a
    // regular problem is solved by them alone. With the interior point
    // off, exchanges false is not heard: the exchanges are the solver
    const rbd::blockPivotingLCP solver(parse(noBaraffDict));
    const rbd::blockPivotingLCP pure(parse(pureDict));
    const rbd::enumerationLCP reference(dictionary::null);
    rng gen(91);
    label interiorAlone = 0;
    const label trials = 60;
    for (int trial = 0; trial < trials; ++trial)
    {
        const problem p =
            trial % 2 == 0 ? randomProblem(gen, kind::regular)
          : randomProblem(gen, kind::overdetermined, 10);
        const Eigen::SparseMatrix<double> A(p.A.sparseView());
        const rbd::lcpFactors none;
        Vec fRef;
        ASSERT_TRUE(reference.solve(p.A, p.b, fRef).converged) << trial;
        const double scale = wScale(p, fRef);

        rbd::activeSetFactor kept;
        Vec f;
        const rbd::lcpResult r =
            solver.solve(A, none, p.b, {}, f, kept, false);
        EXPECT_TRUE(r.converged) << trial;
        EXPECT_GT(r.newtonSteps, 0) << trial;
        // The interior point alone, unless it failed (a few of the
        // smallest problems: then the exchanges after all)
        interiorAlone += r.iterations == r.newtonSteps;
        EXPECT_GE(f.minCoeff(), 0) << trial;
        EXPECT_LE((w(p, f) - w(p, fRef)).cwiseAbs().maxCoeff(), 1e-6*scale)
            << trial;

        if (trial % 2 == 0)
        {
            Vec fx;
            const rbd::lcpResult rx =
                solver.solve(A, none, p.b, {}, fx, kept, true);
            EXPECT_TRUE(rx.converged) << trial;
            EXPECT_EQ(rx.newtonSteps, 0) << trial;
        }

        Vec fp;
        const rbd::lcpResult rp = pure.solve(A, none, p.b, {}, fp, kept, false);
        EXPECT_EQ(rp.newtonSteps, 0) << trial;
        EXPECT_GT(rp.iterations, 0) << trial;
    }
    std::cout
        << "[ measured ] the interior point alone solved " << interiorAlone
        << " of " << trials << std::endl;
    EXPECT_GT(interiorAlone, trials/2);
}


TEST(blockPivotingLCP, interiorPointStartsOnTheScaleOfTheLoad)
{
    // Contacts within the proximity band but apart enter the normal pass
    // with b = 2 (gap + h v_n)/h^2, up to 2e6 m/s^2 at the steps of a
    // heap under a rain of pellets; they carry nothing. The interior
    // point starts on the scale of the load (max -b_i), so rows of that
    // kind carry no force and cost at most two more Newton steps than the
    // problem without them (a start on max |b| took about ten more:
    // docs/restingSolveCost.md, "Twenty-sixth session")
    const rbd::blockPivotingLCP solver(parse(noBaraffDict));
    rng gen(93);
    for (int trial = 0; trial < 20; ++trial)
    {
        const std::string what = "trial " + std::to_string(trial);
        const int nBodies = uniformInt(gen, 2, 4);
        const int m = 8*nBodies;
        const heap full(randomHeap(gen, nBodies, m, 1e-5));
        problem withApart(full.p);
        std::vector<int> kept;
        for (int r = 0; r < m; ++r)
        {
            if (r % 3 == 1)
            {
                withApart.b(r) = 2e6;
            }
            else
            {
                kept.push_back(r);
            }
        }
        const int k = kept.size();
        problem touching{Mat(k, k), Vec(k)};
        for (int a = 0; a < k; ++a)
        {
            touching.b(a) = full.p.b(kept[a]);
            for (int c = 0; c < k; ++c)
            {
                touching.A(a, c) = full.p.A(kept[a], kept[c]);
            }
        }

        const rbd::lcpFactors none;
        rbd::activeSetFactor factor;
        Vec f, fTouching;
        const rbd::lcpResult r = solver.solve
        (
            withApart.A.sparseView(), none, withApart.b, {}, f, factor,
            false
        );
        const rbd::lcpResult rt = solver.solve
        (
            touching.A.sparseView(), none, touching.b, {}, fTouching,
            factor, false
        );
        ASSERT_TRUE(r.converged) << what << ": " << r.maxViolation;
        ASSERT_TRUE(rt.converged) << what << ": " << rt.maxViolation;
        // (The touching rows' answers agree only to the tolerance, which
        // is relative to max |b|: here the apart rows' 2e6)
        const double fRef = max(fTouching.cwiseAbs().maxCoeff(), 1e-300);
        for (int r2 = 0; r2 < m; ++r2)
        {
            if (r2 % 3 == 1)
            {
                EXPECT_LE(f(r2), 1e-9*fRef) << what << ", row " << r2;
            }
        }
        EXPECT_LE(r.newtonSteps, rt.newtonSteps + 2) << what;
    }
}


TEST(blockPivotingLCP, bodySpaceMatchesEnumeration)
{
    // Two bodies, 13-15 contacts (d = 12 < n): the block exchanges and the
    // interior point work in body space; compliant (unique f) and exact
    // (singular A, redundant contacts) problems
    const rbd::blockPivotingLCP solver(parse(noBaraffDict));
    const rbd::blockPivotingLCP interior(parse(interiorDict));
    rng gen(404);
    for (int trial = 0; trial < 60; ++trial)
    {
        const double c = trial % 2 ? 1e-4 : 0;
        const heap hp = randomHeap(gen, 2, uniformInt(gen, 13, 15), c);
        const std::string what =
            "trial " + std::to_string(trial) + " c " + std::to_string(c);
        compareWithEnumeration
        (
            solver, hp.p, {}, 1e-7, what, hp.factors
        );
        compareWithEnumeration
        (
            interior, hp.p, {}, 1e-6, "interior point, " + what, hp.factors
        );
    }
}


TEST(blockPivotingLCP, bodySpaceAgreesWithContactSpace)
{
    // Heaps of 2-6 bodies with 7-12 contacts per body: the solve with the
    // factors (body space) and without (contact space) meet the tolerance
    // and agree in w (unique for PSD A) and, where the compliance makes A
    // positive definite, in f
    const rbd::blockPivotingLCP solver(parse(noBaraffDict));
    rng gen(505);
    const double compliances[] = {0, 1e-5, 1e-3};
    for (int trial = 0; trial < 60; ++trial)
    {
        const double c = compliances[trial % 3];
        const int k = uniformInt(gen, 2, 6);
        const heap hp = randomHeap(gen, k, uniformInt(gen, 7*k, 12*k), c);
        const std::string what =
            "trial " + std::to_string(trial) + " c " + std::to_string(c);
        const Eigen::SparseMatrix<double> As(hp.p.A.sparseView());
        std::vector<bool> guess(hp.p.b.size());
        for (label i = 0; i < label(guess.size()); ++i)
        {
            guess[i] = hp.p.b(i) < 0;
        }

        Vec fBody, fContact;
        const rbd::lcpResult rb =
            solver.solve(As, hp.factors, hp.p.b, guess, fBody);
        const rbd::lcpResult rc = solver.solve(As, hp.p.b, guess, fContact);
        EXPECT_TRUE(rb.converged) << what << ": " << rb.maxViolation;
        EXPECT_TRUE(rc.converged) << what << ": " << rc.maxViolation;
        EXPECT_LE(rbd::lcpSolver::violation(As, hp.p.b, fBody), 1e-8)
            << what;
        EXPECT_GE(fBody.minCoeff(), 0) << what;

        // Without compliance (c = 0) A is singular and K = I + G^T G/eps
        // has a condition of about 1/regularisation (1e10): both answers
        // meet the violation tolerance, and their w agree to what that
        // round-off allows (measured over these 20 trials: at most 2.3e-7
        // of scale with the block factorisation of K, 2.5e-8 with the
        // scalar one it replaced; 1e-14 with compliance)
        const double scale = wScale(hp.p, fContact);
        EXPECT_LE
        (
            (w(hp.p, fBody) - w(hp.p, fContact)).cwiseAbs().maxCoeff(),
            (c > 0 ? 1e-7 : 1e-6)*scale
        ) << what;
        if (c > 0)
        {
            EXPECT_LE
            (
                (fBody - fContact).cwiseAbs().maxCoeff(),
                1e-6*fContact.cwiseAbs().maxCoeff()
            ) << what;
        }
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
        const std::vector<bool> exact(activeSet(f));
        EXPECT_EQ
        (
            compareWithEnumeration(solver, p, exact, 1e-8, "exact guess"),
            1
        );
    }
}


TEST(blockPivotingLCP, keptFactorChangesTheWorkNotTheAnswer)
{
    // The staggered friction's two normal passes: the same A, b changed;
    // the second starts from the active set the first ended with, from
    // the factor the first left in the caller's activeSetFactor (that of
    // its last factorised set, its last set by an update: the forces
    // then differ from a fresh solve's by round-off only)
    const rbd::blockPivotingLCP solver(parse(pureDict));
    rng gen(17);
    for (int trial = 0; trial < 60; ++trial)
    {
        const problem p = randomProblem(gen, kind::regular);
        const label n = p.b.size();
        const Eigen::SparseMatrix<double> A(p.A.sparseView());
        const rbd::lcpFactors none;

        rbd::activeSetFactor kept;
        Vec f1;
        solver.solve(A, none, p.b, {}, f1, kept);
        ASSERT_TRUE(kept.valid) << trial;
        const std::vector<bool> active(activeSet(f1));

        Vec b2(p.b);
        for (label i = 0; i < n; ++i)
        {
            b2(i) += 0.01*uniform(gen, -1, 1)*p.b.cwiseAbs().maxCoeff();
        }
        Vec fKept, fFresh;
        const rbd::lcpResult rKept =
            solver.solve(A, none, b2, active, fKept, kept);
        const rbd::lcpResult rFresh = solver.solve(A, none, b2, active, fFresh);
        EXPECT_EQ(rKept.iterations, rFresh.iterations) << trial;
        EXPECT_EQ(rKept.converged, rFresh.converged) << trial;
        EXPECT_LE
        (
            (fKept - fFresh).cwiseAbs().maxCoeff(),
            1e-9*fFresh.cwiseAbs().maxCoeff()
        ) << trial << ": the kept factor changed the forces";
    }
}


TEST(blockPivotingLCP, keptFactorIsTakenAsTheFactorOfItsSet)
{
    // A kept factor is used as it is, without a check of the matrix: the
    // caller invalidates it when A changes. A factor kept for another
    // matrix (with the same diagonal) then gives another answer, which
    // shows the reuse takes place; invalidated, the answer is right again.
    // One candidate only (maxIterations 1): the answer is the candidate
    // of the guessed set, not one the exchanges repaired
    const rbd::blockPivotingLCP solver
    (
        parse("interiorPointIterations 0; fallbackSize 0; maxIterations 1;")
    );
    const rbd::blockPivotingLCP full(parse(pureDict));
    rng gen(23);
    label differed = 0;
    for (int trial = 0; trial < 20; ++trial)
    {
        const problem p = randomProblem(gen, kind::regular);
        const label n = p.b.size();
        const Eigen::SparseMatrix<double> A(p.A.sparseView());
        // Another matrix with the same diagonal (so the same
        // regularisation): (A + diag(A))/2, positive semidefinite
        const Eigen::MatrixXd dense2
        (
            0.5*p.A + 0.5*Eigen::MatrixXd(p.A.diagonal().asDiagonal())
        );
        const Eigen::SparseMatrix<double> A2(dense2.sparseView());
        const rbd::lcpFactors none;

        rbd::activeSetFactor kept;
        Vec f;
        full.solve(A2, none, p.b, {}, f);
        const std::vector<bool> active2(activeSet(f));
        solver.solve(A2, none, p.b, active2, f, kept);
        const std::vector<bool> active(activeSet(f));

        Vec fStale, fRight;
        solver.solve(A, none, p.b, active, fStale, kept);
        kept.invalidate();
        solver.solve(A, none, p.b, active, fRight, kept);
        Vec fRef;
        solver.solve(A, p.b, active, fRef);
        EXPECT_TRUE((fRight.array() == fRef.array()).all()) << trial;

        // A_FF and A2_FF differ where two contacts of F are coupled
        bool coupled = false;
        for (label i = 0; i < n; ++i)
        {
            for (label j = 0; j < n; ++j)
            {
                coupled =
                    coupled
                 || (i != j && active[i] && active[j] && p.A(i, j) != 0);
            }
        }
        const bool differs =
            (fStale - fRef).cwiseAbs().maxCoeff()
          > 1e-6*fRef.cwiseAbs().maxCoeff();
        EXPECT_EQ(differs, coupled) << trial;
        differed += differs;
    }
    EXPECT_GT(differed, 5);
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
        parse("maxIterations 1; interiorPointIterations 0; fallbackSize 400;")
    );
    EXPECT_TRUE(handed.solve(p.A.sparseView(), p.b, {}, f).converged);
    EXPECT_LE(rbd::lcpSolver::violation(p.A, p.b, f), 1e-9);

    const rbd::blockPivotingLCP capped
    (
        parse("maxIterations 1; interiorPointIterations 0; fallbackSize 0;")
    );
    const rbd::lcpResult r = capped.solve(p.A.sparseView(), p.b, {}, f);
    EXPECT_FALSE(r.converged);
    EXPECT_EQ(r.iterations, 1);
    EXPECT_GE(f.minCoeff(), 0);
    EXPECT_GT(r.maxViolation, 1e-9);
}




// Two islands of 140 contacts from a 347-sphere bed at N = 5.6 (Table 3
// properties, at 118 pellets), written by the solver when its block
// pivoting failed them (blockPivotingLCP's debug switch writes such files):
// singular (rank 127 and 130), feasible (checked with an LP), degenerate;
// and two of 262 and 273 contacts from the spheres tutorial.
// File: n nnz eps, then the triplets (row col value) of A, then b_i and the
// previous step's guess per row.
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
        const std::string file
        (
            std::string(RBD_TEST_SOURCE_DIR)
          + "/rbdPacking/contactResolution/lcp/blockPivotingLCP/data/"
          + name + ".lcp"
        );
        std::ifstream is(file);
        if (!is.good())
        {
            // Not a crash further on: the caller's checks fail on the
            // empty problem
            ADD_FAILURE() << "cannot read " << file;
            return p;
        }
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


TEST(blockPivotingLCP, solvesDegenerateBedIslands)
{
    // The block exchanges cycle on both (pivoting alone stops 1e-8 to
    // 2.5e-6 away); the interior point solves them within the tolerance,
    // warm or cold, and returns the load-carrying contacts (f = 0 where
    // the force is below the tolerance and the gap dominates), not a
    // strictly positive iterate
    const rbd::blockPivotingLCP solver(parse(noBaraffDict));
    for (const std::string name : {"bedIsland140a", "bedIsland140b"})
    {
        const recordedIsland p = readIsland(name);
        ASSERT_GT(p.b.size(), 0) << name;
        for (const bool warm : {true, false})
        {
            Vec f;
            const rbd::lcpResult r = solver.solve
            (
                p.A, p.b, warm ? p.guess : std::vector<bool>(), f
            );
            const std::string what = name + (warm ? " warm" : " cold");
            EXPECT_TRUE(r.converged) << what;
            EXPECT_GE(f.minCoeff(), 0) << what;
            EXPECT_GT(f.maxCoeff(), 0) << what;
            EXPECT_LE(independentViolation(p, f), 1e-9) << what;
            EXPECT_GT((f.array() == 0).count(), p.b.size()/10) << what;
        }
    }
}


TEST(blockPivotingLCP, solvesTheTutorialsHardestIslands)
{
    // Two islands of the spheres tutorial (seeds 2 and 3) that no earlier
    // version solved within the tolerance: on the 273-contact one the
    // interior point stalled at 1.4e-8 with its Newton matrix regularised
    // (and baraff then took 44 s); on the 262-contact one the violation
    // stays near 4e-8 for five Newton steps before it converges
    const rbd::blockPivotingLCP solver(parse(noBaraffDict));
    for (const std::string name : {"tutorialIsland273", "tutorialIsland262"})
    {
        const recordedIsland p = readIsland(name);
        ASSERT_GT(p.b.size(), 0) << name;
        Vec f;
        const rbd::lcpResult r = solver.solve(p.A, p.b, p.guess, f);
        EXPECT_TRUE(r.converged) << name;
        EXPECT_GE(f.minCoeff(), 0) << name;
        EXPECT_LE(independentViolation(p, f), 1e-9) << name;
        EXPECT_LE(r.iterations, 60) << name;
    }
}


TEST(blockPivotingLCP, reportsAnUnsolvedDegenerateIslandWithItsBestCandidate)
{
    // Block pivoting alone on an island where it cycles: the solver must
    // say whether its candidate meets the tolerance, report its violation,
    // and return f >= 0
    const rbd::blockPivotingLCP pure(parse(pureDict));
    const recordedIsland p = readIsland("bedIsland140b");
    ASSERT_GT(p.b.size(), 0);
    for (const bool warm : {true, false})
    {
        Vec f;
        const rbd::lcpResult r =
            pure.solve(p.A, p.b, warm ? p.guess : std::vector<bool>(), f);
        const double v = independentViolation(p, f);
        EXPECT_EQ(r.converged, v <= 1e-9) << "warm " << warm;
        EXPECT_NEAR(r.maxViolation, v, 1e-12 + 1e-6*v);
        EXPECT_GE(f.minCoeff(), 0);
    }
}


// ************************************************************************* //
