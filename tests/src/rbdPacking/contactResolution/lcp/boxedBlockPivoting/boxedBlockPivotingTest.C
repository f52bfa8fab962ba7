// Unit tests for src/rbdPacking/contactResolution/lcp/boxedBlockPivoting:
// the boxed LCP of resting contacts with friction (a normal row and two
// tangent rows per contact) against a brute-force reference that tries
// every assignment of the variables to their lower bound, upper bound or
// the free set; block pivoting alone and the interior point alone; body
// space against contact space; fixed variables; the violation measure

#include <gtest/gtest.h>
#include "rbdPacking/contactResolution/lcp/lcpTestProblems.H"
#include "boxedBlockPivoting.H"

#include <limits>
#include <memory>

using namespace Foam;
using namespace lcpTest;

namespace
{
    const double inf = std::numeric_limits<double>::infinity();

    //- A boxed problem with A's factors
    struct boxedProblem
    {
        problem p;
        Vec lo, hi;
        rbd::lcpFactors factors;
    };

    //- Spheres resting on each other and the floor, each contact with a
    //  normal row and two tangent rows; A = J W J^T + diag(c A_ii) (the
    //  compliance of restingContactSolver), b = J u + a random slip/h on
    //  the tangent rows; normal in [0, inf), tangents in +-mu phiRef
    boxedProblem randomFrictionProblem(rng& gen, const int nContacts)
    {
        const int nBodies = uniformInt(gen, 1, 3);
        std::vector<body> bodies;
        for (int i = 0; i < nBodies; ++i)
        {
            bodies.push_back
            (
                sphere
                (
                    uniform(gen, 0.002, 0.01), 0.005,
                    Vec3(0.01*i, 0, 0.005)
                )
            );
        }
        const int n = 3*nContacts;
        Mat J(n, 6*nBodies);
        Vec lo(n), hi(n), slip(Vec::Zero(n));
        for (int c = 0; c < nContacts; ++c)
        {
            const int i = uniformInt(gen, 0, nBodies - 1);
            int k = uniformInt(gen, -1, nBodies - 1);
            if (k == i)
            {
                k = -1;
            }
            const Vec3 nrm(randomUnit(gen));
            const Vec3 p(bodies[i].x - 0.005*nrm);
            const Vec3 t1(nrm.unitOrthogonal());
            const Vec3 t2(nrm.cross(t1));
            J.row(3*c) = contactRow(bodies, i, k, p, nrm);
            J.row(3*c + 1) = contactRow(bodies, i, k, p, t1);
            J.row(3*c + 2) = contactRow(bodies, i, k, p, t2);
            const double limit = uniform(gen, 0, 0.05);
            lo(3*c) = 0;
            hi(3*c) = inf;
            lo(3*c + 1) = lo(3*c + 2) = -limit;
            hi(3*c + 1) = hi(3*c + 2) = limit;
            slip(3*c + 1) = uniform(gen, -10, 10);
            slip(3*c + 2) = uniform(gen, -10, 10);
        }
        problem p(restingUnderGravity(bodies, J));
        Vec s(n);
        for (int r = 0; r < n; ++r)
        {
            s(r) = 1e-5*p.A(r, r);
            p.A(r, r) += s(r);
        }
        p.b += slip;
        return boxedProblem{p, lo, hi, factorsOf(bodies, J, s)};
    }

    //- Every assignment of the variables to L, U or F (3^n, n <= 9): the
    //  first that solves the problem (A positive definite: the only one)
    bool enumerate(const boxedProblem& q, Vec& x)
    {
        const Mat& A = q.p.A;
        const Vec& b = q.p.b;
        const int n = b.size();
        long combos = 1;
        for (int i = 0; i < n; ++i)
        {
            combos *= 3;
        }
        const double bRef = b.cwiseAbs().maxCoeff();
        for (long code = 0; code < combos; ++code)
        {
            std::vector<int> side(n);
            long c = code;
            bool valid = true;
            for (int i = 0; i < n; ++i)
            {
                side[i] = int(c % 3);
                c /= 3;
                valid = valid && !(side[i] == 2 && !std::isfinite(q.hi(i)));
            }
            if (!valid)
            {
                continue;
            }
            x = Vec::Zero(n);
            std::vector<int> F;
            for (int i = 0; i < n; ++i)
            {
                if (side[i] == 0) x(i) = q.lo(i);
                else if (side[i] == 2) x(i) = q.hi(i);
                else F.push_back(i);
            }
            const Vec r(-(b + A*x));
            Mat AFF(F.size(), F.size());
            Vec rF(F.size());
            for (size_t a = 0; a < F.size(); ++a)
            {
                rF(a) = r(F[a]);
                for (size_t c2 = 0; c2 < F.size(); ++c2)
                {
                    AFF(a, c2) = A(F[a], F[c2]);
                }
            }
            const Vec xF(AFF.ldlt().solve(rF));
            for (size_t a = 0; a < F.size(); ++a)
            {
                x(F[a]) = xF(a);
            }
            const Vec w(A*x + b);
            const double xTol = 1e-9*std::max(x.cwiseAbs().maxCoeff(), 1e-30);
            bool ok = true;
            for (int i = 0; i < n && ok; ++i)
            {
                if (side[i] == 1)
                {
                    ok = x(i) >= q.lo(i) - xTol && x(i) <= q.hi(i) + xTol;
                }
                else if (side[i] == 0)
                {
                    ok = w(i) >= -1e-9*bRef;
                }
                else
                {
                    ok = w(i) <= 1e-9*bRef;
                }
            }
            if (ok)
            {
                return true;
            }
        }
        return false;
    }

    //- Solve q with solver, with or without the factors, and compare with
    //  the reference
    void compare
    (
        const rbd::boxedBlockPivoting& solver,
        const boxedProblem& q,
        const bool bodySpace,
        const std::string& what
    )
    {
        Vec xRef;
        ASSERT_TRUE(enumerate(q, xRef)) << what << ": no reference";

        std::vector<rbd::boxedBlockPivoting::side> sides;
        Vec x;
        const rbd::lcpResult r = solver.solve
        (
            q.p.A.sparseView(), bodySpace ? q.factors : rbd::lcpFactors(),
            q.p.b, q.lo, q.hi, sides, x
        );
        EXPECT_TRUE(r.converged) << what << ": " << r.maxViolation;
        EXPECT_LE(r.maxViolation, 1e-8) << what;
        ASSERT_EQ(x.size(), xRef.size()) << what;
        for (int i = 0; i < x.size(); ++i)
        {
            EXPECT_GE(x(i), q.lo(i)) << what;
            EXPECT_LE(x(i), q.hi(i)) << what;
        }
        EXPECT_LE
        (
            (x - xRef).cwiseAbs().maxCoeff(),
            1e-6*xRef.cwiseAbs().maxCoeff() + 1e-15
        ) << what;
    }
}


TEST(boxedBlockPivoting, blockPivotingMatchesEnumeration)
{
    // Pivoting alone (no interior point) on problems of one to three
    // contacts (3-9 variables)
    const rbd::boxedBlockPivoting pivoting(1e-9, 1e-10, 100, 0);
    rng gen(11);
    label solved = 0;
    for (int trial = 0; trial < 40; ++trial)
    {
        const boxedProblem q(randomFrictionProblem(gen, uniformInt(gen, 1, 3)));
        std::vector<rbd::boxedBlockPivoting::side> sides;
        Vec x;
        const rbd::lcpResult r = pivoting.solve
        (
            q.p.A.sparseView(), rbd::lcpFactors(), q.p.b, q.lo, q.hi,
            sides, x
        );
        if (r.converged)
        {
            ++solved;
            compare(pivoting, q, false, "trial " + std::to_string(trial));
        }
    }
    // Block exchanges may cycle (then the interior point takes over); on
    // these small problems they rarely do
    EXPECT_GE(solved, 36);
}


TEST(boxedBlockPivoting, interiorPointMatchesEnumeration)
{
    // One factorisation of block pivoting, then the interior point
    const rbd::boxedBlockPivoting interior(1e-9, 1e-10, 1, 50);
    rng gen(12);
    for (int trial = 0; trial < 30; ++trial)
    {
        compare
        (
            interior, randomFrictionProblem(gen, uniformInt(gen, 1, 3)),
            false, "trial " + std::to_string(trial)
        );
    }
}


TEST(boxedBlockPivoting, bodySpaceMatchesEnumeration)
{
    // Three contacts on one sphere (9 rows, 6 degrees of freedom): body
    // space; pivoting and the interior point alike
    const rbd::boxedBlockPivoting solver;
    const rbd::boxedBlockPivoting interior(1e-9, 1e-10, 1, 50);
    rng gen(13);
    label inBodySpace = 0;
    for (int trial = 0; trial < 30; ++trial)
    {
        const boxedProblem q(randomFrictionProblem(gen, 3));
        if (q.factors.G.cols() < q.factors.G.rows())
        {
            ++inBodySpace;
            compare(solver, q, true, "pivoting " + std::to_string(trial));
            compare(interior, q, true, "interior " + std::to_string(trial));
        }
    }
    EXPECT_GE(inBodySpace, 5);
}


TEST(boxedBlockPivoting, interiorPointInBodySpaceMeetsTheToleranceUnrefined)
{
    // Heaps of 8-12 contacts with friction on 1-3 spheres (24-36 rows, at
    // most 18 degrees of freedom; compliance 1e-5 A_aa: A positive
    // definite but ill-conditioned, E^-1 large where r - G y loses
    // digits): the interior point alone, its Newton directions not
    // refined in body space, meets the tolerance and gives the answer
    // of the same interior point in contact space (a direct LDL^T of A +
    // D), unique for positive definite A
    const rbd::boxedBlockPivoting interior(1e-9, 1e-10, 1, 50);
    rng gen(15);
    label inBodySpace = 0;
    for (int trial = 0; trial < 40; ++trial)
    {
        const boxedProblem q
        (
            randomFrictionProblem(gen, uniformInt(gen, 8, 12))
        );
        if (!(q.factors.G.cols() < q.factors.G.rows()))
        {
            continue;
        }
        ++inBodySpace;
        const std::string what = "trial " + std::to_string(trial);
        const Eigen::SparseMatrix<double> As(q.p.A.sparseView());
        std::vector<rbd::boxedBlockPivoting::side> sidesB, sidesC;
        Vec xB, xC;
        const rbd::lcpResult rb = interior.solve
        (
            As, q.factors, q.p.b, q.lo, q.hi, sidesB, xB
        );
        const rbd::lcpResult rc = interior.solve
        (
            As, rbd::lcpFactors(), q.p.b, q.lo, q.hi, sidesC, xC
        );
        EXPECT_TRUE(rb.converged) << what << ": " << rb.maxViolation;
        EXPECT_TRUE(rc.converged) << what << ": " << rc.maxViolation;
        EXPECT_LE(rb.maxViolation, 1e-9) << what;
        EXPECT_LE
        (
            (xB - xC).cwiseAbs().maxCoeff(),
            1e-5*xC.cwiseAbs().maxCoeff() + 1e-15
        ) << what;
    }
    EXPECT_GE(inBodySpace, 30);
}


TEST(boxedBlockPivoting, withoutExchangesTheInteriorPointAnswersAlone)
{
    // exchanges = false (the later rounds of an island whose first round
    // cycled): no factorisation of block pivoting, the interior point
    // from the start; its answer matches enumeration in contact and in
    // body space, and every iteration is one of its Newton steps
    const rbd::boxedBlockPivoting solver;
    rng gen(16);
    label inBodySpace = 0;
    for (int trial = 0; trial < 30; ++trial)
    {
        const boxedProblem q(randomFrictionProblem(gen, uniformInt(gen, 1, 3)));
        Vec xRef;
        ASSERT_TRUE(enumerate(q, xRef));
        const Eigen::SparseMatrix<double> As(q.p.A.sparseView());
        std::unique_ptr<rbd::lcpBodySpace> body;
        if (rbd::lcpBodySpace::pays(As, q.factors))
        {
            body.reset(new rbd::lcpBodySpace(q.factors));
            ++inBodySpace;
        }
        for (const bool exchanges : {true, false})
        {
            const std::string what =
                "trial " + std::to_string(trial)
              + (exchanges ? ", exchanges" : ", interior point alone");
            std::vector<rbd::boxedBlockPivoting::side> sides;
            Vec x;
            const rbd::lcpResult r = solver.solve
            (
                As, body.get(), q.p.b, q.lo, q.hi, sides, x, exchanges
            );
            EXPECT_TRUE(r.converged) << what << ": " << r.maxViolation;
            EXPECT_LE
            (
                (x - xRef).cwiseAbs().maxCoeff(),
                1e-6*xRef.cwiseAbs().maxCoeff() + 1e-15
            ) << what;
            if (!exchanges)
            {
                EXPECT_GT(r.newtonSteps, 0) << what;
                EXPECT_EQ(r.iterations, r.newtonSteps) << what;
            }
            else
            {
                EXPECT_LE(r.newtonSteps, r.iterations) << what;
            }
            ASSERT_EQ(label(sides.size()), label(x.size())) << what;
        }
    }
    EXPECT_GE(inBodySpace, 3);
}


TEST(boxedBlockPivoting, interiorPointStartsOnTheScaleOfTheLoad)
{
    // A third of the contacts within the proximity band but apart: normal
    // row b + 2e6 m/s^2 (2 (gap + h v_n)/h^2 at a heap's small steps),
    // no friction (lo = hi = 0: no normal force in the pass before). The
    // interior point alone gives them no force, at most two Newton steps
    // dearer than the problem without them (a start on max |b| took about
    // seven more: docs/restingSolveCost.md, "Twenty-sixth session")
    const rbd::boxedBlockPivoting solver;
    rng gen(17);
    for (int trial = 0; trial < 20; ++trial)
    {
        const std::string what = "trial " + std::to_string(trial);
        const int nContacts = uniformInt(gen, 6, 12);
        boxedProblem q(randomFrictionProblem(gen, nContacts));
        std::vector<int> kept;
        for (int c = 0; c < nContacts; ++c)
        {
            if (c % 3 == 1)
            {
                q.p.b(3*c) += 2e6;
                q.lo(3*c + 1) = q.hi(3*c + 1) = 0;
                q.lo(3*c + 2) = q.hi(3*c + 2) = 0;
            }
            else
            {
                kept.push_back(3*c);
                kept.push_back(3*c + 1);
                kept.push_back(3*c + 2);
            }
        }
        const int k = kept.size();
        Mat At(k, k);
        Vec bt(k), lot(k), hit(k);
        for (int a = 0; a < k; ++a)
        {
            bt(a) = q.p.b(kept[a]);
            lot(a) = q.lo(kept[a]);
            hit(a) = q.hi(kept[a]);
            for (int c = 0; c < k; ++c)
            {
                At(a, c) = q.p.A(kept[a], kept[c]);
            }
        }

        std::vector<rbd::boxedBlockPivoting::side> sides, sidesT;
        Vec x, xT;
        const Eigen::SparseMatrix<double> As(q.p.A.sparseView());
        const Eigen::SparseMatrix<double> AsT(At.sparseView());
        const rbd::lcpResult r = solver.solve
        (
            As, nullptr, q.p.b, q.lo, q.hi, sides, x, false
        );
        const rbd::lcpResult rt = solver.solve
        (
            AsT, nullptr, bt, lot, hit, sidesT, xT, false
        );
        ASSERT_TRUE(r.converged) << what << ": " << r.maxViolation;
        ASSERT_TRUE(rt.converged) << what << ": " << rt.maxViolation;
        // (The other rows' answers agree only to the tolerance, which is
        // relative to max |b|: here the apart rows' 2e6)
        const double xRef = max(xT.cwiseAbs().maxCoeff(), 1e-300);
        for (int c = 1; c < nContacts; c += 3)
        {
            EXPECT_LE(mag(x(3*c)), 1e-9*xRef) << what << ", contact " << c;
        }
        EXPECT_LE(r.newtonSteps, rt.newtonSteps + 2) << what;
    }
}


TEST(boxedBlockPivoting, keepsFixedVariablesAtTheirBound)
{
    // lo = hi (friction of a contact without normal force): x = lo, w free
    rng gen(14);
    boxedProblem q(randomFrictionProblem(gen, 2));
    q.lo(1) = q.hi(1) = 0.01;
    q.lo(2) = q.hi(2) = -0.02;
    compare(rbd::boxedBlockPivoting(), q, false, "fixed");
    std::vector<rbd::boxedBlockPivoting::side> sides;
    Vec x;
    rbd::boxedBlockPivoting().solve
    (
        q.p.A.sparseView(), rbd::lcpFactors(), q.p.b, q.lo, q.hi, sides, x
    );
    EXPECT_EQ(x(1), 0.01);
    EXPECT_EQ(x(2), -0.02);
}


TEST(boxedBlockPivoting, violationMeasuresBoundsAndComplementarity)
{
    const Vec lo((Vec(3) << 0, -1, -1).finished());
    const Vec hi((Vec(3) << inf, 1, 1).finished());
    const Vec b((Vec(3) << -1, 1, 1).finished());
    // At the bounds with the right signs of w, or free with w = 0
    EXPECT_EQ
    (
        rbd::boxedBlockPivoting::violation
        (
            (Vec(3) << 0, -2, 0).finished(), b, lo, hi,
            (Vec(3) << 0.5, 1, 0.3).finished()
        ),
        0
    );
    // Above its upper bound
    EXPECT_NEAR
    (
        rbd::boxedBlockPivoting::violation
        (
            Vec::Zero(3), b, lo, hi, (Vec(3) << 0.5, 1.5, 0).finished()
        ),
        0.5/1.5, 1e-15
    );
    // At the lower bound pushed below it (w < 0): a violation
    EXPECT_GT
    (
        rbd::boxedBlockPivoting::violation
        (
            (Vec(3) << 0, 0, -1).finished(), b, lo, hi,
            (Vec(3) << 0.5, 0, -1).finished()
        ),
        0.1
    );
}


// ************************************************************************* //
