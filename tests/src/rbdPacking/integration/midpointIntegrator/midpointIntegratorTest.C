// src/rbdPacking/integration/midpointIntegrator (eqs 4-5)

#include <gtest/gtest.h>
#include "midpointIntegrator.H"

using namespace Foam;
using namespace Foam::rbd;

class torqueFreeSpin : public ::testing::TestWithParam<scalar> {};

TEST_P(torqueFreeSpin, keepsUnitQuaternionAndConservesMomentumAndEnergy)
{
    // Asymmetric body, spinning about a generic axis
    const scalar h = GetParam();
    rigidBody b(1, vector(1, 2, 3), point::zero, quaternion(1), true);
    b.setState(point::zero, quaternion(1), Zero, vector(1, 0.5, 0.2));
    const scalar E0 = b.kineticEnergy();
    const vector L0 = b.L();

    for (label i = 0; i < label(2/h); ++i)
    {
        midpointIntegrator::step(b, Zero, Zero, h);
        const quaternion& q = b.q();
        ASSERT_NEAR(sqr(q.w()) + magSqr(q.v()), 1, 1e-14);
    }
    EXPECT_LT(mag(b.L() - L0), 1e-15);
    // Second-order method: energy error shrinks with h^2
    EXPECT_NEAR(b.kineticEnergy(), E0, 50*h*h*E0);
}

INSTANTIATE_TEST_SUITE_P(stepSizes, torqueFreeSpin, ::testing::Values(1e-2, 1e-3));


TEST(midpointIntegrator, constantForceIsIntegratedExactly)
{
    rigidBody b(2, vector(1, 1, 1), point(1, 2, 3), quaternion(1), false);
    b.setState(point(1, 2, 3), quaternion(1), vector(2, 0, 0), Zero);
    const vector F(0, 0, -19.62);
    const scalar h = 0.05;
    for (int i = 0; i < 10; ++i)
    {
        midpointIntegrator::step(b, F, Zero, h);
    }
    const scalar t = 0.5;
    EXPECT_NEAR(b.x().x(), 1 + t, 1e-14);
    EXPECT_NEAR(b.x().z(), 3 - 0.5*9.81*t*t, 1e-13);
    EXPECT_NEAR(b.v().z(), -9.81*t, 1e-13);
}
