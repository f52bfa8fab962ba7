// Unit tests for src/rbdPacking/caseWriting/planeSection: section areas of
// cells by a horizontal plane against closed forms (cube, sheared cube,
// tetrahedron, a plane through a layer of faces), and the area average

#include <gtest/gtest.h>
#include "planeSection.H"
#include "rbdPacking/shapes/meshing/testMeshes.H"

using namespace Foam;

namespace
{
    //- The 8 corners of the unit cube, z + k for layer k, the top layer
    //  shifted by (sx, sy) per unit height
    pointField corners
    (
        const label layers,
        const scalar sx = 0,
        const scalar sy = 0
    )
    {
        pointField p(4*(layers + 1));
        for (label k = 0; k <= layers; ++k)
        {
            for (label i = 0; i < 4; ++i)
            {
                p[4*k + i] =
                    point((i & 1) + sx*k, ((i >> 1) & 1) + sy*k, k);
            }
        }
        return p;
    }

    //- The faces of cell k between layers k and k + 1, outward
    //  (counter-clockwise seen from outside), bottom and top included
    faceList cellFaces(const label k)
    {
        const label b = 4*k, t = 4*(k + 1);
        return faceList
        ({
            face({b + 0, b + 2, b + 3, b + 1}),   // bottom, -z
            face({t + 0, t + 1, t + 3, t + 2}),   // top, +z
            face({b + 0, b + 1, t + 1, t + 0}),   // y = 0
            face({b + 2, t + 2, t + 3, b + 3}),   // y = 1
            face({b + 0, t + 0, t + 2, b + 2}),   // x = 0
            face({b + 1, b + 3, t + 3, t + 1})    // x = 1
        });
    }
}


TEST(planeSection, unitCubeAndShearedCube)
{
    const faceList f(cellFaces(0));
    const labelList owner(6, Zero);
    for (const scalar z : {0.01, 0.5, 0.99})
    {
        EXPECT_NEAR
        (
            rbd::planeSection::cellAreas(corners(1), f, owner, {}, 1, z)[0],
            1, 1e-14
        ) << "z = " << z;
        // Slanted side faces: a parallelogram section of area 1
        EXPECT_NEAR
        (
            rbd::planeSection::cellAreas
            (
                corners(1, 0.3, -0.2), f, owner, {}, 1, z
            )[0],
            1, 1e-14
        ) << "z = " << z;
    }
    // Outside: nothing
    EXPECT_EQ
    (
        rbd::planeSection::cellAreas(corners(1), f, owner, {}, 1, 1.5)[0], 0
    );
}


TEST(planeSection, tetrahedron)
{
    // Section of (0,0,0), (1,0,0), (0,1,0), (0,0,1) at z: (1 - z)^2/2
    const rbd::triMesh t = rbdTest::tetrahedron();
    faceList f(t.faces().size());
    forAll(f, i)
    {
        f[i] = face(t.faces()[i]);
    }
    const labelList owner(f.size(), Zero);
    for (const scalar z : {0.1, 0.25, 0.5, 0.9})
    {
        EXPECT_NEAR
        (
            rbd::planeSection::cellAreas(t.points(), f, owner, {}, 1, z)[0],
            0.5*sqr(1 - z), 1e-14
        ) << "z = " << z;
    }
}


TEST(planeSection, twoCellsAndAPlaneThroughTheirFace)
{
    // Cells 0 (z in [0, 1]) and 1 (z in [1, 2]); the face between them is
    // the internal face 0, owner 0, neighbour 1, normal +z
    const faceList c0(cellFaces(0)), c1(cellFaces(1));
    faceList f;
    labelList owner;
    f.append(c0[1]);
    owner.append(0);
    for (label i : {0, 2, 3, 4, 5})
    {
        f.append(c0[i]);
        owner.append(0);
    }
    for (label i : {1, 2, 3, 4, 5})
    {
        f.append(c1[i]);
        owner.append(1);
    }
    const labelList neighbour({1});
    const pointField p(corners(2, 0.1, 0.05));

    const scalarField A05(rbd::planeSection::cellAreas(p, f, owner,
        neighbour, 2, 0.5));
    EXPECT_NEAR(A05[0], 1, 1e-14);
    EXPECT_NEAR(A05[1], 0, 1e-14);
    const scalarField A15(rbd::planeSection::cellAreas(p, f, owner,
        neighbour, 2, 1.5));
    EXPECT_NEAR(A15[0], 0, 1e-14);
    EXPECT_NEAR(A15[1], 1, 1e-14);
    // On the face: once, to the cell below
    const scalarField A1(rbd::planeSection::cellAreas(p, f, owner,
        neighbour, 2, 1));
    EXPECT_NEAR(A1[0] + A1[1], 1, 1e-14);
    EXPECT_NEAR(A1[0], 1, 1e-14);

    // The area average of the cell values
    scalar area = 0;
    EXPECT_NEAR
    (
        rbd::planeSection::areaAverage(scalarField(List<scalar>({3, 5})), A05, area),
        3, 1e-14
    );
    EXPECT_NEAR(area, 1, 1e-14);
    EXPECT_NEAR
    (
        rbd::planeSection::areaAverage
        (
            scalarField(List<scalar>({3, 5})), scalarField(List<scalar>({0.25, 0.75})), area
        ),
        4.5, 1e-14
    );
    // No section: NaN, no value a comparison passes
    EXPECT_TRUE
    (
        std::isnan
        (
            rbd::planeSection::areaAverage
            (
                scalarField(List<scalar>({3, 5})), scalarField(2, Zero), area
            )
        )
    );
}


TEST(planeSection, volumeBelowAPlane)
{
    // One cell, every face on the boundary: the unit cube and the sheared
    // cube (volume 1 too) hold z of their volume below the plane z
    const faceList f(cellFaces(0));
    for (const scalar z : {-0.5, 0.0, 0.01, 0.5, 0.99, 1.0, 1.5})
    {
        const scalar expected = min(max(z, scalar(0)), scalar(1));
        EXPECT_NEAR
        (
            rbd::planeSection::volumeBelow(corners(1), f, 0, z),
            expected, 1e-14
        ) << "z = " << z;
        EXPECT_NEAR
        (
            rbd::planeSection::volumeBelow(corners(1, 0.3, -0.2), f, 0, z),
            expected, 1e-14
        ) << "z = " << z;
    }

    // Two cells on each other: the shared face is internal (face 0, the
    // first nInternalFaces faces) and does not count; the outer faces
    // give the stack's volume below z
    faceList two(11);
    two[0] = cellFaces(0)[1];                 // z = 1, owner 0
    label n = 1;
    for (label k = 0; k < 2; ++k)
    {
        const faceList c(cellFaces(k));
        for (label i = 0; i < 6; ++i)
        {
            if ((k == 0 && i == 1) || (k == 1 && i == 0))
            {
                continue;
            }
            two[n++] = c[i];
        }
    }
    ASSERT_EQ(n, 11);
    for (const scalar z : {0.25, 1.0, 1.75, 3.0})
    {
        EXPECT_NEAR
        (
            rbd::planeSection::volumeBelow(corners(2, 0.1, 0.2), two, 1, z),
            min(z, scalar(2)), 1e-14
        ) << "z = " << z;
    }
}
