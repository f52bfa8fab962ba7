// Unit tests for src/rbdPacking/caseWriting/contactGeometry: bridge axis,
// length and diameter; caps remove the right volume; the touching filter

#include <gtest/gtest.h>
#include "contactGeometry.H"
#include "cgalMeshTools.H"
#include "pelletMeshes.H"
#include "mathematicalConstants.H"
#include "rbdPacking/shapes/meshing/testMeshes.H"

using namespace Foam;
using Foam::constant::mathematical::pi;

namespace
{
    rbd::contact makeContact
    (
        const label i,
        const label k,
        const vector& n,
        const point& p,
        const scalar gap
    )
    {
        rbd::contact c;
        c.i = i;
        c.k = k;
        c.n = normalised(n);
        c.p = p;
        c.gap = gap;
        c.nDot = Zero;
        c.e = 0.9;
        c.mu = 0.1;
        c.centreBased = true;
        return c;
    }
}


TEST(contactGeometry, bridgeAxisLengthAndDiameter)
{
    const scalar d = 0.002;
    for (const vector& n : {vector(1, 1, 0), vector(0, 0, -1),
        vector(0.2, -0.3, 1)})
    {
        const rbd::contact c =
            makeContact(3, 5, n, point(0.01, 0.02, 0.03), 2e-4);
        point s, e;
        rbd::contactGeometry::bridgeAxis(c, d, s, e);
        // Axis along n through p, gap + d long, centred on p
        EXPECT_NEAR(mag(e - s), 2e-4 + d, 1e-15);
        EXPECT_NEAR(mag(0.5*(s + e) - c.p), 0, 1e-15);
        EXPECT_NEAR(((e - s)/mag(e - s)) & c.n, 1, 1e-14);

        const rbd::triMesh m = rbd::contactGeometry::bridge(c, d, 200);
        EXPECT_EQ(rbd::checkClosedSolid(m), "") << n.x() << " " << n.y();
        // Every vertex within d/2 of the axis and between its ends; the
        // rim on the circle of radius d/2
        scalar rMax = 0, tMin = GREAT, tMax = -GREAT;
        for (const point& x : m.points())
        {
            const scalar t = (x - c.p) & c.n;
            rMax = max(rMax, mag((x - c.p) - t*c.n));
            tMin = min(tMin, t);
            tMax = max(tMax, t);
        }
        EXPECT_NEAR(rMax, 0.5*d, 1e-12);
        EXPECT_NEAR(tMin, -0.5*(2e-4 + d), 1e-12);
        EXPECT_NEAR(tMax, 0.5*(2e-4 + d), 1e-12);
        // Volume of the inscribed prism: within 3 % of the cylinder
        EXPECT_NEAR(m.volume()/(0.25*pi*d*d*(2e-4 + d)), 1, 0.03);
    }
    // Overlap (negative gap): length d
    point s, e;
    rbd::contactGeometry::bridgeAxis
    (
        makeContact(0, -1, vector(1, 0, 0), point::zero, -1e-5), d, s, e
    );
    EXPECT_NEAR(mag(e - s), d, 1e-15);
}


TEST(contactGeometry, capsRemoveTheCapVolume)
{
    // Cube [-a, a]^3 touched at its bottom face: a slab a^2 4 hc goes
    const scalar a = 0.004, hc = 3e-4;
    rbd::triMesh cube(rbdTest::box(2*a, 2*a, 2*a));
    cube.transform(tensor::I, vector(-a, -a, -a));
    const rbd::triMesh cut = rbd::contactGeometry::cap
    (
        cube, point(0, 0, -a), vector(0, 0, 1), hc
    );
    EXPECT_EQ(rbd::checkClosedSolid(cut), "");
    EXPECT_NEAR(cube.volume() - cut.volume(), 4*a*a*hc, 1e-12*cube.volume());
    EXPECT_NEAR(cut.bounds().min().z(), -a + hc, 1e-15);

    // Sphere touched at its side: cap of height hc, pi hc^2 (3r - hc)/3
    // (mesh of 5120 faces: within 3 %)
    const scalar r = 0.005;
    const rbd::triMesh sphere(rbd::pelletMeshes::sphere(2*r, 5120));
    const vector m = normalised(vector(-1, 0.5, 0.2));
    const rbd::triMesh flat =
        rbd::contactGeometry::cap(sphere, -r*m, m, 5*hc);
    EXPECT_EQ(rbd::checkClosedSolid(flat), "");
    const scalar h = 5*hc;
    EXPECT_NEAR
    (
        (sphere.volume() - flat.volume())/(pi*h*h*(3*r - h)/3), 1, 0.03
    );
    // Nothing left beyond the plane
    for (const point& x : flat.points())
    {
        EXPECT_GE((x + r*m) & m, h - 1e-12);
    }
}


TEST(contactGeometry, aSecondCapOnTheSamePlaneLeavesThePellet)
{
    // A face lying on a face touches at several points of one plane: the
    // second cap, at a point of the first cap's face and tilted by 1e-4
    // rad, has nothing to cut (within capSkip capHeight) and returns the
    // pellet as the first cap left it, instead of handing CGAL a plane
    // along a face (its corefinement asserted on such a bed)
    const scalar a = 0.004, hc = 3e-4;
    rbd::triMesh cube(rbdTest::box(2*a, 2*a, 2*a));
    cube.transform(tensor::I, vector(-a, -a, -a));
    const rbd::triMesh once = rbd::contactGeometry::cap
    (
        cube, point(0, 0, -a), vector(0, 0, 1), hc
    );
    const rbd::triMesh twice = rbd::contactGeometry::cap
    (
        once, point(0.5*a, 0.5*a, -a), vector(1e-4, 0, 1), hc
    );
    EXPECT_EQ(rbd::checkClosedSolid(twice), "");
    EXPECT_EQ(twice.points().size(), once.points().size());
    EXPECT_EQ(twice.volume(), once.volume());

    // A plane that does cut is not skipped
    const rbd::triMesh deeper = rbd::contactGeometry::cap
    (
        once, point(0, 0, -a + hc), vector(0, 0, 1), hc
    );
    EXPECT_NEAR
    (
        once.volume() - deeper.volume(), 4*a*a*hc, 1e-12*cube.volume()
    );
}


TEST(contactGeometry, aPlaneAcrossThePelletIsNoCap)
{
    // Where the rims of two stacked cylinders met (a bed of ten), a
    // contact carried a normal across the axes: for one of them its plane
    // ran along the side, and cut there it kept a sliver of the pellet
    // (the next cap left nothing, and the case writer stopped on a
    // pellet of no volume). A cut deeper than capDepthLimit capHeights
    // is no cap: the pellet stays as it is.
    const scalar a = 0.004, hc = 1e-4;
    rbd::triMesh cube(rbdTest::box(2*a, 2*a, 2*a));
    cube.transform(tensor::I, vector(-a, -a, -a));

    // The contact at an edge of the side x = -a, its normal into the
    // pellet along -x: the whole cube lies beyond the plane
    const rbd::triMesh across = rbd::contactGeometry::cap
    (
        cube, point(-a, 0, a), vector(-1, 0, 0), hc
    );
    EXPECT_EQ(across.points().size(), cube.points().size());
    EXPECT_EQ(across.volume(), cube.volume());

    // The same contact with its normal into the pellet, +x: a cap of
    // height hc off the side, as always
    const rbd::triMesh capped = rbd::contactGeometry::cap
    (
        cube, point(-a, 0, a), vector(1, 0, 0), hc
    );
    EXPECT_EQ(rbd::checkClosedSolid(capped), "");
    EXPECT_NEAR
    (
        cube.volume() - capped.volume(), 4*a*a*hc, 1e-12*cube.volume()
    );

    // A pellet overlapped by capDepthLimit capHeights less a little is
    // still capped
    const scalar depth = (rbd::contactGeometry::capDepthLimit - 1.5)*hc;
    const rbd::triMesh deep = rbd::contactGeometry::cap
    (
        cube, point(-a + depth, 0, 0), vector(1, 0, 0), hc
    );
    EXPECT_NEAR
    (
        cube.volume() - deep.volume(), 4*a*a*(depth + hc),
        1e-12*cube.volume()
    );
}


TEST(contactGeometry, touchingFiltersGapBottomAndDuplicates)
{
    List<rbd::contact> all
    ({
        makeContact(0, 1, vector(1, 0, 0), point(0, 0, 0), 0),
        makeContact(0, 1, vector(1, 0, 0), point(0, 0, 1e-4), 0),
        makeContact(0, 1, vector(1, 0, 0), point(0, 0, 3e-3), 1e-5),
        makeContact(0, 2, vector(1, 0, 0), point(0, 0, 0), 5e-4),
        makeContact(2, rbd::tubeWall, vector(1, 0, 0), point(1, 0, 0), 0),
        makeContact(2, rbd::tubeBottom, vector(0, 0, 1), point(1, 0, 0), 0)
    });
    const List<rbd::contact> t =
        rbd::contactGeometry::touching(all, 1e-4, 2e-3);
    ASSERT_EQ(t.size(), 3);
    EXPECT_EQ(t[0].k, 1);
    EXPECT_NEAR(t[1].p.z(), 3e-3, 1e-15);
    EXPECT_EQ(t[2].k, rbd::tubeWall);
}
