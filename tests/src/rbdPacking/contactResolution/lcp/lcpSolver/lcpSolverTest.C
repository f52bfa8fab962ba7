// Unit tests for src/rbdPacking/contactResolution/lcp/lcpSolver: run-time
// selection, settings echo, the violation measure, and every solver on
// physical resting-contact scenes with closed-form answers

#include <gtest/gtest.h>
#include "rbdPacking/contactResolution/lcp/lcpTestProblems.H"
#include "lcpSolver.H"
#include "OStringStream.H"

using namespace Foam;
using namespace lcpTest;

// * * * * * * * * * * * * * * * * Selection * * * * * * * * * * * * * * * //

TEST(lcpSolver, selectsBlockPivotingByDefault)
{
    const autoPtr<rbd::lcpSolver> solver = rbd::lcpSolver::New(parse(""));
    EXPECT_EQ(solver->type(), "blockPivoting");
}


TEST(lcpSolver, echoedSettingsReadBackTheSame)
{
    const dictionary dict = parse
    (
        "lcpSolver projectedGaussSeidel;"
        "projectedGaussSeidelCoeffs { maxIterations 7; relaxation 1.3; }"
    );
    const autoPtr<rbd::lcpSolver> solver = rbd::lcpSolver::New(dict);
    EXPECT_EQ(solver->type(), "projectedGaussSeidel");

    OStringStream os;
    solver->write(os);
    const dictionary echoed = parse(os.str());
    EXPECT_EQ(echoed.get<word>("lcpSolver"), "projectedGaussSeidel");
    const dictionary& coeffs = echoed.subDict("projectedGaussSeidelCoeffs");
    EXPECT_EQ(coeffs.get<label>("maxIterations"), 7);
    EXPECT_DOUBLE_EQ(coeffs.get<scalar>("relaxation"), 1.3);
    EXPECT_DOUBLE_EQ(coeffs.get<scalar>("tolerance"), 1e-6);   // default
    EXPECT_FALSE(coeffs.get<bool>("warmStart"));                // default

    // The echo selects an identical solver
    OStringStream os2;
    rbd::lcpSolver::New(echoed)->write(os2);
    EXPECT_EQ(os.str(), os2.str());

    // ... which stops at the 7 sweeps it was given
    const scene s = spherePyramid();
    Vec f;
    const rbd::lcpResult r = solver->solve(s.p.A, s.p.b, f);
    EXPECT_EQ(r.iterations, 7);
    EXPECT_FALSE(r.converged);
}


TEST(lcpSolverDeath, unknownNameListsValidNames)
{
    EXPECT_EXIT
    (
        rbd::lcpSolver::New(parse("lcpSolver dantzig;")),
        ::testing::ExitedWithCode(1),
        "Unknown lcpSolver type dantzig(.|\n)*Valid lcpSolver types"
        "(.|\n)*baraff(.|\n)*enumeration(.|\n)*projectedGaussSeidel"
    );
}


TEST(lcpSolverDeath, rejectsBadCoefficient)
{
    EXPECT_EXIT
    (
        rbd::lcpSolver::New
        (
            parse("lcpSolver baraff; baraffCoeffs { tolerance -1; }")
        ),
        ::testing::ExitedWithCode(1),
        "Bad entry 'tolerance -1;'(.|\n)*allowed: a number in \\(0, 0.01\\]"
    );
    EXPECT_EXIT
    (
        rbd::lcpSolver::New
        (
            parse
            (
                "lcpSolver projectedGaussSeidel;"
                "projectedGaussSeidelCoeffs { relaxation 2; }"
            )
        ),
        ::testing::ExitedWithCode(1),
        "Bad entry 'relaxation 2;'(.|\n)*allowed: a number in \\(0, 2\\)"
    );
}


TEST(lcpSolverDeath, rejectsMisspeltCoefficient)
{
    EXPECT_EXIT
    (
        rbd::lcpSolver::New
        (
            parse("lcpSolver baraff; baraffCoeffs { tolerence 1e-8; }")
        ),
        ::testing::ExitedWithCode(1),
        "Unknown entry 'tolerence'"
    );
}


TEST(lcpSolverDeath, rejectsInconsistentSizes)
{
    const autoPtr<rbd::lcpSolver> solver = rbd::lcpSolver::New(parse(""));
    Vec f;
    EXPECT_EXIT
    (
        solver->solve(Mat::Identity(3, 3), Vec::Ones(2), f),
        ::testing::ExitedWithCode(1),
        "LCP of inconsistent size: A is 3 x 3, b has 2 entries"
    );
}


// * * * * * * * * * * * * * * * * Violation * * * * * * * * * * * * * * * //

TEST(lcpSolver, violationMeasuresSignsAndComplementarity)
{
    // A = [2], b = [-2]: f = 1 solves it
    const Mat A = Mat::Constant(1, 1, 2);
    const Vec b = Vec::Constant(1, -2);
    EXPECT_DOUBLE_EQ(rbd::lcpSolver::violation(A, b, Vec::Constant(1, 1)), 0);

    // f = 0.5: w = -1, wRef = |b| = 2; -w/wRef = 1/2 and
    // |f w|/(fRef wRef) = 0.5/1 = 1/2
    EXPECT_DOUBLE_EQ
    (
        rbd::lcpSolver::violation(A, b, Vec::Constant(1, 0.5)), 0.5
    );

    // f = 3: w = 4 > 0 with f > 0: |f w|/(fRef wRef) = 12/6 = 2
    EXPECT_DOUBLE_EQ
    (
        rbd::lcpSolver::violation(A, b, Vec::Constant(1, 3)), 2
    );

    // f = -1: -f/fRef = 1, w = -4: -w/wRef = 2, |f w|/(1*2) = 2
    EXPECT_DOUBLE_EQ
    (
        rbd::lcpSolver::violation(A, b, Vec::Constant(1, -1)), 2
    );

    // b = 0: wRef = max|A| fRef; f = 1 gives w = 2 > 0, |f w|/(1*2) = 1
    EXPECT_DOUBLE_EQ
    (
        rbd::lcpSolver::violation(A, Vec::Zero(1), Vec::Constant(1, 1)), 1
    );

    // Invariant to the units of f and w
    EXPECT_DOUBLE_EQ
    (
        rbd::lcpSolver::violation(1e3*A, 1e-2*b, Vec::Constant(1, 0.5e-5)),
        0.5
    );
}


// * * * * * * * * * * * * * Physical scenes  * * * * * * * * * * * * * * //

namespace
{
    //- A solver and the accuracy expected from it
    struct solverCase
    {
        const char* name;
        const char* dict;

        //- Accuracy of forces and accelerations, relative to m g and g
        double accuracy;
    };

    void PrintTo(const solverCase& c, std::ostream* os)
    {
        *os << c.name;
    }

    const solverCase baraffCase
    {
        "baraff", "lcpSolver baraff;", 1e-10
    };
    const solverCase pgsCase
    {
        "projectedGaussSeidel",
        "lcpSolver projectedGaussSeidel;"
        "projectedGaussSeidelCoeffs"
        "{ tolerance 1e-11; maxIterations 100000; relaxation 1.2; }",
        1e-7
    };
    const solverCase enumerationCase
    {
        "enumeration", "lcpSolver enumeration;", 1e-10
    };
    const solverCase blockPivotingCase
    {
        "blockPivoting",
        "lcpSolver blockPivoting; blockPivotingCoeffs { fallbackSize 0; }",
        1e-8
    };

    class lcpScenes
    :
        public ::testing::TestWithParam<solverCase>
    {
    protected:

        autoPtr<rbd::lcpSolver> solver_ =
            rbd::lcpSolver::New(parse(GetParam().dict));

        const double tol_ = GetParam().accuracy;

        //- Solve, expect convergence, f >= 0 and every body at rest
        Vec solveAtRest(const scene& s)
        {
            Vec f;
            const rbd::lcpResult r = solver_->solve(s.p.A, s.p.b, f);
            EXPECT_TRUE(r.converged) << r.maxViolation;
            EXPECT_GE(f.minCoeff(), 0);
            EXPECT_LE
            (
                s.accelerations(f).cwiseAbs().maxCoeff(), tol_*gravity
            );
            EXPECT_GE(w(s.p, f).minCoeff(), -tol_*gravity);
            return f;
        }
    };
}


TEST_P(lcpScenes, sphereOnFloorCarriesItsWeight)
{
    const Vec f = solveAtRest(sphereOnFloor());
    EXPECT_NEAR(f(0), 2*gravity, tol_*2*gravity);
}


TEST_P(lcpScenes, duplicatedContactSharesTheWeight)
{
    // f is not unique (f0 + f1 = m g), the motion is
    const Vec f = solveAtRest(sphereOnFloor(2));
    EXPECT_NEAR(f.sum(), 2*gravity, tol_*2*gravity);
}


TEST_P(lcpScenes, sphereInPocketOfFourContacts)
{
    const scene s = sphereInPocket();
    const Vec f = solveAtRest(s);
    // Net contact force balances the weight
    const Vec3 F = s.J.leftCols<3>().transpose()*f;
    EXPECT_LE((F - Vec3(0, 0, gravity)).norm(), tol_*gravity);
}


TEST_P(lcpScenes, sphereInGrooveClosedForm)
{
    const Vec f = solveAtRest(sphereInGroove());
    const double expected = gravity/(2*std::cos(30*M_PI/180));
    EXPECT_NEAR(f(0), expected, tol_*gravity);
    EXPECT_NEAR(f(1), expected, tol_*gravity);
}


TEST_P(lcpScenes, cubeOnFourCornersBalancesForceAndTorque)
{
    const scene s = cubeOnFloor();
    const Vec f = solveAtRest(s);
    EXPECT_NEAR(f.sum(), 3*gravity, tol_*3*gravity);
    // Torque about the centre: sum f_i (p_i - x) x z = 0
    const Vec3 T = s.J.rightCols<3>().transpose()*f;
    EXPECT_LE(T.norm(), tol_*3*gravity);
}


TEST_P(lcpScenes, discOnTwelveRimContacts)
{
    const Vec f = solveAtRest(discOnFloor());
    EXPECT_NEAR(f.sum(), gravity, tol_*gravity);
}


TEST_P(lcpScenes, twoSphereStackClosedForm)
{
    const Vec f = solveAtRest(twoSphereStack());
    EXPECT_NEAR(f(0), 2*gravity, tol_*gravity);
    EXPECT_NEAR(f(1), gravity, tol_*gravity);
}


TEST_P(lcpScenes, liftingSphereGetsNoForce)
{
    // Pulled up by 2 g: the floor contact separates, w = b = g
    scene s = sphereOnFloor();
    s.p.b = -s.p.b;
    Vec f;
    const rbd::lcpResult r = solver_->solve(s.p.A, s.p.b, f);
    EXPECT_TRUE(r.converged);
    EXPECT_EQ(f(0), 0);
}


TEST_P(lcpScenes, infeasibleIsReportedNotConverged)
{
    // A sphere in a vice whose velocity terms press it into both jaws:
    // w_0 + w_1 = b_0 + b_1 < 0 for every f
    const std::vector<body> bodies{sphere(1, 0.5, Vec3(0, 0, 0.5))};
    const scene s = makeScene
    (
        bodies,
        {
            contactRow(bodies, 0, -1, Vec3(-0.5, 0, 0.5), Vec3(1, 0, 0)),
            contactRow(bodies, 0, -1, Vec3(0.5, 0, 0.5), Vec3(-1, 0, 0))
        }
    );
    const Vec b(Eigen::Vector2d(-1, -2));

    Vec f;
    const rbd::lcpResult r = solver_->solve(s.p.A, b, f);
    EXPECT_FALSE(r.converged);
    ASSERT_TRUE(f.allFinite());
    EXPECT_GE(f.minCoeff(), 0);
    EXPECT_GT(r.maxViolation, 1e-3);
}


INSTANTIATE_TEST_SUITE_P
(
    allSolvers,
    lcpScenes,
    ::testing::Values
    (
        baraffCase, pgsCase, enumerationCase, blockPivotingCase
    ),
    [](const ::testing::TestParamInfo<solverCase>& info)
    {
        return std::string(info.param.name);
    }
);


// Scenes beyond the reach of enumeration (n > 16)

class lcpLargeScenes
:
    public lcpScenes
{};


TEST_P(lcpLargeScenes, spherePyramidInABox)
{
    // 30 spheres, 128 contacts; the floor carries the whole weight
    const scene s = spherePyramid();
    const Vec f = solveAtRest(s);
    EXPECT_NEAR(f.head(16).sum(), 30*gravity, tol_*30*gravity);
}


INSTANTIATE_TEST_SUITE_P
(
    iterativeAndPivoting,
    lcpLargeScenes,
    ::testing::Values(baraffCase, pgsCase, blockPivotingCase),
    [](const ::testing::TestParamInfo<solverCase>& info)
    {
        return std::string(info.param.name);
    }
);


// ************************************************************************* //
