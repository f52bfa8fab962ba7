// Unit tests for src/rbdPacking/packedBed: the binned inside-sphere test
// that gives bedCaseWriter its locationInMesh check, against brute force,
// and the safety-net endTime that fits the loading

#include <gtest/gtest.h>
#include "packedBed.H"
#include "Random.H"

using namespace Foam;

namespace
{
    bool insideBruteForce
    (
        const UList<point>& centres,
        const scalar r,
        const point& p
    )
    {
        for (const point& c : centres)
        {
            if (magSqr(p - c) < sqr(r))
            {
                return true;
            }
        }
        return false;
    }
}

TEST(packedBed, insideAnySphereAgreesWithBruteForce)
{
    // 300 spheres of radius 5 mm in a 60 x 60 x 100 mm box; points in and
    // around the box (also far outside the grid of centres)
    Random rnd(7);
    const scalar r = 0.005;
    pointField centres(300);
    for (point& c : centres)
    {
        c = point
        (
            0.06*rnd.sample01<scalar>() - 0.03,
            0.06*rnd.sample01<scalar>() - 0.03,
            0.1*rnd.sample01<scalar>()
        );
    }
    const auto inside = rbd::packedBed::insideAnySphere(centres, r);

    label nInside = 0;
    for (label i = 0; i < 20000; ++i)
    {
        const point p
        (
            0.1*rnd.sample01<scalar>() - 0.05,
            0.1*rnd.sample01<scalar>() - 0.05,
            0.14*rnd.sample01<scalar>() - 0.02
        );
        const bool expected = insideBruteForce(centres, r, p);
        ASSERT_EQ(inside(p), expected)
            << "at (" << p.x() << ' ' << p.y() << ' ' << p.z() << ')';
        nInside += expected;
    }
    // Both answers occur
    EXPECT_GT(nInside, 1000);
    EXPECT_LT(nInside, 19000);

    // Just inside and just outside one sphere, along each axis
    for (direction d = 0; d < 3; ++d)
    {
        vector e(Zero);
        e[d] = r;
        const point& c = centres[17];
        EXPECT_TRUE(inside(c + 0.999*e));
        EXPECT_EQ
        (
            inside(c + 1.001*e), insideBruteForce(centres, r, c + 1.001*e)
        );
    }
}

TEST(packedBed, insideAnySphereOfNoSpheres)
{
    const auto inside = rbd::packedBed::insideAnySphere(pointField(), 0.01);
    EXPECT_FALSE(inside(point::zero));
}


TEST(packedBed, endTimeLeavesTwiceTheLoadingTime)
{
    // 10 mm spheres, spacing 1.2: one release per fall of 12 mm from rest
    const scalar g = 9.81;
    const scalar interval = std::sqrt(2*0.012/g);
    EXPECT_NEAR(interval, 0.0495, 1e-4);

    // Small beds keep the given 30 s
    EXPECT_EQ(rbd::packedBed::endTimeForLoading(30, 100, 1, 0.012, g), 30);

    // 1000 in one column: 49.5 s of loading, 109 s; four columns: 250 each
    EXPECT_NEAR
    (
        rbd::packedBed::endTimeForLoading(30, 1000, 1, 0.012, g),
        2*1000*interval + 10, 1e-9
    );
    EXPECT_NEAR
    (
        rbd::packedBed::endTimeForLoading(30, 1000, 4, 0.012, g),
        2*250*interval + 10, 1e-9
    );

    // 1001 in four columns: the fullest column releases 251
    EXPECT_NEAR
    (
        rbd::packedBed::endTimeForLoading(30, 1001, 4, 0.012, g),
        2*251*interval + 10, 1e-9
    );

    // No gravity: nothing falls, the given value stays
    EXPECT_EQ(rbd::packedBed::endTimeForLoading(30, 1000, 1, 0.012, 0), 30);
}
