// The island matrix of src/rbdPacking/contactResolution/resting/lcpAssembly
// (eq 31): A = J M^-1 J^T against a dense product, the compliance on the
// diagonal of material contact points, the body-space factors, and A as its
// diagonal alone where a body-space solver needs no more

#include <gtest/gtest.h>
#include "lcpAssembly.H"
#include "boxedBlockPivoting.H"
#include "mathematicalConstants.H"
#include <Eigen/Dense>
#include <limits>
#include <random>

using namespace Foam;
using namespace Foam::rbd;

namespace
{
    const scalar r = 0.005;

    //- A body with an anisotropic inertia, turned, so that I^-1 is full
    rigidBody bodyAt(const point& x, const quaternion& q)
    {
        const scalar m = 2e-3;
        const vector I(0.3*m*r*r, 0.4*m*r*r, 0.5*m*r*r);
        return rigidBody(m, I, x, q, true);
    }

    contact makeContact
    (
        const label i,
        const label k,
        const vector& n,
        const point& p,
        const bool centreBased
    )
    {
        contact c;
        c.i = i;
        c.k = k;
        c.n = n/mag(n);
        c.p = p;
        c.centreBased = centreBased;
        return c;
    }

    //- Dense J M^-1 J^T of the rows dirs over the moving bodies
    Eigen::MatrixXd denseA
    (
        const UList<rigidBody>& bodies,
        const UList<contact>& contacts,
        const boolList& fixed,
        const std::vector<lcpAssembly::constraint>& dirs
    )
    {
        const label nb = bodies.size();
        const label n = dirs.size();
        Eigen::MatrixXd J(Eigen::MatrixXd::Zero(n, 6*nb));
        Eigen::MatrixXd Minv(Eigen::MatrixXd::Zero(6*nb, 6*nb));
        for (label b = 0; b < nb; ++b)
        {
            for (label d = 0; d < 3; ++d)
            {
                Minv(6*b + d, 6*b + d) = bodies[b].invMass();
                for (label e = 0; e < 3; ++e)
                {
                    Minv(6*b + 3 + d, 6*b + 3 + e) =
                        bodies[b].invInertia()(d, e);
                }
            }
        }
        for (label a = 0; a < n; ++a)
        {
            const contact& c = contacts[dirs[a].first];
            const vector& u = dirs[a].second;
            const vector angI((c.p - bodies[c.i].x()) ^ u);
            for (label d = 0; d < 3; ++d)
            {
                J(a, 6*c.i + d) = u[d];
                J(a, 6*c.i + 3 + d) = angI[d];
            }
            if (c.k >= 0 && !fixed[c.k])
            {
                const vector angK((c.p - bodies[c.k].x()) ^ u);
                for (label d = 0; d < 3; ++d)
                {
                    J(a, 6*c.k + d) = -u[d];
                    J(a, 6*c.k + 3 + d) = -angK[d];
                }
            }
        }
        return J*Minv*J.transpose();
    }
}


TEST(lcpAssembly, matrixIsJMinvJtWithTheCompliance)
{
    // Three bodies: 0 and 1 touch each other and the floor, 2 rests on a
    // sleeper (fixed body 3) and touches 1; normals and tangents as rows
    List<rigidBody> bodies(4);
    bodies[0] = bodyAt(point(0, 0, r), quaternion(vector(1, 2, 3), 0.7));
    bodies[1] = bodyAt(point(2*r, 0, r), quaternion(vector(0, 1, 1), 1.1));
    bodies[2] = bodyAt(point(3*r, 0, 2.6*r), quaternion(1));
    bodies[3] = bodyAt(point(3*r, 0, 0.8*r), quaternion(1));
    boolList fixed(4, false);
    fixed[3] = true;

    List<contact> contacts
    ({
        makeContact(0, tubeBottom, vector(0, 0, 1), point(0, 0, 0), true),
        makeContact(1, tubeBottom, vector(0, 0, 1), point(2*r, 0, 0), false),
        makeContact(1, 0, vector(1, 0.1, 0), point(r, 0, r), false),
        makeContact(2, 1, vector(0.3, 0, 1), point(2.5*r, 0, 2*r), true),
        makeContact(2, 3, vector(0, 0.2, 1), point(3*r, 0, 1.7*r), false)
    });
    std::vector<lcpAssembly::constraint> dirs;
    forAll(contacts, ci)
    {
        dirs.emplace_back(ci, contacts[ci].n);
        const vector t(contacts[ci].n ^ vector(0, 1, 0));
        dirs.emplace_back(ci, t/mag(t));
    }

    const scalar compliance = 0.05;
    lcpAssembly assembly(compliance);
    Eigen::SparseMatrix<double> A;
    Eigen::VectorXd shift;
    lcpFactors factors;
    assembly.assemble(bodies, contacts, fixed, dirs, A, shift, factors);

    const Eigen::MatrixXd D(denseA(bodies, contacts, fixed, dirs));
    const label n = dirs.size();
    ASSERT_EQ(A.rows(), n);
    ASSERT_EQ(A.cols(), n);
    const scalar scale = D.cwiseAbs().maxCoeff();
    for (label a = 0; a < n; ++a)
    {
        const bool material = !contacts[dirs[a].first].centreBased;
        EXPECT_NEAR(shift(a), material ? compliance*D(a, a) : 0, 1e-12*scale);
        for (label b = 0; b < n; ++b)
        {
            const scalar expected = D(a, b) + (a == b ? shift(a) : 0);
            EXPECT_NEAR(A.coeff(a, b), expected, 1e-12*scale)
                << "row " << a << " column " << b;
        }
    }

    // 10 rows on 3 bodies (18 columns): no factors
    EXPECT_FALSE(factors.valid());

    // The buffers are left as between calls: a second call gives the same
    Eigen::SparseMatrix<double> A2;
    assembly.assemble(bodies, contacts, fixed, dirs, A2, shift, factors);
    EXPECT_EQ((A2 - A).norm(), 0);
}


TEST(lcpAssembly, factorsOfAHeapReproduceA)
{
    // One turned body on eight floor points (material contacts), normal
    // and two tangents each: 24 rows on 6 columns, so the factors are
    // given, and G G^T + diag(shift) is A
    List<rigidBody> bodies(1);
    bodies[0] = bodyAt(point(0, 0, r), quaternion(vector(1, -1, 2), 0.4));
    const boolList fixed(1, false);
    List<contact> contacts;
    std::vector<lcpAssembly::constraint> dirs;
    for (label k = 0; k < 8; ++k)
    {
        const scalar phi = 2*constant::mathematical::pi*k/8;
        contacts.append
        (
            makeContact
            (
                0, tubeBottom, vector(0, 0, 1),
                point(r*std::cos(phi), r*std::sin(phi), 0), false
            )
        );
        dirs.emplace_back(k, vector(0, 0, 1));
        dirs.emplace_back(k, vector(1, 0, 0));
        dirs.emplace_back(k, vector(0, 1, 0));
    }

    lcpAssembly assembly(0.01);
    Eigen::SparseMatrix<double> A;
    Eigen::VectorXd shift;
    lcpFactors factors;
    assembly.assemble(bodies, contacts, fixed, dirs, A, shift, factors);

    ASSERT_TRUE(factors.valid());
    EXPECT_EQ(factors.G.rows(), 24);
    EXPECT_EQ(factors.G.cols(), 6);
    const Eigen::MatrixXd G(factors.G);
    Eigen::MatrixXd GGt(G*G.transpose());
    GGt.diagonal() += factors.s;
    const Eigen::MatrixXd Ad(A);
    EXPECT_LE((GGt - Ad).cwiseAbs().maxCoeff(), 1e-12*Ad.cwiseAbs().maxCoeff());
}


TEST(lcpAssembly, diagonalInBodySpaceIsTheSameDiagonalAndSolve)
{
    // Two turned bodies on the floor and on each other, eight material
    // points per contact patch, a normal and two tangents each: 72 rows
    // on 12 columns. entries::diagonalInBodySpace gives A's diagonal, the
    // shift and the factors bit for bit as entries::all, nothing else of
    // A, and the boxed solve in body space the same answer bit for bit
    List<rigidBody> bodies(2);
    bodies[0] = bodyAt(point(0, 0, r), quaternion(vector(1, -1, 2), 0.4));
    bodies[1] = bodyAt(point(0, 0, 3*r), quaternion(vector(2, 1, 0), 0.3));
    const boolList fixed(2, false);
    List<contact> contacts;
    std::vector<lcpAssembly::constraint> dirs;
    for (label k = 0; k < 8; ++k)
    {
        const scalar phi = 2*constant::mathematical::pi*k/8;
        const scalar x = r*std::cos(phi), y = r*std::sin(phi);
        contacts.append
        (
            makeContact(0, tubeBottom, vector(0, 0, 1), point(x, y, 0), false)
        );
        contacts.append
        (
            makeContact(1, 0, vector(0.05, 0, 1), point(x, y, 2*r), false)
        );
    }
    forAll(contacts, ci)
    {
        const vector& n = contacts[ci].n;
        vector t(n ^ vector(0, 1, 0));
        t /= mag(t);
        dirs.emplace_back(ci, n);
        dirs.emplace_back(ci, t);
        dirs.emplace_back(ci, n ^ t);
    }
    const label n = dirs.size();

    lcpAssembly assembly(0.01);
    Eigen::SparseMatrix<double> A, Ad;
    Eigen::VectorXd shift, shiftD;
    lcpFactors factors, factorsD;
    assembly.assemble(bodies, contacts, fixed, dirs, A, shift, factors);
    assembly.assemble
    (
        bodies, contacts, fixed, dirs, Ad, shiftD, factorsD,
        lcpAssembly::entries::diagonalInBodySpace
    );

    ASSERT_TRUE(factorsD.valid());
    ASSERT_EQ(Ad.rows(), n);
    ASSERT_EQ(Ad.cols(), n);
    EXPECT_EQ(Ad.nonZeros(), n);
    EXPECT_GT(A.nonZeros(), 4*n);
    for (label a = 0; a < n; ++a)
    {
        EXPECT_EQ(Ad.coeff(a, a), A.coeff(a, a)) << "row " << a;
        EXPECT_EQ(shiftD(a), shift(a)) << "row " << a;
    }
    EXPECT_EQ((Eigen::MatrixXd(factorsD.G) - Eigen::MatrixXd(factors.G))
        .cwiseAbs().maxCoeff(), 0);
    EXPECT_EQ((factorsD.s - factors.s).cwiseAbs().maxCoeff(), 0);

    // The boxed problem of a coupled friction solve: normal rows >= 0
    // pushed by gravity, tangent rows in a box, a tangential push
    Eigen::VectorXd b(n), lo(n), hi(n);
    const scalar inf = std::numeric_limits<scalar>::infinity();
    for (label a = 0; a < n; ++a)
    {
        const bool normal = (a % 3 == 0);
        b(a) = normal ? -9.81 : (a % 3 == 1 ? 0.7 : -0.2);
        lo(a) = normal ? 0 : -0.02;
        hi(a) = normal ? inf : 0.02;
    }
    const boxedBlockPivoting boxed;
    std::vector<boxedBlockPivoting::side> sides(n), sidesD(n);
    Eigen::VectorXd x(Eigen::VectorXd::Zero(n)), xD(x);
    const lcpResult r = boxed.solve(A, factors, b, lo, hi, sides, x);
    const lcpResult rD = boxed.solve(Ad, factorsD, b, lo, hi, sidesD, xD);
    EXPECT_TRUE(r.converged);
    EXPECT_EQ(rD.iterations, r.iterations);
    EXPECT_EQ(rD.maxViolation, r.maxViolation);
    EXPECT_EQ((xD - x).cwiseAbs().maxCoeff(), 0);
    EXPECT_TRUE(sidesD == sides);

    // Fewer rows than columns: no factors, and A whole whatever is asked
    std::vector<lcpAssembly::constraint> few(dirs.begin(), dirs.begin() + 6);
    Eigen::SparseMatrix<double> Af, Afd;
    assembly.assemble(bodies, contacts, fixed, few, Af, shift, factors);
    assembly.assemble
    (
        bodies, contacts, fixed, few, Afd, shiftD, factorsD,
        lcpAssembly::entries::diagonalInBodySpace
    );
    EXPECT_FALSE(factorsD.valid());
    EXPECT_EQ(Afd.nonZeros(), Af.nonZeros());
    EXPECT_EQ((Afd - Af).norm(), 0);
}
