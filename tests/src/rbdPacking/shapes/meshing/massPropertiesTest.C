// Unit tests for src/rbdPacking/shapes/meshing/massProperties

#include <gtest/gtest.h>
#include "massProperties.H"
#include "pelletMeshes.H"
#include "quaternion.H"
#include "rbdPacking/shapes/meshing/testMeshes.H"

using namespace Foam;

namespace
{
    //- Largest off-diagonal magnitude of a symmetric tensor
    scalar offDiagonal(const symmTensor& I)
    {
        return max(mag(I.xy()), max(mag(I.xz()), mag(I.yz())));
    }

    //- Inertia of a mesh in its principal frame, recomputed from scratch
    symmTensor principalInertia(const rbd::triMesh& m, const scalar rho)
    {
        const rbd::massProperties mp(m, rho);
        return rbd::massProperties(mp.toPrincipalFrame(m), rho).inertia();
    }
}


TEST(massProperties, unitCubeClosedForm)
{
    const scalar rho = 2;
    const rbd::massProperties mp(rbdTest::box(), rho);
    EXPECT_NEAR(mp.volume(), 1, 1e-15);
    EXPECT_NEAR(mp.mass(), 2, 1e-15);
    EXPECT_NEAR(mag(mp.centreOfMass() - point(0.5, 0.5, 0.5)), 0, 1e-15);
    // I = m a^2/6 about the centre, no products
    const symmTensor I = mp.inertia();
    EXPECT_NEAR(I.xx(), 2.0/6, 1e-15);
    EXPECT_NEAR(I.yy(), 2.0/6, 1e-15);
    EXPECT_NEAR(I.zz(), 2.0/6, 1e-15);
    EXPECT_NEAR(offDiagonal(I), 0, 1e-15);
}

TEST(massProperties, boxClosedForm)
{
    const scalar a = 1, b = 2, c = 3, rho = 5;
    const rbd::massProperties mp(rbdTest::box(a, b, c), rho);
    const scalar m = rho*a*b*c;
    EXPECT_NEAR(mp.mass(), m, 1e-13);
    EXPECT_NEAR(mp.inertia().xx(), m*(b*b + c*c)/12, 1e-12);
    EXPECT_NEAR(mp.inertia().yy(), m*(a*a + c*c)/12, 1e-12);
    EXPECT_NEAR(mp.inertia().zz(), m*(a*a + b*b)/12, 1e-12);
    EXPECT_NEAR(offDiagonal(mp.inertia()), 0, 1e-13);
}

TEST(massProperties, unitTetrahedronClosedForm)
{
    // V = 1/6, c = (1/4, 1/4, 1/4); about c: int (y^2 + z^2) = 1/80,
    // -int xy = +1/480 (from int x^2 = 1/60, int xy = 1/120 at the origin)
    const rbd::massProperties mp(rbdTest::tetrahedron(), 1);
    EXPECT_NEAR(mp.volume(), 1.0/6, 1e-16);
    EXPECT_NEAR(mag(mp.centreOfMass() - point(0.25, 0.25, 0.25)), 0, 1e-16);
    const symmTensor& I = mp.inertia();
    for (const scalar d : {I.xx(), I.yy(), I.zz()})
    {
        EXPECT_NEAR(d, 1.0/80, 1e-16);
    }
    for (const scalar o : {I.xy(), I.xz(), I.yz()})
    {
        EXPECT_NEAR(o, 1.0/480, 1e-16);
    }
}

TEST(massProperties, farFromOriginKeepsPrecision)
{
    const rbd::triMesh m = rbdTest::tetrahedron().transformed
    (
        tensor::I,
        vector(1e3, -2e3, 5e2)
    );
    const rbd::massProperties mp(m, 1);
    EXPECT_NEAR(mp.volume(), 1.0/6, 1e-13);
    EXPECT_NEAR
    (
        mag(mp.centreOfMass() - point(1e3 + 0.25, -2e3 + 0.25, 5e2 + 0.25)),
        0,
        1e-12
    );
    EXPECT_NEAR(mp.inertia().xx(), 1.0/80, 1e-12);
    EXPECT_NEAR(mp.inertia().xy(), 1.0/480, 1e-12);
}

TEST(massProperties, principalFrameOfRotatedBox)
{
    const scalar a = 1, b = 2, c = 3, rho = 3;
    const tensor R = quaternion(vector(1, 2, -1)/std::sqrt(6.0), 1.1).R();
    const rbd::triMesh m =
        rbdTest::box(a, b, c).transformed(R, vector(4, 5, 6));

    const rbd::massProperties mp(m, rho);
    const tensor& Q = mp.principalRotation();
    EXPECT_NEAR(det(Q), 1, 1e-14);
    EXPECT_NEAR(mag((Q.T() & Q) - tensor::I), 0, 1e-14);

    // The moments are those of the box, in some order
    const scalar mass = rho*a*b*c;
    List<scalar> expected({mass*(b*b + c*c)/12, mass*(a*a + c*c)/12,
        mass*(a*a + b*b)/12});
    List<scalar> got
    ({
        mp.principalMoments().x(),
        mp.principalMoments().y(),
        mp.principalMoments().z()
    });
    Foam::sort(expected);
    Foam::sort(got);
    for (label i = 0; i < 3; ++i)
    {
        EXPECT_NEAR(got[i], expected[i], 1e-12);
    }

    // Re-expressed: centre of mass at the origin, inertia diagonal and
    // equal to the principal moments, still outward (det Q = +1)
    const rbd::triMesh body = mp.toPrincipalFrame(m);
    const rbd::massProperties bp(body, rho);
    EXPECT_NEAR(mag(bp.centreOfMass()), 0, 1e-13);
    EXPECT_NEAR(offDiagonal(bp.inertia()), 0, 1e-12);
    EXPECT_NEAR(bp.inertia().xx(), mp.principalMoments().x(), 1e-12);
    EXPECT_NEAR(bp.inertia().yy(), mp.principalMoments().y(), 1e-12);
    EXPECT_NEAR(bp.inertia().zz(), mp.principalMoments().z(), 1e-12);
    EXPECT_NEAR(bp.volume(), a*b*c, 1e-12);

    // The box edges now lie along the axes: its bounding box is a x b x c
    // in some order
    const vector span = body.bounds().span();
    List<scalar> spans({span.x(), span.y(), span.z()});
    Foam::sort(spans);
    EXPECT_NEAR(spans[0], a, 1e-12);
    EXPECT_NEAR(spans[1], b, 1e-12);
    EXPECT_NEAR(spans[2], c, 1e-12);
}

TEST(massProperties, principalFrameOfIrregularMesh)
{
    // No symmetry: the tetrahedron, stretched and turned
    const tensor S(1, 0.3, 0, 0, 2, 0.1, 0.2, 0, 3);
    pointField p(rbdTest::tetrahedron().points());
    for (point& x : p)
    {
        x = S & x;
    }
    const rbd::triMesh m(p, rbdTest::tetrahedron().faces());
    const symmTensor I = principalInertia(m, 7);
    EXPECT_LT(offDiagonal(I), 1e-14*max(I.xx(), max(I.yy(), I.zz())));
}

TEST(massProperties, principalMeshIsNotTurned)
{
    // Axis-aligned box about its centre: Q = I
    const rbd::triMesh box =
        rbdTest::box(1, 2, 3).transformed(tensor::I, vector(-0.5, -1, -1.5));
    const rbd::massProperties bp(box, 1);
    EXPECT_NEAR(mag(bp.principalRotation() - tensor::I), 0, 1e-14);

    // Cube: all moments equal, Q = I
    const rbd::massProperties cp(rbdTest::box(), 1);
    EXPECT_NEAR(mag(cp.principalRotation() - tensor::I), 0, 1e-14);

    // Cylinder (Ixx = Iyy): not turned about its axis
    const rbd::triMesh cyl = rbd::pelletMeshes::cylinder(0.01, 0.01, 500);
    const rbd::massProperties yp(cyl, 1);
    EXPECT_NEAR(mag(yp.principalRotation() - tensor::I), 0, 1e-12);
}

TEST(massProperties, rotatedCylinderAxisFound)
{
    // Two equal moments: the distinct (axial) axis is found, the frame is
    // right-handed and the inertia diagonal
    const vector turn(0.3, -1, 0.5);
    const tensor R = quaternion(turn/mag(turn), 0.8).R();
    const rbd::triMesh cyl = rbd::pelletMeshes::cylinder(0.01, 0.02, 500)
        .transformed(R, vector::one);
    const rbd::massProperties mp(cyl, 1000);
    const tensor& Q = mp.principalRotation();
    EXPECT_NEAR(det(Q), 1, 1e-14);

    // The cylinder axis R z is one of the principal axes (a column of Q)
    const vector axis = R & vector(0, 0, 1);
    const scalar best = max
    (
        mag(axis & Q.cx()),
        max(mag(axis & Q.cy()), mag(axis & Q.cz()))
    );
    EXPECT_NEAR(best, 1, 1e-12);

    const symmTensor I = principalInertia(cyl, 1000);
    EXPECT_LT(offDiagonal(I), 1e-12*max(I.xx(), max(I.yy(), I.zz())));
}

TEST(massPropertiesDeath, rejectsInwardMesh)
{
    rbd::triMesh m = rbdTest::box();
    m.flip();
    EXPECT_EXIT
    (
        rbd::massProperties(m, 1),
        ::testing::ExitedWithCode(1),
        "not a closed outward mesh"
    );
}
