// The state of src/rbdPacking/world written and read back (the
// checkpoint): a world read from it goes on exactly as the one that wrote
// it, through collisions, resting contacts and sleep

#include <gtest/gtest.h>
#include "../../testTools/worldFixture.H"
#include "stateIO.H"

#include <cstring>
#include <sstream>

using namespace rbdTest;

namespace
{
    bool sameBits(const vector& a, const vector& b)
    {
        return std::memcmp(&a, &b, sizeof(vector)) == 0;
    }

    bool sameState(const rigidBody& a, const rigidBody& b)
    {
        return
            sameBits(a.x(), b.x()) && sameBits(a.P(), b.P())
         && sameBits(a.L(), b.L()) && sameBits(a.q().v(), b.q().v())
         && std::memcmp(&a.q(), &b.q(), sizeof(quaternion)) == 0;
    }

    //- Twelve spheres dropped with spin into a 30 mm tube, friction on
    //  pellets and wall, sleep on: collisions, resting stacks and
    //  sleepers within 1.25 s, the checkpoint at 0.25 s before most of it
    void fill(world& w)
    {
        for (label i = 0; i < 12; ++i)
        {
            const scalar a = 2.4*i;
            w.addBody
            (
                point(0.008*std::cos(a), 0.008*std::sin(a), 0.006 + 0.011*i),
                quaternion(1)
            );
            w.setVelocity
            (
                i, vector(0.05*std::sin(a), 0, -0.1), vector(0, 3*i, 1)
            );
        }
    }
}


TEST(worldCheckpoint, readStateContinuesBitForBit)
{
    const std::string sim = "sleepVelocity 0.002; sleepTime 0.1;";
    sphereScene a(0.03, 0.01, 0.3, 0.8, 0.5, 0.6, sim);
    fill(a());
    a().advance(0.25);
    ASSERT_GT(a().stats().collisions, 0);
    ASSERT_GT(a().stats().restingSolves, 0);

    std::stringstream ss;
    stateWriter out(ss);
    a().writeState(out);
    ASSERT_TRUE(out.good());

    sphereScene b(0.03, 0.01, 0.3, 0.8, 0.5, 0.6, sim);
    stateReader in(ss, "test");
    b().readState(in);

    ASSERT_EQ(b().bodies().size(), a().bodies().size());
    EXPECT_EQ(b().time(), a().time());
    EXPECT_EQ(b().stats().steps, a().stats().steps);
    EXPECT_EQ(b().sleeping(), a().sleeping());

    // Both go on through more collisions and sleep
    const label sleepingBefore = a().nSleeping();
    const std::int64_t collisionsBefore = a().stats().collisions;
    a().advance(1.0);
    b().advance(1.0);
    EXPECT_EQ(b().stats().steps, a().stats().steps);
    EXPECT_EQ(b().stats().collisions, a().stats().collisions);
    EXPECT_EQ(b().stats().lcpIterations, a().stats().lcpIterations);
    EXPECT_EQ(b().sleeping(), a().sleeping());
    forAll(a().bodies(), i)
    {
        EXPECT_TRUE(sameState(a().bodies()[i], b().bodies()[i]))
            << "pellet " << i;
    }
    // The scene did something worth checking after the checkpoint
    EXPECT_GT(a().nSleeping(), sleepingBefore);
    EXPECT_GT(a().stats().collisions, collisionsBefore);
}


TEST(worldCheckpoint, aWorldBuiltAnewDiffersWithoutTheBroadPhaseState)
{
    // The control: the same pellets, poses and momenta, but a world that
    // starts with an empty neighbour list and no warm start, takes other
    // steps. This is why the checkpoint holds more than the pellets.
    const std::string sim = "sleepVelocity 0;";
    sphereScene a(0.03, 0.01, 0.3, 0.8, 0.5, 0.6, sim);
    fill(a());
    a().advance(0.5);

    sphereScene b(0.03, 0.01, 0.3, 0.8, 0.5, 0.6, sim);
    forAll(a().bodies(), i)
    {
        const rigidBody& ab = a().bodies()[i];
        b().addBody(ab.x(), ab.q());
        b().setVelocity(i, ab.v(), ab.omega());
    }
    b().advance(0.5);
    a().advance(0.5);

    bool anyDiffers = false;
    forAll(a().bodies(), i)
    {
        anyDiffers =
            anyDiffers || !sameState(a().bodies()[i], b().bodies()[i]);
    }
    EXPECT_TRUE(anyDiffers);
}
