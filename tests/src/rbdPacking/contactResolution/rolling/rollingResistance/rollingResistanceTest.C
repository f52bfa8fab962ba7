// Unit tests of src/rbdPacking/contactResolution/rolling/rollingResistance:
// the couple of a loaded contact opposes the relative rolling, is bounded
// by mu_r r N, never reverses the rolling within the step, leaves spin
// about the normal alone, and is absent when off or unloaded.
#include <gtest/gtest.h>
#include "rollingResistance.H"

using namespace Foam;
using namespace Foam::rbd;

namespace
{
    rigidBody spinning(const vector& omega)
    {
        // A sphere-like body (isotropic inertia 1e-8 kg m^2), mass 1e-3 kg
        rigidBody b(1e-3, vector::one*1e-8, point(0, 0, 0.005), quaternion(1),
            true);
        b.setState(b.x(), b.q(), Zero, 1e-8*omega);
        return b;
    }

    contact onFloor()
    {
        contact c;
        c.i = 0;
        c.k = tubeBottom;
        c.n = vector(0, 0, 1);
        c.p = point(0, 0, 0);
        c.ri = vector(0, 0, -0.005);
        return c;
    }
}


TEST(rollingResistance, opposesRollingBoundedByMuRN)
{
    const rollingResistance rr(0.1, 0.005);
    const List<rigidBody> bodies(1, spinning(vector(10, 0, 3)));
    const List<contact> cs(1, onFloor());
    const List<scalar> N(1, 0.05);
    const boolList fixed(1, false);
    List<vector> tau(1, Zero);
    rr.apply(bodies, cs, N, fixed, 1e-4, tau);

    // Along -x only (the spin about the normal z is free), of mu_r r N
    EXPECT_NEAR(tau[0].x(), -0.1*0.005*0.05, 1e-15);
    EXPECT_NEAR(tau[0].y(), 0, 1e-18);
    EXPECT_NEAR(tau[0].z(), 0, 1e-18);
}


TEST(rollingResistance, neverReversesTheRollingWithinAStep)
{
    // Slow rolling: mu_r r N would reverse it within the step; the couple
    // stops it instead (|tau| h/I = |omega|)
    const rollingResistance rr(0.1, 0.005);
    const scalar w = 1e-6;
    const List<rigidBody> bodies(1, spinning(vector(0, w, 0)));
    const List<contact> cs(1, onFloor());
    const List<scalar> N(1, 0.05);
    const boolList fixed(1, false);
    List<vector> tau(1, Zero);
    const scalar h = 1e-3;
    rr.apply(bodies, cs, N, fixed, h, tau);
    EXPECT_LT(tau[0].y(), 0);
    EXPECT_NEAR(-tau[0].y()*h/1e-8, w, 1e-12*w);
}


TEST(rollingResistance, absentWhenOffOrUnloaded)
{
    const List<rigidBody> bodies(1, spinning(vector(10, 0, 0)));
    const List<contact> cs(1, onFloor());
    const boolList fixed(1, false);
    List<vector> tau(1, Zero);

    const rollingResistance off(0, 0.005);
    EXPECT_FALSE(off.active());
    off.apply(bodies, cs, List<scalar>(1, 0.05), fixed, 1e-4, tau);
    EXPECT_EQ(tau[0], vector::zero);

    const rollingResistance on(0.1, 0.005);
    on.apply(bodies, cs, List<scalar>(1, 0.0), fixed, 1e-4, tau);
    EXPECT_EQ(tau[0], vector::zero);
}


TEST(rollingResistance, pairGetsEqualAndOppositeCouples)
{
    // Two bodies rolling on each other: the couples on i and k cancel
    // (no net angular momentum from the contact)
    const rollingResistance rr(0.1, 0.005);
    List<rigidBody> bodies(2, spinning(vector(0, 5, 0)));
    bodies[1] = spinning(vector(0, -5, 0));
    contact c(onFloor());
    c.k = 1;
    const List<contact> cs(1, c);
    const boolList fixed(2, false);
    List<vector> tau(2, Zero);
    rr.apply(bodies, cs, List<scalar>(1, 0.05), fixed, 1e-4, tau);
    EXPECT_LT(tau[0].y(), 0);
    EXPECT_NEAR(mag(tau[0] + tau[1]), 0, 1e-18);
}
