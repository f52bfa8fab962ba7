// Exact cylinder-container contacts of src/rbdPacking/narrowPhase/
// cylinderContacts against closed forms and against the mesh contacts of
// the same configuration (meshContacts::meshTube).

#include <gtest/gtest.h>
#include "cylinderContacts.H"
#include "floorSupport.H"
#include "meshContacts.H"
#include "pelletMeshes.H"
#include <random>

using namespace Foam;
using namespace Foam::rbd;

namespace
{
    const scalar d = 0.01;
    const scalar h = 0.01;
    const scalar a = 0.5*d;
    const scalar b = 0.5*h;
    const scalar rb = Foam::sqrt(a*a + b*b);
    const scalar band = 0.1*rb;

    rigidBody body(const point& x, const quaternion& q)
    {
        return rigidBody(1, vector::one, x, q, true);
    }

    scalar minGap(const UList<contact>& cs)
    {
        scalar g = GREAT;
        for (const contact& c : cs)
        {
            g = min(g, c.gap);
        }
        return g;
    }
}


TEST(cylinderContacts, standingOnItsFaceGivesFourRimPoints)
{
    const tube container(1, 1, 0.6, 0.6);
    const scalar gap = 5e-5;
    DynamicList<contact> cs;
    cylinderContacts::cylinderTube
    (
        0, body(point(0, 0, b + gap), quaternion(1)), a, b, container, band,
        cs
    );
    ASSERT_EQ(cs.size(), 4);
    for (const contact& c : cs)
    {
        EXPECT_EQ(c.k, tubeBottom);
        EXPECT_NEAR(c.gap, gap, 1e-15);
        EXPECT_NEAR(mag(vector(c.p.x(), c.p.y(), 0)), a, 1e-15);
    }
}


TEST(cylinderContacts, lyingOnItsSideGivesOnePointPerRim)
{
    const tube container(1, 1, 0.6, 0.6);
    const scalar gap = -2e-5;
    DynamicList<contact> cs;
    cylinderContacts::cylinderTube
    (
        0, body(point(0.1, 0, a + gap), quaternion(vector(0, 1, 0), 0.5*M_PI)),
        a, b, container, band, cs
    );
    // The exact lowest point of each rim (round: rhoI set), each with
    // the floor's next points of its circle (floorSupport: material
    // points within floorNearSpan band, above the lowest)
    std::vector<contact> lowest;
    for (const contact& c : cs)
    {
        if (c.rhoI != 0)
        {
            lowest.push_back(c);
        }
        else
        {
            EXPECT_GT(c.gap, gap);
            EXPECT_LE(c.gap, gap + floorNearSpan*band);
        }
    }
    ASSERT_EQ(lowest.size(), 2);
    EXPECT_NEAR(lowest[0].gap, gap, 1e-15);
    EXPECT_NEAR(lowest[1].gap, gap, 1e-15);
    EXPECT_NEAR(mag(lowest[0].p.x() - lowest[1].p.x()), h, 1e-15);
}


TEST(cylinderContacts, tiltedOnItsRimGivesTheLowestPoint)
{
    const tube container(1, 1, 0.6, 0.6);
    const scalar tilt = 0.6;
    // Lowest rim point at z = zc - b cos - a sin
    const scalar zc = b*Foam::cos(tilt) + a*Foam::sin(tilt);
    DynamicList<contact> cs;
    cylinderContacts::cylinderTube
    (
        0, body(point(0, 0, zc), quaternion(vector(1, 0, 0), tilt)),
        a, b, container, band, cs
    );
    ASSERT_GE(cs.size(), 1);
    EXPECT_NE(cs[0].rhoI, 0);
    EXPECT_NEAR(cs[0].gap, 0, 1e-15);
    for (label ci = 1; ci < cs.size(); ++ci)
    {
        EXPECT_EQ(cs[ci].rhoI, 0) << ci;
        EXPECT_GT(cs[ci].gap, 0) << ci;
        EXPECT_LE(cs[ci].gap, floorNearSpan*band) << ci;
    }
}


TEST(cylinderContacts, againstTheWallAlongAGenerator)
{
    // Axis vertical, touching the wall: the two rim points on the wall
    const scalar R = 0.02;
    const tube container(2*R, 1, 0.6, 0.6);
    const scalar gap = 1e-4;
    const vector dir(vector(0.6, 0.8, 0));
    DynamicList<contact> cs;
    cylinderContacts::cylinderTube
    (
        0, body((R - a - gap)*dir + vector(0, 0, 0.5), quaternion(1)),
        a, b, container, band, cs
    );
    ASSERT_EQ(cs.size(), 2);
    for (const contact& c : cs)
    {
        EXPECT_EQ(c.k, tubeWall);
        EXPECT_NEAR(c.gap, gap, 1e-12);
        EXPECT_NEAR(mag(c.n + dir), 0, 1e-12);
    }
}


TEST(cylinderContacts, farthestRimPointFromTheAxisMatchesBruteForce)
{
    const scalar R = 0.02;
    const tube container(2*R, 1, 0.6, 0.6);
    const quaternion q(vector(1, 2, 0.5)/mag(vector(1, 2, 0.5)), 1.1);
    const point x(0.011, -0.004, 0.3);
    const rigidBody bd(body(x, q));

    DynamicList<contact> cs;
    cylinderContacts::cylinderTube(0, bd, a, b, container, 0.01, cs);
    ASSERT_GE(cs.size(), 1);

    // Brute force over both rims
    scalar best = GREAT;
    const vector ax(bd.R() & vector(0, 0, 1));
    const vector u(bd.R() & vector(1, 0, 0));
    const vector v(bd.R() & vector(0, 1, 0));
    for (const scalar side : {-1.0, 1.0})
    {
        for (label j = 0; j < 100000; ++j)
        {
            const scalar t = 2*M_PI*j/100000;
            const point p(x + side*b*ax + a*(Foam::cos(t)*u + Foam::sin(t)*v));
            best = min(best, R - tube::axialDistance(p));
        }
    }
    EXPECT_NEAR(minGap(cs), best, 1e-10);
}


TEST(cylinderContacts, meshAndExactContactsAgreeOnTheFloor)
{
    const label nSeg = 32;
    const triMesh m(pelletMeshes::cylinder(d, h, 300));
    const meshContacts mc(m, band);
    const tube container(1, 1, 0.6, 0.6);

    // Largest gap error of the inscribed mesh: the sagitta of a rim
    // segment (at least 16 segments per circle)
    const scalar sagitta = a*(1 - Foam::cos(M_PI/16));
    (void)nSeg;

    for (const scalar tilt : {0.0, 0.2, 0.7, 0.5*M_PI})
    {
        const quaternion q(vector(1, 0, 0), tilt);
        const point x(0, 0, b*Foam::cos(tilt) + a*Foam::sin(tilt) + 1e-4);
        const rigidBody bd(body(x, q));

        DynamicList<contact> exact, mesh;
        cylinderContacts::cylinderTube(0, bd, a, b, container, band, exact);
        mc.meshTube(0, bd, container, mesh);

        ASSERT_GE(exact.size(), 1);
        ASSERT_GE(mesh.size(), 1);
        // Reduced: a flat patch to its corners; a line of support (lying
        // on its side: two lines of vertices, 0.2 mm apart in gap, in two
        // tiers) to its two ends and the deepest point of each tier; and
        // the points one step can bring down, at most floorSupport::
        // nLowest of them
        EXPECT_LE(mesh.size(), 6 + floorSupport::nLowest) << "tilt " << tilt;
        EXPECT_GE(minGap(mesh), minGap(exact) - 1e-12) << "tilt " << tilt;
        EXPECT_LE(minGap(mesh), minGap(exact) + sagitta) << "tilt " << tilt;
    }
}


TEST(cylinderContacts, tiltedDiscNearTheAxisFindsTheOutermostRimPoint)
{
    // A disc (d 10 mm, h 2 mm) leaning across a tube of 15 mm: rho has two
    // maxima over each rim, and the one in the direction of the centre may
    // be the lower (a disc went 7 % of d through the wall). Random poses
    // near the axis; the contacts' smallest wall gap is the rim's (brute
    // force over 20000 angles of the circles)
    const scalar bDisc = 0.001;
    const scalar Rt = 0.0075;
    const tube container(2*Rt, 1, 0.6, 0.6);

    std::mt19937 rng(11);
    std::uniform_real_distribution<double> U(-1, 1);
    label found = 0;
    for (label trial = 0; trial < 200; ++trial)
    {
        const vector axis(U(rng), U(rng), U(rng));
        const quaternion q(axis/mag(axis), M_PI*U(rng));
        const point x(0.002*U(rng), 0.002*U(rng), 0.05);
        const rigidBody bd(body(x, q));
        const vector ax(bd.R() & vector(0, 0, 1));
        const vector u(bd.R() & vector(1, 0, 0));
        const vector v(bd.R() & vector(0, 1, 0));

        scalar circleGap = GREAT;
        for (const scalar side : {-1.0, 1.0})
        {
            for (label j = 0; j < 20000; ++j)
            {
                const scalar t = 2*M_PI*j/20000;
                const point p
                (
                    x + side*bDisc*ax + a*(Foam::cos(t)*u + Foam::sin(t)*v)
                );
                circleGap = min(circleGap, Rt - tube::axialDistance(p));
            }
        }

        const scalar wide = 0.01;   // every rim point is within the band
        DynamicList<contact> circle;
        cylinderContacts::cylinderTube
        (
            0, bd, a, bDisc, container, wide, circle
        );
        auto wallGap = [](const UList<contact>& cs)
        {
            scalar g = GREAT;
            for (const contact& c : cs)
            {
                if (c.k == tubeWall)
                {
                    g = min(g, c.gap);
                }
            }
            return g;
        };
        EXPECT_NEAR(wallGap(circle), circleGap, 1e-9) << "trial " << trial;
        found += wallGap(circle) < GREAT;
    }
    EXPECT_EQ(found, 200);
}
