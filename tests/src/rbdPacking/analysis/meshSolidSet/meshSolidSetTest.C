// Unit tests for src/rbdPacking/analysis/meshSolidSet: exactness on
// polyhedra (box: closed forms; tilted box: additivity and the coarea
// identity), a cylinder mesh against the closed-form cylinder, and the
// mesh error on a sphere bed against the exact sphereSolidSet

#include <gtest/gtest.h>
#include "meshSolidSet.H"
#include "sphereSolidSet.H"
#include "bedVoidage.H"
#include "pelletMeshes.H"
#include "quaternion.H"
#include "mathematicalConstants.H"
#include "rbdPacking/shapes/meshing/testMeshes.H"

#include <cmath>

using namespace Foam;

namespace
{
    const scalar pi = constant::mathematical::pi;

    //- Box of half-sides a, b, c centred on the origin
    rbd::triMesh centredBox(const scalar a, const scalar b, const scalar c)
    {
        rbd::triMesh m(rbdTest::box(2*a, 2*b, 2*c));
        m.transform(tensor::I, vector(-a, -b, -c));
        return m;
    }

    rbd::meshSolidSet onePellet
    (
        const rbd::triMesh& body,
        const point& x,
        const tensor& R = tensor::I
    )
    {
        return rbd::meshSolidSet
        (
            body, List<point>({x}), List<tensor>({R})
        );
    }
}


TEST(meshSolidSet, boxOnTheAxisMatchesClosedForms)
{
    const scalar a = 0.003, c = 0.005;
    const rbd::meshSolidSet s =
        onePellet(centredBox(a, a, c), point(0, 0, 0.02));

    EXPECT_NEAR(s.axialExtent(0).min(), 0.015, 1e-15);
    EXPECT_NEAR(s.radialExtent(0).min(), 0, 1e-15);
    EXPECT_NEAR(s.radialExtent(0).max(), a*std::sqrt(2.0), 1e-15);

    // Slab volumes: cross-section 4 a^2 times the overlap
    EXPECT_NEAR(s.volume(0, 0, 1), 8*a*a*c, 1e-12*8*a*a*c);
    EXPECT_NEAR(s.volume(0, 0.016, 0.019), 4*a*a*0.003, 1e-12*8*a*a*c);
    EXPECT_NEAR(s.volume(0, 0.024, 0.1), 4*a*a*0.001, 1e-12*8*a*a*c);
    EXPECT_EQ(s.volume(0, 0.026, 0.1), 0);

    // Cylinder areas: whole circle inside for r < a; for a < r < a sqrt2
    // the four corners hold the angle 2 pi - 8 acos(a/r)
    for (const scalar r : {0.001, 0.0029, 0.0031, 0.0035, 0.0042})
    {
        const scalar angle =
            r < a ? 2*pi : 2*pi - 8*std::acos(a/r);
        for (const auto& slab :
            {std::pair<scalar, scalar>(0, 1), {0.017, 0.0205}, {0.01, 0.016}})
        {
            const scalar L = max
            (
                min(slab.second, 0.025) - max(slab.first, 0.015), scalar(0)
            );
            EXPECT_NEAR
            (
                s.cylinderArea(0, r, slab.first, slab.second),
                r*angle*L, 1e-11*r*2*pi*2*c
            ) << "r " << r << " slab " << slab.first << ' ' << slab.second;
        }
    }
    EXPECT_EQ(s.cylinderArea(0, 0.0043, 0, 1), 0);
}


TEST(meshSolidSet, tiltedBoxIsAdditiveAndSatisfiesTheCoarea)
{
    const scalar a = 0.002, b = 0.003, c = 0.004;
    const tensor R =
        quaternion(normalised(vector(1, 2, 0.5)), 0.7).R();
    const rbd::meshSolidSet s =
        onePellet(centredBox(a, b, c), point(0.004, -0.001, 0.01), R);
    const scalar V = 8*a*b*c;

    EXPECT_NEAR(s.volume(0, -1, 1), V, 1e-12*V);
    const scalar z1 = 0.0087, z2 = 0.0113;
    EXPECT_NEAR
    (
        s.volume(0, -1, z1) + s.volume(0, z1, z2) + s.volume(0, z2, 1),
        V, 1e-12*V
    );

    // int_0^inf S_int(r) dr = V in the slab (coarea formula); midpoint
    // rule on 4000 radii (S_int is continuous, error ~ 1e-6)
    const scalarMinMax rr = s.radialExtent(0);
    const label n = 4000;
    const scalar dr = (rr.max() - rr.min())/n;
    scalar integral = 0;
    for (label k = 0; k < n; ++k)
    {
        integral += s.cylinderArea(0, rr.min() + (k + 0.5)*dr, z1, z2)*dr;
    }
    EXPECT_NEAR(integral/s.volume(0, z1, z2), 1, 1e-4);
}


TEST(meshSolidSet, cylinderMeshAgainstTheClosedFormCylinder)
{
    // d = h = 10 mm, the paper's 4400 faces; inscribed polygon of n
    // sides: area factor n sin(2 pi/n)/(2 pi)
    const scalar d = 0.01, h = 0.01;
    const rbd::triMesh body(rbd::pelletMeshes::cylinder(d, h, 4400));
    const scalar Vexact = 0.25*pi*d*d*h;

    // Upright on the axis: slab volume, and S_int = 2 pi r (slab) inside
    const rbd::meshSolidSet up = onePellet(body, point(0, 0, 0.005));
    EXPECT_NEAR(up.volume(0, 0, 1), body.volume(), 1e-12*Vexact);
    EXPECT_NEAR(up.volume(0, 0, 1)/Vexact, 1, 2e-3);
    EXPECT_LT(up.volume(0, 0, 1), Vexact);
    EXPECT_NEAR(up.volume(0, 0.002, 0.004)/(0.25*pi*d*d*0.002), 1, 2e-3);
    EXPECT_NEAR
    (
        up.cylinderArea(0, 0.003, 0.002, 0.006), 2*pi*0.003*0.004,
        1e-12*2*pi*0.003*0.004
    );

    // Lying across the tube off the axis: all of it in a wide slab
    const tensor R = quaternion(vector(1, 0, 0), 0.5*pi).R();
    const rbd::meshSolidSet lying =
        onePellet(body, point(0.006, 0.002, 0.005), R);
    EXPECT_NEAR(lying.volume(0, -1, 1), body.volume(), 1e-12*Vexact);
    // Lying on its side, the slab 0.004 <= z <= 0.006 of the circle of
    // diameter d holds the segment area times h
    const scalar t = 0.001/0.005;
    const scalar segment =
        2*sqr(0.005)*(std::asin(t) + t*std::sqrt(1 - t*t));
    EXPECT_NEAR(lying.volume(0, 0.004, 0.006)/(segment*h), 1, 3e-3);
}


TEST(meshSolidSet, sphereBedErrorAgainstExactSpheresFallsAsOneOverFaces)
{
    // 3 layers of 6 spheres of dp = 10 mm on rings in a tube of 40 mm
    const scalar dp = 0.01, R = 0.02;
    DynamicList<point> centres;
    for (label layer = 0; layer < 3; ++layer)
    {
        for (label k = 0; k < 6; ++k)
        {
            const scalar phi = pi/3*k + 0.5*layer;
            centres.append
            (
                point
                (
                    0.0145*std::cos(phi), 0.0145*std::sin(phi),
                    0.005 + 0.0101*layer
                )
            );
        }
    }
    const rbd::sphereSolidSet exact(centres, 0.5*dp);
    const rbd::bedVoidage exactVoidage(exact, R, 0.003, 0.022);
    const scalar solidExact = 1 - exactVoidage.bulkPorosity();
    const scalarField epsExact(exactVoidage.radialProfile(40));

    const List<tensor> rotations(centres.size(), tensor::I);
    scalar lastError = 1;
    for (const label faces : {320, 1280, 5120})
    {
        const rbd::triMesh body(rbd::pelletMeshes::sphere(dp, faces));
        const rbd::meshSolidSet meshes(body, centres, rotations);
        const rbd::bedVoidage voidage(meshes, R, 0.003, 0.022);

        // The relative error of the solid fraction is about that of the
        // sphere mesh volume (inscribed: too small)
        const scalar err = 1 - (1 - voidage.bulkPorosity())/solidExact;
        const scalar volumeErr = 1 - body.volume()/(pi*dp*dp*dp/6);
        EXPECT_GT(err, 0) << faces;
        EXPECT_NEAR(err/volumeErr, 1, 0.3) << faces;
        EXPECT_LT(err, lastError/3) << faces;
        lastError = err;

        // The radial profile converges alike
        const scalarField eps(voidage.radialProfile(40));
        EXPECT_LT(max(mag(eps - epsExact)), 3*volumeErr) << faces;
    }
    EXPECT_LT(lastError, 3e-3);
}
