// Sleeping pellets in src/rbdPacking/world: who may sleep, when, and who
// wakes with whom

#include <gtest/gtest.h>
#include "../../testTools/worldFixture.H"

using namespace rbdTest;

namespace
{
    const scalar d = 0.01;
    const scalar vSleep = 0.001;
    const scalar tSleep = 0.2;

    const std::string sleepOn =
        "sleepVelocity 0.001; sleepTime 0.2; deltaT 0.005;";

    //- Three spheres stacked on the floor of s (a tube barely wider than
    //  one), run until all three sleep; false if they do not within 3 s
    bool sleepingColumn(sphereScene& s)
    {
        for (label i = 0; i < 3; ++i)
        {
            s().addBody(point(0, 0, 0.5*d + i*d), quaternion(1));
        }
        while (s().time() < 3 && s().nSleeping() < 3)
        {
            s().advance(0.005);
        }
        return s().nSleeping() == 3;
    }

    //- Whether a sleeping pellet rests on an awake one: a contact of the
    //  current list whose normal, from the other pellet to the sleeper,
    //  points up
    bool sleeperOnAwake(world& w)
    {
        const boolList& asleep = w.sleeping();
        for (const contact& c : w.allContacts())
        {
            if (c.k < 0)
            {
                continue;
            }
            if (asleep[c.i] && !asleep[c.k] && c.n.z() > 0)
            {
                return true;
            }
            if (asleep[c.k] && !asleep[c.i] && c.n.z() < 0)
            {
                return true;
            }
        }
        return false;
    }
}


TEST(sleep, aPelletOnAnAwakePelletStaysAwake)
{
    // Frictionless: the lower sphere slides at twice the sleep velocity,
    // so it never sleeps; the upper one, balanced on it, barely moves for
    // the first sleep times (it is still by the mean-speed test; later it
    // falls off) but may not sleep on a support that moves. Short sleep
    // time (10 ms), so that the balance holds long enough. Index 0 is the
    // upper one, so that it is tested first within a step.
    const scalar v = 0.01;
    const scalar T = 0.01;
    sphereScene s
    (
        1, d, 0, 0.5, 0, 0.5,
        "sleepVelocity 0.01; sleepTime 0.01; deltaT 0.001;"
    );
    s().addBody(point(0, 0, 1.5*d), quaternion(1));
    s().addBody(point(0, 0, 0.5*d), quaternion(1));
    s().setVelocity(1, vector(2*v, 0, 0), Zero);

    scalar stillFor = 0;
    while (s().time() < 0.1)
    {
        s().advance(0.001);
        ASSERT_FALSE(sleeperOnAwake(s())) << "t = " << s().time();
        ASSERT_FALSE(s().sleeping()[1]);
        if (mag(s().bodies()[0].x() - point(0, 0, 1.5*d)) < 0.5*v*T)
        {
            stillFor = s().time();
        }
    }
    // The test means something: the upper sphere was still for longer
    // than the sleep time
    EXPECT_GT(stillFor, 2*T);
}


TEST(sleep, growsFromTheBottomUpInAStack)
{
    // Three spheres stacked in a tube barely wider than a sphere
    sphereScene s(1.05*d, d, 0.3, 0.5, 0.3, 0.5, sleepOn);
    for (label i = 0; i < 3; ++i)
    {
        s().addBody(point(0, 0, 0.5*d + i*1.05*d), quaternion(1));
    }

    while (s().time() < 3 && s().nSleeping() < 3)
    {
        s().advance(0.005);
        ASSERT_FALSE(sleeperOnAwake(s())) << "t = " << s().time();
    }
    EXPECT_EQ(s().nSleeping(), 3);
}


TEST(sleep, wakingSpreadsToThePelletsAbove)
{
    sphereScene s(1.05*d, d, 0.3, 0.5, 0.3, 0.5, sleepOn);
    ASSERT_TRUE(sleepingColumn(s));

    // The middle one is woken: the top one, which rests on it, wakes too;
    // the bottom one, below it, sleeps on
    s().setVelocity(1, Zero, Zero);
    EXPECT_FALSE(s().sleeping()[1]);
    EXPECT_FALSE(s().sleeping()[2]);
    EXPECT_TRUE(s().sleeping()[0]);
}


TEST(sleep, anImpulsePassedOnToASleeperDoesNotWakeIt)
{
    // Two sleepers at the bottom of a column, an awake sphere resting on
    // them, and a fourth touching it at 5 cm/s (a slow collision: the step
    // stays long), with wakeVelocity = eps_p: the impulse the awake sphere
    // passes down to the upper sleeper inside the collision stage is
    // reflected there as off the floor. The sleeper neither wakes nor
    // moves, and nothing sinks into it
    sphereScene s
    (
        1.05*d, d, 0.3, 0.5, 0.3, 0.5, sleepOn + " wakeVelocity 0.01;"
    );
    ASSERT_TRUE(sleepingColumn(s));

    s().setVelocity(2, Zero, Zero);
    ASSERT_TRUE(s().sleeping()[1]);
    ASSERT_FALSE(s().sleeping()[2]);
    const scalar overlapBefore = s().stats().maxOverlap;
    const point x1 = s().bodies()[1].x();

    const label top =
        s().addBody(s().bodies()[2].x() + vector(0, 0, d), quaternion(1));
    s().setVelocity(top, vector(0, 0, -0.05), Zero);
    bool topBounced = false;
    while (s().time() < 3.5)
    {
        s().advance(0.005);
        topBounced = topBounced || s().bodies()[top].v().z() > 0;
        ASSERT_TRUE(s().sleeping()[1]) << "t = " << s().time();
    }
    EXPECT_TRUE(topBounced);
    EXPECT_EQ(s().bodies()[1].x(), x1);
    EXPECT_LT(s().stats().maxOverlap, max(overlapBefore, 1e-3*d));
}


TEST(sleep, aPelletSleepsWhenItsMeanSpeedIsBelowTheThreshold)
{
    // Frictionless spheres slide on the floor at constant speed: at half
    // the sleep velocity one moves half the sleep distance in sleepTime
    // and sleeps; at twice the sleep velocity one never does
    sphereScene s(1, d, 0, 0.5, 0, 0.5, sleepOn);
    s().addBody(point(-0.2, 0, 0.5*d), quaternion(1));
    s().addBody(point(0.2, 0, 0.5*d), quaternion(1));
    s().setVelocity(0, vector(0.5*vSleep, 0, 0), Zero);
    s().setVelocity(1, vector(2*vSleep, 0, 0), Zero);

    s().advance(0.8*tSleep);
    EXPECT_FALSE(s().sleeping()[0]);
    s().advance(0.4*tSleep);
    EXPECT_TRUE(s().sleeping()[0]);
    EXPECT_EQ(s().bodies()[0].v(), vector::zero);

    s().advance(5*tSleep);
    EXPECT_FALSE(s().sleeping()[1]);
    EXPECT_NEAR(s().bodies()[1].v().x(), 2*vSleep, 1e-12);
}


TEST(sleep, allContactsIncludesPairsOfSleepers)
{
    sphereScene s(1.05*d, d, 0.3, 0.5, 0.3, 0.5, sleepOn);
    s().addBody(point(0, 0, 0.5*d), quaternion(1));
    s().addBody(point(0, 0, 1.5*d), quaternion(1));
    while (s().time() < 3 && s().nSleeping() < 2)
    {
        s().advance(0.005);
    }
    ASSERT_EQ(s().nSleeping(), 2);

    // The step's list skips the pair of sleepers
    s().step(1e-3);
    label pairs = 0;
    for (const contact& c : s().contacts())
    {
        pairs += (c.k >= 0);
    }
    EXPECT_EQ(pairs, 0);

    // The final list has it, and the state is unchanged
    const point x1 = s().bodies()[1].x();
    pairs = 0;
    label floor = 0;
    for (const contact& c : s().allContacts())
    {
        pairs += (c.k >= 0);
        floor += (c.k == tubeBottom);
    }
    EXPECT_EQ(pairs, 1);
    EXPECT_EQ(floor, 1);
    EXPECT_EQ(s().bodies()[1].x(), x1);
}


TEST(sleep, onlyAHitFasterThanWakeVelocityWakesTheBed)
{
    // A sphere falls onto a sleeping column of three: hitting the top
    // sleeper at 0.05 m/s (below wakeVelocity 0.1 m/s) it bounces off as
    // off the floor, and the column sleeps on; at 0.5 m/s it wakes the
    // top sleeper, and what that one passes on is reflected at the middle
    // one, which sleeps on with the bottom one (only a hit wakes: the
    // impact is not passed into the settled bed). 40 ms: the bounce is
    // over (the fast case: the top sphere leaves within the first steps)
    for (const scalar speed : {0.05, 0.5})
    {
        sphereScene s
        (
            1.05*d, d, 0.3, 0.5, 0.3, 0.5, sleepOn + " wakeVelocity 0.1;"
        );
        ASSERT_TRUE(sleepingColumn(s));
        const point x2 = s().bodies()[2].x();

        const label top =
            s().addBody(x2 + vector(0, 0, 1.001*d), quaternion(1));
        s().setVelocity(top, vector(0, 0, -speed), Zero);
        bool topBounced = false;
        bool wokeTop = false;
        for (label n = 0; n < 40; ++n)
        {
            s().advance(0.001);
            topBounced = topBounced || s().bodies()[top].v().z() > 0;
            wokeTop = wokeTop || !s().sleeping()[2];
            ASSERT_TRUE(s().sleeping()[0]) << speed;
            ASSERT_TRUE(s().sleeping()[1]) << speed;
        }
        EXPECT_TRUE(topBounced) << speed;
        EXPECT_EQ(wokeTop, speed > 0.1) << speed;
        if (speed < 0.1)
        {
            EXPECT_EQ(s().bodies()[2].x(), x2);
        }
    }
}


TEST(sleep, aPelletStillInTheAirStaysAwake)
{
    // At gravity 0.005 m/s^2 a released sphere moves 0.1 mm in its first
    // 0.2 s, well under sleepVelocity sleepTime (2 mm): still by the
    // mean-speed test, but touching nothing, so it may not sleep; it
    // falls freely, z = z0 - g t^2/2
    sphereScene s
    (
        0.1, d, 0.1, 0.5, 0.1, 0.5,
        "gravity 0.005; sleepVelocity 0.01; sleepTime 0.2; deltaT 0.01;"
    );
    const scalar z0 = 0.5;
    s().addBody(point(0, 0, z0), quaternion(1));
    while (s().time() < 1 - 1e-9)
    {
        s().advance(0.01);
        ASSERT_EQ(s().nSleeping(), 0) << "t = " << s().time();
    }
    EXPECT_NEAR
    (
        s().bodies()[0].x().z(), z0 - 0.5*0.005*sqr(s().time()), 1e-9
    );
}
