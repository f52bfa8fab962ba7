// Unit tests for src/rbdPacking/contactResolution/lcp/baraffLCP:
// against the enumeration reference on random (also singular) problems,
// large islands, infeasible and degenerate input

#include <gtest/gtest.h>
#include "rbdPacking/contactResolution/lcp/lcpTestProblems.H"
#include "baraffLCP.H"
#include "rbdPacking/contactResolution/lcp/enumerationLCP/enumerationLCP.H"

using namespace Foam;
using namespace lcpTest;

namespace
{
    //- Solve p with baraff and enumeration; expect both to converge, to
    //  agree on w (unique for symmetric PSD A) and baraff's f to be a
    //  solution. Returns baraff's pivots.
    label compareWithEnumeration
    (
        const rbd::lcpSolver& solver,
        const problem& p,
        const double wTol,
        const std::string& what
    )
    {
        const rbd::enumerationLCP reference(dictionary::null);
        Vec fRef;
        const rbd::lcpResult rRef = reference.solve(p.A, p.b, fRef);
        EXPECT_TRUE(rRef.converged) << what << ": reference failed";

        Vec f;
        const rbd::lcpResult r = solver.solve(p.A, p.b, f);
        EXPECT_TRUE(r.converged) << what << ": " << r.maxViolation;
        EXPECT_TRUE(f.allFinite()) << what;
        EXPECT_GE(f.minCoeff(), 0) << what;
        EXPECT_LE(r.maxViolation, 1e-10) << what;
        EXPECT_DOUBLE_EQ(r.maxViolation, rbd::lcpSolver::violation(p.A, p.b, f))
            << what;

        const double scale = wScale(p, fRef);
        EXPECT_LE((w(p, f) - w(p, fRef)).cwiseAbs().maxCoeff(), wTol*scale)
            << what;
        return r.iterations;
    }
}


TEST(baraffLCP, matchesEnumerationOnRandomProblems)
{
    const rbd::baraffLCP solver(dictionary::null);
    rng gen(1994);
    label pivots = 0;
    label contacts = 0;
    for (int trial = 0; trial < 150; ++trial)
    {
        const problem p = randomProblem(gen, kind::regular);
        pivots += compareWithEnumeration
        (
            solver, p, 1e-9, "regular " + std::to_string(trial)
        );
        contacts += p.b.size();
    }
    // Dantzig-type pivoting visits each contact a few times at most
    EXPECT_LE(pivots, 3*contacts);
}


TEST(baraffLCP, matchesEnumerationOnSingularProblems)
{
    const rbd::baraffLCP solver(dictionary::null);
    rng gen(34);
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
            solver, p, 1e-8, "singular " + std::to_string(trial)
        );
    }
}


TEST(baraffLCP, isScaleFreeAtPelletScale)
{
    // 4 g pellets of 5 mm: A ~ 1e3 1/kg, f ~ 1e-2 N; same tolerances
    const rbd::baraffLCP solver(dictionary::null);
    rng gen(10);
    for (int trial = 0; trial < 60; ++trial)
    {
        compareWithEnumeration
        (
            solver,
            randomProblem(gen, kind::pelletScale),
            1e-9,
            "pellet " + std::to_string(trial)
        );
    }
}


TEST(baraffLCP, denseFallbackMatchesUpdatedFactor)
{
    // Larger islands (no reference possible): the updated Cholesky and
    // the per-pivot complete orthogonal decomposition give the same w
    const rbd::baraffLCP updated(dictionary::null);
    const rbd::baraffLCP dense(parse("updateFactorisation no;"));
    rng gen(7);
    for (int trial = 0; trial < 10; ++trial)
    {
        std::vector<body> bodies;
        for (int i = 0; i < 8; ++i)
        {
            bodies.push_back(randomBody(gen, 1, 1));
        }
        Mat J = randomJacobian(gen, bodies, 40, 1);
        J.row(39) = J.row(0);           // a duplicated contact
        const problem p = restingUnderGravity(bodies, J);

        Vec f1, f2;
        const rbd::lcpResult r1 = updated.solve(p.A, p.b, f1);
        const rbd::lcpResult r2 = dense.solve(p.A, p.b, f2);
        EXPECT_TRUE(r1.converged) << trial << ": " << r1.maxViolation;
        EXPECT_TRUE(r2.converged) << trial << ": " << r2.maxViolation;
        EXPECT_LE
        (
            (w(p, f1) - w(p, f2)).cwiseAbs().maxCoeff(),
            1e-8*wScale(p, f1)
        ) << trial;
    }
}


TEST(baraffLCP, solvesLargeSingularIsland)
{
    // 300 contacts on 40 bodies (A of rank <= 240)
    const rbd::baraffLCP solver(dictionary::null);
    rng gen(2018);
    std::vector<body> bodies;
    for (int i = 0; i < 40; ++i)
    {
        bodies.push_back(randomBody(gen, 1, 1));
    }
    const Mat J = randomJacobian(gen, bodies, 300, 1);
    const problem p = restingUnderGravity(bodies, J);

    Vec f;
    const rbd::lcpResult r = solver.solve(p.A, p.b, f);
    EXPECT_TRUE(r.converged) << r.maxViolation;
    EXPECT_LE(r.maxViolation, 1e-10);
    EXPECT_GE(f.minCoeff(), 0);
    EXPECT_LE(r.iterations, 3*300);
}


TEST(baraffLCP, reportsInfeasibleWithoutNaN)
{
    // A sphere between two parallel walls touching at the same height,
    // with velocity terms pressing it into both: w_1 + w_2 = b_1 + b_2 < 0
    // whatever f is. A contact on the floor below is still solved.
    const std::vector<body> bodies{sphere(1, 0.5, Vec3(0, 0, 0.5))};
    Mat J(3, 6);
    J.row(0) = contactRow(bodies, 0, -1, Vec3(-0.5, 0, 0.5), Vec3(1, 0, 0));
    J.row(1) = contactRow(bodies, 0, -1, Vec3(0.5, 0, 0.5), Vec3(-1, 0, 0));
    J.row(2) = contactRow(bodies, 0, -1, Vec3(0, 0, 0), Vec3(0, 0, 1));
    problem p = restingUnderGravity(bodies, J);
    p.b(0) = -1;
    p.b(1) = -2;

    const rbd::baraffLCP solver(dictionary::null);
    Vec f;
    const rbd::lcpResult r = solver.solve(p.A, p.b, f);
    EXPECT_FALSE(r.converged);
    ASSERT_TRUE(f.allFinite());
    EXPECT_GE(f.minCoeff(), 0);
    EXPECT_GT(r.maxViolation, 1e-3);
    EXPECT_NEAR(f(2), gravity, 1e-9);   // floor contact: m g
}


TEST(baraffLCP, recoversKnownForcesWhenAllContactsAreActive)
{
    // b = -A g, g > 0: w = 0 at the solution, and for nonsingular A
    // (not guaranteed: a body may get more than 6 contacts) f = g is the
    // only solution
    const rbd::baraffLCP solver(dictionary::null);
    rng gen(38);
    int unique = 0;
    for (int trial = 0; trial < 100; ++trial)
    {
        const int nBodies = uniformInt(gen, 1, 4);
        Vec g;
        const problem p =
            activeProblem(gen, nBodies, uniformInt(gen, 1, 6*nBodies), g);
        Vec f;
        const rbd::lcpResult r = solver.solve(p.A, p.b, f);
        EXPECT_TRUE(r.converged) << trial;
        EXPECT_LE(w(p, f).cwiseAbs().maxCoeff(), 1e-10*wScale(p, f))
            << trial;

        const Vec ev = Eigen::SelfAdjointEigenSolver<Mat>
        (
            p.A, Eigen::EigenvaluesOnly
        ).eigenvalues();
        const double cond = ev.maxCoeff()/ev.minCoeff();
        if (ev.minCoeff() > 0 && cond < 1e8)
        {
            ++unique;
            EXPECT_LE((f - g).cwiseAbs().maxCoeff(), 1e-15*cond*gravity)
                << trial << ", cond(A) " << cond;
        }
    }
    EXPECT_GE(unique, 50);
}


TEST(baraffLCP, stopsAtPivotCap)
{
    // Find a problem whose solve removes contacts from the clamped set
    // (more than n pivots), then allow only n
    rng gen(5);
    const rbd::baraffLCP solver(dictionary::null);
    const rbd::baraffLCP capped(parse("maxPivotsPerContact 1;"));
    bool found = false;
    for (int trial = 0; trial < 300 && !found; ++trial)
    {
        const int nBodies = uniformInt(gen, 1, 3);
        Vec g;
        const problem p =
            activeProblem(gen, nBodies, uniformInt(gen, 2, 6*nBodies), g);
        Vec f;
        const rbd::lcpResult r = solver.solve(p.A, p.b, f);
        if (r.iterations > p.b.size())
        {
            found = true;
            EXPECT_TRUE(r.converged);
            const rbd::lcpResult rc = capped.solve(p.A, p.b, f);
            EXPECT_FALSE(rc.converged);
            EXPECT_EQ(rc.iterations, p.b.size());
            EXPECT_TRUE(f.allFinite());
            EXPECT_GE(f.minCoeff(), 0);
        }
    }
    EXPECT_TRUE(found);
}


TEST(baraffLCP, handlesTrivialAndNonFiniteInput)
{
    const rbd::baraffLCP solver(dictionary::null);
    Vec f;

    // No contacts
    rbd::lcpResult r = solver.solve(Mat(0, 0), Vec(0), f);
    EXPECT_TRUE(r.converged);
    EXPECT_EQ(f.size(), 0);

    // Separating contacts: f = 0 without a pivot
    Mat A(2, 2);
    A << 2, 1, 1, 2;
    r = solver.solve(A, Eigen::Vector2d(1, 0), f);
    EXPECT_TRUE(r.converged);
    EXPECT_EQ(r.iterations, 0);
    EXPECT_EQ(f, Vec::Zero(2));

    // NaN: f = 0, not converged
    r = solver.solve(A, Eigen::Vector2d(-1, std::nan("")), f);
    EXPECT_FALSE(r.converged);
    EXPECT_EQ(f, Vec::Zero(2));
}


// ************************************************************************* //
