// Unit tests for src/rbdPacking/contactResolution/lcp/lcpBodySpace: its
// products and solves against the dense n x n matrix A = J M^-1 J^T +
// diag(s), built here by hand from bodies and contacts (independently of
// lcpTestProblems.H), dense solves of (A_FF + eps I) x_F = r_F, and its
// block factorisation of K against a dense Cholesky

#include <gtest/gtest.h>
#include "lcpBodySpace.H"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wold-style-cast"
#include <Eigen/Dense>
#pragma GCC diagnostic pop

#include <random>
#include <vector>

using namespace Foam;

namespace
{
    using Mat = Eigen::MatrixXd;
    using Vec = Eigen::VectorXd;

    //- Bodies (mass, world inertia, centre) and contacts (bodies i, k (k <
    //  0: a wall), point p, unit direction u), with their dense J, M and
    //  the factors G (G G^T = J M^-1 J^T) as the solver is handed them
    struct problem
    {
        Mat J;      // n x 6 nb
        Mat M;      // 6 nb x 6 nb, block diagonal (m I, I_world)
        Vec s;      // compliance [1/kg]
        Mat A;      // J M^-1 J^T + diag(s)
        rbd::lcpFactors factors;
    };

    //- nb bodies, n contacts, a share of them against a wall; some rows
    //  without compliance (as sphere contacts); W^1/2 by Cholesky of each
    //  body's W block, or that times a reflection
    problem makeProblem
    (
        const label nb,
        const label n,
        const unsigned seed,
        const bool reflected
    )
    {
        std::mt19937 gen(seed);
        std::uniform_real_distribution<double> U(-1, 1);
        std::uniform_real_distribution<double> U01(0, 1);

        problem P;
        const label d = 6*nb;
        P.M = Mat::Zero(d, d);
        std::vector<Eigen::Vector3d> x(nb);
        for (label b = 0; b < nb; ++b)
        {
            // Masses 0.5-2 g, inertia: a random rotation of principal
            // moments 1e-8 to 1e-7 kg m^2 (a centimetre pellet)
            const double m = 5e-4 + 1.5e-3*U01(gen);
            const Eigen::Quaterniond q
            (
                Eigen::Vector4d(U(gen), U(gen), U(gen), U(gen)).normalized()
            );
            const Eigen::Matrix3d Rot(q.toRotationMatrix());
            Eigen::Vector3d I;
            for (label k = 0; k < 3; ++k) I(k) = 1e-8*(1 + 9*U01(gen));
            P.M.block(6*b, 6*b, 3, 3) = m*Eigen::Matrix3d::Identity();
            P.M.block(6*b + 3, 6*b + 3, 3, 3) =
                Rot*I.asDiagonal()*Rot.transpose();
            x[b] = Eigen::Vector3d(0.01*b, 0.003*U(gen), 0.003*U(gen));
        }

        P.J = Mat::Zero(n, d);
        P.s = Vec::Zero(n);
        for (label a = 0; a < n; ++a)
        {
            const label i = a % nb;
            // Every third contact against the wall, the others with the
            // next body
            const label k = (a % 3 == 0) ? -1 : (i + 1 + a/nb) % nb;
            const Eigen::Vector3d u
            (
                Eigen::Vector3d(U(gen), U(gen), U(gen)).normalized()
            );
            const Eigen::Vector3d p
            (
                x[i] + 0.005*Eigen::Vector3d(U(gen), U(gen), U(gen))
            );
            P.J.block(a, 6*i, 1, 3) = u.transpose();
            P.J.block(a, 6*i + 3, 1, 3) = (p - x[i]).cross(u).transpose();
            if (k >= 0 && k != i)
            {
                P.J.block(a, 6*k, 1, 3) = -u.transpose();
                P.J.block(a, 6*k + 3, 1, 3) =
                    -(p - x[k]).cross(u).transpose();
            }
            P.s(a) = (a % 4 == 0) ? 0 : 10*U01(gen);
        }

        const Mat W(P.M.inverse());
        P.A = P.J*W*P.J.transpose();
        P.A.diagonal() += P.s;

        // W^1/2 per block: L with L L^T = W_b (Cholesky, by hand: Eigen's
        // LLT and eigen solver warn falsely under GCC 12 -O3), or L H with
        // H a Householder reflection (orthogonal: (L H)(L H)^T = W_b too),
        // a factor that is not triangular
        Mat Wh(Mat::Zero(d, d));
        for (label b = 0; b < nb; ++b)
        {
            const Mat Wb(W.block(6*b, 6*b, 6, 6));
            Mat L(Mat::Zero(6, 6));
            for (label j = 0; j < 6; ++j)
            {
                double dj = Wb(j, j);
                for (label k = 0; k < j; ++k) dj -= L(j, k)*L(j, k);
                L(j, j) = std::sqrt(dj);
                for (label i = j + 1; i < 6; ++i)
                {
                    double v = Wb(i, j);
                    for (label k = 0; k < j; ++k) v -= L(i, k)*L(j, k);
                    L(i, j) = v/L(j, j);
                }
            }
            if (reflected)
            {
                Vec v(6);
                for (label i = 0; i < 6; ++i) v(i) = U(gen);
                const Mat H
                (
                    Mat::Identity(6, 6) - 2*v*v.transpose()/v.squaredNorm()
                );
                L = L*H;
            }
            Wh.block(6*b, 6*b, 6, 6) = L;
        }
        const Mat G(P.J*Wh);
        P.factors.G = G.sparseView();
        P.factors.s = P.s;
        return P;
    }

    double relErr(const Vec& a, const Vec& b)
    {
        return (a - b).norm()/max(b.norm(), 1e-300);
    }

    //- The reference solve: x_F = (A_FF + eps I)^-1 r_F, 0 elsewhere
    Vec denseSolve
    (
        const problem& P,
        const std::vector<label>& F,
        const double eps,
        const Vec& r
    )
    {
        const label m = F.size();
        Mat AF(m, m);
        Vec rF(m);
        for (label i = 0; i < m; ++i)
        {
            rF(i) = r(F[i]);
            for (label j = 0; j < m; ++j)
            {
                AF(i, j) = P.A(F[i], F[j]);
            }
            AF(i, i) += eps;
        }
        const Vec xF(AF.partialPivLu().solve(rF));
        Vec x(Vec::Zero(r.size()));
        for (label i = 0; i < m; ++i)
        {
            x(F[i]) = xF(i);
        }
        return x;
    }
}


TEST(lcpBodySpace, productIsTheDenseJMinvJtPlusCompliance)
{
    for (const bool reflected : {false, true})
    {
        const problem P(makeProblem(4, 40, 1, reflected));
        // The factors are those of A (the test's own construction)
        const Mat GGt(Mat(P.factors.G)*Mat(P.factors.G).transpose());
        ASSERT_LT((GGt + Mat(P.s.asDiagonal()) - P.A).norm(), 1e-12*P.A.norm());

        const rbd::lcpBodySpace B(P.factors);
        EXPECT_EQ(B.compliance(), P.s);
        std::mt19937 gen(2);
        std::normal_distribution<double> N(0, 1);
        for (label k = 0; k < 10; ++k)
        {
            Vec x(40);
            for (label i = 0; i < 40; ++i) x(i) = N(gen);
            EXPECT_LT(relErr(B.product(x), P.A*x), 1e-13) << k;
        }
        // Unit vectors: the columns of A
        for (label j = 0; j < 40; ++j)
        {
            EXPECT_LT(relErr(B.product(Vec::Unit(40, j)), P.A.col(j)), 1e-13)
                << "column " << j;
        }
    }
}


TEST(lcpBodySpace, applySolvesTheActiveRowsShiftedByEps)
{
    const label n = 48;
    const problem P(makeProblem(5, n, 3, false));
    const double maxDiag = P.A.diagonal().maxCoeff();
    rbd::lcpBodySpace B(P.factors);

    std::mt19937 gen(5);
    std::uniform_real_distribution<double> U01(0, 1);
    std::normal_distribution<double> N(0, 1);
    // Several active sets and shifts, factorised one after the other on
    // the same object (the values of K are refilled each time)
    for (const double rel : {1e-1, 1e-3, 1e-6})
    {
        for (const double share : {1.0, 0.6, 0.2})
        {
            const double eps = rel*maxDiag;
            std::vector<label> F;
            Vec Einv(Vec::Zero(n));
            for (label a = 0; a < n; ++a)
            {
                if (U01(gen) < share)
                {
                    F.push_back(a);
                    Einv(a) = 1/(P.s(a) + eps);
                }
            }
            ASSERT_TRUE(B.factorise(Einv));
            Vec r(n);
            for (label i = 0; i < n; ++i) r(i) = N(gen);
            const Vec ref(denseSolve(P, F, eps, r));

            // One apply: Woodbury loses digits as E^-1 grows (the header);
            // a few steps of refinement as the callers do
            Vec x(B.apply(r));
            for (label a = 0; a < n; ++a)
            {
                if (Einv(a) == 0)
                {
                    ASSERT_EQ(x(a), 0) << "inactive row " << a;
                }
            }
            // (A + E) on the active rows, E = 1/E^-1 = s + eps
            auto residual = [&](const Vec& y)
            {
                Vec res(Vec::Zero(n));
                for (const label a : F)
                {
                    double Ay = 0;
                    for (const label b : F) Ay += P.A(a, b)*y(b);
                    res(a) = r(a) - Ay - eps*y(a);
                }
                return res;
            };
            const double first = relErr(x, ref);
            for (label it = 0; it < 3; ++it)
            {
                x += B.apply(residual(x));
            }
            SCOPED_TRACE
            (
                "eps " + std::to_string(rel) + " max A_ii, active share "
              + std::to_string(share)
            );
            EXPECT_LT(first, rel > 1e-4 ? 1e-9 : 1e-4);
            EXPECT_LT(relErr(x, ref), 1e-10);
            EXPECT_LT(residual(x).norm(), 1e-10*r.norm()*maxDiag);
        }
    }
}


TEST(lcpBodySpace, blockFactorisationSolvesKAsTheDenseCholeskyDoes)
{
    // lcpBodySpace sums K = I + G^T E^-1 G into 6 x 6 blocks of bodies
    // and factorises it
    // block-sparse in its own (AMD) order, fill included; the reference
    // here is K built densely from G and factorised by a dense Cholesky:
    // y = K^-1 G^T E^-1 r and x = E^-1 (r - G y). Well conditioned (E^-1
    // of order 1/A_ii), the two agree to round-off; and the same factors
    // give the same answers to the bit (the packings are deterministic).
    // Rows one by one (each on other bodies than the row before) and in
    // runs of three on the same bodies (as the rows of a contact come)
    for (const unsigned seed : {7u, 8u, 9u})
    {
        const problem P(makeProblem(7, 60, seed, seed == 8));
        std::mt19937 gen(seed);
        std::uniform_real_distribution<double> U01(0, 1);
        std::normal_distribution<double> N(0, 1);
        for (const bool runs : {false, true})
        {
            // Runs: each row three times, its entries scaled at random
            // (the same bodies, other directions)
            Mat G(P.factors.G);
            Vec s(P.s);
            if (runs)
            {
                const Mat G1(G);
                G.resize(3*G1.rows(), G1.cols());
                s.resize(3*G1.rows());
                for (label a = 0; a < G1.rows(); ++a)
                {
                    for (label k = 0; k < 3; ++k)
                    {
                        for (label j = 0; j < G1.cols(); ++j)
                        {
                            G(3*a + k, j) = G1(a, j)*(0.5 + U01(gen));
                        }
                        s(3*a + k) = P.s(a);
                    }
                }
            }
            rbd::lcpFactors factors;
            factors.G = G.sparseView();
            factors.s = s;
            const label n = G.rows();
            const label d = G.cols();
            rbd::lcpBodySpace B(factors);
            rbd::lcpBodySpace again(factors);

            for (const double share : {1.0, 0.5, 0.1})
            {
                Vec Einv(Vec::Zero(n));
                for (label a = 0; a < n; ++a)
                {
                    if (U01(gen) < share)
                    {
                        Einv(a) = 1/(s(a) + 1e-3*G.row(a).squaredNorm());
                    }
                }
                const Mat K
                (
                    Mat::Identity(d, d) + G.transpose()*Einv.asDiagonal()*G
                );
                const Eigen::LLT<Mat> ref(K);
                ASSERT_EQ(ref.info(), Eigen::Success);

                ASSERT_TRUE(B.factorise(Einv));
                ASSERT_TRUE(again.factorise(Einv));
                for (label k = 0; k < 3; ++k)
                {
                    Vec r(n);
                    for (label i = 0; i < n; ++i) r(i) = N(gen);
                    const Vec Er(Einv.cwiseProduct(r));
                    const Vec y(ref.solve(Vec(G.transpose()*Er)));
                    const Vec expected(Er - Einv.cwiseProduct(Vec(G*y)));
                    const Vec x(B.apply(r));
                    SCOPED_TRACE
                    (
                        "seed " + std::to_string(seed) + (runs ? ", runs" : "")
                      + ", share " + std::to_string(share)
                    );
                    EXPECT_LT(relErr(x, expected), 1e-12);
                    const Vec x2(again.apply(r));
                    for (label a = 0; a < n; ++a)
                    {
                        ASSERT_EQ(x(a), x2(a)) << "row " << a;
                    }
                    const Vec Ar(G*(G.transpose()*r) + s.cwiseProduct(r));
                    EXPECT_LT(relErr(B.product(r), Ar), 1e-13);
                }
            }
        }
    }
}


TEST(lcpBodySpace, refusesFactorsNotInBlocksOfSixColumns)
{
    // The body-space solve works by bodies of 6 columns; factors of any
    // other width are not its to take
    const problem P(makeProblem(3, 30, 4, false));
    rbd::lcpFactors odd;
    odd.G = P.factors.G.leftCols(17);
    odd.s = P.s;
    EXPECT_FALSE(rbd::lcpBodySpace::pays(P.A.sparseView(), odd));
}


TEST(lcpBodySpace, noActiveRowGivesZeroAndNonFiniteIsRefused)
{
    const problem P(makeProblem(3, 30, 7, true));
    rbd::lcpBodySpace B(P.factors);
    ASSERT_TRUE(B.factorise(Vec::Zero(30)));
    const Vec r(Vec::Ones(30));
    EXPECT_EQ(B.apply(r), Vec::Zero(30));

    Vec bad(Vec::Ones(30));
    bad(4) = std::numeric_limits<double>::infinity();
    EXPECT_FALSE(B.factorise(bad));
    bad(4) = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(B.factorise(bad));
    // ... and a good one after them
    EXPECT_TRUE(B.factorise(Vec::Constant(30, 2.0)));
}


TEST(lcpBodySpace, paysOnlyWithFewerBodyColumnsThanRows)
{
    // 3 bodies: d = 18 columns
    const problem many(makeProblem(3, 30, 9, false));
    const Eigen::SparseMatrix<double> A30(many.A.sparseView());
    EXPECT_TRUE(rbd::lcpBodySpace::pays(A30, many.factors));

    // 18 rows, 18 columns: not smaller
    const problem square(makeProblem(3, 18, 9, false));
    EXPECT_FALSE
    (
        rbd::lcpBodySpace::pays(square.A.sparseView(), square.factors)
    );
    // 12 rows < 18 columns
    const problem few(makeProblem(3, 12, 9, false));
    EXPECT_FALSE(rbd::lcpBodySpace::pays(few.A.sparseView(), few.factors));

    // No factors, or factors of another A
    EXPECT_FALSE(rbd::lcpBodySpace::pays(A30, rbd::lcpFactors()));
    EXPECT_FALSE(rbd::lcpBodySpace::pays(A30, square.factors));
}
