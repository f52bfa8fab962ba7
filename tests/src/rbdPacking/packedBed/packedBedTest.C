// Unit tests for src/rbdPacking/packedBed: the binned inside-sphere test
// that gives bedCaseWriter its locationInMesh check, against brute force

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
