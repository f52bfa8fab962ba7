// Unit tests for src/rbdPacking/loading/loadingScheme: the release points
// and poses against the scheme's definition (the paper's schemes 1-3, the
// header's Description), drawn many times where the pose is random

#include <gtest/gtest.h>
#include "loadingScheme.H"
#include "stateIO.H"
#include "IStringStream.H"
#include "mathematicalConstants.H"
#include "unitConversion.H"

#include <sstream>

using namespace Foam;
using Foam::constant::mathematical::pi;

namespace
{
    dictionary parse(const std::string& text)
    {
        IStringStream is(text);
        return dictionary(is);
    }

    // Tube of D = 40 mm, H = 100 mm
    const rbd::tube tube40(0.04, 0.1, 0.6, 0.6);

    // Sphere dp = 10 mm (r_b = 5 mm) and cylinder d = 10 mm, h = 20 mm
    // (r_b = sqrt(5^2 + 10^2) mm = 11.18 mm)
    autoPtr<rbd::pelletShape> sphere()
    {
        return rbd::pelletShape::New
        (
            parse("shape sphere; diameter 0.01; faces 80;")
        );
    }

    autoPtr<rbd::pelletShape> cylinder()
    {
        return rbd::pelletShape::New
        (
            parse("shape cylinder; diameter 0.01; height 0.02; faces 200;")
        );
    }

    // The body z axis of pose q in the world frame
    vector bodyAxis(const quaternion& q)
    {
        return q.R() & vector(0, 0, 1);
    }

    // Rotation angle [rad] and unit axis of q2 q1^-1 (the rotation that
    // takes pose q1 to pose q2)
    void relativeRotation
    (
        const quaternion& q1,
        const quaternion& q2,
        scalar& angle,
        vector& axis
    )
    {
        quaternion d(q2*inv(q1));
        if (d.w() < 0)
        {
            d = -d;
        }
        angle = 2*std::atan2(mag(d.v()), d.w());
        axis = d.v()/max(mag(d.v()), VSMALL);
    }
}


TEST(loadingScheme, columnReleasesOnTheAxisAtTheDefaultHeight)
{
    autoPtr<rbd::pelletShape> s = cylinder();
    const scalar rb = s->boundingRadius();
    rbd::loadingScheme L
    (
        parse("scheme column; positionDisturbance 0;"), tube40, s()
    );

    ASSERT_EQ(L.nColumns(), 1);
    // Default release height: container height - r_b
    EXPECT_NEAR(L.releaseHeight(), 0.1 - rb, 1e-15);
    EXPECT_NEAR(mag(L.column(0) - point(0, 0, 0.1 - rb)), 0, 1e-15);
    // Default spacing 1.2 bounding diameters (the cylinder's 2 r_b > dp)
    EXPECT_NEAR(L.clearance(), 1.2*2*rb, 1e-15);

    // No disturbance: every pose is the column point, tilted by the
    // default 45 degrees
    for (label i = 0; i < 5; ++i)
    {
        point x;
        quaternion q;
        L.nextPose(0, x, q);
        EXPECT_EQ(x, L.column(0));
        const vector a(bodyAxis(q));
        EXPECT_NEAR(std::acos(a.z()), degToRad(45), 1e-12);
        // ... about the world x axis: the axis stays in the y-z plane
        EXPECT_NEAR(a.x(), 0, 1e-15);
    }

    // The default positionDisturbance is 0.3 dp (d = 10 mm here): offsets
    // drawn, none beyond 3 mm
    rbd::loadingScheme D(dictionary(), tube40, s());
    scalar largest = 0;
    for (label i = 0; i < 1000; ++i)
    {
        point x;
        quaternion q;
        D.nextPose(0, x, q);
        largest = max(largest, mag(x - D.column(0)));
    }
    EXPECT_LE(largest, 0.3*0.01*(1 + 1e-12));
    EXPECT_GT(largest, 0.29*0.01);
}


TEST(loadingScheme, spacingIsPerLargerOfDiameterAndBoundingDiameter)
{
    // Sphere: 2 r_b = dp
    autoPtr<rbd::pelletShape> s = sphere();
    rbd::loadingScheme L(parse("spacing 1.5;"), tube40, s());
    EXPECT_NEAR(L.clearance(), 1.5*0.01, 1e-15);
}


TEST(loadingScheme, twoAndFourColumnsAtTheirOffset)
{
    autoPtr<rbd::pelletShape> s = sphere();
    const scalar rb = s->boundingRadius();
    const scalar R = 0.02;
    const scalar z = 0.07;

    // Default offset midway between r_b + delta and R - r_b - delta
    // (delta = 0.3 dp, the default): R/2; columns on opposite sides of
    // the axis
    {
        rbd::loadingScheme L
        (
            parse("scheme twoColumns; releaseHeight 0.07;"), tube40, s()
        );
        ASSERT_EQ(L.nColumns(), 2);
        const scalar off = 0.5*R;
        EXPECT_NEAR(mag(L.column(0) - point(off, 0, z)), 0, 1e-15);
        EXPECT_NEAR(mag(L.column(1) - point(-off, 0, z)), 0, 1e-15);
        EXPECT_NEAR(L.releaseHeight(), z, 1e-15);
    }

    // Given offset: four columns, 90 degrees apart, all at that distance
    // from the axis and at the release height (12 mm: the largest with
    // delta 3 mm, R - r_b - delta)
    {
        rbd::loadingScheme L
        (
            parse("scheme fourColumns; columnOffset 0.012;"), tube40, s()
        );
        ASSERT_EQ(L.nColumns(), 4);
        for (label c = 0; c < 4; ++c)
        {
            const point& p = L.column(c);
            EXPECT_NEAR(rbd::tube::axialDistance(p), 0.012, 1e-15) << c;
            EXPECT_NEAR(p.z(), 0.1 - rb, 1e-15) << c;
            const scalar phi = 0.5*pi*c;
            EXPECT_NEAR(p.x(), 0.012*std::cos(phi), 1e-15) << c;
            EXPECT_NEAR(p.y(), 0.012*std::sin(phi), 1e-15) << c;
        }
    }

    // The largest offset without a disturbance: a pellet there touches
    // the wall
    {
        rbd::loadingScheme L
        (
            parse
            (
                "scheme twoColumns; positionDisturbance 0; columnOffset "
              + std::to_string(R - rb) + ";"
            ),
            tube40, s()
        );
        EXPECT_NEAR(L.column(0).x() + rb, R, 1e-12);
    }
}


TEST(loadingScheme, tiltTurnsTheAxisAboutWorldX)
{
    autoPtr<rbd::pelletShape> s = cylinder();
    for (const scalar tilt : {0.0, 10.0, 45.0, 90.0, 135.0, 180.0})
    {
        rbd::loadingScheme L
        (
            parse
            (
                "tilt " + std::to_string(tilt) + "; positionDisturbance 0;"
            ),
            tube40, s()
        );
        point x;
        quaternion q;
        L.nextPose(0, x, q);
        const vector a(bodyAxis(q));
        // Closed form: R_x(t) e_z = (0, -sin t, cos t)
        const scalar t = degToRad(tilt);
        EXPECT_NEAR(a.x(), 0, 1e-15) << tilt;
        EXPECT_NEAR(a.y(), -std::sin(t), 1e-12) << tilt;
        EXPECT_NEAR(a.z(), std::cos(t), 1e-12) << tilt;
        // ... and the body x axis stays the world x axis
        const vector ex(q.R() & vector(1, 0, 0));
        EXPECT_NEAR(mag(ex - vector(1, 0, 0)), 0, 1e-12) << tilt;
    }
}


TEST(loadingScheme, positionDisturbanceUniformInADisc)
{
    autoPtr<rbd::pelletShape> s = sphere();
    const scalar dp = 0.01;
    const scalar pd = 0.3;
    rbd::loadingScheme L
    (
        parse("scheme twoColumns; positionDisturbance 0.3; seed 7;"),
        tube40, s()
    );

    // Off the wall: the default offset R/2 + 0.3 dp = 13 mm < R - r_b =
    // 15 mm
    const label n = 20000;
    label inner = 0;
    vector mean(Zero);
    scalar largest = 0;
    for (label i = 0; i < n; ++i)
    {
        const label c = i % 2;
        point x;
        quaternion q;
        L.nextPose(c, x, q);
        const vector d(x - L.column(c));
        EXPECT_EQ(d.z(), 0);
        const scalar r = mag(d);
        ASSERT_LE(r, pd*dp*(1 + 1e-12)) << i;
        largest = max(largest, r);
        if (r < 0.5*pd*dp)
        {
            ++inner;
        }
        mean += d/n;
    }
    // Uniform in the disc: P(r < R/2) = 1/4 (not 1/2 as a radius uniform
    // in [0, R] gives), tolerance 5 sigma = 5 sqrt(p (1 - p)/n) = 0.015
    EXPECT_NEAR(scalar(inner)/n, 0.25, 0.015);
    // Isotropic: mean offset 0 within 5 sigma (sigma of one component
    // R/2, of the mean R/(2 sqrt n))
    EXPECT_LT(mag(mean), 5*0.5*pd*dp/std::sqrt(scalar(n)));
    // The disc is filled out to its radius
    EXPECT_GT(largest, 0.99*pd*dp);
}


TEST(loadingScheme, angleDisturbanceUniformInAngleAboutARandomAxis)
{
    autoPtr<rbd::pelletShape> s = cylinder();
    const scalar maxAngle = 30;
    rbd::loadingScheme L
    (
        parse
        (
            "tilt 45; angleDisturbance 30; positionDisturbance 0; seed 3;"
        ),
        tube40, s()
    );
    const quaternion q0(vector(1, 0, 0), degToRad(45.0));

    const label n = 20000;
    scalar meanAngle = 0, largest = 0;
    vector meanAxis(Zero);
    scalar meanZ2 = 0;
    for (label i = 0; i < n; ++i)
    {
        point x;
        quaternion q;
        L.nextPose(0, x, q);
        EXPECT_EQ(x, L.column(0));
        EXPECT_NEAR(mag(q), 1, 1e-14);
        scalar angle;
        vector axis;
        relativeRotation(q0, q, angle, axis);
        ASSERT_LE(angle, degToRad(maxAngle) + 1e-12) << i;
        largest = max(largest, angle);
        meanAngle += angle/n;
        meanAxis += axis/n;
        meanZ2 += sqr(axis.z())/n;
    }
    const scalar a = degToRad(maxAngle);
    // Angle uniform in [0, a]: mean a/2, sigma of the mean a/sqrt(12 n)
    EXPECT_NEAR(meanAngle, 0.5*a, 5*a/std::sqrt(12.0*n));
    EXPECT_GT(largest, 0.99*a);
    // Axis uniform on the sphere: mean 0 (sigma 1/sqrt(3 n) per
    // component), <z^2> = 1/3 (sigma sqrt(4/45/n))
    EXPECT_LT(mag(meanAxis), 5*std::sqrt(3.0/(3.0*n)));
    EXPECT_NEAR(meanZ2, 1.0/3.0, 5*std::sqrt(4.0/45.0/n));
}


TEST(loadingScheme, sameSeedSamePosesAnotherSeedOthers)
{
    // Four columns of these cylinders need R >= (1 + sqrt(2)) r_b = 27 mm
    const rbd::tube tube100(0.1, 0.1, 0.6, 0.6);
    autoPtr<rbd::pelletShape> s = cylinder();
    const std::string d =
        "scheme fourColumns; positionDisturbance 0.5; angleDisturbance 40;";
    rbd::loadingScheme A(parse(d + " seed 11;"), tube100, s());
    rbd::loadingScheme B(parse(d + " seed 11;"), tube100, s());
    rbd::loadingScheme C(parse(d + " seed 12;"), tube100, s());
    label differ = 0;
    for (label i = 0; i < 100; ++i)
    {
        point xa, xb, xc;
        quaternion qa, qb, qc;
        A.nextPose(i % 4, xa, qa);
        B.nextPose(i % 4, xb, qb);
        C.nextPose(i % 4, xc, qc);
        // Bit for bit
        EXPECT_EQ(xa, xb) << i;
        EXPECT_TRUE(qa.w() == qb.w() && qa.v() == qb.v()) << i;
        if (xa != xc)
        {
            ++differ;
        }
    }
    EXPECT_EQ(differ, 100);
}


TEST(loadingScheme, stateCarriesTheGeneratorAcrossARestart)
{
    autoPtr<rbd::pelletShape> s = sphere();
    const dictionary d(parse("positionDisturbance 0.5; seed 5;"));
    rbd::loadingScheme A(d, tube40, s());
    point x;
    quaternion q;
    for (label i = 0; i < 17; ++i)
    {
        A.nextPose(0, x, q);
    }
    std::stringstream buf;
    {
        rbd::stateWriter out(buf);
        A.writeState(out);
    }
    // A fresh scheme (generator at the seed) takes the state over
    rbd::loadingScheme B(d, tube40, s());
    {
        rbd::stateReader in(buf, "test");
        B.readState(in);
    }
    for (label i = 0; i < 10; ++i)
    {
        point xa, xb;
        quaternion qa, qb;
        A.nextPose(0, xa, qa);
        B.nextPose(0, xb, qb);
        EXPECT_EQ(xa, xb) << i;
    }
}


TEST(loadingSchemeDeath, entriesOutsideTheirRangeNameTheEntry)
{
    autoPtr<rbd::pelletShape> s = sphere();
    EXPECT_EXIT
    (
        rbd::loadingScheme(parse("spacing 0.9;"), tube40, s()),
        ::testing::ExitedWithCode(1),
        "Bad entry 'spacing 0.9;'(.|\n)*a number >= 1"
    );
    // columnOffset above R - r_b - 0.3 dp = 12 mm (loadingSchemeBoundsTest:
    // every bound)
    EXPECT_EXIT
    (
        rbd::loadingScheme
        (
            parse("scheme twoColumns; columnOffset 0.016;"), tube40, s()
        ),
        ::testing::ExitedWithCode(1),
        "Bad entry 'columnOffset 0.016;'(.|\n)*a number in "
        "\\[0.008, 0.012\\]"
    );
    // releaseHeight at most H - r_b = 95 mm
    EXPECT_EXIT
    (
        rbd::loadingScheme(parse("releaseHeight 0.097;"), tube40, s()),
        ::testing::ExitedWithCode(1),
        "Bad entry 'releaseHeight 0.097;'(.|\n)*a height in \\(0.005, 0.095\\]"
    );
    EXPECT_EXIT
    (
        rbd::loadingScheme(parse("scheme threeColumns;"), tube40, s()),
        ::testing::ExitedWithCode(1),
        "Bad entry 'scheme threeColumns;'"
    );
}
