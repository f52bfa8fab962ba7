// Unit tests for src/rbdPacking/shapes/meshing/triMesh

#include <gtest/gtest.h>
#include "triMesh.H"
#include "quaternion.H"
#include "rbdPacking/shapes/meshing/testMeshes.H"

using namespace Foam;

TEST(triMesh, unitCubeVolumeAreaRadiusEdges)
{
    const rbd::triMesh m = rbdTest::box();
    EXPECT_EQ(m.nPoints(), 8);
    EXPECT_EQ(m.nFaces(), 12);
    EXPECT_NEAR(m.volume(), 1, 1e-15);
    EXPECT_NEAR(m.area(), 6, 1e-15);
    EXPECT_NEAR(m.boundingRadius(), std::sqrt(3.0), 1e-15);
    // 12 cube edges and one diagonal per square
    EXPECT_EQ(m.edges().size(), 18);

    const vectorField n = m.faceNormals();
    EXPECT_NEAR(mag(n[0] - vector(0, 0, -1)), 0, 1e-15);
}

TEST(triMesh, tetrahedronVolume)
{
    EXPECT_NEAR(rbdTest::tetrahedron().volume(), 1.0/6, 1e-15);
}

TEST(triMesh, transformRotatesThenTranslates)
{
    const rbd::triMesh m = rbdTest::box(1, 2, 3);
    const tensor R = quaternion(vector(1, 1, 1)/std::sqrt(3.0), 0.7).R();
    const vector x(1, -2, 3);

    const rbd::triMesh t = m.transformed(R, x);
    EXPECT_NEAR(t.volume(), 6, 1e-13);
    EXPECT_NEAR(t.area(), m.area(), 1e-13);
    forAll(m.points(), i)
    {
        EXPECT_NEAR(mag(t.points()[i] - ((R & m.points()[i]) + x)), 0, 1e-15);
    }

    const pointField tp(m.transformedPoints(R, x));
    EXPECT_NEAR(max(mag(tp - t.points())), 0, 1e-15);

    rbd::triMesh f(m);
    f.flip();
    EXPECT_NEAR(f.volume(), -6, 1e-14);

    rbd::triMesh s(m);
    s.scale(0.5);
    EXPECT_NEAR(s.volume(), 6.0/8, 1e-15);
}
