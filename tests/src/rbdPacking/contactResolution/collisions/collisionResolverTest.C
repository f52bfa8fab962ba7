// Impulses of src/rbdPacking/contactResolution/collisions (eqs 20-26)

#include <gtest/gtest.h>
#include "collisionResolver.H"
#include "sphereContacts.H"
#include <random>

using namespace Foam;
using namespace Foam::rbd;

namespace
{
    const scalar a = 0.005;
    const scalar m = 4.2e-3;
    const vector Ib(0.4*m*a*a, 0.4*m*a*a, 0.4*m*a*a);

    vector angularMomentum(const UList<rigidBody>& bs)
    {
        vector L(Zero);
        for (const rigidBody& b : bs)
        {
            L += (b.x() ^ b.P()) + b.L();
        }
        return L;
    }

    vector linearMomentum(const UList<rigidBody>& bs)
    {
        return bs[0].P() + bs[1].P();
    }

    scalar energy(const UList<rigidBody>& bs)
    {
        return bs[0].kineticEnergy() + bs[1].kineticEnergy();
    }

    //- One sphere touching the floor of a wide tube (wall friction mu,
    //  restitution e) with velocity v, and its floor contact
    struct sphereOnTheFloor
    {
        List<rigidBody> bs;
        tube t;
        DynamicList<contact> cs;

        sphereOnTheFloor(const vector& v, const scalar mu, const scalar e)
        :
            bs(1),
            t(1, 1, mu, e),
            cs()
        {
            bs[0] = rigidBody(m, Ib, point(0, 0, a), quaternion(1), true);
            bs[0].setState(point(0, 0, a), quaternion(1), m*v, Zero);
            sphereContacts::sphereTube(0, bs[0], a, t, 1e-3, cs);
            for (contact& c : cs)
            {
                c.e = e;
                c.mu = mu;
            }
        }
    };
}


class twoSpheres : public ::testing::TestWithParam<std::pair<scalar, scalar>>
{};

TEST_P(twoSpheres, conserveMomentaAndObeyRestitutionLaw)
{
    const scalar e = GetParam().first;
    const scalar mu = GetParam().second;

    std::mt19937 rng(7);
    std::uniform_real_distribution<double> U(-1, 1);

    for (int trial = 0; trial < 50; ++trial)
    {
        List<rigidBody> bs(2);
        bs[0] = rigidBody(m, Ib, point(0, 0, 0), quaternion(1), true);
        bs[1] = rigidBody(2*m, 2*Ib, point(0, 0, 0), quaternion(1), true);
        // Touching at a random direction, approaching, random spins
        vector n(U(rng), U(rng), U(rng));
        n /= mag(n);
        bs[0].setState(2*a*n, quaternion(1), m*(-n + 0.3*vector(U(rng), U(rng), U(rng))), Ib.x()*vector(U(rng), U(rng), U(rng))*100);
        bs[1].setState(point::zero, quaternion(1), 2*m*0.2*vector(U(rng), U(rng), U(rng)), 2*Ib.x()*vector(U(rng), U(rng), U(rng))*100);

        contact c;
        ASSERT_TRUE
        (
            sphereContacts::sphereSphere(0, bs[0], a, 1, bs[1], a, 1e-3, c)
        );
        c.e = e;
        c.mu = mu;

        const boolList fixed(2, false);
        const scalar vn0 =
            collisionResolver::relativeVelocity(c, bs, fixed) & c.n;
        if (vn0 > -0.05)
        {
            continue;
        }
        const vector P0 = linearMomentum(bs);
        const vector L0 = angularMomentum(bs);
        const scalar E0 = energy(bs);

        collisionResolver resolver(1e-3, 1e-6, 10, 100, 1e-3, 0.1);
        const List<contact> cs({c});
        resolver.resolve(bs, cs, 1e-9, fixed);

        const scalar vn1 =
            collisionResolver::relativeVelocity(c, bs, fixed) & c.n;

        EXPECT_LT(mag(linearMomentum(bs) - P0), 1e-14);
        EXPECT_LT(mag(angularMomentum(bs) - L0), 1e-15);
        EXPECT_LE(energy(bs), E0*(1 + 1e-12));
        if (mu == 0)
        {
            // Restitution law (eq 20)
            EXPECT_NEAR(vn1, -e*vn0, 1e-12);
        }
        else
        {
            // Friction may only add to the separation it couples into
            EXPECT_GE(vn1, -1e-12);
        }
    }
}

INSTANTIATE_TEST_SUITE_P
(
    restitutionAndFriction,
    twoSpheres,
    ::testing::Values
    (
        std::make_pair(1.0, 0.0),
        std::make_pair(0.9, 0.0),
        std::make_pair(0.0, 0.0),
        std::make_pair(0.9, 0.1),
        std::make_pair(0.6, 0.9)
    )
);


TEST(collisionResolver, frictionNeverReversesSlipOnTheFloor)
{
    // A sphere hitting the floor obliquely with high friction: the
    // tangential impulse stops the slip at most, never reverses it
    sphereOnTheFloor s(vector(0.2, 0, -1), 5.0, 0.5);
    List<rigidBody>& bs = s.bs;
    const DynamicList<contact>& cs = s.cs;
    ASSERT_EQ(cs.size(), 1);

    const boolList fixed(1, false);
    collisionResolver(1e-3, 1e-6, 10, 100, 1e-3, 0.1)
       .resolve(bs, cs, 1e-9, fixed);

    const vector vp = bs[0].pointVelocity(cs[0].p);
    EXPECT_NEAR(vp.z(), 0.5, 1e-12);    // restitution 0.5 of 1 m/s
    EXPECT_GE(vp.x(), -1e-12);          // slip stopped, not reversed
    EXPECT_NEAR(vp.x(), 0, 1e-12);      // mu = 5 is enough to stop it
}


TEST(collisionResolver, approachesBelowTheToleranceAreLeftToTheRestingSolve)
{
    // A sphere touching the floor and approaching it slower than eps_p:
    // a plastic impulse stops it if it approaches faster than
    // collisionTolerance eps_p, otherwise it is left alone
    const scalar epsP = 0.01;
    for (const scalar tolerance : {1e-3, 1e-2})
    {
        for (const scalar factor : {0.5, 2.0})
        {
            const scalar vz = -factor*tolerance*epsP;
            sphereOnTheFloor s(vector(0, 0, vz), 0.0, 0.9);
            List<rigidBody>& bs = s.bs;
            const DynamicList<contact>& cs = s.cs;
            ASSERT_EQ(cs.size(), 1);

            const boolList fixed(1, false);
            const collisionResolver::result r =
                collisionResolver(epsP, 1e-6, 10, 100, tolerance, 0.1)
               .resolve(bs, cs, 1e-9, fixed);

            const scalar vAfter = bs[0].v().z();
            if (factor < 1)
            {
                EXPECT_EQ(r.impulses, 0) << tolerance;
                EXPECT_DOUBLE_EQ(vAfter, vz) << tolerance;
            }
            else
            {
                // Resting approach: plastic (e = 0), whatever the COR
                EXPECT_EQ(r.impulses, 1) << tolerance;
                EXPECT_EQ(r.collisions, 0) << tolerance;
                EXPECT_NEAR(vAfter, 0, 1e-15) << tolerance;
            }
        }
    }
}


TEST(collisionResolver, aSleeperTakesAnyHitAsTheWall)
{
    // Sphere 0 falls onto sphere 1, asleep: it bounces off it as off the
    // floor (restitution e, the sleeper does not move), slower or faster
    // than wakeVelocity; wakes() (the test world::step makes before the
    // sweeps) tells the two apart
    const scalar e = 0.9;
    const scalar vWake = 0.1;
    for (const scalar speed : {0.05, 0.2})
    {
        List<rigidBody> bs(2);
        bs[0] = rigidBody(m, Ib, point(0, 0, 2*a), quaternion(1), true);
        bs[1] = rigidBody(m, Ib, point(0, 0, 0), quaternion(1), true);
        bs[0].setState
        (
            point(0, 0, 2*a), quaternion(1), m*vector(0, 0, -speed), Zero
        );

        contact c;
        ASSERT_TRUE
        (
            sphereContacts::sphereSphere(0, bs[0], a, 1, bs[1], a, 1e-3, c)
        );
        c.e = e;
        c.mu = 0;
        const List<contact> cs({c});

        boolList fixed(2, false);
        fixed[1] = true;
        const collisionResolver resolver(0.01, 1e-6, 10, 100, 1e-3, vWake);
        const scalar vn = bs[0].pointVelocity(c.p) & c.n;
        EXPECT_EQ(resolver.wakes(c, vn, fixed), speed > vWake) << speed;

        resolver.resolve(bs, cs, 1e-9, fixed);

        EXPECT_NEAR(bs[0].v().z(), e*speed, 1e-12) << speed;
        EXPECT_EQ(mag(bs[1].v()), 0) << speed;
    }
}
