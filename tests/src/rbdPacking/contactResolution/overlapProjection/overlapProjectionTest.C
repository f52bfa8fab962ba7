// The overlap correction of src/rbdPacking/contactResolution/
// overlapProjection: deeper than the slop is pushed back to half the slop,
// in inverse proportion to the masses, the fixed side not moved

#include <gtest/gtest.h>
#include "overlapProjection.H"

using namespace Foam;
using namespace Foam::rbd;

namespace
{
    const scalar a = 0.005;
    const scalar slop = 1e-6;

    rigidBody sphereAt(const point& x, const scalar m)
    {
        const scalar Is = 0.4*m*a*a;
        return rigidBody(m, vector(Is, Is, Is), x, quaternion(1), true);
    }

    //- The contact of spheres 0 and 1 (centre-based), 0 above 1
    contact pairContact(const UList<rigidBody>& bs)
    {
        contact c;
        c.i = 0;
        c.k = 1;
        c.n = normalised(bs[0].x() - bs[1].x());
        c.p = 0.5*(bs[0].x() + bs[1].x());
        c.centreBased = true;
        return c;
    }
}


TEST(overlapProjection, deepPairIsPushedBackToHalfTheSlopByTheMasses)
{
    // Spheres of 1 and 3 units of mass, 5 slops into each other: the light
    // one moves three quarters of the way
    const scalar depth = 5*slop;
    List<rigidBody> bs(2);
    bs[0] = sphereAt(point(0, 0, 0.02 + 2*a - depth), 1e-3);
    bs[1] = sphereAt(point(0, 0, 0.02), 3e-3);
    const point x0(bs[0].x()), x1(bs[1].x());
    List<contact> cs(1, pairContact(bs));
    const boolList fixed(2, false);
    const tube container(0.05, 0.2, 0.5, 0.5);

    const overlapProjection projection(slop, a);
    EXPECT_EQ(projection.correct(bs, fixed, container, cs), 1);
    const scalar moved = depth - 0.5*slop;
    EXPECT_NEAR(bs[0].x().z() - x0.z(), 0.75*moved, 1e-15);
    EXPECT_NEAR(x1.z() - bs[1].x().z(), 0.25*moved, 1e-15);
    EXPECT_NEAR(cs[0].gap, -0.5*slop, 1e-15);
    EXPECT_NEAR(mag(bs[0].x() - bs[1].x()) - 2*a, -0.5*slop, 1e-15);
}


TEST(overlapProjection, withinTheSlopOrAgainstASleeperOnlyTheAwakeMoves)
{
    List<rigidBody> bs(2);
    bs[0] = sphereAt(point(0, 0, 0.02 + 2*a - 0.5*slop), 1e-3);
    bs[1] = sphereAt(point(0, 0, 0.02), 1e-3);
    List<contact> cs(1, pairContact(bs));
    boolList fixed(2, false);
    const tube container(0.05, 0.2, 0.5, 0.5);
    const overlapProjection projection(slop, a);

    // Within the slop: nothing
    EXPECT_EQ(projection.correct(bs, fixed, container, cs), 0);
    EXPECT_EQ(bs[0].x().z(), 0.02 + 2*a - 0.5*slop);

    // Deeper, against a sleeper: the awake sphere takes it all
    bs[0] = sphereAt(point(0, 0, 0.02 + 2*a - 4*slop), 1e-3);
    fixed[1] = true;
    EXPECT_EQ(projection.correct(bs, fixed, container, cs), 1);
    EXPECT_EQ(bs[1].x().z(), 0.02);
    EXPECT_NEAR(bs[0].x().z() - (0.02 + 2*a), -0.5*slop, 1e-15);
}
