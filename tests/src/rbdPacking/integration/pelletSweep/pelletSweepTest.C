// The sweep of fast pellets of src/rbdPacking/integration/pelletSweep
// (conservative advancement): which pellets are swept, and that a swept
// pellet stops at its first touch, translating and turning, and keeps its
// whole step where its path is clear

#include <gtest/gtest.h>
#include "pelletSweep.H"
#include "stepControl.H"
#include "mathematicalConstants.H"
#include "scalarList.H"

using namespace Foam;
using namespace Foam::rbd;

namespace
{
    const scalar r = 0.005;
    const scalar m = 1.3e-3;
    const vector I(0.4*m*r*r, 0.4*m*r*r, 0.4*m*r*r);
    const scalar band = 0.1*r;
    const scalar touch = 1e-4*2*r;

    //- What a pair of exact solids with no contact may close in a step
    //  (stepControl::unseenClosing)
    const scalar unseen = stepControl::unseenGap*band - 0.5*touch;

    rigidBody bodyAt
    (
        const point& x,
        const quaternion& q = quaternion(1),
        const vector& v = Zero,
        const vector& L = Zero
    )
    {
        rigidBody b(m, I, x, q, true);
        b.setState(x, q, m*v, L);
        return b;
    }

    //- Gap of a sphere of radius r to the plane z = 0 [m]
    scalar sphereOverFloor(const rigidBody& b)
    {
        return b.x().z() - r;
    }

    //- Gap of a rod (its ends at +-r along the body's x axis) to the plane
    //  z = 0 [m]
    scalar rodOverFloor(const rigidBody& b)
    {
        const vector e(b.R() & vector(r, 0, 0));
        return min(b.x().z() + e.z(), b.x().z() - e.z());
    }

    //- The sweep's advance for a gap function: seen within the band, a
    //  lower bound beyond it
    pelletSweep::advanceFunction advanceOf
    (
        const pelletSweep& sweep,
        scalar (*gap)(const rigidBody&)
    )
    {
        return [&sweep, gap](const rigidBody& b)
        {
            const scalar g = gap(b);
            return sweep.advanceFor(g, g < band);
        };
    }
}


TEST(pelletSweep, stopsAtTheFirstTouchOfAFloor)
{
    // From 5 mm over the floor to 4 mm through it in one step: stopped
    // between half the touching gap and the touching gap, with its
    // momentum at the same fraction of the step
    const pelletSweep sweep(0.5, touch, band, unseen, r, true, 1);
    const rigidBody start(bodyAt(point(0, 0, r + 5e-3), quaternion(1),
        vector(0, 0, -5)));
    rigidBody body(bodyAt(point(0, 0, r - 4e-3), quaternion(1),
        vector(0, 0, -5.02)));

    const scalar s =
        sweep.sweep(start, body, advanceOf(sweep, sphereOverFloor));
    EXPECT_LT(s, 1);
    EXPECT_NEAR(s, (5e-3 - 0.5*touch)/9e-3, 1e-9);
    EXPECT_GE(sphereOverFloor(body), 0.5*touch*(1 - 1e-9));
    EXPECT_LE(sphereOverFloor(body), touch);
    EXPECT_NEAR(body.v().z(), -5 - s*0.02, 1e-12);
}


TEST(pelletSweep, aTurnIsSweptToo)
{
    // A rod lying 0.2 mm over the floor turns by 60 degrees about y in
    // one step without moving its centre: one end would go 4.1 mm below
    // the floor. The sweep counts the turn (theta r_b) and stops before
    // the end touches
    const pelletSweep sweep(0.5, touch, band, unseen, r, false, 1);
    const point x(0, 0, 2e-4);
    const rigidBody start(bodyAt(x));
    const quaternion turned(vector(0, 1, 0), constant::mathematical::pi/3);
    rigidBody body(bodyAt(x, turned));
    ASSERT_LT(rodOverFloor(body), -4e-3);

    const scalar s = sweep.sweep(start, body, advanceOf(sweep, rodOverFloor));
    EXPECT_GT(s, 0);
    EXPECT_LT(s, 1);
    EXPECT_GE(rodOverFloor(body), 0.5*touch*(1 - 1e-9));
    EXPECT_LE(rodOverFloor(body), touch);
    // ... turned by s of the turn, about the same axis
    const quaternion expected
    (
        vector(0, 1, 0), s*constant::mathematical::pi/3
    );
    EXPECT_NEAR(mag(body.R() - expected.R()), 0, 1e-12);
}


TEST(pelletSweep, advancesAsAStepCloses)
{
    // Seen (a contact within the band): eq 38's 0.2 lambda at most, and
    // to half the touching gap; touching: none. Not seen: the lower bound
    // (at least stepControl::unseenGap lambda) to half the touching gap
    const pelletSweep sweep(0.5, touch, band, unseen, r, false, 1);
    EXPECT_DOUBLE_EQ(sweep.advanceFor(0.9*band, true), 0.2*band);
    EXPECT_DOUBLE_EQ(sweep.advanceFor(0.1*band, true), 0.1*band - 0.5*touch);
    EXPECT_EQ(sweep.advanceFor(touch, true), 0);
    EXPECT_DOUBLE_EQ
    (
        sweep.advanceFor(0, false),
        stepControl::unseenGap*band - 0.5*touch
    );
    EXPECT_DOUBLE_EQ(sweep.advanceFor(3*band, false), 3*band - 0.5*touch);
}


TEST(pelletSweep, aClearPathKeepsTheWholeStep)
{
    // Falling from 20 mm to 10 mm over the floor: nothing met, nothing
    // changed
    const pelletSweep sweep(0.5, touch, band, unseen, r, true, 1);
    const rigidBody start(bodyAt(point(0, 0, 0.02), quaternion(1),
        vector(0, 0, -5)));
    const rigidBody end(bodyAt(point(0, 0, 0.01), quaternion(1),
        vector(0, 0, -5.02)));
    rigidBody body(end);
    EXPECT_EQ(sweep.sweep(start, body, advanceOf(sweep, sphereOverFloor)), 1);
    EXPECT_EQ(body.x(), end.x());
    EXPECT_EQ(body.P(), end.P());
}


TEST(pelletSweep, interpolatesThePoseAlongTheShorterTurn)
{
    const rigidBody a(bodyAt(point(0, 0, 0), quaternion(1)));
    // q and -q are the same orientation: the path takes the shorter way
    const quaternion q(vector(0, 0, 1), 0.5);
    const rigidBody b(bodyAt(point(1, 2, 3), quaternion(-q.w(), -q.v())));
    rigidBody at(a);
    pelletSweep::interpolate(a, b, 0.5, at);
    EXPECT_NEAR(mag(at.x() - point(0.5, 1, 1.5)), 0, 1e-15);
    const quaternion half(vector(0, 0, 1), 0.25);
    EXPECT_NEAR(mag(at.R() - half.R()), 0, 1e-12);
}


TEST(pelletSweep, selectsFastPelletsTouchingNothingNoTwoNeighbours)
{
    // Relative surface speeds against the listed neighbours:
    //   0 (2 m/s) touches 4: not swept, nor 4; 1 touching 0 would not
    //   be either (a contact nearer than clearGap lambda);
    //   1 (1 m/s) and 2 (3 m/s) are neighbours; 2 also of 3 (0.2 m/s):
    //   2 is the faster against its neighbours (2.8 m/s) and is taken,
    //   1 and 3 (its neighbours) are not;
    //   5 (1 m/s) is within the band of 4 (at rest) but clearer than
    //   pelletSweep::clearGap: taken;
    //   6 and 7 fall together at 5 m/s, a column: not swept
    const pelletSweep sweep(0.5, touch, band, unseen, r, true, 1);
    List<rigidBody> bs(8);
    const scalarList speed({2, 1, 3, 0.2, 0, 1, 5, 5});
    forAll(bs, i)
    {
        bs[i] = bodyAt(point(0.03*i, 0, 0.5), quaternion(1),
            vector(0, 0, -speed[i]));
    }
    List<contact> contacts(2);
    contacts[0].i = 0;
    contacts[0].k = 4;
    contacts[0].gap = 0.5*touch;
    contacts[1].i = 5;
    contacts[1].k = 4;
    contacts[1].gap = 0.5*band;
    List<DynamicList<label>> neighbours(bs.size());
    auto link = [&](const label i, const label k)
    {
        neighbours[i].append(k);
        neighbours[k].append(i);
    };
    link(0, 4);
    link(1, 2);
    link(2, 3);
    link(4, 5);
    link(6, 7);
    const boolList fixed(bs.size(), false);

    DynamicList<label> swept;
    sweep.select
    (
        bs, fixed, labelList(identity(bs.size())), contacts, neighbours, swept
    );
    EXPECT_EQ(labelList(swept), labelList({2, 5}));
    EXPECT_NEAR(sweep.relativeSpeed(2, bs, fixed, neighbours[2]), 2.8, 1e-12);
    EXPECT_EQ(sweep.relativeSpeed(6, bs, fixed, neighbours[6]), 0);

    // Near the floor a pellet's own speed counts: 6 alone at 5 m/s
    bs[6] = bodyAt(point(0.03*6, 0, 1.5*r), quaternion(1), vector(0, 0, -5));
    EXPECT_EQ(sweep.relativeSpeed(6, bs, fixed, neighbours[6]), 5);

    // Off: none
    const pelletSweep off(0, touch, band, unseen, r, true, 1);
    off.select
    (
        bs, fixed, labelList(identity(bs.size())), contacts, neighbours, swept
    );
    EXPECT_EQ(swept.size(), 0);
}


TEST(pelletSweep, boundingSpheresClearOfAPathNeedNoNarrowPhase)
{
    // A bounding sphere moving along x from 0 to 0.02 m at z = 0.5 in a
    // tube of radius 0.1: a sphere beside the middle of the path at 2 r_b
    // + 1 mm is 1 mm clear, one beyond the end is clear by its distance
    // to the end; the floor and the wall only near them
    const pelletSweep sweep(0.5, touch, band, unseen, r, true, 0.1);
    const point x0(0, 0, 0.5);
    const point x1(0.02, 0, 0.5);
    EXPECT_TRUE(sweep.clearOf(x0, x1, point(0.01, 2*r + 1e-3, 0.5), 0.999e-3));
    EXPECT_FALSE(sweep.clearOf(x0, x1, point(0.01, 2*r + 1e-3, 0.5), 1.001e-3));
    EXPECT_TRUE(sweep.clearOf(x0, x1, point(0.03 + 2*r, 0, 0.5), 0.0099));
    EXPECT_FALSE(sweep.clearOf(x0, x1, point(0.03 + 2*r, 0, 0.5), 0.0101));
    EXPECT_TRUE(sweep.clearOfContainer(x0, x1, 0.07));
    EXPECT_FALSE(sweep.clearOfContainer(x0, x1 + vector(0.06, 0, 0), 0.02));
    EXPECT_FALSE
    (
        sweep.clearOfContainer(x0, point(0, 0, r + 1e-3), 1.001e-3)
    );
}
