// Who falls asleep and who wakes: src/rbdPacking/world/sleep (section 9 of
// docs/method.md), on hand-made contacts

#include <gtest/gtest.h>
#include "sleepControl.H"

using namespace Foam;
using namespace Foam::rbd;

namespace
{
    const scalar r = 0.005;
    const scalar band = 0.1*r;
    const scalar vSleep = 1e-3;
    const scalar tSleep = 0.2;
    const scalar h = 0.01;

    rigidBody sphereAt(const point& x)
    {
        const scalar m = 1e-3;
        return rigidBody(m, vector::one*0.4*m*r*r, x, quaternion(1), true);
    }

    contact restsOn(const label i, const label k)
    {
        contact c;
        c.i = i;
        c.k = k;
        c.n = vector(0, 0, 1);
        return c;
    }

    //- n spheres in a column on the floor, each resting on the one below
    struct column
    {
        List<rigidBody> bodies;
        boolList fixed;
        labelList awake;
        List<contact> contacts;
        sleepControl sleep;

        column(const label n, const scalar sleepVelocity = vSleep)
        :
            bodies(n),
            fixed(n, false),
            awake(identity(n)),
            contacts(n),
            sleep(sleepVelocity, tSleep, r, band, true, true)
        {
            for (label i = 0; i < n; ++i)
            {
                bodies[i] = sphereAt(point(0, 0, r + 2*r*i));
                sleep.addBody(bodies[i].x(), bodies[i].q());
                contacts[i] = restsOn(i, i ? i - 1 : label(tubeBottom));
            }
        }

        //- Steps of h until a pellet falls asleep; the time it took and
        //  who
        scalar untilAsleep(boolList& sleeps, const scalar tEnd = 1)
        {
            scalar t = 0;
            while (t < tEnd)
            {
                t += h;
                if (sleep.fallAsleep(h, bodies, fixed, awake, contacts, sleeps))
                {
                    return t;
                }
            }
            return GREAT;
        }
    };
}


TEST(sleepControl, stillColumnSleepsTogetherAfterSleepTime)
{
    column c(3);
    boolList sleeps;
    const scalar t = c.untilAsleep(sleeps);
    EXPECT_NEAR(t, tSleep, 0.5*h);
    EXPECT_TRUE(sleeps[0] && sleeps[1] && sleeps[2]);
}


TEST(sleepControl, nobodySleepsWithSleepVelocityZero)
{
    column c(3, 0);
    boolList sleeps;
    EXPECT_EQ(c.untilAsleep(sleeps), GREAT);
}


TEST(sleepControl, pelletInTheAirStaysAwake)
{
    column c(1);
    c.contacts.clear();
    boolList sleeps;
    EXPECT_EQ(c.untilAsleep(sleeps), GREAT);
}


TEST(sleepControl, pelletOnAMovingOneStaysAwake)
{
    // The bottom pellet drifts at 3 sleepVelocity: it restarts its window
    // again and again, and the pellet resting on it may not sleep either
    column c(2);
    boolList sleeps;
    scalar t = 0;
    bool any = false;
    while (t < 1)
    {
        t += h;
        c.bodies[0].setState
        (
            c.bodies[0].x() + vector(3*vSleep*h, 0, 0), quaternion(1),
            Zero, Zero
        );
        any = c.sleep.fallAsleep
        (
            h, c.bodies, c.fixed, c.awake, c.contacts, sleeps
        ) || any;
    }
    EXPECT_FALSE(any);
}


TEST(sleepControl, slowDriftWithinTheWindowSleeps)
{
    // Half the sleep velocity: within sleepVelocity x sleepTime of the
    // anchor after sleepTime, so still
    column c(1);
    boolList sleeps;
    scalar t = 0;
    bool asleep = false;
    while (t < 1 && !asleep)
    {
        t += h;
        c.bodies[0].setState
        (
            c.bodies[0].x() + vector(0.5*vSleep*h, 0, 0), quaternion(1),
            Zero, Zero
        );
        asleep = c.sleep.fallAsleep
        (
            h, c.bodies, c.fixed, c.awake, c.contacts, sleeps
        );
    }
    EXPECT_TRUE(asleep);
    EXPECT_NEAR(t, tSleep, 0.5*h);
}


TEST(sleepControl, wakeSpreadsUpwardsOnly)
{
    // Four sleepers in a column; waking the second wakes the two above it
    // (within reach, centres higher), not the one below
    column c(4);
    c.fixed = true;
    List<DynamicList<label>> adjacency(4);
    adjacency[0] = labelList({1});
    adjacency[1] = labelList({0, 2});
    adjacency[2] = labelList({1, 3});
    adjacency[3] = labelList({2});

    EXPECT_TRUE(c.sleep.wake(1, c.bodies, c.fixed, adjacency));
    EXPECT_TRUE(c.fixed[0]);
    EXPECT_FALSE(c.fixed[1]);
    EXPECT_FALSE(c.fixed[2]);
    EXPECT_FALSE(c.fixed[3]);

    // Waking an awake pellet with no sleepers above wakes nobody
    EXPECT_FALSE(c.sleep.wake(3, c.bodies, c.fixed, adjacency));
}


TEST(sleepControl, wokenPelletRestartsItsWindow)
{
    column c(1);
    boolList sleeps;
    ASSERT_NEAR(c.untilAsleep(sleeps), tSleep, 0.5*h);
    c.fixed[0] = true;
    const List<DynamicList<label>> adjacency(1);
    EXPECT_TRUE(c.sleep.wake(0, c.bodies, c.fixed, adjacency));
    EXPECT_FALSE(c.fixed[0]);
    EXPECT_NEAR(c.untilAsleep(sleeps), tSleep, 0.5*h);
}
